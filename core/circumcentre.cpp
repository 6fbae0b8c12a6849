// The exact (expansion) parts of circumcentre.h: they run only for ill-conditioned triangles.
// Out of line so that the expansion arithmetic is compiled here, with contraction off, as
// expansion_arithmetic.h requires of every includer.
#include "fp_contract_off.h" // first: before the expansion arithmetic

#include "circumcentre.h"

#include "expansion_arithmetic.h"

// GCC 12 at -O3 inlines lift_expansion here and reports its buffers as maybe uninitialized when
// passed to expansion_sum (a false positive, as expansion_arithmetic.h notes for expansion_sum;
// every component read is written first).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <algorithm>
#include <cmath>

namespace tessera
{

namespace
{

/// The value of an expansion, rounded (summed from its smallest component up).
double EstimateOf(const double* e, int n)
{
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    sum += e[i];
  }
  return sum;
}

/// e * f - g * h from exact products, rounded (e and g of at most 2 components, f and h of at most
/// 16).
double DifferenceOfProducts(const double* e,
  int ne,
  const double* f,
  int nf,
  const double* g,
  int ng,
  const double* h,
  int nh)
{
  double difference[128];
  return EstimateOf(
    difference, expansion::cross_expansion<16>(e, ne, f, nf, g, ng, h, nh, difference));
}

} // namespace

double ExactTwiceSignedArea(double bx, double by, double cx, double cy)
{
  double pHigh, pLow, qHigh, qLow;
  expansion::two_product(bx, cy, pHigh, pLow);
  expansion::two_product(by, cx, qHigh, qLow);
  return (pHigh - qHigh) + (pLow - qLow); // pHigh - qHigh is exact here (Sterbenz)
}

namespace
{
/// u = circumcentre - o from exact arithmetic: the sides as exact differences, scaled by a power of
/// two that takes their largest component to about 2^300 (so that products of three stay below
/// 2^900, and a side a subnormal length long keeps its bits: only parts some 2^-650 of the largest
/// underflow in products, too small to matter), the numerators (degree 3) and the denominator
/// (degree 2) as exact expansions, each rounded (summing an expansion's components errs by a few
/// ulps), and the quotient scaled back.
void ExactCircumcentreOffset(const Point2& o,
  const Point2& b,
  const Point2& c,
  double& ux,
  double& uy)
{
  using namespace expansion;
  double side[4][2];
  int length[4];
  length[0] = diff_expansion(b.x, o.x, side[0]);
  length[1] = diff_expansion(b.y, o.y, side[1]);
  length[2] = diff_expansion(c.x, o.x, side[2]);
  length[3] = diff_expansion(c.y, o.y, side[3]);
  double largest = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    for (int i = 0; i < length[k]; ++i)
    {
      largest = std::max(largest, std::fabs(side[k][i]));
    }
  }
  const int scale = largest > 0.0 ? 300 - std::ilogb(largest) : 0;
  for (int k = 0; k < 4; ++k)
  {
    for (int i = 0; i < length[k]; ++i)
    {
      side[k][i] = std::ldexp(side[k][i], scale);
    }
  }
  const double *bx = side[0], *by = side[1], *cx = side[2], *cy = side[3];
  const int nbx = length[0], nby = length[1], ncx = length[2], ncy = length[3];
  // Squared sides (b2, c2) exactly; twice the area (bx cy - by cx) rounded from exact products.
  double b2[16], c2[16], area[16];
  const int nb2 = lift_expansion(bx, nbx, by, nby, b2);
  const int nc2 = lift_expansion(cx, ncx, cy, ncy, c2);
  // ux = (cy b2 - by c2) / (2 area), uy = (bx c2 - cx b2) / (2 area).
  const double denominator =
    2.0 * EstimateOf(area, cross_expansion(bx, nbx, cy, ncy, by, nby, cx, ncx, area));
  ux = std::ldexp(DifferenceOfProducts(cy, ncy, b2, nb2, by, nby, c2, nc2) / denominator, -scale);
  uy = std::ldexp(DifferenceOfProducts(bx, nbx, c2, nc2, cx, ncx, b2, nb2) / denominator, -scale);
}
} // namespace

void IllConditionedCircumcentre(const Point2& b, const Point2& c, CircumcentreTerms& t)
{
  t.d = 2.0 * TwiceSignedArea(t.bx, t.by, t.cx, t.cy);
  ExactCircumcentreOffset(t.Origin, b, c, t.ux, t.uy);
}

} // namespace tessera
