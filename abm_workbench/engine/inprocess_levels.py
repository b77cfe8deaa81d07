"""The level view of the in-process search: lines along the tool axis against the z levels of a program.

Roughing programs cut most of their material in moves across the tool axis at a few heights: every
move of a z level of a three-axis or 3+2 program. Such a move of a flat-end mill (axis w, its bottom
at height z along w, flute length H, radius r) sweeps the stadium of its path in plan (the plane
across w: the points within r of the path) times z … z + H along w. A line along w whose foot lies
at plan point P is inside that volume over its whole height range where P lies in the stadium, and
nowhere else: the question for such a line is a plan question, asked once per level, not once per
move.

Here the moves are grouped in levels (one axis for the whole program, the most common one; one
bottom height z and one tool per level, at least MIN_MOVES moves). Consecutive pieces of a
level with one radius make chains of up to CHAIN pieces, each bounded by its chord (first start to
last end, in plan) and its slack: every piece end lies within the slack of the chord, so the path's
distance from a point is the chord's within ± slack (the path runs from one end of the chord to the
other, so every point of the chord is within the slack of it too). Each level gets a grid in plan.
Per cell: the chain that comes first to hold the whole cell (chord within r − slack − half the cell's
diagonal of its centre, r less the tool's corner radius), and the chains that may reach into it (within
r + slack + half the diagonal), by their first move. A line asks its levels in ascending z, from the
lowest whose range reaches its material: in the cell of its foot, a chain that holds the cell and ends
before the line's CL point answers yes; no chain reaching the cell that begins before it answers no;
otherwise the chords of the chains reaching it are measured, then those of the quarters (runs of
CHAIN // 4 pieces) of the chains the chords leave in doubt (or that run past the CL point), then the pieces of
the quarters still in doubt. Where the answer is yes the removal is that of one piece's hull as the
closed form gives it (swept.line_hull_interval, as the general search solves it: the same numbers); a
line whose material is covered up to its top, from no higher than the next level's lowest end, needs no
higher level (they start there or higher and add nothing below). The levels of a tool with a corner
answer a line, and the end edges and corner arcs of any tool, by the pairs of the pieces near them
(inprocess_level_pairs), found through the same grid. Lengths in mm.
"""

import numpy as np

from .inprocess_level_pairs import MARGIN, expand, plan_distance, segment_distance, sides
from .inprocess_plan import earlier_radius
from .ordering import group_order
from .swept import clamp, every_column, kept, line_hull_interval, row_dot, rows
from .tolerances import LENGTH_EPS

#: Moves of one level (axis, z, H) at least for it to get a grid; the others stay with the general search.
MIN_MOVES = 16
#: Heights (mm) along the axis this near count as one: a move across the axis within it, a level's moves
#: within it of the next; a level spans at most LEVEL_SPAN (else its moves stay with the general search).
#: Both far above the rounding of points turned from a file's frame (some 10⁻¹² mm), far below MARGIN.
LEVEL_TOLERANCE = 1e-9
LEVEL_SPAN = 1e-8
#: Cells per smallest tool radius of a level along each plan direction.
CELLS_PER_RADIUS = 2
#: Pieces per chain at most, and the largest slack of a chain as a share of its radius (a chain that
#: bends more is cut in quarters, then in single pieces).
CHAIN = 32
CHAIN_SLACK = 0.25
#: Cells of one level's grid at most, and per piece of the level at most (at least MIN_CELLS; the cells
#: are made larger beyond either): some 24 bytes a cell, so at most some 400 bytes a level piece whatever
#: the levels' extent.
MAX_CELLS = 1 << 20
CELLS_PER_PIECE = 16
MIN_CELLS = 256
#: A move index larger than any (none).
_NONE = np.iinfo(np.int64).max


def level_moves(moves):
    """(axis (3,) or None, level (N,) int): for the rows j of a ProgramMoves, the level (0, 1, …; −1 none) of the
    cutting move into j: a move whose axis is the same at both ends and equal (bit for bit) to the program's most
    common such axis w, with both ends at the same height along w to LEVEL_TOLERANCE (a 3+2 program's points,
    turned from the file's frame, round differently); levels by tool (flute length, radius, corner radius) and
    height (heights LEVEL_TOLERANCE apart or nearer together, a level spanning at most LEVEL_SPAN), of at
    least MIN_MOVES moves."""
    n = len(moves)
    level = np.full(n, -1, dtype=np.intp)
    j = np.flatnonzero(moves.cutting[1:]) + 1
    j = j[(moves.axis[j] == moves.axis[j - 1]).all(axis=1)]
    if j.size == 0:
        return None, level
    axes, inverse, counts = np.unique(moves.axis[j], axis=0, return_inverse=True, return_counts=True)
    w = axes[np.argmax(counts)]
    j = j[inverse.reshape(-1) == np.argmax(counts)]
    ww = np.broadcast_to(w, (j.size, 3))
    z0, z1 = row_dot(moves.cl[j - 1], ww), row_dot(moves.cl[j], ww)
    across = np.abs(z1 - z0) <= LEVEL_TOLERANCE
    j, low, high = j[across], np.minimum(z0, z1)[across], np.maximum(z0, z1)[across]
    tool = np.stack([moves.flute_length[j], moves.radius[j], moves.corner_radius[j]])
    order = np.lexsort((low, *tool))
    j, low, high, tool = j[order], low[order], high[order], tool[:, order]
    new = np.ones(j.size, dtype=bool)
    new[1:] = (tool[:, 1:] != tool[:, :-1]).any(axis=0) | (low[1:] - low[:-1] > LEVEL_TOLERANCE)
    group = np.cumsum(new) - 1
    if j.size == 0:
        return None, level
    size = np.bincount(group)
    span = np.maximum.reduceat(high, np.flatnonzero(new)) - low[new]
    keep = (size >= MIN_MOVES) & (span <= LEVEL_SPAN)
    if not keep.any():
        return None, level
    number = np.cumsum(keep) - 1
    mine = keep[group]
    level[j[mine]] = number[group[mine]]
    return w, level


class LevelView:
    """The level pieces of a SweptPieces (flat-end hulls c0, c1 (P, 3), axis (P, 3), radius, height (P,),
    move (P,) their program row, non-decreasing), of which those at `index` (K,) ascending form the levels
    `level` (K,) (0, 1, …, as level_moves numbers them) about axis w (3,), in chains with a plan grid per level
    (module docstring)."""

    def __init__(self, c0, c1, axis, radius, height, corner, move, index, level, w):
        self.hull = (c0, c1, axis, radius, height)
        self.corner = corner
        self.move = move
        self.w = np.asarray(w, dtype=float)
        # On a coordinate axis the closed form's interval of a line along w inside a level hull is
        # −a0 … H − a0, a0 = (o − c0)·w, bit for bit (swept.line_hull_interval with u·w = 1, d·w = 0).
        self.aligned = bool(np.count_nonzero(self.w) == 1)
        helper = np.eye(3)[int(np.argmin(np.abs(self.w)))]
        u = np.cross(self.w, helper)
        self.u = u / np.linalg.norm(u)
        self.v = np.cross(self.w, self.u)
        index = np.asarray(index, dtype=np.intp)
        ww = np.broadcast_to(self.w, (index.size, 3))
        z0, z1 = row_dot(c0[index], ww), row_dot(c1[index], ww)
        # Levels in ascending height: each its lowest piece end, its flute length, and whether every piece end
        # lies at that height bit for bit (exact).
        count = int(level.max()) + 1 if level.size else 0
        self.z = np.full(count, np.inf)
        np.minimum.at(self.z, level, np.minimum(z0, z1))
        top = np.full(count, -np.inf)
        np.maximum.at(top, level, np.maximum(z0, z1))
        self.h, self.r, self.rc = np.zeros(count), np.zeros(count), np.zeros(count)
        self.h[level], self.r[level], self.rc[level] = height[index], radius[index], corner[index]
        self.exact = top == self.z
        rank = np.argsort(self.z, kind="stable")
        self.z, self.h, self.exact = self.z[rank], self.h[rank], self.exact[rank]
        self.r, self.rc = self.r[rank], self.rc[rank]
        level = np.argsort(rank)[level]
        self.first = np.full(count, _NONE)
        np.minimum.at(self.first, level, move[index])
        # The smallest first move of every run of 2^j levels from each (a sparse table): a line skips the levels
        # begun after its CL point (deeper levels of a program cut from the top down) in log2 steps.
        self.table = [self.first]
        while (1 << len(self.table)) <= count:
            half = 1 << (len(self.table) - 1)
            last = self.table[-1]
            self.table.append(np.minimum(last, np.r_[last[half:], np.full(half, _NONE)]))
        self.a, self.b = self.plan(c0), self.plan(c1)
        # The last level piece of each program row's move (−1: none), and its level.
        self.last = np.full(int(move.max()) + 1 if move.size else 0, -1, dtype=np.intp)
        tail = np.r_[move[index][1:] != move[index][:-1], True] if index.size else np.zeros(0, dtype=bool)
        self.last[move[index][tail]] = index[tail]
        self.piece_level = np.full(c0.shape[0], -1, dtype=np.intp)
        self.piece_level[index] = level
        self._chains(index, level, radius)
        self.origin = np.zeros((count, 2))
        self.size = np.zeros(count)
        self.shape = np.zeros((count, 2), dtype=np.int64)
        self.offset = np.zeros(count + 1, dtype=np.int64)
        order = np.argsort(self.chain_level, kind="stable")
        bounds = np.searchsorted(self.chain_level[order], np.arange(count + 1))
        parts = [self._grid(k, order[bounds[k]:bounds[k + 1]]) for k in range(count)]
        self.whole_move = np.concatenate([part[0] for part in parts])
        self.whole_chain = np.concatenate([part[1] for part in parts])
        # Cells held whole within the tool's full radius R (for a corner tool's sides above every level's corner,
        # inprocess_level_pairs.sides); within the rim already where no level's tool has a corner.
        bent = (self.rc > 0.0).any()
        self.full_move = np.concatenate([part[4] for part in parts]) if bent else self.whole_move
        self.full_chain = np.concatenate([part[5] for part in parts]) if bent else self.whole_chain
        cell = np.concatenate([part[2] + self.offset[k] for k, part in enumerate(parts)])
        self.entry_chain = np.concatenate([part[3] for part in parts])
        # Entries sorted by cell, then first move: the chains begun before a CL point are a prefix of its cell's.
        self.scale = int(move.max()) + 2 if move.size else 2
        self.key = cell * self.scale + self.chain_first_move[self.entry_chain]
        self.start = np.searchsorted(cell, np.arange(int(self.offset[-1]) + 1))

    def _chains(self, index, level, radius):
        """Chains of the level pieces `index` (level (K,) each): runs of consecutive pieces of one level and
        radius cut in blocks of CHAIN, a block whose slack passes CHAIN_SLACK·r in quarters, then in pieces.
        Sets chain_piece (the pieces of all chains, chain by chain), chain_start, chain_count, chain_level,
        chain_a, chain_b (C, 2) the chords, chain_slack, chain_radius, chain_first_move, chain_last_move."""
        n = index.size
        new = np.ones(n, dtype=bool)
        new[1:] = (np.diff(index) != 1) | (level[1:] != level[:-1]) | (radius[index[1:]] != radius[index[:-1]])
        run = np.cumsum(new) - 1
        rank = np.arange(n) - np.flatnonzero(new)[run]
        todo = np.ones(n, dtype=bool)
        heads, lengths, slacks = [], [], []
        for size in (CHAIN, CHAIN // 4, 1):
            at = np.flatnonzero(todo)
            block = run[at] * (n + 1) + rank[at] // size
            begin = np.flatnonzero(np.r_[True, block[1:] != block[:-1]])
            length = np.diff(np.r_[begin, at.size])
            head = at[begin]
            slack = self._slack(index, head, length) if size > 1 else np.zeros(head.size)
            good = slack <= CHAIN_SLACK * radius[index[head]]
            heads.append(head[good])
            lengths.append(length[good])
            slacks.append(slack[good])
            todo[at] = np.repeat(~good, length)
            if not todo.any():
                break
        head, length, slack = (np.concatenate(part) for part in (heads, lengths, slacks))
        order = np.argsort(head)
        head, length = head[order], length[order]
        self.chain_piece = index
        self.chain_start, self.chain_count, self.chain_slack = head, length, slack[order]
        self.chain_level = level[head]
        first, last = index[head], index[head + length - 1]
        self.chain_a, self.chain_b = self.a[first], self.b[last]
        self.chain_radius = radius[first]
        self.chain_rim = radius[first] - self.corner[first]
        self.chain_first_move, self.chain_last_move = self.move[first], self.move[last]
        # Each chain's quarters (runs of CHAIN // 4 of its pieces, the chain itself if no longer), bounded alike:
        # a chain in doubt hands over its quarters, a quarter in doubt its pieces.
        quarters = -(-length // (CHAIN // 4))
        owner, rank = expand(np.arange(head.size), np.zeros(head.size, dtype=np.intp), quarters)
        self.chain_quarter = np.cumsum(quarters) - quarters
        self.chain_quarters = quarters
        self.quarter_start = head[owner] + rank * (CHAIN // 4)
        self.quarter_count = np.minimum(head[owner] + length[owner] - self.quarter_start, CHAIN // 4)
        self.quarter_slack = self._slack(index, self.quarter_start, self.quarter_count)
        self.quarter_a = self.a[index[self.quarter_start]]
        self.quarter_b = self.b[index[self.quarter_start + self.quarter_count - 1]]
        self.quarter_radius = radius[index[self.quarter_start]]
        self.quarter_first_move = self.move[index[self.quarter_start]]
        self.quarter_last_move = self.move[index[self.quarter_start + self.quarter_count - 1]]

    def _slack(self, index, head, length):
        """(C,) the largest plan distance of the piece ends of the blocks index[head … head + length − 1] from
        their chords."""
        owner = np.repeat(np.arange(head.size), length)
        pos = head[owner] + np.arange(owner.size) - np.repeat(np.cumsum(length) - length, length)
        piece = index[pos]
        a, b = self.a[index[head]][owner], self.b[index[head + length - 1]][owner]
        gap = np.maximum(plan_distance(self.a[piece], a, b), plan_distance(self.b[piece], a, b))
        return np.maximum.reduceat(gap, np.cumsum(length) - length) if gap.size else np.zeros(0)

    def _grid(self, k, chains):
        """Level k's grid of its chains: (whole move, whole chain) per cell, and the entries (cell, chain)
        sorted by cell and the chain's first move. Sets the level's origin, cell size, shape and next offset."""
        a, b = self.chain_a[chains], self.chain_b[chains]
        reach = self.chain_radius[chains] + self.chain_slack[chains]
        low = np.minimum(a, b) - reach[:, None]
        high = np.maximum(a, b) + reach[:, None]
        origin = low.min(axis=0)
        size = float(self.chain_radius[chains].min()) / CELLS_PER_RADIUS
        extent = high.max(axis=0) - origin
        most = min(MAX_CELLS, max(MIN_CELLS, CELLS_PER_PIECE * int(self.chain_count[chains].sum())))
        # Counted in floating point (a tiny radius over a wide level would overflow integers).
        count = float(np.prod(np.floor(extent / size) + 1.0))
        if count > most:
            size *= max(float(np.sqrt(count / most)), 1.0)
        while float(np.prod(np.floor(extent / size) + 1.0)) > most:  # whole cells at the edges: a few steps
            size *= 1.1
        shape = np.floor(extent / size).astype(np.int64) + 1
        half = size * np.sqrt(0.5)
        self.origin[k], self.size[k], self.shape[k] = origin, size, shape
        self.offset[k + 1] = self.offset[k] + shape.prod()
        first = clamp(np.floor((low - half - origin) / size).astype(np.int64), 0, shape - 1)
        last = clamp(np.floor((high + half - origin) / size).astype(np.int64), 0, shape - 1)
        span = last - first + 1
        count = span[:, 0] * span[:, 1]
        owner = np.repeat(np.arange(chains.size), count)
        rank = np.arange(owner.size) - np.repeat(np.cumsum(count) - count, count)
        ix = first[owner, 0] + rank % span[owner, 0]
        iy = first[owner, 1] + rank // span[owner, 0]
        centre = origin + (np.stack([ix, iy], axis=1) + 0.5) * size
        distance = plan_distance(centre, a[owner], b[owner])
        gap = distance - self.chain_radius[chains][owner]
        slack = self.chain_slack[chains][owner]
        cell = iy * shape[0] + ix
        chain = chains[owner]
        cells = int(shape.prod())

        def holders(whole):
            """(move, chain) per cell: of the chains holding it whole, the one that ends first (_NONE, −1: none)."""
            whole_move = np.full(cells, _NONE)
            whole_chain = np.full(cells, -1, dtype=np.intp)
            if whole.any():
                when = self.chain_last_move[chain[whole]]
                order = np.lexsort((when, cell[whole]))
                at, when, which = cell[whole][order], when[order], chain[whole][order]
                head = np.r_[True, at[1:] != at[:-1]]
                whole_move[at[head]], whole_chain[at[head]] = when[head], which[head]
            return whole_move, whole_chain

        # Held whole: within the rim (the radius where a corner tool's bottom is flat; a flat-end mill's radius),
        # and within the full radius.
        rim = holders(distance - self.chain_rim[chains][owner] <= -slack - half - MARGIN)
        full = holders(gap <= -slack - half - MARGIN)
        near = gap <= slack + half + MARGIN
        order = np.lexsort((self.chain_first_move[chain[near]], cell[near]))
        return rim + (cell[near][order], chain[near][order]) + full

    def removals(self, origin, direction, lo, hi, before, group):
        """Removal intervals (line (K,), enter, leave (K,) mm) of the lines (origin (L, 3), direction (L, 3) = w)
        inside the level moves of program row at most before (L,), those that overlap the line's material
        lo … hi (L,) by more than LENGTH_EPS (as the general search keeps them); one or a few per line and
        level (group (L,): the lines' CL points, for the levels of a tool with a corner, inprocess_level_pairs)."""
        found = [(np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0))]
        if origin.shape[0] == 0 or self.z.size == 0:
            return found[0]
        height = row_dot(origin, np.broadcast_to(self.w, origin.shape))  # not a matrix product: no BLAS threads
        plan = self.plan(origin)
        tallest = float(self.h.max())
        level = self._begun(np.searchsorted(self.z, height + lo - tallest - MARGIN, side="left"), before)
        live = np.arange(origin.shape[0])
        while live.size:
            k = level[live]
            going = k < self.z.size
            live, k = live[going], k[going]
            going = self.z[k] - height[live] <= hi[live] + MARGIN
            live, k = live[going], k[going]
            if live.size == 0:
                break
            ask = (self.first[k] <= before[live]) & (self.z[k] + self.h[k] - height[live] >= lo[live] - MARGIN)
            bent = self.rc[k] > 0.0
            line, enter, leave = (np.concatenate(part) for part in zip(
                self._solved(live[ask & ~bent], k[ask & ~bent], origin, direction, plan, before),
                sides(self, live[ask & bent], k[ask & bent], group, origin, direction, plan, before)))
            with np.errstate(invalid="ignore"):
                hit = (np.minimum(leave, hi[line]) - np.maximum(enter, lo[line])) > LENGTH_EPS
            found.append((line[hit], enter[hit], leave[hit]))
            # Covered to its top from below the next level's lowest end: no later level adds anything.
            of = np.zeros(origin.shape[0], dtype=np.intp)
            of[live] = k
            above = np.r_[self.z[1:], np.inf][of[line]] - height[line]
            topped = np.zeros(origin.shape[0], dtype=bool)
            topped[line[hit & (leave >= hi[line]) & (enter <= above)]] = True
            live = live[~topped[live]]
            level[live] = self._begun(level[live] + 1, before[live])
        return tuple(np.concatenate(part) for part in zip(*found))

    def plan(self, points):
        """Plan coordinates (K, 2) of points (K, 3) (on a coordinate axis, two of their coordinates: the same
        numbers as the products with u and v, whose other components are 0)."""
        if self.aligned:
            columns = np.flatnonzero(self.w == 0.0)
            plan = points[:, columns] * np.array([self.u[columns[0]] + self.v[columns[0]],
                                                  self.u[columns[1]] + self.v[columns[1]]])
            return plan if abs(self.u[columns[0]]) == 1.0 else plan[:, ::-1]
        return np.stack([row_dot(points, np.broadcast_to(self.u, points.shape)),
                         row_dot(points, np.broadcast_to(self.v, points.shape))], axis=1)

    def levels_holding(self, origin, before):
        """(line, k, h) (K,): the levels k begun by program row before (L,) whose height range holds the points
        origin (L, 3) (h: the point's height above the level along w, within −MARGIN … H + MARGIN; in a level exact
        on a coordinate axis, where h is the closed form's own number, within 0 … H)."""
        height = row_dot(origin, np.broadcast_to(self.w, origin.shape))
        first = np.searchsorted(self.z, height - float(self.h.max()) - MARGIN, side="left")
        last = np.searchsorted(self.z, height + MARGIN, side="right")
        line, k = expand(np.arange(origin.shape[0]), first, last - first)
        h = height[line] - self.z[k]
        exact = self.aligned & self.exact[k]
        keep = (self.first[k] <= before[line]) & (h <= self.h[k] + MARGIN) & (~exact | ((h >= 0.0) & (h <= self.h[k])))
        return line[keep], k[keep], h[keep]

    def levels_meeting(self, origin, low, high, before):
        """(line, k) (K,): the levels k begun by program row before (L,) whose height range meets low … high (L,)
        above the points origin (L, 3) along w, to MARGIN."""
        height = row_dot(origin, np.broadcast_to(self.w, origin.shape))
        first = np.searchsorted(self.z, height + low - float(self.h.max()) - MARGIN, side="left")
        last = np.searchsorted(self.z, height + high + MARGIN, side="right")
        line, k = expand(np.arange(origin.shape[0]), first, last - first)
        keep = (self.first[k] <= before[line]) & (self.z[k] + self.h[k] >= height[line] + low[line] - MARGIN)
        return line[keep], k[keep]

    def previous(self, k, before):
        """(K,) the last piece of the move into program row before (K,) where that move belongs to level k (K,), else
        −1: the piece an edge of the next CL point most likely lies in."""
        piece = np.where((before >= 0) & (before < self.last.size), self.last[clamp(before, 0, self.last.size - 1)],
                         -1)
        return np.where((piece >= 0) & (self.piece_level[np.maximum(piece, 0)] == k), piece, -1)

    def piece_hulls(self, piece):
        """(c0, c1, axis, radius, height, corner) of the pieces (K,) (each (K, 3) or (K,))."""
        return tuple(rows(part, piece) for part in self.hull) + (rows(self.corner, piece),)

    def quarter_hulls(self, quarter):
        """(c0, c1, axis, radius, height, corner) of one hull per quarter (K,): from its first piece's start to its
        last piece's end, with its first piece's tool (the union of its pieces where these run along its chord)."""
        start = rows(self.quarter_start, quarter)
        first = rows(self.chain_piece, start)
        last = rows(self.chain_piece, start + rows(self.quarter_count, quarter) - 1)
        c0, c1, axis, radius, height = self.hull
        return (rows(c0, first), rows(c1, last), rows(axis, first), rows(radius, first), rows(height, first),
                rows(self.corner, first))

    def rim_of(self, piece):
        """(K,) the rim (radius less corner radius: where the tool's bottom is flat) of the tools of pieces (K,)."""
        return self.hull[3][piece] - self.corner[piece]

    def earlier_radius(self, k, h):
        """(K,) the plan radius of level k's tool at height h (K,) above its bottom (clipped to 0 … H)."""
        return earlier_radius(clamp(h, 0.0, self.h[k]), self.r[k], self.rc[k])

    def held(self, line, k, at, before, full=False):
        """(K,) the chain that holds the whole grid cell of the plan points at (K, 2) in level k within its rim (within
        its radius if full) and ends by program row before (K,), or −1."""
        shape = rows(self.shape, k)
        cell_xy = np.floor((at - rows(self.origin, k)) / rows(self.size, k)[:, None])
        inside = every_column((cell_xy >= 0) & (cell_xy < shape))
        cell_xy = np.where(inside[:, None], cell_xy, 0).astype(np.int64)
        cell = rows(self.offset, k) + cell_xy[:, 1] * shape[:, 0] + cell_xy[:, 0]
        move, chain = (self.full_move, self.full_chain) if full else (self.whole_move, self.whole_chain)
        return np.where(inside & (rows(move, cell) <= before), rows(chain, cell), -1)

    def near_chains(self, query, k, a, b, before):
        """(owner, chain) (K,): for the queries `query` (Q,, indices into k, a, b, before), the chains of level k[q]
        begun by program row before[q] that the grid lists in the cells of the bounding box of a[q] … b[q] ((N, 2)
        plan points; every chain with a piece within its radius of a point of that box), each once per query."""
        kq = rows(k, query)
        size = rows(self.size, kq)[:, None]
        shape = rows(self.shape, kq)
        aq, bq = rows(a, query), rows(b, query)
        low = clamp(np.floor((np.minimum(aq, bq) - self.origin[kq]) / size), -1.0, shape).astype(np.int64)
        high = clamp(np.floor((np.maximum(aq, bq) - self.origin[kq]) / size), -1.0, shape).astype(np.int64)
        meets = every_column((high >= 0) & (low < shape))
        low, high = np.maximum(low, 0), np.minimum(high, shape - 1)
        span = np.where(meets[:, None], high - low + 1, 0)
        count = span[:, 0] * span[:, 1]
        where, rank = expand(np.arange(query.size), np.zeros(query.size, dtype=np.intp), count)
        low, span, shape = rows(low, where), rows(span[:, 0], where), rows(shape[:, 0], where)
        ix = low[:, 0] + rank % span
        iy = low[:, 1] + rank // span
        cell = rows(self.offset, rows(kq, where)) + iy * shape + ix
        owner = rows(query, where)
        stop = np.searchsorted(self.key, cell * self.scale + rows(before, owner), side="right")
        start = rows(self.start, cell)
        owner, entry = expand(owner, start, stop - start)
        chain = rows(self.entry_chain, entry)
        if count.size and count.max() > 1:  # a chain listed in several cells of a query once
            chains = self.chain_start.size
            pair = np.unique(owner * chains + chain)
            owner, chain = pair // chains, pair % chains
        return owner, chain

    def quarters_near(self, owner, chain, a, b, reach, before):
        """(owner, quarter, low) (K,): the quarters of the chains `chain` (K,) begun by program row before[owner] whose
        chords lie within reach[owner] + slack + MARGIN of the plan segments a … b[owner] ((Q, 2); owner indexes the
        queries' arrays), and low: that distance less the slack (no piece of the quarter is nearer)."""
        owner, quarter = expand(owner, rows(self.chain_quarter, chain), rows(self.chain_quarters, chain))
        owner, quarter = kept(rows(self.quarter_first_move, quarter) <= rows(before, owner), owner, quarter)
        ao = rows(a, owner)
        low = segment_distance(ao, ao if a is b else rows(b, owner), rows(self.quarter_a, quarter),
                               rows(self.quarter_b, quarter))
        low -= rows(self.quarter_slack, quarter)
        return kept(low <= rows(reach, owner) + MARGIN, owner, quarter, low)

    def quarter_pieces(self, owner, quarter, before):
        """(owner, piece) (K,): the pieces of the quarters (K,) of program row at most before[owner]."""
        owner, at = expand(owner, rows(self.quarter_start, quarter), rows(self.quarter_count, quarter))
        piece = rows(self.chain_piece, at)
        return kept(rows(self.move, piece) <= rows(before, owner), owner, piece)

    def _begun(self, k, before):
        """(K,) for each level index k (K,) the first level at or after it begun by program row before (K,)
        (first ≤ before), or the number of levels where none is."""
        levels = self.z.size
        for j in reversed(range(len(self.table))):
            skip = (k < levels) & (self.table[j][np.minimum(k, levels - 1)] > before)
            k = np.where(skip, k + (1 << j), k)
        return np.minimum(k, levels)

    def _solved(self, line, k, origin, direction, plan, before):
        """(line, enter, leave) (K,): each line's interval inside level k (K,) as the closed form gives it for
        one piece that holds its foot (NaN where none does; every piece within MARGIN of the foot's distance
        where its nearest lies on its radius up to MARGIN, so that the closed form's own slack decides)."""
        line_in, k_in = line, k
        at = plan[line]
        cell_xy = np.floor((at - self.origin[k]) / self.size[k][:, None]).astype(np.int64)
        inside = every_column((cell_xy >= 0) & (cell_xy < self.shape[k]))
        line, k, cell_xy = line[inside], k[inside], cell_xy[inside]
        cell = self.offset[k] + cell_xy[:, 1] * self.shape[k, 0] + cell_xy[:, 0]
        whole = self.whole_move[cell] <= before[line]
        chain = self.whole_chain[cell[whole]]
        sure = [(line[whole], self.chain_start[chain], self.chain_count[chain])]
        line, cell = line[~whole], cell[~whole]
        stop = np.searchsorted(self.key, cell * self.scale + before[line], side="right")
        line, chain = expand(line, self.start[cell], stop - self.start[cell])
        chain = self.entry_chain[chain]
        gap = plan_distance(plan[line], self.chain_a[chain], self.chain_b[chain]) - self.chain_radius[chain]
        slack = self.chain_slack[chain]
        held = (gap < -slack - MARGIN) & (self.chain_last_move[chain] <= before[line])
        sure.append((line[held], self.chain_start[chain[held]], self.chain_count[chain[held]]))
        yes = np.zeros(origin.shape[0], dtype=bool)
        yes[line[held]] = True
        yes[sure[0][0]] = True
        doubt = ~held & (gap <= slack + MARGIN) & ~yes[line]
        # The quarters of the chains in doubt, those begun before the CL point; then the pieces of the quarters
        # in doubt, those before it.
        line, quarter = expand(line[doubt], self.chain_quarter[chain[doubt]], self.chain_quarters[chain[doubt]])
        begun = self.quarter_first_move[quarter] <= before[line]
        line, quarter = line[begun], quarter[begun]
        gap = plan_distance(plan[line], self.quarter_a[quarter], self.quarter_b[quarter])
        gap -= self.quarter_radius[quarter]
        slack = self.quarter_slack[quarter]
        held = (gap < -slack - MARGIN) & (self.quarter_last_move[quarter] <= before[line])
        sure.append((line[held], self.quarter_start[quarter[held]], self.quarter_count[quarter[held]]))
        yes[line[held]] = True
        doubt = ~held & (gap <= slack + MARGIN) & ~yes[line]
        line, at = expand(line[doubt], self.quarter_start[quarter[doubt]], self.quarter_count[quarter[doubt]])
        piece = self.chain_piece[at]
        piece_gap = plan_distance(plan[line], self.a[piece], self.b[piece]) - self.hull[3][piece]
        keep = (self.move[piece] <= before[line]) & (piece_gap <= MARGIN)
        line, at, piece_gap = line[keep], at[keep], piece_gap[keep]
        held = piece_gap < -MARGIN
        sure.append((line[held], at[held], np.ones(int(held.sum()), dtype=np.intp)))
        yes[line[held]] = True
        solve_line, solve_piece = line[~yes[line]], self.chain_piece[at[~yes[line]]]
        # One piece per line held for sure: the first of its run where the axis is a coordinate axis and the
        # level exact (any piece of the level gives the same numbers), else the run's piece nearest to it.
        sure_line, sure_start, sure_count = (np.concatenate(part) for part in zip(*sure))
        first = np.unique(sure_line, return_index=True)[1]
        sure_line, sure_start, sure_count = sure_line[first], sure_start[first], sure_count[first]
        fast = np.zeros(sure_line.size, dtype=bool)
        if self.aligned:
            of = np.zeros(origin.shape[0], dtype=np.intp)
            of[line_in] = k_in
            fast = self.exact[of[sure_line]]
        chosen = self.chain_piece[sure_start[fast]]
        c0, _, _, _, h = self.hull
        a0 = row_dot(origin[sure_line[fast]] - c0[chosen], np.broadcast_to(self.w, (chosen.size, 3)))
        slow = np.flatnonzero(~fast)
        nearest = self.nearest(sure_line[slow], sure_start[slow], sure_count[slow], plan)
        line = np.concatenate([sure_line[fast], sure_line[slow], solve_line])
        piece = np.concatenate([nearest, solve_piece])
        enter, leave = line_hull_interval(origin[line[fast.sum():]], direction[line[fast.sum():]],
                                          *(part[piece] for part in self.hull))
        return line, np.concatenate([-a0, enter]), np.concatenate([h[chosen] - a0, leave])

    def nearest(self, line, start, count, plan):
        """(K,) for each line (K,, distinct) the piece nearest to its foot in plan of its run of pieces
        chain_piece[start … start + count − 1]."""
        owner, at = expand(np.arange(line.size), start, count)
        candidate = self.chain_piece[at]
        gap = plan_distance(plan[line[owner]], self.a[candidate], self.b[candidate])
        order = group_order(gap, owner)
        head = order[np.r_[True, owner[order][1:] != owner[order][:-1]]] if order.size else order
        return candidate[head]
