"""Registers the ABM workbench with FreeCAD's GUI; its commands are imported on activation."""

import os

import FreeCADGui

import abm_workbench


class ABMWorkbench(FreeCADGui.Workbench):
    """Cut geometry of five-axis flat-end milling on staircase stock (analytical boundary method)."""

    MenuText = "ABM"
    ToolTip = "Analytical cut geometry for five-axis milling of staircase stock"
    Icon = os.path.join(os.path.dirname(os.path.dirname(abm_workbench.__file__)), "resources", "icons", "ABM_Workbench.svg")

    def Initialize(self):
        """Called once, when the workbench is first activated."""

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(ABMWorkbench())
