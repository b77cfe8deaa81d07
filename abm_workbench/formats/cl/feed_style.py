"""How a CL file writes its FEDRAT records, learnt from the file, and feeds written the same way.

Every CAM system writes FEDRAT its own way, and a post-processor may read only its own:

=====================  ==================================================================
PTC Creo               ``FEDRAT / 400.000000, MMPM``: blanks around '/' and after ',', 6 decimals
SOLIDWORKS CAM         ``FEDRAT/889.,MMPM``, ``FEDRAT/801.963285,MMPM``: value first (its post
                       reads the first field as the feed), trailing zeros dropped
CATIA V5               ``fedrat/ 600.0000, mmpm``: lower case, 4 decimals
Siemens NX CLSF        ``FEDRAT/MMPM,400.0000``: unit first, 4 decimals
Mastercam              ``FEDRAT/MMPM,900.,``: unit first, trailing '.', a trailing comma
PowerMill              ``FEDRAT/1200.0,MMPM``: value first, 1 decimal
=====================  ==================================================================

A :class:`FeedStyle` is what one FEDRAT record shows (:func:`style_of`): its major word and the
blanks before '/' as written, the blanks after '/' and around ',', a trailing comma, the order
(unit word first, value first, or no unit word), the case of the unit word, and how its number is
written. What the record alone cannot show comes from the file's numbers (:class:`FileNumbers`):
a value written with trailing zeros (``400.0000``) gives fixed decimals; one without (``889.``,
``801.963285``, ``500``) is compact, unless another FEDRAT of the file has trailing zeros or
the file writes other numbers with as many decimals ending in 0 (NX's ``873.2213`` beside
``GOTO/0.0000,...``), either of which makes it fixed. Compact numbers drop trailing zeros and
have at most max(6, the most decimals of the file's FEDRAT values) decimals; an integer keeps
its '.' when the record writes one (``889.``). A value under 1 is written without its 0 (``.5``)
when the file's first such number is. A file without FEDRAT gets :func:`default_style`.

Feeds are written rounded down (:func:`rounded_down`), so a scheduled feed limit is never
exceeded by the text that reads back.
"""

import re
from decimal import ROUND_CEILING, ROUND_FLOOR, Context, Decimal
from typing import NamedTuple

from .. import NUMBER
from .units import FEED_UNITS

_NUMBER = re.compile(NUMBER)
_PLAIN = re.compile(r"[+-]?(?P<whole>[0-9]*)\.?(?P<fraction>[0-9]*)")
_SEPARATOR = re.compile(r"(\s*,\s*)")
#: Decimals of compact numbers when the file shows no more, and of a file without FEDRAT.
DECIMALS = 6
#: A feed short of a decimal step by at most this fraction of itself is that step (floating error).
_FLOATING = Decimal("1e-12")


class FeedStyle(NamedTuple):
    """How one FEDRAT record is written.

    head: the text before '/' as written (major word, its case, the blanks before '/').
    after_slash, comma, trailing: the blanks after '/', the separator between fields, what
    follows the last field ("" or a trailing comma). order: "unit-first", "value-first" or
    "bare" (no unit word). lower: unit words in lower case. point: an integer is written with
    a '.' (``889.``). fixed: decimals kept with their trailing zeros (``400.0000``), else dropped.
    decimals: the decimals written (at most, when not fixed). lead_dot: a value under 1 is
    written without its 0 (``.5``).
    """

    head: str
    after_slash: str
    comma: str
    trailing: str
    order: str
    lower: bool
    point: bool
    fixed: bool
    decimals: int
    lead_dot: bool


class FileNumbers(NamedTuple):
    """What a file's numbers tell of how it writes a FEDRAT value.

    fixed: decimals of its first FEDRAT value written with trailing zeros, or None.
    longest: the most decimals of any FEDRAT value. zero_ended: the decimal counts of the
    file's numbers (any record) that end in 0. lead_dot: whether its first number under 1
    with decimals is written without its 0 (FEDRAT values first, then every number); None
    when it has none.
    """

    fixed: int | None
    longest: int
    zero_ended: frozenset
    lead_dot: bool | None

    @classmethod
    def of(cls, records):
        """The FileNumbers of the lexed `records` (see :mod:`.lexer`)."""
        values = [value for value in map(value_text, records) if value is not None]
        numbers = [arg for record in records for arg in record.args if _NUMBER.fullmatch(arg)]
        fixed = next((len(_fraction(v)) for v in values if _fraction(v).endswith("0")), None)
        longest = max((len(_fraction(v)) for v in values), default=0)
        zero_ended = frozenset(len(_fraction(n)) for n in numbers if _fraction(n).endswith("0"))
        lead_dot = next((dot for dot in map(_lead_dot, values + numbers) if dot is not None), None)
        return cls(fixed, longest, zero_ended, lead_dot)


def value_text(record):
    """The text of a FEDRAT `record`'s feed value (its first number), or None (not a FEDRAT, or no number)."""
    if record.word != "FEDRAT":
        return None
    return next((arg for arg in record.args if _NUMBER.fullmatch(arg)), None)


def unit_word(record):
    """The feed unit word of a FEDRAT `record` as written (``MMPM``, ``mmpm``, ...), or None."""
    return next((arg for arg in record.args if arg.upper() in FEED_UNITS), None)


def _fraction(text):
    """The digits after the point of a plain number text ("" without, and for an exponent form)."""
    match = _PLAIN.fullmatch(text)
    return match["fraction"] if match else ""


def _lead_dot(text):
    """Whether the number `text`, under 1 with decimals, omits its 0 (``.5``); None for another number."""
    match = _PLAIN.fullmatch(text)
    if not match or not match["fraction"] or match["whole"].strip("0"):
        return None
    return not match["whole"]


def head_of(line):
    """The text before '/' of the record starting on the source `line` (its comment dropped), or None."""
    code = line.partition("$$")[0]
    return code.partition("/")[0] if "/" in code else None


def _fields(rest):
    """(blanks after '/', fields, separators, trailing text) of a record's text after '/'."""
    pieces = _SEPARATOR.split(rest)
    fields, separators = [piece.strip() for piece in pieces[0::2]], pieces[1::2]
    trailing = ""
    if len(fields) > 1 and not fields[-1]:
        fields.pop()
        trailing = separators.pop()
    return rest[:len(rest) - len(rest.lstrip())], fields, separators, trailing


def style_of(record, line, numbers):
    """The FeedStyle of FEDRAT `record` whose first source line is `line`, with the file's FileNumbers `numbers`."""
    head = head_of(line) or record.word
    after_slash, fields, separators, trailing = _fields(record.rest)
    unit, value = unit_word(record), value_text(record)
    if unit is None:
        order = "bare"
    else:
        order = "unit-first" if fields.index(unit) < fields.index(value) else "value-first"
    fixed, decimals = _decimals(value, numbers)
    lead_dot = _lead_dot(value)
    return FeedStyle(head=head, after_slash=after_slash, comma=separators[0] if separators else ",",
                     trailing=trailing, order=order, lower=(unit or head.strip()).islower(), point="." in value,
                     fixed=fixed, decimals=decimals, lead_dot=bool(numbers.lead_dot) if lead_dot is None else lead_dot)


def _decimals(value, numbers):
    """(fixed, decimals) of a FEDRAT's value text `value` in a file of FileNumbers `numbers` (module docstring)."""
    own = _fraction(value)
    if own.endswith("0"):
        return True, len(own)
    if numbers.fixed is not None:
        return True, numbers.fixed
    if own and len(own) in numbers.zero_ended:
        return True, len(own)
    return False, max(DECIMALS, numbers.longest)


def default_style(records, lines):
    """The FeedStyle of a file without FEDRAT: value first (``FEDRAT/f,MMPM``), 6 fixed decimals,
    in the case and blanks of its first record whose major word has six letters as FEDRAT has
    (CATIA pads its words to six: ``goto  /``, ``fedrat/``), else of its first record with '/';
    the separator of the first of those that has one (then of any record), else ','.

    records: the lexed records; lines: the file's source lines (1-based record lines index them).
    """
    written = [(record, head_of(lines[record.line - 1])) for record in records]
    written = [(record, head) for record, head in written if head is not None and head.strip()]
    written.sort(key=lambda pair: len(pair[1].strip()) != 6)   # six letters first, in file order
    record, head = written[0] if written else (None, "FEDRAT")
    lower = head.strip().islower()
    indent, blanks = head[:len(head) - len(head.lstrip())], head[len(head.rstrip()):]
    comma = next((separators[0] for _, _, separators, _ in (_fields(r.rest) for r, _ in written) if separators),
                 ",")
    return FeedStyle(head=indent + ("fedrat" if lower else "FEDRAT") + blanks,
                     after_slash=_fields(record.rest)[0] if record else "", comma=comma, trailing="",
                     order="value-first", lower=lower, point=True, fixed=True, decimals=DECIMALS, lead_dot=False)


def rounded_down(value, decimals):
    """`value` (> 0) rounded down to `decimals` places, a Decimal; a value short of a step by at
    most 1e-12 of itself (the floating error of the feed's computation) is that step."""
    exact = Decimal(repr(float(value)))
    step = Decimal(1).scaleb(-decimals)
    digits = Context(prec=max(exact.adjusted(), 0) + decimals + 2)   # every digit of the result
    up = exact.quantize(step, ROUND_CEILING, digits)
    return up if up - exact <= exact * _FLOATING else exact.quantize(step, ROUND_FLOOR, digits)


def number_text(value, style):
    """The text of `value` (a Decimal already at the style's decimals) as `style` writes a number."""
    text = f"{value:f}"
    if not style.fixed and "." in text:
        text = text.rstrip("0")
    text = text.rstrip(".")
    if style.point and "." not in text:
        text += "."
    if style.lead_dot and text.startswith("0."):
        text = text[1:]
    return text


def record_text(style, number, unit):
    """A FEDRAT record in `style` with the number text `number` and the feed unit word `unit`
    (upper case: "MMPM", "IPM", "MMPR", "IPR"), or without a unit word when `unit` is None."""
    if unit is None:
        fields = [number]
    else:
        word = unit.lower() if style.lower else unit
        fields = [word, number] if style.order == "unit-first" else [number, word]
    return f"{style.head}/{style.after_slash}{style.comma.join(fields)}{style.trailing}"
