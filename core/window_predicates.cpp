// Exact window predicates: filter, then expansion arithmetic (Shewchuk 1997: nonoverlapping
// expansions, grow/scale with zero elimination; the sign is that of the largest component).
//
// Filters. Each polynomial is evaluated in doubles in a fixed order; its rounding error is at most
// gamma_k times its permanent (the same expression over absolute values), k the largest number of
// roundings on any path from an input to the result (9 here at most). The bounds below use 16 eps,
// which also absorbs the rounding of the permanent itself. A permanent below 2^-900 (where an
// underflowed product could matter) or a non-finite value goes to the exact tier.
//
// Contraction would change the roundings the bounds assume and break the error-free
// transformations of expansion_arithmetic.h, so it is off for this file (before the includes); the
// exact products use std::fma, which is exact by definition.

#include "fp_contract_off.h" // first: before the expansion arithmetic

#include "window_predicates.h"

#include "expansion_arithmetic.h"
#include "predicates.h"

#include <cmath>
#include <vector>

namespace tessera
{
namespace
{

constexpr double kEps = 0x1p-53;
constexpr double kBound = 16.0 * kEps;
constexpr double kTiny = 0x1p-900;

int FilteredSign(double value, double permanent, double bound)
{
  if (!(permanent >= kTiny) || !std::isfinite(permanent))
  {
    return 2; // undecided
  }
  const double error = bound * permanent;
  if (value > error)
  {
    return 1;
  }
  if (-value > error)
  {
    return -1;
  }
  return 2;
}

// An expansion: nonoverlapping doubles in increasing magnitude, no zeros. The arithmetic is that
// of expansion_arithmetic.h; these wrappers size a vector to the bound, run the shared routine
// and shrink the vector to the result.
using Expansion = std::vector<double>;

Expansion Of(double a)
{
  return a == 0.0 ? Expansion{} : Expansion{ a };
}

int Length(const Expansion& e)
{
  return static_cast<int>(e.size());
}

Expansion Add(const Expansion& e, const Expansion& f)
{
  Expansion h(e.size() + f.size());
  h.resize(static_cast<std::size_t>(
    expansion::expansion_sum(e.data(), Length(e), f.data(), Length(f), h.data())));
  return h;
}

Expansion Grow(const Expansion& e, double b)
{
  return Add(e, Of(b));
}

Expansion Negate(Expansion e)
{
  expansion::negate(e.data(), Length(e));
  return e;
}

Expansion Subtract(const Expansion& e, const Expansion& f)
{
  return Add(e, Negate(f));
}

// e * b. The products use std::fma (exact without splitting, so also for huge factors: these
// inputs are not rescaled into a window as predicates.cpp's are).
Expansion Scale(const Expansion& e, double b)
{
  Expansion h(2 * e.size());
  h.resize(static_cast<std::size_t>(
    expansion::scale_expansion<expansion::two_product_fma>(e.data(), Length(e), b, h.data())));
  return h;
}

Expansion Multiply(const Expansion& e, const Expansion& f)
{
  Expansion result;
  for (const double fi : f)
  {
    result = Add(result, Scale(e, fi));
  }
  return result;
}

// a - b exactly.
Expansion Difference(double a, double b)
{
  Expansion h(2);
  h.resize(static_cast<std::size_t>(expansion::diff_expansion(a, b, h.data())));
  return h;
}

Expansion Sum2(double a, double b)
{
  return Difference(a, -b);
}

int Sign(const Expansion& e)
{
  return expansion::expansion_sign(e.data(), Length(e));
}

// h.a * u + h.b * v + k (u, v expansions, k a double).
Expansion Affine(const HalfPlane& h, const Expansion& u, const Expansion& v, double k)
{
  return Grow(Add(Scale(u, h.a), Scale(v, h.b)), k);
}

// 2 * h(midpoint of a, b) and h(d) as expansions.
void BisectorTerms(const HalfPlane& h,
  const Point2& a,
  const Point2& b,
  Expansion& f0,
  Expansion& f1)
{
  f0 = Affine(h, Sum2(a.x, b.x), Sum2(a.y, b.y), 2.0 * h.c);
  f1 = Add(Scale(Difference(a.y, b.y), h.a), Scale(Difference(b.x, a.x), h.b));
}

} // namespace

// h(centre) = (2 D H0 + a X + b Y) / (2 D), relative to p: B = q - p, C = r - p, D = B x C,
// X = C.y |B|^2 - B.y |C|^2, Y = B.x |C|^2 - C.x |B|^2 (the centre is p + (X, Y) / (2 D)),
// H0 = h(p).
int CircumcentreSide(const HalfPlane& h, const Point2& p, const Point2& q, const Point2& r)
{
  const int orientation = orient2d(p, q, r);
  if (orientation == 0)
  {
    return 0; // no centre: callers never ask
  }
  {
    const double bx = q.x - p.x, by = q.y - p.y, cx = r.x - p.x, cy = r.y - p.y;
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const double d = bx * cy - by * cx;
    const double x = cy * b2 - by * c2, y = bx * c2 - cx * b2;
    const double ap = h.a * p.x, bp = h.b * p.y;
    const double h0 = (ap + bp) + h.c;
    const double ax = h.a * x, by2 = h.b * y;
    const double value = 2.0 * d * h0 + (ax + by2);
    const double pd = std::fabs(bx * cy) + std::fabs(by * cx);
    const double ph = (std::fabs(ap) + std::fabs(bp)) + std::fabs(h.c);
    const double px = std::fabs(cy) * b2 + std::fabs(by) * c2;
    const double py = std::fabs(bx) * c2 + std::fabs(cx) * b2;
    const double permanent = 2.0 * pd * ph + (std::fabs(h.a) * px + std::fabs(h.b) * py);
    const int sign = FilteredSign(value, permanent, kBound);
    if (sign != 2)
    {
      return sign * orientation;
    }
  }
  const Expansion bx = Difference(q.x, p.x), by = Difference(q.y, p.y);
  const Expansion cx = Difference(r.x, p.x), cy = Difference(r.y, p.y);
  const Expansion b2 = Add(Multiply(bx, bx), Multiply(by, by));
  const Expansion c2 = Add(Multiply(cx, cx), Multiply(cy, cy));
  const Expansion d = Subtract(Multiply(bx, cy), Multiply(by, cx));
  const Expansion x = Subtract(Multiply(cy, b2), Multiply(by, c2));
  const Expansion y = Subtract(Multiply(bx, c2), Multiply(cx, b2));
  const Expansion h0 = Affine(h, Of(p.x), Of(p.y), h.c);
  const Expansion value = Add(Scale(Multiply(d, h0), 2.0), Add(Scale(x, h.a), Scale(y, h.b)));
  return Sign(value) * orientation;
}

int BisectorDirectionSign(const HalfPlane& h, const Point2& a, const Point2& b)
{
  const double dx = a.y - b.y, dy = b.x - a.x;
  const double u = h.a * dx, v = h.b * dy;
  const int sign = FilteredSign(u + v, std::fabs(u) + std::fabs(v), kBound);
  if (sign != 2)
  {
    return sign;
  }
  Expansion f0, f1;
  BisectorTerms(h, a, b, f0, f1);
  return Sign(f1);
}

int MidpointSide(const HalfPlane& h, const Point2& a, const Point2& b)
{
  const double u = h.a * (a.x + b.x), v = h.b * (a.y + b.y);
  const int sign =
    FilteredSign((u + v) + 2.0 * h.c, (std::fabs(u) + std::fabs(v)) + 2.0 * std::fabs(h.c), kBound);
  if (sign != 2)
  {
    return sign;
  }
  Expansion f0, f1;
  BisectorTerms(h, a, b, f0, f1);
  return Sign(f0);
}

// h(m + t d) = f0 / 2 + t f1, so t_h = -f0_h / (2 f1_h) and
// t_h - t_g = (f0_g f1_h - f0_h f1_g) / (2 f1_h f1_g).
int CompareBisectorCrossings(const HalfPlane& h,
  const HalfPlane& g,
  const Point2& a,
  const Point2& b)
{
  const int directions = BisectorDirectionSign(h, a, b) * BisectorDirectionSign(g, a, b);
  if (directions == 0)
  {
    return 0; // not both crossing: callers never ask
  }
  {
    const double sx = a.x + b.x, sy = a.y + b.y, dx = a.y - b.y, dy = b.x - a.x;
    const double hu = h.a * sx, hv = h.b * sy, gu = g.a * sx, gv = g.b * sy;
    const double f0h = (hu + hv) + 2.0 * h.c, f0g = (gu + gv) + 2.0 * g.c;
    const double p0h = (std::fabs(hu) + std::fabs(hv)) + 2.0 * std::fabs(h.c);
    const double p0g = (std::fabs(gu) + std::fabs(gv)) + 2.0 * std::fabs(g.c);
    const double hx = h.a * dx, hy = h.b * dy, gx = g.a * dx, gy = g.b * dy;
    const double f1h = hx + hy, f1g = gx + gy;
    const double p1h = std::fabs(hx) + std::fabs(hy), p1g = std::fabs(gx) + std::fabs(gy);
    const int sign = FilteredSign(f0g * f1h - f0h * f1g, p0g * p1h + p0h * p1g, kBound);
    if (sign != 2)
    {
      return sign * directions;
    }
  }
  Expansion f0h, f1h, f0g, f1g;
  BisectorTerms(h, a, b, f0h, f1h);
  BisectorTerms(g, a, b, f0g, f1g);
  return Sign(Subtract(Multiply(f0g, f1h), Multiply(f0h, f1g))) * directions;
}

} // namespace tessera
