"""Python wrappers of Qt objects that outlive their object: found and let go before a lookup trusts them.

PySide keeps one Python wrapper per C++ address and hands it back on every lookup (``findChild``,
``children``, ``button``). A wrapper FreeCAD makes for a widget of its own (the task dialog's
button box, given to ``modifyStandardButtons``) stays registered at that address after FreeCAD
deletes the widget, as long as anything holds it; and ``findChild`` / ``findChildren`` on the
main window, as any macro or workbench may call, keep what they find for as long as the main
window lives. A new widget that the allocator puts at the same address is then handed the old
wrapper: of another class (``findChild(QLineEdit)`` passes over it and finds nothing) or of a
deleted object ("Internal C++ object (QDialogButtonBox) already deleted"). Which address comes
back is chance, so a panel built right after another closed failed now and then.

:func:`let_go_stale` walks a widget's children and unregisters every wrapper that is not of a
live object of its own class (``shiboken2.invalidate``: the C++ object is left alone); the next
lookup makes a right one.
"""

import shiboken2


def stale(wrapper):
    """True when `wrapper` is not a wrapper of a live object of its class: its object deleted, or its
    address now holding an object of another class."""
    if not shiboken2.isValid(wrapper):
        return True
    name = next(cls.__name__ for cls in type(wrapper).__mro__ if cls.__module__.startswith("PySide2."))
    return not wrapper.inherits(name)  # asks the object that lives at the address now


def let_go_stale(root):
    """Unregister the stale wrappers (:func:`stale`) of the descendants of the live QObject `root`;
    how many were let go."""
    count = 0
    children = root.children()
    for child in children:
        if stale(child):
            shiboken2.invalidate(child)
            count += 1
    if count:
        children = root.children()  # the wrappers made again, of the objects that live there
    for child in children:
        if not stale(child):
            count += let_go_stale(child)
    return count
