/**
 * @class   vtkGeographicProjection
 * @brief   project longitude/latitude points, lines and polygons to a plane (and back)
 *
 * vtkGeographicProjection maps the x, y coordinates of any vtkPointSet, read as longitude and
 * latitude in degrees on the WGS84 ellipsoid, to projected x, y in metres with GeographicLib
 * (z is kept). Thiessen polygons and Dirichlet tiles are only meaningful in a plane, so gauges
 * given in lon/lat pass through this filter first. A composite data set of point sets (such as
 * vtkGDALVectorReader's layers) gives a composite of the same structure, all its blocks projected
 * with one projection fitted to them all (its errors name the block). An input without points
 * gives an empty output, without a record when the projection would be fitted to the data (a
 * grid set out of range is an error then too).
 *
 * Projections (SetProjectionTo...):
 * - Automatic (default): an Albers equal-area conic whose standard parallels sit at 1/6 and 5/6
 *   of the data's latitude span and whose central meridian is the middle of the data's longitude
 *   extent. Equal-area, so tile areas in the plane are areas on the ellipsoid.
 * - AlbersEqualArea, LambertConformalConic: conics with two standard parallels.
 * - TransverseMercator (scale 1 on the central meridian) and UTM (zone from SetUTMZone, 0 = the
 *   zone of the central longitude: the data's, or CentralLongitude with ParametersFromData off,
 *   the hemisphere then CentralLatitude's; false easting 500 km, false northing 10000 km south).
 * - AzimuthalEquidistant about (CentralLongitude, CentralLatitude).
 * - LambertAzimuthalEqualArea about (CentralLongitude, CentralLatitude), on the ellipsoid (EPSG
 *   method 9820, as EPSG:3035, LAEA Europe, whose false easting and northing are set below).
 *   Equal-area, as Albers is.
 * - Mercator about CentralLongitude, on the ellipsoid, scale 1 on the equator (EPSG:3395, World
 *   Mercator, about 0), and WebMercator: WGS84 latitudes by the sphere's formulas (EPSG:3857,
 *   the web maps' Pseudo-Mercator, about 0). Neither reaches the poles (beyond 1e8 m: about
 *   89.99999 degrees). With ParametersFromData on (default), they are about the data's middle
 *   meridian: EPSG:3395 and EPSG:3857 themselves need it off, with CentralLongitude 0.
 * With ParametersFromData on (default) the centre and standard parallels come from the data as
 * for Automatic; off, the values set with SetCentralLongitude, SetCentralLatitude and
 * SetStandardParallels are used, by Automatic too (it is then the Albers equal-area conic with
 * them). A projected coordinate system's grid (false easting and northing, scale factor, latitude
 * of origin) is laid on any of these planes with SetFalseEasting and the others below.
 *
 * Longitudes are angles: the data's extent is the shortest longitude arc that holds it, so a set
 * crossing the antimeridian (e.g. 165..181.6) is handled, and the inverse returns longitudes
 * within 180 degrees of the central meridian (continuous across the antimeridian), never beyond
 * 360: with a meridian set beyond 180 by hand, where any place would come back beyond 360, the
 * whole output takes a turn west, so that it stays continuous (central meridian 300: 350, 250 and
 * 20 come back as -10, -110 and 20, within 180 of -60). One place
 * written two ways (181.5 and -178.5, 180 and -180) projects to one point, bit for bit. Data that
 * span more than 270 degrees of longitude get a warning under a projection cut at a meridian (all
 * but the azimuthal ones): places either side of the cut lie far apart in the plane; data round a
 * pole want LambertAzimuthalEqualArea about it. A longitude beyond 360 or a latitude beyond 90 is
 * an error naming the point, whatever gives the projection.
 *
 * For vtkPolyData input, line and polygon edges are straight in lon/lat (RFC 7946): before
 * projecting, every edge longer than MaximumEdgeLength degrees is cut into equal pieces (point
 * data interpolated linearly; an edge shared by two cells is cut once), so a boundary along a
 * parallel stays on it. MaximumEdgeLength 0 turns this off (a negative or NaN one is an
 * error). An edge whose
 * longitudes differ by more than 180 degrees as written is cut the shorter way round, across the
 * 180th meridian (179 to -179) or, in 0 .. 360 data, the prime meridian; where they differ by 180
 * to 270 degrees it could be meant either way, and a warning counts such edges and names the first
 * (add a vertex in between for the straight reading). The inverse's edges are straight in the
 * plane: each is cut there into equal pieces, so that none spans more than about
 * MaximumEdgeLength degrees between the places of its ends, and the lon/lat output, read with
 * edges straight in lon/lat, keeps the plane's shapes and areas (an uncut 600 km square of an
 * Albers plane came back 5e-4 off in area, cut at 0.1 degree 4e-7). Other point sets are
 * projected point by point.
 *
 * ProjectionRecord, when set, is the projection, forward or inverse: the record another data set's
 * projection wrote, so that both are projected alike (as vtkWindowClip requires).
 *
 * Field data written (array names are API):
 * - `TesseraProjection` (vtkStringArray, one value): the projection and its parameters as
 *   "projection=AlbersEqualArea lon0=... lat0=... lat1=... lat2=... zone=... north=..." and the
 *   grid's terms that are set (" x0=... y0=... k0=... origin_lat=..."), exact to the last bit. With
 * Inverse on, the filter reads it from its input (so nobody retypes parameters) and removes it from
 * the output. vtkWindowClip compares its two inputs' records: tiles and window projected
 * differently (e.g. each with its own automatic projection) are an error. On a composite the record
 * is written on the whole and each block.
 *
 * Bad input (NaN/Inf, |latitude| > 90, a point the projection cannot represent such as a UTM
 * point beyond 500 km from the zone's meridian, a transverse Mercator point beyond 45 degrees
 * from the central meridian or a coordinate beyond 1e8 m, i.e. at a singularity) gives an error
 * naming the point id and value, and an empty output.
 */

#ifndef vtkGeographicProjection_h
#define vtkGeographicProjection_h

#include "tesseraFiltersModule.h" // For export macro
#include "vtkPointSetAlgorithm.h"

#include <string> // For the record

class TESSERAFILTERS_EXPORT vtkGeographicProjection : public vtkPointSetAlgorithm
{
public:
  static vtkGeographicProjection* New();
  vtkTypeMacro(vtkGeographicProjection, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ProjectionTypes
  {
    AUTOMATIC = 0,
    ALBERS_EQUAL_AREA = 1,
    LAMBERT_CONFORMAL_CONIC = 2,
    TRANSVERSE_MERCATOR = 3,
    UTM = 4,
    AZIMUTHAL_EQUIDISTANT = 5,
    LAMBERT_AZIMUTHAL_EQUAL_AREA = 6,
    MERCATOR = 7,
    WEB_MERCATOR = 8
  };

  ///@{
  /**
   * The projection (default AUTOMATIC: Albers equal-area from the data's extent). Another value
   * is an error at the update.
   */
  vtkSetMacro(Projection, int);
  // The range VTK's clamping setter announced (kept: a value outside is an error at the update).
  virtual int GetProjectionMinValue() { return AUTOMATIC; }
  virtual int GetProjectionMaxValue() { return WEB_MERCATOR; }
  vtkGetMacro(Projection, int);
  void SetProjectionToAutomatic() { this->SetProjection(AUTOMATIC); }
  void SetProjectionToAlbersEqualArea() { this->SetProjection(ALBERS_EQUAL_AREA); }
  void SetProjectionToLambertConformalConic() { this->SetProjection(LAMBERT_CONFORMAL_CONIC); }
  void SetProjectionToTransverseMercator() { this->SetProjection(TRANSVERSE_MERCATOR); }
  void SetProjectionToUTM() { this->SetProjection(UTM); }
  void SetProjectionToAzimuthalEquidistant() { this->SetProjection(AZIMUTHAL_EQUIDISTANT); }
  void SetProjectionToLambertAzimuthalEqualArea()
  {
    this->SetProjection(LAMBERT_AZIMUTHAL_EQUAL_AREA);
  }
  void SetProjectionToMercator() { this->SetProjection(MERCATOR); }
  void SetProjectionToWebMercator() { this->SetProjection(WEB_MERCATOR); }
  ///@}

  ///@{
  /**
   * UTM zone 1..60; 0 (default) takes the zone of the data's central longitude. With the UTM
   * projection another value is an error at the update; the other projections do not read it.
   */
  vtkSetMacro(UTMZone, int);
  // The range VTK's clamping setter announced (kept: a value outside is an error at the update).
  virtual int GetUTMZoneMinValue() { return 0; }
  virtual int GetUTMZoneMaxValue() { return 60; }
  vtkGetMacro(UTMZone, int);
  ///@}

  ///@{
  /**
   * UTM hemisphere when the zone is set by hand (default on: north). With UTMZone 0 the
   * hemisphere of the data's centre is used. A grid of the other hemisphere than every point
   * (off for points all north of the equator, on for points all south) is warned of: their
   * northings are 10,000 km off the zone's grid for their hemisphere.
   */
  vtkSetMacro(UTMNorth, bool);
  vtkGetMacro(UTMNorth, bool);
  vtkBooleanMacro(UTMNorth, bool);
  ///@}

  ///@{
  /**
   * On (default): centre and standard parallels come from the data's extent. Off: the values
   * below are used.
   */
  vtkSetMacro(ParametersFromData, bool);
  vtkGetMacro(ParametersFromData, bool);
  vtkBooleanMacro(ParametersFromData, bool);
  ///@}

  ///@{
  /**
   * Central meridian and centre latitude in degrees (used when ParametersFromData is off).
   */
  vtkSetMacro(CentralLongitude, double);
  vtkGetMacro(CentralLongitude, double);
  vtkSetMacro(CentralLatitude, double);
  vtkGetMacro(CentralLatitude, double);
  ///@}

  ///@{
  /**
   * The conics' standard parallels in degrees (used when ParametersFromData is off).
   */
  vtkSetVector2Macro(StandardParallels, double);
  vtkGetVector2Macro(StandardParallels, double);
  ///@}

  ///@{
  /**
   * The grid a projected coordinate system lays on the plane, as PROJ's +x_0, +y_0, +k_0 and
   * +lat_0 (EPSG's false easting and northing, scale factor and latitude of natural origin), so
   * that coordinates come out, and go back in, in that system's own numbers: x = ScaleFactor *
   * (plane x - x_O) + FalseEasting, and alike for y, where (x_O, y_O) is the plane's image of
   * (central longitude, LatitudeOfOrigin) with UseLatitudeOfOrigin on, else (0, 0), the plane's
   * own origin (the conics': a latitude between the standard parallels). For EPSG:5070 (USGS
   * Albers): AlbersEqualArea, CentralLongitude -96, StandardParallels 29.5, 45.5,
   * UseLatitudeOfOrigin on with LatitudeOfOrigin 23; for EPSG:3035 (LAEA Europe):
   * LambertAzimuthalEqualArea about 10 E 52 N with FalseEasting 4321000, FalseNorthing 3210000.
   * FalseEasting and FalseNorthing in metres (default 0, within 1e8), ScaleFactor 0.1 to 10
   * (default 1; real systems' are within a few parts in a thousand of 1), LatitudeOfOrigin in
   * degrees (default 0, read only with UseLatitudeOfOrigin on, default off: a LatitudeOfOrigin
   * other than 0 set then is warned of, unused). A latitude of origin is taken by the conics, the
   * transverse Mercator and the Mercators (PROJ's merc ignores +lat_0: leave it off for a PROJ
   * Mercator; at the update, another projection with
   * UseLatitudeOfOrigin on is an error: UTM's grid is fixed, the azimuthal projections' origin is
   * their centre); the grid applies on top of UTM's own. They are used with ParametersFromData on
   * or off, and written into the record (keys x0, y0, k0, origin_lat); with Inverse on and a record
   * on the input, the record's are used. Files in feet are scaled to metres first (ParaView's
   * Transform), as PROJ's +x_0 is in metres.
   */
  vtkSetMacro(FalseEasting, double);
  vtkGetMacro(FalseEasting, double);
  vtkSetMacro(FalseNorthing, double);
  vtkGetMacro(FalseNorthing, double);
  vtkSetMacro(ScaleFactor, double);
  vtkGetMacro(ScaleFactor, double);
  vtkSetMacro(LatitudeOfOrigin, double);
  vtkGetMacro(LatitudeOfOrigin, double);
  vtkSetMacro(UseLatitudeOfOrigin, bool);
  vtkGetMacro(UseLatitudeOfOrigin, bool);
  vtkBooleanMacro(UseLatitudeOfOrigin, bool);
  ///@}

  ///@{
  /**
   * Longest edge, in degrees of the lon/lat plane, left uncut before projecting (default 0.1);
   * inverse, about the longest that a plane edge's pieces span in lon/lat after it (equal pieces
   * in the plane, as many as the ends' places are MaximumEdgeLength apart: where the image bends
   * strongly they span more, 1.6 times on an edge across 240 degrees of a cone).
   * 0: no densification (a negative or NaN length is an error). An edge is cut into at most
   * 10^6 pieces (a warning counts those), and a step that would add more than 10^7 points in all
   * is an error (a step given in metres, say), before any point is made.
   */
  vtkSetMacro(MaximumEdgeLength, double);
  vtkGetMacro(MaximumEdgeLength, double);
  ///@}

  ///@{
  /**
   * Off (default): lon/lat to x/y. On: x/y back to lon/lat, with the parameters read from the
   * input's `TesseraProjection` field data when present, else from this filter's settings: a
   * UTM zone (UTMZone 1 to 60 with UTMNorth: the whole of a UTM projection), or the parameters
   * set with ParametersFromData off, with the grid set above (FalseEasting, FalseNorthing,
   * ScaleFactor, LatitudeOfOrigin): a file's x, y in EPSG:3035 or EPSG:5070 go back as they
   * are, with those set. A file in feet is scaled to metres first (ParaView's Transform). With a
   * record on the input, settings that describe another projection (a UTM zone, a Projection
   * other than the record's, ParametersFromData off, a grid) are not used, and a warning names
   * them beside the record. An input whose points all lie within longitude and latitude ranges
   * (|x| <= 360, |y| <= 90) gets a warning: degrees, most likely, where metres are taken.
   */
  vtkSetMacro(Inverse, bool);
  vtkGetMacro(Inverse, bool);
  vtkBooleanMacro(Inverse, bool);
  ///@}

  ///@{
  /**
   * A `TesseraProjection` record ("projection=... lon0=... ...", as this filter writes it) to
   * project with, forward or inverse; empty (default): Projection and the parameters above (and,
   * inverse, the input's record). Set, it overrides them all: a second data set projected with the
   * first's record gets the very same projection, as vtkWindowClip requires of its two inputs
   * (two automatic projections are fitted each to its own data). A record that cannot be read is
   * an error naming it, at the update, even for an input without points (whose forward output then
   * carries the record). Inverse with an input that carries another record warns, naming both.
   */
  vtkSetStdStringFromCharMacro(ProjectionRecord);
  vtkGetCharFromStdStringMacro(ProjectionRecord);
  ///@}

protected:
  vtkGeographicProjection();
  ~vtkGeographicProjection() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int ComputeInputUpdateExtent(vtkInformation*,
    vtkInformationVector**,
    vtkInformationVector*) override;

  int Projection = AUTOMATIC;
  int UTMZone = 0;
  bool UTMNorth = true;
  bool ParametersFromData = true;
  double CentralLongitude = 0.0;
  double CentralLatitude = 0.0;
  double StandardParallels[2] = { 30.0, 60.0 };
  double FalseEasting = 0.0;
  double FalseNorthing = 0.0;
  double ScaleFactor = 1.0;
  double LatitudeOfOrigin = 0.0;
  bool UseLatitudeOfOrigin = false;
  double MaximumEdgeLength = 0.1;
  bool Inverse = false;
  std::string ProjectionRecord;

private:
  friend class vtkGeographicProjectionInternals;
  // The LatitudeOfOrigin last warned of as unused (UseLatitudeOfOrigin off), 0 for none: the
  // warning comes once per value, not at every update (in ParaView the value is hidden with the
  // box off, and a user who unticked the box could not stop it).
  double UnusedLatitudeWarnedOf = 0.0;

  vtkGeographicProjection(const vtkGeographicProjection&) = delete;
  void operator=(const vtkGeographicProjection&) = delete;
};

#endif
