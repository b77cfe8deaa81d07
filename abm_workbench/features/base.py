"""What the ABM document objects share: property helpers, the version, the proxy's saved state.

Every feature is a ``Part::FeaturePython`` whose ``Proxy`` is one of the classes of this
package. The proxy keeps what it computes (a Staircase, a Toolpath, an Engagement) as plain
Python attributes that are *not* saved: :meth:`FeatureProxy.__getstate__` returns only the
proxy's kind and the format version, so nothing of the engine is pickled into the document.
What a feature computes either is its Shape (saved by FreeCAD as BREP), a read-only property,
or, for the engagement, a results CSV beside the document (see :mod:`.engagement`).

Input files: the stock's ``SourceFile`` and the toolpath's ``File`` (:data:`FILE_PROPERTIES`) are
absolute paths; as the document is saved (:func:`remember_relative`, called by the engagement
module's save observer) each is also remembered relative to the document's folder, in
``SourceFileRelative`` / ``FileRelative``. On restore, an input file that is not where its
absolute path says but is where its relative one says (the project folder moved or copied
whole) is re-pointed there (:func:`repoint_relative`). What is still missing,
:func:`missing_files` lists and :func:`repoint` re-points to one folder holding the files by
name (the GUI asks for that folder in one dialog).

Migration: every object carries a read-only ``Version`` property (group "Base"), set to
:data:`VERSION` when it is created. On restore, :meth:`FeatureProxy.onDocumentRestored` calls
:meth:`FeatureProxy.migrate` with the version the file was saved with; a later version of the
workbench adds missing properties, renames old ones, etc. there, then sets ``Version``.
"""

import functools
import os
import sys

from ..cad.freecad_env import FreeCAD
from ..errors import InputError, ParameterError

#: Version of the document objects' properties: bump it when they change, and migrate (4: the toolpath's Operation;
#: 5: the engagement's stock model; 6: its corner radius).
VERSION = 6
#: Editor modes of FreeCAD properties.
READ_ONLY, HIDDEN = 1, 2
#: The property holding the input file of each kind of object; its relative twin adds RELATIVE.
FILE_PROPERTIES = {"ABM::Stock": "SourceFile", "ABM::Toolpath": "File"}
RELATIVE = "Relative"
#: Property type flag: changing it does not touch the object (FreeCAD's Prop_Output).
PROP_OUTPUT = 8


class _Named(type):
    """Metaclass of RecomputeFailed: see there."""

    previous = None  # sys.tracebacklimit before FreeCAD reported one

    def __str__(cls):
        _Named.previous = getattr(sys, "tracebacklimit", None)
        sys.tracebacklimit = 0
        return PROG


class RecomputeFailed(InputError, metaclass=_Named):
    """An InputError that fails an object's recompute with its message alone, no Python traceback.

    FreeCAD 0.20 reports an exception leaving a Python feature's ``execute`` as
    ``<traceback><str(type)>: <message>`` (``PyException``: the type and message as strings, then
    the traceback printed by ``PyTraceBack_Print``), and marks the object Invalid with the message
    as its status string. str() of this class, which FreeCAD takes first, is "ABM" and sets
    ``sys.tracebacklimit`` to 0, so the traceback prints as nothing; the instance, which FreeCAD
    lets go right after, puts the limit back as it is deleted. Python code catching it sees an
    InputError with the same message.
    """

    def __del__(self):
        if getattr(sys, "tracebacklimit", None) == 0:
            if _Named.previous is None:
                del sys.tracebacklimit
            else:
                sys.tracebacklimit = _Named.previous


#: What puts the features' printed messages into the user's language (see :func:`localize_with`).
_LOCALIZER = [str]


def localize_with(function):
    """Let `function(text)` put the messages the features print into the user's language: the GUI gives its
    own (gui.reporting.localized, by gui.reporting.install as FreeCAD starts); headless they are printed as
    they are. The features import no GUI module."""
    _LOCALIZER[0] = function


def tell(obj, message, kind="Warning"):
    """Print `message` about `obj` to the report view as ``<label>: <message>`` (``FreeCAD.Console.Print<kind>``:
    Warning, Message or Error), in the user's language where the GUI runs (:func:`localize_with`)."""
    getattr(FreeCAD.Console, f"Print{kind}")(f"{obj.Label}: {_LOCALIZER[0](message)}\n")


#: How FreeCAD names a failed recompute of an engagement in the report view ("ABM: <message>").
PROG = "ABM"


def failing_in_words(execute):
    """Decorate a proxy's ``execute(self, obj)``: an InputError (a ParameterError too) fails the recompute
    with its message alone, no Python traceback in the report view (:class:`RecomputeFailed`)."""

    @functools.wraps(execute)
    def wrapped(self, obj):
        try:
            return execute(self, obj)
        except RecomputeFailed:
            raise
        except (InputError, ParameterError) as error:
            raise RecomputeFailed(str(error)) from None

    return wrapped


def file_property(obj):
    """The name of the input-file property of the ABM object `obj`, or None (no file, not ABM)."""
    return FILE_PROPERTIES.get(getattr(getattr(obj, "Proxy", None), "KIND", None))


def remember_relative(obj, filename):
    """Remember the input file of `obj` relative to the folder of `filename` (the document being saved)."""
    prop = file_property(obj)
    path = getattr(obj, prop, "") if prop else ""
    if not path:
        return
    name = prop + RELATIVE
    if name not in obj.PropertiesList:
        obj.addProperty("App::PropertyString", name, obj.getGroupOfProperty(prop),
                        f"{prop} relative to the folder of the document (used on opening when {prop} is missing)",
                        PROP_OUTPUT)
        obj.setEditorMode(name, READ_ONLY)
    relative = os.path.relpath(os.path.abspath(path), os.path.dirname(os.path.abspath(filename)))
    if getattr(obj, name) != relative:
        setattr(obj, name, relative)


def repoint_relative(obj):
    """Re-point the input file of `obj` to its relative path from the document's folder when the absolute
    one is missing and the relative one exists; True if re-pointed."""
    prop = file_property(obj)
    if prop is None or prop + RELATIVE not in obj.PropertiesList or not obj.Document.FileName:
        return False
    path, relative = getattr(obj, prop), getattr(obj, prop + RELATIVE)
    if not relative or os.path.isfile(path):
        return False
    moved = os.path.normpath(os.path.join(os.path.dirname(obj.Document.FileName), relative))
    if not os.path.isfile(moved):
        return False
    setattr(obj, prop, moved)
    tell(obj, f"{prop} {path} is missing; using {moved}", "Message")
    return True


def missing_files(doc):
    """[(object, property, path)] of the ABM objects of `doc` whose input file is missing."""
    missing = []
    for obj in doc.Objects:
        prop = file_property(obj)
        path = getattr(obj, prop, "") if prop else ""
        if path and not os.path.isfile(path):
            missing.append((obj, prop, path))
    return missing


def repoint(doc, folder):
    """Re-point the missing input files of `doc` to the files of the same name in `folder`; the objects
    re-pointed (touched: the next recompute reads the files)."""
    moved = []
    for obj, prop, path in missing_files(doc):
        candidate = os.path.join(folder, os.path.basename(path))
        if os.path.isfile(candidate):
            setattr(obj, prop, candidate)
            moved.append(obj)
    return moved


def document_or_active(doc):
    """`doc`, else FreeCAD's active document; RuntimeError when there is none (Addon-Template)."""
    if doc is None:
        doc = FreeCAD.ActiveDocument
    if doc is None:
        raise RuntimeError("no document: open or create a FreeCAD document first (FreeCAD.newDocument())")
    return doc


def add_properties(obj, group, specs, *, read_only=False):
    """Add properties to `obj` in `group`: specs is a list of (type, name, tooltip[, value]).

    Properties already there (a restored or migrated object) are left as they are. read_only
    marks them read-only in the property editor (computed values).
    """
    for spec in specs:
        kind, name, tip = spec[:3]
        if name not in obj.PropertiesList:
            obj.addProperty(kind, name, group, tip)
            if len(spec) > 3:
                setattr(obj, name, spec[3])
        if read_only:
            obj.setEditorMode(name, READ_ONLY)


class FeatureProxy:
    """Base of the ABM proxies: version property, saved state (no engine objects), migration hook.

    Subclasses set KIND and implement ``execute(obj)``; computed attributes live on the proxy
    and are rebuilt on demand after a restore.
    """

    KIND = "ABM"

    def __init__(self, obj):
        obj.Proxy = self
        add_properties(obj, "Base", [("App::PropertyInteger", "Version",
                                      "version of this object's properties (for migration on restore)", VERSION)],
                       read_only=True)
        self._reset()

    def _reset(self):
        """Forget what was computed (also the state after a restore)."""

    # Saved state: the kind and version only (FreeCAD 0.20 calls __getstate__ / __setstate__;
    # older ones dumps / loads).
    def __getstate__(self):
        return {"kind": self.KIND, "version": VERSION}

    def __setstate__(self, state):
        self._reset()

    dumps, loads = __getstate__, __setstate__

    def onDocumentRestored(self, obj):
        """Migrate an object saved by an older version, then let the subclass restore itself."""
        repoint_relative(obj)
        saved = int(getattr(obj, "Version", 0)) if "Version" in obj.PropertiesList else 0
        if saved < VERSION:
            self.migrate(obj, saved)
        self.restored(obj)

    def migrate(self, obj, saved_version):
        """Bring an object saved with `saved_version` (0: before versions) to VERSION.

        Here: the Version property itself; subclasses add what their later versions added.
        """
        add_properties(obj, "Base", [("App::PropertyInteger", "Version",
                                      "version of this object's properties (for migration on restore)")],
                       read_only=True)
        obj.Version = VERSION

    def restored(self, obj):
        """Called after migration when the document is restored."""
