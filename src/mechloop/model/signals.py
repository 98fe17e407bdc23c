"""Values over calculation positions as a model file states them: tables (sparse, filled by
KDAM's rules), motion laws, and the model time.  Shared by model arguments and by loads.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Discriminator, Field, Tag, model_serializer

from mechloop.model.numbers import (  # noqa: F401  (QuantityText, Scalar: re-exported)
    MAX_MAGNITUDE,
    RANGE,
    Number,
    QuantityText,
    Scalar,
    UnitName,
)

#: Largest ``positions`` (N) of a model: 10⁸ positions; what a solve needs in memory is
#: checked against the machine before solving (:func:`mechloop.solve.memory.require_memory`).
MAX_POSITIONS = 100_000_000


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


def _table_tag(value: Any) -> str | None:
    if isinstance(value, dict):
        return "mapping"
    if isinstance(value, list | tuple):
        return "list"
    return None


def _table_of(item: Any) -> Any:
    return Annotated[
        Annotated[dict[int, item], Tag("mapping")] | Annotated[list[item], Tag("list")],
        Discriminator(
            _table_tag,
            custom_error_type="table_form",
            custom_error_message="a table is a mapping of position: value, or a list with "
            "one value per position",
        ),
    ]


TableDerivatives = Literal["linear", "spline"]


class TableArgument(_Frozen):
    """Argument values at calculation positions.

    A mapping ``{position: value}`` may be sparse and is filled by KDAM's rules: before the
    first given position the first value holds, between two given positions values are
    interpolated linearly, after the last the last value holds.  A list gives a value for
    every position ``0..N``.
    """

    table: _table_of(Scalar)
    unit: UnitName | None = Field(None, description="unit of the values (default: model unit)")
    derivatives: TableDerivatives = Field(
        "linear", description="'linear': derivatives of the piecewise-linear fill (central "
        "differences: the slope inside a segment, zero while a value holds); 'spline': of "
        "the cubic spline through the filled values (for smooth tabulated motion)")


LawName = Literal["constant_speed", "harmonic", "cycloidal", "poly345"]


class LawArgument(_Frozen):
    """A motion law from ``start = [position, value]`` to ``end = [position, value]``.

    Evaluated on the model time (or on the position number when the model has no time),
    with exact first and second derivatives; the start value holds before the start
    position and the end value after the end position.
    """

    law: LawName
    start: tuple[int, Scalar]
    end: tuple[int, Scalar]
    unit: UnitName | None = Field(None, description="unit of the values (default: model unit)")


class CsvTable(_Frozen):
    """A table read from a CSV file when the model is loaded: the first column holds
    position numbers, ``column`` (a header name, or a 0-based column index) the values; the
    positions may be sparse and are filled like any table.  The path is relative to the
    model file."""

    csv: str = Field(description="CSV file, relative to the model file")
    column: str | int = Field(1, description="column of the values: header or index")
    unit: UnitName | None = Field(None, description="unit of the values (default: model unit)")
    derivatives: TableDerivatives = Field("linear", description="as for a table")


#: Most values of an intermediate argument swept in one position.
MAX_INTERMEDIATE = 100_000


class Sweep(_Frozen):
    """``count`` equally spaced values from ``from`` to ``to`` (both included)."""

    model_config = ConfigDict(frozen=True, extra="forbid", populate_by_name=True)

    start: Scalar = Field(alias="from", description="first value (model units)")
    to: Scalar = Field(description="last value (model units)")
    count: int = Field(ge=2, le=MAX_INTERMEDIATE, description="number of values, ends "
                       "included (2 to 10⁵)")

    @model_serializer(mode="wrap")
    def _as_written(self, handler: Any) -> Any:
        """Dumped with the key a file uses (``from``), with or without ``by_alias``."""
        data = handler(self)
        if isinstance(data, dict) and "start" in data:
            data = {"from": data.pop("start"), **data}
        return data


class IntermediateArgument(_Frozen):
    """An argument swept inside every calculation position (KDAM's "intermediate
    argument"): e.g. the angle around a roller or the points of a follower's face.  The
    parameters it drives, and every contour depending on them, get one more axis of
    results (:func:`mechloop.solve.intermediate.solve_intermediate`); it does not move in
    time (its rate is zero).  The ordinary solve holds it at its first value."""

    intermediate: Sweep
    unit: UnitName | None = Field(None, description="unit of the values (default: model unit)")


def _argument_tag(value: Any) -> str | None:
    if isinstance(value, IntermediateArgument) or (
            isinstance(value, dict) and "intermediate" in value):
        return "intermediate"
    if isinstance(value, CsvTable) or (isinstance(value, dict) and "csv" in value):
        return "csv"
    if isinstance(value, TableArgument) or (isinstance(value, dict) and "table" in value):
        return "table"
    if isinstance(value, LawArgument) or (isinstance(value, dict) and "law" in value):
        return "law"
    return None


Argument = Annotated[
    Annotated[TableArgument, Tag("table")] | Annotated[LawArgument, Tag("law")]
    | Annotated[CsvTable, Tag("csv")]
    | Annotated[IntermediateArgument, Tag("intermediate")],
    Discriminator(
        _argument_tag,
        custom_error_type="argument_form",
        custom_error_message="an argument needs a 'table', a 'law' with 'start' and 'end', "
        "a 'csv' file, or an 'intermediate' sweep",
    ),
]


class RpmTime(_Frozen):
    """Model time from a speed: ``turns`` full turns (default one) over positions ``0..N``,
    ``t = 60·turns/n · k/N``."""

    rpm: Number = Field(ge=1e-6, le=1e6, description="speed of the input, revolutions per "
                        "minute (10⁻⁶ to 10⁶)")
    turns: Number = Field(1.0, ge=1e-6, le=1e6, description="turns of the input over "
                          "positions 0..N (2 for a four-stroke cycle over 720 degrees)")


#: Shortest time between two positions, s (a speed of 10⁶ rpm over 10⁷ positions steps
#: 6·10⁻¹²; shorter steps only square velocities towards overflow).
MIN_TIME_STEP = 1e-15


class TableTime(_Frozen):
    """Model time as a table ``{position: seconds}`` filled like an argument table; it
    increases by at least :data:`MIN_TIME_STEP` from position to position."""

    table: _table_of(Number)
    derivatives: TableDerivatives = Field(
        "linear", description="how dt/dposition is taken: 'linear' or 'spline' (as for "
        "argument tables)")


def _time_tag(value: Any) -> str | None:
    if isinstance(value, RpmTime) or (isinstance(value, dict) and "rpm" in value):
        return "rpm"
    if isinstance(value, TableTime) or (isinstance(value, dict) and "table" in value):
        return "table"
    return None


Time = Annotated[
    Annotated[RpmTime, Tag("rpm")] | Annotated[TableTime, Tag("table")],
    Discriminator(
        _time_tag,
        custom_error_type="time_form",
        custom_error_message="time needs either 'rpm' or a 'table' of seconds",
    ),
]


#: Largest CSV table read, bytes (10⁶ rows of a position and a value take about 20 MB).
MAX_CSV_BYTES = 64 * 2**20


def read_csv_table(spec: dict[str, Any], base: Path) -> dict[str, Any]:
    """The table form of a ``{csv: ...}`` spec (``{table: {position: value}, ...}``).

    Raises ``ValueError`` with a message and a hint (``args = (message, hint)``).
    """
    import numpy as np
    import pandas as pd

    path = Path(str(spec["csv"]))
    path = path if path.is_absolute() else base / path
    if path.exists() and not path.is_file():  # a folder, a device, a pipe: never read
        raise ValueError(f"{path} is not a CSV file", "give the path of a CSV file, "
                         "relative to the model file")
    try:
        if path.stat().st_size > MAX_CSV_BYTES:
            raise ValueError(f"{path} is larger than {MAX_CSV_BYTES // 2**20} MiB, the limit "
                             "for a table", "give fewer rows (one per calculation position "
                             "at most)")
        frame = pd.read_csv(path)
    except FileNotFoundError:
        raise ValueError(f"CSV file {path} not found",
                         "give the path relative to the model file") from None
    except OSError as exc:
        raise ValueError(f"cannot read {path} ({exc.strerror or exc})",
                         "check the path and its permissions") from None
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise ValueError(f"cannot read {path} as CSV ({exc})",
                         "write a header line, then position,value rows") from None
    column = spec.get("column", 1)
    if isinstance(column, int):
        if not 0 < column < len(frame.columns):
            raise ValueError(f"{path} has no value column {column}",
                             f"use 1..{len(frame.columns) - 1} or a header name")
        values = frame.iloc[:, column]
    elif column in frame.columns:
        values = frame[column]
    else:
        raise ValueError(f"{path} has no column {column!r}",
                         f"use one of {', '.join(map(str, frame.columns[1:]))}")
    positions = pd.to_numeric(frame.iloc[:, 0], errors="coerce")
    values = pd.to_numeric(values, errors="coerce")
    bad = positions.isna() | values.isna() | (positions != positions.round())
    if bad.any():
        row = int(bad.to_numpy().nonzero()[0][0]) + 2  # 1-based, after the header
        raise ValueError(f"{path}, line {row}: not a position number and a value",
                         "every row is an integer position and a number")
    v, k = values.to_numpy(float), positions.to_numpy(float)
    wild = ~(np.isfinite(v) & (np.abs(v) <= MAX_MAGNITUDE)
             & np.isfinite(k) & (np.abs(k) <= MAX_MAGNITUDE))
    if wild.any():
        row = int(np.flatnonzero(wild)[0])
        raise ValueError(f"{path}, line {row + 2}: {positions.iloc[row]}, {values.iloc[row]} "
                         f"is outside the range of a position and a model value ({RANGE})",
                         "write a whole position number and a finite value of a physical "
                         "size (model units)")
    table = {int(k): float(v) for k, v in zip(positions, values, strict=True)}
    out: dict[str, Any] = {"table": table, "derivatives": spec.get("derivatives", "linear")}
    if spec.get("unit") is not None:
        out["unit"] = spec["unit"]
    return out


class Envelope(_Frozen):
    """The envelope of the curves that the end of the chain ``vectors`` (laid end to end
    from the origin) draws over the intermediate argument, one curve per position."""

    name: str = Field(min_length=1, description="name of the envelope (tables, plots)")
    vectors: list[int] = Field(min_length=1, description="vector numbers: the point is "
                               "the end of these vectors laid end to end from the origin")
    argument: int | None = Field(None, ge=1, description="the intermediate argument swept "
                                 "(default: the model's only one)")
