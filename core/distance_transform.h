#pragma once
// Exact Euclidean nearest-feature transform of a binary image: for every pixel, the index of a
// nearest feature pixel. Felzenszwalb and Huttenlocher's separable method (Theory of Computing,
// 2012): a scan of each column for the nearest feature row, then per row the lower envelope of
// parabolas (i - i')^2 + g(i'), each pass carrying the minimiser along. O(pixels).

#include <cstdint>
#include <vector>

namespace tessera
{

/// Nearest feature pixel index (j * width + i) of every pixel; -1 everywhere if there is no
/// feature. Ties are broken arbitrarily. Throws InputError if the mask size does not match.
std::vector<int> NearestFeatureTransform(const std::vector<std::uint8_t>& features,
  int width,
  int height);

} // namespace tessera
