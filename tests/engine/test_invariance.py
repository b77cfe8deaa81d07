"""Symmetries of the engine: translating a job, mirroring it in y and in x.

Engine against engine only. Lengths and points agree to TOL (mm); names and counts exactly.
"""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from abm_workbench.engine import CASES, engage

from .reference import StairData
from .strategies import Job, engine_inputs, jobs

TOL = 1e-6  # mm
# Mirroring x swaps the lean of the edge, so the Table 1 rows for +x and −x swap.
X_MIRROR_CASE = {"A.1": "A.2", "A.2": "A.1", "A.3": "A.4", "A.4": "A.3",
                 "B.1": "B.2", "B.2": "B.1", "B.3": "B.4", "B.4": "B.3"}


def run(job):
    """Engine Engagement of a strategies.Job."""
    return engage(*engine_inputs(job))


def assert_close(got, want):
    """Arrays (mm) equal to TOL, NaN where the other is NaN."""
    np.testing.assert_allclose(got, want, rtol=0, atol=TOL)


def flipped(engagement, name):
    """Field `name` of an Engagement with its φ axis reversed, shape (m, p, ...)."""
    return getattr(engagement, name)[:, ::-1]


def mirror_y(job: Job) -> Job:
    """The job mirrored in y → −y: θ_A → −θ_A, φ → 180° − φ (the φ range mirrored too)."""
    s = job.stock
    walls = tuple(tuple((x, -y) for x, y in wall) for wall in s.walls)
    stock = StairData(s.x_min, s.x_max, -s.y_max, -s.y_min, s.base_z, s.z_top, walls)
    return job._replace(stock=stock, cl=job.cl * [1, -1, 1], theta_a=-job.theta_a,
                        phi_start=180.0 - job.phi_end, phi_end=180.0 - job.phi_start)


def mirror_x(job: Job) -> Job:
    """The job mirrored in x → −x: sections reversed, θ_B → −θ_B, φ → −φ (range mirrored too).

    Wall j (between old sections j−1 and j) starts the new section n−j.
    """
    s = job.stock
    walls = tuple(tuple((-x, y) for x, y in wall) for wall in reversed(s.walls))
    stock = StairData(-s.x_max, -s.x_min, s.y_min, s.y_max, s.base_z, tuple(reversed(s.z_top)), walls)
    return job._replace(stock=stock, cl=job.cl * [-1, 1, 1], theta_b=-job.theta_b,
                        phi_start=-job.phi_end, phi_end=-job.phi_start)


@settings(max_examples=60)
@given(jobs(), st.tuples(*[st.floats(-500.0, 500.0)] * 3))
def test_translation(job, offset):
    """Moving stock and toolpath by the same vector moves the points and changes nothing else."""
    stock, tool, path, cut = engine_inputs(job)
    e = engage(stock, tool, path, cut)
    moved = engage(stock.translated(np.array(offset)), tool, path.translated(np.array(offset)), cut)
    for name in ("length", "lep_l", "uep_l"):
        assert_close(getattr(moved, name), getattr(e, name))
    assert_close(moved.lep_xyz, e.lep_xyz + offset)
    assert_close(moved.uep_xyz, e.uep_xyz + offset)
    for name in ("pieces", "uep_surface", "uep_section", "uep_wall", "case"):
        np.testing.assert_array_equal(getattr(moved, name), getattr(e, name))


@settings(max_examples=60)
@given(jobs())
def test_mirror_y(job):
    """Mirrored in y, instant φ maps to 180° − φ (reversed grid): same lengths, mirrored points."""
    e, m = run(job), run(mirror_y(job))
    np.testing.assert_allclose(m.phi[::-1], 180.0 - e.phi, atol=1e-9)
    for name in ("length", "lep_l", "uep_l"):
        assert_close(flipped(m, name), getattr(e, name))
    assert_close(flipped(m, "lep_xyz"), e.lep_xyz * [1, -1, 1])
    assert_close(flipped(m, "uep_xyz"), e.uep_xyz * [1, -1, 1])
    for name in ("pieces", "uep_surface", "uep_section", "uep_wall", "case"):
        np.testing.assert_array_equal(flipped(m, name), getattr(e, name))


@settings(max_examples=60)
@given(jobs())
def test_mirror_x(job):
    """Mirrored in x, instant φ maps to −φ (reversed grid): same lengths, mirrored points,
    sections j → n−1−j, walls j → n−j, the lean of the Table 1 case swapped."""
    e, m = run(job), run(mirror_x(job))
    n = len(job.stock.z_top)
    np.testing.assert_allclose(m.phi[::-1], -e.phi, atol=1e-9)
    for name in ("length", "lep_l", "uep_l"):
        assert_close(flipped(m, name), getattr(e, name))
    assert_close(flipped(m, "lep_xyz"), e.lep_xyz * [-1, 1, 1])
    assert_close(flipped(m, "uep_xyz"), e.uep_xyz * [-1, 1, 1])
    np.testing.assert_array_equal(flipped(m, "pieces"), e.pieces)
    np.testing.assert_array_equal(flipped(m, "uep_surface"), e.uep_surface)
    np.testing.assert_array_equal(flipped(m, "uep_section"), np.where(e.uep_section >= 0, n - 1 - e.uep_section, -1))
    np.testing.assert_array_equal(flipped(m, "uep_wall"), np.where(e.uep_wall >= 0, n - e.uep_wall, -1))
    cases = np.array([CASES.index(X_MIRROR_CASE.get(CASES[c], CASES[c])) for c in e.case.ravel()])
    np.testing.assert_array_equal(flipped(m, "case"), cases.reshape(e.case.shape))
