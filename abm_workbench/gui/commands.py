"""The ABM commands: one class each, sharing :class:`Command`; registered by :func:`register`.

``Name = "ABM_<Verb><Noun>"`` is also the icon's name (``resources/icons/<Name>.svg``). Every
action runs inside a document transaction (``openTransaction`` / ``commitTransaction``), so
one undo takes it back. A failure aborts the transaction (the document is left as it was) and
prints its message in plain words to the report view (``FreeCAD.Console.PrintError``; a bad
parameter in its label's words, ``jobs.label_words``); objects that a recompute marks invalid
count as failures, with their status string as the message.

The work of each command is ``execute(*args)`` (errors reported) or ``run(*args)`` (errors
raised), with the dialog's answer as an argument, so it can be driven without a dialog (the
GUI tests do: ``ImportStock().execute(path)``).
"""

import os

import FreeCAD
import FreeCADGui

from . import dock, task_panel, view_providers  # noqa: F401 (the dock and task panel listen to gui.state)
from . import preferences
from .i18n import QT_TRANSLATE_NOOP, noop, translate
from .progress import ProgressDialog, busy
from .reporting import PROG, CommandError, recompute_checked, report_error

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MODEL_TEST_1 = os.path.join(ROOT, "resources", "models", "model_test_1")
STOCK_FILTER = "Stock (*.step *.stp *.brep *.brp *.FCStd *.json);;All files (*)"
TOOLPATH_FILTER = ("Toolpath (*.csv *.apt *.cls *.ngc *.nc *.gcode *.tap *.FCStd);;CL file (*.apt *.cls *.cl);;"
                   "G-code (*.ngc *.nc *.gcode *.tap);;FreeCAD CAM Job (*.FCStd);;All files (*)")


def load_settings(path):
    """Cutting parameters of a job.json as create_engagement's keywords (flutes an int)."""
    from ..jobs import load_job

    job = load_job(path)
    job.pop("description", None)
    if "flutes" in job:
        job["flutes"] = int(round(job["flutes"]))
    return job


def fit_view():
    """Fit the active 3D view to everything, isometric (no view: nothing)."""
    gui_doc = FreeCADGui.ActiveDocument
    view = getattr(gui_doc, "ActiveView", None) if gui_doc else None
    if view is not None and hasattr(view, "fitAll"):
        view.viewIsometric()
        view.fitAll()


class Command:
    """Base of the ABM commands: resources from Name, the transaction, errors to the report view.

    Subclasses set Name, MenuText, ToolTip and implement ``activated(doc)``, which returns what
    it made; ``document()`` gives the document to work in.
    """

    Name = "ABM"
    MenuText = ""
    ToolTip = ""
    Accel = ""
    needs_document = True

    def GetResources(self):
        return {"Pixmap": view_providers.icon(self.Name + ".svg"), "MenuText": self.MenuText, "ToolTip": self.ToolTip,
                "Accel": self.Accel}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None or not self.needs_document

    def document(self):
        """The document to work in: the active one, or a new one when there is none."""
        return FreeCAD.ActiveDocument or FreeCAD.newDocument()

    def Activated(self):
        self.execute()

    def execute(self, *args):
        """run(*args), errors to the report view; what was made, or None after an error."""
        try:
            return self.run(*args)
        except Exception as error:  # noqa: BLE001 (reported; the GUI goes on)
            report_error(error)
            return None

    def run(self, *args):
        """Do the action inside a transaction of the document; re-raise errors after aborting it."""
        doc = self.document()
        doc.openTransaction(self.MenuText)
        try:
            made = self.activated(doc, *args)
        except BaseException:
            doc.abortTransaction()
            doc.recompute()
            raise
        doc.commitTransaction()
        return made


class OpenModelTest(Command):
    """Model test 1 in one click: STEP stock (exact walls), toolpath, engagement with job.json."""

    Name = "ABM_OpenModelTest"
    MenuText = QT_TRANSLATE_NOOP("ABM_OpenModelTest", "Open model test 1")
    ToolTip = QT_TRANSLATE_NOOP("ABM_OpenModelTest",
                                "New document with model test 1 (after Hendriko 2020): the STEP stock with exact "
                                "walls, the toolpath and the engagement with job.json's tool and cut, computed")
    Accel = "A, O"
    needs_document = False

    def document(self):
        return FreeCAD.newDocument("ModelTest1")

    def activated(self, doc, folder=MODEL_TEST_1):
        from ..features import create_engagement, create_stock, create_toolpath

        job = load_settings(os.path.join(folder, "job.json"))
        stock = create_stock(doc, os.path.join(folder, "stock.step"), walls="exact")
        toolpath = create_toolpath(doc, os.path.join(folder, "toolpath.csv"))
        engagement = create_engagement(doc, stock, toolpath, **job)
        for obj in (stock, toolpath, engagement):
            view_providers.attach(obj)
        with busy(translate("Computing model test 1…")):
            recompute_checked(doc, (stock, toolpath, engagement))
        fit_view()
        dock.show(engagement)
        return stock, toolpath, engagement


class _ImportFile(Command):
    """Base of the import commands: a file dialog, then the object made by ``create(doc, path)``
    (a features factory), shown and recomputed."""

    FILTER = ""
    TITLE = ""

    needs_document = False

    def Activated(self):
        from PySide import QtGui

        path, _ = QtGui.QFileDialog.getOpenFileName(FreeCADGui.getMainWindow(), translate(self.TITLE), "",
                                                    self.FILTER)
        if path:
            self.execute(path)

    def activated(self, doc, source, *options):
        made = self.create(doc, source, *options)
        made.Proxy.load(made)  # bad input refused in words before the recompute (the long reading in a worker)
        view_providers.attach(made)
        recompute_checked(doc, (made,))
        fit_view()
        return made


class ImportStock(_ImportFile):
    """A stock from the selected solid of the document, else a STEP / BREP / FCStd solid or a
    staircase JSON chosen in a file dialog."""

    Name = "ABM_ImportStock"
    MenuText = QT_TRANSLATE_NOOP("ABM_ImportStock", "Import stock…")
    ToolTip = QT_TRANSLATE_NOOP("ABM_ImportStock",
                                "Add a staircase stock from the selected solid, or from a STEP, BREP or FCStd solid "
                                "(recognised, exact walls) or a staircase JSON")
    Accel = "A, S"
    TITLE = noop("Import stock")
    FILTER = STOCK_FILTER

    def Activated(self):
        doc = FreeCAD.ActiveDocument
        solids = [obj for obj in FreeCADGui.Selection.getSelection(doc.Name) if is_solid_object(obj)] if doc else []
        if len(solids) == 1:
            self.execute(solids[0])
        else:
            super().Activated()

    @staticmethod
    def create(doc, source):
        """The stock object of `source`: a file path or a document object with a solid."""
        from ..features import create_stock

        return create_stock(doc, source)


def is_solid_object(obj):
    """True for a document object (not an ABM one) whose Shape holds a solid."""
    shape = getattr(obj, "Shape", None)
    return view_providers.kind(obj) is None and shape is not None and not shape.isNull() and bool(shape.Solids)


class ImportToolpath(_ImportFile):
    """A toolpath from the selected FreeCAD CAM Job (or one of its operations), else from a file: CSV, APT /
    CL, G-code, or an FCStd holding a CAM Job."""

    Name = "ABM_ImportToolpath"
    MenuText = QT_TRANSLATE_NOOP("ABM_ImportToolpath", "Import toolpath…")
    ToolTip = QT_TRANSLATE_NOOP("ABM_ImportToolpath",
                                "Add a toolpath from the selected CAM Job or operation, or from a CSV "
                                "(x,y,z,theta_a,theta_b or x,y,z,i,j,k), an APT / CL file, G-code or an FCStd "
                                "holding a CAM Job")
    Accel = "A, T"
    TITLE = noop("Import toolpath")
    FILTER = TOOLPATH_FILTER

    def Activated(self):
        from PySide import QtGui

        from ..cam.freecad_cam import job_of

        doc = FreeCAD.ActiveDocument
        selected = [obj for obj in FreeCADGui.Selection.getSelection(doc.Name) if job_of(obj)] if doc else []
        if selected:
            self.execute(selected[0])
            return
        path, _ = QtGui.QFileDialog.getOpenFileName(FreeCADGui.getMainWindow(), translate(self.TITLE), "",
                                                    self.FILTER)
        if not path:
            return
        try:
            options = ask_toolpath_options(path)
        except Exception as error:  # noqa: BLE001 (reported; the GUI goes on)
            report_error(error)
            return
        if options is not None:
            self.execute(path, *options)

    @staticmethod
    def create(doc, source, operation=0, tool_table="", units=None):
        """The toolpath object of `source`: a file path (its `operation`, 1-based, 0: its one milling
        operation; a G-code program's `tool_table` and the `units` of its lengths, "mm" or "inch", None
        not said), or a CAM Job or operation of the document."""
        from ..cam.freecad_cam import is_job, job_of
        from ..features import create_toolpath

        if isinstance(source, (str, os.PathLike)):
            return create_toolpath(doc, source, operation=int(operation), tool_table=tool_table,
                                   tool_table_units=units or "not said")
        job = job_of(source)
        return create_toolpath(doc, cam_job=job, cam_operation=None if is_job(source) else source)


def toolpath_needs(path, tool_table="", units=None):
    """What reading the toolpath file `path` needs from the user: ("operation", operations) when it holds
    several milling operations (formats.cl Operation objects, all of the program's), ("tool table", message)
    when it is G-code whose T words need a tool table and none is given, ("units", message) when it is
    G-code in inches whose LinuxCNC `tool_table` gives lengths in units not said (`units`: "mm", "inch" or
    None); else None (it reads, or fails for a reason the import will say). Read in a worker thread."""
    from ..errors import InputError
    from ..formats.cl.program import OperationChoiceError
    from ..jobs import load_path
    from . import worker

    options = None
    if tool_table:
        from ..formats.gcode.options import ReadOptions

        options = ReadOptions(tool_table=tool_table, machine_units=units)
    try:
        worker.work(load_path, path, None, options=options, text=noop("Reading the toolpath…"))
    except OperationChoiceError as error:
        if any(operation.refusal() is None for operation in error.operations):
            return "operation", error.operations
    except worker.Cancelled:
        raise
    except InputError as error:
        if not tool_table and "no tool table" in str(error):
            return "tool table", str(error)
        if tool_table and units is None and "--machine-units" in str(error):
            return "units", str(error)
    return None


def ask_toolpath_options(path, tool_table=""):
    """(operation, tool table, units of its lengths) to import the toolpath file `path` with, asked in dialogs
    where the file needs them (:func:`toolpath_needs`): the operation of a program of several, the tool table
    of G-code and, for a program in inches, the units of a LinuxCNC table; None when the user cancels."""
    from PySide import QtGui

    window = FreeCADGui.getMainWindow()
    need = toolpath_needs(path, tool_table)
    if need is not None and need[0] == "tool table":
        chosen, _ = QtGui.QFileDialog.getOpenFileName(
            window, translate("Tool table of {file}", file=os.path.basename(path)), os.path.dirname(path),
            translate("Tool table (*.tbl *.FCStd);;All files (*)"))
        if not chosen:
            FreeCAD.Console.PrintWarning(
                f"{PROG}: " + translate("{file}: not imported: its program loads tools by number, and no tool table "
                                        "was chosen (a LinuxCNC tool table, or the FreeCAD document that posted "
                                        "the program)", file=os.path.basename(path)) + "\n")
            return None
        tool_table = chosen
        need = toolpath_needs(path, tool_table)
    units = None
    if need is not None and need[0] == "units":
        units = ask_units(path, tool_table)
        if units is None:
            return None
        need = toolpath_needs(path, tool_table, units)
    operation = 0
    if need is not None and need[0] == "operation":
        operations = need[1]
        dialog = QtGui.QInputDialog(window)
        dialog.setObjectName("ABM_ChooseOperation")
        dialog.setWindowTitle(translate("Import toolpath"))
        dialog.setLabelText(translate("{file} holds several operations: choose the one to compute "
                                      "(the toolpath's Operation; change it later in the property editor)",
                                      file=os.path.basename(path)))
        dialog.setComboBoxItems([operation_words(op) for op in operations])
        dialog.setComboBoxEditable(False)
        milling = [op for op in operations if op.refusal() is None]
        dialog.setTextValue(operation_words(milling[0]))
        if not dialog.exec_():
            dialog.deleteLater()
            return None
        operation = operations[[operation_words(op) for op in operations].index(dialog.textValue())].number
        dialog.deleteLater()
    return operation, tool_table, units


#: The choices of :func:`ask_units`, in the order shown: (words, ReadOptions' machine_units).
UNITS = ((noop("millimetres (mm)"), "mm"), (noop("inches (in)"), "inch"))


def ask_units(path, tool_table):
    """The units of the lengths of the LinuxCNC `tool_table` of the G-code program `path` (which works in inches),
    asked in a dialog (``ABM_MachineUnits``): "mm" or "inch"; None when the user cancels (said in the report
    view: nothing imported)."""
    from PySide import QtGui

    program, table = os.path.basename(path), os.path.basename(tool_table)
    dialog = QtGui.QInputDialog(FreeCADGui.getMainWindow())
    dialog.setObjectName("ABM_MachineUnits")
    dialog.setWindowTitle(translate("Import toolpath"))
    dialog.setLabelText(translate("{program} works in inches, and the tool table {table} gives its lengths in the "
                                  "machine's units, which LinuxCNC does not write in the table. Which units is the "
                                  "machine set up in (LINEAR_UNITS of its INI file)? (the toolpath's ToolTableUnits; "
                                  "change it later in the property editor)", program=program, table=table))
    words = [translate(text) for text, _ in UNITS]
    dialog.setComboBoxItems(words)
    dialog.setComboBoxEditable(False)
    chosen = dialog.exec_()
    answer = dialog.textValue()
    dialog.deleteLater()
    if not chosen:
        FreeCAD.Console.PrintWarning(
            f"{PROG}: " + translate("{file}: not imported: it works in inches, and the units of the tool table {table} "
                                    "were not said", file=program, table=table) + "\n")
        return None
    return UNITS[words.index(answer)][1]


def operation_words(operation):
    """An operation of a program as the dialog lists it: its summary, and why the engine refuses it if it does."""
    refusal = operation.refusal()
    return operation.summary() + ("" if refusal is None else f" ({translate('not for the engine')}: {refusal})")


#: The ABM objects' kinds in words, one and several, for messages.
NOUNS = {"ABM::Stock": (noop("stock"), noop("stocks")), "ABM::Toolpath": (noop("toolpath"), noop("toolpaths")),
         "ABM::Engagement": (noop("engagement"), noop("engagements"))}


def pick(doc, kind, selection):
    """The one ABM object of `kind` ("ABM::Stock", …): the selected one, else the document's only one."""
    noun, nouns = (translate(word) for word in NOUNS[kind])
    chosen = [obj for obj in selection if view_providers.kind(obj) == kind]
    if len(chosen) > 1:
        raise CommandError(translate("{count} {nouns} selected: select one {noun}", count=len(chosen), nouns=nouns,
                                     noun=noun))
    if chosen:
        return chosen[0]
    found = [obj for obj in doc.Objects if view_providers.kind(obj) == kind]
    if not found:
        raise CommandError(translate("no {noun} in the document: import one first", noun=noun))
    if len(found) > 1:
        raise CommandError(translate("{count} {nouns} in the document: select the one to use", count=len(found),
                                     nouns=nouns))
    return found[0]


class ComputeEngagement(Command):
    """The engagement of the selected stock and toolpath (or the document's only ones): task panel."""

    Name = "ABM_ComputeEngagement"
    MenuText = QT_TRANSLATE_NOOP("ABM_ComputeEngagement", "Compute engagement")
    ToolTip = QT_TRANSLATE_NOOP("ABM_ComputeEngagement",
                                "Compute where the cutter engages the stock along the toolpath: select a stock and a "
                                "toolpath (or have only one of each), then set the tool and cut in the task panel")
    Accel = "A, E"

    def Activated(self):
        """Interactive: the task panel (:mod:`.task_panel`) for a new engagement; it owns the transaction."""
        try:
            doc = FreeCAD.ActiveDocument
            selection = FreeCADGui.Selection.getSelection(doc.Name)
            stock, toolpath = pick(doc, "ABM::Stock", selection), pick(doc, "ABM::Toolpath", selection)
            task_panel.compute(doc, stock, toolpath)
        except Exception as error:  # noqa: BLE001 (reported; the GUI goes on)
            report_error(error)

    def activated(self, doc, settings, selection=None):
        """Scripts and tests: add and compute the engagement with `settings` (create_engagement's
        keywords, e.g. a job.json's through load_settings) without the panel."""
        from ..features import create_engagement
        if selection is None:
            selection = FreeCADGui.Selection.getSelection(doc.Name)
        stock, toolpath = pick(doc, "ABM::Stock", selection), pick(doc, "ABM::Toolpath", selection)
        engagement = create_engagement(doc, stock, toolpath, **settings)
        view_providers.attach(engagement)
        recompute_checked(doc, (engagement,))
        dock.show(engagement)
        return engagement


class EngageCamJob(Command):
    """The engagement of the selected FreeCAD CAM Job (or of some of its operations): toolpaths linked to the
    Job, its stock, engagements with the tool controllers' tools (:mod:`.cam_jobs`), computed."""

    Name = "ABM_EngageCamJob"
    MenuText = QT_TRANSLATE_NOOP("ABM_EngageCamJob", "Engage CAM job")
    ToolTip = QT_TRANSLATE_NOOP("ABM_EngageCamJob",
                                "Compute where the cutter engages the stock in a FreeCAD CAM Job: select the Job "
                                "(every operation the engine computes) or some of its operations; the results "
                                "follow the Job when it recomputes")
    Accel = "A, J"

    def Activated(self):
        doc = FreeCAD.ActiveDocument
        self.execute(FreeCADGui.Selection.getSelection(doc.Name))

    def activated(self, doc, selection):
        from .cam_jobs import engage

        made = engage(doc, selection)
        with busy(translate("Computing the engagement of the CAM job…")):
            recompute_checked(doc, made)
        dock.show(made[-1])
        return made


def selected_engagement(doc):
    """The selected engagement object, else the document's only one (CommandError otherwise)."""
    return pick(doc, "ABM::Engagement", FreeCADGui.Selection.getSelection(doc.Name))


class InspectEngagement(Command):
    """The dock of the selected engagement: CL point slider, colours and legend, plots."""

    Name = "ABM_InspectEngagement"
    MenuText = QT_TRANSLATE_NOOP("ABM_InspectEngagement", "Inspect engagement")
    ToolTip = QT_TRANSLATE_NOOP("ABM_InspectEngagement",
                                "Open the engagement dock for the selected engagement: choose a CL point (highlighted "
                                "on the model), colour by segment, length of cut or cut area, and see the plots")
    Accel = "A, I"

    def Activated(self):
        try:
            self.show(selected_engagement(FreeCAD.ActiveDocument))
        except Exception as error:  # noqa: BLE001 (reported; the GUI goes on)
            report_error(error)

    @staticmethod
    def show(engagement, cl=None):
        """Open the dock on `engagement` at CL point `cl`; the dock."""
        return dock.show(engagement, cl)


class ValidateEngagement(Command):
    """The selected engagement against OpenCASCADE booleans: the HTML report, opened."""

    Name = "ABM_ValidateEngagement"
    MenuText = QT_TRANSLATE_NOOP("ABM_ValidateEngagement", "Validate engagement…")
    ToolTip = QT_TRANSLATE_NOOP("ABM_ValidateEngagement",
                                "Check the selected engagement's length of cut against OpenCASCADE booleans at all or "
                                "chosen CL points (about 1 s per CL point; cancellable) and open the HTML report")
    Accel = "A, V"

    def Activated(self):
        """Ask for the CL points (checked at once: a bad list is said in a dialog, and asked again), then, for an
        unsaved document without a report folder, the folder; then validate."""
        from PySide import QtGui

        from .validate import cl_indices, report_folder

        window = FreeCADGui.getMainWindow()
        try:
            doc = FreeCAD.ActiveDocument
            engagement = selected_engagement(doc)
            if engagement.Proxy.result(engagement) is None:
                raise CommandError(translate("{label}: compute it first (recompute the document)",
                                             label=engagement.Label))
            count = len(engagement.Toolpath.Proxy.load(engagement.Toolpath)[0])
        except Exception as error:  # noqa: BLE001 (said in a dialog and the report view; the GUI goes on)
            report_error(error, window)
            return
        shown = dock.find()
        text = str(shown.spin.value()) if shown is not None and shown.obj is engagement else "all"
        while True:
            dialog = QtGui.QInputDialog(window)
            dialog.setObjectName("ABM_ValidateCLPoints")
            dialog.setWindowTitle(translate("Validate engagement"))
            dialog.setLabelText(translate("CL points to check (all, or e.g. 0,22,40; about 1 s each):"))
            dialog.setTextValue(text)
            ok = dialog.exec_()
            text = dialog.textValue()
            dialog.deleteLater()
            if not ok:
                return
            try:
                cl_indices(text, count)
                break
            except Exception as error:  # noqa: BLE001 (said in a dialog, then asked again)
                report_error(error, window)
        folder = report_folder(engagement)
        root = preferences.report_root()
        if root:
            folder = os.path.join(root, f"{doc.Name}_{engagement.Name}_validation")
        elif not doc.FileName:
            chosen = QtGui.QFileDialog.getExistingDirectory(window, translate("Folder for the validation report"))
            if not chosen:
                return
            folder = os.path.join(chosen, f"{engagement.Name}_validation")
        self.execute(engagement, text, folder, True, window)

    def execute(self, *args):
        """run(*args), errors to the report view, a cancel said as such; the report's path, or None."""
        from .validate import Cancelled

        try:
            return self.run(*args[:4])
        except Cancelled as cancelled:
            FreeCAD.Console.PrintWarning(f"{PROG}: {cancelled}\n")
            return None
        except Exception as error:  # noqa: BLE001 (reported; the GUI goes on)
            report_error(error, args[4] if len(args) > 4 else None)
            return None

    def activated(self, doc, engagement, cls_text="all", folder=None, open_report=True):
        """Validate `engagement` at the CL points of `cls_text` ("all" or "0,22,40") into `folder`
        (default beside the document) in a worker thread (the progress dialog's Cancel answers at once);
        records ValidationReport and opens the report. Its path."""
        from . import worker
        from .validate import Cancelled, cl_indices, prepare, report_folder

        if engagement.Proxy.result(engagement) is None:
            raise CommandError(translate("{label}: compute it first (recompute the document)", label=engagement.Label))
        count = len(engagement.Toolpath.Proxy.load(engagement.Toolpath)[0])
        cls = cl_indices(cls_text, count)
        progress = ProgressDialog(translate("Validating {label} at {count} CL points against booleans…",
                                            label=engagement.Label, count=len(cls)))
        try:
            run = prepare(engagement, cls, folder or report_folder(engagement))
            cancelled = Cancelled(translate("validation cancelled: nothing written"))
            page = worker.work(run, sink=progress, cancelled=cancelled)
        finally:
            progress.close()
        engagement.ValidationReport = page
        said = translate("{label}: validation report {page}", label=engagement.Label, page=page)
        FreeCAD.Console.PrintMessage(f"{PROG}: {said}\n")
        if open_report:
            from PySide import QtCore, QtGui

            QtGui.QDesktopServices.openUrl(QtCore.QUrl.fromLocalFile(page))
        return page


class ShowInProcessStock(Command):
    """The in-process stock at the dock's chosen CL point in the 3D view, following the dock's slider."""

    Name = "ABM_ShowInProcessStock"
    MenuText = QT_TRANSLATE_NOOP("ABM_ShowInProcessStock", "Show in-process stock")
    ToolTip = QT_TRANSLATE_NOOP("ABM_ShowInProcessStock",
                                "Show the stock as it is at the dock's chosen CL point: the stock minus what the "
                                "program's earlier moves near it removed (OpenCASCADE booleans, a few seconds); it "
                                "follows the CL point chosen in the dock")
    Accel = "A, P"

    def activated(self, doc):
        from .inprocess_view import show_for_dock

        return show_for_dock()


COMMANDS = (OpenModelTest, ImportStock, ImportToolpath, ComputeEngagement, EngageCamJob, InspectEngagement,
            ValidateEngagement, ShowInProcessStock)
#: Command names in menu and toolbar order.
NAMES = tuple(command.Name for command in COMMANDS)


def register():
    """Add every ABM command to FreeCADGui (once); returns their names."""
    known = FreeCADGui.listCommands()
    for command in COMMANDS:
        if command.Name not in known:
            FreeCADGui.addCommand(command.Name, command())
    return NAMES
