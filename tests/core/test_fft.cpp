// The radix-2 FFT against the defining O(n^2) sum, and the 2-D transposed pair as a round trip
// and against a separable direct 2-D DFT.
#include "errors.h"
#include "fft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{

using tessera::Complex;

std::vector<Complex> RandomSignal(std::size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Complex> x(n);
  for (Complex& c : x)
  {
    c = { value(rng), value(rng) };
  }
  return x;
}

std::vector<Complex> NaiveDft(const std::vector<Complex>& x, double sign)
{
  const std::size_t n = x.size();
  const double pi = std::acos(-1.0);
  std::vector<Complex> out(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    long double re = 0.0L;
    long double im = 0.0L;
    for (std::size_t j = 0; j < n; ++j)
    {
      // Reduce j*k mod n first so the angle is exact to one rounding.
      const long double angle = sign * 2.0L * pi * static_cast<long double>((j * k) % n) / n;
      re += x[j].re * std::cos(angle) - x[j].im * std::sin(angle);
      im += x[j].re * std::sin(angle) + x[j].im * std::cos(angle);
    }
    out[k] = { static_cast<double>(re), static_cast<double>(im) };
  }
  return out;
}

double MaxDifference(const std::vector<Complex>& a, const std::vector<Complex>& b)
{
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    worst = std::max(worst, std::hypot(a[k].re - b[k].re, a[k].im - b[k].im));
  }
  return worst;
}

TEST(Fft, MatchesTheDefiningSumForEveryPowerOfTwoUpTo512)
{
  for (std::size_t n = 1; n <= 512; n *= 2)
  {
    const std::vector<Complex> x = RandomSignal(n, static_cast<unsigned>(n));
    std::vector<Complex> forward = x;
    tessera::FftPlan(n).Forward(forward.data());
    // Cooley-Tukey error grows like eps * log2(n) * ||x||; 1e-13 * sqrt(n) * log2(2n) is that
    // with a generous constant, and far below the O(1) error of a wrong twiddle or permutation.
    const double tolerance = 1e-13 * std::sqrt(double(n)) * std::log2(2.0 * n);
    EXPECT_LT(MaxDifference(forward, NaiveDft(x, -1.0)), tolerance) << "n = " << n;
    std::vector<Complex> inverse = x;
    tessera::FftPlan(n).InverseUnscaled(inverse.data());
    EXPECT_LT(MaxDifference(inverse, NaiveDft(x, 1.0)), tolerance) << "n = " << n;
  }
}

TEST(Fft, RejectsLengthsThatAreNotPowersOfTwo)
{
  EXPECT_THROW(tessera::FftPlan(0), tessera::InputError);
  EXPECT_THROW(tessera::FftPlan(12), tessera::InputError);
  EXPECT_EQ(tessera::NextPowerOfTwo(1025), 2048u);
  EXPECT_EQ(tessera::NextPowerOfTwo(1024), 1024u);
}

TEST(Fft, TwoDimensionalTransformMatchesRowThenColumnDft)
{
  const std::size_t rows = 8;
  const std::size_t cols = 16;
  const std::vector<Complex> x = RandomSignal(rows * cols, 7);
  // Independent 2-D DFT: naive DFT of every row, then of every column.
  std::vector<Complex> expected(rows * cols);
  std::vector<std::vector<Complex>> rowSpectra(rows);
  for (std::size_t r = 0; r < rows; ++r)
  {
    rowSpectra[r] =
      NaiveDft(std::vector<Complex>(x.begin() + r * cols, x.begin() + (r + 1) * cols), -1.0);
  }
  for (std::size_t c = 0; c < cols; ++c)
  {
    std::vector<Complex> column(rows);
    for (std::size_t r = 0; r < rows; ++r)
    {
      column[r] = rowSpectra[r][c];
    }
    const std::vector<Complex> spectrum = NaiveDft(column, -1.0);
    for (std::size_t r = 0; r < rows; ++r)
    {
      expected[c * rows + r] = spectrum[r]; // transposed layout
    }
  }
  std::vector<Complex> data = x;
  std::vector<Complex> scratch;
  tessera::Fft2DForwardTransposed(data, rows, cols, scratch);
  EXPECT_LT(MaxDifference(data, expected), 1e-12);
  tessera::Fft2DInverseFromTransposed(data, rows, cols, rows, scratch);
  EXPECT_LT(MaxDifference(data, x), 1e-14);
}

} // namespace
