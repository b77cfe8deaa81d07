"""Brute-force reference for the side edge of a flat-end mill on staircase stock.

Independent of the code under test: nothing here imports or mirrors ``abm_workbench``.
Inputs are plain data (a :class:`StairData`, floats in mm and degrees).

Method. The edge is S(φ, l) = T + R·(R_t sin φ, R_t cos φ, l) for 0 ≤ l ≤ L, with
R = Rx(θ_A)·Ry(θ_B). Every boundary of the stock gives a scalar function of l that
changes sign where the edge crosses it (x − x_min, x_max − x, y − y_min, y_max − y,
z − base_z, z − z_top for each top height, x − P_j(y) for each wall). Each function is
sampled on a dense grid of l; every sign change is refined by bisection to
``BISECT_TOL``. Between consecutive crossings the edge is wholly inside or wholly
outside, decided by the height field at the midpoint. As a self-check, every grid
sample is classified too and must agree with the interval holding it.

Sampling each boundary function separately, not only the inside flag, means crossings
of two different surfaces closer together than the grid step (an edge passing near a
corner) are both found; only a surface crossed twice within one grid step (an edge
almost tangent to a wall) could be missed. :func:`table1_case` applies the Table 1 case
rules to a result.
"""

from typing import NamedTuple, Sequence, Tuple

import numpy as np

SAMPLES = 2001          # grid points on [0, L]
BISECT_TOL = 1e-13      # mm, bracket width at which bisection stops
MIN_PIECE = 1e-12       # mm, inside pieces shorter than this are ignored
SAME_POINT = 1e-9       # mm, crossings this close to the UEP are candidates for its surface


class StairData(NamedTuple):
    """Staircase stock as plain data (mm).

    z_top: n top heights, section 0 first (along +x).
    walls: n−1 walls, each six (x, y) points on its top edge; wall j starts section j.
    """

    x_min: float
    x_max: float
    y_min: float
    y_max: float
    base_z: float
    z_top: Tuple[float, ...]
    walls: Tuple[Tuple[Tuple[float, float], ...], ...]


class RefEngagement(NamedTuple):
    """Engagement of one edge (one CL point, one φ); lengths along the edge in mm.

    pieces: inside runs ((l_start, l_end), ...), ascending.
    lep, uep: start of the first / end of the last piece (NaN without engagement).
    length: total inside length. lep_xyz, uep_xyz: (3,) points (NaN without engagement).
    uep_candidates: set of (surface name, wall index) within SAME_POINT of the UEP (more
    than one only at ties); wall index is 0 / n for the x limits, j for wall j, −1 for
    other surfaces; {('none', −1)} without engagement.
    uep_section: section holding the material just below the UEP (−1 none).
    sections: sections holding at least MIN_PIECE of inside length.
    bottom_section: section under l = 0.
    """

    pieces: Tuple[Tuple[float, float], ...]
    lep: float
    uep: float
    length: float
    lep_xyz: np.ndarray
    uep_xyz: np.ndarray
    uep_candidates: frozenset
    uep_section: int
    sections: frozenset
    bottom_section: int


class _Walls:
    """Wall curves x = P_j(y), each the quintic through its six points.

    Built from the Lagrange basis in t = (y − y_mid)/half_span of each wall's own points,
    expanded to powers of t and evaluated by Horner; straight walls (six equal x) give
    their x exactly.
    """

    def __init__(self, walls):
        pts = np.asarray(walls, dtype=float).reshape(-1, 6, 2)
        ys = pts[:, :, 1]
        self.mid = 0.5 * (ys.max(axis=1) + ys.min(axis=1))
        self.half = 0.5 * (ys.max(axis=1) - ys.min(axis=1))
        if np.any(self.half <= 0):
            raise ValueError("wall points need distinct y")
        self.x = pts[:, :, 0]
        self.straight = np.all(self.x == self.x[:, :1], axis=1)
        t = (ys - self.mid[:, None]) / self.half[:, None]
        self.coef = np.array([_lagrange_coefficients(tw, xw) for tw, xw in zip(t, self.x)]).reshape(-1, 6)

    def __len__(self):
        return self.x.shape[0]

    def __call__(self, y):
        """x of every wall at y (...,) -> (..., W)."""
        t = (np.asarray(y)[..., None] - self.mid) / self.half
        value = np.zeros_like(t) + self.coef[:, 0]
        for c in self.coef[:, 1:].T:
            value = value * t + c
        return np.where(self.straight, self.x[:, 0], value)


def _lagrange_coefficients(t, x):
    """Coefficients (6,), highest power first, of the quintic through (t_i, x_i), t and x (6,)."""
    coef = np.zeros(6)
    for i in range(6):
        others = np.delete(t, i)
        coef += x[i] * np.poly(others) / np.prod(t[i] - others)
    return coef


def rotation(theta_a, theta_b):
    """R = Rx(θ_A)·Ry(θ_B) for angles in degrees -> (3, 3)."""
    a, b = np.radians(theta_a), np.radians(theta_b)
    rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    ry = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
    return rx @ ry


def edge_lines(radius, cl, theta_a, theta_b, phi):
    """Bottom points (K, 3) and the common direction (3,) of the edges at angles phi (K,) deg."""
    rot = rotation(theta_a, theta_b)
    phi = np.radians(np.atleast_1d(np.asarray(phi, dtype=float)))
    local = np.stack([radius * np.sin(phi), radius * np.cos(phi), np.zeros_like(phi)], axis=1)
    return np.asarray(cl, dtype=float) + local @ rot.T, rot[:, 2]


class _Stock:
    """A StairData with its boundary functions and height field, vectorised over points."""

    def __init__(self, stock: StairData):
        self.data = stock
        self.z_top = np.asarray(stock.z_top, dtype=float)
        self.n = len(self.z_top)
        self.walls = _Walls(stock.walls if stock.walls else np.zeros((0, 6, 2)))
        if len(self.walls) != self.n - 1:
            raise ValueError("need n-1 walls for n sections")
        self.tops = np.unique(self.z_top)
        wall_tags = [("straight_wall" if s else "curved_wall", j + 1) for j, s in enumerate(self.walls.straight)]
        self.tags = ([("straight_wall", 0), ("straight_wall", self.n), ("stock_side", -1), ("stock_side", -1),
                      ("base", -1)] + [("top", -1)] * len(self.tops) + wall_tags)

    def section(self, xyz):
        """Section index (...,) of points (..., 3): number of walls with x ≥ P_j(y)."""
        return self.section_of(self.boundaries(xyz))

    def section_of(self, vals):
        """Section index (...,) from boundary values (..., F)."""
        return np.sum(vals[..., 5 + len(self.tops):] >= 0.0, axis=-1)

    def inside_of(self, vals, z):
        """In the stock (boundary included) (...,) bool, from boundary values (..., F) and z (...,)."""
        return np.all(vals[..., :5] >= 0.0, axis=-1) & (z <= self.z_top[self.section_of(vals)])

    def inside(self, xyz):
        """Whether points (..., 3) are in the stock (boundary included) -> (...,) bool."""
        return self.inside_of(self.boundaries(xyz), xyz[..., 2])

    def boundaries(self, xyz):
        """Boundary functions (..., F) at points (..., 3); column f is tagged self.tags[f]."""
        d = self.data
        x, y, z = xyz[..., 0], xyz[..., 1], xyz[..., 2]
        cols = [x - d.x_min, d.x_max - x, y - d.y_min, d.y_max - y, z - d.base_z]
        return np.concatenate([np.stack(cols, axis=-1), z[..., None] - self.tops,
                               x[..., None] - self.walls(y)], axis=-1)


def _crossings(stock, p0, w, length):
    """All boundary crossings of K edges: (instant (C,), l (C,), column (C,)) arrays."""
    grid = np.linspace(0.0, length, SAMPLES)
    vals = stock.boundaries(p0[:, None, :] + grid[:, None] * w)           # (K, N, F)
    k0, i0, f0 = np.nonzero(vals == 0.0)
    k, i, f = np.nonzero(vals[:, :-1] * vals[:, 1:] < 0.0)
    lo, hi = grid[i], grid[i + 1]
    lo_sign = np.sign(vals[k, i, f])
    idx = np.arange(len(k))
    while len(k) and np.max(hi - lo) > BISECT_TOL:
        mid = 0.5 * (lo + hi)
        fm = stock.boundaries(p0[k] + mid[:, None] * w)[idx, f]
        same = np.sign(fm) == lo_sign
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
    return (np.concatenate([k0, k]), np.concatenate([grid[i0], 0.5 * (lo + hi)]),
            np.concatenate([f0, f]), grid, vals)


def _runs(inside, bp):
    """Inside runs ((l_start, l_end), ...) mm of one edge from interval flags (M,) and
    increasing breakpoints (M+1,); runs shorter than MIN_PIECE are dropped."""
    flags = np.concatenate([[False], inside, [False]]).astype(int)
    starts = np.nonzero(np.diff(flags) == 1)[0]
    ends = np.nonzero(np.diff(flags) == -1)[0]
    return [(bp[s], bp[e]) for s, e in zip(starts, ends) if bp[e] - bp[s] >= MIN_PIECE]


def _one(stock, p0, w, length, roots, cols, grid, grid_inside):
    """RefEngagement of the edge p0 + l·w (p0, w (3,)), 0 ≤ l ≤ length, from its crossings
    roots (C,) mm of boundary columns cols (C,); grid (N,) and grid_inside (N,) for the self-check."""
    bp = np.unique(np.concatenate([[0.0, length], roots[(roots > 0.0) & (roots < length)]]))
    mids = 0.5 * (bp[:-1] + bp[1:])
    inside = stock.inside(p0 + mids[:, None] * w)
    _self_check(bp, inside, grid, grid_inside)
    pieces = _runs(inside, bp)
    bottom = int(stock.section(p0))
    nan3 = np.full(3, np.nan)
    if not pieces:
        return RefEngagement((), np.nan, np.nan, 0.0, nan3, nan3, frozenset({("none", -1)}), -1,
                             frozenset(), bottom)
    lep, uep = pieces[0][0], pieces[-1][1]
    in_piece = np.zeros(len(mids), bool)
    for a, b in pieces:
        in_piece |= (mids > a) & (mids < b)
    last = mids[in_piece][-1]
    in_piece &= bp[1:] - bp[:-1] >= MIN_PIECE
    sections = frozenset(stock.section(p0 + mids[in_piece, None] * w).tolist())
    candidates = {stock.tags[c] for c in cols[np.abs(roots - uep) <= SAME_POINT]}
    if length - uep <= SAME_POINT:
        candidates.add(("flute_end", -1))
    return RefEngagement(tuple(pieces), lep, uep, sum(b - a for a, b in pieces), p0 + lep * w,
                         p0 + uep * w, frozenset(candidates), int(stock.section(p0 + last * w)), sections, bottom)


def _self_check(bp, inside, grid, grid_inside):
    """Raise if a grid sample's inside flag contradicts the interval holding it (missed crossing)."""
    j = np.clip(np.searchsorted(bp, grid, side="right") - 1, 0, len(inside) - 1)
    near = np.min(np.abs(grid[:, None] - bp[None, :]), axis=1) <= 1e-9
    bad = (grid_inside != inside[j]) & ~near
    if np.any(bad):
        raise RuntimeError(f"reference missed a boundary crossing near l = {grid[bad][0]!r}")


def reference_sweep(stock: StairData, radius, flute_length, cl, theta_a, theta_b, phis: Sequence[float]):
    """RefEngagement for each rotation angle of phis (K,) deg at one CL point cl (3,) mm."""
    model = _Stock(stock)
    p0, w = edge_lines(radius, cl, theta_a, theta_b, phis)
    inst, roots, cols, grid, vals = _crossings(model, p0, w, float(flute_length))
    grid_inside = model.inside_of(vals, p0[:, None, 2] + grid * w[2])
    return [_one(model, p0[k], w, float(flute_length), roots[inst == k], cols[inst == k], grid, grid_inside[k])
            for k in range(len(p0))]


def reference_engagement(stock: StairData, radius, flute_length, cl, theta_a, theta_b, phi):
    """RefEngagement of the edge at rotation angle phi (deg) at CL point cl (3,) mm."""
    return reference_sweep(stock, radius, flute_length, cl, theta_a, theta_b, [phi])[0]


def table1_case(ref: RefEngagement, z_top, theta_b):
    """The Table 1 case name of one edge (rules of the test brief), from its RefEngagement."""
    a = ref.bottom_section
    lean = np.sign(np.sin(np.radians(theta_b)))
    b = a + int(lean)
    has_b = lean != 0 and 0 <= b < len(z_top)
    plus = lean > 0
    if not ref.pieces:
        return "B.5" if has_b and z_top[a] < z_top[b] else "none"
    if ref.sections - {a, b if has_b else a}:
        return "multi"
    if not has_b:
        return "none"
    if ref.sections == {a, b}:
        if z_top[a] > z_top[b]:
            return "A.2" if plus else "A.1"
        if z_top[a] < z_top[b]:
            one = len(ref.pieces) == 1
            return ("B.1" if plus else "B.2") if one else ("B.3" if plus else "B.4")
    on_wall = any(s in ("straight_wall", "curved_wall") and j == max(a, b) for s, j in ref.uep_candidates)
    if ref.sections == {a} and z_top[a] > z_top[b] and on_wall:
        return "A.4" if plus else "A.3"
    if ref.sections == {b} and z_top[a] < z_top[b]:
        return "B.6"
    return "none"


# ---------------------------------------------------------------------------------------------
# Helical edges (issue #6). The same boundary functions, sampled along the exact helix
#     S(l) = T + R·(R_t sin ψ(l), R_t cos ψ(l), l),  ψ(l) = ψ_0 − l·tan β / R_t,
# plus, with an immersion range [a, b] (deg), the functions sin(π(ψ − a)/360) and
# sin(π(ψ − b)/360), which change sign where ψ crosses a + 360n and b + 360n. Every sign
# change on the grid is refined by bisection; pieces between crossings are classified at their
# midpoints (in the stock, and (ψ − a) mod 360 ≤ b − a).


class RefHelix(NamedTuple):
    """Engagement of one helical edge: pieces ((l_start, l_end), ...) ascending (axial mm),
    lep, uep (NaN without engagement), length (total axial inside length), lep_xyz, uep_xyz (3,)."""

    pieces: Tuple[Tuple[float, float], ...]
    lep: float
    uep: float
    length: float
    lep_xyz: np.ndarray
    uep_xyz: np.ndarray


def helix_points(radius, cl, theta_a, theta_b, psi0, helix, l):
    """Points (K, N, 3) of the helices with start angles psi0 (K,) deg at axial positions l (K, N) mm."""
    rot = rotation(theta_a, theta_b)
    l = np.asarray(l, dtype=float)
    psi = np.radians(np.asarray(psi0, dtype=float))[:, None] - l * np.tan(np.radians(helix)) / radius
    local = np.stack([radius * np.sin(psi), radius * np.cos(psi), np.broadcast_to(l, psi.shape)], axis=-1)
    return np.asarray(cl, dtype=float) + local @ rot.T


def _helix_values(stock, radius, cl, theta_a, theta_b, psi0, helix, l, immersion):
    """Boundary values (K, N, F), z (K, N) and the immersion flag (K, N) at positions l (K, N)."""
    points = helix_points(radius, cl, theta_a, theta_b, psi0, helix, l)
    vals = stock.boundaries(points)
    psi = np.asarray(psi0, dtype=float)[:, None] - np.degrees(l * np.tan(np.radians(helix)) / radius)
    flag = np.ones(psi.shape, dtype=bool)
    if immersion is not None:
        a, b = immersion
        angle = np.stack([np.sin(np.pi * (psi - a) / 360.0), np.sin(np.pi * (psi - b) / 360.0)], axis=-1)
        vals = np.concatenate([vals, angle], axis=-1)
        flag = np.mod(psi - a, 360.0) <= b - a
    return vals, points[..., 2], flag


def reference_helix_sweep(stock: StairData, radius, flute_length, cl, theta_a, theta_b, psi0: Sequence[float],
                          helix, immersion=None, samples=SAMPLES):
    """RefHelix for each helix start angle of psi0 (K,) deg at CL point cl (3,) mm; helix β deg;
    immersion None or (start, end) deg with 0 ≤ end − start < 360."""
    model = _Stock(stock)
    psi0 = np.atleast_1d(np.asarray(psi0, dtype=float))
    length = float(flute_length)
    grid = np.linspace(0.0, length, samples)
    n_k = len(psi0)
    vals, z, flag = _helix_values(model, radius, cl, theta_a, theta_b, psi0, helix, np.tile(grid, (n_k, 1)), immersion)
    grid_inside = model.inside_of(vals[..., :5 + len(model.tops) + len(model.walls)], z) & flag
    k, i, f = np.nonzero(vals[:, :-1] * vals[:, 1:] < 0.0)
    lo, hi = grid[i], grid[i + 1]
    lo_sign = np.sign(vals[k, i, f])
    while len(k) and np.max(hi - lo) > BISECT_TOL:
        mid = 0.5 * (lo + hi)
        fm = _helix_values(model, radius, cl, theta_a, theta_b, psi0[k], helix, mid[:, None], immersion)[0][:, 0, :]
        fm = fm[np.arange(len(k)), f]
        same = np.sign(fm) == lo_sign
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
    k0, i0, _ = np.nonzero(vals == 0.0)
    roots_k = np.concatenate([k0, k])
    roots = np.concatenate([grid[i0], 0.5 * (lo + hi)])
    out = []
    for kk in range(n_k):
        bp = np.unique(np.concatenate([[0.0, length], roots[(roots_k == kk) & (roots > 0.0) & (roots < length)]]))
        mids = 0.5 * (bp[:-1] + bp[1:])
        mvals, mz, mflag = _helix_values(model, radius, cl, theta_a, theta_b, psi0[[kk]], helix, mids[None, :],
                                         immersion)
        inside = model.inside_of(mvals[0, :, :5 + len(model.tops) + len(model.walls)], mz[0]) & mflag[0]
        _self_check(bp, inside, grid, grid_inside[kk])
        pieces = _runs(inside, bp)
        nan3 = np.full(3, np.nan)
        if not pieces:
            out.append(RefHelix((), np.nan, np.nan, 0.0, nan3, nan3))
            continue
        lep, uep = pieces[0][0], pieces[-1][1]
        ends = helix_points(radius, cl, theta_a, theta_b, [psi0[kk]], helix, np.array([[lep, uep]]))[0]
        out.append(RefHelix(tuple(pieces), lep, uep, sum(b - a for a, b in pieces), ends[0], ends[1]))
    return out
