"""ABM workbench: analytical cut geometry of flat-end five-axis milling on staircase stock.

The engine (:mod:`abm_workbench.engine`) is pure numpy and never imports FreeCAD; file
formats, the command line and reports sit beside it, the FreeCAD layers on top.
Lengths are in millimetres; angles are in degrees at every interface.
"""

__version__ = "0.1.0"
