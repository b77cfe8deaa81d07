"""The task panel of an engagement object: tool, cut, wall model, y window and forces, checked as typed.

Opened by ABM_ComputeEngagement for a new engagement (:func:`compute`) and by double-click /
``setEdit`` for an existing one (:func:`edit`). Lengths and angles are FreeCAD quantity spin
boxes (``Gui::QuantitySpinBox``: units typed or shown, "12 mm", "0.5 in", "10 °").

As the user types, the values are checked by the job model, as the command line's are:
``jobs.resolve`` (every value against its declaration in ``jobs.parameters``; what an APT / CL
toolpath file gives wins; a missing required value), ``jobs.tool_and_settings`` (with the helix
angle), the cutting-force settings (on / off, material or custom coefficients, immersion) by
``features.engagement.force_settings``, and the y window as ``features.engagement.y_window``
checks it. A problem is a ParameterError naming its parameter: the parameter's field is marked
(its declared property) and the problem shown at the top of the panel in plain words
(``jobs.label_words``), and OK is disabled. The coefficient fields show the material's values,
read-only, unless the material is custom. Fields the toolpath file fixes show its value, are
read-only and say so.

The whole edit is one document transaction: OK commits it (after a recompute that succeeds),
Cancel aborts it, which for a new engagement removes the object.
"""

from PySide2 import QtWidgets

import FreeCADGui

from ..errors import InputError, ParameterError
from ..features.engagement import COEFFICIENT_PROPERTIES, MATERIAL_CHOICES, Y_WINDOWS, WALL_CHOICES, force_settings
from ..forces import MATERIALS
from ..jobs import BY_NAME, label_words, resolve, tool_and_settings
from . import state, view_providers
from .progress import busy
from .reporting import CommandError, message_of, recompute_checked, report_error

#: Fields: (property, label, unit or None for a plain number, minimum, maximum, step).
FIELDS = (
    ("Diameter", "Diameter", "mm", -1e6, 1e6, 1.0),
    ("Flutes", "Flutes", None, 0, 100, 1),
    ("FluteLength", "Flute length", "mm", -1e6, 1e6, 1.0),
    ("HelixAngle", "Helix angle β", "deg", -1e6, 1e6, 5.0),
    ("FeedPerTooth", "Feed per tooth", "mm", -1e6, 1e6, 0.01),
    ("SpindleSpeed", "Spindle speed (rpm)", None, 0.0, 1e6, 100.0),
    ("Inclination", "Inclination α", "deg", -1e6, 1e6, 1.0),
    ("PhiStart", "φ start", "deg", -1e6, 1e6, 1.0),
    ("PhiEnd", "φ end", "deg", -1e6, 1e6, 1.0),
    ("PhiStep", "φ step", "deg", -1e6, 1e6, 0.5),
    ("YWindowMin", "y window from", "mm", -1e6, 1e6, 1.0),
    ("YWindowMax", "y window to", "mm", -1e6, 1e6, 1.0),
)
#: Force fields after the Forces check box and the Material combo: (property, label, unit, minimum, maximum, step).
FORCE_FIELDS = tuple((prop, f"{prop} ({'N/mm²' if prop.endswith('c') else 'N/mm'})", None, -1e6, 1e6, 10.0)
                     for prop in COEFFICIENT_PROPERTIES.values()) + (
    ("ImmersionStart", "Immersion from", "deg", -1e6, 1e6, 5.0), ("ImmersionEnd", "Immersion to", "deg", -1e6, 1e6, 5.0))
#: Cutting parameters a toolpath file can fix, with their fields.
FILE_FIELDS = ("diameter", "flute_length", "spindle_rpm", "feed_per_tooth")
INVALID_STYLE = "background-color: #ffc8c8;"


_SHOWN = []  # the panel shown, if any (for scripts and tests: shown())


def shown():
    """The engagement task panel shown now, or None."""
    return _SHOWN[-1] if _SHOWN else None


class EngagementPanel:
    """Task panel editing the engagement object `obj` (see the module docstring)."""

    def __init__(self, obj, *, new):
        self.obj, self.new = obj, new
        self.buttons = None  # the task dialog's QDialogButtonBox, once FreeCAD has made it
        self.form = QtWidgets.QWidget()
        self.form.setObjectName("ABM_EngagementPanel")
        self.form.setWindowTitle("Engagement: tool and cut")
        layout = QtWidgets.QFormLayout(self.form)
        self.source = QtWidgets.QLabel(f"Stock: {_label(obj.Stock)}<br>Toolpath: {_label(obj.Toolpath)}")
        layout.addRow(self.source)
        self.message = QtWidgets.QLabel()  # at the top: seen whatever the panel is scrolled to
        self.message.setObjectName("ABM_Message")
        self.message.setWordWrap(True)
        self.message.setStyleSheet("color: #b00000;")
        layout.addRow(self.message)
        self.fixed = QtWidgets.QLabel()
        self.fixed.setObjectName("ABM_Fixed")
        self.fixed.setWordWrap(True)
        layout.addRow(self.fixed)
        self.names = []  # of the fields, in order: self.field(name) finds each
        for name, label, unit, low, high, step in FIELDS:
            widget = _spin_box(unit, low, high, step, integer=name == "Flutes")
            widget.setObjectName(f"ABM_{name}")
            widget.setToolTip(obj.getDocumentationOfProperty(name))
            self.names.append(name)
            if name == "YWindowMin":
                layout.addRow("Wall model", self._combo("WallModel", WALL_CHOICES))
                layout.addRow("y window", self._combo("YWindow", Y_WINDOWS))
            layout.addRow(label, widget)
            _set_value(widget, _property_value(obj, name))
            widget.valueChanged.connect(self.check)
        self.field("SpindleSpeed").setSpecialValueText("none")
        self._force_fields(layout)
        self.hints = self._hints()
        self.check()

    def _force_fields(self, layout):
        """The Forces check box beside the Material combo, then the coefficients and the immersion."""
        obj = self.obj
        forces = QtWidgets.QCheckBox("Cutting forces")
        forces.setObjectName("ABM_Forces")
        forces.setChecked(bool(obj.Forces))
        forces.setToolTip(obj.getDocumentationOfProperty("Forces"))
        forces.toggled.connect(self.check)
        self.names.append("Forces")
        layout.addRow(forces, self._combo("Material", MATERIAL_CHOICES))
        for name, label, unit, low, high, step in FORCE_FIELDS:
            widget = _spin_box(unit, low, high, step)
            if unit is None:
                widget.setDecimals(3)
            widget.setObjectName(f"ABM_{name}")
            widget.setToolTip(obj.getDocumentationOfProperty(name))
            self.names.append(name)
            layout.addRow(label, widget)
            _set_value(widget, _property_value(obj, name))
            widget.valueChanged.connect(self.check)

    def _combo(self, name, choices):
        combo = QtWidgets.QComboBox()
        combo.setObjectName(f"ABM_{name}")
        combo.addItems(list(choices))
        combo.setCurrentIndex(list(choices).index(getattr(self.obj, name)))
        combo.setToolTip(self.obj.getDocumentationOfProperty(name))
        combo.currentIndexChanged.connect(self.check)
        self.names.append(name)
        return combo

    def field(self, name):
        """The widget of field `name` (a property name). Found by object name each time: the Python
        wrappers of FreeCAD's own widgets (Gui::QuantitySpinBox) do not stay valid."""
        return self.form.findChild(QtWidgets.QWidget, f"ABM_{name}")

    def _hints(self):
        """PathHints of the toolpath file, or the InputError reading it."""
        toolpath = self.obj.Toolpath
        try:
            return toolpath.Proxy.load(toolpath)[1]
        except (InputError, AttributeError) as error:
            return error

    # ---- values -----------------------------------------------------------------------------
    def values(self):
        """{property: value} of the fields (numbers in mm, deg, rpm; choices as text)."""
        values = {}
        for name in self.names:
            widget = self.field(name)
            if isinstance(widget, QtWidgets.QComboBox):
                values[name] = widget.currentText()
            elif isinstance(widget, QtWidgets.QCheckBox):
                values[name] = widget.isChecked()
            else:
                values[name] = _get_value(widget)
        values["Flutes"] = int(values["Flutes"])
        return values

    def given(self, values):
        """jobs.resolve's `given` of the field values (required ones 0: not given)."""
        def unset_zero(value):
            return None if value == 0 else value

        return {
            "diameter": unset_zero(values["Diameter"]), "flutes": unset_zero(values["Flutes"]),
            "flute_length": unset_zero(values["FluteLength"]), "feed_per_tooth": unset_zero(values["FeedPerTooth"]),
            "inclination": values["Inclination"], "spindle_rpm": unset_zero(values["SpindleSpeed"]),
            "phi_start": values["PhiStart"], "phi_end": values["PhiEnd"], "phi_step": values["PhiStep"],
        }

    def problem(self, values):
        """(message, field) of the first problem of `values`, or (None, None); marks what the file fixes."""
        if isinstance(self.hints, Exception):
            return str(self.hints), None
        try:
            parameters = resolve(self.given(values), self.hints, {})
            self.show_fixed(parameters)
            tool_and_settings(parameters.values, values["HelixAngle"])
            if values["Forces"]:
                force_settings(values["Material"], values, (values["ImmersionStart"], values["ImmersionEnd"]))
        except ParameterError as error:
            parameter = BY_NAME.get(error.field)
            return label_words(error), parameter.prop if parameter is not None else None
        stock = self.obj.Stock
        solid = stock is not None and stock.Proxy.is_solid(stock)
        if values["WallModel"] != "stock" and not solid:
            return (f"The wall model {values['WallModel']} applies to a solid stock (STEP, BREP or FCStd), not to "
                    f"{stock.Proxy.source_name(stock)}.", "WallModel")
        if values["YWindow"] in ("swept", "custom") and not solid:
            return (f"The y window {values['YWindow']} applies to a solid stock (STEP, BREP or FCStd), not to "
                    f"{stock.Proxy.source_name(stock)}.", "YWindow")
        if values["YWindow"] == "custom" and not values["YWindowMin"] < values["YWindowMax"]:
            return (f"The y window must start below its end: {values['YWindowMin']:g} mm to "
                    f"{values['YWindowMax']:g} mm.", "YWindowMin")
        return None, None

    def show_fixed(self, parameters):
        """Fields whose value the toolpath file gives: its value, read-only, explained."""
        notes = []
        for key in FILE_FIELDS:
            name = BY_NAME[key].prop
            widget = self.field(name)
            fixed = parameters.fixed_by_file(key)
            if fixed:
                widget.blockSignals(True)
                _set_value(widget, parameters.values[key])
                widget.blockSignals(False)
                notes.append(f"{BY_NAME[key].label} {parameters.values[key]:g} ({parameters.sources[key][1]})")
            widget.setEnabled(not fixed)
        self.fixed.setText("Fixed by the toolpath file, the values it was made for: " + ", ".join(notes)
                           if notes else "")

    def show_material(self, values):
        """Force fields: enabled with Forces on; the coefficients show a material's values, read-only,
        unless it is custom."""
        self.field("Material").setEnabled(values["Forces"])
        custom = values["Material"] == "custom"
        for name, prop in COEFFICIENT_PROPERTIES.items():
            widget = self.field(prop)
            if not custom:
                widget.blockSignals(True)
                _set_value(widget, getattr(MATERIALS[values["Material"]][0], name))
                widget.blockSignals(False)
                values[prop] = _get_value(widget)
            widget.setEnabled(values["Forces"] and custom)
        for name in ("ImmersionStart", "ImmersionEnd"):
            self.field(name).setEnabled(values["Forces"])

    def check(self, *_):
        """Check the fields: mark the bad one, say why, enable OK only when all is well; True if valid."""
        values = self.values()
        for name in ("YWindowMin", "YWindowMax"):
            self.field(name).setEnabled(values["YWindow"] == "custom")
        self.show_material(values)
        message, field = self.problem(values)
        for name in self.names:
            self.field(name).setStyleSheet(INVALID_STYLE if name == field else "")
        self.message.setText(message or "")
        if self.buttons is not None:
            self.buttons.button(QtWidgets.QDialogButtonBox.Ok).setEnabled(message is None)
        return message is None

    # ---- task dialog --------------------------------------------------------------------------
    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

    def modifyStandardButtons(self, buttons):
        """FreeCAD hands over the dialog's button box once it is made: OK follows the check."""
        self.buttons = buttons
        self.check()

    def accept(self):
        """Apply the values and recompute; close and commit when that works, else say why and stay."""
        if not self.check():
            return False
        obj, doc = self.obj, self.obj.Document
        for name, value in self.values().items():
            if self.field(name).isEnabled() or name in ("WallModel", "YWindow", "Forces", "Material"):
                setattr(obj, name, value)
        try:
            with busy("Computing the engagement…"):
                recompute_checked(doc, (obj,))
        except (CommandError, InputError) as error:
            report_error(error)
            self.message.setText(message_of(error))
            return False
        self.close()
        doc.commitTransaction()
        state.tell("show", obj)
        return True

    def reject(self):
        """Take everything back (a new engagement is removed) and close."""
        doc = self.obj.Document
        self.close()
        doc.abortTransaction()
        doc.recompute()
        return True

    def close(self):
        """Close the panel (leaving edit mode when it was opened by setEdit)."""
        if self in _SHOWN:
            _SHOWN.remove(self)
        gui_doc = FreeCADGui.getDocument(self.obj.Document.Name)
        if not self.new and gui_doc.getInEdit() is not None:
            gui_doc.resetEdit()  # the view provider's unsetEdit closes the dialog
        else:
            FreeCADGui.Control.closeDialog()


def compute(doc, stock, toolpath):
    """Open a transaction, add an engagement of `stock` and `toolpath` (what the toolpath file gives
    filled in) and open its task panel; the panel."""
    from ..features import create_engagement
    doc.openTransaction("Compute engagement")
    try:
        obj = create_engagement(doc, stock, toolpath)
        view_providers.attach(obj)
    except BaseException:
        doc.abortTransaction()
        raise
    return _show(EngagementPanel(obj, new=True))


def edit(obj):
    """Open the task panel of the existing engagement `obj` in a transaction; the panel."""
    doc = obj.Document
    if not doc.HasPendingTransaction:
        doc.openTransaction("Edit engagement")
    return _show(EngagementPanel(obj, new=False))


def _show(panel):
    FreeCADGui.Control.showDialog(panel)
    _SHOWN[:] = [panel]
    return panel


def _label(obj):
    return obj.Label if obj is not None else "(none)"


def _property_value(obj, name):
    value = getattr(obj, name)
    return float(getattr(value, "Value", value))


def _spin_box(unit, low, high, step, *, integer=False):
    """A Gui::QuantitySpinBox in `unit`, or a plain (integer) spin box when unit is None."""
    if unit is None:
        widget = QtWidgets.QSpinBox() if integer else QtWidgets.QDoubleSpinBox()
        if not integer:
            widget.setDecimals(1)
        widget.setRange(low, high)
        widget.setSingleStep(step)
        return widget
    widget = FreeCADGui.UiLoader().createWidget("Gui::QuantitySpinBox")
    widget.setProperty("unit", unit)
    widget.setProperty("minimum", float(low))
    widget.setProperty("maximum", float(high))
    widget.setProperty("singleStep", float(step))
    return widget


def _set_value(widget, value):
    if isinstance(widget, (QtWidgets.QSpinBox, QtWidgets.QDoubleSpinBox)):
        widget.setValue(type(widget.value())(value))
    else:
        widget.setProperty("rawValue", float(value))


def _get_value(widget):
    if isinstance(widget, (QtWidgets.QSpinBox, QtWidgets.QDoubleSpinBox)):
        return widget.value()
    return float(widget.property("rawValue"))


state.listen("edit", edit)
