#pragma once
// Plain geometric value types shared by every core algorithm.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace tessera
{

/// pi, as the double nearest it (what std::acos(-1.0) gives).
constexpr double Pi = 3.14159265358979323846;

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

  /// A box holding no point: its bounds are inverted infinities, so it contains no point and meets
  /// no box, and the first point it is extended by becomes its box.
  static Box2 Empty()
  {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return Box2{ inf, -inf, inf, -inf };
  }
  /// The smallest box holding this one and p.
  void Extend(const Point2& p)
  {
    this->XMin = std::min(this->XMin, p.x);
    this->XMax = std::max(this->XMax, p.x);
    this->YMin = std::min(this->YMin, p.y);
    this->YMax = std::max(this->YMax, p.y);
  }
  /// The smallest box holding this one and another (bound by bound, so that an empty other,
  /// Box2::Empty(), adds nothing).
  void Extend(const Box2& other)
  {
    this->XMin = std::min(this->XMin, other.XMin);
    this->XMax = std::max(this->XMax, other.XMax);
    this->YMin = std::min(this->YMin, other.YMin);
    this->YMax = std::max(this->YMax, other.YMax);
  }
  double LargerSide() const { return std::max(this->XMax - this->XMin, this->YMax - this->YMin); }
  /// Whether the two boxes have a point in common (closed: boxes that touch meet).
  bool Meets(const Box2& other) const
  {
    return this->XMin <= other.XMax && other.XMin <= this->XMax && this->YMin <= other.YMax &&
      other.YMin <= this->YMax;
  }
  /// Whether the two boxes share an area (boxes that only touch do not).
  bool Overlaps(const Box2& other) const
  {
    return this->XMin < other.XMax && other.XMin < this->XMax && this->YMin < other.YMax &&
      other.YMin < this->YMax;
  }
  /// Whether inner lies in this box (closed; false where a bound is NaN).
  bool Holds(const Box2& inner) const
  {
    return this->XMin <= inner.XMin && inner.XMax <= this->XMax && this->YMin <= inner.YMin &&
      inner.YMax <= this->YMax;
  }
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

/// The order in which constructions take their points: by x, then by y (two distinct points are
/// never tied). The engines give a face centre its first three points in this order and clip a
/// tile edge from the first of its two points (circumcentre.h), and sum an area from a polygon's
/// first vertex in it: by coordinates, not ids, so that the bits do not depend on how the points
/// are numbered (a shuffled gauge list, or the areal average's incremental and rebuilt
/// tessellations, which number the same gauges differently, give the same tiles). Written without
/// branches (which of two points comes first is close to random): callers sort with it.
inline bool ComesFirst(const Point2& p, const Point2& q)
{
  return (p.x < q.x) | ((p.x == q.x) & (p.y < q.y));
}

/// The index after k of a ring stored as begin .. end - 1, which closes on itself: the second
/// vertex of the ring's edge from k.
inline std::size_t NextInRing(std::size_t k, std::size_t begin, std::size_t end)
{
  return k + 1 < end ? k + 1 : begin;
}

/// Whether c, known to lie on the line through a and b (an exact orientation of 0), lies on the
/// closed segment a-b: exact, by its coordinates.
inline bool OnSegment(const Point2& a, const Point2& b, const Point2& c)
{
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
    c.y <= std::max(a.y, b.y);
}

/// The first vertex of a ring (count >= 1) by ComesFirst.
inline std::size_t LowestVertex(const Point2* ring, std::size_t count)
{
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < count; ++i)
  {
    lowest = ComesFirst(ring[i], ring[lowest]) ? i : lowest;
  }
  return lowest;
}

/// The exponent e of a power of two above a finite magnitude (0 for 0): values of at most that
/// magnitude divided by 2^e lie in (-1, 1), exactly unless they fall below the normal doubles. For
/// sums that would overflow (RaG curves and pixel means of points near 1e306) and for tests that
/// multiply coordinates (shared borders at 1e308).
inline int ExponentAbove(double magnitude)
{
  return magnitude > 0.0 ? std::ilogb(magnitude) + 1 : 0;
}

/// The cell, 0 .. cells - 1, of a coordinate already scaled to cell units (spatial grids and
/// curves). NaN and everything below 0 go to cell 0, everything beyond to the last: a box of
/// subnormal width, or wider than the largest double, makes scales infinite or zero and scaled
/// coordinates NaN (0 * inf), and converting those to an integer is undefined.
inline std::uint32_t GridCell(double scaled, std::uint32_t cells)
{
  return scaled > 0.0 ? std::uint32_t(std::min(scaled, double(cells - 1))) : 0U;
}

/// Whether some vertex equals the one before it or the one two before, cyclically (the last
/// vertices count as the ones before the first). A pass without branches: almost no polygon has a
/// repeat, and the compaction below copies every vertex (and tag) to find out.
inline bool HasRepeatedVertex(const std::vector<Point2>& polygon)
{
  const std::size_t n = polygon.size();
  if (n < 2)
  {
    return false;
  }
  bool repeated = polygon[0] == polygon[n - 1];
  if (n > 2)
  {
    repeated |= polygon[0] == polygon[n - 2];
    repeated |= polygon[1] == polygon[n - 1]; // (not `a | b` of bools: clang's -Wall warns)
  }
  for (std::size_t k = 1; k < n; ++k)
  {
    repeated |= polygon[k] == polygon[k - 1];
  }
  for (std::size_t k = 2; k < n; ++k)
  {
    repeated |= polygon[k] == polygon[k - 2];
  }
  return repeated;
}

namespace polygon_detail
{
/// Tags that go nowhere: DropRepeatedVertices without tags.
struct NoTags
{
  struct Tag
  {
    bool operator!=(const Tag&) const { return false; }
  };
  Tag operator[](std::size_t) const { return {}; }
  Tag& operator[](std::size_t) { return this->Dummy; }
  void resize(std::size_t) {}
  Tag Dummy;
};
} // namespace polygon_detail

/// Drops repeats of a vertex in a closed polygon, with each removed vertex's tag (tags[k] goes
/// with polygon[k]): consecutive repeats, cyclically (the coinciding rounded ends of a clipped or
/// assembled polygon), and spikes X, Y, X, which keep one X only, wherever Y is: out to Y and
/// back encloses no area, and the polygon would not be simple. (Where it arises: rounding can
/// give two distinct faces around a tile one rounded centre, with a third an ulp away between
/// them, and the tile's side X - Y would be used by four tile sides where the neighbours meet.)
/// A triangle X, Y, X becomes X alone. With merged, also lists (kept tag, dropped tag) of two
/// vertices at one point wherever the tags differ (a spike's Y is at a point of its own).
///
///   ... W  X  Y  X  Z ...   ->   ... W  X  Z ...        (in tiles: Y an ulp from X; W, Z far)
template<class Polygon, class Tags, class Merged>
void DropRepeatedVerticesAndSpikes(Polygon& polygon, Tags& tags, Merged* merged)
{
  const auto drop = [&](std::size_t kept, std::size_t dropped)
  {
    if (merged && tags[kept] != tags[dropped])
    {
      merged->emplace_back(tags[kept], tags[dropped]);
    }
  };
  std::size_t size = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k)
  {
    polygon[size] = polygon[k];
    tags[size] = tags[k];
    ++size;
    for (;;)
    {
      if (size >= 2 && polygon[size - 1] == polygon[size - 2])
      {
        drop(size - 2, size - 1);
        size -= 1;
      }
      else if (size >= 3 && polygon[size - 1] == polygon[size - 3])
      {
        drop(size - 3, size - 1);
        size -= 2;
      }
      else
      {
        break;
      }
    }
  }
  // Across the end: the last vertices before the first ones.
  std::size_t front = 0;
  for (;;)
  {
    const std::size_t n = size - front;
    if (n >= 2 && polygon[front] == polygon[size - 1])
    {
      drop(front, size - 1);
      size -= 1;
    }
    else if (n >= 3 && polygon[size - 2] == polygon[front])
    {
      drop(front, size - 2); // X (size - 2), Y (size - 1), X (front): keep X (front)
      size -= 2;
    }
    else if (n >= 3 && polygon[size - 1] == polygon[front + 1])
    {
      drop(front + 1, size - 1); // X (size - 1), Y (front), X (front + 1): keep X (front + 1)
      front += 1;
      size -= 1;
    }
    else
    {
      break;
    }
  }
  if (front > 0)
  {
    for (std::size_t k = front; k < size; ++k)
    {
      polygon[k - front] = polygon[k];
      tags[k - front] = tags[k];
    }
    size -= front;
  }
  polygon.resize(size);
  tags.resize(size);
}

/// Drops repeated vertices and spikes (DropRepeatedVerticesAndSpikes), without tags.
inline void DropRepeatedVertices(std::vector<Point2>& polygon)
{
  if (!HasRepeatedVertex(polygon))
  {
    return;
  }
  polygon_detail::NoTags none;
  using NoPairs = std::vector<std::pair<polygon_detail::NoTags::Tag, polygon_detail::NoTags::Tag>>;
  DropRepeatedVerticesAndSpikes(polygon, none, static_cast<NoPairs*>(nullptr));
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
  DropRepeatedVerticesAndSpikes(polygon, tags, merged);
}

} // namespace tessera
