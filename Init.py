# ABM workbench, loaded by FreeCAD at start-up (with or without the GUI).
# Nothing to set up before the GUI: the engine and the CAD layer are imported on use.
