"""Mechanistic cutting forces of flat-end, bull-nose and ball-end mills from their engagement (pure numpy).

The linear edge-force model (Altintas, *Manufacturing Automation*, ch. 2): an edge element
of axial length db cutting a chip of thickness h feels

    dF_t = (K_tc h + K_te) db,  dF_r = (K_rc h + K_re) db,  dF_a = (K_ac h + K_ae) db

(tangential, radial, axial; K_·c in N/mm², K_·e in N/mm). With straight flutes every point
of flute k sits at the same angle φ_k = φ + 360·k/Z (φ the angle of flute 1, k = 0..Z−1), so
its force is that times its engaged length b_k (the engine's length of cut at φ_k), with
h_k = f sin φ_k cos α (α the inclination of the CL point's move). A flute cuts only inside the immersion, start ≤ φ_k < end (mod 360,
half-open so that a flute on the boundary counts once over a revolution).

Tool frame (u, v, w = the columns of R = Rz(α)·Rx(θ_A)·Ry(θ_B), Toolpath.frames; φ from +v towards +u):

    F_u = −F_t cos φ_k − F_r sin φ_k,  F_v = F_t sin φ_k − F_r cos φ_k,  F_w = F_a

summed over the flutes, then F_global = R·F_tool. Torque about the tool axis = R_t·ΣF_t
(N·mm); spindle power = torque·ω (W). Forces are affine in the feed per tooth at every
instant, F = f·A + B (A the chip-thickness part per mm of feed, B the edge part), which is
what :class:`Forces` stores, so a new feed (scheduling) needs no new engagement.

Helical flutes (helix angle β, κ = tan β / R_t): the point of flute k at height l has the
angle ψ_k(l) = φ + 360·k/Z − κ·l, and the engine (helix.flute_engagement) gives the engaged
intervals [a, b] of l, already cut to the immersion. Every force component is then a sum of
∫ sin ψ, ∫ cos ψ, ∫ sin² ψ, ∫ sin ψ cos ψ and ∫ 1 over dl, taken in closed form
(:func:`interval_integrals`), with db = dl the axial height of an element.

Tools with a corner radius r (bull-nose, ball; straight flutes only): an element of the peripheral
edge at arc length s (engine.profile) has κ, the angle between the axis and the tool surface's
normal n = sin κ·d − cos κ·w (κ = s/r on the corner arc, 90° on the straight side), cuts the chip
h = f sin φ_k sin κ cos α over the width db = dz / sin κ = ds (the edge lies in the plane of d and
w), and its force on the tool is −dF_t·∂d/∂φ − dF_r·n + dF_a·(cos κ·d + sin κ·w), which is the
flat-end's at κ = 90°. Each flute's engaged runs in s (profile.profile_intervals, or a runs_at
callback) are integrated in closed form (:func:`edge_integrals`, :func:`profile_forces`); the torque
takes each element's own distance from the axis, ρ = R − r + r sin κ on the corner.

Units: N, mm, N·mm, W; angles in degrees at the interface.
"""

import dataclasses
from dataclasses import dataclass
from typing import Optional

import numpy as np

from .engine import flute_engagement
from .engine.intervals import EdgeIntervals
from .engine.arguments import WrongArgument, check_arguments
from .engine.model import finite_number
from .engine.profile import as_terraced, corner_top, profile_intervals
from .engine.stocks import engage_stock

#: Default immersion (deg): a flute cuts over the leading half, full slotting.
FULL_SLOT = (0.0, 180.0)
#: Angles (deg) closer than this to an immersion limit count as on it.
ANGLE_EPS = 1e-9
#: Instants (CL points × angles) per call of profile.profile_intervals when flute_runs solves the flutes.
CHUNK_INSTANTS = 1 << 15
#: The six coefficient names, cutting (N/mm²) then edge (N/mm).
COEFFICIENT_NAMES = ("ktc", "krc", "kac", "kte", "kre", "kae")


@dataclass(frozen=True)
class Coefficients:
    """Cutting-force coefficients: ktc, krc, kac (N/mm²), kte, kre, kae (N/mm).

    Every value must be a finite number; ktc must be positive (it drives the torque).
    """

    ktc: float
    krc: float
    kac: float
    kte: float = 0.0
    kre: float = 0.0
    kae: float = 0.0

    def __post_init__(self):
        for name in COEFFICIENT_NAMES:
            object.__setattr__(self, name, finite_number(name, getattr(self, name)))
        if self.ktc <= 0.0:
            raise ValueError(f"ktc must be positive, got {self.ktc:g}")

    @property
    def cutting(self):
        """(3,) K_tc, K_rc, K_ac (N/mm²)."""
        return np.array([self.ktc, self.krc, self.kac])

    @property
    def edge(self):
        """(3,) K_te, K_re, K_ae (N/mm)."""
        return np.array([self.kte, self.kre, self.kae])


#: Materials with published coefficients, each with where its numbers come from (docs/FORCES.md).
MATERIALS = {
    "al7075-t6": (Coefficients(767.01, 168.8, 222.0, 27.7, 26.6, 0.7),
                  "Al7075-T6, cemented carbide, dry: Table 5 (row of its ref. [190]) of 'Milling Force Model "
                  "for Aviation Aluminum Alloy: Academic Insight and Perspective Analysis', Chin. J. Mech. Eng. "
                  "(2021), doi:10.1186/s10033-021-00536-9"),
    "al6082-t6": (Coefficients(631.0, 99.0, 273.0, 13.0, 10.0, 2.8),
                  "Al6082-T6, cemented carbide, dry: Table 5 (row of its ref. [189]) of the same review, "
                  "doi:10.1186/s10033-021-00536-9"),
}


def material(name):
    """Coefficients of a material of MATERIALS (case-insensitive); ValueError listing the known ones."""
    key = str(name).strip().lower()
    if key not in MATERIALS:
        raise ValueError(f"unknown material {name!r} (known: {', '.join(sorted(MATERIALS))})")
    return MATERIALS[key][0]


def check_immersion(immersion):
    """(start, end) in degrees as floats, 0 ≤ start < end ≤ 180; ValueError otherwise.

    Outside 0..180° the chip thickness f sin φ would be negative: that half does not cut.
    """
    try:
        start, end = (float(v) for v in immersion)
    except (TypeError, ValueError):
        raise ValueError(f"immersion must be (start, end) in degrees, got {immersion!r}") from None
    if not (np.isfinite(start) and np.isfinite(end) and 0.0 <= start < end <= 180.0):
        raise ValueError(f"immersion {start:g}:{end:g} must satisfy 0 <= start < end <= 180 degrees")
    return start, end


def in_immersion(phi_deg, immersion=FULL_SLOT):
    """Whether a flute at angles phi_deg (any shape, deg) cuts: start ≤ φ < end modulo 360."""
    start, end = check_immersion(immersion)
    relative = np.mod(np.asarray(phi_deg, dtype=float) - start + ANGLE_EPS, 360.0) - ANGLE_EPS
    return relative < (end - start) - ANGLE_EPS


def flute_angles(phi_deg, flutes):
    """(Z, p) angle of each flute (deg) when flute 1 is at phi_deg (p,): φ + 360·k/Z."""
    return np.asarray(phi_deg, dtype=float)[None, :] + 360.0 * np.arange(int(flutes))[:, None] / int(flutes)


def flute_lengths(stock, tool, toolpath, settings, *, first=None, lengths_at=None):
    """(Z, m, p) engaged length (mm) of each straight flute at every CL point and angle of settings.phi.

    Flute k is the edge at φ + 360·k/Z, solved by the engine of `stock` (a Staircase or a
    TerracedStock, engine.stocks.engage_stock). first: the (m, p) lengths of
    flute 1 when already computed (an Engagement's length), to save that solve. lengths_at:
    a function of the flute's Settings giving its (m, p) lengths another way (e.g. against
    the in-process stock), instead of the engine's engage on `stock`.
    """
    phi = settings.phi
    lengths = []
    for k, shift in enumerate(360.0 * np.arange(tool.flutes) / tool.flutes):
        if k == 0 and first is not None:
            lengths.append(np.asarray(first, dtype=float))
            continue
        start = settings.phi_start + shift
        shifted = dataclasses.replace(settings, phi_start=start, phi_end=start + settings.phi_step * (phi.size - 1))
        if shifted.phi.size != phi.size:
            raise ValueError(f"flute {k + 1}: {shifted.phi.size} angles instead of {phi.size}")
        lengths.append(engage_stock(stock, tool, toolpath, shifted).length if lengths_at is None else
                       lengths_at(shifted))
    return np.stack(lengths)


@dataclass(frozen=True)
class Forces:
    """Cutting forces over a pass of m CL points × p angles φ (of flute 1), affine in the feed.

    phi: (p,) deg. rotation: (m, 3, 3) R of each CL point. radius: R_t (mm).
    feed: (m,) feed per tooth at each CL point (mm). spindle_rpm: rpm or None.
    cutting: (m, p, 3) tool-frame force per mm of feed per tooth (N/mm), summed over the flutes.
    edge: (m, p, 3) tool-frame edge force (N), independent of the feed.
    cutting_tangential, edge_tangential: (m, p) Σ (ρ/R_t)·dF_t per mm of feed (N/mm) and edge part (N),
    ρ each element's distance from the axis (R_t on a straight side: then ΣdF_t), so that the torque
    is R_t times them.
    area_per_feed: (m, p) total cut area per mm of feed, Σ b_k sin φ_k cos α over the cutting
    flutes (∫ sin φ_k sin κ cos α ds along an edge with a corner) (mm; × f gives mm²).
    """

    phi: np.ndarray
    rotation: np.ndarray
    radius: float
    feed: np.ndarray
    spindle_rpm: Optional[float]
    cutting: np.ndarray
    edge: np.ndarray
    cutting_tangential: np.ndarray
    edge_tangential: np.ndarray
    area_per_feed: np.ndarray

    @property
    def shape(self):
        """(m, p): CL points × rotation angles."""
        return self.edge.shape[:2]

    def with_feed(self, feed):
        """The same pass at feed per tooth `feed` (scalar or (m,), mm)."""
        return dataclasses.replace(self, feed=_feeds(feed, self.shape[0]))

    @property
    def tool_frame(self):
        """(m, p, 3) force on the tool in its own frame (u, v, w) (N)."""
        return self.feed[:, None, None] * self.cutting + self.edge

    @property
    def xyz(self):
        """(m, p, 3) force on the tool in the global frame (N): R·F_tool."""
        return np.einsum("mij,mpj->mpi", self.rotation, self.tool_frame)

    @property
    def cutting_xyz(self):
        """(m, p, 3) global force per mm of feed per tooth (N/mm)."""
        return np.einsum("mij,mpj->mpi", self.rotation, self.cutting)

    @property
    def edge_xyz(self):
        """(m, p, 3) global edge force (N)."""
        return np.einsum("mij,mpj->mpi", self.rotation, self.edge)

    @property
    def torque(self):
        """(m, p) torque about the tool axis, Σ ρ·dF_t (R_t·ΣF_t on straight sides) (N·mm)."""
        return self.radius * (self.feed[:, None] * self.cutting_tangential + self.edge_tangential)

    @property
    def power(self):
        """(m, p) spindle power torque·ω (W), or None without a spindle speed."""
        if self.spindle_rpm is None:
            return None
        return 1e-3 * self.torque * 2.0 * np.pi * self.spindle_rpm / 60.0

    @property
    def area(self):
        """(m, p) total cut area of the cutting flutes (mm²)."""
        return self.feed[:, None] * self.area_per_feed

    @property
    def resultant(self):
        """(m, p) magnitude of the force (N)."""
        return np.linalg.norm(self.tool_frame, axis=-1)

    @property
    def peak(self):
        """(m,) largest resultant over the angles of each CL point (N)."""
        return self.resultant.max(axis=1)

    def _revolution(self):
        """(p,) bool: the angles of the first revolution from phi[0] (a sample 360° on repeats one)."""
        return self.phi < self.phi[0] + 360.0 - ANGLE_EPS

    @property
    def mean(self):
        """(m,) mean resultant over the angles of each CL point, one revolution at most (N)."""
        return self.resultant[:, self._revolution()].mean(axis=1)

    @property
    def mean_xyz(self):
        """(m, 3) mean global force components over the angles, one revolution at most (N)."""
        return self.xyz[:, self._revolution()].mean(axis=1)


def _feeds(feed, m):
    """Feed per tooth (m,) mm from a scalar or (m,) array; ValueError unless finite and ≥ 0."""
    try:
        feed = np.broadcast_to(np.asarray(feed, dtype=float), (m,)).copy()
    except ValueError:
        raise ValueError(f"feed per tooth must be a number or have shape ({m},), got {np.shape(feed)}") from None
    if not np.isfinite(feed).all() or (feed < 0.0).any():
        raise ValueError("feed per tooth must be finite and not negative at every CL point")
    return feed


def edge_forces(lengths, phi_deg, rotation, radius, inclination, feed, coefficients, *, immersion=FULL_SLOT,
                spindle_rpm=None):
    """Forces of straight flutes from their engaged lengths.

    lengths: (Z, m, p) engaged length of flute k (mm) at CL point i when flute 1 is at
    phi_deg[j] (p,) deg. rotation: (m, 3, 3) R of each CL point. radius: R_t (mm).
    inclination: α (deg), scalar or (m,) (each CL point's). feed: feed per tooth, scalar or (m,) (mm).
    coefficients: Coefficients.
    immersion: (start, end) deg. Returns Forces.
    """
    lengths = np.asarray(lengths, dtype=float)
    phi = np.asarray(phi_deg, dtype=float)
    rotation = np.asarray(rotation, dtype=float)
    if lengths.ndim != 3 or lengths.shape[2] != phi.size:
        raise ValueError(f"lengths must have shape (Z, m, {phi.size}), got {lengths.shape}")
    if rotation.shape != (lengths.shape[1], 3, 3):
        raise ValueError(f"rotation must have shape ({lengths.shape[1]}, 3, 3), got {rotation.shape}")
    if not np.isfinite(lengths).all() or (lengths < 0.0).any():
        raise ValueError("lengths must be finite and not negative")
    angles = flute_angles(phi, lengths.shape[0])                     # (Z, p)
    cuts = in_immersion(angles, immersion)
    s, c = np.sin(np.radians(angles)), np.cos(np.radians(angles))
    scale = np.cos(np.radians(np.broadcast_to(np.asarray(inclination, dtype=float), (lengths.shape[1],))))
    thickness = np.where(cuts, s, 0.0)[:, None, :] * scale[None, :, None]  # h / f, (Z, m, p)
    length = np.where(cuts[:, None, :], lengths, 0.0)                 # (Z, m, p)

    def tool_frame(tangential, radial, axial):
        """Σ over the flutes of the tool-frame vector of per-flute (Z, m, p) components -> (m, p, 3)."""
        return np.stack([(-tangential * c[:, None] - radial * s[:, None]).sum(axis=0),
                         (tangential * s[:, None] - radial * c[:, None]).sum(axis=0),
                         axial.sum(axis=0)], axis=-1)

    k = coefficients
    chip = length * thickness                                         # b·h/f (mm)
    return Forces(
        phi=phi, rotation=rotation, radius=float(radius), feed=_feeds(feed, lengths.shape[1]),
        spindle_rpm=None if spindle_rpm is None else float(spindle_rpm),
        cutting=tool_frame(k.ktc * chip, k.krc * chip, k.kac * chip),
        edge=tool_frame(k.kte * length, k.kre * length, k.kae * length),
        cutting_tangential=k.ktc * chip.sum(axis=0), edge_tangential=k.kte * length.sum(axis=0),
        area_per_feed=chip.sum(axis=0),
    )


def interval_integrals(start, end, psi0, kappa):
    """∫ over l in [start, end] of sin ψ, cos ψ, sin² ψ and sin ψ cos ψ, with ψ = psi0 − kappa·l.

    start, end: (...) mm, NaN for no interval (integrals 0); psi0 (rad) broadcast with them;
    kappa: rad/mm. Closed forms about the midpoint ψ_m with Δ = end − start, free of
    cancellation as kappa → 0: ∫ sin = Δ sin ψ_m S₁, ∫ cos = Δ cos ψ_m S₁,
    ∫ sin² = Δ/2 − Δ cos 2ψ_m S₂/2, ∫ sin cos = Δ sin 2ψ_m S₂/2, S₁ = sinc(κΔ/2), S₂ = sinc(κΔ)
    (sinc x = sin x / x). Returns (width Δ, ∫ sin, ∫ cos, ∫ sin², ∫ sin cos), each (...) mm.
    """
    start, end = np.broadcast_arrays(np.asarray(start, dtype=float), np.asarray(end, dtype=float))
    width = np.where(np.isnan(start) | np.isnan(end), 0.0, end - start)
    mid = np.asarray(psi0, dtype=float) - kappa * np.where(width > 0.0, 0.5 * (start + end), 0.0)
    s1 = np.sinc(kappa * width / (2.0 * np.pi))   # numpy's sinc is sin(πx)/(πx)
    s2 = np.sinc(kappa * width / np.pi)
    return (width, width * np.sin(mid) * s1, width * np.cos(mid) * s1,
            0.5 * width * (1.0 - np.cos(2.0 * mid) * s2), 0.5 * width * np.sin(2.0 * mid) * s2)


def helical_forces(flutes, rotation, coefficients, *, feed=None, spindle_rpm=None):
    """Forces of helical flutes from their engaged intervals.

    flutes: a FluteEngagement (helix.flute_engagement) whose intervals were cut to the
    immersion, so that sin ψ ≥ 0 on them. rotation: (m, 3, 3) R of each CL point. feed: feed
    per tooth, scalar or (m,) mm (default the engagement's). Returns Forces.
    """
    rotation = np.asarray(rotation, dtype=float)
    m = flutes.shape[0]
    if rotation.shape != (m, 3, 3):
        raise ValueError(f"rotation must have shape ({m}, 3, 3), got {rotation.shape}")
    kappa = np.tan(np.radians(flutes.helix)) / flutes.radius
    psi0 = np.radians(flute_angles(flutes.phi, flutes.flutes).T)[None, :, :, None]   # (1, p, Z, 1)
    width, i_s, i_c, i_ss, i_sc = (v.sum(axis=-1) for v in interval_integrals(flutes.start, flutes.end, psi0, kappa))
    k, scale = coefficients, np.cos(np.radians(np.broadcast_to(flutes.inclination, (m,))))[:, None]

    def summed(*components):
        """(m, p, 3) tool-frame vector of per-flute (m, p, Z) components, summed over the flutes."""
        return np.stack([c.sum(axis=-1) for c in components], axis=-1)

    return Forces(
        phi=np.asarray(flutes.phi, dtype=float), rotation=rotation, radius=float(flutes.radius),
        feed=_feeds(flutes.feed_per_tooth if feed is None else feed, m),
        spindle_rpm=None if spindle_rpm is None else float(spindle_rpm),
        cutting=scale[..., None] * summed(-k.ktc * i_sc - k.krc * i_ss, k.ktc * i_ss - k.krc * i_sc, k.kac * i_s),
        edge=summed(-k.kte * i_c - k.kre * i_s, k.kte * i_s - k.kre * i_c, k.kae * width),
        cutting_tangential=scale * k.ktc * i_s.sum(axis=-1), edge_tangential=k.kte * width.sum(axis=-1),
        area_per_feed=scale * i_s.sum(axis=-1),
    )


def joined_forces(parts):
    """The Forces of a pass from the Forces of its chunks of CL points, in pass order: the
    per-CL-point arrays joined, φ, the radius and the spindle speed taken from the first."""
    first = parts[0]
    per_cl = {f.name: np.concatenate([getattr(part, f.name) for part in parts])
              for f in dataclasses.fields(Forces) if f.name not in ("phi", "radius", "spindle_rpm")}
    return dataclasses.replace(first, **per_cl)


def corner_integrals(start, end, corner_radius):
    """∫ over s in [start, end] on the corner arc of 1, sin κ, cos κ, sin² κ and sin κ cos κ, κ = s/r.

    start, end: (...) arc lengths (mm), NaN for none (integrals 0); corner_radius r > 0 (mm).
    interval_integrals with ψ = 0 − (−1/r)·s. Returns five (...) arrays (mm).
    """
    return interval_integrals(start, end, 0.0, -1.0 / corner_radius)


def edge_integrals(start, end, radius, corner_radius, psi_max):
    """Integrals along runs [start, end] (K,) of the peripheral edge (arc length s, mm; engine.profile).

    κ = s/r on the corner (0 ≤ s ≤ r·ψ_max), 90° on the straight side beyond; ρ = R − r + r sin κ the
    distance from the axis (R on the side). Returns seven (K,) arrays (mm, ρ-weighted ones mm²):
    ∫ ds, ∫ sin κ ds, ∫ cos κ ds, ∫ sin² κ ds, ∫ sin κ cos κ ds, ∫ ρ ds, ∫ ρ sin κ ds.
    """
    start, end = np.asarray(start, dtype=float), np.asarray(end, dtype=float)
    top = corner_radius * psi_max
    side = np.maximum(end - np.maximum(start, top), 0.0)
    if corner_radius <= 0.0:
        zero = np.zeros_like(side)
        return side, side, zero, side, zero, radius * side, radius * side
    corner_end = np.minimum(end, top)
    on_corner = corner_end > start
    width, i_s, i_c, i_ss, i_sc = corner_integrals(np.where(on_corner, start, np.nan),
                                                   np.where(on_corner, corner_end, np.nan), corner_radius)
    inner = radius - corner_radius
    return (width + side, i_s + side, i_c, i_ss + side, i_sc,
            inner * width + corner_radius * i_s + radius * side, inner * i_s + corner_radius * i_ss + radius * side)


def _runs_of(found, n_rows, name):
    """`found` checked to be EdgeIntervals of n_rows rows; ValueError naming `name` otherwise."""
    if not isinstance(found, EdgeIntervals):
        raise ValueError(f"{name} must be EdgeIntervals (engine.intervals), got {type(found).__name__}")
    if found.n_rows != n_rows:
        raise ValueError(f"{name} must have {n_rows} rows (CL points × angles), got {found.n_rows}")
    return found


def profile_forces(runs, phi_deg, rotation, tool, inclination, feed, coefficients, *, immersion=FULL_SLOT,
                   spindle_rpm=None):
    """Forces of straight flutes along their whole peripheral edge (corner arc and side) from their engaged runs.

    runs: Z EdgeIntervals, flute k's (k = 0..Z−1) of m·p rows (row i·p + j: CL point i, flute 1 at
    phi_deg[j], flute k at phi_deg[j] + 360·k/Z), in arc length s along the edge (mm; engine.profile).
    phi_deg: (p,) deg. rotation: (m, 3, 3) R of each CL point. tool: Tool (radius, corner radius,
    flute length; any corner radius, 0 included). inclination: α (deg), scalar or (m,). feed: feed
    per tooth, scalar or (m,) (mm). immersion: (start, end) deg. Returns Forces.

    Per flute, with κ the element's angle (s/r on the corner, 90° on the side), e = ∂d/∂φ, n = sin κ·d −
    cos κ·w, a = cos κ·d + sin κ·w and c = f sin φ_k cos α (docs/FORCES.md):

        F = −(K_tc c ∫sin κ + K_te ∫1)·e
            + (−K_rc c ∫sin² κ + K_ac c ∫sin κ cos κ − K_re ∫sin κ + K_ae ∫cos κ)·d
            + (K_rc c ∫sin κ cos κ + K_ac c ∫sin² κ + K_re ∫cos κ + K_ae ∫sin κ)·w

    (∫ over the engaged runs in ds, edge_integrals), with e = cos φ·u − sin φ·v and d = sin φ·u + cos φ·v.
    """
    phi = np.asarray(phi_deg, dtype=float).reshape(-1)
    rotation = np.asarray(rotation, dtype=float)
    if rotation.ndim != 3 or rotation.shape[1:] != (3, 3):
        raise ValueError(f"rotation must have shape (m, 3, 3), got {rotation.shape}")
    m, p, flutes = rotation.shape[0], phi.size, int(tool.flutes)
    runs = list(runs)
    if len(runs) != flutes:
        raise ValueError(f"runs must hold one EdgeIntervals per flute ({flutes}), got {len(runs)}")
    psi_max = corner_top(tool)
    sums = np.zeros((7, flutes, m * p))
    for k, found in enumerate(runs):
        found = _runs_of(found, m * p, f"runs of flute {k + 1}")
        for j, values in enumerate(edge_integrals(found.start, found.end, tool.radius, tool.corner_radius, psi_max)):
            sums[j, k] = np.bincount(found.rows, weights=values, minlength=m * p)
    if not np.isfinite(sums).all():
        raise ValueError("runs must be finite")
    angles = flute_angles(phi, flutes)                                        # (Z, p)
    cuts = in_immersion(angles, immersion)[:, None, :]                        # (Z, 1, p)
    length, i_s, i_c, i_ss, i_sc, rho, rho_s = np.where(cuts, sums.reshape(7, flutes, m, p), 0.0)
    s, c = np.sin(np.radians(angles))[:, None, :], np.cos(np.radians(angles))[:, None, :]
    scale = np.cos(np.radians(np.broadcast_to(np.asarray(inclination, dtype=float), (m,))))
    chip = np.where(cuts, s, 0.0) * scale[None, :, None]                      # h / (f sin κ), (Z, m, p)

    def tool_frame(tangential, across, axial):
        """Σ over the flutes of −tangential·e + across·d + axial·w, each (Z, m, p) -> (m, p, 3)."""
        return np.stack([(-tangential * c + across * s).sum(axis=0), (tangential * s + across * c).sum(axis=0),
                         axial.sum(axis=0)], axis=-1)

    k = coefficients
    return Forces(
        phi=phi, rotation=rotation, radius=float(tool.radius), feed=_feeds(feed, m),
        spindle_rpm=None if spindle_rpm is None else float(spindle_rpm),
        cutting=tool_frame(k.ktc * chip * i_s, chip * (k.kac * i_sc - k.krc * i_ss),
                           chip * (k.krc * i_sc + k.kac * i_ss)),
        edge=tool_frame(k.kte * length, k.kae * i_c - k.kre * i_s, k.kre * i_c + k.kae * i_s),
        cutting_tangential=k.ktc * (chip * rho_s).sum(axis=0) / tool.radius,
        edge_tangential=k.kte * rho.sum(axis=0) / tool.radius,
        area_per_feed=(chip * i_s).sum(axis=0),
    )


def flute_runs(stock, tool, toolpath, phi_deg, *, runs_at=None, chunk_instants=CHUNK_INSTANTS):
    """Z EdgeIntervals: flute k's engaged runs along its peripheral edge (arc length s, mm) at every CL point
    and angle φ + 360·k/Z, φ in phi_deg (p,), rows i·p + j.

    Solved by profile.profile_intervals against `stock` (a Staircase or a TerracedStock, as given), about
    `chunk_instants` instants at a time; or, with runs_at, taken from runs_at(angles (p,) deg), which must give
    the EdgeIntervals of the len(toolpath)·p edges at those angles (e.g. against the in-process stock).
    """
    phi = np.asarray(phi_deg, dtype=float).reshape(-1)
    m, p = len(toolpath), phi.size
    shifts = 360.0 * np.arange(tool.flutes) / tool.flutes
    if runs_at is not None:
        return [_runs_of(runs_at(phi + shift), m * p, f"runs_at for flute {k + 1}") for k, shift in enumerate(shifts)]
    terraced = as_terraced(stock, tool.corner_radius) if tool.corner_radius > 0.0 else None
    step = max(1, int(chunk_instants) // max(p, 1))
    out = []
    for shift in shifts:
        parts = [(start, profile_intervals(stock, tool, toolpath.rows(slice(start, min(m, start + step))), phi + shift,
                                           terraced)) for start in range(0, m, step)]
        out.append(parts[0][1] if len(parts) == 1 else _stacked_runs(parts, m * p, p))
    return out


def _stacked_runs(parts, n_rows, p):
    """One EdgeIntervals of n_rows rows from [(first CL point, EdgeIntervals of its chunk)] in order."""
    fields = ("start", "end", "start_surface", "start_section", "start_wall", "end_surface", "end_section", "end_wall")
    rows = np.concatenate([part.rows + first * p for first, part in parts])
    return EdgeIntervals(n_rows, rows, *(np.concatenate([getattr(part, name) for _, part in parts]) for name in fields))


def pass_forces(stock, tool, toolpath, settings, coefficients, *, immersion=FULL_SLOT, feed=None, first=None,
                lengths_at=None, runs_at=None):
    """Forces of a pass: straight flat-end flutes through the engine's engage per flute (edge_forces),
    helical ones (tool.helix ≠ 0) through helix.flute_engagement (helical_forces), tools with a corner
    radius through their flutes' runs along the whole peripheral edge (flute_runs, profile_forces).

    feed: feed per tooth, scalar or (m,) mm (default settings.feed_per_tooth). first: flute 1's
    (m, p) lengths when already computed (flat-end straight flutes; a tool with a corner needs the runs,
    not the lengths, and solves flute 1 again). lengths_at: how a flat-end tool's flutes' lengths are
    found (flute_lengths). runs_at: a function of the angles (p,) deg giving the EdgeIntervals of the
    m·p edges at them (flute_runs), for any straight-fluted tool; a flat-end tool takes their lengths.
    Returns Forces.
    """
    check_arguments(stock=stock, tool=tool, toolpath=toolpath, settings=settings)
    if not isinstance(coefficients, Coefficients):
        raise WrongArgument(f"coefficients must be Coefficients (forces.material(name), or your own), got "
                            f"{type(coefficients).__name__}")
    if tool.helix != 0.0 and (lengths_at is not None or runs_at is not None):
        raise ValueError("lengths_at and runs_at are for straight flutes only")
    if lengths_at is not None and runs_at is not None:
        raise ValueError("give lengths_at or runs_at, not both")
    if tool.corner_radius > 0.0 and lengths_at is not None:
        raise ValueError("the forces of a ball mill need each flute's engaged runs along its corner, not only its "
                         "lengths of cut: lengths_at (such as the in-process stock's) cannot give them; pass runs_at "
                         "instead" if tool.kind == "ball" else
                         "the forces of a bull-nose mill need each flute's engaged runs along its corner, not only "
                         "its lengths of cut: lengths_at (such as the in-process stock's) cannot give them; pass "
                         "runs_at instead")
    immersion = check_immersion(immersion)
    rotation = toolpath.frames()
    feed = settings.feed_per_tooth if feed is None else feed
    if tool.helix != 0.0:
        engaged = flute_engagement(stock, tool, toolpath, settings, immersion=immersion)
        return helical_forces(engaged, rotation, coefficients, feed=feed, spindle_rpm=settings.spindle_rpm)
    if tool.corner_radius > 0.0:
        runs = flute_runs(stock, tool, toolpath, settings.phi, runs_at=runs_at)
        return profile_forces(runs, settings.phi, rotation, tool, toolpath.inclinations(settings), feed, coefficients,
                              immersion=immersion, spindle_rpm=settings.spindle_rpm)
    if runs_at is not None:
        m, p = len(toolpath), settings.phi.size

        def lengths_at(shifted):
            return _runs_of(runs_at(shifted.phi), m * p, "runs_at").length.reshape(m, p)
    lengths = flute_lengths(stock, tool, toolpath, settings, first=first, lengths_at=lengths_at)
    return edge_forces(lengths, settings.phi, rotation, tool.radius, toolpath.inclinations(settings), feed,
                       coefficients, immersion=immersion, spindle_rpm=settings.spindle_rpm)
