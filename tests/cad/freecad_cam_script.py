"""A FreeCAD CAM Job built and posted by FreeCAD itself, run by ``freecadcmd`` (its CAM needs FreeCAD's own
home folder to find toolbit shapes and posts, which a plain interpreter does not have).

    ABM_CAM_SCRIPT='["build", FOLDER]' freecadcmd freecad_cam_script.py     # job.FCStd, job.ngc, tools.tbl
    ABM_CAM_SCRIPT='["post", DOC, OUT]' freecadcmd freecad_cam_script.py    # the Job of DOC posted to OUT

The part: a 40 × 30 × 10 mm block with a 16 × 12 × 5 mm pocket and a 5 mm hole through it. The Job
(FreeCAD's default stock, 1 mm around the part): a profile around the part with a 5 mm end mill (T1),
the pocket with a 6 mm bull-nose (T2), an adaptive clearing of the pocket with a 6 mm ball end
mill (T3), the hole drilled (G81) with a 5 mm drill (T4). Posted as FreeCAD's Post command posts a
Job: each fixture, then the operations in order, each after its tool controller where that changes.
freecadcmd runs this file with ``__name__`` other than ``"__main__"``, so the work is done at the
top level; its arguments come in the environment, as freecadcmd opens its own arguments as files.
"""

import json
import os

import FreeCAD
import Path

MOD = os.path.join(FreeCAD.getHomePath(), "Mod", "Path")
#: (toolbit file, tool number, flutes, spindle rpm, horizontal feed mm/min) of each tool controller.
TOOLS = (("5mm_Endmill", 1, 2, 8000, 600), ("6mm_Bullnose", 2, 4, 9000, 700), ("6mm_Ball_End", 3, 2, 10000, 500),
         ("5mm_Drill", 4, 2, 3000, 150))


def build(folder):
    """Build the Job (module docstring) and save it, its post and a LinuxCNC tool table into `folder`."""
    import PathScripts.PathAdaptive as PathAdaptive
    import PathScripts.PathDrilling as PathDrilling
    import PathScripts.PathJob as PathJob
    import PathScripts.PathPocketShape as PathPocketShape
    import PathScripts.PathProfile as PathProfile
    import PathScripts.PathToolBit as PathToolBit
    import PathScripts.PathToolController as PathToolController

    doc = FreeCAD.newDocument("CamJob")
    block = doc.addObject("Part::Box", "Block")
    block.Length, block.Width, block.Height = 40, 30, 10
    pocket = doc.addObject("Part::Box", "PocketVolume")
    pocket.Length, pocket.Width, pocket.Height = 16, 12, 6
    pocket.Placement.Base = FreeCAD.Vector(12, 9, 5)
    hole = doc.addObject("Part::Cylinder", "HoleVolume")
    hole.Radius, hole.Height = 2.5, 12
    hole.Placement.Base = FreeCAD.Vector(6, 6, -1)
    cut = doc.addObject("Part::Cut", "PocketCut")
    cut.Base, cut.Tool = block, pocket
    part = doc.addObject("Part::Cut", "Part")
    part.Base, part.Tool = cut, hole
    doc.recompute()
    job = PathJob.Create("Job", [part], None)
    doc.recompute()
    # The operations find the one tool controller there is (several would ask the user which).
    profile = PathProfile.Create("Profile")
    pocketing = PathPocketShape.Create("Pocket")
    adaptive = PathAdaptive.Create("Adaptive")
    drilling = PathDrilling.Create("Drilling")
    default = job.Tools.Group[0]
    controllers = []
    for name, number, flutes, rpm, feed in TOOLS:
        bit = PathToolBit.Factory.CreateFrom(os.path.join(MOD, "Tools", "Bit", f"{name}.fctb"))
        bit.Flutes = flutes
        controller = PathToolController.Create(f"TC: {name}", bit, number)
        controller.SpindleSpeed = rpm
        controller.HorizFeed = f"{feed} mm/min"
        controller.VertFeed = f"{feed / 3} mm/min"
        job.Proxy.addToolController(controller)
        controllers.append(controller)
    job.Tools.Group = controllers
    doc.removeObject(default.Tool.Name)
    doc.removeObject(default.Name)
    model = job.Model.Group[0]
    floor = next(f"Face{i}" for i, face in enumerate(model.Shape.Faces, start=1)
                 if face.Surface.__class__.__name__ == "Plane" and abs(face.BoundBox.ZMax - 5.0) < 1e-6)
    profile.ToolController, profile.Base = controllers[0], []
    profile.processHoles = False
    pocketing.ToolController, pocketing.Base = controllers[1], [(model, [floor])]
    adaptive.ToolController, adaptive.Base = controllers[2], [(model, [floor])]
    drilling.ToolController = controllers[3]
    for op, step in ((profile, 4.0), (pocketing, 2.0), (adaptive, 2.5)):
        op.setExpression("StepDown", None)
        op.StepDown = step
    doc.recompute()
    doc.saveAs(os.path.join(folder, "job.FCStd"))
    post(job, os.path.join(folder, "job.ngc"))
    with open(os.path.join(folder, "tools.tbl"), "w", encoding="utf-8") as table:
        for controller in controllers:
            bit = controller.Tool
            extra = f" R{bit.Diameter.Value / 2 - bit.FlatRadius.Value:g}" if "FlatRadius" in bit.PropertiesList else ""
            table.write(f"T{controller.ToolNumber} P{controller.ToolNumber} D{bit.Diameter.Value:.3f} "
                        f"Z+{bit.Length.Value:.3f} ;{bit.Label}{extra}\n")


class _Fixture:
    """A fixture's commands as FreeCAD's Post command posts them: the work offset, then up to clearance."""

    def __init__(self, job, name):
        self.Name = self.Label = name
        height = job.Stock.Shape.BoundBox.ZMax + job.SetupSheet.ClearanceHeightOffset.Value
        self.Path = Path.Path([Path.Command(name), Path.Command(f"G0 Z{height}")])


def post(job, out):
    """Post `job` with linuxcnc_post to `out`: each fixture, then its active operations, each after its tool
    controller where that changes (FreeCAD's Post command, ordered by fixture)."""
    import PathScripts.PathUtil as PathUtil
    from PathScripts.post import linuxcnc_post

    items = []
    for fixture in job.Fixtures:
        items.append(_Fixture(job, fixture))
        current = None
        for op in job.Operations.Group:
            if not PathUtil.opProperty(op, "Active"):
                continue
            controller = PathUtil.toolControllerForOp(op)
            if controller is not None and controller is not current:
                items.append(controller)
                current = controller
            items.append(op)
    linuxcnc_post.export(items, out, "--no-show-editor")


ARGUMENTS = json.loads(os.environ["ABM_CAM_SCRIPT"])
if ARGUMENTS[0] == "build":
    build(ARGUMENTS[1])
elif ARGUMENTS[0] == "post":
    document = FreeCAD.openDocument(ARGUMENTS[1])
    post(next(obj for obj in document.Objects if "Operations" in obj.PropertiesList), ARGUMENTS[2])
else:
    raise SystemExit(f"unknown command {ARGUMENTS[0]!r}")
