"""Engagement against the in-process stock: the stock minus what earlier cutting moves removed.

A program is one row per CL point of all its operations, in program order (ProgramMoves).
Move j goes from row j − 1 to row j; when it cuts it removes the volume swept by the tool's
cutting part (radius and flute length of row j), position and axis interpolated linearly (the
axis normalised). At CL point k the in-process stock is the stock minus the volumes of every
cutting move j ≤ k − 1. A move with a constant axis sweeps the convex hull of its end cylinders,
met by a line in closed form (swept.line_hull_interval); a move whose axis turns is replaced by
sub-steps of constant axis, each turning the tool by little enough that no point of the cutting
part moves more than the tolerance (docs/ENGINE.md gives the construction and the error).

Each edge line's inside intervals in the stock (an EdgeIntervals, as the staircase engine's
`inside_intervals` gives them) lose their parts inside those volumes. The pieces are grouped
in spans; a KD tree over bounding spheres of slices of the spans gives each CL point the spans near it, and
tests that prove a miss drop most pairs before the closed form, so the cost grows with the
moves near a point, not with the program's length (docs/ENGINE.md). Neighbouring CL points of a
pass meet nearly the same earlier moves: most are searched guided by the moves that bounded a
neighbour's material, then proved. Lengths in mm.
"""

import functools
from dataclasses import dataclass

import numpy as np

from .engagement import SURFACES
from .inprocess_balls import BallParts
from .inprocess_cover import narrow, run_starts
from .inprocess_level_pairs import GROUP, ends
from .inprocess_levels import LevelView, level_moves
from .inprocess_reach import capsule_spheres, group_capsules
from .inprocess_touch import touching
from .inprocess_plan import piece_line_interval
from .intervals import EdgeIntervals
from .ordering import group_order
from .swept import FEASIBLE_EPS, clamp, every_column, line_hull_interval, row_dot
from .swept import rows as _rows  # (this module names its rows of intervals `rows`)
from .tolerances import LENGTH_EPS

_MACHINED = SURFACES.index("machined")
#: A sure miss clears the hull by more than this (mm): the closed form counts points within
#: FEASIBLE_EPS of its boundary as inside, and the sure-miss test's rounding is far smaller.
_CLEAR = 2.0 * FEASIBLE_EPS
#: Tool axes closer than this to opposite (1 − |cos|) have no defined interpolation.
_OPPOSITE_EPS = 1e-12
#: Spans per chain at most.
_CHAIN = 8
#: A chain whose pieces all lie within this (mm) of its hull is rigid: solved as one hull. The
#: hull of a straight run of moves with one axis is the union of theirs; rounding puts its
#: pieces some 1e-15 mm off it.
_RIGID = 1e-12
#: Sub-steps per span at most (a turning move is cut into more spans rather than more sub-steps per span).
_SPAN_PIECES = 8
#: Pairs of (edge line, swept piece) solved per batch, to bound memory.
_PAIR_BATCH = 1 << 16
#: Runs of angles per CL point, each bounded by its own capsule (inprocess_reach.group_capsules).
_GROUPS = 18
#: Largest key range for which _distinct marks keys in a bool array rather than sorting them.
_MARK_LIMIT = 1 << 24
#: … and is at most this many times the number of keys (else sorting them is cheaper).
_MARK_SPARSE = 64
#: (edge line, span) pairs examined per batch, to bound memory.
_EXPAND_BATCH = 1 << 17
#: Chains, then spans, per group of edge lines and per criterion solved first (_probe).
_PROBE = 1
#: Chains per group whose spans _line_probe weighs for each of the group's lines.
_GUESSED_CHAINS = 3
#: Spans near a CL point's groups above which chains are tested per line, probes made and the
#: lines searched in waves (_waves); at most that many, chains go straight to (group, span)
#: pairs. Where the two cost the same (docs/ENGINE.md, step 1).
_FEW_SPANS = 64
#: Every _SAMPLE_EVERY-th CL point of a call (and every seed) is looked at to decide between the
#: two (_spans_per_point).
_SAMPLE_EVERY = 4
#: Every _SEED_EVERY-th CL point of a call is searched in full first (a power of 2); the
#: others follow in waves, each guided by a CL point of an earlier wave (_waves).
_SEED_EVERY = 16
#: Spans remembered per line as solved for it (_Solved).
_SOLVED = 4
#: Spheres per KD query of _sphere_chains (bounds the memory of the pairs it finds).
_SPHERE_BLOCK = 1024
#: Lines per KD query of _near_rest (their material's spheres meet few balls: a program's few moves off its levels).
_REST_BLOCK = 4096
#: Balls per part of the other moves of a program with levels (inprocess_balls.BallParts): a ramp or plunge
#: between levels in a part or two, so that a part above a line's material is skipped whole by its floor.
_FLOOR_BLOCK = 64


def _float_array(name, value, shape, copy=True):
    """A finite float array of `shape` (None matches any length), a copy unless `copy` is False;
    ValueError naming `name`."""
    array = np.array(value, dtype=float, copy=copy)
    if array.ndim != len(shape) or any(s is not None and s != a for s, a in zip(shape, array.shape)):
        raise ValueError(f"{name} must have shape {shape}, got {array.shape}")
    finite = np.isfinite(array)
    if not finite.all():
        bad = np.argwhere(~finite)[0]
        raise ValueError(f"{name}{list(int(i) for i in bad)} is not a finite number")
    return array


@dataclass(frozen=True)
class ProgramMoves:
    """Every CL point of a program, in program order, in one frame (mm).

    cl: (N, 3) bottom centre of the tool. axis: (N, 3) unit tool axis. cutting: (N,) bool, the
    move from row j − 1 to row j removes material (a rapid does not; row 0 has no move).
    radius, flute_length: (N,) the tool at row j (mm), which makes the move into row j.
    line: (N,) int, the source line of the row (−1 unknown), named in errors and warnings.
    corner_radius: (N,) the corner radius r of the tool at row j (mm, 0 ≤ r ≤ radius: 0 a flat-end
    mill, radius a ball-end mill), or None for flat-end mills throughout (zeros).
    """

    cl: np.ndarray
    axis: np.ndarray
    cutting: np.ndarray
    radius: np.ndarray
    flute_length: np.ndarray
    line: np.ndarray
    corner_radius: np.ndarray = None

    def __post_init__(self):
        cl = _float_array("cl", self.cl, (None, 3))
        n = cl.shape[0]
        axis = _float_array("axis", self.axis, (n, 3))
        norm = np.linalg.norm(axis, axis=1)
        bad = np.flatnonzero(np.abs(norm - 1.0) > 1e-6)
        line = np.array(self.line).astype(int).reshape(-1)
        if line.shape != (n,):
            raise ValueError(f"line must have shape ({n},), got {line.shape}")
        if bad.size:
            j = int(bad[0])
            raise ValueError(f"row {j} (line {line[j]}): tool axis {axis[j].tolist()} is not a unit vector")
        cutting = np.array(self.cutting, dtype=bool).reshape(-1)
        if cutting.shape != (n,):
            raise ValueError(f"cutting must have shape ({n},), got {cutting.shape}")
        for name in ("radius", "flute_length"):
            values = _float_array(name, self.__dict__[name], (n,))
            low = np.flatnonzero(values <= 0.0)
            if low.size:
                j = int(low[0])
                raise ValueError(f"row {j} (line {line[j]}): {name} must be positive, got {values[j]}")
            object.__setattr__(self, name, values)
        corner = np.zeros(n) if self.corner_radius is None else _float_array("corner_radius", self.corner_radius, (n,))
        wrong = np.flatnonzero((corner < 0.0) | (corner > self.radius))
        if wrong.size:
            j = int(wrong[0])
            raise ValueError(f"row {j} (line {line[j]}): corner_radius must be within [0, radius {self.radius[j]:g}], "
                             f"got {corner[j]}")
        object.__setattr__(self, "corner_radius", corner)
        opposite = np.flatnonzero(cutting[1:] & (row_dot(axis[1:], axis[:-1]) < -1.0 + _OPPOSITE_EPS)) + 1
        if opposite.size:
            j = int(opposite[0])
            raise ValueError(f"row {j} (line {line[j]}): the tool axis turns by 180° in one cutting move")
        object.__setattr__(self, "cl", cl)
        object.__setattr__(self, "axis", axis / norm[:, None])
        object.__setattr__(self, "cutting", cutting)
        object.__setattr__(self, "line", line)

    def __len__(self):
        return self.cl.shape[0]

    def transformed(self, rotation, translation):
        """The same program in another frame: p' = R·p + t for the points, R·a for the axes.

        rotation: (3, 3) orthonormal; translation: (3,) mm.
        """
        rotation = _float_array("rotation", rotation, (3, 3))
        if not np.allclose(rotation @ rotation.T, np.eye(3), atol=1e-9):
            raise ValueError("rotation must be an orthonormal 3×3 matrix")
        translation = _float_array("translation", translation, (3,))
        return ProgramMoves(self.cl @ rotation.T + translation, self.axis @ rotation.T, self.cutting, self.radius,
                            self.flute_length, self.line, self.corner_radius)


@dataclass(frozen=True)
class SweptPieces:
    """The cutting moves of a program as P constant-axis pieces grouped in S spans and C chains,
    with a KD tree over the chains.

    Pieces: c0, c1 (P, 3) bottom centres at the piece's ends; axis (P, 3) unit; radius, height
    (P,) (mm); move (P,) the program row j ending the move the piece belongs to.
    Spans (consecutive pieces of one move): first, count (S,) their pieces; move (S,) as above;
    c0, c1 (S, 3), axis (S, 3), height (S,): the span as one constant-axis hull, and slack (S,)
    (mm): every piece of the span lies within slack of that hull with its radius, the axes of
    its pieces within turn/2 (S,) (rad) of the span's axis.
    Chains (runs of consecutive spans of one tool, no longer than its radius): chain_first,
    chain_count (C,) their spans; chain_move (C,) the first move; chain_c0, chain_c1,
    chain_axis (C, 3), chain_radius, chain_height (C,): one constant-axis hull from the first
    span's start to the last one's end; chain_slack (C,): the pieces' bottom centres lie
    within that of its path, chain_lean (C,): their axes within that of its axis (|w_p − w|);
    chain_rise (C,) (≤ chain_slack): those bottom centres lie within that, along the chain's axis,
    of the axial range of its path (0 for a run of moves in one plane across a constant axis);
    chain_rigid (C,) bool: slack and lean put every piece within _RIGID of the chain's hull, which
    is then the union of its pieces (a straight run with a constant axis) and is solved whole;
    chain_last (C,): its last move.
    Balls: each chain's height cut in slices about as tall as its radius, each in a bounding
    sphere (ball_chain (B,) its chain, ball_centre (B, 3), ball_bound (B,)); tree: the
    balls in parts with a KD tree each (inprocess_balls.BallParts).
    tolerance: the largest distance (mm) any point of the tool moves within one piece by the
    turning of its axis.
    corner, span_corner, chain_corner: (P,), (S,), (C,) the tool's corner radius (mm; None: 0, flat-end
    mills throughout). The tool solid is then the cylinder of its radius and height with the bottom
    rim rounded by the corner radius (docs/ENGINE.md, "Tools with a corner in the in-process
    stock"); it lies inside the cylinder, so every bound made for the cylinder holds for it.
    levels: the pieces of the program's z levels in plan (inprocess_levels.LevelView), None where it has
    none; rest: the SweptPieces of its other cutting moves (None with levels None). Lines along the levels'
    axis are searched in both; every other consumer takes these pieces whole.
    """

    c0: np.ndarray
    c1: np.ndarray
    axis: np.ndarray
    radius: np.ndarray
    height: np.ndarray
    move: np.ndarray
    span_first: np.ndarray
    span_count: np.ndarray
    span_move: np.ndarray
    span_c0: np.ndarray
    span_c1: np.ndarray
    span_axis: np.ndarray
    span_height: np.ndarray
    span_radius: np.ndarray
    span_slack: np.ndarray
    span_turn: np.ndarray
    chain_first: np.ndarray
    chain_count: np.ndarray
    chain_move: np.ndarray
    chain_c0: np.ndarray
    chain_c1: np.ndarray
    chain_axis: np.ndarray
    chain_radius: np.ndarray
    chain_height: np.ndarray
    chain_slack: np.ndarray
    chain_lean: np.ndarray
    chain_rise: np.ndarray
    chain_rigid: np.ndarray
    chain_last: np.ndarray
    ball_chain: np.ndarray
    ball_centre: np.ndarray
    ball_bound: np.ndarray
    tree: BallParts
    tolerance: float
    corner: np.ndarray = None
    span_corner: np.ndarray = None
    chain_corner: np.ndarray = None
    levels: LevelView = None
    rest: "SweptPieces" = None

    def __post_init__(self):
        for name, like in (("corner", "radius"), ("span_corner", "span_radius"), ("chain_corner", "chain_radius")):
            if getattr(self, name) is None:
                object.__setattr__(self, name, np.zeros(getattr(self, like).shape))

    @property
    def any_corner(self):
        """Whether some piece's tool has a corner radius (corner)."""
        return bool(self.corner.any())

    def corners(self, level, index):
        """(K,) the corner radius of the tools of the pieces, spans or chains at index (K,)."""
        return _rows(self.corner if level == "piece" else getattr(self, level + "_corner"), index)

    @property
    def any_rigid(self):
        """Whether some chain is rigid (chain_rigid)."""
        return bool(self.chain_rigid.any())

    def hulls(self, level, index):
        """(c0, c1, axis, radius, height) (K, 3), (K, 3), (K, 3), (K,), (K,) of the constant-axis
        hulls of the pieces, spans or chains (level "piece", "span" or "chain") at index (K,)."""
        prefix = "" if level == "piece" else level + "_"
        return tuple(_rows(getattr(self, prefix + name), index) for name in ("c0", "c1", "axis", "radius", "height"))


def _turned(theta, fraction):
    """Interpolation parameter t along a move where the normalised linear interpolation of its
    axis has turned by fraction·Θ: t = sin θ / (sin θ + sin(Θ − θ)) (t = fraction when Θ = 0)."""
    angle = fraction * theta
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.sin(angle) / (np.sin(angle) + np.sin(theta - angle))
    return np.where(theta > 0.0, t, fraction)


def _steps(p0, p1, w0, w1, theta, index, count):
    """Positions (K, 3) at the start and end of step `index` of `count` equal turning steps of
    the moves (p0, p1, w0, w1, theta: per step), and the axis (K, 3) at its middle angle."""
    n = count.astype(float)
    t0, t1, tm = (_turned(theta, f) for f in (index / n, (index + 1) / n, (index + 0.5) / n))
    c0 = p0 + t0[:, None] * (p1 - p0)
    c1 = p0 + t1[:, None] * (p1 - p0)
    axis = (1.0 - tm)[:, None] * w0 + tm[:, None] * w1
    return c0, c1, axis / np.linalg.norm(axis, axis=1)[:, None]


def _csr(count):
    """For counts (n,): the owner (sum,) of each item and its rank within its owner."""
    owner = np.repeat(np.arange(count.size), count)
    return owner, np.arange(owner.size) - np.repeat(np.cumsum(count) - count, count)


def swept_pieces(moves: ProgramMoves, tolerance=0.05, levels=True, floor_axis=None):
    """The cutting moves of `moves` as constant-axis pieces in spans (SweptPieces).

    A move whose axis turns by Θ (rad) is cut into n ≥ Θ·ρ/tolerance sub-steps (ρ = the largest
    distance from the bottom centre to a point of the cutting part, √(r² + H²)) at equal angles
    of the interpolated axis; sub-step i keeps the axis at its middle angle and runs between the
    interpolated positions at its ends. Moves are also cut into spans no longer than about ρ
    (exact: the hulls of consecutive parts of a straight move make up the hull of the move)
    and of at most _SPAN_PIECES sub-steps, each span a whole number of sub-steps, so that
    bounding volumes stay small and a span that comes near a line hands it few pieces.
    With `levels`, the moves of the program's z levels (inprocess_levels.level_moves) also get their plan
    view, and the other moves their own SweptPieces (levels, rest), whose balls get floors along the levels'
    axis (floor_axis: _floors) in parts of _FLOOR_BLOCK balls.
    """
    tolerance = float(tolerance)
    if not tolerance > 0.0:
        raise ValueError(f"tolerance must be positive, got {tolerance}")
    j = np.flatnonzero(moves.cutting[1:]) + 1
    w0, w1 = moves.axis[j - 1], moves.axis[j]
    p0, p1 = moves.cl[j - 1], moves.cl[j]
    radius, height, corner = moves.radius[j], moves.flute_length[j], moves.corner_radius[j]
    rho = np.hypot(radius, height)
    turn = np.arccos(np.clip(row_dot(w0, w1), -1.0, 1.0))
    steps = np.ceil(turn * rho / tolerance)
    spans = np.maximum(np.maximum(np.ceil(np.linalg.norm(p1 - p0, axis=1) / rho), np.ceil(steps / _SPAN_PIECES)),
                       1).astype(np.intp)
    per_span = np.maximum(np.ceil(steps / spans), 1).astype(np.intp)
    # Spans: equal turning steps of their move.
    span_of, span_index = _csr(spans)
    s0, s1, s_axis = _steps(p0[span_of], p1[span_of], w0[span_of], w1[span_of], turn[span_of], span_index,
                            spans[span_of])
    s_radius, s_height = radius[span_of], height[span_of]
    # Within a span the axis turns by Θ/spans: every point of the tool stays within
    # ρ·Θ/(2·spans) of the same point turned to the span's middle axis.
    slack = 0.5 * rho[span_of] * turn[span_of] / spans[span_of]
    # Pieces: per_span equal turning steps of each span's move, in order.
    count = per_span[span_of]
    owner, rank = _csr(count)
    move = span_of[owner]
    c0, c1, axis = _steps(p0[move], p1[move], w0[move], w1[move], turn[move], span_index[owner] * count[owner] + rank,
                          spans[move] * count[owner])
    first = np.cumsum(count) - count
    s_corner = corner[span_of]
    chains = _chains(j[span_of], s0, s1, s_axis, s_radius, s_height, c0, c1, axis, owner, s_corner)
    if floor_axis is None:
        balls = BallParts(chains[-2], chains[-1], chains[2][chains[-3]])
    else:
        floor = _floors(c0, c1, axis, first[chains[0]], floor_axis)
        balls = BallParts(chains[-2], chains[-1], chains[2][chains[-3]], floor[chains[-3]], _FLOOR_BLOCK)
    view = rest = None
    w, level = level_moves(moves) if levels else (None, None)
    if w is not None:
        of_piece = level[j[move]]
        index = np.flatnonzero(of_piece >= 0)
        view = LevelView(c0, c1, axis, radius[move], height[move], corner[move], j[move], index, of_piece[index], w)
        others = ProgramMoves(moves.cl, moves.axis, moves.cutting & (level < 0), moves.radius, moves.flute_length,
                              moves.line, moves.corner_radius)
        rest = swept_pieces(others, tolerance, levels=False, floor_axis=w)
    return SweptPieces(c0, c1, axis, radius[move], height[move], j[move], first, count, j[span_of], s0, s1, s_axis,
                       s_height, s_radius, slack, turn[span_of] / spans[span_of], *chains, balls,
                       tolerance, corner[move], s_corner, s_corner[chains[0]], view, rest)


def _floors(c0, c1, axis, chain_start, w):
    """(C,) each chain's floor along w (3,): the least height c·w of its pieces' bottom centres (c0, c1 (P, 3),
    axis (P, 3), the chains' pieces from chain_start (C,) on, in order), below which its tools have no point
    (every point of a tool lies 0 … H along its axis above its bottom centre); −inf for a chain with a piece
    whose axis is not w (bit for bit)."""
    if chain_start.size == 0:
        return np.zeros(0)
    ww = np.broadcast_to(w, c0.shape)
    low = np.where(every_column(axis == w), np.minimum(row_dot(c0, ww), row_dot(c1, ww)), -np.inf)
    return np.minimum.reduceat(low, chain_start)


def _chains(span_move, s0, s1, s_axis, radius, height, c0, c1, axis, piece_span, corner=None):
    """The chains of the spans (SweptPieces's chain_… and ball_… fields, in order).

    span_move, radius, height, corner (S,), s0, s1, s_axis (S, 3): the spans; c0, c1, axis (P, 3), piece_span
    (P,): the pieces and their span. A chain breaks where the moves stop following each other
    or the tool changes (radius, height or corner radius), and after _CHAIN spans or a path as long as the tool's radius. Its
    axis w is the mean of its spans' axes; its slack the largest distance of a piece's ends
    from its path, its lean the largest |w_p − w| of a piece's axis w_p, its rise the largest
    distance along w of a piece's end beyond the axial range of its path (see _apart).
    """
    n = span_move.size
    step = np.linalg.norm(s1 - s0, axis=1)
    corner = np.zeros(n) if corner is None else corner
    run = (np.cumsum(np.r_[True, (np.diff(span_move) > 1) | (np.diff(radius) != 0) | (np.diff(height) != 0)
                           | (np.diff(corner) != 0)]) - 1)[:n]
    run_first = np.flatnonzero(np.r_[True, run[1:] != run[:-1]]) if n else np.zeros(0, dtype=np.intp)
    before = np.cumsum(step) - step
    along = before - before[run_first][run]
    rank = np.arange(n) - run_first[run]
    key = np.stack([run, rank // _CHAIN, np.floor(along / radius)])
    new = np.r_[True, (key[:, 1:] != key[:, :-1]).any(axis=0)] if n else np.zeros(0, dtype=bool)
    chain = np.cumsum(new) - 1
    first = np.flatnonzero(new)
    count = np.diff(np.r_[first, n])
    last = first + count - 1
    mean = np.add.reduceat(s_axis, first, axis=0) if n else np.zeros((0, 3))
    chain_axis = mean / np.linalg.norm(mean, axis=1)[:, None]
    ch0, ch1 = s0[first], s1[last]
    piece_chain = chain[piece_span]
    d = ch1[piece_chain] - ch0[piece_chain]
    start = ch0[piece_chain]
    off = np.maximum(_point_distance(c0 - start, d), _point_distance(c1 - start, d))
    # Pieces come span by span and spans chain by chain, each chain with at least one piece.
    piece_first = np.flatnonzero(np.r_[True, piece_chain[1:] != piece_chain[:-1]]) if n else np.zeros(0, np.intp)
    slack = np.maximum.reduceat(off, piece_first) if n else np.zeros(0)
    lean = np.maximum.reduceat(np.linalg.norm(axis - chain_axis[piece_chain], axis=1), piece_first) if n else np.zeros(0)
    w = chain_axis[piece_chain]
    a0, a1, da = row_dot(c0 - start, w), row_dot(c1 - start, w), row_dot(d, w)
    beyond = np.maximum(np.maximum(np.minimum(da, 0.0) - np.minimum(a0, a1), np.maximum(a0, a1) - np.maximum(da, 0.0)),
                        0.0)
    rise = np.minimum(np.maximum.reduceat(beyond, piece_first), slack) if n else np.zeros(0)
    r, h = radius[first], height[first]
    rigid = slack + lean * np.hypot(r, h) <= _RIGID
    slices = np.maximum(np.ceil(h / r), 1).astype(np.intp)
    ball_chain, ball_index = _csr(slices)
    tall = (h / slices)[ball_chain]
    ball_centre = (0.5 * (ch0 + ch1))[ball_chain] + ((ball_index + 0.5) * tall)[:, None] * chain_axis[ball_chain]
    # A point c0 + s·d + a·w + b of the hull lies within |d|/2 + √(r² + (a − a_mid)²) of the
    # point (c0 + c1)/2 + a_mid·w; the pieces lie within slack + lean·√(r² + H²) of the hull.
    grown = 0.5 * np.linalg.norm(ch1 - ch0, axis=1) + slack + lean * np.hypot(r, h)
    ball_bound = grown[ball_chain] + np.hypot(r[ball_chain], 0.5 * tall)
    return (first, count, span_move[first], ch0, ch1, chain_axis, r, h, slack, lean, rise, rigid, span_move[last],
            ball_chain, ball_centre, ball_bound)


def _apart(a, b, c0, c1, axis, radius, height, slack, lean=None, touch=False, rise=None):
    """(K,) bool: the segments a … b surely miss the hulls (c0, c1, axis, radius, height) grown by
    slack: seen along the axis the segment stays farther than radius + slack from the move, or
    it lies wholly below or above the hull's axial range ± slack (± rise (K,) instead, if given:
    a bound, no larger than slack, of how far the volume reaches beyond that range along the
    axis). All (K, 3) or (K,), mm. Both by more than _CLEAR, so that rounding never drops a
    pair the closed form would count.

    lean (K,): the volume is made of pieces whose bottom centres lie within slack of the
    hull's path and whose axes w_p differ from its axis w by at most lean (|w_p − w|). A point
    c + h·w_p + e of a piece (e ⊥ w_p, |e| ≤ radius) then lies, along w, within lean·radius of
    where it would with w_p = w (|e·w| = |e·(w − w_p)|, and h·(w_p·w) ≤ h), and across w within
    radius + lean·h of c (|e| ≤ radius, h·|w_p − w| ≤ lean·h). So the axial range grows by
    slack + lean·radius, and the distance seen along the axis by slack + lean·h, h up to the
    height at which a piece point can be level with the segment (h·(w_p·w) ≥ h·(1 − lean²/2)).

    touch: also apart when the segment reaches into that axial range by less than
    inprocess_touch.TOUCH along itself (inprocess_touch.touching): for line segments, whose
    material such a hull can change by less than that.
    """
    qa, qb, d = a - c0, b - c0, c1 - c0
    aa, ab, da = (row_dot(v, axis) for v in (qa, qb, d))
    across = np.broadcast_to(slack + _CLEAR, aa.shape)
    axial = across if rise is None else rise + _CLEAR
    if lean is not None:
        axial = axial + lean * radius
        level = 1.0 - 0.5 * lean * lean
        rise = np.maximum(np.maximum(aa, ab) - np.minimum(da, 0.0) + axial, 0.0)
        reach = np.where(level > 0.0, np.minimum(rise / np.where(level > 0.0, level, 1.0), height), height)
        across = across + lean * reach
    floor, ceiling = np.minimum(da, 0.0) - axial, height + np.maximum(da, 0.0) + axial
    if touch:
        apart = touching(a, b, aa, ab, floor, ceiling)
    else:
        apart = (np.maximum(aa, ab) < floor) | (np.minimum(aa, ab) > ceiling)
    # The distance seen along the axis only where the cheaper test left it open.
    i = np.flatnonzero(~apart)
    qa_i = _rows(qa, i)
    apart[i] = _seen_along(qa_i, _rows(qb, i) - qa_i, _rows(d, i), aa[i], ab[i] - aa[i], da[i]) > radius[i] + across[i]
    return apart


def _inside(ends, c0, c1, axis, radius, low, high):
    """(K,) bool: the points of every array in ends (each (K, 3)) lie in the volume
    {c0 + s·(c1 − c0) + a·axis + b : 0 ≤ s ≤ 1, low ≤ a ≤ high, b ⊥ axis, |b| ≤ radius} (mm): per
    point, the s allowed by the axial bounds and the s allowed by the radius are two intervals,
    which must meet within [0, 1]. The volume's own terms are computed once for all the points."""
    d = c1 - c0
    da = row_dot(d, axis)
    dp = d - da[:, None] * axis
    flat = np.abs(da) <= 1e-15
    aa = row_dot(dp, dp)
    still = aa <= 1e-24
    rr = radius * radius
    inside = None
    for x in ends:
        q = x - c0
        a0 = row_dot(q, axis)
        b0 = q - a0[:, None] * axis
        with np.errstate(divide="ignore", invalid="ignore"):
            s1, s2 = (a0 - low) / da, (a0 - high) / da
        ok = (a0 >= low) & (a0 <= high)
        lo = np.where(flat, np.where(ok, 0.0, np.inf), np.minimum(s1, s2))
        hi = np.where(flat, np.where(ok, 1.0, -np.inf), np.maximum(s1, s2))
        bb = row_dot(b0, dp)
        cc = row_dot(b0, b0) - rr
        disc = bb * bb - aa * cc
        root = np.sqrt(np.maximum(disc, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            r_lo = np.where(still, np.where(cc <= 0.0, 0.0, np.inf), np.where(disc >= 0.0, (bb - root) / aa, np.inf))
            r_hi = np.where(still, np.where(cc <= 0.0, 1.0, -np.inf), np.where(disc >= 0.0, (bb + root) / aa, -np.inf))
        meets = np.maximum(np.maximum(lo, r_lo), 0.0) <= np.minimum(np.minimum(hi, r_hi), 1.0)
        inside = meets if inside is None else inside & meets
    return inside


def _deep_inside(a, b, c0, c1, axis, radius, height, slack, corner):
    """(K,) bool: both ends a, b (K, 3) of each segment lie at least `slack` inside the volume swept by the
    tool (c0, c1, axis, radius, height, corner: hulls and their tools' corner radii), so the segment does
    (the volume is convex). A tool with a corner holds the cylinders of radius R − r over its whole
    height and of radius R above its corner; both ends must lie in one of them (each convex)."""
    inside = _inside((a, b), c0, c1, axis, radius - slack, slack, height - slack)
    bent = np.flatnonzero(corner > 0.0)
    if bent.size:
        ends = (a[bent], b[bent])
        inner = (c0[bent], c1[bent], axis[bent], radius[bent] - corner[bent] - slack[bent], slack[bent],
                 height[bent] - slack[bent])
        upper = (c0[bent], c1[bent], axis[bent], radius[bent] - slack[bent], corner[bent] + slack[bent],
                 height[bent] - slack[bent])
        inside[bent] = ((inner[3] > 0.0) & _inside(ends, *inner) | (upper[3] > 0.0) & _inside(ends, *upper))
    return inside


def _point_distance(q, d):
    """(K,) distance from points q to the segments t·d, t ∈ [0, 1] ((K, 3) each, mm)."""
    dd = row_dot(d, d)
    t = clamp(row_dot(q, d) / np.where(dd > 0.0, dd, 1.0), 0.0, 1.0)
    gap = q - t[:, None] * d
    return np.sqrt(row_dot(gap, gap))


def _dot_across(x, y, xw, yw):
    """(K,) dot products of the components of x and y (K, 3) across unit axes w, from their
    components xw, yw (K,) along w."""
    return row_dot(x, y) - xw * yw


def _seen_along(q, e, d, qw, ew, dw):
    """(K,) shortest distance between the segments q + s·e and t·d (s, t ∈ [0, 1]) seen along
    unit axes w: their components across w, from the vectors q, e, d (K, 3) and their
    components qw, ew, dw (K,) along w (mm). Closest points of two segments, clamped to their
    ends, computed from the six dot products of the components across w."""
    a, c, f = _dot_across(e, e, ew, ew), _dot_across(e, q, ew, qw), _dot_across(d, q, dw, qw)
    b, g, h = _dot_across(e, d, ew, dw), _dot_across(d, d, dw, dw), _dot_across(q, q, qw, qw)
    safe_a, safe_g = np.where(a > 0.0, a, 1.0), np.where(g > 0.0, g, 1.0)
    denom = a * g - b * b
    s = np.where(denom > 1e-12 * a * g, clamp((b * f - c * g) / np.where(denom > 0.0, denom, 1.0), 0.0, 1.0), 0.0)
    # A path seen as a point (g = 0: a move along the axis, a plunge) has t = 0 and s the point's projection.
    t = np.where(g > 0.0, (b * s + f) / safe_g, 0.0)
    s = np.where((t < 0.0) | (g <= 0.0), clamp(-c / safe_a, 0.0, 1.0),
                 np.where(t > 1.0, clamp((b - c) / safe_a, 0.0, 1.0), s))
    t = clamp(t, 0.0, 1.0)
    # |q + s·e − t·d|² across w, expanded in the dot products.
    gap = h + 2.0 * s * c - 2.0 * t * f + s * s * a - 2.0 * s * t * b + t * t * g
    return np.sqrt(np.maximum(gap, 0.0))


def inprocess_intervals(stock_intervals: EdgeIntervals, moves, program_index, origins, directions, p, *,
                        tolerance=0.05):
    """The edge lines' inside intervals in the in-process stock, and which CL points changed.

    stock_intervals: the N = m·p lines' intervals inside the stock (row i·p + k: CL point i,
    angle k). moves: ProgramMoves of the whole program, or its SweptPieces (build them once
    with swept_pieces when calling chunk by chunk). program_index: (m,) int, the program row of
    each CL point. origins, directions: (N, 3) the lines' points at l = 0 and unit directions
    (mm). p: angles per CL point. tolerance: mm, for moves whose axis turns (ignored when
    `moves` is already SweptPieces).
    Returns (EdgeIntervals, changed (m,) bool): the stock intervals minus their parts inside
    the volume swept by every cutting move ending at or before row program_index[i] − 1; an
    end made by that removal has surface "machined", section and wall −1. changed[i]: some
    line of CL point i lost material.
    """
    pieces = moves if isinstance(moves, SweptPieces) else swept_pieces(moves, tolerance)
    p = int(p)
    n = stock_intervals.n_rows
    m = n // max(p, 1)
    if p <= 0 or m * p != n:
        raise ValueError(f"{n} edge lines are not a whole number of CL points of {p} angles")
    program_index = np.asarray(program_index, dtype=np.intp).reshape(-1)
    if program_index.shape != (m,):
        raise ValueError(f"program_index must have shape ({m},), got {program_index.shape}")
    origins = _float_array("origins", origins, (n, 3), copy=False)
    directions = _float_array("directions", directions, (n, 3), copy=False)
    rows, enter, leave = _removals(stock_intervals, pieces, program_index, origins, directions, p)
    result = subtract(stock_intervals, rows, enter, leave)
    if result is stock_intervals:  # no removal: nothing changed
        return result, np.zeros(m, dtype=bool)
    lost = result.length != stock_intervals.length
    return result, lost.reshape(m, p).any(axis=1)


def _removals(stock, pieces, program_index, origins, directions, p):
    """Intervals (rows, enter, leave) of the lines inside the pieces that precede their CL point."""
    if stock.rows.size == 0:
        return np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0)
    # Per line with stock material: the range lo … hi from its first start to its last end.
    first = np.flatnonzero(np.r_[True, stock.rows[1:] != stock.rows[:-1]])
    last = np.r_[first[1:], stock.rows.size] - 1
    return removal_intervals(pieces, program_index, stock.rows[first], stock.start[first], stock.end[last], origins,
                             directions, p)


def removal_intervals(pieces: SweptPieces, program_index, line, lo, hi, origins, directions, p):
    """Removal intervals (rows (R,) int, enter, leave (R,) mm) of the edge lines `line` inside the
    pieces of the cutting moves that end before their CL point.

    line: (L,) int ascending, the lines holding material (row i·p + k: CL point i, angle k),
    all of it within lo … hi (L,) mm along the line; origins, directions: (N, 3) every line at
    l = 0, unit; program_index: (m,) the program row of each CL point. Only removals that overlap
    lo … hi by more than LENGTH_EPS are given, and a line whose lo … hi is covered whole gets
    one removal [lo, hi]: a line without a removal keeps its material as it is. Which removals
    are given depends only on the line, not on the other lines of the call nor on the order
    the search finds them in (docs/ENGINE.md, "Same input, same bits").

    Where many earlier moves come near the CL points, the lines are searched in waves: every
    _SEED_EVERY-th CL point in full, each other one first guided by the CL point of an earlier
    wave nearest before it (_waves_searched). Where the program has z levels (pieces.levels), the lines
    along their axis meet them in plan (inprocess_levels) and the other moves in that search.
    """
    line = np.asarray(line, dtype=np.intp).reshape(-1)
    if line.size == 0 or pieces.move.size == 0:
        return _none()[:3]
    lo, hi = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    if pieces.levels is not None:
        return _level_removals(pieces, program_index, line, lo, hi, origins, directions, p)
    return _searched_removals(pieces, program_index, line, lo, hi, origins, directions, p)


def _level_removals(pieces, program_index, line, lo, hi, origins, directions, p):
    """removal_intervals of a program with z levels: the lines along the levels' axis in plan view
    (inprocess_levels) and then, those not removed whole, among the other moves (pieces.rest); the other
    lines among all moves."""
    view = pieces.levels
    direction = _rows(directions, line)
    along = (direction == view.w).all(axis=1)
    across = row_dot(direction, np.broadcast_to(view.w, direction.shape)) == 0.0
    other = ~along & ~across
    parts = []
    if other.any():
        parts.append(_searched_removals(pieces, program_index, line[other], lo[other], hi[other], origins,
                                        directions, p))
    end_edges = functools.partial(ends, view)
    for mine, ask in ((np.flatnonzero(along), view.removals), (np.flatnonzero(across), end_edges)):
        if mine.size:
            parts.extend(_in_levels(pieces, ask, program_index, line[mine], lo[mine], hi[mine], origins, directions,
                                    p))
    return tuple(np.concatenate(part) for part in zip(*parts))


def _in_levels(pieces, ask, program_index, at, lo, hi, origins, directions, p):
    """Removal parts (line, enter, leave) of lines `at` along or across the levels' axis: the level view's answer
    `ask` (LevelView.removals or inprocess_level_pairs.ends; GROUP consecutive lines share a candidate search),
    then the search among the other moves for the lines it did not remove whole whose material comes near them."""
    parts = []
    seg, enter, leave = ask(_rows(origins, at), _rows(directions, at), lo, hi, program_index[at // p] - 1,
                            at // GROUP)
    envelope = np.stack([lo, hi])
    narrow(envelope, seg, enter, leave)
    dead = envelope[0] >= envelope[1]
    alive = ~dead[seg]
    parts.append((at[dead], lo[dead], hi[dead]))
    parts.append((at[seg[alive]], enter[alive], leave[alive]))
    if pieces.rest.move.size and not dead.all():
        alive = np.flatnonzero(~dead)
        alive = alive[_near_rest(pieces.rest, _rows(origins, at[alive]), _rows(directions, at[alive]),
                                 envelope[0, alive], envelope[1, alive], program_index[at[alive] // p] - 1,
                                 pieces.levels.w)]
        parts.append(_searched_removals(pieces.rest, program_index, at[alive], lo[alive], hi[alive],
                                        origins, directions, p, envelope[:, alive]))
    return parts


def _near_rest(rest, origin, direction, lo, hi, before, w):
    """(L,) bool: the lines' material, within lo … hi (L,) along origin + l·direction (L, 3), may meet a chain of
    `rest` (a SweptPieces) that begins by program row before (L,): the chain's floor along w (3,) is not above
    the segment's top (its pieces have no point below it, _floors), the segment's bounding sphere meets a ball of
    the chain (the balls hold every point of their chains' hulls), and the segment is not surely apart from the
    chain's hull (the sure-miss test of the search, touches included). The others need no search among them."""
    near = np.zeros(origin.shape[0], dtype=bool)
    chains = rest.chain_first.size
    for begin in range(0, origin.shape[0], _REST_BLOCK):
        part = slice(begin, begin + _REST_BLOCK)
        half = 0.5 * (hi[part] - lo[part])
        centre = origin[part] + (lo[part] + half)[:, None] * direction[part]
        ww = np.broadcast_to(w, centre.shape)
        top = np.maximum(row_dot(origin[part] + lo[part][:, None] * direction[part], ww),
                         row_dot(origin[part] + hi[part][:, None] * direction[part], ww))
        i, ball = rest.tree.meeting(centre, half, int(before[part].max()), top)
        pair = _distinct(i * chains + rest.ball_chain[ball], half.size * chains)
        i, k = pair // chains, pair % chains
        keep = rest.chain_move[k] <= before[part][i]
        i, k = i[keep] + begin, k[keep]
        a = origin[i] + lo[i][:, None] * direction[i]
        b = origin[i] + hi[i][:, None] * direction[i]
        keep = ~_apart(a, b, *rest.hulls("chain", k), rest.chain_slack[k], rest.chain_lean[k], touch=True,
                       rise=rest.chain_rise[k])
        near[i[keep]] = True
    return near


def _searched_removals(pieces, program_index, line, lo, hi, origins, directions, p, left=None):
    """removal_intervals by the general search (the docstring's waves), lines (L,) not empty; left (from, to) (L,),
    if given: what removals found elsewhere left of each line's material lo … hi, where the search starts."""
    if line.size == 0 or pieces.move.size == 0:
        return _none()[:3]
    # Rows 0, 1: the envelope of each line's remaining material, narrowed as removals are found
    # (lo ≥ hi: nothing remains, the line is removed whole); rows 2, 3: lo, hi as given.
    envelope = np.stack([lo, hi, lo, hi] if left is None else [*left, lo, hi])
    state = (envelope, _rows(origins, line), _rows(directions, line), program_index[line // p] - 1, pieces)
    group, group_before = _line_groups(line, p, program_index)
    cl = line // p
    new = np.r_[True, cl[1:] != cl[:-1]]
    rank = np.cumsum(new) - 1
    capsules = group_capsules(group, group_before.size, *state[:3])
    sampled = np.zeros(group_before.size, dtype=bool)
    sampled[group[(rank % _SAMPLE_EVERY == 0) | (rank % _SEED_EVERY == 0)]] = True
    spheres = capsule_spheres(*capsules)
    g, k = _sphere_chains(*spheres, group_before, pieces, np.flatnonzero(sampled))
    if _spans_per_point(cl[np.r_[True, group[1:] != group[:-1]]], g, k, pieces) <= _FEW_SPANS:
        # Few spans near the CL points (as in a single pass, whose own earlier moves are far
        # from its leading edge): every line straight to its spans.
        rest = _sphere_chains(*spheres, group_before, pieces, np.flatnonzero(~sampled))
        g, k = _near_groups(np.r_[g, rest[0]], np.r_[k, rest[1]], capsules, pieces)
        n = group_before.size
        near = (np.searchsorted(group, np.arange(n)), np.bincount(group, minlength=n), capsules, g, k)
        found = [_spans_near(np.arange(line.size), near, group_before, *state)]
    else:
        # The sampled groups' pairs hold the seeds'.
        found = _waves_searched(*_waves(line % p, cl[new], rank, p), group, g, k, group_before, state)
    dead = envelope[0] >= envelope[1]
    seg, enter, leave, _ = (np.concatenate(part) for part in zip(*found))
    alive = ~dead[seg]
    return (np.concatenate([line[dead], line[seg[alive]]]), np.concatenate([lo[dead], enter[alive]]),
            np.concatenate([hi[dead], leave[alive]]))


def _none():
    """No removal intervals: (seg, enter, leave, span), each empty."""
    return np.zeros(0, dtype=np.intp), np.zeros(0), np.zeros(0), np.zeros(0, dtype=np.intp)


def _waves(angle, present, rank, p):
    """(wave (L,), source (L,)) of the lines at angles `angle` (L,) (indices 0 … p − 1) of the
    CL points present (ascending) at `rank` (L,) among them: the lines of every _SEED_EVERY-th
    CL point are wave 0; a CL point at rank r with r mod _SEED_EVERY = h·(odd) is in the wave
    whose step is h, and its lines follow those at the same angle on the CL point h ranks
    before (source: index into the lines, −1 for wave 0 and where that line holds no material)."""
    offset = rank % _SEED_EVERY
    step = offset & -offset  # the lowest set bit: the distance to a CL point of an earlier wave
    wave = np.where(offset == 0, 0, np.log2(_SEED_EVERY // np.maximum(step, 1)).astype(np.intp))
    line = present[rank] * p + angle
    row = present[rank - step] * p + angle
    at = np.minimum(np.searchsorted(line, row), line.size - 1)
    return wave, np.where((line[at] == row) & (offset != 0), at, -1)


def _astray(follower, source, envelope):
    """(F,) bool: followers (F,) whose envelope (envelope (4, L): rows 0, 1 now, rows 2, 3 at
    first) the guess left less narrowed than their source's (F,): open where the source's
    closed, or with an end where it was at first while the source's end moved."""
    now, was = envelope[:2, follower], envelope[2:, follower]
    model, model_was = envelope[:2, source], envelope[2:, source]
    open_ = now[0] < now[1]
    return open_ & ((model[0] >= model[1]) | ((model != model_was) & (now == was)).any(axis=0))


def _followed(follower, source, found, envelope, origins, directions, before, pieces, solved):
    """Removal intervals (seg, enter, leave, span) of the follower lines (F,) from the spans that
    bound what was left of their source lines (F,) (_witnesses), each shifted along the earlier
    moves by the lines' distance; the pairs remembered in `solved` (_Solved)."""
    seg, span = _witnesses(found, envelope)
    first = np.searchsorted(seg, source)
    count = np.searchsorted(seg, source, side="right") - first
    owner, rank = _csr(count)
    who, w = follower[owner], span[first[owner] + rank]
    shift = _rows(origins, who) - _rows(origins, source[owner])
    d = pieces.span_c1[w] - pieces.span_c0[w]
    dd = row_dot(d, d)
    step = np.rint(row_dot(shift, d) / np.where(dd > 0.0, dd, 1.0)).astype(np.intp)
    w = np.clip(w + step, 0, pieces.span_move.size - 1)
    keep = pieces.span_move[w] <= before[who]
    solved.add(who[keep], w[keep])
    return _line_span_pairs(who[keep], w[keep], envelope, origins, directions, before, pieces)


def _witnesses(found, envelope):
    """(seg, span) sorted by seg: for each line whose search is done, the spans whose removals
    (found: seg, enter, leave, span) bound what is left of it: where its envelope (4, L) is
    open, those ending at its lower end or starting at its upper one; where it closed, of
    the removals over its first range the one reaching highest from its start, the one reaching
    lowest from its end and the one covering most of it."""
    order = np.argsort(found[0], kind="stable")
    seg, enter, leave, span = (part[order] for part in found)
    low, high, first_low, first_high = envelope[:, seg]
    closed = low >= high
    pick = ~closed & ((leave == low) | (enter == high))
    cover = np.minimum(leave, first_high) - np.maximum(enter, first_low)
    for key in (np.where(enter <= first_low, -leave, np.inf), np.where(leave >= first_high, enter, np.inf), -cover):
        pick |= closed & _smallest(seg, np.where(closed, key, np.inf), 1)
    return seg[pick], span[pick]


def _spans_per_point(group_cl, g, k, pieces):
    """The largest number of spans, over the CL points of the pairs (group g, chain k) (K,),
    of the chains paired with its groups; group_cl (G,) each group's CL point; 0 without a
    pair."""
    if g.size == 0:
        return 0
    chains = pieces.chain_first.size
    pair = np.unique(group_cl[g] * chains + k)
    return int(np.bincount(pair // chains, pieces.chain_count[pair % chains]).max())


class _Solved:
    """Per line, the first _SOLVED spans that a guess or a probe solved for it. Every piece of
    such a span was then solved for the line or surely apart from its envelope, which only
    narrows later; so the closing search skips the pair (solving it again would find the same
    removals)."""

    def __init__(self, n):
        self.span = np.full((_SOLVED, n), -1, dtype=np.intp)

    def add(self, seg, span):
        """Remember the pairs (segment seg, span) (K,), in the free places of each segment."""
        if seg.size == 0:
            return
        order = np.argsort(seg, kind="stable")
        seg, span = seg[order], span[order]
        head, count = run_starts(seg)
        filled = (self.span[:, seg[head]] >= 0).sum(axis=0)
        place = np.arange(seg.size) - np.repeat(head, count) + np.repeat(filled, count)
        ok = place < _SOLVED
        self.span[place[ok], seg[ok]] = span[ok]

    def fresh(self, seg, span):
        """(K,) bool: the pairs (segment seg, span) (K,) not remembered as solved."""
        return (span != self.span[:, seg]).all(axis=0)


def _waves_searched(wave, source, group, g, k, group_before, state):
    """Removal intervals (a list of (seg, enter, leave, span)) of all lines, wave by wave
    (_waves): the seeds (wave 0) get the whole search (_searched, from the pairs (group g,
    chain k) that hold their groups' own); each follower of a later
    wave first the spans that bound what is left of its source line, shifted (_followed), then
    the search without probes; followers without a source line, and those the guess left
    astray (_astray), the whole search. A span a guess or a probe solved for a line is not
    solved for it again (_Solved)."""
    envelope = state[0]
    solved = _Solved(envelope.shape[1])
    found = [_searched(np.flatnonzero(wave == 0), group, g, k, group_before, *state, solved=solved)]
    for level in range(1, int(wave.max()) + 1):
        mine = wave == level
        follower = np.flatnonzero(mine & (source >= 0))
        astray = np.zeros(follower.size, dtype=bool)
        if follower.size:
            so_far = tuple(np.concatenate(part) for part in zip(*found))
            found.append(_followed(follower, source[follower], so_far, *state, solved))
            astray = _astray(follower, source[follower], envelope)
            found.append(_searched(follower[~astray], group, None, None, group_before, *state, probe=False,
                                   solved=solved))
        lead = np.union1d(np.flatnonzero(mine & (source < 0)), follower[astray])
        found.append(_searched(lead, group, None, None, group_before, *state, solved=solved))
    return found


def _subset(sub, group, g, k, group_before, envelope, origins, directions, pieces):
    """The lines `sub` (ascending indices into the lines) as groups of their own: (starts,
    sizes) per group (of all n groups; size 0 without a line of sub), their capsules, and the
    pairs (group g, chain k) of their groups not surely apart from those capsules: of the pairs
    g, k given, or, with g None, from the KD tree (_group_chains)."""
    n = group[-1] + 1
    mine = group[sub]
    starts, sizes = np.searchsorted(mine, np.arange(n)), np.bincount(mine, minlength=n)
    capsules = group_capsules(mine, n, envelope[:, sub], _rows(origins, sub), _rows(directions, sub))
    if g is None:
        g, k = _group_chains(capsules, group_before, pieces)
    else:
        keep = sizes[g] > 0
        g, k = _near_groups(g[keep], k[keep], capsules, pieces)
    return starts, sizes, capsules, g, k


def _spans_near(sub, near, group_before, envelope, origins, directions, before, pieces):
    """Removal intervals (seg, enter, leave, span) of the lines `sub` where they meet few spans,
    near (starts, sizes, capsules, g, k) as _subset gives them: the chains straight to (group,
    span) pairs, no test of chains per line."""
    starts, sizes, (a, b, thick), g, k = near
    owner, rank = _csr(pieces.chain_count[k])
    g, span = g[owner], pieces.chain_first[k][owner] + rank
    keep = pieces.span_move[span] <= group_before[g]
    g, span = g[keep], span[keep]
    keep = ~_apart(_rows(a, g), _rows(b, g), *pieces.hulls("span", span), pieces.span_slack[span] + thick[g])
    return _expanded(g[keep], span[keep], sub, starts, sizes, envelope, origins, directions, before, pieces,
                     _spans_solved)


def _searched(sub, group, g, k, group_before, envelope, origins, directions, before, pieces, probe=True, solved=None):
    """Removal intervals (seg, enter, leave, span) of the lines `sub` (ascending indices into the
    lines) from the pairs (group g, chain k) of their groups: with `probe` first a few spans per
    group and a guess per line, then every chain near each line (docs/ENGINE.md); with
    `solved` (_Solved), the probes' pairs are remembered and the closing search skips the
    pairs remembered."""
    if sub.size == 0:
        return _none()
    starts, sizes, capsules, g, k = _subset(sub, group, g, k, group_before, envelope, origins, directions, pieces)
    lines = (sub, starts, sizes, envelope, origins, directions, before, pieces)
    found = [_none()]
    if probe:
        # Where the lines meet many chains: first a few spans per group (_probe), which
        # usually remove most of the lines; then per line a first guess among the spans of
        # the chains its group seems to enter first (_line_probe), which usually finds what
        # is left of it; each time the narrowed envelopes meet far fewer chains; then the rest.
        centre, radius = capsule_spheres(*capsules)
        found.append(_expanded(*_probe(g, k, centre, radius, _rows(directions, sub[np.minimum(starts, sub.size - 1)]),
                                       group_before, pieces), *lines, functools.partial(_spans_solved, solved=solved)))
        starts, sizes, capsules, g, k = _subset(sub, group, g, k, group_before, envelope, origins, directions, pieces)
        a, b, _ = capsules
        pick = _entered_first(g, _rows(a, g), _rows(b, g), *pieces.hulls("chain", k)[:4], _GUESSED_CHAINS)
        found.append(_expanded(g[pick], k[pick], *lines, functools.partial(_line_probe, solved=solved)))
        starts, sizes, capsules, g, k = _subset(sub, group, g, k, group_before, envelope, origins, directions, pieces)
    found.append(_expanded(g, k, *lines, functools.partial(_chains_solved, solved=solved)))
    return tuple(np.concatenate(part) for part in zip(*found))


def _line_groups(line, p, program_index):
    """The lines (L,) (rows i·p + k, ascending) in groups: a CL point's angles in _GROUPS runs,
    all with that point's tool axis as direction. Returns group (L,) each line's group
    (non-decreasing, 0 … G − 1) and each group's last earlier program row (G,) (its CL point's
    program_index − 1)."""
    key = (line // p) * _GROUPS + (line % p) * _GROUPS // p
    new = np.r_[True, key[1:] != key[:-1]]
    group = np.cumsum(new) - 1
    return group, program_index[key[new] // _GROUPS] - 1


def _group_chains(capsules, group_before, pieces):
    """The pairs (group g, chain k) (K,) that may remove material from the groups' lines: the
    group's bounding sphere meets a ball of the chain, the chain's first move ends by the
    group's CL point (group_before (G,) its last earlier program row), and the group's capsule
    (inprocess_reach.group_capsules, G of them) is not surely apart from the chain."""
    return _near_groups(*_sphere_chains(*capsule_spheres(*capsules), group_before, pieces), capsules, pieces)


def _sphere_chains(centre, radius, before, pieces, among=None):
    """The pairs (sphere i, chain k) (K,), sorted, where the sphere (centre (n, 3), radius (n,),
    −inf for none; with `among`, only the spheres of those indices) meets a ball of the chain
    and the chain's first move ends by `before` (n,), the sphere's last earlier program row."""
    live = np.flatnonzero(radius > -np.inf) if among is None else among[radius[among] > -np.inf]
    if live.size == 0:
        return np.zeros(0, dtype=np.intp), np.zeros(0, dtype=np.intp)
    chains = pieces.chain_first.size
    found = []
    # The spheres in blocks: the (sphere, ball) pairs that meet grow with the earlier moves
    # stacked near the lines (every z level above a deep one), the block's memory with them.
    for begin in range(0, live.size, _SPHERE_BLOCK):
        mine = live[begin:begin + _SPHERE_BLOCK]
        i, ball = pieces.tree.meeting(centre[mine], radius[mine], int(before[mine].max()))
        pair = _distinct(i * chains + pieces.ball_chain[ball], mine.size * chains)
        i, k = mine[pair // chains], pair % chains
        keep = pieces.chain_move[k] <= before[i]
        found.append((i[keep], k[keep]))
    return np.concatenate([f[0] for f in found]), np.concatenate([f[1] for f in found])


def _distinct(keys, bound):
    """The distinct values of keys (K,) int in 0 … bound − 1, sorted: by marking them when
    bound is small enough (a pass over a bool array instead of a sort), else np.unique."""
    if bound > min(_MARK_LIMIT, _MARK_SPARSE * keys.size):
        return np.unique(keys)
    seen = np.zeros(bound, dtype=bool)
    seen[keys] = True
    return np.flatnonzero(seen)


def _probe(g, k, centre, radius, direction, group_before, pieces):
    """A few (group, span) pairs per group from its (group g, chain k) pairs: first chains, then
    their spans (those ending before the group's CL point), chosen alike: among the hulls whose
    sides hold the group's whole sphere (seen along their axis), the _PROBE reaching lowest and
    the _PROBE reaching highest along the group's lines (direction (n, 3)), and the _PROBE whose
    axes pass nearest the sphere's centre."""
    def chosen(g, c0, c1, axis, r, h, slack):
        at = _rows(centre, g)
        across = _across(at, c0, c1, axis) - r
        lower, upper = _extent(at, _rows(direction, g), c0, c1, axis, r, h)
        holds = across + radius[g] + slack <= 0.0
        return np.flatnonzero(_smallest(g, across, _PROBE) | _smallest(g, np.where(holds, lower, np.inf), _PROBE)
                              | _smallest(g, np.where(holds, -upper, np.inf), _PROBE))

    grown = pieces.chain_slack + pieces.chain_lean * np.hypot(pieces.chain_radius, pieces.chain_height)
    pick = chosen(g, *pieces.hulls("chain", k), grown[k])
    owner, rank = _csr(pieces.chain_count[k[pick]])
    g, span = g[pick][owner], pieces.chain_first[k[pick]][owner] + rank
    keep = pieces.span_move[span] <= group_before[g]
    g, span = g[keep], span[keep]
    pick = chosen(g, *pieces.hulls("span", span), pieces.span_slack[span])
    return g[pick], span[pick]


def _near_groups(g, k, capsules, pieces):
    """The pairs (group g, chain k) whose group capsule (a, b, radius: inprocess_reach.group_capsules)
    is not surely apart from the chain."""
    a, b, thick = capsules
    keep = ~_apart(_rows(a, g), _rows(b, g), *pieces.hulls("chain", k), pieces.chain_slack[k] + thick[g],
                   pieces.chain_lean[k], rise=pieces.chain_rise[k] + thick[g])
    return g[keep], k[keep]


def _expanded(g, k, members, starts, sizes, envelope, origins, directions, before, pieces, solve):
    """Removal intervals (seg, enter, leave, span) from the pairs (group g, chain or span k), expanded
    to the group's lines (members[starts[g] …] of sizes[g]) in batches of at most _EXPAND_BATCH
    and given to solve(seg, k, envelope, origins, directions, before, pieces) (_spans_solved,
    _chains_solved or _line_probe); before (L,) the last program row that precedes each
    line's CL point."""
    order = np.argsort(g, kind="stable")
    g, k = g[order], k[order]
    count = sizes[g]
    cuts = np.unique(np.r_[0, np.searchsorted(np.cumsum(count), np.arange(_EXPAND_BATCH, int(count.sum()),
                                                                          _EXPAND_BATCH), side="right"), g.size])
    found = [_none()]
    for first, stop in zip(cuts[:-1], cuts[1:]):
        pair, rank = _csr(count[first:stop])
        seg, item = members[starts[g[first:stop]][pair] + rank], k[first:stop][pair]
        found.append(solve(seg, item, envelope, origins, directions, before, pieces))
    return tuple(np.concatenate(part) for part in zip(*found))


def _spans_solved(seg, span, envelope, origins, directions, before, pieces, solved=None):
    """Removal intervals (seg, enter, leave, span) from the (segment, span) pairs (_line_span_pairs),
    remembered in `solved` if given."""
    if solved is not None:
        solved.add(seg, span)
    return _line_span_pairs(seg, span, envelope, origins, directions, before, pieces)


def _chains_solved(seg, chain, envelope, origins, directions, before, pieces, solved=None):
    """Removal intervals (seg, enter, leave, span) from the (segment, chain) pairs: the chains
    near each segment; a rigid one that ends before the segment's CL point solved whole (its
    hull is the union of its pieces), of the others their spans (_line_span_pairs)."""
    seg, chain = _chains_near(seg, chain, envelope, origins, directions, pieces)
    whole = pieces.chain_rigid[chain] & (pieces.chain_last[chain] <= before[seg])
    found = _solved(seg[whole], chain[whole], envelope, origins, directions, pieces, whole=True)
    seg, span = _chain_spans(seg[~whole], chain[~whole], before, pieces)
    if solved is not None:
        keep = solved.fresh(seg, span)
        seg, span = seg[keep], span[keep]
    return tuple(np.concatenate(part) for part in zip(found, _line_span_pairs(seg, span, envelope, origins,
                                                                              directions, before, pieces)))


def _entered_first(owner, a, b, c0, c1, axis, radius, take):
    """(K,) bool: per owner (K,, ascending), the `take` hulls (c0, c1, axis, radius) that the
    segment a … b (K, 3) seems to enter first going from a to b; none that it seems not to
    enter. The guess: its distance from the hull's path seen along the axis, interpolated
    linearly between the ends, falls to the radius, after it crosses the hull's bottom plane."""
    near, far = _across(a, c0, c1, axis) - radius, _across(b, c0, c1, axis) - radius
    qa, d = a - c0, c1 - c0
    aa, da = row_dot(qa, axis), row_dot(d, axis)
    rise = row_dot(b - a, axis)
    with np.errstate(divide="ignore", invalid="ignore"):
        side = np.where(near > 0.0, near / (near - far), 0.0)
        bottom = np.where(rise > 0.0, (np.minimum(da, 0.0) - aa) / rise, 0.0)
    entry = np.maximum(side, bottom)
    ok = (np.minimum(near, far) < 0.0) & (entry < 1.0)
    return _smallest(owner, np.where(ok, entry, np.inf), take) & ok


def _line_probe(seg, chain, envelope, origins, directions, before, pieces, solved=None):
    """Removal intervals (seg, enter, leave, span) of a first guess per segment from its chains (seg,
    chain (K,)): of their spans before the segment's CL point, the one its line seems to enter
    first (_entered_first), its pieces solved (its whole chain where _whole_chains says so);
    the pairs remembered in `solved` if given."""
    open_ = envelope[0, seg] < envelope[1, seg]
    seg, chain = seg[open_], chain[open_]
    order = np.argsort(seg, kind="stable")
    seg, chain = seg[order], chain[order]
    owner, rank = _csr(pieces.chain_count[chain])
    seg, span = seg[owner], pieces.chain_first[chain][owner] + rank
    keep = pieces.span_move[span] <= before[seg]
    seg, span = seg[keep], span[keep]
    pick = _entered_first(seg, *_ends(seg, envelope, origins, directions), *pieces.hulls("span", span)[:4], 1)
    if solved is not None:
        solved.add(seg[pick], span[pick])
    (whole, chain), (seg, span) = _whole_chains(seg[pick], span[pick], before, pieces)
    found = _solved(whole, chain, envelope, origins, directions, pieces, whole=True)
    seg, piece = _span_pieces(seg, span, pieces)
    near = _near_pieces(seg, piece, envelope, origins, directions, pieces)
    return tuple(np.concatenate(part) for part in zip(found, _solved(seg[near], piece[near], envelope, origins,
                                                                     directions, pieces)))


def _chains_near(seg, chain, envelope, origins, directions, pieces):
    """The pairs (segment seg, chain) (K,) whose segment is open and not surely apart from the
    chain."""
    open_ = envelope[0, seg] < envelope[1, seg]
    seg, chain = seg[open_], chain[open_]
    a, b = _ends(seg, envelope, origins, directions)
    keep = ~_apart(a, b, *pieces.hulls("chain", chain), pieces.chain_slack[chain], pieces.chain_lean[chain],
                   touch=True, rise=pieces.chain_rise[chain])
    return seg[keep], chain[keep]


def _chain_spans(seg, chain, before, pieces):
    """The pairs (segment seg, chain) (K,) as (segment, span) pairs: each span of the chain that
    ends before the segment's CL point (before (L,) its last earlier program row)."""
    owner, rank = _csr(pieces.chain_count[chain])
    seg, span = seg[owner], pieces.chain_first[chain][owner] + rank
    keep = pieces.span_move[span] <= before[seg]
    return seg[keep], span[keep]


def _ends(seg, envelope, origins, directions):
    """The ends (K, 3) of the current envelopes of segments `seg` (K,): per segment once, then
    gathered, where segments repeat."""
    if seg.size > 2 * envelope.shape[1]:
        low = origins + envelope[0, :, None] * directions
        high = origins + envelope[1, :, None] * directions
        return _rows(low, seg), _rows(high, seg)
    origin, direction = _rows(origins, seg), _rows(directions, seg)
    return origin + envelope[0, seg, None] * direction, origin + envelope[1, seg, None] * direction


def _whole_chains(seg, span, before, pieces):
    """The pairs (segment seg, span) (K,) split: ((segments, chains), distinct) where the span's
    chain is rigid and ends before the segment's CL point (before (L,) its last earlier program
    row), so that it is solved whole, never piece by piece, for that segment; (segments,
    spans) for the others."""
    if not pieces.any_rigid:
        return (seg[:0], seg[:0]), (seg, span)
    chain = np.searchsorted(pieces.chain_first, span, side="right") - 1
    whole = pieces.chain_rigid[chain] & (pieces.chain_last[chain] <= before[seg])
    count = pieces.chain_first.size
    pair = np.unique(seg[whole] * count + chain[whole])
    return (pair // count, pair % count), (seg[~whole], span[~whole])


def _line_span_pairs(seg, span, envelope, origins, directions, before, pieces):
    """Removal intervals (seg, enter, leave, span) from the pairs (segment seg[i], span span[i]);
    span: the span each removal comes from.

    envelope: (4, L), rows 0, 1 the range lo … hi (mm along the line) holding each segment's
    remaining material, narrowed in place by the removals found (rows 2, 3: as it was at
    first); origins, directions: (L, 3) the segments' lines; before (L,) the last program row
    before each segment's CL point. A span of a rigid chain that ends before that row is
    solved as its whole chain (_whole_chains). A segment found to lie inside a span's hull (or
    a rigid chain's) is removed whole: its envelope as it was then is given as one removal; the
    latest chain and the latest span of each segment are tested for that first, and the pairs
    of the segments they remove are not tested at all. The other pairs are
    solved in rounds: each round solves, per segment, the pieces reaching lowest and highest
    along its line (1, 2, 4, … of each), narrows the envelopes, and drops the pairs whose piece
    is then surely apart from the envelope (it can remove nothing more), so that a line cut by
    many pieces solves few of them.
    """
    (whole, chain), (seg, span) = _whole_chains(seg, span, before, pieces)
    out = [_none()]
    if whole.size:
        # The latest rigid chain of each segment first: a segment deep inside it is removed
        # whole, and its other chains and spans need no solving (as the spans below).
        latest = _latest(whole, chain)
        closed, by = _closed_inside("chain", whole[latest], chain[latest],
                                    *_ends(whole[latest], envelope, origins, directions), envelope, pieces)
        out.append((closed, envelope[0, closed], envelope[1, closed], pieces.chain_first[by]))
        envelope[1, closed] = envelope[0, closed]
    open_ = envelope[0, whole] < envelope[1, whole]
    out.append(_solved(whole[open_], chain[open_], envelope, origins, directions, pieces, whole=True))
    a, b = _ends(seg, envelope, origins, directions)
    # A segment lying deep enough inside a span (both ends at least the span's slack inside
    # its hull, which is convex) is removed whole: its other pairs need no solving. First the
    # latest span of each segment: on a path of short moves (arcs as chords)
    # a line on the tool's trailing side lies inside dozens of the moves just before, and the
    # latest closes it without a test of the others.
    latest = _latest(seg, span)
    closed, by = _closed_inside("span", seg[latest], span[latest], _rows(a, latest), _rows(b, latest), envelope, pieces)
    out.append((closed, envelope[0, closed], envelope[1, closed], by))
    envelope[1, closed] = envelope[0, closed]
    tried = np.zeros(seg.size, dtype=bool)
    tried[latest] = True
    rest = np.flatnonzero(envelope[0, seg] < envelope[1, seg])
    seg, span, tried = seg[rest], span[rest], tried[rest]
    a, b = _rows(a, rest), _rows(b, rest)
    hulls = pieces.hulls("span", span)
    keep = ~_apart(a, b, *hulls, 0.0, 0.5 * pieces.span_turn[span], touch=True)
    seg, span = seg[keep], span[keep]
    if seg.size == 0:
        return tuple(np.concatenate(part) for part in zip(*out))
    # The others (a latest span not found inside saw the same ends and the same tests).
    at = np.flatnonzero(keep)
    inside = np.zeros(at.size, dtype=bool)
    test = np.flatnonzero(~tried[at])
    c0, c1, axis, radius, h = (_rows(column, at[test]) for column in hulls)
    inside[test] = _deep_inside(_rows(a, at[test]), _rows(b, at[test]), c0, c1, axis, radius, h,
                                pieces.span_slack[span[test]], pieces.corners("span", span[test]))
    out.append((seg[inside], envelope[0, seg[inside]], envelope[1, seg[inside]], span[inside]))
    envelope[1, seg[inside]] = envelope[0, seg[inside]]
    span = span[~inside]
    seg, piece = _span_pieces(seg[~inside], span, pieces)
    # A span of one piece that does not turn is that piece's own hull, tested just now with the
    # same ends (only envelopes closed by `inside` changed since): not tested again.
    tested = np.repeat((pieces.span_count[span] == 1) & (pieces.span_turn[span] == 0.0), pieces.span_count[span])
    # First, per segment, the pair whose piece reaches lowest along its line and the one
    # reaching highest (per run of the segment's pairs, without sorting); they usually leave
    # few pairs near. Those are ranked once by how low and how high their pieces reach; each
    # later round solves the `take` first of each ranking among the pairs still open.
    lower, upper = _extent(_rows(origins, seg), _rows(directions, seg), *pieces.hulls("piece", piece))
    open_ = _near_pieces(seg, piece, envelope, origins, directions, pieces, tested)
    chosen = np.flatnonzero(open_ & (_smallest(seg, np.where(open_, lower, np.inf), 1)
                                     | _smallest(seg, np.where(open_, -upper, np.inf), 1)))
    out.append(_solved(seg[chosen], piece[chosen], envelope, origins, directions, pieces))
    open_[chosen] = False
    rest = np.flatnonzero(open_)
    seg, piece, lower, upper = seg[rest], piece[rest], lower[rest], upper[rest]
    rankings = [_Ranking(seg, lower), _Ranking(seg, -upper)]
    open_ = np.ones(seg.size, dtype=bool)
    take = 1
    while open_.any():
        at = np.flatnonzero(open_)
        open_[at[~_near_pieces(seg[at], piece[at], envelope, origins, directions, pieces)]] = False
        chosen = np.flatnonzero(rankings[0].first(open_, take) | rankings[1].first(open_, take))
        out.append(_solved(seg[chosen], piece[chosen], envelope, origins, directions, pieces))
        open_[chosen] = False
        take *= 2
    return tuple(np.concatenate(part) for part in zip(*out))



def _latest(seg, item):
    """(R,) the rows, one per distinct segment of seg (K,), of its largest item (K,) int (ties: the
    first): runs of equal segments, where they come in order, else after a stable sort by segment."""
    if seg.size == 0:
        return np.zeros(0, dtype=np.intp)
    order = None
    if (seg[1:] < seg[:-1]).any():
        order = np.argsort(seg, kind="stable")
        seg, item = seg[order], item[order]
    start, count = run_starts(seg)
    hit = (item == np.repeat(np.maximum.reduceat(item, start), count)).nonzero()[0]
    first = hit[run_starts(seg[hit])[0]]
    return first if order is None else order[first]

def _closed_inside(level, seg, item, a, b, envelope, pieces):
    """(segments, items): of the pairs (segment seg, span or chain item) (K,) (level "span" or
    "chain"), with the segments' ends a, b (K, 3), those whose segment is still open and lies
    deep inside the item's hull (_deep_inside, grown by its slack). A span must also pass the
    sure-miss test that _line_span_pairs makes of every pair first (a segment within
    inprocess_touch.TOUCH of its axial range counts as apart), so that a pair found inside here
    is one found inside there; a rigid chain is solved whole unconditionally, and its closed form
    removes such a segment as well."""
    open_ = np.flatnonzero(envelope[0, seg] < envelope[1, seg])
    seg, item, a, b = seg[open_], item[open_], _rows(a, open_), _rows(b, open_)
    hulls = pieces.hulls(level, item)
    if level == "span":
        near = np.flatnonzero(~_apart(a, b, *hulls, 0.0, 0.5 * pieces.span_turn[item], touch=True))
        seg, item, a, b = seg[near], item[near], _rows(a, near), _rows(b, near)
        hulls = tuple(_rows(column, near) for column in hulls)
    inside = _deep_inside(a, b, *hulls, getattr(pieces, level + "_slack")[item], pieces.corners(level, item))
    return seg[inside], item[inside]

class _Ranking:
    """The rows (K,) of each owner (K,) ordered by a key (K,), ties to the earlier row,
    sorted once for rounds that each take the first few rows still open."""

    def __init__(self, owner, key):
        self.order = group_order(key, owner)
        ranked = owner[self.order]
        self.start, self.count = run_starts(ranked)

    def first(self, open_, take):
        """(K,) bool: of each owner's rows with open_ (K,) True, the `take` first in the order."""
        still = open_[self.order]
        seen = np.cumsum(still)
        before = np.repeat(seen[self.start] - still[self.start], self.count)
        chosen = np.zeros(open_.size, dtype=bool)
        chosen[self.order[still & (seen - before <= take)]] = True
        return chosen


def _near_pieces(seg, piece, envelope, origins, directions, pieces, tested=None):
    """(K,) bool: the pairs (seg, piece) (K,) whose segment's envelope is open and from which the
    piece may remove more than LENGTH_EPS; tested (K,) bool: pairs known to pass that test for
    the present envelopes where open (not tested again)."""
    near = envelope[0, seg] < envelope[1, seg]
    at = np.flatnonzero(near if tested is None else near & ~tested)
    seg, piece = seg[at], piece[at]
    a, b = _ends(seg, envelope, origins, directions)
    near[at] = ~_apart(a, b, *pieces.hulls("piece", piece), 0.0, touch=True)
    return near


def _span_pieces(seg, span, pieces):
    """The pairs (seg, span) (K,) expanded to (seg, piece): every piece of each span."""
    owner, rank = _csr(pieces.span_count[span])
    return seg[owner], pieces.span_first[span][owner] + rank


def _solved(seg, piece, envelope, origins, directions, pieces, whole=False):
    """Removal intervals (seg, enter, leave, span) of the segments seg (K,) inside pieces piece (K,)
    (with `whole`, inside the hulls of rigid chains piece (K,)) that overlap their first ranges
    (envelope (4, L), rows 2, 3) by more than LENGTH_EPS, closed form in batches; the envelopes
    (rows 0, 1) are narrowed; span: the span of each piece (of a chain, its first)."""
    found = [_none()]
    for begin in range(0, seg.size, _PAIR_BATCH):
        s, q = seg[begin:begin + _PAIR_BATCH], piece[begin:begin + _PAIR_BATCH]
        enter, leave = _line_interval(_rows(origins, s), _rows(directions, s), pieces, "chain" if whole else "piece", q)
        # Kept when it overlaps the line's first range by more than LENGTH_EPS, not the
        # current one: which removals are kept then does not depend on the order they are
        # found in (docs/ENGINE.md, "Same input, same bits").
        with np.errstate(invalid="ignore"):
            hit = (np.minimum(leave, envelope[3, s]) - np.maximum(enter, envelope[2, s])) > LENGTH_EPS
        span = pieces.chain_first[q[hit]] if whole else np.searchsorted(pieces.span_first, q[hit], side="right") - 1
        found.append((s[hit], enter[hit], leave[hit], span))
        narrow(envelope, *found[-1][:3])
    return tuple(np.concatenate(part) for part in zip(*found))


def _line_interval(origin, direction, pieces, level, index):
    """(enter, leave) (K,) of the lines (origin, direction (K, 3)) in the hulls of pieces or chains `index`
    (K,) at `level`: inprocess_plan.piece_line_interval (closed forms for flat-end tools and where the plan view
    decides, inprocess_swept.line_swept_interval for the others)."""
    hulls = pieces.hulls(level, index)
    if not pieces.any_corner:
        return line_hull_interval(origin, direction, *hulls)
    return piece_line_interval(origin, direction, *hulls, pieces.corners(level, index))


def _extent(origin, direction, c0, c1, axis, radius, height):
    """(lower, upper) (K,) mm: every point of each hull (c0, c1, axis, radius, height) on the
    line origin + l·direction has lower ≤ l ≤ upper. Two bounds, the tighter taken: the hull's
    extent along the direction, and where the line crosses the planes bounding the hull's
    axial range (the point at l has axial height a0 + l·ua − s·da for some s ∈ [0, 1], which
    must lie within 0 … H)."""
    q, d = origin - c0, c1 - c0
    base = -row_dot(q, direction)
    du = row_dot(d, direction)
    wu = row_dot(axis, direction)
    across = radius * np.sqrt(np.maximum(1.0 - wu * wu, 0.0))
    lower = base + np.minimum(du, 0.0) + np.minimum(height * wu, 0.0) - across
    upper = base + np.maximum(du, 0.0) + np.maximum(height * wu, 0.0) + across
    a0, da = row_dot(q, axis), row_dot(d, axis)
    with np.errstate(divide="ignore", invalid="ignore"):
        first = (np.minimum(da, 0.0) - a0) / wu
        second = (height + np.maximum(da, 0.0) - a0) / wu
    crossing = np.abs(wu) > 0.0
    lower = np.where(crossing, np.maximum(lower, np.minimum(first, second)), lower)
    upper = np.where(crossing, np.minimum(upper, np.maximum(first, second)), upper)
    return lower, upper


def _smallest(owner, key, take):
    """(K,) bool: the `take` rows of smallest key (K,) of each owner (K,, ascending), ties to the
    earlier row: `take` rounds of a minimum per owner (no sort). Owners out of order are
    taken per run: an owner in two runs gets `take` rows in each."""
    chosen = np.zeros(owner.size, dtype=bool)
    if owner.size == 0:
        return chosen
    start, count = run_starts(owner)
    left = np.array(key, dtype=float)  # a copy: chosen rows become NaN, which fmin passes over
    for _ in range(take):
        hit = np.flatnonzero(left == np.repeat(np.fmin.reduceat(left, start), count))
        first = hit[run_starts(owner[hit])[0]]
        chosen[first] = True
        left[first] = np.nan
    return chosen


def _across(x, c0, c1, axis):
    """(K,) distance from points x to the segments c0 … c1 seen along the unit axis (all (K, 3),
    mm), from dot products of the components across the axis."""
    q, d = x - c0, c1 - c0
    qw, dw = row_dot(q, axis), row_dot(d, axis)
    qd, dd = _dot_across(q, d, qw, dw), _dot_across(d, d, dw, dw)
    t = clamp(qd / np.where(dd > 0.0, dd, 1.0), 0.0, 1.0)
    return np.sqrt(np.maximum(_dot_across(q, q, qw, qw) - t * (2.0 * qd - t * dd), 0.0))


def subtract(stock: EdgeIntervals, rows, enter, leave):
    """`stock` minus the removal intervals [enter, leave] (R,) of lines `rows` (R,).

    Lines without a removal keep their intervals bit for bit. An end made by a removal gets
    surface "machined", section and wall −1. Returns an EdgeIntervals.
    """
    rows = np.asarray(rows, dtype=np.intp)
    touched = np.zeros(stock.n_rows, dtype=bool)
    touched[rows] = True
    labels = ("start_surface", "start_section", "start_wall", "end_surface", "end_section", "end_wall")
    if not touched.any():
        return stock
    mine = touched[stock.rows]
    keep = np.flatnonzero(~mine)
    edit = np.flatnonzero(mine)
    # Events along each touched line; at one position: stock ends, removal starts, removal
    # ends, stock starts (so that touching removals never open a gap and stock labels win):
    # given in that order, which the stable sorts keep among equal positions.
    k, r = edit.size, rows.size
    ev_row = np.concatenate([stock.rows[edit], rows, rows, stock.rows[edit]])
    ev_pos = np.concatenate([stock.end[edit], enter, leave, stock.start[edit]])
    ev_kind = np.repeat(np.arange(4), [k, r, r, k])
    ev_source = np.concatenate([edit, np.full(2 * r, -1), edit])
    order = group_order(ev_pos, ev_row)
    ev_row, ev_pos, ev_kind, ev_source = ev_row[order], ev_pos[order], ev_kind[order], ev_source[order]
    # Kinds 0 … 3: stock end, removal start, removal end, stock start.
    in_stock = np.cumsum(np.array([-1, 0, 0, 1])[ev_kind])
    in_removal = np.cumsum(np.array([0, 1, -1, 0])[ev_kind])
    inside = (in_stock > 0) & (in_removal == 0)
    seg = np.flatnonzero(inside[:-1] & (ev_row[1:] == ev_row[:-1]) & (ev_pos[1:] - ev_pos[:-1] > LENGTH_EPS))
    begin, finish = seg, seg + 1
    out = {"rows": ev_row[begin], "start": ev_pos[begin], "end": ev_pos[finish]}
    from_stock = ev_kind[begin] == 3
    to_stock = ev_kind[finish] == 0
    for name in labels:
        at, own = (begin, from_stock) if name.startswith("start") else (finish, to_stock)
        machined = _MACHINED if name.endswith("surface") else -1
        out[name] = np.where(own, getattr(stock, name)[np.maximum(ev_source[at], 0)], machined)
    # Both parts come sorted by row, then start, and share no row: a stable sort by row
    # (which merges the two runs) puts them in order.
    merged = {name: np.concatenate([getattr(stock, name)[keep], out[name]]) for name in out}
    order = np.argsort(merged["rows"], kind="stable")
    return EdgeIntervals(stock.n_rows, **{name: values[order] for name, values in merged.items()})


def rapid_collisions(stock, moves: ProgramMoves, *, spacing=0.5, chunk_lines=1 << 16):
    """Rapids whose swept tool enters the staircase `stock` (for a collision warning).

    Each rapid (a move into row j with cutting[j] False, j ≥ 1) is probed by the lines of its
    tool's side at positions along the move no farther apart than `spacing` (mm) and at angles
    no farther apart than `spacing` along the rim, position and axis interpolated as for a
    cutting move; their inside length in the stock is exact (inside_intervals). A probe finds
    any material the tool's side passes through, and material under its bottom face that
    reaches its rim; a spike thinner than `spacing` that only touches the face between probes
    can be missed. Returns (rows (R,) int, lines (R,) int, depth (R,) mm): the rapids that cut,
    their source lines and the longest probe length inside the stock.
    """
    from .engagement import inside_intervals

    spacing = float(spacing)
    if not spacing > 0.0:
        raise ValueError(f"spacing must be positive, got {spacing}")
    j = np.flatnonzero(~moves.cutting[1:]) + 1
    found_rows, found_depth = [], []
    for row in j:
        p0, p1, w0, w1 = moves.cl[row - 1], moves.cl[row], moves.axis[row - 1], moves.axis[row]
        r, h = moves.radius[row], moves.flute_length[row]
        steps = max(1, int(np.ceil(np.linalg.norm(p1 - p0) / spacing)))
        t = np.linspace(0.0, 1.0, steps + 1)
        centre = p0 + t[:, None] * (p1 - p0)
        axis = (1.0 - t)[:, None] * w0 + t[:, None] * w1
        axis /= np.linalg.norm(axis, axis=1)[:, None]
        helper = np.where(np.abs(axis[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
        u = np.cross(helper, axis)
        u /= np.linalg.norm(u, axis=1)[:, None]
        v = np.cross(axis, u)
        angle = np.linspace(0.0, 2.0 * np.pi, max(8, int(np.ceil(2.0 * np.pi * r / spacing))), endpoint=False)
        radial = np.cos(angle)[None, :, None] * u[:, None, :] + np.sin(angle)[None, :, None] * v[:, None, :]
        origins = (centre[:, None, :] + r * radial).reshape(-1, 3)
        directions = np.repeat(axis, angle.size, axis=0)
        depth = 0.0
        for begin in range(0, origins.shape[0], chunk_lines):
            part = inside_intervals(stock, origins[begin:begin + chunk_lines], directions[begin:begin + chunk_lines], h)
            if part.rows.size:
                depth = max(depth, float(part.length.max()))
        if depth > LENGTH_EPS:
            found_rows.append(row)
            found_depth.append(depth)
    rows = np.array(found_rows, dtype=np.intp)
    return rows, moves.line[rows], np.array(found_depth, dtype=float)


def pass_inprocess(stock, tool, toolpath, phi_deg, pieces: SweptPieces, program_index, *, chunk_instants=1 << 15):
    """The in-process intervals of a whole pass, chunk by chunk (bounded memory).

    stock: Staircase; tool: Tool; toolpath: Toolpath of m CL points in the stock's frame (the
    program's pieces moved into it, e.g. swept_pieces(moves.transformed(R, t))); phi_deg: (p,)
    angles (deg); program_index: (m,) the program row of each CL point. Yields (start, stop,
    EdgeIntervals of the (stop − start)·p lines, row (i − start)·p + k, changed (stop − start,)).
    """
    from .engagement import _slice, edge_lines, inside_intervals

    phi = np.atleast_1d(np.asarray(phi_deg, dtype=float))
    program_index = np.asarray(program_index, dtype=np.intp).reshape(-1)
    m, p = len(toolpath), phi.size
    if program_index.shape != (m,):
        raise ValueError(f"program_index must have shape ({m},), got {program_index.shape}")
    step = max(1, int(chunk_instants) // max(p, 1))
    for start in range(0, m, step):
        stop = min(m, start + step)
        base, direction = edge_lines(_slice(toolpath, start, stop), tool, phi)
        origins, directions = base.reshape(-1, 3), np.repeat(direction, p, axis=0)
        stock_intervals = inside_intervals(stock, origins, directions, tool.flute_length)
        result, changed = inprocess_intervals(stock_intervals, pieces, program_index[start:stop], origins, directions, p)
        yield start, stop, result, changed
