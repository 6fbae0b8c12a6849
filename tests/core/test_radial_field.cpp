// The FFT field against the direct sum of equation 8 on small grids: within the stated bound for
// arbitrary points, and to rounding level when points sit on pixel centres (spreading is then
// exact, so only the convolution itself is being checked).
#include "errors.h"
#include "radial_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{

using tessera::Point2;
using tessera::RadialBasis;

std::vector<Point2> RandomPixelPoints(int count, int width, int height, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(0.0, width - 1.0);
  std::uniform_real_distribution<double> y(0.0, height - 1.0);
  std::vector<Point2> points(count);
  for (Point2& p : points)
  {
    p = { x(rng), y(rng) };
  }
  return points;
}

double MaxAbsDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    worst = std::max(worst, std::abs(a[k] - b[k]));
  }
  return worst;
}

double MaxValue(const std::vector<double>& a)
{
  double best = 0.0;
  for (double v : a)
  {
    best = std::max(best, v);
  }
  return best;
}

// Reference basis written out from the paper, independent of RadialBasisValue.
double ReferenceBasis(RadialBasis basis, double width, double d2)
{
  return basis == RadialBasis::Gaussian ? std::exp(-d2 / (2 * width * width))
                                        : std::pow(d2 + width * width, -0.5);
}

TEST(RadialField, DirectFieldIsEquationEight)
{
  const std::vector<Point2> points = RandomPixelPoints(5, 9, 7, 3);
  for (RadialBasis basis : { RadialBasis::InverseMultiquadric, RadialBasis::Gaussian })
  {
    const std::vector<double> field = tessera::DirectField(points, 9, 7, basis, 2.5);
    for (int j = 0; j < 7; ++j)
    {
      for (int i = 0; i < 9; ++i)
      {
        double sum = 0.0;
        for (const Point2& p : points)
        {
          sum += ReferenceBasis(basis, 2.5, (i - p.x) * (i - p.x) + (j - p.y) * (j - p.y));
        }
        EXPECT_NEAR(field[j * 9 + i], sum, 1e-12 * sum);
      }
    }
  }
}

struct FieldCase
{
  RadialBasis basis;
  double width;
  int gridWidth;
  int gridHeight;
  int points;
};

TEST(RadialField, FastFieldIsWithinTheStatedBoundOfTheDirectSum)
{
  const FieldCase cases[] = { { RadialBasis::InverseMultiquadric, 5.0, 48, 33, 300 },
    { RadialBasis::InverseMultiquadric, 2.0, 17, 40, 120 },
    { RadialBasis::Gaussian, 5.0, 48, 33, 300 },
    { RadialBasis::Gaussian, 3.0, 31, 31, 200 },
    { RadialBasis::InverseMultiquadric, 4.0, 1, 25, 30 } };
  unsigned seed = 11;
  for (const FieldCase& c : cases)
  {
    const std::vector<Point2> points =
      RandomPixelPoints(c.points, c.gridWidth, c.gridHeight, seed++);
    const std::vector<double> direct =
      tessera::DirectField(points, c.gridWidth, c.gridHeight, c.basis, c.width);
    const std::vector<double> fast =
      tessera::FastField(points, c.gridWidth, c.gridHeight, c.basis, c.width);
    const double bound =
      tessera::FastFieldErrorBound(c.basis, c.width, points.size(), c.gridWidth, c.gridHeight);
    const double error = MaxAbsDifference(fast, direct);
    EXPECT_LE(error, bound) << "width " << c.width << " grid " << c.gridWidth;
    // The bound is a worst case; in practice spreading errors are far smaller. A relative 1%
    // of the field maximum still catches an off-by-one pixel shift or a wrong padding (those
    // give errors comparable to the field itself).
    EXPECT_LT(error, 0.01 * MaxValue(direct)) << "width " << c.width;
  }
}

TEST(RadialField, FastFieldIsExactUpToRoundingForPointsOnPixelCentres)
{
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> column(0, 63);
  std::uniform_int_distribution<int> row(0, 40);
  std::vector<Point2> points(400);
  for (Point2& p : points)
  {
    p = { double(column(rng)), double(row(rng)) };
  }
  for (RadialBasis basis : { RadialBasis::InverseMultiquadric, RadialBasis::Gaussian })
  {
    const std::vector<double> direct = tessera::DirectField(points, 64, 41, basis, 3.0);
    const std::vector<double> fast = tessera::FastField(points, 64, 41, basis, 3.0);
    // Rounding only: 1e-10 of the largest value, far below any spreading error.
    EXPECT_LT(MaxAbsDifference(fast, direct), 1e-10 * MaxValue(direct));
  }
}

TEST(RadialField, BadPointsAreNamedByIndex)
{
  std::vector<Point2> points = { { 1, 1 }, { 2, 2 }, { NAN, 3 } };
  try
  {
    tessera::FastField(points, 10, 10, RadialBasis::Gaussian, 2.0);
    FAIL() << "NaN accepted";
  }
  catch (const tessera::InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 2"), std::string::npos) << e.what();
  }
  points[2] = { 10.5, 3 };
  EXPECT_THROW(tessera::FastField(points, 10, 10, RadialBasis::Gaussian, 2.0), tessera::InputError);
  points[2] = { 3, 3 };
  EXPECT_THROW(
    tessera::FastField(points, 10, 10, RadialBasis::Gaussian, -1.0), tessera::InputError);
}

} // namespace
