"""Which CL points validate checks by the boolean: `--check I,J,A-B` and `--check-every N`.

The boolean reference costs a second to minutes per CL point; the engine runs on every CL
point anyway. A selection names CL points (0-based) one by one or as inclusive ranges A-B,
and/or every N-th CL point from 0; the CL points shown in detail (`--cl`) are always checked.
Without either option every CL point is checked.
"""

import re

import numpy as np

from ..errors import ParameterError

#: A CL index as the lists write it: ASCII digits only (int() would also take '1_0' and other scripts' digits).
INDEX = re.compile(r"[0-9]+")


def parse_cl_list(text, m, field):
    """Sorted distinct CL indices (list of int) from 'I,J,A-B' (A-B inclusive, A ≤ B) in a pass of
    m CL points. ParameterError naming `field` when the text is empty, an item is malformed, a
    range runs backwards, or an index is outside 0..m−1."""
    items = [item.strip() for item in str(text).split(",")]
    if not any(items):
        raise ParameterError(field, "is empty: give CL indices such as 0,27,80-100")
    indices = set()
    for position, item in enumerate(items, start=1):
        first, dash, last = (part.strip() for part in item.partition("-"))
        try:
            if not (INDEX.fullmatch(first) and (INDEX.fullmatch(last) or not dash)):
                raise ValueError(item)
            low = int(first)
            high = int(last) if dash else low
        except ValueError:
            raise ParameterError(field, f"item {position} {item!r} is not a CL index or a range A-B "
                                        f"(such as 0,27,80-100)") from None
        if high < low:
            raise ParameterError(field, f"item {position} {item!r} runs backwards (write {high}-{low})")
        for index in (low, high):
            if not 0 <= index < m:
                raise ParameterError(field, f"item {position}: CL point {index} is not in the pass (0..{m - 1})")
        indices.update(range(low, high + 1))
    return sorted(indices)


def checked_cls(check, every, shown, m):
    """The CL points (sorted list of int) the boolean checks in a pass of m CL points, or None for all.

    check: 'I,J,A-B' text or None; every: N (every N-th CL point from 0) or None; shown: CL indices
    shown in detail (always checked) or None. None when neither check nor every is given.
    ParameterError naming "check" or "check_every" for a bad value."""
    if check is None and every is None:
        return None
    chosen = set(shown or ())
    if check is not None:
        chosen.update(parse_cl_list(check, m, "check"))
    if every is not None:
        if isinstance(every, bool) or int(every) != every or every < 1:
            raise ParameterError("check_every", f"must be a positive whole number of CL points, got {every!r}")
        chosen.update(range(0, m, int(every)))
    return [int(cl) for cl in np.sort(list(chosen))]
