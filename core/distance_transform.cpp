#include "distance_transform.h"

#include "errors.h"

#include <string>

namespace tessera
{

namespace
{

// For each pixel, the nearest feature row in its own column (-1 when the column has none).
std::vector<int> NearestRowInColumn(const std::vector<std::uint8_t>& features,
  int width,
  int height)
{
  std::vector<int> nearestRow(features.size(), -1);
  for (int i = 0; i < width; ++i)
  {
    int last = -1;
    for (int j = 0; j < height; ++j)
    {
      if (features[static_cast<std::size_t>(j) * width + i])
      {
        last = j;
      }
      nearestRow[static_cast<std::size_t>(j) * width + i] = last;
    }
    last = -1;
    for (int j = height - 1; j >= 0; --j)
    {
      const std::size_t p = static_cast<std::size_t>(j) * width + i;
      if (features[p])
      {
        last = j;
      }
      if (last >= 0 && (nearestRow[p] < 0 || last - j < j - nearestRow[p]))
      {
        nearestRow[p] = last;
      }
    }
  }
  return nearestRow;
}

// Lower envelope of the parabolas (x - column)^2 + height(column) over one row, for the columns
// that have a feature; writes the minimising feature pixel of every x.
class RowEnvelope
{
public:
  explicit RowEnvelope(int width)
    : Vertex(width)
    , Boundary(width + 1)
  {
  }

  void Solve(const std::vector<int>& nearestRow, int width, int j, std::vector<int>& nearest)
  {
    const std::size_t rowStart = static_cast<std::size_t>(j) * width;
    auto heightAt = [&](int column)
    {
      const double dy = nearestRow[rowStart + column] - j;
      return dy * dy;
    };
    int count = 0;
    for (int q = 0; q < width; ++q)
    {
      if (nearestRow[rowStart + q] < 0)
      {
        continue;
      }
      const double hq = heightAt(q);
      double s = 0.0;
      while (count > 0)
      {
        const int v = this->Vertex[count - 1];
        s = ((hq + double(q) * q) - (heightAt(v) + double(v) * v)) / (2.0 * (q - v));
        if (s > this->Boundary[count - 1])
        {
          break;
        }
        --count;
      }
      this->Vertex[count] = q;
      this->Boundary[count] = count == 0 ? -1e300 : s;
      ++count;
    }
    if (count == 0)
    {
      return;
    }
    int k = 0;
    for (int x = 0; x < width; ++x)
    {
      while (k + 1 < count && this->Boundary[k + 1] < x)
      {
        ++k;
      }
      const int column = this->Vertex[k];
      nearest[rowStart + x] = nearestRow[rowStart + column] * width + column;
    }
  }

private:
  std::vector<int> Vertex;
  std::vector<double> Boundary; // Boundary[k]: where parabola Vertex[k] starts to be lowest
};

} // namespace

std::vector<int> NearestFeatureTransform(const std::vector<std::uint8_t>& features,
  int width,
  int height)
{
  if (width < 1 || height < 1 ||
    features.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
  {
    throw InputError("feature mask of " + std::to_string(features.size()) +
      " pixels does not match " + std::to_string(width) + " x " + std::to_string(height));
  }
  const std::vector<int> nearestRow = NearestRowInColumn(features, width, height);
  std::vector<int> nearest(features.size(), -1);
  RowEnvelope envelope(width);
  for (int j = 0; j < height; ++j)
  {
    envelope.Solve(nearestRow, width, j, nearest);
  }
  return nearest;
}

} // namespace tessera
