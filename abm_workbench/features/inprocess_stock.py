"""The in-process stock at one CL point as a document object: the stock solid cut by what earlier moves removed.

``create_inprocess_stock(doc, engagement, cl)`` adds a ``Part::FeaturePython`` (proxy
:class:`InProcessStockFeature`):

- group "Inputs": ``Engagement`` (link to an engagement object), ``CLPoint`` (0-based CL point of
  its operation, as in the results CSV and the dock's slider), ``Reach`` (mm: the earlier moves
  cut are those whose swept volume comes within Reach of the tool's bounding sphere at the CL
  point; 0: those touching that sphere, all the cutting edges there can meet), ``SweepTolerance``
  (mm: the sub-step of five-axis moves at the tool's rim for this view; 0: the engagement's own);
- group "View": ``FollowDock`` (the GUI moves the object to the CL point chosen in the engagement
  dock and recomputes it; changing it does not touch the object);
- group "Results" (read-only, set by ``execute``): ``ProgramRow`` (the CL point's row in the
  whole program), ``RemovedVolume`` (mm³: the stock's volume minus the Shape's),
  ``ComputeTime`` (s).

Its Shape is the stock object's solid (part coordinates) minus the volumes the cutting moves of
the whole program that end before the CL point swept, near it: the OpenCASCADE construction
the validation uses (:func:`abm_workbench.cad.inprocess_boolean.inprocess_solid`), each
constant-axis piece of a move an exact solid (a corner tool's piece the flat-end hull that holds it,
said in the Report view: fusing hundreds of exact corner solids takes OpenCASCADE too long). Five-axis moves are cut into sub-steps no farther
apart than SweepTolerance at the tool's rim: the engagement's 0.05 mm makes hundreds of pieces
near a CL point of a five-axis program, minutes of booleans, so the view takes 0.5 mm by default
(the cut surfaces then show facets of at most that size between sub-steps). The program's swept
pieces stay on the proxy while the engagement's inputs and the tolerance are unchanged, and so does the
last shape computed: a recompute back at its CL point (the GUI's Cancel puts the object back there)
takes it again without booleans.
"""

import time

import numpy as np

from ..cad.inprocess_boolean import cut_and_removed, hulls_near
from ..engine.inprocess import swept_pieces
from ..errors import InputError
from ..jobs.inputs import program_moves
from .base import PROP_OUTPUT, FeatureProxy, add_properties, document_or_active, failing_in_words, tell

#: Default sub-step (mm) of five-axis moves at the tool's rim for the view.
VIEW_TOLERANCE = 0.5


def _call(function, *args):
    return function(*args)


#: boolean_call(function, stock_shape, hulls) -> function(stock_shape, hulls), the cut stock, the volume
#: it lost: how execute runs the OpenCASCADE booleans (seconds to minutes near a dense five-axis program;
#: function takes a progress(done, total) keyword too). Headless, a plain call; the GUI runs it in a
#: worker process, with progress and Cancel (``gui.worker.install``: ``gui.worker.in_process``).
boolean_call = _call


class InProcessStockFeature(FeatureProxy):
    """Proxy of the in-process stock object (see the module docstring)."""

    KIND = "ABM::InProcessStock"

    def __init__(self, obj):
        super().__init__(obj)
        add_properties(obj, "Inputs", [
            ("App::PropertyLink", "Engagement", "the engagement object (ABM Engagement) whose program and stock"),
            ("App::PropertyInteger", "CLPoint", "CL point of the engagement's operation (0-based, as in the results "
                                                "CSV and the dock)", 0),
            ("App::PropertyLength", "Reach", "earlier moves cut: those within this distance of the tool's bounding "
                                             "sphere at the CL point (0: those touching it)", 0.0),
            ("App::PropertyLength", "SweepTolerance", "sub-step of five-axis moves at the tool's rim for this view "
                                                      "(0: the engagement's; smaller is closer and slower)",
             VIEW_TOLERANCE),
        ])
        if "FollowDock" not in obj.PropertiesList:
            obj.addProperty("App::PropertyBool", "FollowDock", "View", "follow the CL point chosen in the engagement "
                            "dock (off: only the command moves it)", PROP_OUTPUT)
            obj.FollowDock = True
        add_properties(obj, "Results", [
            ("App::PropertyInteger", "ProgramRow", "the CL point's row in the whole program"),
            ("App::PropertyFloat", "RemovedVolume", "volume the earlier moves near the CL point removed (mm³)"),
            ("App::PropertyFloat", "ComputeTime", "time the booleans took (s)"),
        ], read_only=True)

    def _reset(self):
        self._sweep = None  # (key, (ProgramMoves, SweptPieces, (m,) program rows of the operation))
        self._last = None  # (key, Shape, RemovedVolume, ComputeTime) of the last shape computed

    def sweep(self, obj):
        """(ProgramMoves of the whole program in part coordinates, their SweptPieces, (m,) program rows of
        the engagement's CL points), kept while the engagement's inputs are unchanged."""
        from .engagement import EngagementFeature, inputs_key

        engagement = obj.Engagement
        if not isinstance(getattr(engagement, "Proxy", None), EngagementFeature):
            raise InputError(f"{obj.Label}: Engagement must link an ABM Engagement object")
        inputs = engagement.Proxy.inputs(engagement)
        tolerance = obj.SweepTolerance.Value or engagement.SweepTolerance.Value
        key = (inputs_key(engagement, inputs.toolpath, inputs.stock), tolerance)
        if self._sweep is None or self._sweep[0] != key:
            moves, rows, _ = program_moves(inputs.hints.program, inputs.hints.operation, inputs.tool)
            self._sweep = (key, (moves, swept_pieces(moves, tolerance), rows))
        return self._sweep[1]

    @failing_in_words
    def execute(self, obj):
        """Cut the stock solid by the earlier moves near the CL point; set the Shape and the results."""
        moves, pieces, rows = self.sweep(obj)
        if not 0 <= obj.CLPoint < len(rows):
            raise InputError(f"{obj.Label}: CLPoint {obj.CLPoint} is not a CL point of {obj.Engagement.Label} "
                             f"(0..{len(rows) - 1})")
        row = int(rows[obj.CLPoint])
        stock_shape = obj.Engagement.Stock.Shape
        started = time.perf_counter()
        near = obj.Reach.Value + tool_sphere(moves, row) if obj.Reach.Value > 0.0 else None
        key = (self._sweep[0], row, near, stock_shape.hashCode())
        if self._last is not None and self._last[0] == key:  # back at the shape last computed (e.g. after Cancel)
            shape, removed, seconds = self._last[1:]
        else:
            hulls = hulls_near((moves, pieces), row, near)
            shape, removed, outlined = boolean_call(cut_and_removed, stock_shape, hulls)
            if outlined:
                tell(obj, f"{outlined} of the {len(hulls['radius'])} earlier pieces near CL point {obj.CLPoint} are "
                     "moves of a tool with a corner: they are cut as the hull of the flat-end cylinder of their "
                     "radius, which holds their volume, so the view shows less stock beside the corner than is left "
                     "(the engine and validate take their exact volumes)")
            seconds = time.perf_counter() - started
            self._last = (key, shape, removed, seconds)
        obj.Shape = shape
        obj.ProgramRow = row
        obj.RemovedVolume = removed
        obj.ComputeTime = seconds


def tool_sphere(moves, row):
    """Radius (mm) of the tool's bounding sphere at program row `row` (ProgramMoves `moves`), about the
    centre of its cutting part, as cad.inprocess_boolean measures nearness."""
    return float(np.hypot(moves.radius[row], 0.5 * moves.flute_length[row]))


def create_inprocess_stock(doc=None, engagement=None, cl=0, name="InProcessStock"):
    """Add an in-process stock object of `engagement` at CL point `cl` to `doc` (default the active
    document; RuntimeError if none). Returns the object (not yet recomputed)."""
    doc = document_or_active(doc)
    obj = doc.addObject("Part::FeaturePython", name)
    InProcessStockFeature(obj)
    obj.Engagement, obj.CLPoint = engagement, int(cl)
    return obj
