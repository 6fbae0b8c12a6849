#pragma once
// A compact radix-2 fast Fourier transform (iterative Cooley-Tukey with bit reversal) and a 2-D
// transform built from it. Written for the FFT convolution of the ridge-grouping field, where the
// padded grid sides are powers of two by construction.

#include <cstddef>
#include <vector>

namespace tessera
{

/// A complex number with plain arithmetic: std::complex multiplication goes through the
/// NaN-recovering library call unless fast-math is on, which the core never enables.
struct Complex
{
  double re = 0.0;
  double im = 0.0;
};

/// Precomputed twiddles and bit-reversal permutation for transforms of one power-of-two length.
class FftPlan
{
public:
  /// Throws InputError unless n is a power of two >= 1.
  explicit FftPlan(std::size_t n);

  std::size_t Size() const { return this->Length; }
  /// In-place forward transform X[k] = sum_j x[j] exp(-2 pi i j k / n) of data[0..n).
  void Forward(Complex* data) const { this->Transform(data, false); }
  /// In-place inverse transform without the 1/n factor (callers fold it into another step).
  void InverseUnscaled(Complex* data) const { this->Transform(data, true); }

private:
  void Transform(Complex* data, bool inverse) const;

  std::size_t Length = 0;
  std::vector<Complex> Twiddles;        // exp(-2 pi i k / n), k < n/2
  std::vector<std::size_t> BitReversed; // permutation partner of each index
};

/// True for 1, 2, 4, 8, ...
bool IsPowerOfTwo(std::size_t n);
/// Smallest power of two >= n (n >= 1).
std::size_t NextPowerOfTwo(std::size_t n);

/// 2-D transform of a rows x cols row-major array (both powers of two). The forward transform
/// leaves the spectrum transposed (cols x rows, spectrum[kx * rows + ky]) so that both passes
/// run over contiguous rows; InverseFromTransposed takes that layout back. `scratch` is resized
/// as needed and reused to avoid a second allocation per call.
void Fft2DForwardTransposed(std::vector<Complex>& data,
  std::size_t rows,
  std::size_t cols,
  std::vector<Complex>& scratch);
/// Inverse of Fft2DForwardTransposed including the 1/(rows*cols) factor. Only the first
/// `rowsNeeded` rows of the result are computed (the rest are left unspecified): a linear
/// convolution keeps only the unpadded part of the grid.
void Fft2DInverseFromTransposed(std::vector<Complex>& data,
  std::size_t rows,
  std::size_t cols,
  std::size_t rowsNeeded,
  std::vector<Complex>& scratch);

} // namespace tessera
