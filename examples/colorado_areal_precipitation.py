#!/usr/bin/env python3
"""Thiessen areal-average precipitation over Colorado, month by month (Thiessen 1911), or over
your own catchment, monthly, daily, hourly or by minutes (--stations, --observations,
--catchment).

The hydrologist's main job with Tessera: 376 rain gauges given in longitude/latitude (many of
them outside the state), the state outline as the catchment, and 1236 months (1895-1997) of
monthly totals of which 58% are missing. For each month the gauges that reported are
tessellated exactly (Green-Sibson), their tiles are clipped to the catchment, each gauge is
weighted by the ellipsoidal area of its tile inside the catchment, and the areal mean is the
weighted mean. A gauge outside the state still owns the part of the state nearest to it.

Writes into --out:
  areal_mean.csv         year,month,stations_used,stations_weighted,areal_mean (one row a month,
                         from the first to the last month of the observations, or from --start
                         to --end, months without
                         any row included; stations_used = gauges that reported, gauges
                         at one place counted once,
                         stations_weighted = those whose tile reaches the catchment; areal_mean
                         is empty where no gauge reported)
  areal_total_by_month.csv
                         for daily observations: year,month,days,days_with_mean,areal_total, the
                         days' areal means added up over each month (days: the calendar's);
                         areal_total is empty unless every day of the month has a mean (not for a
                         month the records cover in part, or with a day where no gauge reported);
                         areal_total_by_day.csv likewise over each day for hours (hours,
                         hours_with_mean) and steps of minutes (steps, steps_with_mean), a step
                         counted in the day it ends in but for one ending at 00:00, which closes
                         the day before (hour-ending records: hours 01:00 to 24:00)
  weights_YYYY_MM.csv    station_id,name,lon,lat,weight,area_km2,precip for --month (for each
                         --month when it is given more than once; so for the tiles and the map;
                         without --month, 1963-08 or the month nearest it where a gauge reported,
                         or with other observations, the last month where a gauge reported)
  weights_all_months.csv year,month,station_id,weight,area_km2,precip: every month's weights (a row
                         per month and gauge with a weight)
  tiles_YYYY_MM.vtp      that month's tiles clipped to the catchment, in lon/lat: simple
                         polygons, several for a tile around a lake, across a bay or under a wavy
                         outline (cell data
                         StationId, GaugeId, Weight, Area_m2 and Value per gauge, CellArea_m2
                         and CellWeight per cell)
  tiles_YYYY_MM.geojson  the same tiles for a GIS (RFC 7946): a feature per gauge, its part of the
                         catchment a polygon with holes (several for a tile across a bay), with
                         station_id, name, weight, area_km2, precip
  map_YYYY_MM.png        the tiles coloured by that month's precipitation, gauges, the outline
                         (each ring of it), over the catchment and the weighted gauges' extent
  areal_mean.png         the areal-mean time series
  unused_inputs.csv      kind,file,line,station_id,note: every gauge and observation that was valid
                         but not used (no observed value, a tile that never reaches the catchment,
                         at the place of an earlier gauge, an observation of such a gauge in a
                         month where the earlier one reported, a repeated observation, an observation of
                         a station no gauge has, and an observation before --start or after
                         --end); for a gauge at the place of an earlier one, or a repeated
                         observation, the note gives the earlier one's line, for a gauge whose
                         station id an earlier gauge has, that gauge's line, and for an
                         observation of a gauge at the place of an earlier one, the line of the
                         observation used instead; observations outside --start/--end one after
                         the other make one row: its lines first-last, and in the note how
                         many (of how many stations); the warnings name only the first 20 of
                         each kind
  areal_mean_by_ATTRIBUTE.csv
                         with --each ATTRIBUTE: ATTRIBUTE,year,month,stations_used,
                         stations_weighted,areal_mean,area_km2, the means over each group of the
                         catchment's features with one value of the attribute (each sub-basin;
                         stations_used counts all gauges that reported, as in areal_mean.csv,
                         stations_weighted those whose tiles reach the group),
                         in the whole catchment's projection (their means weighted by area_km2
                         make the whole's)
Daily observations (columns station_id, year, month, day, precip, or station_id, date, precip
with dates YYYY-MM-DD) make a step a day: areal_mean.csv and weights_all_days.csv (which
stands for weights_all_months.csv) gain a day column (year,month,day,...), --day chooses the day
of the weights, tiles and map (named YYYY_MM_DD), and every day from the first to the last has
its row. A date column of YYYY-MM gives months.
Hourly observations (an hour column, 0-23, beside year, month and day, or dates with a time on
the hour, YYYY-MM-DD HH:00) make a step an hour in the same way: an hour column (year,month,day,
hour,...), weights_all_hours.csv, --hour 'YYYY-MM-DD HH:00' (files named YYYY_MM_DD_HH), every
hour from the first to the last. Hours keep their labels (hour-ending data: 06:00 is 05:00 to
06:00), and hour 24 (24:00, as hour-ending records write a day's last hour) is hour 0 of the
next day. Dates whose times are all midnight are days; a time column beside the date is refused.
Times may end with a time zone (Z, +01:00) when all have the same offset: they are read as
written, and the options (--hour, --start, ...) take them without it.
Observations of minutes (tipping buckets, loggers: dates with times YYYY-MM-DD HH:MM, or a minute
column beside the hour) make a step some minutes long: the most minutes that divide 60 and every
time's minute (15 for times at :00, :15, :30 and :45), each step labelled by its time as hours
are; a minute column (year,month,day,hour,minute,...), weights_all_minutes.csv, --minute
'YYYY-MM-DD HH:MM' (files named YYYY_MM_DD_HH_MM), every step from the first to the last.
Only gauges' values set the step; the times that make it finer than most are apart, and gauges
of different steps (5 minutes beside 15; gauges of 8 times or more), are named. --sum-to MINUTES
sums each station's values into steps of that many minutes first (60: hours, with hour columns
and weights_all_hours.csv), such as 5-minute records into quarter hours or hours.
Observations may also be wide: a row per time (date, or year and month, with day, hour and minute
as above) and a column per station named by its station_id (date,050109,050114,...), without
station_id and precip columns; a column that names no gauge's station is named and not read.
Units are those of the data (for the Colorado data: documented as mm, the magnitudes look like
cm; see examples/data/README.md).
Files of an earlier run in --out that this run does not write (another month's map, weights and
tiles, another --each's means, areal_mean.png after --no-plots) are kept and named in a note;
--no-all-weights removes an earlier weights_all_*.csv of the same steps, and says so.

Run with Debian's /usr/bin/python3 and PYTHONPATH=build/python (scripts/demo does both).
"""

import argparse
import array
import calendar
import collections
import csv
import datetime
import itertools
import math
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")
EXAMPLE_STATIONS = os.path.join(DATA, "colorado_stations.csv")  # (the defaults, the example's own)
EXAMPLE_CATCHMENT = os.path.join(DATA, "colorado_boundary.geojson")
DEFAULT_OBSERVATIONS = os.path.join(DATA, "colorado_monthly_precip.csv")
sys.path.insert(0, HERE)

import csv_input  # noqa: E402 (the examples' CSV reading, beside this script)
import projected_input  # noqa: E402 (projected coordinates made lon/lat, beside this script)


def decimal_time(year, month):
    """Month as a time value: year + (month - 1) / 12."""
    return year + (month - 1) / 12.0


class Steps:
    """The time steps of the observations: months, as (year, month), days, as (year, month, day),
    hours, as (year, month, day, hour), or steps of some minutes (minutes: 1 to 30, a divisor of
    60, so that every hour starts a step), as (year, month, day, hour, minute), as the observations
    give them (observation_step, file_steps)."""

    UNITS = ("month", "day", "hour", "minute")
    ADJECTIVES = {"month": "monthly", "day": "daily", "hour": "hourly"}

    def __init__(self, unit, minutes=60):
        self.unit = unit
        self.minutes = minutes  # (a step of minutes: its length)
        self.fields = 2 + Steps.UNITS.index(unit)  # the numbers of a step
        self.columns = ["year", "month", "day", "hour", "minute"][:self.fields]
        self.adjective = Steps.ADJECTIVES.get(unit, f"{minutes}-minute")
        # What the messages count (a month, a day, an hour, or a 15-minute step), and say the
        # observations are (monthly, daily, hourly, or in 15-minute steps).
        self.noun = unit if unit in Steps.ADJECTIVES else f"{self.adjective} step"
        self.described = self.adjective if unit in Steps.ADJECTIVES else f"in {self.noun}s"
        self.of_time = {}  # the step of each time value made by time()

    @staticmethod
    def of(step):
        """The Steps of which step (a tuple of 2, 3 or 4 numbers: months, days or hours) is one."""
        return Steps(Steps.UNITS[len(step) - 2])

    def time(self, step):
        """The step as a time value: decimal_time of its month, plus a day's (and an hour's and a
        minute's) share of its month (of_time maps the value back: the filter gives back the times
        it was given)."""
        t = decimal_time(step[0], step[1])
        if self.fields > 2:
            days = step[2] - 1 + (step[3] / 24.0 if self.fields > 3 else 0) + (
                step[4] / 1440.0 if self.fields > 4 else 0)
            t += days / (12.0 * calendar.monthrange(step[0], step[1])[1])
        self.of_time[t] = step
        return t

    @staticmethod
    def digits(step):
        """The step's numbers as written: a year of four digits, the rest of two."""
        return [f"{v:0{4 if k == 0 else 2}d}" for k, v in enumerate(step)]

    def text(self, step):
        """2001-03, 2001-03-01, 2001-03-01 06:00 or 2001-03-01 06:15."""
        numbers = Steps.digits(step)
        text = "-".join(numbers[:3])
        if len(numbers) > 3:
            text += f" {numbers[3]}:{numbers[4] if len(numbers) > 4 else '00'}"
        return text

    def tag(self, step):
        """2001_03, 2001_03_01, 2001_03_01_06 or 2001_03_01_06_15, for file names."""
        return "_".join(Steps.digits(step))

    def length(self):
        """A step's length, for days and finer (a timedelta)."""
        return datetime.timedelta(days=1) if self.fields == 3 else datetime.timedelta(minutes=self.minutes)

    def count(self, first, last):
        """The number of steps from first to last, both included (between's length, not made)."""
        if self.fields == 2:
            return 12 * (last[0] - first[0]) + last[1] - first[1] + 1
        return (datetime.datetime(*last) - datetime.datetime(*first)) // self.length() + 1

    def between(self, first, last):
        """Every step from first to last, both included."""
        if self.fields == 2:
            return [(y, m) for y in range(first[0], last[0] + 1) for m in range(1, 13) if first <= (y, m) <= last]
        start, end, length = datetime.datetime(*first), datetime.datetime(*last), self.length()
        every = (start + k * length for k in range((end - start) // length + 1))
        return [(d.year, d.month, d.day, d.hour, d.minute)[:self.fields] for d in every]

    def on_grid(self, step):
        """Whether a step (or a coarser bound: a day, a month) is on these steps' grid (a minute a
        multiple of minutes)."""
        return len(step) < 5 or step[4] % self.minutes == 0


def is_calendar_day(year, month, day):
    return year >= 1 and 1 <= month <= 12 and 1 <= day <= calendar.monthrange(year, month)[1]


# A station id as vtkThiessenArealAverage matches it ("0102" and 102 are one station); in
# csv_input, as project_gauges.py compares ids the same way.
station_key = csv_input.station_key


def read_gauges(path, system=None, combined=False, id_field=None):
    """The gauges as a vtkPolyData (points in lon/lat, point data station_id and name), and the
    stations file's line of each gauge (gauge i is the file's i-th record; with combined, its
    i-th station). combined: the file is the observations file too (as NOAA's Climate Data Online
    writes one, a row per station and day with the station's place on each): a row repeating an
    earlier row's station at its place is that gauge's observation, not another gauge, and one
    at another place ends the script naming both lines. system: the
    projected_input.PlaneSystem of --stations-utm or --stations-crs, for a file of x and y
    columns in it, made lon/lat by the projection's inverse; without it, a file of x and y columns
    and no lon and lat ends the script saying to give the system. A GIS file of points
    (GIS_SUFFIXES) is read by read_gauge_points (id_field: --stations-id)."""
    if path.lower().endswith(GIS_SUFFIXES):
        if system:
            csv_input.fail(f"{path}: --stations-utm and --stations-crs are for a CSV file's x and y; a GIS file "
                           "declares its own coordinate system")
        return read_gauge_points(path, id_field)
    if id_field:
        csv_input.fail(f"--stations-id {id_field}: is for a GIS file of points (a CSV file's ids are its "
                       "station_id column)")

    gauges = GaugeTable()
    lines = []
    columns = csv_input.header_columns(path, "stations", ("station_id", "lon", "lat")) if system is None else set()
    if {"x", "y"} <= columns and not {"lon", "lat"} <= columns:
        csv_input.fail(f"{path}: the stations file has columns x and y, not lon and lat: if they are eastings and "
                       "northings of a UTM zone, give the zone with --stations-utm (such as 13N); of another "
                       "projected system, give it with --stations-crs (such as EPSG:5070)")
    coordinates = ("x", "y") if system else ("lon", "lat")
    place_of = {}  # (combined) station id: (its place, its first line)
    for line, _, station, name, lon, lat in csv_input.gauges(path, coordinates=coordinates, distinct=combined,
                                                             numbers=OBSERVATION_NUMBERS if combined else ()):
        if combined:
            place, first = place_of.setdefault(station, ((lon, lat), line))
            if first != line:
                if place != (lon, lat):
                    csv_input.fail(f"{path}:{line}: station {station} at ({lon:.15g}, {lat:.15g}), where line {first} "
                                   f"puts it at ({place[0]:.15g}, {place[1]:.15g}): a file of both stations and "
                                   "observations gives each station one place")
                continue
        if system and system.kind == "utm" and not projected_input.in_utm_range(system, lon, lat):
            csv_input.fail(f"{path}:{line}: ({lon:.15g}, {lat:.15g}) is not an easting and northing of a UTM zone "
                           f"({projected_input.UTM_RANGE}), as {system.describe()}")
        lines.append(line)
        gauges.add((lon, lat), station, name)
    gauges = gauges.data
    if system:
        gauges = projected_input.to_lonlat(gauges, system,
                                           lambda g: f"{path}:{lines[g]}" if 0 <= g < len(lines) else path)
    return gauges, lines


class GaugeTable:
    """The gauges as read_gauges gives them, made a gauge at a time: data, a vtkPolyData of their
    places (x, y, z 0, in doubles) with point data station_id and name."""

    def __init__(self):
        from vtkmodules.vtkCommonCore import vtkPoints, vtkStringArray
        from vtkmodules.vtkCommonDataModel import vtkPolyData

        self.points = vtkPoints()
        self.points.SetDataTypeToDouble()
        self.ids, self.names = vtkStringArray(), vtkStringArray()
        self.ids.SetName("station_id")
        self.names.SetName("name")
        self.data = vtkPolyData()
        self.data.SetPoints(self.points)
        self.data.GetPointData().AddArray(self.ids)
        self.data.GetPointData().AddArray(self.names)

    def add(self, place, station, name):
        self.points.InsertNextPoint(place[0], place[1], 0.0)
        self.ids.InsertNextValue(station)
        self.names.InsertNextValue(name)


GIS_SUFFIXES = (".geojson", ".json", ".shp", ".kml", ".gpkg", ".zip")
STATION_FIELDS = ("station_id", "station", "site_no", "id")  # (a GIS file's id attribute, in this order)


def read_gauge_points(path, id_field=None):
    """The gauges of a GIS file of points (as read_gis_file reads it): the vtkPolyData that
    read_gauges gives, and each gauge's feature number (from 1), which stands for its line in the
    messages and in unused_inputs.csv. The station id is the attribute id_field (--stations-id),
    else the first of STATION_FIELDS that the file has (in any case); the name, a "name"
    attribute where there is one. A file declaring a projected system (projected_input) is made
    lon/lat. Ends the script naming the file (and the feature) where GDAL reads no feature, a
    feature is not one point, or no attribute holds the ids."""
    from vtkmodules.vtkCommonDataModel import VTK_VERTEX

    reader, output, errors, gdal = read_gis_file(path, "stations", "a GeoJSON or shapefile of points")
    blocks = projected_input.polydata_blocks(output) if output else []
    reasons = [text for level, text in gdal if level == "ERROR"]
    if errors or not blocks:
        csv_input.fail(f"{path}: GDAL read no feature from the stations file (expected a GeoJSON or shapefile of "
                       "points, or a CSV file with a header such as station_id,lon,lat)"
                       + (f"; GDAL: {reasons[0]}" if reasons else ""))
    say_gdal_messages(path, gdal)
    numbered = list(enumerate(blocks, 1))
    layers = range(reader.GetNumberOfLayers())
    point_layers = set(projected_input.layers_of(reader, True))  # (every layer where none is of points)
    layer_of = [layer for layer in layers for _ in range(reader.GetFeatureCount(layer))]
    if len(point_layers) < len(layers) and len(layer_of) == len(numbered):
        # A GeoPackage of the gauges beside the catchment: the layers of points are the gauges
        # (their features numbered in the whole file, as GDAL gives them).
        others = [k for k, _ in numbered if layer_of[k - 1] not in point_layers]
        numbered = [(k, block) for k, block in numbered if layer_of[k - 1] in point_layers]
        print(f"note: {path}: the gauges are its {len(numbered)} feature(s) of points; its other layers' "
              f"{len(others)} feature(s) ({first_and_more(others, str)}; counted from 1) are not read as gauges",
              file=sys.stderr)
    for k, block in numbered:
        if block.GetNumberOfCells() != 1 or block.GetCellType(0) != VTK_VERTEX:
            csv_input.fail(f"{path}: feature {k} is not one point (GDAL reads it as {cell_kinds(block)}, a polygon's "
                           "rings as lines): a stations file holds a point per gauge (features counted from 1)")
    data = numbered[0][1].GetCellData()
    fields = [data.GetAbstractArray(i).GetName() for i in range(data.GetNumberOfArrays())]
    lower = {}
    for name in fields:
        lower.setdefault(name.lower(), name)
    field = lower.get(id_field.lower()) if id_field else next((lower[f] for f in STATION_FIELDS if f in lower), None)
    if field not in fields:
        wanted = f"named {id_field!r}" if id_field else f"holds the station ids ({', '.join(STATION_FIELDS)})"
        csv_input.fail(f"{path}: no attribute {wanted}; its attributes: {', '.join(fields) or 'none'} (give the one "
                       "holding the ids with --stations-id)")
    table = GaugeTable()
    for k, block in numbered:
        values = block.GetCellData().GetAbstractArray(field)
        station = attribute_text(values).strip() if values else ""
        if not station:
            csv_input.fail(f"{path}: feature {k}: its attribute {field!r} (the station id) is empty (features counted "
                           "from 1)")
        name = block.GetCellData().GetAbstractArray(lower.get("name", ""))
        table.add(block.GetPoint(block.GetCell(0).GetPointId(0)), station, attribute_text(name).strip() if name else "")
    gauges = table.data
    xy = [gauges.GetPoint(g)[:2] for g in range(gauges.GetNumberOfPoints())]
    def feature(g):
        return f"feature {numbered[g][0]} (counted from 1)"

    system = projected_input.declared_system(reader, [xy], path, points=True, point_name=feature)
    if system:
        gauges = projected_input.to_lonlat(gauges, system, lambda g: f"{path}: {feature(g)}")
    say_declared_systems(reader, path, system, points=True)
    return gauges, [k for k, _ in numbered]


def holds_observations(stations, observations):
    """Whether the stations file is a file of observations too, a row per station and time with the
    station's place on each (as NOAA's Climate Data Online writes one): the observations file
    itself, or a CSV file with a precip column (or PRCP, ALIAS_OF)."""
    if not (os.path.isfile(stations) and not stations.lower().endswith(GIS_SUFFIXES)):
        return False
    if os.path.isfile(observations) and os.path.samefile(stations, observations):
        return True
    return "precip" in csv_input.header_columns(stations, "stations", ("station_id", "lon", "lat"))


def check_missing_values(codes):
    """Ends the script for a --missing-value that would do harm or nothing: 0 made every dry month
    missing (a mean of 2.463 for 1.185, the dry gauges listed as never reporting), and NaN or an
    infinity matches no value read (a value is a finite number, or missing). The filter refuses a
    MissingValue of 0 or NaN alike."""
    for code in codes:
        if code == 0:
            sys.exit("--missing-value 0 would make every zero value (a dry step) missing; give the number that "
                     "marks missing values, such as -9999")
        if not math.isfinite(code):
            sys.exit(f"--missing-value {code:g} changes nothing: every value read is a finite number or missing "
                     "(empty, NA); give the number that marks missing values, such as -9999")


def stations_path(observations):
    """--stations' default: the observations file where its header has station_id, lon and lat
    (or names ALIAS_OF reads as them), else the Colorado gauges."""
    if observations and os.path.isfile(observations):
        if {"station_id", "lon", "lat"} <= csv_input.header_columns(observations, "observations",
                                                                  ("station_id", "lon", "lat")):
            return observations
    return EXAMPLE_STATIONS


DATE = re.compile(r"([0-9]{4})-([0-9]{1,2})(?:-([0-9]{1,2}))?")
# A time of day after a date (2001-02-03T06:00, 2001-02-03 06:00:00), as a spreadsheet or a
# program writes a timestamp.
TIME_OF_DAY = re.compile(r"[T ]([0-9]{1,2}):([0-9]{2})(?::([0-9]{2})(?:\.([0-9]+))?)?")
# A time zone after a time of day: Z, or an offset (+01:00, -0700, +05); every time of a file in
# the same one, read as written (not moved to UTC).
ZONE = re.compile(r"[Zz]|([+-])([0-9]{2})(?::?([0-9]{2}))?")


def observation_step(row, path, line):
    """The month (year, month), day (year, month, day) or day and time (year, month, day, hour,
    minute: the hour 0 to 24, 24 only at minute 0) of an observations record: from its year,
    month, day, hour and minute columns (day, hour and minute where given), or from its date column
    (YYYY-MM for a month, YYYY-MM-DD for a day, with a time HH:MM for a time of the day); with
    the time's zone (date_column_step's, for check_zone) or None. read_observations makes the
    file's steps of them (file_steps). Ends the script naming file, line and column for a value
    that is no such date."""
    check_time_columns(row, path)
    clock = zone = None
    if "date" in row:
        step, where, clock, zone = date_column_step(row, path, line)
    elif "year" in row and "month" in row:
        step, where = year_month_step(row, path, line)
    else:
        fail_without_time_columns(row, path)
    if not (1 <= step[0] and 1 <= step[1] <= 12) or (len(step) == 3 and not is_calendar_day(*step)):
        csv_input.fail(f"{where} is not a date of the calendar" if "date" in row else f"{where} is not a day of "
                       f"{step[0]}-{step[1]:02d}")
    if clock:
        hour, minute = int(clock.group(1)), int(clock.group(2))
        if hour > 24 or minute > 59 or (hour == 24 and minute):
            csv_input.fail(f"{where} is not a time of the day (00:00 to 23:59, or 24:00 for the day's end)")
        return (*step, hour, minute), zone
    if "hour" in row:
        return hour_column_step(step, row, path, line), None
    return step, None


def check_time_columns(row, path):
    """Ends the script for an observations file whose time columns clash (a date column beside
    year/month/... columns, a time column beside an hour, date or day column)."""
    if "date" in row and any(name in row for name in ("year", "month", "day", "hour", "minute")):
        csv_input.fail(f"{path}: the observations file has both a date column and year/month/day/hour columns "
                       "(keep one)")
    if "time" in row and ("date" in row or "day" in row):
        # (ignored, it made hours of one day the repeats of its first hour)
        beside = "hour" if "hour" in row else "date" if "date" in row else "day"
        csv_input.fail(f"{path}: the observations file has a time column beside its {beside} column: " +
                       ("leave one of them out" if beside == "hour" else
                        "give hours as dates with their time in one column (YYYY-MM-DD HH:00) or in an hour column "
                        "(0-23); if it is the time each day was read, leave it out"))


def date_column_step(row, path, line):
    """observation_step's date column read: the step's date fields, where they were written (for
    the messages), the match of its time of day (TIME_OF_DAY) or None, and its time zone (ZONE's
    text and its offset in minutes) or None."""
    text = csv_input.text(row, "date", path, line)
    date = DATE.match(text)
    step = tuple(int(v) for v in date.groups() if v is not None) if date else ()
    where = f"{path}:{line}: column 'date': {text!r}"
    timed = TIME_OF_DAY.match(text, date.end()) if date and date.group(3) else None
    zone = zone_of(ZONE.fullmatch(text, timed.end())) if timed and timed.end() < len(text) else None
    clock = timed if timed and (timed.end() == len(text) or zone) else None
    if not date or (date.end() < len(text) and not clock):
        csv_input.fail(f"{where} is not a date (YYYY-MM-DD, YYYY-MM-DD HH:00 for an hour, YYYY-MM-DD HH:MM for a "
                       "step of minutes, or YYYY-MM for a month; a time may end with a time zone, Z or +01:00, "
                       "the same for every time)")
    if clock and any(int(v or 0) for v in clock.groups()[2:]):
        csv_input.fail(f"{where} is not on the minute: the steps are minutes (HH:MM), hours, days or months, so "
                       "give each step's total at its minute")
    return step, where, clock, zone


def zone_of(match):
    """A ZONE match's text and offset from UTC in minutes; None for no match, or an offset beyond
    23:59."""
    if not match:
        return None
    if match.group(0) in ("Z", "z"):
        return match.group(0), 0
    sign, hours, minutes = match.group(1), int(match.group(2)), int(match.group(3) or 0)
    if hours > 23 or minutes > 59:
        return None
    return match.group(0), (-1 if sign == "-" else 1) * (60 * hours + minutes)


def year_month_step(row, path, line):
    """observation_step's year, month and day columns read: the step's date fields, and where the
    day was written (for the messages)."""
    year = (row.get("year") or "").strip()
    if re.fullmatch(r"\+?0*[0-9]{1,2}(?:[.,]0*)?", year):
        # (99 would be AD 99, and 00 no year at all: most likely a year shortened to two digits)
        csv_input.fail(f"{path}:{line}: column 'year': {year!r} is a year below 100: write years in full "
                       "(1999, 2000)")
    step = (csv_input.integer(row, "year", path, line, 1, 9999),
            csv_input.integer(row, "month", path, line, 1, 12))
    if "hour" in row and "day" not in row:
        csv_input.fail(f"{path}: the observations file has an hour column but no day column "
                       "(hours need year, month, day and hour)")
    if "minute" in row and "hour" not in row:
        csv_input.fail(f"{path}: the observations file has a minute column but no hour column "
                       "(minutes need year, month, day, hour and minute)")
    if "day" in row:
        step += (csv_input.integer(row, "day", path, line, 1, 31),)
    where = f"{path}:{line}: column 'day': {step[-1]}"
    return step, where


def fail_without_time_columns(row, path):
    """Ends the script for an observations file with neither year and month nor date columns."""
    columns = ", ".join(name for name in row if name is not None)
    lacking = " and ".join(name for name in ("year", "month") if name not in row)
    csv_input.fail(f"{path}: the observations file has no column{'s' if ' and ' in lacking else ''} {lacking}, "
                   "nor a date column "
                   f"(it needs station_id, year, month, precip, with day for daily values and hour for "
                   f"hourly ones, or station_id, date, precip; its header: {columns})")


def hour_column_step(step, row, path, line):
    """step (a day) with the time of its hour and minute columns (minute 0 without one)."""
    hour = csv_input.integer(row, "hour", path, line, 0, 24)
    minute = csv_input.integer(row, "minute", path, line, 0, 59) if "minute" in row else 0
    if hour == 24 and minute:
        csv_input.fail(f"{path}:{line}: columns 'hour' and 'minute': 24:{minute:02d} is not a time of the day "
                       "(hour 24 is the day's end, 24:00)")
    return (*step, hour, minute)


# observation_step's steps by their length ("time": a date with a time; "hour" where that time is
# not midnight, "minute" where it is not on the hour), what the messages call them, and the kinds
# one file cannot mix.
STEP_KINDS = {2: "month", 3: "day", 5: "time"}
STEP_NAMES = {"month": "a month", "day": "a day", "time": "a day and time", "hour": "an hour",
              "minute": "a time of day"}


def step_kind(step):
    kind = STEP_KINDS[len(step)]
    if kind == "time" and step[4]:
        return "minute"
    return "hour" if kind == "time" and step[3] % 24 else kind


def steps_clash(kind, other):
    return kind != other and ("month" in (kind, other) or (
        "day" in (kind, other) and bool({kind, other} & {"hour", "minute"})))


def hour_step(step):
    """A time (year, month, day, hour, and a minute where given) with hour 24, the end of the day,
    as hour 0 of the next day."""
    if step[3] < 24:
        return step
    after = datetime.date(*step[:3]) + datetime.timedelta(1)
    return (after.year, after.month, after.day, 0, *step[4:])


def file_steps(rows, path, station_ids, sum_to=None):
    """The steps of an observations file (Steps), and the step of each one observation_step read
    (rows: scan_observations'). The steps are times of the day where the file has an hour column
    or a date with a time other than midnight: hours when every time used is on the hour, else
    steps of the largest number of minutes that divides 60 and every used time's minute (15 for
    times at :00, :15, :30 and :45), each step the total of the minutes up to its time, as
    tipping-bucket and logger records give them. A time is used where a gauge's station has a
    value then (rows.reporting; --start/--end aside, as the period is one of the steps made of the
    times): a row without a value or of no gauge's station does not make the steps finer, and goes
    to the step that ends after its time (step_at_grid). Hour 24 (24:00) is hour 0 of the next
    day, as hour-ending records write a day's last hour, which is said. Dates with times all at
    midnight (00:00, or 24:00 for a day's end) are days, as a spreadsheet may export them: a day
    at 24:00 is the day it ends. Times all at one time of day over several days are said (daily
    values stamped with the hour they are read), and so are the times that make the steps finer
    than most times are apart and gauges whose times keep to different steps than the means'
    (say_step_grids; sum_to: --sum-to's minutes, the means' steps where given)."""
    read, first = set(rows.step_index), rows.first
    if not (rows.hour_column or "hour" in first or "minute" in first):
        return Steps("month" if "month" in first or not first else "day"), {m: m[:3] for m in read}
    if rows.at_24:
        print(f"{path}: {rows.at_24} observation(s) at hour 24 (the end of a day) are read as hour 0 of the next day",
              file=sys.stderr)
    used = rows.reporting or dict.fromkeys(read, set())
    minutes = math.gcd(60, *(m[4] for m in used))
    steps = Steps("hour") if minutes == 60 else Steps("minute", minutes)
    if len({m[3:] for m in read}) == 1 and len({m[:3] for m in read}) > 1:
        # Daily values stamped with the time their day ends (a climate day read at 07:00) would be
        # read as hours with 23 hours without a report between them: said, as for days of months.
        print(f"{path}: every time is {'{:02d}:{:02d}'.format(*next(iter(read))[3:])}; if these are daily values "
              "(a day read at that time), " + ("leave out the hour column" if rows.hour_column else
                                "give the dates without the time (YYYY-MM-DD)") +
              f": they are read as {steps.noun}s", file=sys.stderr)
    say_step_grids(rows, used, steps, path, station_ids, sum_to)
    return steps, {m: step_at_grid(hour_step(m), minutes)[:steps.fields] for m in read}


def step_at_grid(time, minutes):
    """A time (year, month, day, hour, minute; hour below 24) as the step of minutes that holds it:
    itself on the grid, else the step that ends after it (a step is the total of the minutes up to
    its time)."""
    late = time[4] % minutes
    if not late:
        return time
    try:
        after = datetime.datetime(*time) + datetime.timedelta(minutes=minutes - late)
    except OverflowError:  # (after 9999-12-31 23:00: the step before, the calendar's last)
        return (*time[:4], time[4] - late)
    return (after.year, after.month, after.day, after.hour, after.minute)


# The times that make a pattern of steps: a gauge's, or those of most rows of a file. Fewer may
# keep to a coarser grid by chance: 4 times of 5-minute steps are all at multiples of 15 minutes
# once in 81, 8 of them once in 6561.
PATTERN_TIMES = 8


def say_step_grids(rows, used, steps, path, station_ids, sum_to):
    """Names what made steps of minutes finer than the times mostly are, and the times off the
    steps' grid (used: the times with a gauge's value, and those gauges; station_ids: the gauges'
    ids; sum_to: --sum-to's minutes, or None)."""
    off = say_few_times_off_a_grid(rows, used, steps, path) if steps.minutes < 60 else ()
    unused = sorted(m for m in rows.step_index if m not in used and m[4] % steps.minutes)
    if unused:
        print(f"{path}: {len(unused)} time(s) of rows without a value or of no gauge's station are not "
              f"{at_multiples(steps.minutes)}, as the steps are, and are read at the step after them: "
              f"{times_and_lines(rows, unused, rows.first_line)}", file=sys.stderr)
    say_gauges_of_other_steps({m: gauges for m, gauges in used.items() if m not in off}, sum_to or steps.minutes,
                              path, station_ids)


def say_few_times_off_a_grid(rows, used, steps, path):
    """Names the few used times off the grid of all the others (at most 1 in 100, or 1), where a
    mistyped :07 among quarter hours makes 1-minute steps, each by the line of its first value;
    returns them (a set)."""
    coarser = (d for d in range(60, steps.minutes, -1) if 60 % d == 0 and d % steps.minutes == 0)
    off_grid = ((d, sorted(m for m in used if m[4] % d)) for d in coarser)
    grid, off = next(((d, off) for d, off in off_grid
                      if len(used) - PATTERN_TIMES >= len(off) <= max(1, len(used) // 100)), (None, []))
    if not grid:
        return set()
    print(f"{path}: read {steps.described} because of {len(off)} time(s) not {at_multiples(grid)} as the others "
          f"are: {times_and_lines(rows, off, rows.valued_line)}; if they are mistyped, mend them", file=sys.stderr)
    return set(off)


def say_gauges_of_other_steps(used, minutes, path, station_ids):
    """Warns when gauges' times keep to different steps (each gauge of PATTERN_TIMES times or
    more), some longer than the means' (minutes): their values may be totals over different
    lengths of time."""
    grids, times = {}, collections.Counter()
    for m, gauges in used.items():
        for gauge in gauges:
            grids[gauge] = math.gcd(grids.get(gauge, 60), m[4])
            times[gauge] += 1
    by_grid = {}
    for gauge in sorted(grids):
        if times[gauge] >= PATTERN_TIMES:
            by_grid.setdefault(grids[gauge], []).append(station_ids[gauge])
    if len(by_grid) > 1 and max(by_grid) > minutes:
        listed = "; ".join(f"{at_multiples(grid)} for {len(ids)} gauge(s) ({first_and_more(ids, str, 5)})"
                           for grid, ids in sorted(by_grid.items()))
        longest = max(by_grid)
        print(f"{path}: the gauges' times keep to different steps: {listed}. The means are of {minutes}-minute "
              "steps, and a gauge is taken as not reporting at a step without its row: where a gauge's values are "
              "totals over its longer step, the means add totals of different lengths (--sum-to "
              f"{longest} sums every gauge's values to steps of {longest} minutes)", file=sys.stderr)


def times_and_lines(rows, times, line_of):
    """'line 62 (2001-03-01 10:07), ...': each time (observation_step's) with its line (line_of:
    rows.first_line or rows.valued_line)."""
    return first_and_more(times, lambda m: f"line {line_of[m]} ({Steps.of(m).text(m)})")


def at_multiples(minutes):
    """Where the times of steps of minutes fall: 'on the hour', 'at multiples of 15 minutes'."""
    return "on the hour" if minutes == 60 else "at any minute" if minutes == 1 else f"at multiples of {minutes} minutes"


TIME_COLUMNS = ("year", "month", "day", "hour", "minute", "date", "time")  # (observation_step's)
# The columns of a long observations file read as numbers, with the place of a file of both stations
# and observations: their fields alone tell whether the file's numbers have decimal commas
# (csv_input.rows' numbers), read as stations or as observations (a name 3,5 or a height 5,280
# with digit grouping in another column does not).
OBSERVATION_NUMBERS = ("precip", "year", "month", "day", "hour", "minute", "lon", "lat", "x", "y")


def observation_numbers(columns, gauge_of):
    """The columns of an observations file (its header's, as csv_input.rows names them) that are
    read as numbers: OBSERVATION_NUMBERS, and in a wide file (without station_id and precip) the
    columns that name a gauge's station (gauge_of, by station_key)."""
    if "station_id" in columns or "precip" in columns:
        return OBSERVATION_NUMBERS
    return (*OBSERVATION_NUMBERS, *(name for name in columns
                                    if name not in TIME_COLUMNS and station_key(name) in gauge_of))


def observation_records(path, gauge_of, stations_path, station_ids, unmatched, gaps, repeats, flagged,
                        drop_flagged=False):
    """Yields (line, row, station_id, value column) for each observation of the file at path, in
    either of two layouts:
    - long: a record per station and time, with columns station_id and precip (the value column);
    - wide: a record per time, with a column per station named by its id (as a spreadsheet or a
      data portal gives a record: date,05-1234,05-2345,...) beside the time columns, and no
      station_id or precip column. The station columns whose id a gauge has (station_key) give
      an observation per record where they hold a value (a record without any gives its first
      column's, missing), in the header's order, the column being the value column;
      those whose id no gauge has are not read, but appended to unmatched as (column number from 1,
      name). Ends the script when none of them is a gauge's, naming the stations
      file (stations_path) and some of its ids as written (station_ids), when two columns name
      one gauge's station (which of them holds its values would be a guess), or when it has no
      time column. The cells without a value passed over are appended to gaps as (the index of
      the line's first record yielded, how many), a row repeating the time of an earlier one to
      repeats as (that index, line, the earlier line): the caller names those within --start/--end
      once it knows which records are, as it does its own records' odd values.
    A file with only one of station_id and precip is a long file lacking the other (named). A long
    file's records whose quality flag (noaa_quality_flag) is set are appended to flagged as (line,
    flag, station_id), before the record is yielded."""
    header = []
    records = csv_input.rows(path, (), "observations", ("station_id", "precip", *TIME_COLUMNS), header,
                             ("station_id", "precip"), lambda columns: observation_numbers(columns, gauge_of))
    first = next(records, None)  # (the header is read with it)
    records = itertools.chain((first,) if first else (), records)
    if "station_id" in header or "precip" in header:
        yield from long_records(path, header, records, flagged, drop_flagged)
        return
    check_wide_header(path, header)
    columns = wide_columns(path, header, gauge_of, stations_path, station_ids, unmatched)
    yield from wide_records(records, header, columns, gaps, repeats)


def long_records(path, header, records, flagged, drop_flagged):
    """observation_records' records of a long file (header: its columns)."""
    csv_input.check_columns(path, "observations", ("station_id", "precip"), header)
    attributes = next((name for name in header if name.lower() in NOAA_ATTRIBUTES), None)
    say_unnamed_columns(path, header)
    if drop_flagged and not attributes:
        print(f"{path}: --drop-flagged: the file has no PRCP_ATTRIBUTES column (NOAA's quality flags), so no "
              "value is left out", file=sys.stderr)
    for line, row in records:
        station = csv_input.text(row, "station_id", path, line)
        if attributes and (flag := noaa_quality_flag(row.get(attributes))):
            flagged.append((line, flag, station))
        yield line, row, station, "precip"


def check_wide_header(path, header):
    """Ends the script for a file read as wide that has no header, or no time column in it."""
    if not header:
        csv_input.fail(f"{path}: the observations file is empty (no header, no rows); expected a long file "
                       "(station_id, a time column such as date, precip) or a wide one (a time column, a column "
                       "per station)")
    if not any(name in TIME_COLUMNS for name in header):
        unnamed = " (its first column has no name: if it holds the times, name it date)" if header[:1] == [""] else ""
        csv_input.fail(f"{path}: the observations file has no station_id and precip columns, so it is read as a "
                       "wide file (a row per time, a column per station), but it has no time column: date, or "
                       f"year and month{unnamed}; its header: {', '.join(header) or 'none'}")


def wide_columns(path, header, gauge_of, stations_path, station_ids, unmatched):
    """A wide file's value columns: those naming a gauge's station (observation_records)."""
    columns, named = [], {}  # (the value columns, and the first column of each gauge's station)
    for number, name in enumerate(header, 1):
        if name in TIME_COLUMNS:
            continue
        key = station_key(name)
        if key not in gauge_of:  # (an empty name too: a trailing separator, or a column left unnamed)
            unmatched.append((number, name))
            continue
        if key in named:
            csv_input.fail(f"{path}:1: columns {named[key]} and {number} both name station {name!r}: keep one")
        named[key] = number
        columns.append(name)
    if not columns:
        there = list(dict.fromkeys(station_ids))
        csv_input.fail(f"{path}: the observations file has no station_id and precip columns, and none of its "
                       f"other columns names a station of {stations_path} (columns here: "
                       f"{', '.join(header) or 'none'}; ids there: {', '.join(there[:5])}"
                       f"{', ...' if len(there) > 5 else ''}): give a row per station and time (columns "
                       "station_id, year, month, precip, or station_id, date, precip), or a row per time "
                       "with a column per station named by its station_id (date,ID1,ID2,...)")
    return columns


def wide_records(records, header, columns, gaps, repeats):
    """observation_records' records of a wide file (columns: its value columns, wide_columns')."""
    times = [name for name in header if name in TIME_COLUMNS]
    first_line = {}  # each row's time as written, and the line that first gave it
    yielded = 0  # the records yielded so far
    for line, row in records:
        written = tuple((row.get(name) or "").strip() for name in times)
        if first_line.setdefault(written, line) != line:
            repeats.append((yielded, line, first_line[written]))
        # Only the cells with a value (a wide record is mostly gaps: 58% of Colorado's cells), and
        # the first cell of a row without any, whose time stays a step where no gauge reported.
        reported = [column for column in columns if not csv_input.is_missing(row.get(column))]
        if len(columns) > max(len(reported), 1):  # (the cells passed over, for the count)
            gaps.append((yielded, len(columns) - max(len(reported), 1)))
        for column in reported or columns[:1]:
            yield line, row, column, column
        yielded += max(len(reported), 1)


def say_unnamed_columns(path, header):
    """Names a long file's columns without a name (a pandas index written with its frame), which
    are not read; a wide file's are named with the columns that name no station."""
    unnamed = [number for number, name in enumerate(header, 1) if not name]
    if unnamed:
        which = f"column {unnamed[0]} has" if len(unnamed) == 1 else f"columns {', '.join(map(str, unnamed))} have"
        print(f"note: {path}: {which} no name (a row index, or a separator ending each line?) and "
              f"{'is' if len(unnamed) == 1 else 'are'} not read", file=sys.stderr)


# The column of NOAA's Climate Data Online CSV beside PRCP: "MFLAG,QFLAG,SFLAG,OBSTIME" for GHCN-Daily.
NOAA_ATTRIBUTES = ("prcp_attributes", "precip_attributes")


def noaa_quality_flag(attributes):
    """The quality flag (QFLAG, the second field) of NOAA's GHCN-Daily attributes text
    ("MFLAG,QFLAG,SFLAG" with OBSTIME after, such as ",I,7,0700": I, a value that failed the
    internal consistency check); "" where it is blank (the value passed every check) or the text
    has not that form."""
    fields = (attributes or "").split(",")
    return fields[1].strip() if len(fields) >= 3 else ""


def say_quality_flags(path, flagged, dropped):
    """Names the observations whose NOAA quality flag is set (flagged: (line, flag, station_id)):
    used as given, or with dropped (--drop-flagged) read as missing."""
    if flagged:
        shown = first_and_more(flagged, lambda item: f"line {item[0]} ({item[1]})")
        done = ("are left out, read as missing (--drop-flagged; unused_inputs.csv lists them)" if dropped else
                "are used as given (--drop-flagged leaves them out)")
        print(f"{path}: {len(flagged)} observation(s) have a NOAA quality flag (QFLAG, the second field of "
              f"PRCP_ATTRIBUTES: the value failed a quality check) and {done}: {shown}", file=sys.stderr)


def say_repeated_times(path, repeats):
    """Names a wide file's rows that repeat the time of an earlier row (repeats: observation_records'
    (record, line, the earlier line)). A repeated time is a repeated observation for each station, as in a long file: the
    earlier value is used, a repeat's fills an earlier empty cell; said here by row."""
    if repeats:
        shown = first_and_more(repeats, lambda repeat: f"line {repeat[1]} (as line {repeat[2]})")
        print(f"{path}: {len(repeats)} row(s) repeat the time of an earlier row: {shown}; where both have a value "
              "the earlier one is used, and a repeat's value fills an earlier empty cell", file=sys.stderr)


def first_and_more(items, describe, count=20):
    """The first count items, each as describe gives it, joined by commas, then ' and N more' for
    the rest (a warning names a few of what may be millions)."""
    more = f" and {len(items) - count} more" if len(items) > count else ""
    return ", ".join(describe(item) for item in items[:count]) + more


# The most steps (hours, in practice) from the first observation's to the last's: every step
# between is a row of areal_mean.csv, and a million took 0.9 GB. A mistyped year 1000 in a 2020
# record of hours would make 8.9 million (some 8 GB): refused. A mistyped 1900 makes 1,051,896
# (0.9 GB, 8 s), which a century of hours also is: taken, and the warning on steps without any
# row names the lines of the first and the last step.
MOST_STEPS = 2_000_000


# What read_observations gives: the observations as a long-format vtkTable (station_id, time,
# precip); their steps (Steps: months, days, hours or minutes); the set of reporting gauges of every step,
# as gauge indices; the file's line of each observation read (table row r, counted from 0, is the
# observation of line lines[r]; the rows after them are the filler rows of steps without a row of
# a gauge's station); a wide file's columns that are no gauge's station, not read, as (column
# number, name); the observations outside --start/--end, in runs (rows_in_period); the Period.
# read: the number of observations the file gave (more than the table's rows where --sum-to summed
# them).
# summed_repeats: the rows --sum-to left out as repeats (sum_rows'). dropped: the rows --drop-flagged
# read as missing, as (line, flag, station_id).
Observations = collections.namedtuple("Observations",
                                      "table steps reporting lines unmatched outside period read summed_repeats "
                                      "dropped")


def read_observations(path, gauge_of, filler, stations_path, missing_values=(), station_ids=(), bounds=(None, None),
                      bound_texts=(None, None), sum_to=None, drop_flagged=False):
    """The observations of a long or a wide file (observation_records), as Observations. gauge_of:
    the gauge that a station's observations go to, by station_key() (ids are compared as the filter
    compares them; a step none of whose rows names a gauge's station is a step where no gauge
    reported). filler: a gauge's station id, given to the rows of those steps. missing_values:
    numbers that mean missing (--missing-value, such as -9999), read as a missing value. Ends the
    script when no row names a gauge's station, naming the stations file (stations_path) and some
    of its ids as written (station_ids): ids that do not match at all (a prefix, another numbering)
    would otherwise give months without a mean. bounds: --start's and --end's steps
    (period_bound's, or None), as bound_texts gives them: only the observations between them are
    in the table (the others are in Observations.outside), and the table's steps run from the one
    to the other. sum_to: --sum-to's minutes, or None: each gauge's values are summed into steps of
    that many minutes (sum_rows). drop_flagged: values with a NOAA quality flag are read as
    missing."""
    from vtkmodules.vtkCommonDataModel import vtkTable

    rows = scan_observations(path, gauge_of, stations_path, station_ids, missing_values, drop_flagged)
    steps, step_of = file_steps(rows, path, station_ids, sum_to)
    if sum_to:
        fine = (steps.minutes, step_of)  # (the file's steps, for sum_rows)
        steps, step_of = summed_steps(steps, step_of, sum_to, path)
    rows.take_steps(step_of)
    period = Period(steps, *bounds, bound_texts, path)
    if rows.lines and not rows.present:
        # (the ids as written, each once, in the files' order: they are for comparing by eye)
        seen, there = list(rows.names), list(dict.fromkeys(station_ids))
        csv_input.fail(f"{path}: none of its {len(rows.lines)} rows names a station of {stations_path} "
                       f"(ids here: {', '.join(seen[:5])}{', ...' if len(seen) > 5 else ''}; ids there: "
                       f"{', '.join(there[:5])}{', ...' if len(there) > 5 else ''})")
    outside = keep_period(rows, period, steps, step_of, path, bound_texts) if period.given() else []
    if rows.flagged:  # (those outside --start/--end are listed as such)
        kept = set(rows.lines)
        rows.flagged = [item for item in rows.flagged if item[0] in kept]
    say_odd_observations(rows, path, stations_path, missing_values, steps, drop_flagged)
    # (a wide file's empty cells, which make no row, counted as a long file's rows without a value)
    read = len(rows.lines) + sum(count for _, count in rows.gaps)
    if sum_to:
        sum_rows(rows, steps, step_of, fine, path)
    # A step between the first and the last without a row of any gauge's station is a step where
    # no gauge reported: a row with a missing value (for a gauge's station: the filter makes no
    # step of a row naming a station no gauge has) keeps it a step of its own, so that
    # areal_mean.csv has every month (or day, or hour), empty where nothing was measured.
    times = rows.times(steps, step_of)
    if rows.every_step and gauge_of:
        add_steps_without_rows(rows, times, steps, step_of, period, filler, path)
    table = vtkTable()
    for column in (rows.stations, times, rows.values):
        table.AddColumn(column)
    return Observations(table, steps, rows.reporting, rows.lines, rows.unmatched, outside, period, read,
                        rows.summed_repeats, rows.flagged if drop_flagged else [])


def summed_steps(steps, step_of, minutes, path):
    """--sum-to's steps (minutes: a divisor of 60, 60 for hours) for a file of finer steps of
    minutes (steps), and the step each time read (step_of: the file's steps of them) goes to: the
    step that holds it (step_at_grid: 10:05 and 10:15 go to 10:15 in 15-minute steps); ends the
    script, naming the file's steps, where they are not minutes of which minutes is a multiple
    (or hours, for 60)."""
    if steps.unit == "hour" and minutes == 60:
        return steps, step_of
    if steps.unit != "minute" or minutes % steps.minutes:
        finer = [m for m in range(steps.minutes * 2, 61, steps.minutes) if 60 % m == 0]
        csv_input.fail(f"--sum-to {minutes}: the observations of {path} are {steps.described}" + (
            f": give a multiple of {steps.minutes} that divides 60 ({', '.join(map(str, finer))})"
            if steps.unit == "minute" else " (--sum-to sums steps of minutes into longer ones)"))
    summed = Steps("hour") if minutes == 60 else Steps("minute", minutes)
    return summed, {m: step_at_grid(step, minutes)[:summed.fields] for m, step in step_of.items()}


def sum_rows(rows, steps, step_of, fine, path):
    """Sums the rows (ObservationRows, after keep_period) of each station and step (steps,
    step_of: summed_steps') into one row with the first row's station id as written, line and
    time: the sum of its values, missing where none has one (fine: the file's steps' minutes, and
    the file's step of each time read). A row repeating a station and time of the file's steps
    where an earlier row has a value is left out, as the filter leaves one out (the earlier value
    is used), and kept in rows.summed_repeats as (line, the earlier row's line, station id);
    say_sums names those, counts the sums without a value for a time whose rows are all missing,
    and names a first or last step that holds only part of its minutes."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray

    stations, values = vtkStringArray(), vtkDoubleArray()
    stations.SetName(rows.stations.GetName())
    values.SetName(rows.values.GetName())
    lines, read, missing_kind = array.array("l"), array.array("l"), array.array("b")
    times = list(rows.step_index)  # (by index)
    # Each time read as its place within the step it goes to (from 0: the step of the file that
    # ends the summed step), for the bits of a sum's places.
    length, fine_of = datetime.timedelta(minutes=fine[0]), fine[1]
    place = [(as_datetime(step_of[m]) - as_datetime(fine_of[m])) // length for m in times]
    filled, gaps = [], []  # per sum, the bits of its places with a value, and with a missing one
    repeated, valued = [], set()  # (row, sum, bit) of the repeats; the step indices with a value
    for r, at, bit in sum_places(rows, times, step_of, place):
        if at == len(filled):
            filled.append(0)
            gaps.append(0)
            stations.InsertNextValue(rows.stations.GetValue(r))
            values.InsertNextValue(math.nan)
            lines.append(rows.lines[r])
            read.append(rows.read[r])
            missing_kind.append(rows.missing_kind[r])
        if rows.missing_kind[r]:
            gaps[at] |= bit
            continue
        if filled[at] & bit:
            repeated.append((r, at, bit))
            continue
        filled[at] |= bit
        valued.add(rows.read[r])
        value = rows.values.GetValue(r)
        values.SetValue(at, value if math.isnan(values.GetValue(at)) else values.GetValue(at) + value)
        missing_kind[at] = 0
    rows.summed_repeats = earlier_lines(rows, times, step_of, place, repeated)
    partial = sum(1 for have, lack in zip(filled, gaps) if have and lack & ~have)
    say_sums(len(rows.lines), len(filled), rows.summed_repeats, partial, steps, path)
    if valued:
        ends = sorted((fine_of[times[k]], step_of[times[k]]) for k in valued)
        say_partial_ends(ends[0], ends[-1], steps, fine[0], path)
    rows.stations, rows.values, rows.lines, rows.read, rows.missing_kind = stations, values, lines, read, missing_kind


def sum_places(rows, times, step_of, place):
    """Yields (row, the index of its sum, its place's bit) for each of the rows (sum_rows'; times:
    the times read, by index): a sum per station (station_key) and step (step_of), numbered as
    they first come."""
    slot, key_of = {}, {}
    for r, k in enumerate(rows.read):
        station = rows.stations.GetValue(r)
        key = key_of.get(station) or key_of.setdefault(station, station_key(station))
        yield r, slot.setdefault((key, step_of[times[k]]), len(slot)), 1 << place[k]


def earlier_lines(rows, times, step_of, place, repeated):
    """(line, the line of the first row with a value of its station and time, station id) for each
    repeated row (sum_rows' (row, sum, bit))."""
    earlier = dict.fromkeys(((at, bit) for _, at, bit in repeated), None)
    for r, at, bit in sum_places(rows, times, step_of, place) if repeated else ():
        if earlier.get((at, bit), 0) is None and not rows.missing_kind[r]:
            earlier[(at, bit)] = rows.lines[r]
    return [(rows.lines[r], earlier[(at, bit)], rows.stations.GetValue(r)) for r, at, bit in repeated]


def say_partial_ends(first_end, last_end, steps, fine_minutes, path):
    """Names the first summed step when the first time with a value is after its step's first
    minutes, and the last when the last is before its end (first_end, last_end: each time, the
    file's step, with its summed step): a record that starts or ends there gives them only part
    of their minutes."""
    (first, first_step), (last, last_step) = first_end, last_end
    span = datetime.timedelta(minutes=steps.minutes - fine_minutes)
    if as_datetime(first) > as_datetime(first_step) - span:
        print(f"{path}: the first {steps.noun} ({steps.text(first_step)}) sums the values from "
              f"{Steps.of(first).text(first)} on: part of its minutes, if the record starts there", file=sys.stderr)
    if as_datetime(last) < as_datetime(last_step):
        print(f"{path}: the last {steps.noun} ({steps.text(last_step)}) sums the values up to "
              f"{Steps.of(last).text(last)}: part of its minutes, if the record ends there", file=sys.stderr)


def say_sums(count, sums, repeated, partial, steps, path):
    """Says how many observations (count) sum_rows summed into how many sums, the lines of those
    it left out as repeats (repeated: sum_rows' summed_repeats), and how many sums (partial) left
    out a missing value."""
    print(f"{path}: {count} observation(s) summed into {sums} total(s) of a station {steps.described} (--sum-to)",
          file=sys.stderr)
    if repeated:
        print(f"{path}: {len(repeated)} observation(s) repeat a station and time of an earlier one and are left out "
              "of the sums (the earlier value is used; unused_inputs.csv lists them): line(s) "
              f"{first_and_more(repeated, lambda repeat: f'{repeat[0]} (as line {repeat[1]})')}", file=sys.stderr)
    if partial:
        print(f"{path}: {partial} total(s) leave out a missing value and sum the others", file=sys.stderr)


def as_datetime(step):
    """A time step (year, month, day, hour, and a minute where given) as a datetime."""
    return datetime.datetime(*step)


class ObservationRows:
    """The records of an observations file, a row each, as scan_observations reads them (before
    file_steps makes their steps the file's): station ids and values (vtk arrays, the table's
    columns), and per row, in machine integers (arrays, not lists of Python objects: a large file
    has millions of rows), its line, the index of its step in step_index, and whether its value is
    missing (1: no value, 2: a --missing-value value, 0: a value); with what was noticed on the
    way, named once the period is known (only the rows within --start/--end are used)."""

    def __init__(self):
        from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray

        self.stations, self.values = vtkStringArray(), vtkDoubleArray()
        self.stations.SetName("station_id")
        self.values.SetName("precip")
        self.lines = array.array("l")  # the file's line of each row read
        self.read = array.array("l")  # the index of each row's step in step_index
        self.missing_kind = array.array("b")  # per row: 0 a value, 1 none, 2 --missing-value's, 3 dropped flagged
        self.step_index = {}  # each step read, by first appearance
        self.first_line, self.valued_line = {}, {}  # each step's first line, and first with a gauge's value
        self.negative = []  # (row, line) of the negative values
        self.present = set()  # the step of every row of a gauge's station
        self.reporting = {}  # step: the gauges with a value then
        self.every_step = set()  # (take_steps: the file's steps)
        self.names = {}  # every row's station id, as written, once each in the file's order
        self.first = {}  # the first line of a month, a day, a day and time, and a time other than midnight
        self.zone = None  # (check_zone's) the first time's zone (None for none), line and date text
        self.hour_column, self.at_24 = False, 0
        self.wide = False  # a wide file's rows (a column per station)
        self.unmatched = []  # a wide file's columns that are no gauge's station
        self.gaps = []  # (row, how many) of a wide file's cells without a value, not made rows
        self.repeats = []  # (row, line, the earlier line) of a wide file's rows repeating an earlier row's time
        self.flagged = []  # (line, flag) of the rows with a NOAA quality flag (noaa_quality_flag)
        self.summed_repeats = []  # (sum_rows')

    def take_steps(self, step_of):
        """The steps read made the file's steps (file_steps' step_of)."""
        self.every_step, self.present = set(step_of.values()), {step_of[m] for m in self.present}
        merged = {}  # (the frozensets kept: a step is most often one time read)
        for m, gauges in self.reporting.items():
            step = step_of[m]
            merged[step] = merged[step] | gauges if step in merged else gauges
        self.reporting = merged

    def times(self, steps, step_of):
        """The time column: each row's step as a time value (Steps.time)."""
        from vtkmodules.vtkCommonCore import vtkDoubleArray

        times = vtkDoubleArray()
        times.SetName("time")
        time_of = [steps.time(step_of[m]) for m in self.step_index]  # (by index)
        for k in self.read:
            times.InsertNextValue(time_of[k])
        return times


def scan_observations(path, gauge_of, stations_path, station_ids, missing_values, drop_flagged=False):
    """The ObservationRows of every record of the file (observation_records), with each record's
    step as observation_step reads it (once per time as written, and each station id's gauge once
    per id as written: a file of 5-minute steps has 20 rows of each time, and millions of rows);
    ends the script where a record's step is of another length than an earlier one's (all months,
    all days or all hours)."""
    rows = ObservationRows()
    reading = ReadingProgress(path)
    index_of = {}  # each time as written (its time fields): its step's index in step_index
    gauge_by_id = {}  # each station id as written: its gauge, None for no gauge's station
    present, reporting = set(), {}  # (by step index: ObservationRows' present and reporting)
    first_line, valued_line = [], {}  # (by step index: ObservationRows' first_line and valued_line)
    for line, row, station, column in observation_records(path, gauge_of, stations_path, station_ids, rows.unmatched,
                                                          rows.gaps, rows.repeats, rows.flagged, drop_flagged):
        rows.lines.append(line)
        if not len(rows.lines) & 0xFFFF:
            reading.tick(len(rows.lines), line)
        written = tuple(map(row.get, TIME_COLUMNS))
        index = index_of.get(written)
        if index is None:
            index = index_of[written] = new_step(rows, row, path, line)
            rows.wide = column != "precip"
            if index == len(first_line):
                first_line.append(line)
        rows.read.append(index)
        if station in gauge_by_id:
            gauge = gauge_by_id[station]
        else:
            gauge = gauge_by_id[station] = gauge_of.get(station_key(station))
            rows.names.setdefault(station.strip(" \t\""))
        if gauge is not None:
            present.add(index)
        # A missing value stays in the table as NaN: the gauge does not report that month (the
        # filter drops it for that step), and the month remains a step even if no gauge reports.
        value = math.nan
        if drop_flagged and rows.flagged and rows.flagged[-1][0] == line:  # (observation_records' last)
            rows.missing_kind.append(3)
        elif csv_input.is_missing(row.get(column)):
            rows.missing_kind.append(1)
        elif (number := csv_input.number(row, column, path, line)) in missing_values:
            rows.missing_kind.append(2)
        else:
            rows.missing_kind.append(0)
            value = number
            if value < 0:
                rows.negative.append((len(rows.lines) - 1, line if column == "precip" else f"{line} ({column})"))
            if gauge is not None:
                if index not in reporting:
                    valued_line[index] = line
                reporting.setdefault(index, set()).add(gauge)
        rows.stations.InsertNextValue(station)
        rows.values.InsertNextValue(value)
    steps = list(rows.step_index)  # (by index)
    rows.present = {steps[k] for k in present}
    rows.first_line = dict(zip(steps, first_line))
    rows.valued_line = {steps[k]: line for k, line in valued_line.items()}
    # (one frozenset for each set of gauges: most steps of a year of 5-minute steps have the same
    # gauges, and 105,120 sets of 20 gauges took 137 MB)
    alike = {}
    rows.reporting = {steps[k]: alike.setdefault(frozenset(gauges), frozenset(gauges))
                      for k, gauges in reporting.items()}
    at_24 = {k for k, step in enumerate(steps) if len(step) == 5 and step[3] == 24}
    rows.at_24 = sum(1 for k in rows.read if k in at_24) if at_24 else 0
    return rows


def new_step(rows, row, path, line):
    """The index in rows.step_index of the step of a time first written at line (observation_step),
    noting the first line of its kind (month, day, time, hour, minute); ends the script where that
    kind clashes with an earlier line's."""
    step, zone = observation_step(row, path, line)
    check_zone(rows, zone, row, path, line)
    kind = step_kind(step)  # (a time at midnight may be a day's or an hour's)
    if kind not in rows.first:
        clash = next((k for k in rows.first if steps_clash(k, kind)), None)
        if clash:
            csv_input.fail(f"{path}:{line}: column 'date': {row['date'].strip()!r} is {STEP_NAMES[kind]}, where "
                           f"line {rows.first[clash]} gives {STEP_NAMES[clash]} (the steps are all months, all days "
                           "or all times of day)")
        rows.first[kind] = line
    rows.hour_column = "hour" in row
    return rows.step_index.setdefault(step, len(rows.step_index))


def check_zone(rows, zone, row, path, line):
    """Ends the script where a time's zone (date_column_step's, None for none) is not the first
    time's: times are read as written, not moved to UTC, so a file in two zones (or with a zone on
    some times only) would be misordered unwarned. rows.zone keeps the first."""
    if rows.zone is None:
        rows.zone = (zone, line, row["date"].strip() if "date" in row else None)
        return
    first, first_line, first_text = rows.zone
    if (zone[1] if zone else None) != (first[1] if first else None):  # (by offset: +00:00 is Z)
        csv_input.fail(f"{path}:{line}: column 'date': {row['date'].strip()!r} {zone_said(zone)}, where line "
                       f"{first_line}'s {first_text!r} {zone_said(first)}: times are read as written (not moved to "
                       "UTC), so give them all in one zone, or all without one")


def zone_said(zone):
    """'has time zone Z' for a zone_of's zone, or 'has no time zone' for None."""
    return f"has time zone {zone[0]}" if zone else "has no time zone"


def keep_period(rows, period, steps, step_of, path, bound_texts):
    """Keeps the rows within --start/--end (period, given), and what was noticed of them; returns
    the others in runs (rows_in_period), which it says. Ends the script when no observation of a
    gauge's station is within."""
    kept = array.array("b", (step_of[m] in period for m in rows.step_index))  # (by step index)
    row_kept = array.array("b", (kept[k] for k in rows.read))
    # (a wide file's empty cells and repeated times by the row of their line: those within only)
    rows.gaps = [gap for gap in rows.gaps if row_kept[gap[0]]]
    rows.repeats = [repeat for repeat in rows.repeats if row_kept[repeat[0]]]
    rows.negative = [(row, line) for row, line in rows.negative if row_kept[row]]
    # (a wide file's row without any value gives a record without one, only to keep its time a
    # step: no observation)
    counted = array.array("b", (kind != 1 for kind in rows.missing_kind)) if rows.wide else None
    rows.missing_kind = array.array("b", (kind for kind, used in zip(rows.missing_kind, row_kept) if used))
    rows.stations, rows.values, rows.lines, rows.read, outside = rows_in_period(
        rows.stations, rows.values, rows.lines, rows.read, row_kept, counted)
    every_steps = rows.every_step
    rows.every_step = {step for step in rows.every_step if step in period}
    rows.present = {step for step in rows.present if step in period}
    rows.reporting = {step: gauges for step, gauges in rows.reporting.items() if step in period}
    if outside:
        print(f"{path}: {outside_count(outside)} observation(s) outside --start/--end are not used (unused_inputs.csv "
              "lists them)", file=sys.stderr)
    if not rows.present:
        given = " and ".join(f"--{name} {text}" for name, text in zip(("start", "end"), bound_texts)
                             if text is not None)
        csv_input.fail(f"{path}: no observation of a gauge's station is within {given} (its {steps.noun}s run "
                       f"from {steps.text(min(every_steps))} to {steps.text(max(every_steps))})")
    return outside


def say_odd_observations(rows, path, stations_path, missing_values, steps, dropped=False):
    """Warns of what the rows kept hold that may not be what the file means: a wide file's columns
    of no station, --missing-value values, repeated times, values with a NOAA quality flag (left
    out where dropped), values missing or negative, and daily values that look monthly."""
    if rows.unmatched:
        shown = first_and_more(rows.unmatched, lambda column: f"{column[1]!r} (column {column[0]})")
        print(f"{path}: {len(rows.unmatched)} column(s) name no station of {stations_path} and are not read: {shown}",
              file=sys.stderr)
    if coded := rows.missing_kind.count(2):
        print(f"{path}: {coded} observation(s) with a --missing-value value "
              f"({', '.join(f'{v:g}' for v in sorted(missing_values))}) count as missing", file=sys.stderr)
    say_repeated_times(path, rows.repeats)
    say_quality_flags(path, rows.flagged, dropped)
    if unrecorded := rows.missing_kind.count(1) + sum(count for _, count in rows.gaps):
        print(f"{path}: {unrecorded} observation(s) without a value ({csv_input.MISSING_TEXT}) "
              "count as missing", file=sys.stderr)
    if rows.negative:
        # Precipitation is never negative: these are most often a missing-value code (-99, -9999)
        # that would drag the means down. They are used as given, and named.
        shown = first_and_more(rows.negative, lambda negative: str(negative[1]))
        print(f"{path}: {len(rows.negative)} observation(s) have a negative precipitation, used as given "
              f"(write a missing value as NA, or give --missing-value, if that is what they mean): line(s) {shown}",
              file=sys.stderr)
    days = rows.every_step
    if steps.unit == "day" and len({day[:2] for day in days}) > 1:
        # Monthly values stamped with a day (2001-01-01, 2001-02-01; or month ends) would be read
        # as days with some 29 days without a report between them: said, since the means of
        # those days are then the months'.
        last = all(d == calendar.monthrange(y, m)[1] for y, m, d in days)
        same = len({d for _, _, d in days}) == 1
        if last or same:
            which = "the last day of its month" if last else f"day {next(iter(days))[2]} of its month"
            print(f"{path}: every date is {which}; if these are monthly values, give the dates as YYYY-MM "
                  "(or year and month columns): they are read as days", file=sys.stderr)


def add_steps_without_rows(rows, times, steps, step_of, period, filler, path):
    """Appends a row (filler's station, no value) for each step from the first to the last (the
    period's, where given) that no row of a gauge's station has, and says how many. Ends the
    script when there are more than MOST_STEPS steps, naming the first and the last."""
    first, last = period.start or min(rows.every_step), period.end or max(rows.every_step)
    count = steps.count(first, last)
    span = steps_span(rows, steps, step_of, period, first, last) if count > len(rows.present) else ""
    if count > MOST_STEPS:
        spanning = "the period (--start, --end) spans" if period.given() else "the observations span"
        csv_input.fail(f"{path}: {spanning} {count} {steps.noun}s {span}, more than "
                       f"{MOST_STEPS} (each a row of areal_mean.csv, and some 1 GB of memory a "
                       f"million); is a date mistyped?")
    missing = [step for step in steps.between(first, last) if step not in rows.present]
    shown = first_and_more(missing, steps.text, 5)
    for step in missing:  # (a gauge's id: the step is a step of the filter)
        rows.stations.InsertNextValue(filler)
        times.InsertNextValue(steps.time(step))
        rows.values.InsertNextValue(math.nan)
    if missing:
        print(f"{path}: {len(missing)} {steps.noun}(s) {span} have no row of a gauge's station ({shown}); they are "
              f"{steps.noun}s where no gauge reported", file=sys.stderr)


def steps_span(rows, steps, step_of, period, first, last):
    """'between FIRST (where) and LAST (where)': where is --start or --end for a bound given as an
    option, else the line of the step's first row, where a mistyped year makes the span."""
    named = {}  # the bounds given as options, which name themselves
    if period.start:
        named[first] = "--start"
    if period.end:
        named[last] = "--end"
    read_steps, wanted, line_of = list(rows.step_index), {first, last} - set(named), {}
    for row, k in enumerate(rows.read if wanted else ()):
        step = step_of[read_steps[k]]
        if step in wanted and step not in line_of:
            line_of[step] = rows.lines[row]
            if len(line_of) == len(wanted):
                break
    named.update((step, f"line {line}") for step, line in line_of.items())
    return f"between {steps.text(first)} ({named[first]}) and {steps.text(last)} ({named[last]})"


def rows_in_period(stations, values, lines, read, keep, counted=None):
    """The observation rows whose step is in --start/--end (keep: 1 for each such row): their
    station ids, values, lines and step indices, and the others in runs of rows one after the other
    (no kept row between), each as [first line, last line, how many, {station ids}]: a record
    trimmed to a few of its years has millions of rows outside, in a few runs (one before and one
    after when the file is in time order, two per station when it is in station order). counted:
    1 for each row that is an observation (all, where None); a run without one is left out."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray

    kept_stations, kept_values = vtkStringArray(), vtkDoubleArray()
    kept_stations.SetName(stations.GetName())
    kept_values.SetName(values.GetName())
    kept_lines, kept_read, outside = array.array("l"), array.array("l"), []
    run_end = -1  # the row after the last run's last row
    for row, k in enumerate(read):
        if keep[row]:
            kept_stations.InsertNextValue(stations.GetValue(row))
            kept_values.InsertNextValue(values.GetValue(row))
            kept_lines.append(lines[row])
            kept_read.append(k)
            continue
        if row != run_end:
            outside.append([lines[row], lines[row], 0, set()])
        run = outside[-1]
        run[1] = lines[row]
        if counted is None or counted[row]:
            run[2] += 1
            run[3].add(stations.GetValue(row))
        run_end = row + 1
    return kept_stations, kept_values, kept_lines, kept_read, [run for run in outside if run[2]]


def outside_count(outside):
    """How many observations the runs of rows_in_period hold."""
    return sum(count for _, _, count, _ in outside)


# The names this script gives its outputs (the module docstring's list; a step's tag is Steps.tag's
# 2001_03, 2001_03_01, 2001_03_01_06 or 2001_03_01_06_15): a file in --out named so that this run did not write is
# most likely an earlier run's.
TAG = r"[0-9]{4}_[0-9]{2}(_[0-9]{2}(_[0-9]{2}(_[0-9]{2})?)?)?"
OUTPUT_NAME = re.compile(rf"areal_mean\.(csv|png)|areal_mean_by_.+\.csv|areal_total_by_(month|day)\.csv"
                         rf"|unused_inputs\.csv"
                         rf"|weights_all_(months|days|hours|minutes)\.csv"
                         rf"|weights_{TAG}\.csv|tiles_{TAG}\.(vtp|geojson)|map_{TAG}\.png")


def say_earlier_outputs(out, written):
    """Names the files in out named as this script names its outputs but not written by this run
    (written: their names): most likely an earlier run's, with other options or other data, which
    could be taken for this run's. They are left in place (they may be wanted)."""
    earlier = sorted(name for name in os.listdir(out) if OUTPUT_NAME.fullmatch(name) and name not in written)
    if earlier:
        print(f"note: {out} also holds {len(earlier)} file(s) named as this script's outputs that this run did "
              f"not write (an earlier run's?), kept: {first_and_more(earlier, str, 10)}", file=sys.stderr)


def zip_member(path, what="catchment"):
    """The GDAL path (/vsizip/) of the catchment (what) file in a zip file, as such files are often
    downloaded: its one shapefile, GeoJSON, KML or GeoPackage file (a shapefile's .shx, .dbf and
    .prj beside it; macOS's __MACOSX copies and hidden files left aside); ends the script naming
    the files when it holds several such files or none."""
    import zipfile

    try:
        names = [n for n in zipfile.ZipFile(path).namelist() if not n.endswith("/")
                 and not n.startswith("__MACOSX/") and not os.path.basename(n).startswith(".")]
    except (OSError, zipfile.BadZipFile) as e:
        csv_input.fail(f"{path}: cannot be read as a zip file ({e})")
    candidates = [n for n in names if os.path.splitext(n)[1].lower() in (".shp", ".geojson", ".json", ".kml", ".gpkg")]
    if len(candidates) == 1:
        return f"/vsizip/{os.path.abspath(path)}/{candidates[0]}"
    listed = candidates or names
    shown = ", ".join(listed[:10]) + (", ..." if len(listed) > 10 else "")
    csv_input.fail(f"{path}: holds no single {what} file (one shapefile, GeoJSON, KML or GeoPackage) "
                   f"to read: {shown or 'no files'}; unzip it and give the file")


def side_of_ring(point, ring):
    """1 inside the ring (even-odd), -1 outside, 0 on its boundary; ring an (n, 2) array."""
    import numpy as np

    x, y = point
    a, b = ring, np.roll(ring, -1, axis=0)
    cross = (b[:, 0] - a[:, 0]) * (y - a[:, 1]) - (b[:, 1] - a[:, 1]) * (x - a[:, 0])
    on = ((cross == 0) & (np.minimum(a[:, 0], b[:, 0]) <= x) & (x <= np.maximum(a[:, 0], b[:, 0]))
          & (np.minimum(a[:, 1], b[:, 1]) <= y) & (y <= np.maximum(a[:, 1], b[:, 1])))
    if on.any():
        return 0
    straddles = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        meets = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return 1 if np.count_nonzero(straddles & (x < meets)) % 2 else -1


def holes_outside_their_polygons(path, feature=None):
    """For a GeoJSON file: (feature, ring) of each hole (a polygon's ring after its first, counted
    over the feature's polygons) whose first vertex off its polygon's outer ring lies outside it.
    The even-odd rule takes such a ring as an island, adding its area, where the file means a hole
    (a hole that crosses its outline, with vertices on both sides, is refused by the filter; it is
    listed here too when that first vertex is outside). Only the features with
    `feature`'s ATTRIBUTE=VALUE when given; a malformed feature (which GDAL names or skips) is
    passed over. Empty for other files."""
    import json

    import numpy as np

    if os.path.splitext(path)[1].lower() not in (".geojson", ".json"):
        return []
    try:
        with open(path, encoding="utf-8-sig") as f:
            document = json.load(f)
    except (OSError, ValueError):
        return []  # (GDAL's reading says what is wrong)
    name, _, wanted = (feature or "").partition("=")
    features = document.get("features", [document]) if isinstance(document, dict) else []
    found = []
    for k, item in enumerate(features):
        try:
            if feature is not None and str((item.get("properties") or {}).get(name.strip())) != wanted.strip():
                continue
            geometry = item.get("geometry", item)
            kind, coordinates = geometry.get("type"), geometry.get("coordinates") or []
            polygons = [coordinates] if kind == "Polygon" else coordinates if kind == "MultiPolygon" else []
            ring_number = 0
            for polygon in polygons:
                outer = np.asarray([p[:2] for p in polygon[0]], dtype=float)
                for hole in polygon[1:]:
                    ring_number += 1
                    # (a hole with vertices on both sides crosses its outline: the filter names it;
                    # so the first vertex off the outline decides, where testing every one cost a
                    # 20,000-vertex lake in a 300,000-vertex outline 85 s)
                    sides = (side_of_ring(p[:2], outer) for p in hole)
                    if next((side for side in sides if side != 0), 0) < 0:
                        found.append((k, ring_number))
                ring_number += 1
        except (AttributeError, TypeError, ValueError, IndexError):
            continue
    return found


def cell_kinds(data):
    """What the cells of data's polydata blocks are, for a file that holds no polygon: "3 point(s),
    1 line(s)"."""
    from vtkmodules.vtkCommonDataModel import VTK_LINE, VTK_POLY_LINE, VTK_POLY_VERTEX, VTK_VERTEX

    counts = {"point": 0, "line": 0, "other cell": 0}
    for block in projected_input.polydata_blocks(data):
        for c in range(block.GetNumberOfCells()):
            kind = block.GetCellType(c)
            counts["point" if kind in (VTK_VERTEX, VTK_POLY_VERTEX) else
                   "line" if kind in (VTK_LINE, VTK_POLY_LINE) else "other cell"] += 1
    return ", ".join(f"{n} {kind}(s)" for kind, n in counts.items() if n) or "nothing"


GDAL_MESSAGES = None


def gdal_messages():
    """The script's GdalMessages, made at the first call."""
    global GDAL_MESSAGES
    GDAL_MESSAGES = GDAL_MESSAGES or projected_input.GdalMessages()
    return GDAL_MESSAGES


def read_gis_file(path, what, expected):
    """(reader, output, errors, gdal) of a GIS file (GeoJSON, shapefile, KML, GeoPackage, or a zip
    file holding one) read by vtkGDALVectorReader (updated; output: a multiblock with a block per
    feature), with VTK's error events and GDAL's messages (GdalMessages.new's) while it read; ends
    the script naming the file when it is a directory, missing, or a shapefile without its .shx.
    what: what the file holds ("catchment"), expected: what it should be (for the messages)."""
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkIOGDAL import vtkGDALVectorReader

    if os.path.isdir(path):
        csv_input.fail(f"{path}: is a directory, not a {what} file (expected {expected})")
    if not os.path.isfile(path):
        csv_input.fail(f"{path}: no such {what} file")
    source = zip_member(path, what) if path.lower().endswith(".zip") else path
    # A shapefile is several files: GDAL's own message for a missing one is a raw log line.
    stem, extension = os.path.splitext(path)
    if extension.lower() == ".shp":
        if not any(os.path.isfile(stem + e) for e in (".shx", ".SHX")):
            csv_input.fail(f"{path}: the shapefile's {stem}.shx beside it is missing (a shapefile is a .shp "
                           "with its .shx, .dbf and often .prj; copy them all)")
    reader = vtkGDALVectorReader()
    errors = []
    reader.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
    reader.SetFileName(source)
    with gdal_messages().capturing():
        reader.Update()
    return reader, reader.GetOutput(), errors, gdal_messages().new()


def say_gdal_messages(path, gdal, passed_over=()):
    """Prints GDAL's warnings and errors (read_gis_file's gdal: (level, text)) on stderr under the
    file's name, but for those starting with passed_over (a str or tuple of them)."""
    for level, message in gdal:
        if level and not message.startswith(passed_over):
            print(f"{path}: GDAL: {message}", file=sys.stderr)


def read_catchment(path, feature=None):
    """The catchment (a vtkGDALVectorReader's output: a multiblock with a block per feature, or the
    features chosen by `feature`, "ATTRIBUTE=VALUE") and its rings (catchment_rings); ends the
    script naming the file when it is missing, unreadable or holds no polygon, or when no
    feature has the value."""
    reader, output, errors, gdal = read_gis_file(path, "catchment", "a GeoJSON or shapefile polygon in lon/lat")
    rings = catchment_rings(output) if output else []
    if errors or not rings:
        # GDAL's error is the reason where nothing was read (a file it cannot parse); where
        # points or lines were, they are (an unknown "crs" is an error of GDAL's too).
        reasons = [text for level, text in gdal if level == "ERROR"]
        kinds = cell_kinds(output) if output else "nothing"
        if reasons and kinds == "nothing":
            csv_input.fail(f"{path}: GDAL cannot read the catchment file: {reasons[0]}")
        found = f"only {kinds}" if kinds != "nothing" else "no geometry at all (a table, such as a CSV file, has none)"
        csv_input.fail(f"{path}: VTK's GDAL reader (vtkGDALVectorReader) found no polygon in the "
                       f"catchment file, {found} (expected a GeoJSON or shapefile polygon in lon/lat; "
                       "polygons with measures, such as PolygonM or PolygonZM shapefiles, read as empty: drop "
                       "the measures first, e.g. with ogr2ogr -dim XY)"
                       + (f"; GDAL: {reasons[0]}" if reasons else ""))
    say_gdal_messages(path, gdal, "Non closed ring detected")  # (the filter names an open ring)
    # (with --feature, only the chosen features count: their having no polygon is an error below)
    empty = [k for k, block in enumerate(projected_input.polydata_blocks(output)) if block.GetNumberOfCells() == 0]
    if empty and feature is None:
        print(f"{path}: {len(empty)} feature(s) have no geometry that VTK's GDAL reader reads (a null geometry, "
              f"or one with measures; the first is feature {empty[0]}, counted from 0), and are left out of the "
              "catchment", file=sys.stderr)
    system = projected_input.declared_system(reader, rings, path)
    # (a GeoPackage's layer of gauges: the filter would warn of each point as a cell it cannot
    # read, and the system's inverse, of metres, would refuse their lon/lat)
    output, points = without_point_blocks(output)
    if points:
        print(f"{path}: {points} feature(s) of points are not polygons, and are left out of the catchment",
              file=sys.stderr)
    if system:
        output = projected_input.to_lonlat(output, system, lambda point: path, densify=True)
        rings = catchment_rings(output)
    for k, ring in holes_outside_their_polygons(path, feature):
        print(f"{path}: feature {k} ring {ring} is a hole (a polygon's ring after its first) but lies outside "
              "its polygon's outer ring: the even-odd rule takes it as an island, adding its area (GeoJSON's "
              "holes lie inside their polygon; counted from 0)", file=sys.stderr)
    if feature is not None:
        output = select_features(output, feature, path)
        rings = catchment_rings(output)
        if not rings:
            csv_input.fail(f"{path}: the features with {feature} have no polygon")
    features = polygon_blocks(output)
    if features > 1 and feature is None:
        print(f"{path}: the catchment is the {features} polygon features of the file taken "
              "together (even-odd rule: a feature inside another is a hole, and one that fills "
              "another's hole exactly joins it); --feature ATTRIBUTE=VALUE takes only those with "
              "that value", file=sys.stderr)
    say_declared_systems(reader, path, system)
    return output, rings


def without_point_blocks(data):
    """(blocks, count): the polydata blocks of a vtkGDALVectorReader's output as a new multiblock,
    each block of points only made an empty one (in its place: the filter's messages number the
    blocks as the file's features), and the number of those."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData

    kept, left_out = vtkMultiBlockDataSet(), 0
    for block in projected_input.polydata_blocks(data):
        if block.GetNumberOfPolys() or block.GetNumberOfLines() or not block.GetNumberOfVerts():
            kept.SetBlock(kept.GetNumberOfBlocks(), block)
        else:
            kept.SetBlock(kept.GetNumberOfBlocks(), vtkPolyData())
            left_out += 1
    return kept, left_out


def say_declared_systems(reader, path, system, points=False):
    """Says what a GIS file (reader: its vtkGDALVectorReader, updated) declares for its layers that
    hold what is read (projected_input.layers_of): the projected system (projected_input.PlaneSystem,
    or None) its metres were made lon/lat from, or a projected system over coordinates read as
    lon/lat, and an older datum. The coordinates are read as lon/lat whatever the file declares,
    but for the metres of a projected system read."""
    for layer in projected_input.layers_of(reader, points):
        declared = reader.GetLayerProjection(layer) or ""
        name = re.match(r'PROJC(?:RS|S)\["([^"]*)"', declared)
        name = name.group(1) if name else declared[:60]
        if system:
            print(f"{path}: declares the projected coordinate system {name!r}, whose eastings and northings are "
                  f"made longitude/latitude ({system.describe()})", file=sys.stderr)
        elif declared.startswith(("PROJCS", "PROJCRS")):
            print(f"{path}: declares the projected coordinate system {name!r}; its coordinates are read as "
                  "longitude/latitude in degrees (WGS84), which they must be (else reproject the file, e.g. "
                  f"ogr2ogr -t_srs EPSG:4326 out.shp in.shp; the metres of {projected_input.READ} are made "
                  "lon/lat here)",
                  file=sys.stderr)
        # A system on an older datum (NAD27, ED50, ...) or one some way from WGS84 (Israel 1993)
        # differs from WGS84 by tens to hundreds of metres, which reading its lon/lat as WGS84's
        # leaves in place.
        other = projected_input.other_datum(declared)
        if other:
            print(f"{path}: declares {other}; its longitudes/latitudes are read as WGS84 ones, without the "
                  "datum shift of tens to hundreds of metres: reproject the file to WGS84 (e.g. ogr2ogr "
                  "-t_srs EPSG:4326) where that matters", file=sys.stderr)


def attribute_text(array, cell=0):
    """A cell attribute's value as text: numbers that are whole as integers (14010001, not
    14010001.0), others as written."""
    if array.IsA("vtkDataArray"):
        value = array.GetTuple1(cell)
        return str(int(value)) if math.isfinite(value) and value == int(value) else repr(value)
    return str(array.GetVariantValue(cell).ToString())


def features_by_value(data, name, path):
    """The blocks (features) of a vtkGDALVectorReader output with cells, by the text of their
    attribute `name` (attribute_text), each value's as a new multiblock; ends the script naming
    the attributes there are when no feature has that one."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    chosen, names = {}, set()
    for block in projected_input.polydata_blocks(data):
        if block.GetNumberOfCells() == 0:
            continue
        cells = block.GetCellData()
        names.update(cells.GetArrayName(i) for i in range(cells.GetNumberOfArrays()))
        array = cells.GetAbstractArray(name)
        if array is not None:
            blocks = chosen.setdefault(attribute_text(array), vtkMultiBlockDataSet())
            blocks.SetBlock(blocks.GetNumberOfBlocks(), block)
    if not chosen:
        known = ", ".join(sorted(n for n in names if n and not n.startswith("_vtk"))) or "none"
        csv_input.fail(f"{path}: no feature has the attribute {name!r} (its attributes: {known})")
    return chosen


def select_features(data, feature, path):
    """The blocks (features) of a vtkGDALVectorReader output whose attribute has the value, for
    --feature ATTRIBUTE=VALUE, as a new multiblock; ends the script naming the attributes or the
    values there are when none matches."""
    name, _, wanted = feature.partition("=")
    name, wanted = name.strip(), wanted.strip()
    if not name or not _:
        csv_input.fail(f"--feature {feature!r}: expected ATTRIBUTE=VALUE, such as HUC8=14010001")
    chosen = features_by_value(data, name, path)
    if wanted not in chosen:
        values = sorted(chosen)
        shown = ", ".join(values[:20]) + (", ..." if len(values) > 20 else "")
        csv_input.fail(f"{path}: no feature has {name} = {wanted!r} (its values: {shown})")
    return chosen[wanted]


class ReadingProgress:
    """A line every ReadingProgress.EVERY seconds while a large file is read (millions of rows take
    a minute or more, before any other output)."""

    EVERY = 10.0

    def __init__(self, path):
        self.path, self.last, self.lines = path, time.monotonic(), None

    def tick(self, rows, line):
        """rows read so far, the last on the file's line `line`."""
        now = time.monotonic()
        if now - self.last >= self.EVERY:
            self.last = now
            print(f"reading {self.path}: {rows:,} rows so far{self.share(line)}", file=sys.stderr, flush=True)

    def share(self, line):
        """" (83% of its 5,843,000 lines)": how far line is into the file, its lines counted at the
        first line said (a trial's 127 MB took a second read of 0.1 s); "" for a compressed file."""
        if self.lines is None:
            self.lines = line_count(self.path)
        # (rounded down: 100% only at the last line)
        return f" ({min(100, 100 * line // self.lines)}% of its {self.lines:,} lines)" if self.lines else ""


def line_count(path):
    """The lines of the file at path, their ends counted as the reader splits lines (\\r\\n, \\r
    or \\n: csv_input.LINE); 0 for a compressed file (whose bytes are not its lines) or one that
    cannot be read. For UTF-16 text, which the reader decodes first, a count of its bytes' line
    ends: near enough for progress."""
    lf = cr = crlf = 0
    last = b""
    try:
        with open(path, "rb") as handle:
            if csv_input.compression(handle.read(10)):
                return 0
            handle.seek(0)
            for chunk in iter(lambda: handle.read(1 << 24), b""):
                # (a \r\n split between two chunks is one end too)
                crlf += chunk.count(b"\r\n") + (last == b"\r" and chunk[:1] == b"\n")
                lf, cr, last = lf + chunk.count(b"\n"), cr + chunk.count(b"\r"), chunk[-1:]
    except OSError:
        return 0
    return lf + cr - crlf + (1 if last not in (b"\n", b"\r", b"") else 0)


def interactive():
    """Whether stderr is a terminal: progress is then redrawn on one line with \\r; into a file
    or a pipe (a log) that made one long line with the warnings spliced in, so there progress is
    written as lines of its own, fewer of them."""
    return sys.stderr.isatty()


class Progress:
    """Prints the filter's progress over the steps: on one line at a terminal, in steps of 5%
    (end_line() ends that line before another message is printed), or as a line of its own at 0,
    25, 50, 75 and 100% into a log; stop() ends it for good (the filter failed, or its run is
    over). say() prints a message after the progress: one that comes while it runs is held until
    it ends (the warning of gauges never weighted, given as the run ends, came between the 75% and
    100% lines)."""

    def __init__(self, label):
        self.label, self.last, self.open, self.stopped = label, -1, False, False
        self.step = 5 if interactive() else 25
        self.held = []

    def __call__(self, caller, event):
        percent = int(caller.GetProgress() * 100)
        percent -= percent % self.step  # shown even when the filter reports past a step
        if not self.stopped and percent != self.last:
            self.last = percent
            if self.step == 25:
                print(f"{self.label}: {percent:3d}%", file=sys.stderr, flush=True)
            else:
                print(f"\r{self.label}: {percent:3d}%", end="", file=sys.stderr, flush=True)
                self.open = True
            if percent == 100:
                self.stop()

    def running(self):
        return 0 <= self.last < 100 and not self.stopped

    def say(self, line):
        if self.running():
            self.held.append(line)
            return
        self.end_line()
        print(line, file=sys.stderr, flush=True)

    def print_held(self):
        for line in self.held:
            print(line, file=sys.stderr, flush=True)
        self.held = []

    def end_line(self):
        if self.open:
            print(file=sys.stderr, flush=True)
            self.open = False

    def stop(self):
        """Ends the progress for good (the filter failed, or its run is over): the held messages
        are printed."""
        self.end_line()
        self.stopped = True
        self.print_held()


class InputFiles:
    """Where the filter's inputs came from: its messages, which name gauges by index and
    observation rows by table row (both from 0), become lines naming the file and, for a gauge or a
    row, its line. The mapping is simple: gauge g is the stations file's g-th record, table row r
    the observations file's r-th record (the filler rows after them are never named: they have a
    gauge's id, a time and no value). within: where a period is given (period_given), what a
    gauge without an observed value lacks it within (the filter sees only the period's rows)."""

    def __init__(self, stations, gauge_lines, observations, row_lines, catchment, unit="month", period_given=False):
        self.stations, self.gauge_lines = stations, gauge_lines
        self.observations, self.row_lines = observations, row_lines
        self.catchment, self.unit = catchment, unit
        self.within = " within --start/--end" if period_given else ""

    def row_line(self, row):
        """The observations file's line of table row `row` (as text), or None for a filler row."""
        return str(self.row_lines[row]) if row < len(self.row_lines) else None

    def rows_as_lines(self, text):
        """text with "row R" as "line L" and without the filter's note on its row numbering."""
        def line(m):
            found = self.row_line(int(m.group(1)))
            return f"line {found}" if found else f"{m.group(0)} (a row added for a {self.unit} without rows)"
        text = re.sub(r"\brow (\d+)\b", line, re.sub(r" \(rows from 0, listed in [^)]*\)", "", text))
        # (a wide file's line holds the value used too: "line 3 (station B) (line 3 used)")
        return re.sub(r"line (\d+) \(station ([^)]*)\) \(line \1 used\)",
                      r"line \1 (station \2; the line's value of the earlier gauge at its place used)", text)

    def place_word(self):
        """What a gauge's number in gauge_lines is: "line" of a CSV file, "feature" of a GIS file."""
        return "feature" if str(self.stations).lower().endswith(GIS_SUFFIXES) else "line"

    def gauges_as_lines(self, text):
        """text with "(gauges A and B)" as "(gauges A and B: lines L and M)", and "(gauge A)" (a
        gauge whose station id others have too) as "(gauge A: line L)" (features of a GIS file),
        without the filter's note on the field data that lists them."""
        word = self.place_word()
        text = re.sub(r" \(listed in [^)]*\)", "", text)

        def lines(m):
            a, b = int(m.group(1)), int(m.group(2))
            if max(a, b) >= len(self.gauge_lines):
                return m.group(0)
            return f"(gauges {a} and {b}: {word}s {self.gauge_lines[a]} and {self.gauge_lines[b]})"

        def line(m):
            a = int(m.group(1))
            return f"(gauge {a}: {word} {self.gauge_lines[a]})" if a < len(self.gauge_lines) else m.group(0)
        return re.sub(r"\(gauge (\d+)\)", line, re.sub(r"\(gauges (\d+) and (\d+)\)", lines, text))

    def error(self, text):
        """The one line that reports the filter's error `text`."""
        gauge = re.match(r"gauge (\d+)\b", text)
        if gauge:
            g = int(gauge.group(1))
            if g >= len(self.gauge_lines):
                return f"{self.stations}: {text}"
            # (the filter's gauge index counts from 0; the file's line, or a GIS file's feature
            # number, is what to look at)
            text = re.sub(r"^gauge \d+ \(station ([^)]*)\)", r"station \1", text)
            if self.place_word() == "feature":
                return f"{self.stations}: feature {self.gauge_lines[g]} (counted from 1): {text}"
            return f"{self.stations}:{self.gauge_lines[g]}: {text}"
        row = re.match(r"observation row (\d+): (.*)", text)
        if row and self.row_line(int(row.group(1))):
            return f"{self.observations}:{self.row_line(int(row.group(1)))}: {row.group(2)}"
        if re.match(r"(catchment )?ring \d+", text):
            metres = ("; if they are metres of a projected system, the file must declare it in a form GDAL reads (a "
                      "shapefile's .prj, a GeoJSON crs) to be made lon/lat here"
                      if "look like projected coordinates" in text else "")
            return f"{self.catchment}: {text} (counted from 0, in the file's order){metres}"
        if text.startswith("the catchment meets itself once projected"):
            return f"{self.catchment}: {text}"
        if text.startswith("the window/catchment input"):
            hint = (" (a polygon ring whose last vertex is not its first is read as an open line: "
                    "close it)" if "holds no polygon" in text else "")
            return f"{self.catchment}: {text}{hint}"
        if re.match(r"the observations table|none of the \d+ observation rows", text):
            return f"{self.observations}: {self.rows_as_lines(text)}"
        return f"the areal average failed: {text}"

    def warning(self, text):
        """The line that reports the filter's warning `text`, or None for one the script's table
        makes untrue: the times may be coarser than the rows (the script gives every row its
        step's time; repeated rows are warned of on their own)."""
        if re.match(r"\d+ of the \d+ observation rows repeat a station and time", text):
            return None
        if re.match(r"\d+ (station id\(s\) of the observations|observation row\(s\))", text):
            return f"{self.observations}: {self.rows_as_lines(text)}"
        if re.match(r"\d+ observation value\(s\) are exactly", text):
            # (the script's option for the filter's UseMissingValue)
            text = re.sub(r"turn UseMissingValue on with MissingValue (\S+)", r"give --missing-value \1", text)
            return f"{self.observations}: {self.rows_as_lines(text)}"
        if re.match(r"\d+ (gauge\(s\)|station id\(s\) are given to more than one gauge)", text):
            text = text.replace("have no observed value", "have no observed value" + self.within, 1)
            return f"{self.stations}: {self.gauges_as_lines(text)}"
        if re.match(r"none of the \d+ gauges", text):
            return f"{self.stations}: {text}"
        if re.match(r"\d+ (cell\(s\) of the catchment|catchment ring\(s\)|catchment vertex)", text):
            return f"{self.catchment}: {text}"
        return f"warning: {text}"


class FilterMessages:
    """Catches the filter's errors and warnings. Its warnings are printed each on a line of its own
    (InputFiles.warning), after the progress where they come while it runs (Progress.say); check()
    ends the script with one line for its error (InputFiles.error). Caught by
    csv_input.catch_vtk_messages, none of them is printed as VTK's log line, and the executive's
    follow-up ("Algorithm ... returned failure for request: ...", with a dump of the request) is
    kept until check()."""

    def __init__(self, average, files, progress):
        self.files, self.progress = files, progress
        self.errors, self.executive_errors = [], []

        def on_error(text):
            progress.stop()
            self.errors.append(text)

        def on_warning(text):
            line = files.warning(text)
            if line:
                progress.say(line)

        def on_executive_error(text):
            progress.stop()
            self.executive_errors.append(text)

        csv_input.catch_vtk_messages(average, on_error, on_warning, on_executive_error)

    def check(self, failed=False):
        """Ends the script with one line if the filter (or its executive) gave an error since it was
        updated, or if it failed (failed: its output is missing) without one."""
        if self.errors:
            csv_input.fail(self.files.error(self.errors[0]))
        if self.executive_errors:
            csv_input.fail("the areal average failed: " + re.sub(r" for request: .*", "", self.executive_errors[0]))
        if failed:
            self.progress.stop()
            csv_input.fail("the areal average failed and gave no message")


def write_all_weights(table, steps, path):
    """Output 2 of the filter (a row per step and weighted gauge) as CSV."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    times = vtk_to_numpy(table.GetColumnByName("Time"))
    weights = vtk_to_numpy(table.GetColumnByName("Weight"))
    areas = vtk_to_numpy(table.GetColumnByName("Area_m2"))
    values = vtk_to_numpy(table.GetColumnByName("Value"))
    stations = table.GetColumnByName("StationId")
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow([*steps.columns, "station_id", "weight", "area_km2", "precip"])
        for r in range(table.GetNumberOfRows()):
            out.writerow([*steps.of_time[float(times[r])], stations.GetValue(r), f"{weights[r]:.15g}",
                          f"{areas[r] / 1e6:.15g}", f"{values[r]:.15g}"])
    return table.GetNumberOfRows()


def summary_rows(table, steps):
    """Output 1 of the filter as (time, step, stations used, stations weighted, areal mean) rows."""
    for r in range(table.GetNumberOfRows()):
        t = table.GetValueByName(r, "Time").ToDouble()
        yield (t, steps.of_time[t], table.GetValueByName(r, "StationsUsed").ToInt(),
               table.GetValueByName(r, "StationsWeighted").ToInt(), table.GetValueByName(r, "ArealMean").ToDouble())


def mean_text(mean):
    """An areal mean as the CSV files write it: empty where no gauge reported."""
    return "" if math.isnan(mean) else f"{mean:.15g}"


def write_summary(table, steps, path):
    """areal_mean.csv from output 1 of the filter; returns its rows as (*step, stations used,
    stations weighted, areal mean)."""
    rows = []
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow([*steps.columns, "stations_used", "stations_weighted", "areal_mean"])
        for _, step, used, weighted, mean in summary_rows(table, steps):
            out.writerow([*step, used, weighted, mean_text(mean)])
            rows.append((*step, used, weighted, mean))
    return rows


# Totals of finer steps' areal means over each month (steps of days) or day (hours, minutes), as
# hydrologists add up daily areal rainfall: the file, its period's columns and what it counts.
TOTALS = {"day": ("areal_total_by_month.csv", 2, "days"), "hour": ("areal_total_by_day.csv", 3, "hours"),
          "minute": ("areal_total_by_day.csv", 3, "steps")}


def totals_name(steps):
    """The totals file of these steps (TOTALS), or None for months."""
    return TOTALS[steps.unit][0] if steps.unit in TOTALS else None


def steps_in_period(period, steps):
    """How many steps the calendar gives a month (days) or a day (24 hours, or 1440 / minutes)."""
    if len(period) == 2:
        return calendar.monthrange(*period)[1]
    return 24 * 60 // steps.minutes


def period_of_step(step, steps):
    """The month of a day; the day of an hour or a step of minutes, which ends at its label (the
    hour labelled 00:00 closes the day before, as hour-ending records and --sum-to's totals run)."""
    if steps.fields == 3:
        return tuple(step[:2])
    start = datetime.datetime(*step) - steps.length()
    return (start.year, start.month, start.day)


def write_totals(rows, steps, path):
    """The areal means of areal_mean.csv's rows added up over each month or day (TOTALS): the
    period, the steps the calendar gives it, how many of them have an areal mean, and their total,
    empty unless every one has (a month the records cover in part, or with a day where no gauge
    reported, gets no total: its days with means are counted)."""
    _, fields, noun = TOTALS[steps.unit]
    periods = {}
    for row in rows:
        periods.setdefault(period_of_step(row[:steps.fields], steps), []).append(row[-1])
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow([*steps.columns[:fields], noun, f"{noun}_with_mean", "areal_total"])
        for period, means in periods.items():
            known = [m for m in means if not math.isnan(m)]
            expected = steps_in_period(period, steps)
            total = math.fsum(known) if len(known) == expected else math.nan
            out.writerow([*period, expected, len(known), mean_text(total)])


# The filter's lists of valid input it did not use (output 1's field data), as unused_inputs.csv
# gives them: (array, what it lists ({unit}: month or day), whether it lists observation rows
# rather than gauges).
OUTSIDE_PERIOD = "observation before --start or after --end"
DROPPED_FLAGGED = "observation with a NOAA quality flag (left out: --drop-flagged)"
SUMMED_REPEAT = "observation repeating the station and time of an earlier one with a value (left out of --sum-to's sum)"
UNUSED_LISTS = (
    ("UnobservedGaugeIds", "gauge without any observed value", False),
    ("UnweightedGaugeIds", "gauge whose tile never reaches the catchment", False),
    ("DuplicateGaugeIds", "gauge at the place of an earlier gauge (used only in {unit}s where no "
     "earlier gauge there reports)", False),
    ("CoLocatedObservationRows", "observation of a gauge at the place of an earlier gauge that "
     "reported that {unit} (the earlier gauge's value is used)", True),
    ("RepeatedObservationRows", "observation repeating the station and {unit} of an earlier one "
     "with a value (the earlier value is used)", True),
    # (the filter lists rows without a station id or time here too: the script ends naming those)
    ("UnusedObservationRows", "observation of a station no gauge has", True),
)


def covered_areas(weights):
    """Per time value, the area (m2) the tiles cover, from output 2 of the filter (summed in row
    order, by numpy: a year of 5-minute steps has millions of rows per group of --each)."""
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    times, inverse = numpy.unique(vtk_to_numpy(weights.GetColumnByName("Time")), return_inverse=True)
    areas = numpy.bincount(inverse, weights=vtk_to_numpy(weights.GetColumnByName("Area_m2")), minlength=len(times))
    return dict(zip(times.tolist(), areas.tolist()))


def polygon_groups(features, name, path):
    """The groups of features_by_value that hold a polygon; the others (lines or points only) are
    named on a line of their own, before any work, and get no means."""
    kept = {value: data for value, data in features.items() if catchment_rings(data)}
    empty = sorted(set(features) - set(kept))
    if empty:
        print(f"{path}: the features with {name} = {', '.join(empty)} have no polygon: no means for them",
              file=sys.stderr)
    if not kept:
        csv_input.fail(f"{path}: no feature with the attribute {name} has a polygon")
    return kept


def areal_average(gauges, catchment, observations):
    """A vtkThiessenArealAverage of the gauges over the catchment, with the observations' precip."""
    average = csv_input.import_tessera().vtkThiessenArealAverage()
    average.SetGaugesData(gauges)
    average.SetCatchmentData(catchment)
    average.SetObservationsData(observations)
    average.SetValueColumn("precip")
    return average


def write_means_by_feature(features, name, gauges, observations, steps, whole, catchment_path, path):
    """--each ATTRIBUTE: the areal mean of every step over each feature group of the catchment
    (features: features_by_value's), as CSV: ATTRIBUTE, the step's columns, stations_used,
    stations_weighted, areal_mean and area_km2 (the group's area the tiles cover: all of it once
    a gauge reports). Each group is averaged by a filter of its own, with the same gauges and
    observations and the whole catchment's projection (the record the whole's filter, `whole`,
    used), so that the tiles are the whole's and the groups' means weighted by their areas are the
    whole's mean (each group's automatic projection, fitted to it alone, moved weights by some
    1e-5); where the groups do not make the whole catchment (a group inside or over another's,
    which the whole's even-odd rule makes a hole), that is said. Its warnings, said for the whole
    catchment before, are not repeated; an error ends the script naming the group."""
    record = whole.GetOutputDataObject(1).GetFieldData().GetAbstractArray("TesseraProjection").GetValue(0)
    whole_areas = covered_areas(whole.GetOutputDataObject(2))
    group_areas = {}

    def by_value(v):  # numbers in numeric order first, then text
        try:
            number = float(v)
        except ValueError:
            number = math.nan
        return (0, number, v) if math.isfinite(number) else (1, 0.0, v)
    values = sorted(features, key=by_value)
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow([name, *steps.columns, "stations_used", "stations_weighted", "areal_mean", "area_km2"])
        for k, value in enumerate(values):
            if interactive():
                print(f"\rareal means by {name}: {k + 1} of {len(values)}", end="", file=sys.stderr, flush=True)
            average = areal_average(gauges, features[value], observations)
            average.SetProjectionRecord(record)
            errors = csv_input.errors_of_update(average, 1)
            summary, weights = average.GetOutputDataObject(1), average.GetOutputDataObject(2)
            if errors or summary is None or summary.GetNumberOfRows() == 0:
                if interactive():
                    print(file=sys.stderr)
                csv_input.fail(f"{catchment_path}: the features with {name} = {value}: "
                               + (errors[0] if errors else "the areal average failed"))
            covered = covered_areas(weights)
            for t, area in covered.items():
                group_areas[t] = group_areas.get(t, 0.0) + area
            for t, step, used, weighted, mean in summary_rows(summary, steps):
                area = covered.get(t)
                out.writerow([value, *step, used, weighted, mean_text(mean),
                              "" if area is None else f"{area / 1e6:.15g}"])
    print(f"\rareal means by {name}: {len(values)} of {len(values)}" if interactive()
          else f"areal means by {name}: {len(values)} of {len(values)}", file=sys.stderr)
    # (Areas the tiles cover: all of a region once a gauge reports; the largest difference of the
    # steps, relative, beyond what densifying the groups' own edges can make.)
    off = max((abs(group_areas.get(t, 0.0) - a) / a for t, a in whole_areas.items() if a > 0), default=0.0)
    if off > 1e-6:
        t = max(whole_areas, key=lambda t: abs(group_areas.get(t, 0.0) - whole_areas[t]))
        print(f"{catchment_path}: the groups of {name} do not make the catchment: their areas sum to "
              f"{group_areas.get(t, 0.0) / 1e6:.6g} km2 where the catchment has {whole_areas[t] / 1e6:.6g} km2 (a "
              "feature inside or over a feature of another group is a hole of the catchment, by the even-odd "
              "rule, but a part of its group): their means weighted by area do not make the whole's",
              file=sys.stderr)


def write_unused(summary, files, station_ids, observations, unit, path, unmatched_columns=(), outside=(),
                 summed_repeats=(), dropped=()):
    """Every input the filter did not use, one row each (the warnings name the first 20 of each
    kind): kind, file, line, station_id and a note: for a gauge at the place of an earlier one,
    that gauge's line; for a gauge without an observed value whose station id an earlier gauge has
    (station_key: 0102 and 102), that gauge's line (its observations went there); for an
    observation repeating an earlier one, the earlier one's line; for an observation of a gauge at
    the place of an earlier one that reported, the line of the observation used (the filter's
    CoLocatedObservationOfRows); a row for each column of a wide observations file that names no
    gauge's station (unmatched_columns: (column number, name), read_observations), at the header's line, its
    number in the note; and a row for each run of observations outside --start/--end (outside:
    rows_in_period's runs), which the filter never saw: its lines (first-last), its station, or
    when it holds several, how many observations of how many stations; and a row for each
    observation --sum-to left out as a repeat (summed_repeats: sum_rows'), the earlier one's line
    in the note; and a row for each value --drop-flagged left out (dropped: (line, flag,
    station_id)), its flag in the note. Returns the number of inputs listed."""
    fields = summary.GetFieldData()
    stations = observations.GetColumnByName("station_id")
    shared_of = later_gauges_of_shared_ids(station_ids)
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["kind", "file", "line", "station_id", "note"])
        written = write_unused_by_filter(out, fields, files, station_ids, shared_of, stations, unit)
        written += write_unused_in_reading(out, files, unmatched_columns, outside, summed_repeats, dropped)
    return written


def later_gauges_of_shared_ids(station_ids):
    """Each gauge whose station id (station_key) an earlier gauge has: that earlier gauge."""
    first_with_id, shared_of = {}, {}  # (station_key: its first gauge; a later gauge with it: that gauge)
    for g, station in enumerate(station_ids):
        first = first_with_id.setdefault(station_key(station), g)
        if first != g:
            shared_of[g] = first
    return shared_of


def write_unused_by_filter(out, fields, files, station_ids, shared_of, stations, unit):
    """write_unused's rows of the inputs the filter named unused (UNUSED_LISTS, in its summary's
    field data: fields); shared_of: later_gauges_of_shared_ids'; stations: the observations'
    station_id column. Returns how many."""
    earlier = fields.GetArray("DuplicateOfGaugeIds")
    repeated_of = fields.GetArray("RepeatedObservationOfRows")
    used_instead = fields.GetArray("CoLocatedObservationOfRows")
    written = 0
    for name, kind, of_rows in UNUSED_LISTS:
        kind = kind.format(unit=unit) + (files.within if name == "UnobservedGaugeIds" else "")
        ids = fields.GetArray(name)
        for k in range(ids.GetNumberOfTuples() if ids else 0):
            i = int(ids.GetValue(k))
            if of_rows:
                note = unused_observation_note(name, k, files, stations, repeated_of, used_instead)
                out.writerow([kind, files.observations, files.row_line(i) or "", stations.GetValue(i), note])
            else:
                note = unused_gauge_note(name, k, i, files, station_ids, earlier, shared_of)
                out.writerow([kind, files.stations, files.gauge_lines[i], station_ids[i], note])
            written += 1
    return written


def unused_observation_note(name, k, files, stations, repeated_of, used_instead):
    """The note on the k-th observation of the filter's list name: the line it repeats, or the
    line of the value used in its place."""
    note = ""
    if name == "RepeatedObservationRows" and repeated_of:
        note = f"repeats line {files.row_line(int(repeated_of.GetValue(k))) or ''}"
    elif name == "CoLocatedObservationRows" and used_instead:
        used = int(used_instead.GetValue(k))
        if used >= 0 and files.row_line(used):
            note = (f"the value of line {files.row_line(used)} (station {stations.GetValue(used)} "
                    "at the same place) is used")
    return note


def unused_gauge_note(name, k, i, files, station_ids, earlier, shared_of):
    """The note on gauge i, the k-th of the filter's list name: the gauge at its place, or the
    gauge its observations go to."""
    note = ""
    if name == "DuplicateGaugeIds" and earlier:
        note = f"same place as {files.place_word()} {files.gauge_lines[int(earlier.GetValue(k))]}"
    elif name == "UnobservedGaugeIds" and i in shared_of:
        first = shared_of[i]
        note = (f"station id of {files.place_word()} {files.gauge_lines[first]} "
                f"({station_ids[first]}): its observations go to that gauge")
    return note


def write_unused_in_reading(out, files, unmatched_columns, outside, summed_repeats, dropped):
    """write_unused's rows of the inputs left out in reading, which the filter never saw. Returns
    how many inputs they list."""
    written = 0
    for number, name in unmatched_columns:
        out.writerow(["observations column naming no gauge's station (not read)", files.observations, 1, name,
                      f"column {number}"])
        written += 1
    for line, earlier, station in summed_repeats:
        out.writerow([SUMMED_REPEAT, files.observations, line, station, f"repeats line {earlier}"])
        written += 1
    for line, flag, station in dropped:
        out.writerow([DROPPED_FLAGGED, files.observations, line, station, f"QFLAG {flag}"])
        written += 1
    for first, last, count, names in outside:
        several = f" of {len(names)} stations" if len(names) > 1 else ""
        out.writerow([OUTSIDE_PERIOD, files.observations, first if first == last else f"{first}-{last}",
                      next(iter(names)) if len(names) == 1 else "",
                      f"{count} observations{several}" if count > 1 else ""])
        written += count
    return written


def tiles_by_gauge(tiles):
    """Per gauge: weight, area, value (the gauge's, repeated on each of its cells) and its pieces
    (one cell each: lists of (lon, lat); a tile whose part of the catchment has a hole or is in
    parts joined at the tile's edge comes as several pieces)."""
    cd = tiles.GetCellData()
    gauge_ids, weights = cd.GetArray("GaugeId"), cd.GetArray("Weight")
    areas, values = cd.GetArray("Area_m2"), cd.GetArray("Value")
    result = {}
    for c, ring in enumerate(polygon_rings(tiles)):  # (the tiles are polygon cells only)
        g = gauge_ids.GetValue(c)
        entry = result.setdefault(g, {"weight": weights.GetValue(c), "area": areas.GetValue(c),
                                      "value": values.GetValue(c), "rings": []})
        entry["rings"].append(ring)
    return result


def write_tiles_geojson(outlines, gauges, path):
    """The step's tiles as GeoJSON (RFC 7946) at path, for a GIS: a Feature per gauge whose tile
    reaches the catchment, with its station_id, name, weight, area_km2 and precip as
    weights_TAG.csv gives them. Its geometry is its part of the catchment (the filter's output 3,
    the tiles' outlines) in lon/lat: a Polygon (the outer ring anticlockwise, then its holes
    clockwise, each closed), or a MultiPolygon of several (a tile across a bay; a tile across the
    180th meridian, cut there), longitudes within -180 to 180. Ends the script naming the file when
    it cannot be written."""
    import json

    ids = gauges.GetPointData().GetAbstractArray("station_id")
    names = gauges.GetPointData().GetAbstractArray("name")
    cd = outlines.GetCellData()
    gauge_ids, polygon_ids, weights, areas, values = (
        cd.GetArray(n) for n in ("GaugeId", "PolygonId", "Weight", "Area_m2", "Value"))
    features, polygons = {}, {}  # by gauge: the feature; by polygon id: its rings
    for c, ring in enumerate(polygon_rings(outlines)):  # (closed lines, the first point repeated)
        g, p = gauge_ids.GetValue(c), polygon_ids.GetValue(c)
        if g not in features:
            value = values.GetValue(c)
            features[g] = {"type": "Feature", "geometry": [], "properties": {
                "station_id": ids.GetValue(g), "name": names.GetValue(g), "weight": weights.GetValue(c),
                "area_km2": areas.GetValue(c) / 1e6,
                "precip": value if math.isfinite(value) else None}}  # (JSON has no NaN)
        if p not in polygons:
            polygons[p] = []
            features[g]["geometry"].append(polygons[p])
        polygons[p].append(ring)
    for feature in features.values():
        feature["geometry"] = [within_180(polygon) for polygon in feature["geometry"]]
        parts = feature["geometry"]
        feature["geometry"] = ({"type": "Polygon", "coordinates": parts[0]} if len(parts) == 1 else
                               {"type": "MultiPolygon", "coordinates": parts})
    try:
        with open(path, "w") as f:
            json.dump({"type": "FeatureCollection", "features": list(features.values())}, f)
    except OSError as error:
        csv_input.fail(f"{path}: cannot write the tiles ({error.strerror or error})")


def within_180(polygon):
    """A polygon's rings (lists of (lon, lat)), which lie on one side of the 180th meridian or a
    copy of it a whole turn away (the outlines are cut there), moved by whole turns to within
    -180 .. 180, as lists [lon, lat]. The turns go by the side the polygon is on: by its
    westernmost longitude, 179.99999999999997 + 180 rounds to 360, and a western part ending at
    180 was moved a turn, to -180.00000000000003 .. -180."""
    west, east = min(x for x, _ in polygon[0]), max(x for x, _ in polygon[0])
    turns = 0
    if east > 180.0:
        turns = math.ceil((east - 180.0) / 360.0)
    elif west < -180.0:
        turns = math.floor((west + 180.0) / 360.0)
    return [[[x - 360.0 * turns, y] for x, y in ring] for ring in polygon]


def write_weights(per_gauge, gauges, path):
    ids = gauges.GetPointData().GetAbstractArray("station_id")
    names = gauges.GetPointData().GetAbstractArray("name")
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["station_id", "name", "lon", "lat", "weight", "area_km2", "precip"])
        for g in sorted(per_gauge, key=lambda g: -per_gauge[g]["weight"]):
            lon, lat, _ = gauges.GetPoint(g)
            e = per_gauge[g]
            # (15 digits as the other values: a UTM gauge's inverse gave -108.07999999999866)
            out.writerow([ids.GetValue(g), names.GetValue(g), f"{lon:.15g}", f"{lat:.15g}",
                          f"{e['weight']:.15g}", f"{e['area'] / 1e6:.15g}", f"{e['value']:.15g}"])


def polygon_rings(data):
    """The vertices, as lists of (x, y), of each polygon cell of a vtkPolyData, then of each of its
    polylines."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    rings = []
    if data.GetPoints() is None:
        return rings
    # (as arrays: a point at a time, 10^6 points of a detailed catchment's tiles took seconds)
    xy = vtk_to_numpy(data.GetPoints().GetData())[:, :2].tolist()
    for cells in (data.GetPolys(), data.GetLines()):
        offsets = vtk_to_numpy(cells.GetOffsetsArray()).tolist()
        connectivity = vtk_to_numpy(cells.GetConnectivityArray()).tolist()
        for c in range(cells.GetNumberOfCells()):
            rings.append([tuple(xy[i]) for i in connectivity[offsets[c]:offsets[c + 1]]])
    return rings


def polygon_blocks(data):
    """The number of polydata blocks with a polygon or closed line (features, for a
    vtkGDALVectorReader's output)."""
    return sum(1 for block in projected_input.polydata_blocks(data) if catchment_rings(block))


def catchment_rings(data):
    """The catchment's rings as lists of (lon, lat), one per polygon cell or closed polyline of
    every polydata block (a multiblock such as vtkGDALVectorReader's, or a vtkPolyData), a
    closing point equal to the first dropped: an outline of several rings (islands, holes) is
    drawn ring by ring, not as one line through all its points."""
    rings = []
    for block in projected_input.polydata_blocks(data):
        # GDAL gives a polygon's rings as polygons or as closed lines; the filter reads both.
        for ring in polygon_rings(block):
            if len(ring) > 1 and ring[0] == ring[-1]:
                ring.pop()
            if len(ring) >= 3:
                rings.append(ring)
    return rings


def near(lon, reference):
    """lon moved by whole turns to within 180 degrees of reference."""
    return lon - 360.0 * round((lon - reference) / 360.0)


def unwrapped(ring, reference):
    """A ring's vertices with their longitudes moved by whole turns so that the first lies within
    180 degrees of reference and each other within 180 degrees of the one before: a ring across the
    180th meridian (179.5 then -179.5) stays one small ring instead of one around the globe."""
    result, last = [], reference
    for lon, lat in ring:
        last = near(lon, last)
        result.append((last, lat))
    return result


def map_extent(rings, points, margin=0.05):
    """(lon_min, lon_max, lat_min, lat_max) of the rings and the points, each side moved out by
    margin times the larger of the two spans, so that the catchment and the gauges that carry
    weight fill the map wherever the catchment is."""
    lons = [p[0] for ring in rings for p in ring] + [p[0] for p in points]
    lats = [p[1] for ring in rings for p in ring] + [p[1] for p in points]
    pad = margin * max(max(lons) - min(lons), max(lats) - min(lats), 1e-6)
    # (no latitude beyond a pole: a catchment wide in longitude near one padded them to -110)
    return min(lons) - pad, max(lons) + pad, max(min(lats) - pad, -90.0), min(max(lats) + pad, 90.0)


def map_layout(outline, per_gauge, points):
    """What the map draws, in longitudes near the catchment's (whole turns apart, so that a
    catchment across the 180th meridian, or written in 0..360 while the tiles come in -180..180,
    is drawn in one piece): the outline unwrapped from its first vertex, then the tiles and the
    gauges within 180 degrees of the middle of its longitudes (of its first vertex, a catchment
    wide in longitude had the tiles beyond 180 degrees from it drawn a turn away from it). Returns
    (outline, per_gauge with its rings moved, the gauges' longitudes, their latitudes, map_extent of
    the outline and the weighted gauges). points: every gauge's (lon, lat)."""
    outline = [unwrapped(ring, outline[0][0][0]) for ring in outline]
    lons = [p[0] for ring in outline for p in ring]
    reference = (min(lons) + max(lons)) / 2 if lons else 0.0
    per_gauge = {g: dict(e, rings=[unwrapped(ring, reference) for ring in e["rings"]])
                 for g, e in per_gauge.items()}
    lon = [near(p[0], reference) for p in points]
    lat = [p[1] for p in points]
    return outline, per_gauge, lon, lat, map_extent(outline, [(lon[g], lat[g]) for g in per_gauge])


def plot_map(per_gauge, gauges, outline, reporting, title, path, adjective="monthly"):
    """outline: the catchment's rings (catchment_rings); the map shows them and the weighted
    gauges (map_extent). A month (or day) where no gauge reported has no tiles: the map shows the
    outline and the gauges, without tiles or colour bar."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    from matplotlib.collections import PolyCollection

    outline, per_gauge, lon, lat, (lon_min, lon_max, lat_min, lat_max) = map_layout(
        outline, per_gauge, [gauges.GetPoint(i)[:2] for i in range(gauges.GetNumberOfPoints())])
    fig, ax = plt.subplots(figsize=(9, 6.5))
    # A tile of one piece is outlined in white; the pieces of a tile in several are drawn without
    # outlines, so that the seams between them do not look like tile boundaries: edges a point wide
    # in their own colour cover the seams (at 0.4 points, antialiasing left faint lines there, a
    # trial's maps of wavy outlines striped with them).
    values = [e["value"] for e in per_gauge.values()]
    for whole in ((False, True) if values else ()):
        pieces = [(ring, e["value"]) for e in per_gauge.values() if (len(e["rings"]) == 1) == whole
                  for ring in e["rings"]]
        collection = PolyCollection([ring for ring, _ in pieces], array=[v for _, v in pieces],
                                    cmap="viridis_r", edgecolors="white" if whole else "face",
                                    linewidths=0.4 if whole else 1.0)
        collection.set_clim(min(values), max(values))
        ax.add_collection(collection)
    if values:
        fig.colorbar(collection, ax=ax, label=f"{adjective} precipitation (data units)")
    for ring in outline:
        xs, ys = zip(*ring)
        ax.plot(xs + xs[:1], ys + ys[:1], color="black", linewidth=1.2)
    # A legend entry only for the kinds of gauge on the map ("gauge, no report" stood on maps where
    # every gauge shown reported).
    shown = [i for i in range(len(lon)) if lon_min <= lon[i] <= lon_max and lat_min <= lat[i] <= lat_max]
    silent = [i for i in shown if i not in reporting]
    heard = [i for i in shown if i in reporting]
    if silent:
        ax.scatter([lon[i] for i in silent], [lat[i] for i in silent],
                   s=6, facecolors="none", edgecolors="grey", linewidths=0.5, label="gauge, no report")
    if heard:
        ax.scatter([lon[i] for i in heard], [lat[i] for i in heard], s=9, color="red", label="gauge, reported")
    ax.set_xlim(lon_min, lon_max)
    ax.set_ylim(lat_min, lat_max)
    ax.set_aspect(1.0 / math.cos(math.radians((lat_min + lat_max) / 2)))  # degrees of equal length
    # (longitudes beyond 180 after unwrapping are labelled as written: 181 as -179)
    ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda x, _: f"{near(x, 0.0):g}"))
    ax.set_xlabel("longitude")
    ax.set_ylabel("latitude")
    ax.set_title(title)
    # Below the map, beside no tile: "best" put it over the tiles of a catchment that fills the map.
    if silent or heard:
        fig.legend(loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0.0, 0.04, 1.0, 1.0))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def step_series(rows, steps=None):
    """The time series areal_mean.png plots, from write_summary's rows (of steps, Steps; by
    default months, days or hours as the rows' fields say): (times,
    means, gauges reporting), a point for every step from the first row's to the last's. A step
    without an areal mean (no gauge reported, or no row: 0 gauges) has mean NaN, where matplotlib
    breaks the line: dropping it would draw the line straight across the gap as if it had been
    measured."""
    by_step = {tuple(r[:-3]): (r[-3], r[-1]) for r in rows}
    steps = steps or Steps.of(rows[0][:-3])
    every = steps.between(min(by_step), max(by_step))
    values = [by_step.get(step, (0, math.nan)) for step in every]
    return [steps.time(step) for step in every], [mean for _, mean in values], [used for used, _ in values]


def plot_series(rows, path, steps=None):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    steps = steps or Steps.of(rows[0][:-3])
    t, v, used = step_series(rows, steps)
    first, last = tuple(rows[0][:-3]), tuple(rows[-1][:-3])
    # Days or times, or months of a few years: dates on the axis (decimal years of a few days read
    # 0.078 .. 0.083 + 2.001e3, and of three months 0.000 .. 0.175 + 2.02e3).
    dated = steps.fields > 2 or (steps.fields == 2 and last[0] - first[0] < 5)
    if dated:
        moment = datetime.datetime if steps.fields > 3 else datetime.date
        t = [moment(*step, *(1,) * (3 - len(step))) for step in steps.between(first, last)]
    # A step with a mean between two without is no segment of the line: a dot shows it.
    alone = [i for i in range(len(v)) if not math.isnan(v[i])
             and (i == 0 or math.isnan(v[i - 1])) and (i == len(v) - 1 or math.isnan(v[i + 1]))]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(11, 6), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1]})
    top.plot(t, v, linewidth=0.6, color="tab:blue")
    top.plot([t[i] for i in alone], [v[i] for i in alone], linestyle="none", marker=".", markersize=2,
             color="tab:blue")
    top.set_ylabel("Thiessen areal mean (data units)")
    span = (steps.text(first) if first == last else f"{steps.text(first)} to {steps.text(last)}" if dated
            else f"{rows[0][0]}-{rows[-1][0]}")
    top.set_title(f"{steps.adjective.capitalize()} precipitation, Thiessen areal mean {span}")
    bottom.plot(t, used, linewidth=0.6, color="tab:grey")
    bottom.set_ylabel("gauges reporting")
    bottom.set_xlabel("date" if dated else "year")
    if dated:
        fig.autofmt_xdate()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def say_zone_not_taken(text, date, option):
    """Ends the script for an option's time (text, stripped; date: its DATE match) that ends with
    a time zone: the observations' times are read as written (in their one zone), so the
    options' are too, without it."""
    timed = TIME_OF_DAY.match(text, date.end()) if date and date.group(3) else None
    if timed and timed.end() < len(text) and ZONE.fullmatch(text, timed.end()):
        sys.exit(f"{option} {text!r}: give the time without its time zone (the observations' times are read as "
                 "written, in their one zone)")


def chosen_time(text, option="--hour"):
    """--hour's (year, month, day, hour), or for another option (--minute, --start, --end) the
    time as (year, month, day, hour, minute), written as the observations write a time
    (YYYY-MM-DD HH:00 for an hour, HH:MM otherwise, or with a T; 24:00 is hour 0 of the next day);
    ends the script naming the value otherwise (as the option's, option)."""
    date = DATE.match(text.strip())
    clock = TIME_OF_DAY.fullmatch(text.strip(), date.end()) if date and date.group(3) else None
    hour = option == "--hour"
    zero = clock.groups()[1 if hour else 2:] if clock else ()  # (minutes for an hour; seconds)
    if not clock:
        say_zone_not_taken(text.strip(), date, option)
    if not clock or any(int(v or 0) for v in zero):
        sys.exit(f"{option} {text!r}: expected a date and " + ("hour, YYYY-MM-DD HH:00" if hour else
                                                              "time, YYYY-MM-DD HH:MM"))
    step = tuple(int(v) for v in (*date.groups(), *clock.groups()[:2]))
    if not is_calendar_day(*step[:3]) or step[3] > 24 or step[4] > 59 or (step[3] == 24 and step[4]):
        sys.exit(f"{option} {text!r}: is not {'an hour' if hour else 'a time'} of the calendar")
    try:
        step = hour_step(step)
    except OverflowError:  # (24:00 of 9999-12-31)
        sys.exit(f"{option} {text!r}: is after the calendar's last hour")
    return step[:4] if hour else step


def period_bound(text, option):
    """--start's or --end's (option's) step as written: (year, month), (year, month, day) or (year,
    month, day, hour), or None when not given; ends the script naming the value otherwise."""
    if text is None:
        return None
    text = text.strip()
    date = DATE.match(text)
    if date and date.group(3) and date.end() < len(text):
        return chosen_time(text, option)
    if not date or date.end() < len(text):
        sys.exit(f"{option} {text!r}: expected YYYY-MM, YYYY-MM-DD or 'YYYY-MM-DD HH:MM'")
    step = tuple(int(v) for v in date.groups() if v is not None)
    if step[0] < 1 or not 1 <= step[1] <= 12 or (len(step) == 3 and not is_calendar_day(*step)):
        sys.exit(f"{option} {text!r}: is not a date of the calendar")
    return step


def widened(bound, fields, last, minutes=1):
    """A period bound (period_bound's) as a step of `fields` numbers: a month is its first day (its
    last, for last), a day its first hour (its last), an hour its first step of minutes (its last,
    of steps of minutes long); a bound as fine is itself."""
    if len(bound) == 2 and fields > 2:
        bound = (*bound, calendar.monthrange(*bound)[1] if last else 1)
    if len(bound) == 3 and fields > 3:
        bound = (*bound, 23 if last else 0)
    if len(bound) == 4 and fields > 4:
        bound = (*bound, 60 - minutes if last else 0)
    return bound


def check_period(start, end, texts):
    """Ends the script when --start (period_bound's) comes after --end, each taken as widely as it
    reads (a month from its first hour, to its last)."""
    if start is not None and end is not None and widened(start, 5, False) > widened(end, 5, True):
        sys.exit(f"--start {texts[0].strip()} is after --end {texts[1].strip()}")


def off_grid(given, steps, path):
    """The message for an option's time (given: the option and its value) off the steps' grid."""
    return (f"{given}: the observations of {path} are {steps.described}: give a time whose minute is a multiple of "
            f"{steps.minutes}")


class Period:
    """--start and --end (period_bound's steps, or None), made steps of the observations' unit
    (steps): a month given for days or hours is its first or last day or hour, a day given for
    hours its first or last hour. Ends the script for a bound finer than the observations' steps
    (a start after the end is refused before the file is read: check_period)."""

    def __init__(self, steps, start, end, texts, path):
        self.start = self.unit_step(steps, start, False, texts[0], path)
        self.end = self.unit_step(steps, end, True, texts[1], path)

    @staticmethod
    def unit_step(steps, bound, last, text, path):
        if bound is None:
            return None
        option = "--end" if last else "--start"
        if len(bound) == 5 and steps.fields == 4 and not bound[4]:
            bound = bound[:4]  # (a time on the hour is the hour)
        if len(bound) > steps.fields:
            written = {2: "YYYY-MM", 3: "YYYY-MM-DD", 4: "YYYY-MM-DD HH:00"}[steps.fields]
            csv_input.fail(f"{option} {text}: the observations of {path} are {steps.described}: give "
                           f"{'an' if steps.unit == 'hour' else 'a'} {steps.unit} ({written})")
        if not steps.on_grid(bound):
            csv_input.fail(off_grid(f"{option} {text}", steps, path))
        return widened(bound, steps.fields, last, steps.minutes)

    def __contains__(self, step):
        return (self.start is None or self.start <= step) and (self.end is None or step <= self.end)

    def given(self):
        return self.start is not None or self.end is not None


def argument_parser():
    """The script's options, in the order --help lists them."""
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="out", help="output directory (created if missing; default out, in the current directory)")
    add_step_options(parser)
    add_input_options(parser)
    add_catchment_options(parser)
    add_value_options(parser)
    parser.add_argument("--no-plots", action="store_true", help="skip the PNG files")
    parser.add_argument("--no-all-weights", action="store_true",
                        help="skip weights_all_*.csv (every step's weights: with thousands of gauges and "
                             "years of days, as large as the observations) and the memory it takes")
    return parser


def add_step_options(parser):
    """--month, --day, --hour, --minute (the steps shown), --sum-to and --start/--end."""
    parser.add_argument("--month", action="append", help="month for the weights, tiles and map, YYYY-MM (may be "
                                                         "given more than once: each month's files; default: 1963-08, "
                                                         "or the nearest month of the record where a gauge reported; "
                                                         "with observations other than the Colorado example's, "
                                                         "their last month (day, hour) where a gauge reported; "
                                                         "with daily, hourly or sub-hourly observations its first "
                                                         "day, hour or step in the record and --start/--end; a "
                                                         "month none of whose steps is in the record and within "
                                                         "--start/--end is an error, as is such a --day, --hour "
                                                         "or --minute)")
    parser.add_argument("--day", action="append", help="day for the weights, tiles and map when the observations "
                                                       "give days, YYYY-MM-DD (may be given more than once; with "
                                                       "hourly observations its first hour in the record and "
                                                       "--start/--end: 00:00 where they hold it, which for "
                                                       "hour-ending data is the day before's last; not with "
                                                       "--month)")
    parser.add_argument("--hour", action="append", help="hour for the weights, tiles and map when the observations "
                                                        "give hours, 'YYYY-MM-DD HH:00' (or with a T: "
                                                        "YYYY-MM-DDTHH:00; 24:00 is the next day's 00:00; may be "
                                                        "given more than once; not with --month or --day)")
    parser.add_argument("--minute", action="append", help="time for the weights, tiles and map when the observations "
                                                          "give steps of minutes, 'YYYY-MM-DD HH:MM' (or with a T; "
                                                          "may be given more than once; not with --month, --day or "
                                                          "--hour)")
    parser.add_argument("--sum-to", type=int, metavar="MINUTES",
                        help="sum each station's values of steps of minutes into steps of MINUTES minutes (a "
                             "multiple of the observations' steps that divides 60; 60 gives hours), each the total "
                             "of the minutes up to its time (a value at 10:05 goes to 10:15 with --sum-to 15), "
                             "missing where none of its values is given: for gauges of 5-minute steps beside "
                             "gauges of 15, or to average hours")
    parser.add_argument("--start", help="the first step to average: YYYY-MM, YYYY-MM-DD or 'YYYY-MM-DD HH:MM', no "
                                        "finer than the observations' steps (a month is its first day or hour with "
                                        "daily or hourly observations; default: the observations' first); "
                                        "areal_mean.csv starts there, and unused_inputs.csv lists the observations "
                                        "before it; hours keep their labels, so for hour-ending data a day's last hour "
                                        "is its 24:00, the next day's 00:00: give --end 'YYYY-MM-DD 24:00' to end with "
                                        "it, and --start 'YYYY-MM-DD 01:00' to start a day")
    parser.add_argument("--end", help="the last step to average, as --start (a month is its last day or hour with "
                                      "daily or hourly observations; default: the observations' last)")


def add_input_options(parser):
    """--stations and the options of its coordinates, and --observations."""
    parser.add_argument("--stations",
                        help="CSV of gauges: columns station_id, lon, lat (degrees, WGS84), "
                             f"optional name; {csv_input.SEPARATORS_TEXT}; "
                             f"{', '.join(f'{other} as {name}' for other, name in csv_input.ALIAS_OF.items())} "
                             "(in any case, as NOAA's Climate Data Online writes STATION, LATITUDE, LONGITUDE) "
                             "are read too, and site_no or id as station_id in a file without station_id or "
                             "station (site_no in --observations too, id not: there it is as likely a row's "
                             "number). It may be the observations file, with the station's place on each row "
                             "(as NOAA's CSV has it); default: the observations file where it has such columns, "
                             "else examples/data/colorado_stations.csv. Or a GIS file of points (GeoJSON, "
                             "shapefile, KML, GeoPackage, or a zip file holding one), an id attribute on each "
                             "(--stations-id), in lon/lat or a projected system it declares; the messages and "
                             "unused_inputs.csv then give a gauge's feature number (from 1) as its line")
    parser.add_argument("--stations-id", metavar="ATTRIBUTE",
                        help="with a GIS file of points as --stations: the attribute holding the station ids "
                             f"(default: the first of {', '.join(STATION_FIELDS)} it has, in any case)")
    parser.add_argument("--stations-utm", metavar="ZONE",
                        help="the stations file gives eastings and northings in metres of this UTM zone (1 to 60 "
                             "with N or S, such as 13N; WGS84, within a metre or two of NAD83 and ETRS89), in "
                             "columns x and y instead of lon and lat: they are made lon/lat first (the outputs "
                             "give lon/lat)")
    parser.add_argument("--stations-crs", metavar="CRS",
                        help="the stations file gives x and y (columns x, y) in this projected system: EPSG:CODE "
                             "(such as EPSG:5070, NAD83 / Conus Albers, or EPSG:2232, Colorado Central in US feet) "
                             "or PROJ terms ('+proj=aea +lat_0=23 +lon_0=-96 +lat_1=29.5 +lat_2=45.5 +x_0=0 "
                             f"+y_0=0 +units=m'); read: {projected_input.READ}, on WGS84 or GRS80; they are "
                             "made lon/lat first")
    parser.add_argument("--observations", default=DEFAULT_OBSERVATIONS,
                        help="CSV of monthly values, one row per gauge and month: columns "
                             f"station_id, year, month, precip ({csv_input.MISSING_TEXT} = missing); "
                             "or of daily values: columns station_id, year, month, day, precip, or "
                             "station_id, date (YYYY-MM-DD), precip; or of hourly values: columns station_id, "
                             "year, month, day, hour (0-23, or 24 for the end of the day), precip, or station_id, "
                             "date (YYYY-MM-DD HH:00), precip; or of steps of minutes (tipping buckets, loggers): "
                             "dates YYYY-MM-DD HH:MM, or hour and minute columns, each value the total up to its "
                             "time, the step the largest that divides 60 and every time's minute; a date column of "
                             "YYYY-MM gives months; or "
                             "wide: a row per time (date, or year, month, ...) with a column per station named "
                             f"by its station_id; {csv_input.SEPARATORS_TEXT}; default: the Colorado example's "
                             "record, examples/data/colorado_monthly_precip.csv")


def add_catchment_options(parser):
    """--catchment, and --feature and --each, which choose and group its features."""
    parser.add_argument("--catchment",
                        help="catchment polygon (GeoJSON or shapefile, or KML or GeoPackage, lon/lat, or a zip file "
                             "holding one; a file declaring a projected system in metres or feet, "
                             f"{projected_input.READ}, is made lon/lat); "
                             "every polygon feature of the file is taken, unless --feature chooses; default: "
                             "the Colorado example's outline, examples/data/colorado_boundary.geojson, for the "
                             "example's gauges; other gauges need it given")
    parser.add_argument("--feature", metavar="ATTRIBUTE=VALUE",
                        help="take only the catchment file's features whose attribute has this "
                             "value, such as HUC8=14010001 (whole numbers are written without .0)")
    parser.add_argument("--each", metavar="ATTRIBUTE",
                        help="also average over each group of the catchment file's features that share a "
                             "value of this attribute (such as HUC8: each sub-basin), into "
                             "areal_mean_by_ATTRIBUTE.csv (GDAL reads a feature without the attribute, or "
                             "with a null one, as 0 or empty text: it is grouped there)")


def add_value_options(parser):
    """--missing-value and --drop-flagged: the observed values read as missing."""
    parser.add_argument("--missing-value", action="append", type=float, default=[], metavar="NUMBER",
                        help="a precip value that means missing, such as -9999 (may be given more than once)")
    parser.add_argument("--drop-flagged", action="store_true",
                        help="leave out the values that have a NOAA quality flag (QFLAG, the second field of "
                             "PRCP_ATTRIBUTES in NOAA's Climate Data Online CSV: the value failed a quality check), "
                             "reading them as missing and listing them in unused_inputs.csv; without it they are "
                             "used as given, and named")


def main(argv=None):
    args = argument_parser().parse_args(argv)
    each, asked, bounds = checked_options(args)

    # Tessera first: without VTK (another Python than Debian's) this says how to run the script.
    csv_input.import_tessera()
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    # (the options first, --stations-crs's code looked up, the default inputs, then --out: all before
    # any input is read but the observations' header)
    stations_system = projected_input.stations_system(args.stations_utm, args.stations_crs, gdal_messages())
    choose_default_inputs(args)
    csv_input.output_directory(args.out)
    inputs = read_inputs(args, stations_system, asked, bounds, each)
    average, files, messages, summary = averaged_steps(args, inputs, vtkCommand)
    rows, unused = write_tables(args, inputs, average, files, summary)
    shown = write_shown_steps(args, inputs, average, messages, rows, vtkXMLPolyDataWriter)
    if not args.no_plots:
        plot_series(rows, os.path.join(args.out, "areal_mean.png"), inputs.record.steps)
    say_summary(args, inputs, rows, shown, unused)


def checked_options(args):
    """--each's attribute (or None), the steps asked for (asked_steps) and the --start/--end bounds,
    once the options are checked: a wrong one ends the script before any work."""
    given = [f"--{name} {values[0]}" for name, values in (("month", args.month), ("day", args.day),
                                                           ("hour", args.hour), ("minute", args.minute)) if values]
    if len(given) > 1:
        sys.exit(f"{' and '.join(given)}: give one of them")
    if args.each is not None and args.feature is not None:
        sys.exit(f"--each {args.each} and --feature {args.feature}: give one of them")
    each = args.each.strip() if args.each is not None else None
    if each is not None and not each:
        sys.exit("--each: expected the name of an attribute of the catchment's features, such as HUC8")
    if args.sum_to is not None and (args.sum_to < 1 or 60 % args.sum_to):
        sys.exit(f"--sum-to {args.sum_to}: expected a number of minutes that divides 60 (2, 3, 4, 5, 6, 10, 12, 15, "
                 "20, 30 or 60)")
    check_missing_values(args.missing_value)
    csv_input.check_paths(("--stations", args.stations, "stations"),
                          ("--observations", args.observations, "observations"),
                          ("--catchment", args.catchment, "catchment"))
    asked = asked_steps(args)
    bounds = (period_bound(args.start, "--start"), period_bound(args.end, "--end"))
    check_period(*bounds, (args.start, args.end))
    return each, asked, bounds


def choose_default_inputs(args):
    """Sets args.stations and args.catchment where not given: the stations from the observations
    file where it has their places (stations_path), the catchment the example's outline, for the
    example's gauges only (ends the script for others)."""
    if args.stations is None:
        args.stations = stations_path(args.observations)
        if args.observations != DEFAULT_OBSERVATIONS and args.stations != args.observations:
            print(f"note: without --stations, the gauges are the Colorado example's ({args.stations}): "
                  f"{args.observations} has no place columns (lon and lat, or LONGITUDE and LATITUDE) to read "
                  "its stations from; give your stations file with --stations", file=sys.stderr)
    if args.catchment is None:
        # (not the example's outline for other gauges: a trial's own data averaged over Colorado
        # ended with status 0 and a note, which a script calling this one does not read)
        if os.path.realpath(args.stations) != os.path.realpath(EXAMPLE_STATIONS):
            csv_input.fail(f"--catchment: not given, and the gauges ({args.stations}) are not the Colorado "
                           "example's: give your catchment's polygon file with --catchment (for gauges in "
                           f"Colorado, the example's outline is {EXAMPLE_CATCHMENT})")
        args.catchment = EXAMPLE_CATCHMENT


# The inputs read (read_inputs): the gauges (vtkPolyData) and each one's line in the stations file,
# their station ids, the observations (read_observations' Observations), the steps to show
# (check_asked_steps'), the catchment and its outline (read_catchment's), and --each's attribute and
# groups of features (None without --each).
Inputs = collections.namedtuple("Inputs", "gauges gauge_lines station_ids record wanted catchment outline each groups")


def read_inputs(args, stations_system, asked, bounds, each):
    """The gauges, observations and catchment, as Inputs; the steps asked for (asked) checked
    against the observations' steps."""
    started = time.time()
    combined = holds_observations(args.stations, args.observations)
    gauges, gauge_lines = read_gauges(args.stations, stations_system, combined, args.stations_id)
    if not gauge_lines:
        csv_input.fail(f"{args.stations}: no gauges (the file has no rows)")
    ids = gauges.GetPointData().GetAbstractArray("station_id")
    station_ids = [ids.GetValue(i) for i in range(ids.GetNumberOfValues())]
    record = read_observations(
        args.observations, first_gauge_of_stations(station_ids), min(station_ids, default=None), args.stations,
        set(args.missing_value), station_ids, bounds, (args.start, args.end), args.sum_to, args.drop_flagged)
    wanted = wanted_steps(asked, record, args)
    # (the observations file's rows: the table also has a row for each step without any)
    print(f"read {gauges.GetNumberOfPoints()} gauges and {record.read} observations in "
          f"{time.time() - started:.1f} s", file=sys.stderr)
    started = time.time()
    catchment, outline = read_catchment(args.catchment, args.feature)
    groups = polygon_groups(features_by_value(catchment, each, args.catchment), each,
                            args.catchment) if each is not None else None
    if time.time() - started >= 1.0:  # (a detailed outline: some 300,000 vertices take a second)
        print(f"read the catchment ({sum(map(len, outline))} vertices) in {time.time() - started:.1f} s",
              file=sys.stderr)
    return Inputs(gauges, gauge_lines, station_ids, record, wanted, catchment, outline, each, groups)


def first_gauge_of_stations(station_ids):
    """The gauge that a station's observations go to, by station_key."""
    # A station's observations go to the first gauge with its id (station_key), as in the filter.
    gauge_of = {}
    for i, station in enumerate(station_ids):
        gauge_of.setdefault(station_key(station), i)
    return gauge_of


def wanted_steps(asked, record, args):
    """The steps asked for (asked_steps') as check_asked_steps takes them, once each is checked to
    be of the observations' kind of step and on their grid."""
    steps = record.steps
    for option, when in asked:
        if len(when) > steps.fields:
            csv_input.fail(f"{option}: the observations of {args.observations} are {steps.described} "
                           f"(use --{steps.unit})")
        if not steps.on_grid(when):
            csv_input.fail(off_grid(option, steps, args.observations))
    # (a month is its first day or hour with daily or hourly steps, a day its 00:00 hour; check_asked_steps
    # takes the first of them in the record and period)
    wanted = [(option, when, widened(when, steps.fields, False, steps.minutes)) for option, when in asked]
    return check_asked_steps(wanted, record, args.observations, (args.start, args.end))


def averaged_steps(args, inputs, vtkCommand):
    """The areal average filter run over every step, with a progress bar: the filter, its InputFiles,
    its FilterMessages and its summary table (output 1)."""
    record = inputs.record
    steps = record.steps
    average = areal_average(inputs.gauges, inputs.catchment, record.table)
    # (--each measures its groups from that table)
    average.SetWeightsTable(not args.no_all_weights or inputs.groups is not None)
    progress = Progress("Thiessen areal means")
    progress_tag = average.AddObserver(vtkCommand.ProgressEvent, progress)
    started = time.time()
    files = InputFiles(args.stations, inputs.gauge_lines, args.observations, record.lines, args.catchment, steps.noun,
                       record.period.given())
    messages = FilterMessages(average, files, progress)
    average.Update(1)
    progress.stop()  # (prints what it held, had the run not reached 100%)
    summary = average.GetOutputDataObject(1)
    messages.check(summary is None or summary.GetNumberOfRows() == 0)
    count = summary.GetNumberOfRows()
    print(f"{count} {steps.noun}{'s' if count != 1 else ''} in {time.time() - started:.2f} s", file=sys.stderr)
    # The step's tiles below re-run the filter for that time only: no second progress bar.
    average.RemoveObserver(progress_tag)
    return average, files, messages, summary


def all_weights_name(steps):
    """The name of the file of every step's weights."""
    return f"weights_all_{steps.unit}s.csv"


def by_feature_name(each):
    """The name of the file of --each's areal means."""
    return "areal_mean_by_" + re.sub(r"[^A-Za-z0-9_.-]", "_", each) + ".csv"


def write_tables(args, inputs, average, files, summary):
    """Writes the files of all steps: areal_mean.csv, every step's weights, unused_inputs.csv and
    --each's means. Returns areal_mean.csv's rows (write_summary's) and the number of unused inputs."""
    record = inputs.record
    steps = record.steps
    rows = write_summary(summary, steps, os.path.join(args.out, "areal_mean.csv"))
    if totals_name(steps):
        write_totals(rows, steps, os.path.join(args.out, totals_name(steps)))
    write_all_weights_or_remove(args, average, steps)
    unused = write_unused(summary, files, inputs.station_ids, record.table, steps.noun,
                          os.path.join(args.out, "unused_inputs.csv"), record.unmatched, record.outside,
                          record.summed_repeats, record.dropped)
    if inputs.groups:
        write_means_by_feature(inputs.groups, inputs.each, inputs.gauges, record.table, steps, average,
                               args.catchment, os.path.join(args.out, by_feature_name(inputs.each)))
    return rows, unused


def write_all_weights_or_remove(args, average, steps):
    """Writes every step's weights (output 2), or with --no-all-weights removes an earlier run's file."""
    all_weights = all_weights_name(steps)
    if args.no_all_weights:
        stale = os.path.join(args.out, all_weights)
        if os.path.exists(stale):
            os.remove(stale)  # (an earlier run's, which would no longer match the other files)
            print(f"note: removed {stale}, an earlier run's: with --no-all-weights it would not match this run's "
                  "files", file=sys.stderr)
    else:
        write_all_weights(average.GetOutputDataObject(2), steps, os.path.join(args.out, all_weights))


def write_shown_steps(args, inputs, average, messages, rows, vtkXMLPolyDataWriter):
    """Writes the weights, tiles and map of each step shown (--month, ..., or the default), once
    each. Returns per step shown: (step, its tag, per_gauge)."""
    steps = inputs.record.steps
    shown = []  # per step shown: (step, its tag, per_gauge)
    for option, when, step in inputs.wanted:
        if not option:
            step = nearest_reported(rows, steps, default_step(rows, step, args.observations, DEFAULT_OBSERVATIONS))
        tiles, chosen = step_tiles(average, messages, steps, option, step)
        if any(chosen == earlier for earlier, _, _ in shown):
            continue  # (its files are written: another option gave the same step)
        tag = steps.tag(chosen)
        per_gauge = write_step_files(args, inputs, average, tiles, rows, chosen, tag, vtkXMLPolyDataWriter)
        shown.append((chosen, tag, per_gauge))
    return shown


def step_tiles(average, messages, steps, option, step):
    """The filter's tiles of step, and the table's step they are of (option: the option that asked
    for it, "" for the default)."""
    average.UpdateTimeStep(steps.time(step))
    tiles = average.GetOutputDataObject(0)
    messages.check(tiles is None)
    # (a step asked for is one of the table's (check_asked_steps); the default may be another)
    chosen = steps.of_time[tiles.GetInformation().Get(tiles.DATA_TIME_STEP())]
    if option and chosen != step:
        csv_input.fail(f"{option}: internal error: the filter gave the tiles of {steps.text(chosen)} for "
                       f"{steps.text(step)}, a step of the table (please report it)")
    return tiles, chosen


def write_step_files(args, inputs, average, tiles, rows, chosen, tag, vtkXMLPolyDataWriter):
    """Writes a step's (chosen's, tag: its part of the names) weights, tiles (VTK and GeoJSON) and
    map. Returns its tiles by gauge (tiles_by_gauge)."""
    steps = inputs.record.steps
    per_gauge = tiles_by_gauge(tiles)
    write_weights(per_gauge, inputs.gauges, os.path.join(args.out, f"weights_{tag}.csv"))
    csv_input.write_vtk(vtkXMLPolyDataWriter(), tiles, os.path.join(args.out, f"tiles_{tag}.vtp"))
    write_tiles_geojson(average.GetOutputDataObject(3), inputs.gauges, os.path.join(args.out, f"tiles_{tag}.geojson"))
    if not args.no_plots:
        plot_map(per_gauge, inputs.gauges, inputs.outline, inputs.record.reporting.get(chosen, set()),
                 map_title(rows, steps, chosen), os.path.join(args.out, f"map_{tag}.png"), steps.adjective)
    return per_gauge


def say_summary(args, inputs, rows, shown, unused):
    """The closing lines: a note on earlier runs' files kept in --out, the means, and the files
    written."""
    record, groups = inputs.record, inputs.groups
    steps = record.steps
    all_weights = all_weights_name(steps)
    if groups:
        by_feature = by_feature_name(inputs.each)
    tags = [tag for _, tag, _ in shown]
    step_files = [name for tag in tags for name in (f"weights_{tag}.csv", f"tiles_{tag}.vtp", f"tiles_{tag}.geojson")]
    plot_files = [] if args.no_plots else [f"map_{tag}.png" for tag in tags] + ["areal_mean.png"]
    totals = [totals_name(steps)] if totals_name(steps) else []
    say_earlier_outputs(args.out, {"areal_mean.csv", "unused_inputs.csv", *totals, *step_files, *plot_files}
                        | (set() if args.no_all_weights else {all_weights})
                        | ({by_feature} if groups else set()))
    say_means(rows, steps, shown)
    print(f"wrote {args.out}/areal_mean.csv, " + "".join(f"{name}, " for name in totals)
          + ("" if args.no_all_weights else f"{all_weights}, ")
          + ", ".join(step_files + plot_files)
          + f", unused_inputs.csv ({unused} input(s) not used"
          + (f", {outside_count(record.outside)} of them outside --start/--end)" if record.outside else ")")
          + (f", {by_feature} ({len(groups)} group(s) of features)" if groups else ""))


def say_means(rows, steps, shown):
    """The number of steps and the mean of their areal means, then each shown step's areal mean."""
    valid = [r[-1] for r in rows if not math.isnan(r[-1])]
    print(f"{len(rows)} {steps.noun}{'s' if len(rows) != 1 else ''}, {len(valid)} with data"
          + (f"; mean of the {steps.adjective} areal means {shown_mean(sum(v / len(valid) for v in valid))}"
             if valid else ""))
    for step, _, per_gauge in shown:
        used, weighted, mean = step_counts(rows, step)
        if used == 0:  # (its weights file and tiles are empty: said, not "areal mean nan")
            print(f"{steps.text(step)}: no gauge reported, so no areal mean; its weights and tiles files are empty")
            continue
        print(f"{steps.text(step)}: areal mean {shown_mean(mean)}, {used} gauges reported, "
              f"{weighted} weighted; weights sum to {sum(e['weight'] for e in per_gauge.values()):.12f}")


def check_asked_steps(wanted, record, path, bound_texts):
    """The steps asked for (wanted: (the option as given, the step as given, the step it stands
    for: a month of days is its first day)), each made the first of the table's steps (record:
    read_observations'; path: its file) within what it asks for: a --month of days or hours (a
    --day of hours) is taken where any of its days (hours) lies in the record and the period, from
    the first of them (a record from 1963-08-15, or --start 1963-08-10, has 1963-08). Ends the
    script, before the long work, for one none of whose steps is in the table: outside
    --start/--end (bound_texts: their values as given), or beyond the record. The filter would show
    its nearest step in its place, and the user would get another month's weights and map than the
    one asked for, under that month's name. The default step (option "") is the record's nearest
    where a gauge reported (nearest_reported), and is kept as it is."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy

    steps, period = record.steps, record.period
    times = vtk_to_numpy(record.table.GetColumnByName("time"))
    if not len(times):
        return wanted
    # The table has a row for every step from its first to its last (add_steps_without_rows): the
    # period's bounds where given, else the record's first and last step.
    first, last = steps.of_time[float(np.min(times))], steps.of_time[float(np.max(times))]
    taken = []
    for option, when, step in wanted:
        if not option:
            taken.append((option, when, step))
            continue
        # (what the option asks for, from its first step to its last: a month of days, all its days)
        asked_first, asked_last = step, widened(when, steps.fields, True, steps.minutes)
        if asked_first <= last and first <= asked_last:
            taken.append((option, when, max(asked_first, first)))
            continue
        if period.given() and not (asked_first <= (period.end or asked_first)
                                   and (period.start or asked_last) <= asked_last):
            bounds = " and ".join(f"--{name} {text.strip()}" for name, text in zip(("start", "end"), bound_texts)
                                  if text is not None)
            csv_input.fail(f"{option}: is outside {bounds} (the {steps.noun}s averaged run from {steps.text(first)} "
                           f"to {steps.text(last)}); give a {steps.noun} within them")
        run = "the {0}s averaged run" if period.given() else "its {0}s run"
        csv_input.fail(f"{option}: is not in the record of {path} ({run.format(steps.noun)} from {steps.text(first)} "
                       f"to {steps.text(last)}); give a {steps.noun} of the record")
    return taken


def shown_mean(value):
    """A mean as the messages and the map's title give it: to 3 decimals, or to 6 figures where
    that would be a long row of digits (values near 1e308 printed 300 of them)."""
    return f"{value:.3f}" if abs(value) < 1e12 else f"{value:.6g}"


def default_step(rows, step, observations, example_observations):
    """The step shown without --month (--day, ...): step (1963-08) for the Colorado example's
    record (example_observations), the record's last (rows: write_summary's) for another, where
    1963 means nothing; nearest_reported then takes the nearest where a gauge reported."""
    if os.path.realpath(observations) == os.path.realpath(example_observations) or not rows:
        return step
    return tuple(rows[-1][:-3])


def nearest_reported(rows, steps, step):
    """The first step of step's month where a gauge reported, else the step nearest to step (the
    earlier of two as near) where one did (rows: write_summary's), for the default: a --start
    before the data, or a gap in the record, would otherwise show a map without any gauge. step
    itself when none reported."""
    reported = [tuple(r[:-3]) for r in rows if r[-3] > 0]
    target = steps.time(step)
    return min(reported, key=lambda s: (s[:2] != step[:2], abs(steps.time(s) - target), steps.time(s)),
               default=step)


def map_title(rows, steps, step):
    """The map's title: the step, its areal mean and how many gauges gave it."""
    used, weighted, mean = step_counts(rows, step)
    if used == 0:
        return f"{steps.text(step)}: no gauge reported (Thiessen areal mean nan)"
    return f"{steps.text(step)}: Thiessen areal mean {shown_mean(mean)} from {weighted} of {used} reporting gauges"


def step_counts(rows, step):
    """areal_mean.csv's stations_used, stations_weighted and areal_mean of a step (rows:
    write_summary's)."""
    return next(r[-3:] for r in rows if tuple(r[:-3]) == step)


def asked_steps(args):
    """The steps --month, --day or --hour ask for, as (the option as given, the step: (year, month),
    (year, month, day) or (year, month, day, hour)), in the order given: the default month 1963-08
    (option "") when none is given. Ends the script naming a value that is not one."""
    asked = []
    for text in args.month or []:
        chosen = re.fullmatch(r"([0-9]{1,4})-([0-9]{1,2})", text.strip())
        if not chosen:
            sys.exit(f"--month {text!r}: expected YYYY-MM")
        year, month = int(chosen.group(1)), int(chosen.group(2))
        if not 1 <= year or not 1 <= month <= 12:
            sys.exit(f"--month {text!r}: {'the year must be 1 or later' if year < 1 else 'the month must be 01 to 12'}")
        asked.append((f"--month {text}", (year, month)))
    for text in args.day or []:
        chosen = DATE.fullmatch(text.strip())
        day = tuple(int(v) for v in chosen.groups()) if chosen and chosen.group(3) else None
        if not day:
            sys.exit(f"--day {text!r}: expected a date YYYY-MM-DD")
        if not is_calendar_day(*day):
            sys.exit(f"--day {text!r}: is not a date of the calendar")
        asked.append((f"--day {text}", day))
    for text in args.hour or []:
        asked.append((f"--hour {text}", chosen_time(text)))
    for text in args.minute or []:
        asked.append((f"--minute {text}", chosen_time(text, "--minute")))
    return asked or [("", (1963, 8))]


if __name__ == "__main__":
    csv_input.run(main)
