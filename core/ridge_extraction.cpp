#include "ridge_extraction.h"

#include "errors.h"

#include <cmath>
#include <string>

namespace tessera
{

namespace
{

bool Inside(int i, int j, int width, int height)
{
  return i >= 0 && j >= 0 && i < width && j < height;
}

double At(const std::vector<double>& image, int width, int i, int j)
{
  return image[static_cast<std::size_t>(j) * width + i];
}

void CheckImage(const std::vector<double>& image, int width, int height)
{
  if (width < 1 || height < 1 ||
    image.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
  {
    throw InputError("image of " + std::to_string(image.size()) + " values does not match " +
      std::to_string(width) + " x " + std::to_string(height) + " pixels");
  }
  for (std::size_t k = 0; k < image.size(); ++k)
  {
    if (std::isnan(image[k]))
    {
      throw InputError("pixel " + std::to_string(k) + " of the image is NaN");
    }
  }
}

} // namespace

int GradientDirection(const std::vector<double>& image,
  int width,
  int height,
  int i,
  int j,
  int reach)
{
  const double centre = At(image, width, i, j);
  int best = -1;
  double bestChange = 0.0;
  for (int k = 0; k < 8; ++k)
  {
    const int ni = i + reach * NeighbourDx[k];
    const int nj = j + reach * NeighbourDy[k];
    if (!Inside(ni, nj, width, height))
    {
      continue;
    }
    // Diagonal neighbours are sqrt(2) pixels away: compare slopes, not raw differences.
    const double distance = reach * ((k % 2 == 1) ? std::sqrt(2.0) : 1.0);
    const double change = std::abs(At(image, width, ni, nj) - centre) / distance;
    if (change > bestChange)
    {
      bestChange = change;
      best = k;
    }
  }
  return best;
}

bool IsMaximumAlongAxis(const std::vector<double>& image,
  int width,
  int height,
  int i,
  int j,
  int axis)
{
  const int ai = i + NeighbourDx[axis];
  const int aj = j + NeighbourDy[axis];
  const int bi = i - NeighbourDx[axis];
  const int bj = j - NeighbourDy[axis];
  if (!Inside(ai, aj, width, height) || !Inside(bi, bj, width, height))
  {
    return false;
  }
  const double centre = At(image, width, i, j);
  return At(image, width, ai, aj) < centre && At(image, width, bi, bj) < centre;
}

RidgeMasks ExtractRidges(const std::vector<double>& image,
  int width,
  int height,
  double floor,
  int gradientReach)
{
  CheckImage(image, width, height);
  RidgeMasks masks;
  masks.Minor.assign(image.size(), 0);
  masks.Major.assign(image.size(), 0);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      if (!(At(image, width, i, j) > floor))
      {
        continue;
      }
      bool minor = false;
      for (int axis = 0; axis < 4 && !minor; ++axis)
      {
        minor = IsMaximumAlongAxis(image, width, height, i, j, axis);
      }
      if (!minor)
      {
        continue;
      }
      const std::size_t index = static_cast<std::size_t>(j) * width + i;
      masks.Minor[index] = 1;
      const int direction = GradientDirection(image, width, height, i, j, gradientReach);
      if (direction >= 0 && IsMaximumAlongAxis(image, width, height, i, j, direction % 4))
      {
        masks.Major[index] = 1;
      }
    }
  }
  return masks;
}

} // namespace tessera
