"""The Parquet writer: the schema says which columns can be missing (a column of numbers
without NaN is required, NaN is null), statistics and dictionaries only where they are
cheap, the same bytes through Arrow's own file as through a Python buffer, and a failure
halfway leaves the old file and nothing else."""

from __future__ import annotations

import io

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from helpers.bits import same_bits

from mechloop.output import parquet
from mechloop.output.tables import write_frame


@pytest.fixture(autouse=True)
def small_groups(monkeypatch):
    """Row groups of 4 rows (6 columns) and pages of a few values, so that every test
    crosses group and page boundaries."""
    monkeypatch.setattr(parquet, "PARQUET_GROUP_VALUES", 24)
    monkeypatch.setattr(parquet, "PARQUET_BATCH_VALUES", 2)
    monkeypatch.setattr(parquet, "PARQUET_PAGE_VALUES", 3)


def _frame(rows: int = 23) -> pd.DataFrame:
    """Int positions, a float column with every awkward double but no NaN, one with NaN
    in a late group only, one with NaN in the first row only, a bool mark, strings."""
    special = np.array([5e-324, 1.7976931348623157e308, -0.0, 1 / 3, 0.1 + 0.2, np.inf,
                        -np.inf, 2.0**-1074 * 3, -1e22, 1.0])
    exact = np.resize(np.concatenate([special, -special]), rows)
    late = np.linspace(-1.0, 1.0, rows)
    late[rows - 2] = np.nan
    first = np.geomspace(1e-300, 1e300, rows)
    first[0] = np.nan
    return pd.DataFrame({
        "position": np.arange(rows), "exact [m]": exact, "late [rad]": late,
        "first [N]": first, "chain_break": np.isnan(late),
        "note": [f"row {i}" if i % 3 else None for i in range(rows)],
    })


def test_columns_without_nan_are_required_and_nan_is_null(tmp_path):
    frame = _frame()
    write_frame(frame, tmp_path / "t.parquet")
    file = pq.ParquetFile(tmp_path / "t.parquet")
    assert file.metadata.num_row_groups == 6  # 23 rows in groups of 4
    schema = file.schema_arrow
    assert {f.name: f.nullable for f in schema} == {
        "position": False, "exact [m]": False, "late [rad]": True, "first [N]": True,
        "chain_break": False, "note": True}
    assert schema.pandas_metadata == pa.Schema.from_pandas(frame, preserve_index=False
                                                           ).pandas_metadata
    table = file.read()
    assert table.column("late [rad]").null_count == 1
    assert table.column("first [N]").null_count == 1
    assert table.column("note").null_count == 8
    back = table.to_pandas()
    assert list(back.columns) == list(frame.columns)
    for name in ("exact [m]", "late [rad]", "first [N]"):
        assert same_bits(frame[name], back[name]), name
    assert back["position"].dtype == np.int64 and back["chain_break"].dtype == bool
    assert back["position"].tolist() == frame["position"].tolist()
    assert back["chain_break"].tolist() == frame["chain_break"].tolist()
    assert back["note"].tolist() == frame["note"].tolist()


def test_statistics_and_dictionaries_only_where_they_are_cheap(tmp_path):
    """Min/max statistics cost as much as the encoding for doubles: kept for the other
    columns; a dictionary only for strings; pages of at most PARQUET_PAGE_VALUES values."""
    write_frame(_frame(), tmp_path / "t.parquet")
    meta = pq.ParquetFile(tmp_path / "t.parquet").metadata
    group = meta.row_group(1)
    columns = {group.column(i).path_in_schema: group.column(i) for i in range(6)}
    assert {name: c.statistics is not None for name, c in columns.items()} == {
        "position": True, "exact [m]": False, "late [rad]": False, "first [N]": False,
        "chain_break": True, "note": True}
    assert (columns["position"].statistics.min, columns["position"].statistics.max) == (4, 7)
    assert {name: c.has_dictionary_page for name, c in columns.items()} == {
        "position": False, "exact [m]": False, "late [rad]": False, "first [N]": False,
        "chain_break": False, "note": True}
    assert all(c.compression == "UNCOMPRESSED" for c in columns.values())


def test_a_python_buffer_gets_the_same_bytes_as_a_file(tmp_path, monkeypatch):
    """Arrow writes the file itself (by its /proc link) where it can; into a buffer, a
    file already written into, or a file it may not open, through the handle: the same
    bytes every way."""
    frame = _frame()
    write_frame(frame, tmp_path / "t.parquet")
    expected = (tmp_path / "t.parquet").read_bytes()
    buffer = io.BytesIO()
    parquet.write_parquet(frame, buffer)
    assert buffer.getvalue() == expected
    with open(tmp_path / "after.bin", "wb") as handle:  # after other content: appended
        handle.write(b"head")
        parquet.write_parquet(frame, handle)
    assert (tmp_path / "after.bin").read_bytes() == b"head" + expected
    with open(tmp_path / "before.bin", "wb") as handle:  # Arrow's own file, then more
        parquet.write_parquet(frame, handle)
        handle.write(b"tail")
    assert (tmp_path / "before.bin").read_bytes() == expected + b"tail"

    def refused(path, mode):
        raise PermissionError(13, "Permission denied", path)

    monkeypatch.setattr(pa, "OSFile", refused)  # e.g. a umask taking the owner's write bit
    write_frame(frame, tmp_path / "refused.parquet")
    assert (tmp_path / "refused.parquet").read_bytes() == expected


def test_a_failure_halfway_leaves_the_old_file_and_nothing_else(tmp_path, monkeypatch):
    real = pq.ParquetWriter.write_table
    calls = []

    def failing(self, table, *args, **kwargs):
        calls.append(len(table))
        if len(calls) == 3:
            raise ValueError("encoding failed in the third row group")
        return real(self, table, *args, **kwargs)

    monkeypatch.setattr(pq.ParquetWriter, "write_table", failing)
    target = tmp_path / "t.parquet"
    target.write_bytes(b"old")
    with pytest.raises(ValueError, match="third row group"):
        write_frame(_frame(), target)
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["t.parquet"]


def test_an_empty_or_string_only_table(tmp_path):
    for frame in (_frame().iloc[:0], pd.DataFrame({"name": ["a", None, "c"]}), pd.DataFrame()):
        write_frame(frame, tmp_path / "t.parquet")
        back = pd.read_parquet(tmp_path / "t.parquet")
        assert list(back.columns) == list(frame.columns) and len(back) == len(frame)
