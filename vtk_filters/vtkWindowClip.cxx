#include "vtkWindowClip.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include "TesseraFilterUtilities.h"
#include "clip.h"
#include "compensated_sum.h"
#include "display_pieces.h"
#include "errors.h"
#include "geo.h"
#include "nested_rings.h"
#include "piece_outlines.h"
#include "polygon_area.h"
#include "window.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkWindowClip);

namespace
{
/// The filter's own cell arrays. Their names are API: an input cell-data array with one of them
/// is passed under another name (tessera_vtk::RenameArraysNamed).
const std::vector<const char*> OwnArrayNames{ "TileId",
  "ClippedArea",
  "AreaFraction",
  "PieceArea" };
/// Output 1's own cell arrays (API, as OwnArrayNames): output 0's first three, so that a GIS has
/// a tile's clipped area with its outline, then its own two.
const std::vector<const char*> OutlineArrayNames{ "TileId",
  "ClippedArea",
  "AreaFraction",
  "PolygonId",
  "Hole" };

/// What both outputs' cells of one point set of tiles carry: the tile's cell data (its global ids
/// too, passed as an ordinary array: a tile in several cells repeats its id), then TileId,
/// ClippedArea and AreaFraction, the first three of the output's own arrays (`names`). An input
/// cell-data array of one of those names is passed under another (adding the filter's arrays
/// would replace it silently).
class TileCells
{
protected:
  TileCells(vtkPointSet* tiles, vtkPolyData* output, const std::vector<const char*>& names)
    : Output(output)
    , CellData(output->GetCellData())
    , TileCellData(tiles->GetCellData())
  {
    this->Points->SetDataTypeToDouble();
    this->CellData->CopyGlobalIdsOn(); // (CopyAllocate leaves them out by default)
    this->CellData->CopyAllocate(this->TileCellData);
    this->Renamed = tessera_vtk::RenameArraysNamed(this->CellData, names, false);
    this->TileIds->SetName(names[0]);
    this->ClippedAreas->SetName(names[1]);
    this->Fractions->SetName(names[2]);
  }

  /// Tile c's data for the output's last cell.
  void AddTileData(vtkIdType c, vtkIdType cell, double clippedArea, double fraction)
  {
    this->CellData->CopyData(this->TileCellData, c, cell);
    this->TileIds->InsertNextValue(c);
    this->ClippedAreas->InsertNextValue(clippedArea);
    this->Fractions->InsertNextValue(fraction);
  }

  /// The points, and the tiles' arrays, their global ids no longer active (see CopyGlobalIdsOn).
  void AttachTileData()
  {
    this->Output->SetPoints(this->Points);
    this->CellData->SetActiveAttribute(-1, vtkDataSetAttributes::GLOBALIDS);
    this->CellData->AddArray(this->TileIds);
    this->CellData->AddArray(this->ClippedAreas);
    this->CellData->AddArray(this->Fractions);
  }

  vtkPolyData* Output;
  vtkCellData* CellData;
  vtkCellData* TileCellData;
  tessera_vtk::RenamedArrays Renamed;
  vtkNew<vtkPoints> Points;
  vtkNew<vtkIdTypeArray> TileIds;
  vtkNew<vtkDoubleArray> ClippedAreas, Fractions;
};

/// Output 1 of one point set of tiles: each clipped tile's outline (core/piece_outlines.h, its
/// display pieces joined back into polygons with holes) as closed polylines, a cell per ring (its
/// first point repeated last), with the tile's cell data, TileId, ClippedArea and AreaFraction (as
/// output 0's), PolygonId (numbered over the output) and Hole (0: a polygon's outer ring,
/// anticlockwise, listed first; 1: a hole in it).
class OutlineCells : TileCells
{
public:
  OutlineCells(vtkPointSet* tiles, vtkPolyData* output)
    : TileCells(tiles, output, OutlineArrayNames)
  {
    output->GetFieldData()->PassData(tiles->GetFieldData()); // (a projection's record with it)
    this->PolygonIds->SetName(OutlineArrayNames[3]);
    this->Holes->SetName(OutlineArrayNames[4]);
  }

  /// Tile c's pieces (scaled by 2^exponent) joined and added as its rings, with its clipped area
  /// and area fraction (OutlinesOfTilePieces).
  void Append(const tessera::ClippedRings& pieces,
    vtkIdType c,
    int exponent,
    double clippedArea,
    double fraction)
  {
    const tessera::RegionOutlines outlines = tessera::OutlinesOfTilePieces(pieces);
    for (std::size_t p = 0; p + 1 < outlines.PolygonOffsets.size(); ++p)
    {
      for (std::size_t r = outlines.PolygonOffsets[p]; r < outlines.PolygonOffsets[p + 1]; ++r)
      {
        const std::size_t begin = outlines.Rings.RingOffsets[r];
        tessera_vtk::AppendClosedLine(&outlines.Rings.Vertices[begin],
          outlines.Rings.RingOffsets[r + 1] - begin,
          exponent,
          this->Points,
          this->Lines);
        this->AddTileData(c, this->Lines->GetNumberOfCells() - 1, clippedArea, fraction);
        this->PolygonIds->InsertNextValue(this->NextPolygon);
        this->Holes->InsertNextValue(r == outlines.PolygonOffsets[p] ? 0 : 1);
      }
      ++this->NextPolygon;
    }
  }

  /// Puts the rings into the output; returns the warning for input arrays renamed, if any.
  std::string Finish()
  {
    this->AttachTileData();
    this->Output->SetLines(this->Lines);
    // No active scalars (the tiles' are those of the whole tile, such as its Area): ParaView
    // draws the rings in one colour over the clipped tiles.
    this->CellData->SetActiveAttribute(-1, vtkDataSetAttributes::SCALARS);
    this->CellData->AddArray(this->PolygonIds);
    this->CellData->AddArray(this->Holes);
    // (output 0's names are renamed as there, whose warning says so: only PolygonId and Hole here)
    tessera_vtk::RenamedArrays more;
    for (const auto& renamed : this->Renamed)
    {
      if (std::find_if(OwnArrayNames.begin(),
            OwnArrayNames.end(),
            [&](const char* own) { return renamed.first == own; }) == OwnArrayNames.end())
      {
        more.push_back(renamed);
      }
    }
    return more.empty()
      ? std::string()
      : tessera_vtk::RenamedArraysWarning(more, "cell-data", "the clipped tiles' outlines", "cell");
  }

private:
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkIdTypeArray> PolygonIds;
  vtkNew<vtkUnsignedCharArray> Holes;
  vtkIdType NextPolygon = 0;
};

/// Whether bounds lie within the degrees a longitude and a latitude take (tessera::InLonLatRange
/// at two opposite corners).
bool WithinDegrees(const double bounds[6])
{
  return tessera::InLonLatRange({ bounds[0], bounds[2] }) &&
    tessera::InLonLatRange({ bounds[1], bounds[3] });
}

/// Whether bounds reach metres (tessera::LooksProjected at the corner farthest out).
bool ReachesMetres(const double bounds[6])
{
  return tessera::LooksProjected({ std::max(std::fabs(bounds[0]), std::fabs(bounds[1])),
    std::max(std::fabs(bounds[2]), std::fabs(bounds[3])) });
}

std::string BoundsText(const double bounds[6])
{
  return "x " + tessera::NumberText(bounds[0]) + " to " + tessera::NumberText(bounds[1]) + ", y " +
    tessera::NumberText(bounds[2]) + " to " + tessera::NumberText(bounds[3]);
}

/// Tiles and window in two different planes would be clipped as if in one, the areas wrong by
/// the projections' difference, silently: two automatic projections of different data (gauges
/// and catchment projected apart) differ. Throws when the inputs' TesseraProjection records
/// differ, and when one input has a record in metres and the other none, in degrees (tiles of
/// lon/lat gauges clipped to a projected catchment came out whole, covering 2.5e-10 of it, with
/// a warning only); returns a warning when only one input has a record otherwise, else "".
std::string ProjectionWarning(vtkDataObject* tiles, vtkDataObject* window)
{
  const std::string ofTiles = tessera_vtk::ProjectionRecordOf(tiles, "input 0 (the tiles)");
  const std::string ofWindow = tessera_vtk::ProjectionRecordOf(window, "input 1 (the window)");
  if (!ofTiles.empty() && !ofWindow.empty() &&
    !tessera::SameProjection(tessera::ProjectionParameters::FromString(ofTiles),
      tessera::ProjectionParameters::FromString(ofWindow)))
  {
    throw tessera::InputError("the tiles (input 0) and the window (input 1) were projected "
                              "differently (tiles: " +
      ofTiles + "; window: " + ofWindow +
      "): project both with one projection (give the window's Geographic Projection the tiles' "
      "record as its Projection Record, copied from the tiles' TesseraProjection field data, or "
      "Group Datasets the gauges and the catchment before one Geographic Projection), or use "
      "Thiessen Areal Average, which projects gauges and catchment together");
  }
  if (ofTiles.empty() == ofWindow.empty())
  {
    return std::string();
  }
  const std::string projected = ofTiles.empty() ? "the window (input 1)" : "the tiles (input 0)";
  const std::string other = ofTiles.empty() ? "the tiles (input 0)" : "the window (input 1)";
  // (verbs agree with their input: "the tiles are", "the window is")
  const bool tilesProjected = !ofTiles.empty();
  const char* const is = tilesProjected ? " are" : " is";
  const char* const carries = tilesProjected ? " carry" : " carries";
  const char* const otherCarries = tilesProjected ? " carries" : " carry";
  const char* const otherLooks = tilesProjected ? " looks" : " look";
  const std::string it = tilesProjected ? "it" : "them",
                    itIs = tilesProjected ? "it is" : "they are";
  double projectedBounds[6], otherBounds[6];
  if (!tessera_vtk::DataBounds(ofTiles.empty() ? tiles : window, otherBounds) ||
    !tessera_vtk::DataBounds(ofTiles.empty() ? window : tiles, projectedBounds))
  {
    // (an empty input is said to be empty, not to carry a record or none: tiles whose
    // tessellation failed upstream were said to carry none, which pointed at the projection)
    return std::string();
  }
  if (ReachesMetres(projectedBounds) && WithinDegrees(otherBounds))
  {
    throw tessera::InputError(projected + is + " projected (TesseraProjection " + ofTiles +
      ofWindow + "; " + BoundsText(projectedBounds) + ") and " + other + otherCarries +
      " no record and" + otherLooks + " like longitude and latitude in degrees (" +
      BoundsText(otherBounds) + "): project " + it +
      " too, with Geographic Projection's Projection Record set to that record (or Group Datasets "
      "the gauges and the catchment before one Geographic Projection); if " +
      itIs + " in that plane already, remove the TesseraProjection field data of " + projected);
  }
  return projected + carries + " a TesseraProjection record (" + ofTiles + ofWindow + ") and " +
    other + " none: both are taken to be in the same plane";
}

/// A block of tiles with a TesseraProjection record of its own, against the window's (the whole
/// composite's record, checked first, hides the blocks' when it has one); throws naming the block.
void CheckBlockProjection(vtkPointSet* tiles, vtkDataObject* window, const std::string& block)
{
  if (tessera_vtk::ProjectionRecordOf(tiles, "input 0 (the tiles)").empty())
  {
    return;
  }
  try
  {
    ProjectionWarning(tiles, window); // (its warning, if any, was given for the whole input)
  }
  catch (const tessera::InputError& e)
  {
    throw tessera::InputError(block + " of input 0: " + e.what());
  }
}

/// A block of tiles as a point set; throws InputError naming the block (label) if it is none.
vtkPointSet* PointSetOfBlock(vtkDataObject* leaf, const std::string& label)
{
  auto* tiles = vtkPointSet::SafeDownCast(leaf);
  if (!tiles)
  {
    throw tessera::InputError(label + " of input 0 (the tiles) is a " + leaf->GetClassName() +
      ": only point sets (vtkPolyData, vtkUnstructuredGrid, ...) are clipped");
  }
  return tiles;
}

/// The power of two 2^e that brings a window whose largest coordinate (in magnitude) is below
/// 2^-128 to [1, 2): the clip then works as at unit scale. 0 for any other window (a window too
/// large is an error where a tile's area overflows).
int UpScaleExponent(const std::vector<tessera::Point2>& vertices)
{
  if (vertices.empty())
  {
    return 0; // (rings without vertices: the window's own check names them)
  }
  const tessera::Box2 box = tessera::BoundsOf(vertices.data(), vertices.size());
  const double reach = std::max(
    { std::fabs(box.XMin), std::fabs(box.XMax), std::fabs(box.YMin), std::fabs(box.YMax) });
  return std::max(tessera::RangeScaleExponentOf(reach), 0);
}

/// The clip's window from the rings read (vertices: theirs, scaled); an error about rings names
/// the cells they came from (the core numbers rings, not cells).
tessera::Catchment WindowOf(const tessera_vtk::Rings& rings,
  const std::vector<tessera::Point2>& vertices)
{
  try
  {
    return tessera::Catchment(rings.Offsets, vertices);
  }
  catch (const tessera::RingError& error)
  {
    throw tessera_vtk::WithRingSources(error, rings, "window (input 1)");
  }
}

/// The clip's window from the rings read, scaled by 2^exponent (UpScaleExponent). Throws
/// InputError for a window whose area overflows or whose rings cancel out.
tessera::Catchment ScaledWindowOf(const tessera_vtk::Rings& window, int exponent)
{
  std::vector<tessera::Point2> windowVertices = window.Vertices;
  for (tessera::Point2& p : windowVertices)
  {
    p = { std::ldexp(p.x, exponent), std::ldexp(p.y, exponent) };
  }
  tessera::Catchment catchment = WindowOf(window, windowVertices);
  if (!std::isfinite(catchment.Area()))
  {
    throw tessera::InputError("the window (input 1): its area overflows (coordinates of some "
                              "1e154 or more); scale the tiles and the window down");
  }
  if (catchment.RingsCancelOut())
  {
    // (an empty output without an error, CoveredFraction 0 / 0 written as 0, or a warning that
    // blamed the tiles for having no area to clip)
    throw tessera::InputError(
      "the window (input 1) has no area: " + catchment.RingsCancelOutText() +
      "; give the outer ring alone, or each part as a window of its own");
  }
  return catchment;
}

/// For a tile that is not convex: where the tiles are vtkThiessenArealAverage's (its cell arrays
/// Area_m2 and CellWeight), what to do instead. Its tiles come in lon/lat, their edges densified:
/// convex in the plane where they were made, not in lon/lat, so splitting them (what the error
/// advises) was no help to a user clipping them to a sub-basin.
std::string ThiessenTilesNote(vtkPointSet* tiles)
{
  vtkCellData* data = tiles ? tiles->GetCellData() : nullptr;
  if (!data || !data->GetAbstractArray("Area_m2") || !data->GetAbstractArray("CellWeight"))
  {
    return std::string();
  }
  return ". These look like Thiessen Areal Average's tiles, which are convex in its projected "
         "plane, not in lon/lat: for the weights over a sub-basin, give it the sub-basin as its "
         "catchment; to clip tiles, clip Dirichlet Tessellation's tiles of the projected gauges "
         "by the projected sub-basin (one ProjectionRecord for both)";
}

/// A field-data array of one double.
vtkSmartPointer<vtkDoubleArray> OneValue(const char* name, double value)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  return array;
}

/// Throws InputError for tiles that are neither a point set nor a composite data set, for no
/// window, or for a window that is a data set of another type than vtkPolyData.
void CheckInputTypes(vtkDataObject* tiles, vtkDataObject* window)
{
  if (!tiles) // (port 0 is required: a producer that gave no data object at all)
  {
    throw tessera::InputError("input 0 holds no tiles (no data object)");
  }
  if (!vtkPointSet::SafeDownCast(tiles) && !vtkCompositeDataSet::SafeDownCast(tiles))
  {
    throw tessera::InputError(std::string("the tiles (input 0) are a ") + tiles->GetClassName() +
      ", not a point set (vtkPolyData, vtkUnstructuredGrid, ...) nor a composite of them");
  }
  if (!window)
  {
    throw tessera::InputError("no window is connected to input 1 (SetWindowData or "
                              "SetWindowConnection; in ParaView, the filter's Window input)");
  }
  // (said before the projection records are compared: a trial's image window beside projected
  // tiles was told to be projected, where no window of that type is read at all)
  if (vtkDataSet::SafeDownCast(window) && !vtkPolyData::SafeDownCast(window))
  {
    throw tessera::InputError(std::string("the window (input 1) is a ") + window->GetClassName() +
      ": only vtkPolyData (or a composite data set of it) is read as a window; " +
      tessera_vtk::ExtractSurfaceHint);
  }
}

/// Whether data (a data set, or a composite's data sets) has a cell.
bool HasCells(vtkDataObject* data)
{
  if (auto* blocks = vtkCompositeDataSet::SafeDownCast(data))
  {
    return blocks->GetNumberOfCells() > 0;
  }
  auto* set = vtkDataSet::SafeDownCast(data);
  return set && set->GetNumberOfCells() > 0;
}

/// For tiles whose bounding box and the window's share no area, so that the output is empty: both
/// boxes (a ParaView user got an empty output and no message, CoveredFraction 0 in the field
/// data); empty where they overlap (tiles in a gap of the window, or cells that are no polygons,
/// which ClipTilesOf's warnings name).
std::string ApartWarning(const double tilesBounds[6], const std::vector<tessera::Point2>& window)
{
  const tessera::Box2 tiles{ tilesBounds[0], tilesBounds[1], tilesBounds[2], tilesBounds[3] };
  const tessera::Box2 box = tessera::BoundsOf(window.data(), window.size());
  if (tiles.Overlaps(box)) // (boxes that only touch share no area either)
  {
    return std::string();
  }
  return "the tiles (input 0) and the window (input 1) do not meet, so the output is empty: the "
         "tiles span " +
    tessera_vtk::BoxText(tiles) + ", the window " + tessera_vtk::BoxText(box) +
    " (are both in the same units and projection?)";
}

/// The tiles' point data is not passed (their cell and field data are): the pieces' vertices are
/// new points, crossings of tile edges and window rings among them. A warning names its arrays.
std::string PointDataWarning(vtkPointSet* tiles)
{
  vtkPointData* pointData = tiles->GetPointData();
  const int count = pointData->GetNumberOfArrays();
  if (count == 0)
  {
    return std::string();
  }
  const std::string names = tessera_vtk::ListNames(static_cast<std::size_t>(count),
    [pointData](std::size_t k)
    {
      const char* name = pointData->GetArrayName(static_cast<int>(k));
      return "'" + std::string(name ? name : "(unnamed)") + "'";
    });
  return "the point data of input 0 (" + names +
    ") is not passed: the clipped pieces' vertices are new points (the tiles' cell data is "
    "passed)";
}

/// Throws InputError naming the cells where a tile given as a closed polyline, with a part in the
/// window, lies inside another:
/// the GDAL reader gives a polygon's outline and each of its holes as a closed polyline of their
/// own, and the hole, clipped as a tile, counted twice (a 4 x 4 square with a 2 x 2 hole gave
/// clipped areas 16 and 4, with no word).
void ThrowForHolesAmong(const tessera::ClippedRings& lineTiles, const std::vector<vtkIdType>& cells)
{
  if (cells.size() < 2)
  {
    return;
  }
  const auto nested = tessera::FindRingInsideAnother(lineTiles.RingOffsets, lineTiles.Vertices);
  if (nested)
  {
    throw tessera::InputError("cell " + std::to_string(cells[nested->second]) +
      " of input 0, a closed polyline, lies inside cell " + std::to_string(cells[nested->first]) +
      ", another: a polygon with a hole, as the GDAL reader gives one (a cell a ring), is no "
      "convex tile, and its hole would be clipped as a tile of its own; split such polygons "
      "into convex parts without holes first");
  }
}

/// Appends warning unless it is empty (nothing to say).
void AppendIfAny(std::vector<std::string>& warnings, std::string warning)
{
  if (!warning.empty())
  {
    warnings.push_back(std::move(warning));
  }
}

/// The warnings about the tiles' own data: their cell-data arrays longer than their cells
/// (LongAttributeWarnings), then their point data, which is not passed (PointDataWarning).
void AppendTileDataWarnings(vtkPointSet* tiles, std::vector<std::string>& warnings)
{
  for (std::string& warning :
    tessera_vtk::LongAttributeWarnings(tiles, "the tiles (input 0)", false))
  {
    warnings.push_back(std::move(warning));
  }
  AppendIfAny(warnings, PointDataWarning(tiles));
}

/// Output 0 of one point set of tiles: each clipped tile's display pieces as polygons, with the
/// tile's cell data, TileId, ClippedArea, AreaFraction (the active scalars) and PieceArea.
class PieceCells : TileCells
{
public:
  PieceCells(vtkPointSet* tiles, vtkPolyData* output)
    : TileCells(tiles, output, OwnArrayNames)
  {
    this->PieceAreas->SetName(OwnArrayNames[3]);
  }

  /// Tile c's display pieces (scaled by 2^exponent), a polygon each, with its clipped area and
  /// area fraction.
  void Append(const tessera::ClippedRings& pieces,
    vtkIdType c,
    int exponent,
    double clippedArea,
    double fraction)
  {
    for (std::size_t r = 0; r + 1 < pieces.RingOffsets.size(); ++r)
    {
      const std::size_t begin = pieces.RingOffsets[r], end = pieces.RingOffsets[r + 1];
      this->InsertPolygon(&pieces.Vertices[begin], end - begin, exponent);
      this->AddTileData(c, this->Polys->GetNumberOfCells() - 1, clippedArea, fraction);
      this->PieceAreas->InsertNextValue(std::ldexp(
        tessera::CompensatedPolygonArea(&pieces.Vertices[begin], end - begin), -2 * exponent));
    }
  }

  /// Puts the pieces into the output; returns the warning for input arrays renamed, if any.
  std::string Finish()
  {
    this->AttachTileData();
    this->Output->SetPolys(this->Polys);
    this->CellData->AddArray(this->PieceAreas);
    // Coloured by the share of each tile inside the window (not by an input's active scalars,
    // such as the tessellation's Area of the whole, unclipped tile).
    this->CellData->SetActiveScalars(this->Fractions->GetName());
    return this->Renamed.empty()
      ? std::string()
      : tessera_vtk::RenamedArraysWarning(this->Renamed, "cell-data", "the clipped tiles", "cell");
  }

private:
  /// A polygon of the count vertices, scaled back by 2^-exponent.
  void InsertPolygon(const tessera::Point2* vertices, std::size_t count, int exponent)
  {
    this->Polys->InsertNextCell(static_cast<vtkIdType>(count));
    for (std::size_t k = 0; k < count; ++k)
    {
      const auto& a = vertices[k];
      this->Polys->InsertCellPoint(
        this->Points->InsertNextPoint(std::ldexp(a.x, -exponent), std::ldexp(a.y, -exponent), 0.0));
    }
  }

  vtkNew<vtkCellArray> Polys;
  vtkNew<vtkDoubleArray> PieceAreas;
};

/// How a cell of the tiles is clipped (CellRingIds).
enum class TileKind
{
  NotClipped, ///< not a polygon, triangle, quad, pixel or closed polyline, or of under 3 points
  Polygon,
  ClosedLine ///< a polygon's ring as vtkGDALVectorReader gives it
};

/// A pixel's ids in ring order.
void PixelIdsAsRing(vtkIdList* ids)
{
  // A pixel's points go row by row (0 1 / 2 3): its ring is 0 1 3 2.
  const vtkIdType third = ids->GetId(2);
  ids->SetId(2, ids->GetId(3));
  ids->SetId(3, third);
}

/// How cell c of the tiles is clipped, and (but for NotClipped) its ring's point ids in ids.
TileKind CellRingIds(vtkPointSet* tiles, vtkIdType c, vtkIdList* ids)
{
  const int type = tiles->GetCellType(c);
  const bool polygon =
    type == VTK_POLYGON || type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_PIXEL;
  if (!polygon && type != VTK_POLY_LINE)
  {
    return TileKind::NotClipped;
  }
  tiles->GetCellPoints(c, ids);
  if (type == VTK_PIXEL)
  {
    PixelIdsAsRing(ids);
  }
  if (!polygon)
  {
    // A closed polyline is a polygon's ring as vtkGDALVectorReader gives it (a shapefile's
    // tiles): its last point, the first again, is dropped. An open one is no tile.
    if (!tessera_vtk::IsClosedLine(tiles, ids))
    {
      return TileKind::NotClipped;
    }
    ids->SetNumberOfIds(ids->GetNumberOfIds() - 1);
  }
  if (ids->GetNumberOfIds() < 3)
  {
    // A polygon collapsed to 1 or 2 points (a tessellation's tile between points some
    // nanometres apart can be): nothing to clip.
    return TileKind::NotClipped;
  }
  return polygon ? TileKind::Polygon : TileKind::ClosedLine;
}

/// The tiles' points at ids, scaled by 2^exponent as the window is, into tile.
void ScaledCorners(vtkPointSet* tiles,
  vtkIdList* ids,
  int exponent,
  std::vector<tessera::Point2>& tile)
{
  tile.resize(ids->GetNumberOfIds());
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    double p[3];
    tiles->GetPoint(ids->GetId(k), p);
    tile[k] = { std::ldexp(p[0], exponent), std::ldexp(p[1], exponent) };
  }
}

/// Tile c's own area, its corners turned anticlockwise (tessera_vtk::OrientAnticlockwise). Throws
/// InputError where finite corners give an area beyond the doubles.
double OwnAreaOf(std::vector<tessera::Point2>& tile, vtkIdType c, int exponent)
{
  const double ownArea = tessera_vtk::OrientAnticlockwise(tile);
  const bool finiteCorners = std::all_of(tile.begin(),
    tile.end(),
    [](const tessera::Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
  if (finiteCorners && !std::isfinite(ownArea)) // (a NaN corner is named by the clip after this)
  {
    // (a window of tiny coordinates scales the tiles up with it: a unit tile in a window of
    // 1e-300 was said to have "coordinates of some 1e154 or more")
    throw tessera::InputError("cell " + std::to_string(c) + " of input 0: its area overflows" +
      (exponent > 0
          ? " at the window's scale: the window (input 1) is so small (coordinates below 2^-128) "
            "that tiles and window are clipped scaled up by 2^" +
            std::to_string(exponent) +
            ", and this tile is then beyond the doubles (some 1e154 times the window's size "
            "or more); clip tiles of the window's size"
          : std::string(" (coordinates of some 1e154 or more); scale the tiles and the window "
                        "down")));
  }
  return ownArea;
}

/// The rounding a tile's convexity is checked to: a float's for tiles whose points are floats.
double ConvexityEpsilon(vtkPointSet* tiles)
{
  // Tiles whose points are floats are convex up to a float's rounding (the clip's convexity
  // check allows for it).
  const bool floatPoints = tiles->GetPoints() && tiles->GetPoints()->GetDataType() == VTK_FLOAT;
  return floatPoints ? std::numeric_limits<float>::epsilon()
                     : std::numeric_limits<double>::epsilon();
}

/// ClipBlock's loop over the tiles of one point set: clips each into PieceCells and OutlineCells,
/// lists the cells it does not clip (SkippedCellIds) and those with no area to clip in the window
/// (EmptyTileIds), and sums the clipped areas.
class TileClipper
{
public:
  TileClipper(vtkPointSet* tiles,
    const tessera::Catchment& catchment,
    int exponent,
    PieceCells& pieceCells,
    OutlineCells& outlineCells)
    : Tiles(tiles)
    , Window(catchment)
    , Exponent(exponent)
    , Epsilon(ConvexityEpsilon(tiles))
    , Pieces(pieceCells)
    , Outlines(outlineCells)
  {
    this->Skipped->SetName("SkippedCellIds");
    this->Empty->SetName("EmptyTileIds");
  }

  /// Clips every cell; progress(fraction done).
  void ClipAll(const std::function<void(double)>& progress)
  {
    const vtkIdType cellCount = this->Tiles->GetNumberOfCells();
    for (vtkIdType c = 0; c < cellCount; ++c)
    {
      if (c % 4096 == 0)
      {
        progress(static_cast<double>(c) / std::max<vtkIdType>(cellCount, 1));
      }
      this->ClipCell(c);
    }
  }

  /// Throws where a tile given as a closed polyline lies inside another (ThrowForHolesAmong).
  void ThrowForHoles() const { ThrowForHolesAmong(this->LineTiles, this->LineTileCells); }

  /// Adds EmptyTileIds, SkippedCellIds, WindowArea and CoveredFraction to fieldData.
  void AddFieldArrays(vtkFieldData* fieldData) const
  {
    // Both lists always (empty or not), as the other filters write theirs: a script reads them
    // without testing for a missing array.
    fieldData->AddArray(this->Empty);
    fieldData->AddArray(this->Skipped);
    const double windowArea = std::ldexp(this->Window.Area(), -2 * this->Exponent);
    fieldData->AddArray(OneValue("WindowArea", windowArea));
    // (of the scaled areas: a window of 1e-300 has an area below the doubles, 0 once scaled back)
    fieldData->AddArray(OneValue("CoveredFraction",
      this->Window.Area() > 0.0 ? this->Covered.Value() / this->Window.Area() : 0.0));
  }

  /// The warnings counting the cells listed in EmptyTileIds, then in SkippedCellIds.
  void AppendListWarnings(std::vector<std::string>& warnings) const
  {
    if (this->Empty->GetNumberOfValues() > 0)
    {
      warnings.push_back(std::to_string(this->Empty->GetNumberOfValues()) +
        " polygon(s) of input 0 lie in the window but have no area to clip (collinear corners, or "
        "thinner than the clip's rounding, or some 10^14 times the window's size, its part in them "
        "below that rounding), so they give no piece (the first is cell " +
        std::to_string(this->Empty->GetValue(0)) +
        "); their ids are in the field data array EmptyTileIds.");
    }
    if (this->Skipped->GetNumberOfValues() > 0)
    {
      warnings.push_back(std::to_string(this->Skipped->GetNumberOfValues()) +
        " cell(s) of input 0 are not polygons of 3 or more points, triangles, quads, pixels or "
        "closed polylines (the first is cell " +
        std::to_string(this->Skipped->GetValue(0)) +
        ") and were not clipped; their ids are in the field data array SkippedCellIds.");
    }
  }

private:
  /// Clips cell c if it is a tile (else lists it as skipped).
  void ClipCell(vtkIdType c)
  {
    const TileKind kind = CellRingIds(this->Tiles, c, this->Ids);
    if (kind == TileKind::NotClipped)
    {
      this->Skipped->InsertNextValue(c);
      return;
    }
    ScaledCorners(this->Tiles, this->Ids, this->Exponent, this->Tile);
    const double ownArea = OwnAreaOf(this->Tile, c, this->Exponent);
    const double clipped = this->ClipTile(c);
    if (clipped <= 0.0)
    {
      // Outside the window, or without area to clip: collinear corners, or a sliver thinner
      // than the clip's rounding. The latter lie in the window, and are reported.
      if (this->Window.HoldsPartOf(this->Tile.data(), this->Tile.size()))
      {
        this->Empty->InsertNextValue(c);
      }
      return;
    }
    if (kind == TileKind::ClosedLine)
    {
      // (only those with a part in the window: a holed polygon outside it counts nothing twice)
      this->LineTiles.Vertices.insert(
        this->LineTiles.Vertices.end(), this->Tile.begin(), this->Tile.end());
      this->LineTiles.RingOffsets.push_back(this->LineTiles.Vertices.size());
      this->LineTileCells.push_back(c);
    }
    this->Covered.Add(clipped);
    this->AddPieces(c, clipped, ownArea);
  }

  /// The area of tile c (Tile) inside the window, its rings (ClipInto's) in Rings.
  double ClipTile(vtkIdType c)
  {
    this->Rings.RingOffsets.assign(1, 0);
    this->Rings.Vertices.clear();
    return this->Window.ClipInto(this->Tile.data(),
      this->Tile.size(),
      static_cast<std::size_t>(c),
      this->Work,
      &this->Rings,
      tessera::Catchment::FoldedTile::IsAnError,
      this->Epsilon);
  }

  /// Tile c's display pieces and outline, from the rings of its clipped area.
  void AddPieces(vtkIdType c, double clipped, double ownArea)
  {
    // ClipInto's rings are right for areas, not for display (zero-width spikes and bridges,
    // lobes joined into one ring, holes as clockwise rings): one cell per display piece instead,
    // each a simple polygon, the pieces disjoint and filling tile & window.
    const tessera::ClippedRings pieces = tessera::DisplayPieces(this->Rings);
    // (At most 1: the two areas are summed differently, and a tile inside the window gave
    // 1 + 2^-52.)
    const double fraction = ownArea > 0.0 ? std::min(1.0, clipped / ownArea) : 0.0;
    const double clippedArea = std::ldexp(clipped, -2 * this->Exponent);
    this->Outlines.Append(pieces, c, this->Exponent, clippedArea, fraction);
    this->Pieces.Append(pieces, c, this->Exponent, clippedArea, fraction);
  }

  vtkPointSet* Tiles;
  const tessera::Catchment& Window; // (its coordinates scaled by 2^Exponent)
  int Exponent;
  double Epsilon;
  PieceCells& Pieces;
  OutlineCells& Outlines;
  tessera::Catchment::Workspace Work;
  std::vector<tessera::Point2> Tile;
  vtkNew<vtkIdList> Ids;
  tessera::ClippedRings Rings;     // reused: ClipInto appends to it
  tessera::ClippedRings LineTiles; // the tiles given as closed polylines, and their cells
  std::vector<vtkIdType> LineTileCells;
  vtkNew<vtkIdTypeArray> Skipped;  // cells that are not polygons: reported, not clipped
  vtkNew<vtkIdTypeArray> Empty;    // polygons in the window without area to clip: reported
  tessera::CompensatedSum Covered; // the clipped areas (scaled as the window is)
};

/// Clips the tiles (one point set: the input, or a block of it) by the window (catchment, its
/// coordinates scaled by 2^exponent) into output, with the tiles' field data and the clip's own,
/// and their outlines into outlines (OutlineCells). Throws tessera::InputError for bad tiles;
/// appends its warnings; progress(fraction done).
void ClipBlock(vtkPointSet* tiles,
  const tessera::Catchment& catchment,
  int exponent,
  vtkPolyData* output,
  vtkPolyData* outlines,
  const std::function<void(double)>& progress,
  std::vector<std::string>& warnings)
{
  // (the tiles' arrays are copied by cell id: a short one was read past its end)
  tessera_vtk::CheckArraysAndCellPointIds(tiles, "the tiles (input 0)");
  AppendTileDataWarnings(tiles, warnings);
  if (output->GetFieldData()->GetNumberOfArrays() == 0)
  {
    output->GetFieldData()->PassData(tiles->GetFieldData()); // (a block's: the pipeline's is not)
  }
  PieceCells pieceCells(tiles, output);
  OutlineCells outlineCells(tiles, outlines);
  TileClipper clipper(tiles, catchment, exponent, pieceCells, outlineCells);
  clipper.ClipAll(progress);
  clipper.ThrowForHoles();
  AppendIfAny(warnings, pieceCells.Finish());
  AppendIfAny(warnings, outlineCells.Finish());
  clipper.AddFieldArrays(output->GetFieldData());
  clipper.AppendListWarnings(warnings);
}

} // namespace

//------------------------------------------------------------------------------
vtkWindowClip::vtkWindowClip()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
int vtkWindowClip::FillInputPortInformation(int port, vtkInformation* info)
{
  // Tiles as a point set (vtkPolyData; vtkUnstructuredGrid, as ParaView's Threshold gives a
  // selection of tiles), or a composite of them (a shapefile's polygons read by
  // vtkGDALVectorReader, say), clipped here block by block (not by the composite pipeline, which
  // kept the other blocks' pieces after an error, and whose messages could not name the block).
  // Any data object on either port, and the window optional: RequestData names a wrong type or a
  // missing window in an error of its own (the pipeline's checks stopped before RequestData, with
  // a log line and no ErrorEvent from the filter, which scripts observe).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkWindowClip::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // The window whole on every process (ParaView under MPI asks each for a piece); the tiles may
  // come in pieces, each clipped on its own.
  tessera_vtk::RequestWholeInputs(inputVector, 1, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkWindowClip::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkDataObject* tilesData = vtkDataObject::GetData(inputVector[0]);
  vtkDataObject* windowData = vtkDataObject::GetData(inputVector[1]);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkDataObject* outlines = vtkDataObject::GetData(outputVector, 1);
  try
  {
    this->ClipByWindow(tilesData, windowData, output, outlines, outputVector);
    return 1;
  }
  catch (const std::exception& e)
  {
    // (a stop that a progress observer asked for empties the outputs too, without an error)
    output->Initialize();
    outlines->Initialize();
    return tesseraErrorOrStopMacro(e);
  }
}

//------------------------------------------------------------------------------
void vtkWindowClip::ClipByWindow(vtkDataObject* tilesData,
  vtkDataObject* windowData,
  vtkDataObject* output,
  vtkDataObject* outlines,
  vtkInformationVector* outputVector)
{
  CheckInputTypes(tilesData, windowData);
  tesseraWarnUnlessEmptyMacro(this, ProjectionWarning(tilesData, windowData));
  std::vector<std::string> ringWarnings;
  const tessera_vtk::Rings window =
    tessera_vtk::ReadPolygonRings(windowData, "window (input 1)", ringWarnings);
  tesseraWarnEachMacro(this, ringWarnings);
  // A window of tiny coordinates is clipped scaled up by a power of two (exact), tiles alike,
  // and the results scaled back: below some 1e-150 the clip's products fell below the doubles,
  // and areas came out wrong (a fraction of 0.945 for 17/18 at 1e-161) or not at all.
  const int exponent = UpScaleExponent(window.Vertices);
  const tessera::Catchment catchment = ScaledWindowOf(window, exponent);
  double tilesBounds[6];
  const bool tilesHavePoints = tessera_vtk::DataBounds(tilesData, tilesBounds);
  if (!tilesHavePoints)
  {
    vtkWarningMacro(<< "the tiles (input 0) have no points, so nothing is clipped (did the filter "
                       "that makes them fail?)");
  }
  this->ClipTiles(tilesData, windowData, catchment, exponent, output, outlines);
  // (not for one process's piece of the tiles under MPI: each is clipped alone, and a piece
  // away from the window gives nothing by design)
  if (tilesHavePoints && HasCells(tilesData) && !HasCells(output) && !window.Vertices.empty() &&
    !tessera_vtk::IsPieceOfMany(outputVector))
  {
    tesseraWarnUnlessEmptyMacro(this, ApartWarning(tilesBounds, window.Vertices));
  }
  tessera_vtk::ListNonEmptyFieldArraysFirst(output);
  tessera_vtk::ListNonEmptyFieldArraysFirst(outlines);
}

//------------------------------------------------------------------------------
void vtkWindowClip::ClipTiles(vtkDataObject* tilesData,
  vtkDataObject* windowData,
  const tessera::Catchment& catchment,
  int exponent,
  vtkDataObject* output,
  vtkDataObject* outlines)
{
  auto* blocks = vtkCompositeDataSet::SafeDownCast(tilesData);
  if (!blocks)
  {
    tesseraWarnEachMacro(this,
      this->ClipTilesOf(vtkPointSet::SafeDownCast(tilesData),
        catchment,
        exponent,
        vtkPolyData::SafeDownCast(output),
        vtkPolyData::SafeDownCast(outlines),
        std::string(),
        0.0,
        1.0));
    return;
  }
  // Block by block, each clipped alone (its CoveredFraction its share of the window); an
  // error names its block and leaves the whole output empty.
  auto* outBlocks = vtkCompositeDataSet::SafeDownCast(output);
  auto* outlineBlocks = vtkCompositeDataSet::SafeDownCast(outlines);
  for (vtkCompositeDataSet* made : { outBlocks, outlineBlocks })
  {
    made->CopyStructure(blocks);
    made->GetFieldData()->PassData(blocks->GetFieldData());
  }
  this->WarnFirstFew(
    this->ClipBlocks(blocks, windowData, catchment, exponent, outBlocks, outlineBlocks));
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkWindowClip::ClipBlocks(vtkCompositeDataSet* blocks,
  vtkDataObject* windowData,
  const tessera::Catchment& catchment,
  int exponent,
  vtkCompositeDataSet* outBlocks,
  vtkCompositeDataSet* outlineBlocks)
{
  std::vector<std::string> warnings;
  const tessera_vtk::BlockLabels labels(blocks);
  vtkSmartPointer<vtkCompositeDataIterator> block;
  block.TakeReference(blocks->NewIterator());
  const double count = std::max(1.0, static_cast<double>(blocks->GetNumberOfCells()));
  double done = 0.0;
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
  {
    vtkDataObject* leaf = block->GetCurrentDataObject();
    const std::string label = labels.Of(block);
    vtkPointSet* tiles = PointSetOfBlock(leaf, label);
    CheckBlockProjection(tiles, windowData, label);
    vtkNew<vtkPolyData> clipped, clippedOutlines;
    const double cells = static_cast<double>(tiles->GetNumberOfCells());
    const std::vector<std::string> said = this->ClipTilesOf(tiles,
      catchment,
      exponent,
      clipped,
      clippedOutlines,
      label + " of input 0: ",
      done / count,
      (done + cells) / count);
    warnings.insert(warnings.end(), said.begin(), said.end());
    done += cells;
    outBlocks->SetDataSet(block, clipped);
    outlineBlocks->SetDataSet(block, clippedOutlines);
  }
  return warnings;
}

//------------------------------------------------------------------------------
void vtkWindowClip::WarnFirstFew(const std::vector<std::string>& warnings)
{
  // The first few (a layer of 10,000 features gave 10,000), then their count.
  constexpr std::size_t shown = 5;
  for (std::size_t k = 0; k < std::min(shown, warnings.size()); ++k)
  {
    vtkWarningMacro(<< warnings[k]);
  }
  if (warnings.size() > shown)
  {
    vtkWarningMacro(<< warnings.size() - shown
                    << " more warning(s) about blocks of input 0 are not shown (the first " << shown
                    << " are)");
  }
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkWindowClip::ClipTilesOf(vtkPointSet* tiles,
  const tessera::Catchment& catchment,
  int exponent,
  vtkPolyData* output,
  vtkPolyData* outlines,
  const std::string& block,
  double progressFrom,
  double progressTo)
{
  std::vector<std::string> warnings;
  try
  {
    ClipBlock(
      tiles,
      catchment,
      exponent,
      output,
      outlines,
      [&](double fraction)
      { tessera_vtk::ProgressOrStop(this, progressFrom + fraction * (progressTo - progressFrom)); },
      warnings);
  }
  catch (const tessera::NotConvexError& e)
  {
    throw tessera::InputError(block + e.what() + ThiessenTilesNote(tiles));
  }
  catch (const tessera::InputError& e)
  {
    throw tessera::InputError(block + e.what());
  }
  for (std::string& warning : warnings)
  {
    warning.insert(0, block);
  }
  return warnings;
}

//------------------------------------------------------------------------------
int vtkWindowClip::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkWindowClip::ProcessRequest(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkWindowClip::RequestDataObject(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // The tiles' kind: a vtkPolyData, or a composite of the same class as the tiles' (a
  // vtkPolyData too for no input yet, or one of another type, which RequestData refuses).
  tessera_vtk::MakeCompositeOrPolyDataOutput(
    vtkCompositeDataSet::GetData(inputVector[0], 0), outputVector);
  return 1;
}

//------------------------------------------------------------------------------
void vtkWindowClip::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
