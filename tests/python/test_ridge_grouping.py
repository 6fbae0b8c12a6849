"""vtkRidgeGrouping from Python: noisy samples along known curves are grouped (adjusted Rand
index against the truth, computed here), ordered (Kendall tau of Node against true arc length),
fitted (distance of the curves to the truth); plus the outputs' arrays and bad input."""

import math
import random

import numpy as np
from vtkmodules.vtkCommonCore import vtkCommand

from tessera import vtkRidgeGrouping
from tessera_testing import (assert_close, assert_that, double_array, make_points, messages_of, points_in_blocks, run,
                             warnings_of_update)


def adjusted_rand_index(a, b):
    from collections import Counter

    n = len(a)
    pairs = lambda k: k * (k - 1) / 2
    joint = sum(pairs(c) for c in Counter(zip(a, b)).values())
    sa = sum(pairs(c) for c in Counter(a).values())
    sb = sum(pairs(c) for c in Counter(b).values())
    expected = sa * sb / pairs(n)
    return (joint - expected) / (0.5 * (sa + sb) - expected)


def kendall_tau(x, y):
    concordant = discordant = 0
    for i in range(len(x)):
        for j in range(i + 1, len(x)):
            s = (x[i] - x[j]) * (y[i] - y[j])
            concordant += s > 0
            discordant += s < 0
    return (concordant - discordant) / max(1, concordant + discordant)


def two_noisy_curves(sigma=1.0, seed=3):
    """A straight line and a parabola 60 units apart, 300 points each, noise sigma."""
    rng = random.Random(seed)
    coords, truth, arc = [], [], []
    for k in range(300):
        t = rng.uniform(0, 200)
        coords.append((t + rng.gauss(0, sigma), 20 + rng.gauss(0, sigma)))
        truth.append(0)
        arc.append(t)
    for k in range(300):
        t = rng.uniform(0, 200)
        coords.append((t + rng.gauss(0, sigma), 80 + 0.002 * (t - 100) ** 2 + rng.gauss(0, sigma)))
        truth.append(1)
        arc.append(t)
    return coords, truth, arc


def test_two_noisy_curves_are_grouped_ordered_and_fitted():
    coords, truth, arc = two_noisy_curves()
    f = vtkRidgeGrouping()
    f.SetInputData(make_points(coords))
    f.SetImageSize(256)
    f.SetCurveSigma(0.02)
    f.Update()
    pts = f.GetOutput(0)
    groups = [pts.GetPointData().GetArray("GroupId").GetValue(i) for i in range(len(coords))]
    nodes = [pts.GetPointData().GetArray("Node").GetValue(i) for i in range(len(coords))]
    ari = adjusted_rand_index(groups, truth)
    # Two well separated curves (60 units apart, noise 1): anything but a clean split is a bug.
    assert_that(ari > 0.95, f"adjusted Rand index {ari:.3f}")
    for curve in (0, 1):
        members = [i for i in range(len(coords)) if truth[i] == curve]
        tau = kendall_tau([nodes[i] for i in members[:150]], [arc[i] for i in members[:150]])
        # Node order may run either way along the curve.
        assert_that(abs(tau) > 0.95, f"curve {curve}: Kendall tau {tau:.3f}")
        assert_that(all(0.0 <= nodes[i] <= 1.0 for i in members), "nodes in [0, 1]")
    # Each point's distance to its contour: the nearest of the contours' pixel centres (noise 1).
    distance = pts.GetPointData().GetArray("ContourDistance")
    contours = f.GetOutputDataObject(1)
    pixels = np.array([contours.GetPoint(k)[:2] for k in range(contours.GetNumberOfPoints())])
    for i in range(0, len(coords), 37):
        nearest = np.min(np.hypot(pixels[:, 0] - coords[i][0], pixels[:, 1] - coords[i][1]))
        assert_close(distance.GetValue(i), nearest, 1e-9 * (1 + nearest), f"ContourDistance of point {i}")
    assert_that(contours.GetCellData().GetArray("ContourId") is not None, "ContourId")
    assert_that(contours.GetCellData().GetArray("Closed") is not None, "Closed")
    curves = f.GetOutputDataObject(2)
    # Each output is coloured by its groups (ParaView colours by the active scalars).
    active = [pts.GetPointData().GetScalars(), contours.GetCellData().GetScalars(), curves.GetCellData().GetScalars()]
    assert_that([a.GetName() if a else None for a in active] == ["GroupId", "ContourId", "GroupId"],
                f"active scalars {[a.GetName() if a else None for a in active]}")
    assert_that(curves.GetNumberOfCells() >= 2, f"{curves.GetNumberOfCells()} fitted curves")
    # Every sample of the fitted curves lies near one of the true curves (within 6 noise sigmas,
    # the open-end and bend allowance of the core's own tests).
    for c in range(curves.GetNumberOfCells()):
        ids = curves.GetCell(c).GetPointIds()
        for k in range(0, ids.GetNumberOfIds(), 5):
            x, y, _ = curves.GetPoint(ids.GetId(k))
            xs = np.linspace(0, 200, 2001)
            d_line = np.min(np.hypot(xs - x, 20 - y))
            d_parabola = np.min(np.hypot(xs - x, 80 + 0.002 * (xs - 100) ** 2 - y))
            assert_that(min(d_line, d_parabola) < 6.0, f"curve {c} sample {k} is {min(d_line, d_parabola):.1f} off")
    image = f.GetOutputDataObject(3)
    dims = image.GetDimensions()
    assert_that(max(dims[0], dims[1]) == 256, f"image {dims}")
    for name in ("Field", "MinorRidge", "MajorRidge"):
        assert_that(image.GetPointData().GetArray(name) is not None, f"image array {name}")
    assert_that(pts.GetFieldData().GetArray("ImageSize").GetValue(0) == 256, "ImageSize recorded")


def test_no_loop_smaller_than_the_basis_makes_a_closed_group():
    # Three noisy sine roads, 250 apart, at a basis width of 8 pixels: where a road ends the field
    # made a ridge loop of 14.5 pixels, which took the road's last 60 points into a closed group of
    # their own (4 groups, the road's Node order broken). A loop shorter than a circle of one basis
    # width is dropped: three open groups, one a road, in order (some 50 points past the end of the
    # middle road's contour still join the bottom road's group, hence a Rand index of 0.86, not 1).
    # A circle of points (at the default width) stays one closed group.
    rng = np.random.default_rng(1)
    coords, truth, along = [], [], []
    for k in range(3):
        t = np.sort(rng.random(300))
        xy = np.column_stack([1000 * t, 250 * k + 40 * np.sin(2 * np.pi * 1.5 * t + k)])
        xy += rng.normal(scale=8.0, size=xy.shape)
        coords += [tuple(p) for p in xy]
        truth += [k] * 300
        along += list(t)
    circle = [(300 * math.cos(a) + rng.normal(0, 8.0), 300 * math.sin(a) + rng.normal(0, 8.0))
              for a in np.sort(rng.random(600)) * 2 * math.pi]
    for points, roads in ((coords, True), (circle, False)):
        f = vtkRidgeGrouping()
        f.SetInputData(make_points(points))
        f.SetWidth(8.0 if roads else 5.0)
        f.Update()
        contours = f.GetOutput(1).GetCellData()
        pixel = f.GetOutput(0).GetFieldData().GetArray("PixelSize").GetValue(0)
        loops = [contours.GetArray("Length").GetValue(c) / pixel for c in range(f.GetOutput(1).GetNumberOfCells())
                 if contours.GetArray("Closed").GetValue(c)]
        group = f.GetOutput(0).GetPointData().GetArray("GroupId")
        groups = [group.GetValue(i) for i in range(len(points))]
        if not roads:
            assert_that(len(loops) == 1 and loops[0] > 2 * math.pi * 5 and set(groups) == {0},
                        f"the circle: loops of {loops} pixels, groups {set(groups)}")
            continue
        assert_that(not loops, f"the roads: closed contours of {loops} pixels")
        assert_that(len(set(groups)) == 3 and adjusted_rand_index(groups, truth) > 0.8,
                    f"the roads: groups {sorted(set(groups))}, adjusted Rand index {adjusted_rand_index(groups, truth)}")
        node = f.GetOutput(0).GetPointData().GetArray("Node")
        for k in range(3):
            ids = [i for i in range(len(points)) if truth[i] == k and groups[i] == groups[300 * k + 150]]
            tau = kendall_tau([node.GetValue(i) for i in ids], [along[i] for i in ids])
            assert_that(abs(tau) > 0.9, f"road {k}: Node against the true parameter, Kendall tau {tau}")


def test_points_past_a_contour_end_are_not_named_as_far():
    # 100,000 points on three noisy sine roads: the contours stop short of the roads' ends, and the
    # points past them continue the curves (their nodes extended), some more than 10 basis widths
    # from the end pixel. Such points were named as far from their contour (1910 of them); now
    # only true outliers are.
    rng = np.random.default_rng(1)
    xy = []
    for k in range(3):
        t = np.sort(rng.random(33333))
        road = np.column_stack([1000 * t, 250 * k + 40 * np.sin(2 * np.pi * 1.5 * t + k)])
        xy.append(road + rng.normal(scale=8.0, size=road.shape))
    # Outliers: between two roads, 400 past the bottom road's end along it, and 150 to the side of
    # (and past) its end: the last two take the node of the last continuation, and were not named.
    end = xy[0][-1]
    xy = np.vstack(xy + [np.array([[500.0, 125.0 + 40 * np.sin(2 * np.pi * 0.75 + 0.5)],
                                   [end[0] + 400.0, end[1]], [end[0] + 20.0, end[1] - 150.0]])])
    f = vtkRidgeGrouping()
    warnings = warnings_of_update(f, make_points([tuple(p) for p in xy]))
    distance = f.GetOutput(0).GetPointData().GetArray("ContourDistance")
    width = 5.0 * f.GetOutput(0).GetFieldData().GetArray("PixelSize").GetValue(0)
    far = [i for i in range(len(xy)) if distance.GetValue(i) > 10 * width]
    outliers = list(range(len(xy) - 3, len(xy)))
    assert_that(set(outliers) <= set(far) and len(far) > 100, f"{len(far)} points beyond 10 widths: the test checks nothing")
    assert_that(all(xy[i][0] < 100 or xy[i][0] > 900 for i in far if i not in outliers),
                f"points beyond 10 widths away from the roads' ends: {[tuple(xy[i]) for i in far][:5]}")
    named = [w for w in warnings if "from the contour they are grouped by" in w]
    assert_that(len(named) == 1 and "3 point(s) lie more than 10 basis widths" in named[0]
                and "point(s) {}, {}, {} (".format(*outliers) in named[0], f"the far points named: {named}")


def test_bad_and_degenerate_input():
    f = vtkRidgeGrouping()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(make_points([(1.0, 2.0)]))
    f.Update()
    assert_that(f.GetOutputDataObject(2).GetNumberOfCells() == 0 and len(warnings) >= 1,
          f"one point: empty outputs with a warning {warnings}")
    same = vtkRidgeGrouping()
    same.SetInputData(make_points([(3.0, 3.0)] * 10))
    same.Update()
    g = same.GetOutput(0).GetPointData().GetArray("GroupId")
    assert_that({g.GetValue(i) for i in range(10)} == {0}, "identical points: one group")
    assert_that(same.GetOutputDataObject(2).GetNumberOfCells() == 0, "identical points: no curve")
    big = vtkRidgeGrouping()
    errors = messages_of(big)
    big.SetInputData(make_points(two_noisy_curves()[0]))
    big.SetImageSize(100000)
    big.Update()
    assert_that(len(errors) == 1 and "100000" in errors[0] and "memory" in errors[0],
          f"image size refused, naming it and the memory: {errors}")
    assert_that(big.GetOutputDataObject(3).GetNumberOfPoints() == 0, "no image allocated")
    nan = vtkRidgeGrouping()
    errors = messages_of(nan)
    nan.SetInputData(make_points([(0, 0), (1, math.nan), (2, 2)]))
    nan.Update()
    assert_that(len(errors) == 1 and "point 1" in errors[0], f"NaN point named: {errors}")
    # Joined from blocks: the joined id, and the point's own block and number in it.
    nan = vtkRidgeGrouping()
    errors = messages_of(nan)
    nan.SetInputData(points_in_blocks([(0, 0), (1, 1)], [(2, 0), (math.nan, 2)]))
    nan.Update()
    assert_that(len(errors) == 1 and "point 3 (point 1 of block 1 (composite index 2)) has a NaN" in errors[0],
                f"NaN point in a block named: {errors}")


def test_bad_settings_and_coordinates_are_errors_and_arrays_are_kept():
    """Settings out of range are errors naming them (they were clamped to other values, silently:
    Width -5 gave 15 groups for two curves), as are a basis width whose margins leave no room in
    the largest image (2^31 pixels overflowed) and points beyond +-1e306, each value as given (six
    decimals made -1e-9 "-0.000000"); points up to 2e305 give
    the same groups as at scale 1. Input arrays named GroupId or Node are passed as NAME_input."""
    coords, _, _ = two_noisy_curves()
    xs, ys = [x for x, _ in coords], [y for _, y in coords]
    cases = [("SetWidth", -5.0, "basis width -5"), ("SetWidth", 3e9, "leaves no room"),
             ("SetWidth", 1020.25, "basis width 1020.25 pixels leaves no room"),
             ("SetWidth", -1e-9, "basis width -1e-09 is not a positive number"),
             ("SetCurveSigma", 0.0, "curve sigma 0"), ("SetMinimumContourLength", -2.0, "minimum contour length -2"),
             # A width or sigma whose square underflows made NaN curves (no message) or a NaN pixel.
             ("SetCurveSigma", 1e-162, "curve sigma 1e-162 is below 1e-150"),
             # A sigma of half the curve or more made every curve a point near its points' mean.
             ("SetCurveSigma", 5.0, "curve sigma 5 is above 0.25"),
             ("SetWidth", 1e-170, "basis width 1e-170 is below 1e-150"),
             ("SetImageSize", -1, "image size -1 is negative")]
    for setter, value, expected in cases:
        f = vtkRidgeGrouping()
        errors = messages_of(f)
        getattr(f, setter)(value)
        f.SetInputData(make_points(list(zip(xs, ys))))
        f.Update()
        assert_that(len(errors) == 1 and expected in errors[0] and f.GetOutput(0).GetNumberOfPoints() == 0,
                    f"{setter}({value}): {errors}")

    def groups_at(scale):
        f = vtkRidgeGrouping()
        errors = messages_of(f)
        f.SetInputData(make_points([(x * scale, y * scale) for x, y in zip(xs, ys)]))
        f.Update()
        array = f.GetOutput(0).GetPointData().GetArray("GroupId")
        return [array.GetValue(i) for i in range(array.GetNumberOfTuples())] if array else None, errors

    unit, _ = groups_at(1.0)
    huge, errors = groups_at(2e305 / max(map(abs, xs + ys)))
    assert_that(not errors and huge == unit, f"points up to 2e305: the groups at scale 1 ({errors})")
    none, errors = groups_at(1e307 / max(map(abs, xs + ys)))
    assert_that(none is None and len(errors) == 1 and "beyond +-1e306" in errors[0], f"points of 1e307: {errors}")
    # Within +-1e306, a wide basis's margins can still carry the grid beyond the doubles.
    f = vtkRidgeGrouping()
    errors = messages_of(f)
    f.SetWidth(600)
    scale = 9e305 / max(map(abs, xs + ys))
    f.SetInputData(make_points([(x * scale, y * scale) for x, y in zip(xs, ys)]))
    f.Update()
    assert_that(len(errors) == 1 and "reaches beyond the largest double" in errors[0], f"a wide basis: {errors}")

    data = make_points(list(zip(xs, ys)), GroupId=[7.0] * len(xs), Node=[7.0] * len(xs))
    f = vtkRidgeGrouping()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputData(data)
    f.Update()
    out = f.GetOutput(0).GetPointData()
    kept = [out.GetArray(n) for n in ("GroupId_input", "Node_input")]
    assert_that(all(a is not None and a.GetValue(0) == 7.0 for a in kept)
                and out.GetArray("GroupId").GetValue(0) != 7.0, "the input's arrays kept under NAME_input")
    assert_that(any("'GroupId' is passed to output 0 as 'GroupId_input'" in w for w in warnings), f"warned: {warnings}")
    assert_that(data.GetPointData().GetArray("GroupId") is not None, "the input's own array keeps its name")
    # So are field-data arrays of the names of the filter's own (they were replaced silently).
    data.GetFieldData().AddArray(double_array("ImageSize", [4096.0]))
    f = vtkRidgeGrouping()
    warnings = warnings_of_update(f, data)
    fields = f.GetOutput(0).GetFieldData()
    assert_that(fields.GetArray("ImageSize_input").GetValue(0) == 4096.0
                and fields.GetArray("ImageSize").GetValue(0) <= 1024,  # the automatic size's largest
                "the input's ImageSize kept as ImageSize_input beside the filter's")
    assert_that(any("'ImageSize' is passed to output 0 as 'ImageSize_input'" in w for w in warnings),
                f"warned: {warnings}")
    # Points a few subnormal doubles apart: an error naming their extent (an allocation's error).
    f = vtkRidgeGrouping()
    errors = messages_of(f)
    f.SetInputData(make_points([(0.0, 0.0), (1e-322, 0.0), (5e-323, 1e-322)]))
    f.Update()
    assert_that(len(errors) == 1 and "extent 9.88131291682493e-323 is too small" in errors[0], f"subnormal: {errors}")



def test_the_field_image_is_advertised_before_it_is_made():
    """Output 3's extent, origin and spacing are known from the pipeline information, before
    RequestData, and equal the image made; an image filter downstream then gets every pixel (it
    asked for the advertised empty extent, and ParaView showed the image as nothing)."""
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    from vtkmodules.vtkImagingCore import vtkImageShiftScale

    coords, _, _ = two_noisy_curves()
    for size in (0, 200):
        f = vtkRidgeGrouping()
        f.SetInputData(make_points(coords))
        f.SetImageSize(size)
        f.UpdateInformation()
        info = f.GetOutputInformation(3)
        advertised = (info.Get(vtkStreamingDemandDrivenPipeline.WHOLE_EXTENT()), info.Get(f.GetOutputDataObject(3).ORIGIN()),
                      info.Get(f.GetOutputDataObject(3).SPACING()))
        scaled = vtkImageShiftScale()
        scaled.SetInputConnection(f.GetOutputPort(3))
        scaled.SetScale(2.0)
        scaled.Update()
        image = f.GetOutputDataObject(3)
        made = (image.GetExtent(), image.GetOrigin(), image.GetSpacing())
        assert_that(image.GetNumberOfPoints() > 1000 and advertised == made,
                    f"size {size}: advertised {advertised}, made {made}")
        assert_that(scaled.GetOutput().GetNumberOfPoints() == image.GetNumberOfPoints(),
                    f"size {size}: downstream {scaled.GetOutput().GetNumberOfPoints()} of {image.GetNumberOfPoints()}")



def test_the_image_is_advertised_from_the_whole_input_when_its_source_gave_a_piece():
    """The extent is advertised from the whole input even when the source last gave a piece (in
    ParaView under MPI, to its own representation): RequestInformation updated it as it stood, a
    third of the points, and the image made from all of them differed from the one announced."""
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
    from vtkmodules.vtkFiltersGeneral import vtkImageDataToPointSet
    from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

    source = vtkRTAnalyticSource()
    source.SetWholeExtent(0, 29, 0, 29, 0, 0)
    points = vtkImageDataToPointSet()
    points.SetInputConnection(source.GetOutputPort())
    points.UpdatePiece(2, 3, 0)  # a sibling consumer asked for the last third
    assert_that(points.GetOutput().GetNumberOfPoints() < 900, "the source gave a piece")
    f = vtkRidgeGrouping()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    f.SetInputConnection(points.GetOutputPort())
    f.UpdateInformation()
    announced = f.GetOutputInformation(3).Get(vtkStreamingDemandDrivenPipeline.WHOLE_EXTENT())
    f.Update()
    made = f.GetOutputDataObject(3).GetExtent()
    assert_that(f.GetOutput(0).GetNumberOfPoints() == 900 and announced == made
                and not [w for w in warnings if "differs from the one announced" in w],
                f"announced {announced}, made {made}: {warnings}")



def test_a_time_varying_input_is_grouped_at_each_time_with_an_image_consumer():
    """An ellipse whose height changes with time, its field image consumed downstream: each time's
    points are grouped (at the second time the pipeline stopped on VTK's extent errors and the
    outputs stayed at the first), and the image keeps the announced extent, a grid of another size
    given on it with a warning."""
    import math

    from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase
    from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
    from vtkmodules.vtkImagingCore import vtkImageCast

    class Ellipse(VTKPythonAlgorithmBase):
        def __init__(self):
            VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1, outputType="vtkPolyData")

        def RequestInformation(self, request, inInfo, outInfo):
            info = outInfo.GetInformationObject(0)
            info.Remove(sddp.TIME_STEPS())
            for t in (1.0, 2.0, 3.0):
                info.Append(sddp.TIME_STEPS(), t)
            info.Set(sddp.TIME_RANGE(), [1.0, 3.0], 2)
            return 1

        def RequestData(self, request, inInfo, outInfo):
            info = outInfo.GetInformationObject(0)
            t = info.Get(sddp.UPDATE_TIME_STEP()) if info.Has(sddp.UPDATE_TIME_STEP()) else 1.0
            points = vtkPoints()
            for k in range(300):
                a = 2 * math.pi * k / 300
                points.InsertNextPoint(100 * math.cos(a), 30 * t * math.sin(a), 0)
            vtkPolyData.GetData(outInfo).SetPoints(points)
            return 1

    source = Ellipse()
    f = vtkRidgeGrouping()
    warnings = messages_of(f, vtkCommand.WarningEvent)
    errors = messages_of(f, vtkCommand.ErrorEvent)
    f.SetInputConnection(source.GetOutputPort())
    consumer = vtkImageCast()
    consumer.SetOutputScalarTypeToFloat()
    consumer.SetInputConnection(f.GetOutputPort(3))
    executive_errors = []
    consumer.GetExecutive().AddObserver("ErrorEvent", lambda o, e: executive_errors.append(e))
    for t in (1.0, 3.0, 2.0, 1.0):
        consumer.UpdateTimeStep(t)
        height = f.GetOutputDataObject(0).GetBounds()[3]
        assert_that(abs(height - 30 * t) < 1e-9, f"t = {t}: points up to y = {height}")
        dims = f.GetOutputDataObject(3).GetDimensions()
        assert_that(consumer.GetOutput().GetDimensions() == dims == (128, 49, 1), f"t = {t}: image {dims}")
    assert_that(not errors and not executive_errors, f"{errors} {executive_errors}")
    assert_that(sum("differs from the one announced" in w for w in warnings) == 2, f"{warnings}")


def test_a_basis_or_join_rule_that_is_no_choice_is_named():
    # SetBasis(5) ran the Gaussian and SetJoinRule(-1) the longest contour, silently (clamped).
    # The ranges the clamping setters announced are still there (and the classes' layout with them).
    coords, _, _ = two_noisy_curves()
    f = vtkRidgeGrouping()
    assert_that((f.GetBasisMinValue(), f.GetBasisMaxValue(), f.GetJoinRuleMinValue(), f.GetJoinRuleMaxValue())
                == (0, 1, 0, 1), "the ranges")
    for setup, expected in [(lambda f: f.SetBasis(5), "Basis 5 is not one of 0 (InverseMultiquadric), 1 (Gaussian)"),
                            (lambda f: f.SetJoinRule(-1), "JoinRule -1 is not one of 0 (Longest), 1 (ClosestTangent)")]:
        f = vtkRidgeGrouping()
        errors = messages_of(f)
        setup(f)
        f.SetInputData(make_points(coords))
        f.Update()
        assert_that(len(errors) == 1 and expected in errors[0] and f.GetOutput(0).GetNumberOfPoints() == 0, f"{errors}")


def test_duplicates_are_listed_and_points_off_the_plane_named():
    # From a trial: a Python user got no word of repeated points (only the example script named
    # them), and a curve in the x-z plane was grouped as a straight line, silently. The repeats are
    # found here by a dictionary of places, independently of the filter's sort.
    coords, _, _ = two_noisy_curves()
    coords = coords + [coords[3], coords[3], coords[17], coords[3]]  # points 600-603
    first, expected = {}, []
    for k, place in enumerate(coords):
        earlier = first.setdefault(place, k)
        if earlier != k:
            expected.append((k, earlier))
    f = vtkRidgeGrouping()
    warnings = warnings_of_update(f, make_points(coords))
    fd = f.GetOutput(0).GetFieldData()
    got = [(fd.GetArray("DuplicatePointIds").GetValue(k), fd.GetArray("DuplicateOfPointIds").GetValue(k))
           for k in range(fd.GetArray("DuplicatePointIds").GetNumberOfTuples())]
    assert_that(got == expected == [(600, 3), (601, 3), (602, 17), (603, 3)], f"duplicates {got}, expected {expected}")
    said = [w for w in warnings if "at the x and y of an earlier point" in w]
    assert_that(len(said) == 1 and "4 point(s)" in said[0] and "point 602 (of point 17)" in said[0], f"{warnings}")
    groups = f.GetOutput(0).GetPointData().GetArray("GroupId")
    assert_that(all(groups.GetValue(k) == groups.GetValue(e) for k, e in expected), "a repeat joins its original's group")
    assert_that(not any("z runs" in w for w in warnings), f"points at z = 0: no word of z {warnings}")
    # Without repeats: empty arrays, no warning.
    f = vtkRidgeGrouping()
    warnings = warnings_of_update(f, make_points(coords[:600]))
    fd = f.GetOutput(0).GetFieldData()
    assert_that(fd.GetArray("DuplicatePointIds").GetNumberOfTuples() == 0
                and not any("earlier point" in w for w in warnings), f"{warnings}")
    # The curves drawn in the x-z plane (y = 0): z's range is named.
    upright = make_points([(x, 0.0) for x, _ in coords[:600]])
    for k, (_, y) in enumerate(coords[:600]):
        upright.GetPoints().SetPoint(k, upright.GetPoint(k)[0], 0.0, y)
    lowest, highest = min(y for _, y in coords[:600]), max(y for _, y in coords[:600])
    warnings = warnings_of_update(vtkRidgeGrouping(), upright)
    said = [w for w in warnings if "z runs from" in w]
    assert_that(len(said) == 1 and f"z runs from {lowest!r} to {highest!r}: only x and y are read" in said[0],
                f"{warnings}")


def test_progress_goes_by_stages_and_an_abort_empties_the_outputs():
    # From a trial: the progress bar sat at 5% for the seconds of the field. Now each core stage
    # reports; an abort asked in the middle stops the run with empty outputs and no error.
    coords, _, _ = two_noisy_curves()
    f = vtkRidgeGrouping()
    seen = []
    f.AddObserver(vtkCommand.ProgressEvent, lambda o, e: seen.append(o.GetProgress()))
    f.SetInputData(make_points(coords))
    f.Update()
    inner = [p for p in seen if 0.05 < p < 0.9]
    assert_that(seen == sorted(seen) and seen[-1] == 1.0 and len(set(inner)) >= 3, f"progress {seen}")
    stopped = vtkRidgeGrouping()
    errors = messages_of(stopped)
    stopped.AddObserver(vtkCommand.ProgressEvent,
                        lambda o, e: o.SetAbortExecute(1) if 0.5 < o.GetProgress() < 0.9 else None)
    stopped.SetInputData(make_points(coords))
    stopped.Update()
    assert_that(not errors and all(stopped.GetOutputDataObject(k).GetNumberOfPoints() == 0 for k in range(4)),
                f"aborted: {errors}, {[stopped.GetOutputDataObject(k).GetNumberOfPoints() for k in range(4)]}")


if __name__ == "__main__":
    run([test_two_noisy_curves_are_grouped_ordered_and_fitted, test_no_loop_smaller_than_the_basis_makes_a_closed_group,
         test_points_past_a_contour_end_are_not_named_as_far,
         test_bad_and_degenerate_input,
         test_bad_settings_and_coordinates_are_errors_and_arrays_are_kept,
         test_the_field_image_is_advertised_before_it_is_made,
         test_the_image_is_advertised_from_the_whole_input_when_its_source_gave_a_piece,
         test_a_time_varying_input_is_grouped_at_each_time_with_an_image_consumer,
         test_a_basis_or_join_rule_that_is_no_choice_is_named,
         test_duplicates_are_listed_and_points_off_the_plane_named,
         test_progress_goes_by_stages_and_an_abort_empties_the_outputs])
