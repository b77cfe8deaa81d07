"""The search for the removals of corner arcs: which earlier swept pieces each arc of a bull-nose or ball-end
mill is solved against (inprocess_arc.arc_swept_intervals solves one (arc, piece) pair).

The arcs come a block of whole CL points at a time (at most ARC_BLOCK arcs, so memory is bounded by the block,
not by the call). The arcs of one CL point make a group, held by one sphere. The group's *units* are what its
arcs may be solved against: the chains whose slices (KD tree) meet the sphere and which are not surely apart
from it; a rigid chain ending before the CL point as one hull (its pieces' union), of every other chain the
pieces of its spans ending before the CL point, each not surely apart from the sphere either. The units are
ranked by how deep the sphere's centre lies in them (the tool's corner rounded, _depth). Then rounds: every arc
with something left takes its group's next 1, 2, 4, … units in that order, drops those surely apart from what is
left of it, solves the others and narrows its range. The sure-miss test comes in two steps: the open arcs of a CL
point at consecutive angles in clusters of up to CLUSTER, each cluster in PARTS spheres (sphere j holds every arc
of the cluster over part j of the cluster's range of ψ), and a unit apart from all of a cluster's spheres is
dropped for all its arcs; then each arc alone, what is left of it in PARTS equal parts, each in the capsule of its
chord grown by its sagitta (not for the pairs the plan view decides in closed form, inprocess_plan, whose solve
costs less than that test). An arc whose range closes takes no more units; most arcs of a program that went over
them before close after a unit or two (docs/ENGINE.md, "Tools with a corner in the in-process stock", "The arcs'
search").

A unit is dropped for an arc only when it is surely apart from what is left of the arc at that time, and the range
only narrows: so every unit that could remove something of what is left at the end is solved, and what is
removed (the union of the removals over the arc's range) is the same whatever the order. Which removals are
found may depend on the other arcs of the CL point in the call (the group's sphere and order), not what they
remove. Shapes: L arcs; ψ in radians, lengths in mm.
"""

import functools

import numpy as np

from .inprocess import _CLEAR, _apart, _across, _chain_spans, _csr, _seen_along, _span_pieces, \
    _sphere_chains
from .inprocess_cover import narrow
from .inprocess_level_pairs import GROUP, arcs as level_arcs
from .inprocess_plan import arc_kinds, arc_piece_intervals
from .ordering import group_order
from .swept import every_column, row_dot, rows
from .tolerances import LENGTH_EPS

#: Arcs per block at most (whole CL points; a CL point with more arcs is a block alone).
ARC_BLOCK = 1 << 13
#: (arc, unit) pairs taken per round at most (an arc takes at least one unit per round).
ROUND_PAIRS = 1 << 17
#: Parts of what is left of an arc, each in its own capsule, in the sure-miss test of a pair.
PARTS = 4
#: Pairs solved per batch.
PAIR_BATCH = 1 << 12
#: Open arcs of one CL point at consecutive angles tested together first, at most.
CLUSTER = 8


def arc_removal_intervals(pieces, program_index, line, lo, hi, centres, ds, ws, radius, top, p, tips, big):
    """Removal intervals (rows (R,) int, enter, leave (R,) mm of arc length) of the corner arcs `line` inside
    the pieces of the cutting moves that end before their CL point.

    line: (L,) int ascending, the arcs holding material (row i·p + k: CL point i, angle k), all of it
    within lo … hi (L,) mm of arc length s = radius·ψ; centres, ds, ws: (N, 3) every arc's centre and unit
    vectors (P(ψ) = centre + radius·(sin ψ·d − cos ψ·w), 0 ≤ ψ ≤ top); tips (N, 3): each arc's tool tip;
    radius, big: the tool's corner radius and radius (mm); pieces, program_index and p as for
    inprocess.removal_intervals, whose rules these follow: removals overlapping lo … hi by more than LENGTH_EPS,
    one removal [lo, hi] for an arc covered whole (each (arc, piece) pair is solved over the whole arc, 0 … top,
    whatever is left of it). See the module docstring for the search. Where the program has z levels
    (pieces.levels), the arcs across their axis meet them in plan (inprocess_level_pairs.arcs) and then, what is
    left of them, the other moves (pieces.rest) in that search.
    """
    line = np.asarray(line, dtype=np.intp).reshape(-1)
    empty = (np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))
    if line.size == 0 or pieces.move.size == 0:
        return empty
    radius = float(radius)
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    cl = line // p
    before = np.asarray(program_index, dtype=np.intp)[cl] - 1
    geometry = (centres, ds, ws, tips, radius, float(big), float(top))
    view = pieces.levels
    if view is not None:
        w, d = np.take(ws, line, axis=0), np.take(ds, line, axis=0)
        level = every_column(w == view.w) & (row_dot(d, w) == 0.0)
        found = [_searched(pieces, line[~level], lo[~level], hi[~level], cl[~level], before[~level], geometry)]
        level = np.flatnonzero(level)
        for begin, end in _blocks(cl[level]):
            found += _in_levels(pieces, level[begin:end], line, lo, hi, cl, before, d, w, geometry)
        return tuple(np.concatenate(part) for part in zip(*found))
    return _searched(pieces, line, lo, hi, cl, before, geometry)


def _in_levels(pieces, at, line, lo, hi, cl, before, d, w, geometry):
    """Removal parts [(rows, enter, leave)] (mm of arc length) of the arcs line[at] (at: a block of whole CL points)
    across the levels' axis: the level view (inprocess_level_pairs.arcs, the pairs it does not decide screened by
    the sure-miss test of _Arcs), then the search among the other moves for those not removed whole."""
    centres, _, ws, tips, radius, big, top = geometry
    psi = (lo[at] / radius, hi[at] / radius)
    screened = _Arcs(line[at], *psi, geometry)
    arc, start, end = level_arcs(pieces.levels, np.take(tips, line[at], axis=0), rows(d, at), rows(w, at),
                                 np.take(centres, line[at], axis=0), *psi, before[at], line[at] // GROUP, big, radius,
                                 top, functools.partial(_screen, screened))
    envelope = np.stack(psi)
    narrow(envelope, arc, start, end)
    dead = envelope[0] >= envelope[1]
    alive = ~dead[arc]
    found = [(line[at[dead]], psi[0][dead] * radius, psi[1][dead] * radius),
             (line[at[arc[alive]]], start[alive] * radius, end[alive] * radius)]
    left = np.flatnonzero(~dead)
    if pieces.rest.move.size and left.size:
        mine = at[left]
        left = left[_near_rest(pieces.rest, tips, ws, line[mine], cl[mine], before[mine], radius, big)]
        mine = at[left]
        found.append(_searched(pieces.rest, line[mine], lo[mine], hi[mine], cl[mine], before[mine], geometry,
                               envelope[:, left]))
    return found


def _near_rest(rest, tips, ws, line, cl, before, radius, big):
    """(L,) bool: the arcs `line` (L,) whose CL point's sphere may meet a chain of `rest` (a SweptPieces) begun by
    program row before (L,) (cl (L,) non-decreasing, each arc's CL point): the sphere of radius big about the corner's
    centre height on the axis (tip + radius·w) holds every corner arc of the tool (a point at ψ lies
    (big − radius + radius·sin ψ, −radius·cos ψ) from it across and along the axis: at most big away); a chain whose
    balls all miss it, or whose hull is surely apart from it (the units' test, _Units), removes nothing of them."""
    first = np.flatnonzero(np.r_[True, cl[1:] != cl[:-1]])
    centre = np.take(tips, line[first], axis=0) + radius * np.take(ws, line[first], axis=0)
    size = np.full(first.size, big * (1.0 + 1e-9) + 1e-9)
    g, k = _sphere_chains(centre, size, before[first], rest)
    keep = ~_apart(centre[g], centre[g], *rest.hulls("chain", k), rest.chain_slack[k] + size[g], rest.chain_lean[k])
    near = np.zeros(first.size, dtype=bool)
    near[g[keep]] = True
    return np.repeat(near, np.diff(np.r_[first, cl.size]))


def _screen(arcs, seg, hulls, low, high):
    """(K,) bool: the pairs (arc seg (K,) non-decreasing, earlier tool's hull: c0, c1, axis, radius, height, corner)
    not surely apart (_Arcs.near) over the arcs' parts low … high (K,) ψ (per arc, the hull of its pairs' parts)."""
    arcs.envelope[0, seg], arcs.envelope[1, seg] = np.inf, -np.inf
    np.minimum.at(arcs.envelope[0], seg, low)
    np.maximum.at(arcs.envelope[1], seg, high)
    return arcs.near_hulls(seg, hulls)


def _searched(pieces, line, lo, hi, cl, before, geometry, left=None):
    """arc_removal_intervals by the search (module docstring) among pieces, in blocks of whole CL points; left
    (from, to) (L,) ψ, if given: what is left of each arc's material lo … hi (mm) by removals found elsewhere,
    where the search starts (it keeps the removals that overlap lo … hi, as always)."""
    found = [(np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))]
    if line.size == 0 or pieces.move.size == 0:
        return found[0]
    radius = geometry[4]
    for begin, end in _blocks(cl):
        rows = slice(begin, end)
        found.append(_block(pieces, line[rows], lo[rows] / radius, hi[rows] / radius, cl[rows], before[rows],
                            geometry, None if left is None else (left[0][rows], left[1][rows])))
    return tuple(np.concatenate(part) for part in zip(*found))


def _blocks(cl):
    """(begin, end) of runs of whole CL points of `cl` (L,) ascending, at most ARC_BLOCK arcs each (or one CL
    point)."""
    ends = np.r_[np.flatnonzero(cl[1:] != cl[:-1]) + 1, cl.size]
    out, begin = [], 0
    while begin < cl.size:
        # The last CL point ending within ARC_BLOCK arcs, or the first one.
        at = max(np.searchsorted(ends, begin + ARC_BLOCK, side="right") - 1, np.searchsorted(ends, begin, side="right"))
        out.append((begin, int(ends[at])))
        begin = out[-1][1]
    return out


class _Arcs:
    """The arcs of a block: each one's geometry, the envelope of what is left of it (rows 0, 1: ψ from, to,
    narrowed as removals are found; rows 2, 3: the range as given) and its capsule."""

    def __init__(self, line, lo, hi, geometry, left=None):
        centres, ds, ws, tips, self.radius, self.big, self.top = geometry
        self.centre, self.d, self.w, self.tip = (np.take(v, line, axis=0) for v in (centres, ds, ws, tips))
        self.envelope = np.stack([lo, hi, lo, hi] if left is None else [*left, lo, hi])

    def capsule(self, seg):
        """(a, b, sagitta, middle) of what is left of the arcs seg: chord ends, a bound of the arc's distance
        from the chord, the arc's middle point."""
        low, high = self.envelope[0, seg], self.envelope[1, seg]
        mid = 0.5 * (low + high)
        centre, d, w = (rows(part, seg) for part in (self.centre, self.d, self.w))
        points = [centre + self.radius * (np.sin(t)[:, None] * d - np.cos(t)[:, None] * w) for t in (low, high, mid)]
        sag = self.radius * (1.0 - np.cos(0.5 * np.maximum(high - low, 0.0)))
        return points[0], points[1], sag * (1.0 + 1e-9) + 1e-12, points[2]

    def near(self, seg, level, index, pieces):
        """(K,) bool: the pairs (arc seg (K,) non-decreasing, hull index at `level`) not surely apart: what is left
        of the arc in PARTS equal parts, each in the capsule of its chord grown by its sagitta, and the hull (a
        chain's grown by its slack and lean) apart from none of them (inprocess._apart)."""
        hulls = pieces.hulls(level, index) + (pieces.corners(level, index),)
        if level == "chain":
            return self.near_hulls(seg, hulls, pieces.chain_slack[index], pieces.chain_lean[index])
        return self.near_hulls(seg, hulls)

    def near_hulls(self, seg, hulls, slack=None, lean=None):
        """near for the hulls (c0, c1, axis, radius, height, corner) (K each) of the pairs, grown by slack and lean
        (K,) where given."""
        if seg.size == 0:
            return np.zeros(0, dtype=bool)
        # The parts' ends per arc, then gathered for its pairs.
        new = np.r_[True, seg[1:] != seg[:-1]]
        arc, owner = seg[new], np.cumsum(new) - 1
        low, high = self.envelope[0, arc], self.envelope[1, arc]
        step = (high - low) / PARTS
        sag = self.radius * (1.0 - np.cos(0.5 * np.maximum(step, 0.0))) * (1.0 + 1e-9) + 1e-12
        centre, d, w = (rows(part, arc) for part in (self.centre, self.d, self.w))
        ends = [centre + self.radius * (np.sin(t)[:, None] * d - np.cos(t)[:, None] * w)
                for t in (low + j * step for j in range(PARTS + 1))]
        near = np.zeros(seg.size, dtype=bool)
        for j in range(PARTS):
            open_ = np.flatnonzero(~near)
            if open_.size == 0:
                break
            at = owner[open_]
            grown = sag[at] if slack is None else sag[at] + slack[open_]
            near[open_] = _close(rows(ends[j], at), rows(ends[j + 1], at), grown,
                                 tuple(rows(h, open_) for h in hulls), None if lean is None else lean[open_])
        return near

    def spheres(self, live, first):
        """(centre (C, PARTS, 3), size (C, PARTS)) of the clusters of the open arcs live (n,) (cluster c: live[first[c]]
        up to the next first): sphere j holds every arc of the cluster over part j of PARTS equal parts of the
        cluster's range of ψ (from the least to the largest of what is left of its arcs): an arc of at most π lies
        within half its chord of the chord's middle (its ends are the farthest)."""
        count = np.diff(np.r_[first, live.size])
        low = np.minimum.reduceat(self.envelope[0, live], first)
        high = np.maximum.reduceat(self.envelope[1, live], first)
        owner = np.repeat(np.arange(first.size), count)
        step = (high - low) / PARTS
        centre, d, w = (rows(part, live) for part in (self.centre, self.d, self.w))
        ends = [centre + self.radius * (np.sin(t)[:, None] * d - np.cos(t)[:, None] * w)
                for t in ((low + j * step)[owner] for j in range(PARTS + 1))]
        middle, size = np.zeros((first.size, PARTS, 3)), np.zeros((first.size, PARTS))
        for j in range(PARTS):
            chord = ends[j + 1] - ends[j]
            mid = ends[j] + 0.5 * chord
            middle[:, j] = np.add.reduceat(mid, first, axis=0) / count[:, None]
            gap = mid - middle[owner, j]
            reach = np.sqrt(row_dot(gap, gap)) + 0.5 * np.sqrt(row_dot(chord, chord))
            size[:, j] = np.maximum.reduceat(reach, first) * (1.0 + 1e-9) + 1e-12
        return middle, size

    def plan(self, seg, level, index, pieces):
        """(K,) bool: the pairs (arc seg, hull index at `level`) the plan view decides (inprocess_plan.arc_kinds)."""
        tool = (np.full(seg.size, self.big), np.full(seg.size, self.radius))
        below, at, steady, above = arc_kinds(rows(self.tip, seg), rows(self.w, seg), *tool, *pieces.hulls(level, index),
                                             pieces.corners(level, index))
        return below | at | steady | above

    def open(self):
        """(L,) bool: the arcs with something left."""
        return self.envelope[0] < self.envelope[1]

    def solve(self, seg, index, level, pieces):
        """Removal intervals (seg, enter, leave) in ψ of the arcs seg (K,) inside the hulls `index` (K,) at
        `level` ("piece" or "chain"), each pair solved over the whole arc (0 … top) and kept where it overlaps
        the arc's range as given by more than LENGTH_EPS of arc length; the envelopes narrowed; in batches of
        PAIR_BATCH. Pairs the plan view decides (an earlier move across the axis: inprocess_plan) in closed form,
        the others by inprocess_arc."""
        out = [(np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))]
        for begin in range(0, seg.size, PAIR_BATCH):
            s, q = seg[begin:begin + PAIR_BATCH], index[begin:begin + PAIR_BATCH]
            full = [np.full(s.size, v) for v in (self.big, self.radius, self.top)]
            arc = (rows(part, s) for part in (self.tip, self.d, self.w, self.centre))
            pair, start, end = arc_piece_intervals(*arc, *full, *pieces.hulls(level, q), pieces.corners(level, q),
                                                   arc=s)
            owner = s[pair]
            overlap = (np.minimum(end, self.envelope[3, owner]) - np.maximum(start, self.envelope[2, owner]))
            hit = overlap * self.radius > LENGTH_EPS
            out.append((owner[hit], start[hit], end[hit]))
        found = tuple(np.concatenate(part) for part in zip(*out))
        narrow(self.envelope, *found)
        return found


def _block(pieces, line, lo, hi, cl, before, geometry, left=None):
    """arc_removal_intervals of one block (lo, hi in ψ; cl, before (L,) each arc's CL point and last earlier
    program row): (rows, enter, leave) in mm of arc length."""
    arcs = _Arcs(line, lo, hi, geometry, left)
    first = np.flatnonzero(np.r_[True, cl[1:] != cl[:-1]])
    group = np.cumsum(np.r_[True, cl[1:] != cl[:-1]]) - 1
    units = _Units(arcs, group, first, before[first], pieces)
    found = []
    pos = np.zeros(first.size, dtype=np.intp)
    take = 1
    while True:
        left = units.count[group] - pos[group]
        live = np.flatnonzero(arcs.open() & (left > 0))
        if live.size == 0:
            break
        step = max(1, min(take, ROUND_PAIRS // live.size))
        count = np.minimum(left[live], step)
        owner, rank = _csr(count)
        # The clusters' spheres first: a pair goes on only where its cluster's does.
        heads, cluster = _clusters(live, line, group)
        near = _clusters_near(arcs, units, live, heads, group, pos, count[heads], pieces)
        keep = near[(np.cumsum(count[heads]) - count[heads])[cluster[owner]] + rank]
        owner, rank = owner[keep], rank[keep]
        seg = live[owner]
        unit = units.start[group[seg]] + pos[group[seg]] + rank
        whole = units.whole[unit]
        for level, chosen in (("chain", np.flatnonzero(whole)), ("piece", np.flatnonzero(~whole))):
            index = units.index[unit[chosen]]
            # A pair the plan view decides costs less to solve than to test.
            near = arcs.plan(seg[chosen], level, index, pieces)
            rest = np.flatnonzero(~near)
            near[rest] = arcs.near(seg[chosen[rest]], level, index[rest], pieces)
            found.append(arcs.solve(seg[chosen[near]], index[near], level, pieces))
        pos += step
        take *= 2
    dead = ~arcs.open()
    found = [(np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))] + found
    seg, enter, leave = (np.concatenate(part) for part in zip(*found))
    alive = ~dead[seg]
    rows = np.concatenate([line[dead], line[seg[alive]]])
    start = np.concatenate([arcs.envelope[2, dead], enter[alive]]) * arcs.radius
    end = np.concatenate([arcs.envelope[3, dead], leave[alive]]) * arcs.radius
    return rows, start, end


def _clusters(live, line, group):
    """(first (C,), cluster (n,)): the open arcs live (n,) ascending in clusters, runs of at most CLUSTER arcs of one
    CL point at consecutive rows (angles) of line; first: each cluster's first position in live, cluster: each
    arc's cluster."""
    rows, mine = line[live], group[live]
    new = np.r_[True, (mine[1:] != mine[:-1]) | (rows[1:] - rows[:-1] != 1)]
    start = np.flatnonzero(new)
    rank = np.arange(live.size) - start[np.cumsum(new) - 1]
    new |= rank % CLUSTER == 0
    return np.flatnonzero(new), np.cumsum(new) - 1


def _clusters_near(arcs, units, live, first, group, pos, count, pieces):
    """(sum(count),) bool: the pairs (cluster c, its group's next count[c] units) not surely apart from the
    cluster's spheres (_Arcs.spheres), cluster by cluster, unit by unit in order."""
    centre, size = arcs.spheres(live, first)
    owner, rank = _csr(count)
    g = group[live[first]][owner]
    unit = units.start[g] + pos[g] + rank
    whole = units.whole[unit]
    near = np.zeros(unit.size, dtype=bool)
    for level, chosen in (("chain", np.flatnonzero(whole)), ("piece", np.flatnonzero(~whole))):
        index = units.index[unit[chosen]]
        close = np.zeros(chosen.size, dtype=bool)
        for j in range(PARTS):
            rows = np.flatnonzero(~close)
            if rows.size == 0:
                break
            at = owner[chosen[rows]]
            point = centre[at, j]
            close[rows] = _close(point, point, *_grown(size[at, j], level, index[rows], pieces))
        near[chosen] = close
    return near


class _Units:
    """The units of the groups of a block (module docstring): index (U,) a chain (whole (U,) True) or a piece;
    the units of group g are start[g] … start[g] + count[g] − 1, deepest first."""

    def __init__(self, arcs, group, first, before, pieces):
        g_count = np.diff(np.r_[first, group.size])
        a, b, sag, _ = arcs.capsule(np.arange(group.size))
        middle, bound = 0.5 * (a + b), 0.5 * np.sqrt(row_dot(b - a, b - a)) + sag
        # The group's sphere: about the mean of its arcs' spheres, holding each of them.
        centre = np.add.reduceat(middle, first, axis=0) / g_count[:, None]
        gap = middle - centre[group]
        reach = np.sqrt(row_dot(gap, gap)) + bound
        size = np.maximum.reduceat(reach, first) * (1.0 + 1e-9) + 1e-12
        g, k = _sphere_chains(centre, size, before, pieces)
        keep = ~_apart(centre[g], centre[g], *pieces.hulls("chain", k), pieces.chain_slack[k] + size[g],
                       pieces.chain_lean[k])
        g, k = g[keep], k[keep]
        whole = pieces.chain_rigid[k] & (pieces.chain_last[k] <= before[g])
        g_span, span = _chain_spans(g[~whole], k[~whole], before, pieces)
        keep = ~_apart(centre[g_span], centre[g_span], *pieces.hulls("span", span),
                       pieces.span_slack[span] + size[g_span], 0.5 * pieces.span_turn[span])
        g_piece, piece = _span_pieces(g_span[keep], span[keep], pieces)
        keep = ~_apart(centre[g_piece], centre[g_piece], *pieces.hulls("piece", piece), size[g_piece])
        g_piece, piece = g_piece[keep], piece[keep]
        owner = np.r_[g[whole], g_piece]
        self.index = np.r_[k[whole], piece]
        self.whole = np.r_[np.ones(int(whole.sum()), dtype=bool), np.zeros(piece.size, dtype=bool)]
        depth = np.r_[_depth(centre[g[whole]], *pieces.hulls("chain", k[whole])[:4], pieces.chain_corner[k[whole]]),
                      _depth(centre[g_piece], *pieces.hulls("piece", piece)[:4], pieces.corner[piece])]
        order = group_order(depth, owner)
        owner, self.index, self.whole = owner[order], self.index[order], self.whole[order]
        self.count = np.bincount(owner, minlength=first.size)
        self.start = np.cumsum(self.count) - self.count


def _grown(grown, level, index, pieces):
    """(grown, hulls, lean) for _close of the hulls `index` (K,) at `level`: a chain's grown by its slack, with its
    lean."""
    hulls = pieces.hulls(level, index) + (pieces.corners(level, index),)
    if level == "chain":
        return grown + pieces.chain_slack[index], hulls, pieces.chain_lean[index]
    return grown, hulls, None


def _close(a, b, grown, hulls, lean=None):
    """(K,) bool: the segments a … b (K, 3) grown by `grown` (K,) not surely apart from the hulls (c0, c1, axis,
    radius, height, corner) (K each; a chain's grown by its slack, and lean (K,) its lean): the flat cylinder's test
    (inprocess._apart), and where it leaves a pair open and the tool has a corner, the corner's (_corner_apart)."""
    corner = hulls[5]
    close = ~_apart(a, b, *hulls[:5], grown, lean)
    bent = np.flatnonzero(close & (corner > 0.0))
    if bent.size:
        slack = grown[bent] if lean is None else grown[bent] + lean[bent] * np.hypot(hulls[3][bent], hulls[4][bent])
        close[bent] = ~_corner_apart(a[bent], b[bent], *(h[bent] for h in hulls[:4]), corner[bent], slack)
    return close


def _corner_apart(a, b, c0, c1, axis, big, corner, slack):
    """(K,) bool: the segments a … b (K, 3) grown by slack (K,) surely miss the hulls (c0, c1, axis, radius big) of
    tools with a corner radius (K,) > 0, by more than inprocess._CLEAR.

    The tool is the points within r (its corner radius) of K = {a ≥ r, |b| ≤ R − r} (below its top), so its sweep
    lies within r of K's sweep. A point y whose distance seen along the axis from the path is e, and whose height
    above the path's lowest bottom is h, lies at least hypot(max(e − (R − r), 0), max(r − h, 0)) from K's sweep
    (across the axis K reaches R − r from the path, along it no lower than r above that bottom); over the segment
    both bounds are taken at their least (inprocess._seen_along, the higher end)."""
    qa, e, d = a - c0, b - a, c1 - c0
    aa, ew, dw = row_dot(qa, axis), row_dot(e, axis), row_dot(d, axis)
    out = np.maximum(_seen_along(qa, e, d, aa, ew, dw) - (big - corner), 0.0)
    below = np.maximum(corner + np.minimum(dw, 0.0) - np.maximum(aa, aa + ew), 0.0)
    return np.hypot(out, below) > corner + slack + _CLEAR


def _depth(x, c0, c1, axis, big, corner):
    """(K,) about how far points x (K, 3) lie outside the hulls (c0, c1, axis, radius big, tools' corner radius)
    (negative: inside): seen along the axis and below the hull's lowest bottom, the corner rounded. Only the
    order in which units are taken (deepest first) comes from it."""
    across = _across(x, c0, c1, axis)
    height = row_dot(x - c0, axis) - np.minimum(row_dot(c1 - c0, axis), 0.0)
    rounded = np.hypot(np.maximum(across - (big - corner), 0.0), np.maximum(corner - height, 0.0)) - corner
    return np.maximum(rounded, np.maximum(across - big, -height))
