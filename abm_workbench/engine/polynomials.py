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

from .tolerances import ROOT_MAX_ITER, ROOT_TOL


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
    ascending in u: K_k = q^k · Σ_{i=k..d} C(i, k) c_i t0^(i−k).
    """
    c = np.asarray(coefficients, dtype=float)
    t0, q = np.asarray(t0, dtype=float), np.asarray(q, dtype=float)
    d = c.shape[-1] - 1
    shape = np.broadcast_shapes(c.shape[:-1], t0.shape, q.shape)
    powers = [np.ones(t0.shape)]
    for _ in range(d):
        powers.append(powers[-1] * t0)
    out = np.empty(shape + (d + 1,))
    scale = np.ones(q.shape)
    for k in range(d + 1):
        total = np.zeros(shape)
        for i in range(k, d + 1):
            total = total + comb(i, k) * c[..., i] * powers[i - k]
        out[..., k] = total * scale
        scale = scale * q
    return out


def k_coefficients(h, a, b, s, sin_b):
    """The paper's K_0..K_5 (Eqs. 15-21 as corrected in the notes §4), ascending, shape (..., 6).

    h: (6,) raw coefficients H_0..H_5 of x = P(y); a, b, s (= sin θ_A cos θ_B) and sin_b
    (= sin θ_B) broadcast together. Σ K_k l^k = P(b − s·l) − (a + sin_b·l).
    """
    k = compose_linear(h, np.asarray(b, dtype=float), -np.asarray(s, dtype=float))
    k[..., 0] -= a
    k[..., 1] -= sin_b
    return k


def bracketed_root(coefficients, lo, hi, f_lo, f_hi):
    """The root of p in [lo, hi] where p(lo), p(hi) differ in sign (or one is zero).

    coefficients: (m, d+1); lo, hi, f_lo, f_hi: (m,). Safeguarded Newton: a Newton step
    that leaves the bracket is replaced by bisection, the bracket shrinks every step.
    Returns (m,) roots, accurate to ROOT_TOL on the unit scale.
    """
    lo, hi, f_lo = lo.copy(), hi.copy(), f_lo.copy()
    with np.errstate(divide="ignore", invalid="ignore"):
        x = np.where(f_hi != f_lo, lo - f_lo * (hi - lo) / (f_hi - f_lo), 0.5 * (lo + hi))
    x = np.where((x > lo) & (x < hi), x, 0.5 * (lo + hi))
    x = np.where(f_lo == 0.0, lo, np.where(f_hi == 0.0, hi, x))
    active = np.flatnonzero((f_lo != 0.0) & (f_hi != 0.0))
    slope = derivative(coefficients)
    for _ in range(ROOT_MAX_ITER):
        if active.size == 0:
            break
        c, xa = coefficients[active], x[active]
        f = horner(c, xa)
        same = np.sign(f) == np.sign(f_lo[active])
        lo[active] = np.where(same, xa, lo[active])
        f_lo[active] = np.where(same, f, f_lo[active])
        hi[active] = np.where(same, hi[active], xa)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = f / horner(slope[active], xa)
            nxt = xa - step
        a_lo, a_hi = lo[active], hi[active]
        nxt = np.where((nxt > a_lo) & (nxt < a_hi), nxt, 0.5 * (a_lo + a_hi))
        x[active] = nxt
        done = (f == 0.0) | (np.abs(nxt - xa) <= ROOT_TOL) | (a_hi - a_lo <= ROOT_TOL)
        x[active[f == 0.0]] = xa[f == 0.0]
        active = active[~done]
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
    critical = real_roots_unit(derivative(c))
    knots = np.sort(np.concatenate([np.zeros((m, 1)), critical, np.ones((m, 1))], axis=1), axis=1)
    knots = np.where(np.isnan(knots), 1.0, knots)
    lo, hi = knots[:, :-1], knots[:, 1:]
    rows = np.broadcast_to(np.arange(m)[:, None], lo.shape)
    f_lo, f_hi = horner(c[:, None, :], lo), horner(c[:, None, :], hi)
    last = hi == 1.0
    found = (hi > lo) & (
        (np.sign(f_lo) * np.sign(f_hi) < 0.0) | (f_lo == 0.0) | ((f_hi == 0.0) & last)
    )
    out = np.full((m, d), np.nan)
    r, k = np.nonzero(found)
    if r.size:
        out[r, k] = bracketed_root(c[r], lo[r, k], hi[r, k], f_lo[r, k], f_hi[r, k])
    return np.sort(out, axis=1)


def monotone_root_unit(coefficients):
    """The root in [0, 1] of polynomials known to be monotone there; (m, d+1) -> (m,), NaN if none."""
    c = np.asarray(coefficients, dtype=float)
    m = c.shape[0]
    f_lo, f_hi = c[:, 0], c.sum(axis=1)
    found = (np.sign(f_lo) * np.sign(f_hi) < 0.0) | (f_lo == 0.0) | (f_hi == 0.0)
    out = np.full(m, np.nan)
    idx = np.flatnonzero(found)
    if idx.size:
        out[idx] = bracketed_root(c[idx], np.zeros(idx.size), np.ones(idx.size), f_lo[idx], f_hi[idx])
    return out
