#pragma once
// Plain geometric value types shared by every core algorithm.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tessera
{

struct Point2
{
  double x = 0.0;
  double y = 0.0;
};

inline bool operator==(const Point2& a, const Point2& b)
{
  return a.x == b.x && a.y == b.y;
}
inline bool operator!=(const Point2& a, const Point2& b)
{
  return !(a == b);
}

/// An axis-aligned bounding box.
struct Box2
{
  double XMin = 0.0;
  double XMax = 0.0;
  double YMin = 0.0;
  double YMax = 0.0;

  /// The smallest box holding this one and p.
  void Extend(const Point2& p)
  {
    this->XMin = std::min(this->XMin, p.x);
    this->XMax = std::max(this->XMax, p.x);
    this->YMin = std::min(this->YMin, p.y);
    this->YMax = std::max(this->YMax, p.y);
  }
  /// The smallest box holding this one and another.
  void Extend(const Box2& other)
  {
    this->Extend(Point2{ other.XMin, other.YMin });
    this->Extend(Point2{ other.XMax, other.YMax });
  }
  double LargerSide() const { return std::max(this->XMax - this->XMin, this->YMax - this->YMin); }
  /// The largest |coordinate| in the box (what the rounding of its points' coordinates scales
  /// with).
  double LargestMagnitude() const
  {
    return std::max(std::max(std::abs(this->XMin), std::abs(this->XMax)),
      std::max(std::abs(this->YMin), std::abs(this->YMax)));
  }
};

/// The bounding box of count >= 1 points.
inline Box2 BoundsOf(const Point2* points, std::size_t count)
{
  Box2 box{ points[0].x, points[0].x, points[0].y, points[0].y };
  for (std::size_t i = 1; i < count; ++i)
  {
    box.Extend(points[i]);
  }
  return box;
}

/// The smallest box holding all of boxes (at least one): the join of boxes found in chunks.
inline Box2 UnionOf(const std::vector<Box2>& boxes)
{
  Box2 box = boxes.front();
  for (std::size_t k = 1; k < boxes.size(); ++k)
  {
    box.Extend(boxes[k]);
  }
  return box;
}

/// The cell, 0 .. cells - 1, of a coordinate already scaled to cell units (spatial grids and
/// curves). NaN and everything below 0 go to cell 0, everything beyond to the last: a box of
/// subnormal width, or wider than the largest double, makes scales infinite or zero and scaled
/// coordinates NaN (0 * inf), and converting those to an integer is undefined.
inline std::uint32_t GridCell(double scaled, std::uint32_t cells)
{
  return scaled > 0.0 ? std::uint32_t(std::min(scaled, double(cells - 1))) : 0U;
}

/// Whether some vertex equals the one before it, cyclically (the last vertex counts as the one
/// before the first). A pass without branches: almost no polygon has a repeat, and the compaction
/// below copies every vertex (and tag) to find out.
inline bool HasRepeatedVertex(const std::vector<Point2>& polygon)
{
  const std::size_t n = polygon.size();
  bool repeated = n > 1 && polygon[0] == polygon[n - 1];
  for (std::size_t k = 1; k < n; ++k)
  {
    repeated |= polygon[k] == polygon[k - 1];
  }
  return repeated;
}

/// Drops consecutive repeats of a vertex, cyclically (the last vertex equal to the first too):
/// the coinciding rounded ends of a clipped or assembled polygon.
inline void DropRepeatedVertices(std::vector<Point2>& polygon)
{
  if (!HasRepeatedVertex(polygon))
  {
    return;
  }
  polygon.erase(std::unique(polygon.begin(), polygon.end()), polygon.end());
  while (polygon.size() > 1 && polygon.front() == polygon.back())
  {
    polygon.pop_back();
  }
}

/// The same, dropping each removed vertex's tag too (tags[k] goes with polygon[k]). With merged,
/// also lists (kept tag, dropped tag) wherever the two differ: things at one point.
template<class Tag>
void DropRepeatedVertices(std::vector<Point2>& polygon,
  std::vector<Tag>& tags,
  std::vector<std::pair<Tag, Tag>>* merged = nullptr)
{
  if (!HasRepeatedVertex(polygon))
  {
    return;
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k)
  {
    if (kept == 0 || !(polygon[k] == polygon[kept - 1]))
    {
      polygon[kept] = polygon[k];
      tags[kept] = tags[k];
      ++kept;
    }
    else if (merged && tags[k] != tags[kept - 1])
    {
      merged->emplace_back(tags[kept - 1], tags[k]);
    }
  }
  while (kept > 1 && polygon[0] == polygon[kept - 1])
  {
    if (merged && tags[0] != tags[kept - 1])
    {
      merged->emplace_back(tags[0], tags[kept - 1]);
    }
    --kept;
  }
  polygon.resize(kept);
  tags.resize(kept);
}

} // namespace tessera
