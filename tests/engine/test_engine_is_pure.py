"""The engine never imports FreeCAD: it must import and run with FreeCAD blocked."""

import subprocess
import sys
import textwrap

from tests.conftest import ROOT


def test_engine_imports_and_runs_with_freecad_blocked():
    script = textwrap.dedent(
        """
        import sys
        class Block:
            def find_spec(self, name, path=None, target=None):
                if name.split(".")[0] in ("FreeCAD", "FreeCADGui", "Part", "Mesh"):
                    raise ImportError("blocked: " + name)
        sys.meta_path.insert(0, Block())
        from abm_workbench.engine import CutSettings, Staircase, Tool, Toolpath, engage
        stock = Staircase(0, 50, -10, 10, -5, [2.0, 4.0], [[[25.0, y] for y in range(-10, 11, 4)]])
        result = engage(stock, Tool(10, 2, 20), Toolpath([[20, 0, 0]], [0], [10]), CutSettings(0.1))
        assert result.length.max() > 0
        assert not [m for m in sys.modules if m.split(".")[0] in ("FreeCAD", "Part")]
        print("ok")
        """
    )
    run = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "ok"
