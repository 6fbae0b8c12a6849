#include "radial_field.h"

#include "errors.h"
#include "fft.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tessera
{

double RadialBasisValue(RadialBasis basis, double width, double squaredDistance)
{
  if (basis == RadialBasis::Gaussian)
  {
    return std::exp(-squaredDistance / (2.0 * width * width));
  }
  return 1.0 / std::sqrt(squaredDistance + width * width);
}

namespace
{

void CheckGrid(int gridWidth, int gridHeight, double width)
{
  if (gridWidth < 1 || gridHeight < 1)
  {
    throw InputError("field grid " + std::to_string(gridWidth) + " x " +
      std::to_string(gridHeight) + " has no pixels");
  }
  CheckPositiveScale(width, "basis width");
}

void CheckPointsInsideGrid(const std::vector<Point2>& pixelPoints, int gridWidth, int gridHeight)
{
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const Point2& p = pixelPoints[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
    {
      throw InputError("point " + std::to_string(k) + " has a NaN or infinite coordinate");
    }
    if (p.x < 0.0 || p.y < 0.0 || p.x > gridWidth - 1 || p.y > gridHeight - 1)
    {
      throw InputError("point " + std::to_string(k) + " at pixel (" + NumberText(p.x) + ", " +
        NumberText(p.y) + ") lies outside the field grid");
    }
  }
}

// Lower corner of the pixel cell holding coordinate t and the fraction towards the upper one.
// The last pixel is folded into the cell below it so that all four corners exist.
void CellCorner(double t, int sideLength, int& corner, double& fraction)
{
  if (sideLength == 1)
  {
    corner = 0;
    fraction = 0.0;
    return;
  }
  corner = std::min(static_cast<int>(std::floor(t)), sideLength - 2);
  fraction = t - corner;
}

// Row y of the padded grid holds kernel offset y (y < P/2) or y - P (wrapped negative offsets).
int WrappedOffset(std::size_t index, std::size_t paddedSide)
{
  return index < (paddedSide + 1) / 2 ? static_cast<int>(index)
                                      : static_cast<int>(index) - static_cast<int>(paddedSide);
}

// Real part: the points spread bilinearly onto the unpadded corner of the grid. Imaginary part:
// the kernel over the whole padded domain. One complex transform then serves both real inputs.
void FillPackedInput(std::vector<Complex>& buffer,
  std::size_t paddedWidth,
  std::size_t paddedHeight,
  const std::vector<Point2>& pixelPoints,
  int gridWidth,
  int gridHeight,
  RadialBasis basis,
  double width)
{
  buffer.assign(paddedWidth * paddedHeight, Complex{});
  for (const Point2& p : pixelPoints)
  {
    int i = 0;
    int j = 0;
    double fx = 0.0;
    double fy = 0.0;
    CellCorner(p.x, gridWidth, i, fx);
    CellCorner(p.y, gridHeight, j, fy);
    const std::size_t base = static_cast<std::size_t>(j) * paddedWidth + i;
    buffer[base].re += (1.0 - fx) * (1.0 - fy);
    if (gridWidth > 1)
    {
      buffer[base + 1].re += fx * (1.0 - fy);
    }
    if (gridHeight > 1)
    {
      buffer[base + paddedWidth].re += (1.0 - fx) * fy;
    }
    if (gridWidth > 1 && gridHeight > 1)
    {
      buffer[base + paddedWidth + 1].re += fx * fy;
    }
  }
  for (std::size_t y = 0; y < paddedHeight; ++y)
  {
    const double dy = WrappedOffset(y, paddedHeight);
    Complex* row = buffer.data() + y * paddedWidth;
    for (std::size_t x = 0; x < paddedWidth; ++x)
    {
      const double dx = WrappedOffset(x, paddedWidth);
      row[x].im = RadialBasisValue(basis, width, dx * dx + dy * dy);
    }
  }
}

// Z = FFT(a + i k) for real a, k gives A(f) = (Z(f) + conj Z(-f)) / 2 and
// K(f) = (Z(f) - conj Z(-f)) / 2i. Their product is Hermitian, so each conjugate pair is
// computed once. The spectrum is in the transposed layout [kx * rows + ky].
void MultiplyUnpackedSpectra(std::vector<Complex>& spectrum, std::size_t rows, std::size_t cols)
{
  for (std::size_t kx = 0; kx < cols; ++kx)
  {
    const std::size_t mx = (cols - kx) % cols;
    for (std::size_t ky = 0; ky < rows; ++ky)
    {
      const std::size_t my = (rows - ky) % rows;
      const std::size_t here = kx * rows + ky;
      const std::size_t mirror = mx * rows + my;
      if (mirror < here)
      {
        continue;
      }
      const Complex z = spectrum[here];
      const Complex w = spectrum[mirror];
      const Complex a = { 0.5 * (z.re + w.re), 0.5 * (z.im - w.im) };
      const Complex k = { 0.5 * (z.im + w.im), -0.5 * (z.re - w.re) };
      const Complex product = { a.re * k.re - a.im * k.im, a.re * k.im + a.im * k.re };
      spectrum[here] = product;
      spectrum[mirror] = { product.re, -product.im };
    }
  }
}

} // namespace

std::vector<double> DirectField(const std::vector<Point2>& pixelPoints,
  int gridWidth,
  int gridHeight,
  RadialBasis basis,
  double width)
{
  CheckGrid(gridWidth, gridHeight, width);
  std::vector<double> field(static_cast<std::size_t>(gridWidth) * gridHeight, 0.0);
  for (int j = 0; j < gridHeight; ++j)
  {
    for (int i = 0; i < gridWidth; ++i)
    {
      double sum = 0.0;
      for (const Point2& p : pixelPoints)
      {
        const double dx = i - p.x;
        const double dy = j - p.y;
        sum += RadialBasisValue(basis, width, dx * dx + dy * dy);
      }
      field[static_cast<std::size_t>(j) * gridWidth + i] = sum;
    }
  }
  return field;
}

std::vector<double> FastField(const std::vector<Point2>& pixelPoints,
  int gridWidth,
  int gridHeight,
  RadialBasis basis,
  double width)
{
  CheckGrid(gridWidth, gridHeight, width);
  CheckPointsInsideGrid(pixelPoints, gridWidth, gridHeight);
  // Linear (not cyclic) convolution needs every offset in [-(n-1), n-1] on each axis.
  const std::size_t paddedWidth = NextPowerOfTwo(2 * static_cast<std::size_t>(gridWidth) - 1);
  const std::size_t paddedHeight = NextPowerOfTwo(2 * static_cast<std::size_t>(gridHeight) - 1);
  std::vector<Complex> buffer;
  std::vector<Complex> scratch;
  FillPackedInput(
    buffer, paddedWidth, paddedHeight, pixelPoints, gridWidth, gridHeight, basis, width);
  Fft2DForwardTransposed(buffer, paddedHeight, paddedWidth, scratch);
  MultiplyUnpackedSpectra(buffer, paddedHeight, paddedWidth);
  Fft2DInverseFromTransposed(
    buffer, paddedHeight, paddedWidth, static_cast<std::size_t>(gridHeight), scratch);
  std::vector<double> field(static_cast<std::size_t>(gridWidth) * gridHeight);
  for (int j = 0; j < gridHeight; ++j)
  {
    for (int i = 0; i < gridWidth; ++i)
    {
      field[static_cast<std::size_t>(j) * gridWidth + i] =
        buffer[static_cast<std::size_t>(j) * paddedWidth + i].re;
    }
  }
  return field;
}

double FastFieldErrorBound(RadialBasis basis,
  double width,
  std::size_t pointCount,
  int gridWidth,
  int gridHeight)
{
  CheckGrid(gridWidth, gridHeight, width);
  const double secondDerivativeBound =
    basis == RadialBasis::Gaussian ? 1.0 / (width * width) : 1.0 / (width * width * width);
  const double basisMax = RadialBasisValue(basis, width, 0.0);
  const double padded =
    static_cast<double>(NextPowerOfTwo(2 * static_cast<std::size_t>(gridWidth) - 1)) *
    static_cast<double>(NextPowerOfTwo(2 * static_cast<std::size_t>(gridHeight) - 1));
  const double eps = std::numeric_limits<double>::epsilon();
  const double n = static_cast<double>(pointCount);
  const double spreading = n * secondDerivativeBound / 4.0;
  const double rounding =
    16.0 * eps * std::max(1.0, std::log2(padded)) * std::sqrt(padded) * n * basisMax;
  return spreading + rounding;
}

// In double: for the sizes it is asked about to refuse them (up to 2^31 pixels a side), the
// product of the padded sides overflows 64 bits (an image size of 2^31 - 1 was said to need 0 MiB).
double FastFieldMemoryBytes(int gridWidth, int gridHeight)
{
  const double padded =
    static_cast<double>(NextPowerOfTwo(2 * static_cast<std::size_t>(std::max(gridWidth, 1)) - 1)) *
    static_cast<double>(NextPowerOfTwo(2 * static_cast<std::size_t>(std::max(gridHeight, 1)) - 1));
  return 2.0 * padded * static_cast<double>(sizeof(Complex));
}

} // namespace tessera
