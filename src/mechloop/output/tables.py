"""Streaming table writers: CSV, JSON, Parquet and XLSX by the file's suffix.

A table of a million rows and thousands of columns is written in chunks of rows, each
formatted by C code (orjson for the numbers of CSV and JSON, pyarrow for Parquet) and
written at once, so memory stays bounded by one chunk and the speed by the disk.  Every
float is written in its shortest form that reads back to the same double (bit for bit).

Formats (as before the writers streamed):

- CSV: a header of the column names, then one line per row; a missing value (NaN, a
  broken position) is an empty field, a boolean is ``True``/``False``, ``inf`` is ``inf``.
- JSON: a list of records ``[{"column": value, ...}, ...]``, one per row; NaN and
  infinities are ``null``, booleans ``true``/``false``, integers stay integers.
- Parquet: one column per column with its type; NaN is null.
- XLSX: one sheet, refused past the format's 1,048,576 rows or 16,384 columns.
"""

from __future__ import annotations

import csv
import io
import os
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, BinaryIO

import numpy as np

from mechloop.output.atomic import atomic_file
from mechloop.output.paths import OutputError

if TYPE_CHECKING:
    import pandas as pd

#: File types a table can be written as.
TABLE_SUFFIXES = (".csv", ".json", ".parquet", ".xlsx")

#: The largest sheet Excel opens: rows (with the header) and columns.
XLSX_ROWS = 1_048_576
XLSX_COLUMNS = 16_384

#: Values in one chunk of rows (rows x columns): a few tens of MB of text at most.
CHUNK_VALUES = 1_000_000


def check_table_size(rows: int, columns: int, path: str | os.PathLike[str]) -> None:
    """An :class:`OutputError` when a table of ``rows`` x ``columns`` (header not counted)
    does not fit the file type of ``path`` (only XLSX has limits)."""
    if Path(path).suffix.lower() != ".xlsx":
        return
    if rows + 1 > XLSX_ROWS or columns > XLSX_COLUMNS:
        raise OutputError(
            f"{path}: {rows:,} rows and {columns:,} columns do not fit an Excel sheet "
            f"(at most {XLSX_ROWS - 1:,} rows under the header and {XLSX_COLUMNS:,} "
            "columns)", "write a .csv or .parquet file instead")


def write_frame(frame: pd.DataFrame, path: str | os.PathLike[str], *,
                sheet: str = "results") -> Path:
    """Write ``frame`` (without its index) to ``path`` by its suffix — ``.csv``,
    ``.json``, ``.parquet`` or ``.xlsx`` (sheet ``sheet``) — atomically and streaming."""
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in TABLE_SUFFIXES:
        raise OutputError(f"{target}: unknown output format '{target.suffix}'",
                          "use a file name ending in .csv, .json, .parquet or .xlsx")
    check_table_size(len(frame), len(frame.columns), target)
    with atomic_file(target) as handle:
        if suffix == ".csv":
            write_csv(frame, handle)
        elif suffix == ".json":
            write_json(frame, handle)
        elif suffix == ".parquet":
            write_parquet(frame, handle)
        else:
            frame.to_excel(handle, index=False, sheet_name=sheet)
    return target


def _chunks(frame: pd.DataFrame) -> Iterator[pd.DataFrame]:
    step = max(1, CHUNK_VALUES // max(1, len(frame.columns)))
    for start in range(0, len(frame), step):
        yield frame.iloc[start:start + step]


def _numeric(values: np.ndarray) -> np.ndarray | None:
    """``values`` as an array orjson writes exactly (bool, int64, float64), or None for
    any other kind (strings, objects)."""
    if values.dtype.kind == "b":
        return values
    if values.dtype.kind in "iu":
        return values.astype(np.int64, copy=False)
    if values.dtype.kind == "f":
        return values.astype(np.float64, copy=False)
    return None


def _tokens(values: np.ndarray, *, csv_form: bool) -> list[bytes]:
    """One formatted value per row of a column: JSON text, or CSV text when ``csv_form``
    (empty for NaN, ``inf``, ``True``/``False``, strings quoted when needed)."""
    import orjson

    array = _numeric(values)
    if array is None:
        return [_other(v, csv_form=csv_form) for v in values]
    text = orjson.dumps(array, option=orjson.OPT_SERIALIZE_NUMPY)[1:-1]
    if csv_form:
        if array.dtype.kind == "b":
            text = text.replace(b"true", b"True").replace(b"false", b"False")
        else:
            text = text.replace(b"null", b"")
    tokens = text.split(b",")
    if csv_form and array.dtype.kind == "f":
        for i in np.flatnonzero(np.isinf(array)):
            tokens[i] = b"inf" if array[i] > 0 else b"-inf"
    return tokens


def _other(value: object, *, csv_form: bool) -> bytes:
    """A value that is not a number array element (a string, None, a Python scalar)."""
    import orjson

    missing = value is None or (isinstance(value, float) and np.isnan(value))
    if csv_form:
        if missing:
            return b""
        text = io.StringIO()
        csv.writer(text, lineterminator="").writerow([value])
        return text.getvalue().encode("utf-8")
    if missing:
        return b"null"
    return orjson.dumps(value, option=orjson.OPT_SERIALIZE_NUMPY, default=str)


def _rows(frame: pd.DataFrame, prefixes: list[bytes], end: bytes, *, csv_form: bool
          ) -> bytes:
    """The rows of ``frame`` as one block: per row, prefix 0, value 0, prefix 1, value 1,
    ..., then ``end`` — interleaved by list slices, without a Python loop per value."""
    n, k = len(frame), len(frame.columns)
    parts: list[bytes] = [b""] * (n * (2 * k + 1))
    width = 2 * k + 1
    for j in range(k):
        parts[j * 2::width] = [prefixes[j]] * n
        parts[j * 2 + 1::width] = _tokens(frame.iloc[:, j].to_numpy(), csv_form=csv_form)
    parts[2 * k::width] = [end] * n
    return b"".join(parts)


def write_csv(frame: pd.DataFrame, handle: BinaryIO) -> None:
    """``frame`` as CSV (header, then one line per row) into the binary ``handle``."""
    names = [_other(str(c), csv_form=True) for c in frame.columns]
    handle.write(b",".join(names) + b"\n")
    if len(frame.columns) == 0:
        handle.write(b"\n" * len(frame))
        return
    prefixes = [b""] + [b","] * (len(frame.columns) - 1)
    for chunk in _chunks(frame):
        handle.write(_rows(chunk, prefixes, b"\n", csv_form=True))


def write_json(frame: pd.DataFrame, handle: BinaryIO) -> None:
    """``frame`` as a JSON list of records, one line per row, into ``handle``."""
    import orjson

    keys = [orjson.dumps(str(c)) for c in frame.columns]
    if len(frame) == 0:
        handle.write(b"[]\n")
        return
    prefixes = ([b"{" + keys[0] + b":"] if keys else [])
    prefixes += [b"," + key + b":" for key in keys[1:]]
    handle.write(b"[\n")
    for i, chunk in enumerate(_chunks(frame)):
        if not keys:
            block = b"{},\n" * len(chunk)
        else:
            block = _rows(chunk, prefixes, b"},\n", csv_form=False)
        if i:
            handle.write(b",\n")
        handle.write(memoryview(block)[:-2])
    handle.write(b"\n]\n")


def write_parquet(frame: pd.DataFrame, handle: BinaryIO) -> None:
    """``frame`` as Parquet (one row group per chunk of rows) into ``handle``."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    named = frame.set_axis([str(c) for c in frame.columns], axis=1)
    schema = pa.Schema.from_pandas(named, preserve_index=False)
    with pq.ParquetWriter(handle, schema) as writer:
        for chunk in _chunks(named):
            writer.write_table(pa.Table.from_pandas(chunk, schema=schema,
                                                    preserve_index=False))
