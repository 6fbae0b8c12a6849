#include "rational_gaussian_curve.h"

#include "errors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace tessera
{

namespace
{

struct ControlPoint
{
  double Node;
  double Weight;
  Point2 Position;
};

void CheckInput(const std::vector<double>& nodes,
  const std::vector<Point2>& controls,
  const std::vector<double>& weights,
  double sigma,
  int sampleCount)
{
  if (nodes.size() != controls.size() || weights.size() != controls.size())
  {
    throw InputError("RaG curve: " + std::to_string(nodes.size()) + " nodes, " +
      std::to_string(controls.size()) + " control points and " + std::to_string(weights.size()) +
      " weights differ in number");
  }
  if (controls.empty())
  {
    throw InputError("RaG curve has no control point");
  }
  CheckPositiveScale(sigma, "RaG curve sigma");
  if (sampleCount < 2)
  {
    throw InputError("RaG curve sample count " + std::to_string(sampleCount) + " is below 2");
  }
  for (std::size_t k = 0; k < nodes.size(); ++k)
  {
    if (!(nodes[k] >= 0.0 && nodes[k] <= 1.0))
    {
      throw InputError(
        "RaG node " + std::to_string(k) + " (" + NumberText(nodes[k]) + ") is outside [0, 1]");
    }
    if (!(weights[k] > 0.0) || !std::isfinite(weights[k]))
    {
      throw InputError("RaG weight " + std::to_string(k) + " (" + NumberText(weights[k]) +
        ") is not a positive number");
    }
    if (!std::isfinite(controls[k].x) || !std::isfinite(controls[k].y))
    {
      throw InputError(
        "RaG control point " + std::to_string(k) + " has a NaN or infinite coordinate");
    }
  }
}

// Controls sorted by node. A closed curve gets copies shifted by -1 and +1 so that a window of
// half-width below 1/2 around any u in [0, 1) sees each periodic image at most once.
std::vector<ControlPoint> SortedControls(const std::vector<double>& nodes,
  const std::vector<Point2>& controls,
  const std::vector<double>& weights,
  bool closed)
{
  std::vector<ControlPoint> sorted;
  const int shifts = closed ? 1 : 0;
  for (int shift = -shifts; shift <= shifts; ++shift)
  {
    for (std::size_t k = 0; k < nodes.size(); ++k)
    {
      sorted.push_back({ nodes[k] + shift, weights[k], controls[k] });
    }
  }
  std::sort(sorted.begin(),
    sorted.end(),
    [](const ControlPoint& a, const ControlPoint& b) { return a.Node < b.Node; });
  return sorted;
}

// Sum of weighted Gaussians relative to exp(-nearest^2 / 2 sigma^2), over the controls within
// `radius` of u, found by walking outwards from the insertion point of u. Returns false for a
// closed curve whose window would reach half a period (and so could see a node twice).
bool WindowedAverage(const std::vector<ControlPoint>& sorted,
  double u,
  double sigma,
  bool closed,
  Point2& average)
{
  const auto at = std::lower_bound(sorted.begin(),
    sorted.end(),
    u,
    [](const ControlPoint& c, double value) { return c.Node < value; });
  const std::size_t position = static_cast<std::size_t>(at - sorted.begin());
  double nearest = std::numeric_limits<double>::infinity();
  if (position < sorted.size())
  {
    nearest = std::min(nearest, std::abs(sorted[position].Node - u));
  }
  if (position > 0)
  {
    nearest = std::min(nearest, std::abs(sorted[position - 1].Node - u));
  }
  const double twoSigma2 = 2.0 * sigma * sigma;
  const double radius2 = nearest * nearest + 64.0 * sigma * sigma;
  if (closed && radius2 >= 0.25)
  {
    return false;
  }
  double sumW = 0.0;
  double sumX = 0.0;
  double sumY = 0.0;
  auto accumulate = [&](const ControlPoint& c)
  {
    const double d = c.Node - u;
    const double g = c.Weight * std::exp(-(d * d - nearest * nearest) / twoSigma2);
    sumW += g;
    sumX += g * c.Position.x;
    sumY += g * c.Position.y;
  };
  for (std::size_t k = position; k < sorted.size(); ++k)
  {
    const double d = sorted[k].Node - u;
    if (d * d > radius2)
    {
      break;
    }
    accumulate(sorted[k]);
  }
  for (std::size_t k = position; k-- > 0;)
  {
    const double d = sorted[k].Node - u;
    if (d * d > radius2)
    {
      break;
    }
    accumulate(sorted[k]);
  }
  average = { sumX / sumW, sumY / sumW };
  return true;
}

// Below this sigma a closed curve's periodic Gaussian is summed over its images directly (at most
// 2 * 6 + 1 of them); from it on, as its Fourier series (PeriodicFourierSum).
constexpr double FourierSigma = 0.5;

// A closed curve with a wide sigma (a period of 1): by Poisson summation, the periodic Gaussian
// sum over k of exp(-(d + k)^2 / (2 sigma^2)) is sqrt(2 pi) sigma (1 + 2 sum over m >= 1 of
// exp(-2 pi^2 sigma^2 m^2) cos(2 pi m d)), whose terms fall so fast for sigma >= 1/2 that three
// give it to double precision. The images summed directly would number 16 sigma (a sigma of 1e4
// took a minute, and one of 1e9 overflowed their count into NaN curves). The constant factor
// cancels in the ratio; for a huge sigma every weight is 1: the curve is the controls' centroid.
Point2 PeriodicFourierSum(const std::vector<double>& nodes,
  const std::vector<Point2>& controls,
  const std::vector<double>& weights,
  double u,
  double sigma)
{
  // The terms beyond exp(-40) (4e-18) of the first are dropped: m up to sqrt(40 / 2 pi^2) / sigma.
  // (At most 3 terms from sigma 1/2 on: no allocation per sample.)
  const int terms = static_cast<int>(std::ceil(std::sqrt(40.0 / (2.0 * Pi * Pi)) / sigma));
  std::array<double, 4> amplitude{};
  for (int m = 1; m <= terms; ++m)
  {
    amplitude[m] = 2.0 * std::exp(-2.0 * Pi * Pi * sigma * sigma * m * m);
  }
  double sumW = 0.0;
  double sumX = 0.0;
  double sumY = 0.0;
  for (std::size_t k = 0; k < nodes.size(); ++k)
  {
    double g = 1.0;
    for (int m = 1; m <= terms; ++m)
    {
      g += amplitude[m] * std::cos(2.0 * Pi * m * (u - nodes[k]));
    }
    g *= weights[k];
    sumW += g;
    sumX += g * controls[k].x;
    sumY += g * controls[k].y;
  }
  return { sumX / sumW, sumY / sumW };
}

// Closed curve whose window reaches half a period: sum every periodic image explicitly (sigma
// under FourierSigma: at most 6 images either way).
Point2 PeriodicFullSum(const std::vector<double>& nodes,
  const std::vector<Point2>& controls,
  const std::vector<double>& weights,
  double u,
  double sigma)
{
  if (sigma >= FourierSigma)
  {
    return PeriodicFourierSum(nodes, controls, weights, u, sigma);
  }
  const double twoSigma2 = 2.0 * sigma * sigma;
  const int images = static_cast<int>(std::ceil(8.0 * sigma)) + 2;
  double nearest = std::numeric_limits<double>::infinity();
  for (double node : nodes)
  {
    const double d = u - node;
    nearest = std::min(nearest, std::abs(d - std::round(d)));
  }
  double sumW = 0.0;
  double sumX = 0.0;
  double sumY = 0.0;
  for (std::size_t k = 0; k < nodes.size(); ++k)
  {
    for (int shift = -images; shift <= images; ++shift)
    {
      const double d = u - nodes[k] + shift;
      const double g = weights[k] * std::exp(-(d * d - nearest * nearest) / twoSigma2);
      sumW += g;
      sumX += g * controls[k].x;
      sumY += g * controls[k].y;
    }
  }
  return { sumX / sumW, sumY / sumW };
}

// The samples of the curve of these controls and weights at the indices where samples is not
// finite (all of them, at first), scaled by 2^xExponent and 2^yExponent.
void SampleWhereNotFinite(const std::vector<double>& nodes,
  const std::vector<Point2>& controls,
  const std::vector<double>& weights,
  double sigma,
  bool closed,
  int xExponent,
  int yExponent,
  std::vector<Point2>& samples)
{
  const std::vector<ControlPoint> sorted = SortedControls(nodes, controls, weights, closed);
  const double denominator = closed ? samples.size() : samples.size() - 1;
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    if (std::isfinite(samples[s].x) && std::isfinite(samples[s].y))
    {
      continue;
    }
    const double u = double(s) / denominator;
    Point2 sample;
    if (!WindowedAverage(sorted, u, sigma, closed, sample))
    {
      sample = PeriodicFullSum(nodes, controls, weights, u, sigma);
    }
    samples[s] = { std::ldexp(sample.x, xExponent), std::ldexp(sample.y, yExponent) };
  }
}

} // namespace

// The sums of weight x coordinate overflow for finite input: 2000 points about 9e305 (within the
// +-1e306 RidgeGrouping takes) gave NaN samples, and so did weights of 1e300 on coordinates of 10.
// A sample that does not come out finite is computed again from the controls' x and y, each
// scaled into (-1, 1) by a power of two (exact; the sums are then at most the number of controls),
// and where that is not enough, from the weights too scaled to a largest of [1, 2). The samples
// that came out finite are the unscaled sums' (scaling every sample lost the weights below 2^-1074
// of the largest, which decide the curve far from that control's node, and made tiny y subnormal
// beside huge x).
std::vector<Point2> SampleRationalGaussianCurve(const std::vector<double>& nodes,
  const std::vector<Point2>& controls,
  const std::vector<double>& weights,
  double sigma,
  bool closed,
  int sampleCount)
{
  CheckInput(nodes, controls, weights, sigma, sampleCount);
  constexpr double NotYet = std::numeric_limits<double>::quiet_NaN();
  std::vector<Point2> samples(static_cast<std::size_t>(sampleCount), Point2{ NotYet, NotYet });
  SampleWhereNotFinite(nodes, controls, weights, sigma, closed, 0, 0, samples);
  if (std::all_of(samples.begin(),
        samples.end(),
        [](const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }))
  {
    return samples;
  }
  double largestX = 0.0, largestY = 0.0;
  for (const Point2& c : controls)
  {
    largestX = std::max(largestX, std::fabs(c.x));
    largestY = std::max(largestY, std::fabs(c.y));
  }
  const int xExponent = ExponentAbove(largestX), yExponent = ExponentAbove(largestY);
  std::vector<Point2> scaled(controls.size());
  for (std::size_t k = 0; k < controls.size(); ++k)
  {
    scaled[k] = { std::ldexp(controls[k].x, -xExponent), std::ldexp(controls[k].y, -yExponent) };
  }
  SampleWhereNotFinite(nodes, scaled, weights, sigma, closed, xExponent, yExponent, samples);
  const int weightExponent = ExponentAbove(*std::max_element(weights.begin(), weights.end())) - 1;
  std::vector<double> scaledWeights(weights.size());
  for (std::size_t k = 0; k < weights.size(); ++k)
  {
    scaledWeights[k] = std::ldexp(weights[k], -weightExponent);
  }
  SampleWhereNotFinite(nodes, scaled, scaledWeights, sigma, closed, xExponent, yExponent, samples);
  return samples;
}

} // namespace tessera
