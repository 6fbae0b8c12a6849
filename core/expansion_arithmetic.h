#pragma once
// Internal to tessera_core: Shewchuk's error-free transformations and expansion arithmetic
// ("Adaptive precision floating-point arithmetic and fast robust geometric predicates", 1997),
// shared by the exact predicates (predicates.cpp) and the window predicates
// (window_predicates.cpp). Not part of the public API.
//
// Every includer MUST compile with floating-point contraction switched off, and the switch must
// come before this #include (the GCC pragma only affects functions defined after it): include
// "fp_contract_off.h" first.
//
// Fusing a*b+c into an fma would break the error-free transformations (two_sum, two_diff, Dekker's
// product). These are inline functions, so a single contracted copy in any translation unit could
// be the one the linker keeps for all of them.
//
// All results are exact as long as nothing overflows and no product underflows.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace tessera
{
namespace expansion
{

// ---------------------------------------------------------------------------------------------
// Error-free transformations.

inline void two_sum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void fast_two_sum(double a, double b, double& x, double& y) // requires |a| >= |b| or a == 0
{
  x = a + b;
  y = b - (x - a);
}

inline void two_diff(double a, double b, double& x, double& y)
{
  x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  y = (a - av) + (bv - b);
}

// x + y == a * b exactly, by std::fma: exact by definition, emulated in software without
// hardware fma (slow there, but needs no splitting, so it stays exact for products of huge
// factors, where Dekker's split overflows).
inline void two_product_fma(double a, double b, double& x, double& y)
{
  x = a * b;
  y = std::fma(a, b, -x);
}

#if defined(__FMA__) || defined(__ARM_FEATURE_FMA) || defined(__FP_FAST_FMA) || defined(FP_FAST_FMA)
inline void two_product(double a, double b, double& x, double& y)
{
  two_product_fma(a, b, x, y);
}
#else
// Veltkamp's split: a == hi + lo with both halves of at most 26 significant bits.
inline void split(double a, double& hi, double& lo)
{
  const double c = 134217729.0 * a; // 2^27 + 1
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// Dekker's product: x + y == a * b exactly (without hardware fma, where std::fma is emulated).
inline void two_product(double a, double b, double& x, double& y)
{
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}
#endif

// ---------------------------------------------------------------------------------------------
// Expansions: arrays of nonoverlapping doubles in increasing order of magnitude, no zero
// components; length 0 is the number 0. The value is the exact sum of the components, and its
// sign is the sign of the last (largest) component.

inline int expansion_sign(const double* e, int n)
{
  return n == 0 ? 0 : (e[n - 1] > 0.0 ? 1 : -1);
}

// The expansion of a two-term result x + y (y the smaller): its nonzero terms into h, smaller
// first; returns their count (<= 2).
inline int two_term_expansion(double x, double y, double* h)
{
  int n = 0;
  if (y != 0.0)
  {
    h[n++] = y;
  }
  if (x != 0.0)
  {
    h[n++] = x;
  }
  return n;
}

// a - b as an expansion of length <= 2.
inline int diff_expansion(double a, double b, double* h)
{
  double x, y;
  two_diff(a, b, x, y);
  return two_term_expansion(x, y, h);
}

// a * b as an expansion of length <= 2 (exact where two_product is).
inline int product_expansion(double a, double b, double* h)
{
  double x, y;
  two_product(a, b, x, y);
  return two_term_expansion(x, y, h);
}

// h = e + f (h has room for elen + flen, and must not alias e or f). Shewchuk's fast expansion
// sum: merge the components by magnitude, then carry a running approximation Q through them with
// two_sum, emitting each roundoff. Correct for strongly nonoverlapping inputs with
// round-to-nearest-even, which all expansions built here are.
// Not inlined: it only runs once a filter has failed, and inlined into its callers GCC 12 at -O3
// reports false stringop-overflow and maybe-uninitialized warnings (errors here).
__attribute__((noinline)) inline int expansion_sum(const double* e,
  int elen,
  const double* f,
  int flen,
  double* h)
{
  if (elen == 0)
  {
    std::copy(f, f + flen, h);
    return flen;
  }
  if (flen == 0)
  {
    std::copy(e, e + elen, h);
    return elen;
  }
  int ei = 0;
  int fi = 0;
  auto next = [&]() -> double
  {
    if (fi >= flen || (ei < elen && std::fabs(e[ei]) < std::fabs(f[fi])))
    {
      return e[ei++];
    }
    return f[fi++];
  };
  double q = next();
  int n = 0;
  const int total = elen + flen;
  for (int k = 1; k < total; ++k)
  {
    const double g = next();
    double qnew, hh;
    two_sum(q, g, qnew, hh);
    q = qnew;
    if (hh != 0.0)
    {
      h[n++] = hh;
    }
  }
  if (q != 0.0)
  {
    h[n++] = q;
  }
  return n;
}

// h = b * e (h has room for 2 * elen). TwoProduct is the exact product used: two_product (fast;
// with Dekker's split its factors must stay below about 2^996, see predicates.cpp) or
// two_product_fma (exact for any finite factors whose products neither overflow nor underflow).
template<void (*TwoProduct)(double, double, double&, double&) = two_product>
inline int scale_expansion(const double* e, int elen, double b, double* h)
{
  if (elen == 0 || b == 0.0)
  {
    return 0;
  }
  int n = 0;
  double q, hh;
  TwoProduct(e[0], b, q, hh);
  if (hh != 0.0)
  {
    h[n++] = hh;
  }
  for (int i = 1; i < elen; ++i)
  {
    double p1, p0, sum;
    TwoProduct(e[i], b, p1, p0);
    two_sum(q, p0, sum, hh);
    if (hh != 0.0)
    {
      h[n++] = hh;
    }
    fast_two_sum(p1, sum, q, hh);
    if (hh != 0.0)
    {
      h[n++] = hh;
    }
  }
  if (q != 0.0)
  {
    h[n++] = q;
  }
  return n;
}

constexpr int kMaxProduct = 512; // 2 * 16 * 16: the largest product predicates.cpp forms

// h = e * f (h has room for 2 * elen * flen <= kMaxProduct; neither length above 16).
inline int expansion_product(const double* e, int elen, const double* f, int flen, double* h)
{
  if (elen < flen)
  {
    std::swap(e, f);
    std::swap(elen, flen);
  }
  // Scale the longer expansion by each component of the shorter one and accumulate, ping-ponging
  // between h and a local buffer so that the result ends in h.
  double term[2 * 16 * 2];
  double other[kMaxProduct];
  double* acc = (flen % 2 == 1) ? h : other;
  double* spare = (flen % 2 == 1) ? other : h;
  int n = 0;
  for (int j = 0; j < flen; ++j)
  {
    const int tn = scale_expansion(e, elen, f[j], term);
    if (j == 0)
    {
      std::copy(term, term + tn, acc);
      n = tn;
    }
    else
    {
      n = expansion_sum(acc, n, term, tn, spare);
      std::swap(acc, spare);
    }
  }
  // After flen steps (the first a copy, each later one a swap) acc is h again.
  return n;
}

inline void negate(double* e, int n)
{
  for (int i = 0; i < n; ++i)
  {
    e[i] = -e[i];
  }
}

// (u * v - w * z), for u and w of length <= 2 and v and z of length <= Factor (h has room for
// 8 * Factor): length <= 16 for the default, as the determinants use it.
template<std::size_t Factor = 2>
inline int cross_expansion(const double* u,
  int un,
  const double* v,
  int vn,
  const double* w,
  int wn,
  const double* z,
  int zn,
  double* h)
{
  double p[4 * Factor], q[4 * Factor];
  const int pn = expansion_product(u, un, v, vn, p);
  const int qn = expansion_product(w, wn, z, zn, q);
  negate(q, qn);
  return expansion_sum(p, pn, q, qn, h);
}

// u^2 + v^2 for expansions of length <= 2: length <= 16.
inline int lift_expansion(const double* u, int un, const double* v, int vn, double* h)
{
  double p[8], q[8];
  const int pn = expansion_product(u, un, u, un, p);
  const int qn = expansion_product(v, vn, v, vn, q);
  return expansion_sum(p, pn, q, qn, h);
}

} // namespace expansion
} // namespace tessera
