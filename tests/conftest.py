"""Test set-up shared by every tier: the checkout on sys.path, and hypothesis profiles."""

import os
import sys

from hypothesis import HealthCheck, settings

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)

# Reproducible property tests: the same examples on every run and in CI.
settings.register_profile(
    "abm", derandomize=True, database=None, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("abm")
