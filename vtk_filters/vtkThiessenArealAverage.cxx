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
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkExecutive.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVariant.h"

#include "TesseraFilterUtilities.h"
#include "areal_average.h"
#include "decimal_time.h"
#include "errors.h"
#include "observation_series.h"

#include <algorithm>
#include <functional>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

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

/// A station id as text, trimmed; empty for NaN (what a reader may make of an empty field).
std::string StationName(const vtkVariant& value)
{
  if (value.IsChar() || value.IsSignedChar())
  {
    // Numbers, as numpy's int8 makes them (vtkCharArray), not characters: ToString() gave 'A'
    // for 65, which then matched no observation's 65.
    return std::to_string(value.ToInt());
  }
  if (!(value.IsFloat() || value.IsDouble()))
  {
    return Trimmed(value.ToString(), " \t\"");
  }
  // A floating-point id (a CSV reader's numeric column) in full: ToString() keeps 6 digits, which
  // made USGS-style ids such as 06730200 and 06730500 one station.
  const double number = value.ToDouble();
  if (std::isnan(number))
  {
    return std::string();
  }
  const bool integral = std::isfinite(number) && number == std::floor(number) &&
    std::fabs(number) < 9007199254740992.0; // 2^53: every such double is an exact integer
  if (integral)
  {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.0f", number);
    return digits;
  }
  return tessera::NumberText(number);
}

using tessera_vtk::ListNames;

/// The names of a table's columns or of point data's arrays, for messages: "a, b, c", or "none".
std::string ArrayNames(vtkFieldData* data)
{
  const std::string names = ListNames(static_cast<std::size_t>(data->GetNumberOfArrays()),
    [data](std::size_t a)
    {
      const char* name = data->GetArrayName(static_cast<int>(a));
      return std::string(name ? name : "(unnamed)");
    });
  return names.empty() ? "none" : names;
}

/// The column of the observations table, or an InputError naming it, the property that names it
/// and what it should hold, and the columns the table has (the usual mistake is a name).
vtkAbstractArray* ObservationColumn(vtkTable* table,
  const std::string& column,
  const char* property,
  const char* holds)
{
  vtkAbstractArray* array = table->GetColumnByName(column.c_str());
  if (!array)
  {
    throw tessera::InputError("the observations table has no column '" + column + "' (" + property +
      ": " + holds + "); its columns are " + ArrayNames(table->GetRowData()));
  }
  if (array->GetNumberOfComponents() != 1)
  {
    throw tessera::InputError("the observations table's column '" + column + "' (" + property +
      ": " + holds + ") has " + std::to_string(array->GetNumberOfComponents()) +
      " components, where one value a row is read");
  }
  return array;
}

/// An InputError when the observations table's columns differ in length: the table's rows are its
/// first column's, and a shorter column was read past its end (garbage means, or a crash for
/// text), a longer one's rows beyond them left out without a word.
void CheckColumnLengths(vtkTable* table)
{
  const vtkIdType rows = table->GetNumberOfRows();
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    vtkAbstractArray* column = table->GetColumn(c);
    if (column && column->GetNumberOfTuples() != rows)
    {
      throw tessera::InputError("the observations table's columns differ in length: column " +
        tessera_vtk::ArrayLabel(column) + " has " + std::to_string(column->GetNumberOfTuples()) +
        " value(s), the first column, " + tessera_vtk::ArrayLabel(table->GetColumn(0)) + ", " +
        std::to_string(rows));
    }
  }
}

/// The station id of a row of the observations table's station column, as written (StationName).
std::string RowStation(vtkAbstractArray* stations, std::size_t row)
{
  return StationName(stations->GetVariantValue(static_cast<vtkIdType>(row)));
}

/// A row of the observations table in a warning's list: "row R (station S)".
std::string RowName(vtkAbstractArray* stations, std::int32_t row)
{
  return "row " + std::to_string(row) + " (station " +
    RowStation(stations, static_cast<std::size_t>(row)) + ")";
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
  /// A cell, read once: a text column's text, or a numeric column's number.
  struct Cell
  {
    std::optional<std::string> Text; ///< a text column's (and only then)
    double Value = 0.0;              ///< a numeric column's

    /// Blank text, or NaN (what a reader may make of an empty numeric field).
    bool IsEmpty() const
    {
      return this->Text ? Trimmed(*this->Text).empty() : std::isnan(this->Value);
    }

    /// The number; nothing for text that is not one (spaces around it are allowed).
    std::optional<double> Number() const
    {
      if (!this->Text)
      {
        return this->Value;
      }
      const std::string text = Trimmed(*this->Text);
      // (strtod also reads hexadecimal, "0x10" as 16: no data file means that)
      if (text.find_first_of("xX") != std::string::npos)
      {
        return std::nullopt;
      }
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size())
      {
        return std::nullopt;
      }
      return value;
    }
  };

  explicit NumberColumn(vtkAbstractArray* array)
    : Array(array)
    , Numbers(vtkDataArray::SafeDownCast(array))
  {
  }

  Cell Read(vtkIdType row) const
  {
    Cell cell;
    if (this->Numbers)
    {
      cell.Value = this->Numbers->GetTuple1(row);
    }
    else
    {
      cell.Text = this->Text(row);
    }
    return cell;
  }

  /// The row as text (for messages).
  std::string Text(vtkIdType row) const { return this->Array->GetVariantValue(row).ToString(); }

private:
  vtkAbstractArray* Array;
  vtkDataArray* Numbers;
};

/// text in lower case (ASCII letters).
std::string LowerCase(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return text;
}

/// Whether text marks a missing value: empty, NA, N/A, NaN or null (any case, spaces around).
bool IsMissingMarker(const std::string& text)
{
  const std::string lower = LowerCase(Trimmed(text));
  return lower.empty() || lower == "na" || lower == "n/a" || lower == "nan" || lower == "null";
}

/// Reads a row's time (decimal_time.h): the time column's number, its text as an ISO date (YYYY,
/// YYYY-MM, YYYY-MM-DD, optionally with a time of day), or, with a month column, the time column's
/// year plus the month's twelfth.
class RowTimeReader
{
public:
  RowTimeReader(vtkTable* table, const std::string& timeColumn, const std::string& monthColumn)
    : TimeColumn(timeColumn)
    , MonthColumn(monthColumn)
    , Times(ObservationColumn(table,
        timeColumn,
        "TimeColumn",
        monthColumn.empty() ? "numbers, or dates as text such as 1963-08 or 1963-08-16" : "years"))
  {
    if (!monthColumn.empty())
    {
      this->Months.emplace(ObservationColumn(table, monthColumn, "MonthColumn", "months 1 .. 12"));
    }
  }

  /// Whether every time read so far was a calendar date (text, or a year with a month column),
  /// none a plain number: the tables then get a Date column.
  bool AllDates() const { return this->OnlyDates; }

  /// The warning for dates read at different periods, a year or a month beside finer dates
  /// (monthly totals among daily values, say), which the steps would mix: each date is taken as
  /// its period's start, so 2020-03 shares the step of 2020-03-01. Empty where the dates keep to
  /// one period; days and times of day count as one (midnight written as the date alone is
  /// common in hourly files).
  std::string MixedPeriodsWarning() const
  {
    static const char* const names[] = { "a year", "a month", "a day" };
    std::vector<std::size_t> seen;
    for (std::size_t p = 0; p < Periods; ++p)
    {
      if (this->FirstRowOfPeriod[p] >= 0)
      {
        seen.push_back(p);
      }
    }
    if (seen.size() < 2)
    {
      return std::string();
    }
    std::string firsts;
    for (const std::size_t p : seen)
    {
      firsts += std::string(firsts.empty() ? "" : ", ") + "row " +
        std::to_string(this->FirstRowOfPeriod[p]) + "'s '" + this->FirstTextOfPeriod[p] + "' " +
        names[p];
    }
    const std::size_t coarse = seen.front(), fine = seen.back();
    return "column '" + this->TimeColumn + "' gives dates of different periods (" + firsts +
      "): each date is taken as its period's start (a month as its first day at 00:00, a year as "
      "1 January), so a value for " +
      names[coarse] + " shares a step with the values of its first " +
      (fine == 2 ? "day" : "month") +
      "; give every date at one period (a total of months for a monthly series, say)";
  }

  /// The row's time; nothing when its time or month field is empty (blank text, or NaN: what a
  /// reader may make of an empty numeric field). Throws InputError naming the row for a time that
  /// is not a finite number, a date or a month 1 .. 12.
  std::optional<double> operator()(vtkIdType row) const
  {
    const NumberColumn::Cell time = this->Times.Read(row);
    if (time.IsEmpty())
    {
      return std::nullopt;
    }
    if (!this->Months)
    {
      if (time.Text)
      {
        return this->Date(row, time);
      }
      this->OnlyDates = false;
      return this->Finite(row, time);
    }
    const NumberColumn::Cell monthCell = this->Months->Read(row);
    if (monthCell.IsEmpty())
    {
      return std::nullopt;
    }
    const std::optional<double> number = time.Number();
    const double year = number.value_or(std::nan(""));
    // (a date column given as the time with a month column was "not a finite number", and a
    // year-month number such as 200001 was taken for the year 200001 without a word)
    if (!(std::fabs(year) <= 9999.0) || year != std::floor(year))
    {
      ThrowRowError(row,
        "the year '" + this->Times.Text(row) + "' in column '" + this->TimeColumn +
          "' is not a whole number of -9999 .. 9999: with a MonthColumn ('" + this->MonthColumn +
          "'), TimeColumn names a column of years such as 1963 (clear MonthColumn for dates such "
          "as 1963-08 or times as numbers)");
    }
    const double month = monthCell.Number().value_or(0.0);
    if (!(month >= 1.0 && month <= 12.0 && month == std::floor(month)))
    {
      ThrowRowError(row,
        "the month " + this->Months->Text(row) + " in column '" + this->MonthColumn +
          "' is not 1 .. 12");
    }
    return tessera::MonthTime(year, static_cast<int>(month));
  }

private:
  /// The time cell's number, or an error naming the row when it is not a finite number.
  double Finite(vtkIdType row, const NumberColumn::Cell& time) const
  {
    const std::optional<double> t = time.Number();
    if (!t || !std::isfinite(*t))
    {
      ThrowRowError(row,
        "the time '" + this->Times.Text(row) + "' in column '" + this->TimeColumn +
          "' is not a finite number");
    }
    return *t;
  }

  /// A text time: an ISO date (with the series' time zone, where its dates carry one), or else a
  /// number (a numeric column read as text, as ParaView's CSV reader gives it with Detect Numeric
  /// Columns off, which the README advises for files with blank missing values).
  double Date(vtkIdType row, const NumberColumn::Cell& time) const
  {
    // (read once, with its zone or without: two readings had parsed every zoned date twice)
    if (const std::optional<tessera::DateTimeAndZone> t = tessera::IsoDateTimeAndZone(*time.Text))
    {
      this->CheckZone(row, *time.Text, t->OffsetMinutes);
      this->NotePeriod(row, *time.Text, t->Given);
      return t->Time;
    }
    const std::optional<double> number = time.Number();
    this->OnlyDates = false;
    if (!number || !std::isfinite(*number))
    {
      ThrowRowError(row,
        "'" + *time.Text + "' in column '" + this->TimeColumn +
          "' is not a date (YYYY, YYYY-MM or YYYY-MM-DD, optionally with hh:mm[:ss], 24:00 for "
          "the day's end, and a time zone such as Z or +01:00 of the same offset on every date) "
          "or a finite number");
    }
    return *number;
  }

  /// Refuses a date in another time zone than the first date read (a different offset, or a zone
  /// where that had none, or none where it had one), as the example script does: times are read
  /// as written, not moved to UTC, so a series in several zones would be misordered unwarned.
  void CheckZone(vtkIdType row, const std::string& text, std::optional<int> offset) const
  {
    if (this->FirstDateRow < 0)
    {
      this->FirstDateRow = row;
      this->FirstDateText = Trimmed(text);
      this->FirstOffset = offset;
      return;
    }
    if (offset == this->FirstOffset)
    {
      return;
    }
    ThrowRowError(row,
      "'" + Trimmed(text) + "' in column '" + this->TimeColumn + "' " + ZoneSaid(text) +
        ", where row " + std::to_string(this->FirstDateRow) + "'s '" + this->FirstDateText + "' " +
        ZoneSaid(this->FirstDateText) +
        ": times are read as written (not moved to UTC), so give them all in one zone, or all "
        "without one");
  }

  /// The first row of each period that a date was given at (MixedPeriodsWarning's), and its text.
  void NotePeriod(vtkIdType row,
    const std::string& text,
    tessera::DateTimeAndZone::Period given) const
  {
    const auto p = static_cast<std::size_t>(given);
    if (this->FirstRowOfPeriod[p] < 0)
    {
      this->FirstRowOfPeriod[p] = row;
      this->FirstTextOfPeriod[p] = Trimmed(text);
    }
  }

  /// "has time zone Z", or "has no time zone".
  static std::string ZoneSaid(const std::string& text)
  {
    const std::optional<std::string> zone = tessera::TimeZoneOf(text);
    return zone ? "has time zone " + *zone : "has no time zone";
  }

  std::string TimeColumn, MonthColumn;
  NumberColumn Times;
  std::optional<NumberColumn> Months;
  mutable bool OnlyDates = true;            // AllDates
  mutable vtkIdType FirstDateRow = -1;      // CheckZone's: the first date's row, text and zone
  mutable std::string FirstDateText;        //
  mutable std::optional<int> FirstOffset;   // (minutes from UTC; nothing without a zone)
  static constexpr std::size_t Periods = 3; // DateTimeAndZone::Period's (NotePeriod's)
  mutable vtkIdType FirstRowOfPeriod[Periods] = { -1, -1, -1 };
  mutable std::string FirstTextOfPeriod[Periods];
};

/// The gauges' station ids as text (StationName), one per gauge; none without an id array.
std::vector<std::string> GaugeNames(vtkAbstractArray* stationIds)
{
  std::vector<std::string> names;
  if (stationIds)
  {
    for (vtkIdType g = 0; g < stationIds->GetNumberOfTuples(); ++g)
    {
      names.push_back(StationName(stationIds->GetVariantValue(g)));
    }
  }
  return names;
}

/// The observation rows matched with the gauges and their time steps (observation_series.h).
struct ObservationRows
{
  tessera::StationMatch Match;
  tessera::ObservationSteps Steps;
  bool TimesAreDates = false;      ///< every used row's time was a calendar date (RowTimeReader)
  std::string MixedPeriodsWarning; ///< RowTimeReader's, for dates at different periods
};

/// The rows of the observations table matched with the gauges' station ids (as GaugeNames gives
/// them) and, those of a gauge's station only, read for times (ObservationRows). Throws
/// InputError for a missing column and, naming the row, for such a row's time that cannot be read.
ObservationRows ReadRows(vtkTable* table,
  const std::vector<std::string>& gaugeNames,
  const std::string& stationColumn,
  const std::string& timeColumn,
  const std::string& monthColumn)
{
  ObservationRows rows;
  const vtkIdType count = table->GetNumberOfRows();
  if (count == 0)
  {
    return rows; // no steps: Build says so, even when the columns are missing too
  }
  vtkAbstractArray* stations =
    ObservationColumn(table, stationColumn, "StationColumn", "station ids, numbers or text");
  const RowTimeReader timeOf(table, timeColumn, monthColumn);
  std::vector<std::string> rowNames(static_cast<std::size_t>(count));
  for (std::size_t r = 0; r < rowNames.size(); ++r)
  {
    rowNames[r] = RowStation(stations, r);
  }
  rows.Match = tessera::MatchStations(gaugeNames, rowNames);
  // The station first: a row of no known station is not used, whatever its time holds.
  std::vector<std::optional<double>> rowTimes(rowNames.size());
  for (std::size_t r = 0; r < rowTimes.size(); ++r)
  {
    if (rows.Match.GaugeOfRow[r] >= 0)
    {
      rowTimes[r] = timeOf(static_cast<vtkIdType>(r));
    }
  }
  rows.Steps = tessera::StepsOfRows(rows.Match, rowTimes);
  rows.TimesAreDates = timeOf.AllDates();
  rows.MixedPeriodsWarning = timeOf.MixedPeriodsWarning();
  return rows;
}

/// Whether text (spaces and tabs around it aside) is digits, one comma and digits, as a number with
/// a decimal comma reads: what a CSV file saved in a European locale holds (12,5).
bool LooksLikeDecimalComma(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t");
  const std::size_t last = text.find_last_not_of(" \t");
  if (first == std::string::npos)
  {
    return false;
  }
  const std::size_t digitsFrom = (text[first] == '-' || text[first] == '+') ? first + 1 : first;
  const std::size_t comma = text.find(',', digitsFrom);
  const auto allDigits = [&text](std::size_t from, std::size_t to)
  {
    return from < to &&
      std::all_of(
        text.begin() + from, text.begin() + to, [](char c) { return c >= '0' && c <= '9'; });
  };
  return comma != std::string::npos && comma < last && allDigits(digitsFrom, comma) &&
    allDigits(comma + 1, last + 1);
}

/// A row's value: a number, or NaN (missing) for NaN or, in a text column, a missing-value marker
/// (IsMissingMarker: a CSV reader gives a text column where such markers stand among the numbers).
/// Other text is an error naming the row.
double ObservationValue(const NumberColumn& values, vtkIdType row, const std::string& column)
{
  const NumberColumn::Cell cell = values.Read(row);
  if (const std::optional<double> value = cell.Number())
  {
    return *value;
  }
  const std::string& text = *cell.Text; // (a numeric cell is always a number)
  if (!IsMissingMarker(text))
  {
    ThrowRowError(row,
      "'" + text + "' in column '" + column +
        "' is not a number (a missing value is an empty field, NA, N/A, NaN or null)" +
        (LooksLikeDecimalComma(text)
            ? std::string(": a decimal comma is not read here; write the file with decimal points")
            : std::string()));
  }
  return std::numeric_limits<double>::quiet_NaN();
}

/// An unknown station (observation_series.h) of the station column: "X (1 row: row 5)", "Y (3
/// rows from row 7)", X and Y as written in their first row.
std::string UnknownStationName(vtkAbstractArray* stations, const tessera::UnknownStation& station)
{
  return RowStation(stations, static_cast<std::size_t>(station.FirstRow)) +
    (station.Rows == 1 ? " (1 row: row "
                       : " (" + std::to_string(station.Rows) + " rows from row ") +
    std::to_string(station.FirstRow) + ")";
}

/// The cause an error names first when the gauges have no points (an upstream filter that failed,
/// such as Table To Points without its Z column, or kept none): the array or the stations the
/// error is about are missing because of it.
const char* const NoGaugePoints =
  "the gauges input has no points (does the filter before it give none?)";

/// The error for a table none of whose rows can be used: how many lack a station or time, and which
/// station ids no gauge has (all of them, where the gauges input has no points: said first), with
/// the gauges' own ids and the two settings that choose them (a ParaView user who chose another
/// point array as StationIdArrayName was told only of the table's ids).
std::string NoUsableRowMessage(const ObservationRows& rows,
  vtkAbstractArray* stations,
  const std::vector<std::string>& gaugeNames,
  const std::string& idArray,
  const std::string& stationColumn)
{
  const std::vector<tessera::UnknownStation>& unknown = rows.Match.UnknownStations;
  std::ostringstream message;
  if (gaugeNames.empty())
  {
    message << NoGaugePoints << ", so ";
  }
  message << "none of the " << rows.Steps.StepOfRow.size()
          << " observation rows can be used (no time step to average): "
          << rows.Steps.IncompleteRows.size() << " have no station id or no time";
  if (!unknown.empty())
  {
    message << ", the others name station ids that no gauge has: "
            << ListNames(unknown.size(),
                 [&](std::size_t k) { return UnknownStationName(stations, unknown[k]); });
  }
  if (!unknown.empty() && !gaugeNames.empty())
  {
    message << "; the gauges' ids (their point-data array '" << idArray
            << "', StationIdArrayName) are "
            << ListNames(gaugeNames.size(), [&](std::size_t k) { return gaugeNames[k]; })
            << " (do StationIdArrayName and StationColumn '" << stationColumn
            << "' hold the same ids?)";
  }
  return message.str();
}

/// A warning, or "", for settings changed from their defaults that the inputs leave unused: the
/// gauges' value array (ValueArrayName) beside an observations table, or the table's columns
/// without one (a ParaView user changed them and saw no effect, and no word on why).
std::string UnusedSettingsWarning(vtkThiessenArealAverage* self, bool observations)
{
  // (the defaults are a new filter's: they are written once, in the class)
  vtkNew<vtkThiessenArealAverage> defaults;
  const std::string valueArray = self->GetValueArrayName();
  if (observations)
  {
    return valueArray == defaults->GetValueArrayName() ? std::string()
                                                       : "ValueArrayName '" + valueArray +
        "' is not used: the values come from the observations table (input 2, ValueColumn)";
  }
  using Getter = const char* (vtkThiessenArealAverage::*)();
  const std::pair<const char*, Getter> columns[] = {
    { "StationColumn", &vtkThiessenArealAverage::GetStationColumn },
    { "TimeColumn", &vtkThiessenArealAverage::GetTimeColumn },
    { "ValueColumn", &vtkThiessenArealAverage::GetValueColumn },
    { "MonthColumn", &vtkThiessenArealAverage::GetMonthColumn },
  };
  std::string changed;
  for (const auto& [name, get] : columns)
  {
    const std::string value = (self->*get)();
    if (value != (defaults.GetPointer()->*get)())
    {
      changed += (changed.empty() ? "" : ", ") + std::string(name) + " '" + value + "'";
    }
  }
  return changed.empty() ? std::string()
                         : changed +
      " not used: no observations table is connected (input 2), so the values are the gauges' "
      "point-data array '" +
      valueArray + "' (ValueArrayName)";
}

/// A warning, or "", when most observation rows repeat a station and time: times coarser than the
/// rows, as a table of years and months read with TimeColumn 'year' and no MonthColumn gives (in
/// ParaView, Month Column is a text box easily left empty). Each station's first row of a year was
/// used, January's, and the other 11 set aside as repeats, with no word on why.
std::string CoarseTimesWarning(vtkTable* observations,
  std::size_t repeated,
  const std::string& timeColumn,
  const std::string& monthColumn)
{
  const vtkIdType rows = observations->GetNumberOfRows();
  if (2 * static_cast<vtkIdType>(repeated) <= rows || !monthColumn.empty())
  {
    return std::string();
  }
  std::ostringstream text;
  text << repeated << " of the " << rows << " observation rows repeat a station and time of an "
       << "earlier row: the times of column '" << timeColumn
       << "' may be coarser than the rows (years, with the months in another column?)";
  for (vtkIdType c = 0; c < observations->GetNumberOfColumns(); ++c)
  {
    const char* name = observations->GetColumnName(c);
    if (name && LowerCase(name) == "month")
    {
      text << ": set MonthColumn to '" << name << "'";
      break;
    }
  }
  return text.str();
}

/// A warning, or "", for rows of the year 0 in a record whose other years are 1000 or later
/// (with a MonthColumn): ParaView's CSV reader reads an empty field of a numeric column as 0, and a
/// trial's row with an empty year made a step 0000-01, the time slider running from the year 0.
std::string YearZeroWarning(const tessera::ObservationSteps& steps,
  vtkAbstractArray* stations,
  const std::string& timeColumn,
  const std::string& monthColumn)
{
  const std::vector<double>& times = steps.Times;
  const auto later = std::find_if(times.begin(), times.end(), [](double t) { return t >= 1.0; });
  const std::size_t yearZero = std::size_t(later - times.begin());
  if (monthColumn.empty() || yearZero == 0 || times.front() < 0.0 || later == times.end() ||
    *later < 1000.0)
  {
    return std::string();
  }
  std::vector<std::int32_t> rows;
  for (std::size_t r = 0; r < steps.StepOfRow.size(); ++r)
  {
    if (steps.StepOfRow[r] >= 0 && std::size_t(steps.StepOfRow[r]) < yearZero)
    {
      rows.push_back(std::int32_t(r));
    }
  }
  return std::to_string(rows.size()) + " observation row(s) have the year 0 in column '" +
    timeColumn + "', where the record's other years start at " +
    std::to_string(static_cast<int>(std::floor(*later))) +
    " (ParaView's CSV reader reads an empty field of a numeric column as 0: give a missing year "
    "as NaN, or leave such rows out); they make " +
    std::to_string(yearZero) + " step(s) of their own (rows from 0): " +
    ListNames(rows.size(), [&](std::size_t k) { return RowName(stations, rows[k]); });
}

/// An incomplete row (observation_series.h) of the station column: "row 12 (no station id)",
/// "row 13 (station A: no time)".
std::string IncompleteRowName(vtkAbstractArray* stations, std::int32_t row)
{
  const std::string name = RowStation(stations, static_cast<std::size_t>(row));
  return "row " + std::to_string(row) +
    (name.empty() ? " (no station id)" : " (station " + name + ": no time)");
}

/// The observation rows with a value for a gauge at the place of others (DuplicateGauges) whose
/// value the average does not use at that step (ThiessenArealAverage::GaugesUsed: another gauge
/// there reported first), so these values are valid and unused, with the row whose value is used
/// in their place (-1 where none is known). Repeated rows are listed apart.
struct CoLocated
{
  std::vector<std::int32_t> Rows;
  std::vector<std::int32_t> UsedRows;
};

CoLocated CoLocatedRows(const ObservationRows& rows,
  const std::vector<double>& rowValues,
  const std::vector<std::vector<double>>& values,
  const tessera::ThiessenArealAverage& average,
  const std::vector<std::int32_t>& repeatedRows)
{
  CoLocated found;
  std::map<std::int32_t, std::int32_t> placeOf; // a gauge at a place with others: the place's first
  for (const auto& [gauge, first] : average.DuplicateGauges())
  {
    placeOf[gauge] = first;
    placeOf[first] = first;
  }
  if (placeOf.empty())
  {
    return found;
  }
  const std::set<std::int32_t> repeated(repeatedRows.begin(), repeatedRows.end());
  std::map<std::int32_t, std::vector<char>> usedAt; // per step met, GaugesUsed
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> usedRowAt; // (place, step): row
  std::vector<std::int32_t> unused;
  for (std::size_t r = 0; r < rowValues.size(); ++r)
  {
    const std::int32_t gauge = rows.Match.GaugeOfRow[r];
    const std::int32_t step = rows.Steps.StepOfRow[r];
    if (step < 0 || !placeOf.count(gauge) || std::isnan(rowValues[r]) ||
      repeated.count(static_cast<std::int32_t>(r)))
    {
      continue;
    }
    auto used = usedAt.find(step);
    if (used == usedAt.end())
    {
      used = usedAt.emplace(step, average.GaugesUsed(values[static_cast<std::size_t>(step)])).first;
    }
    if (used->second[static_cast<std::size_t>(gauge)])
    {
      usedRowAt[{ placeOf[gauge], step }] = static_cast<std::int32_t>(r);
    }
    else
    {
      unused.push_back(static_cast<std::int32_t>(r));
    }
  }
  for (const std::int32_t r : unused)
  {
    const auto row = static_cast<std::size_t>(r);
    const auto used =
      usedRowAt.find({ placeOf[rows.Match.GaugeOfRow[row]], rows.Steps.StepOfRow[row] });
    found.Rows.push_back(r);
    found.UsedRows.push_back(used == usedRowAt.end() ? -1 : used->second);
  }
  return found;
}

/// Per row, the value of a used row (NaN for the others, which are not read). Throws InputError
/// naming the row for a value that is infinite or neither a number nor a missing-value marker.
std::vector<double> RowValues(vtkTable* table,
  const tessera::ObservationSteps& steps,
  const std::string& stationColumn,
  const std::string& valueColumn)
{
  const NumberColumn values(ObservationColumn(
    table, valueColumn, "ValueColumn", "numbers; NaN, NA or an empty field where missing"));
  vtkAbstractArray* stations = table->GetColumnByName(stationColumn.c_str());
  std::vector<double> rowValues(steps.StepOfRow.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t r = 0; r < rowValues.size(); ++r)
  {
    if (steps.StepOfRow[r] < 0)
    {
      continue;
    }
    const vtkIdType row = static_cast<vtkIdType>(r);
    rowValues[r] = ObservationValue(values, row, valueColumn);
    if (std::isinf(rowValues[r]))
    {
      ThrowRowError(row, "station " + RowStation(stations, r) + " has an infinite value");
    }
  }
  return rowValues;
}

/// The warning for values that look like missing-value codes (`seen`, not empty); where(k) names
/// the place of value k; `inUse`, the MissingValue in use ("" with UseMissingValue off).
std::string MissingCodeWarning(const std::vector<tessera::MissingCodeSightings>& seen,
  const std::string& what,
  const std::function<std::string(std::size_t)>& where,
  const std::string& inUse)
{
  const std::string code = tessera::NumberText(seen.front().Code);
  std::string text = std::to_string(seen.front().Count) + " " + what + " exactly " + code +
    ", a common missing-value code, and averaged as measured values (the first " +
    where(seen.front().First) + ")";
  for (std::size_t k = 1; k < seen.size(); ++k)
  {
    text += "; " + std::to_string(seen[k].Count) + " exactly " + tessera::NumberText(seen[k].Code) +
      ", another (the first " + where(seen[k].First) + ")";
  }
  // MissingValue takes one code: with one in use already, the advice to switch to another would
  // make the values of the first measurements again.
  if (!inUse.empty())
  {
    return text + ": MissingValue takes one code, and " + inUse +
      " is in use; if these values are missing too, write them as NaN (or as " + inUse + ")";
  }
  return text +
    (seen.size() == 1
        ? ": if " + code + " marks missing values, turn UseMissingValue on with MissingValue " +
          code
        : std::string(": if one of these codes marks missing values, turn UseMissingValue on with "
                      "MissingValue set to it (it takes one code: write the other's values as "
                      "NaN)"));
}

/// Takes the missing values out of `values` (tessera::TakeMissingValues, with UseMissingValue `use`
/// and MissingValue `missing`) and gives the warning for common codes left among them, or "".
std::string TakeMissingValuesWarning(std::vector<double>& values,
  bool use,
  double missing,
  const std::string& what,
  const std::function<std::string(std::size_t)>& where)
{
  const std::vector<tessera::MissingCodeSightings> seen =
    tessera::TakeMissingValues(values, use, missing);
  return seen.empty()
    ? std::string()
    : MissingCodeWarning(seen, what, where, use ? tessera::NumberText(missing) : std::string());
}

/// The StationId array of an output: the gauges' id for each entry, in their id array's type
/// and components; none when the gauges have no ids.
class StationIdColumn
{
public:
  explicit StationIdColumn(vtkAbstractArray* stationIds)
    : StationIds(stationIds)
  {
    if (stationIds)
    {
      this->Stations = vtk::TakeSmartPointer(stationIds->NewInstance());
      this->Stations->SetNumberOfComponents(stationIds->GetNumberOfComponents());
      this->Stations->SetName("StationId");
    }
  }

  void Append(std::int32_t gauge)
  {
    if (this->Stations)
    {
      this->Stations->InsertNextTuple(gauge, this->StationIds);
    }
  }

  /// The array, or null without ids.
  vtkAbstractArray* Array() const { return this->Stations; }

private:
  vtkAbstractArray* StationIds;
  vtkSmartPointer<vtkAbstractArray> Stations;
};

/// The arrays of an output that describe a gauge, an entry per cell or row: StationId (the
/// gauges' id array's type, when they have one), GaugeId, Weight, Area_m2 and Value.
class GaugeColumns
{
public:
  explicit GaugeColumns(vtkAbstractArray* stationIds)
    : Stations(stationIds)
  {
    this->GaugeIds->SetName("GaugeId");
    this->Weights->SetName("Weight");
    this->Areas->SetName("Area_m2");
    this->Values->SetName("Value");
  }

  void Append(std::int32_t gauge, double weight, double area, double value)
  {
    this->Stations.Append(gauge);
    this->GaugeIds->InsertNextValue(gauge);
    this->Weights->InsertNextValue(weight);
    this->Areas->InsertNextValue(area);
    this->Values->InsertNextValue(value);
  }

  /// Adds the arrays, in the order above, to cell data or a table's row data (its columns).
  void AddTo(vtkFieldData* data)
  {
    if (this->Stations.Array())
    {
      data->AddArray(this->Stations.Array());
    }
    data->AddArray(this->GaugeIds);
    data->AddArray(this->Weights);
    data->AddArray(this->Areas);
    data->AddArray(this->Values);
  }

private:
  StationIdColumn Stations;
  vtkNew<vtkIdTypeArray> GaugeIds;
  vtkNew<vtkDoubleArray> Weights, Areas, Values;
};

/// Output 0's cell data, a cell per piece of a gauge's clipped tile: GaugeColumns (the gauge's, on
/// each of its cells), then CellArea_m2 and CellWeight (the cell's own area and its share of the
/// catchment).
class TileCellData
{
public:
  TileCellData(vtkAbstractArray* stationIds, double catchmentArea)
    : Gauges(stationIds)
    , CatchmentArea(catchmentArea)
  {
    this->CellAreas->SetName("CellArea_m2");
    this->CellWeights->SetName("CellWeight");
  }

  void Append(std::int32_t gauge, double weight, double area, double value, double cellArea)
  {
    this->Gauges.Append(gauge, weight, area, value);
    this->CellAreas->InsertNextValue(cellArea);
    this->CellWeights->InsertNextValue(cellArea / this->CatchmentArea);
  }

  void AddTo(vtkCellData* cellData)
  {
    this->Gauges.AddTo(cellData);
    cellData->AddArray(this->CellAreas);
    cellData->AddArray(this->CellWeights);
    // The step's values colour the tiles in a view (ParaView colours by the active scalars).
    cellData->SetActiveScalars("Value");
  }

private:
  GaugeColumns Gauges;
  double CatchmentArea;
  vtkNew<vtkDoubleArray> CellAreas, CellWeights;
};

/// A gauge's weight and clipped area at a step: 0 for a gauge whose tile is in the tessellation
/// but not weighted (its removal deferred).
struct GaugeWeight
{
  double Weight = 0.0;
  double AreaM2 = 0.0;
};

GaugeWeight WeightOf(const tessera::ArealStep& result, std::int32_t g)
{
  const auto found = std::lower_bound(result.Gauges.begin(), result.Gauges.end(), g);
  if (found == result.Gauges.end() || *found != g)
  {
    return {};
  }
  const std::size_t index = static_cast<std::size_t>(found - result.Gauges.begin());
  return { result.Weights[index], result.AreasM2[index] };
}

/// Output 3: each clipped tile's outline (core/piece_outlines.h) as closed polylines, a cell per
/// ring (its first point repeated last), with GaugeColumns and PolygonId (the polygon the ring
/// bounds, numbered over the output) and Hole (0: the polygon's outer ring, anticlockwise; 1: a
/// hole, clockwise). No active scalars: ParaView draws the lines in one colour over the tiles.
void WriteOutlines(const tessera::ClippedTilesLonLat& clipped,
  const tessera::ArealStep& result,
  const std::vector<double>& values,
  vtkAbstractArray* stationIds,
  vtkPolyData* output)
{
  const tessera::RegionOutlines& outlines = clipped.Outlines;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  GaugeColumns cells(stationIds);
  vtkNew<vtkIdTypeArray> polygonIds;
  polygonIds->SetName("PolygonId");
  vtkNew<vtkUnsignedCharArray> holes;
  holes->SetName("Hole");
  for (std::size_t k = 0; k < clipped.Gauges.size(); ++k)
  {
    const std::int32_t g = clipped.Gauges[k];
    const GaugeWeight weight = WeightOf(result, g);
    for (std::size_t p = clipped.TileOutlineOffsets[k]; p < clipped.TileOutlineOffsets[k + 1]; ++p)
    {
      for (std::size_t r = outlines.PolygonOffsets[p]; r < outlines.PolygonOffsets[p + 1]; ++r)
      {
        const std::size_t begin = outlines.Rings.RingOffsets[r];
        tessera_vtk::AppendClosedLine(&outlines.Rings.Vertices[begin],
          outlines.Rings.RingOffsets[r + 1] - begin,
          0,
          points,
          lines);
        cells.Append(g, weight.Weight, weight.AreaM2, values[static_cast<std::size_t>(g)]);
        polygonIds->InsertNextValue(static_cast<vtkIdType>(p));
        holes->InsertNextValue(r == outlines.PolygonOffsets[p] ? 0 : 1);
      }
    }
  }
  output->SetPoints(points);
  output->SetLines(lines);
  cells.AddTo(output->GetCellData());
  output->GetCellData()->AddArray(polygonIds);
  output->GetCellData()->AddArray(holes);
}

/// The latest modification time of a data object and, for a composite one, of its blocks.
vtkMTimeType LatestMTime(vtkDataObject* data)
{
  vtkMTimeType latest = data->GetMTime();
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    auto iter = vtk::TakeSmartPointer(composite->NewIterator());
    if (auto* tree = vtkDataObjectTreeIterator::SafeDownCast(iter))
    {
      tree->VisitOnlyLeavesOff(); // inner blocks too: a leaf moved within one changes only it
    }
    for (iter->InitTraversal(); !iter->IsDoneWithTraversal(); iter->GoToNextItem())
    {
      latest = std::max(latest, iter->GetCurrentDataObject()->GetMTime());
    }
  }
  return latest;
}

/// The modification time of a table's column, 0 when it has none.
vtkMTimeType ColumnMTime(vtkTable* table, const std::string& column)
{
  vtkAbstractArray* array = table->GetColumnByName(column.c_str());
  return array ? array->GetMTime() : 0;
}

/// Output 2's columns, a row per step and weighted gauge: Time, Date (when the steps have
/// dates), then GaugeColumns.
class WeightRows
{
public:
  WeightRows(vtkAbstractArray* stationIds, bool withDates)
    : Gauges(stationIds)
    , WithDates(withDates)
  {
    this->Times->SetName("Time");
    this->Dates->SetName("Date");
  }

  /// A step's rows; date: its Date (unused without dates).
  void Append(double time,
    const std::string& date,
    const tessera::ArealStep& step,
    const std::vector<double>& values)
  {
    for (std::size_t k = 0; k < step.Gauges.size(); ++k)
    {
      const std::int32_t g = step.Gauges[k];
      this->Times->InsertNextValue(time);
      if (this->WithDates)
      {
        this->Dates->InsertNextValue(date);
      }
      this->Gauges.Append(g, step.Weights[k], step.AreasM2[k], values[static_cast<std::size_t>(g)]);
    }
  }

  void Fill(vtkTable* table)
  {
    table->Initialize();
    table->AddColumn(this->Times);
    if (this->WithDates)
    {
      table->AddColumn(this->Dates);
    }
    this->Gauges.AddTo(table->GetRowData()); // (a table's columns are its row data's arrays)
  }

private:
  vtkNew<vtkDoubleArray> Times;
  vtkNew<vtkStringArray> Dates;
  GaugeColumns Gauges;
  const bool WithDates;
};

/// The warning for catchment rings that lie inside a ring of another block, or "" when none does
/// (or the rings are not from blocks). vtkGDALVectorReader gives each feature a block, so such a
/// ring is a feature inside another feature, and the even-odd rule cuts it out as a hole: a
/// sub-basin given beside its basin takes itself out of the catchment. (A hole of a polygon comes
/// in its polygon's block.)
std::string RingsInsideOtherBlocksWarning(const tessera_vtk::Rings& rings,
  const tessera::ThiessenArealAverage& average)
{
  const std::vector<std::int64_t>& block = rings.Blocks;
  if (std::adjacent_find(block.begin(), block.end(), std::not_equal_to<std::int64_t>()) ==
    block.end())
  {
    return std::string(); // one block (or a vtkPolyData): holes are where the rings put them
  }
  struct Inside
  {
    std::size_t Ring;
    std::int32_t Around; // a ring of another block around it
    bool Land;           // inside an even number of rings: an island in a hole, land again
  };
  std::vector<Inside> inside;
  for (std::size_t r = 0; r < block.size(); ++r)
  {
    const std::vector<std::int32_t> around = average.CatchmentRingsAround(r);
    for (const std::int32_t ring : around)
    {
      if (block[static_cast<std::size_t>(ring)] != block[r])
      {
        inside.push_back({ r, ring, around.size() % 2 == 0 });
        break;
      }
    }
  }
  if (inside.empty())
  {
    return std::string();
  }
  return std::to_string(inside.size()) +
    " catchment ring(s) lie inside a ring of another block (feature), so the even-odd rule cuts "
    "them out of the catchment as holes, or, inside a hole, makes them land again (a sub-basin "
    "given beside its basin removes itself; give the basin alone, or each hole in the block of "
    "its polygon): " +
    ListNames(inside.size(),
      [&](std::size_t k)
      {
        // (by their cells: ring numbers shift where a pair of rings given twice was left out)
        const std::size_t r = inside[k].Ring;
        const auto around = static_cast<std::size_t>(inside[k].Around);
        return rings.Sources[r] + " inside " + rings.Sources[around] +
          (inside[k].Land ? " (land again: inside a hole)" : " (a hole)");
      });
}

/// Sets the time steps (and their range) on the tiles and their outlines (outputs 0 and 3),
/// which both follow the time; none for no times.
void AdvertiseTimeSteps(vtkInformationVector* outputVector, const std::vector<double>& times)
{
  if (times.empty())
  {
    return;
  }
  for (vtkInformation* info :
    { outputVector->GetInformationObject(0), outputVector->GetInformationObject(3) })
  {
    info->Set(
      vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
    const double range[2] = { times.front(), times.back() };
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
}

/// The information holding the time asked for by the output that asked (the tiles or their
/// outlines; the tables have none): ParaView's view of the outlines alone asks through output 3.
/// A request without a time goes by output 0's.
vtkInformation* TimeRequestInformation(vtkInformation* request, vtkInformationVector* outputVector)
{
  const int asking = request->Has(vtkExecutive::FROM_OUTPUT_PORT())
    ? request->Get(vtkExecutive::FROM_OUTPUT_PORT())
    : 0;
  vtkInformation* outlinesInfo = outputVector->GetInformationObject(3);
  if (asking == 3 && outlinesInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    return outlinesInfo;
  }
  return outputVector->GetInformationObject(0);
}

} // namespace

struct vtkThiessenArealAverage::Internals
{
  vtkMTimeType BuiltFor = 0;
  /// Per topic, the warning last given on it ("" for none): said again only when it changes, not
  /// at every build (gauges that change with the time steps, as a series of gauge files, rebuild
  /// at each step, and each step repeated the warnings about the settings).
  std::map<std::string, std::string> Said;

  /// Whether to give text, the warning on topic now ("" for none): not when it was the last one.
  bool SayOnce(const std::string& topic, const std::string& text)
  {
    std::string& last = this->Said[topic];
    const bool say = !text.empty() && text != last;
    last = text;
    return say;
  }
  /// Gauges given as a composite data set (a point GeoJSON or shapefile read by
  /// vtkGDALVectorReader: a block per gauge) are joined into one point set, and a point set whose
  /// station ids or values are its vertices' cell data (the same after Merge Blocks) is copied with
  /// them as point data; either is kept while the input and the array names are unchanged, so that
  /// its modification time, and with it the results above, last as a plain point set's would.
  vtkSmartPointer<vtkPointSet> Joined;
  /// Why the blocks' value arrays could not be joined ("" when they were, or not asked for).
  std::string ValueProblem;
  vtkDataObject* JoinedFrom = nullptr; ///< compared by address, never dereferenced
  vtkMTimeType JoinedAt = 0;
  std::vector<std::string> JoinedArrays;
  std::vector<double> Times;
  std::vector<std::vector<double>> Values; // per step, per gauge; NaN = missing
  std::unique_ptr<tessera::ThiessenArealAverage> Average;
  vtkNew<vtkTable> Summary;
  vtkNew<vtkTable> Weights; // output 2: one row per step and weighted gauge

  /// What the observation rows were classified from: the table and the gauges' station ids (each
  /// compared by address, never dereferenced, and modification times), and the column names.
  struct RowsSource
  {
    vtkTable* Table = nullptr; // null: nothing cached
    vtkAbstractArray* StationIds = nullptr;
    std::vector<vtkMTimeType> MTimes;
    std::vector<std::string> Columns;
    bool operator==(const RowsSource& other) const
    {
      return this->Table == other.Table && this->StationIds == other.StationIds &&
        this->MTimes == other.MTimes && this->Columns == other.Columns;
    }
  };
  RowsSource ClassifiedFrom;
  ObservationRows Classified;

  /// ReadRows of the table, read by RequestInformation (which needs the time steps) and kept
  /// for Build while the table, the gauges' ids and the columns are unchanged. gaugeNames: the
  /// GaugeNames of stationIds.
  const ObservationRows& CachedRows(vtkTable* table,
    vtkPointSet* gauges,
    vtkAbstractArray* stationIds,
    const std::vector<std::string>& gaugeNames,
    const std::string& stationColumn,
    const std::string& timeColumn,
    const std::string& monthColumn)
  {
    RowsSource source;
    source.Table = table;
    source.StationIds = stationIds;
    source.Columns = { stationColumn, timeColumn, monthColumn };
    // (the gauges' time too: an id changed in place with only the gauges marked modified)
    source.MTimes = { table->GetMTime(), stationIds->GetMTime(), gauges->GetMTime() };
    for (const std::string& column : source.Columns)
    {
      source.MTimes.push_back(ColumnMTime(table, column));
    }
    if (!(source == this->ClassifiedFrom))
    {
      CheckColumnLengths(table);           // (before any column is read)
      this->ClassifiedFrom = RowsSource(); // until the read succeeds (it throws on bad times)
      this->Classified = ReadRows(table, gaugeNames, stationColumn, timeColumn, monthColumn);
      this->ClassifiedFrom = source;
    }
    return this->Classified;
  }
};

//------------------------------------------------------------------------------
vtkThiessenArealAverage::vtkThiessenArealAverage()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(4);
}

vtkThiessenArealAverage::~vtkThiessenArealAverage() = default;

int vtkThiessenArealAverage::GetNumberOfTimeSteps()
{
  return static_cast<int>(this->Internal->Times.size());
}

//------------------------------------------------------------------------------
double vtkThiessenArealAverage::TimeOfDate(const char* date)
{
  // (a zone left off, as the observations' dates in one zone are read: as written)
  const std::optional<tessera::DateTimeAndZone> time =
    date ? tessera::IsoDateTimeAndZone(date) : std::nullopt;
  return time ? time->Time : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
int vtkThiessenArealAverage::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    // Points, or a composite of point sets (a point layer from vtkGDALVectorReader: a block per
    // feature) joined into one set of gauges; any other type too, for GaugesOf to name (the
    // pipeline's own check would stop before RequestData and leave the last results in place).
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  }
  else if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  }
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject"); // a table: RequestData
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkThiessenArealAverage::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 || port == 3 ? "vtkPolyData" : "vtkTable");
  return 1;
}

//------------------------------------------------------------------------------
int vtkThiessenArealAverage::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (this->GetNumberOfInputConnections(2) == 0)
  {
    // Without a table an update averages the gauges' one array as it is: the gauges' own time
    // steps (a file series of gauge files, say), which the pipeline copies from input 0, are the
    // filter's, and a requested time goes up to the gauges.
    return 1;
  }
  for (vtkInformation* info : { outInfo, outputVector->GetInformationObject(3) })
  {
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  if (this->GetNumberOfInputConnections(0) == 0)
  {
    return 1;
  }
  // The time steps are the times of the observation rows that can be used, those of stations
  // the gauges have: the table and the gauges are read now, ahead of RequestData, so that the
  // pipeline (and ParaView's time slider) knows them.
  auto* table = vtkTable::SafeDownCast(tessera_vtk::UpdatedData(this->GetInputConnection(2, 0)));
  vtkDataObject* gaugesData = tessera_vtk::UpdatedData(this->GetInputConnection(0, 0));
  if (!table || !gaugesData)
  {
    return 1;
  }
  try
  {
    vtkPointSet* gauges = this->GaugesOf(gaugesData);
    vtkAbstractArray* stationIds = this->GaugeStationIds(gauges, true);
    const std::vector<double>& times = this->Internal
                                         ->CachedRows(table,
                                           gauges,
                                           stationIds,
                                           GaugeNames(stationIds),
                                           this->StationColumn,
                                           this->TimeColumn,
                                           this->MonthColumn)
                                         .Steps.Times;
    AdvertiseTimeSteps(outputVector, times);
  }
  catch (const std::exception&)
  {
    // No time steps, and no error yet: RequestData reads the same inputs and reports it. ParaView
    // asks for the information as soon as the filter is made, before the user has set the
    // columns (the defaults, time and value, are seldom a file's names), and an error then would
    // greet every new filter. Until RequestData runs, the outputs must not show the last good
    // input's results as if they were this input's.
    this->DiscardResults(outputVector);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkThiessenArealAverage::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // Every gauge, the whole catchment and every observation at once: see RequestWholeInputs
  // (ParaView under MPI asks each process for a piece, and each averaged over its own piece).
  tessera_vtk::RequestWholeInputs(inputVector, 0, 2);
  return 1;
}

//------------------------------------------------------------------------------
int vtkThiessenArealAverage::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  if (!tessera_vtk::MakesOutput(outputVector))
  {
    return 1; // another process's piece: the first makes the whole output (RequestWholeInputs)
  }
  vtkDataObject* gaugesData = vtkDataObject::GetData(inputVector[0]);
  vtkDataObject* catchment = vtkDataObject::GetData(inputVector[1]);
  vtkDataObject* observationsData = vtkDataObject::GetData(inputVector[2]);
  vtkTable* observations = vtkTable::SafeDownCast(observationsData);
  vtkInformation* tilesInfo = TimeRequestInformation(request, outputVector);
  vtkPolyData* tilesOutput = vtkPolyData::GetData(outputVector, 0);
  vtkTable* summaryOutput = vtkTable::GetData(outputVector, 1);
  vtkTable* weightsOutput = vtkTable::GetData(outputVector, 2);
  vtkPolyData* outlinesOutput = vtkPolyData::GetData(outputVector, 3);
  Internals& in = *this->Internal;
  try
  {
    tessera_vtk::CheckChoice(
      "AreaMethod", this->AreaMethod, { "Automatic", "EqualAreaPlane", "GeodesicPolygon" });
    if (observationsData && !observations)
    {
      throw tessera::InputError(std::string("the observations (input 2) are a ") +
        observationsData->GetClassName() + ", not a table");
    }
    vtkPointSet* gauges = this->GaugesOf(gaugesData);
    vtkAbstractArray* stationIds = this->GaugeStationIds(gauges, observations != nullptr);
    this->BuildIfChanged(gauges, stationIds, catchment, observations);
    summaryOutput->ShallowCopy(in.Summary);
    weightsOutput->ShallowCopy(in.Weights);
    std::size_t step = 0;
    if (!this->RequestedStep(tilesInfo, step))
    {
      tilesOutput->Initialize();
      outlinesOutput->Initialize();
      return 0;
    }
    this->WriteTiles(step, stationIds, tilesOutput, outlinesOutput);
    for (vtkPolyData* output : { tilesOutput, outlinesOutput })
    {
      if (!in.Times.empty())
      {
        output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), in.Times[step]);
      }
      tessera_vtk::ListNonEmptyFieldArraysFirst(output);
    }
    return 1;
  }
  catch (const std::exception& e)
  {
    // (a stop that a progress observer asked for empties the outputs too, without an error)
    this->DiscardResults(outputVector);
    return tesseraErrorOrStopMacro(e);
  }
}

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::BuildIfChanged(vtkPointSet* gauges,
  vtkAbstractArray* stationIds,
  vtkDataObject* catchment,
  vtkTable* observations)
{
  Internals& in = *this->Internal;
  vtkMTimeType stamp = std::max(this->GetMTime(), gauges->GetMTime());
  stamp = std::max(stamp, catchment->GetMTime());
  if (observations)
  {
    // (a table's own time does not follow its columns; its row data's does)
    stamp = std::max({ stamp, observations->GetMTime(), observations->GetRowData()->GetMTime() });
  }
  if (in.Average && stamp <= in.BuiltFor)
  {
    return;
  }
  // Without observations the ids only name the gauges: a mistyped name was taken silently.
  const std::string noIds = !stationIds && gauges->GetNumberOfPoints() > 0
    ? "the gauges have no point-data array '" + this->StationIdArrayName +
      "' (StationIdArrayName): the outputs have no StationId and the gauges are named by "
      "their index; their arrays are " +
      ArrayNames(gauges->GetPointData())
    : std::string();
  if (in.SayOnce("station ids", noIds))
  {
    vtkWarningMacro(<< noIds);
  }
  this->Build(gauges, stationIds, catchment, observations);
  in.BuiltFor = stamp;
}

//------------------------------------------------------------------------------
bool vtkThiessenArealAverage::RequestedStep(vtkInformation* tilesInfo, std::size_t& step)
{
  // The requested step: the last one at or before the requested time.
  const std::vector<double>& times = this->Internal->Times;
  step = 0;
  if (!tilesInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) || times.empty())
  {
    return true;
  }
  const double t = tilesInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  if (std::isnan(t))
  {
    // (Every comparison with NaN is false: the search below would give the last step.) A bad
    // request, not bad input: the average, its tables and time steps stay for the next one.
    vtkErrorMacro(<< "the requested time is NaN; the steps' times run from "
                  << tessera::NumberText(times.front()) << " to "
                  << tessera::NumberText(times.back()));
    return false;
  }
  const auto after = std::upper_bound(times.begin(), times.end(), t);
  step = after == times.begin() ? 0 : static_cast<std::size_t>(after - times.begin() - 1);
  return true;
}

//------------------------------------------------------------------------------
vtkPointSet* vtkThiessenArealAverage::GaugesOf(vtkDataObject* data)
{
  auto* points = vtkPointSet::SafeDownCast(data);
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!points && !composite)
  {
    throw tessera::InputError(std::string("the gauges (input 0) are a ") +
      (data ? data->GetClassName() : "nothing") + ", not points");
  }
  Internals& in = *this->Internal;
  const std::vector<std::string> arrays{ this->StationIdArrayName, this->ValueArrayName };
  if (points)
  {
    // (Values and ids are read by gauge id: a short array was read past its end.)
    tessera_vtk::CheckAttributeLengths(points, "the gauges (input 0)");
  }
  const vtkMTimeType latest = LatestMTime(data);
  if (!in.Joined || in.JoinedFrom != data || in.JoinedAt != latest || in.JoinedArrays != arrays)
  {
    this->JoinGauges(data, arrays);
    in.JoinedFrom = data;
    in.JoinedAt = latest;
    in.JoinedArrays = arrays;
  }
  if (in.Joined.GetPointer() == data)
  {
    return points;
  }
  // The input's time (of a time-aware source) on the joined or copied gauges, which their one
  // step takes without observations.
  vtkInformation* time = data->GetInformation();
  if (time->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    in.Joined->GetInformation()->Set(
      vtkDataObject::DATA_TIME_STEP(), time->Get(vtkDataObject::DATA_TIME_STEP()));
  }
  else
  {
    in.Joined->GetInformation()->Remove(vtkDataObject::DATA_TIME_STEP());
  }
  return in.Joined;
}

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::JoinGauges(vtkDataObject* data,
  const std::vector<std::string>& arrays)
{
  Internals& in = *this->Internal;
  auto* points = vtkPointSet::SafeDownCast(data);
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  in.Joined = nullptr; // until the join succeeds
  in.ValueProblem.clear();
  if (points)
  {
    // Attributes of one vertex per point (a GDAL point layer after Merge Blocks) are the
    // points' (the point set itself when there are none).
    in.Joined = tessera_vtk::VertexArraysAsPointData(points, arrays);
    tesseraWarnEachMacro(
      this, tessera_vtk::LongAttributeWarnings(in.Joined, "the gauges (input 0)", true, arrays));
  }
  else
  {
    // The station ids are needed; the value array only without observations, where the
    // reason it could not be joined is the error (ValueProblem).
    std::map<std::string, std::string> dropped;
    vtkSmartPointer<vtkPolyData> joined = tessera_vtk::MergedPoints(composite, arrays, &dropped);
    const auto stationProblem = dropped.find(this->StationIdArrayName);
    if (stationProblem != dropped.end())
    {
      throw tessera::InputError(stationProblem->second);
    }
    const auto valueProblem = dropped.find(this->ValueArrayName);
    in.ValueProblem = valueProblem != dropped.end() ? valueProblem->second : std::string();
    in.Joined = joined;
  }
  tesseraWarnEachMacro(
    this, tessera_vtk::HiddenVertexArrayWarnings(data, arrays, "the gauges (input 0)"));
}

//------------------------------------------------------------------------------
vtkAbstractArray* vtkThiessenArealAverage::GaugeStationIds(vtkPointSet* gauges, bool required)
{
  vtkAbstractArray* ids =
    gauges->GetPointData()->GetAbstractArray(this->StationIdArrayName.c_str());
  if (!ids && required)
  {
    throw tessera::InputError(
      (gauges->GetNumberOfPoints() == 0 ? std::string(NoGaugePoints) + " and "
                                        : std::string("the gauges have ")) +
      "no point-data array '" + this->StationIdArrayName +
      "' (StationIdArrayName) of station ids to match the observations with; their arrays are " +
      ArrayNames(gauges->GetPointData()));
  }
  if (ids && ids->GetNumberOfComponents() != 1)
  {
    // (read value by value, a 2-component array's (101, 0), (102, 0) gave the second gauge the
    // id 0 and the third 102, the second's station)
    throw tessera::InputError("the gauges' station id array '" + this->StationIdArrayName +
      "' has " + std::to_string(ids->GetNumberOfComponents()) +
      " components, where one id a gauge is read");
  }
  if (ids && ids->GetNumberOfTuples() != gauges->GetNumberOfPoints())
  {
    throw tessera::InputError("the gauges' station id array '" + this->StationIdArrayName +
      "' has " + std::to_string(ids->GetNumberOfTuples()) + " values for " +
      std::to_string(gauges->GetNumberOfPoints()) + " gauges");
  }
  return ids;
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
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    if (vtkDataObject* output = info->Get(vtkDataObject::DATA_OBJECT()))
    {
      output->Initialize();
      output->GetInformation()->Remove(vtkDataObject::DATA_TIME_STEP());
    }
  }
}

//------------------------------------------------------------------------------
/// One Build, in the order its messages come: the engine made from the gauges and the catchment,
/// the values read (the observations, or the gauges' one array), everything valid but unused
/// reported by id, every step averaged into the summary table. A nested class: it reads the
/// filter's settings and fills its internals.
struct vtkThiessenArealAverage::BuildRun
{
  BuildRun(vtkThiessenArealAverage* self,
    vtkPointSet* gauges,
    vtkAbstractArray* stationIds,
    vtkTable* observations)
    : Self(self)
    , In(*self->Internal)
    , Gauges(gauges)
    , StationIds(stationIds)
    , Observations(observations)
  {
  }

  vtkThiessenArealAverage* const Self;
  Internals& In;
  vtkPointSet* const Gauges;
  vtkAbstractArray* const StationIds;
  vtkTable* const Observations;
  std::vector<tessera::Point2> LonLat;
  std::vector<std::string> Names; // the gauges' station ids as text (GaugeNames)
  std::size_t GaugeCount = 0;

  // Read from the observations (none without them):
  const ObservationRows* Rows = nullptr;
  vtkAbstractArray* Stations = nullptr;                  // their station column (for messages)
  std::vector<double> ValuesOfRows;                      // per observation row (NaN: missing)
  std::vector<std::int32_t> RepeatedRows, RepeatedRowOf; // and the earlier row each one repeats

  // Valid but unused input, reported by id:
  std::vector<char> IdShared; // per gauge: other gauges have its station id
  std::vector<std::int32_t> Unobserved, Duplicates, DuplicateOf, Unweighted;
  CoLocated CoLocatedValues;

  /// Makes the engine from the gauges and the catchment (input 1), with the settings' warnings.
  void MakeEngine(vtkDataObject* catchment)
  {
    this->In.Average.reset();
    // (unchecked: the core names a NaN or infinite gauge by index and, via GaugeNames, station id)
    this->LonLat = tessera_vtk::CopyPoints2D(this->Gauges->GetPoints());
    this->GaugeCount = this->LonLat.size();
    std::vector<std::string> ringWarnings;
    const tessera_vtk::Rings rings =
      tessera_vtk::ReadPolygonRings(catchment, "catchment (input 1)", ringWarnings);
    tesseraWarnEachMacro(this->Self, ringWarnings);
    const std::string unusedSettings = UnusedSettingsWarning(this->Self, this->Observations);
    if (this->In.SayOnce("unused settings", unusedSettings))
    {
      this->Warn(unusedSettings);
    }
    // (GaugeStationIds checked: one per gauge)
    this->Names = GaugeNames(this->StationIds);
    const tessera::ArealAverageSettings settings = this->EngineSettings();
    try
    {
      this->In.Average.reset(
        new tessera::ThiessenArealAverage(this->LonLat, rings.Offsets, rings.Vertices, settings));
    }
    catch (const tessera::RingError& error)
    {
      // (the core numbers the rings as read: say which cells they are)
      throw tessera_vtk::WithRingSources(error, rings, "catchment (input 1)");
    }
    const std::string nested = RingsInsideOtherBlocksWarning(rings, *this->In.Average);
    this->Warn(nested);
  }

  tessera::ArealAverageSettings EngineSettings() const
  {
    tessera::ArealAverageSettings settings;
    if (!this->Self->ProjectionRecord.empty())
    {
      settings.HaveProjection = true;
      settings.Projection = tessera::ProjectionParameters::FromString(this->Self->ProjectionRecord);
    }
    settings.GaugeNames = this->Names; // for errors
    const int method = this->Self->AreaMethod;
    settings.Areas = method == EQUAL_AREA_PLANE ? tessera::AreaMethod::EqualAreaPlane
      : method == GEODESIC_POLYGON              ? tessera::AreaMethod::GeodesicPolygon
                                                : tessera::AreaMethod::Automatic;
    return settings;
  }

  /// Warns of catchment vertices put on another ring's edge, and of gauges none of which lies
  /// inside the catchment (a sign of swapped or unsigned coordinates).
  void WarnOfCatchmentAndGauges()
  {
    if (const std::size_t snapped = this->In.Average->CatchmentVerticesPutOnEdges())
    {
      std::ostringstream text;
      text << snapped << " catchment vertex(es) lay within "
           << tessera::ArealAverageSettings::SharedBorderDegrees
           << " degrees of another ring's edge (a shared border with vertices that only one side "
              "has: on the edge, or off it by their coordinates' rounding) and were put on that "
              "edge as projected too";
      this->Warn(text.str());
    }
    std::size_t gaugesInside = 0;
    for (std::size_t g = 0; g < this->GaugeCount; ++g)
    {
      gaugesInside += this->In.Average->GaugeInsideCatchment(g) ? 1 : 0;
    }
    if (this->GaugeCount > 0 && gaugesInside == 0)
    {
      this->Warn("none of the " + std::to_string(this->GaugeCount) +
        " gauges lies inside the catchment: every weight goes to gauges outside it, as "
        "Thiessen's rule gives them. If that is unexpected, check that the gauges and the "
        "catchment are both longitude, latitude in degrees (a west longitude without its minus "
        "sign, or the two swapped in either; for coordinates made longitude, latitude from "
        "projected ones, the projection and its grid those of their system).");
    }
  }

  /// The times and per-step values from the observations table: its rows matched with the
  /// gauges, missing-value codes taken, repeated rows found.
  void ReadObservations()
  {
    vtkThiessenArealAverage* self = this->Self;
    vtkTable* observations = this->Observations;
    CheckColumnLengths(observations);
    if (observations->GetNumberOfRows() == 0)
    {
      throw tessera::InputError("the observations table has no rows (no time step to average)");
    }
    this->Rows = &this->In.CachedRows(observations,
      this->Gauges,
      this->StationIds,
      this->Names,
      self->StationColumn,
      self->TimeColumn,
      self->MonthColumn);
    vtkAbstractArray* stations = observations->GetColumnByName(self->StationColumn.c_str());
    this->Stations = stations;
    if (this->Rows->Steps.Times.empty())
    {
      throw tessera::InputError(NoUsableRowMessage(
        *this->Rows, stations, this->Names, self->StationIdArrayName, self->StationColumn));
    }
    this->Warn(this->Rows->MixedPeriodsWarning);
    this->In.Times = this->Rows->Steps.Times;
    this->ValuesOfRows =
      RowValues(observations, this->Rows->Steps, self->StationColumn, self->ValueColumn);
    this->Warn(TakeMissingValuesWarning(this->ValuesOfRows,
      self->UseMissingValue,
      self->MissingValue,
      "observation value(s) are",
      [stations](std::size_t row)
      { return "in row " + std::to_string(row) + ", station " + RowStation(stations, row); }));
    tessera::StepSeries series = tessera::BuildSeries(
      this->Rows->Match, this->Rows->Steps, this->ValuesOfRows, this->GaugeCount);
    this->In.Values = std::move(series.Values);
    this->RepeatedRows = std::move(series.RepeatedRows);
    this->RepeatedRowOf = std::move(series.RepeatedRowOf);
  }

  /// Without observations: one step, the gauges' point-data array ValueArrayName at the gauges'
  /// own time (from a time-aware source), else 0.
  void ReadGaugeValues()
  {
    vtkDataArray* values = this->GaugeValueArray();
    vtkInformation* gaugesInfo = this->Gauges->GetInformation();
    this->In.Times.push_back(gaugesInfo->Has(vtkDataObject::DATA_TIME_STEP())
        ? gaugesInfo->Get(vtkDataObject::DATA_TIME_STEP())
        : 0.0);
    this->In.Values.emplace_back(this->GaugeCount);
    for (std::size_t g = 0; g < this->GaugeCount; ++g)
    {
      this->In.Values[0][g] = values->GetTuple1(static_cast<vtkIdType>(g));
    }
    const std::vector<std::string>& names = this->Names;
    this->Warn(TakeMissingValuesWarning(this->In.Values[0],
      this->Self->UseMissingValue,
      this->Self->MissingValue,
      "gauge value(s) in '" + this->Self->ValueArrayName + "' are",
      [&names](std::size_t g)
      {
        const std::string name = g < names.size() ? names[g] : "";
        return "of gauge " + std::to_string(g) + (name.empty() ? std::string() : " (" + name + ")");
      }));
  }

  /// The gauges' value array (ValueArrayName) when it is numbers, one per gauge; else an
  /// InputError saying what it is, or what the gauges have.
  vtkDataArray* GaugeValueArray() const
  {
    const std::string& name = this->Self->ValueArrayName;
    vtkAbstractArray* given = this->Gauges->GetPointData()->GetAbstractArray(name.c_str());
    auto* values = vtkDataArray::SafeDownCast(given);
    if (this->Gauges->GetNumberOfPoints() == 0)
    {
      // (a missing array is missing because the points are: said first, as with observations;
      // an empty one, as an upstream Threshold that kept none leaves, gave no word)
      throw tessera::InputError(std::string(NoGaugePoints) +
        (values ? ": no gauge to average"
                : ": no gauge, no value array '" + name + "' (ValueArrayName)"));
    }
    if (given && !values)
    {
      // (it was "need a numeric point-data array 'value' ...; their arrays are station_id, value")
      throw tessera::InputError("without observations the gauges' point-data array '" + name +
        "' (ValueArrayName) is read as one number per gauge, but it is a " + given->GetClassName() +
        ", not numbers; make it numeric, or give the values as observations (input 2: station id, "
        "time, value), whose text values are read as numbers");
    }
    if (!values)
    {
      const std::string& problem = this->In.ValueProblem;
      throw tessera::InputError(
        "without observations the gauges need a numeric point-data array '" + name +
        "' (ValueArrayName)" + (problem.empty() ? std::string() : ": " + problem) +
        "; their arrays are " + ArrayNames(this->Gauges->GetPointData()));
    }
    if (values->GetNumberOfComponents() != 1)
    {
      throw tessera::InputError("the gauges' value array '" + name + "' has " +
        std::to_string(values->GetNumberOfComponents()) +
        " components, where one value a gauge is read (ValueArrayName; ParaView's Calculator "
        "makes an array of one component)");
    }
    return values;
  }

  /// Marks the gauges whose station id other gauges have too (by the key the observations are
  /// matched by, tessera::StationKey: "050848" and "50848" are one id; with or without
  /// observations).
  void MarkSharedIds()
  {
    this->IdShared.assign(this->GaugeCount, 0);
    std::map<std::string, std::size_t> firstWithKey;
    for (std::size_t g = 0; this->StationIds && g < this->GaugeCount; ++g)
    {
      const auto found = firstWithKey.emplace(tessera::StationKey(this->Names[g]), g);
      if (!found.second && !this->Names[g].empty())
      {
        this->IdShared[g] = 1;
        this->IdShared[found.first->second] = 1;
      }
    }
  }

  /// A gauge by its station id, or by its point id when it has none (an empty id named nothing);
  /// by both when other gauges have its id ("A (gauge 4)": "A" alone would name them all).
  std::string IdOf(std::int32_t gauge) const
  {
    const auto g = static_cast<std::size_t>(gauge);
    if (!this->StationIds || this->Names[g].empty())
    {
      return "gauge " + std::to_string(g) + " (no station id)";
    }
    return this->IdShared[g] ? this->Names[g] + " (gauge " + std::to_string(g) + ")"
                             : this->Names[g];
  }

  /// The gauges without a value at any step, and those at the place of an earlier gauge.
  void FindUnusedGauges()
  {
    for (std::size_t g = 0; g < this->GaugeCount; ++g)
    {
      const auto valued = [g](const std::vector<double>& stepValues)
      { return !std::isnan(stepValues[g]); };
      if (std::none_of(this->In.Values.begin(), this->In.Values.end(), valued))
      {
        this->Unobserved.push_back(static_cast<std::int32_t>(g));
      }
    }
    for (const auto& pair : this->In.Average->DuplicateGauges())
    {
      this->Duplicates.push_back(pair.first);
      this->DuplicateOf.push_back(pair.second);
    }
  }

  /// One warning per kind of unused input: "N <what>: the first 20 names" (only those are made).
  template<class NameOf>
  void WarnOf(std::size_t count, const char* what, const NameOf& nameOf) const
  {
    if (count > 0)
    {
      this->Warn(std::to_string(count) + " " + what + ": " + ListNames(count, nameOf));
    }
  }

  /// Everything valid but unused, reported by id: gauges, station ids and rows.
  void WarnOfUnusedInputs()
  {
    this->MarkSharedIds();
    this->FindUnusedGauges();
    this->WarnOf(this->Unobserved.size(),
      "gauge(s) have no observed value (no row, or only missing values) and are never used",
      [&](std::size_t k) { return this->IdOf(this->Unobserved[k]); });
    this->WarnOfUnusedRows();
    this->WarnOf(this->Duplicates.size(),
      "gauge(s) stand where an earlier gauge stands; the first that reports is used",
      [&](std::size_t k)
      {
        return this->IdOf(this->Duplicates[k]) + " (same place as " +
          this->IdOf(this->DuplicateOf[k]) + ")";
      });
    this->CoLocatedValues = CoLocatedRows(
      *this->Rows, this->ValuesOfRows, this->In.Values, *this->In.Average, this->RepeatedRows);
    const CoLocated& coLocated = this->CoLocatedValues;
    this->WarnOf(coLocated.Rows.size(),
      "observation row(s) have a value for a gauge at the place of another that reported at the "
      "same time, whose value is used (rows from 0, listed in CoLocatedObservationRows, the rows "
      "used in their place in CoLocatedObservationOfRows)",
      [&](std::size_t k)
      {
        return RowName(this->Stations, coLocated.Rows[k]) + " (row " +
          std::to_string(coLocated.UsedRows[k]) + " used)";
      });
  }

  /// The observations' rows and station ids that are not used, and times that look mistyped.
  void WarnOfUnusedRows() const
  {
    vtkAbstractArray* stations = this->Stations;
    const std::vector<tessera::UnknownStation>& unknown = this->Rows->Match.UnknownStations;
    this->WarnOf(unknown.size(),
      "station id(s) of the observations that no gauge has: their rows were ignored (rows from 0, "
      "listed in UnusedObservationRows)",
      [&](std::size_t k) { return UnknownStationName(stations, unknown[k]); });
    const std::vector<std::int32_t>& incomplete = this->Rows->Steps.IncompleteRows;
    this->WarnOf(incomplete.size(),
      "observation row(s) have no station id or no time and were ignored (rows from 0, listed in "
      "UnusedObservationRows)",
      [&](std::size_t k) { return IncompleteRowName(stations, incomplete[k]); });
    const std::vector<tessera::SharedStation>& shared = this->Rows->Match.SharedStations;
    this->WarnOf(shared.size(),
      "station id(s) are given to more than one gauge; their observations go to the first (listed "
      "in SharedStationGaugeIds, the first gauges in SharedStationOfGaugeIds)",
      [&](std::size_t k)
      {
        return this->Names[static_cast<std::size_t>(shared[k].Gauge)] + " (gauges " +
          std::to_string(shared[k].FirstGauge) + " and " + std::to_string(shared[k].Gauge) + ")";
      });
    this->WarnOf(this->RepeatedRows.size(),
      "observation row(s) repeat a station and time of an earlier row with a value; the earlier "
      "value is used (rows from 0, listed in RepeatedObservationRows, the rows they repeat in "
      "RepeatedObservationOfRows)",
      [&](std::size_t k)
      {
        return RowName(stations, this->RepeatedRows[k]) + " repeating row " +
          std::to_string(this->RepeatedRowOf[k]);
      });
    if (this->Observations)
    {
      const vtkThiessenArealAverage* self = this->Self;
      this->Warn(CoarseTimesWarning(
        this->Observations, this->RepeatedRows.size(), self->TimeColumn, self->MonthColumn));
      this->Warn(YearZeroWarning(this->Rows->Steps, stations, self->TimeColumn, self->MonthColumn));
    }
  }

  /// Dates beside the decimal years, for a series given as dates: a CSV writer's default
  /// precision writes some months alike (ParaView's 5 digits make 1895-03 and 1895-04 both
  /// 1895.2). None, with a warning, when some time is not a date of years 0 .. 9999.
  std::vector<std::string> StepDates() const
  {
    const std::vector<double>& times = this->In.Times;
    const std::vector<std::string> dates =
      this->Rows->TimesAreDates ? tessera::DateTexts(times) : std::vector<std::string>();
    if (this->Rows->TimesAreDates && dates.empty())
    {
      this->Warn("the times are dates, but not all of them can be written as dates (years 0 .. "
                 "9999: from " +
        tessera::NumberText(times.front()) + " to " + tessera::NumberText(times.back()) +
        " as decimal years), so the tables have no Date column");
    }
    return dates;
  }

  /// The summary table's columns (output 1), a row per step.
  struct SummaryColumns
  {
    SummaryColumns()
    {
      this->Times->SetName("Time");
      this->Dates->SetName("Date");
      this->Means->SetName("ArealMean");
      this->Used->SetName("StationsUsed");
      this->Weighted->SetName("StationsWeighted");
      this->Covered->SetName("CoveredFraction");
    }
    void Append(double time, const tessera::ArealStep& result)
    {
      this->Times->InsertNextValue(time);
      this->Means->InsertNextValue(result.Mean);
      this->Used->InsertNextValue(result.StationsUsed);
      this->Weighted->InsertNextValue(result.StationsWeighted);
      this->Covered->InsertNextValue(result.CoveredFraction);
    }
    vtkNew<vtkDoubleArray> Times, Means, Covered;
    vtkNew<vtkStringArray> Dates;
    vtkNew<vtkIntArray> Used, Weighted;
  };

  /// Every step in order, each one updating the tessellation of the one before: the summary
  /// table's rows and output 2's weights. Returns per gauge whether it was weighted at a step.
  std::vector<char> AverageEveryStep(SummaryColumns& columns, const std::vector<std::string>& dates)
  {
    for (const std::string& date : dates)
    {
      columns.Dates->InsertNextValue(date);
    }
    WeightRows weightRows(this->StationIds, !dates.empty());
    std::vector<char> everWeighted(this->GaugeCount, 0);
    const std::vector<double>& times = this->In.Times;
    for (std::size_t step = 0; step < times.size(); ++step)
    {
      if (step % 16 == 0)
      {
        tessera_vtk::ProgressOrStop(this->Self, 0.9 * static_cast<double>(step) / times.size());
      }
      const tessera::ArealStep result = this->In.Average->Step(this->In.Values[step]);
      columns.Append(times[step], result);
      for (const std::int32_t g : result.Gauges)
      {
        everWeighted[static_cast<std::size_t>(g)] = 1;
      }
      if (this->Self->WeightsTable)
      {
        weightRows.Append(
          times[step], dates.empty() ? std::string() : dates[step], result, this->In.Values[step]);
      }
    }
    weightRows.Fill(this->In.Weights);
    return everWeighted;
  }

  /// Gauges with values whose tiles never reach the catchment (those without values, and gauges
  /// at the place of another, are reported above, so they count as told), and of those the ones
  /// at a longitude or latitude of exactly 0.
  void WarnOfUnweighted(std::vector<char>& everWeighted)
  {
    for (const std::vector<std::int32_t>* told : { &this->Unobserved, &this->Duplicates })
    {
      for (const std::int32_t g : *told)
      {
        everWeighted[static_cast<std::size_t>(g)] = 1;
      }
    }
    for (std::size_t g = 0; g < this->GaugeCount; ++g)
    {
      if (!everWeighted[g])
      {
        this->Unweighted.push_back(static_cast<std::int32_t>(g));
      }
    }
    this->WarnOf(this->Unweighted.size(),
      "gauge(s) have observed values, but their tiles never reach the catchment at any step, so "
      "they are never weighted (listed in UnweightedGaugeIds)",
      [&](std::size_t k) { return this->IdOf(this->Unweighted[k]); });
    // An empty field of a CSV read by vtkDelimitedTextReader with DetectNumericColumns is 0 (a
    // trial's gauge inside the catchment went to the equator so, named only among the gauges
    // never weighted).
    std::vector<std::int32_t> atZero;
    for (const std::int32_t g : this->Unweighted)
    {
      const tessera::Point2& p = this->LonLat[static_cast<std::size_t>(g)];
      if (p.x == 0.0 || p.y == 0.0)
      {
        atZero.push_back(g);
      }
    }
    this->WarnOf(atZero.size(),
      "of the gauge(s) never weighted have a longitude or latitude of exactly 0: an empty lon or "
      "lat of a CSV file read with numbers detected (vtkDelimitedTextReader's "
      "DetectNumericColumns) is 0",
      [&](std::size_t k)
      {
        const tessera::Point2& p = this->LonLat[static_cast<std::size_t>(atZero[k])];
        return this->IdOf(atZero[k]) + " at (" + tessera::NumberText(p.x) + ", " +
          tessera::NumberText(p.y) + ")";
      });
  }

  /// Output 1: the summary columns, and as field data the ids of what was not used.
  void WriteSummary(SummaryColumns& columns, bool withDates) const
  {
    vtkTable* summary = this->In.Summary;
    summary->Initialize();
    summary->AddColumn(columns.Times);
    if (withDates)
    {
      summary->AddColumn(columns.Dates);
    }
    summary->AddColumn(columns.Means);
    summary->AddColumn(columns.Used);
    summary->AddColumn(columns.Weighted);
    summary->AddColumn(columns.Covered);
    tessera_vtk::AddIdFieldArray(summary, "UnobservedGaugeIds", this->Unobserved);
    std::vector<std::int32_t> sharing, sharingOf; // a gauge with an earlier gauge's station id
    for (const tessera::SharedStation& station : this->Rows->Match.SharedStations)
    {
      sharing.push_back(station.Gauge);
      sharingOf.push_back(station.FirstGauge);
    }
    tessera_vtk::AddIdFieldArray(summary, "SharedStationGaugeIds", sharing);
    tessera_vtk::AddIdFieldArray(summary, "SharedStationOfGaugeIds", sharingOf);
    tessera_vtk::AddIdFieldArray(summary, "UnweightedGaugeIds", this->Unweighted);
    tessera_vtk::AddIdFieldArray(summary, "DuplicateGaugeIds", this->Duplicates);
    tessera_vtk::AddIdFieldArray(summary, "DuplicateOfGaugeIds", this->DuplicateOf);
    tessera_vtk::AddIdFieldArray(summary, "RepeatedObservationRows", this->RepeatedRows);
    tessera_vtk::AddIdFieldArray(summary, "RepeatedObservationOfRows", this->RepeatedRowOf);
    tessera_vtk::AddIdFieldArray(summary, "CoLocatedObservationRows", this->CoLocatedValues.Rows);
    tessera_vtk::AddIdFieldArray(
      summary, "CoLocatedObservationOfRows", this->CoLocatedValues.UsedRows);
    tessera_vtk::AddIdFieldArray(summary, "UnusedObservationRows", this->Rows->Steps.UnusedRows());
    // The projection the tiles were made in, as vtkGeographicProjection records it: another
    // average given it (ProjectionRecord) makes the same tiles, as for a part of this catchment.
    tessera_vtk::WriteProjectionRecord(summary, this->In.Average->Projection().ToString());
    tessera_vtk::ListNonEmptyFieldArraysFirst(summary);
  }

  /// The filter's warning text ("" says nothing).
  void Warn(const std::string& text) const { tesseraWarnUnlessEmptyMacro(this->Self, text); }
};

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::Build(vtkPointSet* gauges,
  vtkAbstractArray* stationIds,
  vtkDataObject* catchment,
  vtkTable* observations)
{
  static const ObservationRows noRows;
  BuildRun run(this, gauges, stationIds, observations);
  run.MakeEngine(catchment);
  run.WarnOfCatchmentAndGauges();
  Internals& in = *this->Internal;
  in.Times.clear();
  in.Values.clear();
  run.Rows = &noRows;
  if (observations)
  {
    run.ReadObservations();
  }
  else
  {
    run.ReadGaugeValues();
  }
  run.WarnOfUnusedInputs();
  BuildRun::SummaryColumns columns;
  const std::vector<std::string> dates = run.StepDates();
  std::vector<char> everWeighted = run.AverageEveryStep(columns, dates);
  run.WarnOfUnweighted(everWeighted);
  run.WriteSummary(columns, !dates.empty());
}

//------------------------------------------------------------------------------
void vtkThiessenArealAverage::WriteTiles(std::size_t step,
  vtkAbstractArray* stationIds,
  vtkPolyData* output,
  vtkPolyData* outlines)
{
  Internals& in = *this->Internal;
  const tessera::ArealStep result = in.Average->Step(in.Values[step]);
  const tessera::ClippedTilesLonLat clipped = in.Average->CurrentClippedTiles(2000.0);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : clipped.Pieces.Vertices)
  {
    points->InsertNextPoint(p.x, p.y, 0.0);
  }
  vtkNew<vtkCellArray> polys;
  TileCellData cells(stationIds, in.Average->CatchmentAreaM2());
  for (std::size_t k = 0; k < clipped.Gauges.size(); ++k)
  {
    const std::int32_t g = clipped.Gauges[k];
    const GaugeWeight weight = WeightOf(result, g);
    // One cell per piece; the gauge's Weight and Area_m2 are repeated on each of its cells, the
    // cell's own share is CellArea_m2 / CellWeight.
    for (std::size_t r = clipped.TilePieceOffsets[k]; r < clipped.TilePieceOffsets[k + 1]; ++r)
    {
      const std::size_t begin = clipped.Pieces.RingOffsets[r],
                        end = clipped.Pieces.RingOffsets[r + 1];
      polys->InsertNextCell(static_cast<vtkIdType>(end - begin));
      for (std::size_t v = begin; v < end; ++v)
      {
        polys->InsertCellPoint(static_cast<vtkIdType>(v));
      }
      cells.Append(g,
        weight.Weight,
        weight.AreaM2,
        in.Values[step][static_cast<std::size_t>(g)],
        clipped.PieceAreasM2[r]);
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  cells.AddTo(output->GetCellData());
  WriteOutlines(clipped, result, in.Values[step], stationIds, outlines);
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
  os << indent << "UseMissingValue: " << (this->UseMissingValue ? "on" : "off") << "\n";
  os << indent << "MissingValue: " << this->MissingValue << "\n";
}
