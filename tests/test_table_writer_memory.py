"""The streaming CSV and JSON writers hold a bounded amount of memory, whatever the
table's length: the peak of Python's and NumPy's allocations (tracemalloc) while a table
is written stays under a bound set by the writers' chunk sizes, not by the rows, for a
table and one of 4x its rows, far below the text written."""

from __future__ import annotations

import tracemalloc
from unittest import mock

import numpy as np
import pandas as pd
import pytest

from mechloop.output import lines, tables


class _Sink:
    """A binary handle that keeps only the count of the bytes written to it."""

    def __init__(self) -> None:
        self.size = 0

    def write(self, data: bytes | memoryview) -> int:
        size = memoryview(data).nbytes
        self.size += size
        return size

    def flush(self) -> None:
        pass


def _frame(rows: int) -> pd.DataFrame:
    rng = np.random.default_rng(rows)
    values = rng.normal(size=(rows, 24)) * 10.0 ** rng.integers(-3, 4, size=24)
    frame = pd.DataFrame(values, columns=[f"a{j} [rad]" for j in range(24)])
    frame.insert(0, "position", np.arange(rows))
    frame["chain_break"] = rng.random(rows) < 0.01
    frame.loc[frame["chain_break"], "a3 [rad]"] = np.nan
    return frame


def _peak(writer, frame: pd.DataFrame) -> tuple[int, int]:
    """Peak traced bytes allocated while ``writer`` writes ``frame``, and the bytes
    written (lines formatted in compiled code by two threads while this one writes, as
    for a large table)."""
    sink = _Sink()
    with mock.patch.object(tables, "_compiled", lambda values: True), \
            mock.patch.object(tables, "threads_for", lambda values: 2):
        writer(frame.iloc[:100], _Sink())  # compiled code loaded before tracing
        tracemalloc.start()
        try:
            writer(frame, sink)
            _, peak = tracemalloc.get_traced_memory()
        finally:
            tracemalloc.stop()
    return peak, sink.size


@pytest.mark.parametrize("writer", [tables.write_csv, tables.write_json])
def test_memory_does_not_grow_with_the_rows(writer):
    for rows in (30_000, 120_000):
        frame = _frame(rows)
        peak, size = _peak(writer, frame)
        csv = writer is tables.write_csv
        prefixes = ([b","] * len(frame.columns) if csv else
                    [b'},\n{"' + str(c).encode() + b'":' for c in frame.columns])
        frame_lines = lines.Lines([frame[c].to_numpy() for c in frame.columns],
                                  prefixes, b"\n" if csv else b"", csv=csv)
        block = lines.block_rows(frame_lines) * frame_lines.row_bytes  # bytes of a buffer
        # what the writer may hold, whatever the rows: the buffers of the blocks being
        # formatted or waiting to be written (AHEAD per thread, one more being written)
        bound = (lines.AHEAD * 2 + 2) * block
        assert peak < bound + (1 << 20), (rows, peak, bound)
        if rows == 120_000:
            assert bound < size / 4, (bound, size)  # far less than the text written
