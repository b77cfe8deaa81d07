"""Numbers typed into the engagement's task panel with real key events: each is taken in the field's
declared unit (mm, degrees, or a plain number) and checked, never clamped, rounded or re-scaled.

Faults found that way, each a test below: a feed per tooth shown as "80.00 µm", after which a bare
"0.1" was taken as 0.1 µm; 1e400 turned into 1e4 (a 10 m tool), 99999999999999999999 into 999999,
99999999 flutes into 99, 1e400 rpm into 1400, "12,5" into 125 mm, 1e-400 and 0 called "required", an
emptied field accepted with the old value; spin boxes with ranges of their own (flutes up to 100,
everything within ±1e6, three decimals) instead of the job model's. The last test types strings that
hypothesis makes into every enabled field; it found φ beyond ±360° clamped by the angle properties.

The first three tests share one GUI session (about 15 s), the fuzz test has its own (about 30 s).
"""

import pytest

from abm_workbench.errors import ParameterError
from abm_workbench.jobs import BY_NAME, label_words
from tests.gui.conftest import run_macro
from tests.gui.test_panel_faults import SETUP, clean, run_body

#: Examples the fuzz test types (each up to a few dozen key events, about 0.1 s).
FUZZ_EXAMPLES = 200

#: Shared by the macros: what the user sees of field `name` after typing; a task panel opened anew.
SEEN = """
def text_of(name):
    return task_panel.shown().field(name).findChild(QtWidgets.QLineEdit).text()
def seen(name):
    # the field's text, the message, OK enabled, the field marked
    panel = task_panel.shown()
    return [text_of(name), panel.message.text(), button("OK").isEnabled(), bool(panel.field(name).styleSheet())]
def fresh_panel():
    # the task panel opened anew (one left open is cancelled first)
    if task_panel.shown() is not None:
        click("Cancel")
    return open_panel()
"""

BODY = SETUP + SEEN + """
start = len(report.toPlainText())

# ---- 1. the feed per tooth: shown in mm, a bare number read in mm ---------------------------------------
panel = open_panel()
retype("FeedPerTooth", "0.08")
click("OK")
applied = [task_panel.shown() is None, engagement.FeedPerTooth.Value]
engagement.YWindowMax = 20000.0  # 20 m: shown in mm too
panel = open_panel()
verdict["feed_shown"] = applied + [text_of("FeedPerTooth"), text_of("YWindowMax")]
retype("FeedPerTooth", "0.1")
verdict["feed_typed"] = seen("FeedPerTooth")
click("OK")
verdict["feed_stored"] = [task_panel.shown() is None, engagement.FeedPerTooth.Value, engagement.State]
panel = open_panel()
retype("FeedPerTooth", "80 µm")  # a unit typed is taken
verdict["feed_micrometres"] = seen("FeedPerTooth") + [panel.values()["FeedPerTooth"]]
click("OK")
verdict["feed_micrometres_stored"] = [task_panel.shown() is None, engagement.FeedPerTooth.Value]

# ---- 2. numbers never silently changed: refused in words, OK disabled and doing nothing -------------------
panel = fresh_panel()
good = {{"Diameter": "12", "Flutes": "2", "SpindleSpeed": "none", "FeedPerTooth": "0.08", "Inclination": "10"}}
refused = {{}}
for name, text in (("Diameter", "1e400"), ("Diameter", "99999999999999999999"), ("Flutes", "99999999"),
                   ("SpindleSpeed", "1e400"), ("Diameter", "12,5"), ("Diameter", "1e-400"), ("Diameter", "0"),
                   ("FeedPerTooth", "0")):
    retype(name, text)
    refused[f"{{name}} {{text}}"] = seen(name)
    if text == "12,5":
        for folder in {folders!r}:
            os.makedirs(folder, exist_ok=True)
            grab_screen(os.path.join(folder, "task_panel_numbers.png"))
    click("OK")
    refused[f"{{name}} {{text}}"].append([task_panel.shown() is panel, engagement.Diameter.Value,
                                          engagement.Flutes, engagement.FeedPerTooth.Value])
    panel = task_panel.shown() or open_panel()  # (opened again where OK took the value: a fault)
    retype(name, good[name])
verdict["refused"] = refused
clear("Diameter")
verdict["emptied"] = seen("Diameter")
click("OK")
verdict["emptied_ok"] = [task_panel.shown() is panel, engagement.Diameter.Value]
panel = task_panel.shown() or open_panel()
retype("Diameter", "12")
clear("Inclination")
verdict["emptied_inclination"] = seen("Inclination")
retype("Inclination", "10")
verdict["good_again"] = [panel.message.text(), button("OK").isEnabled()]
# where the decimal point is a comma, "12,5" is 12.5 and "12.5" is refused
QtCore.QLocale.setDefault(QtCore.QLocale(QtCore.QLocale.German, QtCore.QLocale.Germany))
panel = fresh_panel()
verdict["comma_shown"] = text_of("FeedPerTooth")
retype("Diameter", "12.5")
verdict["comma_point"] = seen("Diameter")
retype("Diameter", "12,5")
verdict["comma"] = seen("Diameter") + [panel.values()["Diameter"]]
click("OK")
verdict["comma_stored"] = [task_panel.shown() is None, engagement.Diameter.Value]
QtCore.QLocale.setDefault(QtCore.QLocale.c())

# ---- 3. the job model's ranges: its messages, and the arrows stepping within them ------------------------
panel = fresh_panel()
key(panel.field("Forces"), QtCore.Qt.Key_Space, " ")
panel.field("Material").setCurrentText("custom")
settle()
ranges = {{}}
good.update({{"HelixAngle": "0", "Ktc": "796.1"}})
for name, text in (("Flutes", "500"), ("Flutes", "1001"), ("Inclination", "90"), ("Inclination", "-89.5"),
                   ("HelixAngle", "61"), ("Ktc", "2000000"), ("Ktc", "796.12345"), ("Ktc", "0")):
    retype(name, text)
    ranges[f"{{name}} {{text}}"] = seen(name) + [panel.values()[name]]
    retype(name, good[name])
verdict["ranges"] = ranges
steps = []
for name, text, code in (("Inclination", "88.5", QtCore.Qt.Key_Up), ("Flutes", "999", QtCore.Qt.Key_Up),
                         ("Flutes", "2", QtCore.Qt.Key_Down)):
    retype(name, text)
    for _ in range(2):
        key(panel.field(name), code)
        settle()
        steps.append(text_of(name))
verdict["steps"] = steps
click("Cancel")
verdict["report"] = report_since(start)
"""


@pytest.fixture(scope="module")
def verdict(tmp_path_factory):
    """The verdict of BODY run once in the real GUI, for the first three tests."""
    folder = tmp_path_factory.mktemp("numbers")
    return run_body(folder, lambda body: run_macro(body, folder), BODY)


def words(name, value):
    """The job model's message for `value` of parameter `name`, in the GUI's words (jobs.label_words)."""
    with pytest.raises(ParameterError) as error:
        BY_NAME[name].check(value)
    return label_words(error.value)


def test_feed_per_tooth_is_shown_and_read_in_mm(verdict):
    # 0.08 mm was shown as "80.00 µm", and a bare "0.1" typed next was 0.1 µm: 0.0001 mm/tooth
    assert verdict["feed_shown"] == [True, 0.08, "0.08 mm", "20000 mm"]
    assert verdict["feed_typed"] == ["0.1", "", True, False]
    assert verdict["feed_stored"] == [True, 0.1, ["Up-to-date"]]
    # a unit typed is still converted
    assert verdict["feed_micrometres"] == ["80 µm", "", True, False, 0.08]
    assert verdict["feed_micrometres_stored"] == [True, 0.08]


def test_numbers_typed_are_never_silently_changed(verdict):
    kept = [True, 12.0, 2, 0.08]  # OK clicked: nothing applied
    refused = verdict["refused"]
    assert refused == {
        "Diameter 1e400": ["1e400", "Tool diameter: “1e400” is too large a number.", False, True, kept],
        "Diameter 99999999999999999999": ["99999999999999999999", words("diameter", 1e20), False, True, kept],
        "Flutes 99999999": ["99999999", words("flutes", 99999999.0), False, True, kept],
        "SpindleSpeed 1e400": ["1e400", "Spindle speed: “1e400” is too large a number.", False, True, kept],
        "Diameter 12,5": ["12,5", "Tool diameter: “12,5” has a “,”: decimals take a “.” (12.5), thousands no "
                                  "separator (1000).", False, True, kept],
        "Diameter 1e-400": ["1e-400", "Tool diameter: “1e-400” is too small a number: it would be taken as 0.",
                            False, True, kept],
        "Diameter 0": ["0", words("diameter", 0.0), False, True, kept],
        "FeedPerTooth 0": ["0", words("feed_per_tooth", 0.0), False, True, kept],
    }
    assert words("diameter", 0.0) == "Tool diameter must be positive, got 0 mm."
    # an emptied field is an error, not the old value
    assert verdict["emptied"] == ["", "Tool diameter is required: the field is empty.", False, True]
    assert verdict["emptied_ok"] == [True, 12.0]
    assert verdict["emptied_inclination"] == [
        "", "Inclination angle: the field is empty: type a number, with a unit if you like (10°, 0.2 rad).", False,
        True]
    assert verdict["good_again"] == ["", True]
    # with a decimal comma: "12,5" is 12.5, "12.5" refused, values shown with the comma
    assert verdict["comma_shown"] == "0,08 mm"
    assert verdict["comma_point"] == ["12.5", "Tool diameter: “12.5” has a “.”: decimals take a “,” (12,5), "
                                              "thousands no separator (1000).", False, True]
    assert verdict["comma"] == ["12,5", "", True, False, 12.5]
    assert verdict["comma_stored"] == [True, 12.5]


def test_ranges_are_the_job_models(verdict):
    ranges = verdict["ranges"]
    assert ranges == {
        "Flutes 500": ["500", "", True, False, 500.0],
        "Flutes 1001": ["1001", words("flutes", 1001.0), False, True, 1001.0],
        "Inclination 90": ["90", words("inclination", 90.0), False, True, 90.0],
        "Inclination -89.5": ["-89.5", "", True, False, -89.5],
        "HelixAngle 61": ["61", words("helix", 61.0), False, True, 61.0],
        "Ktc 2000000": ["2000000", "", True, False, 2e6],
        "Ktc 796.12345": ["796.12345", "", True, False, 796.12345],
        "Ktc 0": ["0", words("ktc", 0.0), False, True, 0.0],
    }
    # the arrow keys step within the range, and not out of it
    assert verdict["steps"] == ["89.5°", "89.5°", "1000", "1000", "1", "1"]
    assert clean(verdict["report"]), verdict["report"]


FUZZ_BODY = SETUP + SEEN + """
import math
from hypothesis import HealthCheck, given, settings, strategies as st
from abm_workbench.gui.reporting import CommandError
from abm_workbench.jobs import BY_NAME

start = len(report.toPlainText())
panel = open_panel()
key(panel.field("Forces"), QtCore.Qt.Key_Space, " ")
panel.field("Material").setCurrentText("custom")
settle()
units = {{row[0]: row[2] for row in task_panel.FIELDS + task_panel.FORCE_FIELDS}}  # declared: "mm", "deg", None
parameter_of = {{parameter.prop: parameter for parameter in BY_NAME.values()}}
names = [name for name in units if panel.field(name).isEnabled()]
originals = {{name: text_of(name) for name in names}}
def not_computed(doc, objects):
    # OK sets the properties, then recomputes: not here (any accepted value, however slow to compute)
    raise CommandError("not computed in this test")
task_panel.recompute_checked = not_computed
BARE = set("0123456789.eE+- ")
def reference(name, typed):
    # what `typed` means in the field's declared unit, found without the panel's reader: a plain decimal
    # number by Python's float, one with a unit by FreeCAD's own parser; None when it is neither
    unit, stripped = units[name], typed.strip()
    if name == "SpindleSpeed" and stripped.lower() == "none":
        return 0.0
    if stripped and set(stripped) <= BARE:
        try:
            return float(stripped)
        except ValueError:
            return None
    if unit is None:
        return None
    try:
        quantity = FreeCAD.Units.Quantity(stripped)
    except ValueError:
        return None
    if quantity.Unit != getattr(FreeCAD.Units, {{"mm": "Length", "deg": "Angle"}}[unit]):
        return None
    return quantity.getValueAs(unit).Value
seen_counts = {{"accepted": 0, "refused": 0, "fields": set()}}
NUMBER = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False).map(repr),
    st.floats(-1e4, 1e4).map(lambda x: f"{{x:.3f}}"),
    st.integers(-10 ** 22, 10 ** 22).map(str),
    st.floats(0.0, 60.0).map(repr), st.floats(0.0, 60.0).map(lambda x: f"{{x:.2f}}"), st.integers(1, 100).map(str),
    st.sampled_from(["1e400", "-1e400", "1e-400", "4e-320", "0", "-0", ".5", "5.", "12,5", "1,000", "none", " 7 "]))
UNIT = st.sampled_from(["", "", " mm", "mm", " in", " µm", " m", "°", " rad", " deg", " s", " e", "x2"])
CHARACTERS = st.characters(whitelist_categories=("L", "N", "P", "S", "Zs"), max_codepoint=0xFFFF)
TYPED = st.one_of(st.tuples(NUMBER, UNIT).map("".join), st.text(CHARACTERS, max_size=8),
                  st.text("0123456789.,eE+- ", max_size=10))

@settings(max_examples={examples}, deadline=None, database=None, suppress_health_check=list(HealthCheck))
@given(st.sampled_from(names), TYPED)
def typed_into(name, typed):
    clear(name)
    for char in typed:
        upper = char.upper()
        key(panel.field(name), ord(upper) if len(upper) == 1 else QtCore.Qt.Key_unknown, char)
    settle()
    shown, message, ok, _ = seen(name)
    assert shown == typed, f"{{name}}: typed {{typed!r}}, the field shows {{shown!r}}"
    if ok:
        assert not message, message
        click("OK")
        stored = task_panel._property_value(engagement, name)
        expected = reference(name, typed)
        assert expected is not None, f"{{name}}: {{typed!r}} is no number, yet {{stored!r}} was stored"
        assert math.isclose(stored, expected, rel_tol=1e-15, abs_tol=0.0), f"{{name}}: {{typed!r}} stored: {{stored!r}}"
        if not (name == "SpindleSpeed" and stored == 0):
            parameter_of[name].check(stored)  # accepted: inside the declared range
        seen_counts["accepted"] += 1
    else:
        assert message, f"{{name}}: {{typed!r}} refused without a word"
        seen_counts["refused"] += 1
    seen_counts["fields"].add(name)
    trace = report_since(start)
    assert "Traceback" not in trace and 'File "' not in trace, trace
    panel.field(name).findChild(QtWidgets.QLineEdit).setText(originals[name])
    assert panel.check(), panel.message.text()

typed_into()
verdict["fuzz"] = [seen_counts["accepted"], seen_counts["refused"], sorted(seen_counts["fields"]), sorted(names)]
click("Cancel")
verdict["report"] = [line for line in report_since(start).splitlines() if "not computed in this test" not in line]
"""


def test_fuzz_typed_strings_are_read_in_the_declared_unit_or_refused(tmp_path, run_gui):
    # hypothesis's strings typed key by key into every enabled field: the field shows what was typed; the
    # panel either accepts it, and OK stores the number it means in the field's declared unit (Python's
    # float for a plain number, FreeCAD's parser for one with a unit) inside the job model's range, or
    # says why and disables OK; the report view never shows a traceback
    verdict = run_body(tmp_path, run_gui, FUZZ_BODY.replace("{examples}", str(FUZZ_EXAMPLES)))
    accepted, refused, fields, names = verdict["fuzz"]
    assert accepted > 10 and refused > 10 and len(fields) > 10, verdict["fuzz"]
    assert len(names) == 19 and "CornerRadius" in names and "YWindowMin" not in names, names  # all 21 number
    # fields but the y window's two (a JSON stock has none)
    assert clean("\n".join(verdict["report"])), verdict["report"]
