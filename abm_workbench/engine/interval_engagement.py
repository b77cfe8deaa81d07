"""An Engagement built from the inside intervals of a pass's edge lines (the terraced and in-process engines)."""

import dataclasses

import numpy as np

from .engagement import CASES, empty_results, finished_engagement


def engagement_from_intervals(intervals, toolpath, tool, settings, origins, directions):
    """The Engagement of a pass from the inside intervals of its edge lines.

    intervals: EdgeIntervals of N = m·p lines (row i·p + k for CL point i of `toolpath` and
    angle k of settings.phi); origins (N, 3) mm at l = 0 and directions (N, 3) unit, the lines
    they were found on; `tool` gives the flute length the intervals must lie within. Per
    instant: lep_l = start of the first interval, uep_l = end of the last, length = their
    total, pieces = their count, the UEP's labels from the last interval's end and the LEP's
    (lep_surface, lep_section, lep_wall) from the first one's start; case "2.5D" where
    engaged, "none" elsewhere; cut thickness, area, depth of cut and segments as
    engagement.engage derives them.
    """
    m, p = len(toolpath), settings.phi.size
    n = m * p
    origins = np.asarray(origins, dtype=float).reshape(-1, 3)
    directions = np.asarray(directions, dtype=float).reshape(-1, 3)
    if intervals.n_rows != n or origins.shape[0] != n or directions.shape[0] != n:
        raise ValueError(f"{m} CL points × {p} angles need {n} lines; got {intervals.n_rows} rows of intervals, "
                         f"{origins.shape[0]} origins and {directions.shape[0]} directions")
    if intervals.rows.size and intervals.end.max() > tool.flute_length:
        raise ValueError(f"an interval ends at l = {intervals.end.max():.6g} mm, beyond the flute length "
                         f"{tool.flute_length:g} mm")
    out, _, _ = empty_results(m, p)
    count = intervals.count
    engaged = count > 0
    rows = np.flatnonzero(engaged)
    first = np.searchsorted(intervals.rows, rows, side="left")
    last = np.searchsorted(intervals.rows, rows, side="right") - 1
    flat = {name: values.reshape(-1) for name, values in out.items()}
    flat["lep_l"][rows] = intervals.start[first]
    flat["uep_l"][rows] = intervals.end[last]
    flat["length"][:] = intervals.length
    flat["pieces"][:] = count
    flat["uep_surface"][rows] = intervals.end_surface[last]
    flat["uep_section"][rows] = intervals.end_section[last]
    flat["uep_wall"][rows] = intervals.end_wall[last]
    flat["case"][rows] = CASES.index("2.5D")
    lep = {"lep_surface": np.zeros(n, dtype=np.int8), "lep_section": np.full(n, -1, dtype=np.int32),
           "lep_wall": np.full(n, -1, dtype=np.int32)}
    lep["lep_surface"][rows] = intervals.start_surface[first]
    lep["lep_section"][rows] = intervals.start_section[first]
    lep["lep_wall"][rows] = intervals.start_wall[first]
    lep_xyz = (origins + flat["lep_l"][:, None] * directions).reshape(m, p, 3)
    uep_xyz = (origins + flat["uep_l"][:, None] * directions).reshape(m, p, 3)
    engagement = finished_engagement(settings.phi, settings, out, lep_xyz, uep_xyz, toolpath.inclinations(settings))
    return dataclasses.replace(engagement, **{name: values.reshape(m, p) for name, values in lep.items()})
