#pragma once
// A catchment (a polygon with holes, even-odd over its rings) and the clipping of convex tiles by
// it: the area of tile & catchment and that intersection as rings.
//
// How a tile is clipped. Each ring is oriented so that the catchment lies on its left (outer
// boundaries anticlockwise, holes clockwise, islands in holes anticlockwise); then the catchment's
// indicator is the sum of the rings' winding numbers, and area(tile & catchment) is the sum over
// rings of the signed area of the ring clipped by the tile (Sutherland-Hodgman against each tile
// edge keeps winding numbers inside the tile, even for a non-convex ring). The clipping polygon is
// the convex hull of the tile's vertices: Sutherland-Hodgman intersects the edges' half-planes,
// which is the tile only when every turn is strictly convex, and rounded tiles have collinear,
// repeated and ulp-apart vertices; the line through two vertices an ulp apart points anywhere. Only
// the ring segments near the tile are visited: a uniform grid over the segments gives those whose
// cells meet the tile's bounding box B. Each run of the other segments lies outside B and is
// replaced by a path around B's boundary; that changes the ring's winding number inside B by a
// whole number of turns, found exactly by counting signed crossings of a horizontal ray from B's
// centre with the whole ring (the grid's row) and with the replaced ring, and repaid with whole
// loops around B. Rings with no segment near the tile contribute a constant over B: the tile
// itself, or nothing. A tile that holds the catchment's whole bounding box (exactly) gives the
// catchment itself, its rings and area, without clipping.
//
// Which segments are near, and every winding number, are decided exactly (orient2d) on the input
// coordinates. The clipping runs on coordinates relative to the tile's first vertex (its
// inside/outside decisions exact there too): rounded intersection points then err by ulps of the
// tile's size, not of the coordinates' magnitude, and areas are compensated sums of products made
// exact by fma. An area errs by about (piece perimeter) * ulp(tile size): near 1e-16 relative for
// pieces that are not slivers, whatever the offset of the coordinates. A piece whose area is
// within that rounding's bound (16 eps * its perimeter * the magnitude of the shifted coordinates
// it is made of; see RoundingAreaBound in clip.cpp) counts as empty: no area and no ring, so that
// a tile wholly outside the catchment gives nothing rather than a degenerate ring of area 1e-19.
// So does a tile whose pieces sum to no more than the sum of their bounds (a tile inside a hole:
// the tile from the outer ring and its reversal from the hole's ring, which cancel).
//
// Areas alone (ClipInto without rings, ClipAll without them) are measured another way where a
// tile's box spans 64 grid cells or more: from where the catchment's boundary crosses the tile's,
// the pieces between crossings summed from prefix sums along the rings (crossing_area.cpp). That
// costs the segments near the tile's boundary, not those inside it; a tile on a detailed outline
// (3e5 vertices) a step cost a seventeenth as much. Its error has the clipping's source and
// size: crossing points rounded by ulps of the tile's size, so some 1e-16 of a fat tile's area
// and eps * length^2 for a sliver (1e-7 of a tile 1e-9 as thick as long, on both ways). It hands
// the tile to the clipping wherever exactness needs it: a catchment vertex on the tile's
// boundary, a segment through a tile vertex, a result within 1e-9 of the tile of empty or whole
// (and beyond the limits crossing_area.cpp lists: 64 rings, 64 hull vertices, coarse sums).
//
// Cost: construction O(n log n) for validation plus the grid (about 2 cells per segment); a tile
// costs O(its vertices x nearby segments) plus a walk along one grid row; measured by crossings,
// O(its vertices x the segments in the cells along its boundary) plus the same walk and the rings.
// A tile whose box misses the catchment's box, or meets only cells that no segment crosses, costs
// O(its vertices + cells). A Catchment is immutable after construction: concurrent clipping from
// several threads is safe with one Workspace per thread.

#include "compensated_sum.h"
#include "errors.h" // InputError, which the functions below throw
#include "geometry.h"
#include "polygon_validation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace tessera
{

/// An unevaluated sum Hi + Lo with |Lo| <= ulp(Hi) / 2: some 106 bits (internal to the
/// catchment's prefix sums).
struct DoubleDouble
{
  double Hi = 0.0;
  double Lo = 0.0;
};

/// Polygons as flat rings: ring r has vertices RingOffsets[r] .. RingOffsets[r+1]-1.
struct ClippedRings
{
  std::vector<std::size_t> RingOffsets{ 0 };
  std::vector<Point2> Vertices;
};

/// One tile clipped by the catchment.
///
/// The rings describe tile & catchment both ways: by the even-odd rule over the rings, and as the
/// sum of the rings' signed areas (each is oriented with the region on its left, so pieces of
/// outer boundaries run anticlockwise and pieces of holes clockwise). Sutherland-Hodgman may leave
/// zero-width bridges: a ring that runs along a tile edge and back, joining two lobes, and pieces
/// of different rings may share stretches of the tile's boundary. Such bridges enclose no area and
/// cancel in any sum of signed areas (planar or ellipsoidal), but they are not split apart.
struct ClippedTile
{
  double Area = 0.0;
  ClippedRings Rings;
};

/// Many tiles clipped by one catchment.
struct ClippedTiles
{
  /// Area of tile t & catchment.
  std::vector<double> Areas;
  /// Rings of tile t are rings TileRingOffsets[t] .. TileRingOffsets[t+1]-1 of Rings (no rings, and
  /// all offsets 0, when the rings were not asked for).
  std::vector<std::size_t> TileRingOffsets;
  ClippedRings Rings;
  double CatchmentArea = 0.0;
};

class Catchment
{
public:
  /// Rings as flat arrays: ring r is vertices[ringOffsets[r]] .. vertices[ringOffsets[r+1]-1]
  /// (ringOffsets starts at 0 and ends at vertices.size()). Orientation and nesting of the rings
  /// do not matter: a point is in the catchment when it is inside an odd number of rings. Rings may
  /// repeat their first vertex at the end. Throws InputError (naming ring, vertex and segment
  /// indices) for a NaN or infinite vertex, a ring with fewer than 3 distinct vertices, a ring
  /// that touches or crosses itself, two rings that cross, or two that run along each other all
  /// the way round (a ring given twice). Rings may touch at points (a hole touching the outer
  /// boundary at a vertex, as OGC allows) and share stretches of boundary (adjacent parts, a lake
  /// on the outline).
  Catchment(const std::vector<std::size_t>& ringOffsets, const std::vector<Point2>& vertices);

  std::size_t RingCount() const { return this->Offsets.size() - 1; }
  /// The rings as stored: repeated consecutive vertices dropped, and each ring oriented with the
  /// catchment on its left (outer boundaries anticlockwise, holes clockwise). Ring r here is ring r
  /// of the constructor's input.
  const std::vector<std::size_t>& RingOffsets() const { return this->Offsets; }
  const std::vector<Point2>& Vertices() const { return this->Points; }
  /// Number of other rings that enclose ring r (even: an outer boundary, odd: a hole).
  const std::vector<int>& RingDepths() const { return this->Depths; }
  /// The other rings that enclose ring r, ascending (RingDepths()[r] of them).
  std::vector<std::int32_t> EnclosingRings(std::size_t r) const;
  /// Whether ring r was reversed to orient it as above.
  const std::vector<bool>& RingReversed() const { return this->Reversed; }

  double Area() const { return this->TotalArea; }
  /// The rings' areas summed without their signs (each ring's whole area): Area() is this less
  /// twice the holes'.
  double RingAreaSum() const { return this->RingAreas; }
  /// Whether the rings cancel out under the even-odd rule, leaving no area (a basin given with
  /// all its sub-basins: each is a hole in it). Rounding of projected vertices leaves slivers of
  /// some 1e-16 of the rings' areas: below 1e-9 of them counts as none.
  bool RingsCancelOut() const
  {
    return this->RingCount() > 0 && !(std::abs(this->TotalArea) > 1e-9 * this->RingAreas);
  }
  /// "its N rings cancel out, as a point inside an even number of them is outside it (...)", for
  /// the callers' errors when RingsCancelOut.
  std::string RingsCancelOutText() const;
  const Box2& Bounds() const { return this->Box; }

  /// Even-odd membership, exact for points off the boundary (boundary points get either answer).
  bool Contains(const Point2& p) const;

  /// Whether a tile that clips to no area still lies (partly) in the catchment: a sliver thinner
  /// than rounding, or collinear corners. Its vertex mean inside, or the catchment's boundary
  /// entering it, a vertex strictly inside or a segment through its interior (a catchment some
  /// 10^-14 of the tile's size, partly in it, whose piece measures below the clip's rounding); or,
  /// for corners all on one line (exactly), any corner or
  /// edge midpoint inside, since the mean of a flat tile half in the catchment can lie outside.
  /// (Boundary points get either answer, as in Contains.)
  bool HoldsPartOf(const Point2* tile, std::size_t count) const;

  /// Area of tile & catchment. The tile is a convex polygon with anticlockwise vertices; it is
  /// clipped as the convex hull of its vertices, so repeated and collinear vertices, and the small
  /// non-convexity of rounding (vertices an ulp apart, folds), change the area by ulps. Throws
  /// InputError for fewer than 3 vertices, a NaN or infinite vertex, clockwise vertices, or (a
  /// NotConvexError) a tile that is not convex (its area differing from its convex hull's by more
  /// than a millionth, beyond the rounding of double coordinates; see ClipInto for others); a
  /// tile of zero area
  /// gives 0.
  double ClipArea(const std::vector<Point2>& tile) const;
  /// Area and rings of tile & catchment (see ClippedTile).
  ClippedTile Clip(const std::vector<Point2>& tile) const;
  /// All tiles at once: tile t is tileVertices[tileOffsets[t]] .. [tileOffsets[t+1]-1]. Errors name
  /// the tile. With withRings false only the areas are computed.
  ClippedTiles ClipAll(const std::vector<std::size_t>& tileOffsets,
    const std::vector<Point2>& tileVertices,
    bool withRings = true) const;

  /// Where the catchment's boundary crosses a tile's (crossing_area.cpp): on segment Segment
  /// (from vertex Segment), at At (relative to the tile hull's first vertex), on hull edge Edge
  /// at Along (0 to 1 from its start); Entry when the segment passes into the tile there; Order
  /// 0 or 1 among the segment's crossings (an entry first).
  struct Crossing
  {
    std::uint32_t Segment = 0;
    std::uint32_t Edge = 0;
    double Along = 0.0;
    Point2 At;
    bool Entry = false;
    unsigned char Order = 0;
  };
  /// Scratch buffers: reusing one between calls avoids allocating per tile.
  struct Workspace
  {
    std::vector<std::uint32_t> Candidates;
    std::vector<std::uint32_t> SortScratch;
    std::vector<std::pair<std::uint32_t, int>> Crossings;
    std::vector<Point2> Local;
    std::vector<Point2> Tile;
    std::vector<Point2> ClipA;
    std::vector<Point2> ClipB;
    std::vector<Point2> Rotated;
    std::vector<Point2> Hull;
    std::vector<Crossing> BoundaryCrossings;
    std::vector<std::uint32_t> AlongBoundary;
    std::vector<char> RingCrossed;
    std::vector<std::uint32_t> SegmentStamp;
    std::uint32_t Stamp = 0;
    /// Tiles whose area came from their crossings (AreaByCrossings), not from clipping.
    std::size_t AreasByCrossings = 0;
  };
  /// What a tile with fewer than 3 vertices or clockwise vertices is.
  enum class FoldedTile
  {
    IsAnError, ///< an InputError naming it (tiles given by a user; a non-convex tile is one too)
    IsEmpty,   ///< area 0: tiles derived from a tessellation, where a tile thinner than the
               ///< rounding of its vertices (between points nanometres apart) can come out folded
               ///< or collapsed, its true area being below the rounding's
  };
  /// The same as ClipArea / Clip for tile vertices tile[0] .. tile[count-1]; rings are appended to
  /// *rings when it is not null. tileId only names the tile in error messages. With
  /// FoldedTile::IsAnError the tile must also be convex up to the rounding of its coordinates,
  /// whose relative precision is coordinateEpsilon: the machine epsilon of the type they were
  /// computed in (2^-23 for tiles that went through float, as VTK points often do).
  double ClipInto(const Point2* tile,
    std::size_t count,
    std::size_t tileId,
    Workspace& work,
    ClippedRings* rings,
    FoldedTile folded = FoldedTile::IsAnError,
    double coordinateEpsilon = std::numeric_limits<double>::epsilon()) const;

private:
  // Whether cell (i, j) is the first cell of segment v's that lies in the box of cells from
  // (x0, y0) on: a walk over the box's cells meets each segment there once.
  bool FirstListedAt(std::uint32_t v,
    std::size_t i,
    std::size_t j,
    std::size_t x0,
    std::size_t y0) const
  {
    const std::uint32_t first = this->FirstCell[v];
    return std::max<std::size_t>(first >> 16, x0) == i &&
      std::max<std::size_t>(first & 0xffff, y0) == j;
  }
  // Whether the catchment's boundary enters the convex tile: a vertex strictly inside it, or a
  // segment through its interior (found by the grid).
  bool BoundaryEntersTile(const Point2* tile, std::size_t count) const;
  void BuildGrid();
  void FindDepths();
  void OrientRings();
  void ClassifyEmptyCells();
  // ClipInto's steps and cases, after its checks: tile anticlockwise from its lowest vertex, box
  // its bounds (widened until its centre is inside, but for ClipWholeCatchment). ListCandidates
  // lists the segments that meet the box; then a tile without any is all in or all out
  // (ClipWithoutCandidates), and one with some is clipped piece by piece (ClipPieces).
  double ClipWholeCatchment(double tileArea, ClippedRings* rings) const;
  std::size_t ListCandidates(const Box2& box, Workspace& work) const;
  double ClipWithoutCandidates(const Point2* tile,
    std::size_t count,
    double tileArea,
    const Box2& box,
    const Point2& centre,
    std::size_t firstCell,
    Workspace& work,
    ClippedRings* rings) const;
  double ClipPieces(const Point2* tile,
    std::size_t count,
    double tileArea,
    const Box2& box,
    const Point2& centre,
    bool hullBuilt,
    Workspace& work,
    ClippedRings* rings) const;
  void BuildLocalRing(std::uint32_t ring,
    const std::uint32_t* ids,
    std::size_t count,
    const Box2& box,
    const Point2& centre,
    int winding,
    std::vector<Point2>& local) const;
  // The area of tile & catchment from where the catchment's boundary crosses the tile's
  // (crossing_area.cpp): false where the clipping must decide instead (see there).
  bool CrossingsWorthIt(const Box2& box) const;
  bool AreaByCrossings(const Point2* tile,
    std::size_t count,
    double tileArea,
    const Box2& box,
    Workspace& work,
    double& area) const;
  bool SumsTooCoarse(const Point2& origin,
    const Box2& hullBox,
    double tileArea,
    std::size_t sweeps) const;
  bool FindCrossings(const std::vector<Point2>& hull, Workspace& work) const;
  template<typename Visit>
  void ForEachCellAlong(const Point2& p, const Point2& q, Visit&& visit) const;
  bool AddEdgeCrossing(std::uint32_t v,
    const Point2& p,
    const Point2& q,
    std::size_t e,
    const Point2& origin,
    std::vector<Crossing>& crossings) const;
  bool AddInsidePieces(const Point2& origin, Workspace& work, CompensatedSum& twice) const;
  void AddPiece(const Crossing& in,
    const Crossing& out,
    const Point2& origin,
    CompensatedSum& twice) const;
  void AddSweep(std::size_t p, std::size_t q, const Point2& origin, CompensatedSum& twice) const;
  void AddBoundaryStretches(const std::vector<Point2>& hull,
    Workspace& work,
    CompensatedSum& twice) const;
  int IndicatorAtVertex(const Point2& h, Workspace& work) const;
  bool AddRingsWithin(const std::vector<Point2>& hull,
    const Box2& hullBox,
    const Workspace& work,
    CompensatedSum& twice) const;
  void BuildPrefixSums();
  // Grid cell of a coordinate along one axis: floor((value - lo) * scale), clamped to
  // [0, count).
  static std::size_t CellIndex(double value, double lo, double scale, std::size_t count);
  std::size_t CellX(double x) const;
  std::size_t CellY(double y) const;
  std::size_t NextVertex(std::size_t v) const;
  // Signed crossings of the ray from p towards +x, per ring, over the whole catchment.
  void RayCrossings(const Point2& p, std::vector<std::pair<std::uint32_t, int>>& out) const;
  // Winding number of the rings at p (the crossings in work.Crossings).
  int WindingAt(const Point2& p, Workspace& work) const;

  std::vector<std::size_t> Offsets;
  std::vector<Point2> Points;
  std::vector<std::uint32_t> EdgeRing; // ring of the segment starting at each vertex
  std::vector<int> Depths;
  // The pairs of rings that meet, and whether the first lies inside the second (validation's).
  std::vector<CleanRings::RingContact> Contacts;
  std::vector<bool> Reversed;
  double TotalArea = 0.0;
  double RingAreas = 0.0;
  Box2 Box;
  // Uniform grid over the segments: segment v (from vertex v) is listed in every cell its bounding
  // box meets. Cell (i, j) is i + j * GridX.
  std::size_t GridX = 1;
  std::size_t GridY = 1;
  double CellScaleX = 1.0;
  double CellScaleY = 1.0;
  std::vector<std::uint32_t> CellStart;
  std::vector<std::uint32_t> CellEdges;
  // Per segment, the first cell its box meets: column << 16 | row (GridX, GridY <= 4096).
  std::vector<std::uint32_t> FirstCell;
  // Per cell: -1 when segments meet it, else 0 or 1 for outside or inside the catchment.
  std::vector<signed char> EmptyCellInside;
  // For AreaByCrossings. Per vertex v: the sum of cross(p_k, p_k+1) over its ring's segments
  // before it (twice the signed area swept from the origin), and per ring the whole sum: exact
  // products summed as double-doubles. PrefixError bounds the sums' error.
  std::vector<DoubleDouble> Prefix;
  std::vector<DoubleDouble> RingSweep;
  std::vector<Box2> RingBoxes;
  double PrefixError = 0.0;
};

// (Inline, and through int, which holds any count up to 4096: as calls converting to an unsigned
// 64-bit type, the cell lookups were a tenth of the clipping's instructions.)
inline std::size_t Catchment::CellIndex(double value, double lo, double scale, std::size_t count)
{
  const double cell = (value - lo) * scale;
  if (!(cell > 0.0))
  {
    return 0;
  }
  return cell >= static_cast<double>(count) ? count - 1
                                            : static_cast<std::size_t>(static_cast<int>(cell));
}

inline std::size_t Catchment::CellX(double x) const
{
  return CellIndex(x, this->Box.XMin, this->CellScaleX, this->GridX);
}

inline std::size_t Catchment::CellY(double y) const
{
  return CellIndex(y, this->Box.YMin, this->CellScaleY, this->GridY);
}

inline std::size_t Catchment::NextVertex(std::size_t v) const
{
  const std::uint32_t ring = this->EdgeRing[v];
  return v + 1 == this->Offsets[ring + 1] ? this->Offsets[ring] : v + 1;
}

} // namespace tessera
