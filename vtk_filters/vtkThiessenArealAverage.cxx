#include "vtkThiessenArealAverage.h"

#include "vtkAbstractArray.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include "TesseraFilterUtilities.h"
#include "areal_average.h"
#include "decimal_time.h"
#include "errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <unordered_map>

vtkStandardNewMacro(vtkThiessenArealAverage);

namespace
{

/// text without the given characters at either end.
std::string Trimmed(const std::string& text, const char* characters = " \t")
{
  const auto first = text.find_first_not_of(characters);
  const auto last = text.find_last_not_of(characters);
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

/// Station ids compare as text, trimmed, with leading zeros of integer ids dropped, so that an id
/// read as text ("050109") matches the same id read as a number (50109).
std::string StationKey(const vtkVariant& value)
{
  // A floating-point id (a CSV reader's numeric column) in full: ToString() keeps 6 digits, which
  // made USGS-style ids such as 06730200 and 06730500 one station.
  std::string text;
  if (value.IsFloat() || value.IsDouble())
  {
    const double number = value.ToDouble();
    char digits[64];
    const bool integral = std::isfinite(number) && number == std::floor(number) &&
      std::fabs(number) < 9007199254740992.0; // 2^53: every such double is an exact integer
    std::snprintf(digits, sizeof digits, integral ? "%.0f" : "%.17g", number);
    text = digits;
  }
  else
  {
    text = Trimmed(value.ToString(), " \t\"");
  }
  if (!text.empty() &&
    std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
  {
    const auto nonZero = text.find_first_not_of('0');
    text = nonZero == std::string::npos ? "0" : text.substr(nonZero);
  }
  return text;
}

std::string ListIds(const std::vector<std::string>& ids)
{
  std::ostringstream out;
  for (std::size_t k = 0; k < ids.size() && k < 20; ++k)
  {
    out << (k ? ", " : "") << ids[k];
  }
  if (ids.size() > 20)
  {
    out << ", ... (" << ids.size() << " in all)";
  }
  return out.str();
}

/// The column of the observations table, or an InputError naming it and what it should hold.
vtkAbstractArray* ObservationColumn(vtkTable* table, const std::string& column, const char* holds)
{
  vtkAbstractArray* array = table->GetColumnByName(column.c_str());
  if (!array || array->GetNumberOfComponents() != 1)
  {
    throw tessera::InputError(
      "the observations table has no column '" + column + "' (" + holds + ")");
  }
  return array;
}

/// An InputError for a row of the observations table: "observation row R: what".
[[noreturn]] void ThrowRowError(vtkIdType row, const std::string& what)
{
  std::ostringstream message;
  message << "observation row " << row << ": " << what;
  throw tessera::InputError(message.str());
}

/// A column read as numbers: a numeric array directly, text parsed row by row (the array's type
/// is found once, not per row).
class NumberColumn
{
public:
  explicit NumberColumn(vtkAbstractArray* array)
    : Array(array)
    , Numbers(vtkDataArray::SafeDownCast(array))
  {
  }

  bool IsText() const { return !this->Numbers; }
  std::string Text(vtkIdType row) const { return this->Array->GetVariantValue(row).ToString(); }

  /// The row's number; nothing for text that is not one (spaces around it are allowed).
  std::optional<double> Number(vtkIdType row) const
  {
    if (this->Numbers)
    {
      return this->Numbers->GetTuple1(row);
    }
    const std::string text = Trimmed(this->Text(row));
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size())
    {
      return std::nullopt;
    }
    return value;
  }

private:
  vtkAbstractArray* Array;
  vtkDataArray* Numbers;
};

/// Whether text marks a missing value: empty, NA, N/A, NaN or null (any case, spaces around).
bool IsMissingMarker(const std::string& text)
{
  std::string lower = Trimmed(text);
  std::transform(lower.begin(),
    lower.end(),
    lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.empty() || lower == "na" || lower == "n/a" || lower == "nan" || lower == "null";
}

/// The time of each row of the observations table (decimal_time.h): the time column's numbers,
/// its text read as ISO dates (YYYY, YYYY-MM, YYYY-MM-DD, optionally with a time of day), or, with
/// a month column, the time column's year plus the month's twelfth.
std::vector<double> ReadRowTimes(vtkTable* table,
  const std::string& timeColumn,
  const std::string& monthColumn)
{
  if (table->GetNumberOfRows() == 0)
  {
    return {}; // no steps: Build says so, even when the columns are missing too
  }
  const bool byMonth = !monthColumn.empty();
  const NumberColumn times(ObservationColumn(table,
    timeColumn,
    byMonth ? "years" : "numbers, or dates as text such as 1963-08 or 1963-08-16"));
  const NumberColumn months(
    byMonth ? ObservationColumn(table, monthColumn, "months 1 .. 12") : nullptr);
  const bool dates = !byMonth && times.IsText();
  std::vector<double> rowTimes(static_cast<std::size_t>(table->GetNumberOfRows()));
  for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
  {
    if (dates)
    {
      const std::optional<double> t = tessera::IsoDateTime(times.Text(r));
      if (!t)
      {
        ThrowRowError(r,
          "'" + times.Text(r) + "' in column '" + timeColumn +
            "' is not a date (YYYY, YYYY-MM or YYYY-MM-DD, optionally with hh:mm[:ss])");
      }
      rowTimes[r] = *t;
      continue;
    }
    const std::optional<double> t = times.Number(r);
    if (!t || !std::isfinite(*t))
    {
      ThrowRowError(r,
        "the time '" + times.Text(r) + "' in column '" + timeColumn + "' is not a finite number");
    }
    rowTimes[r] = *t;
    if (byMonth)
    {
      const double month = months.Number(r).value_or(0.0);
      if (!(month >= 1.0 && month <= 12.0 && month == std::floor(month)))
      {
        ThrowRowError(
          r, "the month " + months.Text(r) + " in column '" + monthColumn + "' is not 1 .. 12");
      }
      rowTimes[r] = tessera::MonthTime(*t, static_cast<int>(month));
    }
  }
  return rowTimes;
}

/// A row's value: a number, or NaN (missing) for NaN or, in a text column, a missing-value marker
/// (IsMissingMarker: a CSV reader gives a text column where such markers stand among the numbers).
/// Other text is an error naming the row.
double ObservationValue(const NumberColumn& values, vtkIdType row, const std::string& column)
{
  if (const std::optional<double> value = values.Number(row))
  {
    return *value;
  }
  const std::string text = values.Text(row);
  if (!IsMissingMarker(text))
  {
    ThrowRowError(row,
      "'" + text + "' in column '" + column +
        "' is not a number (a missing value is an empty field, NA, N/A, NaN or null)");
  }
  return std::numeric_limits<double>::quiet_NaN();
}

/// The distinct times, ascending.
std::vector<double> UniqueTimes(std::vector<double> times)
{
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

/// The modification time of a table's column, 0 when it has none.
vtkMTimeType ColumnMTime(vtkTable* table, const std::string& column)
{
  vtkAbstractArray* array = table->GetColumnByName(column.c_str());
  return array ? array->GetMTime() : 0;
}

/// Output 2's columns, a row per step and weighted gauge: Time, StationId (the gauges' id array's
/// type, when they have one), GaugeId, Weight, Area_m2, Value.
class WeightRows
{
public:
  explicit WeightRows(vtkAbstractArray* stationIds)
    : StationIds(stationIds)
  {
    if (stationIds)
    {
      this->Stations = vtk::TakeSmartPointer(stationIds->NewInstance());
      this->Stations->SetNumberOfComponents(stationIds->GetNumberOfComponents());
      this->Stations->SetName("StationId");
    }
    this->Times->SetName("Time");
    this->GaugeIds->SetName("GaugeId");
    this->Weights->SetName("Weight");
    this->Areas->SetName("Area_m2");
    this->Values->SetName("Value");
  }

  void Append(double time, const tessera::ArealStep& step, const std::vector<double>& values)
  {
    for (std::size_t k = 0; k < step.Gauges.size(); ++k)
    {
      const std::int32_t g = step.Gauges[k];
      this->Times->InsertNextValue(time);
      if (this->Stations)
      {
        this->Stations->InsertNextTuple(g, this->StationIds);
      }
      this->GaugeIds->InsertNextValue(g);
      this->Weights->InsertNextValue(step.Weights[k]);
      this->Areas->InsertNextValue(step.AreasM2[k]);
      this->Values->InsertNextValue(values[static_cast<std::size_t>(g)]);
    }
  }

  void Fill(vtkTable* table)
  {
    table->Initialize();
    table->AddColumn(this->Times);
    if (this->Stations)
    {
      table->AddColumn(this->Stations);
    }
    table->AddColumn(this->GaugeIds);
    table->AddColumn(this->Weights);
    table->AddColumn(this->Areas);
    table->AddColumn(this->Values);
  }

private:
  vtkAbstractArray* StationIds;
  vtkSmartPointer<vtkAbstractArray> Stations;
  vtkNew<vtkDoubleArray> Times, Weights, Areas, Values;
  vtkNew<vtkIdTypeArray> GaugeIds;
};

} // namespace

struct vtkThiessenArealAverage::Internals
{
  vtkMTimeType BuiltFor = 0;
  std::vector<double> Times;
  std::vector<std::vector<double>> Values; // per step, per gauge; NaN = missing
  std::unique_ptr<tessera::ThiessenArealAverage> Average;
  vtkNew<vtkTable> Summary;
  vtkNew<vtkTable> Weights; // output 2: one row per step and weighted gauge

  /// The observation times read (and validated) by RequestInformation, with what they were read
  /// from, so that Build reuses them while the table and the time columns are unchanged.
  struct TimesCache
  {
    vtkTable* Table = nullptr; // compared only, never dereferenced; null: nothing cached
    vtkMTimeType TableMTime = 0;
    vtkMTimeType ColumnMTimes[2] = { 0, 0 };
    std::string Columns[2];
    std::vector<double> RowTimes; // per row of the table
    std::vector<double> Times;    // distinct, ascending: the time steps
  } ReadTimesCache;

  /// ReadRowTimes(table, timeColumn, monthColumn) and its distinct times, from the cache when
  /// they were read from this table, unchanged since.
  const TimesCache& CachedReadTimes(vtkTable* table,
    const std::string& timeColumn,
    const std::string& monthColumn);
};

const vtkThiessenArealAverage::Internals::TimesCache&
vtkThiessenArealAverage::Internals::CachedReadTimes(vtkTable* table,
  const std::string& timeColumn,
  const std::string& monthColumn)
{
  TimesCache& cache = this->ReadTimesCache;
  const vtkMTimeType tableMTime = table->GetMTime();
  const vtkMTimeType columnMTimes[2] = { ColumnMTime(table, timeColumn),
    monthColumn.empty() ? 0 : ColumnMTime(table, monthColumn) };
  if (cache.Table == table && cache.TableMTime == tableMTime &&
    cache.ColumnMTimes[0] == columnMTimes[0] && cache.ColumnMTimes[1] == columnMTimes[1] &&
    cache.Columns[0] == timeColumn && cache.Columns[1] == monthColumn)
  {
    return cache;
  }
  cache.Table = nullptr; // until the read succeeds (it throws on bad times)
  cache.RowTimes = ReadRowTimes(table, timeColumn, monthColumn);
  cache.Times = UniqueTimes(cache.RowTimes);
  cache.Table = table;
  cache.TableMTime = tableMTime;
  cache.ColumnMTimes[0] = columnMTimes[0];
  cache.ColumnMTimes[1] = columnMTimes[1];
  cache.Columns[0] = timeColumn;
  cache.Columns[1] = monthColumn;
  return cache;
}

//------------------------------------------------------------------------------
vtkThiessenArealAverage::vtkThiessenArealAverage()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(3);
}

vtkThiessenArealAverage::~vtkThiessenArealAverage() = default;

int vtkThiessenArealAverage::GetNumberOfTimeSteps()
{
  return static_cast<int>(this->Internal->Times.size());
}

//------------------------------------------------------------------------------
int vtkThiessenArealAverage::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  }
  else if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkTable");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkThiessenArealAverage::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkTable");
  return 1;
}

//------------------------------------------------------------------------------
int vtkThiessenArealAverage::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  if (this->GetNumberOfInputConnections(2) == 0)
  {
    return 1;
  }
  // The time steps are the observation table's times: that table is read now, ahead of
  // RequestData, so that the pipeline (and ParaView's time slider) knows them.
  vtkAlgorithm* source = this->GetInputAlgorithm(2, 0);
  source->Update(this->GetInputConnection(2, 0)->GetIndex());
  auto* table =
    vtkTable::SafeDownCast(source->GetOutputDataObject(this->GetInputConnection(2, 0)->GetIndex()));
  if (!table)
  {
    return 1;
  }
  try
  {
    const std::vector<double>& times =
      this->Internal->CachedReadTimes(table, this->TimeColumn, this->MonthColumn).Times;
    if (!times.empty())
    {
      outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(),
        times.data(),
        static_cast<int>(times.size()));
      const double range[2] = { times.front(), times.back() };
      outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    // RequestData will not run: without this the outputs would still show the last good input's
    // results as if they were this input's.
    this->DiscardResults(outputVector);
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkThiessenArealAverage::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPointSet* gauges = vtkPointSet::GetData(inputVector[0]);
  vtkDataObject* catchment = vtkDataObject::GetData(inputVector[1]);
  vtkTable* observations = vtkTable::GetData(inputVector[2]);
  vtkInformation* tilesInfo = outputVector->GetInformationObject(0);
  vtkPolyData* tilesOutput = vtkPolyData::GetData(outputVector, 0);
  vtkTable* summaryOutput = vtkTable::GetData(outputVector, 1);
  vtkTable* weightsOutput = vtkTable::GetData(outputVector, 2);
  Internals& in = *this->Internal;
  try
  {
    vtkAbstractArray* stationIds =
      gauges->GetPointData()->GetAbstractArray(this->StationIdArrayName.c_str());
    if (!stationIds && observations)
    {
      throw tessera::InputError("the gauges have no point-data array '" + this->StationIdArrayName +
        "' of station ids to match the observations with");
    }
    vtkMTimeType stamp = std::max(this->GetMTime(), gauges->GetMTime());
    stamp = std::max(stamp, catchment->GetMTime());
    if (observations)
    {
      stamp = std::max(stamp, observations->GetMTime());
    }
    if (!in.Average || stamp > in.BuiltFor)
    {
      this->Build(gauges, stationIds, catchment, observations);
      in.BuiltFor = stamp;
    }
    summaryOutput->ShallowCopy(in.Summary);
    weightsOutput->ShallowCopy(in.Weights);

    // The requested step: the last one at or before the requested time.
    std::size_t step = 0;
    if (tilesInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) && !in.Times.empty())
    {
      const double t = tilesInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
      const auto after = std::upper_bound(in.Times.begin(), in.Times.end(), t);
      step = after == in.Times.begin() ? 0 : static_cast<std::size_t>(after - in.Times.begin() - 1);
    }
    this->WriteTiles(step, stationIds, tilesOutput);
    if (!in.Times.empty())
    {
      tilesOutput->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), in.Times[step]);
    }
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
    this->DiscardResults(outputVector);
    return 0;
  }
}

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::DiscardResults(vtkInformationVector* outputVector)
{
  Internals& in = *this->Internal;
  in.Average.reset();
  in.Times.clear();
  in.Values.clear();
  in.Summary->Initialize();
  in.Weights->Initialize();
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    if (vtkDataObject* output = info->Get(vtkDataObject::DATA_OBJECT()))
    {
      output->Initialize();
      output->GetInformation()->Remove(vtkDataObject::DATA_TIME_STEP());
    }
  }
}

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::Build(vtkPointSet* gauges,
  vtkAbstractArray* stationIds,
  vtkDataObject* catchment,
  vtkTable* observations)
{
  Internals& in = *this->Internal;
  in.Average.reset();
  const std::vector<tessera::Point2> lonlat = tessera_vtk::ReadPoints2D(gauges->GetPoints());
  const tessera_vtk::Rings rings = tessera_vtk::ReadPolygonRings(catchment);
  const std::string skippedRings = tessera_vtk::SkippedCellsWarning(rings, "catchment (input 1)");
  if (!skippedRings.empty())
  {
    vtkWarningMacro(<< skippedRings);
  }
  tessera::ArealAverageSettings settings;
  if (!this->ProjectionRecord.empty())
  {
    settings.HaveProjection = true;
    settings.Projection = tessera::ProjectionParameters::FromString(this->ProjectionRecord);
  }
  settings.Areas = this->AreaMethod == EQUAL_AREA_PLANE ? tessera::AreaMethod::EqualAreaPlane
    : this->AreaMethod == GEODESIC_POLYGON              ? tessera::AreaMethod::GeodesicPolygon
                                                        : tessera::AreaMethod::Automatic;
  in.Average.reset(
    new tessera::ThiessenArealAverage(lonlat, rings.Offsets, rings.Vertices, settings));
  const std::size_t gaugeCount = lonlat.size();
  const double missing = std::numeric_limits<double>::quiet_NaN();

  in.Times.clear();
  in.Values.clear();
  std::vector<std::string> unknownStations, sharedIds, repeatedNames;
  std::vector<std::int32_t> repeatedRows;
  if (observations)
  {
    if (observations->GetNumberOfRows() == 0)
    {
      throw tessera::InputError("the observations table has no rows (no time step to average)");
    }
    vtkAbstractArray* stations =
      ObservationColumn(observations, this->StationColumn, "station ids, numbers or text");
    const NumberColumn values(ObservationColumn(
      observations, this->ValueColumn, "numbers; NaN, NA or an empty field where missing"));
    std::unordered_map<std::string, std::size_t> gaugeOf; // the first gauge of each id
    for (std::size_t g = 0; g < gaugeCount; ++g)
    {
      const auto [at, first] =
        gaugeOf.emplace(StationKey(stationIds->GetVariantValue(static_cast<vtkIdType>(g))), g);
      if (!first)
      {
        sharedIds.push_back(
          at->first + " (gauges " + std::to_string(at->second) + " and " + std::to_string(g) + ")");
      }
    }
    const Internals::TimesCache& read =
      in.CachedReadTimes(observations, this->TimeColumn, this->MonthColumn);
    in.Times = read.Times;
    in.Values.assign(in.Times.size(), std::vector<double>(gaugeCount, missing));
    std::unordered_map<std::string, bool> reportedUnknown;
    for (vtkIdType r = 0; r < observations->GetNumberOfRows(); ++r)
    {
      const std::string key = StationKey(stations->GetVariantValue(r));
      const auto gauge = gaugeOf.find(key);
      if (gauge == gaugeOf.end())
      {
        if (reportedUnknown.emplace(key, true).second)
        {
          unknownStations.push_back(key);
        }
        continue;
      }
      const double value = ObservationValue(values, r, this->ValueColumn);
      if (std::isinf(value))
      {
        ThrowRowError(r, "station " + key + " has an infinite value");
      }
      const std::size_t step = static_cast<std::size_t>(
        std::lower_bound(
          in.Times.begin(), in.Times.end(), read.RowTimes[static_cast<std::size_t>(r)]) -
        in.Times.begin());
      double& slot = in.Values[step][gauge->second];
      if (std::isnan(slot))
      {
        slot = value; // a repeated (station, time) row keeps its first value
      }
      else
      {
        repeatedRows.push_back(static_cast<std::int32_t>(r));
        repeatedNames.push_back("row " + std::to_string(r) + " (station " + key + ")");
      }
    }
  }
  else
  {
    auto* values = vtkDataArray::SafeDownCast(
      gauges->GetPointData()->GetAbstractArray(this->ValueArrayName.c_str()));
    if (!values)
    {
      throw tessera::InputError(
        "without observations the gauges need a numeric point-data array '" + this->ValueArrayName +
        "'");
    }
    in.Times.push_back(0.0);
    in.Values.emplace_back(gaugeCount);
    for (std::size_t g = 0; g < gaugeCount; ++g)
    {
      in.Values[0][g] = values->GetTuple1(static_cast<vtkIdType>(g));
    }
  }

  // Everything valid but unused is reported by id.
  auto idOf = [&](std::size_t g)
  {
    return stationIds ? stationIds->GetVariantValue(static_cast<vtkIdType>(g)).ToString()
                      : std::to_string(g);
  };
  std::vector<std::int32_t> unobserved;
  std::vector<std::string> unobservedNames;
  for (std::size_t g = 0; g < gaugeCount; ++g)
  {
    bool any = false;
    for (const auto& stepValues : in.Values)
    {
      if (!std::isnan(stepValues[g]))
      {
        any = true;
        break;
      }
    }
    if (!any)
    {
      unobserved.push_back(static_cast<std::int32_t>(g));
      unobservedNames.push_back(idOf(g));
    }
  }
  std::vector<std::int32_t> duplicates, duplicateOf;
  std::vector<std::string> duplicateNames;
  for (const auto& pair : in.Average->DuplicateGauges())
  {
    duplicates.push_back(pair.first);
    duplicateOf.push_back(pair.second);
    duplicateNames.push_back(idOf(pair.first) + " (same place as " + idOf(pair.second) + ")");
  }
  // One warning per kind of unused input: "N <what>: the first 20 names".
  const auto warnOf = [this](const std::vector<std::string>& names, const char* what)
  {
    if (!names.empty())
    {
      vtkWarningMacro(<< names.size() << " " << what << ": " << ListIds(names));
    }
  };
  warnOf(unobservedNames, "gauge(s) have no observation and are never used");
  warnOf(unknownStations, "station id(s) of the observations that no gauge has were ignored");
  warnOf(sharedIds,
    "station id(s) are given to more than one gauge; their observations go to the first");
  warnOf(repeatedNames,
    "observation row(s) repeat a station and time of an earlier row with a value; the earlier "
    "value is used (rows from 0, listed in RepeatedObservationRows)");
  warnOf(
    duplicateNames, "gauge(s) stand where an earlier gauge stands; the first that reports is used");

  // The summary: every step in order, each one updating the tessellation of the one before.
  vtkNew<vtkDoubleArray> timeColumn, means, covered;
  vtkNew<vtkIntArray> used, weighted;
  timeColumn->SetName("Time");
  means->SetName("ArealMean");
  used->SetName("StationsUsed");
  weighted->SetName("StationsWeighted");
  covered->SetName("CoveredFraction");
  WeightRows weightRows(stationIds);
  for (std::size_t step = 0; step < in.Times.size(); ++step)
  {
    if (step % 16 == 0)
    {
      this->UpdateProgress(0.9 * static_cast<double>(step) / in.Times.size());
    }
    const tessera::ArealStep result = in.Average->Step(in.Values[step]);
    timeColumn->InsertNextValue(in.Times[step]);
    means->InsertNextValue(result.Mean);
    used->InsertNextValue(result.StationsUsed);
    weighted->InsertNextValue(result.StationsWeighted);
    covered->InsertNextValue(result.CoveredFraction);
    if (this->WeightsTable)
    {
      weightRows.Append(in.Times[step], result, in.Values[step]);
    }
  }
  weightRows.Fill(in.Weights);
  in.Summary->Initialize();
  in.Summary->AddColumn(timeColumn);
  in.Summary->AddColumn(means);
  in.Summary->AddColumn(used);
  in.Summary->AddColumn(weighted);
  in.Summary->AddColumn(covered);
  tessera_vtk::AddIdFieldArray(in.Summary, "UnobservedGaugeIds", unobserved);
  tessera_vtk::AddIdFieldArray(in.Summary, "DuplicateGaugeIds", duplicates);
  tessera_vtk::AddIdFieldArray(in.Summary, "DuplicateOfGaugeIds", duplicateOf);
  tessera_vtk::AddIdFieldArray(in.Summary, "RepeatedObservationRows", repeatedRows);
}

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::WriteTiles(std::size_t step,
  vtkAbstractArray* stationIds,
  vtkPolyData* output)
{
  Internals& in = *this->Internal;
  const tessera::ArealStep result = in.Average->Step(in.Values[step]);
  const tessera::ClippedTilesLonLat clipped = in.Average->CurrentClippedTiles(2000.0);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : clipped.Rings.Vertices)
  {
    points->InsertNextPoint(p.x, p.y, 0.0);
  }
  vtkNew<vtkCellArray> polys;
  vtkSmartPointer<vtkAbstractArray> station;
  if (stationIds)
  {
    station = vtk::TakeSmartPointer(stationIds->NewInstance());
    station->SetNumberOfComponents(stationIds->GetNumberOfComponents());
  }
  vtkNew<vtkIdTypeArray> gaugeIds;
  vtkNew<vtkDoubleArray> weights, areas, values;
  gaugeIds->SetName("GaugeId");
  weights->SetName("Weight");
  areas->SetName("Area_m2");
  values->SetName("Value");
  for (std::size_t k = 0; k < clipped.Gauges.size(); ++k)
  {
    const std::int32_t g = clipped.Gauges[k];
    const auto found = std::lower_bound(result.Gauges.begin(), result.Gauges.end(), g);
    const std::size_t index = static_cast<std::size_t>(found - result.Gauges.begin());
    const bool isWeighted = found != result.Gauges.end() && *found == g;
    for (std::size_t r = clipped.TileRingOffsets[k]; r < clipped.TileRingOffsets[k + 1]; ++r)
    {
      const std::size_t begin = clipped.Rings.RingOffsets[r],
                        end = clipped.Rings.RingOffsets[r + 1];
      polys->InsertNextCell(static_cast<vtkIdType>(end - begin));
      for (std::size_t v = begin; v < end; ++v)
      {
        polys->InsertCellPoint(static_cast<vtkIdType>(v));
      }
      if (station)
      {
        station->InsertNextTuple(g, stationIds);
      }
      gaugeIds->InsertNextValue(g);
      weights->InsertNextValue(isWeighted ? result.Weights[index] : 0.0);
      areas->InsertNextValue(isWeighted ? result.AreasM2[index] : 0.0);
      values->InsertNextValue(in.Values[step][g]);
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  if (station)
  {
    station->SetName("StationId");
    output->GetCellData()->AddArray(station);
  }
  output->GetCellData()->AddArray(gaugeIds);
  output->GetCellData()->AddArray(weights);
  output->GetCellData()->AddArray(areas);
  output->GetCellData()->AddArray(values);
}

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StationIdArrayName: " << this->StationIdArrayName << "\n";
  os << indent << "ValueArrayName: " << this->ValueArrayName << "\n";
  os << indent << "StationColumn: " << this->StationColumn << "\n";
  os << indent << "TimeColumn: " << this->TimeColumn << "\n";
  os << indent << "MonthColumn: " << this->MonthColumn << "\n";
  os << indent << "ValueColumn: " << this->ValueColumn << "\n";
  os << indent << "ProjectionRecord: " << this->ProjectionRecord << "\n";
  os << indent << "AreaMethod: " << this->AreaMethod << "\n";
  os << indent << "WeightsTable: " << (this->WeightsTable ? "on" : "off") << "\n";
}
