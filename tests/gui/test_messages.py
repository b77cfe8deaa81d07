"""The engine's and readers' messages in the user's language (abm_workbench.gui.messages), without the GUI:
every template gathered from the sources is in the translation template and translated into German with
the same placeholders, and real errors of the readers and the job model, raised by bad files, are found
by their template and shown in German with their values unchanged. In the running GUI: test_german.py."""

import re

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
