"""The engine's and the readers' messages in the user's language.

The engine, the readers and the job model word their errors in English, with their values filled in by
f-strings (``f"{path}: line {line}: {detail}"``). Their templates are gathered from the sources
(:func:`templates`: every string or f-string that holds a phrase, passed to an exception such as
``InputError`` or to a call within a ``raise`` statement, such as a reader's ``self.error(record, …)``, to a
warning or note (``warn``, ``features.base.tell``, ``errors.note``) or appended to a list of warnings, notes or
conflicts; and what a local name such a message is, or holds as a value, was assigned in the same function)
into the translation template's context :data:`CONTEXT`, each value a named placeholder (``{path}``, named
after the f-string's expression). The GUI finds the template a message was made from
(:class:`Catalogue`: the template's words in order, its values in between) and shows the translation
with the same values, each value itself translated where it is a message. A message no template matches,
or whose template has no translation, is shown as it is: the values are never changed, only the words
around them. Pure Python (no Qt): the translation is a function given in.
"""

import ast
import os
import re
import xml.etree.ElementTree as ElementTree

from ..jobs.parameters import REQUIRED_WORDS

#: Translation context of the engine's and readers' messages.
CONTEXT = "ABM_messages"
PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
#: Packages whose messages the GUI shows (its own words go through i18n.translate).
SOURCES = ("engine", "formats", "jobs", "cad", "cam", "features", "report", "errors.py", "limits.py",
           "parallel.py", "scheduling.py", "validation.py", "forces.py", "worker_processes.py")
#: Callees whose string arguments are messages: exception classes by their name's ending.
_ENDINGS = ("Error", "Failed", "Exception")
_PLACEHOLDER = re.compile(r"\{([A-Za-z_][A-Za-z0-9_]*)\}")
#: Words that messages carry, made where no exception is: the job model's ranges (jobs.Parameter.range_text:
#: "must be {range}, got …") and what a missing parameter says (jobs.label_words).
VALUES = ("positive", "above {low}", "at least {low}", "below {high}", "at most {high}", "within {interval}",
          REQUIRED_WORDS)
#: Values within a message that are themselves messages are translated this many levels deep.
DEPTH = 4


def _name(expression, taken):
    """A placeholder name for the f-string value `expression` (an ast node), made unique among `taken`:
    a variable's or attribute's name (``error.detail`` → ``detail``), ``count`` for ``len(…)``, ``type``
    for a type's name, short expressions in word characters (``row[0]`` → ``row_0``), else ``value``."""
    if isinstance(expression, ast.Name):
        words = expression.id
    elif isinstance(expression, ast.Attribute):
        words = "type" if expression.attr.startswith("__") else expression.attr
    elif isinstance(expression, ast.Call) and getattr(expression.func, "id", "") == "len":
        words = "count"
    else:
        words = re.sub(r"[^A-Za-z0-9_]+", "_", ast.unparse(expression)).strip("_")
        words = words if 0 < len(words) <= 16 and not words[0].isdigit() else "value"
    name, number = words, 2
    while name in taken:
        name, number = f"{words}_{number}", number + 1
    taken.add(name)
    return name


def template_of(node):
    """The template of a str constant or f-string node (its values as named placeholders), or None for
    other nodes and for text without a phrase (a field's name such as ``phi_end``: no space and letter)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        text, literal = node.value, node.value
    elif isinstance(node, ast.JoinedStr):
        taken, parts, literal = set(), [], ""
        for value in node.values:
            if isinstance(value, ast.Constant):
                parts.append(value.value)
                literal += value.value
            else:
                parts.append("{" + _name(value.value, taken) + "}")
        text = "".join(parts)
    else:
        return None
    if " " not in literal.strip() or not re.search(r"[A-Za-z]{2}", literal) or _PLACEHOLDER.search(literal):
        return None
    return text


def templates(package=PACKAGE, sources=SOURCES):
    """[template, …] of the messages passed to exceptions, to calls within raise statements or to warnings
    and notes (:func:`_says`), with the strings their local names were assigned (:func:`_messages`), in the
    `sources` (files or folders) of `package`, in the order of the files and lines, each once; then
    :data:`VALUES`."""
    paths = []
    for source in sources:
        path = os.path.join(package, source)
        if os.path.isdir(path):
            paths += sorted(os.path.join(folder, name) for folder, _, names in os.walk(path)
                            for name in names if name.endswith(".py"))
        elif os.path.exists(path):
            paths.append(path)
    found = {}
    for path in sorted(paths):
        with open(path, encoding="utf-8") as handle:
            tree = ast.parse(handle.read(), path)
        raised = {id(call) for node in ast.walk(tree) if isinstance(node, ast.Raise) and node.exc is not None
                  for call in ast.walk(node.exc) if isinstance(call, ast.Call)}
        for scope in [tree] + [node for node in ast.walk(tree) if isinstance(node, _FUNCTIONS)]:
            assigned = _assigned(scope)
            for node in _own(scope):
                if isinstance(node, ast.Call) and _says(node, raised):
                    for argument in node.args:
                        for branch in _messages(argument, assigned):
                            found.setdefault((path, branch.lineno, branch.col_offset), template_of(branch))
    ordered = dict.fromkeys(found[place] for place in sorted(found) if found[place] is not None)
    return list(ordered) + [text for text in VALUES if text not in ordered]


_FUNCTIONS = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)
#: Callees whose string arguments are messages said without an exception: the readers' and the job model's
#: warnings (``self.warn(line, word, f"…")``, ``warn(f"…")``), the features' report-view lines
#: (features.base.tell) and the phrases marked as messages (errors.note).
_SAYERS = ("warn", "warn_once", "_warn", "tell", "note")
#: Lists whose appended strings are messages: warnings, notes and parameter conflicts collected to be said.
_LISTS = ("warnings", "notes", "conflicts")


def _own(scope):
    """The nodes of `scope` (a module or function node) that are not within a function defined in it."""
    pending = list(ast.iter_child_nodes(scope))
    while pending:
        node = pending.pop()
        yield node
        if not isinstance(node, _FUNCTIONS):
            pending.extend(ast.iter_child_nodes(node))


def _assigned(scope):
    """{name: [value node, …]} of the plain assignments ``name = …`` of `scope`'s own code."""
    found = {}
    for node in _own(scope):
        if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            found.setdefault(node.targets[0].id, []).append(node.value)
    return found


def _says(call, raised):
    """Whether the arguments of `call` are messages: an exception's (by its name's ending), a call within a
    raise statement, a warning's or note's (:data:`_SAYERS`), or a string appended to a list of them."""
    callee = call.func.attr if isinstance(call.func, ast.Attribute) else getattr(call.func, "id", "")
    if callee.endswith(_ENDINGS) or callee in _SAYERS or id(call) in raised:
        return True
    owner = getattr(call.func, "value", None)
    return callee == "append" and (getattr(owner, "id", None) or getattr(owner, "attr", None)) in _LISTS


def _messages(node, assigned, depth=2):
    """The string and f-string nodes a message argument `node` is made of: both branches of a conditional
    (``f"… a number" if … else f"…"``), and what a local name it is, or an f-string holds as a value, was
    assigned in the same function (``reason = "…"`` before ``raise …(f"{where}: {reason}")``), `depth` names
    deep."""
    if isinstance(node, ast.IfExp):
        return _messages(node.body, assigned, depth) + _messages(node.orelse, assigned, depth)
    if isinstance(node, ast.Name):
        return [part for value in assigned.get(node.id, ()) if depth > 0
                for part in _messages(value, assigned, depth - 1)]
    if isinstance(node, ast.JoinedStr):
        return [node] + [part for value in node.values if isinstance(value, ast.FormattedValue)
                         and isinstance(value.value, ast.Name) for part in _messages(value.value, assigned, depth)]
    return [node] if isinstance(node, ast.Constant) and isinstance(node.value, str) else []


#: Messages longer than this (characters) are shown as they are: the matching's time grows with the length.
MAX_LENGTH = 4000


def _pattern(template):
    """(regex, [placeholder, …], [word piece, …]) matching the messages `template` makes: its words
    exactly, any text (at least a character) for each placeholder."""
    pieces = _PLACEHOLDER.split(template)
    regex = "".join(re.escape(piece) if i % 2 == 0 else "(.+?)" for i, piece in enumerate(pieces))
    return re.compile(regex, re.DOTALL), pieces[1::2], [piece for piece in pieces[::2] if piece]


class Catalogue:
    """The templates of the messages (:func:`templates`), to find the one a message was made from."""

    def __init__(self, texts):
        # The templates with the most words first: a message matching a longer one and a shorter one (a
        # general "{where}: {detail}" against the specific) is taken as the longer's.
        self._texts = list(texts)
        self._words = {text: len(_PLACEHOLDER.sub("", text)) for text in self._texts}
        self._patterns = [(text, *_pattern(text)) for text in sorted(self._texts, key=self._words.get, reverse=True)]

    @classmethod
    def from_ts(cls, path):
        """The catalogue of the messages in context CONTEXT of the Qt Linguist file `path`."""
        texts = [message.findtext("source") for context in ElementTree.parse(path).getroot().iter("context")
                 if context.findtext("name") == CONTEXT for message in context.iter("message")]
        return cls(texts)

    def texts(self):
        """[template, …] of the catalogue, in the order given."""
        return list(self._texts)

    def match(self, text):
        """(template, {placeholder: value}) of the template `text` was made from (of those that match it, the
        one with the most words), or None."""
        for template, pattern, names, words in self._patterns:
            if not all(word in text for word in words):
                continue
            found = pattern.fullmatch(text)
            if found:
                return template, dict(zip(names, found.groups()))
        return None

    def translated(self, text, translate, depth=DEPTH):
        """`text` in the words of `translate(template)` (a translation of the template, with the same
        placeholders, or the template itself where there is none), its values kept, and translated in turn
        where they are messages (`depth` levels deep). A leading location no template names (``a.cl:12: ``,
        ``CL 4: ``: up to three parts ending in ": ") is kept, the rest translated, where that reads more of
        the message as templates' words than the whole does. Text no template matches, or longer than
        MAX_LENGTH, stays as it is."""
        return self._translated(text, translate, depth)[0]

    def _translated(self, text, translate, depth):
        """(translated, words): `translated` as translated() gives it, and how many of its characters are
        templates' words (the reading kept: the one with the most)."""
        best = (text, 0)
        if len(text) > MAX_LENGTH or depth < 0:
            return best
        kept, rest = "", text
        for _ in range(4):
            found = self.match(rest)
            if found is not None:
                template, values = found
                words, shown = self._words[template], {}
                for name, value in values.items():
                    shown[name], inner = self._translated(value, translate, depth - 1)
                    words += inner
                if words > best[1]:
                    target = translate(template)
                    if sorted(_PLACEHOLDER.findall(target)) != sorted(values):
                        target = template  # a translator's slip: the placeholders differ
                    best = (kept + _PLACEHOLDER.sub(lambda placeholder: shown[placeholder.group(1)], target), words)
            head, sep, rest = rest.partition(": ")
            if not sep:
                break
            kept += head + sep
        return best
