#pragma once
// Gauge time series from observations in long format (one row per station, time and value, as a
// CSV table holds them): the rows matched with the gauges by station id and assembled into a value
// per time step and gauge, what ThiessenArealAverage::Step (areal_average.h) takes step by step.
//
// A row is used when it names a station that a gauge has and has a time; the time steps are the
// distinct times of the used rows only, so that a blank line or a station outside the gauges never
// makes a step of its own. Three passes, so that a caller reads a row's time only when its station
// matched and its value only when the row is used (and reports a bad one by its row):
//
//   MatchStations(gauge ids, row ids)           the gauge each row names
//   StepsOfRows(match, the matched rows' times)  the time steps, each used row's step
//   BuildSeries(match, steps, the used rows' values, gauge count)  the step x gauge values
//
// Rows and gauges are numbered from 0 in the caller's order.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tessera
{

/// The key by which station ids compare: the id as text, with the leading zeros of an integer id
/// (digits only) dropped, so that an id read as text ("050109") matches the same id read as a
/// number (50109); "000" is "0". An integer id written with a point or comma and zeros ("50109.0",
/// "50109,0", as a program writes a whole-number column that has gaps) is that integer. Empty for
/// an empty id.
std::string StationKey(std::string id);

/// A station id of the observations that no gauge has: its rows are not used.
struct UnknownStation
{
  std::int32_t FirstRow; ///< its first row (whose id, as written, names it)
  std::int32_t Rows;     ///< how many rows name it (by key)
};

/// A gauge whose station id (by key) an earlier gauge has: the id's rows go to the earlier one.
struct SharedStation
{
  std::int32_t FirstGauge; ///< the first gauge with the id
  std::int32_t Gauge;      ///< the later gauge
};

/// The rows' station ids matched with the gauges' (MatchStations).
struct StationMatch
{
  /// Per row: the first gauge with its station id, -1 for none (an empty id or one no gauge has).
  std::vector<std::int32_t> GaugeOfRow;
  std::vector<std::int32_t> RowsWithoutStation; ///< the rows with an empty id, ascending
  std::vector<UnknownStation> UnknownStations;  ///< ids no gauge has, in the order first met
  std::vector<SharedStation> SharedStations;    ///< ascending by Gauge
};

/// Matches each row's station id with the gauges' by StationKey. gaugeIds: one per gauge;
/// rowIds: one per row, empty for a row without one.
StationMatch MatchStations(const std::vector<std::string>& gaugeIds,
  const std::vector<std::string>& rowIds);

/// The time steps of the observations (StepsOfRows).
struct ObservationSteps
{
  std::vector<double> Times;           ///< the distinct times of the used rows, ascending
  std::vector<std::int32_t> StepOfRow; ///< per row: the index of its time in Times, -1 if not used
  /// The rows without a station id, and those of a gauge's station without a time, ascending.
  std::vector<std::int32_t> IncompleteRows;

  /// The rows not used (StepOfRow -1): incomplete ones and those of ids that no gauge has,
  /// ascending.
  std::vector<std::int32_t> UnusedRows() const;
};

/// The time steps and each used row's step. rowTimes: per row of match, its time, nothing for a
/// row without one; only the rows with a gauge (GaugeOfRow >= 0) are looked at, so the others
/// need not be read.
ObservationSteps StepsOfRows(const StationMatch& match,
  const std::vector<std::optional<double>>& rowTimes);

/// The values per step and gauge (BuildSeries).
struct StepSeries
{
  /// Per step, per gauge: the value of the gauge's row at that step, NaN where none has one.
  std::vector<std::vector<double>> Values;
  /// The rows repeating the gauge and step of an earlier row that had a value (not NaN), ascending:
  /// the earlier value is kept.
  std::vector<std::int32_t> RepeatedRows;
  /// Per repeated row, the earlier row whose value is kept (the first of its gauge and step with a
  /// value), so that a report can say which row each one repeats.
  std::vector<std::int32_t> RepeatedRowOf;
};

/// The step x gauge values of the used rows. rowValues: per row, its value (NaN for a missing
/// one); only the used rows' (StepOfRow >= 0) are looked at. gaugeCount: the number of gauges.
StepSeries BuildSeries(const StationMatch& match,
  const ObservationSteps& steps,
  const std::vector<double>& rowValues,
  std::size_t gaugeCount);

/// Values exactly equal to one common missing-value code (TakeMissingValues): the code, how many
/// values have it, and the first one's index.
struct MissingCodeSightings
{
  double Code = 0.0;
  std::size_t Count = 0;
  std::size_t First = 0;
};

/// With `use`, sets the values equal to `missing` to NaN (missing); throws InputError for a
/// missing value of 0 (every dry step would be missing) or NaN (missing anyway: nothing would
/// change). Then finds the values exactly equal to a common missing-value code (-9999, -999, 9999,
/// 99999) other than the one used, which would be averaged as measurements: one entry per code
/// met, the most often met first (ties in that order of codes); none when there are none.
std::vector<MissingCodeSightings> TakeMissingValues(std::vector<double>& values,
  bool use,
  double missing);

} // namespace tessera
