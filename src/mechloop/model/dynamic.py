"""The dynamic part of a model file: bodies, joints, loads, gravity (KDAM's "basic dynamic
model", DESIGN §5).

A **body** is a set of vectors that move together; the ground is body 0.  Points are
given on vectors: ``{tail: 3}``, ``{head: 3}``, or ``{vector: 2, share: 0.3}`` (a fraction
of the vector's length from its tail) / ``{vector: 2, along: 0.06, across: 0.01}`` (a
distance along the vector from its tail and a distance to its left).  Numbers are in the
model's units (``units``); any value may also carry its own unit ("2 kg", "1 kN").

Sign conventions: angles and moments counter-clockwise positive; a joint's reaction is
the force that the first body of ``bodies`` exerts on the second.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, Discriminator, Field, Tag, model_validator

from mechloop.model.indicator import IndicatorValue
from mechloop.model.signals import Argument, Number, Scalar, _Frozen


class TailPoint(_Frozen):
    """The tail (start) of a vector."""

    tail: int = Field(ge=1, description="vector number")


class HeadPoint(_Frozen):
    """The head (end) of a vector."""

    head: int = Field(ge=1, description="vector number")


class VectorPoint(_Frozen):
    """A point placed on a vector: ``share`` of its length from the tail, or ``along`` it
    from the tail; ``across`` to its left (counter-clockwise side)."""

    vector: int = Field(ge=1, description="vector number")
    share: Number | None = Field(None, description="fraction of the vector's length from "
                                "its tail (0 = tail, 1 = head)")
    along: Scalar | None = Field(None, description="distance from the tail along the "
                                 "vector (length units)")
    across: Scalar = Field(0.0, description="distance to the left of the vector (length "
                           "units)")

    @model_validator(mode="after")
    def _one_placement(self) -> VectorPoint:
        if (self.share is None) == (self.along is None):
            raise ValueError("give either 'share' (a fraction of the length) or 'along' "
                             "(a distance from the tail)")
        return self


def _point_tag(value: Any) -> str | None:
    for cls, key in ((TailPoint, "tail"), (HeadPoint, "head"), (VectorPoint, "vector")):
        if isinstance(value, cls) or (isinstance(value, dict) and key in value):
            return key
    return None


PointOn = Annotated[
    Annotated[TailPoint, Tag("tail")] | Annotated[HeadPoint, Tag("head")]
    | Annotated[VectorPoint, Tag("vector")],
    Discriminator(
        _point_tag,
        custom_error_type="point_form",
        custom_error_message="a point is {tail: K}, {head: K} or {vector: K, share: s} / "
        "{vector: K, along: d, across: e}",
    ),
]


def point_vector(point: TailPoint | HeadPoint | VectorPoint) -> int:
    """The number of the vector a point is given on (its tail, its head, or along it)."""
    if isinstance(point, TailPoint):
        return point.tail
    if isinstance(point, HeadPoint):
        return point.head
    return point.vector

#: A moment of inertia, or ``rod``: a slender rod about its middle, ``m·l²/12`` with ``l``
#: the length of the vector that carries the centre (KDAM's m→Js button).
Inertia = Scalar | Literal["rod"]
#: A body's inertia: :data:`Inertia`, or in a model with spatial contours ``[Jx, Jy, Jz]``
#: (principal moments in the body's frame) or the 3×3 tensor (:mod:`mechloop.spatial.bodies`).
BodyInertia = Inertia | list[Scalar] | list[list[Scalar]]


class MassPart(_Frozen):
    """A lumped mass of a body: mass, moment of inertia about its own centre, centre."""

    mass: Scalar = Field(description="mass (mass units)")
    inertia: BodyInertia = Field(0.0, description="moment of inertia about the part's centre "
                             "of mass (inertia units), or 'rod' for m·l²/12; with spatial "
                             "contours a tensor [Jx, Jy, Jz] or 3×3 in the body frame")
    center: PointOn = Field(description="centre of mass, on one of the body's vectors")


class Body(_Frozen):
    """A link: vectors that move together, with its mass characteristics.

    ``mass``/``inertia``/``center`` describe the body as one lumped mass; ``parts`` adds
    more (a body with several centres of mass).  A vector whose length varies has one end
    fixed in the body: the tail, unless ``ends`` says ``head``.
    """

    vectors: list[int] = Field(min_length=1, description="vectors fixed in this body")
    name: str | None = None
    mass: Scalar = Field(0.0, description="mass (mass units)")
    inertia: BodyInertia = Field(0.0, description="moment of inertia about the centre of mass "
                             "(inertia units), or 'rod' for m·l²/12; with spatial contours a "
                             "tensor [Jx, Jy, Jz] or 3×3 in the body frame")
    center: PointOn | None = Field(None, description="centre of mass (required with a mass)")
    parts: list[MassPart] = Field(default_factory=list, description="further lumped masses")
    ends: dict[int, Literal["tail", "head"]] = Field(
        default_factory=dict, description="for a vector of varying length: which of its "
        "ends is fixed in this body (default tail)")


def _axis_tag(value: Any) -> str | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int):
        return "vector"
    if isinstance(value, list | tuple):
        return "direction"
    return None


#: A joint's axis in a model with spatial contours: a vector number, or ``[x, y, z]``.
JointAxis = Annotated[
    Annotated[Annotated[int, Field(ge=1)], Tag("vector")]
    | Annotated[tuple[Number, Number, Number], Tag("direction")],
    Discriminator(
        _axis_tag,
        custom_error_type="joint_axis",
        custom_error_message="a joint's axis is a vector number K (along vector K) or a "
        "direction [x, y, z]",
    ),
]


class Joint(_Frozen):
    """A kinematic pair between two bodies (the ground is body 0).

    ``revolute``: a pin at point ``at``; friction is a moment ``f·radius·|R|`` against the
    relative rotation.  ``prismatic``: a slide along vector ``along``; its reaction is a
    normal force and a moment about point ``at`` (default: the tail of ``along``, where a
    slider's vector starts); friction is a force ``f·max(|N|, 2|M|/length)`` against the relative
    sliding (a slider of ``length`` loaded at its two edges).

    In a model with spatial contours (:mod:`mechloop.spatial.joints`) a joint is
    ``spherical`` (a ball at ``at``: three force components), ``revolute`` (a pin at ``at``
    turning about ``axis``: three forces, two moments across the axis), ``cylindrical``
    (turning about and sliding along ``axis``: two forces and two moments across it) or
    ``prismatic`` (sliding along ``axis``: two forces across it, three moments); ``axis``
    is a vector number (the axis along that vector, turning with it) or a direction
    ``[x, y, z]`` fixed in the model's axes.
    """

    type: Literal["revolute", "prismatic", "spherical", "cylindrical"] = "revolute"
    bodies: tuple[int, int] = Field(description="the two bodies; the reaction is the "
                                    "force of the first on the second")
    at: PointOn | None = Field(None, description="revolute: the pin; prismatic: the "
                               "reference point of the normal force and moment")
    along: int | None = Field(None, description="prismatic: the vector along which the "
                              "bodies slide")
    axis: JointAxis | None = Field(
        None, description="in a model with spatial contours (revolute, cylindrical, "
        "prismatic): the joint's axis, a vector number (along that vector, turning with it) "
        "or a direction [x, y, z] fixed in the model's axes")
    friction: Number | None = Field(None, ge=0, description="coefficient of friction "
                                   "(default: friction.coefficient, or none)")
    radius: Scalar | None = Field(None, description="revolute: pin radius for friction "
                                  "(length units; default friction.radius)")
    length: Scalar | None = Field(None, description="prismatic: slider length for friction "
                                  "(length units; default friction.length)")


class Friction(_Frozen):
    """Defaults for every joint that does not set its own."""

    coefficient: Number = Field(0.0, ge=0, description="coefficient of friction")
    radius: Scalar | None = Field(None, description="pin radius of revolute joints")
    length: Scalar | None = Field(None, description="slider length of prismatic joints")


#: A parameter of the model: ``rK`` (length of vector K) or ``aK`` (its angle).
ParameterName = Annotated[str, Field(pattern=r"^[ra][1-9][0-9]{0,5}$")]


class ParameterValue(_Frozen):
    """A load as a function of a model parameter's value: ``[value, load]`` pairs, the
    parameter's values increasing (its units: length or angle), the load linear between
    them and held at the end values beyond (e.g. a resistance over the output's
    position)."""

    of: ParameterName = Field(description="the parameter, e.g. r5 (the length of vector "
                              "5) or a3 (the angle of vector 3)")
    table: list[tuple[Scalar, Scalar]] = Field(
        min_length=2, description="[parameter value, load] pairs, parameter increasing "
        "(model units, or numbers with units)")
    unit: str | None = Field(None, description="unit of the loads (default: the model's)")


class ExpressionValue(_Frozen):
    """A load as an expression of the state: ``t`` (s), the parameters ``rK`` (m) and
    ``aK`` (rad) and their rates ``drK`` (m/s), ``daK`` (rad/s) — SI, whatever the model's
    units — with ``+ − * / ** %``, comparisons (1 or 0), ``pi`` and sin, cos, tan, arcsin,
    arccos, arctan, arctan2, sqrt, exp, log, abs, sign, min, max, minimum, maximum, where,
    hypot, tanh; the value is in ``unit`` (default the model's force or moment unit).
    Without model time rates are per unit of argument 1 and ``t`` is not known."""

    expression: str = Field(max_length=400, description="e.g. '-800*sign(dr6)' (names "
                            "in SI: t s, rK m, aK rad, drK m/s, daK rad/s)")
    unit: str | None = Field(None, description="unit of the value (default: the model's)")

    @model_validator(mode="after")
    def _parses(self) -> ExpressionValue:
        from mechloop.model.expression import Expression

        Expression(self.expression)
        return self


class When(_Frozen):
    """A load that acts only while a parameter changes one way: ``rate_of`` the parameter
    whose rate decides, ``sign`` positive (while it grows) or negative (while it falls).
    Where the rate is zero the load does not act."""

    rate_of: ParameterName = Field(description="the parameter whose rate decides, e.g. r5")
    sign: Literal["positive", "negative"] = Field(description="act while the rate is "
                                                  "positive (growing) or negative")


def _value_tag(value: Any) -> str | None:
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float | str):
        return "constant"
    if isinstance(value, ParameterValue) or (isinstance(value, dict) and "of" in value):
        return "parameter"
    if isinstance(value, ExpressionValue) or (isinstance(value, dict)
                                              and "expression" in value):
        return "expression"
    if isinstance(value, dict | BaseModel):
        return "signal"
    return None


#: A load over positions: a constant, a table / law exactly like a model argument, or a
#: table over a parameter's value.
LoadValue = Annotated[
    Annotated[Scalar, Tag("constant")] | Annotated[Argument, Tag("signal")]
    | Annotated[ParameterValue, Tag("parameter")]
    | Annotated[ExpressionValue, Tag("expression")],
    Discriminator(
        _value_tag,
        custom_error_type="load_value",
        custom_error_message="a load value is a number, a quantity like '1 kN', a table "
        "{table: {position: value}}, a law {law: ..., start: [k, v], end: [k, v]}, a "
        "table over a parameter {of: r5, table: [[value, load], ...]} or an expression "
        "{expression: '-800*sign(dr5)'}",
    ),
]


def _force_value_tag(value: Any) -> str | None:
    if isinstance(value, IndicatorValue) or (isinstance(value, dict) and "piston" in value):
        return "indicator"
    return _value_tag(value)


#: A force's value: a load value, or the gas force of an indicator diagram
#: (:mod:`mechloop.model.indicator`).
ForceValue = Annotated[
    Annotated[Scalar, Tag("constant")] | Annotated[Argument, Tag("signal")]
    | Annotated[ParameterValue, Tag("parameter")]
    | Annotated[ExpressionValue, Tag("expression")]
    | Annotated[IndicatorValue, Tag("indicator")],
    Discriminator(
        _force_value_tag,
        custom_error_type="load_value",
        custom_error_message="a force's value is a number, a quantity like '1 kN', a "
        "table {table: {position: value}}, a law {law: ..., start: [k, v], end: [k, v]}, "
        "a table over a parameter {of: r5, table: [[value, load], ...]}, an expression "
        "{expression: '-800*sign(dr5)'} or an indicator diagram {piston: r3, bore: ..., "
        "engine: {...}}",
    ),
]


class Force(_Frozen):
    """A force on a body at a point.  Its direction is the angle ``angle`` from +X, or,
    with ``along: K``, the direction of vector K turned by ``angle``; a negative value
    pushes the other way."""

    body: int = Field(ge=1, description="the body the force acts on")
    at: PointOn = Field(description="point of application")
    value: ForceValue = Field(description="magnitude over positions (force units)")
    angle: Scalar = Field(0.0, description="direction (angle units): from +X, or from "
                          "vector 'along'")
    along: int | None = Field(None, description="the force follows this vector's direction")
    direction: tuple[Number, Number, Number] | None = Field(
        None, description="in a model with spatial contours: the force's direction [x, y, "
        "z] (any length; normalized)")
    when: When | None = Field(None, description="act only while a parameter's rate has "
                              "this sign (default: always)")
    name: str | None = None


class Moment(_Frozen):
    """A moment (couple) on a body, counter-clockwise positive."""

    body: int = Field(ge=1, description="the body the moment acts on")
    value: LoadValue = Field(description="moment over positions (moment units)")
    axis: tuple[Number, Number, Number] | None = Field(
        None, description="in a model with spatial contours: the moment's axis [x, y, z] "
        "(any length; normalized; default Z, counter-clockwise in XY)")
    when: When | None = Field(None, description="act only while a parameter's rate has "
                              "this sign (default: always)")
    name: str | None = None


class Gravity(_Frozen):
    """Gravity: acceleration ``g`` pointing at ``angle`` from +X (default −90°, along −Y)."""

    g: Scalar = Field(9.81, description="acceleration of gravity (acceleration units)")
    angle: Scalar = Field("-90 deg", description="direction of gravity from +X (angle "
                          "units)")


class Machine(_Frozen):
    """Machine motion (the second sheet of the course project): the steady motion of a
    one-input machine over its cycle (positions 0..N = one cycle) under its reduced loads
    plus a constant moment (force) on the input that makes the cycle's net work zero — the
    resistance of an engine's consumer, or the mean torque of a motor — and the flywheel
    for a coefficient of speed fluctuation ``delta``."""

    delta: Number | None = Field(None, gt=0, lt=2, description="wanted coefficient of speed "
                                "fluctuation (ω_max − ω_min)/ω_mean; the flywheel is sized "
                                "for it")
    friction: bool = Field(True, description="include the friction losses found by the "
                           "force analysis at the nominal speed")
