"""The task panel's reading and writing of typed numbers (abm_workbench.gui.numbers), without the GUI:
FreeCAD headless for its units. The panel itself, typed into with key events: test_panel_numbers.py.
"""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from abm_workbench.gui.numbers import Unreadable, read, text

UNITS = ("mm", "deg", None)


@pytest.mark.parametrize(("typed", "unit", "point", "number"), [
    ("0.1", "mm", ".", 0.1),  # a bare number in the declared unit, whatever was shown before
    (" 12 mm ", "mm", ".", 12.0),
    ("80 µm", "mm", ".", 0.08),
    ("0.5 in", "mm", ".", 12.7),
    ("1e-310", "mm", ".", 1e-310),  # tiny, but not 0
    ("10°", "deg", ".", 10.0),
    ("0.2 rad", "deg", ".", math.degrees(0.2)),
    ("4", None, ".", 4.0),
    ("12,5", "mm", ",", 12.5),
    ("-.5e3", None, ".", -500.0),
    ("", "mm", ".", None),  # empty: the caller decides
    ("  ", None, ".", None),
])
def test_a_number_is_read_in_the_declared_unit(typed, unit, point, number):
    assert read(typed, unit, point) == number


@pytest.mark.parametrize(("typed", "unit", "point", "words"), [
    ("1e400", "mm", ".", "“1e400” is too large a number"),
    ("1e308 km", "mm", ".", "“1e308 km” is too large a number"),
    ("1e-400", "mm", ".", "“1e-400” is too small a number: it would be taken as 0"),
    ("1e-320 nm", "mm", ".", "“1e-320 nm” is too small a number: it would be taken as 0"),
    ("12,5", "mm", ".", "“12,5” has a “,”: decimals take a “.” (12.5), thousands no separator (1000)"),
    ("1.000", None, ",", "“1.000” has a “.”: decimals take a “,” (12,5), thousands no separator (1000)"),
    ("1x2", "mm", ".", "“1x2” is not a length: type a number, with a unit if you like (12 mm, 0.5 in)"),
    ("12 mm", "deg", ".", "“12 mm” is not an angle: type a number, with a unit if you like (10°, 0.2 rad)"),
    ("4 mm", None, ".", "“4 mm” is not a number: type a number without a unit (4, 2.5)"),
    ("1 μm", "mm", ".", "“1 μm” is not a length: type a number, with a unit if you like (12 mm, 0.5 in)"),  # Greek mu
    ("1 e", "mm", ".", "“1 e” is not a length: type a number, with a unit if you like (12 mm, 0.5 in)"),
    ("inf", None, ".", "“inf” is not a number: type a number without a unit (4, 2.5)"),
    ("1_000", None, ".", "“1_000” is not a number: type a number without a unit (4, 2.5)"),
    ("٣", None, ".", "“٣” is not a number: type a number without a unit (4, 2.5)"),
])
def test_what_is_no_number_of_its_kind_is_refused_in_words(typed, unit, point, words):
    with pytest.raises(Unreadable) as error:
        read(typed, unit, point)
    assert str(error.value) == words


def test_values_are_shown_in_the_declared_unit():
    assert [text(0.08, "mm"), text(20000.0, "mm"), text(10.0, "deg"), text(4.0, None)] == [
        "0.08 mm", "20000 mm", "10°", "4"]
    assert [text(0.1 + 0.2, "mm"), text(1e300, "mm", ","), text(0.08, "mm", ",")] == [
        "0.30000000000000004 mm", "1e+300 mm", "0,08 mm"]


@settings(max_examples=300, deadline=None)
@given(st.floats(allow_nan=False, allow_infinity=False), st.sampled_from(UNITS), st.sampled_from(".,"))
def test_a_value_shown_reads_back_exactly(value, unit, point):
    assert read(text(value, unit, point), unit, point) == value
