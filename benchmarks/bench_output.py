"""Writing a large results table: CSV, JSON and Parquet by mechloop's streaming writers.

The model is ``--contours`` crank-rocker four-bars (default 200; crank 0.1 m, coupler
0.35 m + 0.5 mm per four-bar, rocker 0.25 m, frame 0.3 m), all driven by argument 1 over
``--positions`` positions (default 10^5): a table of positions x (3 + 9 per four-bar)
columns, 1,803 columns at the default, solved by ``mechloop.solve``.

Each format is written in a forked child process (the table is shared copy-on-write), so
its peak memory is its own: ``peak RSS`` is the child's ``ru_maxrss`` and ``above the
table`` that minus the resident size at the fork.  CSV and JSON are formatted in
compiled code by a thread per core while the writer's thread writes (``threads``:
how many the writer chose).  ``MB/CPU-s`` is the size over the CPU time of the writer's
threads together (how fast one free core formats; ``MB/s`` depends on the machine's load
and its free cores).  The file
is read back and checked against the table (its row count, and the first and last 1,000
rows bit for bit, read without loading the whole file) and removed.

    python benchmarks/bench_output.py                  # options: --contours 200
    python benchmarks/bench_output.py --contours 20 --positions 20000 --pandas
    python benchmarks/bench_output.py --contours 50 --threads all   # or one

``--pandas`` also times pandas' own ``to_csv`` and ``to_json`` (what mechloop used before)
for comparison.  ``--ecosystem`` times the library writers mechloop does not use, streamed
in chunks of about 2^20 values as mechloop's are and read back by the same check: polars'
``write_csv`` and ``write_ndjson`` (its ndjson joined into the list of records; NaN as an
empty field or null, booleans as ``True``/``False``, as mechloop writes them; polars is not
a dependency: ``pip install polars``) and Arrow's C++ CSV writer (``pyarrow.csv``; its own
text: ``1`` for ``1.0``, ``true``, quoted strings).  ``--disk-mb N`` first writes N MB of
ready text (1 MiB blocks) through the same atomic write, fsync included: the disk speed,
the most any writer can reach here.

The disk speed is also measured right after every mechloop format, in the same run: a
``disk`` line writes as many bytes of ready text as that format's file through the same
atomic write (1 MiB blocks, fsync included), and ``of disk`` is the format's MB/s over it
(1.00: the writer is as fast as the disk; ``--no-disk`` skips these lines).

The default size writes about 3.4 GB of CSV and 8 GB of JSON: see that the folder
(``--dir``, default the system temporary folder) has room.
"""

from __future__ import annotations

import argparse
import io
import json
import math
import os
import resource
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

import mechloop
from mechloop.output.tables import write_frame


def build_frame(contours: int, positions: int) -> pd.DataFrame:
    """The results table of ``contours`` four-bars at ``positions`` positions."""
    vectors: dict[int, dict] = {}
    loops = []
    for k in range(contours):
        base = 4 * k
        vectors[base + 1] = {"r": 0.1, "a": {"argument": 1}}
        vectors[base + 2] = {"r": 0.35 + 0.0005 * k, "a": "function"}
        vectors[base + 3] = {"r": 0.25, "a": "function"}
        vectors[base + 4] = {"r": 0.3, "a": math.pi}
        loops.append({"vectors": [base + 1, base + 2, base + 3, base + 4], "variant": 1})
    model = mechloop.Model.from_dict({
        "units": {"length": "m", "angle": "rad"},
        "positions": positions - 1,
        "time": {"rpm": 60},
        "arguments": {1: {"law": "constant_speed", "start": [0, 0.0],
                          "end": [positions - 1, 2.0 * math.pi]}},
        "vectors": vectors,
        "contours": loops,
    })
    return mechloop.solve(model).to_frame()


def _rss_mb() -> float:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20


def _maxrss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def _lines(path: Path, count: int) -> tuple[int, list[bytes], list[bytes]]:
    """Lines in the file, its first ``count`` and last ``count`` lines (read in blocks:
    the check holds no more of the file than that)."""
    total, head, tail = 0, [], b""
    with path.open("rb") as f:
        while block := f.read(1 << 26):
            total += block.count(b"\n")
            if len(head) < count:
                head = (b"".join(head) + block).split(b"\n")[:count]
            tail = (tail + block)[-(1 << 26):]
    return total, head, tail.split(b"\n")[-count - 1:-1]


def _read(path: Path, count: int) -> tuple[int, pd.DataFrame]:
    """Rows in the file and a frame of its first and last ``count`` rows."""
    if path.suffix == ".parquet":
        import pyarrow.parquet as pq

        f = pq.ParquetFile(path)
        sizes = [f.metadata.row_group(g).num_rows for g in range(f.num_row_groups)]
        first = next((g for g in range(len(sizes)) if sum(sizes[:g + 1]) >= count),
                     len(sizes) - 1)
        last = next((g for g in reversed(range(len(sizes))) if sum(sizes[g:]) >= count), 0)
        groups = sorted({*range(first + 1), *range(last, len(sizes))})
        table = f.read_row_groups(groups).to_pandas()
        if f.metadata.num_rows > 2 * count:
            table = pd.concat([table.iloc[:count], table.iloc[-count:]])
        return f.metadata.num_rows, table
    total, head, tail = _lines(path, count + 1)
    if path.suffix == ".csv":
        rows = total - 1
        lines = head if rows <= 2 * count else [*head, *tail[-count:]]
        return rows, pd.read_csv(io.BytesIO(b"\n".join(lines) + b"\n"), engine="pyarrow")
    import orjson  # one record per line between "[" and "]"

    rows = total - 2
    lines = head[1:rows + 1] if rows <= 2 * count else [*head[1:], *tail[:-1]]
    return rows, pd.DataFrame([orjson.loads(line.rstrip(b",")) for line in lines])


def _check(frame: pd.DataFrame, path: Path) -> str:
    count = 1000
    rows, back = _read(path, count)
    if rows != len(frame):
        return f"FAILED: {rows} rows instead of {len(frame)}"
    pick = (np.arange(len(frame)) if len(frame) <= 2 * count
            else np.r_[0:count, len(frame) - count:len(frame)])
    if list(back.columns) != [str(c) for c in frame.columns] or len(back) != len(pick):
        return "FAILED: columns or rows differ"
    for name in frame.columns:
        a = frame[name].to_numpy()[pick]
        b = back[str(name)].to_numpy()
        if a.dtype.kind == "f":
            same = np.array_equal(a.view(np.int64), b.astype(np.float64).view(np.int64))
        else:
            same = np.array_equal(a, b.astype(a.dtype))
        if not same:
            return f"FAILED: column {name} differs"
    return "first and last 1000 rows read back identical"


#: Values per chunk of the library writers (``--ecosystem``).
ECOSYSTEM_CHUNK = 1 << 20


def _chunks(frame: pd.DataFrame) -> list[tuple[int, int]]:
    step = max(1, ECOSYSTEM_CHUNK // max(1, len(frame.columns)))
    return [(s, min(s + step, len(frame))) for s in range(0, len(frame), step)]


def _polars(frame: pd.DataFrame, json_nulls: bool):
    """A chunk as polars frame with mechloop's conventions: NaN (and, for JSON,
    infinities) null, booleans ``True``/``False`` for CSV."""
    import polars as pl

    data = pl.from_pandas(frame)
    fixes = []
    for name, dtype in data.schema.items():
        col = pl.col(name)
        if dtype.is_float():
            fixes.append(pl.when(col.is_finite()).then(col) if json_nulls
                         else col.fill_nan(None))
        elif dtype == pl.Boolean and not json_nulls:
            fixes.append(pl.when(col).then(pl.lit("True")).otherwise(pl.lit("False"))
                         .alias(name))
    return data.with_columns(fixes) if fixes else data


def write_polars(frame: pd.DataFrame, path: Path) -> None:
    """``frame`` by polars, chunk after chunk: CSV, or JSON as a list of records."""
    with path.open("wb") as handle:
        if path.suffix == ".csv":
            for start, stop in _chunks(frame):
                _polars(frame.iloc[start:stop], False).write_csv(
                    handle, include_header=start == 0)
            return
        handle.write(b"[\n")
        for start, stop in _chunks(frame):
            text = io.BytesIO()
            _polars(frame.iloc[start:stop], True).write_ndjson(text)
            handle.write((b",\n" if start else b"")
                         + text.getvalue()[:-1].replace(b"\n", b",\n"))
        handle.write(b"\n]\n")


def write_arrow(frame: pd.DataFrame, path: Path) -> None:
    """``frame`` by Arrow's C++ CSV writer (multi-threaded), chunk after chunk."""
    import pyarrow as pa
    import pyarrow.csv as pc

    schema = pa.Schema.from_pandas(frame, preserve_index=False)
    with pc.CSVWriter(str(path), schema) as writer:
        for start, stop in _chunks(frame):
            writer.write_table(pa.Table.from_pandas(frame.iloc[start:stop], schema=schema,
                                                    preserve_index=False))


def write_disk(path: Path, size: int) -> None:
    """``size`` bytes of ready text written through the atomic write, as the table
    writers write (fsync included), in blocks of 1 MiB: the disk speed.

    A block of 1 MiB (the atomic handle's buffer) stays in a core's L2 cache (1.25 MiB on
    the development machine) from one write to the next; blocks of 8 MiB, copied from the
    shared L3 cache or from memory, took two to five times the CPU time under load
    (1.0-2.9 against 0.35-0.8 CPU-s for 1.5 GB), so the disk line was slower than a writer
    that writes small pages."""
    from mechloop.output.atomic import atomic_file

    block = (b"0.30000000000000004," * (1 << 16))[:1 << 20]
    with atomic_file(path) as handle:
        for start in range(0, size, len(block)):
            handle.write(memoryview(block)[:min(len(block), size - start)])


def run_child(frame: pd.DataFrame, path: Path, how: str, disk_bytes: int = 0) -> dict:
    """Write in a forked child; its seconds, peak memory and check."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: report, and never return into the parent's code
        try:
            os.close(read)
            start_rss = _rss_mb()
            cpu0 = {who: resource.getrusage(who)
                    for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)}
            t0 = time.perf_counter()
            if how == "mechloop":
                write_frame(frame, path)
            elif how == "disk":
                write_disk(path, disk_bytes)
            elif how == "polars":
                write_polars(frame, path)
            elif how == "arrow":
                write_arrow(frame, path)
            elif path.suffix == ".csv":
                frame.to_csv(path, index=False)
            else:
                frame.to_json(path, orient="records", double_precision=15)
            seconds = time.perf_counter() - t0
            cpu = sum(getattr(resource.getrusage(who), f) - getattr(cpu0[who], f)
                      for who in cpu0 for f in ("ru_utime", "ru_stime"))
            peak = _maxrss_mb()
            verdict = ("" if how == "pandas" else "disk speed" if how == "disk"
                       else _check(frame, path))
            report = {"seconds": seconds, "cpu": cpu, "peak": peak, "above": peak - start_rss,
                      "size": path.stat().st_size, "check": verdict}
            os.write(write, json.dumps(report).encode())
        except BaseException as exc:
            os.write(write, json.dumps({"check": f"FAILED: {exc!r}"}).encode())
        finally:
            os._exit(0)
    os.close(write)
    data = b""
    os.set_blocking(read, False)
    while True:
        try:
            chunk = os.read(read, 65536)
        except BlockingIOError:
            time.sleep(0.02)
            continue
        if not chunk:
            break
        data += chunk
    os.close(read)
    os.waitpid(pid, 0)
    report = json.loads(data) if data else {"check": "FAILED: the child died"}
    return report


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--contours", type=int, default=200, help="four-bars (default 200)")
    parser.add_argument("--positions", type=int, default=100_000,
                        help="rows (default 100000)")
    parser.add_argument("--formats", default="csv,json,parquet",
                        help="comma-separated (default csv,json,parquet)")
    parser.add_argument("--dir", default=None, help="where to write (default: temp folder)")
    parser.add_argument("--pandas", action="store_true",
                        help="also time pandas' to_csv and to_json")
    parser.add_argument("--disk-mb", type=int, default=0,
                        help="first write this many MB of ready text: the disk speed")
    parser.add_argument("--no-disk", action="store_true",
                        help="skip the disk speed after each mechloop format")
    parser.add_argument("--ecosystem", action="store_true",
                        help="also time polars' write_csv/write_ndjson and Arrow's C++ "
                        "CSV writer")
    parser.add_argument("--threads", choices=("auto", "all", "one"), default="auto",
                        help="CSV/JSON formatting threads: auto or all (one per core, as "
                        "mechloop does), one")
    args = parser.parse_args()
    from mechloop.output import tables

    if args.threads == "one":
        tables.threads_for = lambda values: 1

    t0 = time.perf_counter()
    frame = build_frame(args.contours, args.positions)
    print(f"{args.contours} four-bars x {args.positions} positions: {len(frame)} rows x "
          f"{len(frame.columns)} columns ({frame.memory_usage().sum() / 2**20:.0f} MB in "
          f"memory), built in {time.perf_counter() - t0:.1f} s; resident "
          f"{_rss_mb():.0f} MB")
    cells = len(frame) * len(frame.columns)
    print(f"threads ({args.threads}): {tables.threads_for(cells)} for "
          f"CSV and JSON; load average {os.getloadavg()[0]:.1f} on "
          f"{len(os.sched_getaffinity(0))} cores")
    runs = [("disk", "csv")] if args.disk_mb else []
    runs += [("mechloop", f) for f in args.formats.split(",")]
    if args.pandas:
        runs += [("pandas", f) for f in ("csv", "json") if f in args.formats.split(",")]
    if args.ecosystem:
        runs += [(how, f) for how, f in (("polars", "csv"), ("arrow", "csv"),
                                         ("polars", "json"))
                 if f in args.formats.split(",")]
    failed = False
    print(f"{'writer':<10} {'format':<8} {'seconds':>8} {'MB':>8} {'MB/s':>7} "
          f"{'MB/CPU-s':>9} "
          f"{'peak RSS MB':>12} {'above table MB':>15} {'of disk':>8}  "
          "check")
    with tempfile.TemporaryDirectory(dir=args.dir) as folder:
        for how, fmt in runs:
            path = Path(folder) / f"table.{fmt}"
            r = run_child(frame, path, how, args.disk_mb * 2**20)
            path.unlink(missing_ok=True)
            if "seconds" not in r:
                print(f"{how:<10} {fmt:<8} {r['check']}")
                failed = True
                continue
            disk = None
            if how == "mechloop" and not args.no_disk:  # the same bytes, ready: the disk
                disk = run_child(frame, path, "disk", r["size"])
                path.unlink(missing_ok=True)
            mb = r["size"] / 2**20
            ratio = (f"{mb / r['seconds'] / (mb / disk['seconds']):8.2f}"
                     if disk and "seconds" in disk else f"{'':8}")
            print(f"{how:<10} {fmt:<8} {r['seconds']:8.1f} {mb:8.0f} "
                  f"{mb / r['seconds']:7.0f} {mb / r['cpu']:9.0f} {r['peak']:12.0f} "
                  f"{r['above']:15.0f} {ratio}  {r['check']}")
            failed |= r["check"].startswith("FAILED")
            if disk:
                if "seconds" not in disk:
                    print(f"{'disk':<10} {fmt:<8} {disk['check']}")
                    failed = True
                    continue
                print(f"{'disk':<10} {fmt:<8} {disk['seconds']:8.1f} {mb:8.0f} "
                      f"{mb / disk['seconds']:7.0f} {mb / disk['cpu']:9.0f} "
                      f"{disk['peak']:12.0f} {disk['above']:15.0f} "
                      f"{'':8}  the same bytes, ready")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
