"""The job model: one declaration of every parameter, jobs built from any front end, and the runs they share.

- :mod:`.parameters`: each parameter once (name, label, unit, range, default, help, option,
  property); ParameterError carries the parameter, each front end words it.
- :mod:`.inputs`: reading the stock, the toolpath (and what its file says), the job file.
- :mod:`.resolve`: each cutting parameter from the toolpath file, the front end, the job file or
  its default, with where it came from.
- :mod:`.job`: :class:`Job` (one run's inputs) and :func:`prepare` (resolved and checked).
- :mod:`.run`: engage, validate and schedule, for the command line and the GUI alike.
"""

from .inputs import (SOLID_SUFFIXES, SWEPT_MARGIN, WALL_MODELS, WALL_POINTS, PathHints, Stock,
                     load_job, load_path, load_stock, swept_y_window)
from .job import Job, Prepared, cl_indices, force_model, is_solid, load_job_stock, prepare
from .parameters import BY_NAME, CUTTING, MATERIAL_CHOICES, PARAMETERS, REQUIRED, Parameter, label_words, option_words
from .resolve import Parameters, resolve, tool_and_settings

__all__ = [
    "BY_NAME", "CUTTING", "Job", "MATERIAL_CHOICES", "PARAMETERS", "Parameter", "Parameters",
    "PathHints", "Prepared", "REQUIRED", "SOLID_SUFFIXES", "SWEPT_MARGIN", "Stock", "WALL_MODELS", "WALL_POINTS",
    "cl_indices", "force_model", "is_solid", "label_words", "load_job", "load_job_stock", "load_path", "load_stock",
    "option_words", "prepare", "resolve", "swept_y_window", "tool_and_settings",
]
