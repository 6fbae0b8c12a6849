"""pvbatch: the README's pvpython block, as written, from the source directory (the plugin from
the build tree): the areal average advertises the 1236 months and gives August 1963's tiles and
the table of means."""

import contextlib
import io
import os
import re
import sys

from paraview import servermanager

source = os.environ["TESSERA_SOURCE_DIR"]
with open(os.path.join(source, "README.md")) as f:
    text = f.read()
section = text[text.index("From `pvpython`/`pvbatch`:"):text.index("## Use from C++")]
block = re.search(r"```python\n(.*?)```", section, re.S).group(1)
plugin = "build/lib/paraview-plugins/Tessera/Tessera.so"
failures = []
if plugin not in block:
    failures.append(f"the README's block does not load {plugin}")
os.chdir(source)
names = {}
printed = io.StringIO()
# (the block's literal path to the plugin becomes the build tree's: that it was found is checked)
runnable = block.replace(f'"{plugin}"', repr(os.environ["TESSERA_PLUGIN"]))
if runnable == block:
    failures.append(f'the README\'s block does not load "{plugin}" as a literal')
with contextlib.redirect_stdout(printed):
    exec(runnable, names)
if printed.getvalue().split() != ["1236"]:
    failures.append(f"printed {printed.getvalue()!r}, expected the 1236 months")
means, tiles = names["means"], names["tiles"]
if means.GetNumberOfRows() != 1236:
    failures.append(f"{means.GetNumberOfRows()} rows of means, expected 1236")
weights = tiles.GetCellData().GetArray("CellWeight")
total = sum(weights.GetValue(c) for c in range(weights.GetNumberOfTuples())) if weights else 0.0
if not abs(total - 1.0) < 1e-12:
    failures.append(f"August 1963's cell weights sum to {total}")
bounds = tiles.GetBounds()
if not (-110 < bounds[0] < bounds[1] < -101 and 36 < bounds[2] < bounds[3] < 42):
    failures.append(f"the tiles are not in lon/lat over Colorado: {bounds}")
projected = names["projected"]
projected.UpdatePipeline()
if projected.GetDataInformation().GetNumberOfPoints() != 376:
    failures.append(f"{projected.GetDataInformation().GetNumberOfPoints()} projected gauges, expected 376")


def first_leaf(data):
    """The first point set of a fetched data object (a GDAL file's multiblock, or a point set)."""
    if not data.IsA("vtkCompositeDataSet"):
        return data
    iterator = data.NewIterator()
    iterator.InitTraversal()
    return iterator.GetCurrentDataObject()


# The outline in EPSG:5070's own metres: its first vertex (102.055244 W, 40.009644 N) where PROJ 9.1.1 puts it
# (cs2cs +proj=longlat +ellps=WGS84 +to +proj=aea +lat_0=23 +lon_0=-96 +lat_1=29.5 +lat_2=45.5 +ellps=WGS84),
# and back where it was.
in_5070 = first_leaf(servermanager.Fetch(names["outline_5070"]))
back = first_leaf(servermanager.Fetch(names["back"]))
x, y = in_5070.GetPoint(0)[:2] if in_5070.GetNumberOfPoints() else (None, None)
if x is None or abs(x - -511995.224709) > 1e-5 or abs(y - 1904375.096779) > 1e-5:
    failures.append(f"the outline's first vertex in EPSG:5070 is {x}, {y}")
lon, lat = back.GetPoint(0)[:2] if back.GetNumberOfPoints() else (None, None)
if lon is None or abs(lon - -102.055244) > 1e-9 or abs(lat - 40.009644) > 1e-9:
    failures.append(f"the outline's first vertex came back at {lon}, {lat}")
if failures:
    print("FAIL:\n" + "\n".join(failures))
    sys.exit(1)
print("1 passed, 0 failed")
