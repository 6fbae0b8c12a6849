#pragma once
// Brassel and Reif's procedure for Thiessen polygons (Geographical Analysis 11(3), 1979): an
// engine independent of Green and Sibson's, giving the same results (tiles.h types) for a
// rectangular window: the same contiguities, rejected and duplicate points, and tiles up to
// rounding where a tile edge crosses the window (such a corner may differ by an ulp, and an area
// by that ulp's share of it: 1e-15 relative for a tile of ordinary shape, 4e-12 measured for a
// sliver among 20k points on a slanted line, 4e-11 at coordinates of 1e6; each engine's tiles
// share their corners).
//
// The paper's procedure, as done here:
//  - The window is a rectangle (the paper's border). For the centroid being processed, four dummy
//    points are its reflections in the four sides (Fig. 2), so every bisector with a dummy is a
//    side and every centroid is "interior". Dummies never enter a predicate as rounded
//    coordinates: they are exact offsets from their centroid (predicates.h, Offset2).
//  - Centroids are sorted by x. The one nearest the lower-left corner V0 is processed first, from
//    V0 with the left dummy as its first known neighbour; the rest follow in x order (ties by y).
//    A centroid none of whose vertices is known yet starts from its nearest centroid, which always
//    shares a side with it (the midpoint of the two is nearer to them than to any other point).
//  - A polygon is completed by repeatedly finding the next clockwise neighbour of its centroid A
//    after a known neighbour X (Figs. 3, 4): the point P of the half-plane E1 clockwise of AX
//    whose circle (V, R) through A, X, P holds no other point of E1. Every candidate P' passes
//    the abscissa-range test against the current circle, the half-plane test (P' in E1) and the
//    in-circle test, and then replaces P, shrinking the circle. The range test uses a bounding
//    box of the circle widened by a rigorous bound on its rounding error, so it never rejects a
//    point the exact test would accept; the half-plane and circle tests are the exact
//    predicates. The paper starts from a dummy as the first potential neighbour; here the dummies
//    in E1 bound the range only once a search has gone two rounds of strips without a candidate,
//    or one with nothing left to visit (their circles are large unless A is near the border), and
//    are tested last, which changes the work, not the result.
//  - Candidates come from a bucket index over the x-sorted centroids: the sorted sequence cut
//    into about sqrt(N) strips of consecutive x (a run of equal x, a lattice column, is never
//    split), each sorted by y. The scan starts at A and moves outward in y within a strip and
//    outward strip by strip, as the paper's scan moves outward from X along the sorted sequence.
//    Until a first candidate is found it widens ring by ring over the neighbouring strips; then
//    it stops where the shrinking circle's abscissa range ends, and within each strip where the
//    circle's chord over that strip's abscissae ends (so a strip the circle only grazes costs a
//    binary search, not a scan); strips lying on a vertical or horizontal segment in the closed
//    far side of A -> X are skipped whole.
//  - Cost: near-linear for uniform and clustered points and for lattices (about 1 us per point at
//    1M points here, the Green-Sibson engine's order). Points exactly on one slanted line are
//    this method's bad case: the circles then graze the line, meet every strip, and the work
//    grows like N^1.5 to N^2 (64k points on a diagonal took 7.5 s, 20k on y = 0.3 x in a
//    window 4 wide 2 minutes). Points on one circle are another: every search circle is nearly
//    that circle and holds every point in its range (2k points on a circle take 2.7 s, 10k about
//    a minute). A transect with some scatter is fine (40k points within 1e-3 of a line: 0.07 s;
//    within 1e-7: 0.6 s, ten times the Green-Sibson engine). The same holds wherever long stretches
//    of points lie exactly on lines or circles (measured at 1e5 points, against the Green-Sibson
//    engine): 20 parallel slanted survey lines 15 s (over 50 times; jittered by 1e-9 some 15
//    times), one straight transect among 1000 scattered gauges some 30 times, 10 concentric rings
//    some 70 times. Long tiles cost time as well, as every search then meets every strip: points on
//    two horizontal lines 10 apart 2.6 s (8 times), on one line in a tall window 0.9 s. Any scale
//    works alike: the sweep runs on coordinates rescaled by a power of two to a unit-sized window
//    (chosen by the points inside it only: those rejected play no part), which changes no decision
//    and no rounding; and a search circle's bounding box is computed at unit size, so that a
//    cluster tiny beside its window (1e-80 wide in a window of 1) keeps its searches local.
//  - Neighbour records (Fig. 6): every vertex found is stored once and entered in the records of
//    all its (unprocessed) centroids, so a later polygon uses its known vertices and searches only
//    the missing ones; a record is dropped when its polygon is completed.
//  - Degenerate vertices (Fig. 5): points exactly on the circle are ties, all remembered with the
//    potential neighbour and then sorted round the circle (the neighbour recorded is the most
//    clockwise of them), so a vertex with k >= 4 co-circular centroids is found once, as one
//    vertex, with all its centroids. Its centroids
//    that are adjacent around the circle share edges; every other pair (the zero-length "neighbour"
//    the paper records and the pair it drops) is reported as half-neighbours (kind 1), as the
//    Green-Sibson engine does, when the vertex is inside the window.
//  - Every vertex is found once, so a tile never repeats one; but distinct vertices can round to
//    one point (circumcentres of nearly co-circular centroids, a side crossing within rounding of
//    a window corner). The tile's polygon lists that point once, as the Green-Sibson engine's
//    does: no two consecutive vertices (the last and the first included) are equal (at
//    coordinates above the subnormal range, 1e-307: below it a repeat was seen). Its
//    NeighborCount is the exact tile's (it can then exceed the vertex count), its area the listed
//    polygon's (0 for a tile rounded to a segment: on a lattice one ulp apart).
//  - Instrumentation (Fig. 11), per polygon, summed over its searches: A = points consulted
//    (fetched from the index within the ordinate range, and the dummies), B = points passing the
//    abscissa-range and half-plane tests, C = points inside or on the circle (each one replaced
//    the potential neighbour or tied with it). Searches = vertices the polygon had to find itself
//    (the others came from its neighbour record).
//
// Points: those not strictly inside the window are rejected, exact duplicates of an earlier
// point are reported with the id they copy (the smallest id is kept); both are listed, not used.

#include "tiles.h"
#include "window.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace tessera
{

/// The paper's Fig. 11 counts for one polygon, summed over its neighbour searches.
struct SweepSearchCounts
{
  std::uint32_t Consulted = 0;   ///< A: points subjected to the range and half-plane tests
  std::uint32_t PassedTests = 0; ///< B: points in the abscissa range and in half-plane E1
  std::uint32_t InCircle = 0;    ///< C: points inside or on the circle (V, R)
  std::uint32_t Searches = 0;    ///< next-clockwise-neighbour searches run for the polygon
};

struct ThiessenSweepResult
{
  /// One tile per accepted id, in ascending id order, as a TileSet (tiles.h). ComputeTiles gives
  /// the Green-Sibson engine's tiles in its spatial order, and each tile may start at another
  /// corner: compare the two by PointIds, each ring up to its first corner.
  TileSet Tiles;
  /// Per corner of Tiles.Vertices, the Thiessen vertex it is, numbered from 0 in the order the
  /// corners first come: tiles that meet at a vertex name it alike (a mesh, MeshOfNumberedCorners
  /// in tiles.h), and distinct vertices that a tile lists once, as they round to one point, are
  /// one.
  std::vector<std::int32_t> CornerVertexIds;
  /// As ComputeContiguityGraph's (each pair once, its kind), sorted by the pair's first id, where
  /// ComputeContiguityGraph's come in the engine's order: compare them as sets.
  ContiguityGraph Contiguities;
  std::vector<std::int32_t> RejectedIds;                         ///< ascending
  std::vector<std::pair<std::int32_t, std::int32_t>> Duplicates; ///< (duplicate, kept), ascending
  std::vector<SweepSearchCounts> Counts; ///< per tile, in the order of Tiles.PointIds
  std::size_t VertexCount = 0;           ///< Thiessen vertices stored (each once)
  std::size_t DegenerateVertexCount = 0; ///< vertices with 4 or more centroids and dummies
};

/// Throws InputError, naming the constraint, unless every side of the (axis-aligned, rectangular)
/// window lies at a double, exactly (x < 1/3, as 3x - 1 < 0, lies at none): the sweep's border is
/// the rectangle of the window's corners. ComputeThiessenSweep checks it; a caller that scales
/// the window first (ScaleIntoExactRange) checks it before, so that the message gives the side
/// as the user gave it.
void CheckSidesAreDoubles(const Window& window);

/// Why the window is no axis-aligned rectangle, for a message: the first of its effective
/// constraints whose side is slanted, by its name ("window constraint 2 gives a slanted side"),
/// or its number of sides; empty for an axis-aligned rectangle.
std::string WhyNotAnAxisAlignedRectangle(const Window& window);

/// Runs the procedure on all points (ids are their indices). Throws InputError if the window is
/// not an axis-aligned rectangle (WhyNotAnAxisAlignedRectangle) whose sides lie at doubles (x <
/// 1/3, as 3x - 1 < 0, lies at none: see CheckSidesAreDoubles), when its points reflected across
/// its sides would overflow (coordinates beyond some 4e307 that cannot be scaled down exactly), or
/// naming the first point with a NaN or infinite coordinate.
/// progress, if given, is called with the fraction of the points swept, every 64 points; when it
/// returns false the sweep stops and throws Cancelled (the sweep's bad cases, points along one
/// slanted line or circle, take a minute at 10^4 points: a viewer can offer to stop them).
ThiessenSweepResult ComputeThiessenSweep(const Window& window,
  const std::vector<Point2>& points,
  const std::function<bool(double)>& progress = nullptr);

} // namespace tessera
