"""FreeCAD on a screen 768 pixels high (1366 × 768), and 1000 (1280 × 1000): the engagement's task panel
with every section unfolded scrolls on the first and fits the second, and no field reaches under the
scroll bar or past the combo view's edge; the dock stays on the screen and the labels of its plots over
φ are neither cut off by the canvas nor run into each other (at 768 both were, seen in screenshots: the
panel at least 244 pixels wide in a 244-pixel viewport, "length of cut (mm)" taller than its axes)."""

import pytest

from tests.conftest import ROOT
from tests.gui.conftest import run_macro
from tests.gui.events import EVENTS

BODY = """
import shiboken2
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
window.showMaximized()
{events}
FreeCADGui.activateWorkbench("ABMWorkbench")
from abm_workbench.gui import commands, dock, task_panel
_, _, engagement = commands.OpenModelTest().run()
settle()
shown = dock.find()
screen = QtWidgets.QApplication.primaryScreen().geometry()
bottom = shown.mapToGlobal(QtCore.QPoint(0, shown.height())).y()
verdict["dock"] = [bottom, screen.height(), shown.canvas.height()]
figure = shown.canvas.figure
shown.canvas.draw()
renderer = shown.canvas.get_renderer()
labels = [ax.yaxis.label.get_window_extent(renderer) for ax in figure.axes[:3]]
verdict["labels"] = [[box.y0, box.y1] for box in labels]
verdict["figure_height"] = figure.bbox.height

FreeCADGui.ActiveDocument.setEdit(engagement, 0)
settle()
panel = task_panel.shown()
for section in panel.sections.values():
    section.fold(False)
settle()
scroll = panel.form.parentWidget()
while scroll is not None and not isinstance(scroll, QtWidgets.QScrollArea):
    scroll = scroll.parentWidget()
viewport = scroll.viewport()
def right_edge(widget):
    return widget.mapTo(viewport, QtCore.QPoint(widget.width(), 0)).x()
verdict["panel"] = [viewport.width(), scroll.verticalScrollBar().isVisible(),
                    scroll.horizontalScrollBar().isVisible(),
                    {{name: right_edge(panel.field(name)) for name in panel.names}}]
panel.reject()
settle()
"""


@pytest.mark.parametrize("screen", ["1366x768", "1280x1000"])
def test_panel_and_dock_fit_a_small_screen(tmp_path, screen):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    verdict = run_macro(BODY.format(events=EVENTS), tmp_path, screen=screen)
    bottom, height, canvas = verdict["dock"]
    assert bottom <= height and canvas >= 260, verdict["dock"]
    top = verdict["figure_height"]
    labels = verdict["labels"]  # length of cut, cut area, h: top to bottom
    assert all(0 <= low and high <= top for low, high in labels), (labels, top)
    assert all(lower[1] <= upper[0] for upper, lower in zip(labels, labels[1:])), labels
    width, vertical, horizontal, edges = verdict["panel"]
    # all unfolded, the panel is taller than the combo view of a 768-pixel screen (it scrolls), not of a 1000
    assert vertical == (screen == "1366x768"), verdict["panel"]
    assert not horizontal
    assert all(edge <= width for edge in edges.values()), (width, edges)
