"""The README's GUI screenshots: model test 1 in the real FreeCAD GUI, under Xvfb.

``/usr/bin/python3 -m abm_workbench.gui.screenshots docs/images`` (``make screenshots``) starts
FreeCAD under ``xvfb-run`` with a fresh HOME in which the checkout is linked as the ABM
workbench, runs this file there as a macro, and waits for it. Inside the GUI,
:func:`take_screenshots` writes (1280 × 1024 screen, 1024 × 768 views):

- ``gui_window.png``: the whole window: model test 1, the dock at the CL point with the most
  kinds of UEP surface, coloured by engagement segment;
- ``gui_cl_segments.png`` / ``gui_cl_length.png``: the 3D view zoomed on that CL point, coloured
  by UEP surface of the segments / by length of cut, the CL point highlighted;
- ``gui_task_panel.png``: the whole window with the engagement's task panel, a negative
  diameter typed: the field marked, OK disabled, the command line's message;
- ``gui_dock_forces.png``: the whole window, forces on (Al7075-T6, full slot), the dock's Forces
  tab at the CL point with the highest peak force;
- ``gui_program.png``: the whole window with model test 3's program of two operations (stock with
  exact walls, job.json's cut): the dock's program slider moved into operation 2 and rested there, the
  engagement recomputed for it (:mod:`.program`), at that operation's CL point with the most kinds of UEP
  surface.

The GUI tests call :func:`take_screenshots` too, so the pictures and the tests see the same.
"""

import os
import shutil
import signal
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
#: Size (px) of the 3D view pictures, and the height (mm) of the view zoomed on a CL point.
VIEW_SIZE, ZOOM_HEIGHT = (1024, 768), 30.0
#: Environment variable naming the output folder for the macro run.
FOLDER_VARIABLE = "ABM_SCREENSHOTS"
#: Seconds FreeCAD may take to start, take the screenshots and quit.
TIMEOUT = 300


def richest_cl(result):
    """The CL point whose segments reach the most kinds of UEP surface (then: the most segments)."""
    return max(range(result.shape[0]), key=lambda cl: (len({s["surface"] for s in result.segments(cl)}),
                                                       len(result.segments(cl))))


def zoom_on(view, result, cl, height=ZOOM_HEIGHT):
    """Centre the 3D view's camera on the engaged points of CL point `cl`, `height` mm tall."""
    import numpy as np
    from pivy import coin

    points = np.concatenate([result.lep_xyz[cl], result.uep_xyz[cl]])
    centre = points[~np.isnan(points).any(axis=1)].mean(axis=0)
    camera = view.getCameraNode()
    direction = camera.orientation.getValue().multVec(coin.SbVec3f(0, 0, -1))
    camera.position.setValue(coin.SbVec3f(*centre) - direction * camera.focalDistance.getValue())
    camera.height.setValue(height)


#: Rounds of the event loop before a screenshot: what was queued for later is drawn.
SETTLE_ROUNDS = 4


def grab_screen(path):
    """Save the whole X screen (3D view included, unlike QWidget.grab) as a PNG."""
    from PySide import QtGui

    for _ in range(SETTLE_ROUNDS):  # the dock plots on the next turn, and matplotlib draws on the one after
        QtGui.QApplication.processEvents()
    QtGui.QApplication.primaryScreen().grabWindow(0).save(path)


def take_screenshots(folder):
    """Open model test 1 and write the screenshots (see the module docstring) into `folder`; their paths."""
    import FreeCAD
    import FreeCADGui

    import numpy as np

    from . import commands, dock, task_panel

    os.makedirs(folder, exist_ok=True)
    window = FreeCADGui.getMainWindow()
    window.showMaximized()
    FreeCADGui.activateWorkbench("ABMWorkbench")
    _, _, engagement = commands.OpenModelTest().run()
    result = engagement.Proxy.result(engagement)
    cl = richest_cl(result)
    commands.InspectEngagement.show(engagement, cl)
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    FreeCADGui.updateGui()
    paths = [os.path.join(folder, name) for name in
             ("gui_window.png", "gui_cl_segments.png", "gui_cl_length.png", "gui_task_panel.png",
              "gui_dock_forces.png", "gui_program.png")]
    grab_screen(paths[0])
    zoom_on(view, result, cl)
    for path, colour_by in zip(paths[1:3], ("segment", "length")):
        engagement.ViewObject.ColourBy = colour_by
        FreeCADGui.updateGui()
        view.saveImage(path, *VIEW_SIZE, "White")
    engagement.ViewObject.ColourBy = "segment"
    view.fitAll()
    FreeCADGui.ActiveDocument.setEdit(engagement, 0)
    FreeCADGui.updateGui()
    panel = task_panel.shown()
    panel.set_number("Diameter", -3.0)
    FreeCADGui.updateGui()
    grab_screen(paths[3])
    panel.reject()
    engagement.Forces, engagement.Material = True, "al7075-t6"
    engagement.Document.recompute()
    forces = engagement.Proxy.forces(engagement)
    shown = dock.show(engagement, int(np.argmax(forces.peak)))
    shown.tabs.setCurrentIndex(dock.FORCES_TAB)
    FreeCADGui.updateGui()
    grab_screen(paths[4])
    FreeCAD.closeDocument(engagement.Document.Name)
    program_window(paths[5])
    return paths


def program_window(path):
    """Model test 3 in a new document, the dock's program slider moved into operation 2 and rested there: the
    whole window saved to `path`."""
    import FreeCAD
    import FreeCADGui

    from ..features import create_engagement, create_stock, create_toolpath
    from . import commands, dock, view_providers

    folder = os.path.join(ROOT, "resources", "models", "model_test_3")
    doc = FreeCAD.newDocument("ModelTest3")
    stock = create_stock(doc, os.path.join(folder, "stock.step"), walls="exact")
    toolpath = create_toolpath(doc, os.path.join(folder, "program.apt"), operation=1)
    engagement = create_engagement(doc, stock, toolpath, **commands.load_settings(os.path.join(folder, "job.json")))
    for obj in (stock, toolpath, engagement):
        view_providers.attach(obj)
    doc.recompute()
    commands.fit_view()
    row = dock.show(engagement).program
    second = row.spans[1]
    row.slider.setValue(second.start + second.count // 2)  # as a user moves it; the dock goes there once it rests
    row.settle()
    row.slider.setValue(second.start + richest_cl(engagement.Proxy.result(engagement)))
    FreeCADGui.updateGui()
    grab_screen(path)
    FreeCAD.closeDocument(doc.Name)


def _macro():
    """Run inside FreeCAD's GUI: the screenshots into $ABM_SCREENSHOTS, then quit (status 0 or 1)."""
    import traceback

    from PySide import QtCore

    def run():
        status = 1
        try:
            sys.path.insert(0, ROOT)
            from abm_workbench.gui.screenshots import take_screenshots as take  # this file, as a package module

            paths = take(os.environ[FOLDER_VARIABLE])
            print("\n".join(paths))
            status = 0
        except Exception:  # noqa: BLE001 (printed; the exit status says it)
            traceback.print_exc()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os._exit(status)

    QtCore.QTimer.singleShot(1500, run)


def main(folder):
    """Start FreeCAD under Xvfb with this file as its macro; the exit status (0: all written)."""
    home = tempfile.mkdtemp(prefix="abm-screenshots-")
    try:
        mods = os.path.join(home, ".local", "share", "FreeCAD", "Mod")
        os.makedirs(mods)
        os.symlink(ROOT, os.path.join(mods, "ABM"))
        env = dict(os.environ, HOME=home, QTWEBENGINE_DISABLE_SANDBOX="1", PYTHONPATH=ROOT,
                   **{FOLDER_VARIABLE: os.path.abspath(folder)})
        process = subprocess.Popen(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "freecad",
                                    os.path.abspath(__file__)], env=env, start_new_session=True)
        try:
            return process.wait(timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)  # xvfb-run, Xvfb and FreeCAD: the session started here
            print(f"screenshots: FreeCAD did not finish in {TIMEOUT} s", file=sys.stderr)
            return 1
    finally:
        shutil.rmtree(home, ignore_errors=True)


if "FreeCADGui" in sys.modules and __name__ != "abm_workbench.gui.screenshots":  # FreeCAD runs it as its macro
    _macro()
elif __name__ == "__main__":  # python -m abm_workbench.gui.screenshots FOLDER
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "docs", "images")))
