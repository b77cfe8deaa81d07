"""Translatable text of the GUI, and the translation template (translations/ABM.ts).

The GUI's words go through :func:`translate` (menu texts and tooltips of the commands through
FreeCAD itself, which translates them in the context of the command's name); words declared in
tables go through :func:`noop` there and :func:`translate` where they are shown. All in the
context :data:`CONTEXT` but the commands'.

``/usr/bin/python3 -m abm_workbench.gui.i18n`` writes ``translations/ABM.ts``, the template a
translator opens in Qt Linguist: every string literal passed to ``translate``, ``noop`` or
``QT_TRANSLATE_NOOP`` in ``abm_workbench/gui`` (found by parsing the sources, as Qt's own
``pylupdate`` does). A translation ``ABM_<language>.qm`` put beside it is loaded by FreeCAD
(InitGui.py adds the folder with ``FreeCADGui.addLanguagePath``).
"""

import ast
import os
import sys
from xml.sax.saxutils import escape

#: Translation context of the GUI's words.
CONTEXT = "ABM"
GUI = os.path.dirname(os.path.abspath(__file__))
#: The translations folder and its template.
FOLDER = os.path.join(os.path.dirname(os.path.dirname(GUI)), "translations")
TEMPLATE = os.path.join(FOLDER, "ABM.ts")


def translate(text, context=CONTEXT):
    """`text` in the user's language (as it is without a translation)."""
    from PySide import QtCore

    return QtCore.QCoreApplication.translate(context, text)


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


def template(found):
    """The .ts XML (Qt Linguist's format) of {context: [text, …]}, untranslated."""
    lines = ['<?xml version="1.0" encoding="utf-8"?>', "<!DOCTYPE TS>", '<TS version="2.1">']
    for context in sorted(found):
        lines += ["<context>", f"    <name>{escape(context)}</name>"]
        for text in found[context]:
            lines += ["    <message>", f"        <source>{escape(text)}</source>",
                      '        <translation type="unfinished"></translation>', "    </message>"]
        lines.append("</context>")
    lines.append("</TS>")
    return "\n".join(lines) + "\n"


def main(path=TEMPLATE):
    """Write the template to `path`; 0."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(template(messages()))
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
