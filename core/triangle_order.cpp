// DirichletTessellation::OrderTrianglesByVertex: renumbers the triangles so that those near in
// space are near in memory again after many removals and insertions.
//
// Why. A batch build creates triangles along its spatial insertion order, so a vertex's ring and
// its neighbours' rings lie in a few cache lines. Updates spoil that: Remove frees two slots of
// each star, and Insert takes its two new triangles from the free list, from wherever the last
// removal was. After some 40,000 insertions among 100,000 triangles (the areal average's
// synthetic stream) the tiles derived around the changed points took 35-40% longer than just
// after the build, each ring step a cache miss.
//
// How. Triangles are sorted by their smallest vertex id (a counting sort: O(triangles + ids)),
// keeping their old order within one key; ghost triangles go by their smallest real vertex, free
// slots are dropped. Where ids were given in a spatial order (a batch build's input sorted along
// a curve, or the areal average's gauges, numbered along a Hilbert curve), that is a spatial
// order. Half-edges keep their place within their triangle, so only indices change:
//
//     old t:  [a b c | twins x y z]   ->   new u = NewIndex[t]:  [a b c | twins x' y' z']
//             x' = 3 * NewIndex[x / 3] + x % 3  (likewise y, z, vertex edges, the walk's start)
//
// The triangulation itself is unchanged: every derived result is the same, bit for bit, though
// results listed in triangle order (a TileMesh's face-centre vertices, the Delaunay faces) come in
// the new order.
#include "dirichlet_tessellation.h"

#include "parallel_chunks.h"

#include <algorithm>
#include <cstdint>

namespace tessera
{
namespace
{

// The moves and the vertex edges' remapping run in chunks on the cores (from 50000 triangles or
// ids per chunk): each triangle goes to its own new slot, each id's edge is its own, so the
// chunks write apart. (They are most of an ordering, which the areal average's updates make every
// few steps among 100k gauges: KeepTrianglesLocal.)
constexpr std::int64_t MovesPerThread = 50000;

/// Half-edge e's number once its triangle has moved to newIndex[e / 3].
std::int32_t NewEdge(const std::vector<std::int32_t>& newIndex, std::int32_t e)
{
  return 3 * newIndex[std::size_t(e / 3)] + e % 3;
}

/// Each kept triangle t (newIndex[t] < kept) of org and twin copied to slot newIndex[t] of
/// origins and twins, its twins renumbered.
void MoveTriangles(const std::int32_t* org,
  const std::int32_t* twin,
  std::int32_t triangleCount,
  const std::vector<std::int32_t>& newIndex,
  std::int32_t kept,
  HalfEdgeArray& origins,
  HalfEdgeArray& twins)
{
  const std::vector<std::int32_t> bounds =
    parallel::ChunkBounds(triangleCount, parallel::ThreadCount(triangleCount, MovesPerThread));
  parallel::RunChunks(bounds.size() - 1,
    [&](std::size_t chunk)
    {
      for (std::int32_t t = bounds[chunk]; t < bounds[chunk + 1]; ++t)
      {
        const std::int32_t u = newIndex[std::size_t(t)];
        if (u >= kept)
        {
          continue; // a free slot
        }
        for (std::int32_t k = 0; k < 3; ++k)
        {
          origins[std::size_t(3 * u + k)] = org[3 * t + k];
          twins[std::size_t(3 * u + k)] = NewEdge(newIndex, twin[3 * t + k]);
        }
      }
    });
}

/// Each id's edge renumbered where it still leaves that id in org (edgeCount half-edges), else
/// -1: an entry of an id that is no vertex any more may name a freed slot, which has no place in
/// the new arrays.
void RemapVertexEdges(const std::int32_t* org,
  std::size_t edgeCount,
  const std::vector<std::int32_t>& newIndex,
  std::vector<std::int32_t>& vertexEdges)
{
  const std::int32_t ids = std::int32_t(vertexEdges.size());
  const std::vector<std::int32_t> bounds =
    parallel::ChunkBounds(ids, parallel::ThreadCount(ids, MovesPerThread));
  parallel::RunChunks(bounds.size() - 1,
    [&](std::size_t chunk)
    {
      for (std::int32_t id = bounds[chunk]; id < bounds[chunk + 1]; ++id)
      {
        std::int32_t& e = vertexEdges[std::size_t(id)];
        const bool leaves = e >= 0 && std::size_t(e) < edgeCount && org[e] == id;
        e = leaves ? NewEdge(newIndex, e) : -1;
      }
    });
}

} // namespace

void DirichletTessellation::OrderTrianglesByVertex()
{
  this->ForgetWalkStarts(); // (its triangles are renumbered)
  this->ScatteredTriangles = 0;
  if (this->Origins.empty())
  {
    return;
  }
  const std::int32_t triangleCount = std::int32_t(this->Origins.size() / 3);
  const std::int32_t kept = this->NumberTrianglesByVertex();
  const std::vector<std::int32_t>& newIndex = this->Ordering.NewIndex;
  // The capacity kept: insertions after the ordering append (no slot is free), and a fresh
  // array of exactly this size would be copied whole by the first of them.
  HalfEdgeArray& origins = this->Ordering.Origins;
  HalfEdgeArray& twins = this->Ordering.Twins;
  origins.reserve(this->Origins.capacity());
  twins.reserve(this->Twins.capacity());
  origins.resize(3 * std::size_t(kept));
  twins.resize(3 * std::size_t(kept));
  MoveTriangles(
    this->Origins.data(), this->Twins.data(), triangleCount, newIndex, kept, origins, twins);
  RemapVertexEdges(this->Origins.data(), this->Origins.size(), newIndex, this->VertexEdges);
  const std::int32_t last = newIndex[this->Serial.LastTriangle];
  this->Serial.LastTriangle = last < kept ? last : 0;
  this->Serial.NextSlot = this->Serial.EndSlot = 0;
  this->Origins.swap(origins);
  this->Twins.swap(twins);
  this->FreeTriangles.clear();
}

// Each triangle's new index (Ordering.NewIndex), by a counting sort on its smallest real vertex
// id, keeping the old order within one key; returns how many are kept (free slots get indices
// from there on, never read). Key of triangle t: as unsigned numbers Ghost (-1) and Free (-2) are
// the largest, so the smallest of the three is real except in a free slot (all Free), which gets
// the key idCount and is dropped. Branch-free: which vertex is smallest is a coin toss. NewIndex
// holds the keys first, then (in place) each triangle's new index.
std::int32_t DirichletTessellation::NumberTrianglesByVertex()
{
  const std::int32_t triangleCount = std::int32_t(this->Origins.size() / 3);
  const std::int32_t* org = this->Origins.data();
  const std::int32_t idCount = std::int32_t(this->Coordinates.size());
  std::vector<std::int32_t>& newIndex = this->Ordering.NewIndex;
  newIndex.resize(std::size_t(triangleCount));
  std::vector<std::int32_t>& first = this->Ordering.First;
  first.assign(std::size_t(idCount) + 2, 0);
  for (std::int32_t t = 0; t < triangleCount; ++t)
  {
    const std::uint32_t smallest = std::min(
      { std::uint32_t(org[3 * t]), std::uint32_t(org[3 * t + 1]), std::uint32_t(org[3 * t + 2]) });
    const std::int32_t key = std::int32_t(std::min(smallest, std::uint32_t(idCount)));
    newIndex[t] = key;
    ++first[std::size_t(key) + 1];
  }
  for (std::size_t k = 1; k < first.size(); ++k)
  {
    first[k] += first[k - 1];
  }
  const std::int32_t kept = first[std::size_t(idCount)];
  for (std::int32_t& index : newIndex)
  {
    index = first[std::size_t(index)]++;
  }
  return kept;
}

} // namespace tessera
