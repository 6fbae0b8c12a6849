"""Projected coordinates made longitude/latitude, for the main job (colorado_areal_precipitation.py):
a catchment file that declares a projected coordinate system (a shapefile's .prj, a GeoJSON
"crs"), and a stations file of x and y columns given --stations-utm or --stations-crs.

The systems read are those GDAL writes in PROJ's terms as +proj=utm, tmerc (transverse Mercator),
aea (Albers equal-area conic), lcc (Lambert conformal conic, with one or two standard parallels),
laea (Lambert azimuthal equal-area, as LAEA Europe, EPSG:3035) and merc (Mercator, as EPSG:3395,
or on the sphere of WGS84's radius, the web maps' EPSG:3857), in metres or feet, with any order
and direction of axes (+axis: EPSG:2053's westings and southings) and prime meridian (+pm: Paris's
NTF zones), on an ellipsoid (another sphere's, +R=, is refused: its inverse differs by
kilometres). Each is made lon/lat by vtkGeographicProjection's inverse, given the system's grid:
its false easting and northing (+x_0, +y_0), scale (+k_0, or a Mercator's +lat_ts) and, for the
conics and the transverse Mercator, its latitude of origin (+lat_0). The file's x, y are only
made eastings and northings in metres first (its unit and axes).

The filter's ellipsoid is WGS84's. NAD83 and ETRS89 (GRS80) lie within a metre or two of it;
another datum (NAD27, ED50, OSGB36, or Israel 1993 on GRS80 but 78 m away) is warned of.
"""

import collections
import contextlib
import math
import os
import re
import sys

import csv_input

# What each PROJ projection is in vtkGeographicProjection (SetProjectionTo<name>).
KINDS = {"tmerc": "TransverseMercator", "aea": "AlbersEqualArea", "lcc": "LambertConformalConic",
         "laea": "LambertAzimuthalEqualArea", "merc": "Mercator", "webmerc": "WebMercator"}
READ = ("UTM, transverse Mercator (tmerc), Albers equal-area (aea), Lambert conformal conic (lcc), Lambert "
        "azimuthal equal-area (laea) and Mercator (merc, and the web maps' EPSG:3857)")

# The web maps' Mercator (EPSG:3857) is the sphere's formulas on a sphere of WGS84's equatorial
# radius, applied to WGS84 latitudes; GDAL writes it +proj=merc +a=6378137 +b=6378137.
WEB_RADIUS = 6378137.0
WGS84_E2 = 0.0066943799901413165  # (f (2 - f), f = 1 / 298.257223563)

# Metres per unit of PROJ's +units (GDAL writes +to_meter for others).
UNITS = {"m": 1.0, "km": 1000.0, "ft": 0.3048, "us-ft": 1200.0 / 3937.0}

# PROJ's named prime meridians (+pm), in degrees east of Greenwich (PROJ's pj_prime_meridians).
PRIME_MERIDIANS = {"greenwich": 0.0, "lisbon": -9.131906111111, "paris": 2.337229166667,
                   "bogota": -74.080916666667, "madrid": -3.687938888889, "rome": 12.452333333333,
                   "bern": 7.439583333333, "jakarta": 106.807719444444, "ferro": -17.666666666667,
                   "brussels": 4.367975, "stockholm": 18.058277777778, "athens": 23.7163375,
                   "oslo": 10.722916666667, "copenhagen": 12.577875}

# GeographicLib's UTM limits (UTMUPS, without MGRS's): a zone's grid reaches across the equator, so
# a northern zone's northings go below 0 and a southern zone's above 10,000,000 m (GDAL and PROJ
# write them so for a catchment on the equator).
UTM_RANGE = ("eastings 0 to 1,000,000 m; northings -9,100,000 to 9,600,000 m in a northern zone, "
             "900,000 to 19,600,000 m in a southern one")
UTM_NORTHINGS = {True: (-9.1e6, 9.6e6), False: (0.9e6, 19.6e6)}  # by hemisphere: north is True

# A projected file's edges are straight in metres, which unprojected to lon/lat they are not: an
# edge of 10 km at 40N bows some 2 m from the lon/lat line between its ends, one of 1 km 2 cm. Cut
# into pieces of 1 km before the inverse, the catchment keeps its shape to centimetres.
EDGE_METRES = 1000.0


class PlaneSystem:
    """A projected coordinate system that is read here: the filter's projection (kind: a key of
    KINDS, or "utm") and PROJ's parameters: origin (lon0, lat0), standard parallels (lat1, lat2),
    scale k0, false easting and northing (x0, y0, metres), metres per unit, and the axes (PROJ's
    +axis: "enu", x east and y north; "wsu", westings and southings; "neu", northings first). lon0 is
    east of Greenwich (a +pm is added in)."""

    def __init__(self, kind, lon0=0.0, lat0=0.0, lat1=0.0, lat2=0.0, k0=1.0, x0=0.0, y0=0.0, metres=1.0,
                 zone=0, north=True, axis="enu"):
        self.kind, self.lon0, self.lat0, self.lat1, self.lat2 = kind, lon0, lat0, lat1, lat2
        self.k0, self.x0, self.y0, self.metres, self.zone, self.north = k0, x0, y0, metres, zone, north
        self.axis = axis

    @classmethod
    def utm(cls, zone, north, metres=1.0, axis="enu"):
        return cls("utm", zone=zone, north=north, metres=metres, axis=axis)

    def to_grid(self, x, y):
        """A file's (x, y) (numbers or numpy arrays) as the filter's grid takes them: eastings and northings in
        metres."""
        a, b = x * self.metres, y * self.metres
        first = -a if self.axis[0] in "ws" else a
        second = -b if self.axis[1] in "ws" else b
        return (first, second) if self.axis[0] in "ew" else (second, first)

    def from_grid(self, east, north):
        """The file's (x, y) of the filter grid's (east, north) in metres: to_grid undone."""
        first, second = (east, north) if self.axis[0] in "ew" else (north, east)
        a = -first if self.axis[0] in "ws" else first
        b = -second if self.axis[1] in "ws" else second
        return a / self.metres, b / self.metres

    def describe(self):
        """As the messages name it: "UTM zone 13N, WGS84" or "AlbersEqualArea lon_0=-96 lat_0=23
        lat_1=29.5 lat_2=45.5 x_0=0 y_0=0, WGS84"."""
        extra = (f", {self.metres:.10g} m per unit" if self.metres != 1.0 else "") + (
            f", axes {self.axis}" if self.axis != "enu" else "")
        if self.kind == "utm":
            return f"UTM zone {self.zone}{'N' if self.north else 'S'}{extra}, WGS84"
        terms = [f"lon_0={self.lon0:g}", f"lat_0={self.lat0:g}"]
        if self.kind in ("aea", "lcc"):
            terms += [f"lat_1={self.lat1:g}", f"lat_2={self.lat2:g}"]
        if self.kind in ("merc", "webmerc"):
            terms = terms[:1]  # (the origin is on the equator)
        if self.k0 != 1.0:
            terms.append(f"k_0={self.k0:.10g}")
        terms += [f"x_0={self.x0:.10g}", f"y_0={self.y0:.10g}"]
        return f"{KINDS[self.kind]} {' '.join(terms)}{extra}, WGS84"


def proj_terms(text):
    """PROJ terms ("+proj=aea +lat_1=29.5 +no_defs") as a dict: {"proj": "aea", "lat_1": "29.5",
    "no_defs": ""}."""
    return dict(term[1:].partition("=")[::2] for term in text.split() if term.startswith("+"))


def unit_axes_meridian(terms):
    """(metres per unit, axes, prime meridian in degrees east of Greenwich) of PROJ terms (proj_terms'), or why
    one of them is not taken (a str: one with "(read here" names a choice not read here, crs_system's test; the
    others a value that is no number or out of range)."""
    try:
        to_meter = float(terms.get("to_meter", "1"))
    except ValueError:
        return f"+to_meter={terms['to_meter']}, which is not a number"
    # (+units before +to_meter, as PROJ reads them)
    metres = UNITS.get(terms["units"]) if "units" in terms else to_meter
    if metres is None:
        return f"the unit +units={terms['units']} (read here: {', '.join(UNITS)}, or +to_meter)"
    if not (math.isfinite(metres) and metres > 0):
        return f"+to_meter={terms['to_meter']}, a unit that is not a finite length above 0"
    axis = terms.get("axis", "enu")
    if not (len(axis) == 3 and axis[2] == "u" and sorted(c in "ew" for c in axis[:2]) == [False, True]
            and all(c in "ewns" for c in axis[:2])):
        return f"+axis={axis} (read here: an east or west axis and a north or south one, then u: enu, wsu, neu ...)"
    meridian = terms.get("pm", "greenwich")
    try:
        pm = PRIME_MERIDIANS[meridian.lower()] if meridian.lower() in PRIME_MERIDIANS else float(meridian)
    except ValueError:
        return f"the prime meridian +pm={meridian} (read here: {', '.join(PRIME_MERIDIANS)}, or degrees)"
    if not abs(pm) <= 180:
        return f"the prime meridian +pm={meridian}, which is not a longitude (within 180)"
    return metres, axis, pm


def proj4_system(text):
    """The PlaneSystem of PROJ terms as GDAL writes them (GetLayerProjectionAsProj4), or why it is
    not taken (a str, as unit_axes_meridian gives it): another projection, a unit of no known
    length (choices not read here), a term that is not a number or out of range."""
    terms = proj_terms(text)
    name = terms.get("proj", "")
    read = unit_axes_meridian(terms)
    if isinstance(read, str):
        return read
    metres, axis, pm = read
    if name == "utm":
        zone = terms.get("zone", "")
        if not re.fullmatch(r"[0-9]{1,2}", zone) or not 1 <= int(zone) <= 60:
            return f"a UTM zone {zone!r} (expected 1 to 60)"
        if pm:
            return f"a UTM zone about the prime meridian +pm={terms['pm']} (read here: UTM about Greenwich's)"
        return PlaneSystem.utm(int(zone), "south" not in terms, metres, axis)
    sphere = spherical(terms)
    if name == "merc" and sphere and sphere_radius(terms) == WEB_RADIUS:
        name, sphere = "webmerc", ""
    if name not in KINDS:
        return f"the projection +proj={name} (read here: {READ})"
    if sphere:
        return (f"{sphere}: a projection of the sphere, whose inverse differs from the ellipsoid's by up to "
                "kilometres (read here: systems on WGS84, GRS80 or another ellipsoid, and the web maps' Mercator)")
    wanted = {"lon_0": "0", "lat_0": "0", "lat_1": "0", "lat_2": terms.get("lat_1", "0"), "x_0": "0", "y_0": "0",
              "k_0": terms.get("k", "1"), "lat_ts": "0"}  # (one standard parallel: both at it)
    number = {}
    for key, default in wanted.items():
        try:
            number[key] = float(terms.get(key, default))
        except ValueError:
            return f"+{key}={terms[key]}, which is not a number"
    bad = next((key for key, value in number.items() if not math.isfinite(value)), None)
    if bad or not number["k_0"] > 0:
        return f"+{bad}={terms.get(bad, wanted[bad])}, which is not finite" if bad else "a scale of 0 or less"
    beyond = next((key for key in ("lat_0", "lat_1", "lat_2", "lat_ts") if not abs(number[key]) <= 90), None)
    if beyond or not abs(number["lon_0"]) <= 360:
        key = beyond or "lon_0"
        what = "a latitude (within 90)" if beyond else "a longitude (within 360)"
        return f"+{key}={terms[key]}, which is not {what}"
    if terms["proj"] == "merc" and abs(number["lat_ts"]) == 90:
        return f"+lat_ts={terms['lat_ts']}, where a Mercator's scale is 0 (its true-scale parallel must miss the poles)"
    if name in ("aea", "laea", "webmerc") and terms["proj"] != "merc":
        number["k_0"] = 1.0  # (PROJ's aea, laea and webmerc take no +k, webmerc no +lat_ts)
    if name in ("merc", "webmerc"):
        number["lat_0"] = 0.0  # (the origin is on the equator whatever +lat_0 says)
        if terms["proj"] == "merc" and "lat_ts" in terms:
            # True scale on +lat_ts, in place of +k (as PROJ takes them): the scale on the equator
            # is that parallel's radius over the equator's.
            e2 = WGS84_E2 if name == "merc" else 0.0
            sin_ts = math.sin(math.radians(number["lat_ts"]))
            number["k_0"] = math.cos(math.radians(number["lat_ts"])) / math.sqrt(1 - e2 * sin_ts * sin_ts)
    # (+lon_0 is counted from +pm: Paris's NTF Lambert zones have lon_0=0 there, 2.337 degrees east of Greenwich)
    return PlaneSystem(name, number["lon_0"] + pm, number["lat_0"], number["lat_1"], number["lat_2"], number["k_0"],
                       number["x_0"], number["y_0"], metres, axis=axis)


def in_utm_range(system, x, y):
    """Whether a file's (x, y) in system (a UTM zone's PlaneSystem: its unit and axes) can be an easting and northing
    of the zone (UTM_RANGE; beyond it the projection's inverse gives a place, but not one the zone holds)."""
    east, north = system.to_grid(x, y)
    low, high = UTM_NORTHINGS[system.north]
    return 0.0 < east < 1e6 and low <= north <= high


POINT_LAYER_TYPES = (1, 4)  # OGR's wkbPoint and wkbMultiPoint


def layers_of(reader, points):
    """The layers of a GIS file (reader: its vtkGDALVectorReader, updated) that can hold what is
    read from it: with points True, the layers of points, or every layer where none is (the
    gauges of a GeoPackage that holds the catchment too); else those whose geometry is not points
    (a catchment GeoPackage's layer of gauges adds no ring, and its system must not be the
    catchment's). OGR's 2.5D flag and ISO Z/M codes are taken off the geometry type."""
    layers = range(reader.GetNumberOfLayers())
    of_points = [layer for layer in layers if (reader.GetLayerType(layer) & 0x7FFFFFFF) % 1000 in POINT_LAYER_TYPES]
    if points:
        return of_points or list(layers)
    return [layer for layer in layers if layer not in of_points]


def declared_system(reader, rings, path, points=False, point_name=None):
    """The PlaneSystem that the GIS file (reader: its vtkGDALVectorReader, updated) declares for
    all its layers that hold what is read (layers_of: with points False, a catchment's, a layer of
    points aside), where its coordinates (rings) are metres, most of them out of lon/lat's range (a
    file of lon/lat under a projected declaration is read as lon/lat, and said); else None. A
    projected system that is not read here ends the script naming it, and so does a UTM vertex
    that no zone holds (point_name(k), for points, names the k-th of rings[0])."""
    systems = set()
    for layer in layers_of(reader, points):
        proj4 = reader.GetLayerProjectionAsProj4(layer) or ""
        systems.add(proj4 if "+proj=" in proj4 and "+proj=longlat" not in proj4 else None)
    # (most vertices, not all: a system about the catchment itself puts some within 360 m of its
    # origin, and a vertex of a lon/lat file mistyped must not make the file metres)
    vertices = [p for ring in rings for p in ring]
    metres = 2 * sum(abs(x) > 360.0 or abs(y) > 90.0 for x, y in vertices) > len(vertices)
    if len(systems) != 1 or None in systems or not metres:
        return None
    proj4 = systems.pop()
    system = proj4_system(proj4)
    if isinstance(system, str):
        csv_input.fail(f"{path}: declares a projected coordinate system with {system}; its coordinates are metres, "
                       f"not longitude/latitude: reproject the file (e.g. ogr2ogr -t_srs EPSG:4326 out.shp in.shp) "
                       f"(the file's system: {proj4.strip()})")
    outside = next(((r, k, p) for r, ring in enumerate(rings) for k, p in enumerate(ring)
                    if not in_utm_range(system, *p)),
                   None) if system.kind == "utm" else None
    if outside:
        where = point_name(outside[1]) if point_name else f"ring {outside[0]} vertex {outside[1]}"
        csv_input.fail(f"{path}: {where} ({outside[2][0]:.15g}, {outside[2][1]:.15g}) "
                       f"is not an easting and northing of a UTM zone ({UTM_RANGE}), as the file declares "
                       f"({system.describe()}{'' if point_name else '; counted from 0'})")
    return system


class GdalMessages:
    """GDAL's messages while a GIS file is read (parse errors, "Non closed ring detected") or an
    EPSG code is looked up (crs_system: "PROJ: proj_create_from_database: crs not found"), which
    GDAL prints to stderr as "ERROR 1: ..." beside the script's own one-line errors: CPL_LOG, set
    while GDAL reads, sends them to a temporary file to read back. A CPL_LOG the user set is left
    alone (their file gets them). Used by colorado_areal_precipitation.py and project_gauges.py."""

    def __init__(self):
        import atexit
        import tempfile

        self.path, self.seen = None, 0
        if "CPL_LOG" not in os.environ:
            handle, self.path = tempfile.mkstemp(prefix="tessera_gdal_", suffix=".log")
            os.close(handle)
            atexit.register(lambda path=self.path: os.path.exists(path) and os.remove(path))

    @contextlib.contextmanager
    def capturing(self):
        """CPL_LOG names the file while GDAL reads (GDAL opens it at its first message and keeps
        it), and is unset after: child processes print GDAL's messages as usual."""
        if self.path:
            os.environ["CPL_LOG"] = self.path
        try:
            yield
        finally:
            if self.path:
                os.environ.pop("CPL_LOG", None)

    def new(self):
        """(level, text) of each message since the last call, each once: level "ERROR" or
        "Warning", or "" for other lines (CPL_DEBUG's)."""
        if not self.path:
            return []
        with open(self.path, "rb") as f:
            f.seek(self.seen)
            data = f.read()
        self.seen += len(data)
        messages = []
        for line in data.decode("utf-8", errors="replace").splitlines():
            found = re.match(r"(ERROR|Warning) \d+: (.*)", line.strip())
            messages.append((found.group(1), found.group(2).strip()) if found else ("", line.strip()))
        return list(dict.fromkeys(m for m in messages if m[1]))


def stations_system(utm, crs, gdal_messages):
    """The PlaneSystem of a stations file of x, y: --stations-utm's ZONE[N|S] (13N, 33S; a zone
    alone is north) or --stations-crs's EPSG:CODE or PROJ terms (+proj=aea ...); None when neither
    is given. A bad value ends the script naming it. gdal_messages: the script's GdalMessages,
    which keep GDAL's own lines off stderr while an EPSG code is looked up."""
    # (an empty value given is refused by name, not taken as the option left out)
    if utm is not None and crs is not None:
        csv_input.fail("--stations-utm and --stations-crs: give one of them")
    if utm is not None:
        zone = re.fullmatch(r"([0-9]{1,2})([NnSs]?)", utm.strip())
        if not zone or not 1 <= int(zone.group(1)) <= 60:
            csv_input.fail(f"--stations-utm {utm!r}: expected a UTM zone 1 to 60 with N or S (such as 13N)")
        if not zone.group(2):
            print(f"--stations-utm {utm}: read as zone {int(zone.group(1))}N, in the northern hemisphere (give "
                  f"{int(zone.group(1))}S for the southern)", file=sys.stderr)
        return PlaneSystem.utm(int(zone.group(1)), zone.group(2).upper() != "S")
    if crs is None:
        return None
    return crs_system(crs, "--stations-crs", gdal_messages,
                      lonlat="give the file lon and lat columns, without --stations-crs",
                      datum="the gauges' x, y are made longitude/latitude on WGS84's",
                      unread="or make the gauges lon/lat first (PROJ's cs2cs, or GDAL's ogr2ogr -t_srs "
                             "EPSG:4326 for a GIS file) and give lon and lat columns without --stations-crs")


def crs_system(crs, option, gdal_messages=None, lonlat="", datum="", unread=""):
    """The PlaneSystem of `option`'s value crs, EPSG:CODE or PROJ terms (+proj=aea ...); a bad value ends the
    script naming it. gdal_messages: the script's GdalMessages, or None to let GDAL's own lines through while an
    EPSG code is looked up. lonlat: what to do when crs is a geographic system; datum: what is made of
    coordinates on another datum (said, with a warning, for such a system); unread: what else to do for a
    system not read here (a trial's Swiss EPSG:2056 was refused without a way on)."""
    text = crs.strip()
    code = re.fullmatch(r"(?i)(?:epsg:\s*|urn:ogc:def:crs:epsg:[0-9.]*:)?([0-9]+)", text)
    example = "'+proj=aea +lat_0=23 +lon_0=-96 +lat_1=29.5 +lat_2=45.5 +x_0=0 +y_0=0 +units=m'"
    if not code and not text.startswith("+proj="):
        csv_input.fail(f"{option} {crs!r}: expected EPSG:CODE (such as EPSG:5070) or PROJ terms starting "
                       f"+proj= (such as {example})")
    wkt = ""
    if code:
        if gdal_messages:
            with gdal_messages.capturing():
                found = epsg_system(int(code.group(1)))
            gdal_messages.new()  # (read: they are not the catchment's)
        else:
            found = epsg_system(int(code.group(1)))
        if found.successor:
            csv_input.fail(f"{option} {crs!r}: GDAL gives another system in its place, EPSG:{found.successor[0]} "
                           f"({found.successor[1]!r}), as it does for a deprecated code, and the two may differ (as "
                           "EPSG:2163, on a sphere, and its successor EPSG:9311, on the Clarke 1866 ellipsoid, do): "
                           "give the system as PROJ terms (+proj=...)")
        if not found.proj4:
            csv_input.fail(f"{option} {crs!r}: GDAL's database has no such EPSG code")
        text, wkt = found.proj4, found.wkt
    system = proj4_system(text)
    if isinstance(system, str) and "+proj=longlat" in text.split():
        system = f"a geographic system (longitude/latitude): {lonlat}"
    # (a value that is no number or out of range is a slip to mend; a system not read here needs
    # another, or the gauges converted, which unread says how to do)
    if isinstance(system, str) and "(read here" not in system:
        csv_input.fail(f"{option} {crs!r}: {system}")
    if isinstance(system, str):
        csv_input.fail(f"{option} {crs!r}: not read here: {system}; give EPSG:CODE or PROJ terms of a system "
                       f"read here, such as {example}{', ' + unread if unread else ''}")
    other = other_ellipsoid(text) or other_datum(wkt)
    if other:
        print(f"{option} {crs!r}: {other}; {datum}, without the datum shift: they may lie tens to hundreds of metres "
              "off (reproject them to WGS84 where that matters)", file=sys.stderr)
    return system


def spherical(terms):
    """The terms that make PROJ terms (proj_terms') a sphere's, as PROJ reads them ("+R=6370997",
    "+R_A", "+ellps=sphere", "+a=6378137 +b=6378137", "+es=0", or +a with no shape); else ""."""
    radius = next((key for key in terms if key == "R" or key.startswith("R_")), None)
    if radius:
        return f"+{radius}" + (f"={terms[radius]}" if terms[radius] else "")
    if terms.get("ellps") == "sphere":
        return "+ellps=sphere"
    if "a" in terms and not any(key in terms for key in ("b", "rf", "f", "es", "e", "ellps", "datum")):
        return f"+a={terms['a']} without a flattening"
    for key, sphere in (("b", terms.get("a")), ("rf", "0"), ("f", "0"), ("es", "0"), ("e", "0")):
        try:
            if key in terms and float(terms[key]) == float(sphere):
                return f"+a={terms['a']} +{key}={terms[key]}" if key == "b" else f"+{key}={terms[key]}"
        except (TypeError, ValueError):
            pass  # (a term that is not a number is named where it is read)
    return ""


def sphere_radius(terms):
    """The radius (m) of a sphere's PROJ terms (+R, else +a), or None where it is not a number."""
    try:
        return float(terms.get("R", terms.get("a")))
    except (TypeError, ValueError):
        return None


# Datums that lie within a metre or two of WGS84 (so a file's coordinates on them are taken as WGS84's), as GDAL's
# WKT names them: the ITRF-aligned national realisations (PROJ takes each as WGS84 without a shift). A name holding
# one of these is such a datum.
WGS84_LIKE_DATUMS = ("WGS_1984", "North_American_Datum_1983", "North_American_1983", "NAD83", "ETRS", "ETRF",
                     "European_Terrestrial_Reference", "Terrestrial_Reference", "ITRF", "IGS", "SIRGAS",
                     "Sistema_de_Referencia", "Geocentric_Datum_of_Australia", "GDA", "Geocentric_datum_of_Korea",
                     "Korea_2000", "Marco_Geocentrico", "New_Zealand_Geodetic_Datum_2000", "Hartebeesthoek94",
                     "China_2000", "Reseau_Geodesique_Francais_1993", "RGF93", "Japanese_Geodetic_Datum_20",
                     "Geodetic_Datum_of_Malaysia_2000", "SWEREF99", "SVY21", "Latvia_1992", "Estonia_1997",
                     "Lithuania_1994")


def other_datum(wkt):
    """"the datum 'Israel_1993' (ellipsoid 'GRS 1980')" where a WKT declares a datum on an ellipsoid other than
    WGS84's or GRS80's (an older datum: NAD27, ED50, ...), or one not known here to lie within a metre or two of
    WGS84 (Israel 1993 is on GRS80 but some 80 m away); else ""."""
    datum = re.search(r'DATUM\["([^"]*)"', wkt)
    ellipsoid = re.search(r'(?:SPHEROID|ELLIPSOID)\["([^"]*)",\s*([0-9.eE+]+)', wkt)
    older = ellipsoid and abs(float(ellipsoid.group(2)) - 6378137.0) > 0.5
    # (an ESRI .prj names them D_WGS_1984, D_North_American_1983; Mexico_ITRF2008 holds its frame's name)
    unknown = datum and not any(name in datum.group(1) for name in WGS84_LIKE_DATUMS)
    if not (older or unknown):
        return ""
    name = datum.group(1) if datum else ellipsoid.group(1)
    return f"the datum {name!r}" + (f" (ellipsoid {ellipsoid.group(1)!r})" if ellipsoid else "") + (
        "" if older else ", not one known here to lie within a metre or two of WGS84's")


def other_ellipsoid(proj4):
    """"the datum NAD27" or "the ellipsoid airy" where PROJ terms name a datum or ellipsoid other
    than WGS84's or GRS80's (NAD83, ETRS89: within a metre or two of WGS84), or a shift from WGS84
    (+towgs84 other than zeros); else ""."""
    terms = proj_terms(proj4)
    if terms.get("datum", "WGS84") not in ("WGS84", "NAD83"):
        return f"the datum {terms['datum']}"
    if terms.get("ellps", "WGS84") not in ("WGS84", "GRS80"):
        return f"the ellipsoid {terms['ellps']}"
    if "a" in terms and terms["a"] != "6378137":
        return f"an ellipsoid of semi-major axis {terms['a']} m"
    try:
        shifted = any(float(value) != 0.0 for value in terms.get("towgs84", "0").split(","))
    except ValueError:
        shifted = True
    if shifted:
        # (PROJ terms typed with their shift, as epsg.io writes Israel 1993's: on GRS80 but some 80 m from WGS84)
        return f"a datum shifted from WGS84's by +towgs84={terms['towgs84']}"
    return ""


# What GDAL's database gives for an EPSG code: its PROJ terms and WKT ("" for a code it does not know), and
# successor: (code, name) where it gives another code's system in its place (a deprecated code's successor).
EpsgSystem = collections.namedtuple("EpsgSystem", "proj4 wkt successor")


def epsg_system(code):
    """The EpsgSystem of an EPSG code, from GDAL's database (through vtkGDALVectorReader: a GeoJSON of one point
    that declares the code)."""
    import json
    import os
    import tempfile
    from vtkmodules.vtkIOGDAL import vtkGDALVectorReader

    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "crs.geojson")
        with open(path, "w") as f:
            json.dump({"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": f"EPSG:{code}"}},
                       "features": [{"type": "Feature", "properties": {},
                                     "geometry": {"type": "Point", "coordinates": [0, 0]}}]}, f)
        reader = vtkGDALVectorReader()
        reader.SetFileName(path)
        reader.Update()
        declared = reader.GetLayerProjection(0) or "" if reader.GetNumberOfLayers() == 1 else ""
        authority = re.findall(r'AUTHORITY\["EPSG","([0-9]+)"\]\]$', declared)
        if authority and authority[0] != str(code) and declared.startswith("PROJCS"):
            name = re.match(r'[A-Z]+\["([^"]*)"', declared)
            return EpsgSystem("", declared, (authority[0], name.group(1) if name else ""))
        if authority != [str(code)]:
            return EpsgSystem("", "", None)  # (a code GDAL does not know gives its default, WGS84's lon/lat)
        return EpsgSystem(reader.GetLayerProjectionAsProj4(0) or "", declared, None)


def polydata_blocks(data):
    """The vtkPolyData leaves of a composite data set (vtkGDALVectorReader's output has a block per
    feature), or [data] for a vtkPolyData."""
    if not data.IsA("vtkCompositeDataSet"):
        return [data] if data.IsA("vtkPolyData") else []
    blocks, leaves = [], data.NewIterator()
    leaves.InitTraversal()
    while not leaves.IsDoneWithTraversal():
        block = leaves.GetCurrentDataObject()
        if block is not None and block.IsA("vtkPolyData"):
            blocks.append(block)
        leaves.GoToNextItem()
    return blocks


def densify_edges(data, step):
    """Cuts every edge of data's polygons and lines (a vtkPolyData or a multiblock of them, changed
    in place) into pieces of at most step, in its coordinates' units; the cells and their data stay
    as they are (vtkGDALVectorReader's output has no point data, and gets none)."""
    from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray

    for leaf in polydata_blocks(data):
        points = leaf.GetPoints()
        if points is None:
            continue
        cut = vtkPoints()
        cut.SetDataTypeToDouble()
        cut.DeepCopy(points)  # (the old points keep their ids; the new ones follow)
        ids = vtkIdList()
        for cells, closed, assign in ((leaf.GetPolys(), True, leaf.SetPolys), (leaf.GetLines(), False, leaf.SetLines)):
            pieces = vtkCellArray()
            cells.InitTraversal()
            while cells.GetNextCell(ids):
                count = ids.GetNumberOfIds()
                kept = []
                for k in range(count if closed else count - 1):
                    a, b = points.GetPoint(ids.GetId(k)), points.GetPoint(ids.GetId((k + 1) % count))
                    kept.append(ids.GetId(k))
                    n = math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / step)
                    kept.extend(cut.InsertNextPoint(a[0] + i / n * (b[0] - a[0]), a[1] + i / n * (b[1] - a[1]), 0.0)
                                for i in range(1, n))
                if not closed and count:
                    kept.append(ids.GetId(count - 1))
                pieces.InsertNextCell(len(kept), kept)
            assign(pieces)
        leaf.GetPointData().Initialize()
        leaf.SetPoints(cut)


def projection_filter(system, inverse):
    """A vtkGeographicProjection set to system's projection and grid (false origin, scale, latitude of origin)."""
    projection = csv_input.import_tessera().vtkGeographicProjection()
    if system.kind == "utm":
        projection.SetProjectionToUTM()
        projection.SetUTMZone(system.zone)
        projection.SetUTMNorth(system.north)
    else:
        getattr(projection, "SetProjectionTo" + KINDS[system.kind])()
        projection.SetParametersFromData(False)
        projection.SetCentralLongitude(system.lon0)
        projection.SetCentralLatitude(system.lat0)
        projection.SetStandardParallels(system.lat1, system.lat2)
        projection.SetFalseEasting(system.x0)
        projection.SetFalseNorthing(system.y0)
        projection.SetScaleFactor(system.k0)
        # (laea's lat_0 is its centre, set above; PROJ's Mercators start at the equator whatever lat_0 says)
        if system.kind in ("aea", "lcc", "tmerc"):
            projection.UseLatitudeOfOriginOn()
            projection.SetLatitudeOfOrigin(system.lat0)
    projection.SetInverse(inverse)
    return projection


# The most a coordinate can be from a system's false origin, in metres: the Earth's circumference.
# A transverse Mercator or a conic holds places to some 2e7 m from its origin; beyond this, a point
# is a typo (-1e9 for -1e6), whose inverse would still give a place.
MOST_METRES = 4.0e7


def into_grid(data, system, where):
    """Moves data's points (changed in place) from system's unit and axes to the filter's grid: eastings and
    northings in metres. A point beyond MOST_METRES from the false origin ends the script, where(point index)
    naming where it came from (UTM's range is checked where its file is read)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkPoints

    for leaf in polydata_blocks(data):
        if leaf.GetPoints() is None:
            continue
        xyz = vtk_to_numpy(leaf.GetPoints().GetData()).astype(float)  # (a copy, in doubles)
        xyz[:, 0], xyz[:, 1] = system.to_grid(xyz[:, 0].copy(), xyz[:, 1].copy())
        off = abs(xyz[:, :2] - (system.x0, system.y0)) / system.k0
        far = (~(off <= MOST_METRES)).any(axis=1).nonzero()[0]  # (NaN too)
        if len(far):
            csv_input.fail(f"{where(int(far[0]))}: as {system.describe()}: a point {off[far[0]].max():.3g} m from "
                           "the projection's origin, beyond any place on the Earth (a typo?)")
        moved = vtkPoints()
        moved.SetData(numpy_to_vtk(xyz, deep=True))
        leaf.SetPoints(moved)


def to_lonlat(data, system, where, densify=False):
    """data (a vtkPolyData or a multiblock of them) with its points made lon/lat from x, y of
    system (a PlaneSystem), by vtkGeographicProjection's inverse; its edges cut every EDGE_METRES
    first when densify is set. An error (a point the projection cannot hold, or one beyond
    MOST_METRES from the false origin) ends the script, where(point index) naming where that point
    came from."""
    into_grid(data, system, where)
    if densify:
        densify_edges(data, EDGE_METRES)
    projection = projection_filter(system, True)
    projection.SetInputData(data)
    errors = csv_input.errors_of_update(projection)
    if errors:
        point = re.search(r"\bpoint (\d+)(?: \(([^,()]+), ([^,()]+)\))?", errors[0])
        message = errors[0]
        if point and point.group(3):
            # (the filter names the point by its index there, and in its grid: said in the file's unit and axes)
            x, y = system.from_grid(float(point.group(2)), float(point.group(3)))
            message = message.replace(point.group(0), f"the point ({x:.15g}, {y:.15g})")
        csv_input.fail(f"{where(int(point.group(1))) if point else where(-1)}: as {system.describe()}: {message}")
    return projection.GetOutputDataObject(0)


def main(argv=None):
    # `python3 projected_input.py` with or without --help: what the module is for (the README's
    # "every script takes --help" reaches this file too).
    import argparse

    parser = argparse.ArgumentParser(description=__doc__ + "\nA module imported by colorado_areal_precipitation.py; "
                                     "it does nothing run on its own.",
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.parse_args(argv)
    parser.print_help()


if __name__ == "__main__":
    main()
