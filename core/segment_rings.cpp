// JoinSegmentsIntoRings: each point's segments found by sorting the segment ends by point id,
// paired at each point, then each cycle of pairs walked from one of its segments (see
// segment_rings.h).
#include "segment_rings.h"

#include "predicates.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace tessera
{

namespace
{
struct End
{
  std::int64_t Point;
  std::size_t Segment;
  bool operator<(const End& o) const
  {
    return this->Point != o.Point ? this->Point < o.Point : this->Segment < o.Segment;
  }
};

/// Whether direction a (from centre) comes before direction b going anticlockwise from the
/// positive x axis, exactly: first the upper half (the positive axis included), then orient2d.
bool ComesBeforeAnticlockwise(const Point2& centre, const Point2& a, const Point2& b)
{
  const auto lower = [&centre](const Point2& q)
  { return q.y < centre.y || (q.y == centre.y && q.x < centre.x); };
  if (lower(a) != lower(b))
  {
    return !lower(a);
  }
  return orient2d(centre, a, b) > 0;
}

/// Records that a walk through `point` goes on from segment s into segment t, and back.
void Link(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments,
  std::int64_t point,
  std::size_t s,
  std::size_t t,
  std::vector<std::int64_t>& across)
{
  across[2 * s + (segments[s].first == point ? 0 : 1)] = std::int64_t(t);
  across[2 * t + (segments[t].first == point ? 0 : 1)] = std::int64_t(s);
}

/// Pairs the ends ends[first, last) of one point (of the segments' point ids: places[point]) where
/// four, six, ... segments meet: by angle around the point, each end with the next, so that the
/// rings through it touch there and never cross. False, pairing none, where two segments leave in
/// one direction (overlapping: no pairing would make rings that validation accepts). (No place
/// here is NaN: a NaN end has a place of its own, so its chain was cut as a dead end.)
bool PairByAngle(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments,
  const std::vector<Point2>& places,
  std::vector<End>& ends,
  std::size_t first,
  std::size_t last,
  std::vector<std::int64_t>& across)
{
  const std::int64_t point = ends[first].Point;
  const Point2 centre = places[std::size_t(point)];
  const auto far = [&](const End& end)
  {
    const auto& [a, b] = segments[end.Segment];
    return places[std::size_t(a == point ? b : a)];
  };
  const auto begin = ends.begin() + std::ptrdiff_t(first);
  const auto end = ends.begin() + std::ptrdiff_t(last);
  std::sort(begin,
    end,
    [&](const End& a, const End& b) { return ComesBeforeAnticlockwise(centre, far(a), far(b)); });
  for (std::size_t k = first; k + 1 < last; ++k)
  {
    if (!ComesBeforeAnticlockwise(centre, far(ends[k]), far(ends[k + 1])))
    {
      return false; // one direction twice
    }
  }
  for (std::size_t k = first; k < last; k += 2)
  {
    Link(segments, point, ends[k].Segment, ends[k + 1].Segment, across);
  }
  return true;
}

/// Per segment, whether it lies on a closed path of the segments: the others, dead ends and the
/// chains that lead to them, are cut away from each point left with one segment, point by point.
/// A contour through a saddle may have closed lobes and open branches there (to the edge of its
/// domain): pairing by angle among the lobes' segments alone keeps the lobes, whatever the
/// picture's rotation (a lobe's side was paired with a branch, and both were lost, in some
/// rotations). ends: both ends of each proper segment, sorted by point.
std::vector<char> OffDeadEnds(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments,
  const std::vector<End>& ends)
{
  std::vector<char> live(segments.size(), 0);
  std::vector<std::size_t> groupBegin; // point g's ends: ends[groupBegin[g], groupBegin[g + 1])
  std::vector<std::size_t> groupOfEnd(ends.size());
  std::vector<std::size_t> otherEnd(ends.size()); // the place in ends of the segment's other end
  std::vector<std::size_t> firstEndAt(segments.size());
  for (std::size_t k = 0; k < ends.size(); ++k)
  {
    if (k == 0 || ends[k].Point != ends[k - 1].Point)
    {
      groupBegin.push_back(k);
    }
    groupOfEnd[k] = groupBegin.size() - 1;
    const std::size_t s = ends[k].Segment;
    if (live[s])
    {
      otherEnd[k] = firstEndAt[s];
      otherEnd[firstEndAt[s]] = k;
    }
    live[s] = 1;
    firstEndAt[s] = k;
  }
  groupBegin.push_back(ends.size());
  std::vector<std::size_t> degree(groupBegin.size() - 1), loose;
  for (std::size_t g = 0; g + 1 < groupBegin.size(); ++g)
  {
    degree[g] = groupBegin[g + 1] - groupBegin[g];
    if (degree[g] == 1)
    {
      loose.push_back(g);
    }
  }
  while (!loose.empty())
  {
    const std::size_t g = loose.back();
    loose.pop_back();
    for (std::size_t k = groupBegin[g]; degree[g] == 1 && k < groupBegin[g + 1]; ++k)
    {
      if (live[ends[k].Segment])
      {
        live[ends[k].Segment] = 0;
        degree[g] = 0;
        const std::size_t h = groupOfEnd[otherEnd[k]];
        if (--degree[h] == 1)
        {
          loose.push_back(h);
        }
      }
    }
  }
  return live;
}

/// Appends the closed walk `walk` (point ids, the first not repeated) to result as rings in which
/// no point stands twice: where the walk comes back to a point it stood on, the loop since then
/// is a ring of its own (the segments, and so the even-odd region, are the same).
///
///     a-------b-------e      the walk a b c d b e f g (back to a) stands on b twice:
///     |      / \      |      b c d is cut off as a ring of its own and a b e f g stays,
///     |     d---c     |      the two touching at b (a hole touching its outline)
///     g---------------f
void AppendSimpleRings(const std::vector<std::int64_t>& walk,
  std::vector<std::int64_t>& stack,
  std::unordered_map<std::int64_t, std::size_t>& placeInStack,
  SegmentRings& result)
{
  stack.clear();
  placeInStack.clear();
  for (const std::int64_t point : walk)
  {
    const auto [it, isNew] = placeInStack.emplace(point, stack.size());
    if (isNew)
    {
      stack.push_back(point);
      continue;
    }
    const std::size_t from = it->second; // the loop stack[from] .. (back to point)
    result.Ids.insert(result.Ids.end(), stack.begin() + std::ptrdiff_t(from), stack.end());
    result.Offsets.push_back(result.Ids.size());
    for (std::size_t k = from + 1; k < stack.size(); ++k)
    {
      placeInStack.erase(stack[k]);
    }
    stack.resize(from + 1);
  }
  result.Ids.insert(result.Ids.end(), stack.begin(), stack.end());
  result.Offsets.push_back(result.Ids.size());
}

/// Both ends of every proper segment (one whose ends differ), sorted: grouped by point.
std::vector<End> EndsByPoint(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments)
{
  std::vector<End> ends;
  ends.reserve(2 * segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    if (segments[s].first != segments[s].second)
    {
      ends.push_back({ segments[s].first, s });
      ends.push_back({ segments[s].second, s });
    }
  }
  std::sort(ends.begin(), ends.end());
  return ends;
}

/// Fills across (see JoinSegments) point by point, from ends grouped by point (each group is
/// reordered, its live ends first): a point of two live segments links them, and with places one
/// of four, six, ... is paired by angle. Whether a point was paired by angle, so that a walk may
/// come back to a point.
bool PairAtEachPoint(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments,
  const std::vector<Point2>* places,
  const std::vector<char>& live,
  std::vector<End>& ends,
  std::vector<std::int64_t>& across)
{
  bool junctions = false;
  for (std::size_t k = 0; k < ends.size();)
  {
    std::size_t end = k;
    while (end < ends.size() && ends[end].Point == ends[k].Point)
    {
      ++end;
    }
    // The point's live ends first: [k, last).
    const std::size_t last = std::size_t(std::stable_partition(ends.begin() + std::ptrdiff_t(k),
                                           ends.begin() + std::ptrdiff_t(end),
                                           [&live](const End& e) { return live[e.Segment] != 0; }) -
      ends.begin());
    if (last - k == 2)
    {
      // (a segment cannot meet itself: its ends differ)
      Link(segments, ends[k].Point, ends[k].Segment, ends[k + 1].Segment, across);
    }
    else if (places && last - k >= 4 && (last - k) % 2 == 0)
    {
      junctions = PairByAngle(segments, *places, ends, k, last, across) || junctions;
    }
    k = end;
  }
  return junctions;
}

/// Walks the cycle of pairs from segment `start` along its direction, entering each next segment
/// at the shared point, and marks each segment it takes seen; walk: those segments, in order.
/// Whether the walk closed at start's first point. A walk that meets a point without a partner
/// fails; so does every other segment of its chain, which its own walk then meets as already seen.
bool WalkCycle(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments,
  const std::vector<std::int64_t>& across,
  std::size_t start,
  std::vector<char>& seen,
  std::vector<std::size_t>& walk)
{
  walk.assign(1, start);
  seen[start] = 1;
  std::size_t s = start;
  std::int64_t at = segments[s].second; // the point the walk stands on, leaving s
  for (;;)
  {
    const int end = segments[s].first == at ? 0 : 1;
    const std::int64_t next = across[2 * s + end];
    if (next < 0)
    {
      return false;
    }
    if (std::size_t(next) == start)
    {
      return at == segments[start].first;
    }
    if (seen[std::size_t(next)])
    {
      return false;
    }
    s = std::size_t(next);
    seen[s] = 1;
    walk.push_back(s);
    at = segments[s].first == at ? segments[s].second : segments[s].first;
  }
}

/// Scratch space for the rings of closed walks, kept from walk to walk.
struct WalkBuffers
{
  std::vector<std::size_t> Walk; // segments
  std::vector<std::int64_t> Points, Stack;
  std::unordered_map<std::int64_t, std::size_t> PlaceInStack;
};

/// Marks the segments of the closed walk in buffers.Walk joined and appends its points to result:
/// one ring, or where junctions were paired (a walk may come back to a point) rings in which no
/// point stands twice.
void AppendWalk(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments,
  bool junctions,
  WalkBuffers& buffers,
  std::vector<char>& joined,
  SegmentRings& result)
{
  std::int64_t point = segments[buffers.Walk.front()].first;
  buffers.Points.clear();
  for (const std::size_t w : buffers.Walk)
  {
    joined[w] = 1;
    buffers.Points.push_back(point);
    point = segments[w].first == point ? segments[w].second : segments[w].first;
  }
  if (junctions)
  {
    AppendSimpleRings(buffers.Points, buffers.Stack, buffers.PlaceInStack, result);
  }
  else
  {
    result.Ids.insert(result.Ids.end(), buffers.Points.begin(), buffers.Points.end());
    result.Offsets.push_back(result.Ids.size());
  }
}

/// The segments not joined, ascending.
std::vector<std::size_t> UnjoinedSegments(const std::vector<char>& joined)
{
  std::vector<std::size_t> unjoined;
  for (std::size_t s = 0; s < joined.size(); ++s)
  {
    if (!joined[s])
    {
      unjoined.push_back(s);
    }
  }
  return unjoined;
}

/// JoinSegmentsIntoRings, and with places (coordinates by point id) JoinSegmentsAtEqualEnds'
/// pairing of the segments by angle where more than two meet.
SegmentRings JoinSegments(const std::vector<std::pair<std::int64_t, std::int64_t>>& segments,
  const std::vector<Point2>* places)
{
  SegmentRings result;
  const std::size_t count = segments.size();
  std::vector<End> ends = EndsByPoint(segments);
  // With places, only the segments on closed paths are paired (the others stay unjoined).
  const std::vector<char> live = places ? OffDeadEnds(segments, ends) : std::vector<char>(count, 1);
  // Per segment and end (0: first, 1: second), the other segment at that point, or -1 when the
  // point has not exactly two segments (nor, with places, an even number paired by angle).
  std::vector<std::int64_t> across(2 * count, -1);
  const bool junctions = PairAtEachPoint(segments, places, live, ends, across);
  // Walk each cycle of pairs once, from its first segment.
  std::vector<char> seen(count, 0);
  std::vector<char> joined(count, 0);
  WalkBuffers buffers;
  for (std::size_t start = 0; start < count; ++start)
  {
    if (seen[start] || segments[start].first == segments[start].second)
    {
      continue;
    }
    if (WalkCycle(segments, across, start, seen, buffers.Walk))
    {
      AppendWalk(segments, junctions, buffers, joined, result);
    }
  }
  result.Unjoined = UnjoinedSegments(joined);
  return result;
}

} // namespace

SegmentRings JoinSegmentsIntoRings(
  const std::vector<std::pair<std::int64_t, std::int64_t>>& segments)
{
  return JoinSegments(segments, nullptr);
}

PointRings JoinSegmentsAtEqualEnds(const std::vector<Point2>& ends)
{
  // Each end numbered by its place: the ends sorted by (x, y), equal ones given one number. An end
  // with a NaN coordinate equals none (and would break the sort's order): a place of its own, for
  // the ring's validation to name.
  std::vector<std::int64_t> place(ends.size());
  std::vector<Point2> places;
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < ends.size(); ++k)
  {
    if (std::isnan(ends[k].x) || std::isnan(ends[k].y))
    {
      place[k] = std::int64_t(places.size());
      places.push_back(ends[k]);
    }
    else
    {
      order.push_back(k);
    }
  }
  const auto before = [&ends](std::size_t a, std::size_t b)
  { return ends[a].x != ends[b].x ? ends[a].x < ends[b].x : ends[a].y < ends[b].y; };
  std::sort(order.begin(), order.end(), before);
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    if (k == 0 || !(ends[order[k]] == ends[order[k - 1]]))
    {
      places.push_back(ends[order[k]]);
    }
    place[order[k]] = std::int64_t(places.size()) - 1;
  }
  std::vector<std::pair<std::int64_t, std::int64_t>> segments(ends.size() / 2);
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    segments[s] = { place[2 * s], place[2 * s + 1] };
  }
  const SegmentRings joined = JoinSegments(segments, &places);
  PointRings rings;
  rings.Offsets = joined.Offsets;
  rings.Vertices.reserve(joined.Ids.size());
  std::vector<char> onRing(places.size(), 0);
  for (const std::int64_t id : joined.Ids)
  {
    rings.Vertices.push_back(places[std::size_t(id)]);
    onRing[std::size_t(id)] = 1;
  }
  // A segment of no length at a point of a ring adds nothing to it (vtkContourFilter gives one
  // between two ids of one point): it is not listed. One elsewhere is. (An end with a NaN
  // coordinate has a place of its own, so such a segment has two.)
  for (const std::size_t s : joined.Unjoined)
  {
    const auto [from, to] = segments[s];
    if (!(from == to && onRing[std::size_t(from)]))
    {
      rings.Unjoined.push_back(s);
    }
  }
  return rings;
}

} // namespace tessera
