"""The kinds of the engine entry functions' arguments, checked before any is read.

The entry functions (engage, flute_engagement, engage_stock, engage_terraced, zmap_engage, and
forces.pass_forces and parallel.engage_parallel outside the engine) read their arguments attribute by
attribute: a str for the Tool would end in an AttributeError far from the cause. Apart from model so
that model and terraced_model need not import each other.
"""

from .model import CutSettings, Staircase, Tool, Toolpath
from .terraced_model import TerracedStock


class WrongArgument(TypeError):
    """An argument of an engine function that is not of its kind (a str for the Tool, ...)."""


#: The kinds of each checked argument, by its name.
KINDS = {"stock": (Staircase, TerracedStock), "tool": (Tool,), "toolpath": (Toolpath,), "settings": (CutSettings,)}


def check_arguments(**arguments):
    """WrongArgument (a TypeError) naming the first argument that is not of its kind, by its name: stock
    (Staircase or TerracedStock), tool (Tool), toolpath (Toolpath), settings (CutSettings); other names
    are not checked."""
    for name, value in arguments.items():
        kind = KINDS.get(name)
        if kind is not None and not isinstance(value, kind):
            expected = " or ".join(k.__name__ for k in kind)
            raise WrongArgument(f"{name} must be a {expected}, got {type(value).__name__}")
