"""``python -m abm_workbench``: the command line (see :mod:`abm_workbench.cli`).

Importing the command line (numpy, the engine) takes a good part of a second; a stop signal
meanwhile (Ctrl-C, SIGTERM, SIGHUP) ends the process at once with the command line's message and
status, before anything was written, instead of a traceback (the package sets this up as runpy
imports it, and again here). cli.main then takes the signals over; once it has returned, they are
ignored.
"""

import signal
import sys

from . import _stopped_early

if __name__ == "__main__":
    for _name in ("SIGINT", "SIGTERM", "SIGHUP"):
        if hasattr(signal, _name):
            signal.signal(getattr(signal, _name), _stopped_early)
    from .cli import main

    status = main()
    for _name in ("SIGINT", "SIGTERM", "SIGHUP"):  # the run is over: a late signal changes nothing
        if hasattr(signal, _name):
            signal.signal(getattr(signal, _name), signal.SIG_IGN)
    sys.exit(status)
