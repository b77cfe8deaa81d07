"""The stock as a document object: a staircase solid recognised from a Part object or a file.

``create_stock(doc, source=...)`` adds a ``Part::FeaturePython`` (proxy :class:`StockFeature`):

- group "Source": ``SourceObject`` (link to a Part object of the document holding the solid)
  or ``SourceFile`` (a staircase JSON, or a STEP / BREP / FCStd solid); the link wins when
  both are set.
- group "Walls": ``WallModel`` (exact: the solid's own wall curves; quintic: the paper's
  quintic through six points), ``WallPoints`` (chebyshev or even: where the six points lie).
  A JSON stock always has the paper's quintic walls.
- group "Summary" (read-only, set by ``execute``): ``Sections``, ``StraightWalls``,
  ``CurvedWalls``, ``YMin``, ``YMax`` (the y window recognised: the stock's whole y range).

Its Shape is the stock solid (the source's own solid, or for JSON the staircase built as a
solid). The recognised :class:`~abm_workbench.engine.Staircase` stays on the proxy, never in the
file; :meth:`StockFeature.staircase` recognises it again when needed after a restore.
Bad input raises the command line's InputError message; FreeCAD then marks the object invalid.
"""

import os

import numpy as np

from ..errors import InputError
from ..engine import PlanLine
from ..jobs import WALL_MODELS, WALL_POINTS, load_stock
from ..jobs.inputs import recognised
from .base import FeatureProxy, add_properties, document_or_active, failing_in_words

#: Recognised stocks kept per stock object (wall models × y windows asked for).
_CACHED = 4
_WALL_MODEL_TIP = ("exact: each wall is the solid's own curve (default); quintic: the paper's quintic through "
                   "six points on the wall. A JSON stock always has the paper's quintic walls.")



def _call(function, *args, **keywords):
    return function(*args, **keywords)


#: recognise_call(function, *args, **keywords) -> function(*args, **keywords): how a stock is read and
#: recognised (STEP / BREP reading and recognition, seconds for a large solid). Headless, a plain call;
#: the GUI puts a worker thread with progress and Cancel here (``gui.worker.install``).
recognise_call = _call


class StockFeature(FeatureProxy):
    """Proxy of the stock object (see the module docstring)."""

    KIND = "ABM::Stock"

    def __init__(self, obj):
        super().__init__(obj)
        add_properties(obj, "Source", [
            ("App::PropertyLink", "SourceObject", "Part object holding the stock solid (wins over SourceFile)"),
            ("App::PropertyFile", "SourceFile", "staircase JSON, or a STEP / BREP / FCStd file holding the solid"),
        ])
        add_properties(obj, "Walls", [("App::PropertyEnumeration", "WallModel", _WALL_MODEL_TIP),
                                      ("App::PropertyEnumeration", "WallPoints",
                                       "where the six points of each wall lie over the y window")])
        obj.WallModel, obj.WallPoints = list(WALL_MODELS), list(WALL_POINTS)
        obj.WallModel, obj.WallPoints = WALL_MODELS[0], WALL_POINTS[0]
        add_properties(obj, "Summary", [
            ("App::PropertyInteger", "Sections", "number of sections of the staircase"),
            ("App::PropertyInteger", "StraightWalls", "walls that are planes x = const"),
            ("App::PropertyInteger", "CurvedWalls", "walls that are curved"),
            ("App::PropertyDistance", "YMin", "y window recognised: lower limit (the stock's whole y range)"),
            ("App::PropertyDistance", "YMax", "y window recognised: upper limit"),
        ], read_only=True)

    def _reset(self):
        self._cache = {}  # {(key of the source, walls, wall points, y window): jobs.Stock}

    @failing_in_words
    def execute(self, obj):
        """Recognise the stock, set the Shape and the summary properties."""
        stock = self.load(obj)
        obj.Shape = stock.solid()
        staircase = stock.staircase
        if staircase is None:  # a general 2.5D stock: its slabs, and its boundary curves as walls
            curves = [curve for slab in stock.terraced.slabs for loop in slab.loops for curve in loop.curves]
            straight = sum(isinstance(curve, PlanLine) for curve in curves)
            obj.Sections, obj.StraightWalls, obj.CurvedWalls = len(stock.terraced.slabs), straight, len(curves) - straight
            box = obj.Shape.BoundBox
            obj.YMin, obj.YMax = box.YMin, box.YMax
            return
        straight = sum(bool(wall.is_straight) for wall in staircase.walls)
        obj.Sections = staircase.n_sections
        obj.StraightWalls, obj.CurvedWalls = straight, len(staircase.walls) - straight
        obj.YMin, obj.YMax = stock.y_window

    def source_name(self, obj):
        """What the stock comes from, for messages: the linked object's label or the file."""
        if obj.SourceObject is not None:
            return obj.SourceObject.Label
        return obj.SourceFile

    def staircase(self, obj, walls=None, y_window=None):
        """The Staircase of the stock (with wall model `walls`, default the WallModel property),
        recognised over y_window ((y0, y1) mm within the stock's y range; None: all of it)."""
        return self.load(obj, walls, y_window).staircase

    def is_solid(self, obj):
        """True when the stock comes from a solid (a Part object or a STEP / BREP / FCStd file)."""
        return obj.SourceObject is not None or not obj.SourceFile.lower().endswith(".json")

    def load(self, obj, walls=None, y_window=None, frame=None):
        """The stock as a :class:`abm_workbench.jobs.Stock`, cached while its inputs stay the same
        (the last few wall models, y windows and frames asked for; y_window as in :meth:`staircase`;
        frame: (R, t) from part coordinates to an operation's engine frame, or None)."""
        walls = walls or obj.WallModel
        window = None if y_window is None else tuple(float(y) for y in y_window)
        frame_key = None if frame is None else (tuple(np.ravel(frame[0])), tuple(np.ravel(frame[1])))
        source = self._source_key(obj)
        key = (source, walls, obj.WallPoints, window, frame_key)
        if key not in self._cache:
            kept = {old: stock for old, stock in self._cache.items() if old[0] == source}
            kept = dict(list(kept.items())[-(_CACHED - 1):])
            self._cache = {**kept, key: self._load(obj, walls, window, frame)}
        return self._cache[key]

    def _source_key(self, obj):
        if obj.SourceObject is not None:
            shape = obj.SourceObject.Shape
            return ("object", obj.SourceObject.Name, shape.hashCode(), round(shape.Volume, 9))
        path = obj.SourceFile
        try:
            stamp = os.stat(path).st_mtime_ns
        except OSError:
            stamp = None
        return ("file", path, stamp)

    def _load(self, obj, walls, y_window, frame):
        source = obj.SourceObject
        if source is not None:
            from ..cad.solids import moved
            shape = getattr(source, "Shape", None)
            if shape is None or shape.isNull():
                raise InputError(f"{source.Label}: the linked object has no shape")
            shape = shape.copy() if frame is None else moved(shape, *frame)
            return recognise_call(recognised, shape, source.Label, walls=walls, wall_points=obj.WallPoints,
                                  y_window=y_window, frame=frame)
        if not obj.SourceFile:
            raise InputError(f"{obj.Label}: no stock source: set SourceObject or SourceFile")
        return recognise_call(load_stock, obj.SourceFile, walls=walls, wall_points=obj.WallPoints, y_window=y_window,
                              frame=frame)


def create_stock(doc=None, source=None, name="Stock", *, walls="exact", wall_points="chebyshev"):
    """Add a stock object to `doc` (default the active document; RuntimeError if none).

    source: a file path (JSON, STEP, BREP, FCStd) or a document object with a solid Shape.
    walls: "exact" or "quintic"; wall_points: "chebyshev" or "even". Returns the object
    (not yet recomputed).
    """
    doc = document_or_active(doc)
    if walls not in WALL_MODELS:
        raise ValueError(f"walls must be one of {WALL_MODELS}, got {walls!r}")
    if wall_points not in WALL_POINTS:
        raise ValueError(f"wall_points must be one of {WALL_POINTS}, got {wall_points!r}")
    obj = doc.addObject("Part::FeaturePython", name)
    StockFeature(obj)
    if source is None:
        pass
    elif isinstance(source, (str, os.PathLike)):
        obj.SourceFile = os.fspath(source)
    else:
        obj.SourceObject = source
    obj.WallModel, obj.WallPoints = walls, wall_points
    return obj
