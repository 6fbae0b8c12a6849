// RaG curves against the formula summed directly over every control point (and, for closed
// curves, over many periodic images), plus the merging of control points that share a node.
#include "errors.h"
#include "rational_gaussian_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{

using tessera::Point2;

// Goshtasby 1995 with unit weights per point, written out directly.
Point2 DirectRag(const std::vector<double>& nodes,
  const std::vector<Point2>& points,
  double u,
  double sigma,
  bool closed)
{
  long double sw = 0.0L;
  long double sx = 0.0L;
  long double sy = 0.0L;
  const int images = closed ? 6 : 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    for (int k = -images; k <= images; ++k)
    {
      const long double d = u - nodes[i] + k;
      const long double g = std::exp(-d * d / (2.0L * sigma * sigma));
      sw += g;
      sx += g * points[i].x;
      sy += g * points[i].y;
    }
  }
  return { static_cast<double>(sx / sw), static_cast<double>(sy / sw) };
}

void RandomControls(int n, unsigned seed, std::vector<double>& nodes, std::vector<Point2>& points)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  nodes.resize(n);
  points.resize(n);
  for (int i = 0; i < n; ++i)
  {
    nodes[i] = unit(rng);
    points[i] = { 10 * std::cos(6 * nodes[i]) + unit(rng),
      10 * std::sin(6 * nodes[i]) + unit(rng) };
  }
}

TEST(RationalGaussianCurve, MatchesTheDirectFormula)
{
  std::vector<double> nodes;
  std::vector<Point2> points;
  RandomControls(200, 3, nodes, points);
  const std::vector<double> weights(nodes.size(), 1.0);
  for (bool closed : { false, true })
  {
    for (double sigma : { 0.01, 0.04, 0.08, 0.3 })
    {
      const int samples = 101;
      const std::vector<Point2> curve =
        tessera::SampleRationalGaussianCurve(nodes, points, weights, sigma, closed, samples);
      ASSERT_EQ(curve.size(), std::size_t(samples));
      for (int s = 0; s < samples; ++s)
      {
        const double u = closed ? s / double(samples) : s / double(samples - 1);
        const Point2 expected = DirectRag(nodes, points, u, sigma, closed);
        // Skipped terms are below exp(-32) of the largest: relative 1e-12 of the coordinates.
        EXPECT_NEAR(curve[s].x, expected.x, 1e-9) << "sigma " << sigma << " u " << u;
        EXPECT_NEAR(curve[s].y, expected.y, 1e-9) << "sigma " << sigma << " u " << u;
      }
    }
  }
}

TEST(RationalGaussianCurve, MergingPointsWithTheSameNodeGivesTheSameCurve)
{
  std::vector<double> nodes;
  std::vector<Point2> points;
  RandomControls(60, 9, nodes, points);
  // Each node carries three points; merged, their mean with weight 3.
  std::vector<double> allNodes;
  std::vector<Point2> allPoints;
  std::vector<double> mergedWeights(nodes.size(), 3.0);
  std::vector<Point2> means(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    Point2 sum{ 0, 0 };
    for (int copy = 0; copy < 3; ++copy)
    {
      const Point2 p{ points[i].x + copy * 0.3, points[i].y - copy * 0.2 };
      allNodes.push_back(nodes[i]);
      allPoints.push_back(p);
      sum.x += p.x;
      sum.y += p.y;
    }
    means[i] = { sum.x / 3, sum.y / 3 };
  }
  const std::vector<double> unit(allNodes.size(), 1.0);
  for (bool closed : { false, true })
  {
    const auto full =
      tessera::SampleRationalGaussianCurve(allNodes, allPoints, unit, 0.03, closed, 77);
    const auto merged =
      tessera::SampleRationalGaussianCurve(nodes, means, mergedWeights, 0.03, closed, 77);
    for (std::size_t s = 0; s < full.size(); ++s)
    {
      EXPECT_NEAR(full[s].x, merged[s].x, 1e-9);
      EXPECT_NEAR(full[s].y, merged[s].y, 1e-9);
    }
  }
}

TEST(RationalGaussianCurve, StaysFiniteFarFromAllNodes)
{
  // Two clusters of nodes with a wide gap: exp(-d^2 / 2 sigma^2) underflows to 0 for every term
  // in the middle, where the unnormalised formula would give 0/0.
  const std::vector<double> nodes = { 0.0, 0.01, 0.99, 1.0 };
  const std::vector<Point2> points = { { 0, 0 }, { 1, 0 }, { 5, 5 }, { 6, 5 } };
  const std::vector<double> weights(4, 1.0);
  const auto curve = tessera::SampleRationalGaussianCurve(nodes, points, weights, 0.001, false, 51);
  for (const Point2& p : curve)
  {
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
  }
  EXPECT_NEAR(curve[20].x, 1.0, 1e-9); // u = 0.4: the nearest node is 0.01
}

// A wide sigma on a closed curve is summed as a Fourier series (from sigma 1/2): it must match the
// images summed directly (enough of them: 16 sigma + 12), run in time independent of sigma, and
// tend to the controls' weighted centroid (a sigma of 1e9 once gave NaN curves, and 1e4 a minute).
TEST(RationalGaussianCurve, ClosedCurvesWithAWideSigmaMatchTheImageSum)
{
  std::vector<double> nodes;
  std::vector<Point2> points;
  RandomControls(50, 5, nodes, points);
  std::vector<double> weights(nodes.size());
  for (std::size_t i = 0; i < weights.size(); ++i)
  {
    weights[i] = 1.0 + static_cast<double>(i % 3);
  }
  for (double sigma : { 0.4999, 0.5, 0.7, 2.0 })
  {
    const int samples = 40;
    const auto curve =
      tessera::SampleRationalGaussianCurve(nodes, points, weights, sigma, true, samples);
    const int images = static_cast<int>(std::ceil(16.0 * sigma)) + 12;
    for (int s = 0; s < samples; ++s)
    {
      const double u = s / double(samples);
      long double sw = 0.0L, sx = 0.0L, sy = 0.0L;
      for (std::size_t i = 0; i < nodes.size(); ++i)
      {
        for (int k = -images; k <= images; ++k)
        {
          const long double d = u - nodes[i] + k;
          const long double g = weights[i] * std::exp(-d * d / (2.0L * sigma * sigma));
          sw += g;
          sx += g * points[i].x;
          sy += g * points[i].y;
        }
      }
      EXPECT_NEAR(curve[s].x, static_cast<double>(sx / sw), 1e-11) << "sigma " << sigma;
      EXPECT_NEAR(curve[s].y, static_cast<double>(sy / sw), 1e-11) << "sigma " << sigma;
    }
  }
  double cx = 0.0, cy = 0.0, total = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    cx += weights[i] * points[i].x;
    cy += weights[i] * points[i].y;
    total += weights[i];
  }
  for (double sigma : { 1e4, 1e9, 1e300 })
  {
    for (const Point2& p :
      tessera::SampleRationalGaussianCurve(nodes, points, weights, sigma, true, 16))
    {
      EXPECT_NEAR(p.x, cx / total, 1e-12) << "sigma " << sigma;
      EXPECT_NEAR(p.y, cy / total, 1e-12) << "sigma " << sigma;
    }
  }
}

// Finite controls and weights whose products overflow: the curve is the one of the controls
// scaled down, scaled back (an affine map: RaG basis functions sum to 1). 2000 controls about
// 9e305, or weights of 1e300 on coordinates of 10, gave NaN samples.
TEST(RationalGaussianCurve, LargeCoordinatesAndWeightsDoNotOverflow)
{
  std::vector<double> nodes;
  std::vector<Point2> points;
  RandomControls(2000, 7, nodes, points);
  const std::vector<double> ones(nodes.size(), 1.0);
  for (bool closed : { false, true })
  {
    for (double sigma : { 0.04, 0.3, 0.7 })
    {
      const auto curve =
        tessera::SampleRationalGaussianCurve(nodes, points, ones, sigma, closed, 64);
      std::vector<Point2> far(points.size());
      for (std::size_t i = 0; i < points.size(); ++i)
      {
        far[i] = { 9e305 + 1e304 * points[i].x, -9e305 + 1e304 * points[i].y };
      }
      const auto farCurve =
        tessera::SampleRationalGaussianCurve(nodes, far, ones, sigma, closed, 64);
      const std::vector<double> heavy(nodes.size(), 1e300);
      const auto heavyCurve =
        tessera::SampleRationalGaussianCurve(nodes, points, heavy, sigma, closed, 64);
      for (std::size_t s = 0; s < curve.size(); ++s)
      {
        EXPECT_NEAR((farCurve[s].x - 9e305) / 1e304, curve[s].x, 1e-6) << "sigma " << sigma;
        EXPECT_NEAR((farCurve[s].y + 9e305) / 1e304, curve[s].y, 1e-6) << "sigma " << sigma;
        EXPECT_NEAR(heavyCurve[s].x, curve[s].x, 1e-12) << "sigma " << sigma;
        EXPECT_NEAR(heavyCurve[s].y, curve[s].y, 1e-12) << "sigma " << sigma;
      }
    }
  }
}

// Where nothing overflows, nothing is scaled: weights far below the largest decide the curve far
// from that control's node (at u = 0.95 with sigma 0.01 the weight of 1e300 at node 0 counts
// e^-4512 of itself, nothing, and the sample is the mean of the controls at 0.9 and 1 weighted
// 1 : 3), and a tiny y beside a huge x keeps its digits. Scaling every sample gave (0, 16) for
// (4, 17.5), and y wrong in the 4th digit.
TEST(RationalGaussianCurve, SmallWeightsAndCoordinatesKeepTheirDigits)
{
  const std::vector<double> nodes{ 0.0, 0.9, 1.0 };
  const std::vector<Point2> controls{ { 0, 0 }, { 1, 10 }, { 5, 20 } };
  for (const double small : { 1e-10, 1e-30, 1e-200 })
  {
    const auto curve = tessera::SampleRationalGaussianCurve(
      nodes, controls, { 1e300, small, 3 * small }, 0.01, false, 21);
    EXPECT_NEAR(curve[19].x, 4.0, 1e-12) << small;
    EXPECT_NEAR(curve[19].y, 17.5, 1e-12) << small;
  }
  std::vector<double> randomNodes;
  std::vector<Point2> points;
  RandomControls(200, 9, randomNodes, points);
  std::vector<Point2> tinyY(points.size()), largeY(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    tinyY[i] = { 1e20 * (1 + points[i].x), 1e-300 * (20 + points[i].y) };
    largeY[i] = { tinyY[i].x, std::ldexp(tinyY[i].y, 1000) }; // (y scaled alone: an affine map)
  }
  const std::vector<double> ones(points.size(), 1.0);
  const auto tiny = tessera::SampleRationalGaussianCurve(randomNodes, tinyY, ones, 0.04, false, 50);
  const auto large =
    tessera::SampleRationalGaussianCurve(randomNodes, largeY, ones, 0.04, false, 50);
  for (std::size_t s = 0; s < tiny.size(); ++s)
  {
    EXPECT_NEAR(std::ldexp(tiny[s].y, 1000), large[s].y, 1e-14 * std::fabs(large[s].y)) << s;
  }
}

TEST(RationalGaussianCurve, RejectsBadInput)
{
  const std::vector<double> nodes = { 0.0, 0.5 };
  const std::vector<Point2> points = { { 0, 0 }, { 1, 1 } };
  const std::vector<double> weights = { 1.0, 1.0 };
  EXPECT_THROW(tessera::SampleRationalGaussianCurve(nodes, points, weights, 0.0, false, 10),
    tessera::InputError);
  EXPECT_THROW(tessera::SampleRationalGaussianCurve({ 0.0, 1.5 }, points, weights, 0.1, false, 10),
    tessera::InputError);
  EXPECT_THROW(tessera::SampleRationalGaussianCurve(nodes, points, { 1.0, -1.0 }, 0.1, false, 10),
    tessera::InputError);
  EXPECT_THROW(tessera::SampleRationalGaussianCurve(nodes, points, weights, 0.1, false, 1),
    tessera::InputError);
}

} // namespace
