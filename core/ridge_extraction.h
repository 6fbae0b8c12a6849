#pragma once
// Minor and major ridges of a digital image (Goshtasby 2000, section 2).
//
// Minor ridge: a pixel brighter than both neighbours of at least one opposing pair
// (equations 2-5: horizontal, vertical and the two diagonals, strict inequalities).
// Gradient direction: the one of the eight neighbour directions with the largest intensity
// change per unit distance, |I(q) - I(p)| / |q - p| (figure 1a).
// Major ridge: a minor-ridge pixel that is a maximum along the axis of its own gradient
// direction, i.e. brighter than the two neighbours B and C with BC along the gradient.
//
// Measured on noisy circles and lines (1 pixel ~ 0.4 noise sigma): this rule marks no pixel
// far from the true curve, but only 15-40% of the crest pixels, because sampling noise makes a
// first-order change along the crest that often beats the second-order drop across it. The
// contour stage (ridge_contours.h) is built to live with sparse major pixels.
//
// A neighbour outside the image does not exist: an opposing pair with one outside is not tested.

#include <cstdint>
#include <limits>
#include <vector>

namespace tessera
{

struct RidgeMasks
{
  std::vector<std::uint8_t> Minor; ///< 1 on minor-ridge pixels
  std::vector<std::uint8_t> Major; ///< 1 on major-ridge pixels (a subset of Minor)
};

/// Offsets of the eight neighbour directions, in the order E, NE, N, NW, W, SW, S, SE.
constexpr int NeighbourDx[8] = { 1, 1, 0, -1, -1, -1, 0, 1 };
constexpr int NeighbourDy[8] = { 0, 1, 1, 1, 0, -1, -1, -1 };

/// Gradient direction 0..7 of pixel (i, j), or -1 where every compared pixel has the same
/// intensity. The change towards direction k is measured to the pixel `reach` steps away,
/// |I(p + reach d_k) - I(p)| / (reach |d_k|); reach 1 is the paper's neighbour rule (pixels
/// beyond the image are skipped).
int GradientDirection(const std::vector<double>& image,
  int width,
  int height,
  int i,
  int j,
  int reach = 1);

/// Whether (i, j) is brighter than both neighbours along `axis` (0..3); false if either is
/// outside the image.
bool IsMaximumAlongAxis(const std::vector<double>& image,
  int width,
  int height,
  int i,
  int j,
  int axis);

/// Minor and major ridge masks of a row-major width x height image. O(pixels).
/// Pixels whose value is not above `floor` are never ridges: a Gaussian field far from every
/// point is rounding noise of the FFT (~1e-16 of its maximum), whose random wiggles would
/// otherwise pass the strict-inequality tests and fill the empty parts of the image with ridges.
/// Throws InputError if the image size does not match or a value is NaN (naming the pixel).
RidgeMasks ExtractRidges(const std::vector<double>& image,
  int width,
  int height,
  double floor = -std::numeric_limits<double>::infinity(),
  int gradientReach = 1);

} // namespace tessera
