#pragma once
// A convex ring inside another: how a polygon with a hole shows among rings read one a cell.
// vtkGDALVectorReader gives a polygon's rings as closed polylines, its outline and each hole a
// cell of its own; taken each as a convex tile, a hole becomes a tile over the outline's, and the
// clipped areas count it twice without a word (a 4 x 4 square with a 2 x 2 hole gave 16 + 4).
//
//     +-----------+     outer ring A (convex), ring B inside it: (A, B) is found;
//     |   +---+   |     B touching A at points, or sharing a stretch of A, still counts;
//     |   | B |   |     two copies of one ring do not (neither is smaller)
//     |   +---+   |
//     +-----------+

#include "geometry.h"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace tessera
{

/// The first ring inside another, as (outer, inner): ring B = vertices[offsets[B],
/// offsets[B + 1]) lies inside convex ring A when every vertex of B is inside A or on its boundary
/// (exact orientation tests, either orientation of A), and B is not A again: a vertex of B is
/// strictly inside A, or B encloses less area than A beyond rounding. Rings of
/// fewer than 3 vertices, of zero area or with a coordinate that is not finite are passed over;
/// A is taken as convex (its tests are the half-planes of its edges). Rings are indexed on a grid
/// of their boxes: near-linear for rings that tile the plane. Offsets as ValidateRings takes them.
std::optional<std::pair<std::size_t, std::size_t>> FindRingInsideAnother(
  const std::vector<std::size_t>& offsets,
  const std::vector<Point2>& vertices);

} // namespace tessera
