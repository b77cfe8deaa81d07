"""The in-process search's touch rule (engine/inprocess_touch.py): hulls that reach into a line's
envelope along their axis by less than TOUCH (mm, measured along the line) are dropped unsolved,
no others; the engine against the full computation where it counts."""

import numpy as np
import pytest

from abm_workbench.engine import inprocess_touch
from abm_workbench.engine.inprocess_touch import _CLEAR, TOUCH, touching

from .test_inprocess import STOCK, Program, straight
from .test_inprocess_reach import against_full

#: The grown hull's floor and ceiling as the sure-miss test hands them over (its clearance included).
FLOOR, CEILING = np.array([-_CLEAR]), np.array([10.0 + _CLEAR])


def _segment(top, cosine=1.0):
    """A segment from 1 mm below the hull's bottom up to `top` (mm along the axis z), at `cosine` to the axis."""
    lean = np.sqrt(1.0 - cosine * cosine) / cosine
    a, b = np.array([[0.0, 0.0, -1.0]]), np.array([[lean * (top + 1.0), 0.0, top]])
    return a, b, a[:, 2], b[:, 2]


def test_a_reach_below_touch_is_dropped_a_longer_one_kept():
    for reach, dropped in ((-1.0, True), (0.0, True), (0.5 * TOUCH, True), (2.0 * TOUCH, False), (1e-9, False),
                           (0.5, False)):
        assert touching(*_segment(reach), FLOOR, CEILING)[0] == dropped, reach


def test_a_slanted_segment_gets_no_more_than_the_old_clearance_allows():
    """At cos 0.5 the allowance, (TOUCH + clearance)·c, is less than the clearance: such a segment is
    dropped only when it stays below the hull's bottom, by a little less than before."""
    threshold = -_CLEAR + 0.5 * (TOUCH + _CLEAR)
    assert touching(*_segment(threshold - 1e-12, 0.5), FLOOR, CEILING)[0]
    assert not touching(*_segment(threshold + 1e-12, 0.5), FLOOR, CEILING)[0]


def test_above_the_ceiling_alike():
    a = np.array([[0.0, 0.0, 10.0 - 0.5 * TOUCH], [0.0, 0.0, 10.0 - 2.0 * TOUCH], [0.0, 0.0, 11.0]])
    b = np.array([[0.0, 0.0, 12.0]] * 3)
    found = touching(a, b, a[:, 2], b[:, 2], np.repeat(FLOOR, 3), np.repeat(CEILING, 3))
    assert found.tolist() == [True, False, True]


def _skimmed():
    """A curved pass skimming 0.05 mm off the first section's top (chords: not a rigid chain),
    then a straight pass 3 mm below the top under it."""
    program = Program()
    top = STOCK["z_top"][0]
    angle = np.radians(np.linspace(-60, 60, 41))
    arc = np.stack([10 + 4 * np.sin(angle), 30 * (1 - np.cos(angle)) - 3, np.full(angle.size, top - 0.05)], axis=1)
    program.add_pass(arc, 6.0, 12.0)
    rows = program.add_pass(straight(2, 18, 0.0, top - 3.0, 17), 3.0, 12.0)
    return program, rows[1:16:2]


def test_skimmed_top_against_full():
    assert against_full(*_skimmed()).all()


def test_a_touch_as_large_as_the_skim_fails(monkeypatch):
    """TOUCH made 0.1 mm drops the 0.05 mm skim: the comparison with the full computation fails,
    so the engine reads the module's TOUCH and the comparison sees it (in the general search: the passes
    here are z levels, which the level view would take without it)."""
    monkeypatch.setattr(inprocess_touch, "TOUCH", 0.1)
    with pytest.raises(AssertionError):
        against_full(*_skimmed(), levels=(False,))
