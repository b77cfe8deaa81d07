"""LinuxCNC tool tables: the tools a G-code program's ``T… M6`` load, by number.

Each line ``T<n> P<pocket> [X…] [Y…] Z<length> [A… B… C…] D<diameter> [I… J… Q…] ;comment`` (any
order, any case; lengths in the machine's units, mm unless said) describes tool n: D its diameter, Z its length offset (taken as the
tool's length), the comment its name. Lines with only a comment, blank lines and the other words
(pocket, lathe angles and orientation, other offsets) are accepted and not used. The comment names
the kind where it says it (:func:`kind_of_comment`): ``ball`` (corner radius D/2), ``bull`` /
``bullnose`` / ``torus`` (its corner radius written ``R1.5``), ``end mill`` / ``endmill`` / ``flat``
(corner radius 0), and the words a CL file's tool names use (drill, tap, spot drill, reamer, …);
a tool whose comment says none is of unknown kind, with its diameter.
"""

import os
import re

from ...errors import InputError
from .. import MAX_MAGNITUDE, read_text
from ..cl.lexer import split_lines
from ..cl.tools import ToolSpec, kind_of_name

_WORD = re.compile(r"([A-Za-z])\s*([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))")
_LETTERS = set("TPXYZABCUVWDIJQ")
_RADIUS = re.compile(r"\bR\s*([0-9]+\.?[0-9]*|\.[0-9]+)")
_BALL = re.compile(r"\bBALL")
_BULL = re.compile(r"\bBULL|\bTORUS|CORNER\s*RAD")
_FLAT = re.compile(r"END\s*MILL|\bFLAT\b|SQUARE")


def load_tool_table(path, scale=1.0):
    """{tool number: ToolSpec} of the LinuxCNC tool table at `path`, its lengths times `scale` (the machine's
    unit in mm: 1 or 25.4); InputError naming the file and line."""
    name = os.fspath(path)
    tools = {}
    for number, raw in enumerate(split_lines(read_text(name)), start=1):
        code, _, comment = raw.partition(";")
        code = code.strip()
        if not code:
            continue
        words, at = {}, 0
        compact = "".join(code.split())
        while at < len(compact):
            match = _WORD.match(compact, at)
            if match is None or match.group(1).upper() not in _LETTERS:
                shown = compact[at:at + 12]
                raise InputError(f"{name}:{number}: {shown}: not a tool table word (T P X Y Z A B C U V W D I J Q "
                                 "and a number)")
            letter, value = match.group(1).upper(), float(match.group(2))
            if letter in words:
                raise InputError(f"{name}:{number}: {letter}: given twice on the line")
            if abs(value) > MAX_MAGNITUDE:
                raise InputError(f"{name}:{number}: {match.group()}: the number is above {MAX_MAGNITUDE:g}")
            words[letter] = value
            at = match.end()
        if "T" not in words:
            raise InputError(f"{name}:{number}: no T word: each line of a tool table describes tool T<n>")
        tool = int(words["T"])
        if tool in tools:
            raise InputError(f"{name}:{number}: T{tool}: the table describes tool {tool} twice")
        source = f"{os.path.basename(name)} line {number} (T{tool})"
        tools[tool] = table_tool(_scaled(words.get("D"), scale), _scaled(words.get("Z"), scale), comment.strip(),
                                 source, scale)
    return tools


def _scaled(value, scale):
    """`value` times `scale`, None for None."""
    return None if value is None else value * scale


def table_tool(diameter, length, comment, source, scale=1.0):
    """The ToolSpec of a tool table line: `diameter` and `length` mm (None or 0: not given), its `comment`
    naming it (and its kind: :func:`kind_of_comment`, a corner radius written there times `scale`),
    `source` the record it came from."""
    diameter = diameter if diameter and diameter > 0.0 else None
    kind, radius = kind_of_comment(comment, diameter, scale)
    return ToolSpec(kind, diameter, radius, None, (source,), unit="inch" if scale != 1.0 else "mm", name=comment,
                    length=length if length and length > 0.0 else None)


def kind_of_comment(comment, diameter, scale=1.0):
    """(kind, corner radius mm or None) that a tool table comment says for a tool of `diameter` mm; a radius
    written in the comment (``R1.5``) times `scale`, the table's unit in mm."""
    text = " ".join(str(comment).upper().replace("_", " ").replace("-", " ").split())
    if _BALL.search(text):
        return "ball", None if diameter is None else diameter / 2.0
    if _BULL.search(text):
        radius = _RADIUS.search(text)
        return "bull-nose", float(radius.group(1)) * scale if radius else None
    other = kind_of_name(text)
    if other is not None:
        return other, None
    if _FLAT.search(text):
        return "flat", 0.0
    return "unknown", None
