#include "snap_to_segments.h"

#include "polygon_validation.h"
#include "ring_insertions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace tessera
{
namespace
{

struct Segment
{
  std::size_t Ring;
  std::size_t First; ///< index of its first vertex in the caller's array
  Point2 A, B;
};

bool Finite(const Point2& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y);
}

/// Segments indexed by the grid cells they pass near: each is registered in the 3 x 3 cells
/// about points along it no farther apart than half a cell, so a point within the tolerance (far
/// below a cell) of a segment finds it in the point's own cell.
class SegmentGrid
{
public:
  SegmentGrid(const std::vector<Segment>& segments, double cell, const Point2& origin)
    : Cell(cell)
    , Origin(origin)
  {
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      const Segment& seg = segments[s];
      const double length = std::hypot(seg.B.x - seg.A.x, seg.B.y - seg.A.y);
      const std::int64_t steps =
        std::max<std::int64_t>(1, std::int64_t(std::ceil(2.0 * length / cell)));
      std::int64_t lastKey = -1;
      for (std::int64_t i = 0; i <= steps; ++i)
      {
        const double t = double(i) / double(steps);
        const Point2 p{ seg.A.x + t * (seg.B.x - seg.A.x), seg.A.y + t * (seg.B.y - seg.A.y) };
        const auto [cx, cy] = this->CellOf(p);
        const std::int64_t key = Key(cx, cy);
        if (key == lastKey)
        {
          continue;
        }
        lastKey = key;
        for (std::int64_t dx = -1; dx <= 1; ++dx)
        {
          for (std::int64_t dy = -1; dy <= 1; ++dy)
          {
            std::vector<std::size_t>& list = this->Cells[Key(cx + dx, cy + dy)];
            if (list.empty() || list.back() != s)
            {
              list.push_back(s);
            }
          }
        }
      }
    }
  }

  const std::vector<std::size_t>* Near(const Point2& p) const
  {
    const auto [cx, cy] = this->CellOf(p);
    const auto found = this->Cells.find(Key(cx, cy));
    return found == this->Cells.end() ? nullptr : &found->second;
  }

private:
  std::pair<std::int64_t, std::int64_t> CellOf(const Point2& p) const
  {
    return { std::int64_t(std::floor((p.x - this->Origin.x) / this->Cell)),
      std::int64_t(std::floor((p.y - this->Origin.y) / this->Cell)) };
  }
  static std::int64_t Key(std::int64_t cx, std::int64_t cy) { return cx * 4194304 + cy; }

  double Cell;
  Point2 Origin;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> Cells;
};

/// The parameter along segment s at which p lies within tolerance of it (strictly between its
/// ends and farther than the tolerance from both), or a negative number.
double SnapParameter(const Segment& s, const Point2& p, double tolerance)
{
  const double dx = s.B.x - s.A.x, dy = s.B.y - s.A.y;
  const double lengthSquared = dx * dx + dy * dy;
  const double t = ((p.x - s.A.x) * dx + (p.y - s.A.y) * dy) / lengthSquared;
  if (!(t > 0.0 && t < 1.0))
  {
    return -1.0;
  }
  const double offLine =
    std::abs(dx * (p.y - s.A.y) - dy * (p.x - s.A.x)) / std::sqrt(lengthSquared);
  const bool nearEnd = std::hypot(p.x - s.A.x, p.y - s.A.y) <= tolerance ||
    std::hypot(p.x - s.B.x, p.y - s.B.y) <= tolerance;
  return offLine <= tolerance && !nearEnd ? t : -1.0;
}

/// Per ring, the box of its finite vertices (empty, XMin > XMax, where it has none).
std::vector<Box2> RingBoxes(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices)
{
  const std::size_t rings = offsets.empty() ? 0 : offsets.size() - 1;
  std::vector<Box2> boxes(rings, Box2{ HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL });
  for (std::size_t r = 0; r < rings; ++r)
  {
    for (std::size_t k = offsets[r]; k < offsets[r + 1]; ++k)
    {
      if (Finite(vertices[k]))
      {
        boxes[r].Extend(vertices[k]);
      }
    }
  }
  return boxes;
}

/// Per ring, whether its box, grown by the tolerance, meets another ring's: only such rings can
/// hold junctions. (A catchment of one ring, the common case, has none, and a 3 10^5-vertex
/// outline was indexed for nothing: a third of its construction.)
std::vector<char> RingsNearOthers(const std::vector<Box2>& boxes, double tolerance)
{
  // Boxes by their west sides: each meets only boxes that start before its east side.
  std::vector<std::size_t> order(boxes.size());
  for (std::size_t r = 0; r < boxes.size(); ++r)
  {
    order[r] = r;
  }
  std::sort(order.begin(),
    order.end(),
    [&boxes](std::size_t a, std::size_t b) { return boxes[a].XMin < boxes[b].XMin; });
  std::vector<char> near(boxes.size(), 0);
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    const Box2& a = boxes[order[i]];
    for (std::size_t j = i + 1; j < boxes.size() && boxes[order[j]].XMin <= a.XMax + 2 * tolerance;
         ++j)
    {
      const Box2& b = boxes[order[j]];
      if (b.YMin <= a.YMax + 2 * tolerance && a.YMin <= b.YMax + 2 * tolerance)
      {
        near[order[i]] = near[order[j]] = 1;
      }
    }
  }
  return near;
}

/// The segments that may take vertices, with what finding those vertices needs.
struct CandidateSegments
{
  std::vector<Segment> Segments;   ///< of rings near others; finite, of nonzero length
  std::vector<std::size_t> RingOf; ///< per vertex (of every ring)
  Box2 Box{ HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL }; ///< of the rings near others
};

/// The segments of rings near others, and the box of those rings.
CandidateSegments SegmentsNearOthers(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices,
  const std::vector<Box2>& boxes,
  const std::vector<char>& nearOthers)
{
  CandidateSegments found;
  found.RingOf.assign(vertices.size(), 0);
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
  {
    const std::size_t begin = offsets[r], end = offsets[r + 1];
    if (nearOthers[r])
    {
      found.Box.Extend(boxes[r]);
    }
    for (std::size_t k = begin; k < end; ++k)
    {
      found.RingOf[k] = r;
      const Point2& a = vertices[k];
      const Point2& b = vertices[NextInRing(k, begin, end)];
      if (nearOthers[r] && Finite(a) && Finite(b) && !(a == b))
      {
        found.Segments.push_back({ r, k, a, b });
      }
    }
  }
  return found;
}

/// Every vertex of a ring near others within the tolerance of another ring's segment, in the order
/// of the vertices and of the segments in their grid cells. Needs segments and a positive
/// tolerance (the grid's cell is sized by them).
std::vector<RingInsertion> FindInsertions(const std::vector<Point2>& vertices,
  const CandidateSegments& found,
  const std::vector<char>& nearOthers,
  double tolerance)
{
  // Cells about as wide as a segment on average (each segment in a few cells), and far wider
  // than the tolerance.
  const double cell = std::max({ 16.0 * tolerance,
    found.Box.LargerSide() / std::sqrt(double(found.Segments.size())),
    1e-300 });
  const SegmentGrid grid(found.Segments, cell, Point2{ found.Box.XMin, found.Box.YMin });
  const std::vector<std::size_t> none;
  std::vector<RingInsertion> insertions;
  for (std::size_t v = 0; v < vertices.size(); ++v)
  {
    const Point2& p = vertices[v];
    const std::vector<std::size_t>* near =
      Finite(p) && nearOthers[found.RingOf[v]] ? grid.Near(p) : nullptr;
    for (const std::size_t s : near ? *near : none)
    {
      if (found.Segments[s].Ring == found.RingOf[v])
      {
        continue;
      }
      const double t = SnapParameter(found.Segments[s], p, tolerance);
      if (t > 0.0)
      {
        insertions.push_back({ found.Segments[s].First, t, p });
      }
    }
  }
  return insertions;
}

} // namespace

SnappedRings SnapVerticesOntoSegments(const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices,
  double tolerance)
{
  CheckRingOffsets(offsets, vertices.size());
  const std::vector<Box2> boxes = RingBoxes(offsets, vertices);
  const std::vector<char> nearOthers = RingsNearOthers(boxes, tolerance);
  const CandidateSegments found = SegmentsNearOthers(offsets, vertices, boxes, nearOthers);
  std::vector<RingInsertion> insertions;
  if (!found.Segments.empty() && tolerance > 0.0)
  {
    insertions = FindInsertions(vertices, found, nearOthers, tolerance);
  }
  SortAlongEdges(insertions);
  return InsertIntoRings(offsets, vertices, insertions, SegmentNumbers::Kept);
}

} // namespace tessera
