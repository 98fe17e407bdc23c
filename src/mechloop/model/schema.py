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
* ``{link: "a2", delta: c}`` — equal to another vector's parameter plus a constant;
  ``{link: "a2", ratio: k, delta: c}`` — ``k`` times it plus a constant (``α_i = k·α_j + c``:
  a gear pair, ``k = −z1/z2`` external, ``+z1/z2`` internal; ``k`` is 1 by default).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Annotated, Any, Literal

from pydantic import BeforeValidator, Discriminator, Field, Tag, WithJsonSchema
from pydantic_core import PydanticCustomError

from mechloop.model.display import DisplaySection
from mechloop.model.dynamic import (
    Body,
    Force,
    Friction,
    Gravity,
    HeadPoint,
    Joint,
    Machine,
    Moment,
    TailPoint,
)
from mechloop.model.elements import Damper, Spring
from mechloop.model.gearing import GearMesh
from mechloop.model.plane import Plane
from mechloop.model.project import Project
from mechloop.model.report_info import ReportInfo
from mechloop.model.roles import FUNCTION
from mechloop.model.signals import (  # noqa: F401  (re-exported: part of the model)
    MAX_POSITIONS,
    Argument,
    Envelope,
    IntermediateArgument,
    LawArgument,
    LawName,
    Number,
    QuantityText,
    RpmTime,
    Scalar,
    TableArgument,
    TableDerivatives,
    TableTime,
    Time,
    UnitName,
    _Frozen,
)
from mechloop.model.simulate import Simulate
from mechloop.model.synthesis import SynthesisTask

#: Reads plain data into a checked model: :func:`mechloop.model.load.model_from_data`,
#: which puts itself here (:func:`set_model_reader`).  The loader builds on the schema, so
#: the schema does not import it; the package ``mechloop.model`` imports the loader with
#: any of its modules, so the reader is there before a model can be read.
_model_reader: list[Callable[..., Model]] = []


def set_model_reader(reader: Callable[..., Model]) -> None:
    """Make ``reader(data, file=...)`` the reader :meth:`Model.from_dict` calls."""
    _model_reader[:] = [reader]


ParamName = Annotated[
    str,
    Field(
        pattern=r"^[rab][1-9][0-9]*$",
        description="a vector parameter: 'r' (length), 'a' (angle α) or 'b' (rotation β "
        "about Y, spatial vectors) and the vector number, e.g. 'a2' or 'r3'",
    ),
]


class ArgumentRole(_Frozen):
    """The parameter equals model argument ``argument`` plus ``offset``."""

    argument: int = Field(ge=1, description="number of the model argument (1, 2, ...)")
    offset: Scalar = Field(0.0, description="constant added to the argument (model units)")


_FRACTION = re.compile(r"^\s*([+-]?\d+(?:\.\d*)?)\s*/\s*(\d+(?:\.\d*)?)\s*$")


def _fraction(value: Any) -> Any:
    """A ratio written as a fraction of tooth counts (``"-20/50"``) as its float."""
    if isinstance(value, str) and (found := _FRACTION.match(value)):
        top, bottom = float(found[1]), float(found[2])
        if bottom == 0:
            raise PydanticCustomError("ratio_fraction", "the ratio '{value}' divides by 0",
                                      {"value": value})
        return top / bottom
    return value


#: A link's ratio: a number, or a fraction ``"p/q"`` such as ``"-20/50"`` (teeth over teeth).
Ratio = Annotated[Number, BeforeValidator(_fraction), WithJsonSchema({
    "anyOf": [{"type": "number"}, {"type": "string", "pattern": _FRACTION.pattern}],
    "description": "factor on the linked parameter (dimensionless, finite, not 0): 1 for a "
    "rigid link, e.g. -20/50 (-z1/z2) for an external gear pair, +z1/z2 for an internal "
    "one; a number or a fraction 'p/q'"})]


class LinkRole(_Frozen):
    """The parameter equals ``ratio`` times another vector's parameter plus ``delta``:
    ``α_i = k·α_j + Δ`` (or ``r_i = k·r_j + Δ``).

    ``ratio`` 1 (the default) is a rigid link; any other ratio is a transmission — a gear
    pair (``−z1/z2`` for external gears, ``+z1/z2`` for an internal one), a gear train
    (the product of its pairs' ratios), a planetary train (ratios from Willis' formula).
    The rates follow exactly: ``α̇_i = k·α̇_j``, ``α̈_i = k·α̈_j``; chains compose
    (``α_i = k_i(k_j α_m + Δ_j) + Δ_i``).

    A link has one source.  That is enough for every train with one degree of freedom:
    with one member of a planetary train fixed, Willis' formula
    ``(ω1 − ωH)/(ω3 − ωH) = −z3/z1`` makes every member's angle a linear function of the
    input, so each member is a link with its ratio (``examples/planetary_reducer.yaml``).
    A second source (``α_p = k·α_H + m·α_1 + Δ``) is needed only by a differential, with
    two inputs; it would turn every link chain from one root into a sum over roots for
    every reader of links (solve, designs, existence, sensitivities, dynamics), and is not
    part of the format.  An angle linked with a ratio ≠ 1 to an angle a contour solves
    (a gear on a rocker, a coupler or a driven crank) follows that angle continuously,
    whole turns included, from position 0 where it lies in [0, 2π); the link may not
    point into its own coupled block.
    """

    link: ParamName
    ratio: Ratio = Field(1.0, description="factor on the linked parameter (dimensionless, "
                         "finite, not 0): 1 for a rigid link, e.g. -20/50 (-z1/z2) for an "
                         "external gear pair, +z1/z2 for an internal one; a number or a "
                         "fraction 'p/q'")
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
    Annotated[Number, Tag("constant")]
    | Annotated[Literal["function"], Tag("function")]
    | Annotated[QuantityText, Tag("quantity"), WithJsonSchema({
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
    b: Param | None = Field(
        None, description="spatial vectors only: rotation β about Y (α is then the "
        "elevation above the XZ plane, the vector r (cos α cos β, sin α, cos α sin β)); "
        "same roles as r; 0 when absent (mechloop.model.spatial)")
    name: str | None = Field(None, description="optional label (e.g. 'crank')")


class Contour(_Frozen):
    """A closed vector loop: the listed vectors sum to zero.

    A planar contour has exactly two function parameters among its vectors.  The module
    type follows from them (Pl1 ``r,α`` of one vector; Pl2 two lengths; Pl3 a length and
    another vector's angle; Pl4 two angles); "vector 1" of the module is the first listed.
    A ``spatial`` contour has three (:mod:`mechloop.model.spatial`: modules Pr1–Pr19).
    """

    vectors: list[int] = Field(min_length=2, description="vector numbers in the loop")
    variant: Literal[1, 2, 3, 4, 5, 6, 7, 8, "auto"] = Field(
        1, description="solution variant: 1, 2, or 'auto' (start with 1, then follow "
        "continuity from the previous position); a spatial contour's module has up to 8 "
        "(1..8)"
    )
    spatial: bool = Field(
        False, description="a spatial contour (mechloop.model.spatial): its vectors have "
        "r, a (α) and b (β), three of them 'function'; a negative vector number in "
        "'vectors' subtracts that vector")
    convention: Literal[1, 2] = Field(
        1, description="a spatial contour's parameter ranges (seed 000 sec. 1.1) for a "
        "vector whose α and β it both solves: 1 — α a full turn, β a half turn (-90, 90] "
        "(β = 0: the planar XY contour); 2 — β a full turn, α a half turn [-90, 90] "
        "(azimuth and elevation)")
    plane: Plane | None = Field(
        None, description="a planar contour's plane in a model with spatial contours "
        "(mechloop.model.plane): {normal: [nx, ny, nz]} or the normal's angles {a: .., "
        "b: ..}; the XY plane when absent")
    name: str | None = None
    start: Literal["origin"] | TailPoint | HeadPoint | tuple[Scalar, Scalar] = Field(
        "origin", description="where the tail of the first vector lies: 'origin', the tail "
        "or head of a vector of an earlier contour ({tail: K} / {head: K}), or fixed "
        "coordinates [x, y] (length units); places the contour's points in the plane")
    guess: dict[ParamName, Scalar] | None = Field(
        None, description="approximate values of the functions of this contour's coupled "
        "block at position 0 (model units), e.g. {a5: 40, r7: 300}: the assembly Newton's "
        "method starts from; only for contours solved as a coupled block")


class Units(_Frozen):
    """Units of the numbers in the model file (any pint unit of the right kind)."""

    length: UnitName = Field("m", description="length unit: m, cm, mm, ...")
    angle: UnitName = Field("deg", description="angle unit: deg, rad, grad")
    mass: UnitName = Field("kg", description="mass unit: kg, g, t")
    inertia: UnitName = Field("kg*m^2", description="moment of inertia unit: kg*m^2, g*cm^2")
    force: UnitName = Field("N", description="force unit: N, kN, kgf")
    moment: UnitName = Field("N*m", description="moment unit: N*m, kN*m, kgf*m")
    acceleration: UnitName = Field("m/s^2", description="unit of the acceleration of gravity")


class Model(_Frozen):
    """A planar vector model of a mechanism.

    ``positions`` is N: the model is calculated at positions ``0..N`` (N + 1 rows).
    """

    name: str = ""
    description: str = ""
    units: Units = Units()
    positions: int = Field(ge=1, le=MAX_POSITIONS, description="N: calculation positions "
                           "are 0..N (at most 10⁸)")
    time: Time | None = Field(
        None, description="model time; without it derivatives are analogs with respect to "
        "argument 1"
    )
    arguments: dict[int, Argument] = Field(default_factory=dict)
    vectors: dict[int, Vector]
    contours: list[Contour] = Field(min_length=1)
    bodies: dict[int, Body] = Field(
        default_factory=dict, description="links with their vectors and masses (body 0 is "
        "the ground; vectors not listed and fully constant belong to it)")
    joints: dict[str, Joint] | None = Field(
        None, description="kinematic pairs by name; inferred from the contours when absent")
    gears: dict[str, GearMesh] = Field(
        default_factory=dict, description="gear meshes (higher pairs) by name, for the "
        "force analysis: bodies, pitch point, pressure angle")
    forces: list[Force] = Field(default_factory=list, description="external forces")
    moments: list[Moment] = Field(default_factory=list, description="external moments")
    gravity: Gravity | None = Field(None, description="gravity (off when absent)")
    springs: list[Spring] = Field(default_factory=list, description="springs between "
                                  "two points of two bodies")
    dampers: list[Damper] = Field(default_factory=list, description="dampers between two "
                                  "points, or in the joint of two bodies")
    friction: Friction = Field(Friction(), description="friction defaults for every joint")
    machine: Machine | None = Field(None, description="machine motion and flywheel sizing "
                                    "(one-input machines)")
    envelopes: list[Envelope] = Field(
        default_factory=list, description="envelopes of the curves a point draws over the "
        "intermediate argument, one per position (e.g. a cam profile)")
    simulate: Simulate | None = Field(None, description="motion in time of a one-input "
                                      "machine under a motor (mechloop simulate)")
    synthesis: SynthesisTask | None = Field(
        None, description="a synthesis task: dimensions to vary, the target, conditions, "
        "search (mechloop synthesize)")
    project: Project | None = Field(
        None, description="the course project's cam (sheet 4) and gear pair or planetary "
        "train (sheet 3) documents, for mechloop report")
    display: DisplaySection | None = Field(
        None, description="units and precision of the results: tables, exports, energy, "
        "plots (KDAM's units and tolerances panels)")
    report: ReportInfo | None = Field(
        None, description="the title page of mechloop report: university, department, "
        "course, title, student, group, supervisor, city, year")

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, file: str | None = None) -> Model:
        """Build and fully check a model from plain data (as read from YAML or JSON).

        Raises :class:`mechloop.errors.ModelError` listing every problem found.
        """
        return _model_reader[0](data, file=file)


def model_json_schema() -> dict[str, Any]:
    """The JSON Schema of a model file, generated from :class:`Model`."""
    schema = Model.model_json_schema()
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "mechloop vector model"
    return schema
