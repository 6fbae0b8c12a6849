#include "shared_borders.h"

#include "cache_line.h"
#include "parallel_chunks.h"
#include "predicates.h"
#include "ring_insertions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace tessera
{
namespace
{

constexpr double ToleranceUlps = 64.0;

// Vertices per thread looking for the edges they lie inside: enough to pay for a pass on the
// cores (a vertex tries some ten to a hundred edges, 0.1 to 1 us).
constexpr std::int64_t VerticesPerThread = 20000;

double Tolerance(const Point2& a, const Point2& b)
{
  const double largest =
    std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y) });
  return ToleranceUlps * (std::nextafter(largest, HUGE_VAL) - largest);
}

// The parameter along a -> b of v when v lies inside the edge (within tolerance of its line,
// farther than that from either end); otherwise a negative number.
double InsideParameter(const Point2& a, const Point2& b, const Point2& v)
{
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length = std::hypot(dx, dy);
  if (!(length > 0.0))
  {
    return -1.0;
  }
  const double wx = v.x - a.x, wy = v.y - a.y;
  const double along = (wx * dx + wy * dy) / length;
  const double off = std::fabs(wx * dy - wy * dx) / length;
  const double tolerance = Tolerance(a, b);
  if (off > tolerance || along <= tolerance || along >= length - tolerance)
  {
    return -1.0;
  }
  return along / length;
}

// ShareBorderVertices works on coordinates scaled below 1 in magnitude, where an ulp is at most
// 2^-53: no edge's Tolerance there exceeds this.
constexpr double LargestScaledTolerance = ToleranceUlps * 0x1p-53;

// Whether v lies in the box of a -> b widened by twice LargestScaledTolerance (scaled
// coordinates). A vertex outside it is inside no edge (InsideParameter), and this test costs four
// comparisons where that one costs a hypot and a nextafter: a cell along a detailed catchment
// outline lists a hundred of its edges (3 10^5 vertices), and every vertex in the cell was tried on
// every one. (Twice: at once, a vertex 64 ulps off an edge's line, to an ulp, could fall outside
// the box by its sides' rounding and be inside the edge by InsideParameter's.)
bool InEdgeBox(const Point2& a, const Point2& b, const Point2& v)
{
  const double m = 2.0 * LargestScaledTolerance;
  return v.x >= std::min(a.x, b.x) - m && v.x <= std::max(a.x, b.x) + m &&
    v.y >= std::min(a.y, b.y) - m && v.y <= std::max(a.y, b.y) + m;
}

// A grid over the vertices' box whose cells list the edges that pass through them (widened by
// twice the largest tolerance): about one vertex a cell, and an edge listed only in the cells along
// it, so that long slanted edges (the tiles of a transect's gauges) cost their length in cells, not
// their box.
class EdgeGrid
{
public:
  EdgeGrid(const std::vector<Point2>& v, const std::vector<std::size_t>& next)
  {
    for (const Point2& p : v)
    {
      this->Low = { std::min(this->Low.x, p.x), std::min(this->Low.y, p.y) };
      this->High = { std::max(this->High.x, p.x), std::max(this->High.y, p.y) };
    }
    this->ChooseCells(v.size());
    this->Starts.assign(std::size_t(this->Columns) * this->Rows + 1, 0);
    // Two passes: count each cell's edges, then fill them in (a flat array, cell by cell, each
    // cell's edges ascending).
    std::vector<std::size_t> fill;
    for (int pass = 0; pass < 2; ++pass)
    {
      for (std::size_t e = 0; e < v.size(); ++e)
      {
        this->ForEachCellAlong(v[e],
          v[next[e]],
          [&](std::size_t cell)
          {
            if (pass == 0)
            {
              ++this->Starts[cell + 1];
            }
            else
            {
              this->Edges[fill[cell]++] = e;
            }
          });
      }
      if (pass == 0)
      {
        for (std::size_t c = 1; c < this->Starts.size(); ++c)
        {
          this->Starts[c] += this->Starts[c - 1];
        }
        this->Edges.resize(this->Starts.back());
        fill.assign(this->Starts.begin(), this->Starts.end() - 1);
      }
    }
  }

  // The edges listed in the cell of p: [first, last), ascending. (Found once per vertex: a loop
  // to end(p) had found the cell again at every edge it tried.)
  std::pair<const std::size_t*, const std::size_t*> EdgesAt(const Point2& p) const
  {
    const std::size_t cell = this->Cell(p);
    return { this->Edges.data() + this->Starts[cell], this->Edges.data() + this->Starts[cell + 1] };
  }

private:
  // About one cell a vertex, at most 2^20, the cells about square: with as many columns as rows,
  // 10^5 pieces stacked in a column made every horizontal edge cross hundreds of cells (7.8 s).
  void ChooseCells(std::size_t vertices)
  {
    constexpr double MaxCells = 1048576.0;
    const double cells = std::clamp(double(vertices), 1.0, MaxCells);
    const double width = this->High.x - this->Low.x, height = this->High.y - this->Low.y;
    const double aspect = width > 0.0 && height > 0.0 ? width / height : 1.0;
    const double columns = std::clamp(std::round(std::sqrt(cells * aspect)), 1.0, cells);
    this->Columns = static_cast<int>(columns);
    this->Rows = static_cast<int>(std::clamp(std::round(cells / columns), 1.0, cells));
  }

  // Calls f(cell) for each cell that a -> b, widened by twice the largest tolerance, meets:
  // column by column, the rows of the edge's stretch over that column. (The largest, not the
  // edge's own: it saves a nextafter per edge, and the own tolerance of an edge near 0 is finer
  // than the rounding of the cells' sides, computed from the box's corners.)
  template<typename F>
  void ForEachCellAlong(const Point2& a, const Point2& b, F&& f) const
  {
    const double margin = 2.0 * LargestScaledTolerance;
    const double left = std::min(a.x, b.x), right = std::max(a.x, b.x);
    const int x0 = Index(left - margin, this->Low.x, this->High.x, this->Columns);
    const int x1 = Index(right + margin, this->Low.x, this->High.x, this->Columns);
    const double columnWidth = (this->High.x - this->Low.x) / this->Columns;
    for (int x = x0; x <= x1; ++x)
    {
      double yLow = std::min(a.y, b.y), yHigh = std::max(a.y, b.y);
      if (a.x != b.x && x0 != x1)
      {
        const double from = std::max(left, this->Low.x + x * columnWidth - margin);
        const double to = std::min(right, this->Low.x + (x + 1) * columnWidth + margin);
        const double slope = (b.y - a.y) / (b.x - a.x);
        const double yFrom = a.y + (from - a.x) * slope, yTo = a.y + (to - a.x) * slope;
        yLow = std::max(yLow, std::min(yFrom, yTo));
        yHigh = std::min(yHigh, std::max(yFrom, yTo));
      }
      const int y0 = Index(yLow - margin, this->Low.y, this->High.y, this->Rows);
      const int y1 = Index(yHigh + margin, this->Low.y, this->High.y, this->Rows);
      for (int y = y0; y <= y1; ++y)
      {
        f(std::size_t(y) * this->Columns + x);
      }
    }
  }

  static int Index(double c, double low, double high, int count)
  {
    const double width = high - low;
    if (!(width > 0.0))
    {
      return 0;
    }
    const double cell = std::floor((c - low) / width * count);
    return static_cast<int>(std::clamp(cell, 0.0, double(count - 1)));
  }

  std::size_t Cell(const Point2& p) const
  {
    return std::size_t(Index(p.y, this->Low.y, this->High.y, this->Rows)) * this->Columns +
      Index(p.x, this->Low.x, this->High.x, this->Columns);
  }

  Point2 Low{ HUGE_VAL, HUGE_VAL };
  Point2 High{ -HUGE_VAL, -HUGE_VAL };
  int Columns = 1;
  int Rows = 1;
  std::vector<std::size_t> Starts;
  std::vector<std::size_t> Edges;
};

// The representative of k's group (union-find with path halving).
std::size_t Root(std::vector<std::size_t>& parent, std::size_t k)
{
  while (parent[k] != k)
  {
    parent[k] = parent[parent[k]];
    k = parent[k];
  }
  return k;
}

// Links (union-find, parent) each vertex to the vertices of other pieces within the tolerance
// of it; order: the vertices by ComesFirst. Runs of one x, ascending y within each: a vertex
// looks at the runs within the tolerance to its right, and in each at the stretch within the
// tolerance of its y only (the pieces' vertical cuts, and a catchment edge on the central
// meridian, put thousands of vertices on one x). Whether any were linked.
bool LinkNearCopies(const std::vector<Point2>& v,
  const std::vector<std::size_t>& ringOf,
  const std::vector<std::size_t>& order,
  std::vector<std::size_t>& parent)
{
  std::vector<std::size_t> runEnd(order.size());
  for (std::size_t i = order.size(); i-- > 0;)
  {
    runEnd[i] = i + 1 < order.size() && v[order[i + 1]].x == v[order[i]].x ? runEnd[i + 1] : i + 1;
  }
  const auto yOf = [&](std::size_t k, double y) { return v[k].y < y; };
  bool joined = false;
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    const Point2& p = v[order[i]];
    const double tolerance = Tolerance(p, p);
    for (std::size_t run = i + 1; run < order.size() && v[order[run]].x - p.x <= tolerance;
         run = runEnd[run])
    {
      const auto end = order.begin() + std::ptrdiff_t(runEnd[run]);
      for (auto b =
             std::lower_bound(order.begin() + std::ptrdiff_t(run), end, p.y - tolerance, yOf);
           b != end && v[*b].y <= p.y + tolerance;
           ++b)
      {
        if (ringOf[order[i]] != ringOf[*b])
        {
          parent[Root(parent, order[i])] = Root(parent, *b);
          joined = true;
        }
      }
    }
  }
  return joined;
}

// Per group root, 1 for a group left apart: a piece has two distinct vertices in it (made one,
// they would fold its ring; copies of one point in one piece, as a ring through a point twice
// has, do not), or a vertex lies beyond the tolerance of the group's smallest (a chain of copies
// each near the next: five 50 ulps apart moved the last by 200).
std::vector<char> GroupsLeftApart(const std::vector<Point2>& v,
  const std::vector<std::size_t>& ringOf,
  std::vector<std::size_t>& parent,
  const std::vector<std::size_t>& smallest,
  std::vector<std::size_t> grouped)
{
  // By group, then piece: records sorted, not indices whose roots each comparison looked up (this
  // stage took a third of the near copies' time under a detailed outline). Which of a run of one
  // group and piece comes first does not matter: if two of it differ, two next to each other do.
  struct Member
  {
    std::size_t Root, Ring, Vertex;
  };
  std::vector<Member> members;
  members.reserve(grouped.size());
  for (const std::size_t k : grouped)
  {
    members.push_back({ Root(parent, k), ringOf[k], k });
  }
  std::sort(members.begin(),
    members.end(),
    [](const Member& a, const Member& b)
    { return a.Root != b.Root ? a.Root < b.Root : a.Ring < b.Ring; });
  std::vector<char> apart(v.size(), 0);
  for (std::size_t i = 1; i < members.size(); ++i)
  {
    const Member& a = members[i - 1];
    const Member& b = members[i];
    if (a.Root == b.Root && a.Ring == b.Ring && !(v[a.Vertex] == v[b.Vertex]))
    {
      apart[a.Root] = 1;
    }
  }
  for (const std::size_t k : grouped)
  {
    const std::size_t root = Root(parent, k);
    const Point2& to = v[smallest[root]];
    const double tolerance = Tolerance(to, v[k]);
    apart[root] |= std::fabs(to.x - v[k].x) > tolerance || std::fabs(to.y - v[k].y) > tolerance;
  }
  return apart;
}

// Per group of near copies (by its root): its smallest vertex (by ComesFirst; order: the vertices
// in that order); and the vertices in groups of two or more, ascending.
struct CopyGroups
{
  std::vector<std::size_t> Smallest, Grouped;
};

CopyGroups GroupsOfCopies(const std::vector<std::size_t>& order, std::vector<std::size_t>& parent)
{
  const std::size_t n = order.size();
  CopyGroups groups;
  groups.Smallest.assign(n, SIZE_MAX);
  std::vector<std::size_t> size(n, 0);
  for (const std::size_t k : order) // (ascending: a group's first is its smallest)
  {
    const std::size_t root = Root(parent, k);
    groups.Smallest[root] = groups.Smallest[root] == SIZE_MAX ? k : groups.Smallest[root];
    ++size[root];
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    if (size[Root(parent, k)] > 1)
    {
      groups.Grouped.push_back(k);
    }
  }
  return groups;
}

// Per vertex, the vertex it is made: itself if its group is left apart, else its group's smallest.
void PlaceOnSmallest(std::vector<std::size_t>& parent,
  const std::vector<std::size_t>& smallest,
  const std::vector<char>& apart,
  std::vector<std::size_t>& made)
{
  for (std::size_t k = 0; k < made.size(); ++k)
  {
    const std::size_t root = Root(parent, k);
    made[k] = apart[root] ? k : smallest[root];
  }
}

// Leaves groups apart, too, where a corner would turn the other way, its vertex or a neighbour
// moved (a sliver piece's apex, moved onto a copy across its opposite edge, folded it flat): the
// groups of the three are left, and the corners are looked at again until none turns. A straight
// corner may bend (a vertex on its piece's edge, welded to a copy an ulp off it).
void LeaveApartWhereCornersTurn(const std::vector<Point2>& v,
  const std::vector<std::size_t>& prev,
  const std::vector<std::size_t>& next,
  std::vector<std::size_t>& parent,
  const std::vector<std::size_t>& smallest,
  std::vector<char>& apart,
  std::vector<std::size_t>& made)
{
  for (bool turned = true; turned;)
  {
    turned = false;
    for (std::size_t k = 0; k < v.size(); ++k)
    {
      const std::size_t a = prev[k], b = next[k];
      if (made[a] == a && made[k] == k && made[b] == b)
      {
        continue;
      }
      const int before = orient2d(v[a], v[k], v[b]);
      if (before != 0 && orient2d(v[made[a]], v[made[k]], v[made[b]]) != before)
      {
        for (const std::size_t moved : { a, k, b })
        {
          const std::size_t root = Root(parent, moved);
          turned |= made[moved] != moved && !apart[root];
          apart[root] = 1;
        }
      }
    }
    if (turned)
    {
      PlaceOnSmallest(parent, smallest, apart, made);
    }
  }
}

// The vertices' indices by ComesFirst, copies of one point by index: records of coordinates and
// index sorted, so that a comparison reads its operands in place, not two vertices anywhere in
// memory (some 10^6 vertices under a detailed outline).
std::vector<std::size_t> InOrder(const std::vector<Point2>& v)
{
  struct Keyed
  {
    Point2 At;
    std::size_t Vertex;
  };
  std::vector<Keyed> keyed(v.size());
  for (std::size_t k = 0; k < v.size(); ++k)
  {
    keyed[k] = { v[k], k };
  }
  std::sort(keyed.begin(),
    keyed.end(),
    [](const Keyed& a, const Keyed& b)
    { return ComesFirst(a.At, b.At) || (!ComesFirst(b.At, a.At) && a.Vertex < b.Vertex); });
  std::vector<std::size_t> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    order[i] = keyed[i].Vertex;
  }
  return order;
}

// Per vertex, the vertex it is made (itself, or the smallest, by ComesFirst, of a group of copies
// of one point in different pieces within the tolerance of each other; prev and next: each
// vertex's neighbours in its ring). Each piece computed its own copy (both tiles cut at one x, a
// crossing computed from either end), and copies an ulp or two apart stayed apart in lon/lat: a
// GIS's union of the pieces kept zero-width slivers there, 2 to 10 a month in Colorado. Groups
// that would fold a piece are left apart (GroupsLeftApart; corners that would turn:
// LeaveApartWhereCornersTurn).
std::vector<std::size_t> NearCopiesMadeOne(const std::vector<Point2>& v,
  const std::vector<std::size_t>& ringOf,
  const std::vector<std::size_t>& prev,
  const std::vector<std::size_t>& next)
{
  const std::vector<std::size_t> order = InOrder(v);
  std::vector<std::size_t> parent(v.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  std::vector<std::size_t> made(v.size());
  std::iota(made.begin(), made.end(), std::size_t(0));
  if (!LinkNearCopies(v, ringOf, order, parent))
  {
    return made;
  }
  CopyGroups groups = GroupsOfCopies(order, parent);
  std::vector<char> apart =
    GroupsLeftApart(v, ringOf, parent, groups.Smallest, std::move(groups.Grouped));
  PlaceOnSmallest(parent, groups.Smallest, apart, made);
  LeaveApartWhereCornersTurn(v, prev, next, parent, groups.Smallest, apart, made);
  return made;
}

// The largest magnitude of the vertices' coordinates, or NaN when one is not finite.
double LargestCoordinate(const std::vector<Point2>& vertices)
{
  double largest = 0.0;
  for (const Point2& p : vertices)
  {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
    {
      return std::nan("");
    }
    largest = std::max({ largest, std::fabs(p.x), std::fabs(p.y) });
  }
  return largest;
}

// The vertices of pieces scaled by 2^-exponent (exact), with each vertex's ring and its
// neighbours in that ring.
struct ScaledPieces
{
  std::vector<Point2> Vertices;
  std::vector<std::size_t> RingOf, Next, Prev;
};

ScaledPieces Scaled(const ClippedRings& given, int exponent)
{
  ScaledPieces s;
  s.Vertices.resize(given.Vertices.size());
  s.RingOf.resize(s.Vertices.size());
  s.Next.resize(s.Vertices.size());
  s.Prev.resize(s.Vertices.size());
  for (std::size_t r = 0; r + 1 < given.RingOffsets.size(); ++r)
  {
    const std::size_t begin = given.RingOffsets[r], end = given.RingOffsets[r + 1];
    for (std::size_t k = begin; k < end; ++k)
    {
      s.Vertices[k] = { std::ldexp(given.Vertices[k].x, -exponent),
        std::ldexp(given.Vertices[k].y, -exponent) };
      s.RingOf[k] = r;
      s.Next[k] = NextInRing(k, begin, end);
      s.Prev[k] = k > begin ? k - 1 : end - 1;
    }
  }
  return s;
}

// Moves each vertex onto the one it is made (made: NearCopiesMadeOne), both in pieces (from
// given's coordinates) and in v (their scaled copies).
void WeldNearCopies(const ClippedRings& given,
  const std::vector<std::size_t>& made,
  ClippedRings& pieces,
  std::vector<Point2>& v)
{
  const std::vector<Point2> unmoved = v;
  for (std::size_t k = 0; k < v.size(); ++k)
  {
    pieces.Vertices[k] = given.Vertices[made[k]];
    v[k] = unmoved[made[k]];
  }
}

// Appends (edge, t, own[k]) for each edge listed in the grid where vertex k lies that k lies
// inside (InsideParameter, on the scaled vertices s.Vertices), in the order of the cell's list.
void AddEdgesHolding(const ScaledPieces& s,
  const EdgeGrid& grid,
  std::size_t k,
  const std::vector<Point2>& own,
  std::vector<RingInsertion>& insertions)
{
  const std::vector<Point2>& v = s.Vertices;
  const auto [first, last] = grid.EdgesAt(v[k]);
  for (const std::size_t* e = first; e != last; ++e)
  {
    const Point2& a = v[*e];
    const Point2& b = v[s.Next[*e]];
    if (s.RingOf[*e] == s.RingOf[k] || !InEdgeBox(a, b, v[k]))
    {
      continue; // (its own piece's edge, never: the ring is simple; or too far to be inside)
    }
    const double t = InsideParameter(a, b, v[k]);
    if (t > 0.0)
    {
      insertions.push_back({ *e, t, own[k] });
    }
  }
}

// Each vertex that lies inside an edge of another piece, with its coordinates from own; in the
// order of the vertices and of the edges in their grid cells. The vertices in chunks on the cores
// (3 10^5 outline vertices: some 40 10^6 vertex-edge pairs tried a time step), their lists joined
// in order: the same list on any number of threads.
std::vector<RingInsertion> VerticesInsideEdges(const ScaledPieces& s,
  const std::vector<Point2>& own)
{
  const EdgeGrid grid(s.Vertices, s.Next);
  const std::size_t n = s.Vertices.size();
  const std::vector<std::int32_t> bounds = parallel::ChunkBounds(
    std::int32_t(n), parallel::ThreadCount(std::int64_t(n), VerticesPerThread));
  std::vector<OwnCacheLines<std::vector<RingInsertion>>> found(bounds.size() - 1);
  parallel::RunChunks(found.size(),
    [&](std::size_t chunk)
    {
      for (std::size_t k = std::size_t(bounds[chunk]); k < std::size_t(bounds[chunk + 1]); ++k)
      {
        AddEdgesHolding(s, grid, k, own, found[chunk].Value);
      }
    });
  std::vector<RingInsertion> insertions = std::move(found[0].Value);
  for (std::size_t chunk = 1; chunk < found.size(); ++chunk)
  {
    insertions.insert(insertions.end(), found[chunk].Value.begin(), found[chunk].Value.end());
  }
  return insertions;
}

} // namespace

ClippedRings ShareBorderVertices(const ClippedRings& given)
{
  // The tests run on the vertices scaled by a power of two to a largest coordinate below 1
  // (exact): coordinates of 1e308 overflowed the grid's box, and beyond some 1e154 the products
  // of InsideParameter did. Vertices that are not finite are left as they are, unshared.
  const double largest = LargestCoordinate(given.Vertices);
  if (std::isnan(largest) || largest == 0.0)
  {
    return given;
  }
  ScaledPieces scaled = Scaled(given, ExponentAbove(largest));
  ClippedRings pieces = given;
  const std::vector<std::size_t> made =
    NearCopiesMadeOne(scaled.Vertices, scaled.RingOf, scaled.Prev, scaled.Next);
  WeldNearCopies(given, made, pieces, scaled.Vertices);
  std::vector<RingInsertion> insertions = VerticesInsideEdges(scaled, pieces.Vertices);
  if (insertions.empty())
  {
    return pieces;
  }
  SortAlongEdges(insertions);
  InsertedRings shared =
    InsertIntoRings(pieces.RingOffsets, pieces.Vertices, insertions, SegmentNumbers::Dropped);
  return { std::move(shared.Offsets), std::move(shared.Vertices) };
}

void DensifyRingSymmetrically(const Point2* ring,
  std::size_t count,
  double step,
  std::vector<Point2>& out)
{
  out.clear();
  for (std::size_t k = 0; k < count; ++k)
  {
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % count];
    out.push_back(a);
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int pieces = step > 0.0 ? std::max(1, static_cast<int>(std::ceil(length / step))) : 1;
    const bool fromA = a.x < b.x || (a.x == b.x && a.y <= b.y);
    const Point2& p = fromA ? a : b;
    const Point2& q = fromA ? b : a;
    for (int i = 1; i < pieces; ++i)
    {
      const double t = static_cast<double>(fromA ? i : pieces - i) / pieces;
      out.push_back({ p.x + t * (q.x - p.x), p.y + t * (q.y - p.y) });
    }
  }
}

} // namespace tessera
