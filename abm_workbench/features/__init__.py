"""Parametric document objects of the ABM workbench; they work headless (FreeCADCmd or /usr/bin/python3).

- :mod:`.stock`: ``create_stock(doc, source)``, the staircase stock recognised from a Part object or a file.
- :mod:`.toolpath`: ``create_toolpath(doc, path)``, the CL points of a CSV or APT / CL file.
- :mod:`.engagement`: ``create_engagement(doc, stock, toolpath, **settings)``, the engine's results.

Each is a ``Part::FeaturePython`` with properties in groups, tooltips, computed ones read-only,
a ``Version`` property (:mod:`.base`) and nothing of the engine pickled into the document.
docs/FEATURES.md describes them; view providers and commands live in ``abm_workbench/gui``.
"""

from .base import VERSION
from .engagement import create_engagement
from .stock import create_stock
from .toolpath import create_toolpath

__all__ = ["VERSION", "create_engagement", "create_stock", "create_toolpath"]
