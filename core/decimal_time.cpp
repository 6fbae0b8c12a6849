// Decimal years on a month grid (decimal_time.h): parsing of ISO 8601 calendar dates, and the
// dates of such times written back as text.
#include "decimal_time.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace tessera
{
namespace
{

bool IsLeapYear(int year)
{
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

int DaysInMonth(int year, int month)
{
  static constexpr int days[12] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
  return month == 2 && IsLeapYear(year) ? 29 : days[month - 1];
}

/// Reads exactly `digits` decimal digits at text[at ..] into value; advances at.
bool ReadDigits(std::string_view text, std::size_t& at, int digits, int& value)
{
  if (at + static_cast<std::size_t>(digits) > text.size())
  {
    return false;
  }
  value = 0;
  for (int k = 0; k < digits; ++k, ++at)
  {
    const unsigned char c = static_cast<unsigned char>(text[at]);
    if (!std::isdigit(c))
    {
      return false;
    }
    value = 10 * value + (c - '0');
  }
  return true;
}

/// Consumes the character c at text[at] if it is there.
bool Skip(std::string_view text, std::size_t& at, char c)
{
  if (at < text.size() && text[at] == c)
  {
    ++at;
    return true;
  }
  return false;
}

std::string_view Trimmed(std::string_view text)
{
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
  {
    text.remove_prefix(1);
  }
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
  {
    text.remove_suffix(1);
  }
  return text;
}

/// Reads a time of day "hh:mm" or "hh:mm:ss" at text[at ..] (24:00 and 24:00:00 the day's end),
/// advancing at past it: its seconds since midnight, 86400 for the day's end.
std::optional<int> ReadTimeOfDay(std::string_view text, std::size_t& at)
{
  int hours = 0, minutes = 0, seconds = 0;
  if (!ReadDigits(text, at, 2, hours) || !Skip(text, at, ':') ||
    !ReadDigits(text, at, 2, minutes) || hours > 24 || minutes > 59)
  {
    return std::nullopt;
  }
  if (Skip(text, at, ':') && (!ReadDigits(text, at, 2, seconds) || seconds > 59))
  {
    return std::nullopt;
  }
  if (hours == 24 && (minutes != 0 || seconds != 0))
  {
    return std::nullopt;
  }
  return 3600 * hours + 60 * minutes + seconds;
}

/// Reads a calendar date "YYYY", "YYYY-MM" or "YYYY-MM-DD" at the start of text, advancing at
/// past it; false when it is none.
bool ReadDate(std::string_view text, std::size_t& at, int& year, int& month, int& day)
{
  year = 0, month = 1, day = 1;
  if (!ReadDigits(text, at, 4, year))
  {
    return false;
  }
  if (Skip(text, at, '-') && (!ReadDigits(text, at, 2, month) || month < 1 || month > 12))
  {
    return false;
  }
  return !(at > 4 && Skip(text, at, '-') &&
    (!ReadDigits(text, at, 2, day) || day < 1 || day > DaysInMonth(year, month)));
}

/// Whether text[at] starts a time of day after a full date (at 10): "T" or a space.
bool AtTimeOfDay(std::string_view text, std::size_t at)
{
  return at == 10 && at < text.size() && (text[at] == 'T' || text[at] == ' ');
}

/// The offset from UTC in minutes of a time zone designator: "Z" or "z" (0), or a sign and hh,
/// hhmm or hh:mm (hours to 23, minutes to 59; "-00:00", RFC 3339's UTC time of an unknown local
/// offset, is 0 too); nothing for any other text.
std::optional<int> ZoneOffsetMinutes(std::string_view text)
{
  if (text == "Z" || text == "z")
  {
    return 0;
  }
  std::size_t at = 0;
  int hours = 0, minutes = 0;
  const bool west = Skip(text, at, '-');
  if (!(west || Skip(text, at, '+')) || !ReadDigits(text, at, 2, hours) || hours > 23)
  {
    return std::nullopt;
  }
  if (at < text.size())
  {
    Skip(text, at, ':');
    if (!ReadDigits(text, at, 2, minutes) || minutes > 59 || at != text.size())
    {
      return std::nullopt;
    }
  }
  const int offset = 60 * hours + minutes;
  return west ? -offset : offset;
}

/// A calendar date at the start of text (spaces around it aside), with the time of day that may
/// follow a full date ("T" or a space, then ReadTimeOfDay's), and what is left after them.
struct DateTimeRead
{
  int Year = 0, Month = 1, Day = 1;
  int Seconds = 0;      ///< into the day (86400 for 24:00)
  bool HasTime = false; ///< a time of day was read
  DateTimeAndZone::Period Given = DateTimeAndZone::Period::Day;
  std::string_view Rest;
};

std::optional<DateTimeRead> ReadDateTime(std::string_view text)
{
  text = Trimmed(text);
  std::size_t at = 0;
  DateTimeRead read;
  if (!ReadDate(text, at, read.Year, read.Month, read.Day))
  {
    return std::nullopt;
  }
  // ("YYYY" ends at 4, "YYYY-MM" at 7, "YYYY-MM-DD" at 10)
  read.Given = at == 4 ? DateTimeAndZone::Period::Year
    : at == 7          ? DateTimeAndZone::Period::Month
                       : DateTimeAndZone::Period::Day;
  if (AtTimeOfDay(text, at))
  {
    ++at;
    const std::optional<int> seconds = ReadTimeOfDay(text, at);
    if (!seconds)
    {
      return std::nullopt;
    }
    read.Seconds = *seconds;
    read.HasTime = true;
  }
  read.Rest = text.substr(at);
  return read;
}

/// The time of a date and a time of day, seconds into the day (86400 for 24:00).
double TimeOfDate(int year, int month, int day, int seconds)
{
  if (seconds == 0 && day == 1)
  {
    return MonthTime(year, month); // bit for bit the value of the year and month columns
  }
  // (24:00 of a month's last day: intoMonth is 1 exactly, the next month's start bit for bit)
  const double intoMonth = (day - 1 + seconds / 86400.0) / DaysInMonth(year, month);
  return year + (month - 1 + intoMonth) / 12.0;
}

/// A date and a time of day, in seconds (below 86400).
struct CalendarTime
{
  int Year = 0, Month = 1, Day = 1, Seconds = 0;
};

/// The whole second whose TimeOfDate is time exactly, found by inverting the month grid and then
/// trying the months and seconds beside the estimate (the estimate's rounding can be a second
/// or a month boundary off); nothing when none is.
std::optional<CalendarTime> CalendarTimeOf(double time)
{
  if (!(time >= 0.0 && time < 10000.0))
  {
    return std::nullopt;
  }
  const int year = static_cast<int>(std::floor(time));
  const double months = (time - year) * 12.0; // (time - year is exact)
  const int estimate = static_cast<int>(std::floor(months)) + 1;
  for (int month = std::max(1, estimate - 1); month <= std::min(12, estimate + 1); ++month)
  {
    const int days = DaysInMonth(year, month);
    const double seconds = std::round((months - (month - 1)) * days * 86400.0);
    for (double s = seconds - 2; s <= seconds + 2; ++s)
    {
      if (s < 0 || s >= days * 86400.0)
      {
        continue;
      }
      const CalendarTime at{
        year, month, static_cast<int>(s / 86400) + 1, static_cast<int>(std::fmod(s, 86400.0))
      };
      if (TimeOfDate(at.Year, at.Month, at.Day, at.Seconds) == time)
      {
        return at;
      }
    }
  }
  return std::nullopt;
}

/// How finely a date must be written: 0 its year, 1 its month, 2 its day, 3 its minute, 4 its
/// second.
int ResolutionOf(const CalendarTime& at)
{
  if (at.Seconds % 60 != 0)
  {
    return 4;
  }
  if (at.Seconds != 0)
  {
    return 3;
  }
  if (at.Day != 1)
  {
    return 2;
  }
  return at.Month != 1 ? 1 : 0;
}

/// The date as text, cut to its first fields: "YYYY-MM-DD hh:mm:ss" up to the resolution's.
std::string DateText(const CalendarTime& at, int resolution)
{
  static constexpr std::size_t Lengths[] = { 4, 7, 10, 16, 19 }; // YYYY, -MM, -DD, hh:mm, :ss
  char text[32];
  std::snprintf(text,
    sizeof text,
    "%04d-%02d-%02d %02d:%02d:%02d",
    at.Year,
    at.Month,
    at.Day,
    at.Seconds / 3600,
    at.Seconds / 60 % 60,
    at.Seconds % 60);
  return std::string(text, Lengths[resolution]);
}

} // namespace

double MonthTime(double year, int month)
{
  return year + (month - 1) / 12.0;
}

std::vector<std::string> DateTexts(const std::vector<double>& times)
{
  std::vector<CalendarTime> dates;
  dates.reserve(times.size());
  int resolution = 0;
  for (const double time : times)
  {
    const std::optional<CalendarTime> at = CalendarTimeOf(time);
    if (!at)
    {
      return {};
    }
    dates.push_back(*at);
    resolution = std::max(resolution, ResolutionOf(*at));
  }
  std::vector<std::string> texts;
  texts.reserve(dates.size());
  for (const CalendarTime& at : dates)
  {
    texts.push_back(DateText(at, resolution));
  }
  return texts;
}

std::optional<double> IsoDateTime(std::string_view text)
{
  const std::optional<DateTimeAndZone> read = IsoDateTimeAndZone(text);
  if (!read || read->OffsetMinutes)
  {
    return std::nullopt; // (not a date, or one with a time zone)
  }
  return read->Time;
}

std::optional<std::string> TimeZoneOf(std::string_view text)
{
  const std::optional<ZonedTime> zoned = IsoDateTimeInZone(text);
  if (!zoned)
  {
    return std::nullopt;
  }
  return zoned->Zone;
}

std::optional<ZonedTime> IsoDateTimeInZone(std::string_view text)
{
  const std::optional<DateTimeRead> read = ReadDateTime(text);
  if (!read || !read->HasTime)
  {
    return std::nullopt;
  }
  const std::optional<int> offset = ZoneOffsetMinutes(read->Rest);
  if (!offset)
  {
    return std::nullopt;
  }
  return ZonedTime{
    TimeOfDate(read->Year, read->Month, read->Day, read->Seconds), *offset, std::string(read->Rest)
  };
}

std::optional<DateTimeAndZone> IsoDateTimeAndZone(std::string_view text)
{
  const std::optional<DateTimeRead> read = ReadDateTime(text);
  if (!read)
  {
    return std::nullopt;
  }
  DateTimeAndZone out;
  if (!read->Rest.empty())
  {
    out.OffsetMinutes = read->HasTime ? ZoneOffsetMinutes(read->Rest) : std::nullopt;
    if (!out.OffsetMinutes)
    {
      return std::nullopt; // (something after the date that is no zone)
    }
  }
  out.Time = TimeOfDate(read->Year, read->Month, read->Day, read->Seconds);
  out.Given = read->Given;
  return out;
}

} // namespace tessera
