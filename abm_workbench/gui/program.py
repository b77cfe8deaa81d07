"""The engagement dock's program row: a slider over every CL point of the whole program.

A CL file or G-code program of several operations (model test 3's ``program.apt``, a CAM Job) is read
operation by operation, and an engagement computes one of them (the toolpath's ``Operation``). The
row (:class:`ProgramRow`, shown when the engagement's toolpath comes from a program of two operations
or more) puts every cutting CL point of the program, operation after operation in the file's order, on
one slider (``ABM_ProgramSlider``), with a line (``ABM_ProgramWhere``) saying where its position is:
the program's CL point, its operation (number, name, tool) and the CL point within that operation.

- The row and the dock's CL slider and spin box are kept in step: choosing a CL point in the dock
  moves the program slider, and moving the program slider within the engagement's operation moves
  the dock's CL point at once (highlight, text, plots as for the dock's own slider).
- Moved into another operation, the dock goes there once the slider has rested :data:`SETTLE_MS`
  (a drag or held key recomputes once, where it stops; and not while an earlier recompute runs): to
  the engagement of the document that computes that operation of the same program on the same stock
  if there is one (no recompute), else the engagement's own toolpath is set to that operation and
  the engagement recomputed (one undo step "Choose operation"; the tool and cut the file gives for
  that operation are copied into the engagement, as on import). A toolpath linked to a CAM Job follows the Job's operation, so
  there the row only goes to the engagements "Engage CAM job" made. An operation the engine does not
  compute (a drill) is said, not computed.

Program CL points are 0-based like the dock's; operations without cutting moves take no place.
"""

from dataclasses import dataclass
from typing import Optional

from PySide import QtCore, QtGui

from .i18n import translate
from .progress import busy
from .reporting import CommandError, message_of, recompute_checked, report_error

#: Milliseconds the program slider must rest in another operation before the dock goes there.
SETTLE_MS = 400
#: The cutting parameters a toolpath file may give (create_engagement copies them), copied for another operation.
FILE_PARAMETERS = ("diameter", "flute_length", "corner_radius", "spindle_rpm", "flutes", "feed_per_tooth")


@dataclass(frozen=True)
class Span:
    """One operation of the program on the slider: its number (1-based), name ("" if none), tool in words,
    its cutting CL points `count`, the program CL point it starts at, and why the engine does not compute
    it (None when it does)."""

    number: int
    name: str
    tool: str
    count: int
    start: int
    refusal: Optional[str]


def spans_of(engagement):
    """(the Spans of the program of the engagement's toolpath, the number of the operation it computes);
    ((), None) for a toolpath of one operation, or one that cannot be read."""
    toolpath = getattr(engagement, "Toolpath", None)
    try:
        _, hints = toolpath.Proxy.load(toolpath)
    except Exception:  # noqa: BLE001 (the engagement's own recompute says what is wrong with its toolpath)
        return (), None
    program = hints.program
    if program is None or len(program.operations) < 2 or hints.operation is None:
        return (), None
    spans, start = [], 0
    for operation in program.operations:
        count = len(operation.lines)
        spans.append(Span(operation.number, operation.name, operation.tool.describe(), count, start,
                          operation.refusal()))
        start += count
    return tuple(spans), hints.operation.number


def locate(spans, index):
    """(Span, CL point within it) of program CL point `index` (0-based) of `spans`; ValueError outside."""
    for span in spans:
        if span.start <= index < span.start + span.count:
            return span, index - span.start
    raise ValueError(f"program CL point {index} is outside the program (0 to {total(spans) - 1})")


def total(spans):
    """The number of cutting CL points of the program of `spans`."""
    return sum(span.count for span in spans)


def where_words(spans, index):
    """Where program CL point `index` is, in words: its operation and the CL point within it."""
    span, cl = locate(spans, index)
    name = f" ({span.name})" if span.name else ""
    return translate("Program CL {index} of {count}: operation {number}{name}, {tool}, its CL {cl}",
                     index=index, count=total(spans), number=span.number, name=name, tool=span.tool, cl=cl)


def same_program(engagement, other, number):
    """True when `other` is an engagement of `engagement`'s stock computing operation `number` of the same
    program (the same file, or the same CAM Job)."""
    if getattr(getattr(other, "Proxy", None), "KIND", None) != "ABM::Engagement" or other.Stock != engagement.Stock:
        return False
    mine, theirs = engagement.Toolpath, other.Toolpath
    if theirs is None or mine.Proxy.source_name(mine) != theirs.Proxy.source_name(theirs):
        return False
    try:
        return theirs.Proxy.load(theirs)[1].operation.number == number
    except Exception:  # noqa: BLE001 (a toolpath that cannot be read computes no operation)
        return False


def take_from_file(engagement):
    """Set the engagement's cutting properties that its toolpath file gives (for the operation it now reads) to
    the file's values, as create_engagement does for a new engagement: the task panel then shows them, and
    the recompute has no value of the object to overrule."""
    from ..features.engagement import SETTINGS, given_parameters
    from ..jobs import resolve

    _, hints = engagement.Toolpath.Proxy.load(engagement.Toolpath)
    parameters = resolve(given_parameters(engagement), hints, {}, words=lambda parameter: f"the property {parameter.prop}")
    for key in FILE_PARAMETERS:
        if parameters.fixed_by_file(key):
            setattr(engagement, SETTINGS[key][0], parameters.values[key])


class ProgramRow(QtGui.QWidget):
    """The program slider and its line, in step with the dock `shown`'s CL slider and spin box (module
    docstring). :meth:`show_for` fills it for the dock's engagement."""

    def __init__(self, shown):
        super().__init__()
        self.dock = shown
        self.spans, self.number = (), None
        self.computing = False
        layout = QtGui.QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        row = QtGui.QHBoxLayout()
        row.addWidget(QtGui.QLabel(translate("Program")))
        self.slider = QtGui.QSlider(QtCore.Qt.Horizontal)
        self.slider.setObjectName("ABM_ProgramSlider")
        self.slider.setToolTip(translate("Every CL point of the whole program, operation after operation: "
                                         "moved into another operation, the dock goes there once it rests"))
        row.addWidget(self.slider, 1)
        layout.addLayout(row)
        self.where = QtGui.QLabel()
        self.where.setObjectName("ABM_ProgramWhere")
        self.where.setWordWrap(True)
        layout.addWidget(self.where)
        self.timer = QtCore.QTimer(self)
        self.timer.setSingleShot(True)
        self.timer.setInterval(SETTLE_MS)
        self.timer.timeout.connect(self.settle)
        self.slider.valueChanged.connect(self.moved)
        shown.spin.valueChanged.connect(self.follow)
        self.hide()

    def show_for(self, engagement, cl):
        """Fill the row for `engagement` at its CL point `cl`; hidden when its toolpath holds one operation."""
        self.spans, self.number = spans_of(engagement) if engagement is not None else ((), None)
        if not self.spans or total(self.spans) == 0:
            self.spans = ()
            self.hide()
            return
        self.slider.blockSignals(True)
        self.slider.setRange(0, total(self.spans) - 1)
        self.slider.blockSignals(False)
        self.show()
        self.follow(cl)

    def follow(self, cl):
        """The dock's CL point changed to `cl`: the program slider to the same CL point, its line."""
        if not self.spans:
            return
        span = next(span for span in self.spans if span.number == self.number)
        if not 0 <= cl < span.count:
            return
        self.timer.stop()
        self.slider.blockSignals(True)
        self.slider.setValue(span.start + cl)
        self.slider.blockSignals(False)
        self.where.setText(where_words(self.spans, span.start + cl))

    def moved(self, index):
        """The program slider moved to `index`: within the engagement's operation the dock follows at once;
        in another, once the slider rests (:meth:`settle`)."""
        span, cl = locate(self.spans, index)
        words = where_words(self.spans, index)
        if span.number == self.number:
            self.timer.stop()
            self.where.setText(words)
            self.dock.spin.setValue(cl)
            return
        self.where.setText(words + "; " + (translate("not computed: {reason}", reason=span.refusal)
                                           if span.refusal else translate("going there once the slider rests…")))
        self.timer.start()

    def settle(self):
        """The slider has rested in another operation: the dock goes there (module docstring)."""
        if self.computing:  # an earlier recompute still runs: look again once it is done
            self.timer.start()
            return
        span, cl = locate(self.spans, self.slider.value())
        if span.number == self.number or span.refusal:
            return
        try:
            self.go_to(span.number, cl)
        except Exception as error:  # noqa: BLE001 (reported; the dock stays on its engagement)
            report_error(error)
            self.where.setText(where_words(self.spans, self.slider.value()) + "; "
                               + translate("not shown: {reason}", reason=message_of(error)))

    def go_to(self, number, cl):
        """Show CL point `cl` of operation `number` in the dock: its engagement, else the dock's engagement
        recomputed for it (CommandError when neither can be)."""
        engagement = self.dock.obj
        doc = engagement.Document
        for other in doc.Objects:
            if other is not engagement and same_program(engagement, other, number):
                self.dock.show_object(other, cl)
                return
        toolpath = engagement.Toolpath
        if toolpath.CamJob is not None:
            raise CommandError(translate("no engagement of operation {number} of {job}: select the Job and use "
                                         "Engage CAM job", number=number, job=toolpath.CamJob.Label))
        self.computing = True
        doc.openTransaction(translate("Choose operation"))
        try:
            toolpath.Operation = number
            take_from_file(engagement)
            with busy(translate("Computing operation {number} of the program…", number=number)):
                recompute_checked(doc, (toolpath, engagement))
        except BaseException:
            doc.abortTransaction()
            doc.recompute()
            raise
        else:
            doc.commitTransaction()
        finally:
            self.computing = False
        self.dock.show_object(engagement, cl)
