"""The annotated FCStd written headless opens in the real FreeCAD GUI: objects shown, no errors."""

from abm_workbench.cad.annotate import write_annotated
from abm_workbench.cad.solids import staircase_solid
from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, engage

STOCK = Staircase(0, 80, -12, 12, -10, [3.0, 7.0, 4.0],
                  [[[30 + 0.02 * y * y, y] for y in (-12, -8, -3, 3, 8, 12)], [[55.0, y] for y in (-12, -8, -3, 3, 8, 12)]])
TOOL = Tool(12, 2, 25)
PATH = Toolpath([[26.0, 0.5, 1.0], [50.0, -0.5, 2.0]], [8.0, -5.0], [15.0, 20.0])


def test_annotated_document_opens_in_the_gui_with_its_objects_shown(tmp_path, run_gui):
    engagement = engage(STOCK, TOOL, PATH, CutSettings(0.1, 10, 0, 180, 5))
    path = tmp_path / "pass.FCStd"
    write_annotated(path, "ABM_gui", staircase_solid(STOCK), engagement, PATH, TOOL, intersections=[1])
    verdict = run_gui(f"""
        document = FreeCAD.openDocument({str(path)!r})
        view = FreeCADGui.ActiveDocument.ActiveView
        view.viewIsometric(); view.fitAll(); FreeCADGui.updateGui()
        view.saveImage({str(tmp_path / 'pass.png')!r}, 800, 600, "White")
        verdict["hidden"] = [o.Name for o in document.Objects if not o.ViewObject.Visibility]
        verdict["invalid"] = [o.Name for o in document.Objects
                              if o.TypeId == "Part::Feature" and not o.Shape.isValid()]
        verdict["segments"] = sorted(o.Name for o in document.Objects if "_Seg_" in o.Name)
        verdict["colours"] = {{o.Name: list(o.ViewObject.ShapeColor)[:3] for o in document.Objects
                              if "_Seg_" in o.Name}}
    """)
    assert verdict["hidden"] == [] and verdict["invalid"] == []
    expected = sorted(f"CL{cl:03d}_Seg_{s['letter']}_{s['surface']}" for cl in (0, 1) for s in engagement.segments(cl))
    assert verdict["segments"] == expected
    assert len({tuple(round(c, 3) for c in colour) for colour in verdict["colours"].values()}) >= 2
    assert (tmp_path / "pass.png").stat().st_size > 10_000  # a picture, not a blank view
