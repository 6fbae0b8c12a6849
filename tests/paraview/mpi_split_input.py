"""mpiexec -n 2 pvbatch: the filters ask every process for the whole input; an upstream filter
that splits it anyway (Redistribute DataSet) leaves process 1's points out, and the tessellation
says so in a warning instead of dropping them without a word. A pipeline that honours the request
(the Colorado areal average, three inputs) runs on both processes without that warning, and its
weights are whole."""

import math
import os
import sys

from paraview import servermanager
from paraview.simple import (CSVReader, Delaunay3D, LoadPlugin, MergeBlocks, OpenDataFile, PointSource,
                             RedistributeDataSet, TableToPoints)
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkOutputWindow

LoadPlugin(os.environ["TESSERA_PLUGIN"], remote=False, ns=globals())
failures = []
processes = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if processes != 2:
    failures.append(f"{processes} processes, expected 2 (run under mpiexec -n 2)")
warnings = []


@calldata_type(VTK_STRING)
def on_warning(caller, event, message):
    warnings.append(message)


output_window = vtkOutputWindow.GetInstance()
output_window.AddObserver(vtkCommand.WarningEvent, on_warning)

split = RedistributeDataSet(Input=MergeBlocks(Input=Delaunay3D(Input=PointSource(NumberOfPoints=200, Radius=1.0))))
tiles = DirichletTessellation(Input=split)  # noqa: F821
tiles.UpdatePipeline()
told = [w for w in warnings if "differs between the 2 processes" in w]
if len(told) != 1 or "Redistribute DataSet" not in told[0]:
    failures.append(f"the split input was not told: {warnings}")

warnings.clear()
data = os.path.join(os.environ["TESSERA_SOURCE_DIR"], "examples", "data")
# (the reader updated first: under MPI, Table To Points made at once finds no columns)
table = CSVReader(FileName=[os.path.join(data, "colorado_stations.csv")])
table.UpdatePipeline()
stations = TableToPoints(Input=table, XColumn="lon", YColumn="lat")
average = ThiessenArealAverage(  # noqa: F821
    Gauges=stations, Catchment=OpenDataFile(os.path.join(data, "colorado_boundary.geojson")),
    Observations=CSVReader(FileName=[os.path.join(data, "colorado_monthly_precip.csv")]))
average.TimeColumn, average.MonthColumn, average.ValueColumn = "year", "month", "precip"
average.UpdatePipeline(1963 + 7 / 12.0)
if any("differs between" in w for w in warnings):
    failures.append(f"a whole input was taken for a split one: {warnings}")
result = servermanager.Fetch(average)
weights = result.GetCellData().GetArray("Weight") if result else None
gauges = result.GetCellData().GetArray("GaugeId") if result else None
per_gauge = {gauges.GetValue(c): weights.GetValue(c) for c in range(result.GetNumberOfCells())} if weights else {}
if abs(math.fsum(per_gauge.values()) - 1.0) > 1e-12:
    failures.append(f"the areal average's weights on 2 processes sum to {math.fsum(per_gauge.values())}")
if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print("1 passed, 0 failed")
