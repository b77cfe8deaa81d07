"""Registers the ABM workbench with FreeCAD's GUI (its commands are imported on activation), its
preferences page, its translations folder and the features' report-view lines in the user's language.

FreeCAD executes this file with separate globals and locals: the class and its methods cannot
see names imported at the top, so each method imports what it uses.
"""

import FreeCADGui


class ABMWorkbench(FreeCADGui.Workbench):
    """Cut geometry of five-axis flat-end milling on staircase stock (analytical boundary method)."""

    MenuText = "ABM"
    ToolTip = "Analytical cut geometry for five-axis milling of staircase stock"

    def __init__(self):
        import os

        import abm_workbench

        self.__class__.Icon = os.path.join(os.path.dirname(os.path.dirname(abm_workbench.__file__)), "resources",
                                           "icons", "ABM_Workbench.svg")

    def Initialize(self):
        """Called once, when the workbench is first activated: register the commands, menu and toolbar."""
        from abm_workbench.gui import commands

        names = list(commands.register())
        self.appendToolbar("ABM", names)
        self.appendMenu("ABM", names)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(ABMWorkbench())

# View providers for ABM objects restored or made outside the commands (light: FreeCAD only).
from abm_workbench.gui.view_providers import install_observer  # noqa: E402

install_observer()

# Edit -> Preferences -> ABM (its icon: resources/icons/preferences-abm.svg, which FreeCAD finds by the
# group's name), and the translations (translations/ABM_<language>.qm, loaded again when the language changes).
from abm_workbench.gui import i18n, preferences, reporting  # noqa: E402

FreeCADGui.addIconPath(preferences.ICONS)
FreeCADGui.addPreferencePage(preferences.PreferencesPage, "ABM")
i18n.install()
reporting.install()  # the features' report-view lines in the user's language
