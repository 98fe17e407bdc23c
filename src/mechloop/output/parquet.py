"""The Parquet writer: a pandas table written by pyarrow, row group by row group, as fast
as the disk takes it.

The columns go to Arrow without a copy: a column of numbers (float, int, bool) that holds
no NaN is handed to Arrow as the NumPy array it is (``pa.array`` on a view of the frame's
memory), and is declared *required* (not null) in the file's schema, which spares Arrow's
writer the definition levels of every value (reading back gives the same frame).  A float
column with a NaN anywhere is optional, and its NaN are nulls, as pandas' own conversion
makes them; strings and other objects go through that conversion, with a dictionary.  The
whole table is searched for NaN once, before the first row group, to settle the schema.

The pages are written uncompressed, in the PLAIN encoding, without statistics for the
float columns, by Arrow into a file it opens itself (the same file as the caller's
handle, by its ``/proc/self/fd`` link), so that its writes do not call back into Python.
Each choice was measured on a table of 300,000 rows x 202 columns of mechanism results
(``benchmarks/bench_output.py --contours 22 --positions 300000``; 461 MB), encoded into
``/dev/null`` on the loaded 2-core development machine, in CPU-seconds:

- snappy: 0.05-0.06 more (lz4 the same) for a file a fifth smaller (noisy doubles hardly
  compress); written and fsynced, both took the same time here (0.74-0.93 s against
  0.81-0.85 s, three runs each under load), so compression would pay only on a disk
  slower than this one's 1-1.5 GB/s (set PARQUET_COMPRESSION);
- min/max statistics of the float columns: 0.10, as much again as the whole encoding of
  the other choices (0.09-0.10) — readers skip row groups by them, but a results table is
  read whole; the int, bool and string columns (positions, marks) keep theirs;
- optional instead of required columns: 0.15-0.17 (definition levels for every value);
- Arrow's default batches of 1,024 values: 0.05-0.08 more than batches of 32,768 or
  65,536;
- pandas' conversion (``pa.Table.from_pandas``: no copy either, but Arrow's search of
  every value for NaN and pandas' bookkeeping, group by group): 0.3; the search here
  (the minimum of each column, once): 0.04;
- writing through a Python file object: 0.05-0.1 more than through a native file, with
  Python's lock taken for every buffer.
"""

from __future__ import annotations

import io
import os
import stat
from collections.abc import Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from contextlib import contextmanager
from typing import TYPE_CHECKING, BinaryIO

import numpy as np

if TYPE_CHECKING:
    import pandas as pd
    import pyarrow as pa

#: Parquet's compression of the columns' pages: none (see the module's docstring).
PARQUET_COMPRESSION = "none"

#: Values in one Parquet row group (about 64 MB of doubles: fewer, larger groups write
#: faster and read better).
PARQUET_GROUP_VALUES = 1 << 23

#: Values Arrow's writer takes from a column at a time (its default, 1,024, spends more in
#: the steps around each batch than in the encoding of doubles): a page of doubles.
PARQUET_BATCH_VALUES = 1 << 15

#: Bytes and values in one data page at most: 256 KiB, so that a page is built in the
#: core's L2 cache (1.25 MiB on the development machine) and copied from there into the
#: page cache.  Pages of Arrow's default 1 MiB took 1.65-1.77 CPU-s for the 10^6 rows x
#: 202 columns of ``bench_output.py --contours 22 --positions 1000000``, pages of 256 KiB
#: 0.9-1.2 (written and fsynced, under load).
PARQUET_PAGE_BYTES = 1 << 18
PARQUET_PAGE_VALUES = 1 << 15


def _numbers(series: pd.Series) -> np.ndarray | None:
    """The column's values as a NumPy array of numbers (float, int, unsigned, bool), a view
    where pandas holds them so; None for any other column (strings, objects, pandas'
    extension types with their own missing values)."""
    if not isinstance(series.dtype, np.dtype) or series.dtype.kind not in "fiub":
        return None
    return series.to_numpy()


def _has_nan(values: np.ndarray) -> bool:
    """Whether a column of numbers holds a NaN (the minimum of an array with a NaN is NaN;
    no temporary array)."""
    return values.dtype.kind == "f" and values.size > 0 and bool(np.isnan(values.min()))


@contextmanager
def _native(handle: BinaryIO) -> Iterator[pa.NativeFile | BinaryIO]:
    """A native Arrow file writing the regular, empty file ``handle`` writes (opened
    again by its ``/proc/self/fd`` link; ``handle`` is moved to its end afterwards), else
    ``handle`` itself (a buffer, a pipe, a file already written into, a system without
    ``/proc``, or a file its owner may not open for writing: a umask without the owner's
    write bit)."""
    import pyarrow as pa

    try:
        fd = handle.fileno()
        info = os.fstat(fd)
    except (AttributeError, OSError, io.UnsupportedOperation):
        yield handle
        return
    link = f"/proc/self/fd/{fd}"
    if not stat.S_ISREG(info.st_mode) or info.st_size or handle.tell() or \
            not os.path.exists(link):
        yield handle
        return
    try:
        sink = pa.OSFile(link, "wb")
    except PermissionError:
        yield handle
        return
    with sink:
        yield sink
    handle.seek(0, io.SEEK_END)


def write_parquet(frame: pd.DataFrame, handle: BinaryIO) -> None:
    """``frame`` (without its index; column names as strings) as Parquet into ``handle``:
    row groups of about PARQUET_GROUP_VALUES values, each encoded and written by a thread
    while the next is gathered (zero-copy for columns of numbers: at most two groups of
    Arrow's arrays, views of the frame, are alive at a time); see the module's docstring
    for the encoding."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    named = frame.set_axis([str(c) for c in frame.columns], axis=1)
    numbers = [_numbers(named.iloc[:, j]) for j in range(len(named.columns))]
    with ThreadPoolExecutor(1) as pool:
        half = len(numbers) // 2  # the search for NaN on two cores
        tail = pool.submit(lambda: [a is not None and _has_nan(a) for a in numbers[half:]])
        nans = [a is not None and _has_nan(a) for a in numbers[:half]] + tail.result()
        schema = pa.Schema.from_pandas(named, preserve_index=False)
        schema = pa.schema([f.with_nullable(a is None or nan) for f, a, nan
                            in zip(schema, numbers, nans, strict=True)],
                           metadata=schema.metadata)
        plain = [f.name for f, a in zip(schema, numbers, strict=True) if a is not None]
        floats = [f.name for f, a in zip(schema, numbers, strict=True)
                  if a is not None and a.dtype.kind == "f"]
        step = max(1, PARQUET_GROUP_VALUES // max(1, len(named.columns)))

        def group(start: int) -> pa.Table:
            stop = start + step
            return pa.Table.from_arrays(
                [pa.array(named.iloc[start:stop, j], type=f.type, from_pandas=True)
                 if a is None else
                 pa.array(a[start:stop], type=f.type, from_pandas=nan)
                 for j, (f, a, nan) in enumerate(zip(schema, numbers, nans, strict=True))],
                schema=schema)

        with _native(handle) as sink, pq.ParquetWriter(
                sink, schema, compression=PARQUET_COMPRESSION,
                use_dictionary=[f.name for f in schema if f.name not in plain],
                write_statistics=[f.name for f in schema if f.name not in floats],
                write_batch_size=PARQUET_BATCH_VALUES, data_page_size=PARQUET_PAGE_BYTES,
                max_rows_per_page=PARQUET_PAGE_VALUES) as writer:
            writing: Future[None] | None = None  # Arrow's encoding releases Python's lock
            for start in range(0, len(named), step):
                table = group(start)
                if writing is not None:
                    writing.result()  # at most two groups alive
                writing = pool.submit(writer.write_table, table)
            if writing is not None:
                writing.result()
