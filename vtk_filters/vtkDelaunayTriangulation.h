/**
 * @class   vtkDelaunayTriangulation
 * @brief   exact Delaunay triangulation of 2D points, degenerate faces kept whole
 *
 * vtkDelaunayTriangulation computes the Delaunay faces of the input points (x, y used), the dual
 * of vtkDirichletTessellation's tiles, with exact predicates. The output keeps every input point
 * in input order (point data passed as it is, global ids included), with one cell per Delaunay
 * face of the accepted, distinct points: a face whose 4 or more points are exactly co-circular is
 * one cell, unless SplitDegenerateFaces is on, when it becomes a fan of triangles from its
 * smallest point id. A face's cell type is by its size: VTK_TRIANGLE for 3 points, VTK_QUAD for 4
 * (a square lattice's faces), VTK_POLYGON for more; count faces by cells, not by one type. The
 * result does not depend on the order of the points. The cell array uses 32-bit storage (read by
 * VTK like the 64-bit kind).
 *
 * Only points strictly inside the window take part (see vtkDirichletTessellation for the window:
 * WindowBounds, constraints, Padding); the rest are listed, never dropped silently. Field data:
 * `RejectedPointIds`, `DuplicatePointIds`, `DuplicateOfPointIds` (vtkIdType), as in
 * vtkDirichletTessellation (an input field array with one of these names is kept renamed
 * NAME_input, with a warning); a warning counts the points not triangulated, with their first ids,
 * and where no point lies inside the window it names both boxes. Fewer than 3 points or collinear
 * points give no face.
 *
 * The input is a vtkPointSet, or a composite data set of them whose points are joined in block
 * order into one set (a point layer from vtkGDALVectorReader, a block per feature with its
 * attributes as its vertex's cell data, carried as the point's): ids then count the joined
 * points, and attribute roles such as global ids are not kept. Any other type is an error naming
 * it, with the outputs emptied.
 *
 * Any finite scale: coordinates of some 1e100 or 1e-100 are scaled by a power of two (exactly)
 * before the triangulation, which is the same; the faces are ids, so nothing is scaled back. A
 * window too large for its area to be a double is taken (a triangulation needs no area), and a
 * Padding that would carry the automatic window past the largest double is cut to the room there
 * is (points of 1e308 are triangulated). Points spanning more orders of magnitude than the doubles
 * hold around one scale (1e300 with 1e-200) are an error naming the point.
 *
 * @sa vtkDirichletTessellation vtkDelaunay2D
 */

#ifndef vtkDelaunayTriangulation_h
#define vtkDelaunayTriangulation_h

#include "tesseraFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector> // For the constraint list

class TESSERAFILTERS_EXPORT vtkDelaunayTriangulation : public vtkPolyDataAlgorithm
{
public:
  static vtkDelaunayTriangulation* New();
  vtkTypeMacro(vtkDelaunayTriangulation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Off (default): a degenerate (co-circular) face is one polygon. On: a fan of triangles.
   */
  vtkSetMacro(SplitDegenerateFaces, bool);
  vtkGetMacro(SplitDegenerateFaces, bool);
  vtkBooleanMacro(SplitDegenerateFaces, bool);
  ///@}

  ///@{
  /**
   * The window rectangle (xmin, xmax, ymin, ymax). Ignored while empty (xmin >= xmax or
   * ymin >= ymax; the default is 0, 0, 0, 0), with a warning unless it is that default.
   */
  vtkSetVector4Macro(WindowBounds, double);
  vtkGetVector4Macro(WindowBounds, double);
  ///@}

  ///@{
  /**
   * Strict linear window constraints a*x + b*y + c < 0, combined with WindowBounds.
   */
  void AddWindowConstraint(double a, double b, double c);
  void RemoveAllWindowConstraints();
  int GetNumberOfWindowConstraints() const;
  ///@}

  ///@{
  /**
   * Padding of the automatic window (default 0.1 of the larger bounding-box side; as for
   * vtkDirichletTessellation, points without extent get the unit square centred on them). Used
   * only without WindowBounds and constraints; a negative or NaN padding is then an error at the
   * update. It changes no face: the automatic window holds every point at any padding (the
   * triangulation depends on the window only through the points it holds), so ParaView's panel
   * does not show it.
   */
  vtkSetMacro(Padding, double);
  vtkGetMacro(Padding, double);
  ///@}

protected:
  vtkDelaunayTriangulation() = default;
  ~vtkDelaunayTriangulation() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  bool SplitDegenerateFaces = false;
  double WindowBounds[4] = { 0.0, 0.0, 0.0, 0.0 };
  std::vector<double> WindowConstraints;
  double Padding = 0.1;

private:
  vtkDelaunayTriangulation(const vtkDelaunayTriangulation&) = delete;
  void operator=(const vtkDelaunayTriangulation&) = delete;
};

#endif
