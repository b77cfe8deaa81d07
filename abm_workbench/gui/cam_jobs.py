"""The engagement of a FreeCAD CAM Job, made from what is selected (ABM_EngageCamJob).

A selected Job stands for every operation of its program the engine computes (flat-end mills with
cutting moves); a selected operation (or one under a dressup) for itself, which must be one. Each
operation gets a toolpath linked to the Job and the operation (features.toolpath: it follows the Job
when the document recomputes) and an engagement of it with the Job's stock (one stock object per Job,
linked to the Job's Stock solid). The cut comes from the operation's tool controller: the toolbit's
diameter, flute length and flutes, the spindle speed, and the feed per tooth of its horizontal feed,
HorizFeed / (rpm · flutes); what it does not give, from the preferences (Edit → Preferences → ABM).
"""

from ..cam.freecad_cam import is_job, job_of, operations, tool_controller
from ..cam.job_program import job_program
from ..cam.toolbits import controller_tool
from ..formats.cl import STEP, TOLERANCE
from . import preferences, view_providers
from .i18n import noop, translate
from .reporting import CommandError

#: The required values of preferences.REQUIRED in words, for messages.
REQUIRED_WORDS = {"diameter": noop("diameter"), "flutes": noop("flutes"), "flute_length": noop("flute length"),
                  "feed_per_tooth": noop("feed per tooth")}


def chosen(selection):
    """[(Job, its operation or None for all it computes)] of the selected objects, in order; CommandError
    when nothing selected is a Job or an operation of one."""
    found = []
    for obj in selection:
        job = job_of(obj)
        if job is None:
            continue
        if is_job(obj):
            found.append((job, None))
        else:
            placed = next((op for op in operations(job) if _dresses(op, obj)), None)
            if placed is not None and (job, placed) not in found:
                found.append((job, placed))
    if not found:
        raise CommandError(translate("select a FreeCAD CAM Job, or operations of one"))
    return [(job, op) for job, op in found if op is None or (job, None) not in found]  # a Job chosen takes all


def _dresses(op, obj):
    """Whether operation `op` of a Job is `obj` or a dressup over it (dressups link their operation as
    Base; an operation's own Base is a list of faces)."""
    while op is not None and not isinstance(op, (list, tuple)):
        if op is obj:
            return True
        op = getattr(op, "Base", None)
    return False


def operations_to_engage(job, op):
    """The CAM operations to engage of `job`: `op` (CommandError when the engine cannot compute it), or
    with op None every operation of the Job's program the engine computes."""
    program = job_program(job, job.Document.FileName or job.Document.Name, TOLERANCE, STEP)
    by_label = {operation.name: operation for operation in program.operations}
    if op is not None:
        operation = by_label.get(op.Label)
        if operation is None:
            raise CommandError(translate("{operation}: not in the program of {job} (inactive, or no moves)",
                                         operation=op.Label, job=job.Label))
        if operation.refusal() is not None:
            raise CommandError(operation.refusal())
        return [op]
    found = [cam_op for cam_op in operations(job)
             if cam_op.Label in by_label and by_label[cam_op.Label].refusal() is None]
    if not found:
        reasons = "; ".join(operation.refusal() for operation in program.operations) or translate(
            "no operation has moves")
        raise CommandError(translate("{job}: no operation the engine computes ({reasons})", job=job.Label,
                                     reasons=reasons))
    return found


def settings_of(op):
    """create_engagement's keywords for CAM operation `op`: its tool controller's tool, spindle and
    horizontal feed, the rest from the preferences; CommandError for a required value given nowhere."""
    settings = preferences.engagement_defaults()
    controller = tool_controller(op)
    if controller is None:
        raise CommandError(translate("{operation}: no tool controller", operation=op.Label))
    tool, _ = controller_tool(controller)
    for key, value in (("diameter", tool.diameter), ("corner_radius", tool.corner_radius),
                       ("flute_length", tool.flute_length), ("flutes", tool.flutes)):
        if value is not None:
            settings[key] = value
    rpm = float(controller.SpindleSpeed)
    feed = float(controller.HorizFeed.getValueAs("mm/min"))
    if rpm > 0.0:
        settings["spindle_rpm"] = rpm
        if feed > 0.0 and settings.get("flutes"):
            settings["feed_per_tooth"] = feed / (rpm * settings["flutes"])
    missing = [key for key in preferences.REQUIRED if not settings.get(key)]
    if missing:
        raise CommandError(translate("{operation}: {controller} gives no {value} (set it in its toolbit, or in Edit → "
                                     "Preferences → ABM)", operation=op.Label, controller=controller.Label,
                                     value=translate(REQUIRED_WORDS[missing[0]])))
    return settings


def engage(doc, selection):
    """Toolpaths and engagements of the chosen operations (module docstring), not yet recomputed; the
    engagements made."""
    from ..features import create_engagement, create_stock, create_toolpath

    made, stocks = [], {}
    for job, op in chosen(selection):
        for cam_op in operations_to_engage(job, op):
            settings = settings_of(cam_op)
            if job.Name not in stocks:
                stocks[job.Name] = _stock_of(doc, job) or create_stock(doc, job.Stock, name="Stock")
                view_providers.attach(stocks[job.Name])
            toolpath = create_toolpath(doc, cam_job=job, cam_operation=cam_op, name="Toolpath")
            toolpath.Label = f"{cam_op.Label} toolpath"
            engagement = create_engagement(doc, stocks[job.Name], toolpath, **settings)
            engagement.Label = f"{cam_op.Label} engagement"
            for obj in (toolpath, engagement):
                view_providers.attach(obj)
            made.append(engagement)
    return made


def _stock_of(doc, job):
    """The ABM stock of the document linked to `job`'s Stock, or None."""
    for obj in doc.Objects:
        if view_providers.kind(obj) == "ABM::Stock" and obj.SourceObject is job.Stock:
            return obj
    return None
