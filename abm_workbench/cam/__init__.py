"""FreeCAD's own CAM (the Path workbench) with the ABM workbench: its Jobs read as programs, and the
scheduled feeds written back as a dressup its posts write (docs/USAGE.md, docs/GUI.md). Needs FreeCAD.

Modules: :mod:`.freecad_cam` (Jobs, operations and tool controllers, the seam between FreeCAD
versions), :mod:`.toolbits` (a tool controller's tool as a ToolSpec), :mod:`.job_program` (a Job as
a Program), :mod:`.documents` (FCStd files: a Job, the tools), :mod:`.dressup` (scheduled feeds).
"""
