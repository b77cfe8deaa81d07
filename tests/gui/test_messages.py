"""The engine's and readers' messages in the user's language (abm_workbench.gui.messages), without the GUI:
every template gathered from the sources is in the translation template and translated into German with
the same placeholders, and real errors of the readers and the job model, raised by bad files, are found
by their template and shown in German with their values unchanged. In the running GUI: test_german.py."""

import re
from types import SimpleNamespace

import pytest

from abm_workbench.errors import InputError
from abm_workbench.gui.i18n import TEMPLATE, catalogue, read_translations
from abm_workbench.gui.messages import CONTEXT, Catalogue, templates
from tests.conftest import ROOT

GERMAN = read_translations(f"{ROOT}/translations/ABM_de.ts")
PLACEHOLDER = re.compile(r"\{([A-Za-z_][A-Za-z0-9_]*)\}")


def german(template):
    return GERMAN.get((CONTEXT, template), template)


def test_every_message_is_in_the_template_and_in_german_with_its_placeholders():
    found = templates()
    assert len(found) > 300  # the engine's, readers' and job model's messages, not a handful
    assert found == catalogue()[CONTEXT] == Catalogue.from_ts(TEMPLATE).texts()
    untranslated = [text for text in found if (CONTEXT, text) not in GERMAN]
    assert untranslated == []
    slips = [text for text in found if sorted(PLACEHOLDER.findall(german(text))) != sorted(PLACEHOLDER.findall(text))]
    assert slips == []
    # every template that needs words translated got German words, not the English copied
    assert sum(german(text) == text for text in found) <= 5


def test_a_message_is_taken_apart_into_its_template_and_its_values():
    messages = Catalogue(["{path}: line {line}: {detail}", "must be positive, got {value}", "{where}: no solid"])
    words = {"{path}: line {line}: {detail}": "{path}: Zeile {line}: {detail}",
             "must be positive, got {value}": "muss positiv sein, erhalten: {value}"}
    assert messages.match("a.cl: line 4: must be positive, got -3") == (
        "{path}: line {line}: {detail}", {"path": "a.cl", "line": "4", "detail": "must be positive, got -3"})
    # the values are kept as they are, and translated where they are messages themselves
    assert messages.translated("a.cl: line 4: must be positive, got -3", lambda t: words.get(t, t)) == \
        "a.cl: Zeile 4: muss positiv sein, erhalten: -3"
    # a leading location no template names is kept, the rest translated
    assert messages.translated("CL 7: must be positive, got 0 mm", lambda t: words.get(t, t)) == \
        "CL 7: muss positiv sein, erhalten: 0 mm"
    # nothing matches: as it was; a translation with other placeholders (a slip): the English template
    assert messages.translated("something else entirely", lambda t: "x") == "something else entirely"
    assert messages.translated("a.cl: line 4: oops", lambda t: "{path}: Zeile {zeile}") == "a.cl: line 4: oops"


def _raised(call):
    with pytest.raises(ValueError) as caught:
        call()
    return str(caught.value)


def _errors(tmp_path):
    """Messages of real errors: bad files through the readers, bad values through the job model."""
    from abm_workbench.formats.cl import read_program
    from abm_workbench.formats.staircase_json import load_staircase
    from abm_workbench.jobs.parameters import BY_NAME

    stock = tmp_path / "stock.json"
    stock.write_text('{"format": "abm-staircase", "sections": 3}')
    cl = tmp_path / "program.apt"
    cl.write_text("CUTTER/6\nGOTO/1,2\n")
    text = tmp_path / "notes.txt"
    text.write_text("hello\n")
    missing = tmp_path / "nothing.apt"
    return [_raised(lambda: load_staircase(str(stock))), _raised(lambda: read_program(str(cl))),
            _raised(lambda: read_program(str(text))), _raised(lambda: read_program(str(missing))),
            _raised(lambda: BY_NAME["diameter"].check(-3.0)), _raised(lambda: BY_NAME["flutes"].check(2.5))]


def test_real_errors_are_found_by_their_template_and_shown_in_german(tmp_path):
    messages = Catalogue(templates())
    for text in _errors(tmp_path):
        assert messages.match(text) is not None or messages.match(text.partition(": ")[2]) is not None, text
        assert messages.translated(text, lambda template: template) == text  # English: the message unchanged
        shown = messages.translated(text, german)
        assert shown != text, text
        # the values (the file's name, the numbers) are all still there
        for value in re.findall(r"[\w.-]*\d[\w.-]*|[\w-]+\.(?:json|apt|txt)", text):
            assert value in shown, (value, text, shown)


@pytest.fixture
def reporting(monkeypatch):
    """gui.reporting with ABM_de.ts's German in place of Qt's translator (no GUI runs here), installed for the
    features' report-view lines as InitGui.py installs it."""
    import abm_workbench.cad.freecad_env  # noqa: F401 (FreeCAD on the path)
    from abm_workbench.features import base
    from abm_workbench.gui import reporting

    monkeypatch.setattr(reporting, "translate", lambda text, context="ABM": GERMAN.get((context, text), text))
    monkeypatch.setattr(base, "_LOCALIZER", list(base._LOCALIZER))
    reporting.install()
    return reporting


def test_warnings_the_features_print_reach_the_report_view_in_german(reporting, monkeypatch):
    from abm_workbench.features import base
    from abm_workbench.jobs.inputs import PathHints

    printed = []
    monkeypatch.setattr(base.FreeCAD, "Console", SimpleNamespace(PrintWarning=printed.append))
    hints = PathHints("a.apt", unknown=(("PPRINT", 12, 3), ("SPINDL", 14, 1)), ignored=(("COOLNT", 4, 2),))
    engagement = SimpleNamespace(Label="Engagement")
    for message in hints.messages():
        base.tell(engagement, message)
    base.tell(engagement, f"results not restored ({InputError('r.csv: no such file')}); recompute to compute them")
    assert printed[:3] == ["Engagement: a.apt:12: PPRINT: Datensatz nicht verstanden, ignoriert (3-mal)\n",
                           "Engagement: a.apt:14: SPINDL: Datensatz nicht verstanden, ignoriert\n",
                           "Engagement: a.apt: Datensätze ohne etwas, das der Rechenkern braucht, ignoriert: "
                           "COOLNT (2)\n"]
    assert printed[3].startswith("Engagement: Ergebnisse nicht wiederhergestellt (r.csv: ")
    assert "no such file" not in printed[3] and printed[3].endswith("berechnen Sie neu, um sie zu erhalten\n")


def test_a_message_built_in_a_variable_before_its_raise_is_shown_in_german(reporting, tmp_path):
    from abm_workbench.formats.apt import load_apt
    from abm_workbench.jobs.run import in_process_sweep

    program = tmp_path / "no_moves.apt"
    program.write_text("CUTTER/6\nFEDRAT/100\n")
    with pytest.raises(InputError) as caught:
        load_apt(str(program))
    shown = reporting.message_of(caught.value)
    assert shown.startswith(f"{program}:2: ") and shown.endswith("(kein GOTO-Datensatz)"), shown
    # a phrase given as a value (the tool the in-process stock is not there for yet) is translated too
    prepared = SimpleNamespace(job=SimpleNamespace(stock_model=None), tool=SimpleNamespace(helix=30.0))
    assert reporting.localized(in_process_sweep(prepared)[1]) == \
        "das Zwischenrohteil ist mit einem Werkzeug mit Drallwinkel noch nicht verfügbar"


def test_singular_and_plural_are_whole_phrases_in_each_language():
    from abm_workbench.formats import check_keys, parse_number

    messages = Catalogue(templates())
    one = _raised(lambda: check_keys({"a": 1, "tool": 2}, ("a",), (), "job.json"))
    two = _raised(lambda: check_keys({"a": 1, "tool": 2, "mill": 3}, ("a",), (), "job.json"))
    assert (one, two) == ("job.json: unknown key 'tool' (allowed: 'a')",
                          "job.json: unknown keys 'tool', 'mill' (allowed: 'a')")
    assert messages.translated(one, german) == "job.json: unbekannter Schlüssel 'tool' (erlaubt: 'a')"
    assert messages.translated(two, german) == "job.json: unbekannte Schlüssel 'tool', 'mill' (erlaubt: 'a')"
    assert messages.translated(_raised(lambda: parse_number("nan", "a.csv:3")), german) == \
        "a.csv:3: 'nan' ist keine endliche Zahl (Ziffern 0-9, optionales Vorzeichen, '.' und Exponent)"


def test_the_operating_systems_file_errors_are_in_german_with_their_file(reporting, tmp_path):
    missing = tmp_path / "stock.json"
    with pytest.raises(OSError) as caught:
        open(missing, encoding="utf-8")
    assert reporting.message_of(caught.value) == f"[Errno 2] Datei oder Verzeichnis nicht gefunden: '{missing}'"
    with pytest.raises(OSError) as caught:
        open(tmp_path, encoding="utf-8")
    assert reporting.message_of(caught.value) == f"[Errno 21] Ist ein Verzeichnis: '{tmp_path}'"
    # within another message too; words that are not the system's exact ones for the number stay as they are
    assert reporting.localized(f"a.FCStd: cannot write: [Errno 28] No space left on device: '{missing}'") == \
        f"a.FCStd: cannot write: [Errno 28] Kein Speicherplatz mehr auf dem Gerät: '{missing}'"
    assert reporting.localized("[Errno 2] Is a directory: 'x'") == "[Errno 2] Is a directory: 'x'"


def test_a_g_code_word_is_a_wort_in_every_german_message():
    words = [text for text in templates() if re.search(r"\b(?:[A-Z]|\{\w+\}|axis) words?\b", text)]
    assert len(words) >= 5
    # "Wort" (a letter and its number, DIN 66025), never "Adresse" (the letter alone)
    wrong = [german(text) for text in words if "Adresse" in german(text) or not re.search("Wort|Wörter", german(text))]
    assert wrong == []


def test_a_kind_given_as_a_word_is_a_whole_german_phrase(monkeypatch):
    """The feed schedule's limit and a mill's kind are whole messages, one for each kind: no English word
    ("force", "bull-nose") is left as a value inside the German sentence."""
    from abm_workbench import forces
    from abm_workbench.scheduling import schedule

    messages = Catalogue(templates())
    shown = {kind: messages.translated(_raised(lambda: schedule(None, -2.0, kind=kind)), german)
             for kind in ("force", "area")}
    assert shown == {"force": "der Grenzwert der Schnittkraft muss eine positive Zahl sein, erhalten: -2",
                     "area": "der Grenzwert des Spanungsquerschnitts muss eine positive Zahl sein, erhalten: -2"}
    monkeypatch.setattr(forces, "check_arguments", lambda **given: None)
    coefficients = forces.Coefficients(ktc=700.0, krc=210.0, kac=120.0, kte=25.0, kre=30.0, kae=4.0)
    for kind, mill in (("ball", "Kugelfräsers"), ("bull-nose", "Torusfräsers")):
        tool = SimpleNamespace(helix=0.0, corner_radius=2.0, kind=kind)
        text = _raised(lambda: forces.pass_forces(None, tool, None, None, coefficients, lengths_at=len))
        assert messages.translated(text, german).startswith(f"die Kräfte eines {mill} erfordern "), text
    # the job model's (the Z-map baseline's refusal, the schedule's warning), as the code words them
    for text, words in (
            ("the Z-map baseline samples a flat-end mill's edge; this bull-nose mill (corner radius 2 mm) is computed "
             "by the ABM engine only", "dieser Torusfräser (Eckenradius 2 mm)"),
            ("the Z-map baseline samples a flat-end mill's edge; this ball mill (corner radius 5 mm) is computed by "
             "the ABM engine only", "dieser Kugelfräser (Eckenradius 5 mm)"),
            ("3 CL points cannot keep the area at or under 4 mm² at any feed from the minimum feed up; they get the "
             "minimum feed: CL 1 (peak 5 mm²)", "können den Spanungsquerschnitt bei keinem Vorschub")):
        assert words in messages.translated(text, german), text


def test_a_file_without_solids_says_so_in_german(tmp_path):
    """A BREP file of a face alone, asked for a solid by name: "(its solids: none)" is a message of its own, not
    the English "none" as the list of solids."""
    from abm_workbench.cad.freecad_env import Part
    from abm_workbench.cad.recognise import load_solid

    path = tmp_path / "face.brep"
    Part.makePlane(10, 10).exportBrep(str(path))
    text = _raised(lambda: load_solid(path, "Solid1"))
    assert text == f"{path}: no solid named 'Solid1' in the BREP file (its solids: none)"
    assert Catalogue(templates()).translated(text, german) == \
        f"{path}: kein Volumenkörper namens 'Solid1' in der BREP-Datei (sie enthält keine Volumenkörper)"


def test_phrases_returned_or_joined_into_a_message_are_german_too(tmp_path):
    """Words a helper returns into a message (what a path is instead of a file, why a G-code word or a B-spline's
    knots are refused, what a JSON value must be) and a remedy added to the size checks' messages are gathered
    (errors.note) and shown in German, the values kept."""
    from abm_workbench.formats import check_input_file
    from abm_workbench.formats.cl.nurbs import resolve
    from abm_workbench.formats.gcode.blocks import blocks_of_text
    from abm_workbench.formats.terraced_json import load_terraced
    from abm_workbench.limits import check_large, check_memory

    messages = Catalogue(templates())

    def shown(call):
        return messages.translated(_raised(call), german)

    assert shown(lambda: check_input_file(tmp_path)) == \
        f"{tmp_path}: ist ein Ordner, keine Datei; geben Sie die Eingabedatei selbst an"
    assert _raised(lambda: check_input_file(tmp_path, "tool table")) == \
        f"{tmp_path}: is a folder, not a file; give the tool table file itself"
    assert shown(lambda: check_input_file(tmp_path, "tool table")) == \
        f"{tmp_path}: ist ein Ordner, keine Datei; geben Sie die Werkzeugtabellendatei selbst an"
    assert shown(lambda: blocks_of_text("G1 X=5\n", "a.nc")) == \
        "a.nc:1: X=5: Zuweisungen (X=…) werden nicht gelesen: schreiben Sie einen Buchstaben und eine Zahl"
    assert shown(lambda: resolve([0, 0, 1, 0.5, 1, 1], [(0, 0, 0), (1, 0, 0), (2, 0, 0)], None, 0.01)) == \
        "seine Knoten ergeben keine Kurve (full, Grad 2: die Knoten fallen)"
    stock = tmp_path / "plate.json"
    stock.write_text('{"format": "abm-terraced/1", "units": "mm", "base_z": 0, "slabs": []}')
    assert shown(lambda: load_terraced(stock)) == \
        f"{stock}: slabs: muss eine nicht leere Liste von Schichten sein, erhalten: []"
    memory = shown(lambda: check_memory(1e30, "a.apt", "the engage run", "give a larger --grid"))
    assert memory.startswith("a.apt: der Lauf von engage würde etwa ") and \
        memory.endswith(": geben Sie ein größeres --grid an"), memory
    from abm_workbench.jobs.run import check_run_size

    run = SimpleNamespace(toolpath=range(10 ** 7), settings=SimpleNamespace(phi=SimpleNamespace(size=1000)))
    assert shown(lambda: check_run_size(SimpleNamespace(toolpath="a.apt"), run)).startswith(
        "a.apt: 10,000,000 CL-Punkte x 1,000 Winkel = 10,000,000,000 Zeitpunkte (mehr als die ")
    # the in-process stock's sweep, as check_sweep words it: the file, then what is large, each translated
    assert messages.translated("a.apt: the in-process stock: its sweep (5 pieces, 7 bounding balls) would need about "
                               "3 GiB of memory, and this process may use 1 GiB: give --stock-model initial (the "
                               "stock as given)", german) == \
        ("a.apt: das Zwischenrohteil: sein Überstreichen (5 Stücke, 7 Hüllkugeln) würde etwa 3 GiB Arbeitsspeicher "
         "benötigen, und der für diesen Prozess nutzbare Arbeitsspeicher beträgt 1 GiB: geben Sie --stock-model "
         "initial (das Rohteil wie gegeben) an")
    large = shown(lambda: check_large("a.apt", "{} pieces", 10, 5, "give --stock-model initial (the stock as given)"))
    assert large == ("a.apt: 10 pieces (mehr als die 5, die ein Lauf ohne Bestätigung verarbeitet): geben Sie "
                     "--stock-model initial (das Rohteil wie gegeben) an, oder geben Sie --allow-large an, um ihn "
                     "trotzdem auszuführen")
