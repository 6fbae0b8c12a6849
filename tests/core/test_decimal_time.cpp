// Decimal years on a month grid: every day of 1900-2100 (listed by the C library's gmtime, an
// independent calendar) parses, in calendar order, inside its month's twelfth, with the first of
// each month equal bit for bit to the year-and-month value; malformed and impossible dates are
// refused; and each date written back as text reads back to its time bit for bit.
#include "decimal_time.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

using tessera::DateTimeAndZone;
using tessera::IsoDateTime;
using tessera::IsoDateTimeAndZone;
using tessera::IsoDateTimeInZone;
using tessera::MonthTime;
using tessera::TimeZoneOf;
using tessera::ZonedTime;

namespace
{

struct Day
{
  int Year, Month, DayOfMonth, DaysInMonth;
  std::string Text;
};

/// Every day from 1900-01-01 to 2100-12-31 from gmtime, with its month's length counted by
/// walking the days (not from a table).
std::vector<Day> CalendarDays()
{
  std::vector<Day> days;
  std::tm start{};
  start.tm_year = 0; // 1900
  start.tm_mday = 1;
  const std::time_t first = timegm(&start);
  for (std::time_t t = first;; t += 86400)
  {
    std::tm date{};
    gmtime_r(&t, &date);
    if (date.tm_year + 1900 > 2100)
    {
      break;
    }
    char text[40];
    std::snprintf(
      text, sizeof text, "%04d-%02d-%02d", date.tm_year + 1900, date.tm_mon + 1, date.tm_mday);
    days.push_back({ date.tm_year + 1900, date.tm_mon + 1, date.tm_mday, 0, text });
  }
  for (std::size_t k = 0; k < days.size();)
  {
    std::size_t end = k;
    while (end < days.size() && days[end].Month == days[k].Month && days[end].Year == days[k].Year)
    {
      ++end;
    }
    for (std::size_t j = k; j < end; ++j)
    {
      days[j].DaysInMonth = int(end - k);
    }
    k = end;
  }
  return days;
}

} // namespace

TEST(DecimalTime, EveryDayOfTwoCenturiesIsInItsMonthAndInOrder)
{
  const std::vector<Day> days = CalendarDays();
  ASSERT_EQ(days.size(), 73414U); // 201 years, 49 of them leap (2000 is, 1900 and 2100 are not)
  double previous = -1.0;
  for (const Day& day : days)
  {
    const std::optional<double> t = IsoDateTime(day.Text);
    ASSERT_TRUE(t) << day.Text;
    const double monthStart = MonthTime(day.Year, day.Month);
    const double expected =
      day.Year + (day.Month - 1 + double(day.DayOfMonth - 1) / day.DaysInMonth) / 12.0;
    EXPECT_NEAR(*t, expected, 1e-12) << day.Text;
    EXPECT_GE(*t, monthStart) << day.Text;
    EXPECT_LT(*t, day.Month < 12 ? MonthTime(day.Year, day.Month + 1) : day.Year + 1.0) << day.Text;
    EXPECT_GT(*t, previous) << day.Text;
    previous = *t;
    if (day.DayOfMonth == 1)
    {
      // The first of a month, "YYYY-MM" and the year-and-month columns give the same step.
      EXPECT_EQ(*t, monthStart) << day.Text;
      EXPECT_EQ(IsoDateTime(day.Text.substr(0, 7)), monthStart) << day.Text;
      EXPECT_EQ(IsoDateTime(day.Text + "T00:00:00"), monthStart) << day.Text;
      // With a time zone it is not read (a series in several zones would be misordered).
      EXPECT_FALSE(IsoDateTime(day.Text + "T00:00:00Z")) << day.Text;
    }
  }
}

TEST(DecimalTime, TimesOfDayAndSpacesAndYears)
{
  EXPECT_EQ(IsoDateTime("1963"), 1963.0);
  EXPECT_EQ(IsoDateTime("  1963-08 "), MonthTime(1963, 8));
  EXPECT_NEAR(*IsoDateTime("1963-08-01T12:00"), 1963 + (7 + 0.5 / 31) / 12.0, 1e-12);
  EXPECT_NEAR(*IsoDateTime("1963-08-16 18:00:00"), 1963 + (7 + 15.75 / 31) / 12.0, 1e-12);
  EXPECT_LT(*IsoDateTime("1963-08-31T23:59:59"), MonthTime(1963, 9));
}

TEST(DecimalTime, HourTwentyFourIsTheNextDaysStart)
{
  // Hour-ending records write a day's last hour as 24:00: the next day's 00:00, bit for bit, also
  // across a month's and a year's end (where it is the next month's "YYYY-MM").
  EXPECT_EQ(IsoDateTime("1963-08-16 24:00"), IsoDateTime("1963-08-17 00:00"));
  EXPECT_EQ(IsoDateTime("1963-08-01T24:00:00"), IsoDateTime("1963-08-02"));
  EXPECT_EQ(IsoDateTime("1963-08-31 24:00"), MonthTime(1963, 9));
  EXPECT_EQ(IsoDateTime("1964-02-29 24:00"), MonthTime(1964, 3));
  EXPECT_EQ(IsoDateTime("1963-12-31T24:00"), 1964.0);
  EXPECT_LT(*IsoDateTime("1963-08-16 23:59:59"), *IsoDateTime("1963-08-16 24:00"));
}

TEST(DecimalTime, TimeZonesAreNamedAndMalformedOnesAreNone)
{
  EXPECT_EQ(TimeZoneOf("1963-08-01T10:00:00Z"), std::string("Z"));
  EXPECT_EQ(TimeZoneOf(" 1963-08-01 10:00+05:00 "), std::string("+05:00"));
  EXPECT_EQ(TimeZoneOf("1963-08-01T10:00-0700"), std::string("-0700"));
  EXPECT_EQ(TimeZoneOf("1963-08-01T10:00:30+05"), std::string("+05"));
  for (const char* text : { "1963-08-01T10:00",
         "1963-08-01",
         "1963-08-01Z",
         "1963-08-01T10:00+5",
         "1963-08-01T10:00+05:0",
         "1963-08-01T10:00 Z",
         "1963-08-01T10:00ZZ",
         "1963-13-01T10:00Z",
         "1963-08-01T10:00+24:00",
         "1963-08-01T10:00-05:60",
         "abc" })
  {
    EXPECT_FALSE(TimeZoneOf(text)) << text;
    EXPECT_FALSE(IsoDateTimeInZone(text)) << text;
  }
}

TEST(DecimalTime, ATimeInAZoneIsReadAsWrittenWithTheZonesOffset)
{
  // The time is the text's without its zone, bit for bit (not moved to UTC), for every form of
  // designator; the offset says which zone, so that a caller can refuse a series in several.
  // (-00:00, RFC 3339's UTC time of an unknown local offset, is UTC's offset; z is Z.)
  const struct
  {
    const char* Zoned;
    const char* Plain;
    const char* Zone;
    int Offset;
  } cases[] = { { "1963-08-01T10:00:00Z", "1963-08-01T10:00:00", "Z", 0 },
    { " 1963-08-01 10:00+05:30 ", "1963-08-01 10:00", "+05:30", 330 },
    { "1963-08-31T24:00-0700", "1963-08-31T24:00", "-0700", -420 },
    { "2000-02-29T00:00:30+05", "2000-02-29T00:00:30", "+05", 300 },
    { "1963-08-01T10:00-00:00", "1963-08-01T10:00", "-00:00", 0 },
    { "1963-08-01T10:00z", "1963-08-01T10:00", "z", 0 },
    { "1963-12-31T23:59:59-23:59", "1963-12-31T23:59:59", "-23:59", -1439 } };
  for (const auto& c : cases)
  {
    const std::optional<ZonedTime> zoned = IsoDateTimeInZone(c.Zoned);
    ASSERT_TRUE(zoned) << c.Zoned;
    EXPECT_EQ(zoned->Time, IsoDateTime(c.Plain).value()) << c.Zoned;
    EXPECT_EQ(zoned->OffsetMinutes, c.Offset) << c.Zoned;
    EXPECT_EQ(zoned->Zone, c.Zone) << c.Zoned;
    EXPECT_EQ(TimeZoneOf(c.Zoned), std::string(c.Zone)) << c.Zoned;
  }
  const std::optional<ZonedTime> dayEnd = IsoDateTimeInZone("1963-08-01T24:00Z");
  ASSERT_TRUE(dayEnd);
  EXPECT_EQ(dayEnd->Time, IsoDateTime("1963-08-02").value());
}

TEST(DecimalTime, ADateWithOrWithoutAZoneIsReadOnceAsEachReadingReadsIt)
{
  for (const char* text : { "1963",
         " 1963-08 ",
         "1963-08-16 18:00:00",
         "1963-08-31T24:00",
         "1963-08-01T10:00:00Z",
         "1963-08-01 10:00+05:30",
         "1963-08-31T24:00-0700",
         "1963-08-01Z",
         "1963-08-01T10:00+24:00",
         "1963-08-01T10:00 Z",
         "1963-13-01",
         "abc" })
  {
    const std::optional<DateTimeAndZone> read = IsoDateTimeAndZone(text);
    const std::optional<double> plain = IsoDateTime(text);
    const std::optional<ZonedTime> zoned = IsoDateTimeInZone(text);
    ASSERT_EQ(read.has_value(), plain.has_value() || zoned.has_value()) << text;
    if (plain)
    {
      EXPECT_EQ(read->Time, *plain) << text;
      EXPECT_FALSE(read->OffsetMinutes) << text;
    }
    if (zoned)
    {
      EXPECT_EQ(read->Time, zoned->Time) << text;
      EXPECT_EQ(read->OffsetMinutes, zoned->OffsetMinutes) << text;
    }
  }
}

// The period a date is written at: a year, a month, or a day (with a time of day or without; a
// time zone's hyphen, after the time, is no date's).
TEST(DecimalTime, TheDatesPeriodIsRead)
{
  using Period = DateTimeAndZone::Period;
  for (const auto& [text, period] : { std::make_pair(" 1963 ", Period::Year),
         std::make_pair("1963-08", Period::Month),
         std::make_pair("1963-08-16", Period::Day),
         std::make_pair("1963-08-16T06:00", Period::Day),
         std::make_pair("1963-08-16 06:00-05:00", Period::Day),
         std::make_pair("1963-08-31 24:00Z", Period::Day) })
  {
    const std::optional<DateTimeAndZone> read = IsoDateTimeAndZone(text);
    ASSERT_TRUE(read) << text;
    EXPECT_EQ(read->Given, period) << text;
  }
}

TEST(DecimalTime, MalformedAndImpossibleDatesAreRefused)
{
  for (const char* text : { "",
         "abc",
         "63-08",
         "1963-8",
         "1963/08",
         "1963-13",
         "1963-00",
         "1963-08-00",
         "1963-08-32",
         "1963-09-31",
         "1963-02-29",
         "1900-02-29",
         "2100-02-29",
         "1963-08-01T24:01",
         "1963-08-01T24:00:01",
         "1963-08-01T25:00",
         "1963-08-01T12:00Z",
         "1963-08-01T12:00+05:00",
         "1963-08-01T12",
         "1963-08-01T12:60",
         "1963-08-01 12:00:60",
         "1963-08-01x",
         "1963-08T12:00",
         "1963T12:00",
         "1963-08-",
         "19630801" })
  {
    EXPECT_FALSE(IsoDateTime(text)) << text;
  }
  EXPECT_TRUE(IsoDateTime("2000-02-29"));
  EXPECT_TRUE(IsoDateTime("1964-02-29"));
}

// Written back as text: every day of the two centuries at a time of day from a random stream
// (gmtime's calendar again), and the day's start, each reads back to its time bit for bit, at
// the one resolution the series needs.
TEST(DecimalTime, DatesAreWrittenBackToTheirTimesBitForBit)
{
  const std::vector<Day> days = CalendarDays();
  std::vector<double> starts, times;
  std::vector<std::string> clocks;
  std::uint64_t state = 12345;
  for (const Day& day : days)
  {
    starts.push_back(*IsoDateTime(day.Text));
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const int seconds = static_cast<int>((state >> 33) % 86400);
    char clock[16];
    std::snprintf(
      clock, sizeof clock, " %02d:%02d:%02d", seconds / 3600, seconds / 60 % 60, seconds % 60);
    clocks.push_back(day.Text + clock);
    times.push_back(*IsoDateTime(clocks.back()));
  }
  const std::vector<std::string> dayTexts = tessera::DateTexts(starts);
  const std::vector<std::string> clockTexts = tessera::DateTexts(times);
  ASSERT_EQ(dayTexts.size(), days.size());
  ASSERT_EQ(clockTexts.size(), days.size());
  for (std::size_t k = 0; k < days.size(); ++k)
  {
    ASSERT_EQ(dayTexts[k], days[k].Text);
    ASSERT_EQ(clockTexts[k], clocks[k]);
    ASSERT_EQ(IsoDateTime(clockTexts[k]), times[k]) << clockTexts[k];
  }
}

TEST(DecimalTime, DatesAreWrittenAtTheFinestResolutionTheSeriesNeeds)
{
  using tessera::DateTexts;
  using Texts = std::vector<std::string>;
  EXPECT_EQ(DateTexts({ 1963.0, 1964.0, *IsoDateTime("1965") }), (Texts{ "1963", "1964", "1965" }));
  EXPECT_EQ(DateTexts({ MonthTime(1963, 8), MonthTime(1963, 9), 1964.0 }),
    (Texts{ "1963-08", "1963-09", "1964-01" }));
  EXPECT_EQ(DateTexts({ MonthTime(1963, 8), *IsoDateTime("1963-08-16") }),
    (Texts{ "1963-08-01", "1963-08-16" }));
  EXPECT_EQ(DateTexts({ MonthTime(1963, 8), *IsoDateTime("1963-08-16T06:30") }),
    (Texts{ "1963-08-01 00:00", "1963-08-16 06:30" }));
  EXPECT_EQ(DateTexts({ *IsoDateTime("1963-08-16 23:59:59"), *IsoDateTime("1963-08-16 24:00") }),
    (Texts{ "1963-08-16 23:59:59", "1963-08-17 00:00:00" }));
  EXPECT_EQ(DateTexts({ *IsoDateTime("1963-12-31 24:00") }), (Texts{ "1964" }));
  EXPECT_EQ(DateTexts({ *IsoDateTime("1963-12-31 24:00"), MonthTime(1964, 2) }),
    (Texts{ "1964-01", "1964-02" }));
  // The first and last years written: 0 and 9999 (their last second; its 24:00 is year 10000).
  EXPECT_EQ(
    DateTexts({ 0.0, *IsoDateTime("0000-02-29 12:00"), *IsoDateTime("9999-12-31 23:59:59") }),
    (Texts{ "0000-01-01 00:00:00", "0000-02-29 12:00:00", "9999-12-31 23:59:59" }));
  EXPECT_EQ(DateTexts({}), Texts{});
}

TEST(DecimalTime, TimesThatAreNoDatesGetNoTexts)
{
  using tessera::DateTexts;
  // A time between two whole seconds, outside years 0 .. 9999, or not finite: none of the
  // series is written (it was given as numbers).
  for (const double time : { 1963.123456789, -0.5, 10000.0, std::nan(""), HUGE_VAL })
  {
    EXPECT_TRUE(DateTexts({ MonthTime(1963, 8), time }).empty()) << time;
  }
  // Half a second into a day, one ulp beside a day's start: no whole second gives them.
  const double start = *IsoDateTime("1963-08-16");
  EXPECT_TRUE(DateTexts({ start + 0.5 / 86400 / 31 / 12 }).empty());
  EXPECT_TRUE(DateTexts({ std::nextafter(start, 2000.0) }).empty());
  EXPECT_EQ(DateTexts({ start }), std::vector<std::string>{ "1963-08-16" });
}
