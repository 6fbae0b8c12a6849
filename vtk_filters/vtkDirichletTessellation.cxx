#include "vtkDirichletTessellation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "TesseraFilterUtilities.h"
#include "dirichlet_tessellation.h"
#include "errors.h"
#include "thiessen_sweep.h"
#include "tiles.h"

#include <algorithm>
#include <exception>
#include <utility>

vtkStandardNewMacro(vtkDirichletTessellation);

namespace
{

/// What either engine produces, in the core's flat arrays.
struct TessellationResult
{
  tessera::TileSet Tiles;
  tessera::ContiguityGraph Graph;
  std::vector<std::int32_t> Rejected;
  std::vector<std::pair<std::int32_t, std::int32_t>> Duplicates;
};

TessellationResult RunGreenSibson(tessera::Window window, std::vector<tessera::Point2> points)
{
  const tessera::DirichletTessellation tessellation(std::move(window), std::move(points));
  const tessera::TessellationDual dual(tessellation);
  return {
    dual.Tiles(), dual.Contiguities(), tessellation.RejectedIds(), tessellation.Duplicates()
  };
}

TessellationResult RunBrasselReif(const tessera::Window& window,
  std::vector<tessera::Point2> points)
{
  if (!window.IsAxisAlignedRectangle())
  {
    throw tessera::InputError("the BrasselReif algorithm needs a rectangular window (WindowBounds "
                              "only); remove the window constraints or use GreenSibson");
  }
  tessera::ThiessenSweepResult sweep = tessera::ComputeThiessenSweep(window, points);
  return { std::move(sweep.Tiles),
    std::move(sweep.Contiguities),
    std::move(sweep.RejectedIds),
    std::move(sweep.Duplicates) };
}

/// Positions 0..count-1 ordered by key (keys are distinct point ids below idLimit): a counting
/// sort, so that both engines' results come out in ascending point id whatever order their cores
/// list them in.
std::vector<std::int32_t> OrderByPointId(const std::vector<std::int32_t>& keys, std::size_t idLimit)
{
  std::vector<std::int32_t> slot(idLimit, -1);
  for (std::size_t k = 0; k < keys.size(); ++k)
  {
    slot[keys[k]] = static_cast<std::int32_t>(k);
  }
  std::vector<std::int32_t> order;
  order.reserve(keys.size());
  for (std::int32_t k : slot)
  {
    if (k >= 0)
    {
      order.push_back(k);
    }
  }
  return order;
}

/// Output 0: the tiles in ascending point id, their arrays and the input's point data on them.
void WriteTiles(const tessera::TileSet& tiles, vtkPointSet* input, vtkPolyData* output)
{
  const vtkIdType tileCount = static_cast<vtkIdType>(tiles.PointIds.size());
  const vtkIdType vertexCount = static_cast<vtkIdType>(tiles.Vertices.size());
  const std::vector<std::int32_t> order =
    OrderByPointId(tiles.PointIds, static_cast<std::size_t>(input->GetNumberOfPoints()));

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(vertexCount);
  double* xyz = coordinates->GetPointer(0);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(tileCount + 1);
  vtkIdType* offsetData = offsets->GetPointer(0);
  vtkIdType written = 0;
  for (vtkIdType k = 0; k < tileCount; ++k)
  {
    offsetData[k] = written;
    const std::int32_t tile = order[k];
    for (std::int64_t v = tiles.Offsets[tile]; v < tiles.Offsets[tile + 1]; ++v, ++written)
    {
      xyz[3 * written] = tiles.Vertices[v].x;
      xyz[3 * written + 1] = tiles.Vertices[v].y;
      xyz[3 * written + 2] = 0.0;
    }
  }
  offsetData[tileCount] = written;
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);

  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(vertexCount);
  vtkIdType* ids = connectivity->GetPointer(0);
  for (vtkIdType v = 0; v < vertexCount; ++v)
  {
    ids[v] = v;
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);

  vtkCellData* cellData = output->GetCellData();
  vtkPointData* inputData = input->GetPointData();
  // The input's point data follows the tiles (a gauge's values on its tile). Skipped when there
  // is none: a CopyData call per tile costs more than the rest of this loop at a million tiles.
  const bool copyPointData = inputData->GetNumberOfArrays() > 0;
  if (copyPointData)
  {
    cellData->CopyAllocate(inputData, tileCount);
  }
  vtkNew<vtkIdTypeArray> pointIds;
  pointIds->SetName("PointId");
  vtkNew<vtkDoubleArray> areas;
  areas->SetName("Area");
  vtkNew<vtkIntArray> neighborCounts;
  neighborCounts->SetName("NeighborCount");
  pointIds->SetNumberOfValues(tileCount);
  areas->SetNumberOfValues(tileCount);
  neighborCounts->SetNumberOfValues(tileCount);
  vtkIdType* pointIdData = pointIds->GetPointer(0);
  double* areaData = areas->GetPointer(0);
  int* countData = neighborCounts->GetPointer(0);
  for (vtkIdType k = 0; k < tileCount; ++k)
  {
    const std::int32_t tile = order[k];
    if (copyPointData)
    {
      cellData->CopyData(inputData, tiles.PointIds[tile], k);
    }
    pointIdData[k] = tiles.PointIds[tile];
    areaData[k] = tiles.Areas[tile];
    countData[k] = tiles.NeighborCounts[tile];
  }
  cellData->AddArray(pointIds);
  cellData->AddArray(areas);
  cellData->AddArray(neighborCounts);
}

/// Output 1: the input points with one line per contiguous pair and its Kind.
void WriteGraph(const tessera::ContiguityGraph& graph, vtkPointSet* input, vtkPolyData* output)
{
  if (input->GetPoints())
  {
    output->SetPoints(input->GetPoints());
  }
  output->GetPointData()->PassData(input->GetPointData());
  const vtkIdType pairCount = static_cast<vtkIdType>(graph.Kinds.size());
  // Pairs sorted by (i, j). Both cores list the pairs of one i together with j ascending, the
  // groups in their own tile order, so a stable counting sort on i is enough (linear time).
  std::vector<vtkIdType> start(static_cast<std::size_t>(input->GetNumberOfPoints()) + 1, 0);
  for (vtkIdType k = 0; k < pairCount; ++k)
  {
    ++start[graph.Pairs[2 * k] + 1];
  }
  for (std::size_t i = 1; i < start.size(); ++i)
  {
    start[i] += start[i - 1];
  }
  std::vector<std::int32_t> order(static_cast<std::size_t>(pairCount));
  for (vtkIdType k = 0; k < pairCount; ++k)
  {
    order[start[graph.Pairs[2 * k]]++] = static_cast<std::int32_t>(k);
  }
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(pairCount + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(2 * pairCount);
  vtkNew<vtkUnsignedCharArray> kinds;
  kinds->SetName("Kind");
  kinds->SetNumberOfValues(pairCount);
  vtkIdType* offsetData = offsets->GetPointer(0);
  vtkIdType* ids = connectivity->GetPointer(0);
  unsigned char* kindData = kinds->GetPointer(0);
  for (vtkIdType k = 0; k < pairCount; ++k)
  {
    const std::int32_t pair = order[k];
    offsetData[k] = 2 * k;
    ids[2 * k] = graph.Pairs[2 * pair];
    ids[2 * k + 1] = graph.Pairs[2 * pair + 1];
    kindData[k] = graph.Kinds[pair];
  }
  offsets->SetValue(pairCount, 2 * pairCount);
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
  output->SetLines(lines);
  output->GetCellData()->AddArray(kinds);
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
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkDirichletTessellation::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* tilesOutput = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* graphOutput = vtkPolyData::GetData(outputVector, 1);
  try
  {
    std::vector<tessera::Point2> points = tessera_vtk::ReadPoints2D(input->GetPoints());
    tessera::Window window =
      tessera_vtk::ChooseWindow(this->WindowBounds, this->WindowConstraints, this->Padding, points);
    this->UpdateProgress(0.1);
    const TessellationResult result = this->Algorithm == BRASSEL_REIF
      ? RunBrasselReif(window, std::move(points))
      : RunGreenSibson(std::move(window), std::move(points));
    this->UpdateProgress(0.8);
    WriteTiles(result.Tiles, input, tilesOutput);
    WriteGraph(result.Graph, input, graphOutput);
    tessera_vtk::AddUnusedPointIds(tilesOutput, result.Rejected, result.Duplicates);
    tessera_vtk::AddUnusedPointIds(graphOutput, result.Rejected, result.Duplicates);
    if (!result.Rejected.empty() || !result.Duplicates.empty())
    {
      vtkWarningMacro(<< result.Rejected.size() << " point(s) outside the window and "
                      << result.Duplicates.size()
                      << " exact duplicate(s) were not used; their ids are in the field data "
                         "arrays RejectedPointIds, DuplicatePointIds and DuplicateOfPointIds.");
    }
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    tilesOutput->Initialize();
    graphOutput->Initialize();
    return 0;
  }
}

//------------------------------------------------------------------------------
void vtkDirichletTessellation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Algorithm: " << (this->Algorithm == BRASSEL_REIF ? "BrasselReif" : "GreenSibson")
     << "\n";
  os << indent << "WindowBounds: " << this->WindowBounds[0] << ", " << this->WindowBounds[1] << ", "
     << this->WindowBounds[2] << ", " << this->WindowBounds[3] << "\n";
  os << indent << "WindowConstraints: " << this->GetNumberOfWindowConstraints() << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
}
