"""Keep freed memory inside the process, so that numpy's short-lived arrays do not page-fault.

By default glibc's malloc gives every block of 128 KiB or more its own mapping and unmaps it
when it is freed, and it hands the free top of its heap back to the kernel as soon as that
exceeds 128 KiB. The engine makes hundreds of temporary arrays of 10 KiB to a few MiB per chunk
of instants; with those defaults each new one is fresh memory from the kernel, and touching it
costs one page fault (a zeroed 4 KiB page) per page. On a model test's 53-point pass that was
a quarter to 40 % of the engine's time.

keep_freed_memory() raises both thresholds once for the whole process (the command line, the
GUI and any other code that shares it): freed blocks up to KEPT_BYTES stay mapped and are reused
by the next allocation. The cost is that the process keeps up to that much memory it no longer
uses. Off glibc (macOS, musl, Windows) it does nothing.
"""

import ctypes
import os

#: Freed memory the process keeps for reuse (bytes): the heap is trimmed only above it.
KEPT_BYTES = 64 << 20

# mallopt parameters, from glibc's <malloc.h>.
_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3

_applied = None


def keep_freed_memory():
    """Tell glibc's malloc to keep freed memory (up to KEPT_BYTES) for reuse; once per process.

    Blocks below the mmap threshold come from the heap; glibc caps that threshold at 32 MiB on
    64-bit systems (4 MiB × sizeof(long)), so larger arrays are still mapped and unmapped.
    Returns True when the thresholds are set (now or by an earlier call), False off glibc.
    """
    global _applied
    if _applied is None:
        _applied = _set_thresholds()
    return _applied


def _set_thresholds():
    """Set glibc's trim and mmap thresholds; False where the C library is not glibc."""
    try:
        if not os.confstr("CS_GNU_LIBC_VERSION"):  # only glibc answers this
            return False
        mallopt = ctypes.CDLL(None).mallopt
    except (ValueError, OSError, AttributeError):
        return False
    largest_heap_block = 4 * 1024 * 1024 * ctypes.sizeof(ctypes.c_long)
    trimmed = mallopt(_M_TRIM_THRESHOLD, KEPT_BYTES)
    mapped = mallopt(_M_MMAP_THRESHOLD, min(KEPT_BYTES, largest_heap_block))
    return bool(trimmed and mapped)
