"""Frames of CL data: where the file's coordinates sit in the part, and each operation's own frame.

Every frame is (R (3, 3), t (3,)) with ``part = R @ file + t`` (mm).

- NX ``MSYS/x0,y0,z0,xi,xj,xk,yi,yj,yk``: the origin and the X and Y axes of the machine
  coordinate system in the part; Z = X × Y. R's columns are X, Y, Z.
- ``CSYS/r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz`` (CATIA, one per setup): the 3 × 4
  matrix [R | t], row by row, taking setup coordinates to part coordinates.
- ``ROTABL/a,AAXIS|BAXIS|CAXIS[,CLW|CCLW][,INCR|ATANGL]``: the indexed table has turned the part
  by a degrees about the machine's X, Y or Z axis (counter-clockwise, i.e. right-handed,
  unless CLW; INCR adds to the angle before). The CL points that follow are machine
  coordinates of the turned part: part = Rᵀ·file with R the table's rotation.

The engine frame of an operation (:func:`engine_frame`) is the frame its tool axes point up
in on the whole: the file frame (the MCS or setup frame the operation was written in) when every
cutting axis has k > 0 there; otherwise a frame whose Z is the normalised mean of the cutting axes
(X the file's X made square to it, or the file's Y when X is too close to Z), origin that of the
file frame; the file frame when the axes cancel out. Single axes may point sideways or down in it:
the engine takes every direction. A solid stock then turns it to its own 2.5D direction
(``cad.stock_frame``).
"""

import math

import numpy as np

from ...errors import note

#: Direction cosines must be unit and square to within this.
FRAME_TOLERANCE = 1e-3
IDENTITY = (np.eye(3), np.zeros(3))
_ROTARY_AXES = {"AAXIS": 0, "BAXIS": 1, "CAXIS": 2}


def _orthonormal(rotation):
    """The nearest rotation to `rotation` (3, 3), or a reason (str) it is not one."""
    rotation = np.asarray(rotation, dtype=float)
    error = np.abs(rotation.T @ rotation - np.eye(3)).max()
    if error > FRAME_TOLERANCE:
        return note("its axes are not unit vectors square to each other")
    u, _, vt = np.linalg.svd(rotation)
    nearest = u @ vt
    if np.linalg.det(nearest) < 0.0:
        return note("it is a reflection, not a rotation")
    return nearest


def msys_frame(values):
    """(R, t) of the 9 MSYS numbers (origin in mm); a str reason when the axes are not a frame."""
    x_axis, y_axis = np.array(values[3:6]), np.array(values[6:9])
    rotation = _orthonormal(np.column_stack([x_axis, y_axis, np.cross(x_axis, y_axis)]))
    if isinstance(rotation, str):
        return rotation
    return rotation, np.array(values[:3], dtype=float)


def csys_frame(values):
    """(R, t) of the 12 CSYS numbers (translation in mm); a str reason when R is not a rotation."""
    matrix = np.array(values, dtype=float).reshape(3, 4)
    rotation = _orthonormal(matrix[:, :3])
    if isinstance(rotation, str):
        return rotation
    return rotation, matrix[:, 3].copy()


def table_frame(angle, axis_word):
    """(R, t) of a table turned by `angle` degrees (right-handed) about machine axis `axis_word`."""
    index = _ROTARY_AXES[axis_word]
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    j, k = (index + 1) % 3, (index + 2) % 3
    turn = np.eye(3)
    turn[j, j], turn[j, k], turn[k, j], turn[k, k] = c, -s, s, c
    return turn.T, np.zeros(3)


def compose(outer, inner):
    """(R, t) of applying `inner` then `outer`."""
    return outer[0] @ inner[0], outer[0] @ inner[1] + outer[1]


def engine_frame(to_part, axes_file):
    """(R, t) from part coordinates to the operation's engine frame (see the module docstring).

    to_part: the operation's (R, t) file -> part. axes_file: (n, 3) unit cutting axes in the
    file frame. Returns the (R, t) part -> engine. Axes may point anywhere in it (the engine takes
    every direction); the frame only chooses which way the stock's 2.5D direction is read up.
    """
    rotation, translation = to_part
    inverse = (rotation.T, -rotation.T @ translation)
    axes_file = np.asarray(axes_file, dtype=float).reshape(-1, 3)
    if len(axes_file) == 0 or (axes_file[:, 2] > 0.0).all():
        return inverse
    mean = axes_file.mean(axis=0)
    size = np.linalg.norm(mean)
    if size < 1e-9:  # the axes cancel out: the file's own frame
        return inverse
    z = mean / size
    x = np.array([1.0, 0.0, 0.0]) if abs(z[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = x - (x @ z) * z
    x /= np.linalg.norm(x)
    local = np.array([x, np.cross(z, x), z])  # rows: the new axes in file coordinates
    return compose((local, np.zeros(3)), inverse)
