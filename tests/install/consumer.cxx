// Uses both installed targets: the core's tessellation and the VTK filter, on the same points, and
// requires them to agree with each other and with the window's area (Failed, require.h). Prints
// "ok" when every requirement held.
#include "require.h"

#include "dirichlet_tessellation.h" // Tessera::core
#include "tiles.h"
#include "window.h"

#include "vtkDirichletTessellation.h" // Tessera::Filters
#include "vtkDoubleArray.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

int main()
{
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<tessera::Point2> points(500);
  vtkNew<vtkPoints> vtkPts;
  vtkPts->SetDataTypeToDouble();
  for (tessera::Point2& p : points)
  {
    p = { u(random), u(random) };
    vtkPts->InsertNextPoint(p.x, p.y, 0.0);
  }
  tessera::DirichletTessellation core(tessera::Window::Rectangle(0.0, 1.0, 0.0, 1.0), points);
  const tessera::TileSet tiles = tessera::ComputeTiles(core);

  vtkNew<vtkPolyData> input;
  input->SetPoints(vtkPts);
  vtkNew<vtkDirichletTessellation> filter;
  filter->SetInputData(input);
  filter->SetWindowBounds(0.0, 1.0, 0.0, 1.0);
  filter->Update();
  vtkCellData* cells = filter->GetOutput()->GetCellData();
  auto* areas = vtkDoubleArray::SafeDownCast(cells->GetArray("Area"));
  vtkDataArray* ids = cells->GetArray("PointId");
  if (!(areas && ids))
  {
    return Failed("the filter's output lacks its Area or PointId array");
  }
  if (!(areas->GetNumberOfTuples() == static_cast<vtkIdType>(tiles.Areas.size())))
  {
    return Failed("the filter gave %lld tiles, the core %zu",
      static_cast<long long>(areas->GetNumberOfTuples()),
      tiles.Areas.size());
  }
  std::vector<double> coreArea(points.size(), -1.0);
  for (std::size_t t = 0; t < tiles.Areas.size(); ++t)
  {
    coreArea[static_cast<std::size_t>(tiles.PointIds[t])] = tiles.Areas[t];
  }
  double sum = 0.0;
  for (vtkIdType c = 0; c < areas->GetNumberOfTuples(); ++c)
  {
    const double area = areas->GetValue(c);
    const auto id = static_cast<std::size_t>(ids->GetTuple1(c));
    sum += area;
    if (!(id < points.size()))
    {
      return Failed("a tile's PointId %zu is no input point", id);
    }
    if (!(std::abs(area - coreArea[id]) <= 1e-12 * area))
    {
      return Failed(
        "point %zu: the filter's tile area %.17g, the core's %.17g", id, area, coreArea[id]);
    }
  }
  if (!(std::abs(sum - 1.0) <= 1e-12))
  {
    return Failed("the tiles' areas sum to %.17g, not the window's 1", sum);
  }
  std::printf("ok\n");
  return 0;
}
