"""FreeCAD's CAM (the Path workbench) as this package reads it, and the seam between its versions.

FreeCAD 0.20 keeps its CAM in the Path workbench's ``PathScripts`` (``PathScripts.PathJob``,
``PathScripts.PathToolController``, …), FreeCAD 1.x in the CAM workbench's ``Path.Main``
(``Path.Main.Job``, ``Path.Tool.Controller``, …). The document objects and their properties are
the same in both, so objects are recognised here by the properties they have, never by their
Python classes:

- a Job has ``Operations`` (a group of operations, in order), ``Tools``, ``Stock`` and ``Model``;
- an operation has a ``Path`` (its commands) and, itself or through the ``Base`` of a dressup,
  ``Active`` and a ``ToolController``;
- a tool controller has ``ToolNumber``, ``SpindleSpeed``, ``SpindleDir``, its own ``Path`` (the
  tool change and spindle commands its posts write) and a ``Tool``.

Only restoring a document's objects needs the version's modules (their Python classes):
:func:`make_importable` puts FreeCAD's CAM and Draft folders on ``sys.path`` where the interpreter
is not FreeCAD's own, and imports the modules of :data:`CAM_MODULES` that exist, which a document
restored in a plain interpreter cannot always import by itself.
"""

import importlib
import os
import sys

from ..cad.freecad_env import FreeCAD

#: The folders of FreeCAD's resource directory that hold the CAM workbench and what it imports.
_FOLDERS = ("Mod/Path", "Mod/CAM", "Mod/Draft", "Ext")
#: Modules holding classes of a CAM document's objects, by FreeCAD version (0.20, then 1.x).
CAM_MODULES = (("PathScripts.PathJob", "draftobjects.clone"), ("Path.Main.Job", "draftobjects.clone"))


def make_importable():
    """Put FreeCAD's CAM folders on sys.path (where missing) and import a version's CAM modules; True
    when one version's all imported."""
    resources = FreeCAD.getResourceDir()
    for folder in _FOLDERS:
        path = os.path.join(resources, folder)
        if os.path.isdir(path) and path not in sys.path:
            sys.path.append(path)
    for modules in CAM_MODULES:
        try:
            for module in modules:
                importlib.import_module(module)
        except ImportError:
            continue
        return True
    return False


def is_job(obj):
    """Whether document object `obj` is a CAM Job."""
    names = getattr(obj, "PropertiesList", ())
    return all(name in names for name in ("Operations", "Tools", "Stock", "Model"))


def jobs(document):
    """The CAM Jobs of `document`, in the document's order."""
    return [obj for obj in document.Objects if is_job(obj)]


def op_property(op, name):
    """Property `name` of operation `op`, or of the operation under it (a dressup's Base), or None."""
    while op is not None:
        if name in getattr(op, "PropertiesList", ()):
            return getattr(op, name)
        op = getattr(op, "Base", None) if "Base" in getattr(op, "PropertiesList", ()) else None
    return None


def operations(job):
    """The operations of `job` in its order, each with its Path (a dressup in place of its base)."""
    return [op for op in job.Operations.Group if "Path" in getattr(op, "PropertiesList", ())]


def is_active(op):
    """Whether operation `op` is active (posted); an operation without Active is."""
    active = op_property(op, "Active")
    return True if active is None else bool(active)


def tool_controller(op):
    """The tool controller of operation `op`, or None."""
    return op_property(op, "ToolController")


def job_of(obj):
    """The Job that holds document object `obj` (an operation, through its group or the dressups over it;
    `obj` itself when it is a Job), or None."""
    seen, todo = set(), [obj]
    while todo:
        item = todo.pop(0)
        if is_job(item):
            return item
        if item.Name not in seen:
            seen.add(item.Name)
            todo.extend(item.InList)
    return None
