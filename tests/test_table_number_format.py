"""Every double the CSV and JSON writers write, property-tested: the writers' text is
byte for byte the text built value by value (orjson's form of each float — the form the
writers have always used —, an empty CSV field or JSON null for NaN, ``inf`` in CSV, the
same header, the same record layout), whatever the chunking; every number reads back to
the same bits; and its digits are the shortest that do (the digits and exponent of
Python's repr, an independent shortest round-trip algorithm, David Gay's)."""

from __future__ import annotations

import io
import json
import re
from unittest import mock

import numpy as np
import orjson
import pandas as pd
from hypothesis import given, settings
from hypothesis import strategies as st

from mechloop.output import lines, tables

#: Doubles of every kind: any bit pattern (subnormals, huge and tiny exponents, NaN with
#: any payload, infinities, -0.0), integer-valued floats, and round decimals.
DOUBLES = st.one_of(
    st.integers(0, 2**64 - 1).map(lambda b: float(np.array(b, np.uint64).view(np.float64))),
    st.floats(allow_nan=True, allow_infinity=True, allow_subnormal=True),
    st.integers(-(2**60), 2**60).map(float),
    st.integers(-10**6, 10**6).map(lambda k: k / 10.0 ** (abs(k) % 23)),
    st.sampled_from([0.0, -0.0, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                     1e-5, 1e-7, 1e15, 1e16, 1e21, 1e22, 0.1 + 0.2, 9007199254740993.0]),
)


def _frame(data: st.DataObject) -> pd.DataFrame:
    rows = data.draw(st.integers(1, 40), label="rows")
    width = data.draw(st.integers(1, 6), label="float columns")
    values = data.draw(st.lists(DOUBLES, min_size=rows * width, max_size=rows * width),
                       label="values")
    floats = np.array(values, dtype=np.float64).reshape(rows, width)
    frame = pd.DataFrame({"position": np.arange(rows) - 3})
    for j in range(width):
        frame[f"a{j} [rad]"] = floats[:, j]
    if data.draw(st.booleans(), label="bool column"):
        frame["chain_break"] = np.isnan(floats).any(axis=1)
    if data.draw(st.booleans(), label="int column between floats"):
        frame.insert(2, "k", np.arange(rows) * 7)
    return frame


def _written(writer, frame: pd.DataFrame, chunk: int, woven: bool) -> bytes:
    """The text ``writer`` writes, in chunks (blocks) of about ``chunk`` values, formatted
    in compiled code (:mod:`mechloop.output.lines`, as for large tables) or by orjson and
    joined in Python."""
    with mock.patch.object(tables, "CHUNK_VALUES", chunk), \
            mock.patch.object(tables, "GATHER_VALUES", 3 * chunk + 1), \
            mock.patch.object(lines, "BLOCK_VALUES", chunk), \
            mock.patch.object(tables, "_compiled", lambda values: woven):
        handle = io.BytesIO()
        writer(frame, handle)
    return handle.getvalue()


def _csv_field(value: object) -> bytes:
    if isinstance(value, bool | np.bool_):
        return b"True" if value else b"False"
    if isinstance(value, int | np.integer):
        return str(int(value)).encode()
    value = float(value)
    if np.isnan(value):
        return b""
    return orjson.dumps(value) if np.isfinite(value) else repr(value).encode()


def _json_value(value: object) -> object:
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, int | np.integer):
        return int(value)
    return float(value) if np.isfinite(value) else None


def _shortest(text: str, value: float) -> None:
    """``text`` reads back to ``value`` bit for bit, with the digits and exponent of
    Python's repr (the shortest round-trip form)."""
    assert np.float64(float(text)).view(np.int64) == np.float64(value).view(np.int64), text

    def digits(number: str) -> tuple[str, int]:
        sign = number.startswith("-")
        mantissa, _, exponent = number.lstrip("-").partition("e")
        whole, _, part = mantissa.partition(".")
        figures = (whole + part).lstrip("0")
        point = len(whole) - (len(whole + part) - len((whole + part).lstrip("0")))
        return ("-" if sign else "") + (figures.rstrip("0") or "0"), \
            int(exponent or 0) + point if figures else 0

    assert digits(text) == digits(repr(value)), (text, repr(value))


@settings(max_examples=40, deadline=None)
@given(st.data(), st.sampled_from([1, 7, 1 << 12]), st.booleans())
def test_csv_is_the_text_built_value_by_value(data, chunk, woven):
    frame = _frame(data)
    got = _written(tables.write_csv, frame, chunk, woven)
    header = b",".join(str(c).encode() for c in frame.columns)
    lines = [b",".join(_csv_field(v) for v in row) for row in frame.itertuples(index=False)]
    assert got == b"\n".join([header, *lines]) + b"\n"
    for name in frame.columns:
        if frame[name].dtype.kind != "f":
            continue
        column = [line.split(",")[frame.columns.get_loc(name)]
                  for line in got.decode().splitlines()[1:]]
        for text, value in zip(column, frame[name], strict=True):
            if np.isnan(value):
                assert text == ""
            elif np.isinf(value):
                assert text == repr(value)
            else:
                _shortest(text, value)


@settings(max_examples=40, deadline=None)
@given(st.data(), st.sampled_from([1, 7, 1 << 12]), st.booleans())
def test_json_is_the_text_built_value_by_value(data, chunk, woven):
    frame = _frame(data)
    got = _written(tables.write_json, frame, chunk, woven)
    records = [orjson.dumps({str(c): _json_value(v) for c, v in zip(frame.columns, row,
                                                                     strict=True)})
               for row in frame.itertuples(index=False)]
    assert got == b"[\n" + b",\n".join(records) + b"\n]\n"
    back = json.loads(got)
    for name in frame.columns:
        if frame[name].dtype.kind != "f":
            continue
        for record, value in zip(back, frame[name], strict=True):
            if not np.isfinite(value):
                assert record[name] is None
        texts = re.findall(rb'"' + re.escape(name.encode()) + rb'":([^,}]*)', got)
        for text, value in zip(texts, frame[name], strict=True):
            if np.isfinite(value):
                _shortest(text.decode(), value)
