"""Helical cutting edges: where every flute's helix engages the staircase stock (issue #6).

Flute k (0-based, of Z) of a tool with helix angle β, at rotation angle φ, is the helix

    S_k(l) = T + R·(R_t sin ψ_k(l), R_t cos ψ_k(l), l),   ψ_k(l) = φ + 2πk/Z − l·tan β / R_t,

0 ≤ l ≤ L, with R = Rz(α)·Rx(θ_A)·Ry(θ_B) the tool frame of the CL point T (Toolpath.frames) (β = 0 is the straight edge
of engagement.py). Along it every boundary of the stock is found exactly: the box limits and
the section tops (sine-lines, roots bracketed by their closed-form critical points,
helix_roots.py), the walls (subdivision with derivative bounds, helix_walls.py). The pieces
between consecutive breakpoints are classified by the height field at their midpoints;
inside runs are the engaged intervals of the flute. See docs/HELIX.md.

Lengths in mm, angles in degrees at the interface (radians inside).
"""

from dataclasses import dataclass, replace

import numpy as np

from .engagement import SURFACES, _table1_case, finished_engagement
from .helix_roots import SineLines
from .helix_walls import WallModels, wall_crossings
from .arguments import check_arguments
from .model import CutSettings, Staircase, Tool, Toolpath
from .tolerances import LENGTH_EPS

_NONE, _TOP, _STRAIGHT, _CURVED, _FLUTE_END, _SIDE, _IMMERSION = (SURFACES.index(name) for name in (
    "none", "top", "straight_wall", "curved_wall", "flute_end", "stock_side", "immersion_end"))


@dataclass(frozen=True)
class FluteEngagement:
    """Engagement of every flute's helical edge: m CL points × p rotation angles × Z flutes.

    phi: (p,) rotation angle φ of flute 0 at l = 0 (deg); helix β (deg); flutes Z; radius R_t
    (mm); feed_per_tooth f (mm); inclination α (m,) (deg, each CL point's move).
    start, end: (m, p, Z, K) axial positions l (mm from the tool tip) of each engaged interval,
    sorted, disjoint, NaN-padded (K ≥ 1, the most intervals anywhere in the pass).
    Per flute, (m, p, Z): lep_l, uep_l (mm, NaN without engagement), axial_length (sum of the
    intervals, mm), edge_length (axial_length / cos β: along the helical edge, mm), pieces
    (intervals), uep_surface (index into engagement.SURFACES of the boundary ending the last
    interval), uep_section (section holding it, −1 none), uep_wall (wall index, 0 and n for the
    x limits, −1 otherwise), case (index into engagement.CASES; Table 1 is for straight edges,
    so always 0 = "none" when β ≠ 0); lep_xyz, uep_xyz: (m, p, Z, 3) mm.
    """

    phi: np.ndarray
    helix: float
    flutes: int
    radius: float
    feed_per_tooth: float
    inclination: np.ndarray
    start: np.ndarray
    end: np.ndarray
    lep_l: np.ndarray
    uep_l: np.ndarray
    axial_length: np.ndarray
    edge_length: np.ndarray
    pieces: np.ndarray
    uep_surface: np.ndarray
    uep_section: np.ndarray
    uep_wall: np.ndarray
    case: np.ndarray
    lep_xyz: np.ndarray
    uep_xyz: np.ndarray

    @property
    def shape(self):
        """(m, p, Z): CL points × rotation angles × flutes."""
        return self.axial_length.shape

    def angle_at(self, l, flute):
        """ψ (deg, not reduced mod 360) of flute `flute` at axial position l (mm), l broadcast with phi (p,)."""
        return self.phi + 360.0 * flute / self.flutes - np.degrees(np.asarray(l, dtype=float)
                                                                   * np.tan(np.radians(self.helix)) / self.radius)

    def thickness_at(self, l, flute):
        """Cut thickness h = f·sin ψ·cos α (m, p) (mm) at axial position l (mm, a number or (m, p)) of flute
        `flute`, α each CL point's inclination; 0 where sin ψ < 0."""
        h = (self.feed_per_tooth * np.sin(np.radians(self.angle_at(l, flute)))
             * np.cos(np.radians(self.inclination))[:, None])
        return np.maximum(h, 0.0)

    def area(self):
        """(m, p, Z) ∫ h db over the engaged intervals (mm²), in closed form.

        db is the axial height (db = dl, the chip width of the mechanistic force model), not
        the length along the helical edge (which is db / cos β).
        """
        kappa = np.tan(np.radians(self.helix)) / self.radius
        psi0 = np.radians(self.phi[None, :, None] + 360.0 * np.arange(self.flutes) / self.flutes)
        scale = self.feed_per_tooth * np.cos(np.radians(self.inclination))[:, None, None]
        pieces = positive_sine_integral(self.start, self.end, psi0[..., None], kappa)
        return scale * np.where(np.isnan(pieces), 0.0, pieces).sum(axis=-1)

    def as_engagement(self, flute=0):
        """The engine Engagement (engagement.py) of flute `flute`, for the CSV writer and plots.

        phi stays the tool's rotation angle; length is the axial length of cut; h (m, p) is the
        thickness at the flute's tip (l = 0, angle φ + 360·flute/Z); area is the closed-form
        ∫ h db of :meth:`area`; segments follow the UEP surface as in the straight engine.
        """
        flute = int(flute)
        if not 0 <= flute < self.flutes:
            raise ValueError(f"flute must be in 0..{self.flutes - 1}, got {flute}")
        out = {name: getattr(self, name)[:, :, flute] for name in (
            "lep_l", "uep_l", "pieces", "uep_surface", "uep_section", "uep_wall", "case")}
        out["length"] = self.axial_length[:, :, flute]
        result = finished_engagement(self.phi, CutSettings(self.feed_per_tooth), out, self.lep_xyz[:, :, flute],
                                     self.uep_xyz[:, :, flute], self.inclination)
        return replace(result, h=self.thickness_at(0.0, flute), area=self.area()[:, :, flute])


def positive_sine_integral(start, end, psi0, kappa):
    """∫ max(sin ψ(l), 0) dl over [start, end] (mm) with ψ(l) = psi0 − kappa·l (rad, rad/mm).

    start, end: same shape, NaN kept; psi0 broadcast with them; kappa float. Closed form and
    free of cancellation: over less than half a turn the interval is split at the one zero of
    sin ψ it may hold and each part is Δ·sin ψ_mid·sinc(κΔ/2); over more, the antiderivative
    F(ψ) = 2⌊ψ/2π⌋ + (1 − cos r if r < π else 2), r = ψ mod 2π, divided by |κ|.
    """
    start, end = np.broadcast_arrays(np.asarray(start, dtype=float), np.asarray(end, dtype=float))
    psi0 = np.broadcast_to(psi0, start.shape)
    if kappa == 0.0:
        return np.maximum(np.sin(psi0), 0.0) * (end - start)
    psi_s, psi_e = psi0 - kappa * start, psi0 - kappa * end
    low, high = np.minimum(psi_s, psi_e), np.maximum(psi_s, psi_e)
    zero = np.ceil(low / np.pi) * np.pi
    split = np.where((zero > low) & (zero < high), (psi0 - zero) / kappa, end)

    def part(a, b):
        width = b - a
        mid = psi0 - kappa * 0.5 * (a + b)
        return np.maximum(width * np.sin(mid) * np.sinc(kappa * width / (2.0 * np.pi)), 0.0)

    short = part(start, split) + part(split, end)
    with np.errstate(invalid="ignore"):
        long = np.abs(_positive_sine_antiderivative(psi_s) - _positive_sine_antiderivative(psi_e)) / abs(kappa)
    return np.where(high - low < np.pi, short, long)


def _positive_sine_antiderivative(psi):
    """F(ψ) = ∫_0^ψ max(sin, 0): continuous, non-decreasing."""
    turns = np.floor(psi / (2.0 * np.pi))
    r = psi - 2.0 * np.pi * turns
    return 2.0 * turns + np.where(r < np.pi, 1.0 - np.cos(r), 2.0)


def flute_engagement(stock: Staircase, tool: Tool, toolpath: Toolpath, settings: CutSettings, *, immersion=None,
                     chunk_instants=1 << 14, progress=None):
    """Engagement of every flute's helical edge at every CL point × angle of `settings.phi`.

    immersion: None (no restriction) or (start, end) deg: a point of flute k at height l
    cuts only where its own angle ψ_k(l) lies in [start + 360n, end + 360n] for some integer
    n (ψ mod 360 in [start, end] for 0 ≤ start ≤ end < 360); a range of 360° or more
    restricts nothing. Work goes in chunks of about `chunk_instants` (CL point, angle,
    flute) triples (fewer when the helix makes more than four turns over the flute length);
    `progress(done, total)` (CL points) after each chunk.
    Returns a FluteEngagement.
    """
    check_arguments(stock=stock, tool=tool, toolpath=toolpath, settings=settings)
    window = _immersion_window(immersion)
    phi = settings.phi
    m, p, z = len(toolpath), phi.size, tool.flutes
    kappa = np.tan(np.radians(tool.helix)) / tool.radius
    rot = toolpath.frames()
    psi0 = np.radians(phi[:, None] + 360.0 * np.arange(z) / z)                  # (p, Z)
    models = WallModels(stock)
    # Per edge, the work and memory grow with the turns the helix makes over the flute.
    turns = abs(kappa) * tool.flute_length / (2.0 * np.pi)
    step = max(1, int(int(chunk_instants) / max(1.0, turns / 4.0)) // max(p * z, 1))
    chunks = []
    for first in range(0, m, step):
        last = min(m, first + step)
        n_cl = last - first
        frames = np.repeat(rot[first:last], p * z, axis=0)
        helices = Helices(np.repeat(toolpath.cl[first:last], p * z, axis=0), frames,
                          np.tile(psi0.reshape(-1), n_cl), kappa, tool.radius, tool.flute_length)
        intervals = _solve(stock, models, helices)
        if window is not None:
            intervals = _clip_to_immersion(intervals, helices, window)
        chunks.append(_per_flute(stock, helices, intervals, (n_cl, p, z), tool.helix == 0.0))
        if progress is not None:
            progress(last, m)
    k = max(c["start"].shape[-1] for c in chunks)
    joined = {name: np.concatenate([_pad(c[name], k) if name in ("start", "end") else c[name] for c in chunks])
              for name in chunks[0]}
    return FluteEngagement(phi=phi, helix=tool.helix, flutes=z, radius=tool.radius,
                           feed_per_tooth=settings.feed_per_tooth, inclination=toolpath.inclinations(settings),
                           edge_length=joined["axial_length"] / np.cos(np.radians(tool.helix)), **joined)


def _immersion_window(immersion):
    """(start, end) deg as floats, or None; ValueError for anything else."""
    if immersion is None:
        return None
    try:
        start, end = (float(v) for v in immersion)
    except (TypeError, ValueError):
        raise ValueError(f"immersion must be (start, end) in degrees, got {immersion!r}") from None
    if not (np.isfinite(start) and np.isfinite(end)) or end < start:
        raise ValueError(f"immersion {start}:{end} must be finite and not decreasing")
    return None if end - start >= 360.0 else (start, end)


def _pad(values, k):
    """(..., K) → (..., k) padded with NaN."""
    extra = k - values.shape[-1]
    return np.concatenate([values, np.full(values.shape[:-1] + (extra,), np.nan)], axis=-1) if extra else values


class Helices:
    """N helical edges S(l) = T + R_t sin ψ·u + R_t cos ψ·v + l·w, ψ = psi0 − kappa·l, 0 ≤ l ≤ length.

    cl: (N, 3) mm; frames: (N, 3, 3) rotations (columns u, v, w); psi0: (N,) rad; kappa
    rad/mm; radius, length mm. coordinates: the three SineLines x, y, z.
    """

    def __init__(self, cl, frames, psi0, kappa, radius, length):
        self.cl, self.frames, self.psi0 = cl, frames, psi0
        self.kappa, self.radius, self.length = float(kappa), float(radius), float(length)
        n = psi0.size
        self.coordinates = tuple(
            SineLines(radius * frames[:, c, 0], radius * frames[:, c, 1], frames[:, c, 2], cl[:, c], psi0, kappa,
                      np.full(n, self.length))
            for c in range(3))

    def __len__(self):
        return int(self.psi0.size)

    def points(self, l):
        """Points (N, K, 3) at axial positions l (N, K) mm (sin ψ and cos ψ once for all three coordinates)."""
        psi = self.psi0[:, None] - self.kappa * l
        radial = (np.sin(psi)[..., None] * self.frames[:, None, :, 0]
                  + np.cos(psi)[..., None] * self.frames[:, None, :, 1])
        return self.cl[:, None, :] + self.radius * radial + l[..., None] * self.frames[:, None, :, 2]


def _tagged_roots(lines, offsets, tags):
    """Roots (N, C) of lines + offsets[:, j] and their (surface, wall) tags (N, C) each."""
    roots = lines.roots(offsets)
    n, planes, per = roots.shape
    surface = np.broadcast_to(np.repeat([t[0] for t in tags], per), (n, planes * per))
    wall = np.broadcast_to(np.repeat([t[1] for t in tags], per), (n, planes * per))
    return roots.reshape(n, -1), surface, wall


def _sorted_pieces(columns):
    """Sort breakpoint columns [(l, surface, wall), …] (N, ·) by l, NaN last, trimmed.

    Returns at (N, B), surface (N, B), wall (N, B)."""
    at = np.concatenate([c[0] for c in columns], axis=1)
    surface = np.concatenate([np.broadcast_to(c[1], c[0].shape) for c in columns], axis=1)
    wall = np.concatenate([np.broadcast_to(c[2], c[0].shape) for c in columns], axis=1)
    order = np.argsort(at, axis=1)
    width = max(int((~np.isnan(at)).sum(axis=1).max()), 2) if at.shape[0] else 2
    order = order[:, :width]
    return tuple(np.take_along_axis(v, order, axis=1) for v in (at, surface, wall))


def _inside(stock, helices, l):
    """Whether the points at l (N, K) are in the stock, and the section holding each (N, K)."""
    with np.errstate(invalid="ignore"):
        xyz = helices.points(np.where(np.isnan(l), 0.0, l))
    x, y, z = xyz[..., 0], xyz[..., 1], xyz[..., 2]
    box = ((x >= stock.x_min) & (x <= stock.x_max) & (y >= stock.y_min) & (y <= stock.y_max)
           & (z >= stock.base_z) & (z <= stock.z_top.max()) & ~np.isnan(l))
    section = np.full(l.shape, -1)
    section[box] = stock.section_at(x[box], y[box])
    return box & (z <= stock.z_top[np.clip(section, 0, stock.n_sections - 1)]), section


def _solve(stock, models, helices):
    """Engaged intervals of N helices: a dict of (N, K) arrays start, end (mm, NaN-padded), end
    surface and wall of each interval, its last section, and (N, P) inside_section (section of
    each inside piece, −1 elsewhere) for the Table 1 case."""
    n = len(helices)
    xs, ys, zs = helices.coordinates
    n_sec = stock.n_sections
    ends = [(np.zeros((n, 1)), np.array([[_NONE]]), np.array([[-1]])),
            (np.full((n, 1), helices.length), np.array([[_FLUTE_END]]), np.array([[-1]]))]
    box = ends + [
        _tagged_roots(xs, np.tile([-stock.x_min, -stock.x_max], (n, 1)), [(_STRAIGHT, 0), (_STRAIGHT, n_sec)]),
        _tagged_roots(ys, np.tile([-stock.y_min, -stock.y_max], (n, 1)), [(_SIDE, -1), (_SIDE, -1)]),
    ]
    tops = np.unique(stock.z_top)
    levels = np.concatenate([[stock.base_z], tops])
    heights = _tagged_roots(zs, np.tile(-levels, (n, 1)), [(_SIDE, -1)] + [(_TOP, -1)] * tops.size)
    # The box: limits in x, y and z (base to the highest top); walls only matter inside it.
    top_root = heights[0].reshape(n, levels.size, -1)[:, -1]
    in_box = _sorted_pieces(box + [(heights[0].reshape(n, levels.size, -1)[:, 0], _SIDE, -1), (top_root, _TOP, -1)])[0]
    a, b = in_box[:, :-1], in_box[:, 1:]
    with np.errstate(invalid="ignore"):
        mid = helices.points(np.where(b > a, 0.5 * (a + b), 0.0))
        inside_box = ((b - a > 0.0) & (mid[..., 0] >= stock.x_min) & (mid[..., 0] <= stock.x_max)
                      & (mid[..., 1] >= stock.y_min) & (mid[..., 1] <= stock.y_max)
                      & (mid[..., 2] >= stock.base_z) & (mid[..., 2] <= tops[-1]))
    columns = box + [heights]
    if stock.walls:
        row, piece = np.nonzero(inside_box)
        n_walls = len(stock.walls)
        rows = np.repeat(row, n_walls)
        walls = np.tile(np.arange(n_walls), row.size)
        r, j, l = wall_crossings(models, xs, ys, rows, walls, np.repeat(a[row, piece], n_walls),
                                 np.repeat(b[row, piece], n_walls))
        if r.size:
            order = np.argsort(r, kind="stable")
            r, j, l = r[order], j[order], l[order]
            rank = np.arange(r.size) - np.searchsorted(r, r)
            at = np.full((n, int(rank.max()) + 1), np.nan)
            at[r, rank] = l
            wall = np.full(at.shape, -1)
            wall[r, rank] = j + 1
            straight = np.array([False] + [w.is_straight for w in stock.walls])
            columns.append((at, np.where(straight[np.maximum(wall, 0)], _STRAIGHT, _CURVED), wall))
    at, surface, wall = _sorted_pieces(columns)
    start, end = at[:, :-1], at[:, 1:]
    real = end - start > LENGTH_EPS
    inside, section = _inside(stock, helices, np.where(real, 0.5 * (start + end), np.nan))
    return _runs(start, end, real, inside, section, surface[:, 1:], wall[:, 1:])


def _runs(start, end, real, inside, section, end_surface, end_wall):
    """Inside runs of pieces (N, P): zero-length pieces neither start nor break a run.

    Returns the dict of _solve."""
    n, p = start.shape
    column = np.arange(p)
    last_real = np.maximum.accumulate(np.where(real, column, -1), axis=1)
    state = np.where(last_real >= 0, np.take_along_axis(inside, np.maximum(last_real, 0), axis=1), False)
    before = np.concatenate([np.zeros((n, 1), dtype=bool), state[:, :-1]], axis=1)
    next_real = np.minimum.accumulate(np.where(real, column, p)[:, ::-1], axis=1)[:, ::-1]
    next_real = np.concatenate([next_real[:, 1:], np.full((n, 1), p)], axis=1)
    after = np.where(next_real < p, np.take_along_axis(inside, np.minimum(next_real, p - 1), axis=1), False)
    opens = real & inside & ~before
    closes = real & inside & ~after
    out = _compact(opens, start=start)
    closing = _compact(closes, end=end, end_surface=end_surface, end_wall=end_wall, section=section)
    out.update(closing)
    out["inside_section"] = np.where(real & inside, section, -1)
    return out


def _compact(mask, **arrays):
    """The entries where mask (N, P) holds, moved left in order: (N, K) each, NaN / −1 padded."""
    n = mask.shape[0]
    count = mask.sum(axis=1)
    k = max(int(count.max()) if n else 0, 1)
    r, c = np.nonzero(mask)
    slot = np.arange(r.size) - np.searchsorted(r, r)
    out = {}
    for name, values in arrays.items():
        fill = np.nan if values.dtype.kind == "f" else -1
        packed = np.full((n, k), fill, dtype=values.dtype)
        packed[r, slot] = values[r, c]
        out[name] = packed
    return out


def _clip_to_immersion(intervals, helices, window):
    """Intervals cut to where ψ(l) (deg) lies in [start + 360n, end + 360n]; a cut end gets the
    surface immersion_end. ψ is linear in l, so this is interval arithmetic."""
    lo_w, hi_w = window
    start, end = intervals["start"], intervals["end"]
    psi0 = np.degrees(helices.psi0)[:, None]
    slope = np.degrees(helices.kappa)
    if slope == 0.0:
        keep = np.broadcast_to(np.mod(psi0 - lo_w, 360.0) <= hi_w - lo_w, start.shape)
        return {**intervals, "start": np.where(keep, start, np.nan), "end": np.where(keep, end, np.nan)}
    psi_s, psi_e = psi0 - slope * start, psi0 - slope * end
    low, high = np.minimum(psi_s, psi_e), np.maximum(psi_s, psi_e)
    first = np.ceil((low - hi_w) / 360.0)
    with np.errstate(invalid="ignore"):
        spans = np.floor((high - lo_w) / 360.0) - first
    count = int(np.nanmax(spans, initial=0.0)) + 1
    n = first[..., None] + np.arange(max(count, 1))                        # (N, K, W)
    w_low = np.maximum(lo_w + 360.0 * n, low[..., None])
    w_high = np.minimum(hi_w + 360.0 * n, high[..., None])
    with np.errstate(over="ignore", invalid="ignore"):
        l_a, l_b = (psi0[..., None] - w_low) / slope, (psi0[..., None] - w_high) / slope
    new_start = np.maximum(np.minimum(l_a, l_b), start[..., None])
    new_end = np.minimum(np.maximum(l_a, l_b), end[..., None])
    with np.errstate(invalid="ignore"):
        ok = (w_high >= w_low) & (new_end - new_start > LENGTH_EPS)
    # ψ falls along l when slope > 0: the end's ψ is the window's low side, else its high side.
    cut = np.where(slope > 0.0, w_low > low[..., None], w_high < high[..., None])
    shape = ok.shape
    fields = {"start": new_start, "end": new_end,
              "end_surface": np.where(cut, _IMMERSION, intervals["end_surface"][..., None]),
              "end_wall": np.where(cut, -1, intervals["end_wall"][..., None]),
              "section": np.broadcast_to(intervals["section"][..., None], shape)}
    flat = ok.reshape(shape[0], -1)
    order = np.argsort(np.where(flat, new_start.reshape(shape[0], -1), np.inf), axis=1, kind="stable")
    fields = {name: np.take_along_axis(v.reshape(shape[0], -1), order, axis=1) for name, v in fields.items()}
    out = _compact(np.take_along_axis(flat, order, axis=1), **fields)
    out["inside_section"] = intervals["inside_section"]
    return out


def _per_flute(stock, helices, intervals, shape, straight):
    """Per-flute results of one chunk, each (n_cl, p, Z) or (n_cl, p, Z, K / 3)."""
    start, end = intervals["start"], intervals["end"]
    n = start.shape[0]
    pieces = (~np.isnan(start)).sum(axis=1)
    engaged = pieces > 0
    rows = np.arange(n)
    last = np.maximum(pieces - 1, 0)
    lep = np.where(engaged, start[:, 0], np.nan)
    uep = np.where(engaged, end[rows, last], np.nan)
    surface = np.where(engaged, intervals["end_surface"][rows, last], _NONE).astype(np.int8)
    wall = np.where(engaged, intervals["end_wall"][rows, last], -1)
    section = np.where(engaged, intervals["section"][rows, last], -1)
    ends = helices.points(np.column_stack([np.where(engaged, lep, 0.0), np.where(engaged, uep, 0.0)]))
    ends[~engaged] = np.nan
    case = np.zeros(n, dtype=np.int8)
    if straight:
        x0, y0, _ = helices.points(np.zeros((n, 1)))[:, 0].T
        case = _table1_case(stock, x0, y0, helices.frames[:, 0, 2], np.full(n, -1), intervals["inside_section"],
                            engaged, pieces, wall)
    k = start.shape[1]
    return {
        "start": start.reshape(shape + (k,)), "end": end.reshape(shape + (k,)),
        "lep_l": lep.reshape(shape), "uep_l": uep.reshape(shape),
        "axial_length": np.where(np.isnan(start), 0.0, end - start).sum(axis=1).reshape(shape),
        "pieces": pieces.reshape(shape).astype(np.int32), "uep_surface": surface.reshape(shape),
        "uep_section": section.reshape(shape).astype(np.int32), "uep_wall": wall.reshape(shape).astype(np.int32),
        "case": case.reshape(shape), "lep_xyz": ends[:, 0].reshape(shape + (3,)),
        "uep_xyz": ends[:, 1].reshape(shape + (3,)),
    }
