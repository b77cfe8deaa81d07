"""What the ABM document objects share: property helpers, the version, the proxy's saved state.

Every feature is a ``Part::FeaturePython`` whose ``Proxy`` is one of the classes of this
package. The proxy keeps what it computes (a Staircase, a Toolpath, an Engagement) as plain
Python attributes that are *not* saved: :meth:`FeatureProxy.__getstate__` returns only the
proxy's kind and the format version, so nothing of the engine is pickled into the document.
What a feature computes either is its Shape (saved by FreeCAD as BREP), a read-only property,
or, for the engagement, a results CSV beside the document (see :mod:`.engagement`).

Migration: every object carries a read-only ``Version`` property (group "Base"), set to
:data:`VERSION` when it is created. On restore, :meth:`FeatureProxy.onDocumentRestored` calls
:meth:`FeatureProxy.migrate` with the version the file was saved with; a later version of the
workbench adds missing properties, renames old ones, etc. there, then sets ``Version``.
"""

from ..cad.freecad_env import FreeCAD

#: Version of the document objects' properties: bump it when they change, and migrate (4: the toolpath's Operation).
VERSION = 4
#: Editor modes of FreeCAD properties.
READ_ONLY, HIDDEN = 1, 2


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
