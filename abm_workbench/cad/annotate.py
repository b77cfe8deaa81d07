"""An annotated FreeCAD document of a pass: stock, toolpath, and the cut at each CL point (mm).

Objects (all Part::Feature unless said), per CL point i in a group ``CL<i>`` (zero-padded):

- ``Stock``: the stock solid; ``Toolpath``: the polyline through the CL points;
- ``CL<i>_LEP``, ``CL<i>_UEP``: polylines through the lowermost and uppermost engagement
  points over φ (one polyline per run of consecutive engaged angles);
- ``CL<i>_Seg_<letter>_<surface>``: per engagement segment, the engaged part of the cutter
  surface, the ruled surface between the LEP and UEP polylines over the segment's φ range
  (a line LEP–UEP for a segment of one angle); for a tool with a corner radius, the cutting edge
  from LEP to UEP at each angle of the segment instead, its corner part drawn as circular arcs and
  its side part as segments (cad.profile_edges);
- ``CL<i>_Intersection``: the material of the stock as given inside the cutter
  (cad.boolean.cutter_intersection: a cylinder, or the body of a tool with a corner radius), for the
  CL points asked for;
- validated against the in-process stock, for the CL points given: ``CL<i>_Removed``, the solids
  of the volumes that the earlier moves near the tool swept (what they removed is the stock
  inside them; the reference sections the edges with each), and ``CL<i>_InProcessTop``, the top
  of the in-process stock around the tool as a wire grid (cad.inprocess_boolean.stock_heights).

Each segment object carries, in the property group "ABM", its CL point, letter, UEP surface,
φ range (deg) and its colour (App::PropertyColor ``Colour``, by UEP surface kind). With the
GUI up the colours, line widths and transparencies are set on the view objects; when FreeCAD
saves no view properties (headless), :func:`write_annotated` adds them to the file as its
``GuiDocument.xml`` (the part of an FCStd file FreeCAD's GUI restores them from), so the
document opens coloured. Nothing of the engine is pickled into the document.
"""

import zipfile

import numpy as np

from ..engine import Engagement, Tool, Toolpath
from ..report.colours import SURFACE_COLOURS
from .boolean import cutter_intersection
from .freecad_env import FreeCAD, Part
from .inprocess_boolean import swept_near_tool
from .profile_edges import EdgeGeometry, profile_piece_shapes, tool_frames

V = FreeCAD.Vector
#: Consecutive polyline points closer than this (mm) are merged.
POINT_TOL = 1e-7


def annotated_document(name, solid, engagement: Engagement, toolpath: Toolpath, tool: Tool, *, cls=None,
                       intersections=(), sweep=None, tops=None):
    """A new FreeCAD document `name` holding the annotated pass (see the module docstring).

    solid: the stock (Part.Shape). cls: CL indices to annotate (default all). intersections:
    CL indices that also get the boolean intersection solid. sweep: for a validation against the
    in-process stock, (SweptPieces of the program, (m,) program row of each CL point): the
    intersection CL points then also get CL<i>_Removed (cad.inprocess_boolean.swept_near_tool); tops:
    {CL index: (x (c,), y (c,), z (c, c))} mm, the in-process stock's top around those CL points (NaN
    where none is left), for CL<i>_InProcessTop. Returns (document, styles):
    styles maps object names to their view properties ({"ShapeColor": (r, g, b), ...}). The
    caller saves and closes the document.
    """
    document = FreeCAD.newDocument(name, name, True)
    builder = _Builder(document)
    try:
        builder.feature("Stock", solid, "the stock", transparency=70)
        builder.feature("Toolpath", _polyline(toolpath.cl), "CL points of the pass, in order", line_width=3.0)
        width = max(3, len(str(len(toolpath) - 1)))
        for cl in range(len(toolpath)) if cls is None else cls:
            prefix = f"CL{cl:0{width}d}"
            group = document.addObject("App::DocumentObjectGroup", prefix)
            for obj in _cl_objects(builder, prefix, engagement, int(cl), tool, toolpath):
                group.addObject(obj)
            if cl in intersections:
                shape = cutter_intersection(solid, tool, toolpath, int(cl))
                against = "the stock as given" if sweep is None else (
                    "the stock as given, not the in-process stock (earlier moves removed what lies in "
                    f"{prefix}_Removed)")
                group.addObject(builder.feature(f"{prefix}_Intersection", shape, "material inside the cutter "
                                                f"(boolean) of {against}", transparency=40))
                if sweep is not None:
                    pieces, rows = sweep
                    removed = swept_near_tool(pieces, rows[cl], tool, toolpath, int(cl))
                    for obj in _inprocess_objects(builder, prefix, removed, (tops or {}).get(cl)):
                        group.addObject(obj)
        document.recompute()
    except BaseException:
        FreeCAD.closeDocument(document.Name)
        raise
    return document, builder.styles


def write_annotated(path, name, *args, **kwargs):
    """Build the annotated document (arguments as annotated_document), save it to `path`, close it.

    `path` must end in .FCStd (FreeCAD appends it otherwise). When FreeCAD saved no
    GuiDocument.xml (no GUI, or a hidden document), the view properties are added as one, with
    every object visible (without it FreeCAD 0.20 opens such a document with all objects hidden).
    """
    document, styles = annotated_document(name, *args, **kwargs)
    styles = {obj.Name: {"Visibility": True, **styles.get(obj.Name, {})} for obj in document.Objects}
    try:
        document.saveAs(str(path))
    finally:
        FreeCAD.closeDocument(document.Name)
    with zipfile.ZipFile(path, "a") as archive:
        if "GuiDocument.xml" not in archive.namelist():
            archive.writestr("GuiDocument.xml", gui_document_xml(styles))


def gui_document_xml(styles):
    """GuiDocument.xml text setting the view properties of `styles` ({object name: {property: value}}).

    Colours (RGB 0..1) as App::PropertyColor, "Transparency" (%) as App::PropertyPercent,
    "LineWidth" (px) as App::PropertyFloatConstraint, "Visibility" as App::PropertyBool;
    FreeCAD keeps its defaults for the rest.
    """
    providers = []
    for name, properties in styles.items():
        items = []
        for prop, value in properties.items():
            if prop == "Visibility":
                items.append(f'<Property name="{prop}" type="App::PropertyBool"><Bool value="{str(bool(value)).lower()}"/>'
                             "</Property>")
            elif prop == "Transparency":
                items.append(f'<Property name="{prop}" type="App::PropertyPercent"><Integer value="{int(value)}"/>'
                             "</Property>")
            elif prop == "LineWidth":
                items.append(f'<Property name="{prop}" type="App::PropertyFloatConstraint">'
                             f'<Float value="{float(value)}"/></Property>')
            else:
                items.append(f'<Property name="{prop}" type="App::PropertyColor">'
                             f'<PropertyColor value="{_packed(value)}"/></Property>')
        providers.append(f'  <ViewProvider name="{name}" expanded="0"><Properties Count="{len(items)}" '
                         f'TransientCount="0">{"".join(items)}</Properties></ViewProvider>')
    return ("<?xml version='1.0' encoding='utf-8'?>\n<Document SchemaVersion=\"1\">\n"
            f'<ViewProviderData Count="{len(providers)}">\n' + "\n".join(providers)
            + '\n</ViewProviderData>\n<Camera settings=""/>\n</Document>\n')


def _packed(rgb):
    """FreeCAD's packed colour 0xRRGGBBAA of RGB (0..1), alpha byte 0."""
    r, g, b = (int(round(255 * min(max(float(c), 0.0), 1.0))) for c in rgb[:3])
    return (r << 24) | (g << 16) | (b << 8)


def _cl_objects(builder, prefix, engagement, cl, tool=None, toolpath=None):
    """The LEP and UEP polylines and one object per engagement segment of CL point `cl` (for a `tool` with a
    corner radius, of `toolpath`, the edges from LEP to UEP as arcs and segments)."""
    lep, uep = engagement.lep_xyz[cl], engagement.uep_xyz[cl]
    runs = _runs(engagement.segment[cl] >= 0)
    objects = []
    if runs:
        for points, label in ((lep, "LEP"), (uep, "UEP")):
            shape = Part.Compound([_polyline(points[a:b]) for a, b in runs])
            objects.append(builder.feature(f"{prefix}_{label}", shape, f"{label} over the engaged angles φ",
                                           colour=(0.1, 0.1, 0.1), line_width=3.0))
    for index, segment in enumerate(engagement.segments(cl)):
        rows = np.flatnonzero(engagement.segment[cl] == index)
        surface = segment["surface"]
        if tool is not None and tool.corner_radius > 0.0:
            shape, what = _edge_pieces(tool, toolpath, engagement, cl, rows), "cutting edges from LEP to UEP"
        else:
            shape, what = _band(lep[rows], uep[rows]), "engaged cutter surface"
        obj = builder.feature(
            f"{prefix}_Seg_{segment['letter']}_{surface}", shape,
            f"{what}, segment {segment['letter']}, UEP on {surface.replace('_', ' ')}",
            colour=SURFACE_COLOURS[surface], line_width=2.0 if tool is not None and tool.corner_radius else None)
        for kind, prop, value, tip in (
            ("App::PropertyInteger", "ClIndex", cl, "CL point (0-based)"),
            ("App::PropertyString", "Segment", segment["letter"], "engagement segment letter"),
            ("App::PropertyString", "UepSurface", surface, "surface holding the UEP"),
            ("App::PropertyAngle", "PhiStart", segment["phi_start"], "first rotation angle φ of the segment"),
            ("App::PropertyAngle", "PhiEnd", segment["phi_end"], "last rotation angle φ of the segment"),
        ):
            obj.addProperty(kind, prop, "ABM", tip)
            setattr(obj, prop, value)
            obj.setEditorMode(prop, 1)
        objects.append(obj)
    return objects


def _inprocess_objects(builder, prefix, removed, top):
    """CL<i>_Removed (from swept_near_tool's (Part.Shape or None, outlined)) and CL<i>_InProcessTop (from
    (x, y, z) or None), as present."""
    objects = []
    shape, outlined = removed
    if shape is not None:
        outline = "" if not outlined else (
            f"; {outlined} pieces of a tool with a corner (a bull-nose mill's moves within 5.74° of the plane across "
            "its axis, which have no exact solid) drawn as the hull of the flat-end cylinder of their radius, "
            "which holds their volume")
        objects.append(builder.feature(
            f"{prefix}_Removed", shape, "volumes swept by the earlier cutting moves near the tool (solids of each "
            f"constant-axis piece, not fused): the material of the stock inside them is gone{outline}",
            colour=(0.85, 0.3, 0.2), transparency=85))
    if top is not None and np.isfinite(top[2]).any():
        objects.append(builder.feature(
            f"{prefix}_InProcessTop", _height_grid(*top), "top of the in-process stock around the tool "
            "(the stock minus the earlier moves' swept volumes, along vertical lines)",
            colour=(0.2, 0.45, 0.8), line_width=1.0))
    return objects


def _height_grid(x, y, z):
    """Part.Compound of polylines through the heights z (c, c) over (x[b], y[a]) along each grid row and
    column, broken where z is NaN (mm); lone points are left out."""
    x, y, z = (np.asarray(v, dtype=float) for v in (x, y, z))
    gx, gy = np.meshgrid(x, y)
    points = np.stack([gx, gy, z], axis=-1)
    lines = []
    for grid in (points, points.transpose(1, 0, 2)):
        for row in grid:
            for start, stop in _runs(np.isfinite(row[:, 2])):
                if stop - start > 1:
                    lines.append(_polyline(row[start:stop]))
    return Part.Compound(lines)


def _runs(mask):
    """[(start, stop)] of the runs of True in a 1-D bool array (stop exclusive)."""
    edges = np.flatnonzero(np.diff(np.concatenate([[0], mask.astype(np.int8), [0]])))
    return list(zip(edges[::2].tolist(), edges[1::2].tolist()))


def _edge_pieces(tool, toolpath, engagement, cl, rows):
    """Part.Compound of the peripheral edge of a tool with a corner at CL point `cl` from the LEP's height
    to the UEP's (engagement.lep_l, uep_l) at each angle of `rows`: arcs on the corner, segments on the side."""
    geometry = EdgeGeometry.of(tool, toolpath.cl[cl], tool_frames(toolpath)[cl], engagement.phi[rows])
    s0 = geometry.arc_length(engagement.lep_l[cl, rows])
    s1 = geometry.arc_length(engagement.uep_l[cl, rows])
    edges = [edge for k in range(len(rows)) if s1[k] - s0[k] > POINT_TOL
             for edge in profile_piece_shapes(geometry, k, s0[k], s1[k])]
    if not edges:
        return Part.Compound([Part.Vertex(V(*engagement.lep_xyz[cl, row])) for row in rows])
    return Part.Compound(edges)


def _band(lep, uep):
    """The ruled surface between polylines through lep and uep (k, 3); a line LEP–UEP when k = 1."""
    if len(lep) == 1:
        return Part.LineSegment(V(*lep[0]), V(*uep[0])).toShape()
    return Part.makeRuledSurface(_polyline(lep), _polyline(uep))


def _polyline(points):
    """A wire through points (k, 3) (mm), consecutive duplicates dropped; a vertex for one point."""
    points = np.asarray(points, dtype=float)
    keep = np.concatenate([[True], np.linalg.norm(np.diff(points, axis=0), axis=1) > POINT_TOL])
    points = points[keep]
    if len(points) == 1:
        return Part.Vertex(V(*points[0]))
    return Part.makePolygon([V(*p) for p in points])


class _Builder:
    """Adds Part::Features to a document and collects their view properties (styles)."""

    def __init__(self, document):
        self.document = document
        self.styles = {}

    def feature(self, name, shape, description, *, colour=None, transparency=None, line_width=None):
        """A Part::Feature `name` holding `shape`, its description in the property group "ABM".

        colour (RGB 0..1) is stored in the property Colour; colour, transparency (%) and
        line_width (px) go into the styles and, with the GUI up, onto the view object.
        """
        obj = self.document.addObject("Part::Feature", name)
        obj.Label = name
        obj.Shape = shape
        obj.addProperty("App::PropertyString", "Description", "ABM", "what this object is")
        obj.Description = description
        style = {}
        if colour is not None:
            obj.addProperty("App::PropertyColor", "Colour", "ABM", "display colour (by UEP surface kind)")
            obj.Colour = tuple(colour)
            style.update(ShapeColor=tuple(colour), LineColor=tuple(colour), PointColor=tuple(colour))
        if transparency is not None:
            style["Transparency"] = transparency
        if line_width is not None:
            style["LineWidth"] = line_width
        if style:
            self.styles[name] = style
            view = obj.ViewObject if FreeCAD.GuiUp else None
            for prop, value in style.items() if view is not None else ():
                setattr(view, prop, value)
        return obj
