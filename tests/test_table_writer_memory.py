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

from mechloop.output import parallel, tables


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
    written (lines woven in compiled code and written by a thread, as for a large table
    on a busy machine)."""
    sink = _Sink()
    with mock.patch.object(tables, "_weaving", lambda values: True), \
            mock.patch.object(tables, "GATHER_VALUES", 1 << 16), \
            mock.patch.object(parallel, "PARALLEL_VALUES", 1 << 62):
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
        width = len(frame.columns)
        chunk = max(16, tables.CHUNK_VALUES // width) * size / rows  # bytes of a part
        # what the writer may hold, whatever the rows: a gathered block of each run of
        # columns (3 runs, 8-byte values), the parts queued for the writing thread, the
        # one it writes and the one being formatted (its texts and its lines)
        bound = 3 * 8 * (1 << 16) + (parallel.WRITE_AHEAD + 2) * chunk + 2 * chunk
        assert peak < bound + (1 << 20), (rows, peak, bound)
        if rows == 120_000:
            assert bound < size / 8, (bound, size)  # far less than the text written
