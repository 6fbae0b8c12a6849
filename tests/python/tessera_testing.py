"""Small helpers shared by the Python tests: a failing check raises AssertionError with a message,
and the process exits non-zero, so ctest sees the failure."""

import os
import sys

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
    """Runs every test function, prints a summary line ctest users can read, exits 1 on failure."""
    failed = 0
    for test in tests:
        try:
            test()
            print(f"PASS {test.__name__}")
        except Exception as error:  # report every failing test, not only the first
            failed += 1
            print(f"FAIL {test.__name__}: {error!r}")
    print(f"{len(tests) - failed} passed, {failed} failed")
    sys.exit(1 if failed else 0)
