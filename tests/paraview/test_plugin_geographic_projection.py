"""pvbatch: load the Tessera plugin from the build tree, apply Filters > Tessera > Geographic
Projection by its menu name to the Colorado gauges, and check the fetched data."""

import csv
import os
import sys

from paraview import servermanager
from paraview.simple import CSVReader, Delete, LoadPlugin, TableToPoints

plugin = os.environ["TESSERA_PLUGIN"]
source_dir = os.environ["TESSERA_SOURCE_DIR"]
LoadPlugin(plugin, remote=False, ns=globals())

if "GeographicProjection" not in globals():
    print("FAIL: the plugin did not define GeographicProjection")
    sys.exit(1)

stations = os.path.join(source_dir, "examples", "data", "colorado_stations.csv")
reader = CSVReader(FileName=[stations])
points = TableToPoints(Input=reader, XColumn="lon", YColumn="lat", ZColumn="elev_m")
projected = GeographicProjection(Input=points)  # noqa: F821 (defined by LoadPlugin)
projected.Projection = "UTM"
projected.UpdatePipeline()
data = servermanager.Fetch(projected)

failures = []
if data.GetNumberOfPoints() != 376:
    failures.append(f"expected 376 points, got {data.GetNumberOfPoints()}")
record = data.GetFieldData().GetAbstractArray("TesseraProjection")
if record is None or "projection=UTM" not in record.GetValue(0) or "zone=13" not in record.GetValue(0):
    failures.append(f"bad TesseraProjection record: {record.GetValue(0) if record else None}")
# UTM zone 13 eastings of the gauges stay inside the zone's 0..1000 km and their northings
# follow the latitudes (about 111 km a degree).
with open(stations) as f:
    lats = [float(row["lat"]) for row in csv.DictReader(f)]
for i in range(data.GetNumberOfPoints()):
    x, y, _ = data.GetPoint(i)
    if not 0.0 < x < 1.0e6:
        failures.append(f"point {i}: easting {x} outside the zone")
    if abs(y / 1000.0 - lats[i] * 110.9) > 60.0:
        failures.append(f"point {i}: northing {y} far from latitude {lats[i]}")

# The panel shows a setting only where it is read: UTMZone for UTM, UTMNorth for a UTM zone set; the centre and
# parallels with ParametersFromData off, each for the projections that read it (a Central Latitude
# shown for a conic did nothing; UTM with zone 0 takes its zone and hemisphere from them), and
# ParametersFromData except for UTM with a zone set. Checked against the filter: under each
# projection (and UTM zone), a setting is shown (its decorators, evaluated here as ParaView's panel
# does) exactly when changing it moves the points.


def shown(element, values):
    """Whether a property whose Hints element this is would be shown, the other properties holding
    values ({name: int}): GenericDecorator (mode visibility: property == value, or != with
    inverse="1") and CompositeDecorator (Expression and/or)."""
    kind = element.GetName()
    if kind == "PropertyWidgetDecorator" and element.GetAttribute("type") == "GenericDecorator":
        equal = values[element.GetAttribute("property")] == int(element.GetAttribute("value"))
        return equal != (element.GetAttribute("inverse") == "1")
    children = [element.GetNestedElement(k) for k in range(element.GetNumberOfNestedElements())]
    children = [c for c in children if c.GetName() in ("PropertyWidgetDecorator", "Expression")]
    if kind == "Expression" and element.GetAttribute("type") == "or":
        return any(shown(c, values) for c in children)
    return all(shown(c, values) for c in children)  # (Hints, a composite, an "and")


def moves_points(settings, name, value):
    """Whether setting name to value moves the projected gauges (or makes them unprojectable), the
    other settings as given (ParametersFromData off unless given), the centre at the gauges'
    (-105, 39), parallels 37 and 41."""
    outputs = []
    for changed in (False, True):
        f = GeographicProjection(Input=points)  # noqa: F821
        f.CentralLongitude, f.CentralLatitude, f.StandardParallels = -105.0, 39.0, [37.0, 41.0]
        for key, setting in settings.items():
            setattr(f, key, setting)
        if changed:
            setattr(f, name, value)
        f.UpdatePipeline()
        data = servermanager.Fetch(f)
        outputs.append([data.GetPoint(i) for i in range(0, data.GetNumberOfPoints(), 25)])
        Delete(f)
    return outputs[0] != outputs[1]


# Values that change what each setting can change: another UTM zone (-111 is zone 12) and
# hemisphere (-38), another centre for the others.
CHANGES = (("CentralLongitude", -111.0), ("CentralLatitude", -38.0), ("StandardParallels", [36.0, 42.0]))
for projection in range(9):  # (every entry of the Projection menu)
    for zone in ((0, 13) if projection == 4 else (0,)):
        settings = {"Projection": projection, "UTMZone": zone, "ParametersFromData": 0}
        for name, value in CHANGES:
            visible = shown(projected.GetProperty(name).GetHints(), settings)
            if visible != moves_points(settings, name, value):
                failures.append(f"projection {projection} zone {zone}: {name} is {'shown' if visible else 'hidden'} "
                                f"but {'does not move' if visible else 'moves'} the points")
        for name, _ in CHANGES:
            if shown(projected.GetProperty(name).GetHints(), {**settings, "ParametersFromData": 1}):
                failures.append(f"projection {projection}: {name} shown with ParametersFromData on")
        # ParametersFromData itself: shown exactly where turning it on moves the points (with the
        # centre set away from the gauges' own).
        visible = shown(projected.GetProperty("ParametersFromData").GetHints(), settings)
        away = {**settings, "CentralLongitude": -111.0, "CentralLatitude": -38.0}
        if visible != moves_points(away, "ParametersFromData", 1):
            failures.append(f"projection {projection} zone {zone}: ParametersFromData is "
                            f"{'shown' if visible else 'hidden'} but {'does not move' if visible else 'moves'} the points")
    if shown(projected.GetProperty("UTMZone").GetHints(), {"Projection": projection}) != (projection == 4):
        failures.append(f"projection {projection}: UTMZone shown {not projection == 4}")
    # UTM North: only with a zone set by hand (with zone 0 the hemisphere is the data's, and the box
    # did nothing while shown), exactly where it moves the points.
    for zone in (0, 13):
        values = {"Projection": projection, "UTMZone": zone}
        visible = shown(projected.GetProperty("UTMNorth").GetHints(), values)
        if visible != (projection == 4 and moves_points({**values, "ParametersFromData": 0}, "UTMNorth", 0)):
            failures.append(f"projection {projection} zone {zone}: UTMNorth is {'shown' if visible else 'hidden'}")
# The grid (a projected system's false origin and scale): shown for every projection, where each term moves the
# points; Latitude Of Origin shown with Use Latitude Of Origin on, where it moves the points of every projection
# that takes one (UTM and the azimuthal ones, 4 to 6, take none: an error names it).
for projection in range(9):
    settings = {"Projection": projection, "ParametersFromData": 0}
    for name, value in (("FalseEasting", 1000.0), ("FalseNorthing", -1000.0), ("ScaleFactor", 0.9996)):
        if projected.GetProperty(name).GetHints() is not None or not moves_points(settings, name, value):
            failures.append(f"projection {projection}: {name} hidden or moving no point")
    if projection not in (4, 5, 6) and not moves_points({**settings, "UseLatitudeOfOrigin": 1}, "LatitudeOfOrigin", 30):
        failures.append(f"projection {projection}: LatitudeOfOrigin moves no point")
origin_hints = projected.GetProperty("LatitudeOfOrigin").GetHints()
if shown(origin_hints, {"UseLatitudeOfOrigin": 0}) or not shown(origin_hints, {"UseLatitudeOfOrigin": 1}):
    failures.append("LatitudeOfOrigin is not shown exactly with UseLatitudeOfOrigin on")
if projected.GetProperty("ProjectionRecord") is None:
    failures.append("no ProjectionRecord property")
# The panel's labels: ParaView splits a name at capitals (UTMZone would read "U TMZone").
for name, label in (("UTMZone", "UTM Zone"), ("UTMNorth", "UTM North")):
    xml_label = projected.GetProperty(name).GetXMLLabel()
    if xml_label != label:
        failures.append(f"{name} is labelled {xml_label!r}, not {label!r}")
if failures:
    print("FAIL:\n" + "\n".join(failures[:20]))
    sys.exit(1)
print("1 passed, 0 failed")
