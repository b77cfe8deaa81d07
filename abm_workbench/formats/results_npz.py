"""An Engagement's results and summary as one NumPy archive (``R.npz``): one array per column.

The archive holds, as ``.npy`` members stored uncompressed (numpy.load reads them):

- ``format``: the text ``abm-results/1``;
- ``<column>``: each results column (formats.results_columns: the results CSV's names, rows and
  units), an array (rows,), one row per instant;
- ``summary/<column>``: each summary column, an array (summary rows,), one row per CL point and
  engagement segment;
- ``labels/<column>``: for each text column (uep_surface, lep_surface, case, segment) the
  names its integer codes stand for (str array; code i is labels[i]; segment: '' for none, then
  A, B, …), shared by the results and the summary.

Floats are float64 as computed (the CSV rounds them to 10 decimals), NaN where the CSV has an
empty field; integer and code columns have the dtypes of formats.results_columns.column_dtype.

:func:`write_chunks` streams the columns of a pass chunk by chunk: each results column straight
into its place in the archive (formats.stored_zip), the small summary columns through an unnamed
temporary file, so its memory is one chunk's; :func:`read_results` reads an archive back as
results_csv.read_results reads a CSV, refusing (InputError naming the file) anything else: not a zip, pickled arrays, missing or
unknown columns, wrong dtypes or lengths, codes without a label, numbers too large.
"""

import io
import math
import os
import tempfile
import zipfile
import zlib

import numpy as np

from ..errors import InputError
from . import MAX_MAGNITUDE, check_input_file
from .overlapped import consume_overlapped
from .stored_zip import StoredZip
from .results_columns import (ADDED_COLUMNS, FORCE_COLUMNS, FORCE_SUMMARY_COLUMNS, INPROCESS_COLUMNS,
                              INPROCESS_SUMMARY_COLUMNS, INT_COLUMNS, RESULT_COLUMNS, SUMMARY_COLUMNS, TEXT_COLUMNS,
                              TOOLPATH_COLUMNS, column_dtype, text_labels)

#: The `format` member's text.
FORMAT = "abm-results/1"
#: Key prefixes of the summary columns and of the labels of the text columns.
SUMMARY, LABELS = "summary/", "labels/"
#: Columns every archive has, and the ones it may have, per table.
_TABLES = {"": (tuple(c for c in RESULT_COLUMNS if c not in ADDED_COLUMNS),
               ADDED_COLUMNS + INPROCESS_COLUMNS + FORCE_COLUMNS),
           SUMMARY: (SUMMARY_COLUMNS, TOOLPATH_COLUMNS + FORCE_SUMMARY_COLUMNS + INPROCESS_SUMMARY_COLUMNS)}
#: The first bytes of a zip file (a local file header).
_ZIP = b"PK\x03\x04"
#: Bytes copied at a time from the summary columns' temporary file into the archive.
_COPY = 1 << 22


def write_chunks(parts, path, rows):
    """Write the (results columns, summary columns) pairs of the iterable `parts` (dicts name -> (rows,)
    array of formats.results_columns, the same names in every pair), in order, as the archive `path`,
    the results columns holding `rows` rows in all (CL points × angles). Returns the number of pairs.
    Memory: three pairs (one being written, one waiting, one being made), and a copy buffer.

    Each results column's member is reserved at the first pair and filled in place as the pairs arrive
    (formats.stored_zip), in a second thread while the next pair is being made (formats.overlapped);
    the summary columns, whose length is only known at the end (a row per CL point and engagement
    segment, about 1/p of the bytes), go to an unnamed temporary file beside `path` (gone with the
    process, whatever stops it) and are copied in last. ValueError when the pairs do not hold `rows`
    results rows or change their columns; write `path` itself to a temporary (formats.replacing) for
    all-or-nothing output.
    """
    path = os.fspath(path)
    with _SpilledColumns(os.path.dirname(os.path.abspath(path))) as summary, StoredZip(path) as archive:
        _add_array(archive, "format", np.array(FORMAT))
        results = _ResultColumns(archive, rows)

        def write(pair):
            results.add(pair[0])
            summary.add(pair[1])

        count = consume_overlapped(parts, write)
        for key, dtype in summary.dtypes.items():
            member = _reserve(archive, SUMMARY + key, dtype, summary.rows[key])
            for block in summary.blocks(key):
                archive.append(member, block)
        codes = results.codes
        for name, code in summary.codes.items():
            codes[name] = max(code, codes.get(name, 0))
        for text in TEXT_COLUMNS:
            if text in codes:
                _add_array(archive, LABELS + text, np.array(text_labels(text, codes[text] + 1), dtype=str))
    return count


class _ResultColumns:
    """The results columns of an archive being written: each one's member reserved for `rows` rows at
    the first chunk, then filled chunk by chunk; per text column, the largest code seen."""

    def __init__(self, archive, rows):
        self.archive, self.rows, self.members, self.codes = archive, rows, None, {}

    def add(self, columns):
        """Append the arrays of dict `columns`; ValueError when the names or dtypes differ from the first chunk's."""
        if self.members is None:
            self.members = {name: _reserve(self.archive, name, column_dtype(name), self.rows) for name in columns}
        if list(columns) != list(self.members):
            raise ValueError(f"chunk columns {list(columns)} differ from the first chunk's {list(self.members)}")
        for name, values in columns.items():
            values = _checked(name, values, column_dtype(name))
            self.archive.append(self.members[name], values)
            if name in TEXT_COLUMNS and values.size:
                self.codes[name] = max(self.codes.get(name, 0), int(values.max()))


def _npy_header(dtype, rows):
    """The .npy (format 1.0) header of a C-ordered array (rows,) of `dtype`, as bytes."""
    header = io.BytesIO()
    np.lib.format.write_array_header_1_0(header, {"descr": np.lib.format.dtype_to_descr(np.dtype(dtype)),
                                                  "fortran_order": False, "shape": (int(rows),)})
    return header.getvalue()


def _reserve(archive, key, dtype, rows):
    """The member key.npy of `archive` reserved for an array (rows,) of `dtype`, its .npy header written."""
    header = _npy_header(dtype, rows)
    member = archive.reserve(key + ".npy", len(header) + int(rows) * np.dtype(dtype).itemsize)
    archive.append(member, header)
    return member


def _add_array(archive, key, array):
    """The member key.npy of `archive` holding `array` (1-D or a scalar; no objects)."""
    data = io.BytesIO()
    np.lib.format.write_array(data, array, allow_pickle=False)
    archive.add(key + ".npy", data.getbuffer())


def _checked(key, values, dtype):
    """`values` as a contiguous array; ValueError unless it is 1-D of `dtype`."""
    values = np.ascontiguousarray(values)
    if values.dtype != dtype or values.ndim != 1:
        raise ValueError(f"column {key}: {values.dtype} {values.shape}, expected {dtype} (rows,)")
    return values


class _SpilledColumns:
    """Summary columns appended chunk by chunk to one unnamed temporary file in `folder`, each chunk's
    columns one after the other: per column its dtype (in column order), row count, the (offset, bytes)
    spans it holds and, per text column, the largest code seen. A context manager closing the file."""

    def __init__(self, folder):
        self.file = tempfile.TemporaryFile(dir=folder)
        self.dtypes, self.rows, self.codes, self.spans, self._end = {}, {}, {}, {}, 0

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.file.close()
        return False

    def add(self, columns):
        """Append the arrays of dict `columns`; ValueError when the names or dtypes differ from the first chunk's."""
        if self.dtypes and list(columns) != list(self.dtypes):
            raise ValueError(f"chunk columns {list(columns)} differ from the first chunk's {list(self.dtypes)}")
        for key, values in columns.items():
            if key not in self.dtypes:
                self.dtypes[key], self.rows[key], self.spans[key] = column_dtype(key), 0, []
            values = _checked(SUMMARY + key, values, self.dtypes[key])
            self.file.write(values.data)
            self.spans[key].append((self._end, values.nbytes))
            self._end += values.nbytes
            self.rows[key] += values.size
            if key in TEXT_COLUMNS and values.size:
                self.codes[key] = max(self.codes.get(key, 0), int(values.max()))

    def blocks(self, key):
        """The bytes of column `key`, in order, in blocks of at most _COPY bytes."""
        self.file.flush()
        for offset, size in self.spans[key]:
            for start in range(offset, offset + size, _COPY):
                yield os.pread(self.file.fileno(), min(_COPY, offset + size - start), start)


def read_results(path, summary=False):
    """The results columns (summary: the summary columns) of archive `path`, as a dict name -> (rows,)
    array, as formats.results_csv.read_results gives a CSV's: text columns as str arrays, integer
    columns as int, every other float (NaN: no value; here the doubles as computed, not rounded).
    InputError naming the file for anything but an archive written by write_chunks."""
    return read_tables(path)[1 if summary else 0]


def read_tables(path):
    """(results columns, summary columns) of archive `path` (read_results)."""
    name = os.fspath(path)
    arrays = _arrays(name)
    text = arrays.pop("format", None)
    if text is None or text.shape != () or text.dtype.kind != "U" or str(text) != FORMAT:
        raise InputError(f"{name}: not an ABM results archive (no 'format' member saying {FORMAT})")
    labels = {key[len(LABELS):]: arrays.pop(key) for key in list(arrays) if key.startswith(LABELS)}
    tables = []
    for prefix, (required, optional) in _TABLES.items():
        keys = [key for key in arrays if key.startswith(SUMMARY) == (prefix == SUMMARY)]
        columns = {key[len(prefix):]: arrays.pop(key) for key in keys}
        missing = [column for column in required if column not in columns]
        if missing:
            raise InputError(f"{name}: not a results archive: no array {prefix + missing[0]!r}")
        unknown = [column for column in columns if column not in required + optional]
        if unknown:
            raise InputError(f"{name}: unknown array {prefix + unknown[0]!r} in a results archive")
        rows = columns[required[0]].shape
        tables.append({column: _column(name, prefix + column, values, rows, labels)
                       for column, values in columns.items()})
    return tuple(tables)


#: Most members an archive may hold (the columns of results, summary and labels are far fewer).
MAX_MEMBERS = 256
#: Longest .npy header read (numpy writes them padded to 64 bytes or a few more).
_MAX_HEADER = 4096


def _arrays(name):
    """Every member of the npz file `name` as a dict key -> array; InputError when it is not one.

    The archive is read as write_chunks writes it, never more than the file holds: members stored
    uncompressed (a compressed member could expand a small file to any size), .npy headers of plain
    dtypes (no objects, no pickles) whose shape's bytes are exactly the member's, at most
    :data:`MAX_MEMBERS` members; anything else is refused naming the file and the member."""
    check_input_file(name, "results archive")
    try:
        with open(name, "rb") as handle:
            magic = handle.read(4)
            size = os.fstat(handle.fileno()).st_size
    except OSError as error:
        raise InputError(f"{name}: cannot read: {error.strerror or error}") from None
    if magic != _ZIP:
        raise InputError(f"{name}: not a results archive (an .npz file is a zip file, and this is not one)")
    try:
        with zipfile.ZipFile(name) as archive:
            members = archive.infolist()
            if len(members) > MAX_MEMBERS:
                raise InputError(f"{name}: not a results archive: {len(members):,} members (at most {MAX_MEMBERS})")
            return {_member_key(name, member): _member_array(name, archive, member, size) for member in members}
    except OSError as error:
        raise InputError(f"{name}: cannot read: {error.strerror or error}") from None
    except (ValueError, EOFError, KeyError, NotImplementedError, RuntimeError, zipfile.BadZipFile,
            zlib.error) as error:
        if isinstance(error, InputError):
            raise
        raise InputError(f"{name}: not a results archive: damaged ({error})") from None


def _member_key(name, member):
    """The key of a member 'key.npy'; InputError for any other name."""
    if not member.filename.endswith(".npy") or member.is_dir():
        raise InputError(f"{name}: not a results archive: member {member.filename!r} is not an .npy array")
    return member.filename[:-len(".npy")]


def _member_array(name, archive, member, size):
    """The array of one stored member, its header and size checked first (see _arrays)."""
    where = f"{name}: not a results archive: member {member.filename!r}"
    if member.compress_type != zipfile.ZIP_STORED:
        raise InputError(f"{where} is compressed; the archives written here store their arrays uncompressed")
    if not 0 <= member.file_size <= size:
        raise InputError(f"{where} claims {member.file_size:,} bytes in a file of {size:,}")
    with archive.open(member) as data:
        try:
            version = np.lib.format.read_magic(data)
            reader = {(1, 0): np.lib.format.read_array_header_1_0, (2, 0): np.lib.format.read_array_header_2_0}
            if version not in reader:
                raise ValueError(f"npy version {version}")
            shape, fortran, dtype = reader[version](data, max_header_size=_MAX_HEADER)
        except Exception as error:  # numpy's header parser raises ValueError, SyntaxError, TokenError, ...
            raise InputError(f"{where}: not an .npy header ({type(error).__name__}: {error})") from None
        if dtype.hasobject or dtype.itemsize == 0 or dtype.kind not in "biufU":
            raise InputError(f"{where}: holds {dtype} values, which are not read (no pickled objects)")
        if not (isinstance(shape, tuple) and all(isinstance(n, int) and n >= 0 for n in shape) and len(shape) <= 1):
            raise InputError(f"{name}: not a results archive: array {member.filename[:-len('.npy')]!r}: shape "
                             f"{shape!r}; a results array is 1-D or a scalar")
        count = math.prod(shape)
        body = member.file_size - data.tell()
        if count * dtype.itemsize != body:
            raise InputError(f"{where}: shape {shape} of {dtype} needs {count * dtype.itemsize:,} bytes; the member "
                             f"holds {body:,}")
        values = np.empty(count, dtype=dtype)
        if body and data.readinto(memoryview(values.view(np.uint8))) != body:
            raise InputError(f"{where}: cut short")
    return values.reshape(shape)


def _column(name, key, values, rows, labels):
    """Column `key` of archive `name` checked (dtype, shape `rows`, codes, magnitudes) and read."""
    column = key.rsplit("/", 1)[-1]
    dtype = column_dtype(column)
    if values.dtype != dtype or values.shape != rows:
        raise InputError(f"{name}: array {key!r}: {values.dtype} of shape {values.shape}, expected {dtype} of "
                         f"shape {rows}")
    if column in TEXT_COLUMNS:
        names = labels.get(column)
        if names is None or names.ndim != 1 or names.dtype.kind != "U":
            raise InputError(f"{name}: array {key!r}: no labels ({LABELS + column!r}: a 1-D str array)")
        bad = np.flatnonzero((values < 0) | (values >= names.size))
        if bad.size:
            raise InputError(f"{name}: array {key!r}: row {bad[0]}: code {values[bad[0]]} has no label "
                             f"(labels 0..{names.size - 1})")
        return names[values]
    if column in INT_COLUMNS:
        return values.astype(int)
    bad = np.flatnonzero(~(np.abs(values) <= MAX_MAGNITUDE) & ~np.isnan(values))
    if bad.size:
        raise InputError(f"{name}: array {key!r}: row {bad[0]}: {values[bad[0]]:g} is too large (at most "
                         f"{MAX_MAGNITUDE:g} in magnitude)")
    return values
