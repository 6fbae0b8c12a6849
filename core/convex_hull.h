#pragma once
// The convex hull of a set of points, by exact predicates, for a batch build's sample
// (two_region_build.cpp): a region there never inserts a point outside the hull of what is already
// built, so every point outside the sample's hull waited for the serial end. At 10^4 uniform points
// the sample of 312 left about 5% of the points outside its hull.
//
// Akl and Toussaint's filter first: the points strictly inside the octagon of the eight extreme
// points (lowest, highest, leftmost, rightmost and the four diagonal ones) are not hull vertices.
// For points spread over a square that is nearly all of them, for a disc some 90%. The others are
// sorted and joined by Andrew's monotone chain. Points in convex position all pass the filter; a
// cap on how many may pass bounds the cost where the hull would be most of the points.

#include "geometry.h"

#include <cstdint>
#include <vector>

namespace tessera
{

/// The positions k in [0, count) of the vertices of the convex hull of points[0 .. count),
/// anticlockwise from the lowest of the leftmost: strictly convex, so a point inside a hull edge
/// is not one, and of exact copies of a vertex one only. Empty when the hull has fewer than three
/// vertices (fewer than three distinct points, or all on one line) or when more than
/// `maxCandidates` points are not inside the extreme points' octagon.
std::vector<std::int32_t> ConvexHullPositions(const Point2* points,
  std::int32_t count,
  std::int32_t maxCandidates);

/// Moves the hull's vertices (ConvexHullPositions of all the points, with maxCandidates) to the
/// front, in the order they had, each swapped with the point it displaces, and ids with the points
/// (ids[k] belongs to points[k]; ids.size() == points.size()). Returns how many were moved: 0 when
/// there is no hull or it has more than maxHull vertices (then nothing moves).
std::int32_t MoveHullToFront(std::vector<Point2>& points,
  std::vector<std::int32_t>& ids,
  std::int32_t maxCandidates,
  std::int32_t maxHull);

} // namespace tessera
