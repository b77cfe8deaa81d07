"""Real input events for the GUI tests' macros: Python text put into a macro's body (it needs
FreeCADGui, QtCore, QtGui, QtWidgets, shiboken2, the main `window` and, for retype, the GUI's
`task_panel` module, defined before it is called).

settle() runs the event loop a few rounds; key(widget, code, text, modifiers) sends a key press
and release; retype(name, text) selects all in the task panel's field `name` (Ctrl+A) and types
`text` key by key (Qt's key codes are ASCII upper case); clear(name) selects all in it and deletes
it (Backspace); press(widget) clicks the middle of a widget (press and release); button(text) is
the visible dialog button of that text, and click(text) presses it and settles.
"""

EVENTS = '''
def settle():
    for _ in range(5):
        FreeCADGui.updateGui()
        QtWidgets.QApplication.processEvents()
def key(widget, code, text="", modifiers=QtCore.Qt.NoModifier):
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtWidgets.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, code, modifiers, text))
def retype(name, text):
    widget = task_panel.shown().field(name)
    widget.setFocus()
    key(widget, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
    for char in text:
        key(task_panel.shown().field(name), ord(char.upper()), char)
    settle()
def clear(name):
    widget = task_panel.shown().field(name)
    widget.setFocus()
    key(widget, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
    key(task_panel.shown().field(name), QtCore.Qt.Key_Backspace)
    settle()
def press(target):
    centre = QtCore.QPointF(target.rect().center())
    for kind in (QtCore.QEvent.MouseButtonPress, QtCore.QEvent.MouseButtonRelease):
        QtWidgets.QApplication.sendEvent(target, QtGui.QMouseEvent(kind, centre, QtCore.Qt.LeftButton,
                                                                  QtCore.Qt.LeftButton, QtCore.Qt.NoModifier))
def button(text):
    boxes = [box for box in window.findChildren(QtWidgets.QDialogButtonBox)
             if shiboken2.isValid(box) and box.isVisible()]
    return {b.text().replace("&", ""): b for box in boxes for b in box.buttons()}.get(text)
def click(text):
    press(button(text))
    settle()
'''
