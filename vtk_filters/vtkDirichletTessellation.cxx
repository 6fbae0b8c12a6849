#include "vtkDirichletTessellation.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include "TesseraFilterUtilities.h"
#include "dirichlet_tessellation.h"
#include "errors.h"
#include "large_pages.h"
#include "order_by_key.h"
#include "parallel_chunks.h"
#include "thiessen_sweep.h"
#include "tiles.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkDirichletTessellation);

namespace
{

/// What either engine produces, in the core's flat arrays.
struct TessellationResult
{
  tessera::TileMesh Tiles;
  tessera::ContiguityGraph Graph;
  std::vector<std::int32_t> Rejected;
  std::vector<std::pair<std::int32_t, std::int32_t>> Duplicates;
};

TessellationResult RunGreenSibson(tessera::Window window,
  std::vector<tessera::Point2> points,
  bool withGraph,
  vtkAlgorithm* filter)
{
  const tessera::DirichletTessellation tessellation(std::move(window), std::move(points));
  tessera_vtk::ProgressOrStop(filter, 0.45); // (the build is about half of the engine's time)
  tessera::TileMeshAndGraph both =
    tessera::TessellationDual(tessellation).TileMeshAndContiguities(withGraph);
  return { std::move(both.Tiles),
    std::move(both.Graph),
    tessellation.RejectedIds(),
    tessellation.Duplicates() };
}

TessellationResult RunBrasselReif(const tessera::Window& window,
  std::vector<tessera::Point2> points,
  vtkAlgorithm* filter)
{
  const std::string notRectangle = tessera::WhyNotAnAxisAlignedRectangle(window);
  if (!notRectangle.empty())
  {
    throw tessera::InputError("the Brassel-Reif algorithm (BrasselReif) needs a window that is a "
                              "rectangle with sides parallel to the axes (WindowBounds, or "
                              "constraints that make one), and " +
      notRectangle + "; use Green-Sibson (GreenSibson) for other windows");
  }
  tessera::ThiessenSweepResult sweep =
    tessera::ComputeThiessenSweep(window, points, tessera_vtk::StageProgress(filter, 0.1, 0.75));
  return { tessera::MeshOfNumberedCorners(std::move(sweep.Tiles), sweep.CornerVertexIds),
    std::move(sweep.Contiguities),
    std::move(sweep.RejectedIds),
    std::move(sweep.Duplicates) };
}

/// The cell arrays use 32-bit storage, which VTK reads like the 64-bit kind: half the memory to
/// fill. Both engines hold fewer than INT32_MAX / 8 points, so fewer than 2^31 ids fit.
void CheckFitsInt32(vtkIdType count, const char* what)
{
  if (count > vtkIdType(INT32_MAX))
  {
    throw tessera::InputError(
      std::string("too many ") + what + " for 32-bit cell arrays: " + std::to_string(count));
  }
}

/// The filter's own cell arrays on output 0. Their names are API: an input point-data array with
/// one of them is passed under another name (tessera_vtk::RenameArraysNamed).
const std::vector<const char*> OwnArrayNames{ "PointId", "Area", "NeighborCount" };

/// The warning for accepted points whose tiles collapsed (tessera::CollapsedTilePoints), or "".
std::string CollapsedTilesWarning(const tessera::TileMesh& tiles)
{
  const std::vector<std::int32_t> collapsed = tessera::CollapsedTilePoints(tiles);
  if (collapsed.empty())
  {
    return std::string();
  }
  return std::to_string(collapsed.size()) +
    " tile(s) are narrower than the coordinates can resolve (their points lie an ulp or so from "
    "their neighbours), so their polygons have fewer than 3 corners, or collinear ones, and no "
    "area in doubles: points " +
    tessera_vtk::ListNames(
      collapsed.size(), [&](std::size_t k) { return std::to_string(collapsed[k]); });
}

/// Output 0: the tiles in ascending point id, on the mesh's vertices (tiles that meet share
/// them), with their arrays and the input's point data. Made in steps, like GraphWriter, so that
/// the filling can be shared between two threads: the constructor orders the tiles, allocates the
/// arrays and places each tile's vertex ids; CopyVertices fills a range of the points and
/// CopyTiles a range of the tiles' ids and own cell data (plain loops, any thread);
/// CopyPointData copies the input's point data (VTK calls: the calling thread); Attach hands
/// everything to the output.
class TileWriter
{
public:
  TileWriter(const tessera::TileMesh& tiles, vtkPointSet* input, vtkPolyData* output)
    : Tiles(tiles)
    , Input(input)
    , Output(output)
    , TileCount(static_cast<vtkIdType>(tiles.PointIds.size()))
    , VertexCount(static_cast<vtkIdType>(tiles.Vertices.size()))
    , Order(tessera::OrderByDistinctKeys(tiles.PointIds.data(),
        tiles.PointIds.size(),
        static_cast<std::size_t>(input->GetNumberOfPoints())))
  {
    const vtkIdType idCount = static_cast<vtkIdType>(tiles.VertexIds.size());
    CheckFitsInt32(idCount, "tile vertices");
    tessera_vtk::AllocateValues(this->Coordinates.Get(), this->VertexCount, 3);
    tessera_vtk::AllocateValues(this->Offsets.Get(), this->TileCount + 1);
    tessera_vtk::AllocateValues(this->Connectivity.Get(), idCount);
    this->PointIds->SetName(OwnArrayNames[0]);
    this->Areas->SetName(OwnArrayNames[1]);
    this->NeighborCounts->SetName(OwnArrayNames[2]);
    tessera_vtk::AllocateValues(this->PointIds.Get(), this->TileCount);
    tessera_vtk::AllocateValues(this->Areas.Get(), this->TileCount);
    tessera_vtk::AllocateValues(this->NeighborCounts.Get(), this->TileCount);
    // Where each tile's ids go. The order jumps about the core's (spatial) order: the offsets
    // are requested a few tiles ahead.
    std::int32_t* offsets = this->Offsets->GetPointer(0);
    const auto& from = tiles.Offsets;
    std::int32_t written = 0;
    for (vtkIdType k = 0; k < this->TileCount; ++k)
    {
      if (k + Ahead < this->TileCount)
      {
        __builtin_prefetch(from.data() + this->Order[k + Ahead]);
      }
      offsets[k] = written;
      written += std::int32_t(from[this->Order[k] + 1] - from[this->Order[k]]);
    }
    offsets[this->TileCount] = written;
  }

  vtkIdType Count() const { return this->TileCount; }
  vtkIdType PointCount() const { return this->VertexCount; }
  /// Input arrays passed under another name by CopyPointData: (input name, output name).
  const tessera_vtk::RenamedArrays& RenamedArrays() const { return this->Renamed; }

  /// The points (x, y, 0) [begin, end).
  void CopyVertices(vtkIdType begin, vtkIdType end)
  {
    const tessera::Point2* vertices = this->Tiles.Vertices.data();
    double* xyz = this->Coordinates->GetPointer(0);
    for (vtkIdType v = begin; v < end; ++v)
    {
      xyz[3 * v] = vertices[v].x;
      xyz[3 * v + 1] = vertices[v].y;
      xyz[3 * v + 2] = 0.0;
    }
  }

  /// The vertex ids, PointId, Area and NeighborCount of the tiles [begin, end) of the output
  /// order (plain loops, any thread).
  void CopyTiles(vtkIdType begin, vtkIdType end)
  {
    const tessera::TileMesh& tiles = this->Tiles;
    const std::int32_t* offsets = this->Offsets->GetPointer(0);
    std::int32_t* ids = this->Connectivity->GetPointer(0);
    vtkIdType* pointIdData = this->PointIds->GetPointer(0);
    double* areaData = this->Areas->GetPointer(0);
    int* countData = this->NeighborCounts->GetPointer(0);
    for (vtkIdType k = begin; k < end; ++k)
    {
      if (k + Ahead < end)
      {
        const std::int32_t upcoming = this->Order[k + Ahead];
        __builtin_prefetch(tiles.Offsets.data() + upcoming);
        __builtin_prefetch(tiles.PointIds.data() + upcoming);
        __builtin_prefetch(tiles.Areas.data() + upcoming);
        __builtin_prefetch(tiles.NeighborCounts.data() + upcoming);
        __builtin_prefetch(tiles.VertexIds.data() + tiles.Offsets[this->Order[k + Ahead / 2]]);
      }
      const std::int32_t tile = this->Order[k];
      std::copy(tiles.VertexIds.data() + tiles.Offsets[tile],
        tiles.VertexIds.data() + tiles.Offsets[tile + 1],
        ids + offsets[k]);
      pointIdData[k] = tiles.PointIds[tile];
      areaData[k] = tiles.Areas[tile];
      countData[k] = tiles.NeighborCounts[tile];
    }
  }

  /// The input's point data, per tile (VTK calls: the calling thread). Nothing when there is none:
  /// a CopyData call per tile costs more than the rest of the writing at a million tiles.
  void CopyPointData()
  {
    vtkCellData* cellData = this->Output->GetCellData();
    vtkPointData* inputData = this->Input->GetPointData();
    if (inputData->GetNumberOfArrays() == 0)
    {
      return;
    }
    // Global ids too (VTK copies none by default): one tile per point keeps them unique. Not
    // the points' ghost flags: as cell ghosts their bits mean other things (a duplicate point's
    // flag hid its tile as a duplicate cell, and the tiles' integrated area fell short).
    cellData->SetCopyGlobalIds(1, vtkDataSetAttributes::COPYTUPLE);
    cellData->CopyFieldOff(vtkDataSetAttributes::GhostArrayName());
    cellData->CopyAllocate(inputData, this->TileCount);
    this->Renamed = tessera_vtk::RenameArraysNamed(cellData, OwnArrayNames, false);
    const std::int32_t* pointIds = this->Tiles.PointIds.data();
    for (vtkIdType k = 0; k < this->TileCount; ++k)
    {
      if (k + Ahead < this->TileCount)
      {
        __builtin_prefetch(pointIds + this->Order[k + Ahead]);
      }
      cellData->CopyData(inputData, pointIds[this->Order[k]], k);
    }
  }

  void Attach()
  {
    vtkNew<vtkPoints> points;
    points->SetData(this->Coordinates);
    this->Output->SetPoints(points);
    vtkNew<vtkCellArray> polys;
    polys->SetData(this->Offsets, this->Connectivity);
    this->Output->SetPolys(polys);
    vtkCellData* cellData = this->Output->GetCellData();
    cellData->AddArray(this->PointIds);
    cellData->AddArray(this->Areas);
    cellData->AddArray(this->NeighborCounts);
    // Area is what a view colours the tiles by (ParaView colours by the active scalars on Show;
    // they were one solid colour), unless the input's active scalars came with its point data.
    if (!cellData->GetScalars())
    {
      cellData->SetActiveScalars(this->Areas->GetName());
    }
  }

private:
  static constexpr vtkIdType Ahead = 8; ///< tiles read ahead of the one being written
  const tessera::TileMesh& Tiles;
  vtkPointSet* Input;
  vtkPolyData* Output;
  const vtkIdType TileCount;
  const vtkIdType VertexCount;
  const std::vector<std::int32_t> Order;
  vtkNew<vtkDoubleArray> Coordinates;
  vtkNew<vtkTypeInt32Array> Offsets;
  vtkNew<vtkTypeInt32Array> Connectivity;
  vtkNew<vtkIdTypeArray> PointIds;
  vtkNew<vtkDoubleArray> Areas;
  vtkNew<vtkIntArray> NeighborCounts;
  tessera_vtk::RenamedArrays Renamed;
};

/// Output 1: the input points with one line per contiguous pair and its Kind, sorted by (i, j).
/// Both cores list the pairs of one i together with j ascending, the groups in their own tile
/// order, so a stable counting sort on i is enough (linear time). It runs in steps, so that the
/// plain loops can share two threads while the tiles are written: the constructor passes the
/// input's points and point data and allocates the arrays; Count(h) counts half h of the pairs
/// per i, Place turns the counts into each half's first slot per i (half 0's pairs of an i before
/// half 1's: the sort stays stable), Scatter(h) writes half h's pairs to their slots; Attach hands
/// the arrays to the output.
class GraphWriter
{
public:
  GraphWriter(const tessera::ContiguityGraph& graph, vtkPointSet* input, vtkPolyData* output)
    : Graph(graph)
    , PairCount(static_cast<vtkIdType>(graph.Kinds.size()))
    , IdLimit(static_cast<std::size_t>(input->GetNumberOfPoints()))
  {
    if (input->GetPoints())
    {
      output->SetPoints(input->GetPoints());
    }
    output->GetPointData()->PassData(input->GetPointData());
    CheckFitsInt32(2 * this->PairCount, "contiguities");
    tessera_vtk::AllocateValues(this->Offsets.Get(), this->PairCount + 1);
    tessera_vtk::AllocateValues(this->Connectivity.Get(), 2 * this->PairCount);
    this->Kinds->SetName("Kind");
    tessera_vtk::AllocateValues(this->Kinds.Get(), this->PairCount);
    // Each line's point ids as cell data too, so that a spreadsheet or a CSV of the graph lists
    // the neighbours (a ParaView user saw only Kind). Its own copy: an array sharing the
    // connectivity's buffer would dangle once the lines were replaced.
    this->PairIds->SetName("PointIds");
    tessera_vtk::AllocateValues(this->PairIds.Get(), this->PairCount, 2);
    this->PairIds->SetComponentName(0, "i");
    this->PairIds->SetComponentName(1, "j");
  }

  void Count(int half)
  {
    std::vector<std::int32_t>& count = this->Slots[half];
    tessera::AssignOnLargePages(count, this->IdLimit, std::int32_t(0)); // counted at random
    const std::int32_t* pairs = this->Graph.Pairs.data();
    const vtkIdType begin = this->HalfBegin(half), end = this->HalfBegin(half + 1);
    // Point ids are random in space: the counters are requested a few pairs ahead.
    for (vtkIdType k = begin; k < end; ++k)
    {
      if (k + Ahead < end)
      {
        __builtin_prefetch(count.data() + pairs[2 * (k + Ahead)]);
      }
      ++count[pairs[2 * k]];
    }
  }

  void Place()
  {
    std::int32_t next = 0;
    for (std::size_t i = 0; i < this->IdLimit; ++i)
    {
      for (std::vector<std::int32_t>& slots : this->Slots)
      {
        const std::int32_t count = slots[i];
        slots[i] = next;
        next += count;
      }
    }
  }

  void Scatter(int half)
  {
    std::vector<std::int32_t>& slot = this->Slots[half];
    const std::int32_t* pairs = this->Graph.Pairs.data();
    const std::uint8_t* kinds = this->Graph.Kinds.data();
    std::int32_t* ids = this->Connectivity->GetPointer(0);
    std::int32_t* pairIds = this->PairIds->GetPointer(0);
    unsigned char* kindData = this->Kinds->GetPointer(0);
    const vtkIdType begin = this->HalfBegin(half), end = this->HalfBegin(half + 1);
    for (vtkIdType k = begin; k < end; ++k)
    {
      if (k + Ahead < end)
      {
        __builtin_prefetch(slot.data() + pairs[2 * (k + Ahead)]);
      }
      const std::int32_t i = pairs[2 * k];
      const std::int32_t at = slot[i]++;
      ids[2 * at] = pairIds[2 * at] = i;
      ids[2 * at + 1] = pairIds[2 * at + 1] = pairs[2 * k + 1];
      kindData[at] = kinds[k];
    }
    std::int32_t* offsetData = this->Offsets->GetPointer(0);
    for (vtkIdType k = begin; k < end + (half == 1 ? 1 : 0); ++k)
    {
      offsetData[k] = std::int32_t(2 * k);
    }
  }

  void Attach(vtkPolyData* output)
  {
    vtkNew<vtkCellArray> lines;
    lines->SetData(this->Offsets, this->Connectivity);
    output->SetLines(lines);
    output->GetCellData()->AddArray(this->Kinds);
    output->GetCellData()->SetActiveScalars(this->Kinds->GetName()); // (neighbours by colour)
    output->GetCellData()->AddArray(this->PairIds);
  }

private:
  static constexpr vtkIdType Ahead = 16; ///< pairs read ahead of the one counted or written
  vtkIdType HalfBegin(int half) const
  {
    return half == 0 ? 0 : half == 1 ? this->PairCount / 2 : this->PairCount;
  }

  const tessera::ContiguityGraph& Graph;
  const vtkIdType PairCount;
  const std::size_t IdLimit;
  std::vector<std::int32_t> Slots[2]; ///< per half: counts per i, then next slot per i
  vtkNew<vtkTypeInt32Array> Offsets;
  vtkNew<vtkTypeInt32Array> Connectivity;
  vtkNew<vtkUnsignedCharArray> Kinds;
  vtkNew<vtkTypeInt32Array> PairIds; ///< cell data PointIds: each line's i and j
};

/// A warning, or "", for tiles whose areas, scaled back to the input's coordinates, underflow:
/// to 0 below about 5e-324, with fewer digits below 2.2e-308 (subnormal; a window whose area
/// overflows is refused). A trial's points 1e-200 apart got 20 tiles of Area 0 without a word,
/// where the tiles' shapes are exact at any scale.
std::string AreasUnderflowWarning(const tessera::UninitializedVector<double>& areas)
{
  std::size_t zero = 0, subnormal = 0;
  for (const double a : areas)
  {
    zero += a == 0.0 ? 1 : 0;
    subnormal += std::fpclassify(a) == FP_SUBNORMAL ? 1 : 0;
  }
  if (zero == 0 && subnormal == 0)
  {
    return std::string();
  }
  const std::string counts = zero == 0
    ? std::to_string(subnormal) + " tile(s) have an Area below 2.2e-308, with fewer digits"
    : std::to_string(zero) + " tile(s) have Area 0" +
      (subnormal == 0
          ? std::string()
          : " and " + std::to_string(subnormal) + " an Area below 2.2e-308, with fewer digits");
  return counts +
    ": their areas in the input's units lie below the doubles' normal range, though their "
    "shapes are exact; scale the coordinates nearer 1 (by a power of two to keep them exact) "
    "where the areas are wanted";
}

/// Tiles scaled by 2^-exponent back to the input's coordinates, with a warning where their areas
/// underflow there.
void ScaleTilesBack(vtkDirichletTessellation* self, tessera::TileMesh& tiles, int exponent)
{
  tessera::ScaleByPowerOfTwo(tiles, -exponent);
  tesseraWarnUnlessEmptyMacro(self, AreasUnderflowWarning(tiles.Areas));
}

/// The tessellation of the points in the window by either engine (progress 0.1 to 0.75), its
/// tiles checked to fill the window, in the input's coordinates.
TessellationResult Tessellate(vtkDirichletTessellation* self,
  tessera::Window window,
  std::vector<tessera::Point2> points,
  bool brasselReif,
  bool withGraph)
{
  // Coordinates of some 1e100 or 1e-100: both engines work on points and window scaled by a
  // power of two (exactly) into the range where the tiles' window decisions are exact
  // (window_predicates.h), and the tiles are scaled back.
  if (brasselReif && window.IsAxisAlignedRectangle())
  {
    tessera::CheckSidesAreDoubles(window); // (before scaling: its message gives the side as set)
  }
  const int exponent = tessera::ScaleIntoExactRange(window, points);
  if (!brasselReif) // (its sweep's tests keep their range)
  {
    tessera::CheckPointsInExactRange(window, points, exponent);
  }
  const double windowArea = window.Area();
  const double cornerRounding = tessera::CornerRoundingOfTiles(window);
  tessera_vtk::ProgressOrStop(self, 0.1);
  TessellationResult result = brasselReif
    ? RunBrasselReif(window, std::move(points), self)
    : RunGreenSibson(std::move(window), std::move(points), withGraph, self);
  tessera::CheckTilesFillWindow(result.Tiles, windowArea, cornerRounding);
  if (exponent != 0)
  {
    ScaleTilesBack(self, result.Tiles, exponent);
  }
  return result;
}

/// The tiles' points, ids and the graph's counts, then the tiles' cell data and the graph's
/// lines, filled by the writers.
void FillOutputs(TileWriter& tiles, std::optional<GraphWriter>& graph)
{
  // Two threads for large outputs: first the points, the tiles' ids and own cell data, and the
  // graph's counts in two halves (first touching the output's pages), then the input's point
  // data (VTK calls: this thread) beside the graph's lines.
  const bool beside = tessera::parallel::ThreadCount(tiles.Count(), 25000) > 1;
  const vtkIdType half = tiles.Count() / 2;
  const vtkIdType halfPoints = tiles.PointCount() / 2;
  tessera::parallel::RunSideBySide(
    beside,
    [&]()
    {
      tiles.CopyVertices(0, halfPoints);
      tiles.CopyTiles(0, half);
      if (graph)
      {
        graph->Count(0);
      }
    },
    [&]()
    {
      tiles.CopyVertices(halfPoints, tiles.PointCount());
      tiles.CopyTiles(half, tiles.Count());
      if (graph)
      {
        graph->Count(1);
      }
    });
  if (graph)
  {
    graph->Place(); // both halves counted
  }
  tessera::parallel::RunSideBySide(
    beside,
    [&]() { tiles.CopyPointData(); },
    [&]()
    {
      if (graph)
      {
        graph->Scatter(0);
        graph->Scatter(1);
      }
    });
}

/// The arrays that writing the outputs passed under other names, for the warnings that come last.
struct RenamedOnOutputs
{
  tessera_vtk::RenamedArrays TilePointData; // the input's point data, as the tiles' cell data
  tessera_vtk::RenamedArrays FieldData;     // the field data of both outputs
};

/// Output 0 (the tiles) and output 1 (the contiguity graph, or nothing without it), both with
/// the unused points' field data.
RenamedOnOutputs WriteOutputs(const TessellationResult& result,
  vtkPointSet* input,
  bool withGraph,
  vtkPolyData* tilesOutput,
  vtkPolyData* graphOutput)
{
  std::optional<GraphWriter> graph; // none: output 1 stays empty (its field data passed)
  if (withGraph)
  {
    graph.emplace(result.Graph, input, graphOutput);
  }
  TileWriter tiles(result.Tiles, input, tilesOutput);
  FillOutputs(tiles, graph);
  tiles.Attach();
  const tessera_vtk::RenamedArrays renamedFields =
    tessera_vtk::AddUnusedPointIds(tilesOutput, result.Rejected, result.Duplicates);
  if (graph)
  {
    graph->Attach(graphOutput);
  }
  // With the graph off too: output 1 carries the same field data as output 0.
  tessera_vtk::AddUnusedPointIds(graphOutput, result.Rejected, result.Duplicates);
  return { tiles.RenamedArrays(), renamedFields };
}

/// The warnings for points given no tile (rejected or duplicates), for a window with no point in
/// it, and for tiles collapsed to no area.
void WarnOfUnusedPointsAndCollapsedTiles(vtkDirichletTessellation* self,
  const TessellationResult& result,
  const tessera::Box2& windowBox,
  vtkPoints* inputPoints)
{
  tesseraWarnUnlessEmptyMacro(self,
    tessera_vtk::PointsNotUsedWarning(
      windowBox, result.Rejected, result.Duplicates, "used", "tile", inputPoints));
  tesseraWarnUnlessEmptyMacro(self, CollapsedTilesWarning(result.Tiles));
}

/// The warnings for the input's arrays passed under other names.
void WarnOfRenamedArrays(vtkDirichletTessellation* self, const RenamedOnOutputs& renamed)
{
  if (!renamed.TilePointData.empty())
  {
    vtkWarningWithObjectMacro(self,
      << tessera_vtk::RenamedArraysWarning(
           renamed.TilePointData, "point-data", "the tiles", "cell"));
  }
  if (!renamed.FieldData.empty())
  {
    vtkWarningWithObjectMacro(self,
      << tessera_vtk::RenamedArraysWarning(
           renamed.FieldData, "field-data", "both outputs", "field"));
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkDirichletTessellation::vtkDirichletTessellation()
{
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
void vtkDirichletTessellation::AddWindowConstraint(double a, double b, double c)
{
  this->WindowConstraints.insert(this->WindowConstraints.end(), { a, b, c });
  this->Modified();
}

void vtkDirichletTessellation::RemoveAllWindowConstraints()
{
  if (!this->WindowConstraints.empty())
  {
    this->WindowConstraints.clear();
    this->Modified();
  }
}

int vtkDirichletTessellation::GetNumberOfWindowConstraints() const
{
  return static_cast<int>(this->WindowConstraints.size() / 3);
}

//------------------------------------------------------------------------------
int vtkDirichletTessellation::FillInputPortInformation(int, vtkInformation* info)
{
  // Any data object: InputPoints takes points or a composite of them and names any other type
  // (a type the pipeline refused never reached RequestData, and the last results stayed).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkDirichletTessellation::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Every point at once: see RequestWholeInputs (ParaView under MPI asks each process for a
  // piece, and each made the tessellation of its own piece's points).
  tessera_vtk::RequestWholeInputs(inputVector, 0, 0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkDirichletTessellation::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (!tessera_vtk::MakesOutput(outputVector))
  {
    return 1; // another process's piece: the first makes the whole output (RequestWholeInputs)
  }
  vtkDataObject* inputData = vtkDataObject::GetData(inputVector[0]);
  vtkPolyData* tilesOutput = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* graphOutput = vtkPolyData::GetData(outputVector, 1);
  try
  {
    tessera_vtk::CheckChoice("Algorithm", this->Algorithm, { "GreenSibson", "BrasselReif" });
    std::vector<std::string> notCarried;
    const vtkSmartPointer<vtkPointSet> input = tessera_vtk::InputPoints(inputData, notCarried);
    tesseraWarnEachMacro(this, notCarried);
    // The build's temporaries, then the tessellation, are freed before the next step allocates
    // arrays of about their sizes: reused, their pages are not mapped and faulted twice (at 10^7
    // points, blocks above HugePageAdviceLimit on small pages either way, the filter took
    // 0.54-0.58 us per point with this, 0.68-0.72 without).
    const tessera::ReuseLargeBlocks reuse;
    std::vector<tessera::Point2> points = tessera_vtk::ReadPoints2D(input->GetPoints(), inputData);
    if (points.empty())
    {
      vtkWarningMacro(<< tessera_vtk::NoPointsWarning("tile and no contiguity"));
    }
    tessera::Window window = tessera_vtk::ChooseWindowWithWarning(
      this, this->WindowBounds, this->WindowConstraints, this->Padding, points, true);
    const tessera::Box2 windowBox = window.Bounds();
    const TessellationResult result = Tessellate(this,
      std::move(window),
      std::move(points),
      this->Algorithm == BRASSEL_REIF,
      this->ComputeContiguityGraph);
    tessera_vtk::ProgressOrStop(this, 0.8);
    const RenamedOnOutputs renamed =
      WriteOutputs(result, input, this->ComputeContiguityGraph, tilesOutput, graphOutput);
    WarnOfUnusedPointsAndCollapsedTiles(this, result, windowBox, input->GetPoints());
    WarnOfRenamedArrays(this, renamed);
    tessera_vtk::ListNonEmptyFieldArraysFirst(tilesOutput);
    tessera_vtk::ListNonEmptyFieldArraysFirst(graphOutput);
    return 1;
  }
  catch (const std::exception& e)
  {
    // (a stop that a progress observer asked for empties the outputs too, without an error)
    tilesOutput->Initialize();
    graphOutput->Initialize();
    return tesseraErrorOrStopMacro(e);
  }
}

//------------------------------------------------------------------------------
void vtkDirichletTessellation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Algorithm: "
     << (this->Algorithm == BRASSEL_REIF      ? "BrasselReif"
            : this->Algorithm == GREEN_SIBSON ? "GreenSibson"
                                              : "(not one of them)")
     << " (" << this->Algorithm << ")\n";
  os << indent << "WindowBounds: " << this->WindowBounds[0] << ", " << this->WindowBounds[1] << ", "
     << this->WindowBounds[2] << ", " << this->WindowBounds[3] << "\n";
  os << indent << "WindowConstraints: " << this->GetNumberOfWindowConstraints() << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "ComputeContiguityGraph: " << (this->ComputeContiguityGraph ? "on" : "off")
     << "\n";
}
