"""Errors in the GUI's words, and a recompute that fails like a command: shared by the commands and the task panel.

Messages go to the report view (``FreeCAD.Console.PrintError``) as ``ABM: <plain words>``: a bad
parameter in its label's words (``jobs.label_words``), FreeCAD's own exceptions by their text; a
message of the engine or a reader that names a command-line option (``--tool-table FILE``) names
what the GUI has for it instead (:data:`OPTION_WORDS`, :func:`gui_words`). Messages of the engine and
the readers are shown in the user's language where their template has a translation (:func:`localized`), the
operating system's words of the common file errors too (:func:`os_words`); :func:`install` lets the features
print their warnings and notes that way.
"""

import errno
import functools
import re

import FreeCAD

from ..errors import ParameterError
from ..features import base as features_base
from ..jobs.parameters import label_words
from . import view_providers
from .i18n import PARAMETERS, TEMPLATE, noop, translate
from .messages import CONTEXT as MESSAGES, Catalogue

#: Prefix of the workbench's lines in the report view.
PROG = "ABM"


class CommandError(Exception):
    """A command cannot do what was asked (the message says why)."""


#: Command-line options that messages of the engine and the readers name, as the GUI names them.
OPTION_WORDS = {
    "tool-table": noop("the toolpath's ToolTable property"),
    "machine-units": noop("the toolpath's ToolTableUnits property"),
    "operation": noop("the toolpath's Operation property"),
    "helix": noop("the helix angle β"),
    "stock-model": noop("the engagement's StockModel property"),
    "cam-job": noop("a toolpath linked to the CAM Job"),
    "machine": noop("a machine file (not read by the GUI yet)"),
    "offsets": noop("work offsets (not read by the GUI yet)"),
    "walls": noop("the wall model"),
    "y-window": noop("the y window"),
    "forces": noop("Cutting forces"),
    "cl": noop("the CL points"),
}
#: Whole phrases of the command line's messages, as the GUI says them.
PHRASES = (("give the tool table (--tool-table FILE: ", noop("set the toolpath's ToolTable property (")),
           ("choose one with --operation N", noop("choose one in the toolpath's Operation property")),
           ("say them (--machine-units mm or inch)", noop("say them in the toolpath's ToolTableUnits property (mm "
                                                          "or inch)")))
_OPTION = re.compile(r"--([a-z][a-z-]*)(?: [A-Z]+\b)?")
#: The operating system's words for the common file errors (as Linux's C library says them, which Python puts
#: in an OSError's text: "[Errno 2] No such file or directory: 'x'"), by their number.
OS_WORDS = {
    errno.ENOENT: noop("No such file or directory"),
    errno.EACCES: noop("Permission denied"),
    errno.EISDIR: noop("Is a directory"),
    errno.ENOTDIR: noop("Not a directory"),
    errno.ENOSPC: noop("No space left on device"),
    errno.EROFS: noop("Read-only file system"),
    errno.EEXIST: noop("File exists"),
    errno.ENAMETOOLONG: noop("File name too long"),
    errno.ELOOP: noop("Too many levels of symbolic links"),
}
_ERRNO = re.compile(r"\[Errno (\d+)\] ([^:\n]+)")


def gui_words(text):
    """`text` with the command-line options it names (``--tool-table FILE``) put as the GUI names them."""
    for phrase, words in PHRASES:
        text = text.replace(phrase, translate(words))

    def word(match):
        name = match.group(1)
        return translate(OPTION_WORDS[name]) if name in OPTION_WORDS else name.replace("-", " ")
    return _OPTION.sub(word, text)


def os_words(text):
    """`text` with the operating system's words of each file error it holds (``[Errno 2] No such file or
    directory``) in the user's language, where they are exactly those of :data:`OS_WORDS` for their number; the
    number, the file's name and the rest as they are."""
    def word(match):
        number, words = int(match.group(1)), match.group(2)
        if OS_WORDS.get(number) != words:
            return match.group(0)
        return f"[Errno {number}] {translate(words)}"
    return _ERRNO.sub(word, text)


@functools.lru_cache(maxsize=1)
def _catalogue():
    """The messages' templates of the translation template (an empty catalogue where none is shipped)."""
    try:
        return Catalogue.from_ts(TEMPLATE)
    except (OSError, SyntaxError):  # ElementTree's ParseError is a SyntaxError
        return Catalogue([])


def localized(text):
    """`text`, a message of the engine, a reader, the job model or the features, in the user's language where
    its template has a translation (messages.Catalogue over the translation template), else as it is; the
    operating system's file errors in it too (:func:`os_words`)."""
    return os_words(_catalogue().translated(text, lambda template: translate(template, MESSAGES)))


def install():
    """Let the features print their warnings and notes in the user's language (features.base.tell through
    :func:`localized`); InitGui.py calls it as FreeCAD starts, before documents are restored."""
    features_base.localize_with(localized)


def parameter_words(error):
    """A ParameterError in the user's words (jobs.label_words, its label and detail translated): 'Tool
    diameter must be positive, got -3 mm.'"""
    return label_words(error, lambda label: translate(label, PARAMETERS), localized)


def message_of(error):
    """The text of `error` in the GUI's words: a ParameterError by its parameter's label, FreeCAD's own
    exceptions by their dict's "sErrMsg", others as they say it; in the user's language (localized) and
    with command-line options as the GUI names them (:func:`gui_words`)."""
    if isinstance(error, ParameterError):
        return gui_words(parameter_words(error))
    if error.args and isinstance(error.args[0], dict) and "sErrMsg" in error.args[0]:
        return gui_words(localized(error.args[0]["sErrMsg"]))
    return gui_words(localized(str(error)))


def report_error(error, parent=None):
    """Print `error` to the report view in the GUI's words (message_of); with a `parent` widget, also say
    it in a message box (``ABM_Error``)."""
    message = message_of(error)
    FreeCAD.Console.PrintError(f"{PROG}: {message}\n")
    if parent is not None:
        from PySide import QtGui

        box = QtGui.QMessageBox(QtGui.QMessageBox.Warning, "ABM", message, QtGui.QMessageBox.Ok, parent)
        box.setObjectName("ABM_Error")
        box.exec_()
        box.deleteLater()


def recompute_checked(doc, objects):
    """Recompute `doc`; CommandError with the status string of the first of `objects` left invalid."""
    doc.recompute()
    for obj in objects:
        if "Invalid" in obj.State or "Error" in obj.State:
            raise CommandError(obj.getStatusString())
    for obj in objects:
        view_providers.refresh(obj)
