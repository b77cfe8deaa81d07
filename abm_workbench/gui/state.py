"""What the GUI's parts tell each other without importing each other: the engagement to edit or show.

The dock and the task panel listen (:func:`listen`) when they are imported, which the workbench
does on activation (``commands.register``); the view providers and the task panel tell
(:func:`tell`). Events: ``"edit"`` (obj: open the engagement's task panel), ``"show"`` (obj: show
it in the dock), ``"refresh"`` (obj: its results or colours changed), ``"forget"`` (doc: the
document is closing), ``"gone"`` (objects were deleted, or taken back by undo or redo).
"""

_LISTENERS = {"edit": [], "show": [], "refresh": [], "forget": [], "gone": []}


def listen(event, handler):
    """Call handler(*args) on each tell(event, *args); once per handler."""
    handlers = _LISTENERS[event]
    if handler not in handlers:
        handlers.append(handler)


def tell(event, *args):
    """Call the handlers of `event` with `args`; whether any listened."""
    handlers = list(_LISTENERS[event])
    for handler in handlers:
        handler(*args)
    return bool(handlers)
