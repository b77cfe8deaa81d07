"""Validate an engagement object against OpenCASCADE booleans and write the HTML report.

:func:`validate_engagement` runs the command line's validation (``validation.validate``: the
engine and the boolean reference on the same pass) on the engagement object's own inputs
(``EngagementFeature.inputs``: its stock with its wall model and y window, the tool and cut it
was computed with), for all its CL points or a chosen subset, and writes the report of
``report.html`` into a folder that appears whole or not at all (``report.staging.staged``).

With a subset, the pass validated is made of the chosen CL points only, in their order; the
report numbers them 0, 1, … and each detailed CL point says which CL point of the pass it is.
The boolean costs about 0.5–1 s per CL point, so the progress callback is called after each.
With the object's Forces on, the report gets its "Cutting forces" section: the object's force
model (``features.engagement.force_model_of``) on the pass validated. A helical tool is
validated by the helix boolean (``jobs.run.validation``), flute 1 reported, as ``validate --helix``.
The boolean reference runs on the processes of the preference "Validation workers"
(``preferences.validation_workers``: N spawned processes, 0 one per core), as ``validate
--workers``, never on FreeCAD's own process while its GUI is up (its bindings hold Python's lock through
each boolean, which would stall the GUI's thread as long); a progress callback that raises (Cancel) ends
those processes at once. The report is in the GUI's language (its headings and sentences, report.html's
``words``; the plots and CSV files stay English), as the command line's is in English.
"""

import os
import time

import numpy as np

from ..errors import InputError, ParameterError
from .cancel import Cancelled as _WorkCancelled  # not .worker: this module runs without Qt too
from .i18n import language, translate


class Cancelled(_WorkCancelled):
    """The user cancelled the validation; nothing was written."""


def cl_indices(text, count):
    """CL indices (0-based, sorted, distinct) of "all" / "" (every CL point) or "0,22,40", checked by
    the job model (``jobs.cl_indices``) against a pass of `count` CL points; InputError "CL points: ..."."""
    from ..jobs import cl_indices as checked_indices

    text = text.strip().replace(" ", "")
    if text.lower() in ("", "all"):
        return list(range(count))
    try:
        return checked_indices(text, count)
    except ParameterError as error:
        raise InputError(f"CL points: {error.detail}") from None


def report_folder(obj):
    """Default report folder of the engagement `obj`: ``<results folder>/<Name>_validation``
    (beside the saved document, see features.engagement.results_folder)."""
    from ..features.engagement import results_folder

    return os.path.join(results_folder(obj.Document), f"{obj.Name}_validation")


def validate_engagement(obj, cls, folder, progress=None, workers=None, apart=None):
    """Validate the engagement object `obj` at CL points `cls` (indices, None: all) and write the
    report into `folder`; the path of its index.html.

    progress(done, total) is called after each CL point of the boolean reference; an exception
    it raises (e.g. :class:`Cancelled`) stops the validation, ends its worker processes and leaves
    `folder` as it was. workers: processes computing the boolean reference (0 one per core), None: the
    preference "Validation workers"; apart: True computes it in worker processes also for 1 (FreeCAD's
    Python bindings hold the interpreter's lock through each boolean: in FreeCAD's own process the GUI's
    thread would stall as long), False in this process for 1, None: True when FreeCAD's GUI is up.
    InputError with the command line's message for bad input.
    """
    return prepare(obj, cls, folder, workers, apart)(progress)


def prepare(obj, cls, folder, workers=None, apart=None):
    """The validation of :func:`validate_engagement` in two halves: this one reads the document object `obj`
    (its inputs, on the GUI thread), and returns the other, ``run(progress=None)`` -> the report's path,
    which touches no document object (the worker thread runs it, gui.worker)."""
    from ..features.engagement import force_model_of
    from ..jobs.run import pass_forces_of, validation as checked_validation
    from ..report.html import ReportJob, write_report
    from ..report.staging import staged
    from ..validation import NoEngagementError
    from .preferences import validation_workers

    started = time.perf_counter()
    model = force_model_of(obj)
    toolpath, hints, parameters, tool, settings, stock = obj.Proxy.inputs(obj)
    solid = stock.solid()
    stock_seconds = time.perf_counter() - started  # the stock object's cache makes this small
    chosen = list(range(len(toolpath))) if cls is None else [int(cl) for cl in cls]
    if not chosen:
        raise InputError("CL points: choose at least one")
    index = np.array(chosen)
    pass_ = toolpath.rows(index)
    sweep, model_note = obj.Proxy.stock_model(obj, toolpath, hints, parameters, tool, settings, model)
    if sweep is not None:
        sweep = (sweep[0], np.asarray(sweep[1])[index])
    label, workers = obj.Label, validation_workers() if workers is None else workers
    code = language()  # here: FreeCAD's GUI is asked on its own thread
    if apart is None:
        import FreeCAD

        apart = bool(FreeCAD.GuiUp)

    def run(progress=None):
        try:
            validation, helix = checked_validation(solid, stock.model, tool, pass_, settings, progress=progress,
                                                   workers=workers, sweep=sweep, apart=apart)
        except NoEngagementError:
            raise InputError(f"{hints.source}: the tool never touches the stock at CL points "
                             f"{_cl_list(chosen)}") from None
        forces = None if model is None else pass_forces_of(stock.model, tool, pass_, settings, model,
                                                             validation.engagement, in_process=sweep)
        subset = len(chosen) < len(toolpath)
        what = translate("ABM against booleans") if helix is None else translate(
            "Helical edges (β = {helix}°), flute 1 of {flutes}, ABM against booleans", helix=f"{tool.helix:g}",
            flutes=tool.flutes)
        title = f"{what}: {label} ({os.path.basename(stock.source)} / {os.path.basename(hints.source)})"
        description = translate("CL points {listed} of the pass, numbered 0..{last} here.", listed=_cl_list(chosen),
                                last=len(chosen) - 1) if subset else ""
        walls = translate("the paper's quintic walls (JSON)") if stock.shape is None else {
            "exact": translate("exact walls"), "quintic": translate("quintic walls")}.get(stock.walls,
                                                                                       f"{stock.walls} walls")
        if sweep is not None:
            stock_model = translate("in-process: the stock minus what earlier cutting moves of the program removed")
        elif model_note:
            stock_model = translate("initial: the stock as given ({why})", why=_localized(model_note))
        else:
            stock_model = translate("initial: the stock as given")
        job = ReportJob(title, description, stock.source, hints.source, pass_, tool, settings,
                        parameters.describe(lambda parameter: parameter.prop), walls, stock.y_window, stock_seconds,
                        stock_model=stock_model)
        shown = [(i, translate("pass CL {cl}", cl=cl)) for i, cl in enumerate(chosen)][:6]
        os.makedirs(os.path.dirname(os.path.abspath(folder)), exist_ok=True)
        with staged(folder, folder=True) as temporary:
            page = write_report(temporary, validation, job, shown, forces, words=translate, language=code)
        return os.path.join(os.path.abspath(folder), os.path.basename(page))

    return run


def _localized(text):
    """`text`, a message of the job model, in the GUI's language (gui.reporting.localized; as it is without
    FreeCAD's GUI modules)."""
    try:
        from .reporting import localized
    except ImportError:
        return text
    return localized(text)


def _cl_list(cls):
    return ", ".join(str(cl) for cl in cls[:12]) + (", …" if len(cls) > 12 else "")
