"""Work offsets G54–G59.3: where each work coordinate system's zero lies, as a table gives it.

A program's X Y Z (and A B C) plus the offset of the coordinate system in force are positions in
the table's frame, which is then the part frame. Without a table every offset is zero and the
part frame is the program's own. Two files are read (angles in degrees):

- a LinuxCNC parameter file (``linuxcnc.var``): lines ``number value``; parameters 5221–5226 are
  G54's X Y Z A B C, and each next system's are 20 further on (5241 G55, …, 5381 G59.3); lengths
  in the machine's units, as LinuxCNC keeps them (mm unless said);
- a JSON object ``{"G54": [x, y, z], "G55": [x, y, z, a, b, c], …}``, lengths in mm.
"""

import os

import numpy as np

from ...errors import InputError
from .. import MAX_MAGNITUDE, json_number, load_json_object, read_text
from ..cl.lexer import split_lines

#: The work coordinate systems, in the order of LinuxCNC's P numbers (G10 L2 P1 is G54).
SYSTEMS = ("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3")
#: LinuxCNC's parameter number of G54's X offset; each system's are 20 further on.
_FIRST_PARAMETER, _PARAMETER_STEP = 5221, 20


def zero_offsets():
    """{system: (6,) zeros} for every system of SYSTEMS."""
    return {system: np.zeros(6) for system in SYSTEMS}


def load_offsets(path, scale=1.0):
    """({system: (6,) x, y, z mm, a, b, c degrees}, in_machine_units) of the offsets file at `path` (module
    docstring): a parameter file's lengths times `scale` (the machine's unit in mm: 1 or 25.4), and
    in_machine_units True for it (False for JSON, in mm); systems it does not give are zero. InputError
    naming the file and the line or key."""
    name = os.fspath(path)
    text = read_text(name)
    if text.lstrip().startswith("{"):
        return _json_offsets(name), False
    table = zero_offsets()
    for number, raw in enumerate(split_lines(text), start=1):
        fields = raw.split()
        if not fields:
            continue
        try:
            parameter, value = int(fields[0]), float(fields[1])
        except (ValueError, IndexError):
            raise InputError(f"{name}:{number}: expected 'parameter value' (LinuxCNC parameter file), got "
                             f"{raw.strip()!r}") from None
        if not abs(value) <= MAX_MAGNITUDE:
            raise InputError(f"{name}:{number}: {fields[1]}: not a number of at most {MAX_MAGNITUDE:g} in magnitude")
        system, axis = divmod(parameter - _FIRST_PARAMETER, _PARAMETER_STEP)
        if 0 <= system < len(SYSTEMS) and axis < 6:
            table[SYSTEMS[system]][axis] = value * (scale if axis < 3 else 1.0)
    return table, True


def _json_offsets(name):
    """The offsets of a JSON offsets file."""
    data = load_json_object(name)
    table = zero_offsets()
    for key, value in data.items():
        if key not in table:
            raise InputError(f"{name}: {key!r} is not a work coordinate system ({', '.join(SYSTEMS)})")
        if not isinstance(value, list) or len(value) not in (3, 6):
            raise InputError(f"{name}: {key}: must be [x, y, z] or [x, y, z, a, b, c] (mm, degrees)")
        table[key][:len(value)] = [json_number(item, f"{name}: {key}[{index}]") for index, item in enumerate(value)]
    return table
