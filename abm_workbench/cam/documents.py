"""FreeCAD documents (FCStd) as sources of programs and tools: a CAM Job, its tool controllers.

A document already open (in the GUI, or by an earlier call) is used as it is and left open;
another is opened hidden and closed again. Reading needs none of the CAM workbench's Python
modules: the commands, tool controllers and toolbits are properties saved in the document.
"""

import contextlib
import os

from ..cad.freecad_env import FreeCAD
from ..errors import InputError
from .freecad_cam import jobs, operations, tool_controller
from .job_program import job_program
from .toolbits import controller_tool


@contextlib.contextmanager
def opened(path):
    """The FreeCAD document of the FCStd at `path` for the block: one already open, else opened hidden
    and closed after. InputError when it cannot be opened."""
    name = os.fspath(path)
    already = [doc for doc in FreeCAD.listDocuments().values() if doc.FileName and same_file(doc.FileName, name)]
    if already:
        yield already[0]
        return
    if not os.path.isfile(name):
        raise InputError(f"{name}: no such file")
    try:
        document = FreeCAD.openDocument(name, True)
    except Exception as error:  # noqa: BLE001 (FreeCAD raises several kinds)
        raise InputError(f"{name}: cannot open as a FreeCAD document: {error}") from None
    try:
        yield document
    finally:
        FreeCAD.closeDocument(document.Name)


def same_file(a, b):
    """Whether paths a and b name the same existing file."""
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def find_job(document, name, path):
    """The CAM Job of `document` named `name` (its Name or Label), or its one Job with `name` None.
    InputError naming `path` and the Jobs there otherwise."""
    found = jobs(document)
    listed = ", ".join(f"{job.Label} ({job.Name})" if job.Label != job.Name else job.Name for job in found)
    if name is None:
        if len(found) == 1:
            return found[0]
        if not found:
            raise InputError(f"{path}: no FreeCAD CAM Job in the document")
        raise InputError(f"{path}: several CAM Jobs ({listed}): choose one with --cam-job NAME")
    chosen = [job for job in found if job.Name == name] or [job for job in found if job.Label == name]
    if len(chosen) != 1:
        raise InputError(f"{path}: {'no' if not chosen else 'several'} CAM Job named {name!r} (its Jobs: "
                         f"{listed or 'none'})")
    return chosen[0]


def read_job_file(path, options, tolerance, step):
    """The Program of the CAM Job of the FCStd at `path` (options.cam_job names it; None or no options: its
    one Job); arcs to `tolerance` mm, their CL points at most `step` mm apart."""
    name = os.fspath(path)
    with opened(name) as document:
        job = find_job(document, getattr(options, "cam_job", None), name)
        return job_program(job, name, tolerance, step)


def job_stock(path, name=None, required=True):
    """The Name of the Stock object of the CAM Job `name` (None: the one Job) of the FCStd at `path`.
    InputError when there is no such Job or it has no Stock; with `required` False, None instead when the
    document holds no CAM Job at all."""
    with opened(path) as document:
        if not required and not jobs(document):
            return None
        job = find_job(document, name, os.fspath(path))
        if getattr(job, "Stock", None) is None:
            raise InputError(f"{os.fspath(path)}: the CAM Job {job.Label} has no Stock: give the stock (--stock)")
        return job.Stock.Name


def document_tools(path):
    """{tool number: ToolSpec} of the tool controllers of the FCStd at `path` (a posted program's tool table):
    those the Jobs' operations use first, then the others. InputError when two controllers the operations use
    give one number different tools."""
    name = os.fspath(path)
    tools, owners = {}, {}
    with opened(name) as document:
        used = [tool_controller(op) for job in jobs(document) for op in operations(job)]
        controllers = [obj for obj in document.Objects if all(
            prop in getattr(obj, "PropertiesList", ()) for prop in ("ToolNumber", "Tool", "SpindleSpeed"))]
        controllers.sort(key=lambda controller: not any(controller is other for other in used))
        for controller in controllers:
            number = int(controller.ToolNumber)
            tool, _ = controller_tool(controller)
            in_use = any(controller is other for other in used)
            if number in tools and in_use and not tool.same_tool(tools[number]):
                raise InputError(f"{name}: T{number}: the tool controllers {owners[number]} and {controller.Label} "
                                 f"give tool {number} different tools ({tools[number].describe()}, "
                                 f"{tool.describe()})")
            tools.setdefault(number, tool)
            owners.setdefault(number, controller.Label)
    return tools
