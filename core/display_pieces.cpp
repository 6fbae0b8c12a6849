#include "display_pieces.h"

#include "polygon_area.h"
#include "predicates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace tessera
{
namespace
{

/// Rings whose area is not negligible beside the others' (ClipInto leaves rings of no area where a
/// ring of the catchment only runs along the tile's boundary: they contribute nothing but slabs).
ClippedRings WithoutEmptyRings(const ClippedRings& rings)
{
  std::vector<double> areas;
  double total = 0.0;
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    const std::size_t begin = rings.RingOffsets[r], count = rings.RingOffsets[r + 1] - begin;
    areas.push_back(count < 3 ? 0.0 : CompensatedPolygonArea(&rings.Vertices[begin], count));
    total += std::fabs(areas.back());
  }
  ClippedRings kept;
  for (std::size_t r = 0; r < areas.size(); ++r)
  {
    if (std::fabs(areas[r]) > 1e-12 * total)
    {
      kept.Vertices.insert(kept.Vertices.end(),
        rings.Vertices.begin() + static_cast<std::ptrdiff_t>(rings.RingOffsets[r]),
        rings.Vertices.begin() + static_cast<std::ptrdiff_t>(rings.RingOffsets[r + 1]));
      kept.RingOffsets.push_back(kept.Vertices.size());
    }
  }
  return kept;
}

/// A ring edge that is not vertical, from its left end to its right end. Winding: +1 when its ring
/// runs left to right along it (the region is above it), -1 otherwise.
struct SweepEdge
{
  Point2 Left, Right;
  int Winding;
  /// |dy / dx|: how much a rounding of x moves the edge's height.
  double Steepness() const
  {
    return std::fabs(this->Right.y - this->Left.y) / (this->Right.x - this->Left.x);
  }
};

/// The edge's height at x, exactly its end's height at its ends (so that slabs meeting at a
/// vertex see the same corner on either side).
double HeightAt(const SweepEdge& e, double x)
{
  if (x <= e.Left.x)
  {
    return e.Left.y;
  }
  if (x >= e.Right.x)
  {
    return e.Right.y;
  }
  return e.Left.y + (x - e.Left.x) / (e.Right.x - e.Left.x) * (e.Right.y - e.Left.y);
}

/// Every edge that is not vertical, sorted by its left end's x.
std::vector<SweepEdge> SweepEdges(const ClippedRings& rings)
{
  std::vector<SweepEdge> edges;
  edges.reserve(rings.Vertices.size());
  for (std::size_t r = 0; r + 1 < rings.RingOffsets.size(); ++r)
  {
    const std::size_t begin = rings.RingOffsets[r], end = rings.RingOffsets[r + 1];
    for (std::size_t v = begin; v < end; ++v)
    {
      const Point2& a = rings.Vertices[v];
      const Point2& b = rings.Vertices[NextInRing(v, begin, end)];
      if (a.x < b.x)
      {
        edges.push_back({ a, b, +1 });
      }
      else if (b.x < a.x)
      {
        edges.push_back({ b, a, -1 });
      }
    }
  }
  std::sort(edges.begin(),
    edges.end(),
    [](const SweepEdge& e, const SweepEdge& f) { return e.Left.x < f.Left.x; });
  return edges;
}

/// The distinct x of the vertices, ascending: the slabs' sides.
std::vector<double> SlabSides(const ClippedRings& rings)
{
  std::vector<double> xs;
  xs.reserve(rings.Vertices.size());
  for (const Point2& p : rings.Vertices)
  {
    xs.push_back(p.x);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  return xs;
}

/// How far apart two points must be to count as different: a few ulps of the largest coordinate.
/// Where two edges of opposite sense run along one line (a ring of the catchment and the tile's
/// edge, or the two sides of a bridge), their rounded vertices put one a little above the other;
/// the sliver between them is no part of the region, and a piece continued through it would come
/// out with a spike along the line. (Heights on steep edges are compared with this times the
/// steepness: a rounding of x moves them that much more.)
double PointTolerance(const ClippedRings& rings)
{
  const double largest = rings.Vertices.empty()
    ? 0.0
    : BoundsOf(rings.Vertices.data(), rings.Vertices.size()).LargestMagnitude();
  return 64.0 * std::numeric_limits<double>::epsilon() * largest;
}

/// A corner of a trapezoid: a point on a side, and whether it is a vertex of the rings (its
/// height an edge's end's own) rather than a height interpolated along an edge.
struct Corner
{
  Point2 At;
  bool IsVertex;
};

/// The region between two edges inside one slab: vertical sides at the slab's x.
struct Trapezoid
{
  std::size_t Bottom, Top; // edges
  Corner BottomLeft, BottomRight, TopLeft, TopRight;
  double HeightTolerance; // heights closer than this on its sides are one (PointTolerance)
};

/// Whether x is one of the edge's ends, where HeightAt gives a vertex's own height.
bool EndsAt(const SweepEdge& e, double x)
{
  return x <= e.Left.x || x >= e.Right.x;
}

/// An edge spanning the current slab and its heights (HeightAt) there: at the slab's middle, which
/// orders the slab's edges, and at its sides, which the trapezoids' corners take. The height at
/// the left side is the one computed at the right side of the slab before (the same x, so the same
/// bits): each is computed once, not once for each trapezoid side (four divisions a trapezoid).
/// With them the edge's Steepness and whether it ends at either side (EndsAt), so that a slab's
/// trapezoids are made from its ordered edges alone.
struct SlabEdge
{
  double Middle;
  std::size_t Edge;
  int Winding;
  bool EndsLeft, EndsRight;
  double LeftHeight, RightHeight;
  double Steepness;
};

/// Whether a lies below b in a slab: by height at the slab's middle; at equal heights rising edges
/// (winding +1) first, so that coincident edges of opposite sense (a bridge) never split the
/// region, then by edge index, so that the order is one whatever the order before.
bool Lower(const SlabEdge& a, const SlabEdge& b)
{
  return a.Middle < b.Middle ||
    (a.Middle == b.Middle &&
      (a.Winding > b.Winding || (a.Winding == b.Winding && a.Edge < b.Edge)));
}

/// A trapezoid's corners on its side at x, between edges bottom and top, whose heights there are
/// low and high (bottomEnds, topEnds: whether they end at x). Where the two edges meet there (the
/// corners no further apart than tolerance, or the top one a little below: rounding), the meeting
/// point is often a vertex of the rings that lies on the other edge only to rounding: a crossing
/// ClipInto computed on a tile edge, which Sutherland-Hodgman then runs along to the tile's corner
/// and back. When one edge ends at x and the other is interpolated there, both corners take the
/// end's height, the vertex's own: on a steep edge a rounding of x moves the interpolated height
/// far (6.7e-14 at a slope of 3700), and the piece's corner, moved that much along the steep edge,
/// made the piece 1.6e-16 too large, 2e-12 of its tile's clipped area. Otherwise the top corner is
/// kept no lower than the bottom one.
void SideCorners(double x,
  double low,
  bool bottomEnds,
  double high,
  bool topEnds,
  double tolerance,
  Corner& bottomCorner,
  Corner& topCorner)
{
  // (Decided in scalars, each field stored once: corners built whole and copied were written to
  // the stack in parts and read back whole, a stalled load where perf put a fifth of the samples.)
  const bool kept = high >= low;
  double bottomY = low, topY = kept ? high : low;
  bool bottomIsVertex = bottomEnds, topIsVertex = kept ? topEnds : bottomEnds;
  if (high - low <= tolerance && topEnds != bottomEnds)
  {
    bottomY = topY = topEnds ? high : low;
    bottomIsVertex = topIsVertex = true;
  }
  bottomCorner.At.x = x;
  bottomCorner.At.y = bottomY;
  bottomCorner.IsVertex = bottomIsVertex;
  topCorner.At.x = x;
  topCorner.At.y = topY;
  topCorner.IsVertex = topIsVertex;
}

/// Whether the ring (anticlockwise) is a fan about its vertex apex: every triangle of apex and an
/// edge not at it turns anticlockwise or is flat, so that the triangles tile the ring without
/// overlap. Such a vertex lies in the ring's kernel (it sees the whole ring). The triangles are
/// tested in turn, those of the edges that last ruled out a vertex (killers) first: the few
/// edges of a bay or a hole rule out most vertices, and a fan test of every edge for every
/// vertex was quadratic. budget: tests left to spend, counted down; when it runs out the answer
/// is false, as for a vertex ruled out.
bool IsFanAbout(const std::vector<Point2>& ring,
  std::size_t apex,
  std::vector<std::size_t>& killers,
  std::size_t& budget)
{
  const std::size_t n = ring.size();
  const auto rulesOut = [&](std::size_t edge)
  {
    const std::size_t next = edge + 1 == n ? 0 : edge + 1;
    return edge != apex && next != apex && orient2d(ring[apex], ring[edge], ring[next]) < 0;
  };
  for (const std::size_t edge : killers)
  {
    if (budget == 0)
    {
      return false;
    }
    --budget;
    if (rulesOut(edge))
    {
      return false;
    }
  }
  for (std::size_t edge = 0; edge < n; ++edge)
  {
    if (budget == 0)
    {
      return false;
    }
    --budget;
    if (rulesOut(edge))
    {
      killers.insert(killers.begin(), edge);
      killers.resize(std::min<std::size_t>(killers.size(), 4));
      return false;
    }
  }
  return true;
}

/// A vertex about which the ring is a fan (IsFanAbout), vertex 0 first, then the reflex
/// vertices (a bay's or a hole's corner sees most), then the rest; n if none is found within
/// 8 n + 64 orientation tests (then the ring is cut, which is never wrong, only more pieces).
std::size_t FanApex(const std::vector<Point2>& ring)
{
  const std::size_t n = ring.size();
  std::vector<std::size_t> killers;
  std::size_t budget = 8 * n + 64;
  if (IsFanAbout(ring, 0, killers, budget))
  {
    return 0; // (most pieces, convex ones: no need to sort the vertices)
  }
  std::vector<std::size_t> candidates;
  std::vector<std::size_t> rest;
  for (std::size_t v = 1; v < n; ++v)
  {
    const bool reflex = orient2d(ring[v - 1], ring[v], ring[v + 1 == n ? 0 : v + 1]) < 0;
    (reflex ? candidates : rest).push_back(v);
  }
  candidates.insert(candidates.end(), rest.begin(), rest.end());
  for (const std::size_t v : candidates)
  {
    if (IsFanAbout(ring, v, killers, budget))
    {
      return v;
    }
    if (budget == 0)
    {
      break;
    }
  }
  return n;
}

/// An x-monotone anticlockwise ring cut by the vertical line at x (strictly inside its x range)
/// into its parts left and right of it, both anticlockwise, x-monotone, sharing the cut:
///
///        upper chain  <---+--------              where the line meets a chain at vertices
///      /                  |         \             (a vertical step of it), each part takes the
///     +                cut at x       +          one nearest to it along the ring: on the lower
///      \                  |         /             chain the left part the first, on the upper
///        lower chain  ----+-------->             chain (walked leftwards) the last; elsewhere
///                                                both take the point interpolated on the edge
///
/// Walking on from a vertex left of the line, the ring first crosses it on its lower chain
/// (rightwards), then on its upper chain (leftwards).
void CutAtX(const std::vector<Point2>& ring,
  double x,
  std::vector<Point2>& left,
  std::vector<Point2>& right)
{
  const std::size_t n = ring.size();
  std::size_t i = 0;
  while (ring[i].x >= x)
  {
    ++i; // a vertex left of the line
  }
  const auto at = [&](std::size_t k) -> const Point2& { return ring[k % n]; };
  std::size_t k = i;
  for (; at(k).x < x; ++k) // the left part's lower chain
  {
    left.push_back(at(k));
  }
  // Where the walk meets the line at vertex j: the first and the last of its vertices on it (a
  // vertical step), or twice the point interpolated on the edge into j; j is left past them.
  const auto crossing = [&](std::size_t& j)
  {
    if (at(j).x != x)
    {
      const Point2 p{ x, CrossingHeight(at(j - 1), at(j), x) };
      return std::make_pair(p, p);
    }
    const Point2 first = at(j);
    for (; at(j + 1).x == x; ++j)
    {
    }
    return std::make_pair(first, at(j++));
  };
  auto [lowerLeft, lowerRight] = crossing(k); // the cut's lower ends in the left and right part
  right.push_back(lowerRight);
  for (; at(k).x > x; ++k) // the right part
  {
    right.push_back(at(k));
  }
  auto [upperRight, upperLeft] = crossing(k);
  // (an interpolated end rounded past the other: the cut no lower than a point)
  upperRight.y = std::max(upperRight.y, lowerRight.y);
  lowerLeft.y = std::min(lowerLeft.y, upperLeft.y);
  right.push_back(upperRight);
  left.push_back(lowerLeft);
  left.push_back(upperLeft);
  for (; k % n != i; ++k) // the left part's upper chain
  {
    left.push_back(at(k));
  }
}

/// The middle of the x of the ring's vertices strictly inside its x range; NaN if there is none.
double MiddleInnerX(const std::vector<Point2>& ring)
{
  std::vector<double> xs;
  for (const Point2& p : ring)
  {
    xs.push_back(p.x);
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  return xs.size() < 3 ? std::numeric_limits<double>::quiet_NaN() : xs[xs.size() / 2];
}

/// Appends an x-monotone piece to done as fans: rings that start at a vertex about which they are
/// a fan (FanApex). VTK draws a polygon, and its Cell Size and Integrate Variables measure it, as
/// the fan of triangles about its first point: a piece that is no fan about it (an L, a U round a
/// hole, a tile under a wavy shore) was drawn over its concave corners, and measured 5 to 10%
/// too large. A piece that is a fan about no vertex is cut in two at the middle of its vertices'
/// x, and each part made fans in turn.
void AppendFans(std::vector<Point2> ring, ClippedRings& done)
{
  DropRepeatedVertices(ring); // (a cut's point can fall on a vertex)
  if (ring.size() < 3 || CompensatedPolygonArea(ring.data(), ring.size()) <= 0.0)
  {
    return;
  }
  const std::size_t apex = FanApex(ring);
  const double x = apex < ring.size() ? 0.0 : MiddleInnerX(ring);
  if (apex < ring.size() || std::isnan(x))
  {
    // (no inner x: all its vertices on its two sides, a convex ring but for rounding)
    std::rotate(
      ring.begin(), ring.begin() + std::ptrdiff_t(apex < ring.size() ? apex : 0), ring.end());
    done.Vertices.insert(done.Vertices.end(), ring.begin(), ring.end());
    done.RingOffsets.push_back(done.Vertices.size());
    return;
  }
  std::vector<Point2> left, right;
  CutAtX(ring, x, left, right);
  AppendFans(std::move(left), done);
  AppendFans(std::move(right), done);
}

/// x-monotone pieces grown from left to right out of the slabs' trapezoids.
class PieceBuilder
{
public:
  explicit PieceBuilder(double tolerance)
    : Tolerance(tolerance)
  {
  }

  /// A slab's trapezoids are added bottom to top (BeginSlab, Add each, EndSlab): each one continues
  /// the first piece of the slab before whose right side shares a stretch with its left side (a
  /// vertical line then still meets the piece in one interval, so that it stays a simple polygon),
  /// unless a trapezoid below took that piece; otherwise it starts a piece. The pieces that no
  /// trapezoid continues are finished.
  ///
  /// The open pieces are in the order of the slab before's trapezoids, bottom to top, so one pass
  /// up both lists finds the matches: a piece wholly below a trapezoid is below every later one,
  /// and once a piece lies wholly above it so do the rest. (A search of all open pieces for each
  /// trapezoid, with erasing from the middle, made a catchment with 600 small lakes in a column
  /// take 20 s a step: cubic in the lakes.)
  void BeginSlab()
  {
    this->NextOpen.clear();
    this->Taken.assign(this->Open.size(), 0);
    this->First = 0;
  }

  /// Adds the slab's next trapezoid up.
  void Add(const Trapezoid& t)
  {
    std::size_t& first = this->First;
    while (first < this->Open.size() && (this->Taken[first] || this->OpenPiece(first).Below(t)))
    {
      ++first;
    }
    std::size_t k = first;
    while (k < this->Open.size() && !this->OpenPiece(k).Above(t) &&
      (this->Taken[k] || !this->OpenPiece(k).Meets(t)))
    {
      ++k;
    }
    if (k < this->Open.size() && !this->Taken[k] && this->OpenPiece(k).Meets(t))
    {
      this->OpenPiece(k).Extend(t);
      this->NextOpen.push_back(this->Open[k]);
      this->Taken[k] = 1;
    }
    else
    {
      this->NextOpen.push_back(this->StartPiece(t));
    }
  }

  void EndSlab()
  {
    for (std::size_t k = 0; k < this->Open.size(); ++k)
    {
      if (!this->Taken[k])
      {
        this->Finish(this->Open[k]);
      }
    }
    std::swap(this->Open, this->NextOpen);
  }

  ClippedRings Pieces()
  {
    for (const std::size_t p : this->Open)
    {
      this->Finish(p);
    }
    this->Open.clear();
    return this->Done;
  }

private:
  /// A piece's boundary, left to right: its points but the last, and the last (End) apart, which
  /// most slabs replace (the boundary runs on along one edge) and the next slab's matching reads:
  /// kept in the piece, it is read without following a pointer to the vector's heap block (the
  /// wavy shore's 63 tiles: 512 ms with back(), 378 ms with End).
  struct Boundary
  {
    std::vector<Point2> Before;
    Point2 End;
    bool EndIsVertex; // whether End is a vertex of the rings

    void Start(const Corner& left, const Corner& right)
    {
      this->Before.assign(1, left.At);
      this->End = right.At;
      this->EndIsVertex = right.IsVertex;
    }

    void Push(const Point2& p)
    {
      this->Before.push_back(this->End);
      this->End = p;
    }

    /// Taken on to the next slab's side, from left to right: a vertical step first where the
    /// sides' ends differ by more than tolerance (a vertical edge of the rings, or a piece ending
    /// beside this one; less is the rounding of one point seen from two edges); along the same
    /// edge the joint is no corner, and its point is replaced, not kept. Where the sides' ends
    /// are one point, it is the one that is a vertex of the rings, if either is (see SideCorners:
    /// the other's height, interpolated along a steep edge, may be far off).
    void Continue(const Corner& left, const Corner& right, bool sameEdge, double tolerance)
    {
      if (std::fabs(this->End.y - left.At.y) > tolerance)
      {
        this->Push(left.At);
        sameEdge = false;
      }
      else if (left.IsVertex && !this->EndIsVertex)
      {
        this->End = left.At;
      }
      if (sameEdge)
      {
        this->End = right.At;
      }
      else
      {
        this->Push(right.At);
      }
      this->EndIsVertex = right.IsVertex;
    }
  };

  /// Its lower and upper boundaries, the edges of its last trapezoid and the height tolerances of
  /// that one and of all.
  struct Piece
  {
    Boundary Lower, Upper;
    std::size_t Bottom, Top;
    double LastTolerance, LargestTolerance;

    /// Starts it anew as t (keeping the boundaries' buffers).
    void Start(const Trapezoid& t)
    {
      this->Lower.Start(t.BottomLeft, t.BottomRight);
      this->Upper.Start(t.TopLeft, t.TopRight);
      this->Bottom = t.Bottom;
      this->Top = t.Top;
      this->LastTolerance = this->LargestTolerance = t.HeightTolerance;
    }

    /// Whether t's left side and this piece's right side (at the same x) overlap in a stretch
    /// longer than either's height tolerance.
    bool Meets(const Trapezoid& t) const
    {
      return std::min(this->Upper.End.y, t.TopLeft.At.y) -
        std::max(this->Lower.End.y, t.BottomLeft.At.y) >
        std::max(this->LastTolerance, t.HeightTolerance);
    }

    /// Whether this piece's right side lies wholly below t's left side (no stretch in common).
    bool Below(const Trapezoid& t) const { return this->Upper.End.y <= t.BottomLeft.At.y; }

    /// Whether this piece's right side lies wholly above t's left side.
    bool Above(const Trapezoid& t) const { return this->Lower.End.y >= t.TopLeft.At.y; }

    /// Takes in t, which Meets this piece.
    void Extend(const Trapezoid& t)
    {
      const double tolerance = std::max(this->LastTolerance, t.HeightTolerance);
      this->Lower.Continue(t.BottomLeft, t.BottomRight, t.Bottom == this->Bottom, tolerance);
      this->Upper.Continue(t.TopLeft, t.TopRight, t.Top == this->Top, tolerance);
      this->Bottom = t.Bottom;
      this->Top = t.Top;
      this->LastTolerance = t.HeightTolerance;
      this->LargestTolerance = std::max(this->LargestTolerance, t.HeightTolerance);
    }
  };

  Piece& OpenPiece(std::size_t k) { return this->Store[this->Open[k]]; }

  /// A piece started as t, in a slot of Store that a finished piece left, if there is one: not
  /// moved from one slab's list to the next with its two vectors, nor new vectors for each piece
  /// (part of the 577 to 490 ms of SlabSweep's buffers).
  std::size_t StartPiece(const Trapezoid& t)
  {
    if (this->Unused.empty())
    {
      this->Unused.push_back(this->Store.size());
      this->Store.emplace_back();
    }
    const std::size_t p = this->Unused.back();
    this->Unused.pop_back();
    this->Store[p].Start(t);
    return p;
  }

  /// The piece as an anticlockwise ring (lower boundary, then the upper one backwards), points
  /// within the tolerance of the one before counted once (corners where the two boundaries meet,
  /// sides no higher than rounding); a piece of no area is dropped. Its slot is then free.
  void Finish(std::size_t piece)
  {
    const Piece& p = this->Store[piece];
    std::vector<Point2> ring;
    ring.reserve(p.Lower.Before.size() + p.Upper.Before.size() + 2);
    ring.insert(ring.end(), p.Lower.Before.begin(), p.Lower.Before.end());
    ring.push_back(p.Lower.End);
    ring.push_back(p.Upper.End);
    ring.insert(ring.end(), p.Upper.Before.rbegin(), p.Upper.Before.rend());
    const auto near = [&](const Point2& a, const Point2& b) {
      return std::fabs(a.x - b.x) <= this->Tolerance && std::fabs(a.y - b.y) <= p.LargestTolerance;
    };
    ring.erase(std::unique(ring.begin(), ring.end(), near), ring.end());
    while (ring.size() > 1 && near(ring.front(), ring.back()))
    {
      ring.pop_back();
    }
    AppendFans(std::move(ring), this->Done); // (dropped there if it has no area)
    this->Unused.push_back(piece);
  }

  double Tolerance;
  std::vector<Piece> Store;        // the pieces being grown, and slots of finished ones
  std::vector<std::size_t> Unused; // Store's slots of finished pieces
  std::vector<std::size_t> Open; // the pieces that the last slab's trapezoids ended, bottom to top
  std::vector<std::size_t> NextOpen; // (the next slab's Open)
  std::vector<char> Taken;           // per Open piece: whether a trapezoid of this slab took it
  std::size_t First = 0; // Open[0, First): taken, or below every trapezoid still to come
  ClippedRings Done;
};

/// The slabs' edges and trapezoids, slab by slab from left to right. Its buffers are kept from one
/// slab to the next: with a vector of its own for each slab's order, trapezoids and pieces (and
/// PieceBuilder's pool below), the 63 tiles under a wavy shore of 300,000 vertices (20,545 in
/// one ring, some 70 edges a slab) took 577 ms, 490 ms with them kept.
class SlabSweep
{
public:
  SlabSweep(const std::vector<SweepEdge>& edges, double tolerance)
    : Edges(edges)
    , Tolerance(tolerance)
  {
  }

  /// Moves on to the slab left .. right (the next one) and adds the region inside it to pieces,
  /// bottom to top, without slivers no higher than their HeightTolerance.
  void Next(double left, double right, PieceBuilder& pieces)
  {
    this->OrderEdges(left, right);
    pieces.BeginSlab();
    this->CutIntoTrapezoids(left, right, pieces);
    pieces.EndSlab();
  }

private:
  /// Active: the edges spanning the slab, in order of their height at its middle (Lower).
  /// They come in the slab before's order with the entering edges at its end, and edges do not
  /// cross, so that order still holds but for rounding: the entering edges are sorted and merged
  /// in, then an insertion pass mends what rounding swapped, in time linear in the active edges
  /// (a full sort of every slab made a catchment with 600 small lakes in a column take seconds a
  /// step).
  void OrderEdges(double left, double right)
  {
    const std::size_t carried = this->CarryAndEnterEdges(left, right);
    this->SortEnteredIn(carried);
  }

  /// The next slab's edges, with their heights there, into Active: those of the slab before that
  /// span this one, in their order, then those entering at left. Returns how many were carried.
  std::size_t CarryAndEnterEdges(double left, double right)
  {
    const double middle = left + 0.5 * (right - left);
    // (written in place: push_back, not inlined, had 13% of the samples)
    this->Entered.resize(std::max(this->Entered.size(), this->Active.size()));
    std::size_t carried = 0;
    for (const SlabEdge& a : this->Active)
    {
      const SweepEdge& e = this->Edges[a.Edge];
      if (e.Right.x > left)
      {
        this->Entered[carried++] = { HeightAt(e, middle),
          a.Edge,
          a.Winding,
          a.EndsRight,
          EndsAt(e, right),
          a.RightHeight,
          HeightAt(e, right),
          a.Steepness };
      }
    }
    this->Entered.resize(carried);
    for (; this->Entering < this->Edges.size() && this->Edges[this->Entering].Left.x <= left;
         ++this->Entering)
    {
      const SweepEdge& e = this->Edges[this->Entering];
      // (every edge ends at a side: it spans whole slabs)
      this->Entered.push_back({ HeightAt(e, middle),
        this->Entering,
        e.Winding,
        EndsAt(e, left),
        EndsAt(e, right),
        HeightAt(e, left),
        HeightAt(e, right),
        e.Steepness() });
    }
    std::swap(this->Active, this->Entered);
    return carried;
  }

  /// Active in order (Lower): its first `carried` edges are in the slab before's order.
  void SortEnteredIn(std::size_t carried)
  {
    std::vector<SlabEdge>& order = this->Active;
    const auto tail = order.begin() + std::ptrdiff_t(carried);
    // Without a NaN height Lower is a total order (heights, then windings, then distinct edge
    // indices), so that the order it sorts to is one, however found: a few entering edges are
    // placed by the insertion pass alone (std::inplace_merge allocated a buffer at nearly every
    // slab). Many are sorted and merged, not inserted one by one across the slab. A NaN height,
    // which Lower does not order, always takes these steps as they were, to the same order.
    if (tail != order.end() && (order.end() - tail > 8 || HasNaN(order)))
    {
      std::sort(tail, order.end(), Lower);
      std::inplace_merge(order.begin(), tail, order.end(), Lower);
    }
    for (std::size_t i = 1; i < order.size(); ++i)
    {
      if (!Lower(order[i], order[i - 1]))
      {
        continue; // (most: nothing to move, no copy made)
      }
      const SlabEdge item = order[i];
      std::size_t j = i;
      for (; j > 0 && Lower(item, order[j - 1]); --j)
      {
        order[j] = order[j - 1];
      }
      order[j] = item;
    }
  }

  /// The trapezoids of the active edges, added to pieces as they are found (no slab's vector of
  /// them to write and read back). Where the sum of the windings below rises above 0 a trapezoid
  /// starts, where it falls back it ends.
  void CutIntoTrapezoids(double left, double right, PieceBuilder& pieces)
  {
    int winding = 0;
    std::size_t bottom = 0;
    for (std::size_t k = 0; k < this->Active.size(); ++k)
    {
      const int below = winding;
      winding += this->Active[k].Winding;
      if (below <= 0 && winding > 0)
      {
        bottom = k;
      }
      else if (below > 0 && winding <= 0)
      {
        this->AddTrapezoid(this->Active[bottom], this->Active[k], left, right, pieces);
      }
    }
  }

  static bool HasNaN(const std::vector<SlabEdge>& order)
  {
    return std::any_of(
      order.begin(), order.end(), [](const SlabEdge& a) { return std::isnan(a.Middle); });
  }

  /// Adds the trapezoid between bottom and top to pieces, unless it is a sliver between edges along
  /// one line.
  void AddTrapezoid(const SlabEdge& bottom,
    const SlabEdge& top,
    double left,
    double right,
    PieceBuilder& pieces) const
  {
    Trapezoid t;
    t.Bottom = bottom.Edge;
    t.Top = top.Edge;
    t.HeightTolerance = this->Tolerance * (1.0 + std::max(bottom.Steepness, top.Steepness));
    SideCorners(left,
      bottom.LeftHeight,
      bottom.EndsLeft,
      top.LeftHeight,
      top.EndsLeft,
      t.HeightTolerance,
      t.BottomLeft,
      t.TopLeft);
    SideCorners(right,
      bottom.RightHeight,
      bottom.EndsRight,
      top.RightHeight,
      top.EndsRight,
      t.HeightTolerance,
      t.BottomRight,
      t.TopRight);
    if (t.TopLeft.At.y - t.BottomLeft.At.y > t.HeightTolerance ||
      t.TopRight.At.y - t.BottomRight.At.y > t.HeightTolerance)
    {
      pieces.Add(t); // (not a sliver between edges along one line)
    }
  }

  const std::vector<SweepEdge>& Edges; // sorted by their left ends' x
  double Tolerance;                    // PointTolerance
  std::size_t Entering = 0;            // the next edge, by its left end, to enter
  std::vector<SlabEdge> Active;        // the current slab's edges, bottom to top
  std::vector<SlabEdge> Entered;       // (the next order's buffer)
};

/// The region as x-monotone pieces (see the header): slab by slab, left to right.
ClippedRings MonotonePieces(const ClippedRings& rings)
{
  const std::vector<SweepEdge> edges = SweepEdges(rings);
  const std::vector<double> sides = SlabSides(rings);
  const double tolerance = PointTolerance(rings);
  SlabSweep slabs(edges, tolerance);
  PieceBuilder builder(tolerance);
  for (std::size_t s = 0; s + 1 < sides.size(); ++s)
  {
    slabs.Next(sides[s], sides[s + 1], builder);
  }
  return builder.Pieces();
}

} // namespace

double CrossingHeight(const Point2& a, const Point2& b, double x)
{
  const SweepEdge edge = a.x < b.x ? SweepEdge{ a, b, 0 } : SweepEdge{ b, a, 0 };
  return std::clamp(HeightAt(edge, x), std::min(a.y, b.y), std::max(a.y, b.y));
}

ClippedRings DisplayPieces(const ClippedRings& rings)
{
  return MonotonePieces(WithoutEmptyRings(rings));
}

bool StartAtFanApex(std::vector<Point2>& ring)
{
  const std::size_t apex = ring.size() < 3 ? ring.size() : FanApex(ring);
  if (apex == ring.size())
  {
    return false;
  }
  std::rotate(ring.begin(), ring.begin() + std::ptrdiff_t(apex), ring.end());
  return true;
}

} // namespace tessera
