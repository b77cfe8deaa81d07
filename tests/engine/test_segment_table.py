"""Engagement.segment_table and segments against a plain loop over each CL point's angles."""

import numpy as np
import pytest

from abm_workbench.engine import SURFACES, Toolpath, engage, segment_letter

from .test_parallel import model_job


def _by_loop(engagement, cl):
    """Segments of CL point cl from first principles: runs of engaged angles with one UEP
    surface, section and wall, a new run after every gap."""
    rows, run = [], []
    keys = list(zip(engagement.uep_surface[cl], engagement.uep_section[cl], engagement.uep_wall[cl]))
    for k in range(engagement.shape[1]):
        engaged = engagement.length[cl, k] > 0.0
        if run and (not engaged or keys[k] != keys[run[-1]] or run[-1] != k - 1):
            rows.append(run)
            run = []
        if engaged:
            run.append(k)
    if run:
        rows.append(run)
    return [
        {"letter": segment_letter(i), "phi_start": engagement.phi[r[0]], "phi_end": engagement.phi[r[-1]],
         "surface": SURFACES[keys[r[0]][0]], "section": int(keys[r[0]][1]), "wall": int(keys[r[0]][2]),
         "mean_length": float(np.mean(engagement.length[cl, r])), "max_length": float(np.max(engagement.length[cl, r]))}
        for i, r in enumerate(rows)
    ]


def _check(engagement):
    table = engagement.segment_table()
    assert np.all(np.diff(table["cl"]) >= 0)
    for cl in range(engagement.shape[0]):
        want = _by_loop(engagement, cl)
        got = engagement.segments(cl)
        assert [{k: v for k, v in s.items() if k != "mean_length"} for s in got] == \
               [{k: v for k, v in s.items() if k != "mean_length"} for s in want]
        assert np.allclose([s["mean_length"] for s in got], [s["mean_length"] for s in want], rtol=1e-14, atol=0.0)
        assert np.count_nonzero(table["cl"] == cl) == len(want)


@pytest.mark.parametrize("number", [1, 2])
def test_segments_of_the_model_passes_and_perturbed_ones(number):
    stock, tool, toolpath, settings = model_job(number)
    _check(engage(stock, tool, toolpath, settings))
    rng = np.random.default_rng(number)
    cl = toolpath.cl + rng.normal(0.0, 1.5, toolpath.cl.shape)
    shaken = Toolpath(cl, toolpath.theta_a + rng.normal(0.0, 8.0, len(toolpath)),
                      toolpath.theta_b + rng.normal(0.0, 8.0, len(toolpath)))
    _check(engage(stock, tool, shaken, settings))


def test_a_pass_without_engagement_has_no_segments():
    stock, tool, toolpath, settings = model_job(1)
    far = Toolpath(toolpath.cl + [0.0, 0.0, 500.0], toolpath.theta_a, toolpath.theta_b)
    engagement = engage(stock, tool, far, settings)
    assert engagement.segment_table()["cl"].size == 0
    assert all(engagement.segments(cl) == [] for cl in range(len(far)))
