"""Small polynomials, many at once: evaluation, composition with a line, real roots on [0, 1].

Used for the curve boundary (notes §4): the edge line composed with a wall's quintic is a
polynomial in the edge parameter. Roots are isolated exactly by recursion on derivatives
(between two consecutive real roots of p' the polynomial p is monotone, so it has at most one
root there) and polished by a safeguarded Newton-bisection that never leaves its bracket.
A tiny or zero leading coefficient (the degree drop when sin θ_A cos θ_B → 0) needs no special
case: nothing here divides by the leading coefficient.
"""

from math import comb

import numpy as np

from .rows import row_max, row_min, row_sum
from .tolerances import FAST_NEWTON, ROOT_MAX_ITER, ROOT_TOL


def horner(coefficients, t):
    """Σ c_k t^k for ascending coefficients (d+1,) or (..., d+1) broadcast against t."""
    coefficients = np.asarray(coefficients, dtype=float)
    result = np.zeros(np.broadcast_shapes(coefficients.shape[:-1], np.shape(t)))
    for k in range(coefficients.shape[-1] - 1, -1, -1):
        result = result * t + coefficients[..., k]
    return result


def derivative(coefficients):
    """Ascending coefficients (..., d+1) -> those of the derivative (..., d)."""
    d = coefficients.shape[-1] - 1
    return coefficients[..., 1:] * np.arange(1, d + 1)


def compose_linear(coefficients, t0, q):
    """Coefficients in u of P(t0 + q·u), for many polynomials at once.

    coefficients: (..., d+1) ascending; t0, q: (...) broadcast with them. Returns (..., d+1)
    ascending in u (compose_columns on the coefficients laid out as columns).
    """
    c = np.moveaxis(np.asarray(coefficients, dtype=float), -1, 0)
    return np.moveaxis(compose_columns(c, t0, q), 0, -1)


def compose_columns(columns, t0, q):
    """compose_linear with the coefficients as columns: (d+1, ...) ascending -> (d+1, ...).

    K_k = q^k · Σ_{i=k..d} C(i, k) c_i t0^(i−k), the Taylor coefficients of P at t0 (by
    repeated synthetic division: d(d+1)/2 multiply-adds) scaled by q^k. Each K_k is one
    contiguous array, which is what the root finders take.
    """
    c = np.asarray(columns, dtype=float)
    t0, q = np.asarray(t0, dtype=float), np.asarray(q, dtype=float)
    d = c.shape[0] - 1
    shape = np.broadcast_shapes(c.shape[1:], t0.shape, q.shape)
    taylor = [np.broadcast_to(c[k], shape).copy() for k in range(d + 1)]
    product = np.empty(shape)
    for i in range(d):
        for k in range(d - 1, i - 1, -1):
            taylor[k] += np.multiply(t0, taylor[k + 1], out=product)
    out = np.empty((d + 1,) + shape)
    scale = np.ones(shape)
    for k in range(d + 1):
        np.multiply(taylor[k], scale, out=out[k, ...])
        if k < d:
            scale *= q
    return out


def k_coefficients(h, a, b, s, sin_b):
    """The paper's K_0..K_5 (Eqs. 15-21 as corrected in the notes §4), ascending, shape (..., 6).

    h: (6,) raw coefficients H_0..H_5 of x = P(y); a, b, s (= sin θ_A cos θ_B) and sin_b
    (= sin θ_B) broadcast together. Σ K_k l^k = P(b − s·l) − (a + sin_b·l).
    """
    a, b, s, sin_b = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (a, b, s, sin_b)))
    k = compose_linear(h, b, -s)
    k[..., 0] -= a
    k[..., 1] -= sin_b
    return k


def value_and_slope(columns, t):
    """p(t) and p′(t) by one Horner pass; columns (d+1, m): the coefficients, ascending, by row.

    In place on two arrays (new ones per step cost more than the arithmetic at 10^4 rows).
    """
    value = np.array(columns[-1], dtype=float)
    slope = np.zeros_like(value)
    for k in range(columns.shape[0] - 2, -1, -1):
        slope *= t
        slope += value
        value *= t
        value += columns[k]
    return value, slope


def bracketed_root(columns, lo, hi, f_lo, f_hi):
    """The root of p in [lo, hi] where p(lo), p(hi) differ in sign (or one is zero).

    columns: (d+1, m) coefficients, ascending, by row (as value_and_slope takes them); lo,
    hi, f_lo, f_hi: (m,). From the secant point, FAST_NEWTON plain
    Newton steps; a row whose result lies in its bracket with a last Newton step below
    ROOT_TOL is done (p has one root in the bracket, and Newton has converged to a point of
    it). The other rows restart from the secant point with the safeguarded Newton: a step
    that leaves the bracket is replaced by bisection, and the bracket shrinks every step.
    Every row's result depends on that row alone. Returns (m,) roots, accurate to ROOT_TOL on
    the unit scale.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        start = np.where(f_hi != f_lo, lo - f_lo * (hi - lo) / (f_hi - f_lo), 0.5 * (lo + hi))
    start = np.where((start > lo) & (start < hi), start, 0.5 * (lo + hi))
    start = np.where(f_lo == 0.0, lo, np.where(f_hi == 0.0, hi, start))
    x = start.copy()
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for _ in range(FAST_NEWTON):
            x -= _newton_step(columns, x)
        step = _newton_step(columns, x)
    done = (f_lo == 0.0) | (f_hi == 0.0)
    x = np.where(done, start, np.minimum(np.maximum(x - step, lo), hi))
    ok = done | ((x >= lo) & (x <= hi) & (np.abs(step) <= ROOT_TOL))
    again = np.flatnonzero(~ok)
    if again.size:
        x[again] = _safeguarded_newton(columns[:, again], lo[again], hi[again], f_lo[again], start[again])
    return x


def guarded_root(columns, lo, hi, f_lo, f_hi):
    """The root of p in [lo, hi] where p(lo) = f_lo and p(hi) = f_hi differ in sign, both nonzero: the
    safeguarded Newton of bracketed_root's fallback from the secant point, which never leaves the bracket
    (for a polynomial that need not be monotone there, where plain Newton may run to another root).
    columns (d+1, m), lo, hi, f_lo, f_hi (m,) as bracketed_root takes them; (m,) roots to ROOT_TOL."""
    with np.errstate(divide="ignore", invalid="ignore"):
        start = lo - f_lo * (hi - lo) / (f_hi - f_lo)
    start = np.where((start > lo) & (start < hi), start, 0.5 * (lo + hi))
    return _safeguarded_newton(columns, lo, hi, f_lo, start)


def _newton_step(columns, x):
    """p(x)/p′(x), 0 where p(x) = 0, for columns (d+1, m) and x (m,) (call under np.errstate)."""
    f, step = value_and_slope(columns, x)
    np.divide(f, step, out=step)
    np.copyto(step, 0.0, where=f == 0.0)
    return step


def _safeguarded_newton(columns, lo, hi, f_lo, x):
    """bracketed_root's fallback from start points x (m,) inside the brackets, p(lo) = f_lo ≠ 0;
    columns (d+1, m) as bracketed_root takes them.

    All rows step together (a finished row stays put), which at these sizes is cheaper than
    gathering the unfinished ones.
    """
    lo, hi = lo.copy(), hi.copy()
    done = np.zeros(x.shape, dtype=bool)
    negative_lo = f_lo < 0.0
    for _ in range(ROOT_MAX_ITER):
        if done.all():
            break
        f, slope = value_and_slope(columns, x)
        toward_hi = (f < 0.0) == negative_lo  # same sign as at lo: the root is above x
        lo = np.where(done | ~toward_hi, lo, x)
        hi = np.where(done | toward_hi, hi, x)
        with np.errstate(divide="ignore", invalid="ignore"):
            nxt = x - f / slope
        nxt = np.where((nxt > lo) & (nxt < hi), nxt, 0.5 * (lo + hi))
        finished = done | (f == 0.0) | (np.abs(nxt - x) <= ROOT_TOL) | (hi - lo <= ROOT_TOL)
        x = np.where(done | (f == 0.0), x, nxt)
        done = finished
    return x


def real_roots_unit(coefficients):
    """All real roots in [0, 1] of each polynomial; (m, d+1) ascending -> (m, d), NaN-padded.

    Roots come in increasing order along each row, each simple or tangential root once.
    """
    c = np.asarray(coefficients, dtype=float)
    m, d = c.shape[0], c.shape[1] - 1
    if d == 1:
        with np.errstate(divide="ignore", invalid="ignore"):
            r = -c[:, 0] / c[:, 1]
        return np.where((r >= 0.0) & (r <= 1.0), r, np.nan)[:, None]
    if d == 2:
        return _quadratic_roots_unit(c)
    critical = real_roots_unit(derivative(c))
    knots = np.sort(np.concatenate([np.zeros((m, 1)), critical, np.ones((m, 1))], axis=1), axis=1)
    knots = np.where(np.isnan(knots), 1.0, knots)
    lo, hi = knots[:, :-1], knots[:, 1:]
    f_lo, f_hi = horner(c[:, None, :], lo), horner(c[:, None, :], hi)
    last = hi == 1.0
    found = (hi > lo) & (
        (np.sign(f_lo) * np.sign(f_hi) < 0.0) | (f_lo == 0.0) | ((f_hi == 0.0) & last)
    )
    out = np.full((m, d), np.nan)
    r, k = np.nonzero(found)
    if r.size:
        out[r, k] = bracketed_root(np.ascontiguousarray(c[r].T), lo[r, k], hi[r, k], f_lo[r, k], f_hi[r, k])
    return np.sort(out, axis=1)


def _quadratic_roots_unit(c):
    """Real roots in [0, 1] of c0 + c1 u + c2 u², (m, 3) -> (m, 2) sorted, NaN-padded.

    The cancellation-free form: q = −(c1 + sign(c1)·√disc)/2, roots q/c2 and c0/q. A vanishing
    c2 sends q/c2 off to infinity (dropped) and leaves c0/q = −c0/c1, the linear root; a double
    root is kept once.
    """
    c0, c1, c2 = c[:, 0], c[:, 1], c[:, 2]
    disc = c1 * c1 - 4.0 * c2 * c0
    with np.errstate(divide="ignore", invalid="ignore"):
        q = -0.5 * (c1 + np.where(c1 < 0.0, -1.0, 1.0) * np.sqrt(np.maximum(disc, 0.0)))
        roots = np.stack([q / c2, c0 / q], axis=1)
    roots = np.where((disc >= 0.0)[:, None] & (roots >= 0.0) & (roots <= 1.0), roots, np.nan)
    roots = np.sort(roots, axis=1)
    roots[:, 1] = np.where(roots[:, 1] == roots[:, 0], np.nan, roots[:, 1])
    return roots


def proved_monotone_unit(coefficients):
    """(m,) bool: each polynomial is strictly monotone on [0, 1], proved by its derivative's
    Bernstein coefficients on [0, 1] all having one sign (they bound the derivative there).

    coefficients: (m, d+1) ascending. A coefficient within the rounding margin of zero counts
    as no proof, so a row near a tangency is left to the root isolation.
    """
    c = np.asarray(coefficients, dtype=float)
    d = c.shape[1] - 1
    if d < 1:
        return np.zeros(c.shape[0], dtype=bool)
    slope = derivative(c)
    bernstein = bernstein_unit(slope)
    margin = 1e-12 * row_sum(np.abs(slope))
    return (row_min(bernstein) > margin) | (row_max(bernstein) < -margin)


def bernstein_unit(coefficients):
    """Bernstein coefficients on [0, 1] (m, d+1) of polynomials given in the power basis (m, d+1),
    ascending; each polynomial lies between the least and the greatest of its own over [0, 1]."""
    c = np.asarray(coefficients, dtype=float)
    return c @ _power_to_bernstein(c.shape[1] - 1).T


def product(p, q):
    """Row-wise products (m, a+b−1) of polynomials (m, a) and (m, b), ascending."""
    out = np.zeros((p.shape[0], p.shape[1] + q.shape[1] - 1))
    for i in range(p.shape[1]):
        out[:, i:i + q.shape[1]] += p[:, i:i + 1] * q
    return out


def _power_to_bernstein(degree):
    """(degree+1, degree+1) matrix B with b = B·a: Bernstein coefficients on [0, 1] of the
    power-basis coefficients a (b_j = Σ_{i ≤ j} C(j, i)/C(degree, i)·a_i)."""
    return np.array([[comb(j, i) / comb(degree, i) if i <= j else 0.0 for i in range(degree + 1)]
                     for j in range(degree + 1)])


def monotone_root_unit(columns):
    """The root in [0, 1] of polynomials known to be monotone there, NaN if none.

    columns: (d+1, m) coefficients, ascending, by row (as bracketed_root takes them) -> (m,).
    """
    c = np.asarray(columns, dtype=float)
    m = c.shape[1]
    f_lo, f_hi = c[0], row_sum(c.T)
    found = (np.sign(f_lo) * np.sign(f_hi) < 0.0) | (f_lo == 0.0) | (f_hi == 0.0)
    out = np.full(m, np.nan)
    idx = np.flatnonzero(found)
    if idx.size == m:
        out = bracketed_root(c, np.zeros(m), np.ones(m), f_lo, f_hi)
    elif idx.size:
        out[idx] = bracketed_root(c[:, idx], np.zeros(idx.size), np.ones(idx.size), f_lo[idx], f_hi[idx])
    return out
