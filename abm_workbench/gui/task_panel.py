"""The task panel of an engagement object: tool, cut, wall model, y window and forces, checked as typed.

Opened by ABM_ComputeEngagement for a new engagement (:func:`compute`) and by double-click /
``setEdit`` for an existing one (:func:`edit`). Every number is a :class:`NumberField`: the text
typed is the value, read in the field's declared unit (mm, degrees, or a plain number: flutes,
rpm, N/mm², N/mm) by :mod:`.numbers`. A bare number is in that unit whatever was shown before; a
length or an angle may carry its own unit ("0.5 in", "0.2 rad"). Values are shown in the declared
unit ("0.08 mm", never "80 µm"); no key is refused and nothing is clamped, rounded or re-scaled.
A required value that is not set shows an empty field; the spindle speed shows "none" (typed:
"none" or 0).

As the user types, the values are checked by the job model, as the command line's are:
``jobs.resolve`` (every value against its declaration in ``jobs.parameters``; what an APT / CL
toolpath file gives wins; a missing required value), ``jobs.tool_and_settings`` (with the helix
angle), the cutting-force settings (on / off, material or custom coefficients, immersion) by
``features.engagement.force_settings``, and the y window as ``features.engagement.y_window``
checks it. A problem is a ParameterError naming its parameter: the parameter's field is marked
(its declared property) and the problem shown at the top of the panel in plain words
(``reporting.parameter_words``), and OK is disabled. The coefficient fields show the material's values,
read-only, unless the material is custom. Fields the toolpath file fixes show its value, are
read-only and say so.

A field whose text is not a number of its kind (letters typed into a length, "12,5" where the
decimal point is ".", 1e400, 1e-400) or is empty is refused in the same way: its field marked, the
problem in plain words, OK disabled. A value outside the range the job model declares for its
parameter gets the parameter's own message; the fields' arrows step only within that range.

The whole edit is one document transaction: OK commits it (after a recompute that succeeds),
Cancel aborts it, which for a new engagement removes the object; for an existing one it gives
back its properties and, with them, the results it had (kept by the feature, so the recompute
after Cancel does not run the engine again) and its view.

Its widgets are looked up by name (:meth:`EngagementPanel.field`) once the wrappers that deleted
widgets left at their addresses are let go (:mod:`.wrappers`): without that, a panel opened right
after another closed was now and then refused (its field or line edit found as the old dialog's
button box). The panel reads and writes the fields by their text only, through Qt's own methods.

Scripts and tests set a field as if typed with :meth:`EngagementPanel.set_number` and read it with
:meth:`EngagementPanel.number`.

The panel is in sections that fold (:class:`Section`): tool, cut, the angles φ (side by side),
stock model (wall model and y window; folded while they are the defaults) and cutting forces
(folded while off; the coefficients three a row). The section of a field marked as wrong unfolds.
All unfolded, the panel fits a screen 1000 pixels high beside OK and Cancel. The mouse wheel
changes a field or a choice only once it has the focus, so the wheel scrolls the panel over them.
The panel fits FreeCAD's combo view: rows too long for a label and a field side by side wrap
the field under its label, and the text wraps.
"""

import shiboken2
from PySide import QtCore, QtGui

import FreeCADGui

from ..errors import InputError, MissingParameter, ParameterError
from ..features.engagement import COEFFICIENT_PROPERTIES, MATERIAL_CHOICES, Y_WINDOWS, WALL_CHOICES, force_settings
from ..forces import MATERIALS
from ..jobs import BY_NAME, CUTTING, REQUIRED, resolve, tool_and_settings
from . import numbers, preferences, state, view_providers, wrappers
from .i18n import PARAMETERS, noop, translate
from .progress import busy
from .reporting import CommandError, message_of, parameter_words, recompute_checked, report_error

#: Number fields: (property, label, declared unit: "mm", "deg" or None for a plain number, step of the arrows).
FIELDS = (
    ("Diameter", noop("Diameter"), "mm", 1.0),
    ("Flutes", noop("Flutes"), None, 1.0),
    ("FluteLength", noop("Flute length"), "mm", 1.0),
    ("CornerRadius", noop("Corner radius"), "mm", 0.5),
    ("HelixAngle", noop("Helix angle β"), "deg", 5.0),
    ("FeedPerTooth", noop("Feed per tooth"), "mm", 0.01),
    ("SpindleSpeed", noop("Spindle speed (rpm)"), None, 100.0),
    ("Inclination", noop("Inclination α"), "deg", 1.0),
    ("PhiStart", noop("φ start"), "deg", 1.0),
    ("PhiEnd", noop("φ end"), "deg", 1.0),
    ("PhiStep", noop("φ step"), "deg", 0.5),
    ("YWindowMin", noop("y window from"), "mm", 1.0),
    ("YWindowMax", noop("y window to"), "mm", 1.0),
)
#: Number fields after the Forces check box and the Material combo: (property, label, unit, step).
FORCE_FIELDS = tuple((prop, f"{prop} ({'N/mm²' if prop.endswith('c') else 'N/mm'})", None, 10.0)
                     for prop in COEFFICIENT_PROPERTIES.values()) + (
    ("ImmersionStart", noop("Immersion from"), "deg", 5.0),
    ("ImmersionEnd", noop("Immersion to"), "deg", 5.0))
#: Sections of the panel, top to bottom: (name, title, number fields); the stock model's section also holds the
#: wall model and y window, the forces' the Forces check box, the material and the coefficients.
SECTIONS = (
    ("tool", noop("Tool"), ("Diameter", "Flutes", "FluteLength", "CornerRadius", "HelixAngle")),
    ("cut", noop("Cut"), ("FeedPerTooth", "SpindleSpeed", "Inclination")),
    ("angles", noop("Tool rotation angles φ"), ("PhiStart", "PhiEnd", "PhiStep")),
    ("stock", noop("Stock model"), ("YWindowMin", "YWindowMax")),
    ("forces", noop("Cutting forces"), ()),
)
#: property -> (label, unit, step) of each number field.
FIELD_OF = {name: (label, unit, step) for name, label, unit, step in FIELDS + FORCE_FIELDS}
#: property -> declared unit of every number field.
UNITS = {name: unit for name, _, unit, _ in FIELDS + FORCE_FIELDS}
#: property -> the job model's Parameter of a field (its label, range and check); the y window has none.
PARAMETER_OF = {parameter.prop: parameter for parameter in BY_NAME.values()}
#: Fields of required parameters: empty means not given (no default to fall back on).
REQUIRED_FIELDS = tuple(parameter.prop for parameter in BY_NAME.values() if parameter.default is REQUIRED)
#: The spindle speed's text for no speed (its property 0).
NONE = "none"
#: The angles (°) an App::PropertyAngle holds: FreeCAD clamps any other to this range, in silence.
ANGLE_PROPERTY_RANGE = (-360.0, 360.0)
#: Cutting parameters a toolpath file can fix, with their fields.
FILE_FIELDS = ("diameter", "flute_length", "corner_radius", "spindle_rpm", "feed_per_tooth")
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
        layout = QtGui.QVBoxLayout(self.form)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.setSpacing(2)
        self.source = QtGui.QLabel(f"{translate('Stock')}: {_label(obj.Stock)}<br>"
                                   f"{translate('Toolpath')}: {_label(obj.Toolpath)}")
        self.source.setWordWrap(True)
        layout.addWidget(self.source)
        self.message = _Note()  # at the top: seen whatever the panel is scrolled to
        self.message.setObjectName("ABM_Message")
        self.message.setWordWrap(True)
        self.message.setStyleSheet("color: #b00000;")
        layout.addWidget(self.message)
        self.fixed = _Note()
        self.fixed.setObjectName("ABM_Fixed")
        self.fixed.setWordWrap(True)
        layout.addWidget(self.fixed)
        self.names = []  # of the fields, in order: self.field(name) finds each
        self.sections = {}  # section name -> Section
        self.section_of = {}  # field name -> section name
        for section, title, names in SECTIONS:
            box = Section(section, translate(title), self.form)
            self.sections[section] = box
            layout.addWidget(box)
            if section == "stock":
                box.rows.addRow(translate("Wall model"), self._combo("WallModel", WALL_CHOICES))
                box.rows.addRow(translate("y window"), self._combo("YWindow", Y_WINDOWS))
            if section == "forces":
                self._force_fields(box)
            for name in names:
                label, unit, step = FIELD_OF[name]
                widget = _spin_box(unit, step, PARAMETER_OF.get(name), self.form)
                widget.setObjectName(f"ABM_{name}")
                widget.setToolTip(_tip(obj, name))
                self.names.append(name)
                if section == "angles":
                    box.grid(label, widget)
                else:
                    box.rows.addRow(translate(label), widget)
            for name in self.names:
                self.section_of.setdefault(name, section)
        layout.addStretch(1)
        self.sections["stock"].fold(obj.WallModel == "stock" and obj.YWindow == "auto")
        self.sections["forces"].fold(not obj.Forces)
        wrappers.let_go_stale(self.form)  # before any lookup: the fields may sit where deleted widgets were
        for name in UNITS:
            _put(self.field(name), _starting_text(obj, name))
            self.field(name).findChild(QtGui.QLineEdit).textChanged.connect(self.check)
        self.hints = self._hints()
        self.check()

    def _force_fields(self, box):
        """The Forces check box beside the Material combo, then the coefficients (three a row, each label above
        its field, the unit under the name: narrow enough for the combo view) and the immersion, into the section `box`."""
        obj = self.obj
        forces = QtGui.QCheckBox(translate("Cutting forces"))
        forces.setObjectName("ABM_Forces")
        forces.setChecked(bool(obj.Forces))
        forces.setToolTip(_tip(obj, "Forces"))
        forces.toggled.connect(self.check)
        self.names.append("Forces")
        box.rows.addRow(forces, self._combo("Material", MATERIAL_CHOICES))
        grid = QtGui.QGridLayout()
        grid.setContentsMargins(0, 0, 0, 0)
        grid.setVerticalSpacing(0)
        for index, (name, label, unit, step) in enumerate(FORCE_FIELDS[:6]):
            widget = _spin_box(unit, step, PARAMETER_OF.get(name), self.form)
            widget.setObjectName(f"ABM_{name}")
            widget.setToolTip(_tip(obj, name))
            self.names.append(name)
            row, column = 2 * (index // 3), index % 3
            grid.addWidget(QtGui.QLabel(label.replace(" (", "\n(")), row, column)  # the unit under the name
            grid.addWidget(widget, row + 1, column)
        box.rows.addRow(grid)
        for name, label, unit, step in FORCE_FIELDS[6:]:
            widget = _spin_box(unit, step, PARAMETER_OF.get(name), self.form)
            widget.setObjectName(f"ABM_{name}")
            widget.setToolTip(_tip(obj, name))
            self.names.append(name)
            box.rows.addRow(translate(label), widget)

    def _combo(self, name, choices):
        combo = Combo()
        combo.setObjectName(f"ABM_{name}")
        combo.addItems(list(choices))
        combo.setCurrentIndex(list(choices).index(getattr(self.obj, name)))
        combo.setToolTip(_tip(self.obj, name))
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
    def number(self, name):
        """The number typed into field `name`, in its declared unit (the spindle speed's "none": 0), or None
        when the field is empty; numbers.Unreadable when it is no number of its kind."""
        return _number(name, self.field(name).text())

    def set_number(self, name, value):
        """Show `value` (declared unit; a spindle speed of 0: "none") in field `name` as if it were typed:
        the panel checks it."""
        _put(self.field(name), _text(name, value))

    def values(self):
        """{property: value} of the fields: numbers in their declared units (mm, deg, rpm, N/mm², N/mm;
        None when empty or unreadable, see :meth:`unreadable`), choices as text, Forces as a bool."""
        values = {}
        for name in self.names:
            widget = self.field(name)
            if isinstance(widget, QtGui.QComboBox):
                values[name] = widget.currentText()
            elif isinstance(widget, QtGui.QCheckBox):
                values[name] = widget.isChecked()
            else:
                try:
                    values[name] = self.number(name)
                except numbers.Unreadable:
                    values[name] = None
        return values

    @staticmethod
    def given(values):
        """jobs.resolve's `given` of the field values (an empty field and a spindle speed of none: not given)."""
        given = {name: values[BY_NAME[name].prop] for name in CUTTING}
        if given["spindle_rpm"] == 0:
            given["spindle_rpm"] = None
        return given

    def unreadable(self):
        """(message, field) of the first enabled number field whose text is no number of its kind, or that
        is empty and not a required one (those are missing: :meth:`problem`); or (None, None)."""
        for name, label, unit, _ in FIELDS + FORCE_FIELDS:
            if not self.field(name).isEnabled():
                continue
            try:
                number = self.number(name)
            except numbers.Unreadable as error:
                return f"{_words(name, label)}: {error}.", name
            if number is None and name not in REQUIRED_FIELDS:
                return translate("{field}: the field is empty: {hint}.", field=_words(name, label),
                                 hint=numbers.hint(unit)), name
        return None, None

    def problem(self, values):
        """(message, field) of the first problem of `values`, or (None, None); marks what the file fixes."""
        if isinstance(self.hints, Exception):
            return message_of(self.hints), None
        message, field = self.unreadable()
        if message is not None:
            return message, field
        try:
            parameters = resolve(self.given(values), self.hints, {}, words=lambda parameter: f"the property {parameter.prop}")
            self.show_fixed(parameters)
            tool_and_settings(parameters.values, values["HelixAngle"])
            if values["Forces"]:
                force_settings(values["Material"], values, (values["ImmersionStart"], values["ImmersionEnd"]))
        except MissingParameter as error:  # only an empty field leaves a required value missing here
            prop = BY_NAME[error.field].prop
            return translate("{field} is required: the field is empty.", field=_words(prop, prop)), prop
        except ParameterError as error:
            parameter = BY_NAME.get(error.field)
            return parameter_words(error), parameter.prop if parameter is not None else None
        message, field = self.unheld(values)
        if message is not None:
            return message, field
        stock = self.obj.Stock
        solid = stock is not None and stock.Proxy.is_solid(stock)
        if values["WallModel"] != "stock" and not solid:
            return (translate("The wall model {model} applies to a solid stock (STEP, BREP or FCStd), not to "
                              "{stock}.", model=values["WallModel"], stock=stock.Proxy.source_name(stock)), "WallModel")
        if values["YWindow"] in ("swept", "custom") and not solid:
            return (translate("The y window {window} applies to a solid stock (STEP, BREP or FCStd), not to "
                              "{stock}.", window=values["YWindow"], stock=stock.Proxy.source_name(stock)), "YWindow")
        if values["YWindow"] == "custom" and not values["YWindowMin"] < values["YWindowMax"]:
            return (translate("The y window must start below its end: {start} mm to {end} mm.",
                              start=f"{values['YWindowMin']:g}", end=f"{values['YWindowMax']:g}"), "YWindowMin")
        return None, None

    def unheld(self, values):
        """(message, field) of the first enabled angle field whose value the job model allows but the engagement
        object's angle property cannot hold (beyond ANGLE_PROPERTY_RANGE: φ start, end and step), or (None, None)."""
        low, high = ANGLE_PROPERTY_RANGE
        for name, label, unit, _ in FIELDS + FORCE_FIELDS:
            if unit == "deg" and self.field(name).isEnabled() and not low <= values[name] <= high:
                return (translate("{field}: the engagement object holds angles within [{low}, {high}]°, got "
                                  "{value}°.", field=_words(name, label), low=f"{low:g}", high=f"{high:g}",
                                  value=f"{values[name]:g}"), name)
        return None, None

    def show_fixed(self, parameters):
        """Fields whose value the toolpath file gives: its value, read-only, explained."""
        notes = []
        for key in FILE_FIELDS:
            name = BY_NAME[key].prop
            widget = self.field(name)
            fixed = parameters.fixed_by_file(key)
            if fixed:
                _put(widget, _text(name, parameters.values[key]), quiet=True)
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
                values[prop] = getattr(MATERIALS[values["Material"]][0], name)
                _put(widget, _text(prop, values[prop]), quiet=True)
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
        if field in self.section_of:  # the marked field in view
            self.sections[self.section_of[field]].fold(False)
        if values["Forces"]:
            self.sections["forces"].fold(False)
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
                setattr(obj, name, int(value) if name == "Flutes" else value)
        try:
            with busy(translate("Computing the engagement…")):
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


def _tip(obj, name):
    """The tooltip of field `name`: its property's documentation, in the GUI's words (no command-line options)."""
    from .reporting import gui_words

    return gui_words(obj.getDocumentationOfProperty(name))


class Section(QtGui.QWidget):
    """A titled part of the panel that folds: a header button (an arrow and the title) over its rows
    (``rows``, a QFormLayout; ``grid`` puts fields side by side, each label above its field).

    The header is the arrow button (``header``, its text the title, not drawn) beside the title as a label
    that wraps and folds the section when clicked too: a long title never makes the panel wider than the
    combo view (a button's text cannot wrap, and the narrow combo view then clips the fields' right edge)."""

    def __init__(self, name, title, parent):
        super().__init__(parent)
        self.setObjectName(f"ABM_Section_{name}")
        layout = QtGui.QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        self.header = QtGui.QToolButton()
        self.header.setObjectName(f"ABM_SectionHeader_{name}")
        self.header.setText(title)
        self.header.setToolTip(title)
        self.header.setToolButtonStyle(QtCore.Qt.ToolButtonIconOnly)
        self.header.setAutoRaise(True)
        self.header.setCheckable(True)
        self.header.setChecked(True)
        self.header.setStyleSheet("QToolButton { border: none; }")
        self.header.toggled.connect(self._toggled)
        self.title = _Title(f"<b>{title}</b>", self.header)
        self.title.setObjectName(f"ABM_SectionTitle_{name}")
        row = QtGui.QHBoxLayout()
        row.setContentsMargins(0, 0, 0, 0)
        row.setSpacing(2)
        row.addWidget(self.header)
        row.addWidget(self.title, 1)
        layout.addLayout(row)
        self.body = QtGui.QWidget()
        self.rows = QtGui.QFormLayout(self.body)
        self.rows.setContentsMargins(12, 0, 0, 4)
        self.rows.setVerticalSpacing(2)
        self.rows.setRowWrapPolicy(QtGui.QFormLayout.WrapLongRows)
        self.rows.setFieldGrowthPolicy(QtGui.QFormLayout.AllNonFixedFieldsGrow)
        self._grid = None
        layout.addWidget(self.body)
        self._toggled(True)

    def grid(self, label, widget):
        """Put `widget` beside the fields before it, its `label` above it."""
        if self._grid is None:
            self._grid = QtGui.QGridLayout()
            self._grid.setContentsMargins(0, 0, 0, 0)
            self._grid.setVerticalSpacing(0)
            self.rows.addRow(self._grid)
        column = self._grid.columnCount() if self._grid.count() else 0
        self._grid.addWidget(QtGui.QLabel(translate(label)), 0, column)
        self._grid.addWidget(widget, 1, column)

    def fold(self, folded):
        """Fold the section (only its header shown) or unfold it."""
        self.header.setChecked(not folded)

    def folded(self):
        return not self.header.isChecked()

    def _toggled(self, shown):
        self.header.setArrowType(QtCore.Qt.DownArrow if shown else QtCore.Qt.RightArrow)
        self.body.setVisible(shown)


class _Note(QtGui.QLabel):
    """A label shown only while it has text: the empty message and note take no room above the fields
    (all sections unfolded, the panel then fits a 1000-pixel screen with its labels wrapped)."""

    def __init__(self):
        super().__init__()
        self.setVisible(False)

    def setText(self, text):  # noqa: N802 (Qt's name)
        super().setText(text)
        self.setVisible(bool(text))


class _Title(QtGui.QLabel):
    """A section's title: wraps, and a click on it folds or unfolds the section as its arrow `button` does."""

    def __init__(self, text, button):
        super().__init__(text)
        self.button = button
        self.setWordWrap(True)
        self.setSizePolicy(QtGui.QSizePolicy.Expanding, QtGui.QSizePolicy.Preferred)

    def mousePressEvent(self, event):  # noqa: N802 (Qt's name)
        if event.button() == QtCore.Qt.LeftButton:
            self.button.toggle()
        event.accept()


class Combo(QtGui.QComboBox):
    """A combo box that the mouse wheel changes only once it has the focus (clicked or tabbed to): a wheel
    turned over it while the panel scrolls goes on scrolling the panel."""

    def __init__(self, *args):
        super().__init__(*args)
        self.setFocusPolicy(QtCore.Qt.StrongFocus)

    def wheelEvent(self, event):  # noqa: N802 (Qt's name)
        if self.hasFocus():
            super().wheelEvent(event)
        else:
            event.ignore()


def _property_value(obj, name):
    value = getattr(obj, name)
    return float(getattr(value, "Value", value))


def _words(name, label):
    """The field `name` in messages: its parameter's label ('Tool diameter'), else its own `label`."""
    parameter = PARAMETER_OF.get(name)
    words = translate(parameter.label, PARAMETERS) if parameter is not None else translate(label)
    return f"{words[:1].upper()}{words[1:]}"


def _number(name, typed):
    """The number `typed` into field `name`, in its declared unit (the spindle speed's "none": 0), or None
    when it is empty; numbers.Unreadable when it is no number of its kind."""
    if name == "SpindleSpeed" and typed.strip().lower() == NONE:
        return 0.0
    return numbers.read(typed, UNITS[name], numbers.decimal_point())


def _text(name, value):
    """`value` as field `name` shows it, in its declared unit (a spindle speed of 0: "none")."""
    if name == "SpindleSpeed" and value == 0:
        return NONE
    return numbers.text(value, UNITS[name], numbers.decimal_point())


def _starting_text(obj, name):
    """What field `name` shows first: the property of `obj`, empty for a required value not set (0)."""
    value = _property_value(obj, name)
    return "" if value == 0 and name in REQUIRED_FIELDS else _text(name, value)


def _put(widget, text, *, quiet=False):
    """Put `text` in the number field `widget` (as typed: checked, unless `quiet`)."""
    edit = widget.findChild(QtGui.QLineEdit)
    if edit.text() == text:
        return
    edit.blockSignals(quiet)
    edit.setText(text)
    edit.blockSignals(False)


def _spin_box(unit, step, parameter, parent):
    """A NumberField in the declared `unit` ("mm", "deg", None: a plain number), stepped by `step` within
    the range of `parameter` (None: any), a child of `parent` from the start: Qt deletes it with its parent,
    never Python with a wrapper of it."""
    return NumberField(unit, step, parameter, parent)


class NumberField(QtGui.QAbstractSpinBox):
    """A field holding one number as typed (:mod:`.numbers`): no key refused, nothing clamped, rounded or
    shown in another unit. Its arrows, arrow keys and wheel step it by `step` (declared `unit`) while it
    stays inside the range the job model declares for `parameter` (None: any number)."""

    def __init__(self, unit, step, parameter, parent):
        super().__init__(parent)
        self.unit, self.step, self.parameter = unit, step, parameter
        self.setFocusPolicy(QtCore.Qt.StrongFocus)

    def wheelEvent(self, event):  # noqa: N802 (Qt's name)
        """The wheel steps the field only once it has the focus; otherwise the panel scrolls on."""
        if self.hasFocus():
            super().wheelEvent(event)
        else:
            event.ignore()

    def stepped(self, steps):
        """The number `steps` steps on (to 9 decimals: 0.11, not 0.11000000000000001), or None: no number
        typed, or the step leaves the parameter's range (or, for an angle, ANGLE_PROPERTY_RANGE)."""
        try:
            value = numbers.read(self.text(), self.unit, numbers.decimal_point())
        except numbers.Unreadable:
            return None
        if value is None:
            return None
        value = round(value + steps * self.step, 9)
        low, high = ANGLE_PROPERTY_RANGE
        if self.unit == "deg" and not low <= value <= high:
            return None
        if self.parameter is not None:
            try:
                self.parameter.check(value)
            except ParameterError:
                return None
        return value

    def stepEnabled(self):  # noqa: N802 (Qt's name)
        """Up and down, each while its step stays inside the range; neither when read-only."""
        enabled = QtGui.QAbstractSpinBox.StepNone
        if not self.isReadOnly():
            if self.stepped(1) is not None:
                enabled |= QtGui.QAbstractSpinBox.StepUpEnabled
            if self.stepped(-1) is not None:
                enabled |= QtGui.QAbstractSpinBox.StepDownEnabled
        return enabled

    def stepBy(self, steps):  # noqa: N802 (Qt's name)
        """Step the number `steps` steps on, if it stays inside the range (as if typed: checked)."""
        value = self.stepped(steps)
        if value is not None:
            _put(self, numbers.text(value, self.unit, numbers.decimal_point()))


state.listen("edit", edit)
