"""A FreeCAD CAM Job built and posted by FreeCAD itself, for the tests: freecad_cam_script.py run by
freecadcmd (FreeCAD's own CAM needs FreeCAD's home folder), its arguments in the environment."""

import json
import os
import subprocess

from tests.conftest import ROOT

SCRIPT = os.path.join(ROOT, "tests", "cad", "freecad_cam_script.py")
#: Files a build writes: the document, its linuxcnc post and a LinuxCNC tool table of its tools.
BUILT = ("job.FCStd", "job.ngc", "tools.tbl")


def freecad_cam(*arguments, cwd):
    """Run the script in freecadcmd with `arguments` ("build", FOLDER or "post", DOC, OUT); its output, for
    messages."""
    environment = dict(os.environ, ABM_CAM_SCRIPT=json.dumps(arguments), PYTHONPATH=ROOT)
    done = subprocess.run(["freecadcmd", SCRIPT], env=environment, cwd=cwd, capture_output=True, text=True,
                          timeout=900)
    return done.stdout[-3000:] + done.stderr[-3000:]


def build_job(folder):
    """Build the Job into `folder` (BUILT); AssertionError with FreeCAD's output when a file is missing."""
    output = freecad_cam("build", str(folder), cwd=folder)
    assert all((folder / name).is_file() for name in BUILT), output
    return folder
