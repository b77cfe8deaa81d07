"""A toolpath file as a document object: its Shape is the polyline through the CL points.

``create_toolpath(doc, path)`` adds a ``Part::FeaturePython`` (proxy :class:`ToolpathFeature`):

- group "Source": ``File``, a toolpath CSV (``.csv``) or APT / CL file (``.apt``, ``.cls``).
- group "Summary" (read-only, set by ``execute`` from the file): ``CLPoints``, and what an APT
  file says about the tool and the cut, 0 where it says nothing: ``ToolDiameter`` and
  ``FluteLength`` (CUTTER / TLDATA, mm), ``SpindleSpeed`` (SPINDL, rpm), ``Feed`` with
  ``FeedUnit`` (a FEDRAT constant along the pass); ``Warnings`` (records not understood,
  assumptions made).

The Toolpath and its PathHints stay on the proxy (:meth:`ToolpathFeature.load`), read again
from the file when needed after a restore; nothing of them is saved but the Shape and the
summary. Bad input raises the command line's InputError message.
"""

import os

import numpy as np

from ..cad.freecad_env import FreeCAD, Part
from ..jobs import load_path
from .base import FeatureProxy, add_properties, document_or_active

#: Consecutive CL points closer than this (mm) are one vertex of the polyline.
POINT_TOL = 1e-9


class ToolpathFeature(FeatureProxy):
    """Proxy of the toolpath object (see the module docstring)."""

    KIND = "ABM::Toolpath"

    def __init__(self, obj):
        super().__init__(obj)
        add_properties(obj, "Source", [
            ("App::PropertyFile", "File", "toolpath: CSV (x,y,z,theta_a,theta_b or x,y,z,i,j,k) or APT / CL file"),
        ])
        add_properties(obj, "Summary", [
            ("App::PropertyInteger", "CLPoints", "number of CL points of the pass"),
            ("App::PropertyLength", "ToolDiameter", "tool diameter the file gives (CUTTER / TLDATA), 0 if none"),
            ("App::PropertyLength", "FluteLength", "flute length the file gives (CUTTER / TLDATA), 0 if none"),
            ("App::PropertyFloat", "SpindleSpeed", "spindle speed the file gives (SPINDL, rpm), 0 if none"),
            ("App::PropertyFloat", "Feed", "feed the file gives when it is constant along the pass (FEDRAT, "
                                           "in FeedUnit), 0 if none"),
            ("App::PropertyString", "FeedUnit", "unit of Feed: MMPM, MMPR, IPM or IPR"),
            ("App::PropertyStringList", "Warnings", "what the reader did not understand or assumed"),
        ], read_only=True)

    def _reset(self):
        self._cache = None  # ((path, mtime), (Toolpath, PathHints))

    def execute(self, obj):
        """Read the file; set the Shape (polyline of CL points) and the summary properties."""
        toolpath, hints = self.load(obj)
        obj.Shape = polyline(toolpath.cl)
        obj.CLPoints = len(toolpath)
        obj.ToolDiameter = hints.diameter or 0.0
        obj.FluteLength = hints.flute_length or 0.0
        obj.SpindleSpeed = hints.spindle_rpm or 0.0
        feed = hints.feed
        constant = (feed is not None and hints.feed_unit is not None and np.isfinite(feed).all()
                    and np.ptp(feed) <= 1e-9 * np.abs(feed).max())
        obj.Feed = float(feed[0]) if constant else 0.0
        obj.FeedUnit = hints.feed_unit if constant else ""
        obj.Warnings = hints.messages()

    def load(self, obj):
        """(Toolpath, PathHints) of the file, cached while the file is unchanged."""
        path = obj.File
        if not path:
            from ..errors import InputError
            raise InputError(f"{obj.Label}: no toolpath file: set File")
        try:
            stamp = os.stat(path).st_mtime_ns
        except OSError:
            stamp = None
        if self._cache is None or self._cache[0] != (path, stamp):
            self._cache = ((path, stamp), load_path(path))
        return self._cache[1]


def polyline(points):
    """A wire through points (k, 3) mm, consecutive duplicates dropped; a vertex for one point."""
    points = np.asarray(points, dtype=float)
    keep = np.concatenate([[True], np.linalg.norm(np.diff(points, axis=0), axis=1) > POINT_TOL])
    points = points[keep]
    if len(points) == 1:
        return Part.Vertex(FreeCAD.Vector(*points[0]))
    return Part.makePolygon([FreeCAD.Vector(*p) for p in points.tolist()])


def create_toolpath(doc=None, path=None, name="Toolpath"):
    """Add a toolpath object reading `path` (CSV, APT, CLS) to `doc` (default the active document;
    RuntimeError if none). Returns the object (not yet recomputed)."""
    doc = document_or_active(doc)
    obj = doc.addObject("Part::FeaturePython", name)
    ToolpathFeature(obj)
    if path is not None:
        obj.File = os.fspath(path)
    return obj
