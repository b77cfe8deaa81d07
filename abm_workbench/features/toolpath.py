"""A toolpath file as a document object: its Shape is the polyline through the CL points.

``create_toolpath(doc, path)`` adds a ``Part::FeaturePython`` (proxy :class:`ToolpathFeature`):

- group "Source": ``File``, a CL file as CAM systems write it, a toolpath CSV or G-code (read by
  its content, docs/CL_FILES.md, docs/GCODE.md); ``CamJob``, a FreeCAD CAM Job of the document
  (wins over File: its program is read from the Job as it is, so the toolpath follows the Job when
  it recomputes; cam.job_program); ``CamOperation``, the Job's operation computed (wins over
  Operation); ``Operation``, the program's operation computed (1-based; 0: its one milling
  operation); ``ToolTable``, the tools of a G-code program's T words (a LinuxCNC tool table or
  the FCStd that posted it; empty: none); ``ToolTableUnits``, the units of a LinuxCNC tool table's
  lengths, the machine's (``not said``: mm, and a program in inches with such a table is refused
  until they are said; ``mm``; ``inch``).
- group "Summary" (read-only, set by ``execute`` from the file): ``CLPoints``, and what an APT
  file says about the tool and the cut, 0 where it says nothing: ``Operations`` (every
  operation of the file: number, name, tool, CL points), ``ToolDiameter`` and
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
from .base import FeatureProxy, add_properties, document_or_active, failing_in_words

#: Consecutive CL points closer than this (mm) are one vertex of the polyline.
POINT_TOL = 1e-9


class ToolpathFeature(FeatureProxy):
    """Proxy of the toolpath object (see the module docstring)."""

    KIND = "ABM::Toolpath"

    def __init__(self, obj):
        super().__init__(obj)
        add_properties(obj, "Source", [
            ("App::PropertyFile", "File", "toolpath: a CL file (APT, NX CLSF, CATIA, Creo, SOLIDWORKS CAM, ...) or a "
                                          "toolpath CSV"),
        ])
        add_cam_property(obj)
        add_operation_property(obj)
        add_tool_table_property(obj)
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

    @failing_in_words
    def execute(self, obj):
        """Read the file; set the Shape (polyline of the operation's CL points, part coordinates) and the
        summary properties."""
        toolpath, hints = self.load(obj)
        obj.Shape = polyline(toolpath.cl if hints.operation is None else hints.operation.points_part)
        obj.Operations = [operation.summary() for operation in hints.program.operations] if hints.program else []
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

    def source_name(self, obj):
        """What the toolpath comes from, for messages: the CAM Job's document and label, or the file."""
        job = getattr(obj, "CamJob", None)
        return obj.File if job is None else f"{_document_name(job)}#{job.Label}"

    def load(self, obj):
        """(Toolpath, PathHints) of the CAM Job or the file, cached while it is unchanged."""
        job = getattr(obj, "CamJob", None)
        operation = getattr(obj, "Operation", 0) or None
        if job is not None:
            from ..cam.job_program import job_fingerprint

            chosen = obj.CamOperation.Label if obj.CamOperation is not None else operation
            key = ("job", job.Name, job_fingerprint(job), chosen)
            if self._cache is None or self._cache[0] != key:
                self._cache = (key, self._read(obj, _document_name(job), chosen, job))
            return self._cache[1]
        path = obj.File
        if not path:
            from ..errors import InputError
            raise InputError(f"{obj.Label}: no toolpath file: set File")
        try:
            stamp = os.stat(path).st_mtime_ns
        except OSError:
            stamp = None
        operation = getattr(obj, "Operation", 0) or None
        tools = getattr(obj, "ToolTable", "")
        units = machine_units(obj)
        if self._cache is None or self._cache[0] != (path, stamp, operation, tools, units):
            self._cache = ((path, stamp, operation, tools, units), self._read(obj, path, operation))
        return self._cache[1]

    def _read(self, obj, path, operation, job=None):
        """load_path (of the CAM `job` when given), a program of several operations told in the GUI's words."""
        from ..errors import InputError
        from ..formats.cl import STEP, TOLERANCE, OperationChoiceError

        try:
            if job is not None:
                from ..cam.job_program import job_program

                program = job_program(job, path, TOLERANCE, STEP)
                if isinstance(operation, str):  # the label of the CAM operation chosen
                    named = [op.number for op in program.operations if op.name == operation]
                    if not named:
                        raise InputError(f"{obj.Label}: the CAM operation {operation} is not in the program of "
                                         f"{job.Label} (inactive, or no moves)")
                    operation = named[0]
                return load_path(program.source, operation, program=program)
            tools = getattr(obj, "ToolTable", "")
            if tools:
                from ..formats.gcode.options import ReadOptions

                return load_path(path, operation, options=ReadOptions(tool_table=tools,
                                                                      machine_units=machine_units(obj)))
            return load_path(path, operation)
        except OperationChoiceError as error:
            listing = "; ".join(op.summary() for op in error.operations)
            raise InputError(f"{obj.Label}: {path} holds several operations ({listing}): set the toolpath's "
                             "Operation property to the number of the one to compute") from None

    def migrate(self, obj, saved_version):
        """Objects saved before the Operation property took the file's one milling operation."""
        add_operation_property(obj)
        add_tool_table_property(obj)
        super().migrate(obj, saved_version)


def _document_name(obj):
    """The file of the document of `obj`, or its name before it is saved."""
    return obj.Document.FileName or obj.Document.Name


def add_cam_property(obj):
    """Add CamJob and CamOperation (group "Source") when missing."""
    add_properties(obj, "Source", [
        ("App::PropertyLink", "CamJob", "a FreeCAD CAM Job of this document: its program (wins over File; "
                                        "CamOperation or Operation chooses the operation)"),
        ("App::PropertyLink", "CamOperation", "the CAM Job's operation computed (wins over Operation)"),
    ])


def add_operation_property(obj):
    """Add Operation (group "Source") and Operations (group "Summary", read-only) when missing."""
    if "Operation" not in obj.PropertiesList:
        add_properties(obj, "Source", [
            ("App::PropertyInteger", "Operation", "the file's operation to compute (1-based; 0: its one milling "
                                                  "operation; Operations lists them)", 0),
        ])
    if "Operations" not in obj.PropertiesList:
        add_properties(obj, "Summary", [
            ("App::PropertyStringList", "Operations", "every operation of the file: number, name, tool, CL points"),
        ], read_only=True)


#: Values of ToolTableUnits: the first says nothing (read in mm, a program in inches refused).
TOOL_TABLE_UNITS = ("not said", "mm", "inch")


def add_tool_table_property(obj):
    """Add ToolTable and ToolTableUnits (group "Source") when missing."""
    if "ToolTable" not in obj.PropertiesList:
        add_properties(obj, "Source", [
            ("App::PropertyFile", "ToolTable", "G-code: the tools of its T words, a LinuxCNC tool table or the FreeCAD "
                                               "document (FCStd) that posted the program (empty: none)"),
        ])
    if "ToolTableUnits" not in obj.PropertiesList:
        add_properties(obj, "Source", [
            ("App::PropertyEnumeration", "ToolTableUnits", "units of a LinuxCNC tool table's lengths: the machine's "
                                                           "(its INI file's LINEAR_UNITS), which LinuxCNC does not "
                                                           "write in the table; not said: mm, and a program in inches "
                                                           "with such a table is refused"),
        ])
        obj.ToolTableUnits = list(TOOL_TABLE_UNITS)


def machine_units(obj):
    """ReadOptions' machine_units of the toolpath `obj`: "mm", "inch", or None (not said, or no table)."""
    units = getattr(obj, "ToolTableUnits", TOOL_TABLE_UNITS[0])
    return units if getattr(obj, "ToolTable", "") and units != TOOL_TABLE_UNITS[0] else None


def polyline(points):
    """A wire through points (k, 3) mm, consecutive duplicates dropped; a vertex for one point."""
    points = np.asarray(points, dtype=float)
    keep = np.concatenate([[True], np.linalg.norm(np.diff(points, axis=0), axis=1) > POINT_TOL])
    points = points[keep]
    if len(points) == 1:
        return Part.Vertex(FreeCAD.Vector(*points[0]))
    return Part.makePolygon([FreeCAD.Vector(*p) for p in points.tolist()])


def create_toolpath(doc=None, path=None, name="Toolpath", *, cam_job=None, cam_operation=None, operation=0,
                    tool_table="", tool_table_units=TOOL_TABLE_UNITS[0]):
    """Add a toolpath object reading `path` (CSV, APT, CLS, G-code), or the program of `cam_job` (a FreeCAD CAM
    Job of the document), to `doc` (default the active document; RuntimeError if none); the operation
    computed: `cam_operation` (an operation of the Job), else `operation` (1-based; 0: the program's one
    milling operation); tool_table: a G-code program's tool table (LinuxCNC, or the FCStd that posted it);
    tool_table_units: the units of a LinuxCNC table's lengths (TOOL_TABLE_UNITS).
    Returns the object (not yet recomputed)."""
    doc = document_or_active(doc)
    obj = doc.addObject("Part::FeaturePython", name)
    ToolpathFeature(obj)
    if path is not None:
        obj.File = os.fspath(path)
    obj.CamJob, obj.CamOperation = cam_job, cam_operation
    obj.Operation = operation
    obj.ToolTable = os.fspath(tool_table)
    obj.ToolTableUnits = tool_table_units or TOOL_TABLE_UNITS[0]
    return obj
