#pragma once
// Partition and node estimation (Goshtasby 2000, section 6): a point joins the ridge contour
// holding the pixel nearest to it; that pixel is its projection, and its node is the contour
// length from the start pixel to the projection divided by the contour length. An open contour
// starts at its first traced end pixel, a closed one at its first traced pixel.
//
// The nearest contour pixel comes from an exact nearest-feature transform of the contour pixels
// (linear in pixels), refined per point by comparing the true distances to the nearest
// features of the point's pixel and its eight neighbours (linear in points). This finds the
// nearest pixel centre except in near-ties, where the one chosen is at most a small fraction of
// a pixel farther.
//
// Addition to the paper: the major-ridge test stops a ridge contour a few pixels before the end
// of the points along it (the crest near a data end slopes along itself), and every point past
// the end would then share the end pixel's node, collapsing the end of the fitted curve onto
// their mean. A point whose nearest pixel is an end pixel of an open contour, or one of the last
// few pixels before it (over which the end tangent is measured: contours often hook at an end)
// lying behind the end pixel along that tangent (not where the contour turns back), and that lies
// beyond the end pixel along the end tangent, is projected on the end pixel and gets the arc
// length extended by that tangent distance; the nodes of the contour's points are then
// the extended arc lengths rescaled to [0, 1]. For contours whose ends are not passed the nodes
// are the paper's. Only points that continue the curve are extended: taken by distance beyond the
// end (along the end tangent), each at most maximumGap (pixels) further than the one before, the
// first than the end pixel. A point after a larger gap is an outlier and gets the node of the last
// continuation (the end pixel's if there is none); otherwise one far point would stretch the node
// range and squeeze every other node.
//
// Continuations are also taken from other contours. A contour often stops short of its points
// (above, or where the field of a nearby line pulls its crest down), and past its end the nearest
// pixel can be another contour's: with two parallel lines 5-7 basis widths apart, the points of
// one line past its contour's end went, as a dense chain, to the other line's contour and bent its
// curve. So a point far from every contour (more than maximumGap from its nearest pixel) that a
// chain reaches from an open contour's end joins that contour. A chain starts at a point of the
// contour continuing it past that end (a far point is more than maximumGap from the end pixel
// too), and steps at most maximumGap at a time over far points lying beyond the end (along the end
// tangent). Chains from all ends grow at once in order of their length (sum of steps), and a point
// joins the first to reach it. Points within maximumGap of their nearest contour are never taken:
// in a T, the line ending at another's middle does not take the other's points. Points beside a
// contour are not taken to its end either. A reached point is projected on the end pixel, its
// distance beyond the end being the largest along its chain (the nodes do not run back where a
// chain turns; a point that came back more than maximumGap gets that node as an outlier would).
// Far points no chain reaches keep their nearest contour.
//
//   A ==========E  . . . . . . .      dots: far from A's end (past its first maximumGap), nearer
//                                     to B's pixels below them, but each within maximumGap of the
//   B ============================    one before: they continue A, not B.

#include "geometry.h"
#include "ridge_contours.h"

#include <vector>

namespace tessera
{

struct PointPartition
{
  std::vector<int> GroupId;    ///< contour id per point, -1 when there is no contour
  std::vector<double> Node;    ///< in [0, 1] (closed contours: [0, 1)); 0 when unassigned
  std::vector<int> Projection; ///< position in RidgeContours::Pixels of the projection, or -1
  /// Whether the node of the point was extended past an end pixel (it then differs from the
  /// nodes of the other points with the same projection).
  std::vector<std::uint8_t> Extended;
  /// Whether the point is past an open contour's end and continues it (Extended, and not an
  /// outlier after a gap, which takes the node of the last continuation), and how far past the
  /// end it lies along the end tangent (pixels; for an outlier, the last continuation's).
  std::vector<std::uint8_t> Continues;
  std::vector<double> Beyond;
  /// Per contour, the node of the arc length 0 (start pixel) and the node length of one pixel.
  std::vector<double> NodeOrigin;
  std::vector<double> NodePerPixel;
  /// Per position in RidgeContours::Pixels: arc length (pixels) from its contour's start.
  std::vector<double> ArcLength;
};

/// Arc length from the start of its contour at every position of contours.Pixels.
std::vector<double> ContourArcLengths(const RidgeContours& contours, int width);

/// pixelPoints are in pixel units (pixel centres at integers) and must lie inside the image;
/// a point outside or with a NaN coordinate is an InputError naming its index.
PointPartition PartitionPoints(const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  int width,
  int height,
  double maximumGap);

/// The points (indices) whose node says nothing of their order: not continuing a contour past its
/// end (Continues), and more than maximumGap (pixels) from their projection pixel along the
/// contour's tangent there (over up to 3 pixels either side). A point's nearest pixel is within
/// half a pixel of it along the contour except past an end or beyond a bend, so these lie past an
/// end after a gap, or along a stretch where the ridge turns away from the points or stops; each
/// shares its pixel's node with the points there.
std::vector<std::size_t> PointsWithoutOrder(const std::vector<Point2>& pixelPoints,
  const RidgeContours& contours,
  const PointPartition& partition,
  int width,
  double maximumGap);

} // namespace tessera
