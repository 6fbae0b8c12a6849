#pragma once
// Green and Sibson's incremental Dirichlet tessellation (The Computer Journal 21(2), 1978), kept as
// its dual, the Delaunay triangulation, in flat half-edge arrays.
//
// Objects and rings. The paper's objects are the accepted points and the effective window
// constraints, each with an anticlockwise contiguity ring. Here the ring of a point is the
// anticlockwise sequence of half-edges leaving it (see RingNext): it is derived from two int32
// arrays, not stored as a list, so inserting a point "splices its neighbours' rings" simply by
// rewriting the few triangles around it. Constraints are not stored at all: a constraint takes
// part only as the reflection of a point (its virtual point), and the only place where that
// matters is the clipping of each tile by the window, which tiles.h does when deriving results.
// That is equivalent to the paper's construction because an accepted point's tile is the
// unwindowed tile intersected with the (convex) window (section 1.2).
//
// Storage (Delaunator style). Half-edge e belongs to triangle e / 3; Origin()[e] is the vertex it
// leaves, Twin()[e] the opposite half-edge. Triangles are anticlockwise. The convex hull is closed
// by "ghost" triangles that have the vertex Ghost (-1) in place of a third point, so every
// half-edge has a twin and every ring is a closed cycle. Per accepted point this costs 2
// triangles * 3 half-edges * 2 int32 = 48 bytes, plus 16 bytes of coordinates.
//
// Insertion. The triangle containing the new point is found by a visibility walk from the last
// triangle created (the paper's walk from the previous point); the point splits it (or the edge it
// lies on) and Lawson flips with an explicit stack restore the empty-circle property. Every
// decision uses the exact predicates, and an edge is flipped only when the circle test is strictly
// positive, so where 4 or more points are exactly co-circular the stored diagonal is arbitrary:
// derived results merge such triangles into one degenerate face and record neither diagonal as a
// contiguity (section 2.2), which makes them identical for every insertion order.
//
// Degenerate input. Until three non-collinear points are accepted the structure is "collinear":
// the accepted points are kept sorted along their line (CollinearPoints) and there are no
// triangles.

#include "cache_line.h"
#include "duplicate_places.h"
#include "geometry.h"
#include "uninitialized_allocator.h"
#include "walk_hints.h"
#include "window.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace tessera
{

/// The half-edge arrays' type: a std::vector of int32 whose resize() writes nothing, so that the
/// two-region build sizes its arrays once and each thread writes (and so first touches) its own
/// part.
using HalfEdgeArray = UninitializedVector<std::int32_t>;

enum class PointStatus : std::uint8_t
{
  Accepted,      ///< a vertex of the tessellation
  OutsideWindow, ///< rejected: not strictly inside the window
  Duplicate,     ///< exact copy of an accepted point with a smaller id (DuplicateOf)
  Removed,       ///< removed by Remove()
};

/// Threads: separate objects may be used on separate threads at once, and one object may be read
/// (its const members, NearestPoint(s) among them, and the results tiles.h derives from it) by
/// several threads at once while none changes it. Insert, Reinsert and Remove need it to
/// themselves. (The batch constructor, OrderTrianglesByVertex and the derivations run on several
/// threads of their own.)
class DirichletTessellation
{
public:
  static constexpr std::int32_t Ghost = -1; ///< the vertex "at infinity" of the ghost triangles
  static constexpr std::int32_t Free = -2;  ///< Origin() of the half-edges of a recycled triangle

  /// An empty tessellation in the window; add points with Insert().
  explicit DirichletTessellation(Window window);
  /// Batch construction: point ids are the indices into points; they are inserted in a BRIO +
  /// Hilbert order (spatial_order.h). Throws InputError naming the first point with a NaN or
  /// infinite coordinate (nothing is inserted then).
  DirichletTessellation(Window window, std::vector<Point2> points);

  /// Streaming: appends p with the next id and inserts it. Returns its id; its status tells
  /// whether it was accepted. Throws InputError (naming that id) for a NaN/Inf coordinate; the
  /// point is then not appended, and the next point inserted gets that id.
  /// nearId: an accepted point near p, where the walk to p starts when vertex edges are tracked
  /// (TrackVertexEdges); otherwise, or for -1, at the triangle made last, or, while walks from
  /// it run long (points in random order), at the nearest to p of it, the triangles made around
  /// the last 64 points, and the triangles an index along a Hilbert curve holds beside p (jump
  /// and walk, walk_hints.h). A p beyond a side of the box of the points accepted before it
  /// (removed ones included, unless the removals left points on a line; a stream sorted by x or
  /// y) is put beside the hull edge it sees at the last streamed point that reached that side,
  /// without a walk. The result is the same either way: only the walk's length differs (so an id
  /// that is no accepted point, out of range included, is not an error: the walk starts as for -1).
  std::int32_t Insert(const Point2& p, std::int32_t nearId = -1);
  /// Inserts a removed point again under its id, as Insert would insert its coordinates (nearId
  /// likewise; the window may reject it again, and it may be an exact copy of an accepted point).
  /// A stream whose points come and go, as gauges stop and start reporting, then keeps each
  /// point's id and its arrays' size, and points near in space stay near in memory when their
  /// ids were given in a spatial order. Throws InputError for an id that is not Removed.
  void Reinsert(std::int32_t id, std::int32_t nearId = -1);
  /// Removes an accepted point (the result equals the tessellation built without it; if it had
  /// exact duplicates, the smallest of them takes its place). A duplicate or rejected point is
  /// only marked removed. Throws InputError for an unknown or already removed id. The hole left
  /// by an interior or hull vertex is re-triangulated in place (O(1) expected): cut into Delaunay
  /// ears (O(degree^2)), or, for a hole of more than 64 vertices, by a batch build of its
  /// vertices (O(degree log degree): the centre of 4000 points on a circle in 6 ms, where ears
  /// took 4.5 s); only a removal that leaves the points collinear rebuilds.
  void Remove(std::int32_t id);

  const Window& GetWindow() const { return this->TheWindow; }
  /// Throws InputError naming the first accepted point that has a nonzero coordinate below 2^-200
  /// of the window's reach (CheckPointsInExactRange, window.h): the tiles' window decisions are
  /// not exact for it, and its tiles came out wrong without a word. The derivations (tiles.h) call
  /// it; such points are noted as they come (O(1) each), so a call costs O(their number).
  void CheckPointsInExactRange() const;
  /// Every point ever given, by id (removed and rejected ones included).
  const std::vector<Point2>& Points() const { return this->Coordinates; }
  std::size_t PointCount() const { return this->Coordinates.size(); }
  std::size_t AcceptedCount() const { return this->Accepted; }
  /// Triangles the walk of the last Insert or Reinsert crossed to find its point (a diagnostic: a
  /// stream whose walks stay long comes in no spatial order the jumps can follow).
  std::int64_t LastWalkSteps() const { return this->Serial.LastWalk; }

  /// O(1) once Insert or Remove has been called (a status byte per id); before that (a batch
  /// build only) a binary search among the rejected and duplicate ids.
  PointStatus Status(std::int32_t id) const;
  /// For a Duplicate, the accepted id it copies; -1 otherwise (an id out of range included, where
  /// Status throws). O(1) for a non-duplicate once Insert or Remove has been called, else a
  /// binary search among the duplicates.
  std::int32_t DuplicateOf(std::int32_t id) const;
  /// The accepted point nearest q (any finite point, in the window or not), by exact distance
  /// comparisons; of points equally near, the smallest id; -1 when no point is accepted. The
  /// walk of section 2.3 as a query: from q's triangle (found by the walk from the last triangle
  /// made) to a neighbour nearer q while there is one, which in a Delaunay triangulation ends at
  /// a nearest point. Throws InputError for a NaN or infinite q. O(walk length): short for q near
  /// the last point inserted; a scan of the points while they are collinear.
  std::int32_t NearestPoint(const Point2& q) const;
  /// The accepted point nearest each query, as NearestPoint answers it (the same ids), for many
  /// queries at once (nearest_point.cpp): they are taken along a Hilbert curve, each descent
  /// starting at the point found for the query before, so that queries spread like the points
  /// cost O(1) steps each after an O(m log m) sort, where NearestPoint's walk from the last
  /// triangle made is O(sqrt n) for a query anywhere. Throws InputError naming the first query
  /// (by index) that is not finite. While the points are collinear, a scan per query.
  std::vector<std::int32_t> NearestPoints(const std::vector<Point2>& queries) const;
  /// Rejected (outside the window) ids, ascending.
  std::vector<std::int32_t> RejectedIds() const;
  /// (duplicate id, accepted id it copies) pairs, ascending by duplicate id.
  std::vector<std::pair<std::int32_t, std::int32_t>> Duplicates() const;
  /// Removed ids, ascending.
  std::vector<std::int32_t> RemovedIds() const;

  /// True once three accepted points are not collinear; then the arrays below are the
  /// triangulation. Otherwise CollinearPoints() lists the accepted points in order along their
  /// line (lexicographic (x, y) order).
  bool IsTwoDimensional() const { return !this->Origins.empty(); }
  const std::vector<std::int32_t>& CollinearPoints() const { return this->Collinear; }

  const HalfEdgeArray& Origin() const { return this->Origins; }
  const HalfEdgeArray& Twin() const { return this->Twins; }
  static std::int32_t Next(std::int32_t e) { return e % 3 == 2 ? e - 2 : e + 1; }
  static std::int32_t Prev(std::int32_t e) { return e % 3 == 0 ? e + 2 : e - 1; }
  /// The half-edge after e anticlockwise around Origin()[e] (one step along its ring).
  std::int32_t RingNext(std::int32_t e) const { return this->Twins[std::size_t(Prev(e))]; }
  bool IsGhostTriangle(std::int32_t t) const;

  /// Keeps one half-edge leaving each vertex up to date from now on (4 bytes per id; Remove turns
  /// it on by itself), so that EdgeLeaving is O(1).
  void TrackVertexEdges() { this->EnableVertexEdges(); }
  bool TracksVertexEdges() const { return !this->VertexEdges.empty(); }
  /// A half-edge leaving vertex id, or -1 when id is not a vertex (rejected, duplicate, removed,
  /// unknown, or the tessellation is not two-dimensional). O(1) when vertex edges are tracked,
  /// otherwise a walk from the last triangle.
  std::int32_t EdgeLeaving(std::int32_t id) const;
  /// Appends to out the points joined to id by an edge of the triangulation, anticlockwise (none
  /// when id is not a vertex or the tessellation is not two-dimensional). Where points are
  /// co-circular the triangulation keeps some diagonals of their face, so these are a superset of
  /// the points whose tiles share an edge of positive length with id's; they include every point
  /// whose tile gains area when id is removed, or lost area when id was inserted. Why: if j's new
  /// tile takes area from id's old tile, that overlap is open, so walking inside it from j's side
  /// crosses a Voronoi edge between id and j of positive length; its points are centres of empty
  /// circles through just id and j, which makes id-j an edge of every Delaunay triangulation.
  /// O(degree) when vertex edges are tracked (see EdgeLeaving).
  void AppendNeighbours(std::int32_t id, std::vector<std::int32_t>& out) const;
  /// Asks the processor to bring toward its cache what operations at the given points read first
  /// (their coordinates and statuses, and, where vertex edges are tracked, the triangle of each
  /// one's edge), waiting only for the vertex edges it reads to find those triangles. A caller
  /// about to remove, or walk from, many vertices spread over a large triangulation calls it
  /// beforehand: the misses then overlap, where its operations, one after the other, each waited
  /// for its own (Remove, AppendNeighbours and Reinsert read these first). Changes nothing; ids
  /// out of range are skipped.
  void Prefetch(const std::int32_t* ids, std::size_t count) const;
  bool IsFreeTriangle(std::int32_t t) const { return this->Origins[3 * std::size_t(t)] == Free; }
  /// True when no two adjacent real triangles are exactly co-circular (so the tessellation has
  /// no degenerate vertex), as tracked since construction: the Delaunay faces are then exactly
  /// the real triangles. False when unknown or once such triangles were met (possibly only on
  /// the way: it stays false until a rebuild). Insertions track it from tests they make anyway
  /// plus one per triangle around each new point; removals test their new triangles against
  /// their neighbours. Derived results use it to skip their own check.
  bool KnownFreeOfCocircularTriangles() const { return this->NoCocircularTriangles; }

  /// Bytes held by the structure (capacities of all arrays, coordinates included). A batch build
  /// holds no per-id arrays besides the coordinates; the first Insert adds a status byte per id
  /// and the first Remove an incident half-edge per id (4 bytes, so that Remove finds its
  /// vertex in O(1)): 69 bytes per point in streaming use, and a stream in no spatial order
  /// builds the walk hints (8 bytes a triangle, some 16 a point). OrderTrianglesByVertex keeps
  /// its arrays (about 60 bytes per point more) once called.
  std::size_t StructureBytes() const;

  /// Triangles made (new or from freed slots) since the build or the last
  /// OrderTrianglesByVertex: each may lie anywhere in memory, away from its neighbours.
  std::size_t ScatteredTriangleCount() const { return this->ScatteredTriangles; }
  /// Renumbers the triangles in the order of their smallest vertex id and drops freed slots, so
  /// that, where ids were given in a spatial order, triangles near in space are near in memory
  /// again after many updates (triangle_order.cpp). The triangulation and every derived result
  /// stay the same (those listed in triangle order, such as a TileMesh's face-centre vertices,
  /// in the new order); half-edge numbers held from before are void. O(triangles + ids), its
  /// moves in chunks on the cores from 100000 triangles on.
  void OrderTrianglesByVertex();

private:
  enum class Location
  {
    Inside,
    OnEdge,
    OnVertex,
    InGhost,
    Foreign ///< inserting the point would change a triangle its region does not own
  };

  /// Who may change which triangles while points are inserted. The serial insertion (member
  /// Serial) owns every triangle. The two regions of a parallel batch build each own the
  /// triangles whose vertices all lie on their side of a vertical seam (ghosts count for neither
  /// side), and defer a point whose insertion would touch any other triangle
  /// (two_region_build.cpp). Each region has cache lines of its own: two threads write the two
  /// at every insertion (cache_line.h).
  struct alignas(CacheLineBytes) Region
  {
    double SeamX = std::numeric_limits<double>::infinity();
    bool Upper = false; ///< owns the points with x >= SeamX rather than x < SeamX
    bool Owns(const Point2& p) const { return (p.x < this->SeamX) != this->Upper; }
    /// Whether the region may insert points outside the hull: only the one that owns everything.
    /// A region that owns part of the hull must not: its hull may be reflex where a flip across
    /// the seam was skipped, and a new triangle on a hull edge could then overlap the
    /// triangulation.
    bool GrowsHull() const { return this->SeamX == std::numeric_limits<double>::infinity(); }
    std::int32_t LastTriangle = 0;
    /// Preallocated triangles [NextSlot, EndSlot), used before NewTriangle() is asked.
    std::int32_t NextSlot = 0;
    std::int32_t EndSlot = 0;
    /// A walk longer than this gives up (Foreign): a safety net where the triangulation outside
    /// the region is not yet Delaunay.
    std::int64_t MaxWalk = std::numeric_limits<std::int64_t>::max();
    /// Steps of the last insertion's walk (Locate): a streaming insertion after a long one jumps
    /// first.
    std::int64_t LastWalk = 0;
    std::vector<std::int32_t> FlipStack;
    std::vector<std::int32_t> Deferred; ///< points left for the serial insertion
    std::size_t Inserted = 0;
    /// Whether an insertion met two adjacent real triangles exactly co-circular (see
    /// StarIsCocircular for why the tests made during insertion are enough).
    bool SawCocircular = false;
  };

  /// Throws InputError naming the point id for a NaN/Inf coordinate (after: appended to it).
  void Validate(const Point2& p, std::size_t id, const char* after = "") const;
  /// knownBox: the bounding box of the points of ids when the caller has it (else computed).
  void BuildFrom(std::vector<std::int32_t>& ids, const Box2* knownBox = nullptr);
  /// The input id of a vertex (differs only during BuildFrom, which numbers vertices locally).
  std::int32_t InputId(std::int32_t v) const
  {
    return this->BuildOrder ? (*this->BuildOrder)[std::size_t(v)] : v;
  }
  void InsertKnownPoint(std::int32_t id, std::int32_t nearId);
  /// JumpTowards: off; probing with a few samples after a long walk; on, with many.
  enum class Jumping : std::uint8_t
  {
    Off,
    Probe,
    On
  };
  Jumping JumpMode = Jumping::Off;
  /// Steps of the last walk that started without a hint (nearId): JumpTowards decides by it. By
  /// the last walk of any kind, a stream alternating hinted and unhinted points walked some 550
  /// triangles per unhinted point at 2 10^5 points: each hinted walk, short, turned jumps off.
  std::int64_t UnhintedWalk = 0;
  int JumpMisses = 0;       ///< jumps in a row, while on, that found no nearer start
  WalkHints Hints;          ///< JumpTowards's index of the triangles (built on first need)
  std::size_t Removals = 0; ///< removals of accepted points so far (with Serial.Inserted: Hints)
  /// A triangle made around each of the last points streamed in (its insertion's last triangle),
  /// a ring (triangle 0 before them): jumps may start there (JumpTowards). It may have changed or
  /// been freed since, which a jump sees.
  std::array<std::int32_t, 64> RecentStarts{};
  std::size_t NextRecentStart = 0;
  /// Streams sorted along an axis (a table's rows by x): the box of the points accepted so far
  /// (not shrunk by a removal from the triangles in place: it holds every accepted point, and
  /// perhaps removed ones) and, per side of it (x max, x min, y max, y min), the last point
  /// streamed in that reached that side with the triangle its insertion made last (-1, -1 when
  /// unknown). A point beyond a side is outside the hull and sees that point: its walk starts
  /// there (StartBesideExtreme), where from the last point's triangle it crossed the hull's
  /// inside (10^5 points sorted by x walked 100 triangles each without the jumps, 8.6 with).
  struct SideStart
  {
    std::int32_t Id = -1;
    std::int32_t Triangle = -1;
  };
  /// (empty at first; a rebuild starts it afresh from the points left, and a removal from the line
  /// while the points are collinear sets it to the line's ends)
  Box2 AcceptedBox = Box2::Empty();
  std::array<SideStart, 4> SideStarts{};
  bool StartBesideExtreme(const Point2& p);
  bool StartBesideHullVertex(const SideStart& start, const Point2& p);
  void NoteSidesReached(std::int32_t id);
  void NoteBatchBox(const Box2& box);
  Box2 BoxOfCollinearPoints() const;
  void JumpTowards(const Point2& p);
  /// The jump index, the recent starts and the sides' starts, where triangles renumber.
  void ForgetWalkStarts();
  /// The half-edge of ghost triangle t on the hull; -1 for a free triangle.
  std::int32_t HullEdgeOfGhost(std::int32_t t) const;
  // JumpTowards' parts (dirichlet_tessellation.cpp).
  bool JumpWanted(std::int32_t triangles);
  double SquaredDistanceToTriangle(std::int32_t t, const Point2& p) const;
  int JumpSamples(std::int32_t triangles) const;
  std::int32_t NextJumpSample(std::int32_t triangles);
  void UpdateJumpMode(bool foundNearer);
  void InsertAcceptedPoint(std::int32_t id);
  void InsertCollinear(std::int32_t id);
  void SortCollinearBatch();
  void LeaveCollinearPhase(std::int32_t id);
  void InsertIntoTriangulation(std::int32_t id);
  Location InsertInRegion(Region& region, std::int32_t id, std::int32_t& edge);
  /// walked: where an insertion keeps the walk's length (steps), for JumpTowards.
  Location Locate(const Region& region,
    const Point2& p,
    std::int32_t& edge,
    std::int64_t* walked = nullptr) const;
  // Locate's parts: defined [[gnu::always_inline]] in dirichlet_tessellation.cpp and callable
  // only there (as calls, they added 1.2% to a build's instructions).
  inline bool TestFirstTriangle(const Region& region,
    std::int32_t t,
    const Point2& p,
    int* sides,
    std::int32_t& crossed) const;
  inline Location WhereInTriangle(const Region& region,
    std::int32_t t,
    const Point2& p,
    const int* sides,
    std::int32_t& edge) const;
  void SplitTriangle(Region& region, std::int32_t t, std::int32_t p);
  void SplitEdge(Region& region, std::int32_t e, std::int32_t p);
  int EdgeTest(std::int32_t x, std::int32_t y, std::int32_t p, std::int32_t q) const;
  void RestoreDelaunay(Region& region);
  std::int32_t NewTriangle();
  std::int32_t NewTriangle(Region& region)
  {
    return region.NextSlot < region.EndSlot ? region.NextSlot++ : this->NewTriangle();
  }
  // Two-region batch build (two_region_build.cpp).
  /// box: the bounding box of the vertices [0, order.size()).
  void InsertInOrder(std::vector<std::int32_t>& order, const Box2& box);
  // Batch build steps (dirichlet_tessellation.cpp).
  void KeepInsideWindow(const std::vector<std::int32_t>& bounds, std::vector<std::int32_t>& inside);
  void RenameToInputIds(const std::vector<std::int32_t>& order);
  std::int32_t NumberTrianglesByVertex(); ///< OrderTrianglesByVertex's sort (triangle_order.cpp)
  bool InsertInTwoRegions(std::int32_t first, std::int32_t end, const Box2& box);
  struct TwoRegionBuild; // its steps and state
  bool LegalizeEdges(std::vector<std::int32_t>& edges);
  void FlipEdge(std::int32_t e);
  void CompactFreeTriangles();
  void SetTriangle(std::int32_t t,
    std::int32_t a,
    std::int32_t b,
    std::int32_t c,
    std::int32_t ta,
    std::int32_t tb,
    std::int32_t tc);
  bool StarIsCocircular(std::int32_t start) const;
  void RecordDuplicate(std::int32_t id, std::int32_t kept, std::int32_t keptEdge);
  void Relabel(std::int32_t edge, std::int32_t newId);
  std::int32_t FindVertexEdge(std::int32_t id) const;
  void EnableStatusBytes();
  void EnableVertexEdges();
  void RecomputeStatusBytes();
  void RecomputeVertexEdges();
  void AddDuplicatePair(std::int32_t duplicate, std::int32_t kept);
  void ResolveDuplicateChains();
  std::vector<std::pair<std::int32_t, std::int32_t>>::const_iterator FindDuplicatePair(
    std::int32_t id) const;
  /// One triangle of a re-triangulated hole: its vertices and the twins of its three half-edges
  /// (-1 where a later triangle of the same plan supplies the twin).
  struct Ear
  {
    std::int32_t A, B, C, TwinA, TwinB, TwinC;
  };
  /// RemoveInteriorVertex's lists, kept between calls: a removal then allocates nothing (growing
  /// four vectors from empty was some 15 allocations per removal).
  struct RemovalScratch
  {
    std::vector<std::int32_t> Ring;  ///< link vertices, anticlockwise
    std::vector<std::int32_t> Outer; ///< Outer[i]: twin of the link edge Ring[i] -> Ring[i+1]
    std::vector<std::int32_t> Slots; ///< the star's triangles, reused
    std::vector<Ear> Plan;
  };
  bool CutDelaunayEars(std::vector<std::int32_t>& ring,
    std::vector<std::int32_t>& outer,
    const std::vector<std::int32_t>& slots,
    std::size_t first,
    std::vector<Ear>& plan) const;
  bool IsDelaunayEar(const std::vector<std::int32_t>& ring,
    std::size_t i,
    std::size_t b,
    std::size_t c) const;
  bool TriangulateHole(std::vector<std::int32_t>& ring,
    std::vector<std::int32_t>& outer,
    const std::vector<std::int32_t>& slots,
    std::size_t first,
    std::vector<Ear>& plan) const;
  bool TriangulateLinkByBuild(const std::vector<std::int32_t>& ring,
    const std::vector<std::int32_t>& outer,
    const std::vector<std::int32_t>& slots,
    std::size_t first,
    std::vector<Ear>& plan) const;
  void ApplyPlan(const std::vector<Ear>& plan, const std::vector<std::int32_t>& slots);
  bool RemoveInteriorVertex(std::int32_t edge);
  bool RemoveHullVertex(std::int32_t edge);
  // Remove's cases (dirichlet_tessellation.cpp).
  void ForgetRejected();
  bool PassToHeir(std::int32_t id,
    std::uint8_t flags,
    std::int32_t edge,
    std::vector<std::int32_t>::iterator onLine);
  void RemoveVertex(std::int32_t id, std::int32_t edge, std::vector<std::int32_t>::iterator onLine);
  /// A hull vertex v's star: its chain of neighbours a = n_0 .. n_k = b, the twins outside the
  /// chain's edges, the star's triangles in ring order from the ghost (v, G, a) (Slots[0]), and
  /// the twins of the ghosts' edges beyond a and b. RemoveHullVertex's steps: ReadHullStar, the
  /// new hull (ConvexChain), PlanHullRemoval, WriteHullRemoval (dirichlet_tessellation.cpp).
  struct HullStar
  {
    std::vector<std::int32_t> Chain, Outer, Slots;
    std::int32_t TwinBeforeA = -1, TwinAfterB = -1;
  };
  bool ReadHullStar(std::int32_t edge, HullStar& star) const;
  bool PlanHullRemoval(const HullStar& star,
    const std::vector<std::size_t>& hull,
    std::vector<Ear>& plan,
    std::vector<Ear>& ghosts) const;
  void WriteHullRemoval(const HullStar& star,
    const std::vector<Ear>& plan,
    const std::vector<Ear>& ghosts);
  void FreeTriangle(std::int32_t t); ///< marks triangle t free, for reuse
  void RebuildWithout(std::int32_t id);
  bool AnyCocircularNeighbour(const std::int32_t* triangles, std::size_t count) const;
  void BeginTrackedChange();
  void EndTrackedChange();

  Window TheWindow;
  std::vector<Point2> Coordinates;
  /// Ids of the points inside the window with a coordinate below TinyBelow but not 0, in order
  /// (rare; CheckPointsInExactRange reads their status).
  std::vector<std::int32_t> TinyIds;
  double TinyBelow = 0.0; ///< 2^-200 of the window's reach
  void NoteIfTiny(std::int32_t id);
  HalfEdgeArray Origins;
  HalfEdgeArray Twins;
  std::vector<std::int32_t> FreeTriangles;
  std::uint64_t JumpState = 0x9E3779B97F4A7C15ULL; ///< JumpTowards's random samples
  std::vector<std::int32_t> Collinear;
  /// During BuildFrom: Collinear[2..] were appended in build order, to be sorted at the end.
  bool CollinearUnsorted = false;
  /// Rejected ids: ascending after a batch build; once there are status bytes, in the order
  /// rejected, with stale entries (ids removed, or rejected again) that the status bytes tell
  /// apart, compacted when they outnumber the live ones (CompactRejected): erasing each removed
  /// id from a sorted list moved the rest (2 us a removal at 10^5 rejected points).
  std::vector<std::int32_t> Rejected;
  std::size_t RejectedLive = 0; ///< rejected ids in Rejected, once there are status bytes
  void CompactRejected(const std::vector<std::uint8_t>& status);
  /// A batch build's exact copies: (copy, kept) pairs, sorted by copy outside BuildFrom. Once
  /// there are status bytes (streaming) the copies are kept by place in Places instead, and
  /// this holds only what a rebuild (BuildFrom) finds, until RecomputeStatusBytes moves it there.
  std::vector<std::pair<std::int32_t, std::int32_t>> DuplicatePairs;
  DuplicatePlaces Places;
  /// During BuildFrom: a kept point gave way to a copy with a smaller input id, so pairs may name
  /// a point that is now a duplicate as kept (ResolveDuplicateChains follows them at the end).
  bool DuplicateChains = false;
  /// Per id, a PointStatus in the low bits plus HasDuplicates for an accepted point that exact
  /// copies point to; empty until the first Insert or Remove (a batch build does not pay for it).
  std::vector<std::uint8_t> StatusBytes;
  /// Whether the status bytes are made (streaming): Status and the copies' queries read them and
  /// the places; before, a batch build's sorted lists.
  bool HasStatusBytes() const { return this->StatusBytes.size() == this->Coordinates.size(); }
  /// Per id, one half-edge leaving that vertex (-1 for ids that are not vertices); empty until
  /// the first Remove, then kept up to date wherever a triangle's vertices are written.
  std::vector<std::int32_t> VertexEdges;
  bool VertexEdgesOn = false; ///< VertexEdges kept (it is empty while there are no points)
  Region Serial;
  RemovalScratch Removal;
  const std::vector<std::int32_t>* BuildOrder = nullptr;
  std::size_t Accepted = 0;
  bool NoCocircularTriangles = false;
  /// Between BeginTrackedChange and EndTrackedChange, when the tessellation was known free of
  /// co-circular triangles: the change tests what it makes (star tests, removal's new triangles).
  bool TrackingCocircular = false;
  std::size_t ScatteredTriangles = 0; ///< see ScatteredTriangleCount
  /// OrderTrianglesByVertex's arrays, kept between calls (the half-edge arrays it fills are
  /// swapped with the structure's): fresh pages cost more than the ordering itself.
  struct OrderScratch
  {
    std::vector<std::int32_t> First;
    std::vector<std::int32_t> NewIndex;
    HalfEdgeArray Origins;
    HalfEdgeArray Twins;
  };
  OrderScratch Ordering;
};

} // namespace tessera
