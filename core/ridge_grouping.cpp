#include "ridge_grouping.h"

#include "distance_transform.h"
#include "errors.h"
#include "point_partition.h"
#include "rational_gaussian_curve.h"
#include "ridge_extraction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <string>

namespace tessera
{

namespace
{

// Measured on noisy circles and lines (1500 / 300 points, noise 2-3 pixels): crest pixels
// found major 40% / 13% with the paper's 1-step comparison, 56% / 26% with 3 steps, and no
// pixel more than 4 pixels from the true curve marked major in either case.
constexpr int GradientReach = 3;
constexpr int AutomaticCandidates[] = { 64, 96, 128, 192, 256, 384, 512, 768, 1024 };

void CheckPositive(double value, const char* name)
{
  if (!(value > 0.0) || !std::isfinite(value))
  {
    throw InputError(std::string(name) + " " + NumberText(value) + " is not a positive number");
  }
}

/// Every point finite (else an error naming the first that is not), and within +-1e306 (some
/// 2^1016): beyond, the pixel grid's origin and the curves' control points overflow, and the
/// errors met there name values the caller never gave. One pass; a NaN or infinity anywhere is
/// named before a point out of range.
void CheckPoints(const std::vector<Point2>& points)
{
  constexpr double Limit = 1e306;
  std::size_t beyond = points.size(); // the first point out of range, if any
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    if (!std::isfinite(points[k].x) || !std::isfinite(points[k].y))
    {
      throw InputError("point " + std::to_string(k) + " has a NaN or infinite coordinate");
    }
    if (beyond == points.size() &&
      (std::fabs(points[k].x) > Limit || std::fabs(points[k].y) > Limit))
    {
      beyond = k;
    }
  }
  if (beyond < points.size())
  {
    throw InputError("point " + std::to_string(beyond) + " (" + NumberText(points[beyond].x) +
      ", " + NumberText(points[beyond].y) +
      ") lies beyond +-1e306, the coordinates ridge grouping takes (its pixel grid and curves "
      "would overflow): scale the points");
  }
}

/// The grid reaches beyond the points by its margins, up to some 500 times their extent for the
/// widest basis in the smallest image that holds it: points within +-1e306 can still put its
/// origin or far corner beyond the doubles.
void CheckGridIsFinite(const PixelGrid& grid, double width)
{
  const double farX = grid.OriginX + (grid.Width - 1) * grid.Spacing;
  const double farY = grid.OriginY + (grid.Height - 1) * grid.Spacing;
  if (!std::isfinite(grid.OriginX) || !std::isfinite(grid.OriginY) || !std::isfinite(farX) ||
    !std::isfinite(farY) || !std::isfinite(grid.Spacing))
  {
    throw InputError("the pixel grid around the points, with the margins of a basis width of " +
      NumberText(width) + " pixels, reaches beyond the largest double: scale the points");
  }
}

/// Points that differ by a few subnormal doubles (an extent below some 1e-305) make a pixel too
/// small to be a double's step: the spacing underflows to zero or loses its precision, and the
/// grid's side became infinite, an allocation's "larger than max_size()" error.
void CheckSpacingIsNormal(double spacing, double extent)
{
  if (extent > 0.0 && !(spacing >= std::numeric_limits<double>::min()))
  {
    throw InputError("the points' extent " + NumberText(extent) +
      " is too small to be divided into pixels (a pixel would be below the smallest normal "
      "double): scale the points");
  }
}

Point2 ClampToGrid(Point2 q, const PixelGrid& grid)
{
  // Rounding in ToPixelUnits can put an extreme point a hair outside the last pixel centre.
  q.x = std::clamp(q.x, 0.0, grid.Width - 1.0);
  q.y = std::clamp(q.y, 0.0, grid.Height - 1.0);
  return q;
}

void AppendPixelPolyline(const RidgeContours& contours,
  int c,
  const PixelGrid& grid,
  Polylines& lines)
{
  for (int k = contours.Offsets[c]; k < contours.Offsets[c + 1]; ++k)
  {
    const int pixel = contours.Pixels[k];
    lines.Points.push_back(grid.PixelCentre(pixel % grid.Width, pixel / grid.Width));
  }
  lines.Offsets.push_back(static_cast<int>(lines.Points.size()));
}

/// The points FitCurves fits, gathered per contour pixel: per position in the contours' Pixels,
/// the sums of the coordinates of the points projected on it (scaled by 2^-XExponent in x and
/// 2^-YExponent in y) and their count; per contour, the points whose node was extended past one
/// of its ends.
struct PixelSums
{
  int XExponent = 0, YExponent = 0;
  std::vector<double> SumX, SumY, Count;
  std::vector<std::vector<std::size_t>> Extended;
};

// The points are summed scaled into (-1, 1) by a power of two for x and one for y (exact but where
// a coordinate falls below 2^-1022 of its axis's largest): 300 copies of a point at 9e305 summed
// to infinity, and the run failed on a "RaG control point" with an infinite coordinate.
PixelSums SumPointsByPixel(const std::vector<Point2>& points,
  const RidgeContours& contours,
  const PointPartition& partition)
{
  const std::size_t positions = contours.Pixels.size();
  PixelSums sums;
  sums.SumX.assign(positions, 0.0);
  sums.SumY.assign(positions, 0.0);
  sums.Count.assign(positions, 0.0);
  sums.Extended.resize(std::size_t(contours.Count()));
  double largestX = 0.0, largestY = 0.0;
  for (const Point2& p : points)
  {
    largestX = std::max(largestX, std::fabs(p.x));
    largestY = std::max(largestY, std::fabs(p.y));
  }
  sums.XExponent = ExponentAbove(largestX);
  sums.YExponent = ExponentAbove(largestY);
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const int position = partition.Projection[k];
    if (position < 0)
    {
      continue;
    }
    if (partition.Extended[k])
    {
      sums.Extended[std::size_t(partition.GroupId[k])].push_back(k);
      continue;
    }
    sums.SumX[std::size_t(position)] += std::ldexp(points[k].x, -sums.XExponent);
    sums.SumY[std::size_t(position)] += std::ldexp(points[k].y, -sums.YExponent);
    sums.Count[std::size_t(position)] += 1.0;
  }
  return sums;
}

/// What a RaG curve is fitted to: a node, a control point and a weight per member.
struct CurveMembers
{
  std::vector<double> Nodes;
  std::vector<Point2> Controls;
  std::vector<double> Weights;
};

/// Contour c's members: the mean of each of its pixels' points, weighted by their count, then
/// the points extended past its ends, one by one.
CurveMembers MembersOf(int c,
  const std::vector<Point2>& points,
  const RidgeContours& contours,
  const PointPartition& partition,
  const PixelSums& sums)
{
  CurveMembers members;
  for (int k = contours.Offsets[c]; k < contours.Offsets[c + 1]; ++k)
  {
    if (sums.Count[k] > 0.0)
    {
      members.Nodes.push_back(std::clamp(
        partition.NodeOrigin[c] + partition.ArcLength[k] * partition.NodePerPixel[c], 0.0, 1.0));
      members.Controls.push_back({ std::ldexp(sums.SumX[k] / sums.Count[k], sums.XExponent),
        std::ldexp(sums.SumY[k] / sums.Count[k], sums.YExponent) });
      members.Weights.push_back(sums.Count[k]);
    }
  }
  for (std::size_t k : sums.Extended[c])
  {
    members.Nodes.push_back(partition.Node[k]);
    members.Controls.push_back(points[k]);
    members.Weights.push_back(1.0);
  }
  return members;
}

/// Contour c's curve through its members, sampled CurveSamplesPerPixel times per pixel of the
/// contour (16 to 100,000 samples), appended to output 2.
void AppendCurve(int c,
  const CurveMembers& members,
  const RidgeContours& contours,
  const RidgeGroupingSettings& settings,
  RidgeGroupingResult& result)
{
  const double samples = std::ceil(settings.CurveSamplesPerPixel * contours.Lengths[c]);
  const int sampleCount = static_cast<int>(std::clamp(samples, 16.0, 100000.0));
  const std::vector<Point2> curve = SampleRationalGaussianCurve(members.Nodes,
    members.Controls,
    members.Weights,
    settings.CurveSigma,
    contours.Closed[c] != 0,
    sampleCount);
  result.Curves.Points.insert(result.Curves.Points.end(), curve.begin(), curve.end());
  result.Curves.Offsets.push_back(static_cast<int>(result.Curves.Points.size()));
  result.CurveGroupId.push_back(c);
  result.CurveClosed.push_back(contours.Closed[c]);
}

/// A warning naming the groups of a single point (none: no warning), which get no curve.
void NameSinglePointGroups(const std::vector<int>& single,
  const std::vector<Point2>& points,
  const RidgeContours& contours,
  const PointPartition& partition,
  RidgeGroupingResult& result)
{
  if (single.empty())
  {
    return;
  }
  // Each named with its point, which a caller can trace to its input (a file's line).
  std::vector<std::size_t> pointOf(std::size_t(contours.Count()), 0);
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    if (partition.Projection[k] >= 0)
    {
      pointOf[std::size_t(partition.GroupId[k])] = k;
    }
  }
  result.Warnings.push_back(std::to_string(single.size()) +
    " group(s) of a single point get no curve (a curve needs two points): group(s) " +
    ListNames(single.size(),
      [&](std::size_t k)
      {
        return std::to_string(single[k]) + " (point " +
          std::to_string(pointOf[std::size_t(single[k])]) + ")";
      }));
}

// One RaG curve per contour. Points sharing a projection pixel share a node, so they enter as
// their mean with their count as weight (the same curve, evaluated per pixel instead of per
// point); points whose node was extended past a contour end enter one by one (SumPointsByPixel
// tells how the means are summed without overflow).
void FitCurves(const std::vector<Point2>& points,
  const RidgeContours& contours,
  const PointPartition& partition,
  const RidgeGroupingSettings& settings,
  RidgeGroupingResult& result)
{
  const PixelSums sums = SumPointsByPixel(points, contours, partition);
  std::vector<int> single; // groups of one point: no curve to fit
  for (int c = 0; c < contours.Count(); ++c)
  {
    const CurveMembers curveMembers = MembersOf(c, points, contours, partition, sums);
    const double weightSum =
      std::accumulate(curveMembers.Weights.begin(), curveMembers.Weights.end(), 0.0);
    if (weightSum < 2.0)
    {
      if (weightSum > 0.0)
      {
        single.push_back(c);
      }
      continue;
    }
    AppendCurve(c, curveMembers, contours, settings, result);
  }
  NameSinglePointGroups(single, points, contours, partition, result);
}

/// A reach as warnings give it: "4 basis widths (12.04 in the points' units)", for a basis
/// `basisWidth` pixels wide.
std::string WidthsText(double widths, double basisWidth, const PixelGrid& grid)
{
  return NumberText(widths) + " basis widths (" + NumberText(widths * basisWidth * grid.Spacing) +
    " in the points' units)";
}

/// What the checks after the partition read: the points (pixel units), the contours, the
/// partition, the grid, and the basis width (pixels).
struct GroupedPoints
{
  const std::vector<Point2>& PixelPoints;
  const RidgeContours& Contours;
  const PointPartition& Partition;
  const PixelGrid& Grid;
  double Width;

  /// The centre of the grid's pixel of index `pixel` (pixel units).
  Point2 PixelPoint(int pixel) const
  {
    return { double(pixel % this->Grid.Width), double(pixel / this->Grid.Width) };
  }
  /// The centre of the contour pixel at `position` in Contours.Pixels (pixel units).
  Point2 ContourPoint(int position) const
  {
    return this->PixelPoint(this->Contours.Pixels[static_cast<std::size_t>(position)]);
  }
  /// The distance (pixels) from point k to the centre of pixel `pixel`.
  double DistanceToPixel(std::size_t k, int pixel) const
  {
    const Point2 centre = this->PixelPoint(pixel);
    return std::hypot(this->PixelPoints[k].x - centre.x, this->PixelPoints[k].y - centre.y);
  }
};

/// How far point k (with a projection pixel) lies off its contour, in pixels: from its projection
/// pixel; but a point past an open contour's end that continues it (its node extended along the
/// end tangent, each such point within two widths of the one before) lies beyond the end pixel by
/// design, and its curve goes there: only its distance off the end tangent's line counts. (Along
/// dense lines the contours stop some 10-20 widths short of the points' ends, and 1910 of 100,000
/// points on three roads were named as far, every one of them past an end.)
double OffContour(const GroupedPoints& grouped, std::size_t k)
{
  const PointPartition& partition = grouped.Partition;
  const double pixels = grouped.DistanceToPixel(
    k, grouped.Contours.Pixels[static_cast<std::size_t>(partition.Projection[k])]);
  return partition.Continues[k]
    ? std::sqrt(std::max(0.0, pixels * pixels - partition.Beyond[k] * partition.Beyond[k]))
    : pixels;
}

/// ContourDistance per point, and a warning naming the points beyond FarContourWidths basis
/// widths of their contour: the partition gives every point not continuing a contour past its end
/// to the nearest contour, so an outlier far from every ridge joins a group silently and pulls its
/// curve (a point 1e4 away from a circle of radius 100 put a spike of 468 into its curve).
/// Returns, per point, whether it is so named.
std::vector<std::uint8_t> MeasureContourDistances(const GroupedPoints& grouped,
  RidgeGroupingResult& result)
{
  const auto& [pixelPoints, contours, partition, grid, width] = grouped;
  result.ContourDistance.assign(pixelPoints.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<std::size_t> far;
  std::vector<std::uint8_t> named(pixelPoints.size(), 0);
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int position = partition.Projection[k];
    if (position < 0)
    {
      continue;
    }
    result.ContourDistance[k] =
      grouped.DistanceToPixel(k, contours.Pixels[static_cast<std::size_t>(position)]) *
      grid.Spacing;
    if (OffContour(grouped, k) > RidgeGrouping::FarContourWidths * width)
    {
      far.push_back(k);
      named[k] = 1;
    }
  }
  if (!far.empty())
  {
    result.Warnings.push_back(std::to_string(far.size()) + " point(s) lie more than " +
      WidthsText(RidgeGrouping::FarContourWidths, width, grid) +
      " from the contour they are grouped by, whose curve they pull: "
      "point(s) " +
      ListNames(far.size(), [&](std::size_t k) { return std::to_string(far[k]); }) +
      " (ContourDistance gives every point's distance)");
  }
  return named;
}

/// Contour pixels further than this many basis widths from every point are named
/// (NameContoursAwayFromPoints).
constexpr double EmptyStretchWidths = 3.0;

/// A warning naming the contours that no point is grouped by (no curve is fitted to them).
void NamePointlessContours(const GroupedPoints& grouped, RidgeGroupingResult& result)
{
  const RidgeContours& contours = grouped.Contours;
  std::vector<std::size_t> members(static_cast<std::size_t>(contours.Count()), 0);
  for (const int group : grouped.Partition.GroupId)
  {
    if (group >= 0 && group < contours.Count())
    {
      ++members[static_cast<std::size_t>(group)];
    }
  }
  std::vector<int> pointless;
  for (int c = 0; c < contours.Count(); ++c)
  {
    if (members[static_cast<std::size_t>(c)] == 0)
    {
      pointless.push_back(c);
    }
  }
  if (!pointless.empty())
  {
    result.Warnings.push_back(std::to_string(pointless.size()) +
      " ridge contour(s) have no point grouped by them (other contours are nearer every point), "
      "so no group and no curve: ContourId " +
      ListNames(pointless.size(), [&](std::size_t k) { return std::to_string(pointless[k]); }));
  }
}

/// Per grid pixel, the nearest pixel holding a point (the nearest-feature transform of the
/// points' pixels: distances to it are exact on the grid).
std::vector<int> NearestPointPixels(const GroupedPoints& grouped)
{
  const PixelGrid& grid = grouped.Grid;
  std::vector<std::uint8_t> occupied(grid.PixelCount(), 0);
  for (const Point2& p : grouped.PixelPoints)
  {
    occupied[grid.Index(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)))] =
      1;
  }
  return NearestFeatureTransform(occupied, grid.Width, grid.Height);
}

/// Contour c's pixels further than `reach` pixels from every point (nearest: NearestPointPixels)
/// as "contour c (n pixels, up to d from every point)", or "" when it has none.
std::string EmptyStretchOf(const GroupedPoints& grouped,
  int c,
  const std::vector<int>& nearest,
  double reach)
{
  const RidgeContours& contours = grouped.Contours;
  int away = 0;
  double farthest = 0.0;
  for (int k = contours.Offsets[c]; k < contours.Offsets[c + 1]; ++k)
  {
    const int pixel = contours.Pixels[static_cast<std::size_t>(k)];
    const Point2 at = grouped.PixelPoint(pixel);
    const Point2 to = grouped.PixelPoint(nearest[static_cast<std::size_t>(pixel)]);
    const double d = std::hypot(at.x - to.x, at.y - to.y);
    if (d > reach)
    {
      ++away;
      farthest = std::max(farthest, d);
    }
  }
  if (away == 0)
  {
    return {};
  }
  return "contour " + std::to_string(c) + " (" + std::to_string(away) + " pixels, up to " +
    NumberText(farthest * grouped.Grid.Spacing) + " from every point)";
}

/// Warnings naming the contours that no point is grouped by (NamePointlessContours), and the
/// contours that run more than EmptyStretchWidths basis widths from every point: the field of a
/// long-reaching basis has ridges across empty space, and such a contour's group can join points
/// of curves that lie far apart. With the default basis, a noisy line and a small ring 14 widths
/// above it made one ridge through the gap, the line cut in two, half of it grouped with the ring
/// and its curve drawn 24 units from every point, and nothing said so. Distances are to the
/// nearest pixel holding a point (exact on the grid: the nearest-feature transform).
void NameContoursAwayFromPoints(const GroupedPoints& grouped, RidgeGroupingResult& result)
{
  const RidgeContours& contours = grouped.Contours;
  const double width = grouped.Width;
  NamePointlessContours(grouped, result);
  if (contours.Count() == 0)
  {
    return;
  }
  const std::vector<int> nearest = NearestPointPixels(grouped);
  const double reach = EmptyStretchWidths * width;
  std::vector<std::string> stretches;
  for (int c = 0; c < contours.Count(); ++c)
  {
    std::string stretch = EmptyStretchOf(grouped, c, nearest, reach);
    if (!stretch.empty())
    {
      stretches.push_back(std::move(stretch));
    }
  }
  if (!stretches.empty())
  {
    result.Warnings.push_back(std::to_string(stretches.size()) +
      " ridge contour(s) run more than " + WidthsText(EmptyStretchWidths, width, grouped.Grid) +
      " from every point: the field's ridge crosses empty space there, so "
      "the group may join points of curves that lie apart, and its curve is drawn where there "
      "are no points (a smaller Width, or the Gaussian basis, may part them): " +
      ListNames(stretches.size(), [&](std::size_t k) { return stretches[k]; }));
  }
}

/// A warning naming the points without order (PointsWithoutOrder, maximumGap pixels being 2 basis
/// widths): each shares its projection pixel's node. On the Fiji epicentres at a width of 5, 247
/// of a trench's 793 points had one node, spread over 1775 km beyond a hooked end, and nothing
/// said so.
void NameUnorderedPoints(const std::vector<std::size_t>& tied,
  const PixelGrid& grid,
  double maximumGap,
  RidgeGroupingResult& result)
{
  if (!tied.empty())
  {
    result.Warnings.push_back(std::to_string(tied.size()) + " point(s) lie more than " +
      WidthsText(2.0, maximumGap / 2.0, grid) +
      " along their contour beyond the pixel they are projected on (past an "
      "end, or where the ridge turns away from the points): each shares that pixel's node, so "
      "their order along the curve is not known and the curve does not follow them (another "
      "Width, or the Gaussian basis, may give the ridge their stretch): point(s) " +
      ListNames(tied.size(), [&](std::size_t k) { return std::to_string(tied[k]); }));
  }
}

/// Below this many basis widths across, the bulk of the points is too small in the image for its
/// curves (NameStretchingPoints): a circle of 500 points 4 widths across was grouped, pulled by
/// the stray point, one 2 widths across was not; at 8 widths it came out whole.
constexpr double SqueezedBulkWidths = 6.0;

/// A warning naming the points that stretch the image far beyond the bulk of the points (whole:
/// the larger side of their bounding box). The image spans the points' bounding box at ImageSize
/// pixels (at most 1024 automatic), so one stray point 200 radii from a noisy circle of 500 shrank
/// the circle to 10 pixels, 2 basis widths across, and left every point ungrouped, with no word of
/// the stray point. The bulk is the box of the points without the most extreme 1% on each side of
/// each axis (at least 1 point, from 20 points on); named when it spans less than
/// SqueezedBulkWidths basis widths and less than a quarter of the image's larger side (the stray
/// points are what squeezes it), for each point further outside it than its own size and an eighth
/// of the image's. More stray points than that 1% make the bulk's box themselves, and are not
/// named.
///
///    +--------------------------------------+   the image: the points' bounding box
///    | +--+                                 |
///    | |##|  bulk (98% of the points)       * stray point: named
///    | +--+                                 |
///    +--------------------------------------+
void NameStretchingPoints(const std::vector<Point2>& points,
  double whole,
  const PixelGrid& grid,
  double width,
  RidgeGroupingResult& result)
{
  const std::size_t n = points.size();
  if (n < 20)
  {
    return;
  }
  const std::size_t trimmed = std::max<std::size_t>(1, n / 100);
  const auto bulkRange = [&](double Point2::*axis)
  {
    std::vector<double> values(n);
    std::transform(
      points.begin(), points.end(), values.begin(), [axis](const Point2& p) { return p.*axis; });
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(trimmed), values.end());
    const double low = values[trimmed];
    std::nth_element(values.begin(), values.end() - 1 - std::ptrdiff_t(trimmed), values.end());
    return std::make_pair(low, values[n - 1 - trimmed]);
  };
  const auto [xLow, xHigh] = bulkRange(&Point2::x);
  const auto [yLow, yHigh] = bulkRange(&Point2::y);
  const double bulk = std::max(xHigh - xLow, yHigh - yLow);
  const double pixels = bulk / grid.Spacing;
  // (a bulk of one place, copies of a point, is no curve: the identical points' own warnings)
  if (!(4.0 * bulk < whole) || !(pixels < SqueezedBulkWidths * width) || bulk == 0.0)
  {
    return;
  }
  std::vector<std::size_t> stretching;
  for (std::size_t k = 0; k < n; ++k)
  {
    const double dx = std::max({ xLow - points[k].x, points[k].x - xHigh, 0.0 });
    const double dy = std::max({ yLow - points[k].y, points[k].y - yHigh, 0.0 });
    if (std::hypot(dx, dy) > std::max(bulk, 0.125 * whole))
    {
      stretching.push_back(k);
    }
  }
  if (stretching.empty())
  {
    return;
  }
  result.Warnings.push_back(std::to_string(stretching.size()) +
    " point(s) lie far outside the box of the other points (without the " +
    std::to_string(trimmed) + " most extreme on each side: " + NumberText(bulk) +
    " across in the points' units, against the image's " + NumberText(whole) +
    "): the image spans them all, so the other points' box takes " +
    NumberText(std::round(10.0 * pixels) / 10.0) + " pixels across (" +
    NumberText(std::round(10.0 * pixels / width) / 10.0) +
    " basis widths), and their groups come out coarse, or not at all; group the stray points "
    "apart: point(s) " +
    ListNames(stretching.size(),
      [&](std::size_t k)
      {
        const Point2& p = points[stretching[k]];
        return std::to_string(stretching[k]) + " (" + NumberText(p.x) + ", " + NumberText(p.y) +
          ")";
      }));
}

/// Why the field gave no contour, at which step of TraceRidgeContours the ridges were lost: all
/// contours too short, or too short a loop; no crest (segments without a major-ridge pixel); or
/// no ridge at all. (It blamed the minimum length alone, and so misled at a minimum of 0: four
/// points on an arc left 12 major-ridge pixels and no contour.)
std::string NoContourWarning(const RidgeContours& contours,
  const RidgeContourSettings& settings,
  double basisWidth,
  const PixelGrid& grid)
{
  std::string why;
  if (contours.ShortContourCount > 0 || contours.ShortLoopCount > 0)
  {
    why = "the field's ridges made " +
      std::to_string(contours.ShortContourCount + contours.ShortLoopCount) + " contour(s), " +
      (contours.ShortContourCount > 0 ? std::to_string(contours.ShortContourCount) +
            " shorter than the minimum length (" + NumberText(settings.MinimumLength) + " pixels)"
                                      : std::string()) +
      (contours.ShortContourCount > 0 && contours.ShortLoopCount > 0 ? " and " : "") +
      (contours.ShortLoopCount > 0 ? std::to_string(contours.ShortLoopCount) +
            " closed, shorter than a circle of one basis width (" +
            NumberText(std::round(10.0 * settings.MinimumLoopLength) / 10.0) + " pixels)"
                                   : std::string());
  }
  else if (contours.SegmentCount > 0)
  {
    why = "the field's " + std::to_string(contours.SegmentCount) +
      " ridge segment(s) hold no crest (major-ridge pixel) that joins them into a contour";
  }
  else
  {
    why = "the field has no ridge line";
  }
  // A basis an eighth of the image wide or more makes broad hills: a larger one was advised
  // where a Width of 100 pixels in an image of 20 had left the field one hill.
  const bool wide = 8.0 * basisWidth >= std::max(grid.Width, grid.Height);
  return "no ridge contour: " + why +
    "; no point is grouped (too few points, or points further apart than the basis reaches: a "
    "larger Width may join them" +
    (wide ? "; or the basis is so wide against the image (Width " + NumberText(basisWidth) +
          " pixels, image " + std::to_string(grid.Width) + " x " + std::to_string(grid.Height) +
          ") that the field is a broad hill without ridges: a smaller Width, or a larger "
          "ImageSize, may give it ridges"
          : std::string()) +
    ")";
}

/// Open groups' ends within this many basis widths of another end are named (FindNearEnds).
constexpr double NearEndWidths = 4.0;

/// Curves closer than this many basis widths make one ridge of the field, one contour between
/// them (the README's advice on Width).
constexpr double MergedCurvesWidths = 2.0;

/// A contour that passes within this many basis widths of itself, where it is much further along
/// itself, is named as folded (NameFoldedContours).
constexpr double FoldWidths = 4.0;

/// A place given in pixel units, as messages give it: "(x, y)" in the points' units.
std::string PlaceText(const PixelGrid& grid, const Point2& at)
{
  const Point2 p = grid.FromPixelUnits(at);
  return "(" + NumberText(p.x) + ", " + NumberText(p.y) + ")";
}

/// An open contour's end: where its group's points end, and the way the contour runs out there.
struct ContourEnd
{
  int Contour;
  Point2 At;      // where the group's points end (pixel units)
  Point2 Outward; // from a pixel a width or so inside the contour towards its end pixel (the tip
                  // of an end that hooks back: EndTip)
};

/// Two contour ends within NearEndWidths basis widths of each other, Pixels apart.
struct NearEnds
{
  ContourEnd A, B;
  double Pixels;
};

/// Per contour, its points of the smallest and of the largest node (-1: none); of points with the
/// same node, the nearest to that end's pixel: an outlier past an end takes the node of the last
/// point continuing it (point_partition.h), and must not stand for where the points end (taken by
/// index, one stray point gave or hid the warning by its place in the input).
std::pair<std::vector<std::ptrdiff_t>, std::vector<std::ptrdiff_t>> EndPointsOfGroups(
  const GroupedPoints& grouped)
{
  const auto& [pixelPoints, contours, partition, grid, width] = grouped;
  std::vector<std::ptrdiff_t> lowest(std::size_t(contours.Count()), -1);
  std::vector<std::ptrdiff_t> highest(std::size_t(contours.Count()), -1);
  const auto endward = [&](std::size_t k, std::ptrdiff_t best, int end, double sign)
  {
    if (best < 0)
    {
      return true;
    }
    const std::size_t b = std::size_t(best);
    const double dk = sign * partition.Node[k], db = sign * partition.Node[b];
    const int pixel = contours.Pixels[std::size_t(end)];
    return dk > db ||
      (dk == db && grouped.DistanceToPixel(k, pixel) < grouped.DistanceToPixel(b, pixel));
  };
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int c = partition.GroupId[k];
    if (c < 0)
    {
      continue;
    }
    std::ptrdiff_t& low = lowest[std::size_t(c)];
    std::ptrdiff_t& high = highest[std::size_t(c)];
    low = endward(k, low, contours.Offsets[c], -1.0) ? std::ptrdiff_t(k) : low;
    high = endward(k, high, contours.Offsets[c + 1] - 1, 1.0) ? std::ptrdiff_t(k) : high;
  }
  return { std::move(lowest), std::move(highest) };
}

/// The position an open contour's end (end, its neighbour inside at end + inward) reaches out to:
/// of the end and the `reach` - 1 pixels before it, the one farthest from the pixel `reach` inside
/// (the nearest to the end of equals). A ridge's end can hook back over its last few pixels, and
/// its direction there then points back along the curve: two pieces of a noisy sine with a gap of
/// 1.9 widths between their points looked away from each other, and the gap was not named.
///
///    ===================.  tip          the way out is taken at the tip, not at the hook's end
///                  end '
int EndTip(const GroupedPoints& grouped, int end, int inward, int reach)
{
  const Point2 base = grouped.ContourPoint(end + inward * reach);
  const auto distance2 = [&](int position)
  {
    const Point2 p = grouped.ContourPoint(position);
    return (p.x - base.x) * (p.x - base.x) + (p.y - base.y) * (p.y - base.y);
  };
  int tip = end;
  for (int k = 1; k < reach; ++k)
  {
    const int position = end + inward * k;
    if (distance2(position) > distance2(tip))
    {
      tip = position;
    }
  }
  return tip;
}

/// The two ends of each open contour of two pixels or more, at its group's end points (the
/// contour's end pixel for a contour without points).
std::vector<ContourEnd> OpenContourEnds(const GroupedPoints& grouped)
{
  const auto& [pixelPoints, contours, partition, grid, width] = grouped;
  const auto [lowest, highest] = EndPointsOfGroups(grouped);
  std::vector<ContourEnd> ends;
  for (int c = 0; c < contours.Count(); ++c)
  {
    const int first = contours.Offsets[c], last = contours.Offsets[c + 1] - 1;
    if (contours.Closed[c] || last <= first)
    {
      continue;
    }
    const int back = std::min(last - first, std::max(2, static_cast<int>(std::lround(width))));
    for (const auto& [end, inward] : { std::make_pair(first, 1), std::make_pair(last, -1) })
    {
      const int tip = EndTip(grouped, end, inward, std::min(last - first, 2 * back));
      const int inner = std::clamp(tip + inward * back, first, last);
      const Point2 pixel = grouped.ContourPoint(tip), from = grouped.ContourPoint(inner);
      const std::ptrdiff_t point = (end == first ? lowest : highest)[std::size_t(c)];
      ends.push_back({ c,
        point < 0 ? grouped.ContourPoint(end) : pixelPoints[std::size_t(point)],
        { pixel.x - from.x, pixel.y - from.y } });
    }
  }
  return ends;
}

/// The pairs of ends FindNearEnds found to name, and per contour whether its own two ends lie
/// within reach and are no fold's.
struct EndPairs
{
  std::vector<NearEnds> Named;
  std::vector<std::uint8_t> NearlyClosed;
};

/// The pairs of open groups' ends to name (NameNearContourEnds): ends within NearEndWidths basis
/// widths of each other, one looking towards the other (the two ends of one long contour whichever
/// way they look, below; an end that hooks back looks out from its tip, EndTip). A group's end is
/// where its points end: its point of the smallest node for
/// the contour's first end, of the largest for its last (the contour's end pixel for a contour
/// without points). A contour stops some basis widths before the points along it
/// (point_partition.h), so its end pixels were 9.4 widths apart across a gap of 2.2 in a line's
/// points, and the line split silently. Where a curve's points lie further apart than the basis
/// reaches, its ridge breaks, and the curve comes out as pieces, or a closed one open, without a
/// word. Clean, dense points make it likely: most of them need pixels of their own, so the
/// automatic image is large and the basis narrow in the points' units (1000 points at random on a
/// circle, without noise, gave 4 open groups with the Gaussian basis at 512 pixels, their ends 1-3
/// widths apart). One of the ends must look towards the other, the gap within 45 degrees of its own
/// direction (not both: a short piece's end often hooks back): the ends of two lines side by side
/// (24 units apart, 3.8 widths), of crossing lines and of a spiral's neighbouring turns are near
/// each other too, but the gap runs across them, and a larger Width would merge those curves. A
/// long contour's own two ends within reach are named whichever way they look (a noisy circle came
/// out open, its ends 1.8 widths apart and hooked past each other, looking away from each other,
/// and nothing was said), except the ends of a fold: side by side, looking the same way, and
/// further apart than merged curves lie (NameFoldedContours names those). Also gives per contour
/// whether its own two ends lie within reach and are no fold's: a closed curve broken (named where
/// the contour is long), or a short contour whose ends are near by its shortness, both of which
/// NameFoldedContours leaves out.
///
///    piece A  ====>  . . gap . .  <====  piece B      named: an end looks at the other
///
///    line 1   ====>
///                 |  gap across                       not named
///    line 2   ====>
///
///    ----------->  end 1                              one contour's ends past each other:
///         end 2  <-----------                         named
///
///     .--------------->  end 1                        one contour's ends of a fold: not named
///    (                                                here
///     `--------------->  end 2
EndPairs FindNearEnds(const GroupedPoints& grouped, const std::vector<ContourEnd>& ends)
{
  const RidgeContours& contours = grouped.Contours;
  const double width = grouped.Width;
  const double reach = NearEndWidths * width;
  // Whether directions a and b lie within 45 degrees of each other.
  const auto within45 = [](const Point2& a, const Point2& b)
  { return a.x * b.x + a.y * b.y > std::sqrt(0.5) * std::hypot(a.x, a.y) * std::hypot(b.x, b.y); };
  // Whether the end looks towards the point `to`; whether two ends look the same way.
  const auto looksAt = [&](const ContourEnd& end, const Point2& to) {
    return within45({ to.x - end.At.x, to.y - end.At.y }, end.Outward);
  };
  const auto sameWay = [&](const ContourEnd& u, const ContourEnd& v)
  { return within45(u.Outward, v.Outward); };
  // Whether a contour is long enough to be a curve bent back on itself.
  const auto isLong = [&](int c) { return contours.Lengths[std::size_t(c)] >= 4.0 * reach; };
  EndPairs pairs{ {}, std::vector<std::uint8_t>(std::size_t(contours.Count()), 0) };
  std::vector<NearEnds>& near = pairs.Named;
  for (std::size_t a = 0; a < ends.size(); ++a)
  {
    for (std::size_t b = a + 1; b < ends.size(); ++b)
    {
      const ContourEnd& u = ends[a];
      const ContourEnd& v = ends[b];
      const double pixels = std::hypot(u.At.x - v.At.x, u.At.y - v.At.y);
      // One contour's own ends: only a contour long enough to be a curve bent back on itself
      // (a short one's ends are near by its shortness).
      const bool own = u.Contour == v.Contour;
      if (pixels > reach)
      {
        continue;
      }
      const bool looking = looksAt(u, v.At) || looksAt(v, u.At);
      // (a contour's own ends side by side and looking the same way, further apart than merged
      // curves lie, are the ends of a fold: NameFoldedContours)
      const bool folded = own && !looking && sameWay(u, v) && pixels > MergedCurvesWidths * width;
      // A short contour's own ends are near by its shortness, and not named; but it is no fold
      // either (a C of 10.7 widths, its ends 1.3 radians apart, was named as one).
      pairs.NearlyClosed[std::size_t(u.Contour)] |= own && !folded;
      if (looking ? !own || isLong(u.Contour) : own && !folded && isLong(u.Contour))
      {
        near.push_back({ u, v, pixels });
      }
    }
  }
  // One pair of ends per pair of contours (the nearest): a piece near another names it once.
  std::sort(near.begin(),
    near.end(),
    [](const NearEnds& x, const NearEnds& y) { return x.Pixels < y.Pixels; });
  std::set<std::pair<int, int>> named;
  near.erase(std::remove_if(near.begin(),
               near.end(),
               [&](const NearEnds& n) {
                 return !named.insert({ n.A.Contour, n.B.Contour }).second;
               }),
    near.end());
  return pairs;
}

/// A warning naming the pairs of ends FindNearEnds found (none: no warning).
void NameNearContourEnds(const GroupedPoints& grouped,
  const std::vector<NearEnds>& near,
  RidgeGroupingResult& result)
{
  if (near.empty())
  {
    return;
  }
  const PixelGrid& grid = grouped.Grid;
  const double width = grouped.Width;
  result.Warnings.push_back(std::to_string(near.size()) +
    " pair(s) of open contour ends (where their groups' points end) lie within " +
    WidthsText(NearEndWidths, width, grid) +
    " of each other, one looking towards the other (a group's own two ends "
    "whichever way they look): a curve may be broken "
    "there, where its points lie further apart than the basis reaches (a sparse stretch; or "
    "clean, dense points, which take a large automatic ImageSize, in whose pixels the basis is "
    "narrow), or where another curve's field close by bends its crest; a larger Width, or a "
    "smaller ImageSize, may join the pieces of the first kind: " +
    ListNames(near.size(),
      [&](std::size_t k)
      {
        const NearEnds& n = near[k];
        return (n.A.Contour == n.B.Contour ? "group " + std::to_string(n.A.Contour) + "'s two ends"
                                           : "groups " + std::to_string(n.A.Contour) + " and " +
                     std::to_string(n.B.Contour)) +
          ", " + NumberText(std::round(100.0 * n.Pixels / width) / 100.0) + " widths apart at " +
          PlaceText(grid, n.A.At) + " and " + PlaceText(grid, n.B.At);
      }));
}

/// A contour pixel as NameFoldedContours compares it with the others.
struct Station
{
  int Contour;
  double Arc; // pixels along the contour from its first pixel (the partition's ArcLength)
  Point2 At;
};

/// The stations of the contours NameFoldedContours looks at, and per contour its length when
/// closed (0: open, or left out).
struct ContourStations
{
  std::vector<Station> Stations;
  std::vector<double> LoopLength;
};

/// Every pixel of every contour but those nearlyClosed, as a station.
ContourStations StationsOf(const GroupedPoints& grouped,
  const std::vector<std::uint8_t>& nearlyClosed)
{
  const RidgeContours& contours = grouped.Contours;
  ContourStations stations;
  stations.LoopLength.assign(std::size_t(contours.Count()), 0.0); // 0: open
  for (int c = 0; c < contours.Count(); ++c)
  {
    if (nearlyClosed[std::size_t(c)])
    {
      continue; // (its ends may run past each other: named already)
    }
    for (int k = contours.Offsets[c]; k < contours.Offsets[c + 1]; ++k)
    {
      stations.Stations.push_back(
        { c, grouped.Partition.ArcLength[std::size_t(k)], grouped.ContourPoint(k) });
    }
    stations.LoopLength[std::size_t(c)] =
      contours.Closed[c] ? contours.Lengths[std::size_t(c)] : 0.0;
  }
  return stations;
}

/// Stations bucketed in square cells of Side pixels over the grid, Columns by Rows: the indices
/// of the stations in each cell, row by row (BucketStations).
struct StationCells
{
  double Side = 0.0;
  int Columns = 0, Rows = 0;
  std::vector<std::vector<std::size_t>> Cells;

  /// The column and row of the cell holding p (pixel units).
  std::pair<int, int> CellOf(const Point2& p) const
  {
    return std::make_pair(int(GridCell(p.x / this->Side, std::uint32_t(this->Columns))),
      int(GridCell(p.y / this->Side, std::uint32_t(this->Rows))));
  }
  std::size_t IndexOf(int i, int j) const
  {
    return std::size_t(j) * std::size_t(this->Columns) + std::size_t(i);
  }
  const std::vector<std::size_t>& Cell(int i, int j) const
  {
    return this->Cells[this->IndexOf(i, j)];
  }
};

StationCells BucketStations(const std::vector<Station>& stations,
  const PixelGrid& grid,
  double reach)
{
  // Stations bucketed in square cells of side at least reach: a pair within reach lies in
  // neighbouring cells. At least 4 pixels: a Width below one pixel (warned of, not refused) made
  // cells of a fraction of a pixel, and their empty lists took gigabytes.
  StationCells cells;
  cells.Side = std::max(reach, 4.0);
  cells.Columns = std::max(1, int(std::ceil(grid.Width / cells.Side)));
  cells.Rows = std::max(1, int(std::ceil(grid.Height / cells.Side)));
  cells.Cells.resize(std::size_t(cells.Columns) * std::size_t(cells.Rows));
  for (std::size_t k = 0; k < stations.size(); ++k)
  {
    const auto [i, j] = cells.CellOf(stations[k].At);
    cells.Cells[cells.IndexOf(i, j)].push_back(k);
  }
  return cells;
}

/// A contour's closest fold: stations A and B, Across pixels apart and Along pixels apart along
/// the contour (an infinite Across: none found).
struct Fold
{
  double Across = std::numeric_limits<double>::infinity(), Along = 0.0;
  Point2 A, B;
};

/// Takes stations u and v of one contour (of length loop when closed, else 0) as its fold when
/// they lie within reach across and much further apart along it, and closer than fold.
void ConsiderFold(const Station& u, const Station& v, double loop, double reach, Fold& fold)
{
  const double across = std::hypot(u.At.x - v.At.x, u.At.y - v.At.y);
  const double along = loop > 0.0
    ? std::min(std::abs(v.Arc - u.Arc), loop - std::abs(v.Arc - u.Arc))
    : std::abs(v.Arc - u.Arc);
  if (across <= reach && along >= 0.5 * Pi * across + reach && across < fold.Across)
  {
    fold = { across, along, u.At, v.At };
  }
}

/// Per contour, its closest fold among the pairs of its stations in neighbouring cells.
std::vector<Fold> ClosestFolds(const ContourStations& stations,
  const StationCells& cells,
  double reach,
  int contourCount)
{
  std::vector<Fold> folds(static_cast<std::size_t>(contourCount));
  for (std::size_t k = 0; k < stations.Stations.size(); ++k)
  {
    const Station& u = stations.Stations[k];
    const auto [i, j] = cells.CellOf(u.At);
    for (int nj = std::max(0, j - 1); nj <= std::min(cells.Rows - 1, j + 1); ++nj)
    {
      for (int ni = std::max(0, i - 1); ni <= std::min(cells.Columns - 1, i + 1); ++ni)
      {
        for (const std::size_t m : cells.Cell(ni, nj))
        {
          const Station& v = stations.Stations[m];
          if (m <= k || v.Contour != u.Contour)
          {
            continue;
          }
          ConsiderFold(u,
            v,
            stations.LoopLength[std::size_t(u.Contour)],
            reach,
            folds[std::size_t(u.Contour)]);
        }
      }
    }
  }
  return folds;
}

/// A warning naming the contours that pass within FoldWidths basis widths of themselves (d) where
/// they are much further along themselves (s, the shorter way round a closed contour): s at least
/// pi / 2 d + FoldWidths widths. Contours whose own ends FindNearEnds took for a closed
/// curve broken (its ends perhaps run past each other) are left out. Such a contour runs out along
/// one curve and back along another beside it, grouping the two as one: noisy lines 3.3 widths
/// apart came out as one group, along one line and back along the next, in 10 of 40 trials, and
/// nothing was said. A circle has s at most pi / 2 d; a hairpin needs arms of about 2 widths beyond
/// its turn to reach the margin, a V of 30 degrees arms of 3.4 (only Vs sharper than some 46
/// degrees are named); a loop much longer than wide (an ellipse of 100 by 8) is named too: to the
/// field its two sides are two curves side by side. The closest such pair per contour is named.
/// Pairs are found among the contour pixels in square cells at least as wide as the reach.
///
///    .-------------------->      d: across the fold (at most FoldWidths)
///   (         | d                s: along the contour, round the turn
///    `-------------------->
void NameFoldedContours(const GroupedPoints& grouped,
  const std::vector<std::uint8_t>& nearlyClosed,
  RidgeGroupingResult& result)
{
  const PixelGrid& grid = grouped.Grid;
  const double width = grouped.Width;
  const double reach = FoldWidths * width;
  const ContourStations stations = StationsOf(grouped, nearlyClosed);
  const StationCells cells = BucketStations(stations.Stations, grid, reach);
  const std::vector<Fold> folds = ClosestFolds(stations, cells, reach, grouped.Contours.Count());
  std::vector<int> named;
  for (int c = 0; c < grouped.Contours.Count(); ++c)
  {
    if (std::isfinite(folds[std::size_t(c)].Across))
    {
      named.push_back(c);
    }
  }
  if (named.empty())
  {
    return;
  }
  result.Warnings.push_back(std::to_string(named.size()) +
    " group(s) have a contour that passes within " + WidthsText(FoldWidths, width, grid) +
    " of itself where it is much further along itself: it may run out along "
    "one curve and back along another beside it, grouping the two as one (a smaller Width, or a "
    "larger ImageSize, may part them): " +
    ListNames(named.size(),
      [&](std::size_t k)
      {
        const Fold& fold = folds[std::size_t(named[k])];
        return "group " + std::to_string(named[k]) + ", " +
          NumberText(std::round(100.0 * fold.Across / width) / 100.0) + " widths across at " +
          PlaceText(grid, fold.A) + " and " + PlaceText(grid, fold.B) + ", " +
          NumberText(std::round(10.0 * fold.Along / width) / 10.0) + " widths apart along it";
      }));
}

/// The points in pixel units, each within the grid.
std::vector<Point2> PixelPointsOf(const std::vector<Point2>& points, const PixelGrid& grid)
{
  std::vector<Point2> pixelPoints(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    pixelPoints[k] = ClampToGrid(grid.ToPixelUnits(points[k]), grid);
  }
  return pixelPoints;
}

/// Steps 1-2: the field of the points (pixel units) on the grid, and its error bound.
void ComputeField(const std::vector<Point2>& pixelPoints,
  const PixelGrid& grid,
  const RidgeGroupingSettings& settings,
  RidgeGroupingResult& result)
{
  result.Field = FastField(pixelPoints, grid.Width, grid.Height, settings.Basis, settings.Width);
  result.FieldErrorBound = FastFieldErrorBound(
    settings.Basis, settings.Width, pixelPoints.size(), grid.Width, grid.Height);
}

/// Longest side strand dropped, in basis widths (see ContourSettingsFor): the holes that make side
/// strands are a pixel or a few across, and a chain of them gave 17 pixels at a width of 5.
constexpr double SideStrandWidths = 4.0;

/// Farthest a side strand lies from the contours kept, in pixels, at most (ContourSettingsFor):
/// the strands around the holes of noisy circles lay 1.4 to 3.2 pixels from the circle's contour,
/// while a separate segment 1.5 basis widths beside a line, with a ridge of its own, lay 4 pixels
/// from the line's at a width of 5 (a review's case, dropped at one width). Measured at a width
/// of 5 only: the holes may be wider under a wider basis.
constexpr double SideStrandPixels = 3.5;

/// How ridges become contours for these settings.
RidgeContourSettings ContourSettingsFor(const RidgeGroupingSettings& settings)
{
  RidgeContourSettings contourSettings;
  contourSettings.Join = settings.Join;
  contourSettings.MinimumLength = settings.MinimumContourLength;
  // Two basis widths: ridges closer than about that merge into one, so a saddle path between
  // two separate ridges is longer (with four widths, noisy lines 4.3 widths apart were joined
  // across into Z-shaped groups).
  contourSettings.MaximumBridgeLength = MergedCurvesWidths * settings.Width;
  // A ridge loop shorter than a circle of one basis width is no closed curve of the data: the
  // field merges such a loop of points into one peak. Such loops come from the field's shape
  // where a curve ends or bends (11-29 pixel loops at a basis width of 8 took a road's last 60
  // points into a closed group, and broke an ellipse's tips into small closed groups); dropped,
  // their points join the contours nearby.
  contourSettings.MinimumLoopLength = 2.0 * Pi * settings.Width;
  // A short contour within a few pixels of longer ones all along (and within one basis width:
  // curves that close make one ridge) is a second strand of their ridge around the band's holes
  // (ridge_contours.h, step 5). An 11-pixel one took 14 points of a noisy circle into a group of
  // their own beside it; the longest seen (of 10 such data sets, spirals, lines, circles) was 17
  // pixels.
  contourSettings.SideStrandDistance = std::min(settings.Width, SideStrandPixels);
  contourSettings.MaximumSideStrandLength = SideStrandWidths * settings.Width;
  return contourSettings;
}

/// Steps 3-6: the field's minor and major ridges (output 3) and the contours traced along them,
/// with a warning of why there is none when there is none.
RidgeContours TraceContours(const PixelGrid& grid,
  const RidgeGroupingSettings& settings,
  RidgeGroupingResult& result)
{
  // A millionth of the peak: a Gaussian basis is that small 5.3 widths from its point, so no
  // ridge supported by the data is lost, while FFT rounding noise (1e-16 relative) is excluded.
  const double peak = *std::max_element(result.Field.begin(), result.Field.end());
  RidgeMasks masks =
    ExtractRidges(result.Field, grid.Width, grid.Height, 1e-6 * peak, GradientReach);
  const RidgeContourSettings contourSettings = ContourSettingsFor(settings);
  RidgeContours contours = TraceRidgeContours(
    masks.Minor, masks.Major, grid.Width, grid.Height, contourSettings, &result.Field);
  result.MinorRidge = std::move(masks.Minor);
  result.MajorRidge = std::move(masks.Major);
  if (contours.Count() == 0)
  {
    result.Warnings.push_back(NoContourWarning(contours, contourSettings, settings.Width, grid));
  }
  return contours;
}

/// Points more than this many basis widths to one side of their contour count as beside it
/// (NamePointsBesideContours): a curve's own scatter lies within it (a noisy line's points, a
/// width or so across, stay within 2 widths), and curves closer than MergedCurvesWidths make one
/// ridge anyway.
constexpr double BesideWidths = MergedCurvesWidths;

/// How far point k lies to the left (positive) or right (negative) of its contour, in pixels;
/// nothing where the contour gives no direction (a contour of one pixel, a closed one of four or
/// fewer).
/// A point is measured from its projection pixel, its side taken by the contour's way there (from
/// the pixel two before to the pixel two after). A point past an open contour's end (projected
/// within two widths of it, and beyond it along the contour's last two widths) is measured off
/// that chord's line instead, as the curve continues along it: a line's points beyond its contour's
/// end lie along it, and a hook of the end's last pixels turned the local direction so that they
/// were taken for points beside it. (The far-points warning measures continuing points off the
/// partition's end tangent, OffContour.)
///
///     p . . . . end ============ inner     p: past the end, measured off the chord's line
std::optional<double> SignedOffContour(const GroupedPoints& grouped, std::size_t k)
{
  const RidgeContours& contours = grouped.Contours;
  const int c = grouped.Partition.GroupId[k];
  const int first = contours.Offsets[c], last = contours.Offsets[c + 1] - 1;
  const int at = grouped.Partition.Projection[k];
  const int count = last - first + 1;
  const Point2& p = grouped.PixelPoints[k];
  const auto offLine = [&](const Point2& from, const Point2& to, const Point2& through)
  {
    const double tx = to.x - from.x, ty = to.y - from.y;
    return (tx * (p.y - through.y) - ty * (p.x - through.x)) / std::hypot(tx, ty);
  };
  if (!contours.Closed[c])
  {
    const int back =
      std::min(last - first, std::max(2, static_cast<int>(std::lround(2.0 * grouped.Width))));
    // (each end's own half at most: a point beside one arm of a short U is not past the other end)
    const int zone = std::min(back, (last - first) / 2);
    for (const auto& [end, inner] :
      { std::make_pair(first, first + back), std::make_pair(last, last - back) })
    {
      const Point2 e = grouped.ContourPoint(end), in = grouped.ContourPoint(inner);
      const bool beyond = (p.x - e.x) * (e.x - in.x) + (p.y - e.y) * (e.y - in.y) > 0.0;
      if (std::abs(at - end) <= zone && beyond && !(e == in))
      {
        // (the contour's way: from its first pixel inwards, from inside to its last)
        return end == first ? offLine(e, in, e) : offLine(in, e, e);
      }
    }
  }
  const auto near = [&](int offset)
  {
    return grouped.ContourPoint(contours.Closed[c]
        ? first + ((at - first + offset) % count + count) % count
        : std::clamp(at + offset, first, last));
  };
  const Point2 from = near(-2), to = near(2);
  if ((contours.Closed[c] && count < 5) || from == to)
  {
    return std::nullopt; // (a closed contour of 3 pixels ran backwards from at - 2 to at + 2)
  }
  const Point2 pixel = grouped.ContourPoint(at);
  const double pixels = std::hypot(p.x - pixel.x, p.y - pixel.y);
  return offLine(from, to, pixel) < 0.0 ? -pixels : pixels;
}

/// Per group, its points and, of them, those more than BesideWidths from their contour
/// (SignedOffContour), but for those named as far (namedFar), on its left and on its right, with
/// their distances (pixels).
struct BesideCounts
{
  std::size_t Points = 0;
  std::vector<double> Left, Right;
};

std::vector<BesideCounts> CountPointsBeside(const GroupedPoints& grouped,
  const std::vector<std::uint8_t>& namedFar)
{
  const auto& [pixelPoints, contours, partition, grid, width] = grouped;
  std::vector<BesideCounts> counts(std::size_t(contours.Count()));
  for (std::size_t k = 0; k < pixelPoints.size(); ++k)
  {
    const int c = partition.GroupId[k];
    const int at = partition.Projection[k];
    if (c < 0 || at < 0)
    {
      continue;
    }
    BesideCounts& group = counts[std::size_t(c)];
    ++group.Points;
    // (points that MeasureContourDistances names as far are left to it: three clusters far apart
    // were named by both, one as 157 widths to the left of the other's contour)
    const std::optional<double> off = SignedOffContour(grouped, k);
    if (off && std::abs(*off) > BesideWidths * width && !namedFar[k])
    {
      (*off > 0.0 ? group.Left : group.Right).push_back(std::abs(*off));
    }
  }
  return counts;
}

/// A warning naming the groups with many points more than BesideWidths basis widths to one side of
/// their contour: at least 10 points, a tenth of the group, and four in five of its points that
/// far. That is a curve beside the contour that has no ridge of its own there: two noisy lines
/// 3.3 widths apart gave one contour that ran along one line and crossed to the other, the first
/// line's rest joining it from 3 widths away and its curve drawn through neither (in 7 of 20
/// runs, 5 of them without a word from NameFoldedContours, since the contour never came back).
/// Or a spread of points beside the ridge, as the Fiji epicentres' eastern cloud is. A noisy
/// curve's own scatter lies on both sides, within 2 widths.
///
///    . . . . . . . . . . .  (a second line: its own ridge stopped, or crossed over)
///                                  > 2 widths, all on one side
///    ======================  contour, along the first line
void NamePointsBesideContours(const GroupedPoints& grouped,
  const std::vector<std::uint8_t>& namedFar,
  RidgeGroupingResult& result)
{
  const std::vector<BesideCounts> counts = CountPointsBeside(grouped, namedFar);
  std::vector<std::string> named;
  for (std::size_t c = 0; c < counts.size(); ++c)
  {
    const BesideCounts& group = counts[c];
    const bool left = group.Left.size() >= group.Right.size();
    std::vector<double> side = left ? group.Left : group.Right;
    const std::size_t far = group.Left.size() + group.Right.size();
    if (side.size() < 10 || 10 * side.size() < group.Points || 5 * side.size() < 4 * far)
    {
      continue;
    }
    std::nth_element(side.begin(), side.begin() + std::ptrdiff_t(side.size() / 2), side.end());
    const double median = side[side.size() / 2] / grouped.Width;
    named.push_back("group " + std::to_string(c) + ", " + std::to_string(side.size()) + " of its " +
      std::to_string(group.Points) + " points, " + NumberText(std::round(10.0 * median) / 10.0) +
      " widths to its " + (left ? "left" : "right") + " (median)");
  }
  if (!named.empty())
  {
    result.Warnings.push_back(std::to_string(named.size()) +
      " group(s) hold many points more than " +
      WidthsText(BesideWidths, grouped.Width, grouped.Grid) +
      " to one side of their contour: another curve beside it without a ridge of its own there "
      "(its ridge may cross over to this one), or a spread of points that the ridge does not "
      "follow, is grouped with it, and the group's curve does not follow those points (a smaller "
      "Width, a larger ImageSize, or the Gaussian basis may part two curves; ContourDistance "
      "gives each point's distance): " +
      ListNames(named.size(), [&](std::size_t k) { return named[k]; }));
  }
}

/// Each point's distance to its contour, and the warnings on the groups: far points, points
/// without order, contour ends near each other, folded contours, points beside their contours,
/// contours away from the points.
void CheckGroups(const GroupedPoints& grouped, double maximumGap, RidgeGroupingResult& result)
{
  const std::vector<std::uint8_t> namedFar = MeasureContourDistances(grouped, result);
  NameUnorderedPoints(
    PointsWithoutOrder(
      grouped.PixelPoints, grouped.Contours, grouped.Partition, grouped.Grid.Width, maximumGap),
    grouped.Grid,
    maximumGap,
    result);
  const EndPairs endPairs = FindNearEnds(grouped, OpenContourEnds(grouped));
  NameNearContourEnds(grouped, endPairs.Named, result);
  NameFoldedContours(grouped, endPairs.NearlyClosed, result);
  NamePointsBesideContours(grouped, namedFar, result);
  NameContoursAwayFromPoints(grouped, result);
}

/// Output 1: the contours' pixel centres in input coordinates, whether closed, and lengths.
void OutputContours(const RidgeContours& contours,
  const PixelGrid& grid,
  RidgeGroupingResult& result)
{
  for (int c = 0; c < contours.Count(); ++c)
  {
    AppendPixelPolyline(contours, c, grid, result.Contours);
    result.ContourClosed.push_back(contours.Closed[c]);
    result.ContourLength.push_back(contours.Lengths[c] * grid.Spacing);
  }
}

/// Steps 7-8: the points grouped by the contours and ordered along them (output 0, with the
/// checks on the groups), the contours (output 1) and a curve per group (output 2).
void GroupAndFit(const std::vector<Point2>& points,
  const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  const PixelGrid& grid,
  const RidgeGroupingSettings& settings,
  RidgeGroupingResult& result)
{
  // Points past a contour end continue it while each is within two basis widths of the one
  // before: points further apart along a curve no longer make one ridge of the field.
  const double maximumGap = 2.0 * settings.Width;
  const PointPartition partition =
    PartitionPoints(pixelPoints, contours, grid.Width, grid.Height, maximumGap);
  result.GroupId = partition.GroupId;
  result.Node = partition.Node;
  const GroupedPoints grouped{ pixelPoints, contours, partition, grid, settings.Width };
  CheckGroups(grouped, maximumGap, result);
  OutputContours(contours, grid, result);
  FitCurves(points, contours, partition, settings, result);
}

} // namespace

RidgeGrouping::RidgeGrouping(const RidgeGroupingSettings& settings)
  : Settings(settings)
{
  CheckPositiveScale(settings.Width, "basis width");
  // The margins (MarginPixels: ceil(Width) + 2) on both sides of the largest image must leave
  // room inside it: 2 (ceil(Width) + 2) + 3 <= MaxImageSize.
  const double widest = double((MaxImageSize - 3) / 2 - 2);
  if (settings.Width > widest)
  {
    throw InputError("basis width " + NumberText(settings.Width) +
      " pixels leaves no room inside the largest image (" + std::to_string(MaxImageSize) +
      " pixels, margins of the width on both sides): at most " + NumberText(widest));
  }
  CheckPositiveScale(settings.CurveSigma, "curve sigma");
  if (settings.CurveSigma > MaxCurveSigma)
  {
    throw InputError("curve sigma " + NumberText(settings.CurveSigma) + " is above " +
      NumberText(MaxCurveSigma) +
      " (node units: a share of each curve's length): each point would pull on the whole curve, "
      "which shrinks towards the points' mean (a closed curve keeps exp(-2 pi^2 sigma^2) of its "
      "radius); the paper uses 0.01 to 0.08");
  }
  CheckPositive(settings.CurveSamplesPerPixel, "curve samples per pixel");
  if (!(settings.MinimumContourLength >= 0.0) || !std::isfinite(settings.MinimumContourLength))
  {
    throw InputError("minimum contour length " + NumberText(settings.MinimumContourLength) +
      " is not a finite non-negative number");
  }
  if (settings.ImageSize < 0)
  {
    throw InputError("image size " + std::to_string(settings.ImageSize) + " is negative");
  }
  if (settings.ImageSize > 0)
  {
    this->CheckImageSize(settings.ImageSize);
  }
}

int RidgeGrouping::MarginPixels() const
{
  return static_cast<int>(std::ceil(this->Settings.Width)) + 2;
}

void RidgeGrouping::CheckImageSize(int imageSize) const
{
  if (imageSize > MaxImageSize)
  {
    const double mebibytes = FastFieldMemoryBytes(imageSize, imageSize) / (1024.0 * 1024.0);
    throw InputError("image size " + std::to_string(imageSize) + " exceeds the limit of " +
      std::to_string(MaxImageSize) + " pixels: its FFT field would need " +
      std::to_string(static_cast<long long>(mebibytes)) + " MiB of memory");
  }
  const int smallest = 2 * this->MarginPixels() + 3;
  if (imageSize < smallest)
  {
    throw InputError("image size " + std::to_string(imageSize) + " is below " +
      std::to_string(smallest) + " pixels, the least that leaves room inside the margins of a " +
      "basis width of " + NumberText(this->Settings.Width) + " pixels");
  }
}

PixelGrid RidgeGrouping::MakeGrid(const std::vector<Point2>& points, int imageSize) const
{
  const Box2 box = BoundsOf(points.data(), points.size());
  const int margin = this->MarginPixels();
  PixelGrid grid;
  grid.Spacing = box.LargerSide() / static_cast<double>(imageSize - 1 - 2 * margin);
  CheckSpacingIsNormal(grid.Spacing, box.LargerSide());
  auto side = [&](double extent)
  {
    return std::min(imageSize, static_cast<int>(std::ceil(extent / grid.Spacing)) + 1 + 2 * margin);
  };
  grid.Width = side(box.XMax - box.XMin);
  grid.Height = side(box.YMax - box.YMin);
  // Centre the bounding box in the image.
  grid.OriginX = 0.5 * (box.XMin + box.XMax) - 0.5 * (grid.Width - 1) * grid.Spacing;
  grid.OriginY = 0.5 * (box.YMin + box.YMax) - 0.5 * (grid.Height - 1) * grid.Spacing;
  CheckGridIsFinite(grid, this->Settings.Width);
  return grid;
}

double RidgeGrouping::FractionInOwnPixel(const std::vector<Point2>& points, const PixelGrid& grid)
{
  std::vector<int> occupancy(grid.PixelCount(), 0);
  std::vector<std::size_t> pixelOf(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const Point2 q = ClampToGrid(grid.ToPixelUnits(points[k]), grid);
    pixelOf[k] = grid.Index(static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)));
    ++occupancy[pixelOf[k]];
  }
  std::size_t alone = 0;
  for (std::size_t pixel : pixelOf)
  {
    alone += occupancy[pixel] == 1 ? 1 : 0;
  }
  return points.empty() ? 0.0 : static_cast<double>(alone) / static_cast<double>(points.size());
}

std::vector<Point2> RidgeGrouping::DistinctPoints(const std::vector<Point2>& points)
{
  std::vector<Point2> distinct = points;
  std::sort(distinct.begin(), distinct.end(), ComesFirst);
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  return distinct;
}

// Copies of a point count once: they can never have pixels of their own, and counting them
// would push data with repeated measurements to the finest image, splitting a curve into dozens.
int RidgeGrouping::AutomaticImageSize(const std::vector<Point2>& points, bool& capped) const
{
  const int smallest = 2 * this->MarginPixels() + 3;
  const std::vector<Point2> distinct = DistinctPoints(points);
  capped = false;
  for (int candidate : AutomaticCandidates)
  {
    if (candidate < smallest)
    {
      continue;
    }
    if (FractionInOwnPixel(distinct, this->MakeGrid(points, candidate)) > 0.5)
    {
      return candidate;
    }
  }
  capped = true;
  return std::max(MaxAutomaticImageSize, smallest);
}

int RidgeGrouping::ChosenImageSize(const std::vector<Point2>& points, bool& capped) const
{
  capped = false;
  const int size = this->Settings.ImageSize == 0 ? this->AutomaticImageSize(points, capped)
                                                 : this->Settings.ImageSize;
  this->CheckImageSize(size);
  return size;
}

PixelGrid RidgeGrouping::ImageGridOf(const std::vector<Point2>& points) const
{
  CheckPoints(points);
  if (points.size() < 2 || BoundsOf(points.data(), points.size()).LargerSide() == 0.0)
  {
    return PixelGrid();
  }
  bool capped = false;
  return this->MakeGrid(points, this->ChosenImageSize(points, capped));
}

PixelGrid RidgeGrouping::ChooseImage(const std::vector<Point2>& points,
  double extent,
  RidgeGroupingResult& result) const
{
  result.ImageSizeAutomatic = this->Settings.ImageSize == 0;
  bool capped = false;
  result.ImageSize = this->ChosenImageSize(points, capped);
  if (capped)
  {
    // Above the largest automatic size no size was tried: the margins alone decided.
    result.Warnings.push_back(result.ImageSize > MaxAutomaticImageSize
        ? "automatic image size " + std::to_string(result.ImageSize) +
          " pixels, the least that holds the margins of a basis width of " +
          NumberText(this->Settings.Width) + " pixels (more than any automatic size)"
        : "automatic image size capped at " + std::to_string(result.ImageSize) +
          " pixels: fewer than half of the distinct points have a pixel of their own (points in "
          "one pixel share a node, with no order among them, which matters where they lie "
          "further apart than their noise; an ImageSize up to " +
          std::to_string(MaxImageSize) +
          " parts more of them, each doubling taking four times the memory and time)");
  }
  if (this->Settings.Width < 1.0)
  {
    // (At 0.2 pixels four of a noisy circle's points in five were named as unordered or far from
    // their contour; at 1e-20 the inverse multiquadric's peaks of 1/Width swamped the FFT's
    // field with their rounding, negative values of -3e4 in it.)
    result.Warnings.push_back("basis width " + NumberText(this->Settings.Width) +
      " pixels is below one pixel: the field is sampled more coarsely than its basis, so its "
      "ridges join little more than points in neighbouring pixels, and groups and orders mean "
      "little; give a Width of a pixel or more (the default is 5)");
  }
  const PixelGrid grid = this->MakeGrid(points, result.ImageSize);
  result.Grid = grid;
  result.PixelSize = grid.Spacing;
  NameStretchingPoints(points, extent, grid, this->Settings.Width, result);
  return grid;
}

namespace
{
/// The points at the x and y of an earlier point, each with the first point there, ascending by
/// point (RidgeGroupingResult::Duplicates), named in a warning: the filters name what they take
/// but treat specially (a trial's Python user got no word of them, where the example script said
/// them).
void NameDuplicatePoints(const std::vector<Point2>& points, RidgeGroupingResult& result)
{
  std::vector<std::int32_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  const auto at = [&](std::int32_t k) { return points[std::size_t(k)]; };
  std::stable_sort(order.begin(),
    order.end(),
    [&](std::int32_t a, std::int32_t b) { return ComesFirst(at(a), at(b)); });
  std::vector<std::pair<std::int32_t, std::int32_t>>& duplicates = result.Duplicates;
  for (std::size_t k = 1, first = 0; k < order.size(); ++k)
  {
    first = at(order[k]) == at(order[first]) ? first : k;
    if (first != k)
    {
      duplicates.emplace_back(order[k], order[first]);
    }
  }
  if (duplicates.empty())
  {
    return;
  }
  std::sort(duplicates.begin(), duplicates.end());
  result.Warnings.push_back(std::to_string(duplicates.size()) +
    " point(s) lie at the x and y of an earlier point, and are grouped as any other (the place "
    "weighs as often in the field, and they share a node); their ids are in the field data "
    "arrays DuplicatePointIds and DuplicateOfPointIds: " +
    DuplicatePairNames(duplicates));
}

// Run's progress at the start of its stages, from their times on 10^5 points of a noisy circle:
// the field took 79% and 74% of the run at 2048 and 1024 pixels, the contours 8% and 2%, the
// groups and curves 13% and 20%.
constexpr double FieldStart = 0.02;
constexpr double ContoursStart = 0.78;
constexpr double GroupsStart = 0.84;
} // namespace

RidgeGroupingResult RidgeGrouping::Run(const std::vector<Point2>& points,
  const std::function<bool(double)>& progress) const
{
  CheckPoints(points);
  RidgeGroupingResult result;
  NameDuplicatePoints(points, result);
  result.GroupId.assign(points.size(), -1);
  result.Node.assign(points.size(), 0.0);
  if (points.size() < 2)
  {
    result.Warnings.push_back("ridge grouping needs at least 2 points, got " +
      std::to_string(points.size()) +
      ": no group, contour or curve (the points are output 0, unassigned)");
    return result;
  }
  const double extent = BoundsOf(points.data(), points.size()).LargerSide();
  if (extent == 0.0)
  {
    std::fill(result.GroupId.begin(), result.GroupId.end(), 0);
    result.Warnings.push_back("all points are identical: one group, no ridge and no curve");
    return result;
  }
  const PixelGrid grid = this->ChooseImage(points, extent, result);
  const std::vector<Point2> pixelPoints = PixelPointsOf(points, grid);
  ReportOrStop(progress, FieldStart);
  ComputeField(pixelPoints, grid, this->Settings, result);
  ReportOrStop(progress, ContoursStart);
  const RidgeContours contours = TraceContours(grid, this->Settings, result);
  ReportOrStop(progress, GroupsStart);
  GroupAndFit(points, pixelPoints, contours, grid, this->Settings, result);
  if (progress)
  {
    progress(1.0); // (done: the answer no longer matters)
  }
  return result;
}

} // namespace tessera
