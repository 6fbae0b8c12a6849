"""Reading the examples' CSV files the way a user's own files need: the named columns are checked
before any row is read, a value that is not a number is named with its file, line and column, and
missing values (an empty field, NA, N/A, NaN, null, in any case) are told apart from bad ones.
Every failure ends the script with one line naming what is wrong and where, never a traceback."""

import codecs
import csv
import io
import math
import sys

MISSING = frozenset(("", "na", "n/a", "nan", "null"))


def fail(message):
    """Ends the script with the message on stderr and exit status 1."""
    sys.exit(message)


def decoded(path, what):
    """The text of the file: UTF-8 (with or without a byte-order mark), UTF-16 with its mark, or
    else Windows-1252, which is what a spreadsheet saves as CSV on Windows."""
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except OSError as error:
        fail(f"{path}: cannot read the {what} file ({error.strerror})")
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            return data.decode("utf-16")
        except UnicodeDecodeError as error:
            fail(f"{path}: the {what} file is not valid UTF-16 text ({error.reason})")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("cp1252", errors="replace")


def rows(path, required, what):
    """Yields (line, row) for each record of the CSV file at path (a header line first; row maps
    the header's names, stripped of spaces, to the fields); blank lines and records whose fields
    are all empty are skipped. Ends the script, naming the file, when it cannot be read, is not a
    CSV file, lacks one of the required columns, or is not well-formed CSV; what says what the
    file holds."""
    text = decoded(path, what)
    if text.lstrip().startswith(("{", "[")):
        fail(f"{path}: the {what} file is not a CSV file (it starts like JSON or GeoJSON; "
             f"expected a header line such as {','.join(required)})")
    reader = csv.DictReader(io.StringIO(text, newline=""), strict=True)
    try:
        columns = [name.strip() for name in reader.fieldnames or []]
        absent = [name for name in required if name not in columns]
        if absent:
            fail(f"{path}: the {what} file has no column {', '.join(repr(n) for n in absent)} "
                 f"(it needs {', '.join(required)}; its header: {', '.join(columns) or 'none'})")
        reader.fieldnames = columns
        for row in reader:
            # A record whose fields are all empty (",,," as a spreadsheet exports a blank row, or
            # a line of spaces) holds nothing: skipped, like a blank line.
            fields = [value for key, value in row.items() if key is not None] + (row.get(None) or [])
            if all(not (field or "").strip() for field in fields):
                continue
            # A record with more or fewer fields than the header would shift or lose values.
            if None in row or None in row.values():
                fields = len(columns) + len(row.get(None) or []) - list(row.values()).count(None)
                fail(f"{path}:{reader.line_num}: {fields} field(s) where the header has "
                     f"{len(columns)} ({', '.join(columns)})")
            yield reader.line_num, row
    except csv.Error as error:  # e.g. a quote opened and never closed
        # The underlying reader's count: the lines read up to the error (the DictReader's own
        # line_num is that of the last record it returned, 0 while the header is read).
        fail(f"{path}:{max(reader.reader.line_num, 1)}: not well-formed CSV ({error})")


def is_missing(text):
    """True for an empty field or a missing-value marker (NA, N/A, NaN, null, in any case)."""
    return (text or "").strip().lower() in MISSING


def number(row, column, path, line):
    """The field as a finite float; ends the script, naming file, line, column and text, if it is
    not one (a missing value included: test is_missing first where one is allowed)."""
    text = row.get(column)
    try:
        value = float((text or "").strip())
    except ValueError:
        fail(f"{path}:{line}: column {column!r}: {text!r} is not a number")
    if not math.isfinite(value):  # float() takes inf, 1e999 and nan
        fail(f"{path}:{line}: column {column!r}: {text!r} is not a finite number")
    return value


def integer(row, column, path, line, low, high):
    """The field as an int in [low, high]; ends the script naming it otherwise."""
    text = (row.get(column) or "").strip()
    try:
        value = int(text)
    except ValueError:
        fail(f"{path}:{line}: column {column!r}: {text!r} is not an integer")
    if not low <= value <= high:
        fail(f"{path}:{line}: column {column!r}: {value} is outside {low}..{high}")
    return value


def text(row, column, path, line):
    """The field stripped of spaces; ends the script, naming file, line and column, if empty."""
    value = (row.get(column) or "").strip()
    if not value:
        fail(f"{path}:{line}: column {column!r} is empty")
    return value


def gauges(path):
    """Yields (line, row, station_id, name, lon, lat) for each gauge of a stations file: columns
    station_id, lon, lat (degrees), an optional name, and any others (left in row)."""
    for line, row in rows(path, ("station_id", "lon", "lat"), "stations"):
        yield (line, row, text(row, "station_id", path, line), (row.get("name") or "").strip(),
               number(row, "lon", path, line), number(row, "lat", path, line))


def import_tessera():
    """The tessera package; ends the script with how to run it when Python cannot find it."""
    try:
        import tessera
    except ImportError as error:
        fail(f"cannot import tessera ({error}): run with Debian's /usr/bin/python3 and "
             "PYTHONPATH=build/python after scripts/build (scripts/demo does both)")
    return tessera
