"""ABM workbench: analytical cut geometry of flat-end five-axis milling on staircase stock.

The engine (:mod:`abm_workbench.engine`) is pure numpy and never imports FreeCAD; file
formats, the command line and reports sit beside it, the FreeCAD layers on top.
Lengths are in millimetres; angles are in degrees at every interface.
"""

__version__ = "0.1.0"


def _stopped_early(number, frame):
    """A stop signal while ``python -m abm_workbench`` is still importing: nothing to clean up yet; say
    so and end with the command line's status (128 + the signal), without a traceback."""
    import os
    import signal

    words = "interrupted" if number == signal.SIGINT else f"stopped by {signal.Signals(number).name}"
    os.write(2, f"abm: {words}\n".encode())
    os._exit(128 + number)


def _early_signals():
    """Under ``python -m abm_workbench`` only (runpy imports this package first, with sys.argv[0] '-m'):
    stop signals end the process at once until the command line takes them over (__main__, cli.main)."""
    import sys

    argv = getattr(sys, "orig_argv", [])
    if sys.argv[:1] == ["-m"] and any(a == "-m" and b == __name__ for a, b in zip(argv, argv[1:])):
        import signal

        for name in ("SIGINT", "SIGTERM", "SIGHUP"):
            if hasattr(signal, name):
                signal.signal(getattr(signal, name), _stopped_early)


_early_signals()
