"""Reading the examples' CSV files the way a user's own files need: the named columns are checked
before any row is read, a value that is not a number is named with its file, line and column, and
missing values (an empty field, NA, N/A, NaN, null, in any case) are told apart from bad ones.
Every failure ends the script with one line naming what is wrong and where, never a traceback."""

import csv
import sys

MISSING = frozenset(("", "na", "n/a", "nan", "null"))


def fail(message):
    """Ends the script with the message on stderr and exit status 1."""
    sys.exit(message)


def rows(path, required, what):
    """Yields (line, row) for each record of the CSV file at path (a header line first; row maps
    the header's names, stripped of spaces, to the fields). Ends the script, naming the file, when
    it cannot be read or lacks one of the required columns; what says what the file holds."""
    try:
        handle = open(path, newline="", encoding="utf-8-sig")  # a spreadsheet's byte-order mark
    except OSError as error:
        fail(f"{path}: cannot read the {what} file ({error.strerror})")
    with handle:
        reader = csv.DictReader(handle)
        columns = [name.strip() for name in reader.fieldnames or []]
        absent = [name for name in required if name not in columns]
        if absent:
            fail(f"{path}: the {what} file has no column {', '.join(repr(n) for n in absent)} "
                 f"(it needs {', '.join(required)}; its header: {', '.join(columns) or 'none'})")
        reader.fieldnames = columns
        for row in reader:
            # A record with more or fewer fields than the header would shift or lose values.
            if None in row or None in row.values():
                fields = len(columns) + len(row.get(None) or []) - list(row.values()).count(None)
                fail(f"{path}:{reader.line_num}: {fields} field(s) where the header has "
                     f"{len(columns)} ({', '.join(columns)})")
            yield reader.line_num, row


def is_missing(text):
    """True for an empty field or a missing-value marker (NA, N/A, NaN, null, in any case)."""
    return (text or "").strip().lower() in MISSING


def number(row, column, path, line):
    """The field as a float; ends the script, naming file, line, column and text, if it is not a
    number (a missing value included: test is_missing first where one is allowed)."""
    text = row.get(column)
    try:
        return float((text or "").strip())
    except ValueError:
        fail(f"{path}:{line}: column {column!r}: {text!r} is not a number")


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


def import_tessera():
    """The tessera package; ends the script with how to run it when Python cannot find it."""
    try:
        import tessera
    except ImportError as error:
        fail(f"cannot import tessera ({error}): run with Debian's /usr/bin/python3 and "
             "PYTHONPATH=build/python after scripts/build (scripts/demo does both)")
    return tessera
