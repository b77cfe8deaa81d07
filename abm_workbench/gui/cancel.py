"""The exception of work stopped by Cancel, apart from :mod:`.worker` (which needs Qt): :mod:`.validate`
raises it and is used without a GUI (FreeCAD headless, the GUI helpers' tests)."""

from ..errors import InputError


class Cancelled(InputError):
    """The work was stopped by Cancel: nothing was made."""
