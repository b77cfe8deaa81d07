"""Import FreeCAD and Part, finding the Debian build if it is not on sys.path yet.

Debian's ``freecad-python3`` installs FreeCAD's Python modules in
``/usr/lib/freecad-python3/lib``, which the system interpreter (``/usr/bin/python3``)
does not search by default. Import this module instead of FreeCAD itself::

    from .freecad_env import FreeCAD, Part
"""

import sys

#: Where Debian's freecad-python3 package puts FreeCAD.so and Part.so.
DEBIAN_LIB = "/usr/lib/freecad-python3/lib"


def _import():
    """(FreeCAD, Part), adding DEBIAN_LIB to sys.path if needed; ImportError saying what to install."""
    try:
        import FreeCAD  # noqa: F401 (FreeCAD must be imported before Part)
    except ImportError:
        if DEBIAN_LIB not in sys.path:
            sys.path.append(DEBIAN_LIB)
        try:
            import FreeCAD  # noqa: F811
        except ImportError as error:
            raise ImportError(
                f"FreeCAD is not importable from {sys.executable} ({error}). Install the Debian "
                "package freecad-python3 (apt-get install freecad-python3) and run the system "
                "interpreter /usr/bin/python3."
            ) from error
    import Part

    return FreeCAD, Part


FreeCAD, Part = _import()
