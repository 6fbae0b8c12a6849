// Observation rows matched with gauges and assembled into step x gauge values
// (observation_series.h): station keys with leading zeros, ids no gauge has, ids shared by several
// gauges, rows without a station id or a time, repeated rows, and steps sorted and distinct. Small
// cases are checked against values written out by hand; random tables against a brute-force
// reading of the rules (integer ids compared as numbers, every row against every earlier row).
#include "errors.h"
#include "observation_series.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using tessera::BuildSeries;
using tessera::InputError;
using tessera::MatchStations;
using tessera::MissingCodeSightings;
using tessera::StationKey;
using tessera::StepsOfRows;
using tessera::TakeMissingValues;

namespace
{

using Rows = std::vector<std::int32_t>;
const double NaN = std::numeric_limits<double>::quiet_NaN();

/// Values equal, NaN equal to NaN.
bool SameValues(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    if (!(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k]))))
    {
      return false;
    }
  }
  return true;
}

TEST(ObservationSeries, StationKeyDropsLeadingZerosOfIntegerIdsOnly)
{
  EXPECT_EQ(StationKey("050109"), "50109");
  EXPECT_EQ(StationKey("50109"), "50109");
  EXPECT_EQ(StationKey("000"), "0");
  EXPECT_EQ(StationKey("0"), "0");
  EXPECT_EQ(StationKey(""), "");
  EXPECT_EQ(StationKey("007A"), "007A"); // not an integer: as written
  EXPECT_EQ(StationKey("-07"), "-07");
  // A whole number written with a point and zeros is that integer; other decimals as written.
  EXPECT_EQ(StationKey("07.0"), "7");
  EXPECT_EQ(StationKey("050109.000"), "50109");
  EXPECT_EQ(StationKey("102."), "102");
  EXPECT_EQ(StationKey("0102,00"), "102"); // (decimal comma)
  EXPECT_EQ(StationKey("7,5"), "7,5");
  EXPECT_EQ(StationKey("7.,0"), "7.,0");
  EXPECT_EQ(StationKey("0.0"), "0");
  EXPECT_EQ(StationKey("7.01"), "7.01");
  EXPECT_EQ(StationKey("7.0.0"), "7.0.0");
  EXPECT_EQ(StationKey(".0"), ".0");
  EXPECT_EQ(StationKey("A7.0"), "A7.0");
  EXPECT_EQ(StationKey("-7.0"), "-7.0");
  EXPECT_EQ(StationKey("7.0 "), "7.0 ");
  EXPECT_EQ(StationKey(" 07"), " 07");
  EXPECT_EQ(StationKey("0730020000000000000001"), "730020000000000000001"); // beyond 64 bits
}

TEST(ObservationSeries, IdsWithLeadingZerosMatchTheSameNumber)
{
  const std::vector<std::string> gauges = { "050109", "A01", "0", "7" };
  const std::vector<std::string> rows = {
    "50109", "0050109", "A1", "A01", "000", "07", "+7", "7.0", "7.5", "50109.00"
  };
  const tessera::StationMatch match = MatchStations(gauges, rows);
  EXPECT_EQ(match.GaugeOfRow, (Rows{ 0, 0, -1, 1, 2, 3, -1, 3, -1, 0 }));
  ASSERT_EQ(match.UnknownStations.size(), 3u); // A1, +7, 7.5: one row each
  EXPECT_EQ(match.UnknownStations[0].FirstRow, 2);
  EXPECT_EQ(match.UnknownStations[1].FirstRow, 6);
  EXPECT_EQ(match.UnknownStations[2].FirstRow, 8);
  for (const tessera::UnknownStation& station : match.UnknownStations)
  {
    EXPECT_EQ(station.Rows, 1);
  }
  EXPECT_TRUE(match.RowsWithoutStation.empty());
  EXPECT_TRUE(match.SharedStations.empty());
}

TEST(ObservationSeries, UnknownStationsAreTalliedByKeyInTheOrderFirstMet)
{
  const std::vector<std::string> rows = { "x", "a", "y", "007", "x", "", "7", "y", "y" };
  const tessera::StationMatch match = MatchStations({ "a" }, rows);
  EXPECT_EQ(match.GaugeOfRow, (Rows{ -1, 0, -1, -1, -1, -1, -1, -1, -1 }));
  EXPECT_EQ(match.RowsWithoutStation, (Rows{ 5 }));
  ASSERT_EQ(match.UnknownStations.size(), 3u);
  const std::int32_t expected[3][2] = { { 0, 2 }, { 2, 3 }, { 3, 2 } }; // x, y, 007 (and 7)
  for (std::size_t k = 0; k < 3; ++k)
  {
    EXPECT_EQ(match.UnknownStations[k].FirstRow, expected[k][0]) << k;
    EXPECT_EQ(match.UnknownStations[k].Rows, expected[k][1]) << k;
  }
  // Their rows are not used, whatever times they hold, and make no step.
  std::vector<std::optional<double>> times(rows.size(), 2000.0);
  times[1] = 1990.0;
  const tessera::ObservationSteps steps = StepsOfRows(match, times);
  EXPECT_EQ(steps.Times, (std::vector<double>{ 1990.0 }));
  EXPECT_EQ(steps.UnusedRows(), (Rows{ 0, 2, 3, 4, 5, 6, 7, 8 }));
  EXPECT_EQ(steps.IncompleteRows, (Rows{ 5 }));
}

TEST(ObservationSeries, AnIdSharedByGaugesGoesToTheFirst)
{
  const std::vector<std::string> gauges = { "a", "b", "c", "b", "07", "7", "b" };
  const tessera::StationMatch match = MatchStations(gauges, { "b", "7", "007", "c" });
  ASSERT_EQ(match.SharedStations.size(), 3u);
  const std::int32_t expected[3][2] = { { 1, 3 }, { 4, 5 }, { 1, 6 } };
  for (std::size_t k = 0; k < 3; ++k)
  {
    EXPECT_EQ(match.SharedStations[k].FirstGauge, expected[k][0]) << k;
    EXPECT_EQ(match.SharedStations[k].Gauge, expected[k][1]) << k;
  }
  EXPECT_EQ(match.GaugeOfRow, (Rows{ 1, 4, 4, 2 }));
  const tessera::ObservationSteps steps = StepsOfRows(match, { 1.0, 1.0, 2.0, 1.0 });
  const tessera::StepSeries series = BuildSeries(match, steps, { 10.0, 20.0, 30.0, 40.0 }, 7);
  ASSERT_EQ(series.Values.size(), 2u);
  EXPECT_TRUE(SameValues(series.Values[0], { NaN, 10.0, 40.0, NaN, 20.0, NaN, NaN }));
  EXPECT_TRUE(SameValues(series.Values[1], { NaN, NaN, NaN, NaN, 30.0, NaN, NaN }));
  EXPECT_TRUE(series.RepeatedRows.empty());
}

TEST(ObservationSeries, GaugesWithoutAStationIdShareNone)
{
  // (two gauges with NaN ids, from a numeric id column, were said to share the station id "")
  const tessera::StationMatch match = MatchStations({ "", "a", "", "a" }, { "", "a" });
  ASSERT_EQ(match.SharedStations.size(), 1u);
  EXPECT_EQ(match.SharedStations[0].FirstGauge, 1);
  EXPECT_EQ(match.SharedStations[0].Gauge, 3);
  EXPECT_EQ(match.GaugeOfRow, (Rows{ -1, 1 }));
  EXPECT_EQ(match.RowsWithoutStation, (Rows{ 0 }));
}

TEST(ObservationSeries, RowsWithoutStationOrTimeAreIncompleteAndMakeNoStep)
{
  const std::vector<std::string> rows = { "a", "", "b", "c", "a", "", "b" };
  const tessera::StationMatch match = MatchStations({ "a", "b" }, rows);
  EXPECT_EQ(match.RowsWithoutStation, (Rows{ 1, 5 }));
  // Only the rows of a gauge's station are looked at: the others' times make no step.
  const tessera::ObservationSteps steps =
    StepsOfRows(match, { 2001.0, 1999.0, std::nullopt, 1998.0, 2000.0, std::nullopt, 2001.0 });
  EXPECT_EQ(steps.Times, (std::vector<double>{ 2000.0, 2001.0 }));
  EXPECT_EQ(steps.StepOfRow, (Rows{ 1, -1, -1, -1, 0, -1, 1 }));
  EXPECT_EQ(steps.IncompleteRows, (Rows{ 1, 2, 5 })); // no station id, b without a time, none
  EXPECT_EQ(steps.UnusedRows(), (Rows{ 1, 2, 3, 5 }));
  // Their values are not looked at either.
  const tessera::StepSeries series =
    BuildSeries(match, steps, { 1.0, 99.0, 99.0, 99.0, 2.0, 99.0, 3.0 }, 2);
  ASSERT_EQ(series.Values.size(), 2u);
  EXPECT_TRUE(SameValues(series.Values[0], { 2.0, NaN }));
  EXPECT_TRUE(SameValues(series.Values[1], { 1.0, 3.0 }));
}

TEST(ObservationSeries, ARepeatedRowKeepsTheEarlierValue)
{
  // At time 1: a 10, a 11 (a repeat), b NaN, b 5 (fills the missing value), b 6 (a repeat). At
  // time 2: a NaN, a NaN (still missing: no repeat), b 7, b NaN (a repeat, though missing).
  const std::vector<std::string> rows = { "a", "a", "b", "b", "b", "a", "a", "b", "b" };
  const tessera::StationMatch match = MatchStations({ "a", "b" }, rows);
  const tessera::ObservationSteps steps =
    StepsOfRows(match, { 1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0 });
  const tessera::StepSeries series =
    BuildSeries(match, steps, { 10.0, 11.0, NaN, 5.0, 6.0, NaN, NaN, 7.0, NaN }, 2);
  ASSERT_EQ(series.Values.size(), 2u);
  EXPECT_TRUE(SameValues(series.Values[0], { 10.0, 5.0 }));
  EXPECT_TRUE(SameValues(series.Values[1], { NaN, 7.0 }));
  EXPECT_EQ(series.RepeatedRows, (Rows{ 1, 4, 8 }));
  EXPECT_EQ(series.RepeatedRowOf, (Rows{ 0, 3, 7 })); // b's first row was missing: 3 is kept
}

TEST(ObservationSeries, NoRowsNoSteps)
{
  const tessera::StationMatch match = MatchStations({ "a" }, {});
  const tessera::ObservationSteps steps = StepsOfRows(match, {});
  EXPECT_TRUE(steps.Times.empty());
  EXPECT_TRUE(steps.UnusedRows().empty());
  EXPECT_TRUE(BuildSeries(match, steps, {}, 1).Values.empty());
}

/// Brute force: whether two ids name one station, integer ids (digits only, short enough)
/// compared as numbers, others as text.
bool SameStation(const std::string& a, const std::string& b)
{
  const auto integer = [](const std::string& id)
  {
    return !id.empty() && id.size() < 19 && id.find_first_not_of("0123456789") == std::string::npos;
  };
  if (integer(a) && integer(b))
  {
    return std::stoull(a) == std::stoull(b);
  }
  return a == b;
}

TEST(ObservationSeries, RandomTablesAgreeWithABruteForceReading)
{
  const std::vector<std::string> pool = {
    "1", "01", "001", "12", "012", "0", "00", "a", "A", "b07", "b7", "x", ""
  };
  std::mt19937 random(20240611);
  for (int trial = 0; trial < 200; ++trial)
  {
    const auto pick = [&](std::size_t n)
    { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random); };
    std::vector<std::string> gauges(1 + pick(6));
    for (auto& id : gauges)
    {
      do
      {
        id = pool[pick(pool.size())];
      } while (id.empty());
    }
    const std::size_t count = pick(60);
    std::vector<std::string> ids(count);
    std::vector<std::optional<double>> times(count);
    std::vector<double> values(count);
    for (std::size_t r = 0; r < count; ++r)
    {
      ids[r] = pool[pick(pool.size())];
      if (pick(8) > 0)
      {
        times[r] = 1990.0 + static_cast<double>(pick(7)) / 4.0; // few times: many repeats
      }
      values[r] = pick(5) == 0 ? NaN : static_cast<double>(r);
    }

    const tessera::StationMatch match = MatchStations(gauges, ids);
    const tessera::ObservationSteps steps = StepsOfRows(match, times);
    const tessera::StepSeries series = BuildSeries(match, steps, values, gauges.size());

    // Each row's gauge: the first with the same station.
    std::vector<std::int32_t> gaugeOf(count, -1);
    for (std::size_t r = 0; r < count; ++r)
    {
      for (std::size_t g = 0; g < gauges.size() && gaugeOf[r] < 0 && !ids[r].empty(); ++g)
      {
        if (SameStation(ids[r], gauges[g]))
        {
          gaugeOf[r] = static_cast<std::int32_t>(g);
        }
      }
    }
    ASSERT_EQ(match.GaugeOfRow, gaugeOf) << trial;
    // The steps: the set of the used rows' times.
    std::set<double> used;
    Rows incomplete, unused;
    for (std::size_t r = 0; r < count; ++r)
    {
      if (gaugeOf[r] >= 0 && times[r])
      {
        used.insert(*times[r]);
      }
      else
      {
        unused.push_back(static_cast<std::int32_t>(r));
        if (ids[r].empty() || gaugeOf[r] >= 0)
        {
          incomplete.push_back(static_cast<std::int32_t>(r));
        }
      }
    }
    ASSERT_EQ(steps.Times, std::vector<double>(used.begin(), used.end())) << trial;
    EXPECT_EQ(steps.IncompleteRows, incomplete) << trial;
    EXPECT_EQ(steps.UnusedRows(), unused) << trial;
    for (std::size_t r = 0; r < count; ++r)
    {
      const std::int32_t step = steps.StepOfRow[r];
      ASSERT_EQ(step >= 0, gaugeOf[r] >= 0 && times[r].has_value()) << trial << " row " << r;
      if (step >= 0)
      {
        EXPECT_EQ(steps.Times[static_cast<std::size_t>(step)], *times[r]) << trial << " row " << r;
      }
    }
    // Unknown stations: one per distinct station of the rows of no gauge, first row and count.
    std::vector<std::pair<std::int32_t, std::int32_t>> unknown; // first row, rows
    for (std::size_t r = 0; r < count; ++r)
    {
      if (ids[r].empty() || gaugeOf[r] >= 0)
      {
        continue;
      }
      bool seen = false;
      for (auto& station : unknown)
      {
        if (SameStation(ids[static_cast<std::size_t>(station.first)], ids[r]))
        {
          ++station.second;
          seen = true;
          break;
        }
      }
      if (!seen)
      {
        unknown.push_back({ static_cast<std::int32_t>(r), 1 });
      }
    }
    ASSERT_EQ(match.UnknownStations.size(), unknown.size()) << trial;
    for (std::size_t k = 0; k < unknown.size(); ++k)
    {
      EXPECT_EQ(match.UnknownStations[k].FirstRow, unknown[k].first) << trial;
      EXPECT_EQ(match.UnknownStations[k].Rows, unknown[k].second) << trial;
    }
    // Shared ids: each gauge with the station of an earlier one, paired with the first such.
    std::vector<std::pair<std::int32_t, std::int32_t>> shared;
    for (std::size_t g = 0; g < gauges.size(); ++g)
    {
      for (std::size_t f = 0; f < g; ++f)
      {
        if (SameStation(gauges[f], gauges[g]))
        {
          shared.push_back({ static_cast<std::int32_t>(f), static_cast<std::int32_t>(g) });
          break;
        }
      }
    }
    ASSERT_EQ(match.SharedStations.size(), shared.size()) << trial;
    for (std::size_t k = 0; k < shared.size(); ++k)
    {
      EXPECT_EQ(match.SharedStations[k].FirstGauge, shared[k].first) << trial;
      EXPECT_EQ(match.SharedStations[k].Gauge, shared[k].second) << trial;
    }
    // Values: per step and gauge, the value of the first of its rows that has one (not NaN); a
    // row is a repeat when an earlier row of its gauge and time had one.
    Rows repeated, repeatedOf;
    ASSERT_EQ(series.Values.size(), used.size()) << trial;
    std::size_t s = 0;
    for (const double t : used)
    {
      std::vector<double> expected(gauges.size(), NaN);
      for (std::size_t r = 0; r < count; ++r)
      {
        double& slot = expected[static_cast<std::size_t>(std::max(gaugeOf[r], 0))];
        if (gaugeOf[r] >= 0 && times[r] == t && std::isnan(slot) && !std::isnan(values[r]))
        {
          slot = values[r];
        }
      }
      EXPECT_TRUE(SameValues(series.Values[s++], expected)) << trial << " time " << t;
    }
    for (std::size_t r = 0; r < count; ++r)
    {
      for (std::size_t e = 0; e < r && gaugeOf[r] >= 0 && times[r]; ++e)
      {
        if (gaugeOf[e] == gaugeOf[r] && times[e] == times[r] && !std::isnan(values[e]))
        {
          repeated.push_back(static_cast<std::int32_t>(r));
          repeatedOf.push_back(static_cast<std::int32_t>(e)); // the first with a value
          break;
        }
      }
    }
    EXPECT_EQ(series.RepeatedRows, repeated) << trial;
    EXPECT_EQ(series.RepeatedRowOf, repeatedOf) << trial;
  }
}

TEST(ObservationSeries, AMissingValueCodeIsMissingWhenUsedAndCountedWhenNot)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> given{ 1.0, -9999.0, 0.0, 9999.0, -9999.0, 2.5, nan };
  // Not used: nothing changes; -9999 (twice, first at 1), then 9999 (once, at 3): every code met,
  // the most often met first (only the first was reported, and the 9999 averaged unnamed).
  const auto sightings = [](const std::vector<MissingCodeSightings>& seen)
  {
    std::vector<std::tuple<double, std::size_t, std::size_t>> out;
    for (const MissingCodeSightings& s : seen)
    {
      out.emplace_back(s.Code, s.Count, s.First);
    }
    return out;
  };
  using Sighting = std::tuple<double, std::size_t, std::size_t>;
  std::vector<double> values = given;
  std::vector<MissingCodeSightings> seen = TakeMissingValues(values, false, -9999.0);
  EXPECT_EQ(sightings(seen), (std::vector<Sighting>{ { -9999.0, 2, 1 }, { 9999.0, 1, 3 } }));
  EXPECT_TRUE(std::equal(values.begin(), values.end() - 1, given.begin()));
  // Ties in count keep the codes' order; none met gives none.
  std::vector<double> tied{ 99999.0, 5.0, -999.0 };
  EXPECT_EQ(sightings(TakeMissingValues(tied, false, -9999.0)),
    (std::vector<Sighting>{ { -999.0, 1, 2 }, { 99999.0, 1, 0 } }));
  std::vector<double> clean{ 1.0, 2.0 };
  EXPECT_TRUE(TakeMissingValues(clean, false, -9999.0).empty());
  // Used: the -9999s are NaN, the rest as given (0 a value), and 9999, at 3, is counted.
  seen = TakeMissingValues(values, true, -9999.0);
  for (std::size_t k = 0; k < given.size(); ++k)
  {
    EXPECT_EQ(std::isnan(values[k]), given[k] == -9999.0 || std::isnan(given[k])) << k;
    if (!std::isnan(values[k]))
    {
      EXPECT_EQ(values[k], given[k]) << k;
    }
  }
  EXPECT_EQ(sightings(seen), (std::vector<Sighting>{ { 9999.0, 1, 3 } }));
  // 0 and NaN are no codes: named, before anything changes.
  for (const double missing : { 0.0, -0.0, nan })
  {
    std::vector<double> kept = given;
    try
    {
      TakeMissingValues(kept, true, missing);
      ADD_FAILURE() << "MissingValue " << missing << " accepted";
    }
    catch (const InputError& e)
    {
      EXPECT_NE(std::string(e.what()).find("MissingValue"), std::string::npos) << e.what();
    }
    EXPECT_EQ(kept[2], 0.0);
  }
}

} // namespace
