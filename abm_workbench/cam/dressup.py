"""Scheduled feeds back into FreeCAD's CAM: a dressup of an operation whose feed moves carry the schedule.

``schedule`` computes a feed per CL point (abm_workbench.scheduling); on a FreeCAD CAM Job those CL
points come from the commands of an operation's Path (cam.job_program: each CL point's line is the
number of its command). :func:`command_feeds` gives each command the lowest feed of its CL points
(an arc's are several), and the dressup (a ``Path::FeaturePython`` with proxy :class:`FeedDressup`,
group "Feeds": ``ScheduledFeeds``, mm/min, one per command of the operation's Path, 0 where none is
scheduled; ``Schedule``, how the feeds were found) takes the operation's place in the Job. Its Path is
the operation's, every feed move (G1, G2, G3) carrying an explicit F: its scheduled feed, else the
operation's own F in force there, so nothing of the schedule runs on into the moves after it. The
Job's post, whatever it is, then writes the scheduled F words; every other command is the
operation's own. The operation stays in the document under the dressup (its Base), unchanged.

A dressup whose operation has since changed its number of commands refuses to recompute: schedule
again. The dressup's proxy is this module's class, which FreeCAD restores where the workbench is
installed; elsewhere the saved Path is still what the posts write.
"""

import os
import shutil
import tempfile

import numpy as np

from ..cad.freecad_env import FreeCAD
from ..errors import InputError
from .documents import find_job, same_file
from .freecad_cam import is_active, make_importable, operations

#: Commands that move at the feed rate.
FEED_MOVES = {"G1", "G01", "G2", "G02", "G3", "G03"}
#: FreeCAD's commands keep F in mm/s.
_SECONDS_PER_MINUTE = 60.0


def command_feeds(operation, feed, count):
    """(count,) mm/min: for each command of an operation's Path (count of them) the lowest of `feed` (n,)
    mm/min over the CL points it made (operation.lines, 1-based command numbers), 0 for the others."""
    feed = np.asarray(feed, dtype=float).reshape(-1)
    if feed.shape != operation.lines.shape:
        raise ValueError(f"feed has {feed.size} values, {operation.label()} {operation.lines.size} CL points")
    per_command = np.full(count, np.inf)
    np.minimum.at(per_command, operation.lines - 1, feed)
    per_command[~np.isfinite(per_command)] = 0.0
    return per_command


class FeedDressup:
    """Proxy of the dressup (module docstring)."""

    KIND = "ABM::FeedDressup"

    def __init__(self, obj, base):
        obj.addProperty("App::PropertyLink", "Base", "Base", "the operation whose feeds are scheduled")
        obj.addProperty("App::PropertyFloatList", "ScheduledFeeds", "Feeds",
                        "feed (mm/min) of each command of the operation's Path, 0 where none is scheduled")
        obj.addProperty("App::PropertyString", "Schedule", "Feeds", "how the feeds were scheduled")
        obj.setEditorMode("ScheduledFeeds", 1)
        obj.setEditorMode("Schedule", 1)
        obj.Base = base
        obj.Proxy = self

    def __getstate__(self):
        return {"kind": self.KIND}

    def __setstate__(self, state):
        return None

    dumps, loads = __getstate__, __setstate__

    def execute(self, obj):
        """The Path: the operation's commands, each feed move with its scheduled F (module docstring)."""
        import Path

        commands = obj.Base.Path.Commands
        feeds = list(obj.ScheduledFeeds)
        if len(feeds) != len(commands):
            raise RuntimeError(f"{obj.Label}: {obj.Base.Label} has {len(commands)} commands now, the schedule "
                               f"{len(feeds)}: the operation changed since its feeds were scheduled; schedule again")
        dressed, in_force = [], None
        for command, feed in zip(commands, feeds):
            if command.Name not in FEED_MOVES:
                dressed.append(command)
                continue
            parameters = dict(command.Parameters)
            if parameters.get("F", 0.0) > 0.0:
                in_force = parameters["F"]
            value = feed / _SECONDS_PER_MINUTE if feed > 0.0 else in_force
            if value is not None:
                parameters["F"] = value
            dressed.append(Path.Command(command.Name, parameters))
        obj.Path = Path.Path(dressed)


def add_feed_dressup(job, op, feeds, schedule=""):
    """Put a dressup of operation `op` (in `job`) with `feeds` (mm/min per command of its Path) in the op's
    place in the Job; returns it (not yet recomputed)."""
    document = op.Document
    obj = document.addObject("Path::FeaturePython", f"{op.Name}_ScheduledFeeds")
    obj.Label = f"{op.Label} (scheduled feeds)"
    FeedDressup(obj, op)
    obj.ScheduledFeeds = [float(value) for value in feeds]
    obj.Schedule = schedule
    group = list(job.Operations.Group)
    group[group.index(op)] = obj
    job.Operations.Group = group
    return obj


def write_scheduled_document(source, out, job_name, operation, feed, schedule=""):
    """Write the FCStd `source` to `out` with operation `operation` (a cl.program.Operation of its Job
    `job_name`, read by cam.job_program) dressed with `feed` (n,) mm/min per CL point; whole or not at all.
    The source file is left as it is. InputError when the source is open in FreeCAD already, or when
    FreeCAD's CAM modules cannot be imported (the document's objects would be saved without them)."""
    source, out = os.fspath(source), os.fspath(out)
    if any(doc.FileName and same_file(doc.FileName, source) for doc in FreeCAD.listDocuments().values()):
        raise InputError(f"{source}: the document is open in FreeCAD: add the dressup there, or close it first")
    if not make_importable():
        raise InputError(f"{source}: FreeCAD's CAM workbench cannot be imported here, and the document saved "
                         "without it would lose its CAM objects' behaviour")
    document = FreeCAD.openDocument(source, True)
    folder = tempfile.mkdtemp(prefix=".abm-", dir=os.path.dirname(os.path.abspath(out)))
    try:
        job = find_job(document, job_name, source)
        op = next(op for op in operations(job) if is_active(op) and op.Label == operation.name)
        dressup = add_feed_dressup(job, op, command_feeds(operation, feed, len(op.Path.Commands)), schedule)
        dressup.recompute()  # only the dressup: the operations stay as FreeCAD computed them where they were made
        if not dressup.isValid():
            raise InputError(f"{source}: {dressup.Label}: {dressup.getStatusString()}")
        staged = os.path.join(folder, "scheduled.FCStd")
        document.saveAs(staged)
        os.replace(staged, out)
    finally:
        FreeCAD.closeDocument(document.Name)
        shutil.rmtree(folder, ignore_errors=True)
    return out
