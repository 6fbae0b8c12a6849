#include "observation_series.h"

#include "errors.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <unordered_map>

namespace tessera
{

std::string StationKey(std::string id)
{
  const auto isDigit = [](char c) { return c >= '0' && c <= '9'; };
  // "102.0" or "102.": a whole-number id as a program writes a numeric column with a gap (pandas
  // makes such an integer column floating point), the same station as 102 and 0102; "102,0" as
  // it writes one with decimal commas.
  const std::size_t point = id.find_first_of(".,");
  if (point != std::string::npos && point > 0 &&
    std::all_of(id.begin(), id.begin() + std::ptrdiff_t(point), isDigit) &&
    id.find_first_not_of('0', point + 1) == std::string::npos)
  {
    id.resize(point);
  }
  if (!id.empty() && std::all_of(id.begin(), id.end(), isDigit))
  {
    const auto nonZero = id.find_first_not_of('0');
    id = nonZero == std::string::npos ? "0" : id.substr(nonZero);
  }
  return id;
}

StationMatch MatchStations(const std::vector<std::string>& gaugeIds,
  const std::vector<std::string>& rowIds)
{
  StationMatch match;
  std::unordered_map<std::string, std::int32_t> gaugeOf; // the first gauge of each key
  for (std::size_t g = 0; g < gaugeIds.size(); ++g)
  {
    std::string key = StationKey(gaugeIds[g]);
    if (key.empty())
    {
      continue; // (no station id, as NaN in a numeric column: not an id the gauges share)
    }
    const auto [at, first] = gaugeOf.emplace(std::move(key), static_cast<std::int32_t>(g));
    if (!first)
    {
      match.SharedStations.push_back({ at->second, static_cast<std::int32_t>(g) });
    }
  }
  std::unordered_map<std::string, std::size_t> unknownOf; // index in UnknownStations of each key
  match.GaugeOfRow.assign(rowIds.size(), -1);
  for (std::size_t r = 0; r < rowIds.size(); ++r)
  {
    const auto row = static_cast<std::int32_t>(r);
    std::string key = StationKey(rowIds[r]);
    if (key.empty())
    {
      match.RowsWithoutStation.push_back(row);
      continue;
    }
    const auto gauge = gaugeOf.find(key);
    if (gauge != gaugeOf.end())
    {
      match.GaugeOfRow[r] = gauge->second;
      continue;
    }
    const auto [at, first] = unknownOf.emplace(std::move(key), match.UnknownStations.size());
    if (first)
    {
      match.UnknownStations.push_back({ row, 0 });
    }
    ++match.UnknownStations[at->second].Rows;
  }
  return match;
}

std::vector<std::int32_t> ObservationSteps::UnusedRows() const
{
  std::vector<std::int32_t> unused;
  for (std::size_t r = 0; r < this->StepOfRow.size(); ++r)
  {
    if (this->StepOfRow[r] < 0)
    {
      unused.push_back(static_cast<std::int32_t>(r));
    }
  }
  return unused;
}

ObservationSteps StepsOfRows(const StationMatch& match,
  const std::vector<std::optional<double>>& rowTimes)
{
  ObservationSteps steps;
  const std::size_t count = match.GaugeOfRow.size();
  std::vector<double> usedTimes;         // the used rows', in row order
  std::vector<std::int32_t> withoutTime; // the rows of a gauge without a time
  for (std::size_t r = 0; r < count; ++r)
  {
    if (match.GaugeOfRow[r] >= 0)
    {
      if (rowTimes[r])
      {
        usedTimes.push_back(*rowTimes[r]);
      }
      else
      {
        withoutTime.push_back(static_cast<std::int32_t>(r));
      }
    }
  }
  std::merge(match.RowsWithoutStation.begin(),
    match.RowsWithoutStation.end(),
    withoutTime.begin(),
    withoutTime.end(),
    std::back_inserter(steps.IncompleteRows));
  steps.Times = usedTimes;
  std::sort(steps.Times.begin(), steps.Times.end());
  steps.Times.erase(std::unique(steps.Times.begin(), steps.Times.end()), steps.Times.end());
  steps.StepOfRow.assign(count, -1);
  auto usedTime = usedTimes.begin();
  for (std::size_t r = 0; r < count; ++r)
  {
    if (match.GaugeOfRow[r] >= 0 && rowTimes[r])
    {
      steps.StepOfRow[r] = static_cast<std::int32_t>(
        std::lower_bound(steps.Times.begin(), steps.Times.end(), *usedTime++) -
        steps.Times.begin());
    }
  }
  return steps;
}

namespace
{
/// Per repeated row, the first row of its gauge and step with a value: the one whose value was
/// kept. A second pass over the rows, taken only when some row repeats (Colorado's record has
/// none), so that the series keeps no row per step and gauge.
std::vector<std::int32_t> KeptRowsOf(const std::vector<std::int32_t>& repeated,
  const StationMatch& match,
  const ObservationSteps& steps,
  const std::vector<double>& rowValues,
  std::size_t gaugeCount)
{
  if (repeated.empty())
  {
    return {};
  }
  const auto slotOf = [&](std::size_t r)
  {
    return static_cast<std::uint64_t>(steps.StepOfRow[r]) * gaugeCount +
      static_cast<std::uint64_t>(match.GaugeOfRow[r]);
  };
  std::unordered_map<std::uint64_t, std::int32_t> kept; // slot -> kept row, -1 until found
  for (const std::int32_t r : repeated)
  {
    kept.emplace(slotOf(static_cast<std::size_t>(r)), -1);
  }
  for (std::size_t r = 0; r < steps.StepOfRow.size(); ++r)
  {
    if (steps.StepOfRow[r] < 0 || std::isnan(rowValues[r]))
    {
      continue;
    }
    const auto found = kept.find(slotOf(r));
    if (found != kept.end() && found->second < 0)
    {
      found->second = static_cast<std::int32_t>(r);
    }
  }
  std::vector<std::int32_t> of;
  of.reserve(repeated.size());
  for (const std::int32_t r : repeated)
  {
    of.push_back(kept.at(slotOf(static_cast<std::size_t>(r))));
  }
  return of;
}
} // namespace

StepSeries BuildSeries(const StationMatch& match,
  const ObservationSteps& steps,
  const std::vector<double>& rowValues,
  std::size_t gaugeCount)
{
  StepSeries series;
  series.Values.assign(
    steps.Times.size(), std::vector<double>(gaugeCount, std::numeric_limits<double>::quiet_NaN()));
  for (std::size_t r = 0; r < steps.StepOfRow.size(); ++r)
  {
    if (steps.StepOfRow[r] < 0)
    {
      continue;
    }
    double& slot = series.Values[static_cast<std::size_t>(steps.StepOfRow[r])]
                                [static_cast<std::size_t>(match.GaugeOfRow[r])];
    if (std::isnan(slot))
    {
      slot = rowValues[r];
    }
    else
    {
      series.RepeatedRows.push_back(static_cast<std::int32_t>(r));
    }
  }
  series.RepeatedRowOf = KeptRowsOf(series.RepeatedRows, match, steps, rowValues, gaugeCount);
  return series;
}

std::vector<MissingCodeSightings> TakeMissingValues(std::vector<double>& values,
  bool use,
  double missing)
{
  if (use && (missing == 0.0 || std::isnan(missing)))
  {
    throw InputError("MissingValue " + NumberText(missing) +
      (missing == 0.0 ? " would make every zero value (a dry step) missing"
                      : " changes nothing: NaN values are missing anyway") +
      "; give the number that marks missing values, or turn UseMissingValue off");
  }
  if (use)
  {
    std::replace(values.begin(), values.end(), missing, std::numeric_limits<double>::quiet_NaN());
  }
  // (the code met most often was the only one named: a 9999 beside two -999s was averaged without
  // a word)
  std::vector<MissingCodeSightings> seen;
  for (const double code : { -9999.0, -999.0, 9999.0, 99999.0 })
  {
    const auto first = std::find(values.begin(), values.end(), code);
    const std::size_t count = static_cast<std::size_t>(std::count(first, values.end(), code));
    if (count > 0)
    {
      seen.push_back({ code, count, static_cast<std::size_t>(first - values.begin()) });
    }
  }
  std::stable_sort(seen.begin(),
    seen.end(),
    [](const MissingCodeSightings& a, const MissingCodeSightings& b) { return a.Count > b.Count; });
  return seen;
}

} // namespace tessera
