#!/usr/bin/env python3
"""Group the Fiji earthquake epicentres into curves with Goshtasby's ridge grouping.

1000 seismic events near Fiji (R's `quakes` data; longitudes pass 180) trace the Tonga trench and
a second arc. The epicentres are projected with vtkGeographicProjection (automatic equal-area
conic, antimeridian-aware), grouped by the ridges of a radial field with vtkRidgeGrouping, ordered
along each ridge contour (Node) and described by rational Gaussian curves.

Writes into --out, each name beginning with --prefix (fiji for the Fiji file, else the input
file's name without its extension: your_points.csv gives your_points_groups.png, ...):
  fiji_groups.png        points coloured by group, ridge contours, fitted curves (km; --planar:
                         the file's unit)
  fiji_points.vtp        output 0: points with GroupId, Node and ContourDistance (+ depth_km, mag)
  fiji_contours.vtp      output 1: ridge contours (ContourId, Closed, Length)
  fiji_curves.vtp        output 2: fitted curves (GroupId, Closed)
  fiji_field.vti         output 3: the field image (Field, MinorRidge, MajorRidge)

With --planar the file's points are plane coordinates already (columns x, y, in any one unit) and
are grouped as they are, without a projection.

A point at the place of an earlier one is grouped as any other, and named in a warning with its
line and the earlier one's; the Fiji file's two such pairs (events at one rounded epicentre) are
only noted, in a line on stdout.

Run with Debian's /usr/bin/python3 and PYTHONPATH=build/python.
"""

import argparse
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import csv_input  # noqa: E402 (the examples' CSV reading, beside this script)

DEFAULT_QUAKES = os.path.join(HERE, "data", "fiji_quakes.csv")


def read_quakes(path, planar=False):
    """The file's points (lon, lat; x, y when planar) with depth and mag, and each point's line."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData

    points = vtkPoints()
    points.SetDataTypeToDouble()
    depth, mag = vtkDoubleArray(), vtkDoubleArray()
    depth.SetName("depth_km")
    mag.SetName("mag")
    lines = []
    def passenger(row, column, line):
        """depth and mag only ride along (the grouping uses neither): absent or missing is NaN."""
        if csv_input.is_missing(row.get(column)):
            return math.nan
        return csv_input.number(row, column, path, line)

    x, y = ("x", "y") if planar else ("lon", "lat")
    wanted = (x, y) if planar else (y, x)  # (as the messages name them: x, y; lat, lon)
    what = "points" if planar else "epicentres"
    columns = {c.lower() for c in csv_input.header_columns(path, what, wanted)}
    if not planar and {"x", "y"} <= columns and not {"lat", "lon"} & columns:
        csv_input.fail(f"{path}: the file has columns x, y and no lat, lon: for plane coordinates, "
                       f"give --planar")
    if planar and {"lat", "lon"} <= columns and not {"x", "y"} & columns:
        csv_input.fail(f"{path}: the file has columns lat, lon and no x, y: for latitudes and longitudes "
                       f"(projected before grouping), leave out --planar")
    for line, row in csv_input.rows(path, wanted, what, optional=("depth", "mag")):
        lines.append(line)
        points.InsertNextPoint(csv_input.number(row, x, path, line), csv_input.number(row, y, path, line), 0.0)
        depth.InsertNextValue(passenger(row, "depth", line))
        mag.InsertNextValue(passenger(row, "mag", line))
    data = vtkPolyData()
    data.SetPoints(points)
    data.GetPointData().AddArray(depth)
    data.GetPointData().AddArray(mag)
    return data, lines


def projected(quakes, path, lines, vtkGeographicProjection):
    """The epicentres projected (the automatic equal-area conic); an error ends the run."""
    errors = []
    projection = vtkGeographicProjection()
    projection.SetInputData(quakes)
    # An epicentre the projection rejects (a latitude beyond 90) or a grouping error ends the run
    # with one line naming the file (and the epicentre's line), not VTK's log and the executive's
    # dump of its request. The projection runs on its own first: a failed projection's output is
    # empty, and the grouping would warn about its 0 points before the line that says why.
    csv_input.catch_vtk_messages(projection, lambda text: errors.append(
        csv_input.point_error(text, path, lines, lambda g: "epicentre")
        or f"{path}: cannot project the epicentres: {text}"),
        lambda text: print(f"warning: {path}: {projection_warning(text)}", file=sys.stderr))
    projection.Update()
    if errors:
        csv_input.fail(errors[0])
    if projection.GetOutput().GetNumberOfPoints() != quakes.GetNumberOfPoints():
        csv_input.fail(f"{path}: the projection of the epicentres failed and gave no message")
    return projection.GetOutput()


def projection_warning(text):
    """The projection's warning as the script says it: its advice on settings, which the script
    does not have, is replaced by what can be done here, and a cut conic's "tiles" are curves."""
    text = text.replace("so their tiles do not meet", "so a curve across it is cut in two")
    text = re.sub(r"; for data round a pole, .*$", "", text)
    return (f"{text} (this script projects with the automatic equal-area conic: to group them in another "
            "projection, project them yourself and give x, y with --planar)")


def image_size(text):
    """--image-size's value: an int the filter's setter takes (it raised OverflowError beyond)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of pixels")
    if not -2**31 <= value < 2**31:
        raise argparse.ArgumentTypeError(f"{text} pixels is out of range (the largest image is 2048)")
    return value


# The filter's errors about a setting begin with its name in words: the option that sets it.
OPTION_OF_SETTING = {"basis width": "--width", "image size": "--image-size", "curve sigma": "--curve-sigma",
                     "minimum contour length": "--minimum-contour-length"}


def grouping_error(text):
    """The grouping filter's error as one line, naming the script's option for a bad setting."""
    for setting, option in OPTION_OF_SETTING.items():
        if text.startswith(setting + " "):
            return f"{option}: {text}"
    return f"ridge grouping failed: {text}"


def with_lines(text, path, lines):
    """A warning that lists points by id ("point(s) 69, 397", "point 12"), with their lines in the file."""
    def lines_of(match):
        ids = [int(k) for k in re.findall(r"\d+", match.group(1))]
        if not ids or max(ids) >= len(lines):
            return match.group(0)
        return f"{match.group(0)} (line(s) {', '.join(str(lines[k]) for k in ids)} of {path})"
    return re.sub(r"point(?:\(s\))? (\d+(?:, \d+)*)", lines_of, text)


def prefix_error(prefix):
    """Why --prefix cannot start the output files' names, or None: the files go into --out, and a
    prefix with a path separator would put them elsewhere (../escape, outside --out) or into a
    directory that is not there (a/b, found once the grouping is done); an empty one, . or .. is no
    name's start."""
    separators = sorted({os.sep, "/", os.altsep} - {None})
    if not prefix.strip():
        return f"--prefix {prefix!r}: an empty prefix (give the start of the files' names, such as fiji)"
    if prefix in (".", ".."):
        return f"--prefix {prefix!r}: is not the start of a file's name (give one such as fiji)"
    held = [separator for separator in separators if separator in prefix]
    if held:
        return (f"--prefix {prefix!r}: holds the path separator {held[0]!r}; give the start of the files' names "
                "alone (they go into --out: give the directory there)")
    return None


def say_repeated_points(quakes, path, lines, planar, bundled=False):
    """Says the points that repeat an earlier point's place (csv_input.say_repeats): each is still
    grouped as a point of its own, and a place given twice weighs twice in the field. bundled: the
    file is the example's own Fiji file, whose two pairs of events at one rounded epicentre are
    known: a short note on stdout says so, not a warning on every run of the demo."""
    x, y = ("x", "y") if planar else ("lon", "lat")
    place = [quakes.GetPoint(k)[:2] for k in range(quakes.GetNumberOfPoints())]
    if bundled:
        found = csv_input.repeats(place)
        if found:
            print(f"note: {len(found)} epicentre(s) of the Fiji file repeat an earlier one's place (lines "
                  + ", ".join(f"{lines[k]} as {lines[first]}" for k, first in found)
                  + "; events at one rounded epicentre), each grouped as a point of its own")
        return
    csv_input.say_repeats(path, lines, place,
                          f"{'point(s)' if planar else 'epicentre(s)'} repeat the {x}, {y} of an earlier one (each is "
                          "grouped, a point of its own: the place weighs as often in the field)",
                          lambda k, first: f"{x} {place[k][0]:.15g}, {y} {place[k][1]:.15g}", "point")


def say_grouping_warning(text, path, lines):
    """The grouping filter's warning on stderr, its points with their lines; but not its repeated
    points, which say_repeated_points said with their places (or, for the Fiji file, noted)."""
    if DUPLICATES_WARNING not in text:
        print(f"warning: {with_lines(text, path, lines)}", file=sys.stderr)


# (the start of vtkRidgeGrouping's warning of points at the place of an earlier one)
DUPLICATES_WARNING = "point(s) lie at the x and y of an earlier point"


def polylines(data):
    lines = []
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        lines.append([data.GetPoint(ids.GetId(k))[:2] for k in range(ids.GetNumberOfIds())])
    return lines


# The Fiji file's settings, where another file gets the filter's defaults.
FIJI_SETTINGS = {"width": 4.0, "curve_sigma": 0.1, "minimum_contour_length": 15.0}


def chosen_settings(args, fiji, grouping):
    """Width, curve sigma and minimum contour length: those given, else the Fiji file's settings for
    the Fiji file and the defaults of grouping (a new vtkRidgeGrouping) for any other."""
    defaults = FIJI_SETTINGS if fiji else {"width": grouping.GetWidth(), "curve_sigma": grouping.GetCurveSigma(),
                                           "minimum_contour_length": grouping.GetMinimumContourLength()}
    return {name: getattr(args, name) if getattr(args, name) is not None else value
            for name, value in defaults.items()}


def argument_parser():
    """The script's options, in the order --help lists them."""
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quakes", default=DEFAULT_QUAKES,
                        help=f"CSV of epicentres: columns lat, lon (degrees; also read as latitude, longitude, "
                             f"long or lng; with --planar, x, y), and optionally depth and mag "
                             f"(carried to the output, not used; empty or missing values are NaN); "
                             f"{csv_input.SEPARATORS_TEXT} (default: examples/data/fiji_quakes.csv)")
    parser.add_argument("--planar", action="store_true",
                        help="the file's columns x, y are plane coordinates (any one unit), grouped without a "
                             "projection, in place of lat, lon")
    parser.add_argument("--out", default="out", help="output directory, created if missing (default: out)")
    parser.add_argument("--prefix", default=None,
                        help="start of the output files' names, without a path separator (the files go into "
                             "--out; default: fiji for the Fiji file, else the input file's name without its "
                             "extension)")
    add_grouping_options(parser)
    return parser


def add_grouping_options(parser):
    """The settings of the grouping filter."""
    # (the Fiji file's settings differ from the filter's defaults, which another file gets: tuned to
    # the scattered epicentres, CurveSigma 0.1 drew a smooth curve 3.9 units off a clean S curve)
    parser.add_argument("--width", type=float, default=None,
                        help="basis width in pixels, at most 1020 (default: the filter's, 5; for the Fiji file "
                             f"{FIJI_SETTINGS['width']}, since 5 merges the southern half of the trench with the "
                             "cluster north of it)")
    parser.add_argument("--image-size", type=image_size, default=0,
                        help="pixels along the longer side, 0 for automatic (default %(default)s), else at most 2048 "
                             "and at least 2 (ceil(width) + 2) + 3 (17 at width 5)")
    parser.add_argument("--curve-sigma", type=float, default=None,
                        help="RaG curve smoothness (node units: a share of each curve's length; default: the "
                             "filter's, the paper's 0.04; for the Fiji file "
                             f"{FIJI_SETTINGS['curve_sigma']}, which draws the arcs' course through the scattered "
                             "epicentres; a closed curve's radius shrinks by 3%% at 0.04, 18%% at 0.1)")
    parser.add_argument("--minimum-contour-length", type=float, default=None,
                        help="pixels (default: the filter's, 10; for the Fiji file "
                             f"{FIJI_SETTINGS['minimum_contour_length']}, which leaves out the shorter ridges of "
                             "scattered events)")
    parser.add_argument("--gaussian", action="store_true", help="Gaussian basis instead of inverse multiquadric")
    parser.add_argument("--closest-tangent", action="store_true", help="closest-tangent join rule")


def main(argv=None):
    args = argument_parser().parse_args(argv)
    # (what is wrong with the options is said before any work: the grouping takes seconds)
    problem = prefix_error(args.prefix) if args.prefix is not None else None
    if problem:
        csv_input.fail(problem)
    csv_input.check_paths(("--quakes", args.quakes, "points" if args.planar else "epicentres"))

    # Tessera first: without VTK (another Python than Debian's) this says how to run the script.
    tessera = csv_input.import_tessera()
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLPolyDataWriter
    vtkGeographicProjection, vtkRidgeGrouping = tessera.vtkGeographicProjection, tessera.vtkRidgeGrouping

    csv_input.output_directory(args.out)
    quakes, lines = read_quakes(args.quakes, args.planar)
    if quakes.GetNumberOfPoints() == 0:
        csv_input.fail(f"{args.quakes}: no {'points' if args.planar else 'epicentres'} to group (the file has no rows)")
    grouped = quakes if args.planar else projected(quakes, args.quakes, lines, vtkGeographicProjection)
    # (said once the projection has taken the epicentres: one it rejects is the run's one line)
    # (the bundled file as the script reads it: with --planar it is refused for its lat, lon)
    fiji = os.path.abspath(args.quakes) == os.path.abspath(DEFAULT_QUAKES) and not args.planar
    say_repeated_points(quakes, args.quakes, lines, args.planar, bundled=fiji)
    grouping = run_grouping(args, grouped, lines, fiji, vtkRidgeGrouping)
    names = write_outputs(args, grouping, fiji, vtkXMLPolyDataWriter, vtkXMLImageDataWriter)
    summary = grouping_summary(grouping.GetOutput(0), args.planar)
    plot_groups(args, grouping, fiji, summary, os.path.join(args.out, names["groups.png"]))
    print(summary)
    print(f"wrote {args.out}/" + ", ".join(names.values()))


def run_grouping(args, grouped, lines, fiji, vtkRidgeGrouping):
    """The grouping filter with the options' settings, run on grouped (the points projected, or as
    given with --planar): its outputs are the groups, contours, curves and field. Its error ends
    the script."""
    errors = []
    grouping = vtkRidgeGrouping()
    settings = chosen_settings(args, fiji, grouping)
    csv_input.catch_vtk_messages(grouping, lambda text: errors.append(grouping_error(text)),
                                 lambda text: say_grouping_warning(text, args.quakes, lines))
    grouping.SetInputData(grouped)
    grouping.SetWidth(settings["width"])
    grouping.SetImageSize(args.image_size)
    grouping.SetCurveSigma(settings["curve_sigma"])
    grouping.SetMinimumContourLength(settings["minimum_contour_length"])
    if args.gaussian:
        grouping.SetBasisToGaussian()
    if args.closest_tangent:
        grouping.SetJoinRuleToClosestTangent()
    grouping.Update()
    if errors:
        csv_input.fail(errors[0])
    if grouping.GetOutput(0).GetNumberOfPoints() == 0:
        csv_input.fail("ridge grouping failed and gave no message")
    return grouping


def write_outputs(args, grouping, fiji, vtkXMLPolyDataWriter, vtkXMLImageDataWriter):
    """Writes the grouping's four outputs into --out. Returns the output files' names, by their
    part after the prefix (the plot's too, written later)."""
    prefix = args.prefix if args.prefix is not None else (
        "fiji" if fiji else os.path.splitext(os.path.basename(args.quakes))[0])
    names = {part: f"{prefix}_{part}" for part in ("groups.png", "points.vtp", "contours.vtp", "curves.vtp",
                                                   "field.vti")}
    for port, part in ((0, "points.vtp"), (1, "contours.vtp"), (2, "curves.vtp")):
        csv_input.write_vtk(vtkXMLPolyDataWriter(), grouping.GetOutputDataObject(port),
                            os.path.join(args.out, names[part]))
    csv_input.write_vtk(vtkXMLImageDataWriter(), grouping.GetOutputDataObject(3),
                        os.path.join(args.out, names["field.vti"]))
    return names


def plot_scale(planar):
    """The plot's unit in the points' own."""
    # Plotted in km when projected (metres), else in the file's own unit.
    return 1.0 if planar else 1000.0


def group_ids(points):
    """Each point's GroupId (-1: unassigned)."""
    groups = points.GetPointData().GetArray("GroupId")
    return [groups.GetValue(i) for i in range(points.GetNumberOfPoints())]


def grouping_summary(points, planar):
    """The line that sums up the grouping (points: its output 0): groups, points unassigned, the
    image's size and pixel."""
    ids = group_ids(points)
    fd = points.GetFieldData()
    scale = plot_scale(planar)
    pixel = fd.GetArray("PixelSize").GetValue(0)
    return (f"{len(set(ids) - {-1})} groups, {ids.count(-1)} points unassigned; image "
            f"{int(fd.GetArray('ImageSize').GetValue(0))} px, pixel "
            + (f"{pixel:.4g}" if planar else f"{pixel / scale:.1f} km"))


def plot_groups(args, grouping, fiji, summary, path):
    """Plots the points coloured by group, the ridge contours and the fitted curves into path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    points = grouping.GetOutput(0)
    ids = group_ids(points)
    scale = plot_scale(args.planar)
    fig, ax = plt.subplots(figsize=(7, 9))
    xs = [points.GetPoint(i)[0] / scale for i in range(points.GetNumberOfPoints())]
    ys = [points.GetPoint(i)[1] / scale for i in range(points.GetNumberOfPoints())]
    ax.scatter(xs, ys, c=[g if g >= 0 else -5 for g in ids], cmap="tab10", s=7,
               label=("epicentres" if fiji else "points") + " (by group)")
    for k, line in enumerate(polylines(grouping.GetOutputDataObject(1))):
        lx, ly = zip(*line)
        ax.plot([x / scale for x in lx], [y / scale for y in ly], color="grey", linewidth=0.8,
                linestyle="--", label="ridge contours" if k == 0 else None)
    for k, line in enumerate(polylines(grouping.GetOutputDataObject(2))):
        lx, ly = zip(*line)
        ax.plot([x / scale for x in lx], [y / scale for y in ly], color="black", linewidth=1.6,
                label="fitted RaG curves" if k == 0 else None)
    ax.set_aspect("equal")
    ax.set_xlabel("x" if args.planar else "x (km, equal-area conic)")
    ax.set_ylabel("y" if args.planar else "y (km)")
    title = "Fiji epicentres" if fiji else os.path.basename(args.quakes) + ": points"
    ax.set_title(title + " grouped by ridges\n" + summary, fontsize=10)
    ax.legend(loc="lower left" if fiji else "best", fontsize=8)  # (Fiji: its empty corner)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    csv_input.run(main)
