"""Small helpers shared by the Python tests: a failing check raises AssertionError with a message,
and the process exits non-zero, so ctest sees the failure."""

import json
import os
import sys
from fractions import Fraction

SOURCE_DIR = os.environ.get("TESSERA_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE_DATA = os.path.join(SOURCE_DIR, "examples", "data")


def assert_that(condition, message):
    if not condition:
        raise AssertionError(message)


def assert_close(actual, expected, tolerance, what):
    if not abs(actual - expected) <= tolerance:
        raise AssertionError(f"{what}: {actual!r} differs from {expected!r} by more than {tolerance}")


def messages_of(algorithm, event=None):
    """Collects the messages a VTK algorithm emits for an event (default: ErrorEvent)."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand

    messages = []

    @calldata_type(VTK_STRING)
    def on_message(caller, e, message):
        messages.append(message)

    algorithm.AddObserver(vtkCommand.ErrorEvent if event is None else event, on_message)
    return messages


def warnings_of_update(algorithm, data):
    """Runs algorithm on data (input 0); returns the warnings it gave."""
    from vtkmodules.vtkCommonCore import vtkCommand

    warnings = messages_of(algorithm, vtkCommand.WarningEvent)
    algorithm.SetInputData(data)
    algorithm.Update()
    return warnings


def double_array(name, values):
    """A vtkDoubleArray named name holding values."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray

    array = vtkDoubleArray()
    array.SetName(name)
    for value in values:
        array.InsertNextValue(value)
    return array


def polygon(rings):
    """vtkPolyData with one polygon cell per ring of (x, y) vertices (z = 0, double precision)."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    points = vtkPoints()
    points.SetDataTypeToDouble()
    polys = vtkCellArray()
    for ring in rings:
        polys.InsertNextCell(len(ring))
        for x, y in ring:
            polys.InsertCellPoint(points.InsertNextPoint(x, y, 0.0))
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetPolys(polys)
    return data


def cells(xy, polys=(), lines=()):
    """vtkPolyData of points xy with polygon and polyline cells given as lists of point ids."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    data = vtkPolyData()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    for x, y in xy:
        points.InsertNextPoint(x, y, 0.0)
    data.SetPoints(points)
    for ids_of_cells, setter in ((lines, data.SetLines), (polys, data.SetPolys)):
        array = vtkCellArray()
        for ids in ids_of_cells:
            array.InsertNextCell(len(ids), ids)
        setter(array)
    return data


def cell_rings(data):
    """The (x, y) vertices of each cell of a vtkPolyData, cell by cell."""
    rings = []
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        rings.append([data.GetPoint(ids.GetId(k))[:2] for k in range(ids.GetNumberOfIds())])
    return rings


def colorado_outline():
    """The Colorado catchment's ring (examples/data/colorado_boundary.geojson) as (lon, lat)
    tuples, without the closing point."""
    with open(os.path.join(EXAMPLE_DATA, "colorado_boundary.geojson")) as f:
        return [tuple(p) for p in json.load(f)["features"][0]["geometry"]["coordinates"][0][:-1]]


# ---- an exact simplicity test --------------------------------------------------------------------

def exact_area(ring):
    """The polygon's signed area, exactly (as a fraction)."""
    q = [(Fraction(x), Fraction(y)) for x, y in ring]
    return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(q, q[1:] + q[:1])) / 2


def orient(a, b, c):
    """Sign of the turn a -> b -> c, exactly (the doubles as fractions)."""
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def on_segment(p, a, b):
    """p on the closed segment a-b (p, a, b collinear)."""
    return min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def segments_meet(a, b, c, d):
    """Whether the closed segments a-b and c-d have a point in common."""
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    return ((o1 == 0 and on_segment(c, a, b)) or (o2 == 0 and on_segment(d, a, b))
            or (o3 == 0 and on_segment(a, c, d)) or (o4 == 0 and on_segment(b, c, d)))


def simplicity_defect(ring):
    """None for a simple polygon (at least 3 distinct vertices, positive area, edges meeting only
    where consecutive ones share their vertex, no spike back along an edge); otherwise what is
    wrong. Exact: the vertices are taken as fractions."""
    q = [(Fraction(x), Fraction(y)) for x, y in ring]
    n = len(q)
    if n < 3 or len(set(q)) != n:
        return f"{n} vertices, {len(set(q))} distinct"
    edges = [(q[i], q[(i + 1) % n]) for i in range(n)]
    for i in range(n):
        a, b = edges[i]
        c = edges[(i + 1) % n][1]
        if orient(a, b, c) == 0 and (c[0] - b[0]) * (a[0] - b[0]) + (c[1] - b[1]) * (a[1] - b[1]) > 0:
            return f"a spike at vertex {(i + 1) % n}"
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue  # consecutive (the closing edge)
            if segments_meet(a, b, *edges[j]):
                return f"edges {i} and {j} meet"
    if exact_area(ring) <= 0:
        return "not anticlockwise"
    return None


def projection_record(data):
    """The TesseraProjection field-data record of a data object, or None."""
    array = data.GetFieldData().GetAbstractArray("TesseraProjection")
    return array.GetValue(0) if array else None


def points_in_blocks(*block_coords):
    """vtkMultiBlockDataSet with block k holding make_points(block_coords[k])."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    blocks = vtkMultiBlockDataSet()
    for k, coords in enumerate(block_coords):
        blocks.SetBlock(k, make_points(coords))
    return blocks


def make_points(coords, **arrays):
    """vtkPolyData of (x, y) points (z = 0, double precision), with one double point-data array
    per keyword argument (name=list of values)."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    points = vtkPoints()
    points.SetDataTypeToDouble()
    for x, y in coords:
        points.InsertNextPoint(x, y, 0.0)
    data = vtkPolyData()
    data.SetPoints(points)
    for name, values in arrays.items():
        array = vtkDoubleArray()
        array.SetName(name)
        for v in values:
            array.InsertNextValue(v)
        data.GetPointData().AddArray(array)
    return data


def run(tests):
    """Runs every test function, prints a summary line ctest users can read, exits 1 on failure.
    A test_ function of the script that is not in the list fails too (one was written and never
    run)."""
    passed = failed = 0
    script = vars(sys.modules["__main__"])
    listed = {test.__name__ for test in tests}
    for name in sorted(n for n, f in script.items() if n.startswith("test_") and callable(f) and n not in listed):
        failed += 1
        print(f"FAIL {name}: defined but not in the list given to run()")
    for test in tests:
        try:
            test()
            passed += 1
            print(f"PASS {test.__name__}")
        except Exception as error:  # report every failing test, not only the first
            failed += 1
            print(f"FAIL {test.__name__}: {error!r}")
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)
