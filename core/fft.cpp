#include "fft.h"

#include "errors.h"
#include "geometry.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace tessera
{

bool IsPowerOfTwo(std::size_t n)
{
  return n != 0 && (n & (n - 1)) == 0;
}

std::size_t NextPowerOfTwo(std::size_t n)
{
  std::size_t p = 1;
  while (p < n)
  {
    p <<= 1;
  }
  return p;
}

FftPlan::FftPlan(std::size_t n)
  : Length(n)
{
  if (!IsPowerOfTwo(n))
  {
    throw InputError("FFT length " + std::to_string(n) + " is not a power of two");
  }
  // Twiddles from cos/sin of each angle directly (not by repeated multiplication), so their
  // error stays at one rounding and does not grow with n.
  this->Twiddles.resize(n / 2);
  for (std::size_t k = 0; k < n / 2; ++k)
  {
    const double angle = -2.0 * Pi * static_cast<double>(k) / static_cast<double>(n);
    this->Twiddles[k] = { std::cos(angle), std::sin(angle) };
  }
  this->BitReversed.resize(n);
  std::size_t bits = 0;
  while ((std::size_t(1) << bits) < n)
  {
    ++bits;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    std::size_t r = 0;
    for (std::size_t b = 0; b < bits; ++b)
    {
      r |= ((i >> b) & 1u) << (bits - 1 - b);
    }
    this->BitReversed[i] = r;
  }
}

void FftPlan::Transform(Complex* data, bool inverse) const
{
  const std::size_t n = this->Length;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = this->BitReversed[i];
    if (i < j)
    {
      std::swap(data[i], data[j]);
    }
  }
  // The inverse uses conjugate twiddles; flipping the sign of the imaginary part is exact.
  const double sign = inverse ? -1.0 : 1.0;
  for (std::size_t half = 1; half < n; half <<= 1)
  {
    const std::size_t stride = n / (2 * half);
    for (std::size_t start = 0; start < n; start += 2 * half)
    {
      Complex* a = data + start;
      Complex* b = a + half;
      for (std::size_t k = 0; k < half; ++k)
      {
        const Complex w = this->Twiddles[k * stride];
        const double wi = sign * w.im;
        const double tr = b[k].re * w.re - b[k].im * wi;
        const double ti = b[k].re * wi + b[k].im * w.re;
        b[k] = { a[k].re - tr, a[k].im - ti };
        a[k] = { a[k].re + tr, a[k].im + ti };
      }
    }
  }
}

namespace
{

// Cache-blocked out-of-place transpose: a naive column walk misses the cache on every element
// once a row exceeds a few kilobytes.
void Transpose(const std::vector<Complex>& in,
  std::size_t rows,
  std::size_t cols,
  std::vector<Complex>& out)
{
  constexpr std::size_t block = 32;
  out.resize(rows * cols);
  for (std::size_t r0 = 0; r0 < rows; r0 += block)
  {
    const std::size_t r1 = std::min(rows, r0 + block);
    for (std::size_t c0 = 0; c0 < cols; c0 += block)
    {
      const std::size_t c1 = std::min(cols, c0 + block);
      for (std::size_t r = r0; r < r1; ++r)
      {
        for (std::size_t c = c0; c < c1; ++c)
        {
          out[c * rows + r] = in[r * cols + c];
        }
      }
    }
  }
}

void CheckGridSides(std::size_t rows, std::size_t cols, std::size_t size)
{
  if (!IsPowerOfTwo(rows) || !IsPowerOfTwo(cols))
  {
    throw InputError("2-D FFT sides " + std::to_string(rows) + " x " + std::to_string(cols) +
      " are not powers of two");
  }
  if (size != rows * cols)
  {
    throw InputError("2-D FFT buffer has " + std::to_string(size) + " entries, expected " +
      std::to_string(rows * cols));
  }
}

} // namespace

void Fft2DForwardTransposed(std::vector<Complex>& data,
  std::size_t rows,
  std::size_t cols,
  std::vector<Complex>& scratch)
{
  CheckGridSides(rows, cols, data.size());
  const FftPlan rowPlan(cols);
  for (std::size_t r = 0; r < rows; ++r)
  {
    rowPlan.Forward(data.data() + r * cols);
  }
  Transpose(data, rows, cols, scratch);
  data.swap(scratch);
  const FftPlan columnPlan(rows);
  for (std::size_t c = 0; c < cols; ++c)
  {
    columnPlan.Forward(data.data() + c * rows);
  }
}

void Fft2DInverseFromTransposed(std::vector<Complex>& data,
  std::size_t rows,
  std::size_t cols,
  std::size_t rowsNeeded,
  std::vector<Complex>& scratch)
{
  CheckGridSides(rows, cols, data.size());
  const FftPlan columnPlan(rows);
  for (std::size_t c = 0; c < cols; ++c)
  {
    columnPlan.InverseUnscaled(data.data() + c * rows);
  }
  Transpose(data, cols, rows, scratch);
  data.swap(scratch);
  const FftPlan rowPlan(cols);
  const double scale = 1.0 / static_cast<double>(rows * cols);
  for (std::size_t r = 0; r < std::min(rows, rowsNeeded); ++r)
  {
    Complex* row = data.data() + r * cols;
    rowPlan.InverseUnscaled(row);
    for (std::size_t c = 0; c < cols; ++c)
    {
      row[c].re *= scale;
      row[c].im *= scale;
    }
  }
}

} // namespace tessera
