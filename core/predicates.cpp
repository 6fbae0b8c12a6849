// Exact geometric predicates.
//
// Sign conventions (y axis up):
//   orient2d(a, b, c)         +1 when a, b, c turn anticlockwise (c left of the line a->b),
//                             -1 clockwise, 0 collinear.
//   incircle(a, b, c, d)      +1 when d is strictly inside the circle through a, b, c given
//                             anticlockwise, -1 outside, 0 co-circular. Flips if a, b, c clockwise.
//                             (Also 0 whenever a, b, c are collinear and d on their line.)
//   compare_distance(p, a, b) sign of |p - a|^2 - |p - b|^2: -1 when a is strictly nearer to p.
//   affine_sign(a, b, c, p)   sign of a * p.x + b * p.y + c.
//   determinant3_sign(...)    sign of the 3x3 determinant of its three rows.
//
// Three tiers, each exact wherever it answers:
//  1. Floating-point filter (predicates_inline.h): the determinant in doubles, accepted when its
//     magnitude exceeds a bound proportional to the permanent (Shewchuk 1997, bounds "A") plus an
//     absolute term covering gradual underflow. Overflow produces Inf/NaN, which never passes.
//  1b. orient2d and incircle only: points on a common power-of-two grid (lattices, integers), where
//     the double evaluation is itself exact (GridOrient, GridInCircle below).
//  1c. orient2d only: Shewchuk's adaptive stages B and C (AdaptiveOrient below), for coordinates
//     between 2^-300 and 2^300 in magnitude: nearly collinear points off any grid.
//  2. Expansion arithmetic: each difference of coordinates is an exact two-term expansion
//     (two_diff), and the determinant is evaluated exactly as a sum of nonoverlapping doubles
//     (two_product, scale_expansion, merge-based expansion sum with zero elimination), its sign
//     being the sign of the largest component. This is exact as long as no product underflows
//     below 2^-1074 and nothing overflows. The inputs are first scaled by a power of two (which
//     changes neither the exactness nor the sign: the predicates are homogeneous) to bring them
//     into a window where that is guaranteed; see exponent_window(). Every input's bits must fit
//     in about 518 (incircle) or 1037 (orient2d, compare_distance) binary orders of magnitude.
//     (affine_sign uses this tier only when its inputs already fit, unscaled; determinant3_sign,
//     evaluated a few times per window, goes from the filter straight to tier 3.)
//  3. Big-integer arithmetic, for inputs whose magnitudes span more than that (say 1e150 next to
//     1e-300): every double is an integer times a power of two, so after shifting to the smallest
//     such power the determinant is an integer polynomial. Slow, and only ever reached for such
//     inputs, so the predicates have no limits on finite inputs.
//
// Contraction (fusing a*b+c into an fma) would change the roundings the filter's bounds and the
// Dekker product rely on, so it is switched off for this file.

#include "fp_contract_off.h" // first: before the expansion arithmetic

#include "predicates.h"
#include "expansion_arithmetic.h"
#include "predicates_inline.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace tessera
{
namespace
{

// Error-free transformations and expansion arithmetic (two_sum, two_product, expansion_sum,
// scale_expansion, expansion_product, ...): expansion_arithmetic.h.
using namespace expansion;

// ---------------------------------------------------------------------------------------------
// Exponent windows and scaling.

// The binary exponents of the highest and lowest set bits of a finite nonzero double.
inline void bit_span(double x, int& high, int& low)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
  int exponent; // of the mantissa's last bit
  if (biased == 0)
  {
    exponent = -1074; // subnormal
  }
  else
  {
    mantissa |= std::uint64_t(1) << 52;
    exponent = biased - 1075;
  }
  // mantissa != 0 because x != 0.
#if defined(__GNUC__)
  const int top = 63 - __builtin_clzll(mantissa);
  const int bottom = __builtin_ctzll(mantissa);
#else
  int top = 63;
  while (!((mantissa >> top) & 1))
  {
    --top;
  }
  int bottom = 0;
  while (!((mantissa >> bottom) & 1))
  {
    ++bottom;
  }
#endif
  high = exponent + top;
  low = exponent + bottom;
}

struct BitRange
{
  int high = INT_MIN;
  int low = INT_MAX;
  bool finite = true;

  void add(double x)
  {
    if (!std::isfinite(x))
    {
      this->finite = false;
      return;
    }
    if (x == 0.0)
    {
      return;
    }
    int h, l;
    bit_span(x, h, l);
    this->high = std::max(this->high, h);
    this->low = std::min(this->low, l);
  }
  bool allZero() const { return this->high == INT_MIN; }
};

// Finds a power-of-two scale 2^k that brings every set bit of the inputs inside [2^lowMin,
// 2^highMax], preferring k == 0. Returns false when the inputs span too many binary orders.
bool exponent_window(const BitRange& range, int highMax, int lowMin, int& k)
{
  const int kLow = lowMin - range.low;    // k must be >= this
  const int kHigh = highMax - range.high; // and <= this
  if (kLow > kHigh)
  {
    return false;
  }
  k = std::clamp(0, kLow, kHigh);
  return true;
}

// Bounds for the expansion tier. A difference of two inputs is below 2^(high+2); degree-2
// determinants (orient2d, compare_distance) then stay below 2^(2 high + 8) and degree-4 ones
// (incircle, up to 1536 terms) below 2^(4 high + 19), both under 2^1023. The smallest bit of a
// degree-d product is at least 2^(d low), which must not fall below 2^-1074 (the subnormal grid),
// and every number fed to split() is then normal.
constexpr int kDegree2HighMax = 500;
constexpr int kDegree2LowMin = -537;
constexpr int kDegree4HighMax = 250;
constexpr int kDegree4LowMin = -268;

inline Point2 scaled(const Point2& p, int k)
{
  return k == 0 ? p : Point2{ std::ldexp(p.x, k), std::ldexp(p.y, k) };
}

// ---------------------------------------------------------------------------------------------
// Big integers (sign and magnitude, 32-bit limbs, least significant first) for the last tier.

class BigInt
{
public:
  BigInt() = default;

  /// The integer x / 2^base, where base is at most the exponent of x's lowest set bit.
  static BigInt FromDouble(double x, int base)
  {
    BigInt r;
    if (x == 0.0)
    {
      return r;
    }
    int high, low;
    bit_span(x, high, low);
    // |x| = m * 2^low with m odd, m < 2^53.
    const std::uint64_t m =
      static_cast<std::uint64_t>(std::ldexp(std::fabs(x), -low)); // exact: m fits in 53 bits
    const int shift = low - base;
    const int limbShift = shift / 32;
    const int bitShift = shift % 32;
    r.Magnitude.assign(static_cast<std::size_t>(limbShift), 0u);
    // m << bitShift spans at most 53 + 31 bits: three limbs.
    const std::uint64_t low64 = (m & 0xffffffffu) << bitShift; // below 2^63
    const std::uint64_t high64 = (m >> 32) << bitShift;        // below 2^52
    const std::uint64_t middle = (low64 >> 32) + (high64 & 0xffffffffu);
    r.Magnitude.push_back(static_cast<std::uint32_t>(low64));
    r.Magnitude.push_back(static_cast<std::uint32_t>(middle));
    r.Magnitude.push_back(static_cast<std::uint32_t>((high64 >> 32) + (middle >> 32)));
    r.Trim();
    r.Negative = x < 0.0;
    return r;
  }

  int Sign() const { return this->Magnitude.empty() ? 0 : (this->Negative ? -1 : 1); }

  friend BigInt operator+(const BigInt& a, const BigInt& b) { return Add(a, b, b.Negative); }
  friend BigInt operator-(const BigInt& a, const BigInt& b) { return Add(a, b, !b.Negative); }
  friend BigInt operator*(const BigInt& a, const BigInt& b)
  {
    BigInt r;
    if (a.Magnitude.empty() || b.Magnitude.empty())
    {
      return r;
    }
    r.Magnitude.assign(a.Magnitude.size() + b.Magnitude.size(), 0u);
    for (std::size_t i = 0; i < a.Magnitude.size(); ++i)
    {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < b.Magnitude.size(); ++j)
      {
        const std::uint64_t t =
          static_cast<std::uint64_t>(a.Magnitude[i]) * b.Magnitude[j] + r.Magnitude[i + j] + carry;
        r.Magnitude[i + j] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
      }
      r.Magnitude[i + b.Magnitude.size()] = static_cast<std::uint32_t>(carry);
    }
    r.Trim();
    r.Negative = a.Negative != b.Negative;
    return r;
  }

private:
  void Trim()
  {
    while (!this->Magnitude.empty() && this->Magnitude.back() == 0u)
    {
      this->Magnitude.pop_back();
    }
    if (this->Magnitude.empty())
    {
      this->Negative = false;
    }
  }

  static int CompareMagnitude(const BigInt& a, const BigInt& b)
  {
    if (a.Magnitude.size() != b.Magnitude.size())
    {
      return a.Magnitude.size() < b.Magnitude.size() ? -1 : 1;
    }
    for (std::size_t i = a.Magnitude.size(); i-- > 0;)
    {
      if (a.Magnitude[i] != b.Magnitude[i])
      {
        return a.Magnitude[i] < b.Magnitude[i] ? -1 : 1;
      }
    }
    return 0;
  }

  // a + (bNegative ? -|b| : |b|)
  static BigInt Add(const BigInt& a, const BigInt& b, bool bNegative)
  {
    BigInt r;
    if (a.Negative == bNegative)
    {
      const std::size_t n = std::max(a.Magnitude.size(), b.Magnitude.size());
      r.Magnitude.resize(n + 1);
      std::uint64_t carry = 0;
      for (std::size_t i = 0; i < n; ++i)
      {
        const std::uint64_t t = carry + (i < a.Magnitude.size() ? a.Magnitude[i] : 0u) +
          (i < b.Magnitude.size() ? b.Magnitude[i] : 0u);
        r.Magnitude[i] = static_cast<std::uint32_t>(t);
        carry = t >> 32;
      }
      r.Magnitude[n] = static_cast<std::uint32_t>(carry);
      r.Negative = a.Negative;
      r.Trim();
      return r;
    }
    const int cmp = CompareMagnitude(a, b);
    if (cmp == 0)
    {
      return r;
    }
    const BigInt& big = cmp > 0 ? a : b;
    const BigInt& small = cmp > 0 ? b : a;
    r.Magnitude.resize(big.Magnitude.size());
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < big.Magnitude.size(); ++i)
    {
      std::int64_t t = static_cast<std::int64_t>(big.Magnitude[i]) - borrow -
        (i < small.Magnitude.size() ? static_cast<std::int64_t>(small.Magnitude[i]) : 0);
      borrow = t < 0 ? 1 : 0;
      if (t < 0)
      {
        t += std::int64_t(1) << 32;
      }
      r.Magnitude[i] = static_cast<std::uint32_t>(t);
    }
    r.Negative = cmp > 0 ? a.Negative : bNegative;
    r.Trim();
    return r;
  }

  bool Negative = false;
  std::vector<std::uint32_t> Magnitude;
};

// ---------------------------------------------------------------------------------------------
// The determinants in the expansion tier (inputs already scaled into the exponent window).

int orient2d_expansion(const Point2& a, const Point2& b, const Point2& c)
{
  double acx[2], acy[2], bcx[2], bcy[2];
  const int acxn = diff_expansion(a.x, c.x, acx);
  const int acyn = diff_expansion(a.y, c.y, acy);
  const int bcxn = diff_expansion(b.x, c.x, bcx);
  const int bcyn = diff_expansion(b.y, c.y, bcy);
  double det[16];
  return expansion_sign(det, cross_expansion(acx, acxn, bcy, bcyn, acy, acyn, bcx, bcxn, det));
}

// The incircle determinant from the exact offsets (expansions of length <= 2) of a, b, c from d.
int incircle_from_offsets(const double* adx,
  int adxn,
  const double* ady,
  int adyn,
  const double* bdx,
  int bdxn,
  const double* bdy,
  int bdyn,
  const double* cdx,
  int cdxn,
  const double* cdy,
  int cdyn)
{
  double minor[16], lift[16];
  double aterm[kMaxProduct], bterm[kMaxProduct], cterm[kMaxProduct];
  int mn = cross_expansion(bdx, bdxn, cdy, cdyn, cdx, cdxn, bdy, bdyn, minor);
  int ln = lift_expansion(adx, adxn, ady, adyn, lift);
  const int an = expansion_product(minor, mn, lift, ln, aterm);
  mn = cross_expansion(cdx, cdxn, ady, adyn, adx, adxn, cdy, cdyn, minor);
  ln = lift_expansion(bdx, bdxn, bdy, bdyn, lift);
  const int bn = expansion_product(minor, mn, lift, ln, bterm);
  mn = cross_expansion(adx, adxn, bdy, bdyn, bdx, bdxn, ady, adyn, minor);
  ln = lift_expansion(cdx, cdxn, cdy, cdyn, lift);
  const int cn = expansion_product(minor, mn, lift, ln, cterm);

  double ab[2 * kMaxProduct], det[3 * kMaxProduct];
  const int abn = expansion_sum(aterm, an, bterm, bn, ab);
  const int n = expansion_sum(ab, abn, cterm, cn, det);
  return expansion_sign(det, n);
}

int incircle_expansion(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  double adx[2], ady[2], bdx[2], bdy[2], cdx[2], cdy[2];
  const int adxn = diff_expansion(a.x, d.x, adx);
  const int adyn = diff_expansion(a.y, d.y, ady);
  const int bdxn = diff_expansion(b.x, d.x, bdx);
  const int bdyn = diff_expansion(b.y, d.y, bdy);
  const int cdxn = diff_expansion(c.x, d.x, cdx);
  const int cdyn = diff_expansion(c.y, d.y, cdy);
  return incircle_from_offsets(adx, adxn, ady, adyn, bdx, bdxn, bdy, bdyn, cdx, cdxn, cdy, cdyn);
}

// An offset component x + tail (|tail| <= half an ulp of x) scaled by 2^k, as an expansion.
inline int offset_expansion(double x, double tail, int k, double* h)
{
  int n = 0;
  if (tail != 0.0)
  {
    h[n++] = k == 0 ? tail : std::ldexp(tail, k);
  }
  if (x != 0.0)
  {
    h[n++] = k == 0 ? x : std::ldexp(x, k);
  }
  return n;
}

int compare_distance_expansion(const Point2& p, const Point2& a, const Point2& b)
{
  double dax[2], day[2], dbx[2], dby[2];
  const int daxn = diff_expansion(a.x, p.x, dax);
  const int dayn = diff_expansion(a.y, p.y, day);
  const int dbxn = diff_expansion(b.x, p.x, dbx);
  const int dbyn = diff_expansion(b.y, p.y, dby);
  double la[16], lb[16], det[32];
  const int lan = lift_expansion(dax, daxn, day, dayn, la);
  const int lbn = lift_expansion(dbx, dbxn, dby, dbyn, lb);
  negate(lb, lbn);
  const int n = expansion_sum(la, lan, lb, lbn, det);
  return expansion_sign(det, n);
}

// ---------------------------------------------------------------------------------------------
// The same determinants over the integers.

struct BigPoint
{
  BigInt x;
  BigInt y;
};

BigPoint to_big(const Point2& p, int base)
{
  return BigPoint{ BigInt::FromDouble(p.x, base), BigInt::FromDouble(p.y, base) };
}

int orient2d_big(const Point2& a0, const Point2& b0, const Point2& c0, int base)
{
  const BigPoint a = to_big(a0, base), b = to_big(b0, base), c = to_big(c0, base);
  const BigInt det = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
  return det.Sign();
}

int incircle_big(const Point2& a0, const Point2& b0, const Point2& c0, const Point2& d0, int base)
{
  const BigPoint a = to_big(a0, base), b = to_big(b0, base), c = to_big(c0, base),
                 d = to_big(d0, base);
  const BigInt adx = a.x - d.x, ady = a.y - d.y;
  const BigInt bdx = b.x - d.x, bdy = b.y - d.y;
  const BigInt cdx = c.x - d.x, cdy = c.y - d.y;
  const BigInt det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
    (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
    (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return det.Sign();
}

int compare_distance_big(const Point2& p0, const Point2& a0, const Point2& b0, int base)
{
  const BigPoint p = to_big(p0, base), a = to_big(a0, base), b = to_big(b0, base);
  const BigInt dax = a.x - p.x, day = a.y - p.y, dbx = b.x - p.x, dby = b.y - p.y;
  const BigInt det = (dax * dax + day * day) - (dbx * dbx + dby * dby);
  return det.Sign();
}

BigInt big_offset(double x, double tail, int base)
{
  return BigInt::FromDouble(x, base) + BigInt::FromDouble(tail, base);
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Tiers 2 and 3.

namespace
{

// Tier 1b, between the filter and the expansions: points on a common grid. Degenerate inputs are
// usually lattices or rounded data (the benchmark's 1000 x 1000 lattice, gauges on integer
// coordinates), and there nearly every undecided determinant is exactly zero. If all coordinates
// are integer multiples of a power of two u, with quotients below 2^51, then the coordinate
// differences are exact; if moreover they are below 2^B u in magnitude, every product and sum of
// the floating-point determinant is an integer multiple of a power of u below 2^53 times it, so
// the determinant is computed without any rounding and its sign is exact. B = 25 for orient2d
// (2 * 25 + 1 bits) and 12 for incircle (4 * 12 + 4 bits). The range of u keeps its powers normal
// and their multiples finite. Otherwise the expansions decide.
constexpr int NoExponent = -100000;

// floor(log2(v)) for a positive normal v; NoExponent for 0, subnormals, infinity and NaN.
inline int ExponentOf(double v)
{
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  const int biased = int((bits >> 52) & 0x7ff);
  return biased == 0 || biased == 0x7ff ? NoExponent : biased - 1023;
}

// 2^k for -1022 <= k <= 1023.
inline double PowerOfTwo(int k)
{
  const std::uint64_t bits = std::uint64_t(k + 1023) << 52;
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

// Whether v is an integer multiple of the power of two u, with |v / u| < 2^51.
inline bool OnGrid(double v, double u)
{
  const double q = v / u; // exact unless it underflows, which the product below detects
  if (!(std::fabs(q) < 0x1p51) || q * u != v)
  {
    return false;
  }
  // Adding and subtracting 1.5 * 2^52 rounds q to an integer (|q| < 2^51, round to nearest).
  const volatile double magic = 0x1.8p52;
  return (q + magic) - magic == q;
}

// The grid unit for differences of largest magnitude m (at most 2^bits units), or 0 if none fits.
inline double GridUnit(double m, int bits, int lowest, int highest)
{
  const int e = ExponentOf(m);
  if (e == NoExponent)
  {
    return 0.0;
  }
  const int k = e + 1 - bits; // m < 2^(e + 1) = 2^bits * 2^k
  return k < lowest || k > highest ? 0.0 : PowerOfTwo(k);
}

// Sign of orient2d when a, b, c lie on a common grid as above; false if they do not.
bool GridOrient(const Point2& a, const Point2& b, const Point2& c, int& sign)
{
  const double acx = a.x - c.x, bcx = b.x - c.x, acy = a.y - c.y, bcy = b.y - c.y;
  const double m =
    std::max(std::max(std::fabs(acx), std::fabs(bcx)), std::max(std::fabs(acy), std::fabs(bcy)));
  const double u = GridUnit(m, 25, -500, 480);
  if (u == 0.0 || !OnGrid(a.x, u) || !OnGrid(a.y, u) || !OnGrid(b.x, u) || !OnGrid(b.y, u) ||
    !OnGrid(c.x, u) || !OnGrid(c.y, u))
  {
    return false;
  }
  const double det = acx * bcy - acy * bcx;
  sign = int(det > 0.0) - int(det < 0.0);
  return true;
}

// Sign of incircle when a, b, c, d lie on a common grid as above; false if they do not.
bool GridInCircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d, int& sign)
{
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double m = std::max(std::max(std::max(std::fabs(adx), std::fabs(bdx)), std::fabs(cdx)),
    std::max(std::max(std::fabs(ady), std::fabs(bdy)), std::fabs(cdy)));
  const double u = GridUnit(m, 12, -250, 240);
  if (u == 0.0 || !OnGrid(a.x, u) || !OnGrid(a.y, u) || !OnGrid(b.x, u) || !OnGrid(b.y, u) ||
    !OnGrid(c.x, u) || !OnGrid(c.y, u) || !OnGrid(d.x, u) || !OnGrid(d.y, u))
  {
    return false;
  }
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
    clift * (adx * bdy - bdx * ady);
  sign = int(det > 0.0) - int(det < 0.0);
  return true;
}

// Tier 1c, orient2d only: Shewchuk's adaptive stages B and C (1997, section 4.3), between the
// filter and the expansions. Nearly collinear points that are not on a grid (a transect's
// gauges, y = x / 3 rounded) fail the filter at nearly every walk step of an insertion, and the
// full expansion took some 120 ns a call there, most of an insertion's time.
//  B: the determinant of the rounded differences, exactly (two products, each an exact pair):
//     if its estimate clears bound B, or the differences were exact, its sign is the answer.
//  C: the first-order effect of the differences' roundings (their tails) added to B's estimate:
//     the rest is second order (bound C).
// The bounds hold without underflow: every coordinate lies in [2^-300, 2^300] in magnitude or is
// 0, so every nonzero difference, tail and product is a normal number far from the limits
// (a tail's ulp is at least 2^-352, a product of two tails at least 2^-704). Otherwise, and
// when C cannot decide, the expansions (or tier 1b) do. Returns false when undecided.
constexpr double kOrientBoundB = (2.0 + 12.0 * detail::kEpsilon) * detail::kEpsilon;
constexpr double kOrientBoundC =
  (9.0 + 64.0 * detail::kEpsilon) * detail::kEpsilon * detail::kEpsilon;
constexpr double kResultBound = (3.0 + 8.0 * detail::kEpsilon) * detail::kEpsilon;

inline bool InAdaptiveRange(double v)
{
  const double m = std::fabs(v);
  return v == 0.0 || (m >= 0x1p-300 && m <= 0x1p300);
}

bool AdaptiveOrient(const Point2& a, const Point2& b, const Point2& c, int& sign)
{
  if (!InAdaptiveRange(a.x) || !InAdaptiveRange(a.y) || !InAdaptiveRange(b.x) ||
    !InAdaptiveRange(b.y) || !InAdaptiveRange(c.x) || !InAdaptiveRange(c.y))
  {
    return false;
  }
  double acx, acxTail, bcx, bcxTail, acy, acyTail, bcy, bcyTail;
  two_diff(a.x, c.x, acx, acxTail);
  two_diff(b.x, c.x, bcx, bcxTail);
  two_diff(a.y, c.y, acy, acyTail);
  two_diff(b.y, c.y, bcy, bcyTail);
  double left, leftTail, right, rightTail;
  two_product(acx, bcy, left, leftTail);
  two_product(acy, bcx, right, rightTail);
  // B = (left + leftTail) - (right + rightTail) exactly, as four nonoverlapping components of
  // increasing magnitude, some maybe 0 (Shewchuk's Two-Two-Diff: the tail subtracted, then the
  // head, each as one step of Grow-Expansion). Its sign is the largest nonzero component's.
  double i, j, k, b0, b1, b2, b3;
  two_diff(leftTail, rightTail, i, b0);
  two_sum(left, i, j, k);
  two_diff(k, right, i, b1);
  two_sum(j, i, b3, b2);
  const double estimate = ((b0 + b1) + b2) + b3;
  const double permanent = std::fabs(left) + std::fabs(right);
  if (std::fabs(estimate) >= kOrientBoundB * permanent ||
    (acxTail == 0.0 && bcxTail == 0.0 && acyTail == 0.0 && bcyTail == 0.0))
  {
    const double largest = b3 != 0.0 ? b3 : (b2 != 0.0 ? b2 : (b1 != 0.0 ? b1 : b0));
    sign = int(largest > 0.0) - int(largest < 0.0);
    return true;
  }
  const double corrected =
    estimate + ((acx * bcyTail + bcy * acxTail) - (acy * bcxTail + bcx * acyTail));
  const double bound = kOrientBoundC * permanent + kResultBound * std::fabs(estimate);
  if (std::fabs(corrected) >= bound)
  {
    sign = int(corrected > 0.0) - int(corrected < 0.0);
    return true;
  }
  return false;
}

} // namespace

namespace detail
{

int orient2d_exact(const Point2& a, const Point2& b, const Point2& c)
{
  int sign = 0;
  if (AdaptiveOrient(a, b, c, sign) || GridOrient(a, b, c, sign))
  {
    return sign;
  }
  BitRange range;
  for (const Point2* p : { &a, &b, &c })
  {
    range.add(p->x);
    range.add(p->y);
  }
  if (!range.finite || range.allZero())
  {
    return 0;
  }
  int k = 0;
  if (exponent_window(range, kDegree2HighMax, kDegree2LowMin, k))
  {
    return orient2d_expansion(scaled(a, k), scaled(b, k), scaled(c, k));
  }
  return orient2d_big(a, b, c, range.low);
}

int incircle_exact(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  int sign = 0;
  if (GridInCircle(a, b, c, d, sign))
  {
    return sign;
  }
  BitRange range;
  for (const Point2* p : { &a, &b, &c, &d })
  {
    range.add(p->x);
    range.add(p->y);
  }
  if (!range.finite || range.allZero())
  {
    return 0;
  }
  int k = 0;
  if (exponent_window(range, kDegree4HighMax, kDegree4LowMin, k))
  {
    return incircle_expansion(scaled(a, k), scaled(b, k), scaled(c, k), scaled(d, k));
  }
  return incircle_big(a, b, c, d, range.low);
}

int compare_distance_exact(const Point2& p, const Point2& a, const Point2& b)
{
  BitRange range;
  for (const Point2* q : { &p, &a, &b })
  {
    range.add(q->x);
    range.add(q->y);
  }
  if (!range.finite || range.allZero())
  {
    return 0;
  }
  int k = 0;
  if (exponent_window(range, kDegree2HighMax, kDegree2LowMin, k))
  {
    return compare_distance_expansion(scaled(p, k), scaled(a, k), scaled(b, k));
  }
  return compare_distance_big(p, a, b, range.low);
}

} // namespace detail

// ---------------------------------------------------------------------------------------------
// Public entry points: the filter (compiled here without contraction), then the exact tiers.

int orient2d(const Point2& a, const Point2& b, const Point2& c)
{
  return detail::orient2d_filter(a, b, c);
}

int incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  return detail::incircle_filter(a, b, c, d);
}

int compare_distance(const Point2& p, const Point2& a, const Point2& b)
{
  return detail::compare_distance_filter(p, a, b);
}

namespace
{

/// The sign of a x + b y + c from the products' expansions: exact when every nonzero factor lies
/// within [2^-537, 2^500] (the products exact and normal enough for split()) and |c| < 2^1001
/// (the sum finite).
int affine_sign_expansion(double a, double b, double c, const Point2& p)
{
  double px[2], py[2], sum[4], total[5];
  const int pxn = product_expansion(a, p.x, px);
  const int pyn = product_expansion(b, p.y, py);
  const int sn = expansion_sum(px, pxn, py, pyn, sum);
  const int cn = c != 0.0 ? 1 : 0;
  const int n = expansion_sum(sum, sn, &c, cn, total);
  return expansion_sign(total, n);
}

/// The sign of a x + b y + c for finite values of any exponents, in integers: every term is an
/// integer times 2^base, base the smallest exponent in play.
int affine_sign_integers(double a, double b, double c, const Point2& p)
{
  int base = INT_MAX;
  int lowA = 0, lowX = 0, lowB = 0, lowY = 0, lowC = 0, high = 0;
  if (a != 0.0 && p.x != 0.0)
  {
    bit_span(a, high, lowA);
    bit_span(p.x, high, lowX);
    base = std::min(base, lowA + lowX);
  }
  if (b != 0.0 && p.y != 0.0)
  {
    bit_span(b, high, lowB);
    bit_span(p.y, high, lowY);
    base = std::min(base, lowB + lowY);
  }
  if (c != 0.0)
  {
    bit_span(c, high, lowC);
    base = std::min(base, lowC);
  }
  if (base == INT_MAX)
  {
    return 0;
  }
  BigInt total;
  if (a != 0.0 && p.x != 0.0)
  {
    // a * x = (a / 2^lowA) (x / 2^lowX) 2^(lowA + lowX); shift the first factor to the base.
    total = total + BigInt::FromDouble(a, base - lowX) * BigInt::FromDouble(p.x, lowX);
  }
  if (b != 0.0 && p.y != 0.0)
  {
    total = total + BigInt::FromDouble(b, base - lowY) * BigInt::FromDouble(p.y, lowY);
  }
  if (c != 0.0)
  {
    total = total + BigInt::FromDouble(c, base);
  }
  return total.Sign();
}

} // namespace

int affine_sign(double a, double b, double c, const Point2& p)
{
  // Filter: the value's rounding error is below 2 eps (|a x| + |b y|) (1 + eps); 4 eps is safe.
  const double ax = a * p.x;
  const double by = b * p.y;
  const double value = (ax + by) + c;
  const double errbound =
    4.0 * detail::kEpsilon * ((std::fabs(ax) + std::fabs(by)) + std::fabs(c)) +
    detail::kUnderflowTerm;
  if (value > errbound)
  {
    return 1;
  }
  if (-value > errbound)
  {
    return -1;
  }

  const double factors[4] = { a, p.x, b, p.y };
  bool finite = std::isfinite(c);
  BitRange factorRange;
  for (double f : factors)
  {
    factorRange.add(f);
    finite = finite && std::isfinite(f);
  }
  if (!finite)
  {
    return 0;
  }
  BitRange cRange;
  cRange.add(c);
  // Expansion tier without scaling (the coefficients and the point scale independently).
  const bool factorsFit = factorRange.allZero() ||
    (factorRange.high <= kDegree2HighMax && factorRange.low >= kDegree2LowMin);
  if (factorsFit && (cRange.allZero() || cRange.high <= 1000))
  {
    return affine_sign_expansion(a, b, c, p);
  }
  return affine_sign_integers(a, b, c, p);
}

Offset2 exact_offset(const Point2& q, const Point2& p)
{
  Offset2 o;
  two_diff(q.x, p.x, o.x, o.xTail);
  two_diff(q.y, p.y, o.y, o.yTail);
  return o;
}

int cross_sign(const Offset2& u, const Offset2& v)
{
  // Filter: the rounded offsets carry relative errors below eps, as the differences in orient2d.
  const double detleft = u.x * v.y;
  const double detright = u.y * v.x;
  const double det = detleft - detright;
  const double errbound =
    detail::kOrientBound * (std::fabs(detleft) + std::fabs(detright)) + detail::kUnderflowTerm;
  if (det > errbound)
  {
    return 1;
  }
  if (-det > errbound)
  {
    return -1;
  }
  BitRange range;
  for (double c : { u.x, u.xTail, u.y, u.yTail, v.x, v.xTail, v.y, v.yTail })
  {
    range.add(c);
  }
  if (!range.finite || range.allZero())
  {
    return 0;
  }
  int k = 0;
  if (exponent_window(range, kDegree2HighMax, kDegree2LowMin, k))
  {
    double ux[2], uy[2], vx[2], vy[2], left[8], right[8], total[16];
    const int uxn = offset_expansion(u.x, u.xTail, k, ux);
    const int uyn = offset_expansion(u.y, u.yTail, k, uy);
    const int vxn = offset_expansion(v.x, v.xTail, k, vx);
    const int vyn = offset_expansion(v.y, v.yTail, k, vy);
    const int ln = expansion_product(ux, uxn, vy, vyn, left);
    const int rn = expansion_product(uy, uyn, vx, vxn, right);
    negate(right, rn);
    return expansion_sign(total, expansion_sum(left, ln, right, rn, total));
  }
  const int base = range.low;
  const BigInt det2 = big_offset(u.x, u.xTail, base) * big_offset(v.y, v.yTail, base) -
    big_offset(u.y, u.yTail, base) * big_offset(v.x, v.xTail, base);
  return det2.Sign();
}

int incircle_offsets(const Offset2& a, const Offset2& b, const Offset2& c)
{
  // Filter on the rounded offsets: they carry relative errors below eps, as the differences
  // incircle computes, which is all Shewchuk's bound assumes about them.
  const int filtered = detail::incircle_filter_differences(a.x, a.y, b.x, b.y, c.x, c.y);
  if (filtered != 0)
  {
    return filtered;
  }
  BitRange range;
  for (const Offset2* o : { &a, &b, &c })
  {
    range.add(o->x);
    range.add(o->xTail);
    range.add(o->y);
    range.add(o->yTail);
  }
  if (!range.finite || range.allZero())
  {
    return 0;
  }
  int k = 0;
  if (exponent_window(range, kDegree4HighMax, kDegree4LowMin, k))
  {
    double adx[2], ady[2], bdx[2], bdy[2], cdx[2], cdy[2];
    const int adxn = offset_expansion(a.x, a.xTail, k, adx);
    const int adyn = offset_expansion(a.y, a.yTail, k, ady);
    const int bdxn = offset_expansion(b.x, b.xTail, k, bdx);
    const int bdyn = offset_expansion(b.y, b.yTail, k, bdy);
    const int cdxn = offset_expansion(c.x, c.xTail, k, cdx);
    const int cdyn = offset_expansion(c.y, c.yTail, k, cdy);
    return incircle_from_offsets(adx, adxn, ady, adyn, bdx, bdxn, bdy, bdyn, cdx, cdxn, cdy, cdyn);
  }
  const int base = range.low;
  const BigInt adx = big_offset(a.x, a.xTail, base), ady = big_offset(a.y, a.yTail, base);
  const BigInt bdx = big_offset(b.x, b.xTail, base), bdy = big_offset(b.y, b.yTail, base);
  const BigInt cdx = big_offset(c.x, c.xTail, base), cdy = big_offset(c.y, c.yTail, base);
  const BigInt det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
    (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
    (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return det.Sign();
}

int determinant3_sign(double a1,
  double b1,
  double c1,
  double a2,
  double b2,
  double c2,
  double a3,
  double b3,
  double c3)
{
  // Filter. Each minor's error is below 2 eps (1 + eps) of its permanent, each term's below 3 eps
  // of its permanent, the first sum adds eps of its operands: below 4 eps of the whole permanent
  // (the last rounding keeps the sign). 8 eps leaves room for the rounding of the bound itself.
  const double b2c3 = b2 * c3, b3c2 = b3 * c2;
  const double a2c3 = a2 * c3, a3c2 = a3 * c2;
  const double a2b3 = a2 * b3, a3b2 = a3 * b2;
  const double det = (a1 * (b2c3 - b3c2) - b1 * (a2c3 - a3c2)) + c1 * (a2b3 - a3b2);
  const double permanent = std::fabs(a1) * (std::fabs(b2c3) + std::fabs(b3c2)) +
    std::fabs(b1) * (std::fabs(a2c3) + std::fabs(a3c2)) +
    std::fabs(c1) * (std::fabs(a2b3) + std::fabs(a3b2));
  const double errbound = 8.0 * detail::kEpsilon * permanent +
    detail::kUnderflowTerm * (((std::fabs(a1) + std::fabs(b1)) + std::fabs(c1)) + 1.0);
  if (det > errbound)
  {
    return 1;
  }
  if (-det > errbound)
  {
    return -1;
  }

  const double entries[9] = { a1, b1, c1, a2, b2, c2, a3, b3, c3 };
  BitRange range;
  for (double e : entries)
  {
    range.add(e);
  }
  if (!range.finite || range.allZero())
  {
    return 0;
  }
  BigInt m[9];
  for (int i = 0; i < 9; ++i)
  {
    m[i] = BigInt::FromDouble(entries[i], range.low);
  }
  const BigInt value = m[0] * (m[4] * m[8] - m[7] * m[5]) - m[1] * (m[3] * m[8] - m[6] * m[5]) +
    m[2] * (m[3] * m[7] - m[6] * m[4]);
  return value.Sign();
}

} // namespace tessera
