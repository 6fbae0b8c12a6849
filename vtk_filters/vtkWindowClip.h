/**
 * @class   vtkWindowClip
 * @brief   clip convex tiles by a polygon window with holes (even-odd), with exact areas
 *
 * vtkWindowClip intersects every polygon of input 0 (a point set: convex tiles, such as the
 * output of vtkDirichletTessellation or a vtkUnstructuredGrid of some of them, as ParaView's
 * Threshold gives; or closed polylines, as vtkGDALVectorReader gives a shapefile's
 * polygons; a clockwise one is reversed first; a closed polyline inside another of the same
 * block, which is how that reader gives a polygon's hole, is an error naming both cells, as the
 * hole would be clipped as a tile) with the region of input 1: the
 * polygons (and closed polylines, as vtkGDALVectorReader gives rings, and lines that join end to
 * end into closed rings, as a contour from vtkCutter or ParaView's Contour is given; where four or
 * six lines meet, as at a saddle, the rings touch there; a line of no length at a point of a ring,
 * as vtkContourFilter gives between two ids of one point, adds nothing) of input 1 taken as rings
 * under the even-odd rule, so a ring inside another is a hole and a ring inside a hole an island
 * (other cells of input 1, such as lines in no closed ring, are ignored with a warning). Ring
 * orientation and order do not matter. A catchment boundary that touches or crosses itself, or two
 * rings that cross, is an error naming them; rings may touch at points and share stretches of
 * boundary (a hole touching the outer boundary at a vertex, as OGC's simple features allow;
 * adjacent parts). An island that fills a hole exactly (an enclave given as a hole and as a
 * polygon) cancels it by the even-odd rule: both are left out with a warning naming them. An outer
 * ring given twice (a feature repeated) is an error naming both copies: cancelled, it would take
 * its region away; so are rings that cancel out altogether (a basin given with all its sub-basins),
 * tiles that are neither a point set nor a composite data set (a table), and no window connected.
 * An error too is a tile of input 0 that is not convex (beyond the rounding of its vertices, in
 * float or double as its points are stored: its area differing from its convex hull's by more
 * than a millionth), whose clipped area would otherwise be its hull's. Tiles given as a composite
 * data set (a shapefile's polygons from vtkGDALVectorReader) are clipped block by block into a
 * composite of the same structure, each block with its own field data and summary arrays; a
 * message about a block's tiles names the block ("block 1 (composite index 2) of input 0: tile 0
 * is not convex"), and an error leaves the whole output empty. Of the blocks' warnings, the first
 * 5 are given, then one counting the rest (a layer of 10000 features gave 10000).
 *
 * The output holds each clipped tile as one or more polygons, its display pieces: simple,
 * anticlockwise, without holes, not overlapping one another, inside the window, together filling
 * exactly tile & window, and each a fan about its first point (every triangle of that point and
 * an edge not at it anticlockwise or flat), which is how VTK draws a polygon and how
 * vtkCellSizeFilter and Integrate Variables measure it: so rendering, those filters and
 * vtkTriangleFilter read them as meant. A tile that the window cuts into lobes gives one polygon
 * per lobe or more; a tile around a hole is cut into pieces around it (x-monotone pieces: a
 * vertical line meets each in one interval; an x-monotone part is one piece if it is a fan about
 * one of its points, else it is cut by vertical lines into fans: an L is one piece, a U two). Each
 * polygon has the tile's cell data (the tiles' global ids as an ordinary array: a tile in several
 * pieces repeats its id) and:
 * - `TileId` (vtkIdType): the input 0 cell the polygon comes from;
 * - `ClippedArea` (double): the area of the whole tile inside the window (same on all its pieces);
 * - `AreaFraction` (double): ClippedArea over the tile's own area (at most 1: a tile inside the
 *   window has 1, not 1 + 2^-52 from the two areas' rounding);
 * - `PieceArea` (double): the area of this polygon; a tile's PieceArea values add up to its
 *   ClippedArea (to rounding).
 * An input cell-data array with one of these four names is passed under the first free name of
 * NAME_input, NAME_input_2, ..., with a warning naming it.
 *
 * Output 1 holds each clipped tile's outline: its pieces joined back into polygons with holes
 * (core/piece_outlines.h), as a GIS wants a tile and as a view draws the tiles' borders without
 * the cuts between pieces, one closed polyline per ring (its first point repeated last), with the
 * tile's cell data and `TileId`, `ClippedArea`, `AreaFraction` (as above), `PolygonId` (the
 * polygon the ring bounds, numbered over the output or block) and `Hole` (0: the polygon's outer
 * ring, anticlockwise, listed first; 1: a
 * hole in it, clockwise); an input array so named is passed under another name, as above. It
 * has the tiles' field data, and for tiles in a composite the same structure as output 0; it has
 * no active scalars, so that ParaView draws the rings in one colour over the clipped tiles.
 * Tiles entirely outside the window give no polygon. Cells of input 0 that are not polygons,
 * triangles, quads, pixels or closed polylines (open lines, vertices, strips, 3D cells), and
 * polygons of fewer
 * than 3 points, are not
 * clipped: a warning counts them and the output's field data array `SkippedCellIds` (vtkIdType)
 * lists them. Polygons that lie in the window but have no area to clip (collinear corners, a
 * sliver thinner than the clip's rounding, or a polygon some 10^14 times the window's size that
 * holds part of it, its rounding larger than that part) give no piece either, and are counted in
 * a warning and listed in `EmptyTileIds` (both arrays are always written, empty when nothing is
 * listed); one that holds the whole window gives the window. A tile
 * whose area overflows (coordinates of some 1e154 or more) is an error naming it; a window of
 * tiny coordinates (below 2^-128, some 3e-39) is clipped scaled up by a power of two, tiles
 * alike, so that AreaFraction is as at unit scale (ClippedArea and PieceArea are then as small as
 * the doubles allow: 0 below some 1e-323). Areas use exact
 * orientation tests and compensated sums, so the clipped areas of a tiling that covers the window
 * sum to the window's area to round-off. The field data arrays `WindowArea` (the window's area)
 * and `CoveredFraction` (the tiles' clipped areas summed, over WindowArea) say whether they do:
 * below 1 where part of the window has no tile (tiles of a tessellation made in a smaller window,
 * such as vtkDirichletTessellation's default box about its points: areas over the window then
 * count only the covered part), above 1 where tiles overlap. (Not a warning: a clip of a few
 * tiles, or of a composite's blocks and a parallel run's pieces, each clipped alone, covers a
 * share of the window by design. Where the tiles' bounding box and the window's do not meet, a
 * warning names both, the output being empty; not for one process's piece of the tiles under
 * MPI.) The tiles' point data is not passed (the pieces'
 * vertices are new points; a warning names its arrays). Only x and y are used, in one plane: inputs
 * whose `TesseraProjection` records (vtkGeographicProjection) differ are an error naming both; a
 * record on one input only is an error where that input reaches metres (1e4 or more) and the other
 * lies within degrees (|x| <= 360, |y| <= 90: lon/lat tiles and a projected window), else a
 * warning.
 */

#ifndef vtkWindowClip_h
#define vtkWindowClip_h

#include "tesseraFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For ClipTilesOf
#include <vector> // For ClipTilesOf

class vtkCompositeDataSet;
class vtkPointSet;

namespace tessera
{
class Catchment;
}

class TESSERAFILTERS_EXPORT vtkWindowClip : public vtkPolyDataAlgorithm
{
public:
  static vtkWindowClip* New();
  vtkTypeMacro(vtkWindowClip, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The window polygons (input port 1).
   */
  void SetWindowConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetWindowData(vtkDataObject* data) { this->SetInputData(1, data); }

protected:
  vtkWindowClip();
  ~vtkWindowClip() override = default;

  vtkTypeBool ProcessRequest(vtkInformation*,
    vtkInformationVector**,
    vtkInformationVector*) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;

private:
  /// RequestData's work, its errors thrown: the inputs and the window checked, the tiles clipped by
  /// the window (ClipTiles), the warnings given as they come.
  void ClipByWindow(vtkDataObject* tilesData,
    vtkDataObject* windowData,
    vtkDataObject* output,
    vtkDataObject* outlines,
    vtkInformationVector* outputVector);

  /// Clips the tiles, a point set (ClipTilesOf) or a composite of them (ClipBlocks, into outputs
  /// of its structure), by the window (catchment, scaled by 2^exponent); gives their warnings.
  void ClipTiles(vtkDataObject* tilesData,
    vtkDataObject* windowData,
    const tessera::Catchment& catchment,
    int exponent,
    vtkDataObject* output,
    vtkDataObject* outlines);

  /// Clips each block of tiles alone (ClipTilesOf) into the same block of outBlocks and
  /// outlineBlocks; returns the blocks' warnings, each naming its block.
  std::vector<std::string> ClipBlocks(vtkCompositeDataSet* blocks,
    vtkDataObject* windowData,
    const tessera::Catchment& catchment,
    int exponent,
    vtkCompositeDataSet* outBlocks,
    vtkCompositeDataSet* outlineBlocks);

  /// Gives the first 5 of the blocks' warnings, then one counting the rest.
  void WarnFirstFew(const std::vector<std::string>& warnings);

  /// Clips one point set of tiles into output and their outlines into outlines, its messages
  /// prefixed by block ("" for a point set input; "block 1 (composite index 2) of input 0: " for
  /// a block), its progress running from progressFrom to progressTo. Returns its warnings, so
  /// prefixed; throws its error.
  std::vector<std::string> ClipTilesOf(vtkPointSet* tiles,
    const tessera::Catchment& catchment,
    int exponent,
    vtkPolyData* output,
    vtkPolyData* outlines,
    const std::string& block,
    double progressFrom,
    double progressTo);

  vtkWindowClip(const vtkWindowClip&) = delete;
  void operator=(const vtkWindowClip&) = delete;
};

#endif
