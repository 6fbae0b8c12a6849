#pragma once
// Results derived from a DirichletTessellation (Green and Sibson: "all other properties of the
// tessellation, tile vertex positions and tile areas for example, are easily calculated from the
// contiguities and the point coordinates"): tile polygons with their areas and neighbour counts,
// the contiguity graph with half-neighbours, and the Delaunay faces.
//
// Local derivation (ComputeTilesOf): the same tiles for chosen points only, labelling just the
// faces around them; with face mates, it is what an incremental user (areal_average) needs to
// re-derive only the tiles a removal or insertion can change.
//
// Faces. Triangles of the stored triangulation whose circumcircles coincide exactly (4 or more
// co-circular points, decided with the exact incircle) are merged into one degenerate face. A
// face's centre is computed once, from its first three points by coordinates (geometry.h:
// ComesFirst), so every tile that has it as a vertex gets the same bits, and the result depends
// neither on which diagonal the triangulation happens to store nor on how the points are numbered.
// Neither diagonal of a degenerate face is a contiguity: its non-adjacent vertex pairs are
// half-neighbours (kind 1), reported when the centre lies inside the window.
//
// Window constraints (the paper's second kind of object) are handled here. The edge a tile shares
// with point j runs along the bisector of the two points between the centres of the faces on
// either side of the Delaunay edge (a ray where that face is a ghost). It is clipped once, to the
// window, from the first of the two points by coordinates, so both tiles agree on it. Every
// decision about the window is exact (window_predicates.h; "exact predicates, inexact
// constructions"): whether a face centre lies strictly inside (the rounded centre with its error
// bound settles almost every face, the exact predicate the rest), which window lines the bisector
// crosses first and last, and whether the face centres lie before or after those crossings. So a
// contiguity (kind 0) is reported iff the open Voronoi edge meets the open window in a segment of
// positive length, and half-neighbours iff their degenerate vertex is strictly inside. Only the
// coordinates are rounded: a kept face centre, a crossing computed from the bisector's midpoint
// and direction (accurate even when the far centre is huge), a window corner where the edge
// passes exactly through it. Between an edge leaving the window on constraint a and the next one
// entering on constraint b, the tile follows the window boundary through corners a+1 .. b. Each
// polygon side is then one contiguity: with a point (both tiles see it) or with a constraint.
// NeighborCount counts these sides from the exact decisions (two rounded vertices may coincide
// where the true ones do not; the polygon drops such repeats, the count does not), as in the
// paper, and
//   sum of NeighborCount + (constraint sides) + 2 * constraints = 4 * constraints + 6 * points - 6
// when no vertex is degenerate (section 2.3).

#include "dirichlet_tessellation.h"
#include "geometry.h"
#include "uninitialized_allocator.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace tessera
{

/// One polygon per accepted point, in a spatially coherent order (PointIds names the point).
struct TileSet
{
  std::vector<std::int32_t> PointIds;
  std::vector<std::int64_t> Offsets; ///< tile k's vertices are [Offsets[k], Offsets[k+1])
  std::vector<Point2> Vertices;      ///< anticlockwise; face centres and window-edge points
  std::vector<double> Areas;         ///< compensated (Neumaier) summation of the shoelace terms
  std::vector<std::int32_t> NeighborCounts; ///< contiguities: sides of the polygon
};

/// Pairs (i < j), grouped by i (in the tiles' order), ascending j within a group. The arrays'
/// resize() leaves new elements uninitialised (UninitializedVector): the derivation's chunks
/// write their parts in place, each thread first touching its own pages.
struct ContiguityGraph
{
  UninitializedVector<std::int32_t> Pairs; ///< 2 ids per contiguity
  UninitializedVector<std::uint8_t>
    Kinds; ///< 0: share an edge of positive length, 1: half-neighbours
};

struct TilesAndGraph
{
  TileSet Tiles;
  ContiguityGraph Graph;
};

/// The tiles of a TileSet as a mesh whose tiles share vertices: tile k's polygon is
/// Vertices[VertexIds[Offsets[k]]], ... and has exactly the coordinates of the TileSet's tile k.
/// Where tiles meet at a face centre inside the window they use one vertex, and likewise at a
/// window corner and where a tile edge crosses the window boundary (both tiles compute that point
/// alike). Distinct faces whose rounded centres coincide, which a tile lists once, are one vertex
/// too, and a tile whose rounded corners go X, Y, X (three faces an ulp apart, the outer two
/// rounding to one point) keeps one X: it would go out to Y and back. So tiles that share a side
/// name it by the same two vertex ids: a conforming mesh. (Limit: where four or more face centres
/// lie within rounding of each other, as when some 20 points lie within 1e-16 of one circle, a
/// tile can still touch itself at a rounded corner, X, Y, Z, X; its area and sides stay exact.) The
/// per-tile and per-id arrays are UninitializedVectors, as in ContiguityGraph.
struct TileMesh
{
  UninitializedVector<std::int32_t> PointIds;
  UninitializedVector<std::int64_t> Offsets; ///< tile k's vertex ids are [Offsets[k], Offsets[k+1])
  UninitializedVector<std::int32_t> VertexIds; ///< anticlockwise, into Vertices
  /// Face centres inside the window (in the order of the triangle arrays), then the window's
  /// corners, then the crossings of tile edges with the window boundary.
  UninitializedVector<Point2> Vertices;
  UninitializedVector<double> Areas;
  UninitializedVector<std::int32_t> NeighborCounts;
};

struct TileMeshAndGraph
{
  TileMesh Tiles;
  ContiguityGraph Graph;
};

/// A TileSet as a TileMesh whose vertices are numbered by the caller: cornerVertexIds[k] is the
/// vertex of corner k (tiles.Vertices[k]), ids from 0 without gaps, in the order they first come,
/// equal ids only for equal corners. For the Brassel-Reif engine (ThiessenSweepResult's
/// CornerVertexIds), so that its tiles make a conforming mesh as TessellationDual's do. Throws
/// std::logic_error (a caller's mistake, not the input's) when there is not one id per corner.
TileMesh MeshOfNumberedCorners(TileSet tiles, const std::vector<std::int32_t>& cornerVertexIds);

/// Scales a mesh's vertices by 2^exponent and its areas by 2^(2 exponent), exactly: the tiles of
/// points scaled by Window::RangeScaleExponent, brought back to the points' own scale.
void ScaleByPowerOfTwo(TileMesh& mesh, int exponent);

/// Throws InputError when the tessellation's window lies outside the range where the tiles'
/// window decisions are exact (Window::RangeScaleExponent is not 0: coordinates beyond about
/// 2^128, or all below 2^-128): its tiles came out wrong there without a word (corners inf or NaN
/// at 1e120, collapsed tiles at 1e-120). The derivations of tiles and contiguities call it (not
/// that of the Delaunay faces, which are exact at any scale);
/// ScaleIntoExactRange (window.h) before building, and ScaleByPowerOfTwo after, handle any scale.
/// It also throws for an accepted point with a nonzero coordinate below 2^-200 of the window's
/// reach (DirichletTessellation::CheckPointsInExactRange), which no scale helps: 50 points within
/// 1e-200 of a corner gave tiles whose areas summed to 44.9 times the window's.
void CheckWindowInExactRange(const DirichletTessellation& tessellation);

/// The points, ascending, whose tiles have fewer than 3 distinct corners, or only collinear ones
/// (exactly): strips narrower than the coordinates' resolution (points an ulp or so
/// apart), whose corners round onto each other or onto one line, so that the polygon has no area
/// in doubles (and which corners are left can depend on the input's order).
std::vector<std::int32_t> CollapsedTilePoints(const TileMesh& tiles);

/// Throws InputError unless the tiles' areas add up to the window's area (within 1e-6 relative,
/// plus cornerRounding, CornerRoundingOfTiles(window); none given counts as 0): a check that
/// points lay within the range where the tiles are exact (window_predicates.h). Necessary, not
/// sufficient: it catches tiles that overlap or leave gaps, not a tile given to the wrong point.
/// No tiles pass. windowArea must be Window::Area() of the window the tiles were made in: the
/// message blames the points, as that is what it checks, and where no cornerRounding was given,
/// names it too (a small slanted window far from the origin fails on its corners alone).
void CheckTilesFillWindow(const TileMesh& tiles,
  double windowArea,
  std::optional<double> cornerRounding = std::nullopt);

/// How far the tiles' areas can add up from the window's exact area because their corners are
/// rounded to doubles: a corner on a slanted side lies off it by some ulps of the coordinates (a
/// computed crossing, not a correctly rounded one), and the tiles' outer boundary, which is what
/// their areas add up to (inner corners are shared), moves by up to the window's perimeter times
/// that: an estimate, four ulps. Negligible unless the window is small beside
/// its distance from the origin: a triangle 2^-40 wide at 0.5 summed 8e-6 and 2.1e-5 off for
/// two sets of points, where this gives 3.3e-3 of its area (a rectangle's sides hold their
/// rounded corners exactly).
double CornerRoundingOfTiles(const Window& window);

/// Delaunay faces, each anticlockwise and starting at its smallest point id, listed in the order
/// of the triangle arrays. The set of faces, and each face, do not depend on the insertion order;
/// the listing order does.
/// Offsets are int32 like the ids: a tessellation holds at most INT32_MAX / 8 points, so fewer
/// than 6 ids per point fit.
struct DelaunayFaces
{
  std::vector<std::int32_t> Offsets;
  std::vector<std::int32_t> PointIds;
};

namespace tiles_detail
{
struct EdgeEnd;  // an end of a clipped tile edge (tile_edges.h)
struct TileEdge; // a clipped tile edge (tile_edges.h)
struct FaceView; // a face as a tile edge sees it (tile_edges.h)
} // namespace tiles_detail

/// Face structure of a tessellation (merged degenerate faces, centres): computed once, then each
/// result is derived from it. Holds a reference: the tessellation must outlive it and not change.
class TessellationDual
{
public:
  explicit TessellationDual(const DirichletTessellation& tessellation);

  TileSet Tiles() const;
  ContiguityGraph Contiguities() const;
  /// Both, as Tiles() and Contiguities() give them, in one pass over the rings (faster than
  /// calling the two).
  TilesAndGraph TilesAndContiguities() const;
  /// The same tiles as a TileMesh, and the contiguities, in one pass (what a caller that writes
  /// a mesh needs: a third of the vertices to store). Without withContiguities the graph is not
  /// derived and stays empty (the mesh is the same). Not const: it numbers the face vertices,
  /// so it must not run while another thread uses this object.
  TileMeshAndGraph TileMeshAndContiguities(bool withContiguities = true);
  /// With splitDegenerate, a degenerate face becomes a fan of triangles from its smallest id.
  DelaunayFaces Faces(bool splitDegenerate) const;

  /// Number of merged faces with 4 or more points.
  std::size_t DegenerateFaceCount() const { return this->DegenerateReps.size(); }

  /// The results are derived in chunks of at least this many points, one per thread (a second
  /// thread pays off from a few thousand tiles, about 250 ns of work each: at 10^4 points the
  /// build plus tiles went from 6.4-7.9 to 5.4-6.7 ms, medians of 5, with this instead of 25000).
  static constexpr std::int64_t MinimumTilesPerThread = 2500;

  // Face access for the tile walk (tiles.cpp): triangle t's face label, and a face's view.
  std::int32_t Label(std::int32_t t) const { return this->Data[std::size_t(t)].Face; }
  tiles_detail::FaceView View(std::int32_t label) const;

private:
  void OrderPoints();
  void ComputeTriangleCentres(std::vector<std::uint8_t>& cocircular);
  void CentresOf(std::int32_t begin, std::int32_t end);
  void CocircularEdgesOf(std::int32_t begin, std::int32_t end, std::uint8_t* cocircular) const;
  bool Cocircular(std::int32_t t, std::int32_t f) const;
  void LabelFaces(const std::vector<std::uint8_t>& cocircular);
  struct ClusterList; // co-circular clusters found by one chunk of triangles (tiles.cpp)
  void MergeClusters(std::int32_t begin,
    std::int32_t end,
    const std::vector<std::uint8_t>& cocircular,
    ClusterList& found);
  /// MergeClusters' flood of one cluster and, when its chunk keeps it, its record (tiles.cpp).
  bool FloodCircle(std::int32_t t,
    const std::vector<std::uint8_t>& cocircular,
    std::vector<std::uint8_t>& visited,
    std::vector<std::int32_t>& cluster,
    std::vector<std::int32_t>& stack,
    std::vector<std::int32_t>& boundary) const;
  void KeepCluster(std::int32_t t,
    const std::vector<std::int32_t>& cluster,
    std::vector<std::int32_t>& boundary,
    ClusterList& found);
  void RecordClusters(const std::vector<std::int32_t>& bounds,
    const std::vector<ClusterList>& found);
  /// The collinear case's tile edges of v (the planar case uses RingTileEdges).
  void CollinearTileEdges(std::int32_t v, std::vector<tiles_detail::TileEdge>& edges) const;
  /// Tiles() and Contiguities() run chunks of Order in parallel (Derive, DeriveOf);
  /// TouchRings walks RingBatch rings side by side to overlap their cache misses.
  static constexpr std::int32_t RingBatch = 32;
  struct RingScratch; // one chunk's buffers (tiles.cpp)
  struct MeshPart;    // one chunk's mesh tiles (tiles.cpp)
  struct GraphPart;   // one chunk's contiguities (tiles.cpp)
  void TouchRings(std::int32_t begin, std::int32_t end) const;
  void Derive(TileSet* tiles, TileMesh* mesh, ContiguityGraph* graph) const;
  /// Derive's set-up of each chunk's mesh and graph parts; sortedCorners: the window's corners
  /// as (x, y, corner index), sorted. Returns the mesh's first crossing vertex (tiles.cpp).
  std::int32_t PrepareMeshParts(TileMesh& mesh,
    const std::vector<std::int32_t>& bounds,
    std::vector<MeshPart>& parts,
    std::vector<std::tuple<double, double, std::int32_t>>& sortedCorners) const;
  static void PrepareGraphParts(ContiguityGraph& graph,
    const std::vector<std::int32_t>& bounds,
    double halfPerPoint,
    std::vector<GraphPart>& parts);
  void DeriveOf(std::int32_t begin,
    std::int32_t end,
    bool half,
    TileSet* tiles,
    MeshPart* mesh,
    GraphPart* graph) const;
  void JoinMeshParts(TileMesh& mesh,
    const std::vector<std::int32_t>& bounds,
    std::vector<MeshPart>& parts,
    std::int32_t firstCrossing) const;
  std::int64_t HalfNeighbourPairCount() const;
  void AppendHalfNeighboursOf(std::int32_t v,
    const std::vector<std::int32_t>& ring,
    std::vector<std::pair<std::int32_t, std::uint8_t>>& around) const;
  std::int32_t TilePolygonOf(std::int32_t v, RingScratch& scratch, bool withLabels) const;
  void AppendTileOf(std::int32_t v, RingScratch& scratch, TileSet& tiles) const;
  void AppendMeshTileOf(std::int32_t v, RingScratch& scratch, MeshPart& mesh) const;
  std::int32_t MeshVertexAt(const tiles_detail::EdgeEnd& end) const;
  void IndexEdgeEnds(RingScratch& scratch) const;
  std::int32_t MeshVertexOf(const Point2& p, const RingScratch& scratch, MeshPart& mesh) const;
  void NumberFaceVertices(UninitializedVector<Point2>& vertices);
  void AppendContiguitiesOf(std::int32_t v,
    bool half,
    RingScratch& scratch,
    GraphPart& graph) const;
  const std::int32_t* DegeneratePolygon(std::int32_t face, std::int32_t& size) const;
  std::int32_t Neighbors1D(std::int32_t v, std::int32_t& next) const;

  const DirichletTessellation& Tess;
  std::vector<std::int32_t> LinePosition; ///< collinear case: per point id, index along the line
  /// Accepted points in traversal order: first appearance in the half-edge arrays read from the
  /// end (OrderPoints), which follows the spatial insertion order, so walking rings in this order
  /// stays in cache.
  UninitializedVector<std::int32_t> Order;
  /// Two-dimensional case: a half-edge leaving Order[k].
  UninitializedVector<std::int32_t> OrderEdge;
  /// Per triangle, together so that a ring walk touches one cache line per triangle: its face
  /// (a representative triangle; -2 - t for a ghost), and for a representative the face's centre
  /// and whether it lies inside the window: Vertex >= 0 (once NumberFaceVertices has run, the
  /// centre's index among a TileMesh's vertices; 0 before), -1 otherwise.
  /// Trivially constructible (no initializers), so that sizing Data writes nothing: every
  /// entry is first written by CentresOf, in parallel chunks (a serial zero fill took 19 ms at a
  /// million points).
  struct TriangleData
  {
    double X, Y; ///< the centre
    std::int32_t Face;
    std::int32_t Vertex;
    Point2 Centre() const { return { this->X, this->Y }; }
    bool Inside() const { return this->Vertex >= 0; }
  };
  UninitializedVector<TriangleData> Data;
  std::vector<double> CentreError; ///< per triangle, while labelling faces
  // Degenerate faces: representative -> index k; polygon k is DegenerateVertices[Starts[k] ..
  // Starts[k+1]), anticlockwise, starting at its smallest id.
  // Written by RecordClusters in parallel chunks, so sized without a fill.
  UninitializedVector<std::int32_t> DegenerateIndex;
  UninitializedVector<std::int32_t> DegenerateStarts;
  UninitializedVector<std::int32_t> DegenerateVertices;
  UninitializedVector<std::int32_t> DegenerateReps;
};

/// The tile of every accepted point, with its area and number of sides
/// (TessellationDual(t).Tiles()). Tiles come in a spatially coherent order, not by id:
/// TileSet::PointIds says whose each is. Reads the tessellation only, on several threads.
TileSet ComputeTiles(const DirichletTessellation& tessellation);

/// Per point, the ids of the points that share a face with it (its Delaunay ring neighbours and
/// the other points of its merged degenerate faces), ascending: the points whose tiles can change
/// when it is removed.
struct FaceMateLists
{
  std::vector<std::int32_t> PointIds;
  std::vector<std::int64_t> Offsets; ///< point k's mates are Ids[Offsets[k], Offsets[k+1])
  std::vector<std::int32_t> Ids;
};

/// The tiles of the given points only, in the given order (ids that are not accepted, and
/// repeats, are skipped), bit for bit the tiles TessellationDual(tessellation).Tiles() gives for
/// them: the same faces (degenerate ones merged, centres from their first three points) and the
/// same clipping. Only the faces around the given points are labelled, so the time is
/// proportional to their rings, plus, unless the tessellation tracks vertex edges
/// (TrackVertexEdges), one pass over the half-edge arrays to find an edge leaving each point.
/// With mates, also fills their face mates (same order as the tiles).
TileSet ComputeTilesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids,
  FaceMateLists* mates = nullptr);

/// What VisitTilesOf hands over per tile: the chunk it belongs to, the point's id and its tile's
/// vertices (valid during the call only).
using TileVisitor = std::function<
  void(std::size_t chunk, std::int32_t id, const Point2* vertices, std::size_t count)>;

/// What VisitTilesOf keeps between calls when given one: per chunk, a table of the triangles'
/// faces, set back after each call entry by entry, so that a caller that visits a few tiles at
/// each of many steps (the areal average's updates) does not clear a table of every triangle each
/// time; and the share of the tiles that the calling thread's chunk takes, adapted to how fast
/// the chunks went in the calls before. Its contents are VisitTilesOf's business.
struct LocalTilesWorkspace
{
  std::vector<std::vector<std::int32_t>> FaceTables;
  /// Tiles of chunk 0 (the calling thread's) per tile of each other chunk.
  double CallerWeight = 1.0;
};

/// ComputeTilesOf's tiles (the same, in the same order) handed to visit one by one as they are
/// made, instead of collected: a caller that clips or measures each tile does so while it is in
/// the cache, on the thread that made it. The ids are cut into contiguous chunks, at most
/// maxChunks, as many as have minimumPerThread ids each (parallel::ThreadCount); chunk 0 runs on
/// the calling thread, the others beside it, so visit must only write what belongs to its chunk
/// or to the id. The chunks are equal, but with a workspace chunk 0 takes its CallerWeight times
/// the others' share (1/2 to 2 times: adapted from call to call, LocalTilesWorkspace). A chunk
/// stops at the first tile whose visit throws; once every chunk has stopped, the error of the first
/// failing tile in the given order is rethrown. Returns the number of tiles visited.
std::size_t VisitTilesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids,
  std::size_t maxChunks,
  std::int64_t minimumPerThread,
  const TileVisitor& visit,
  LocalTilesWorkspace* workspace = nullptr);

/// The face mates of the given points only (same rules as ComputeTilesOf), without the tiles.
FaceMateLists ComputeFaceMatesOf(const DirichletTessellation& tessellation,
  const std::vector<std::int32_t>& ids);
/// The contiguity graph (TessellationDual(t).Contiguities()): every pair of neighbours once,
/// with half-neighbours (pairs that share only a degenerate vertex) marked as such.
ContiguityGraph ComputeContiguityGraph(const DirichletTessellation& tessellation);
/// The Delaunay faces (TessellationDual(t).Faces(splitDegenerate)): a face of 4 or more exactly
/// co-circular points is one polygon, or triangles when splitDegenerate.
DelaunayFaces ComputeDelaunayFaces(const DirichletTessellation& tessellation, bool splitDegenerate);

/// An upper bound on the number of faces when every Delaunay face is a triangle.
std::size_t DelaunayFaceCapacity(const DirichletTessellation& tessellation);

/// ComputeDelaunayFaces when every face is a triangle (the common case), written into the
/// caller's arrays, e.g. a VTK filter's output, so that nothing is copied. pointIds must hold
/// 3 * DelaunayFaceCapacity() ids and offsets DelaunayFaceCapacity() + 1. Returns the number of
/// faces written (the same faces, in the same order, as ComputeDelaunayFaces), or -1 when some
/// face is degenerate or the tessellation is not two-dimensional: then the arrays hold nothing
/// of use and ComputeDelaunayFaces gives the faces.
std::int64_t WriteTriangularDelaunayFaces(const DirichletTessellation& tessellation,
  std::int32_t* pointIds,
  std::int32_t* offsets);

} // namespace tessera
