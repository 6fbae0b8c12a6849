#!/usr/bin/env python3
"""Project rain gauges given in longitude/latitude to a plane with Tessera's
vtkGeographicProjection, and write them out.

Reads a CSV with columns station_id, lon, lat and optional name, elev_m (default: the 376 Colorado gauges in
examples/data/colorado_stations.csv) and writes into --out:
  gauges_projected.vtp   the gauges as VTK points (x, y in metres, z = elevation), with point data
                         StationId, Name, Longitude, Latitude, and field data TesseraProjection;
  gauges_projected.csv   station_id, name, lon, lat, x_m, y_m; with --crs also x_crs, y_crs: the
                         coordinates in that system's own unit (its feet, for a state plane in feet).

--projection picks one of the filter's projections, fitted to the gauges; --crs gives a projected
coordinate system by its EPSG code or PROJ terms (as the main job's --stations-crs reads them: UTM,
tmerc, aea, lcc, laea, merc, in metres or feet), whose own numbers then come out: EPSG:5070 (NAD83 /
Conus Albers) gives that system's eastings and northings, false origin and all.

The other projections are fitted to the gauges (their centre, parallels, UTM zone), so that one
gauge far from the rest (a lon of 200 for -160, a gauge of another country) moves them: the line
the script prints gives the projection's parameters, and gauges far from the rest are named in a
warning, with their lines. A gauge is far from the rest where its lon or lat lies more than
FAR_DEGREES (5) degrees, and more than FAR_DEVIATIONS (6) times the gauges' median absolute
deviation, from the gauges' median (lon taken across the antimeridian). A station id given to more
than one gauge, and gauges at one place, are named too (each is projected and written).

Run it with Debian's /usr/bin/python3 and PYTHONPATH pointing to build/python (scripts/demo does).
"""

import argparse
import csv
import math
import os
import re
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import csv_input  # noqa: E402 (the examples' CSV reading, beside this script)
import projected_input  # noqa: E402 (the projected systems read, beside this script)

PROJECTIONS = {
    "automatic": "SetProjectionToAutomatic",
    "albers": "SetProjectionToAlbersEqualArea",
    "lambert": "SetProjectionToLambertConformalConic",
    "tmerc": "SetProjectionToTransverseMercator",
    "utm": "SetProjectionToUTM",
    "azimuthal": "SetProjectionToAzimuthalEquidistant",
    "laea": "SetProjectionToLambertAzimuthalEqualArea",
    "mercator": "SetProjectionToMercator",
    "webmercator": "SetProjectionToWebMercator",
}


# A gauge far from the rest (far_gauges): beyond both, in lon or lat, from the gauges' median.
FAR_DEGREES = 5.0
FAR_DEVIATIONS = 6.0


def wrapped(degrees):
    """A difference of longitudes within -180 .. 180."""
    return (degrees + 180.0) % 360.0 - 180.0


def far_gauges(lons, lats):
    """The indices of the gauges that lie far from the rest: their lon or lat more than FAR_DEGREES
    and more than FAR_DEVIATIONS median absolute deviations from the gauges' median (a rule of
    medians, which the outlying gauges themselves barely move, where a fitted projection's centre
    moves by half their distance). Longitudes are differences from the gauges' circular mean,
    within 180 degrees, so that gauges on both sides of the antimeridian are near one another."""
    if len(lons) < 3:
        return []
    east = statistics.fmean(math.cos(math.radians(lon)) for lon in lons)
    north = statistics.fmean(math.sin(math.radians(lon)) for lon in lons)
    centre = math.degrees(math.atan2(north, east)) if (east, north) != (0.0, 0.0) else lons[0]
    far = set()
    for values in ([wrapped(lon - centre) for lon in lons], list(lats)):
        middle = statistics.median(values)
        off = [abs(value - middle) for value in values]
        limit = max(FAR_DEGREES, FAR_DEVIATIONS * statistics.median(off))
        far.update(k for k, value in enumerate(off) if value > limit)
    return sorted(far)


def say_far_gauges(path, gauges, lines):
    """Warns of the gauges far from the rest (far_gauges), naming each with its line: a projection
    fitted to the gauges takes them in, and its centre and parallels are not those of the rest."""
    points = [gauges.GetPoint(k)[:2] for k in range(gauges.GetNumberOfPoints())]
    far = far_gauges([lon for lon, _ in points], [lat for _, lat in points])
    if far:
        station = gauges.GetPointData().GetAbstractArray("StationId")
        shown = ", ".join(f"{station.GetValue(k)} at lon {points[k][0]:.15g}, lat {points[k][1]:.15g} "
                          f"(line {lines[k]})" for k in far[:20])
        more = f" and {len(far) - 20} more" if len(far) > 20 else ""
        print(f"{path}: warning: {len(far)} gauge(s) lie far from the rest (more than {FAR_DEGREES:g} degrees and "
              f"{FAR_DEVIATIONS:g} median absolute deviations from the gauges' median lon or lat); the projection, "
              f"fitted to all the gauges, is moved by them (a mistyped place? --crs gives a projection of its own): "
              f"{shown}{more}", file=sys.stderr)


def say_repeated_gauges(path, gauges, lines):
    """Names the gauges that repeat an earlier gauge's station id or place (csv_input.say_repeats),
    as the main job names them: each is projected and written all the same."""
    station = gauges.GetPointData().GetAbstractArray("StationId")
    ids = [station.GetValue(k) for k in range(gauges.GetNumberOfPoints())]
    places = [gauges.GetPoint(k)[:2] for k in range(gauges.GetNumberOfPoints())]
    csv_input.say_repeats(path, lines, ids, "station id(s) are given to more than one gauge (each is projected)",
                          lambda k, first: ids[k], "gauge")
    csv_input.say_repeats(path, lines, places, "gauge(s) stand where an earlier gauge stands (each is projected)",
                          lambda k, first: f"{ids[k]} (same place as {ids[first]})", "gauge")


def read_gauges(path):
    """The gauges as vtkPolyData (one vertex each), and the stations file's line of each gauge
    (gauge i is the file's i-th record); names the row of any coordinate that is not a number."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints, vtkStringArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    points = vtkPoints()
    points.SetDataTypeToDouble()
    ids, names = vtkStringArray(), vtkStringArray()
    ids.SetName("StationId")
    names.SetName("Name")
    lon_array, lat_array = vtkDoubleArray(), vtkDoubleArray()
    lon_array.SetName("Longitude")
    lat_array.SetName("Latitude")
    lines = []
    for line, row, station, name, lon, lat in csv_input.gauges(path, ("elev_m",)):
        lines.append(line)
        missing_elevation = csv_input.is_missing(row.get("elev_m"))
        elev = 0.0 if missing_elevation else csv_input.number(row, "elev_m", path, line)
        points.InsertNextPoint(lon, lat, elev)
        ids.InsertNextValue(station)
        names.InsertNextValue(name)
        lon_array.InsertNextValue(lon)
        lat_array.InsertNextValue(lat)
    gauges = vtkPolyData()
    gauges.SetPoints(points)
    verts = vtkCellArray()
    for i in range(points.GetNumberOfPoints()):
        verts.InsertNextCell(1)
        verts.InsertCellPoint(i)
    gauges.SetVerts(verts)
    for array in (ids, names, lon_array, lat_array):
        gauges.GetPointData().AddArray(array)
    return gauges, lines


def projection_error(text, path, gauges, lines):
    """The one line that reports the projection's error `text`: a bad gauge by the stations file's
    line and its station, any other error by the file."""
    station = gauges.GetPointData().GetAbstractArray("StationId")
    return (csv_input.point_error(text, path, lines, lambda g: f"station {station.GetValue(g)}")
            or f"{path}: cannot project the gauges: {text}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stations", default=os.path.join(HERE, "data", "colorado_stations.csv"),
                        help="CSV of gauges: columns station_id, lon, lat (degrees), optional name, elev_m; "
                             f"{csv_input.SEPARATORS_TEXT}")
    chosen = parser.add_mutually_exclusive_group()
    chosen.add_argument("--projection", choices=sorted(PROJECTIONS), default="automatic",
                        help="map projection, fitted to the gauges (default: automatic Albers equal-area); "
                             f"gauges more than {FAR_DEGREES:g} degrees and {FAR_DEVIATIONS:g} median absolute "
                             "deviations from the gauges' median lon or lat, which move it, are named in a warning")
    chosen.add_argument("--crs", metavar="CRS",
                        help="a projected coordinate system: EPSG:CODE (such as EPSG:5070) or PROJ terms "
                             "(such as '+proj=aea +lat_0=23 +lon_0=-96 +lat_1=29.5 +lat_2=45.5 +x_0=0 +y_0=0')")
    parser.add_argument("--out", default="out", help="output directory (created if missing)")
    args = parser.parse_args(argv)
    csv_input.check_paths(("--stations", args.stations, "stations"))
    # Imported after parsing so that --help works without VTK on the path; Tessera first, so that
    # without VTK (another Python than Debian's) this says how to run the script.
    vtkGeographicProjection = csv_input.import_tessera().vtkGeographicProjection
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    system = None
    if args.crs is not None:  # (an empty --crs is refused by name, not taken as none given)
        # (GdalMessages keeps GDAL's own line for an unknown code off stderr: the script names it)
        system = projected_input.crs_system(args.crs, "--crs", projected_input.GdalMessages(),
                                            lonlat="the gauges are in it already; give a projected system",
                                            datum="the gauges' lon/lat are taken as on WGS84's")
    csv_input.output_directory(args.out)
    gauges, lines = read_gauges(args.stations)
    if gauges.GetNumberOfPoints() == 0:
        csv_input.fail(f"{args.stations}: no gauges to project (the file has no rows)")
    if system:
        projection = projected_input.projection_filter(system, False)
    else:
        projection = vtkGeographicProjection()
        getattr(projection, PROJECTIONS[args.projection])()
    # A gauge the projection rejects (a latitude beyond 90, too far from a UTM zone) ends the run
    # with one line naming its line in the file, as the main example does, not VTK's log and the
    # executive's dump of its request.
    errors, executive_errors = [], []
    csv_input.catch_vtk_messages(projection, errors.append, on_executive_error=executive_errors.append)
    projection.SetInputData(gauges)
    projection.Update()
    projected = projection.GetOutput()
    if errors:
        csv_input.fail(projection_error(errors[0], args.stations, gauges, lines))
    if executive_errors:
        csv_input.fail("the projection failed: " + re.sub(r" for request: .*", "", executive_errors[0]))
    if projected.GetNumberOfPoints() != gauges.GetNumberOfPoints():
        csv_input.fail("the projection failed and gave no message")
    # (said once the projection has taken the gauges: a gauge it rejects is the run's one line)
    say_repeated_gauges(args.stations, gauges, lines)
    if not system:
        say_far_gauges(args.stations, gauges, lines)

    csv_input.write_vtk(vtkXMLPolyDataWriter(), projected, os.path.join(args.out, "gauges_projected.vtp"))
    ids = projected.GetPointData().GetAbstractArray("StationId")
    names = projected.GetPointData().GetAbstractArray("Name")
    with open(os.path.join(args.out, "gauges_projected.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["station_id", "name", "lon", "lat", "x_m", "y_m"] + (["x_crs", "y_crs"] if system else []))
        for i in range(projected.GetNumberOfPoints()):
            lon, lat, _ = gauges.GetPoint(i)
            x, y, _ = projected.GetPoint(i)
            own = [f"{value:.3f}" for value in system.from_grid(x, y)] if system else []
            out.writerow([ids.GetValue(i), names.GetValue(i), lon, lat, f"{x:.3f}", f"{y:.3f}"] + own)
    record = projected.GetFieldData().GetAbstractArray("TesseraProjection").GetValue(0)
    print(f"projected {projected.GetNumberOfPoints()} gauges with {record}"
          + (f" ({system.describe()})" if system else ""))
    print(f"wrote {args.out}/gauges_projected.vtp and {args.out}/gauges_projected.csv")


if __name__ == "__main__":
    csv_input.run(main)
