"""Engagement of a flat-end mill's side cutting edge with staircase stock, for a whole pass.

For every CL point i and rotation angle φ_k the edge is the segment
S(l) = T_i + R_i·(R_t sin φ_k, R_t cos φ_k, l), 0 ≤ l ≤ L (notes §2). It is clipped to the
stock's bounding box, cut at every crossing with the section tops (Z-cylindrical), the
straight walls (X-cylindrical) and the curved walls (curve boundary, real roots of the
composed quintic), and each piece between crossings is classified by the height field at its
midpoint (notes §5). LEP is the start of the first inside piece, UEP the end of the last, and
the length of cut the total inside length. All instants of a chunk of CL points are solved in
one set of array operations, exact (B-spline) walls included (Staircase.splines stacks them).

Lengths are in mm, φ in degrees at the interface.
"""

from dataclasses import dataclass
from functools import reduce

import numpy as np

from .allocator import keep_freed_memory
from .arguments import check_arguments
from .model import CutSettings, Staircase, Tool, Toolpath
from .ordering import group_order
from .polynomials import compose_columns, horner, monotone_root_unit, proved_monotone_unit, real_roots_unit
from .rows import row_any, row_count, row_sum
from .intervals import EdgeIntervals
from .tolerances import LENGTH_EPS, PARALLEL_EPS
from .walls import Wall

#: Names of the surfaces that can hold the UEP; results store indices into this tuple.
#: "immersion_end" only comes from helix.flute_engagement with an immersion range; "bottom" (a
#: face facing down, or the base) and "flute_start" (the edge's start inside the material) only
#: label LEPs, from terraced.terraced_intervals; "machined" only comes from
#: inprocess.inprocess_intervals (an end cut by an earlier move).
SURFACES = ("none", "top", "straight_wall", "curved_wall", "flute_end", "stock_side", "immersion_end", "bottom",
            "flute_start", "machined")
#: Names of the Table 1 cases; results store indices into this tuple.
#: "2.5D": an engaged instant on a terraced stock (terraced.engage_terraced), where Table 1 does not apply;
#: "corner": an engaged instant of a tool with a corner radius (profile.profile_engagement), Table 1 being
#: for flat-end mills.
CASES = ("none", "A.1", "A.2", "A.3", "A.4", "B.1", "B.2", "B.3", "B.4", "B.5", "B.6", "multi", "2.5D", "corner")

_NONE, _TOP, _STRAIGHT, _CURVED, _FLUTE_END, _SIDE = range(6)
_CASE = {name: i for i, name in enumerate(CASES)}


@dataclass(frozen=True)
class Engagement:
    """Cut geometry of a pass: m CL points × p rotation angles.

    phi: (p,) rotation angles (deg). Per instant, (m, p): h, the cut thickness f·sin φ·cos α (mm, 0
    where sin φ < 0; α the inclination of the CL point's move, Toolpath.inclinations), lep_l, uep_l (mm along the edge, NaN without engagement),
    length (total inside length, mm), pieces (inside runs), uep_surface (index into SURFACES),
    uep_section (section whose material holds the UEP, −1 none), uep_wall (wall index j of the
    UEP's wall, 0 and n for the x limits, −1 otherwise), case (index into CASES),
    segment (engagement segment 0 = A, 1 = B, … per CL point, −1 without engagement),
    area (length·h, mm²); lep_xyz, uep_xyz: (m, p, 3) (mm, NaN without engagement).
    Per CL point, (m,): depth_of_cut (z span from lowest LEP to highest UEP, NaN if none).
    Optional, (m, p): lep_surface, lep_section, lep_wall, the LEP's labels as uep_surface,
    uep_section and uep_wall give the UEP's; an engine that does not label the LEP leaves them
    out (None), and they are then "none" (0) and −1 everywhere. end_length: the engaged length of
    the end cutting edge (mm, profile.end_lengths), NaN where an engine does not compute it.
    """

    phi: np.ndarray
    h: np.ndarray
    lep_l: np.ndarray
    uep_l: np.ndarray
    length: np.ndarray
    pieces: np.ndarray
    uep_surface: np.ndarray
    uep_section: np.ndarray
    uep_wall: np.ndarray
    case: np.ndarray
    segment: np.ndarray
    area: np.ndarray
    lep_xyz: np.ndarray
    uep_xyz: np.ndarray
    depth_of_cut: np.ndarray
    lep_surface: np.ndarray = None
    lep_section: np.ndarray = None
    lep_wall: np.ndarray = None
    end_length: np.ndarray = None

    def __post_init__(self):
        for name, fill, dtype in (("lep_surface", _NONE, np.int8), ("lep_section", -1, np.int32),
                                  ("lep_wall", -1, np.int32), ("end_length", np.nan, float)):
            if getattr(self, name) is None:
                object.__setattr__(self, name, np.full(np.shape(self.length), fill, dtype=dtype))

    @property
    def shape(self):
        """(m, p): CL points × rotation angles."""
        return self.length.shape

    @property
    def engaged(self):
        """(m, p) bool: the edge is in the stock at this instant."""
        return self.length > 0.0

    def surface_names(self):
        """(m, p) str array of UEP surface names."""
        return np.asarray(SURFACES)[self.uep_surface]

    def case_names(self):
        """(m, p) str array of Table 1 case names."""
        return np.asarray(CASES)[self.case]

    def segments(self, cl):
        """Engagement segments of CL point `cl`, in φ order.

        Returns a list of dicts: letter, phi_start, phi_end (deg), surface, section, wall, and
        the mean and max length of cut (mm) over the segment.
        """
        table = self.segment_table(cl, cl + 1)
        return [
            {
                "letter": segment_letter(table["index"][i]),
                "phi_start": float(table["phi_start"][i]), "phi_end": float(table["phi_end"][i]),
                "surface": SURFACES[table["surface"][i]], "section": int(table["section"][i]),
                "wall": int(table["wall"][i]), "mean_length": float(table["mean_length"][i]),
                "max_length": float(table["max_length"][i]),
            }
            for i in range(table["cl"].size)
        ]

    def segment_table(self, start=0, stop=None):
        """The engagement segments of CL points start … stop − 1 (default: all), in pass order
        then φ order, as arrays (S,): cl, index (0 = segment A), phi_start, phi_end (deg),
        surface (index into SURFACES), section, wall, mean_length and max_length (mm, over the
        segment's instants; a segment's numbers depend on its own instants alone).
        """
        segment = self.segment[start:stop].reshape(-1)
        p = self.segment.shape[1]
        flat = np.flatnonzero(segment >= 0)  # engaged instants, each segment a run of them
        cl = flat // p
        key = cl * (p + 1) + segment[flat]
        first = np.flatnonzero(np.concatenate([[True], key[1:] != key[:-1]])[: flat.size])
        last = np.append(first[1:], flat.size)[: first.size] - 1
        length = self.length[start:stop].reshape(-1)[flat]
        at = flat[first]
        sums = np.add.reduceat(length, first) if first.size else np.zeros(0)
        peaks = np.maximum.reduceat(length, first) if first.size else np.zeros(0)
        return {
            "cl": cl[first] + start, "index": segment[at], "phi_start": self.phi[at % p],
            "phi_end": self.phi[flat[last] % p],
            **{name: getattr(self, f"uep_{name}")[start:stop].reshape(-1)[at] for name in ("surface", "section", "wall")},
            "mean_length": sums / (last - first + 1), "max_length": peaks,
        }


def segment_letter(index):
    """0 -> 'A', 25 -> 'Z', 26 -> 'AA', … (spreadsheet-column style)."""
    letters = ""
    index = int(index) + 1
    while index:
        index, rest = divmod(index - 1, 26)
        letters = chr(ord("A") + rest) + letters
    return letters


def cut_thickness(phi_deg, feed_per_tooth, inclination_deg):
    """h = f·sin φ·cos α (mm) for φ (p,) in degrees and inclinations α in degrees, a number (-> (p,))
    or one per CL point (m,) (-> (m, p)); 0 where sin φ < 0 (the flute is not cutting)."""
    inclination = np.asarray(inclination_deg, dtype=float)
    scale = np.cos(np.radians(inclination))[..., None] if inclination.ndim else np.cos(np.radians(inclination))
    h = feed_per_tooth * np.sin(np.radians(phi_deg)) * scale
    return np.maximum(h, 0.0)


def edge_lines(toolpath, tool, phi_deg):
    """Base points (m, p, 3) at l = 0 and unit directions (m, 3) of the cutting edge lines (mm)."""
    rot = toolpath.frames()
    phi = np.radians(np.asarray(phi_deg, dtype=float))
    radial = np.sin(phi)[None, :, None] * rot[:, None, :, 0] + np.cos(phi)[None, :, None] * rot[:, None, :, 1]
    return toolpath.cl[:, None, :] + tool.radius * radial, rot[:, :, 2]


def engage(stock: Staircase, tool: Tool, toolpath: Toolpath, settings: CutSettings, *, chunk_instants=1 << 15,
           progress=None):
    """Cut geometry of every CL point × every rotation angle of `settings.phi`.

    Work is done in chunks of CL points holding about `chunk_instants` instants each, so
    memory stays bounded. `progress(done, total)` is called after each chunk, if given.
    Freed memory is kept for reuse, process-wide (allocator.keep_freed_memory). Returns an
    Engagement. A helical tool (tool.helix ≠ 0) is refused: use helix.flute_engagement.
    """
    check_arguments(stock=stock, tool=tool, toolpath=toolpath, settings=settings)
    if tool.helix != 0.0:
        raise ValueError(f"engage is for straight edges; the tool has a helix angle of {tool.helix} deg: "
                         "use flute_engagement")
    keep_freed_memory()
    phi = settings.phi
    m, p = len(toolpath), phi.size
    out, lep_xyz, uep_xyz = empty_results(m, p)
    step = max(1, int(chunk_instants) // max(p, 1))
    for start in range(0, m, step):
        stop = min(m, start + step)
        base, direction = edge_lines(_slice(toolpath, start, stop), tool, phi)
        n_cl = stop - start
        chunk = _solve_lines(stock, tool.flute_length, *_edge_components(base, direction))
        for name in out:
            out[name][start:stop] = chunk[name].reshape(n_cl, p)
        lep_xyz[start:stop] = (base + chunk["lep_l"].reshape(n_cl, p, 1) * direction[:, None, :])
        uep_xyz[start:stop] = (base + chunk["uep_l"].reshape(n_cl, p, 1) * direction[:, None, :])
        if progress is not None:
            progress(stop, m)
    return finished_engagement(phi, settings, out, lep_xyz, uep_xyz, toolpath.inclinations(settings))


def _edge_components(base, direction):
    """x0, y0, z0, dx, dy, dz: the N = m·p edge lines of base points (m, p, 3) and directions
    (m, 3) (edge_lines), each component one contiguous (N,) array, lines by CL point then φ.

    Contiguous, because every later step does arithmetic on them: on a column of an (N, 3)
    array (a stride of 3) numpy's element-wise operations take several times as long.
    """
    x0, y0, z0 = np.ascontiguousarray(np.moveaxis(base, -1, 0).reshape(3, -1))
    dx, dy, dz = np.repeat(direction.T, base.shape[1], axis=1)
    return x0, y0, z0, dx, dy, dz


def finished_engagement(phi, settings, out, lep_xyz, uep_xyz, inclination, *, axial=None, end_length=None):
    """The Engagement of filled per-instant arrays (as empty_results made them): cut thickness (with
    `inclination` (m,) deg, each CL point's), area, depth of cut per CL point and engagement segments
    derived from them. axial: (m, p) the engaged edge's extent along the axis (mm) where it differs from
    its length (a corner, profile.py), for the area; end_length (m, p) mm or None (not computed)."""
    h = cut_thickness(phi, settings.feed_per_tooth, inclination)
    engaged = out["length"] > 0.0
    with np.errstate(invalid="ignore"):
        top = np.where(engaged, uep_xyz[..., 2], -np.inf).max(axis=1)
        bottom = np.where(engaged, lep_xyz[..., 2], np.inf).min(axis=1)
    depth = np.where(engaged.any(axis=1), top - bottom, np.nan)
    return Engagement(
        phi=phi, h=h, area=(out["length"] if axial is None else axial) * h, lep_xyz=lep_xyz, uep_xyz=uep_xyz,
        depth_of_cut=depth, segment=_segments(engaged, out["uep_surface"], out["uep_section"], out["uep_wall"]),
        end_length=end_length, **out,
    )


def empty_results(m, p):
    """Per-instant result arrays of an Engagement before any is solved, for m CL points × p
    angles: ({lep_l, uep_l, length, pieces, uep_surface, uep_section, uep_wall, case: (m, p)},
    lep_xyz (m, p, 3), uep_xyz (m, p, 3)), all "no engagement"."""
    out = {
        name: np.full((m, p), fill, dtype=dtype)
        for name, fill, dtype in (
            ("lep_l", np.nan, float), ("uep_l", np.nan, float), ("length", 0.0, float),
            ("pieces", 0, np.int32), ("uep_surface", _NONE, np.int8), ("uep_section", -1, np.int32),
            ("uep_wall", -1, np.int32), ("case", 0, np.int8),
        )
    }
    return out, np.full((m, p, 3), np.nan), np.full((m, p, 3), np.nan)


def _slice(toolpath, start, stop):
    """CL points start:stop of a toolpath, without re-validating them."""
    part = object.__new__(Toolpath)
    for name in ("cl", "theta_a", "theta_b", "alpha"):
        object.__setattr__(part, name, getattr(toolpath, name)[start:stop])
    object.__setattr__(part, "cc", None)
    object.__setattr__(part, "inclination", None if toolpath.inclination is None else
                       toolpath.inclination[start:stop])
    return part


def _clip(stock, length, x0, y0, z0, dx, dy, dz, start_labels=False):
    """Part [lo, hi] of each edge line inside the stock's bounding box, and what bounds it at hi.

    Returns lo, hi (N,) in mm along the edge, and at hi the surface (index into SURFACES:
    flute end, x-limit wall, y-limit side, top) and wall index (0 or n at the x limits, −1
    otherwise). The edge rises (dz > 0), so the base can only bound it at lo. With
    `start_labels`, also the surface and wall at lo: flute end (the bottom of the edge, l = 0),
    x-limit wall, or stock side (a y limit or the base).
    """
    n = x0.size
    lo, hi = np.zeros(n), np.full(n, float(length))
    hi_surface = np.full(n, _FLUTE_END)
    hi_wall = np.full(n, -1)
    lo_surface, lo_wall = np.full(n, _FLUTE_END), np.full(n, -1)
    limits = (
        (x0, dx, stock.x_min, stock.x_max, _STRAIGHT, (0, stock.n_sections), _STRAIGHT),
        (y0, dy, stock.y_min, stock.y_max, _SIDE, (-1, -1), _SIDE),
        (z0, dz, stock.base_z, float(stock.z_top.max()), _TOP, (-1, -1), _SIDE),
    )
    for start, slope, low, high, surface, (wall_low, wall_high), enter_surface in limits:
        flat = np.abs(slope) <= PARALLEL_EPS
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            at_low, at_high = (low - start) / slope, (high - start) / slope
        rising = slope > 0.0
        enter = np.where(flat, np.where((start >= low) & (start <= high), -np.inf, np.inf),
                         np.where(rising, at_low, at_high))
        leave = np.where(flat, np.inf, np.where(rising, at_high, at_low))
        if start_labels:
            later = enter > lo
            lo_surface = np.where(later, enter_surface, lo_surface)
            lo_wall = np.where(later, np.where(rising, wall_low, wall_high), lo_wall)
        lo = np.maximum(lo, enter)
        sooner = leave < hi
        hi = np.where(sooner, leave, hi)
        hi_surface = np.where(sooner, surface, hi_surface)
        hi_wall = np.where(sooner, np.where(rising, wall_high, wall_low), hi_wall)
    if start_labels:
        return lo, hi, hi_surface, hi_wall, lo_surface, lo_wall
    return lo, hi, hi_surface, hi_wall


def _reachable_walls(stock, live, seg_min, seg_max, y_a, y_b):
    """Which walls each clipped edge segment can cross, and how many lie wholly left of it.

    seg_min, seg_max: (N,) x range of each segment, y_a, y_b: (N,) y at its ends. The walls
    are ordered along +x, so the ones whose x range over the window meets the segment's are a
    run of indices, found by bisection; each is then kept only if its x range over the
    segment's y bins still meets it. Returns the pairs rows, walls (P,) (by row, then wall),
    left_of (N,) and steepness (P,): the wall's max |dx/dy| over the segment's y range.
    """
    first = np.searchsorted(stock.bands.reach_high, seg_min, side="left")
    count = np.where(live, np.searchsorted(stock.bands.reach_low, seg_max, side="right") - first, 0).clip(0)
    rows = np.repeat(np.arange(seg_min.size), count)
    walls = first[rows] + (np.arange(rows.size) - np.repeat(np.cumsum(count) - count, count))
    low, high, slope = stock.bands.query(y_a[rows], y_b[rows], walls)
    beyond = seg_min[rows] > high
    keep = ~beyond & (seg_max[rows] >= low)
    left_of = first + np.bincount(rows[beyond], minlength=seg_min.size)
    return rows[keep], walls[keep], left_of, slope[keep]


def _uep_surface(stock, column, hi_surface, hi_wall, blocks):
    """Surface (index into SURFACES) and wall index of the breakpoint in `column` (N,) of each line.

    Columns: 0 the clipped start, 1 the clipped end (surface hi_surface, wall hi_wall), then
    the tops, then the wall-crossing blocks (first column, columns per wall, wall ids (N, k)).
    """
    rows = np.arange(column.size)
    wall = np.where(column == 1, hi_wall, -1)
    for first, per_wall, ids in blocks:
        within = (column >= first) & (column < first + per_wall * ids.shape[1])
        slot = np.clip((column - first) // per_wall, 0, ids.shape[1] - 1)
        wall = np.where(within, ids[rows, slot], wall)
    straight = np.array([True] + [w.is_straight for w in stock.walls] + [True])  # walls 0..n
    surface = np.where(column == 1, hi_surface, _TOP)
    is_wall = (wall > 0) & (column != 1)
    return np.where(is_wall, np.where(straight[np.maximum(wall, 0)], _STRAIGHT, _CURVED), surface), wall


def _quintic_table(stock, walls):
    """Coefficients (6, P) as columns, y_mid (P,) and y_half (P,) of the quintic walls with indices `walls` (P,)."""
    table = [(w.coefficients, w.y_mid, w.y_half) if isinstance(w, Wall) else (np.zeros(6), 0.0, 1.0)
             for w in stock.walls]
    columns = np.array([t[0] for t in table]).reshape(-1, 6).T
    return columns[:, walls], np.array([t[1] for t in table])[walls], np.array([t[2] for t in table])[walls]


def _wall_crossings(stock, rows, walls, steepness, lo, hi, x0, y0, dx, dy):
    """Where line rows[i] crosses quintic wall walls[i] inside [lo, hi] (P pairs).

    The curve boundary of the notes §4 on the unit interval l = lo + u·(hi − lo): the wall's
    quintic composed with the line, g(u) = P(y(u)) − x(u) (a straight wall is a constant
    polynomial and needs no special case). Where g is proved monotone, by the wall's slope bound
    over the segment (steepness (P,), max |dx/dy|) or else by the Bernstein coefficients of g′,
    one bracketed root; otherwise all real roots by derivative isolation.
    Returns l (P, 5) NaN-padded, monotone (P,), and whether the line is at or beyond the wall
    (x ≥ W(y), i.e. g ≤ 0) at lo and at hi, each (P,).
    """
    if rows.size == 0:
        return np.empty((0, 5)), np.zeros(0, dtype=bool), np.zeros(0, dtype=bool), np.zeros(0, dtype=bool)
    coefficients, y_mid, y_half = _quintic_table(stock, walls)
    lo, hi, x0, y0, dx, dy = lo[rows], hi[rows], x0[rows], y0[rows], dx[rows], dy[rows]
    span = hi - lo
    k = compose_columns(coefficients, (y0 + dy * lo - y_mid) / y_half, dy * span / y_half)
    k[0] -= x0 + dx * lo
    k[1] -= dx * span
    monotone = np.abs(dy) * steepness < np.abs(dx)
    unproved = np.flatnonzero(~monotone)
    monotone[unproved] = proved_monotone_unit(k[:, unproved].T)
    u = np.full((rows.size, 5), np.nan)
    u[monotone, 0] = monotone_root_unit(k[:, monotone])
    if not monotone.all():
        u[~monotone] = real_roots_unit(k[:, ~monotone].T)
    return lo[:, None] + u * span[:, None], monotone, k[0] <= 0.0, row_sum(k.T) <= 0.0


def _solve_lines(stock, length, x0, y0, z0, dx, dy, dz, intervals=False):
    """Engagement of N edge lines S(l) = (x0, y0, z0) + l·(dx, dy, dz), 0 ≤ l ≤ length.

    Returns a dict of (N,) arrays: lep_l, uep_l, length, pieces, uep_surface, uep_section,
    uep_wall, case. Lines that can reach no wall stay in one section, and lines whose
    candidate walls are each crossed at most once pass from section to section at the
    crossings: both are solved in closed form. The others go through the breakpoints.
    With `intervals`, also "intervals": the inside pieces the length sums, as an EdgeIntervals.
    """
    n = x0.size
    dz = dz + 0.0  # −0.0 (a level edge) as +0.0: divisions by it give +inf, as for a rising edge
    if intervals:
        lo, hi, hi_surface, hi_wall, lo_surface, lo_wall = _clip(stock, length, x0, y0, z0, dx, dy, dz, True)
    else:
        lo, hi, hi_surface, hi_wall = _clip(stock, length, x0, y0, z0, dx, dy, dz)
    live = hi > lo
    lo, hi = np.where(live, lo, 0.0), np.where(live, hi, 0.0)
    seg_x = np.stack([x0 + dx * lo, x0 + dx * hi])
    pair_rows, pair_walls, left_of, steepness = _reachable_walls(
        stock, live, seg_x.min(axis=0), seg_x.max(axis=0), y0 + dy * lo, y0 + dy * hi)
    quintic = np.array([isinstance(w, Wall) for w in stock.walls], dtype=bool)[pair_walls]
    on_quintic = np.flatnonzero(quintic)  # indices: gathering by them is cheaper than by the mask
    crossings = _wall_crossings(stock, pair_rows[on_quintic], pair_walls[on_quintic], steepness[on_quintic],
                                lo, hi, x0, y0, dx, dy)
    reach = np.bincount(pair_rows, minlength=n)
    # Per pair: the first crossing (NaN without one), whether it is the only one, and the
    # line's side of the wall at lo and at hi.
    root = np.full(pair_rows.size, np.nan)
    single, at_lo, at_hi = (np.zeros(pair_rows.size, dtype=bool) for _ in range(3))
    solved = [(on_quintic, crossings)]
    exact = np.flatnonzero(~quintic)
    if exact.size:
        solved.append((exact, _exact_crossings(stock, pair_rows[exact], pair_walls[exact], lo, hi, x0, y0, dx, dy)))
    for pairs, (found, once, lo_side, hi_side) in solved:
        root[pairs], single[pairs], at_lo[pairs], at_hi[pairs] = found[:, 0], once, lo_side, hi_side
    # Lines whose candidate walls are each crossed at most once go in closed form.
    simple = (reach > 0) & (np.bincount(pair_rows[np.flatnonzero(~single)], minlength=n) == 0)
    rank = np.arange(pair_rows.size) - (np.cumsum(reach) - reach)[pair_rows]  # pairs come grouped by row
    lines = (x0, y0, z0, dx, dy, dz, lo, hi, hi_surface, hi_wall, left_of)
    result, found = {}, []
    # (One wall and several apart: a line with one wall needs no sorting.)
    for subset, solve in ((reach == 0, _single_section), (simple & (reach == 1), _single_crossings),
                          (simple & (reach > 1), _single_crossings), ((reach > 0) & ~simple, _broken_lines)):
        rows = np.flatnonzero(subset)
        if rows.size == 0:
            continue
        renumber = np.cumsum(subset) - 1
        in_subset = subset[pair_rows]
        pairs = np.flatnonzero(in_subset)
        starts = (lo_surface[rows], lo_wall[rows]) if intervals else None
        if solve is _single_crossings:
            part = solve(stock, *(v[rows] for v in lines), renumber[pair_rows[pairs]], rank[pairs], pair_walls[pairs] + 1,
                         root[pairs], at_lo[pairs], at_hi[pairs], starts=starts)
        else:
            on = np.flatnonzero(in_subset[on_quintic])
            part = solve(stock, *(v[rows] for v in lines), renumber[pair_rows[pairs]], pair_walls[pairs],
                         quintic[pairs], tuple(c[on] for c in crossings), starts=starts)
        if intervals:
            piece_rows, *values = part.pop("intervals")
            found.append((rows[piece_rows], *values))
        for name, values in part.items():
            result.setdefault(name, np.empty(n, dtype=values.dtype))[rows] = values
    if intervals:
        result["intervals"] = _gathered_intervals(n, found)
    return result


def _gathered_intervals(n, found):
    """One EdgeIntervals of n lines from the solvers' pieces: a list of (rows, start, end,
    start_surface, start_section, start_wall, end_surface, end_section, end_wall) (K_s,) each,
    every list sorted by row then along the line."""
    columns = [np.concatenate([part[c] for part in found]) if found else np.zeros(0, dtype=int if c != 1 and c != 2 else float)
               for c in range(9)]
    order = np.argsort(columns[0], kind="stable")
    return EdgeIntervals(n, *(column[order] for column in columns))


def inside_intervals(stock: Staircase, origins, directions, length):
    """Where N edge lines o + l·u, 0 ≤ l ≤ length, lie inside the staircase: the inside pieces
    the engine sums into the length of cut (so `.length` equals engage's length bit for bit).

    origins, directions: (N, 3) points at l = 0 and unit directions (any: a line that falls,
    u_z < 0, is solved from its other end, as the rising line it is read backwards);
    length: flute length (mm). Pieces of one line that touch share a breakpoint (a wall
    crossing or the height of another section's top); the labels there name that breakpoint.
    An end of a piece at either end of the line is labelled flute_end; at the base or a y limit,
    stock_side. Returns an EdgeIntervals.
    """
    keep_freed_memory()
    origins = np.asarray(origins, dtype=float).reshape(-1, 3)
    directions = np.asarray(directions, dtype=float).reshape(-1, 3)
    if origins.shape != directions.shape:
        raise ValueError(f"origins {origins.shape} and directions {directions.shape} must have the same shape (N, 3)")
    length = float(length)
    falling = directions[:, 2] < 0.0
    if falling.any():
        origins = np.where(falling[:, None], origins + length * directions, origins)
        directions = np.where(falling[:, None], -directions, directions)
    # Each component contiguous (a column's stride slows every later step: see _edge_components).
    found = _solve_lines(stock, length, *np.ascontiguousarray(origins.T), *np.ascontiguousarray(directions.T),
                         intervals=True)["intervals"]
    return reversed_lines(found, falling, length) if falling.any() else found


def reversed_lines(intervals, which, length):
    """EdgeIntervals with the lines `which` (N,) bool read backwards: l -> length − l, each piece's
    ends and labels swapped, the pieces of each line back in order."""
    flip = which[intervals.rows]
    start = np.where(flip, length - intervals.end, intervals.start)
    end = np.where(flip, length - intervals.start, intervals.end)
    labels = [np.where(flip, b, a) for a, b in (
        (intervals.start_surface, intervals.end_surface), (intervals.start_section, intervals.end_section),
        (intervals.start_wall, intervals.end_wall), (intervals.end_surface, intervals.start_surface),
        (intervals.end_section, intervals.start_section), (intervals.end_wall, intervals.start_wall))]
    order = group_order(start, intervals.rows)
    return EdgeIntervals(intervals.n_rows, intervals.rows[order], start[order], end[order],
                         *(label[order] for label in labels))


def _exact_crossings(stock, rows, walls, lo, hi, x0, y0, dx, dy):
    """Crossings of line rows[i] with exact (B-spline) wall walls[i] inside [lo, hi] (P pairs),
    as _wall_crossings gives them: l (P, 1), the first one or NaN, whether at most one was
    found (P,), and whether the line is at or beyond the wall at lo and at hi, each (P,)."""
    roots, at_lo, at_hi = stock.splines.crossings(walls, x0[rows], y0[rows], dx[rows], dy[rows], lo[rows], hi[rows],
                                                  sides=True)
    if roots.shape[1] <= 1:  # at most one crossing per pair
        found = roots if roots.shape[1] else np.full((rows.size, 1), np.nan)
        return found, np.ones(rows.size, dtype=bool), at_lo, at_hi
    count = row_count(~np.isnan(roots))
    found = np.full((rows.size, 1), np.nan)
    found[count >= 1, 0] = np.nanmin(roots[count >= 1], axis=1)
    return found, count <= 1, at_lo, at_hi


def _single_section(stock, x0, y0, z0, dx, dy, dz, lo, hi, hi_surface, hi_wall, left_of, *_, starts=None):
    """Engagement of lines whose clipped segment [lo, hi] stays in section left_of: inside from
    lo up to that section's top or hi, whichever comes first (same dict as _solve_lines)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        top = (stock.z_top[np.minimum(left_of, stock.n_sections - 1)] - z0) / dz
    end = np.minimum(hi, top)
    engaged = (hi > lo) & (end - lo > LENGTH_EPS)
    at_top = top < hi
    surface = np.where(engaged, np.where(at_top, _TOP, hi_surface), _NONE)
    wall_index = np.where(engaged & ~at_top, hi_wall, -1)
    section = np.where(engaged, left_of, -1)
    bottom = np.where((hi > lo) & (lo == 0.0), left_of, -1)  # else _table1_case looks it up
    pieces = engaged.astype(np.intp)
    result = {
        "lep_l": np.where(engaged, lo, np.nan), "uep_l": np.where(engaged, end, np.nan),
        "length": np.where(engaged, end - lo, 0.0), "pieces": pieces, "uep_surface": surface,
        "uep_section": section, "uep_wall": wall_index,
        "case": _table1_case(stock, x0, y0, dx, bottom, section[:, None], engaged, pieces, wall_index),
    }
    if starts is not None:
        e = np.flatnonzero(engaged)
        result["intervals"] = (e, lo[e], end[e], starts[0][e], section[e], starts[1][e], surface[e], section[e],
                               wall_index[e])
    return result


def _single_crossings(stock, x0, y0, z0, dx, dy, dz, lo, hi, hi_surface, hi_wall, left_of, pair_rows, pair_rank,
                      pair_walls, roots, at_lo, at_hi, starts=None):
    """Engagement of lines whose candidate walls are each crossed at most once (same dict as
    _solve_lines), in closed form.

    Pairs (P,): line pair_rows[i], its pair_rank[i]-th candidate wall pair_walls[i] (1-based
    wall index j), crossed at roots[i] (NaN: not in [lo, hi]); at_lo, at_hi: whether the line is
    at or beyond that wall at lo and at hi. The crossings, sorted, cut [lo, hi] into pieces; in
    each piece the line is beyond the walls it has crossed (side at hi) and on its side at lo
    of the others, which gives the piece's section. Each piece is inside from its start up to
    its section's top or its end, whichever comes first. With `starts` (the surface and wall at
    lo), also "intervals": the inside pieces.
    """
    n, k = x0.size, int(pair_rank.max()) + 1
    # Per line, its walls as columns: crossing, side at lo, side at hi, wall index (a line
    # with fewer walls has no crossing and stays on the left of the others).
    pairs = (roots, at_lo, at_hi, pair_walls)
    if k == 1:  # one pair per line, in line order
        columns = [[values] for values in pairs]
    else:
        columns = [[np.full(n, fill, dtype=values.dtype) for _ in range(k)] for fill, values in zip((np.nan, 0, 0, 0), pairs)]
        for c in range(k):
            at = np.flatnonzero(pair_rank == c)
            for column, values in zip(columns, pairs):
                column[c][pair_rows[at]] = values[at]
    # Sorted along the line (no crossing last) by a bubble network of column swaps.
    key = [np.where(np.isnan(r), np.inf, r) for r in columns[0]]
    for last in range(k - 1, 0, -1):
        for c in range(last):
            swap = key[c + 1] < key[c]
            for values in [key] + columns:
                values[c], values[c + 1] = np.where(swap, values[c + 1], values[c]), np.where(swap, values[c], values[c + 1])
    cuts, side_lo, side_hi, cut_walls = columns
    crossed = [~np.isnan(cut) for cut in cuts]
    # A wall's side in a piece: at hi once crossed, at lo before (and without a crossing, at hi).
    before = [np.where(crossed[c], side_lo[c], side_hi[c]) for c in range(k)]
    section = reduce(np.add, before, left_of)
    straight = np.array([True] + [w.is_straight for w in stock.walls] + [True])
    pieces = np.zeros(n, dtype=np.intp)
    carry = np.zeros(n, dtype=bool)  # an inside run reaches the current piece's start
    lep, uep, length = np.full(n, np.nan), np.full(n, np.nan), np.zeros(n)
    surface, wall_index, uep_section = np.full(n, _NONE), np.full(n, -1), np.full(n, -1)
    bottom, bottom_found = np.zeros(n, dtype=np.intp), np.zeros(n, dtype=bool)
    inside_sections, found = [], []
    start = lo
    start_surface, start_wall = starts if starts is not None else (None, None)
    for j in range(k + 1):
        if j < k:
            end = np.where(crossed[j], cuts[j], hi)
        else:
            end = hi
        if j > 0:
            section = section - before[j - 1] + side_hi[j - 1]
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            top = (stock.z_top[np.clip(section, 0, stock.n_sections - 1)] - z0) / dz
        inside_end = np.minimum(end, top)
        inside = inside_end - start > LENGTH_EPS
        to_end = top >= end
        real = end - start > LENGTH_EPS
        pieces += inside & ~carry
        carry = np.where(real, inside & to_end, carry)
        lep = np.where(inside & np.isnan(lep), start, lep)
        uep = np.where(inside, inside_end, uep)
        length = length + np.where(inside, inside_end - start, 0.0)
        if j < k:
            end_surface = np.where(crossed[j], np.where(straight[cut_walls[j]], _STRAIGHT, _CURVED), hi_surface)
            end_wall = np.where(crossed[j], cut_walls[j], hi_wall)
        else:
            end_surface, end_wall = hi_surface, hi_wall
        surface = np.where(inside, np.where(to_end, end_surface, _TOP), surface)
        wall_index = np.where(inside, np.where(to_end, end_wall, -1), wall_index)
        uep_section = np.where(inside, section, uep_section)
        inside_sections.append(np.where(inside, section, -1))
        if starts is not None:
            found.append((inside, start, inside_end, start_surface, section, start_wall,
                          np.where(to_end, end_surface, _TOP), section, np.where(to_end, end_wall, -1)))
            if j < k:
                start_surface = end_surface
                start_wall = end_wall
        bottom = np.where(bottom_found, bottom, section)
        bottom_found |= real
        start = end
    engaged = ~np.isnan(uep)
    bottom = np.where(lo == 0.0, bottom, -1)
    inside_section = np.stack(inside_sections, axis=1)
    result = {
        "lep_l": lep, "uep_l": uep, "length": length, "pieces": pieces, "uep_surface": surface,
        "uep_section": uep_section, "uep_wall": wall_index,
        "case": _table1_case(stock, x0, y0, dx, bottom, inside_section, engaged, pieces, wall_index),
    }
    if starts is not None:
        result["intervals"] = _stacked_pieces(found)
    return result


def _stacked_pieces(columns):
    """The inside pieces of per-column tuples (inside, start, end, 6 labels), each (N,) or a
    scalar, as (rows, start, end, labels…) (K,), ordered by row then column."""
    inside = np.stack([c[0] for c in columns], axis=1)
    rows, at = np.nonzero(inside)
    n = inside.shape[0]
    return (rows,) + tuple(np.stack([np.broadcast_to(c[f], (n,)) for c in columns], axis=1)[rows, at]
                           for f in range(1, 9))


def _broken_lines(stock, x0, y0, z0, dx, dy, dz, lo, hi, hi_surface, hi_wall, left_of, pair_rows, pair_walls,
                  is_quintic, crossings, starts=None):
    """Engagement of lines that may cross walls (pairs pair_rows, pair_walls; the crossings of
    the quintic ones, is_quintic, as _wall_crossings found them), cut at every breakpoint (same
    dict as _solve_lines; with `starts`, the surface and wall at lo, also "intervals")."""
    n = x0.size
    live = hi > lo
    # Breakpoints: the clipped ends, the section tops, the wall crossings. Only the tops of
    # the sections the segment can reach count: those from the first one right of every wall
    # wholly left of it, over each wall it may cross.
    reach = np.bincount(pair_rows, minlength=n)
    section = left_of[:, None] + np.arange(int(reach.max()) + 1 if n else 1)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        tops = (stock.z_top[np.minimum(section, stock.n_sections - 1)] - z0[:, None]) / dz[:, None]
    tops = np.where((section <= (left_of + reach)[:, None]) & (tops > lo[:, None]) & (tops < hi[:, None]), tops, np.nan)
    columns = [lo[:, None], hi[:, None], tops]
    rows, walls = pair_rows[is_quintic], pair_walls[is_quintic]
    rank = np.arange(rows.size) - np.searchsorted(rows, rows)
    # wall index (j ≥ 1) of each column block after the tops: (first column, columns per
    # wall, (N, walls in block) wall indices)
    blocks = []
    _add_crossings(n, rows, walls, crossings[0], columns, blocks)
    exact_rows, exact_walls = pair_rows[~is_quintic], pair_walls[~is_quintic]
    if exact_rows.size:
        e = exact_rows
        _add_crossings(n, e, exact_walls, stock.splines.crossings(exact_walls, x0[e], y0[e], dx[e], dy[e], lo[e], hi[e]),
                       columns, blocks)
    at = np.concatenate(columns, axis=1)
    at[~live] = np.nan
    order = np.argsort(at, axis=1)
    order = order[:, : max(int(row_count(~np.isnan(at)).max()), 2)]
    at = np.take_along_axis(at, order, axis=1)

    # Classify each piece between consecutive breakpoints at its midpoint.
    start, end = at[:, :-1], at[:, 1:]
    real = end - start > LENGTH_EPS
    mid = 0.5 * (start + end)
    section = np.repeat(left_of[:, None], mid.shape[1], axis=1)
    if rows.size:
        section = section + _walls_left_of(stock, rows, walls, rank, crossings, x0, y0, dx, dy, mid)
    if exact_rows.size:
        e, l = exact_rows, mid[exact_rows]
        with np.errstate(invalid="ignore"):
            beyond = x0[e, None] + dx[e, None] * l >= stock.splines.x_at(exact_walls[:, None], y0[e, None] + dy[e, None] * l)
        np.add.at(section, e, beyond.astype(section.dtype))
    with np.errstate(invalid="ignore"):
        inside = real & (z0[:, None] + dz[:, None] * mid <= stock.z_top[np.clip(section, 0, stock.n_sections - 1)])

    # Runs of inside pieces: zero-length pieces neither start nor break a run.
    column = np.arange(inside.shape[1])
    last_real = np.maximum.accumulate(np.where(real, column, -1), axis=1)
    state = np.where(last_real >= 0, np.take_along_axis(inside, np.maximum(last_real, 0), axis=1), False)
    before = np.concatenate([np.zeros((n, 1), dtype=bool), state[:, :-1]], axis=1)
    pieces = row_count(inside & ~before)
    any_inside = inside.any(axis=1)
    first = np.argmax(inside, axis=1)
    last = inside.shape[1] - 1 - np.argmax(inside[:, ::-1], axis=1)
    rows = np.arange(n)
    lep = np.where(any_inside, start[rows, first], np.nan)
    uep = np.where(any_inside, end[rows, last], np.nan)
    surface, wall_index = _uep_surface(stock, order[rows, last + 1], hi_surface, hi_wall, blocks)
    surface = np.where(any_inside, surface, _NONE)
    wall_index = np.where(any_inside, wall_index, -1)
    uep_section = np.where(any_inside, section[rows, last], -1)
    inside_section = np.where(inside, section, -1)
    bottom = np.where((lo == 0.0) & real[:, 0], section[:, 0], -1)
    case = _table1_case(stock, x0, y0, dx, bottom, inside_section, any_inside, pieces, wall_index)
    result = {
        "lep_l": lep, "uep_l": uep, "length": row_sum(np.where(inside, end - start, 0.0)),
        "pieces": pieces, "uep_surface": surface, "uep_section": uep_section, "uep_wall": wall_index, "case": case,
    }
    if starts is not None:
        found = []
        for c in range(inside.shape[1]):
            begin_surface, begin_wall = _uep_surface(stock, order[rows, c], hi_surface, hi_wall, blocks)
            first_column = order[rows, c] == 0
            begin_surface = np.where(first_column, starts[0], begin_surface)
            begin_wall = np.where(first_column, starts[1], begin_wall)
            end_surface, end_wall = _uep_surface(stock, order[rows, c + 1], hi_surface, hi_wall, blocks)
            found.append((inside[:, c], start[:, c], end[:, c], begin_surface, section[:, c], begin_wall,
                          end_surface, section[:, c], end_wall))
        result["intervals"] = _stacked_pieces(found)
    return result


def _add_crossings(n, rows, walls, found, columns, blocks):
    """Append the crossings `found` (P, r), NaN-padded, of the pairs (rows, walls) (P,), grouped
    by row, to the breakpoint `columns` of n lines as one block of (rank in row) × r columns,
    and its (first column, r, (n, ranks) wall ids j + 1) to `blocks`."""
    found = found[:, ~np.isnan(found).all(axis=0)]
    if rows.size == 0 or found.size == 0:
        return
    rank = np.arange(rows.size) - np.searchsorted(rows, rows)
    crossing = np.full((n, int(rank.max()) + 1, found.shape[1]), np.nan)
    crossing[rows, rank] = found
    ids = np.full(crossing.shape[:2], -1)
    ids[rows, rank] = walls + 1
    blocks.append((sum(c.shape[1] for c in columns), found.shape[1], ids))
    columns.append(crossing.reshape(n, -1))


def _walls_left_of(stock, rows, walls, rank, crossings, x0, y0, dx, dy, along):
    """(N, W) count of the candidate quintic walls (rows[i], walls[i]) with W_j(y) ≤ x at the points `along` (N, W).

    crossings: what _wall_crossings returned for these pairs. A monotone pair changes side
    only at its one root, so its side follows from the sides at the segment's ends; the others
    are evaluated.
    """
    found, monotone, left_at_lo, left_at_hi = crossings
    l = along[rows]
    with np.errstate(invalid="ignore"):
        left = np.where(l < found[:, :1], left_at_lo[:, None], left_at_hi[:, None])
    other = np.flatnonzero(~monotone)
    if other.size:
        coefficients, y_mid, y_half = _quintic_table(stock, walls[other])
        r, lo = rows[other], l[other]
        t = (y0[r, None] + dy[r, None] * lo - y_mid[:, None]) / y_half[:, None]
        with np.errstate(invalid="ignore"):
            left[other] = x0[r, None] + dx[r, None] * lo >= horner(coefficients.T[:, None, :], t)
    count = np.zeros(along.shape, dtype=np.intp)
    starts = np.flatnonzero(rank == 0)  # pairs come grouped by row
    count[rows[starts]] = np.add.reduceat(left.astype(np.intp), starts, axis=0)
    return count


def _table1_case(stock, x0, y0, dx, bottom, inside_section, engaged, pieces, uep_wall):
    """Table 1 case of each line (index into CASES); see docs/ENGINE.md for the rules.

    Sec. A holds the edge's bottom point; Sec. B is the next section when the edge leans
    towards +x (θ_B > 0), the previous one when it leans towards −x.
    """
    n_sec = stock.n_sections
    unknown = np.flatnonzero(bottom < 0)
    if unknown.size:
        bottom = bottom.copy()
        bottom[unknown] = stock.section_at(x0[unknown], y0[unknown])
    a = np.clip(bottom, 0, n_sec - 1)
    lean = np.where(dx > PARALLEL_EPS, 1, np.where(dx < -PARALLEL_EPS, -1, 0))
    b = a + lean
    has_b = (lean != 0) & (b >= 0) & (b < n_sec)
    b = np.clip(b, 0, n_sec - 1)
    z_a, z_b = stock.z_top[a], stock.z_top[b]
    is_a = inside_section == a[:, None]
    is_b = (inside_section == b[:, None]) & has_b[:, None]
    in_a, in_b = row_any(is_a), row_any(is_b)
    other = row_any((inside_section >= 0) & ~is_a & ~is_b)
    forward = lean > 0
    between = np.maximum(a, b)  # index of the wall between A and B
    down, up = has_b & (z_a > z_b), has_b & (z_a < z_b)
    c = _CASE
    rules = (  # the first rule that holds names the case
        (~engaged & up, c["B.5"]),
        (~engaged, c["none"]),
        (other, c["multi"]),
        (in_a & in_b & down, np.where(forward, c["A.2"], c["A.1"])),
        (in_a & in_b & up & (pieces == 1), np.where(forward, c["B.1"], c["B.2"])),
        (in_a & in_b & up, np.where(forward, c["B.3"], c["B.4"])),
        (in_a & ~in_b & down & (uep_wall == between), np.where(forward, c["A.4"], c["A.3"])),
        (~in_a & in_b & up, c["B.6"]),
    )
    case = np.full(engaged.shape, c["none"], dtype=np.int8)
    for holds, name in reversed(rules):
        np.copyto(case, name, where=holds, casting="unsafe")  # case indices fit in int8
    return case


def _segments(engaged, surface, section, wall):
    """(m, p) engagement segment index per CL point: runs of equal UEP surface, section and wall."""
    key = np.where(engaged, (surface.astype(np.int64) * 4096 + section) * 4096 + wall + 1, -1)
    previous = np.concatenate([np.full((key.shape[0], 1), -2), key[:, :-1]], axis=1)
    starts = engaged & (key != previous)
    return np.where(engaged, np.cumsum(starts, axis=1) - 1, -1).astype(np.int32)
