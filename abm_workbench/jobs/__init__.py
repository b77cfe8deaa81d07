"""The job model: one declaration of every parameter, jobs built from any front end, and the runs they share.

- :mod:`.parameters`: each parameter once (name, label, unit, range, default, help, option,
  property); ParameterError carries the parameter, each front end words it.
- :mod:`.inputs`: reading the stock, the toolpath (and what its file says), the job file.
- :mod:`.resolve`: each cutting parameter from the toolpath file, the front end, the job file or
  its default, with where it came from.
- :mod:`.job`: :class:`Job` (one run's inputs) and :func:`prepare` (resolved and checked).
- :mod:`.run`: engage, validate and schedule, for the command line and the GUI alike.
"""

#: The names this package gives, by the module that defines them (imported when a name is first asked for,
#: so that a front end importing one part, e.g. the parameters for its options, does not import the rest).
_NAMES = {
    "inputs": ("SOLID_SUFFIXES", "SWEPT_MARGIN", "WALL_MODELS", "WALL_POINTS", "PathHints", "Stock", "load_job",
               "load_path", "load_stock", "swept_y_window"),
    "job": ("Job", "Prepared", "cl_indices", "force_model", "is_solid", "load_job_stock", "prepare"),
    "parameters": ("BY_NAME", "CUTTING", "MATERIAL_CHOICES", "PARAMETERS", "REQUIRED", "Parameter", "label_words",
                   "option_words"),
}
# Imported at once: the function resolve shares its name with its module, which importing any other
# part would otherwise put in its place.
from .resolve import Parameters, resolve, tool_and_settings  # noqa: E402


def __getattr__(name):
    """A name of :data:`_NAMES` from its module (submodules such as ``run`` are imported as usual)."""
    if name in _NAMES["inputs"]:
        from . import inputs as module
    elif name in _NAMES["job"]:
        from . import job as module
    elif name in _NAMES["parameters"]:
        from . import parameters as module
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(module, name)


__all__ = [
    "BY_NAME", "CUTTING", "Job", "MATERIAL_CHOICES", "PARAMETERS", "Parameter", "Parameters",
    "PathHints", "Prepared", "REQUIRED", "SOLID_SUFFIXES", "SWEPT_MARGIN", "Stock", "WALL_MODELS", "WALL_POINTS",
    "cl_indices", "force_model", "is_solid", "label_words", "load_job", "load_job_stock", "load_path", "load_stock",
    "option_words", "prepare", "resolve", "swept_y_window", "tool_and_settings",
]
