"""pvbatch: Filters > Tessera > Ridge Grouping on the projected Fiji epicentres; all four output
ports are fetched and checked."""

import os
import sys

from paraview import servermanager
from paraview.simple import CSVReader, LoadPlugin, TableToPoints

LoadPlugin(os.environ["TESSERA_PLUGIN"], remote=False, ns=globals())
quakes = os.path.join(os.environ["TESSERA_SOURCE_DIR"], "examples", "data", "fiji_quakes.csv")
points = TableToPoints(Input=CSVReader(FileName=[quakes]), XColumn="long", YColumn="lat", ZColumn="depth")
projected = GeographicProjection(Input=points)  # noqa: F821
grouping = RidgeGrouping(Input=projected)  # noqa: F821
grouping.Width = 4.0
grouping.CurveSigma = 0.1
grouping.MinimumContourLength = 15.0
grouping.UpdatePipeline()
failures = []
grouped = servermanager.Fetch(grouping)
n = grouped.GetNumberOfPoints()
groups = grouped.GetPointData().GetArray("GroupId")
nodes = grouped.GetPointData().GetArray("Node")
if n != 1000 or groups is None or nodes is None:
    failures.append(f"grouped points: {n}, GroupId {groups}, Node {nodes}")
else:
    found = {groups.GetValue(i) for i in range(n)}
    if len(found - {-1}) < 2:
        failures.append(f"the trench and the arc should give at least 2 groups: {found}")
    if any(not 0.0 <= nodes.GetValue(i) <= 1.0 for i in range(n)):
        failures.append("a Node outside [0, 1]")
contours = servermanager.Fetch(grouping, idx=1)
if contours.GetNumberOfCells() < 2 or contours.GetCellData().GetArray("ContourId") is None:
    failures.append(f"{contours.GetNumberOfCells()} ridge contours")
curves = servermanager.Fetch(grouping, idx=2)
if curves.GetNumberOfCells() < 2 or curves.GetCellData().GetArray("GroupId") is None:
    failures.append(f"{curves.GetNumberOfCells()} fitted curves")
image = servermanager.Fetch(grouping, idx=3)
if image.GetNumberOfPoints() == 0 or image.GetPointData().GetArray("Field") is None:
    failures.append("no field image")
if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print("1 passed, 0 failed")
