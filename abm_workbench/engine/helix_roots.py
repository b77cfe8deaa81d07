"""Roots along a helical cutting edge, many edges at once (lengths in mm, angles in radians).

A helical edge is P(l) = T + R_t sin ψ·u + R_t cos ψ·v + l·w with ψ = ψ_0 − κ·l
(κ = tan β / R_t), u, v, w the columns of the tool's rotation. Each coordinate, and so
each plane boundary (a top, a limit of the stock's box), is a *sine-line*

    f(l) = a sin ψ + b cos ψ + c·l + d = ρ sin(θ) + c·l + d,   θ = ψ + δ = θ_0 − κ·l,

ρ = hypot(a, b), δ = atan2(b, a). Its derivative f′(l) = c − κρ cos θ vanishes only where
cos θ = c / (κρ): in closed form, at θ = ±arccos(c/(κρ)) + 2πn. Between two consecutive
critical points f is strictly monotone, so it has at most one root there: the critical
points and the ends of [0, L] bracket every root, and none is missed. Each bracket with a
sign change is refined by :func:`safeguarded_root`.
"""

import numpy as np

from .tolerances import ROOT_MAX_ITER

#: Root finders along the helix stop when the Newton step or the bracket is below this (mm).
HELIX_ROOT_TOL = 1e-12


def safeguarded_root(evaluate, lo, hi, f_lo, f_hi):
    """Root of each row's function in [lo, hi] (mm), where f(lo) and f(hi) differ in sign or one is 0.

    evaluate(rows, l) -> (f, slope), each like l: the function and its derivative for the
    rows `rows` (int array into lo) at l; a NaN slope means bisection. Safeguarded Newton: a
    step that leaves the bracket is replaced by bisection and the bracket shrinks every step;
    only unfinished rows are evaluated; the first guess is the secant's root. lo, hi, f_lo,
    f_hi: (N,). Returns (N,) roots, to
    HELIX_ROOT_TOL mm.
    """
    lo, hi = np.array(lo, dtype=float), np.array(hi, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        x = lo - f_lo * (hi - lo) / (f_hi - f_lo)  # the secant's root: exact for a straight edge on a plane
    x = np.where((x > lo) & (x < hi), x, 0.5 * (lo + hi))
    x = np.where(f_lo == 0.0, lo, np.where(f_hi == 0.0, hi, x))
    negative_lo = f_lo < 0.0
    active = np.flatnonzero((f_lo != 0.0) & (f_hi != 0.0))
    for _ in range(ROOT_MAX_ITER):
        if active.size == 0:
            break
        xa = x[active]
        f, slope = evaluate(active, xa)
        toward_hi = (f < 0.0) == negative_lo[active]
        lo[active] = np.where(toward_hi, xa, lo[active])
        hi[active] = np.where(toward_hi, hi[active], xa)
        la, ha = lo[active], hi[active]
        with np.errstate(divide="ignore", invalid="ignore"):
            nxt = xa - f / slope
        nxt = np.where((nxt > la) & (nxt < ha), nxt, 0.5 * (la + ha))
        finished = (f == 0.0) | (np.abs(nxt - xa) <= HELIX_ROOT_TOL) | (ha - la <= HELIX_ROOT_TOL)
        x[active] = np.where(f == 0.0, xa, nxt)
        active = active[~finished]
    return x


class SineLines:
    """N sine-lines f_i(l) = a_i sin ψ_i + b_i cos ψ_i + c_i·l + d_i, ψ_i = ψ0_i − κ·l, 0 ≤ l ≤ length_i.

    a, b, c, d, psi0, length: (N,) (mm, radians); kappa: float (rad/mm), shared. Roots are
    asked for f plus offsets, so one set of critical points serves several parallel planes.
    """

    def __init__(self, a, b, c, d, psi0, kappa, length):
        self.a, self.b, self.c, self.d, self.psi0 = (np.asarray(v, dtype=float) for v in (a, b, c, d, psi0))
        self.kappa = float(kappa)
        self.length = np.broadcast_to(np.asarray(length, dtype=float), self.a.shape)
        self.knots = self._knots()

    def value(self, rows, l):
        """f(l) for rows `rows` (int array) at l (broadcast with rows)."""
        psi = self.psi0[rows] - self.kappa * l
        return self.a[rows] * np.sin(psi) + self.b[rows] * np.cos(psi) + self.c[rows] * l + self.d[rows]

    def slope(self, rows, l):
        """f′(l) for rows `rows` at l."""
        psi = self.psi0[rows] - self.kappa * l
        return self.c[rows] - self.kappa * (self.a[rows] * np.cos(psi) - self.b[rows] * np.sin(psi))

    def bounds(self):
        """(max |f′|, max |f″|) over all l, each (N,): |c| + |κ|ρ and κ²ρ."""
        rho = np.hypot(self.a, self.b)
        return np.abs(self.c) + abs(self.kappa) * rho, self.kappa ** 2 * rho

    def _knots(self):
        """(N, J) sorted 0, the critical points inside (0, length), then length (padded with length)."""
        n = self.a.size
        ends = [np.zeros((n, 1)), self.length[:, None]]
        if self.kappa == 0.0 or n == 0:
            return np.concatenate(ends, axis=1)
        rho = np.hypot(self.a, self.b)
        theta0 = self.psi0 + np.arctan2(self.b, self.a)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            ratio = self.c / (self.kappa * rho)
        has = (rho > 0.0) & (np.abs(ratio) < 1.0)
        alpha = np.arccos(np.clip(np.where(has, ratio, 0.0), -1.0, 1.0))
        theta_end = theta0 - self.kappa * self.length
        low, high = np.minimum(theta0, theta_end), np.maximum(theta0, theta_end)
        turns = int(abs(self.kappa) * float(self.length.max()) / (2.0 * np.pi)) + 2
        columns = list(ends)
        for sign in (1.0, -1.0):
            first = np.ceil((low - sign * alpha) / (2.0 * np.pi))
            theta = sign * alpha[:, None] + 2.0 * np.pi * (first[:, None] + np.arange(turns))
            with np.errstate(over="ignore", invalid="ignore"):
                l = (theta0[:, None] - theta) / self.kappa
            ok = has[:, None] & (theta <= high[:, None]) & (l > 0.0) & (l < self.length[:, None])
            columns.append(np.where(ok, l, np.nan))
        knots = np.sort(np.concatenate(columns, axis=1), axis=1)
        return np.where(np.isnan(knots), self.length[:, None], knots)

    def roots(self, offsets):
        """Roots in [0, length] of f = (the sine-line) + offsets[:, j], each column j apart.

        offsets: (N, J) mm (NaN: no plane). Returns (N, J, B) roots (mm), NaN-padded, B the
        number of monotone brackets: one root at most per bracket.
        """
        n, planes = offsets.shape
        knots = self.knots
        rows = np.arange(n)[:, None]
        at_knots = self.value(rows, knots)                                  # (N, J+1)
        f = at_knots[:, None, :] + offsets[:, :, None]                      # (N, P, K)
        lo, hi = knots[:, None, :-1], knots[:, None, 1:]
        f_lo, f_hi = f[..., :-1], f[..., 1:]
        last = np.arange(lo.shape[2]) == lo.shape[2] - 1
        found = (hi > lo) & ((np.sign(f_lo) * np.sign(f_hi) < 0.0) | (f_lo == 0.0) | ((f_hi == 0.0) & last))
        out = np.full(found.shape, np.nan)
        r, j, k = np.nonzero(found)
        if r.size:
            shift = offsets[r, j]

            def evaluate(sub, l):
                return self.value(r[sub], l) + shift[sub], self.slope(r[sub], l)

            out[r, j, k] = safeguarded_root(evaluate, lo[r, 0, k], hi[r, 0, k], f_lo[r, j, k], f_hi[r, j, k])
        return out
