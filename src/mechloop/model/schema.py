"""The vector model as frozen data: what a model file holds, and what Python code builds.

One data model serves the file format, the Python API and the JSON Schema
(:func:`model_json_schema`).  Numbers are in the model's own units (``units``); a value may
also be a string with its unit, e.g. ``"50 mm"`` or ``"90 deg"``.  Conversion to SI happens
only when a model is compiled for solving (:mod:`mechloop.model.compile`).

A vector parameter (``r`` — length, ``a`` — angle α from the X axis, counter-clockwise) has
one role:

* a number (or quantity string) — a *constant*;
* ``"function"`` — an unknown solved by the contour that holds the vector;
* ``{argument: k, offset: c}`` — driven by model argument ``k`` (plus a constant offset);
* ``{link: "a2", delta: c}`` — equal to another vector's parameter plus a constant.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Discriminator, Field, Tag, WithJsonSchema

FUNCTION = "function"

#: A constant: a number in the model's units, or a string with its own unit ("50 mm").
Scalar = float | str

ParamName = Annotated[
    str,
    Field(
        pattern=r"^[ra][1-9][0-9]*$",
        description="a vector parameter: 'r' (length) or 'a' (angle) and the vector number, "
        "e.g. 'a2' or 'r3'",
    ),
]


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


class ArgumentRole(_Frozen):
    """The parameter equals model argument ``argument`` plus ``offset``."""

    argument: int = Field(ge=1, description="number of the model argument (1, 2, ...)")
    offset: Scalar = Field(0.0, description="constant added to the argument (model units)")


class LinkRole(_Frozen):
    """The parameter equals another vector's parameter plus ``delta``."""

    link: ParamName
    delta: Scalar = Field(0.0, description="constant added to the linked parameter")


def _param_tag(value: Any) -> str | None:
    if isinstance(value, ArgumentRole):
        return "argument"
    if isinstance(value, LinkRole):
        return "link"
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float):
        return "constant"
    if isinstance(value, str):
        return "function" if value.strip() == FUNCTION else "quantity"
    if isinstance(value, dict):
        if "argument" in value:
            return "argument"
        if "link" in value:
            return "link"
    return None


Param = Annotated[
    Annotated[float, Tag("constant")]
    | Annotated[Literal["function"], Tag("function")]
    | Annotated[str, Tag("quantity"), WithJsonSchema({
        "type": "string", "pattern": r"^(?!\s*function\s*$)",
        "description": "a number with its unit, e.g. '50 mm' or '90 deg'"})]
    | Annotated[ArgumentRole, Tag("argument")]
    | Annotated[LinkRole, Tag("link")],
    Discriminator(
        _param_tag,
        custom_error_type="parameter_role",
        custom_error_message="expected a number, a quantity like '50 mm', 'function', "
        "an argument or a link",
    ),
]


class Vector(_Frozen):
    """One vector of the model: length ``r`` and angle ``a`` (α), each with its role."""

    r: Param = Field(description="length: constant, 'function', {argument: K} or {link: ..}")
    a: Param = Field(description="angle α from +X, counter-clockwise: same roles as r")
    name: str | None = Field(None, description="optional label (e.g. 'crank')")


class Contour(_Frozen):
    """A closed vector loop: the listed vectors sum to zero.

    A planar contour has exactly two function parameters among its vectors.  The module
    type follows from them (Pl1 ``r,α`` of one vector; Pl2 two lengths; Pl3 a length and
    another vector's angle; Pl4 two angles); "vector 1" of the module is the first listed.
    """

    vectors: list[int] = Field(min_length=2, description="vector numbers in the loop")
    variant: Literal[1, 2, "auto"] = Field(
        1, description="solution variant: 1, 2, or 'auto' (start with 1, then follow "
        "continuity from the previous position)"
    )
    name: str | None = None


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
    unit: str | None = Field(None, description="unit of the values (default: model unit)")
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
    unit: str | None = Field(None, description="unit of the values (default: model unit)")


def _argument_tag(value: Any) -> str | None:
    if isinstance(value, TableArgument) or (isinstance(value, dict) and "table" in value):
        return "table"
    if isinstance(value, LawArgument) or (isinstance(value, dict) and "law" in value):
        return "law"
    return None


Argument = Annotated[
    Annotated[TableArgument, Tag("table")] | Annotated[LawArgument, Tag("law")],
    Discriminator(
        _argument_tag,
        custom_error_type="argument_form",
        custom_error_message="an argument needs either a 'table' or a 'law' with 'start' and "
        "'end'",
    ),
]


class RpmTime(_Frozen):
    """Model time from a speed: one full turn over positions ``0..N``, ``t = 60/n·k/N``."""

    rpm: float = Field(gt=0, description="speed of the input, revolutions per minute")


class TableTime(_Frozen):
    """Model time as a table ``{position: seconds}`` filled like an argument table."""

    table: _table_of(float)
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


class Units(_Frozen):
    """Units of the numbers in the model file (any pint unit of the right kind)."""

    length: str = Field("m", description="length unit: m, cm, mm, ...")
    angle: str = Field("deg", description="angle unit: deg, rad, grad")


class Model(_Frozen):
    """A planar vector model of a mechanism.

    ``positions`` is N: the model is calculated at positions ``0..N`` (N + 1 rows).
    """

    name: str = ""
    description: str = ""
    units: Units = Units()
    positions: int = Field(ge=1, description="N: calculation positions are 0..N")
    time: Time | None = Field(
        None, description="model time; without it derivatives are analogs with respect to "
        "argument 1"
    )
    arguments: dict[int, Argument] = Field(default_factory=dict)
    vectors: dict[int, Vector]
    contours: list[Contour] = Field(min_length=1)

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, file: str | None = None) -> Model:
        """Build and fully check a model from plain data (as read from YAML or JSON).

        Raises :class:`mechloop.errors.ModelError` listing every problem found.
        """
        from mechloop.model.load import model_from_data

        return model_from_data(data, file=file)


def model_json_schema() -> dict[str, Any]:
    """The JSON Schema of a model file, generated from :class:`Model`."""
    schema = Model.model_json_schema()
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "mechloop vector model"
    return schema
