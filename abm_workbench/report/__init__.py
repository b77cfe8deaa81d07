"""Reports of an Engagement: plots (matplotlib on an Agg canvas, never FreeCAD or pyplot)."""
