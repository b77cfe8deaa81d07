"""Reports of an Engagement and of a validation (matplotlib on an Agg canvas, never pyplot; no FreeCAD).

- :mod:`.plots`: the pass figure of ``engage --plot``.
- :mod:`.figures`: the figures of a validation report (the paper's Figs. 6-8).
- :mod:`.tables`: the CSV files behind a validation report.
- :mod:`.html`: the self-contained HTML page of a validation report.
- :mod:`.colours`: colours shared with the annotated FreeCAD document.
- :mod:`.staging`: outputs written under a temporary name and moved into place at the end.
"""
