"""The engagement object: a stock, a toolpath and the cut settings; the engine runs in ``execute``.

``create_engagement(doc, stock, toolpath, **settings)`` adds a ``Part::FeaturePython`` (proxy
:class:`EngagementFeature`) with:

- group "Inputs": ``Stock`` and ``Toolpath`` (links to the objects of :mod:`.stock` and
  :mod:`.toolpath`), ``WallModel`` (stock: the stock object's; exact or quintic: that model,
  for a solid stock only), ``StockModel`` (in-process: the stock minus what the program's
  earlier cutting moves removed, where the engine has it; initial: the stock as given) and
  ``SweepTolerance`` (mm, the sub-step of five-axis moves at the tool's rim);
- group "Tool": ``Diameter`` (mm), ``Flutes``, ``FluteLength`` (mm), ``HelixAngle`` (deg, 0:
  straight flutes; a helical tool is solved by ``engine.helix.flute_engagement``, flute 1 shown);
- group "Cut": ``FeedPerTooth`` (mm), ``SpindleSpeed`` (rpm, 0: none), ``Inclination`` (deg),
  ``PhiStart``, ``PhiEnd``, ``PhiStep`` (deg);
- group "Forces" (the command line's ``engage --forces``, docs/FORCES.md): ``Forces`` (on / off),
  ``Material`` (a name of ``forces.MATERIALS``, or custom), ``Ktc``, ``Krc``, ``Kac`` (N/mm²),
  ``Kte``, ``Kre``, ``Kae`` (N/mm; read-only and taken from the table unless Material is custom),
  ``ImmersionStart``, ``ImmersionEnd`` (deg: where a flute cuts);
- group "Display": ``ShowSurfaces``: the Shape is the outline of the engaged cutter surface
  (below) and the GUI draws the surface, or both are empty;
- group "Results" (read-only, set by ``execute``): ``DepthOfCutMin``, ``DepthOfCutMax``,
  ``MaxLengthOfCut`` (mm), ``Instants`` (CL points × angles), ``EngagedInstants``,
  ``EngagedCLPoints``, ``ChangedCLPoints`` (CL points whose edges meet material earlier moves
  removed), ``StockModelUsed`` (in-process, or initial and why), ``EngineTime`` (s),
  ``Parameters`` (each value and where it came from),
  ``Warnings``, ``ResultsFile`` (where the results CSV is), ``ResultsDigest``; with forces on,
  ``PeakForce`` (N, largest resultant over the pass) and ``ForceFeedPerTooth`` (mm, the feed the
  forces are for).

With forces on, ``execute`` also runs ``forces.pass_forces`` and the results CSV gains fx, fy,
fz (N), torque (N·mm) and, with a spindle speed, power (W) per instant; they are read back with
the results (:meth:`EngagementFeature.forces`, a :class:`.stored.PassForces`). Version 3 added
the helix and the forces; older objects are migrated with straight flutes and forces off.

The stock model is the command line's ``--stock-model`` through the same job-model call
(``jobs.run.in_process_sweep``): StockModel in-process is its default (in-process where the engine
has it; with a helical tool or the forces, the stock as given, the reason in StockModelUsed and
Warnings), initial is ``--stock-model initial``. Against the in-process stock the results CSV gains
``length_initial`` and its summary ``changed`` (:class:`.stored.InProcess`, read by
:meth:`EngagementFeature.in_process`). Version 5 added the stock model; older objects were
computed against the stock as given and are migrated with StockModel initial.

Parameters follow the job model's precedence (:func:`abm_workbench.jobs.resolve`): what an
APT / CL toolpath file gives (tool diameter, flute length, spindle speed, a constant feed) wins
over the properties, which play the command-line options; a required value that is 0 and not in
the file is missing. Every value is checked by its declaration (``jobs.parameters``); a bad one
fails the recompute with the parameter's plain label and its property named.
``create_engagement`` fills the properties not given from the file, so they show the values used.

Results are not pickled into the document. ``execute`` writes the results CSV and its summary
(:mod:`abm_workbench.formats.results_csv`) to ``<folder of the .FCStd>/<file stem>_abm/<object
Name>.csv`` (and ``.summary.csv``); for a document never saved, to a temporary folder, and when
the document is saved the results in memory are written beside it (a document observer, at
the start of the save, so ``ResultsFile`` is saved right). ``ResultsDigest`` keeps the CSV's
SHA-256. On restore (``onDocumentRestored``) the CSV is read back, with no recompute; when it
is missing, or is not the file saved with the document (its digest differs: recomputed but not
saved), the object is marked touched as the document is activated (FreeCAD 0.20 clears touched
flags at the end of a restore) and the next recompute computes it again.

The Shape: per CL point and engagement segment, the outline of the engaged part of the cutter
surface (a closed polyline through the segment's LEP and UEP points), all in one compound; the
GUI draws the surface itself as a mesh (``gui.surface_mesh``). See docs/FEATURES.md.

Bad input fails the recompute with its message alone, without a Python traceback in FreeCAD's
report view (:class:`RecomputeFailed`). The engine's calls go through :data:`engine_call`, which
the GUI replaces by a worker thread.
"""

import atexit
import functools
import hashlib
import os
import shutil
import sys
import tempfile
import time
from typing import NamedTuple

import numpy as np

from ..cad.freecad_env import FreeCAD, Part
from ..engine.profile import edge_between
from ..errors import InputError, ParameterError
from ..forces import COEFFICIENT_NAMES, MATERIALS
from ..jobs import BY_NAME, MATERIAL_CHOICES, WALL_MODELS, Job, force_model, label_words, resolve, swept_y_window
from ..jobs import tool_and_settings
from ..jobs import run as _run
from ..jobs.job import Prepared
from ..jobs.parameters import SWEEP_TOLERANCE
from ..jobs.run import STOCK_MODELS, check_model, in_part_frame, in_process_sweep
from .base import PROP_OUTPUT as _PROP_OUTPUT, READ_ONLY, FeatureProxy, add_properties, document_or_active
from .base import PROG, RecomputeFailed, remember_relative, tell  # noqa: F401 (RecomputeFailed: its home was here)
from .stored import InProcess, PassForces, read_archive, read_engagement, read_forces, read_in_process, write_archive
from .stored import write_results_csv
from .stock import StockFeature
from .toolpath import POINT_TOL, ToolpathFeature

#: WallModel choices: the stock object's, or one of the wall models.
WALL_CHOICES = ("stock",) + WALL_MODELS
#: YWindow choices: auto is the command line's default (swept for quintic walls, whole for exact ones).
Y_WINDOWS = ("auto", "whole", "swept", "custom")
#: Coefficient name (forces.COEFFICIENT_NAMES) -> property.
COEFFICIENT_PROPERTIES = {name: name.capitalize() for name in COEFFICIENT_NAMES}
#: create_engagement keyword -> (property, value when not set). Required ones are 0 when not set.
SETTINGS = {
    "diameter": ("Diameter", 0.0), "flutes": ("Flutes", 0), "flute_length": ("FluteLength", 0.0),
    "corner_radius": ("CornerRadius", 0.0),
    "feed_per_tooth": ("FeedPerTooth", 0.0), "spindle_rpm": ("SpindleSpeed", 0.0),
    **{name: (BY_NAME[name].prop, BY_NAME[name].default)
       for name in ("inclination", "phi_start", "phi_end", "phi_step", "helix", "immersion_start", "immersion_end")},
    "forces": ("Forces", False), "material": ("Material", MATERIAL_CHOICES[0]),
    "stock_model": ("StockModel", STOCK_MODELS[0]), "sweep_tolerance": ("SweepTolerance", SWEEP_TOLERANCE.default),
    **{name: (COEFFICIENT_PROPERTIES[name], getattr(MATERIALS[MATERIAL_CHOICES[0]][0], name))
       for name in COEFFICIENT_NAMES},
}
_TEMP_FOLDERS = {}  # document Name -> temporary results folder of an unsaved document
#: Results kept per engagement object (for undo, redo and Cancel), and the groups of the properties
#: they depend on.
KEPT = 8
INPUT_GROUPS = ("Inputs", "Tool", "Cut", "Forces", "Display")
#: Properties execute sets from the results (restored with kept results).
KEPT_PROPERTIES = ("DepthOfCutMin", "DepthOfCutMax", "MaxLengthOfCut", "Instants", "EngagedInstants",
                   "EngagedCLPoints", "ChangedCLPoints", "StockModelUsed", "EngineTime", "Parameters", "Warnings",
                   "PeakForce", "ForceFeedPerTooth")


def _call(function, *args):
    return function(*args)


#: engine_call(function, *args) -> function(*args): how execute runs the engine's pure-numpy calls
#: (flute_1, pass_forces_of below). Headless, a plain call; the GUI puts a worker thread with
#: progress and Cancel here (``gui.worker.install``).
engine_call = _call


def flute_1(*args):
    """``jobs.run.flute_1`` through engine_call."""
    return engine_call(_run.flute_1, *args)


def pass_forces_of(*args, **keywords):
    """``jobs.run.pass_forces_of`` through engine_call."""
    return engine_call(lambda: _run.pass_forces_of(*args, **keywords))


def engage_in_process(*args):
    """``jobs.run.in_process_1`` (the in-process engine in chunks, with progress) through engine_call."""
    return engine_call(_run.in_process_1, *args)


class EngagementInputs(NamedTuple):
    """The engine's inputs of an engagement object: the Toolpath and PathHints of its file, the
    resolved Parameters, the Tool and CutSettings, and the stock as a
    :class:`abm_workbench.jobs.Stock` (its staircase, solid and wall model)."""

    toolpath: object
    hints: object
    parameters: object
    tool: object
    settings: object
    stock: object


def given_parameters(obj):
    """The engagement object's cutting properties as jobs.resolve's `given` (unset: None)."""
    return {
        "diameter": _or_none(obj.Diameter.Value), "flutes": _or_none(obj.Flutes),
        "flute_length": _or_none(obj.FluteLength.Value), "corner_radius": obj.CornerRadius.Value,
        "feed_per_tooth": _or_none(obj.FeedPerTooth.Value),
        "inclination": obj.Inclination.Value, "spindle_rpm": _or_none(obj.SpindleSpeed),
        "phi_start": obj.PhiStart.Value, "phi_end": obj.PhiEnd.Value, "phi_step": obj.PhiStep.Value,
    }


def property_words(label, error):
    """InputError of a ParameterError of the engagement `label` in plain words, its property named."""
    parameter = BY_NAME.get(error.field)
    prop = f" (property {parameter.prop})" if parameter is not None and parameter.prop else ""
    return InputError(f"{label}: {label_words(error)[:-1]}{prop}.")




class EngagementFeature(FeatureProxy):
    """Proxy of the engagement object (see the module docstring)."""

    KIND = "ABM::Engagement"

    def __init__(self, obj):
        super().__init__(obj)
        add_properties(obj, "Inputs", [
            ("App::PropertyLink", "Stock", "the stock object (ABM Stock)"),
            ("App::PropertyLink", "Toolpath", "the toolpath object (ABM Toolpath)"),
            ("App::PropertyEnumeration", "WallModel", "stock: the stock object's wall model; exact or quintic: "
                                                      "that model (solid stocks only)"),
        ])
        obj.WallModel = list(WALL_CHOICES)
        obj.WallModel = "stock"
        add_version_2_properties(obj, "auto")
        add_properties(obj, "Tool", [
            ("App::PropertyLength", "Diameter", "tool diameter (required; the toolpath file's CUTTER wins)", 0.0),
            ("App::PropertyInteger", "Flutes", "number of flutes (required)", 0),
            ("App::PropertyLength", "FluteLength", "flute length (required; the toolpath file's CUTTER wins)", 0.0),
        ])
        add_version_3_properties(obj)
        add_version_5_properties(obj, STOCK_MODELS[0])
        add_version_6_properties(obj)
        add_properties(obj, "Cut", [
            ("App::PropertyLength", "FeedPerTooth", "feed per tooth f (required; a constant FEDRAT in the "
                                                    "toolpath file wins)", 0.0),
            ("App::PropertyFloat", "SpindleSpeed", "spindle speed (rpm), 0 for none (the file's SPINDL wins)", 0.0),
            *(("App::PropertyAngle", BY_NAME[name].prop, BY_NAME[name].help, BY_NAME[name].default)
              for name in ("inclination", "phi_start", "phi_end", "phi_step")),
        ])
        add_properties(obj, "Display", [
            ("App::PropertyBool", "ShowSurfaces", "Shape: the outline of the engaged cutter surface of every "
                                                  "CL point (one closed polyline per engagement segment; the "
                                                  "GUI draws the surface), or empty", True),
        ])
        add_properties(obj, "Results", [
            ("App::PropertyLength", "DepthOfCutMin", "smallest depth of cut over the engaged CL points"),
            ("App::PropertyLength", "DepthOfCutMax", "largest depth of cut over the engaged CL points"),
            ("App::PropertyLength", "MaxLengthOfCut", "largest length of cut over all instants"),
            ("App::PropertyInteger", "Instants", "CL points × rotation angles computed"),
            ("App::PropertyInteger", "EngagedInstants", "instants at which the edge is in the stock"),
            ("App::PropertyInteger", "EngagedCLPoints", "CL points at which the tool engages the stock"),
            ("App::PropertyFloat", "EngineTime", "time the engine took (s)"),
            ("App::PropertyString", "Parameters", "each cutting parameter used and where it came from"),
            ("App::PropertyStringList", "Warnings", "what the toolpath file could not read, conflicts"),
        ], read_only=True)
        for name, tip in (("ResultsFile", "results CSV: relative to the document's folder, or a temporary path "
                                          "before it is saved"),
                          ("ResultsDigest", "SHA-256 of the results CSV written last: on restore, a CSV that "
                                            "differs (recomputed but not saved) is not used")):
            if name not in obj.PropertiesList:
                obj.addProperty("App::PropertyString", name, "Results", tip, _PROP_OUTPUT)
            obj.setEditorMode(name, 1)
        add_results_data(obj)

    def _reset(self):
        self._result = None  # the Engagement, computed or read back
        self._written = None  # path the results were last written to
        self._stale = False  # restored without results: touched once the document is restored
        self._toolpath = None  # the Toolpath of the results (for the summary's CL point columns)
        self._forces = None  # the PassForces of the results, with forces on
        self._in_process = None  # the InProcess of the results, against the in-process stock
        self._kept = {}  # ResultsDigest -> Kept: the last KEPT results, for undo, redo and Cancel

    # ---- computing -------------------------------------------------------------------------
    def inputs(self, obj):
        """What the engine runs on, as ``execute`` resolves it (an :class:`EngagementInputs`).

        InputError in plain words for bad or missing input.
        """
        toolpath, hints = _proxy(obj.Toolpath, ToolpathFeature, "Toolpath", obj).load(obj.Toolpath)
        stock_obj = obj.Stock
        stock_proxy = _proxy(stock_obj, StockFeature, "Stock", obj)
        try:
            parameters = resolve(given_parameters(obj), hints, {}, words=lambda parameter: f"the property {parameter.prop}")
            tool, settings = tool_and_settings(parameters.values, obj.HelixAngle.Value)
        except ParameterError as error:
            raise property_words(obj.Label, error) from None
        walls = None if obj.WallModel == "stock" else obj.WallModel
        if walls is not None and not stock_proxy.is_solid(stock_obj):
            raise InputError(f"WallModel {walls} applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), not to "
                             f"{stock_proxy.source_name(stock_obj)}")
        window = y_window(obj, stock_obj, walls or stock_obj.WallModel, toolpath, tool)
        stock = stock_proxy.load(stock_obj, walls, window, hints.frame)
        try:
            check_model(stock, helix=tool.helix)
        except ParameterError as error:
            raise property_words(obj.Label, error) from None
        return EngagementInputs(toolpath, hints, parameters, tool, settings, stock)

    def execute(self, obj):
        """Recompute (:meth:`compute`); bad input fails it with its message alone (:class:`RecomputeFailed`)."""
        try:
            self.compute(obj)
        except ParameterError as error:
            raise RecomputeFailed(str(property_words(obj.Label, error))) from None
        except InputError as error:
            raise RecomputeFailed(str(error)) from None

    def compute(self, obj):
        """Run the engine; store the results (CSV, read-only properties, Shape). Inputs the results of
        which are kept (:meth:`result`) take them back instead of running the engine again."""
        self._result, self._written, self._forces = None, None, None
        obj.ResultsDigest = ""  # no results while this fails
        model = force_model_of(obj)
        toolpath, hints, parameters, tool, settings, stock = self.inputs(obj)
        staircase = stock.model
        if obj.YWindow != "custom" and stock.y_window is not None:
            obj.YWindowMin, obj.YWindowMax = stock.y_window
        key = inputs_key(obj, toolpath, stock)
        if self._take_back(obj, key):
            return

        sweep, model_note = self.stock_model(obj, toolpath, hints, parameters, tool, settings, model)
        started = time.perf_counter()
        if sweep is None:
            engine_result, in_process = flute_1(staircase, tool, toolpath, settings), None
        else:
            engine_result, initial, changed = engage_in_process(staircase, tool, toolpath, settings, *sweep)
            in_process = InProcess(initial, changed)
        result = in_part_frame(engine_result, hints.frame)
        elapsed = time.perf_counter() - started
        if not result.engaged.any():
            if in_process is not None and in_process.initial.any():
                raise InputError(f"{hints.source}: earlier moves of the program already removed all the "
                                 "material this operation's tool would meet (StockModel initial computes it "
                                 "against the stock as given)")
            raise InputError(f"{hints.source}: the tool never touches the stock: no CL point of the pass "
                             f"engages it (are the toolpath and {obj.Stock.Proxy.source_name(obj.Stock)} in the "
                             "same frame?)")
        warnings = [*hints.messages(), *parameters.conflicts, *([model_note] if model_note else [])]
        for message in warnings:
            tell(obj, message)
        if model is not None:
            forces = pass_forces_of(staircase, tool, toolpath, settings, model, engine_result, in_process=sweep)
            self._forces = PassForces.of(forces)
            # From the forces kept (part frame), which the dock and the results file show: the tool
            # frame's norms can differ from theirs in the last bit.
            obj.PeakForce = float(self._forces.peak.max())
            obj.ForceFeedPerTooth = settings.feed_per_tooth
        else:
            obj.PeakForce, obj.ForceFeedPerTooth = 0.0, 0.0
        self._result, self._toolpath, self._in_process = result, toolpath, in_process
        self._write(obj, results_path(obj))
        self._summary(obj, result)
        obj.ChangedCLPoints = 0 if in_process is None else int(np.count_nonzero(in_process.changed))
        obj.StockModelUsed = STOCK_MODELS[0] if in_process is not None else \
            f"{STOCK_MODELS[1]}: {model_note}" if model_note else STOCK_MODELS[1]
        obj.EngineTime = elapsed
        obj.Parameters = parameters.describe(lambda parameter: parameter.prop)
        obj.Warnings = warnings
        obj.Shape = engaged_outline(result) if obj.ShowSurfaces else Part.Shape()
        self._keep(obj, key, (toolpath, stock))

    def stock_model(self, obj, toolpath, hints, parameters, tool, settings, model):
        """(The engine's in-process arguments (SweptPieces, (m,) program rows) or None for the stock as
        given; why in-process is not used, or '') of the engagement `obj`, by the command line's
        job-model call (jobs.run.in_process_sweep) on the resolved inputs; model: its force model
        or None. InputError naming SweepTolerance when it is not positive."""
        try:
            tolerance = SWEEP_TOLERANCE.check(obj.SweepTolerance.Value)
        except ParameterError as error:
            raise InputError(f"{obj.Label}: {label_words(error)[:-1]} (property {SWEEP_TOLERANCE.prop}).") from None
        job = Job(obj.Stock.Proxy.source_name(obj.Stock), hints.source,
                  stock_model=None if obj.StockModel == STOCK_MODELS[0] else obj.StockModel,
                  sweep_tolerance=tolerance)
        return in_process_sweep(Prepared(job, {}, toolpath, hints, parameters, tool, settings, model))

    def _keep(self, obj, key, sources):
        """Keep the results just made under their ResultsDigest (the last KEPT of them)."""
        kept = Kept(key, self._result, self._forces, self._toolpath, obj.Shape, sources,
                    {name: getattr(obj, name) for name in KEPT_PROPERTIES}, self._in_process)
        self._kept.pop(obj.ResultsDigest, None)
        self._kept[obj.ResultsDigest] = kept
        while len(self._kept) > KEPT:
            self._kept.pop(next(iter(self._kept)))

    def _take_back(self, obj, key):
        """Make kept results of the inputs `key` the object's again (CSV, properties, Shape); False if none."""
        found = [(digest, kept) for digest, kept in self._kept.items() if kept.key == key]
        if not found:
            return False
        digest, kept = found[-1]
        self._result, self._forces, self._toolpath = kept.result, kept.forces, kept.toolpath
        self._in_process = kept.in_process
        self._write(obj, results_path(obj))
        for name, value in kept.properties.items():
            setattr(obj, name, value)
        obj.Shape = kept.shape
        if obj.ResultsDigest != digest:  # the CSV says otherwise (another writer): keep under its digest
            self._kept[obj.ResultsDigest] = self._kept.pop(digest)
        return True

    def migrate(self, obj, saved_version):
        """Version 2 added the y window and the validation report; objects saved before were computed
        over the whole y range. Version 3 added the helix and the forces (straight flutes, forces off).
        Version 5 added the stock model; objects saved before were computed against the stock as given.
        Version 6 added the corner radius; objects saved before were flat-end mills (0)."""
        add_version_2_properties(obj, "whole")
        add_version_3_properties(obj)
        add_version_5_properties(obj, STOCK_MODELS[1])
        add_version_6_properties(obj)
        super().migrate(obj, saved_version)

    def onChanged(self, obj, prop):
        """A Material of the table fills the coefficients and makes them read-only; custom frees them."""
        if prop == "Material" and "Ktc" in obj.PropertiesList:
            show_material(obj)

    def _summary(self, obj, result):
        depth = result.depth_of_cut
        engaged = ~np.isnan(depth)
        obj.DepthOfCutMin = float(np.nanmin(depth)) if engaged.any() else 0.0
        obj.DepthOfCutMax = float(np.nanmax(depth)) if engaged.any() else 0.0
        obj.MaxLengthOfCut = float(result.length.max())
        obj.Instants = int(result.length.size)
        obj.EngagedInstants = int(np.count_nonzero(result.engaged))
        obj.EngagedCLPoints = int(np.count_nonzero(engaged))

    def _write(self, obj, path):
        """Write the results and summary CSV to `path`, and note where in ResultsFile."""
        os.makedirs(os.path.dirname(path), exist_ok=True)
        toolpath = self._toolpath
        if toolpath is None and isinstance(getattr(obj.Toolpath, "Proxy", None), ToolpathFeature):
            try:  # results read back: the toolpath file gives the summary's CL point columns
                toolpath = obj.Toolpath.Proxy.load(obj.Toolpath)[0]
            except InputError:
                toolpath = None
        if toolpath is not None and len(toolpath) != self._result.shape[0]:
            toolpath = None
        write_results_csv(path, self._result, toolpath=toolpath, forces=self._forces, in_process=self._in_process)
        self._written = path
        obj.ResultsFile = _relative(obj.Document, path)
        obj.ResultsDigest = _digest(path)

    # ---- results --------------------------------------------------------------------------
    def result(self, obj):
        """The Engagement (arrays over CL points × φ) the object's properties stand for, or None before a
        successful recompute.

        Results are keyed by their CSV's digest (``ResultsDigest``), a property that undo, redo and an
        aborted transaction restore with the others: the results come back with them.
        """
        kept = self._kept.get(obj.ResultsDigest)
        return kept.result if kept is not None else None

    def edge_along(self, obj):
        """None where the drawn edge is straight (a flat-end mill, or the tool or results not known now);
        for a tool with a corner, the `along` function gui.surface_mesh takes: each engaged instant's
        peripheral edge between its LEP and its UEP, in the part's frame (engine.profile.edge_between)."""
        kept = self._kept.get(obj.ResultsDigest)
        if kept is None or kept.toolpath is None or obj.Toolpath is None:
            return None
        try:
            _, hints = obj.Toolpath.Proxy.load(obj.Toolpath)
            tool, _ = tool_and_settings(resolve(given_parameters(obj), hints, {}, words=lambda parameter: f"the property {parameter.prop}").values, obj.HelixAngle.Value)
        except (InputError, ParameterError):
            return None
        if tool.corner_radius == 0.0:
            return None
        return functools.partial(edge_between, kept.result, kept.toolpath, tool, hints.frame)

    def forces(self, obj):
        """The PassForces of the results (fx, fy, fz, torque, power per instant), or None: forces off,
        or before a successful recompute."""
        kept = self._kept.get(obj.ResultsDigest)
        return kept.forces if kept is not None else None

    def in_process(self, obj):
        """The InProcess of the results (initial lengths, changed CL points), or None: computed against the
        stock as given, or before a successful recompute."""
        kept = self._kept.get(obj.ResultsDigest)
        return kept.in_process if kept is not None else None

    def save_results(self, obj):
        """Put the results the object stands for into the document (ResultsData) and write their CSV
        beside it, unless they are there already (an object restored from an older file gains
        ResultsData as it is restored)."""
        kept = self._kept.get(obj.ResultsDigest)
        if kept is None:
            return
        path, digest = results_path(obj), obj.ResultsDigest
        if not os.path.isfile(path) or _digest(path) != digest:
            self._result, self._forces, self._toolpath = kept.result, kept.forces, kept.toolpath
            self._in_process = kept.in_process
            self._write(obj, path)
            self._kept[obj.ResultsDigest] = self._kept.pop(digest)  # the same results, written anew
        if "ResultsData" in obj.PropertiesList:
            embed(obj, kept.result, kept.forces, kept.in_process)

    def restored_from_document(self, obj):
        """Take the results back from ResultsData (the document's own copy); True if they are the ones
        the object stands for (its ResultsDigest and Instants)."""
        add_results_data(obj)
        path = obj.ResultsData
        if not path or not os.path.isfile(path):
            return False
        try:
            digest, result, forces, in_process = read_archive(path)
        except InputError as error:
            tell(obj, f"results in the document not read ({error})")
            return False
        if digest != obj.ResultsDigest or result.length.size != obj.Instants:
            return False
        self._result, self._forces, self._in_process = result, forces, in_process
        self._kept[digest] = Kept(None, result, forces, None, obj.Shape, (),
                                  {name: getattr(obj, name) for name in KEPT_PROPERTIES}, in_process)
        return True

    def restored(self, obj):
        """Take the results back from the document (ResultsData), else read the results CSV (no
        recompute); mark the object touched when neither holds them."""
        if self.restored_from_document(obj):
            return
        path = _absolute(obj.Document, obj.ResultsFile) if obj.ResultsFile else results_path(obj)
        if not os.path.isfile(path):
            path = results_path(obj)
        try:
            if not os.path.isfile(path):
                raise InputError(f"{path}: no such file")
            if _digest(path) != obj.ResultsDigest:
                raise InputError(f"{path}: not the results saved with the document (recomputed since?)")
            result = read_engagement(path)
            if result.length.size != obj.Instants:
                raise InputError(f"{path}: {result.length.size} instants, the object says {obj.Instants}")
            forces = read_forces(path, obj.ForceFeedPerTooth.Value) if obj.Forces else None
            if obj.Forces and forces is None:
                raise InputError(f"{path}: no force columns, but Forces is on")
            in_process = read_in_process(path)
            if (in_process is not None) != (obj.StockModelUsed == STOCK_MODELS[0]):
                raise InputError(f"{path}: not computed against the stock model {obj.StockModelUsed}")
        except (InputError, OSError) as error:
            tell(obj, f"results not restored ({error}); recompute to compute them")
            # FreeCAD 0.20 clears touched flags at the end of a restore and tells Python observers
            # nothing after that but the document's activation: the observer touches it then.
            self._stale = True
            return
        self._result, self._written, self._forces, self._in_process = result, path, forces, in_process
        self._kept[obj.ResultsDigest] = Kept(None, result, forces, None, obj.Shape, (),
                                             {name: getattr(obj, name) for name in KEPT_PROPERTIES}, in_process)


class Kept(NamedTuple):
    """Results an engagement object keeps for undo, redo and Cancel: the inputs_key they were computed
    for (None: read back), the Engagement, PassForces (or None), Toolpath (or None), the Shape, the
    (Toolpath, Stock) they came from (kept alive, so their ids in the key stay theirs), the
    values of KEPT_PROPERTIES and the InProcess (or None: against the stock as given)."""

    key: object
    result: object
    forces: object
    toolpath: object
    shape: object
    sources: tuple
    properties: dict
    in_process: object = None


def inputs_key(obj, toolpath, stock):
    """What the results of the engagement `obj` depend on: its input properties (groups INPUT_GROUPS,
    the y window's ends only when it is custom) and the Toolpath and Stock its links load (the
    loaders keep one object while their files are unchanged)."""
    values = []
    for name in sorted(obj.PropertiesList):
        if obj.getGroupOfProperty(name) not in INPUT_GROUPS or (name.startswith("YWindowM")
                                                                and obj.YWindow != "custom"):
            continue
        value = getattr(obj, name)
        values.append((name, value.Name if hasattr(value, "Document") else str(value)))
    return tuple(values), id(toolpath), id(stock)


def _proxy(linked, kind, role, obj):
    """The proxy (of class `kind`) of a linked ABM object; InputError when the link is missing or wrong."""
    proxy = getattr(linked, "Proxy", None) if linked is not None else None
    if not isinstance(proxy, kind):
        raise InputError(f"{obj.Label}: {role} must link an ABM {role} object")
    return proxy


def add_results_data(obj):
    """Add ResultsData (group "Results", read-only, not touching the object) if missing."""
    if "ResultsData" not in obj.PropertiesList:
        obj.addProperty("App::PropertyFileIncluded", "ResultsData", "Results",
                        "the results inside the document: a compressed NumPy archive of every array of the "
                        "engagement (and forces), written as the document is saved", _PROP_OUTPUT)
    obj.setEditorMode("ResultsData", READ_ONLY)


def embed(obj, result, forces, in_process):
    """Put the results of the engagement `obj` (its ResultsDigest's) into ResultsData: FreeCAD keeps a
    copy of the file and saves it inside the .FCStd."""
    handle, path = tempfile.mkstemp(prefix=f"{obj.Name}_", suffix=".npz")
    os.close(handle)
    try:
        write_archive(path, obj.ResultsDigest, result, forces, in_process)
        obj.ResultsData = path
    finally:
        if os.path.exists(path):
            os.remove(path)


def add_version_2_properties(obj, mode):
    """Add what version 2 added, if missing: the y window (group "Inputs", YWindow set to `mode`)
    and ValidationReport (group "Validation", read-only, not touching the object)."""
    if "ValidationReport" not in obj.PropertiesList:
        obj.addProperty("App::PropertyString", "ValidationReport", "Validation",
                        "HTML report of the last validation against OpenCASCADE booleans (ABM_ValidateEngagement)",
                        _PROP_OUTPUT)
        obj.setEditorMode("ValidationReport", 1)
    if "YWindow" in obj.PropertiesList:
        return
    add_properties(obj, "Inputs", [
        ("App::PropertyEnumeration", "YWindow", "y range of a solid stock that is recognised: auto (swept for "
                                                "quintic walls, whole for exact ones, as the command line), whole "
                                                "(the stock's y range), swept (the y range the cutting edges "
                                                "sweep below the stock's top, plus 1 mm), custom (YWindowMin.."
                                                "YWindowMax)"),
        ("App::PropertyDistance", "YWindowMin", "lower end of the y window: the input when YWindow is custom, "
                                                "else the one used"),
        ("App::PropertyDistance", "YWindowMax", "upper end of the y window: the input when YWindow is custom, "
                                                "else the one used"),
    ])
    obj.YWindow = list(Y_WINDOWS)
    obj.YWindow = mode


def add_version_3_properties(obj):
    """Add what version 3 added, if missing: HelixAngle (group "Tool", 0: straight flutes), the
    force model (group "Forces", off, the first material of the table) and the force results
    (group "Results", read-only)."""
    add_properties(obj, "Tool", [
        ("App::PropertyAngle", "HelixAngle", "helix angle β of the flutes, 0 for straight flutes (the command "
                                             "line's --helix)", 0.0),
    ])
    if "Forces" in obj.PropertiesList:
        return
    cut, edge = "cutting-force coefficient (N/mm²) of the linear edge-force model", \
        "edge-force coefficient (N/mm) of the linear edge-force model"
    add_properties(obj, "Forces", [
        ("App::PropertyBool", "Forces", "compute the cutting forces: fx, fy, fz (N), torque (N·mm) and power (W, "
                                        "with a spindle speed) per instant in the results CSV", False),
        ("App::PropertyEnumeration", "Material", "coefficients from the table of docs/FORCES.md, or custom: the "
                                                 "six coefficients as typed"),
        *[("App::PropertyFloat", COEFFICIENT_PROPERTIES[name],
           f"{name[:1].upper()}_{name[1:]}: {'tangential' if name[1] == 't' else 'radial' if name[1] == 'r' else 'axial'} "
           f"{cut if name.endswith('c') else edge}") for name in COEFFICIENT_NAMES],
        ("App::PropertyAngle", "ImmersionStart", "angle from which a flute cuts (0 <= start < end <= 180)",
         BY_NAME["immersion_start"].default),
        ("App::PropertyAngle", "ImmersionEnd", "angle up to which a flute cuts", BY_NAME["immersion_end"].default),
    ])
    add_properties(obj, "Results", [
        ("App::PropertyFloat", "PeakForce", "largest resultant cutting force over the pass (N); 0 with forces off"),
        ("App::PropertyLength", "ForceFeedPerTooth", "feed per tooth the forces were computed at"),
    ], read_only=True)
    obj.Material = list(MATERIAL_CHOICES)
    obj.Material = MATERIAL_CHOICES[0]
    show_material(obj)


def add_version_5_properties(obj, model):
    """Add what version 5 added, if missing: StockModel (group "Inputs", set to `model`, a STOCK_MODELS
    name), SweepTolerance (group "Inputs", mm) and the in-process results ChangedCLPoints and
    StockModelUsed (group "Results", read-only)."""
    if "StockModel" in obj.PropertiesList:
        return
    add_properties(obj, "Inputs", [
        ("App::PropertyEnumeration", "StockModel", "in-process: the stock minus what the program's earlier cutting "
                                                   "moves removed (where available: straight flutes, no forces); "
                                                   "initial: the stock as given (the command line's --stock-model)"),
        ("App::PropertyLength", SWEEP_TOLERANCE.prop, f"{SWEEP_TOLERANCE.help} (the command line's "
                                                      f"{SWEEP_TOLERANCE.option})", SWEEP_TOLERANCE.default),
    ])
    add_properties(obj, "Results", [
        ("App::PropertyInteger", "ChangedCLPoints", "CL points whose cutting edges meet material that earlier moves "
                                                    "of the program removed (0 against the stock as given)"),
        ("App::PropertyString", "StockModelUsed", "the stock the results are against: in-process, or initial and "
                                                  "why"),
    ], read_only=True)
    obj.StockModel = list(STOCK_MODELS)
    obj.StockModel = model
    obj.StockModelUsed = model


def add_version_6_properties(obj):
    """Add what version 6 added, if missing: CornerRadius (group "Tool", mm, 0: a flat-end mill)."""
    if "CornerRadius" in obj.PropertiesList:
        return
    parameter = BY_NAME["corner_radius"]
    add_properties(obj, "Tool", [
        ("App::PropertyLength", parameter.prop, f"{parameter.help} (the toolpath file's CUTTER or TLDATA wins)",
         parameter.default),
    ])


def show_material(obj):
    """Coefficient properties of the engagement `obj` for its Material: the table's values, read-only,
    or (custom) as they are, editable."""
    custom = obj.Material == "custom"
    if not custom:
        table = MATERIALS[obj.Material][0]
        for name, prop in COEFFICIENT_PROPERTIES.items():
            if getattr(obj, prop) != getattr(table, name):
                setattr(obj, prop, getattr(table, name))
    for prop in COEFFICIENT_PROPERTIES.values():
        obj.setEditorMode(prop, 0 if custom else READ_ONLY)


def force_model_of(obj):
    """(Coefficients, immersion (start, end) deg) of the engagement `obj`, or None with Forces off.

    InputError in plain words, the property named, for bad coefficients or immersion.
    """
    if not obj.Forces:
        return None
    values = {prop: getattr(obj, prop) for prop in COEFFICIENT_PROPERTIES.values()}
    try:
        return force_settings(obj.Material, values, (obj.ImmersionStart.Value, obj.ImmersionEnd.Value))
    except ParameterError as error:
        raise property_words(obj.Label, error) from None


def force_settings(material_name, values, immersion):
    """(Coefficients, immersion (start, end) deg) of a material name of MATERIAL_CHOICES (custom: the
    coefficient `values`, {property: number}) and an immersion (start, end) deg; ParameterError naming
    the coefficient or immersion that is bad."""
    given = {"immersion_start": immersion[0], "immersion_end": immersion[1]}
    if material_name == "custom":
        given.update({name: values[prop] for name, prop in COEFFICIENT_PROPERTIES.items()})
    return force_model(Job("", "", given=given, forces=True,
                           material=None if material_name == "custom" else material_name))


def y_window(obj, stock_obj, walls, toolpath, tool):
    """(y0, y1) mm the stock is recognised over for the engagement `obj`, or None for the whole range.

    walls: the wall model used ("exact" or "quintic"). A JSON stock has no y window: YWindow
    swept or custom is then an InputError, as ``--y-window`` is on the command line. The window
    is cut to the stock's y range; InputError when nothing is left.
    """
    mode = obj.YWindow
    if mode == "auto":
        mode = "swept" if walls == "quintic" else "whole"
    solid = stock_obj.Proxy.is_solid(stock_obj)
    if not solid:
        if obj.YWindow in ("swept", "custom"):
            raise InputError(f"YWindow {obj.YWindow} applies to a solid stock (.step, .stp, .brep, .brp, .FCStd), "
                             f"not to {stock_obj.Proxy.source_name(stock_obj)}")
        return None
    if mode == "whole":
        return None
    box = stock_obj.Shape.BoundBox
    if mode == "swept":
        low, high = swept_y_window(toolpath, tool, box.ZMax)
    else:
        low, high = obj.YWindowMin.Value, obj.YWindowMax.Value
        if not low < high:
            raise InputError(f"{obj.Label}: YWindowMin ({low:g} mm) must be below YWindowMax ({high:g} mm)")
    clipped = (max(low, box.YMin), min(high, box.YMax))
    if not clipped[0] < clipped[1]:
        raise InputError(f"{stock_obj.Proxy.source_name(stock_obj)}: y window {low:g}..{high:g} mm misses the "
                         f"stock's y range {box.YMin:g}..{box.YMax:g} mm")
    return clipped


def _or_none(value):
    return None if value == 0 else value


def results_folder(doc):
    """Folder of the results of `doc`: ``<folder>/<stem>_abm`` beside its file, or a temporary one."""
    if doc.FileName:
        folder, name = os.path.split(doc.FileName)
        return os.path.join(folder, os.path.splitext(name)[0] + "_abm")
    if doc.Name not in _TEMP_FOLDERS:
        _TEMP_FOLDERS[doc.Name] = tempfile.mkdtemp(prefix=f"abm-{doc.Name}-")
    return _TEMP_FOLDERS[doc.Name]


def results_path(obj):
    """Results CSV of the engagement object `obj` (its summary: .summary.csv beside it)."""
    return os.path.join(results_folder(obj.Document), obj.Name + ".csv")


def _digest(path):
    """SHA-256 (hex) of the file at `path`."""
    with open(path, "rb") as file:
        return hashlib.sha256(file.read()).hexdigest()


def _relative(doc, path):
    if doc.FileName:
        return os.path.relpath(path, os.path.dirname(doc.FileName))
    return path


def _absolute(doc, path):
    if os.path.isabs(path) or not doc.FileName:
        return path
    return os.path.join(os.path.dirname(doc.FileName), path)


def engaged_outline(result):
    """A compound of the outline of the engaged cutter surface (see :func:`engaged_outline_parts`)."""
    return Part.Compound(engaged_outline_parts(result)[0])


def engaged_outline_parts(result):
    """The outline of the engaged cutter surface of every CL point, piece by piece, and what each is.

    Per CL point and engagement segment: one closed polyline edge (a B-spline of degree 1, whose
    poles are the points) along the LEP points of the segment's angles and back along its UEP
    points (a line LEP–UEP for a one-angle segment; nothing for a segment of zero length). One
    edge per segment, not one per pair of points, keeps FreeCAD's drawing of the Shape cheap. The
    surface itself is drawn by the GUI as a mesh (``gui.surface_mesh``). Returns (shapes, keys):
    keys[i] = (cl, segment letter, UEP surface name) of shapes[i].
    """
    from ..engine.engagement import SURFACES, segment_letter

    segment = result.segment
    cl, row = np.nonzero(segment >= 0)
    key = cl * (segment.shape[1] + 1) + segment[cl, row]
    starts = np.flatnonzero(np.concatenate([[True], key[1:] != key[:-1]]))
    stops = np.append(starts[1:], cl.size)
    lep, uep = result.lep_xyz[cl, row], result.uep_xyz[cl, row]
    shapes, keys = [], []
    for start, stop in zip(starts.tolist(), stops.tolist()):
        first = (cl[start], row[start])
        points = np.concatenate([lep[start:stop], uep[start:stop][::-1], lep[start:start + 1]]) \
            if stop - start > 1 else np.stack([lep[start], uep[start]])
        points = points[np.concatenate([[True], np.linalg.norm(np.diff(points, axis=0), axis=1) > POINT_TOL])]
        if len(points) < 2:
            continue  # a segment of zero length has no outline
        curve = Part.BSplineCurve()
        curve.buildFromPoles([FreeCAD.Vector(*point) for point in points.tolist()], False, 1)
        shapes.append(curve.toShape())
        keys.append((int(first[0]), segment_letter(segment[first]), SURFACES[result.uep_surface[first]]))
    return shapes, keys


class _SaveObserver:
    """As a document is saved: remembers the input files of its ABM objects relative to it and writes
    the results of every engagement object into it and beside it; removes an unsaved document's
    temporary results folder when it is closed."""

    def slotStartSaveDocument(self, doc, filename):
        for obj in doc.Objects:
            if isinstance(getattr(obj, "Proxy", None), FeatureProxy):
                remember_relative(obj, filename)
            if isinstance(getattr(obj, "Proxy", None), EngagementFeature):
                try:
                    obj.Proxy.save_results(obj)
                except Exception as error:  # noqa: BLE001 (the save itself must go on)
                    tell(obj, f"cannot write results: {error}", "Error")

    def slotActivateDocument(self, doc):
        for obj in doc.Objects:
            proxy = getattr(obj, "Proxy", None)
            if isinstance(proxy, EngagementFeature) and proxy._stale:
                proxy._stale = False
                obj.touch()

    def slotDeletedDocument(self, doc):
        folder = _TEMP_FOLDERS.pop(doc.Name, None)
        if folder:
            shutil.rmtree(folder, ignore_errors=True)


_OBSERVER = _SaveObserver()
FreeCAD.addDocumentObserver(_OBSERVER)
atexit.register(lambda: [shutil.rmtree(folder, ignore_errors=True) for folder in _TEMP_FOLDERS.values()])


def create_engagement(doc=None, stock=None, toolpath=None, name="Engagement", *, walls="stock", y_window="auto",
                      **settings):
    """Add an engagement object of `stock` and `toolpath` (objects of create_stock / create_toolpath)
    to `doc` (default the active document; RuntimeError if none).

    settings: diameter, flutes, flute_length, corner_radius, feed_per_tooth (mm), spindle_rpm, inclination,
    phi_start, phi_end, phi_step (deg), or phi_range=(start, end); helix (deg); forces (bool),
    material (a forces.MATERIALS name or "custom"), ktc, krc, kac (N/mm²), kte, kre, kae (N/mm),
    immersion_start, immersion_end (deg), or immersion=(start, end); stock_model ("in-process" or
    "initial", jobs.run.STOCK_MODELS), sweep_tolerance (mm). Those not given come from
    the toolpath file where it gives them (read now), else stay unset (0) or at their defaults.
    walls: "stock", "exact" or "quintic". y_window: "auto", "whole", "swept", or (y0, y1) mm
    (custom). Returns the object (not yet recomputed).
    """
    doc = document_or_active(doc)
    if "phi_range" in settings:
        settings["phi_start"], settings["phi_end"] = settings.pop("phi_range")
    if "immersion" in settings:
        settings["immersion_start"], settings["immersion_end"] = settings.pop("immersion")
    unknown = sorted(set(settings) - set(SETTINGS))
    if unknown:
        raise TypeError(f"create_engagement: unknown setting {unknown[0]!r} (known: {', '.join(SETTINGS)})")
    if walls not in WALL_CHOICES:
        raise ValueError(f"walls must be one of {WALL_CHOICES}, got {walls!r}")
    if isinstance(y_window, str) and y_window not in Y_WINDOWS[:3]:
        raise ValueError(f"y_window must be auto, whole, swept or (y0, y1), got {y_window!r}")
    obj = doc.addObject("Part::FeaturePython", name)
    EngagementFeature(obj)
    obj.Stock, obj.Toolpath, obj.WallModel = stock, toolpath, walls
    if isinstance(y_window, str):
        obj.YWindow = y_window
    else:
        obj.YWindow = "custom"
        obj.YWindowMin, obj.YWindowMax = (float(value) for value in y_window)
    if toolpath is not None and (getattr(toolpath, "File", "") or getattr(toolpath, "CamJob", None)):
        try:
            _, hints = toolpath.Proxy.load(toolpath)
        except InputError:
            hints = None  # execute reports it
        if hints is not None:
            for key, value in (("diameter", hints.diameter), ("flute_length", hints.flute_length),
                               ("corner_radius", hints.corner_radius),
                               ("spindle_rpm", hints.spindle_rpm), ("flutes", hints.flutes)):
                if value is not None and key not in settings:
                    settings[key] = value
    for key, value in sorted(settings.items(), key=lambda item: item[0] != "material"):  # the table first
        if value is not None:
            setattr(obj, SETTINGS[key][0], value)
    return obj
