"""The corner arcs of bull-nose and ball-end mills against a Staircase, exactly, for many arcs at once.

The arc of the corner at one instant (docs/ENGINE.md, "Tools with a corner") is

    P(ψ) = C + a·cos ψ + b·sin ψ,   a = −r·w,   b = r·d,   0 ≤ ψ ≤ ψ_max ≤ 90°,

its arc length s = r·ψ. corner.py solves it against any terraced stock (slab by slab, ray parity,
generic Bézier pieces); a staircase needs less, since whether a point is in it is a closed test:
within its x and y limits, at or above the base, at or below the top of the section holding it, the
section being the number of walls with x ≥ W_j(y). Along each arc:

1. **Breakpoints.**
   * The planes (the x and y limits, the base, each distinct top): one component of the arc against
     a constant, a·cos ψ + b·sin ψ = c', in closed form (corner.trig_roots), for the arcs whose exact
     range in that component (its ends and turning point) holds the plane.
   * The walls an arc may cross: those whose x band over the arc's y range meets the arc's x range
     (per bin of the y window, as the line engine's bands; walls wholly left of the arc count for the
     section, walls wholly right of it cost nothing). A straight wall is the plane x = c.
   * A quintic wall x = P(t), t = (y − y_mid)/y_half: with tan(ψ/2) = T·u, T = tan(ψ_max/2),
     u ∈ [0, 1], D = 1 + T²u², cos ψ = (1 − T²u²)/D and sin ψ = 2Tu/D, so G(u) = D⁵·(x − P(t)) along
     the arc is a polynomial of degree 10 whose sign is the side of the wall (G ≥ 0: x ≥ P). Its
     Bernstein coefficients on [0, 1] come from its values at 11 Chebyshev–Lobatto nodes (one small
     matrix product); one sign: no crossing (most pairs). Otherwise Descartes' rule with de Casteljau
     halving isolates each change of side (_isolated: a piece whose coefficients are nonzero with one
     change holds one simple root; two changes closer than 2^−DEEP_DEPTH count as none, a touch), and
     Newton on x(ψ) − P(t(ψ)) itself, in ψ, from where the control polygon crosses 0 and kept inside
     the piece, refines each to ROOT_TOL. The side at the arc's start is the sign of G(0), and each
     crossing changes it (+1 or −1 to the section, by the piece's first coefficient), so the section
     of every piece follows without evaluating a wall.
   * A B-spline wall (per span x = X/Ω, y = Y/Ω in its own u): the arc's plan projection is the
     ellipse arc Q(ψ) = C_p + A·cos ψ + B·sin ψ (A, B the plan parts of a, b), whose implicit equation
     |adj(M)(Q − C_p)|² − det(M)² = 0, M = [A B], is a polynomial of degree 2p in a span's u (as
     corner.py solves a terraced stock's pieces); the span's end values are those at the curve's knots,
     shared by the two spans that meet there, so a crossing at a knot is found once. The spans solved
     are those of the y range where the arc can meet the wall (_narrowed: within a strip about the
     chord of the spans, from their slope bounds; two rounds), whose control boxes meet the arc's box.
     A crossing's ψ comes from its point (corner._ellipse_angle). Where the ellipse is flat (smaller
     semi-axis below corner.FLAT mm, as for an upright tool) its plan line is crossed instead
     (SplineTable.crossings) and each crossing's ψ solves a·cos ψ + b·sin ψ = t. Either way Newton on
     C(u) = Q(ψ) then polishes the crossing to rounding (_polished). The side of a B-spline or straight
     wall is evaluated at each piece's middle (a B-spline's span holding y first: outside its control
     box no curve point is needed).
2. **Pieces.** The breakpoints of each arc are sorted in one row of a small padded table (its start
   first, its end last among equals), and cut it into pieces; a piece is inside when its middle is.
   Consecutive inside pieces make a run (a gap of at most LENGTH_EPS does not break one; a run not
   longer than that is dropped).

No bound on a B-spline wall here rests on SplineTable.x_at (or the stock's bands, made with it), which
can take the wrong end of a span when y is a knot whose stored span start rounds below it: its bands are
the spans' control boxes per bin, and W(y) is _spline_x.

Labels of a run's ends (EdgeIntervals), from the breakpoint there: "top" (a section's top), "bottom"
(the base), "straight_wall" / "curved_wall" with wall j (1 … n−1, wall j starts section j, as the
staircase engine numbers them), "straight_wall" with 0 or n at the x limits, "stock_side" (a y limit,
wall −1, as the staircase engine labels it), "flute_start" (the arc's first point inside the material)
and, at its last point, CORNER_TOP where the arc reaches 90° (the straight side goes on there) or
"flute_end" (the flute ends within the corner). Section: the staircase section whose material holds
that end (corner.py gives the slab of the terraced form). Where breakpoints coincide, one names the end.

Shapes: N arcs; centre, d, w (N, 3) (mm, unit vectors); r and ψ_max floats. Lengths in mm.
"""

import weakref
from math import comb

import numpy as np

from .allocator import keep_freed_memory
from .bands import BINS, sparse_table
from .corner import CORNER_TOP, FLAT, _ellipse_angle, trig_roots
from .engagement import SURFACES
from .intervals import EdgeIntervals
from .polynomials import bracketed_root, derivative, horner, product, value_and_slope
from .tolerances import LENGTH_EPS, ROOT_MAX_ITER, ROOT_TOL
from .walls import SplineWall, Wall

_CODE = {name: SURFACES.index(name) for name in ("top", "straight_wall", "curved_wall", "flute_end", "stock_side",
                                                    "bottom", "flute_start")}
#: Margin (mm) by which the arcs' exact ranges are widened where they exclude a plane, a wall or a span.
MARGIN = 1e-9
#: Arcs solved at once (bounds the padded tables of breakpoints and the (arc, wall) pairs).
CHUNK = 1 << 15
#: Levels of halving in the isolation of a wall's crossings (_isolated): two changes of side closer than
#: 2^−DEEP_DEPTH of the arc's or span's parameter are taken as none (the arc touches the wall there).
DEEP_DEPTH = 48
#: Newton steps on a wall's one crossing before the general root finder takes the rows not yet converged.
FAST_STEPS = 5
#: Newton steps polishing a B-spline wall's crossing (_polished).
POLISH_STEPS = 3
#: A label as one integer: surface code · _LABEL + wall + 1 (codes may be negative: CORNER_TOP).
_LABEL = 1 << 20


def staircase_corner_intervals(stock, centre, d, w, radius, psi_max):
    """Inside intervals of N corner arcs in a Staircase, in arc length s = r·ψ (mm) from each arc's lowest
    point: an EdgeIntervals with the labels of the module docstring (corner.corner_intervals' contract)."""
    c = np.asarray(centre, dtype=float).reshape(-1, 3)
    d = np.asarray(d, dtype=float).reshape(-1, 3)
    w = np.asarray(w, dtype=float).reshape(-1, 3)
    if not c.shape == d.shape == w.shape:
        raise ValueError(f"centre, d and w must all be (N, 3), got {c.shape}, {d.shape} and {w.shape}")
    n, r, top = c.shape[0], float(radius), float(psi_max)
    keep_freed_memory()
    walls = _wall_table(stock)
    parts = [_chunk(stock, walls, c[s:s + CHUNK], -r * w[s:s + CHUNK], r * d[s:s + CHUNK], r, top, s)
             for s in range(0, n, CHUNK)]
    columns = [np.concatenate(v) for v in zip(*parts)] if parts else [np.zeros(0, dtype=np.intp)] * 9
    rows, start, end, s_code, s_section, s_wall, e_code, e_section, e_wall = columns
    return EdgeIntervals(n, rows.astype(np.intp), start.astype(float), end.astype(float), s_code.astype(np.int8),
                         s_section.astype(np.int32), s_wall.astype(np.int32), e_code.astype(np.int8),
                         e_section.astype(np.int32), e_wall.astype(np.int32))


_LAST_TABLE = [None, None]  # (weak reference to a Staircase, its _WallTable): the chunks of one pass share it


def _wall_table(stock):
    """The _WallTable of `stock`, kept for the last stock asked for."""
    ref, table = _LAST_TABLE
    if ref is None or ref() is not stock:
        table = _WallTable(stock)
        _LAST_TABLE[:] = [weakref.ref(stock), table]
    return table


class _WallTable:
    """The staircase's walls as the corner solves them.

    coefficients (n_w, 6), y_mid, y_half (n_w,): the quintic walls' (walls.Wall); kind (n_w,): 0 quintic,
    1 straight (the plane x = plane_x), 2 B-spline; code: their surface codes. Bands: per wall and bin of
    the y window (bands.BINS), the x range, as sparse tables (low, high: (levels, n_w, BINS)) with the
    run envelopes reach_low, reach_high (n_w,), as bands.WallBands keeps them: a quintic's from the
    stock's own bands (exact); a B-spline's from the control boxes of the spans meeting the bin (the span
    lies in them), so that no bound rests on evaluating the curve at a bin edge (SplineTable.x_at can
    miss a point there when the edge is a knot: see _spline_x).
    """

    def __init__(self, stock):
        n_w = len(stock.walls)
        self.coefficients, self.y_mid, self.y_half = np.zeros((n_w, 6)), np.zeros(n_w), np.ones(n_w)
        self.kind, self.plane_x = np.zeros(n_w, dtype=np.intp), np.zeros(n_w)
        for j, wall in enumerate(stock.walls):
            if wall.is_straight:
                self.kind[j] = 1
                straight_x = wall.poles[0, 0] if isinstance(wall, SplineWall) else wall.coefficients[0]
                self.plane_x[j] = float(straight_x)
            elif isinstance(wall, Wall):
                self.coefficients[j], self.y_mid[j], self.y_half[j] = wall.coefficients, wall.y_mid, wall.y_half
            else:
                self.kind[j] = 2
        self.code = np.where(self.kind == 1, _CODE["straight_wall"], _CODE["curved_wall"])
        self.n_walls, self.y_min, self.y_max = n_w, stock.y_min, stock.y_max
        if n_w == 0:
            return
        low, high = stock.bands.low[0].copy(), stock.bands.high[0].copy()
        edges = np.linspace(stock.y_min, stock.y_max, BINS + 1)
        for j in np.flatnonzero(self.kind == 2):
            # The spans meeting each bin: first … last (the end ones for bins beyond the curve).
            wall = stock.walls[j]
            spans = wall.span_y.size - 1
            first = np.clip(np.searchsorted(wall.span_y[1:], edges[:-1], side="left"), 0, spans - 1)
            last = np.maximum(np.clip(np.searchsorted(wall.span_y[:-1], edges[1:], side="right") - 1, 0, spans - 1),
                              first)
            count = last - first + 1
            offsets = np.cumsum(count) - count
            index = np.repeat(first, count) + np.arange(count.sum()) - np.repeat(offsets, count)
            low[j] = np.minimum.reduceat(wall.span_boxes[index, 0], offsets)
            high[j] = np.maximum.reduceat(wall.span_boxes[index, 1], offsets)
        self.low, self.high = sparse_table(low, np.minimum), sparse_table(high, np.maximum)
        whole = np.column_stack([low.min(axis=1), high.max(axis=1)])
        self.reach_low = np.minimum.accumulate(whole[::-1, 0])[::-1]
        self.reach_high = np.maximum.accumulate(whole[:, 1])
        self._scale = BINS / (stock.y_max - stock.y_min)

    def query(self, y_a, y_b, walls):
        """(low, high) (P,): x range of wall walls[i] over y from y_a[i] to y_b[i] ≥ y_a[i] (as
        bands.WallBands.query)."""
        first, last = (np.minimum(np.maximum(np.floor((y - self.y_min) * self._scale), 0.0), BINS - 1.0).astype(np.intp)
                       for y in (y_a, y_b))
        level = np.frexp(last - first + 1)[1] - 1  # ⌊log2 of the bin count⌋
        row = (level * self.n_walls + walls) * BINS
        at_first, at_second = row + first, row + last - (1 << level) + 1
        low, high = self.low.reshape(-1), self.high.reshape(-1)
        return (np.minimum(low.take(at_first), low.take(at_second)),
                np.maximum(high.take(at_first), high.take(at_second)))

    def beyond(self, stock, walls, x, y):
        """(P,) bool: x[i] ≥ W_j(y[i]) for the straight or B-spline walls walls[i] (0-based). A B-spline's
        span holding y is looked up first: where x lies outside its control box, no curve point is needed."""
        out = x >= self.plane_x[walls]
        spline = np.flatnonzero(self.kind[walls] == 2)
        if spline.size:
            table = stock.splines
            j, xs, ys = walls[spline], x[spline], y[spline]
            local = table.key_search.search(np.clip(ys, table.y_first[j], table.y_last[j]) - table.base
                                            + table.slot[j] * table.shift, "right") - 1 - table.first_end[j]
            box = table.span_boxes[table.first_span[j] + np.clip(local, 0, table.n_spans[j] - 1)]
            side = xs > box[:, 1]
            unsure = np.flatnonzero((xs >= box[:, 0]) & ~side)
            side[unsure] = xs[unsure] >= _spline_x(table, j[unsure], ys[unsure])
            out[spline] = side
        return out


def _spline_parameter(table, walls, y):
    """(span (P,) stacked index, u (P,)) where B-spline walls walls[i] have height y[i] (clipped to the
    curve's ends): the root u of Y(u) − y·Ω(u) in the span holding y. Where y is within rounding of a knot
    the span found may not change sign on [0, 1] (its end's y rounds to the other side of y); its nearer end
    is then the point (SplineTable.span_parameter would take a root outside the bracket there)."""
    y = np.clip(y, table.y_first[walls], table.y_last[walls])
    key = y - table.base + table.slot[walls] * table.shift
    local = table.key_search.search(key, "right") - 1 - table.first_end[walls]
    span = table.first_span[walls] + np.clip(local, 0, table.n_spans[walls] - 1)
    c = table.spans_y[span] - y[:, None] * table.spans_w[span]
    f_lo, f_hi = c[:, 0], c.sum(axis=1)
    u = np.where(np.abs(f_lo) <= np.abs(f_hi), 0.0, 1.0)
    bracket = np.flatnonzero(np.sign(f_lo) * np.sign(f_hi) <= 0.0)
    if bracket.size:
        u[bracket] = bracketed_root(np.ascontiguousarray(c[bracket].T), np.zeros(bracket.size), np.ones(bracket.size),
                                    f_lo[bracket], f_hi[bracket])
    return span, u


def _spline_x(table, walls, y):
    """x = W_j(y) (P,) of B-spline walls walls[i] at y[i] (_spline_parameter, then X/Ω there)."""
    span, u = _spline_parameter(table, walls, y)
    return horner(table.spans_x[span], u) / horner(table.spans_w[span], u)


def _chunk(stock, walls, c, a, b, r, top, offset):
    """Runs of one chunk of arcs (rows numbered from `offset`): (rows, start, end (mm of s), start code,
    start section, start wall, end code, end section, end wall), each (K,), sorted by row then s."""
    low, high = _ranges(c, a, b, top)
    box_low = np.array([stock.x_min, stock.y_min, stock.base_z])
    box_high = np.array([stock.x_max, stock.y_max, float(stock.z_top.max())])
    live = np.flatnonzero(((high + MARGIN >= box_low) & (low - MARGIN <= box_high)).all(axis=1))
    n = live.size
    if n == 0:
        return tuple(np.zeros(0, dtype=float if k in (1, 2) else np.intp) for k in range(9))
    c, a, b, low, high = c[live], a[live], b[live], low[live], high[live]
    blocks = []
    # The planes: x and y limits, the base and each distinct top.
    planes = [(0, stock.x_min, _CODE["straight_wall"], 0), (0, stock.x_max, _CODE["straight_wall"], stock.n_sections),
              (1, stock.y_min, _CODE["stock_side"], -1), (1, stock.y_max, _CODE["stock_side"], -1),
              (2, stock.base_z, _CODE["bottom"], -1)]
    planes += [(2, float(z), _CODE["top"], -1) for z in np.unique(stock.z_top)]
    crossed = []
    for axis, value, code, wall in planes:
        rows = np.flatnonzero((low[:, axis] - MARGIN <= value) & (high[:, axis] + MARGIN >= value))
        crossed.append((rows, a[rows, axis], b[rows, axis], value - c[rows, axis], code * _LABEL + wall + 1))
    sizes = [part[0].size for part in crossed]
    roots = trig_roots(*(np.concatenate([part[k] for part in crossed]) for k in (1, 2, 3)), top)
    for (rows, *_, label), part in zip(crossed, np.split(roots, np.cumsum(sizes)[:-1])):
        blocks.extend(_root_blocks(rows, part, np.full(rows.size, label)))
    # The walls the arcs may cross: a quintic's side of each piece follows from its side at the arc's start
    # and its changes of side (deltas of the section), the others are evaluated at the pieces' middles.
    y_lo, y_hi = np.maximum(low[:, 1], stock.y_min), np.minimum(high[:, 1], stock.y_max)
    pair_rows, pair_walls, section = _candidate_walls(walls, low[:, 0], high[:, 0], y_lo, y_hi)
    kind = walls.kind[pair_walls]
    quintic = np.flatnonzero(kind == 0)
    if quintic.size:
        found, beyond = _quintic_walls(walls, pair_rows[quintic], pair_walls[quintic], c, a, b, top)
        blocks.extend(found)
        section = section + np.bincount(pair_rows[quintic][beyond], minlength=n)
    evaluated = np.flatnonzero(kind != 0)
    for which, solve in ((1, _plane_walls), (2, _spline_walls)):
        pairs = evaluated[kind[evaluated] == which]
        if pairs.size:
            blocks.extend(solve(stock, walls, pair_rows[pairs], pair_walls[pairs], c, a, b, low, high, top))
    psi, packed = _sorted_breakpoints(n, blocks, top)
    return _runs(stock, walls, live + offset, psi, packed, c, a, b, r, section, pair_rows[evaluated],
                 pair_walls[evaluated])


def _ranges(c, a, b, top):
    """(low, high) (N, 3) of each component of c + a cos ψ + b sin ψ over ψ in [0, top] (top ≤ π/2): the
    ends and, where it lies on the arc, the turning point: a cos ψ + b sin ψ = amplitude·cos(ψ − θ) is
    greatest at ψ = θ, the angle of (a, b), on the arc when b ≥ 0 and a·sin top ≥ b·cos top, and least at
    θ + π, on the arc when the same holds for (−a, −b)."""
    cos_top, sin_top = np.cos(top), np.sin(top)
    start, end = c + a, c + a * cos_top + b * sin_top
    amplitude = np.sqrt(a * a + b * b)
    turn = a * sin_top - b * cos_top
    high = np.maximum(start, end)
    low = np.minimum(start, end)
    np.maximum(high, c + amplitude, out=high, where=(b >= 0.0) & (turn >= 0.0))
    np.minimum(low, c - amplitude, out=low, where=(b <= 0.0) & (turn <= 0.0))
    return low, high


def _root_blocks(rows, roots, label, delta=None):
    """Breakpoint blocks (rows, ψ, label, section delta) from NaN-padded roots (m, k) of the arcs `rows`
    (m,), labels (m,), one block per column (each arc once in a block); delta (m,) or None: 0."""
    out = []
    for k in range(roots.shape[1]):
        found = np.flatnonzero(~np.isnan(roots[:, k]))
        if found.size:
            out.append((rows[found], roots[found, k], label[found], 0 if delta is None else delta[found]))
    return out


def _candidate_walls(bands, x_lo, x_hi, y_lo, y_hi):
    """Walls each arc may cross: pairs (rows, walls) (P,), by row then wall (walls 0-based), and left_of (n,),
    the number of walls wholly left of the arc's x range over its y range (y_lo ≤ y_hi within the window;
    an arc outside the window's y has no pairs). The bands (_WallTable) as engagement._reachable_walls
    uses the stock's."""
    if bands.n_walls == 0:
        empty = np.zeros(0, dtype=np.intp)
        return empty, empty, np.zeros(x_lo.size, dtype=np.intp)
    lo, hi = x_lo - MARGIN, x_hi + MARGIN
    first = np.searchsorted(bands.reach_high, lo, side="left")
    count = np.where(y_lo <= y_hi, np.searchsorted(bands.reach_low, hi, side="right") - first, 0).clip(0)
    rows = np.repeat(np.arange(x_lo.size), count)
    walls = first[rows] + (np.arange(rows.size) - np.repeat(np.cumsum(count) - count, count))
    low, high = bands.query(y_lo[rows], y_hi[rows], walls)
    beyond = lo[rows] > high
    keep = ~beyond & (hi[rows] >= low)
    left_of = first + np.bincount(rows[beyond], minlength=x_lo.size)
    return rows[keep], walls[keep], left_of


def _wall_label(table, wall_index):
    """Labels (P,) of crossings of the walls `wall_index` (0-based; wall j + 1 in the labels)."""
    return table.code[wall_index] * _LABEL + wall_index + 2


def _plane_walls(stock, table, rows, wall_index, c, a, b, low, high, top):
    """Breakpoint blocks of straight walls: the planes x = const, in closed form (their sides are evaluated)."""
    roots = trig_roots(a[rows, 0], b[rows, 0], table.plane_x[wall_index] - c[rows, 0], top)
    return _root_blocks(rows, roots, _wall_label(table, wall_index))


_BERNSTEIN = {}


def _to_bernstein(degree):
    """(d+1, d+1) matrix T: power-basis coefficients (m, d+1) @ T are the Bernstein ones on [0, 1]."""
    if degree not in _BERNSTEIN:
        _BERNSTEIN[degree] = np.array([[comb(j, i) / comb(degree, i) if i <= j else 0.0 for i in range(degree + 1)]
                                       for j in range(degree + 1)]).T.copy()
    return _BERNSTEIN[degree]


_POWER = {}


def _to_power(degree):
    """(d+1, d+1) matrix: Bernstein coefficients on [0, 1] (m, d+1) @ it are the power-basis ones."""
    if degree not in _POWER:
        _POWER[degree] = np.linalg.inv(_to_bernstein(degree))
    return _POWER[degree]


#: The nodes u_k (11,) of G on [0, 1] (Chebyshev–Lobatto: its values there give its Bernstein coefficients
#: with the least growth of rounding, a factor of at most about 700).
_NODES = 0.5 - 0.5 * np.cos(np.pi * np.arange(11) / 10)
#: Values of G at _NODES (m, 11) @ this = its Bernstein coefficients on [0, 1] (m, 11).
_NODES_TO_BERNSTEIN = np.linalg.inv(np.array([[comb(10, j) * u ** j * (1.0 - u) ** (10 - j) for j in range(11)]
                                              for u in _NODES])).T.copy()


def _quintic_walls(table, rows, wall_index, c, a, b, top):
    """Crossings of quintic walls: the changes of side of G(u) = D⁵·(x − P(t)) along each arc (module
    docstring), from its Bernstein coefficients (its values at 11 nodes, D⁵·g there), each root refined on
    g itself (_quintic_roots). Returns the breakpoint blocks (delta +1 where the arc passes to x ≥ P, −1
    back) and whether each pair (P,) starts at or beyond its wall (G(0) ≥ 0); rows (P,) by row."""
    t_top = np.tan(0.5 * top)
    t2 = t_top * t_top
    scale = 1.0 + t2 * _NODES ** 2
    trig = np.stack([np.ones(11), (1.0 - t2 * _NODES ** 2) / scale, 2.0 * t_top * _NODES / scale])  # 1, cos, sin
    arcs = _QuinticArcs.of(table, rows, wall_index, c, a, b)
    g = arcs.values(trig) * scale ** 5
    bernstein = g @ _NODES_TO_BERNSTEIN
    beyond = bernstein[:, 0] >= 0.0
    mixed = np.flatnonzero((bernstein >= 0.0).any(axis=1) & (bernstein < 0.0).any(axis=1))
    if mixed.size == 0:
        return [], beyond
    bernstein = bernstein[mixed] / np.abs(bernstein[mixed]).max(axis=1, keepdims=True)
    owner, lo, width, coefficients, deep, u, deep_rising = _isolated(bernstein)
    psi = _quintic_roots(arcs.rows(mixed[owner]), lo, width, coefficients, t_top, top)
    rising = coefficients[:, 0] < 0.0
    if deep.size:
        owner = np.concatenate([owner, deep])
        psi = np.concatenate([psi, 2.0 * np.arctan(t_top * u)])
        rising = np.concatenate([rising, deep_rising])
    order = np.argsort(owner, kind="stable")
    pair = mixed[owner[order]]
    delta = np.where(rising[order], 1, -1)
    return [(rows[pair], psi[order], _wall_label(table, wall_index[pair]), delta)], beyond


class _QuinticArcs:
    """(Arc, quintic wall) pairs: g(ψ) = x(ψ) − P(t(ψ)) along each arc, t = (y − y_mid)/y_half, with
    x − c_0 = xf·(1, cos ψ, sin ψ) and t = tf·(1, cos ψ, sin ψ): xf, tf (P, 3); c (P, 5) the walls'
    c_1 … c_5."""

    def __init__(self, xf, tf, c):
        self.xf, self.tf, self.c = xf, tf, c

    @classmethod
    def of(cls, table, rows, wall_index, c, a, b):
        """The pairs (arc rows[i], quintic wall wall_index[i]) of arcs c + a cos ψ + b sin ψ (n, 3)."""
        coefficients = table.coefficients[wall_index]
        xf = np.column_stack([c[rows, 0] - coefficients[:, 0], a[rows, 0], b[rows, 0]])
        tf = np.column_stack([c[rows, 1] - table.y_mid[wall_index], a[rows, 1], b[rows, 1]])
        return cls(xf, tf / table.y_half[wall_index, None], np.ascontiguousarray(coefficients[:, 1:]))

    def rows(self, index):
        """The pairs `index` as a _QuinticArcs."""
        return _QuinticArcs(self.xf[index], self.tf[index], self.c[index])

    def values(self, trig):
        """g (P, k) at the angles whose (1, cos, sin) are the columns of trig (3, k)."""
        t = self.tf @ trig
        total = self.c[:, 4:5] * t
        for k in range(3, -1, -1):
            total += self.c[:, k:k + 1]
            total *= t
        return self.xf @ trig - total

    def value_and_slope(self, cos, sin):
        """g and dg/dψ (P,) at angles with cosines and sines cos, sin (P,)."""
        xf, tf, c = self.xf, self.tf, self.c
        t = tf[:, 0] + tf[:, 1] * cos + tf[:, 2] * sin
        dt = tf[:, 2] * cos - tf[:, 1] * sin
        value, slope = c[:, 4] * t, c[:, 4] * 5.0
        for k in range(3, -1, -1):
            slope = slope * t + (k + 1) * c[:, k]
            value = (value + c[:, k]) * t
        return xf[:, 0] + xf[:, 1] * cos + xf[:, 2] * sin - value, xf[:, 2] * cos - xf[:, 1] * sin - slope * dt


def _quintic_roots(arcs, lo, width, bernstein, t_top, top):
    """ψ (m,) of the one crossing of each pair of `arcs` (a _QuinticArcs) in u ∈ [lo, lo + width], where
    G's Bernstein coefficients `bernstein` (m, 11) are nonzero with one change of sign: Newton on g(ψ)
    itself (exact, in the trigonometric form) from where the control polygon crosses 0, kept inside the
    bracket, which shrinks by the sign of each value (a step out of it is a halving); rows not converged
    (last step above ROOT_TOL) after FAST_STEPS go on, halving at worst, until they are."""
    m = bernstein.shape[0]
    negative = bernstein < 0.0
    at = np.argmax(negative[:, 1:] != negative[:, :-1], axis=1)
    every = np.arange(m)
    left, right = bernstein[every, at], bernstein[every, at + 1]
    start = lo + width * (at + left / (left - right)) / 10.0
    angle = np.where(lo + width >= 1.0, top, 2.0 * np.arctan(t_top * (lo + width)))
    bracket = (2.0 * np.arctan(t_top * lo), angle)
    psi = 2.0 * np.arctan(t_top * start)
    return _bracketed_newton(arcs, psi, *bracket, negative[:, 0])


def _bracketed_newton(arcs, x, lo, hi, negative_lo):
    """Roots (m,) of g (arcs.value_and_slope, in ψ) in [lo, hi] (m,) from x (m,), g(lo) < 0 where
    negative_lo (m,) and g(hi) of the other sign: Newton kept in the bracket (see _quintic_roots)."""
    todo = np.arange(x.size)
    for count in range(1, ROOT_MAX_ITER + 1):
        xs, ls, hs = x[todo], lo[todo], hi[todo]
        value, slope = arcs.value_and_slope(np.cos(xs), np.sin(xs))
        toward_hi = (value < 0.0) == negative_lo[todo]
        ls = np.where(toward_hi, xs, ls)
        hs = np.where(toward_hi, hs, xs)
        with np.errstate(divide="ignore", invalid="ignore"):
            following = xs - value / slope
        following = np.where((following >= ls) & (following <= hs), following, 0.5 * (ls + hs))
        following = np.where(value == 0.0, xs, following)
        x[todo], lo[todo], hi[todo] = following, ls, hs
        if count >= FAST_STEPS:
            going = np.flatnonzero((np.abs(following - xs) > ROOT_TOL) & (hs - ls > ROOT_TOL))
            if going.size == 0:
                break
            if going.size < todo.size:
                todo, arcs = todo[going], arcs.rows(going)
    return x


def _isolated(bernstein):
    """The changes of sign of M polynomials on [0, 1] given by their Bernstein coefficients (M, d+1), with
    the side rule of terraced.side_changes (a value ≥ 0 is one side, < 0 the other; a tangent contact is no
    change): Descartes' rule in the Bernstein basis, with de Casteljau halving. A piece whose coefficients
    are nonzero with one change of sign holds one simple root; a piece of one sign (zeros allowed) holds no
    change; the others are halved, up to DEEP_DEPTH levels, where a piece (2^−DEEP_DEPTH wide: roots that
    close, or a double root) holds one change, at its middle, when its end values are on different sides.

    Returns owner, lo, width (C,) and the coefficients (C, d+1) of the pieces holding one simple root, and
    owner, u (E,) of the changes placed at the middle of a deepest piece, with rising (E,): from < 0 to ≥ 0.
    """
    m = bernstein.shape[0]
    owner, lo, width, coefficients = np.arange(m), np.zeros(m), np.ones(m), bernstein
    found, placed = [], []
    for depth in range(DEEP_DEPTH + 1):
        negative = coefficients < 0.0
        if depth == DEEP_DEPTH:
            change = negative[:, 0] != negative[:, -1]
            placed.append((owner[change], lo[change] + 0.5 * width[change], negative[change, 0]))
            break
        variations = (negative[:, 1:] != negative[:, :-1]).sum(axis=1)
        nonzero = (coefficients != 0.0).all(axis=1)
        single = nonzero & (variations == 1)
        found.append((owner[single], lo[single], width[single], coefficients[single]))
        split = ~(single | negative.all(axis=1) | (~negative).all(axis=1))
        if not split.any():
            break
        owner, lo, width, coefficients = owner[split], lo[split], width[split], coefficients[split]
        left, right = _halves(coefficients)
        owner = np.concatenate([owner, owner])
        lo = np.concatenate([lo, lo + 0.5 * width])
        width = np.concatenate([0.5 * width, 0.5 * width])
        coefficients = np.concatenate([left, right])
    owner, lo, width, coefficients = (np.concatenate(v) for v in zip(*found))
    if not placed:
        return owner, lo, width, coefficients, np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0, dtype=bool)
    return (owner, lo, width, coefficients) + placed[0]


def _halves(coefficients):
    """Bernstein coefficients (M, d + 1) of each polynomial on the two halves of its interval (de Casteljau)."""
    d = coefficients.shape[1] - 1
    left, right = np.empty_like(coefficients), np.empty_like(coefficients)
    row = coefficients
    left[:, 0], right[:, d] = row[:, 0], row[:, d]
    for k in range(1, d + 1):
        row = 0.5 * (row[:, :-1] + row[:, 1:])
        left[:, k], right[:, d - k] = row[:, 0], row[:, -1]
    return left, right


def _single_roots(columns, lo, width, bernstein):
    """The one root in [lo, lo + width] (m,) of each polynomial whose Bernstein coefficients there,
    `bernstein` (m, d+1), are nonzero with one change of sign; columns (d+1, m) its power-basis
    coefficients on [0, 1], ascending: Newton from where the control polygon crosses 0, kept inside a
    bracket that shrinks by the sign of each value (a step out of it is a halving), FAST_STEPS times; a row
    whose last step is above ROOT_TOL goes to polynomials.bracketed_root within its bracket."""
    m = bernstein.shape[0]
    degree = bernstein.shape[1] - 1
    negative = bernstein < 0.0
    at = np.argmax(negative[:, 1:] != negative[:, :-1], axis=1)
    every = np.arange(m)
    left, right = bernstein[every, at], bernstein[every, at + 1]
    x = lo + width * (at + left / (left - right)) / degree
    hi = lo + width
    negative_lo = negative[:, 0]
    step = np.ones(m)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for _ in range(FAST_STEPS):
            value, slope = value_and_slope(columns, x)
            toward_hi = (value < 0.0) == negative_lo
            lo = np.where(toward_hi, x, lo)
            hi = np.where(toward_hi, hi, x)
            following = x - value / slope
            following = np.where((following >= lo) & (following <= hi), following, 0.5 * (lo + hi))
            step = np.where(value == 0.0, 0.0, x - following)
            x = x - step
    again = np.flatnonzero(~(np.abs(step) <= ROOT_TOL))
    if again.size:
        c = columns[:, again]
        x[again] = bracketed_root(c, lo[again], hi[again], horner(c.T, lo[again]), horner(c.T, hi[again]))
    return x


def _spline_walls(stock, table, rows, wall_index, c, a, b, low, high, top):
    """Breakpoint blocks of B-spline walls (module docstring): flat ellipses by their plan line, the others
    by the ellipse's implicit equation on each span near the arc; rows (P,) by row."""
    ap, bp = a[rows, :2], b[rows, :2]
    det = ap[:, 0] * bp[:, 1] - ap[:, 1] * bp[:, 0]
    major = np.maximum(np.hypot(ap[:, 0], ap[:, 1]), np.hypot(bp[:, 0], bp[:, 1]))
    with np.errstate(divide="ignore", invalid="ignore"):
        flat = ~(np.abs(det) / np.where(major > 0.0, major, 1.0) > FLAT)
    pairs, angles, spans, parameters = [], [], [], []
    for part, solve in ((np.flatnonzero(flat), _flat_spline_crossings),
                        (np.flatnonzero(~flat), _ellipse_spline_crossings)):
        if part.size:
            found, psi, span, u = solve(stock, rows[part], wall_index[part], c, a, b, low, high, top)
            pairs.append(part[found])
            angles.append(psi)
            spans.append(span)
            parameters.append(u)
    if not pairs:
        return []
    pair, psi = np.concatenate(pairs), np.concatenate(angles)
    span = np.concatenate(spans)
    u = np.concatenate(parameters)
    g = rows[pair]
    psi = _polished(stock.splines, span, u, psi, c[g, :2], a[g, :2], b[g, :2], top)
    order = np.argsort(pair, kind="stable")  # by row, as the pairs are
    pair, psi = pair[order], psi[order]
    return [(rows[pair], psi, _wall_label(table, wall_index[pair]), 0)]


def _polished(table, span, u, psi, cp, ap, bp, top):
    """The crossings ψ (E,) of arcs (plan C_p + A cos ψ + B sin ψ; cp, ap, bp (E, 2)) with B-spline spans
    `span` (E,) near u (E,), refined by Newton on C(u) = Q(ψ) (two equations, the span's point and the
    arc's plan point): POLISH_STEPS steps, kept where they converge (the last step in ψ below 1e-9, the
    whole move below 1e-6) to a point of the span (u within [0, 1] but for rounding) on the arc. The crossings as found (the implicit equation's root and the
    ellipse's angle of its point, or a plan line's crossing) lose digits where the ellipse is thin; this
    gives them back."""
    sx, sy, sw = table.spans_x[span], table.spans_y[span], table.spans_w[span]
    dx, dy, dw = (derivative(v) for v in (sx, sy, sw))
    x0, s0 = u.copy(), psi.copy()
    for _ in range(POLISH_STEPS):
        w = horner(sw, u)
        cx, cy = horner(sx, u) / w, horner(sy, u) / w
        wd = horner(dw, u)
        cx1, cy1 = (horner(dx, u) - cx * wd) / w, (horner(dy, u) - cy * wd) / w
        cos, sin = np.cos(psi), np.sin(psi)
        fx = cx - (cp[:, 0] + ap[:, 0] * cos + bp[:, 0] * sin)
        fy = cy - (cp[:, 1] + ap[:, 1] * cos + bp[:, 1] * sin)
        qx1, qy1 = bp[:, 0] * cos - ap[:, 0] * sin, bp[:, 1] * cos - ap[:, 1] * sin
        det = qx1 * cy1 - cx1 * qy1  # of [[cx1, −qx1], [cy1, −qy1]]
        with np.errstate(divide="ignore", invalid="ignore"):
            step = (cx1 * fy - cy1 * fx) / det
            u = u - (qx1 * fy - qy1 * fx) / det
            psi = psi - step
    with np.errstate(invalid="ignore"):
        good = ((np.abs(step) <= 1e-9) & (np.abs(u - x0) <= 1e-6) & (np.abs(psi - s0) <= 1e-6) & (u >= -1e-9)
                & (u <= 1.0 + 1e-9))
    return np.where(good, np.clip(psi, 0.0, top), s0)


def _flat_spline_crossings(stock, rows, wall_index, c, a, b, low, high, top):
    """(pair (E,), ψ (E,)) where arcs whose plan projection is a segment (traced once or back and forth)
    cross B-spline walls: the plan line through C_p along the longer of A, B, crossed by
    SplineTable.crossings within the segment, each crossing t giving up to two ψ of
    (A·e) cos ψ + (B·e) sin ψ = t."""
    ap, bp = a[rows, :2], b[rows, :2]
    size_a, size_b = np.hypot(ap[:, 0], ap[:, 1]), np.hypot(bp[:, 0], bp[:, 1])
    longer = np.where((size_a >= size_b)[:, None], ap, bp)
    size = np.maximum(size_a, size_b)
    moving = np.flatnonzero(size > 0.0)  # a point in plan crosses nothing
    e = longer[moving] / size[moving, None]
    along_a = (ap[moving] * e).sum(axis=1)
    along_b = (bp[moving] * e).sum(axis=1)
    zero = np.zeros(moving.size)
    t_lo, t_hi = _ranges(zero, along_a, along_b, top)
    g = rows[moving]
    roots = stock.splines.crossings(wall_index[moving], c[g, 0], c[g, 1], e[:, 0], e[:, 1], t_lo - MARGIN,
                                    t_hi + MARGIN)
    pairs, angles = [], []
    for k in range(roots.shape[1]):
        hit = np.flatnonzero(~np.isnan(roots[:, k]))
        psi = trig_roots(along_a[hit], along_b[hit], roots[hit, k], top)
        for slot in range(2):
            ok = ~np.isnan(psi[:, slot])
            pairs.append(moving[hit[ok]])
            angles.append(psi[ok, slot])
    if not pairs:
        return np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0, dtype=np.intp), np.zeros(0)
    pair, psi = np.concatenate(pairs), np.concatenate(angles)
    g = rows[pair]
    y = c[g, 1] + a[g, 1] * np.cos(psi) + b[g, 1] * np.sin(psi)
    return (pair, psi) + _spline_parameter(stock.splines, wall_index[pair], y)


def _span_run(table, wall_index, y_lo, y_hi):
    """Local indices (first, last) (P,) of the spans of B-spline walls wall_index (P,) over y from y_lo to
    y_hi (clipped to each curve's ends); last < first where the curve is not met."""
    y_first, y_last = table.y_first[wall_index], table.y_last[wall_index]
    key = table.slot[wall_index] * table.shift - table.base
    first_end = table.first_end[wall_index]
    first = table.key_search.search(np.clip(y_lo, y_first, y_last) + key, "left") - 1 - first_end
    last = table.key_search.search(np.clip(y_hi, y_first, y_last) + key, "right") - 1 - first_end
    first = np.maximum(first, 0)
    last = np.where((y_hi >= y_first) & (y_lo <= y_last), np.minimum(last, table.n_spans[wall_index] - 1), -1)
    return first, last


def _sinusoid_range(c, a, b, lo, hi):
    """(low, high) of c + a cos ψ + b sin ψ over ψ in [lo, hi] ⊂ [0, π/2] (all (P,)): ends and turning points."""
    values = [c + a * np.cos(lo) + b * np.sin(lo), c + a * np.cos(hi) + b * np.sin(hi)]
    amplitude, turn = np.sqrt(a * a + b * b), np.arctan2(b, a)
    low, high = np.minimum(*values), np.maximum(*values)
    high = np.where((turn >= lo) & (turn <= hi), np.maximum(high, c + amplitude), high)
    low = np.where((turn + np.pi >= lo) & (turn + np.pi <= hi), np.minimum(low, c - amplitude), low)
    return low, high


def _narrowed(table, wall_index, cp, ap, bp, top, y_lo, y_hi, rounds=2):
    """The arc's y range (y_lo, y_hi) (P,) where it may cross its B-spline wall, narrowed by strips: over the
    run of spans covering y_lo … y_hi, the curve lies within ±e (in x) of the chord between the run's end
    knots, e = (S_hi − m)(m − S_lo)·Δy/(S_hi − S_lo) for the run's bounds S_lo ≤ dx/dy ≤ S_hi
    (SplineTable's span slopes) and the chord's slope m. A crossing lies where x(ψ) − chord(y(ψ)), a sinusoid,
    is within ±e: between the least and greatest ψ of the arc there (closed form), whose y range is the new
    one. Returns y_lo, y_hi, and alive (P,) bool: False where the strip excludes every crossing."""
    alive = np.ones(wall_index.size, dtype=bool)
    for _ in range(rounds):
        first, last = _span_run(table, wall_index, y_lo, y_hi)
        alive &= last >= first
        span_first = table.first_span[wall_index] + first
        span_last = table.first_span[wall_index] + np.maximum(last, first)
        s_lo, s_hi = table._slopes(span_first, span_last)
        knot_a = table.first_end[wall_index] + first
        knot_b = table.first_end[wall_index] + np.maximum(last, first) + 1
        xa, ya, wa = table.knot_points[:, knot_a]
        xb, yb, wb = table.knot_points[:, knot_b]
        xa, ya, xb, yb = xa / wa, ya / wa, xb / wb, yb / wb
        with np.errstate(divide="ignore", invalid="ignore"):
            m = (xb - xa) / (yb - ya)
            e = np.where(s_hi > s_lo, (s_hi - m) * (m - s_lo) * (yb - ya) / (s_hi - s_lo), 0.0)
        e = np.abs(e) + MARGIN + 1e-12 * (np.abs(xa) + np.abs(xb))
        usable = np.isfinite(e) & np.isfinite(m)
        # f(ψ) = x(ψ) − chord(y(ψ)) = fc + fa cos ψ + fb sin ψ.
        m = np.where(usable, m, 0.0)
        fc = cp[:, 0] - xa - m * (cp[:, 1] - ya)
        fa, fb = ap[:, 0] - m * ap[:, 1], bp[:, 0] - m * bp[:, 1]
        ends = [np.zeros(fc.size), np.full(fc.size, top)]
        values = [fc + fa, fc + fa * np.cos(top) + fb * np.sin(top)]
        hull_lo, hull_hi = np.full(fc.size, np.inf), np.full(fc.size, -np.inf)
        for at, value in zip(ends, values):
            within = np.abs(value) <= e
            hull_lo = np.where(within, np.minimum(hull_lo, at), hull_lo)
            hull_hi = np.where(within, np.maximum(hull_hi, at), hull_hi)
        for edge in (-e, e):
            roots = trig_roots(fa, fb, edge - fc, top)
            hull_lo = np.fmin(hull_lo, np.nanmin(np.where(np.isnan(roots), np.inf, roots), axis=1))
            hull_hi = np.fmax(hull_hi, np.nanmax(np.where(np.isnan(roots), -np.inf, roots), axis=1))
        empty = usable & ~(hull_lo <= hull_hi)
        alive &= ~empty
        narrow = usable & ~empty
        lo = np.where(narrow, hull_lo, 0.0)
        hi = np.where(narrow, hull_hi, top)
        new_lo, new_hi = _sinusoid_range(cp[:, 1], ap[:, 1], bp[:, 1], lo, hi)
        y_lo = np.where(narrow, np.maximum(y_lo, new_lo - MARGIN), y_lo)
        y_hi = np.where(narrow, np.minimum(y_hi, new_hi + MARGIN), y_hi)
    return y_lo, y_hi, alive


def _ellipse_spline_crossings(stock, rows, wall_index, c, a, b, low, high, top):
    """(pair (E,), ψ (E,)) where arcs with a proper plan ellipse cross B-spline walls: per span of the wall
    over the arc's y range where it may cross (_narrowed) whose control box meets the arc's box, the sign
    changes of E(u) = |adj(M)(Q(u) − C_p)|² − det(M)² (times Ω² for a rational span), its end values those
    of the curve's knots; each crossing's ψ from its point, kept on the arc."""
    table = stock.splines
    x_lo, x_hi = low[rows, 0] - MARGIN, high[rows, 0] + MARGIN
    y_lo, y_hi, alive = _narrowed(table, wall_index, c[rows, :2], a[rows, :2], b[rows, :2], top,
                                  low[rows, 1] - MARGIN, high[rows, 1] + MARGIN)
    first, last = _span_run(table, wall_index, y_lo, y_hi)
    first_end = table.first_end[wall_index]
    count = np.where(alive, last - first + 1, 0).clip(0)
    pair = np.repeat(np.arange(rows.size), count)
    local = first[pair] + np.arange(pair.size) - np.repeat(np.cumsum(count) - count, count)
    span = table.first_span[wall_index[pair]] + local
    box = table.span_boxes[span]
    near = ((box[:, 0] <= x_hi[pair]) & (box[:, 1] >= x_lo[pair]) & (box[:, 2] <= y_hi[pair])
            & (box[:, 3] >= y_lo[pair]))
    pair, span, local = pair[near], span[near], local[near]
    if pair.size == 0:
        return np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0, dtype=np.intp), np.zeros(0)
    knot = first_end[pair] + local
    g = rows[pair]
    cp, ap, bp = c[g, :2], a[g, :2], b[g, :2]
    det = ap[:, 0] * bp[:, 1] - ap[:, 1] * bp[:, 0]

    sx, sy, sw = table.spans_x[span], table.spans_y[span], table.spans_w[span]
    degree = 2 * (sx.shape[1] - 1)
    column = (cp[:, 0:1], cp[:, 1:2], ap[:, 0:1], ap[:, 1:2], bp[:, 0:1], bp[:, 1:2], det[:, None])
    values = _implicit(sx, sy, sw, *column, product) @ _to_bernstein(degree)
    # The ends are the knots' values, the same for both spans that meet there.
    scalar = tuple(v[:, 0] for v in column)
    values[:, 0] = _implicit(*table.knot_points[:, knot], *scalar, np.multiply)
    values[:, -1] = _implicit(*table.knot_points[:, knot + 1], *scalar, np.multiply)
    mixed = np.flatnonzero((values >= 0.0).any(axis=1) & (values < 0.0).any(axis=1))
    if mixed.size == 0:
        return np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0, dtype=np.intp), np.zeros(0)
    scale = np.abs(values[mixed]).max(axis=1, keepdims=True)
    values = values[mixed] / scale
    found, lo, width, coefficients, deep, at, _ = _isolated(values)
    power = values @ _to_power(degree)
    u = _single_roots(np.ascontiguousarray(power[found].T), lo, width, coefficients)
    found, u = mixed[np.concatenate([found, deep])], np.concatenate([u, at])
    weight = horner(sw[found], u)
    q = np.column_stack([horner(sx[found], u) / weight, horner(sy[found], u) / weight])
    for end, at in ((0.0, knot[found]), (1.0, knot[found] + 1)):
        kx, ky, kw = table.knot_points[:, at]
        q = np.where((u == end)[:, None], np.column_stack([kx / kw, ky / kw]), q)
    psi = _ellipse_angle(q, cp[found], ap[found], bp[found], det[found])
    keep = (psi >= 0.0) & (psi <= top)
    return pair[found][keep], psi[keep], span[found][keep], u[keep]


def _implicit(x, y, weight, cx, cy, ax, ay, bx, by, det, times):
    """|adj(M)(Q − C_p·Ω)|² − det(M)²·Ω² of homogeneous plan points (x, y, Ω): polynomials (P, k) with
    times = polynomials.product and the arc's numbers as columns (P, 1), or values (P,) with np.multiply.
    adj(M) = [[B_y, −B_x], [−A_y, A_x]]."""
    rx, ry = x - cx * weight, y - cy * weight
    l1 = by * rx - bx * ry
    l2 = ax * ry - ay * rx
    return times(l1, l1) + times(l2, l2) - (det * det) * times(weight, weight)


def _sorted_breakpoints(n, blocks, top):
    """(ψ, packed) (n, K): each arc's breakpoints in increasing ψ, its start (ψ = 0, "flute_start") first and
    its end (ψ = top) last among equals, padded with +inf; packed = 4·label + delta + 1. blocks: (rows (E,)
    non-decreasing, ψ (E,), label (E,), section delta (E,) or 0)."""
    counts = np.full(n, 2, dtype=np.intp)
    for rows, *_ in blocks:
        counts += np.bincount(rows, minlength=n)
    width = int(counts.max())
    psi = np.full(n * width, np.inf)
    packed = np.full(n * width, 4 * _CODE["flute_start"] * _LABEL + 1, dtype=np.int32)
    first = np.arange(n) * width
    psi[first] = 0.0
    fill = first + 1
    for rows, angles, labels, delta in blocks:
        at = fill[rows]
        if rows.size > 1 and (rows[1:] == rows[:-1]).any():  # an arc more than once: its rank among them
            at += np.arange(rows.size) - np.searchsorted(rows, rows, side="left")
        psi[at] = angles
        packed[at] = 4 * labels + delta + 1
        fill += np.bincount(rows, minlength=n)
    psi[fill] = top
    packed[fill] = 4 * (CORNER_TOP if top >= 0.5 * np.pi else _CODE["flute_end"]) * _LABEL + 1
    psi, packed = psi.reshape(n, width), packed.reshape(n, width)
    # The start is first and the end last already: only arcs with two breakpoints or more between need sorting.
    rows = np.flatnonzero(counts > 3)
    if rows.size:
        part = psi[rows]
        order = np.argsort(part, axis=1, kind="stable")
        psi[rows] = np.take_along_axis(part, order, axis=1)
        packed[rows] = np.take_along_axis(packed[rows], order, axis=1)
    return psi, packed


def _runs(stock, table, rows, psi, packed, c, a, b, r, base, pair_rows, pair_walls):
    """Runs (module docstring, step 2) of the arcs whose sorted breakpoints are psi, packed (n, K); rows (n,)
    their row numbers in the result; base (n,): the section at each arc's start of the walls not evaluated
    (those wholly left of it and its quintics, whose changes the deltas give); pairs (P,) the walls to
    evaluate at each piece's middle (0-based). Returns _chunk's tuple."""
    n, width = psi.shape
    flat_psi = psi.reshape(-1)
    valid = (psi[:, 1:] > psi[:, :-1]) & (psi[:, 1:] < np.inf)
    piece = np.flatnonzero(valid)
    piece_row = piece // (width - 1)
    event = piece + piece_row  # the piece's first breakpoint in the (n, width) tables
    start, end = flat_psi.take(event), flat_psi.take(event + 1)
    middle = 0.5 * (start + end)
    cos, sin = np.cos(middle), np.sin(middle)
    x, y, z = (c[:, k].take(piece_row) + a[:, k].take(piece_row) * cos + b[:, k].take(piece_row) * sin
               for k in range(3))
    inside = ((x >= stock.x_min) & (x <= stock.x_max) & (y >= stock.y_min) & (y <= stock.y_max) & (z >= stock.base_z))
    delta = np.cumsum(packed % 4 - 1, axis=1, dtype=np.int32)
    section = base.take(piece_row) + delta.reshape(-1).take(event)
    if pair_rows.size:
        per_row = np.bincount(piece_row, minlength=n)
        first_piece = np.cumsum(per_row) - per_row
        count = per_row[pair_rows]
        pair = np.repeat(np.arange(pair_rows.size), count)
        at = first_piece[pair_rows][pair] + np.arange(pair.size) - np.repeat(np.cumsum(count) - count, count)
        needed = np.flatnonzero(inside[at])
        pair, at = pair[needed], at[needed]
        beyond = table.beyond(stock, pair_walls[pair], x[at], y[at])
        section = section + np.bincount(at[beyond], minlength=piece.size)
    section = np.minimum(section, stock.n_sections - 1)
    inside = np.flatnonzero(inside & (z <= stock.z_top.take(section)))
    if inside.size == 0:
        return tuple(np.zeros(0, dtype=float if k in (1, 2) else np.intp) for k in range(9))
    k_row, k_start, k_end = piece_row[inside], start[inside], end[inside]
    new = np.ones(inside.size, dtype=bool)
    new[1:] = (k_row[1:] != k_row[:-1]) | (r * (k_start[1:] - k_end[:-1]) > LENGTH_EPS)
    first = np.flatnonzero(new)
    last = np.append(first[1:], inside.size) - 1
    s0, s1 = r * k_start[first], r * k_end[last]
    keep = s1 - s0 > LENGTH_EPS
    first, last, s0, s1 = first[keep], last[keep], s0[keep], s1[keep]
    flat_packed = packed.reshape(-1)
    start_label = flat_packed.take(event[inside[first]]) // 4
    end_label = flat_packed.take(event[inside[last]] + 1) // 4
    start_code, end_code = start_label // _LABEL, end_label // _LABEL
    return (rows[k_row[first]], s0, s1, start_code, section[inside[first]], start_label - start_code * _LABEL - 1,
            end_code, section[inside[last]], end_label - end_code * _LABEL - 1)
