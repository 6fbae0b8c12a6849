#include "vtkRidgeGrouping.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include "TesseraFilterUtilities.h"
#include "errors.h"
#include "ridge_grouping.h"

#include <algorithm>
#include <exception>
#include <limits>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkRidgeGrouping);

namespace
{

void AddScalar(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fd->AddArray(array);
}

/// Polylines from the core's flat arrays; a closed line repeats its first point.
void WritePolylines(const tessera::Polylines& lines,
  const std::vector<std::uint8_t>& closed,
  vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : lines.Points)
  {
    points->InsertNextPoint(p.x, p.y, 0.0);
  }
  vtkNew<vtkCellArray> cells;
  for (int k = 0; k < lines.Count(); ++k)
  {
    const int begin = lines.Offsets[k], end = lines.Offsets[k + 1];
    const bool isClosed = closed[k] != 0 && end - begin > 2;
    cells->InsertNextCell(end - begin + (isClosed ? 1 : 0));
    for (int i = begin; i < end; ++i)
    {
      cells->InsertCellPoint(i);
    }
    if (isClosed)
    {
      cells->InsertCellPoint(begin);
    }
  }
  output->SetPoints(points);
  output->SetLines(cells);
}

vtkSmartPointer<vtkUnsignedCharArray> ByteArray(const char* name,
  const std::vector<std::uint8_t>& v)
{
  auto array = vtkSmartPointer<vtkUnsignedCharArray>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(v.size()));
  std::copy(v.begin(), v.end(), array->GetPointer(0));
  return array;
}

/// The whole extent of the field image on grid (0, -1, ... for an empty grid).
void ExtentOf(const tessera::PixelGrid& grid, int extent[6])
{
  const bool empty = grid.PixelCount() == 0;
  const int bounds[6] = {
    0, empty ? -1 : grid.Width - 1, 0, empty ? -1 : grid.Height - 1, 0, empty ? -1 : 0
  };
  std::copy(bounds, bounds + 6, extent);
}

/// The grid's pixel values onto an image of width x height pixels from its lower left corner,
/// straight into the array: the rows that both have, cropped or padded with `fill`.
template<class T, class ArrayT>
void CopyOntoImage(const std::vector<T>& values,
  const tessera::PixelGrid& grid,
  int width,
  int height,
  T fill,
  ArrayT* array)
{
  array->SetNumberOfValues(static_cast<vtkIdType>(width) * height);
  T* out = array->GetPointer(0);
  std::fill(out, out + static_cast<std::size_t>(width) * height, fill);
  const int columns = std::min(width, grid.Width);
  for (int j = 0; j < std::min(height, grid.Height); ++j)
  {
    const T* row = values.data() + static_cast<std::size_t>(j) * grid.Width;
    std::copy(row, row + columns, out + static_cast<std::size_t>(j) * width);
  }
}

/// The core's settings from the filter's.
tessera::RidgeGroupingSettings CoreSettings(vtkRidgeGrouping* self)
{
  tessera::RidgeGroupingSettings settings;
  settings.Basis = self->GetBasis() == vtkRidgeGrouping::GAUSSIAN
    ? tessera::RadialBasis::Gaussian
    : tessera::RadialBasis::InverseMultiquadric;
  settings.Width = self->GetWidth();
  settings.ImageSize = self->GetImageSize();
  settings.CurveSigma = self->GetCurveSigma();
  settings.Join = self->GetJoinRule() == vtkRidgeGrouping::CLOSEST_TANGENT
    ? tessera::JoinRule::ClosestTangent
    : tessera::JoinRule::Longest;
  settings.MinimumContourLength = self->GetMinimumContourLength();
  return settings;
}

/// Where points lie off the plane z = 0, that only x and y are read: a curve drawn in the x-z
/// plane was grouped as a straight line, and points at z = 5 lay above their contours and curves
/// (at z = 0), with no word. "" when every z is 0.
std::string OffPlaneWarning(vtkPoints* points)
{
  if (!points || points->GetNumberOfPoints() == 0)
  {
    return std::string();
  }
  double bounds[6];
  points->GetBounds(bounds);
  // (every z NaN leaves VTK's bounds inverted: z is not read, and no range to give)
  if ((bounds[4] == 0.0 && bounds[5] == 0.0) || !(bounds[4] <= bounds[5]))
  {
    return std::string();
  }
  return "the points' z runs from " + tessera::NumberText(bounds[4]) + " to " +
    tessera::NumberText(bounds[5]) +
    ": only x and y are read, so the points are grouped as they lie in the plane z = 0, where "
    "the contours, curves and image are (give points whose curves lie in the x-y plane)";
}

/// The core's grouping of the points, over progress 0.05 to 0.9, with its warnings given.
tessera::RidgeGroupingResult RunGrouping(vtkRidgeGrouping* self,
  const std::vector<tessera::Point2>& points)
{
  const tessera::RidgeGrouping grouping(CoreSettings(self));
  tessera_vtk::ProgressOrStop(self, 0.05);
  tessera::RidgeGroupingResult result =
    grouping.Run(points, tessera_vtk::StageProgress(self, 0.05, 0.9));
  tesseraWarnEachMacro(self, result.Warnings);
  return result;
}

/// Output 0's geometry: the input's points, one vertex each, with the input's point data.
void PassPointsAsVertices(vtkPointSet* input, vtkIdType n, vtkPolyData* pointsOut)
{
  if (input->GetPoints())
  {
    pointsOut->SetPoints(input->GetPoints());
  }
  vtkNew<vtkCellArray> verts;
  for (vtkIdType i = 0; i < n; ++i)
  {
    verts->InsertNextCell(1, &i);
  }
  pointsOut->SetVerts(verts);
  pointsOut->GetPointData()->PassData(input->GetPointData());
}

/// Output 0's point data GroupId, Node and ContourDistance (input arrays of those names renamed).
void AddGroupArrays(vtkRidgeGrouping* self,
  const tessera::RidgeGroupingResult& result,
  vtkIdType n,
  vtkPolyData* pointsOut)
{
  // (copies: the passed arrays are the input's, which keep their names)
  const tessera_vtk::RenamedArrays renamed = tessera_vtk::RenameArraysNamed(
    pointsOut->GetPointData(), { "GroupId", "Node", "ContourDistance" }, true);
  if (!renamed.empty())
  {
    vtkWarningWithObjectMacro(
      self, << tessera_vtk::RenamedArraysWarning(renamed, "point-data", "output 0", "point"));
  }
  vtkNew<vtkIntArray> groups;
  groups->SetName("GroupId");
  vtkNew<vtkDoubleArray> nodes;
  nodes->SetName("Node");
  vtkNew<vtkDoubleArray> distances;
  distances->SetName("ContourDistance");
  groups->SetNumberOfValues(n);
  nodes->SetNumberOfValues(n);
  distances->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    groups->SetValue(i, result.GroupId.empty() ? -1 : result.GroupId[i]);
    nodes->SetValue(i, result.Node.empty() ? 0.0 : result.Node[i]);
    distances->SetValue(i,
      result.ContourDistance.empty() ? std::numeric_limits<double>::quiet_NaN()
                                     : result.ContourDistance[i]);
  }
  pointsOut->GetPointData()->AddArray(groups);
  pointsOut->GetPointData()->AddArray(nodes);
  pointsOut->GetPointData()->AddArray(distances);
  pointsOut->GetPointData()->SetActiveScalars("GroupId"); // (ParaView colours the groups)
}

/// Output 0's field data: the image's size, pixel size and error bound, and the duplicates.
void AddGroupingFieldData(vtkRidgeGrouping* self,
  const tessera::RidgeGroupingResult& result,
  vtkPolyData* pointsOut)
{
  // The input's field data (passed on by the pipeline) keeps arrays of these names as NAME_input.
  const tessera_vtk::RenamedArrays renamedFields =
    tessera_vtk::RenameArraysNamed(pointsOut->GetFieldData(),
      { "ImageSize", "PixelSize", "FieldErrorBound", "DuplicatePointIds", "DuplicateOfPointIds" },
      true);
  if (!renamedFields.empty())
  {
    vtkWarningWithObjectMacro(
      self, << tessera_vtk::RenamedArraysWarning(renamedFields, "field-data", "output 0", "field"));
  }
  AddScalar(pointsOut->GetFieldData(), "ImageSize", result.ImageSize);
  AddScalar(pointsOut->GetFieldData(), "PixelSize", result.PixelSize);
  AddScalar(pointsOut->GetFieldData(), "FieldErrorBound", result.FieldErrorBound);
  tessera_vtk::AddDuplicatePointIds(pointsOut, result.Duplicates);
}

/// Output 1: the ridge contours with cell data ContourId, Closed and Length.
void WriteContours(const tessera::RidgeGroupingResult& result, vtkPolyData* contoursOut)
{
  WritePolylines(result.Contours, result.ContourClosed, contoursOut);
  vtkNew<vtkIntArray> contourIds;
  contourIds->SetName("ContourId");
  vtkNew<vtkDoubleArray> lengths;
  lengths->SetName("Length");
  for (int k = 0; k < result.Contours.Count(); ++k)
  {
    contourIds->InsertNextValue(k);
    lengths->InsertNextValue(result.ContourLength[k]);
  }
  contoursOut->GetCellData()->AddArray(contourIds);
  contoursOut->GetCellData()->AddArray(ByteArray("Closed", result.ContourClosed));
  contoursOut->GetCellData()->AddArray(lengths);
  contoursOut->GetCellData()->SetActiveScalars(contourIds->GetName());
}

/// Output 2: the fitted curves with cell data GroupId and Closed.
void WriteCurves(const tessera::RidgeGroupingResult& result, vtkPolyData* curvesOut)
{
  WritePolylines(result.Curves, result.CurveClosed, curvesOut);
  vtkNew<vtkIntArray> curveGroups;
  curveGroups->SetName("GroupId");
  for (int g : result.CurveGroupId)
  {
    curveGroups->InsertNextValue(g);
  }
  curvesOut->GetCellData()->AddArray(curveGroups);
  curvesOut->GetCellData()->AddArray(ByteArray("Closed", result.CurveClosed));
  curvesOut->GetCellData()->SetActiveScalars("GroupId");
}

/// The warning that the grid made differs from the width x height pixels announced.
void WarnOfUnannouncedGrid(vtkRidgeGrouping* self,
  const tessera::PixelGrid& grid,
  int width,
  int height)
{
  vtkWarningWithObjectMacro(self,
    << "the field image's grid (" << grid.Width << " x " << grid.Height
    << " pixels, from the points at this time) differs from the one announced "
       "to the pipeline, from the points when it last asked ("
    << width << " x " << height
    << "): it is given on the announced pixels from its lower left corner, "
    << (grid.Width > width || grid.Height > height ? "cropped" : "padded")
    << " (Field NaN, ridges 0 where padded); modify the filter to announce "
       "the new grid");
}

/// The image's point data Field, MinorRidge and MajorRidge on outWidth x outHeight pixels.
void AddFieldArrays(const tessera::RidgeGroupingResult& result,
  int outWidth,
  int outHeight,
  vtkImageData* imageOut)
{
  const tessera::PixelGrid& grid = result.Grid;
  vtkNew<vtkDoubleArray> field;
  field->SetName("Field");
  CopyOntoImage(
    result.Field, grid, outWidth, outHeight, std::numeric_limits<double>::quiet_NaN(), field.Get());
  imageOut->GetPointData()->AddArray(field);
  imageOut->GetPointData()->SetActiveScalars("Field");
  for (const auto& [name, ridge] : { std::make_pair("MinorRidge", &result.MinorRidge),
         std::make_pair("MajorRidge", &result.MajorRidge) })
  {
    vtkNew<vtkUnsignedCharArray> mask;
    mask->SetName(name);
    CopyOntoImage(*ridge, grid, outWidth, outHeight, std::uint8_t(0), mask.Get());
    imageOut->GetPointData()->AddArray(mask);
  }
}

/// Output 3: the field image, on the extent announced in imageInfo.
void WriteFieldImage(vtkRidgeGrouping* self,
  const tessera::RidgeGroupingResult& result,
  vtkInformation* imageInfo,
  vtkImageData* imageOut)
{
  const tessera::PixelGrid& grid = result.Grid;
  int advertised[6] = { 0, -1, 0, -1, 0, -1 };
  imageInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), advertised);
  int made[6];
  ExtentOf(grid, made);
  // The image keeps the extent announced: RequestInformation chose it from the points as they
  // were then, and a change of time alone does not run it again, while consumers ask for that
  // extent (the made one, advertised instead, failed their next request with VTK's extent
  // errors, and the filter's outputs stayed at the last time). A grid of another size is given
  // on the announced pixels from its lower left corner, cropped or padded.
  const int width = advertised[1] - advertised[0] + 1;
  const int height = advertised[3] - advertised[2] + 1;
  const bool fits = std::equal(made, made + 6, advertised);
  if (!fits && width > 0 && height > 0 && grid.PixelCount() > 0)
  {
    WarnOfUnannouncedGrid(self, grid, width, height);
  }
  const int outWidth = fits || width <= 0 ? grid.Width : width;
  const int outHeight = fits || height <= 0 ? grid.Height : height;
  imageOut->SetDimensions(outWidth, outHeight, grid.PixelCount() > 0 ? 1 : 0);
  imageOut->SetOrigin(grid.OriginX, grid.OriginY, 0.0);
  imageOut->SetSpacing(grid.Spacing, grid.Spacing, 1.0);
  if (grid.PixelCount() > 0)
  {
    AddFieldArrays(result, outWidth, outHeight, imageOut);
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkRidgeGrouping::vtkRidgeGrouping()
{
  this->SetNumberOfOutputPorts(4);
}

int vtkRidgeGrouping::FillInputPortInformation(int, vtkInformation* info)
{
  // Any data object: InputPoints takes points or a composite of them and names any other type
  // (a type the pipeline refused never reached RequestData, and the last results stayed).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

int vtkRidgeGrouping::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 3 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkRidgeGrouping::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  // The field image's extent, origin and spacing, which the pipeline needs before RequestData:
  // without them a consumer asks for an empty extent (ParaView showed the image as nothing). They
  // depend on the points, so the input is brought up to date and its grid chosen here as Run
  // will choose it (no field is computed).
  tessera::PixelGrid grid; // empty until the input gives one
  try
  {
    if (vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0))
    {
      std::vector<std::string> ignored; // (RequestData gives the warnings)
      const vtkSmartPointer<vtkPointSet> input =
        tessera_vtk::InputPoints(tessera_vtk::UpdatedData(connection), ignored);
      grid = tessera::RidgeGrouping(CoreSettings(this))
               .ImageGridOf(tessera_vtk::ReadPoints2D(input->GetPoints()));
    }
  }
  catch (const std::exception&)
  {
    // RequestData reads the same input and settings, and reports the error.
  }
  int extent[6];
  ExtentOf(grid, extent);
  const double origin[3] = { grid.OriginX, grid.OriginY, 0.0 };
  const double spacing[3] = { grid.Spacing, grid.Spacing, 1.0 };
  vtkInformation* imageInfo = outputVector->GetInformationObject(3);
  imageInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  imageInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  imageInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkRidgeGrouping::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Every point at once: see RequestWholeInputs (ParaView under MPI asks each process for a
  // piece, and each grouped its own piece's points).
  tessera_vtk::RequestWholeInputs(inputVector, 0, 0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkRidgeGrouping::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (!tessera_vtk::MakesOutput(outputVector))
  {
    return 1; // another process's piece: the first makes the whole output (RequestWholeInputs)
  }
  vtkDataObject* inputData = vtkDataObject::GetData(inputVector[0]);
  vtkPolyData* pointsOut = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* contoursOut = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* curvesOut = vtkPolyData::GetData(outputVector, 2);
  vtkImageData* imageOut = vtkImageData::GetData(outputVector, 3);
  try
  {
    tessera_vtk::CheckChoice("Basis", this->Basis, { "InverseMultiquadric", "Gaussian" });
    tessera_vtk::CheckChoice("JoinRule", this->JoinRule, { "Longest", "ClosestTangent" });
    std::vector<std::string> notCarried;
    const vtkSmartPointer<vtkPointSet> input = tessera_vtk::InputPoints(inputData, notCarried);
    tesseraWarnEachMacro(this, notCarried);
    const std::vector<tessera::Point2> points =
      tessera_vtk::ReadPoints2D(input->GetPoints(), inputData);
    tesseraWarnUnlessEmptyMacro(this, OffPlaneWarning(input->GetPoints()));
    const tessera::RidgeGroupingResult result = RunGrouping(this, points);

    // Output 0: the points with GroupId and Node.
    const vtkIdType n = static_cast<vtkIdType>(points.size());
    PassPointsAsVertices(input, n, pointsOut);
    AddGroupArrays(this, result, n, pointsOut);
    AddGroupingFieldData(this, result, pointsOut);

    // Output 1: ridge contours.
    WriteContours(result, contoursOut);

    // Output 2: fitted curves.
    WriteCurves(result, curvesOut);

    // Output 3: the field image.
    WriteFieldImage(this, result, outputVector->GetInformationObject(3), imageOut);
    for (vtkDataObject* output : { static_cast<vtkDataObject*>(pointsOut),
           static_cast<vtkDataObject*>(contoursOut),
           static_cast<vtkDataObject*>(curvesOut),
           static_cast<vtkDataObject*>(imageOut) })
    {
      tessera_vtk::ListNonEmptyFieldArraysFirst(output);
    }
    return 1;
  }
  catch (const std::exception& e)
  {
    // (a stop that a progress observer asked for empties the outputs too, without an error)
    pointsOut->Initialize();
    contoursOut->Initialize();
    curvesOut->Initialize();
    imageOut->Initialize();
    return tesseraErrorOrStopMacro(e);
  }
}

//------------------------------------------------------------------------------
void vtkRidgeGrouping::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Basis: " << (this->Basis == GAUSSIAN ? "Gaussian" : "InverseMultiquadric")
     << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "ImageSize: " << this->ImageSize << "\n";
  os << indent << "CurveSigma: " << this->CurveSigma << "\n";
  os << indent << "JoinRule: " << (this->JoinRule == CLOSEST_TANGENT ? "ClosestTangent" : "Longest")
     << "\n";
  os << indent << "MinimumContourLength: " << this->MinimumContourLength << "\n";
}
