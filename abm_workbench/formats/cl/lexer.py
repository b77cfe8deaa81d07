"""CL text split into records: comments kept apart, continuations joined, arguments split.

Rules (every CAM system's APT / CLSF output): ``$$`` starts a comment (a whole line or the
end of one); a record whose text ends with ``$`` continues on the next line that holds text;
a whole-line comment ending with ``$`` continues on the next line unless that line starts a
record (``WORD/`` or a bare record word); major and minor words are case-insensitive; blanks
around ``/`` and ``,`` are dropped; trailing empty arguments (``GOTO/1,2,3,``) are dropped.
``WORD/args`` gives the comma-separated arguments; a record without ``/`` is its first word
(upper case) with the rest of the text, if any, as one argument (``PARTNO TEXT``).
"""

import re
from typing import NamedTuple

from ...errors import InputError

_LINE_END = re.compile(r"\r\n|\r|\n")
_RECORD_START = re.compile(r"\s*[A-Za-z][A-Za-z0-9_ -]*\s*/")
#: Records written without a slash that may follow a comment continued with '$'.
BARE_WORDS = frozenset({"RAPID", "MULTAX", "END", "FINI", "END-OF-PATH", "STOP", "OPSTOP", "GOHOME", "NURBS"})


class Record(NamedTuple):
    """One record: the 1-based line it starts on, its major word (upper case), its argument texts,
    and the text after its '/' (empty for a record without one)."""

    line: int
    word: str
    args: tuple
    rest: str


def split_lines(text):
    """The lines of `text` (any line ends); a final line end does not start another line."""
    lines = _LINE_END.split(text)
    if len(lines) > 1 and not lines[-1]:
        lines.pop()
    return lines


def lex(text, name):
    """(records, comments, number of lines) of CL `text` from file `name`.

    records: list of :class:`Record` in file order. comments: list of (line, comment text
    without the ``$$``, stripped), continued comments joined with a blank.
    """
    lines = split_lines(text)
    records, comments = [], []
    pieces, start = [], 0
    comment_open = False
    for number, raw in enumerate(lines, start=1):
        code, mark, comment = raw.partition("$$") if "$" in raw else (raw, "", "")
        code = code.strip()
        if not code and not mark:
            continue
        if comment_open and code and not _starts_record(code):
            line, previous = comments[-1]
            whole = raw.strip()
            comments[-1] = (line, f"{previous[:-1].rstrip()} {whole.rstrip('$').strip()}")
            comment_open = whole.endswith("$")
            continue
        comment_open = False
        if mark:
            comment = comment.strip()
            comments.append((number, comment))
            comment_open = not code and not pieces and comment.endswith("$")
        if not code:
            continue
        if not pieces:
            start = number
        if code.endswith("$"):
            pieces.append(code[:-1].strip())
            continue
        if pieces:
            pieces.append(code)
            code = "".join(pieces)
            pieces = []
        records.append(_record(start, code, name))
    if pieces:
        raise InputError(f"{name}:{start}: the record ends with the continuation mark '$' "
                         "but the file ends before it is continued")
    return records, comments, len(lines)


def _starts_record(code):
    """Whether the text `code` reads as the start of a record."""
    return bool(_RECORD_START.match(code)) or code.split(None, 1)[0].upper() in BARE_WORDS


def _record(line, statement, name):
    """The Record of one joined statement that starts on `line`."""
    head, slash, rest = statement.partition("/")
    if slash:
        word = " ".join(head.split()).upper()
        args = [arg.strip() for arg in rest.split(",")]
        while args and not args[-1]:
            args.pop()
        if not word:
            raise InputError(f"{name}:{line}: record {statement!r} has no major word before '/'")
        return Record(line, word, tuple(args), rest)
    word, *more = statement.split(None, 1)
    return Record(line, word.upper(), tuple(more), "")
