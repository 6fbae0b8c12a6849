#include "piece_outlines.h"

#include "polygon_area.h"
#include "polygon_validation.h" // RingOrientation, RingWinding, SegmentsIntersect
#include "predicates.h"
#include "shared_borders.h" // ShareBorderVertices

#include <algorithm>
#include <cstdint>
#include <map>

namespace tessera
{
namespace
{

struct Edge
{
  Point2 From;
  Point2 To;
};

/// The edges of the pieces' rings that no other ring walks the other way: the region's boundary.
/// Edges are keyed by their ends in (x, y) order; within a key, walks one way cancel walks the
/// other, and what is left over (one walk, for a boundary edge) stays.
std::vector<Edge> BoundaryEdges(const ClippedRings& pieces, std::size_t first, std::size_t last)
{
  struct Walk
  {
    Point2 Low, High;
    bool Upward; // runs from Low to High
  };
  std::vector<Walk> walks;
  for (std::size_t r = first; r < last; ++r)
  {
    const std::size_t begin = pieces.RingOffsets[r], end = pieces.RingOffsets[r + 1];
    for (std::size_t v = begin; v < end; ++v)
    {
      const Point2& a = pieces.Vertices[v];
      const Point2& b = pieces.Vertices[NextInRing(v, begin, end)];
      if (a != b)
      {
        const bool upward = ComesFirst(a, b);
        walks.push_back(upward ? Walk{ a, b, true } : Walk{ b, a, false });
      }
    }
  }
  const auto keyBefore = [](const Walk& p, const Walk& q)
  {
    if (p.Low != q.Low)
    {
      return ComesFirst(p.Low, q.Low);
    }
    return ComesFirst(p.High, q.High);
  };
  std::sort(walks.begin(), walks.end(), keyBefore);
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < walks.size();)
  {
    std::size_t j = i;
    long net = 0;
    for (; j < walks.size() && walks[j].Low == walks[i].Low && walks[j].High == walks[i].High; ++j)
    {
      net += walks[j].Upward ? 1 : -1;
    }
    for (; net > 0; --net)
    {
      edges.push_back(Edge{ walks[i].Low, walks[i].High });
    }
    for (; net < 0; ++net)
    {
      edges.push_back(Edge{ walks[i].High, walks[i].Low });
    }
    i = j;
  }
  return edges;
}

/// Where direction v->w lies when turning clockwise from v->u: 0 for a turn of less than a half,
/// 1 for exactly a half, 2 for more, 3 for a full turn (w on the ray from v through u).
int ClockwiseQuadrant(const Point2& v, const Point2& u, const Point2& w)
{
  const int side = orient2d(v, u, w); // > 0: w left of v->u, a turn of more than a half
  if (side != 0)
  {
    return side < 0 ? 0 : 2;
  }
  const bool sameWay = ((w.x > v.x) == (u.x > v.x)) && ((w.x < v.x) == (u.x < v.x)) &&
    ((w.y > v.y) == (u.y > v.y)) && ((w.y < v.y) == (u.y < v.y));
  return sameWay ? 3 : 1;
}

/// Whether v->a comes before v->b turning clockwise from v->u (exact).
bool ClockwiseBefore(const Point2& v, const Point2& u, const Point2& a, const Point2& b)
{
  const int qa = ClockwiseQuadrant(v, u, a), qb = ClockwiseQuadrant(v, u, b);
  if (qa != qb)
  {
    return qa < qb;
  }
  return (qa == 0 || qa == 2) && orient2d(v, a, b) < 0; // b clockwise from a
}

/// The boundary edges chained into rings, the region on the left of each: at a vertex with several
/// ways out, the first clockwise from the way in (see the header's sketch).
ClippedRings ChainedRings(std::vector<Edge> edges)
{
  std::sort(edges.begin(),
    edges.end(),
    [](const Edge& p, const Edge& q) { return ComesFirst(p.From, q.From); });
  std::vector<char> used(edges.size(), 0);
  const auto waysOut = [&edges](const Point2& v)
  {
    return std::equal_range(edges.begin(),
      edges.end(),
      Edge{ v, v },
      [](const Edge& p, const Edge& q) { return ComesFirst(p.From, q.From); });
  };
  ClippedRings rings;
  for (std::size_t start = 0; start < edges.size(); ++start)
  {
    if (used[start])
    {
      continue;
    }
    used[start] = 1;
    std::size_t current = start;
    while (true)
    {
      rings.Vertices.push_back(edges[current].From);
      const Point2& u = edges[current].From;
      const Point2& v = edges[current].To;
      std::size_t next = edges.size();
      const auto [lo, hi] = waysOut(v);
      for (auto e = lo; e != hi; ++e)
      {
        const std::size_t k = static_cast<std::size_t>(e - edges.begin());
        if ((!used[k] || k == start) &&
          (next == edges.size() || ClockwiseBefore(v, u, edges[k].To, edges[next].To)))
        {
          next = k;
        }
      }
      if (next == edges.size() || next == start)
      {
        break; // closed (no way out is left only for edges that do not balance: never here)
      }
      used[next] = 1;
      current = next;
    }
    rings.RingOffsets.push_back(rings.Vertices.size());
  }
  return rings;
}

/// A ring that passes a vertex more than once (the chaining above joins a hole to the outline, or
/// a lobe to another, where they touch at a point) as the loops between its passes: rings that
/// only touch one another, each simple, as a GIS wants them. Each loop is cut out where the walk
/// comes back to a vertex still open on a stack of the walk's vertices.
void AppendLoops(const Point2* ring, std::size_t count, ClippedRings& out)
{
  std::vector<Point2> sorted(ring, ring + count);
  std::sort(sorted.begin(), sorted.end(), ComesFirst);
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
  {
    out.Vertices.insert(out.Vertices.end(), ring, ring + count); // simple already (most rings)
    out.RingOffsets.push_back(out.Vertices.size());
    return;
  }
  std::vector<Point2> open;
  std::map<Point2, std::size_t, bool (*)(const Point2&, const Point2&)> openAt(ComesFirst);
  for (std::size_t i = 0; i <= count; ++i)
  {
    const Point2& p = ring[i < count ? i : 0];
    const auto again = openAt.find(p);
    if (again != openAt.end())
    {
      const std::size_t from = again->second;
      for (std::size_t k = from; k < open.size(); ++k)
      {
        openAt.erase(open[k]);
      }
      out.Vertices.insert(
        out.Vertices.end(), open.begin() + static_cast<std::ptrdiff_t>(from), open.end());
      out.RingOffsets.push_back(out.Vertices.size());
      open.resize(from);
    }
    openAt.emplace(p, open.size());
    open.push_back(p);
  }
}

/// Whether ring a lies inside ring b (exact), by its first vertex not on b's boundary.
bool RingInside(const Point2* a, std::size_t countA, const Point2* b, std::size_t countB)
{
  for (std::size_t i = 0; i < countA; ++i)
  {
    bool onB = false;
    for (std::size_t k = 0; k < countB && !onB; ++k)
    {
      onB = SegmentsIntersect(a[i], a[i], b[k], b[k + 1 < countB ? k + 1 : 0]);
    }
    if (!onB)
    {
      return RingWinding(b, countB, a[i]) % 2 != 0;
    }
  }
  return false; // (every vertex on b: a and b are one path)
}

/// Where ring r of rings starts.
const Point2* RingAt(const ClippedRings& rings, std::size_t r)
{
  return &rings.Vertices[rings.RingOffsets[r]];
}

/// How many vertices ring r of rings has.
std::size_t RingSize(const ClippedRings& rings, std::size_t r)
{
  return rings.RingOffsets[r + 1] - rings.RingOffsets[r];
}

/// The chained rings cut into loops where they touch themselves.
ClippedRings LoopsOf(const ClippedRings& chained)
{
  ClippedRings loops;
  for (std::size_t r = 0; r + 1 < chained.RingOffsets.size(); ++r)
  {
    AppendLoops(RingAt(chained, r), RingSize(chained, r), loops);
  }
  return loops;
}

/// The loops that bound the region, outer rings (anticlockwise) and holes, each with its area's
/// size and its box (indexed by loop; 0 and an empty box for the others).
struct BoundingLoops
{
  std::vector<std::size_t> Outers, Holes;
  std::vector<double> Areas;
  std::vector<Box2> Boxes;
};

BoundingLoops ClassifyLoops(const ClippedRings& loops)
{
  const std::size_t count = loops.RingOffsets.size() - 1;
  BoundingLoops sorted;
  sorted.Areas.assign(count, 0.0);
  sorted.Boxes.resize(count);
  for (std::size_t r = 0; r < count; ++r)
  {
    const Point2* ring = RingAt(loops, r);
    const std::size_t size = RingSize(loops, r);
    if (size < 3)
    {
      continue;
    }
    // A ring of no area, or whose area's sign is not its turn at its lowest vertex, is no
    // boundary of the region: pieces that overlap (a window's slit some ulps wide, which
    // ShareBorderVertices closed) leave a bow tie of two opposite lobes there.
    const int turn = RingOrientation(ring, size); // (0: flat there; the area tells)
    const double area = CompensatedPolygonArea(ring, size);
    if (area != 0.0 && (turn == 0 || (turn > 0) == (area > 0.0)))
    {
      sorted.Areas[r] = std::abs(area);
      sorted.Boxes[r] = BoundsOf(ring, size);
      (area > 0.0 ? sorted.Outers : sorted.Holes).push_back(r);
    }
  }
  return sorted;
}

/// Per loop, the holes it holds: each hole goes with the smallest outer ring that holds it (the
/// largest outer ring when none does, none when there is no outer ring).
std::vector<std::vector<std::size_t>> HolesByHolder(const ClippedRings& loops,
  const BoundingLoops& sorted)
{
  const std::size_t count = sorted.Areas.size();
  std::vector<std::size_t> bySize = sorted.Outers;
  std::stable_sort(bySize.begin(),
    bySize.end(),
    [&sorted](std::size_t a, std::size_t b) { return sorted.Areas[a] < sorted.Areas[b]; });
  std::vector<std::vector<std::size_t>> holesOf(count);
  for (const std::size_t h : sorted.Holes)
  {
    std::size_t holder = bySize.empty() ? count : bySize.back();
    for (const std::size_t o : bySize)
    {
      if (sorted.Boxes[o].Holds(sorted.Boxes[h]) &&
        RingInside(RingAt(loops, h), RingSize(loops, h), RingAt(loops, o), RingSize(loops, o)))
      {
        holder = o;
        break;
      }
    }
    if (holder < count)
    {
      holesOf[holder].push_back(h);
    }
  }
  return holesOf;
}

} // namespace

RegionOutlines OutlinesOfPieces(const ClippedRings& pieces, std::size_t first, std::size_t last)
{
  const ClippedRings loops = LoopsOf(ChainedRings(BoundaryEdges(pieces, first, last)));
  const BoundingLoops sorted = ClassifyLoops(loops);
  const std::vector<std::vector<std::size_t>> holesOf = HolesByHolder(loops, sorted);
  // Outer rings in the order found: ChainedRings starts each ring at its lowest unused edge.
  RegionOutlines out;
  const auto append = [&](std::size_t r)
  {
    out.Rings.Vertices.insert(
      out.Rings.Vertices.end(), RingAt(loops, r), RingAt(loops, r) + RingSize(loops, r));
    out.Rings.RingOffsets.push_back(out.Rings.Vertices.size());
  };
  for (const std::size_t o : sorted.Outers)
  {
    append(o);
    for (const std::size_t h : holesOf[o])
    {
      append(h);
    }
    out.PolygonOffsets.push_back(out.Rings.RingOffsets.size() - 1);
  }
  return out;
}

RegionOutlines OutlinesOfTilePieces(const ClippedRings& pieces)
{
  const ClippedRings shared = ShareBorderVertices(pieces);
  return OutlinesOfPieces(shared, 0, shared.RingOffsets.size() - 1);
}

void AppendOutlines(const RegionOutlines& more, RegionOutlines& all)
{
  const std::size_t vertices = all.Rings.Vertices.size();
  const std::size_t rings = all.Rings.RingOffsets.size() - 1;
  all.Rings.Vertices.insert(
    all.Rings.Vertices.end(), more.Rings.Vertices.begin(), more.Rings.Vertices.end());
  for (std::size_t r = 1; r < more.Rings.RingOffsets.size(); ++r)
  {
    all.Rings.RingOffsets.push_back(vertices + more.Rings.RingOffsets[r]);
  }
  for (std::size_t p = 1; p < more.PolygonOffsets.size(); ++p)
  {
    all.PolygonOffsets.push_back(rings + more.PolygonOffsets[p]);
  }
}

} // namespace tessera
