/**
 * @class   vtkDirichletTessellation
 * @brief   exact Dirichlet (Voronoi / Thiessen) tiles of 2D points within a convex window
 *
 * vtkDirichletTessellation computes the tile of every point: the part of a convex window nearer
 * to that point than to any other (Green and Sibson 1978). Only x and y of the input points are
 * used (z is not read, and output 1 passes the points on as they are, NaN z included). Every
 * topological decision uses exact predicates, so the combinatorics (which tiles there are, which
 * points neighbour which, and each tile's sides) are the same for every insertion order, and
 * exactly co-circular points are handled consistently: at a vertex shared by 4 or more tiles,
 * neither diagonal is recorded as a contiguity; the pairs that meet only there are half-neighbours
 * when that vertex lies strictly inside the window (tiles that meet only at a point of the window's
 * boundary are no pair at all). The corners are rounded constructions (circumcentres, window
 * crossings), each computed from its points taken in coordinate order, and an area is summed from
 * its tile's lowest corner, so the input reordered gives the same corners and areas, bit for bit
 * (except where corners of a tile round onto one another: points some ulps apart). A tile is
 * convex up to that rounding: where points lie some ulps apart, a corner may sit ulps inside the
 * line of its neighbours, a reflex turn (a trial's points 1 mm apart in UTM metres left such
 * dents of up to 3.5e-10 m), which vtkWindowClip accepts as rounding.
 *
 * The window is the intersection of the rectangle SetWindowBounds(xmin, xmax, ymin, ymax) (when
 * xmin < xmax and ymin < ymax) and the strict constraints a*x + b*y + c < 0 added with
 * AddWindowConstraint. With neither, it is the points' bounding box padded on every side by
 * Padding (default 0.1) times its larger side; points without extent (one point, or copies of
 * one) get the square of side 1 centred on them (or, where the coordinates cannot hold it, the
 * square an ulp out on every side: side 4 about 1e16), and no points the square
 * -1 < x, y < 1. Padding
 * 0 keeps a margin of 1e-9 of the larger side, so that every point is strictly inside. Redundant
 * constraints are ignored; an empty or unbounded window is an error, and so is a constraint with
 * a = b = 0 (no half-plane, even one every point satisfies).
 *
 * The input is a vtkPointSet, or a composite data set of them whose points are joined in block
 * order into one set (a point layer from vtkGDALVectorReader, a block per feature with its
 * attributes as its vertex's cell data, carried as the point's): ids then count the joined
 * points, and attribute roles such as global ids are not kept. Any other type is an error naming
 * it, with the outputs emptied.
 *
 * Algorithms: GreenSibson (default), the incremental engine; BrasselReif, the Thiessen sweep of
 * Brassel and Reif (1979), which needs a rectangular window whose sides lie at doubles (any
 * WindowBounds; a constraint 3x - 1 < 0, at x = 1/3, is an error naming it). Both give the same
 * combinatorics;
 * corners and areas agree to rounding (an ulp or so). The sweep has the paper's bad cases: when
 * the points lie on one slanted line or on one circle, its search circles meet nearly every point
 * and its time grows like N^1.5 to N^2 (10^4 points on a circle: about a minute, against 0.03 s
 * for GreenSibson); GreenSibson has no such case.
 *
 * Output 0 (vtkPolyData): one polygon per accepted point (anticlockwise), in ascending point id.
 * Its points are the tile corners: circumcentres inside the window, window corners and the points
 * where tile edges cross the window boundary. Tiles that meet share the point there: the tiles
 * form a conforming mesh (with BrasselReif, tiles share a point where their corners are equal,
 * as the sweep makes them). Cell data:
 * - `PointId` (vtkIdType): the index of the point in the input;
 * - `Area` (double): the tile's area, by compensated summation;
 * - `NeighborCount` (int): contiguities of the tile, window edges included (its polygon sides,
 *   decided exactly: where distinct corners round to one point, the polygon lists it once, never
 *   twice in a row, and has fewer points than NeighborCount; a corner an ulp off between two that
 *   round to one point is left out, so that the polygon does not go out to it and back).
 *   Half-neighbours (output 1's Kind 1 lines) share no side and are not counted;
 * - every input point-data array, copied to the tile of its point (a gauge's values follow it),
 *   attributes included: global ids become the tiles' global ids (one tile per point keeps them
 *   unique), pedigree ids their pedigree ids, active scalars etc. stay active.
 * Without active scalars from the input, `Area` is the active scalars (a view such as ParaView's
 * colours the tiles by it); output 1's `Kind` is its active scalars. The three names above are
 * the filter's API and always hold its own arrays. An input array with one of them is still
 * passed, renamed NAME_input (or NAME_input_2, _3 ... if the input has that name too), and a
 * warning names it (e.g. an input `Area` becomes `Area_input`).
 * Field data (on both outputs):
 * - `RejectedPointIds` (vtkIdType): points not strictly inside the window;
 * - `DuplicatePointIds` and `DuplicateOfPointIds` (vtkIdType, same length): exact copies of an
 *   earlier point, and the accepted point each one copies (the first is kept).
 * A warning counts the points not used, with their first ids; where no point lies inside the
 * window, it names the window's bounding box and the points' instead (bounds in other units, or
 * given as xmin, ymin, ...).
 * The input's field data is passed too; an input field array with one of these three names (say,
 * from an earlier tessellation) is kept renamed NAME_input, with a warning.
 *
 * Output 1 (vtkPolyData): the contiguity graph, sorted by (i, j). Its points are the input points
 * (same ids, point data passed as it is: names and global ids kept), with one line per contiguous
 * pair (i < j) and cell data `Kind` (unsigned char): 0 = neighbours sharing an edge of positive
 * length, 1 = half-neighbours (sharing only a degenerate vertex strictly inside the window), and
 * `PointIds` (32-bit, 2 components named i and j): the line's two point ids, so that a
 * spreadsheet or a CSV of the cells lists the pairs.
 *
 * With ComputeContiguityGraph off, output 1 has no points and no lines (its field data is still
 * output 0's) and the graph is not written (nor derived, with GreenSibson; the sweep finds
 * it anyway): a caller that wants only the tiles saves that time (about 10-25% of the filter's)
 * and the graph's memory (some 21 bytes per contiguity, with its PointIds; 3 contiguities per
 * point).
 *
 * Both outputs' cell arrays use 32-bit storage (read by VTK like the 64-bit kind).
 *
 * 0, 1 or 2 points and collinear points give valid output: the tiles are the whole window,
 * strips or half-planes within it. A NaN or infinite x or y is an error naming the point.
 *
 * Range. The Delaunay decisions are exact for any finite coordinates. The window decisions of the
 * tiles (where a Voronoi vertex lies against a window side) are exact for nonzero coordinates
 * within about 1e-60 .. 1e60 in magnitude: coordinates of some 1e100 or 1e-100 are therefore
 * scaled by a power of two (exactly) into that range and the tiles scaled back, so the tiles of
 * points scaled by s are those of the points, scaled (areas by s^2: a window whose area
 * overflows, of sides beyond about 1e154, is an error saying so, and areas underflow to 0 below
 * about 1e-154). A point inside the window with a coordinate
 * nonzero but below 2^-200 (some 6e-61) of the window's reach (its largest corner coordinate),
 * where those products underflow whatever the scale, is an error naming it (GreenSibson; the
 * BrasselReif sweep's tests keep their range), and so is one that cannot be scaled exactly
 * beside the window (its coordinate would lose bits).
 * Tiles whose areas do not fill the window (points closer together than some 1e-60 of its size)
 * are an error too, a last check that catches overlaps and gaps, not every wrong tile.
 *
 * @sa vtkDelaunayTriangulation vtkVoronoi2D
 */

#ifndef vtkDirichletTessellation_h
#define vtkDirichletTessellation_h

#include "tesseraFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector> // For the constraint list

class TESSERAFILTERS_EXPORT vtkDirichletTessellation : public vtkPolyDataAlgorithm
{
public:
  static vtkDirichletTessellation* New();
  vtkTypeMacro(vtkDirichletTessellation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum AlgorithmTypes
  {
    GREEN_SIBSON = 0,
    BRASSEL_REIF = 1
  };

  ///@{
  /**
   * The engine: GREEN_SIBSON (default) or BRASSEL_REIF (rectangular windows only). Another value
   * is an error at the update.
   */
  vtkSetMacro(Algorithm, int);
  // The range VTK's clamping setter announced (kept: a value outside is an error at the update).
  virtual int GetAlgorithmMinValue() { return GREEN_SIBSON; }
  virtual int GetAlgorithmMaxValue() { return BRASSEL_REIF; }
  vtkGetMacro(Algorithm, int);
  void SetAlgorithmToGreenSibson() { this->SetAlgorithm(GREEN_SIBSON); }
  void SetAlgorithmToBrasselReif() { this->SetAlgorithm(BRASSEL_REIF); }
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
   * Padding of the automatic window, as a fraction of the points' larger bounding-box side
   * (default 0.1). Used only when there is no window rectangle and no constraint; a negative or
   * NaN padding is then an error at the update.
   */
  vtkSetMacro(Padding, double);
  vtkGetMacro(Padding, double);
  ///@}

  ///@{
  /**
   * Whether output 1 (the contiguity graph) is made (default on). Off leaves it empty; output 0
   * is the same either way.
   */
  vtkSetMacro(ComputeContiguityGraph, bool);
  vtkGetMacro(ComputeContiguityGraph, bool);
  vtkBooleanMacro(ComputeContiguityGraph, bool);
  ///@}

protected:
  vtkDirichletTessellation();
  ~vtkDirichletTessellation() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  int Algorithm = GREEN_SIBSON;
  double WindowBounds[4] = { 0.0, 0.0, 0.0, 0.0 };
  std::vector<double> WindowConstraints; // a, b, c triples
  double Padding = 0.1;
  bool ComputeContiguityGraph = true;

private:
  vtkDirichletTessellation(const vtkDirichletTessellation&) = delete;
  void operator=(const vtkDirichletTessellation&) = delete;
};

#endif
