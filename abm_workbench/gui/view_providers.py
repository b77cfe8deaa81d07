"""View providers of the ABM document objects, attached only when FreeCAD.GuiUp.

The feature proxies (``abm_workbench.features``) are headless and do not know about the GUI,
so the view providers are attached from outside:

- by the commands (:mod:`.commands`), through :func:`attach`, as they create objects;
- by a document observer (:func:`install_observer`, installed by InitGui.py), for ABM objects
  made otherwise: created in the Python console (attached after their first recompute) or
  restored from a file written headless (attached when the document is activated, which
  FreeCAD does as it opens it). A document saved from the GUI restores its view providers
  itself: FreeCAD imports this module and the class named in GuiDocument.xml.

What each shows (colours RGB 0..1, from :mod:`abm_workbench.report.colours`):

- Stock: light grey, 75 % transparent, so the toolpath and the engaged surface show through.
- Toolpath: a 4 px line through the CL points, its vertices (the CL points) as 6 px points.
- Engagement: the engaged cutter surface, each face coloured by the UEP surface of its
  engagement segment (``DiffuseColor`` per face, :data:`SURFACE_COLOURS`), lit on both sides,
  shaded without edges.

Nothing of the view provider is saved but its class (``__getstate__`` returns None).
"""

import os

import FreeCAD

#: Folder of the SVG icons (named like the commands).
ICONS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                     "resources", "icons")
#: Icon of each kind of ABM object (the icon of the command that makes it).
OBJECT_ICONS = {"ABM::Stock": "ABM_ImportStock.svg", "ABM::Toolpath": "ABM_ImportToolpath.svg",
                "ABM::Engagement": "ABM_ComputeEngagement.svg"}
STOCK_COLOUR = (0.78, 0.80, 0.82)
STOCK_TRANSPARENCY = 75  # percent
TOOLPATH_COLOUR = (0.0, 0.0, 0.0)
TOOLPATH_LINE_WIDTH = 4.0  # px
TOOLPATH_POINT_SIZE = 6.0  # px


def icon(name):
    """Path of the icon file `name` (e.g. ``"ABM_ImportStock.svg"``)."""
    return os.path.join(ICONS, name)


def kind(obj):
    """The ABM kind of a document object ("ABM::Stock", …), or None for any other object."""
    value = getattr(getattr(obj, "Proxy", None), "KIND", None)
    return value if isinstance(value, str) and value in OBJECT_ICONS else None


class ViewProvider:
    """View provider of an ABM object: its icon and style; subclasses restyle on updates."""

    def __init__(self, vobj):
        vobj.Proxy = self
        self.attach(vobj)

    def attach(self, vobj):
        self.ViewObject, self.Object = vobj, vobj.Object

    def getIcon(self):
        return icon(OBJECT_ICONS.get(kind(self.Object), "ABM_Workbench.svg"))

    def style(self, vobj):
        """Set the look of a newly attached object."""

    def updateData(self, obj, prop):
        pass

    def onChanged(self, vobj, prop):
        pass

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    dumps, loads = __getstate__, __setstate__


class StockViewProvider(ViewProvider):
    """The stock: semi-transparent grey solid."""

    def style(self, vobj):
        vobj.ShapeColor = STOCK_COLOUR
        vobj.Transparency = STOCK_TRANSPARENCY


class ToolpathViewProvider(ViewProvider):
    """The toolpath: a thick black line with its CL points."""

    def style(self, vobj):
        vobj.LineColor = TOOLPATH_COLOUR
        vobj.LineWidth = TOOLPATH_LINE_WIDTH
        vobj.PointColor = TOOLPATH_COLOUR
        vobj.PointSize = TOOLPATH_POINT_SIZE


class EngagementViewProvider(ViewProvider):
    """The engaged cutter surface, coloured per face by the UEP surface of its segment."""

    def style(self, vobj):
        if "Lighting" in vobj.PropertiesList:
            vobj.Lighting = "Two side"
        vobj.DisplayMode = "Shaded"  # no edges: 9000 faces' boundaries would hide the colours
        colour_by_surface(vobj)

    def updateData(self, obj, prop):
        # FreeCAD calls this before its own view provider has the new Shape's faces, and
        # per-face colours set now would not match them: colour once the event loop runs again.
        if prop == "Shape":
            from PySide2 import QtCore

            vobj = obj.ViewObject
            QtCore.QTimer.singleShot(0, lambda: _colour_later(vobj))


def _colour_later(vobj):
    try:
        colour_by_surface(vobj)
    except Exception as error:  # noqa: BLE001 (the object may be gone: deleted, undone, closed)
        FreeCAD.Console.PrintLog(f"ABM: engagement not coloured: {error}\n")


def face_surfaces(obj):
    """The UEP surface name of each face of the engagement object's Shape, or None when unknown.

    The Shape is ``Part.Compound(engaged_surface_parts(result)[0])``: its children are in the
    order of the keys (cl, letter, surface). The keys are rebuilt from the result's segments
    without building any geometry (a segment of one angle is a line, of several a ruled
    surface); when that does not match the compound (OCC refused a ruling and the two curves
    stand in for it) :func:`engaged_surface_parts` itself is asked.
    """
    import numpy as np

    result = obj.Proxy.result(obj)
    shape = obj.Shape
    if result is None or shape.isNull():
        return None
    children = shape.childShapes()
    keys = []
    for cl in range(result.shape[0]):
        for index, segment in enumerate(result.segments(cl)):
            rows = np.flatnonzero(result.segment[cl] == index)
            if len(rows) == 1:
                if np.linalg.norm(result.uep_xyz[cl, rows[0]] - result.lep_xyz[cl, rows[0]]) > 1e-9:
                    keys.append(segment["surface"])
            else:
                keys.append(segment["surface"])
    if len(keys) != len(children):
        from ..features.engagement import engaged_surface_parts
        keys = [key[2] for key in engaged_surface_parts(result)[1]]
        if len(keys) != len(children):
            return None
    surfaces = []
    for key, child in zip(keys, children):
        surfaces += [key] * len(child.Faces)
    if len(surfaces) != len(shape.Faces):
        return None
    return surfaces


def colour_by_surface(vobj):
    """Set DiffuseColor of the engagement's view object per face from SURFACE_COLOURS."""
    from ..report.colours import SURFACE_COLOURS

    surfaces = face_surfaces(vobj.Object)
    if not surfaces:
        return
    vobj.DiffuseColor = [(*SURFACE_COLOURS.get(name, SURFACE_COLOURS["none"]), 0.0) for name in surfaces]


_CLASSES = {"ABM::Stock": StockViewProvider, "ABM::Toolpath": ToolpathViewProvider,
            "ABM::Engagement": EngagementViewProvider}


def refresh(obj):
    """Restyle what depends on the results after a recompute (the engagement's face colours)."""
    if FreeCAD.GuiUp and kind(obj) == "ABM::Engagement":
        colour_by_surface(obj.ViewObject)


def attach(obj):
    """Give the ABM object `obj` its view provider (and style) when the GUI is up; True if attached.

    An object that already has an ABM view provider, a non-ABM object, or no GUI: nothing.
    """
    if not FreeCAD.GuiUp:
        return False
    name = kind(obj)
    vobj = getattr(obj, "ViewObject", None)
    if name is None or vobj is None or isinstance(getattr(vobj, "Proxy", None), ViewProvider):
        return False
    provider = _CLASSES[name](vobj)
    provider.style(vobj)
    return True


def attach_all(doc):
    """Attach view providers to every ABM object of `doc`; the number attached."""
    return sum(attach(obj) for obj in doc.Objects)


class _Observer:
    """Attaches view providers to ABM objects made outside the commands (see the module docstring)."""

    def slotActivateDocument(self, doc):
        attach_all(doc)

    def slotRecomputedObject(self, obj):
        attach(obj)


_OBSERVER = None


def install_observer():
    """Install the document observer once (InitGui.py calls it), and attach to open documents."""
    global _OBSERVER
    if _OBSERVER is None and FreeCAD.GuiUp:
        _OBSERVER = _Observer()
        FreeCAD.addDocumentObserver(_OBSERVER)
        for doc in FreeCAD.listDocuments().values():
            attach_all(doc)
