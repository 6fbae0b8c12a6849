#pragma once
// Plain geometric value types shared by every core algorithm.

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

} // namespace tessera
