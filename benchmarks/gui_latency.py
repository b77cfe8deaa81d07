"""Edit latency in the real FreeCAD GUI (under Xvfb): model test 1, a value typed into the task panel
then OK, until the recompute is done and the 3D view drawn again; the same with forces on; the
dock's CL point moved by one (a key press on its slider) until the 3D view shows the new
highlight, and until the dock's plots are drawn too.

Then the GUI's longest stall (the longest gap between two ticks of a 10 ms timer of the GUI thread)
while long work runs: a recompute with forces (measured before the in-process stock exists: a
recompute of the engagement recomputes that too), a validation of two CL points (and, apart, the
seconds of its half on the GUI thread, ``validate.prepare``), and the in-process stock at a CL
point ("Show in-process stock": its OpenCASCADE booleans in a worker process);
and how soon Cancel answers: a validation of every CL point cancelled after 1.5 s by a click on its
progress dialog's Cancel, the seconds from the click until the dialog is gone and the GUI thread
ticks again, and until the command has returned; the same for the in-process stock moved to the next
CL point (its progress dialog ``ABM_Engine``), which must then stay at its CL point.

    /usr/bin/python3 benchmarks/gui_latency.py [--root CHECKOUT ...] [--repeat N]

Each --root is a checkout of the workbench (default: this one); give the old one too (e.g.
``--root /work/main --root .``) to print before and after from one run, and their ratios. Times
are medians of N edits (default 3), in seconds; the machine's load average is printed with them.
"""

import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
#: Seconds one GUI run may take.
TIMEOUT = 900

MACRO = r'''
import json, os, sys, time, traceback
sys.path.insert(0, {root!r})
from PySide2 import QtCore, QtGui, QtWidgets

def run():
    out = {{}}
    try:
        import FreeCAD, FreeCADGui
        import numpy as np
        FreeCADGui.getMainWindow().showMaximized()
        FreeCADGui.activateWorkbench("ABMWorkbench")
        from abm_workbench.gui import commands, dock, task_panel
        app = QtWidgets.QApplication.instance()
        window = FreeCADGui.getMainWindow()

        def settle():
            for _ in range(3):
                FreeCADGui.updateGui()
                app.processEvents()

        def drawn():
            # the 3D view painted now, synchronously, and the GL pipeline finished
            view = FreeCADGui.ActiveDocument.ActiveView
            settle()
            view.graphicsView().viewport().repaint()
            app.processEvents()

        def key(widget, code, text="", modifiers=QtCore.Qt.NoModifier):
            for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
                app.sendEvent(widget, QtGui.QKeyEvent(kind, code, modifiers, text))

        def ok_button():
            boxes = [b for b in window.findChildren(QtWidgets.QDialogButtonBox) if b.isVisible()]
            return [b for box in boxes for b in box.buttons() if b.text().replace("&", "") == "OK"][0]

        def click(button):
            centre = QtCore.QPointF(button.rect().center())
            for kind in (QtCore.QEvent.MouseButtonPress, QtCore.QEvent.MouseButtonRelease):
                app.sendEvent(button, QtGui.QMouseEvent(kind, centre, QtCore.Qt.LeftButton, QtCore.Qt.LeftButton,
                                                        QtCore.Qt.NoModifier))

        def edited(engagement, name, text):
            # task panel opened, `text` typed into field `name`, then OK clicked: seconds until recomputed and drawn
            FreeCADGui.ActiveDocument.setEdit(engagement, 0)
            settle()
            panel = task_panel.shown()
            field = panel.field(name)
            field.setFocus()
            key(field, QtCore.Qt.Key_A, "", QtCore.Qt.ControlModifier)
            for char in text:
                key(field, ord(char.upper()), char)
            settle()
            button = ok_button()
            started = time.perf_counter()
            click(button)
            waited = 0
            while engagement.Proxy.result(engagement) is None or task_panel.shown() is not None:
                settle()
                waited += 1
                if waited > 10000:
                    raise RuntimeError("the edit did not finish")
            drawn()
            return time.perf_counter() - started

        started = time.perf_counter()
        _, _, engagement = commands.OpenModelTest().run()
        drawn()
        out["open"] = time.perf_counter() - started
        out["state"] = engagement.State
        values = ("9", "11", "8", "12", "7", "13", "6")
        out["edit"] = [edited(engagement, "Inclination", v) for v in values[:{repeat}]]
        engagement.Forces = True
        engagement.touch()
        engagement.Document.recompute()
        settle()
        out["forces"] = [edited(engagement, "Inclination", v) for v in values[:{repeat}]]
        out["forces_on"] = bool(engagement.PeakForce > 0)
        shown = dock.find()
        slider = shown.slider
        slider.setFocus()
        highlighted, plotted = [], []
        view = FreeCADGui.ActiveDocument.ActiveView
        for step in range(2 * {repeat}):
            started = time.perf_counter()
            key(slider, QtCore.Qt.Key_Right if step % 2 == 0 else QtCore.Qt.Key_Left)
            view.graphicsView().viewport().repaint()  # the highlight drawn, before any queued event
            highlighted.append(time.perf_counter() - started)
            settle()
            shown.canvas.repaint()
            drawn()
            plotted.append(time.perf_counter() - started)
        out["slider"], out["plots"] = highlighted, plotted

        # ---- stalls of the GUI thread during long work, and Cancel --------------------------------
        ticks = []
        heart = QtCore.QTimer()
        heart.timeout.connect(lambda: ticks.append(time.perf_counter()))
        heart.start(10)

        def stall(action):
            # the longest gap (s) between two ticks while action() runs, and its seconds
            settle()
            del ticks[:]
            started = time.perf_counter()
            action()
            ended = time.perf_counter()
            settle()
            inside = [started] + [t for t in ticks if started <= t <= ended] + [ended]
            return max(b - a for a, b in zip(inside, inside[1:])), ended - started

        from abm_workbench.gui import inprocess_view, validate
        doc = engagement.Document
        # the forces' recompute first: once the in-process stock exists, a recompute of the engagement
        # recomputes it too (its booleans, on the GUI thread), which is not what this figure is about
        # a new inclination: a touch alone finds the results kept for these inputs and computes nothing
        out["forces_stall"] = stall(lambda: (setattr(engagement, "Inclination", 14.5), doc.recompute()))
        engagement.Forces = False
        doc.recompute()
        settle()
        cl = int(shown.spin.value())
        report = os.path.join(os.path.dirname({out!r}), "report")
        started = time.perf_counter()
        validate.prepare(engagement, [cl, cl + 1], report + "_prepared")  # its GUI-thread half alone
        out["validation_prepare"] = time.perf_counter() - started
        out["validation"] = stall(lambda: commands.ValidateEngagement().execute(engagement, f"{{cl}},{{cl + 1}}",
                                                                                report, False))
        out["inprocess"] = stall(lambda: inprocess_view.show_at(engagement, cl))
        out["inprocess_compute"] = inprocess_view.stock_of(engagement).ComputeTime
        def cancel_soon(name, clicked):
            dialog = window.findChild(QtWidgets.QProgressDialog, name)
            if dialog is None or not dialog.isVisible():
                QtCore.QTimer.singleShot(50, lambda: cancel_soon(name, clicked))
                return
            def gone():
                if dialog.isVisible():
                    QtCore.QTimer.singleShot(5, gone)
                else:
                    clicked["gone"] = time.perf_counter()
            button = dialog.findChild(QtWidgets.QPushButton)
            clicked["at"] = time.perf_counter()
            click(button)
            QtCore.QTimer.singleShot(0, gone)

        clicked = {{}}
        QtCore.QTimer.singleShot(1500, lambda: cancel_soon("ABM_Progress", clicked))
        started = time.perf_counter()
        commands.ValidateEngagement().execute(engagement, "all", report + "_cancelled", False)
        returned = time.perf_counter()
        out["cancel"] = [clicked.get("gone", returned) - clicked["at"], returned - clicked["at"],
                         os.path.exists(report + "_cancelled")]
        clicked = {{}}
        QtCore.QTimer.singleShot(1500, lambda: cancel_soon("ABM_Engine", clicked))
        del ticks[:]
        started = time.perf_counter()
        inprocess_view.show_at(engagement, cl + 1)
        returned = time.perf_counter()
        inside = [started] + [t for t in ticks if started <= t <= returned] + [returned]
        kept = inprocess_view.stock_of(engagement)
        out["inprocess_cancel"] = [clicked.get("gone", returned) - clicked["at"], returned - clicked["at"],
                                   kept.CLPoint == cl and kept.State == ["Up-to-date"],
                                   max(b - a for a, b in zip(inside, inside[1:]))]
        heart.stop()
        out["ok"] = True
    except Exception:
        out["error"] = traceback.format_exc()
    finally:
        with open({out!r}, "w") as handle:
            json.dump(out, handle)
        os._exit(0)

QtCore.QTimer.singleShot(1500, run)
'''


def measure(root, repeat):
    """The figures of one GUI run on the checkout `root` (dict of lists of seconds)."""
    with tempfile.TemporaryDirectory(prefix="abm-latency-") as folder:
        out, macro = os.path.join(folder, "out.json"), os.path.join(folder, "macro.py")
        with open(macro, "w") as handle:
            handle.write(MACRO.format(root=os.path.abspath(root), out=out, repeat=repeat))
        mods = os.path.join(folder, "home", ".local", "share", "FreeCAD", "Mod")
        os.makedirs(mods)
        os.symlink(os.path.abspath(root), os.path.join(mods, "ABM"))
        env = dict(os.environ, HOME=os.path.join(folder, "home"), QTWEBENGINE_DISABLE_SANDBOX="1")
        process = subprocess.Popen(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", "freecad", macro], env=env,
                                   cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                   start_new_session=True)
        try:
            process.wait(timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            sys.exit(f"{root}: the GUI did not finish in {TIMEOUT} s")
        with open(out) as handle:
            figures = json.load(handle)
    if not figures.get("ok"):
        sys.exit(f"{root}: {figures.get('error')}")
    return figures


def median(values):
    ordered = sorted(values)
    return ordered[len(ordered) // 2]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", action="append", help="a checkout of the workbench (repeatable)")
    parser.add_argument("--repeat", type=int, default=3, help="edits and slider moves measured (median)")
    args = parser.parse_args(argv)
    roots = args.root or [HERE]
    rows, stalls = [], {}
    for root in roots:
        figures = measure(root, args.repeat)
        stalls[root] = figures
        rows.append((root, figures["open"], median(figures["edit"]), median(figures["forces"]),
                     median(figures["slider"]) * 1000.0, median(figures.get("plots", figures["slider"])) * 1000.0))
    print(f"load average: {' '.join(f'{value:.2f}' for value in os.getloadavg())}")
    print("| checkout | open model test 1 (s) | edit → OK → drawn (s) | with forces (s) | slider: highlight drawn (ms) "
          "| slider: plots drawn too (ms) |")
    print("|---|---|---|---|---|---|")
    for root, *values in rows:
        print(f"| {root} | " + " | ".join(f"{value:.3g}" for value in values) + " |")
    print()
    print("| checkout | longest GUI stall: in-process stock (s) | validation of 2 CL points (s) | forces recompute (s) "
          "| Cancel: dialog gone (s) | Cancel: command returned (s) | in-process Cancel: dialog gone, returned (s) |")
    print("|---|---|---|---|---|---|---|")
    for root in roots:
        figures = stalls[root]
        (a, a_s), (b, b_s), (c, c_s) = figures["inprocess"], figures["validation"], figures["forces_stall"]
        gone, returned, written = figures["cancel"]
        in_gone, in_returned, in_kept, in_stall = figures.get("inprocess_cancel", (float("nan"),) * 2 + (True, 0.0))
        print(f"| {root} | {a:.3f} (of {a_s:.1f} s) | {b:.3f} (of {b_s:.1f} s) | {c:.3f} (of {c_s:.1f} s) | "
              f"{gone:.3f} | {returned:.3f}{' (a report written!)' if written else ''} | "
              f"{in_gone:.3f}, {in_returned:.3f}{'' if in_kept else ' (the stock not kept!)'} "
              f"(stall {in_stall:.3f}) |")
        print(f"  {root}: validation's GUI-thread half (prepare) {figures['validation_prepare']:.3f} s; "
              f"the in-process stock's own ComputeTime {figures['inprocess_compute']:.1f} s")
    if len(rows) > 1:
        first = rows[0]
        for row in rows[1:]:
            ratios = " | ".join(f"{old / new:.3g}×" for old, new in zip(first[1:], row[1:]))
            print(f"| {first[0]} ÷ {row[0]} | {ratios} |")


if __name__ == "__main__":
    main()
