"""``python -m abm_workbench``: the command line (see :mod:`abm_workbench.cli`)."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
