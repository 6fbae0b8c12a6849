#include "dirichlet_tessellation.h"

#include "errors.h"
#include "large_pages.h"
#include "parallel_chunks.h"
#include "predicates.h"
#include "predicates_inline.h"
#include "spatial_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace tessera
{
namespace
{

// Most points are far from the window's edges: decide those in floating point (the error of
// a*x + b*y + c is below 3 units of roundoff of |a*x| + |b*y| + |c|; 8 leaves a margin) and leave
// the rest to the exact Window::Contains.
bool ClearlyInside(const std::vector<HalfPlane>& constraints, const Point2& p)
{
  for (const HalfPlane& h : constraints)
  {
    const double ax = h.a * p.x, by = h.b * p.y;
    const double f = ax + by + h.c;
    const double bound =
      8.0 * 0x1p-53 * (std::fabs(ax) + std::fabs(by) + std::fabs(h.c)) + 0x1p-1000;
    if (!(f < -bound))
    {
      return false;
    }
  }
  return true;
}

// Whether every point is finite and strictly inside the window, from one pass on the cores that
// also writes inside[k] = k and the points' bounding box: its corners inside the (convex) window
// put every point inside. The filters' default window pads that box, so this is the usual case;
// it saves a window test per point (10-20 ns each, half of the build's serial-looking start).
bool AllFiniteAndInside(const std::vector<Point2>& points,
  const Window& window,
  const std::vector<std::int32_t>& bounds,
  std::vector<std::int32_t>& inside,
  Box2& box,
  double tinyBelow,
  bool& anyTiny)
{
  const std::size_t chunks = bounds.size() - 1;
  anyTiny = false;
  if (bounds.back() == 0)
  {
    return true;
  }
  std::vector<Box2> boxes(chunks);
  std::vector<char> finite(chunks), tiny(chunks);
  parallel::RunChunks(chunks,
    [&](std::size_t c)
    {
      Box2 chunkBox = BoundsOf(&points[bounds[c]], 1);
      bool allFinite = true, someTiny = false;
      for (std::int32_t k = bounds[c]; k < bounds[c + 1]; ++k)
      {
        const Point2& p = points[k];
        allFinite &= (p.x - p.x == 0.0) & (p.y - p.y == 0.0); // false for NaN and infinities
        someTiny |= HasCoordinateBelow(p, tinyBelow);         // (while the points are read anyway)
        chunkBox.Extend(p);
        inside[k] = k;
      }
      boxes[c] = chunkBox;
      finite[c] = allFinite;
      tiny[c] = someTiny;
    });
  anyTiny = std::find(tiny.begin(), tiny.end(), 1) != tiny.end();
  if (std::find(finite.begin(), finite.end(), 0) != finite.end())
  {
    return false;
  }
  box = UnionOf(boxes);
  return window.Contains({ box.XMin, box.YMin }) && window.Contains({ box.XMax, box.YMin }) &&
    window.Contains({ box.XMax, box.YMax }) && window.Contains({ box.XMin, box.YMax });
}

// orient2d and incircle for the hot loops: the inlined filters of predicates_inline.h (their exact
// stages decide lattice and other rounding-free input cheaply, see predicates.cpp).
inline int Orient(const Point2& a, const Point2& b, const Point2& c)
{
  return orient2d_fast(a, b, c);
}

inline int InCircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d)
{
  return incircle_fast(a, b, c, d);
}

// The Delaunay test of half-edge x -> y of triangle (x, y, p) against q, the apex across it:
// 1 when p lies strictly inside the circle of (y, x, q), so that the edge must flip; 0 when the
// four real points are exactly co-circular; -1 otherwise. For a ghost triangle the "circle" is the
// open half-plane beyond its hull edge (a hull vertex that became reflex flips away); a hull edge
// seen from inside (p or q the ghost) never flips.
inline int DelaunayEdgeTest(const Point2* pts,
  std::int32_t x,
  std::int32_t y,
  std::int32_t p,
  std::int32_t q)
{
  constexpr std::int32_t ghost = DirichletTessellation::Ghost;
  if (x == ghost)
  {
    return Orient(pts[q], pts[y], pts[p]) > 0 ? 1 : -1;
  }
  if (y == ghost)
  {
    return Orient(pts[x], pts[q], pts[p]) > 0 ? 1 : -1;
  }
  if (p == ghost || q == ghost)
  {
    return -1;
  }
  return InCircle(pts[y], pts[x], pts[q], pts[p]);
}

// StatusBytes: the PointStatus in the low bits; HasDuplicates marks an accepted point that some
// Duplicate may copy, so that Remove looks for an heir only then (the mark may outlive the last
// copy: it is a hint, never a promise).
constexpr std::uint8_t StatusMask = 0x7f;
constexpr std::uint8_t HasDuplicates = 0x80;

} // namespace

DirichletTessellation::DirichletTessellation(Window window)
  : TheWindow(std::move(window))
  , TinyBelow(ExactRangeFloor(this->TheWindow))
  , NoCocircularTriangles(true) // no triangles yet
{
}

DirichletTessellation::DirichletTessellation(Window window, std::vector<Point2> points)
  : TheWindow(std::move(window))
  , Coordinates(std::move(points))
  , TinyBelow(ExactRangeFloor(this->TheWindow))
{
  if (this->Coordinates.size() > std::size_t(INT32_MAX / 8))
  {
    throw InputError("too many points: " + std::to_string(this->Coordinates.size()));
  }
  // The build's sorting steps free large arrays before later ones ask for arrays of their sizes.
  const ReuseLargeBlocks reuse;
  const std::int32_t n = std::int32_t(this->Coordinates.size());
  const std::vector<std::int32_t> bounds = parallel::ChunkBounds(n, parallel::ThreadCount(n));
  std::vector<std::int32_t> inside;
  ResizeOnLargePages(inside, static_cast<std::size_t>(n));
  Box2 box = Box2::Empty(); // (stays so for no points)
  bool anyTiny = true;      // (unless the fast pass below finds none)
  const bool allInside = AllFiniteAndInside(
    this->Coordinates, this->TheWindow, bounds, inside, box, this->TinyBelow, anyTiny);
  for (std::int32_t id = 0; anyTiny && id < n; ++id)
  {
    this->NoteIfTiny(id);
  }
  if (allInside)
  {
    this->BuildFrom(inside, &box);
    return;
  }
  this->KeepInsideWindow(bounds, inside);
  this->BuildFrom(inside);
}

// Validation and the window test per point, on the cores: inside keeps the ids inside the window,
// in id order, and Rejected gets the others. Each chunk writes the ids it keeps over its own part
// of `inside` and lists the others; the kept parts are then moved together. The first bad point
// of the first chunk that has one is the one reported, as when serial.
void DirichletTessellation::KeepInsideWindow(const std::vector<std::int32_t>& bounds,
  std::vector<std::int32_t>& inside)
{
  const std::size_t chunks = bounds.size() - 1;
  std::vector<std::int32_t> kept(chunks);
  std::vector<std::vector<std::int32_t>> outside(chunks);
  const std::vector<HalfPlane>& constraints = this->TheWindow.EffectiveConstraints();
  parallel::RunChunks(chunks,
    [&](std::size_t c)
    {
      std::int32_t* const out = inside.data() + bounds[c];
      std::int32_t count = 0;
      for (std::int32_t id = bounds[c]; id < bounds[c + 1]; ++id)
      {
        const Point2& p = this->Coordinates[id];
        this->Validate(p, std::size_t(id));
        if (ClearlyInside(constraints, p) || this->TheWindow.Contains(p))
        {
          out[count++] = id;
        }
        else
        {
          outside[c].push_back(id);
        }
      }
      kept[c] = count;
    });
  std::int32_t end = kept[0];
  for (std::size_t c = 1; c < chunks; ++c)
  {
    if (end != bounds[c])
    {
      std::copy_n(inside.begin() + bounds[c], kept[c], inside.begin() + end);
    }
    end += kept[c];
  }
  inside.resize(std::size_t(end));
  for (const std::vector<std::int32_t>& ids : outside)
  {
    this->Rejected.insert(this->Rejected.end(), ids.begin(), ids.end());
  }
}

namespace
{

// points[order[k]] for each k, gathered on the cores (random reads of a large array).
std::vector<Point2> GatherInOrder(const std::vector<Point2>& points,
  const std::vector<std::int32_t>& order)
{
  const std::vector<std::int32_t> chunks = parallel::ChunkBounds(
    std::int32_t(order.size()), parallel::ThreadCount(std::int64_t(order.size())));
  std::vector<Point2> gathered;
  ResizeOnLargePages(gathered, order.size());
  parallel::RunChunks(chunks.size() - 1,
    [&](std::size_t c)
    {
      for (std::int32_t k = chunks[c]; k < chunks[c + 1]; ++k)
      {
        gathered[k] = points[order[k]];
      }
    });
  return gathered;
}

} // namespace

// Batch insertion in BRIO + Hilbert order. While building, vertex k is the k-th point of that
// order and Coordinates holds the points in that order: consecutive insertions then touch
// neighbouring memory instead of coordinates scattered by input id (the difference is a factor of
// about two at 1M points). At the end the vertices are renamed to input ids and the input order
// is restored, so the structure costs no more than with input ids throughout.
void DirichletTessellation::BuildFrom(std::vector<std::int32_t>& ids, const Box2* knownBox)
{
  // A triangulation of n points with its ghosts has exactly 2n - 2 triangles.
  const std::size_t triangles = ids.size() >= 3 ? 2 * ids.size() - 2 : 0;
  this->Origins.reserve(this->Origins.size() + 3 * triangles);
  this->Twins.reserve(this->Twins.size() + 3 * triangles);
  // The batch's box serves the order and then the two-region build (its restart grids and curve).
  const Box2 box = knownBox ? *knownBox
    : ids.empty()           ? Box2::Empty()
                            : BoundsOfIds(this->Coordinates, ids);
  this->NoteBatchBox(box);
  std::vector<std::int32_t> order = BrioHilbertOrder(this->Coordinates, ids, box);
  ids.clear();
  ids.shrink_to_fit();
  std::vector<Point2> local = GatherInOrder(this->Coordinates, order);
  std::vector<std::pair<std::int32_t, std::int32_t>> earlierDuplicates;
  earlierDuplicates.swap(this->DuplicatePairs);
  this->Coordinates.swap(local);
  this->BuildOrder = &order;
  this->Serial.SawCocircular = false;
  this->InsertInOrder(order, box);
  this->ResolveDuplicateChains();
  this->SortCollinearBatch(); // (while vertices are numbered in build order)
  this->BuildOrder = nullptr;
  this->NoCocircularTriangles = !this->Serial.SawCocircular;
  this->Coordinates.swap(local);
  this->RenameToInputIds(order);
  this->DuplicatePairs.insert(
    this->DuplicatePairs.end(), earlierDuplicates.begin(), earlierDuplicates.end());
  // Outside BuildFrom the pairs are kept sorted by duplicate id (binary searches, ordered output).
  std::sort(this->DuplicatePairs.begin(), this->DuplicatePairs.end());
  if (!this->StatusBytes.empty())
  {
    this->RecomputeStatusBytes();
  }
  this->ScatteredTriangles = 0; // made along the build's spatial order
}

// The batch's vertices, numbered in build order while it runs, renamed to input ids (order[k] is
// vertex k's id): in the half-edges (a random read of a large array: on the cores from 150,000
// half-edges a thread, where the other core gains more than it costs to fetch what this one wrote:
// at 10^4 points, 60,000 half-edges, two chunks took 50-65 us and one 28), the line and the
// duplicate pairs.
void DirichletTessellation::RenameToInputIds(const std::vector<std::int32_t>& order)
{
  std::int32_t* const origins = this->Origins.data();
  const std::int64_t edges = std::int64_t(this->Origins.size());
  const std::vector<std::int32_t> edgeChunks =
    parallel::ChunkBounds(std::int32_t(edges), parallel::ThreadCount(edges, 150000));
  parallel::RunChunks(edgeChunks.size() - 1,
    [&](std::size_t c)
    {
      for (std::int32_t e = edgeChunks[c]; e < edgeChunks[c + 1]; ++e)
      {
        const std::int32_t v = origins[e];
        origins[e] = v >= 0 ? order[v] : v;
      }
    });
  for (std::int32_t& v : this->Collinear)
  {
    v = order[v];
  }
  for (auto& pair : this->DuplicatePairs)
  {
    pair = { order[pair.first], order[pair.second] };
  }
}

// Whether two adjacent triangles around a new point are exactly co-circular; start is a half-edge
// leaving it. Why this and the insertion's own tests suffice to know that a batch build has no
// co-circular adjacent pair: take such a pair in the result and the event that made the later of
// the two triangles.
// - A split or Lawson flip while inserting N, with the shared edge opposite N: the triangle went
//   on the flip stack and its edge was tested against the other (RestoreDelaunay records a zero),
//   or the flip was skipped at the seam and LegalizeEdges tested it.
// - The same, with the shared edge incident to N: both triangles lie around N, tested here.
// - A Lawson flip in LegalizeEdges: the four outer edges are tested; the two triangles on either
//   side of the new diagonal are not co-circular, as the flip needed a strictly positive test.
bool DirichletTessellation::StarIsCocircular(std::int32_t start) const
{
  const std::int32_t* const org = this->Origins.data();
  const std::int32_t* const twin = this->Twins.data();
  const Point2* const pts = this->Coordinates.data();
  const std::int32_t p = org[start];
  std::int32_t e = start;
  do
  {
    // (p, v1, v2) and the next triangle around p, (p, v2, v3), share the edge p - v2.
    const std::int32_t next = twin[Prev(e)];
    const std::int32_t v1 = org[Next(e)], v2 = org[Prev(e)], v3 = org[Prev(next)];
    if (v1 >= 0 && v2 >= 0 && v3 >= 0 && incircle_fast(pts[p], pts[v1], pts[v2], pts[v3]) == 0)
    {
      return true;
    }
    e = next;
  } while (e != start);
  return false;
}

void DirichletTessellation::NoteIfTiny(std::int32_t id)
{
  const Point2& p = this->Coordinates[id];
  if (HasCoordinateBelow(p, this->TinyBelow) && this->TheWindow.Contains(p))
  {
    this->TinyIds.push_back(id);
  }
}

void DirichletTessellation::CheckPointsInExactRange() const
{
  for (const std::int32_t id : this->TinyIds)
  {
    if (this->Status(id) == PointStatus::Accepted)
    {
      throw InputError(
        BelowExactRangeMessage(this->TheWindow, this->Coordinates[id], std::size_t(id), 0));
    }
  }
}

void DirichletTessellation::Validate(const Point2& p, std::size_t id, const char* after) const
{
  if (std::isnan(p.x) || std::isnan(p.y))
  {
    throw InputError("point " + std::to_string(id) + " has a NaN coordinate" + after);
  }
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
  {
    throw InputError("point " + std::to_string(id) + " has an infinite coordinate" + after);
  }
}

std::int32_t DirichletTessellation::Insert(const Point2& p, std::int32_t nearId)
{
  const std::size_t id = this->Coordinates.size();
  this->Validate(p, id, ": not inserted (the next point inserted gets that id)");
  if (id >= std::size_t(INT32_MAX / 8))
  {
    throw InputError("too many points: " + std::to_string(id + 1));
  }
  this->EnableStatusBytes();
  this->Coordinates.push_back(p);
  this->StatusBytes.push_back(std::uint8_t(PointStatus::Accepted));
  this->NoteIfTiny(std::int32_t(id));
  if (this->VertexEdgesOn)
  {
    this->VertexEdges.push_back(-1);
  }
  this->InsertKnownPoint(std::int32_t(id), nearId);
  return std::int32_t(id);
}

void DirichletTessellation::Reinsert(std::int32_t id, std::int32_t nearId)
{
  if (this->Status(id) != PointStatus::Removed) // (throws for an out-of-range id)
  {
    throw InputError(
      "point " + std::to_string(id) + " cannot be inserted again: it is not removed");
  }
  this->StatusBytes[id] = std::uint8_t(PointStatus::Accepted);
  this->InsertKnownPoint(id, nearId);
}

// Inserts point id (coordinates stored, status Accepted) unless the window rejects it.
void DirichletTessellation::InsertKnownPoint(std::int32_t id, std::int32_t nearId)
{
  const Point2& p = this->Coordinates[id];
  if (!this->TheWindow.Contains(p))
  {
    this->Rejected.push_back(id);
    ++this->RejectedLive;
    this->StatusBytes[id] = std::uint8_t(PointStatus::OutsideWindow);
    return;
  }
  bool hinted = false;
  if (nearId >= 0 && this->TracksVertexEdges())
  {
    const std::int32_t e = this->EdgeLeaving(nearId); // -1 unless an accepted vertex
    if (e >= 0)
    {
      this->Serial.LastTriangle = e / 3;
      hinted = true;
    }
  }
  if (!hinted && this->IsTwoDimensional())
  {
    hinted = this->StartBesideExtreme(p);
    if (!hinted)
    {
      this->JumpTowards(p);
    }
  }
  this->BeginTrackedChange();
  this->InsertAcceptedPoint(id);
  this->EndTrackedChange();
  this->NoteSidesReached(id);
  if (!hinted)
  {
    this->UnhintedWalk = this->Serial.LastWalk;
  }
  this->RecentStarts[this->NextRecentStart] = this->Serial.LastTriangle;
  this->NextRecentStart = (this->NextRecentStart + 1) % this->RecentStarts.size();
}

// Whether p lies beyond a side of the accepted points' box whose extreme point v is known with a
// triangle that still holds it; then the walk starts there. p is strictly beyond the side's line,
// on which v lies and beyond which no vertex lies, so p is outside the hull; v's two hull edges
// bound a wedge that holds the hull and lies on or behind that line, so p is strictly beyond one
// of them, and the walk reaches the hull beside v rather than crossing the inside.
//
//        hull     | side (x max)
//     ---------   |
//              \  |      p: beyond the side, so beyond an edge at v
//               v +
//              /  |
bool DirichletTessellation::StartBesideExtreme(const Point2& p)
{
  const Box2& box = this->AcceptedBox;
  const bool beyond[4] = { (p.x > box.XMax), (p.x < box.XMin), (p.y > box.YMax), (p.y < box.YMin) };
  for (int side = 0; side < 4; ++side)
  {
    if (beyond[side] && this->StartBesideHullVertex(this->SideStarts[side], p))
    {
      return true;
    }
  }
  return false;
}

// Whether start's triangle still holds its point v, and a ghost triangle round v has a hull edge
// that p is strictly beyond; then the walk starts at that ghost triangle.
bool DirichletTessellation::StartBesideHullVertex(const SideStart& start, const Point2& p)
{
  if (start.Triangle < 0 || std::size_t(start.Triangle) >= this->Origins.size() / 3)
  {
    return false;
  }
  const std::int32_t* const org = this->Origins.data();
  const std::int32_t* const twin = this->Twins.data();
  std::int32_t e = 3 * start.Triangle;
  while (org[e] != start.Id)
  {
    if (++e == 3 * start.Triangle + 3)
    {
      return false; // changed since: the point is no vertex of it
    }
  }
  const Point2* const pts = this->Coordinates.data();
  const std::int32_t first = e;
  do
  {
    // In a ghost triangle round v, the hull edge is the one of its edges at v that does not end
    // at the ghost: v's outgoing e when the ghost precedes v, else the incoming Prev(e).
    const std::int32_t f = org[Prev(e)] == Ghost ? e : org[Next(e)] == Ghost ? Prev(e) : -1;
    if (f >= 0 && Orient(pts[org[f]], pts[org[Next(f)]], p) > 0)
    {
      this->Serial.LastTriangle = e / 3;
      return true;
    }
    e = twin[Prev(e)]; // the next triangle round v
  } while (e != first);
  return false;
}

// After a streamed point's insertion: extends the accepted points' box by it, if accepted, and
// makes it the known extreme of each side it reached (unknown while the points are collinear).
void DirichletTessellation::NoteSidesReached(std::int32_t id)
{
  if (this->StatusBytes[id] != std::uint8_t(PointStatus::Accepted))
  {
    return; // (rejected, or a copy: inside the box)
  }
  const Point2& p = this->Coordinates[id];
  Box2& box = this->AcceptedBox;
  const bool reached[4] = { p.x >= box.XMax, p.x <= box.XMin, p.y >= box.YMax, p.y <= box.YMin };
  box.Extend(p);
  const SideStart start =
    this->IsTwoDimensional() ? SideStart{ id, this->Serial.LastTriangle } : SideStart{};
  for (int side = 0; side < 4; ++side)
  {
    if (reached[side])
    {
      this->SideStarts[side] = start;
    }
  }
}

// A batch's points (box: theirs, empty for none) extend the accepted points' box; which of them lie
// on its sides is not kept, so no side's extreme is known until a streamed point reaches it.
void DirichletTessellation::NoteBatchBox(const Box2& box)
{
  this->AcceptedBox.Extend(box); // (an empty batch's box is empty: nothing added)
  this->SideStarts.fill(SideStart{});
}

// Jump and walk (Muecke, Saias and Zhu 1996), while walks run long: the walk to p starts at
// whichever is nearest p (by their vertices) of the triangle made last, the triangles made around
// the last 64 points (RecentStarts) and the triangles indexed beside p along a Hilbert curve
// (walk_hints.h; built on first need, again once stale, cleared where triangles are renumbered or
// made again), or, where there is no index (the points' box has no extent), triangles sampled at
// random. With random samples alone every sample and step was a cache miss: 10^6 uniform points
// in random order took 18.8 s (3.1 s now, the batch 0.3 s), 10^5 along a parabola 1.3 s (0.10 s).
// From the last triangle alone, points streamed in random order walked O(sqrt n) triangles each,
// and points along a line that doubles only approximate (y = x/3: a fan of slivers) O(n): 10000
// of them took 2.35 s, where a batch took 0.11 s (0.13 s now). Without the recent points, 10^6
// points sorted by x walked 228 steps each (16-24 s; CGAL, inserting one by one, 2.8 s), as the
// index does not hold the points since its last build; with them 17 (2.0-2.3 s); no step since
// such points start beside the extreme point of the side they pass (StartBesideExtreme, 1.1 s:
// jumps are not asked for them). A stream in spatial order must not pay for jumps (each sample is
// a cache miss or two at 10^6 points: sampling at every point made one 5 times slower), so:
//
//   Off --unhinted walk of 2 cube roots of the triangles or more--> Probe (the recent starts,
//            and the index or 16 samples)
//   Probe --a start nearer than the last triangle--> On (the recent starts, and the index or a
//            quarter as many samples as the last unhinted walk's steps, from a cube root to a
//            square root of the triangles); else --> Off
//   On --JumpMissesToStop jumps in a row finding none nearer--> Off
void DirichletTessellation::JumpTowards(const Point2& p)
{
  const std::int32_t triangles = std::int32_t(this->Origins.size() / 3);
  if (!this->JumpWanted(triangles))
  {
    return;
  }
  std::int32_t best = this->Serial.LastTriangle;
  double bestDistance = this->SquaredDistanceToTriangle(best, p);
  const auto consider = [&](std::int32_t t)
  {
    const double d = t < triangles ? this->SquaredDistanceToTriangle(t, p) : HUGE_VAL;
    if (d < bestDistance)
    {
      best = t;
      bestDistance = d;
    }
  };
  const std::size_t changes = this->Serial.Inserted + this->Removals;
  if (this->Hints.Stale(changes))
  {
    this->Hints.Build(this->Origins.data(), this->Origins.size(), this->Coordinates, changes);
  }
  std::int32_t near[3];
  const int hints = this->Hints.Near(p, near);
  for (int k = 0; k < hints; ++k)
  {
    consider(near[k]);
  }
  // A stream sorted along one axis whose points do not pass the side of the box of those before
  // (ties: rows of rounded coordinates) comes back beside one of the last few points, though far
  // from the very last and beyond the index, built before them.
  for (const std::int32_t t : this->RecentStarts)
  {
    consider(t);
  }
  const int samples = hints > 0 ? 0 : this->JumpSamples(triangles);
  for (int k = 0; k < samples; ++k)
  {
    consider(this->NextJumpSample(triangles));
  }
  this->UpdateJumpMode(best != this->Serial.LastTriangle);
  this->Serial.LastTriangle = best;
}

// Off turns to Probe once an unhinted walk ran 2 cube roots of the triangles or more; whether to
// jump.
bool DirichletTessellation::JumpWanted(std::int32_t triangles)
{
  // (walk >= 2 cbrt(triangles), cubed: most insertions stop here, and need no root)
  const double walk = double(this->UnhintedWalk);
  if (this->JumpMode == Jumping::Off && triangles >= 64 && walk * walk * walk >= 8.0 * triangles)
  {
    this->JumpMode = Jumping::Probe;
  }
  return this->JumpMode != Jumping::Off;
}

// The squared distance from p to the nearest vertex of triangle t (HUGE_VAL for a free triangle,
// whose origins are all Free).
double DirichletTessellation::SquaredDistanceToTriangle(std::int32_t t, const Point2& p) const
{
  double nearest = HUGE_VAL;
  for (std::int32_t k = 0; k < 3; ++k)
  {
    const std::int32_t v = this->Origins[3 * t + k];
    if (v >= 0)
    {
      const Point2& q = this->Coordinates[v];
      nearest = std::min(nearest, (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y));
    }
  }
  return nearest;
}

// Random triangles to sample where there is no index: a few while probing, then a quarter as
// many as the last unhinted walk's steps, from a cube root to a square root of the triangles.
int DirichletTessellation::JumpSamples(std::int32_t triangles) const
{
  constexpr int ProbeSamples = 16;
  if (this->JumpMode == Jumping::Probe)
  {
    return ProbeSamples;
  }
  const double fewest = std::cbrt(double(triangles)), most = std::sqrt(double(triangles));
  return int(std::clamp(double(this->UnhintedWalk) / 4.0, fewest, most));
}

// xorshift64: a fixed sequence, so that a stream gives the same walks every run.
std::int32_t DirichletTessellation::NextJumpSample(std::int32_t triangles)
{
  this->JumpState ^= this->JumpState << 13;
  this->JumpState ^= this->JumpState >> 7;
  this->JumpState ^= this->JumpState << 17;
  return std::int32_t(this->JumpState % std::uint64_t(triangles));
}

// On after a jump that found a nearer start; Off after a probe that did not, or after
// JumpMissesToStop jumps in a row that did not.
void DirichletTessellation::UpdateJumpMode(bool foundNearer)
{
  constexpr int JumpMissesToStop = 2;
  if (foundNearer)
  {
    this->JumpMode = Jumping::On;
    this->JumpMisses = 0;
  }
  else if (this->JumpMode == Jumping::Probe || ++this->JumpMisses >= JumpMissesToStop)
  {
    this->JumpMode = Jumping::Off;
  }
}

void DirichletTessellation::InsertAcceptedPoint(std::int32_t id)
{
  if (this->IsTwoDimensional())
  {
    this->InsertIntoTriangulation(id);
  }
  else
  {
    this->InsertCollinear(id);
  }
}

// ---------------------------------------------------------------------------------------------
// Collinear phase: the accepted points so far lie on one line; keep them sorted along it.

void DirichletTessellation::InsertCollinear(std::int32_t id)
{
  const std::vector<Point2>& pts = this->Coordinates;
  const Point2& p = pts[id];
  if (this->Collinear.size() >= 2 &&
    orient2d(pts[this->Collinear[0]], pts[this->Collinear[1]], p) != 0)
  {
    this->LeaveCollinearPhase(id);
    return;
  }
  if (this->BuildOrder && this->Collinear.size() >= 2)
  {
    // A batch appends, and SortCollinearBatch sorts once: finding each point's place and moving
    // the rest up was O(n) per point, 7.1 s for 10^6 points on a line (0.08 s at 10^5).
    // Collinear[0] and [1] stay the two distinct points that give the line.
    this->Collinear.push_back(id);
    this->CollinearUnsorted = true;
    ++this->Accepted;
    return;
  }
  auto at = std::lower_bound(this->Collinear.begin(),
    this->Collinear.end(),
    p,
    [&pts](std::int32_t k, const Point2& q) { return ComesFirst(pts[k], q); });
  if (at != this->Collinear.end() && pts[*at] == p)
  {
    this->RecordDuplicate(id, *at, -1);
    if (this->InputId(id) < this->InputId(*at))
    {
      *at = id;
    }
    return;
  }
  this->Collinear.insert(at, id);
  ++this->Accepted;
}

// Puts what a batch appended to Collinear in order along the line and reports exact copies as
// InsertCollinear does: of the copies of a place, the one with the smallest input id is kept,
// and pairs that named a dropped copy as kept name the kept one instead.
void DirichletTessellation::SortCollinearBatch()
{
  if (!this->CollinearUnsorted)
  {
    return;
  }
  this->CollinearUnsorted = false;
  const std::vector<Point2>& pts = this->Coordinates;
  std::sort(this->Collinear.begin(),
    this->Collinear.end(),
    [&](std::int32_t a, std::int32_t b) {
      return pts[a] == pts[b] ? this->InputId(a) < this->InputId(b) : ComesFirst(pts[a], pts[b]);
    });
  std::vector<std::pair<std::int32_t, std::int32_t>> dropped; // (copy, the one kept)
  std::size_t kept = 0;
  for (const std::int32_t v : this->Collinear)
  {
    if (kept > 0 && pts[this->Collinear[kept - 1]] == pts[v])
    {
      dropped.emplace_back(v, this->Collinear[kept - 1]);
      continue;
    }
    this->Collinear[kept++] = v;
  }
  this->Collinear.resize(kept);
  if (dropped.empty())
  {
    return;
  }
  std::sort(dropped.begin(), dropped.end());
  for (auto& pair : this->DuplicatePairs)
  {
    const auto it = std::lower_bound(
      dropped.begin(), dropped.end(), std::make_pair(pair.second, std::int32_t(INT32_MIN)));
    if (it != dropped.end() && it->first == pair.second)
    {
      pair.second = it->second;
    }
  }
  for (const auto& pair : dropped)
  {
    this->AddDuplicatePair(pair.first, pair.second);
  }
  this->Accepted -= dropped.size();
}

// The first point off the line: make a triangle of it and two neighbouring points of the line,
// close it with three ghost triangles, and insert the rest of the line as ordinary points (they lie
// on the triangle's edge line, outside it or on its edge, which the general insertion handles).
//
//            p
//           / \          ghosts: (b,a,G) below a-b, (p,b,G) right of b-p, (a,p,G) left of p-a
//          /   \ .
//         a-----b
void DirichletTessellation::LeaveCollinearPhase(std::int32_t id)
{
  this->SortCollinearBatch(); // a and b must be neighbours on the line
  const std::vector<Point2>& pts = this->Coordinates;
  std::int32_t a = this->Collinear[0];
  std::int32_t b = this->Collinear[1];
  if (orient2d(pts[a], pts[b], pts[id]) < 0)
  {
    std::swap(a, b);
  }
  const std::vector<std::int32_t> rest(this->Collinear.begin() + 2, this->Collinear.end());
  this->Collinear.clear();
  this->Collinear.shrink_to_fit();
  const std::int32_t t0 = this->NewTriangle();
  const std::int32_t g1 = this->NewTriangle();
  const std::int32_t g2 = this->NewTriangle();
  const std::int32_t g3 = this->NewTriangle();
  this->SetTriangle(t0, a, b, id, 3 * g1, 3 * g2, 3 * g3);
  this->SetTriangle(g1, b, a, Ghost, 3 * t0, 3 * g3 + 2, 3 * g2 + 1);
  this->SetTriangle(g2, id, b, Ghost, 3 * t0 + 1, 3 * g1 + 2, 3 * g3 + 1);
  this->SetTriangle(g3, a, id, Ghost, 3 * t0 + 2, 3 * g2 + 2, 3 * g1 + 1);
  this->Serial.LastTriangle = t0;
  ++this->Accepted;
  this->Accepted -= rest.size();
  for (const std::int32_t r : rest)
  {
    this->InsertIntoTriangulation(r);
  }
}

// ---------------------------------------------------------------------------------------------
// Triangulation phase.

void DirichletTessellation::InsertIntoTriangulation(std::int32_t id)
{
  std::int32_t edge = -1;
  if (this->InsertInRegion(this->Serial, id, edge) == Location::OnVertex)
  {
    this->RecordDuplicate(id, this->Origins[edge], edge);
    return;
  }
  ++this->Accepted;
}

// Inserts vertex id unless it is a copy of a vertex (OnVertex, edge leaves that vertex) or its
// insertion would change a triangle the region does not own (Foreign, nothing changed; edge, if
// set, is a half-edge of the triangle the region owns that holds id on its edge: id was found,
// but the triangle across that edge is another's or a ghost, a hull edge to split).
DirichletTessellation::Location DirichletTessellation::InsertInRegion(Region& region,
  std::int32_t id,
  std::int32_t& edge)
{
  const Location location = this->Locate(region, this->Coordinates[id], edge, &region.LastWalk);
  switch (location)
  {
    case Location::OnVertex:
      // The next walk starts at the copy's place: copies come in runs (a batch defers them all
      // to its end, along the curve), and each walked from the triangle made last before the run
      // (10^6 points, half of them copies: 300 steps a copy, 1.9 s).
      region.LastTriangle = edge / 3;
      return location;
    case Location::Foreign:
      return location;
    case Location::OnEdge:
      this->SplitEdge(region, edge, id);
      break;
    case Location::Inside:
    case Location::InGhost:
      this->SplitTriangle(region, edge / 3, id);
      break;
  }
  this->RestoreDelaunay(region);
  ++region.Inserted;
  if ((this->BuildOrder || this->TrackingCocircular) && !region.SawCocircular)
  {
    const std::int32_t start = 3 * region.LastTriangle + 2; // leaves id (see SplitTriangle)
    region.SawCocircular = this->Origins[start] != id || this->StarIsCocircular(start);
  }
  return location;
}

// Where the triangles are renumbered or made again, the jump index, the ring of recent starts and
// the sides' starts name other triangles: all are dropped (the ring back to its start, all
// triangle 0).
void DirichletTessellation::ForgetWalkStarts()
{
  this->Hints.Clear();
  this->RecentStarts.fill(0);
  this->NextRecentStart = 0;
  this->SideStarts.fill(SideStart{});
}

bool DirichletTessellation::IsGhostTriangle(std::int32_t t) const
{
  return this->Origins[3 * t] == Ghost || this->Origins[3 * t + 1] == Ghost ||
    this->Origins[3 * t + 2] == Ghost;
}

namespace
{

// Writes the walk's length (steps) to *Kept, if any, when Locate returns, whichever return it is.
struct KeepWalkLength
{
  const std::int64_t& Steps;
  std::int64_t* Kept;
  ~KeepWalkLength()
  {
    if (this->Kept)
    {
      *this->Kept = this->Steps;
    }
  }
};

} // namespace

// Visibility walk from the region's last triangle (made last, or where a hint, a jump or a side's
// start put it: see InsertKnownPoint): cross any edge that has p strictly on
// its far side. In a Delaunay triangulation this walk cannot cycle. Reaching a ghost triangle means
// p is strictly outside the hull edge just crossed. The walk stays in triangles the region owns:
// it enters a triangle across an edge it owns, so only the apex needs checking, and it reads no
// other triangle (in a two-region build another thread may be writing those).
DirichletTessellation::Location DirichletTessellation::Locate(const Region& region,
  const Point2& p,
  std::int32_t& edge,
  std::int64_t* walked) const
{
  const Point2* const pts = this->Coordinates.data();
  const std::int32_t* const org = this->Origins.data();
  const std::int32_t* const twin = this->Twins.data();
  // The walk tests real triangles only: a ghost start gives way to the real triangle across its
  // hull edge, unless p is strictly beyond that edge (as StartBesideExtreme finds it), and so
  // outside the hull, there.
  std::int32_t t = region.LastTriangle;
  if (this->IsGhostTriangle(t))
  {
    const std::int32_t f = this->HullEdgeOfGhost(t);
    if (f >= 0)
    {
      if (region.GrowsHull() && Orient(pts[org[f]], pts[org[Next(f)]], p) > 0)
      {
        edge = f;
        if (walked)
        {
          *walked = 0;
        }
        return Location::InGhost;
      }
      t = twin[f] / 3;
    }
  }
  // The edge of t the walk came through (p is strictly beyond it, seen from the triangle left),
  // as 0, 1, 2, or 3 at the start. The other two edges are tested in turn starting after it.
  static constexpr std::int32_t NextIndex[4] = { 1, 2, 0, 0 };
  int sides[3] = { 1, 1, 1 };
  std::int32_t crossed = -1;
  if (!this->TestFirstTriangle(region, t, p, sides, crossed))
  {
    return Location::Foreign;
  }
  // Then each triangle is entered through one edge and has two left to test. Both are evaluated
  // and the edge to cross is selected without a branch on the (unpredictable) side signs; only
  // the end of the walk is a branch.
  std::int64_t steps = 0;
  // (an insertion keeps its walk's length, at whichever return ends it; a query, const, does not)
  const KeepWalkLength keep{ steps, walked };
  while (crossed >= 0)
  {
    const std::int32_t f = twin[crossed];
    const std::int32_t tf = f / 3;
    const std::int32_t base = 3 * tf;
    const std::int32_t entered = f - base;
    const std::int32_t k1 = NextIndex[entered], k2 = NextIndex[k1];
    const std::int32_t apex = org[base + k2];
    if (apex == Ghost)
    {
      if (!region.GrowsHull())
      {
        return Location::Foreign; // (edge untouched: see InsertInRegion)
      }
      edge = f;
      return Location::InGhost;
    }
    const Point2& c = pts[apex];
    if (!region.Owns(c) || ++steps > region.MaxWalk)
    {
      return Location::Foreign;
    }
    t = tf;
    const Point2& a = pts[org[base + entered]];
    const Point2& b = pts[org[base + k1]];
    const int s1 = Orient(b, c, p);
    const int s2 = Orient(c, a, p);
    const bool cross1 = s1 < 0;
    crossed = cross1 ? base + k1 : base + k2;
    if (!cross1 && s2 >= 0)
    {
      sides[entered] = 1;
      sides[k1] = s1;
      sides[k2] = s2;
      break;
    }
  }
  return this->WhereInTriangle(region, t, p, sides, edge);
}

// The half-edge of ghost triangle t on the hull (between its two real vertices; p is strictly
// beyond that hull edge when Orient(its origin, its end, p) > 0); -1 for a free triangle.
std::int32_t DirichletTessellation::HullEdgeOfGhost(std::int32_t t) const
{
  const std::int32_t* const org = this->Origins.data();
  for (std::int32_t k = 0; k < 3; ++k)
  {
    const std::int32_t e = 3 * t + k;
    if (org[e] >= 0 && org[Next(e)] >= 0)
    {
      return e;
    }
  }
  return -1;
}

// The walk's first triangle: all three edges tested, in order, until p is strictly beyond one
// (crossed; -1 when none is); false when the region does not own t.
[[gnu::always_inline]] inline bool DirichletTessellation::TestFirstTriangle(const Region& region,
  std::int32_t t,
  const Point2& p,
  int* sides,
  std::int32_t& crossed) const
{
  const Point2* const pts = this->Coordinates.data();
  const std::int32_t* const org = this->Origins.data();
  const std::int32_t base = 3 * t;
  if (!region.Owns(pts[org[base]]) || !region.Owns(pts[org[base + 1]]) ||
    !region.Owns(pts[org[base + 2]]))
  {
    return false;
  }
  const Point2& a = pts[org[base]];
  const Point2& b = pts[org[base + 1]];
  const Point2& c = pts[org[base + 2]];
  sides[0] = Orient(a, b, p);
  if (sides[0] < 0)
  {
    crossed = base;
    return true;
  }
  sides[1] = Orient(b, c, p);
  if (sides[1] < 0)
  {
    crossed = base + 1;
    return true;
  }
  sides[2] = Orient(c, a, p);
  if (sides[2] < 0)
  {
    crossed = base + 2;
  }
  return true;
}

// Where p lies in triangle t, which the walk ended in (sides: p's side of each edge, none
// negative): strictly inside, on a vertex, or on an edge (Foreign when splitting that edge would
// split a triangle across it that the region does not own).
[[gnu::always_inline]] inline DirichletTessellation::Location
DirichletTessellation::WhereInTriangle(const Region& region,
  std::int32_t t,
  const Point2& p,
  const int* sides,
  std::int32_t& edge) const
{
  const Point2* const pts = this->Coordinates.data();
  const std::int32_t* const org = this->Origins.data();
  const std::int32_t base = 3 * t;
  if (sides[0] != 0 && sides[1] != 0 && sides[2] != 0)
  {
    edge = base;
    return Location::Inside;
  }
  for (std::int32_t k = 0; k < 3; ++k)
  {
    if (pts[org[base + k]] == p)
    {
      edge = base + k;
      return Location::OnVertex;
    }
  }
  for (std::int32_t k = 0; k < 3; ++k)
  {
    if (sides[k] == 0)
    {
      // Splitting the edge also splits the triangle across it.
      edge = base + k;
      const std::int32_t across = org[Prev(this->Twins[edge])];
      return (across == Ghost ? region.GrowsHull() : region.Owns(pts[across])) ? Location::OnEdge
                                                                               : Location::Foreign;
    }
  }
  edge = base;
  return Location::Inside;
}

std::int32_t DirichletTessellation::NewTriangle()
{
  ++this->ScatteredTriangles;
  if (!this->FreeTriangles.empty())
  {
    const std::int32_t t = this->FreeTriangles.back();
    this->FreeTriangles.pop_back();
    return t;
  }
  const std::int32_t t = std::int32_t(this->Origins.size() / 3);
  for (int k = 0; k < 3; ++k)
  {
    this->Origins.push_back(Free);
    this->Twins.push_back(-1);
  }
  return t;
}

void DirichletTessellation::SetTriangle(std::int32_t t,
  std::int32_t a,
  std::int32_t b,
  std::int32_t c,
  std::int32_t ta,
  std::int32_t tb,
  std::int32_t tc)
{
  const std::int32_t e = 3 * t;
  this->Origins[e] = a;
  this->Origins[e + 1] = b;
  this->Origins[e + 2] = c;
  this->Twins[e] = ta;
  this->Twins[e + 1] = tb;
  this->Twins[e + 2] = tc;
  if (!this->VertexEdges.empty())
  {
    // Each vertex of the new triangle now has a half-edge known to leave it.
    for (std::int32_t k = 0; k < 3; ++k)
    {
      if (this->Origins[e + k] >= 0)
      {
        this->VertexEdges[this->Origins[e + k]] = e + k;
      }
    }
  }
  if (ta >= 0)
  {
    this->Twins[ta] = e;
  }
  if (tb >= 0)
  {
    this->Twins[tb] = e + 1;
  }
  if (tc >= 0)
  {
    this->Twins[tc] = e + 2;
  }
}

// Every new triangle gets the new point p as its third vertex, so the edge to check against the
// empty-circle property is always its first half-edge; the flip stack holds triangle ids.
//
//          z                       z
//         / \                     /|\ .
//        /   \        ->         / p \ .
//       x-----y                 x-----y
void DirichletTessellation::SplitTriangle(Region& region, std::int32_t t, std::int32_t p)
{
  const std::int32_t t1 = this->NewTriangle(region);
  const std::int32_t t2 = this->NewTriangle(region);
  std::int32_t* const org = this->Origins.data();
  std::int32_t* const twin = this->Twins.data();
  const std::int32_t e = 3 * t, e1 = 3 * t1, e2 = 3 * t2;
  const std::int32_t y = org[e + 1], z = org[e + 2];
  const std::int32_t ty = twin[e + 1], tz = twin[e + 2];
  __builtin_prefetch(&org[twin[e]]);
  __builtin_prefetch(&org[ty]);
  __builtin_prefetch(&org[tz]);
  // t keeps x -> y and its twin.
  org[e + 2] = p;
  twin[e + 1] = e1 + 2;
  twin[e + 2] = e2 + 1;
  org[e1] = y;
  org[e1 + 1] = z;
  org[e1 + 2] = p;
  twin[e1] = ty;
  twin[e1 + 1] = e2 + 2;
  twin[e1 + 2] = e + 1;
  twin[ty] = e1;
  org[e2] = z;
  org[e2 + 1] = org[e];
  org[e2 + 2] = p;
  twin[e2] = tz;
  twin[e2 + 1] = e + 2;
  twin[e2 + 2] = e1 + 1;
  twin[tz] = e2;
  if (!this->VertexEdges.empty())
  {
    // x and y keep their half-edges e and e + 1; z's may have been e + 2, now p's.
    if (z >= 0)
    {
      this->VertexEdges[z] = e2;
    }
    this->VertexEdges[p] = e + 2;
  }
  region.FlipStack.push_back(t);
  region.FlipStack.push_back(t1);
  region.FlipStack.push_back(t2);
  region.LastTriangle = t;
}

// p lies strictly inside edge x->y (half-edge e); the far side may be a ghost (w = Ghost).
//
//          z                       z
//         / \                     /|\ .
//        x---y        ->         x-p-y
//         \ /                     \|/
//          w                       w
void DirichletTessellation::SplitEdge(Region& region, std::int32_t e, std::int32_t p)
{
  const std::int32_t f = this->Twins[e];
  const std::int32_t x = this->Origins[e], y = this->Origins[Next(e)], z = this->Origins[Prev(e)];
  const std::int32_t w = this->Origins[Prev(f)];
  const std::int32_t oyz = this->Twins[Next(e)], ozx = this->Twins[Prev(e)];
  const std::int32_t oxw = this->Twins[Next(f)], owy = this->Twins[Prev(f)];
  const std::int32_t ta = e / 3, tb = f / 3;
  const std::int32_t tc = this->NewTriangle(region);
  const std::int32_t td = this->NewTriangle(region);
  this->SetTriangle(ta, y, z, p, oyz, 3 * tb + 2, 3 * td + 1);
  this->SetTriangle(tb, z, x, p, ozx, 3 * tc + 2, 3 * ta + 1);
  this->SetTriangle(tc, x, w, p, oxw, 3 * td + 2, 3 * tb + 1);
  this->SetTriangle(td, w, y, p, owy, 3 * ta + 2, 3 * tc + 1);
  region.FlipStack.push_back(ta);
  region.FlipStack.push_back(tb);
  region.FlipStack.push_back(tc);
  region.FlipStack.push_back(td);
  region.LastTriangle = ta;
}

// For LegalizeEdges (two_region_build.cpp); RestoreDelaunay calls DelaunayEdgeTest inlined.
int DirichletTessellation::EdgeTest(std::int32_t x,
  std::int32_t y,
  std::int32_t p,
  std::int32_t q) const
{
  return DelaunayEdgeTest(this->Coordinates.data(), x, y, p, q);
}

// Pops the flip stack: each triangle t = (x, y, p) has the new point p third; its first edge
// x -> y is flipped when p lies strictly inside the circle of the triangle (y, x, q) across it
// (for a ghost triangle the "circle" is the open half-plane beyond its hull edge). Both results
// keep p third, so both are checked again. An edge whose far triangle the region does not own is
// left as it is (two_region_build.cpp legalizes those edges afterwards).
//
//          p                       p
//         / \                     /|\ .
//        x---y        ->         x | y
//         \ /                     \|/
//          q                       q
void DirichletTessellation::RestoreDelaunay(Region& region)
{
  std::int32_t* const org = this->Origins.data();
  std::int32_t* const twin = this->Twins.data();
  const Point2* const pts = this->Coordinates.data();
  // Null in a batch build, which does not keep vertex half-edges.
  std::int32_t* const vertexEdge = this->VertexEdges.empty() ? nullptr : this->VertexEdges.data();
  std::vector<std::int32_t>& stack = region.FlipStack;
  bool cocircular = false;
  while (!stack.empty())
  {
    const std::int32_t t = stack.back();
    stack.pop_back();
    const std::int32_t e = 3 * t;
    const std::int32_t f = twin[e];
    const std::int32_t t2 = f / 3;
    const std::int32_t g = 3 * t2;
    // f's position in t2 and the half-edges after and before it.
    const std::int32_t nf = f == g + 2 ? g : f + 1;
    const std::int32_t pf = f == g ? g + 2 : f - 1;
    const std::int32_t q = org[pf];
    if (q == Ghost)
    {
      continue; // e is a hull edge seen from inside: p is on the inner side
    }
    if (!region.Owns(pts[q]))
    {
      continue;
    }
    const std::int32_t x = org[e], y = org[e + 1], p = org[e + 2];
    const int test = DelaunayEdgeTest(pts, x, y, p, q);
    cocircular |= test == 0;
    const bool conflict = test > 0;
    if (!conflict)
    {
      continue;
    }
    const std::int32_t oxq = twin[nf], oqy = twin[pf];
    const std::int32_t oyp = twin[e + 1];
    // t = (x, q, p); its last edge p -> x keeps its twin.
    org[e + 1] = q;
    twin[e] = oxq;
    twin[oxq] = e;
    twin[e + 1] = g + 2;
    // t2 = (q, y, p).
    org[g] = q;
    org[g + 1] = y;
    org[g + 2] = p;
    twin[g] = oqy;
    twin[oqy] = g;
    twin[g + 1] = oyp;
    twin[oyp] = g + 1;
    twin[g + 2] = e + 1;
    if (vertexEdge)
    {
      // The half-edges whose origin changed are e + 1, g, g + 1 and g + 2: x, q and y may have
      // had theirs among them (p keeps e + 2).
      if (x >= 0)
      {
        vertexEdge[x] = e;
      }
      if (y >= 0)
      {
        vertexEdge[y] = g + 1;
      }
      vertexEdge[q] = e + 1;
    }
    // The next checks read the triangles across x -> q and q -> y: start loading them.
    __builtin_prefetch(&org[oxq]);
    __builtin_prefetch(&org[oqy]);
    stack.push_back(t);
    stack.push_back(t2);
  }
  region.SawCocircular |= cocircular;
}

// ---------------------------------------------------------------------------------------------
// Duplicates: the smallest id among exact copies is the one kept, whatever the insertion order.

void DirichletTessellation::RecordDuplicate(std::int32_t id,
  std::int32_t kept,
  std::int32_t keptEdge)
{
  if (this->InputId(id) > this->InputId(kept))
  {
    this->AddDuplicatePair(id, kept);
    return;
  }
  if (keptEdge >= 0)
  {
    this->Relabel(keptEdge, id);
  }
  if (!this->BuildOrder)
  {
    // Streaming: the place's other copies name it, not kept, so they follow by themselves.
    this->Places.GiveWay(kept, id);
    this->StatusBytes[kept] = std::uint8_t(PointStatus::Duplicate);
    this->StatusBytes[id] = std::uint8_t(PointStatus::Accepted) | HasDuplicates;
    return;
  }
  // The pairs naming kept are repointed once, at the end: scanning them all here made a batch
  // with many copies quadratic (10^6 points, half of them copies: 12.8 s).
  this->DuplicateChains = true;
  this->AddDuplicatePair(kept, id);
}

// Each pair's kept point is followed through the pairs to the copy that is kept now (a chain of
// ids, each with a smaller input id than the one before: no cycle), compressing the paths.
void DirichletTessellation::ResolveDuplicateChains()
{
  if (!this->DuplicateChains)
  {
    return;
  }
  this->DuplicateChains = false;
  std::vector<std::int32_t> keptOf(this->Coordinates.size(), -1);
  for (const auto& pair : this->DuplicatePairs)
  {
    keptOf[pair.first] = pair.second;
  }
  for (auto& pair : this->DuplicatePairs)
  {
    std::int32_t root = pair.second;
    while (keptOf[root] >= 0)
    {
      root = keptOf[root];
    }
    for (std::int32_t v = pair.second; keptOf[v] >= 0;)
    {
      const std::int32_t next = keptOf[v];
      keptOf[v] = root;
      v = next;
    }
    pair.second = root;
  }
}

// During BuildFrom the ids are local and the pairs are sorted at its end; otherwise (streaming:
// Insert and Reinsert have made the status bytes) the copy joins its place.
void DirichletTessellation::AddDuplicatePair(std::int32_t duplicate, std::int32_t kept)
{
  if (this->BuildOrder)
  {
    this->DuplicatePairs.emplace_back(duplicate, kept);
    return;
  }
  this->Places.AddCopy(duplicate, kept);
  this->StatusBytes[duplicate] = std::uint8_t(PointStatus::Duplicate);
  this->StatusBytes[kept] = std::uint8_t(PointStatus::Accepted) | HasDuplicates;
}

void DirichletTessellation::Relabel(std::int32_t edge, std::int32_t newId)
{
  if (!this->VertexEdges.empty())
  {
    // The old id is no vertex now: its entry would name a half-edge that leaves newId (and,
    // once that triangle is freed and the triangles ordered, a slot past the arrays' end).
    this->VertexEdges[this->Origins[edge]] = -1;
    this->VertexEdges[newId] = edge;
  }
  std::int32_t e = edge;
  do
  {
    this->Origins[e] = newId;
    e = this->RingNext(e);
  } while (e != edge);
}

// ---------------------------------------------------------------------------------------------
// Status queries.

PointStatus DirichletTessellation::Status(std::int32_t id) const
{
  if (id < 0 || std::size_t(id) >= this->Coordinates.size())
  {
    throw InputError("point id " + std::to_string(id) + " is out of range");
  }
  if (this->HasStatusBytes())
  {
    return PointStatus(this->StatusBytes[id] & StatusMask);
  }
  // A batch build only (no Insert or Remove yet): nothing is removed, and Rejected and
  // DuplicatePairs are sorted.
  if (std::binary_search(this->Rejected.begin(), this->Rejected.end(), id))
  {
    return PointStatus::OutsideWindow;
  }
  if (this->FindDuplicatePair(id) != this->DuplicatePairs.end())
  {
    return PointStatus::Duplicate;
  }
  return PointStatus::Accepted;
}

std::int32_t DirichletTessellation::DuplicateOf(std::int32_t id) const
{
  if (this->HasStatusBytes())
  {
    return this->Places.KeptOf(id); // (-1 for an id no place holds as a copy: out of range too)
  }
  const auto it = this->FindDuplicatePair(id);
  return it != this->DuplicatePairs.end() ? it->second : -1;
}

std::vector<std::pair<std::int32_t, std::int32_t>>::const_iterator
DirichletTessellation::FindDuplicatePair(std::int32_t id) const
{
  const auto it = std::lower_bound(this->DuplicatePairs.begin(),
    this->DuplicatePairs.end(),
    id,
    [](const std::pair<std::int32_t, std::int32_t>& pair, std::int32_t key)
    { return pair.first < key; });
  return it != this->DuplicatePairs.end() && it->first == id ? it : this->DuplicatePairs.end();
}

// The per-id arrays are built on first need from the lists (O(N) once): a batch build that is
// only queried never holds them, which keeps it at 64 bytes per point.
void DirichletTessellation::EnableStatusBytes()
{
  if (!this->HasStatusBytes())
  {
    this->RecomputeStatusBytes();
  }
}

// From a batch build's lists (before is empty), or after a rebuild (before holds the status
// bytes of every id, which tell the live entries of Rejected apart, and removed points, known by
// their bytes alone, keep theirs). Either way the pairs the build found join the places.
void DirichletTessellation::RecomputeStatusBytes()
{
  std::vector<std::uint8_t> before;
  before.swap(this->StatusBytes);
  if (before.size() == this->Coordinates.size())
  {
    this->CompactRejected(before);
  }
  else
  {
    this->RejectedLive = this->Rejected.size();
  }
  for (const auto& pair : this->DuplicatePairs)
  {
    this->Places.AddCopy(pair.first, pair.second);
  }
  this->DuplicatePairs.clear();
  this->DuplicatePairs.shrink_to_fit();
  this->StatusBytes.assign(this->Coordinates.size(), std::uint8_t(PointStatus::Accepted));
  for (std::size_t id = 0; id < before.size() && id < this->StatusBytes.size(); ++id)
  {
    if ((before[id] & StatusMask) == std::uint8_t(PointStatus::Removed))
    {
      this->StatusBytes[id] = std::uint8_t(PointStatus::Removed);
    }
  }
  for (const std::int32_t id : this->Rejected)
  {
    this->StatusBytes[id] = std::uint8_t(PointStatus::OutsideWindow);
  }
  this->Places.ForEachPair(
    [this](std::int32_t copy, std::int32_t kept)
    {
      this->StatusBytes[copy] = std::uint8_t(PointStatus::Duplicate);
      this->StatusBytes[kept] = std::uint8_t(PointStatus::Accepted) | HasDuplicates;
    });
}

// Keeps the entries of Rejected whose status is still OutsideWindow, once each, ascending.
void DirichletTessellation::CompactRejected(const std::vector<std::uint8_t>& status)
{
  const auto stale = [&status](std::int32_t id)
  { return (status[id] & StatusMask) != std::uint8_t(PointStatus::OutsideWindow); };
  this->Rejected.erase(
    std::remove_if(this->Rejected.begin(), this->Rejected.end(), stale), this->Rejected.end());
  std::sort(this->Rejected.begin(), this->Rejected.end());
  this->Rejected.erase(
    std::unique(this->Rejected.begin(), this->Rejected.end()), this->Rejected.end());
  this->RejectedLive = this->Rejected.size();
}

void DirichletTessellation::EnableVertexEdges()
{
  if (!this->VertexEdgesOn)
  {
    this->RecomputeVertexEdges();
    this->VertexEdgesOn = true; // (from the first point on, when there is none yet)
  }
}

void DirichletTessellation::RecomputeVertexEdges()
{
  this->VertexEdges.assign(this->Coordinates.size(), -1);
  for (std::size_t e = 0; e < this->Origins.size(); ++e)
  {
    if (this->Origins[e] >= 0)
    {
      this->VertexEdges[this->Origins[e]] = std::int32_t(e);
    }
  }
}

std::vector<std::int32_t> DirichletTessellation::RejectedIds() const
{
  if (!this->HasStatusBytes())
  {
    return this->Rejected; // a batch build's, ascending
  }
  std::vector<std::int32_t> ids;
  ids.reserve(this->RejectedLive);
  for (const std::int32_t id : this->Rejected)
  {
    if ((this->StatusBytes[id] & StatusMask) == std::uint8_t(PointStatus::OutsideWindow))
    {
      ids.push_back(id);
    }
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

std::vector<std::pair<std::int32_t, std::int32_t>> DirichletTessellation::Duplicates() const
{
  return this->HasStatusBytes() ? this->Places.Pairs() : this->DuplicatePairs;
}

// Removed points are known by their status bytes alone (Remove makes them, and they stay in step
// with the coordinates from then on, through rebuilds too): no list to keep, which Reinsert
// would have to search.
std::vector<std::int32_t> DirichletTessellation::RemovedIds() const
{
  std::vector<std::int32_t> ids;
  for (std::size_t id = 0; id < this->StatusBytes.size(); ++id)
  {
    if ((this->StatusBytes[id] & StatusMask) == std::uint8_t(PointStatus::Removed))
    {
      ids.push_back(std::int32_t(id));
    }
  }
  return ids;
}

std::size_t DirichletTessellation::StructureBytes() const
{
  return this->Coordinates.capacity() * sizeof(Point2) +
    (this->Origins.capacity() + this->Twins.capacity() + this->FreeTriangles.capacity() +
      this->Collinear.capacity() + this->Rejected.capacity() + this->Serial.FlipStack.capacity() +
      this->VertexEdges.capacity()) *
    sizeof(std::int32_t) +
    this->StatusBytes.capacity() +
    this->DuplicatePairs.capacity() * sizeof(std::pair<std::int32_t, std::int32_t>) +
    this->Places.Bytes() +
    (this->Ordering.First.capacity() + this->Ordering.NewIndex.capacity() +
      this->Ordering.Origins.capacity() + this->Ordering.Twins.capacity()) *
    sizeof(std::int32_t) +
    this->Hints.Bytes();
}

// ---------------------------------------------------------------------------------------------
// Removal.

std::int32_t DirichletTessellation::FindVertexEdge(std::int32_t id) const
{
  // VertexEdges is kept exact; the check costs one load and keeps the walk as a safety net.
  if (!this->VertexEdges.empty())
  {
    const std::int32_t e = this->VertexEdges[id];
    if (e >= 0 && std::size_t(e) < this->Origins.size() && this->Origins[e] == id)
    {
      return e;
    }
  }
  std::int32_t edge = -1;
  if (this->Locate(this->Serial, this->Coordinates[id], edge) == Location::OnVertex &&
    this->Origins[edge] == id)
  {
    return edge;
  }
  return -1;
}

std::int32_t DirichletTessellation::EdgeLeaving(std::int32_t id) const
{
  if (id < 0 || std::size_t(id) >= this->Coordinates.size() || !this->IsTwoDimensional())
  {
    return -1;
  }
  if (!this->VertexEdges.empty())
  {
    const std::int32_t e = this->VertexEdges[id];
    return e >= 0 && std::size_t(e) < this->Origins.size() && this->Origins[e] == id ? e : -1;
  }
  return this->Status(id) == PointStatus::Accepted ? this->FindVertexEdge(id) : -1;
}

void DirichletTessellation::Prefetch(const std::int32_t* ids, std::size_t count) const
{
  const std::size_t n = this->Coordinates.size();
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::size_t id = std::size_t(ids[k]); // (a negative id wraps round to out of range)
    if (id < n)
    {
      __builtin_prefetch(&this->Coordinates[id]);
      if (id < this->StatusBytes.size())
      {
        __builtin_prefetch(&this->StatusBytes[id]);
      }
      if (id < this->VertexEdges.size())
      {
        __builtin_prefetch(&this->VertexEdges[id]);
      }
    }
  }
  // The edges' triangles, once their edges are on their way (independent loads, which overlap).
  for (std::size_t k = 0; k < count && !this->VertexEdges.empty(); ++k)
  {
    const std::size_t id = std::size_t(ids[k]);
    const std::int32_t e = id < this->VertexEdges.size() ? this->VertexEdges[id] : -1;
    if (e >= 0 && std::size_t(e) < this->Origins.size())
    {
      __builtin_prefetch(&this->Origins[std::size_t(e - e % 3)]);
      __builtin_prefetch(&this->Twins[std::size_t(e - e % 3)]);
    }
  }
}

void DirichletTessellation::AppendNeighbours(std::int32_t id, std::vector<std::int32_t>& out) const
{
  const std::int32_t first = this->EdgeLeaving(id);
  if (first < 0)
  {
    return;
  }
  std::int32_t e = first;
  do
  {
    const std::int32_t j = this->Origins[Next(e)];
    if (j != Ghost)
    {
      out.push_back(j);
    }
    e = this->RingNext(e);
  } while (e != first);
}

void DirichletTessellation::Remove(std::int32_t id)
{
  const PointStatus status = this->Status(id); // throws for an out-of-range id
  if (status == PointStatus::Removed)
  {
    throw InputError("point " + std::to_string(id) + " is already removed");
  }
  this->EnableStatusBytes();
  this->EnableVertexEdges();
  const std::uint8_t flags = this->StatusBytes[id];
  this->StatusBytes[id] = std::uint8_t(PointStatus::Removed);
  if (status == PointStatus::OutsideWindow)
  {
    this->ForgetRejected();
    return;
  }
  if (status == PointStatus::Duplicate)
  {
    // The copied point keeps its HasDuplicates mark (a hint; see StatusMask).
    this->Places.RemoveCopy(id);
    return;
  }
  std::int32_t edge = -1;
  std::vector<std::int32_t>::iterator onLine = this->Collinear.end();
  if (this->IsTwoDimensional())
  {
    edge = this->FindVertexEdge(id);
    if (edge < 0)
    {
      throw std::logic_error("accepted point not found in the triangulation");
    }
  }
  else
  {
    onLine = std::find(this->Collinear.begin(), this->Collinear.end(), id);
  }
  this->VertexEdges[id] = -1;
  if (!this->PassToHeir(id, flags, edge, onLine))
  {
    this->RemoveVertex(id, edge, onLine);
  }
}

// A rejected point removed: the list of rejected points is compacted once most are removed.
void DirichletTessellation::ForgetRejected()
{
  --this->RejectedLive;
  if (this->Rejected.size() > 2 * this->RejectedLive + 64)
  {
    this->CompactRejected(this->StatusBytes);
  }
}

// A duplicate of the removed point takes its place, when it has one: the structure does not
// change (the vertex at edge, or the line's entry onLine, is relabelled). Whether one did.
bool DirichletTessellation::PassToHeir(std::int32_t id,
  std::uint8_t flags,
  std::int32_t edge,
  std::vector<std::int32_t>::iterator onLine)
{
  bool copied = false;
  const std::int32_t heir = (flags & HasDuplicates) ? this->Places.PromoteHeir(id, copied) : -1;
  if (heir < 0)
  {
    return false;
  }
  this->StatusBytes[heir] = std::uint8_t(PointStatus::Accepted) | (copied ? HasDuplicates : 0);
  if (edge >= 0)
  {
    this->Relabel(edge, heir);
  }
  else
  {
    *onLine = heir;
  }
  return true;
}

// The accepted point id leaves the structure: off the line, or out of the triangulation in place
// (an interior or a hull vertex), else by a rebuild.
void DirichletTessellation::RemoveVertex(std::int32_t id,
  std::int32_t edge,
  std::vector<std::int32_t>::iterator onLine)
{
  --this->Accepted;
  if (edge < 0) // (on the line: Remove found no edge in a collinear set)
  {
    this->Collinear.erase(onLine);
    this->AcceptedBox = this->BoxOfCollinearPoints();
    return;
  }
  ++this->Removals;
  // Remove's other paths (a rejected point, a duplicate, an heir) change no triangle and keep the
  // co-circularity flag; an in-place removal tests its new triangles against their neighbours
  // (AnyCocircularNeighbour); a rebuild sets the flag afresh.
  this->BeginTrackedChange();
  const bool inPlace = this->RemoveInteriorVertex(edge) || this->RemoveHullVertex(edge);
  this->EndTrackedChange();
  if (!inPlace)
  {
    this->RebuildWithout(id);
  }
}

// Known free of co-circular triangles before a change to the triangles: still so after it if the
// tests it makes (SawCocircular) meet no zero. Unknown (false) while it runs, so also if it throws.
void DirichletTessellation::BeginTrackedChange()
{
  this->TrackingCocircular = this->NoCocircularTriangles;
  this->NoCocircularTriangles = false;
  this->Serial.SawCocircular = false;
}

void DirichletTessellation::EndTrackedChange()
{
  this->NoCocircularTriangles = this->TrackingCocircular && !this->Serial.SawCocircular;
  this->TrackingCocircular = false;
}

// Whether a real triangle among the given ones is exactly co-circular with a real triangle
// across one of its edges: after a removal, the pairs that involve a new triangle are exactly
// these (the others are unchanged).
bool DirichletTessellation::AnyCocircularNeighbour(const std::int32_t* triangles,
  std::size_t count) const
{
  const Point2* const pts = this->Coordinates.data();
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::int32_t t = triangles[k];
    const std::int32_t a = this->Origins[3 * t], b = this->Origins[3 * t + 1],
                       c = this->Origins[3 * t + 2];
    if (a < 0 || b < 0 || c < 0)
    {
      continue;
    }
    for (std::int32_t side = 0; side < 3; ++side)
    {
      const std::int32_t d = this->Origins[Prev(this->Twins[3 * t + side])];
      if (d >= 0 && incircle_fast(pts[a], pts[b], pts[c], pts[d]) == 0)
      {
        return true;
      }
    }
  }
  return false;
}

// Triangulates the anticlockwise polygon ring (outer[i]: twin of the edge ring[i] -> ring[i+1])
// by cutting Delaunay ears (Devillers 1999): an ear (a, b, c) that turns left and whose circle
// contains no other polygon vertex is a triangle of the Delaunay triangulation of the points
// without the removed vertex. The k-th triangle of the plan goes to slots[first + k]. Returns
// false (plan unusable) only if no ear is found, which cannot happen with exact predicates.
bool DirichletTessellation::CutDelaunayEars(std::vector<std::int32_t>& ring,
  std::vector<std::int32_t>& outer,
  const std::vector<std::int32_t>& slots,
  std::size_t first,
  std::vector<Ear>& plan) const
{
  std::size_t used = first;
  // The scan goes round the ring from where it last cut, one step back: a cut changes only the
  // ears at its two ends (and can make others empty, which the scan meets on its way round).
  // Restarting at 0 after every cut, as this once did, made a vertex of degree d cost O(d^3):
  // the centre of 8000 points on an ellipse took 26 s to remove.
  std::size_t i = 0;
  std::size_t failed = 0; // candidates in a row that were no ear
  while (ring.size() > 3)
  {
    const std::size_t n = ring.size();
    if (failed >= n)
    {
      return false; // once round without an ear
    }
    i %= n;
    const std::size_t b = (i + 1) % n, c = (i + 2) % n;
    if (!this->IsDelaunayEar(ring, i, b, c))
    {
      ++i;
      ++failed;
      continue;
    }
    const std::int32_t t = slots[used++];
    plan.push_back({ ring[i], ring[b], ring[c], outer[i], outer[b], -1 });
    outer[i] = 3 * t + 2; // the new edge ring[i] -> ring[c] faces this triangle's c -> a
    ring.erase(ring.begin() + std::ptrdiff_t(b));
    outer.erase(outer.begin() + std::ptrdiff_t(b));
    // b's removal shifted the entries after it down by one; i's own entry moved if b was 0.
    i = b == 0 ? i - 1 : i;
    i = i == 0 ? ring.size() - 1 : i - 1;
    failed = 0;
  }
  plan.push_back({ ring[0], ring[1], ring[2], outer[0], outer[1], outer[2] });
  return true;
}

// Whether ring[i], ring[b], ring[c] (consecutive) turn left and no other ring vertex lies strictly
// inside their circle: an ear of the Delaunay triangulation without the removed vertex.
bool DirichletTessellation::IsDelaunayEar(const std::vector<std::int32_t>& ring,
  std::size_t i,
  std::size_t b,
  std::size_t c) const
{
  const std::vector<Point2>& pts = this->Coordinates;
  const Point2& pa = pts[ring[i]];
  const Point2& pb = pts[ring[b]];
  const Point2& pc = pts[ring[c]];
  if (orient2d_fast(pa, pb, pc) <= 0)
  {
    return false;
  }
  for (std::size_t k = 0; k < ring.size(); ++k)
  {
    if (k != i && k != b && k != c && incircle_fast(pa, pb, pc, pts[ring[k]]) > 0)
    {
      return false;
    }
  }
  return true;
}

// Re-triangulates the star of an interior vertex with Delaunay ears of its link polygon. Returns
// false (nothing changed) for a hull vertex.
//
//        c---b                 c---b
//       / \ / \               /   / \ .
//      d---v---a     ->      d   /   a     ear (a, b, c) cut first; then the smaller polygon
//       \ / \ /               \ /   /
//        e---f                 e---f

bool DirichletTessellation::RemoveInteriorVertex(std::int32_t edge)
{
  std::vector<std::int32_t>& ring = this->Removal.Ring;
  std::vector<std::int32_t>& outer = this->Removal.Outer;
  std::vector<std::int32_t>& slots = this->Removal.Slots;
  ring.clear();
  outer.clear();
  slots.clear();
  std::int32_t e = edge;
  do
  {
    const std::int32_t j = this->Origins[Next(e)];
    if (j == Ghost)
    {
      return false;
    }
    ring.push_back(j);
    outer.push_back(this->Twins[Next(e)]);
    slots.push_back(e / 3);
    e = this->RingNext(e);
  } while (e != edge);

  std::vector<Ear>& plan = this->Removal.Plan;
  plan.clear();
  if (!this->TriangulateHole(ring, outer, slots, 0, plan))
  {
    return false; // rebuilding is always correct
  }
  this->ApplyPlan(plan, slots);
  if (this->TrackingCocircular)
  {
    this->Serial.SawCocircular = this->AnyCocircularNeighbour(slots.data(), plan.size());
  }
  return true;
}

// Above this many vertices a hole left by a removal is triangulated by a batch build of its
// vertices (TriangulateLinkByBuild) rather than cut into ears: each ear test reads the whole
// polygon, so cutting is quadratic in its size (the centre of 4000 points on a circle took 7.6 s
// to remove, every test exact there; a hull vertex before 4000 points on a half circle, 8.6 s).
constexpr std::size_t EarCuttingDegree = 64;

// Triangulates the hole ring (an anticlockwise polygon whose edges are Delaunay edges of the
// points without the removed vertex; outer[i] the twin of its edge ring[i] -> ring[i + 1]) into
// plan[first ..], the k-th new triangle going to slots[first + k]: by a batch build where the
// polygon is large, else (or where the build does not hold it) by cutting Delaunay ears, which
// shortens ring and outer. False only if no ear is found, which exact predicates exclude.
bool DirichletTessellation::TriangulateHole(std::vector<std::int32_t>& ring,
  std::vector<std::int32_t>& outer,
  const std::vector<std::int32_t>& slots,
  std::size_t first,
  std::vector<Ear>& plan) const
{
  if (ring.size() > EarCuttingDegree &&
    this->TriangulateLinkByBuild(ring, outer, slots, first, plan))
  {
    return true;
  }
  plan.resize(first);
  return this->CutDelaunayEars(ring, outer, slots, first, plan);
}

namespace
{

// The link build's half-edges along the polygon's d edges, r_a -> r_a+1 (edgeOf: the polygon edge
// each is, else -1), and their triangles, where the flood starts (order, and each one's place in
// it, indexOf); false unless all d edges are there.
bool FindPolygonEdges(const HalfEdgeArray& org,
  std::int32_t d,
  std::vector<std::int32_t>& edgeOf,
  std::vector<std::int32_t>& order,
  std::vector<std::int32_t>& indexOf)
{
  std::int32_t found = 0;
  for (std::int32_t e = 0; e < std::int32_t(org.size()); ++e)
  {
    const std::int32_t a = org[e], b = org[DirichletTessellation::Next(e)];
    if (a >= 0 && b >= 0 && b == (a + 1) % d)
    {
      edgeOf[e] = a;
      ++found;
      if (indexOf[e / 3] < 0)
      {
        indexOf[e / 3] = std::int32_t(order.size());
        order.push_back(e / 3);
      }
    }
  }
  return found == d;
}

// Floods from the triangles listed, across every edge but the polygon's, appending the triangles
// reached to order; false where it reaches a ghost (it left the polygon).
bool FloodInsidePolygon(const HalfEdgeArray& org,
  const HalfEdgeArray& twin,
  const std::vector<std::int32_t>& edgeOf,
  std::vector<std::int32_t>& order,
  std::vector<std::int32_t>& indexOf)
{
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    for (std::int32_t i = 0; i < 3; ++i)
    {
      const std::int32_t e = 3 * order[k] + i;
      if (edgeOf[e] >= 0)
      {
        continue;
      }
      const std::int32_t t = twin[e] / 3;
      if (org[3 * t] < 0 || org[3 * t + 1] < 0 || org[3 * t + 2] < 0)
      {
        return false; // (a ghost: the flood left the polygon)
      }
      if (indexOf[t] < 0)
      {
        indexOf[t] = std::int32_t(order.size());
        order.push_back(t);
      }
    }
  }
  return true;
}

} // namespace

// Triangulates a large hole polygon (as TriangulateHole) by a batch build of its vertices alone,
// into plan[first ..] (a triangle per slot, twins set): the polygon's edges are Delaunay edges of
// the points without the vertex, so they are edges of that build, and its triangles inside the
// polygon, reached from the polygon's edges without crossing one, are the hole's Delaunay
// triangles. O(d log d), where cutting ears reads the whole link for each candidate ear. Returns
// false (plan undefined) where the build does not hold the polygon as expected; cutting ears then
// decides.
//
//         r3 ------- r2        The build of r0..r4 covers their convex hull, so it also
//        /  \        /  \       has the triangle r4 r0 r1 outside the polygon, beyond its reflex
//      r4    \      /    r1     vertex r0. The flood starts at the triangles on the left of the
//        \     \    /    /      polygon's edges and never crosses one of them: r4 r0 r1 is
//         \______ r0 ___/       never reached.
bool DirichletTessellation::TriangulateLinkByBuild(const std::vector<std::int32_t>& ring,
  const std::vector<std::int32_t>& outer,
  const std::vector<std::int32_t>& slots,
  std::size_t first,
  std::vector<Ear>& plan) const
{
  const std::int32_t d = std::int32_t(ring.size());
  std::vector<Point2> local(ring.size());
  for (std::int32_t k = 0; k < d; ++k)
  {
    local[k] = this->Coordinates[ring[k]];
  }
  const Box2 box = BoundsOf(local.data(), local.size());
  const double pad = std::max(box.LargerSide(), std::numeric_limits<double>::min());
  const DirichletTessellation link(
    Window::Rectangle(box.XMin - pad, box.XMax + pad, box.YMin - pad, box.YMax + pad), local);
  if (link.AcceptedCount() != std::size_t(d) || !link.IsTwoDimensional())
  {
    return false;
  }
  const HalfEdgeArray& org = link.Origin();
  const HalfEdgeArray& twin = link.Twin();
  // The polygon's edge each half-edge is (-1: none), and the triangles inside, in flood order.
  std::vector<std::int32_t> edgeOf(org.size(), -1);
  std::vector<std::int32_t> order, indexOf(org.size() / 3, -1);
  if (!FindPolygonEdges(org, d, edgeOf, order, indexOf) ||
    !FloodInsidePolygon(org, twin, edgeOf, order, indexOf))
  {
    return false;
  }
  if (order.size() != std::size_t(d - 2) || slots.size() < first + order.size())
  {
    return false;
  }
  for (const std::int32_t t : order)
  {
    std::int32_t vertex[3], twins[3];
    for (std::int32_t i = 0; i < 3; ++i)
    {
      const std::int32_t e = 3 * t + i;
      vertex[i] = ring[org[e]];
      twins[i] =
        edgeOf[e] >= 0 ? outer[edgeOf[e]] : 3 * slots[first + indexOf[twin[e] / 3]] + twin[e] % 3;
    }
    plan.push_back({ vertex[0], vertex[1], vertex[2], twins[0], twins[1], twins[2] });
  }
  return true;
}

// Writes plan[k] into slots[k] and recycles the slots left over.
void DirichletTessellation::ApplyPlan(const std::vector<Ear>& plan,
  const std::vector<std::int32_t>& slots)
{
  for (std::size_t k = 0; k < plan.size(); ++k)
  {
    const Ear& ear = plan[k];
    this->SetTriangle(slots[k], ear.A, ear.B, ear.C, ear.TwinA, ear.TwinB, ear.TwinC);
  }
  for (std::size_t k = plan.size(); k < slots.size(); ++k)
  {
    this->FreeTriangle(slots[k]);
  }
  this->Serial.LastTriangle = slots[0];
}

void DirichletTessellation::FreeTriangle(std::int32_t t)
{
  this->Origins[3 * t] = this->Origins[3 * t + 1] = this->Origins[3 * t + 2] = Free;
  this->Twins[3 * t] = this->Twins[3 * t + 1] = this->Twins[3 * t + 2] = -1;
  this->FreeTriangles.push_back(t);
}

// Removes a hull vertex v without rebuilding. Its star is the real triangles (v, n_i, n_i+1)
// over its chain of neighbours a = n_0, ..., n_k = b (anticlockwise around v), plus the two ghost
// triangles (v, G, a) and (v, b, G). Without v the hull runs from a to b along the convex hull of
// the chain, seen from v: the chain vertices kept by a stack scan in chain order that pops a
// vertex where the chain turns left (strictly: collinear chain vertices stay hull vertices, as
// every point on a hull edge is a vertex here). Each pair of consecutive new hull vertices h, h'
// gets a ghost triangle (h, h', G); where they are not neighbours on the chain, the pocket between
// the chain and the new hull edge h -> h' is an anticlockwise polygon (TriangulateHole). A
// pocket's edges are Delaunay edges without v (chain edges stay Delaunay, the closing edge is a
// hull edge), so its Delaunay triangulation is that of all the points there. Returns false
// (nothing changed) when the points left are collinear: then some chain edge would become a hull
// edge on both sides.
//
//               v
//            / /|\ \ .
//          /  / | \  \                       n1-----------n3
//        n1--/  |  \--n3          ->        / \           / \ .
//       /  \    |    /  \                  a   \         /   b
//      a    \   |   /    b                      \       /
//              \|/                                \   /
//               n2                                  n2
//
// The chain is a, n1, n2, n3, b; n2 lies beyond n1 -> n3 (seen from v), so the new hull is
// a -> n1 -> n3 -> b with a ghost triangle outside each of its three edges, and the pocket
// n1 -> n2 -> n3 (closed by n3 -> n1) becomes one triangle.
//
// Slots: the star has k + 2 triangles; the new ones are k (the pockets' k - h triangles and h
// ghosts, h = number of new hull edges), so two are recycled.
namespace
{

// The new hull from a to b, as chain positions: a stack scan in chain order that pops a vertex
// where the chain turns left (strictly).
std::vector<std::size_t> ConvexChain(const std::vector<Point2>& pts,
  const std::vector<std::int32_t>& chain)
{
  std::vector<std::size_t> hull;
  for (std::size_t i = 0; i < chain.size(); ++i)
  {
    while (hull.size() >= 2 &&
      Orient(pts[chain[hull[hull.size() - 2]]], pts[chain[hull.back()]], pts[chain[i]]) > 0)
    {
      hull.pop_back();
    }
    hull.push_back(i);
  }
  return hull;
}

} // namespace

bool DirichletTessellation::RemoveHullVertex(std::int32_t edge)
{
  HullStar star;
  if (!this->ReadHullStar(edge, star))
  {
    return false;
  }
  const std::vector<std::size_t> hull = ConvexChain(this->Coordinates, star.Chain);
  const std::size_t k = star.Chain.size() - 1, h = hull.size() - 1;
  for (std::size_t s = 0; s < h; ++s)
  {
    if (hull[s + 1] == hull[s] + 1 && this->IsGhostTriangle(star.Outer[hull[s]] / 3))
    {
      return false; // a hull edge on both sides: the rest is collinear
    }
  }
  std::vector<Ear> plan, ghosts;
  if (!this->PlanHullRemoval(star, hull, plan, ghosts))
  {
    return false; // rebuilding is always correct
  }
  this->WriteHullRemoval(star, plan, ghosts);
  if (this->TrackingCocircular)
  {
    this->Serial.SawCocircular = this->AnyCocircularNeighbour(star.Slots.data(), k - h);
  }
  return true;
}

// v's star from the half-edge of the ghost triangle (v, G, a): false when v is no hull vertex
// or its chain is too short.
bool DirichletTessellation::ReadHullStar(std::int32_t edge, HullStar& star) const
{
  std::int32_t e0 = edge;
  while (this->Origins[Next(e0)] != Ghost)
  {
    e0 = this->RingNext(e0);
    if (e0 == edge)
    {
      return false; // not a hull vertex (cannot happen: RemoveInteriorVertex handled it)
    }
  }
  star.Slots.assign(1, e0 / 3);
  star.TwinBeforeA = this->Twins[Next(e0)]; // a -> G of the ghost before a
  star.TwinAfterB = -1;
  for (std::int32_t e = this->RingNext(e0); e != e0; e = this->RingNext(e))
  {
    star.Slots.push_back(e / 3);
    star.Chain.push_back(this->Origins[Next(e)]);
    if (this->Origins[Prev(e)] == Ghost)
    {
      star.TwinAfterB = this->Twins[Next(e)]; // e / 3 is (v, b, G)
    }
    else
    {
      star.Outer.push_back(this->Twins[Next(e)]);
    }
  }
  const std::size_t k = star.Chain.size() - 1;
  return star.TwinAfterB >= 0 && k >= 1 && star.Outer.size() == k;
}

// The ghost triangle outside each new hull edge (ghost s takes slots[k - h + s]) and the pockets'
// triangles (which take slots[0 ..]), into ghosts and plan; false when a pocket cannot be
// triangulated.
bool DirichletTessellation::PlanHullRemoval(const HullStar& star,
  const std::vector<std::size_t>& hull,
  std::vector<Ear>& plan,
  std::vector<Ear>& ghosts) const
{
  const std::vector<std::int32_t>& chain = star.Chain;
  const std::size_t k = chain.size() - 1, h = hull.size() - 1;
  for (std::size_t s = 0; s < h; ++s)
  {
    const std::size_t i = hull[s], j = hull[s + 1];
    const std::int32_t ghost = star.Slots[k - h + s];
    if (j == i + 1)
    {
      ghosts.push_back({ chain[i], chain[j], Ghost, star.Outer[i], -1, -1 });
      continue;
    }
    // The closing edge n_j -> n_i faces the ghost's n_i -> n_j; a pocket triangle sets that twin.
    ghosts.push_back({ chain[i], chain[j], Ghost, -1, -1, -1 });
    std::vector<std::int32_t> ring(
      chain.begin() + std::ptrdiff_t(i), chain.begin() + std::ptrdiff_t(j) + 1);
    std::vector<std::int32_t> ringOuter(
      star.Outer.begin() + std::ptrdiff_t(i), star.Outer.begin() + std::ptrdiff_t(j));
    ringOuter.push_back(3 * ghost);
    if (!this->TriangulateHole(ring, ringOuter, star.Slots, plan.size(), plan))
    {
      return false;
    }
  }
  return plan.size() == k - h; // (cannot fail)
}

// Ghosts first (their mutual twins and those towards the hull beyond a and b), then the pockets,
// which set the twins of the ghosts' inner edges; the star's two slots left over are freed.
void DirichletTessellation::WriteHullRemoval(const HullStar& star,
  const std::vector<Ear>& plan,
  const std::vector<Ear>& ghosts)
{
  const std::vector<std::int32_t>& slots = star.Slots;
  const std::size_t k = star.Chain.size() - 1, h = ghosts.size();
  for (std::size_t s = 0; s < h; ++s)
  {
    const Ear& g = ghosts[s];
    const std::int32_t before =
      s == 0 ? star.TwinBeforeA : 3 * slots[k - h + s - 1] + 1; // p -> G of the previous ghost
    this->SetTriangle(slots[k - h + s], g.A, g.B, Ghost, g.TwinA, -1, before);
  }
  this->Twins[3 * slots[k - 1] + 1] = star.TwinAfterB;
  this->Twins[star.TwinAfterB] = 3 * slots[k - 1] + 1;
  for (std::size_t t = 0; t < k - h; ++t)
  {
    const Ear& ear = plan[t];
    this->SetTriangle(slots[t], ear.A, ear.B, ear.C, ear.TwinA, ear.TwinB, ear.TwinC);
  }
  for (std::size_t t = k; t < slots.size(); ++t)
  {
    this->FreeTriangle(slots[t]);
  }
  this->Serial.LastTriangle = slots[0];
}

// The box of the collinear points, from the ends of their list, which is kept sorted along their
// line (empty when no point is left).
Box2 DirichletTessellation::BoxOfCollinearPoints() const
{
  Box2 box = Box2::Empty();
  if (!this->Collinear.empty())
  {
    box.Extend(this->Coordinates[this->Collinear.front()]);
    box.Extend(this->Coordinates[this->Collinear.back()]);
  }
  return box;
}

// When the points left are collinear (or an ear search fails, which exact predicates exclude),
// the structure is built again from the remaining accepted points: O(N log N), but exactly the
// tessellation built without the point.
void DirichletTessellation::RebuildWithout(std::int32_t id)
{
  this->ForgetWalkStarts();
  std::vector<char> isVertex(this->Coordinates.size(), 0);
  for (const std::int32_t v : this->Origins)
  {
    if (v >= 0 && v != id)
    {
      isVertex[v] = 1;
    }
  }
  std::vector<std::int32_t> ids;
  for (std::size_t v = 0; v < isVertex.size(); ++v)
  {
    if (isVertex[v])
    {
      ids.push_back(std::int32_t(v));
    }
  }
  this->Origins.clear();
  this->Twins.clear();
  this->FreeTriangles.clear();
  this->Collinear.clear();
  this->Serial.LastTriangle = 0;
  this->Accepted = 0;
  // The box shrinks to the points left, so that points beyond them start beside the hull again.
  this->AcceptedBox = Box2::Empty();
  // BuildFrom numbers vertices locally: the vertex half-edges are derived afterwards.
  this->VertexEdges.clear();
  this->BuildFrom(ids);
  this->RecomputeVertexEdges();
}

} // namespace tessera
