"""Streaming table writers: CSV, JSON, Parquet and XLSX by the file's suffix.

A table of a million rows and thousands of columns is written in chunks of rows, so memory
stays bounded by a few chunks.  A large table of numbers (float, int and bool columns) is
formatted in compiled code without Python's lock (:mod:`mechloop.output.lines`; every float
by :mod:`mechloop.output.shortest`), on a thread per core, while the calling thread
writes the blocks in order.  Small tables (loading the compiled code costs about half a
CPU-second) and tables with strings or objects are formatted by orjson and joined in
Python, into the same text, and written by a thread of their own while the next chunks
are formatted (:mod:`mechloop.output.parallel`).  Every float is written in its shortest
form that reads back to the same double (bit for bit), as orjson writes it.  Arrow's C++
CSV writer and polars' writers were measured against orjson's (``benchmarks/bench_output.py
--ecosystem``): neither formats more per CPU-second, streamed in chunks (see
``benchmarks/README.md``).

Formats (as before the writers streamed):

- CSV: a header of the column names, then one line per row; a missing value (NaN, a
  broken position) is an empty field, a boolean is ``True``/``False``, ``inf`` is ``inf``.
- JSON: a list of records ``[{"column": value, ...}, ...]``, one per row; NaN and
  infinities are ``null``, booleans ``true``/``false``, integers stay integers.
- Parquet: one column per column with its type; NaN is null (:mod:`mechloop.output.parquet`:
  uncompressed, columns of numbers handed to Arrow without a copy).
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
from mechloop.output.parallel import Part, Render, threads_for, write_ordered
from mechloop.output.parquet import write_parquet
from mechloop.output.paths import TABLE_SUFFIXES, OutputError

if TYPE_CHECKING:
    import pandas as pd

#: File types a table can be written as.

#: The largest sheet Excel opens: rows (with the header) and columns.
XLSX_ROWS = 1_048_576
XLSX_COLUMNS = 16_384

#: Values in one chunk of rows (rows x columns, at least 16 rows): about 100 kB of text,
#: small enough for the CPU cache (larger chunks format more slowly).
CHUNK_VALUES = 1 << 12

#: Fewest values in a table worth formatting in compiled code
#: (:mod:`mechloop.output.lines`): loading numba and the compiled code takes about half a
#: CPU-second (smaller tables are formatted by orjson and joined in Python, into the same
#: text).
COMPILED_VALUES = 1 << 22

#: Values gathered from the columns of a run at once (8 MB of doubles).
GATHER_VALUES = 1 << 20

#: Values in one piece of rows (about 5 MB of CSV text; gathers of columns do not cross
#: pieces).
PIECE_VALUES = 1 << 18

def _compiled(values: int) -> bool:
    """Whether to format a table of ``values`` values (numbers only) in compiled code."""
    return values >= COMPILED_VALUES


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


def _kind(values: np.ndarray) -> str:
    """'f' (float64), 'i' (int64), 'b' (bool): arrays orjson writes exactly and fast; 'o'
    for anything else (strings, objects), written value by value."""
    kind = values.dtype.kind
    return {"f": "f", "i": "i", "u": "i", "b": "b"}.get(kind, "o")


def _exact(values: np.ndarray, kind: str) -> np.ndarray:
    if kind == "f":
        return values.astype(np.float64, copy=False)
    if kind == "i":
        return values.astype(np.int64, copy=False)
    return values


class _Columns:
    """The frame's columns as arrays (views, not copies), grouped into runs of neighbours
    of one kind, cut into chunks of rows."""

    def __init__(self, frame: pd.DataFrame):
        arrays = [frame.iloc[:, j].to_numpy() for j in range(len(frame.columns))]
        kinds = [_kind(a) for a in arrays]
        self.arrays = [_exact(a, k) for a, k in zip(arrays, kinds, strict=True)]
        self.rows, self.width = len(frame), len(arrays)
        self._gathered: dict[int, tuple[int, int, np.ndarray]] = {}
        self._bound = self.rows  # gathers stop here (the end of the piece being formatted)
        self.runs: list[tuple[int, int, str]] = []  # (first column, end, kind)
        for j, kind in enumerate(kinds):
            if self.runs and self.runs[-1][2] == kind:
                self.runs[-1] = (self.runs[-1][0], j + 1, kind)
            else:
                self.runs.append((j, j + 1, kind))
        self.widths = [end - first for first, end, _ in self.runs]
        self.compiled = (all(kind != "o" for _, _, kind in self.runs)
                         and _compiled(self.rows * self.width))

    def lines(self, prefixes: list[bytes], suffix: bytes, *, csv: bool):
        """The compiled formatter of these columns' lines
        (:class:`mechloop.output.lines.Lines`)."""
        from mechloop.output.lines import Lines  # numba: only when a large table is written

        return Lines(self.arrays, prefixes, suffix, csv=csv)

    def write_compiled(self, handle: BinaryIO, prefixes: list[bytes], suffix: bytes, *,
                       csv: bool, skip: int = 0) -> None:
        """Every row formatted in compiled code on a thread per core and written in
        order into ``handle`` (the first ``skip`` bytes left out)."""
        from mechloop.output.lines import write_lines

        write_lines(handle, self.lines(prefixes, suffix, csv=csv),
                    threads_for(self.rows * self.width), skip=skip)

    def step(self) -> int:
        """Rows in one chunk: about CHUNK_VALUES values, at least 16 rows."""
        return max(16, CHUNK_VALUES // max(1, self.width))

    def pieces(self) -> list[tuple[int, int]]:
        """The rows cut into pieces of whole chunks, about PIECE_VALUES values each."""
        step = self.step()
        rows = max(1, -(-(PIECE_VALUES // max(1, self.width)) // step)) * step
        return [(start, min(start + rows, self.rows)) for start in range(0, self.rows, rows)]

    def chunks(self, first: int = 0, last: int | None = None) -> Iterator[tuple[int, int]]:
        """Rows ``first:last`` (default: all) in chunks; gathers stay inside them."""
        last = self.rows if last is None else last
        self._bound = last
        step = self.step()
        for start in range(first, last, step):
            yield start, min(start + step, last)

    def block(self, run: tuple[int, int, str], start: int, stop: int) -> np.ndarray:
        """Rows ``start:stop`` of a run as one C-ordered array, shape (rows, columns).

        The columns are gathered for many chunks at once (about GATHER_VALUES values, a
        few MB): gathering a wide table chunk by chunk would cost more than formatting it.
        """
        first, end, _ = run
        cached = self._gathered.get(first)
        if cached is None or not cached[0] <= start < stop <= cached[1]:
            rows = max(stop - start, GATHER_VALUES // (end - first))
            top = max(stop, min(self._bound, start + rows))
            cached = (start, top, np.stack([a[start:top] for a in self.arrays[first:end]],
                                           axis=1))
            self._gathered[first] = cached
        return cached[2][start - cached[0]:stop - cached[0]]


def _dump(block: np.ndarray) -> bytes:
    """orjson's text of a 2-D array: ``[[v,v],[v,v]]`` (NaN and infinities as null)."""
    import orjson

    return orjson.dumps(block, option=orjson.OPT_SERIALIZE_NUMPY)


def _csv_value(value: object) -> bytes:
    """One CSV field: empty for a missing value or an empty string, ``inf``,
    ``True``/``False``, a float as orjson writes it (as every other chunk), quoted when
    needed."""
    if value is None or value == "" or (isinstance(value, float) and np.isnan(value)):
        return b""
    if isinstance(value, float | np.floating):
        number = float(value)
        if np.isinf(number):
            return b"inf" if number > 0 else b"-inf"
        import orjson

        return orjson.dumps(number)  # the same text as the chunks without an infinity
    text = io.StringIO()
    csv.writer(text, lineterminator="").writerow([value])
    return text.getvalue().encode("utf-8")


def _json_value(value: object) -> bytes:
    """One JSON value: null for a missing value or a non-finite float."""
    import orjson

    if value is None or (isinstance(value, float | np.floating) and not np.isfinite(value)):
        return b"null"
    return orjson.dumps(value, option=orjson.OPT_SERIALIZE_NUMPY, default=str)


def _csv_lines(columns: _Columns, run: tuple[int, int, str], start: int, stop: int
               ) -> list[bytes]:
    """The fields of one run in rows ``start:stop``, one comma-joined line per row."""
    first, end, kind = run
    block = columns.block(run, start, stop) if kind != "o" else None
    if block is None or (kind == "f" and np.isinf(block).any()):
        return [b",".join(_csv_value(v) for v in row)
                for row in zip(*(a[start:stop] for a in columns.arrays[first:end]),
                               strict=True)]
    text = _dump(block)
    if kind == "f" and np.isnan(block).any():
        text = text.replace(b"null", b"")
    elif kind == "b":
        text = text.replace(b"true", b"True").replace(b"false", b"False")
    return _unbracket(text.split(b"],["), 2)


def _unbracket(items: list[bytes], brackets: int) -> list[bytes]:
    """The pieces of a split orjson text with its ``brackets`` opening and closing
    brackets taken off the ends (splitting the whole text, then trimming the first and
    last piece, spares a copy of the whole text)."""
    if len(items) == 1:
        items[0] = items[0][brackets:-brackets]
    else:
        items[0], items[-1] = items[0][brackets:], items[-1][:-brackets]
    return items


def _csv_chunk(columns: _Columns, start: int, stop: int) -> Part:
    """Rows ``start:stop`` as CSV lines (each ending in a newline), joined in Python."""
    if len(columns.runs) == 1 and columns.runs[0][2] == "f":  # floats only: no line split
        block = columns.block(columns.runs[0], start, stop)
        if not np.isinf(block).any():
            text = _dump(block)
            if np.isnan(block).any():
                text = text.replace(b"null", b"")
            return [memoryview(text.replace(b"],[", b"\n"))[2:-2], b"\n"]
    runs = [_csv_lines(columns, run, start, stop) for run in columns.runs]
    parts: list[bytes] = [b","] * (2 * len(runs) * (stop - start))
    for i, lines in enumerate(runs):
        parts[2 * i::2 * len(runs)] = lines
    parts[2 * len(runs) - 1::2 * len(runs)] = [b"\n"] * (stop - start)
    return [b"".join(parts)]


def write_csv(frame: pd.DataFrame, handle: BinaryIO) -> None:
    """``frame`` as CSV (header, then one line per row) into the binary ``handle``,
    formatted on every core for a large table (:mod:`mechloop.output.lines`)."""
    handle.write(b",".join(_csv_value(str(c)) for c in frame.columns) + b"\n")
    columns = _Columns(frame)
    if not columns.runs:
        handle.write(b"\n" * columns.rows)
        return
    if columns.compiled:
        columns.write_compiled(handle, [b""] + [b","] * (columns.width - 1), b"\n",
                               csv=True)
        return

    def render(first: int, last: int) -> Iterator[Part]:
        for start, stop in columns.chunks(first, last):
            yield _csv_chunk(columns, start, stop)

    _write_pieces(columns, handle, render)


def _write_pieces(columns: _Columns, handle: BinaryIO, render: Render) -> None:
    write_ordered(handle, columns.pieces(), render)


def _json_tokens(columns: _Columns, start: int, stop: int) -> list[bytes]:
    """Every value in rows ``start:stop`` as JSON text, row by row."""
    rows = stop - start
    tokens: list[bytes] = [b""] * (rows * columns.width)
    for run in columns.runs:
        first, end, kind = run
        if kind == "o":
            for j in range(first, end):
                tokens[j::columns.width] = [_json_value(v)
                                            for v in columns.arrays[j][start:stop]]
            continue
        found = _unbracket(_dump(columns.block(run, start, stop).ravel()).split(b","), 1)
        size = end - first
        if size == columns.width:
            return found
        if rows < size:  # few long rows: copy row by row
            for i in range(rows):
                at = i * columns.width + first
                tokens[at:at + size] = found[i * size:(i + 1) * size]
        else:  # many short rows: column by column
            for j in range(first, end):
                tokens[j::columns.width] = found[j - first::size]
    return tokens


def write_json(frame: pd.DataFrame, handle: BinaryIO) -> None:
    """``frame`` as a JSON list of records, one line per row, into ``handle``."""
    import orjson

    columns = _Columns(frame)
    if columns.rows == 0:
        handle.write(b"[]\n")
        return
    if columns.width == 0:
        handle.write(b"[\n" + b",\n".join([b"{}"] * columns.rows) + b"\n]\n")
        return
    keys = [orjson.dumps(str(c)) for c in frame.columns]
    opener = b"},\n{"
    prefixes = [opener + keys[0] + b":"] + [b"," + key + b":" for key in keys[1:]]
    handle.write(b"[\n")
    if columns.compiled:
        columns.write_compiled(handle, prefixes, b"", csv=False, skip=len(opener) - 1)
        handle.write(b"}\n]\n")
        return

    def render(first: int, last: int) -> Iterator[Part]:
        for start, stop in columns.chunks(first, last):
            parts: list[bytes] = [b""] * (2 * (stop - start) * columns.width)
            parts[0::2] = prefixes * (stop - start)
            parts[1::2] = _json_tokens(columns, start, stop)
            block = b"".join(parts)
            yield [memoryview(block)[len(opener) - 1:] if start == 0 else block]

    _write_pieces(columns, handle, render)
    handle.write(b"}\n]\n")
