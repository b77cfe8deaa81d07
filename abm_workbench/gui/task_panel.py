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

A quantity field whose text is not a quantity of its kind (letters typed into a length) is refused
in the same way: its field marked, the problem in plain words, OK disabled.

The whole edit is one document transaction: OK commits it (after a recompute that succeeds),
Cancel aborts it, which for a new engagement removes the object; for an existing one it gives
back its properties and, with them, the results it had (kept by the feature, so the recompute
after Cancel does not run the engine again) and its view.

Its widgets are looked up by name (:meth:`EngagementPanel.field`) once the wrappers that deleted
widgets left at their addresses are let go (:mod:`.wrappers`): without that, a panel opened right
after another closed was now and then refused (its field or line edit found as the old dialog's
button box).

The panel fits FreeCAD's combo view: rows too long for a label and a field side by side wrap
the field under its label, and the text wraps.
"""

import shiboken2
from PySide import QtGui

import FreeCAD
import FreeCADGui

from ..errors import InputError, ParameterError
from ..features.engagement import COEFFICIENT_PROPERTIES, MATERIAL_CHOICES, Y_WINDOWS, WALL_CHOICES, force_settings
from ..forces import MATERIALS
from ..jobs import BY_NAME, label_words, resolve, tool_and_settings
from . import preferences, state, view_providers, wrappers
from .i18n import noop, translate
from .progress import busy
from .reporting import CommandError, message_of, recompute_checked, report_error

#: Fields: (property, label, unit or None for a plain number, minimum, maximum, step).
FIELDS = (
    ("Diameter", noop("Diameter"), "mm", -1e6, 1e6, 1.0),
    ("Flutes", noop("Flutes"), None, 0, 100, 1),
    ("FluteLength", noop("Flute length"), "mm", -1e6, 1e6, 1.0),
    ("HelixAngle", noop("Helix angle β"), "deg", -1e6, 1e6, 5.0),
    ("FeedPerTooth", noop("Feed per tooth"), "mm", -1e6, 1e6, 0.01),
    ("SpindleSpeed", noop("Spindle speed (rpm)"), None, 0.0, 1e6, 100.0),
    ("Inclination", noop("Inclination α"), "deg", -1e6, 1e6, 1.0),
    ("PhiStart", noop("φ start"), "deg", -1e6, 1e6, 1.0),
    ("PhiEnd", noop("φ end"), "deg", -1e6, 1e6, 1.0),
    ("PhiStep", noop("φ step"), "deg", -1e6, 1e6, 0.5),
    ("YWindowMin", noop("y window from"), "mm", -1e6, 1e6, 1.0),
    ("YWindowMax", noop("y window to"), "mm", -1e6, 1e6, 1.0),
)
#: Force fields after the Forces check box and the Material combo: (property, label, unit, minimum, maximum, step).
FORCE_FIELDS = tuple((prop, f"{prop} ({'N/mm²' if prop.endswith('c') else 'N/mm'})", None, -1e6, 1e6, 10.0)
                     for prop in COEFFICIENT_PROPERTIES.values()) + (
    ("ImmersionStart", noop("Immersion from"), "deg", -1e6, 1e6, 5.0),
    ("ImmersionEnd", noop("Immersion to"), "deg", -1e6, 1e6, 5.0))
#: Quantity kinds of the units of FIELDS: (FreeCAD unit, the kind in words, examples).
KINDS = {"mm": ("Length", "length", "12 mm, 0.5 in"), "deg": ("Angle", "angle", "10°, 0.2 rad")}
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
        self.doc_name = obj.Document.Name
        self.buttons = None  # the task dialog's QDialogButtonBox, while FreeCAD shows it (ok_button)
        self.closed = False
        self.form = QtGui.QWidget()
        self.form.setObjectName("ABM_EngagementPanel")
        self.form.setWindowTitle(translate("Engagement: tool and cut"))
        layout = QtGui.QFormLayout(self.form)
        layout.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        layout.setFieldGrowthPolicy(QtGui.QFormLayout.AllNonFixedFieldsGrow)
        self.source = QtGui.QLabel(f"{translate('Stock')}: {_label(obj.Stock)}<br>"
                                   f"{translate('Toolpath')}: {_label(obj.Toolpath)}")
        self.source.setWordWrap(True)
        layout.addRow(self.source)
        self.message = QtGui.QLabel()  # at the top: seen whatever the panel is scrolled to
        self.message.setObjectName("ABM_Message")
        self.message.setWordWrap(True)
        self.message.setStyleSheet("color: #b00000;")
        layout.addRow(self.message)
        self.fixed = QtGui.QLabel()
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
                layout.addRow(translate("Wall model"), self._combo("WallModel", WALL_CHOICES))
                layout.addRow(translate("y window"), self._combo("YWindow", Y_WINDOWS))
            layout.addRow(translate(label), widget)
            _set_value(widget, _property_value(obj, name))
        self._force_fields(layout)
        wrappers.let_go_stale(self.form)  # before any lookup: the fields may sit where deleted widgets were
        for name, *_ in FIELDS + FORCE_FIELDS:
            _connect(self.field(name), self.check)
        self.field("SpindleSpeed").setSpecialValueText("none")
        self.hints = self._hints()
        self.check()

    def _force_fields(self, layout):
        """The Forces check box beside the Material combo, then the coefficients and the immersion."""
        obj = self.obj
        forces = QtGui.QCheckBox(translate("Cutting forces"))
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

    def _combo(self, name, choices):
        combo = QtGui.QComboBox()
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
        return self.form.findChild(QtGui.QWidget, f"ABM_{name}")

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
            if isinstance(widget, QtGui.QComboBox):
                values[name] = widget.currentText()
            elif isinstance(widget, QtGui.QCheckBox):
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

    def unreadable(self):
        """(message, field) of the first enabled quantity field whose text is not a quantity of its kind,
        or (None, None)."""
        for name, label, unit, *_ in FIELDS + FORCE_FIELDS:
            widget = self.field(name)
            if unit is None or not widget.isEnabled():
                continue
            text = widget.findChild(QtGui.QLineEdit).text().strip()
            unit_name, kind, examples = KINDS[unit]
            try:
                quantity = FreeCAD.Units.Quantity(text)
                readable = quantity.Unit in (getattr(FreeCAD.Units, unit_name), FreeCAD.Units.Unit())
            except ValueError:
                readable = False
            if not readable:
                parameter = next((p for p in BY_NAME.values() if p.prop == name), None)
                words = parameter.label if parameter is not None else label
                return (f"{words[:1].upper()}{words[1:]}: “{text}” is not a {kind}: type a number, with a unit "
                        f"if you like ({examples}).", name)
        return None, None

    def problem(self, values):
        """(message, field) of the first problem of `values`, or (None, None); marks what the file fixes."""
        if isinstance(self.hints, Exception):
            return str(self.hints), None
        message, field = self.unreadable()
        if message is not None:
            return message, field
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
        self.fixed.setText(translate("Fixed by the toolpath file, the values it was made for:") + " "
                           + ", ".join(notes) if notes else "")

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
        """Check the fields: mark the bad one, say why, enable OK only when all is well; True if valid.
        Once the panel is closed: nothing (its fields may still signal as they go), False."""
        if self.closed:
            return False
        values = self.values()
        for name in ("YWindowMin", "YWindowMax"):
            self.field(name).setEnabled(values["YWindow"] == "custom")
        self.show_material(values)
        message, field = self.problem(values)
        for name in self.names:
            self.field(name).setStyleSheet(INVALID_STYLE if name == field else "")
        self.message.setText(message or "")
        ok = self.ok_button()
        if ok is not None:
            ok.setEnabled(message is None)
        return message is None

    def ok_button(self):
        """The task dialog's OK button, or None: not made yet, or gone with the dialog (FreeCAD deletes
        the button box; a reference kept to it must not be used then)."""
        if self.buttons is None or not shiboken2.isValid(self.buttons):
            self.buttons = None
            return None
        return self.buttons.button(QtGui.QDialogButtonBox.Ok)

    # ---- task dialog --------------------------------------------------------------------------
    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def modifyStandardButtons(self, buttons):
        """FreeCAD hands over the dialog's button box once it is made: OK follows the check."""
        wrappers.let_go_stale(buttons)  # its buttons too may sit where deleted widgets were
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
        """Take everything back (a new engagement is removed) and close: the transaction is aborted before
        edit mode ends (ending it commits what is open), then the document recomputed, which gives an
        existing engagement the results it had (kept, not computed again) and its view."""
        doc, new = self.obj.Document, self.new
        obj_name = self.obj.Name
        doc.abortTransaction()
        self.close()
        doc.recompute()
        obj = None if new else doc.getObject(obj_name)
        if obj is not None:
            view_providers.refresh(obj)
            state.tell("refresh", obj)
        return True

    def close(self):
        """Close the panel (leaving edit mode when it was opened by setEdit); forget the button box."""
        self.closed, self.buttons = True, None
        if self in _SHOWN:
            _SHOWN.remove(self)
        gui_doc = FreeCADGui.getDocument(self.doc_name)
        if not self.new and gui_doc.getInEdit() is not None:
            gui_doc.resetEdit()  # the view provider's unsetEdit closes the dialog
        else:
            FreeCADGui.Control.closeDialog()


def compute(doc, stock, toolpath):
    """Open a transaction, add an engagement of `stock` and `toolpath` (what the toolpath file gives
    filled in, the rest from the preferences, :func:`.preferences.engagement_defaults`) and open its
    task panel; the panel."""
    from ..features import create_engagement
    from ..features.engagement import SETTINGS
    doc.openTransaction("Compute engagement")
    try:
        obj = create_engagement(doc, stock, toolpath)
        for key, value in preferences.engagement_defaults().items():
            prop = SETTINGS[key][0]
            if key not in preferences.REQUIRED or not _property_value(obj, prop):
                setattr(obj, prop, value)
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
        widget = QtGui.QSpinBox() if integer else QtGui.QDoubleSpinBox()
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


def _connect(widget, check):
    """Call check when the value of a field changes, and for a quantity field also when its text does
    (text that is no quantity leaves the value as it was)."""
    widget.valueChanged.connect(check)
    if not isinstance(widget, (QtGui.QSpinBox, QtGui.QDoubleSpinBox)):
        widget.findChild(QtGui.QLineEdit).textChanged.connect(check)


def _set_value(widget, value):
    if isinstance(widget, (QtGui.QSpinBox, QtGui.QDoubleSpinBox)):
        widget.setValue(type(widget.value())(value))
    else:
        widget.setProperty("rawValue", float(value))


def _get_value(widget):
    if isinstance(widget, (QtGui.QSpinBox, QtGui.QDoubleSpinBox)):
        return widget.value()
    return float(widget.property("rawValue"))


state.listen("edit", edit)
