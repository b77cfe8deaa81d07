"""The dock's program slider in the real GUI, driven by key presses and a mouse drag: model test 3's
program of two operations (OP1_SEMI_FINISH, D12, and OP2_REST, D8) on one slider, in step with the CL
spin box, and the engagement recomputed once for the other operation where the slider rests.

The reference is the file itself, read here with a few lines (cutting moves: the GOTOs not after a
RAPID, per TOOL PATH), not with the workbench's reader."""

import os

import numpy as np

from tests.conftest import ROOT
from tests.gui.events import EVENTS

MODEL = os.path.join(ROOT, "resources", "models", "model_test_3")


def cutting_points(path):
    """[(name, (k, 3) cutting CL points)] of each TOOL PATH of the APT file `path`."""
    operations, rapid = [], False
    with open(path) as handle:
        for line in handle:
            word = line.strip()
            if word.startswith("TOOL PATH/"):
                operations.append((word.split("/")[1].split(",")[0], []))
            elif word == "RAPID":
                rapid = True
            elif word.startswith("GOTO/"):
                if not rapid:
                    operations[-1][1].append([float(v) for v in word[5:].split(",")[:3]])
                rapid = False
    return [(name, np.array(points)) for name, points in operations]


BODY = """
import json
import numpy as np
import shiboken2
from PySide import QtCore, QtGui
QtWidgets = QtGui
window = FreeCADGui.getMainWindow()
report = window.findChild(QtWidgets.QDockWidget, "Report view").widget()
{events}
def wait(ms):
    until = QtCore.QTime.currentTime().addMSecs(ms)
    while QtCore.QTime.currentTime() < until:
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
def mouse(widget, kind, x, buttons):
    point = QtCore.QPointF(x, widget.height() / 2)
    button = QtCore.Qt.NoButton if kind == QtCore.QEvent.MouseMove else QtCore.Qt.LeftButton
    QtWidgets.QApplication.sendEvent(widget, QtGui.QMouseEvent(kind, point, button, buttons, QtCore.Qt.NoModifier))

from abm_workbench.features import create_engagement, create_stock, create_toolpath
from abm_workbench.features import engagement as engagement_feature
from abm_workbench.gui import commands, view_providers

recomputes = []
plain = engagement_feature.EngagementFeature.execute
def counted(self, obj):
    recomputes.append(obj.Name)
    return plain(self, obj)
engagement_feature.EngagementFeature.execute = counted

FreeCADGui.activateWorkbench("ABMWorkbench")
doc = FreeCAD.newDocument("Program")
stock = create_stock(doc, {stock!r}, walls="exact")
toolpath = create_toolpath(doc, {program!r}, operation=1)
engagement = create_engagement(doc, stock, toolpath, **commands.load_settings({job!r}))
for obj in (stock, toolpath, engagement):
    view_providers.attach(obj)
doc.recompute()
shown = commands.InspectEngagement.show(engagement, 0)
settle()
row, slider = shown.program, shown.findChild(QtWidgets.QSlider, "ABM_ProgramSlider")
where = shown.findChild(QtWidgets.QLabel, "ABM_ProgramWhere")
def state():
    return dict(operation=toolpath.Operation, rows=engagement.Proxy.result(engagement).shape[0],
                diameter=float(engagement.Proxy.inputs(engagement).tool.diameter), program=slider.value(),
                cl=shown.spin.value(), cl_slider=shown.slider.value(), where=where.text(),
                recomputes=len(recomputes), highlight=engagement.ViewObject.Proxy.cl,
                properties=[engagement.Diameter.Value, engagement.FluteLength.Value, engagement.SpindleSpeed,
                            engagement.FeedPerTooth.Value],
                points=[[v.X, v.Y, v.Z] for v in toolpath.Shape.Vertexes])
verdict["start"] = dict(state(), visible=row.isVisible(), maximum=slider.maximum())
recomputes.clear()

# a CL point typed into the dock's spin box: the program slider follows
shown.spin.setFocus()
key(shown.spin, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
for char in "100":
    key(shown.spin, ord(char), char)
key(shown.spin, QtCore.Qt.Key_Return)
settle()
verdict["typed"] = state()

# the program slider moved by keys within operation 1: the CL point follows at once, no recompute
slider.setFocus()
for _ in range(3):
    key(slider, QtCore.Qt.Key_Right)
settle()
verdict["right"] = state()
wait(800)
verdict["right_rested"] = state()

# End: the program's last CL point, in operation 2: said at once, computed once the slider rests
key(slider, QtCore.Qt.Key_End)
settle()
verdict["end_moving"] = state()
wait(1500)
settle()
verdict["end_rested"] = dict(state(), undo=list(doc.UndoNames))

# Home then End before the slider rests: back in the engagement's operation (2), nothing recomputed
key(slider, QtCore.Qt.Key_Home)
settle()
verdict["home_moving"] = state()
key(slider, QtCore.Qt.Key_End)
wait(1500)
settle()
verdict["home_end"] = state()

# a mouse drag from the handle at the right end into operation 1, over many positions: one recompute
style, option = slider.style(), QtWidgets.QStyleOptionSlider()
slider.initStyleOption(option)
handle = style.subControlRect(QtWidgets.QStyle.CC_Slider, option, QtWidgets.QStyle.SC_SliderHandle, slider)
x0 = handle.center().x()
mouse(slider, QtCore.QEvent.MouseButtonPress, x0, QtCore.Qt.LeftButton)
seen = []
for x in np.linspace(x0, 0.25 * slider.width(), 25):
    mouse(slider, QtCore.QEvent.MouseMove, float(x), QtCore.Qt.LeftButton)
    QtWidgets.QApplication.processEvents()
    seen.append(slider.value())
mouse(slider, QtCore.QEvent.MouseButtonRelease, 0.25 * slider.width(), QtCore.Qt.NoButton)
settle()
verdict["seen"] = seen
wait(1500)
settle()
verdict["dragged"] = state()
verdict["report"] = report.toPlainText()  # what the program slider's moves wrote

# a second engagement computing operation 2 of the same program on the same stock: End goes to it, nothing
# recomputed, the first engagement's toolpath left at operation 1
second_path = create_toolpath(doc, {program!r}, operation=2)
second = create_engagement(doc, stock, second_path, **commands.load_settings({job!r}))
for obj in (second_path, second):
    view_providers.attach(obj)
doc.recompute()
shown = commands.InspectEngagement.show(engagement, 5)
settle()
recomputes.clear()
slider.setFocus()
key(slider, QtCore.Qt.Key_End)
wait(1500)
settle()
verdict["other"] = [shown.obj.Name, second.Name, toolpath.Operation, len(recomputes), shown.spin.value(),
                    second.ViewObject.Proxy.cl, slider.value(), where.text()]
"""


def test_program_slider_keys_and_drag(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"  # the workbench installed
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    program = os.path.join(MODEL, "program.apt")
    (first_name, first), (second_name, second) = cutting_points(program)
    n1, n2 = len(first), len(second)
    verdict = run_gui(BODY.format(events=EVENTS, stock=os.path.join(MODEL, "stock.step"), program=program,
                                  job=os.path.join(MODEL, "job.json")))
    start = verdict["start"]
    assert start["visible"] and start["maximum"] == n1 + n2 - 1
    assert start["operation"] == 1 and start["rows"] == n1 and start["diameter"] == 12.0
    assert start["program"] == 0 and start["cl"] == 0

    typed = verdict["typed"]
    assert typed["cl"] == typed["program"] == 100 and typed["highlight"] == 100
    assert typed["where"] == f"Program CL 100 of {n1 + n2}: operation 1 ({first_name}), flat-end mill D12 mm, its CL 100"

    right = verdict["right"]
    assert right["program"] == right["cl"] == right["cl_slider"] == right["highlight"] == 103
    assert right["recomputes"] == 0 and verdict["right_rested"]["recomputes"] == 0

    moving = verdict["end_moving"]
    assert moving["program"] == n1 + n2 - 1 and moving["operation"] == 1 and moving["cl"] == 103
    assert moving["recomputes"] == 0 and "going there once the slider rests" in moving["where"]
    rested = verdict["end_rested"]
    assert rested["operation"] == 2 and rested["rows"] == n2 and rested["diameter"] == 8.0
    assert rested["cl"] == rested["highlight"] == n2 - 1 and rested["program"] == n1 + n2 - 1
    assert rested["recomputes"] == 1 and rested["undo"][0] == "Choose operation"
    # the file's tool and cut of operation 2 in the engagement's properties: CUTTER/8, flute length 20,
    # SPINDL 5000 rpm, FEDRAT 600 mm/min with job.json's 2 flutes: 600 / (5000 · 2) mm per tooth
    assert np.allclose(rested["properties"], [8.0, 20.0, 5000.0, 600 / (5000 * 2)], rtol=1e-12, atol=0)
    assert rested["where"] == (f"Program CL {n1 + n2 - 1} of {n1 + n2}: operation 2 ({second_name}), "
                               f"flat-end mill D8 mm, its CL {n2 - 1}")
    # the toolpath object now draws operation 2's cutting points, as the file has them
    assert np.abs(np.array(rested["points"]) - second).max() < 1e-9

    home = verdict["home_moving"]
    assert home["program"] == 0 and home["operation"] == 2 and "going there" in home["where"]
    back = verdict["home_end"]
    assert back["operation"] == 2 and back["recomputes"] == 1 and back["program"] == n1 + n2 - 1

    seen = verdict["seen"]
    assert len(set(seen)) > 5 and seen[-1] < n1  # the drag went through many positions, into operation 1
    dragged = verdict["dragged"]
    assert dragged["recomputes"] == 2 and dragged["operation"] == 1 and dragged["rows"] == n1
    assert dragged["cl"] == dragged["program"] == dragged["highlight"] == seen[-1]
    assert np.abs(np.array(dragged["points"]) - first).max() < 1e-9
    assert np.allclose(dragged["properties"], [12.0, 30.0, 4000.0, 800 / (4000 * 2)], rtol=1e-12, atol=0)
    name, second_name_, operation, count, cl, highlight, index, words = verdict["other"]
    assert name == second_name_ and operation == 1 and count == 0
    assert cl == highlight == n2 - 1 and index == n1 + n2 - 1 and f"operation 2 ({second_name})" in words
    # nothing the user must read as a command line's option, no error
    assert "--" not in verdict["report"] and "Traceback" not in verdict["report"], verdict["report"]
