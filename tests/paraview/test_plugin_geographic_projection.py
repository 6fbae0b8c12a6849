"""pvbatch: load the Tessera plugin from the build tree, apply Filters > Tessera > Geographic
Projection by its menu name to the Colorado gauges, and check the fetched data."""

import csv
import os
import sys

from paraview import servermanager
from paraview.simple import CSVReader, LoadPlugin, TableToPoints

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

# The panel shows the UTM settings for UTM only, the centre and parallels with ParametersFromData
# off only; ProjectionRecord is there to project a second data set alike.
for name, shown_by in (("UTMZone", "Projection"), ("UTMNorth", "Projection"), ("CentralLongitude", "ParametersFromData"),
                       ("CentralLatitude", "ParametersFromData"), ("StandardParallels", "ParametersFromData")):
    hints = projected.GetProperty(name).GetHints()
    decorator = hints.FindNestedElementByName("PropertyWidgetDecorator") if hints else None
    if decorator is None or decorator.GetAttribute("property") != shown_by:
        failures.append(f"{name} is not shown by {shown_by}")
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
