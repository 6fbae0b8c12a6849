"""pvbatch: Filters > Tessera > Thiessen Areal Average on the Colorado gauges, outline and monthly
table as ParaView reads them (the table's year and month columns give the steps); checks the
fetched table and the tiles at a requested time."""

import csv
import math
import os
import sys
import tempfile

from paraview import servermanager
from paraview.simple import (CreateRenderView, CSVReader, GetTimeKeeper, LoadPlugin, OpenDataFile, OutputPort,
                             PVTrivialProducer, SaveData, Show, TableToPoints)
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkDoubleArray, vtkOutputWindow, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_VERTEX, vtkPolyData

LoadPlugin(os.environ["TESSERA_PLUGIN"], remote=False, ns=globals())
data = os.path.join(os.environ["TESSERA_SOURCE_DIR"], "examples", "data")
stations = TableToPoints(Input=CSVReader(FileName=[os.path.join(data, "colorado_stations.csv")]),
                         XColumn="lon", YColumn="lat", ZColumn="elev_m")
outline = OpenDataFile(os.path.join(data, "colorado_boundary.geojson"))
# The monthly CSV as ParaView reads it (year and month columns), with no Python in between.
monthly = CSVReader(FileName=[os.path.join(data, "colorado_monthly_precip.csv")])
# Made as the Filters menu makes it, with the default columns (time, value), which this table
# lacks: ParaView asks for the pipeline information at once, and that gives no error yet.
creation_errors = []


@calldata_type(VTK_STRING)
def on_error(caller, event, message):
    creation_errors.append(message)


output_window = vtkOutputWindow.GetInstance()
observer = output_window.AddObserver(vtkCommand.ErrorEvent, on_error)
average = ThiessenArealAverage(Gauges=stations, Catchment=outline, Observations=monthly)  # noqa: F821
output_window.RemoveObserver(observer)
average.TimeColumn = "year"
average.MonthColumn = "month"
average.ValueColumn = "precip"
failures = []
if any("vtkThiessenArealAverage" in m for m in creation_errors):
    failures.append(f"errors as the filter was made: {creation_errors}")
average.UpdatePipeline(1963 + 7 / 12.0)
information = average.GetDataInformation().DataInformation
if information.GetNumberOfTimeSteps() != 1236:
    failures.append(f"{information.GetNumberOfTimeSteps()} time steps advertised, expected 1236")
# The time keeper (hence the time slider and animation) knows the steps through the proxy's
# TimestepValues information property, which the GUI updates on Apply.
average.UpdatePipelineInformation()
if len(average.TimestepValues) != 1236 or len(GetTimeKeeper().TimestepValues) != 1236:
    failures.append(f"the time keeper has {len(GetTimeKeeper().TimestepValues)} steps "
                    f"(the proxy's TimestepValues {len(average.TimestepValues)}), expected 1236")
tiles = servermanager.Fetch(average)
weights = tiles.GetCellData().GetArray("Weight")
gauge = tiles.GetCellData().GetArray("GaugeId")
per_gauge = {gauge.GetValue(c): weights.GetValue(c) for c in range(tiles.GetNumberOfCells())}
if abs(math.fsum(per_gauge.values()) - 1.0) > 1e-12:
    failures.append(f"weights of 1963-08 sum to {math.fsum(per_gauge.values())}")
cell_weights = tiles.GetCellData().GetArray("CellWeight")
covered = math.fsum(cell_weights.GetValue(c) for c in range(tiles.GetNumberOfCells())) if cell_weights else None
if covered is None or abs(covered - 1.0) > 1e-12:
    failures.append(f"the cells' CellWeight of 1963-08 sum to {covered}, not 1")
if len(per_gauge) < 150:
    failures.append(f"only {len(per_gauge)} weighted gauges in 1963-08")
values = tiles.GetCellData().GetArray("Value")
mean = math.fsum(per_gauge[gauge.GetValue(c)] * values.GetValue(c) for c in
           {gauge.GetValue(c): c for c in range(tiles.GetNumberOfCells())}.values())
if not 7.0 < mean < 9.5:
    failures.append(f"1963-08 areal mean {mean} far from the 8.17 the example computes")
# Output 3, the tiles' outlines: the same gauges' rings, drawn in one colour over the tiles (no
# array to colour by), following the time asked for through it.
outlines = servermanager.Fetch(average, idx=3)
ringed = {outlines.GetCellData().GetArray("GaugeId").GetValue(c) for c in range(outlines.GetNumberOfCells())}
if ringed != set(per_gauge) or outlines.GetNumberOfLines() != outlines.GetNumberOfCells():
    failures.append(f"output 3 has rings of {len(ringed)} gauges, the tiles {len(per_gauge)}")
outline_colour = list(Show(OutputPort(average, 3), CreateRenderView()).ColorArrayName)
if outline_colour[1]:
    failures.append(f"the outlines are coloured by {outline_colour}")
average.UpdatePipeline(1920.0)
tiles_1920 = servermanager.Fetch(average)
outlines_1920 = servermanager.Fetch(average, idx=3)
gauges_of = [{data.GetCellData().GetArray("GaugeId").GetValue(c) for c in range(data.GetNumberOfCells())}
             for data in (tiles_1920, outlines_1920)]
if gauges_of[0] != gauges_of[1] or gauges_of[0] == ringed:
    failures.append(f"at 1920, output 3's {len(gauges_of[1])} gauges against the tiles' {len(gauges_of[0])}")
# Shown, the tiles are coloured by the step's Value (they were one solid colour).
shown = list(Show(average, CreateRenderView()).ColorArrayName)
if shown != ["CELLS", "Value"]:
    failures.append(f"the tiles are coloured by {shown}, not by Value")
# Output 2: every step's weights; the rows of 1963-08 are the tiles' weights.
table = servermanager.Fetch(average, idx=2)
times, gauges, listed = (table.GetColumnByName(n) for n in ("Time", "GaugeId", "Weight"))
august = {gauges.GetValue(r): listed.GetValue(r) for r in range(table.GetNumberOfRows())
          if abs(times.GetValue(r) - (1963 + 7 / 12.0)) < 1e-9}
tiled = {g: w for g, w in per_gauge.items() if w > 0.0}
if august.keys() != tiled.keys() or any(abs(august[g] - w) > 1e-14 for g, w in tiled.items()):
    failures.append(f"output 2's {len(august)} weights for 1963-08 differ from the tiles' {len(tiled)}")
if len({times.GetValue(r) for r in range(table.GetNumberOfRows())}) != 1236:
    failures.append("output 2 does not list all 1236 months")
# Saved as File > Save Data saves it, with the CSV writer's default precision: the months' decimal
# years collide (1895-03 and 1895-04 are both 1895.2), their Date labels do not, and each is the
# month of a row of the table read (year, month).
with tempfile.TemporaryDirectory() as saved:
    means_csv = os.path.join(saved, "means.csv")
    SaveData(means_csv, proxy=OutputPort(average, 1))
    with open(means_csv) as written:
        rows = list(csv.DictReader(written))
    with open(os.path.join(data, "colorado_monthly_precip.csv")) as read:
        months = {f"{int(r['year']):04d}-{int(r['month']):02d}" for r in csv.DictReader(read)}
    labels = [r.get("Date") for r in rows]
    if len(rows) != 1236 or len(set(labels)) != 1236 or set(labels) != months:
        failures.append(f"the saved table's Date labels: {len(set(labels))} distinct of {len(rows)}, "
                        f"{sorted(set(labels) ^ months)[:4]} not the table's months")
    if len({r["Time"] for r in rows}) == len(rows):
        failures.append("the saved decimal years no longer collide: the Date check tests nothing")
# Removing the optional Observations input (the GUI's "None") disconnects it: the gauges' own
# value array is then the one step. (The property once kept the table connected.) Without a value
# array the gauges give no step at all: the tiles carry no Weight, and no time is advertised.
average.Observations = None
average.UpdatePipelineInformation()
average.UpdatePipeline()
if average.GetClientSideObject().GetNumberOfInputConnections(2) != 0:
    failures.append("the Observations input is still connected after it was set to None")
if len(average.TimestepValues) != 0:
    failures.append(f"{len(average.TimestepValues)} time steps advertised without observations")
# The column and array properties offer the table's columns and the gauges' point arrays (a list
# in the panel, not a text box), and keep their defaults where the input lacks such a column. The
# value array is offered among the numbers of one component only (the stations' names are text),
# and Month Column's list begins with the empty entry, no month column.
columns = servermanager.Fetch(monthly)
arrays = servermanager.Fetch(stations).GetPointData()
numbers = [arrays.GetAbstractArray(a) for a in range(arrays.GetNumberOfArrays())]
numbers = [a.GetName() for a in numbers if a.IsNumeric() and a.GetNumberOfComponents() == 1]
offered = {"StationColumn": sorted(columns.GetColumnName(c) for c in range(columns.GetNumberOfColumns())),
           "StationIdArrayName": sorted(arrays.GetArrayName(a) for a in range(arrays.GetNumberOfArrays())),
           "ValueArrayName": sorted(numbers)}
offered.update(TimeColumn=offered["StationColumn"], ValueColumn=offered["StationColumn"],
               MonthColumn=[""] + offered["StationColumn"])
if len(numbers) == arrays.GetNumberOfArrays():
    failures.append("the stations have no text array, so the value list's filter is not tested")
for name, expected in offered.items():
    if sorted(average.GetProperty(name).Available) != expected:
        failures.append(f"{name} offers {list(average.GetProperty(name).Available)}, expected {expected}")
# Neither list offers the gauges' field data (one value for the whole set, never a gauge's), nor
# does the value list offer a vector; cell data (a GDAL reader's feature attributes) is offered.
made = vtkPolyData()
made.SetPoints(vtkPoints())
made.AllocateEstimate(3, 1)
for i in range(3):
    made.GetPoints().InsertNextPoint(-105.0 + i, 39.0 + i % 2, 0.0)
    made.InsertNextCell(VTK_VERTEX, 1, [i])
for data, name, components in ((made.GetPointData(), "id", 1), (made.GetPointData(), "wind", 3),
                               (made.GetCellData(), "rain", 1), (made.GetFieldData(), "run", 1)):
    array = vtkDoubleArray()
    array.SetName(name)
    array.SetNumberOfComponents(components)
    array.SetNumberOfTuples(1 if name == "run" else 3)
    data.AddArray(array)
producer = PVTrivialProducer()
producer.GetClientSideObject().SetOutput(made)
lists = ThiessenArealAverage(Gauges=producer, Catchment=outline)  # noqa: F821
for name, expected in (("StationIdArrayName", ["id", "rain", "wind"]), ("ValueArrayName", ["id", "rain"])):
    if sorted(lists.GetProperty(name).Available) != expected:
        failures.append(f"made gauges: {name} offers {list(lists.GetProperty(name).Available)}, expected {expected}")
fresh = ThiessenArealAverage(Gauges=stations, Catchment=outline, Observations=monthly)  # noqa: F821
defaults = [fresh.GetPropertyValue(name) for name in ("StationIdArrayName", "ValueArrayName", "StationColumn",
                                                      "TimeColumn", "MonthColumn", "ValueColumn")]
if defaults != ["station_id", "value", "station_id", "time", "", "value"]:
    failures.append(f"a new filter's columns are {defaults}, not the documented defaults")
# Use Missing Value (off) and Missing Value (-9999) reach the filter as set.
if [fresh.UseMissingValue, fresh.MissingValue] != [0, -9999]:
    failures.append(f"missing-value defaults {fresh.UseMissingValue}, {fresh.MissingValue}")
# (A command the filter lacks is an error from the server as the values are pushed.)
creation_errors.clear()
observer = output_window.AddObserver(vtkCommand.ErrorEvent, on_error)
fresh.UseMissingValue = 1
fresh.MissingValue = -999
fresh.UpdateVTKObjects()
output_window.RemoveObserver(observer)
if creation_errors:
    failures.append(f"errors as the missing-value properties were pushed: {creation_errors}")
if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print("1 passed, 0 failed")
