"""vtkThiessenArealAverage and vtkWindowClip from Python: hand-known cases, the real Colorado
record against a brute-force raster of geodesically nearest gauges, and bad input."""

import csv
import math
import os

import numpy as np
from matplotlib.path import Path
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkIntArray, vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData, vtkTable
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkIOInfovis import vtkDelimitedTextReader

from tessera import (vtkDirichletTessellation, vtkGeographicProjection, vtkThiessenArealAverage,
                     vtkWindowClip)
from tessera_testing import (EXAMPLE_DATA, assert_close, assert_that, cell_rings, colorado_outline,
                             make_points, messages_of, polygon, projection_record, run, simplicity_defect)


def gauges_polydata(coords, ids, values=None):
    points = vtkPoints()
    points.SetDataTypeToDouble()
    station = vtkStringArray()
    station.SetName("station_id")
    for (lon, lat), sid in zip(coords, ids):
        points.InsertNextPoint(lon, lat, 0.0)
        station.InsertNextValue(sid)
    data = vtkPolyData()
    data.SetPoints(points)
    data.GetPointData().AddArray(station)
    if values is not None:
        array = vtkDoubleArray()
        array.SetName("value")
        for v in values:
            array.InsertNextValue(v)
        data.GetPointData().AddArray(array)
    return data


def summary_column(f, name):
    table = f.GetOutputDataObject(1)
    column = table.GetColumnByName(name)
    return [column.GetValue(r) for r in range(table.GetNumberOfRows())]


def weights_by_gauge(tiles):
    cd = tiles.GetCellData()
    return {cd.GetArray("GaugeId").GetValue(c): cd.GetArray("Weight").GetValue(c)
            for c in range(tiles.GetNumberOfCells())}


def test_four_symmetric_gauges_share_a_square():
    # Symmetric about the equator and the central meridian: every quadrant is a quarter.
    f = vtkThiessenArealAverage()
    f.SetGaugesData(gauges_polydata([(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)],
                                    ["a", "b", "c", "d"], [1.0, 2.0, 3.0, 4.0]))
    f.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
    f.Update(1)
    assert_close(summary_column(f, "ArealMean")[0], 2.5, 1e-9, "areal mean")
    assert_that(summary_column(f, "StationsUsed")[0] == 4, "4 gauges used")
    f.Update(0)
    w = weights_by_gauge(f.GetOutputDataObject(0))
    for g in range(4):
        assert_close(w[g], 0.25, 1e-9, f"weight of gauge {g}")


def read_colorado():
    coords, ids = [], []
    with open(os.path.join(EXAMPLE_DATA, "colorado_stations.csv")) as f:
        for row in csv.DictReader(f):
            coords.append((float(row["lon"]), float(row["lat"])))
            ids.append(row["station_id"])
    ring = colorado_outline()
    months = {}
    with open(os.path.join(EXAMPLE_DATA, "colorado_monthly_precip.csv")) as f:
        for row in csv.DictReader(f):
            key = (int(row["year"]), int(row["month"]))
            if key in ((1963, 8), (1920, 1), (1990, 7)):
                months.setdefault(key, {})[row["station_id"]] = float(row["precip"])
    return coords, ids, ring, months


def observations_table(months):
    """The months' values in long format with a numeric time column (year + (month - 1) / 12)."""
    return dated_table(months, lambda year, month: {"time": year + (month - 1) / 12})


def brute_force_mean(coords, ids, ring, values, step=0.01):
    """Cell-area-weighted mean over a lon/lat raster of the value of the geodesically nearest
    reporting gauge (distances on the WGS84 ellipsoid by the local-radii approximation, which
    ranks gauges correctly at these spacings)."""
    a, e2 = 6378137.0, 0.00669437999014
    reporting = [(c, values[i]) for c, i in zip(coords, ids) if i in values]
    glon = np.radians([c[0] for c, _ in reporting])
    glat = np.radians([c[1] for c, _ in reporting])
    gval = np.array([v for _, v in reporting])
    lon = np.arange(-109.1 + step / 2, -102.0, step)
    lat = np.arange(36.95 + step / 2, 41.05, step)
    LON, LAT = np.meshgrid(lon, lat)
    inside = Path(ring).contains_points(np.column_stack([LON.ravel(), LAT.ravel()])).reshape(LON.shape)
    phi = np.radians(LAT[inside])
    lam = np.radians(LON[inside])
    # cell area on the ellipsoid: M * N * cos(phi) * dphi * dlambda
    s2 = np.sin(phi) ** 2
    meridional = a * (1 - e2) / (1 - e2 * s2) ** 1.5
    normal = a / np.sqrt(1 - e2 * s2)
    cell = meridional * normal * np.cos(phi)
    best = np.full(phi.shape, np.inf)
    nearest = np.zeros(phi.shape, dtype=int)
    for g in range(len(gval)):
        mid = 0.5 * (phi + glat[g])
        s2m = np.sin(mid) ** 2
        dy = (phi - glat[g]) * a * (1 - e2) / (1 - e2 * s2m) ** 1.5
        dx = (lam - glon[g]) * a / np.sqrt(1 - e2 * s2m) * np.cos(mid)
        d = dx * dx + dy * dy
        closer = d < best
        best[closer] = d[closer]
        nearest[closer] = g
    return float(np.sum(cell * gval[nearest]) / np.sum(cell))


def test_colorado_months_match_a_brute_force_raster():
    coords, ids, ring, months = read_colorado()
    f = vtkThiessenArealAverage()
    f.SetGaugesData(gauges_polydata(coords, ids))
    f.SetCatchmentData(polygon([ring]))
    f.SetObservationsData(observations_table(months))
    f.Update(1)
    means = summary_column(f, "ArealMean")
    times = summary_column(f, "Time")
    assert_that(len(means) == 3, "three months")
    for k, key in enumerate(sorted(months)):
        expected = brute_force_mean(coords, ids, ring, months[key])
        print(f"  {key}: Thiessen {means[k]:.6f}, raster of nearest gauges {expected:.6f}")
        assert_that(abs(means[k] - expected) <= 1e-3 * abs(expected),
              f"{key}: Thiessen {means[k]:.6f} vs raster {expected:.6f}")
        f.UpdateTimeStep(times[k])
        tiles = f.GetOutputDataObject(0)
        w = weights_by_gauge(tiles)
        assert_close(sum(w.values()), 1.0, 1e-12, f"{key}: weights sum to 1")
        reported = sum(1 for i in ids if i in months[key])
        assert_that(summary_column(f, "StationsUsed")[k] == reported, f"{key}: StationsUsed")
    steps = f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    assert_that(steps is not None and len(steps) == 3, f"time steps advertised: {steps}")


def test_missing_steps_and_unused_input_are_reported():
    f = vtkThiessenArealAverage()
    f.SetGaugesData(gauges_polydata([(0.2, 0.2), (0.8, 0.8), (0.5, 0.5), (0.2, 0.2)],
                                    ["g1", "g2", "never", "g1copy"]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    # 2000-02: a gauge's row without a value keeps the month a step where no gauge reported;
    # 2000-04 has only a station that no gauge has: no step.
    months = {(2000, 1): {"g1": 3.0, "unknown": 5.0}, (2000, 2): {"other": 1.0, "g2": math.nan},
              (2000, 3): {"g1copy": 7.0, "g2": 1.0}, (2000, 4): {"other": 2.0}}
    table = observations_table(months)
    f.SetObservationsData(table)
    f.Update(1)
    times = summary_column(f, "Time")
    assert_that(times == [2000.0, 2000 + 1 / 12, 2000 + 2 / 12], f"steps {times}")
    means = summary_column(f, "ArealMean")
    assert_that(means[0] == 3.0, f"only g1 reported: {means[0]}")
    assert_that(math.isnan(means[1]), "no gauge: NaN mean")
    assert_that(summary_column(f, "StationsUsed")[1] == 0, "no gauge: StationsUsed 0")
    assert_that(summary_column(f, "StationsUsed")[2] == 2, "the repeat stands in for g1")
    fd = f.GetOutputDataObject(1).GetFieldData()
    unobserved = fd.GetArray("UnobservedGaugeIds")
    assert_that([unobserved.GetValue(i) for i in range(unobserved.GetNumberOfTuples())] == [2],
          "gauge 2 never observed")
    assert_that(fd.GetArray("DuplicateGaugeIds").GetValue(0) == 3 and fd.GetArray("DuplicateOfGaugeIds").GetValue(0) == 0,
          "gauge 3 repeats gauge 0")


def test_gauges_given_an_earlier_gauges_station_id_are_listed():
    """Station ids a, b, a, c, b, a: the later gauges of a shared id get no observation, and are
    listed with the first gauge of their id (found here by scanning the ids), apart from gauges at
    one place (DuplicateGaugeIds: none here), and named in the warning."""
    ids = ["a", "b", "a", "c", "b", "a"]
    coords = [(0.1 + 0.15 * k, 0.2 + 0.1 * k) for k in range(len(ids))]
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges_polydata(coords, ids))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    f.SetObservationsData(observations_table({(2000, 1): {"a": 1.0, "b": 2.0, "c": 3.0}}))
    f.Update(1)
    expected = [(g, ids.index(sid)) for g, sid in enumerate(ids) if ids.index(sid) != g]
    assert_that(field_ids(f, "SharedStationGaugeIds") == [g for g, _ in expected],
                f"{field_ids(f, 'SharedStationGaugeIds')}")
    assert_that(field_ids(f, "SharedStationOfGaugeIds") == [first for _, first in expected],
                f"{field_ids(f, 'SharedStationOfGaugeIds')}")
    assert_that(field_ids(f, "DuplicateGaugeIds") == [], "no gauges at one place")
    assert_that(field_ids(f, "UnobservedGaugeIds") == [g for g, _ in expected], "the later gauges get no observation")
    shared = [w for w in warnings if "given to more than one gauge" in w]
    assert_that(len(shared) == 1 and "(listed in SharedStationGaugeIds" in shared[0]
                and "a (gauges 0 and 2), b (gauges 1 and 4), a (gauges 0 and 5)" in shared[0], f"{warnings}")


def test_values_of_a_co_located_gauge_that_are_not_used_are_listed():
    """Two gauges at one place: at a step where both report, the first's value is used and the
    second's row is listed in CoLocatedObservationRows and named in a warning; at a step where
    only the second reports, its value is used and not listed."""
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges_polydata([(0.2, 0.2), (0.8, 0.8), (0.2, 0.2)], ["g1", "g2", "g1copy"]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    table = observations_table({(2000, 1): {"g1": 3.0, "g1copy": 100.0, "g2": 1.0},
                                (2000, 2): {"g1copy": 7.0, "g2": 1.0}})
    f.SetObservationsData(table)
    f.Update(1)
    stations, times = table.GetColumnByName("station_id"), table.GetColumnByName("time")
    shadowed = [r for r in range(table.GetNumberOfRows())
                if stations.GetValue(r) == "g1copy" and times.GetValue(r) == 2000.0]
    listed = f.GetOutputDataObject(1).GetFieldData().GetArray("CoLocatedObservationRows")
    assert_that([listed.GetValue(i) for i in range(listed.GetNumberOfTuples())] == shadowed,
                f"the row of g1copy in 2000-01 is listed: {shadowed}")
    # The row used in its place: g1's of 2000-01 (CoLocatedObservationOfRows, and the warning).
    used = [r for r in range(table.GetNumberOfRows()) if stations.GetValue(r) == "g1" and times.GetValue(r) == 2000.0]
    instead = f.GetOutputDataObject(1).GetFieldData().GetArray("CoLocatedObservationOfRows")
    assert_that([instead.GetValue(i) for i in range(instead.GetNumberOfTuples())] == used,
                f"g1's row of 2000-01 is used in its place: {used}")
    named = [w for w in warnings if "CoLocatedObservationRows" in w]
    assert_that(len(named) == 1 and f"row {shadowed[0]} (station g1copy) (row {used[0]} used)" in named[0],
                f"{warnings}")
    # The means: g1's 3 (not g1copy's 100) in January, g1copy's 7 in February, each with g2's 1.
    means = summary_column(f, "ArealMean")
    assert_that(abs((means[0] - 1.0) / (3.0 - 1.0) - (means[1] - 1.0) / (7.0 - 1.0)) < 1e-12,
                f"the same weight for the place in both months: {means}")
    assert_that(summary_column(f, "StationsUsed") == [2, 2], "co-located gauges counted once")


def test_an_unobserved_gauge_without_a_station_id_is_named_by_its_point():
    """A gauge whose station id is empty can never be matched: the warning names it by its point
    id (it listed nothing after the colon)."""
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges_polydata([(0.2, 0.2), (0.8, 0.8)], ["g1", ""]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    f.SetObservationsData(observations_table({(2000, 1): {"g1": 3.0}}))
    f.Update(1)
    named = [w for w in warnings if "never used" in w]
    assert_that(len(named) == 1 and "never used: gauge 1 (no station id)" in named[0], f"{warnings}")


def test_a_gauge_whose_station_id_others_share_is_named_with_its_index():
    """Without an observations table too: gauges A, B and a second A without a value; "never used:
    A" named the used A as well."""
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges_polydata([(0.2, 0.2), (0.8, 0.8), (0.5, 0.3)], ["A", "B", "A"], [1.0, 2.0, math.nan]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    f.SetValueArrayName("value")
    f.Update(1)
    named = [w for w in warnings if "never used" in w]
    assert_that(len(named) == 1 and named[0].rstrip().endswith("never used: A (gauge 2)"), f"{warnings}")
    # A mistyped station-id array name (no observations need it) is said, once per build.
    before = len(warnings)
    f.SetStationIdArrayName("station")
    f.Update(1)
    f.Update(0)
    told = [w for w in warnings[before:] if "no point-data array 'station' (StationIdArrayName)" in w]
    assert_that(len(told) == 1 and "named by their index; their arrays are station_id, value" in told[0],
                f"{warnings[before:]}")
    # The arrays the gauges have are listed where a name matches none (a ParaView user typing it
    # into the panel otherwise had to look them up).
    errors = messages_of(f)
    f.SetValueArrayName("precip")
    f.Update(1)
    assert_that(len(errors) == 1 and "numeric point-data array 'precip' (ValueArrayName)" in errors[0]
                and errors[0].rstrip().endswith("their arrays are station_id, value"), f"{errors}")
    # Settings changed but left unused by the inputs are said (a ParaView user saw no effect): the
    # observations' columns without observations, and the gauges' value array beside them.
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges_polydata([(0.2, 0.2), (0.8, 0.8)], ["A", "B"], [1.0, 2.0]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    f.SetTimeColumn("date")
    f.SetMonthColumn("month")
    f.Update(1)
    unused = [w for w in warnings if "not used" in w]
    assert_that(len(unused) == 1 and "TimeColumn 'date', MonthColumn 'month' not used: no observations table is "
                "connected (input 2), so the values are the gauges' point-data array 'value'" in unused[0],
                f"columns without observations: {warnings}")
    # Said once while it holds: gauges that change (as a series of gauge files does at each time
    # step) rebuild the average, and the warning came again at each.
    f.SetGaugesData(gauges_polydata([(0.3, 0.2), (0.8, 0.7)], ["A", "B"], [1.0, 3.0]))
    f.Update(1)
    assert_that(len([w for w in warnings if "not used" in w]) == 1, f"said again at a rebuild: {warnings}")
    f.SetObservationsData(csv_reader_table("station_id,date,value\nA,2000-03,5\nB,2000-03,7\n"))
    f.SetMonthColumn("")
    f.SetValueArrayName("precip")
    before = len(warnings)
    f.Update(1)
    unused = [w for w in warnings[before:] if "not used" in w]
    assert_that(len(unused) == 1 and "ValueArrayName 'precip' is not used: the values come from the observations "
                "table (input 2, ValueColumn)" in unused[0], f"a value array beside observations: {warnings[before:]}")


def test_gauges_never_weighted_and_no_gauge_inside_are_reported():
    """A gauge whose tile never reaches the catchment is named (and listed in UnweightedGaugeIds),
    and again with its place where a coordinate is exactly 0 (an empty CSV field read as a number);
    gauges all outside the catchment (a west longitude without its minus sign) get a warning."""
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    # a, b, c, d share the square; far's tile (beyond 3) never reaches it; unseen never reports.
    f.SetGaugesData(gauges_polydata([(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5), (6, 0), (7, 0)],
                                    ["a", "b", "c", "d", "far", "unseen"]))
    f.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
    f.SetObservationsData(observations_table({(2000, 1): {"a": 1.0, "b": 2.0, "c": 3.0, "d": 4.0, "far": 9.0},
                                              (2000, 2): {"a": 1.0, "far": 9.0}}))
    f.Update(1)
    assert_that(summary_column(f, "ArealMean") == [2.5, 1.0], f"means {summary_column(f, 'ArealMean')}")
    ids = f.GetOutputDataObject(1).GetFieldData().GetArray("UnweightedGaugeIds")
    assert_that([ids.GetValue(i) for i in range(ids.GetNumberOfTuples())] == [4], "far never weighted")
    named = [w for w in warnings if "never reach the catchment" in w]
    assert_that(len(named) == 1 and named[0].rstrip().endswith("(listed in UnweightedGaugeIds): far"),
                f"{warnings}")
    # far lies at a latitude of exactly 0, where an empty lat read as a number puts a gauge: said.
    at_zero = [w for w in warnings if "longitude or latitude of exactly 0" in w]
    assert_that(len(at_zero) == 1 and at_zero[0].rstrip().endswith("is 0: far at (6, 0)"), f"{warnings}")
    assert_that(not any("none of the" in w for w in warnings), f"gauges are inside: {warnings}")
    # Every gauge east of the catchment: the means come from gauges outside it, and it is said.
    g = vtkThiessenArealAverage()
    outside = messages_of(g, vtkCommand.WarningEvent)
    g.SetGaugesData(gauges_polydata([(105.0, 39.0), (104.0, 38.0)], ["a", "b"], [1.0, 2.0]))
    g.SetCatchmentData(polygon([[(-109, 37), (-102, 37), (-102, 41), (-109, 41)]]))
    g.Update(1)
    said = [w for w in outside if "none of the 2 gauges lies inside the catchment" in w]
    assert_that(len(said) == 1 and "minus sign" in said[0] and "the gauges and the catchment" in said[0], f"{outside}")
    assert_that(not any("exactly 0" in w for w in outside), f"no gauge at 0: {outside}")


def test_a_catchment_ring_inside_another_blocks_ring_is_reported():
    """vtkGDALVectorReader gives each feature a block: a sub-basin given beside its basin is cut out
    as a hole by the even-odd rule, and a warning names it; a hole in its polygon's block is not."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    basin = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    sub = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
    for blocks, expected in (([[basin], [sub]], 1), ([[basin, sub]], 0), ([[basin], [[(2, 2), (3, 2), (3, 3)]]], 0)):
        catchment = vtkMultiBlockDataSet()
        for k, rings in enumerate(blocks):
            catchment.SetBlock(k, polygon(rings))
        f = vtkThiessenArealAverage()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetGaugesData(gauges_polydata([(-0.75, 0.0), (0.75, 0.0)], ["w", "e"], [1.0, 3.0]))
        f.SetCatchmentData(catchment)
        f.Update(1)
        if sub in blocks[-1]:
            # Either way the even-odd rule holds: the inner square is a hole (both halves alike).
            assert_close(summary_column(f, "ArealMean")[0], 2.0, 1e-9, f"mean of {len(blocks)} block(s)")
        said = [w for w in warnings if "inside a ring of another block" in w]
        assert_that(len(said) == expected, f"{len(blocks)} block(s): {warnings}")
        if expected:
            # (blocks by their index under the root, with ParaView's composite index beside it)
            assert_that("): 1 catchment ring(s)" in said[0]
                        and "block 1 (composite index 2) cell 0 inside block 0 (composite index 1) cell 0 (a hole)"
                        in said[0], said[0])
    # An island in that hole, a feature of its own too, is land again: said so, not called a hole.
    catchment = vtkMultiBlockDataSet()
    for k, ring in enumerate((basin, sub, [(-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)])):
        catchment.SetBlock(k, polygon([ring]))
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges_polydata([(-0.75, 0.0), (0.75, 0.0)], ["w", "e"], [1.0, 3.0]))
    f.SetCatchmentData(catchment)
    f.Update(1)
    said = [w for w in warnings if "inside a ring of another block" in w]
    assert_that(len(said) == 1 and "2 catchment ring(s)" in said[0]
                and "block 1 (composite index 2) cell 0 inside block 0 (composite index 1) cell 0 (a hole)" in said[0]
                and "block 2 (composite index 3) cell 0 inside block 0 (composite index 1) cell 0 (land again: "
                    "inside a hole)" in said[0], f"{warnings}")


def test_gauges_in_blocks_as_a_point_layer_gives_them_are_joined():
    """A point GeoJSON or shapefile read by vtkGDALVectorReader is a multiblock with a block per
    gauge, its attributes the cell data of its vertex: the gauges are joined in block order and
    give what the same gauges as one point set give (the filter crashed in ParaView on them)."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    coords = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5), (0.1, 0.2)]
    names = ["a", "b", "c", "d", "e"]
    months = {(2000, 1): {"a": 1.0, "b": 2.0, "c": 3.0, "d": 4.0, "e": 10.0}, (2000, 2): {"b": 5.0, "e": 1.0}}
    blocks = vtkMultiBlockDataSet()
    for k, ((lon, lat), name) in enumerate(zip(coords, names)):
        leaf = vtkPolyData()
        points = vtkPoints()
        points.SetDataTypeToDouble()
        points.InsertNextPoint(lon, lat, 0.0)
        leaf.SetPoints(points)
        verts = vtkCellArray()
        verts.InsertNextCell(1, [0])
        leaf.SetVerts(verts)
        station = vtkStringArray()
        station.SetName("station_id")
        station.InsertNextValue(name)
        leaf.GetCellData().AddArray(station)
        blocks.SetBlock(k, leaf)
    def averaged(gauges):
        """The filter on these gauges, the square catchment and the months, updated, and its errors."""
        f = vtkThiessenArealAverage()
        errors = messages_of(f)
        f.SetGaugesData(gauges)
        f.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
        f.SetObservationsData(observations_table(months))
        f.Update(1)
        return f, errors

    # The same vertices as one point set (Merge Blocks of the layer): their cell data is theirs too
    # (it was not read: "no point-data array 'station_id'").
    merged = vtkPolyData()
    merged_points = vtkPoints()
    merged_points.SetDataTypeToDouble()
    merged_verts = vtkCellArray()
    merged_ids = vtkStringArray()
    merged_ids.SetName("station_id")
    for k in reversed(range(len(coords))):  # vertices in another order than the points
        merged_verts.InsertNextCell(1, [k])
        merged_ids.InsertNextValue(names[k])
    for lon, lat in coords:
        merged_points.InsertNextPoint(lon, lat, 0.0)
    merged.SetPoints(merged_points)
    merged.SetVerts(merged_verts)
    merged.GetCellData().AddArray(merged_ids)
    results = []
    for gauges in (gauges_polydata(coords, names), blocks, merged):
        f, errors = averaged(gauges)
        assert_that(not errors, f"{gauges.GetClassName()}: {errors}")
        f.Update(0)
        results.append((summary_column(f, "ArealMean"), sorted(weights_by_gauge(f.GetOutputDataObject(0)).items())))
    assert_that(results[0] == results[1] == results[2] and len(results[0][1]) == 5,
                f"point set {results[0]}, blocks {results[1]}, vertices' cell data {results[2]}")
    # A point-data 'station_id' beside the vertices' one (here with the same ids): the point
    # data's is used, and a warning names the hidden one, for a point set and for a block.
    def station_ids(values):
        """A point-data 'station_id' array of these ids."""
        array = vtkStringArray()
        array.SetName("station_id")
        for v in values:
            array.InsertNextValue(v)
        return array

    hiding_set = vtkPolyData()
    hiding_set.DeepCopy(merged)
    hiding_set.GetPointData().AddArray(station_ids(names))
    hiding_blocks = vtkMultiBlockDataSet()
    hiding_blocks.DeepCopy(blocks)
    hiding_blocks.GetBlock(0).GetPointData().AddArray(station_ids(["a"]))
    for gauges, label in ((hiding_set, "the gauges (input 0)"),
                          (hiding_blocks, "block 0 (composite index 1) of the gauges (input 0)")):
        f = vtkThiessenArealAverage()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetGaugesData(gauges)
        f.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
        f.SetObservationsData(observations_table(months))
        f.Update(1)
        expected = f"the cell-data array(s) 'station_id' of {label} are not used: point-data arrays of the same names are"
        assert_that(any(expected in w for w in warnings), f"{warnings}")
        assert_that(summary_column(f, "ArealMean") == results[0][0], "the point data's ids give the same means")
    # Without observations, the blocks' value arrays make the one step, at the composite's time.
    from vtkmodules.vtkCommonDataModel import vtkDataObject

    for k, value in enumerate([1.0, 2.0, 3.0, 4.0, 10.0]):
        array = vtkDoubleArray()
        array.SetName("value")
        array.InsertNextValue(value)
        blocks.GetBlock(k).GetCellData().AddArray(array)
    blocks.GetInformation().Set(vtkDataObject.DATA_TIME_STEP(), 1963.5)
    g = vtkThiessenArealAverage()
    g.SetGaugesData(blocks)
    g.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
    g.Update(1)
    assert_that(summary_column(g, "Time") == [1963.5] and summary_column(g, "ArealMean") == [results[0][0][0]],
                f"one step from the blocks' values: {summary_column(g, 'Time')}, {summary_column(g, 'ArealMean')}")
    # Without observations, a block whose value array is missing is named as the reason (the error
    # said only that the gauges need a numeric array 'value').
    blocks.GetBlock(2).GetCellData().RemoveArray("value")
    g.Modified()
    errors = messages_of(g)
    g.Update(1)
    assert_that(len(errors) == 1 and "need a numeric point-data array 'value' (ValueArrayName): block 2 (composite "
                "index 3) of the points has no array 'value', which block 0 (composite index 1) has" in errors[0],
                f"{errors}")
    # A value array shorter than the gauges of one point set was read past its end (a mean of
    # garbage): an error naming it.
    short = gauges_polydata(coords, names, [1.0, 2.0, 3.0, 4.0, 5.0])
    short.GetPointData().GetArray("value").SetNumberOfTuples(1)
    h = vtkThiessenArealAverage()
    errors = messages_of(h)
    h.SetGaugesData(short)
    h.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
    h.Update(1)
    assert_that(len(errors) == 1 and "the gauges (input 0): its point-data array 'value' has 1 value(s) for 5 points"
                in errors[0], f"{errors}")
    # A longer value array is named in a warning (not the gauges' other long arrays, unread), and
    # the mean is that of the gauges' own values: the extra ones are not used.
    means = []
    for extra in ([], [1000.0, 2000.0]):
        gauges = gauges_polydata(coords, names, [1.0, 2.0, 3.0, 4.0, 5.0] + extra)
        unread = vtkDoubleArray()
        unread.SetName("elevation")
        unread.SetNumberOfTuples(6)
        gauges.GetPointData().AddArray(unread)
        h = vtkThiessenArealAverage()
        warnings = messages_of(h, vtkCommand.WarningEvent)
        h.SetGaugesData(gauges)
        h.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
        h.Update(1)
        long_ones = [w for w in warnings if "values for 5 points" in w]
        expected = ["the gauges (input 0): its point-data array 'value' has 7 values for 5 points, so its values 5 "
                    "to 6 (counted from 0) belong to none and are not used"] if extra else []
        assert_that(len(long_ones) == len(expected) and all(e in w for e, w in zip(expected, long_ones)),
                    f"{warnings}")
        means.append(summary_column(h, "ArealMean"))
    assert_that(means[0] == means[1] and len(means[0]) == 1, f"means {means}")
    # A block without the station ids is named.
    blocks.GetBlock(3).GetCellData().RemoveArray("station_id")
    _, errors = averaged(blocks)
    assert_that(len(errors) == 1 and "block 3 (composite index 4) of the points has no array 'station_id', which block 0 (composite index 1) has" in errors[0],
                f"{errors}")
    # Inputs of another type after a good run: errors naming the type, and nothing left shown.
    from vtkmodules.vtkCommonDataModel import vtkImageData

    image = vtkImageData()
    image.SetDimensions(2, 2, 1)
    for wrong in ("gauges", "observations"):
        f, errors = averaged(gauges_polydata(coords, names))
        assert_that(f.GetOutputDataObject(1).GetNumberOfRows() == 2 and not errors, f"good run: {errors}")
        getattr(f, "SetGaugesData" if wrong == "gauges" else "SetObservationsData")(image)
        f.Update(1)
        f.UpdateInformation()
        steps = f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
        assert_that(f.GetOutputDataObject(1).GetNumberOfRows() == 0 and steps is None,
                    f"{wrong} as an image: {f.GetOutputDataObject(1).GetNumberOfRows()} rows, steps {steps}")
        said = "the gauges (input 0) are a vtkImageData" if wrong == "gauges" else "the observations (input 2) are a vtkImageData"
        assert_that(any(said in e for e in errors), f"{wrong}: {errors}")


def test_bad_gauge_and_self_intersecting_catchment_are_named():
    f = vtkThiessenArealAverage()
    messages = messages_of(f)
    f.SetGaugesData(gauges_polydata([(0.2, 0.2), (0.8, 95.0)], ["a", "b"], [1.0, 2.0]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    f.Update()
    assert_that(len(messages) == 1 and "gauge 1 (station b)" in messages[0], f"gauge 1 named: {messages}")
    # By its station id too, as a double id column (a CSV reader's) gives it in full.
    usgs = gauges_polydata([(0.2, 0.2), (0.8, 95.0)], ["a", "b"], [1.0, 2.0])
    usgs.GetPointData().RemoveArray("station_id")
    usgs.GetPointData().AddArray(make_points([(0, 0), (0, 0)], station_id=[6730200.0, 394529105231201.0])
                                 .GetPointData().GetArray("station_id"))
    f.SetGaugesData(usgs)
    f.Update()
    assert_that(len(messages) == 2 and "gauge 1 (station 394529105231201)" in messages[1],
                f"gauge 1 named by its double id: {messages}")
    for gauge, ring, named in [((-1031.5, 0.5), [(0, 0), (1, 0), (1, 1), (0, 1)], "gauge 1 (station b)"),
                               ((0.5, 0.5), [(0, 0), (1000, 0), (1000, 1), (0, 1)], "catchment ring 0 vertex 1")]:
        h = vtkThiessenArealAverage()
        messages = messages_of(h)
        h.SetGaugesData(gauges_polydata([(0.2, 0.2), gauge], ["a", "b"], [1.0, 2.0]))
        h.SetCatchmentData(polygon([ring]))
        h.Update()
        assert_that(len(messages) == 1 and named in messages[0], f"longitude typo named ({named}): {messages}")
    g = vtkThiessenArealAverage()
    messages = messages_of(g)
    g.SetGaugesData(gauges_polydata([(0.2, 0.2)], ["a"], [1.0]))
    g.SetCatchmentData(polygon([[(0, 0), (1, 1), (1, 0), (0, 1)]]))
    g.Update()
    assert_that(len(messages) == 1 and "self-intersecting" in messages[0], f"bowtie named: {messages}")
    # A text 'value' array without observations: said to be text (it was "need a numeric array
    # 'value'; their arrays are station_id, value").
    text = gauges_polydata([(0.2, 0.2), (0.8, 0.8)], ["a", "b"])
    values = vtkStringArray()
    values.SetName("value")
    for v in ("1", "2"):
        values.InsertNextValue(v)
    text.GetPointData().AddArray(values)
    g.SetGaugesData(text)
    g.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    g.Update()
    assert_that(len(messages) == 2 and "the gauges' point-data array 'value' (ValueArrayName) is read as one number "
                "per gauge, but it is a vtkStringArray, not numbers" in messages[1], f"text values: {messages}")
    g.SetGaugesData(gauges_polydata([(0.2, 0.2)], ["a"], [1.0]))
    # A catchment cell with a point id beyond its points took garbage for a vertex (ArealMean 3.77
    # for 2.26, and the projection's centre moved); it is named now.
    catchment = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    catchment.InsertNextCell(7, 3, [0, 1, 99])
    g.SetCatchmentData(catchment)
    g.Update()
    assert_that(len(messages) == 3 and "the catchment (input 1): cell 1 refers to point 99, but the points are 0 to 3"
                in messages[2], f"point id 99 named: {messages}")


def test_window_clip_of_projected_tiles_sums_to_the_catchment():
    coords, ids, ring, _ = read_colorado()
    project = vtkGeographicProjection()
    gauges = gauges_polydata(coords, ids)
    project.SetInputData(gauges)
    project.Update()
    record = project.GetOutput().GetFieldData().GetAbstractArray("TesseraProjection").GetValue(0)
    outline = vtkGeographicProjection()
    outline.ParametersFromDataOff()
    # the outline in the gauges' projection: read the record's numbers back
    values = dict(item.split("=") for item in record.split())
    outline.SetProjectionToAlbersEqualArea()
    outline.SetCentralLongitude(float(values["lon0"]))
    outline.SetStandardParallels(float(values["lat1"]), float(values["lat2"]))
    outline.SetInputData(polygon([ring]))
    outline.Update()
    tess = vtkDirichletTessellation()
    tess.SetInputConnection(project.GetOutputPort())
    clip = vtkWindowClip()
    clip.SetInputConnection(tess.GetOutputPort(0))
    clip.SetWindowConnection(outline.GetOutputPort())
    clip.Update()
    out = clip.GetOutput()
    cd = out.GetCellData()
    clipped = {cd.GetArray("TileId").GetValue(c): cd.GetArray("ClippedArea").GetValue(c)
               for c in range(out.GetNumberOfCells())}
    for c in range(out.GetNumberOfCells()):
        fraction = cd.GetArray("AreaFraction").GetValue(c)
        assert_that(0.0 < fraction <= 1.0 + 1e-12, f"AreaFraction {fraction} in (0, 1]")
    assert_that(cd.GetAbstractArray("station_id") is not None, "tile cell data carried")
    pts = np.array(cell_rings(outline.GetOutput())[0])
    x, y = pts[:, 0], pts[:, 1]
    area = 0.5 * abs(float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)))
    assert_close(sum(clipped.values()), area, 1e-12 * area, "clipped tiles sum to the catchment")


def test_window_clip_names_a_non_convex_tile():
    square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    ell = [(3, 3), (5, 3), (5, 4), (4, 4), (4, 5), (3, 5)]  # straddles the window's corner
    clip = vtkWindowClip()
    messages = messages_of(clip)
    clip.SetInputData(polygon([[(1, 1), (2, 1), (2, 2), (1, 2)], ell]))
    clip.SetWindowData(polygon([square]))
    clip.Update()
    assert_that(len(messages) == 1 and "tile 1 is not convex" in messages[0],
                f"the L-shaped tile named: {messages}")
    assert_that(clip.GetOutput().GetNumberOfCells() == 0, "no output after the error")
    clip.SetInputData(polygon([[(1, 1), (2, 1), (2, 2), (1, 2)], [(3, 3), (5, 3), (5, 5), (3, 5)]]))
    clip.Update()
    cd = clip.GetOutput().GetCellData()
    areas = [cd.GetArray("ClippedArea").GetValue(c) for c in range(clip.GetOutput().GetNumberOfCells())]
    assert_that(len(messages) == 1 and areas == [1.0, 1.0], f"convex tiles clip: {areas}")
    fields = clip.GetOutput().GetFieldData()
    for name in ("SkippedCellIds", "EmptyTileIds"):
        listed = fields.GetArray(name)
        assert_that(listed is not None and listed.GetNumberOfTuples() == 0, f"{name}: written, and empty")


def test_sub_basins_with_rounded_junctions_average_as_their_union():
    # Two sub-basins whose shared border has vertices only the west one has, rounded to 6
    # decimals (off the east one's edge by up to 7e-7 degrees): refused as crossing rings. Now put
    # on that edge, with a warning that counts them, and the means are the union outline's.
    south, north = (-104.0, 39.0), (-103.7, 40.0)
    junctions = [(round(south[0] + t * (north[0] - south[0]), 6), round(south[1] + t * (north[1] - south[1]), 6))
                 for t in (0.13, 0.37, 0.52, 0.81)]
    west = [(-105.0, 39.0), south, *junctions, north, (-105.0, 40.0)]
    east = [south, (-103.0, 39.0), (-103.0, 40.0), north]
    rng = np.random.default_rng(8)
    coords = [(float(x), float(y)) for x, y in zip(rng.uniform(-105.5, -102.5, 30), rng.uniform(38.5, 40.5, 30))]
    ids = [f"G{k}" for k in range(len(coords))]
    values = [float(v) for v in rng.uniform(0, 10, len(coords))]
    means = []
    for rings in ([west, east], [[(-105.0, 39.0), (-103.0, 39.0), (-103.0, 40.0), (-105.0, 40.0)]]):
        f = vtkThiessenArealAverage()
        warnings = messages_of(f, "WarningEvent")
        errors = messages_of(f)
        f.SetGaugesData(gauges_polydata(coords, ids, values))
        f.SetCatchmentData(polygon(rings))
        f.Update(1)
        assert_that(not errors, f"{len(rings)} ring(s): {errors}")
        said = [w for w in warnings if "catchment vertex(es) lay within 1e-06 degrees of another ring's edge" in w]
        assert_that(len(said) == (len(rings) == 2) and all(w.count("4 catchment vertex(es)") for w in said),
                    f"{len(rings)} ring(s): {warnings}")
        means.append(summary_column(f, "ArealMean")[0])
    assert_close(means[0], means[1], 1e-9 * abs(means[1]), "the sub-basins' mean against the union's")


def test_clipping_the_averages_lon_lat_tiles_says_what_to_do_instead():
    # The areal average's tiles come in lon/lat with densified edges: convex where they were made
    # (the projected plane), not in lon/lat. Clipping them to a sub-basin is a natural next step in
    # ParaView; the error advised splitting the tile into convex parts, no help here. It now says
    # what to do instead; a tile of other origin gets the error alone.
    coords, ids, ring, _ = read_colorado()
    average = vtkThiessenArealAverage()
    average.SetGaugesData(gauges_polydata(coords, ids, [1.0] * len(ids)))
    average.SetCatchmentData(polygon([ring]))
    average.Update(0)
    tiles = average.GetOutputDataObject(0)
    clip = vtkWindowClip()
    errors = messages_of(clip)
    clip.SetInputData(tiles)
    clip.SetWindowData(polygon([[(-106.0, 38.0), (-104.0, 38.0), (-104.0, 40.0), (-106.0, 40.0)]]))
    clip.Update()
    assert_that(len(errors) == 1 and " is not convex: " in errors[0] and "These look like Thiessen Areal Average's "
                "tiles, which are convex in its projected plane, not in lon/lat: for the weights over a sub-basin, "
                "give it the sub-basin as its catchment" in errors[0], f"the areal average's tiles: {errors}")
    tiles.GetCellData().RemoveArray("CellWeight")  # (no longer the areal average's)
    clip.Modified()
    clip.Update()
    assert_that(len(errors) == 2 and " is not convex: " in errors[1] and "Thiessen" not in errors[1],
                f"other tiles: {errors}")


def test_window_clip_reports_cells_that_are_not_polygons():
    tiles = polygon([[(1, 1), (2, 1), (2, 2), (1, 2)]])
    lines = vtkCellArray()
    for a, b in [(0, 1), (1, 2)]:
        lines.InsertNextCell(2)
        lines.InsertCellPoint(a)
        lines.InsertCellPoint(b)
    tiles.SetLines(lines)  # vtkPolyData numbers lines before polygons: cells 0 and 1
    tiles.GetPolys().InsertNextCell(2)  # a polygon collapsed to two points: cell 3
    tiles.GetPolys().InsertCellPoint(0)
    tiles.GetPolys().InsertCellPoint(1)
    clip = vtkWindowClip()
    messages = messages_of(clip, "WarningEvent")
    clip.SetInputData(tiles)
    clip.SetWindowData(polygon([[(0, 0), (4, 0), (4, 4), (0, 4)]]))
    clip.Update()
    out = clip.GetOutput()
    skipped = out.GetFieldData().GetArray("SkippedCellIds")
    listed = sorted(skipped.GetValue(k) for k in range(skipped.GetNumberOfTuples()))
    unclipped = sorted(c for c in range(tiles.GetNumberOfCells())
                       if tiles.GetCellType(c) == 3 or tiles.GetCell(c).GetNumberOfPoints() < 3)
    assert_that(listed == unclipped and len(listed) == 3, f"lines and the 2-point polygon listed: "
                f"{listed} vs {unclipped}")
    assert_that(len(messages) == 1 and "3 cell(s) of input 0 are not polygons" in messages[0],
                f"a warning: {messages}")
    assert_that(out.GetNumberOfCells() == 1, "the square clipped")


def test_window_clip_reports_tiles_without_area_and_names_an_overflow():
    """Polygons in the window without area to clip (a sliver thinner than rounding, collinear
    corners) give no piece: they are listed in EmptyTileIds with a warning (they vanished
    silently); one outside the window is not listed. Coordinates whose area overflows are an
    error naming the cell (every tile vanished without a word)."""
    window = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    tiles = polygon([[(0.1, 0.5), (0.9, 0.5), (0.9, 0.5 + 1e-15)], [(0.2, 0.2), (0.3, 0.2), (0.3, 0.3)],
                     [(0.1, 0.7), (0.5, 0.7), (0.9, 0.7)], [(2, 2), (3, 2), (3, 3)]])
    clip = vtkWindowClip()
    messages = messages_of(clip, "WarningEvent")
    clip.SetInputData(tiles)
    clip.SetWindowData(window)
    clip.Update()
    out = clip.GetOutput()
    empty = out.GetFieldData().GetArray("EmptyTileIds")
    listed = [empty.GetValue(k) for k in range(empty.GetNumberOfTuples())] if empty else None
    assert_that(listed == [0, 2], f"the sliver and the collinear polygon listed: {listed}")
    assert_that(len(messages) == 1 and "2 polygon(s) of input 0 lie in the window but have no area" in messages[0],
                f"{messages}")
    kept = out.GetCellData().GetArray("TileId")
    assert_that([kept.GetValue(k) for k in range(kept.GetNumberOfTuples())] == [1], "tile 1 clipped")
    # A NaN corner is named as such (not as an overflow).
    nan_tile = vtkWindowClip()
    nan_errors = messages_of(nan_tile)
    nan_tile.SetInputData(polygon([[(0.2, 0.2), (float("nan"), 0.2), (0.3, 0.3)]]))
    nan_tile.SetWindowData(window)
    nan_tile.Update()
    assert_that(len(nan_errors) == 1 and "tile 0 vertex 1 has a NaN coordinate" in nan_errors[0], f"{nan_errors}")
    huge = vtkWindowClip()
    errors = messages_of(huge)
    huge.SetInputData(polygon([[(0, 0), (1e200, 0), (1e200, 1e200), (0, 1e200)]]))
    huge.SetWindowData(polygon([[(0, 0), (1e150, 0), (1e150, 1e150), (0, 1e150)]]))  # (its area 1e300)
    huge.Update()
    assert_that(len(errors) == 1 and "cell 0 of input 0: its area overflows" in errors[0], f"{errors}")


def test_window_clip_of_tiles_stored_in_float():
    # Tessellation tiles whose points went through float (VTK's default point type) fold by a
    # float's rounding: the convexity check allows for it, and the tiling still sums to the window.
    rng = np.random.default_rng(1)
    for cx, cy, half in [(5e5, 4.5e6, 5e4), (100.0, 40.0, 1.0)]:
        xy = np.c_[cx + half * (2 * rng.random(3000) - 1), cy + half * (2 * rng.random(3000) - 1)]
        tess = vtkDirichletTessellation()
        tess.SetInputData(make_points([tuple(p) for p in xy]))
        tess.Update()
        tiles = vtkPolyData()
        tiles.DeepCopy(tess.GetOutput(0))
        single = vtkPoints()
        single.SetDataTypeToFloat()
        single.SetNumberOfPoints(tiles.GetNumberOfPoints())
        for i in range(tiles.GetNumberOfPoints()):
            single.SetPoint(i, tiles.GetPoint(i))
        tiles.SetPoints(single)
        window = [(cx - 0.7 * half, cy - 0.6 * half), (cx + 0.8 * half, cy - 0.7 * half),
                  (cx + 0.6 * half, cy + 0.9 * half), (cx - 0.5 * half, cy + 0.5 * half)]
        clip = vtkWindowClip()
        messages = messages_of(clip)
        clip.SetInputData(tiles)
        clip.SetWindowData(polygon([window]))
        clip.Update()
        assert_that(not messages, f"float tiles at ({cx}, {cy}) clip: {messages[:1]}")
        out = clip.GetOutput()
        cd = out.GetCellData()
        clipped = {cd.GetArray("TileId").GetValue(c): cd.GetArray("ClippedArea").GetValue(c)
                   for c in range(out.GetNumberOfCells())}
        x = np.array([p[0] for p in window])
        y = np.array([p[1] for p in window])
        area = 0.5 * abs(float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)))
        assert_close(sum(clipped.values()), area, 1e-4 * area, "float tiles sum to the window")


def with_open_polyline(data):
    """The polygon data with an open polyline (cell 0: lines come before polygons) added."""
    lines = vtkCellArray()
    lines.InsertNextCell(3)
    for k in range(3):
        lines.InsertCellPoint(k)
    data.SetLines(lines)
    return data


def projection_of(f):
    """The TesseraProjection record of output 1's field data."""
    return projection_record(f.GetOutputDataObject(1))


def test_the_projection_used_is_recorded_and_makes_the_same_tiles():
    # Output 1 records the projection the tiles were made in: vtkGeographicProjection's fit to the
    # catchment's rings (an open polyline of the catchment, far off, ignored with a warning, does
    # not move it, as it moves vtkGeographicProjection's fit to every point). Given back as
    # ProjectionRecord, as for a part of the catchment, it makes the same weights, bit for bit.
    coords = [(10.2, 45.1), (10.9, 45.3), (10.5, 45.8), (11.4, 45.6), (11.8, 45.2)]
    square = [(10.0, 45.0), (11.5, 45.0), (11.5, 46.0), (10.0, 46.0)]
    catchment = polygon([square])
    fit = vtkGeographicProjection()
    fit.SetInputData(catchment)
    fit.Update()
    expected = projection_record(fit.GetOutputDataObject(0))
    f = vtkThiessenArealAverage()
    f.SetGaugesData(gauges_polydata(coords, ["a", "b", "c", "d", "e"], [1.0, 2.0, 3.0, 4.0, 5.0]))
    f.SetCatchmentData(catchment)
    f.Update(0)
    assert_that(projection_of(f) == expected, f"the record {projection_of(f)!r}, vtkGeographicProjection's {expected!r}")
    weights = weights_by_gauge(f.GetOutputDataObject(0))
    far = polygon([square])
    far.GetPoints().InsertNextPoint(30.0, 60.0, 0.0)
    lines = vtkCellArray()
    lines.InsertNextCell(2, [0, 4])
    far.SetLines(lines)
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetCatchmentData(far)
    f.Update(0)
    assert_that(projection_of(f) == expected and any("not polygons or closed polylines" in w for w in warnings),
                f"with an open polyline far off: {projection_of(f)!r}, {warnings}")
    fit.SetInputData(far)
    fit.Update()
    moved = projection_record(fit.GetOutputDataObject(0))
    assert_that(moved != expected, "vtkGeographicProjection's fit to every point moves with the polyline")
    again = vtkThiessenArealAverage()
    again.SetGaugesData(gauges_polydata(coords, ["a", "b", "c", "d", "e"], [1.0, 2.0, 3.0, 4.0, 5.0]))
    again.SetCatchmentData(catchment)
    again.SetProjectionRecord(projection_of(f))
    again.Update(0)
    assert_that(projection_of(again) == expected, f"the record given back: {projection_of(again)!r}")
    assert_that(weights_by_gauge(again.GetOutputDataObject(0)) == weights, "the same weights, bit for bit")


def test_an_enclave_given_as_a_hole_and_a_feature_of_its_own_is_in_the_catchment():
    # A basin with an enclave: the basin's feature has a hole, and the enclave is a feature of its
    # own (a block of its own, as vtkGDALVectorReader gives it) that fills the hole exactly. By the
    # even-odd rule the two rings cancel: the catchment is the basin's outline, with a warning
    # naming them (it was refused as a ring given twice).
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet

    coords = [(10.2, 45.1), (10.9, 45.3), (10.5, 45.8), (11.4, 45.6)]
    outline = [(10.0, 45.0), (11.5, 45.0), (11.5, 46.0), (10.0, 46.0)]
    hole = [(10.4, 45.3), (10.4, 45.7), (11.0, 45.7), (11.0, 45.3)]
    enclave = list(reversed(hole))[2:] + list(reversed(hole))[:2]
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, polygon([outline, hole]))
    blocks.SetBlock(1, polygon([enclave]))
    results = []
    for catchment in (polygon([outline]), blocks):
        f = vtkThiessenArealAverage()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        errors = messages_of(f)
        f.SetGaugesData(gauges_polydata(coords, ["a", "b", "c", "d"], [1.0, 2.0, 3.0, 4.0]))
        f.SetCatchmentData(catchment)
        f.Update(0)
        assert_that(not errors, f"errors: {errors}")
        results.append((summary_column(f, "ArealMean"), weights_by_gauge(f.GetOutputDataObject(0)), warnings))
    assert_that(results[1][:2] == results[0][:2], f"the enclave's basin: {results[1][:2]} against {results[0][:2]}")
    assert_that(len(results[1][2]) == 1 and "are filled exactly by a ring of their own" in results[1][2][0]
                and "block 0" in results[1][2][0] and "block 1" in results[1][2][0], f"the pair named: {results[1][2]}")


def test_window_cells_that_are_not_rings_are_reported():
    square = [(0, 0), (1, 0), (1, 1), (0, 1)]
    f = vtkThiessenArealAverage()
    messages = messages_of(f, "WarningEvent")
    f.SetGaugesData(gauges_polydata([(0.2, 0.2), (0.8, 0.8)], ["a", "b"], [1.0, 3.0]))
    f.SetCatchmentData(with_open_polyline(polygon([square])))
    f.Update(1)
    # (about 2: the projected bisector of the two gauges is not quite the square's diagonal)
    assert_close(summary_column(f, "ArealMean")[0], 2.0, 1e-3, "the square is the catchment")
    assert_that(len(messages) == 1 and "1 cell(s) of the catchment (input 1) are not polygons"
                in messages[0] and "cell 0" in messages[0], f"the polyline reported: {messages}")
    clip = vtkWindowClip()
    messages = messages_of(clip, "WarningEvent")
    clip.SetInputData(polygon([[(0.25, 0.25), (0.75, 0.25), (0.75, 0.75), (0.25, 0.75)]]))
    clip.SetWindowData(with_open_polyline(polygon([square])))
    clip.Update()
    assert_that(clip.GetOutput().GetNumberOfCells() == 1, "the tile clipped by the square")
    assert_that(len(messages) == 1 and "of the window (input 1)" in messages[0],
                f"the polyline reported: {messages}")


def dated_table(months, time_of):
    """{(year, month): {station: value}} as a long-format table: station_id, value, and the time
    columns that time_of(year, month) gives for each row ({name: text, int or float})."""
    kinds = {str: vtkStringArray, int: vtkIntArray, float: vtkDoubleArray}
    table = vtkTable()
    s, v = vtkStringArray(), vtkDoubleArray()
    s.SetName("station_id")
    v.SetName("value")
    columns = {}
    for (year, month), values in sorted(months.items()):
        for sid, value in values.items():
            s.InsertNextValue(sid)
            v.InsertNextValue(value)
            for name, item in time_of(year, month).items():
                if name not in columns:
                    columns[name] = kinds[type(item)]()
                    columns[name].SetName(name)
                columns[name].InsertNextValue(item)
    for column in (s, v, *columns.values()):
        table.AddColumn(column)
    return table


def timed_rows_table(rows):
    """A long-format table from (station, time, value) rows: text columns station_id and time (dates
    as text), a double column value."""
    table = vtkTable()
    s, t, v = vtkStringArray(), vtkStringArray(), vtkDoubleArray()
    for column, name in ((s, "station_id"), (t, "time"), (v, "value")):
        column.SetName(name)
        table.AddColumn(column)
    for station, time, value in rows:
        s.InsertNextValue(station)
        t.InsertNextValue(time)
        v.InsertNextValue(value)
    return table


def summary_of(coords, ids, ring, table, **settings):
    f = vtkThiessenArealAverage()
    messages = messages_of(f)
    f.SetGaugesData(gauges_polydata(coords, ids))
    f.SetCatchmentData(polygon([ring]))
    f.SetObservationsData(table)
    for name, value in settings.items():
        getattr(f, "Set" + name)(value)
    f.Update(1)
    return f, messages


def test_dates_and_year_month_columns_give_the_same_steps():
    coords, ids, ring, months = read_colorado()
    numeric, _ = summary_of(coords, ids, ring, observations_table(months))
    expected = {name: summary_column(numeric, name) for name in ("Time", "ArealMean", "StationsUsed")}
    date_of = {year + (month - 1) / 12: f"{year:04d}-{month:02d}" for year, month in months}
    dates = [date_of[t] for t in expected["Time"]]
    cases = {
        "YYYY-MM text": (lambda y, m: {"date": f"{y:04d}-{m:02d}"}, {"TimeColumn": "date"}),
        "YYYY-MM-01 text": (lambda y, m: {"date": f"{y:04d}-{m:02d}-01"}, {"TimeColumn": "date"}),
        "year and month": (lambda y, m: {"year": y, "month": m},
                           {"TimeColumn": "year", "MonthColumn": "month"}),
        "year and month as text": (lambda y, m: {"year": str(y), "month": f"{m:02d}"},
                                   {"TimeColumn": "year", "MonthColumn": "month"}),
    }
    for what, (time_of, settings) in cases.items():
        f, messages = summary_of(coords, ids, ring, dated_table(months, time_of), **settings)
        assert_that(not messages, f"{what}: {messages}")
        for name, values in expected.items():
            got = summary_column(f, name)
            assert_that(got == values, f"{what}: {name} {got} differs from the numeric times' {values}")
        steps = f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
        assert_that(list(steps) == expected["Time"], f"{what}: time steps advertised {steps}")
        # Each step's date beside its decimal year, in both tables (YYYY-MM: every step is a
        # month's start); the numeric times get none.
        assert_that(summary_column(f, "Date") == dates, f"{what}: Date {summary_column(f, 'Date')[:3]}")
        weights = f.GetOutputDataObject(2)
        weight_dates = [weights.GetColumnByName("Date").GetValue(r) for r in range(weights.GetNumberOfRows())]
        weight_times = [weights.GetColumnByName("Time").GetValue(r) for r in range(weights.GetNumberOfRows())]
        assert_that(weight_dates == [date_of[t] for t in weight_times], f"{what}: weights' dates")
    for table in (numeric.GetOutputDataObject(1), numeric.GetOutputDataObject(2)):
        assert_that(table.GetColumnByName("Date") is None, "numeric times got a Date column")


def test_dates_of_days_and_hours_are_written_as_given():
    """Hourly text times (24:00 the next day's 00:00) get their dates back at the finest resolution
    the series needs, each reading back to its step's time; a series with one plain-number time
    gets no Date column."""
    coords, ids, ring, months = read_colorado()
    first = dict(sorted(months.items())[:1])
    (_, values), = first.items()
    texts = ["1963-08-01", "1963-08-16 06:30", "1963-08-16 24:00", "1963-12-31 24:00"]
    expected = ["1963-08-01 00:00", "1963-08-16 06:30", "1963-08-17 00:00", "1964-01-01 00:00"]
    for times, dated in ((texts, True), (texts[:3] + ["1963.99"], False)):
        table = timed_rows_table([(str(sid), time, value) for time in times for sid, value in values.items()])
        f, messages = summary_of(coords, ids, ring, table)
        assert_that(not messages, f"{times}: {messages}")
        column = f.GetOutputDataObject(1).GetColumnByName("Date")
        if not dated:
            assert_that(column is None, "a series with a number among its times got dates")
            continue
        got = [column.GetValue(r) for r in range(column.GetNumberOfValues())]
        assert_that(got == expected, f"dates {got}, expected {expected}")
        # Each date, given as the time, is its own step again (the same decimal year).
        again, _ = summary_of(coords, ids, ring, table_with_times(table, got))
        assert_that(summary_column(again, "Time") == summary_column(f, "Time"),
                    f"{got} read back as {summary_column(again, 'Time')}")
    # Years outside 0 .. 9999 (a year column may hold -9999 .. 9999) have no date text: no column,
    # and a warning says why.
    def averaged_by_year_and_month(table):
        """The filter on table's year and month columns, updated; and its warnings."""
        f = vtkThiessenArealAverage()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetGaugesData(gauges_polydata(coords, ids))
        f.SetCatchmentData(polygon([ring]))
        f.SetObservationsData(table)
        f.SetTimeColumn("year")
        f.SetMonthColumn("month")
        f.Update(1)
        return f, warnings

    ancient = dated_table({(-1, 12): values, (0, 1): values}, lambda y, m: {"year": y, "month": m})
    f, warnings = averaged_by_year_and_month(ancient)
    assert_that(f.GetOutputDataObject(1).GetColumnByName("Date") is None, "a Date column for year -1")
    assert_that(any("the times are dates, but not all of them can be written as dates (years 0 .. 9999"
                    in w for w in warnings), f"{warnings}")
    assert_that(not any("the year 0" in w for w in warnings), f"years -1 and 0: no word of year 0 {warnings}")
    # A year 0 among years from 1963 (ParaView's CSV reader makes an empty year 0): its rows are
    # named, counted from 0 (the table's rows are sorted by year: the year 0's come first).
    empty_year = dated_table({(0, 1): values, (1963, 8): values, (1963, 9): values},
                             lambda y, m: {"year": y, "month": m})
    _, warnings = averaged_by_year_and_month(empty_year)
    said = [w for w in warnings if "the year 0" in w]
    assert_that(len(said) == 1 and f"): {len(values)} observation row(s) have the year 0 in column 'year', where the "
                                   "record's other years start at 1963" in said[0]
                and "they make 1 step(s) of their own (rows from 0): row 0 (station " in said[0], f"{warnings}")


def test_dates_of_different_periods_are_warned_of():
    """A month (or year) among days takes its period's start, and so shares a step with the values of
    its first day: a monthly total among daily values was averaged with them without a word. One
    warning names the first date of the coarsest and of the finest period; days beside times of day
    (midnight written as the date alone) give none."""
    coords, ids = [(10.25, 50.5), (10.75, 50.5), (10.5, 50.9)], ["A", "B", "C"]
    ring = [(10.0, 50.0), (11.0, 50.0), (11.0, 51.0), (10.0, 51.0)]
    cases = (
        (["2020-01-31", "2020-02-01 12:00", " 2020-03 ", "2020"], 4,
         "column 'time' gives dates of different periods (row 3's '2020' a year, row 2's '2020-03' a month, "
         "row 0's '2020-01-31' a day): each date is taken as its period's start (a month as its first day at "
         "00:00, a year as 1 January), so a value for a year shares a step with the values of its first day"),
        (["2020-02", "2020-03", "2020-03-01T00:00"], 2,  # (2020-03 is 2020-03-01's step)
         "(row 0's '2020-02' a month, row 2's '2020-03-01T00:00' a day): each date is taken as its period's start"),
        (["2019", "2020-03"], 2, "(row 0's '2019' a year, row 1's '2020-03' a month): each date"),
        (["2020-03-01", "2020-03-01 06:00", "2020-03-02"], 3, None),
        # (a time zone's hyphen is no date's: it follows a time of day)
        (["2020-03-01 10:00-05:00", "2020-03-01T11:00-05:00", "2020-03-02 00:00-0500"], 3, None),
        (["2020-01", "2020-02"], 2, None))
    for dates, steps, expected in cases:
        table = timed_rows_table([(ids[k % 3], date, float(k)) for k, date in enumerate(dates)])
        f = vtkThiessenArealAverage()
        errors, warnings = messages_of(f), messages_of(f, vtkCommand.WarningEvent)
        f.SetGaugesData(gauges_polydata(coords, ids))
        f.SetCatchmentData(polygon([ring]))
        f.SetObservationsData(table)
        f.Update(1)
        said = [w for w in warnings if "different periods" in w]
        assert_that(not errors and f.GetOutputDataObject(1).GetNumberOfRows() == steps,
                    f"{dates}: {errors}, {f.GetOutputDataObject(1).GetNumberOfRows()} steps")
        if expected is None:
            assert_that(not said, f"{dates}: {said}")
        else:
            assert_that(len(said) == 1 and expected in said[0], f"{dates}: {said}")


def test_time_of_date_picks_that_dates_step():
    """TimeOfDate gives a date's time as the tables do (decimal years on a month grid: a day is a
    share of its month), so UpdateTimeStep of it shows that day's tiles; a day-of-year decimal, the
    usual other reading, would show an earlier day. Text that is not a date gives NaN."""
    time_of = vtkThiessenArealAverage.TimeOfDate
    for text, expected in (("1963-08", 1963 + 7 / 12), ("1963-08-16", 1963 + (7 + 15 / 31) / 12),
                           ("1964-02-29", 1964 + (1 + 28 / 29) / 12),
                           ("1963-08-16 06:00", 1963 + (7 + (15 + 6 / 24) / 31) / 12)):
        assert_close(time_of(text), expected, 1e-12, f"TimeOfDate({text!r})")
    for text in ("1963-02-30", "1963-13", "16/08/1963", "", None):
        assert_that(math.isnan(time_of(text)), f"TimeOfDate({text!r}) = {time_of(text)}, expected NaN")
    # Three gauges over a month's turn, a day apart, each day its own values.
    coords = [(-0.5, -0.5), (0.5, -0.5), (0.0, 0.5)]
    ids = ["a", "b", "c"]
    days = ["2001-02-27", "2001-02-28", "2001-03-01", "2001-03-02"]
    table = timed_rows_table([(sid, day, 10.0 * d + g) for d, day in enumerate(days) for g, sid in enumerate(ids)])
    f, messages = summary_of(coords, ids, [(-1, -1), (1, -1), (1, 1), (-1, 1)], table)
    assert_that(not messages, f"{messages}")
    dates, times = summary_column(f, "Date"), summary_column(f, "Time")
    assert_that(dates == days, f"dates {dates}")
    for d, day in enumerate(days):
        assert_that(time_of(day) == times[d], f"TimeOfDate({day!r}) {time_of(day)} is not its Time {times[d]}")
        f.UpdateTimeStep(time_of(day))
        tiles = f.GetOutputDataObject(0)
        shown = tiles.GetInformation().Get(tiles.DATA_TIME_STEP())
        values = tiles.GetCellData().GetArray("Value")
        got = sorted({values.GetValue(c) for c in range(values.GetNumberOfValues())})
        assert_that(shown == times[d] and got == [10.0 * d + g for g in range(3)],
                    f"{day}: the tiles of time {shown}, values {got}")
    # The day of year as a share of the year puts 2001-03-01 (day 60) before its step: an earlier
    # day's tiles, the last at or before that time.
    day_of_year = 2001 + 59 / 365
    f.UpdateTimeStep(day_of_year)
    tiles = f.GetOutputDataObject(0)
    shown = tiles.GetInformation().Get(tiles.DATA_TIME_STEP())
    assert_that(shown < times[2] and shown == max(x for x in times if x <= day_of_year),
                f"a day-of-year time for {days[2]} gave the step of time {shown} ({times})")


def table_with_times(table, dates):
    """table with its time column's distinct texts replaced, in order, by dates."""
    times = table.GetColumnByName("time")
    distinct = sorted({times.GetValue(r) for r in range(times.GetNumberOfValues())})
    new = vtkTable()
    new.DeepCopy(table)
    column = new.GetColumnByName("time")
    for r in range(column.GetNumberOfValues()):
        column.SetValue(r, dates[distinct.index(column.GetValue(r))])
    return new


def test_the_monthly_csv_as_a_text_reader_gives_it():
    # What ParaView's CSV reader hands the filter: year and month as numbers, no time column.
    coords, ids, ring, months = read_colorado()
    reader = vtkDelimitedTextReader()
    reader.SetFileName(os.path.join(EXAMPLE_DATA, "colorado_monthly_precip.csv"))
    reader.SetHaveHeaders(True)
    reader.SetDetectNumericColumns(True)
    reader.Update()
    f, messages = summary_of(coords, ids, ring, reader.GetOutput(), TimeColumn="year",
                             MonthColumn="month", ValueColumn="precip")
    assert_that(not messages, f"errors: {messages}")
    times, means = summary_column(f, "Time"), summary_column(f, "ArealMean")
    assert_that(len(times) == 1236, f"{len(times)} monthly steps, expected 1236")
    numeric, _ = summary_of(coords, ids, ring, observations_table(months))
    for t, mean in zip(summary_column(numeric, "Time"), summary_column(numeric, "ArealMean")):
        k = times.index(t)
        assert_close(means[k], mean, 1e-12 * abs(mean), f"month {t}: the whole CSV against 3 months")
    # Month Column left empty (in ParaView a text box beside drop-downs): years as the steps, each
    # station's January used and the other months set aside as repeats. A warning says why and
    # names the column to set; there is none with the months given.
    for month_column in ("", "month"):
        f = vtkThiessenArealAverage()
        warnings = messages_of(f, "WarningEvent")
        f.SetGaugesData(gauges_polydata(coords, ids))
        f.SetCatchmentData(polygon([ring]))
        f.SetObservationsData(reader.GetOutput())
        f.SetTimeColumn("year")
        f.SetMonthColumn(month_column)
        f.SetValueColumn("precip")
        f.Update(1)
        coarse = [w for w in warnings if "observation rows repeat a station and time" in w]
        rows = reader.GetOutput().GetNumberOfRows()
        repeats = f.GetOutputDataObject(1).GetFieldData().GetArray("RepeatedObservationRows").GetNumberOfTuples()
        if month_column:
            assert_that(coarse == [] and repeats == 0, f"with the months: {coarse}, {repeats} repeats")
        else:
            # Counted apart: the rows (each with a value, as the numeric reader reads empty ones)
            # beyond the first of each station and year.
            with open(os.path.join(EXAMPLE_DATA, "colorado_monthly_precip.csv")) as csv_file:
                firsts = {(r["station_id"].lstrip("0"), r["year"]) for r in csv.DictReader(csv_file)}
            assert_that(repeats == rows - len(firsts) and 2 * repeats > rows, f"{repeats} repeats of {rows} rows, "
                        f"{len(firsts)} stations and years")
            assert_that(len(coarse) == 1 and f"{repeats} of the {rows} observation rows" in coarse[0]
                        and "set MonthColumn to 'month'" in coarse[0], f"without the months: {warnings}")


def test_blank_values_read_as_text_are_missing():
    """ParaView's CSV reader makes an empty field of a numeric column 0; with Detect Numeric
    Columns off (what the README advises for blank missing values) the columns stay text and the
    filter reads a blank value as missing. Each month's mean and StationsUsed must then equal those
    of the same table without the blank rows, read as numbers."""
    coords, ids, ring, months = read_colorado()
    blanked = {}
    lines = ["station_id,year,month,precip\n"]
    for (year, month), values in sorted(months.items()):
        kept = {}
        for k, (sid, value) in enumerate(sorted(values.items())):
            blank = k % 3 == 0
            lines.append(f"{sid},{year},{month},{'' if blank else repr(value)}\n")
            if not blank:
                kept[sid] = value
        blanked[(year, month)] = kept
    table = csv_reader_table("".join(lines), detect_numeric=False)
    f, messages = summary_of(coords, ids, ring, table, TimeColumn="year",
                             MonthColumn="month", ValueColumn="precip")
    assert_that(not messages, f"errors: {messages}")
    numeric, _ = summary_of(coords, ids, ring, observations_table(blanked))
    for name in ("Time", "StationsUsed", "StationsWeighted"):
        got, want = summary_column(f, name), summary_column(numeric, name)
        assert_that(all(abs(a - b) < 1e-9 for a, b in zip(got, want)) and len(got) == len(want),
                    f"{name}: {got} against the table without blanks {want}")
    for got, want in zip(summary_column(f, "ArealMean"), summary_column(numeric, "ArealMean")):
        assert_close(got, want, 1e-12 * abs(want), "areal mean with blanks as missing")


def test_a_missing_value_code_is_missing_when_set_and_named_when_not():
    """Many gauge records write -9999 where a value is missing. Averaged as a measurement, one such
    value made a mean of -2548 without a word. With UseMissingValue on (MissingValue -9999) every
    month's mean and StationsUsed must equal those of the table without those rows; left off, a
    warning must count them and name the first row. The same for the gauges' own value array."""
    coords, ids, ring, months = read_colorado()
    coded, kept_months = {}, {}
    for (year, month), values in sorted(months.items()):
        coded[(year, month)] = {sid: (-9999.0 if k % 4 == 1 else v)
                                for k, (sid, v) in enumerate(sorted(values.items()))}
        kept_months[(year, month)] = {sid: v for sid, v in coded[(year, month)].items() if v != -9999.0}
    # and one 9999, a second code, named too (only the code met most often was named)
    last = coded[max(coded)]
    nines = next(sid for sid, v in sorted(last.items()) if v != -9999.0)
    last[nines] = kept_months[max(coded)][nines] = 9999.0
    count = sum(v == -9999.0 for values in coded.values() for v in values.values())
    without, _ = summary_of(coords, ids, ring, observations_table(kept_months))
    used, messages = summary_of(coords, ids, ring, observations_table(coded),
                                UseMissingValue=True, MissingValue=-9999.0)
    assert_that(not messages, f"errors: {messages}")
    for name in ("Time", "StationsUsed", "StationsWeighted", "ArealMean"):
        got, want = summary_column(used, name), summary_column(without, name)
        assert_that(len(got) == len(want) and all(
            abs(a - b) <= 1e-12 * max(1.0, abs(b)) for a, b in zip(got, want)),
            f"{name} with -9999 as missing differs from the table without those rows")
    f = vtkThiessenArealAverage()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges_polydata(coords, ids))
    f.SetCatchmentData(polygon([ring]))
    f.SetObservationsData(observations_table(coded))
    f.Update(1)
    first_sid = sorted(months[min(months)].items())[1][0]
    said = [w for w in warnings if "a common missing-value code" in w]
    assert_that(len(said) == 1 and f"{count} observation value(s) are exactly -9999" in said[0]
                and f"(the first in row 1, station {first_sid})" in said[0]
                and "; 1 exactly 9999, another (the first in row " in said[0]
                and f", station {nines})" in said[0]
                and "if one of these codes marks missing values, turn UseMissingValue on with MissingValue set to it"
                in said[0], f"warnings: {warnings}")
    assert_that(min(summary_column(f, "ArealMean")) < -100, "left off, -9999 is averaged as a value")
    # Without observations: the gauges' value array, one step.
    values = [2.0] * len(coords)
    values[3] = 9999.0
    for use in (False, True):
        g = vtkThiessenArealAverage()
        warned = messages_of(g, vtkCommand.WarningEvent)
        g.SetGaugesData(gauges_polydata(coords, ids, values))
        g.SetCatchmentData(polygon([ring]))
        g.SetUseMissingValue(use)
        g.SetMissingValue(9999.0)
        g.Update(1)
        mean = summary_column(g, "ArealMean")[0]
        coded_said = [w for w in warned if "exactly 9999" in w]
        if use:
            assert_close(mean, 2.0, 1e-12, "the gauge at 9999 is missing")
            assert_that(not coded_said, f"no warning when it is used: {warned}")
        else:
            assert_that(len(coded_said) == 1 and f"of gauge 3 ({ids[3]})" in coded_said[0],
                        f"warnings: {warned}")
    # With another code used (-999), the 9999 left is still named, and the advice is not to switch
    # codes (that made the -999s measurements again: MissingValue takes one); 0 and NaN are no codes.
    for missing, said in ((-999.0, "exactly 9999, a common missing-value code, and averaged as measured values "
                           f"(the first of gauge 3 ({ids[3]})): MissingValue takes one code, and -999 is in use; if "
                           "these values are missing too, write them as NaN (or as -999)"),
                          (0.0, "MissingValue 0 would make every zero value"),
                          (math.nan, "MissingValue nan changes nothing")):
        g = vtkThiessenArealAverage()
        warned, errors = messages_of(g, vtkCommand.WarningEvent), messages_of(g)
        g.SetGaugesData(gauges_polydata(coords, ids, values))
        g.SetCatchmentData(polygon([ring]))
        g.SetUseMissingValue(True)
        g.SetMissingValue(missing)
        g.Update(1)
        assert_that(any(said in m for m in warned + errors), f"MissingValue {missing}: {warned} {errors}")


def test_bad_dates_and_months_are_named():
    coords, ids, ring, months = read_colorado()
    one = {(1963, 8): months[(1963, 8)]}
    cases = [
        (lambda y, m: {"date": "1963-13"}, {"TimeColumn": "date"},
         ["observation row 0", "'1963-13'", "column 'date'", "is not a date"]),
        (lambda y, m: {"year": y, "month": 0}, {"TimeColumn": "year", "MonthColumn": "month"},
         ["observation row 0", "month 0", "column 'month'", "1 .. 12"]),
        (lambda y, m: {"year": y}, {"TimeColumn": "year", "MonthColumn": "month"},
         ["no column 'month'"]),
        (lambda y, m: {"date": "1963-08"}, {"TimeColumn": "time"}, ["no column 'time'"]),
    ]
    # A table without rows (a CSV file of a header only).
    cases.append((lambda y, m: {"time": 1963}, {}, ["the observations table has no rows"]))
    for time_of, settings, fragments in cases:
        rows = {(1963, 8): {}} if "no rows" in fragments[0] else one
        f, messages = summary_of(coords, ids, ring, dated_table(rows, time_of), **settings)
        assert_that(messages and all(x in messages[0] for x in fragments),
                    f"{settings}: expected {fragments} in {messages}")
        assert_that(f.GetOutputDataObject(1).GetNumberOfRows() == 0, f"{settings}: output not empty")


def test_columns_of_different_lengths_are_named():
    # From an error audit: the table's rows are its first column's; a shorter column was read past
    # its end (a mean of 1.8e150, made-up times, a crash for text), a longer one cut short silently.
    coords, ids, ring, months = read_colorado()
    rows = {key: months[key] for key in ((1963, 8), (1990, 7))}
    count = sum(len(values) for values in rows.values())
    for column, length, numeric in (("value", 5, True), ("date", count - 3, False), ("value", count + 4, True),
                                    ("station_id", 5, False), ("date", count + 1, False)):
        table = dated_table(rows, lambda y, m: {"date": f"{y}-{m:02d}"})
        table.GetColumnByName(column).SetNumberOfValues(length)
        if length > count:  # (the new values set, so that only the length is wrong)
            for k in range(count, length):
                table.GetColumnByName(column).SetValue(k, 1.0 if numeric else "1963-08")
        first = "station_id"
        expected = (f"the observations table's columns differ in length: column '{column}' has {length} value(s), "
                    f"the first column, '{first}', {count}") if column != first else (
            f"the observations table's columns differ in length: column 'value' has {count} value(s), "
            f"the first column, '{first}', {length}")
        f, messages = summary_of(coords, ids, ring, table, TimeColumn="date")
        assert_that(len(messages) == 1 and expected in messages[0], f"{column} of {length}: {messages}")
        assert_that(f.GetOutputDataObject(1).GetNumberOfRows() == 0, f"{column} of {length}: output not empty")



def test_columns_not_yet_set_give_no_error_until_the_update():
    """ParaView asks for the pipeline information as soon as the filter is made, before its
    columns are set: that gives no error and no time step. The update then names the missing
    column, the property that names it and the columns the table has; the right names work."""
    coords = [(0.25, 0.5), (0.75, 0.5)]
    f = vtkThiessenArealAverage()
    messages = messages_of(f)
    f.SetGaugesData(gauges_polydata(coords, ["a", "b"]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    f.SetObservationsData(text_table([("a", "2000-01", "2"), ("b", "2000-01", "4")]))
    f.UpdateInformation()
    steps = f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    assert_that(not messages and not steps, f"information with the default columns: {messages}, {steps}")
    f.Update(1)
    assert_that(len(messages) == 1 and "no column 'time' (TimeColumn:" in messages[0]
                and "its columns are station_id, date, value" in messages[0],
                f"the update with the default time column: {messages}")
    assert_that(output_sizes(f) == (0, 0, 0, 0), f"outputs after the error: {output_sizes(f)}")
    messages.clear()
    f.SetTimeColumn("date")
    f.SetValueColumn("precip")
    f.Update(1)
    assert_that(len(messages) == 1 and "no column 'precip' (ValueColumn:" in messages[0],
                f"a value column the table lacks: {messages}")
    messages.clear()
    f.SetValueColumn("value")
    f.Update(1)
    assert_that(not messages and summary_column(f, "ArealMean") == [3.0],
                f"the right columns: {messages}, {summary_column(f, 'ArealMean')}")


def text_table(rows):
    """A table of text columns station_id, date, value from (station, date, value) rows: what a
    CSV reader gives when missing-value markers stand among the numbers."""
    table = vtkTable()
    columns = [vtkStringArray() for _ in range(3)]
    for column, name in zip(columns, ("station_id", "date", "value")):
        column.SetName(name)
        table.AddColumn(column)
    for row in rows:
        for column, item in zip(columns, row):
            column.InsertNextValue(item)
    return table


def test_text_values_with_missing_markers():
    coords = [(0.25, 0.5), (0.75, 0.5)]
    square = [[(0, 0), (1, 0), (1, 1), (0, 1)]]
    rows = [("a", "2000-01", " 2.0"), ("b", "2000-01", "4"), ("a", "2000-02", "NA"),
            ("b", "2000-02", "6.5"), ("a", "2000-03", ""), ("b", "2000-03", "n/a"),
            ("a", "2000-04", "null"), ("b", "2000-04", "NaN")]
    f = vtkThiessenArealAverage()
    messages = messages_of(f)
    f.SetGaugesData(gauges_polydata(coords, ["a", "b"]))
    f.SetCatchmentData(polygon(square))
    f.SetObservationsData(text_table(rows))
    f.SetTimeColumn("date")
    f.Update(1)
    assert_that(not messages, f"errors: {messages}")
    means = summary_column(f, "ArealMean")
    used = summary_column(f, "StationsUsed")
    assert_that(used == [2, 1, 0, 0], f"gauges reporting with markers as missing: {used}")
    assert_close(means[0], 3.0, 1e-12, "two halves of the square")
    assert_that(means[1] == 6.5 and math.isnan(means[2]) and math.isnan(means[3]),
                f"areal means {means}")
    f.SetObservationsData(text_table(rows + [("b", "2000-05", "1,5")]))
    f.Update(1)
    assert_that(messages and "observation row 8" in messages[-1] and "'1,5'" in messages[-1]
                and "column 'value'" in messages[-1] and "not a number" in messages[-1]
                and "a decimal comma is not read here" in messages[-1],
                f"a value that is not a number: {messages}")
    # The decimal-comma hint only for digits, one comma, digits.
    for text, hinted in (("-12,25 ", True), ("\t12,5\t", True), ("1,5,5", False), (",5", False), ("1,", False), ("1.2,5", False),
                         ("a,5", False)):
        f.SetObservationsData(text_table(rows + [("b", "2000-05", text)]))
        f.Update(1)
        assert_that(f"'{text}'" in messages[-1] and ("decimal comma" in messages[-1]) == hinted,
                    f"{text!r}: {messages[-1]}")


def output_sizes(f):
    """(cells of output 0, rows of output 1, rows of output 2, advertised time steps)."""
    steps = f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    return (f.GetOutputDataObject(0).GetNumberOfCells(), f.GetOutputDataObject(1).GetNumberOfRows(),
            f.GetOutputDataObject(2).GetNumberOfRows(), len(steps) if steps else 0)


def test_a_failed_update_leaves_no_earlier_result():
    # A good run, then a table whose times cannot be read (RequestInformation fails, so RequestData
    # does not run): whichever port the update asks for, no output keeps the good run's tiles,
    # means or weights, and a good table afterwards gives them again.
    coords = [(0.25, 0.5), (0.75, 0.5)]
    good = [("a", "2000-01", "2"), ("b", "2000-01", "4"), ("a", "2000-02", "1")]
    bad = [("a", "2000-01", "2"), ("b", "2000-13", "4")]
    f = vtkThiessenArealAverage()
    messages = messages_of(f)
    f.SetGaugesData(gauges_polydata(coords, ["a", "b"]))
    f.SetCatchmentData(polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]]))
    f.SetTimeColumn("date")
    for port in range(3):
        f.SetObservationsData(text_table(good))
        for p in range(3):
            f.Update(p)
        sizes = output_sizes(f)
        assert_that(not messages, f"errors on a good table: {messages}")
        assert_that(sizes == (2, 2, 3, 2) and f.GetNumberOfTimeSteps() == 2,
                    f"good table: outputs {sizes}, {f.GetNumberOfTimeSteps()} steps")
        f.SetObservationsData(text_table(bad))
        f.Update(port)
        sizes = output_sizes(f)
        assert_that(len(messages) == 1 and "'2000-13'" in messages[0], f"the bad table's error: {messages}")
        assert_that(sizes == (0, 0, 0, 0) and f.GetNumberOfTimeSteps() == 0,
                    f"after the failure (update of port {port}): outputs {sizes}, "
                    f"{f.GetNumberOfTimeSteps()} steps")
        messages.clear()

def test_review_cases_of_gauges_and_errors():
    """Four review findings. (1) A station id array longer than the gauges is an error giving the
    counts (it was read past the gauges' values). (2) A station id changed in place, with only the
    gauges marked modified, is matched afresh: its rows make their time step again. (3) After an
    error found while averaging (a NaN gauge), no time step stays advertised. (4) Errors name a
    gauge by its station id as written, leading zeros and all."""
    square = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    coords = [(0.25, 0.5), (0.75, 0.5)]
    rows = [("A", "2000-01", "2"), ("B", "2000-01", "4"), ("C", "2000-02", "1")]

    def filter_of(gauges):
        f = vtkThiessenArealAverage()
        messages = messages_of(f)
        f.SetGaugesData(gauges)
        f.SetCatchmentData(square)
        f.SetTimeColumn("date")
        f.SetObservationsData(text_table(rows))
        return f, messages

    longer = gauges_polydata(coords, ["A", "B"])
    longer.GetPointData().GetAbstractArray("station_id").InsertNextValue("C")
    f, messages = filter_of(longer)
    f.Update(1)
    assert_that(len(messages) == 1 and "has 3 values for 2 gauges" in messages[0],
                f"(1) a longer id array: {messages}")

    gauges = gauges_polydata(coords, ["A", "B"])
    f, messages = filter_of(gauges)
    f.Update(1)
    before = summary_column(f, "Time")
    gauges.GetPointData().GetAbstractArray("station_id").SetValue(1, "C")
    gauges.Modified()
    f.Update(1)
    after = summary_column(f, "Time")
    assert_that(not messages and len(before) == 1 and len(after) == 2,
                f"(2) steps {before} then {after} after B became C: {messages}")

    def advertised(f):  # (output 0, the tiles, carries the steps)
        steps = vtkStreamingDemandDrivenPipeline.TIME_STEPS()
        return [f.GetOutputInformation(p).Has(steps) for p in range(3)]

    assert_that(advertised(f)[0], "(3) steps advertised after a good run")
    gauges.GetPoints().SetPoint(1, float("nan"), 0.5, 0.0)
    gauges.Modified()
    f.Update(1)
    assert_that(len(messages) == 1 and "gauge 1 (station C)" in messages[0],
                f"(4) a NaN gauge named by its id: {messages}")
    assert_that(not any(advertised(f)), f"(3) after the error: {advertised(f)}")

    f, messages = filter_of(gauges_polydata(coords, ["050109", "050110"]))
    f.SetObservationsData(text_table([("050109", "2000-01", "2"), ("050110", "2000-01", "inf")]))
    f.Update(1)
    assert_that(len(messages) == 1 and "station 050110" in messages[0],
                f"(4) a row named by the id as written: {messages}")


def written_csv(text):
    """A temporary CSV file holding text; returns its path (removed at exit)."""
    import atexit
    import tempfile

    handle, path = tempfile.mkstemp(suffix=".csv")
    with os.fdopen(handle, "w") as f:
        f.write(text)
    atexit.register(os.remove, path)
    return path


def csv_reader_table(text, detect_numeric=True):
    """The table VTK's CSV reader gives for text (by default numeric columns detected, as ParaView
    does; detect_numeric=False leaves every column text)."""
    reader = vtkDelimitedTextReader()
    reader.SetFileName(written_csv(text))
    reader.SetHaveHeaders(True)
    reader.SetDetectNumericColumns(detect_numeric)
    reader.Update()
    return reader.GetOutput()


def usable_rows(text, gauge_ids, time_of):
    """Independently of the filter: (rows used, rows not used) of the CSV text (rows from 0), a
    row being used when its station (trimmed) is a gauge's id and its time field is not blank;
    time_of gives the step time of a used row's fields."""
    used, unused = {}, []
    for r, row in enumerate(csv.DictReader(text.splitlines())):
        station = (row["station_id"] or "").strip()
        if station in gauge_ids and all((row[c] or "").strip() for c in row if c not in ("station_id", "value")):
            used[r] = time_of(row)
        else:
            unused.append(r)
    return used, unused


def field_ids(f, name):
    array = f.GetOutputDataObject(1).GetFieldData().GetArray(name)
    return [array.GetValue(i) for i in range(array.GetNumberOfTuples())] if array else None


def test_rows_that_cannot_be_used_make_no_step_and_are_listed():
    coords, square = [(0.25, 0.5), (0.75, 0.5)], [[(0, 0), (1, 0), (1, 1), (0, 1)]]
    # Numeric columns: the reader turns the blank last line into station 0, time 0, value 0.
    numeric = "station_id,time,value\n1,2000.0,1.0\n2,2000.0,3.0\n1,2000.5,2.0\n99,2001.0,5.0\n,,\n"
    # Text columns: dates, a blank station, a row without a time, a station no gauge has.
    dated = ("station_id,date,value\nA,2000-01,1\nB,2000-01,3\nA,2000-02,2\nC,2000-03,5\n,,\n"
             "  ,2000-04,1\nA,,2\n")
    cases = [
        (numeric, ["1", "2"], {}, lambda row: float(row["time"]), ["99 (1 row: row 3)", "0 (1 row: row 4)"]),
        (dated, ["A", "B"], {"TimeColumn": "date"},
         lambda row: int(row["date"][:4]) + (int(row["date"][5:7]) - 1) / 12,
         ["C (1 row: row 3)", "row 4 (no station id)", "row 5 (no station id)",
          "row 6 (station A: no time)"]),
    ]
    for text, ids, settings, time_of, named in cases:
        used, unused = usable_rows(text, set(ids), time_of)
        f = vtkThiessenArealAverage()
        errors, warnings = messages_of(f), messages_of(f, vtkCommand.WarningEvent)
        f.SetGaugesData(gauges_polydata(coords, ids))
        f.SetCatchmentData(polygon(square))
        f.SetObservationsData(csv_reader_table(text))
        for name, value in settings.items():
            getattr(f, "Set" + name)(value)
        f.Update(1)
        assert_that(not errors, f"errors: {errors}")
        expected = sorted(set(used.values()))
        times = summary_column(f, "Time")
        assert_that(times == expected, f"steps {times}, the used rows' times are {expected}")
        steps = f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
        assert_that(list(steps) == expected, f"advertised steps {steps}")
        assert_that(summary_column(f, "StationsUsed") == [sum(1 for t in used.values() if t == step) for step in expected],
                    f"StationsUsed {summary_column(f, 'StationsUsed')}")
        assert_that(field_ids(f, "UnusedObservationRows") == unused,
                    f"UnusedObservationRows {field_ids(f, 'UnusedObservationRows')}, expected {unused}")
        for fragment in named:
            assert_that(any(fragment in w for w in warnings), f"{fragment!r} not reported: {warnings}")
    # No usable row at all: an error that says why, and empty outputs.
    f = vtkThiessenArealAverage()
    errors = messages_of(f)
    f.SetGaugesData(gauges_polydata(coords, ["A", "B"]))
    f.SetCatchmentData(polygon(square))
    f.SetObservationsData(csv_reader_table("station_id,date,value\nC,2000-03,5\n,,\n"))
    f.SetTimeColumn("date")
    f.Update(1)
    assert_that(len(errors) == 1 and "none of the 2 observation rows can be used" in errors[0]
                and "1 have no station id or no time" in errors[0] and "C (1 row: row 0)" in errors[0],
                f"no usable row: {errors}")
    assert_that(f.GetOutputDataObject(1).GetNumberOfRows() == 0, "no usable row: output 1 not empty")
    # Gauges without points (the output of an upstream filter that failed or kept none) are named
    # as the cause, with and without their station id array.
    for empty, fragment in ((gauges_polydata([], []), "so none of the 1 observation rows can be used"),
                            (vtkPolyData(), "and no point-data array 'station_id'")):
        f = vtkThiessenArealAverage()
        errors = messages_of(f)
        f.SetGaugesData(empty)
        f.SetCatchmentData(polygon(square))
        f.SetObservationsData(csv_reader_table("station_id,date,value\nA,2000-03,5\n"))
        f.SetTimeColumn("date")
        f.Update(1)
        assert_that(len(errors) == 1 and errors[0].count("the gauges input has no points (does the filter before it "
                                                         "give none?)") == 1 and fragment in errors[0],
                    f"no gauges: {errors}")
    # Without observations too: the missing value array is not the cause (it was "the gauges need a
    # numeric point-data array 'value'; their arrays are none").
    f = vtkThiessenArealAverage()
    errors = messages_of(f)
    f.SetGaugesData(vtkPolyData())
    f.SetCatchmentData(polygon(square))
    f.Update(1)
    assert_that(len(errors) == 1 and errors[0].count("the gauges input has no points (does the filter before it "
                                                     "give none?): no gauge, no value array 'value'") == 1,
                f"no gauges, no observations: {errors}")
    # With an empty value array (an upstream Threshold that kept no gauge leaves one) too.
    f = vtkThiessenArealAverage()
    errors = messages_of(f)
    f.SetGaugesData(gauges_polydata([], [], []))
    f.SetCatchmentData(polygon(square))
    f.Update(1)
    assert_that(len(errors) == 1 and "the gauges input has no points (does the filter before it give none?): no "
                "gauge to average" in errors[0], f"no gauges, an empty value array: {errors}")


def ellipsoidal_area(ring):
    """Signed area (m^2, anticlockwise positive) on WGS84 of a lon/lat ring whose edges are straight
    in longitude and latitude, independently of the filter: A = -closed integral of F(lat) dlon,
    F the integral of the area element M N cos(lat) over latitude (Snyder's q times a^2 / 2),
    each edge by 20-point Gauss-Legendre."""
    a, f = 6378137.0, 1 / 298.257223563
    e2 = f * (2 - f)
    e = math.sqrt(e2)

    def F(lat):
        s = np.sin(lat)
        return a * a * (1 - e2) / 2 * (s / (1 - e2 * s * s) + np.log((1 + e * s) / (1 - e * s)) / (2 * e))

    nodes, weights = np.polynomial.legendre.leggauss(20)
    t = (nodes + 1) / 2
    total = 0.0
    for (lon1, lat1), (lon2, lat2) in zip(ring, ring[1:] + ring[:1]):
        lats = np.radians(lat1 + t * (lat2 - lat1))
        total -= math.radians(lon2 - lon1) * float(np.sum(weights / 2 * F(lats)))
    return total


def test_tiles_of_a_catchment_with_a_hole_or_a_bay():
    # A lake inside the tile of the gauge standing in it; a bay whose mouth a gauge's tile spans, so
    # that the tile meets both shores. Output 0 must show each tile's part of the catchment as
    # simple polygons: nothing over the lake or the bay, no cell over another, cell areas adding up
    # to the catchment, and the weights read per station.
    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    lake = [(0.35, 0.35), (0.35, 0.65), (0.65, 0.65), (0.65, 0.35)]  # clockwise: a hole
    bay = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.6, 1.0), (0.6, 0.3), (0.4, 0.3), (0.4, 1.0), (0.0, 1.0)]
    cases = [("lake", [square, lake], [(0.5, 0.5), (0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)], (0.5, 0.5)),
             ("bay", [bay], [(0.5, 0.9), (0.5, 0.1), (0.1, 0.5), (0.9, 0.5)], (0.5, 0.8))]
    for name, rings, coords, outside in cases:
        f = vtkThiessenArealAverage()
        errors = messages_of(f)
        ids = [f"{name}{k}" for k in range(len(coords))]
        f.SetGaugesData(gauges_polydata(coords, ids, [float(k + 1) for k in range(len(coords))]))
        f.SetCatchmentData(polygon(rings))
        f.Update(0)
        assert_that(not errors, f"{name}: {errors}")
        tiles = f.GetOutputDataObject(0)
        cd = tiles.GetCellData()
        column = {n: [cd.GetAbstractArray(n).GetValue(c) for c in range(tiles.GetNumberOfCells())]
                  for n in ("StationId", "Weight", "Area_m2", "CellArea_m2", "CellWeight")}
        catchment_area = sum(abs(ellipsoidal_area(r)) * (1 if k == 0 else -1) for k, r in enumerate(rings))
        assert_close(math.fsum(column["CellArea_m2"]), catchment_area, 1e-9 * catchment_area,
                     f"{name}: cell areas against the catchment's")
        assert_close(math.fsum(column["CellWeight"]), 1.0, 1e-12, f"{name}: cell weights sum")
        per_station = {}
        for sid, weight, area, cell_area in zip(column["StationId"], column["Weight"], column["Area_m2"],
                                                column["CellArea_m2"]):
            entry = per_station.setdefault(sid, {"weight": weight, "area": area, "cells": 0.0})
            assert_that(entry["weight"] == weight and entry["area"] == area,
                        f"{name}: station {sid}'s cells disagree on its Weight or Area_m2")
            entry["cells"] += cell_area
        assert_close(math.fsum(e["weight"] for e in per_station.values()), 1.0, 1e-12,
                     f"{name}: weights per station sum")
        for sid, e in per_station.items():
            assert_close(e["cells"], e["area"], 1e-9 * e["area"], f"{name}: station {sid}'s cells against its Area_m2")
        cells = cell_rings(tiles)
        assert_that(all(simplicity_defect(ring) is None for ring in cells),
                    f"{name}: a cell is not a simple polygon")
        paths = [Path(ring) for ring in cells]
        assert_that(not any(p.contains_point(outside) for p in paths), f"{name}: a cell covers {outside}")
        # Point by point: inside the catchment (even-odd over its rings) exactly one cell, else none.
        n = 50
        samples = np.array([((i + 0.5 * math.sqrt(2) - 0.2) / n, (j + 0.5 * math.sqrt(3) - 0.4) / n)
                            for i in range(n) for j in range(n)])
        covering = sum(p.contains_points(samples).astype(int) for p in paths)
        inside = sum(Path(r).contains_points(samples).astype(int) for r in rings) % 2
        wrong = np.nonzero(covering != inside)[0]
        assert_that(len(wrong) == 0, f"{name}: {len(wrong)} sample points covered {covering[wrong[:5]]} times, "
                                     f"inside {inside[wrong[:5]]}: {samples[wrong[:5]].tolist()}")


def outline_polygons(outlines):
    """Output 3 as {GaugeId: [[outer ring, hole, ...], ...]}: rings as (lon, lat) lists without the
    repeated first point, after checking that each cell is closed, a polygon's rings are
    consecutive with its outer ring (Hole 0) first, and Hole agrees with the ring's orientation."""
    cd = outlines.GetCellData()
    gauge_ids, polygon_ids, holes = (cd.GetArray(n) for n in ("GaugeId", "PolygonId", "Hole"))
    by_gauge, polygons = {}, {}
    for c, ring in enumerate(cell_rings(outlines)):
        assert_that(len(ring) >= 4 and ring[0] == ring[-1], f"outline cell {c} is not a closed ring")
        ring = ring[:-1]
        twice_area = sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1]))
        hole = holes.GetValue(c)
        assert_that((twice_area < 0) == (hole == 1), f"outline cell {c}: Hole {hole}, signed area {twice_area / 2}")
        p = polygon_ids.GetValue(c)
        if p not in polygons:
            assert_that(hole == 0, f"outline cell {c}: polygon {p} begins with a hole")
            polygons[p] = [ring]
            by_gauge.setdefault(gauge_ids.GetValue(c), []).append(polygons[p])
        else:
            assert_that(hole == 1 and polygon_ids.GetValue(c - 1) == p, f"outline cell {c}: polygon {p}'s rings")
            polygons[p].append(ring)
    return by_gauge


def test_tile_outlines_are_the_tiles_as_polygons_with_holes():
    # Output 3 joins each gauge's cells back into polygons with holes, for a GIS and for drawing the
    # tiles' borders: over a lake, the tile of the gauge in it is one polygon with a hole; across a
    # bay, the tile that meets both shores is two polygons. Each gauge's polygons hold the same
    # points as its cells, and their ellipsoidal area (outer rings less holes) is its cells'.
    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    lake = [(0.35, 0.35), (0.35, 0.65), (0.65, 0.65), (0.65, 0.35)]
    bay = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.6, 1.0), (0.6, 0.3), (0.4, 0.3), (0.4, 1.0), (0.0, 1.0)]
    cases = [("lake", [square, lake], [(0.5, 0.5), (0.1, 0.1), (0.9, 0.1), (0.9, 0.9), (0.1, 0.9)], (0, [2])),
             ("bay", [bay], [(0.5, 0.9), (0.5, 0.1), (0.1, 0.5), (0.9, 0.5)], (0, [1, 1]))]
    n = 40
    samples = np.array([((i + 0.5 * math.sqrt(2) - 0.2) / n, (j + 0.5 * math.sqrt(3) - 0.4) / n)
                        for i in range(n) for j in range(n)])
    for name, rings, coords, (gauge, ring_counts) in cases:
        f = vtkThiessenArealAverage()
        errors = messages_of(f)
        f.SetGaugesData(gauges_polydata(coords, [f"{name}{k}" for k in range(len(coords))],
                                        [float(k + 1) for k in range(len(coords))]))
        f.SetCatchmentData(polygon(rings))
        f.Update()
        tiles, outlines = f.GetOutputDataObject(0), f.GetOutputDataObject(3)
        assert_that(not errors and outlines.GetNumberOfLines() == outlines.GetNumberOfCells() > 0,
                    f"{name}: {errors}")
        assert_that(outlines.GetCellData().GetScalars() is None, f"{name}: outlines have no active scalars")
        by_gauge = outline_polygons(outlines)
        assert_that([len(p) for p in by_gauge[gauge]] == ring_counts,
                    f"{name}: gauge {gauge}'s polygons have {[len(p) for p in by_gauge[gauge]]} rings")
        cd = tiles.GetCellData()
        cells_of = {}
        for c, ring in enumerate(cell_rings(tiles)):
            cells_of.setdefault(cd.GetArray("GaugeId").GetValue(c), []).append(ring)
        assert_that(sorted(by_gauge) == sorted(cells_of), f"{name}: gauges with outlines and with cells")
        for g, polygons in by_gauge.items():
            area = math.fsum(ellipsoidal_area(r) for p in polygons for r in p)
            cells_area = math.fsum(ellipsoidal_area(r) for r in cells_of[g])
            assert_close(area, cells_area, 1e-12 * cells_area, f"{name}: gauge {g}'s outline area against its cells'")
            in_cells = sum(Path(r).contains_points(samples).astype(int) for r in cells_of[g])
            in_polygons = sum(sum(Path(r).contains_points(samples).astype(int) for r in p) % 2 for p in polygons)
            wrong = np.nonzero(in_cells != in_polygons)[0]
            assert_that(len(wrong) == 0, f"{name}: gauge {g}: {len(wrong)} samples in its cells and outlines "
                                         f"differ: {samples[wrong[:5]].tolist()}")


def test_a_tile_border_along_the_180th_meridian_stays_on_it():
    # Gauges mirrored about 180 (given as 179.8 and -179.8): their border runs along the meridian,
    # and its points came back from the plane at 180 and 179.99999999999997, so the eastern tile
    # was cut there into its part and a sliver a few nanometres wide, a polygon of its own. Each
    # gauge has one polygon, on its side of the meridian, meeting the other's at exactly 180, at
    # every latitude the mirror places the border at.
    ring = [(179.4, -16.3), (180.5, -16.2), (180.8, -16.7), (180.3, -17.2), (179.6, -17.1), (179.3, -16.7)]
    for lat in (-16.7, -16.45, 0.3, 41.2, 63.9):
        f = vtkThiessenArealAverage()
        errors = messages_of(f)
        shift = lat + 16.7
        f.SetGaugesData(gauges_polydata([(179.8, lat), (-179.8, lat)], ["W", "E"], [3.0, 4.0]))
        f.SetCatchmentData(polygon([[(x, y + shift) for x, y in ring]]))
        f.Update(3)
        by_gauge = outline_polygons(f.GetOutputDataObject(3))
        assert_that(not errors and sorted(by_gauge) == [0, 1], f"at {lat}: {errors} {sorted(by_gauge)}")
        spans = {g: [(min(x for x, _ in p[0]), max(x for x, _ in p[0])) for p in polygons]
                 for g, polygons in by_gauge.items()}
        assert_that(len(spans[0]) == 1 and len(spans[1]) == 1 and spans[0][0][1] == 180.0 == spans[1][0][0],
                    f"at {lat}: the polygons span {spans}")


def test_tile_outlines_follow_the_time_asked_through_their_port():
    # A view of the outlines alone asks through output 3: the step is the one asked there, and
    # output 0 and 3 show the same step's gauges.
    coords = [(0.25, 0.5), (0.75, 0.5), (0.5, 0.8)]
    months = {(2000, 1): {"a": 1.0, "b": 3.0, "c": 2.0}, (2000, 2): {"a": 5.0}}
    f, messages = summary_of(coords, ["a", "b", "c"], [(0, 0), (1, 0), (1, 1), (0, 1)],
                             observations_table(months))
    times = summary_column(f, "Time")
    steps = f.GetOutputInformation(3).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    assert_that(not messages and steps is not None and list(steps) == times, f"output 3's steps: {steps}")
    for t, gauges in ((times[1], {0}), (times[0], {0, 1, 2})):
        f.GetOutputInformation(3).Set(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP(), t)
        f.Update(3)
        outlines, tiles = f.GetOutputDataObject(3), f.GetOutputDataObject(0)
        seen = {outlines.GetCellData().GetArray("GaugeId").GetValue(c) for c in range(outlines.GetNumberOfCells())}
        assert_that(not messages and seen == gauges
                    and outlines.GetInformation().Get(vtkPolyData.DATA_TIME_STEP()) == t
                    and tiles.GetInformation().Get(vtkPolyData.DATA_TIME_STEP()) == t,
                    f"time {t}: gauges {seen}, {messages}")


def test_weights_table_lists_every_step():
    coords, ids, ring, months = read_colorado()
    f, messages = summary_of(coords, ids, ring, observations_table(months))
    assert_that(not messages, f"errors: {messages}")
    table = f.GetOutputDataObject(2)
    column = {name: table.GetColumnByName(name) for name in
              ("Time", "StationId", "GaugeId", "Weight", "Area_m2", "Value")}
    assert_that(all(column.values()), f"columns of output 2: {[n for n, c in column.items() if not c]}")
    rows = [{name: c.GetValue(r) for name, c in column.items()} for r in range(table.GetNumberOfRows())]
    times = summary_column(f, "Time")
    for k, (key, t) in enumerate(zip(sorted(months), times)):
        step = [r for r in rows if r["Time"] == t]
        assert_that(len(step) == summary_column(f, "StationsWeighted")[k], f"{key}: rows of output 2")
        assert_that([r["GaugeId"] for r in step] == sorted(r["GaugeId"] for r in step), f"{key}: gauge order")
        assert_close(math.fsum(r["Weight"] for r in step), 1.0, 1e-12, f"{key}: weights sum")
        mean = math.fsum(r["Weight"] * r["Value"] for r in step)
        assert_close(mean, summary_column(f, "ArealMean")[k], 1e-12 * abs(mean), f"{key}: sum of weight x value")
        f.UpdateTimeStep(t)
        tiles = weights_by_gauge(f.GetOutputDataObject(0))
        for r in step:
            assert_that(r["StationId"] == ids[r["GaugeId"]], f"{key}: StationId of gauge {r['GaugeId']}")
            assert_that(r["Value"] == months[key][ids[r["GaugeId"]]], f"{key}: value of {r['StationId']}")
            assert_close(r["Weight"], tiles[r["GaugeId"]], 1e-15, f"{key}: weight of gauge {r['GaugeId']} against its tile")
    f.SetWeightsTable(False)
    f.Update(2)
    assert_that(f.GetOutputDataObject(2).GetNumberOfRows() == 0, "WeightsTable off leaves output 2 empty")


def test_a_requested_time_picks_the_step_at_or_before_it_and_nan_is_named():
    coords = [(0.25, 0.5), (0.75, 0.5)]
    months = {(2000, 1): {"a": 1.0, "b": 3.0}, (2000, 2): {"a": 5.0}, (2000, 3): {"b": 7.0}}
    f, messages = summary_of(coords, ["a", "b"], [(0, 0), (1, 0), (1, 1), (0, 1)],
                             observations_table(months))
    times = summary_column(f, "Time")
    assert_that(not messages and len(times) == 3, f"three steps: {messages} {times}")
    # Between steps, before the first and after the last: the step at or before, else the first.
    cells = {}
    for t, step in ((times[1] + 0.01, 1), (times[0] - 1.0, 0), (times[2] + 1.0, 2), (times[2], 2)):
        f.UpdateTimeStep(t)
        tiles = f.GetOutputDataObject(0)
        assert_that(not messages and tiles.GetInformation().Get(vtkPolyData.DATA_TIME_STEP()) == times[step],
                    f"time {t} gives step {step}: {messages}")
        cells[step] = tiles.GetNumberOfCells()
    # NaN compares false with every time, and once gave the last step without a word. It is a
    # bad request, not bad input: the tables and time steps stay, and the next request is served.
    summary = [summary_column(f, name) for name in ("Time", "ArealMean")]
    rows = f.GetOutputDataObject(2).GetNumberOfRows()
    f.UpdateTimeStep(math.nan)
    assert_that(len(messages) == 1 and "the requested time is NaN" in messages[0]
                and f.GetOutputDataObject(0).GetNumberOfCells() == 0, f"a NaN time: {messages}")
    assert_that([summary_column(f, name) for name in ("Time", "ArealMean")] == summary
                and f.GetOutputDataObject(2).GetNumberOfRows() == rows > 0
                and len(f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())) == 3,
                "a NaN time keeps the summary, the weights table and the time steps")
    f.UpdateTimeStep(times[1])
    tiles = f.GetOutputDataObject(0)
    assert_that(len(messages) == 1 and tiles.GetNumberOfCells() == cells[1] > 0
                and tiles.GetInformation().Get(vtkPolyData.DATA_TIME_STEP()) == times[1],
                f"the next request after a NaN one: {messages}")


def test_long_numeric_ids_repeated_rows_and_shared_ids_are_kept_apart_and_reported():
    # USGS-style ids in double columns (as a CSV reader gives them) are four stations, not one:
    # the mean of four symmetric gauges with values 1..4 is 2.5 with weights of 1/4.
    coords = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)]
    ids = [394529105231201.0, 394529105231202.0, 6730200.0, 6730500.0]
    gauges = gauges_polydata(coords, ["x"] * 4)
    numeric = vtkDoubleArray()
    numeric.SetName("usgs")
    for i in ids:
        numeric.InsertNextValue(i)
    gauges.GetPointData().AddArray(numeric)
    table = vtkTable()
    station, value, year = vtkDoubleArray(), vtkDoubleArray(), vtkDoubleArray()
    station.SetName("usgs")
    value.SetName("value")
    year.SetName("time")
    rows = [(ids[0], 1.0), (ids[1], 2.0), (ids[2], 3.0), (ids[3], 4.0), (ids[2], 30.0)]
    for sid, v in rows:
        station.InsertNextValue(sid)
        value.InsertNextValue(v)
        year.InsertNextValue(2000.0)
    for column in (station, value, year):
        table.AddColumn(column)

    f = vtkThiessenArealAverage()
    messages = messages_of(f, vtkCommand.WarningEvent)
    f.SetGaugesData(gauges)
    f.SetStationIdArrayName("usgs")
    f.SetStationColumn("usgs")
    f.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
    f.SetObservationsData(table)
    f.Update(1)
    assert_close(summary_column(f, "ArealMean")[0], 2.5, 1e-9, "four stations, the first of the repeated rows")
    assert_that(summary_column(f, "StationsUsed")[0] == 4, "four stations used")
    repeated = f.GetOutputDataObject(1).GetFieldData().GetArray("RepeatedObservationRows")
    assert_that(repeated.GetNumberOfTuples() == 1 and repeated.GetValue(0) == 4, "row 4 listed as a repeat")
    repeated_of = f.GetOutputDataObject(1).GetFieldData().GetArray("RepeatedObservationOfRows")
    assert_that(repeated_of.GetNumberOfTuples() == 1 and repeated_of.GetValue(0) == 2,
                "row 2 listed as the row that row 4 repeats")
    assert_that(any("row 4 (station 6730200) repeating row 2" in m for m in messages),
                f"the repeat is reported with the row it repeats: {messages}")
    # One station id on two gauges: reported, its observations go to the first.
    g = vtkThiessenArealAverage()
    messages = messages_of(g, vtkCommand.WarningEvent)
    g.SetGaugesData(gauges_polydata(coords, ["a", "b", "c", "b"]))
    g.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
    g.SetObservationsData(observations_table({(2000, 1): {"a": 1.0, "b": 2.0, "c": 3.0}}))
    g.Update(1)
    assert_that(any("b (gauges 1 and 3)" in m for m in messages), f"the shared id is reported: {messages}")
    unobserved = g.GetOutputDataObject(1).GetFieldData().GetArray("UnobservedGaugeIds")
    assert_that(unobserved.GetNumberOfTuples() == 1 and unobserved.GetValue(0) == 3, "gauge 3 unobserved")


def test_review_cases_of_times_values_and_time_aware_gauges():
    """A user review's findings. (1) Numeric times in a text column (a CSV read with numeric
    detection off, as the README advises for blank missing values) are read as numbers; a text
    time that is neither a date nor a number is named. (2) A year that is not whole, with a month
    column, is an error (1963.5 with month 8 became 2064.08). (3) A hexadecimal value is not a
    number (0x10 was read as 16). (4) Without a table, the gauges' own time steps are the
    filter's: a requested time goes up to them, and the tiles carry their time."""
    from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase

    square = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    coords = [(0.25, 0.5), (0.75, 0.5)]

    def run_table(rows, **settings):
        f = vtkThiessenArealAverage()
        messages = messages_of(f)
        f.SetGaugesData(gauges_polydata(coords, ["a", "b"]))
        f.SetCatchmentData(square)
        f.SetObservationsData(text_table(rows))
        f.SetTimeColumn("date")
        for name, value in settings.items():
            getattr(f, "Set" + name)(value)
        f.Update(1)
        return f, messages

    f, messages = run_table([("a", "1963.5", "10"), ("b", "1963.5", "20"), ("a", " 1964.25 ", ""),
                             ("b", "1964.25", "2")])
    assert_that(not messages and summary_column(f, "Time") == [1963.5, 1964.25]
                and summary_column(f, "ArealMean") == [15.0, 2.0] and summary_column(f, "StationsUsed") == [2, 1],
                f"(1) numeric text times: {messages} {summary_column(f, 'Time')} {summary_column(f, 'ArealMean')}")
    f, messages = run_table([("a", "1963.5", "10"), ("b", "mid-1963", "20")])
    assert_that(len(messages) == 1 and "'mid-1963' in column 'date' is not a date" in messages[0]
                and "or a finite number" in messages[0], f"(1) neither a date nor a number: {messages}")
    # Times in one time zone (one offset, however written) are read as written, as the example
    # script reads them, and as TimeOfDate reads a date with its zone; a series in two zones, or
    # with a zone on some times only, is refused naming both rows (times are not moved to UTC).
    plain = [vtkThiessenArealAverage.TimeOfDate(t) for t in ("1963-08-01 09:00", "1963-08-02")]
    f, messages = run_table([("a", "1963-08-01T09:00Z", "10"), ("b", " 1963-08-01 09:00+00:00", "20"),
                             ("a", "1963-08-02T00:00:00Z", "4")])
    assert_that(not messages and summary_column(f, "Time") == plain and summary_column(f, "ArealMean") == [15.0, 4.0]
                and vtkThiessenArealAverage.TimeOfDate("1963-08-01T09:00-07:00") == plain[0],
                f"(1) one time zone: {messages} {summary_column(f, 'Time')} {plain}")
    for first, second, said in (
            ("1963-08-01 09:00", "1963-08-01T10:00:00Z",
             "'1963-08-01T10:00:00Z' in column 'date' has time zone Z, where row 0's '1963-08-01 09:00' has no time"),
            ("1963-08-01 09:00+05:00", "1963-08-01 10:00+0100",
             "'1963-08-01 10:00+0100' in column 'date' has time zone +0100, where row 0's '1963-08-01 09:00+05:00' "
             "has time zone +05:00: times are read as written (not moved to UTC)"),
            ("1963-08-01T09:00Z", "1963-08-02",
             "'1963-08-02' in column 'date' has no time zone, where row 0's '1963-08-01T09:00Z' has time zone Z")):
        f, messages = run_table([("a", first, "10"), ("b", second, "20")])
        assert_that(len(messages) == 1 and "observation row 1: " + said in messages[0],
                    f"(1) two time zones: {messages}")
    # 24:00 is the next day's 00:00, as the script reads hour-ending records.
    f, messages = run_table([("a", "1963-08-01 24:00", "10"), ("b", "1963-08-02", "20"), ("a", "1963-08-31 24:00", "4")])
    assert_that(not messages and summary_column(f, "Time") == [1963 + (7 + 1 / 31) / 12, 1963 + 8 / 12]
                and summary_column(f, "ArealMean") == [15.0, 4.0], f"(1) 24:00: {messages} {summary_column(f, 'Time')}")

    def run_with_month(years):
        table = vtkTable()
        for name, values in (("station_id", ["a", "b"]), ("year", years), ("month", ["8", "8"]),
                             ("value", ["1", "2"])):
            column = vtkStringArray()
            column.SetName(name)
            for v in values:
                column.InsertNextValue(v)
            table.AddColumn(column)
        f = vtkThiessenArealAverage()
        messages = messages_of(f)
        f.SetGaugesData(gauges_polydata(coords, ["a", "b"]))
        f.SetCatchmentData(square)
        f.SetObservationsData(table)
        f.SetTimeColumn("year")
        f.SetMonthColumn("month")
        f.Update(1)
        return f, messages

    # (a date, or a year and month as one number, given as the year was "not a finite number", or
    # taken for the year 200001)
    for years, bad in ((["1963.5", "1963"], "1963.5"), (["2000-01", "2000-01"], "2000-01"),
                       (["200001", "200001"], "200001")):
        f, messages = run_with_month(years)
        assert_that(len(messages) == 1 and f"the year '{bad}' in column 'year' is not a whole number of -9999 .. 9999"
                    in messages[0] and "TimeColumn names a column of years" in messages[0],
                    f"(2) {bad} as a year with a month: {messages}")
    f, messages = run_with_month(["1963", "1963"])
    assert_that(not messages and summary_column(f, "ArealMean") == [1.5], f"(2) a year: {messages}")

    f, messages = run_table([("a", "2000-01", "0x10"), ("b", "2000-01", "2")])
    assert_that(len(messages) == 1 and "'0x10'" in messages[0] and "not a number" in messages[0],
                f"(3) a hexadecimal value: {messages}")

    class TimedGauges(VTKPythonAlgorithmBase):
        """Gauges a and b whose value is 10 t and 20 t at times 1, 2, 3."""

        def __init__(self):
            VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1, outputType="vtkPolyData")
            self.asked = []

        def RequestInformation(self, request, inInfo, outInfo):
            info = outInfo.GetInformationObject(0)
            info.Set(vtkStreamingDemandDrivenPipeline.TIME_STEPS(), [1.0, 2.0, 3.0], 3)
            info.Set(vtkStreamingDemandDrivenPipeline.TIME_RANGE(), [1.0, 3.0], 2)
            return 1

        def RequestData(self, request, inInfo, outInfo):
            info = outInfo.GetInformationObject(0)
            t = info.Get(vtkStreamingDemandDrivenPipeline.UPDATE_TIME_STEP())
            self.asked.append(t)
            out = vtkPolyData.GetData(outInfo)
            out.ShallowCopy(gauges_polydata(coords, ["a", "b"], [10 * t, 20 * t]))
            out.GetInformation().Set(vtkPolyData.DATA_TIME_STEP(), t)
            return 1

    source = TimedGauges()
    f = vtkThiessenArealAverage()
    messages = messages_of(f)
    f.SetGaugesConnection(source.GetOutputPort())
    f.SetCatchmentData(square)
    f.UpdateInformation()
    steps = f.GetOutputInformation(0).Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
    assert_that(steps == (1.0, 2.0, 3.0), f"(4) the gauges' steps advertised: {steps}")
    for t in (2.0, 3.0, 1.0):
        f.UpdateTimeStep(t)
        tiles = f.GetOutputDataObject(0)
        values = sorted(tiles.GetCellData().GetArray("Value").GetValue(c) for c in range(tiles.GetNumberOfCells()))
        assert_that(values == [10 * t, 20 * t] and tiles.GetInformation().Get(vtkPolyData.DATA_TIME_STEP()) == t
                    and summary_column(f, "Time") == [t], f"(4) at time {t}: {values}, {summary_column(f, 'Time')}")
    assert_that(not messages and source.asked[-3:] == [2.0, 3.0, 1.0], f"(4) {messages}, asked {source.asked}")



def test_an_area_method_that_is_no_choice_is_named():
    # SetAreaMethod(3) measured geodesically without a word (clamped).
    f = vtkThiessenArealAverage()
    assert_that((f.GetAreaMethodMinValue(), f.GetAreaMethodMaxValue()) == (0, 2), "the range")
    errors = messages_of(f)
    f.SetAreaMethod(3)
    f.SetGaugesData(gauges_polydata([(-0.5, -0.5), (0.5, 0.5)], ["a", "b"], [1.0, 2.0]))
    f.SetCatchmentData(polygon([[(-1, -1), (1, -1), (1, 1), (-1, 1)]]))
    f.Update()
    assert_that(len(errors) == 1 and "AreaMethod 3 is not one of 0 (Automatic), 1 (EqualAreaPlane), 2 (GeodesicPolygon)"
                in errors[0] and f.GetOutputDataObject(1).GetNumberOfRows() == 0, f"{errors}")


def test_ids_and_values_are_read_one_a_gauge_or_row():
    """A station id or value array of two components was read value by value (the second gauge got
    the id 0, the third the second's station) or by its first component, and a table column of
    two was called missing: each is an error naming the array and its components. Ids of 8-bit
    integers (numpy's int8, a vtkCharArray) are numbers, not characters: 65 matches 65, not 'A'."""
    from vtkmodules.util.numpy_support import numpy_to_vtk

    square = polygon([[(0, 0), (1, 0), (1, 1), (0, 1)]])
    coords = [(0.2, 0.2), (0.8, 0.3), (0.5, 0.8)]

    def run_with(ids, table=None, gauges=None):
        if gauges is None:
            gauges = gauges_polydata(coords, ["x", "y", "z"])
            gauges.GetPointData().RemoveArray("station_id")
            ids.SetName("station_id")
            gauges.GetPointData().AddArray(ids)
        f = vtkThiessenArealAverage()
        errors = messages_of(f)
        f.SetGaugesData(gauges)
        f.SetCatchmentData(square)
        if table is not None:
            f.SetObservationsData(table)
        f.Update(1)
        return f, errors

    pairs = numpy_to_vtk(np.array([[101, 0], [102, 0], [103, 0]], dtype=np.int32), deep=True)
    months = observations_table({(2000, 1): {"101": 1.0, "102": 2.0, "103": 3.0}})
    _, errors = run_with(pairs, months)
    assert_that(len(errors) == 1 and "station id array 'station_id' has 2 components" in errors[0], f"{errors}")
    two_values = gauges_polydata(coords, ["x", "y", "z"])
    doubled = numpy_to_vtk(np.array([[1.0, 9.0], [2.0, 9.0], [3.0, 9.0]]), deep=True)
    doubled.SetName("value")
    two_values.GetPointData().AddArray(doubled)
    _, errors = run_with(None, gauges=two_values)
    assert_that(len(errors) == 1 and "value array 'value' has 2 components" in errors[0], f"{errors}")
    table = observations_table({(2000, 1): {"x": 1.0, "y": 2.0, "z": 3.0}})
    time = table.GetColumnByName("time")
    paired = numpy_to_vtk(np.array([[time.GetValue(r), 0.0] for r in range(table.GetNumberOfRows())]), deep=True)
    paired.SetName("time")
    table.RemoveColumnByName("time")
    table.AddColumn(paired)
    ids = vtkStringArray()
    for sid in ("x", "y", "z"):
        ids.InsertNextValue(sid)
    _, errors = run_with(ids, table)
    assert_that(len(errors) == 1 and "column 'time'" in errors[0] and "has 2 components" in errors[0], f"{errors}")

    small = numpy_to_vtk(np.array([65, 66, 67], dtype=np.int8), deep=True)
    f, errors = run_with(small, observations_table({(2000, 1): {"65": 1.0, "66": 2.0, "67": 3.0}}))
    assert_that(not errors and summary_column(f, "StationsUsed") == [3], f"int8 ids: {errors}")
    _, errors = run_with(numpy_to_vtk(np.array([65, 66, 67], dtype=np.int8), deep=True),
                         observations_table({(2000, 1): {"A": 1.0, "B": 2.0, "C": 3.0}}))
    assert_that(len(errors) == 1 and "station ids that no gauge has: A" in errors[0], f"letters: {errors}")
    # The gauges' own ids and the two settings are named (a trial chose another point array as
    # StationIdArrayName, and was told only of the table's ids).
    assert_that("; the gauges' ids (their point-data array 'station_id', StationIdArrayName) are 65, 66, 67 (do "
                "StationIdArrayName and StationColumn 'station_id' hold the same ids?)" in errors[0], f"{errors}")


if __name__ == "__main__":
    run([test_four_symmetric_gauges_share_a_square,
         test_ids_and_values_are_read_one_a_gauge_or_row,
         test_columns_of_different_lengths_are_named,
         test_a_missing_value_code_is_missing_when_set_and_named_when_not,
         test_colorado_months_match_a_brute_force_raster,
         test_missing_steps_and_unused_input_are_reported,
         test_values_of_a_co_located_gauge_that_are_not_used_are_listed,
         test_an_unobserved_gauge_without_a_station_id_is_named_by_its_point,
         test_a_gauge_whose_station_id_others_share_is_named_with_its_index,
         test_gauges_never_weighted_and_no_gauge_inside_are_reported,
         test_a_catchment_ring_inside_another_blocks_ring_is_reported,
         test_gauges_in_blocks_as_a_point_layer_gives_them_are_joined,
         test_bad_gauge_and_self_intersecting_catchment_are_named,
         test_window_clip_of_projected_tiles_sums_to_the_catchment,
         test_window_clip_names_a_non_convex_tile,
         test_clipping_the_averages_lon_lat_tiles_says_what_to_do_instead,
         test_sub_basins_with_rounded_junctions_average_as_their_union,
         test_window_clip_reports_cells_that_are_not_polygons,
         test_window_clip_reports_tiles_without_area_and_names_an_overflow,
         test_window_cells_that_are_not_rings_are_reported,
         test_window_clip_of_tiles_stored_in_float,
         test_dates_and_year_month_columns_give_the_same_steps,
         test_dates_of_days_and_hours_are_written_as_given,
         test_time_of_date_picks_that_dates_step,
         test_dates_of_different_periods_are_warned_of,
         test_gauges_given_an_earlier_gauges_station_id_are_listed,
         test_the_projection_used_is_recorded_and_makes_the_same_tiles,
         test_an_enclave_given_as_a_hole_and_a_feature_of_its_own_is_in_the_catchment,
         test_the_monthly_csv_as_a_text_reader_gives_it,
         test_blank_values_read_as_text_are_missing,
         test_bad_dates_and_months_are_named,
         test_text_values_with_missing_markers,
         test_a_failed_update_leaves_no_earlier_result,
         test_review_cases_of_gauges_and_errors,
         test_columns_not_yet_set_give_no_error_until_the_update,
         test_review_cases_of_times_values_and_time_aware_gauges,
         test_tile_outlines_are_the_tiles_as_polygons_with_holes,
         test_a_tile_border_along_the_180th_meridian_stays_on_it,
         test_tile_outlines_follow_the_time_asked_through_their_port,
         test_rows_that_cannot_be_used_make_no_step_and_are_listed,
         test_weights_table_lists_every_step,
         test_a_requested_time_picks_the_step_at_or_before_it_and_nan_is_named,
         test_tiles_of_a_catchment_with_a_hole_or_a_bay,
         test_long_numeric_ids_repeated_rows_and_shared_ids_are_kept_apart_and_reported,
         test_an_area_method_that_is_no_choice_is_named])
