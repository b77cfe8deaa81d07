"""What a toolpath file holds, judged by its content, never its name.

- Binary: a NUL byte, or many control characters, in the first 64 KiB.
- The project's toolpath CSV: the first line that is not blank or a ``#`` comment is a
  comma-separated header naming ``x``, ``y`` and ``z``.
- A FreeCAD document (FCStd, a CAM Job's program): a name ending in ``.FCStd`` or a zip header.
- G-code: of the lines holding code (comments ``( )`` and ``;``, ``%`` lines and blank lines left
  out), the first that is an APT record or starts with a G-code word (a letter and a number, after
  an optional block delete ``/`` and block number) starts with a G-code word.
- APT / CL text: a record ``WORD/`` (or a bare record word such as RAPID) on some line.

Text is read as UTF-8 and, failing that, as Latin-1 (CAM systems write comments in either).
"""

import os
import re

from ...errors import InputError
from .. import read_bytes
from .lexer import BARE_WORDS

_PROBE = 65536
_ZIP = b"PK\x03\x04"
_GCODE_WORD = re.compile(r"\s*/?\s*(?:[Nn]\s*[0-9]+\s*)?[A-Za-z]\s*[-+]?\s*\.?[0-9]")
_GCODE_COMMENT = re.compile(r"\([^)]*\)|;.*")
_RECORD = re.compile(r"^\s*(?:[A-Za-z][A-Za-z0-9_ -]*\s*/|(?:" + "|".join(map(re.escape, sorted(BARE_WORDS)))
                     + r")\s*$)", re.IGNORECASE)


def read_file(path):
    """(kind, text, encoding) of the file at `path`: kind "csv", "gcode", "apt" or "fcstd" (then text and
    encoding None), encoding the one the text was read with; InputError for unreadable, binary or
    unknown content, naming the file."""
    name = os.fspath(path)
    data = read_bytes(name)
    if data.startswith(_ZIP) or name.lower().endswith(".fcstd"):
        if not data.startswith(_ZIP):
            raise InputError(f"{name}: not a FreeCAD document (an FCStd is a zip file)")
        return "fcstd", None, None
    probe = data[:_PROBE]
    controls = sum(probe.count(bytes([c])) for c in range(32) if c not in (9, 10, 12, 13, 26))
    if b"\0" in probe or controls > len(probe) // 100:
        raise InputError(f"{name}: binary content, not a CL file (APT / CLSF text) or toolpath CSV")
    encoding = "utf-8-sig" if data.startswith(b"\xef\xbb\xbf") else "utf-8"
    try:
        text = data.decode(encoding)
    except UnicodeDecodeError:
        encoding = "latin-1"
        text = data.decode(encoding)
    for line in text.splitlines():
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        fields = {field.strip().lower() for field in stripped.split(",")}
        if {"x", "y", "z"} <= fields:
            return "csv", text, encoding
        break
    if _first_code_is_gcode(text):
        return "gcode", text, encoding
    if any(_RECORD.match(line) for line in text.splitlines()):
        return "apt", text, encoding
    if not text.strip():
        raise InputError(f"{name}: empty file: no CL records and no toolpath CSV header")
    raise InputError(f"{name}: unknown content: neither G-code, APT / CL records (WORD/...) nor a toolpath CSV "
                     "header (x,y,z,...)")


def _first_code_is_gcode(text):
    """Whether the first line of `text` that is an APT record or starts with a G-code word starts with the
    latter (comments, ``%`` and blank lines left out)."""
    for line in text.splitlines():
        code = _GCODE_COMMENT.sub("", line).strip()
        if not code or code.startswith("%"):
            continue
        if _RECORD.match(line):
            return False
        if _GCODE_WORD.match(code):
            return True
    return False
