"""The engine computes quietly: no floating-point RuntimeWarnings on ordinary input."""

import warnings

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, engage


def engage_strictly(cl, theta_b):
    """engage() with warnings turned into errors: one section x, y in [0, 4] × [0, 10], top 2 mm,
    a 4 mm tool with 5 mm flutes at CL point cl (3,) mm, θ_A = 0, θ_B (deg), φ = 90°."""
    stock = Staircase(0.0, 4.0, 0.0, 10.0, 0.0, np.array([2.0]), np.zeros((0, 6, 2)))
    path = Toolpath(np.array([cl], dtype=float), np.array([0.0]), np.array([theta_b]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return engage(stock, Tool(4.0, 2, 5.0), path, CutSettings(0.1, phi_start=90.0, phi_end=90.0))


def test_quiet_when_edge_crosses_stock():
    """An edge inside the limits, θ_B = 0: no warning."""
    assert engage_strictly([1.0, 5.0, 0.5], 0.0).length[0, 0] == pytest.approx(1.5)


@pytest.mark.parametrize("cl", [[1.0, -5.0, 0.5], [-5.0, 5.0, 0.5]], ids=["beside_y_min", "beside_x_min"])
def test_quiet_when_edge_misses_stock(cl):
    """An edge beside the stock, θ_B = 0: no engagement and no warning (the clipped interval
    is empty there; 0·inf once made NaNs with 'invalid value encountered in multiply')."""
    assert engage_strictly(cl, 0.0).length[0, 0] == 0.0
