"""Table lines made in compiled code, on threads, written in order.

A :class:`Lines` formats rows of a table of float64, int64 and bool columns into the
lines of a CSV or JSON file in one compiled pass (numba, ``nogil``): every value after its
column's prefix (``,`` between CSV fields; ``{"name":`` and ``,"name":`` in a JSON
record), every row followed by a suffix (a newline in CSV).  The columns are read where
they are (their addresses and strides: no copy, no gather), a float by
:func:`mechloop.output.shortest.write_double` (orjson's text), an integer in decimal, a
boolean as ``True``/``False`` (CSV) or ``true``/``false`` (JSON); a NaN is an empty CSV
field or a JSON ``null``, an infinity ``inf``/``-inf`` in CSV and ``null`` in JSON.

:func:`write_lines` cuts the rows into blocks of about BLOCK_VALUES values, formats them
on a pool of threads (one per core, at least one: the compiled code does not hold
Python's lock, so the threads run at once) and writes them in order from the calling
thread while the next blocks are formatted.  At most AHEAD blocks per thread are held, each
in a buffer reused from block to block: memory stays bounded whatever the rows.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Sequence
from concurrent.futures import Future, ThreadPoolExecutor
from typing import BinaryIO

import numpy as np
from numba import njit

from mechloop.output.memory import address_of, load8, load_uint8, store8
from mechloop.output.shortest import SLACK, write_double_at, write_int_at

#: Values in one block of rows formatted by one thread at a time (about 1.3 MB of CSV
#: text: large enough that a thread's hand-over costs nothing, small enough for the
#: CPU's cache).
BLOCK_VALUES = 1 << 16

#: Rows read into a row-major tile at a time.
TILE = 16

#: Blocks per thread formatted ahead of the one being written.
AHEAD = 2

#: Column kinds.
FLOAT, INT, BOOL = 0, 1, 2

#: The longest text of a value of each kind (``-1.7976931348623157e+308``,
#: ``-9223372036854775808``, ``False``; ``null``, ``-inf``).
_WIDEST = {FLOAT: 24, INT: 20, BOOL: 5}

_U52 = np.uint64(52)
_EXPONENT = np.uint64(0x7FF)
_MANTISSA = np.uint64((1 << 52) - 1)
_SIGN = np.uint64(1 << 63)


@njit(nogil=True, cache=True, error_model="numpy", inline="always")
def _copy(source: int, size: int, target: int) -> int:
    """Copy ``size`` bytes from address ``source`` to ``target`` in whole 8-byte words
    (up to 7 bytes past either end are read or overwritten); the address after the copy."""
    for k in range(0, size, 8):
        store8(target + k, load8(source + k))
    return target + size


@njit(nogil=True, cache=True, error_model="numpy")
def _format_rows(addresses: np.ndarray, strides: np.ndarray, kinds: np.ndarray,
                 start: int, stop: int, prefix: np.ndarray, prefix_at: np.ndarray,
                 suffix: np.ndarray, words: np.ndarray, word_at: np.ndarray,
                 out: np.ndarray) -> int:
    """Rows ``start:stop`` of the columns at ``addresses`` (byte ``strides``, ``kinds``)
    as lines into ``out``; the bytes written.  ``words[word_at[w]:word_at[w + 1]]`` are
    the fixed texts: 0 NaN, 1 inf, 2 -inf, 3 true, 4 false.  ``prefix``, ``suffix`` and
    ``words`` end in 8 spare bytes (copied in whole words).

    TILE rows of every column are first read into a row-major tile: a column's values are
    read in a run, not one from each column a row (columns of a 2-D block lie a multiple
    of 4 KiB apart: one value from each would evict each other from the cache)."""
    columns = kinds.size
    tile = np.empty(TILE * columns, dtype=np.uint64)
    base = address_of(out)
    at = base
    prefix_address = address_of(prefix)
    word_address = address_of(words)
    suffix_address = address_of(suffix)
    for first in range(start, stop, TILE):
        count = min(TILE, stop - first)
        for c in range(columns):
            address = addresses[c] + first * strides[c]
            if kinds[c] == BOOL:
                for r in range(count):
                    tile[r * columns + c] = np.uint64(load_uint8(address + r * strides[c]))
            else:
                for r in range(count):
                    tile[r * columns + c] = load8(address + r * strides[c])
        for r in range(count):
            for c in range(columns):
                at = _copy(prefix_address + prefix_at[c], prefix_at[c + 1] - prefix_at[c], at)
                bits = tile[r * columns + c]
                kind = kinds[c]
                if kind == FLOAT:
                    if (bits >> _U52) & _EXPONENT == _EXPONENT:  # NaN or an infinity
                        w = 0 if bits & _MANTISSA else (2 if bits & _SIGN else 1)
                        at = _copy(word_address + word_at[w], word_at[w + 1] - word_at[w], at)
                    else:
                        at = write_double_at(bits, at)
                elif kind == INT:
                    at = write_int_at(np.int64(bits), at)
                else:
                    w = 3 if bits else 4
                    at = _copy(word_address + word_at[w], word_at[w + 1] - word_at[w], at)
            at = _copy(suffix_address, suffix.size - 8, at)
    return at - base


class Lines:
    """The lines of rows of ``arrays`` (1-D, float64, int64 or bool, one per column;
    kept alive here), each value after its entry of ``prefixes``, each row followed by
    ``suffix``; CSV's texts of NaN, infinities and booleans with ``csv``, else JSON's."""

    def __init__(self, arrays: Sequence[np.ndarray], prefixes: Sequence[bytes],
                 suffix: bytes, *, csv: bool):
        kinds = []
        for a in arrays:
            if a.ndim != 1 or a.dtype not in (np.float64, np.int64, np.bool_):
                raise TypeError(f"a column of {a.dtype} cannot be formatted in compiled code")
            kinds.append({"f": FLOAT, "i": INT, "b": BOOL}[a.dtype.kind])
        self.arrays = list(arrays)
        self.rows = len(arrays[0]) if arrays else 0
        self.kinds = np.array(kinds, dtype=np.int8)
        self.addresses = np.array([a.ctypes.data for a in arrays], dtype=np.intp)
        self.strides = np.array([a.strides[0] for a in arrays], dtype=np.intp)
        lengths = [len(p) for p in prefixes]
        self.prefix = np.frombuffer(b"".join(prefixes) + bytes(8), dtype=np.uint8)
        self.prefix_at = np.concatenate(([0], np.cumsum(lengths))).astype(np.int64)
        self.suffix = np.frombuffer(suffix + bytes(8), dtype=np.uint8)
        texts = [b"", b"inf", b"-inf", b"True", b"False"] if csv else \
            [b"null", b"null", b"null", b"true", b"false"]
        self.words = np.frombuffer(b"".join(texts) + bytes(8), dtype=np.uint8)
        self.word_at = np.concatenate(([0], np.cumsum([len(t) for t in texts]))
                                      ).astype(np.int64)
        #: the most bytes one row takes
        self.row_bytes = (sum(lengths) + len(suffix)
                          + sum(_WIDEST[int(k)] for k in self.kinds))

    def __call__(self, start: int, stop: int, out: np.ndarray | None = None) -> memoryview:
        """The lines of rows ``start:stop``, in ``out`` (uint8, at least
        ``(stop - start) * row_bytes + SLACK`` long) or a new buffer."""
        need = (stop - start) * self.row_bytes + SLACK
        if out is None or out.size < need:
            out = np.empty(need, dtype=np.uint8)
        size = _format_rows(self.addresses, self.strides, self.kinds, start, stop,
                            self.prefix, self.prefix_at, self.suffix, self.words,
                            self.word_at, out)
        return memoryview(out)[:size]


def block_rows(lines: Lines) -> int:
    """Rows in one block: about BLOCK_VALUES values, at least one row."""
    return max(1, BLOCK_VALUES // max(1, len(lines.kinds)))


def write_lines(handle: BinaryIO, lines: Lines, threads: int, *, skip: int = 0) -> None:
    """Every row of ``lines`` into ``handle``, in order, formatted by ``threads`` threads
    (at least one) while this thread writes; the first ``skip`` bytes left out."""
    rows, step = lines.rows, block_rows(lines)
    if rows == 0:
        return
    blocks = [(s, min(s + step, rows)) for s in range(0, rows, step)]
    threads = max(1, min(threads, len(blocks)))
    if len(blocks) == 1:
        handle.write(lines(0, rows)[skip:])
        return
    free: list[np.ndarray] = []  # buffers of written blocks, reused
    pending: deque[tuple[Future[memoryview], np.ndarray]] = deque()
    with ThreadPoolExecutor(threads, thread_name_prefix="mechloop-lines") as pool:
        try:
            for start, stop in blocks:
                if len(pending) >= AHEAD * threads + 1:
                    _write_next(handle, pending, free, skip)
                    skip = 0
                buffer = free.pop() if free else np.empty(step * lines.row_bytes + SLACK,
                                                             np.uint8)
                pending.append((pool.submit(lines, start, stop, buffer), buffer))
            while pending:
                _write_next(handle, pending, free, skip)
                skip = 0
        except BaseException:
            for future, _ in pending:
                future.cancel()
            raise


def _write_next(handle: BinaryIO, pending: deque, free: list[np.ndarray], skip: int
                ) -> None:
    future, buffer = pending.popleft()
    text = future.result()
    handle.write(text[skip:] if skip else text)
    free.append(buffer)
