#pragma once
// The circumcentre of three points in doubles (a construction, rounded; every decision about it
// is made by exact predicates elsewhere), shared by both engines so that a Voronoi vertex gets
// the same bits from each.
//
// Conditioning. The centre is computed relative to one vertex o as o + u, with u from the two
// sides leaving o. Rounding the squares of those sides errs by ulps of their squared lengths, and
// dividing by twice the signed area amplifies that by (side length / distance of the third point
// from the side): for a sliver whose two close points are not at o, u can be off by far more
// than the sliver is wide (points 1e-13 apart, 650 away: 100 off), or the rounded area can be 0.
// So when the side opposite the first vertex a is under 2^-10 of the others, o is b instead (an
// end of that short side; the error is then at most 2^-33 of the sliver's width), and the area
// is recomputed from exact products where its two products nearly cancel.
//
//     b
//     |\___________________                 o = a normally; o = b when |bc| << |ab|, |ac|
//     c                    \____________ a
//
// The test is one comparison that almost never holds, so typical triangles pay a few flops.

#include "expansion_arithmetic.h"
#include "geometry.h"

#include <algorithm>
#include <cmath>

namespace tessera
{

/// Twice the signed area of the triangle with sides (bx, by) and (cx, cy) from one vertex:
/// bx * cy - by * cx, recomputed from exact products where the rounded products cancel to less
/// than 2^-26 of their size (so the result has a small relative error, and is 0 only for
/// collinear sides).
inline double TwiceSignedArea(double bx, double by, double cx, double cy)
{
  const double p = bx * cy, q = by * cx;
  const double d = p - q;
  if (std::fabs(d) > 0x1p-26 * (std::fabs(p) + std::fabs(q)))
  {
    return d;
  }
  double pHigh, pLow, qHigh, qLow;
  expansion::two_product(bx, cy, pHigh, pLow);
  expansion::two_product(by, cx, qHigh, qLow);
  return (pHigh - qHigh) + (pLow - qLow); // pHigh - qHigh is exact here (Sterbenz)
}

/// The centre as Origin + (ux, uy), with the sides from Origin, their squared lengths and twice
/// the signed area d, as Circumcentre's error bound uses them.
struct CircumcentreTerms
{
  Point2 Origin;
  double bx, by, cx, cy, b2, c2, d, ux, uy;
};

inline void SidesFrom(const Point2& o, const Point2& b, const Point2& c, CircumcentreTerms& t)
{
  t.Origin = o;
  t.bx = b.x - o.x;
  t.by = b.y - o.y;
  t.cx = c.x - o.x;
  t.cy = c.y - o.y;
  t.b2 = t.bx * t.bx + t.by * t.by;
  t.c2 = t.cx * t.cx + t.cy * t.cy;
}

/// a, b, c in the engines' canonical order (ascending ids); see the conditioning note above.
inline CircumcentreTerms CircumcentreOffset(const Point2& a, const Point2& b, const Point2& c)
{
  CircumcentreTerms t;
  SidesFrom(a, b, c, t);
  const double ex = c.x - b.x, ey = c.y - b.y;
  if (ex * ex + ey * ey < 0x1p-20 * std::min(t.b2, t.c2))
  {
    SidesFrom(b, c, a, t); // a cyclic turn: the orientation is kept
  }
  t.d = 2.0 * TwiceSignedArea(t.bx, t.by, t.cx, t.cy);
  t.ux = (t.cy * t.b2 - t.by * t.c2) / t.d;
  t.uy = (t.bx * t.c2 - t.cx * t.b2) / t.d;
  return t;
}

/// The circumcentre of a, b, c (given in the engines' canonical order: ascending ids).
inline Point2 CircumcentreOf(const Point2& a, const Point2& b, const Point2& c)
{
  const CircumcentreTerms t = CircumcentreOffset(a, b, c);
  return { t.Origin.x + t.ux, t.Origin.y + t.uy };
}

} // namespace tessera
