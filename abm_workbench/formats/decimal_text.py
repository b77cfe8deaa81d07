"""Decimal text of number arrays, built with integer table look-ups as matrices of 8-byte words.

A *field* is the text of a column of n values: a (w, n) matrix of little-endian uint64 words,
value i's text being the non-NUL bytes of its words field[0, i], …, field[w − 1, i] in order
(ASCII, with NUL (0) bytes in between or after). The last byte of field[w − 1, i] is always NUL,
room for a separator. The fields of a table's columns laid side by side as the columns of one
(n, Σw) matrix, separators added, give the table's lines: the matrix's non-NUL bytes in
row-major order (results_csv).

- :func:`number_field`: floats as Python's ``repr(float(np.round(v, DECIMALS) + 0.0))``, the
  shortest text that reads back as the rounded value; empty for NaN.
- :func:`integer_field`: integers as ``str(int(v))``.
- :func:`text_field`: strings as UTF-8.

Why the fast path writes the same text as ``repr`` (proof in docs/SCALING.md, "The CSV text"):
with d = DECIMALS, k = rint(v·10^d) and |k| < 10^15, the rounded value r = k / 10^d is the
double nearest the decimal D = k·10^−d, which has at most 15 significant digits. Two different
decimals of at most 15 significant digits never round to the same double (DBL_DIG = 15), so D
is the only one of them that reads back as r, and repr's shortest text has D's digits. repr
writes them positionally for 10^−4 ≤ |r| < 10^16: D written with d decimals, trailing zeros
stripped, one '0' kept after the point. Elements outside that range (|r| < 10^−4 but not 0,
|k| ≥ 10^15, inf) and any whose k / 10^d is not numpy's rounded value are written by repr itself.
"""

import functools

import numpy as np

#: Decimal places kept by number_field (mm, deg, mm² in the results): values read back within 5e-11.
DECIMALS = 10
#: Significant digits of a decimal that always reads back as itself through a double (DBL_DIG).
SIGNIFICANT = 15
#: Digits per group: one 8-byte word, looked up in a table of 10^GROUP entries per section.
GROUP = 5
WORD = np.dtype("<u8")
_SIZE = 10**GROUP
_SCALE = 10.0**DECIMALS
#: Smallest nonzero k = rint(v·10^DECIMALS) that repr writes positionally (|r| ≥ 10^−4).
_POSITIONAL = 10.0 ** (DECIMALS - 4)
_MINUS, _POINT = ord("-"), ord(".")


@functools.lru_cache(maxsize=None)
def _group_table():
    """(7·10^GROUP,) WORD table, read-only, built on first use (5.6 MB, tens of ms): for g in
    0 … 10^GROUP − 1, entry s + g holds g's GROUP digits in bytes 2 … 6, as written in section s
    (one of the offsets below):

    _WHOLE: leading zeros NUL, '0' for 0, in bytes 1 … 5 and '.' in byte 6; _NEGATIVE_WHOLE (=
    _WHOLE + 10^GROUP): the same with '-' in byte 0; _FULL: leading zeros written; _FIRST_DECIMALS
    (= _FULL + 10^GROUP): trailing zeros NUL, '0' for 0; _TRIMMED: trailing zeros NUL, 0 empty;
    _STRIPPED: leading zeros NUL, 0 empty; _UNITS: leading zeros NUL, '0' for 0. Byte 7 is NUL
    everywhere, byte 0 outside _NEGATIVE_WHOLE (room for a sign).
    """
    numbers = np.arange(_SIZE, dtype=np.int32)[:, None]  # int32 and uint8: small temporaries
    places = 10 ** np.arange(GROUP - 1, -1, -1, dtype=np.int32)
    digits = (numbers // places % 10).astype(np.uint8) + np.uint8(ord("0"))
    leading = digits * (numbers >= places)
    trailing = digits * (numbers % (10 * places) != 0)
    units, first = leading.copy(), trailing.copy()
    units[0, -1] = first[0, 0] = ord("0")
    table = np.zeros((7, _SIZE, 8), dtype=np.uint8)
    table[:2, :, 1:1 + GROUP] = units
    table[:2, :, 1 + GROUP] = _POINT
    table[1, :, 0] = _MINUS
    for section, text in enumerate((digits, first, trailing, leading, units), start=2):
        table[section, :, 2:2 + GROUP] = text
    words = table.reshape(-1, 8).view(WORD).reshape(-1)
    words.flags.writeable = False
    return words


_WHOLE, _NEGATIVE_WHOLE, _FULL, _FIRST_DECIMALS, _TRIMMED, _STRIPPED, _UNITS = range(0, 7 * _SIZE, _SIZE)


def number_field(values):
    """Field (w, n) of float `values` (n,): each rounded to DECIMALS places, in the shortest text
    that reads back as the rounded value (Python's repr), '0.0' for −0.0, NaN empty; a finite
    value always as a finite number, even where v·10^DECIMALS overflows.

    Byte for byte ``repr(float(np.round(v, DECIMALS) + 0.0))``; w is 3, or more when an element
    needs a repr of 24 characters (see the module docstring).
    """
    values = _vector(values, float, "values")
    with np.errstate(over="ignore", invalid="ignore"):
        rounded = np.round(values, DECIMALS)
        # Above ~1.8e298, v·10^DECIMALS overflows and np.round gives inf; such doubles are whole
        # numbers already, their own rounding.
        rounded = np.where(np.isinf(rounded) & np.isfinite(values), values, rounded)
        k = np.rint(values * _SCALE)
        magnitude = np.abs(k)
        fast = (k / _SCALE == rounded) & (magnitude < 10.0**SIGNIFICANT) & (
            (magnitude >= _POSITIONAL) | (magnitude == 0.0))
        words = _fixed_point(magnitude, k < 0.0)
    if fast.all():
        return words
    words[:, ~fast] = 0
    slow = np.flatnonzero(~fast & ~np.isnan(values))
    if slow.size == 0:
        return words
    text = text_field([repr(value) for value in (rounded[slow] + 0.0).tolist()])  # + 0.0: −0.0 as 0.0
    if text.shape[0] > words.shape[0]:
        words = np.concatenate([words, np.zeros((text.shape[0] - words.shape[0], values.size), dtype=WORD)])
    words[:text.shape[0], slow] = text
    return words


def _fixed_point(magnitude, negative):
    """Field (3, n) of ±magnitude·10^−DECIMALS for whole float magnitudes (n,) below 10^SIGNIFICANT
    (any words for others), '-' where bool `negative` (n,): the integer part without leading
    zeros and '.', the first GROUP decimals and the last GROUP decimals, trailing zeros left out
    (one decimal kept).

    In float64, exactly: every integer below 2^53 is a double, and q + r/10^j with r < 10^j rounds
    below q + 1 for q < 10^GROUP, so floor finds the quotient.
    """
    whole = np.floor(magnitude / _SCALE)
    decimals = magnitude - whole * _SCALE
    head = np.floor(decimals / _SIZE)
    tail = decimals - head * _SIZE
    index = np.empty((3, magnitude.size))
    np.add(whole, negative * float(_SIZE), out=index[0])
    np.add(head, (tail == 0.0) * float(_SIZE), out=index[1])
    index[2] = tail
    index = index.astype(np.intp)
    words = np.empty((3, magnitude.size), dtype=WORD)
    for row, section in enumerate((_WHOLE, _FULL, _TRIMMED)):
        np.take(_group_table()[section:], index[row], out=words[row], mode="clip")
    return words


def integer_field(values):
    """Field (w, n) of integer `values` (n,), each as ``str(int(v))``: '-' for negatives, no leading zeros."""
    values = _vector(values, np.int64, "values")
    negative = values < 0
    magnitude = np.where(negative, -(values + 1), values).astype(np.uint64) + negative.astype(np.uint64)
    count = max(1, -(-len(str(int(magnitude.max(initial=0)))) // GROUP))
    words = np.empty((count, values.size), dtype=WORD)
    higher = np.zeros(values.size, dtype=bool)
    for row in range(count):
        group = (magnitude // np.uint64(_SIZE ** (count - 1 - row)) % np.uint64(_SIZE)).astype(np.intp)
        section = np.where(higher, _FULL, _UNITS if row == count - 1 else _STRIPPED)
        np.take(_group_table(), group + section, out=words[row])
        higher |= group != 0
    words[0] |= negative * np.uint64(_MINUS)
    return words


def text_field(strings):
    """Field (w, n) of `strings` (n,) as UTF-8; ValueError naming the first that holds a NUL."""
    encoded = [string.encode("utf-8") for string in strings]
    for index, text in enumerate(encoded):
        if b"\0" in text:
            raise ValueError(f"strings[{index}] = {text.decode('utf-8')!r} holds a NUL character")
    width = max(map(len, encoded), default=0) // 8 + 1
    return np.array(encoded, dtype=f"S{8 * width}").view(WORD).reshape(len(encoded), width).T.copy()


def _vector(values, dtype, name):
    """`values` as a 1-D array of `dtype`; ValueError naming the shape or dtype otherwise."""
    array = np.asarray(values)
    if array.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array (n,), got shape {array.shape}")
    if dtype is np.int64 and array.size and (
            array.dtype.kind not in "iu" or array.dtype.kind == "u" and array.max() > np.uint64(2**63 - 1)):
        raise ValueError(f"{name} must be integers within int64, got dtype {array.dtype}")
    return array.astype(dtype, copy=False)
