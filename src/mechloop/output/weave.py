"""Weaving the texts of column runs into table lines, in one compiled pass.

The table writers format the numbers of a chunk of rows with orjson, one 2-D text per run
of neighbouring columns of one type (``[[v,v],[v,v]]``: a float's shortest round-trip
form, ``null`` for NaN, ``true``/``false``, integers as integers).  A :class:`Weaver`
builds the chunk's lines from these texts in one pass of compiled code (numba), which
finds where the values (or the rows) end with the C library's ``memchr`` and copies them
row by row, each after its column's prefix (``{"name":`` and ``,"name":`` in a JSON
record; ``,`` between the runs of a CSV line, whose values orjson has already joined by
commas), each row followed by a suffix (a newline in CSV).  Splitting the texts in Python
and joining the pieces again (as the writers did before) cost about as much CPU time as
formatting the numbers for JSON, and less for CSV.

The texts hold only numbers, ``null``, ``true`` and ``false``, so a value ends at the next
``,`` or ``]`` (a row of a run ends at ``]``, followed by ``,[`` or ``]``).
"""

from __future__ import annotations

import numpy as np
from numba import njit, types

_COMMA, _CLOSE = ord(","), ord("]")

#: The C library's ``memchr`` (the address of the first byte equal to a value in a
#: buffer, 0 if none): found by the linker, so the compiled code is cached.
_memchr = types.ExternalFunction("memchr", types.intp(types.intp, types.intc, types.intp))


@njit(nogil=True, inline="always")
def _copy(target: np.ndarray, source: np.ndarray) -> None:
    for k in range(source.size):  # a loop over views: vectorized, unlike one over offsets
        target[k] = source[k]


@njit(cache=True, nogil=True)
def _weave(text: np.ndarray, run_start: np.ndarray, run_width: np.ndarray, rows: int,
           prefix: np.ndarray, prefix_at: np.ndarray, suffix: np.ndarray,
           out: np.ndarray) -> int:
    """Copy the values (``run_width`` > 0: one piece per value) or the rows (0: one piece
    per run and row) of the runs' texts in ``text`` (run ``r`` from ``run_start[r]``) row
    by row into ``out``, each piece after its prefix (``prefix[prefix_at[c]:prefix_at[c +
    1]]`` for a row's ``c``-th piece), each row followed by ``suffix``; the bytes
    written."""
    base = np.intp(text.ctypes.data)
    begin = run_start + 2  # past "[["
    at = 0
    for _ in range(rows):
        c = 0
        for r in range(run_start.size):
            p = begin[r]
            width = max(run_width[r], 1)
            for j in range(width):
                size = prefix_at[c + 1] - prefix_at[c]
                _copy(out[at:at + size], prefix[prefix_at[c]:prefix_at[c + 1]])
                at += size
                c += 1
                end = _memchr(base + p, _CLOSE if j == width - 1 else _COMMA,
                              text.size - p) - base
                _copy(out[at:at + end - p], text[p:end])
                at += end - p
                p = end + 1
            begin[r] = p + 2  # past ",[" (after the last row: beyond the text)
        _copy(out[at:at + suffix.size], suffix)
        at += suffix.size
    return at


class Weaver:
    """Lines from orjson's 2-D texts of runs of columns, ``widths`` columns each: every
    value (``values``), or with not ``values`` every run's part of a row as it is (its
    values joined by commas, as in CSV), after its entry in ``prefixes``; every row
    followed by ``suffix``."""

    def __init__(self, widths: list[int], prefixes: list[bytes], suffix: bytes, *,
                 values: bool):
        self.widths = np.asarray(widths if values else [0] * len(widths), dtype=np.int64)
        lengths = np.array([len(p) for p in prefixes], dtype=np.int64)
        self.prefix = np.frombuffer(b"".join(prefixes) or b" ", dtype=np.uint8)
        self.prefix_at = np.concatenate(([0], np.cumsum(lengths))).astype(np.int64)
        self.suffix = np.frombuffer(suffix, dtype=np.uint8)
        self.extra = int(lengths.sum()) + len(suffix)  # bytes a row adds to its values
        # compiled (or loaded from numba's cache) now, before the writers fork their workers
        self([b"[[" + b",".join([b"0"] * max(w, 1)) + b"]]" for w in self.widths], 1)

    def __call__(self, texts: list[bytes], rows: int) -> memoryview:
        """The lines of ``rows`` rows from the runs' ``texts``."""
        text = np.frombuffer(b"".join(texts), dtype=np.uint8)
        sizes = np.array([len(t) for t in texts], dtype=np.int64)
        run_start = np.concatenate(([0], np.cumsum(sizes)[:-1])).astype(np.int64)
        out = np.empty(text.size + rows * self.extra, dtype=np.uint8)
        size = _weave(text, run_start, self.widths, rows, self.prefix, self.prefix_at,
                      self.suffix, out)
        return memoryview(out)[:size]
