"""The docs' drawn figures (docs/images/*.png), made from the engine's own frames: ``make figures``.

- frames_feed.png: φ measured from the feed. A curving path in plan view; at several CL points the
  tool's frame Rz(α)·Rx(θ_A)·Ry(θ_B) as the engine computes it (Toolpath.frames), u along the feed,
  v to its left, φ = 0 at +v and 90° along the feed, the leading half (0..180°) shaded; beside it
  the inclination: the tool axis leaning towards the feed in the plane of the feed and the axis.
- tool_profile.png: the cutting edges of a bull-nose mill in the plane of d and w, drawn from the
  engine's own profile (engine.profile.point_at): the corner's arc about C, ψ and κ, the straight
  side, the end edge, and a floor and a wall cutting it, with the engaged part, lep_l and uep_l;
  beside it the profiles of a flat-end, a bull-nose and a ball-end mill of one diameter.
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Wedge  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

from abm_workbench.engine import Toolpath  # noqa: E402
from abm_workbench.engine.feed import feed_frame, path_directions  # noqa: E402
from abm_workbench.engine.profile import height_at, point_at  # noqa: E402

RADIUS = 6.0


def frames_feed(path):
    """docs/images/frames_feed.png (see the module docstring)."""
    t = np.linspace(0.0, 1.0, 400)
    points = np.column_stack([60 * t, 25 * np.sin(2.6 * t) - 8 * t, np.zeros_like(t)])
    alpha, _ = feed_frame(path_directions(points))
    toolpath = Toolpath.from_axes(points, np.tile([0.0, 0.0, 1.0], (len(t), 1)), alpha=alpha)
    frames = toolpath.frames()
    figure, (plan, side) = plt.subplots(1, 2, figsize=(13, 5.4), gridspec_kw={"width_ratios": [1.7, 1]})
    plan.plot(points[:, 0], points[:, 1], color="0.4", lw=1.2, label="path of the tool tip (CL points)")
    for i in (40, 150, 260, 370):
        centre, u, v = points[i, :2], frames[i, :2, 0], frames[i, :2, 1]
        start = np.degrees(np.arctan2(-v[1], -v[0]))  # the leading half runs from +v through u to -v
        plan.add_patch(Wedge(centre, RADIUS, start, start + 180.0, color="tab:orange", alpha=0.35, lw=0))
        plan.add_patch(plt.Circle(centre, RADIUS, fill=False, color="0.2", lw=1))
        plan.arrow(*centre, *(1.6 * RADIUS * u), width=0.25, color="tab:blue", length_includes_head=True)
        plan.arrow(*centre, *(1.2 * RADIUS * v), width=0.25, color="tab:green", length_includes_head=True)
        plan.annotate("φ = 0", centre + 1.35 * RADIUS * v, color="tab:green", ha="center", va="center")
        plan.annotate(f"u: feed, α = {alpha[i]:.0f}°", centre + 1.9 * RADIUS * u, color="tab:blue", ha="center")
    plan.set(aspect="equal", xlabel="x (mm)", ylabel="y (mm)",
             title="Plan view: each CL point's frame turned to its feed (α)")
    plan.plot([], [], color="tab:orange", alpha=0.4, lw=8, label="leading half, φ = 0…180°")
    plan.legend(loc="lower left", fontsize=8)
    # Side view in the plane of the feed and the axis: the lead (inclination) thins the chip.
    lead = np.radians(15.0)
    axis = np.array([np.sin(lead), np.cos(lead)])
    side.plot([0, 26 * axis[0]], [0, 26 * axis[1]], color="0.2", lw=2, label="tool axis w")
    side.arrow(0, 0, 16, 0, width=0.35, color="tab:blue", length_includes_head=True)
    side.annotate("feed f (along u)", (8, -2.2), color="tab:blue", ha="center")
    across = np.array([np.cos(lead), -np.sin(lead)])
    side.arrow(0, 0, *(16 * np.cos(lead) * across), width=0.25, color="tab:red", length_includes_head=True)
    side.annotate("f·cos(inclination):\nthe feed across the axis", 16 * np.cos(lead) * across + [1, -3.5],
                  color="tab:red", fontsize=8)
    arc = np.linspace(np.pi / 2 - lead, np.pi / 2, 20)
    side.plot(9 * np.cos(arc), 9 * np.sin(arc), color="0.3", lw=1)
    side.annotate("inclination\nasin |f̂·w|", (2.4, 10), fontsize=8)
    side.set(aspect="equal", xlim=(-4, 22), ylim=(-8, 27), xlabel="along the feed (mm)", ylabel="up (mm)",
             title="In the feed's plane: the inclination")
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)


def _profile(radius, corner, length, count=200):
    """(d, w) coordinates (count, 2) of the peripheral edge of a tool, from the engine's point_at."""
    psi_max = 0.5 * np.pi if length >= corner else np.arccos(1.0 - length / corner)
    span = corner * psi_max + max(length - corner, 0.0)
    s = np.linspace(0.0, span, count)
    points = point_at(s, np.zeros(3), np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0]), radius, corner, psi_max)
    return points[:, [0, 2]], s, psi_max


def tool_profile(path):
    """docs/images/tool_profile.png (see the module docstring)."""
    radius, corner, length = 8.0, 3.0, 14.0
    edge, s, psi_max = _profile(radius, corner, length)
    figure, (one, kinds) = plt.subplots(1, 2, figsize=(13, 6), gridspec_kw={"width_ratios": [1.4, 1]})
    floor, wall = 1.2, 9.5  # a floor at height 1.2 and the material below height 9.5 beyond d = 6.5
    one.fill_between([6.5, 12.5], floor, wall, color="0.85", label="material (a slab of the stock)")
    one.plot(edge[:, 0], edge[:, 1], color="0.2", lw=2, label="peripheral edge: corner arc, then side")
    one.plot([0, radius - corner], [0, 0], color="tab:purple", lw=3, label="end edge, T to T + (R − r)·d")
    inside = (edge[:, 0] >= 6.5) & (edge[:, 1] >= floor) & (edge[:, 1] <= wall)
    one.plot(edge[inside, 0], edge[inside, 1], color="tab:orange", lw=5, alpha=0.8, label="engaged: length = its s")
    centre = np.array([radius - corner, corner])
    one.plot(*centre, "k+", ms=10)
    one.annotate("C = T + (R − r)·d + r·w", centre + [-4.8, 0.4], fontsize=9)
    psi = np.radians(50.0)
    point = centre + corner * np.array([np.sin(psi), -np.cos(psi)])
    one.plot(*zip(centre, point), color="0.4", lw=1, ls="--")
    one.annotate("ψ", centre + [0.35, -1.2], fontsize=11)
    normal = np.array([np.sin(psi), -np.cos(psi)])
    one.arrow(*point, *(2.2 * normal), width=0.06, color="tab:red", length_includes_head=True)
    one.annotate("normal: κ = ψ\nfrom the axis", point + 2.3 * normal + [0.2, -0.6], color="tab:red", fontsize=9)
    lep, uep = height_at(s[inside][[0, -1]], corner, psi_max)
    for level, name in ((lep, "lep_l"), (uep, "uep_l")):
        one.plot([-1.2, 0], [level, level], color="tab:green", lw=1)
        one.annotate(f"{name} = {level:.2f} mm", (-5.2, level - 0.15), color="tab:green", fontsize=9)
    one.plot([0, 0], [0, length + 1], color="0.5", lw=1, ls=":")
    one.annotate("w (axis)", (0.2, length + 0.6), fontsize=9)
    one.annotate("T (CL point)", (0.2, -0.9), fontsize=9)
    one.annotate("d →", (11.6, 0.2), fontsize=9)
    one.set(aspect="equal", xlim=(-5.5, 13), ylim=(-1.5, length + 1.5), xlabel="along d (mm)",
            ylabel="along w, height above the tip (mm)", title="A bull-nose mill D16 R3 in the plane of d and w")
    one.legend(loc="upper left", bbox_to_anchor=(0.0, 0.9), fontsize=8)
    for corner_radius, name, colour in ((0.0, "flat-end, r = 0", "tab:blue"), (3.0, "bull-nose, r = 3", "0.2"),
                                        (8.0, "ball-end, r = R = 8", "tab:red")):
        edge, _, _ = _profile(radius, corner_radius, length)
        both = np.concatenate([edge[::-1] * [-1, 1], edge])
        kinds.plot(both[:, 0], both[:, 1], color=colour, lw=2, label=name)
    kinds.set(aspect="equal", xlabel="across the axis (mm)", ylabel="height above the tip (mm)",
              title="D16 tools: r from 0 to R")
    kinds.legend(loc="upper center", fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)


def main(folder):
    os.makedirs(folder, exist_ok=True)
    frames_feed(os.path.join(folder, "frames_feed.png"))
    tool_profile(os.path.join(folder, "tool_profile.png"))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "images"))
