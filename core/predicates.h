#pragma once
// Exact geometric predicates: a fast floating-point filter with a static error bound, falling back
// to exact expansion arithmetic when the filter cannot decide. Never build with -ffast-math.
//
// Sign conventions (y axis up):
//   orient2d(a, b, c) > 0  when a, b, c turn anticlockwise (c lies left of the directed line a->b),
//                     < 0  when they turn clockwise, 0 when collinear.
//   incircle(a, b, c, d) > 0 when d lies strictly inside the circle through a, b, c given
//                        anticlockwise; < 0 outside; 0 co-circular. (Sign flips if a, b, c are
//                        clockwise.)
// Both return -1, 0 or +1 and are exact for every finite double input.

#include "geometry.h"

namespace tessera
{

int orient2d(const Point2& a, const Point2& b, const Point2& c);
int incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

} // namespace tessera
