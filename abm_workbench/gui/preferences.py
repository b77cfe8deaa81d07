"""The workbench's preferences: defaults of a new engagement, the report folder, the colour map.

Stored in FreeCAD's parameters, group ``User parameter:BaseApp/Preferences/Mod/ABM``
(:data:`GROUP`), and edited on the page "ABM" of Edit → Preferences (:class:`PreferencesPage`,
registered by InitGui.py with ``FreeCADGui.addPreferencePage``):

- tool and cut of a new engagement (:data:`DEFAULTS`: diameter, flutes, flute length, feed per
  tooth (mm), inclination, φ step (deg)); 0 leaves a required one (the tool, the feed) unset, so
  the task panel asks for it; the optional ones start at the job model's defaults.
  :func:`engagement_defaults` gives them as ``create_engagement`` keywords; the task panel of
  ABM_ComputeEngagement starts from them (a toolpath file's values still win);
- the folder validation reports go to (empty: beside the document, as before), :func:`report_root`;
- the colour map of the quantities on the engagement surface and in the dock's colour bar
  (a matplotlib colour map name, :data:`COLOUR_MAPS`), :func:`colour_map`;
- the processes computing a validation's boolean reference, "Validation workers"
  (:func:`validation_workers`: 0 one per core, N that many spawned
  Python processes, each with its own FreeCAD).
"""

import os

import FreeCAD

from ..jobs import BY_NAME
from .i18n import noop, translate

#: The icons' folder: FreeCAD shows the page's group with ``preferences-abm.svg`` from it.
ICONS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "resources",
                     "icons")
#: FreeCAD parameter group of the workbench.
GROUP = "User parameter:BaseApp/Preferences/Mod/ABM"
#: Defaults of a new engagement: (create_engagement keyword, parameter name, label, unit, value, step);
#: a value of 0 for a required one (diameter, flutes, flute length, feed) leaves it unset.
DEFAULTS = (
    ("diameter", "Diameter", noop("Tool diameter"), "mm", 0.0, 1.0),
    ("flutes", "Flutes", noop("Flutes"), "", 0, 1),
    ("flute_length", "FluteLength", noop("Flute length"), "mm", 0.0, 1.0),
    ("feed_per_tooth", "FeedPerTooth", noop("Feed per tooth"), "mm", 0.0, 0.01),
    ("inclination", "Inclination", noop("Inclination α"), "°", float(BY_NAME["inclination"].default), 1.0),
    ("phi_step", "PhiStep", noop("φ step"), "°", float(BY_NAME["phi_step"].default), 0.5),
)
#: Keywords of DEFAULTS that the job model requires (0: not set).
REQUIRED = ("diameter", "flutes", "flute_length", "feed_per_tooth")
#: Colour maps offered for the quantities (matplotlib names); the first is the default.
COLOUR_MAPS = ("viridis", "plasma", "inferno", "magma", "cividis", "turbo")
#: Largest number of validation workers the page offers.
MAX_WORKERS = 256


def parameters():
    """FreeCAD's parameter group of the workbench (created on first use)."""
    return FreeCAD.ParamGet(GROUP)


def engagement_defaults():
    """{create_engagement keyword: value} of the preferences, without those left at 0 (unset)."""
    group = parameters()
    values = {}
    for key, name, _, unit, value, _ in DEFAULTS:
        stored = group.GetFloat(name, float(value)) if unit else group.GetInt(name, int(value))
        if stored or key not in REQUIRED:
            values[key] = stored
    return values


def report_root():
    """Folder the validation reports go to, or "" for beside the document."""
    return parameters().GetString("ReportFolder", "")


def colour_map():
    """Name of the colour map of the quantities (one of COLOUR_MAPS)."""
    name = parameters().GetString("ColourMap", COLOUR_MAPS[0])
    return name if name in COLOUR_MAPS else COLOUR_MAPS[0]


def validation_workers():
    """Processes computing a validation's boolean reference (int: 1 this process, 0 one per core)."""
    return min(max(parameters().GetInt("ValidationWorkers", 1), 0), MAX_WORKERS)


class PreferencesPage:
    """The page "ABM" of FreeCAD's preferences: a form FreeCAD shows, loadSettings / saveSettings."""

    def __init__(self, parent=None):
        from PySide import QtGui  # here: the functions above also serve FreeCAD without its GUI

        self.form = QtGui.QWidget(parent)
        self.form.setObjectName("ABM_Preferences")
        self.form.setWindowTitle(translate("ABM"))
        layout = QtGui.QVBoxLayout(self.form)
        box = QtGui.QGroupBox(translate("New engagement: tool and cut (0: ask)"))
        rows = QtGui.QFormLayout(box)
        rows.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        self.fields = {}
        for _, name, label, unit, _, step in DEFAULTS:
            field = QtGui.QDoubleSpinBox() if unit else QtGui.QSpinBox()
            field.setObjectName(f"ABM_Default{name}")
            if unit:
                field.setRange(-90.0 if name == "Inclination" else 0.0, 1e4)
                field.setDecimals(3)
                field.setSuffix(f" {unit}" if unit == "mm" else unit)
            field.setSingleStep(step)
            rows.addRow(translate(label), field)
            self.fields[name] = field
        layout.addWidget(box)
        box = QtGui.QGroupBox(translate("Results"))
        rows = QtGui.QFormLayout(box)
        rows.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        self.report_folder = QtGui.QLineEdit()
        self.report_folder.setObjectName("ABM_ReportFolder")
        self.report_folder.setPlaceholderText(translate("beside the document"))
        rows.addRow(translate("Validation reports in"), self.report_folder)
        self.colour_map = QtGui.QComboBox()
        self.colour_map.setObjectName("ABM_ColourMap")
        self.colour_map.addItems(list(COLOUR_MAPS))
        rows.addRow(translate("Colour map"), self.colour_map)
        self.workers = QtGui.QSpinBox()
        self.workers.setObjectName("ABM_ValidationWorkers")
        self.workers.setRange(0, MAX_WORKERS)
        self.workers.setSpecialValueText(translate("one per core"))
        self.workers.setToolTip(translate("Processes computing the boolean reference of a validation, beside "
                                          "FreeCAD's own (which stays free to draw): 0 one per core"))
        rows.addRow(translate("Validation workers"), self.workers)
        layout.addWidget(box)
        layout.addStretch(1)

    def loadSettings(self):
        group = parameters()
        for _, name, _, unit, value, _ in DEFAULTS:
            field = self.fields[name]
            if unit:
                field.setValue(group.GetFloat(name, float(value)))
            else:
                field.setValue(group.GetInt(name, int(value)))
        self.report_folder.setText(report_root())
        self.colour_map.setCurrentIndex(COLOUR_MAPS.index(colour_map()))
        self.workers.setValue(validation_workers())

    def saveSettings(self):
        group = parameters()
        for _, name, _, unit, _, _ in DEFAULTS:
            if unit:
                group.SetFloat(name, float(self.fields[name].value()))
            else:
                group.SetInt(name, int(self.fields[name].value()))
        group.SetString("ReportFolder", self.report_folder.text().strip())
        group.SetString("ColourMap", self.colour_map.currentText())
        group.SetInt("ValidationWorkers", int(self.workers.value()))
