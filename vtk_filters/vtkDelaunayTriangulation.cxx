#include "vtkDelaunayTriangulation.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "TesseraFilterUtilities.h"
#include "dirichlet_tessellation.h"
#include "parallel_chunks.h"
#include "tiles.h"

#include <algorithm>
#include <exception>
#include <string>
#include <utility>

vtkStandardNewMacro(vtkDelaunayTriangulation);

//------------------------------------------------------------------------------
void vtkDelaunayTriangulation::AddWindowConstraint(double a, double b, double c)
{
  this->WindowConstraints.insert(this->WindowConstraints.end(), { a, b, c });
  this->Modified();
}

void vtkDelaunayTriangulation::RemoveAllWindowConstraints()
{
  if (!this->WindowConstraints.empty())
  {
    this->WindowConstraints.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkDelaunayTriangulation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkDelaunayTriangulation::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  try
  {
    std::vector<tessera::Point2> points = tessera_vtk::ReadPoints2D(input->GetPoints());
    tessera::Window window =
      tessera_vtk::ChooseWindow(this->WindowBounds, this->WindowConstraints, this->Padding, points);
    const tessera::DirichletTessellation tessellation(std::move(window), std::move(points));
    this->UpdateProgress(0.7);
    const tessera::DelaunayFaces faces =
      tessera::ComputeDelaunayFaces(tessellation, this->SplitDegenerateFaces);

    if (input->GetPoints())
    {
      output->SetPoints(input->GetPoints());
    }
    output->GetPointData()->PassData(input->GetPointData());
    // The two id arrays are widened to vtkIdType side by side (two threads for large outputs).
    vtkNew<vtkIdTypeArray> connectivity;
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(faces.PointIds.size()));
    vtkNew<vtkIdTypeArray> offsets;
    offsets->SetNumberOfValues(static_cast<vtkIdType>(faces.Offsets.size()));
    tessera::parallel::RunSideBySide(
      tessera::parallel::ThreadCount(std::int64_t(faces.Offsets.size()), 50000) > 1,
      [&]()
      { std::copy(faces.PointIds.begin(), faces.PointIds.end(), connectivity->GetPointer(0)); },
      [&]() { std::copy(faces.Offsets.begin(), faces.Offsets.end(), offsets->GetPointer(0)); });
    vtkNew<vtkCellArray> polys;
    polys->SetData(offsets, connectivity);
    output->SetPolys(polys);

    const std::vector<std::int32_t> rejected = tessellation.RejectedIds();
    const auto duplicates = tessellation.Duplicates();
    tessera_vtk::AddUnusedPointIds(output, rejected, duplicates);
    const std::string unused =
      tessera_vtk::UnusedPointsWarning(rejected.size(), duplicates.size(), "triangulated");
    if (!unused.empty())
    {
      vtkWarningMacro(<< unused);
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
void vtkDelaunayTriangulation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SplitDegenerateFaces: " << this->SplitDegenerateFaces << "\n";
  os << indent << "WindowBounds: " << this->WindowBounds[0] << ", " << this->WindowBounds[1] << ", "
     << this->WindowBounds[2] << ", " << this->WindowBounds[3] << "\n";
  os << indent << "WindowConstraints: " << this->WindowConstraints.size() / 3 << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
}
