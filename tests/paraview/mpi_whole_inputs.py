"""mpiexec -n 2 pvbatch: the filters ask every process for the whole input and the first makes
the whole output. The Colorado areal average (three inputs) on two processes weighs the whole
catchment; a tessellation of 200 points gives 200 tiles filling the window."""

import math
import os
import sys

from paraview import servermanager
from paraview.simple import CSVReader, LoadPlugin, OpenDataFile, PointSource, TableToPoints

LoadPlugin(os.environ["TESSERA_PLUGIN"], remote=False, ns=globals())
failures = []
processes = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if processes != 2:
    failures.append(f"{processes} processes, expected 2 (run under mpiexec -n 2)")
source = PointSource(NumberOfPoints=200, Radius=1.0)
tiles = servermanager.Fetch(DirichletTessellation(Input=source))  # noqa: F821
if tiles is None or tiles.GetNumberOfCells() != 200:
    failures.append(f"{tiles.GetNumberOfCells() if tiles else 0} tiles of 200 points on 2 processes")
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
