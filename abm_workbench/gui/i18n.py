"""Translatable text of the GUI, and the translation template (translations/ABM.ts).

The GUI's words go through :func:`translate` (menu texts and tooltips of the commands through
FreeCAD itself, which translates them in the context of the command's name); words declared in
tables go through :func:`noop` there and :func:`translate` where they are shown. All in the
context :data:`CONTEXT` but the commands'.

``/usr/bin/python3 -m abm_workbench.gui.i18n`` writes ``translations/ABM.ts``, the template a translator
opens in Qt Linguist: every string literal passed to ``translate``, ``noop`` or ``QT_TRANSLATE_NOOP`` in
``abm_workbench/gui`` (found by parsing the sources, as Qt's own ``pylupdate`` does), the templates of
the engine's and readers' messages (context ``ABM_messages``, :mod:`.messages`) and the job parameters'
labels (context ``ABM_parameters``), and brings each translation ``translations/ABM_<language>.ts`` up
to date with it (its translations kept, new texts added unfinished, texts gone dropped). ``make
translations`` does that and compiles each to ``ABM_<language>.qm`` with Qt's ``lrelease``.

:func:`install` (InitGui.py) adds the folder with ``FreeCADGui.addLanguagePath``: FreeCAD loads the
``.qm`` of its language from there at start and again whenever the language is changed in the
preferences. Widgets made after that show the new language (the dock and the task panel are made
anew when shown).
"""

import ast
import glob
import os
import sys
import xml.etree.ElementTree as ElementTree
from xml.sax.saxutils import escape

#: Translation context of the GUI's words, and of the job parameters' labels (jobs.PARAMETERS).
CONTEXT = "ABM"
PARAMETERS = "ABM_parameters"
GUI = os.path.dirname(os.path.abspath(__file__))
#: The validation report's sources: their words passed to translate / noop are the GUI's too (context ABM).
REPORT = os.path.join(os.path.dirname(GUI), "report")
#: The translations folder and its template.
FOLDER = os.path.join(os.path.dirname(os.path.dirname(GUI)), "translations")
TEMPLATE = os.path.join(FOLDER, "ABM.ts")


def translate(text, context=CONTEXT, **values):
    """`text` in the user's language (as it is without a translation), its {placeholders} filled with
    `values` when given. A translation whose placeholders are not the text's (a translator's slip) is
    not used: the text is shown untranslated rather than the GUI failing. Without Qt (FreeCAD headless,
    whose checks of typed numbers the tests use) the text as it is."""
    try:
        from PySide import QtCore
    except ImportError:
        translated = text
    else:
        translated = QtCore.QCoreApplication.translate(context, text)
    if not values:
        return translated
    try:
        return translated.format(**values)
    except (KeyError, IndexError, ValueError):
        return text.format(**values)


def language():
    """The code of the GUI's language ("de"; "en" where FreeCAD does not say it, or without its GUI)."""
    try:
        import FreeCADGui

        return FreeCADGui.supportedLocales().get(FreeCADGui.getLocale(), "en").replace("_", "-")
    except (ImportError, AttributeError):
        return "en"


def noop(text):
    """`text` unchanged, marked for the template: translated where it is shown (:func:`translate`)."""
    return text


def QT_TRANSLATE_NOOP(context, text):  # noqa: N802 (Qt's name, which FreeCAD's commands use)
    """`text` unchanged, marked for the template in `context` (a command's name: FreeCAD translates
    the command's menu text and tooltip in it)."""
    return text


def messages(folder=GUI):
    """{context: [text, …]} of the string literals passed to translate / noop / QT_TRANSLATE_NOOP in
    the Python files of `folder` (each text once per context)."""
    found = {}

    def add(context, text):
        texts = found.setdefault(context, [])
        if text not in texts:
            texts.append(text)

    for name in sorted(os.listdir(folder)):
        if not name.endswith(".py"):
            continue
        with open(os.path.join(folder, name), encoding="utf-8") as handle:
            tree = ast.parse(handle.read(), name)
        for node in ast.walk(tree):
            if not isinstance(node, ast.Call):
                continue
            called = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            strings = [arg.value if isinstance(arg, ast.Constant) and isinstance(arg.value, str) else None
                       for arg in node.args]
            if called in ("translate", "noop") and strings and strings[0] is not None:
                add(strings[1] if called == "translate" and len(strings) > 1 and strings[1] else CONTEXT, strings[0])
            elif called == "QT_TRANSLATE_NOOP" and len(strings) == 2 and None not in strings:
                add(strings[0], strings[1])
    return found


def catalogue():
    """{context: [text, …]} of everything the template holds: the GUI's words (:func:`messages`) and the
    validation report's (report.html.translate), the engine's and readers' message templates
    (messages.templates) and the job parameters' labels."""
    from ..jobs.parameters import PARAMETERS as LABELLED
    from .messages import CONTEXT as MESSAGES, templates

    found = messages()
    for context, texts in messages(REPORT).items():  # the validation report's words (report.html.translate)
        found[context] = list(dict.fromkeys(found.get(context, []) + texts))
    found[MESSAGES] = templates()
    found[PARAMETERS] = list(dict.fromkeys(parameter.label for parameter in LABELLED))
    return found


def template(found, translations=None, language=None):
    """The .ts XML (Qt Linguist's format) of {context: [text, …]}: untranslated, or with `translations`
    {(context, text): translation} of `language` ("de") where they have one."""
    translations = translations or {}
    head = '<TS version="2.1">' if language is None else f'<TS version="2.1" language="{escape(language)}">'
    lines = ['<?xml version="1.0" encoding="utf-8"?>', "<!DOCTYPE TS>", head]
    for context in sorted(found):
        lines += ["<context>", f"    <name>{escape(context)}</name>"]
        for text in found[context]:
            done = translations.get((context, text))
            translation = ('        <translation type="unfinished"></translation>' if not done else
                           f"        <translation>{escape(done)}</translation>")
            lines += ["    <message>", f"        <source>{escape(text)}</source>", translation, "    </message>"]
        lines.append("</context>")
    lines.append("</TS>")
    return "\n".join(lines) + "\n"


def read_translations(path):
    """{(context, source): translation} of the finished messages of the .ts file `path`."""
    found = {}
    for context in ElementTree.parse(path).getroot().iter("context"):
        name = context.findtext("name")
        for message in context.iter("message"):
            translation = message.find("translation")
            if translation is not None and translation.get("type") != "unfinished" and translation.text:
                found[(name, message.findtext("source"))] = translation.text
    return found


def translations_of(folder=FOLDER):
    """{language: path} of the translations ``ABM_<language>.ts`` in `folder`."""
    paths = glob.glob(os.path.join(folder, "ABM_*.ts"))
    return {os.path.basename(path)[len("ABM_"):-len(".ts")]: path for path in sorted(paths)}


def install():
    """Let FreeCAD load the workbench's translations (now, and when its language changes)."""
    import FreeCADGui

    FreeCADGui.addLanguagePath(FOLDER)
    FreeCADGui.updateLocale()


def main(path=TEMPLATE):
    """Write the template to `path` and bring the translations beside it up to date; 0."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    found = catalogue()
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(template(found))
    print(path)
    for language, translation in translations_of(os.path.dirname(path)).items():
        kept = read_translations(translation)
        with open(translation, "w", encoding="utf-8") as handle:
            handle.write(template(found, kept, language))
        missing = sum(len(texts) for texts in found.values()) - sum(
            (context, text) in kept for context, texts in found.items() for text in texts)
        print(f"{translation}: {missing} texts to translate" if missing else translation)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
