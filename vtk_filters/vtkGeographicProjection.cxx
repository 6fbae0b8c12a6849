#include "vtkGeographicProjection.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include "errors.h"
#include "geo.h"

#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkGeographicProjection);

namespace
{
const char* const ProjectionRecordName = "TesseraProjection";

std::vector<tessera::Point2> ReadXY(vtkPoints* points)
{
  std::vector<tessera::Point2> xy(points ? points->GetNumberOfPoints() : 0);
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(xy.size()); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    xy[i] = { p[0], p[1] };
  }
  return xy;
}

/// The `TesseraProjection` record of a data set's field data, or "" when it has none.
std::string ReadProjectionRecord(vtkDataObject* data)
{
  vtkFieldData* fd = data->GetFieldData();
  auto* record =
    fd ? vtkStringArray::SafeDownCast(fd->GetAbstractArray(ProjectionRecordName)) : nullptr;
  return record && record->GetNumberOfValues() > 0 ? record->GetValue(0) : std::string();
}

void WriteProjectionRecord(vtkDataObject* data, const std::string& record)
{
  vtkNew<vtkStringArray> array;
  array->SetName(ProjectionRecordName);
  array->InsertNextValue(record);
  data->GetFieldData()->AddArray(array);
}

/// Cuts the line and polygon edges of lon/lat poly data so that no piece is longer than maxStep
/// degrees. New points are appended after the input's, with point data interpolated; an edge
/// shared by two cells is cut once, so neighbouring polygons stay conforming.
class EdgeDensifier
{
public:
  EdgeDensifier(vtkPolyData* input, vtkPolyData* output, double maxStep)
    : Input(input)
    , Output(output)
    , MaxStep(maxStep)
  {
    this->Points->SetDataTypeToDouble();
    this->Points->DeepCopy(input->GetPoints());
    output->GetPointData()->CopyAllocate(input->GetPointData());
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      output->GetPointData()->CopyData(input->GetPointData(), i, i);
    }
  }

  void Run()
  {
    this->Output->SetVerts(this->Input->GetVerts());
    this->Output->SetStrips(this->Input->GetStrips());
    this->Output->SetLines(this->DensifyCells(this->Input->GetLines(), false));
    this->Output->SetPolys(this->DensifyCells(this->Input->GetPolys(), true));
    this->Output->SetPoints(this->Points);
    this->Output->GetCellData()->PassData(this->Input->GetCellData());
  }

private:
  vtkSmartPointer<vtkCellArray> DensifyCells(vtkCellArray* cells, bool closed)
  {
    auto result = vtkSmartPointer<vtkCellArray>::New();
    if (!cells)
    {
      return result;
    }
    vtkNew<vtkIdList> ids;
    std::vector<vtkIdType> densified;
    auto iter = vtk::TakeSmartPointer(cells->NewIterator());
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      iter->GetCurrentCell(ids);
      densified.clear();
      const vtkIdType n = ids->GetNumberOfIds();
      const vtkIdType edges = closed ? n : n - 1;
      for (vtkIdType k = 0; k < n; ++k)
      {
        densified.push_back(ids->GetId(k));
        if (k < edges)
        {
          this->AppendInteriorPoints(ids->GetId(k), ids->GetId((k + 1) % n), densified);
        }
      }
      result->InsertNextCell(static_cast<vtkIdType>(densified.size()), densified.data());
    }
    return result;
  }

  /// Appends to `cell` the ids of the points strictly inside edge a->b, creating them once.
  void AppendInteriorPoints(vtkIdType a, vtkIdType b, std::vector<vtkIdType>& cell)
  {
    const bool forward = a < b;
    const auto key = forward ? std::make_pair(a, b) : std::make_pair(b, a);
    auto found = this->Cuts.find(key);
    if (found == this->Cuts.end())
    {
      found = this->Cuts.emplace(key, this->CutEdge(key.first, key.second)).first;
    }
    const vtkIdType first = found->second.first;
    const int pieces = found->second.second;
    for (int k = 1; k < pieces; ++k)
    {
      cell.push_back(forward ? first + k - 1 : first + pieces - 1 - k);
    }
  }

  /// Creates the interior points of edge a->b (a < b); returns the first new id and the count of
  /// pieces.
  std::pair<vtkIdType, int> CutEdge(vtkIdType a, vtkIdType b)
  {
    double pa[3], pb[3];
    this->Input->GetPoint(a, pa);
    this->Input->GetPoint(b, pb);
    const int pieces =
      tessera::DensifiedPieceCount({ pa[0], pa[1] }, { pb[0], pb[1] }, this->MaxStep);
    const vtkIdType first = this->Points->GetNumberOfPoints();
    for (int k = 1; k < pieces; ++k)
    {
      const double t = static_cast<double>(k) / pieces;
      const tessera::Point2 q = tessera::InterpolateLonLat({ pa[0], pa[1] }, { pb[0], pb[1] }, t);
      const vtkIdType id = this->Points->InsertNextPoint(q.x, q.y, pa[2] + t * (pb[2] - pa[2]));
      this->Output->GetPointData()->InterpolateEdge(this->Input->GetPointData(), id, a, b, t);
    }
    return { first, pieces };
  }

  vtkPolyData* Input;
  vtkPolyData* Output;
  double MaxStep;
  vtkNew<vtkPoints> Points;
  std::map<std::pair<vtkIdType, vtkIdType>, std::pair<vtkIdType, int>> Cuts;
};

tessera::ProjectionKind KindOf(int projection)
{
  switch (projection)
  {
    case vtkGeographicProjection::LAMBERT_CONFORMAL_CONIC:
      return tessera::ProjectionKind::LambertConformalConic;
    case vtkGeographicProjection::TRANSVERSE_MERCATOR:
      return tessera::ProjectionKind::TransverseMercator;
    case vtkGeographicProjection::UTM:
      return tessera::ProjectionKind::UTM;
    case vtkGeographicProjection::AZIMUTHAL_EQUIDISTANT:
      return tessera::ProjectionKind::AzimuthalEquidistant;
    default:
      return tessera::ProjectionKind::AlbersEqualArea;
  }
}
/// The forward projection's parameters from the filter's settings and the data.
tessera::ProjectionParameters ChooseForwardParameters(vtkGeographicProjection* self,
  const std::vector<tessera::Point2>& lonlat)
{
  if (self->GetProjection() == vtkGeographicProjection::AUTOMATIC)
  {
    return tessera::AutomaticParameters(lonlat);
  }
  tessera::ProjectionParameters p;
  if (self->GetParametersFromData())
  {
    p =
      tessera::ParametersFromExtent(KindOf(self->GetProjection()), tessera::ComputeExtent(lonlat));
  }
  else
  {
    p.Kind = KindOf(self->GetProjection());
    p.CentralLongitude = self->GetCentralLongitude();
    p.CentralLatitude = self->GetCentralLatitude();
    p.StandardParallel1 = self->GetStandardParallels()[0];
    p.StandardParallel2 = self->GetStandardParallels()[1];
    p.UTMZone = tessera::UTMZoneOfLongitude(self->GetCentralLongitude());
    p.UTMNorth = self->GetCentralLatitude() >= 0.0;
  }
  if (self->GetUTMZone() != 0)
  {
    p.UTMZone = self->GetUTMZone();
    p.UTMNorth = self->GetUTMNorth();
  }
  return p;
}

} // namespace

//------------------------------------------------------------------------------
vtkGeographicProjection::vtkGeographicProjection() = default;

//------------------------------------------------------------------------------
int vtkGeographicProjection::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("vtkGeographicProjection needs a vtkPointSet input.");
    return 0;
  }
  try
  {
    tessera::ProjectionParameters parameters;
    std::vector<tessera::Point2> lonlat; // the input points, read when projecting forward
    const std::string record = ReadProjectionRecord(input);
    if (this->Inverse && !record.empty())
    {
      parameters = tessera::ProjectionParameters::FromString(record);
    }
    else if (this->Inverse && this->ParametersFromData)
    {
      throw tessera::InputError("Inverse needs the input's TesseraProjection field data, or "
                                "ParametersFromData off and the projection's parameters set");
    }
    else
    {
      lonlat = ReadXY(input->GetPoints());
      parameters = ChooseForwardParameters(this, lonlat);
    }

    auto polyInput = vtkPolyData::SafeDownCast(input);
    if (!this->Inverse && polyInput && this->MaximumEdgeLength > 0.0)
    {
      tessera::ValidateLonLat(lonlat);
      EdgeDensifier(polyInput, vtkPolyData::SafeDownCast(output), this->MaximumEdgeLength).Run();
      output->GetFieldData()->PassData(input->GetFieldData());
    }
    else
    {
      output->CopyStructure(input);
      output->GetPointData()->PassData(input->GetPointData());
      output->GetCellData()->PassData(input->GetCellData());
      output->GetFieldData()->PassData(input->GetFieldData());
    }

    const tessera::GeographicProjection projection(parameters);
    vtkPoints* source = output->GetPoints();
    vtkNew<vtkPoints> projected;
    projected->SetDataTypeToDouble();
    const vtkIdType n = source ? source->GetNumberOfPoints() : 0;
    projected->SetNumberOfPoints(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3];
      source->GetPoint(i, p);
      const tessera::Point2 q = this->Inverse ? projection.Inverse({ p[0], p[1] }, i)
                                              : projection.Forward({ p[0], p[1] }, i);
      projected->SetPoint(i, q.x, q.y, p[2]);
    }
    output->SetPoints(projected);

    output->GetFieldData()->RemoveArray(ProjectionRecordName);
    if (!this->Inverse)
    {
      WriteProjectionRecord(output, parameters.ToString());
    }
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    output->Initialize();
    return 0;
  }
}

//------------------------------------------------------------------------------
void vtkGeographicProjection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Projection: " << this->Projection << "\n";
  os << indent << "UTMZone: " << this->UTMZone << "\n";
  os << indent << "UTMNorth: " << this->UTMNorth << "\n";
  os << indent << "ParametersFromData: " << this->ParametersFromData << "\n";
  os << indent << "CentralLongitude: " << this->CentralLongitude << "\n";
  os << indent << "CentralLatitude: " << this->CentralLatitude << "\n";
  os << indent << "StandardParallels: " << this->StandardParallels[0] << ", "
     << this->StandardParallels[1] << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "Inverse: " << this->Inverse << "\n";
}
