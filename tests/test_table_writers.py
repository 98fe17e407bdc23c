"""The streaming table writers: every value reads back bit for bit, broken rows stay
empty (CSV) or null (JSON) as pandas wrote them before, chunk and type boundaries do not
show, and an Excel sheet too large is refused before anything is written."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from helpers.bits import same_bits
from typer.testing import CliRunner

from mechloop.cli import app
from mechloop.output import OutputError, lines, parallel, parquet, tables
from mechloop.output.tables import check_table_size, write_frame

ROOT = Path(__file__).resolve().parents[1]


def _frame(rows: int = 53) -> pd.DataFrame:
    """A results-like table: int position, float columns holding every awkward double
    (subnormal, huge, -0.0, 1/3, values needing 17 digits), NaN in broken rows, a bool
    mark, a float run cut by a string column."""
    rng = np.random.default_rng(7)
    broken = np.zeros(rows, bool)
    broken[[3, 4, 40]] = True
    special = np.array([5e-324, 1.7976931348623157e308, -0.0, 1 / 3, 0.1 + 0.2, 1e-7,
                        123456789.12345679, 2.0**-1074 * 3, -1e22, 1.0])
    a = rng.normal(size=rows) * 10.0 ** rng.integers(-12, 12, rows)
    a[: len(special)] = special
    b = rng.standard_cauchy(rows)
    a[broken] = b[broken] = np.nan
    return pd.DataFrame({
        "position": np.arange(rows), "time [s]": np.linspace(0, 0.5, rows),
        "a2 [deg]": a, "da2 [rad/s]": b,
        "note": ["" if i % 5 else f"row {i}, \"quoted\"" for i in range(rows)],
        "dda2 [rad/s^2]": rng.uniform(-1, 1, rows),
        "chain_break": broken,
    })


@pytest.fixture(autouse=True, params=["compiled, 1 thread", "compiled, 3 threads"])
def small_chunks(monkeypatch, request):
    """Chunks of a few rows and gathers of a few chunks (not a whole number of them), so
    that every test crosses chunk and gather boundaries; lines formatted in compiled code
    as for a large table where no column holds strings (orjson's Python joins:
    test_table_number_format.py), in blocks of a few rows by one thread or by three (each
    test runs both ways)."""
    monkeypatch.setattr(tables, "CHUNK_VALUES", 20)
    monkeypatch.setattr(tables, "GATHER_VALUES", 45)
    monkeypatch.setattr(tables, "PIECE_VALUES", 70)
    monkeypatch.setattr(parquet, "PARQUET_GROUP_VALUES", 30)
    monkeypatch.setattr(lines, "BLOCK_VALUES", 25)
    monkeypatch.setattr(tables, "_compiled", lambda values: True)  # as for a large table
    threads = 3 if request.param.endswith("3 threads") else 1
    monkeypatch.setattr(tables, "threads_for", lambda values: threads)


def test_csv_reads_back_bit_for_bit_and_as_pandas_wrote_it(tmp_path):
    frame = _frame()
    write_frame(frame, tmp_path / "t.csv")
    text = (tmp_path / "t.csv").read_text()
    back = pd.read_csv(tmp_path / "t.csv", engine="pyarrow")
    before = pd.read_csv(pd.io.common.StringIO(frame.to_csv(index=False)))
    assert list(back.columns) == list(frame.columns)
    assert dict(back.dtypes) == dict(before.dtypes)  # same types as the old writer gave
    for name in ("time [s]", "a2 [deg]", "da2 [rad/s]", "dda2 [rad/s^2]"):
        assert same_bits(frame[name], back[name]), name
    assert back["position"].tolist() == frame["position"].tolist()
    assert back["chain_break"].tolist() == frame["chain_break"].tolist()
    assert back["note"].fillna("").tolist() == frame["note"].tolist()
    lines = text.splitlines()
    assert lines[0] == "position,time [s],a2 [deg],da2 [rad/s],note,dda2 [rad/s^2],chain_break"
    assert lines[1 + 3].split(",")[2:4] == ["", ""]  # a broken row: empty, as before
    assert lines[1 + 3].endswith(",True") and lines[1 + 2].endswith(",False")
    assert '"row 5, ""quoted"""' in lines[1 + 5]
    assert len(lines) == 1 + len(frame)


def test_json_is_the_old_list_of_records_with_exact_values(tmp_path):
    frame = _frame()
    write_frame(frame, tmp_path / "t.json")
    records = json.loads((tmp_path / "t.json").read_text())
    old = json.loads(frame.to_json(orient="records", double_precision=15))
    assert len(records) == len(old) == len(frame)
    for new, was in zip(records, old, strict=True):
        assert list(new) == list(was)
        assert [type(v) for v in new.values()] == [type(v) for v in was.values()]
    for name in ("time [s]", "a2 [deg]", "da2 [rad/s]", "dda2 [rad/s^2]"):
        got = np.array([np.nan if r[name] is None else r[name] for r in records])
        assert same_bits(frame[name], got), name
    assert records[3]["a2 [deg]"] is None and records[3]["chain_break"] is True
    assert [r["note"] for r in records] == frame["note"].tolist()


def test_parquet_keeps_types_and_values(tmp_path):
    frame = _frame()
    write_frame(frame, tmp_path / "t.parquet")
    back = pd.read_parquet(tmp_path / "t.parquet")
    assert list(back.columns) == list(frame.columns)
    for name in frame.columns:
        if frame[name].dtype.kind == "f":
            assert same_bits(frame[name], back[name]), name
        else:
            assert back[name].tolist() == frame[name].tolist(), name
    assert back["position"].dtype == np.int64 and back["chain_break"].dtype == bool


def test_an_infinity_reads_back_in_csv(tmp_path):
    frame = pd.DataFrame({"x": [1.0, np.inf, -np.inf, np.nan]})
    write_frame(frame, tmp_path / "t.csv")
    assert (tmp_path / "t.csv").read_text() == "x\n1.0\ninf\n-inf\n\n"


def test_a_chunk_with_an_infinity_formats_its_numbers_as_every_other_chunk(tmp_path):
    values = [1e-05, 1.5e300, 0.1, 2.0, -3.25e-12]
    plain = pd.DataFrame({"x": values, "y": values})
    mixed = pd.DataFrame({"x": [*values, np.inf], "y": [*values, 1.0]})
    write_frame(plain, tmp_path / "plain.csv")
    write_frame(mixed, tmp_path / "mixed.csv")
    plain_rows = (tmp_path / "plain.csv").read_text().splitlines()
    mixed_rows = (tmp_path / "mixed.csv").read_text().splitlines()
    assert mixed_rows[:-1] == plain_rows
    assert mixed_rows[-1] == "inf,1.0"
    assert [float(v) for v in mixed_rows[1].split(",")] == [1e-05, 1e-05]


@pytest.mark.parametrize("suffix", [".csv", ".json", ".parquet", ".xlsx"])
def test_empty_tables(tmp_path, suffix):
    frame = pd.DataFrame({"position": np.arange(0), "x": np.zeros(0)})
    write_frame(frame, tmp_path / f"t{suffix}")
    if suffix == ".json":
        assert json.loads((tmp_path / "t.json").read_text()) == []
    elif suffix == ".csv":
        assert (tmp_path / "t.csv").read_text() == "position,x\n"


def test_xlsx_past_its_limits_is_refused_before_writing(tmp_path):
    with pytest.raises(OutputError) as caught:
        check_table_size(1_048_576, 3, tmp_path / "t.xlsx")
    assert "1,048,575 rows under the header" in str(caught.value)
    assert ".csv or .parquet" in str(caught.value)
    with pytest.raises(OutputError):
        check_table_size(10, 16_385, tmp_path / "t.xlsx")
    check_table_size(1_048_575, 16_384, tmp_path / "t.xlsx")  # the largest that fits
    check_table_size(10**7, 10**5, tmp_path / "t.csv")  # CSV and Parquet have no limit
    wide = pd.DataFrame(np.zeros((1, 16_385)))
    with pytest.raises(OutputError):
        write_frame(wide, tmp_path / "wide.xlsx")
    assert not list(tmp_path.iterdir())


def test_solve_refuses_xlsx_for_too_many_positions_before_solving(tmp_path, monkeypatch):
    model = tmp_path / "m.yaml"
    text = (ROOT / "examples" / "four_bar.yaml").read_text()
    model.write_text(text.replace("positions: 72", "positions: 1048576")
                     .replace("72: 360", "1048576: 360"))

    def no_solve(*args, **kwargs):
        raise AssertionError("solved before the table size was checked")

    import importlib

    kinematics = importlib.import_module("mechloop.solve.kinematics")
    monkeypatch.setattr(kinematics, "solve", no_solve)
    result = CliRunner().invoke(app, ["solve", str(model), "-o", str(tmp_path / "r.xlsx")])
    assert result.exit_code == 2, result.output
    assert "do not fit an Excel sheet" in result.output and ".parquet" in result.output


@pytest.mark.parametrize("suffix", [".csv", ".json", ".parquet", ".xlsx"])
def test_solve_writes_every_format_with_the_same_values(tmp_path, suffix):
    model = tmp_path / "m.yaml"
    shutil.copy(ROOT / "examples" / "four_bar.yaml", model)
    out = tmp_path / f"r{suffix}"
    result = CliRunner().invoke(app, ["solve", str(model), "-o", str(out)])
    assert result.exit_code == 0, result.output
    import mechloop

    frame = mechloop.solve(mechloop.load_model(model)).to_frame()
    back = {".csv": lambda p: pd.read_csv(p, engine="pyarrow"),
            ".json": lambda p: pd.DataFrame(json.loads(p.read_text())),
            ".parquet": pd.read_parquet, ".xlsx": pd.read_excel}[suffix](out)
    assert list(back.columns) == list(frame.columns)
    for name in frame.columns:
        if frame[name].dtype.kind == "f" and suffix != ".xlsx":
            assert same_bits(frame[name], back[name]), name
        else:
            assert np.allclose(back[name].astype(float), frame[name].astype(float),
                               rtol=1e-15, equal_nan=True), name


@pytest.mark.parametrize("suffix", [".csv", ".json"])
def test_a_pipe_or_a_buffer_gets_the_same_text_as_a_file(tmp_path, suffix):
    """The writers also write into a pipe (spliced into, as a file is) and into a Python
    buffer without a file descriptor (read and written), byte for byte as into a file."""
    import io
    import threading

    frame = _frame()
    write_frame(frame, tmp_path / f"t{suffix}")
    expected = (tmp_path / f"t{suffix}").read_bytes()
    writer = tables.write_csv if suffix == ".csv" else tables.write_json
    buffer = io.BytesIO()
    writer(frame, buffer)
    assert buffer.getvalue() == expected
    read, write = os.pipe()
    received: list[bytes] = []
    reader = threading.Thread(target=lambda: received.append(os.fdopen(read, "rb").read()))
    reader.start()
    with open(write, "wb") as handle:
        writer(frame, handle)
    reader.join(timeout=30)
    assert received == [expected]


@pytest.mark.parametrize("numbers_only", [True, False])
def test_a_failing_format_is_raised_and_leaves_nothing(tmp_path, monkeypatch, numbers_only):
    """A failure while formatting (in a formatting thread, or in Python for a table with
    strings) reaches the caller; the old file stays, no temporary file is left and no
    formatting thread goes on."""
    import threading

    real_lines, real_chunk = lines.Lines.__call__, tables._csv_chunk

    def failing_lines(self, start, stop, out=None):
        if start >= 40:
            raise ValueError("formatting failed at row 40")
        return real_lines(self, start, stop, out)

    def failing_chunk(columns, start, stop):
        if start >= 40:
            raise ValueError("formatting failed at row 40")
        return real_chunk(columns, start, stop)

    monkeypatch.setattr(lines.Lines, "__call__", failing_lines)
    monkeypatch.setattr(tables, "_csv_chunk", failing_chunk)
    target = tmp_path / "t.csv"
    target.write_bytes(b"old\n")
    frame = _frame(300)
    if numbers_only:
        frame = frame.drop(columns="note")
    with pytest.raises(ValueError, match="formatting failed at row 40"):
        write_frame(frame, target)
    assert target.read_bytes() == b"old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]
    assert not [t for t in threading.enumerate() if t.name.startswith("mechloop-lines")]


@pytest.mark.parametrize("rows", [1, 2])
@pytest.mark.parametrize("columns", [["x"], ["i", "x", "b"], ["x", "y"]])
def test_one_or_two_rows_and_single_columns(tmp_path, rows, columns):
    """The brackets of orjson's text come off a one-value run too."""
    whole = pd.DataFrame({"i": np.arange(rows) + 7, "x": np.arange(rows) + 0.5,
                          "y": -np.arange(rows) / 3, "b": np.arange(rows) % 2 == 0})
    frame = whole[columns]
    write_frame(frame, tmp_path / "t.csv")
    assert (tmp_path / "t.csv").read_text() == frame.to_csv(index=False)
    write_frame(frame, tmp_path / "t.json")
    expected = [{k: getattr(v, "item", lambda v=v: v)() for k, v in r.items()}
                for r in frame.to_dict("records")]
    back = json.loads((tmp_path / "t.json").read_text())
    assert back == expected
    assert [[type(v) for v in r.values()] for r in back] == [
        [type(v) for v in r.values()] for r in expected]


def test_threads_for_every_core_whatever_the_load(monkeypatch):
    """A formatting thread per core the process may use, whatever the load average or
    the threads running, at least one, and not more than one per 2^16 values."""
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: set(range(4)), raising=False)
    for load in (0.0, 1.4, 9.0):
        monkeypatch.setattr(os, "getloadavg", lambda load=load: (load, load, load))
        monkeypatch.setattr(parallel, "running_threads", lambda: 7)
        assert parallel.threads_for(10**6) == 4, load
    assert parallel.threads_for(3 << 16) == 3 and parallel.threads_for(10) == 1
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: set(range(64)), raising=False)
    assert parallel.threads_for(10**8) == parallel.MAX_THREADS


def test_tables_of_every_size_are_the_same_text_compiled_or_not(tmp_path, monkeypatch):
    """The compiled lines and orjson's Python joins write the same bytes, for tables of
    one block or many, CSV and JSON."""
    for rows in (1, 7, 300):
        frame = _frame(max(rows, 53)).iloc[:rows].drop(columns="note")
        for suffix in (".csv", ".json"):
            texts = []
            for compiled in (True, False):
                monkeypatch.setattr(tables, "_compiled", lambda values, c=compiled: c)
                write_frame(frame, tmp_path / f"t{suffix}")
                texts.append((tmp_path / f"t{suffix}").read_bytes())
            assert texts[0] == texts[1], (rows, suffix)
