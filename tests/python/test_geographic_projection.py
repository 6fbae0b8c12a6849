"""vtkGeographicProjection from Debian's /usr/bin/python3: the real Colorado gauges round-trip,
projected distances agree with geodesic distances, and bad input is reported."""

import csv
import math
import os

from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet, vtkPolyData

from tessera import vtkGeographicProjection
from tessera_testing import (EXAMPLE_DATA, assert_close, assert_that, cell_rings, colorado_outline, make_points, messages_of,
                             polygon, projection_record, run)


def colorado_gauges():
    points = vtkPoints()
    points.SetDataTypeToDouble()
    with open(os.path.join(EXAMPLE_DATA, "colorado_stations.csv")) as f:
        for row in csv.DictReader(f):
            points.InsertNextPoint(float(row["lon"]), float(row["lat"]), float(row["elev_m"]))
    data = vtkPolyData()
    data.SetPoints(points)
    return data


def test_round_trip_of_the_colorado_gauges():
    gauges = colorado_gauges()
    forward = vtkGeographicProjection()
    forward.SetInputData(gauges)
    forward.Update()
    projected = forward.GetOutput()
    assert_that(projected.GetNumberOfPoints() == 376, "all 376 gauges projected")
    record = projected.GetFieldData().GetAbstractArray("TesseraProjection").GetValue(0)
    assert_that(record.startswith("projection=AlbersEqualArea"), record)
    inverse = vtkGeographicProjection()
    inverse.SetInputConnection(forward.GetOutputPort())
    inverse.InverseOn()
    inverse.Update()
    back = inverse.GetOutput()
    for i in range(gauges.GetNumberOfPoints()):
        a, b = gauges.GetPoint(i), back.GetPoint(i)
        assert_close(b[0], a[0], 1e-9, f"longitude of gauge {i}")
        assert_close(b[1], a[1], 1e-9, f"latitude of gauge {i}")
        assert_that(b[2] == a[2], f"elevation of gauge {i} kept")


def geodesic_distance(lon1, lat1, lon2, lat2, a=6378137.0, f=1 / 298.257223563):
    """The geodesic distance (m) on the WGS84 ellipsoid by Vincenty's inverse formula (1975),
    written out here, apart from GeographicLib: to well under a millimetre for points not nearly
    antipodal."""
    b = a * (1 - f)
    u1, u2 = math.atan((1 - f) * math.tan(math.radians(lat1))), math.atan((1 - f) * math.tan(math.radians(lat2)))
    big_l = math.radians(lon2 - lon1)
    lam = big_l
    for _ in range(200):
        sin_sigma = math.hypot(math.cos(u2) * math.sin(lam),
                               math.cos(u1) * math.sin(u2) - math.sin(u1) * math.cos(u2) * math.cos(lam))
        if sin_sigma == 0:
            return 0.0
        cos_sigma = math.sin(u1) * math.sin(u2) + math.cos(u1) * math.cos(u2) * math.cos(lam)
        sigma = math.atan2(sin_sigma, cos_sigma)
        sin_alpha = math.cos(u1) * math.cos(u2) * math.sin(lam) / sin_sigma
        cos2_alpha = 1 - sin_alpha ** 2
        cos_2sm = cos_sigma - 2 * math.sin(u1) * math.sin(u2) / cos2_alpha if cos2_alpha else 0.0
        c = f / 16 * cos2_alpha * (4 + f * (4 - 3 * cos2_alpha))
        previous = lam
        lam = big_l + (1 - c) * f * sin_alpha * (
            sigma + c * sin_sigma * (cos_2sm + c * cos_sigma * (-1 + 2 * cos_2sm ** 2)))
        if abs(lam - previous) < 1e-13:
            break
    u_2 = cos2_alpha * (a * a - b * b) / (b * b)
    big_a = 1 + u_2 / 16384 * (4096 + u_2 * (-768 + u_2 * (320 - 175 * u_2)))
    big_b = u_2 / 1024 * (256 + u_2 * (-128 + u_2 * (74 - 47 * u_2)))
    delta = big_b * sin_sigma * (cos_2sm + big_b / 4 * (cos_sigma * (-1 + 2 * cos_2sm ** 2) - big_b / 6 * cos_2sm
                                                         * (-3 + 4 * sin_sigma ** 2) * (-3 + 4 * cos_2sm ** 2)))
    return b * big_a * (sigma - delta)


def test_azimuthal_equidistant_keeps_distances_from_the_centre():
    # Distances from the centre are true geodesic distances on the ellipsoid (a sphere agreed to
    # 0.5% only, and let an error of scale or ellipsoid that size through).
    points = vtkPoints()
    for lon, lat in [(-105.0, 39.0), (-104.0, 39.5), (-108.0, 37.0), (-102.5, 41.2)]:
        points.InsertNextPoint(lon, lat, 0.0)
    data = vtkPolyData()
    data.SetPoints(points)
    f = vtkGeographicProjection()
    f.SetInputData(data)
    f.SetProjectionToAzimuthalEquidistant()
    f.ParametersFromDataOff()
    f.SetCentralLongitude(-105.0)
    f.SetCentralLatitude(39.0)
    f.Update()
    out = f.GetOutput()
    x0, y0, _ = out.GetPoint(0)
    assert_that(abs(x0) < 1e-6 and abs(y0) < 1e-6, "the centre maps to the origin")
    for i in range(1, 4):
        x, y, _ = out.GetPoint(i)
        lon, lat, _ = data.GetPoint(i)
        expected = geodesic_distance(-105.0, 39.0, lon, lat)
        assert_close(math.hypot(x, y), expected, 1e-3, f"distance (m) of point {i} from the centre")


def test_lambert_azimuthal_equal_area_is_laea_europe_and_goes_back_by_its_record():
    # EPSG Guidance Note 7-2's example of LAEA Europe (EPSG:3035: centre 52 N 10 E, false origin
    # 4321000, 3210000): 50 N 5 E is E 3962799.45, N 2999718.85. The record takes the inverse back.
    data = make_points([(5.0, 50.0), (10.0, 52.0), (-9.5, 38.7)])
    f = vtkGeographicProjection()
    f.SetInputData(data)
    f.SetProjectionToLambertAzimuthalEqualArea()
    f.ParametersFromDataOff()
    f.SetCentralLongitude(10.0)
    f.SetCentralLatitude(52.0)
    f.Update()
    out = f.GetOutput()
    assert_close(out.GetPoint(0)[0] + 4321000.0, 3962799.45, 0.005, "easting of 50 N 5 E")
    assert_close(out.GetPoint(0)[1] + 3210000.0, 2999718.85, 0.005, "northing of 50 N 5 E")
    assert_that(out.GetPoint(1)[:2] == (0.0, 0.0), f"the centre maps to the origin: {out.GetPoint(1)}")
    assert_that(projection_record(out).startswith("projection=LambertAzimuthalEqualArea lon0=10 lat0=52 "),
                projection_record(out))
    inverse = vtkGeographicProjection()
    inverse.SetInputConnection(f.GetOutputPort())
    inverse.InverseOn()
    inverse.Update()
    for i in range(3):
        for axis in range(2):
            assert_close(inverse.GetOutput().GetPoint(i)[axis], data.GetPoint(i)[axis], 1e-9, f"point {i} back")


def test_a_grid_gives_a_projected_systems_own_numbers_and_takes_them_back():
    # PROJ 9.1.1 (cs2cs +proj=longlat +ellps=WGS84 +to ...): the USGS Albers (EPSG:5070: northings from 23 N,
    # which GeographicLib's cone does not start at) and LAEA Europe with its false origin (EPSG:3035; EPSG
    # Guidance Note 7-2's example: 50 N 5 E is E 3962799.45, N 2999718.85). Each goes back by its record,
    # and by the settings alone (ParametersFromData off) from the file's numbers.
    systems = [("Albers", (-105.5, 39.0), (-813760.923180, 1815617.850413), "origin_lat=23",
                lambda f: (f.SetProjectionToAlbersEqualArea(), f.SetCentralLongitude(-96.0),
                           f.SetStandardParallels(29.5, 45.5), f.UseLatitudeOfOriginOn(), f.SetLatitudeOfOrigin(23.0))),
               ("LAEA", (5.0, 50.0), (3962799.450958, 2999718.853159), "x0=4321000 y0=3210000",
                lambda f: (f.SetProjectionToLambertAzimuthalEqualArea(), f.SetCentralLongitude(10.0),
                           f.SetCentralLatitude(52.0), f.SetFalseEasting(4321000.0), f.SetFalseNorthing(3210000.0)))]
    for name, lonlat, expected, keys, settle in systems:
        f = vtkGeographicProjection()
        f.SetInputData(make_points([lonlat]))
        f.ParametersFromDataOff()
        settle(f)
        f.Update()
        x, y, _ = f.GetOutput().GetPoint(0)
        assert_close(x, expected[0], 1e-5, f"{name}: easting")
        assert_close(y, expected[1], 1e-5, f"{name}: northing")
        assert_that(projection_record(f.GetOutput()).endswith(keys), f"{name}: {projection_record(f.GetOutput())}")
        by_record = vtkGeographicProjection()
        by_record.SetInputConnection(f.GetOutputPort())
        by_record.InverseOn()
        by_settings = vtkGeographicProjection()
        by_settings.SetInputData(make_points([expected]))  # (the file's numbers, no record)
        by_settings.ParametersFromDataOff()
        settle(by_settings)
        by_settings.InverseOn()
        for inverse in (by_record, by_settings):
            inverse.Update()
            lon, lat, _ = inverse.GetOutput().GetPoint(0)
            assert_that(abs(lon - lonlat[0]) < 1e-9 and abs(lat - lonlat[1]) < 1e-9,
                        f"{name}: back at {lon!r}, {lat!r}")
    # A latitude of origin set while UseLatitudeOfOrigin is off is warned of, unused.
    f = vtkGeographicProjection()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(make_points([(-105.5, 39.0)]))
    f.SetLatitudeOfOrigin(23.0)
    f.Update()
    assert_that(f.GetOutput().GetNumberOfPoints() == 1 and any(
        "LatitudeOfOrigin 23 is not used: UseLatitudeOfOrigin is off" in w for w in warnings), f"{warnings}")
    # Once per value (NaN too): not again at the next update (ParaView hides the value with the
    # box off), again for another value, and again after the box was on and off.
    def unused_warnings():
        return sum("is not used: UseLatitudeOfOrigin is off" in w for w in warnings)

    for settle, expected in ((lambda: f.Modified(), 1), (lambda: f.SetLatitudeOfOrigin(24.0), 2),
                             (lambda: f.Modified(), 2), (lambda: f.UseLatitudeOfOriginOn(), 2),
                             (lambda: f.UseLatitudeOfOriginOff(), 3),
                             (lambda: f.SetLatitudeOfOrigin(float("nan")), 4), (lambda: f.Modified(), 4)):
        settle()
        f.Update()
        assert_that(unused_warnings() == expected, f"{expected} warnings expected: {warnings}")
    # A latitude of origin where the projection's origin is fixed, and a scale of 0, are errors naming the term.
    for settle, words in (
            (lambda f: (f.SetProjectionToLambertAzimuthalEqualArea(), f.UseLatitudeOfOriginOn()),
             "latitude of origin origin_lat: LambertAzimuthalEqualArea takes none"),
            (lambda f: (f.SetProjectionToUTM(), f.UseLatitudeOfOriginOn()), "UTM takes none"),
            (lambda f: f.SetScaleFactor(0.0), "scale factor k0 = 0 is not within 0.1 to 10"),
            (lambda f: f.SetFalseNorthing(float("nan")), "false northing y0 = nan")):
        f = vtkGeographicProjection()
        errors = messages_of(f)
        f.SetInputData(make_points([(5.0, 50.0)]))
        settle(f)
        f.Update()
        assert_that(f.GetOutput().GetNumberOfPoints() == 0 and any(words in e for e in errors), f"{words}: {errors}")


def test_mercator_and_web_mercator_are_epsg_3395_and_3857():
    # PROJ 9.1.1's (cs2cs EPSG:4326 EPSG:3395, EPSG:3857) eastings and northings of 50 N 5 E: the web
    # maps' northing is the sphere's, 32.75 km north of the ellipsoid's. Each goes back by its record.
    for choose, north in ((vtkGeographicProjection.SetProjectionToMercator, 6413524.594164),
                          (vtkGeographicProjection.SetProjectionToWebMercator, 6446275.841017)):
        f = vtkGeographicProjection()
        f.SetInputData(make_points([(5.0, 50.0)]))
        choose(f)
        f.ParametersFromDataOff()
        f.Update()
        x, y, _ = f.GetOutput().GetPoint(0)
        assert_close(x, 556597.453966, 1e-5, f"{projection_record(f.GetOutput())}: easting")
        assert_close(y, north, 1e-5, f"{projection_record(f.GetOutput())}: northing")
        inverse = vtkGeographicProjection()  # (by the record the forward wrote)
        inverse.SetInputConnection(f.GetOutputPort())
        inverse.InverseOn()
        inverse.Update()
        lon, lat, _ = inverse.GetOutput().GetPoint(0)
        assert_that(abs(lon - 5.0) < 1e-12 and abs(lat - 50.0) < 1e-12, f"{projection_record(f.GetOutput())}: back "
                    f"at {lon!r}, {lat!r}")


def test_nan_point_is_named_and_output_is_empty():
    points = vtkPoints()
    points.InsertNextPoint(-105.0, 39.0, 0.0)
    points.InsertNextPoint(float("nan"), 39.0, 0.0)
    data = vtkPolyData()
    data.SetPoints(points)
    f = vtkGeographicProjection()
    messages = messages_of(f)
    f.SetInputData(data)
    f.Update()
    assert_that(f.GetOutput().GetNumberOfPoints() == 0, "empty output after a NaN point")
    assert_that(len(messages) == 1, f"one error reported, got {messages}")
    assert_that("point 1" in messages[0], f"the error names point 1: {messages[0]}")


def test_the_blocks_of_a_composite_share_one_projection():
    """A multiblock (as vtkGDALVectorReader gives a file's layers) is projected with one projection
    fitted to all its blocks: the same point lands at the same place in every block, exactly where
    projecting all the points as one set puts it. Errors name the block; the inverse undoes it."""
    west, east = [(-109.0, 37.0), (-105.0, 39.0)], [(-105.0, 39.0), (-102.0, 41.0)]
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, make_points(west))
    blocks.SetBlock(1, None)  # an empty place is kept empty
    blocks.SetBlock(2, make_points(east))
    blocks.GetMetaData(2).Set(vtkCompositeDataSet.NAME(), "east")
    f = vtkGeographicProjection()
    messages = messages_of(f)
    f.SetInputData(blocks)
    f.Update()
    out = f.GetOutputDataObject(0)
    assert_that(not messages and out.IsA("vtkMultiBlockDataSet") and out.GetNumberOfBlocks() == 3,
                f"a multiblock out: {messages}, {out.GetClassName()}")
    whole = vtkGeographicProjection()
    whole.SetInputData(make_points(west + east))
    whole.Update()
    expected = whole.GetOutput()
    record = projection_record(expected)
    assert_that(out.GetBlock(1) is None, "the empty place stays empty")
    for b, first in ((0, 0), (2, 2)):
        block = out.GetBlock(b)
        assert_that(projection_record(block) == record, f"block {b}: {projection_record(block)} against {record}")
        for i in range(2):
            assert_that(block.GetPoint(i) == expected.GetPoint(first + i),
                        f"block {b} point {i}: {block.GetPoint(i)} against {expected.GetPoint(first + i)}")
    assert_that(out.GetBlock(0).GetPoint(1) == out.GetBlock(2).GetPoint(0), "(-105, 39) in both blocks")
    assert_that(projection_record(out) == record, f"the composite's own record: {projection_record(out)}")

    inverse = vtkGeographicProjection()
    inverse.SetInputConnection(f.GetOutputPort())
    inverse.InverseOn()
    inverse.Update()
    back = inverse.GetOutputDataObject(0).GetBlock(2)
    for i, (lon, lat) in enumerate(east):
        assert_close(back.GetPoint(i)[0], lon, 1e-9, f"longitude {i} back")
        assert_close(back.GetPoint(i)[1], lat, 1e-9, f"latitude {i} back")

    blocks.SetBlock(2, make_points([(-105.0, 39.0), (-102.0, 95.0)]))
    blocks.GetMetaData(2).Set(vtkCompositeDataSet.NAME(), "east")
    f.Modified()
    f.Update()
    assert_that(len(messages) == 1 and "block 2 (composite index 3, 'east'): point 1" in messages[0],
                f"the bad point named with its block: {messages}")


def test_utm_metres_without_a_record_go_back_by_their_zone():
    """UTM points from elsewhere (no TesseraProjection record) go back to lon/lat by the zone and
    hemisphere alone: a scripter had to turn ParametersFromData off as well, which a UTM zone set
    by hand makes needless (the panel hides it then). Against the forward projection of the same
    places in that zone, north and south; without a zone (0) the error says what to give."""
    places = [(-105.0, 40.0), (-106.3, 37.2), (-103.1, 41.9)]
    forward = vtkGeographicProjection()
    forward.SetInputData(make_points(places))
    forward.SetProjectionToUTM()
    forward.SetUTMZone(13)
    forward.Update()
    metres = [forward.GetOutput().GetPoint(i)[:2] for i in range(len(places))]
    inverse = vtkGeographicProjection()
    errors = messages_of(inverse)
    inverse.SetInputData(make_points(metres))  # (plain points: no record)
    inverse.InverseOn()
    inverse.SetProjectionToUTM()
    inverse.SetUTMZone(13)
    inverse.Update()
    back = inverse.GetOutput()
    assert_that(not errors and back.GetNumberOfPoints() == 3, f"zone 13: {errors}")
    for i, (lon, lat) in enumerate(places):
        assert_close(back.GetPoint(i)[0], lon, 1e-9, f"longitude {i} back")
        assert_close(back.GetPoint(i)[1], lat, 1e-9, f"latitude {i} back")
    # South of the equator, with UTMNorth off (the false northing of 10000 km).
    south = [(-105.0, -40.0), (-103.5, -33.2)]
    forward.SetInputData(make_points(south))
    forward.SetUTMNorth(False)
    forward.Update()
    assert_that(all(forward.GetOutput().GetPoint(i)[1] > 5e6 for i in range(2)), "southern northings")
    inverse.SetInputData(make_points([forward.GetOutput().GetPoint(i)[:2] for i in range(2)]))
    inverse.SetUTMNorth(False)
    inverse.Update()
    for i, (lon, lat) in enumerate(south):
        assert_close(inverse.GetOutput().GetPoint(i)[0], lon, 1e-9, f"south: longitude {i} back")
        assert_close(inverse.GetOutput().GetPoint(i)[1], lat, 1e-9, f"south: latitude {i} back")
    inverse.SetUTMZone(0)
    inverse.Update()
    assert_that(len(errors) == 1 and "Inverse needs the input's TesseraProjection field data, a UTM zone (UTMZone "
                "1 to 60)" in errors[0] and inverse.GetOutput().GetNumberOfPoints() == 0, f"zone 0: {errors}")
    # A grid of the other hemisphere than every point is warned of, both ways, with the northings
    # 10,000 km apart from the right grid's (a trial left UTMNorth off for northern data); points
    # on both sides of the equator take either without a word.
    for places_given, north, said in ((places, False, "UTMNorth is off"), (south, True, "UTMNorth is on")):
        f = vtkGeographicProjection()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetInputData(make_points(places_given))
        f.SetProjectionToUTM()
        f.SetUTMZone(13)
        f.SetUTMNorth(north)
        f.Update()
        right = vtkGeographicProjection()
        right.SetInputData(make_points(places_given))
        right.SetProjectionToUTM()
        right.SetUTMZone(13)
        right.SetUTMNorth(not north)
        right.Update()
        shift = f.GetOutput().GetPoint(0)[1] - right.GetOutput().GetPoint(0)[1]
        assert_that(len(warnings) == 1 and said in warnings[0] and abs(abs(shift) - 1e7) < 1e-6,
                    f"{said}: {warnings}, shift {shift}")
    for north in (True, False):
        f = vtkGeographicProjection()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetInputData(make_points([(-105.0, 1.0), (-104.0, -1.0)]))
        f.SetProjectionToUTM()
        f.SetUTMZone(13)
        f.SetUTMNorth(north)
        f.Update()
        assert_that(not warnings, f"across the equator, UTMNorth {north}: {warnings}")


def test_no_points_give_an_empty_output_without_error():
    # No error, but a warning: an empty output without a word left a ParaView user guessing.
    f = vtkGeographicProjection()
    messages = messages_of(f)
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(make_points([]))
    f.Update()
    assert_that(not messages and f.GetOutput().GetNumberOfPoints() == 0 and projection_record(f.GetOutput()) is None,
                f"no points: {messages}")
    assert_that(len(warnings) == 1 and "the input has no points: no point projected, and no projection fitted, so no "
                "TesseraProjection record (does the filter before it give none?)" in warnings[0],
                f"no points, warned: {warnings}")
    inverse = vtkGeographicProjection()
    inverse_messages = messages_of(inverse)
    inverse_warnings = messages_of(inverse, vtkCommand.WarningEvent)
    inverse.SetInputConnection(f.GetOutputPort())
    inverse.InverseOn()
    inverse.Update()
    assert_that(not inverse_messages and inverse.GetOutput().GetNumberOfPoints() == 0,
                f"the empty output's inverse: {inverse_messages}")
    assert_that(len(inverse_warnings) == 1 and "no point taken back to lon/lat" in inverse_warnings[0],
                f"the empty output's inverse, warned: {inverse_warnings}")
    # A grid set out of range is named even with no points to fit a projection to (it was named
    # only once points came); a good one gives no message.
    for configure, named in ((lambda g: g.SetScaleFactor(100.0), "scale factor k0 = 100 is not within 0.1 to 10"),
                             (lambda g: g.SetFalseEasting(1e9), "false easting x0 = 1000000000 is not within 1e8 m"),
                             (lambda g: (g.SetProjectionToUTM(), g.UseLatitudeOfOriginOn()), "UTM takes none"),
                             (lambda g: g.SetScaleFactor(0.9996), None)):
        gridded = vtkGeographicProjection()
        errors = messages_of(gridded)
        gridded.SetInputData(make_points([]))
        configure(gridded)
        gridded.Update()
        assert_that(len(errors) == (named is not None) and (named is None or named in errors[0]),
                    f"{named}: {errors}")


def test_an_edge_cut_into_the_most_pieces_is_reported():
    """Densifying cuts an edge into at most 10^6 pieces (a step too fine would exhaust memory):
    an edge that needs more gives a warning with the count, one that needs 10^6 or fewer none."""
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkCommonDataModel import vtkCellArray

    line = make_points([(-105.0, 39.0), (-104.0, 39.0), (-104.0, 39.5)])
    cells = vtkCellArray()
    cells.InsertNextCell(3)
    for i in range(3):
        cells.InsertCellPoint(i)
    line.SetLines(cells)
    # (at 5e-7 the half-degree edge needs exactly 10^6 pieces: not counted; the 1-degree one is)
    for step, capped in ((1e-3, 0), (1e-7, 2), (8e-7, 1), (5e-7, 1)):
        f = vtkGeographicProjection()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetMaximumEdgeLength(step)
        f.SetInputData(line)
        f.Update()
        points = f.GetOutput().GetNumberOfPoints()
        expected = 1 + sum(min(math.ceil(length / step), 10 ** 6) for length in (1.0, 0.5))
        assert_that(abs(points - expected) <= 2, f"step {step}: {points} points, about {expected}")
        if capped:
            assert_that(len(warnings) == 1 and warnings[0].find(f"{capped} edge(s) were cut into 1000000") >= 0,
                        f"step {step}: {warnings}")
        else:
            assert_that(not warnings, f"step {step}: {warnings}")
    # More than 10^7 new points in all (a step in metres rather than degrees) is refused before
    # any is made: 12 edges of a degree or more at 1e-7 would add 12 (10^6 - 1) (each capped);
    # two blocks of 6 such edges add up (counted over both before either is cut: the message names
    # no block); 11 edges, 10999989 points, too; four squares in a row have 13 edges, the 3 they
    # share cut once (16 counted by cell). A step of 1e-5 is made.
    def ring(edges, lat=39.0):
        data = make_points([(-105.0 + k, lat) for k in range(edges // 2 + 1)]
                           + [(-105.0 + k, lat + 1.0) for k in reversed(range(edges - edges // 2 - 1))])
        cells = vtkCellArray()
        cells.InsertNextCell(data.GetNumberOfPoints())
        for i in range(data.GetNumberOfPoints()):
            cells.InsertCellPoint(i)
        data.SetPolys(cells)
        return data
    blocks = vtkMultiBlockDataSet()
    blocks.SetBlock(0, ring(6))
    blocks.SetBlock(1, ring(6, 41.0))
    squares = make_points([(-105.0 + k, 39.0 + j) for j in (0, 1) for k in range(5)])
    cells = vtkCellArray()
    for k in range(4):
        cells.InsertNextCell(4)
        for i in (k, k + 1, k + 6, k + 5):
            cells.InsertCellPoint(i)
    squares.SetPolys(cells)
    for data, step, refused in ((ring(12), 1e-7, "would cut the edges into 11999988 new points, more than 10000000"),
                                (blocks, 1e-7, "would cut the edges into 11999988 new points"),
                                (ring(11), 1e-7, "would cut the edges into 10999989 new points"),
                                (squares, 1e-7, "would cut the edges into 12999987 new points"),
                                (ring(12), 1e-5, None)):
        f = vtkGeographicProjection()
        errors = messages_of(f)
        f.SetMaximumEdgeLength(step)
        f.SetInputData(data)
        f.Update()
        output = f.GetOutputDataObject(0)
        points = output.GetNumberOfPoints()
        if refused:
            assert_that(len(errors) == 1 and f"MaximumEdgeLength {step:g} degrees {refused}" in errors[0]
                        and "it is in degrees" in errors[0] and "block" not in errors[0] and points == 0,
                        f"{errors}, {points} points")
        else:
            assert_that(not errors and points > 12 * 10 ** 5, f"{errors}, {points} points")


def test_an_edge_that_reads_both_ways_round_the_globe_is_reported():
    """A polygon edge whose longitudes differ by 180 to 270 degrees as written is densified the
    shorter way round, across the 180th meridian, not straight in lon/lat as RFC 7946 reads it: a
    warning counts such edges and names the first (it was silent, and a box from -100 to 100
    came out as one from 100 to 260). An antimeridian edge written 179 to -179 (358 degrees) is
    read as meant, without a warning."""
    from vtkmodules.vtkCommonCore import vtkCommand

    for west, east, warned in ((-100.0, 100.0, True), (179.0, -179.0, False), (-80.0, 80.0, False)):
        f = vtkGeographicProjection()
        warnings = messages_of(f, vtkCommand.WarningEvent)
        f.SetInputData(polygon([[(west, 10.0), (east, 10.0), (east, 30.0), (west, 30.0)]]))
        f.Update()
        if warned:
            assert_that(len(warnings) == 1 and "2 edge(s) span 180 to 270 degrees" in warnings[0]
                        and "points 0 and 1, longitude -100 to 100" in warnings[0], f"{west}: {warnings}")
            # the densified bottom edge runs through 180 (the other way, it would pass 0)
            inverse = vtkGeographicProjection()
            inverse.SetInverse(True)
            inverse.SetInputConnection(f.GetOutputPort())
            inverse.Update()
            out = inverse.GetOutput()
            lons = [out.GetPoint(i)[0] % 360.0 for i in range(out.GetNumberOfPoints())]
            assert_that(max(lons) > 179.0 and min(lons) >= 100.0 - 1e-6, f"{min(lons)} .. {max(lons)}")
        else:
            assert_that(not warnings, f"{west}: {warnings}")



def test_automatic_with_parameters_set_is_their_albers_conic():
    """Automatic is the Albers equal-area conic fitted to the data; with ParametersFromData off it
    takes the parameters set, forward and inverse (they were ignored: the inverse of metres fitted
    a conic to them as if they were degrees and gave (20.0001, 30.2264) for (10, 20) m)."""
    lonlat = [(-105.0, 39.0), (-104.2, 40.1), (-106.3, 38.2)]

    def projected(kind, source, inverse=False):
        f = vtkGeographicProjection()
        getattr(f, "SetProjectionTo" + kind)()
        f.ParametersFromDataOff()
        f.SetCentralLongitude(-104.5)
        f.SetCentralLatitude(39.5)
        f.SetStandardParallels(39.17, 39.83)
        f.SetInverse(inverse)
        f.SetInputData(source)
        f.Update()
        out = f.GetOutput()
        return [out.GetPoint(k)[:2] for k in range(out.GetNumberOfPoints())]

    albers = projected("AlbersEqualArea", make_points(lonlat))
    automatic = projected("Automatic", make_points(lonlat))
    assert_that(automatic == albers, f"Automatic {automatic}, AlbersEqualArea {albers}")
    back = projected("Automatic", make_points(albers), inverse=True)
    for (lon, lat), (x, y) in zip(lonlat, back):
        assert_close(x, lon, 1e-9, "longitude back")
        assert_close(y, lat, 1e-9, "latitude back")


def test_global_ids_are_kept_where_no_edge_is_cut_and_their_loss_is_said():
    """Points (nothing to cut) keep their global ids through the projection and on to the tiles,
    as the README's pipeline needs (copying tuples left them out); where edges are cut, the new
    points have no id and a warning says the ids were not carried."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkIdTypeArray

    from tessera import vtkDirichletTessellation

    def with_ids(data):
        ids = vtkIdTypeArray()
        ids.SetName("gid")
        for k in range(data.GetNumberOfPoints()):
            ids.InsertNextValue(1000 + k)
        data.GetPointData().SetGlobalIds(ids)
        return data

    f = vtkGeographicProjection()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(with_ids(make_points([(-105, 39), (-104, 40), (-103, 38)])))
    tiles = vtkDirichletTessellation()
    tiles.SetInputConnection(f.GetOutputPort())
    tiles.Update()
    projected = f.GetOutput().GetPointData().GetGlobalIds()
    carried = tiles.GetOutput().GetCellData().GetArray("gid")
    assert_that(projected is not None and [projected.GetValue(k) for k in range(3)] == [1000, 1001, 1002],
                "the projected points' global ids")
    assert_that(carried is not None and [carried.GetValue(k) for k in range(3)] == [1000, 1001, 1002],
                "the tiles' global ids")
    assert_that(not warnings, f"{warnings}")
    g = vtkGeographicProjection()
    warned = messages_of(g, vtkCommand.WarningEvent)
    g.SetInputData(with_ids(polygon([[(-109, 37), (-102, 37), (-102, 41), (-109, 41)]])))
    g.Update()
    assert_that(g.GetOutput().GetNumberOfPoints() > 4 and g.GetOutput().GetPointData().GetGlobalIds() is None,
                "cut edges: new points, no global ids")
    assert_that(len(warned) == 1 and "the global ids of 1 piece(s) (the first: 'gid') were not carried" in warned[0],
                f"{warned}")


def test_a_nan_or_negative_edge_length_is_an_error():
    """MaximumEdgeLength NaN turned the densification off without a word (every comparison with
    NaN is false), and so did a negative length: an error naming it and saying how to turn it off;
    0 turns it off (the square's 4 corners stay 4 points)."""
    f = vtkGeographicProjection()
    errors = messages_of(f)
    f.SetInputData(polygon([[(-109, 37), (-102, 37), (-102, 41), (-109, 41)]]))
    for length, text in ((float("nan"), "nan"), (-1.0, "-1")):
        f.SetMaximumEdgeLength(length)
        f.Update()
        assert_that(len(errors) == 1 and f"MaximumEdgeLength {text} is not a length of 0 or more degrees (0 turns "
                    "the densification off)" in errors[0] and f.GetOutput().GetNumberOfPoints() == 0,
                    f"{length}: {errors}")
        errors.clear()
    f.SetMaximumEdgeLength(0.0)
    f.Update()
    assert_that(not errors and f.GetOutput().GetNumberOfPoints() == 4, f"0: {errors}")


def test_a_projection_or_zone_that_is_no_choice_is_named():
    # SetProjection(9) and SetUTMZone(61) were clamped to another projection and zone 60, silently.
    # A NaN centre set by hand is named too. The ranges the clamping setters announced are kept.
    g = vtkGeographicProjection()
    assert_that((g.GetProjectionMinValue(), g.GetProjectionMaxValue(), g.GetUTMZoneMinValue(), g.GetUTMZoneMaxValue())
                == (0, 8, 0, 60), "the ranges")
    for setup, expected in [(lambda f: f.SetProjection(9), "Projection 9 is not one of 0 (Automatic), 1 (AlbersEqualArea)"),
                            (lambda f: (f.SetProjectionToUTM(), f.SetUTMZone(61)),
                             "UTMZone 61 is neither a zone from 1 to 60 nor 0"),
                            (lambda f: (f.SetProjectionToUTM(), f.SetUTMZone(-1)),
                             "UTMZone -1 is neither a zone from 1 to 60 nor 0"),
                            # (a NaN centre was named "longitude nan has no UTM zone")
                            (lambda f: (f.SetProjectionToTransverseMercator(), f.ParametersFromDataOff(),
                                        f.SetCentralLongitude(math.nan)), "CentralLongitude is nan"),
                            # (1e20 was taken, and every x came out 0; a latitude of 100 was taken
                            # where unused, and written into the record)
                            (lambda f: (f.SetProjectionToTransverseMercator(), f.ParametersFromDataOff(),
                                        f.SetCentralLongitude(1e20)), "CentralLongitude is 1e+20, not in [-360, 360]"),
                            (lambda f: (f.SetProjectionToAlbersEqualArea(), f.ParametersFromDataOff(),
                                        f.SetCentralLatitude(100)), "CentralLatitude is 100, not in [-90, 90]")]:
        f = vtkGeographicProjection()
        errors = messages_of(f)
        setup(f)
        f.SetInputData(make_points([(-105.0, 39.0), (-104.0, 40.0)]))
        f.Update()
        assert_that(len(errors) == 1 and expected in errors[0] and f.GetOutput().GetNumberOfPoints() == 0, f"{errors}")
    # The zone is a UTM setting: a zone left from a UTM choice (a script, a state file) does not
    # stop another projection, nor enter its record (zone 12 did, where the data's is 13): it gives
    # what it gives with zone 0.
    points = make_points([(-105.0, 39.0), (-104.0, 40.0)])
    for projection in (g.AUTOMATIC, g.TRANSVERSE_MERCATOR):
        outputs = []
        for zone in (61, 12, 0):
            f = vtkGeographicProjection()
            errors = messages_of(f)
            f.SetProjection(projection)
            f.SetUTMZone(zone)
            f.SetInputData(points)
            f.Update()
            assert_that(not errors and f.GetOutput().GetNumberOfPoints() == 2, f"projection {projection}: {errors}")
            record = f.GetOutput().GetFieldData().GetAbstractArray("TesseraProjection").GetValue(0)
            outputs.append(([f.GetOutput().GetPoint(i) for i in range(2)], record))
        assert_that(outputs[0] == outputs[1] == outputs[2] and "zone=13" in outputs[0][1],
                    f"projection {projection}: zones 61 and 12 changed the points or the record: {outputs}")


def test_settings_an_inverse_does_not_use_for_the_inputs_record_are_named():
    """Inverse with a record on the input uses the record (the points were projected with it).
    Settings that describe another projection (a grid, a UTM zone, another kind, ParametersFromData off) are
    then unused, and a warning names them beside the record; defaults, or settings that describe
    the record's own projection, give none. The points come back by the record in every case."""
    places = [(-105.0, 40.0), (-106.3, 37.2), (-103.1, 41.9)]
    forward = vtkGeographicProjection()
    forward.SetInputData(make_points(places))
    forward.SetProjectionToUTM()
    forward.SetUTMZone(13)
    forward.SetFalseNorthing(1000.0)
    forward.Update()
    record = projection_record(forward.GetOutput())

    def inverse_warnings(configure):
        inverse = vtkGeographicProjection()
        inverse.SetInputConnection(forward.GetOutputPort())
        inverse.InverseOn()
        configure(inverse)
        warnings = messages_of(inverse, vtkCommand.WarningEvent)
        errors = messages_of(inverse)
        inverse.Update()
        assert_that(not errors, f"errors: {errors}")
        for i, (lon, lat) in enumerate(places):
            assert_close(inverse.GetOutput().GetPoint(i)[0], lon, 1e-9, f"longitude {i} back by the record")
            assert_close(inverse.GetOutput().GetPoint(i)[1], lat, 1e-9, f"latitude {i} back by the record")
        return warnings

    def zone(number, false_northing):
        def configure(f):
            f.SetProjectionToUTM()
            f.SetUTMZone(number)
            f.SetFalseNorthing(false_northing)
        return configure

    assert_that(inverse_warnings(lambda f: None) == [], "defaults describe no projection")
    assert_that(inverse_warnings(zone(13, 1000.0)) == [], "the record's own zone and grid")
    assert_that(inverse_warnings(zone(0, 1000.0)) == [], "the record's kind, fitted, and grid")
    unused = {
        "another false northing": (lambda f: f.SetFalseNorthing(2000.0), "y0=2000"),
        "another zone": (zone(12, 1000.0), "zone=12"),
        "another kind": (lambda f: f.SetProjectionToMercator(),
                         "(Projection Mercator, fitted to the data) are not used"),
        "another kind and grid": (lambda f: (f.SetProjectionToMercator(), f.SetFalseEasting(1000.0)),
                                  "(Projection Mercator, fitted to the data, FalseEasting 1000) are not used"),
        "parameters set": (lambda f: (f.SetProjectionToAzimuthalEquidistant(), f.ParametersFromDataOff(),
                                      f.SetCentralLongitude(-100.0)), "projection=AzimuthalEquidistant lon0=-100"),
        "parameters that are no projection": (lambda f: (f.ParametersFromDataOff(), f.SetCentralLatitude(95.0)),
                                              "are no projection: CentralLatitude is 95"),
    }
    for case, (configure, named) in unused.items():
        warnings = inverse_warnings(configure)
        assert_that(len(warnings) == 1 and f"the input carries the projection record '{record}'" in warnings[0]
                    and named in warnings[0], f"{case}: {warnings}")


def project(data, configure=None, inverse_of=None):
    """The output of a vtkGeographicProjection on data (configure(f) first, if given), with its
    warnings and errors."""
    f = vtkGeographicProjection()
    warnings, errors = messages_of(f, vtkCommand.WarningEvent), messages_of(f)
    if configure:
        configure(f)
    f.SetInputData(data)
    f.Update()
    return f.GetOutput(), warnings, errors


def test_one_place_in_two_longitude_conventions_projects_to_one_point():
    """181.5 and -178.5, or 180 and -180, are one place: they project to the same x and y, bit for
    bit, whatever the record (they were some 1e-9 m apart, and a tessellation kept both copies and
    split one tile between them), and the Fiji epicentres give the same points in 0 .. 360 as in
    -180 .. 180."""
    for lon0 in ("176.5", "-170.25", "183.3", "0.1"):
        record = f"projection=AlbersEqualArea lon0={lon0} lat0=-20 lat1=-25 lat2=-15 zone=1 north=0"
        for east, west in ((181.5, -178.5), (180.0, -180.0), (359.5, -0.5), (190.123456789, 190.123456789 - 360)):
            out, _, errors = project(make_points([(east, -20.0), (west, -20.0)]),
                                     lambda f: f.SetProjectionRecord(record))
            a, b = out.GetPoint(0), out.GetPoint(1)
            assert_that(not errors and a == b, f"lon0 {lon0}: {east} at {a}, {west} at {b}")
    with open(os.path.join(EXAMPLE_DATA, "fiji_quakes.csv")) as f:
        quakes = [(float(row["long"]), float(row["lat"])) for row in csv.DictReader(f)]
    assert_that(any(lon > 180.0 for lon, _ in quakes), "the file has longitudes beyond 180")
    first, _, _ = project(make_points(quakes))
    record = projection_record(first)
    wrapped = [(lon - 360.0 if lon > 180.0 else lon, lat) for lon, lat in quakes]
    second, _, _ = project(make_points(wrapped), lambda f: f.SetProjectionRecord(record))
    moved = [i for i in range(len(quakes)) if first.GetPoint(i) != second.GetPoint(i)]
    assert_that(not moved, f"{len(moved)} of {len(quakes)} epicentres moved, e.g. {moved[:5]}")


def area_straight_in_lonlat(ring):
    """Ellipsoidal (WGS84) area of a lon/lat ring whose edges are straight in lon/lat, anticlockwise
    positive: minus the integral of the area from the equator to each latitude, a^2 q / 2 per
    radian of longitude (Snyder's q, 3-12), along the boundary, by Simpson's rule on each edge."""
    a, f = 6378137.0, 1 / 298.257223563
    e2 = f * (2 - f)
    e = math.sqrt(e2)

    def zone(lat):
        s = math.sin(math.radians(lat))
        return a * a / 2 * (1 - e2) * (s / (1 - e2 * s * s) - math.log((1 - e * s) / (1 + e * s)) / (2 * e))

    total = 0.0
    for (lon1, lat1), (lon2, lat2) in zip(ring, ring[1:] + ring[:1]):
        steps = 16
        weights = [1 if k in (0, steps) else 4 if k % 2 else 2 for k in range(steps + 1)]
        mean = sum(w * zone(lat1 + (lat2 - lat1) * k / steps) for k, w in enumerate(weights)) / (3 * steps)
        total -= mean * math.radians(lon2 - lon1)
    return total


def test_the_inverse_cuts_plane_edges_so_that_lonlat_keeps_their_shape():
    """An inverse's polygon edges are straight in the plane; read straight in lon/lat (RFC 7946, as
    the forward reads them) they would be other lines. The inverse cuts them, so that no piece
    spans more than MaximumEdgeLength degrees: a square of 600 km in an Albers plane (equal-area)
    then comes back as a lon/lat ring whose ellipsoidal area, computed here apart, is the square's
    to 1e-6; uncut (MaximumEdgeLength 0, or before) it was 1e-3 off. Points of a forward's densified
    output, projected back, are not cut again."""
    record = "projection=AlbersEqualArea lon0=-105.5 lat0=39 lat1=37.67 lat2=40.33 zone=13 north=1"
    side = 600000.0
    square = polygon([[(-side / 2, -side / 2), (side / 2, -side / 2), (side / 2, side / 2), (-side / 2, side / 2)]])
    stamp = vtkStringArray()
    stamp.SetName("TesseraProjection")
    stamp.InsertNextValue(record)
    square.GetFieldData().AddArray(stamp)
    errors_of = {}
    for step in (0.1, 0.0):
        out, warnings, errors = project(square, lambda f: (f.InverseOn(), f.SetMaximumEdgeLength(step)))
        ring = [p[:2] for p in cell_rings(out)[0]]
        errors_of[step] = abs(area_straight_in_lonlat(ring) / side ** 2 - 1)
        assert_that(not warnings and not errors, f"step {step}: {warnings} {errors}")
        if step:
            longest = max(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(ring, ring[1:] + ring[:1]))
            assert_that(longest <= step * 1.01 and len(ring) > 4, f"{len(ring)} points, a piece of {longest}")
        else:
            assert_that(len(ring) == 4, f"MaximumEdgeLength 0 keeps the 4 corners: {len(ring)}")
    assert_that(errors_of[0.1] < 1e-6 and errors_of[0.0] > 1e-4, f"relative area errors {errors_of}")
    # Projected and back: the forward's pieces of at most 0.1 degree are not cut again.
    forward = vtkGeographicProjection()
    forward.SetInputData(polygon([colorado_outline()]))
    inverse = vtkGeographicProjection()
    inverse.InverseOn()
    inverse.SetInputConnection(forward.GetOutputPort())
    inverse.Update()
    there, back = forward.GetOutput(), inverse.GetOutput()
    assert_that(there.GetNumberOfPoints() > 2 * len(colorado_outline()) and back.GetNumberOfPoints() == there.GetNumberOfPoints(),
                f"{there.GetNumberOfPoints()} points projected, {back.GetNumberOfPoints()} back")


def test_the_inverse_gives_longitudes_a_reader_takes_back():
    """Stations all round the globe gave an automatic central meridian of 300, and the inverse gave
    longitudes of 400 and 450 back, which the forward (and the areal average) then refused: the
    inverse's longitudes are within 360 degrees, each a whole number of turns from the input's,
    and continuous along the data's arc. A meridian set beyond 180 by hand gives no longitude beyond
    360 either."""
    lons = [150.0, 200.0, 250.0, 300.0, 350.0, 40.0, 90.0]
    stations = make_points([(lon, 5.0 + (k % 3) * 5.0) for k, lon in enumerate(lons)])
    there, warnings, _ = project(stations)
    back, _, errors = project(there, lambda f: f.InverseOn())
    got = [back.GetPoint(i)[0] for i in range(len(lons))]
    assert_that(not errors and all(abs(lon) <= 360.0 for lon in got), f"{errors} {got}")
    assert_that(all(abs(math.remainder(g - lon, 360.0)) < 1e-9 for g, lon in zip(got, lons)), f"{got} for {lons}")
    assert_that(max(got) - min(got) < 360.0, f"continuous along the arc: {got}")
    again, _, errors = project(back)
    assert_that(not errors and again.GetNumberOfPoints() == len(lons), f"{errors}")
    record = "projection=AlbersEqualArea lon0=300 lat0=5 lat1=0 lat2=10 zone=1 north=1"
    there, _, _ = project(stations, lambda f: f.SetProjectionRecord(record))
    back, _, errors = project(there, lambda f: f.InverseOn())
    got = [back.GetPoint(i)[0] for i in range(len(lons))]
    assert_that(not errors and all(abs(lon) <= 360.0 for lon in got) and max(got) - min(got) < 360.0
                and all(abs(math.remainder(g - lon, 360.0)) < 1e-9 for g, lon in zip(got, lons)), f"{errors} {got}")
    # A line about 0 East under that meridian: the whole output moves a turn west, not the points
    # beyond 360 alone (it came back from 355 to 5, an edge round the globe).
    from vtkmodules.vtkCommonDataModel import vtkCellArray
    line = make_points([(355.0, 5.0), (5.0, 5.0)])
    cells = vtkCellArray()
    cells.InsertNextCell(2, [0, 1])
    line.SetLines(cells)
    there, _, _ = project(line, lambda f: f.SetProjectionRecord(record))
    back, _, errors = project(there, lambda f: f.InverseOn())
    got = sorted(back.GetPoint(i)[0] for i in range(back.GetNumberOfPoints()))
    assert_that(not errors and back.GetNumberOfPoints() > 90 and got[-1] - got[0] < 10.0 + 1e-6
                and all(abs(lon) <= 360.0 for lon in got), f"{errors} {got[:2]} .. {got[-2:]}")


def test_a_wide_plane_edge_is_cut_by_the_degrees_it_spans():
    """A plane edge whose ends come back 240 degrees of longitude apart spans 240 (the inverse's
    longitudes are continuous about its meridian), not the 120 of the shorter way round: it is cut
    into 2400 pieces at 0.1 degree, not 1200."""
    record = "projection=AlbersEqualArea lon0=0 lat0=30 lat1=20 lat2=40 zone=31 north=1"
    ends, _, _ = project(make_points([(-120.0, -30.0), (120.0, -30.0)]), lambda f: f.SetProjectionRecord(record))
    from vtkmodules.vtkCommonDataModel import vtkCellArray
    cells = vtkCellArray()
    cells.InsertNextCell(2, [0, 1])
    ends.SetLines(cells)
    back, _, errors = project(ends, lambda f: f.InverseOn())
    ring = [p for p in cell_rings(back)[0]]
    assert_that(not errors and len(ring) >= 2401, f"{errors}: {len(ring)} points")
    longest = max(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(ring, ring[1:]))
    # (equal in the plane, the pieces span up to 1.6 times the step where the image bends most)
    assert_that(longest <= 0.1 * 2.0, f"a piece spans {longest} degrees")


def test_data_round_the_globe_warn_that_the_projection_cuts_them():
    """Stations all round Antarctica, every 5 degrees of longitude: a conic cut in their largest gap
    puts neighbours 359 km apart some 6000 km apart in the plane, and their tiles do not meet. A
    warning says so and names the azimuthal way; data spanning up to 270 degrees, and an azimuthal
    projection, give none."""
    ring = [(5.0 * k, -50.0 - 6.0 * (k % 2)) for k in range(72)]
    for coords, configure, warned in (
            (ring, None, "the data span 355 degrees of longitude: the AlbersEqualArea projection is cut at "
                         "longitude 357.5, in their largest gap (5 degrees)"),
            (ring, lambda f: f.SetProjectionToLambertConformalConic(), "the LambertConformalConic projection"),
            (ring[:55], None, None),
            (ring, lambda f: (f.SetProjectionToLambertAzimuthalEqualArea(), f.ParametersFromDataOff(),
                              f.SetCentralLatitude(-90.0)), None)):
        out, warnings, errors = project(make_points(coords), configure)
        if warned:
            assert_that(len(warnings) == 1 and warned in warnings[0] and "LambertAzimuthalEqualArea" in warnings[0],
                        f"{warnings}")
        else:
            assert_that(not warnings and not errors, f"{len(coords)} points: {warnings} {errors}")
        assert_that(out.GetNumberOfPoints() == len(coords), f"{out.GetNumberOfPoints()} points")


def test_a_longitude_beyond_360_is_refused_whatever_gives_the_projection():
    """A typo of longitude 1000 was wrapped to 280 and projected without a word when a
    ProjectionRecord was set, and refused otherwise: now refused with the point named either way."""
    record = "projection=AlbersEqualArea lon0=178 lat0=-20 lat1=-25 lat2=-15 zone=1 north=0"
    points = make_points([(178.0, -20.0), (179.0, -21.0), (1000.0, -28.11)])
    for configure in (None, lambda f: f.SetProjectionRecord(record),
                      lambda f: (f.ParametersFromDataOff(), f.SetCentralLongitude(178.0))):
        out, _, errors = project(points, configure)
        assert_that(len(errors) == 1 and "point 2 (1000, -28.11) has a longitude beyond 360 degrees" in errors[0]
                    and out.GetNumberOfPoints() == 0, f"{errors}")


def test_degrees_given_to_the_inverse_are_warned_of():
    """The inverse takes metres of the plane: lon/lat given to it with ParametersFromData off came
    back as places within metres of the projection's origin without a word. Points all within the
    lon/lat ranges now give a warning; the same places in metres give none."""
    gauges = make_points([(-105.0, 39.0), (-104.0, 39.5), (-108.0, 37.0)])

    def inverse(f):
        f.InverseOn()
        f.ParametersFromDataOff()
        f.SetCentralLongitude(-105.0)
        f.SetCentralLatitude(39.0)

    out, warnings, errors = project(gauges, inverse)
    assert_that(not errors and len(warnings) == 1 and "all 3 input point(s) lie within longitude and latitude ranges"
                in warnings[0] and "turn Inverse off" in warnings[0], f"{warnings} {errors}")
    projected, _, _ = project(gauges, lambda f: (f.ParametersFromDataOff(), f.SetCentralLongitude(-105.0),
                                                 f.SetCentralLatitude(39.0)))
    back, warnings, errors = project(projected, inverse)
    assert_that(not warnings and not errors and abs(back.GetPoint(2)[0] + 108.0) < 1e-9, f"{warnings} {errors}")


if __name__ == "__main__":
    run([test_round_trip_of_the_colorado_gauges,
         test_azimuthal_equidistant_keeps_distances_from_the_centre,
         test_lambert_azimuthal_equal_area_is_laea_europe_and_goes_back_by_its_record,
         test_a_grid_gives_a_projected_systems_own_numbers_and_takes_them_back,
         test_mercator_and_web_mercator_are_epsg_3395_and_3857,
         test_nan_point_is_named_and_output_is_empty,
         test_the_blocks_of_a_composite_share_one_projection,
         test_utm_metres_without_a_record_go_back_by_their_zone,
         test_settings_an_inverse_does_not_use_for_the_inputs_record_are_named,
         test_no_points_give_an_empty_output_without_error,
         test_an_edge_cut_into_the_most_pieces_is_reported,
         test_an_edge_that_reads_both_ways_round_the_globe_is_reported,
         test_automatic_with_parameters_set_is_their_albers_conic,
         test_global_ids_are_kept_where_no_edge_is_cut_and_their_loss_is_said,
         test_a_nan_or_negative_edge_length_is_an_error,
         test_a_projection_or_zone_that_is_no_choice_is_named,
         test_one_place_in_two_longitude_conventions_projects_to_one_point,
         test_the_inverse_cuts_plane_edges_so_that_lonlat_keeps_their_shape,
         test_the_inverse_gives_longitudes_a_reader_takes_back,
         test_data_round_the_globe_warn_that_the_projection_cuts_them,
         test_a_longitude_beyond_360_is_refused_whatever_gives_the_projection,
         test_degrees_given_to_the_inverse_are_warned_of,
         test_a_wide_plane_edge_is_cut_by_the_degrees_it_spans])
