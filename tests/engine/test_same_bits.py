"""Same input, same bits, wherever numpy's allocator puts a result (docs/ENGINE.md).

numpy 1.24 evaluates the functions in SPREAD (float64) by a vectorised or a scalar routine that
can differ in the last bit, and takes the scalar one when the output may overlap an input: for a
strided input it counts the span start + stride·n, which for a column other than the first of
an (n, 3) array runs past the array's end, where a fresh output can lie. `place_outputs` puts
every output of those functions either far from the inputs (the vectorised routine, as in most
processes) or just past a strided input's buffer (the scalar routine for a strided column, as in
an unlucky process), and the engine must give the same bits both ways. Only calls through the
names ``np.sin`` etc. are caught; ``x ** y`` (np.power) is not.
"""

import dataclasses

import numpy as np
import pytest

from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, axis_to_angles, engage
from abm_workbench.engine.inprocess import swept_pieces
from abm_workbench.engine.stocks import engage_in_process
from abm_workbench.forces import pass_forces

from .test_forces import K
from .test_inprocess import staircase
from .test_inprocess_single import TOOL, second_pass

# The float64 functions that gave other bits for a strided input with the output past its span.
SPREAD = ("sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "sinh", "cosh", "arcsinh", "arccosh",
          "arctanh", "exp", "exp2", "expm1", "log", "log2", "log10", "log1p", "cbrt", "power")
UFUNCS = {name: getattr(np, name) for name in SPREAD}
GAP = 8  # bytes: the least glibc's malloc leaves between one block's end and the next block's data


def _owner(a):
    """The array whose buffer `a` views."""
    while isinstance(a.base, np.ndarray):
        a = a.base
    return a


def _address(a):
    """Where `a`'s first element lies in memory."""
    return a.__array_interface__["data"][0]


def _same_bits(a, b):
    """Whether two arrays are equal bit for bit (NaNs included)."""
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def _beside(ufunc, args, index, like):
    """ufunc(*args) with args[index] copied, same strides, into a new buffer and the output (shaped
    like `like`) placed GAP bytes past that buffer's end."""
    owner = _owner(args[index])
    end = -(-owner.nbytes // GAP) * GAP + GAP
    memory = np.empty(end + like.nbytes, dtype=np.uint8)
    memory[:owner.nbytes] = owner.reshape(-1).view(np.uint8)
    moved = np.ndarray(args[index].shape, args[index].dtype, memory, _address(args[index]) - _address(owner),
                       args[index].strides)
    out = np.ndarray(like.shape, like.dtype, memory, end)
    return ufunc(*args[:index], moved, *args[index + 1:], out=out)


class _Placed:
    """A ufunc whose output lies far from its inputs (near=False: every input copied contiguous
    first, so numpy takes its vectorised routine) or, where it can by chance, just past a strided
    input's buffer (near=True: each strided input whose buffer is contiguous gets its turn; the
    first result whose bits differ from the far one is returned, else the far one)."""

    def __init__(self, ufunc, near):
        self.ufunc, self.near = ufunc, near

    def __getattr__(self, name):
        return getattr(self.ufunc, name)

    def __call__(self, *args, **keywords):
        if keywords:
            return self.ufunc(*args, **keywords)
        far = self.ufunc(*(np.ascontiguousarray(a) if isinstance(a, np.ndarray) else a for a in args))
        if self.near and isinstance(far, np.ndarray):
            for index, a in enumerate(args):
                if isinstance(a, np.ndarray) and not a.flags.c_contiguous and _owner(a).flags.c_contiguous:
                    moved = _beside(self.ufunc, args, index, far)
                    if not _same_bits(moved, far):
                        return moved
        return far


def place_outputs(monkeypatch, near):
    """From here on in the test, np.<f> for f in SPREAD place their outputs as _Placed does."""
    for name, ufunc in UFUNCS.items():
        monkeypatch.setattr(np, name, _Placed(ufunc, near))


@pytest.mark.skipif(not np.core._multiarray_umath.__cpu_features__.get("AVX512_SKX"),
                    reason="numpy 1.24 has a vectorised float64 arctan2 (SVML) only with AVX512_SKX")
def test_output_past_the_span_takes_the_other_routine(monkeypatch):
    """The placement can make a test fail: arctan2 of a strided column other than the first gives
    other bits (the first column's span ends at its array's end, before any fresh output)."""
    place_outputs(monkeypatch, near=True)
    rng = np.random.default_rng(5)
    a = rng.uniform(-1.0, 1.0, (10_000, 3))
    x, y, z = a.T.copy()
    assert _same_bits(np.arctan2(a[:, 0], y), np.arctan2(x, y))
    assert not _same_bits(np.arctan2(a[:, 1], x), np.arctan2(y, x))
    assert not _same_bits(np.arctan2(x, a[:, 2]), np.arctan2(x, z))


@pytest.fixture
def axes():
    """10 000 random tool axes (k > 0) as an (m, 3) view of every other column of an (m, 6) array."""
    rng = np.random.default_rng(11)
    wide = rng.uniform(-1.0, 1.0, (10_000, 6))
    wide[:, 4] = rng.uniform(0.05, 1.0, 10_000)
    return wide[:, ::2]


def test_axis_to_angles_same_bits_wherever_outputs_lie(axes, monkeypatch):
    """θ_A, θ_B of the same axes, contiguous or strided, with outputs past the spans or not."""
    place_outputs(monkeypatch, near=False)
    expected = axis_to_angles(np.ascontiguousarray(axes))
    assert all(_same_bits(a, b) for a, b in zip(axis_to_angles(axes), expected))
    place_outputs(monkeypatch, near=True)
    for given in (axes, np.ascontiguousarray(axes)):
        assert all(_same_bits(a, b) for a, b in zip(axis_to_angles(given), expected))


def _pass():
    """A small tilted pass over a stock with a straight and a curved wall."""
    y = np.linspace(-15.0, 15.0, 6)
    walls = np.array([np.column_stack([np.full(6, 40.0), y]), np.column_stack([80.0 + 3.0 * np.sin(y / 5.0), y])])
    stock = Staircase(0.0, 130.0, -15.0, 15.0, -20.0, [4.0, 6.5, 3.0], walls)
    x = np.linspace(10.0, 120.0, 8)
    axes = np.column_stack([np.sin(np.radians(5.0 + x / 10.0)), np.full(8, -0.1), np.ones(8)])
    toolpath = Toolpath.from_axes(np.column_stack([x, np.zeros(8), x / 60.0 - 1.0]), axes)
    return stock, toolpath, CutSettings(0.1, 10.0, 0.0, 180.0, 10.0, 4000.0)


def _fields(result):
    """The arrays of a result dataclass, by name."""
    return {f.name: getattr(result, f.name) for f in dataclasses.fields(result)
            if isinstance(getattr(result, f.name), np.ndarray)}


def _straight():
    """The pass's toolpath, forces and Engagement with straight flutes."""
    stock, toolpath, settings = _pass()
    return [toolpath, pass_forces(stock, Tool(12.0, 2, 30.0), toolpath, settings, K),
            engage(stock, Tool(12.0, 2, 30.0), toolpath, settings)]


def _helical():
    """The pass's forces with 30° helical flutes (helix solver)."""
    stock, toolpath, settings = _pass()
    return [pass_forces(stock, Tool(12.0, 2, 30.0, 30.0), toolpath, settings, K)]


def _in_process():
    """Swept pieces of a program and the in-process Engagement of its tilted second pass."""
    program, rows, toolpath = second_pass(tilted=True)
    pieces = swept_pieces(program.moves())
    engagement, _, _ = engage_in_process(staircase(), TOOL, toolpath, CutSettings(0.05, 0.0, 0.0, 180.0, 5.0),
                                         pieces, rows)
    return [pieces, engagement]


@pytest.mark.parametrize("run", [_straight, _helical, _in_process])
def test_engine_same_bits_wherever_outputs_lie(run, monkeypatch):
    """Engagement, forces, swept pieces: the same bits with every output next to a strided input."""
    place_outputs(monkeypatch, near=False)
    expected = [_fields(r) for r in run()]
    place_outputs(monkeypatch, near=True)
    for fields, want in zip([_fields(r) for r in run()], expected):
        assert [n for n in want if not _same_bits(fields[n], want[n])] == []
