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
// All return -1, 0 or +1 and are exact for every finite double input (any magnitudes, subnormals
// included); a NaN or infinite input gives an unspecified sign but no crash.
// core/predicates_inline.h has the same predicates with the floating-point filter inlined.

#include "geometry.h"

namespace tessera
{

int orient2d(const Point2& a, const Point2& b, const Point2& c);
int incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

/// Which of a, b is nearer to p: the sign of |p - a|^2 - |p - b|^2, exactly. Negative when a is
/// strictly nearer, positive when b is, 0 when p is equidistant (on the bisector of a and b).
int compare_distance(const Point2& p, const Point2& a, const Point2& b);

/// The sign of a * p.x + b * p.y + c, exactly (no rounding of the products or the sum).
int affine_sign(double a, double b, double c, const Point2& p);

/// The sign of the 3x3 determinant with rows (a1, b1, c1), (a2, b2, c2), (a3, b3, c3), exactly.
/// For lines a*x + b*y + c = 0 it tells on which side of line 3 the crossing of lines 1 and 2
/// lies: sign(a3*x + b3*y + c3) at that crossing is this sign times sign(a1*b2 - a2*b1).
int determinant3_sign(double a1,
  double b1,
  double c1,
  double a2,
  double b2,
  double c2,
  double a3,
  double b3,
  double c3);

/// A vector held exactly as the unevaluated sums x + xTail and y + yTail, where x is the double
/// nearest to x + xTail (|xTail| at most half an ulp of x), and likewise y: e.g. the exact
/// difference of two points (exact_offset), or twice it (a reflection in an axis-parallel line).
struct Offset2
{
  double x = 0.0;
  double xTail = 0.0;
  double y = 0.0;
  double yTail = 0.0;
};

/// q - p, exactly.
Offset2 exact_offset(const Point2& q, const Point2& p);

/// The sign of u.x * v.y - u.y * v.x, exactly: orient2d(o, o + u, o + v) for any origin o.
int cross_sign(const Offset2& u, const Offset2& v);

/// incircle(o + a, o + b, o + c, o) for any origin o, exactly: the sign of the incircle
/// determinant of three points given by their exact offsets from the fourth.
int incircle_offsets(const Offset2& a, const Offset2& b, const Offset2& c);

} // namespace tessera
