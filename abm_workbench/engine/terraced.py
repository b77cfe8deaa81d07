"""Cutting-edge lines against a general 2.5D terraced stock, exactly, slab by slab.

A line is origin + l·direction for 0 ≤ l ≤ L (mm). For slab k the part of it with
z_bottom ≤ z ≤ z_top is an interval of l; over it the line's plan projection is intersected
with the slab's region:

* The side of the plan line a point P lies on is s(P) = u × (P − o) (u the unit plan
  direction, o the plan origin): positive on the left. On a rational Bézier piece of degree d,
  s·w is a polynomial whose Bernstein coefficients are w_i·s(Q_i) (Q_i, w_i its control points
  and weights), so a piece whose control points all lie on one side (s ≥ 0 counts as the left
  side, s < 0 as the right one) never changes side; the others are solved: degree 1 in closed
  form, degree 2 (arcs, quadratic splines) by the quadratic formula, higher degrees by root
  isolation on derivatives (``polynomials.real_roots_unit``), with the side between roots
  decided at the midpoint of each interval between consecutive roots.
* Every change of side along a loop is a crossing of the plan line by the boundary. The
  crossings of all loops of the slab, sorted along the line, alternate outside → inside →
  outside (the even-odd rule with the half-open sides above): inside runs are [e0, e1],
  [e2, e3], … This is exact ray casting along the line itself, so a line through a joint of
  two curves, a line tangent to a curve and a line along a straight wall all come out
  consistently: a tangent contact is two crossings at one place (nothing inside); a line
  running along a boundary counts as inside exactly when the material lies on its right,
  seen from above looking along the line.
* A vertical line (plan direction below ``PARALLEL_EPS``) is inside a slab's region when a
  ray from its plan point along +x crosses the boundary an odd number of times (the same
  crossing machinery), and then inside over the whole slab.
* A horizontal line lying exactly on a level between two slabs belongs to the upper slab
  (the top slab keeps its top level).

The inside runs of all slabs are sorted along each line; runs that touch (gap ≤
``LENGTH_EPS``) are merged across slab levels, and runs no longer than ``LENGTH_EPS`` dropped.

Labels of an interval end (``EdgeIntervals``): surface "straight_wall" (a PlanLine),
"curved_wall" (a PlanArc or PlanSpline), "top" (a horizontal face facing up: the slab's top
where the material ends), "bottom" (a face facing down, or the base), "flute_end" (the edge's
end at l = L inside the material), "flute_start" (its start at l = 0 inside the material);
section = the slab holding the material at that end; wall = the flat curve index
(``terraced_pieces.curve_list``) for walls, −1 otherwise.
"""

import dataclasses

import numpy as np

from .engagement import SURFACES, edge_lines
from .interval_engagement import engagement_from_intervals
from .intervals import EdgeIntervals
from .arguments import check_arguments
from .ordering import group_order
from .polynomials import horner, real_roots_unit
from .terraced_pieces import bernstein_to_power, slab_pieces
from .tolerances import LENGTH_EPS, PARALLEL_EPS

_CODE = {name: SURFACES.index(name) for name in ("top", "straight_wall", "curved_wall", "flute_end",
                                                    "bottom", "flute_start")}
#: Bound on lines × pieces held at once when testing lines against a slab's pieces.
CHUNK_VALUES = 1 << 21


def terraced_intervals(stock, origins, directions, length):
    """Inside intervals of N lines origins + l·directions, 0 ≤ l ≤ length (mm), in `stock`.

    origins, directions: (N, 3) mm and unit vectors. Returns EdgeIntervals with the labels of
    the module docstring.
    """
    return _intervals(slab_pieces(stock), stock, origins, directions, length)


def _intervals(pieces, stock, origins, directions, length):
    """terraced_intervals with the pieces of slab_pieces(stock) given."""
    groups, straight = pieces
    o = np.asarray(origins, dtype=float).reshape(-1, 3)
    d = np.asarray(directions, dtype=float).reshape(-1, 3)
    if o.shape != d.shape:
        raise ValueError(f"origins and directions must both be (N, 3), got {o.shape} and {d.shape}")
    n, length = o.shape[0], float(length)
    plan = np.hypot(d[:, 0], d[:, 1])
    vertical = plan <= PARALLEL_EPS
    # The plan line of each row: origin, unit direction, and the factor from its own parameter
    # to l (a vertical line gets the ray along +x from its plan point).
    ux = np.where(vertical, 1.0, d[:, 0] / np.where(vertical, 1.0, plan))
    uy = np.where(vertical, 0.0, d[:, 1] / np.where(vertical, 1.0, plan))
    scale = np.where(vertical, 1.0, plan)
    wall_code = np.where(straight, _CODE["straight_wall"], _CODE["curved_wall"])
    found = []
    top_slab = len(stock.slabs) - 1
    for k, slab in enumerate(stock.slabs):
        lo, hi, lo_code, hi_code = _slab_range(o[:, 2], d[:, 2], slab.z_bottom, slab.z_top, length, k == top_slab)
        rows = np.flatnonzero(hi > lo)
        if rows.size == 0:
            continue
        ev_row, ev_at, ev_wall = plan_crossings(groups[k], o[rows, 0], o[rows, 1], ux[rows], uy[rows])
        ev_l = ev_at / scale[rows][ev_row]
        order = group_order(ev_l, ev_row)
        ev_row, ev_l, ev_wall = ev_row[order], ev_l[order], ev_wall[order]
        # Vertical rows: inside when an odd number of crossings lie ahead on the +x ray.
        is_vertical = vertical[rows]
        ahead = np.bincount(ev_row[ev_l > 0.0], minlength=rows.size)
        whole = is_vertical & (ahead % 2 == 1)
        wr = rows[whole]
        runs = [(wr, lo[wr], hi[wr], lo_code[wr], np.full(wr.size, -1), hi_code[wr], np.full(wr.size, -1))]
        # Sloping rows: crossings pair up into inside runs of the plan line, clipped to the slab.
        keep = ~is_vertical[ev_row]
        r, at, wall = rows[ev_row[keep]], ev_l[keep], ev_wall[keep]
        r0, r1, a0, a1, w0, w1 = r[0::2], r[1::2], at[0::2], at[1::2], wall[0::2], wall[1::2]
        if not np.array_equal(r0, r1):
            raise ArithmeticError(f"slab {k}: an odd number of boundary crossings on a line")
        start, end = np.maximum(a0, lo[r0]), np.minimum(a1, hi[r0])
        real = end > start
        r0, start, end, a0, a1, w0, w1 = (v[real] for v in (r0, start, end, a0, a1, w0, w1))
        from_wall0, from_wall1 = a0 >= lo[r0], a1 <= hi[r0]
        runs.append((r0, start, end,
                     np.where(from_wall0, wall_code[w0], lo_code[r0]), np.where(from_wall0, w0, -1),
                     np.where(from_wall1, wall_code[w1], hi_code[r0]), np.where(from_wall1, w1, -1)))
        for run in runs:
            found.append(run + (np.full(run[0].size, k),))
    return merged_intervals(n, found)


def _slab_range(z0, dz, z_bottom, z_top, length, is_top):
    """Part [lo, hi] (N,) of each line within z_bottom ≤ z ≤ z_top and 0 ≤ l ≤ length, and the
    surface code of what bounds it at each end (bottom/top level or the flute's ends).
    Empty ranges have hi ≤ lo."""
    flat = np.abs(dz) <= PARALLEL_EPS
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        at_bottom, at_top = (z_bottom - z0) / dz, (z_top - z0) / dz
    rising = dz > 0.0
    within = (z0 >= z_bottom) & ((z0 <= z_top) if is_top else (z0 < z_top))
    enter = np.where(flat, np.where(within, -np.inf, np.inf), np.where(rising, at_bottom, at_top))
    leave = np.where(flat, np.where(within, np.inf, -np.inf), np.where(rising, at_top, at_bottom))
    lo, hi = np.maximum(enter, 0.0), np.minimum(leave, length)
    lo_code = np.where(enter > 0.0, np.where(rising, _CODE["bottom"], _CODE["top"]), _CODE["flute_start"])
    hi_code = np.where(leave < length, np.where(rising, _CODE["top"], _CODE["bottom"]), _CODE["flute_end"])
    return lo, hi, lo_code, hi_code


def plan_crossings(groups, ox, oy, ux, uy, changes=None):
    """Every crossing of the slab's boundary with the plan lines o + t·u (n lines, u unit).

    Returns rows (E,), t (E,) the crossing's parameter along its line (mm), wall (E,) the
    flat curve index; per line an even number (loops are closed). changes: side_changes or a
    function of the same arguments and result that finds them (None: side_changes).
    """
    changes = side_changes if changes is None else changes
    rows, ts, walls = [], [], []
    for group in groups:
        d = group.degree
        per = max(1, CHUNK_VALUES // max(1, group.control.shape[0]))
        # Rounding bound of a side value: a piece whose circle lies farther than this beyond
        # the line has every control point on one side however the values round.
        margin = 1e-9 + 1e-12 * (np.abs(group.centre).sum(axis=1) + group.radius)
        for first in range(0, ox.size, per):
            sl = slice(first, first + per)
            near = np.abs(ux[sl, None] * (group.centre[:, 1] - oy[sl, None])
                          - uy[sl, None] * (group.centre[:, 0] - ox[sl, None]))
            near = near <= group.radius + margin + 1e-12 * (np.abs(ox[sl]) + np.abs(oy[sl]))[:, None]
            line, piece = np.nonzero(near)
            if line.size == 0:
                continue
            qx, qy = group.control[piece, :, 0], group.control[piece, :, 1]
            lx, ly, lux, luy = ox[sl][line, None], oy[sl][line, None], ux[sl][line, None], uy[sl][line, None]
            side = lux * (qy - ly) - luy * (qx - lx)
            count = (side >= 0.0).sum(axis=1)
            mixed = (count > 0) & (count < d + 1)
            line, piece, side = line[mixed], piece[mixed], side[mixed]
            if line.size == 0:
                continue
            r, u = changes(d, side * group.weights[piece])
            point = horner(np.moveaxis(group.homogeneous[piece[r]], 1, -1), u[:, None])
            px, py = point[:, 0] / point[:, 2], point[:, 1] / point[:, 2]
            # Changes at a piece's ends are at its exact end control points.
            at_start, at_end = u == 0.0, u == 1.0
            px = np.where(at_start, group.control[piece[r], 0, 0], np.where(at_end, group.control[piece[r], d, 0], px))
            py = np.where(at_start, group.control[piece[r], 0, 1], np.where(at_end, group.control[piece[r], d, 1], py))
            g = line[r] + first
            rows.append(g)
            ts.append(ux[g] * (px - ox[g]) + uy[g] * (py - oy[g]))
            walls.append(group.wall[piece[r]])
    if not rows:
        return np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0, dtype=np.intp)
    return np.concatenate(rows), np.concatenate(ts), np.concatenate(walls)


def side_changes(degree, b):
    """Where the side (s·w ≥ 0 or < 0) changes along M pieces with Bernstein coefficients b
    (M, d+1) of s·w on u ∈ [0, 1]: (pair index (C,), u (C,)), one entry per change.

    The side at u = 0 and u = 1 is that of the end coefficients (the joints); at a root it is
    "≥ 0"; between consecutive roots that of the midpoint.
    """
    first, last = b[:, 0] >= 0.0, b[:, -1] >= 0.0
    if degree == 1:
        with np.errstate(divide="ignore", invalid="ignore"):
            u = np.clip(b[:, 0] / (b[:, 0] - b[:, 1]), 0.0, 1.0)
        return np.arange(b.shape[0]), u  # only pieces whose ends differ come here
    power = b @ bernstein_to_power(degree).T
    roots = real_roots_unit(power)  # (M, d) ascending, NaN-padded
    valid = ~np.isnan(roots)
    filled = np.where(valid, roots, 1.0)
    bounds = np.concatenate([np.zeros((b.shape[0], 1)), filled, np.ones((b.shape[0], 1))], axis=1)
    mids = 0.5 * (bounds[:, :-1] + bounds[:, 1:])
    between = horner(power[:, None, :], mids) >= 0.0  # (M, d+1): side on each interval
    # Sequence of sides: start, interval 0, root 1, interval 1, …, root d, interval d, end;
    # a padding root and the interval after it repeat the interval before.
    m = b.shape[0]
    sequence = [first, between[:, 0]]
    places = [np.zeros(m), np.zeros(m)]
    current = between[:, 0]
    for j in range(roots.shape[1]):
        root_side = np.where(valid[:, j], True, current)
        current = np.where(valid[:, j], between[:, j + 1], current)
        sequence += [root_side, current]
        places += [filled[:, j], filled[:, j]]
    sequence.append(last)
    places.append(np.ones(m))
    sides = np.stack(sequence, axis=1)
    where = np.stack(places, axis=1)
    pair, step = np.nonzero(sides[:, 1:] != sides[:, :-1])
    return pair, where[pair, step + 1]


def merged_intervals(n, found):
    """EdgeIntervals of n rows from runs (rows, start, end, start surface, start wall, end
    surface, end wall, slab) of all slabs: sorted, touching runs merged, tiny ones dropped."""
    if found:
        parts = [np.concatenate(v) for v in zip(*found)]
    else:
        parts = [np.zeros(0, dtype=np.intp)] + [np.zeros(0)] * 2 + [np.zeros(0, dtype=np.intp)] * 5
    rows, start, end, s_surf, s_wall, e_surf, e_wall, slab = parts
    order = group_order(start, rows)
    rows, start, end, s_surf, s_wall, e_surf, e_wall, slab = (
        v[order] for v in (rows, start, end, s_surf, s_wall, e_surf, e_wall, slab))
    joins = np.zeros(rows.size, dtype=bool)
    joins[1:] = (rows[1:] == rows[:-1]) & (start[1:] - end[:-1] <= LENGTH_EPS)
    first = np.flatnonzero(~joins)
    last = np.append(first[1:], rows.size)[: first.size] - 1
    keep = end[last] - start[first] > LENGTH_EPS
    first, last = first[keep], last[keep]
    return EdgeIntervals(
        n_rows=n, rows=rows[first], start=start[first], end=end[last],
        start_surface=s_surf[first].astype(np.int8), start_section=slab[first].astype(np.int32),
        start_wall=s_wall[first].astype(np.int32), end_surface=e_surf[last].astype(np.int8),
        end_section=slab[last].astype(np.int32), end_wall=e_wall[last].astype(np.int32),
    )


def engage_terraced(stock, tool, toolpath, settings, *, chunk_instants=1 << 15, progress=None):
    """Cut geometry of every CL point × every rotation angle of settings.phi on a TerracedStock.

    The edge lines are those of engagement.edge_lines (the staircase engine's); work goes in
    chunks of CL points of about `chunk_instants` instants; `progress(done, total)` is called
    after each chunk, if given. Returns an Engagement with the LEP labels filled (see
    interval_engagement.engagement_from_intervals and this module's labels). A helical tool is refused.
    """
    check_arguments(stock=stock, tool=tool, toolpath=toolpath, settings=settings)
    if tool.helix != 0.0:
        raise ValueError(f"engage_terraced is for straight edges; the tool has a helix angle of {tool.helix} deg")
    pieces = slab_pieces(stock)
    phi = settings.phi
    m, p = len(toolpath), phi.size
    base, direction = edge_lines(toolpath, tool, phi)
    origins = base.reshape(-1, 3)
    directions = np.repeat(direction, p, axis=0)
    step = max(1, int(chunk_instants) // max(p, 1)) * p
    parts = []
    for start in range(0, m * p, step):
        stop = min(m * p, start + step)
        chunk = _intervals(pieces, stock, origins[start:stop], directions[start:stop], tool.flute_length)
        parts.append(dataclasses.replace(chunk, n_rows=m * p, rows=chunk.rows + start))
        if progress is not None:
            progress(stop // p, m)
    whole = EdgeIntervals(m * p, *(np.concatenate([getattr(part, name) for part in parts])
                                   for name in ("rows", "start", "end", "start_surface", "start_section", "start_wall",
                                                "end_surface", "end_section", "end_wall")))
    return engagement_from_intervals(whole, toolpath, tool, settings, origins, directions)
