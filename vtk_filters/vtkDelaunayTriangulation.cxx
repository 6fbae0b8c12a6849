#include "vtkDelaunayTriangulation.h"

#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"

#include "TesseraFilterUtilities.h"
#include "dirichlet_tessellation.h"
#include "large_pages.h"
#include "tiles.h"

#include <algorithm>
#include <exception>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkDelaunayTriangulation);

namespace
{
vtkNew<vtkTypeInt32Array> Int32Array(std::size_t size)
{
  vtkNew<vtkTypeInt32Array> array;
  tessera_vtk::AllocateValues(array.Get(), static_cast<vtkIdType>(size));
  return array;
}

// The Delaunay faces in a cell array with 32-bit storage, which VTK reads like the 64-bit kind:
// the core writes the triangles straight into it, so the common case copies nothing (about 40 ms
// of a 300 ms run at 1M points went to building the faces apart and widening them to vtkIdType).
vtkNew<vtkCellArray> FacesOf(const tessera::DirichletTessellation& tessellation, bool split)
{
  const std::size_t capacity = tessera::DelaunayFaceCapacity(tessellation);
  auto connectivity = Int32Array(3 * capacity);
  auto offsets = Int32Array(capacity + 1);
  const std::int64_t triangles = tessera::WriteTriangularDelaunayFaces(
    tessellation, connectivity->GetPointer(0), offsets->GetPointer(0));
  if (triangles >= 0)
  {
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(3 * triangles));
    offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles + 1));
  }
  else
  {
    // Degenerate faces (or no triangles at all): the general derivation, then one copy. Straight
    // to the dual: ComputeDelaunayFaces would first try the fast path again.
    const tessera::DelaunayFaces faces = tessera::TessellationDual(tessellation).Faces(split);
    connectivity = Int32Array(faces.PointIds.size());
    std::copy(faces.PointIds.begin(), faces.PointIds.end(), connectivity->GetPointer(0));
    offsets = Int32Array(faces.Offsets.size());
    std::copy(faces.Offsets.begin(), faces.Offsets.end(), offsets->GetPointer(0));
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  return polys;
}

/// The tessellation whose dual gives the triangles (progress 0.1 once the window is cut to the
/// points).
tessera::DirichletTessellation Triangulate(vtkDelaunayTriangulation* self,
  tessera::Window window,
  std::vector<tessera::Point2> points)
{
  // Coordinates of some 1e100 or more, or 1e-100 or less: the triangulation of points and
  // window scaled by a power of two (exactly) is the same, and its faces are ids, so nothing is
  // scaled back; every decision then stays within the predicates' exact range.
  window = tessera_vtk::CutToPoints(std::move(window), points);
  tessera::ScaleIntoExactRange(window, points);
  tessera_vtk::ProgressOrStop(self, 0.1);
  return tessera::DirichletTessellation(std::move(window), std::move(points));
}

/// The output's points (the input's, with their point data) and the Delaunay faces on them.
void WritePointsAndFaces(vtkPointSet* input,
  const tessera::DirichletTessellation& tessellation,
  bool split,
  vtkPolyData* output)
{
  if (input->GetPoints())
  {
    output->SetPoints(input->GetPoints());
  }
  output->GetPointData()->PassData(input->GetPointData());
  output->SetPolys(FacesOf(tessellation, split));
}

/// The output's field data naming the points not triangulated (tessera_vtk::AddUnusedPointIds),
/// and the warnings for them and for a window with no point in it.
void AddUnusedPoints(vtkDelaunayTriangulation* self,
  const tessera::DirichletTessellation& tessellation,
  const tessera::Box2& windowBox,
  vtkPoints* inputPoints,
  vtkPolyData* output)
{
  const std::vector<std::int32_t> rejected = tessellation.RejectedIds();
  const auto duplicates = tessellation.Duplicates();
  const tessera_vtk::RenamedArrays renamed =
    tessera_vtk::AddUnusedPointIds(output, rejected, duplicates);
  if (!renamed.empty())
  {
    vtkWarningWithObjectMacro(
      self, << tessera_vtk::RenamedArraysWarning(renamed, "field-data", "the output", "field"));
  }
  tesseraWarnUnlessEmptyMacro(self,
    tessera_vtk::PointsNotUsedWarning(
      windowBox, rejected, duplicates, "triangulated", "triangle", inputPoints));
}

/// The warning for triangulated points that make no triangle (fewer than three, or on one line).
void WarnOfNoTriangle(vtkDelaunayTriangulation* self,
  const tessera::DirichletTessellation& tessellation)
{
  // An output of points and no face, said (a ParaView user saw nothing and no message).
  const std::size_t accepted = tessellation.AcceptedCount();
  if (accepted > 0 && !tessellation.IsTwoDimensional())
  {
    const std::string why = accepted < 3
      ? "fewer than three distinct points are triangulated"
      : "the " + std::to_string(accepted) + " distinct points triangulated all lie on one line";
    vtkWarningWithObjectMacro(self,
      << "no Delaunay triangle: " << why
      << " (Dirichlet Tessellation gives their tiles, strips across the window)");
  }
}

} // namespace

//------------------------------------------------------------------------------
void vtkDelaunayTriangulation::AddWindowConstraint(double a, double b, double c)
{
  this->WindowConstraints.insert(this->WindowConstraints.end(), { a, b, c });
  this->Modified();
}

int vtkDelaunayTriangulation::GetNumberOfWindowConstraints() const
{
  return static_cast<int>(this->WindowConstraints.size() / 3);
}

//------------------------------------------------------------------------------
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
  // Any data object: InputPoints takes points or a composite of them and names any other type
  // (a type the pipeline refused never reached RequestData, and the last results stayed).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkDelaunayTriangulation::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Every point at once: see RequestWholeInputs (ParaView under MPI asks each process for a
  // piece, and each made the tessellation of its own piece's points).
  tessera_vtk::RequestWholeInputs(inputVector, 0, 0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkDelaunayTriangulation::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (!tessera_vtk::MakesOutput(outputVector))
  {
    return 1; // another process's piece: the first makes the whole output (RequestWholeInputs)
  }
  vtkDataObject* inputData = vtkDataObject::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  try
  {
    std::vector<std::string> notCarried;
    const vtkSmartPointer<vtkPointSet> input = tessera_vtk::InputPoints(inputData, notCarried);
    tesseraWarnEachMacro(this, notCarried);
    // Large arrays freed by one step go to the next (tessera::ReuseLargeBlocks, as in
    // vtkDirichletTessellation): the build's temporaries to the output's arrays.
    const tessera::ReuseLargeBlocks reuse;
    std::vector<tessera::Point2> points = tessera_vtk::ReadPoints2D(input->GetPoints(), inputData);
    if (points.empty())
    {
      vtkWarningMacro(<< tessera_vtk::NoPointsWarning("triangle"));
    }
    tessera::Window window = tessera_vtk::ChooseWindowWithWarning(
      this, this->WindowBounds, this->WindowConstraints, this->Padding, points, false);
    const tessera::Box2 windowBox = window.Bounds();
    const tessera::DirichletTessellation tessellation =
      Triangulate(this, std::move(window), std::move(points));
    tessera_vtk::ProgressOrStop(this, 0.7);

    WritePointsAndFaces(input, tessellation, this->SplitDegenerateFaces, output);
    AddUnusedPoints(this, tessellation, windowBox, input->GetPoints(), output);
    WarnOfNoTriangle(this, tessellation);
    tessera_vtk::ListNonEmptyFieldArraysFirst(output);
    return 1;
  }
  catch (const std::exception& e)
  {
    // (a stop that a progress observer asked for empties the outputs too, without an error)
    output->Initialize();
    return tesseraErrorOrStopMacro(e);
  }
}

//------------------------------------------------------------------------------
void vtkDelaunayTriangulation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SplitDegenerateFaces: " << this->SplitDegenerateFaces << "\n";
  os << indent << "WindowBounds: " << this->WindowBounds[0] << ", " << this->WindowBounds[1] << ", "
     << this->WindowBounds[2] << ", " << this->WindowBounds[3] << "\n";
  os << indent << "WindowConstraints: " << this->GetNumberOfWindowConstraints() << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
}
