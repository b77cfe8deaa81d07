"""Outputs that appear whole or not at all: written under a hidden temporary name, moved at the end."""

import contextlib
import os
import secrets
import shutil

from ..formats import before_moves


@contextlib.contextmanager
def staged(path, *, folder=False):
    """Yield where to write `path`; move it into place when the block finishes without error.

    A file: yields ``<hidden folder beside path>/<name of path>`` (writers that insist on a
    suffix, such as FreeCAD's saveAs, keep it), moved onto `path` with os.replace. A folder
    (folder=True): yields a new empty hidden folder beside `path`, renamed to `path` at the
    end; a folder already at `path` is moved aside first and then removed. If the block
    raises anything (KeyboardInterrupt too), the temporary folder is removed and `path` is
    left as it was. formats.BEFORE_MOVES run before the final move.
    """
    path = os.path.abspath(os.fspath(path))
    parent, name = os.path.split(path)
    made = []
    try:
        temporary = _new_folder(parent, f".{name}.", ".tmp", made)
        if folder:  # made private (0700); a report folder gets the usual permissions
            os.chmod(temporary, 0o777 & ~_umask())
        yield temporary if folder else os.path.join(temporary, name)
        before_moves()
        if folder:
            _swap_in(temporary, path, made)
        else:
            os.replace(os.path.join(temporary, name), path)
    finally:
        for each in made:
            shutil.rmtree(each, ignore_errors=True)


def _new_folder(parent, prefix, suffix, made):
    """Make a new private folder prefix + 12 hex digits + suffix in `parent`, appended to the list `made`
    before it is made (a stop signal can raise between any two steps: one right after os.mkdir returned
    must find it listed, to be removed)."""
    while True:
        made.append(os.path.join(parent, f"{prefix}{secrets.token_hex(6)}{suffix}"))
        try:
            os.mkdir(made[-1], 0o700)
            return made[-1]
        except FileExistsError:
            made.pop()


def _umask():
    """The process's umask (read by setting it and setting it back)."""
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _swap_in(new, path, made):
    """Rename folder `new` to `path`, removing what was at `path` once the new one is in place; the old one
    waits in a folder listed in `made` meanwhile, and is moved back if anything (a stop signal) interrupts."""
    if not os.path.exists(path):
        os.replace(new, path)
        return
    parent, name = os.path.split(path)
    old = os.path.join(_new_folder(parent, f".{name}.", ".old", made), name)
    try:
        os.replace(path, old)
        os.replace(new, path)
    except BaseException:
        if os.path.exists(old) and not os.path.exists(path):
            os.replace(old, path)
        raise
