"""The comparison logic of abm_workbench.validation (pure numpy: a made-up reference, no boolean)."""

import numpy as np
import pytest

from abm_workbench.engine import SURFACES, CutSettings, Tool, Toolpath, engage
from abm_workbench.validation import TINY_LENGTH, compare, overall, segment_summary, surface_summary

from .conftest import STOCKS

TOOL = Tool(12.0, 2, 25.0)
SETTINGS = CutSettings(0.1, phi_start=0, phi_end=180, phi_step=10)
# Three CL points beside walls, and one above the stock (no engagement).
PATH = Toolpath([[21.3, 0.7, 0.9], [44.9, 1.3, 2.1], [73.0, -0.4, 4.3], [50.0, 0.0, 30.0]], [12.0, 0.0, -6.0, 0.0],
                [18.0, 25.0, -30.0, 0.0])


@pytest.fixture(scope="module")
def engagement():
    return engage(STOCKS["ridge"], TOOL, PATH, SETTINGS)


def reference_of(engagement, scale=1.0):
    """A reference equal to the engine's result, its lengths times `scale`."""
    return {"length": engagement.length * scale, "lep_l": engagement.lep_l.copy(),
            "uep_l": engagement.uep_l.copy(), "pieces": engagement.pieces.copy()}


def test_identical_reference_gives_zero_error(engagement):
    comparison = compare(engagement, reference_of(engagement), PATH, TOOL)
    assert not comparison.error.any() and not comparison.mismatched.any()
    np.testing.assert_allclose(comparison.depth_ref, comparison.depth_abm, atol=1e-12)
    total = overall(comparison)
    assert total["max_rel_error"] == 0.0 and total["instants"] == engagement.length.size
    assert total["relative_instants"] == int((engagement.length >= TINY_LENGTH).sum())


def test_relative_error_and_absolute_below_the_threshold(engagement):
    reference = reference_of(engagement, scale=1.0 / 1.02)  # ABM 2 % long everywhere
    cl, k = np.argwhere(engagement.length > 1.0)[0]
    reference["length"][cl, k] = 0.5 * TINY_LENGTH  # the reference barely touches there
    comparison = compare(engagement, reference, PATH, TOOL)
    engaged = (engagement.length > 0) & (reference["length"] >= TINY_LENGTH)
    np.testing.assert_allclose(comparison.error[engaged], 0.02, rtol=1e-12)
    assert not comparison.relative[cl, k]
    assert comparison.error[cl, k] == pytest.approx(engagement.length[cl, k] - 0.5 * TINY_LENGTH)
    assert np.isnan(comparison.relative_error[cl, k])
    assert overall(comparison)["max_rel_error"] == pytest.approx(0.02)


def test_segment_summary_by_hand(engagement):
    reference = reference_of(engagement)
    cl = 1
    segments = engagement.segments(cl)
    rows = np.flatnonzero(engagement.segment[cl] == 0)
    reference["length"][cl, rows[0]] *= 1 / 1.05  # 5 % at one instant of segment A
    reference["uep_l"][cl, rows[-1]] += 0.25
    summary = segment_summary(engagement, compare(engagement, reference, PATH, TOOL), [cl])
    assert [row["segment"] for row in summary] == [s["letter"] for s in segments]
    first = summary[0]
    assert (first["cl"], first["instants"], first["surface"]) == (cl, rows.size, segments[0]["surface"])
    assert first["max_rel_error"] == pytest.approx(0.05)
    assert first["mean_rel_error"] == pytest.approx(0.05 / first["relative_instants"])
    assert first["max_uep_difference"] == pytest.approx(0.25) and first["max_lep_difference"] == 0.0
    assert all(row["max_rel_error"] == 0.0 for row in summary[1:])


def test_surface_summary_lists_only_surfaces_that_occur(engagement):
    reference = reference_of(engagement)
    comparison = compare(engagement, reference, PATH, TOOL)
    names = [row["surface"] for row in surface_summary(engagement, comparison)]
    occurring = {SURFACES[s] for s in np.unique(engagement.uep_surface)} - {"none"}
    assert set(names) == occurring and names == sorted(names, key=SURFACES.index)
    # The reference engages where ABM does not: that shows as "none", mismatched.
    cl, k = np.argwhere(engagement.length == 0)[0]
    reference["length"][cl, k] = 0.5
    comparison = compare(engagement, reference, PATH, TOOL)
    none = surface_summary(engagement, comparison)[0]
    assert (none["surface"], none["instants"], none["mismatched"]) == ("none", 1, 1)
    assert none["max_rel_error"] == pytest.approx(1.0)  # l_ABM = 0: −100 %


def test_reference_of_the_wrong_shape(engagement):
    reference = reference_of(engagement)
    reference["length"] = reference["length"][:, :-1]
    with pytest.raises(ValueError, match=r"reference\['length'\] must have shape \(4, 19\)"):
        compare(engagement, reference, PATH, TOOL)
