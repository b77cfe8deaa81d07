"""The package's structure: the command line needs no GUI, nothing but __main__ imports cli, no import circles.

Imports are read from the source (every ``import`` and ``from … import``, at module level or inside
functions: a lazy import is still a dependency), so the test also covers modules that need FreeCAD.
"""

import ast
import json
import os
import subprocess

import pytest

from tests.conftest import ROOT

PACKAGE = "abm_workbench"
PYTHON = "/usr/bin/python3"


def _modules():
    """{module name: path} of every module of the package."""
    found = {}
    for folder, _, files in os.walk(os.path.join(ROOT, PACKAGE)):
        for name in files:
            if name.endswith(".py"):
                path = os.path.join(folder, name)
                dotted = os.path.relpath(path, ROOT)[:-3].replace(os.sep, ".")
                found[dotted[: -len(".__init__")] if dotted.endswith(".__init__") else dotted] = path
    return found


def imports_of(name, path, modules):
    """The package's modules that module `name` (file `path`) imports, by name."""
    package = name if path.endswith("__init__.py") else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(open(path, encoding="utf-8").read())):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names if alias.name in modules)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[: len(parts) - node.level + 1] + ([node.module] if node.module else []))
            else:
                base = node.module or ""
            submodules = {f"{base}.{alias.name}" for alias in node.names} & set(modules)
            found.update(submodules)
            if base in modules and len(submodules) < len(node.names):  # names defined by the package itself
                found.add(base)
    found.discard(name)
    return found


def circles(graph):
    """The strongly connected components of more than one module of {module: set of modules} (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(node):
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for other in sorted(graph[node]):
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on_stack:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while True:
                other = stack.pop()
                on_stack.discard(other)
                component.append(other)
                if other == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


@pytest.fixture(scope="module")
def graph():
    modules = _modules()
    return {name: imports_of(name, path, modules) for name, path in modules.items()}


def test_no_import_circle(graph):
    assert circles(graph) == []


def test_the_circle_finder_finds_a_planted_circle(graph):
    planted = {name: set(targets) for name, targets in graph.items()}
    planted["abm_workbench.engine.model"].add("abm_workbench.jobs.run")
    assert any("abm_workbench.engine.model" in circle and "abm_workbench.jobs.run" in circle
               for circle in circles(planted))


def test_only_main_imports_cli(graph):
    importers = sorted(name for name, targets in graph.items() if f"{PACKAGE}.cli" in targets)
    assert importers == [f"{PACKAGE}.__main__"]


def test_the_command_line_imports_no_gui_module(tmp_path):
    folder = os.path.join(ROOT, "resources", "models", "model_test_1")
    script = (
        "import json, sys\n"
        "from abm_workbench.cli import main\n"
        f"status = main(['engage', '--job', {os.path.join(folder, 'job.json')!r}, '--stock', "
        f"{os.path.join(folder, 'stock.json')!r}, '--toolpath', {os.path.join(folder, 'toolpath.csv')!r}, "
        f"'--out', {str(tmp_path / 'R.csv')!r}])\n"
        "gui = sorted(m for m in sys.modules if m.startswith('abm_workbench.gui') or m.split('.')[0] in "
        "('FreeCADGui', 'PySide', 'PySide2'))\n"
        "print(json.dumps([status, gui]))\n"
    )
    done = subprocess.run([PYTHON, "-c", script], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout.splitlines()[-1]) == [0, []]
