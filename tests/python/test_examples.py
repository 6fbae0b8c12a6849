"""The examples as a user runs them (examples/*.py with Debian's /usr/bin/python3): the Colorado
main job's files agree with the raw data and with each other, the other two examples run on their
data, and a user's bad files end the run with one line naming the file, line and column, never a
traceback."""

import csv
import datetime
import json
import math
import os
import random
import re
import subprocess
import sys
import tempfile

from tessera_testing import (EXAMPLE_DATA, SOURCE_DIR, assert_close, assert_that, cell_rings, colorado_outline,
                             run)

EXAMPLES = os.path.join(SOURCE_DIR, "examples")
COLORADO_CATCHMENT = os.path.join(EXAMPLE_DATA, "colorado_boundary.geojson")
MONTH = (1963, 8)


def run_example(script, *arguments):
    """Runs examples/<script> with the arguments; returns (exit status, stdout, stderr)."""
    done = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), *arguments],
                          capture_output=True, text=True, timeout=300)
    return done.returncode, done.stdout, done.stderr


def run_colorado(out, *arguments, what="the run", status=0, plots=True, **options):
    """Runs colorado_areal_precipitation.py with --out out, each keyword option as a flag
    (month="2001-01" as --month 2001-01), --no-plots unless plots, then the arguments; asserts its
    exit status (0 unless given) and returns its (stdout, stderr). Own gauges (stations, or
    --stations among the arguments) without a catchment get the Colorado outline as --catchment,
    which the script needs for them (most tests' own gauges lie in Colorado); catchment=None
    leaves it out."""
    if options.get("catchment", "") is None:
        del options["catchment"]
    elif "catchment" not in options and "--catchment" not in arguments and (
            "stations" in options or "--stations" in arguments):
        options["catchment"] = COLORADO_CATCHMENT
    flags = [item for name, value in options.items() for item in (f"--{name}", value)]
    got, stdout, stderr = run_example("colorado_areal_precipitation.py", "--out", out, *flags,
                                      *([] if plots else ["--no-plots"]), *arguments)
    assert_that(got == status, f"{what}: exit status {got}, expected {status}: {stderr}")
    return stdout, stderr


def assert_observations_refused(directory, stations, catchment, cases):
    """Runs the example on each case's observations text (written to directory/bad.csv) with its
    options; each run must end with status 1, its message holding the case's fragment."""
    for text, options, fragment in cases:
        bad = write(directory, "bad.csv", text)
        _, stderr = run_colorado(os.path.join(directory, "bad"), stations=stations, observations=bad,
                                 catchment=catchment, what=f"{text!r} {options}", status=1, plots=False, **options)
        assert_that(fragment in stderr and "Traceback" not in stderr, f"{text!r}: {fragment!r} not in {stderr!r}")


def without_timings(stderr):
    """A run's messages with their durations as "in T s", and without the line that only a slow
    catchment read prints ("read the catchment (9 vertices) in 1.1 s": a loaded machine can take a
    second for a small outline), so that two runs' messages compare."""
    stderr = re.sub(r"read the catchment \([0-9]+ vertices\) in [0-9.]+ s\n", "", stderr)
    return re.sub(r"in [0-9.]+ s\b", "in T s", stderr)


def write(directory, name, text):
    """Writes text into directory/name; returns its path."""
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def write_daily(directory, name, days):
    """A long file of daily observations ({(year, month, day): {station: value}}) as
    station_id,date,precip in directory/name; returns its path."""
    return write(directory, name, "station_id,date,precip\n" + "".join(
        f"{s},{y}-{m:02d}-{d:02d},{v}\n" for (y, m, d), values in days.items() for s, v in values.items()))


def write_stations(path, gauges):
    """A stations file of gauges ({station_id: (lon, lat)})."""
    with open(path, "w") as f:
        f.write("station_id,lon,lat\n" + "".join(f"{s},{lon},{lat}\n" for s, (lon, lat) in gauges.items()))


def assert_geojson_tiles(path, tiles, weighted):
    """Asserts that tiles_TAG.geojson at path holds tiles (the .vtp's vtkPolyData) as the script
    documents it: a feature per gauge with cells, in GaugeId order, with the properties of the
    gauge's row of weighted (weights_TAG.csv's rows); its geometry a Polygon or MultiPolygon of
    closed rings within -180 .. 180, each polygon's outer ring anticlockwise and its holes
    clockwise, holding the area of the gauge's cells (in lon/lat) and a point inside each of
    them. GDAL's reader gets a block per feature
    and a cell per ring."""
    from matplotlib.path import Path
    from vtkmodules.vtkIOGDAL import vtkGDALVectorReader

    def twice_area(ring):
        return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1]))

    with open(path) as f:
        features = json.load(f)["features"]
    cd, row_of = tiles.GetCellData(), {w["station_id"]: w for w in weighted}
    cells_of = {}
    for c, ring in enumerate(cell_rings(tiles)):
        cells_of.setdefault(cd.GetArray("GaugeId").GetValue(c), []).append(ring)
    assert_that(len(features) == len(cells_of), f"{path}: {len(features)} features for {len(cells_of)} gauges")
    ring_counts = []
    for feature, (gauge, cells) in zip(features, sorted(cells_of.items())):
        geometry, properties = feature["geometry"], feature["properties"]
        assert_that(geometry["type"] in ("Polygon", "MultiPolygon"), f"{path}: gauge {gauge}'s {geometry['type']}")
        polygons = [geometry["coordinates"]] if geometry["type"] == "Polygon" else geometry["coordinates"]
        assert_that(geometry["type"] == "Polygon" or len(polygons) > 1,
                    f"{path}: gauge {gauge}'s MultiPolygon of one polygon")
        area = 0.0
        for polygon in polygons:
            for k, ring in enumerate(polygon):
                points = [tuple(p) for p in ring]
                assert_that(len(points) >= 4 and points[0] == points[-1]
                            and all(-180.0 <= x <= 180.0 for x, _ in points)
                            and (twice_area(points[:-1]) > 0) == (k == 0),
                            f"{path}: gauge {gauge}'s ring {k}: closed, within -180 .. 180, outer first "
                            f"anticlockwise, holes clockwise")
                area += twice_area(points[:-1]) / 2
        ring_counts.append(sum(len(polygon) for polygon in polygons))
        moved = [[(x - 360.0 * math.floor((min(p[0] for p in cell) + 180.0) / 360.0), y) for x, y in cell]
                 for cell in cells]
        cell_area = math.fsum(twice_area(cell) / 2 for cell in moved)
        assert_close(area, cell_area, 1e-9 * cell_area, f"{path}: gauge {gauge}'s polygons' area against its cells'")
        for cell in moved:
            # A point inside the cell: the centroid of its first triangle with area from its first
            # vertex (the cells are fans about it).
            a = cell[0]
            b, c = next((b, c) for b, c in zip(cell[1:], cell[2:]) if twice_area([a, b, c]) > 0)
            x = (a[0] + b[0] + c[0]) / 3
            inside = (x - 360.0 * math.floor((x + 180.0) / 360.0), (a[1] + b[1] + c[1]) / 3)  # (-180 .. 180)
            held = sum(sum(Path(r).contains_point(inside) for r in polygon) % 2 for polygon in polygons)
            assert_that(held == 1, f"{path}: gauge {gauge}'s polygons hold {inside} {held} times")
        row = row_of[properties["station_id"]]
        for name in ("weight", "area_km2", "precip"):
            assert_close(properties[name], float(row[name]), 1e-14 * abs(float(row[name])),
                         f"{path}: gauge {gauge}'s {name}")
        assert_that(properties["name"] == row["name"], f"{path}: gauge {gauge}'s name {properties['name']!r}")
    reader = vtkGDALVectorReader()
    reader.SetFileName(path)
    reader.Update()
    output = reader.GetOutput()  # (a block per feature, a polygon's ring a polygon or a closed line)
    rings = [output.GetBlock(k).GetNumberOfCells() for k in range(output.GetNumberOfBlocks())]
    assert_that(rings == ring_counts, f"{path}: GDAL reads rings {rings} of features with {ring_counts}")


def read_polydata(path):
    """A .vtp file's vtkPolyData."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def is_png(path):
    with open(path, "rb") as f:
        return f.read(8) == b"\x89PNG\r\n\x1a\n"


def raw_reporting_counts():
    """Independently of the script: how many gauges of the stations file have a value in each
    (year, month) of the observations file."""
    known = {row["station_id"].strip() for row in read_csv(os.path.join(EXAMPLE_DATA, "colorado_stations.csv"))}
    reporting = {}
    for row in read_csv(os.path.join(EXAMPLE_DATA, "colorado_monthly_precip.csv")):
        if row["precip"].strip() and row["station_id"].strip() in known:
            reporting.setdefault((int(row["year"]), int(row["month"])), set()).add(row["station_id"].strip())
    return {month: len(ids) for month, ids in reporting.items()}


def test_the_colorado_main_job():
    with tempfile.TemporaryDirectory() as out:
        stdout, stderr = run_colorado(out, month="%04d-%02d" % MONTH, what="the main job")
        assert_that("without --catchment" not in stderr, f"the example's own gauges: no note ({stderr})")
        # The warning of gauges never weighted, given as the run ends, follows the progress's 100%
        # line (it came between the 75% and 100% lines).
        lines = stderr.splitlines()
        done = [k for k, line in enumerate(lines) if re.fullmatch(r"Thiessen areal means: +100%", line)]
        never = [k for k, line in enumerate(lines) if "so they are never weighted" in line]
        assert_that(len(done) == 1 and len(never) == 1 and never[0] == done[0] + 1,
                    f"the warning after the progress: {lines}")
        rows = read_csv(os.path.join(out, "areal_mean.csv"))
        assert_that(list(rows[0]) == ["year", "month", "stations_used", "stations_weighted", "areal_mean"],
                    f"areal_mean.csv columns: {list(rows[0])}")
        months = [(int(r["year"]), int(r["month"])) for r in rows]
        expected = [(y, m) for y in range(1895, 1998) for m in range(1, 13)]
        assert_that(months == expected, "areal_mean.csv does not hold the 1236 months 1895-01 .. 1997-12")
        counts = raw_reporting_counts()
        for r, month in zip(rows, months):
            assert_that(int(r["stations_used"]) == counts.get(month, 0),
                        f"{month}: stations_used {r['stations_used']}, the data has {counts.get(month, 0)}")
            assert_that(0 < int(r["stations_weighted"]) <= int(r["stations_used"]),
                        f"{month}: stations_weighted {r['stations_weighted']} of {r['stations_used']}")
        row = rows[months.index(MONTH)]

        tag = "%04d_%02d" % MONTH
        weights = read_csv(os.path.join(out, f"weights_{tag}.csv"))
        total = sum(float(w["weight"]) for w in weights)
        assert_close(total, 1.0, 1e-12, "the month's weights sum (15 digits each)")
        weighted = [w for w in weights if float(w["weight"]) > 0.0]
        assert_that(len(weighted) == int(row["stations_weighted"]),
                    f"{len(weighted)} gauges with a weight, areal_mean.csv says {row['stations_weighted']}")
        mean = math.fsum(float(w["weight"]) * float(w["precip"]) for w in weighted)
        assert_close(mean, float(row["areal_mean"]), 1e-12, "sum of weight x precip against areal_mean (15 digits)")

        tiles = read_polydata(os.path.join(out, f"tiles_{tag}.vtp"))
        cd = tiles.GetCellData()
        ids, weight, cell_weight = cd.GetAbstractArray("StationId"), cd.GetArray("Weight"), cd.GetArray("CellWeight")
        per_station = {}  # station: (its Weight, the sum of its cells' CellWeight)
        for c in range(tiles.GetNumberOfCells()):
            station = ids.GetValue(c)
            earlier = per_station.get(station, (weight.GetValue(c), 0.0))
            assert_that(earlier[0] == weight.GetValue(c), f"station {station}: cells with different Weight")
            per_station[station] = (earlier[0], earlier[1] + cell_weight.GetValue(c))
        for w in weighted:
            station_weight, cells = per_station.get(w["station_id"], (0.0, 0.0))
            assert_close(station_weight, float(w["weight"]), 1e-14,
                         f"station {w['station_id']}: tiles' Weight against weights_{tag}.csv")
            assert_close(cells, float(w["weight"]), 1e-12,
                         f"station {w['station_id']}: its cells' CellWeight against weights_{tag}.csv")
        # The same tiles as GeoJSON for a GIS: a feature per cell, its ring the cell's closed and
        # anticlockwise, its properties the weights file's and the cell's; GDAL reads it.
        assert_geojson_tiles(os.path.join(out, f"tiles_{tag}.geojson"), tiles, weighted)
        # Every month's weights: a month's rows are its weighted gauges, summing to 1, and their
        # weight x precip sums to the month's areal mean.
        per_month = {}
        for w in read_csv(os.path.join(out, "weights_all_months.csv")):
            per_month.setdefault((int(w["year"]), int(w["month"])), []).append(w)
        for r, month in zip(rows, months):
            listed = per_month.get(month, [])
            assert_that(len(listed) == int(r["stations_weighted"]),
                        f"{month}: {len(listed)} rows in weights_all_months.csv, {r['stations_weighted']} weighted")
            assert_close(math.fsum(float(w["weight"]) for w in listed), 1.0, 1e-12, f"{month}: weights sum")
            mean = math.fsum(float(w["weight"]) * float(w["precip"]) for w in listed)
            assert_close(mean, float(r["areal_mean"]), 1e-6, f"{month}: weight x precip against areal_mean")
        chosen = {w["station_id"]: float(w["weight"]) for w in per_month[MONTH]}
        for w in weighted:
            assert_close(chosen[w["station_id"]], float(w["weight"]), 1e-14,
                         f"station {w['station_id']}: weights_all_months.csv against weights_{tag}.csv")
        for name in (f"map_{tag}.png", "areal_mean.png"):
            assert_that(is_png(os.path.join(out, name)), f"{name} is not a PNG file")
        assert_that("1236 months" in stdout, f"summary line: {stdout}")
        # unused_inputs.csv lists every gauge with observed values that no month weighs (the
        # warning names only 20), by its stations file line; from the raw files, independently.
        stations_file = os.path.join(EXAMPLE_DATA, "colorado_stations.csv")
        line_of = {row["station_id"].strip(): k + 2 for k, row in enumerate(read_csv(stations_file))}
        observed = {row["station_id"].strip() for row in read_csv(os.path.join(EXAMPLE_DATA, "colorado_monthly_precip.csv"))
                    if row["precip"].strip() and row["station_id"].strip() in line_of}
        ever = {w["station_id"] for rows_of_month in per_month.values() for w in rows_of_month}
        unused = read_csv(os.path.join(out, "unused_inputs.csv"))
        listed = {u["station_id"] for u in unused if u["kind"] == "gauge whose tile never reaches the catchment"}
        assert_that(listed == observed - ever and len(listed) > 20,
                    f"unused_inputs.csv lists {sorted(listed)}, the data gives {sorted(observed - ever)}")
        for u in unused:
            assert_that(u["file"] == stations_file and int(u["line"]) == line_of[u["station_id"]],
                        f"unused_inputs.csv row {u}")
        assert_that(f"unused_inputs.csv ({len(unused)} input(s) not used)" in stdout, f"summary line: {stdout}")


def test_missing_values_keep_their_months():
    with tempfile.TemporaryDirectory() as out:
        observations = os.path.join(out, "obs.csv")

        def run_on(text, month):
            """Runs the example on observations `text`; returns its stdout, stderr and the rows of
            areal_mean.csv."""
            with open(observations, "w") as f:
                f.write(text)
            stdout, stderr = run_colorado(out, observations=observations, month=month, plots=False)
            return stdout, stderr, read_csv(os.path.join(out, "areal_mean.csv"))

        stdout, stderr, rows = run_on("station_id,year,month,precip\n050848,1950,1,\n050848,1950,2,NA\n"
                                      "051294,1950,2,n/a\n050848,1950,3,2.5\n051294,1950,3,null\n", "1950-03")
        assert_that("4 observation(s) without a value" in stderr, f"missing values not reported: {stderr}")
        assert_that("negative" not in stderr, f"no negative value to report: {stderr}")
        got = [(r["month"], r["stations_used"], r["areal_mean"]) for r in rows]
        assert_that(got == [("1", "0", ""), ("2", "0", ""), ("3", "1", "2.5")],
                    f"months with missing values: {got}")
        # Months without any row between the first and the last (1950-12 to 1951-02 here) are
        # months where no gauge reported: they keep their rows.
        stdout, stderr, rows = run_on("station_id,year,month,precip\n050848,1950,11,1.5\n050848,1951,3,2.5\n",
                                      "1951-01")
        assert_that("3 month(s) between 1950-11 (line 2) and 1951-03 (line 3) have no row of a gauge's station" in stderr,
                    f"gaps not reported: {stderr}")
        got = [(r["year"], r["month"], r["stations_used"], r["areal_mean"]) for r in rows]
        assert_that(got == [("1950", "11", "1", "1.5"), ("1950", "12", "0", ""), ("1951", "1", "0", ""),
                            ("1951", "2", "0", ""), ("1951", "3", "1", "2.5")], f"every month listed: {got}")
        assert_that("1951-01: no gauge reported, so no areal mean" in stdout, f"the chosen empty month: {stdout}")
        # A month whose only row names a station that is not in the stations file (the filter
        # makes no step of it) is a month where no gauge reported, and the first row's station
        # may be such a one.
        stdout, stderr, rows = run_on("station_id,year,month,precip\nNOSUCH,1950,1,1.0\n050848,1950,2,2.5\n",
                                      "1950-02")
        got = [(r["year"], r["month"], r["stations_used"], r["areal_mean"]) for r in rows]
        assert_that(got == [("1950", "1", "0", ""), ("1950", "2", "1", "2.5")],
                    f"a month of an unknown station only: {got}")
        # The filter's row 0 is named as the file's line 2.
        assert_that("NOSUCH (1 row: line 2)" in stderr, f"the unknown station not reported: {stderr}")
        # A negative value (a missing-value code such as -9999, most often) is used as given and
        # named by its line.
        stdout, stderr, rows = run_on("station_id,year,month,precip\n050848,1950,1,-9999\n050848,1950,2,2.5\n"
                                      "051294,1950,2,-0.5\n", "1950-02")
        assert_that("obs.csv: 2 observation(s) have a negative precipitation, used as given" in stderr
                    and "line(s) 2, 4" in stderr, f"negative values not named: {stderr}")
        # -9999 is also named as a common missing-value code, by its line, with the script's option.
        assert_that("obs.csv: 1 observation value(s) are exactly -9999, a common missing-value code, and "
                    "averaged as measured values (the first in line 2, station 050848): if -9999 marks "
                    "missing values, give --missing-value -9999" in stderr, f"the code not named: {stderr}")
        got = [(r["month"], r["stations_used"], float(r["areal_mean"])) for r in rows]
        assert_that(got[0] == ("1", "1", -9999.0) and got[1][1] == "2" and got[1][2] < 2.5,
                    f"negative values used as given: {got}")
        # --missing-value -9999 makes that code a missing value (the other negative stays a value).
        stdout, stderr = run_colorado(out, "--missing-value", "-9999", observations=observations, month="1950-02",
                                      plots=False)
        rows = read_csv(os.path.join(out, "areal_mean.csv"))
        got = [(r["month"], r["stations_used"], r["areal_mean"]) for r in rows]
        assert_that(got[0] == ("1", "0", "") and got[1][1] == "2",
                    f"-9999 as a missing value: {got}")
        assert_that("1 observation(s) with a --missing-value value (-9999) count as missing" in stderr
                    and "1 observation(s) have a negative precipitation" in stderr and "line(s) 4" in stderr,
                    f"the missing-value code and the other negative value: {stderr}")


def test_bad_files_are_named():
    with tempfile.TemporaryDirectory() as out:
        stations_id = write(out, "id.csv", "gauge,lon,lat\n1,-105,39\n")
        stations_lat = write(out, "lat.csv", "station_id,lon,lat\nA,-105,39\nB,-104,north\n")
        month = write(out, "month.csv", "station_id,year,month,precip\n050848,1950,1,1\n050848,1950,13,1\n")
        value = write(out, "value.csv", "station_id,year,month,precip\n050848,1950,1,1\n050848,1950,2,1,5\n")
        value2 = write(out, "value2.csv", "station_id,year,month,precip\n050848,1950,1,1\n050848,1950,2,x\n")
        empty_id = write(out, "empty_id.csv", "station_id,year,month,precip\n ,1950,1,1\n")
        not_polygon = write(out, "catchment.geojson", "{}\n")
        header_only = write(out, "header.csv", "station_id,year,month,precip\n")
        empty_file = write(out, "empty.csv", "")
        infinite = write(out, "inf.csv", "station_id,year,month,precip\n050848,1950,1,1\n050848,1950,2,1e999\n")
        quote = write(out, "quote.csv", 'station_id,year,month,precip\n050848,1950,1,1\n050848,1950,2,"1.2\n')
        bad_header = write(out, "bad_header.csv", 'station_id,"lon"x,lat\n050848,-105,39\n')
        geojson = write(out, "stations.geojson", '{"type": "FeatureCollection", "features": []}\n')
        pretty_json = write(out, "pretty.json", '{\n  "station_id": "050848"\n}\n')
        twice = write(out, "twice.csv", "station_id,year,month,precip,Precip\n050848,1950,1,1,100\n")
        grouped = write(out, "grouped.csv", "station_id,year,month,precip\n050848,1950,1,1_5\n")
        quoted_comma = write(out, "quoted_comma.csv", 'station_id,year,month,precip\n050848,1963,8,"1,5"\n')  # LibreOffice, German
        directory = os.path.join(out, "catchment.d")
        os.mkdir(directory)
        utf16 = os.path.join(out, "utf16.csv")
        with open(utf16, "w", encoding="utf-16") as f:
            f.write("station_id,year,month,precip\n050848,1963,8,1.5\n")
        latin = os.path.join(out, "latin.csv")
        with open(latin, "w", encoding="cp1252") as f:
            f.write("station_id,name,lon,lat\n050848,Café,-105,39.5\n")
        missing = os.path.join(out, "absent.csv")
        import gzip

        gzipped = os.path.join(out, "obs.csv.gz")
        with open(gzipped, "wb") as f:  # (cut short: a download that stopped)
            f.write(gzip.compress(b"station_id,year,month,precip\n050848,1963,8,1.5\n")[:25])
        lone_shp = write(out, "basin.shp", "not read: its .shx is missing\n")
        import zipfile

        workbook = os.path.join(out, "obs.xlsx")
        with zipfile.ZipFile(workbook, "w") as book:
            book.writestr("xl/workbook.xml", "<workbook/>")
        bzh = write(out, "bzh.csv", "BZh_id,lon,lat\n1,-105,39\n")  # text that starts like bzip2
        cases = [
            (("--observations", gzipped), [gzipped, "gzip-compressed but cannot be decompressed"]),
            (("--observations", workbook), [workbook, "a zip archive, not CSV text", "save the sheet as CSV"]),
            (("--stations", bzh), [bzh, "no column 'station_id'"]),
            (("--catchment", lone_shp), [lone_shp, "basin.shx beside it is missing"]),
            (("--stations", stations_id), [stations_id, "no column 'station_id'", "gauge, lon, lat"]),
            (("--stations", stations_lat), [stations_lat + ":3", "'lat'", "'north' is not a number"]),
            (("--stations", missing), [missing, "cannot read the stations file"]),
            (("--observations", month), [month + ":3", "'month'", "13 is outside 1..12"]),
            (("--observations", value2), [value2 + ":3", "'precip'", "'x' is not a number"]),
            (("--observations", empty_id), [empty_id + ":2", "'station_id' is empty"]),
            (("--catchment", not_polygon), [not_polygon, "no polygon"]),
            (("--catchment", missing), [missing, "no such catchment file"]),
            (("--month", "1963-13"), ["--month '1963-13': the month must be 01 to 12"]),
            (("--month", "1963/08"), ["--month '1963/08': expected YYYY-MM"]),
            (("--observations", header_only), ["the observations table has no rows"]),
            # An empty file is said to be one (it was read as a wide file without a time column).
            # (and says what it needs: it ended "it needs the columns " with none named)
            (("--observations", empty_file), [empty_file + ": the observations file is empty (no header, no rows); "
                                              "expected a long file (station_id, a time column"]),
            (("--stations", empty_file), [empty_file + ": the stations file is empty"]),
            (("--observations", infinite), [infinite + ":3", "'precip'", "'1e999' is not a finite number"]),
            # The line the malformed record ends on (the unclosed quote runs to the end of line 3).
            (("--observations", quote), [quote + ":3: not well-formed CSV"]),
            # A bad header is on line 1, not "line 0"; a GeoJSON file of no feature, or a JSON file
            # that is no GeoJSON, holds no gauge.
            (("--stations", bad_header), [bad_header + ":1: not well-formed CSV"]),
            (("--stations", geojson), [geojson + ": GDAL read no feature from the stations file (expected a GeoJSON "
                                       "or shapefile of points, or a CSV file with a header such as "
                                       "station_id,lon,lat)"]),
            (("--stations", pretty_json), [pretty_json + ": GDAL read no feature from the stations file"]),
            (("--catchment", directory), [directory + ": is a directory"]),
            (("--out", stations_id), [f"--out {stations_id}: exists and is not a directory"]),
            # A column twice (in any case): which holds the values would be a guess.
            (("--observations", twice), [twice + ":1", "column 'precip' appears 2 times (columns 4, 5)"]),
            # Python's float() reads 1_5 as 15: not a number in a data file.
            (("--observations", grouped), [grouped + ":2", "'precip'", "'1_5' is not a number"]),
            # A decimal comma in a file of commas (quoted, as a spreadsheet in a German locale saves
            # one with commas as separators) is not read, and the message says why.
            (("--observations", quoted_comma), [quoted_comma + ":2", "'1,5' is not a number: a comma in a number is "
                                                "read, as a decimal comma, only in a file whose fields are separated "
                                                "by semicolons"]),
            (("--month", "1_963-08"), ["--month", "YYYY-MM"]),
            # As the filter refuses them: 0 made every dry month missing; NaN and inf match nothing.
            (("--missing-value", "0"), ["--missing-value 0 would make every zero value (a dry step) missing"]),
            (("--missing-value", "-9999", "--missing-value", "nan"), ["--missing-value nan changes nothing"]),
            (("--missing-value", "inf"), ["--missing-value inf changes nothing"]),
        ]
        for arguments, fragments in cases:
            _, stderr = run_colorado(out, *arguments, what=str(arguments), status=1, plots=False)
            assert_that("Traceback" not in stderr, f"{arguments}: a traceback instead of a message: {stderr}")
            assert_that(":0:" not in stderr, f"{arguments}: a line 0: {stderr}")
            for fragment in fragments:
                assert_that(fragment in stderr, f"{arguments}: {fragment!r} not in {stderr!r}")
        # Text a spreadsheet saves: Windows-1252 stations, UTF-16 observations with its mark.
        run_colorado(out, stations=latin, observations=utf16, month="1963-08", plots=False,
                     what="cp1252 and UTF-16 files")
        weights = read_csv(os.path.join(out, "weights_1963_08.csv"))
        assert_that([(w["name"], float(w["weight"]), float(w["precip"])) for w in weights] == [("Café", 1.0, 1.5)],
                    f"cp1252 and UTF-16 files read as {weights}")
        # Column names in another case, and whole numbers as pandas writes a column with gaps.
        upper = write(out, "upper.csv", "STATION_ID,Lon,LAT\n050848,-105,39.5\n")
        floats = write(out, "floats.csv", "Station_Id,YEAR,Month,PRECIP\n050848,1963.0,8.0,2.5\n"
                                          "050848,1963,9,#N/A\n")
        run_colorado(out, stations=upper, observations=floats, month="1963-08", plots=False,
                     what="column names in capitals, years as 1963.0")
        weights = read_csv(os.path.join(out, "weights_1963_08.csv"))
        assert_that([(w["station_id"], float(w["weight"]), float(w["precip"])) for w in weights]
                    == [("050848", 1.0, 2.5)], f"capitals and 1963.0 read as {weights}")
        short = write(out, "short.csv", "station_id,year,month,precip\n050848,1950,1,1\n050848,1950,2\n")
        for path, fields in ((value, 5), (short, 3)):
            _, stderr = run_colorado(out, observations=path, what=path, status=1, plots=False)
            expected = f"{path}:3: {fields} field(s) where the header has 4"
            assert_that(expected in stderr, f"{path}: {stderr!r}")

# A synthetic basin in New Zealand (lon 175.5-176.5, southern hemisphere) with a lake: a two-ring
# outline (a concave outer ring and a hole), five gauges around and in it, one far away.
LAKE_BASIN = {"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, "geometry": {
    "type": "Polygon", "coordinates": [
        [[175.5, -39.2], [176.5, -39.2], [176.5, -38.4], [176.0, -38.6], [175.5, -38.4], [175.5, -39.2]],
        [[175.8, -38.95], [175.8, -38.7], [176.1, -38.7], [176.1, -38.95], [175.8, -38.95]]]}}]}
LAKE_GAUGES = {"N1": (175.6, -39.1), "N2": (176.4, -39.1), "N3": (175.95, -38.82), "N4": (175.7, -38.5),
               "N5": (176.3, -38.55), "N6": (177.5, -37.0)}


def lake_rings_cut():
    """The lake basin's rings (LAKE_BASIN's, first point repeated last) with each edge cut into
    1000 straight pieces in lon/lat (every 0.001 degrees or less): the outline that a projected
    file's edges, cut every kilometre and made lon/lat, follow to within rounding."""
    return [[[a[0] + (b[0] - a[0]) * i / 1000, a[1] + (b[1] - a[1]) * i / 1000] for a, b in zip(ring, ring[1:])
             for i in range(1000)] + ring[-1:] for ring in LAKE_BASIN["features"][0]["geometry"]["coordinates"]]


def write_lake_basin_cut(directory):
    """lake_rings_cut's basin as cut.geojson in directory; returns its path."""
    cut = json.loads(json.dumps(LAKE_BASIN))
    cut["features"][0]["geometry"]["coordinates"] = lake_rings_cut()
    return write(directory, "cut.geojson", json.dumps(cut))


def write_lake_basin(directory):
    """The basin's catchment, stations and observations files; returns their paths."""
    paths = [os.path.join(directory, name) for name in ("basin.geojson", "stations.csv", "obs.csv")]
    with open(paths[0], "w") as f:
        json.dump(LAKE_BASIN, f)
    write_stations(paths[1], LAKE_GAUGES)
    with open(paths[2], "w") as f:
        f.write("station_id,year,month,precip\n" + "".join(f"{s},2001,1,{10 * k}\n" for k, s in enumerate(LAKE_GAUGES, 1)
                                                          if s != "N6") + "N1,2001,2,5\nN6,2001,2,7\n")
    return paths


def import_example(name="colorado_areal_precipitation"):
    """The module of examples/<name>.py, imported as the examples import csv_input."""
    import importlib

    sys.path.insert(0, EXAMPLES)
    return importlib.import_module(name)


def test_the_map_of_another_place_with_a_lake():
    example = import_example()
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        run_colorado(out, stations=stations, observations=observations, catchment=catchment, month="2001-01",
                     what="the lake basin")
        assert_that(is_png(os.path.join(out, "map_2001_01.png")), "map_2001_01.png is not a PNG file")
        weights = read_csv(os.path.join(out, "weights_2001_01.csv"))
        assert_close(sum(float(w["weight"]) for w in weights), 1.0, 1e-12, "the lake basin's weights sum")
        # The tiles file: no cell over the lake, cells' weights summing to 1.
        from matplotlib.path import Path

        tiles = read_polydata(os.path.join(out, "tiles_2001_01.vtp"))
        cells = cell_rings(tiles)
        assert_that(not any(Path(cell).contains_point((175.95, -38.82)) for cell in cells), "a cell covers the lake")
        cell_weight = tiles.GetCellData().GetArray("CellWeight")
        assert_close(math.fsum(cell_weight.GetValue(c) for c in range(tiles.GetNumberOfCells())), 1.0, 1e-12,
                     "the lake basin's cells' CellWeight")
        # Its GeoJSON: a feature per gauge, the tile round the lake (several cells in the .vtp) one
        # polygon with the lake as its hole.
        geojson = os.path.join(out, "tiles_2001_01.geojson")
        assert_geojson_tiles(geojson, tiles, weights)
        stations = [tiles.GetCellData().GetAbstractArray("StationId").GetValue(c) for c in range(len(cells))]
        assert_that(len(cells) > len(set(stations)) == len(weights), f"the lake basin's pieces: {stations}")
        with open(geojson) as f:
            shapes = [(feature["geometry"]["type"], len(feature["geometry"]["coordinates"]))
                      for feature in json.load(f)["features"]]
        assert_that(("Polygon", 2) in shapes, f"no polygon with a hole among {shapes}")
        # The outline, ring by ring: GDAL's reading of the file gives back the file's two rings.
        _, rings = example.read_catchment(catchment)
        expected = [[tuple(p) for p in ring[:-1]] for ring in LAKE_BASIN["features"][0]["geometry"]["coordinates"]]
        assert_that(rings == expected, f"rings {rings}, the file has {expected}")
    # The map's extent holds the catchment and the weighted gauges with an even margin, here as
    # for Colorado (no place is built in).
    weighted = [LAKE_GAUGES[w["station_id"]] for w in weights]
    colorado = [colorado_outline()]
    for outline, points in ((rings, weighted), (colorado, [(-109.4, 37.1), (-101.1, 40.0)])):
        lon_min, lon_max, lat_min, lat_max = example.map_extent(outline, points)
        xs = [p[0] for ring in outline for p in ring] + [p[0] for p in points]
        ys = [p[1] for ring in outline for p in ring] + [p[1] for p in points]
        margins = [min(xs) - lon_min, lon_max - max(xs), min(ys) - lat_min, lat_max - max(ys)]
        span = max(max(xs) - min(xs), max(ys) - min(ys))
        assert_that(all(abs(m - margins[0]) <= 1e-9 * span for m in margins) and 0 < margins[0] <= 0.1 * span,
                    f"extent {lon_min, lon_max, lat_min, lat_max} of {min(xs), max(xs), min(ys), max(ys)}")


def test_a_lake_touching_the_outline_and_catchments_of_several_features():
    """A lake touching the outline at a vertex (valid in OGC's simple features) is a hole: the run
    succeeds, with less area than without it. A file of several polygon features is taken whole,
    with a line that says so; two adjacent features (sub-catchments) make the whole basin."""
    outline = LAKE_BASIN["features"][0]["geometry"]["coordinates"][0]
    lake = [[176.0, -38.6], [175.8, -38.8], [176.2, -38.8], [176.0, -38.6]]
    far = [[170.0, -45.0], [171.0, -45.0], [171.0, -44.0], [170.0, -44.0], [170.0, -45.0]]

    def feature(rings):
        return {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": rings}}

    def total_area(out):
        return math.fsum(float(w["area_km2"]) for w in read_csv(os.path.join(out, "weights_2001_01.csv")))

    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        areas = []
        for name, features in (("touching.geojson", [feature([outline, lake])]), ("whole.geojson", [feature([outline])])):
            with open(os.path.join(out, name), "w") as f:
                json.dump({"type": "FeatureCollection", "features": features}, f)
            run_colorado(out, stations=stations, observations=observations, catchment=os.path.join(out, name),
                         month="2001-01", plots=False, what=name)
            weights = read_csv(os.path.join(out, "weights_2001_01.csv"))
            assert_close(sum(float(w["weight"]) for w in weights), 1.0, 1e-12, f"{name}: weights sum")
            areas.append(total_area(out))
        # The lake: a triangle 0.4 degrees wide and 0.2 high, near 38.7 S (about 35 x 22 km).
        assert_that(0.8 * 0.5 * 34.8 * 22.2 < areas[1] - areas[0] < 1.2 * 0.5 * 34.8 * 22.2,
                    f"the lake takes its area: {areas}")
        two = os.path.join(out, "two.geojson")
        with open(two, "w") as f:
            json.dump({"type": "FeatureCollection", "features": [feature([outline]), feature([far])]}, f)
        _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=two,
                                 month="2001-01", plots=False, what="two features")
        assert_that(f"{two}: the catchment is the 2 polygon features of the file taken together" in stderr, stderr)
        # --feature takes the basin alone (its area as without the far feature), or names what there is.
        named = os.path.join(out, "named.geojson")
        basin, distant = feature([outline]), feature([far])
        basin["properties"], distant["properties"] = {"HUC8": 14010001}, {"HUC8": 14010002}
        with open(named, "w") as f:
            json.dump({"type": "FeatureCollection", "features": [basin, distant]}, f)
        _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=named,
                                 feature="HUC8=14010001", month="2001-01", plots=False, what="--feature")
        assert_that("polygon features" not in stderr, stderr)
        assert_close(total_area(out), areas[1], 1e-9 * areas[1], "--feature: the basin alone")
        for choice, expected in (("HUC8=1", "no feature has HUC8 = '1' (its values: 14010001, 14010002)"),
                                 ("HUC=14010001", "no feature has the attribute 'HUC' (its attributes: HUC8)"),
                                 ("HUC8", "--feature 'HUC8': expected ATTRIBUTE=VALUE")):
            _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=named,
                                     feature=choice, plots=False, status=1, what=f"--feature {choice}")
            assert_that(expected in stderr, f"--feature {choice}: {stderr}")
        adjacent = os.path.join(out, "adjacent.geojson")
        west = [[175.5, -39.2], [176.0, -39.2], [176.0, -38.6], [175.5, -38.4], [175.5, -39.2]]
        east = [[176.0, -39.2], [176.5, -39.2], [176.5, -38.4], [176.0, -38.6], [176.0, -39.2]]
        with open(adjacent, "w") as f:
            json.dump({"type": "FeatureCollection", "features": [feature([west]), feature([east])]}, f)
        run_colorado(out, stations=stations, observations=observations, catchment=adjacent,
                     month="2001-01", plots=False, what="adjacent features")
        assert_close(total_area(out), areas[1], 1e-9 * areas[1], "the two halves make the whole basin")


def test_each_group_of_features_gets_its_means():
    # --each ATTRIBUTE: sub-basins averaged one by one, in the whole basin's projection. The same
    # tiles serve each, so the whole basin's mean is the sub-basins' means weighted by their areas,
    # at every month; each sub-basin's rows are those of a run with --feature for it alone (which
    # fits a projection to it alone).
    west = [[175.5, -39.2], [176.0, -39.2], [176.0, -38.6], [175.5, -38.4], [175.5, -39.2]]
    east = [[176.0, -39.2], [176.5, -39.2], [176.5, -38.4], [176.0, -38.6], [176.0, -39.2]]
    north = [[176.0, -38.6], [176.5, -38.4], [176.5, -38.3], [175.5, -38.3], [175.5, -38.4], [176.0, -38.6]]
    with tempfile.TemporaryDirectory() as out:
        _, stations, observations = write_lake_basin(out)
        with open(observations, "a") as f:
            f.write("N2,2001,3,4\nN3,2001,3,6\nN5,2001,3,1\n")
        basins = os.path.join(out, "basins.geojson")
        features = [{"type": "Feature", "properties": {"HUC8": code}, "geometry": {"type": "Polygon", "coordinates": [r]}}
                    for code, r in ((14010002, east), (14010001, west), (9, north),
                                    (14010002, [[176.6, -39.2], [176.8, -39.2], [176.8, -39.0], [176.6, -39.2]]))]
        with open(basins, "w") as f:
            json.dump({"type": "FeatureCollection", "features": features}, f)
        whole = os.path.join(out, "whole")
        stdout, stderr = run_colorado(whole, stations=stations, observations=observations, catchment=basins,
                                      month="2001-01", plots=False, each="HUC8", what="--each HUC8")
        assert_that("areal_mean_by_HUC8.csv (3 group(s) of features)" in stdout, f"stdout: {stdout}")
        assert_that("areal means by HUC8: 3 of 3" in stderr, f"progress: {stderr}")
        rows = read_csv(os.path.join(whole, "areal_mean_by_HUC8.csv"))
        assert_that(list(rows[0]) == ["HUC8", "year", "month", "stations_used", "stations_weighted", "areal_mean",
                                      "area_km2"], f"columns: {list(rows[0])}")
        assert_that([r["HUC8"] for r in rows] == ["9"] * 3 + ["14010001"] * 3 + ["14010002"] * 3,
                    f"groups in numeric order: {[r['HUC8'] for r in rows]}")
        means = read_csv(os.path.join(whole, "areal_mean.csv"))
        for month in ("1", "2", "3"):
            parts = [r for r in rows if r["month"] == month]
            area = math.fsum(float(r["area_km2"]) for r in parts)
            mean = math.fsum(float(r["area_km2"]) * float(r["areal_mean"]) for r in parts) / area
            row = next(r for r in means if r["month"] == month)
            assert_close(mean, float(row["areal_mean"]), 1e-9 * abs(mean), f"2001-{month}: the area-weighted sub-basin means")
            assert_that(all(r["stations_used"] == row["stations_used"] for r in parts), f"2001-{month}: {parts}")
        for code in ("9", "14010001", "14010002"):
            alone = os.path.join(out, code)
            run_colorado(alone, stations=stations, observations=observations, catchment=basins, month="2001-01",
                         plots=False, feature=f"HUC8={code}", what=f"--feature HUC8={code}")
            # (Alone, the sub-basin gets a projection fitted to it, which moves its tiles' sides by
            # a little: the means agree to some 1e-5, not to the last bit.)
            expected = read_csv(os.path.join(alone, "areal_mean.csv"))
            got = [r for r in rows if r["HUC8"] == code]
            assert_that([(r["year"], r["month"], r["stations_used"], r["stations_weighted"]) for r in got]
                        == [(r["year"], r["month"], r["stations_used"], r["stations_weighted"]) for r in expected],
                        f"HUC8 {code}: {got} against --feature {expected}")
            for a, b in zip(got, expected):
                assert_close(float(a["areal_mean"]), float(b["areal_mean"]), 1e-4 * float(b["areal_mean"]),
                             f"HUC8 {code}, 2001-{a['month']}: against --feature")
        assert_that("do not make the catchment" not in stderr, f"the groups make the basin: {stderr}")
        # A feature inside a feature of another group is a hole of the catchment (even-odd) but a
        # part of its group: said. A group of lines only is named, without means, and the run goes on.
        nested = os.path.join(out, "nested.geojson")
        inner = [[175.7, -39.0], [175.9, -39.0], [175.9, -38.8], [175.7, -38.8], [175.7, -39.0]]
        road = {"type": "Feature", "properties": {"HUC8": 5},
                "geometry": {"type": "LineString", "coordinates": [[175.6, -39.1], [176.4, -38.5]]}}
        with open(nested, "w") as f:
            json.dump({"type": "FeatureCollection", "features": features[:3] + [
                {"type": "Feature", "properties": {"HUC8": 7}, "geometry": {"type": "Polygon", "coordinates": [inner]}},
                road]}, f)
        stdout, stderr = run_colorado(os.path.join(out, "nested"), stations=stations, observations=observations,
                                      catchment=nested, month="2001-01", plots=False, each=" HUC8 ", what="nested")
        assert_that(f"{nested}: the features with HUC8 = 5 have no polygon: no means for them" in stderr
                    and f"{nested}: the groups of HUC8 do not make the catchment: their areas sum to" in stderr,
                    f"a nested group and a group of lines: {stderr}")
        nested_rows = read_csv(os.path.join(out, "nested", "areal_mean_by_HUC8.csv"))
        assert_that(sorted({r["HUC8"] for r in nested_rows}) == ["14010001", "14010002", "7", "9"],
                    f"the groups with polygons: {nested_rows}")
        example = import_example()
        from vtkmodules.vtkCommonCore import vtkDoubleArray

        values = vtkDoubleArray()
        for v in (math.nan, math.inf, 2.5, 14010001.0):
            values.InsertNextValue(v)
        assert_that([example.attribute_text(values, c) for c in range(4)] == ["nan", "inf", "2.5", "14010001"],
                    "attribute values as text")
        for options, fragment in (({"each": "HUC"}, "no feature has the attribute 'HUC' (its attributes: HUC8)"),
                                  ({"each": " "}, "--each: expected the name of an attribute"),
                                  ({"each": "HUC8", "feature": "HUC8=9"}, "--each HUC8 and --feature HUC8=9: give one")):
            _, stderr = run_colorado(os.path.join(out, "bad"), stations=stations, observations=observations,
                                     catchment=basins, plots=False, status=1, what=str(options), **options)
            assert_that(fragment in stderr, f"{options}: {stderr}")


def test_a_month_without_reports_still_gets_its_map():
    # The lake basin with 2001-02 taken out of the observations: the month is in the record (a
    # month where no gauge reported) and, chosen for the map, gives a map of the outline and the
    # gauges, a weights file of its header only and an areal mean nan.
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        with open(observations, "w") as f:
            f.write("station_id,year,month,precip\nN1,2001,1,10\nN2,2001,1,20\nN1,2001,3,5\nN6,2001,3,7\n")
        stdout, stderr = run_colorado(out, stations=stations, observations=observations, catchment=catchment,
                                      month="2001-02", what="a month without reports")
        assert_that("Traceback" not in stderr, f"a traceback: {stderr}")
        # The rows read from the file: not the row the script adds for 2001-02.
        assert_that("read 6 gauges and 4 observations in" in stderr, f"the rows read: {stderr}")
        assert_that(is_png(os.path.join(out, "map_2001_02.png")), "map_2001_02.png is not a PNG file")
        assert_that(os.path.isfile(os.path.join(out, "tiles_2001_02.vtp")), "no tiles_2001_02.vtp")
        with open(os.path.join(out, "weights_2001_02.csv")) as f:
            lines = f.read().splitlines()
        assert_that(lines == ["station_id,name,lon,lat,weight,area_km2,precip"], f"weights_2001_02.csv: {lines}")
        got = [(r["month"], r["stations_used"], r["areal_mean"]) for r in read_csv(os.path.join(out, "areal_mean.csv"))]
        assert_that(got == [("1", "2", got[0][2]), ("2", "0", ""), ("3", "2", got[2][2])] and got[0][2] and got[2][2],
                    f"areal_mean.csv: {got}")
        assert_that("2001-02: no gauge reported, so no areal mean; its weights and tiles files are empty" in stdout,
                    f"the empty month: {stdout}")


def test_the_time_series_breaks_at_months_without_a_mean():
    # areal_mean.png's line stops at a month where no gauge reported (an empty areal_mean) and
    # starts again after it, rather than joining the months either side: such a month is NaN in
    # the plotted series, and so is a month without a row at all (2002-02 here).
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    example = import_example()
    rows = [(2001, 11, 2, 2, 1.5), (2001, 12, 0, 0, math.nan), (2002, 1, 1, 1, 2.0), (2002, 3, 1, 1, 3.0),
            (2002, 4, 2, 1, 4.0)]
    times, means, used = example.step_series(rows)
    expected = [example.decimal_time(y, m) for y, m in ((2001, 11), (2001, 12), (2002, 1), (2002, 2), (2002, 3),
                                                         (2002, 4))]
    assert_that(times == expected, f"times {times}, expected {expected}")
    shown = ["nan" if math.isnan(v) else v for v in means]
    assert_that(shown == [1.5, "nan", 2.0, "nan", 3.0, 4.0], f"means {shown}")
    assert_that(used == [2, 0, 1, 0, 1, 2], f"gauges reporting {used}")
    # The figure as plot_series draws it (kept from its plt.close(fig); matplotlib.use may call
    # plt.close("all"), passed on): the line is that series, and the lone months 2001-11 and
    # 2002-01 (no line segment: a gap after, or on either side) are drawn as dots.
    figures, close = [], plt.close
    plt.close = lambda fig=None: figures.append(fig) if isinstance(fig, plt.Figure) else close(fig)
    try:
        with tempfile.TemporaryDirectory() as out:
            path = os.path.join(out, "areal_mean.png")
            example.plot_series(rows, path)
            assert_that(is_png(path), "areal_mean.png is not a PNG file")
    finally:
        plt.close = close
    # (months of a record this short are drawn at their dates, first of the month)
    import datetime

    dates = [datetime.date(y, m, 1) for y, m in ((2001, 11), (2001, 12), (2002, 1), (2002, 2), (2002, 3), (2002, 4))]
    line, dots = figures[0].axes[0].get_lines()
    drawn = ["nan" if math.isnan(v) else v for v in line.get_ydata()]
    assert_that(list(line.get_xdata()) == dates and drawn == shown, f"the line: {list(line.get_xdata())}, {drawn}")
    assert_that(list(dots.get_xdata()) == [dates[0], dates[2]] and list(dots.get_ydata()) == [1.5, 2.0],
                f"the lone months: {list(dots.get_xdata())}, {list(dots.get_ydata())}")
    close(figures[0])


def test_ids_without_their_leading_zeros_match_as_in_the_filter():
    # Integer ids whose leading zeros a spreadsheet dropped from the observations ("0101" as 101,
    # "000" as 0) are the same stations, as in vtkThiessenArealAverage: every output is that of
    # the file with the zeros. 2001-02 has rows of integer ids only, 2001-03 none at all.
    gauges = {"0101": (175.6, -39.1), "0102": (176.4, -39.1), "000": (175.95, -38.82), "0104": (175.7, -38.5),
              "N5": (176.3, -38.55), "007": (177.5, -37.0)}
    rows = [("0101", 1, "10"), ("0102", 1, "20"), ("000", 1, "30"), ("0104", 1, "40"), ("N5", 1, "50"),
            ("0101", 2, "5"), ("000", 2, "3"), ("007", 2, "7"), ("N5", 4, "8"), ("0102", 4, "NA")]
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        write_stations(stations, gauges)
        outputs = {}
        # floats: the integer ids as pandas writes a whole-number column with gaps (101.0).
        for name, written in (("zeros", "{}"), ("nozeros", "{:d}"), ("floats", "{:.1f}")):
            observations = os.path.join(directory, f"{name}.csv")
            with open(observations, "w") as f:
                f.write("station_id,year,month,precip\n" + "".join(
                    f"{written.format(int(s) if written != '{}' else s) if s.isdigit() else s},2001,{m},{v}\n"
                    for s, m, v in rows))
            out = os.path.join(directory, name)
            stdout, stderr = run_colorado(out, stations=stations, observations=observations, catchment=catchment,
                                          month="2001-02", what=name)
            files = {}
            for file in ("areal_mean.csv", "weights_all_months.csv", "weights_2001_02.csv", "map_2001_02.png"):
                with open(os.path.join(out, file), "rb") as f:
                    files[file] = f.read()
            gaps = [line.replace(observations, "OBS") for line in stderr.splitlines() if "have no row of" in line]
            outputs[name] = (files, stdout.replace(out, "OUT"), gaps, stderr)
        zeros, nozeros = outputs["zeros"], outputs["nozeros"]
        for file in zeros[0]:
            assert_that(zeros[0][file] == outputs["floats"][0][file], f"{file} differs with ids written 101.0")
        assert_that(zeros[1:3] == outputs["floats"][1:3],
                    f"the messages differ with ids written 101.0: {outputs['floats'][1:3]}")
        assert_that(len(read_csv(os.path.join(directory, "zeros", "areal_mean.csv"))) == 4, "4 months expected")
        for file in zeros[0]:
            # The map too: the gauges drawn as reporting are the same.
            assert_that(zeros[0][file] == nozeros[0][file], f"{file} differs without the leading zeros")
        assert_that(zeros[1] == nozeros[1], f"stdout differs: {zeros[1]!r} against {nozeros[1]!r}")
        assert_that(zeros[2] == nozeros[2] == ["OBS: 1 month(s) between 2001-01 (line 2) and 2001-04 (line 10) have "
                                               "no row of a gauge's station (2001-03); they are months where no gauge "
                                               "reported"],
                    f"the months without a gauge's row: {zeros[2]} against {nozeros[2]}")
        assert_that("repeat a station and time" not in nozeros[3], f"rows flagged as repeated: {nozeros[3]}")


def test_files_of_semicolons_or_tabs_with_decimal_commas():
    # A spreadsheet set to a European locale saves CSV with semicolons and decimal commas (some
    # tools use tabs): the same gauges and values so written give the comma file's outputs byte
    # for byte, names with a comma inside included; in such a file a value with both a decimal
    # comma and a point (digit grouping) is named, and whole years may be written 2001,0.
    rows = [("N1", "2001", 1, "10.25"), ("N2", "2001.0", 1, "20.5"), ("N3", "2001", 1, "30"),
            ("N4", "2001", 1, "0.125"), ("N5", "2001", 1, "-1.5e-3"), ("N1", "2001", 2, "5.75"),
            ("N3", "2001", 2, "NA"), ("N6", "2001", 2, "7.5")]
    names = {"N1": "Lake, north shore", "N2": "Hill", "N3": "Island", "N4": "Ridge", "N5": "Bay", "N6": "Far"}
    with tempfile.TemporaryDirectory() as directory:
        catchment, _, _ = write_lake_basin(directory)
        outputs = {}
        for kind, mark, decimal in (("commas", ",", "."), ("semicolons", ";", ","), ("tabs", "\t", ",")):
            def line(fields):
                return mark.join(f'"{f}"' if mark in f else f for f in fields) + "\n"

            def number(text):
                return text.replace(".", decimal)

            stations = write(directory, f"{kind}_stations.csv", line(("station_id", "name", "lon", "lat")) + "".join(
                line((s, names[s], number(str(lon)), number(str(lat)))) for s, (lon, lat) in LAKE_GAUGES.items()))
            observations = write(directory, f"{kind}_obs.csv", line(("station_id", "year", "month", "precip")) + "".join(
                line((s, number(y), str(m), number(v))) for s, y, m, v in rows))
            out = os.path.join(directory, kind)
            stdout, stderr = run_colorado(out, stations=stations, observations=observations, catchment=catchment,
                                          month="2001-01", what=kind)
            files = {}
            for file in ("areal_mean.csv", "weights_all_months.csv", "weights_2001_01.csv", "map_2001_01.png",
                         "areal_mean.png"):
                with open(os.path.join(out, file), "rb") as f:
                    files[file] = f.read()
            messages = without_timings(stderr.replace(directory, "DIR").replace(kind, "KIND"))
            outputs[kind] = (files, stdout.replace(out, "OUT"), messages)
        means = read_csv(os.path.join(directory, "commas", "areal_mean.csv"))
        assert_that([r["stations_used"] for r in means] == ["5", "2"], f"the comma file's months: {means}")
        weights = read_csv(os.path.join(directory, "commas", "weights_2001_01.csv"))
        assert_that(sorted(float(w["precip"]) for w in weights if float(w["weight"]) > 0)
                    == sorted(float(v) for s, y, m, v in rows if m == 1 and s in ("N1", "N2", "N3", "N4", "N5")),
                    f"the weighted gauges' values: {weights}")
        for kind in ("semicolons", "tabs"):
            for file in outputs["commas"][0]:
                assert_that(outputs[kind][0][file] == outputs["commas"][0][file], f"{kind}: {file} differs")
            assert_that(outputs[kind][1:] == outputs["commas"][1:],
                        f"{kind}: the messages differ: {outputs[kind][1:]} against {outputs['commas'][1:]}")
        # A file of decimal commas has no decimal points: 1.234 there is digit grouping, named (read
        # as 1.234 the mean changed without a word); 1.234,5 is no number either.
        grouped = write(directory, "grouped.csv", "station_id;year;month;precip\nN1;2001;1;12,5\nN2;2001;1;1.234\n")
        _, stderr = run_colorado(os.path.join(directory, "grouped"), stations=stations, observations=grouped,
                                 catchment=catchment, what="digit grouping", status=1, plots=False)
        assert_that(f"{grouped}:3: column 'precip': '1.234' has a point, where the file's numbers have decimal "
                    "commas" in stderr, f"digit grouping: {stderr}")
        both = write(directory, "both.csv", "station_id;year;month;precip\nN1;2001;1;1.234,5\n")
        _, stderr = run_colorado(os.path.join(directory, "both"), stations=stations, observations=both,
                                 catchment=catchment, what="both marks", status=1, plots=False)
        assert_that(f"{both}:2: column 'precip': '1.234,5' is not a number" in stderr, f"both marks: {stderr}")
        # Semicolons with decimal points (as some agencies publish) read the points as decimal points.
        points = write(directory, "points.csv", "station_id;year;month;precip\nN1;2001;1;1.234\n")
        run_colorado(os.path.join(directory, "points"), stations=stations, observations=points,
                     catchment=catchment, what="semicolons and points", plots=False)
        means = read_csv(os.path.join(directory, "points", "areal_mean.csv"))
        assert_that(means[0]["areal_mean"] == "1.234", f"semicolons and points: {means}")
        # In a file of commas a decimal comma splits the field: the count of fields is named.
        split = write(directory, "split.csv", "station_id,year,month,precip\nN1,2001,1,12,5\n")
        _, stderr = run_colorado(os.path.join(directory, "split"), stations=stations, observations=split,
                                 catchment=catchment, what="a decimal comma in a file of commas", status=1,
                                 plots=False)
        assert_that(f"{split}:2: 5 field(s) where the header has 4" in stderr, f"a comma file's 12,5: {stderr}")


def test_daily_observations_give_daily_means():
    # Observations of days, by a date column or by year, month and day columns, give a mean a
    # day, every day from the first to the last (2001-01-31 has no row), each that of the day's
    # values given alone as a month; --day chooses the day of the weights, tiles and map.
    days = {(2001, 1, 30): {"N1": 1.5, "N2": 2.5, "N3": 4.0, "N5": 0.0},
            (2001, 2, 1): {"N1": 3.0, "N4": 1.25, "N6": 9.0},
            (2001, 2, 2): {"N2": 0.5, "N3": 7.0, "N4": 2.0, "N5": 3.5}}
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        by_date = write_daily(directory, "by_date.csv", days)
        by_columns = write(directory, "by_columns.csv", "station_id,year,month,day,precip\n" + "".join(
            f"{s},{y},{m},{d},{v}\n" for (y, m, d), values in days.items() for s, v in values.items()))
        # Timestamps at midnight, as a spreadsheet may export days, are the days.
        by_stamp = write(directory, "by_stamp.csv", "station_id,date,precip\n" + "".join(
            f"{s},{y}-{m:02d}-{d:02d}{' 00:00:00' if k % 2 else 'T00:00'},{v}\n"
            for (y, m, d), values in days.items() for k, (s, v) in enumerate(values.items())))
        outputs = []
        for observations in (by_date, by_columns, by_stamp):
            out = os.path.join(directory, os.path.basename(observations)[:-4])
            stdout, stderr = run_colorado(out, stations=stations, observations=observations, catchment=catchment,
                                          day="2001-02-01", what=observations)
            files = {}
            for file in ("areal_mean.csv", "weights_all_days.csv", "weights_2001_02_01.csv", "map_2001_02_01.png",
                         "areal_mean.png", "unused_inputs.csv", "tiles_2001_02_01.vtp"):
                with open(os.path.join(out, file), "rb") as f:
                    files[file] = f.read()
            outputs.append((files, stdout.replace(out, "OUT"),
                            without_timings(stderr.replace(observations, "OBS"))))
            assert_that("4 days, 3 with data" in stdout and "2001-02-01: areal mean" in stdout, f"stdout: {stdout}")
            assert_that("1 day(s) between 2001-01-30 (line 2) and 2001-02-02 (line " in stderr and ") have no row of a gauge's station" in stderr,
                        f"the day without rows: {stderr}")
        for other in outputs[1:]:
            for file in outputs[0][0]:
                assert_that(outputs[0][0][file] == other[0][file], f"{file} differs between date and day columns")
            assert_that(outputs[0][1:] == other[1:], f"the messages differ: {outputs[0][1:]} against {other[1:]}")
        out = os.path.join(directory, "by_date")
        means = read_csv(os.path.join(out, "areal_mean.csv"))
        assert_that([tuple(int(r[k]) for k in ("year", "month", "day")) for r in means]
                    == [(2001, 1, 30), (2001, 1, 31), (2001, 2, 1), (2001, 2, 2)], f"the days: {means}")
        weights = read_csv(os.path.join(out, "weights_all_days.csv"))
        for r in means:
            day = tuple(int(r[k]) for k in ("year", "month", "day"))
            listed = [w for w in weights if tuple(int(w[k]) for k in ("year", "month", "day")) == day]
            values = days.get(day, {})
            assert_that(int(r["stations_used"]) == len(values) and int(r["stations_weighted"]) == len(listed),
                        f"{day}: {r}, {len(listed)} weighted")
            if not values:
                assert_that(r["areal_mean"] == "", f"{day}: a mean without a report: {r}")
                continue
            assert_close(math.fsum(float(w["weight"]) * float(w["precip"]) for w in listed), float(r["areal_mean"]),
                         1e-12, f"{day}: weights times values")
            # The day's values alone, as a month: the same gauges, so the same mean.
            alone = write(directory, "alone.csv", "station_id,year,month,precip\n" + "".join(
                f"{s},2001,1,{v}\n" for s, v in values.items()))
            run_colorado(os.path.join(directory, "alone"), stations=stations, observations=alone, catchment=catchment,
                         month="2001-01", plots=False, what=f"{day} as a month")
            month = read_csv(os.path.join(directory, "alone", "areal_mean.csv"))
            assert_close(float(month[0]["areal_mean"]), float(r["areal_mean"]), 1e-12, f"{day} against its month")
        tiles = read_polydata(os.path.join(out, "tiles_2001_02_01.vtp"))
        assert_that(tiles.GetNumberOfCells() > 0, "the day's tiles")
        # Bad days are named; --day is for days only.
        cases = [
            ("station_id,date,precip\nN1,2001-02-29,1\n", {}, "column 'date': '2001-02-29' is not a date of the calendar"),
            ("station_id,date,precip\nN1,2001-02-28,1\nN2,2001-03,2\n", {},
             "column 'date': '2001-03' is a month, where line 2 gives a day"),
            ("station_id,date,precip\nN1,Feb 2 2001,1\n", {}, "'Feb 2 2001' is not a date (YYYY-MM-DD"),
            ("station_id,year,month,day,precip\nN1,2001,2,29,1\n", {}, "column 'day': 29 is not a day of 2001-02"),
            ("station_id,date,year,month,precip\nN1,2001-02-03,2001,2,1\n", {}, "both a date column and year/month"),
            ("station_id,when,precip\nN1,2001-02-03,1\n", {}, "no columns year and month, nor a date column"),
            ("station_id,year,precip\nN1,2001,1\n", {}, "no column month, nor a date column"),
            ("station_id,year,month,precip\nN1,00,1,1\n", {},
             "column 'year': '00' is a year below 100: write years in full (1999, 2000)"),
            ("station_id,year,month,precip\nN1,99,1,1\n", {}, "column 'year': '99' is a year below 100"),
            ("station_id,year,month,precip\nN1,099,1,1\n", {}, "column 'year': '099' is a year below 100"),
            ("station_id,year,month,precip\nN1,2001,2,1\n", {"day": "2001-02-01"},
             f"--day 2001-02-01: the observations of {os.path.join(directory, 'bad.csv')} are monthly (use --month)"),
            ("station_id,date,precip\nN1,2001-02-03,1\n", {"day": "2001-02-30"},
             "--day '2001-02-30': is not a date of the calendar"),
            ("station_id,date,precip\nN1,2001-02-03,1\n", {"day": "2001-02"}, "--day '2001-02': expected a date"),
            ("station_id,date,precip\nN1,2001-02-03,1\n", {"day": "2001-02-03", "month": "2001-02"},
             "--month 2001-02 and --day 2001-02-03: give one of them"),
            ("station_id,date,day,precip\nN1,2001-02,3,1\n", {}, "both a date column and year/month/day/hour columns"),
            ("station_id,date,precip\nN1,2001-02-03T06:15:20,1\n", {}, "'2001-02-03T06:15:20' is not on the minute"),
            ("station_id,date,precip\nN1,2001-02T00:00,1\n", {}, "'2001-02T00:00' is not a date"),
        ]
        assert_observations_refused(directory, stations, catchment, cases)
        # Monthly values stamped with a day are read as days, and said; the record's nearest day is
        # shown without a note when no day was asked for.
        stamped = write(directory, "stamped.csv", "station_id,date,precip\nN1,2001-01-01,1\nN2,2001-02-01,2\n")
        _, stderr = run_colorado(os.path.join(directory, "stamped"), stations=stations, observations=stamped,
                                 catchment=catchment, what="month starts", plots=False)
        assert_that(f"{stamped}: every date is day 1 of its month; if these are monthly values" in stderr
                    and "note:" not in stderr, f"month starts: {stderr}")
        ends = write(directory, "ends.csv", "station_id,date,precip\nN1,2001-01-31,1\nN2,2001-02-28,2\n")
        # A day asked for that the record does not have is an error naming it, not another day shown.
        _, stderr = run_colorado(os.path.join(directory, "ends"), stations=stations, observations=ends,
                                 catchment=catchment, what="month ends", plots=False, day="2001-03-01", status=1)
        assert_that("every date is the last day of its month" in stderr
                    and f"--day 2001-03-01: is not in the record of {ends} (its days run from 2001-01-31 to "
                    "2001-02-28)" in stderr and "note:" not in stderr and "Traceback" not in stderr,
                    f"month ends: {stderr}")


def outside_lines(runs):
    """The lines of unused_inputs.csv's rows of observations outside --start/--end (a line, or
    first-last for a run of them), ascending."""
    lines = []
    for span in runs:
        first, _, last = span["line"].partition("-")
        lines.extend(range(int(first), int(last or first) + 1))
    return sorted(lines)


def test_start_and_end_choose_the_period():
    # --start and --end restrict the steps: areal_mean.csv runs from the one to the other, each
    # month as in the whole record's run, months before the data included (without a mean), and
    # unused_inputs.csv lists every observation outside by its line, counted from the raw file.
    outside_kind = "observation before --start or after --end"
    observations_file = os.path.join(EXAMPLE_DATA, "colorado_monthly_precip.csv")
    raw = read_csv(observations_file)
    with tempfile.TemporaryDirectory() as directory:
        run_colorado(os.path.join(directory, "all"), plots=False, what="the whole record")
        whole = {(int(r["year"]), int(r["month"])): r for r in read_csv(os.path.join(directory, "all", "areal_mean.csv"))}
        for start, end, months in (("1960-03", "1961-02", [(1960, m) for m in range(3, 13)] + [(1961, 1), (1961, 2)]),
                                   ("1894-11", "1895-02", [(1894, 11), (1894, 12), (1895, 1), (1895, 2)])):
            out = os.path.join(directory, start)
            stdout, stderr = run_colorado(out, "--start", start, "--end", end, plots=False, what=f"{start} to {end}")
            rows = read_csv(os.path.join(out, "areal_mean.csv"))
            got = [(int(r["year"]), int(r["month"])) for r in rows]
            assert_that(got == months, f"{start} to {end}: the months {got}")
            for r, month in zip(rows, months):
                expected = whole.get(month, {"stations_used": "0", "stations_weighted": "0", "areal_mean": ""})
                for column in ("stations_used", "stations_weighted", "areal_mean"):
                    assert_that(r[column] == expected[column],
                                f"{month}: {column} {r[column]!r}, the whole record's run gives {expected[column]!r}")
            first, last = months[0], months[-1]
            outside = {k + 2: row["station_id"] for k, row in enumerate(raw)
                       if not first <= (int(row["year"]), int(row["month"])) <= last}
            runs = [u for u in read_csv(os.path.join(out, "unused_inputs.csv")) if u["kind"] == outside_kind]
            listed = outside_lines(runs)
            assert_that(sorted(listed) == sorted(outside) and outside, f"{start} to {end}: {len(listed)} observations "
                        f"listed outside, the file has {len(outside)}")
            for span in runs:  # (the file is in time order: a run of several stations before, one after)
                lines = outside_lines([span])
                names = {outside[line] for line in lines}
                said = (span["station_id"], span["note"])
                expected = ((names.pop(), "") if len(lines) == 1 else (next(iter(names)), f"{len(lines)} observations")
                            if len(names) == 1 else ("", f"{len(lines)} observations of {len(names)} stations"))
                assert_that(said == expected, f"{start} to {end}: the run {span}, expected {expected}")
            assert_that(len(runs) == (1 if start == "1894-11" else 2), f"{start} to {end}: the runs {runs}")
            assert_that(f"{len(outside)} observation(s) outside --start/--end are not used" in stderr, stderr)
            assert_that(f"{len(outside)} of them outside --start/--end)" in stdout, stdout)
        # A month asked for outside the period is an error naming both, before the long work (no
        # output written), not another month's files.
        later = os.path.join(directory, "later")
        _, stderr = run_colorado(later, "--start", "1960-03", "--end", "1961-02", month="1970-05", plots=False,
                                 what="a month after the period", status=1)
        assert_that("--month 1970-05: is outside --start 1960-03 and --end 1961-02 (the months averaged run from "
                    "1960-03 to 1961-02)" in stderr and "showing" not in stderr and "Traceback" not in stderr
                    and not os.path.exists(later), f"a month after the period: {stderr}")

        # Daily observations: a month given is its first or last day; a day is a day.
        days = {(2001, 1, 30): {"N1": 1.5, "N2": 2.5}, (2001, 2, 1): {"N1": 3.0, "N4": 1.25},
                (2001, 2, 2): {"N2": 0.5, "N3": 7.0}}
        catchment, stations, _ = write_lake_basin(directory)
        daily = write_daily(directory, "daily.csv", days)
        for options, expected in (({"start": "2001-02"}, [(2001, 2, 1), (2001, 2, 2)]),
                                  ({"end": "2001-01"}, [(2001, 1, 30), (2001, 1, 31)]),
                                  ({"start": "2001-01-31", "end": "2001-02-01"}, [(2001, 1, 31), (2001, 2, 1)])):
            out = os.path.join(directory, "daily_" + "_".join(options.values()))
            _, stderr = run_colorado(out, stations=stations, observations=daily, catchment=catchment, plots=False,
                                     what=f"daily {options}", **options)
            got = [tuple(int(r[k]) for k in ("year", "month", "day")) for r in read_csv(os.path.join(out, "areal_mean.csv"))]
            assert_that(got == expected, f"daily {options}: the days {got}")
            # Gauges whose values are all outside the period are said to have none within it.
            unobserved = sorted(set(LAKE_GAUGES) - {s for day, values in days.items()
                                                    if expected[0] <= day <= expected[-1] for s in values})
            listed = [(u["station_id"], u["kind"]) for u in read_csv(os.path.join(out, "unused_inputs.csv"))
                      if u["kind"].startswith("gauge without")]
            assert_that(sorted(listed) == [(s, "gauge without any observed value within --start/--end")
                                           for s in unobserved]
                        and f"{len(unobserved)} gauge(s) have no observed value within --start/--end (no row, or only "
                        f"missing values) and are never used: {', '.join(unobserved)}" in stderr,
                        f"daily {options}: gauges unobserved within {listed} {stderr}")
            lines = outside_lines([u for u in read_csv(os.path.join(out, "unused_inputs.csv"))
                                   if u["kind"] == outside_kind])
            day_of_line = [day for day, values in days.items() for _ in values]  # (line k + 2)
            assert_that(lines == [k + 2 for k, day in enumerate(day_of_line) if not expected[0] <= day <= expected[-1]],
                        f"daily {options}: lines listed outside {lines}")
        # A month given for days is named as given (any of its days in the period would be shown).
        _, stderr = run_colorado(os.path.join(directory, "daily_month"), stations=stations, observations=daily,
                                 catchment=catchment, plots=False, what="--month of days", start="2001-02",
                                 month="2001-01", status=1)
        assert_that("--month 2001-01: is outside --start 2001-02 (the days averaged run from 2001-02-01 "
                    "to 2001-02-02)" in stderr, stderr)

        # Missing and negative values outside the period are not counted as read: only inside.
        odd = write(directory, "odd.csv", "station_id,date,precip\nN1,2001-01-30,NA\nN2,2001-01-30,-5\n"
                    "N1,2001-02-01,3\nN4,2001-02-01,1.25\n")
        for options, said in (({}, True), ({"start": "2001-02"}, False)):
            _, stderr = run_colorado(os.path.join(directory, "odd"), stations=stations, observations=odd,
                                     catchment=catchment, plots=False, what=f"odd values {options}", **options)
            for fragment in ("1 observation(s) without a value", "1 observation(s) have a negative precipitation"):
                assert_that((fragment in stderr) == said, f"odd values {options}: {fragment!r} in {stderr!r}")

        # Bad bounds are named.
        for options, fragment in ((("--start", "1961-01", "--end", "1960-01"), "--start 1961-01 is after --end 1960-01"),
                                  (("--start", "1960-13"), "--start '1960-13': is not a date of the calendar"),
                                  (("--end", "1960-02-30"), "--end '1960-02-30': is not a date of the calendar"),
                                  (("--start", "1960-01-05"), "are monthly: give a month (YYYY-MM)"),
                                  (("--start", "60-01"), "--start '60-01': expected YYYY-MM, YYYY-MM-DD"),
                                  (("--end", "9999-12-31 24:00"), "is after the calendar's last hour"),
                                  (("--start", "1800-01", "--end", "1801-12"),
                                   "no observation of a gauge's station is within --start 1800-01 and --end 1801-12 "
                                   "(its months run from 1895-01 to 1997-12)")):
            _, stderr = run_colorado(os.path.join(directory, "bad"), *options, plots=False, status=1, what=str(options))
            assert_that(fragment in stderr and "Traceback" not in stderr, f"{options}: {fragment!r} not in {stderr!r}")


def test_a_wide_file_of_a_column_per_station_gives_the_long_files_means():
    # A record as a spreadsheet or a data portal gives it: a row per time, a column per station
    # named by its id. It gives the long file's outputs (days here; the stations numbered 0101 ..
    # 0106, the long file writing them so, the wide header as 101, "0102", 103.0, ... in another
    # order, as they match in the filter), with the columns of no gauge's station (two of one name
    # among them) named in a warning and unused_inputs.csv and not read; a day whose cells are all
    # empty stays a day without reports. A bad value is named by its line and column; two columns
    # of one gauge's station, no column of a gauge's, or no time column end the run.
    ids = {name: f"01{k:02d}" for k, name in enumerate(LAKE_GAUGES, 1)}
    days = {(2001, 1, 30): {"N1": 1.5, "N2": 2.5, "N3": 4.0, "N5": 0.0},
            (2001, 1, 31): {},
            (2001, 2, 1): {"N1": 3.0, "N4": 1.25, "N6": 9.0},
            (2001, 2, 2): {"N2": 0.5, "N3": 7.0, "N4": 2.0, "N5": 3.5}}
    with tempfile.TemporaryDirectory() as directory:
        catchment, _, _ = write_lake_basin(directory)
        stations = os.path.join(directory, "numbered.csv")
        write_stations(stations, {ids[name]: place for name, place in LAKE_GAUGES.items()})
        long = write(directory, "long.csv", "station_id,date,precip\n" + "".join(
            f"{ids[s]},{y}-{m:02d}-{d:02d},{values.get(s, '')}\n" for (y, m, d), values in days.items()
            for s in (values or ["N1"])))
        columns = {"N5": "105", "N1": "101", "N3": '"0103"', "N2": "102.0", "N6": "106", "N4": "0104"}
        wide = write(directory, "wide.csv", "date," + ",".join(columns.values()) + ",RIVER_LEVEL,RIVER_LEVEL\n" + "".join(
            f"{y}-{m:02d}-{d:02d}," + ",".join(str(values.get(s, "")) for s in columns) + ",3.5,\n"
            for (y, m, d), values in days.items()))
        outputs = {}
        for observations in (long, wide):
            out = os.path.join(directory, os.path.basename(observations)[:-4])
            _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=catchment,
                                     plots=False, what=observations)
            outputs[observations] = {name: read_csv(os.path.join(out, name))
                                     for name in ("areal_mean.csv", "weights_all_days.csv", "unused_inputs.csv")}
            outputs[observations]["stderr"] = stderr
        means = outputs[long]["areal_mean.csv"]
        assert_that([r["areal_mean"] == "" for r in means] == [False, True, False, False],
                    f"the long file's days, 2001-01-31 without reports: {means}")
        for name in ("areal_mean.csv", "weights_all_days.csv"):
            assert_that(outputs[long][name] == outputs[wide][name],
                        f"{name}: {outputs[wide][name]} against {outputs[long][name]}")
        kind = "observations column naming no gauge's station (not read)"
        listed = [r for r in outputs[wide]["unused_inputs.csv"] if r["kind"] == kind]
        assert_that(listed == [{"kind": kind, "file": wide, "line": "1", "station_id": "RIVER_LEVEL", "note": note}
                               for note in ("column 8", "column 9")]
                    and [r for r in outputs[wide]["unused_inputs.csv"] if r not in listed]
                    == outputs[long]["unused_inputs.csv"], f"unused inputs: {outputs[wide]['unused_inputs.csv']}")
        said = (f"{wide}: 2 column(s) name no station of {stations} and are not read: 'RIVER_LEVEL' (column 8), "
                "'RIVER_LEVEL' (column 9)")
        assert_that(said in stderr_messages(outputs[wide]["stderr"]), f"the columns of no gauge: {outputs[wide]}")
        # Each counts its observations without a value: the long file's one empty row, and every
        # empty cell of a gauge's station in the wide file (2 + 6 + 3 + 2 by day), though only
        # the whole day without a value becomes a row.
        for observations, file in ((long, "long"), (wide, "wide")):
            missing = [m for m in stderr_messages(outputs[observations]["stderr"]) if "without a value" in m]
            count = 1 if file == "long" else 13
            assert_that(len(missing) == 1 and f": {count} observation(s) without a value" in missing[0],
                        f"{file}: {missing}")
        # The observations read count those without a value in either layout alike: the wide file's
        # 24 cells of gauges' stations, and a long file of the same cells (it counted 11 of them).
        every = write(directory, "every.csv", "station_id,date,precip\n" + "".join(
            f"{ids[s]},{y}-{m:02d}-{d:02d},{values.get(s, '')}\n" for (y, m, d), values in days.items()
            for s in LAKE_GAUGES))
        _, stderr = run_colorado(os.path.join(directory, "every"), stations=stations, observations=every,
                                 catchment=catchment, plots=False, what=every)
        for file, said in (("wide", outputs[wide]["stderr"]), ("long", stderr)):
            assert_that("read 6 gauges and 24 observations in" in said, f"{file}: {said}")
        # Before --start, the day whose cells are all empty holds no observation.
        _, stderr = run_colorado(os.path.join(directory, "later"), stations=stations, observations=wide,
                                 catchment=catchment, plots=False, what="a wide file from 2001-02-01",
                                 start="2001-02-01")
        runs = [(r["line"], r["note"]) for r in read_csv(os.path.join(directory, "later", "unused_inputs.csv"))
                if r["kind"] == "observation before --start or after --end"]
        assert_that("4 observation(s) outside --start/--end are not used" in stderr
                    and runs == [("2-3", "4 observations of 4 stations")], f"before --start: {runs} {stderr}")
        # A gauge at the place of another, both reporting on a line: the line holds the value used
        # too (it read "line 2 (station 107) (line 2 used)").
        shared = os.path.join(directory, "shared.csv")
        write_stations(shared, {**{ids[name]: place for name, place in LAKE_GAUGES.items()}, "0107": LAKE_GAUGES["N1"]})
        two = write(directory, "two.csv", "date,101,107\n2001-01-30,1,2\n")
        _, stderr = run_colorado(os.path.join(directory, "two"), stations=shared, observations=two,
                                 catchment=catchment, plots=False, what="two gauges at one place")
        said = [m for m in stderr_messages(stderr) if "at the place of another" in m]
        assert_that(len(said) == 1 and said[0].endswith(
            ": line 2 (station 107; the line's value of the earlier gauge at its place used)"), f"{said}")
        # A date given on two rows is named, by its lines.
        twice = write(directory, "twice.csv", "date,101,102\n2001-01-30,1,\n2001-01-31,2,3\n2001-01-30,4,5\n")
        _, stderr = run_colorado(os.path.join(directory, "twice"), stations=stations, observations=twice,
                                 catchment=catchment, plots=False, what="a repeated date")
        said = [m for m in stderr_messages(stderr) if "repeat the time of an earlier row" in m]
        assert_that(len(said) == 1 and said[0].startswith(f"{twice}: 1 row(s) repeat the time of an earlier row: "
                                                          "line 4 (as line 2);"), f"the repeated date: {stderr}")
        # With --start/--end only the rows within are counted and named: line 2's empty cell and
        # line 4's repeat of 2001-01-30 are outside --start 2001-01-31, line 5's empty cell inside.
        late = write(directory, "late.csv", "date,101,102\n2001-01-30,1,\n2001-01-31,2,3\n2001-01-30,4,5\n"
                     "2001-02-01,,6\n")
        for options, empty, repeat in (({}, 2, True), ({"start": "2001-01-31"}, 1, False)):
            _, stderr = run_colorado(os.path.join(directory, "late"), stations=stations, observations=late,
                                     catchment=catchment, plots=False, what=f"a wide file {options}", **options)
            said = stderr_messages(stderr)
            assert_that(any(f"{late}: {empty} observation(s) without a value" in m for m in said)
                        and any("repeat the time of an earlier row: line 4 (as line 2)" in m for m in said) == repeat,
                        f"a wide file {options}: {said}")
        assert_observations_refused(directory, stations, catchment, [
            # (a mistyped year made a million empty hours, 0.9 GB; the span's ends are named)
            ("date,101,102\n1000-01-01 01:00,1,2\n2001-01-01 03:00,1,2\n", {},
             "bad.csv: the observations span 8774595 hours between 1000-01-01 01:00 (line 2) and 2001-01-01 03:00 "
             "(line 3), more than 2000000"),
            ("date,101,102\n2001-01,1,x\n", {}, "bad.csv:2: column '102': 'x' is not a number"),
            ("date,101,0101\n2001-01,1,2\n", {}, "bad.csv:1: columns 2 and 3 both name station '0101'"),
            ("date,A1,A2\n2001-01,1,2\n", {}, "bad.csv: the observations file has no station_id and precip "
             "columns, and none of its other columns names a station of"),
            (",101,102\n2001-01,1,2\n", {}, "bad.csv: the observations file has no station_id and precip columns, "
             "so it is read as a wide file (a row per time, a column per station), but it has no time column: date, "
             "or year and month (its first column has no name: if it holds the times, name it date)"),
            ("station_id,date\n101,2001-01\n", {}, "bad.csv: the observations file has no column 'precip'"),
        ])


def test_an_earlier_runs_files_in_out_are_named():
    # A second run into the same --out, for another day and without plots, names the first run's
    # files that it does not write (its day's weights, tiles and map, and the series' plot), and
    # keeps them; the files it writes again are not named. A third run like the second names them
    # still, and a first run into an empty directory names nothing.
    days = {(2001, 1, 30): {"N1": 1.5, "N2": 2.5}, (2001, 2, 1): {"N1": 3.0, "N4": 1.25}}
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        daily = write_daily(directory, "daily.csv", days)
        out = os.path.join(directory, "out")
        os.makedirs(out)
        for own in ("weights_by_hand.csv", "map_of_the_basin.png", "notes.txt"):  # (the user's: not named)
            write(out, own, "")
        earlier = ["areal_mean.png", "map_2001_01_30.png", "tiles_2001_01_30.geojson", "tiles_2001_01_30.vtp",
                   "weights_2001_01_30.csv"]
        for day, plots, named in (("2001-01-30", True, []), ("2001-02-01", False, earlier),
                                  ("2001-02-01", False, earlier)):
            _, stderr = run_colorado(out, stations=stations, observations=daily, catchment=catchment, day=day,
                                     plots=plots, what=f"the run for {day}")
            said = [m for m in stderr_messages(stderr) if "that this run did not write" in m]
            expected = [f"note: {out} also holds {len(named)} file(s) named as this script's outputs that this run "
                        f"did not write (an earlier run's?), kept: {', '.join(named)}"] if named else []
            assert_that(said == expected, f"{day}: {said}, expected {expected}")
            assert_that(all(os.path.exists(os.path.join(out, name)) for name in named), f"{day}: {os.listdir(out)}")


def test_several_days_get_the_files_each_gets_alone():
    # --day given twice writes each day's weights, tiles and map as a run for that day alone does
    # (the same bytes), says each day's line as that run does, and lists both days' files; a day
    # given twice is written once, and a day the record does not have is an error naming it (the
    # record's nearest day, shown in its place, gave files of another day than the one asked for).
    days = {(2001, 1, 30): {"N1": 1.5, "N2": 2.5}, (2001, 2, 1): {"N1": 3.0, "N4": 1.25},
            (2001, 2, 2): {"N2": 0.5, "N3": 7.0}}
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        daily = write_daily(directory, "daily.csv", days)
        common = {"stations": stations, "observations": daily, "catchment": catchment}
        alone = {}
        for day in ("2001-01-30", "2001-02-02"):
            out = os.path.join(directory, day)
            stdout, _ = run_colorado(out, plots=True, day=day, what=f"{day} alone", **common)
            alone[day] = (out, stdout.splitlines())
        both = os.path.join(directory, "both")
        stdout, stderr = run_colorado(both, "--day", "2001-02-02", "--day", "2001-01-30",
                                      plots=True, day="2001-01-30", what="three days", **common)
        lines = stdout.splitlines()
        for day, (out, said) in alone.items():
            tag = day.replace("-", "_")
            for name in (f"weights_{tag}.csv", f"tiles_{tag}.vtp", f"tiles_{tag}.geojson", f"map_{tag}.png"):
                with open(os.path.join(out, name), "rb") as a, open(os.path.join(both, name), "rb") as b:
                    assert_that(a.read() == b.read(), f"{name}: differs from the run for {day} alone")
            assert_that(said[1] in lines, f"{day}: {said[1]!r} not in {lines}")
        _, refused = run_colorado(os.path.join(directory, "beyond"), "--day", "2002-01-01", plots=False,
                                  day="2001-01-30", what="a day beyond the record", status=1, **common)
        assert_that(f"--day 2002-01-01: is not in the record of {daily} (its days run from 2001-01-30 to "
                    "2001-02-02); give a day of the record" in refused and "Traceback" not in refused, refused)
        assert_that(len(lines) == 4 and [line[:10] for line in lines[1:3]] == ["2001-01-30", "2001-02-02"]
                    and "weights_2001_01_30.csv, tiles_2001_01_30.vtp, tiles_2001_01_30.geojson, weights_2001_02_02.csv, "
                    "tiles_2001_02_02.vtp, tiles_2001_02_02.geojson, "
                    "map_2001_01_30.png, map_2001_02_02.png, areal_mean.png, unused_inputs.csv" in lines[3],
                    f"the three days' lines: {lines}")
        # Without --day (own observations): the last day where a gauge reported, 2001-02-02, with
        # a --start before the data too.
        stdout, _ = run_colorado(os.path.join(directory, "early"), plots=False, start="2001-01-28",
                                 what="a --start before the data", **common)
        assert_that(stdout.splitlines()[1] == alone["2001-02-02"][1][1], f"the default day: {stdout}")
        # A last day without a value is passed over: 1963-08-02, not 08-03 nor 07-31.
        august = write(directory, "august.csv", "station_id,date,precip\nN1,1963-07-31,1\nN2,1963-08-02,2\n"
                       "N1,1963-08-03,NaN\n")
        stdout, _ = run_colorado(os.path.join(directory, "august"), plots=False, what="days around 1963-08-01",
                                 **dict(common, observations=august))
        assert_that(stdout.splitlines()[1].startswith("1963-08-02: "), f"the default day: {stdout}")
        files = sorted(name for name in os.listdir(both) if name.startswith(("weights_2", "tiles_", "map_")))
        assert_that(files == ["map_2001_01_30.png", "map_2001_02_02.png", "tiles_2001_01_30.geojson",
                              "tiles_2001_01_30.vtp", "tiles_2001_02_02.geojson", "tiles_2001_02_02.vtp",
                              "weights_2001_01_30.csv", "weights_2001_02_02.csv"],
                    f"the three days' files: {files}")


def test_finer_means_add_up_to_totals():
    # Daily means add up over each month into areal_total_by_month.csv, hourly means over each day
    # into areal_total_by_day.csv, with the calendar's days (hours) of the period and how many had
    # a mean; a period gets a total only when every one had (not the month the records start in,
    # nor one with a day where no gauge reported). The gauges that report in a step all give one
    # value, so its areal mean is that value whatever the weights: the totals are known by hand.
    gauges = sorted(LAKE_GAUGES)
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        reported = [(2001, 1, 30), (2001, 1, 31), *((2001, 2, d) for d in range(1, 29)), (2001, 3, 1), (2001, 3, 3)]
        days = {day: {s: 0.25 * k for s in gauges[:1 + k % 6]} for k, day in enumerate(reported, 1)}
        out = os.path.join(directory, "daily")
        stdout, _ = run_colorado(out, stations=stations, observations=write_daily(directory, "daily.csv", days),
                                 catchment=catchment, plots=False, what="daily observations")
        assert_that("areal_total_by_month.csv, " in stdout, f"the totals file is named: {stdout}")
        totals = read_csv(os.path.join(out, "areal_total_by_month.csv"))
        february = math.fsum(0.25 * k for k, day in enumerate(reported, 1) if day[1] == 2)
        expected = [("2001", "1", "31", "2", None), ("2001", "2", "28", "28", february), ("2001", "3", "31", "2", None)]
        got = [(r["year"], r["month"], r["days"], r["days_with_mean"], r["areal_total"]) for r in totals]
        assert_that([g[:4] for g in got] == [e[:4] for e in expected], f"the months: {got}")
        for g, e in zip(got, expected):
            if e[4] is None:
                assert_that(g[4] == "", f"a month without every day's mean has no total: {g}")
            else:
                assert_close(float(g[4]), e[4], 1e-12, f"{g[:2]}: the days' values added up")
        # Hours and steps of minutes end at their labels: a day runs from the step after 00:00 to
        # the one at 00:00 of the next day (hour-ending records: 01:00 to 24:00).
        for minutes in (60, 15):
            length = datetime.timedelta(minutes=minutes)
            start = datetime.datetime(2001, 3, 1)
            ends = [start + k * length for k in range(1, 24 * 60 // minutes + 1)]  # (all of 2001-03-01)
            ends += [start + datetime.timedelta(days=1, minutes=k * minutes) for k in (1, 5)]  # (two of 03-02)
            values = {end: 0.5 * k for k, end in enumerate(ends, 1)}
            path = write(directory, "finer.csv", "station_id,date,precip\n" + "".join(
                f"{s},{end:%Y-%m-%d %H:%M},{values[end]}\n" for k, end in enumerate(ends) for s in gauges[:1 + k % 6]))
            out = os.path.join(directory, f"every_{minutes}")
            run_colorado(out, stations=stations, observations=path, catchment=catchment, plots=False,
                         what=f"steps of {minutes} minutes")
            totals = read_csv(os.path.join(out, "areal_total_by_day.csv"))
            noun = "hours" if minutes == 60 else "steps"
            got = [(r["day"], r[noun], r[f"{noun}_with_mean"], r["areal_total"]) for r in totals]
            full = str(24 * 60 // minutes)
            assert_that([g[:3] for g in got] == [("1", full, full), ("2", full, "2")] and got[1][3] == "",
                        f"{minutes} minutes: the days {got}")
            assert_close(float(got[0][3]), math.fsum(values[end] for end in ends[:-2]), 1e-12,
                         f"{minutes} minutes: the steps ending in 2001-03-01 01:00 to 2001-03-02 00:00")
        assert_that(not os.path.exists(os.path.join(out, "areal_total_by_month.csv")), "a monthly total of steps")


def test_hourly_observations_give_hourly_means():
    # Observations of hours, by a date column with times on the hour or by an hour column, give a
    # mean an hour, every hour from the first to the last (2001-03-01 01:00 has no row), across
    # the end of a month. Hour 24, as hour-ending records write a day's last hour, is hour 0 of
    # the next day. Each hour's mean is that of the same values given as a day of their own.
    hours = {(2001, 2, 28, 23): {"N1": 1.5, "N2": 2.5, "N3": 4.0, "N5": 0.0},
             (2001, 3, 1, 0): {"N1": 3.0, "N4": 1.25, "N6": 9.0},
             (2001, 3, 1, 2): {"N2": 0.5, "N3": 7.0, "N4": 2.0, "N5": 3.5}}
    ending = {(2001, 2, 28, 23): (2001, 2, 28, 23), (2001, 3, 1, 0): (2001, 2, 28, 24), (2001, 3, 1, 2): (2001, 3, 1, 2)}
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)

        def observations(name, header, when):
            return write(directory, name, header + "".join(f"{s},{when(step)},{v}\n"
                                                           for step, values in hours.items() for s, v in values.items()))
        files = [
            observations("by_date.csv", "station_id,date,precip\n", lambda s: f"{s[0]}-{s[1]:02d}-{s[2]:02d} {s[3]:02d}:00"),
            observations("by_iso.csv", "station_id,date,precip\n",
                         lambda s: f"{s[0]}-{s[1]:02d}-{s[2]:02d}T{s[3]:02d}:00:00"),
            observations("by_columns.csv", "station_id,year,month,day,hour,precip\n", lambda s: ",".join(map(str, s))),
            observations("by_ending.csv", "station_id,year,month,day,hour,precip\n",
                         lambda s: ",".join(map(str, ending[s]))),
            observations("by_ending_date.csv", "station_id,date,precip\n",
                         lambda s: "{}-{:02d}-{:02d} {:02d}:00".format(*ending[s])),
        ]
        outputs = []
        for path in files:
            out = os.path.join(directory, os.path.basename(path)[:-4])
            stdout, stderr = run_colorado(out, stations=stations, observations=path, catchment=catchment,
                                          hour="2001-03-01 00:00", what=path)
            got = {}
            for file in ("areal_mean.csv", "weights_all_hours.csv", "weights_2001_03_01_00.csv",
                         "map_2001_03_01_00.png", "areal_mean.png", "unused_inputs.csv", "tiles_2001_03_01_00.vtp"):
                with open(os.path.join(out, file), "rb") as f:
                    got[file] = f.read()
            note = f"{path}: 3 observation(s) at hour 24 (the end of a day) are read as hour 0 of the next day\n"
            assert_that((note in stderr) == ("ending" in path), f"{path}: the note on hour 24: {stderr}")
            outputs.append((got, stdout.replace(out, "OUT"),
                            without_timings(stderr.replace(note, "").replace(path, "OBS"))))
            assert_that("4 hours, 3 with data" in stdout and "2001-03-01 00:00: areal mean" in stdout,
                        f"stdout: {stdout}")
            assert_that("1 hour(s) between 2001-02-28 23:00 (line 2) and 2001-03-01 02:00 (line " in stderr and ") have no row of a gauge's station"
                        in stderr, f"the hour without rows: {stderr}")
        for path, other in zip(files[1:], outputs[1:]):
            for file in outputs[0][0]:
                assert_that(outputs[0][0][file] == other[0][file], f"{file} differs between by_date and {path}")
            assert_that(outputs[0][1:] == other[1:], f"the messages differ: {outputs[0][1:]} against {other[1:]}")
        out = os.path.join(directory, "by_date")
        means = read_csv(os.path.join(out, "areal_mean.csv"))
        every = [(2001, 2, 28, 23), (2001, 3, 1, 0), (2001, 3, 1, 1), (2001, 3, 1, 2)]
        assert_that([tuple(int(r[k]) for k in ("year", "month", "day", "hour")) for r in means] == every,
                    f"the hours: {means}")
        # The same values with each hour given as a day of its own (the days' path, checked
        # against months in test_daily_observations_give_daily_means).
        as_days = write(directory, "as_days.csv", "station_id,year,month,day,precip\n" + "".join(
            f"{s},2001,1,{every.index(step) + 1},{v}\n" for step, values in hours.items() for s, v in values.items()))
        run_colorado(os.path.join(directory, "as_days"), stations=stations, observations=as_days, catchment=catchment,
                     plots=False, what="the hours as days")
        days = read_csv(os.path.join(directory, "as_days", "areal_mean.csv"))
        weights = read_csv(os.path.join(out, "weights_all_hours.csv"))
        for r, d in zip(means, days):
            hour = tuple(int(r[k]) for k in ("year", "month", "day", "hour"))
            listed = [w for w in weights if tuple(int(w[k]) for k in ("year", "month", "day", "hour")) == hour]
            values = hours.get(hour, {})
            assert_that(int(r["stations_used"]) == len(values) == int(d["stations_used"])
                        and int(r["stations_weighted"]) == len(listed), f"{hour}: {r}, {len(listed)} weighted, {d}")
            if not values:
                assert_that(r["areal_mean"] == "" == d["areal_mean"], f"{hour}: a mean without a report: {r}")
                continue
            assert_close(math.fsum(float(w["weight"]) * float(w["precip"]) for w in listed), float(r["areal_mean"]),
                         1e-12, f"{hour}: weights times values")
            assert_close(float(d["areal_mean"]), float(r["areal_mean"]), 1e-12, f"{hour} against its day")
        # --day with hours chooses the day's first hour; --hour 24:00 is the next day's hour 0.
        for option in ({"day": "2001-03-01"}, {"hour": "2001-02-28 24:00"}, {"hour": "2001-03-01T00:00:00"}):
            stdout, stderr = run_colorado(os.path.join(directory, "a_day"), stations=stations, observations=files[0],
                                          catchment=catchment, plots=False, what=f"{option} of hours", **option)
            assert_that("2001-03-01 00:00: areal mean" in stdout and "note:" not in stderr, f"{option}: {stdout}")
        # Dates all at midnight are days, 24:00 the day it ends.
        ends = write(directory, "ends.csv", "station_id,date,precip\nN1,2001-01-30 24:00,1\nN2,2001-01-31 00:00,2\n")
        run_colorado(os.path.join(directory, "ends"), stations=stations, observations=ends, catchment=catchment,
                     plots=False, what="days at 24:00")
        days = read_csv(os.path.join(directory, "ends", "areal_mean.csv"))
        assert_that([(r["day"], r["stations_used"]) for r in days] == [("30", "1"), ("31", "1")] and "hour" not in days[0],
                    f"days at 24:00: {days}")
        # Times all in one time zone (Z, z and +00:00 the same offset) are read as written: the same
        # means as the times without it.
        means = {}
        for name, zones in (("plain", ("", "", "")), ("zoned", ("Z", "+00:00", "z"))):
            text = "station_id,date,precip\n" + "".join(
                f"{s},2001-03-01T{t}{z},{v}\n" for (s, t, v), z in zip((("N1", "06:00", 1), ("N2", "06:00", 3),
                                                                        ("N1", "07:00", 2)), zones))
            run_colorado(os.path.join(directory, name), stations=stations, catchment=catchment, plots=False,
                         observations=write(directory, name + ".csv", text), what=f"{name} times")
            means[name] = read_csv(os.path.join(directory, name, "areal_mean.csv"))
        assert_that(means["zoned"] == means["plain"] and len(means["plain"]) == 2, f"times in one zone: {means}")
        # Days stamped with the hour they are read at are read as hours, and said; one hour alone is not.
        advice = {"date": "give the dates without the time (YYYY-MM-DD)", "hour": "leave out the hour column"}
        for text, said in (("date\nN1,2001-03-01 07:00,1\nN2,2001-03-02 07:00,2\n", "date"),
                           ("date\nN1,2001-03-01 07:00,1\n", None),
                           ("date\nN1,2001-03-01 07:00,1\nN2,2001-03-01 08:00,2\n", None),
                           ("year,month,day,hour\nN1,2001,3,1,7,1\nN2,2001,3,2,7,2\n", "hour")):
            stamped = write(directory, "stamped.csv", "station_id," + text.replace("\n", ",precip\n", 1))
            _, stderr = run_colorado(os.path.join(directory, "stamped"), stations=stations, observations=stamped,
                                     catchment=catchment, plots=False, what=text)
            warning = (f"{stamped}: every time is 07:00; if these are daily values (a day read at that time), "
                       f"{advice.get(said)}: they are read as hours")
            assert_that((warning in stderr) == (said is not None), f"{text!r}: {stderr}")
        # Bad hours are named; --hour is for hours only.
        hourly = "station_id,date,precip\nN1,2001-03-01 06:00,1\n"
        cases = [
            ("station_id,date,precip\nN1,2001-03-01 24:30,1\n", {}, "'2001-03-01 24:30' is not a time of the day"),
            ("station_id,date,precip\nN1,2001-03-01 06:00:30,1\n", {}, "'2001-03-01 06:00:30' is not on the minute"),
            ("station_id,date,precip\nN1,2001-03-01 25:00,1\n", {}, "'2001-03-01 25:00' is not a time of the day"),
            (hourly + "N2,2001-03-02,1\n", {}, ":3: column 'date': '2001-03-02' is a day, where line 2 gives an hour"),
            ("station_id,date,precip\nN2,2001-03-02,1\nN2,2001-03-02 00:00,1\nN1,2001-03-01 06:00,1\n", {},
             ":4: column 'date': '2001-03-01 06:00' is an hour, where line 2 gives a day"),
            # (a time column was not read: the hours of a day were repeats of its first)
            ("station_id,date,time,precip\nN1,2001-03-01,06:00,1\n", {},
             "has a time column beside its date column: give hours as dates with their time in one column"),
            ("station_id,year,month,day,Time,precip\nN1,2001,3,1,06:00,1\n", {}, "a time column beside its day column"),
            # (times are read as written, in one time zone: two zones, or one on some times only, are refused)
            ("station_id,date,precip\nN1,2001-03-01T06:00Z,1\nN2,2001-03-01 07:00,1\n", {},
             ":3: column 'date': '2001-03-01 07:00' has no time zone, where line 2's '2001-03-01T06:00Z' has time "
             "zone Z: times are read as written (not moved to UTC)"),
            ("station_id,date,precip\nN1,2001-03-01 06:00+01:00,1\nN2,2001-03-01 07:00-0700,1\n", {},
             "'2001-03-01 07:00-0700' has time zone -0700, where line 2's '2001-03-01 06:00+01:00' has time zone +01:00"),
            ("station_id,date,precip\nN1,2001-03-01 06:00+24:00,1\n", {}, "'2001-03-01 06:00+24:00' is not a date (YYYY"),
            # (a day with a fourth number is no date with a zone)
            ("station_id,date,precip\nN1,2001-03-01-05,1\n", {}, "'2001-03-01-05' is not a date (YYYY-MM-DD"),
            ("station_id,year,month,day,hour,time,precip\nN1,2001,3,1,6,06:00,1\n", {},
             "has a time column beside its hour column: leave one of them out"),
            (hourly, {"hour": "2001-03-01T6"}, "--hour '2001-03-01T6': expected a date and hour"),
            (hourly, {"hour": "2001-03-01 06:00Z"}, "--hour '2001-03-01 06:00Z': give the time without its time zone"),
            (hourly, {"hour": "2001-03-01 06:30"}, "--hour '2001-03-01 06:30': expected a date and hour"),
            ("station_id,date,precip\nN1,2001-03,1\nN2,2001-03-01 06:00,1\n", {},
             "'2001-03-01 06:00' is an hour, where line 2 gives a month"),
            ("station_id,date,precip\nN1,2001-03,1\nN2,2001-03-01 00:00,1\n", {},
             "'2001-03-01 00:00' is a day and time, where line 2 gives a month"),
            ("station_id,year,month,day,hour,precip\nN1,2001,3,1,25,1\n", {}, "column 'hour': 25 is outside 0..24"),
            ("station_id,year,month,hour,precip\nN1,2001,3,1,1\n", {}, "an hour column but no day column"),
            ("station_id,date,hour,precip\nN1,2001-03-01,1,1\n", {}, "both a date column and year/month/day/hour"),
            ("station_id,date,precip\nN1,2001-03-01,1\n", {"hour": "2001-03-01 01:00"}, "are daily (use --day)"),
            ("station_id,date,precip\nN1,2001-03,1\n", {"hour": "2001-03-01 01:00"},
             f"--hour 2001-03-01 01:00: the observations of {os.path.join(directory, 'bad.csv')} are monthly "
             "(use --month)"),
            (hourly, {"hour": "2001-03-01"}, "--hour '2001-03-01': expected a date and hour"),
            (hourly, {"hour": "2001-02-30 01:00"}, "--hour '2001-02-30 01:00': is not an hour of the calendar"),
            (hourly, {"hour": "2001-03-01 25:00"}, "--hour '2001-03-01 25:00': is not an hour of the calendar"),
            (hourly, {"day": "2001-03-01", "hour": "2001-03-01 06:00"},
             "--day 2001-03-01 and --hour 2001-03-01 06:00: give one of them"),
        ]
        assert_observations_refused(directory, stations, catchment, cases)


def test_observations_of_minutes_give_a_mean_each_step():
    # Tipping-bucket records at :00, :15 and :45 (by a date column, and by hour and minute columns)
    # give a mean every 15 minutes, every step from the first to the last (10:30 has no row). Each
    # step's counts and mean are those of the same values given as hours of their own (the hours'
    # path, checked against days in test_hourly_observations_give_hourly_means), and --minute
    # chooses a step whose weights are that hour's. Times at :00 and :40 give 20-minute steps.
    minutes = {(2001, 3, 1, 10, 0): {"N1": 1.5, "N2": 2.5, "N3": 4.0},
               (2001, 3, 1, 10, 15): {"N1": 3.0, "N4": 1.25, "N6": 9.0},
               (2001, 3, 1, 10, 45): {"N2": 0.5, "N3": 7.0, "N4": 2.0, "N5": 3.5},
               (2001, 3, 1, 11, 0): {"N5": 1.0, "N6": 2.0}}
    every = [(2001, 3, 1, 10, 0), (2001, 3, 1, 10, 15), (2001, 3, 1, 10, 30), (2001, 3, 1, 10, 45),
             (2001, 3, 1, 11, 0)]
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)

        def observations(name, header, when):
            return write(directory, name, header + "".join(
                f"{s},{when(step)},{v}\n" for step, values in minutes.items() for s, v in values.items()))
        by_date = observations("by_date.csv", "station_id,date,precip\n",
                               lambda s: "{}-{:02d}-{:02d} {:02d}:{:02d}".format(*s))
        by_columns = observations("by_columns.csv", "station_id,year,month,day,hour,minute,precip\n",
                                  lambda s: ",".join(map(str, s)))
        as_hours = observations("as_hours.csv", "station_id,year,month,day,hour,precip\n",
                                lambda s: f"2001,1,1,{every.index(s)}")
        outputs = []
        for path in (by_date, by_columns):
            out = os.path.join(directory, os.path.basename(path)[:-4])
            stdout, stderr = run_colorado(out, stations=stations, observations=path, catchment=catchment,
                                          minute="2001-03-01 10:15", what=path)
            got = {}
            for file in ("areal_mean.csv", "weights_all_minutes.csv", "weights_2001_03_01_10_15.csv",
                         "map_2001_03_01_10_15.png", "areal_mean.png", "unused_inputs.csv",
                         "tiles_2001_03_01_10_15.vtp"):
                with open(os.path.join(out, file), "rb") as f:
                    got[file] = f.read()
            outputs.append(got)
            assert_that("5 15-minute steps, 4 with data" in stdout and "2001-03-01 10:15: areal mean" in stdout,
                        f"{path}: {stdout}")
            assert_that("1 15-minute step(s) between 2001-03-01 10:00 (line 2) and 2001-03-01 11:00 (line " in stderr
                        and "they are 15-minute steps where no gauge reported" in stderr, f"{path}: {stderr}")
        for file in outputs[0]:
            assert_that(outputs[0][file] == outputs[1][file], f"{file} differs between dates and columns")
        means = read_csv(os.path.join(directory, "by_date", "areal_mean.csv"))
        assert_that([tuple(int(r[k]) for k in ("year", "month", "day", "hour", "minute")) for r in means] == every,
                    f"the steps: {means}")
        run_colorado(os.path.join(directory, "as_hours"), stations=stations, observations=as_hours,
                     catchment=catchment, plots=False, hour="2001-01-01 01:00", what="the steps as hours")
        hours = read_csv(os.path.join(directory, "as_hours", "areal_mean.csv"))
        assert_that(len(hours) == len(means), f"hours {hours} against steps {means}")
        for r, h in zip(means, hours):
            assert_that((r["stations_used"], r["stations_weighted"]) == (h["stations_used"], h["stations_weighted"]),
                        f"{r} against {h}")
            if r["areal_mean"] or h["areal_mean"]:
                assert_close(float(h["areal_mean"]), float(r["areal_mean"]), 1e-12, f"{r} against its hour")
        step = read_csv(os.path.join(directory, "by_date", "weights_2001_03_01_10_15.csv"))
        hour = read_csv(os.path.join(directory, "as_hours", "weights_2001_01_01_01.csv"))
        assert_that([(w["station_id"], w["weight"]) for w in step] == [(w["station_id"], w["weight"]) for w in hour]
                    and step, f"--minute's weights {step} against the hour's {hour}")
        # --start and --end as times; 20-minute steps.
        stdout, _ = run_colorado(os.path.join(directory, "period"), stations=stations, observations=by_date,
                                 catchment=catchment, plots=False, start="2001-03-01 10:15", end="2001-03-01 10:45",
                                 what="a period of minutes")
        assert_that("3 15-minute steps, 2 with data" in stdout, f"a period of minutes: {stdout}")
        # A day or a month as a bound is its first step and its last (it ended in a traceback).
        for bounds in ({"start": "2001-03-01", "end": "2001-03-01"}, {"start": "2001-03"}):
            stdout, _ = run_colorado(os.path.join(directory, "period"), stations=stations, observations=by_date,
                                     catchment=catchment, plots=False, what=f"{bounds} of minutes", **bounds)
            steps = 96 if "end" in bounds else 5
            assert_that(f"{steps} 15-minute steps, 4 with data" in stdout, f"{bounds}: {stdout}")
        twenty = write(directory, "twenty.csv",
                       "station_id,date,precip\nN1,2001-03-01 10:00,1\nN2,2001-03-01 10:40,2\n")
        stdout, _ = run_colorado(os.path.join(directory, "twenty"), stations=stations, observations=twenty,
                                 catchment=catchment, plots=False, what="20-minute steps")
        assert_that("3 20-minute steps, 2 with data" in stdout, f"20-minute steps: {stdout}")
        # Bad times are named.
        with open(by_date) as f:
            steps_of_15 = f.read()
        cases = [
            (steps_of_15, {"start": "2001-03-01 10:10"},
             "are in 15-minute steps: give a time whose minute is a multiple of 15"),
            (steps_of_15, {"minute": "2001-03-01 10:15:30"},
             "--minute '2001-03-01 10:15:30': expected a date and time"),
            ("station_id,date,precip\nN1,2001-03-01 06:00,1\n", {"minute": "2001-03-01 06:00"},
             "are hourly (use --hour)"),
            ("station_id,date,precip\nN1,2001-03-01 06:00,1\n", {"start": "2001-03-01 06:30"},
             "are hourly: give an hour (YYYY-MM-DD HH:00)"),
            ("station_id,year,month,day,hour,minute,precip\nN1,2001,3,1,24,15,1\n", {},
             "columns 'hour' and 'minute': 24:15 is not a time of the day"),
            ("station_id,year,month,day,hour,minute,precip\nN1,2001,3,1,6,60,1\n", {},
             "column 'minute': 60 is outside 0..59"),
            ("station_id,year,month,day,minute,precip\nN1,2001,3,1,15,1\n", {}, "a minute column but no hour column"),
            ("station_id,date,precip\nN1,2001-03-01,1\nN2,2001-03-01 06:15,1\n", {},
             ":3: column 'date': '2001-03-01 06:15' is a time of day, where line 2 gives a day"),
        ]
        assert_observations_refused(directory, stations, catchment, cases)


def quarter_hours(gauges, count, step=15, hour="{:02d}"):
    """Rows 'station,date,value' of each gauge every step minutes from 2001-03-01 10:00, count times."""
    return "".join(f"{s},2001-03-01 {hour.format(10 + k * step // 60)}:{k * step % 60:02d},{k % 3 + 0.5}\n"
                   for s in gauges for k in range(count))


def test_times_off_the_steps_and_gauges_of_other_steps_are_named():
    # Times of 15-minute steps, one of them mistyped :07, are read in 1-minute steps, and that time
    # is named with its line; a row at :07 without a value (or of no gauge, or outside the
    # period) leaves the steps 15 minutes, goes to the step after it, and is named; the means are
    # then those of the file without it. Gauges every 5 minutes beside gauges every 15 are named
    # (not gauges of too few times to tell). --minute off the steps is refused as --start is. A
    # single-digit hour (6:15) reads as 06:15.
    header = "station_id,date,precip\n"
    quarters = quarter_hours(("N1", "N2", "N3", "N4", "N5"), 12)
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)

        def run(name, text, what, **options):
            out = os.path.join(directory, name)
            stdout, stderr = run_colorado(out, stations=stations, observations=write(directory, name + ".csv", text),
                                          catchment=catchment, plots=False, what=what, **options)
            return stdout, stderr, read_csv(os.path.join(out, "areal_mean.csv"))

        # (named by the line of its value, not of the missing one before it; N2 is no 1-minute gauge)
        stdout, stderr, _ = run("typo", header + quarters + "N1,2001-03-01 10:07,NA\nN2,2001-03-01 10:07,1.5\n",
                                "a mistyped :07")
        assert_that("read in 1-minute steps because of 1 time(s) not at multiples of 15 minutes as the others are: "
                    "line 63 (2001-03-01 10:07)" in stderr and "166 1-minute steps" in stdout
                    and "keep to different steps" not in stderr, f"a :07: {stderr}")
        _, _, clean = run("clean", header + quarters, "quarter hours")
        assert_that(len(clean) == 12 and clean[-1]["hour"] == "12" and clean[-1]["minute"] == "45", f"{clean}")
        for extra, where in (("N6,2001-03-01 10:07,NA\n", "without a value"), ("X9,2001-03-01 10:22,3\n", "of no gauge")):
            _, stderr, means = run("unused", header + quarters + extra, where)
            assert_that(means == clean and "1 time(s) of rows without a value or of no gauge's station are not at "
                        "multiples of 15 minutes, as the steps are, and are read at the step after them: line 62 "
                        "(2001-03-01 " in stderr, f"a row at :07 {where}: {stderr} {means}")
        # A value at 13:07 outside --end still sets the steps (the period is one of steps), and is
        # named; --sum-to 15 then gives the quarter hours, and lists it as outside.
        late = header + quarters + "N6,2001-03-01 13:07,3\n"
        _, stderr, _ = run("late", late, "a value outside --end", end="2001-03-01 12:45")
        assert_that("read in 1-minute steps because of 1 time(s) not at multiples of 15 minutes as the others are: "
                    "line 62 (2001-03-01 13:07)" in stderr, f"a value at 13:07 outside --end: {stderr}")
        _, stderr, means = run("late", late, "summed, outside --end", end="2001-03-01 12:45", **{"sum-to": "15"})
        outside = [u["line"] for u in read_csv(os.path.join(directory, "late", "unused_inputs.csv"))
                   if u["kind"] == "observation before --start or after --end"]
        assert_that(means == clean and outside == ["62"], f"--sum-to 15 with 13:07 outside --end: {means} {outside}")
        fives = quarter_hours(("N1", "N2", "N3"), 36, step=5)
        _, stderr, _ = run("mixed", header + fives + quarter_hours(("N4", "N5"), 12), "5 and 15 minutes")
        assert_that("the gauges' times keep to different steps: at multiples of 5 minutes for 3 gauge(s) (N1, N2, "
                    "N3); at multiples of 15 minutes for 2 gauge(s) (N4, N5). The means are of 5-minute steps"
                    in stderr, f"5 and 15 minutes: {stderr}")
        _, stderr, _ = run("few", header + fives + quarter_hours(("N4", "N5"), 4), "15 minutes four times")
        assert_that("keep to different steps" not in stderr and "because of" not in stderr, f"four times: {stderr}")
        _, _, single = run("single", header + quarter_hours(("N1", "N2", "N3", "N4", "N5"), 12, hour="{}"), "6:15")
        assert_that(single == clean, f"single-digit hours {single} against {clean}")
        assert_observations_refused(directory, stations, catchment, [
            (header + quarters, {"minute": "2001-03-01 10:07"},
             "--minute 2001-03-01 10:07: the observations of " + os.path.join(directory, "bad.csv") +
             " are in 15-minute steps: give a time whose minute is a multiple of 15")])


def test_sum_to_sums_each_gauges_values_into_longer_steps():
    # Gauges of 5-minute steps beside gauges of 15, summed with --sum-to 15 (and 60), give the means
    # of a file of those sums written by hand: each 15-minute step the total of the values up to its
    # time (10:05, 10:10 and 10:15 go to 10:15); a missing value is left out of its sum (named), a
    # step whose values are all missing is missing, and a repeated station and time is left out
    # (the earlier value is used, as the filter does) and named. Bad --sum-to values are named.
    import datetime

    start = datetime.datetime(2001, 3, 1, 10, 0)
    values = {}  # (station, time): value, None for missing
    for k in range(36):
        for n, station in enumerate(("N1", "N2", "N3")):
            values[(station, start + datetime.timedelta(minutes=5 * k))] = (k * (n + 2)) % 7 * 0.25
    for k in range(12):
        for n, station in enumerate(("N4", "N5")):
            values[(station, start + datetime.timedelta(minutes=15 * k))] = (k + n) % 4 + 0.5
    values[("N1", start + datetime.timedelta(minutes=5))] = None
    values[("N4", start + datetime.timedelta(minutes=30))] = None
    # (N3 at 10:20 missing, then its value: a value after a missing one is no repeat, and used)
    text = f"station_id,date,precip\nN3,{start + datetime.timedelta(minutes=20):%Y-%m-%d %H:%M},NA\n" + "".join(
        f"{s},{t:%Y-%m-%d %H:%M},{'NA' if v is None else v}\n" for (s, t), v in values.items())
    text += f"N2,{start + datetime.timedelta(minutes=10):%Y-%m-%d %H:%M},99\n"  # (a repeat, left out)
    repeat_line = len(text.splitlines())
    earlier_line = next(k for k, line in enumerate(text.splitlines(), 1) if line.startswith(text.splitlines()[-1][:19]))

    def by_hand(minutes):
        sums = {}
        for (s, t), v in values.items():
            end = t + datetime.timedelta(minutes=(minutes - t.minute % minutes) % minutes)
            sums.setdefault((s, end), [])
            if v is not None:
                sums[(s, end)].append(v)
        return "station_id,date,precip\n" + "".join(
            f"{s},{t:%Y-%m-%d %H:%M},{sum(v) if v else 'NA'}\n" for (s, t), v in sorted(sums.items(), key=lambda e: e[0][1]))

    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        mixed = write(directory, "mixed.csv", text)
        for minutes, name in ((15, "minutes"), (60, "hours")):
            got, expected = os.path.join(directory, f"sum_{minutes}"), os.path.join(directory, f"hand_{minutes}")
            stdout, stderr = run_colorado(got, stations=stations, observations=mixed, catchment=catchment, plots=False,
                                          what=f"--sum-to {minutes}", **{"sum-to": str(minutes)})
            run_colorado(expected, stations=stations, observations=write(directory, f"hand_{minutes}.csv",
                                                                         by_hand(minutes)),
                         catchment=catchment, plots=False, what=f"sums by hand of {minutes} minutes")
            for file in ("areal_mean.csv", f"weights_all_{name}.csv"):
                with open(os.path.join(got, file)) as a, open(os.path.join(expected, file)) as b:
                    assert_that(a.read() == b.read(), f"--sum-to {minutes}: {file} differs from the sums by hand")
            means = read_csv(os.path.join(got, "areal_mean.csv"))
            assert_that(len(means) == (13 if minutes == 15 else 4) and all(m["areal_mean"] for m in means),
                        f"--sum-to {minutes}: {means}")
            assert_that(f"{len(values) + 2} observation(s) summed into " in stderr
                        and f"1 observation(s) repeat a station and time of an earlier one and are left out of the "
                        f"sums (the earlier value is used; unused_inputs.csv lists them): line(s) {repeat_line} (as line "
                        f"{earlier_line})" in stderr
                        and "keep to different steps" not in stderr
                        and f"read 6 gauges and {len(values) + 2} observations" in stderr, f"{minutes}: {stderr}")
            # (N1's 10:05 is missing beside values; N4's 10:30 is alone in its quarter, not in its hour;
            # N3's 10:20 has its value too)
            assert_that(f"{1 if minutes == 15 else 2} total(s) leave out a missing value" in stderr,
                        f"{minutes}: {stderr}")
            # The record starts at 10:00 and ends at 12:55: its first and last sums hold part of their minutes.
            noun = "hour" if minutes == 60 else "15-minute step"
            assert_that(f"the first {noun} (2001-03-01 10:00) sums the values from 2001-03-01 10:00 on" in stderr
                        and f"the last {noun} (2001-03-01 13:00) sums the values up to 2001-03-01 12:55" in stderr,
                        f"{minutes}: the ends: {stderr}")
            repeats = [(u["line"], u["station_id"], u["note"]) for u in read_csv(os.path.join(got, "unused_inputs.csv"))
                       if u["kind"].startswith("observation repeating")]
            assert_that(repeats == [(str(repeat_line), "N2", f"repeats line {earlier_line}")], f"{minutes}: {repeats}")
        # Hours summed to hours are themselves.
        stdout, _ = run_colorado(os.path.join(directory, "hours"), stations=stations, catchment=catchment, plots=False,
                                 observations=os.path.join(directory, "hand_60.csv"), what="--sum-to 60 of hours",
                                 **{"sum-to": "60"})
        with open(os.path.join(directory, "hours", "areal_mean.csv")) as a:
            with open(os.path.join(directory, "hand_60", "areal_mean.csv")) as b:
                assert_that(a.read() == b.read(), "--sum-to 60 of hours changed the means")
        quarters = "station_id,date,precip\n" + quarter_hours(("N1", "N2"), 8)
        assert_observations_refused(directory, stations, catchment, [
            (quarters, {"sum-to": "7"}, "--sum-to 7: expected a number of minutes that divides 60"),
            (quarters, {"sum-to": "10"}, "are in 15-minute steps: give a multiple of 15 that divides 60 (30, 60)"),
            ("station_id,year,month,precip\nN1,2001,3,1\n", {"sum-to": "60"},
             "are monthly (--sum-to sums steps of minutes into longer ones)")])


def test_the_field_separator_and_the_decimal_mark():
    csv_input = import_example("csv_input")
    # The separator with which the header has the required columns (quotes kept together), else
    # the header's commonest mark.
    required = ("station_id", "lon", "lat")
    cases = [("a,b;c", (), ","), ("a;b;c,d", (), ";"), ("a\tb\tc", (), "\t"), ("a;b\tc", (), ";"),
             ("single", (), ","), ("\n\n  \nx;y\n1,5;2\n", (), ";"), ("", (), ","),
             ('station_id,lon,lat,"notes; source; qc; flags"', required, ","),
             ('Station_ID;lon;lat;"elev, m, asl"', required, ";"), ("station_id\tlon\tlat\tname, place", required, "\t"),
             ("id;lon;lat", required, ";")]
    for header, wanted, expected in cases:
        got = csv_input.header_delimiter(header, wanted)
        assert_that(got == expected, f"{header!r}: {got!r}, expected {expected!r}")
    # A file of semicolons or tabs has decimal commas when a field is a number written with one.
    for text, delimiter, expected in (("a;b\n1;12,5\n", ";", True), ("a;b\n1;12.5\n", ";", False),
                                      ("a\tb\n-0,25e-3\t1\r\n", "\t", True), ("a;b\nLake, north;1\n", ";", False),
                                      ("a;b\n1,5,5;1\n", ";", False), ('a;b\n"1,5";1\n', ";", True),
                                      ("a;b\r1;2,5\r", ";", True), ('a;b\n1; " 2,5 " \n', ";", True),
                                      ("a;b\n1;1.234,5\n", ";", False)):
        got = csv_input.has_decimal_commas(text, delimiter)
        assert_that(got == expected, f"{text!r}: decimal commas {got}, expected {expected}")
    comma_row, semicolon_row = csv_input.Row({"v": "1,5"}), csv_input.Row({"v": "1,5"}, decimal_comma=True)
    assert_that(csv_input.decimal_point_text("1,5", semicolon_row) == "1.5", "1,5 in a file of semicolons")
    assert_that(csv_input.decimal_point_text("1,5", comma_row) == "1,5", "1,5 in a file of commas is left")
    assert_that(csv_input.decimal_point_text("1.234,5", semicolon_row) is None, "digit grouping is no number")
    assert_that(csv_input.decimal_point_text("1.234", semicolon_row) is None, "a point among decimal commas")
    assert_that(csv_input.number(semicolon_row, "v", "f.csv", 2) == 1.5, "number() of 1,5")
    assert_that(csv_input.integer(csv_input.Row({"y": "1963,0"}, True), "y", "f.csv", 2, 1, 9999) == 1963,
                "integer() of 1963,0")
    for row, what in ((comma_row, "a comma file's 1,5"), (csv_input.Row({"v": "1.2,5"}, True), "1.2,5")):
        try:
            csv_input.number(row, "v", "f.csv", 2)
        except SystemExit as error:
            assert_that("f.csv:2: column 'v'" in str(error), f"{what}: {error}")
        else:
            raise AssertionError(f"{what} was read as a number")


def refusal(directory, name, catchment, stations, observations, what):
    """Runs the example on files it must refuse (exit status 1) into directory/name; returns its stderr."""
    _, stderr = run_colorado(os.path.join(directory, name), stations=stations, observations=observations,
                             catchment=catchment, what=what, status=1, plots=False)
    return stderr


def assert_dialect_means(directory, catchment, stations, plain, dialect):
    """The example's means from two observations files, plain and dialect ((name, path) each), are
    equal and not empty."""
    want, _ = dialect_means(directory, plain[0], catchment, stations, plain[1])
    got, stderr = dialect_means(directory, dialect[0], catchment, stations, dialect[1])
    assert_that(got == want and want[0]["areal_mean"], f"{dialect[0]}: {got} against {want}: {stderr}")


def dialect_means(directory, name, catchment, stations, observations, **options):
    """Runs the example on the stations and observations files into directory/name (without plots);
    returns its areal_mean.csv rows and its stderr."""
    _, stderr = run_colorado(os.path.join(directory, name), stations=stations, observations=observations,
                             catchment=catchment, what=name, plots=False, **options)
    return read_csv(os.path.join(directory, name, "areal_mean.csv")), stderr


# The lake basin's observations with decimals (station, year, month, value), for the files of
# decimal commas below, each of which must give the means of these written plainly.
DECIMAL_ROWS = [("N1", 2001, 1, "10.5"), ("N2", 2001, 1, "20.25"), ("N3", 2001, 1, "30"), ("N4", 2001, 1, "0.125"),
                ("N5", 2001, 1, "-1.5e-3"), ("N1", 2001, 2, "5.75"), ("N6", 2001, 2, "7.5")]


def write_decimal_rows(directory, name, line, comma=False, rows=DECIMAL_ROWS):
    """The rows (DECIMAL_ROWS) as directory/name, each record (the header's too) as line gives it
    from its fields, with decimal commas where comma; returns the path."""
    def decimal(text):
        return text.replace(".", ",") if comma else text
    return write(directory, name, line(("station_id", "year", "month", "precip")) + "".join(
        line((s, str(y), str(m), decimal(v))) for s, y, m, v in rows))


def test_decimal_commas_are_told_by_the_columns_read_as_numbers():
    # A comma in a column that is not read as a number (a height 5,280 with digit grouping in a US
    # file of tabs, a name 3,5 in a file of semicolons) made the file one of decimal commas, and
    # then its correct lon -105.2 was named as digit grouping: now only the columns read decide,
    # and such files give the plain file's means. Where a column read has a decimal comma, a point
    # in another number is named with the field that showed the comma.
    csv_input = import_example("csv_input")
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, observations = write_lake_basin(directory)
        plain, _ = dialect_means(directory, "plain", catchment, stations, observations)
        tabs = write(directory, "tabs.txt", "station_id\tname\tlon\tlat\televation_ft\n" + "".join(
            f"{s}\tGauge {s}\t{lon}\t{lat}\t{5 + k},280\n" for k, (s, (lon, lat)) in enumerate(LAKE_GAUGES.items())))
        named = write(directory, "named.csv", "station_id;name;lon;lat\n" + "".join(
            f"{s};{k},5;{lon};{lat}\n" for k, (s, (lon, lat)) in enumerate(LAKE_GAUGES.items())))
        for name, path in (("tabs", tabs), ("named", named)):
            means, stderr = dialect_means(directory, name, catchment, path, observations)
            assert_that(means == plain, f"{name}: {means} against the plain file's {plain}: {stderr}")
        # (values with points beside a note 1,5)
        points = write_decimal_rows(directory, "points.csv", lambda fields: ",".join(fields) + "\n")
        noted = write(directory, "noted.csv", "station_id;year;month;precip;note\n" + "".join(
            f"{s};{y};{m};{v};1,5\n" for s, y, m, v in DECIMAL_ROWS))
        assert_dialect_means(directory, catchment, stations, ("points", points), ("noted", noted))
        mixed = write(directory, "mixed.csv", "station_id;name;lon;lat\nN1;Lake, north;175,6;-39,1\n"
                      "N2;3,5;176.4;-39.1\n")
        stderr = refusal(directory, "mixed", catchment, mixed, observations, "a point among decimal commas")
        assert_that(f"{mixed}:3: column 'lon': '176.4' has a point, where the file's numbers have decimal commas "
                    "(as '175,6' in column 'lon' on line 2 shows; a point there is digit grouping" in stderr,
                    f"a point among decimal commas: {stderr}")
    # (line, column, field) of the first decimal comma in the columns read (any where None).
    for text, read, expected in (("a;b;c\n1;2,5;x\n", [0], None), ("a;b;c\n1;2,5;x\n", [1], (2, 1, "2,5")),
                                 ("a;b;c\n1;2,5;x\n", None, (2, 1, "2,5")), ("a;b;c\n1;2;3,5\n", [0, 1], None),
                                 ('a;b\n"x;1,5";2,5\n', [1], (2, 1, "2,5")), ('a;b\n"x;1,5";2\n', [1], None),
                                 ("a\tb\n0,5\t1\n2\t3,5\n", [1], (3, 1, "3,5")), ("a;b\n1;2\n", [], None),
                                 # (a quoted field holding a line break is one field: "x\n2,5" is column 1's)
                                 ('a;b;c\n1;"x\n2,5";3\n', [0, 2], None),
                                 ('a;b;c\n1;"x\n2,5";3,5\n', [2], (3, 2, "3,5")),
                                 # (a wide file's hits are counted along their line)
                                 ("a;b;c;d\n1,5;2,5;3;4,5\n", [3], (2, 3, "4,5")),
                                 ("a;b\n1,5;2\n3;4,5\n", [1], (3, 1, "4,5"))):
        got = csv_input.decimal_comma_field(text, "\t" if "\t" in text else ";", read)
        assert_that(got == expected, f"{text!r} {read}: {got}, expected {expected}")


def test_decimal_commas_in_quoted_fields_are_read():
    # R's write.csv2 and pandas' QUOTE_ALL quote fields: "A";"2000";"1";"10,5" gave "'10,5' is
    # not a number". Quoted decimal commas make the file's numbers decimal commas as bare ones do.
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        plain = write_decimal_rows(directory, "plain.csv", lambda fields: ",".join(fields) + "\n")
        quoted = write_decimal_rows(directory, "quoted.csv", lambda fields: ";".join(f'"{f}"' for f in fields) + "\r\n",
                                    comma=True)
        assert_dialect_means(directory, catchment, stations, ("plain", plain), ("quoted", quoted))
        grouped = write(directory, "grouped.csv", '"station_id";"year";"month";"precip"\n"N1";"2001";"1";"10,5"\n'
                        '"N2";"2001";"1";"1.234"\n')
        stderr = refusal(directory, "grouped", catchment, stations, grouped, "a quoted point")
        assert_that(f"{grouped}:3: column 'precip': '1.234' has a point, where the file's numbers have decimal "
                    "commas (as '10,5' in column 'precip' on line 2 shows" in stderr, f"a quoted point: {stderr}")


def test_lines_ending_in_a_lone_cr_read_decimal_commas():
    # Old Excel for Mac ends lines with \r alone: a decimal comma in the last column was not seen
    # (the pattern's end of line was \n's, or the file's end), and 10,5 was "not a number".
    rows = [row for row in DECIMAL_ROWS if row[3] != "30"] + [("N3", 2001, 1, "30")]  # (the last without one)
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        plain = write_decimal_rows(directory, "plain.csv", lambda fields: ",".join(fields) + "\n")
        mac = write_decimal_rows(directory, "mac.csv", lambda fields: ";".join(fields) + "\r", True, rows)
        mac_stations = write(directory, "mac_stations.csv", "station_id;lon;lat\r" + "".join(
            f"{s};{lon};{lat}\r".replace(".", ",") for s, (lon, lat) in LAKE_GAUGES.items()))
        want, _ = dialect_means(directory, "plain", catchment, stations, plain)
        got, stderr = dialect_means(directory, "mac", catchment, mac_stations, mac)
        assert_that(got == want and want[0]["areal_mean"], f"lines ending in \\r: {got} against {want}: {stderr}")
        # A file of both stations and observations so written is read as both (its header was not
        # found: it ran to the file's end).
        both = write(directory, "mac_both.csv", "STATION;LONGITUDE;LATITUDE;DATE;PRCP\r" + "".join(
            f"{s};{LAKE_GAUGES[s][0]};{LAKE_GAUGES[s][1]};{y}-{m:02d};{v}\r".replace(".", ",") for s, y, m, v in rows))
        _, stderr = run_colorado(os.path.join(directory, "mac_both"), observations=both, catchment=catchment,
                                 what="stations and observations in a file of \\r", plots=False)
        got = read_csv(os.path.join(directory, "mac_both", "areal_mean.csv"))
        assert_that(got == want, f"stations and observations in a file of \\r: {got} against {want}: {stderr}")


def test_fields_after_a_comma_and_a_space_may_be_quoted():
    # "station_id", "name", "lon", "lat" (a comma and a space, then a quoted name, as some programs
    # write CSV) was refused: the csv module keeps the space and the quotes of such a field. The
    # spaces are skipped, so the quotes hold the field (a comma inside included), in the header and
    # in the records.
    csv_input = import_example("csv_input")
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, observations = write_lake_basin(directory)
        names = {s: f"Gauge {s}, lake" for s in LAKE_GAUGES}
        named = write(directory, "named.csv", "station_id,name,lon,lat\n" + "".join(
            f'{s},"{names[s]}",{lon},{lat}\n' for s, (lon, lat) in LAKE_GAUGES.items()))
        spaced = write(directory, "spaced.csv", '"station_id", "name", "lon", "lat"\n' + "".join(
            f'"{s}", "{names[s]}", {lon}, "{lat}"\n' for s, (lon, lat) in LAKE_GAUGES.items()))
        spaced_obs = write(directory, "spaced_obs.csv", '"station_id", "year", "month", "precip"\n' + "".join(
            '"' + '", "'.join(line.rstrip().split(",")) + '"\n' for line in open(observations).readlines()[1:]))
        want, _ = dialect_means(directory, "plain", catchment, named, observations, month="2001-01")
        got, stderr = dialect_means(directory, "spaced", catchment, spaced, spaced_obs, month="2001-01")
        assert_that(got == want, f"quoted fields after spaces: {got} against {want}: {stderr}")
        weights = read_csv(os.path.join(directory, "spaced", "weights_2001_01.csv"))
        assert_that(weights == read_csv(os.path.join(directory, "plain", "weights_2001_01.csv"))
                    and {w["name"] for w in weights} <= set(names.values()), f"the names read: {weights}")
    assert_that([csv_input.header_name(f) for f in (' "lon"', '"lat" ', ' " x " ', '"', 'a"b"')]
                == ["lon", "lat", "x", '"', 'a"b"'], "header names stripped of their quotes")
    # Spaces are skipped only where the header quotes its names so and the whole file then reads:
    # a quoted field padded on both sides ("Boulder" ,) or a quote after a space inside a field
    # (101, "Dry" Creek) ended the script as not well-formed; such files read as before.
    for header, record, name in (('station_id, name, lon, lat', '101, "Boulder" ,-105.1,40.5', '"Boulder"'),
                                 ('station_id , "name" , lon , lat', '101 , "Boulder" , -105.1 , 40.5', '"Boulder"'),
                                 ('station_id,name,lon,lat', '101, "Dry" Creek, -105.1, 40.5', '"Dry" Creek')):
        with tempfile.TemporaryDirectory() as directory:
            path = write(directory, "padded.csv", f"{header}\n{record}\n")
            read = [(station, got, lon, lat) for _, _, station, got, lon, lat in csv_input.gauges(path)]
            assert_that(read == [("101", name, -105.1, 40.5)], f"{record!r}: {read}")


def write_shared_and_co_located(directory):
    """The lake basin with gauges 0102 and 102 (one station id by station_key) and N7 at N4's
    place, and observations of both ids and of N4 and N7 in one month; returns (catchment,
    stations, observations)."""
    catchment, _, _ = write_lake_basin(directory)
    gauges = {"0102": LAKE_GAUGES["N1"], "102": LAKE_GAUGES["N2"], "N3": LAKE_GAUGES["N3"], "N4": LAKE_GAUGES["N4"],
              "N5": LAKE_GAUGES["N5"], "N7": LAKE_GAUGES["N4"]}
    stations = os.path.join(directory, "shared.csv")
    write_stations(stations, gauges)
    observations = write(directory, "shared_obs.csv", "station_id,year,month,precip\n102,2001,1,10\nN3,2001,1,30\n"
                         "N4,2001,1,40\nN5,2001,1,50\nN7,2001,1,45\n0102,2001,2,10\nN3,2001,2,30\nN7,2001,2,47\n")
    return catchment, stations, observations


def test_unused_inputs_notes_name_where_the_values_went():
    # A gauge whose station id an earlier gauge has (0102 and 102) is listed as without any
    # observed value: its note names the gauge its id's observations went to, as the warning does;
    # a value set aside for a gauge at the same place that reported names the value used.
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, observations = write_shared_and_co_located(directory)
        _, stderr = dialect_means(directory, "out", catchment, stations, observations)
        assert_that("their observations go to the first: 102 (gauges 0 and 1: lines 2 and 3)" in stderr,
                    f"the warning of the shared id: {stderr}")
        notes = {(row["file"], row["line"]): (row["kind"], row["note"])
                 for row in read_csv(os.path.join(directory, "out", "unused_inputs.csv"))}
        assert_that(notes.get((stations, "3")) == ("gauge without any observed value",
                                                   "station id of line 2 (0102): its observations go to that gauge"),
                    f"the gauge of the shared id: {notes}")
        assert_that(notes.get((stations, "7"), ("", ""))[1] == "same place as line 5", f"the gauge N7: {notes}")
        kind = ("observation of a gauge at the place of an earlier gauge that reported that month (the earlier "
                "gauge's value is used)")
        assert_that(notes.get((observations, "6")) == (kind, "the value of line 4 (station N4 at the same place) is "
                                                             "used"), f"N7's value of 2001-01: {notes}")
        assert_that((observations, "9") not in notes, f"N7's value of 2001-02 (N4 had none) is used: {notes}")


def test_the_help_says_what_unused_inputs_lists():
    # --help listed "an observation ... without a station id or time" in unused_inputs.csv, but
    # the script ends naming such a row; the file's kind said so too. And unused_inputs.csv ends
    # its lines as the other CSV outputs do (the csv module's \r\n, each of them).
    status, stdout, _ = run_example("colorado_areal_precipitation.py", "--help")
    text = " ".join(stdout.split())
    assert_that(status == 0 and "without a station id or time" not in text
                and "an observation of a station no gauge has, and an observation before --start" in text,
                f"--help on unused_inputs.csv: {text}")
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, observations = write_shared_and_co_located(directory)
        write(directory, "unknown.csv", open(observations).read() + "N9,2001,1,3\n")
        _, stderr = dialect_means(directory, "out", catchment, stations, os.path.join(directory, "unknown.csv"))
        rows = read_csv(os.path.join(directory, "out", "unused_inputs.csv"))
        assert_that(["observation of a station no gauge has"] == [r["kind"] for r in rows if r["station_id"] == "N9"],
                    f"the row of N9: {rows}")
        ends = {}
        for name in sorted(os.listdir(os.path.join(directory, "out"))):
            if name.endswith(".csv"):
                with open(os.path.join(directory, "out", name), "rb") as f:
                    data = f.read()
                ends[name] = (data.count(b"\r\n"), data.count(b"\n"))
        assert_that(len(ends) >= 4 and all(crlf == lf for crlf, lf in ends.values()),
                    f"line ends differ between the CSV outputs: {ends}")
        # (a row without its station id or its time ends the run, naming it: it is never listed)
        for name, row in (("no_id", ",2001,1,3"), ("no_time", "N3,,1,3")):
            bad = write(directory, f"{name}.csv", f"station_id,year,month,precip\n{row}\n")
            _, stderr = run_colorado(os.path.join(directory, name), stations=stations, observations=bad,
                                     catchment=catchment, what=name, status=1, plots=False)
            assert_that(f"{bad}:2: column" in stderr and "Traceback" not in stderr, f"{name}: {stderr}")


def stderr_messages(stderr):
    """The lines of the example's stderr other than its reading summary and progress lines."""
    return [line for line in stderr.splitlines()
            if line and not line.startswith("read ") and "Thiessen areal means:" not in line]


def assert_without_vtk_decoration(stderr, what):
    """No VTK log line (colour codes, source line, object address) nor executive dump in stderr,
    and every progress line holds progress only (a message after it starts a line of its own)."""
    for mark in ("\x1b", "ERR|", "WARN|", "ERROR: In", "Warning: In", "(0x", "vtkExecutive",
                 "vtkCompositeDataPipeline", "Debug: Off", "Modified Time", "see the error above"):
        assert_that(mark not in stderr, f"{what}: {mark!r} in {stderr!r}")
    for line in stderr.splitlines():  # (run_example's text mode reads the progress's \r as a line end)
        if "Thiessen areal means:" in line:
            assert_that(re.fullmatch(r"Thiessen areal means: +\d+%", line),
                        f"{what}: a message on the progress line {line!r}")


def test_small_values_and_a_catchment_across_the_antimeridian():
    # Means of 1e-5 and 1e-8 (data in metres) keep their digits in areal_mean.csv, and the map of a
    # catchment across the 180th meridian, its gauges on both sides, spans the catchment, not the
    # globe: its outline is one small ring near 180.
    example = import_example()
    with tempfile.TemporaryDirectory() as out:
        gauges = {"A": (179.6, -16.2), "B": (179.7, -16.8), "C": (-179.9, -16.7), "D": (-179.6, -16.4)}
        stations = os.path.join(out, "stations.csv")
        write_stations(stations, gauges)
        observations = write(out, "obs.csv", "station_id,year,month,precip\n" + "".join(
            f"{s},2000,{m},{v * 10.0 ** -(3 * m + 2)}\n" for m in (1, 2) for s, v in zip("ABCD", (1, 2, 3, 4))))
        catchment = write(out, "across.geojson", json.dumps({"type": "Polygon", "coordinates": [[
            [179.5, -17], [-179.5, -17], [-179.5, -16], [179.5, -16], [179.5, -17]]]}))
        run_colorado(out, stations=stations, observations=observations, catchment=catchment, month="2000-01",
                     what="across the antimeridian")
        means = {int(r["month"]): float(r["areal_mean"]) for r in read_csv(os.path.join(out, "areal_mean.csv"))}
        per_month = {}
        for w in read_csv(os.path.join(out, "weights_all_months.csv")):
            per_month.setdefault(int(w["month"]), []).append(float(w["weight"]) * float(w["precip"]))
        for month, products in per_month.items():
            assert_close(math.fsum(products), means[month], 1e-12, f"month {month}: areal mean of small values")
        assert_that(0 < means[2] < 1e-7, f"the second month's mean: {means[2]}")
        assert_that(is_png(os.path.join(out, "map_2000_01.png")), "map_2000_01.png is not a PNG file")
        tiles = read_polydata(os.path.join(out, "tiles_2000_01.vtp"))
        per_gauge = example.tiles_by_gauge(tiles)
        _, outline = example.read_catchment(catchment)
        points = list(gauges.values())
        moved, moved_tiles, lon, _, (lon_min, lon_max, _, _) = example.map_layout(outline, per_gauge, points)
        assert_that(lon_max - lon_min < 1.5 and lon_min < 180.0 < lon_max,
                    f"the map spans longitudes {lon_min} .. {lon_max}")
        for ring in moved + [r for e in moved_tiles.values() for r in e["rings"]]:
            xs = [p[0] for p in ring]
            assert_that(max(xs) - min(xs) <= 1.0 + 1e-9, f"a ring spans {min(xs)} .. {max(xs)}")
        assert_that(all(lon_min < x < lon_max for x in lon), f"gauges at {lon}, map {lon_min} .. {lon_max}")
        # The GeoJSON tiles keep to -180..180 (RFC 7946): a tile across the meridian is a
        # MultiPolygon of its parts, cut there, each on its side and together holding its cells'
        # area (checked with the rest by assert_geojson_tiles).
        assert_geojson_tiles(os.path.join(out, "tiles_2000_01.geojson"), tiles,
                             read_csv(os.path.join(out, "weights_2000_01.csv")))
        with open(os.path.join(out, "tiles_2000_01.geojson")) as f:
            features = json.load(f)["features"]
        kinds = [feature["geometry"]["type"] for feature in features]
        assert_that("MultiPolygon" in kinds and "Polygon" in kinds, f"the tiles' kinds: {kinds}")
        for feature in features:
            if feature["geometry"]["type"] == "MultiPolygon":
                sides = sorted((min(p[0] for p in polygon[0]), max(p[0] for p in polygon[0]))
                               for polygon in feature["geometry"]["coordinates"])
                assert_that(len(sides) == 2 and sides[0][0] == -180.0 and sides[1][1] == 180.0,
                            f"{feature['properties']['station_id']}: the parts span {sides}")


def test_the_map_of_a_catchment_wide_in_longitude_keeps_its_tiles_over_it():
    # A band round the South Pole from -150 to 150 degrees: its tiles and gauges were moved to
    # within 180 degrees of its first vertex, so those east of 30 were drawn a turn away, and its
    # latitudes were padded beyond the pole, to -103.
    example = import_example()
    band = [[(lon, -86.0) for lon in range(-150, 151, 5)] + [(lon, -88.5) for lon in range(150, -151, -5)]]
    per_gauge = {g: {"value": 1.0, "rings": [[(lon - 5, -87.0), (lon + 5, -87.0), (lon, -86.5)]]}
                 for g, lon in enumerate((-120.0, 0.0, 60.0, 140.0))}
    points = [(-120.0, -87.2), (0.0, -87.2), (60.0, -87.2), (140.0, -87.2)]
    _, tiles, lon, _, (lon_min, lon_max, lat_min, lat_max) = example.map_layout(band, per_gauge, points)
    assert_that(lon == [p[0] for p in points], f"gauges moved to {lon}")
    assert_that(all(tiles[g]["rings"] == per_gauge[g]["rings"] for g in per_gauge), f"tiles moved: {tiles}")
    assert_that(lon_min < -150 and lon_max > 150 and lat_min == -90.0 and -86 < lat_max <= 90,
                f"the map's extent {lon_min} .. {lon_max}, {lat_min} .. {lat_max}")


def test_tile_polygons_are_moved_within_180_by_their_side_of_the_meridian():
    # A western part ending at 180 whose westernmost longitude rounds to 180 once 180 is added:
    # moved by its westernmost longitude, it went a turn east, to -180.00000000000003 .. -180.
    example = import_example()
    for polygon, expected in (([[(179.99999999999997, 0), (180, 0), (180, 1)]], (179.99999999999997, 180)),
                              ([[(180, 0), (180.5, 0), (180.5, 1)]], (-180, -179.5)),
                              ([[(-180.5, 0), (-180, 0), (-180, 1)]], (179.5, 180)),
                              ([[(-180, 0), (-179.5, 0), (-179.5, 1)]], (-180, -179.5)),
                              ([[(200, 0), (210, 0), (210, 1)], [(205, 0.2), (205, 0.5), (206, 0.2)]], (-160, -150)),
                              ([[(-105, 39), (-104, 39), (-104, 40)]], (-105, -104))):
        moved = example.within_180(polygon)
        lons = [x for ring in moved for x, _ in ring]
        assert_that((min(lons), max(lons)) == expected and len(moved) == len(polygon),
                    f"{polygon} moved to {moved}")


def test_compressed_observations_are_read_and_all_weights_can_be_skipped():
    # A large record is often kept compressed: gzip, bzip2 and xz files were refused ("decompress it
    # first"); each gives the plain file's outputs byte for byte. --no-all-weights leaves out
    # weights_all_months.csv (and an earlier run's), nothing else.
    import bz2
    import gzip
    import lzma

    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        plain = os.path.join(out, "plain")
        run_colorado(plain, stations=stations, observations=observations, catchment=catchment, plots=False)
        with open(observations, "rb") as f:
            text = f.read()
        names = sorted(os.listdir(plain))
        for module, extension in ((gzip, ".gz"), (bz2, ".bz2"), (lzma, ".xz")):
            packed = observations + extension
            with open(packed, "wb") as f:
                f.write(module.compress(text))
            unpacked = os.path.join(out, extension[1:])
            run_colorado(unpacked, stations=stations, observations=packed, catchment=catchment, plots=False,
                         what=f"observations{extension}")
            for name in ("areal_mean.csv", "weights_all_months.csv", "unused_inputs.csv"):
                same = open(os.path.join(plain, name)).read() == open(os.path.join(unpacked, name)).read()
                assert_that(same, f"{name} from observations{extension} differs from the plain file's")
        stdout, stderr = run_colorado(plain, "--no-all-weights", stations=stations, observations=observations,
                                      catchment=catchment, plots=False, what="--no-all-weights")
        left = sorted(os.listdir(plain))
        assert_that(left == [n for n in names if n != "weights_all_months.csv"] and "weights_all" not in stdout,
                    f"--no-all-weights: {left} (before {names}), {stdout!r}")
        removed = os.path.join(plain, "weights_all_months.csv")
        assert_that(f"note: removed {removed}, an earlier run's: with --no-all-weights it would not match this "
                    "run's files" in stderr_messages(stderr), f"--no-all-weights: {stderr}")


def test_text_lines_split_as_a_string_io_does():
    # csv_input.text_lines stands for io.StringIO(text, newline="") (whose copy of a large file
    # took 4 bytes a character): the same lines, ends kept, for every kind of line end, a last line
    # without one, blank lines and a quoted field across lines.
    import io

    csv_input = import_example("csv_input")
    for text in ("", "x", "a\nb\r\nc\rd", "a\n\nb\n", "\r\n\r\n", "a,\"b\nc\"\r\nd\n", "a\r\rb\n\r"):
        got, want = list(csv_input.text_lines(text)), list(io.StringIO(text, newline=""))
        assert_that(got == want, f"{text!r}: {got} against {want}")


def test_reading_a_large_file_says_how_far_it_got():
    # Reading millions of rows took a minute or more with no output at all. read_observations says
    # how many rows it has read every ReadingProgress.EVERY seconds (0 here: at every check, which
    # it makes every 65536 rows), and how far that is into the file's lines; of a compressed file,
    # whose bytes are not its lines, the rows alone.
    import contextlib
    import gzip
    import io

    example = import_example()
    stations = [f"N{k}" for k in range(70)]
    text = "station_id,year,month,precip\n" + "".join(
        f"{s},{1900 + m // 12},{m % 12 + 1},1\n" for m in range(1000) for s in stations)
    with tempfile.TemporaryDirectory() as out:
        plain = write(out, "obs.csv", text)
        packed = os.path.join(out, "obs.csv.gz")
        with open(packed, "wb") as f:
            f.write(gzip.compress(text.encode()))
        # (row 65,536 is on line 65,537 of the header and 70,000 rows)
        for path, share in ((plain, f" ({100 * 65537 // 70001}% of its 70,001 lines)"), (packed, "")):
            every, example.ReadingProgress.EVERY = example.ReadingProgress.EVERY, 0.0
            said = io.StringIO()
            try:
                with contextlib.redirect_stderr(said):
                    example.read_observations(path, {example.station_key(s): k for k, s in enumerate(stations)},
                                              stations[0], "stations.csv", set(), stations)
            finally:
                example.ReadingProgress.EVERY = every
            lines = [line for line in said.getvalue().splitlines() if line.startswith(f"reading {path}:")]
            assert_that(lines == [f"reading {path}: 65,536 rows so far{share}"],
                        f"progress lines: {said.getvalue()!r}")
    for text, count in (("", 0), ("a", 1), ("a\n", 1), ("a\r\nb", 2), ("a\rb\r", 2), ("a\n\nb\n", 3),
                        ("a\nb\rc\r\n", 3), ("BZh,x\n1,2\n", 2)):
        with tempfile.TemporaryDirectory() as out:
            got = example.line_count(write(out, "lines.csv", text))
            assert_that(got == count, f"line_count of {text!r}: {got}, expected {count}")


def shapefile_of(rings):
    """The .shp and .shx bytes of one polygon record with the given rings (lists of (x, y), first
    point repeated last), as ESRI's shapefile specification lays them out (no .dbf: GDAL reads the
    geometry without it)."""
    import struct

    points = [p for ring in rings for p in ring]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    box = struct.pack("<4d", min(xs), min(ys), max(xs), max(ys))
    parts, start = [], 0
    for ring in rings:
        parts.append(start)
        start += len(ring)
    content = (struct.pack("<i", 5) + box + struct.pack("<2i", len(rings), len(points))
               + struct.pack(f"<{len(parts)}i", *parts) + b"".join(struct.pack("<2d", *p) for p in points))

    def header(length_bytes):
        return (struct.pack(">7i", 9994, 0, 0, 0, 0, 0, length_bytes // 2) + struct.pack("<2i", 1000, 5) + box
                + struct.pack("<4d", 0, 0, 0, 0))

    record = struct.pack(">2i", 1, len(content) // 2) + content
    shp = header(100 + len(record)) + record
    shx = header(108) + struct.pack(">2i", 50, len(content) // 2)
    return shp, shx


def test_a_catchment_in_a_zip_file_is_read_from_it():
    # A zipped catchment (as downloads come) was "no polygon, drop the measures". A zipped GeoJSON
    # (with macOS's __MACOSX copy beside it) gives the same means as the file itself; a zip of
    # several candidate files names them.
    import zipfile

    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        run_colorado(os.path.join(out, "plain"), stations=stations, observations=observations, catchment=catchment,
                     plots=False)
        zipped = os.path.join(out, "basin.zip")
        with zipfile.ZipFile(zipped, "w") as z:
            z.write(catchment, "data/basin.geojson")
            z.writestr("data/README.txt", "the basin\n")
            z.writestr("__MACOSX/data/._basin.geojson", "macOS's resource fork\n")
        run_colorado(os.path.join(out, "zipped"), stations=stations, observations=observations, catchment=zipped,
                     plots=False, what="a zipped GeoJSON")
        plain, read = (open(os.path.join(out, d, "areal_mean.csv")).read() for d in ("plain", "zipped"))
        assert_that(plain == read and plain.count("\n") == 3, f"zipped {read!r} against plain {plain!r}")
        # The same basin as a zipped shapefile (outline clockwise, lake anticlockwise, as the format
        # orders them): the same means to 12 digits (GDAL may start the rings elsewhere).
        outline, lake = LAKE_BASIN["features"][0]["geometry"]["coordinates"]
        shp, shx = shapefile_of([outline[::-1], lake[::-1]])
        shapefile = os.path.join(out, "basin_shp.zip")
        with zipfile.ZipFile(shapefile, "w") as z:
            z.writestr("basin/basin.shp", shp)
            z.writestr("basin/basin.shx", shx)
        run_colorado(os.path.join(out, "shp"), stations=stations, observations=observations, catchment=shapefile,
                     plots=False, what="a zipped shapefile")
        got, want = (read_csv(os.path.join(out, d, "areal_mean.csv")) for d in ("shp", "plain"))
        assert_that(len(got) == len(want) == 2 and all(
            abs(float(a["areal_mean"]) - float(b["areal_mean"])) <= 1e-12 * abs(float(b["areal_mean"]))
            and a["stations_weighted"] == b["stations_weighted"] for a, b in zip(got, want)),
            f"the zipped shapefile's means {got} against {want}")
        two = os.path.join(out, "two.zip")
        with zipfile.ZipFile(two, "w") as z:
            z.write(catchment, "a.geojson")
            z.write(catchment, "b.json")
        _, stderr = run_colorado(os.path.join(out, "two"), stations=stations, observations=observations,
                                 catchment=two, status=1, plots=False, what="two GeoJSON files zipped")
        assert_that(f"{two}: holds no single catchment file (one shapefile, GeoJSON, KML or GeoPackage) to read: "
                    "a.geojson, b.json; unzip it and give the file" in stderr, f"{stderr}")


def test_a_catchment_declared_projected_is_named():
    # Its coordinates are lon/lat (a UTM declaration over them does not make them metres: see
    # test_gauges_and_a_catchment_in_a_utm_zone_give_the_lon_lat_means); a projected system (here a
    # GeoJSON "crs" of UTM 60S, as a shapefile's .prj gives it) is named on a line of its own. Metres
    # under a .prj that GDAL cannot read are said to need a declaration it reads.
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        declared = dict(LAKE_BASIN, crs={"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::32760"}})
        utm = write(out, "utm.geojson", json.dumps(declared))
        _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=utm, plots=False,
                                 what="a declared UTM system")
        assert_that(f"{utm}: declares the projected coordinate system 'WGS 84 / UTM zone 60S'; its coordinates are "
                    "read as longitude/latitude in degrees (WGS84), which they must be (else reproject the file, "
                    "e.g. ogr2ogr -t_srs EPSG:4326 out.shp in.shp; the metres of UTM, transverse Mercator (tmerc), "
                    "Albers equal-area (aea), Lambert conformal conic (lcc), Lambert azimuthal equal-area (laea) "
                    "and Mercator (merc, and the web maps' EPSG:3857) are made lon/lat here)"
                    in stderr_messages(stderr), f"{stderr}")
        _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=catchment, plots=False)
        assert_that("declares" not in stderr, f"the lon/lat basin: {stderr}")
        # A geographic system on an older datum (NAD27, Clarke 1866) is named, with the shift it
        # leaves; one on NAD83 (GRS80, within a metre or two of WGS84) is not.
        for code, named in (("4267", True), ("4269", False), ("4326", False)):
            declared = dict(LAKE_BASIN, crs={"type": "name", "properties": {"name": f"urn:ogc:def:crs:EPSG::{code}"}})
            geographic = write(out, f"epsg{code}.geojson", json.dumps(declared))
            _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=geographic,
                                     plots=False, what=f"EPSG:{code}")
            said = [m for m in stderr_messages(stderr) if "declares the datum" in m]
            assert_that(len(said) == int(named), f"EPSG:{code}: {stderr}")
            if named:
                assert_that(said[0].startswith(f"{geographic}: declares the datum 'North_American_Datum_1927' "
                                               "(ellipsoid 'Clarke 1866'); its longitudes/latitudes are read as "
                                               "WGS84 ones"), f"{said[0]}")
        # Metres in a shapefile whose .prj GDAL cannot read: the vertex is named, and that the file
        # must declare its system in a form GDAL reads.
        shp, shx = shapefile_of([utm_of(ring) for ring in LAKE_BASIN["features"][0]["geometry"]["coordinates"]])
        for extension, data in ((".shp", shp), (".shx", shx), (".prj", b"not a coordinate system")):
            with open(os.path.join(out, "garbled" + extension), "wb") as f:
                f.write(data)
        garbled = os.path.join(out, "garbled.shp")
        _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=garbled, plots=False,
                                 status=1, what="a garbled .prj")
        assert_that(f"{garbled}: catchment ring 0 vertex 0 has an invalid longitude/latitude" in stderr and
                    "look like projected coordinates" in stderr and "; if they are metres of a projected system, "
                    "the file must declare it in a form GDAL reads" in stderr, f"a garbled .prj: {stderr}")


def test_gauges_and_a_catchment_in_a_utm_zone_give_the_lon_lat_means():
    # The lake basin and its gauges given in UTM zone 60S (the catchment as a shapefile whose .prj
    # declares the zone, its edges cut every 0.001 degrees in lon/lat before projecting, so that it
    # holds the lon/lat shape to a millimetre; the gauges as x, y with --stations-utm 60S) give the
    # counts and means of the lon/lat files, the outline cut alike (its vertices move the automatic
    # projection, and the means with it, by 1e-7): the coordinates are made lon/lat first, and
    # that is said.
    from tessera import vtkGeographicProjection
    from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    def in_utm_60s(rings, closed):
        """rings of (lon, lat) projected to UTM 60S, as lists of (x, y); closed: polygon rings with
        their edges cut every 0.001 degrees and the first point repeated last."""
        points, cells = vtkPoints(), vtkCellArray()
        points.SetDataTypeToDouble()
        for ring in rings:
            cells.InsertNextCell(len(ring), [points.InsertNextPoint(x, y, 0.0) for x, y in ring])
        data = vtkPolyData()
        data.SetPoints(points)
        data.SetPolys(cells) if closed else data.SetVerts(cells)
        projection = vtkGeographicProjection()
        projection.SetInputData(data)
        projection.SetProjectionToUTM()
        projection.SetUTMZone(60)
        projection.SetUTMNorth(False)
        projection.SetMaximumEdgeLength(0.001 if closed else 0.0)
        projection.Update()
        projected, cell, cells = [], vtkIdList(), projection.GetOutput().GetPolys() if closed else None
        if not closed:
            return [[projection.GetOutput().GetPoint(k)[:2] for k in range(points.GetNumberOfPoints())]]
        cells.InitTraversal()
        while cells.GetNextCell(cell):
            ring = [projection.GetOutput().GetPoint(cell.GetId(k))[:2] for k in range(cell.GetNumberOfIds())]
            projected.append(ring + ring[:1])
        return projected

    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        rings = LAKE_BASIN["features"][0]["geometry"]["coordinates"]

        def write_shapefile(name, utm_rings):
            shp, shx = shapefile_of(utm_rings)
            for extension, data in ((".shp", shp), (".shx", shx)):
                with open(os.path.join(out, name + extension), "wb") as f:
                    f.write(data)
            with open(os.path.join(out, name + ".prj"), "w") as f:
                f.write('PROJCS["WGS_1984_UTM_Zone_60S",GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",SPHEROID['
                        '"WGS_1984",6378137.0,298.257223563]],PRIMEM["Greenwich",0.0],UNIT["Degree",'
                        '0.0174532925199433]],PROJECTION["Transverse_Mercator"],PARAMETER["False_Easting",500000.0],'
                        'PARAMETER["False_Northing",10000000.0],PARAMETER["Central_Meridian",177.0],'
                        'PARAMETER["Scale_Factor",0.9996],PARAMETER["Latitude_Of_Origin",0.0],UNIT["Meter",1.0]]')
            return os.path.join(out, name + ".shp")
        utm = write_shapefile("basin_utm", in_utm_60s([ring[:-1] for ring in rings], True))[:-4]
        gauges = in_utm_60s([list(LAKE_GAUGES.values())], False)[0]
        xy = write(out, "stations_xy.csv", "station_id,x,y\n" + "".join(
            f"{s},{x!r},{y!r}\n" for s, (x, y) in zip(LAKE_GAUGES, gauges)))
        run_colorado(os.path.join(out, "lonlat"), stations=stations, observations=observations,
                     catchment=write_lake_basin_cut(out), plots=False, what="lon/lat")
        _, stderr = run_colorado(os.path.join(out, "utm"), stations=xy, observations=observations,
                                 catchment=utm + ".shp", plots=False, what="UTM", **{"stations-utm": "60S"})
        assert_that(f"{utm}.shp: declares the projected coordinate system 'WGS 84 / UTM zone 60S', whose eastings "
                    "and northings are made longitude/latitude (UTM zone 60S, WGS84)" in stderr_messages(stderr),
                    f"the UTM catchment: {stderr}")
        want, got = (read_csv(os.path.join(out, d, "areal_mean.csv")) for d in ("lonlat", "utm"))
        assert_same_means(got, want, "the UTM files")
        # A UTM outline of a few vertices (edges of up to 85 km, which bow some 100 m from the lon/lat
        # lines between their ends) is the polygon straight in metres: the means of the same outline
        # cut every 500th of an edge in metres, to 1e-6 (not cutting it moved them by 1e-4).
        corners = [in_utm_60s([ring[:-1]], False)[0] for ring in rings]
        few = write_shapefile("few", [ring + ring[:1] for ring in corners])
        many = write_shapefile("many", [[(a[0] + (b[0] - a[0]) * i / 500, a[1] + (b[1] - a[1]) * i / 500)
                                         for a, b in zip(ring, ring[1:] + ring[:1]) for i in range(500)] + ring[:1]
                                        for ring in corners])
        for name, path in (("few", few), ("many", many)):
            run_colorado(os.path.join(out, name), stations=xy, observations=observations, catchment=path,
                         plots=False, what=name, **{"stations-utm": "60S"})
        coarse, fine = (read_csv(os.path.join(out, name, "areal_mean.csv")) for name in ("few", "many"))
        assert_close(float(fine[0]["areal_mean"]), float(coarse[0]["areal_mean"]), 1e-6 * float(fine[0]["areal_mean"]),
                     "a few vertices in metres against many")
        # Eastings and northings without the zone, a zone that is none, and a northing no zone has
        # are named.
        far = write(out, "far.csv", "station_id,x,y\nN1,400000,4e9\n")
        cases = [({}, xy, f"{xy}: the stations file has columns x and y, not lon and lat: if they are eastings and "
                          "northings of a UTM zone, give the zone with --stations-utm (such as 13N); of another "
                          "projected system, give it with --stations-crs (such as EPSG:5070)"),
                 ({"stations-utm": "61S"}, xy, "--stations-utm '61S': expected a UTM zone 1 to 60 with N or S"),
                 ({"stations-utm": "60S"}, far,
                  f"{far}:2: (400000, 4000000000) is not an easting and northing of a UTM zone")]
        for options, path, message in cases:
            _, stderr = run_colorado(os.path.join(out, "bad"), stations=path, observations=observations,
                                     catchment=catchment, plots=False, status=1, what=message, **options)
            assert_that(message in stderr and "Traceback" not in stderr, f"{message!r} not in {stderr!r}")


# Snyder's ellipsoidal forward formulas for the two conics and the azimuthal equal-area projection
# (Map Projections: A Working Manual, 1987, eqs. 14-12 to 14-19, 15-7 to 15-11 and 24-13 to 24-17),
# on WGS84, as PROJ defines +proj=aea, lcc and laea: written here apart from the script's path,
# which inverts with GeographicLib's and core/lambert_azimuthal_equal_area's.
WGS84_A, WGS84_F = 6378137.0, 1 / 298.257223563
WGS84_E2 = WGS84_F * (2 - WGS84_F)


def snyder_m(p):
    return math.cos(p) / math.sqrt(1 - WGS84_E2 * math.sin(p) ** 2)


def snyder_q(p):
    e, s = math.sqrt(WGS84_E2), math.sin(p)
    return (1 - WGS84_E2) * (s / (1 - WGS84_E2 * s * s) - math.log((1 - e * s) / (1 + e * s)) / (2 * e))


def snyder_laea(lon, lat, lon0, lat0, x0=0.0, y0=0.0):
    """(x, y) in metres of (lon, lat) in PROJ's laea about (lon0, lat0), oblique aspect."""
    qp = snyder_q(math.pi / 2)
    beta, beta0 = (math.asin(snyder_q(math.radians(v)) / qp) for v in (lat, lat0))
    rq = WGS84_A * math.sqrt(qp / 2)
    d = WGS84_A * snyder_m(math.radians(lat0)) / (rq * math.cos(beta0))
    dl = math.radians(lon - lon0)
    b = rq * math.sqrt(2 / (1 + math.sin(beta0) * math.sin(beta) + math.cos(beta0) * math.cos(beta) * math.cos(dl)))
    return (x0 + b * d * math.cos(beta) * math.sin(dl),
            y0 + b / d * (math.cos(beta0) * math.sin(beta) - math.sin(beta0) * math.cos(beta) * math.cos(dl)))


def snyder_mercator(lon, lat, lon0, lat_ts=0.0, x0=0.0, y0=0.0, sphere=False):
    """(x, y) in metres of (lon, lat) in PROJ's merc with these terms, on WGS84, or on the sphere of
    its equatorial radius (the web maps' EPSG:3857)."""
    e2 = 0.0 if sphere else WGS84_E2
    e, s = math.sqrt(e2), math.sin(math.radians(lat))
    k0 = snyder_m(math.radians(lat_ts)) if not sphere else math.cos(math.radians(lat_ts))
    psi = math.asinh(math.tan(math.radians(lat))) - e * math.atanh(e * s)
    return x0 + WGS84_A * k0 * math.radians(lon - lon0), y0 + WGS84_A * k0 * psi


def snyder_conic(kind, lon, lat, lon0, lat0, lat1, lat2, x0=0.0, y0=0.0, k0=1.0):
    """(x, y) in metres of (lon, lat) in PROJ's kind ("aea" or "lcc") with these terms."""
    e = math.sqrt(WGS84_E2)
    m, q = snyder_m, snyder_q

    def t(p):
        s = math.sin(p)
        return math.tan(math.pi / 4 - p / 2) / ((1 - e * s) / (1 + e * s)) ** (e / 2)

    p, p0, p1, p2 = (math.radians(v) for v in (lat, lat0, lat1, lat2))
    if kind == "aea":
        n = (m(p1) ** 2 - m(p2) ** 2) / (q(p2) - q(p1))
        c = m(p1) ** 2 + n * q(p1)
        rho, rho0 = (WGS84_A * math.sqrt(c - n * q(v)) / n for v in (p, p0))
    else:
        n = math.sin(p1) if lat1 == lat2 else (math.log(m(p1) / m(p2)) / math.log(t(p1) / t(p2)))
        f = m(p1) / (n * t(p1) ** n)
        rho, rho0 = (WGS84_A * k0 * f * t(v) ** n for v in (p, p0))
    theta = n * math.radians(lon - lon0)
    return x0 + rho * math.sin(theta), y0 + rho0 - rho * math.cos(theta)


def assert_same_means(got, want, what):
    """Asserts that two areal_mean.csv's rows (read_csv's) are as many, of two steps, with the
    same counts and the same means to 1e-8 (the same data given in another coordinate system)."""
    assert_that(len(got) == len(want) == 2, f"{what}: {got} against {want}")
    for a, b in zip(got, want):
        assert_that((a["stations_used"], a["stations_weighted"]) == (b["stations_used"], b["stations_weighted"]),
                    f"{what}: {a} against {b}")
        assert_close(float(b["areal_mean"]), float(a["areal_mean"]), 1e-8 * float(b["areal_mean"]),
                     f"{what}: the mean {a}")


def utm_of(points, zone=60, north=False):
    """points ((lon, lat)) as eastings and northings of UTM zone 60S (or of another zone and
    hemisphere), by vtkGeographicProjection's UTM path (GeographicLib's)."""
    from tessera import vtkGeographicProjection
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    data, projected = vtkPolyData(), vtkPoints()
    projected.SetDataTypeToDouble()
    for lon, lat in points:
        projected.InsertNextPoint(lon, lat, 0.0)
    data.SetPoints(projected)
    projection = vtkGeographicProjection()
    projection.SetInputData(data)
    projection.SetProjectionToUTM()
    projection.SetUTMZone(zone)
    projection.SetUTMNorth(north)
    projection.Update()
    return [projection.GetOutput().GetPoint(k)[:2] for k in range(len(points))]


def test_catchment_features_without_geometry_or_crossing_holes_are_named_as_such():
    # From a user trial: a feature with a null geometry was left out without a word; a CSV given as
    # the catchment was "no polygon ..., only nothing"; a hole crossing its outline was first
    # warned of as lying outside it (the filter's error, which names the crossing, follows).
    with tempfile.TemporaryDirectory() as out:
        stations = write(out, "st.csv", "station_id,lon,lat\nA,10.25,-0.25\nB,10.75,0.25\n")
        observations = write(out, "obs.csv", "station_id,year,month,precip\nA,2000,1,10\nB,2000,1,20\n")
        square = [[10, -0.5], [11, -0.5], [11, 0.5], [10, 0.5], [10, -0.5]]
        features = [{"type": "Feature", "properties": {"n": 1}, "geometry": {"type": "Polygon", "coordinates": [square]}},
                    {"type": "Feature", "properties": {"n": 2}, "geometry": None}]
        null = write(out, "null.geojson", json.dumps({"type": "FeatureCollection", "features": features}))
        _, stderr = run_colorado(os.path.join(out, "null"), stations=stations, observations=observations,
                                 catchment=null, plots=False, what="a null geometry")
        assert_that("1 feature(s) have no geometry that VTK's GDAL reader reads" in stderr and
                    "the first is feature 1, counted from 0" in stderr, stderr)
        _, stderr = run_colorado(os.path.join(out, "csv"), stations=stations, observations=observations,
                                 catchment=stations, plots=False, status=1, what="a CSV catchment")
        assert_that("found no polygon in the catchment file, no geometry at all" in stderr and
                    "only nothing" not in stderr, stderr)
        crossing = write(out, "crossing.geojson", json.dumps({"type": "Polygon", "coordinates": [
            square, [[10.3, 0.0], [10.6, 0.0], [10.6, -0.6], [10.3, -0.6], [10.3, 0.0]]]}))
        _, stderr = run_colorado(os.path.join(out, "crossing"), stations=stations, observations=observations,
                                 catchment=crossing, plots=False, status=1, what="a crossing hole")
        assert_that("lies outside" not in stderr and "cross (rings may touch" in stderr, stderr)


def test_utm_gauges_across_the_equator_give_the_lon_lat_means():
    # Four gauges about (10.5E, 0) as eastings and northings of zone 32N (negative northings south
    # of the equator) and of 32S (northings above 10,000,000 m north of it), as GDAL and PROJ write
    # them: the means of the lon/lat file. A northing beyond the zone's grid is still named.
    with tempfile.TemporaryDirectory() as out:
        places = {"A": (10.25, -0.25), "B": (10.75, -0.25), "C": (10.75, 0.25), "D": (10.25, 0.35)}
        lonlat = write(out, "lonlat.csv", "station_id,lon,lat\n" + "".join(
            f"{s},{lon},{lat}\n" for s, (lon, lat) in places.items()))
        observations = write(out, "obs.csv", "station_id,year,month,precip\nA,2000,1,10\nB,2000,1,20\n"
                             "C,2000,1,30\nD,2000,1,40\nA,2000,2,10\nB,2000,2,20\nC,2000,2,30\n")
        catchment = write(out, "square.geojson", json.dumps({"type": "Polygon", "coordinates": [
            [[10, -0.5], [11, -0.5], [11, 0.5], [10, 0.5], [10, -0.5]]]}))
        run_colorado(os.path.join(out, "lonlat"), stations=lonlat, observations=observations,
                     catchment=catchment, plots=False, what="lon/lat")
        want = read_csv(os.path.join(out, "lonlat", "areal_mean.csv"))
        for zone, north in (("32N", True), ("32S", False)):
            xy = utm_of(list(places.values()), 32, north)
            assert_that(min(y for _, y in xy) < 0 if north else max(y for _, y in xy) > 1e7, f"{zone}: {xy}")
            path = write(out, f"{zone}.csv", "station_id,x,y\n" + "".join(
                f"{s},{x!r},{y!r}\n" for s, (x, y) in zip(places, xy)))
            run_colorado(os.path.join(out, zone), stations=path, observations=observations, catchment=catchment,
                         plots=False, what=zone, **{"stations-utm": zone})
            assert_same_means(read_csv(os.path.join(out, zone, "areal_mean.csv")), want, zone)
        far = write(out, "far.csv", "station_id,x,y\nA,600000,-9200000\n")
        _, stderr = run_colorado(os.path.join(out, "far"), stations=far, observations=observations,
                                 catchment=catchment, plots=False, status=1, what="far", **{"stations-utm": "32N"})
        message = f"{far}:2: (600000, -9200000) is not an easting and northing of a UTM zone"
        assert_that(message in stderr and "Traceback" not in stderr, f"{message!r} not in {stderr!r}")


def geopackage_of(path, layers):
    """Writes a GeoPackage (OGC 12-128r18: an SQLite file with its three tables and a table per
    layer) at path. layers: (name, WKT of its system, "POLYGON" or "POINT", geometries: lists of
    rings, lists of (x, y) each with the first point repeated last, or (x, y) points, or
    (station_id, (x, y)) pairs for points with a station_id attribute; a geometry None is NULL)."""
    import sqlite3
    import struct

    def wkb(kind, geometry):
        if kind == "POINT":
            return struct.pack("<BIdd", 1, 1, *geometry)
        body = b"".join(struct.pack("<I", len(ring)) + b"".join(struct.pack("<dd", *p) for p in ring)
                        for ring in geometry)
        return struct.pack("<BII", 1, 3, len(geometry)) + body

    db = sqlite3.connect(path)
    db.execute("PRAGMA application_id = 1196444487")  # 'GPKG'
    db.execute("PRAGMA user_version = 10200")
    db.execute("CREATE TABLE gpkg_spatial_ref_sys (srs_name TEXT NOT NULL, srs_id INTEGER PRIMARY KEY, "
               "organization TEXT NOT NULL, organization_coordsys_id INTEGER NOT NULL, definition TEXT NOT NULL, "
               "description TEXT)")
    db.execute("CREATE TABLE gpkg_contents (table_name TEXT PRIMARY KEY, data_type TEXT NOT NULL, identifier TEXT, "
               "description TEXT DEFAULT '', last_change DATETIME NOT NULL DEFAULT "
               "(strftime('%Y-%m-%dT%H:%M:%fZ','now')), min_x DOUBLE, min_y DOUBLE, max_x DOUBLE, max_y DOUBLE, "
               "srs_id INTEGER)")
    db.execute("CREATE TABLE gpkg_geometry_columns (table_name TEXT NOT NULL, column_name TEXT NOT NULL, "
               "geometry_type_name TEXT NOT NULL, srs_id INTEGER NOT NULL, z TINYINT NOT NULL, m TINYINT NOT NULL)")
    db.execute("INSERT INTO gpkg_spatial_ref_sys VALUES ('Undefined cartesian SRS', -1, 'NONE', -1, 'undefined', "
               "''), ('Undefined geographic SRS', 0, 'NONE', 0, 'undefined', '')")
    for srs, (name, wkt, kind, geometries) in enumerate(layers, start=100000):
        db.execute("INSERT INTO gpkg_spatial_ref_sys VALUES (?, ?, 'NONE', ?, ?, '')", (name, srs, srs, wkt))
        named = kind == "POINT" and geometries and isinstance(geometries[0][0], str)
        db.execute(f"CREATE TABLE {name} (fid INTEGER PRIMARY KEY AUTOINCREMENT, geom {kind}"
                   + (", station_id TEXT)" if named else ")"))
        db.execute("INSERT INTO gpkg_contents (table_name, data_type, identifier, srs_id) VALUES (?, 'features', ?, ?)",
                   (name, name, srs))
        db.execute("INSERT INTO gpkg_geometry_columns VALUES (?, 'geom', ?, ?, 0, 0)", (name, kind, srs))
        for geometry in geometries:  # (the header: magic, version 0, flags: little-endian, no envelope; srs)
            station, geometry = geometry if named else (None, geometry)
            blob = None if geometry is None else b"GP\x00\x01" + struct.pack("<i", srs) + wkb(kind, geometry)
            db.execute(f"INSERT INTO {name} (geom{', station_id' if named else ''}) VALUES (?{', ?' if named else ''})",
                       (blob,) + ((station,) if named else ()))
    db.commit()
    db.close()
    return path


def test_catchment_geopackage_in_metres_beside_a_layer_of_lon_lat_points():
    # A GeoPackage whose catchment layer is in metres (of an Albers conic, of UTM 60S) and which
    # also holds the gauges as a layer of points in lon/lat (as a GIS project is often saved): the
    # points layer adds no ring, so its system is not the catchment's, it is left out (and said)
    # before the metres are made lon/lat, and the run gives the lon/lat files' means to 1e-8. It
    # was refused, told at once that the metres were read as lon/lat and that they looked
    # projected; then, in UTM, its lon/lat points were refused as UTM points no place projects to.
    wgs84 = ('GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],PRIMEM["Greenwich",0],'
             'UNIT["degree",0.0174532925199433]]')
    systems = {
        "lake_aea": ('PROJECTION["Albers_Conic_Equal_Area"],PARAMETER["latitude_of_center",-39],PARAMETER['
                     '"longitude_of_center",176],PARAMETER["standard_parallel_1",-38],PARAMETER["standard_parallel_2",'
                     '-40],PARAMETER["false_easting",1000000],PARAMETER["false_northing",2000000]',
                     lambda ring: [snyder_conic("aea", x, y, 176, -39, -38, -40, 1e6, 2e6) for x, y in ring]),
        "lake_utm": ('PROJECTION["Transverse_Mercator"],PARAMETER["latitude_of_origin",0],PARAMETER['
                     '"central_meridian",177],PARAMETER["scale_factor",0.9996],PARAMETER["false_easting",500000],'
                     'PARAMETER["false_northing",10000000]', utm_of)}
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        run_colorado(os.path.join(out, "lonlat"), stations=stations, observations=observations, plots=False,
                     what="lon/lat", catchment=write_lake_basin_cut(out))
        want = read_csv(os.path.join(out, "lonlat", "areal_mean.csv"))
        for system, (terms, forward) in systems.items():
            wkt = f'PROJCS["{system}",{wgs84},{terms},UNIT["metre",1]]'
            basin = ("basin", wkt, "POLYGON", [[forward(ring) for ring in lake_rings_cut()]])
            for name, layers in (("alone", [basin]),
                                 ("beside_points", [basin, ("gauges", wgs84, "POINT", list(LAKE_GAUGES.values()))])):
                path = geopackage_of(os.path.join(out, f"{system}_{name}.gpkg"), layers)
                _, stderr = run_colorado(os.path.join(out, f"{system}_{name}"), stations=stations,
                                         observations=observations, catchment=path, plots=False, what=name)
                said = [m for m in stderr_messages(stderr) if m.startswith(f"{path}: ")]
                assert_that(f"{path}: declares the projected coordinate system '{system}', whose eastings and "
                            "northings are made longitude/latitude" in " ".join(said) and
                            (f"{path}: 6 feature(s) of points are not polygons, and are left out of the catchment"
                             in said) == (name == "beside_points") and len(said) == 1 + (name == "beside_points"),
                            f"{system}, {name}: {stderr}")
                assert_same_means(read_csv(os.path.join(out, f"{system}_{name}", "areal_mean.csv")), want,
                                  f"{system}, {name}")
        # The gauges of such a file, with their ids, read from it too: its layer of points is the
        # gauges, the catchment's layer is left out of them (and said); it ended the run, its
        # polygon "not one point".
        wkt = f'PROJCS["lake_aea",{wgs84},{systems["lake_aea"][0]},UNIT["metre",1]]'
        both = geopackage_of(os.path.join(out, "both.gpkg"), [
            ("basin", wkt, "POLYGON", [[systems["lake_aea"][1](ring) for ring in lake_rings_cut()]]),
            ("gauges", wgs84, "POINT", list(LAKE_GAUGES.items()))])
        _, stderr = run_colorado(os.path.join(out, "both"), stations=both, observations=observations, catchment=both,
                                 plots=False, what="both")
        said = f"note: {both}: the gauges are its 6 feature(s) of points; its other layers' 1 feature(s) (1; counted from 1)"
        assert_that(said in stderr and "not one point" not in stderr, f"{stderr}")
        assert_same_means(read_csv(os.path.join(out, "both", "areal_mean.csv")), want, "gauges and basin in one file")
        # Its gauges are named by their feature numbers in the whole file (the basin is feature 1):
        # a gauge 9e7 m off is feature 4, and a gauge without a geometry in the layer of points is
        # named too, not taken for another layer's feature.
        far = dict(LAKE_GAUGES, N3=(175.95, 8e2))
        for name, gauges, fragment in (
                ("far", list(far.items()), "feature 4 (counted from 1): "),
                ("null", list(LAKE_GAUGES.items()) + [("N7", None)], "feature 8 is not one point")):
            bad = geopackage_of(os.path.join(out, f"{name}.gpkg"), [
                ("basin", wkt, "POLYGON", [[systems["lake_aea"][1](ring) for ring in lake_rings_cut()]]),
                ("gauges", wgs84, "POINT", gauges)])
            _, stderr = run_colorado(os.path.join(out, name), stations=bad, observations=observations, catchment=bad,
                                     plots=False, what=name, status=1)
            assert_that(f"{bad}: {fragment}" in stderr, f"{name}: {stderr}")


def test_catchments_and_gauges_in_projected_systems_give_the_lon_lat_means():
    # The lake basin (its edges cut every 0.001 degrees in lon/lat) and its gauges given in three
    # projected systems: a southern Albers conic, a Lambert conic in US feet with false origins
    # (Snyder's formulas above) and a transverse Mercator with a latitude of origin, scale and
    # false origins (from UTM 60S's eastings and northings, by the filter's UTM path), and a Lambert
    # azimuthal equal-area projection about the basin (Snyder's formulas) with the gauges in LAEA
    # Europe (EPSG:3035, looked up by GDAL: the basin lies some 164 degrees from its centre), and
    # the web maps' Mercator (EPSG:3857) with the gauges in an ellipsoid's Mercator. Catchment
    # (a GeoJSON "crs" of PROJ terms, a shapefile's ESRI .prj) and gauges (--stations-crs) each
    # in another system than the other: every run gives the lon/lat files' counts and means to
    # 1e-8. The gauges in UTM 60S given as --stations-crs EPSG:32760 do too. A system that is not
    # read, a sphere's, an EPSG code GDAL does not know and both station options end the run naming
    # them.
    us_foot = 1200 / 3937
    origin_utm = utm_of([(177.0, -39.0)])[0]
    systems = {
        "aea": ("+proj=aea +lat_0=-39 +lon_0=176 +lat_1=-38 +lat_2=-40 +x_0=1000000 +y_0=2000000 +datum=WGS84 +units=m",
                lambda ps: [snyder_conic("aea", x, y, 176, -39, -38, -40, 1e6, 2e6) for x, y in ps]),
        "lcc": ("+proj=lcc +lat_0=-41 +lon_0=175 +lat_1=-37.5 +lat_2=-40.5 +x_0=2510000 +y_0=6023150 +datum=WGS84 "
                "+units=us-ft",
                lambda ps: [tuple(v / us_foot for v in snyder_conic("lcc", x, y, 175, -41, -37.5, -40.5, 2510000,
                                                                    6023150)) for x, y in ps]),
        "tmerc": ("+proj=tmerc +lat_0=-39 +lon_0=177 +k=0.9996 +x_0=1600000 +y_0=800000 +datum=WGS84 +units=m",
                  lambda ps: [(x - 500000 + 1600000, y - origin_utm[1] + 800000) for x, y in utm_of(ps)]),
        "laea": ("+proj=laea +lat_0=-40 +lon_0=176 +x_0=500000 +y_0=700000 +datum=WGS84 +units=m",
                 lambda ps: [snyder_laea(x, y, 176, -40, 500000, 700000) for x, y in ps]),
        "EPSG:3035": ("EPSG:3035", lambda ps: [snyder_laea(x, y, 10, 52, 4321000, 3210000) for x, y in ps]),
        "EPSG:3857": ("EPSG:3857", lambda ps: [snyder_mercator(x, y, 0, sphere=True) for x, y in ps]),
        "merc": ("+proj=merc +lon_0=170 +lat_ts=-30 +x_0=100000 +y_0=200000 +datum=WGS84 +units=m",
                 lambda ps: [snyder_mercator(x, y, 170, -30, 100000, 200000) for x, y in ps]),
        # (about the basin's corner itself, without a false origin: that vertex is at 0, 0)
        "laea_corner": ("+proj=laea +lat_0=-39.2 +lon_0=175.5 +datum=WGS84 +units=m",
                        lambda ps: [snyder_laea(x, y, 175.5, -39.2) for x, y in ps])}
    lcc_prj = ('PROJCS["lake_lcc",GEOGCS["GCS_WGS_1984",DATUM["D_WGS_1984",SPHEROID["WGS_1984",6378137.0,'
               '298.257223563]],PRIMEM["Greenwich",0.0],UNIT["Degree",0.0174532925199433]],PROJECTION['
               f'"Lambert_Conformal_Conic"],PARAMETER["False_Easting",{2510000 / us_foot!r}],PARAMETER['
               f'"False_Northing",{6023150 / us_foot!r}],PARAMETER["Central_Meridian",175.0],PARAMETER['
               '"Standard_Parallel_1",-37.5],PARAMETER["Standard_Parallel_2",-40.5],PARAMETER["Latitude_Of_Origin",'
               '-41.0],UNIT["Foot_US",0.3048006096012192]]')

    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        rings = lake_rings_cut()
        cut = json.loads(json.dumps(LAKE_BASIN))
        cut["features"][0]["geometry"]["coordinates"] = rings
        run_colorado(os.path.join(out, "lonlat"), stations=stations, observations=observations,
                     catchment=write_lake_basin_cut(out), plots=False, what="lon/lat")
        want = read_csv(os.path.join(out, "lonlat", "areal_mean.csv"))

        def catchment_in(name):
            terms, forward = systems[name]
            if name == "lcc":  # (a shapefile whose .prj gives the system in ESRI's words)
                shp, shx = shapefile_of([forward(ring) for ring in rings])
                for extension, data in ((".shp", shp), (".shx", shx), (".prj", lcc_prj.encode())):
                    with open(os.path.join(out, "basin_lcc" + extension), "wb") as f:
                        f.write(data)
                return os.path.join(out, "basin_lcc.shp")
            declared = json.loads(json.dumps(cut))
            declared["crs"] = {"type": "name", "properties": {"name": terms}}
            declared["features"][0]["geometry"]["coordinates"] = [[list(p) for p in forward(ring)] for ring in rings]
            return write(out, f"basin_{name.replace(':', '_')}.geojson", json.dumps(declared))

        def stations_in(forward, name):
            xy = forward(list(LAKE_GAUGES.values()))
            return write(out, f"stations_{name}.csv", "station_id,x,y\n" + "".join(
                f"{s},{x!r},{y!r}\n" for s, (x, y) in zip(LAKE_GAUGES, xy)))

        runs = [(c, systems[g][0], stations_in(systems[g][1], g.replace(":", "_"))) for c, g in
                (("aea", "lcc"), ("lcc", "tmerc"), ("tmerc", "aea"), ("laea", "EPSG:3035"), ("EPSG:3857", "merc"),
                 ("laea_corner", "aea"))]
        utm_xy = stations_in(utm_of, "utm")
        runs.append(("aea", "EPSG:32760", utm_xy))
        for name, crs, xy in runs:
            path = catchment_in(name)
            folder = os.path.join(out, name.replace(":", "_"))
            _, stderr = run_colorado(folder, stations=xy, observations=observations, catchment=path,
                                     plots=False, what=f"{name} with stations in {crs}", **{"stations-crs": crs})
            assert_that(any(m.startswith(f"{path}: declares the projected coordinate system ") and
                            "whose eastings and northings are made longitude/latitude" in m
                            for m in stderr_messages(stderr)), f"{name}: {stderr}")
            assert_same_means(read_csv(os.path.join(folder, "areal_mean.csv")), want, f"{name}, {crs}")
        # A system on another ellipsoid is read, and said to leave the datum shift.
        airy = systems["tmerc"][0].replace("+datum=WGS84", "+ellps=airy")
        _, stderr = run_colorado(os.path.join(out, "airy"), stations=runs[1][2], observations=observations,
                                 catchment=catchment, plots=False, what="airy", **{"stations-crs": airy})
        assert_that(f"--stations-crs {airy!r}: the ellipsoid airy; the gauges' x, y are made longitude/latitude on "
                    "WGS84's, without the datum shift" in stderr, f"airy: {stderr}")
        eqc = dict(LAKE_BASIN, crs={"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::4087"}})
        eqc["features"] = json.loads(json.dumps(cut["features"]))
        eqc["features"][0]["geometry"]["coordinates"] = [[[x * 1e4, y * 1e4] for x, y in r] for r in rings]
        eqc_path = write(out, "eqc.geojson", json.dumps(eqc))
        xy = runs[0][2]
        typo = write(out, "typo.csv", "station_id,x,y\nN1,1000000,2000000\nN2,-1e9,2000000\n")
        # A UTM zone without N or S is read as north, and said.
        _, stderr = run_colorado(os.path.join(out, "north"), stations=utm_xy, observations=observations,
                                 catchment=catchment, plots=False, what="--stations-utm 60", **{"stations-utm": "60"})
        assert_that("--stations-utm 60: read as zone 60N, in the northern hemisphere (give 60S for the southern)"
                    in stderr, f"--stations-utm 60: {stderr}")
        # An EPSG code as it is written elsewhere: the same means as EPSG:CODE, bit for bit.
        for code in ("EPSG:32760", "epsg: 32760", "32760", "urn:ogc:def:crs:EPSG::32760"):
            run_colorado(os.path.join(out, code.replace(":", "_")), stations=utm_xy, observations=observations,
                         catchment=catchment, plots=False, what=code, **{"stations-crs": code})
        spelt = [read_csv(os.path.join(out, code.replace(":", "_"), "areal_mean.csv"))
                 for code in ("EPSG:32760", "epsg: 32760", "32760", "urn:ogc:def:crs:EPSG::32760")]
        assert_that(len(spelt[0]) == 2 and all(got == spelt[0] for got in spelt), f"EPSG codes: {spelt}")
        sphere = systems["laea"][0].replace("+datum=WGS84", "+R=6371007")
        rim = write(out, "rim.csv", "station_id,x,y\nN1,4321000,3210000\nN2,30000000,3210000\n")
        # PROJ terms read as PROJ reads them: +units before +to_meter (+to_meter was taken: 6.6 times
        # off); a Mercator's +lat_ts in place of +k (they were multiplied), laea and webmerc without
        # +k; +a alone, +es=0 and +R_A are spheres, and a Mercator on WGS84's radius is the web's.
        system = import_example("projected_input").proj4_system
        assert_that(system("+proj=tmerc +lon_0=177 +units=ft +to_meter=2").metres == 0.3048, "+units, +to_meter")
        e2 = (2 - 1 / 298.257223563) / 298.257223563  # WGS84's first eccentricity squared
        true_scale = math.cos(math.radians(30)) / math.sqrt(1 - e2 * math.sin(math.radians(30)) ** 2)
        assert_close(system("+proj=merc +lat_ts=30 +k=0.5 +datum=WGS84").k0, true_scale, 1e-12, "+lat_ts, +k")
        assert_that(system("+proj=laea +lat_0=52 +k=0.5 +datum=WGS84").k0 == 1.0, "laea's +k")
        assert_that(system("+proj=aea +lat_1=29.5 +lat_2=45.5 +k_0=0.9 +datum=WGS84").k0 == 1.0, "aea's +k_0")
        # +axis: a file's (3, 4) as eastings and northings (westings and southings; northings first), and back;
        # +pm: +lon_0 counted from the prime meridian.
        for axis, grid in (("enu", (3, 4)), ("wsu", (-3, -4)), ("neu", (4, 3)), ("nwu", (-4, 3)), ("swu", (-4, -3))):
            plane = system(f"+proj=tmerc +lon_0=10 +axis={axis} +units=km +datum=WGS84")
            moved = plane.to_grid(3.0, 4.0)
            assert_that(moved == (grid[0] * 1e3, grid[1] * 1e3) and plane.from_grid(*moved) == (3.0, 4.0),
                        f"+axis={axis}: {moved}, back {plane.from_grid(*moved)}")
        assert_close(system("+proj=tmerc +lon_0=1 +pm=paris +ellps=WGS84").lon0, 3.337229166667, 1e-12, "+pm")
        assert_close(system("+proj=tmerc +lon_0=1 +pm=-3.5 +ellps=WGS84").lon0, -2.5, 1e-12, "+pm in degrees")
        # Datums as GDAL's WKT names them: those PROJ takes as WGS84 are not warned of, older and shifted ones are.
        other_datum = import_example("projected_input").other_datum
        for datum, ellipsoid, warned in (("SWEREF99", "GRS 1980\",6378137", False),
                                         ("Mexico_ITRF2008", "GRS 1980\",6378137", False),
                                         ("Geocentric_datum_of_Korea", "GRS 1980\",6378137", False),
                                         ("D_North_American_1983", "GRS_1980\",6378137", False),
                                         ("Israel_1993", "GRS 1980\",6378137", True),
                                         ("CH1903+", "Bessel 1841\",6377397.155", True),
                                         ("Amersfoort", "Bessel 1841\",6377397.155", True)):
            said = other_datum(f'GEOGCS["x",DATUM["{datum}",SPHEROID["{ellipsoid},298.25]]]')
            assert_that(bool(said) == warned and (not said or datum in said), f"datum {datum}: {said!r}")
        assert_that(system("+proj=webmerc +k=0.5 +lat_ts=30").k0 == 1.0, "webmerc's +k and +lat_ts")
        for terms in ("+proj=laea +lat_0=52 +a=6378137", "+proj=aea +a=6371000 +es=0", "+proj=laea +R_A +ellps=GRS80"):
            assert_that("a projection of the sphere" in system(terms), f"{terms}: {system(terms)}")
        assert_that(system("+proj=merc +a=6378137").kind == "webmerc", "+proj=merc +a=6378137")
        cases = [({"catchment": catchment, "stations": xy, "stations-crs": "+proj=laea +lat_0=95"},
                  "--stations-crs '+proj=laea +lat_0=95': +lat_0=95, which is not a latitude (within 90)"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": "+proj=merc +lat_ts=90"},
                  "--stations-crs '+proj=merc +lat_ts=90': +lat_ts=90, where a Mercator's scale is 0"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": "EPSG:2163"},
                  "--stations-crs 'EPSG:2163': GDAL gives another system in its place, EPSG:9311 ('NAD27 / US "
                  "National Atlas Equal Area'), as it does for a deprecated code"),
                 ({"catchment": catchment, "stations": rim, "stations-crs": "EPSG:3035"},
                  f"{rim}:3: as LambertAzimuthalEqualArea lon_0=10 lat_0=52 x_0=4321000 y_0=3210000, WGS84: the point "
                  "(30000000, 3210000) has no inverse"),
                 ({"catchment": eqc_path, "stations": stations},
                  f"{eqc_path}: declares a projected coordinate system with the projection +proj=eqc (read here: "
                  "UTM, transverse Mercator (tmerc), Albers equal-area (aea), Lambert conformal conic (lcc), "
                  "Lambert azimuthal equal-area (laea) and Mercator (merc, and the web maps' EPSG:3857)); its "
                  "coordinates are metres"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": sphere},
                  f"--stations-crs {sphere!r}: not read here: +R=6371007: a projection of the sphere, whose inverse differs from the "
                  "ellipsoid's by up to kilometres"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": "EPSG:99999"},
                  "--stations-crs 'EPSG:99999': GDAL's database has no such EPSG code"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": "+proj=lcc +lat_1=north"},
                  "--stations-crs '+proj=lcc +lat_1=north': +lat_1=north, which is not a number"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": "EPSG:4326"},
                  "--stations-crs 'EPSG:4326': a geographic system (longitude/latitude)"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": "EPSG:32760", "stations-utm": "60S"},
                  "--stations-utm and --stations-crs: give one of them"),
                 ({"catchment": catchment, "stations": xy, "stations-crs": "proj=tmerc lon_0=173"},
                  "--stations-crs 'proj=tmerc lon_0=173': expected EPSG:CODE (such as EPSG:5070) or PROJ terms "
                  "starting +proj="),
                 ({"catchment": catchment, "stations": typo, "stations-crs": systems["aea"][0]},
                  f"{typo}:3: as AlbersEqualArea lon_0=176 lat_0=-39 lat_1=-38 lat_2=-40 x_0=1000000 y_0=2000000, "
                  "WGS84: a point 1e+09 m from the projection's origin, beyond any place on the Earth")]
        for options, message in cases:
            _, stderr = run_colorado(os.path.join(out, "bad"), observations=observations, plots=False, status=1,
                                     what=message, **options)
            assert_that(message in stderr and "Traceback" not in stderr and "ERROR 1" not in stderr,
                        f"{message!r} not in {stderr!r}")


def test_a_plain_id_or_site_no_column_is_the_station_id_where_no_station_column_is():
    # A CSV of gauges (id, lon, lat) or observations (site_no, date, precip) names its stations by
    # the names a GIS file's gauges are read by: the first of site_no and (in a stations file) id
    # it has, said, where it has no station_id or station column; the same means as with
    # station_id. A file with station beside a row id reads station; two columns of one name in
    # two cases are refused.
    import itertools

    with tempfile.TemporaryDirectory() as out:
        catchment, _, _ = write_lake_basin(out)
        days = ("2001-01-01", "2001-01-02")
        rows = [(s, d, round(1.5 * k + 0.7 * j, 2)) for (k, s), (j, d)
                in itertools.product(enumerate(LAKE_GAUGES), enumerate(days))]
        stations = os.path.join(out, "stations.csv")
        write_stations(stations, LAKE_GAUGES)
        plain = write(out, "plain.csv", "station_id,date,precip\n" + "".join(f"{s},{d},{v}\n" for s, d, v in rows))
        ids = write(out, "ids.csv", "id,lon,lat\n" + "".join(f"{s},{lon},{lat}\n" for s, (lon, lat) in LAKE_GAUGES.items()))
        site = write(out, "site.csv", "ID,site_no,date,precip\n" + "".join(
            f"{k},{s},{d},{v}\n" for k, (s, d, v) in enumerate(rows)))
        both = write(out, "both.csv", "id,station,lon,lat\n" + "".join(
            f"{k},{s},{lon},{lat}\n" for k, (s, (lon, lat)) in enumerate(LAKE_GAUGES.items())))
        run_colorado(os.path.join(out, "plain"), stations=stations, observations=plain, catchment=catchment,
                     plots=False, what="station_id columns")
        _, stderr = run_colorado(os.path.join(out, "ids"), stations=ids, observations=site, catchment=catchment,
                                 plots=False, what="id and site_no columns")
        for message in (f"{ids}: reads column 'id' as 'station_id'", f"{site}: reads column 'site_no' as 'station_id'"):
            assert_that(message in stderr, f"{message!r} not in {stderr!r}")
        run_colorado(os.path.join(out, "both"), stations=both, observations=plain, catchment=catchment,
                     plots=False, what="a row id beside station")
        want = read_csv(os.path.join(out, "plain", "areal_mean.csv"))
        for name in ("ids", "both"):
            got = read_csv(os.path.join(out, name, "areal_mean.csv"))
            assert_that(got == want and len(got) == len(days), f"{name}: {got} against {want}")
        twice = write(out, "twice.csv", "id,ID,lon,lat\nN1,N1,175.6,-39.1\n")
        _, stderr = run_colorado(os.path.join(out, "twice"), stations=twice, observations=plain, catchment=catchment,
                                 plots=False, status=1, what="id twice")
        assert_that(f"{twice}:1: columns 'id', 'ID' could each be 'station_id'" in stderr, f"{stderr}")
        # In observations an id is as likely a row's number: not read as the station, and the
        # message names the names that are.
        numbered = write(out, "numbered.csv", "id,gauge,date,precip\n" + "".join(
            f"{k + 1},{s},{d},{v}\n" for k, (s, d, v) in enumerate(rows)))
        _, stderr = run_colorado(os.path.join(out, "numbered"), stations=ids, observations=numbered,
                                 catchment=catchment, plots=False, status=1, what="a row number id")
        assert_that(f"{numbered}: the observations file has no column 'station_id'" in stderr
                    and "station_id may be named station, site_no)" in stderr, f"{stderr}")


def test_a_long_files_unnamed_columns_are_named_as_not_read():
    # A long file written by pandas with its index (a first column without a name) was read
    # without a word, where a wide file's is named: a note names it, and the means are those of
    # the file without it; a file whose columns all have names gets no such note.
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        with open(observations) as f:
            lines = f.read().splitlines()
        indexed = write(out, "indexed.csv", "".join(f"{'' if k == 0 else k - 1},{line}\n" for k, line in enumerate(lines)))
        means = []
        for path in (observations, indexed):
            _, stderr = run_colorado(path + ".out", stations=stations,
                                     observations=path, catchment=catchment, plots=False, what=path)
            notes = [line for line in stderr_messages(stderr) if "no name (a row index" in line]
            expected = [] if path == observations else [
                f"note: {indexed}: column 1 has no name (a row index, or a separator ending each line?) and "
                "is not read"]
            assert_that(notes == expected, f"{path}: {stderr}")
            means.append(open(os.path.join(path + ".out", "areal_mean.csv")).read())
        assert_that(means[0] == means[1], f"the means with and without the index: {means}")


def test_a_noaa_climate_data_online_file_is_both_stations_and_observations():
    # NOAA's Climate Data Online CSV: a row per station and day, the station's place on each,
    # columns STATION, NAME (with commas, quoted), LATITUDE, LONGITUDE, ELEVATION, DATE, PRCP and
    # PRCP_ATTRIBUTES (MFLAG,QFLAG,SFLAG,OBSTIME). Given as --observations alone, it is the
    # stations file too: one gauge per station, the columns said to be read under their names,
    # the flagged value named (and used), and the same means, bit for bit, as a plain stations
    # file and observations file of the same values; a row without its station's place takes the
    # station's other rows'. A station at two places or at none, and two columns that could each
    # be lon, end the run naming them.
    import gzip
    import itertools

    with tempfile.TemporaryDirectory() as out:
        catchment, _, _ = write_lake_basin(out)
        gauges = {s: p for s, p in LAKE_GAUGES.items() if s != "N6"}
        days = ("2001-01-01", "2001-01-02", "2001-01-03")
        value = {(s, d): round(1.5 * k + 0.7 * j, 2) for k, s in enumerate(gauges) for j, d in enumerate(days)}
        value[("N2", days[1])] = None  # (an empty PRCP)
        header = '"STATION","NAME","LATITUDE","LONGITUDE","ELEVATION","DATE","PRCP","PRCP_ATTRIBUTES"\n'
        lines = [f'"{s}","{s} GAUGE, NZ","{lat}","{lon}","12.5","{d}","{"" if value[s, d] is None else value[s, d]}",'
                 f'"{",I,7,0700" if (s, d) == ("N3", days[2]) else ",,7,0700"}"\n'
                 for (s, (lon, lat)), d in itertools.product(gauges.items(), days)]
        noaa = write(out, "noaa.csv", header + "".join(lines))
        flagged_line = 2 + list(itertools.product(gauges, days)).index(("N3", days[2]))
        _, stderr = run_colorado(os.path.join(out, "noaa"), observations=noaa, catchment=catchment, plots=False,
                                 what="the NOAA file")
        said = stderr_messages(stderr)
        for message in (f"{noaa}: reads column 'STATION' as 'station_id', 'LONGITUDE' as 'lon', 'LATITUDE' as 'lat'",
                        f"{noaa}: reads column 'STATION' as 'station_id', 'PRCP' as 'precip'",
                        f"{noaa}: 1 observation(s) have a NOAA quality flag (QFLAG, the second field of "
                        f"PRCP_ATTRIBUTES: the value failed a quality check) and are used as given (--drop-flagged "
                        f"leaves them out): line {flagged_line} (I)"):
            assert_that(any(m.startswith(message) for m in said), f"{message!r} not in {said}")
        assert_that(f"read {len(gauges)} gauges and {len(lines)} observations" in stderr, f"{stderr}")
        stations = os.path.join(out, "stations.csv")
        write_stations(stations, gauges)
        plain = write(out, "plain.csv", "station_id,date,precip\n" + "".join(
            f"{s},{d},{'' if value[s, d] is None else value[s, d]}\n" for s, d in itertools.product(gauges, days)))
        run_colorado(os.path.join(out, "plain"), stations=stations, observations=plain, catchment=catchment,
                     plots=False, what="the plain files")
        # The file gzipped, as a large one is kept: the same (its header is read decompressed).
        with open(noaa, "rb") as f, gzip.open(noaa + ".gz", "wb") as z:
            z.write(f.read())
        run_colorado(os.path.join(out, "gz"), observations=noaa + ".gz", catchment=catchment, plots=False,
                     what="the NOAA file gzipped")
        got, zipped, want = (read_csv(os.path.join(out, d, "areal_mean.csv")) for d in ("noaa", "gz", "plain"))
        assert_that(got == want == zipped and len(got) == len(days), f"the NOAA file's means {got} against {want}")
        # --drop-flagged: the flagged value read as missing, as a plain file without it gives, and
        # listed as unused with its flag.
        _, stderr = run_colorado(os.path.join(out, "dropped"), "--drop-flagged", observations=noaa, catchment=catchment,
                                 plots=False, what="--drop-flagged")
        assert_that(f"and are left out, read as missing (--drop-flagged; unused_inputs.csv lists them): line "
                    f"{flagged_line} (I)" in stderr, f"--drop-flagged: {stderr}")
        _, stderr = run_colorado(os.path.join(out, "before"), "--drop-flagged", observations=noaa, catchment=catchment,
                                 plots=False, what="--end before the flagged day", end=days[1])
        assert_that("quality flag" not in stderr, f"the flagged value outside --end is named: {stderr}")
        value[("N3", days[2])] = None
        blank = write(out, "blank.csv", "station_id,date,precip\n" + "".join(
            f"{s},{d},{'' if value[s, d] is None else value[s, d]}\n" for s, d in itertools.product(gauges, days)))
        run_colorado(os.path.join(out, "blank"), stations=stations, observations=blank, catchment=catchment,
                     plots=False, what="the plain file without the flagged value")
        got, want = (read_csv(os.path.join(out, d, "areal_mean.csv")) for d in ("dropped", "blank"))
        assert_that(got == want and got[2] != zipped[2], f"--drop-flagged's means {got} against {want}")
        unused = [r for r in read_csv(os.path.join(out, "dropped", "unused_inputs.csv")) if "quality flag" in r["kind"]]
        assert_that(unused == [{"kind": "observation with a NOAA quality flag (left out: --drop-flagged)", "file": noaa,
                                "line": str(flagged_line), "station_id": "N3", "note": "QFLAG I"}], f"{unused}")
        # --drop-flagged with a file without NOAA's flags says so; a file of observations without
        # places, given without --stations, is said to leave the Colorado gauges.
        _, stderr = run_colorado(os.path.join(out, "noflags"), "--drop-flagged", stations=stations, observations=plain,
                                 catchment=catchment, plots=False, what="--drop-flagged without flags")
        assert_that(f"{plain}: --drop-flagged: the file has no PRCP_ATTRIBUTES column" in stderr, f"{stderr}")
        _, stderr = run_colorado(os.path.join(out, "nostations"), observations=plain, catchment=catchment, plots=False,
                                 status=1, what="no --stations")
        assert_that("note: without --stations, the gauges are the Colorado example's" in stderr
                    and f"{plain} has no place columns" in stderr, f"no --stations: {stderr}")
        # Own gauges without --catchment: an error before the work (a trial's Oregon gauges were
        # averaged over Colorado with no word but "none inside", a later one's with a note and status 0).
        _, stderr = run_colorado(os.path.join(out, "nocatchment"), stations=stations, observations=plain, plots=False,
                                 catchment=None, status=1, what="no --catchment")
        assert_that(f"--catchment: not given, and the gauges ({stations}) are not the Colorado example's" in stderr
                    and not os.path.exists(os.path.join(out, "nocatchment")),
                    f"no --catchment: {stderr}")
        # (said before --out is made or checked: a file as --out is not named first)
        a_file = write(out, "a_file.txt", "not a directory\n")
        _, stderr = run_colorado(a_file, stations=stations, observations=plain, plots=False, catchment=None,
                                 status=1, what="no --catchment, --out a file")
        said = stderr_messages(stderr)
        assert_that(len(said) == 1 and said[0].startswith("--catchment: not given"), f"{stderr}")
        # The NOAA file as --stations beside another observations file: a gauge per station too.
        _, stderr = run_colorado(os.path.join(out, "beside"), stations=noaa, observations=plain, catchment=catchment,
                                 plots=False, what="the NOAA file as --stations")
        assert_that(f"read {len(gauges)} gauges" in stderr and "more than one gauge" not in stderr, f"{stderr}")
        moved = write(out, "moved.csv", header + "".join(lines[:4]) + lines[4].replace('"-39.1"', '"-39.2"', 1)
                      + "".join(lines[5:]))
        long = write(out, "long.csv", "station_id,longitude,long,lat\nN1,175.6,175.6,-39.1\n")
        # A row without its station's place (an empty LATITUDE) takes it from the station's other
        # rows, and is said; a station that no row places ends the run naming its first row.
        placeless = write(out, "placeless.csv", header + "".join(lines[:4]) + lines[4].replace('"-39.1"', '""', 1)
                          + "".join(lines[5:]))
        _, stderr = run_colorado(os.path.join(out, "placeless"), observations=placeless, catchment=catchment,
                                 plots=False, what="a row without its place")
        assert_that(f"{placeless}:6: station N2 lacks its lon or lat on this row: its place is taken from its other "
                    "rows (1 row(s) of 1 station(s) so)" in stderr, f"{stderr}")
        got_placeless = read_csv(os.path.join(out, "placeless", "areal_mean.csv"))
        assert_that(got_placeless == zipped, f"a row without its place: {got_placeless} against {zipped}")
        unplaced = write(out, "unplaced.csv", header + "".join(lines[:3])
                         + "".join(line.replace('"-39.1"', '""', 1) for line in lines[3:6]) + "".join(lines[6:]))
        for options, message in (
                ({"observations": unplaced}, f"{unplaced}:5: station N2 lacks its lon or lat here and on every other "
                                             "row (each station needs its place on one row at least)"),
                ({"observations": moved}, f"{moved}:6: station N2 at (176.4, -39.2), where line 5 puts it at "
                                          "(176.4, -39.1): a file of both stations and observations gives each "
                                          "station one place"),
                ({"observations": plain, "stations": long},
                 f"{long}:1: columns 'longitude', 'long' could each be 'lon': keep one, or name it lon")):
            _, stderr = run_colorado(os.path.join(out, "bad"), catchment=catchment, plots=False, status=1,
                                     what=message, **options)
            assert_that(message in stderr and "Traceback" not in stderr, f"{message!r} not in {stderr!r}")


def test_gauges_from_a_gis_file_of_points_give_the_csv_means():
    # The lake gauges as a GeoJSON of points (ids in a Station_ID attribute, names in Name) give
    # the stations CSV's counts and means bit for bit; in UTM 60S (a "crs", ids in site_no) to
    # 1e-8; with ids in an attribute of another name, --stations-id names it. A gauge off the
    # globe (named by its feature number), a file without an id attribute, a polygon for a gauge,
    # and --stations-id with a CSV file end the run naming them.
    import zipfile

    def points_file(directory, name, coordinates, field, crs=None):
        collection = {"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {field: s, "Name": f"{s} gauge"},
             "geometry": {"type": "Point", "coordinates": list(p)}} for s, p in zip(LAKE_GAUGES, coordinates)]}
        if crs:
            collection["crs"] = {"type": "name", "properties": {"name": crs}}
        return write(directory, name, json.dumps(collection))

    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        run_colorado(os.path.join(out, "csv"), stations=stations, observations=observations, catchment=catchment,
                     plots=False, what="the CSV gauges")
        want = read_csv(os.path.join(out, "csv", "areal_mean.csv"))
        lonlat = points_file(out, "gauges.geojson", LAKE_GAUGES.values(), "Station_ID")
        run_colorado(os.path.join(out, "points"), stations=lonlat, observations=observations, catchment=catchment,
                     month="2001-01", plots=False, what="the GeoJSON gauges")
        # A projected declaration over lon/lat is said, and the points read as lon/lat.
        declared = points_file(out, "declared.geojson", LAKE_GAUGES.values(), "station_id", "EPSG:2193")
        _, stderr = run_colorado(os.path.join(out, "declared"), stations=declared, observations=observations,
                                 catchment=catchment, plots=False, what="a projected declaration over lon/lat")
        assert_that(f"{declared}: declares the projected coordinate system 'NZGD2000 / New Zealand Transverse "
                    "Mercator 2000'; its coordinates are read as longitude/latitude" in stderr, f"{stderr}")
        assert_that(read_csv(os.path.join(out, "declared", "areal_mean.csv")) == want, "the declared file's means")
        zipped = os.path.join(out, "gauges.zip")  # (as GIS files are downloaded)
        with zipfile.ZipFile(zipped, "w") as z:
            z.write(lonlat, "gauges/gauges.geojson")
        run_colorado(os.path.join(out, "zipped"), stations=zipped, observations=observations, catchment=catchment,
                     plots=False, what="the zipped GeoJSON gauges")
        got, from_zip = (read_csv(os.path.join(out, d, "areal_mean.csv")) for d in ("points", "zipped"))
        assert_that(got == want == from_zip and len(got) == 2, f"the GeoJSON gauges' means {got} against {want}")
        names = {w["station_id"]: w["name"] for w in read_csv(os.path.join(out, "points", "weights_2001_01.csv"))}
        assert_that(names and all(names[s] == f"{s} gauge" for s in names), f"the names: {names}")
        utm = utm_of(list(LAKE_GAUGES.values()))
        for name, path, options in (
                ("utm", points_file(out, "utm.geojson", utm, "site_no", "urn:ogc:def:crs:EPSG::32760"), {}),
                ("code", points_file(out, "code.geojson", LAKE_GAUGES.values(), "code"), {"stations-id": "CODE"})):
            _, stderr = run_colorado(os.path.join(out, name), stations=path, observations=observations,
                                     catchment=catchment, plots=False, what=name, **options)
            assert_same_means(read_csv(os.path.join(out, name, "areal_mean.csv")), want, name)
        # A gauge at an earlier one's place is listed with that one's feature number (not "line").
        twice = write(out, "twice.geojson", json.dumps({"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {"station_id": s}, "geometry": {"type": "Point", "coordinates": list(p)}}
            for s, p in [*LAKE_GAUGES.items(), ("N7", LAKE_GAUGES["N3"])]]}))
        run_colorado(os.path.join(out, "twice"), stations=twice, observations=observations, catchment=catchment,
                     plots=False, what="a gauge at another's place")
        unused = [r for r in read_csv(os.path.join(out, "twice", "unused_inputs.csv"))
                  if r["station_id"] == "N7" and r["kind"].startswith("gauge at the place")]
        assert_that([(r["line"], r["note"]) for r in unused] == [("7", "same place as feature 3")], f"{unused}")
        code = os.path.join(out, "code.geojson")
        far = points_file(out, "far.geojson", [(175.6, -39.1), (176.4, 95.0)], "station_id")
        for options, message in (
                ({"stations": far}, f"{far}: feature 2 (counted from 1): station N2 has an invalid longitude/latitude (176.4, 95)"),
                ({"stations": code}, f"{code}: no attribute holds the station ids (station_id, station, site_no, id); "
                                     "its attributes: code, Name (give the one holding the ids with --stations-id)"),
                ({"stations": code, "stations-id": "kode"}, f"{code}: no attribute named 'kode'"),
                ({"stations": catchment}, f"{catchment}: feature 1 is not one point"),
                # (which feature, when the catchment's messages count from 0: said)
                ({"stations": catchment}, "a stations file holds a point per gauge (features counted from 1)"),
                ({"stations": stations, "stations-id": "code"}, "--stations-id code: is for a GIS file of points")):
            _, stderr = run_colorado(os.path.join(out, "bad"), observations=observations, catchment=catchment,
                                     plots=False, status=1, what=message, **options)
            assert_that(message in stderr and "Traceback" not in stderr, f"{message!r} not in {stderr!r}")


def test_observations_of_no_gauge_end_the_run():
    # Ids that match no gauge at all (a prefix the stations file has and the observations do not)
    # end the run naming both files, instead of a run of months without a mean; so does a stations
    # file without gauges.
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        other = write(out, "other_ids.csv", "station_id,lon,lat\nNZ-N1,175.6,-39.1\nNZ-N2,176.4,-39.1\n007,176,-39\n")
        _, stderr = run_colorado(out, stations=other, observations=observations, catchment=catchment, status=1,
                                 plots=False, what="ids of no gauge")
        messages = stderr_messages(stderr)
        assert_that(len(messages) == 1 and messages[0].startswith(f"{observations}: none of its ")
                    and other in messages[0] and "ids there: NZ-N1, NZ-N2, 007)" in messages[0]
                    and "ids here: N1, N2," in messages[0] and "Traceback" not in stderr,
                    f"ids of no gauge: {stderr}")
        assert_that(not os.path.exists(os.path.join(out, "areal_mean.csv")), "areal_mean.csv written")
        empty = write(out, "empty.csv", "station_id,lon,lat\n")
        _, stderr = run_colorado(out, stations=empty, observations=observations, catchment=catchment, status=1,
                                 plots=False, what="no gauges")
        messages = stderr_messages(stderr)
        assert_that(messages == [f"{empty}: no gauges (the file has no rows)"], f"no gauges: {stderr}")


def test_the_filters_errors_name_the_file_and_line():
    # An input the script passes but vtkThiessenArealAverage rejects ends the run with one line
    # naming the file (and, for a gauge, the stations file's line), not VTK's log and executive dump.
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)

        def polygon(name, ring):
            return write(out, name, json.dumps({"type": "FeatureCollection", "features": [{
                "type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [ring]}}]}))

        bad_gauge = write(out, "bad_gauge.csv", "station_id,lon,lat\nN1,175.6,-39.1\nN2,176.4,-39.1\n"
                                                "N3,175.95,-38.82\n004,-0.5,95\n")
        bow_tie = polygon("bow_tie.geojson", [[175.5, -39.2], [176.5, -38.4], [176.5, -39.2], [175.5, -38.4],
                                              [175.5, -39.2]])
        metres = polygon("metres.geojson", [[500000, 4100000], [800000, 4100000], [800000, 4500000],
                                            [500000, 4500000], [500000, 4100000]])
        header_only = write(out, "header_only.csv", "station_id,year,month,precip\n")
        # GDAL's own lines ("ERROR 1: ...", "Warning 1: Non closed ring detected") went to stderr
        # beside the script's, and a file of points or lines was only "found no polygon".
        square = [[175.5, -39.2], [176.5, -39.2], [176.5, -38.4], [175.5, -38.4]]
        cut_short = write(out, "cut_short.geojson", json.dumps({"type": "Polygon", "coordinates": [square]})[:-3])
        unclosed = polygon("unclosed.geojson", square)
        point_then_bow_tie = write(out, "point_bow_tie.geojson", json.dumps({"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [176.0, -38.9]}},
            {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [
                [[175.5, -39.2], [176.5, -38.4], [176.5, -39.2], [175.5, -38.4], [175.5, -39.2]]]}}]}))
        points_and_lines = write(out, "points.geojson", json.dumps({"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": square[0]}},
            {"type": "Feature", "properties": {}, "geometry": {"type": "LineString", "coordinates": square[:2]}}]}))
        cases = [
            (("--catchment", cut_short), f"{cut_short}: GDAL cannot read the catchment file: "),  # (its words vary)
            (("--catchment", unclosed), f"{unclosed}: the window/catchment input (vtkMultiBlockDataSet) holds no "
                                        "polygon"),
            (("--catchment", points_and_lines), f"{points_and_lines}: VTK's GDAL reader (vtkGDALVectorReader) found "
                                                "no polygon in the catchment file, only 1 point(s), 1 line(s)"),
            (("--stations", bad_gauge),
             f"{bad_gauge}:5: station 004 has an invalid longitude/latitude (-0.5, 95): a latitude beyond 90 degrees"),
            (("--catchment", bow_tie),
             f"{bow_tie}: ring 0 is self-intersecting: segment 0 and segment 2 touch or cross"),
            (("--catchment", metres),
             f"{metres}: catchment ring 0 vertex 0 has an invalid longitude/latitude (500000, 4100000): these "
             "look like projected coordinates (metres)"),
            (("--observations", header_only), f"{header_only}: the observations table has no rows"),
        ]
        for arguments, expected in cases:
            files = {"stations": stations, "observations": observations, "catchment": catchment}
            files[arguments[0].lstrip("-")] = arguments[1]
            _, stderr = run_colorado(out, what=str(arguments), status=1, plots=False, **files)
            assert_without_vtk_decoration(stderr, str(arguments))
            messages = stderr_messages(stderr)
            assert_that(len(messages) == 1 and messages[0].startswith(expected),
                        f"{arguments}: expected one line starting {expected!r}, got {messages}")
        # A point feature before the bow tie is left out of the catchment in its place, so that the
        # blocks named are still the file's features (the bow tie was named block 0).
        _, stderr = run_colorado(out, what="a point, then the bow tie", status=1, plots=False, stations=stations,
                                 observations=observations, catchment=point_then_bow_tie)
        assert_that("(ring 0 is block 1 (composite index 2) cell 0 of the catchment" in stderr, f"{stderr}")


def test_the_filters_warnings_are_lines_of_their_own():
    # The filter's warnings, each on a line of its own after the progress line, naming the file
    # and, for observation rows, the file's lines (the filter's rows from 0); gauges of a shared
    # id by their stations file lines.
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        with open(stations, "a") as f:
            f.write("N1,176.0,-39.0\nN7,176.4,-39.1\n")  # lines 8 and 9: a shared id, a gauge at N2's place
        with open(observations, "w") as f:
            f.write("station_id,year,month,precip\nN1,2001,1,10\nN2,2001,1,20\nXX,2001,1,5\nN3,2001,1,30\n"
                    "N1,2001,1,11\nXX,2001,2,5\nN4,2001,2,40\n")
        _, stderr = run_colorado(out, stations=stations, observations=observations, catchment=catchment,
                                 month="2001-01", plots=False, what="warnings")
        assert_without_vtk_decoration(stderr, "warnings")
        messages = stderr_messages(stderr)
        expected = [
            f"{observations}: 1 station id(s) of the observations that no gauge has: their rows were ignored: "
            "XX (2 rows from line 4)",
            f"{observations}: 1 observation row(s) repeat a station and time of an earlier row with a value; "
            "the earlier value is used: line 6 (station N1) repeating line 2",
            f"{stations}: 1 station id(s) are given to more than one gauge; their observations go to the first: "
            "N1 (gauges 0 and 6: lines 2 and 8)",
            f"{stations}: 1 gauge(s) stand where an earlier gauge stands; the first that reports is used: "
            "N7 (same place as N2)",
        ]
        for line in expected:
            assert_that(line in messages, f"{line!r} not among {messages}")
        # unused_inputs.csv gives the repeated row's line and the line whose value is used.
        repeats = [u for u in read_csv(os.path.join(out, "unused_inputs.csv")) if u["kind"].startswith("observation repeating")]
        assert_that([(u["line"], u["station_id"], u["note"]) for u in repeats] == [("6", "N1", "repeats line 2")],
                    f"the repeated row in unused_inputs.csv: {repeats}")
        unused = [m for m in messages if "never used" in m]
        assert_that(len(unused) == 1 and unused[0].startswith(f"{stations}: 4 gauge(s) have no observed value"),
                    f"the never-used gauges: {messages}")
        # The second N1 (line 8) is never used, the first is: a shared id is named with its gauge.
        assert_that("N1 (gauge 6: line 8)" in unused[0] and "N1," not in unused[0] and not unused[0].endswith("N1"),
                    f"the never-used N1 is not told from the used one: {unused[0]}")


def test_rows_of_empty_fields_are_skipped():
    # Blank rows as a spreadsheet exports them (",,,"), lines of spaces and blank lines hold no
    # data: the run is that of the files without them, and lines are still counted in the file.
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, observations = write_lake_basin(directory)
        outputs = {}
        for name in ("clean", "blank"):
            out = os.path.join(directory, name)
            files = {"stations": stations, "observations": observations}
            if name == "blank":
                with open(stations) as f:
                    lines = f.read().splitlines()
                blank_stations = os.path.join(directory, "blank_stations.csv")
                with open(blank_stations, "w") as f:
                    f.write("\n".join(lines[:3] + [",,", "  ,  ,  "] + lines[3:] + [",,", ",,"]) + "\n")
                with open(observations) as f:
                    lines = f.read().splitlines()
                blank_observations = os.path.join(directory, "blank_obs.csv")
                with open(blank_observations, "w") as f:
                    f.write("\n".join(lines[:2] + [",,,", "", "   "] + lines[2:] + ["XX,2001,2,1", ",,,", ",,,"])
                            + "\n")
                files = {"stations": blank_stations, "observations": blank_observations}
            stdout, stderr = run_colorado(out, catchment=catchment, month="2001-01", plots=False, what=name,
                                          **files)
            with open(os.path.join(out, "areal_mean.csv")) as f:
                # (the blank run's unknown station XX is one more unused input)
                outputs[name] = (f.read(), re.sub(r"\(\d+ input\(s\) not used\)", "", stdout.replace(out, "OUT")),
                                 stderr)
        assert_that(outputs["clean"][:2] == outputs["blank"][:2],
                    f"blank rows change the run: {outputs['clean'][:2]} against {outputs['blank'][:2]}")
        stderr = outputs["blank"][2]
        assert_that("read 6 gauges and 8 observations" in stderr, f"the rows read: {stderr}")
        # The unknown station's row is the file's line 12, lines 3-5 being blank.
        assert_that("XX (1 row: line 12)" in stderr, f"the unknown station's line: {stderr}")
        unused = read_csv(os.path.join(directory, "blank", "unused_inputs.csv"))
        assert_that([(u["station_id"], u["line"]) for u in unused if u["station_id"] == "XX"] == [("XX", "12")],
                    f"unused_inputs.csv: {unused}")


def test_the_messages_map_to_files_and_lines():
    # InputFiles, on messages the files above do not give: a row error (the script checks the
    # values first), a row the script added, a message of no known kind.
    example, csv_input = import_example(), import_example("csv_input")
    files = example.InputFiles("s.csv", [2, 3, 5], "o.csv", [2, 4], "c.geojson")
    cases = [
        (files.error("observation row 1: 'x' in column 'precip' is not a number"),
         "o.csv:4: 'x' in column 'precip' is not a number"),
        (files.error("gauge 2 (station C): point (200, 10) is 60 degrees of longitude from the central meridian"),
         "s.csv:5: station C: point (200, 10) is 60 degrees of longitude from the central meridian"),
        (files.error("none of the 2 observation rows can be used (no time step to average): 0 have no station id "
                     "or no time, the others name station ids that no gauge has: A (2 rows from row 0)"),
         "o.csv: none of the 2 observation rows can be used (no time step to average): 0 have no station id "
         "or no time, the others name station ids that no gauge has: A (2 rows from line 2)"),
        (files.error("something else"), "the areal average failed: something else"),
        (files.warning("1 observation row(s) have no station id or no time and were ignored (rows from 0, listed "
                       "in UnusedObservationRows): row 2 (station A: no time)"),
         "o.csv: 1 observation row(s) have no station id or no time and were ignored: row 2 (a row added for a "
         "month without rows) (station A: no time)"),
        (files.warning("1 cell(s) of the catchment (input 1) are not polygons or closed polylines and were ignored "
                       "(the first is block 0 cell 3)."),
         "c.geojson: 1 cell(s) of the catchment (input 1) are not polygons or closed polylines and were ignored "
         "(the first is block 0 cell 3)."),
        (csv_input.vtk_message_text("ERROR: In /src/vtkThiessenArealAverage.cxx, line 815\nvtkThiessenArealAverage "
                                    "(0x3ab42b20): gauge 3 (station 004) has an invalid longitude/latitude\n\n"),
         "gauge 3 (station 004) has an invalid longitude/latitude"),
        (csv_input.vtk_message_text("Warning: In /src/vtkThiessenArealAverage.cxx, line 980\nvtkThiessenArealAverage "
                                    "(0x3ab42b20): 1 gauge(s) have no observation\n\n"),
         "1 gauge(s) have no observation"),
    ]
    for got, expected in cases:
        assert_that(got == expected, f"{got!r}, expected {expected!r}")


def test_the_other_examples_run_on_their_data():
    with tempfile.TemporaryDirectory() as out:
        status, stdout, stderr = run_example("project_gauges.py", "--out", out)
        assert_that(status == 0, f"project_gauges.py failed: {stderr}")
        projected = read_csv(os.path.join(out, "gauges_projected.csv"))
        stations = read_csv(os.path.join(EXAMPLE_DATA, "colorado_stations.csv"))
        assert_that(len(projected) == len(stations) == 376, f"{len(projected)} projected gauges")
        assert_that(all(math.isfinite(float(r["x_m"])) and math.isfinite(float(r["y_m"])) for r in projected),
                    "a projected coordinate is not finite")
        # The plane's origin is printed (a GIS user took the record's lat0 for it, some 480 m off
        # at 69 N): projected with the gauges' record it is (0, 0) to a millimetre, and for the
        # automatic Albers its latitude lies between the standard parallels.
        found = re.search(r"x_m and y_m are metres from the plane's origin, at lon (\S+), lat (\S+)\n", stdout)
        assert_that(found is not None, f"no origin printed: {stdout}")
        record = read_polydata(os.path.join(out, "gauges_projected.vtp")).GetFieldData().GetAbstractArray(
            "TesseraProjection").GetValue(0)
        terms = dict(term.split("=") for term in record.split())
        from tessera import vtkGeographicProjection
        from tessera_testing import make_points

        origin = make_points([(float(found.group(1)), float(found.group(2)))])
        forward = vtkGeographicProjection()
        forward.SetInputData(origin)
        forward.SetProjectionRecord(record)
        forward.Update()
        x, y, _ = forward.GetOutput().GetPoint(0)
        assert_that(abs(x) < 1e-3 and abs(y) < 1e-3 and float(terms["lat1"]) < float(found.group(2)) <
                    float(terms["lat2"]), f"the origin {found.groups()} projects to {x}, {y}; {record}")
        status, stdout, stderr = run_example("ridge_grouping.py", "--out", out)
        assert_that(status == 0, f"ridge_grouping.py failed: {stderr}")
        points = read_polydata(os.path.join(out, "fiji_points.vtp"))
        groups = points.GetPointData().GetArray("GroupId")
        assert_that(points.GetNumberOfPoints() == 1000 and groups is not None, "fiji_points.vtp")
        found = {groups.GetValue(i) for i in range(points.GetNumberOfPoints())} - {-1}
        assert_that(len(found) >= 2, f"the epicentres fall into {len(found)} group(s)")
        assert_that(is_png(os.path.join(out, "fiji_groups.png")), "fiji_groups.png is not a PNG file")
        # A warning that lists epicentres by id gives their lines too (the file has a header and
        # no blank line: epicentre k is on line k + 2).
        far = re.search(r"point\(s\) ([\d, ]+) \(line\(s\) ([\d, ]+) of ([^)]+)\)", stderr)
        assert_that(far is not None and far.group(3) == os.path.join(EXAMPLE_DATA, "fiji_quakes.csv")
                    and [int(k) + 2 for k in far.group(1).split(", ")] == [int(k) for k in far.group(2).split(", ")],
                    f"the far epicentres' lines: {stderr}")
        quakes = os.path.join(out, "quakes.csv")
        with open(quakes, "w") as f:
            f.write("lat,east\n1,2\n")
        status, _, stderr = run_example("ridge_grouping.py", "--out", out, "--quakes", quakes)
        assert_that(status == 1 and "no column 'lon' (it needs lat, lon" in stderr, f"ridge_grouping.py: {stderr}")
        # Longitude by any of its usual names (the Fiji file's is long): the same groups (only
        # lon, longitude and lng were refused), given the Fiji file's settings (another file gets the
        # filter's defaults).
        with open(os.path.join(EXAMPLE_DATA, "fiji_quakes.csv")) as f:
            fiji = f.read()
        fiji_settings = ("--width", "4", "--curve-sigma", "0.1", "--minimum-contour-length", "15")
        for name in ("lon", "longitude", "lng"):
            with open(quakes, "w") as f:
                f.write(fiji.replace('"long"', f'"{name}"', 1))
            renamed = os.path.join(out, name)
            status, _, stderr = run_example("ridge_grouping.py", "--out", renamed, "--quakes", quakes, *fiji_settings)
            same = read_polydata(os.path.join(renamed, "quakes_points.vtp")).GetPointData().GetArray("GroupId")
            assert_that(status == 0 and [same.GetValue(i) for i in range(same.GetNumberOfTuples())]
                        == [groups.GetValue(i) for i in range(groups.GetNumberOfTuples())], f"{name}: {stderr}")
        # Another file's outputs are named after it (they were named fiji_* whatever was read), and
        # --prefix names them as asked.
        written = sorted(os.listdir(renamed))
        assert_that(written == ["quakes_contours.vtp", "quakes_curves.vtp", "quakes_field.vti", "quakes_groups.png",
                                "quakes_points.vtp"], f"{written}")
        status, stdout, stderr = run_example("ridge_grouping.py", "--out", os.path.join(out, "named"), "--quakes",
                                             quakes, "--prefix", "trench")
        written = sorted(os.listdir(os.path.join(out, "named")))
        assert_that(status == 0 and written == ["trench_contours.vtp", "trench_curves.vtp", "trench_field.vti",
                                                "trench_groups.png", "trench_points.vtp"]
                    and "trench_points.vtp" in stdout, f"{written} {stdout} {stderr}")
        # Plane coordinates (x, y) with --planar, grouped without a projection: a half circle and a
        # line below it, each group's points from one of them; without --planar, the file is named.
        rng = random.Random(3)
        arc = [(100 * math.cos(t) + rng.gauss(0, 1), 100 * math.sin(t) + rng.gauss(0, 1))
               for t in (rng.uniform(0, math.pi) for _ in range(300))]
        line = [(rng.uniform(-100, 100), -50 + rng.gauss(0, 1)) for _ in range(200)]
        plane = write(out, "plane.csv", "x,y\n" + "".join(f"{x!r},{y!r}\n" for x, y in arc + line))
        status, stdout, stderr = run_example("ridge_grouping.py", "--out", os.path.join(out, "plane"), "--quakes",
                                             plane, "--planar")
        grouped = read_polydata(os.path.join(out, "plane", "plane_points.vtp"))
        ids = grouped.GetPointData().GetArray("GroupId")
        on_arc = {ids.GetValue(k) for k in range(300)}
        on_line = {ids.GetValue(k) for k in range(300, 500)}
        first = grouped.GetPoint(0)
        assert_that(status == 0 and len(on_arc) == 1 and len(on_line) == 1 and on_arc != on_line
                    and -1 not in on_arc | on_line and first[:2] == arc[0], f"{on_arc} {on_line} {stderr}")
        status, _, stderr = run_example("ridge_grouping.py", "--out", out, "--quakes", plane)
        assert_that(status == 1 and "plane.csv: the file has columns x, y and no lat, lon: for plane coordinates, "
                    "give --planar" in stderr, f"{status} {stderr}")
        # The other way round: --planar with a file of lat, lon (or latitude, longitude) is named too,
        # and a file of neither is told the columns in the order they are written, x, y.
        for header in ("lat,lon", "Latitude,Longitude"):
            degrees = write(out, "degrees.csv", header + "\n-20,181\n-21,182\n-22,183\n")
            status, _, stderr = run_example("ridge_grouping.py", "--out", out, "--quakes", degrees, "--planar")
            assert_that(status == 1 and "degrees.csv: the file has columns lat, lon and no x, y: for latitudes and "
                        "longitudes (projected before grouping), leave out --planar" in stderr, f"{header}: {stderr}")
        other = write(out, "other.csv", "a,b\n1,2\n3,4\n")
        status, _, stderr = run_example("ridge_grouping.py", "--out", out, "--quakes", other, "--planar")
        assert_that(status == 1 and "has no column 'x', 'y' (it needs x, y;" in stderr, stderr)
        # depth and mag only ride along: a file without them, or with a value missing, is grouped
        # (a missing depth stopped the run), the missing values NaN in the points' arrays.
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

        rows = [line.split(",") for line in open(os.path.join(EXAMPLE_DATA, "fiji_quakes.csv")).read().split()[1:301]]
        for header, row_text in (("lat,long", lambda r: f"{r[0]},{r[1]}"),
                                 ("lat,long,depth,mag", lambda r: f"{r[0]},{r[1]},,{r[3]}")):
            with open(quakes, "w") as f:
                f.write(header + "\n" + "\n".join(row_text(r) for r in rows) + "\n")
            status, _, stderr = run_example("ridge_grouping.py", "--out", out, "--quakes", quakes)
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(os.path.join(out, "quakes_points.vtp"))
            reader.Update()
            depth = reader.GetOutput().GetPointData().GetArray("depth_km")
            assert_that(status == 0 and depth is not None and depth.GetNumberOfTuples() == 300
                        and all(math.isnan(depth.GetValue(k)) for k in range(300)), f"{header}: {status} {stderr}")
        # An epicentre the projection rejects, a file without rows and a grouping error: one line
        # each (the file's line of the epicentre), no VTK log, no traceback.
        north = write(out, "north.csv", "lat,lon,depth,mag\n-20.4,181.6,562,4.8\n\n95,181,100,4.5\n")
        empty = write(out, "empty.csv", "lat,lon,depth,mag\n")
        two = write(out, "two.csv", "lat,lon,depth,mag\n-20,181,1,1\n-21,182,1,1\n")
        for extra, expected in (
                (("--quakes", north), f"{north}:4: epicentre at (181, 95) has a latitude beyond 90 degrees"),
                (("--quakes", empty), f"{empty}: no epicentres to group (the file has no rows)"),
                (("--quakes", two, "--image-size", "100000"), "--image-size: image size 100000 exceeds"),
                (("--quakes", two, "--width", "0"), "--width: basis width 0 is not a positive number")):
            status, _, stderr = run_example("ridge_grouping.py", "--out", os.path.join(out, "bad"), *extra)
            what = f"ridge_grouping.py {extra}"
            assert_without_vtk_decoration(stderr, what)  # (a VTK log line names vtkRidgeGrouping.cxx)
            lines = stderr.strip().splitlines()
            assert_that(status == 1 and len(lines) == 1 and lines[0].startswith(expected),
                        f"{what}: expected one line starting {expected!r}, got {lines}")
        # (beyond an int it was an OverflowError's traceback)
        status, _, stderr = run_example("ridge_grouping.py", "--out", out, "--image-size", "99999999999")
        assert_that(status == 2 and stderr.strip().endswith(
            "argument --image-size: 99999999999 pixels is out of range (the largest image is 2048)"), stderr)
        status, _, stderr = run_example("ridge_grouping.py", "--out", os.path.join(out, "two"), "--quakes", two)
        assert_without_vtk_decoration(stderr, "ridge_grouping.py's warning")
        assert_that(status == 0 and stderr.strip().startswith("warning: no ridge contour: "),
                    f"a warning as a line of its own: {stderr}")


def test_outputs_that_cannot_be_written_are_named():
    # From an error audit: a directory where an output file goes. VTK's writers logged an error
    # and the scripts said they wrote the file, exit status 0; a CSV there was a traceback.
    with tempfile.TemporaryDirectory() as out:
        cases = [(("colorado_areal_precipitation.py", "--no-plots"), "tiles_1963_08.vtp",
                  "cannot write (a directory of that name exists)"),
                 (("colorado_areal_precipitation.py", "--no-plots"), "areal_mean.csv", "Is a directory"),
                 (("ridge_grouping.py",), "fiji_field.vti", "cannot write (a directory of that name exists)"),
                 (("project_gauges.py",), "gauges_projected.vtp", "cannot write (a directory of that name exists)"),
                 (("project_gauges.py",), "gauges_projected.csv", "Is a directory")]
        for k, (command, name, reason) in enumerate(cases):
            target = os.path.join(out, str(k))
            os.makedirs(os.path.join(target, name))
            status, _, stderr = run_example(command[0], "--out", target, *command[1:])
            assert_without_vtk_decoration(stderr, f"{command} {name}")
            last = stderr.strip().splitlines()[-1]
            assert_that(status == 1 and last == f"{os.path.join(target, name)}: {reason}" and "Traceback" not in stderr,
                        f"{command} with a directory {name}: status {status}, {stderr}")


def test_a_hole_outside_its_polygon_is_named():
    # From an error audit: a GeoJSON hole that lies outside its polygon's outer ring is an island by
    # the even-odd rule: the catchment grew by its area without a word. Named now (feature, ring),
    # with the MultiPolygon's rings counted over its polygons; a hole inside and one that touches
    # its outline from inside are not named.
    import copy

    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        basin = copy.deepcopy(LAKE_BASIN)
        outer, lake = basin["features"][0]["geometry"]["coordinates"]
        outside = [[x + 1.0, y] for x, y in lake]
        touching = [[175.5, -39.0], [175.7, -39.0], [175.7, -38.9], [175.5, -39.0]]  # (touches at a vertex)
        basin["features"][0]["geometry"]["coordinates"] = [outer, lake, touching]
        basin["features"].append({"type": "Feature", "properties": {}, "geometry": {"type": "MultiPolygon", "coordinates": [
            [[[x + 2.0, y] for x, y in outer]], [[[x + 4.0, y] for x, y in outer], [[x + 4.0, y] for x, y in lake], outside]]}})
        path = write(out, "holes.geojson", json.dumps(basin))
        _, stderr = run_colorado(out, catchment=path, stations=stations, observations=observations, plots=False)
        named = [line for line in stderr.splitlines() if "is a hole (a polygon" in line]
        expected = (f"{path}: feature 1 ring 3 is a hole (a polygon's ring after its first) but lies outside its "
                    "polygon's outer ring: the even-odd rule takes it as an island, adding its area")
        assert_that(len(named) == 1 and named[0].startswith(expected), f"{named}")
        _, stderr = run_colorado(out, catchment=catchment, stations=stations, observations=observations, plots=False)
        assert_that("is a hole (a polygon" not in stderr, stderr)
        # From a code review: only the features --feature takes are looked at, and a malformed
        # feature that GDAL passes over made a traceback here.
        basin["features"][1]["properties"] = {"HUC8": "2"}
        basin["features"][0]["properties"] = {"HUC8": "1"}
        basin["features"].append({"type": "Feature", "properties": {"HUC8": "3"},
                                  "geometry": {"type": "Polygon", "coordinates": [[1, 2]]}})
        path = write(out, "holes.geojson", json.dumps(basin))
        _, stderr = run_colorado(out, "--feature", "HUC8=1", catchment=path, stations=stations,
                                 observations=observations, plots=False)
        assert_that("is a hole (a polygon" not in stderr and "Traceback" not in stderr, stderr)
        _, stderr = run_colorado(out, "--feature", "HUC8=2", catchment=path, stations=stations,
                                 observations=observations, plots=False)
        assert_that("feature 1 ring 3 is a hole" in stderr and "Traceback" not in stderr, stderr)
        # GDAL's log goes to the script's file while it reads, not for the rest of the process
        # (a host program's, or its children's, GDAL messages went there too).
        example = import_example()
        example.read_catchment(catchment)
        assert_that("CPL_LOG" not in os.environ, "CPL_LOG left set after reading")



def test_ridge_grouping_names_a_bad_epicentre_alone():
    # An epicentre the projection rejects ends the run with the one line naming it, whether the
    # other epicentres would be enough to group or not: the grouping does not run on the failed
    # projection's empty output, so no warning of its about "0 points" comes before the line.
    with tempfile.TemporaryDirectory() as directory:
        out = os.path.join(directory, "out")
        after_one = write(directory, "after_one.csv", "lat,lon,depth,mag\n-20,181,500,4.5\n95,182,500,4.5\n")
        alone = write(directory, "alone.csv", "lat,lon,depth,mag\n-91,181,500,4.5\n")
        among = write(directory, "among.csv", "lat,lon,depth,mag\n-20,181,1,1\n-21,182,1,1\n\n"
                                              "90.5,181,1,1\n-22,183,1,1\n")
        for quakes, expected in (
                (after_one, f"{after_one}:3: epicentre at (182, 95) has a latitude beyond 90 degrees"),
                (alone, f"{alone}:2: epicentre at (181, -91) has a latitude beyond 90 degrees"),
                (among, f"{among}:5: epicentre at (181, 90.5) has a latitude beyond 90 degrees")):
            status, stdout, stderr = run_example("ridge_grouping.py", "--out", out, "--quakes", quakes)
            what = f"ridge_grouping.py --quakes {quakes}"
            assert_that(status == 1, f"{what}: exit status {status}: {stderr}")
            assert_that("warning" not in stderr and "Traceback" not in stderr, f"{what}: {stderr!r}")
            assert_that(stderr.splitlines() == [expected], f"{what}: expected only {expected!r}, got {stderr!r}")
            assert_that(not stdout, f"{what}: printed {stdout!r}")


def test_ridge_grouping_tunes_only_the_fiji_file():
    # The Fiji file's settings (tuned to its scattered epicentres) are not another file's: a clean
    # S curve got CurveSigma 0.1's curve 3.9 units off it. Another file gets the filter's defaults,
    # read from the filter; options given win over both.
    import argparse

    from tessera import vtkRidgeGrouping

    ridge = import_example("ridge_grouping")
    fresh = vtkRidgeGrouping()
    unset = argparse.Namespace(width=None, curve_sigma=None, minimum_contour_length=None)
    assert_that(ridge.chosen_settings(unset, True, vtkRidgeGrouping()) == ridge.FIJI_SETTINGS, "the Fiji file's")
    assert_that(ridge.chosen_settings(unset, False, vtkRidgeGrouping()) ==
                {"width": fresh.GetWidth(), "curve_sigma": fresh.GetCurveSigma(),
                 "minimum_contour_length": fresh.GetMinimumContourLength()}, "another file's")
    given = argparse.Namespace(width=3.0, curve_sigma=None, minimum_contour_length=12.0)
    assert_that(ridge.chosen_settings(given, True, vtkRidgeGrouping()) ==
                {"width": 3.0, "curve_sigma": ridge.FIJI_SETTINGS["curve_sigma"], "minimum_contour_length": 12.0},
                "options given")
    assert_that(ridge.FIJI_SETTINGS != {"width": fresh.GetWidth(), "curve_sigma": fresh.GetCurveSigma(),
                                        "minimum_contour_length": fresh.GetMinimumContourLength()},
                "the Fiji settings are the defaults: the case tests nothing")
    # --help gives the filter's defaults as the filter has them.
    status, stdout, _ = run_example("ridge_grouping.py", "--help")
    flat = " ".join(stdout.split())
    assert_that(status == 0 and f"the filter's, {fresh.GetWidth():g};" in flat
                and f"the paper's {fresh.GetCurveSigma():g};" in flat
                and f"the filter's, {fresh.GetMinimumContourLength():g};" in flat, f"--help: {flat}")


def test_ridge_grouping_says_the_projections_warning_as_a_line_of_its_own():
    # Epicentres round a pole: the automatic conic is cut in their largest gap, which the
    # projection warns of; the script says it as its other warnings (it came as VTK's log line,
    # colours and all, advising settings the script does not have) and says what to do instead.
    with tempfile.TemporaryDirectory() as directory:
        ring = "".join(f"{80 + 0.01 * (k % 7)},{-180 + 360 * k / 300:.6f},10,4\n" for k in range(300))
        quakes = write(directory, "polar.csv", "lat,lon,depth,mag\n" + ring)
        status, _, stderr = run_example("ridge_grouping.py", "--out", os.path.join(directory, "out"),
                                        "--quakes", quakes)
        assert_without_vtk_decoration(stderr, "the projection's warning")
        lines = [line for line in stderr.splitlines() if "degrees of longitude" in line]
        assert_that(status == 0 and len(lines) == 1 and lines[0].startswith(f"warning: {quakes}: the data span")
                    and lines[0].endswith("so a curve across it is cut in two (this script projects with the "
                                          "automatic equal-area conic: to group them in another projection, project "
                                          "them yourself and give x, y with --planar)")
                    and "LambertAzimuthal" not in lines[0] and "tiles" not in lines[0], f"{stderr!r}")


def test_ridge_grouping_checks_its_out_directory_first():
    # An --out that cannot be created ends the run before the epicentres are read and grouped, with
    # one line naming it and why (as the main example says it), not a traceback after the work;
    # the bad epicentres file shows that no reading came first.
    with tempfile.TemporaryDirectory() as directory:
        regular = write(directory, "a_file", "not a directory\n")
        bad_quakes = write(directory, "north.csv", "lat,long,depth,mag\n95,181,1,1\n")
        cases = [
            (regular, f"--out {regular}: exists and is not a directory"),
            (os.path.join(regular, "sub"),
             f"--out {os.path.join(regular, 'sub')}: cannot create the directory (Not a directory)"),
            (os.path.join(regular, "sub", "deeper"),
             f"--out {os.path.join(regular, 'sub', 'deeper')}: cannot create the directory (Not a directory)"),
        ]
        for out, expected in cases:
            # (project_gauges.py too: it made its --out after the projection, with a traceback)
            for script, inputs in (("ridge_grouping.py", ()), ("ridge_grouping.py", ("--quakes", bad_quakes)),
                                   ("project_gauges.py", ())):
                status, stdout, stderr = run_example(script, "--out", out, *inputs)
                what = f"{script} --out {out} {' '.join(inputs)}"
                assert_that(status == 1, f"{what}: exit status {status}: {stderr}")
                assert_that("Traceback" not in stderr, f"{what}: a traceback instead of a message: {stderr}")
                assert_that(stderr.splitlines() == [expected], f"{what}: expected only {expected!r}, got {stderr!r}")
                assert_that(not stdout, f"{what}: printed {stdout!r}")
        with open(regular) as f:
            assert_that(f.read() == "not a directory\n", "--out a file: the file was changed")
        assert_that(sorted(os.listdir(directory)) == ["a_file", "north.csv"],
                    f"files left beside the inputs: {os.listdir(directory)}")

def test_project_gauges_names_a_bad_gauge_by_its_line():
    # A gauge vtkGeographicProjection rejects ends project_gauges.py with one line naming the
    # stations file, the gauge's line and station and the bad value, as in the main example, not
    # VTK's log with the executive's dump nor the filter's "point N" counted from 0.
    with tempfile.TemporaryDirectory() as out:
        # (gauge 2 on line 5: the blank line is counted in the file, not as a gauge)
        north = write(out, "north.csv", "station_id,lon,lat\nA,-105,39\n\nB,-104,40\nC,-0.5,95\n")
        # Two gauges in Colorado and one in Europe: 60 degrees from the UTM zone's meridian.
        far = write(out, "far.csv", "station_id,lon,lat\nA,-105,39\nB,-104,40\nC,20,45\n")
        empty = write(out, "empty.csv", "station_id,lon,lat\n")
        cases = [
            ((), north, f"{north}:5: station C at (-0.5, 95) has a latitude beyond 90 degrees"),
            (("--projection", "utm"), far, f"{far}:2: station A at (-105, 39) is 60 degrees of longitude from the "
                                           "central meridian"),
            ((), empty, f"{empty}: no gauges to project (the file has no rows)"),
        ]
        for arguments, stations, expected in cases:
            status, stdout, stderr = run_example("project_gauges.py", "--out", os.path.join(out, "o"),
                                                 "--stations", stations, *arguments)
            what = f"project_gauges.py --stations {stations} {' '.join(arguments)}"
            assert_that(status == 1, f"{what}: exit status {status}: {stderr}")
            assert_without_vtk_decoration(stderr, what)
            messages = stderr.splitlines()
            assert_that(len(messages) == 1 and messages[0].startswith(expected),
                        f"{what}: expected one line starting {expected!r}, got {messages}")
            # (--out is made before the inputs are read, so that a bad one is told first)
            made = os.path.join(out, "o")
            assert_that(not os.path.exists(made) or not os.listdir(made), f"{what}: wrote its outputs")


def test_project_gauges_writes_a_projected_systems_own_numbers():
    # --crs gives the gauges in a projected system's own numbers, false origin, scale, unit, axes and prime meridian
    # included, as PROJ 9.1.1 gives them (cs2cs EPSG:4326 EPSG:5070, EPSG:2232, Colorado Central in US feet, whose
    # NAD83 PROJ takes as WGS84, and EPSG:2053, South Africa's Lo29 in westings and southings; PROJ terms on
    # WGS84 for the rest): the first two Colorado gauges, TEEC NOS POS (109.1 W, 36.9 N) and AKRON 4 E (103.15 W,
    # 40.15 N), or a gauge of each system's own. EPSG:2232 goes in by its code and by its PROJ terms alike.
    state_plane = ("+proj=lcc +lat_0=37.8333333333333 +lon_0=-105.5 +lat_1=39.75 +lat_2=38.45 "
                   "+x_0=914401.828803658 +y_0=304800.609601219 +datum=NAD83 +units=us-ft +no_defs")
    colorado = [(-1152789.024, 1619131.577), (-603217.884, 1926486.744)]
    feet = [(1946885.106, 680886.132), (3656935.053, 1852284.842)]
    cases = [("EPSG:5070", None, colorado, 1.0),
             ("EPSG:2232", None, feet, 1200.0 / 3937.0),
             (state_plane, None, feet, 1200.0 / 3937.0),
             ("EPSG:2053", "A,29.5,-26.0", [(-50059.251, 2876930.325)], -1.0),  # (westings and southings)
             ("+proj=utm +zone=13 +ellps=GRS80 +units=us-ft", "A,-104.99,39.74", [(1643227.769, 14432059.254)],
              1200.0 / 3937.0),
             # (Paris's NTF Lambert zone II's terms on WGS84: its +lon_0=0 is the Paris meridian, 2.337 E)
             ("+proj=lcc +lat_1=46.8 +lat_0=46.8 +lon_0=0 +k_0=0.99987742 +x_0=600000 +y_0=2200000 +pm=paris "
              "+ellps=WGS84", "A,2.35,48.85", [(600937.759, 2427954.266)], 1.0)]
    with tempfile.TemporaryDirectory() as out:
        for crs, row, expected, metres in cases:
            stations = ["--stations", write(out, "one.csv", f"station_id,lon,lat\n{row}\n")] if row else []
            status, stdout, stderr = run_example("project_gauges.py", "--out", out, "--crs", crs, *stations)
            assert_that(status == 0 and not stderr, f"--crs {crs}: exit status {status}: {stderr}")
            with open(os.path.join(out, "gauges_projected.csv")) as f:
                rows = list(csv.DictReader(f))[:2]
            for row, (x, y) in zip(rows, expected):
                got = [float(row[key]) for key in ("x_crs", "y_crs", "x_m", "y_m")]
                assert_that(abs(got[0] - x) < 2e-3 and abs(got[1] - y) < 2e-3
                            and abs(got[2] - x * metres) < 2e-3 and abs(got[3] - y * metres) < 2e-3,
                            f"--crs {crs}: {row['name']} at {got}, PROJ's {x}, {y} (units of {metres} m)")
        # A geographic system, an unknown code, --crs with --projection and an axis or meridian not read are
        # named; a datum some way from WGS84 on its ellipsoid (Israel 1993, EPSG:2039: 78 m) is warned of.
        israel = write(out, "israel.csv", "station_id,lon,lat\nA,34.78,32.08\n")
        for arguments, expected in ((("--crs", "EPSG:4326"), "--crs 'EPSG:4326': a geographic system"),
                                    (("--crs", "EPSG:999999"), "--crs 'EPSG:999999': GDAL's database has no such"),
                                    (("--crs", "EPSG:5070", "--projection", "utm"), "not allowed with argument"),
                                    (("--crs", "+proj=tmerc +axis=eeu"), "not read here: +axis=eeu (read here: an east or west"),
                                    (("--crs", "+proj=tmerc +pm=mars"), "not read here: the prime meridian +pm=mars (read here:"),
                                    (("--crs", "EPSG:2039", "--stations", israel),
                                     "--crs 'EPSG:2039': the datum 'Israel_1993' (ellipsoid 'GRS 1980'), not one "
                                     "known here to lie within a metre or two of WGS84's")):
            status, _, stderr = run_example("project_gauges.py", "--out", os.path.join(out, "o"), *arguments)
            assert_that((status != 0) == (arguments[1] != "EPSG:2039") and expected in stderr,
                        f"{arguments}: exit status {status}: {stderr}")


def test_progress_into_a_log_is_lines_of_its_own():
    # Into a file or a pipe (a log), progress is lines of their own at 0, 25, 50, 75 and 100%, with
    # no carriage return: redrawn with \r it made one long line with the warnings spliced in.
    with tempfile.TemporaryDirectory() as out:
        catchment, stations, observations = write_lake_basin(out)
        done = subprocess.run([sys.executable, os.path.join(EXAMPLES, "colorado_areal_precipitation.py"), "--out", out,
                               "--stations", stations, "--observations", observations, "--catchment", catchment,
                               "--month", "2001-01", "--no-plots"], capture_output=True, timeout=300)
        assert_that(done.returncode == 0, f"exit status {done.returncode}: {done.stderr!r}")
        assert_that(b"\r" not in done.stderr, f"a carriage return in the log: {done.stderr!r}")
        progress = [re.fullmatch(r"Thiessen areal means: +(\d+)%", line)
                    for line in done.stderr.decode().splitlines() if line.startswith("Thiessen areal means:")]
        percents = [int(m.group(1)) if m else None for m in progress]
        assert_that(percents and percents[-1] == 100 and percents == sorted(set(percents))
                    and set(percents) <= {0, 25, 50, 75, 100}, f"progress lines: {percents}")


def test_the_readme_python_runs():
    # The README's Python examples, as written, from the source directory: they print the
    # tiles' total area (the window's), the clipped area (worked out by hand in a comment) and the
    # share of the clip's window the tiles cover, the number of months of the areal average and
    # the number of curves the ridge grouping finds.
    with open(os.path.join(SOURCE_DIR, "README.md")) as f:
        text = f.read()
    section = text[text.index("## Use from Python"):text.index("## Use from ParaView")]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert_that(len(blocks) == 3, f"the README's Python blocks: {len(blocks)}")
    printed = []
    for block in blocks:
        done = subprocess.run([sys.executable, "-c", block], cwd=SOURCE_DIR, capture_output=True, text=True, timeout=300)
        assert_that(done.returncode == 0, f"the README's block failed: {done.stderr}")
        printed += done.stdout.split()
    assert_that(len(printed) == 5, f"printed: {printed}")
    assert_close(float(printed[0]), 0.875, 1e-12, "the tiles' areas")
    assert_close(float(printed[1]), 0.555, 1e-12, "the clipped areas")
    assert_close(float(printed[2]), 0.555 / 0.6, 1e-12, "the covered share of the clip's window")
    months = {(r["year"], r["month"]) for r in read_csv(os.path.join(EXAMPLE_DATA, "colorado_monthly_precip.csv"))}
    assert_that(printed[3] == str(len(months)), f"the months: {printed[3]}, {len(months)} in the file")
    assert_that(printed[4] == "2", f"the ridge grouping's curves: {printed[4]}, expected the line and the parabola")


def test_every_script_takes_help():
    # The README's promise, csv_input.py included: it is imported by the other examples, and run
    # (with --help or without arguments) it says so; imported, it prints nothing.
    scripts = sorted(name for name in os.listdir(EXAMPLES) if name.endswith(".py"))
    assert_that("csv_input.py" in scripts and len(scripts) >= 4, f"examples: {scripts}")
    for script in scripts:
        status, stdout, stderr = run_example(script, "--help")
        assert_that(status == 0 and stdout.startswith(f"usage: {script}") and not stderr,
                    f"{script} --help: exit status {status}, {stdout!r}, {stderr!r}")
    status, stdout, stderr = run_example("csv_input.py")
    assert_that(status == 0 and stdout.startswith("usage: csv_input.py") and not stderr,
                f"csv_input.py without arguments: exit status {status}, {stdout!r}, {stderr!r}")
    text = " ".join(stdout.split())
    for fragment in ("module imported by the other examples", "colorado_areal_precipitation.py",
                     "project_gauges.py", "ridge_grouping.py"):
        assert_that(fragment in text, f"csv_input.py does not say {fragment!r}: {stdout!r}")
    status, stdout, stderr = run_example("projected_input.py")
    assert_that(status == 0 and "A module imported by colorado_areal_precipitation.py" in " ".join(stdout.split())
                and not stderr, f"projected_input.py without arguments: exit status {status}, {stdout!r}, {stderr!r}")
    done = subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {EXAMPLES!r}); import csv_input"],
                          capture_output=True, text=True, timeout=60)
    assert_that(done.returncode == 0 and not done.stdout and not done.stderr,
                f"importing csv_input: {done.returncode} {done.stdout!r} {done.stderr!r}")


def test_the_shell_scripts_take_help_anywhere_before_any_work():
    # scripts/demo --no-plots --help ran the setup (root's apt-get) and the whole build before the
    # example printed its help. Each script answers --help (or -h) wherever it stands, at once
    # (a PATH without apt-get, cmake or ninja: any work would fail); demo adds the example's help.
    root = os.path.dirname(EXAMPLES)
    environment = dict(os.environ, PATH="/nonexistent")
    for script in ("build", "demo", "setup", "test"):
        for args in (["--help"], ["--out", "x", "-h"]):
            done = subprocess.run(["/bin/bash", os.path.join(root, "scripts", script)] + args,
                                  capture_output=True, text=True, env=environment, timeout=60)
            assert_that(done.returncode == 0 and done.stdout.startswith(f"usage: scripts/{script}"),
                        f"scripts/{script} {args}: {done.returncode} {done.stdout!r} {done.stderr!r}")
            if script == "demo":
                assert_that("usage: colorado_areal_precipitation.py" in done.stdout,
                            f"demo's help lacks the example's: {done.stdout!r}")
        # An argument that only contains " -h " is no help flag (the script then starts its work,
        # which fails here at once); demo run from its own folder finds the example.
        done = subprocess.run(["/bin/bash", os.path.join(root, "scripts", script), "--out", "a -h b"],
                              capture_output=True, text=True, env=environment, timeout=60)
        assert_that(not done.stdout.startswith("usage:"), f"scripts/{script} took 'a -h b' for -h")
    done = subprocess.run(["/bin/bash", "demo", "--help"], capture_output=True, text=True, env=environment,
                          timeout=60, cwd=os.path.join(root, "scripts"))
    assert_that(done.returncode == 0 and "usage: colorado_areal_precipitation.py" in done.stdout,
                f"demo --help from scripts/: {done.returncode} {done.stderr!r}")


def test_every_benchmark_says_what_it_measures():
    # bench_tessellation and bench_ridge_grouping --help printed only Google Benchmark's flags.
    # Each benchmark program answers --help (and -h) with what it measures, at once, running none.
    programs = os.path.join(os.environ["TESSERA_BUILD_DIR"], "bin")
    benches = sorted(name for name in os.listdir(programs) if name.startswith("bench_"))
    with open(os.path.join(os.environ["TESSERA_BUILD_DIR"], "CMakeCache.txt")) as cache:
        built = "TESSERA_BUILD_BENCH:BOOL=ON" in cache.read()
    assert_that(len(benches) >= 7 or not built, f"benchmarks built: {benches}")
    if not built:
        print("test_every_benchmark_says_what_it_measures: no benchmark built (TESSERA_BUILD_BENCH=OFF): "
              "nothing checked", file=sys.stderr)
    for name in benches:
        for flag in ("--help", "-h"):
            done = subprocess.run([os.path.join(programs, name), flag], capture_output=True, text=True,
                                  timeout=60)
            first = done.stdout.splitlines()[0] if done.stdout else ""
            assert_that(done.returncode == 0 and first and not first.startswith("benchmark ["),
                        f"{name} {flag}: {done.returncode} {done.stdout[:200]!r} {done.stderr[:200]!r}")


def test_without_tessera_on_the_path_the_scripts_say_how_to_run():
    environment = dict(os.environ, PYTHONPATH="")
    done = subprocess.run([sys.executable, os.path.join(EXAMPLES, "project_gauges.py"), "--out",
                           tempfile.gettempdir()], capture_output=True, text=True, env=environment,
                          timeout=60)
    assert_that(done.returncode == 1 and "PYTHONPATH=build/python" in done.stderr
                and "Traceback" not in done.stderr, f"without PYTHONPATH: {done.returncode} {done.stderr}")
    # A Python without VTK (another than Debian's, first on PATH): a vtkmodules that cannot be
    # imported stands in for it. Every script says how to run it, none ends in a traceback.
    with tempfile.TemporaryDirectory() as fake:
        os.makedirs(os.path.join(fake, "vtkmodules"))
        write(os.path.join(fake, "vtkmodules"), "__init__.py", "raise ImportError('No module named vtkmodules')\n")
        environment = dict(os.environ, PYTHONPATH=os.pathsep.join([fake, os.environ.get("PYTHONPATH", "")]))
        for script in ("colorado_areal_precipitation.py", "project_gauges.py", "ridge_grouping.py"):
            done = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), "--out", os.path.join(fake, "out")],
                                  capture_output=True, text=True, env=environment, timeout=60)
            assert_that(done.returncode == 1 and "run with Debian's /usr/bin/python3" in done.stderr
                        and "Traceback" not in done.stderr, f"{script} without VTK: {done.returncode} {done.stderr}")


def test_a_failed_run_removes_the_out_directories_it_made_empty():
    # From a trial: a run that ended on an error left its new --out directory behind, empty. The
    # directories the run made go (the parents too), one that was there stays, and one the run
    # wrote a file into stays with it.
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, observations = write_lake_basin(directory)
        deep = os.path.join(directory, "new", "deeper")
        _, stderr = run_colorado(deep, stations=stations, observations=observations, catchment=catchment,
                                 month="2050-01", plots=False, status=1, what="a month not in the record")
        assert_that("--month 2050-01: is not in the record" in stderr
                    and not os.path.exists(os.path.join(directory, "new")), f"{stderr} {os.listdir(directory)}")
        there = os.path.join(directory, "there")
        os.mkdir(there)
        run_colorado(os.path.join(there, "sub"), stations=stations, observations=observations, catchment=catchment,
                     month="2050-01", plots=False, status=1, what="a month not in the record, --out in a directory")
        assert_that(os.listdir(there) == [], f"{os.listdir(there)}")
        empty = os.path.join(directory, "empty")
        os.mkdir(empty)
        run_colorado(empty, stations=stations, observations=observations, catchment=catchment, month="2050-01",
                     plots=False, status=1, what="a month not in the record, --out an empty directory")
        assert_that(os.path.isdir(empty) and os.listdir(empty) == [], "an empty --out that was there stays")
        held = os.path.join(directory, "held")
        os.mkdir(held)
        write(held, "keep.txt", "a file of the user's\n")
        run_colorado(held, stations=stations, observations=observations, catchment=catchment, month="2050-01",
                     plots=False, status=1, what="a month not in the record, --out holding a file")
        assert_that(os.listdir(held) == ["keep.txt"], f"{os.listdir(held)}")
        # (files read once --out is made, with a value that is not a number)
        bad_points = write(directory, "bad_points.csv", "x,y\n1,2\n3,abc\n")
        bad_gauges = write(directory, "bad_gauges.csv", "station_id,lon,lat\nA,-105,abc\n")
        for script, inputs in (("ridge_grouping.py", ("--planar", "--quakes", bad_points)),
                               ("project_gauges.py", ("--stations", bad_gauges))):
            out = os.path.join(directory, "made_by_" + script)
            status, _, stderr = run_example(script, "--out", out, *inputs)
            assert_that(status == 1 and not os.path.exists(out), f"{script}: {status} {stderr}")


def test_a_month_asked_for_is_never_another_month():
    # From a tester's report: --month 2050-01 (not in the record) wrote 1997-12's weights, tiles and
    # map under a note, exit status 0, and so did a month outside --start/--end. A step asked for is
    # now an error naming it and the steps there are, said once the observations are read, before
    # the long work (nothing is written); the default month still chooses the record's nearest.
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, observations = write_lake_basin(directory)
        common = {"stations": stations, "observations": observations, "catchment": catchment}
        for options, expected in (
                ({"month": "2050-01"}, f"--month 2050-01: is not in the record of {observations} (its months run "
                                       "from 2001-01 to 2001-02); give a month of the record"),
                ({"month": "2000-12"}, f"--month 2000-12: is not in the record of {observations}"),
                ({"month": "2001-01", "start": "2001-02"}, "--month 2001-01: is outside --start 2001-02 (the months "
                                                          "averaged run from 2001-02 to 2001-02); give a month within "
                                                          "them")):
            out = os.path.join(directory, "out_" + "_".join(options.values()))
            _, stderr = run_colorado(out, plots=False, status=1, what=f"{options}", **common, **options)
            assert_that(stderr_messages(stderr)[-1].startswith(expected) and "showing" not in stderr
                        and "Traceback" not in stderr, f"{options}: expected {expected!r}, got {stderr!r}")
            assert_that(not os.path.exists(out), f"{options}: wrote into {out} (or left it made)")
        # Both --month values are checked, the good one first not shown alone.
        out = os.path.join(directory, "two")
        _, stderr = run_colorado(out, "--month", "2001-02", "--month", "1999-01", plots=False, status=1,
                                 what="a good and a bad month", **common)
        assert_that("--month 1999-01: is not in the record" in stderr and not os.path.exists(out), stderr)
        # Without --month, for observations other than the Colorado example's: the record's last
        # month where a gauge reported (a trial's own record was shown at the month nearest 1963-08),
        # no note; a month after it with only missing values is passed over.
        stdout, stderr = run_colorado(os.path.join(directory, "default"), plots=False, what="the default", **common)
        assert_that("2001-02: areal mean" in stdout and "note:" not in stderr, f"{stdout} {stderr}")
        with open(observations) as f:
            emptied = write(directory, "emptied.csv", f.read() + "N1,2001,3,\nN6,2001,3,NaN\n")
        stdout, stderr = run_colorado(os.path.join(directory, "emptied"), plots=False, what="a last month without data",
                                      **dict(common, observations=emptied))
        assert_that("2001-02: areal mean" in stdout and os.path.exists(os.path.join(directory, "emptied",
                                                                                    "weights_2001_02.csv")),
                    f"{stdout} {stderr}")
        # The tester's runs on the Colorado record: the error comes after the reading, before the
        # 1236 months are averaged.
        for arguments, expected in ((("--month", "2050-01"),
                                     "--month 2050-01: is not in the record of "
                                     f"{os.path.join(EXAMPLE_DATA, 'colorado_monthly_precip.csv')} (its months run "
                                     "from 1895-01 to 1997-12)"),
                                    (("--month", "1963-08", "--start", "1990-01", "--end", "1991-01"),
                                     "--month 1963-08: is outside --start 1990-01 and --end 1991-01 (the months "
                                     "averaged run from 1990-01 to 1991-01)")):
            out = os.path.join(directory, "colorado")
            _, stderr = run_colorado(out, *arguments, plots=False, status=1, what=" ".join(arguments))
            assert_that(stderr_messages(stderr)[-1].startswith(expected) and "Thiessen areal means" not in stderr,
                        f"{arguments}: expected {expected!r}, got {stderr!r}")


def test_a_month_the_record_covers_in_part_is_shown_from_its_first_step():
    # From a reviewer's report: --month on daily data was its first day, so a record starting
    # 2001-01-15 (or --start 2001-01-16) refused --month 2001-01 as "not in the record"; and with
    # --start alone the message said the record's days ran from --start. A --month (a --day of
    # hours) is shown from its first step in the record and the period, and a refusal with a
    # period gives the steps averaged.
    days = {(2001, 1, 15): {"N1": 1.5, "N2": 2.5, "N3": 4.0}, (2001, 1, 16): {"N1": 3.0, "N4": 1.25},
            (2001, 2, 1): {"N2": 0.5, "N5": 3.5}}
    with tempfile.TemporaryDirectory() as directory:
        catchment, stations, _ = write_lake_basin(directory)
        daily = write_daily(directory, "daily.csv", days)
        hourly = write(directory, "hourly.csv", "station_id,date,precip\nN1,2001-01-15 06:00,1\nN2,2001-01-15 07:00,2\n"
                       "N3,2001-01-16 00:00,3\n")
        common = {"stations": stations, "catchment": catchment}
        for observations, options, shown in ((daily, {"month": "2001-01"}, "2001-01-15"),
                                             (daily, {"month": "2001-01", "start": "2001-01-16"}, "2001-01-16"),
                                             (daily, {"month": "2001-02", "end": "2001-02-10"}, "2001-02-01"),
                                             (hourly, {"day": "2001-01-15"}, "2001-01-15 06:00"),
                                             (hourly, {"month": "2001-01", "start": "2001-01-15 07:00"},
                                              "2001-01-15 07:00")):
            what = f"{os.path.basename(observations)} {options}"
            out = os.path.join(directory, "out_" + re.sub(r"\W", "_", what))
            stdout, stderr = run_colorado(out, plots=False, what=what, observations=observations, **common, **options)
            tag = re.sub(r"[- ]", "_", shown.replace(":00", ""))
            assert_that(f"{shown}: areal mean" in stdout and os.path.exists(os.path.join(out, f"weights_{tag}.csv"))
                        and "internal error" not in stderr, f"{what}: expected {shown} shown: {stdout} {stderr}")
        for options, expected in (
                ({"month": "2001-03", "start": "2001-01-10"},
                 f"--month 2001-03: is not in the record of {daily} (the days averaged run from 2001-01-10 to "
                 "2001-02-01); give a day of the record"),
                ({"month": "2000-12", "start": "2001-01-10"},
                 "--month 2000-12: is outside --start 2001-01-10 (the days averaged run from 2001-01-10 to "
                 "2001-02-01); give a day within them"),
                ({"month": "2001-03"}, f"--month 2001-03: is not in the record of {daily} (its days run from "
                                       "2001-01-15 to 2001-02-01)")):
            out = os.path.join(directory, "refused")
            _, stderr = run_colorado(out, plots=False, status=1, what=f"{options}", observations=daily, **common,
                                     **options)
            assert_that(stderr_messages(stderr)[-1].startswith(expected) and "Traceback" not in stderr,
                        f"{options}: expected {expected!r}, got {stderr!r}")
            assert_that(not os.path.exists(out), f"{options}: wrote into {out} (or left it made)")


def test_an_out_directory_that_takes_no_file_is_named_before_any_work():
    # From a tester's report: an --out directory that exists but takes no file was named only
    # when the first output was written, after all the work. Each script now tries a file there
    # before reading its inputs (a missing input file shows that nothing was read first). Root
    # writes into a directory without write permission, so the case that stops everyone is /proc
    # (no file can be made there); a read-only directory is tried where the tests do not run as root.
    with tempfile.TemporaryDirectory() as directory:
        missing = os.path.join(directory, "missing.csv")
        outs = []
        if os.path.isdir("/proc"):
            outs.append("/proc")
        if os.geteuid() != 0:
            locked = os.path.join(directory, "locked")
            os.makedirs(locked)
            os.chmod(locked, 0o555)
            outs.append(locked)
        for out in outs:
            for script, inputs in (("colorado_areal_precipitation.py", ("--stations", missing, "--catchment", missing)),
                                   ("ridge_grouping.py", ("--quakes", missing)),
                                   ("project_gauges.py", ("--stations", missing))):
                status, stdout, stderr = run_example(script, "--out", out, *inputs)
                what = f"{script} --out {out}"
                assert_that(status == 1 and len(stderr.splitlines()) == 1
                            and stderr.startswith(f"--out {out}: no file can be made there (") and not stdout,
                            f"{what}: status {status}, {stderr!r}")
        if os.geteuid() != 0:
            assert_that(os.listdir(locked) == [], f"left in the locked directory: {os.listdir(locked)}")
        # An empty --out is named as such (it was "cannot create the directory").
        status, _, stderr = run_example("project_gauges.py", "--out", "")
        assert_that(status == 1 and stderr.strip() == "--out '': an empty path (give a directory, such as out)",
                    f"--out '': {status} {stderr!r}")
        # A directory that takes files: the probe leaves nothing behind.
        out = os.path.join(directory, "fine")
        status, _, stderr = run_example("project_gauges.py", "--out", out)
        assert_that(status == 0 and sorted(os.listdir(out)) == ["gauges_projected.csv", "gauges_projected.vtp"],
                    f"{status} {stderr} {os.listdir(out)}")


def test_an_out_directory_says_whether_the_test_file_could_be_made_or_removed():
    # From a reviewer's report: output_directory reported a failed make and a failed remove of its
    # test file as one "cannot write there (...)", and /proc, a directory that is there, as "No such
    # file or directory". The make's error is said as why no file can be made there; a remove that
    # fails is a warning naming the file left behind, and the run goes on (files can be written).
    import contextlib
    import errno
    import io

    csv_input = import_example("csv_input")
    with tempfile.TemporaryDirectory() as directory:
        make, remove = csv_input.tempfile.mkstemp, csv_input.os.remove
        for number, reason in ((errno.EACCES, "no permission to write in it"),
                               (errno.EROFS, "a read-only file system"),
                               (errno.ENOENT, "the system refused a new file: No such file or directory")):
            def refused(*arguments, **options):
                raise OSError(number, os.strerror(number))
            csv_input.tempfile.mkstemp = refused
            try:
                csv_input.output_directory(directory)
            except SystemExit as error:
                assert_that(str(error) == f"--out {directory}: no file can be made there ({reason})",
                            f"{errno.errorcode[number]}: {error}")
            else:
                raise AssertionError(f"{errno.errorcode[number]}: the directory was taken")
            finally:
                csv_input.tempfile.mkstemp = make
        # A byte that cannot be written (a full disk with inodes left, or told at the close): said
        # as no file written there, and the empty test file removed.
        write = csv_input.os.write
        def full(*arguments):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        csv_input.os.write = full
        try:
            csv_input.output_directory(directory)
        except SystemExit as error:
            assert_that(str(error) == f"--out {directory}: no file can be written there (no space left on the device)"
                        and not os.listdir(directory), f"ENOSPC at the write: {error} {os.listdir(directory)}")
        else:
            raise AssertionError("ENOSPC at the write: the directory was taken")
        finally:
            csv_input.os.write = write
        def kept(path):
            raise OSError(errno.EPERM, os.strerror(errno.EPERM))
        said = io.StringIO()
        csv_input.os.remove = kept
        try:
            with contextlib.redirect_stderr(said):
                csv_input.output_directory(directory)
        finally:
            csv_input.os.remove = remove
        left = os.listdir(directory)
        assert_that(len(left) == 1 and said.getvalue() == f"warning: --out {directory}: a test file made there could "
                    f"not be removed ({os.strerror(errno.EPERM)}); it is left behind: "
                    f"{os.path.join(directory, left[0])}\n", f"{left}: {said.getvalue()!r}")


def test_empty_option_values_are_named():
    # From a tester's report: an empty --crs, --stations-crs or --stations-utm was taken as the
    # option left out, and an empty file path gave ": no such catchment file", naming nothing. Each
    # is now one line naming the option, before any work (no --out is made).
    with tempfile.TemporaryDirectory() as directory:
        out = os.path.join(directory, "out")
        cases = [
            ("project_gauges.py", ("--crs", ""), "--crs '': expected EPSG:CODE (such as EPSG:5070) or PROJ terms"),
            ("project_gauges.py", ("--crs", " "), "--crs ' ': expected EPSG:CODE"),
            ("colorado_areal_precipitation.py", ("--stations-crs", ""), "--stations-crs '': expected EPSG:CODE"),
            ("colorado_areal_precipitation.py", ("--stations-utm", ""),
             "--stations-utm '': expected a UTM zone 1 to 60 with N or S"),
            ("colorado_areal_precipitation.py", ("--stations-utm", "", "--stations-crs", "EPSG:5070"),
             "--stations-utm and --stations-crs: give one of them"),
            ("colorado_areal_precipitation.py", ("--catchment", ""),
             "--catchment '': an empty path (give the catchment file)"),
            ("colorado_areal_precipitation.py", ("--stations", ""),
             "--stations '': an empty path (give the stations file)"),
            ("colorado_areal_precipitation.py", ("--observations", ""),
             "--observations '': an empty path (give the observations file)"),
            ("ridge_grouping.py", ("--quakes", ""), "--quakes '': an empty path (give the epicentres file)"),
            ("ridge_grouping.py", ("--quakes", "", "--planar"), "--quakes '': an empty path (give the points file)"),
            ("project_gauges.py", ("--stations", ""), "--stations '': an empty path (give the stations file)"),
        ]
        for script, arguments, expected in cases:
            status, stdout, stderr = run_example(script, "--out", out, *arguments)
            what = f"{script} {arguments}"
            assert_that(status == 1 and len(stderr.splitlines()) == 1 and stderr.startswith(expected)
                        and not stdout, f"{what}: expected one line starting {expected!r}, got {status} {stderr!r}")
            assert_that(not os.path.exists(out), f"{what}: made --out before the option was checked")


def test_project_gauges_names_an_unknown_epsg_code_alone():
    # From a tester's report: GDAL's own "ERROR 1: PROJ: proj_create_from_database: crs not found"
    # came before the script's line; it goes to the script's GDAL log now, as in the main job.
    with tempfile.TemporaryDirectory() as out:
        status, stdout, stderr = run_example("project_gauges.py", "--out", out, "--crs", "EPSG:99999")
        assert_that(status == 1 and stderr.splitlines() == ["--crs 'EPSG:99999': GDAL's database has no such EPSG "
                                                            "code"] and not stdout, f"{status} {stderr!r}")
        assert_that("CPL_LOG" not in os.environ, "CPL_LOG set in the tests' environment")


def test_ridge_grouping_refuses_a_prefix_that_is_not_a_names_start():
    # From a tester's report: --prefix a/b ran the whole grouping and then failed to write, and
    # --prefix ../escape wrote the files beside --out, not into it. A prefix with a path separator,
    # or one that is empty, . or .., is refused at the start, nothing written anywhere.
    with tempfile.TemporaryDirectory() as directory:
        out = os.path.join(directory, "out")
        separators = sorted({os.sep, "/", os.altsep} - {None})
        cases = [(f"a{separators[0]}b", "holds the path separator"), ("../escape", "holds the path separator"),
                 ("", "an empty prefix"), (".", "is not the start of a file's name"),
                 ("..", "is not the start of a file's name")]
        for prefix, fragment in cases:
            status, stdout, stderr = run_example("ridge_grouping.py", "--out", out, "--prefix", prefix)
            assert_that(status == 1 and len(stderr.splitlines()) == 1
                        and stderr.startswith(f"--prefix {prefix!r}: {fragment}") and not stdout,
                        f"--prefix {prefix!r}: {status} {stderr!r}")
            assert_that(os.listdir(directory) == [], f"--prefix {prefix!r}: wrote {os.listdir(directory)}")


def test_repeated_points_and_gauges_are_named_with_their_lines():
    # From a tester's report: ridge_grouping.py and project_gauges.py said nothing of repeated
    # epicentres, of a station id given twice, or of gauges at one place. Each is named now, as the
    # main job names a shared station id ("102 (gauges 0 and 1: lines 2 and 3)"), ids compared as
    # it compares them (station_key: 0102 and 102, 50109.0 and 50109 are one), and still used as
    # before: the Fiji file's two repeated epicentres are grouped, all 1000 points in the output.
    # From a reviewer's report: every run of the demo warned of those two; the bundled file's are a
    # note on stdout, and a file of the user's own is warned of, with the lines.
    fiji = os.path.join(EXAMPLE_DATA, "fiji_quakes.csv")
    with tempfile.TemporaryDirectory() as out:
        status, stdout, stderr = run_example("ridge_grouping.py", "--out", out)
        assert_that(status == 0 and "repeat the lon, lat" not in stderr and "note: 2 epicentre(s) of the Fiji file "
                    "repeat an earlier one's place (lines 396 as 328, 781 as 151;" in stdout,
                    f"ridge_grouping.py: {stdout} {stderr}")
        points = read_polydata(os.path.join(out, "fiji_points.vtp"))
        assert_that(points.GetNumberOfPoints() == 1000, f"{points.GetNumberOfPoints()} points grouped")
        with open(fiji) as f:
            own = write(out, "my_quakes.csv", f.read())
        status, stdout, stderr = run_example("ridge_grouping.py", "--out", out, "--quakes", own)
        expected = (f"{own}: 2 epicentre(s) repeat the lon, lat of an earlier one (each is grouped, a point of its "
                    "own: the place weighs as often in the field): lon 181.2, lat -21.04 (points 326 and 394: lines "
                    "328 and 396), lon 181.5, lat -17.9 (points 149 and 779: lines 151 and 781)")
        assert_that(status == 0 and expected in stderr.splitlines() and "note:" not in stdout,
                    f"ridge_grouping.py --quakes {own}: {stdout} {stderr}")
        stations = write(out, "repeated.csv", "station_id,lon,lat\nA,-105,39\nB,-104,40\n\nA,-103,38\nC,-104,40\n"
                         "D,-104.5,39.5\n0102,-103.5,38.5\n102,-103.2,38.7\n50109.0,-104.2,39.1\n50109,-104.3,39.2\n")
        status, _, stderr = run_example("project_gauges.py", "--out", out, "--stations", stations)
        assert_that(status == 0 and stderr.splitlines() == [
            f"{stations}: 3 station id(s) are given to more than one gauge (each is projected): A (gauges 0 and 2: "
            "lines 2 and 5), 102 (as 0102) (gauges 5 and 6: lines 8 and 9), 50109 (as 50109.0) (gauges 7 and 8: "
            "lines 10 and 11)",
            f"{stations}: 1 gauge(s) stand where an earlier gauge stands (each is projected): C (same place as B) "
            "(gauges 1 and 3: lines 3 and 6)"], f"project_gauges.py: {stderr!r}")
        projected = read_csv(os.path.join(out, "gauges_projected.csv"))
        assert_that([r["station_id"] for r in projected]
                    == ["A", "B", "A", "C", "D", "0102", "102", "50109.0", "50109"], f"{projected}")


def test_project_gauges_refits_every_gauge_that_could_move_the_fit():
    # far_gauges refits (with vtkGeographicProjection) only the gauges could_move picks, those whose
    # leaving out can move a fit to the gauges' extent: held here to refitting every gauge, on sets
    # with ties, shared longitudes, equal gaps and the antimeridian, for each conic.
    project_gauges = import_example("project_gauges")
    rng = random.Random(12)
    for case in range(60):
        count = rng.randint(project_gauges.FAR_FEWEST, 11)
        step = rng.choice((0.0, 1.0, 7.5))  # (whole steps make ties and equal gaps)
        west, width = rng.uniform(-180, 180), rng.choice((3.0, 40.0, 150.0, 300.0))
        lons, lats = [], []
        for _ in range(count):
            lon = west + rng.uniform(0, width)
            lons.append(math.remainder(round(lon / step) * step if step else lon, 360.0))
            lats.append(round(rng.uniform(-60, 60)) if step else rng.uniform(-60, 60))
        if rng.random() < 0.3:
            lons.append(math.remainder(lons[0] + rng.choice((0.0, 90.0, 170.0)), 360.0))
            lats.append(rng.uniform(-80, 80))
        projection = project_gauges.CONICS[case % len(project_gauges.CONICS)]
        whole = project_gauges.fitted_terms(lons, lats, projection)
        lowest = 0.0 if min(lats) <= 0.0 <= max(lats) else min(abs(lat) for lat in lats)
        expected = {}
        for i in range(len(lons)):
            rest_lons, rest_lats = lons[:i] + lons[i + 1:], lats[:i] + lats[i + 1:]
            part = project_gauges.fitted_terms(rest_lons, rest_lats, projection)
            turned = sorted(lon % 360.0 for lon in rest_lons)
            span = 360.0 - max([turned[0] + 360.0 - turned[-1]] + [b - a for a, b in zip(turned, turned[1:])])
            move = max(abs(part[1] - whole[1]), abs(part[2] - whole[2]))
            if span < project_gauges.FAR_ROUND_DEGREES:
                move = max(move, abs(math.remainder(part[0] - whole[0], 360.0)) * math.cos(math.radians(lowest)))
            if move > project_gauges.FAR_DEGREES:
                expected[i] = move
        found = dict(project_gauges.far_gauges(lons, lats, projection))
        assert_that(found.keys() == expected.keys() and all(abs(found[k] - expected[k]) < 1e-9 for k in found),
                    f"case {case} {projection} {list(zip(lons, lats))}: far_gauges {found}, "
                    f"every gauge refitted {expected}")
    # A projection that is no conic is not measured (it has no parallels; UTM reads a zone).
    assert_that(project_gauges.far_gauges([0, 1, 2, 3, 80], [0, 1, 2, 3, 4], "utm") == [], "utm measured")


def test_project_gauges_names_gauges_that_move_the_fitted_projection():
    # From a tester's report: one gauge at lon 200 (for -160), or one in Germany among the Colorado
    # gauges, moved the automatic projection's central meridian by 25 to 55 degrees without a word.
    # The projection's line gives its parameters, and a warning names the gauges without any one of
    # which the fit would move by more than 2 degrees, with their lines; the Colorado file alone,
    # and a projection given by --crs, get no warning. From a reviewer's report on the first rule
    # (6 median absolute deviations from the median): it named gauges of networks dense in one part
    # and sparse in another, and none of CONUS with one gauge in Alaska and one in Hawaii.
    stations = os.path.join(EXAMPLE_DATA, "colorado_stations.csv")
    with open(stations) as f:
        colorado = f.read()
    warned = "move the fitted projection"
    with tempfile.TemporaryDirectory() as out:
        status, stdout, stderr = run_example("project_gauges.py", "--out", out)
        assert_that(status == 0 and warned not in stderr and "lon0=-105.25" in stdout, f"{stdout} {stderr}")
        for name, row, shown in (("pacific", "X1,Far,200,39,1000", "X1 at lon 200, lat 39 (line 378: 20.3 degrees)"),
                                 ("germany", "X2,Kassel,9.5,51.3,160",
                                  "X2 at lon 9.5, lat 51.3 (line 378: 44.4 degrees)")):
            path = write(out, f"{name}.csv", colorado + row + "\n")
            status, stdout, stderr = run_example("project_gauges.py", "--out", out, "--stations", path)
            warning = [line for line in stderr.splitlines() if warned in line]
            assert_that(status == 0 and len(warning) == 1 and warning[0].startswith(f"{path}: warning: 1 gauge(s) "
                                                                                    f"{warned}")
                        and warning[0].endswith(shown) and "projected 377 gauges with projection=AlbersEqualArea"
                        in stdout, f"{name}: {stdout} {stderr}")
            status, _, stderr = run_example("project_gauges.py", "--out", out, "--stations", path, "--crs", "EPSG:5070")
            assert_that(status == 0 and warned not in stderr, f"{name} with --crs: {stderr}")
        spread = random.Random(5)
        def gauges(boxes):
            """Gauges spread at random over boxes ((count, west, east, south, north)), as CSV rows."""
            return "station_id,lon,lat\n" + "".join(
                f"S{k}_{j},{spread.uniform(west, east):.4f},{spread.uniform(south, north):.4f}\n"
                for k, (count, west, east, south, north) in enumerate(boxes) for j in range(count))
        conus = gauges([(300, -124, -67, 25, 49)])
        quiet = {
            # Gauges spread evenly over a continent.
            "spread": "station_id,lon,lat\n" + "".join(f"S{k},{-124 + 0.5 * k},{25 + 0.2 * k}\n" for k in range(120)),
            # Australia's east coast, and fewer gauges in Western Australia and the Northern Territory.
            "australia": gauges([(300, 145, 154, -38, -16), (50, 114, 138, -35, -12)]),
            # A US network heavy in the east, with 40 gauges in the west.
            "east_heavy": gauges([(400, -88, -70, 30, 45), (40, -124, -104, 32, 48)]),
            # Three gauges (none is "the rest" of the other two).
            "three": "station_id,lon,lat\nA,0,0\nB,1,0\nC,10,0\n",
            # Gauges near the pole, a few 20 to 50 degrees of longitude east of the rest: 2 to 4
            # degrees of arc.
            "arctic": gauges([(60, 0, 40, 85, 89), (6, 60, 90, 86, 89)]),
            "conus": conus}
        for name, text in quiet.items():
            status, _, stderr = run_example("project_gauges.py", "--out", out, "--stations", write(out, f"{name}.csv",
                                                                                                   text))
            assert_that(status == 0 and warned not in stderr, f"{name}: {stderr}")
        # CONUS with a gauge in Alaska and one in Hawaii: each moves the fit on its own.
        path = write(out, "fifty.csv", conus + "AK,-149.9,61.2\nHI,-157.86,21.31\n")
        status, _, stderr = run_example("project_gauges.py", "--out", out, "--stations", path)
        warning = [line for line in stderr.splitlines() if warned in line]
        assert_that(status == 0 and len(warning) == 1 and f"{path}: warning: 2 gauge(s) {warned}" in warning[0]
                    and "AK at lon -149.9, lat 61.2 (line 302: " in warning[0]
                    and "HI at lon -157.86, lat 21.31 (line 303: " in warning[0], f"Alaska and Hawaii: {stderr}")
        status, stdout, _ = run_example("project_gauges.py", "--help")
        assert_that("left out alone" in " ".join(stdout.split()) and "2 degrees" in " ".join(stdout.split()),
                    f"--help: {stdout}")


if __name__ == "__main__":
    run([test_utm_gauges_across_the_equator_give_the_lon_lat_means,
         test_catchment_features_without_geometry_or_crossing_holes_are_named_as_such, test_the_colorado_main_job, test_missing_values_keep_their_months, test_bad_files_are_named,
         test_outputs_that_cannot_be_written_are_named, test_a_hole_outside_its_polygon_is_named,
         test_the_map_of_another_place_with_a_lake,
         test_the_map_of_a_catchment_wide_in_longitude_keeps_its_tiles_over_it,
         test_tile_polygons_are_moved_within_180_by_their_side_of_the_meridian,
         test_a_lake_touching_the_outline_and_catchments_of_several_features,
         test_each_group_of_features_gets_its_means,
         test_a_month_without_reports_still_gets_its_map,
         test_the_time_series_breaks_at_months_without_a_mean,
         test_ids_without_their_leading_zeros_match_as_in_the_filter,
         test_files_of_semicolons_or_tabs_with_decimal_commas,
         test_daily_observations_give_daily_means,
         test_finer_means_add_up_to_totals, test_hourly_observations_give_hourly_means, test_observations_of_minutes_give_a_mean_each_step,
         test_times_off_the_steps_and_gauges_of_other_steps_are_named,
         test_sum_to_sums_each_gauges_values_into_longer_steps,
         test_start_and_end_choose_the_period,
         test_a_wide_file_of_a_column_per_station_gives_the_long_files_means,
         test_an_earlier_runs_files_in_out_are_named,
         test_several_days_get_the_files_each_gets_alone,
         test_the_field_separator_and_the_decimal_mark,
         test_decimal_commas_are_told_by_the_columns_read_as_numbers,
         test_decimal_commas_in_quoted_fields_are_read, test_lines_ending_in_a_lone_cr_read_decimal_commas,
         test_fields_after_a_comma_and_a_space_may_be_quoted, test_unused_inputs_notes_name_where_the_values_went,
         test_the_help_says_what_unused_inputs_lists,
         test_small_values_and_a_catchment_across_the_antimeridian,
         test_observations_of_no_gauge_end_the_run,
         test_compressed_observations_are_read_and_all_weights_can_be_skipped,
         test_text_lines_split_as_a_string_io_does,
         test_reading_a_large_file_says_how_far_it_got,
         test_a_catchment_in_a_zip_file_is_read_from_it,
         test_a_catchment_declared_projected_is_named, test_gauges_and_a_catchment_in_a_utm_zone_give_the_lon_lat_means,
         test_catchments_and_gauges_in_projected_systems_give_the_lon_lat_means,
         test_catchment_geopackage_in_metres_beside_a_layer_of_lon_lat_points,
         test_a_plain_id_or_site_no_column_is_the_station_id_where_no_station_column_is,
         test_a_long_files_unnamed_columns_are_named_as_not_read,
         test_a_noaa_climate_data_online_file_is_both_stations_and_observations,
         test_gauges_from_a_gis_file_of_points_give_the_csv_means,
         test_the_filters_errors_name_the_file_and_line,
         test_the_filters_warnings_are_lines_of_their_own,
         test_rows_of_empty_fields_are_skipped,
         test_the_messages_map_to_files_and_lines,
         test_the_other_examples_run_on_their_data,
         test_ridge_grouping_names_a_bad_epicentre_alone,
         test_ridge_grouping_tunes_only_the_fiji_file,
         test_ridge_grouping_says_the_projections_warning_as_a_line_of_its_own,
         test_ridge_grouping_checks_its_out_directory_first,
         test_project_gauges_names_a_bad_gauge_by_its_line,
         test_project_gauges_writes_a_projected_systems_own_numbers,
         test_progress_into_a_log_is_lines_of_its_own,
         test_the_readme_python_runs,
         test_every_script_takes_help,
         test_the_shell_scripts_take_help_anywhere_before_any_work,
         test_every_benchmark_says_what_it_measures,
         test_without_tessera_on_the_path_the_scripts_say_how_to_run,
         test_a_month_asked_for_is_never_another_month,
         test_a_failed_run_removes_the_out_directories_it_made_empty,
         test_a_month_the_record_covers_in_part_is_shown_from_its_first_step,
         test_an_out_directory_that_takes_no_file_is_named_before_any_work,
         test_an_out_directory_says_whether_the_test_file_could_be_made_or_removed,
         test_empty_option_values_are_named,
         test_project_gauges_names_an_unknown_epsg_code_alone,
         test_ridge_grouping_refuses_a_prefix_that_is_not_a_names_start,
         test_repeated_points_and_gauges_are_named_with_their_lines,
         test_project_gauges_names_gauges_that_move_the_fitted_projection,
         test_project_gauges_refits_every_gauge_that_could_move_the_fit])
