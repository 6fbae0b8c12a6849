#pragma once
// The area of a polygon by the shoelace formula, summed with Neumaier's compensation and taken
// relative to its lowest vertex, so that terms far from the origin do not cancel
// catastrophically. Shared by every engine that reports tile areas, so that both engines give
// the same bits for the same polygon.

#include "geometry.h"

#include <cstddef>

namespace tessera
{

/// Signed area (positive for anticlockwise vertices) of the polygon v[0] .. v[n-1], summed from
/// its lowest vertex by (x, y): the same bits whichever vertex the polygon is listed from.
double CompensatedPolygonArea(const Point2* v, std::size_t n);

} // namespace tessera
