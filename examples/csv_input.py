"""Reading the examples' CSV files the way a user's own files need: the named columns are checked
before any row is read, a value that is not a number is named with its file, line and column, and
missing values (an empty field, NA, N/A, #N/A, NaN, null, in any case) are told apart from bad ones.
Fields may be separated by commas, or by semicolons or tabs as a spreadsheet set to a European
locale saves them; in such a file numbers may be written with decimal commas (12,5), and then
none may have a point (1.234 would be digit grouping: named, not read as 1.234).
Every failure ends the script with one line naming what is wrong and where, never a traceback;
catch_vtk_messages() and vtk_message_text() give a script the VTK filters' messages as text, so
that it reports a value the filters reject in such a line too, not as VTK's log; output_directory()
makes the --out directory and tries writing a file there, or says in such a line why it cannot,
before any work is done; check_paths() names a file option given an empty path, and say_repeats()
the records that repeat an earlier one's id or place; station_key() is a station id as the filter
matches it (0102 and 102 are one), for every script that compares ids.

A module imported by the other examples (colorado_areal_precipitation.py, project_gauges.py,
ridge_grouping.py, beside it), not a script: run, it only says so."""

import argparse
import codecs
import csv
import errno
import math
import os
import re
import sys
import tempfile

MISSING = frozenset(("", "na", "n/a", "#n/a", "nan", "null"))  # (#N/A: Excel's)
MISSING_TEXT = "empty, NA, N/A, #N/A, NaN or null"  # MISSING as a user writes them


def fail(message):
    """Ends the script with the message on stderr and exit status 1."""
    sys.exit(message)


def decoded(path, what, head=False):
    """The text of the file: UTF-8 (with or without a byte-order mark), UTF-16 with its mark, or
    else Windows-1252, which is what a spreadsheet saves as CSV on Windows. head: only its start,
    up to a line end after some non-blank text or the whole file (a header, without decoding an
    observations file of 100 MB)."""
    try:
        with open(path, "rb") as handle:
            data = handle.read(HEAD_BYTES if head else -1)
            if head and len(data) == HEAD_BYTES and not has_plain_header(data):
                data += handle.read()
    except OSError as error:
        fail(f"{path}: cannot read the {what} file ({error.strerror})")
    # A compressed download or a workbook read as text gave its binary bytes as the "header".
    if data.startswith(b"PK\x03\x04"):
        fail(f"{path}: the {what} file is a zip archive, not CSV text (an Excel .xlsx or an OpenDocument "
             "sheet is one: save the sheet as CSV; a zipped CSV: unzip it)")
    # A compressed file (a large record is often kept so) is read decompressed.
    kind = compression(data)
    if kind:
        try:
            data = __import__(COMPRESSION_MODULES[kind]).decompress(data)
        except (OSError, EOFError, ValueError) as error:
            fail(f"{path}: the {what} file is {kind}-compressed but cannot be decompressed ({error})")
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            return data.decode("utf-16")
        except UnicodeDecodeError as error:
            fail(f"{path}: the {what} file is not valid UTF-16 text ({error.reason})")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        if head and error.start >= len(data) - 3:  # (a character cut at the head's end)
            return data[:error.start].decode("utf-8-sig")
        return data.decode("cp1252", errors="replace")


HEAD_BYTES = 65536  # (decoded's head)
COMPRESSION_MODULES = {"gzip": "gzip", "bzip2": "bz2", "xz": "lzma"}


def compression(data):
    """The compression of a file whose first bytes (10 or more) are data, by its magic number:
    "gzip", "bzip2" (its whole magic: a plain file may start with "BZh") or "xz"; None for others."""
    if data.startswith(b"\x1f\x8b"):
        return "gzip"
    if data.startswith(b"BZh") and data[3:4].isdigit() and data[4:10] == b"1AY&SY":
        return "bzip2"
    return "xz" if data.startswith(b"\xfd7zXZ\x00") else None


def has_plain_header(data):
    """Whether the first half of data (a file's first HEAD_BYTES) holds a whole line of text, not
    compressed: else decoded's head reads the whole file (a compressed file is decompressed whole;
    a header line may run to hundreds of kB in a wide file of thousands of stations)."""
    return compression(data) is None and re.search(rb"\S[^\n]*\n", data[:HEAD_BYTES // 2]) is not None


def rows(path, required, what, optional=(), header=None, delimiter_columns=None, numbers=None):
    """Yields (line, row) for each record of the CSV file at path (a header line first; row maps
    the header's names, stripped of spaces and of a pair of quotes round them (header_name), to the
    fields); blank lines and records whose fields are all empty are skipped. A required or
    optional column may be named in another case (STATION_ID, Lon). Ends the script, naming the
    file, when it cannot be read, is not a CSV file, lacks one of the required columns, has one of
    them (or an optional one) twice, or is not well-formed CSV; what says what the file holds.
    header: a list that is given the header's columns (as the rows name them) before the first
    record, for a caller whose required columns depend on it (check_columns); delimiter_columns:
    the columns that choose the field separator (header_delimiter), the required ones unless given;
    numbers: the columns read as numbers (in any case, or by another name of ALIAS_OF), or a
    function of the header's columns giving them: only their fields decide whether the file's
    numbers have decimal commas (decimal_comma_evidence); every field where None. A file whose
    fields follow their separator with spaces and a quote (a, "b, c") is read with those spaces
    skipped, so that the quotes hold the field."""
    text = decoded(path, what)
    wanted = required if delimiter_columns is None else delimiter_columns
    if text.lstrip().startswith(("{", "[")):
        fail(f"{path}: the {what} file is not a CSV file (it starts like JSON or GeoJSON; "
             f"expected a header line such as {','.join(wanted)})")
    delimiter = header_delimiter(text, wanted)
    reader = csv.DictReader(text_lines(text), delimiter=delimiter, strict=True,
                            skipinitialspace=spaced_quotes(text, delimiter))
    try:
        renamed = []
        columns = named_columns([header_name(name) for name in reader.fieldnames or []],
                                (*required, *optional), f"{path}:{max(reader.reader.line_num, 1)}", renamed, what)
        if renamed:
            print(f"{path}: reads column {', '.join(f'{a!r} as {b!r}' for a, b in renamed)}", file=sys.stderr)
        check_columns(path, what, required, columns)
        if header is not None:
            header[:] = columns
        reader.fieldnames = columns
        decimal_comma = delimiter != "," and decimal_comma_evidence(text, delimiter, columns, numbers)
        for row in reader:
            if None not in row and None not in row.values():  # (as many fields as the header: most records)
                if any(map(str.strip, row.values())):
                    yield reader.line_num, Row(row, decimal_comma) if decimal_comma else row
                continue  # (all empty)
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
            yield reader.line_num, Row(row, decimal_comma) if decimal_comma else row
    except csv.Error as error:  # e.g. a quote opened and never closed
        # The underlying reader's count: the lines read up to the error (the DictReader's own
        # line_num is that of the last record it returned, 0 while the header is read).
        fail(f"{path}:{max(reader.reader.line_num, 1)}: not well-formed CSV ({error})")


def check_columns(path, what, required, columns):
    """Ends the script, naming the file, its header and what it needs, when columns (a header's,
    as named_columns gives them) lack one of the required names, or are none (an empty file) where
    some are required: a caller that requires none says itself what an empty file lacks."""
    absent = [name for name in required if name not in columns]
    if not columns and required:
        fail(f"{path}: the {what} file is empty (no header, no rows); it needs the columns {', '.join(required)}")
    if absent:
        others = "; ".join(f"{name} may be named {', '.join(other_names(name, what))}"
                           for name in absent if other_names(name, what))
        fail(f"{path}: the {what} file has no column {', '.join(repr(n) for n in absent)} "
             f"(it needs {', '.join(required)}; its header: {', '.join(columns) or 'none'}"
             f"{'; ' + others if others else ''})")


def other_names(name, what=None):
    """The other names a column is read by in a file of what (ALIAS_OF, then its fallbacks)."""
    return [other for other, wanted in ALIAS_OF.items() if wanted == name] + fallbacks(name, what)


LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+$")


def text_lines(text):
    """The lines of text with their ends (\\n, \\r\\n or \\r), one at a time, as io.StringIO(text,
    newline="") gives them: that copy holds 4 bytes a character (some 400 bytes a row of a
    large observations file, against the text's 20)."""
    for line in LINE.finditer(text):
        yield line.group()


DELIMITERS = (",", ";", "\t")  # the first wins a tie
SEPARATORS_TEXT = "fields separated by commas, or by semicolons or tabs with decimal commas allowed"


class Row(dict):
    """A record of rows() from a file whose numbers are written with decimal commas
    (has_decimal_commas): its header's names to its fields; decimal_comma is True, or the text
    that says where the file shows one (decimal_comma_evidence). rows() gives the other files'
    records as plain dicts."""

    def __init__(self, fields, decimal_comma=False):
        super().__init__(fields)
        self.decimal_comma = decimal_comma


def header_delimiter(text, required=()):
    """The mark that separates the fields: of a comma, a semicolon (what a spreadsheet set to a
    locale with a decimal comma saves as CSV) and a tab, the first with which the header line,
    read as CSV (quotes kept together), has every required column (in any case); else the one it
    holds most of, a comma where it holds none (a file of one column)."""
    header = next((line for line in text_lines(text) if line.strip()), "").rstrip("\r\n")
    wanted = {name.lower() for name in required}
    for mark in DELIMITERS:
        try:
            names = header_names(next(csv.reader([header], delimiter=mark), []))
        except csv.Error:
            continue
        if wanted and wanted <= names:
            return mark
    return max(DELIMITERS, key=header.count)


def spaced_quotes(text, delimiter):
    """Whether the file is read with the spaces after its separators skipped: its header quotes
    its names after a separator and spaces ("station_id", "lon", as some programs write CSV,
    whose quotes and spaces the csv module would keep), and the whole file reads so as
    well-formed CSV (a quoted field followed by a space before its separator, "Boulder" , or a
    quote inside a field after a space, 101, "Dry" Creek, is not: such a file is read as before,
    its quotes kept)."""
    header = next(text_lines(text.lstrip("\ufeff")), "")
    if not re.search(rf'{re.escape(delimiter)} +"', header):
        return False
    try:
        for _ in csv.reader(text_lines(text), delimiter=delimiter, strict=True, skipinitialspace=True):
            pass
    except csv.Error:
        return False
    return True


def has_decimal_commas(text, delimiter, read=None):
    """Whether a field of the text (separated by delimiter, not a comma) is a number written with a
    decimal comma (12,5 or -0,25e-3, quoted or not: "12,5"), in one of the columns read (their
    positions, from 0; any column where None): then the file's numbers are read so, and a point in
    one is named as digit grouping rather than read as a decimal point (1.234 is 1234 where 12,5 is
    12.5). A file of only points (semicolons or tabs with 12.5) reads them as decimal points, and
    so does one whose decimal commas are all in columns not read as numbers (a name 3,5, a height
    5,280 with digit grouping)."""
    return decimal_comma_field(text, delimiter, read) is not None


DECIMAL_COMMA = r"[+-]?[0-9]*,[0-9]+(?:[eE][+-]?[0-9]+)?"
COMMA_NUMBER = r"[+-]?[0-9]*(?:,[0-9]+)+(?:[eE][+-]?[0-9]+)?"  # DECIMAL_COMMA's, or digit groups (1,234,567)


def decimal_comma_field(text, delimiter, read=None):
    """The first field of the text as has_decimal_commas finds it, as (its line, its column's
    position from 0, its text), or None. A file with quotes is read record by record (a quoted
    field may hold the separator, or a line break: "Fort\nCollins" is one field); one without is
    searched for numbers with a decimal comma, each field starting after the separator or a line
    end (\n, \r\n, or \r alone, as old spreadsheets for the Mac end lines), and a hit's column
    counted from the hit before it on its line (a file of thousands of columns is read once)."""
    wanted = None if read is None else set(read)
    if wanted is not None and not wanted:
        return None
    if '"' in text:
        return decimal_comma_record(text, delimiter, wanted)
    mark = re.escape(delimiter)
    fields = re.compile(rf"(?<![^\r\n{mark}])[ \t]*{DECIMAL_COMMA}[ \t]*(?={mark}|[\r\n]|\Z)")
    start, column, at = -1, 0, 0  # (the line start of the last hit, its column, its place)
    for found in fields.finditer(text):
        p = found.start()
        line_start = max(text.rfind("\n", at, p), text.rfind("\r", at, p)) + 1
        if line_start == 0 and start >= 0:
            column += text.count(delimiter, at, p)  # (the last hit's line)
        else:
            start, column = line_start, text.count(delimiter, line_start, p)
        at = p
        if wanted is None or column in wanted:
            line = 1 + text.count("\n", 0, p) + text.count("\r", 0, p) - text.count("\r\n", 0, p)
            return line, column, found.group().strip(" \t")
    return None


def decimal_comma_record(text, delimiter, wanted):
    """decimal_comma_field for a file with quotes: its records as the csv module reads them (the
    line is that of the record's end), each field of a column wanted (any where None) stripped of
    spaces and of a pair of quotes round it ("10,5" after a space, which the reader keeps)."""
    number = re.compile(DECIMAL_COMMA)
    reader = csv.reader(text_lines(text), delimiter=delimiter)
    try:
        for record in reader:
            for column, field in enumerate(record):
                if wanted is None or column in wanted:
                    value = header_name(field)
                    if number.fullmatch(value):
                        return reader.line_num, column, value
    except csv.Error:
        return None  # (rows() names the malformed record)
    return None


def decimal_comma_evidence(text, delimiter, columns, numbers=None):
    """Where the text (a CSV file's, its header's columns given) shows that its numbers have decimal
    commas (decimal_comma_field, in the columns numbers names as rows() takes it, or in any column
    where None): "'12,5' in column 'precip' on line 3"; None where it shows none."""
    if callable(numbers):
        numbers = numbers(columns)
    read = None
    if numbers is not None:
        names = {name.lower() for name in numbers}
        read = [k for k, column in enumerate(columns)
                if column.lower() in names or ALIAS_OF.get(column.lower()) in names]
    found = decimal_comma_field(text, delimiter, read)
    if found is None:
        return None
    line, column, field = found
    where = f"column {columns[column]!r}" if column < len(columns) else f"field {column + 1}"
    shown = field.strip('"').strip()
    return f"{shown!r} in {where} on line {line}"


def decimal_comma_note(row, before="", after=""):
    """Where the decimal commas of the row's file were seen (decimal_comma_evidence), as the fail
    messages of number() and integer() say it: "as '12,5' in column 'precip' on line 3 shows",
    between before and after; nothing where the row does not say."""
    evidence = getattr(row, "decimal_comma", None)
    return f"{before}as {evidence} shows{after}" if isinstance(evidence, str) else ""


def decimal_point_text(text, row):
    """The field's text with its decimal comma made a point, in a row of a file of decimal commas
    (Row.decimal_comma; 12,5 is 12.5 there); None for a text with a point there (1.234: digit
    grouping, which is no number here)."""
    if getattr(row, "decimal_comma", False):
        return None if "." in text else text.replace(",", ".")
    return text


# Other names of the columns, in any case, as downloaded files write them: NOAA's Climate Data
# Online CSV (STATION, LATITUDE, LONGITUDE, PRCP), and spelt out. A column is read under another
# name only where the file has none of its own name.
ALIAS_OF = {"station": "station_id", "latitude": "lat", "longitude": "lon", "long": "lon", "lng": "lon",
            "prcp": "precip", "precipitation": "precip"}
# Names read as a column only where the file has neither its name nor one of ALIAS_OF, the first
# of them it has, each with the kind of file it is read in (None: any): USGS's site_no, and in a
# stations file a plain id (id, lon, lat, as a GIS file's gauges are read by the same names). An
# id in a file of observations is as likely the number of its row, and read so it matched a
# stations file's row numbers and gave wrong means without a word. A file with STATION and an ID
# of its rows reads STATION.
FALLBACKS_OF = {"station_id": (("site_no", None), ("id", "stations"))}


def fallbacks(name, what=None):
    """The names that column name may have instead in a file of what ("stations"), in order."""
    return [other for other, kind in FALLBACKS_OF.get(name, ()) if kind in (None, what)]


def other_name_of(column, what=None):
    """The column's name (any case) that it stands for in a file of what (ALIAS_OF or
    FALLBACKS_OF), else None."""
    name = column.lower()
    return ALIAS_OF.get(name) or next((wanted for wanted in FALLBACKS_OF if name in fallbacks(wanted, what)), None)


def header_name(field):
    """A header's field as a column's name: stripped of spaces, and then of a pair of double quotes
    round it ("station_id", "lon" as a program writes a header: the csv module keeps the quotes of a
    field after a space)."""
    name = field.strip()
    if len(name) >= 2 and name[0] == name[-1] == '"':
        name = name[1:-1].strip()
    return name


def header_names(fields, what=None):
    """A header's names (its fields), stripped (header_name) and in lower case, with the names they
    stand for in a file of what (other_name_of): {"station", "station_id", "lat", ...} for STATION,
    LAT."""
    names = {header_name(field).lower() for field in fields}
    return names | ({other_name_of(name, what) for name in names} - {None})


def named_columns(columns, names, where, renamed=None, what=None):
    """The header's columns with each of names in its own spelling where the header has it in
    another case, or has instead one other name of it (ALIAS_OF; else the first of its fallbacks in
    a file of what it has), given in renamed (a list of (the header's name, the name read)); ends
    the script, naming where (file:line of the header), when one of names appears twice (in any
    case, or as two other names): which of them holds the values would be a guess (a reader of a
    dict keeps the last)."""
    columns = list(columns)
    for name in names:
        same = [k for k, column in enumerate(columns) if column.lower() == name.lower()]
        other = [] if same else [k for k, column in enumerate(columns) if ALIAS_OF.get(column.lower()) == name]
        if not same and not other:
            other = next(([k for k, column in enumerate(columns) if column.lower() == fallback]
                          for fallback in fallbacks(name, what) if fallback in map(str.lower, columns)), [])
        if len(same) > 1:
            fail(f"{where}: column {name!r} appears {len(same)} times (columns "
                 f"{', '.join(str(k + 1) for k in same)}): keep one")
        if len(other) > 1:
            fail(f"{where}: columns {', '.join(repr(columns[k]) for k in other)} could each be {name!r}: keep one, "
                 f"or name it {name}")
        for k in same or other:
            if other and renamed is not None:
                renamed.append((columns[k], name))
            columns[k] = name
    return columns


def is_missing(text):
    """True for an empty field or a missing-value marker (MISSING_TEXT, in any case)."""
    return (text or "").strip().lower() in MISSING


def number(row, column, path, line):
    """The field as a finite float (with a decimal comma in a file of semicolons or tabs); ends
    the script, naming file, line, column and text, if it is not one (a missing value included:
    test is_missing first where one is allowed)."""
    text = row.get(column)
    if not (text or "").strip():
        fail(f"{path}:{line}: column {column!r} is empty (a number is needed there)")
    plain = decimal_point_text((text or "").strip(), row)
    if plain is None:
        fail(f"{path}:{line}: column {column!r}: {text!r} has a point, where the file's numbers have "
             f"decimal commas ({decimal_comma_note(row, after='; ')}a point there is digit grouping: write the "
             "number without it, 1234,5)")
    try:
        if "_" in plain:  # float() takes Python's digit groups: 1_5 would be 15
            raise ValueError
        value = float(plain)
    except ValueError:
        comma = re.fullmatch(COMMA_NUMBER, plain) is not None
        fail(f"{path}:{line}: column {column!r}: {text!r} is not a number" + (
             ": a comma in a number is read, as a decimal comma, only in a file whose fields are separated "
             "by semicolons or tabs; write this one with decimal points (and no digit grouping)" if comma else ""))
    if not math.isfinite(value):  # float() takes inf, 1e999 and nan
        fail(f"{path}:{line}: column {column!r}: {text!r} is not a finite number")
    return value


def integer(row, column, path, line, low, high):
    """The field as an int in [low, high] (decimal digits, optionally followed by a point and
    zeros, as a spreadsheet or pandas writes a whole-number column: 1963.0, or 1963,0 where a
    decimal comma may be used); ends the script naming it otherwise."""
    text = (row.get(column) or "").strip()
    whole = re.fullmatch(r"([+-]?[0-9]+)(?:\.0*)?", decimal_point_text(text, row) or "")
    if not whole:
        pointed = getattr(row, "decimal_comma", False) and "." in text
        fail(f"{path}:{line}: column {column!r}: {text!r} is not an integer" + (
             f" (the file's numbers have decimal commas{decimal_comma_note(row, ', ')}: write it without the "
             "point, or with a decimal comma)" if pointed else ""))
    value = int(whole.group(1))
    if not low <= value <= high:
        fail(f"{path}:{line}: column {column!r}: {value} is outside {low}..{high}")
    return value


def text(row, column, path, line):
    """The field stripped of spaces; ends the script, naming file, line and column, if empty."""
    value = (row.get(column) or "").strip()
    if not value:
        fail(f"{path}:{line}: column {column!r} is empty")
    return value


def gauges(path, optional=(), coordinates=("lon", "lat"), distinct=False, numbers=()):
    """Yields (line, row, station_id, name, lon, lat) for each gauge of a stations file: columns
    station_id, lon, lat (degrees; or the columns named by coordinates, such as x, y), an optional
    name, the other optional columns named (checked as rows() checks them), and any others (left
    in row). The coordinates, the optional columns but name, and the columns numbers names (read
    as numbers by another reader of the same file) decide whether the file's numbers have decimal
    commas (rows()' numbers). distinct: a record whose station id and coordinates are written as
    an earlier one's is passed over (a file of observations with the station's place on each row:
    millions of rows, a few hundred stations), and so is one whose coordinates are empty where
    another row of its station gives them (said once; a station that no row places ends the
    script, naming its first such line)."""
    x, y = coordinates
    seen, placed, unplaced = set(), set(), {}  # (distinct) unplaced: station id: [first line, rows]
    for line, row in rows(path, ("station_id", x, y), "stations", ("name", *optional),
                          numbers=(x, y, *optional, *numbers)):
        if distinct:
            station = (row["station_id"] or "").strip()
            if station and not ((row[x] or "").strip() and (row[y] or "").strip()):
                unplaced.setdefault(station, [line, 0])[1] += 1
                continue
            written = (row["station_id"], row[x], row[y])
            if written in seen:
                continue
            seen.add(written)
            placed.add(station)
        yield (line, row, text(row, "station_id", path, line), (row.get("name") or "").strip(),
               number(row, x, path, line), number(row, y, path, line))
    say_unplaced_rows(path, unplaced, placed, coordinates)


def say_unplaced_rows(path, unplaced, placed, coordinates):
    """Says that rows of a file of stations and observations without coordinates (unplaced:
    station id: [first line, rows]) take their station's place from its other rows (placed: the
    stations that have one); a station of no such row ends the script."""
    lost = next(((station, line) for station, (line, _) in unplaced.items() if station not in placed), None)
    if lost:
        fail(f"{path}:{lost[1]}: station {lost[0]} lacks its {coordinates[0]} or {coordinates[1]} here and on every "
             "other row (each station needs its place on one row at least)")
    if unplaced:
        station, (line, count) = next(iter(unplaced.items()))  # (the first met: the smallest line)
        total = sum(count for _, count in unplaced.values())
        print(f"{path}:{line}: station {station} lacks its {coordinates[0]} or {coordinates[1]} on this row: its place "
              f"is taken from its other rows ({total} row(s) of {len(unplaced)} station(s) so)", file=sys.stderr)


def station_key(station_id):
    """A station id as vtkThiessenArealAverage matches it: trimmed of spaces, tabs and quotes and,
    for an integer id (digits only), without its leading zeros, so that "050109" and 50109 (the
    same id after a spreadsheet dropped its zeros) are one station, as is 50109.0 (or 50109,0: a
    whole-number column with gaps as pandas writes it); any other id as its text. The examples
    compare station ids through it (colorado_areal_precipitation.py matches observations to gauges,
    project_gauges.py names ids given twice), so that they agree with the filter and each other."""
    text = station_id.strip(" \t\"")
    whole = re.fullmatch(r"([0-9]+)[.,]0*", text)
    if whole:
        text = whole.group(1)
    if text and all("0" <= c <= "9" for c in text):
        text = text.lstrip("0") or "0"
    return text


def repeats(keys):
    """(k, first) for each item of keys (one per record, hashable) that an earlier item equals: its
    index and the index of the first with that key, in order."""
    first, found = {}, []
    for k, key in enumerate(keys):
        earlier = first.setdefault(key, k)
        if earlier != k:
            found.append((k, earlier))
    return found


def say_repeats(path, lines, keys, what, name, noun):
    """Says on stderr, on one line under the file's name, which records repeat an earlier record's
    key (keys: one per record; record k, counted from 0, is on line lines[k]): what says what the
    repeats are and what is done with them ("station id(s) are given to more than one gauge"), and
    each is named by name(k, first) with the two records' numbers (noun: "gauge") and lines, as
    colorado_areal_precipitation.py names gauges that share a station id: "102 (gauges 0 and 1:
    lines 2 and 3)"; the first 20, then how many more. A repeated id or place is kept and used as
    any other record, but said: a file's copy-and-paste slip, or two records of one place, weigh
    in the results without a word otherwise. Returns the (k, first) pairs (repeats')."""
    found = repeats(keys)
    if found:
        shown = ", ".join(f"{name(k, first)} ({noun}s {first} and {k}: lines {lines[first]} and {lines[k]})"
                          for k, first in found[:20])
        more = f" and {len(found) - 20} more" if len(found) > 20 else ""
        print(f"{path}: {len(found)} {what}: {shown}{more}", file=sys.stderr)
    return found


def header_columns(path, what, wanted):
    """The column names of the header of the CSV file at path (what it holds: "stations") as
    header_names gives them, its separator chosen by the wanted columns as rows() chooses it; none
    for a header that is not well-formed CSV (rows() names it)."""
    header = next(text_lines(decoded(path, what, head=True).lstrip()), "").rstrip("\r\n")  # (\r alone too)
    try:
        return header_names(next(csv.reader([header], delimiter=header_delimiter(header, wanted)), []), what)
    except csv.Error:
        return set()


def check_paths(*given):
    """Ends the script, naming the option, for a file option given an empty path (given: (option,
    its value or None where not given, what the file holds: "stations")): the messages of the
    file's reading start with its path, which would leave ": no such stations file" without a name.
    Called before any work (a path of spaces alone is taken as a slip too)."""
    for option, path, what in given:
        if path is not None and not path.strip():
            fail(f"{option} {path!r}: an empty path (give the {what} file)")


def output_directory(path):
    """Makes the directory path (--out) with its parents unless it exists; ends the script, naming
    it and why, when it is something else (a file), cannot be made (a file where a parent should
    be, no permission), or is a directory where no file can be written (no permission, a read-only
    file system, /proc). Called before the inputs are read, so that a bad --out is told at once,
    not as a traceback once the work is done. Writing is tried (a temporary file made, a byte written
    to it, and removed):
    os.access answers from the permission bits, which do not stop root, nor tell of ACLs or a
    read-only mount. The directory exists by then, so the system's reason for a file it would not
    make is said in those words (/proc gave "No such file or directory" for a directory that is
    there); a test file that cannot be removed is named, and the script goes on (files can be
    written there)."""
    if not path.strip():
        fail(f"--out {path!r}: an empty path (give a directory, such as out)")
    if os.path.exists(path) and not os.path.isdir(path):
        fail(f"--out {path}: exists and is not a directory")
    # (recorded before: a makedirs that fails halfway leaves the outer ones made)
    MADE_DIRECTORIES.extend(missing_directories(path))
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as error:
        fail(f"--out {path}: cannot create the directory ({error.strerror or error})")
    try:
        handle, probe = tempfile.mkstemp(prefix=".tessera_write_test_", dir=path)
    except OSError as error:
        fail(f"--out {path}: no file can be made there ({cannot_make_reason(error)})")
    try:
        # A byte written and closed: a full disk with inodes left makes an empty file, and a
        # network file system may tell of a full disk only at the close.
        try:
            os.write(handle, b"x")
        finally:
            os.close(handle)
    except OSError as error:
        try:
            os.remove(probe)
        except OSError:
            pass
        fail(f"--out {path}: no file can be written there ({cannot_make_reason(error)})")
    try:
        os.remove(probe)
    except OSError as error:
        print(f"warning: --out {path}: a test file made there could not be removed ({error.strerror or error}); "
              f"it is left behind: {probe}", file=sys.stderr)


def cannot_make_reason(error):
    """Why no file could be made in a directory that exists, from the OSError of the attempt: no
    permission, a read-only file system, a full disk, or the system's own words for the rest (a
    "No such file or directory" of /proc said as the system's refusal, not as a missing path)."""
    reasons = {errno.EACCES: "no permission to write in it", errno.EPERM: "no permission to write in it",
               errno.EROFS: "a read-only file system", errno.ENOSPC: "no space left on the device",
               errno.EDQUOT: "the disk quota is used up"}
    if error.errno in reasons:
        return reasons[error.errno]
    return f"the system refused a new file: {error.strerror or error}"


def write_vtk(writer, data, path):
    """Writes data with the VTK writer to path; ends the script naming the file and why when it
    cannot be written (a directory of that name, no permission, a full disk): VTK's writers log
    such an error and go on, and the script said it wrote the file."""
    errors = []
    catch_vtk_messages(writer, errors.append)
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.Write()
    if errors or writer.GetErrorCode():
        reason = ("a directory of that name exists" if os.path.isdir(path)
                  else errors[0] if errors else f"VTK error code {writer.GetErrorCode()}")
        fail(f"{path}: cannot write ({reason})")


# The directories output_directory made or tried to make (the deepest last), which a run that
# ends on an error message removes where it left them empty: a trial's run that ended on a bad
# catchment left its new --out directory behind.
MADE_DIRECTORIES = []


def missing_directories(path):
    """path and those of its parents that do not exist, the outermost first."""
    missing = []
    path = os.path.abspath(path)
    while not os.path.exists(path):
        missing.insert(0, path)
        parent = os.path.dirname(path)
        if parent == path:
            break
        path = parent
    return missing


def remove_made_directories():
    """Removes the directories output_directory made that are empty, the deepest first (rmdir
    removes nothing else: one holding a file, or not made, stays)."""
    for directory in reversed(MADE_DIRECTORIES):
        try:
            os.rmdir(directory)
        except OSError:
            continue


def run(main):
    """Runs a script's main(); an OSError about a file that it did not expect (an output path that
    is a directory, no permission, a full disk) ends the script with one line naming the file and
    why, not a traceback after the work is done. A run that ends on an error message (a
    SystemExit other than 0) removes the --out directories it made and left empty."""
    MADE_DIRECTORIES.clear()  # (this run's only)
    try:
        try:
            main()
        except OSError as error:
            if error.filename is None:
                raise
            fail(f"{error.filename}: {error.strerror or error}")
    except SystemExit as end:
        if end.code not in (None, 0):
            remove_made_directories()
        raise


def import_tessera():
    """The tessera package; ends the script with how to run it when Python cannot find it."""
    try:
        import tessera
    except ImportError as error:
        fail(f"cannot import tessera ({error}): run with Debian's /usr/bin/python3 and "
             "PYTHONPATH=build/python after scripts/build (scripts/demo does both)")
    return tessera


def vtk_message_text(message):
    """The text of a VTK error or warning as an ErrorEvent or WarningEvent observer receives it
    ("ERROR: In file.cxx, line N\nvtkClass (0x...): text\n\n"), on one line, without the source
    line and the object's class and address."""
    lines = [line.strip() for line in message.strip().splitlines()]
    if lines and re.match(r"(ERROR|Warning|Generic Warning): In ", lines[0]):
        lines = lines[1:]
    text = " ".join(line for line in lines if line)
    return re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", text)


def catch_vtk_messages(algorithm, on_error, on_warning=None, on_executive_error=None):
    """Passes the text (vtk_message_text) of each error of the algorithm to on_error, of each of its
    warnings to on_warning and of each error of its executive to on_executive_error. A VTK object
    with an ErrorEvent or WarningEvent observer passes its messages to the observer instead of
    printing them (as a log line with the time, thread and object address); the executive's error
    is the follow-up "Algorithm ... returned failure for request: ..." with a dump of the request,
    kept back when on_executive_error is None. Without on_warning, warnings print as VTK prints
    them."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand

    def observer(handler):
        @calldata_type(VTK_STRING)
        def on_message(caller, event, message):
            if handler is not None:
                handler(vtk_message_text(message))
        return on_message

    algorithm.AddObserver(vtkCommand.ErrorEvent, observer(on_error))
    if on_warning is not None:
        algorithm.AddObserver(vtkCommand.WarningEvent, observer(on_warning))
    algorithm.GetExecutive().AddObserver(vtkCommand.ErrorEvent, observer(on_executive_error))


def errors_of_update(algorithm, *port):
    """Updates the algorithm (its output port, where one is given) and returns the texts of its
    errors and its executive's, its warnings dropped (the callers end the script on an error)."""
    errors = []
    catch_vtk_messages(algorithm, errors.append, lambda text: None, errors.append)
    algorithm.Update(*port)
    return errors


def point_error(text, path, lines, name):
    """A filter's error `text` about a point of the data read from `path`, as one line naming the
    file's line of that point, or None when the error names no point. The filters name a bad point
    as "point N (x, y) ..." (N counted from 0: the file's N-th record, on line lines[N]); the line
    reads "path:line: name(N) at (x, y) ..."."""
    point = re.match(r"point (\d+) (.*)", text)
    if not point or int(point.group(1)) >= len(lines):
        return None
    g = int(point.group(1))
    return f"{path}:{lines[g]}: {name(g)} at {point.group(2)}"


def main(argv=None):
    # `python3 csv_input.py` with or without --help: what the module is for, since the README's
    # "every script takes --help" reaches this file too.
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.parse_args(argv)
    parser.print_help()


if __name__ == "__main__":
    main()
