"""Real input to modal dialogs for the GUI tests' macros: Python text put into a macro's body after
tests.gui.events.EVENTS (it needs QtCore, QtWidgets and the helpers defined there).

A modal dialog blocks the macro where it opens, so what the user does in it is queued before:
when_shown(find, act) polls for the dialog `find()` returns and then runs act(dialog) on it.
top(kind, name) is the visible top-level widget of that class (and object name); type_into(widget, text)
types `text` key by key; choose_file(path) types `path` into a file dialog and clicks Open; toolbar_button(name) is the ABM toolbar's button of the command `name`.
"""

DIALOGS = '''
def top(kind, name=None):
    for widget in QtWidgets.QApplication.topLevelWidgets():
        if isinstance(widget, kind) and widget.isVisible() and (name is None or widget.objectName() == name):
            return widget
    return None
def when_shown(find, act, tries=400):
    def look(left=tries):
        dialog = find()
        if dialog is not None:
            try:
                act(dialog)
            except Exception:
                import traceback
                verdict.setdefault("dialog_errors", []).append(traceback.format_exc())
        elif left:
            QtCore.QTimer.singleShot(50, lambda: look(left - 1))
    QtCore.QTimer.singleShot(50, look)
def type_into(widget, text):
    widget.setFocus()
    for char in text:
        key(widget, ord(char.upper()) if char.isalnum() else 0, char)
def choose_file(path):
    # a file dialog: the path typed into its file name field (the completion list it opens closed with
    # Escape), then its Open button clicked, again while the dialog stays open (a completion taken instead)
    def act(dialog):
        edit = dialog.findChild(QtWidgets.QLineEdit, "fileNameEdit")
        key(edit, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
        type_into(edit, path)
        def open_it(left=5):
            if not shiboken2.isValid(dialog) or not dialog.isVisible():
                return
            popup = edit.completer().popup() if edit.completer() is not None else None
            if popup is not None and popup.isVisible():
                key(popup, QtCore.Qt.Key_Escape)
            if edit.text() != path and left < 5:
                key(edit, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
                type_into(edit, path)
            box = dialog.findChild(QtWidgets.QDialogButtonBox)
            press(box.button(QtWidgets.QDialogButtonBox.Open) or box.buttons()[0])
            if left:
                QtCore.QTimer.singleShot(300, lambda: open_it(left - 1))
        QtCore.QTimer.singleShot(100, open_it)
    return act
def escape(dialog):
    key(dialog.focusWidget() or dialog, QtCore.Qt.Key_Escape)
def toolbar_button(name):
    toolbar = window.findChild(QtWidgets.QToolBar, "ABM")
    return toolbar.widgetForAction(next(a for a in toolbar.actions() if a.objectName() == name))
'''
