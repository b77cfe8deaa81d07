"""CAD tier: FreeCAD headless (HOME is already an empty folder: tests/conftest.py), and the
stocks the tests share. FreeCAD is imported here, not skipped: without it the tier fails with
an ImportError naming the package to install.
"""

import numpy as np
import pytest

import abm_workbench.cad.freecad_env  # noqa: F401  (fails loudly without FreeCAD)
from abm_workbench.cad.solids import staircase_solid
from abm_workbench.engine import Staircase

Y_MIN, Y_MAX = -12.0, 12.0
CHEBYSHEV = 0.5 * (Y_MIN + Y_MAX) - 0.5 * (Y_MAX - Y_MIN) * np.cos((2 * np.arange(6) + 1) * np.pi / 12)


def wall(x_of_y, ys=CHEBYSHEV):
    """Six [x, y] points (6, 2) of the wall x = x_of_y(y) (mm)."""
    return [[float(x_of_y(y)), float(y)] for y in ys]


def curved_stock(z_top):
    """Four sections on x 0..100, y ±12, base −10 mm: curved, straight and curved walls."""
    walls = [
        wall(lambda y: 26.0 + 3.0 * np.sin(0.2 * y) + 0.02 * y * y),
        wall(lambda y: 50.0),
        wall(lambda y: 74.0 - 4.0 * np.cos(0.13 * y) + 0.1 * y),
    ]
    return Staircase(0.0, 100.0, Y_MIN, Y_MAX, -10.0, z_top, walls)


STOCKS = {
    "ascending": curved_stock([2.0, 5.0, 8.0, 11.0]),
    "descending": curved_stock([11.0, 8.0, 5.0, 2.0]),
    "ridge": curved_stock([3.0, 9.0, 6.0, 12.0]),
    "straight": Staircase(0.0, 100.0, Y_MIN, Y_MAX, -10.0, [2.0, 6.0, 4.0],
                          [wall(lambda y: 35.0), wall(lambda y: 65.0)]),
}


@pytest.fixture(scope="session")
def solids():
    """Solids of STOCKS, built once: {name: Part.Solid}."""
    return {name: staircase_solid(stock) for name, stock in STOCKS.items()}
