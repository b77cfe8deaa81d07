"""The level view for tools with a corner: each edge against the level pieces near it in plan, nearest first.

A bull-nose or ball-end mill moving across its axis at a level sweeps a solid whose radius in plan depends on the
height above its bottom (ρ_e(h), inprocess_plan). So the level view's one plan question per line and level (the
flat-end mill's, inprocess_levels) does not answer an edge here: a straight side's removal starts where the
nearest piece's corner reaches it, an end edge's and a corner arc's removals are unions over the pieces near them.
The view hands every edge the pieces near it instead, and each (edge, piece) pair is solved as the general search
solves it (inprocess_plan's closed forms, inprocess_arc where those do not decide).

The pieces near an edge are found once per group (GROUP consecutive edges: angles of one CL point) and level: the
chains the grid lists in the cells of the box of the group's edges in plan, their chords within reach of the box
(every piece that comes within reach of an edge of the group is among them: an earlier tool's points lie within
its radius, its reach, of its path in plan), then per edge the chords, quarters and pieces within reach of its own
plan segment. End edges and arcs take their levels nearest first, in each first the piece into the previous CL
point, then their quarters nearest first in rounds of 1, 2, 4, … per edge; after each round the edge's envelope
(its material less what the removals found cover from either end without a gap, inprocess_cover.narrow) narrows,
and a quarter or piece whose plan distance from what is left exceeds its reach is dropped, its removal lying in
what is covered or beyond the material: the union of the removals over the material is that of all the pairs, so
the lengths are those of the general search (whose removals are the same pairs' numbers; a straight quarter is
solved as its one hull, the union of its pieces). Straight sides take the nearest pieces alone (their removal
starts lowest there), found by branch and bound. docs/ENGINE.md, "The level view for tools with a corner". Lengths
in mm, ψ in radians.
"""

import numpy as np

from .inprocess_cover import narrow, run_starts
from .inprocess_plan import arc_kinds, arc_piece_intervals, piece_line_interval
from .ordering import group_order
from .swept import clamp, kept, row_dot, rows
from .tolerances import LENGTH_EPS

#: Edges per group (consecutive rows, the angles of a CL point): a group's candidate pieces are searched once.
GROUP = 16
#: Margin (mm) of the plan tests: a cell held "whole" is inside by more than this, a piece that "may reach" an edge
#: may be this much beyond it. Far above the rounding of the plan distances and the closed forms' own slack
#: (swept.FEASIBLE_EPS, 1e-9 mm), far below any length that matters.
MARGIN = 1e-7


def expand(owner, start, count):
    """(owner, position) (Σ count,): for each owner (n,), the positions start … start + count − 1."""
    count = np.maximum(count, 0)
    # Each owner's start less the number of positions before its own: plus the running index, its positions.
    shift = start - (np.cumsum(count) - count)
    return np.repeat(owner, count), np.repeat(shift, count) + np.arange(int(count.sum()))


def norm(x, y):
    """(K,) the length of the plan vectors (x, y) (K,) in mm: np.hypot to within an ulp for lengths from 1e-150 to
    1e150 mm (0 below, where the squares underflow; its overflow guard is not needed within the inputs' 1e12 mm
    bound), in a tenth of its time (glibc's hypot, correctly rounded, costs about 25 ns a value)."""
    return np.sqrt(x * x + y * y)


def _toward(qx, qy, dx, dy, dd):
    """(K,) the plan distance of the points a + q from the segments a … a + d (columns qx, qy, dx, dy (K,); dd (K,) the
    squared length of d): the point's distance from the segment's nearest point (a itself where d = 0)."""
    # Where d = 0 so is the numerator: t = 0 (dd + 1 there; dd itself elsewhere, exactly).
    t = clamp((qx * dx + qy * dy) / (dd + (dd == 0.0)), 0.0, 1.0)
    return norm(qx - t * dx, qy - t * dy)


def plan_distance(p, a, b):
    """Distance (K,) in plan from points p (K, 2) to the segments a … b (K, 2) (a point where a = b)."""
    ax, ay = a[:, 0], a[:, 1]
    dx, dy = b[:, 0] - ax, b[:, 1] - ay
    return _toward(p[:, 0] - ax, p[:, 1] - ay, dx, dy, dx * dx + dy * dy)


def _point_distance(p, a, b):
    """segment_distance where each first segment is the point p (K, 2): the same numbers, a quarter of the work."""
    px, py, ax, ay, bx, by = p[:, 0], p[:, 1], a[:, 0], a[:, 1], b[:, 0], b[:, 1]
    dx, dy, qx, qy = bx - ax, by - ay, px - ax, py - ay
    # |a − p| is |p − a| bit for bit: the squares of opposite numbers are the same.
    return np.minimum(_toward(qx, qy, dx, dy, dx * dx + dy * dy), np.minimum(norm(qx, qy), norm(bx - px, by - py)))


def segment_distance(p0, p1, a, b):
    """Distance (K,) in plan between the segments p0 … p1 and a … b (K, 2) (either may be a point): 0 where they
    cross, else the least of the four ends' distances from the other segment (p0 given as p1: its distance). Rows
    where p0 = p1 (an arc's last point, most rows of a ball's arcs) take the point's three distances alone."""
    if p0 is p1:
        return plan_distance(p0, a, b)
    point = (p0[:, 0] == p1[:, 0]) & (p0[:, 1] == p1[:, 1])
    if point.all():
        return _point_distance(p0, a, b)
    if point.any():
        distance = np.empty(point.size)
        distance[point] = _point_distance(p0[point], a[point], b[point])
        rest = ~point
        distance[rest] = _segment_distance(p0[rest], p1[rest], a[rest], b[rest])
        return distance
    return _segment_distance(p0, p1, a, b)


def _segment_distance(p0, p1, a, b):
    """segment_distance of segments p0 … p1 (K, 2) of length: each difference of two ends taken once, shared by the
    four end distances and the two crossing tests (the same numbers as plan_distance and a side test per pair)."""
    ax, ay, bx, by = a[:, 0], a[:, 1], b[:, 0], b[:, 1]
    x0, y0, x1, y1 = p0[:, 0], p0[:, 1], p1[:, 0], p1[:, 1]
    dx, dy, ex, ey = bx - ax, by - ay, x1 - x0, y1 - y0
    dd, ee = dx * dx + dy * dy, ex * ex + ey * ey
    # The ends p0, p1 from a; a and b from p0.
    q0x, q0y, q1x, q1y = x0 - ax, y0 - ay, x1 - ax, y1 - ay
    rax, ray, rbx, rby = ax - x0, ay - y0, bx - x0, by - y0
    d = np.minimum(np.minimum(_toward(q0x, q0y, dx, dy, dd), _toward(q1x, q1y, dx, dy, dd)),
                   np.minimum(_toward(rax, ray, ex, ey, ee), _toward(rbx, rby, ex, ey, ee)))
    # Each segment's ends on either side of the other's line (the sign of a cross product).
    cross = (((dx * q0y - dy * q0x) * (dx * q1y - dy * q1x) < 0.0)
             & ((ex * ray - ey * rax) * (ex * rby - ey * rbx) < 0.0))
    return np.where(cross, 0.0, d)


def near_chains(view, group, k, a, b, reach, before):
    """(query, chain, low, high) (K,): for the queries (Q,) (an edge in a level: group (Q,) its CL point, k its level,
    a … b (Q, 2) its plan segment, reach (Q,) the largest plan distance at which a piece of that level can remove
    anything of it, before (Q,) the last program row before its CL point), the chains of the level begun by then
    whose chords come within reach + slack + MARGIN of the segment, found once per group and level (module
    docstring); low, high: the chord's distance less and plus its slack (bounds of its pieces' distance)."""
    if group.size == 0:
        return np.zeros(0, dtype=np.intp), np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0)
    key = group * view.z.size + k
    order = np.argsort(key, kind="stable")
    head, count = run_starts(key[order])
    low = np.minimum.reduceat(rows(np.minimum(a, b), order), head)
    high = np.maximum.reduceat(rows(np.maximum(a, b), order), head)
    middle = 0.5 * (low + high)
    wide = np.maximum.reduceat(rows(reach, order), head) + 0.5 * np.hypot(*(high - low).T)
    latest = np.maximum.reduceat(rows(before, order), head)
    owner, chain = view.near_chains(np.arange(head.size), rows(rows(k, order), head), low, high, latest)
    keep = plan_distance(rows(middle, owner), rows(view.chain_a, chain), rows(view.chain_b, chain)) \
        - rows(view.chain_slack, chain) <= rows(wide, owner) + MARGIN
    owner, chain = kept(keep, owner, chain)
    # Each group's chains, handed to each of its queries.
    first = np.searchsorted(owner, np.arange(head.size))
    total = np.bincount(owner, minlength=head.size)
    of = np.empty(key.size, dtype=np.intp)
    of[order] = np.repeat(np.arange(head.size), count)
    query, at = expand(np.arange(key.size), rows(first, of), rows(total, of))
    chain = rows(chain, at)
    aq = rows(a, query)
    distance = segment_distance(aq, aq if a is b else rows(b, query), rows(view.chain_a, chain),
                                rows(view.chain_b, chain))
    slack = rows(view.chain_slack, chain)
    return kept(distance - slack <= rows(reach, query) + MARGIN, query, chain, distance - slack, distance + slack)


def _least(query, value, size):
    """(size,) the least value (K,) per query (K,) (inf where none), by runs of equal queries (the queries here come
    grouped from expand; np.minimum.at costs several times a sort of them where they do not)."""
    least = np.full(size, np.inf)
    if query.size:
        order = np.argsort(query, kind="stable")
        head, _ = run_starts(query[order])
        least[query[order][head]] = np.minimum.reduceat(value[order], head)
    return least


def nearest_pieces(view, group, k, at, bound, before, exact):
    """(query, piece) (K,): for point queries (plan points at (Q, 2), otherwise as near_chains; bound (Q,) the
    largest distance that matters), the pieces within bound (+ MARGIN) of the point; where exact (Q,), only those
    within 2·MARGIN of the least such distance, by branch and bound: chains, then quarters, whose nearest piece
    cannot come that near are dropped (a chain or quarter ending by then bounds the least by its distance plus its
    slack)."""
    query, chain, low, high = near_chains(view, group, k, at, at, bound, before)
    done = rows(exact, query) & (rows(view.chain_last_move, chain) <= rows(before, query))
    best = np.minimum(bound, _least(query, np.where(done, high, np.inf), bound.size))
    query, chain = kept(low <= rows(best, query) + 2.0 * MARGIN, query, chain)
    query, quarter, low = view.quarters_near(query, chain, at, at, bound, before)
    done = rows(exact, query) & (rows(view.quarter_last_move, quarter) <= rows(before, query))
    best = np.minimum(best, _least(query, np.where(done, low + 2.0 * rows(view.quarter_slack, quarter), np.inf),
                                   bound.size))
    query, quarter = kept(low <= rows(best, query) + 2.0 * MARGIN, query, quarter)
    query, piece = view.quarter_pieces(query, quarter, before)
    gap = plan_distance(rows(at, query), rows(view.a, piece), rows(view.b, piece))
    best = np.minimum(best, _least(query, np.where(rows(exact, query), gap, np.inf), bound.size))
    return kept(gap <= rows(best, query) + 2.0 * MARGIN, query, piece)


def _first_least(key, value):
    """(K,) bool: in each run of equal keys (K,, non-decreasing), the first row of least value (K,, not NaN): the
    rows a stable sort by (key, value) puts first, without the sort."""
    lead = np.zeros(key.size, dtype=bool)
    if key.size:
        head, count = run_starts(key)
        least = np.flatnonzero(value == np.repeat(np.minimum.reduceat(value, head), count))
        lead[least[run_starts(np.repeat(np.arange(head.size), count)[least])[0]]] = True
    return lead


def rounds(view, query, quarter, owner, envelope, solve, segment, before, skip):
    """Removal parts [(query, enter, leave)] of the queries against the pieces of their quarters (query, quarter (K,),
    nearest first per query), in rounds of 1, 2, 4, … quarters per query (module docstring): a quarter, and then a
    piece, farther than reach + MARGIN in plan from what is left of its query's edge is dropped; a straight quarter
    (slack 0: its pieces run along its chord, and their union is the chord's hull) ending by then is solved as that
    one hull. In each round the nearest piece of each query is solved first, and the round's other pieces only where
    they still come within reach of what is left after it. owner (Q,): each query's edge, envelope (2, L): each
    edge's material (from, to; narrowed here); solve(query, hulls) → (query, enter, leave) of the pairs that remove
    something (hulls: c0, c1, axis, radius, height, corner of each pair's earlier tool); segment(query, from, to) →
    (a, b, reach): the plan segment a … b (K, 2) of that part of the query's edge and the plan distance reach (K,)
    beyond which no piece of the level removes anything of it; before (Q,) as for near_chains; skip (Q,): a piece
    each query has been solved against."""
    found = []
    if query.size == 0:
        return found

    def left(q):
        """The rows of q (K,) (grouped by query) whose query has material left, and each one's segment (a, b) and
        reach, each query's taken once."""
        edge = rows(owner, q)
        keep = np.flatnonzero(rows(envelope[0], edge) < rows(envelope[1], edge))
        first, many = run_starts(rows(q, keep))
        one = rows(keep, first)
        edge = rows(edge, one)
        a, b, reach = segment(rows(q, one), rows(envelope[0], edge), rows(envelope[1], edge))
        mine = np.repeat(np.arange(first.size), many)
        return keep, rows(a, mine), rows(b, mine), rows(reach, mine)

    def solved(parts):
        q = np.concatenate([part[0] for part in parts])
        found.append(solve(q, tuple(np.concatenate(h) for h in zip(*(part[1] for part in parts)))))
        narrow(envelope, rows(owner, found[-1][0]), *found[-1][1:])

    head, count = run_starts(query)
    # The runs (one per query) with quarters left, and their queries' edges.
    run, edge = np.arange(head.size), rows(owner, rows(query, head))
    done, size = 0, 1
    while True:
        # The next (up to) size quarters of each query with quarters and material left: the rows of ranks done …
        # done + size − 1 in its run, in the list's order, found without a pass over the whole list.
        run, edge = kept((rows(count, run) > done) & (rows(envelope[0], edge) < rows(envelope[1], edge)), run, edge)
        if run.size == 0:
            break
        _, at = expand(run, rows(head, run) + done, np.minimum(rows(count, run) - done, size))
        q, qu = rows(query, at), rows(quarter, at)
        keep, a, b, reach = left(q)
        q, qu = rows(q, keep), rows(qu, keep)
        slack = rows(view.quarter_slack, qu)
        keep = segment_distance(a, b, rows(view.quarter_a, qu), rows(view.quarter_b, qu)) - slack <= reach + MARGIN
        q, qu, a, b, reach, slack = kept(keep, q, qu, a, b, reach, slack)
        straight = (slack == 0.0) & (rows(view.quarter_last_move, qu) <= rows(before, q))
        parts = [(q[straight], view.quarter_hulls(qu[straight]))]
        bent = np.flatnonzero(~straight)
        row, pc = view.quarter_pieces(bent, rows(qu, bent), rows(before, q))  # (the segments are the quarters')
        row, pc = kept(pc != rows(skip, rows(q, row)), row, pc)
        gap = segment_distance(rows(a, row), rows(b, row), rows(view.a, pc), rows(view.b, pc))
        pq, pc, gap = kept(gap <= rows(reach, row) + MARGIN, rows(q, row), pc, gap)
        # Of each query's pieces the nearest first (at an arc's last point the deepest, most often the one that
        # removes most); the others only where they still come within reach of what is left after it.
        lead = _first_least(pq, gap)
        solved(parts + [(pq[lead], view.piece_hulls(pc[lead]))])
        pq, pc = kept(~lead, pq, pc)
        keep, a, b, reach = left(pq)
        pq, pc = rows(pq, keep), rows(pc, keep)
        keep = segment_distance(a, b, rows(view.a, pc), rows(view.b, pc)) <= reach + MARGIN
        solved([(pq[keep], view.piece_hulls(pc[keep]))])
        done, size = done + size, 2 * size
    return found


def _hits(query, enter, leave, lo, hi, scale=1.0):
    """(query, enter, leave) of the removals that overlap lo … hi (per query) by more than LENGTH_EPS (in mm: the
    overlap times scale)."""
    with np.errstate(invalid="ignore"):
        hit = (np.minimum(leave, rows(hi, query)) - np.maximum(enter, rows(lo, query))) * scale > LENGTH_EPS
    return kept(hit, query, enter, leave)


def _line_pairs(line, hulls, origin, direction):
    """(enter, leave) of lines (indices into origin, direction) in hulls (c0, c1, axis, radius, height, corner: the
    earlier tools', inprocess_plan.piece_line_interval)."""
    return piece_line_interval(rows(origin, line), rows(direction, line), *hulls)


def sides(view, line, k, group, origin, direction, plan, before):
    """(line, enter, leave) (K,): the intervals (NaN where none) of lines along w (indices line (L,) into origin,
    direction (N, 3), plan (N, 2), before (N,); group (N,) their CL points) inside the pieces of levels k (L,) of a
    tool with a corner, piece by piece: a side's removal runs from where the corner's radius reaches it (the
    nearer the piece, the lower) to the top. In a level exact on a coordinate axis every piece gives the same top,
    so a line whose foot lies within the rim (the tool's flat bottom) of a chain that holds its grid cell, or of the
    piece into its previous CL point, takes the interval of lift 0 alone; a line whose origin stands at least the
    level tool's corner radius above its bottom (its material lying at l ≥ 0), in a cell a chain holds within the
    tool's radius, the interval from the corner's top up (inside it wherever the nearest piece's corner starts);
    and any other line the pieces within 2·MARGIN of its nearest (nearest_pieces): every other piece's interval
    lies inside theirs. In other levels each piece within the level tool's radius gives its own."""
    at = rows(plan, line)
    fast = view.aligned & view.exact[k]
    alone = np.where(fast, view.held(line, k, at, before[line]), -1)
    one = np.flatnonzero(alone >= 0)
    held = view.chain_piece[view.chain_start[alone[one]]]
    c0, _, axis, _, height = view.hull
    # A line whose origin stands at least the level tool's corner radius above its bottom sees that tool's full
    # radius R at every height: a chain holding its cell within R removes it from the corner's top up, wherever the
    # nearest piece's corner would start its removal (lower). Its material lies at l ≥ 0 (from the origin up).
    full = np.flatnonzero(fast & (alone < 0))
    chain = view.held(line[full], k[full], rows(at, full), before[line[full]], full=True)
    full, chain = kept(chain >= 0, full, chain)
    first = view.chain_piece[view.chain_start[chain]]
    lift = row_dot(rows(origin, line[full]) - rows(c0, first), rows(axis, first))
    above = lift >= view.rc[k[full]]
    full, first, lift = full[above], first[above], lift[above]
    alone[full] = -2
    # The piece into the previous CL point: where it holds the foot within its rim its interval is the answer; else
    # its distance bounds the nearest's.
    previous = np.where(alone == -1, view.previous(k, before[line]), -1)
    has = np.flatnonzero(previous >= 0)
    bound = view.r[k]
    gap = plan_distance(rows(at, has), rows(view.a, previous[has]), rows(view.b, previous[has]))
    bound[has] = np.where(fast[has], np.minimum(bound[has], gap + 2.0 * MARGIN), bound[has])
    inner = has[fast[has] & (gap < view.rim_of(previous[has]) - MARGIN)]
    rest = np.flatnonzero(alone == -1)
    rest = rest[~np.isin(rest, inner)]
    query, piece = nearest_pieces(view, group[line[rest]], k[rest], rows(at, rest), bound[rest], before[line[rest]],
                                  fast[rest])
    solved = np.concatenate([line[inner], line[rest[query]]])
    enter, leave = _line_pairs(solved, view.piece_hulls(np.concatenate([previous[inner], piece])), origin, direction)
    # Held within the rim in a level exact on a coordinate axis: the closed form's interval of its nearest piece,
    # lift 0 (inprocess_plan._side_in_move), from any piece of the level (all give the same heights).
    up = row_dot(rows(origin, line[one]) - rows(c0, held), rows(axis, held))
    return (np.concatenate([line[one], line[full], solved]),
            np.concatenate([0.0 - up, view.rc[k[full]] - lift, enter]),
            np.concatenate([height[held] - up, height[first] - lift, leave]))


def ends(view, origin, direction, lo, hi, before, group):
    """Removal intervals (line (K,), enter, leave (K,) mm) of lines across w (origin, direction (L, 3), d·w = 0: the
    end edges of a tool with a corner; group (L,) their CL points) inside the level moves of program row at most
    before (L,), those overlapping the line's material lo … hi (L,) by more than LENGTH_EPS: in each level whose
    height range holds the line, the pieces near its segment lo … hi in plan, within the earlier tool's radius at
    that height (exactly that radius in a level exact on a coordinate axis, else the tool's radius), in rounds."""
    none = (np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))
    if origin.shape[0] == 0:
        return none
    plan, toward = view.plan(origin), view.plan(direction)
    line, k, h = view.levels_holding(origin, before)
    exact = view.aligned & view.exact[k]
    reach = np.where(exact, view.earlier_radius(k, h), view.r[k])
    material = rows(lo, line), rows(hi, line)

    def solve(q, hulls):
        enter, leave = _line_pairs(rows(line, q), hulls, origin, direction)
        return _hits(q, enter, leave, *material)

    plan_of, toward_of = rows(plan, line), rows(toward, line)  # (each query's)

    def segment(q, start, end):
        plan_at, toward_at = rows(plan_of, q), rows(toward_of, q)
        return plan_at + start[:, None] * toward_at, plan_at + end[:, None] * toward_at, rows(reach, q)

    found = _nearest_first(view, line, k, np.abs(h), group[line], before[line], np.stack([lo, hi]), solve, segment)
    return tuple(np.concatenate(part) for part in zip(none, *((line[q], e, x) for q, e, x in found)))


def _nearest_first(view, line, k, far, group, before, envelope, solve, segment):
    """Removal parts [(query, enter, leave)] of the queries (edge line (Q,) in level k (Q,); far (Q,) how far the
    level lies from the edge's tool along the axis: the nearest level first; group, before (Q,) the edge's CL point
    and last earlier program row; envelope (2, L) each edge's material, narrowed here; solve and segment as for
    rounds), level by level while an edge has material left: first against the last piece of the move into the
    previous CL point where that lies in the level (at a CL point of a pass it holds most of what the edges lost),
    then, for what is left, against the pieces near it (near_chains, found from the segments left: shorter than the
    edges), in rounds."""
    order = group_order(far, line)
    head, count = run_starts(line[order])
    rank = np.empty(line.size, dtype=np.intp)
    rank[order] = np.arange(line.size) - np.repeat(head, count)
    previous = view.previous(k, before)
    found = []
    for r in range(int(count.max()) if count.size else 0):
        mine = np.flatnonzero((rank == r) & (rows(envelope[0], line) < rows(envelope[1], line)))
        first = rows(mine, np.flatnonzero(rows(previous, mine) >= 0))
        found.append(solve(first, view.piece_hulls(rows(previous, first))))
        narrow(envelope, rows(line, found[-1][0]), *found[-1][1:])
        edge = rows(line, mine)
        left = rows(mine, np.flatnonzero(rows(envelope[0], edge) < rows(envelope[1], edge)))
        edge = rows(line, left)
        a, b, reach = segment(left, rows(envelope[0], edge), rows(envelope[1], edge))
        # What is left of an edge outside the level's heights (reach −inf): no piece of the level reaches it.
        left, a, b, reach = kept(reach > -np.inf, left, a, b, reach)
        latest = rows(before, left)
        query, chain, _, _ = near_chains(view, rows(group, left), rows(k, left), a, b, reach, latest)
        query, quarter, low = view.quarters_near(query, chain, a, b, reach, latest)
        order = group_order(low, query)
        found += rounds(view, rows(left, rows(query, order)), rows(quarter, order), line, envelope, solve, segment,
                        before, previous)
    return found


def arcs(view, tip, d, w, centre, lo, hi, before, group, big, radius, top, screen=None):
    """Removal intervals (arc (K,), start, end (K,) ψ) of corner arcs (tip, d, w (L, 3) their tool tip, direction
    across w and axis w, centre (L, 3); the tool's radius big, corner radius `radius`, last ψ top) inside the level
    moves of program row at most before (L,) (group (L,) their CL points), those overlapping the arc's material lo … hi (L,)
    (ψ) by more than LENGTH_EPS of arc length: in each level whose height range meets the arc's, the pieces within
    that level's radius of the arc's plan segment (its points at ρ = big − radius + radius·sin ψ from the axis), in
    rounds; each pair as the arcs' search solves it (inprocess_plan.arc_piece_intervals). screen(arc, hulls, low,
    high) (K,) → (K,) bool, if given: False for pairs whose earlier tool's hull (c0, c1, axis, radius, height,
    corner) is surely apart from the arc's part low … high (ψ), asked of the pairs the plan view does not decide
    (their solver costs more than that test)."""
    none = (np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))
    if tip.shape[0] == 0:
        return none
    plan, toward = view.plan(tip), view.plan(d)
    rim = big - radius
    line, k = view.levels_meeting(tip, radius * (1.0 - np.cos(lo)), radius * (1.0 - np.cos(hi)), before)
    # The part of each arc within the level's heights (its bottom and top above the arc's tip, to MARGIN): nothing
    # else of the arc can lie in that level's solids; the reach is the level tool's radius at the part's top.
    height = row_dot(tip, np.broadcast_to(view.w, tip.shape))[line]
    rise = view.z[k] - height
    bottom, roof = rise - MARGIN, rise + view.h[k] + MARGIN
    with np.errstate(invalid="ignore"):
        first = np.where(bottom > 0.0, np.arccos(clamp(1.0 - bottom / radius, -1.0, 1.0)), 0.0)
        last = np.where(roof < radius * (1.0 - np.cos(top)), np.arccos(clamp(1.0 - roof / radius, -1.0, 1.0)),
                        top)
    reach = view.earlier_radius(k, radius * (1.0 - np.cos(np.minimum(last, hi[line]))) - bottom) + MARGIN
    # The same tool at a level at or above the arc's tip (exact on a coordinate axis: the closed form's heights):
    # along the arc, a point's distance from a piece changes no faster than its distance ρ from the axis, and the
    # earlier tool's radius at the point's height grows at least as fast, so a piece that removes something of a
    # part of the arc holds its last point (docs/ENGINE.md, "The level view for tools with a corner").
    same = view.aligned & view.exact[k] & (view.r[k] == big) & (view.rc[k] == radius) & (rise >= 0.0)
    material = rows(lo, line), rows(hi, line)
    plan_of, toward_of = rows(plan, line), rows(toward, line)  # (each query's)

    def segment(q, start, end):
        # What is left of the arc outside the level's heights: no piece of the level reaches it.
        low, high = rows(first, q), rows(last, q)
        outside = (end < low) | (start > high)
        start, end = clamp(start, low, high), clamp(end, low, high)
        plan_at, toward_at = rows(plan_of, q), rows(toward_of, q)
        b = plan_at + (rim + radius * np.sin(end))[:, None] * toward_at
        # Of an arc against the same tool, its last point alone (a = b), within the earlier radius there.
        tight = rows(same, q)
        a, wide = b.copy(), np.flatnonzero(~tight)
        a[wide] = rows(plan_at, wide) + (rim + radius * np.sin(rows(start, wide)))[:, None] * rows(toward_at, wide)
        near = rows(reach, q)
        point = np.flatnonzero(tight)
        mine = rows(q, point)
        near[point] = view.earlier_radius(rows(k, mine), radius * (1.0 - np.cos(rows(end, point)))
                                          - rows(rise, mine) + MARGIN) + MARGIN
        near[outside] = -np.inf
        return a, b, near

    tool = (np.full(tip.shape[0], big), np.full(tip.shape[0], radius), np.full(tip.shape[0], top))

    def solve(q, hulls):
        at = rows(line, q)
        kinds = None
        if screen is not None:
            kinds = arc_kinds(tip[at], w[at], *(part[at] for part in tool[:2]), *hulls)
            general = np.flatnonzero(~np.any(kinds, axis=0))
            if general.size:
                keep = np.ones(q.size, dtype=bool)
                keep[general] = screen(at[general], tuple(part[general] for part in hulls), envelope[0, at[general]],
                                       envelope[1, at[general]])
                q, at = q[keep], at[keep]
                hulls, kinds = (tuple(part[keep] for part in parts) for parts in (hulls, kinds))
        pair, start, end = arc_piece_intervals(rows(tip, at), rows(d, at), rows(w, at), rows(centre, at),
                                               *(rows(part, at) for part in tool), *hulls, arc=at, kinds=kinds)
        return _hits(rows(q, pair), start, end, *material, radius)

    envelope = np.stack([lo, hi])
    far = np.abs(view.z[k] - row_dot(tip, np.broadcast_to(view.w, tip.shape))[line])
    found = _nearest_first(view, line, k, far, group[line], before[line], envelope, solve, segment)
    return tuple(np.concatenate(part) for part in zip(none, *((line[q], e, x) for q, e, x in found)))
