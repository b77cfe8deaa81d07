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
- Engagement: the engaged cutter surface as one Coin triangle mesh built with numpy from the
  results (:mod:`.surface_mesh`; the object's Shape is only its outline), lit on both sides,
  each vertex coloured by the view property ``ColourBy`` (:mod:`.colouring`): the UEP surface
  of its engagement segment, the length of cut, the cut area or the force; the CL point chosen in
  the dock (:mod:`.dock`) drawn on top in yellow. Double-click: the task panel. Selected, it
  keeps its colours: FreeCAD draws its bounding box in the selection colour (``SelectionStyle``
  BoundBox) instead of painting its faces.

A document opened with input files that are neither where they were nor where they were
relative to the document (``features.base.missing_files``) gets one dialog (:func:`ask_repoint`):
it names them and asks for the folder that holds them now; they are re-pointed there by name
and the document recomputed.

After undo and redo (the observer's ``slotUndoDocument`` / ``slotRedoDocument``) the engagements
of the document are recoloured and the dock told (``gui.state`` "refresh"): the results follow
the restored properties (``EngagementFeature.result``).

Nothing of the view provider is saved but its class (``__getstate__`` returns None).
"""

import os

import FreeCAD

from . import state
from .colouring import HIGHLIGHT_COLOUR

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
#: Waiting for an opened document's objects: RESTORE_TRIES times RESTORE_WAIT ms at most.
RESTORE_TRIES, RESTORE_WAIT = 100, 50


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
    """The engaged cutter surface as one Coin mesh coloured per vertex (ColourBy), the chosen CL point
    highlighted; double-click opens the task panel (:mod:`.task_panel`)."""

    def attach(self, vobj):
        super().attach(vobj)
        self.overlay = None  # coin node of the highlighted CL point, made on demand
        self.legend = None  # colouring.Legend of the colours shown
        self.cl = None  # the highlighted CL point
        self.surface = None  # coin SoSwitch holding the mesh, made on demand
        self.mesh = None  # surface_mesh.SurfaceMesh shown, or None
        self.colours = None  # (2n, 3) RGB 0..1 of its vertices, or None
        self.meshed = None  # the Engagement the mesh is of
        self.vertices = None  # its coin SoVertexProperty (points and colours)

    def style(self, vobj):
        vobj.DisplayMode = "Shaded"  # the Shape (the outline) has no faces: only the mesh is drawn
        vobj.SelectionStyle = "BoundBox"  # selected: the box, not selection-green over the colours
        add_colour_by(vobj)
        colour(vobj)

    def updateData(self, obj, prop):
        if prop in ("Shape", "ShowSurfaces"):
            colour_soon(obj)

    def onChanged(self, vobj, prop):
        if prop == "ColourBy":
            colour(vobj)
        elif prop == "Visibility":
            self._show()

    def finishRestoring(self, *_):
        """Draw the mesh once the document is restored (FreeCAD calls this then; the results are back), on the
        next turn of the event loop: nothing more runs inside the restore."""
        from PySide import QtCore

        vobj = self.ViewObject
        QtCore.QTimer.singleShot(0, lambda: _colour_later(vobj))

    def doubleClicked(self, vobj):
        vobj.Document.setEdit(vobj.Object, 0)
        return True

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        return state.tell("edit", vobj.Object)

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True

    def draw(self, result, colours_of):
        """Show the mesh of the Engagement `result` (None: nothing) with the vertex colours
        colours_of(mesh) gives ((2n, 3) RGB 0..1); the mesh is rebuilt only for other results."""
        from pivy import coin

        from .surface_mesh import coord_index, packed_rgba, surface_mesh

        if self.surface is None:
            self.surface = coin.SoSwitch()
            self.ViewObject.RootNode.addChild(self.surface)
        if result is None:
            self.mesh = self.colours = self.meshed = self.vertices = None
            self.surface.removeAllChildren()
            self._show()
            return
        if result is not self.meshed:
            self.mesh, self.meshed = surface_mesh(result, self.Object.Proxy.edge_along(self.Object)), result
            self.surface.removeAllChildren()
            group, hints = coin.SoSeparator(), coin.SoShapeHints()
            hints.vertexOrdering = coin.SoShapeHints.COUNTERCLOCKWISE  # with an unknown shape type:
            hints.shapeType = coin.SoShapeHints.UNKNOWN_SHAPE_TYPE  # lit on both sides
            hints.creaseAngle = MESH_CREASE_ANGLE
            self.vertices, faces = coin.SoVertexProperty(), coin.SoIndexedFaceSet()
            self.vertices.materialBinding = coin.SoVertexProperty.PER_VERTEX_INDEXED
            self.vertices.vertex.setValues(0, len(self.mesh.points), self.mesh.points.tolist())
            faces.vertexProperty = self.vertices
            index = coord_index(self.mesh.triangles)
            faces.coordIndex.setValues(0, len(index), index.tolist())
            for node in (hints, faces):
                group.addChild(node)
            self.surface.addChild(group)
        self.colours = colours_of(self.mesh)
        rgba = packed_rgba(self.colours)
        self.vertices.orderedRGBA.setValues(0, len(rgba), rgba.tolist())
        self._show()

    def _show(self):
        """The mesh drawn while the object is visible and has one."""
        from pivy import coin

        if self.surface is not None:
            shown = self.ViewObject.Visibility and self.mesh is not None
            self.surface.whichChild = coin.SO_SWITCH_ALL if shown else coin.SO_SWITCH_NONE

    def highlight(self, cl):
        """Draw the engaged part of CL point `cl` on top of everything (None: nothing): in yellow, its LEP
        and UEP curves and the cutting edge from LEP to UEP at every HIGHLIGHT_EDGES-th engaged angle
        (the faces' own colours show between them), and the CL point in black."""
        from pivy import coin

        self.cl = cl
        if self.overlay is None:
            self.overlay = coin.SoAnnotation()
            self.ViewObject.RootNode.addChild(self.overlay)
        self.overlay.removeAllChildren()
        result = self.Object.Proxy.result(self.Object)
        if cl is None or result is None or not 0 <= cl < result.shape[0]:
            return
        import numpy as np

        engaged = result.engaged[cl]
        lep, uep = result.lep_xyz[cl, engaged], result.uep_xyz[cl, engaged]
        light = coin.SoLightModel()
        light.model = coin.SoLightModel.BASE_COLOR
        style = coin.SoDrawStyle()
        style.lineWidth, style.pointSize = HIGHLIGHT_LINE_WIDTH, HIGHLIGHT_POINT_SIZE
        material = coin.SoBaseColor()
        material.rgb.setValue(*HIGHLIGHT_COLOUR)
        lines = coin.SoCoordinate3()
        step = max(1, len(lep) // HIGHLIGHT_EDGES)
        points = np.stack([lep[::step], uep[::step]], axis=1).reshape(-1, 3)
        lines.point.setValues(0, len(points), points.tolist())
        fan = coin.SoLineSet()
        fan.numVertices.setValues(0, len(points) // 2, [2] * (len(points) // 2))
        for node in (light, style, material, lines, fan):
            self.overlay.addChild(node)
        for curve in (lep, uep):
            coordinates, line = coin.SoCoordinate3(), coin.SoLineSet()
            coordinates.point.setValues(0, len(curve), curve.tolist())
            line.numVertices.setValue(len(curve))
            self.overlay.addChild(coordinates)
            self.overlay.addChild(line)
        marker, where, dot = coin.SoBaseColor(), coin.SoCoordinate3(), coin.SoPointSet()
        marker.rgb.setValue(*HIGHLIGHT_POINT_COLOUR)
        centre = self.cl_point(cl, lep)
        where.point.setValue(*map(float, centre))
        for node in (marker, where, dot):
            self.overlay.addChild(node)

    def cl_point(self, cl, lep):
        """The CL point `cl` (3,) mm in part coordinates, from the toolpath; when its file cannot be read (a
        document opened without its input files), the middle of the chosen CL point's LEP (k, 3)."""
        from ..errors import InputError

        toolpath = self.Object.Toolpath
        try:
            return toolpath.Proxy.load(toolpath)[0].cl[cl]
        except (InputError, AttributeError, IndexError):
            return lep.mean(axis=0)


#: Highlight of the chosen CL point: colour, line width and point size (px).
HIGHLIGHT_POINT_COLOUR = (0.0, 0.0, 0.0)
HIGHLIGHT_LINE_WIDTH, HIGHLIGHT_POINT_SIZE = 3.0, 12.0
#: About this many cutting edges (LEP to UEP) drawn across the highlighted CL point.
HIGHLIGHT_EDGES = 12
#: Crease angle of the mesh (rad): neighbouring triangles meeting at less than this are shaded smooth.
MESH_CREASE_ANGLE = 0.5


def add_colour_by(vobj):
    """Add the view property ColourBy (group "Display") to the engagement's view object if missing; give an
    older one (without force) the choices of COLOUR_BY, keeping its value."""
    from .colouring import COLOUR_BY

    if "ColourBy" not in vobj.PropertiesList:
        vobj.addProperty("App::PropertyEnumeration", "ColourBy", "Display",
                         "face colours: segment (the UEP surface of each engagement segment), length (length of "
                         "cut, mm), area (cut area, mm²) or force (resultant cutting force, N; with Forces on)")
        vobj.ColourBy = list(COLOUR_BY)
        vobj.ColourBy = "segment"
    elif tuple(vobj.getEnumerationsOfProperty("ColourBy")) != COLOUR_BY:
        value = vobj.ColourBy
        vobj.ColourBy = list(COLOUR_BY)
        vobj.ColourBy = value


def colour_soon(obj):
    """Recolour the engagement `obj` and refresh the dock once the event loop runs again."""
    from PySide import QtCore

    vobj = obj.ViewObject
    QtCore.QTimer.singleShot(0, lambda: _colour_later(vobj))


def _colour_later(vobj):
    try:
        colour(vobj)
        state.tell("refresh", vobj.Object)
    except Exception as error:  # noqa: BLE001 (the object may be gone: deleted, undone, closed)
        FreeCAD.Console.PrintLog(f"ABM: engagement not coloured: {error}\n")


def colour(vobj):
    """Draw the engagement's mesh coloured per vertex by its ColourBy; the Legend, or None when there is
    nothing to draw (no results, or ShowSurfaces off)."""
    from .preferences import colour_map
    from .surface_mesh import vertex_colours

    obj = vobj.Object
    provider = vobj.Proxy
    result = obj.Proxy.result(obj)
    if result is None or not obj.ShowSurfaces:
        provider.draw(None, None)
        provider.legend = None
        return None
    add_colour_by(vobj)
    forces = obj.Proxy.forces(obj)
    colour_by = "segment" if vobj.ColourBy == "force" and forces is None else vobj.ColourBy
    legends = []

    def colours_of(mesh):
        colours, legend = vertex_colours(result, mesh, colour_by, forces, colour_map())
        legends.append(legend)
        return colours

    provider.draw(result, colours_of)
    provider.legend = legends[0]
    return provider.legend


_CLASSES = {"ABM::Stock": StockViewProvider, "ABM::Toolpath": ToolpathViewProvider,
            "ABM::Engagement": EngagementViewProvider}


def refresh(obj):
    """Restyle what depends on the results after a recompute (the engagement's mesh and colours)."""
    if FreeCAD.GuiUp and kind(obj) == "ABM::Engagement" and isinstance(obj.ViewObject.Proxy, ViewProvider):
        colour(obj.ViewObject)


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
    """Attaches view providers to ABM objects made outside the commands (see the module docstring);
    empties the engagement dock when the document it shows is closed."""

    def slotActivateDocument(self, doc):
        attach_all(doc)
        if doc.Name not in _ASKED:  # once per document: as it is opened
            _ASKED.add(doc.Name)
            _ask_when_restored(doc.Name)

    def slotRecomputedObject(self, obj):
        attach(obj)

    def slotDeletedDocument(self, doc):
        _ASKED.discard(doc.Name)
        state.tell("forget", doc)

    def slotUndoDocument(self, doc):
        self._restyle(doc)
        state.tell("gone")

    def slotRedoDocument(self, doc):
        self._restyle(doc)
        state.tell("gone")

    def slotDeletedObject(self, obj):
        """An engagement deleted (or taken back by undo): the dock lets it go once it is gone."""
        if kind(obj) == "ABM::Engagement":
            from PySide import QtCore

            QtCore.QTimer.singleShot(0, lambda: state.tell("gone"))

    @staticmethod
    def _restyle(doc):
        """Recolour the engagements of `doc` and refresh the dock: their results follow the restored
        properties."""
        for obj in doc.Objects:
            if kind(obj) == "ABM::Engagement" and isinstance(getattr(obj.ViewObject, "Proxy", None), ViewProvider):
                colour_soon(obj)


def _ask_when_restored(name, tries=RESTORE_TRIES):
    """ask_repoint for the document `name` once it is restored: FreeCAD activates a document it opens
    before it reads its objects, and runs the event loop meanwhile; an empty document is waited for
    `tries` times RESTORE_WAIT ms at most."""
    from PySide import QtCore

    doc = FreeCAD.listDocuments().get(name)
    if doc is None:
        return
    if doc.Restoring or not doc.Objects:
        if tries:
            QtCore.QTimer.singleShot(RESTORE_WAIT, lambda: _ask_when_restored(name, tries - 1))
        return
    ask_repoint(doc)


def ask_repoint(doc):
    """When input files of `doc` are missing: one dialog naming them that asks for the folder holding
    them now; those found there by name are re-pointed and the document recomputed. The objects
    re-pointed."""
    import FreeCADGui
    from PySide import QtGui

    from ..features.base import missing_files, repoint
    from .i18n import translate

    missing = missing_files(doc)
    if not missing:
        return []
    names = "\n".join(f"{obj.Label}: {path}" for obj, _, path in missing)
    dialog = QtGui.QFileDialog(FreeCADGui.getMainWindow(),
                               translate("Input files missing: choose the folder that holds them")
                               + f" ({len(missing)})", os.path.dirname(doc.FileName))
    dialog.setObjectName("ABM_Repoint")
    dialog.setFileMode(QtGui.QFileDialog.Directory)
    dialog.setOptions(QtGui.QFileDialog.ShowDirsOnly | QtGui.QFileDialog.DontUseNativeDialog)
    dialog.setLabelText(QtGui.QFileDialog.LookIn, translate("Missing:") + " " + names.replace("\n", "; "))
    folder = dialog.selectedFiles()[0] if dialog.exec_() else ""
    dialog.deleteLater()
    if not folder:
        FreeCAD.Console.PrintWarning("ABM: " + translate("{document}: input files missing, not re-pointed:",
                                                         document=doc.Label) + f"\n{names}\n")
        return []
    moved = repoint(doc, folder)
    for obj, _, path in missing_files(doc):
        FreeCAD.Console.PrintWarning("ABM: " + translate("{label}: {file} is not in {folder}", label=obj.Label,
                                                         file=os.path.basename(path), folder=folder) + "\n")
    if moved:
        doc.recompute()
    return moved


_OBSERVER = None
_ASKED = set()  # names of the documents checked for missing input files


def install_observer():
    """Install the document observer once (InitGui.py calls it), and attach to open documents; run the
    engagements' engine in a worker thread (:mod:`.worker`)."""
    global _OBSERVER
    if _OBSERVER is None and FreeCAD.GuiUp:
        from . import worker

        worker.install()
        _OBSERVER = _Observer()
        FreeCAD.addDocumentObserver(_OBSERVER)
        for doc in FreeCAD.listDocuments().values():
            attach_all(doc)
