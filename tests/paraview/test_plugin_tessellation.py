"""pvbatch: Filters > Tessera > Dirichlet Tessellation and Delaunay Triangulation on projected
Colorado gauges; the fetched tiles cover the window and each tile's point is the nearest gauge."""

import os
import sys

from paraview import servermanager
from paraview.simple import CreateRenderView, CSVReader, LoadPlugin, OutputPort, Plane, Show, TableToPoints

LoadPlugin(os.environ["TESSERA_PLUGIN"], remote=False, ns=globals())
stations = os.path.join(os.environ["TESSERA_SOURCE_DIR"], "examples", "data", "colorado_stations.csv")
reader = CSVReader(FileName=[stations])
points = TableToPoints(Input=reader, XColumn="lon", YColumn="lat", ZColumn="elev_m")
projected = GeographicProjection(Input=points)  # noqa: F821 (from LoadPlugin)
tess = DirichletTessellation(Input=projected)  # noqa: F821
tess.Padding = 0.05
tess.UpdatePipeline()
tiles = servermanager.Fetch(tess)
failures = []

gauges = servermanager.Fetch(projected)
n = gauges.GetNumberOfPoints()
fd = tiles.GetFieldData()
dups = fd.GetArray("DuplicatePointIds").GetNumberOfTuples()
if tiles.GetNumberOfCells() + dups != n:
    failures.append(f"{tiles.GetNumberOfCells()} tiles + {dups} duplicates != {n} gauges")
b = gauges.GetBounds()
side = max(b[1] - b[0], b[3] - b[2])
window_area = (b[1] - b[0] + 0.1 * side) * (b[3] - b[2] + 0.1 * side)
areas = tiles.GetCellData().GetArray("Area")
total = sum(areas.GetValue(c) for c in range(tiles.GetNumberOfCells()))
if abs(total - window_area) > 1e-9 * window_area:
    failures.append(f"tile areas {total} != window area {window_area}")
ids = tiles.GetCellData().GetArray("PointId")
station = tiles.GetCellData().GetAbstractArray("station_id")
if station is None:
    failures.append("the gauges' point data did not follow their tiles")
# brute force: each tile's centroid is nearest to its own gauge
coords = [gauges.GetPoint(i)[:2] for i in range(n)]
for c in range(0, tiles.GetNumberOfCells(), 7):
    cell = tiles.GetCell(c).GetPointIds()
    m = cell.GetNumberOfIds()
    cx = sum(tiles.GetPoint(cell.GetId(k))[0] for k in range(m)) / m
    cy = sum(tiles.GetPoint(cell.GetId(k))[1] for k in range(m)) / m
    d = [(x - cx) ** 2 + (y - cy) ** 2 for x, y in coords]
    if d[ids.GetValue(c)] > min(d) * (1 + 1e-9):
        failures.append(f"tile {c}: centroid not nearest to its gauge {ids.GetValue(c)}")

# The XML's Compute Contiguity Graph property: on by default (the graph port has a line per
# contiguity), off leaves that port empty and the tiles as they were.
graph = servermanager.Fetch(tess, idx=1)
if tess.ComputeContiguityGraph != 1 or graph.GetNumberOfCells() < 2 * n:
    failures.append(f"graph by default: {tess.ComputeContiguityGraph}, {graph.GetNumberOfCells()} lines")
tess.ComputeContiguityGraph = 0
tess.UpdatePipeline()
graph = servermanager.Fetch(tess, idx=1)
without = servermanager.Fetch(tess)
if graph.GetNumberOfCells() != 0 or graph.GetNumberOfPoints() != 0:
    failures.append(f"graph off: {graph.GetNumberOfPoints()} points, {graph.GetNumberOfCells()} lines")
if without.GetNumberOfCells() != tiles.GetNumberOfCells() or any(
        without.GetCellData().GetArray("Area").GetValue(c) != areas.GetValue(c)
        for c in range(tiles.GetNumberOfCells())):
    failures.append("graph off changed the tiles")

# Shown, the tiles are coloured by Area and the graph by Kind (they were one solid colour): the
# outputs' active scalars, which ParaView colours by (not rendered here: no display needed).
tess.ComputeContiguityGraph = 1
view = CreateRenderView()
for port, expected in ((0, ["CELLS", "Area"]), (1, ["CELLS", "Kind"])):
    shown = Show(OutputPort(tess, port), view).ColorArrayName
    if list(shown) != expected:
        failures.append(f"output {port} is coloured by {list(shown)}, not {expected}")

tri = DelaunayTriangulation(Input=projected)  # noqa: F821
tri.UpdatePipeline()
faces = servermanager.Fetch(tri)
if faces.GetNumberOfPoints() != n or faces.GetNumberOfCells() < n:
    failures.append(f"Delaunay: {faces.GetNumberOfPoints()} points, {faces.GetNumberOfCells()} faces")

# Field data in the Information panel: ParaView lists none when the first array is empty, and the
# lists of rejected and duplicate points often are. The tiles' lists are shown when one is not
# empty (the gauges have duplicates), and Window Clip's WindowArea and CoveredFraction always
# (after the tiles' empty RejectedPointIds, passed on, they were hidden).
if dups > 0 and "RejectedPointIds" not in tess.FieldData.keys():
    failures.append(f"the tiles' field data listed: {tess.FieldData.keys()}")
quarter = [0.25 * (b[1] - b[0]), 0.25 * (b[3] - b[2])]
window = Plane(Origin=[b[0] + quarter[0], b[2] + quarter[1], 0.0], Point1=[b[1] - quarter[0], b[2] + quarter[1], 0.0],
               Point2=[b[0] + quarter[0], b[3] - quarter[1], 0.0])
clip = WindowClip(Input=tess, Window=window)  # noqa: F821
clip.UpdatePipeline()
for name in ("WindowArea", "CoveredFraction", "EmptyTileIds", "SkippedCellIds", "RejectedPointIds"):
    if name not in clip.FieldData.keys():
        failures.append(f"Window Clip's field data listed: {clip.FieldData.keys()}, without {name}")
# Its second output, the clipped tiles' outlines: a closed line per ring, one ring per tile (the
# window, a rectangle, cuts no tile into lobes), carrying the tiles' PointId.
pieces = servermanager.Fetch(clip)
rings = servermanager.Fetch(clip, idx=1)
tiles_clipped = {pieces.GetCellData().GetArray("TileId").GetValue(c) for c in range(pieces.GetNumberOfCells())}
if rings.GetNumberOfLines() != len(tiles_clipped) or rings.GetCellData().GetArray("PointId") is None:
    failures.append(f"Window Clip's outlines: {rings.GetNumberOfLines()} rings for {len(tiles_clipped)} tiles")
# (drawn in one colour over the tiles: not by the whole tiles' Area, the tiles' active scalars)
outline_colour = list(Show(OutputPort(clip, 1), CreateRenderView()).ColorArrayName)
if outline_colour[1]:
    failures.append(f"Window Clip's outlines are coloured by {outline_colour}")

if failures:
    print("FAIL:\n" + "\n".join(failures[:20]))
    sys.exit(1)
print("1 passed, 0 failed")
