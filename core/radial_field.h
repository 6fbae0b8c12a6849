#pragma once
// The field surface of Goshtasby (2000), equation 8: g(x, y) = sum_i basis(|(x, y) - p_i|),
// digitised at pixel centres. Everything here is in pixel units (pixel centres at integer
// coordinates), because the paper gives basis widths in pixels.
//
// FastField evaluates g by a zero-padded linear FFT convolution of the points, spread onto the
// pixel grid by bilinear weights, with the basis sampled over the whole padded domain (the
// inverse multiquadric has infinite support, so no truncation radius is used).
//
// Error bound (FastFieldErrorBound). Spreading replaces basis(|c - p|) by the bilinear
// interpolant of basis(|c - q|) over the four pixel centres q around p. For f in C^2 and unit
// spacing, |f - bilinear(f)| <= (max|f_xx| + max|f_yy|) / 8. The second derivatives of the
// bases are bounded everywhere by 1/r^3 (inverse multiquadric [d^2 + r^2]^(-1/2)) and 1/s^2
// (Gaussian exp(-d^2 / 2 s^2)), so each point contributes at most 1/(4 r^3), resp. 1/(4 s^2).
// The FFT adds a rounding term of at most 16 eps log2(P) sqrt(P) N max(basis) for a padded
// grid of P pixels (a conservative form of the O(eps log P) accuracy of Cooley-Tukey).

#include "geometry.h"

#include <cstddef>
#include <vector>

namespace tessera
{

enum class RadialBasis
{
  InverseMultiquadric, ///< [d^2 + r^2]^(-1/2), equation 7, r = width
  Gaussian             ///< exp(-d^2 / (2 s^2)), section 7, s = width
};

/// basis(d) for a squared distance d^2 in pixels^2.
double RadialBasisValue(RadialBasis basis, double width, double squaredDistance);

/// g at every pixel centre of a width x height grid by direct summation, O(points x pixels):
/// the reference the fast field is tested against. Returns row-major values (x fastest).
std::vector<double> DirectField(const std::vector<Point2>& pixelPoints,
  int gridWidth,
  int gridHeight,
  RadialBasis basis,
  double width);

/// g at every pixel centre by FFT convolution, O(P log P) for the padded grid of
/// P = NextPowerOfTwo(2 W - 1) x NextPowerOfTwo(2 H - 1) pixels, plus O(points).
/// Points must lie in [0, W-1] x [0, H-1]; an outside or non-finite point is an InputError
/// naming its index.
std::vector<double> FastField(const std::vector<Point2>& pixelPoints,
  int gridWidth,
  int gridHeight,
  RadialBasis basis,
  double width);

/// Upper bound of |FastField - DirectField| at any pixel (see the header comment).
double FastFieldErrorBound(RadialBasis basis,
  double width,
  std::size_t pointCount,
  int gridWidth,
  int gridHeight);

/// Bytes FastField allocates for its padded buffers (two complex arrays of P entries), so a
/// caller can refuse an image size before allocating anything; a double, which cannot overflow.
double FastFieldMemoryBytes(int gridWidth, int gridHeight);

} // namespace tessera
