// vtkGeographicProjection in a C++ pipeline: densification along parallels, equal area against
// GeographicLib's ellipsoidal polygon area, the inverse read from field data, the antimeridian,
// and bad input.
#include "vtkGeographicProjection.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/PolygonArea.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{

class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    ++this->Count;
    this->LastMessage = static_cast<const char*>(callData);
  }
  int Count = 0;
  std::string LastMessage;
};

/// A lon/lat rectangle polygon with a point-data array "elev" equal to the longitude.
vtkNew<vtkPolyData> MakeRectangle(double west, double south, double east, double north)
{
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> elev;
  elev->SetName("elev");
  const double corners[4][2] = {
    { west, south }, { east, south }, { east, north }, { west, north }
  };
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(4);
  for (auto& c : corners)
  {
    polys->InsertCellPoint(points->InsertNextPoint(c[0], c[1], 0.0));
    elev->InsertNextValue(c[0]);
  }
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->AddArray(elev);
  return poly;
}

double PlanarArea(vtkPolyData* poly)
{
  vtkNew<vtkIdList> ids;
  poly->GetPolys()->GetCellAtId(0, ids);
  double twice = 0.0;
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    double a[3], b[3];
    poly->GetPoint(ids->GetId(k), a);
    poly->GetPoint(ids->GetId((k + 1) % ids->GetNumberOfIds()), b);
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * twice;
}

} // namespace

TEST(GeographicProjection, DensifiedPolygonKeepsEllipsoidalArea)
{
  auto rectangle = MakeRectangle(-109.0, 37.0, -102.0, 41.0);
  vtkNew<vtkGeographicProjection> projection;
  projection->SetInputData(rectangle);
  projection->SetMaximumEdgeLength(0.1);
  projection->Update();
  auto* out = vtkPolyData::SafeDownCast(projection->GetOutput());
  ASSERT_NE(out, nullptr);
  // 7 degree edges in 70 pieces and 4 degree edges in 40: 4 corners + 2*69 + 2*39 new points.
  EXPECT_EQ(out->GetNumberOfPoints(), 4 + 2 * 69 + 2 * 39);
  EXPECT_EQ(out->GetPolys()->GetNumberOfConnectivityIds(), 220);

  // Independent area: GeographicLib along the same lon/lat-straight edges, finely cut.
  GeographicLib::PolygonArea polygon(GeographicLib::Geodesic::WGS84());
  const double corners[5][2] = {
    { -109, 37 }, { -102, 37 }, { -102, 41 }, { -109, 41 }, { -109, 37 }
  };
  for (int e = 0; e < 4; ++e)
  {
    for (int k = 0; k < 1000; ++k)
    {
      const double t = k / 1000.0;
      polygon.AddPoint(corners[e][1] + t * (corners[e + 1][1] - corners[e][1]),
        corners[e][0] + t * (corners[e + 1][0] - corners[e][0]));
    }
  }
  double perimeter = 0.0, ellipsoidal = 0.0;
  polygon.Compute(false, true, perimeter, ellipsoidal);
  EXPECT_NEAR(PlanarArea(out) / ellipsoidal, 1.0, 1e-5);

  // Interpolated point data follows the new points (elev = longitude at the corners).
  auto* elev = out->GetPointData()->GetArray("elev");
  ASSERT_NE(elev, nullptr);
  EXPECT_NEAR(elev->GetTuple1(4), -109.0 + 0.1, 1e-9);

  // The record is written, and the inverse reads it: every point returns to its lon/lat, the
  // interior points of the southern edge to latitude 37 exactly as a parallel should.
  auto* record =
    vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("TesseraProjection"));
  ASSERT_NE(record, nullptr);
  EXPECT_EQ(record->GetValue(0).rfind("projection=AlbersEqualArea", 0), 0u);
  vtkNew<vtkGeographicProjection> inverse;
  inverse->SetInputConnection(projection->GetOutputPort());
  inverse->InverseOn();
  inverse->Update();
  auto* back = inverse->GetOutput();
  EXPECT_EQ(back->GetFieldData()->GetAbstractArray("TesseraProjection"), nullptr);
  for (vtkIdType i = 4; i < 4 + 69; ++i)
  {
    double p[3];
    back->GetPoint(i, p);
    EXPECT_NEAR(p[1], 37.0, 1e-9) << i;
    EXPECT_NEAR(p[0], -109.0 + 0.1 * (i - 3), 1e-9) << i;
  }
}

TEST(GeographicProjection, UTMZoneFromData)
{
  auto rectangle = MakeRectangle(-106.0, 39.0, -104.5, 40.0);
  vtkNew<vtkGeographicProjection> projection;
  projection->SetInputData(rectangle);
  projection->SetProjectionToUTM();
  projection->SetMaximumEdgeLength(0);
  projection->Update();
  auto* record = vtkStringArray::SafeDownCast(
    projection->GetOutput()->GetFieldData()->GetAbstractArray("TesseraProjection"));
  ASSERT_NE(record, nullptr);
  EXPECT_NE(record->GetValue(0).find("zone=13"), std::string::npos) << record->GetValue(0);
  double p[3];
  projection->GetOutput()->GetPoint(0, p);
  EXPECT_GT(p[0], 0.0);
  EXPECT_LT(p[0], 500000.0); // west of zone 13's central meridian (-105)
}

TEST(GeographicProjection, PointsAcrossTheAntimeridianStayTogether)
{
  vtkNew<vtkPolyData> quakes;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(165.67, -20.0, 0);
  points->InsertNextPoint(181.62, -15.0, 0);
  points->InsertNextPoint(-179.0, -25.0, 0);
  quakes->SetPoints(points);
  vtkNew<vtkGeographicProjection> projection;
  projection->SetInputData(quakes);
  projection->Update();
  double a[3], b[3];
  projection->GetOutput()->GetPoint(0, a);
  projection->GetOutput()->GetPoint(1, b);
  // The geodesic from (165.67, -20) to (181.62, -15) is about 1770 km; an equal-area conic fitted
  // to the data keeps it within a few percent (the long way round would be 35000 km).
  const double planar = std::hypot(b[0] - a[0], b[1] - a[1]);
  EXPECT_NEAR(planar / 1.77e6, 1.0, 0.03);
  EXPECT_GT(b[0], a[0]); // east stays east across the antimeridian
}

TEST(GeographicProjection, BadPointGivesErrorNamingItAndEmptyOutput)
{
  auto rectangle = MakeRectangle(-109.0, 37.0, -102.0, 41.0);
  rectangle->GetPoints()->SetPoint(2, -102.0, 95.0, 0.0);
  vtkNew<vtkGeographicProjection> projection;
  vtkNew<ErrorCounter> errors;
  projection->AddObserver(vtkCommand::ErrorEvent, errors);
  projection->SetInputData(rectangle);
  projection->Update();
  EXPECT_EQ(errors->Count, 1);
  EXPECT_NE(errors->LastMessage.find("point 2"), std::string::npos) << errors->LastMessage;
  EXPECT_NE(errors->LastMessage.find("95"), std::string::npos) << errors->LastMessage;
  EXPECT_EQ(projection->GetOutput()->GetNumberOfPoints(), 0);
}
