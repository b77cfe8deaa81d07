"""A stock's own 2.5D direction, found on the solid as it is in the part, and the engine frame turned to it.

A 2.5D stock has horizontal faces and vertical walls along one direction d: every plane's
normal is parallel or square to d, every cylinder's axis and extrusion's direction parallel to
it (trimmed and offset surfaces read as the surface they equal, :func:`.faces.exact_surface`).
That direction belongs to the stock, not to the program: a CL program's frame (NX MSYS, CATIA
CSYS, an indexed table) may be turned against the part while the stock stands upright in it.

:func:`stock_direction` finds d among the z of the operation's frame, the part's z, and every
plane normal, cylinder axis and extrusion direction of the solid: a direction fits when no such
face misses it (parallel, or for a plane square) by more than ``RECOGNITION_TOL`` over the
face's extent. The operation's z is kept when it fits; otherwise the fitting direction nearest
to it; when none fits, the operation's z still, and the recognition refuses the stock in words. Faces of other surfaces (B-spline, Bézier, spheres …) point nowhere
and are left to the recognition, which decides every face exactly in the frame chosen.

:func:`stock_frame` turns the operation's engine frame (R, t), part -> engine, the least (about
the axis square to its z and d) so that its z is d.
"""

import numpy as np

from ..engine.tolerances import RECOGNITION_TOL as TOL
from .faces import exact_surface
from .freecad_env import Part


def face_directions(shape):
    """(normals (a, 3), sizes (a,), axes (b, 3), sizes (b,)): unit normals of the shape's planar faces,
    unit axes of its cylinders and directions of its extrusions, and each face's extent (the diagonal
    of its box, mm). Faces whose surface is refused in words later (:func:`.faces.exact_surface`) give
    none."""
    normals, axes = [], []
    for face in shape.Faces:
        try:
            surface = exact_surface(face)
        except ValueError:
            continue
        if isinstance(surface, Part.Plane):
            normals.append((*surface.Axis, face.BoundBox.DiagonalLength))
        elif isinstance(surface, (Part.Cylinder, Part.SurfaceOfExtrusion)):
            axis = surface.Axis if isinstance(surface, Part.Cylinder) else surface.Direction
            axes.append((*axis, face.BoundBox.DiagonalLength))
    normals, axes = (np.array(rows, dtype=float).reshape(-1, 4) for rows in (normals, axes))
    return (_unit(normals[:, :3]), normals[:, 3], _unit(axes[:, :3]), axes[:, 3])


def _unit(vectors):
    """(n, 3) rows of `vectors` (n, 3) scaled to length 1."""
    return vectors / np.linalg.norm(vectors, axis=1, keepdims=True)


def stock_direction(shape, preferred):
    """(3,) unit 2.5D direction of a solid `shape` in its own coordinates (see the module's docstring),
    on the side of `preferred` ((3,) unit: the z of the operation's frame in the same coordinates),
    which is returned itself when it fits.

    A direction fits when every plane, cylinder and extrusion misses it (sine of the angle off
    parallel, or for a plane off square when that is smaller) by at most TOL over the face's extent:
    then the recognition, which allows TOL over a face's height, takes those faces too.
    """
    preferred = np.asarray(preferred, dtype=float)
    normals, normal_sizes, axes, axis_sizes = face_directions(shape)
    candidates = np.vstack([preferred, [0.0, 0.0, 1.0], normals, axes])
    candidates *= np.where(candidates @ preferred < 0.0, -1.0, 1.0)[:, None]
    cosines = np.abs(candidates @ normals.T)  # (c, a)
    sines = np.sqrt(np.clip(1.0 - np.abs(candidates @ axes.T) ** 2, 0.0, None))  # (c, b)
    drift = np.concatenate([np.minimum(cosines, np.sqrt(np.clip(1.0 - cosines ** 2, 0.0, None))) * normal_sizes,
                            sines * axis_sizes], axis=1)
    fits = (drift <= TOL).all(axis=1)
    if fits[0] or not fits.any():
        return preferred
    nearest = np.flatnonzero(fits)[np.argmax(candidates[fits] @ preferred)]
    return candidates[nearest]


def stock_frame(shape, frame=None):
    """The engine frame (R (3, 3), t (3,) mm), part -> engine, for a solid `shape` in part coordinates:
    `frame` itself (the operation's; None: the part's own) when the stock is 2.5D along its z, else
    `frame` turned the least so that its z is the stock's own direction (:func:`stock_direction`)."""
    rotation, translation = (np.eye(3), np.zeros(3)) if frame is None else frame
    direction = stock_direction(shape, rotation[2])
    if np.array_equal(direction, rotation[2]):
        return frame
    turn = turn_to_z(rotation @ direction)
    return turn @ rotation, turn @ translation


def turn_to_z(w):
    """(3, 3) the least rotation taking the unit vector w (3,), w_z ≥ 0, to +z (about w × z, Rodrigues)."""
    v = np.cross(w, [0.0, 0.0, 1.0])
    k = np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])
    return np.eye(3) + k + k @ k / (1.0 + w[2])
