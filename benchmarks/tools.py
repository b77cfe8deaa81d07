"""Cost of bull-nose and ball-end mills against the flat-end mill of the same CL points, per instant, in one run.

Run from the repository root (a minute or two):

    /usr/bin/python3 benchmarks/tools.py [--repeats 3]

Cases (engine time only, engine.stocks.engage_stock, which also gives every tool's end edge):

- "terraced part, five-axis": benchmarks/terraced.py's seven-level part (pocket, boss, ring terrace,
  ridge, B-spline island) and a pass of 400 CL points across it whose axis leans 10-25° and turns
  about z as it goes, the frames turned to the feed (a curving path in plan view);
- "model test 1 (staircase)": the bundled staircase with curved walls and its five-axis pass,
  resampled to 200 CL points;
- "model test 4 (terraced)": the bundled terraced stock and its pass.

For each, a D12 tool of corner radius r = 0 (flat-end), 0.1·R, 0.3·R, 0.5·R and R (ball), the tools
timed in turn within each repeat (a change in the machine's load falls on all of them); the best
time of each and its ratio to the flat-end mill's, measured in the same run, are printed as a
Markdown table.
"""

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core, before numpy is imported

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from abm_workbench.engine import CutSettings, Tool, Toolpath  # noqa: E402
from abm_workbench.engine.feed import feed_frame, path_directions  # noqa: E402
from abm_workbench.engine.stocks import engage_stock  # noqa: E402
from abm_workbench.formats.staircase_json import load_staircase  # noqa: E402
from abm_workbench.formats.terraced_json import load_terraced  # noqa: E402
from engine_throughput import densified, load_model  # noqa: E402
from terraced import model, terraced_part  # noqa: E402

MODELS = os.path.join(ROOT, "resources", "models")
RATIOS = (0.0, 0.1, 0.3, 0.5, 1.0)


def five_axis_pass(count=400):
    """A curving pass across the terraced part: tilt 10-25°, leaning sideways and back, frames to the feed."""
    t = np.linspace(0.0, 1.0, count)
    cl = np.column_stack([5.0 + 110.0 * t, 18.0 * np.sin(2.0 * np.pi * t), 8.0 + 6.0 * np.sin(3.0 * t) ** 2])
    tilt = np.radians(10.0 + 15.0 * t)
    turn = 2.0 * np.pi * 1.5 * t
    axes = np.column_stack([np.sin(tilt) * np.cos(turn), np.sin(tilt) * np.sin(turn), np.cos(tilt)])
    alpha, _ = feed_frame(path_directions(cl))
    return Toolpath.from_axes(cl, axes, alpha=alpha), CutSettings(0.1, 10.0, 0.0, 180.0, 1.0)


def cases():
    """[(name, stock, toolpath, settings)]."""
    stock, _, toolpath, settings = load_model(os.path.join(MODELS, "model_test_1"))
    four_path, _, four_settings = model(4)
    return [("terraced part, five-axis", terraced_part(), *five_axis_pass()),
            ("model test 1 (staircase)", load_staircase(os.path.join(MODELS, "model_test_1", "stock.json")),
             densified(toolpath, 200), settings),
            ("model test 4 (terraced)", load_terraced(os.path.join(MODELS, "model_test_4", "stock.json")), four_path,
             four_settings)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    print("| case | tool | instants | best (s) | µs per instant | ÷ flat-end |")
    print("|---|---|---:|---:|---:|---:|")
    for name, stock, toolpath, settings in cases():
        tools = [Tool(12.0, 2, 30.0, corner_radius=6.0 * ratio) for ratio in RATIOS]
        for tool in tools:  # warm-up
            engage_stock(stock, tool, toolpath, settings)
        best = {tool: np.inf for tool in tools}
        for _ in range(args.repeats):
            for tool in tools:
                start = time.perf_counter()
                engage_stock(stock, tool, toolpath, settings)
                best[tool] = min(best[tool], time.perf_counter() - start)
        instants = len(toolpath) * settings.phi.size
        flat = best[tools[0]]
        for tool in tools:
            words = "flat-end" if tool.corner_radius == 0.0 else f"{tool.kind} r = {tool.corner_radius:g} mm"
            print(f"| {name} | D12 {words} | {instants} | {best[tool]:.3f} | {best[tool] / instants * 1e6:.2f} | "
                  f"{best[tool] / flat:.2f} |")


if __name__ == "__main__":
    main()
