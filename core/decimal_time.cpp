// Decimal years on a month grid (decimal_time.h): parsing of ISO 8601 calendar dates.
#include "decimal_time.h"

#include <cctype>

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

/// Whether text is a time zone designator: "Z", or a sign and hh, hhmm or hh:mm.
bool IsZoneDesignator(std::string_view text)
{
  if (text == "Z")
  {
    return true;
  }
  std::size_t at = 0;
  int hours = 0, minutes = 0;
  if (!(Skip(text, at, '+') || Skip(text, at, '-')) || !ReadDigits(text, at, 2, hours))
  {
    return false;
  }
  if (at == text.size())
  {
    return true;
  }
  Skip(text, at, ':');
  return ReadDigits(text, at, 2, minutes) && at == text.size();
}

/// A calendar date at the start of text (spaces around it aside), with the time of day that may
/// follow a full date ("T" or a space, then ReadTimeOfDay's), and what is left after them.
struct DateTimeRead
{
  int Year = 0, Month = 1, Day = 1;
  int Seconds = 0;      ///< into the day (86400 for 24:00)
  bool HasTime = false; ///< a time of day was read
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

} // namespace

double MonthTime(double year, int month)
{
  return year + (month - 1) / 12.0;
}

std::optional<double> IsoDateTime(std::string_view text)
{
  const std::optional<DateTimeRead> read = ReadDateTime(text);
  if (!read || !read->Rest.empty())
  {
    return std::nullopt; // (not a date, or something after it: a time zone, say)
  }
  const int year = read->Year, month = read->Month, day = read->Day, seconds = read->Seconds;
  if (seconds == 0 && day == 1)
  {
    return MonthTime(year, month); // bit for bit the value of the year and month columns
  }
  // (24:00 of a month's last day: intoMonth is 1 exactly, the next month's start bit for bit)
  const double intoMonth = (day - 1 + seconds / 86400.0) / DaysInMonth(year, month);
  return year + (month - 1 + intoMonth) / 12.0;
}

std::optional<std::string> TimeZoneOf(std::string_view text)
{
  const std::optional<DateTimeRead> read = ReadDateTime(text);
  if (!read || !read->HasTime || !IsZoneDesignator(read->Rest))
  {
    return std::nullopt;
  }
  return std::string(read->Rest);
}

} // namespace tessera
