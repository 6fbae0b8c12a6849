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
//
// Two things the doubles cannot fix: sides that are not exact differences (points near the
// origin with very different exponents), amplified by a nearly collinear triple (a vertex 2.66
// off along a sliver 20 long), and squared sides that underflow (points a subnormal distance
// apart: a vertex 12.6 off, or NaN). When the area's condition (the size of its products over
// their difference) exceeds 2^6, or the squares or the area leave the safe range, the offset is
// recomputed from exact sides, scaled by a power of two, with exact numerators and denominator
// (expansions), each rounded to a few ulps (ExactCircumcentreOffset, circumcentre.cpp). The
// rounded formula loses about the condition's bits: at 2^16 (the line once drawn) flat
// triangles and slivers came some 16 bits off (8.7e-12 of the circumradius); at 2^6, some 1 in
// 8000 triangles of uniform points take the exact path, and the worst measured is 2.4e-13.

#include "geometry.h"

#include <algorithm>
#include <cmath>

namespace tessera
{

/// bx * cy - by * cx from exact products, rounded (circumcentre.cpp).
double ExactTwiceSignedArea(double bx, double by, double cx, double cy);

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
  return ExactTwiceSignedArea(bx, by, cx, cy);
}

/// The centre as Origin + (ux, uy), with the sides from Origin, their squared lengths, twice the
/// signed area d and the size of its products |bx cy| + |by cx|, as Circumcentre's error bound
/// uses them.
struct CircumcentreTerms
{
  Point2 Origin;
  double bx, by, cx, cy, b2, c2, d, products, ux, uy;
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

/// The ill-conditioned case of CircumcentreOffset (circumcentre.cpp), for the sides from t.Origin
/// to b and c already in t: t.d from TwiceSignedArea, and (t.ux, t.uy) from exact sides and exact
/// numerators and denominator, accurate to a few ulps (ExactCircumcentreOffset).
void IllConditionedCircumcentre(const Point2& b, const Point2& c, CircumcentreTerms& t);

/// a, b, c in the engines' canonical order (ComesFirst); see the conditioning note above.
inline CircumcentreTerms CircumcentreOffset(const Point2& a, const Point2& b, const Point2& c)
{
  CircumcentreTerms t;
  SidesFrom(a, b, c, t);
  const double ex = c.x - b.x, ey = c.y - b.y;
  const bool turned = ex * ex + ey * ey < 0x1p-20 * std::min(t.b2, t.c2);
  if (turned)
  {
    SidesFrom(b, c, a, t); // a cyclic turn: the orientation is kept
  }
  // The area's products, once: a difference above 2^-6 of their size is well conditioned (and
  // is what TwiceSignedArea would return). Written so that NaN and infinities fail the test.
  const double p = t.bx * t.cy, q = t.by * t.cx;
  const double twice = p - q;
  t.products = std::fabs(p) + std::fabs(q);
  const bool wellConditioned = std::fabs(twice) > 0x1p-6 * t.products &&
    std::fabs(twice) >= 0x1p-900 && std::min(t.b2, t.c2) >= 0x1p-900 &&
    std::max(t.b2, t.c2) <= 0x1p900;
  if (wellConditioned)
  {
    t.d = 2.0 * twice;
    t.ux = (t.cy * t.b2 - t.by * t.c2) / t.d;
    t.uy = (t.bx * t.c2 - t.cx * t.b2) / t.d;
  }
  else
  {
    IllConditionedCircumcentre(turned ? c : b, turned ? a : c, t);
  }
  return t;
}

/// The circumcentre of a, b, c (given in the engines' canonical order: ComesFirst).
inline Point2 CircumcentreOf(const Point2& a, const Point2& b, const Point2& c)
{
  const CircumcentreTerms t = CircumcentreOffset(a, b, c);
  return { t.Origin.x + t.ux, t.Origin.y + t.uy };
}

} // namespace tessera
