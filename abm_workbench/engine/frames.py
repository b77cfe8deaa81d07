"""Tool frames: R = Rz(α)·Rx(θ_A)·Ry(θ_B) and tool-axis vectors (notes §2, docs/ENGINE.md "Frames").

Angles are in degrees here as at every interface. α turns the paper's frame about z to the feed
direction in plan view (engine.feed): u, v, w are R's columns, w the tool axis, φ measured from
+v towards +u, so φ = 90° points along the feed. With α = 0 this is the paper's frame, whose
pass feeds along +x. The tool axis is w = Rz(α)·(sin θ_B, −sin θ_A cos θ_B, cos θ_A cos θ_B);
θ_A and θ_B are those of the axis (i, j, k) turned by −α: θ_A = atan2(−j, k) over the whole
circle, θ_B = asin(i) in [−90°, 90°], so every direction has angles, also k ≤ 0 (a tool pointing
sideways or down, as on indexed four-axis parts and undercuts).
"""

import numpy as np

from ..errors import CLPointError


def rotation_matrix(theta_a, theta_b, alpha=None):
    """R = Rz(α)·Rx(θ_A)·Ry(θ_B) for angles in degrees: (...,) each -> (..., 3, 3).

    alpha None (or all zero) gives Rx(θ_A)·Ry(θ_B) exactly, as the paper's frame.
    """
    ta = np.radians(np.asarray(theta_a, dtype=float))
    tb = np.radians(np.asarray(theta_b, dtype=float))
    ta, tb = np.broadcast_arrays(ta, tb)
    ca, sa, cb, sb = np.cos(ta), np.sin(ta), np.cos(tb), np.sin(tb)
    zero = np.zeros_like(ca)
    rows = [np.stack([cb, zero, sb], axis=-1), np.stack([sa * sb, ca, -sa * cb], axis=-1),
            np.stack([-ca * sb, sa, ca * cb], axis=-1)]
    if alpha is not None and np.any(alpha):
        turn = np.radians(np.broadcast_to(np.asarray(alpha, dtype=float), ca.shape))
        c, s = np.cos(turn)[..., None], np.sin(turn)[..., None]
        rows = [c * rows[0] - s * rows[1], s * rows[0] + c * rows[1], rows[2]]
    return np.stack(rows, axis=-2)


def angles_to_axis(theta_a, theta_b, alpha=None):
    """Unit tool axes (..., 3) for angles θ_A, θ_B (and the frame's turn α) in degrees (...,)."""
    return rotation_matrix(theta_a, theta_b, alpha)[..., :, 2]


def turned_axes(axes, alpha):
    """The axes (m, 3) expressed in frames turned about z by α (m,) deg: Rz(−α)·axis."""
    axes = np.asarray(axes, dtype=float)
    turn = np.radians(np.asarray(alpha, dtype=float))
    c, s = np.cos(turn), np.sin(turn)
    i, j, k = np.ascontiguousarray(axes.T)
    return np.stack([c * i + s * j, c * j - s * i, k], axis=1)


def axis_to_angles(axes, alpha=None):
    """(θ_A, θ_B) in degrees, each (m,), for tool-axis vectors (m, 3), normalised here, in the frames
    turned by α (m,) deg (None: not turned).

    θ_A in (−180°, 180°], θ_B in [−90°, 90°]. Raises CLPointError (a ValueError) naming the first row
    whose axis is zero or not finite.
    """
    axes = np.asarray(axes, dtype=float)
    if axes.ndim != 2 or axes.shape[1] != 3:
        raise ValueError(f"tool axes must have shape (m, 3), got {axes.shape}")
    norm = np.linalg.norm(axes, axis=1)
    bad = ~np.isfinite(norm) | (norm == 0.0)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise CLPointError(i, f"tool axis {axes[i].tolist()} is zero or not finite")
    unit = axes / norm[:, None]
    if alpha is not None and np.any(alpha):
        unit = turned_axes(unit, alpha)
    # Contiguous columns: numpy picks its vectorised or its scalar arctan2 (which can differ in the last
    # bit) by whether the output's memory may overlap the inputs' span, and a strided column's span
    # runs past its array's end, into memory that a fresh output may occupy.
    i, j, k = np.ascontiguousarray(unit.T)
    theta_b = np.degrees(np.arcsin(np.clip(i, -1.0, 1.0)))
    theta_a = np.degrees(np.arctan2(-j, k))
    return theta_a, theta_b
