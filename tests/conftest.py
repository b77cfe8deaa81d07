"""Test set-up shared by every tier: the checkout on sys.path, an empty HOME, hypothesis profile.

FreeCAD runs the Init.py of every folder in the user's Mod directory when it is imported, so
HOME points at an empty temporary folder before any test can import it.
"""

import atexit
import os
import shutil
import sys
import tempfile

from hypothesis import HealthCheck, settings

_HOME = tempfile.mkdtemp(prefix="abm-test-home-")
atexit.register(shutil.rmtree, _HOME, ignore_errors=True)
os.environ["HOME"] = _HOME

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)

# Reproducible property tests: the same examples on every run and in CI.
settings.register_profile(
    "abm", derandomize=True, database=None, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("abm")
