// Uses both installed targets, as a GoogleTest of a user's own: the core's tessellation and the
// VTK filter, on the same points, must agree with each other and with the window's area.
#include "dirichlet_tessellation.h" // Tessera::core
#include "tiles.h"
#include "window.h"

#include "vtkCellData.h"
#include "vtkDirichletTessellation.h" // Tessera::Filters
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

TEST(InstalledTessera, TheFilterAndTheCoreGiveTheSameTiles)
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
  ASSERT_TRUE(areas && ids) << "the filter's output lacks its Area or PointId array";
  ASSERT_EQ(areas->GetNumberOfTuples(), static_cast<vtkIdType>(tiles.Areas.size()))
    << "tiles of the filter and of the core";
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
    ASSERT_LT(id, points.size()) << "a tile's PointId is no input point";
    EXPECT_NEAR(area, coreArea[id], 1e-12 * area) << "the tile of point " << id;
  }
  EXPECT_NEAR(sum, 1.0, 1e-12) << "the tiles' areas against the window's";
}
