"""File formats of the ABM workbench, and what they share: atomic writing and strict JSON.

- :mod:`.staircase_json`: staircase stock, ``abm-staircase/1`` JSON (mm).
- :mod:`.toolpath_csv`: one pass of CL points with tool orientation, CSV (mm, degrees).
- :mod:`.apt`: toolpaths from APT / CL data files.
- :mod:`.results_csv`: an Engagement as CSV, one row per (CL point, φ), plus a summary.
- :mod:`.results_npz`: the same columns as one NumPy archive (``.npz``), one array per column.

Bad input raises :class:`abm_workbench.errors.InputError` naming the file and the line or
item. Every reader takes numbers in one grammar (:data:`NUMBER`: ASCII digits, an optional
sign, a decimal point, an exponent; no words such as ``nan``, no ``_``, no other scripts'
digits) and refuses magnitudes above :data:`MAX_MAGNITUDE`; JSON is read with limits on
nesting, integer length and duplicate keys (:func:`load_json_object`).

Files are never left half written: :func:`replacing` stages every output beside its
target and swaps it in only when all of them are complete.
"""

import contextlib
import json
import math
import os
import re
import secrets
import stat

from ..errors import InputError, note


#: The number grammar of every reader: optional sign, ASCII digits with an optional decimal point, optional exponent.
NUMBER = r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
_NUMBER = re.compile(NUMBER)
#: Largest magnitude of a number read (1e12: mm, degrees, feeds and counts are all far below).
MAX_MAGNITUDE = 1e12
#: Largest magnitude of an angle read (degrees): a table or rotary axis turned by thousands of turns
#: (1e12° passes MAX_MAGNITUDE but is no machine's angle).
MAX_ANGLE = 1e6
#: Deepest nesting of JSON arrays and objects read.
MAX_JSON_DEPTH = 64
#: Most digits of a JSON integer kept as an int (longer ones are read as float, then refused as too large).
_JSON_INTEGER_DIGITS = 18


def parse_number(text, where):
    """The float written as `text` (blanks around it dropped) in the :data:`NUMBER` grammar.

    InputError naming `where` (e.g. ``"toolpath.csv:7: column 'x'"``) for any other text and
    for a magnitude above :data:`MAX_MAGNITUDE`.
    """
    stripped = text.strip()
    if not _NUMBER.fullmatch(stripped):
        if stripped.lower().lstrip("+-") in ("nan", "inf", "infinity"):
            raise InputError(f"{where}: {stripped!r} is not a finite number (digits 0-9, optional sign, '.' and "
                             "exponent)")
        raise InputError(f"{where}: {stripped!r} is not a number (digits 0-9, optional sign, '.' and exponent)")
    return checked_magnitude(float(stripped), where)


def checked_magnitude(number, where):
    """`number` (a finite float) if |number| ≤ :data:`MAX_MAGNITUDE`; InputError naming `where` otherwise."""
    if not abs(number) <= MAX_MAGNITUDE:
        raise InputError(f"{where}: {number:g} is too large (at most {MAX_MAGNITUDE:g} in magnitude)")
    return number


#: Characters a staged output's hidden name adds to its target's name (:func:`_new_temporary`:
#: ".NAME.<12 hex>.tmp"; report.staging's folders add fewer).
STAGING_EXTRA = 18


def check_output_path(path):
    """InputError unless `path` can name an output file: not empty, not an existing folder, link or
    special file (a FIFO, socket or device: replacing it would break it), not ending in a folder
    separator, and a name short enough for its staged hidden twin (at most
    the folder's NAME_MAX − :data:`STAGING_EXTRA` bytes, 237 on most file systems). Meant to run
    before any computation, so that a bad --out fails at once."""
    text = os.fspath(path)
    if not text.strip():
        raise InputError("an output path is empty; give a file name")
    if text.endswith(os.sep) or os.path.isdir(text):
        raise InputError(f"{text}: is a folder; give a file name for the output")
    if os.path.islink(text):
        raise InputError(f"{text}: is a symbolic link (to {os.readlink(text)}); it would be replaced by the "
                         "output: give the file's own path")
    if os.path.lexists(text) and not stat.S_ISREG(os.lstat(text).st_mode):
        raise InputError(f"{text}: is {_kind(os.lstat(text).st_mode)}, not a file; it would be replaced by "
                         "the output: give a file name")
    folder, name = os.path.split(os.path.abspath(text))
    while not os.path.isdir(folder):
        folder = os.path.dirname(folder)
    try:
        longest = os.pathconf(folder, "PC_NAME_MAX") - STAGING_EXTRA
    except (OSError, ValueError):
        longest = 255 - STAGING_EXTRA
    if len(name.encode("utf-8", "surrogateescape")) > longest:
        raise InputError(f"{text}: the file name is {len(name.encode('utf-8', 'surrogateescape'))} bytes long; "
                         f"at most {longest} are allowed here")


#: Callables (no arguments) run right before staged outputs start moving into place (replacing, and
#: report.staging.staged). The command line adds one that ignores stop signals from then on: a run whose
#: outputs are moving is finishing, and stopped between two moves it would leave a mixed set.
BEFORE_MOVES = []


def before_moves():
    """Run BEFORE_MOVES."""
    for callback in BEFORE_MOVES:
        callback()


@contextlib.contextmanager
def replacing(*paths):
    """Stage new versions of `paths`: yield a list of temporary paths, one per target.

    Each temporary file is created empty in its target's folder. When the block finishes,
    each is moved onto its target with os.replace; if the block raises anything (including
    KeyboardInterrupt), every temporary file is removed and the targets are left as they were.
    Each final move is atomic; the callables in BEFORE_MOVES run before the first (the command line
    ignores stop signals from then on), so only a crash between two of them could leave a mixed set.
    """
    temporaries = []
    try:
        for path in paths:
            _new_temporary(os.fspath(path), temporaries)
        yield list(temporaries)
        before_moves()
        for temporary, path in zip(temporaries, paths):
            os.replace(temporary, path)
    except BaseException:
        for temporary in temporaries:
            with contextlib.suppress(FileNotFoundError):
                os.remove(temporary)
        raise


def _new_temporary(path, temporaries):
    """Create an empty, hidden, uniquely named file beside `path` (permissions by umask), appended to the
    list `temporaries` before it is created: a stop signal right after the file appears finds it listed."""
    folder, name = os.path.split(path)
    while True:
        temporaries.append(os.path.join(folder, f".{name}.{secrets.token_hex(6)}.tmp"))
        try:
            os.close(os.open(temporaries[-1], os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
            return
        except FileExistsError:
            temporaries.pop()


#: Memory a text file takes to read, in bytes per byte of the file: the text, its lines and their
#: fields or records as Python objects (a CL file's CL points about 8×, the text reader's lines more).
TEXT_MEMORY_FACTOR = 16


#: What check_input_file tells to give instead of a path that is no regular file, by what the file is: whole
#: phrases, so that each is translated whole.
_GIVE = {"input": note("give the input file itself"), "stock": note("give the stock file itself"),
         "toolpath": note("give the toolpath file itself"), "job": note("give the job file itself"),
         "tool table": note("give the tool table file itself"), "machine": note("give the machine file itself"),
         "work offsets": note("give the work offsets file itself"),
         "results archive": note("give the results archive file itself")}


def check_input_file(path, what="input"):
    """InputError unless `path` names a regular file (not a folder, FIFO, socket or device such as
    /dev/zero, whose reading would block or never end), naming the file and the `what` file to give
    ("tool table"). Links are followed."""
    name = os.fspath(path)
    try:
        mode = os.stat(name).st_mode
    except OSError as error:
        raise InputError(f"{name}: cannot read: {error.strerror or error}") from None
    if not stat.S_ISREG(mode):
        give = _GIVE.get(what) or f"give the {what} file itself"
        raise InputError(f"{name}: is {_kind(mode)}, not a file; {give}")


def _kind(mode):
    """What a file of `mode` (not a regular file) is, in words."""
    for test, words in ((stat.S_ISDIR, note("a folder")), (stat.S_ISFIFO, note("a FIFO (named pipe)")),
                        (stat.S_ISSOCK, note("a socket")), (stat.S_ISCHR, note("a character device")),
                        (stat.S_ISBLK, note("a block device"))):
        if test(mode):
            return words
    return note("a special file")


def read_bytes(path, factor=TEXT_MEMORY_FACTOR):
    """The bytes of the regular file `path`; InputError naming it when it cannot be read, is no regular
    file (:func:`check_input_file`; opened without blocking, so a FIFO never hangs the reader) or is
    too large to read: `factor` × its size above the memory this process may use (limits)."""
    from ..limits import check_memory

    name = os.fspath(path)
    try:
        descriptor = os.open(name, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0))
    except OSError as error:
        raise InputError(f"{name}: cannot read: {error.strerror or error}") from None
    try:
        status = os.fstat(descriptor)
        if not stat.S_ISREG(status.st_mode):
            raise InputError(f"{name}: is {_kind(status.st_mode)}, not a file; give the input file itself")
        check_memory(factor * status.st_size, name, note(f"reading its {status.st_size:,} bytes"))
        file = open(descriptor, "rb", closefd=False)
        try:
            return file.read()
        except OSError as error:
            raise InputError(f"{name}: cannot read: {error.strerror or error}") from None
        finally:
            file.close()
    finally:
        os.close(descriptor)


def read_text(path):
    """Text of a UTF-8 file (a leading byte-order mark dropped); InputError if unreadable (read_bytes)."""
    data = read_bytes(path)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise InputError(f"{os.fspath(path)}: not UTF-8 text ({error.reason} at byte {error.start})") from None


def load_json_object(path):
    """The JSON object in file `path` as a dict; InputError with line:column for bad JSON.

    Also refused, naming the file: nesting deeper than :data:`MAX_JSON_DEPTH`, a key given
    twice in one object (naming the key and its second line). Integers longer than 18 digits
    are read as floats, so that a huge one is refused as too large by :func:`json_number`.
    """
    name = os.fspath(path)
    text = read_text(path)
    depth = _json_depth(text)
    if depth > MAX_JSON_DEPTH:
        raise InputError(f"{name}: JSON nested {depth} deep; at most {MAX_JSON_DEPTH} levels are read")
    try:
        data = json.loads(text, object_pairs_hook=_unique_keys, parse_int=_json_integer)
    except json.JSONDecodeError as error:
        raise InputError(f"{name}:{error.lineno}:{error.colno}: invalid JSON: {error.msg}") from None
    except _DuplicateKey as duplicate:
        key = duplicate.args[0]
        raise InputError(f"{name}:{_second_key_line(text, key)}: duplicate key {key!r} in one object") from None
    if not isinstance(data, dict):
        raise InputError(f"{name}: expected a JSON object {{...}}, got {type(data).__name__}")
    return data


class _DuplicateKey(Exception):
    """A key given twice in one JSON object (args[0] the key)."""


def _unique_keys(pairs):
    """dict of the (key, value) `pairs` of one JSON object; _DuplicateKey if a key repeats."""
    data = dict(pairs)
    if len(data) != len(pairs):
        seen = set()
        for key, _ in pairs:
            if key in seen:
                raise _DuplicateKey(key)
            seen.add(key)
    return data


class _LongInteger(float):
    """A JSON integer longer than _JSON_INTEGER_DIGITS digits: its float value (±inf beyond the
    doubles) and its number of characters, `length`."""

    def __new__(cls, text):
        number = super().__new__(cls, text)
        number.length = len(text)
        return number


def _json_integer(text):
    """A JSON integer's `text` as int, or as a _LongInteger when longer than _JSON_INTEGER_DIGITS."""
    return int(text) if len(text) <= _JSON_INTEGER_DIGITS else _LongInteger(text)


_JSON_TOKENS = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}]')


def _json_depth(text):
    """Deepest nesting of [ ] and { } in JSON `text`, brackets inside strings not counted."""
    depth = deepest = 0
    for token in _JSON_TOKENS.findall(text):
        if token in "[{":
            depth += 1
            deepest = max(deepest, depth)
        elif token in "]}":
            depth -= 1
    return deepest


def _second_key_line(text, key):
    """1-based line of the second ``"key":`` in JSON `text` (the first line if it is not found)."""
    found = [match.start() for match in re.finditer(re.escape(json.dumps(key)) + r"\s*:", text)]
    return text.count("\n", 0, found[1]) + 1 if len(found) > 1 else 1


def json_number(value, where):
    """`value` as float if it is a finite JSON number (not a boolean, string or NaN) of magnitude
    at most :data:`MAX_MAGNITUDE`.

    `where` names the item for the error, e.g. ``"stock.json: base_z"``.
    """
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(f"{where}: must be a number, got {json.dumps(value)}")
    if isinstance(value, _LongInteger) and not abs(value) <= MAX_MAGNITUDE:
        raise InputError(f"{where}: an integer of {value.length:,} characters is too large "
                         f"(at most {MAX_MAGNITUDE:g} in magnitude)")
    try:
        number = float(value)
    except OverflowError:
        number = math.inf
    if not math.isfinite(number):
        raise InputError(f"{where}: must be a finite number, got {value}")
    return checked_magnitude(number, where)


def check_keys(data, required, optional, where):
    """InputError naming unknown keys of dict `data`, or the first missing required key."""
    unknown = [key for key in data if key not in required and key not in optional]
    if unknown:
        names = ", ".join(repr(key) for key in unknown)
        allowed = ", ".join(repr(key) for key in (*required, *optional))
        raise InputError(f"{where}: unknown keys {names} (allowed: {allowed})" if len(unknown) > 1
                         else f"{where}: unknown key {names} (allowed: {allowed})")
    missing = [key for key in required if key not in data]
    if missing:
        raise InputError(f"{where}: missing key {missing[0]!r}")
