#pragma once
// Results derived from a DirichletTessellation (Green and Sibson: "all other properties of the
// tessellation, tile vertex positions and tile areas for example, are easily calculated from the
// contiguities and the point coordinates"): tile polygons with their areas and neighbour counts,
// the contiguity graph with half-neighbours, and the Delaunay faces.
//
// Faces. Triangles of the stored triangulation whose circumcircles coincide exactly (4 or more
// co-circular points, decided with the exact incircle) are merged into one degenerate face. A
// face's centre is computed once, from its three smallest point ids in ascending order, so every
// tile that has it as a vertex gets the same bits and the result does not depend on which diagonal
// the triangulation happens to store. Neither diagonal of a degenerate face is a contiguity: its
// non-adjacent vertex pairs are half-neighbours (kind 1), reported when the centre lies inside the
// window.
//
// Window constraints (the paper's second kind of object) are handled here. The edge a tile shares
// with point j runs along the bisector of the two points between the centres of the faces on
// either side of the Delaunay edge (a ray where that face is a ghost). It is clipped once, to the
// window, from the point pair in ascending id order, so both tiles agree on it; a face centre
// that lies inside the window (tested in floating point, once per face) is kept as is, and the
// crossings with the window lines are computed from the bisector's midpoint and direction, which
// stays accurate even when the far centre is huge. Between an edge leaving the window on
// constraint a and the next one entering on constraint b, the tile follows the window boundary
// through corners a+1 .. b. Each polygon side is then one contiguity: with a point (both tiles see
// it) or with a constraint, so NeighborCount counts window edges as in the paper, and
//   sum of NeighborCount + (constraint sides) + 2 * constraints = 4 * constraints + 6 * points - 6
// when no vertex is degenerate (section 2.3).

#include "dirichlet_tessellation.h"
#include "geometry.h"

#include <cstdint>
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

/// Pairs (i < j), grouped by i (in the tiles' order), ascending j within a group.
struct ContiguityGraph
{
  std::vector<std::int32_t> Pairs; ///< 2 ids per contiguity
  std::vector<std::uint8_t> Kinds; ///< 0: share an edge of positive length, 1: half-neighbours
};

/// Delaunay faces, each anticlockwise and starting at its smallest point id, listed in the order
/// of the triangle arrays. The set of faces, and each face, do not depend on the insertion order;
/// the listing order does.
struct DelaunayFaces
{
  std::vector<std::int64_t> Offsets;
  std::vector<std::int32_t> PointIds;
};

/// Face structure of a tessellation (merged degenerate faces, centres): computed once, then each
/// result is derived from it. Holds a reference: the tessellation must outlive it and not change.
class TessellationDual
{
public:
  explicit TessellationDual(const DirichletTessellation& tessellation);

  TileSet Tiles() const;
  ContiguityGraph Contiguities() const;
  /// With splitDegenerate, a degenerate face becomes a fan of triangles from its smallest id.
  DelaunayFaces Faces(bool splitDegenerate) const;

  /// Number of merged faces with 4 or more points.
  std::size_t DegenerateFaceCount() const { return this->DegenerateReps.size(); }

private:
  struct EdgeEnd
  {
    Point2 P;
    int Constraint; ///< window constraint the end lies on; -1 for a face centre
  };
  struct TileEdge
  {
    EdgeEnd Lo, Hi;
  };

  void ComputeTriangleCentres();
  bool Cocircular(std::int32_t t, std::int32_t f) const;
  void LabelFaces();
  void MergeCocircular(std::int32_t root,
    std::vector<std::int32_t>& cluster,
    std::vector<std::int32_t>& stack,
    std::vector<std::int32_t>& boundary);
  void ComputeCentres();
  bool ClipEdge(std::int32_t from,
    std::int32_t to,
    std::int32_t rightFace,
    std::int32_t leftFace,
    TileEdge& out) const;
  bool ClipCanonical(std::int32_t a,
    std::int32_t b,
    std::int32_t loFace,
    std::int32_t hiFace,
    TileEdge& out) const;
  void TileEdgesOf(std::int32_t v,
    std::int32_t vertexEdge,
    std::vector<TileEdge>& edges,
    std::vector<std::int32_t>& ring) const;
  void AssemblePolygon(const std::vector<TileEdge>& edges, std::vector<Point2>& polygon) const;
  const std::int32_t* DegeneratePolygon(std::int32_t face, std::int32_t& size) const;
  std::int32_t Neighbors1D(std::int32_t v, std::int32_t& next) const;

  const DirichletTessellation& Tess;
  std::vector<std::int32_t> LinePosition; ///< collinear case: per point id, index along the line
  /// Accepted points in traversal order: first appearance in the half-edge arrays, which follow
  /// the spatial insertion order, so walking rings in this order stays in cache.
  std::vector<std::int32_t> Order;
  std::vector<std::int32_t> OrderEdge; ///< two-dimensional case: a half-edge leaving Order[k]
  /// Per triangle, together so that a ring walk touches one cache line per triangle: its face
  /// (a representative triangle; -2 - t for a ghost), and for a representative the face's centre
  /// and whether it lies inside the window.
  struct TriangleData
  {
    Point2 Centre;
    std::int32_t Face = -1;
    std::uint8_t Inside = 0;
  };
  std::vector<TriangleData> Data;
  std::vector<double> CentreError; ///< per triangle, while labelling faces
  // Degenerate faces: representative -> index k; polygon k is DegenerateVertices[Starts[k] ..
  // Starts[k+1]), anticlockwise, starting at its smallest id.
  std::vector<std::int32_t> DegenerateIndex;
  std::vector<std::int32_t> DegenerateStarts;
  std::vector<std::int32_t> DegenerateVertices;
  std::vector<std::int32_t> DegenerateReps;
};

TileSet ComputeTiles(const DirichletTessellation& tessellation);
ContiguityGraph ComputeContiguityGraph(const DirichletTessellation& tessellation);
DelaunayFaces ComputeDelaunayFaces(const DirichletTessellation& tessellation, bool splitDegenerate);

} // namespace tessera
