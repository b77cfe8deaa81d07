"""Import toolpath on a G-code program in inches (G20) with a LinuxCNC tool table, which LinuxCNC keeps in
the machine's units without writing them: the GUI asks for the units (the dialog ``ABM_MachineUnits``),
driven as a user does it: the toolbar button clicked, the file names typed, the choice made by keys.

Escape imports nothing and says why; inches give the table's D0.25 as 6.35 mm, millimetres as 0.25 mm
(the reference: 0.25 × 25.4, the inch's definition); no command-line word in what the user reads."""

from tests.conftest import ROOT
from tests.gui.dialogs import DIALOGS
from tests.gui.events import EVENTS
from tests.gui.test_user_actions import SETUP

#: A program in inches loading tool 1 (a square of cutting moves).
GCODE = """G20 G90 G17
T1 M6
S4000 M3
G0 X-0.5 Y0 Z0.2
G1 Z-0.1 F20
G1 X2 Y0
G1 X2 Y0.5
G0 Z0.2
M30
"""
#: A LinuxCNC tool table of an inch machine: tool 1 a quarter-inch flat-end mill.
TOOL_TABLE = "T1 P1 D0.25 Z0 ;quarter inch flat end mill\n"

BODY = SETUP + """
doc = FreeCAD.newDocument("Units")
settle()
def tool_table_dialog():
    dialog = top(QtWidgets.QFileDialog)
    return dialog if dialog is not None and dialog.windowTitle().startswith("Tool table of") else None
def answer(downs):
    def act(dialog):
        combo = dialog.findChild(QtWidgets.QComboBox)
        seen.append([dialog.findChild(QtWidgets.QLabel).text(), [combo.itemText(i) for i in range(combo.count())]])
        for _ in range(downs):
            key(combo, QtCore.Qt.Key_Down)
        press([b for b in dialog.findChildren(QtWidgets.QPushButton) if b.text().replace("&", "") == "OK"][0])
    return act
def units_dialog():
    return top(QtWidgets.QInputDialog, "ABM_MachineUnits")
seen = []

def import_with(act):
    start = len(report.toPlainText())
    before = {{o.Name for o in doc.Objects}}
    when_shown(lambda: top(QtWidgets.QFileDialog), choose_file({ngc!r}))
    when_shown(lambda: tool_table_dialog(), choose_file({table!r}))
    when_shown(units_dialog, act)
    press(toolbar_button("ABM_ImportToolpath"))
    settle()
    made = [o for o in doc.Objects if o.Name not in before]
    return [[(o.ToolTableUnits, o.ToolDiameter.Value, o.State) for o in made], report_since(start)]

verdict["escaped"] = import_with(lambda dialog: (seen.append(["escaped", []]), escape(dialog)))
verdict["inch"] = import_with(answer(1))
verdict["mm"] = import_with(answer(0))
verdict["seen"] = seen
# the units taken back in the property editor: a command's recompute refuses in the GUI's words
from abm_workbench.gui.reporting import CommandError, recompute_checked, report_error
made = [o for o in doc.Objects if o.Name.startswith("Toolpath")][0]
made.ToolTableUnits = "not said"
start = len(report.toPlainText())
try:
    recompute_checked(doc, (made,))
except CommandError as error:
    report_error(error)
verdict["unsaid"] = [made.State, made.getStatusString(), report_since(start)]
"""


def test_a_program_in_inches_asks_for_the_tool_tables_units(tmp_path, run_gui):
    mods = tmp_path / "home" / ".local" / "share" / "FreeCAD" / "Mod"  # the workbench installed: its toolbar
    mods.mkdir(parents=True)
    (mods / "ABM").symlink_to(ROOT, target_is_directory=True)
    ngc, table = tmp_path / "inch.ngc", tmp_path / "tools.tbl"
    ngc.write_text(GCODE)
    table.write_text(TOOL_TABLE)
    verdict = run_gui(BODY.format(events=EVENTS, dialogs=DIALOGS, ngc=str(ngc), table=str(table),
                                  out=str(tmp_path / "verdict.json")))
    assert "stuck" not in verdict, verdict
    made, said = verdict["escaped"]
    assert made == [] and "Traceback" not in said and "--" not in said
    assert "inch.ngc: not imported: it works in inches, and the units of the tool table tools.tbl were not said" in said
    made, said = verdict["inch"]
    assert len(made) == 1 and made[0][0] == "inch" and abs(made[0][1] - 0.25 * 25.4) < 1e-12
    assert "Invalid" not in made[0][2] and "Traceback" not in said
    made, said = verdict["mm"]
    assert len(made) == 1 and made[0][0] == "mm" and abs(made[0][1] - 0.25) < 1e-12 and "Invalid" not in made[0][2]
    assert len(verdict["seen"]) == 3  # asked each time, Escape included
    label, items = verdict["seen"][1]
    assert items == ["millimetres (mm)", "inches (in)"]
    assert "inch.ngc works in inches, and the tool table tools.tbl gives its lengths in the machine's units" in label
    assert "--" not in label
    state, status, said = verdict["unsaid"]
    assert "Invalid" in state and "G20: the program works in inches" in status
    said = said[said.rindex("ABM: "):]  # FreeCAD's own lines of the failed recompute come first
    assert "say them in the toolpath's ToolTableUnits property (mm or inch)" in said and "--" not in said
