"""Errors in the GUI's words, and a recompute that fails like a command: shared by the commands and the task panel.

Messages go to the report view (``FreeCAD.Console.PrintError``) as ``ABM: <plain words>``: a bad
parameter in its label's words (``jobs.label_words``), FreeCAD's own exceptions by their text.
"""

import FreeCAD

from ..errors import ParameterError
from ..jobs import label_words
from . import view_providers

#: Prefix of the workbench's lines in the report view.
PROG = "ABM"


class CommandError(Exception):
    """A command cannot do what was asked (the message says why)."""


def message_of(error):
    """The text of `error` in the GUI's words: a ParameterError by its parameter's label, FreeCAD's own
    exceptions by their dict's "sErrMsg", others as they say it."""
    if isinstance(error, ParameterError):
        return label_words(error)
    if error.args and isinstance(error.args[0], dict) and "sErrMsg" in error.args[0]:
        return error.args[0]["sErrMsg"]
    return str(error)


def report_error(error):
    """Print `error` to the report view in the GUI's words (message_of)."""
    FreeCAD.Console.PrintError(f"{PROG}: {message_of(error)}\n")


def recompute_checked(doc, objects):
    """Recompute `doc`; CommandError with the status string of the first of `objects` left invalid."""
    doc.recompute()
    for obj in objects:
        if "Invalid" in obj.State or "Error" in obj.State:
            raise CommandError(obj.getStatusString())
    for obj in objects:
        view_providers.refresh(obj)
