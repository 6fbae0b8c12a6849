/**
 * @class   vtkThiessenArealAverage
 * @brief   Thiessen weights and areal means of gauge time series over a catchment
 *
 * vtkThiessenArealAverage is the hydrologist's Thiessen (1911) method: for each time step, the
 * gauges that reported are tessellated (Green-Sibson, exact), their tiles are clipped to the
 * catchment, and each gauge is weighted by the ellipsoidal area of its tile inside the catchment
 * over the catchment's ellipsoidal area. The tessellation is built in a window holding every gauge
 * and the catchment, so a gauge outside the catchment still owns the part of it nearest to it. A
 * gauge without a value at a step is removed for that step and its neighbours take its area;
 * consecutive steps update the tessellation instead of rebuilding it.
 *
 * Inputs:
 * - port 0, gauges: a vtkPointSet with x = longitude, y = latitude (degrees, WGS84) and a
 *   point-data array of station ids (StationIdArrayName, default "station_id"), or a composite
 *   data set of point sets, whose points are joined in block order (gauge g is the g-th of them):
 *   a point GeoJSON or shapefile read by vtkGDALVectorReader (a block per gauge, its attributes
 *   as the cell data of its vertex, which is then taken as the point's);
 * - port 1, catchment: polygons or closed polylines in lon/lat (vtkPolyData, or a composite data
 * set such as vtkGDALVectorReader's output), or lines that join end to end into closed rings,
 * taken as rings under the even-odd rule (other cells, such as lines in no closed ring, are
 * ignored with a warning that counts them and names the first; an island that fills a hole
 * exactly, as an enclave given as a basin's hole and as a feature of its own, cancels it by that
 * rule, and both are left out with a warning naming them; an outer ring given twice, a feature
 * repeated, is an error naming both copies: cancelled, it would take its region away); edges are
 * straight in lon/lat,
 * but one whose longitudes differ by more than 270 degrees as written is taken the shorter way
 * round (179 to -179 crosses the 180th meridian) and one that differs by 180 to 270 degrees,
 * which could be meant either way, is an error naming its ring and segment; a ring that goes
 * round a pole (its longitudes, so read, turn through 360 degrees) and rings that cancel out
 * into no area (a basin given with all its sub-basins, each then a hole) are errors too;
 * - port 2 (optional), observations: a vtkTable in long format with a station id column, a time
 *   column and a value column (StationColumn, TimeColumn, ValueColumn: defaults "station_id",
 *   "time", "value"). Without it, the gauges' point-data array ValueArrayName is one time step, at
 *   the gauges' own time: their time steps (a time-aware source, a file series) are then the
 *   filter's, and a requested time goes up to them. Times are numbers, or text holding ISO dates
 *   (YYYY, YYYY-MM, YYYY-MM-DD, optionally with a time of day, and with a time zone such as Z or
 *   +01:00 where every date has the same offset: times are read as written, in that zone) or
 *   numbers, or a whole year column with a month column (MonthColumn); dates become decimal years
 *   on a month grid: 1963-08 (or 1963-08-01, or year 1963 with month 8) is 1963 + 7/12, and a day
 *   is its share of its month (core/decimal_time.h). A month or a year among finer dates (a
 *   monthly total among daily values) thus shares the step of its first day, with a warning
 *   naming the first date of each period; a date among times of day (a daily total among hourly
 *   values) shares the step of its 00:00 without one, as midnight is often written as the date
 *   alone. Values are numbers, NaN where missing; a text
 *   value column (what a CSV reader gives when markers stand among the numbers) also takes an
 *   empty field, NA, N/A, NaN or null as missing. A CSV file read by ParaView or
 *   vtkDelimitedTextReader can thus be used as it is, with one caution: those readers turn an
 *   empty field of an otherwise numeric column into 0 (a reported zero), so write missing values
 *   as NaN or NA, or turn the reader's DetectNumericColumns off (the columns stay text, which this
 *   filter reads itself: an empty value is then missing). A text value with a decimal comma (12,5)
 *   is an error that says so: only decimal points are read.
 *   A row is used only when its station is one of the gauges' and it has a time (or year and
 *   month): a row with an empty or blank station id (or a NaN one), an empty time or month field
 *   (blank text, or NaN), or a station id that no gauge has is not used and makes no time step
 *   (a blank last line ",," read into numeric columns becomes station 0 at time 0: not used unless
 *   a gauge has id 0; but an empty time field in a numeric time column is read as time 0, which
 *   is a time like any other, so such a row of a known station makes a step at 0: leave no time
 *   empty, or give dates as text). The time steps are the distinct times of the used rows. A used
 * row's time that is not a finite number, a date or a month 1 .. 12, and a value that is not a
 * number or a missing-value marker, are errors naming the row; a table none of whose rows can be
 * used is an error that counts them. Station ids match as text (leading zeros of integer ids are
 * ignored, so "050109" matches 50109, as does "50109.0"; a floating-point id column, as a CSV
 * reader makes, is read in full, so 6730200 and 6730500 stay two stations; 8-bit integers, as
 * numpy's int8 makes them, are numbers, not characters; matching and steps:
 * core/observation_series.h). Station id and value arrays, and the table's columns, hold one
 * component (another count is an error naming the array).
 *
 * The projection is vtkGeographicProjection's automatic equal-area conic fitted to the catchment
 * (where the tiles are measured, so gauges far from it, such as one that never reports or has a
 * mistyped coordinate, do not change the weights), unless ProjectionRecord holds a
 * `TesseraProjection` record (e.g. "projection=UTM zone=13 north=1"). With an equal-area
 * projection, planar areas are the ellipsoidal areas; otherwise rings are unprojected, densified,
 * and measured with GeographicLib::PolygonArea (AreaMethod selects explicitly). The tiles
 * themselves are Thiessen polygons in the projected plane, not on the ellipsoid: over Colorado
 * the areal means agree with a raster of the geodesically nearest gauge to better than 0.1% (the
 * tests check it), while over a box of 25 by 18 degrees at 50-68 N single weights were found up
 * to 3% (relative) from the geodesic ones, the areal mean 0.08%.
 *
 * Output 0 (vtkPolyData, time-dependent): the tiles of the requested time step clipped to the
 * catchment, in lon/lat. Every cell is a simple polygon (no hole, not touching itself) and cells
 * do not overlap, so ParaView fills exactly the catchment: each tile's part of the catchment is
 * cut by vertical lines (in the projected plane) into x-monotone pieces, a cell each, each a fan
 * about its first point, as ParaView draws a polygon (core/display_pieces.h; in lon/lat each
 * starts at a point that sees all of it, and a piece whose edges bent so that none does, as a
 * thin strip along a parallel, is split along diagonals between its own points into fans,
 * core/fan_diagonals.h, as far as a diagonal is found: a strip in Colorado's tiles of 1895-01 had
 * been measured 24% too large by ParaView's Cell Size). Most tiles, concave ones
 * included, are one piece; a part with a hole (a lake in the tile: three pieces around it), under
 * a wavy shore (a piece a wave or so) or made of lobes that meet only along the tile's edge (a
 * tile across a bay) gives several, so a gauge can have several cells. Neighbouring cells
 * share their borders vertex for vertex, the points that cut the borders into steps of 2 km
 * included (core/shared_borders.h), so that in lon/lat too they meet without gaps or overlaps
 * (to rounding) for a GIS's topology check or union. Cell data:
 * `StationId` (the gauge's id, its array type kept), `GaugeId` (index into the gauges), `Weight`
 * and `Area_m2` (the gauge's weight and clipped ellipsoidal area, m^2: per gauge, repeated on
 * each of its cells, so sum them once per station, not over cells), `Value` (the gauge's value;
 * the active scalars, which ParaView colours the tiles by),
 * `CellArea_m2` (this cell's own ellipsoidal area, m^2) and `CellWeight` (CellArea_m2 over the
 * catchment's area). Summed over all cells, `CellArea_m2` gives the covered catchment area and
 * `CellWeight` the CoveredFraction (1); over a gauge's cells, its `Area_m2` and `Weight` (to
 * round-off for equal-area areas, about 1e-9 for geodesic ones). Time steps are advertised, so
 * ParaView's time slider re-weights the tiles step by step.
 *
 * Output 1 (vtkTable): one row per time step: `Time`, `Date` (when every time was given as a
 * date: text, or a year with a month column; the step's date as text at the finest resolution
 * the series needs, "1963", "1963-08", "1963-08-16" or "1963-08-16 06:00", which reads back to
 * `Time` exactly: a CSV writer's default precision writes some decimal years alike; years 0 ..
 * 9999 only, else a warning and no column), `ArealMean` (NaN
 * where no gauge reported),
 * `StationsUsed` (gauges reporting, co-located ones counted once), `StationsWeighted` (of those,
 * gauges whose tile reaches the catchment), `CoveredFraction` (sum of weights).
 *
 * Output 2 (vtkTable): every gauge's weight at every step, in long format: one row per time step
 * and weighted gauge (steps in order, gauges ascending within a step): `Time`, `Date` (as in
 * output 1), `StationId` (when
 * the gauges have station ids), `GaugeId`, `Weight`, `Area_m2`, `Value`. A step's weights sum to
 * its `CoveredFraction` and its areal mean is the sum of `Weight` x `Value`. WeightsTable off
 * leaves it empty.
 *
 * Output 3 (vtkPolyData, time-dependent like output 0): the same tiles' outlines, each gauge's
 * part of the catchment joined back from its cells into polygons with holes
 * (core/piece_outlines.h), as a GIS wants a Thiessen polygon and as a view draws the tiles'
 * borders without the cuts between cells: one closed polyline per ring (its first point repeated
 * last), in lon/lat. Cell data: `StationId`, `GaugeId`, `Weight`, `Area_m2` and `Value` as in
 * output 0, `PolygonId` (the polygon the ring bounds, numbered over the output: most gauges have
 * one, a tile across a bay two) and `Hole` (0: the polygon's outer ring, anticlockwise, listed
 * first; 1: a hole in it, clockwise, such as a lake inside the tile). A polygon of a tile across
 * the 180th meridian is cut there, so that each lies on one side of it. No active scalars, so
 * ParaView draws the lines in one colour over the coloured tiles.
 *
 * Unused input is reported, never dropped silently, in a warning: gauges with no observation,
 * observation rows of station ids that no gauge has (each id with its number of rows and first
 * row), rows without a station id or a time (by row), a station id given to several gauges (its
 * observations go to the first), observation rows repeating the station and time of an earlier
 * row that had a value (the earlier value is used), co-located gauges (within 1 cm once
 * projected; at each step the first that reports is used), rows with a value for such a gauge at
 * a step where an earlier one at its place reported, and gauges with observed values whose tiles
 * never reach the catchment at any step. Output 1's field data lists the gauges and rows among
 * them: `UnobservedGaugeIds`, `SharedStationGaugeIds` (a gauge whose station id an earlier gauge
 * has, so that it gets no observation and is also unobserved; with `SharedStationOfGaugeIds`, the
 * first gauge with that id), `DuplicateGaugeIds`, `DuplicateOfGaugeIds` (a gauge at the place of
 * an earlier one, and that one), `UnweightedGaugeIds`,
 * `RepeatedObservationRows` (with `RepeatedObservationOfRows`, the earlier row each repeats, whose
 * value is used), `CoLocatedObservationRows` (with `CoLocatedObservationOfRows`, the row used in
 * each one's place, -1 where none is known) and `UnusedObservationRows` (rows not
 * used: no station id, no time, or a station no gauge has; table rows, from 0); it also holds
 * `TesseraProjection`, the record of the projection the tiles were made in (as
 * vtkGeographicProjection writes it: given to another average as ProjectionRecord, as for a part
 * of the catchment, it makes the same tiles). Two more warnings
 * flag input that is used but may not be what was meant: no gauge inside the catchment (a sign of
 * swapped or unsigned coordinates), and a catchment ring inside a ring of another block (in
 * vtkGDALVectorReader's output, a feature inside another feature), which the even-odd rule makes a
 * hole (or, inside a hole, land again: each ring is said to be which).
 *
 * A gauge with a NaN or out-of-range coordinate (latitude beyond 90 degrees, longitude beyond 360,
 * or beyond what ProjectionRecord's projection represents) and a self-intersecting catchment are
 * errors naming them: a gauge by its index and, when the gauges have station ids, its id
 * ("gauge 7 (station 050848)").
 *
 * An error (bad input, whether found while reading the times or while averaging) is reported with
 * vtkErrorMacro and leaves all four outputs empty, with no time steps advertised: an earlier
 * input's results are never left in place to be taken for this one's.
 */

#ifndef vtkThiessenArealAverage_h
#define vtkThiessenArealAverage_h

#include "tesseraFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstddef> // For size_t
#include <memory>  // For the internals
#include <string>  // For the names
#include <vector>  // For the gauges' array names

class vtkAbstractArray;
class vtkPointSet;
class vtkPolyData;
class vtkTable;

class TESSERAFILTERS_EXPORT vtkThiessenArealAverage : public vtkPolyDataAlgorithm
{
public:
  static vtkThiessenArealAverage* New();
  vtkTypeMacro(vtkThiessenArealAverage, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum AreaMethods
  {
    AUTOMATIC_AREAS = 0,
    EQUAL_AREA_PLANE = 1,
    GEODESIC_POLYGON = 2
  };

  ///@{
  /**
   * The three inputs: gauges (port 0), catchment (port 1), observations (port 2, optional).
   */
  void SetGaugesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetCatchmentConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetObservationsConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(2, output);
  }
  void SetGaugesData(vtkDataObject* data) { this->SetInputData(0, data); }
  void SetCatchmentData(vtkDataObject* data) { this->SetInputData(1, data); }
  void SetObservationsData(vtkDataObject* data) { this->SetInputData(2, data); }
  ///@}

  ///@{
  /**
   * Names of the gauges' station id array and, without observations, of their value array.
   * Without observations the station ids are optional (they name the gauges); an absent one is
   * said in a warning, once per build, so that a mistyped name is not taken silently.
   */
  vtkSetStdStringFromCharMacro(StationIdArrayName);
  vtkGetCharFromStdStringMacro(StationIdArrayName);
  vtkSetStdStringFromCharMacro(ValueArrayName);
  vtkGetCharFromStdStringMacro(ValueArrayName);
  ///@}

  ///@{
  /**
   * Column names of the observations table.
   */
  vtkSetStdStringFromCharMacro(StationColumn);
  vtkGetCharFromStdStringMacro(StationColumn);
  vtkSetStdStringFromCharMacro(TimeColumn);
  vtkGetCharFromStdStringMacro(TimeColumn);
  vtkSetStdStringFromCharMacro(ValueColumn);
  vtkGetCharFromStdStringMacro(ValueColumn);
  ///@}

  ///@{
  /**
   * The observations column of months (1 .. 12) when the table gives a row's time as a year
   * column (TimeColumn, e.g. "year") and a month column (e.g. "month"): the time is then
   * year + (month - 1) / 12. Empty (default): TimeColumn alone gives the time.
   */
  vtkSetStdStringFromCharMacro(MonthColumn);
  vtkGetCharFromStdStringMacro(MonthColumn);
  ///@}

  ///@{
  /**
   * A `TesseraProjection` record ("projection=... lon0=... ..."); empty (default) = automatic.
   */
  vtkSetStdStringFromCharMacro(ProjectionRecord);
  vtkGetCharFromStdStringMacro(ProjectionRecord);
  ///@}

  ///@{
  /**
   * How ellipsoidal areas are measured (default automatic: planar areas for an equal-area
   * projection, GeographicLib::PolygonArea of unprojected rings otherwise). EqualAreaPlane with a
   * projection that is not equal-area, or a value that is none of the three, is an error at the
   * update.
   */
  vtkSetMacro(AreaMethod, int);
  // The range VTK's clamping setter announced (kept: a value outside is an error at the update).
  virtual int GetAreaMethodMinValue() { return AUTOMATIC_AREAS; }
  virtual int GetAreaMethodMaxValue() { return GEODESIC_POLYGON; }
  vtkGetMacro(AreaMethod, int);
  void SetAreaMethodToAutomatic() { this->SetAreaMethod(AUTOMATIC_AREAS); }
  void SetAreaMethodToEqualAreaPlane() { this->SetAreaMethod(EQUAL_AREA_PLANE); }
  void SetAreaMethodToGeodesicPolygon() { this->SetAreaMethod(GEODESIC_POLYGON); }
  ///@}

  ///@{
  /**
   * Whether output 2 lists every step's weights (default on). Off saves its memory when gauges
   * times steps run to many millions of rows.
   */
  vtkSetMacro(WeightsTable, bool);
  vtkGetMacro(WeightsTable, bool);
  vtkBooleanMacro(WeightsTable, bool);
  ///@}

  ///@{
  /**
   * A number that marks missing values, such as -9999 in many gauge records, taken as missing
   * (as NaN is) in the value column of the observations or, without them, in the gauges' value
   * array, when UseMissingValue is on (default off, MissingValue default -9999; 0 and NaN are
   * errors). A value of exactly -9999, -999, 9999 or 99999 (common codes) that is not the one
   * used is averaged as a measurement, and a warning counts each code's values and names the
   * first of each (MissingValue takes one code: the others stay values).
   */
  vtkSetMacro(UseMissingValue, bool);
  vtkGetMacro(UseMissingValue, bool);
  vtkBooleanMacro(UseMissingValue, bool);
  vtkSetMacro(MissingValue, double);
  vtkGetMacro(MissingValue, double);
  ///@}

  /**
   * Number of time steps found in the last update (1 without observations).
   */
  int GetNumberOfTimeSteps();

  /**
   * The time that a date of the observations gets, for UpdateTimeStep: "1963-08" is 1963 + 7/12
   * and "1963-08-16" 1963 + (7 + 15/31)/12 (decimal years on a month grid: a day is a share of
   * its month, not of its year), "1963-08-16 06:00" a share of that day ("24:00" is the next
   * day's "00:00"), a year alone "1963" its start; as the tables' Time column gives it beside their
   * Date, and as the filter reads the observations' dates (a time zone such as "Z" at the end is
   * left off: the time is as written). NaN for text that is not such a date.
   */
  static double TimeOfDate(const char* date);

protected:
  vtkThiessenArealAverage();
  ~vtkThiessenArealAverage() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string StationIdArrayName = "station_id";
  std::string ValueArrayName = "value";
  std::string StationColumn = "station_id";
  std::string TimeColumn = "time";
  std::string ValueColumn = "value";
  std::string MonthColumn;
  bool UseMissingValue = false;
  double MissingValue = -9999.0;
  std::string ProjectionRecord;
  int AreaMethod = AUTOMATIC_AREAS;
  bool WeightsTable = true;

private:
  vtkThiessenArealAverage(const vtkThiessenArealAverage&) = delete;
  void operator=(const vtkThiessenArealAverage&) = delete;

  /// Reads the inputs, builds the engine and computes every step's summary row.
  void Build(vtkPointSet* gauges,
    vtkAbstractArray* stationIds,
    vtkDataObject* catchment,
    vtkTable* observations);
  /// The gauges as one point set: input 0 itself, or its blocks' points joined (kept in the
  /// internals while unchanged). Throws InputError for input that is neither.
  vtkPointSet* GaugesOf(vtkDataObject* data);
  /// Joins the gauges' blocks, or copies a point set with its vertices' arrays as point data,
  /// into the internals' Joined (arrays: the station id and value arrays' names).
  void JoinGauges(vtkDataObject* data, const std::vector<std::string>& arrays);
  /// Builds again when the filter or an input changed since the last build.
  void BuildIfChanged(vtkPointSet* gauges,
    vtkAbstractArray* stationIds,
    vtkDataObject* catchment,
    vtkTable* observations);
  /// The step of the time requested of the tiles (tilesInfo), the last at or before it (0 without
  /// a time); false, with an error, for a requested time of NaN.
  bool RequestedStep(vtkInformation* tilesInfo, std::size_t& step);
  /// The gauges' point-data array StationIdArrayName; an InputError naming it when it is missing
  /// and required (to match observations with).
  vtkAbstractArray* GaugeStationIds(vtkPointSet* gauges, bool required);
  /// Forgets the last build and empties every output: after an error nothing is shown as a result
  /// of the failed input.
  void DiscardResults(vtkInformationVector* outputVector);
  /// Outputs 0 and 3 (the tiles and their outlines) for one step.
  void WriteTiles(std::size_t step,
    vtkAbstractArray* stationIds,
    vtkPolyData* output,
    vtkPolyData* outlines);

  struct Internals;
  struct BuildRun; // one Build's steps (in the .cxx)
  std::unique_ptr<Internals> Internal;
};

#endif
