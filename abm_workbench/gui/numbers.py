"""Numbers typed into the task panel's fields: read in the field's declared unit, and written in it.

A field declares its unit: "mm" (a length), "deg" (an angle) or None (a plain number: a count, rpm,
N/mm², N/mm). :func:`read` takes the text the user typed. A bare number is in the declared unit,
whatever unit was shown before; a length or an angle may carry a unit of its kind ("0.5 in",
"80 µm", "0.2 rad"), converted into the declared unit by FreeCAD's units. The decimal point is the
one of FreeCAD's locale (given, :func:`decimal_point`): the other separator ("," where it is ".")
is refused, never dropped as a group separator. Nothing is rounded, clamped or re-scaled: text that
is no number of the field's kind, a number too large for a float (1e400) and one too small to be
told from 0 (1e-400) are refused in words (:class:`Unreadable`). :func:`text` writes a value in the
declared unit ("0.08 mm", "10°"), so that reading it back gives the same float.

Needs FreeCAD (its units) but not its GUI.
"""

import math
import re

from ..cad.freecad_env import FreeCAD
from .i18n import noop, translate

#: A number as typed: sign, digits with one decimal point "." (the locale's, put in its place), exponent;
#: then its unit, if any: letters (mm, in, µm, rad) or a sign (°, ′, ″, ", ').
_NUMBER = re.compile(r"([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)\s*([^\W\d_]+|[°′″\"'])?", re.UNICODE)
#: Each declared unit: FreeCAD's unit of its kind (None: a plain number), the message for text of another kind,
#: what to type.
KINDS = {
    "mm": ("Length", noop("“{typed}” is not a length: {hint}"),
           noop("type a number, with a unit if you like (12 mm, 0.5 in)")),
    "deg": ("Angle", noop("“{typed}” is not an angle: {hint}"),
            noop("type a number, with a unit if you like (10°, 0.2 rad)")),
    None: (None, noop("“{typed}” is not a number: {hint}"), noop("type a number without a unit (4, 2.5)")),
}
#: How declared units are written after a number.
_WRITTEN = {"mm": " mm", "deg": "°"}


class Unreadable(ValueError):
    """Typed text that is no number of its field's kind; the message says why, without the field's name
    ('“1x2” is not a length')."""


def decimal_point():
    """The decimal point of FreeCAD's locale (Qt's default locale): "." or ","."""
    from PySide import QtCore

    return QtCore.QLocale().decimalPoint()


def read(typed, unit, point="."):
    """The number `typed` (str) in the declared `unit` ("mm", "deg" or None for a plain number), as a
    float; None when it is empty (or only spaces). Unreadable when it is no number of that kind.

    point: the locale's decimal point ("." or ","); the other of the two is refused.
    """
    stripped = typed.strip()
    if not stripped:
        return None
    other = "," if point == "." else "."
    if other in stripped:
        raise Unreadable(translate("“{typed}” has a “{other}”: decimals take a “{point}” (12{point}5), "
                                   "thousands no separator (1000)", typed=stripped, other=other, point=point))
    match = _NUMBER.fullmatch(stripped.replace(point, "."))
    if match is None:
        raise _not_of_kind(stripped, unit)
    digits, written = match.groups()
    number = float(digits)
    if written is not None:
        number *= _factor(written, unit, stripped)
    if math.isinf(number):
        raise Unreadable(translate("“{typed}” is too large a number", typed=stripped))
    if number == 0 and re.search("[1-9]", digits.lower().split("e")[0]):
        raise Unreadable(translate("“{typed}” is too small a number: it would be taken as 0", typed=stripped))
    return number


def text(value, unit, point="."):
    """`value` (a finite float in the declared `unit`) as it is shown: "0.08 mm", "10°", "4"; read()
    gives `value` back."""
    digits = f"{value:.15g}"
    if float(digits) != value:
        digits = repr(float(value))  # the shortest text of exactly this float
    return digits.replace(".", point) + _WRITTEN.get(unit, "")


def hint(unit):
    """What to type into a field of the declared `unit`, in words: 'type a number, with a unit if …'."""
    return translate(KINDS[unit][2])


def _factor(written, unit, stripped):
    """The size of one `written` unit in the declared `unit`; Unreadable when it is not of that kind."""
    kind = KINDS[unit][0]
    try:
        quantity = FreeCAD.Units.Quantity(f"1 {written}") if kind is not None else None
    except ValueError:  # FreeCAD's word for text it cannot parse
        quantity = None
    if quantity is None or quantity.Unit != getattr(FreeCAD.Units, kind):
        raise _not_of_kind(stripped, unit)
    return quantity.getValueAs(unit).Value


def _not_of_kind(stripped, unit):
    """Unreadable: “1x2” is not a length: type a number, …"""
    return Unreadable(translate(KINDS[unit][1], typed=stripped, hint=hint(unit)))
