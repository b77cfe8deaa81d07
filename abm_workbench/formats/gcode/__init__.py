"""G-code as machines run it (RS-274 as LinuxCNC, FreeCAD's posts and Fanuc-style controls write it),
read into the programs of formats.cl (docs/GCODE.md). Lengths in mm, angles in degrees.

Modules: :mod:`.blocks` (lines into words), :mod:`.codes` (the words and codes known),
:mod:`.interpreter` (the modal state), :mod:`.circles` (G2 / G3), :mod:`.cycles` (hole cycles),
:mod:`.collect` (operations), :mod:`.tool_table` (LinuxCNC tool tables), :mod:`.offsets` (work
offsets), :mod:`.machine` (five-axis kinematics), :mod:`.options` (what reading needs besides the
file), :mod:`.reader` (a file's text into a Program).
"""
