"""A real CAM roughing program, in-process stock against the stock as given, side by side.

Run from the repository root: `/usr/bin/python3 benchmarks/cam_roughing.py DIR [--runs N]`.

FreeCAD's own CAM (the Path workbench, run by `freecadcmd`) builds the Job into DIR/roughing.FCStd: an
80 × 60 × 20 mm block with a 50 × 36 × 10 mm pocket (its floor at z = 11), FreeCAD's default stock (1 mm
around the part); the pocket cleared by an Adaptive operation (5 mm end mill, 3 flutes, step down 2 mm,
step over 20 %) and then by a Pocket operation (another 5 mm end mill, step down 2.5 mm). The Adaptive
alone is some 15,600 CL points in five levels with helix entries, moves of 0.1 to 1 mm along curves.
Then `engage --operation 1` runs on it N times with each stock model in turn (`--workers 1`, φ 0 … 180°
by 1°): the wall time and CPU time (user + system) of the whole command, the engine's own time as the
command reports it ("instants in … ms", files included), and the command's peak resident memory (its
rusage). The last line gives the in-process ÷ initial ratios of the medians.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PYTHON = "/usr/bin/python3"

BUILD = r'''
import os
import FreeCAD
import PathScripts.PathAdaptive as PathAdaptive
import PathScripts.PathJob as PathJob
import PathScripts.PathPocketShape as PathPocketShape
import PathScripts.PathToolBit as PathToolBit
import PathScripts.PathToolController as PathToolController

bits = os.path.join(FreeCAD.getHomePath(), "Mod", "Path", "Tools", "Bit")
doc = FreeCAD.newDocument("Roughing")
block = doc.addObject("Part::Box", "Block")
block.Length, block.Width, block.Height = 80, 60, 20
pocket = doc.addObject("Part::Box", "PocketVolume")
pocket.Length, pocket.Width, pocket.Height = 50, 36, 10
pocket.Placement.Base = FreeCAD.Vector(15, 12, 11)
part = doc.addObject("Part::Cut", "Part")
part.Base, part.Tool = block, pocket
doc.recompute()
job = PathJob.Create("Job", [part], None)
doc.recompute()
adaptive = PathAdaptive.Create("Adaptive")
pocketing = PathPocketShape.Create("Pocket")
default = job.Tools.Group[0]
controllers = []
for number in (1, 2):
    bit = PathToolBit.Factory.CreateFrom(os.path.join(bits, "5mm_Endmill.fctb"))
    bit.Flutes = 3
    controller = PathToolController.Create(f"TC: 5mm_Endmill {number}", bit, number)
    controller.SpindleSpeed = 9000
    controller.HorizFeed = "800 mm/min"
    controller.VertFeed = "200 mm/min"
    job.Proxy.addToolController(controller)
    controllers.append(controller)
job.Tools.Group = controllers
doc.removeObject(default.Tool.Name)
doc.removeObject(default.Name)
model = job.Model.Group[0]
floor = next(f"Face{i}" for i, face in enumerate(model.Shape.Faces, start=1)
             if face.Surface.__class__.__name__ == "Plane" and abs(face.BoundBox.ZMax - 11.0) < 1e-6)
adaptive.ToolController, adaptive.Base = controllers[0], [(model, [floor])]
pocketing.ToolController, pocketing.Base = controllers[1], [(model, [floor])]
for op, step in ((adaptive, 2.0), (pocketing, 2.5)):
    op.setExpression("StepDown", None)
    op.StepDown = step
adaptive.StepOver = 20
doc.recompute()
doc.saveAs(os.environ["ABM_ROUGHING_OUT"])
'''


def build(path):
    """Build the Job with freecadcmd into `path` (skipped when it exists)."""
    if os.path.exists(path):
        return
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as script:
        script.write(BUILD)
    try:
        subprocess.run(["freecadcmd", script.name], check=True, env=dict(os.environ, ABM_ROUGHING_OUT=path),
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=900)
    finally:
        os.unlink(script.name)
    if not os.path.exists(path):
        raise SystemExit(f"freecadcmd did not write {path}")


def run(job, model, out):
    """One `engage` run: (wall s, CPU s, engine s, peak MB), its own rusage (os.wait4)."""
    command = [PYTHON, "-m", "abm_workbench", "engage", "--toolpath", job, "--operation", "1", "--flutes", "3",
               "--feed-per-tooth", "0.05", "--stock-model", model, "--workers", "1", "--out", out]
    with tempfile.TemporaryFile("w+") as log:
        start = time.perf_counter()
        child = subprocess.Popen(command, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - start
        child.returncode = os.waitstatus_to_exitcode(status)
        log.seek(0)
        text = log.read()
    if child.returncode != 0:
        raise SystemExit(f"engage --stock-model {model} failed:\n{text}")
    engine = re.search(r"instants in (\d+) ms", text)
    return wall, usage.ru_utime + usage.ru_stime, int(engine.group(1)) / 1000.0, usage.ru_maxrss / 1024.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    os.makedirs(args.folder, exist_ok=True)
    job = os.path.abspath(os.path.join(args.folder, "roughing.FCStd"))
    build(job)
    figures = {"initial": [], "in-process": []}
    print("| run | stock model | wall s | CPU s | engine s | peak MB |")
    print("|---|---|---|---|---|---|")
    for k in range(args.runs):
        for model in figures:
            row = run(job, model, os.path.join(args.folder, f"{model}.npz"))
            figures[model].append(row)
            print(f"| {k + 1} | {model} | {row[0]:.2f} | {row[1]:.2f} | {row[2]:.2f} | {row[3]:.0f} |", flush=True)
    median = {model: [statistics.median(column) for column in zip(*rows)] for model, rows in figures.items()}
    ratio = [a / b for a, b in zip(median["in-process"][:3], median["initial"][:3])]
    print(f"\nmedians, in-process ÷ initial: wall {ratio[0]:.2f}, CPU {ratio[1]:.2f}, engine {ratio[2]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
