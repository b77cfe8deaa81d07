"""Outputs that appear whole or not at all: written under a hidden temporary name, moved at the end."""

import contextlib
import os
import shutil
import tempfile


@contextlib.contextmanager
def staged(path, *, folder=False):
    """Yield where to write `path`; move it into place when the block finishes without error.

    A file: yields ``<hidden folder beside path>/<name of path>`` (writers that insist on a
    suffix, such as FreeCAD's saveAs, keep it), moved onto `path` with os.replace. A folder
    (folder=True): yields a new empty hidden folder beside `path`, renamed to `path` at the
    end; a folder already at `path` is moved aside first and then removed. If the block
    raises anything (KeyboardInterrupt too), the temporary folder is removed and `path` is
    left as it was.
    """
    path = os.path.abspath(os.fspath(path))
    parent, name = os.path.split(path)
    temporary = tempfile.mkdtemp(prefix=f".{name}.", suffix=".tmp", dir=parent)
    try:
        if folder:  # mkdtemp makes it private (0700); a report folder gets the usual permissions
            os.chmod(temporary, 0o777 & ~_umask())
        yield temporary if folder else os.path.join(temporary, name)
        if folder:
            _swap_in(temporary, path)
        else:
            os.replace(os.path.join(temporary, name), path)
    finally:
        shutil.rmtree(temporary, ignore_errors=True)


def _umask():
    """The process's umask (read by setting it and setting it back)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _swap_in(new, path):
    """Rename folder `new` to `path`, removing what was at `path` once the new one is in place."""
    if not os.path.exists(path):
        os.replace(new, path)
        return
    parent, name = os.path.split(path)
    aside = tempfile.mkdtemp(prefix=f".{name}.", suffix=".old", dir=parent)
    os.replace(path, os.path.join(aside, name))
    os.replace(new, path)
    shutil.rmtree(aside, ignore_errors=True)
