"""File formats of the ABM workbench, and what they share: atomic writing and strict JSON.

- :mod:`.staircase_json`: staircase stock, ``abm-staircase/1`` JSON (mm).
- :mod:`.toolpath_csv`: one pass of CL points with tool orientation, CSV (mm, degrees).
- :mod:`.apt`: toolpaths from APT / CL data files.
- :mod:`.results_csv`: an Engagement as CSV, one row per (CL point, φ), plus a summary.

Bad input raises :class:`abm_workbench.errors.InputError` naming the file and the line or
item. Files are never left half written: :func:`replacing` stages every output beside its
target and swaps it in only when all of them are complete.
"""

import contextlib
import json
import math
import os
import secrets

from ..errors import InputError


@contextlib.contextmanager
def replacing(*paths):
    """Stage new versions of `paths`: yield a list of temporary paths, one per target.

    Each temporary file is created empty in its target's folder. When the block finishes,
    each is moved onto its target with os.replace; if the block raises anything (including
    KeyboardInterrupt), every temporary file is removed and the targets are left as they were.
    Each final move is atomic; only a crash between two of them could leave a mixed set.
    """
    temporaries = []
    try:
        for path in paths:
            temporaries.append(_new_temporary(os.fspath(path)))
        yield list(temporaries)
        for temporary, path in zip(temporaries, paths):
            os.replace(temporary, path)
    except BaseException:
        for temporary in temporaries:
            with contextlib.suppress(FileNotFoundError):
                os.remove(temporary)
        raise


def _new_temporary(path):
    """Create an empty, hidden, uniquely named file beside `path` (permissions by umask)."""
    folder, name = os.path.split(path)
    while True:
        temporary = os.path.join(folder, f".{name}.{secrets.token_hex(6)}.tmp")
        try:
            os.close(os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
            return temporary
        except FileExistsError:
            continue


def read_text(path):
    """Text of a UTF-8 file (a leading byte-order mark dropped); InputError if unreadable."""
    try:
        with open(path, encoding="utf-8-sig") as file:
            return file.read()
    except OSError as error:
        raise InputError(f"{os.fspath(path)}: cannot read: {error.strerror or error}") from None
    except UnicodeDecodeError as error:
        raise InputError(f"{os.fspath(path)}: not UTF-8 text ({error.reason} at byte {error.start})") from None


def load_json_object(path):
    """The JSON object in file `path` as a dict; InputError with line:column for bad JSON."""
    text = read_text(path)
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise InputError(f"{os.fspath(path)}:{error.lineno}:{error.colno}: invalid JSON: {error.msg}") from None
    if not isinstance(data, dict):
        raise InputError(f"{os.fspath(path)}: expected a JSON object {{...}}, got {type(data).__name__}")
    return data


def json_number(value, where):
    """`value` as float if it is a finite JSON number (not a boolean, string or NaN).

    `where` names the item for the error, e.g. ``"stock.json: base_z"``.
    """
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(f"{where}: must be a number, got {json.dumps(value)}")
    try:
        number = float(value)
    except OverflowError:
        number = math.inf
    if not math.isfinite(number):
        raise InputError(f"{where}: must be a finite number, got {value}")
    return number


def check_keys(data, required, optional, where):
    """InputError naming unknown keys of dict `data`, or the first missing required key."""
    unknown = [key for key in data if key not in required and key not in optional]
    if unknown:
        names = ", ".join(repr(key) for key in unknown)
        allowed = ", ".join(repr(key) for key in (*required, *optional))
        raise InputError(f"{where}: unknown key{'s' if len(unknown) > 1 else ''} {names} (allowed: {allowed})")
    missing = [key for key in required if key not in data]
    if missing:
        raise InputError(f"{where}: missing key {missing[0]!r}")
