"""vtkDirichletTessellation and vtkDelaunayTriangulation from Python, checked against independent
computations: brute-force nearest points, VTK's own vtkDelaunay2D, and hand-known lattices."""

import math
import random
import sys
from fractions import Fraction

import numpy as np
from vtkmodules.vtkCommonCore import vtkCommand, vtkIdList
from vtkmodules.vtkFiltersCore import vtkDelaunay2D

from tessera import vtkDelaunayTriangulation, vtkDirichletTessellation, vtkWindowClip
from tessera_testing import (assert_close, assert_that, double_array, make_points, messages_of, points_in_blocks,
                             polygon, run, warnings_of_update)


def tessellate(data, bounds=None, algorithm="GreenSibson"):
    f = vtkDirichletTessellation()
    f.SetInputData(data)
    if bounds:
        f.SetWindowBounds(*bounds)
    getattr(f, f"SetAlgorithmTo{algorithm}")()
    f.Update()
    return f


def tile_polygons(tiles):
    polys = []
    for c in range(tiles.GetNumberOfCells()):
        ids = tiles.GetCell(c).GetPointIds()
        polys.append(np.array([tiles.GetPoint(ids.GetId(k))[:2] for k in range(ids.GetNumberOfIds())]))
    return polys


def shoelace(poly):
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def test_tiles_are_nearest_point_regions():
    rng = random.Random(1)
    coords = [(rng.uniform(0, 10), rng.uniform(0, 10)) for _ in range(300)]
    values = [rng.uniform(0, 50) for _ in coords]
    f = tessellate(make_points(coords, precip=values), bounds=(-1, 11, -1, 11))
    tiles = f.GetOutput(0)
    assert_that(tiles.GetNumberOfCells() == 300, "one tile per point")
    pts = np.array(coords)
    ids = tiles.GetCellData().GetArray("PointId")
    areas = tiles.GetCellData().GetArray("Area")
    precip = tiles.GetCellData().GetArray("precip")
    total = 0.0
    for c, poly in enumerate(tile_polygons(tiles)):
        pid = ids.GetValue(c)
        area = shoelace(poly)
        assert_that(area > 0, f"tile {c} is anticlockwise")
        assert_close(areas.GetValue(c), area, 1e-9 * 144, f"Area of tile {c}")
        total += areas.GetValue(c)
        assert_that(precip.GetValue(c) == values[pid], f"point data follows tile {c}")
        # Brute force: sample points inside the tile (convex combinations of its corners) are
        # nearest to the tile's point, and every corner is equidistant to it and its nearest.
        rng2 = np.random.default_rng(c)
        for _ in range(5):
            w = rng2.dirichlet(np.ones(len(poly)))
            q = w @ poly
            d = np.hypot(*(pts - q).T)
            assert_that(d[pid] <= d.min() * (1 + 1e-9) + 1e-12, f"sample in tile {c} nearest to point {pid}")
        for corner in poly:
            d = np.hypot(*(pts - corner).T)
            assert_that(abs(d[pid] - d.min()) <= 1e-9 * 12, f"corner of tile {c} equidistant")
    assert_close(total, 144.0, 144.0 * 1e-12, "tile areas sum to the window area")
    # The active scalars (what a view colours by): Area on the tiles, whose input had none, and
    # Kind on the graph.
    scalars = (tiles.GetCellData().GetScalars(), f.GetOutput(1).GetCellData().GetScalars())
    assert_that([a.GetName() if a else None for a in scalars] == ["Area", "Kind"], f"active scalars {scalars}")


def delaunay2d_triangles(coords):
    d = vtkDelaunay2D()
    d.SetInputData(make_points(coords))
    d.Update()
    out = d.GetOutput()
    tris = set()
    for c in range(out.GetNumberOfCells()):
        ids = out.GetCell(c).GetPointIds()
        tris.add(tuple(sorted(ids.GetId(k) for k in range(3))))
    return tris


def test_delaunay_faces_match_vtk_delaunay2d_and_count():
    rng = random.Random(2)
    coords = [(rng.uniform(0, 1), rng.uniform(0, 1)) for _ in range(400)]
    t = vtkDelaunayTriangulation()
    t.SetInputData(make_points(coords))
    t.Update()
    out = t.GetOutput()
    assert_that(out.GetNumberOfPoints() == 400, "all input points kept in order")
    ours = set()
    for c in range(out.GetNumberOfCells()):
        ids = out.GetCell(c).GetPointIds()
        assert_that(ids.GetNumberOfIds() == 3, "random points give triangles")
        ours.add(tuple(sorted(ids.GetId(k) for k in range(3))))
    # vtkDelaunay2D (inexact) is known to miss thin triangles along the hull: every triangle it
    # finds must be ours, and each one only we find must pass the exact empty-circle test.
    theirs = delaunay2d_triangles(coords)
    assert_that(theirs <= ours, f"{len(theirs - ours)} vtkDelaunay2D triangles are missing")
    for tri in sorted(ours - theirs) + sorted(ours)[:40]:
        assert_that(exactly_empty_circle(tri, coords), f"triangle {tri} has a point in its circumcircle")
    # 2n - 2 - h triangles, h from the convex hull (monotone chain, computed here)
    hull = convex_hull(coords)
    assert_that(len(ours) == 2 * 400 - 2 - len(hull), f"{len(ours)} triangles for h = {len(hull)}")


def exactly_empty_circle(tri, coords):
    """Brute force in exact rational arithmetic: no point strictly inside the circumcircle."""
    a, b, c = [tuple(Fraction(v) for v in coords[i]) for i in tri]
    orientation = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    for j, p in enumerate(coords):
        if j in tri:
            continue
        d = (Fraction(p[0]), Fraction(p[1]))
        rows = [(q[0] - d[0], q[1] - d[1]) for q in (a, b, c)]
        rows = [(x, y, x * x + y * y) for x, y in rows]
        det = (rows[0][0] * (rows[1][1] * rows[2][2] - rows[1][2] * rows[2][1])
               - rows[0][1] * (rows[1][0] * rows[2][2] - rows[1][2] * rows[2][0])
               + rows[0][2] * (rows[1][0] * rows[2][1] - rows[1][1] * rows[2][0]))
        if det * (1 if orientation > 0 else -1) > 0:
            return False
    return True


def convex_hull(coords):
    pts = sorted(set(coords))

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def test_square_lattice_has_square_tiles_and_diagonal_half_neighbours():
    coords = [(i, j) for i in range(5) for j in range(5)]
    f = tessellate(make_points(coords), bounds=(-0.5, 4.5, -0.5, 4.5))
    tiles, graph = f.GetOutput(0), f.GetOutput(1)
    areas = tiles.GetCellData().GetArray("Area")
    counts = tiles.GetCellData().GetArray("NeighborCount")
    assert_that(tiles.GetNumberOfCells() == 25, f"{tiles.GetNumberOfCells()} tiles for 25 points")
    for c in range(tiles.GetNumberOfCells()):
        assert_close(areas.GetValue(c), 1.0, 1e-15, f"tile {c} is a unit square")
        assert_that(counts.GetValue(c) == 4, f"tile {c} has 4 sides (neighbours + window edges)")
    kinds = graph.GetCellData().GetArray("Kind")
    edges, halves = set(), set()
    for c in range(graph.GetNumberOfCells()):
        ids = graph.GetCell(c).GetPointIds()
        a, b = coords[ids.GetId(0)], coords[ids.GetId(1)]
        (halves if kinds.GetValue(c) == 1 else edges).add((a, b))
    for (a, b) in edges:
        assert_that(abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1, f"edge neighbours {a} {b} are adjacent")
    for (a, b) in halves:
        assert_that(abs(a[0] - b[0]) == 1 and abs(a[1] - b[1]) == 1, f"half-neighbours {a} {b} are diagonal")
    assert_that(len(edges) == 2 * 5 * 4, f"{len(edges)} edge contiguities")
    assert_that(len(halves) == 2 * 4 * 4, f"{len(halves)} half-neighbour pairs (both diagonals of 16 squares)")
    t = vtkDelaunayTriangulation()
    t.SetInputData(make_points(coords))
    t.Update()
    assert_that(t.GetOutput().GetNumberOfCells() == 16, "16 degenerate square faces")
    t.SplitDegenerateFacesOn()
    t.Update()
    assert_that(t.GetOutput().GetNumberOfCells() == 32, "split into 32 triangles")


def test_unused_points_are_reported_with_ids():
    coords = [(0.2, 0.2), (0.8, 0.3), (5.0, 5.0), (0.2, 0.2), (0.5, 0.9), (0.8, 0.3)]
    f = tessellate(make_points(coords), bounds=(0, 1, 0, 1))
    fd = f.GetOutput(0).GetFieldData()
    rejected = [fd.GetArray("RejectedPointIds").GetValue(i) for i in range(fd.GetArray("RejectedPointIds").GetNumberOfTuples())]
    dups = fd.GetArray("DuplicatePointIds")
    of = fd.GetArray("DuplicateOfPointIds")
    pairs = sorted((dups.GetValue(i), of.GetValue(i)) for i in range(dups.GetNumberOfTuples()))
    assert_that(rejected == [2], f"point 2 outside the window: {rejected}")
    assert_that(pairs == [(3, 0), (5, 1)], f"duplicates reported with their originals: {pairs}")
    assert_that(f.GetOutput(0).GetNumberOfCells() == 3, "three distinct points inside")
    # The warning names the first ids too (a trial's script had the counts alone), for either
    # engine and for the triangulation.
    for algorithm in ("GreenSibson", "BrasselReif", None):
        g = vtkDirichletTessellation() if algorithm else vtkDelaunayTriangulation()
        said = messages_of(g, vtkCommand.WarningEvent)
        g.SetInputData(make_points(coords))
        g.SetWindowBounds(0, 1, 0, 1)
        if algorithm:
            getattr(g, f"SetAlgorithmTo{algorithm}")()
        g.Update()
        assert_that(len(said) == 1 and said[0].strip().endswith("; outside: point(s) 2; duplicates: point 3 (of point 0), "
                                                                "point 5 (of point 1)."), f"{algorithm}: {said}")
    # Points that differ in z alone are duplicates (z is not used), and the warning says why.
    data = make_points([(0.2, 0.2), (0.8, 0.3), (0.5, 0.9)])
    data.GetPoints().InsertNextPoint(0.2, 0.2, 7.0)
    g = vtkDirichletTessellation()
    said = messages_of(g, vtkCommand.WarningEvent)
    g.SetInputData(data)
    g.Update()
    assert_that(id_values(g.GetOutput(0).GetFieldData(), "DuplicatePointIds") == [3]
                and len(said) == 1 and "1 exact duplicate(s) (the same x and y; z is not used)" in said[0],
                f"a point differing in z only: {said}")
    # Every point outside the window (bounds in other units, or in the order xmin, ymin, ...): the
    # count alone was said and the output was empty; then a second warning named both boxes. One
    # warning now names both boxes and the ids, with either engine and for the triangulation.
    data = make_points([(3.0, 1.0), (12.0, 5.0), (7.5, 2.5)])
    for filter_class, algorithm in ((vtkDirichletTessellation, "GreenSibson"),
                                    (vtkDirichletTessellation, "BrasselReif"), (vtkDelaunayTriangulation, None)):
        g = filter_class()
        said = messages_of(g, vtkCommand.WarningEvent)
        g.SetInputData(data)
        g.SetWindowBounds(100, 200, 100, 200)
        if algorithm:
            getattr(g, f"SetAlgorithmTo{algorithm}")()
        g.Update()
        assert_that(g.GetOutput(0).GetNumberOfCells() == 0 and len(said) == 1
                    and f"no point lies inside the window (x 100 .. 200, y 100 .. 200), so there is no "
                        f"{'triangle' if algorithm is None else 'tile'}: the points span x 3 .. 12, y 1 .. 5 (is the "
                        "window in the points' units" in said[0]
                    and said[0].strip().endswith("; all 3 point(s) are in the field data array RejectedPointIds: 0, 1, 2.")
                    and id_values(g.GetOutput(0).GetFieldData(), "RejectedPointIds") == [0, 1, 2],
                    f"{filter_class.__name__} {algorithm}: every point outside: {said}")
    # Points in the window's box but outside its constraint, or on its boundary: no hint on units.
    g = vtkDirichletTessellation()
    said = messages_of(g, vtkCommand.WarningEvent)
    g.SetInputData(make_points([(0.75, 0.75), (0.9, 0.2), (0.0, 0.5)]))
    g.SetWindowBounds(0, 1, 0, 1)
    g.AddWindowConstraint(1, 1, -1)  # x + y < 1
    g.Update()
    assert_that(len(said) == 1 and "(the boxes overlap, but each point lies outside the window or on its boundary)"
                in said[0],
                f"points outside a constraint: {said}")
    # Points outside alone, or duplicates alone: the warning leaves out the count of none ("and 0
    # exact duplicate(s)") and the arrays that are empty.
    for coords, expected, absent in (
            ([(0.2, 0.2), (0.8, 0.3), (0.5, 0.9), (5.0, 5.0)],
             "1 point(s) outside the window or on its boundary were not used; their ids are in the field data array "
             "RejectedPointIds; outside: point(s) 3.", "duplicate"),
            ([(0.2, 0.2), (0.8, 0.3), (0.5, 0.9), (0.8, 0.3)],
             "1 exact duplicate(s) (the same x and y; z is not used) were not used; their ids are in the field data "
             "arrays DuplicatePointIds and DuplicateOfPointIds; duplicates: point 3 (of point 1).", "outside")):
        g = vtkDirichletTessellation()
        g.SetWindowBounds(0, 1, 0, 1)
        said = warnings_of_update(g, make_points(coords))
        assert_that(len(said) == 1 and said[0].strip().endswith(expected) and absent not in said[0],
                    f"{coords}: {said}")


def id_values(field_data, name):
    array = field_data.GetArray(name)
    return None if array is None else [int(array.GetValue(i)) for i in range(array.GetNumberOfTuples())]


def test_input_field_data_named_like_the_unused_point_ids_is_kept_under_another_name():
    """An input whose field data already has RejectedPointIds / DuplicatePointIds (e.g. the output
    of an earlier tessellation) keeps them, renamed NAME_input, beside the filter's own, which
    list this run's unused points (computed here from the window and the coordinates); the
    input's arrays keep their names, and a warning names each renamed array."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkIdTypeArray

    coords = [(0.2, 0.2), (0.8, 0.3), (5.0, 5.0), (0.2, 0.2), (0.5, 0.9), (-1.0, 0.5)]
    outside = [i for i, (x, y) in enumerate(coords) if not (0 < x < 1 and 0 < y < 1)]
    copies = [i for i, p in enumerate(coords) if p in coords[:i] and i not in outside]
    data = make_points(coords)
    for name, value in (("RejectedPointIds", 99), ("DuplicatePointIds", 98)):
        upstream = vtkIdTypeArray()
        upstream.SetName(name)
        upstream.InsertNextValue(value)
        data.GetFieldData().AddArray(upstream)
    filters = []
    for graph in (True, False):
        f = vtkDirichletTessellation()
        f.SetComputeContiguityGraph(graph)
        filters.append((f"tessellation (graph {graph})", f, (0, 1)))
    filters.append(("Delaunay", vtkDelaunayTriangulation(), (0,)))
    for what, f, ports in filters:
        f.SetInputData(data)
        f.SetWindowBounds(0, 1, 0, 1)
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.Update()
        for port in ports:
            fd = f.GetOutput(port).GetFieldData()
            where = f"{what}, output {port}"
            assert_that(id_values(fd, "RejectedPointIds") == outside, f"{where}: own rejected ids")
            assert_that(id_values(fd, "DuplicatePointIds") == copies, f"{where}: own duplicate ids")
            assert_that(id_values(fd, "RejectedPointIds_input") == [99], f"{where}: input's kept")
            assert_that(id_values(fd, "DuplicatePointIds_input") == [98], f"{where}: input's kept")
        renamed = [w for w in warnings if "RejectedPointIds_input" in w and "DuplicatePointIds_input" in w]
        assert_that(len(renamed) == 1, f"{what}: one warning names the renamed arrays: {warnings}")
    assert_that(id_values(data.GetFieldData(), "RejectedPointIds") == [99], "the input keeps its names")
    assert_that(data.GetFieldData().GetArray("RejectedPointIds_input") is None, "nor gains arrays")


def test_degenerate_inputs_give_valid_output():
    for coords, cells in [([], 0), ([(0.5, 0.5)], 1), ([(0.2, 0.5), (0.7, 0.5)], 2),
                          ([(0.1, 0.1), (0.3, 0.3), (0.5, 0.5), (0.9, 0.9)], 4)]:
        f = tessellate(make_points(coords), bounds=(0, 1, 0, 1))
        tiles = f.GetOutput(0)
        assert_that(tiles.GetNumberOfCells() == cells, f"{len(coords)} points give {cells} tiles")
        total = sum(tiles.GetCellData().GetArray("Area").GetValue(c) for c in range(cells))
        if cells:
            assert_close(total, 1.0, 1e-12, f"{len(coords)} points: tiles fill the window")
        t = vtkDelaunayTriangulation()
        said = messages_of(t, vtkCommand.WarningEvent)
        t.SetInputData(make_points(coords))
        t.Update()
        assert_that(t.GetOutput().GetNumberOfCells() == 0, f"{len(coords)} collinear/few points: no face")
        # No face is said, and no point (an upstream filter that failed or kept none: a ParaView
        # user saw an empty output without a word).
        expected = (["the input has no points: no triangle (does the filter before it give none?)"]
                    if not coords else ["fewer than three distinct points"] if len(coords) < 3
                    else ["the 4 distinct points triangulated all lie on one line"])
        assert_that(len(said) == len(expected) and all(e in w for e, w in zip(expected, said)),
                    f"{len(coords)} points: {said}")
        d = vtkDirichletTessellation()
        d.SetWindowBounds(0, 1, 0, 1)
        said = warnings_of_update(d, make_points(coords))
        expected = ["the input has no points: no tile and no contiguity"] if not coords else []
        assert_that(len(said) == len(expected) and all(e in w for e, w in zip(expected, said)),
                    f"{len(coords)} points, tiles: {said}")
    # Without a window, points without extent get the square of side 1 centred on them (the
    # header's rule: a padding of a zero side would leave no window).
    for coords in ([(5e6, 7e6)], [(5e6, 7e6)] * 3):
        tiles = tessellate(make_points(coords)).GetOutput(0)
        bounds = tiles.GetBounds()[:4]
        assert_that(tiles.GetNumberOfCells() == 1 and tiles.GetCellData().GetArray("Area").GetValue(0) == 1.0
                    and bounds == (5e6 - 0.5, 5e6 + 0.5, 7e6 - 0.5, 7e6 + 0.5),
                    f"{len(coords)} copies of one point: the unit square around it, got {bounds}")


def graph_pairs(graph):
    kinds = graph.GetCellData().GetArray("Kind")
    pairs = {0: set(), 1: set()}
    for c in range(graph.GetNumberOfCells()):
        ids = graph.GetCell(c).GetPointIds()
        pairs[kinds.GetValue(c)].add((ids.GetId(0), ids.GetId(1)))
    return pairs


def test_both_engines_agree():
    rng = random.Random(4)
    uniform = [(rng.uniform(0, 1), rng.uniform(0, 1)) for _ in range(2000)]
    clusters = [(rng.gauss(0.3, 0.05), rng.gauss(0.3, 0.05)) for _ in range(500)] + \
               [(rng.gauss(0.7, 0.08), rng.gauss(0.6, 0.08)) for _ in range(500)]
    lattice = [(i / 20, j / 20) for i in range(20) for j in range(20)]
    c, s_ = math.cos(0.3), math.sin(0.3)
    rotated = [(0.5 + c * (x - 0.5) - s_ * (y - 0.5), 0.5 + s_ * (x - 0.5) + c * (y - 0.5)) for x, y in lattice]
    for name, coords in (("uniform", uniform), ("clusters", clusters), ("lattice", lattice), ("rotated", rotated)):
        data = make_points(coords)
        green = tessellate(data, bounds=(-0.5, 1.5, -0.5, 1.5), algorithm="GreenSibson")
        brassel = tessellate(data, bounds=(-0.5, 1.5, -0.5, 1.5), algorithm="BrasselReif")
        a, b = graph_pairs(green.GetOutput(1)), graph_pairs(brassel.GetOutput(1))
        assert_that(a[0] == b[0], f"{name}: Kind 0 pairs differ in {len(a[0] ^ b[0])}")
        assert_that(a[1] == b[1], f"{name}: Kind 1 pairs differ in {len(a[1] ^ b[1])}")
        ta, tb = green.GetOutput(0), brassel.GetOutput(0)
        assert_that(ta.GetNumberOfCells() == tb.GetNumberOfCells(), f"{name}: tile counts")
        # The polygons as written have the areas the cores report, and each engine's tiles make
        # a conforming mesh: a side inside the window is one pair of point ids in two tiles, a
        # side on the window's boundary is in one (Brassel-Reif's tiles each had their own
        # corners: 2213 sides in one tile where Green-Sibson's had 45).
        for engine, tiles in (("GreenSibson", ta), ("BrasselReif", tb)):
            areas = tiles.GetCellData().GetArray("Area")
            for k, poly in enumerate(tile_polygons(tiles)):
                assert_close(shoelace(poly), areas.GetValue(k), 4.0 * 1e-12,
                             f"{name}, {engine}: written tile {k}")
            uses = {}
            ids = vtkIdList()
            for k in range(tiles.GetNumberOfCells()):
                tiles.GetCellPoints(k, ids)
                ring = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
                for u, v in zip(ring, ring[1:] + ring[:1]):
                    uses[frozenset((u, v))] = uses.get(frozenset((u, v)), 0) + 1
            def on_boundary(side):
                (x0, y0, _), (x1, y1, _) = (tiles.GetPoint(i) for i in side)
                return any(a == b == c for a, b, c in ((x0, x1, -0.5), (x0, x1, 1.5), (y0, y1, -0.5), (y0, y1, 1.5)))
            wrong = [side for side, count in uses.items() if count != (1 if on_boundary(side) else 2)]
            assert_that(not wrong, f"{name}, {engine}: {len(wrong)} of {len(uses)} sides are not shared as a mesh's")
        for k in range(ta.GetNumberOfCells()):
            assert_that(ta.GetCellData().GetArray("PointId").GetValue(k) == tb.GetCellData().GetArray("PointId").GetValue(k),
                  f"{name}: tile order")
            assert_close(ta.GetCellData().GetArray("Area").GetValue(k), tb.GetCellData().GetArray("Area").GetValue(k),
                        4.0 * 1e-12, f"{name}: area of tile {k}")
        if name == "lattice":
            assert_that(len(a[1]) == 2 * 19 * 19, f"lattice: both diagonals of every square are half-neighbours ({len(a[1])})")


def test_brassel_reif_refuses_a_non_rectangular_window():
    f = vtkDirichletTessellation()
    messages = messages_of(f)
    f.SetInputData(make_points([(0.2, 0.2), (0.4, 0.5)]))
    f.SetWindowBounds(0, 1, 0, 1)
    f.AddWindowConstraint(1, 1, -1.5)  # x + y < 1.5 cuts a corner
    f.SetAlgorithmToBrasselReif()
    f.Update()
    assert_that(len(messages) == 1 and "a rectangle with sides parallel to the axes" in messages[0]
                and "window constraint 0 gives a slanted side;" in messages[0],
                f"clear error naming the constraint: {messages}")
    # Constraints that leave a rectangle (x < 0.5 here) are taken, as the message says.
    f.RemoveAllWindowConstraints()
    f.AddWindowConstraint(1, 0, -0.5)
    f.Update()
    areas = f.GetOutput(0).GetCellData().GetArray("Area")
    assert_that(len(messages) == 1 and areas is not None and areas.GetNumberOfTuples() == 2, f"x < 0.5: {messages}")
    assert_close(areas.GetValue(0) + areas.GetValue(1), 0.5, 1e-15, "the tiles fill the half window")


def test_nan_point_is_named():
    f = vtkDirichletTessellation()
    messages = messages_of(f)
    f.SetInputData(make_points([(0, 0), (1, 1), (math.nan, 2)]))
    f.Update()
    assert_that(len(messages) == 1 and "point 2" in messages[0], f"error names point 2: {messages}")
    assert_that(f.GetOutput(0).GetNumberOfCells() == 0, "empty output")
    # Points joined from blocks: the joined id, and the point's own block and number in it.
    blocks = points_in_blocks([(0, 0), (1, 1)], [], [(2, 0), (math.nan, 2), (3, 3)])
    for filter_class in (vtkDirichletTessellation, vtkDelaunayTriangulation):
        f = filter_class()
        messages = messages_of(f)
        f.SetInputData(blocks)
        f.Update()
        assert_that(len(messages) == 1 and "point 3 (point 1 of block 2 (composite index 3)) has a NaN" in messages[0],
                    f"{filter_class.__name__}: {messages}")


def test_integer_points_beyond_what_a_double_holds_are_named():
    # Points of 64-bit integers beyond 2^53 were rounded to doubles silently: 2^62 + 1 and 2^62
    # became one point, reported as a duplicate. Those a double holds (2^62 itself, or anything up
    # to 2^53) are taken as they are.
    from vtkmodules.vtkCommonCore import (vtkIdTypeArray, vtkPoints, vtkSOADataArrayTemplate, vtkTypeInt64Array,
                                          vtkTypeUInt64Array)
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    # (a structure of arrays, each coordinate in an array of its own, was not checked)
    soa = vtkSOADataArrayTemplate["int64"]
    for kind, big in ((vtkTypeInt64Array, 2 ** 62), (vtkTypeInt64Array, -2 ** 62), (vtkIdTypeArray, 2 ** 62),
                      (vtkTypeUInt64Array, 2 ** 63), (soa, 2 ** 62), (vtkTypeInt64Array, 2 ** 53 - 1)):
        values = kind()
        values.SetNumberOfComponents(3)
        coordinates = [(0, 0), (big, 0), (big + (1 if big > 0 else -1), 0), (0, abs(big))]
        for x, y in coordinates:
            for value in (x, y, 0):
                values.InsertNextValue(value)
        points = vtkPoints()
        points.SetData(values)
        data = vtkPolyData()
        data.SetPoints(points)
        f = vtkDirichletTessellation()
        messages = messages_of(f)
        f.SetInputData(data)
        f.Update()
        what = f"{kind.__name__} {big}"
        if abs(big) > 2 ** 53:
            beyond = big + (1 if big > 0 else -1)
            assert_that(len(messages) == 1 and f"point 2 has the integer coordinate {beyond}, which the doubles"
                        in messages[0] and f.GetOutput(0).GetNumberOfCells() == 0, f"{what}: {messages}")
        else:
            duplicates = f.GetOutput(0).GetFieldData().GetArray("DuplicatePointIds")
            assert_that(not messages and f.GetOutput(0).GetNumberOfCells() == 4
                        and duplicates.GetNumberOfTuples() == 0, f"{what}: {messages}")


def test_tiles_form_a_conforming_mesh():
    # Tiles that meet share their corner points: VTK's edge filters find no non-manifold edge, and
    # boundary edges only along the window, whose perimeter they add up to; merging coincident
    # points (vtkCleanPolyData) finds nothing to merge.
    from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFeatureEdges

    rng = random.Random(12)
    # Enough tiles for the core to derive them in two chunks, whose crossings are merged.
    coords = [(rng.uniform(0, 1), rng.uniform(0, 1)) for _ in range(7000)]
    coords = [(x, y) for x, y in coords if x + y < 1.45]
    f = vtkDirichletTessellation()
    f.SetInputData(make_points(coords))
    f.SetWindowBounds(0, 1, 0, 1)
    f.AddWindowConstraint(1, 1, -1.5)  # x + y < 1.5 cuts a corner
    f.Update()
    tiles = f.GetOutput(0)
    references = sum(tiles.GetCell(c).GetNumberOfPoints() for c in range(tiles.GetNumberOfCells()))
    assert_that(tiles.GetNumberOfPoints() < references / 2.5,
                f"corners shared: {tiles.GetNumberOfPoints()} points for {references} corners")
    edges = vtkFeatureEdges()
    edges.SetInputData(tiles)
    edges.BoundaryEdgesOff()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.NonManifoldEdgesOn()
    edges.Update()
    assert_that(edges.GetOutput().GetNumberOfCells() == 0, "no non-manifold edge")
    edges.NonManifoldEdgesOff()
    edges.BoundaryEdgesOn()
    edges.Update()
    boundary = edges.GetOutput()
    length = 0.0
    for c in range(boundary.GetNumberOfCells()):
        a, b = (np.array(boundary.GetPoint(boundary.GetCell(c).GetPointId(k))[:2]) for k in (0, 1))
        length += float(np.linalg.norm(b - a))
        for p in (a, b):
            on_window = min(abs(p[0]), abs(p[0] - 1), abs(p[1]), abs(p[1] - 1), abs(p[0] + p[1] - 1.5))
            assert_that(on_window < 1e-12, f"boundary edge {c} lies on the window ({p})")
    assert_close(length, 3 + math.sqrt(0.5), 1e-12, "boundary edges add up to the window's perimeter")
    clean = vtkCleanPolyData()
    clean.SetInputData(tiles)
    clean.PointMergingOn()
    clean.SetTolerance(0.0)
    clean.Update()
    assert_that(clean.GetOutput().GetNumberOfPoints() == tiles.GetNumberOfPoints(),
                "no two corner points coincide")


def test_large_graph_is_sorted_with_kinds_following_pairs():
    # 62,500 lattice points: enough for the filter to write on two threads. The graph's lines are
    # sorted by (i, j) with i < j, Kind 0 pairs are the lattice's edges and Kind 1 pairs its
    # squares' diagonals, all of them.
    from vtkmodules.util.numpy_support import vtk_to_numpy

    side = 250
    coords = [(i, j) for j in range(side) for i in range(side)]
    graph = tessellate(make_points(coords)).GetOutput(1)
    lines = vtk_to_numpy(graph.GetLines().GetConnectivityArray()).reshape(-1, 2).astype(np.int64)
    kinds = vtk_to_numpy(graph.GetCellData().GetArray("Kind"))
    assert_that(bool(np.all(lines[:, 0] < lines[:, 1])), "i < j on every line")
    key = lines[:, 0] * len(coords) + lines[:, 1]
    assert_that(bool(np.all(np.diff(key) > 0)), "lines sorted by (i, j), no repeats")
    ix, iy = lines % side, lines // side
    dx, dy = np.abs(ix[:, 1] - ix[:, 0]), np.abs(iy[:, 1] - iy[:, 0])
    edge = dx + dy == 1
    diagonal = (dx == 1) & (dy == 1)
    assert_that(bool(np.all(kinds[edge] == 0)) and bool(np.all(kinds[diagonal] == 1)),
                "Kind follows its pair")
    assert_that(int(edge.sum()) == 2 * side * (side - 1), f"all lattice edges ({int(edge.sum())})")
    assert_that(int(diagonal.sum()) == 2 * (side - 1) ** 2, f"all diagonals ({int(diagonal.sum())})")
    assert_that(len(kinds) == int(edge.sum() + diagonal.sum()), "nothing else")
    # PointIds lists each line's pair for a spreadsheet: the lines' own ids, components i and j.
    pairs = graph.GetCellData().GetArray("PointIds")
    assert_that(pairs.GetNumberOfComponents() == 2 and pairs.GetComponentName(0) == "i"
                and pairs.GetComponentName(1) == "j" and np.array_equal(vtk_to_numpy(pairs), lines),
                "PointIds are the lines' point ids")


def cells_of(data):
    return [tuple(data.GetCell(c).GetPointIds().GetId(k)
                  for k in range(data.GetCell(c).GetNumberOfPoints()))
            for c in range(data.GetNumberOfCells())]


def test_32_bit_cell_arrays_survive_a_vtp_round_trip():
    # The outputs' cell arrays use 32-bit storage: a VTK writer and reader (which store 64-bit
    # ids here) must give back the same cells, and the legacy GetData() the same ids.
    import os
    import tempfile
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

    rng = random.Random(9)
    coords = [(rng.uniform(0, 1), rng.uniform(0, 1)) for _ in range(300)]
    tiles = tessellate(make_points(coords)).GetOutput(0)
    t = vtkDelaunayTriangulation()
    t.SetInputData(make_points(coords))
    t.Update()
    for name, data in (("tiles", tiles), ("triangles", t.GetOutput())):
        assert_that(not data.GetPolys().IsStorage64Bit(), f"{name}: 32-bit cell storage")
        with tempfile.TemporaryDirectory() as directory:
            path = os.path.join(directory, name + ".vtp")
            writer = vtkXMLPolyDataWriter()
            writer.SetFileName(path)
            writer.SetInputData(data)
            assert_that(writer.Write() == 1, f"{name}: written")
            reader = vtkXMLPolyDataReader()
            reader.SetFileName(path)
            reader.Update()
            assert_that(cells_of(reader.GetOutput()) == cells_of(data), f"{name}: same cells read back")
        legacy = data.GetPolys().GetData()
        flat = []
        for cell in cells_of(data):
            flat += [len(cell), *cell]
        assert_that([legacy.GetValue(k) for k in range(legacy.GetNumberOfValues())] == flat,
                    f"{name}: legacy GetData() lists the same cells")


def test_graph_off_leaves_the_tiles_unchanged():
    # ComputeContiguityGraph off: output 1 empty, output 0 the same arrays bit for bit (both
    # engines; 60,000 points so that the filter writes on two threads; a point-data array, a
    # duplicate and a point outside the window so that everything output 0 carries is there).
    # Turning it back on brings the graph back.
    from vtkmodules.util.numpy_support import vtk_to_numpy

    rng = random.Random(12)
    coords = [(rng.uniform(0, 1), rng.uniform(0, 1)) for _ in range(60000)]
    coords += [coords[7], (3.0, 3.0)]
    data = make_points(coords, rain=[float(k % 97) for k in range(len(coords))])
    from vtkmodules.vtkCommonCore import vtkStringArray
    note = vtkStringArray()
    note.SetName("Provenance")
    note.InsertNextValue("field data every output keeps")
    data.GetFieldData().AddArray(note)

    def arrays(output):
        result = {"points": vtk_to_numpy(output.GetPoints().GetData()).copy(),
                  "offsets": vtk_to_numpy(output.GetPolys().GetOffsetsArray()).copy(),
                  "ids": vtk_to_numpy(output.GetPolys().GetConnectivityArray()).copy()}
        for data_set in (output.GetCellData(), output.GetFieldData()):
            for a in range(data_set.GetNumberOfArrays()):
                array = data_set.GetArray(a)  # None for the string array
                if array is not None:
                    result[array.GetName()] = vtk_to_numpy(array).copy()
        return result

    for algorithm in ("GreenSibson", "BrasselReif"):
        f = vtkDirichletTessellation()
        f.SetInputData(data)
        f.SetWindowBounds(-0.1, 1.1, -0.1, 1.1)
        getattr(f, f"SetAlgorithmTo{algorithm}")()
        f.Update()
        with_graph = arrays(f.GetOutput(0))
        pairs = f.GetOutput(1).GetNumberOfCells()
        assert_that(pairs > 2.9 * 60000, f"{algorithm}: a graph by default ({pairs} pairs)")
        f.ComputeContiguityGraphOff()
        f.Update()
        without = arrays(f.GetOutput(0))
        assert_that(sorted(with_graph) == sorted(without), f"{algorithm}: same arrays {sorted(without)}")
        for name in with_graph:
            assert_that(with_graph[name].dtype == without[name].dtype and
                        np.array_equal(with_graph[name], without[name]),
                        f"{algorithm}: {name} identical without the graph")
        assert_that(list(without["DuplicatePointIds"]) == [60000] and
                    list(without["RejectedPointIds"]) == [60001], f"{algorithm}: unused points listed")
        graph = f.GetOutput(1)
        assert_that(graph.GetNumberOfPoints() == 0 and graph.GetNumberOfCells() == 0,
                    f"{algorithm}: output 1 empty ({graph.GetNumberOfPoints()} points, "
                    f"{graph.GetNumberOfCells()} cells)")
        for port in (0, 1):
            kept = f.GetOutput(port).GetFieldData().GetAbstractArray("Provenance")
            assert_that(kept is not None and kept.GetValue(0) == note.GetValue(0),
                        f"{algorithm}: output {port} keeps the input's field data without the graph")
        f.ComputeContiguityGraphOn()
        f.Update()
        assert_that(f.GetOutput(1).GetNumberOfCells() == pairs, f"{algorithm}: the graph is back")


def test_automatic_window_keeps_every_point_and_bad_windows_are_named():
    # The automatic window's padding can be far below the coordinates' ulp: every point must still
    # get its tile (the window's sides move out to the next doubles), and the tiles fill it.
    import numpy as np

    x = 1e6
    cases = [("0.25 apart at 1e15", [(1e15, 1e15), (1e15 + 0.25, 1e15 + 0.25)], 0.1),
             ("1 ulp apart at 1e6", [(x, x), (float(np.nextafter(x, 2e6)),) * 2], 0.1),
             ("Padding 0 at 1e15", [(1e15 + a, 1e15 + b) for a, b in [(0, 0), (1, 0), (0, 1), (1, 1), (0.5, 0.5)]], 0.0),
             ("Padding 0 at 1e9", [(1e9 + a, 1e9 + b) for a, b in [(0, 0), (1, 0), (0, 1), (1, 1), (0.5, 0.5)]], 0.0),
             ("one point at 1e16", [(1e16, 1e16)], 0.1),
             ("identical points at 1e17", [(1e17, 1e17)] * 3, 0.1)]
    for name, coords, padding in cases:
        f = vtkDirichletTessellation()
        messages = messages_of(f)
        f.SetInputData(make_points(coords))
        f.SetPadding(padding)
        f.Update()
        tiles = f.GetOutput(0)
        distinct = len(set(coords))
        rejected = tiles.GetFieldData().GetArray("RejectedPointIds").GetNumberOfTuples()
        assert_that(tiles.GetNumberOfCells() == distinct and rejected == 0,
                    f"{name}: {tiles.GetNumberOfCells()} tiles of {distinct}, {rejected} rejected, {messages}")
    for name, setup, expected in [
            ("NaN bound", lambda f: f.SetWindowBounds(math.nan, 1, 0, 1), "WindowBounds xmin is NaN"),
            # (an infinite one was "rectangle window: xmin = -inf is not finite", not naming WindowBounds)
            ("infinite bound", lambda f: f.SetWindowBounds(0, 1, -math.inf, 1), "WindowBounds ymin is -inf"),
            ("infinite padding", lambda f: f.SetPadding(math.inf), "Padding inf is not a finite number >= 0"),
            ("huge padding", lambda f: f.SetPadding(1e300),
             "area overflows a double; it is the points' bounding box padded by 1e+300 of its larger side (Padding): set a smaller Padding"),
            ("huge bounds", lambda f: f.SetWindowBounds(-1e200, 1e200, -1e200, 1e200),
             "area overflows a double; set smaller WindowBounds or window constraints"),
            # Points whose own span overflows: no Padding helps (the advice was a smaller Padding,
            # where Padding was 0), nor does a window printed as -inf .. inf.
            ("points 1e300 apart", lambda f: (f.SetPadding(0), f.SetInputData(make_points([(-1e300, 0), (1e300, 1), (0, 1e300)]))),
             "the points span x -1e+300 .. 1e+300, y 0 .. 1e+300: the area of a window that holds them overflows a double, whatever the Padding"),
            # Points on one line at Padding 0, whose window keeps a margin of 1e-9 of the line: they
            # were told to set a smaller Padding than 0.
            ("points 1e200 apart on a line", lambda f: (f.SetPadding(0), f.SetInputData(make_points([(0, 0), (1e200, 0)]))),
             "it is the points' bounding box with a margin of 1e-9 of its larger side (Padding 0): set WindowBounds "
             f"close about the points, a Padding above 0 and below {sys.float_info.max / (4.0 * 1e200) / 1e200!r}"),
            # Points all at one place at 1e300, or an ulp apart there: their window is an ulp about
            # them, and Padding plays no part (it was blamed, at Padding 0 too).
            *[(f"{name} at Padding {padding}",
               lambda f, padding=padding, points=points: (f.SetPadding(padding), f.SetInputData(make_points(points))),
               "its area overflows a double; it is already the smallest window of doubles about the points, one unit "
               "in the last place beyond them each way, whatever the Padding: scale the points down")
              for padding in (0.0, 0.1)
              for name, points in (("one place at 1e300", [(1e300, 1e300)] * 2),
                                   ("an ulp apart at 1e300", [(1e300, 1e300), (math.nextafter(1e300, 2e300), 1e300)]))],
            ("padding past the doubles", lambda f: (f.SetPadding(1e200), f.SetInputData(make_points([(0, 0), (1e150, 1e150)]))),
             "the automatic window reaches beyond the largest double: it is the points' bounding box padded by 1e+200 of its larger side (Padding): set a smaller Padding")]:
        f = vtkDirichletTessellation()
        messages = messages_of(f)
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetInputData(make_points([(0.2, 0.3), (0.7, 0.6), (0.4, 0.9)]))
        setup(f)
        f.Update()
        assert_that(len(messages) == 1 and expected in messages[0] and f.GetOutput(0).GetNumberOfCells() == 0,
                    f"{name}: an error saying '{expected}', not NaN areas: {messages}")
        # (A NaN bound was also called an empty rectangle, "ymin >= ymax", in a warning.)
        assert_that(not warnings, f"{name}: no warning beside the error: {warnings}")
    # A Padding in the range the line's advice gives makes its tiles.
    f = vtkDirichletTessellation()
    messages = messages_of(f)
    f.SetInputData(make_points([(0, 0), (1e200, 0)]))
    f.SetPadding(1e-93)
    f.Update()
    assert_that(not messages and f.GetOutput(0).GetNumberOfCells() == 2, f"the line at Padding 1e-93: {messages}")


def test_window_constraint_errors_name_them_as_the_user_added_them():
    # With WindowBounds, the window is the rectangle's four sides and then the user's constraints:
    # errors used to number those from 4 ("window constraint 4" for the first one added) and to
    # count the sides as constraints ("the 5 constraints").
    cases = [
        ("a == b == 0", (0, 1, 0, 1), [(0, 0, -1)],
         "window constraint 0 has a == b == 0: it is no half-plane (a = 0, b = 0, c = -1)"),
        ("an infinite coefficient", (0, 1, 0, 1), [(0.5, 0.5, -0.5), (math.inf, 1, 1)],
         "window constraint 1 has an infinite coefficient (a = inf, b = 1, c = 1)"),
        ("no interior point", (0, 1, 0, 1), [(1, 1, 1)],
         "window is empty: WindowBounds and the 1 window constraint have no interior point in common"),
        ("two constraints, no interior point", (0, 1, 0, 1), [(1, 1, 1), (-1, 0, -0.5)],
         "window is empty: WindowBounds and the 2 window constraints have no interior point in common"),
        ("parallel to a side", (0, 1, 0, 1), [(1, 0, 1)],
         "window is empty: the WindowBounds side x > xmin (a = -1, b = 0, c = 0) and window constraint 0 "
         "(a = 1, b = 0, c = 1) are parallel and leave no room between them"),
        ("without WindowBounds", None, [(1, 0, -1), (-1, 0, 0), (0, 1, -1), (0, -1, 0), (0, 0, 2)],
         "window constraint 4 has a == b == 0"),
        ("unbounded without WindowBounds", None, [(1, 0, -1), (0, 1, -1)],
         "the boundary line of window constraint 0 (a = 1, b = 0, c = -1) is not closed off"),
    ]
    for name, bounds, constraints, expected in cases:
        for f in (vtkDirichletTessellation(), vtkDelaunayTriangulation()):
            messages = messages_of(f)
            f.SetInputData(make_points([(0.2, 0.3), (0.7, 0.6), (0.4, 0.9)]))
            if bounds:
                f.SetWindowBounds(*bounds)
            for a, b, c in constraints:
                f.AddWindowConstraint(a, b, c)
            f.Update()
            what = f"{f.GetClassName()}, {name}"
            assert_that(len(messages) == 1 and expected in messages[0], f"{what}: '{expected}' in {messages}")
            assert_that("a infinite" not in messages[0], f"{what}: {messages[0]}")


def test_empty_window_bounds_warn_and_leave_the_automatic_window():
    # Bounds given as (xmin, ymin, xmax, ymax) make an empty rectangle, ignored as documented: the
    # filters now say so. The default 0, 0, 0, 0 (no rectangle) and a proper rectangle are
    # silent, and the window used is the padded bounding box either way.
    from vtkmodules.vtkCommonCore import vtkCommand

    coords = [(0.2, 0.3), (0.7, 0.6), (0.4, 0.9), (0.9, 0.1)]
    for f in (vtkDirichletTessellation(), vtkDelaunayTriangulation()):
        what = f.GetClassName()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetInputData(make_points(coords))
        f.Update()
        cells = f.GetOutput().GetNumberOfCells()
        assert_that(warnings == [], f"{what}: default bounds warned {warnings}")
        f.SetWindowBounds(0.0, 0.0, 1.0, 1.0)  # (xmin, ymin, xmax, ymax) read as (xmin, xmax, ...)
        f.Update()
        assert_that(len(warnings) == 1 and "xmin >= xmax" in warnings[0] and "(xmin, ymin, xmax, ymax)"
                    in warnings[0] and "the window is the padded bounding box of the points" in warnings[0],
                    f"{what}: {warnings}")
        assert_that(f.GetOutput().GetNumberOfCells() == cells, f"{what}: output changed")
        f.SetWindowBounds(0.0, 1.0, 1.0, 0.5)
        f.Update()
        assert_that(len(warnings) == 2 and "ymin >= ymax" in warnings[1], f"{what}: {warnings}")
        assert_that(f.GetOutput().GetNumberOfCells() == cells, f"{what}: output changed")
        f.SetWindowBounds(0.0, 1.0, 0.0, 1.0)
        f.Update()
        f.SetWindowBounds(0.0, 0.0, 0.0, 0.0)
        f.Update()
        assert_that(len(warnings) == 2, f"{what}: a rectangle or the default warned {warnings[2:]}")
        # With constraints, an empty rectangle leaves the constraints alone as the window.
        for a, b, c in ((1, 0, -1), (-1, 0, 0), (0, 1, -1), (0, -1, 0)):
            f.AddWindowConstraint(a, b, c)
        f.SetWindowBounds(0.0, 0.0, 1.0, 1.0)
        f.Update()
        assert_that(len(warnings) == 3 and "the window is the window constraints alone" in warnings[2],
                    f"{what}: {warnings[2:]}")
        # Constraints that make no window alone: the warning still comes (it came only after a
        # window was made, so the error of an unbounded window never said the rectangle was
        # ignored).
        g = type(f)()
        said = messages_of(g, vtkCommand.WarningEvent)
        errors = messages_of(g, vtkCommand.ErrorEvent)
        g.SetInputData(make_points(coords))
        g.SetWindowBounds(0.0, 0.0, 1.0, 1.0)
        g.AddWindowConstraint(1.0, 1.0, -1.5)
        g.Update()
        assert_that(len(said) == 1 and "so it is ignored: the window is the window constraints alone" in said[0]
                    and len(errors) == 1 and "window is unbounded" in errors[0], f"{what}: {said} {errors}")
        # The error says what to do: one constraint meant to cut the automatic window is the window.
        assert_that("set WindowBounds for the constraints to cut" in errors[0], f"{what}: {errors}")
    d = vtkDelaunayTriangulation()
    assert_that(d.GetNumberOfWindowConstraints() == 0, "no constraint yet")
    d.AddWindowConstraint(1.0, 0.0, -2.0)
    d.AddWindowConstraint(0.0, 1.0, -2.0)
    assert_that(d.GetNumberOfWindowConstraints() == 2, "two constraints added")


def points_with_attribute_arrays(coords):
    """make_points with arrays named like the filter's own (Area, PointId, NeighborCount), one named
    like the first free name for Area (Area_input), a plain one, global ids and pedigree ids: each
    with values that tell the point apart."""
    from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkIntArray, vtkStringArray

    n = len(coords)
    data = make_points(coords, Area=[1000.0 + k for k in range(n)], PointId=[5000.0 + k for k in range(n)],
                       Area_input=[-1.0 - k for k in range(n)], rain=[0.5 * k for k in range(n)])
    counts = vtkIntArray()
    counts.SetName("NeighborCount")
    global_ids = vtkIdTypeArray()
    global_ids.SetName("GlobalIds")
    stations = vtkStringArray()
    stations.SetName("station")
    for k in range(n):
        counts.InsertNextValue(90 + k)
        global_ids.InsertNextValue(7 * k + 3)
        stations.InsertNextValue(f"S{k}")
    data.GetPointData().AddArray(counts)
    data.GetPointData().SetGlobalIds(global_ids)
    data.GetPointData().SetPedigreeIds(stations)
    data.GetPointData().SetActiveScalars("Area")
    return data


def test_input_arrays_named_like_the_filters_are_kept_under_another_name():
    # The filter's PointId, Area and NeighborCount are its own (checked against a brute-force
    # nearest point and the shoelace area of each tile); the input's arrays of those names reach
    # the tiles as NAME_input (Area as Area_input_2: the input has an Area_input too), named in a
    # warning; global and pedigree ids follow their tile like every other array, as attributes.
    from vtkmodules.vtkCommonCore import vtkCommand

    rng = random.Random(14)
    coords = [(rng.uniform(0, 1), rng.uniform(0, 1)) for _ in range(60)]
    coords += [coords[7], (3.0, 3.0)]  # a duplicate and a point outside the window: ids skip them
    data = points_with_attribute_arrays(coords)
    source = data.GetPointData()
    used = np.array(coords[:60])
    renamed = {"Area": "Area_input_2", "PointId": "PointId_input", "NeighborCount": "NeighborCount_input",
               "Area_input": "Area_input", "rain": "rain"}
    for algorithm in ("GreenSibson", "BrasselReif"):
        f = vtkDirichletTessellation()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetInputData(data)
        f.SetWindowBounds(-0.1, 1.1, -0.1, 1.1)
        getattr(f, f"SetAlgorithmTo{algorithm}")()
        f.Update()
        tiles = f.GetOutput(0)
        cells = tiles.GetCellData()
        assert_that(tiles.GetNumberOfCells() == 60, f"{algorithm}: 60 tiles")
        ids, areas, counts = (cells.GetArray(name) for name in ("PointId", "Area", "NeighborCount"))
        assert_that(ids.GetDataTypeAsString() == "idtype" and counts.GetDataTypeAsString() == "int",
                    f"{algorithm}: the filter's own PointId and NeighborCount")
        for k, poly in enumerate(tile_polygons(tiles)):
            pid = ids.GetValue(k)
            nearest = int(np.argmin(np.hypot(*(used - poly.mean(axis=0)).T)))
            assert_that(pid == nearest, f"{algorithm}: PointId of tile {k} is {pid}, its point is {nearest}")
            assert_close(areas.GetValue(k), shoelace(poly), 1.44e-12, f"{algorithm}: Area of tile {k}")
            assert_that(counts.GetValue(k) >= len(poly), f"{algorithm}: NeighborCount of tile {k}")
            for name, output_name in renamed.items():
                copy = cells.GetArray(output_name)
                assert_that(copy is not None and copy.GetValue(k) == source.GetArray(name).GetValue(pid),
                            f"{algorithm}: input {name} follows tile {k} as {output_name}")
            assert_that(cells.GetGlobalIds() is not None and cells.GetGlobalIds().GetName() == "GlobalIds"
                        and cells.GetGlobalIds().GetValue(k) == 7 * pid + 3,
                        f"{algorithm}: global ids follow tile {k} as the tiles' global ids")
            assert_that(cells.GetPedigreeIds() is not None and cells.GetPedigreeIds().GetValue(k) == f"S{pid}",
                        f"{algorithm}: pedigree ids follow tile {k}")
        assert_that(cells.GetScalars() is not None and cells.GetScalars().GetName() == "Area_input_2",
                    f"{algorithm}: the input's active scalars stay active under their new name")
        named = [m for m in warnings if "filter's own" in m]
        assert_that(len(named) == 1 and all(f"'{name}' is passed to the tiles as '{renamed[name]}'" in named[0]
                                            for name in ("Area", "PointId", "NeighborCount")),
                    f"{algorithm}: one warning naming each renamed array: {warnings}")
        # Output 1's points are the input points: their data keeps its names, global ids included.
        graph_data = f.GetOutput(1).GetPointData()
        assert_that(graph_data.GetArray("Area").GetValue(5) == 1005.0 and graph_data.GetGlobalIds() is not None,
                    f"{algorithm}: output 1 passes the input's point data as it is")
        plain = vtkDirichletTessellation()
        plain_warnings = messages_of(plain, vtkCommand.WarningEvent)
        plain.SetInputData(make_points(coords[:60], rain=[0.0] * 60))
        getattr(plain, f"SetAlgorithmTo{algorithm}")()
        plain.Update()
        assert_that(plain_warnings == [] and plain.GetOutput(0).GetCellData().GetArray("rain") is not None,
                    f"{algorithm}: no warning without a clash: {plain_warnings}")


def test_delaunay_passes_point_data_with_the_input_points():
    # vtkDelaunayTriangulation keeps the input points in order, so their data passes unchanged,
    # every name (it adds no point or cell array) and global ids included.
    coords = [(0.1, 0.2), (0.9, 0.1), (0.5, 0.8), (0.4, 0.4), (0.7, 0.6)]
    data = points_with_attribute_arrays(coords)
    t = vtkDelaunayTriangulation()
    t.SetInputData(data)
    t.Update()
    out = t.GetOutput().GetPointData()
    source = data.GetPointData()
    names = sorted(source.GetAbstractArray(a).GetName() for a in range(source.GetNumberOfArrays()))
    assert_that(sorted(out.GetAbstractArray(a).GetName() for a in range(out.GetNumberOfArrays())) == names,
                f"the input's point arrays, under their names: {names}")
    for name in ("Area", "PointId", "NeighborCount", "rain"):
        assert_that([out.GetArray(name).GetValue(k) for k in range(5)] ==
                    [source.GetArray(name).GetValue(k) for k in range(5)], f"{name} passed unchanged")
    assert_that(out.GetGlobalIds() is not None and [out.GetGlobalIds().GetValue(k) for k in range(5)] ==
                [7 * k + 3 for k in range(5)], "global ids passed as global ids")
    assert_that(t.GetOutput().GetCellData().GetNumberOfArrays() == 0, "no cell array of its own")


def test_tiles_at_any_scale_and_points_too_close_for_exact_tiles():
    """Coordinates of some 1e-270 to 1e150: the tiles equal those of the same points at scale 1,
    scaled, exactly (the filter works on points and window scaled by a power of two into the range
    where the tiles' window decisions are exact). Points some 1e-200 apart in a unit window are
    beyond that range: an error naming one instead of wrong tiles."""
    import random

    rng = random.Random(11)
    unit = [(rng.random(), rng.random()) for _ in range(200)]
    reference = tessellate(make_points(unit), bounds=(0, 1, 0, 1))
    ref_tiles = reference.GetOutput(0)
    ref_areas = [ref_tiles.GetCellData().GetArray("Area").GetValue(c) for c in range(ref_tiles.GetNumberOfCells())]
    ref_pairs = graph_pairs(reference.GetOutput(1))
    for exponent in (-900, -500, -400, 350, 500):
        s = math.ldexp(1.0, exponent)
        f = tessellate(make_points([(x * s, y * s) for x, y in unit]), bounds=(0, s, 0, s))
        tiles = f.GetOutput(0)
        areas = [tiles.GetCellData().GetArray("Area").GetValue(c) for c in range(tiles.GetNumberOfCells())]
        if exponent > -500:  # (at 2^-900, s^2 underflows: the areas are 0, as documented)
            assert_that(areas == [a * s * s for a in ref_areas] and min(areas) > 0,
                        f"2^{exponent}: areas are the unit set's times s^2")
        else:
            assert_that(areas == [0.0] * len(ref_areas) if exponent == -900 else areas == [a * s * s for a in ref_areas],
                        f"2^{exponent}: areas {areas[:3]}")
        assert_that(graph_pairs(f.GetOutput(1)) == ref_pairs, f"2^{exponent}: the same contiguities")
        same_points = all(tiles.GetPoint(i) == tuple(c * s for c in ref_tiles.GetPoint(i))
                          for i in range(ref_tiles.GetNumberOfPoints()))
        assert_that(tiles.GetNumberOfPoints() == ref_tiles.GetNumberOfPoints() and same_points,
                    f"2^{exponent}: tile vertices are the unit set's times s")

    # Areas that underflow, 0 at 2^-900 and subnormal at 2^-520 (the shapes exact), are warned of
    # with their counts, for either engine; at 2^-400 and 2^500, where they do not, nothing is
    # said (a trial got 0 areas without a word). The counts are taken here from the areas.
    smallest_normal = 2.2250738585072014e-308
    for exponent in (-900, -520, -400, 500):
        s = math.ldexp(1.0, exponent)
        for algorithm in ("GreenSibson", "BrasselReif"):
            f = vtkDirichletTessellation()
            warnings = messages_of(f, vtkCommand.WarningEvent)
            f.SetInputData(make_points([(x * s, y * s) for x, y in unit]))
            f.SetWindowBounds(0, s, 0, s)
            getattr(f, f"SetAlgorithmTo{algorithm}")()
            f.Update()
            areas = f.GetOutput(0).GetCellData().GetArray("Area")
            values = [areas.GetValue(c) for c in range(areas.GetNumberOfTuples())]
            zero = sum(a == 0.0 for a in values)
            subnormal = sum(0.0 < a < smallest_normal for a in values)
            said = [w for w in warnings if "tile(s) have " in w]
            expected = " and ".join(([f"{zero} tile(s) have Area 0"] if zero else [])
                                    + ([f"{subnormal} an Area below 2.2e-308" if zero else
                                        f"{subnormal} tile(s) have an Area below 2.2e-308"] if subnormal else []))
            expected += ", with fewer digits: their areas" if subnormal else ": their areas"
            assert_that(len(values) == 200 and (zero + subnormal > 0) == (exponent in (-900, -520))
                        and len(said) == len(warnings) == (1 if zero + subnormal else 0)
                        and all(expected in w for w in said), f"2^{exponent} {algorithm}: {expected}, {warnings}")

    # Scaling up, a point far outside the window stays outside (rejected), not infinite; scaling
    # down, a point whose coordinates would lose bits is an error naming it.
    s = math.ldexp(1.0, -700)
    f = tessellate(make_points([(0.3 * s, 0.4 * s), (0.6 * s, 0.7 * s), (1e300, 0.0)]), bounds=(0, s, 0, s))
    rejected = f.GetOutput(0).GetFieldData().GetArray("RejectedPointIds")
    assert_that(f.GetOutput(0).GetNumberOfCells() == 2 and rejected.GetNumberOfTuples() == 1
                and rejected.GetValue(0) == 2, "a far point beside a tiny window is rejected")
    s = math.ldexp(1.0, 500)
    tiny = math.ldexp(1.0, -560)
    f = vtkDirichletTessellation()
    messages = messages_of(f)
    f.SetInputData(make_points([(0.3 * s, 0.4 * s), (tiny, tiny), (tiny * (1 + 2 ** -20), tiny)]))
    f.SetWindowBounds(0, s, 0, s)
    f.Update()
    # (point 1, a power of two, stays exact as a subnormal; point 2 would lose bits)
    assert_that(len(messages) == 1 and "point 2" in messages[0] and "cannot be scaled" in messages[0],
                f"coordinates that would lose bits: {messages}")

    close = [(0.5, 0.5)] + [(rng.random() * 1e-200, rng.random() * 1e-200) for _ in range(50)]
    f = vtkDirichletTessellation()
    messages = messages_of(f)
    f.SetInputData(make_points(close))
    f.SetWindowBounds(0, 1, 0, 1)
    f.Update()
    # (they lie within 1e-200 of the corner: the first with a coordinate that small is named)
    assert_that(len(messages) == 1 and "has a coordinate below 2^-200 (some 6e-61) of the window's reach" in messages[0]
                and f.GetOutput(0).GetNumberOfCells() == 0, f"points 1e-200 apart: {messages}")


def test_a_negative_padding_is_an_error():
    # (it was clamped to 0, silently)
    for cls in (vtkDirichletTessellation, vtkDelaunayTriangulation):
        f = cls()
        messages = messages_of(f)
        f.SetPadding(-1.0)
        f.SetInputData(make_points([(0, 0), (1, 0), (0, 1)]))
        f.Update()
        assert_that(f.GetPadding() == -1.0 and len(messages) == 1 and "Padding -1 is not a finite number >= 0" in messages[0],
                    f"{cls.__name__}: {messages}")


def test_half_neighbours_need_their_vertex_strictly_inside_the_window():
    # Four points co-circular about (5, 10): their tiles meet there. On the window's top side that
    # point makes no pair; with the window raised it is inside, and the pairs across it are
    # half-neighbours. Both engines agree (the documented rule; a user review asked).
    coords = [(2.0, 6.0), (8.0, 6.0), (5.0, 5.0), (1.0, 7.0)]
    for algorithm in ("GreenSibson", "BrasselReif"):
        on_side = graph_pairs(tessellate(make_points(coords), (0, 10, 0, 10), algorithm).GetOutput(1))
        inside = graph_pairs(tessellate(make_points(coords), (0, 10, 0, 10.5), algorithm).GetOutput(1))
        assert_that(on_side == {0: {(0, 2), (0, 3), (1, 2)}, 1: set()}, f"{algorithm}, vertex on the side: {on_side}")
        assert_that(inside[1] == {(0, 1), (2, 3)}, f"{algorithm}, vertex inside: {inside}")


def test_delaunay_at_any_scale():
    # The faces of points scaled by a power of two are the unit set's, from 2^-900 to 2^660
    # (some 1e198: its automatic window's area overflows, which a triangulation does not need).
    import random

    rng = random.Random(5)
    unit = [(rng.random(), rng.random()) for _ in range(300)]

    def faces(coords, padding=None):
        t = vtkDelaunayTriangulation()
        messages = messages_of(t)
        if padding is not None:
            t.SetPadding(padding)
        t.SetInputData(make_points(coords))
        t.Update()
        out = t.GetOutput()
        ids = out.GetPolys().GetConnectivityArray()
        offsets = out.GetPolys().GetOffsetsArray()
        cells = {tuple(ids.GetValue(k) for k in range(offsets.GetValue(c), offsets.GetValue(c + 1)))
                 for c in range(out.GetNumberOfCells())}
        return cells, messages

    reference, messages = faces(unit)
    assert_that(not messages and len(reference) > 500, f"unit faces: {len(reference)} {messages}")
    for exponent in (-900, -400, 400, 660):
        s = math.ldexp(1.0, exponent)
        got, messages = faces([(x * s, y * s) for x, y in unit])
        assert_that(not messages and got == reference, f"2^{exponent}: {len(got)} faces, {messages}")
    # Points across the doubles (within +-1.95 2^1022, some +-8.8e307) and a Padding of 1e300: the
    # padded window would pass the largest double, and was refused ("its area overflows"); the
    # window of a triangulation is now cut to the room there is. Scaling by 2^1022 is exact, so
    # the faces are those of the points at scale 1.
    centred = [((x - 0.5) * 3.9, (y - 0.5) * 3.9) for x, y in unit]
    expected, _ = faces(centred)
    s = math.ldexp(1.0, 1022)
    got, messages = faces([(x * s, y * s) for x, y in centred])
    assert_that(not messages and got == expected and len(got) > 500, f"across the doubles: {len(got)} faces, {messages}")
    got, messages = faces(unit, padding=1e300)
    assert_that(not messages and got == reference, f"Padding 1e300: {len(got)} faces, {messages}")
    # A point at the largest double leaves no room for a window: said so, not "set a smaller Padding".
    got, messages = faces([(0.0, 0.0), (1.0, 0.0), (sys.float_info.max, 1.0)])
    assert_that(len(messages) == 1 and "the points reach the largest double" in messages[0], f"{messages}")


def test_a_coordinate_too_small_for_exact_window_decisions_is_named():
    # Points 0.053 apart in the window (0, 0.1)^2, one at x = 1e-200: exactly, tile 1's bisector
    # meets the left side just above the corner, so both tiles have 4 sides (BrasselReif: 4). The
    # GreenSibson tiles' window decisions underflow there: tile 1 had 3 sides, with no message.
    # Now an error names the point; the same point at x = 0 is fine.
    tiny = [(1e-200, 0.037500000000000006), (0.037500000000000006, 5e-201)]
    f = vtkDirichletTessellation()
    messages = messages_of(f)
    f.SetInputData(make_points(tiny))
    f.SetWindowBounds(0, 0.1, 0, 0.1)
    f.Update()
    assert_that(len(messages) == 1 and "point 0 (1e-200, 0.037500000000000006) has a coordinate below 2^-200 (some 6e-61) of the window's reach"
                in messages[0] and f.GetOutput(0).GetNumberOfCells() == 0, f"{messages}")
    sweep = tessellate(make_points(tiny), (0, 0.1, 0, 0.1), "BrasselReif").GetOutput(0)
    counts = sweep.GetCellData().GetArray("NeighborCount")
    assert_that([counts.GetValue(c) for c in range(sweep.GetNumberOfCells())] == [4, 4], "the sweep's tiles")
    # At 1e-50 (within the exact range) both engines give the exact 4 sides each, no message; so
    # at 1e-74 in a window of 1e-35 (the limit is relative to the window's reach).
    for algorithm, coordinate, size in (("GreenSibson", 1e-50, 0.1), ("BrasselReif", 1e-50, 0.1),
                                        ("GreenSibson", 1e-74, 1e-35), ("BrasselReif", 1e-74, 1e-35)):
        f = vtkDirichletTessellation()
        messages = messages_of(f)
        inner = 0.375 * size
        f.SetInputData(make_points([(coordinate, inner), (inner, coordinate / 2)]))
        f.SetWindowBounds(0, size, 0, size)
        getattr(f, f"SetAlgorithmTo{algorithm}")()
        f.Update()
        counts = f.GetOutput(0).GetCellData().GetArray("NeighborCount")
        assert_that(not messages and [counts.GetValue(c) for c in range(f.GetOutput(0).GetNumberOfCells())] == [4, 4],
                    f"{algorithm} at {coordinate} in {size}: {messages}")



def point_layer_blocks(coords, values):
    """The points as vtkGDALVectorReader gives a point layer: a block per point, one vertex each,
    its attribute (here "elev") as the vertex's cell data."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkMultiBlockDataSet, vtkPolyData

    blocks = vtkMultiBlockDataSet()
    for k, ((x, y), value) in enumerate(zip(coords, values)):
        points = vtkPoints()
        points.SetDataTypeToDouble()
        points.InsertNextPoint(x, y, 0.0)
        verts = vtkCellArray()
        verts.InsertNextCell(1, [0])
        elev = vtkDoubleArray()
        elev.SetName("elev")
        elev.InsertNextValue(value)
        leaf = vtkPolyData()
        leaf.SetPoints(points)
        leaf.SetVerts(verts)
        leaf.GetCellData().AddArray(elev)
        blocks.SetBlock(k, leaf)
    return blocks


def test_points_in_blocks_are_one_set_and_other_types_empty_the_outputs():
    """A point layer in blocks (vtkGDALVectorReader's, a block per point) is tessellated and
    triangulated as one set of points, its attributes carried (each block was tessellated alone:
    a square per point, no triangle); an input of another type after a good run is an error naming
    the type and leaves empty outputs (the pipeline's type check left the last results)."""
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkCommonDataModel import vtkImageData

    rng = np.random.default_rng(5)
    coords = [tuple(p) for p in rng.random((60, 2))]
    values = list(rng.random(60))
    for cls in (vtkDirichletTessellation, vtkDelaunayTriangulation):
        outputs = []
        for data in (make_points(coords, elev=values), point_layer_blocks(coords, values)):
            f = cls()
            f.SetInputData(data)
            f.Update()
            out = f.GetOutputDataObject(0)
            elev = out.GetCellData().GetArray("elev") or out.GetPointData().GetArray("elev")
            cells = []
            for c in range(out.GetNumberOfCells()):
                ids = out.GetCell(c).GetPointIds()
                cells.append(tuple(out.GetPoint(ids.GetId(k))[:2] for k in range(ids.GetNumberOfIds())))
            outputs.append((out.GetClassName(), cells, [elev.GetValue(k) for k in range(elev.GetNumberOfTuples())]))
        assert_that(outputs[0] == outputs[1] and len(outputs[0][1]) >= 60,
                    f"{cls.__name__}: {len(outputs[0][1])} cells from one point set, {len(outputs[1][1])} from blocks")
        image = vtkImageData()
        image.SetDimensions(3, 3, 1)
        errors = messages_of(f, vtkCommand.ErrorEvent)
        f.SetInputData(image)
        f.Update()
        out = f.GetOutputDataObject(0)
        assert_that(out.GetNumberOfCells() == 0 and out.GetNumberOfPoints() == 0,
                    f"{cls.__name__}: {out.GetNumberOfCells()} cells left after an image")
        assert_that(any("the input is a vtkImageData, not points" in e for e in errors), f"{errors}")


def test_short_attribute_arrays_are_errors_naming_them():
    """A point-data array with fewer values than points was read past its end: a segfault with a
    string array, garbage in the tiles with a double one. It is an error naming the array, for a
    point set and for a block."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkStringArray
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    from tessera import vtkRidgeGrouping

    rng = np.random.default_rng(8)
    coords = [tuple(p) for p in rng.random((1000, 2))]
    for array_type in (vtkStringArray, vtkDoubleArray):
        for cls in (vtkDirichletTessellation, vtkDelaunayTriangulation, vtkRidgeGrouping):
            for in_block in (False, True):
                data = make_points(coords)
                short = array_type()
                short.SetName("name")
                short.InsertNextValue("only one" if array_type is vtkStringArray else 1.0)
                data.GetPointData().AddArray(short)
                if in_block:
                    blocks = vtkMultiBlockDataSet()
                    blocks.SetBlock(0, data)
                    data = blocks
                f = cls()
                errors = messages_of(f, vtkCommand.ErrorEvent)
                f.SetInputData(data)
                f.Update()
                where = "block 0 (composite index 1) of the points" if in_block else "the input"
                expected = f"{where}: its point-data array 'name' has 1 value(s) for 1000 points"
                assert_that(len(errors) == 1 and expected in errors[0],
                            f"{cls.__name__}, {array_type.__name__}, block {in_block}: {errors}")
                assert_that(f.GetOutputDataObject(0).GetNumberOfCells() == 0, "outputs emptied")


def test_long_attribute_arrays_are_named_and_their_extra_values_unused():
    """A point-data array with more values than points (often a mismatch) was taken silently. It is
    named in a warning, and the tiles carry each point's own value: the extra ones are not used."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray

    from tessera import vtkRidgeGrouping

    rng = np.random.default_rng(9)
    coords = [tuple(p) for p in rng.random((50, 2))]
    for cls in (vtkDirichletTessellation, vtkDelaunayTriangulation, vtkRidgeGrouping):
        data = make_points(coords)
        rain = vtkDoubleArray()
        rain.SetName("rain")
        for k in range(53):
            rain.InsertNextValue(10.0 * k)
        data.GetPointData().AddArray(rain)
        wind = vtkDoubleArray()
        wind.SetName("wind")
        wind.SetNumberOfComponents(2)
        wind.SetNumberOfTuples(51)
        data.GetPointData().AddArray(wind)
        f = cls()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        errors = messages_of(f, vtkCommand.ErrorEvent)
        f.SetInputData(data)
        f.Update()
        expected = ("the input: its point-data array 'rain' has 53 values for 50 points, so its values 50 to 52 "
                    "(counted from 0) belong to none and are not used")
        tuples = ("the input: its point-data array 'wind' has 51 tuples for 50 points, so its tuples 50 to 50 "
                  "(counted from 0) belong to none")
        assert_that(not errors and sum(expected in w for w in warnings) == 1 and sum(tuples in w for w in warnings) == 1,
                    f"{cls.__name__}: {errors} {warnings}")
        if cls is vtkDirichletTessellation:
            tiles = f.GetOutputDataObject(0).GetCellData()
            ids, values = tiles.GetArray("PointId"), tiles.GetArray("rain")
            assert_that(ids.GetNumberOfTuples() == 50
                        and all(values.GetValue(c) == 10.0 * ids.GetValue(c) for c in range(50)),
                        "each tile carries its own point's value")


def test_each_process_piece_gets_the_whole_tessellation_once():
    """ParaView under MPI asks each process for a piece of the output: each tessellated its own
    piece's points (overlapping tiles whose areas summed to twice the window's). Now the first piece
    is the tessellation of all the points and the others are empty, whatever the source splits."""
    from vtkmodules.vtkFiltersGeneral import vtkImageDataToPointSet
    from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

    source = vtkRTAnalyticSource()
    source.SetWholeExtent(0, 9, 0, 9, 0, 0)
    points = vtkImageDataToPointSet()
    points.SetInputConnection(source.GetOutputPort())
    for cls in (vtkDirichletTessellation, vtkDelaunayTriangulation):
        f = cls()
        f.SetInputConnection(points.GetOutputPort())
        f.SetWindowBounds(-0.5, 9.5, -0.5, 9.5)
        counts, areas = [], []
        for piece in range(3):
            f.UpdatePiece(piece, 3, 0)
            out = f.GetOutputDataObject(0)
            counts.append(out.GetNumberOfCells())
            area = out.GetCellData().GetArray("Area")
            areas.append(sum(area.GetValue(k) for k in range(area.GetNumberOfTuples())) if area else 0.0)
        whole = 100 if cls is vtkDirichletTessellation else 81  # tiles, or degenerate square faces
        assert_that(counts == [whole, 0, 0], f"{cls.__name__}: cells per piece {counts}")
        if cls is vtkDirichletTessellation:
            assert_close(areas[0], 100.0, 1e-12, "the first piece's tiles fill the window")
    # The projection too (one projection fitted to all the points, on the first piece).
    from tessera import vtkGeographicProjection

    projection = vtkGeographicProjection()
    projection.SetInputConnection(points.GetOutputPort())
    counts = []
    for piece in range(3):
        projection.UpdatePiece(piece, 3, 0)
        counts.append(projection.GetOutputDataObject(0).GetNumberOfPoints())
    assert_that(counts == [100, 0, 0], f"projection: points per piece {counts}")


def test_vertex_cell_data_of_one_point_set_is_carried_and_other_cell_data_is_reported():
    """A point set whose cells are one vertex per point with cell-data attributes (a GDAL point
    layer after ParaView's Merge Blocks) had them dropped silently; now they follow the points, as
    for blocks. Cell data of other cells cannot, and a warning names it."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray

    rng = np.random.default_rng(9)
    coords = [tuple(p) for p in rng.random((40, 2))]
    values = list(rng.random(40))
    for cls in (vtkDirichletTessellation, vtkDelaunayTriangulation):
        data = make_points(coords)
        verts = vtkCellArray()
        for k in reversed(range(40)):  # vertex cells in another order than the points
            verts.InsertNextCell(1, [k])
        data.SetVerts(verts)
        rain = vtkDoubleArray()
        rain.SetName("rain")
        for k in reversed(range(40)):
            rain.InsertNextValue(values[k])
        data.GetCellData().AddArray(rain)
        f = cls()
        f.SetInputData(data)
        f.Update()
        out = f.GetOutputDataObject(0)
        if cls is vtkDirichletTessellation:
            ids = out.GetCellData().GetArray("PointId")
            got = out.GetCellData().GetArray("rain")
            assert_that(got is not None and all(got.GetValue(c) == values[ids.GetValue(c)] for c in range(out.GetNumberOfCells())),
                        "each tile carries its point's vertex value")
        else:
            got = out.GetPointData().GetArray("rain")
            assert_that(got is not None and [got.GetValue(k) for k in range(40)] == values, "points carry their vertex value")
        # The point data keeps its roles and unnamed arrays (a join rebuilt it without them), and a
        # cell ghost array is not made the points' (its bits mean other things there).
        from vtkmodules.vtkCommonCore import vtkUnsignedCharArray

        scalars = vtkDoubleArray()
        scalars.SetName("s")
        unnamed = vtkDoubleArray()
        ghosts = vtkUnsignedCharArray()
        ghosts.SetName("vtkGhostType")
        for k in range(40):
            scalars.InsertNextValue(k)
            unnamed.InsertNextValue(-k)
            ghosts.InsertNextValue(2 if k == 5 else 0)
        data.GetPointData().SetScalars(scalars)
        data.GetPointData().AddArray(unnamed)
        data.GetCellData().AddArray(ghosts)
        d = vtkDelaunayTriangulation()
        d.SetInputData(data)
        d.Update()
        pd = d.GetOutput().GetPointData()
        assert_that(pd.GetScalars() is not None and pd.GetScalars().GetName() == "s", "active scalars kept")
        assert_that(any(pd.GetAbstractArray(k).GetName() is None for k in range(pd.GetNumberOfArrays())),
                    "the unnamed array kept")
        assert_that(pd.GetArray("rain") is not None and pd.GetArray("vtkGhostType") is None,
                    "vertex attributes carried, cell ghosts not")
        # No points: nothing to carry, and no warning that the cells are not vertices.
        empty = make_points([])
        empty.GetCellData().AddArray(vtkDoubleArray())
        empty.GetCellData().GetArray(0).SetName("rain")
        e = cls()
        said = messages_of(e, vtkCommand.WarningEvent)
        e.SetInputData(empty)
        e.Update()
        assert_that(not [w for w in said if "not carried" in w], f"{said}")
        lines = make_points(coords)
        cells = vtkCellArray()
        cells.InsertNextCell(2, [0, 1])
        lines.SetLines(cells)
        lines.GetCellData().AddArray(double_array("tag", [1.0]))
        warnings = warnings_of_update(cls(), lines)
        assert_that(any("cell-data arrays ('tag') are not carried" in w for w in warnings), f"{warnings}")
        # A vertex attribute hidden by a point-data array of its name: the point data's is carried,
        # and a warning names the other (it was left out without a word), alone and in a block.
        hiding = make_points(coords)
        vertices = vtkCellArray()
        for k in range(40):
            vertices.InsertNextCell(1, [k])
        hiding.SetVerts(vertices)
        hiding.GetPointData().AddArray(double_array("rain", [1.0] * 40))
        hiding.GetCellData().AddArray(double_array("rain", [2.0] * 40))
        from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

        block = vtkMultiBlockDataSet()
        block.SetBlock(0, hiding)
        for data_set, who in ((hiding, "the input's"), (block, "block 0 (composite index 1)'s")):
            f = cls()
            warnings = warnings_of_update(f, data_set)
            assert_that(any(f"{who} cell-data array(s) 'rain' are not carried: its point data has arrays of the "
                            "same names, which are carried instead" in w for w in warnings),
                        f"{warnings}")
            carried = f.GetOutput().GetPointData().GetArray("rain") if cls is vtkDelaunayTriangulation \
                else f.GetOutput().GetCellData().GetArray("rain")
            assert_that(carried is not None and carried.GetValue(0) == 1.0, "the point data's 'rain' carried")


def test_blocks_with_different_arrays_are_joined_with_a_warning_either_way_round():
    """An array in some blocks only was dropped silently in one order and an error in the other
    (the grouping needs no array at all); either way the points are now used and a warning names
    the array and the blocks as a script numbers them. The point ghost flags are not copied to the
    tiles (as cell ghosts they hid a tile)."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkUnsignedCharArray
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    rng = np.random.default_rng(10)
    first = [tuple(p) for p in rng.random((20, 2))]
    second = [tuple(p) for p in rng.random((20, 2))]
    for rain_in in (0, 1):
        blocks = vtkMultiBlockDataSet()
        for k, coords in enumerate((first, second)):
            arrays = {"rain": list(rng.random(20))} if k == rain_in else {}
            blocks.SetBlock(k, make_points(coords, **arrays))
        f = vtkDirichletTessellation()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        errors = messages_of(f, vtkCommand.ErrorEvent)
        f.SetInputData(blocks)
        f.Update()
        lacking = 1 - rain_in
        expected = (f"the array 'rain' is not carried: block {lacking} (composite index {lacking + 1}) of the points "
                    f"has no array 'rain', which block {rain_in} (composite index {rain_in + 1}) has")
        assert_that(not errors and len(warnings) == 1 and expected in warnings[0], f"{errors} {warnings}")
        assert_that(f.GetOutputDataObject(0).GetNumberOfCells() == 40, "every point tessellated")
    data = make_points(first)
    ghosts = vtkUnsignedCharArray()
    ghosts.SetName("vtkGhostType")
    for k in range(20):
        ghosts.InsertNextValue(1 if k == 3 else 0)
    data.GetPointData().AddArray(ghosts)
    f = vtkDirichletTessellation()
    f.SetInputData(data)
    f.Update()
    assert_that(f.GetOutputDataObject(0).GetCellData().GetArray("vtkGhostType") is None, "no cell ghosts")


def test_blocks_of_multipoint_features_name_the_attributes_they_cannot_carry():
    """Blocks whose cell is one poly-vertex of several points (a MultiPoint layer from
    vtkGDALVectorReader, its attributes cell data) cannot give their points the attributes: a
    warning names them, as for one such set alone (they were dropped without a word)."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkIntArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkMultiBlockDataSet

    def multipoint(coords, station):
        data = make_points(coords)
        cell = vtkCellArray()
        cell.InsertNextCell(len(coords))
        for k in range(len(coords)):
            cell.InsertCellPoint(k)
        data.SetVerts(cell)
        value = vtkIntArray()
        value.SetName("station")
        value.InsertNextValue(station)
        data.GetCellData().AddArray(value)
        return data

    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, multipoint([(0, 0), (1, 0)], 7))
    blocks.SetBlock(1, multipoint([(0, 1), (1, 1)], 8))
    f = vtkDirichletTessellation()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(blocks)
    f.Update()
    expected = ("the array 'station' is not carried: block 0 (composite index 1) of the points holds 'station' "
                "as cell data of cells that are not one vertex per point (polygons, lines, a multipoint feature)")
    assert_that(len(warnings) == 1 and expected in warnings[0], f"{warnings}")
    assert_that(f.GetOutputDataObject(0).GetNumberOfCells() == 4
                and f.GetOutputDataObject(0).GetCellData().GetArray("station") is None, "four tiles, no 'station'")
    # An unnamed point-data array of a block cannot be joined by name either: said, not dropped unsaid.
    unnamed = double_array(None, [0.0, 1.0])
    blocks.GetBlock(1).GetPointData().AddArray(unnamed)
    warnings = warnings_of_update(vtkDirichletTessellation(), blocks)
    assert_that(any("block 1 (composite index 2) of the points has 1 unnamed point-data array(s), not carried" in w
                    for w in warnings), f"{warnings}")


def test_tiles_narrower_than_an_ulp_are_named():
    """Three points an ulp apart in x: the middle tile is a strip an ulp wide, whose corners round
    onto each other (a polygon of one or two points, no area). It was given silently; both engines
    now name its point. Points a little further apart keep a true tile and no warning."""
    from vtkmodules.vtkCommonCore import vtkCommand

    x = 4.0
    for gap in (1, 2 ** 20):
        # (gap 1: the doubles next to 4 on either side, half an ulp of 4 below it and one above)
        left = math.nextafter(x, 0.0) if gap == 1 else x - gap * math.ulp(x)
        right = math.nextafter(x, 9.0) if gap == 1 else x + gap * math.ulp(x)
        for engine in ("SetAlgorithmToGreenSibson", "SetAlgorithmToBrasselReif"):
            f = vtkDirichletTessellation()
            getattr(f, engine)()
            warnings = messages_of(f, vtkCommand.WarningEvent)
            f.SetInputData(make_points([(left, 5.0), (x, 5.0), (right, 5.0)]))
            f.SetWindowBounds(0.0, 6.0, 4.5, 5.5)
            f.Update()
            named = [w for w in warnings if "narrower than the coordinates can resolve" in w]
            if gap == 1:
                assert_that(len(named) == 1 and "no area in doubles: points 1\n" in named[0], f"{engine}: {warnings}")
            else:
                assert_that(not named, f"{engine}, points {gap} ulps apart: {warnings}")
    # Four points an ulp apart on a vertical line, and one off it: the tile of point 2 is a strip an
    # ulp wide whose corners are distinct but collinear (Area 0). It was not named.
    u = math.ulp(0.5)
    f = vtkDirichletTessellation()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(make_points([(0.5, 0.5 + k * u) for k in range(4)] + [(0.1, 0.1)]))
    f.SetWindowBounds(0.0, 1.0, 0.0, 1.0)
    f.Update()
    tiles = f.GetOutput(0)
    ids, areas = tiles.GetCellData().GetArray("PointId"), tiles.GetCellData().GetArray("Area")
    flat = sorted(ids.GetValue(c) for c in range(tiles.GetNumberOfCells()) if areas.GetValue(c) == 0.0)
    named = [w for w in warnings if "narrower than the coordinates can resolve" in w]
    assert_that(2 in flat and len(named) == 1 and f"no area in doubles: points {', '.join(map(str, flat))}\n" in named[0],
                f"tiles of area 0: {flat}; {warnings}")
    # True tiles of points some 1e-165 apart have areas below the doubles (0), and are no slivers:
    # they are not named.
    s = 1e-165
    f = vtkDirichletTessellation()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(make_points([(0.2 * s, 0.3 * s), (0.7 * s, 0.6 * s), (0.4 * s, 0.9 * s), (0.8 * s, 0.1 * s)]))
    f.Update()
    assert_that(f.GetOutput(0).GetNumberOfCells() == 4
                and not [w for w in warnings if "narrower than the coordinates can resolve" in w], f"{warnings}")


def test_delaunay_takes_a_window_far_larger_than_its_points():
    """The header says a window of any finite scale is taken: WindowBounds of +-1e308, or a Padding
    of 1e308, were refused naming a valid point (it could not be scaled with such a window), and
    so were points down to 3e-300 in a window of 1e200. The triangulation is the one without a
    window, and a point outside the window is still rejected."""
    from vtkmodules.vtkCommonCore import vtkCommand

    coords = [(3e-300, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0), (0.4, 0.7)]
    plain = vtkDelaunayTriangulation()
    plain.SetInputData(make_points(coords))
    plain.Update()
    expected = sorted(tuple(plain.GetOutput().GetCell(c).GetPointIds().GetId(k) for k in range(3))
                      for c in range(plain.GetOutput().GetNumberOfCells()))
    assert_that(len(expected) == 4, f"{expected}")
    for setting in ("bounds", "huge bounds", "padding", "rejecting"):
        f = vtkDelaunayTriangulation()
        errors = messages_of(f, vtkCommand.ErrorEvent)
        data = coords + ([(-1.0, 0.5)] if setting == "rejecting" else [])
        f.SetInputData(make_points(data))
        if setting == "bounds":
            f.SetWindowBounds(-1e200, 1e200, -1e200, 1e200)
        elif setting == "huge bounds":
            f.SetWindowBounds(-sys.float_info.max, sys.float_info.max, -1e308, 1e308)
        elif setting == "padding":
            f.SetPadding(1e308)
        else:
            f.SetWindowBounds(-0.5, 1e300, -1e300, 1e300)
        f.Update()
        out = f.GetOutput()
        faces = sorted(tuple(out.GetCell(c).GetPointIds().GetId(k) for k in range(3)) for c in range(out.GetNumberOfCells()))
        assert_that(not errors and faces == expected, f"{setting}: {faces} against {expected}: {errors}")
        rejected = out.GetFieldData().GetArray("RejectedPointIds")
        listed = [rejected.GetValue(k) for k in range(rejected.GetNumberOfTuples())] if rejected else []
        assert_that(listed == ([5] if setting == "rejecting" else []), f"{setting}: rejected {listed}")


def test_an_algorithm_that_is_no_choice_is_named():
    # SetAlgorithm(7) ran BrasselReif without a word (VTK's clamping setter).
    f = vtkDirichletTessellation()
    assert_that((f.GetAlgorithmMinValue(), f.GetAlgorithmMaxValue()) == (0, 1), "the range VTK's setter announced")
    errors = messages_of(f)
    f.SetAlgorithm(7)
    f.SetInputData(make_points([(0.2, 0.3), (0.7, 0.6), (0.4, 0.9)]))
    f.Update()
    assert_that(len(errors) == 1 and "Algorithm 7 is not one of 0 (GreenSibson), 1 (BrasselReif)" in errors[0]
                and f.GetOutput(0).GetNumberOfCells() == 0, f"{errors}")
    # and PrintSelf says what it holds (it said GreenSibson)
    assert_that("Algorithm: (not one of them) (7)" in str(f), "PrintSelf")
    f.SetAlgorithmToBrasselReif()
    assert_that("Algorithm: BrasselReif (1)" in str(f), "PrintSelf")



def test_a_window_side_that_cannot_be_scaled_is_named_as_the_user_knows_it():
    # A window of 1e300 whose side passes 1e-10 from the origin cannot be scaled into the exact
    # range. The error named "window constraint 2" with no constraint set, "window constraint 3" for
    # the user's constraint 0, another constraint in the Delaunay filter than in the tiles one, and
    # the normalised c; now each filter names the side as the user set it.
    def errors_of(filter_class, setup, coords):
        f = filter_class()
        errors = messages_of(f)
        setup(f)
        f.SetInputData(make_points(coords))
        f.Update()
        return errors

    def four_constraints(f):
        f.AddWindowConstraint(1.0, 0.0, -1e300)   # 0: x < 1e300
        f.AddWindowConstraint(-1.0, 0.0, -1e300)  # 1: x > -1e300
        f.AddWindowConstraint(0.0, 4.0, -4e-10)   # 2: y < 1e-10, which cannot be scaled
        f.AddWindowConstraint(0.0, -1.0, 0.0)     # 3: y > 0

    one = [(0.5e300, 0.5e-10)]
    cases = [("automatic", lambda f: None, [(-1e300, 0.0), (-1e300, 1e-10)],
              "the automatic window's side y > ymin (the points' bounding box, padded) cannot be scaled by 2^-996"),
             ("bounds", lambda f: f.SetWindowBounds(-1e300, 1e300, 0.0, 1e-10), one,
              "the WindowBounds side y < ymax cannot be scaled by 2^-996"),
             ("constraints", four_constraints, one, "window constraint 2 cannot be scaled by 2^-996")]
    for name, setup, coords, expected in cases:
        for filter_class in (vtkDirichletTessellation, vtkDelaunayTriangulation):
            errors = errors_of(filter_class, setup, coords)
            assert_that(len(errors) == 1 and expected in errors[0] and "span more orders of magnitude" in errors[0],
                        f"{name}, {filter_class.__name__}: {errors}")


def test_brassel_reif_names_a_side_that_lies_at_no_double_as_it_was_given():
    """The sweep's border is the rectangle of the window's corners: a side at no double (3x - s < 0,
    at s / 3) is an error naming the constraint and the side as the user gave it (at 1e100 it named
    the window scaled into range, x = 0.38), and Green-Sibson takes the same window."""
    for s in (1.0, 1e100, 1e-100):
        f = vtkDirichletTessellation()
        errors = messages_of(f)
        f.SetInputData(make_points([(0.1 * s, 0.2 * s), (0.2 * s, 0.7 * s)]))
        f.SetWindowBounds(0, s, 0, s)
        f.AddWindowConstraint(3, 0, -s)
        f.SetAlgorithmToBrasselReif()
        f.Update()
        side = f"x = {s / 3!r}" if s != 1.0 else "x = 0.3333333333333333"
        assert_that(len(errors) == 1 and "window constraint 0 puts one at " + side in errors[0], f"{s}: {errors}")
        f.SetAlgorithmToGreenSibson()
        f.Update()
        assert_that(len(errors) == 1 and f.GetOutput(0).GetNumberOfCells() == 2, f"{s}: Green-Sibson: {errors}")


def stopped_then_rerun(f, stop_after, size=lambda data: data.GetNumberOfCells()):
    """Runs f with a progress observer that sets AbortExecute at the first progress above
    stop_after (below 1); returns (the progress values of that run, the errors, the size of output
    0: its cells), then resets AbortExecute, runs f again after Modified() and returns its size."""
    seen, errors = [], messages_of(f)

    def on_progress(caller, _):
        seen.append(caller.GetProgress())
        if stop_after < caller.GetProgress() < 1.0 and len(seen) < 1000:
            caller.SetAbortExecute(1)

    tag = f.AddObserver(vtkCommand.ProgressEvent, on_progress)
    f.Update()
    stopped = (list(seen), list(errors), size(f.GetOutputDataObject(0)))
    f.RemoveObserver(tag)
    f.SetAbortExecute(0)  # (this VTK keeps the flag set: the caller clears it)
    f.Modified()
    f.Update()
    return stopped, size(f.GetOutputDataObject(0))


def test_a_progress_observer_can_stop_a_run():
    """Progress goes up by stages (the Brassel-Reif sweep every 64 points: its bad case, points on
    one circle, took a minute at 10^4 without a word between 0.1 and 0.8), and AbortExecute, set
    by a progress observer, stops each filter at its next stage: empty outputs, no error (it ran
    to the end whatever was asked); cleared, the next run gives the whole output."""
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    circle = make_points([(0.5 + 0.4 * math.cos(2 * math.pi * k / 1500), 0.5 + 0.4 * math.sin(2 * math.pi * k / 1500))
                          for k in range(1500)])
    sweep = vtkDirichletTessellation()
    sweep.SetInputData(circle)
    sweep.SetWindowBounds(0, 1, 0, 1)
    sweep.SetAlgorithmToBrasselReif()
    (seen, errors, cells), rerun = stopped_then_rerun(sweep, 0.2)
    assert_that(not errors and cells == 0 and rerun == 1500, f"sweep: {errors}, {cells}, {rerun}")
    assert_that(seen[-1] == 1.0 and 0.2 < seen[-2] < 0.3 and len(seen) < 15, f"stopped at once: {seen}")
    full = []
    sweep.AddObserver(vtkCommand.ProgressEvent, lambda caller, _: full.append(caller.GetProgress()))
    sweep.Modified()
    sweep.Update()
    inner = [p for p in full if 0.1 < p < 0.75]
    assert_that(len(inner) >= 20 and inner == sorted(inner), f"the sweep's progress: {len(inner)} steps")

    rng = random.Random(4)
    points = make_points([(rng.random(), rng.random()) for _ in range(5000)])
    window = polygon([[(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)]])

    def made(name):
        """The filter of that name on the points, new (the clip's tiles from a tessellation)."""
        f = {"tiles": vtkDirichletTessellation, "triangles": vtkDelaunayTriangulation, "clip": vtkWindowClip}[name]()
        if name == "clip":  # (progress every 4096 tiles)
            tiles = made("tiles")
            tiles.Update()
            f.SetInputData(tiles.GetOutput(0))
            f.SetWindowData(window)
        else:
            f.SetInputData(points)
        return f

    for name in ("tiles", "triangles", "clip"):
        never_stopped = made(name)
        never_stopped.Update()
        count = never_stopped.GetOutputDataObject(0).GetNumberOfCells()
        (seen, errors, cells), rerun = stopped_then_rerun(made(name), 0.05)
        assert_that(not errors and cells == 0 and count > 0 and rerun == count,
                    f"{name}: {errors}, {cells}, {rerun} of {count}")
    stopped = made("tiles")
    stopped_then_rerun(stopped, 0.05)
    assert_that(isinstance(stopped.GetOutputDataObject(1), vtkPolyData), "the graph's output kept its type")
    from tessera import vtkRidgeGrouping

    grouping = vtkRidgeGrouping()  # (progress before and after its core)
    grouping.SetInputData(make_points([(0.01 * k, 0.3 * math.sin(0.05 * k) + rng.gauss(0, 0.01)) for k in range(300)]))
    (seen, errors, points), rerun = stopped_then_rerun(grouping, 0.01, lambda data: data.GetNumberOfPoints())
    assert_that(not errors and points == 0 and rerun == 300, f"grouping: {errors}, {points}, {rerun}")
    from tessera import vtkGeographicProjection

    projection = vtkGeographicProjection()  # (progress between pieces: it took no stop at all)
    projection.SetInputData(make_points([(-105 + 0.01 * k, 39 + 0.01 * k) for k in range(100)]))
    (seen, errors, points), rerun = stopped_then_rerun(projection, 0.05, lambda data: data.GetNumberOfPoints())
    assert_that(not errors and points == 0 and rerun == 100, f"projection: {errors}, {points}, {rerun}")


def test_duplicates_made_by_float_storage_are_said_to_be_so():
    """Points stored as float at UTM-sized coordinates (5e6: a float's step is 0.5 there) become
    one when 0.1 apart: the warning says the float's step and how to keep them apart; stored as
    double they stay apart, and duplicates of doubles get no such note."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    coords = [(500000.0, 5000000.0), (500000.0, 5000000.1), (500100.0, 5000040.0), (500030.0, 5000090.0),
              (500030.0, 5000090.0)]
    step = float(np.spacing(np.float32(5000090.0)))  # the float step at the largest coordinate

    def points_as(kind):
        points = vtkPoints()
        getattr(points, "SetDataTypeTo" + kind)()
        for x, y in coords:
            points.InsertNextPoint(x, y, 0.0)
        data = vtkPolyData()
        data.SetPoints(points)
        return data

    for make in (vtkDirichletTessellation, vtkDelaunayTriangulation):
        for kind, copies, noted in (("Float", "1 -> 0, 4 -> 3", True), ("Double", "4 -> 3", False)):
            warnings = warnings_of_update(make(), points_as(kind))
            said = [w for w in warnings if "exact duplicate(s)" in w]
            assert_that(len(said) == 1, f"{make.__name__} {kind}: {warnings}")
            pairs = said[0].split("duplicates: ")[1]
            assert_that(all(f"point {k.split(' -> ')[0]} (of point {k.split(' -> ')[1]})" in pairs
                            for k in copies.split(", ")), f"{make.__name__} {kind}: pairs {pairs}")
            note = f"The points are stored as float, whose step at coordinates of 5000090 is {step:g}"
            assert_that((note in said[0]) == noted, f"{make.__name__} {kind}: {said[0]}")


if __name__ == "__main__":
    run([test_a_progress_observer_can_stop_a_run,
         test_duplicates_made_by_float_storage_are_said_to_be_so,
         test_tiles_are_nearest_point_regions,
         test_brassel_reif_names_a_side_that_lies_at_no_double_as_it_was_given,
         test_delaunay_faces_match_vtk_delaunay2d_and_count,
         test_square_lattice_has_square_tiles_and_diagonal_half_neighbours,
         test_unused_points_are_reported_with_ids,
         test_integer_points_beyond_what_a_double_holds_are_named,
         test_input_field_data_named_like_the_unused_point_ids_is_kept_under_another_name,
         test_degenerate_inputs_give_valid_output,
         test_both_engines_agree,
         test_brassel_reif_refuses_a_non_rectangular_window,
         test_nan_point_is_named,
         test_tiles_form_a_conforming_mesh,
         test_large_graph_is_sorted_with_kinds_following_pairs,
         test_32_bit_cell_arrays_survive_a_vtp_round_trip,
         test_graph_off_leaves_the_tiles_unchanged,
         test_automatic_window_keeps_every_point_and_bad_windows_are_named,
         test_window_constraint_errors_name_them_as_the_user_added_them,
         test_empty_window_bounds_warn_and_leave_the_automatic_window,
         test_input_arrays_named_like_the_filters_are_kept_under_another_name,
         test_delaunay_passes_point_data_with_the_input_points,
         test_tiles_at_any_scale_and_points_too_close_for_exact_tiles,
         test_a_negative_padding_is_an_error,
         test_half_neighbours_need_their_vertex_strictly_inside_the_window,
         test_delaunay_at_any_scale,
         test_a_coordinate_too_small_for_exact_window_decisions_is_named,
         test_points_in_blocks_are_one_set_and_other_types_empty_the_outputs,
         test_short_attribute_arrays_are_errors_naming_them,
         test_long_attribute_arrays_are_named_and_their_extra_values_unused,
         test_each_process_piece_gets_the_whole_tessellation_once,
         test_vertex_cell_data_of_one_point_set_is_carried_and_other_cell_data_is_reported,
         test_blocks_with_different_arrays_are_joined_with_a_warning_either_way_round,
         test_tiles_narrower_than_an_ulp_are_named,
         test_delaunay_takes_a_window_far_larger_than_its_points,
         test_blocks_of_multipoint_features_name_the_attributes_they_cannot_carry,
         test_an_algorithm_that_is_no_choice_is_named,
         test_a_window_side_that_cannot_be_scaled_is_named_as_the_user_knows_it])
