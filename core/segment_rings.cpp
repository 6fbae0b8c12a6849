// JoinSegmentsIntoRings: each point's segments found by sorting the segment ends by point id,
// then each component walked from one of its segments (see segment_rings.h).
#include "segment_rings.h"

#include <algorithm>
#include <cmath>

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
} // namespace

SegmentRings JoinSegmentsIntoRings(
  const std::vector<std::pair<std::int64_t, std::int64_t>>& segments)
{
  SegmentRings result;
  const std::size_t count = segments.size();
  // ends: both ends of every proper segment, grouped by point.
  std::vector<End> ends;
  ends.reserve(2 * count);
  for (std::size_t s = 0; s < count; ++s)
  {
    if (segments[s].first != segments[s].second)
    {
      ends.push_back({ segments[s].first, s });
      ends.push_back({ segments[s].second, s });
    }
  }
  std::sort(ends.begin(), ends.end());
  // Per segment and end (0: first, 1: second), the other segment at that point, or -1 when the
  // point does not have exactly two segments.
  std::vector<std::int64_t> across(2 * count, -1);
  for (std::size_t k = 0; k < ends.size();)
  {
    std::size_t last = k;
    while (last < ends.size() && ends[last].Point == ends[k].Point)
    {
      ++last;
    }
    if (last - k == 2)
    {
      const std::size_t s = ends[k].Segment, t = ends[k + 1].Segment;
      if (s != t) // (a segment cannot meet itself: its ends differ)
      {
        across[2 * s + (segments[s].first == ends[k].Point ? 0 : 1)] = std::int64_t(t);
        across[2 * t + (segments[t].first == ends[k].Point ? 0 : 1)] = std::int64_t(s);
      }
    }
    k = last;
  }
  // Walk each component once: from segment `start` along its direction, entering each next
  // segment at the shared point. A walk that meets a point without a partner fails; so does every
  // other segment of its component, which its own walk then meets as already seen.
  std::vector<char> seen(count, 0);
  std::vector<char> joined(count, 0);
  std::vector<std::size_t> walk;
  for (std::size_t start = 0; start < count; ++start)
  {
    if (seen[start] || segments[start].first == segments[start].second)
    {
      continue;
    }
    walk.assign(1, start);
    seen[start] = 1;
    std::size_t s = start;
    std::int64_t at = segments[s].second; // the point the walk stands on, leaving s
    bool closed = false;
    for (;;)
    {
      const int end = segments[s].first == at ? 0 : 1;
      const std::int64_t next = across[2 * s + end];
      if (next < 0)
      {
        break;
      }
      if (std::size_t(next) == start)
      {
        closed = at == segments[start].first;
        break;
      }
      if (seen[std::size_t(next)])
      {
        break;
      }
      s = std::size_t(next);
      seen[s] = 1;
      walk.push_back(s);
      at = segments[s].first == at ? segments[s].second : segments[s].first;
    }
    if (!closed)
    {
      continue;
    }
    std::int64_t point = segments[start].first;
    for (const std::size_t w : walk)
    {
      joined[w] = 1;
      result.Ids.push_back(point);
      point = segments[w].first == point ? segments[w].second : segments[w].first;
    }
    result.Offsets.push_back(result.Ids.size());
  }
  for (std::size_t s = 0; s < count; ++s)
  {
    if (!joined[s])
    {
      result.Unjoined.push_back(s);
    }
  }
  return result;
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
  const SegmentRings joined = JoinSegmentsIntoRings(segments);
  PointRings rings;
  rings.Offsets = joined.Offsets;
  rings.Vertices.reserve(joined.Ids.size());
  for (const std::int64_t id : joined.Ids)
  {
    rings.Vertices.push_back(places[std::size_t(id)]);
  }
  rings.Unjoined = joined.Unjoined;
  return rings;
}

} // namespace tessera
