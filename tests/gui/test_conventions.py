"""FreeCAD's conventions: FreeCAD's PySide, translatable text and its template, shortcuts, the
preferences page and what it changes, package.xml.

The first tests read the sources and files (no GUI); the last runs the real GUI under Xvfb.
"""

import ast
import glob
import os
import xml.etree.ElementTree as ElementTree


from tests.conftest import ROOT

MODEL = os.path.join(ROOT, "resources", "models", "model_test_1")
NAMES = ["ABM_OpenModelTest", "ABM_ImportStock", "ABM_ImportToolpath", "ABM_ComputeEngagement",
         "ABM_EngageCamJob", "ABM_InspectEngagement", "ABM_ValidateEngagement"]
GUI_SOURCES = sorted(glob.glob(os.path.join(ROOT, "abm_workbench", "gui", "*.py"))) + [os.path.join(ROOT, "InitGui.py")]


def imported_modules(path):
    """Names of the modules a Python file imports (import x / from x import y)."""
    with open(path, encoding="utf-8") as handle:
        tree = ast.parse(handle.read(), path)
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.append(node.module)
    return names


def test_the_gui_imports_freecads_pyside_never_pyside2():
    offenders = {os.path.basename(path): name for path in GUI_SOURCES for name in imported_modules(path)
                 if name.split(".")[0] == "PySide2"}
    assert offenders == {}
    assert any("PySide" in imported_modules(path) for path in GUI_SOURCES)


def test_the_translation_template_is_qt_linguists_format_and_up_to_date():
    from abm_workbench.gui.i18n import TEMPLATE, catalogue, template

    with open(TEMPLATE, encoding="utf-8") as handle:
        text = handle.read()
    assert text == template(catalogue()), "translations/ABM.ts is stale: /usr/bin/python3 -m abm_workbench.gui.i18n"
    root = ElementTree.fromstring(text.split("\n", 2)[2])  # after the XML declaration and DOCTYPE
    assert root.tag == "TS"
    contexts = {context.findtext("name"): [message.findtext("source") for message in context.iter("message")]
                for context in root.iter("context")}
    # each command: its menu text and tooltip, in the command's own context (FreeCAD translates them there)
    assert set(NAMES) <= set(contexts) and all(len(contexts[name]) == 2 for name in NAMES)
    assert "Validate engagement…" in contexts["ABM_ValidateEngagement"]
    # the task panel's labels and the preferences' words
    assert {"Diameter", "Flute length", "φ step", "Wall model", "Cutting forces", "Colour map"} <= set(contexts["ABM"])
    assert all(message.find("translation").get("type") == "unfinished" for message in root.iter("message"))


def test_package_xml_names_the_repository_bugtracker_maintainer_and_every_python_dependency():
    root = ElementTree.parse(os.path.join(ROOT, "package.xml")).getroot()
    spec = "{https://wiki.freecad.org/Package_Metadata}"
    urls = {url.get("type"): url.text for url in root.iter(spec + "url")}
    assert urls["repository"].startswith("https://github.com/") and urls["bugtracker"].endswith("/issues")
    maintainer = root.find(spec + "maintainer")
    assert maintainer.text and "invalid" not in (maintainer.get("email") or "")
    python = {depend.text for depend in root.iter(spec + "depend") if depend.get("type") == "python"}
    assert {"numpy", "scipy", "matplotlib", "dask", "distributed"} <= python


BODY = """
import numpy as np
from PySide import QtCore, QtGui
from matplotlib import colormaps
window = FreeCADGui.getMainWindow()
def settle():
    for _ in range(5):
        FreeCADGui.updateGui()
def key(widget, code, text="", modifiers=QtCore.Qt.NoModifier):
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtGui.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, code, modifiers, text))
def retype(widget, text):
    key(widget, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
    for char in text:
        key(widget, ord(char.upper()), char)
    settle()

FreeCADGui.activateWorkbench("ABMWorkbench")
verdict["shortcuts"] = {{name: FreeCADGui.Command.get(name).getInfo()["shortcut"] for name in {names!r}}}

# ---- the preferences page: typed in and saved; what it changes -------------------------------
from abm_workbench.gui import commands, task_panel
from abm_workbench.gui.preferences import PreferencesPage, GROUP
page = PreferencesPage()
page.loadSettings()
page.form.show()
retype(page.fields["Diameter"], "10")
retype(page.fields["Flutes"], "3")
retype(page.fields["PhiStep"], "15")
page.colour_map.setFocus()
key(page.colour_map, QtCore.Qt.Key_Down)  # viridis -> plasma
settle()
page.saveSettings()
group = FreeCAD.ParamGet(GROUP)
verdict["stored"] = [group.GetFloat("Diameter"), group.GetInt("Flutes"), group.GetFloat("PhiStep"),
                     group.GetString("ColourMap")]
doc = FreeCAD.newDocument("Conventions")
stock = commands.ImportStock().execute(os.path.join({model!r}, "stock.json"))
path = commands.ImportToolpath().execute(os.path.join({model!r}, "toolpath.csv"))
FreeCADGui.Selection.clearSelection()
FreeCADGui.runCommand("ABM_ComputeEngagement")
settle()
panel = task_panel.shown()
verdict["new_panel"] = [panel.number(name) for name in ("Diameter", "Flutes", "PhiStep", "FluteLength")]
verdict["labels"] = sorted(label.text() for label in panel.form.findChildren(QtGui.QLabel))
panel.reject()
settle()
engagement = commands.ComputeEngagement().execute(dict(diameter=12, flutes=2, flute_length=30, feed_per_tooth=0.1,
                                                       phi_step=10), [stock, path])
engagement.ViewObject.ColourBy = "length"
settle()
colours = np.array(engagement.ViewObject.Proxy.colours)
def on(name):
    table = np.round(colormaps[name](np.linspace(0.0, 1.0, 256))[:, :3], 2)  # the map's 256 colours
    return bool(np.all(np.abs(np.round(colours, 2)[:, None, :] - table[None]).max(axis=2).min(axis=1) <= 0.01))
verdict["colour_map"] = [len(colours), on("plasma"), on("viridis"), engagement.ViewObject.Proxy.legend.colour_map]

# ---- a translation: the panel's labels through Qt's translators ----------------------------------
class Shouting(QtCore.QTranslator):
    def translate(self, context, text, disambiguation=None, n=-1):
        return text.upper() if context == "ABM" else None
    def isEmpty(self):
        return False
shouting = Shouting()
QtCore.QCoreApplication.installTranslator(shouting)
FreeCADGui.ActiveDocument.setEdit(engagement, 0)
settle()
verdict["translated"] = sorted(label.text() for label in task_panel.shown().form.findChildren(QtGui.QLabel))
task_panel.shown().reject()
QtCore.QCoreApplication.removeTranslator(shouting)
"""


def test_shortcuts_preferences_and_translation_in_the_gui(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)

    verdict = run_gui(BODY.format(names=NAMES, model=MODEL))

    shortcuts = verdict["shortcuts"]
    assert all(shortcuts[name] for name in NAMES) and len(set(shortcuts.values())) == len(NAMES), shortcuts
    # typed into the page and saved, read by a new engagement's task panel (the required flute length
    # left unset at 0: its field empty, the panel asks for it)
    assert verdict["stored"] == [10.0, 3, 15.0, "plasma"]
    assert verdict["new_panel"] == [10.0, 3, 15.0, None]
    # the colour map of the preferences on the surface, every face's colour on it (not on viridis)
    count, plasma, viridis, legend = verdict["colour_map"]
    assert count > 100 and plasma and not viridis and legend == "plasma"
    assert "Diameter" in verdict["labels"] and "DIAMETER" in verdict["translated"]
    assert "WALL MODEL" in verdict["translated"] and "Wall model" not in verdict["translated"]
