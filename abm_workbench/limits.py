"""What the machine can do, and the size of a run that must be confirmed before it starts.

Every run estimates its work and memory from its inputs before it computes anything (the CL
points and angles it will solve, the pieces the in-process stock sweeps, the bytes it will
write) and compares them with

- what this process may use: :func:`available_memory` (the system's available memory, the
  process's address-space and data limits, its cgroup's memory limit), the free space of the
  output's file system, :func:`usable_cores`;
- and, for the work, :data:`LARGE_INSTANTS` and the other "large" limits below: a run above
  one is still possible, but long, so it is refused unless the user confirms it
  (``--allow-large`` on the command line; :func:`allowing_large` in Python).

A refusal is a :class:`TooLarge` (an InputError) naming the option or file that makes the run
large and what it would take, before any output file or folder exists. ``--allow-large`` lets
the work limits and the disk estimate through, never the memory estimate: a process that
allocates more than the machine has is killed (or takes other processes with it). A run that
runs out of memory all the same ends with one error line, as every failure does.

Only the standard library is imported here: the readers, the job runs and the command line use it.
"""

import contextlib
import contextvars
import os
import resource

from .errors import InputError

#: Instants (CL points × angles) of one run above which it must be confirmed: about 10 minutes and
#: 15 GB of results CSV at the command line's 2·10⁵ instants/s.
LARGE_INSTANTS = 10 ** 8
#: CL points a program's arcs and curves may be interpolated into (all of them together) before
#: it must be confirmed: about 1 GB of memory and 12 s to read.
LARGE_INTERPOLATION = 2 * 10 ** 6
#: Constant-axis pieces the in-process stock may sweep a program into before it must be confirmed.
LARGE_PIECES = 2 * 10 ** 7
#: Instants the boolean reference of validate may check before it must be confirmed (each takes
#: milliseconds: 10⁵ are minutes to hours).
LARGE_BOOLEAN_INSTANTS = 10 ** 5
#: Points the Z-map baseline may sample along the edges of a run before it must be confirmed.
LARGE_ZMAP_SAMPLES = 10 ** 9
#: Bytes of memory a process needs besides its arrays (interpreter, numpy, scipy, the readers).
BASE_MEMORY = 200 << 20

_ALLOWED = contextvars.ContextVar("abm_allow_large", default=False)


class TooLarge(InputError):
    """A run whose estimated work, memory or output is above what may be done without confirmation."""


@contextlib.contextmanager
def allowing_large(allowed=True):
    """Within the block, runs above the "large" limits and the memory and disk estimates go ahead."""
    token = _ALLOWED.set(bool(allowed))
    try:
        yield
    finally:
        _ALLOWED.reset(token)


def large_allowed():
    """Whether the current block lets large runs through (:func:`allowing_large`)."""
    return _ALLOWED.get()


def size_text(count):
    """A byte count in words: '512 B', '3.2 MiB', '487 GiB', '45 TiB'."""
    value = float(count)
    if not value < 1e300:
        return "more than 1e+300 B"
    for unit in ("B", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if abs(value) < 1024.0 or unit == "PiB":
            return f"{value:.0f} {unit}" if unit == "B" else f"{value:.3g} {unit}"
        value /= 1024.0


def count_text(count):
    """A count in words: 1,234, 3.1e+12, or 'more than 1e+308' for an infinite one."""
    if count != count or count == float("inf"):
        return "more than 1e+308"
    return f"{int(count):,}" if count < 1e15 else f"{count:.3g}"


def check_large(why, what, count, limit, remedy=""):
    """TooLarge unless `count` ≤ `limit` or large runs are allowed (:func:`allowing_large`):
    '<why>: <what> (more than the <limit> a run takes without confirmation): <remedy>, or give
    --allow-large ...', `what` with '{}' where the count goes, or the count already in its words (a
    message of its own, errors.note). why: the file or option that makes the run large, e.g. 'toolpath.csv'."""
    if count <= limit or large_allowed():
        return
    shown, most = what.format(count_text(count)) if "{}" in what else what, count_text(limit)
    raise TooLarge(f"{why}: {shown} (more than the {most} a run takes without confirmation): {remedy}, or give "
                   f"--allow-large to run it anyway" if remedy else
                   f"{why}: {shown} (more than the {most} a run takes without confirmation): give --allow-large to "
                   f"run it anyway")


def check_memory(needed, why, what="the run", remedy=""):
    """TooLarge unless `needed` bytes fit in :func:`available_memory`; --allow-large does not lift this
    (a process that allocates more than the machine has is killed, or takes other processes with it)."""
    available = available_memory()
    if needed <= available:
        return
    size, free = size_text(needed), size_text(available)
    raise TooLarge(f"{why}: {what} would need about {size} of memory, and this process may use {free}: {remedy}"
                   if remedy else f"{why}: {what} would need about {size} of memory, and this process may use {free}")


def check_disk(needed, path, why):
    """TooLarge unless `needed` bytes fit in the free space of the file system of output `path`."""
    folder = os.path.dirname(os.path.abspath(os.fspath(path)))
    while not os.path.isdir(folder):
        folder = os.path.dirname(folder)
    try:
        free = os.statvfs(folder)
    except OSError:
        return
    space = free.f_bavail * free.f_frsize
    if needed <= space or large_allowed():
        return
    raise TooLarge(f"{why}: {os.fspath(path)} would take about {size_text(needed)}, and {folder} has "
                   f"{size_text(space)} free; give --allow-large to try anyway")


def available_memory():
    """Bytes this process may still allocate: the least of the system's available memory, its
    cgroup's limit less its use, and its address-space (RLIMIT_AS) and data (RLIMIT_DATA) limits less
    what it uses now."""
    candidates = []
    meminfo = _read_keys("/proc/meminfo")
    if "MemAvailable" in meminfo:
        candidates.append(meminfo["MemAvailable"])
    cgroup = _cgroup_free()
    if cgroup is not None:
        candidates.append(cgroup)
    status = _read_keys("/proc/self/status")
    for limit, used in ((resource.RLIMIT_AS, status.get("VmSize", 0)), (resource.RLIMIT_DATA, status.get("VmData", 0))):
        soft = resource.getrlimit(limit)[0]
        if soft != resource.RLIM_INFINITY:
            candidates.append(max(0, soft - used))
    return min(candidates) if candidates else 1 << 62


def usable_cores():
    """Cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def _read_keys(path):
    """{key: bytes} of a /proc file of 'Key:  123 kB' lines; {} where it cannot be read."""
    values = {}
    try:
        with open(path, encoding="ascii", errors="replace") as file:
            for line in file:
                key, _, rest = line.partition(":")
                parts = rest.split()
                if parts and parts[0].isdigit():
                    values[key] = int(parts[0]) * (1024 if parts[1:2] == ["kB"] else 1)
    except OSError:
        pass
    return values


def _cgroup_free():
    """Bytes the process's cgroup (v2) may still use, or None without a limit."""
    try:
        with open("/proc/self/cgroup", encoding="ascii", errors="replace") as file:
            lines = file.read().splitlines()
        group = next(line.split(":", 2)[2] for line in lines if line.startswith("0::"))
        folder = os.path.join("/sys/fs/cgroup", group.lstrip("/"))
        with open(os.path.join(folder, "memory.max"), encoding="ascii") as file:
            limit = file.read().strip()
        if limit == "max":
            return None
        with open(os.path.join(folder, "memory.current"), encoding="ascii") as file:
            used = int(file.read().strip())
        return max(0, int(limit) - used)
    except (OSError, StopIteration, ValueError, IndexError):
        return None
