#!/usr/bin/env python3
"""Project rain gauges given in longitude/latitude to a plane with Tessera's
vtkGeographicProjection, and write them out.

Reads a CSV with columns station_id, lon, lat and optional name, elev_m (default: the 376 Colorado gauges in
examples/data/colorado_stations.csv) and writes into --out:
  gauges_projected.vtp   the gauges as VTK points (x, y in metres, z = elevation), with point data
                         StationId, Name, Longitude, Latitude, and field data TesseraProjection;
  gauges_projected.csv   station_id, name, lon, lat, x_m, y_m; with --crs also x_crs, y_crs: the
                         coordinates in that system's own unit (its feet, for a state plane in feet).
x_m and y_m are metres in the projection's plane, from its origin, whose lon/lat the script prints:
for a fitted conic (the automatic projection, Albers, Lambert; without --crs) the central meridian
lon0 at the conic's own origin latitude between lat1 and lat2, not the record's lat0 (the gauges'
middle latitude the parallels are fitted about); with --crs, that system's grid decides it.

--projection picks one of the filter's projections, fitted to the gauges; --crs gives a projected
coordinate system by its EPSG code or PROJ terms (as the main job's --stations-crs reads them: UTM,
tmerc, aea, lcc, laea, merc, in metres or feet), whose own numbers then come out: EPSG:5070 (NAD83 /
Conus Albers) gives that system's eastings and northings, false origin and all.

The other projections are fitted to the gauges (their centre, parallels, UTM zone), so that one
gauge far from the rest (a lon of 200 for -160, a gauge of another country) moves them: the line
the script prints gives the projection's parameters, and a warning names, with their lines, the
gauges that move a fitted conic (the automatic projection, Albers, Lambert): those without any
one of which (left out alone) vtkGeographicProjection would fit the others a central meridian or a
standard parallel more than FAR_DEGREES (2) degrees away. A network dense in one part and sparse in
another gets no warning, a mistyped gauge does. A move of the central meridian counts as degrees
of arc at the gauges' latitude nearest the equator (degrees of longitude times its cosine), and not
at all where the others span 180 degrees of longitude or more (round a pole); of fewer than
FAR_FEWEST (5) gauges none is named. A station id given to more than one gauge (compared as the main job compares
them: 0102 and 102 are one) and gauges at one place are named too (each is projected and written).

Run it with Debian's /usr/bin/python3 and PYTHONPATH pointing to build/python (scripts/demo does).
"""

import argparse
import csv
import math
import os
import re
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


# A gauge that moves the fitted projection (far_gauges): left out alone, the projection fitted to
# the rest would have its centre or a standard parallel this many degrees away; with fewer gauges
# than FAR_FEWEST none is singled out (each is a large part of the network, and a fit to a few
# gauges moves with each); a central meridian is not compared where the rest span FAR_ROUND_DEGREES
# of longitude or more (round a pole: which of their gaps is the largest, and so their meridian,
# turns on any one gauge).
FAR_DEGREES = 2.0
FAR_FEWEST = 5
FAR_ROUND_DEGREES = 180.0


def wrapped(degrees):
    """A difference of longitudes within -180 .. 180."""
    return (degrees + 180.0) % 360.0 - 180.0


# The fitted projections whose central meridian and standard parallels far_gauges compares: the
# conics (the others have no parallels, and UTM reads a zone).
CONICS = ("automatic", "albers", "lambert")


def places_data(places):
    """vtkPolyData of (lon, lat) places (or (x, y) in a plane), in double precision."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    points = vtkPoints()
    points.SetDataTypeToDouble()
    for x, y in places:
        points.InsertNextPoint(x, y, 0.0)
    data = vtkPolyData()
    data.SetPoints(points)
    return data


def fitted_terms(lons, lats, projection):
    """(central meridian, standard parallel 1, standard parallel 2) that vtkGeographicProjection
    fits to the places with the projection (a CONICS name), read off its TesseraProjection record;
    its warnings (on a span round the globe, say) are kept back."""
    fit = csv_input.import_tessera().vtkGeographicProjection()
    getattr(fit, PROJECTIONS[projection])()
    kept = []
    csv_input.catch_vtk_messages(fit, kept.append, kept.append, kept.append)
    fit.SetInputData(places_data(zip(lons, lats)))
    fit.Update()
    return record_terms(projection_record(fit.GetOutput()))


def projection_record(projected):
    """A projected data set's TesseraProjection record (vtkGeographicProjection's field data)."""
    return projected.GetFieldData().GetAbstractArray("TesseraProjection").GetValue(0)


def record_terms(record):
    """(lon0, lat1, lat2) of a TesseraProjection record."""
    terms = dict(term.split("=", 1) for term in record.split() if "=" in term)
    return tuple(float(terms[key]) for key in ("lon0", "lat1", "lat2"))


def longitude_gaps(lons):
    """The longitudes in 0 .. 360, sorted, and the gap that ends at each (at the first: across 360)."""
    turned = sorted(lon % 360.0 for lon in lons)
    return turned, [turned[0] + 360.0 - turned[-1]] + [b - a for a, b in zip(turned, turned[1:])]


def could_move(lons, lats):
    """The gauges whose leaving out alone can move a fit to the gauges' extent: one alone at the
    south or north end of their latitudes, or alone at its longitude with the two gaps beside it
    together as wide as the largest gap at least (only then does the largest gap, which the central
    meridian is taken across, change). Each is refitted: this only spares refitting the others."""
    count = len(lons)
    by_lat = sorted(range(count), key=lats.__getitem__)
    ends = {by_lat[0], by_lat[-1]}
    order = sorted(range(count), key=lambda k: lons[k] % 360.0)
    turned, gaps = longitude_gaps(lons)
    widest = max(gaps)
    for j in range(count):
        beside = gaps[j] + gaps[(j + 1) % count]
        if gaps[j] > 0.0 and gaps[(j + 1) % count] > 0.0 and beside >= widest:
            ends.add(order[j])
    return sorted(ends)


def far_gauges(lons, lats, projection="automatic", whole=None):
    """(index, degrees) of each gauge that moves the fitted conic: left out alone, the central
    meridian or a standard parallel vtkGeographicProjection fits to the other gauges (fitted_terms)
    lies more than FAR_DEGREES degrees from those fitted to all of them (whole, when known: the
    script's own projection's). A move of the central meridian counts as degrees of arc at the
    gauges' latitude nearest the equator (its degrees of longitude times that latitude's cosine:
    near a pole a degree of longitude is a short way); it is not counted where the other gauges
    span FAR_ROUND_DEGREES of longitude or more. Fewer than FAR_FEWEST gauges, or a projection
    that is no conic: none. Gauges are left out one at a time: two mistyped gauges side by side
    each keep the other's pull, and neither is named (the projection line shows the parameters)."""
    if len(lons) < FAR_FEWEST or projection not in CONICS:
        return []
    whole = whole or fitted_terms(lons, lats, projection)
    nearest_equator = 0.0 if min(lats) <= 0.0 <= max(lats) else min(abs(lat) for lat in lats)
    arc = math.cos(math.radians(nearest_equator))
    far = []
    for i in could_move(lons, lats):
        rest_lons, rest_lats = lons[:i] + lons[i + 1:], lats[:i] + lats[i + 1:]
        part = fitted_terms(rest_lons, rest_lats, projection)
        move = max(abs(part[1] - whole[1]), abs(part[2] - whole[2]))
        if 360.0 - max(longitude_gaps(rest_lons)[1]) < FAR_ROUND_DEGREES:
            move = max(move, abs(wrapped(part[0] - whole[0])) * arc)
        if move > FAR_DEGREES:
            far.append((i, move))
    return far


def say_far_gauges(path, gauges, lines, points, projection, projected):
    """Warns of the gauges that move the fitted conic (far_gauges; projected: the script's own
    projection of them, whose fit is the whole set's), naming each with its line and how far it
    moves it: a projection fitted to the gauges takes them in, and its centre and parallels are
    not those of the rest."""
    far = far_gauges([lon for lon, _ in points], [lat for _, lat in points], projection,
                     record_terms(projection_record(projected)))
    if far:
        station = gauges.GetPointData().GetAbstractArray("StationId")
        shown = ", ".join(f"{station.GetValue(k)} at lon {points[k][0]:.15g}, lat {points[k][1]:.15g} "
                          f"(line {lines[k]}: {move:.1f} degrees)" for k, move in far[:20])
        more = f" and {len(far) - 20} more" if len(far) > 20 else ""
        print(f"{path}: warning: {len(far)} gauge(s) move the fitted projection (without any one of them, its "
              f"central meridian or a standard parallel would move by more than {FAR_DEGREES:g} "
              f"degrees; a mistyped place? --crs gives a projection of its own): {shown}{more}", file=sys.stderr)


def say_repeated_gauges(path, gauges, lines, places):
    """Names the gauges that repeat an earlier gauge's station id or place (csv_input.say_repeats),
    as the main job names them: ids are compared as the main job and the filter compare them
    (csv_input.station_key: "0102", "102" and "102.0" are one id), a later gauge's id given as in
    its file, with the earlier one's where the two are written differently ("102 (as 0102)").
    Each gauge is projected and written all the same."""
    station = gauges.GetPointData().GetAbstractArray("StationId")
    ids = [station.GetValue(k) for k in range(gauges.GetNumberOfPoints())]
    csv_input.say_repeats(path, lines, [csv_input.station_key(i) for i in ids],
                          "station id(s) are given to more than one gauge (each is projected)",
                          lambda k, first: ids[k] + (f" (as {ids[first]})" if ids[k] != ids[first] else ""), "gauge")
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


def plane_origin(record):
    """(lon, lat) of the plane's origin, where x_m = y_m = 0 (None where the projection cannot take
    it back): for a conic, its own origin latitude between lat1 and lat2 (GeographicLib's), not
    the record's lat0, the gauges' middle latitude the parallels are fitted about, which a GIS
    user took for PROJ's +lat_0 and found y = 0 some 480 m from it."""
    back = csv_input.import_tessera().vtkGeographicProjection()
    back.SetInputData(places_data([(0.0, 0.0)]))
    back.InverseOn()
    back.SetProjectionRecord(record)
    # (its warning that (0, 0) lies within degrees' ranges is not the user's: dropped)
    errors = csv_input.errors_of_update(back)
    output = back.GetOutput()
    return None if errors or output.GetNumberOfPoints() != 1 else output.GetPoint(0)[:2]


def argument_parser():
    """The script's options, in the order --help lists them."""
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stations", default=os.path.join(HERE, "data", "colorado_stations.csv"),
                        help="CSV of gauges: columns station_id, lon, lat (degrees), optional name, elev_m; "
                             f"{csv_input.SEPARATORS_TEXT}")
    chosen = parser.add_mutually_exclusive_group()
    chosen.add_argument("--projection", choices=sorted(PROJECTIONS), default="automatic",
                        help="map projection, fitted to the gauges (default: automatic Albers equal-area); "
                             "a gauge that moves a fitted conic (automatic, albers, lambert) is named in a warning: "
                             "one without which (left out alone) the projection fitted to the others would have its "
                             f"central meridian or a standard parallel more than {FAR_DEGREES:g} degrees away (a "
                             "meridian's move in "
                             "degrees of arc at the gauges' latitude nearest the equator; none named of fewer than "
                             f"{FAR_FEWEST} gauges; two mistyped gauges side by side keep each other's pull, and "
                             "neither is named)")
    chosen.add_argument("--crs", metavar="CRS",
                        help="a projected coordinate system: EPSG:CODE (such as EPSG:5070) or PROJ terms "
                             "(such as '+proj=aea +lat_0=23 +lon_0=-96 +lat_1=29.5 +lat_2=45.5 +x_0=0 +y_0=0')")
    parser.add_argument("--out", default="out", help="output directory (created if missing)")
    return parser


def main(argv=None):
    args = argument_parser().parse_args(argv)
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
    projected = projected_gauges(args, system, gauges, lines, vtkGeographicProjection)
    # (said once the projection has taken the gauges: a gauge it rejects is the run's one line)
    places = [gauges.GetPoint(k)[:2] for k in range(gauges.GetNumberOfPoints())]
    say_repeated_gauges(args.stations, gauges, lines, places)
    if system is None:
        say_far_gauges(args.stations, gauges, lines, places, args.projection, projected)

    csv_input.write_vtk(vtkXMLPolyDataWriter(), projected, os.path.join(args.out, "gauges_projected.vtp"))
    write_projected_csv(gauges, projected, system, os.path.join(args.out, "gauges_projected.csv"))
    say_projection(projected, system)
    print(f"wrote {args.out}/gauges_projected.vtp and {args.out}/gauges_projected.csv")


def projected_gauges(args, system, gauges, lines, vtkGeographicProjection):
    """The gauges projected: to --crs's system, else with --projection fitted to them. An error
    ends the script."""
    if system is not None:
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
    return projected


def write_projected_csv(gauges, projected, system, path):
    """Writes gauges_projected.csv: each gauge's lon/lat and x, y in metres (and with --crs, in the
    system's own unit)."""
    ids = projected.GetPointData().GetAbstractArray("StationId")
    names = projected.GetPointData().GetAbstractArray("Name")
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["station_id", "name", "lon", "lat", "x_m", "y_m"] + (["x_crs", "y_crs"] if system else []))
        for i in range(projected.GetNumberOfPoints()):
            lon, lat, _ = gauges.GetPoint(i)
            x, y, _ = projected.GetPoint(i)
            own = [f"{value:.3f}" for value in system.from_grid(x, y)] if system else []
            out.writerow([ids.GetValue(i), names.GetValue(i), lon, lat, f"{x:.3f}", f"{y:.3f}"] + own)


def say_projection(projected, system):
    """Says the projection the gauges were projected with, and its plane's origin."""
    record = projection_record(projected)
    print(f"projected {projected.GetNumberOfPoints()} gauges with {record}"
          + (f" ({system.describe()})" if system else ""))
    origin = plane_origin(record)
    if origin is not None:
        print(f"x_m and y_m are metres from the plane's origin, at lon {origin[0]:.10f}, lat {origin[1]:.10f}")


if __name__ == "__main__":
    csv_input.run(main)
