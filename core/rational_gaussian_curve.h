#pragma once
// Rational Gaussian (RaG) curves (Goshtasby 1995), as used by Goshtasby 2000 section 6 to fit
// each point subset with the nodes found from its ridge contour:
//
//   P(u) = sum_i W_i G_i(u) V_i / sum_j W_j G_j(u),   G_i(u) = exp(-(u - u_i)^2 / (2 sigma^2))
//
// with the points as control points V_i at their nodes u_i and unit weights W_i = 1. The closed
// (periodic) form replaces G_i by sum over integers k of exp(-(u - u_i + k)^2 / (2 sigma^2)).
// sigma is the smoothness, in node units (the paper uses 0.01 to 0.08).
//
// Points sharing a node may be merged into their mean with weight equal to their number; the
// curve is identical, which lets a million points on a few thousand contour pixels be
// evaluated in O(pixels) per sample. Terms are normalised by the nearest node's Gaussian and
// those below exp(-32) of it are skipped, so the curve never becomes 0/0 far from all nodes.

#include "geometry.h"

#include <vector>

namespace tessera
{

/// Samples P(u) at sampleCount parameters: u = s / (sampleCount - 1) for an open curve
/// (both ends included), u = s / sampleCount for a closed one (the end is not repeated).
/// Throws InputError naming the bad value: sizes that differ, no control point, a node outside
/// [0, 1] or NaN, a non-positive or non-finite weight or sigma, sampleCount < 2, a NaN point.
std::vector<Point2> SampleRationalGaussianCurve(const std::vector<double>& nodes,
  const std::vector<Point2>& controls,
  const std::vector<double>& weights,
  double sigma,
  bool closed,
  int sampleCount);

} // namespace tessera
