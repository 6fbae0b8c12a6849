#pragma once
// Calendar dates as the time values of the areal average: decimal years on a month grid. A month
// is a twelfth of its year whatever its length, and a day a share of its month, so that
//
//   1963-08  ->  1963 + 7/12            (the same value as year 1963 with month 8)
//   1963-08-16  ->  1963 + (7 + 15/31) / 12
//
// Monthly series given as year and month columns, as "YYYY-MM" text or as the first day of each
// month therefore land on the same steps, and daily series stay in calendar order.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tessera
{

/// year + (month - 1) / 12, month in 1 .. 12 (not checked).
double MonthTime(double year, int month);

/// The time of an ISO 8601 calendar date "YYYY", "YYYY-MM" or "YYYY-MM-DD", optionally followed by
/// a time of day ("T" or a space, then "hh:mm" or "hh:mm:ss"), with spaces around it ignored;
/// nothing when the text is not such a date (a month outside 1 .. 12, a day beyond its month, an
/// hour beyond 24, ...). "24:00" ends its day: the time of the next day's "00:00", as hour-ending
/// records write a day's last hour (and as the example script reads hours; it reads a daily file
/// whose every time is 24:00 as the days they end, which one text cannot tell). A time with a
/// time zone ("Z", "+05:00") is not read here (IsoDateTimeInZone reads it): times are taken as
/// they are written, so one series in several zones would be misordered without a word.
std::optional<double> IsoDateTime(std::string_view text);

/// The calendar dates of times that IsoDateTime (or MonthTime with a whole year) gave, as text
/// that IsoDateTime reads back to each time bit for bit, all at one resolution: the finest that
/// any of them needs, "YYYY" (each a year's start), "YYYY-MM" (a month's), "YYYY-MM-DD",
/// "YYYY-MM-DD hh:mm" or "YYYY-MM-DD hh:mm:ss" (a time of 24:00 was read as the next day's 00:00,
/// and is written so).
/// Empty when a time is no such date: not a whole second of a year 0 .. 9999 (a time given as a
/// plain number, say), so that a table gets dates only for a series that was given as dates.
std::vector<std::string> DateTexts(const std::vector<double>& times);

/// The time zone that a date and time of day ends with ("Z", "+05:00", "-0700", "+05"), which
/// IsoDateTime does not read; nothing for any other text.
std::optional<std::string> TimeZoneOf(std::string_view text);

/// A date and time of day read with the time zone it ends with (TimeZoneOf's).
struct ZonedTime
{
  double Time = 0.0;     ///< IsoDateTime's time of the text without its zone: as written
  int OffsetMinutes = 0; ///< the zone's offset from UTC ("Z", "z", "-00:00" 0, "-0700" -420)
  std::string Zone;      ///< as written
};

/// The time of a date and time of day that ends with a time zone, as written (not moved to UTC),
/// and the zone's offset: a series whose times all carry one offset ("Z" on every row, say, or
/// "Z" on some and "+00:00" on others) is read in that zone, as a series without zones is read in
/// its own. Mixing offsets, or times with a zone and without, is for the caller to refuse.
/// Nothing for text without a zone (or with an offset beyond 23:59).
std::optional<ZonedTime> IsoDateTimeInZone(std::string_view text);

/// A date read once whether or not a time zone ends it, for a caller that takes both kinds (the
/// areal-average filter, at every row of a series): IsoDateTime's time without one, or
/// IsoDateTimeInZone's time and offset with one.
struct DateTimeAndZone
{
  /// The period a date names: "1963" a year, "1963-08" a month, "1963-08-16" (with a time of day
  /// or without) a day.
  enum class Period
  {
    Year,
    Month,
    Day
  };
  double Time = 0.0;
  std::optional<int> OffsetMinutes; ///< nothing without a zone
  Period Given = Period::Day;       ///< the period the date was written at
};

/// IsoDateTime's reading of text, or IsoDateTimeInZone's; nothing where both give nothing.
std::optional<DateTimeAndZone> IsoDateTimeAndZone(std::string_view text);

} // namespace tessera
