#include "polygon_validation.h"

#include "errors.h"
#include "predicates_inline.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace tessera
{
namespace
{

void CheckOffsets(const std::vector<std::size_t>& ringOffsets, std::size_t vertexCount)
{
  if (ringOffsets.size() < 2)
  {
    throw InputError(
      "ring offsets need at least 2 entries (one ring), got " + std::to_string(ringOffsets.size()));
  }
  if (ringOffsets.front() != 0)
  {
    throw InputError("ring offset 0 is " + std::to_string(ringOffsets.front()) + ", expected 0");
  }
  for (std::size_t r = 1; r < ringOffsets.size(); ++r)
  {
    if (ringOffsets[r] < ringOffsets[r - 1])
    {
      throw InputError("ring offset " + std::to_string(r) + " (" + std::to_string(ringOffsets[r]) +
        ") is smaller than the one before it");
    }
  }
  if (ringOffsets.back() != vertexCount)
  {
    throw InputError("last ring offset is " + std::to_string(ringOffsets.back()) +
      ", expected the vertex count " + std::to_string(vertexCount));
  }
}

void CheckFinite(const std::vector<std::size_t>& ringOffsets, const std::vector<Point2>& vertices)
{
  for (std::size_t r = 0; r + 1 < ringOffsets.size(); ++r)
  {
    for (std::size_t v = ringOffsets[r]; v < ringOffsets[r + 1]; ++v)
    {
      const Point2& p = vertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
      {
        const bool nan = std::isnan(p.x) || std::isnan(p.y);
        throw InputError("ring " + std::to_string(r) + " vertex " +
          std::to_string(v - ringOffsets[r]) + " has " +
          (nan ? "a NaN coordinate" : "an infinite coordinate"));
      }
    }
  }
}

// A vertex equal to its successor adds a zero-length segment and nothing else; keeping the last of
// each run makes clean segment k the caller's segment SourceIndex[k].
CleanRings DropRepeats(const std::vector<std::size_t>& ringOffsets,
  const std::vector<Point2>& vertices,
  const std::vector<std::size_t>* segmentOf)
{
  CleanRings clean;
  clean.RingOffsets.push_back(0);
  for (std::size_t r = 0; r + 1 < ringOffsets.size(); ++r)
  {
    const std::size_t begin = ringOffsets[r];
    const std::size_t end = ringOffsets[r + 1];
    for (std::size_t v = begin; v < end; ++v)
    {
      const std::size_t next = v + 1 == end ? begin : v + 1;
      if (vertices[v] != vertices[next])
      {
        clean.Vertices.push_back(vertices[v]);
        clean.SourceIndex.push_back(segmentOf ? (*segmentOf)[v] : v - begin);
      }
    }
    const std::size_t kept = clean.Vertices.size() - clean.RingOffsets.back();
    if (kept < 3)
    {
      throw InputError("ring " + std::to_string(r) + " has fewer than 3 distinct vertices (" +
        std::to_string(kept) + " after dropping repeated consecutive vertices)");
    }
    clean.RingOffsets.push_back(clean.Vertices.size());
  }
  return clean;
}

bool Between(double a, double b, double v)
{
  return std::min(a, b) <= v && v <= std::max(a, b);
}

// c is known to be collinear with a and b.
bool OnSegment(const Point2& a, const Point2& b, const Point2& c)
{
  return Between(a.x, b.x, c.x) && Between(a.y, b.y, c.y);
}

int Sign(double v)
{
  return (v > 0) - (v < 0);
}

struct Segment
{
  std::size_t Ring;
  std::size_t Start; // index into CleanRings::Vertices
  std::size_t End;
  double XMin, XMax, YMin, YMax;
};

std::vector<Segment> CollectSegments(const CleanRings& clean)
{
  std::vector<Segment> segments;
  segments.reserve(clean.Vertices.size());
  for (std::size_t r = 0; r + 1 < clean.RingOffsets.size(); ++r)
  {
    const std::size_t begin = clean.RingOffsets[r];
    const std::size_t end = clean.RingOffsets[r + 1];
    for (std::size_t v = begin; v < end; ++v)
    {
      const std::size_t next = v + 1 == end ? begin : v + 1;
      const Point2& a = clean.Vertices[v];
      const Point2& b = clean.Vertices[next];
      segments.push_back({ r,
        v,
        next,
        std::min(a.x, b.x),
        std::max(a.x, b.x),
        std::min(a.y, b.y),
        std::max(a.y, b.y) });
    }
  }
  return segments;
}

// Neighbouring segments p->x and x->q of one ring share x; they meet elsewhere only when they
// overlap, that is when q lies on the ray from x through p.
bool NeighboursOverlap(const Point2& p, const Point2& x, const Point2& q)
{
  return orient2d_fast(p, x, q) == 0 && Sign(q.x - x.x) == Sign(p.x - x.x) &&
    Sign(q.y - x.y) == Sign(p.y - x.y);
}

// Segment k of a ring runs from its vertex k to vertex k+1 (the last one back to vertex 0).
std::string Describe(const CleanRings& clean, const Segment& s)
{
  return "segment " + std::to_string(clean.SourceIndex[s.Start]);
}

// Returns whether the pair is a defect; neighbours in one ring may share their common vertex.
bool PairIntersects(const CleanRings& clean, const Segment& s, const Segment& t)
{
  const Point2& a = clean.Vertices[s.Start];
  const Point2& b = clean.Vertices[s.End];
  const Point2& c = clean.Vertices[t.Start];
  const Point2& d = clean.Vertices[t.End];
  if (s.Ring == t.Ring)
  {
    if (s.End == t.Start)
    {
      return NeighboursOverlap(a, b, d);
    }
    if (t.End == s.Start)
    {
      return NeighboursOverlap(c, d, b);
    }
  }
  return SegmentsIntersect(a, b, c, d);
}

[[noreturn]] void ReportIntersection(const CleanRings& clean, const Segment& s, const Segment& t)
{
  const Segment& first = s.Start < t.Start ? s : t;
  const Segment& second = s.Start < t.Start ? t : s;
  std::ostringstream text;
  if (first.Ring == second.Ring)
  {
    text << "ring " << first.Ring << " is self-intersecting: " << Describe(clean, first) << " and "
         << Describe(clean, second) << " touch or cross";
  }
  else
  {
    text << "ring " << first.Ring << " " << Describe(clean, first) << " and ring " << second.Ring
         << " " << Describe(clean, second)
         << " touch or cross (rings must be disjoint; holes and islands are separate rings)";
  }
  throw InputError(text.str());
}

// Sweep over segments sorted by their left end: a segment is compared only with those whose
// x-extents overlap it, then by y-extent, then exactly.
void CheckIntersections(const CleanRings& clean)
{
  std::vector<Segment> segments = CollectSegments(clean);
  std::sort(segments.begin(),
    segments.end(),
    [](const Segment& s, const Segment& t)
    { return s.XMin < t.XMin || (s.XMin == t.XMin && s.Start < t.Start); });
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    const Segment& s = segments[i];
    for (std::size_t j = i + 1; j < segments.size() && segments[j].XMin <= s.XMax; ++j)
    {
      const Segment& t = segments[j];
      if (t.YMax < s.YMin || s.YMax < t.YMin)
      {
        continue;
      }
      if (PairIntersects(clean, s, t))
      {
        ReportIntersection(clean, s, t);
      }
    }
  }
}

} // namespace

bool SegmentsIntersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  const int o1 = orient2d_fast(a, b, c);
  const int o2 = orient2d_fast(a, b, d);
  const int o3 = orient2d_fast(c, d, a);
  const int o4 = orient2d_fast(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0)
  {
    return true;
  }
  return (o1 == 0 && OnSegment(a, b, c)) || (o2 == 0 && OnSegment(a, b, d)) ||
    (o3 == 0 && OnSegment(c, d, a)) || (o4 == 0 && OnSegment(c, d, b));
}

CleanRings ValidateRings(const std::vector<std::size_t>& ringOffsets,
  const std::vector<Point2>& vertices,
  const std::vector<std::size_t>* segmentOf)
{
  CheckOffsets(ringOffsets, vertices.size());
  if (segmentOf && segmentOf->size() != vertices.size())
  {
    throw InputError("ValidateRings: " + std::to_string(segmentOf->size()) +
      " segment numbers for " + std::to_string(vertices.size()) + " vertices");
  }
  CheckFinite(ringOffsets, vertices);
  CleanRings clean = DropRepeats(ringOffsets, vertices, segmentOf);
  CheckIntersections(clean);
  return clean;
}

} // namespace tessera
