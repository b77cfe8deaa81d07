"""validate's choice of the CL points the boolean checks (jobs.checked): lists, ranges, every N-th,
the shown CL points always among them, and an error naming the option for each bad value."""

import pytest

from abm_workbench.errors import ParameterError
from abm_workbench.jobs.checked import checked_cls, parse_cl_list


def test_lists_and_ranges():
    assert parse_cl_list("0,27,80-82", 165, "check") == [0, 27, 80, 81, 82]
    assert parse_cl_list(" 5 , 3-3,1-2,2", 6, "check") == [1, 2, 3, 5]
    assert parse_cl_list("164", 165, "check") == [164]


def test_selection_is_the_union_with_the_shown_cl_points():
    assert checked_cls(None, None, [3], 10) is None  # neither option: every CL point
    assert checked_cls("1,4-5", None, [8], 10) == [1, 4, 5, 8]
    assert checked_cls(None, 4, None, 10) == [0, 4, 8]
    assert checked_cls("9", 5, [2], 10) == [0, 2, 5, 9]
    assert checked_cls(None, 20, None, 10) == [0]


@pytest.mark.parametrize("text, words", [
    ("", "is empty"), (",", "is empty"), ("1,,2", "item 2 '' is not a CL index"),
    ("a", "item 1 'a' is not a CL index"), ("1-2-3", "item 1 '1-2-3' is not a CL index"),
    ("1.5", "item 1 '1.5' is not"), ("7-3", "item 1 '7-3' runs backwards (write 3-7)"),
    ("10", "item 1: CL point 10 is not in the pass (0..9)"), ("2,8-12", "item 2: CL point 12 is not in the pass"),
])
def test_bad_lists_name_the_option_and_the_item(text, words):
    with pytest.raises(ParameterError) as error:
        checked_cls(text, None, None, 10)
    assert error.value.field == "check" and words in error.value.detail


@pytest.mark.parametrize("every", [0, -2, 1.5, True])
def test_bad_every(every):
    with pytest.raises(ParameterError) as error:
        checked_cls(None, every, None, 10)
    assert error.value.field == "check_every"
