#include "point_partition.h"

#include "distance_transform.h"
#include "errors.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace tessera
{

namespace
{

void CheckPoint(const Point2& p, std::size_t index, int width, int height)
{
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
  {
    throw InputError("point " + std::to_string(index) + " has a NaN or infinite coordinate");
  }
  if (p.x < -0.5 || p.y < -0.5 || p.x > width - 0.5 || p.y > height - 0.5)
  {
    throw InputError("point " + std::to_string(index) + " lies outside the " +
      std::to_string(width) + " x " + std::to_string(height) + " image");
  }
}

double SquaredDistanceToPixel(const Point2& p, int pixel, int width)
{
  const double dx = p.x - pixel % width;
  const double dy = p.y - pixel / width;
  return dx * dx + dy * dy;
}

// The nearest contour pixel to p among the nearest features of p's pixel and its neighbours.
int NearestContourPixel(const Point2& p, const std::vector<int>& nearest, int width, int height)
{
  const int ci = std::clamp(static_cast<int>(std::lround(p.x)), 0, width - 1);
  const int cj = std::clamp(static_cast<int>(std::lround(p.y)), 0, height - 1);
  int best = -1;
  double bestDistance = 0.0;
  for (int dj = -1; dj <= 1; ++dj)
  {
    for (int di = -1; di <= 1; ++di)
    {
      const int i = ci + di;
      const int j = cj + dj;
      if (i < 0 || j < 0 || i >= width || j >= height)
      {
        continue;
      }
      const int candidate = nearest[static_cast<std::size_t>(j) * width + i];
      const double distance = SquaredDistanceToPixel(p, candidate, width);
      if (best < 0 || distance < bestDistance)
      {
        best = candidate;
        bestDistance = distance;
      }
    }
  }
  return best;
}

// How far p lies beyond pixel `at` in the direction from pixel `from` to pixel `to` (pixel
// indices of an image `width` wide); 0 where from and to are one pixel.
double DistanceAlong(const Point2& p, int at, int from, int to, int width)
{
  const double tx = to % width - from % width;
  const double ty = to / width - from / width;
  const double norm = std::hypot(tx, ty);
  return norm > 0.0 ? ((p.x - at % width) * tx + (p.y - at / width) * ty) / norm : 0.0;
}

// How far p lies past the end pixel `position` of an open contour, along the contour's direction
// at that end (0 if it is not an end pixel, the contour is closed, or p is not past it).
double DistanceBeyondEnd(const Point2& p,
  const RidgeContours& contours,
  int contour,
  int position,
  int width)
{
  const int first = contours.Offsets[contour];
  const int last = contours.Offsets[contour + 1] - 1;
  if (contours.Closed[contour] || last == first || (position != first && position != last))
  {
    return 0.0;
  }
  // Tangent over up to 5 pixels: one pixel step only gives the 8 chain-code directions.
  const int reach = std::min(5, last - first);
  const int inner = contours.Pixels[position == first ? first + reach : last - reach];
  const int end = contours.Pixels[position];
  return std::max(0.0, DistanceAlong(p, end, inner, end, width));
}

// The points past one contour end, in order of their distance beyond it (along the end tangent),
// continue the curve while each lies at most maximumGap further than the one before (the first:
// than the end pixel). From the first gap on they are taken as outliers: each gets the distance of
// the last continuation (0: the end pixel's node, the paper's), so that one far point cannot
// stretch the node range and squeeze the nodes of every other point of the contour.
//
//   contour   continuations    gap > maximumGap     outlier
//   ======E   . . .. . .  ----------------------->    x      (x gets the node of the last dot)
void KeepContinuationsOnly(std::vector<double>& beyond,
  const std::vector<int>& projection,
  double maximumGap,
  std::vector<std::uint8_t>& continues)
{
  std::vector<std::size_t> past; // the points past an end, by end pixel, then distance
  for (std::size_t k = 0; k < beyond.size(); ++k)
  {
    if (beyond[k] > 0.0)
    {
      past.push_back(k);
    }
  }
  std::sort(past.begin(),
    past.end(),
    [&](std::size_t a, std::size_t b) {
      return projection[a] != projection[b] ? projection[a] < projection[b] : beyond[a] < beyond[b];
    });
  double last = 0.0; // distance of the last continuation past the current end
  bool outliers = false;
  for (std::size_t m = 0; m < past.size(); ++m)
  {
    const std::size_t k = past[m];
    if (m == 0 || projection[k] != projection[past[m - 1]])
    {
      last = 0.0;
      outliers = false;
    }
    outliers = outliers || beyond[k] - last > maximumGap;
    if (outliers)
    {
      beyond[k] = last;
    }
    else
    {
      last = beyond[k];
      continues[k] = 1;
    }
  }
}

/// The pixels up to 3 before and after position along contour c (wrapping round a closed
/// contour, stopping at an open one's ends), between which its tangent there is taken.
std::pair<int, int> TangentPixels(const RidgeContours& contours, int c, int position)
{
  const int first = contours.Offsets[c], count = contours.Offsets[c + 1] - first;
  const int reach = std::min(3, count / 2);
  const auto at = [&](int offset)
  {
    const int k = position - first + offset;
    return contours.Pixels[std::size_t(
      first + (contours.Closed[c] ? ((k % count) + count) % count : std::clamp(k, 0, count - 1)))];
  };
  return { at(-reach), at(reach) };
}

} // namespace

std::vector<double> ContourArcLengths(const RidgeContours& contours, int width)
{
  std::vector<double> arc(contours.Pixels.size(), 0.0);
  for (int c = 0; c < contours.Count(); ++c)
  {
    for (int k = contours.Offsets[c] + 1; k < contours.Offsets[c + 1]; ++k)
    {
      arc[k] = arc[k - 1] + StepLength(contours.Pixels[k - 1], contours.Pixels[k], width);
    }
  }
  return arc;
}

PointPartition PartitionPoints(const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  int width,
  int height,
  double maximumGap)
{
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    CheckPoint(pixelPoints[k], k, width, height);
  }
  PointPartition result;
  result.GroupId.assign(pixelPoints.size(), -1);
  result.Node.assign(pixelPoints.size(), 0.0);
  result.Projection.assign(pixelPoints.size(), -1);
  result.ArcLength = ContourArcLengths(contours, width);
  if (contours.Count() == 0)
  {
    return result;
  }
  // Where contours share a junction pixel the later contour owns it; either is equally near.
  const std::size_t pixelCount = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<std::uint8_t> isContour(pixelCount, 0);
  std::vector<int> positionOf(pixelCount, -1);
  std::vector<int> contourOfPosition(contours.Pixels.size(), -1);
  for (int c = 0; c < contours.Count(); ++c)
  {
    for (int k = contours.Offsets[c]; k < contours.Offsets[c + 1]; ++k)
    {
      isContour[contours.Pixels[k]] = 1;
      positionOf[contours.Pixels[k]] = k;
      contourOfPosition[k] = c;
    }
  }
  const std::vector<int> nearest = NearestFeatureTransform(isContour, width, height);
  result.Extended.assign(pixelPoints.size(), 0);
  result.Continues.assign(pixelPoints.size(), 0);
  std::vector<double>& beyond = result.Beyond;
  beyond.assign(pixelPoints.size(), 0.0);
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int pixel = NearestContourPixel(pixelPoints[k], nearest, width, height);
    const int position = positionOf[pixel];
    const int contour = contourOfPosition[position];
    result.GroupId[k] = contour;
    result.Projection[k] = position;
    beyond[k] = DistanceBeyondEnd(pixelPoints[k], contours, contour, position, width);
  }
  KeepContinuationsOnly(beyond, result.Projection, maximumGap, result.Continues);
  std::vector<double> extendedArc(pixelPoints.size(), 0.0);
  std::vector<double> lowest(contours.Count(), 0.0);
  std::vector<double> highest(contours.Lengths.begin(), contours.Lengths.end());
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int position = result.Projection[k];
    const int contour = result.GroupId[k];
    extendedArc[k] = result.ArcLength[position];
    if (beyond[k] > 0.0)
    {
      result.Extended[k] = 1;
      extendedArc[k] += position == contours.Offsets[contour] ? -beyond[k] : beyond[k];
      lowest[contour] = std::min(lowest[contour], extendedArc[k]);
      highest[contour] = std::max(highest[contour], extendedArc[k]);
    }
  }
  result.NodeOrigin.resize(contours.Count());
  result.NodePerPixel.resize(contours.Count());
  for (int c = 0; c < contours.Count(); ++c)
  {
    const double span = highest[c] - lowest[c];
    result.NodePerPixel[c] = span > 0.0 ? 1.0 / span : 0.0;
    result.NodeOrigin[c] = -lowest[c] * result.NodePerPixel[c];
  }
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int c = result.GroupId[k];
    result.Node[k] =
      std::clamp(result.NodeOrigin[c] + extendedArc[k] * result.NodePerPixel[c], 0.0, 1.0);
  }
  return result;
}

std::vector<std::size_t> PointsWithoutOrder(const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  const PointPartition& partition,
  int width,
  double maximumGap)
{
  std::vector<std::size_t> tied;
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int position = partition.Projection[k];
    if (position < 0 || partition.Continues[k])
    {
      continue;
    }
    const auto [before, after] = TangentPixels(contours, partition.GroupId[k], position);
    const int pixel = contours.Pixels[std::size_t(position)];
    if (std::fabs(DistanceAlong(pixelPoints[k], pixel, before, after, width)) > maximumGap)
    {
      tied.push_back(k);
    }
  }
  return tied;
}

} // namespace tessera
