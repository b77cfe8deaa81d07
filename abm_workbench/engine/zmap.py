"""Z-map baseline: the discrete cutter-workpiece engagement the paper compares ABM with.

The stock is a height grid (Z-map): cell (i, j) of size c_x × c_y (at most `grid` mm each:
the x and y ranges are cut into ceil(span / grid) equal cells) holds one height, initially
the staircase's height at the cell centre (z_top of the section holding it); the base is
base_z everywhere. Along the pass, CL point by CL point:

1. **engagement**: the cutting edge of every φ is sampled at l_k = k·s, k = 0..N
   (s = L / ceil(L / edge_step) ≤ edge_step, so l_N = L). A sample is inside when it lies in
   the grid's x/y range, z ≥ base_z and z ≤ the height of its cell. Inside samples form runs;
   a run of samples k_a..k_b stands for the interval [l_a − s/2, l_b + s/2] clipped to
   [0, L], so the length of cut is the count of inside samples times s with the samples at
   l = 0 and l = L weighted s/2 (each end of a run is then within s/2 of the sampled truth).
   LEP / UEP are the l of the first / last inside sample, pieces the number of runs.
2. **removal**: every cell whose centre column meets the tool (a solid cylinder of radius R,
   axis w, bottom centre T, length L) is lowered to the tool's lower envelope there, the
   lowest point of the cylinder on the vertical line through the cell centre, in closed form
   (:func:`tool_floor`), for all the cells of the tool's footprint at once.

See docs/ZMAP.md for the cost model and the error sources. Lengths in mm, φ in degrees.
"""

import math

import numpy as np

from .engagement import SURFACES, edge_lines, empty_results, finished_engagement
from .arguments import check_arguments
from .model import CutSettings, Staircase, Tool, Toolpath

_NONE, _TOP, _STRAIGHT, _CURVED, _FLUTE_END, _SIDE = (SURFACES.index(name) for name in (
    "none", "top", "straight_wall", "curved_wall", "flute_end", "stock_side"))
#: Largest grid (cells) and largest sample count per CL point accepted.
MAX_CELLS = 50_000_000
MAX_SAMPLES = 20_000_000


class ZMap:
    """Height grid of a staircase: cells of cell_x × cell_y mm over [x_min, x_max] × [y_min, y_max].

    height (nx, ny): current top of each cell column (mm); section (nx, ny): the staircase
    section holding the cell centre (fixed). x, y: (nx,), (ny,) cell centres.
    """

    def __init__(self, stock: Staircase, grid=0.2):
        grid = _positive("grid", grid)
        self.stock = stock
        self.nx = max(1, math.ceil((stock.x_max - stock.x_min) / grid - 1e-9))
        self.ny = max(1, math.ceil((stock.y_max - stock.y_min) / grid - 1e-9))
        if self.nx * self.ny > MAX_CELLS:
            raise ValueError(f"grid {grid:g} mm gives {self.nx} x {self.ny} cells, more than {MAX_CELLS}")
        self.cell_x = (stock.x_max - stock.x_min) / self.nx
        self.cell_y = (stock.y_max - stock.y_min) / self.ny
        self.x = stock.x_min + (np.arange(self.nx) + 0.5) * self.cell_x
        self.y = stock.y_min + (np.arange(self.ny) + 0.5) * self.cell_y
        self.section = _cell_sections(stock, self.x, self.y)
        self.height = stock.z_top[self.section].astype(float)
        self.top = float(stock.z_top.max())

    def cells(self, x, y):
        """Flat cell index of points (x, y) (any shape) and whether they lie in the grid's range."""
        s = self.stock
        inside = (x >= s.x_min) & (x <= s.x_max) & (y >= s.y_min) & (y <= s.y_max)
        with np.errstate(invalid="ignore"):
            i = np.clip(np.floor((x - s.x_min) / self.cell_x), 0, self.nx - 1).astype(np.intp)
            j = np.clip(np.floor((y - s.y_min) / self.cell_y), 0, self.ny - 1).astype(np.intp)
        return i * self.ny + j, inside

    def footprint(self, base, axis, radius, length):
        """Index ranges (i0, i1, j0, j1) (half-open) of the cells whose centres lie in the bounding box
        of the tool's projection, the tool cut at the axial height above which it cannot reach
        below the highest cell; None when that box is empty or the tool is above every cell."""
        w_z = axis[2]
        lowest_rim = base[2] - radius * math.sqrt(max(0.0, 1.0 - w_z * w_z))
        reach = min(length, (self.top - lowest_rim) / w_z)
        if reach < 0.0:
            return None
        ends = np.stack([base, base + reach * axis])
        ex = radius * math.sqrt(max(0.0, 1.0 - axis[0] ** 2))
        ey = radius * math.sqrt(max(0.0, 1.0 - axis[1] ** 2))
        s = self.stock
        i0 = max(0, math.ceil((ends[:, 0].min() - ex - s.x_min) / self.cell_x - 0.5))
        i1 = min(self.nx, math.floor((ends[:, 0].max() + ex - s.x_min) / self.cell_x - 0.5) + 1)
        j0 = max(0, math.ceil((ends[:, 1].min() - ey - s.y_min) / self.cell_y - 0.5))
        j1 = min(self.ny, math.floor((ends[:, 1].max() + ey - s.y_min) / self.cell_y - 0.5) + 1)
        return None if i0 >= i1 or j0 >= j1 else (i0, i1, j0, j1)

    def remove(self, base, axis, radius, length):
        """Lower every cell under the tool to the tool's lower envelope there; returns the cells changed."""
        box = self.footprint(base, axis, radius, length)
        if box is None:
            return 0
        i0, i1, j0, j1 = box
        floor = tool_floor(self.x[i0:i1, None], self.y[None, j0:j1], base, axis, radius, length)
        view = self.height[i0:i1, j0:j1]
        lower = floor < view
        view[lower] = floor[lower]
        return int(lower.sum())


def _cell_sections(stock, x, y):
    """(nx, ny) section holding each cell centre (x_i, y_j), as Staircase.section_at gives it.

    section_at counts the walls with W_k(y) ≤ x, which never decreases along x; so per row
    and per k = 1..n−1 the first cell with section ≥ k is found by bisection over the row, all
    rows and k at once (about log2(nx) calls of section_at on ny·(n−1) points instead of one
    on nx·ny), and the sections follow by a cumulative sum.
    """
    nx, ny, walls = x.size, y.size, stock.n_sections - 1
    if walls == 0:
        return np.zeros((nx, ny), dtype=np.intp)
    k = np.arange(1, walls + 1)[None, :]
    low, high = np.zeros((ny, walls), dtype=np.intp), np.full((ny, walls), nx, dtype=np.intp)
    rows = np.broadcast_to(y[:, None], low.shape)
    while (low < high).any():
        middle = (low + high) // 2
        probe = np.minimum(middle, nx - 1)
        reached = (stock.section_at(x[probe], rows) >= k) & (low < high)
        high = np.where(reached, middle, high)
        low = np.where(~reached & (low < high), middle + 1, low)
    steps = np.zeros((nx + 1, ny), dtype=np.intp)
    np.add.at(steps, (low, np.broadcast_to(np.arange(ny)[:, None], low.shape)), 1)
    return np.cumsum(steps[:nx], axis=0)


def tool_floor(x, y, base, axis, radius, length):
    """Lowest z of the solid cylinder (bottom centre `base`, unit `axis` with axis_z > 0, `radius`,
    `length`) on the vertical lines through (x, y) (broadcast); +inf where a line misses it.

    The line p(s) = (x, y, base_z + s) meets the cylinder in the intersection of two intervals
    of s: the slab 0 ≤ (p − base)·w ≤ L, linear in s, and the infinite cylinder
    |(p − base) − ((p − base)·w) w|² ≤ R², the quadratic (1 − w_z²) s² − 2 w_z (r·w) s
    + |r|² − (r·w)² − R² ≤ 0 with r = (x − base_x, y − base_y, 0). Both are convex, so the
    lowest point is the larger of the two entries when it does not pass the smaller exit.
    The entry through the slab is the bottom disc, through the cylinder the side; the top disc
    only ever is an exit (w_z > 0). Roots by the cancellation-free form q = −(B + sign(B)√D)/2.
    """
    base = np.asarray(base, dtype=float)
    w = np.asarray(axis, dtype=float)
    rx, ry = np.asarray(x, dtype=float) - base[0], np.asarray(y, dtype=float) - base[1]
    rw = rx * w[0] + ry * w[1]
    slab_in, slab_out = -rw / w[2], (length - rw) / w[2]
    a = 1.0 - w[2] * w[2]
    c = rx * rx + ry * ry - rw * rw - radius * radius
    if a <= 0.0:  # upright: the side is vertical, inside everywhere or nowhere
        side_in = np.where(c <= 0.0, -np.inf, np.inf)
        side_out = np.where(c <= 0.0, np.inf, -np.inf)
    else:
        b = -2.0 * w[2] * rw
        disc = b * b - 4.0 * a * c
        hit = disc >= 0.0
        root = np.sqrt(np.where(hit, disc, 0.0))
        q = -0.5 * (b + np.where(b >= 0.0, root, -root))
        with np.errstate(divide="ignore", invalid="ignore"):
            r1 = q / a
            r2 = np.where(q != 0.0, c / q, r1)
        side_in = np.where(hit, np.minimum(r1, r2), np.inf)
        side_out = np.where(hit, np.maximum(r1, r2), -np.inf)
    enter = np.maximum(slab_in, side_in)
    leave = np.minimum(slab_out, side_out)
    return np.where(enter <= leave, base[2] + enter, np.inf)


def zmap_engage(stock: Staircase, tool: Tool, toolpath: Toolpath, settings: CutSettings, *, grid=0.2,
                edge_step=None, progress=None, remove=True):
    """Cut geometry of every CL point × rotation angle of `settings.phi` by Z-map simulation.

    grid: cell size (mm, the cells are at most this wide); edge_step: sampling step along the
    edge (mm, default `grid`); progress(done, total) after each CL point; remove: update the
    Z-map by each CL point's removal after its engagement (False: every CL point sees the
    initial stock, as `engage` does). Returns an :class:`Engagement` with the fields `engage`
    gives; `case` is always 'none' (no Table 1 from a grid), the UEP surface is classified from
    the grid (docs/ZMAP.md). A helical tool is refused (ValueError).
    """
    check_arguments(stock=stock, tool=tool, toolpath=toolpath, settings=settings)
    if tool.helix != 0.0:
        raise ValueError(f"the Z-map samples a straight edge; the tool has a helix angle of {tool.helix:g} deg")
    if tool.corner_radius != 0.0:
        raise ValueError(f"the Z-map samples a flat-end mill's edge; the tool has a corner radius of "
                         f"{tool.corner_radius:g} mm")
    zmap = ZMap(stock, grid)
    step = grid if edge_step is None else edge_step
    step = _positive("edge_step", step)
    length = tool.flute_length
    n = max(1, math.ceil(length / step - 1e-9))
    step = length / n
    phi = settings.phi
    m, p = len(toolpath), phi.size
    if p * (n + 1) > MAX_SAMPLES:
        raise ValueError(f"edge_step {step:g} mm gives {p * (n + 1)} samples per CL point, more than {MAX_SAMPLES}")
    l = step * np.arange(n + 1)
    weight = np.full(n + 1, step)
    weight[[0, -1]] *= 0.5
    if n == 0:
        weight[:] = 0.0
    walls = stock.walls
    straight = np.array([True] + [w.is_straight for w in walls] + [True])
    base_points, directions = edge_lines(toolpath, tool, phi)
    out, lep_xyz, uep_xyz = empty_results(m, p)
    rows = np.arange(p)
    height, section = zmap.height.reshape(-1), zmap.section.reshape(-1)  # views: removal shows through
    for i in range(m):
        w = directions[i]
        points = base_points[i][:, None, :] + l[None, :, None] * w  # (p, n + 1, 3)
        x, y, z = points[..., 0], points[..., 1], points[..., 2]
        cell, in_range = zmap.cells(x, y)
        inside = in_range & (z >= stock.base_z) & (z <= height[cell])
        before = np.concatenate([np.zeros((p, 1), dtype=bool), inside[:, :-1]], axis=1)
        engaged = inside.any(axis=1)
        first = np.argmax(inside, axis=1)
        last = n - np.argmax(inside[:, ::-1], axis=1)
        out["pieces"][i] = (inside & ~before).sum(axis=1)
        out["length"][i] = inside @ weight
        out["lep_l"][i] = np.where(engaged, l[first], np.nan)
        out["uep_l"][i] = np.where(engaged, l[last], np.nan)
        lep_xyz[i] = np.where(engaged[:, None], points[rows, first], np.nan)
        uep_xyz[i] = np.where(engaged[:, None], points[rows, last], np.nan)

        # UEP surface: how the edge leaves the stock between the UEP sample and the next one.
        here = cell[rows, last]
        following = np.minimum(last + 1, n)
        nxt = cell[rows, following]
        x_out = (x[rows, following] < stock.x_min) | (x[rows, following] > stock.x_max)
        y_out = ~in_range[rows, following] & ~x_out
        sec_here, sec_next = section[here], section[nxt]
        through_side = (z[rows, following] <= height[here]) & (sec_next != sec_here)
        wall = np.where(sec_next > sec_here, sec_here + 1, sec_here)
        surface = np.select(
            [last == n, x_out, y_out, through_side],
            [_FLUTE_END, _STRAIGHT, _SIDE, np.where(straight[wall], _STRAIGHT, _CURVED)],
            default=_TOP)
        x_wall = np.where(x[rows, following] > stock.x_max, stock.n_sections, 0)
        wall_index = np.select([last == n, x_out, y_out, through_side], [-1, x_wall, -1, wall], default=-1)
        out["uep_surface"][i] = np.where(engaged, surface, _NONE)
        out["uep_wall"][i] = np.where(engaged, wall_index, -1)
        out["uep_section"][i] = np.where(engaged, sec_here, -1)

        if remove:
            zmap.remove(toolpath.cl[i], w, tool.radius, length)
        if progress is not None:
            progress(i + 1, m)
    return finished_engagement(phi, settings, out, lep_xyz, uep_xyz, toolpath.inclinations(settings))


def _positive(name, value):
    """A finite positive float, or ValueError naming `name`."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a number, got {value!r}") from None
    if isinstance(value, bool) or not math.isfinite(number) or number <= 0.0:
        raise ValueError(f"{name} must be a positive number of mm, got {value!r}")
    return number
