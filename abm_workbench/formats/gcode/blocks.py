"""G-code text as blocks: one line each, its words (a letter and a number), its comments.

RS-274 as LinuxCNC, FreeCAD's posts and Fanuc-style controls write it:

- a comment is ``( ... )`` (several on a line, anywhere in it) or ``;`` to the end of the line;
- blanks between and inside words are ignored (``G 1 X 10.5``, ``G1X10.5`` are the same block);
- a leading ``/`` (block delete, the switch off) is dropped, and so are block numbers ``N…``,
  ``%`` lines (with a program name after the ``%`` or not) and a Fanuc program number ``O…`` (a
  line with only it and comments);
- a word is a letter (any case) and a number (an optional sign, digits with an optional point);
- a whole block of certain control words switches the tool centre point control (TCP):
  ``TRAORI`` (Siemens), ``TRAFOOF``, ``TCPM`` / ``TCPM OFF``, ``FUNCTION TCPM …`` and
  ``FUNCTION RESET TCPM`` (Heidenhain).

Anything else is refused as :class:`~abm_workbench.errors.InputError` ``file:line: text: reason``:
parameters and expressions (``#1``, ``[…]``), LinuxCNC's O-word subroutines and loops, Siemens
``X=…`` assignments, an unclosed ``(``.
"""

import re
from typing import NamedTuple

from ...errors import InputError, note
from .. import MAX_MAGNITUDE
from ..cl.lexer import split_lines

_COMMENT = re.compile(r"\(([^)]*)\)")
_WORD = re.compile(r"([A-Z])([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))")
_BLOCK_NUMBER = re.compile(r"^N[0-9]+ ?")
#: Whole blocks that switch TCP: the text (upper case, blanks single) -> True (on) or False (off).
_TCP_BLOCKS = ((re.compile(r"TRAORI(\([0-9]*\))?"), True), (re.compile(r"TRAFOOF"), False),
               (re.compile(r"TCPM( ON)?"), True), (re.compile(r"TCPM OFF"), False),
               (re.compile(r"FUNCTION RESET TCPM.*"), False), (re.compile(r"FUNCTION TCPM.*"), True))


class Word(NamedTuple):
    """One word: its letter (upper case), its value and its text as written (``"G1"``, ``"X-2.5"``)."""

    letter: str
    value: float
    text: str


class Block(NamedTuple):
    """One block: its 1-based line, its words in order, its comments (text inside ``( )`` or after
    ``;``, stripped) and its TCP switch (True on, False off, None: the block has none)."""

    line: int
    words: tuple
    comments: tuple
    tcp: object = None


def blocks_of_text(text, name):
    """The :class:`Block` of every line of G-code `text` from file `name` that holds words, comments or a
    TCP switch, in order. InputError ``name:line: text: reason`` for text that is no G-code word."""
    found = []
    for number, raw in enumerate(split_lines(text), start=1):
        block = _block(raw, number, name)
        if block is not None:
            found.append(block)
    return found


def _block(raw, number, name):
    """The Block of line `raw` (line `number`), or None for a line with nothing in it."""
    code, _, tail = raw.partition(";")
    comments = [text.strip() for text in _COMMENT.findall(code)]
    code = _COMMENT.sub(" ", code)
    if "(" in code:
        raise InputError(f"{name}:{number}: {code[code.index('('):].strip()}: a comment '(' is not closed on its "
                         "line")
    if ")" in code:
        raise InputError(f"{name}:{number}: ): a ')' closes no comment")
    if tail.strip():
        comments.append(tail.strip())
    code = code.strip().lstrip("/").strip()
    if not code or code.startswith("%"):
        return Block(number, (), tuple(comments)) if comments else None
    spaced = _BLOCK_NUMBER.sub("", " ".join(code.upper().split()), count=1).strip()
    for pattern, state in _TCP_BLOCKS:
        if pattern.fullmatch(spaced):
            return Block(number, (), tuple(comments), state)
    return Block(number, _words(code, number, name), tuple(comments))


def _words(code, number, name):
    """The words of the code text of line `number` (comments removed)."""
    compact = "".join(code.upper().split())
    words, at = [], 0
    while at < len(compact):
        match = _WORD.match(compact, at)
        if match is None:
            raise InputError(f"{name}:{number}: {_piece(compact, at)}: {_reason(compact, at)}")
        letter, digits = match.groups()
        value = float(digits)
        if abs(value) > MAX_MAGNITUDE:
            raise InputError(f"{name}:{number}: {match.group()}: the number is above {MAX_MAGNITUDE:g} in magnitude")
        at = match.end()
        if letter == "N" and not words:
            continue  # a block number
        if letter == "O":
            if words or at < len(compact):
                raise InputError(f"{name}:{number}: {match.group()}: O-words (subroutines, loops, conditions) are "
                                 "not read; only a program number alone on its line")
            continue  # a Fanuc program number
        words.append(Word(letter, value, match.group()))
    return tuple(words)


def _piece(compact, at):
    """The text from `at` up to the next letter that could start a word: what the error names."""
    end = at + 1
    while end < len(compact) and not compact[end].isalpha():
        end += 1
    return compact[at:end]


def _reason(compact, at):
    """Why the text at `at` is no word."""
    char = compact[at]
    if char in "#[]":
        return note("parameters and expressions (#, [ ]) are not read")
    if char.isalpha():
        if at + 1 < len(compact) and compact[at + 1] == "=":
            return note("assignments (X=…) are not read: write a letter and a number")
        if at + 1 < len(compact) and compact[at + 1].isalpha():
            return note("not a G-code word (a letter and a number)")
        return note("a letter without a number")
    return note("not a G-code word (a letter and a number)")
