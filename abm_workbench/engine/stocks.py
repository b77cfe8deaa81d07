"""The engine for either stock model: the paper's staircase (its fast special case) or the general 2.5D terraced stock.

:func:`engage_stock` is ``engagement.engage`` for a :class:`~.model.Staircase` and
``terraced.engage_terraced`` for a :class:`~.terraced_model.TerracedStock`; both give an
:class:`~.engagement.Engagement` of m CL points × p angles (mm, degrees).
"""

from .engagement import engage
from .model import Staircase
from .terraced import engage_terraced
from .terraced_model import TerracedStock


def engage_stock(stock, tool, toolpath, settings, *, progress=None):
    """The Engagement of a pass over `stock`, a Staircase or a TerracedStock; TypeError for anything else."""
    if isinstance(stock, Staircase):
        return engage(stock, tool, toolpath, settings, progress=progress)
    if isinstance(stock, TerracedStock):
        return engage_terraced(stock, tool, toolpath, settings, progress=progress)
    raise TypeError(f"stock must be a Staircase or a TerracedStock, got {type(stock).__name__}")
