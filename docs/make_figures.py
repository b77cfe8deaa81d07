"""The docs' drawn figures (docs/images/*.png), made from the engine's own frames: ``make figures``.

- frames_feed.png: φ measured from the feed. A curving path in plan view; at several CL points the
  tool's frame Rz(α)·Rx(θ_A)·Ry(θ_B) as the engine computes it (Toolpath.frames), u along the feed,
  v to its left, φ = 0 at +v and 90° along the feed, the leading half (0..180°) shaded; beside it
  the inclination: the tool axis leaning towards the feed in the plane of the feed and the axis.
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


def main(folder):
    os.makedirs(folder, exist_ok=True)
    frames_feed(os.path.join(folder, "frames_feed.png"))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "images"))
