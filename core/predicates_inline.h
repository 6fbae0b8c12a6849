#pragma once
// Inline fast paths of the exact predicates of predicates.h, for hot loops (an engine that calls
// incircle tens of millions of times). Each one evaluates the determinant in floating point,
// compares it with an error bound proportional to its permanent (Shewchuk's "A" bounds, plus an
// absolute term that covers underflow), and only when that cannot decide calls the exact
// evaluation in predicates.cpp. The results are identical to orient2d / incircle /
// compare_distance: same sign conventions, exact for every finite double input.
//
// Floating-point contraction (a*b+c fused into one fma) would change the rounding the error bounds
// were derived for. When the translation unit is compiled for a target with fma instructions the
// compiler may contract, so there these functions call the out-of-line versions instead, which are
// compiled with contraction switched off.

#include "geometry.h"

#include <cmath>

namespace tessera
{

int orient2d(const Point2& a, const Point2& b, const Point2& c);
int incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
int compare_distance(const Point2& p, const Point2& a, const Point2& b);

namespace detail
{
// Exact evaluations used once the floating-point filter has failed (predicates.cpp).
int orient2d_exact(const Point2& a, const Point2& b, const Point2& c);
int incircle_exact(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
int compare_distance_exact(const Point2& p, const Point2& a, const Point2& b);

constexpr double kEpsilon = 0x1p-53; // half an ulp of 1: the unit roundoff of round-to-nearest
// Shewchuk's first-stage bounds ("Adaptive precision floating-point arithmetic and fast robust
// geometric predicates", 1997), relative to the permanent of the determinant.
constexpr double kOrientBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kIncircleBound = (10.0 + 96.0 * kEpsilon) * kEpsilon;
// Squared distances: two squares of rounded differences (3 roundings each) and one sum per side.
constexpr double kDistanceBound = (4.0 + 64.0 * kEpsilon) * kEpsilon;
// Gradual underflow makes a product's error absolute (at most 2^-1075) rather than relative; this
// term, far above the few such errors a determinant can collect, keeps the bounds valid there.
constexpr double kUnderflowTerm = 0x1p-1020;

/// orient2d's filter; when it cannot decide, orient2d_exact does. The only branch is whether the
/// filter decided, which is almost always true and so predicted; the sign of a decided
/// determinant is computed without a branch (a branch on it would be mispredicted half the time,
/// and callers branch on it once more anyway).
inline int orient2d_filter(const Point2& a, const Point2& b, const Point2& c)
{
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  const double errbound =
    kOrientBound * (std::fabs(detleft) + std::fabs(detright)) + kUnderflowTerm;
  // NaN or infinity (overflow) anywhere makes the comparison false: the exact path decides.
  if (__builtin_expect(std::fabs(det) > errbound, 1))
  {
    return int(det > 0.0) - int(det < 0.0);
  }
  return orient2d_exact(a, b, c);
}

/// incircle's filter on the differences of a, b, c to d (each with a relative error below eps, as
/// a rounded difference has, or none): +1 or -1 when the rounded determinant's sign is certain,
/// 0 when it is not (a decided determinant is never 0). The sign is computed without a branch.
inline int incircle_filter_differences(double adx,
  double ady,
  double bdx,
  double bdy,
  double cdx,
  double cdy)
{
  const double bdxcdy = bdx * cdy;
  const double cdxbdy = cdx * bdy;
  const double alift = adx * adx + ady * ady;
  const double cdxady = cdx * ady;
  const double adxcdy = adx * cdy;
  const double blift = bdx * bdx + bdy * bdy;
  const double adxbdy = adx * bdy;
  const double bdxady = bdx * ady;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
    alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
    (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
    (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  // An underflowed product is multiplied by a lift afterwards, so the absolute term scales with
  // the lifts.
  const double errbound =
    kIncircleBound * permanent + kUnderflowTerm * ((alift + blift + clift) + 1.0);
  // NaN or infinity (overflow) anywhere makes the comparison false: undecided.
  const bool decided = std::fabs(det) > errbound;
  return decided ? int(det > 0.0) - int(det < 0.0) : 0;
}

/// incircle's filter; when it cannot decide, incircle_exact does.
inline int incircle_filter(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  const int sign =
    incircle_filter_differences(a.x - d.x, a.y - d.y, b.x - d.x, b.y - d.y, c.x - d.x, c.y - d.y);
  if (__builtin_expect(sign != 0, 1))
  {
    return sign;
  }
  return incircle_exact(a, b, c, d);
}

inline int compare_distance_filter(const Point2& p, const Point2& a, const Point2& b)
{
  const double dax = a.x - p.x;
  const double day = a.y - p.y;
  const double dbx = b.x - p.x;
  const double dby = b.y - p.y;
  const double la = dax * dax + day * day;
  const double lb = dbx * dbx + dby * dby;
  const double det = la - lb;
  const double errbound = kDistanceBound * (la + lb) + kUnderflowTerm;
  if (det > errbound)
  {
    return 1;
  }
  if (-det > errbound)
  {
    return -1;
  }
  return compare_distance_exact(p, a, b);
}
} // namespace detail

#if defined(__FMA__) || defined(__ARM_FEATURE_FMA) || defined(__FP_FAST_FMA) || defined(FP_FAST_FMA)
inline int orient2d_fast(const Point2& a, const Point2& b, const Point2& c)
{
  return orient2d(a, b, c);
}
inline int incircle_fast(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  return incircle(a, b, c, d);
}
inline int compare_distance_fast(const Point2& p, const Point2& a, const Point2& b)
{
  return compare_distance(p, a, b);
}
#else
/// orient2d, with the floating-point filter inlined.
inline int orient2d_fast(const Point2& a, const Point2& b, const Point2& c)
{
  return detail::orient2d_filter(a, b, c);
}
/// incircle, with the floating-point filter inlined.
inline int incircle_fast(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  return detail::incircle_filter(a, b, c, d);
}
/// compare_distance, with the floating-point filter inlined.
inline int compare_distance_fast(const Point2& p, const Point2& a, const Point2& b)
{
  return detail::compare_distance_filter(p, a, b);
}
#endif

/// Winding-number contribution of segment a->b at p, by the signed crossings of the ray from p
/// towards +x. Half-open in y so a vertex on the ray counts once; exact through orient2d. (Inline:
/// the clip's catchment test runs it for every ring edge near a tile.)
inline int RayCrossing(const Point2& a, const Point2& b, const Point2& p)
{
  if (a.y <= p.y)
  {
    if (b.y > p.y && orient2d_fast(a, b, p) > 0)
    {
      return 1;
    }
  }
  else if (b.y <= p.y && orient2d_fast(a, b, p) < 0)
  {
    return -1;
  }
  return 0;
}

} // namespace tessera
