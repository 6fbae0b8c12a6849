#include "vtkGeographicProjection.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
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

#include "TesseraFilterUtilities.h"
#include "errors.h"
#include "geo.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <tuple>
#include <stdexcept>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkGeographicProjection);

namespace
{
using tessera_vtk::ProjectionRecordName;
using tessera_vtk::ReadProjectionRecord;

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

/// What densifying met, over all pieces: edges cut into MaxDensifiedPieces (their pieces may be
/// longer than the step), and edges that read two ways round the globe (EdgeReadsBothWays), taken
/// the shorter way round (InterpolateLonLat), the first of them named ("block b points a and c,
/// longitude x to y").
struct DensifyReport
{
  vtkIdType Capped = 0;
  vtkIdType Wrapped = 0;
  std::string FirstWrapped;
  /// Pieces whose global ids were not carried (new points have none), and the first's label.
  vtkIdType GlobalIdsDropped = 0;
  std::string FirstGlobalIds;
};

/// A forward's piece counts are exact; an inverse's are taken with this much slack, so that an
/// edge a forward cut into pieces of exactly maxStep degrees, projected and back, is not cut again
/// for the rounding of its ends.
constexpr double InverseStepSlack = 1.0 + 1e-9;

/// The pieces edge a-b of poly is cut into (EdgeDensifier; CheckAddedPoints counts them first): a
/// forward's by its lon/lat ends, the shorter way round; an inverse's by its ends' places as
/// written (places: the lon/lat of poly's points, null for a forward).
int PiecesOfEdge(vtkPolyData* poly,
  vtkIdType a,
  vtkIdType b,
  const std::vector<tessera::Point2>* places,
  double maxStep,
  bool* capped = nullptr)
{
  if (places)
  {
    return tessera::DensifiedPieceCount(
      (*places)[a], (*places)[b], maxStep * InverseStepSlack, capped, true);
  }
  double pa[3], pb[3];
  poly->GetPoint(a, pa);
  poly->GetPoint(b, pb);
  return tessera::DensifiedPieceCount({ pa[0], pa[1] }, { pb[0], pb[1] }, maxStep, capped);
}

/// Cuts the line and polygon edges of poly data so that no piece is longer than maxStep degrees
/// of longitude and latitude. A forward's input is in lon/lat, its edges straight there (RFC 7946),
/// and cut there. An inverse's is in the plane, its edges straight there: each is cut straight,
/// into pieces spanning at most maxStep degrees between the places of its ends (the places of the
/// input's points given), so that its lon/lat output, read with edges straight in lon/lat, keeps
/// the plane's shapes and areas. New points are appended after the input's, with point data
/// interpolated; an edge shared by two cells is cut once, so neighbouring polygons stay
/// conforming.
class EdgeDensifier
{
public:
  /// label: the piece's, put before the first wrapped edge's name; report: added to;
  /// placesOfPoints: an inverse's, the lon/lat of each input point (null for a forward).
  EdgeDensifier(vtkPolyData* input,
    vtkPolyData* output,
    double maxStep,
    const std::string& label,
    DensifyReport& report,
    const std::vector<tessera::Point2>* placesOfPoints = nullptr)
    : Input(input)
    , Output(output)
    , MaxStep(maxStep)
    , Label(label)
    , Report(report)
    , Places(placesOfPoints)
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
    vtkPointData* inputData = this->Input->GetPointData();
    if (this->Points->GetNumberOfPoints() == this->Input->GetNumberOfPoints())
    {
      // Nothing was cut (points, vertices, short edges): the point data as it is, with its roles.
      // (Copying tuples leaves out global ids, which must stay unique: the README's gauges lost
      // theirs on the way to the tiles.)
      this->Output->GetPointData()->Initialize();
      this->Output->GetPointData()->PassData(inputData);
    }
    else if (vtkDataArray* ids = inputData->GetGlobalIds())
    {
      if (this->Report.GlobalIdsDropped++ == 0)
      {
        this->Report.FirstGlobalIds = (this->Label.empty() ? std::string() : this->Label + ": ") +
          "'" + (ids->GetName() ? ids->GetName() : "") + "'";
      }
    }
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
    bool capped = false;
    const tessera::Point2 ends[2] = { { pa[0], pa[1] }, { pb[0], pb[1] } };
    const int pieces = PiecesOfEdge(this->Input, a, b, this->Places, this->MaxStep, &capped);
    this->Report.Capped += capped ? 1 : 0;
    if (!this->Places && tessera::EdgeReadsBothWays(ends[0], ends[1]) &&
      this->Report.Wrapped++ == 0)
    {
      this->Report.FirstWrapped = (this->Label.empty() ? std::string() : this->Label + " ") +
        "points " + std::to_string(a) + " and " + std::to_string(b) + ", longitude " +
        tessera::NumberText(pa[0]) + " to " + tessera::NumberText(pb[0]);
    }
    const vtkIdType first = this->Points->GetNumberOfPoints();
    for (int k = 1; k < pieces; ++k)
    {
      const double t = static_cast<double>(k) / pieces;
      const tessera::Point2 q = this->Places
        ? tessera::Point2{ pa[0] + t * (pb[0] - pa[0]), pa[1] + t * (pb[1] - pa[1]) }
        : tessera::InterpolateLonLat(ends[0], ends[1], t);
      const vtkIdType id = this->Points->InsertNextPoint(q.x, q.y, pa[2] + t * (pb[2] - pa[2]));
      this->Output->GetPointData()->InterpolateEdge(this->Input->GetPointData(), id, a, b, t);
    }
    return { first, pieces };
  }

  vtkPolyData* Input;
  vtkPolyData* Output;
  double MaxStep;
  const std::string& Label;
  DensifyReport& Report;
  const std::vector<tessera::Point2>* Places;
  vtkNew<vtkPoints> Points;
  std::map<std::pair<vtkIdType, vtkIdType>, std::pair<vtkIdType, int>> Cuts;
};

tessera::ProjectionKind KindOf(int projection)
{
  // The values after Automatic name the core's kinds in their order (Automatic and a value out of
  // range: Albers, whose Automatic variant is fitted to the data).
  static_assert(std::size(tessera::ProjectionKinds) ==
      vtkGeographicProjection::WEB_MERCATOR - vtkGeographicProjection::ALBERS_EQUAL_AREA + 1,
    "a Projection value for each kind");
  static_assert(
    tessera::ProjectionKinds[vtkGeographicProjection::WEB_MERCATOR -
      vtkGeographicProjection::ALBERS_EQUAL_AREA] == tessera::ProjectionKind::WebMercator,
    "the kinds in the Projection values' order");
  const bool named = projection >= vtkGeographicProjection::ALBERS_EQUAL_AREA &&
    projection <= vtkGeographicProjection::WEB_MERCATOR;
  return named ? tessera::ProjectionKinds[projection - vtkGeographicProjection::ALBERS_EQUAL_AREA]
               : tessera::ProjectionKind::AlbersEqualArea;
}

/// The Projection values' names, by their index: Automatic, then each projection's own name.
std::vector<const char*> ProjectionChoices()
{
  std::vector<const char*> names = { "Automatic" };
  for (int p = vtkGeographicProjection::ALBERS_EQUAL_AREA;
       p <= vtkGeographicProjection::WEB_MERCATOR;
       ++p)
  {
    names.push_back(tessera::ProjectionKindName(KindOf(p)));
  }
  return names;
}

/// Whether a UTM zone is set by hand (UTMZone 1 to 60): with the hemisphere, the whole of the
/// projection, whatever the data or the other settings say. Then sets p's zone and hemisphere.
bool TakeUTMZoneSet(vtkGeographicProjection* self, tessera::ProjectionParameters& p)
{
  if (self->GetProjection() != vtkGeographicProjection::UTM || self->GetUTMZone() == 0)
  {
    return false;
  }
  p.UTMZone = self->GetUTMZone();
  p.UTMNorth = self->GetUTMNorth();
  return true;
}

/// The grid set on the filter (FalseEasting, ..., LatitudeOfOrigin) laid on p's plane, p as given
/// otherwise.
tessera::ProjectionParameters WithGridSet(vtkGeographicProjection* self,
  tessera::ProjectionParameters p)
{
  p.FalseEasting = self->GetFalseEasting();
  p.FalseNorthing = self->GetFalseNorthing();
  p.ScaleFactor = self->GetScaleFactor();
  p.HasOriginLatitude = self->GetUseLatitudeOfOrigin();
  p.OriginLatitude = p.HasOriginLatitude ? self->GetLatitudeOfOrigin() : 0.0;
  return p;
}

} // namespace

/// The filter's state that its update keeps (the friend of vtkGeographicProjection).
class vtkGeographicProjectionInternals
{
public:
  /// Whether to warn of a LatitudeOfOrigin other than 0 set while UseLatitudeOfOrigin is off:
  /// once per value (NaN included, which equals nothing), and again after the box was on.
  static bool WarnOfUnusedLatitudeOfOrigin(vtkGeographicProjection* self)
  {
    const double latitude = self->LatitudeOfOrigin;
    const bool unused = !self->UseLatitudeOfOrigin && latitude != 0.0;
    const double last = self->UnusedLatitudeWarnedOf;
    const bool same = latitude == last || (std::isnan(latitude) && std::isnan(last));
    self->UnusedLatitudeWarnedOf = unused ? latitude : 0.0;
    return unused && !same;
  }
};

namespace
{

/// Lays the grid set on the filter on p's plane (WithGridSet), warning of a LatitudeOfOrigin set
/// but not used.
void TakeGridTerms(vtkGeographicProjection* self, tessera::ProjectionParameters& p)
{
  p = WithGridSet(self, p);
  if (vtkGeographicProjectionInternals::WarnOfUnusedLatitudeOfOrigin(self) &&
    !p.HasOriginLatitude) // (asked first: it keeps count)
  {
    // (a scripter who set it alone got northings millions of metres off without a word)
    vtkWarningWithObjectMacro(self,
      << "LatitudeOfOrigin " << tessera::NumberText(self->GetLatitudeOfOrigin())
      << " is not used: UseLatitudeOfOrigin is off, so the grid starts at the plane's own origin");
  }
}

/// The whole UTM projection the settings give (Projection UTM, a zone set: TakeUTMZoneSet), with
/// the grid set; nothing where they give none.
std::optional<tessera::ProjectionParameters> UTMZoneSetWithGrid(vtkGeographicProjection* self)
{
  tessera::ProjectionParameters utm;
  utm.Kind = KindOf(vtkGeographicProjection::UTM);
  if (!TakeUTMZoneSet(self, utm))
  {
    return std::nullopt;
  }
  TakeGridTerms(self, utm);
  return utm;
}

/// The widest longitude span a projection cut at a meridian takes without a warning: beyond it
/// the data's largest empty gap in longitude, where the cut runs, is under a quarter turn.
constexpr double WidestSpanWithoutWarning = 270.0;

/// Warns where the data go (nearly) round the globe and p's projection is cut at a meridian (all
/// but the azimuthal ones): places either side of the cut, close on the ground, lie far apart in
/// the plane. (Stations all round Antarctica were cut at one meridian without a word, and the
/// tiles of neighbours 359 km apart did not meet.)
void WarnOfDataRoundTheGlobe(vtkGeographicProjection* self,
  const tessera::ProjectionParameters& p,
  const tessera::GeographicExtent& extent)
{
  // (a transverse Mercator refuses what lies beyond 45 degrees of its meridian itself)
  if (p.Kind == tessera::ProjectionKind::AzimuthalEquidistant ||
    p.Kind == tessera::ProjectionKind::LambertAzimuthalEqualArea ||
    p.Kind == tessera::ProjectionKind::TransverseMercator ||
    p.Kind == tessera::ProjectionKind::UTM || !(extent.LongitudeSpan > WidestSpanWithoutWarning))
  {
    return;
  }
  const double cut = p.CentralLongitude + 180.0;
  const auto tenths = [](double degrees)
  { return tessera::NumberText(std::round(degrees * 10) / 10); };
  vtkWarningWithObjectMacro(self,
    << "the data span " << tenths(extent.LongitudeSpan) << " degrees of longitude: the "
    << tessera::ProjectionKindName(p.Kind) << " projection is cut at longitude "
    << tenths(cut > 360.0 ? cut - 360.0 : cut) << ", in their largest gap ("
    << tenths(360.0 - extent.LongitudeSpan)
    << " degrees), and places either side of it lie far apart in the plane, so their tiles do "
       "not meet; for data round a pole, LambertAzimuthalEqualArea with ParametersFromData off "
       "and CentralLatitude 90 or -90 keeps them together");
}

/// Warns where a UTM zone set (Projection UTM, UTMZone) has the other hemisphere's grid than every
/// point: UTMNorth off for points all north of the equator puts 10,000 km on every northing, on
/// for points all south makes them negative (a trial's northern data, UTMNorth left off, went
/// 10,000 km north without a word). A grid of the other hemisphere is valid (data across the
/// equator take one), so it is a warning.
void WarnOfOtherHemisphere(vtkGeographicProjection* self,
  const tessera::ProjectionParameters& p,
  const std::vector<tessera::Point2>& lonlat)
{
  if (p.Kind != tessera::ProjectionKind::UTM || self->GetUTMZone() == 0 || lonlat.empty())
  {
    return;
  }
  const auto north = [](const tessera::Point2& q) { return q.y > 0.0; };
  const auto south = [](const tessera::Point2& q) { return q.y < 0.0; };
  if (!p.UTMNorth && std::all_of(lonlat.begin(), lonlat.end(), north))
  {
    vtkWarningWithObjectMacro(self,
      << "UTMNorth is off (the southern grid, northings from 10,000 km at the equator), but "
         "every point lies north of the equator: their northings are 10,000 km more than the "
         "zone's northern grid gives them (turn UTMNorth on for that grid)");
  }
  else if (p.UTMNorth && std::all_of(lonlat.begin(), lonlat.end(), south))
  {
    vtkWarningWithObjectMacro(self,
      << "UTMNorth is on (the northern grid, northings from 0 at the equator), but every point "
         "lies south of the equator: their northings are negative, 10,000 km less than the "
         "zone's southern grid gives them (turn UTMNorth off for that grid)");
  }
}

/// The forward projection's parameters from the filter's settings and the data.
tessera::ProjectionParameters ChooseForwardParameters(vtkGeographicProjection* self,
  const std::vector<tessera::Point2>& lonlat)
{
  // Automatic is the Albers equal-area conic fitted to the data; with ParametersFromData off it
  // takes the parameters set, as AlbersEqualArea does (they were ignored).
  tessera::ProjectionParameters p;
  if (self->GetParametersFromData())
  {
    // (KindOf(AUTOMATIC) is Albers: tessera::AutomaticParameters)
    const tessera::GeographicExtent extent = tessera::ComputeExtent(lonlat);
    p = tessera::ParametersFromExtent(KindOf(self->GetProjection()), extent);
    WarnOfDataRoundTheGlobe(self, p, extent);
  }
  else
  {
    p.Kind = KindOf(self->GetProjection());
    // (a NaN centre was named as "longitude nan has no UTM zone", not as the setting; 1e20 was
    // taken, and every x came out 0)
    for (const auto& [name, value, limit] :
      { std::make_tuple("CentralLongitude", self->GetCentralLongitude(), 360.0),
        std::make_tuple("CentralLatitude", self->GetCentralLatitude(), 90.0) })
    {
      if (!(std::fabs(value) <= limit))
      {
        throw tessera::InputError(std::string(name) + " is " + tessera::NumberText(value) +
          ", not in [-" + tessera::NumberText(limit) + ", " + tessera::NumberText(limit) +
          "] (ParametersFromData is off, so the projection takes the parameters set)");
      }
    }
    p.CentralLongitude = self->GetCentralLongitude();
    p.CentralLatitude = self->GetCentralLatitude();
    p.StandardParallel1 = self->GetStandardParallels()[0];
    p.StandardParallel2 = self->GetStandardParallels()[1];
    p.UTMZone = tessera::UTMZoneOfLongitude(self->GetCentralLongitude());
    p.UTMNorth = self->GetCentralLatitude() >= 0.0;
  }
  TakeUTMZoneSet(self, p);
  WarnOfOtherHemisphere(self, p, lonlat);
  TakeGridTerms(self, p);
  return p;
}

/// Inverse with a record on the input: the record is how the points were projected, so it is
/// used. Settings that describe a projection of their own (a UTM zone, ParametersFromData off, a
/// kind other than the record's, a grid) and describe another one are named as unused: a scripter
/// who set a false easting on the inverse saw it have no effect, without a word. Settings that
/// only leave the choice to the data (the defaults) describe nothing, and are not named. This is
/// how the settings differ, for the warning ("" where they do not).
std::string SettingsUnlikeRecord(vtkGeographicProjection* self,
  const tessera::ProjectionParameters& carried)
{
  const bool zoneSet =
    self->GetProjection() == vtkGeographicProjection::UTM && self->GetUTMZone() != 0;
  // A kind chosen other than the record's (its parameters left to the data, which are projected).
  const bool otherKind = self->GetProjection() != vtkGeographicProjection::AUTOMATIC &&
    KindOf(self->GetProjection()) != carried.Kind;
  const bool gridSet = !WithGridSet(self, tessera::ProjectionParameters()).PlaneWithoutGrid();
  if (!zoneSet && !otherKind && self->GetParametersFromData() && !gridSet)
  {
    return std::string();
  }
  if (otherKind && !zoneSet && self->GetParametersFromData())
  {
    std::string grid;
    for (const auto& [name, value, unset] :
      { std::make_tuple("FalseEasting", self->GetFalseEasting(), 0.0),
        std::make_tuple("FalseNorthing", self->GetFalseNorthing(), 0.0),
        std::make_tuple("ScaleFactor", self->GetScaleFactor(), 1.0) })
    {
      grid += value != unset ? std::string(", ") + name + " " + tessera::NumberText(value) : "";
    }
    if (self->GetUseLatitudeOfOrigin())
    {
      grid += ", LatitudeOfOrigin " + tessera::NumberText(self->GetLatitudeOfOrigin());
    }
    return std::string("(Projection ") +
      tessera::ProjectionKindName(KindOf(self->GetProjection())) + ", fitted to the data" + grid +
      ") are not used";
  }
  tessera::ProjectionParameters own = carried; // (only a grid set: the record's with that grid)
  try
  {
    if (zoneSet)
    {
      own = *UTMZoneSetWithGrid(self);
    }
    else if (!self->GetParametersFromData())
    {
      own = ChooseForwardParameters(self, {});
    }
    else
    {
      TakeGridTerms(self, own);
    }
  }
  catch (const tessera::InputError& e)
  {
    return std::string("are not used, and are no projection: ") + e.what();
  }
  return tessera::SameProjection(own, carried)
    ? std::string()
    : "('" + own.ToString() + "') are not used (to project back with them instead, give that " +
      "record as ProjectionRecord)";
}

void WarnOfSettingsTheRecordOverrides(vtkGeographicProjection* self,
  const tessera::ProjectionParameters& carried)
{
  const std::string unlike = SettingsUnlikeRecord(self, carried);
  if (!unlike.empty())
  {
    vtkWarningWithObjectMacro(self,
      << "Inverse: the input carries the projection record '" << carried.ToString()
      << "', with which its points were projected, so it is used; this filter's settings "
      << unlike);
  }
}

/// A point set to project and its output; Label names a composite's block in messages ("" for
/// a lone data set).
struct Piece
{
  vtkPointSet* Input;
  vtkPointSet* Output;
  std::string Label;
};

/// The most points densifying may add over the whole input: MaximumEdgeLength given in metres
/// rather than degrees, or a slip of its exponent, cut a state outline of 78 edges into 70 million
/// points in 37 s, stalling ParaView; such a step is refused before any point is made.
constexpr double MaxAddedPoints = 1e7;

/// Refuses a step that would add more than MaxAddedPoints points over all the pieces' lines and
/// polygons, counted before any is made (each edge once, as EdgeDensifier cuts it). places: an
/// inverse's, the lon/lat of each piece's points (empty for a forward).
void CheckAddedPoints(const std::vector<Piece>& pieces,
  double step,
  const std::vector<std::vector<tessera::Point2>>& places)
{
  double added = 0.0;
  vtkNew<vtkIdList> ids;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    auto* poly = vtkPolyData::SafeDownCast(pieces[p].Input);
    std::set<std::pair<vtkIdType, vtkIdType>> edges;
    for (const auto& [cells, closed] : { std::make_pair(poly ? poly->GetLines() : nullptr, false),
           std::make_pair(poly ? poly->GetPolys() : nullptr, true) })
    {
      auto iter = vtk::TakeSmartPointer(cells ? cells->NewIterator() : nullptr);
      for (iter ? iter->GoToFirstCell() : void(); iter && !iter->IsDoneWithTraversal();
           iter->GoToNextCell())
      {
        iter->GetCurrentCell(ids);
        const vtkIdType n = ids->GetNumberOfIds();
        for (vtkIdType k = 0; k < (closed ? n : n - 1); ++k)
        {
          const vtkIdType a = ids->GetId(k), b = ids->GetId((k + 1) % n);
          if (!edges.insert(std::minmax(a, b)).second)
          {
            continue;
          }
          added += PiecesOfEdge(poly, a, b, places.empty() ? nullptr : &places[p], step) - 1;
        }
      }
    }
  }
  if (added > MaxAddedPoints)
  {
    throw tessera::InputError("MaximumEdgeLength " + tessera::NumberText(step) +
      " degrees would cut the edges into " + tessera::NumberText(added) +
      " new points, more than " + tessera::NumberText(MaxAddedPoints) +
      " (it is in degrees of longitude and latitude: the default, 0.1, is some 11 km)");
  }
}

/// Runs work; an InputError from it gets the piece's label in front.
template<typename Work>
void WithLabel(const Piece& piece, Work&& work)
{
  try
  {
    work();
  }
  catch (const tessera::InputError& e)
  {
    if (piece.Label.empty())
    {
      throw;
    }
    throw tessera::InputError(piece.Label + ": " + e.what());
  }
}

/// The pieces of the input: itself, or each non-empty leaf of a composite, whose structure the
/// output then copies with a new data set of the leaf's type in each place.
std::vector<Piece> PiecesOf(vtkDataObject* input, vtkDataObject* output)
{
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    auto* in = vtkPointSet::SafeDownCast(input);
    auto* out = vtkPointSet::SafeDownCast(output);
    if (!in || !out)
    {
      throw tessera::InputError(std::string("the input is a ") + input->GetClassName() +
        ", not a point set or a composite of point sets");
    }
    tessera_vtk::CheckArraysAndCellPointIds(in, "the input");
    return { Piece{ in, out, std::string() } };
  }
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(output);
  compositeOutput->CopyStructure(composite);
  std::vector<Piece> pieces;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  it->SkipEmptyNodesOn();
  const tessera_vtk::BlockLabels labels(composite);
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    const std::string label = labels.Of(it);
    vtkDataObject* leaf = it->GetCurrentDataObject();
    auto* in = vtkPointSet::SafeDownCast(leaf);
    if (!in)
    {
      throw tessera::InputError(label + " is a " + leaf->GetClassName() + ", not a point set");
    }
    tessera_vtk::CheckArraysAndCellPointIds(in, label);
    vtkSmartPointer<vtkPointSet> out;
    out.TakeReference(in->NewInstance());
    compositeOutput->SetDataSet(it, out);
    pieces.push_back(Piece{ in, out, label });
  }
  return pieces;
}

/// The points of all the pieces, each piece's validated as lon/lat (InputError with its label).
std::vector<tessera::Point2> ValidLonLatOf(const std::vector<Piece>& pieces)
{
  std::vector<tessera::Point2> lonlat;
  for (const Piece& piece : pieces)
  {
    std::vector<tessera::Point2> own = ReadXY(piece.Input->GetPoints());
    WithLabel(piece, [&own]() { tessera::ValidateLonLat(own); });
    if (lonlat.empty())
    {
      lonlat = std::move(own); // (a lone data set's points, not copied again)
    }
    else
    {
      lonlat.insert(lonlat.end(), own.begin(), own.end());
    }
  }
  return lonlat;
}

/// The projection for all pieces: the filter's ProjectionRecord when set; else the inverse's from
/// the input's record (the whole's, or the one its blocks share), else from the settings and all
/// the pieces' points together.
tessera::ProjectionParameters ChooseParameters(vtkGeographicProjection* self,
  vtkDataObject* input,
  const std::vector<Piece>& pieces)
{
  // A forward's points are validated whatever gives the projection (a longitude of 1000 was
  // wrapped to 280 without a word when a ProjectionRecord was set, and refused otherwise), and
  // fitted to below when nothing else gives it. An inverse fits nothing to its points.
  const std::vector<tessera::Point2> lonlat =
    self->GetInverse() ? std::vector<tessera::Point2>() : ValidLonLatOf(pieces);
  const std::string own = self->GetProjectionRecord();
  if (!own.empty())
  {
    tessera::ProjectionParameters parameters;
    try
    {
      parameters = tessera::ProjectionParameters::FromString(own);
    }
    catch (const tessera::InputError& e)
    {
      throw tessera::InputError(std::string("ProjectionRecord '") + own + "': " + e.what());
    }
    // An inverse whose input carries another record: the points were projected otherwise.
    const std::string carried =
      self->GetInverse() ? tessera_vtk::ProjectionRecordOf(input, "the input") : std::string();
    if (!carried.empty() && carried != parameters.ToString())
    {
      vtkWarningWithObjectMacro(self,
        << "ProjectionRecord '" << own << "' is used, but the input carries another record, '"
        << carried << "': its points were projected with that one, so they come back elsewhere");
    }
    return parameters;
  }
  if (self->GetInverse())
  {
    // The record of the whole, or else the one all its blocks carry.
    const std::string record = tessera_vtk::ProjectionRecordOf(input, "the input");
    if (!record.empty())
    {
      const tessera::ProjectionParameters carried =
        tessera::ProjectionParameters::FromString(record);
      WarnOfSettingsTheRecordOverrides(self, carried);
      return carried;
    }
    // (ParametersFromData, on by default, made a scripter turn it off to go back from UTM.)
    if (const auto utm = UTMZoneSetWithGrid(self))
    {
      return *utm;
    }
    if (self->GetParametersFromData())
    {
      throw tessera::InputError("Inverse needs the input's TesseraProjection field data, a UTM "
                                "zone (UTMZone 1 to 60), or ParametersFromData off and the "
                                "projection's parameters set");
    }
  }
  return ChooseForwardParameters(self, lonlat);
}

/// The places (lon/lat) of an inverse's input points, per piece, and the turn (0 or -360 or 360
/// degrees) added to every longitude of the output.
struct InversePlaces
{
  std::vector<std::vector<tessera::Point2>> Places;
  double Turn = 0.0;
  std::size_t Count = 0;        ///< input points
  bool AllInLonLatRange = true; ///< whether every input point lies within lon/lat ranges
};

/// The places of the points of each piece of an inverse's input; throws InputError naming a point
/// that has none. Computed once: the densifier counts an edge's pieces from its ends' places, and
/// they are the output's first points. The inverse gives longitudes within 180 degrees of the
/// meridian; east of one beyond 180 (lon0 = 300, set by hand) they go beyond 360, which every
/// reader of longitudes refuses (this filter's forward included): the whole output then moves a
/// turn west, so that it stays continuous (a point at a time, a polygon about 0 East came back
/// from 355 to 5, an edge round the globe).
InversePlaces PlacesOfInverse(const std::vector<Piece>& pieces,
  const tessera::GeographicProjection& projection)
{
  InversePlaces result;
  result.Places.resize(pieces.size());
  double west = HUGE_VAL, east = -HUGE_VAL;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    std::vector<tessera::Point2>& places = result.Places[p];
    WithLabel(pieces[p],
      [&]()
      {
        places = ReadXY(pieces[p].Input->GetPoints());
        result.Count += places.size();
        for (std::size_t i = 0; i < places.size(); ++i)
        {
          result.AllInLonLatRange = result.AllInLonLatRange && tessera::InLonLatRange(places[i]);
          places[i] = projection.Inverse(places[i], static_cast<long long>(i));
          west = std::min(west, places[i].x);
          east = std::max(east, places[i].x);
        }
      });
  }
  result.Turn = east > 360.0 ? -360.0 : west < -360.0 ? 360.0 : 0.0;
  for (std::vector<tessera::Point2>& places : result.Places)
  {
    for (tessera::Point2& place : places)
    {
      place.x += result.Turn;
    }
  }
  return result;
}

/// Warns where every point of an inverse's input lies within the ranges of longitude and latitude
/// (|x| <= 360, |y| <= 90): degrees, most likely, not metres of a plane (lon/lat given with
/// ParametersFromData off came back as places within metres of the projection's origin without a
/// word). A plane's own data so near its origin is rare.
void WarnOfDegreesGivenToTheInverse(vtkGeographicProjection* self, const InversePlaces& inverse)
{
  if (inverse.Count > 0 && inverse.AllInLonLatRange)
  {
    vtkWarningWithObjectMacro(self,
      << "Inverse: all " << inverse.Count
      << " input point(s) lie within longitude and latitude ranges (|x| <= 360, |y| <= 90): "
         "if they are degrees, turn Inverse off; the inverse takes metres of the projection's "
         "plane, and these come back within metres of its origin");
  }
}

/// The place of point i, cut on a plane edge by the inverse's densifying, a turn added: an error
/// names it as such (a chord across a conic's hole about its pole leaves the projection's domain,
/// and the error named a point the input does not have).
tessera::Point2 InverseOfCutPoint(const tessera::GeographicProjection& projection,
  const double p[3],
  vtkIdType i,
  double turn)
{
  try
  {
    tessera::Point2 place = projection.Inverse({ p[0], p[1] });
    place.x += turn;
    return place;
  }
  catch (const tessera::InputError& e)
  {
    throw tessera::InputError("point " + std::to_string(i) +
      " of the output, made where an edge was cut (MaximumEdgeLength), has no place: " + e.what() +
      "; MaximumEdgeLength 0 keeps the input's points only");
  }
}

/// Projects one piece into its output, with the record (none when empty), adding to report.
/// places: an inverse's, the lon/lat of the piece's points (PlacesOfInverse), else empty; turn:
/// the inverse's, added to the longitudes of the points cut on its edges.
void ProjectPiece(vtkGeographicProjection* self,
  const Piece& piece,
  const tessera::GeographicProjection* projection,
  const std::string& record,
  const std::vector<tessera::Point2>& places,
  double turn,
  DensifyReport& report)
{
  vtkPointSet* input = piece.Input;
  vtkPointSet* output = piece.Output;
  auto polyInput = vtkPolyData::SafeDownCast(input);
  if (polyInput && self->GetMaximumEdgeLength() > 0.0)
  {
    EdgeDensifier densifier(polyInput,
      vtkPolyData::SafeDownCast(output),
      self->GetMaximumEdgeLength(),
      piece.Label,
      report,
      self->GetInverse() ? &places : nullptr);
    densifier.Run();
    output->GetFieldData()->PassData(input->GetFieldData());
  }
  else
  {
    output->CopyStructure(input);
    output->GetPointData()->PassData(input->GetPointData());
    output->GetCellData()->PassData(input->GetCellData());
    output->GetFieldData()->PassData(input->GetFieldData());
  }

  vtkPoints* source = output->GetPoints();
  vtkNew<vtkPoints> projected;
  projected->SetDataTypeToDouble();
  const vtkIdType n = source ? source->GetNumberOfPoints() : 0;
  projected->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    source->GetPoint(i, p);
    const tessera::Point2 q = !self->GetInverse()   ? projection->Forward({ p[0], p[1] }, i)
      : static_cast<std::size_t>(i) < places.size() ? places[i]
                                                    : InverseOfCutPoint(*projection, p, i, turn);
    projected->SetPoint(i, q.x, q.y, p[2]);
  }
  output->SetPoints(projected);
  output->GetFieldData()->RemoveArray(ProjectionRecordName);
  if (!record.empty())
  {
    tessera_vtk::WriteProjectionRecord(output, record);
  }
}

/// The output of a process that does not make it: a composite keeps the input's structure.
void KeepBlockPlaces(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Another process's piece: the first makes the whole output (RequestWholeInputs). Blocks keep
  // their places on every process (ParaView picks and colours blocks by composite index).
  auto* compositeIn = vtkCompositeDataSet::GetData(inputVector[0]);
  auto* compositeOut = vtkCompositeDataSet::GetData(outputVector);
  if (compositeIn && compositeOut)
  {
    compositeOut->CopyStructure(compositeIn);
  }
}

/// Refuses a Projection that is none of the choices, a UTM zone out of range and a
/// MaximumEdgeLength that is not a length.
void CheckSettings(int projection, int utmZone, double maximumEdgeLength)
{
  tessera_vtk::CheckChoice("Projection", projection, ProjectionChoices());
  // (the zone is a UTM setting: a value left from a UTM choice does not stop another projection)
  if (projection == vtkGeographicProjection::UTM && (utmZone < 0 || utmZone > 60))
  {
    throw tessera::InputError("UTMZone " + std::to_string(utmZone) +
      " is neither a zone from 1 to 60 nor 0 (the zone of the data's central longitude)");
  }
  if (!(maximumEdgeLength >= 0.0))
  {
    // (every comparison with NaN is false: it turned the densification off without a word, as
    // a negative length did)
    throw tessera::InputError("MaximumEdgeLength " + tessera::NumberText(maximumEdgeLength) +
      " is not a length of 0 or more degrees (0 turns the densification off)");
  }
}

/// The points of all the pieces.
std::size_t PointCountOf(const std::vector<Piece>& pieces)
{
  std::size_t points = 0;
  for (const Piece& piece : pieces)
  {
    points += static_cast<std::size_t>(piece.Input->GetNumberOfPoints());
  }
  return points;
}

/// The warning for an input without points, saying what is not made.
void WarnOfNoPoints(vtkGeographicProjection* self, bool inverse, bool fitted)
{
  const char* const what = inverse ? "point taken back to lon/lat"
    : fitted ? "point projected, and no projection fitted, so no TesseraProjection record"
             : "point projected";
  vtkWarningWithObjectMacro(self, << tessera_vtk::NoPointsWarning(what));
}

/// The projection an update applies (none for an input with nothing to project), and the record
/// its forward output carries ("" for none and for the inverse).
struct ChosenProjection
{
  std::unique_ptr<tessera::GeographicProjection> Projection;
  std::string Record;
};

/// The projection of the pieces (ChooseParameters), or none; none for a forward still checks the
/// grid set on the filter for its Projection (projectionSetting).
ChosenProjection ChooseProjection(vtkGeographicProjection* self,
  vtkDataObject* input,
  const std::vector<Piece>& pieces,
  bool none,
  bool inverse,
  int projectionSetting)
{
  ChosenProjection chosen;
  if (none && !inverse)
  {
    // No projection is fitted, but a grid set out of range is still named (a ScaleFactor of
    // 100 passed unseen on an empty input, and failed only when points came).
    tessera::ProjectionParameters grid;
    grid.Kind = KindOf(projectionSetting);
    TakeGridTerms(self, grid);
    tessera::CheckGridTerms(grid);
  }
  else if (!none)
  {
    const tessera::ProjectionParameters parameters = ChooseParameters(self, input, pieces);
    chosen.Projection.reset(new tessera::GeographicProjection(parameters));
    chosen.Record = inverse ? std::string() : parameters.ToString();
  }
  return chosen;
}

/// Projects every piece into its output (progress 0.1 to 1), its errors labelled with the
/// piece's block; what densifying met.
DensifyReport ProjectPieces(vtkGeographicProjection* self,
  const std::vector<Piece>& pieces,
  const ChosenProjection& chosen,
  const InversePlaces& inverse)
{
  const std::vector<std::vector<tessera::Point2>>& places = inverse.Places;
  DensifyReport report;
  const std::vector<tessera::Point2> noPlaces; // (a forward's)
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    // (a progress observer's stop is taken between pieces: it was not taken at all)
    tessera_vtk::ProgressOrStop(
      self, 0.1 + 0.9 * static_cast<double>(p) / static_cast<double>(pieces.size()));
    WithLabel(pieces[p],
      [&]()
      {
        ProjectPiece(self,
          pieces[p],
          chosen.Projection.get(),
          chosen.Record,
          places.empty() ? noPlaces : places[p],
          inverse.Turn,
          report);
      });
  }
  return report;
}

/// The warnings for edges cut into the most pieces allowed, for global ids dropped by cutting,
/// and for edges taken the shorter way round the globe.
void WarnOfDensifying(vtkGeographicProjection* self,
  const DensifyReport& report,
  double maximumEdgeLength)
{
  if (report.Capped > 0)
  {
    vtkWarningWithObjectMacro(self,
      << report.Capped << " edge(s) were cut into " << tessera::MaxDensifiedPieces
      << " pieces, the most allowed: their pieces are longer than "
         "MaximumEdgeLength "
      << tessera::NumberText(maximumEdgeLength) << " degrees");
  }
  if (report.GlobalIdsDropped > 0)
  {
    vtkWarningWithObjectMacro(self,
      << "the global ids of " << report.GlobalIdsDropped
      << " piece(s) (the first: " << report.FirstGlobalIds
      << ") were not carried: edges longer than MaximumEdgeLength were cut, and "
         "the new points have no id (MaximumEdgeLength 0 keeps the points as "
         "they are)");
  }
  if (report.Wrapped > 0)
  {
    vtkWarningWithObjectMacro(self,
      << report.Wrapped << " edge(s) span 180 to 270 degrees of longitude as written (the first: "
      << report.FirstWrapped
      << "): each was taken the shorter way round the globe, not straight in "
         "lon/lat; add a vertex in between where an edge should run straight");
  }
}

/// A composite output's own field data: the input's, with the record (none when empty) in place
/// of any it had.
void PassCompositeFieldData(vtkDataObject* input, vtkDataObject* output, const std::string& record)
{
  // A composite: its own field data too.
  output->GetFieldData()->PassData(input->GetFieldData());
  output->GetFieldData()->RemoveArray(ProjectionRecordName);
  if (!record.empty())
  {
    tessera_vtk::WriteProjectionRecord(output, record);
  }
}

} // namespace

//------------------------------------------------------------------------------
vtkGeographicProjection::vtkGeographicProjection() = default;

//------------------------------------------------------------------------------
int vtkGeographicProjection::FillInputPortInformation(int, vtkInformation* info)
{
  // A composite (e.g. vtkGDALVectorReader's layers) is taken whole, so that all its blocks share
  // one projection: block by block, each would get its own automatic one. Any type is taken:
  // RequestData names one that is neither a point set nor a composite, and empties the output
  // (the pipeline's own check stopped before it and left the last result in place).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  return 1;
}

int vtkGeographicProjection::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

//------------------------------------------------------------------------------
int vtkGeographicProjection::RequestDataObject(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  auto* composite = vtkCompositeDataSet::GetData(inputVector[0], 0);
  if (!composite && vtkPointSet::GetData(inputVector[0], 0))
  {
    return this->Superclass::RequestDataObject(request, inputVector, outputVector);
  }
  // A composite's kind, or for neither points nor a composite a vtkPolyData, which RequestData
  // leaves empty with an error naming the input's type.
  tessera_vtk::MakeCompositeOrPolyDataOutput(composite, outputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkGeographicProjection::ComputeInputUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Every point at once: the fitted projection is the same for all of them only if it is fitted
  // to all of them (RequestWholeInputs; ParaView under MPI asks each process for a piece).
  tessera_vtk::RequestWholeInputs(inputVector, 0, 0);
  return 1;
}

//------------------------------------------------------------------------------
int vtkGeographicProjection::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (!tessera_vtk::MakesOutput(outputVector))
  {
    KeepBlockPlaces(inputVector, outputVector);
    return 1;
  }
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0]);
  vtkDataObject* output = vtkDataObject::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("vtkGeographicProjection needs a vtkPointSet or composite input.");
    return 0;
  }
  try
  {
    CheckSettings(this->Projection, this->UTMZone, this->MaximumEdgeLength);
    std::vector<Piece> pieces = PiecesOf(input, output);
    const std::size_t points = PointCountOf(pieces);
    // Nothing to fit a projection to, or to undo: empty in, empty out (with the structure), no
    // record (an empty forward output has none, so its inverse takes it as it is).
    // A ProjectionRecord set is the projection even then (read, so that a bad one is an error,
    // and written on the forward output, as for points).
    const bool fitted = this->ParametersFromData && this->ProjectionRecord.empty();
    const bool none = points == 0 && ((this->Inverse && this->ProjectionRecord.empty()) || fitted);
    if (points == 0)
    {
      WarnOfNoPoints(this, this->Inverse, fitted);
    }
    const ChosenProjection chosen =
      ChooseProjection(this, input, pieces, none, this->Inverse, this->Projection);
    const InversePlaces inverse = this->Inverse && chosen.Projection
      ? PlacesOfInverse(pieces, *chosen.Projection)
      : InversePlaces();
    WarnOfDegreesGivenToTheInverse(this, inverse);
    if (this->MaximumEdgeLength > 0.0)
    {
      CheckAddedPoints(pieces, this->MaximumEdgeLength, inverse.Places);
    }
    const DensifyReport report = ProjectPieces(this, pieces, chosen, inverse);
    WarnOfDensifying(this, report, this->MaximumEdgeLength);
    if (vtkCompositeDataSet::SafeDownCast(output))
    {
      PassCompositeFieldData(input, output, chosen.Record);
    }
    tessera_vtk::ListNonEmptyFieldArraysFirst(output);
    return 1;
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    return tesseraErrorOrStopMacro(e);
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
  os << indent << "FalseEasting: " << this->FalseEasting << "\n";
  os << indent << "FalseNorthing: " << this->FalseNorthing << "\n";
  os << indent << "ScaleFactor: " << this->ScaleFactor << "\n";
  os << indent << "LatitudeOfOrigin: " << this->LatitudeOfOrigin << "\n";
  os << indent << "UseLatitudeOfOrigin: " << this->UseLatitudeOfOrigin << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "Inverse: " << this->Inverse << "\n";
  os << indent << "ProjectionRecord: " << this->ProjectionRecord << "\n";
}
