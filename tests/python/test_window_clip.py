"""vtkWindowClip from Python: its cells are what a renderer and VTK's mesh filters read as meant
(simple polygons inside the window, not overlapping, filling tile & window), checked with an exact
segment-intersection test, vtkTriangleFilter's triangles and point sampling; and the filter's own
array names."""

import math
import random

import numpy as np
from matplotlib.path import Path
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkIntArray
from vtkmodules.vtkFiltersCore import vtkTriangleFilter

from tessera import vtkDirichletTessellation, vtkGeographicProjection, vtkWindowClip
from tessera_testing import (assert_close, assert_that, cell_rings, cells, exact_area, make_points,
                             messages_of, projection_record, polygon, run, simplicity_defect)


def clip_by(tiles, window):
    """tiles clipped by the window data set: the output, the errors and the warnings."""
    f = vtkWindowClip()
    errors = messages_of(f)
    warnings = messages_of(f, "WarningEvent")
    f.SetInputData(tiles)
    f.SetWindowData(window)
    f.Update()
    return f.GetOutputDataObject(0), errors, warnings  # (a composite for tiles in blocks)


def clip(tiles, window_rings):
    output, errors, _ = clip_by(tiles, polygon(window_rings))
    assert_that(not errors, f"no error: {errors}")
    return output


def cell_values(data, name):
    array = data.GetCellData().GetArray(name)
    assert_that(array is not None, f"cell array {name}")
    return [array.GetValue(c) for c in range(data.GetNumberOfCells())]


def shoelace(ring):
    return 0.5 * math.fsum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1]))


# ---- windows ---------------------------------------------------------------------------------------

CONVEX_QUAD = [[(0.13, 0.08), (0.91, 0.17), (0.83, 0.93), (0.11, 0.77)]]


def star(centre, count, r_min, r_max, rng, clockwise=False):
    ring = []
    for k in range(count):
        angle = 2 * math.pi * (k + 0.1 + 0.8 * rng.random()) / count
        radius = r_min + (r_max - r_min) * rng.random()
        ring.append((centre[0] + radius * math.cos(angle), centre[1] + radius * math.sin(angle)))
    return ring[::-1] if clockwise else ring


def windows():
    rng = random.Random(5)
    return {"a convex quad": CONVEX_QUAD,
            "a star": [star((0.5, 0.5), 23, 0.12, 0.45, rng)],
            "a square with a star-shaped hole": [[(0.05, 0.05), (0.95, 0.05), (0.95, 0.95), (0.05, 0.95)],
                                                 star((0.52, 0.47), 17, 0.1, 0.3, rng, clockwise=True)]}


def window_area(rings):
    """Even-odd area: outer ring minus the rings inside it (the windows here nest one deep)."""
    areas = sorted((abs(shoelace(r)) for r in rings), reverse=True)
    return areas[0] - math.fsum(areas[1:])


def window_paths(rings):
    return [Path(np.array(r)) for r in rings]


def in_window(paths, points):
    """Even-odd membership of points."""
    inside = np.zeros(len(points), dtype=int)
    for path in paths:
        inside += path.contains_points(points)
    return inside % 2 == 1


def distances_to_boundary(rings, points):
    """For each point (an n x 2 array), its distance to the nearest edge of the rings."""
    best = np.full(len(points), np.inf)
    for ring in rings:
        for a, b in zip(ring, ring[1:] + ring[:1]):
            a, b = np.array(a), np.array(b)
            t = np.clip((points - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0)
            best = np.minimum(best, np.hypot(*(points - a - t[:, None] * (b - a)).T))
    return best


def random_tiling(seed, count):
    rng = np.random.default_rng(seed)
    tess = vtkDirichletTessellation()
    tess.SetInputData(make_points([tuple(p) for p in rng.random((count, 2))]))
    tess.SetWindowBounds(-0.01, 1.01, -0.02, 1.03)
    tess.Update()
    return tess.GetOutput(0)


def triangulated_area_by_tile(data):
    triangles = vtkTriangleFilter()
    triangles.SetInputData(data)
    triangles.Update()
    out = triangles.GetOutput()
    tile_ids = cell_values(out, "TileId")
    sums = {}
    for tile, ring in zip(tile_ids, cell_rings(out)):
        assert_that(len(ring) == 3, f"vtkTriangleFilter gives triangles, not {len(ring)} points")
        sums.setdefault(tile, []).append(exact_area(ring))
    return {tile: float(sum(areas)) for tile, areas in sums.items()}


def test_cells_are_simple_pieces_that_fill_tile_and_window():
    # Per tile, the cells' areas (PieceArea, and vtkTriangleFilter's triangles measured exactly)
    # add up to ClippedArea within 1e-12 of it, or of a hundredth of the tile for a sliver: its
    # ClippedArea is a sum of signed rings that cancel (a tile mostly in the hole), known to the
    # rounding of the tile's area, not of its own.
    for seed, count in [(1, 60), (2, 400), (3, 2000)]:
        tiles = random_tiling(seed, count)
        tile_areas = [float(exact_area(ring)) for ring in cell_rings(tiles)]
        for name, rings in windows().items():
            what = f"{name}, {count} tiles"
            out = clip(tiles, rings)
            pieces = cell_rings(out)
            tile_ids = cell_values(out, "TileId")
            clipped = cell_values(out, "ClippedArea")
            piece_areas = cell_values(out, "PieceArea")
            assert_that(out.GetCellData().GetArray("PieceArea").GetDataTypeAsString() == "double",
                        f"{what}: PieceArea is double")
            assert_that(out.GetCellData().GetArray("Hole") is None, f"{what}: no Hole array")
            defects = [(c, d) for c, d in enumerate(map(simplicity_defect, pieces)) if d]
            assert_that(not defects, f"{what}: {len(defects)} cells are not simple polygons: {defects[:3]}")
            paths = window_paths(rings)
            vertices = np.array([p for ring in pieces for p in ring], dtype=float).reshape(-1, 2)
            cell_of_vertex = [c for c, ring in enumerate(pieces) for _ in ring]
            away = ~in_window(paths, vertices) & (distances_to_boundary(rings, vertices) > 1e-12)
            outside = [(cell_of_vertex[k], tuple(vertices[k])) for k in np.flatnonzero(away)]
            assert_that(not outside, f"{what}: vertices outside the window: {outside[:3]}")
            per_tile = {}
            for tile, area, piece_area, ring in zip(tile_ids, clipped, piece_areas, pieces):
                per_tile.setdefault(tile, (area, []))[1].append(piece_area)
                assert_close(piece_area, float(exact_area(ring)), 1e-12 * area, f"{what}: PieceArea of a cell of tile {tile}")
                assert_that(per_tile[tile][0] == area, f"{what}: one ClippedArea per tile")
            triangulated = triangulated_area_by_tile(out)
            for tile, (area, piece_list) in per_tile.items():
                tolerance = 1e-12 * max(area, 1e-2 * tile_areas[tile])
                assert_close(math.fsum(piece_list), area, tolerance, f"{what}: PieceArea sum of tile {tile}")
                assert_close(triangulated[tile], math.fsum(piece_list), 1e-12 * area,
                             f"{what}: triangulated area of tile {tile}")
                assert_close(triangulated[tile], area, tolerance, f"{what}: triangulated area of tile {tile}")
            expected = window_area(rings)
            assert_close(math.fsum(a for a, _ in per_tile.values()), expected, 1e-12 * expected,
                         f"{what}: the clipped areas sum to the window's")
            assert_close(math.fsum(triangulated.values()), expected, 1e-12 * expected,
                         f"{what}: the triangles sum to the window's area")
            # No overlaps and no gaps: a point inside the window (not near its boundary or a tile
            # edge) lies in exactly one cell, a point outside in none.
            rng = np.random.default_rng(seed + 10)
            samples = rng.random((4000, 2))
            covering = np.zeros(len(samples), dtype=int)
            for ring in pieces:
                covering += Path(np.array(ring)).contains_points(samples)
            clear = distances_to_boundary(rings, samples) > 1e-9
            inside = in_window(paths, samples)
            surely_in, surely_out = clear & inside, clear & ~inside
            assert_that(np.all(covering[surely_out] == 0), f"{what}: a cell outside the window")
            assert_that(np.all(covering <= 1), f"{what}: {np.sum(covering > 1)} sample points in two cells")
            # (a point on a tile edge lies in no cell: a few at most)
            assert_that(np.sum(covering[surely_in] == 0) <= 2,
                        f"{what}: {np.sum(covering[surely_in] == 0)} points of the window in no cell")


def outline_polygons(outlines):
    """Output 1 as {TileId: [[outer ring, hole, ...], ...]} (rings without the repeated first
    point), after checking that each cell is a closed ring, simple, a polygon's rings consecutive
    with its outer ring (Hole 0, anticlockwise) first and its holes clockwise."""
    tile_ids, polygon_ids, holes = (cell_values(outlines, n) for n in ("TileId", "PolygonId", "Hole"))
    by_tile, polygons = {}, {}
    for c, ring in enumerate(cell_rings(outlines)):
        assert_that(len(ring) >= 4 and ring[0] == ring[-1], f"outline cell {c} is not a closed ring")
        ring = ring[:-1]
        assert_that((exact_area(ring) < 0) == (holes[c] == 1), f"outline cell {c}: Hole {holes[c]}")
        # (simplicity_defect takes anticlockwise rings: a hole is read the other way round)
        defect = simplicity_defect(ring[::-1] if holes[c] == 1 else ring)
        assert_that(defect is None, f"outline cell {c}: {defect}")
        if polygon_ids[c] not in polygons:
            assert_that(holes[c] == 0, f"outline cell {c}: polygon {polygon_ids[c]} begins with a hole")
            polygons[polygon_ids[c]] = [ring]
            by_tile.setdefault(tile_ids[c], []).append(polygons[polygon_ids[c]])
        else:
            assert_that(polygon_ids[c - 1] == polygon_ids[c], f"outline cell {c}: polygon {polygon_ids[c]}'s rings")
            polygons[polygon_ids[c]].append(ring)
    return by_tile


def test_outlines_are_each_tiles_part_of_the_window_as_polygons_with_holes():
    # Output 1 joins each tile's pieces back into polygons with holes: the rings' signed areas
    # add up to its ClippedArea, each sample point lies in a tile's polygons (even-odd) when it
    # lies in one of its pieces, and the rings carry the tile's cell data.
    rng = np.random.default_rng(12)
    samples = rng.random((3000, 2))
    tiles = random_tiling(2, 400)
    bay = [[(0.05, 0.05), (0.95, 0.05), (0.95, 0.95), (0.6, 0.95), (0.6, 0.3), (0.4, 0.3), (0.4, 0.95),
            (0.05, 0.95)], star((0.25, 0.5), 11, 0.03, 0.08, random.Random(3), clockwise=True)]
    for name, rings in list(windows().items()) + [("a bay with a lake", bay)]:
        f = vtkWindowClip()
        errors = messages_of(f)
        f.SetInputData(tiles)
        f.SetWindowData(polygon(rings))
        f.Update()
        pieces, outlines = f.GetOutputDataObject(0), f.GetOutputDataObject(1)
        assert_that(not errors and outlines.GetNumberOfLines() == outlines.GetNumberOfCells() > 0, f"{name}: {errors}")
        by_tile = outline_polygons(outlines)
        clipped = dict(zip(cell_values(pieces, "TileId"), cell_values(pieces, "ClippedArea")))
        assert_that(sorted(by_tile) == sorted(clipped), f"{name}: tiles with outlines and with pieces")
        for array in ("ClippedArea", "AreaFraction"):  # (the tile's, on each of its rings, as on its pieces)
            of_pieces = dict(zip(cell_values(pieces, "TileId"), cell_values(pieces, array)))
            assert_that(all(of_pieces[t] == v for t, v in zip(cell_values(outlines, "TileId"),
                                                               cell_values(outlines, array))),
                        f"{name}: the rings' {array}")
        for tile, polygons in by_tile.items():
            area = float(sum(exact_area(r) for p in polygons for r in p))
            assert_close(area, clipped[tile], 1e-12 * max(clipped[tile], 1e-4), f"{name}: tile {tile}'s outline area")
        in_pieces = {}
        for tile, ring in zip(cell_values(pieces, "TileId"), cell_rings(pieces)):
            in_pieces[tile] = in_pieces.get(tile, 0) + Path(np.array(ring)).contains_points(samples)
        wrong = 0
        for tile, polygons in by_tile.items():
            held = sum(sum(Path(np.array(r)).contains_points(samples).astype(int) for r in p) % 2 for p in polygons)
            wrong += int(np.sum(held != in_pieces[tile]))
        assert_that(wrong <= 2, f"{name}: {wrong} samples in a tile's pieces and its outline differ")  # (on edges)
        joined = [t for t, polygons in by_tile.items()
                  if len(polygons) < cell_values(pieces, "TileId").count(t) or any(len(p) > 1 for p in polygons)]
        assert_that(name == "a convex quad" or joined, f"{name}: no tile's pieces were joined")
        areas = dict(zip(cell_values(outlines, "TileId"), cell_values(outlines, "Area")))
        assert_that(all(areas[t] == tiles.GetCellData().GetArray("Area").GetValue(t) for t in areas),
                    f"{name}: the rings carry their tile's cell data")
    # A tile round a lake with an island in it (the tessellation's tiles are smaller than lakes):
    # one polygon with a hole, and the island a polygon of its own.
    big = polygon([[(-1.0, -1.0), (2.0, -1.0), (2.0, 2.0), (-1.0, 2.0)]])
    lake = [[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], star((0.5, 0.5), 9, 0.2, 0.3, random.Random(4)),
            [(0.45, 0.45), (0.55, 0.45), (0.55, 0.55), (0.45, 0.55)]]
    f = vtkWindowClip()
    f.SetInputData(big)
    f.SetWindowData(polygon(lake))
    f.Update()
    polygons = outline_polygons(f.GetOutputDataObject(1))[0]
    assert_that(sorted(len(p) for p in polygons) == [1, 2], f"the tile round the lake: {polygons}")
    area = float(sum(exact_area(r) for p in polygons for r in p))
    assert_close(area, cell_values(f.GetOutputDataObject(0), "ClippedArea")[0], 1e-13, "its outline's area")
    # Tiles in blocks give outlines in the same blocks; an error leaves them empty too.
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    blocks = vtkMultiBlockDataSet()
    for k, half in enumerate(([(0.0, 0.0), (0.5, 0.0), (0.5, 1.0), (0.0, 1.0)],
                              [(0.5, 0.0), (1.0, 0.0), (1.0, 1.0), (0.5, 1.0)])):
        blocks.SetBlock(k, polygon([half]))
    f = vtkWindowClip()
    f.SetInputData(blocks)
    f.SetWindowData(polygon(windows()["a square with a star-shaped hole"]))
    f.Update()
    outlines = f.GetOutputDataObject(1)
    counts = [outlines.GetBlock(k).GetNumberOfCells() for k in range(outlines.GetNumberOfBlocks())]
    assert_that(counts == [1, 1], f"the blocks' outline rings: {counts}")  # (the hole crosses x = 0.5: a notch in each)
    errors = messages_of(f)
    blocks.SetBlock(1, polygon([[(0.5, 0.0), (1.0, 0.0), (0.6, 0.2), (1.0, 1.0), (0.5, 1.0)]]))
    blocks.Modified()
    f.Update()
    assert_that(errors and f.GetOutputDataObject(1).GetNumberOfBlocks() == 0, f"after an error: {errors}")


def test_review_cases():
    # A square tile by a non-convex window: Sutherland-Hodgman left a spike to (3, 0), outside the
    # window, and vtkTriangleFilter then gave 0.333 for a clipped area of 0.958.
    out = clip(polygon([[(3, 0), (5, 0), (5, 2), (3, 2)]]), [[(0, 0), (4, 1), (3, 4), (0, 3)]])
    rings = cell_rings(out)
    assert_that(all(simplicity_defect(r) is None for r in rings), f"simple cells: {rings}")
    assert_that((3.0, 0.0) not in [p for r in rings for p in r], f"no vertex (3, 0): {rings}")
    assert_close(cell_values(out, "ClippedArea")[0], 23 / 24, 1e-15, "the clipped area")
    assert_close(triangulated_area_by_tile(out)[0], 23 / 24, 1e-15, "the triangulated area")
    # A band across a U-shaped window: two lobes, two cells (not one ring joined along y = 2).
    u_shape = [(0, 0), (3, 0), (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)]
    out = clip(polygon([[(-1, 2), (4, 2), (4, 2.5), (-1, 2.5)]]), [u_shape])
    rings = cell_rings(out)
    assert_that(len(rings) == 2 and all(simplicity_defect(r) is None for r in rings),
                f"two simple cells for the two lobes: {rings}")
    assert_that(sorted(cell_values(out, "PieceArea")) == [0.5, 0.5] and cell_values(out, "ClippedArea") == [1.0, 1.0]
                and cell_values(out, "TileId") == [0, 0] and cell_values(out, "AreaFraction") == [0.4, 0.4],
                "PieceArea 0.5 each, ClippedArea 1 and AreaFraction 1 / 2.5 on both")
    scalars = out.GetCellData().GetScalars()
    assert_that(scalars is not None and scalars.GetName() == "AreaFraction", "coloured by AreaFraction")


def test_input_arrays_named_like_the_filters_are_kept_under_another_name():
    # Tiles that already carry TileId, ClippedArea, AreaFraction and PieceArea (e.g. the output of
    # an earlier clip) and PieceArea_input: the input's arrays reach the output as NAME_input
    # (PieceArea as PieceArea_input_2), following their tile, named in one warning; the filter's
    # own arrays are its own.
    squares = [[(x, 0), (x + 1, 0), (x + 1, 1), (x, 1)] for x in range(4)]
    tiles = polygon(squares)
    inputs = {"TileId": vtkIntArray, "ClippedArea": vtkDoubleArray, "AreaFraction": vtkDoubleArray,
              "PieceArea": vtkDoubleArray, "PieceArea_input": vtkDoubleArray, "rain": vtkDoubleArray}
    for k, (name, kind) in enumerate(inputs.items()):
        array = kind()
        array.SetName(name)
        for c in range(len(squares)):
            array.InsertNextValue(100 * k + c)
        tiles.GetCellData().AddArray(array)
    f = vtkWindowClip()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    errors = messages_of(f)
    f.SetInputData(tiles)
    f.SetWindowData(polygon([[(0.5, 0), (3.5, 0), (3.5, 1), (0.5, 1)]]))  # cuts tiles 0 and 3, covered
    f.Update()
    out = f.GetOutput()
    assert_that(not errors and out.GetNumberOfCells() == 4, f"four cells: {errors}")
    tile_ids = cell_values(out, "TileId")
    assert_that(tile_ids == [0, 1, 2, 3] and out.GetCellData().GetArray("TileId").GetDataTypeAsString() == "idtype",
                f"the filter's own TileId: {tile_ids}")
    assert_that(cell_values(out, "ClippedArea") == [0.5, 1.0, 1.0, 0.5]
                and cell_values(out, "AreaFraction") == [0.5, 1.0, 1.0, 0.5]
                and cell_values(out, "PieceArea") == [0.5, 1.0, 1.0, 0.5], "the filter's own areas")
    renamed = {"TileId": "TileId_input", "ClippedArea": "ClippedArea_input",
               "AreaFraction": "AreaFraction_input", "PieceArea": "PieceArea_input_2",
               "PieceArea_input": "PieceArea_input", "rain": "rain"}
    for k, name in enumerate(inputs):
        assert_that(cell_values(out, renamed[name]) == [100 * k + c for c in tile_ids],
                    f"input {name} follows its tile as {renamed[name]}")
    named = [m for m in warnings if "filter's own" in m]
    assert_that(len(named) == 1 and all(f"'{name}' is passed to the clipped tiles as '{renamed[name]}'"
                                        in named[0] for name in list(inputs)[:4]),
                f"one warning naming each renamed array: {warnings}")
    # The outlines (output 1) rename TileId alike, said once above, and PolygonId and Hole, named in
    # a warning of their own.
    rings = f.GetOutputDataObject(1)
    for k, name in enumerate(list(inputs)[:3]):  # (TileId, ClippedArea, AreaFraction: named as on output 0)
        assert_that(cell_values(rings, renamed[name]) == [100 * k + t for t in cell_values(rings, "TileId")],
                    f"{renamed[name]} on the outlines")
    for k, name in enumerate(("PolygonId", "Hole")):
        array = vtkIntArray()
        array.SetName(name)
        for c in range(len(squares)):
            array.InsertNextValue(7 + k)
        tiles.GetCellData().AddArray(array)
    tiles.Modified()
    warnings.clear()
    f.Update()
    rings = f.GetOutputDataObject(1)
    said = [m for m in warnings if "the clipped tiles' outlines" in m]
    assert_that(len(said) == 1 and "'PolygonId' is passed to the clipped tiles' outlines as 'PolygonId_input'" in said[0]
                and "'Hole' is passed" in said[0] and "'TileId'" not in said[0]
                and set(cell_values(rings, "Hole_input")) == {8} and cell_values(rings, "PolygonId") == [0, 1, 2, 3],
                f"PolygonId and Hole renamed on the outlines: {warnings}")
    plain = vtkWindowClip()
    plain_warnings = messages_of(plain, vtkCommand.WarningEvent)
    plain.SetInputData(polygon(squares))
    plain.SetWindowData(polygon([[(0.5, 0), (3.5, 0), (3.5, 1), (0.5, 1)]]))
    plain.Update()
    assert_that(plain_warnings == [], f"no warning without a clash: {plain_warnings}")


def line_segments(rings, rng, shared_ids):
    """vtkPolyData with one two-point line cell per ring edge, shuffled, some reversed; with
    shared_ids the rings' points are stored once (as vtkCutter gives a contour), else every cell
    has points of its own (line features read from a file)."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    points = vtkPoints()
    points.SetDataTypeToDouble()
    edges = []
    for ring in rings:
        ids = [points.InsertNextPoint(x, y, 0.0) for x, y in ring]
        edges += [(ring[k], ring[(k + 1) % len(ring)], ids[k], ids[(k + 1) % len(ring)])
                  for k in range(len(ring))]
    rng.shuffle(edges)
    lines = vtkCellArray()
    for a, b, ia, ib in edges:
        if rng.random() < 0.5:
            a, b, ia, ib = b, a, ib, ia
        if not shared_ids:
            ia, ib = points.InsertNextPoint(a[0], a[1], 0.0), points.InsertNextPoint(b[0], b[1], 0.0)
        lines.InsertNextCell(2)
        lines.InsertCellPoint(ia)
        lines.InsertCellPoint(ib)
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetLines(lines)
    return data


def test_a_window_of_loose_line_segments_is_joined_into_its_rings():
    # The window with a hole and the star of windows(), given as contour-like line segments, clip
    # exactly as the same rings given as polygons; a dangling segment is reported, not joined.
    rng = random.Random(21)
    tiles = random_tiling(8, 300)
    for name, rings in windows().items():
        expected = cell_values(clip(tiles, rings), "ClippedArea")
        for shared_ids in (True, False):
            output, errors, warnings = clip_by(tiles, line_segments(rings, rng, shared_ids))
            assert_that(not errors and not warnings, f"{name}: joined without a message: {errors} {warnings}")
            got = cell_values(output, "ClippedArea")
            assert_that(got == expected, f"{name}: the same clipped areas as the polygons ({len(got)} cells)")
    # Rings meeting at a point (a contour through a saddle: four segments there, six for three
    # triangles) are joined touching, as the polygons are given.
    meeting = {"squares at a corner": [[(0.1, 0.1), (0.5, 0.1), (0.5, 0.5), (0.1, 0.5)],
                                       [(0.5, 0.5), (0.9, 0.5), (0.9, 0.9), (0.5, 0.9)]],
               "a hole touching its outline": [[(0.1, 0.9), (0.5, 0.9), (0.9, 0.9), (0.9, 0.1), (0.1, 0.1)],
                                               [(0.5, 0.9), (0.7, 0.5), (0.3, 0.5)]],
               "three triangles at a point": [[(0.5, 0.5), (0.9, 0.5), (0.7, 0.8)], [(0.5, 0.5), (0.3, 0.8), (0.1, 0.5)],
                                              [(0.5, 0.5), (0.3, 0.1), (0.7, 0.1)]]}
    for name, rings in meeting.items():
        expected = cell_values(clip(tiles, rings), "ClippedArea")
        for shared_ids in (True, False):
            output, errors, warnings = clip_by(tiles, line_segments(rings, rng, shared_ids))
            assert_that(not errors and not warnings, f"{name}: joined without a message: {errors} {warnings}")
            got = cell_values(output, "ClippedArea")
            assert_that(sorted(got) == sorted(expected) and len(got) > 0,
                        f"{name}: the same clipped areas as the polygons ({len(got)} cells)")
    square = [(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)]
    window = line_segments([square], rng, True)
    tail = window.GetPoints().InsertNextPoint(1.0, 1.0, 0.0)
    window.GetLines().InsertNextCell(2)
    window.GetLines().InsertCellPoint(2)  # the corner (0.9, 0.9): three segments meet there
    window.GetLines().InsertCellPoint(tail)
    output, errors, warnings = clip_by(tiles, window)
    assert_that(not errors and cell_values(output, "ClippedArea") == cell_values(clip(tiles, [square]), "ClippedArea"),
                f"the square clips without its dangling segment: {errors}")
    assert_that(len(warnings) == 1 and "1 cell(s)" in warnings[0] and "the first is cell 4" in warnings[0],
                f"the dangling segment's cell named: {warnings}")
    # Segments of no length between two ids of one point, as vtkContourFilter gives them where a
    # contour passes through a grid point: on a ring they add nothing and are not named (8 such
    # cells of a plain contour were "not lines that join into closed rings"); one off every ring
    # is named.
    for where, at, named in (("on the ring", (0.9, 0.9), False), ("off every ring", (0.5, 0.5), True)):
        window = line_segments([square], rng, True)
        copies = [window.GetPoints().InsertNextPoint(at[0], at[1], 0.0) for _ in range(2)]
        window.GetLines().InsertNextCell(2, copies)
        output, errors, warnings = clip_by(tiles, window)
        assert_that(not errors and cell_values(output, "ClippedArea") == cell_values(clip(tiles, [square]), "ClippedArea"),
                    f"a zero-length segment {where}: {errors}")
        assert_that(warnings == [] if not named else
                    len(warnings) == 1 and "1 cell(s)" in warnings[0] and "the first is cell 4" in warnings[0],
                    f"a zero-length segment {where}: {warnings}")
    # Lines that close no ring: nothing to clip by, their cells named.
    from vtkmodules.vtkCommonDataModel import vtkCellArray

    chain = line_segments([square], rng, True)
    lines = vtkCellArray()
    for a, b in ((0, 1), (1, 2), (2, 3)):  # the square's points 0..3, stored once: three of its sides
        lines.InsertNextCell(2, [a, b])
    chain.SetLines(lines)
    _, errors, _ = clip_by(tiles, chain)
    assert_that(errors and "no polygon" in errors[0] and "3 cell(s) of the input" in errors[0]
                and "the first is cell 0" in errors[0], f"an open chain: {errors}")


def test_an_island_that_fills_a_hole_exactly_cancels_it():
    # Rings given twice cancel by the even-odd rule: an outline with a hole, and an island that
    # fills the hole exactly (its path from another start, the other way round), clip as the
    # outline alone, with a warning naming the two. An outline given twice would take its region
    # away: still refused as a ring given twice.
    tiles = random_tiling(8, 200)
    outline = [(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)]
    hole = [(0.3, 0.3), (0.3, 0.7), (0.7, 0.7), (0.7, 0.3)]
    island = list(reversed(hole))[1:] + list(reversed(hole))[:1]
    expected = cell_values(clip(tiles, [outline]), "ClippedArea")
    output, errors, warnings = clip_by(tiles, polygon([outline, hole, island]))
    assert_that(not errors and cell_values(output, "ClippedArea") == expected, f"the outline's clip: {errors}")
    assert_that(len(warnings) == 1 and "1 hole(s) of the window (input 1) are filled exactly by a ring of their own" in warnings[0]
                and "cell 1 and cell 2" in warnings[0], f"the pair named: {warnings}")
    _, errors, _ = clip_by(tiles, polygon([outline, list(reversed(outline))]))
    assert_that(errors and "run along each other all the way round" in errors[0], f"an outline twice: {errors}")


def test_a_window_whose_rings_cancel_out_is_an_error():
    # A rectangle given with its two halves (a basin with all its sub-basins): under the even-odd
    # rule every point lies in two rings, so the window has no area. It gave an empty output, no
    # error, CoveredFraction 0 / 0 written as 0, and a warning blaming the tile; it is an error as
    # the areal average's catchment is. Half of it cancelled still clips (the other half).
    whole = [(0, 0), (2, 0), (2, 1), (0, 1)]
    left, right = [(0, 0), (1, 0), (1, 1), (0, 1)], [(1, 0), (2, 0), (2, 1), (1, 1)]
    for tile in ([(0, 0), (2, 0), (2, 1), (0, 1)], [(0.2, 0.2), (0.8, 0.2), (0.8, 0.8), (0.2, 0.8)]):
        output, errors, warnings = clip_by(polygon([tile]), polygon([whole, left, right]))
        assert_that(output.GetNumberOfCells() == 0 and len(errors) == 1
                    and "the window (input 1) has no area: its 3 rings cancel out" in errors[0] and not warnings,
                    f"{tile}: {errors} {warnings}")
    output, errors, _ = clip_by(polygon([whole]), polygon([whole, left]))
    assert_that(not errors, f"half cancelled: {errors}")
    assert_close(field_value(output, "WindowArea"), 1.0, 1e-15, "half cancelled: its area")
    assert_close(math.fsum(cell_values(output, "ClippedArea")), 1.0, 1e-15, "half cancelled: the right half clipped")


def test_tiles_and_window_must_share_their_projection():
    """Gauges and catchment projected apart, each with its automatic projection, lie in two
    different planes: clipping one by the other is an error naming both projections. With one
    projection for both it clips, and the output keeps the record (so an inverse finds it). A
    record on one input only is an error where the other lies in degrees and it in metres, else a
    warning."""
    gauges = make_points([(-105.0, 39.0), (-104.0, 40.0), (-103.0, 38.5), (-106.0, 40.5)])
    catchment = polygon([[(-106.0, 38.0), (-103.0, 38.0), (-103.0, 41.0), (-106.0, 41.0)]])

    def projected(data, automatic):
        f = vtkGeographicProjection()
        f.SetInputData(data)
        if not automatic:
            f.SetProjectionToAlbersEqualArea()
            f.ParametersFromDataOff()
            f.SetCentralLongitude(-104.5)
            f.SetStandardParallels(38.0, 41.0)
        f.Update()
        return f.GetOutput()

    def tiles_of(points):
        t = vtkDirichletTessellation()
        t.SetInputData(points)
        t.Update()
        return t.GetOutput()

    output, errors, warnings = clip_by(tiles_of(projected(gauges, True)), projected(catchment, True))
    assert_that(len(errors) == 1 and "projected differently" in errors[0] and errors[0].count("lon0=") == 2
                and output.GetNumberOfCells() == 0, f"two automatic projections: {errors}")
    same = projected(gauges, False)
    output, errors, warnings = clip_by(tiles_of(same), projected(catchment, False))
    assert_that(not errors and not warnings and output.GetNumberOfCells() == 4, f"one projection: {errors} {warnings}")
    assert_that(projection_record(output) == projection_record(same), f"the output's record: {projection_record(output)}")
    # The gauges' automatic projection handed to the catchment's filter as its ProjectionRecord:
    # the same projection (the record's own bits), so the clip goes through; the gauges projected
    # with their own record land on the same bits as by their automatic projection.
    automatic = projected(gauges, True)
    record = projection_record(automatic)
    f = vtkGeographicProjection()
    f.SetInputData(catchment)
    f.SetProjectionRecord(record)
    f.Update()
    output, errors, warnings = clip_by(tiles_of(automatic), f.GetOutput())
    assert_that(not errors and not warnings and output.GetNumberOfCells() == 4
                and projection_record(f.GetOutput()) == record, f"one record for both: {errors} {warnings}")
    again = vtkGeographicProjection()  # the gauges again, with the record: the very same points
    again.SetInputData(gauges)
    again.SetProjectionRecord(record)
    again.Update()
    moved = [again.GetOutput().GetPoint(i) for i in range(4)]
    fitted = [automatic.GetPoint(i) for i in range(4)]
    assert_that(moved == fitted, f"the record's projection: {moved} vs {fitted}")
    # A record that cannot be read is an error naming it, with an empty output; so it is for an
    # input without points, whose output carries a good record.
    errors = messages_of(f, vtkCommand.ErrorEvent)
    f.SetProjectionRecord("projection=Sinusoidal lon0=1")
    f.Update()
    assert_that(len(errors) == 1 and "ProjectionRecord 'projection=Sinusoidal lon0=1'" in errors[0]
                and f.GetOutput().GetNumberOfPoints() == 0, f"a bad record: {errors}")
    f.SetInputData(make_points([]))
    f.Update()
    assert_that(len(errors) == 2 and "ProjectionRecord 'projection=Sinusoidal lon0=1'" in errors[1],
                f"a bad record, no points: {errors}")
    f.SetProjectionRecord(record)
    f.Update()
    assert_that(len(errors) == 2 and projection_record(f.GetOutput()) == record, f"no points: {errors}")
    # The inverse of points that carry another record than the one set warns, naming both.
    back = vtkGeographicProjection()
    said = messages_of(back, vtkCommand.WarningEvent)
    back.SetInputData(automatic)
    back.InverseOn()
    back.SetProjectionRecord(projection_record(same))
    back.Update()
    assert_that(len(said) == 1 and projection_record(same) in said[0] and record in said[0], f"{said}")
    back.SetProjectionRecord(record)
    back.Update()
    assert_that(len(said) == 1, f"the input's own record: {said}")
    # Tiles of lon/lat gauges and a projected window, either way round: degrees against metres,
    # an error naming both extents (the tiles came out whole, covering 2.5e-10 of the window).
    output, errors, warnings = clip_by(tiles_of(gauges), projected(catchment, False))
    assert_that(len(errors) == 1 and "the window (input 1) is projected" in errors[0]
                and "the tiles (input 0) carry no record and look like longitude and latitude" in errors[0]
                and "x -106.3 to -102.7" in errors[0] and output.GetNumberOfCells() == 0,
                f"lon/lat tiles, a projected window: {errors} {warnings}")
    output, errors, warnings = clip_by(tiles_of(same), catchment)
    assert_that(len(errors) == 1 and "the tiles (input 0) are projected" in errors[0]
                and "the window (input 1) carries no record" in errors[0], f"projected tiles: {errors}")
    # Without a record but in metres (another tool's projection, say): one plane is taken, warned.
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    unrecorded = vtkPolyData()
    unrecorded.DeepCopy(tiles_of(same))
    unrecorded.GetFieldData().RemoveArray("TesseraProjection")
    output, errors, warnings = clip_by(unrecorded, projected(catchment, False))
    assert_that(not errors and len(warnings) == 1 and "the window (input 1) carries" in warnings[0]
                and "the tiles (input 0) none" in warnings[0] and output.GetNumberOfCells() == 4,
                f"one record, both in metres: {errors} {warnings}")
    # Empty tiles (a tessellation upstream that failed) against a projected window: said to have
    # no points, not to carry no record (which pointed at the projection).
    output, errors, warnings = clip_by(vtkPolyData(), projected(catchment, False))
    assert_that(not errors and len(warnings) == 1 and "the tiles (input 0) have no points" in warnings[0]
                and output.GetNumberOfCells() == 0, f"empty tiles: {errors} {warnings}")
    # (nor when the empty tiles carry the record and the window none; an empty window is an error
    # alone, not also a warning about the tiles)
    recorded = vtkPolyData()
    recorded.GetFieldData().ShallowCopy(tiles_of(same).GetFieldData())
    output, errors, warnings = clip_by(recorded, catchment)
    assert_that(not errors and len(warnings) == 1 and "the tiles (input 0) have no points" in warnings[0],
                f"empty tiles with a record: {errors} {warnings}")
    output, errors, warnings = clip_by(vtkPolyData(), vtkPolyData())
    assert_that(len(errors) == 1 and not warnings, f"empty tiles and window: {errors} {warnings}")
    # A window of blocks projected apart (each with its own automatic projection) is refused.
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, projected(catchment, True))
    blocks.SetBlock(1, projected(polygon([[(-110.0, 30.0), (-100.0, 30.0), (-100.0, 35.0)]]), True))
    output, errors, warnings = clip_by(tiles_of(same), blocks)
    assert_that(len(errors) == 1 and "input 1 (the window) mixes blocks projected differently" in errors[0],
                f"a window of differently projected blocks: {errors}")
    # Tiles in blocks under a record of the whole, one block with another record of its own: that
    # block is named (the whole's record hid the blocks').
    from vtkmodules.vtkCommonCore import vtkStringArray

    tiles = vtkMultiBlockDataSet()
    tiles.SetBlock(0, tiles_of(same))
    tiles.SetBlock(1, tiles_of(automatic))
    whole = vtkStringArray()
    whole.SetName("TesseraProjection")
    whole.InsertNextValue(projection_record(same))
    tiles.GetFieldData().AddArray(whole)
    output, errors, _ = clip_by(tiles, projected(catchment, False))
    assert_that(len(errors) == 1 and ("): block 1 (composite index 2) of input 0: the tiles (input 0) "
                                      "and the window (input 1) were projected differently") in errors[0]
                and output.GetNumberOfBlocks() == 0, f"a block of another record: {errors}")


def test_the_tiles_point_data_is_named_as_not_passed():
    # (it was dropped without a word; the tiles' cell data is passed)
    tiles = vtkDirichletTessellation()
    tiles.SetInputData(make_points([(0.2, 0.3), (0.7, 0.6)]))
    tiles.SetWindowBounds(0, 1, 0, 1)
    tiles.Update()
    data = tiles.GetOutput(0)
    for name in ("elev", "slope"):
        array = vtkDoubleArray()
        array.SetName(name)
        for i in range(data.GetNumberOfPoints()):
            array.InsertNextValue(1.0)
        data.GetPointData().AddArray(array)
    output, errors, warnings = clip_by(data, polygon([[(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)]]))
    assert_that(not errors and output.GetNumberOfCells() == 2 and output.GetCellData().GetArray("PointId"),
                f"clipped with the cell data: {errors}")
    assert_that(len(warnings) == 1 and "point data of input 0 ('elev', 'slope') is not passed" in warnings[0],
                f"the dropped arrays named: {warnings}")



def test_inputs_of_another_type_are_named_and_leave_empty_outputs():
    """An image or a table in place of the points of the projection, after a good run: an error
    naming its type, and an empty output (the pipeline's own type check stopped before
    RequestData and left the last result in place). Tiles in blocks are still clipped block by
    block (the clip's tiles port takes composites itself, for the composite pipeline)."""
    from vtkmodules.vtkCommonDataModel import vtkImageData, vtkMultiBlockDataSet, vtkTable

    image = vtkImageData()
    image.SetDimensions(3, 3, 1)
    projection = vtkGeographicProjection()
    errors = messages_of(projection)
    projection.SetInputData(make_points([(-105, 39), (-104, 40)]))
    projection.Update()
    assert_that(projection.GetOutputDataObject(0).GetNumberOfPoints() == 2 and not errors, f"{errors}")
    for wrong in (image, vtkTable()):
        projection.SetInputData(wrong)
        projection.Update()
        out = projection.GetOutputDataObject(0)
        assert_that(out.GetNumberOfPoints() == 0, f"{wrong.GetClassName()}: {out.GetNumberOfPoints()} points left")
        assert_that(f"the input is a {wrong.GetClassName()}, not a point set" in errors[-1], f"{errors}")
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, polygon([[(0.2, 0.2), (0.6, 0.2), (0.6, 0.6)]]))
    blocks.SetBlock(1, polygon([[(0.5, 0.5), (1.5, 0.5), (1.5, 1.5), (0.5, 1.5)]]))
    clip = vtkWindowClip()
    clip_errors = messages_of(clip)
    clip.SetInputData(blocks)
    clip.SetWindowData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    clip.Update()
    out = clip.GetOutputDataObject(0)
    areas = [out.GetBlock(k).GetCellData().GetArray("ClippedArea").GetValue(0) for k in range(out.GetNumberOfBlocks())]
    assert_that(not clip_errors and out.IsA("vtkMultiBlockDataSet") and np.allclose(areas, [0.08, 0.25], rtol=1e-12),
                f"blocks clipped one by one: {out.GetClassName()}, {areas}, {clip_errors}")
    # A table as the tiles, and no window at all, were stopped by the pipeline before the filter
    # ran: a log line, no ErrorEvent for a script to observe, and the last result left in place.
    # Now each is the filter's error, and the outputs are empty.
    window = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    for tiles, connected, expected in ((vtkTable(), True, "the tiles (input 0) are a vtkTable, not a point set"),
                                       (polygon([[(0.2, 0.2), (0.6, 0.2), (0.6, 0.6)]]), False,
                                        "no window is connected to input 1")):
        clip = vtkWindowClip()
        clip_errors = messages_of(clip)
        clip.SetInputData(polygon([[(0.2, 0.2), (0.6, 0.2), (0.6, 0.6)]]))
        clip.SetWindowData(window)
        clip.Update()
        assert_that(clip.GetOutputDataObject(0).GetNumberOfCells() == 1 and not clip_errors, f"{clip_errors}")
        clip.SetInputData(tiles)
        if not connected:
            clip.RemoveAllInputConnections(1)
        clip.Update()
        assert_that(clip.GetOutputDataObject(0).GetNumberOfCells() == 0 and len(clip_errors) == 1
                    and expected in clip_errors[0], f"{expected}: {clip_errors}")


def test_review_of_windows_of_other_types_global_ids_and_flat_tiles():
    """A review's findings. (1) A window block that is not poly data (an unstructured grid of a
    hole) was skipped without a word: its area counted as window. It is named in a warning, and a
    window input of that type says only poly data is read. (2) The tiles' global ids were dropped:
    they are an ordinary array now. (3) A flat (collinear) tile half in the window was in no list:
    it is in EmptyTileIds, as a flat tile wholly inside is."""
    from vtkmodules.vtkCommonDataModel import VTK_POLYGON, vtkMultiBlockDataSet, vtkUnstructuredGrid

    square = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    hole = vtkUnstructuredGrid()
    hole.SetPoints(polygon([[(0.25, 0.25), (0.75, 0.25), (0.75, 0.75), (0.25, 0.75)]]).GetPoints())
    hole.InsertNextCell(VTK_POLYGON, 4, [0, 1, 2, 3])
    window = vtkMultiBlockDataSet()
    window.SetBlock(0, square)
    window.SetBlock(1, hole)
    tiles = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    ids = vtkIntArray()
    ids.SetName("gids")
    ids.InsertNextValue(41)
    tiles.GetCellData().SetGlobalIds(ids)
    out, errors, warnings = clip_by(tiles, window)
    assert_that(not errors and any("block 1 (composite index 2) (vtkUnstructuredGrid)" in w and "not read" in w
                                   for w in warnings), f"{errors} {warnings}")
    assert_that(cell_values(out, "gids") == [41] and out.GetCellData().GetGlobalIds() is None,
                f"the global ids as an ordinary array: {cell_values(out, 'gids')}")
    _, errors, _ = clip_by(tiles, hole)
    assert_that(len(errors) == 1 and "the window (input 1) is a vtkUnstructuredGrid: only vtkPolyData (or a "
                "composite data set of it) is read as a window" in errors[0], f"{errors}")
    # An image window beside projected tiles is named by its type, not told to be projected (a
    # trial's case: the projection records were compared first).
    from vtkmodules.vtkCommonDataModel import vtkImageData
    projected = vtkGeographicProjection()
    projected.SetInputData(polygon([[(-105, 39), (-104, 39), (-104, 40), (-105, 40)]]))
    projected.Update()
    image = vtkImageData()
    image.SetDimensions(3, 3, 1)
    _, errors, _ = clip_by(projected.GetOutput(), image)
    assert_that(len(errors) == 1 and errors[0].strip().endswith(
        "the window (input 1) is a vtkImageData: only vtkPolyData (or a composite data set of it) is read as a window; "
        "extract its surface first (ParaView's Extract Surface, vtkGeometryFilter)"), f"{errors}")
    flat = polygon([[(3, 0.5), (5, 0.5), (7, 0.5)], [(0.2, 0.5), (0.4, 0.5), (0.6, 0.5)], [(3, 3), (4, 3), (5, 3)]])
    out, errors, warnings = clip_by(flat, polygon([[(0, 0), (4, 0), (4, 1), (0, 1)]]))
    empty = out.GetFieldData().GetArray("EmptyTileIds")
    assert_that(not errors and [empty.GetValue(k) for k in range(empty.GetNumberOfTuples())] == [0, 1],
                f"flat tiles in the window, half or whole, listed; one outside not: {warnings}")
    # (5) An error about a ring names the cell it came from (the core numbers rings, not cells).
    from vtkmodules.vtkCommonDataModel import vtkCellArray

    window = polygon([[(0, 0), (2, 0), (0, 2), (2, 2)]])  # a bow tie, after two vertex cells
    cells = vtkCellArray()
    for k in (0, 1):
        cells.InsertNextCell(1, [k])
    window.SetVerts(cells)
    _, errors, _ = clip_by(polygon([[(0, 0), (1, 0), (1, 1)]]), window)
    assert_that(len(errors) == 1 and "ring 0 is self-intersecting" in errors[0]
                and "(ring 0 is cell 2 of the window (input 1); ring 0 segment 1 runs from (2, 0) to (0, 2); "
                    "ring 0 segment 3 runs from (2, 2) to (0, 0))" in errors[0], f"{errors}")
    # The segments' ends are the input's coordinates, not the scaled ones the clip works in.
    _, errors, _ = clip_by(polygon([[(0, 0), (1e-200, 0), (1e-200, 1e-200)]]),
                           polygon([[(0, 0), (2e-200, 0), (0, 2e-200), (2e-200, 2e-200)]]))
    assert_that(len(errors) == 1 and "ring 0 segment 1 runs from (2e-200, 0) to (0, 2e-200); "
                "ring 0 segment 3 runs from (2e-200, 2e-200) to (0, 0))" in errors[0], f"{errors}")
    # (4) Tiny coordinates: the clip's products fell below the doubles (a fraction of 0.945 for
    # 17/18 at 1e-161, no piece at 1e-163). The window is scaled up by a power of two now.
    tile, window = [(0, 0), (3, 0), (3, 3), (0, 3)], [(1, 0), (3, 0), (3, 3), (0, 3), (0, 1)]
    for s in (1e-158, 1e-161, 1e-163, 1e-250):
        out = clip(polygon([[(s * x, s * y) for x, y in tile]]), [[(s * x, s * y) for x, y in window]])
        fraction = cell_values(out, "AreaFraction")
        points = [out.GetPoint(k)[:2] for k in range(out.GetNumberOfPoints())]
        assert_that(len(fraction) == 1 and abs(fraction[0] - 17 / 18) < 1e-15
                    and all(0 <= x <= 3 * s and 0 <= y <= 3 * s for x, y in points),
                    f"scale {s}: fraction {fraction}, pieces' points at the tiles' scale {points[:3]}")


def left_of(ring, x_max):
    """The convex ring cut to x <= x_max (Sutherland-Hodgman, one edge)."""
    cut = []
    for a, b in zip(ring, ring[1:] + ring[:1]):
        if a[0] <= x_max:
            cut.append(a)
        if (a[0] - x_max) * (b[0] - x_max) < 0:
            t = (x_max - a[0]) / (b[0] - a[0])
            cut.append((x_max, a[1] + t * (b[1] - a[1])))
    return cut


def field_value(data, name):
    array = data.GetFieldData().GetArray(name)
    assert_that(array is not None and array.GetNumberOfTuples() == 1, f"field data {name}")
    return array.GetValue(0)


def test_the_field_data_says_how_much_of_the_window_the_tiles_cover():
    # Tiles made in a window smaller than the clip's (vtkDirichletTessellation's default box about
    # its points) covered a quarter of it without a word; AreaFraction came out 1 + 2^-52 for
    # tiles inside the window. WindowArea and CoveredFraction against the shoelace areas of the
    # window and of its overlap with the tiles' window (rectangles), 2 for a tiling given twice,
    # and every AreaFraction at most 1.
    from vtkmodules.vtkFiltersCore import vtkAppendPolyData

    rng = np.random.default_rng(11)
    points = make_points([tuple(p) for p in 100000.0 + 1000.0 * rng.random((800, 2))])
    window = [[(100100.0, 100050.0), (100950.0, 100120.0), (100900.0, 100980.0), (100020.0, 100900.0)]]
    for bounds in ((99990.0, 101010.0, 99990.0, 101010.0), (100000.0, 100600.0, 100000.0, 101000.0)):
        tess = vtkDirichletTessellation()
        tess.SetInputData(points)
        tess.SetWindowBounds(*bounds)
        tess.Update()
        output, errors, _ = clip_by(tess.GetOutput(0), polygon(window))
        expected = abs(shoelace(left_of(window[0], bounds[1]))) / abs(shoelace(window[0]))
        fractions = cell_values(output, "AreaFraction")
        assert_that(not errors and all(0.0 < f <= 1.0 for f in fractions) and fractions.count(1.0) > 100,
                    f"{bounds}: AreaFraction in (0, 1], {fractions.count(1.0)} tiles inside: {errors}")
        assert_close(field_value(output, "WindowArea"), abs(shoelace(window[0])), 1e-13, f"{bounds}: WindowArea")
        assert_close(field_value(output, "CoveredFraction"), expected, 1e-11, f"{bounds}: CoveredFraction")
    both = vtkAppendPolyData()
    both.AddInputData(tess.GetOutput(0))
    both.AddInputData(tess.GetOutput(0))
    both.Update()
    output, errors, _ = clip_by(both.GetOutput(), polygon(window))
    assert_close(field_value(output, "CoveredFraction"), 2 * expected, 1e-11, "twice the tiles")
    # A window that no tile reaches (another file, shifted coordinates) gave an empty output and
    # no message: a warning names both boxes. Tiles in the window's box but beside it (a window in
    # a gap of tiles in blocks) get none: the boxes meet, and the empty output is a clip's result.
    for shift, apart in ((5000.0, True), (0.0, False)):
        far = [[(x + shift, y + shift) for x, y in window[0]]]
        tiles = tess.GetOutput(0) if apart else corner_tiles(tess.GetOutput(0), window[0])
        output, errors, warnings = clip_by(tiles, polygon(far))
        said = [w for w in warnings if "do not meet" in w]
        assert_that(not errors and output.GetNumberOfCells() == 0 and len(said) == int(apart)
                    and all("the tiles (input 0) and the window (input 1) do not meet, so the output is empty: the "
                            f"tiles span x 100000 .. 100600, y 100000 .. 101000, the window x {100020.0 + shift:.0f} "
                            f".. {100950.0 + shift:.0f}, y {100050.0 + shift:.0f} .. {100980.0 + shift:.0f}" in w
                            for w in said), f"a window shifted by {shift}: {warnings} {errors}")


def corner_tiles(tiles, ring):
    """The tiles with no point in the box of ring (some of them beyond each of its corners)."""
    xs, ys = [x for x, _ in ring], [y for _, y in ring]
    return polygon([cell for cell in cell_rings(tiles)
                    if not any(min(xs) <= x <= max(xs) and min(ys) <= y <= max(ys) for x, y in cell)])


def test_each_block_of_tiles_gives_its_share_of_the_window():
    """A composite's blocks are clipped one by one: each block's CoveredFraction is its share (0.5
    for each half of a square), each keeps its own field data, and a bad block is named in the error,
    which leaves no block; tiles stored in float that tile a double window exactly cover it to a
    float's rounding."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    window = polygon([[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]])
    halves = [[(0.0, 0.0), (0.5, 0.0), (0.5, 1.0), (0.0, 1.0)], [(0.5, 0.0), (1.0, 0.0), (1.0, 1.0), (0.5, 1.0)]]
    blocks = vtkMultiBlockDataSet()
    for k, half in enumerate(halves):
        blocks.SetBlock(k, polygon([half]))
    tag = vtkIntArray()
    tag.SetName("BlockTag")
    tag.InsertNextValue(7)
    blocks.GetBlock(1).GetFieldData().AddArray(tag)
    output, errors, _ = clip_by(blocks, window)
    shares = [field_value(output.GetBlock(k), "CoveredFraction") for k in range(2)]
    assert_that(not errors and shares == [0.5, 0.5], f"blocks: {shares}, {errors}")
    assert_that(field_value(output.GetBlock(1), "BlockTag") == 7 and
                output.GetBlock(0).GetFieldData().GetArray("BlockTag") is None, "a block's field data is its own")
    # A bad block: the error names it (the tiles' cell ids are the block's), and no block is kept.
    from vtkmodules.vtkCommonDataModel import vtkImageData
    for bad, fragment in ((polygon([[(0.5, 0.0), (1.0, 0.0), (0.6, 0.2), (1.0, 1.0), (0.5, 1.0)]]),
                           "block 1 (composite index 2) of input 0: tile 0 is not convex"),
                          (vtkImageData(), "block 1 (composite index 2) of input 0 (the tiles) is a "
                                           "vtkImageData: only point sets")):
        blocks.SetBlock(1, bad)
        output, errors, _ = clip_by(blocks, window)
        assert_that(len(errors) == 1 and fragment in errors[0], f"{fragment!r} not in {errors}")
        assert_that(output.GetNumberOfBlocks() == 0, f"{output.GetNumberOfBlocks()} blocks left after an error")
    for x in (0.1, 0.3):  # a float tiling of a window whose cut is not a float
        cut = polygon([[(x, 0.0), (1.0, 0.0), (1.0, 1.0), (x, 1.0)], [(0.0, 0.0), (x, 0.0), (x, 1.0), (0.0, 1.0)]])
        floats = vtkPoints()
        floats.SetDataTypeToFloat()
        for i in range(cut.GetNumberOfPoints()):
            floats.InsertNextPoint(cut.GetPoint(i))
        cut.SetPoints(floats)
        output, errors, _ = clip_by(cut, window)
        assert_that(not errors and abs(field_value(output, "CoveredFraction") - 1.0) < 1e-15,
                    f"float tiles at {x}: {field_value(output, 'CoveredFraction')}")


def test_a_shapefiles_polygons_read_by_gdal_are_clipped_as_tiles():
    """vtkGDALVectorReader gives a GeoJSON's (or shapefile's) polygons as closed polylines, a block
    each: they are tiles (16 unit squares clipped by a triangle of area 8 give 10 pieces, area 8,
    as the same squares as polygons do), with their attributes; a polygon with a hole is an error;
    an open polyline is skipped and listed. Of the blocks' warnings, 5 are given and the rest
    counted (one per block was given)."""
    import json
    import os
    import tempfile

    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkMultiBlockDataSet, vtkPolyData
    from vtkmodules.vtkIOGDAL import vtkGDALVectorReader

    squares = [[(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)] for i in range(4) for j in range(4)]
    window = polygon([[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)]])
    with tempfile.TemporaryDirectory() as out:
        path = os.path.join(out, "grid.geojson")
        with open(path, "w") as f:
            json.dump({"type": "FeatureCollection", "features": [
                {"type": "Feature", "properties": {"cell": k},
                 "geometry": {"type": "Polygon", "coordinates": [[list(p) for p in ring + ring[:1]]]}}
                for k, ring in enumerate(squares)]}, f)
        reader = vtkGDALVectorReader()
        reader.SetFileName(path)
        reader.Update()
        read = reader.GetOutput()
        first = read.GetBlock(0)
        assert_that(first.GetCellType(0) == 4, f"GDAL gives a polyline (4), not {first.GetCellType(0)}")
        output, errors, warnings = clip_by(read, window)
    assert_that(not errors and not warnings, f"{errors} {warnings}")
    pieces = [output.GetBlock(k) for k in range(output.GetNumberOfBlocks())]
    areas = [a for block in pieces for a in cell_values(block, "PieceArea")]
    plain = clip(polygon([squares[0]]), [[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)]])
    assert_that(len(areas) == 10 and math.isclose(math.fsum(areas), 8.0, rel_tol=1e-14),
                f"{len(areas)} pieces, area {math.fsum(areas)}")
    assert_close(cell_values(pieces[0], "ClippedArea")[0], cell_values(plain, "ClippedArea")[0], 1e-15, "square 0")
    kept = sorted(int(block.GetCellData().GetArray("cell").GetValue(0)) for block in pieces if block.GetNumberOfCells())
    assert_that(kept == [k for k, ring in enumerate(squares) if ring[0][0] + ring[0][1] < 4], f"{kept}")
    # A polygon with a hole: the reader gives the hole as a closed polyline of its own, which as a
    # tile counted twice (clipped areas 16 and 4 for a 4 x 4 square less 2 x 2): an error naming
    # both cells, the output empty. A multipolygon's parts side by side are tiles.
    big = polygon([[(-10.0, -10.0), (10.0, -10.0), (10.0, 10.0), (-10.0, 10.0)]])
    for geometry, error in (
            ({"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]],
                                                 [[1, 1], [1, 3], [3, 3], [3, 1], [1, 1]]]},
             "cell 1 of input 0, a closed polyline, lies inside cell 0, another: a polygon with a hole"),
            ({"type": "MultiPolygon", "coordinates": [[[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]]],
                                                      [[[5, 0], [6, 0], [6, 1], [5, 1], [5, 0]]]]}, None)):
        with tempfile.TemporaryDirectory() as out:
            path = os.path.join(out, "holed.geojson")
            with open(path, "w") as f:
                json.dump({"type": "FeatureCollection", "features": [
                    {"type": "Feature", "properties": {}, "geometry": geometry}]}, f)
            reader = vtkGDALVectorReader()
            reader.SetFileName(path)
            reader.Update()
            output, errors, _ = clip_by(reader.GetOutput(), big)
        if error:
            assert_that(len(errors) == 1 and error in errors[0] and output.GetNumberOfBlocks() == 0, f"{errors}")
            # Outside the window, the holed polygon counts nothing twice: no error.
            output, errors, _ = clip_by(reader.GetOutput(), polygon([[(20.0, 20.0), (21.0, 20.0), (21.0, 21.0)]]))
            assert_that(not errors, f"a holed polygon outside the window: {errors}")
        else:
            areas = cell_values(output.GetBlock(0), "ClippedArea")
            assert_that(not errors and sorted(areas) == [1.0, 16.0], f"{errors} {areas}")
    # An open polyline in each of 8 blocks: skipped and listed, 5 warnings given, the rest counted.
    blocks = vtkMultiBlockDataSet()
    for k in range(8):
        data = vtkPolyData()
        points = vtkPoints()
        for p in [(0.1, 0.1), (0.9, 0.1), (0.5, 0.8), (0.2, 0.5)]:
            points.InsertNextPoint(p[0], p[1], 0.0)
        lines = vtkCellArray()
        lines.InsertNextCell(4, [0, 1, 2, 3])
        data.SetPoints(points)
        data.SetLines(lines)
        blocks.SetBlock(k, data)
    output, errors, warnings = clip_by(blocks, window)
    skipped = output.GetBlock(7).GetFieldData().GetArray("SkippedCellIds")
    assert_that(not errors and skipped.GetNumberOfValues() == 1 and output.GetBlock(7).GetNumberOfCells() == 0,
                f"{errors}")
    assert_that(len(warnings) == 6 and all("closed polylines" in w for w in warnings[:5])
                and "3 more warning(s) about blocks of input 0 are not shown (the first 5 are)" in warnings[5], f"{warnings}")


def test_short_arrays_and_windows_beyond_the_doubles_are_named():
    """From an error audit: a tile cell-data array shorter than the tiles was read past its end (a
    crash for text, garbage values for numbers); a window of 1e200 gave WindowArea NaN and one of
    1e-300 a CoveredFraction of 0 though the tiles cover it."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkStringArray

    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    for array in (vtkStringArray(), vtkDoubleArray()):
        tiles = polygon([square, [(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]])
        array.SetName("v")
        array.InsertNextValue("a" if isinstance(array, vtkStringArray) else 1.0)
        tiles.GetCellData().AddArray(array)
        output, errors, _ = clip_by(tiles, polygon([square]))
        assert_that(len(errors) == 1
                    and "the tiles (input 0): its cell-data array 'v' has 1 value(s) for 2 cells" in errors[0]
                    and output.GetNumberOfCells() == 0, f"{array.GetClassName()}: {errors}")
    # A longer one is named in a warning, and each clipped tile keeps its own value.
    tiles = polygon([square, [(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]])
    long = vtkDoubleArray()
    long.SetName("v")
    for value in (5.0, 6.0, 7.0):
        long.InsertNextValue(value)
    tiles.GetCellData().AddArray(long)
    output, errors, warnings = clip_by(tiles, polygon([[(0.5, 0.0), (2.0, 0.0), (2.0, 1.0), (0.5, 1.0)]]))
    expected = ("the tiles (input 0): its cell-data array 'v' has 3 values for 2 cells, so its values 2 to 2 "
                "(counted from 0) belong to none and are not used")
    kept = output.GetCellData().GetArray("v")
    assert_that(not errors and sum(expected in w for w in warnings) == 1, f"{errors} {warnings}")
    assert_that(output.GetNumberOfCells() == 2 and [kept.GetValue(c) for c in range(2)] == [5.0, 6.0],
                f"{output.GetNumberOfCells()} clipped tiles")
    huge = [[(1e200 * x, 1e200 * y) for x, y in square]]
    output, errors, _ = clip_by(polygon([[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]]), polygon(huge))
    assert_that(len(errors) == 1 and "the window (input 1): its area overflows" in errors[0],
                f"1e200: {errors}")
    tiny = [[(1e-300 * x, 1e-300 * y) for x, y in square]]
    halves = polygon([[(1e-300 * x, 1e-300 * y) for x, y in ring]
                      for ring in ([(0, 0), (0.5, 0), (0.5, 1), (0, 1)], [(0.5, 0), (1, 0), (1, 1), (0.5, 1)])])
    output = clip(halves, tiny)
    assert_that(field_value(output, "CoveredFraction") == 1.0 and field_value(output, "WindowArea") == 0.0,
                f"1e-300: covered {field_value(output, 'CoveredFraction')} of an area below the doubles "
                f"({field_value(output, 'WindowArea')})")
    # Unit tiles in that window: the tile is too large at the window's scale, not "of some 1e154"
    _, errors, _ = clip_by(polygon([square]), polygon(tiny))
    assert_that(len(errors) == 1 and "cell 0 of input 0: its area overflows at the window's scale: the window (input 1) is so small" in errors[0],
                f"unit tiles in a window of 1e-300: {errors}")


def test_cells_that_refer_to_missing_points_are_named():
    """From a hostile-input trial: VTK reads a cell's point ids without a check. A window triangle
    with point id 99 of 4 clipped to a wrong WindowArea (0.68 for 0.64), a projection densified a
    line to a missing point into 1882 points, and cells without any points crashed Window Clip and
    Geographic Projection; a polygon cell of no points crashed Window Clip. Each is an error naming
    the input, the cell and the id."""
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid

    square = [(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)]
    tiles = polygon([[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]])
    grid = vtkUnstructuredGrid()
    grid.SetPoints(tiles.GetPoints())
    grid.InsertNextCell(7, 4, [0, 1, 2, 3])
    grid.InsertNextCell(7, 3, [0, 1, -1])
    cases = [("window id 99", tiles, cells(square, polys=[[0, 1, 2, 3], [0, 1, 99]]),
              "the window (input 1): cell 1 refers to point 99, but the points are 0 to 3"),
             ("window without points", tiles, cells([], polys=[[0, 1, 2]]),
              "the window (input 1): cell 0 refers to point 0, but there are no points"),
             ("tiles id 100000", cells(square, polys=[[0, 1, 2, 3], [0, 1, 100000]]), polygon([square]),
              "the tiles (input 0): cell 1 refers to point 100000, but the points are 0 to 3"),
             ("tiles in a grid, id -1", grid, polygon([square]),
              "the tiles (input 0): cell 1 refers to point -1, but the points are 0 to 3"),
             ("a window polygon of no points", tiles, cells([], polys=[[]]),
              "ring 0 has 0 vertices (a polygon needs 3 or more) (ring 0 is cell 0 of the window (input 1))")]
    for name, tiles_in, window, expected in cases:
        output, errors, _ = clip_by(tiles_in, window)
        assert_that(len(errors) == 1 and expected in errors[0] and output.GetNumberOfCells() == 0,
                    f"{name}: an error saying '{expected}': {errors}")
        # (errors name the filter's own file, as vtkErrorMacro does, not the shared helper's)
        assert_that("In vtkWindowClip.cxx, line " in errors[0], f"{name}: where: {errors}")
    # A bad id put in after a good run (ReplaceCellAtId does not mark the connectivity array
    # modified, so a range VTK keeps for it was stale, and the id passed, and crashed at 10^8).
    window = cells(square + [(0.1, 0.95), (0.9, 0.95), (0.5, 0.99)], polys=[[0, 1, 2, 3], [4, 5, 6]])
    f = vtkWindowClip()
    errors = messages_of(f)
    f.SetInputData(tiles)
    f.SetWindowData(window)
    f.Update()
    window.GetPolys().ReplaceCellAtId(1, 3, [4, 5, 100000000])
    window.Modified()
    f.Update()
    assert_that(len(errors) == 1 and "cell 1 refers to point 100000000, but the points are 0 to 6" in errors[0],
                f"a bad id after a good run: {errors}")
    # (lines come before polygons in a polydata's cell ids)
    for name, data, expected in [("line to point 50", cells(square, polys=[[0, 1, 2, 3]], lines=[[0, 50]]),
                                  "the input: cell 0 refers to point 50, but the points are 0 to 3"),
                                 ("no points", cells([], polys=[[0, 1, 2]]),
                                  "the input: cell 0 refers to point 0, but there are no points")]:
        f = vtkGeographicProjection()
        errors = messages_of(f)
        f.SetInputData(data)
        f.Update()
        assert_that(len(errors) == 1 and expected in errors[0] and f.GetOutput().GetNumberOfPoints() == 0,
                    f"projection, {name}: {errors}")


def test_window_lines_of_fewer_than_two_points_are_named_as_ignored():
    """A window line of 0 or 1 point was dropped without the warning a 2-point line gets."""
    square = [(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)]
    tiles = polygon([[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]])
    for line in ([], [0], [0, 2]):
        output, errors, warnings = clip_by(tiles, cells(square, polys=[[0, 1, 2, 3]], lines=[line]))
        assert_that(not errors and len(warnings) == 1 and "1 cell(s) of the window (input 1) are not polygons" in warnings[0]
                    and "(the first is cell 0)" in warnings[0] and abs(field_value(output, "WindowArea") - 0.64) < 1e-12,
                    f"a line of {len(line)} point(s): {errors}, {warnings}")


def test_a_window_in_a_vertical_plane_is_said_to_be_read_in_x_and_y():
    # From a user trial: a window drawn in the x-z plane was refused for rings of "fewer than 3
    # distinct vertices", without a word of why.
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import VTK_POLYGON, vtkPolyData

    points = vtkPoints()
    points.SetDataTypeToDouble()
    for x, z in ((0, 0), (10, 0), (10, 10), (0, 10)):
        points.InsertNextPoint(x, 5, z)
    upright = vtkPolyData()
    upright.SetPoints(points)
    upright.Allocate()
    upright.InsertNextCell(VTK_POLYGON, 4, [0, 1, 2, 3])
    _, errors, warnings = clip_by(polygon([[(1, 1), (3, 1), (3, 3), (1, 3)]]), upright)
    assert_that(any("the window (input 1) lies in a vertical plane (x from 0 to 10, y from 5 to 5, z from 0 to 10)"
                    in w for w in warnings) and len(errors) == 1, f"{warnings} {errors}")
    _, errors, warnings = clip_by(polygon([[(1, 1), (3, 1), (3, 3), (1, 3)]]),
                                  polygon([[(0, 0), (10, 0), (10, 10), (0, 10)]]))
    assert_that(not errors and not any("vertical" in w for w in warnings), f"a flat window: {warnings}")


def test_vtk_measures_each_piece_as_its_piece_area():
    """VTK draws a polygon, and vtkCellSizeFilter and Integrate Variables measure it, as the fan
    of triangles about its first point: each piece is a fan about it, so their areas are the
    pieces' own. 300 tiles under the README's window (a square with a square hole) and under a
    wavy shore: the pieces' fan triangles all turn anticlockwise or are flat (exactly), and
    vtkCellSizeFilter's areas match PieceArea to 1e-12 (the Ls round the hole were 0.16 for 0.15,
    and the README's window integrated to 0.600122 for 0.6)."""
    from fractions import Fraction

    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

    rng = random.Random(9)
    tessellation = vtkDirichletTessellation()
    tessellation.SetInputData(make_points([(rng.random(), rng.random()) for _ in range(300)]))
    tessellation.SetWindowBounds(0, 1, 0, 1)
    holed = [[(0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)], [(0.4, 0.4), (0.6, 0.4), (0.6, 0.6), (0.4, 0.6)]]
    wavy = [[(0.02, 0.02), (0.98, 0.02)] + [(0.98 - 0.96 * k / 200, 0.7 + 0.05 * math.sin(k * math.pi / 10))
                                            for k in range(201)]]
    for rings in (holed, wavy):
        clip = vtkWindowClip()
        clip.SetInputConnection(tessellation.GetOutputPort(0))
        clip.SetWindowData(polygon(rings))
        sizes = vtkCellSizeFilter()
        sizes.SetInputConnection(clip.GetOutputPort())
        sizes.Update()
        out = sizes.GetOutput()
        measured = np.array(cell_values(out, "Area"))
        pieces = np.array(cell_values(out, "PieceArea"))
        assert_that(np.allclose(measured, pieces, rtol=1e-12, atol=0), f"worst {np.max(np.abs(measured / pieces - 1))}")
        assert_close(measured.sum(), window_area(rings), 1e-12, "the pieces cover the window")
        for ring in cell_rings(out):
            apex = [Fraction(c) for c in ring[0]]
            for a, b in zip(ring[1:], ring[2:]):
                (ax, ay), (bx, by) = ([Fraction(c) for c in a], [Fraction(c) for c in b])
                assert_that((ax - apex[0]) * (by - apex[1]) - (ay - apex[1]) * (bx - apex[0]) >= 0,
                            f"a piece is no fan about its first point: {ring}")


def test_tiles_in_an_unstructured_grid_are_clipped_as_in_polydata():
    """ParaView's Threshold gives a selection of tiles as a vtkUnstructuredGrid: clipped as the
    same tiles in a vtkPolyData are (same pieces, areas and cell data; cell ids are the grid's),
    its pixels too (their points row by row: the ring is 0 1 3 2), and its 3D cells skipped and
    listed. The window is the unit square, the tiles those of 30 random points in a box 1.6 wide."""
    from vtkmodules.vtkCommonDataModel import (VTK_PIXEL, VTK_POLYGON, VTK_TETRA, vtkPolyData,
                                               vtkUnstructuredGrid)
    from vtkmodules.vtkCommonCore import vtkIdList

    rng = random.Random(5)
    tessellation = vtkDirichletTessellation()
    tessellation.SetInputData(make_points([(rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3)) for _ in range(30)]))
    tessellation.SetWindowBounds(-0.3, 1.3, -0.3, 1.3)
    tessellation.Update()
    tiles = tessellation.GetOutput()
    window = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    grid = vtkUnstructuredGrid()
    grid.SetPoints(tiles.GetPoints())
    grid.GetCellData().ShallowCopy(tiles.GetCellData())
    ids = vtkIdList()
    for c in range(tiles.GetNumberOfCells()):
        tiles.GetCellPoints(c, ids)
        grid.InsertNextCell(VTK_POLYGON, ids)
    from_poly, errors, _ = clip_by(tiles, window)
    from_grid, grid_errors, _ = clip_by(grid, window)
    assert_that(not errors and not grid_errors and from_grid.IsA("vtkPolyData"), f"{errors} {grid_errors}")
    for name in ("TileId", "ClippedArea", "PieceArea", "PointId", "Area"):
        assert_that(cell_values(from_grid, name) == cell_values(from_poly, name), f"{name} differs")
    assert_that(cell_rings(from_grid) == cell_rings(from_poly), "the pieces differ")
    assert_close(field_value(from_grid, "CoveredFraction"), 1.0, 1e-14, "the tiles cover the window")

    # A pixel of [0.5, 1.5] x [0.5, 1.5] (a quarter inside) and a tetrahedron (skipped, listed).
    mixed = vtkUnstructuredGrid()
    mixed.SetPoints(polygon([[(0.5, 0.5), (1.5, 0.5), (0.5, 1.5), (1.5, 1.5)]]).GetPoints())
    mixed.GetPoints().InsertNextPoint(0.2, 0.2, 1.0)
    mixed.InsertNextCell(VTK_TETRA, 4, [0, 1, 2, 4])
    mixed.InsertNextCell(VTK_PIXEL, 4, [0, 1, 2, 3])
    out, errors, warnings = clip_by(mixed, window)
    skipped = out.GetFieldData().GetArray("SkippedCellIds")
    assert_that(not errors and cell_values(out, "TileId") == [1] and cell_values(out, "AreaFraction") == [0.25],
                f"the pixel: {errors} {cell_values(out, 'AreaFraction')}")
    assert_that(skipped.GetNumberOfTuples() == 1 and skipped.GetValue(0) == 0, "the tetrahedron is listed")
    assert_that(len(warnings) == 1 and "not polygons of 3 or more points, triangles, quads, pixels or closed "
                "polylines (the first is cell 0)" in warnings[0], f"the warning lists what is clipped: {warnings}")
    assert_that(isinstance(out, vtkPolyData), "polygons out")


if __name__ == "__main__":
    run([test_vtk_measures_each_piece_as_its_piece_area,
         test_outlines_are_each_tiles_part_of_the_window_as_polygons_with_holes,
         test_tiles_in_an_unstructured_grid_are_clipped_as_in_polydata,
         test_a_window_in_a_vertical_plane_is_said_to_be_read_in_x_and_y,
         test_cells_are_simple_pieces_that_fill_tile_and_window,
         test_review_cases,
         test_input_arrays_named_like_the_filters_are_kept_under_another_name,
         test_a_window_of_loose_line_segments_is_joined_into_its_rings,
         test_an_island_that_fills_a_hole_exactly_cancels_it,
         test_a_window_whose_rings_cancel_out_is_an_error,
         test_tiles_and_window_must_share_their_projection,
         test_the_tiles_point_data_is_named_as_not_passed,
         test_inputs_of_another_type_are_named_and_leave_empty_outputs,
         test_review_of_windows_of_other_types_global_ids_and_flat_tiles,
         test_the_field_data_says_how_much_of_the_window_the_tiles_cover,
         test_each_block_of_tiles_gives_its_share_of_the_window,
         test_a_shapefiles_polygons_read_by_gdal_are_clipped_as_tiles,
         test_short_arrays_and_windows_beyond_the_doubles_are_named,
         test_cells_that_refer_to_missing_points_are_named,
         test_window_lines_of_fewer_than_two_points_are_named_as_ignored])
