"""Mechanisms built from Assur groups: an input group L0 and a sequence of class-II dyads
(seed 002: L1 RRR, L2 RRP, L3 RPR, L4 PRP, L5 RPP), turned into the ordinary vector model.

A :class:`GroupMechanism` names its **points** and **links** and states dimensions; the
builder (:func:`build_model`, :func:`build`) writes the vectors, the contours with their
modules (Pl1–Pl4) and ``start`` placements, the bodies and the joints.  A model file whose
top level has ``groups:`` (and no ``vectors:``) is such a mechanism;
:func:`mechloop.load_model` returns the generated :class:`~mechloop.model.schema.Model`.

**Points.**  Every point has a unique name (no dots): the ``ground`` points, the input's
``joint``, each group's ``joint`` (``point`` for L5) and the ``points`` placed on links.  A
reference to a point is ``NAME`` or ``LINK.NAME``.  A bare name means the point on the link
that introduced it — a ground point on the ground, the input's joint on the input link, a
point of ``points`` on its link.  The internal joint of L1, L2 and L4 belongs to both links
of its group, so name the link: ``coupler.B`` or ``rocker.B``.  A group may use only
points of the ground, the input and earlier groups.

**Lines of links.**  Angles of points on a link are measured from the link's *line*,
counter-clockwise, and ``{share: s}`` goes along it from its first to its second point:

==========================  =====================================================  =========
link                        line (first point → direction)                         2nd point
==========================  =====================================================  =========
ground                      +X                                                     —
crank (input)               pivot → joint                                          joint
slider (input, L2, L4)      its joint, along its guide's direction                 —
L1 first / second link      attachment → joint (both: pivot to pin)                joint
L2 rod                      attachment → joint                                     joint
L3 block and guide          the guide's pivot → the block's pin (block: its pin)   —
L5 block / yoke             pin, along the slot / ``point``, along the guide        —
==========================  =====================================================  =========

**Assembly variants** (``variant: 1 | 2 | auto``): L1 — 1 puts the joint on the left of
the line from the first attachment to the second; L2 — 1 puts the joint ahead of the
attachment along the guide direction (2: behind).  L3 (whose slide passes through the
guide's pivot), L4 and L5 have one assembly.

**A guide** is the line through a placed point ``through`` at ``angle`` from the line of
that point's link (from +X on the ground), shifted ``offset`` to its left; the guide belongs
to the link of ``through``.  An L3 slide has no offset: with one, the slide's direction and
offset turn together and no elementary module solves the loop.

**The vector model.**  Each group is one contour that runs from a ground point along the
vectors that reach its first attachment, through its own vectors, back along the vectors of
its second attachment and through the ground.  Vectors of links are written once and copied
(``{link: rK}``, ``{link: aK, delta: 180}``) where another contour passes them; ground points
are reached from the first ground point (the *root*) by one frame vector each.  A point on
a link that no group uses is placed by a Pl1 contour of its own (``P → X`` closing to the
point it is measured from).  Bodies are numbered as the structure formula numbers the links
(the input 1, then two per group), joints are written explicitly: pins named after their
point (``O``, ``A``; a second pin at the same point ``O2``), slides ``S`` + the pin of the
sliding link (``SB``).

:func:`build` also says where each named point is (:class:`PointLocation`) and which vector
parameter carries each dimension (:class:`Carrier`).

**Synthesis** (``synthesis:``, :class:`GroupSynthesisTask`) varies dimensions by the names
:func:`dimension_names` lists — paths in the document (``input.length``,
``groups[0].lengths[1]``, ``points.P.angle``) and ``ground.C.x`` / ``ground.C.y`` — and
traces named points.  The builder writes the vector model's task with one
:class:`~mechloop.model.synthesis.Dimension` per varied name: the constants it sets (its
carriers; for a ground coordinate the components of the frame vectors it ends and the
starts of the contours that start there, written as coordinates even at the origin).
:func:`with_dimensions` puts a result's values back into the mechanism,
:func:`save_mechanism` writes it, :func:`mechanism_of` reads a group file.
"""

from __future__ import annotations

import cmath
import math
import re
from dataclasses import dataclass, field
from difflib import get_close_matches
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import ConfigDict, Discriminator, Field, Tag, ValidationError
from pydantic.json_schema import SkipJsonSchema

from mechloop.errors import ModelError, Problem, format_path
from mechloop.model.dynamic import (
    Friction,
    Gravity,
    HeadPoint,
    Inertia,
    LoadValue,
    Machine,
    TailPoint,
    VectorPoint,
)
from mechloop.model.schema import Model, Units
from mechloop.model.signals import MAX_POSITIONS, Argument, Number, Scalar, Time, _Frozen
from mechloop.model.synthesis import (
    Dimension,
    MotionTask,
    PathTask,
    SynthesisTask,
    Tie,
    Workspace,
)
from mechloop.model.units import Kind, UnitProblem, to_si, unit_factor

GROUND = "ground"

Name = Annotated[str, Field(pattern=r"^[^.\s]([^.]*[^.\s])?$",
                            description="a name without dots (dots qualify point references)")]
PointRef = Annotated[str, Field(min_length=1, description="a point: NAME, or LINK.NAME for "
                                "the point on a given link")]
Variant = Literal[1, 2, "auto"]


# ------------------------------------------------------------------------------ file schema


class Guide(_Frozen):
    """A straight guide: the line through ``through`` at ``angle`` from the line of that
    point's link (from +X on the ground), shifted ``offset`` to its left."""

    through: PointRef = Field(description="a placed point the guide passes through; the "
                              "guide is fixed in that point's link")
    angle: Scalar = Field(0.0, description="direction of the guide (angle units) from the "
                          "line of its link (from +X on the ground)")
    offset: Scalar | None = Field(None, description="the sliding pin runs this far to the "
                                  "left of the line through 'through' (length units); 0 "
                                  "keeps an offset vector of zero length that synthesis "
                                  "can vary")


class CrankInput(_Frozen):
    """A crank: link ``link`` turns about ground point ``pivot``; its ``joint`` is at
    ``length`` from the pivot at the angle of argument ``argument`` plus ``angle``."""

    kind: Literal["crank"]
    link: Name = Field("crank", description="name of the crank link")
    pivot: PointRef = Field(description="the ground point the crank turns about")
    joint: Name = Field(description="name of the crank pin (a new point)")
    length: Scalar = Field(description="crank length, pivot to joint (length units)")
    argument: int = Field(1, ge=1, description="the model argument that turns the crank")
    angle: Scalar = Field(0.0, description="added to the argument (angle units)")


class SliderInput(_Frozen):
    """A slider driven along a ground guide: its ``joint`` is at the argument (plus
    ``shift``) from the guide's origin, along the guide."""

    kind: Literal["slider"]
    link: Name = Field("slider", description="name of the slider link")
    guide: Guide = Field(description="the ground guide the slider runs along")
    joint: Name = Field(description="name of the slider's pin (a new point)")
    argument: int = Field(1, ge=1, description="the model argument that moves the slider")
    shift: Scalar = Field(0.0, description="added to the argument (length units)")


def _kind_tag(value: Any) -> str | None:
    kind = value.get("kind") if isinstance(value, dict) else getattr(value, "kind", None)
    return kind if isinstance(kind, str) else None


Input = Annotated[
    Annotated[CrankInput, Tag("crank")] | Annotated[SliderInput, Tag("slider")],
    Discriminator(_kind_tag, custom_error_type="input_kind",
                  custom_error_message="the input is {kind: crank, ...} or "
                  "{kind: slider, ...}"),
]


class RRR(_Frozen):
    """L1 (RRR): two links pinned to each other at ``joint`` and to the placed points
    ``at`` — the first link at ``at[0]``, the second at ``at[1]``."""

    kind: Literal["L1", "RRR"]
    links: tuple[Name, Name] = Field(description="names of the two links")
    at: tuple[PointRef, PointRef] = Field(description="the placed points the first and the "
                                          "second link are pinned to")
    joint: Name = Field(description="name of the pin between the two links (a new point)")
    lengths: tuple[Scalar, Scalar] = Field(description="[|at[0] joint|, |joint at[1]|] "
                                           "(length units)")
    variant: Variant = Field(1, description="1: the joint on the left of at[0] → at[1]; 2: "
                             "on the right; auto: 1, then by continuity")


class RRP(_Frozen):
    """L2 (RRP): a rod pinned to the placed point ``at`` and, at ``joint``, to a slider
    that runs along ``guide``."""

    kind: Literal["L2", "RRP"]
    links: tuple[Name, Name] = Field(description="names of the rod and the slider")
    at: PointRef = Field(description="the placed point the rod is pinned to")
    joint: Name = Field(description="name of the pin between rod and slider (a new point)")
    length: Scalar = Field(description="rod length |at joint| (length units)")
    guide: Guide = Field(description="the guide the slider runs along")
    variant: Variant = Field(1, description="1: the joint ahead of 'at' along the guide "
                             "direction; 2: behind")


class RPR(_Frozen):
    """L3 (RPR): a block pinned to the placed point ``at[0]`` slides along a guide link
    (a slotted lever) pivoted at the placed point ``at[1]``; the slide passes through the
    pivot."""

    kind: Literal["L3", "RPR"]
    links: tuple[Name, Name] = Field(description="names of the block and the guide link")
    at: tuple[PointRef, PointRef] = Field(description="[the block's pin, the guide link's "
                                          "pivot]: placed points")
    variant: Variant = Field(1, description="one assembly: 1")


class PRP(_Frozen):
    """L4 (PRP): two sliders pinned to each other at ``joint``, the first running along
    ``guides[0]``, the second along ``guides[1]``."""

    kind: Literal["L4", "PRP"]
    links: tuple[Name, Name] = Field(description="names of the two sliders")
    joint: Name = Field(description="name of the pin between the sliders (a new point)")
    guides: tuple[Guide, Guide] = Field(description="the guides of the first and the "
                                        "second slider")
    variant: Variant = Field(1, description="one assembly: 1")


class RPP(_Frozen):
    """L5 (RPP): a block pinned to the placed point ``at`` slides in a straight slot of a
    yoke; the yoke runs along ``guide``; the slot crosses the guide line at the yoke's
    ``point`` at angle ``slot`` from the guide direction (a Scotch yoke: ``slot: 90``)."""

    kind: Literal["L5", "RPP"]
    links: tuple[Name, Name] = Field(description="names of the block and the yoke")
    at: PointRef = Field(description="the placed point the block is pinned to")
    guide: Guide = Field(description="the guide the yoke runs along")
    slot: Scalar = Field(description="angle of the yoke's slot from the guide direction "
                         "(angle units; not 0 or 180)")
    point: Name = Field(description="name of the yoke's point where the slot crosses the "
                        "guide line (a new point)")
    variant: Variant = Field(1, description="one assembly: 1")


KIND = {"L1": "L1", "RRR": "L1", "L2": "L2", "RRP": "L2", "L3": "L3", "RPR": "L3",
        "L4": "L4", "PRP": "L4", "L5": "L5", "RPP": "L5"}

Group = Annotated[
    Annotated[RRR, Tag("L1")] | Annotated[RRP, Tag("L2")] | Annotated[RPR, Tag("L3")]
    | Annotated[PRP, Tag("L4")] | Annotated[RPP, Tag("L5")],
    Discriminator(lambda v: KIND.get(_kind_tag(v) or ""), custom_error_type="group_kind",
                  custom_error_message="a group's kind is L1 (RRR), L2 (RRP), L3 (RPR), "
                  "L4 (PRP) or L5 (RPP)"),
]


class _FromPoint(_Frozen):
    model_config = ConfigDict(frozen=True, extra="forbid", populate_by_name=True)

    from_: PointRef | None = Field(None, alias="from", description="the point it is "
                                   "measured from (default: the first point of the link's "
                                   "line)")
    distance: Scalar = Field(0.0, description="distance from 'from' (length units)")
    angle: Scalar = Field(0.0, description="direction from 'from', counter-clockwise from "
                          "the link's line (angle units)")


class LinkPoint(_FromPoint):
    """A named point fixed in ``link``: ``distance`` from ``from`` at ``angle`` to the
    link's line (e.g. a coupler point)."""

    link: Name = Field(description="the link the point is fixed in")
    distance: Scalar = Field(description="distance from 'from' (length units, not 0)")


class Share(_Frozen):
    """A point on the link's line: ``share`` of the way from its first to its second
    point."""

    share: Number = Field(description="0 = the first point of the line, 1 = the second")


Place = Annotated[
    Annotated[str, Tag("point")] | Annotated[Share, Tag("share")]
    | Annotated[_FromPoint, Tag("from")],
    Discriminator(
        lambda v: "point" if isinstance(v, str) else (
            "share" if isinstance(v, Share) or (isinstance(v, dict) and "share" in v)
            else "from" if isinstance(v, dict | _FromPoint) else None),
        custom_error_type="place_form",
        custom_error_message="a place on a link is a point name, {share: s} or {from: X, "
        "distance: d, angle: φ}"),
]


class LinkMass(_Frozen):
    """Mass characteristics of a link."""

    mass: Scalar = Field(description="mass (mass units)")
    inertia: Inertia = Field(0.0, description="moment of inertia about the centre of mass "
                             "(inertia units), or 'rod': m·l²/12 with l the distance "
                             "between the two points of the link's line")
    center: Place | None = Field(None, description="centre of mass: a point of the link, "
                                 "{share: s} or {from: X, distance: d, angle: φ}")


class LinkForce(_Frozen):
    """A force on a link at a place on it; ``angle`` from +X, or with ``follow: true``
    from the link's line (the force turns with the link)."""

    link: Name
    at: Place = Field(description="point of application")
    value: LoadValue = Field(description="magnitude over positions (force units)")
    angle: Scalar = Field(0.0, description="direction (angle units)")
    follow: bool = Field(False, description="measure the angle from the link's line")
    name: str | None = None


class LinkMoment(_Frozen):
    """A moment (couple) on a link, counter-clockwise positive."""

    link: Name
    value: LoadValue = Field(description="moment over positions (moment units)")
    name: str | None = None


class GroupPathTask(PathTask):
    """Path generation (as in a vector model) traced by a named point."""

    point: PointRef = Field(  # type: ignore[assignment]
        description="the tracing point: a named point, e.g. P (or LINK.P)")


class GroupMotionTask(MotionTask):
    """Motion generation (as in a vector model) of a named point; ``angle`` is a vector
    parameter of the generated model (``mechloop info`` lists them)."""

    point: PointRef = Field(description="the guided point: a named point")  # type: ignore[assignment]


class GroupWorkspace(Workspace):
    """Named points stay inside a box or a polygon at every position."""

    points: list[PointRef] = Field(description="named points")  # type: ignore[assignment]


class GroupSynthesisTask(SynthesisTask):
    """The synthesis task of a mechanism built from Assur groups: ``vary`` names the
    dimensions as the mechanism's document spells them (``input.length``,
    ``groups[0].lengths[1]``, ``groups[1].guide.angle``, ``points.P.distance``,
    ``ground.C.x``), and points are named points.  The builder translates it into the
    vector model's task (:class:`~mechloop.model.synthesis.SynthesisTask` with
    ``dimensions``); a parameter that only the generated model has (``function.output``,
    ``motion.angle``, ``rotation``, ``criteria``) is named as there (``a3``)."""

    vary: dict[str, tuple[Scalar, Scalar]] = Field(
        description="dimensions to vary with their bounds [low, high] (model units): "
        "input.length, input.angle, groups[i].lengths[j], groups[i].length, "
        "groups[i].guide.angle, groups[i].guide.offset, groups[i].slot, "
        "points.NAME.distance, points.NAME.angle, ground.NAME.x, ground.NAME.y")
    path: GroupPathTask | None = None  # type: ignore[assignment]
    motion: GroupMotionTask | None = None  # type: ignore[assignment]
    workspace: GroupWorkspace | None = None  # type: ignore[assignment]
    dimensions: SkipJsonSchema[dict[str, Dimension]] = Field(  # type: ignore[assignment]
        default_factory=dict, description="written by the builder, not in a group file")


class GroupMechanism(_Frozen):
    """A planar mechanism as an input group plus class-II Assur groups (see the module
    docstring for points, lines and variants).  ``units``, ``positions``, ``time``,
    ``arguments``, ``gravity``, ``friction`` and ``machine`` are those of
    :class:`~mechloop.model.schema.Model`."""

    name: str = ""
    description: str = ""
    units: Units = Units()
    positions: int = Field(ge=1, le=MAX_POSITIONS, description="N: calculation positions "
                           "are 0..N (at most 10⁸)")
    time: Time | None = Field(None, description="model time (as in a vector model)")
    arguments: dict[int, Argument] = Field(default_factory=dict)
    ground: dict[Name, tuple[Scalar, Scalar]] = Field(
        min_length=1, description="fixed points: name: [x, y] (length units); the first is "
        "the root the contours start from")
    input: Input = Field(description="the input group L0: a crank or a driven slider")
    groups: list[Group] = Field(default_factory=list, description="Assur groups in the "
                                "order they attach")
    points: dict[Name, LinkPoint] = Field(default_factory=dict, description="named points "
                                          "fixed in links (coupler points, lever ends)")
    masses: dict[Name, LinkMass] = Field(default_factory=dict, description="masses by link")
    forces: list[LinkForce] = Field(default_factory=list)
    moments: list[LinkMoment] = Field(default_factory=list)
    gravity: Gravity | None = None
    friction: Friction = Friction()
    machine: Machine | None = None
    synthesis: GroupSynthesisTask | None = Field(
        None, description="a synthesis task that varies the dimensions by their names "
        "(mechloop synthesize)")

    @property
    def formula(self) -> str:
        """The structure formula the generated model has: ``L0(1) → L1(2,3) → …``."""
        parts = ["L0(1)"] + [f"{KIND[g.kind]}({2 * i + 2},{2 * i + 3})"
                             for i, g in enumerate(self.groups)]
        return " → ".join(parts)


def group_json_schema() -> dict[str, Any]:
    """The JSON Schema of a model file built from Assur groups."""
    schema = GroupMechanism.model_json_schema(by_alias=True)
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "mechloop mechanism built from Assur groups"
    return schema


# ------------------------------------------------------------------------------ results


@dataclass(frozen=True)
class Carrier:
    """A vector parameter that carries a dimension: ``part`` of parameter ``parameter``
    equals the dimension plus ``shift`` (model units).  ``part`` is ``value`` (the
    constant itself), ``delta`` (of a link role) or ``offset`` (of an argument role)."""

    parameter: str
    part: Literal["value", "delta", "offset"]
    shift: float = 0.0

    @property
    def target(self) -> str:
        """``r2``, ``a5.delta`` or ``a1.offset``: what to set."""
        return self.parameter if self.part == "value" else f"{self.parameter}.{self.part}"

    def __str__(self) -> str:
        return self.target if self.shift == 0 else f"{self.target} ({self.shift:+g})"


@dataclass(frozen=True)
class PointLocation:
    """Where a named point is in the generated model.

    ``start`` are the coordinates (model length units) of the ground point its chain starts
    at, ``vectors`` the chain: the point is ``start + Σ sign(k)·vector |k|``; ``end`` is a
    vector end at the point (``None`` for a ground point no vector touches); ``links`` the
    links that carry it.
    """

    name: str
    start: tuple[float, float]
    vectors: tuple[int, ...]
    end: TailPoint | HeadPoint | None
    links: tuple[str, ...]

    def xy(self, results: Any) -> tuple[Any, Any]:
        """x, y (m) of the point over the positions of solved ``results``, shape (P,)."""
        unit = results.model.units.length
        z = complex(to_si(self.start[0], "length", unit), to_si(self.start[1], "length", unit))
        total = np.full(results.broken.size, z, dtype=complex)
        for k in self.vectors:
            n = abs(k)
            total = total + math.copysign(1.0, k) * results.value(f"r{n}") * np.exp(
                1j * results.value(f"a{n}"))
        return total.real, total.imag


@dataclass(frozen=True)
class BuiltModel:
    """A generated vector model and what it means: body numbers of the links (ground 0),
    the location of every named point, and the parameters that carry each dimension
    (keys are paths in the mechanism's document, e.g. ``groups[0].lengths[1]``,
    ``points.P.angle``, ``ground.C.distance``)."""

    model: Model
    links: dict[str, int]
    points: dict[str, PointLocation]
    dimensions: dict[str, tuple[Carrier, ...]]
    formula: str


def build_model(mech: GroupMechanism) -> Model:
    """The vector model of ``mech``.

    Raises :class:`~mechloop.errors.ModelError` listing every problem, each with its path
    in the mechanism's document and the fix.

    >>> mech = GroupMechanism.model_validate({
    ...     "positions": 36, "arguments": {1: {"table": {0: 0, 36: 360}}},
    ...     "ground": {"O": [0, 0], "C": [0.3, 0]},
    ...     "input": {"kind": "crank", "pivot": "O", "joint": "A", "length": 0.1},
    ...     "groups": [{"kind": "L1", "links": ["coupler", "rocker"], "at": ["A", "C"],
    ...                 "joint": "B", "lengths": [0.35, 0.25]}]})
    >>> model = build_model(mech)
    >>> [c.vectors for c in model.contours]
    [[1, 2, 3, 4]]
    >>> [model.vectors[k].name for k in (1, 2, 3, 4)]
    ['crank OA', 'coupler AB', 'rocker BC', 'frame CO']
    """
    return build(mech).model


def build(mech: GroupMechanism) -> BuiltModel:
    """The vector model of ``mech`` with its point locations and dimension carriers."""
    return _Builder(mech).run()


def point_vectors(mech: GroupMechanism, model: Model, name: str) -> PointLocation:
    """Where point ``name`` of ``mech`` is in ``model`` — the model built from ``mech``,
    possibly with other constants (as synthesis varies them).

    ``Placement(results).point(location.end)`` (``mechloop.dynamics.points``) or
    ``location.xy(results)`` give its position over the positions.
    """
    built = build(mech)
    if [c.vectors for c in built.model.contours] != [c.vectors for c in model.contours] \
            or set(built.model.vectors) != set(model.vectors):
        raise ModelError([Problem((), "the model was not built from this mechanism: its "
                                  "vectors or contours differ",
                                  "pass the model that build_model(mech) returned (its "
                                  "constants may be changed, not its vectors)")])
    if name not in built.points:
        raise ModelError([Problem(("points",), f"no point named {name!r}",
                                  _choose(name, list(built.points)))])
    return built.points[name]


def dimension_parameters(mech: GroupMechanism) -> dict[str, tuple[Carrier, ...]]:
    """Which vector parameter carries each dimension of ``mech`` (see :class:`Carrier`),
    e.g. ``{"input.length": (Carrier("r1", "value"),), "points.P.angle":
    (Carrier("a5", "delta"),), ...}``.  The root ground point is carried by no parameter
    (it places the contours: their ``start``)."""
    return build(mech).dimensions


# ------------------------------------------------------------------------------ loading


def model_from_group_data(data: dict[str, Any], *, file: str | None = None,
                          lines: dict[tuple[Any, ...], int] | None = None) -> Model:
    """Validate the plain data of a group-built model file and build its vector model;
    every problem is raised at once, located in the file (see
    :func:`mechloop.model.load.model_from_data`, which calls this for ``groups:``)."""
    return _from_group_data(data, file, lines, build_it=True)


def mechanism_of(path: str | Path) -> GroupMechanism | None:
    """The :class:`GroupMechanism` a model file describes (with its tables read), or None
    for a vector model file.  Problems are raised located, as by
    :func:`mechloop.load_model`."""
    from mechloop.model.load import read_document

    data, lines = read_document(path)
    if "groups" not in data:
        return None
    return _from_group_data(data, str(path), lines, build_it=False)


def _from_group_data(data: dict[str, Any], file: str | None,
                     lines: dict[tuple[Any, ...], int] | None, *, build_it: bool) -> Any:
    from mechloop.model.load import located_error, validate_data
    from mechloop.model.salvage import GROUP_CORE, GROUP_PATCHED, salvage, set_aside

    lines = lines or {}


    mixed = [k for k in ("vectors", "contours", "bodies", "joints") if k in data]
    if mixed:
        raise located_error([Problem((key,), f"'{key}' belongs to a vector model, and this "
                                     "file describes the mechanism by 'groups'",
                                     f"remove '{key}' (the groups generate it), or remove "
                                     "'groups' and write the vector model")
                             for key in mixed], file, lines)
    mech, problems = validate_data(GroupMechanism, data, file, _group_hint)
    if problems:
        partial, dropped = salvage(data, problems, GroupMechanism, GROUP_CORE,
                                   GROUP_PATCHED)
        if partial is not None:  # what else is wrong, in the parts that validated
            try:
                build_model(partial)
            except ModelError as exc:
                problems += [p for p in exc.problems if p.path and p.path[0] in data
                             and not set_aside(p.path, dropped)]
        raise located_error(problems, file, lines)
    try:
        model = build_model(mech)
    except ModelError as exc:
        raise located_error(list(exc.problems), file, lines) from None
    return model if build_it else mech


def with_dimensions(mech: GroupMechanism, values: dict[str, float]) -> GroupMechanism:
    """``mech`` with dimensions set to ``values`` (model units), keyed as synthesis names
    them (``groups[0].lengths[1]``, ``points.P.angle``, ``ground.C.x``; e.g. a synthesis
    result's ``values()``).  The synthesis task is kept, to refine the result."""
    names = dimension_names(mech)
    unknown = [name for name in values if name not in names]
    if unknown:
        raise ModelError([Problem(("synthesis", "vary", name), f"no dimension named "
                                  f"{name!r}", _choose(name, names)) for name in unknown])
    data = mech.model_dump(mode="json", by_alias=True, exclude_defaults=True)
    for name, value in values.items():
        *keys, last = _document_keys(name)
        node: Any = data
        for key in keys:
            node = node[key]
        node[last] = float(value)
    return GroupMechanism.model_validate(data)


def dimension_names(mech: GroupMechanism) -> list[str]:
    """The dimensions of ``mech`` a synthesis may vary, as ``vary:`` names them."""
    builder = _Builder(mech.model_copy(update={"synthesis": None}))
    builder.run()
    return builder.dimension_names()


def _document_keys(name: str) -> list[str | int]:
    """The keys of a dimension in the mechanism's document: ``groups[0].lengths[1]`` ->
    ``['groups', 0, 'lengths', 1]``, ``ground.C.x`` -> ``['ground', 'C', 0]``."""
    head, _, rest = name.partition(".")
    if head in (GROUND, "points"):
        key, _, attr = rest.rpartition(".")
        return [head, key, "xy".index(attr) if head == GROUND and attr in ("x", "y")
                else attr]
    keys: list[str | int] = []
    for word, index in re.findall(r"([^.\[\]]+)|\[(\d+)\]", name):
        keys.append(int(index) if index else word)
    return keys


def mechanism_text(mech: GroupMechanism, *, json_form: bool = False) -> str:
    """``mech`` as the text of a group file: YAML, or JSON when ``json_form``."""
    import json

    import yaml

    data = mech.model_dump(mode="json", by_alias=True, exclude_defaults=True)
    if json_form:
        return json.dumps(data, indent=2, ensure_ascii=False) + "\n"
    return yaml.safe_dump(data, sort_keys=False, allow_unicode=True)


def save_mechanism(mech: GroupMechanism, path: str | Path) -> Path:
    """Write ``mech`` as a group file (YAML, or JSON for ``.json``) atomically."""
    from mechloop.output.atomic import atomic_write_text

    target = Path(path)
    atomic_write_text(target, mechanism_text(mech, json_form=target.suffix.lower() == ".json"))
    return target


#: What each field a group file may miss holds, for the fix of a "missing" error.
_FIELD_HINTS = {
    "kind": "add kind: L1 (RRR), L2 (RRP), L3 (RPR), L4 (PRP) or L5 (RPP); for the input "
            "crank or slider",
    "links": "add links: [first, second], the names of the group's two links",
    "at": "add at: the placed point(s) the group is pinned to, e.g. at: [A, C]",
    "joint": "add joint: the name of the new pin, e.g. joint: B",
    "lengths": "add lengths: [|at[0] joint|, |joint at[1]|], the two link lengths",
    "length": "add length: the link's length (length units)",
    "guide": "add guide: {through: O, angle: 0}, the line the slider runs along",
    "guides": "add guides: [{through: O, angle: 0}, {through: C, angle: 90}]",
    "through": "add through: a placed point the guide passes through",
    "pivot": "add pivot: the ground point the crank turns about",
    "slot": "add slot: the angle of the yoke's slot from its guide (90 for a Scotch yoke)",
    "point": "add point: a name for the yoke's point on its guide line",
    "distance": "add distance: how far the point is from 'from' (length units)",
    "link": "add link: the name of the link",
    "input": "add input: {kind: crank, pivot: O, joint: A, length: ..., argument: 1}",
    "ground": "add ground: {O: [0, 0], ...}, the fixed points",
    "positions": "add positions: N (the model is calculated at positions 0..N)",
    "mass": "add mass: the link's mass (mass units)",
    "value": "add value: the magnitude (a number, a quantity or a table)",
}


def _group_hint(error: dict[str, Any], message: str, hint: str) -> tuple[str, str]:
    kind = error["type"]
    loc = error["loc"]
    if kind == "missing" and loc and str(loc[-1]) in _FIELD_HINTS:
        return message, _FIELD_HINTS[str(loc[-1])]
    if kind == "group_kind":
        return message, "write kind: L1 (RRR), L2 (RRP), L3 (RPR), L4 (PRP) or L5 (RPP)"
    if kind == "input_kind":
        return message, "write kind: crank (with pivot, joint, length) or kind: slider " \
                        "(with guide, joint)"
    if kind == "place_form":
        return message, "write a point name (center: B), {share: 0.5} or {from: A, " \
                        "distance: 0.1, angle: 0}"
    if kind == "string_pattern_mismatch":
        return message, "write a name without dots or surrounding spaces (a dot separates " \
                        "a link from a point: coupler.B)"
    if kind in ("too_short", "too_long") and loc and str(loc[-1]) in (
            "links", "at", "lengths", "guides"):
        return message, "give exactly two items, one per link of the group"
    return message, hint


# ------------------------------------------------------------------------------ the builder

# role templates: ("const", value, dim) | ("function",) | ("arg", k, offset, dim)
#                 | ("link", segment, letter, delta, dim)
Template = tuple


_GROUND_XY = re.compile(r"^ground\.([^.]+)\.([xy])$")


@dataclass(frozen=True)
class _At:
    """A contour start at the coordinates of a ground point."""

    ground: str


@dataclass
class _Seg:
    """A vector of the mechanism before it is written: from point ``tail`` to ``head``."""

    id: int
    name: str
    tail: str
    head: str
    r: Template
    a: Template
    link: str  # the link it is fixed in (ground for frames and ground offsets)
    held: dict[str, str] = field(default_factory=dict)  # end -> link, for sliding vectors
    vector: int | None = None
    reversed: bool = False


@dataclass
class _Link:
    name: str
    body: int
    ref: int | None  # segment whose angle is the line's plus ref_delta
    ref_delta: float
    local: dict[str, complex]  # points fixed in the link, in the line frame
    first: str | None
    second: str | None
    segments: list[int] = field(default_factory=list)


@dataclass
class _Point:
    name: str
    owners: tuple[str, ...]  # the link(s) that introduced it
    links: list[str]
    ground: str  # the ground point its chain starts at
    path: tuple[tuple[int, int], ...]  # (segment, +1 forward / -1 backward)
    broken: bool = False


@dataclass
class _Vec:
    name: str
    r: Template
    a: Template
    reversed: bool


class _Builder:
    def __init__(self, mech: GroupMechanism):
        self.mech = mech
        self.units = mech.units
        self.problems: list[Problem] = []
        self.segs: list[_Seg] = []
        self.vectors: dict[int, _Vec] = {}
        self.contours: list[dict[str, Any]] = []
        self.links: dict[str, _Link] = {}
        self.points: dict[str, _Point] = {}
        self.pins: list[tuple[str, str, str, int, str]] = []  # name, link1, link2, seg, end
        self.slides: list[tuple[str, str, str, int, int, str]] = []  # + along segment
        self.dims: dict[str, float] = {}
        self.input_segs: set[int] = set()
        self.frames: dict[str, int] = {}
        self.coords: dict[str, complex] = {}
        self.root = next(iter(mech.ground))
        self.half = 0.0
        self.link_names: dict[str, tuple] = {}
        self.declared = self._declared()
        self.pending = dict(mech.points)
        self.starts: dict[int, str] = {}  # contour number -> the ground point it starts at
        task = mech.synthesis
        self.moved = {name.split(".")[1] for name in (task.vary if task else ())
                      if _GROUND_XY.match(name)}  # ground points synthesis moves

    # -- numbers -----------------------------------------------------------------------

    def num(self, value: Scalar, kind: Kind, path: tuple, *, positive: bool = False,
            dim: str | None = None) -> float:
        """``value`` in the model's unit of ``kind``; records a problem and returns 0 when
        it cannot be read."""
        unit = getattr(self.units, kind)
        try:
            si = to_si(value, kind, unit)  # refuses unreadable, non-finite, absurd values
            out = _plain(value)
            if out is None:  # a quantity with its own unit: to SI, then to the model's
                out = si / unit_factor(unit, kind)
        except UnitProblem as exc:
            self.problems.append(Problem(path, exc.message, exc.hint))
            return 0.0
        if positive and not out > 0:
            self.problems.append(Problem(path, f"{format_path(path)} is {out:g}; a length "
                                         "here must be positive", "give a positive length"))
        if dim is not None:
            self.dims[dim] = out
        return out

    # -- names ---------------------------------------------------------------------------

    def _declared(self) -> dict[str, tuple[str, tuple]]:
        """Every point name and where it is defined ("ground", "input", "groups[i]",
        "points")."""
        mech = self.mech
        out: dict[str, tuple[str, tuple]] = {}

        def add(name: str, what: str, path: tuple) -> None:
            if name in out:
                self.problems.append(Problem(path, f"point {name!r} is already defined at "
                                             f"{format_path(out[name][1])}",
                                             "give every point its own name"))
            else:
                out[name] = (what, path)

        for name in mech.ground:
            add(name, "ground", ("ground", name))
        add(mech.input.joint, "input", ("input", "joint"))
        for i, g in enumerate(mech.groups):
            new = getattr(g, "joint", None) or getattr(g, "point", None)
            if new is not None:
                key = "joint" if hasattr(g, "joint") else "point"
                add(new, f"groups[{i}]", ("groups", i, key))
        for name in mech.points:
            add(name, "points", ("points", name))
        names: dict[str, tuple] = {}
        for link, path in [(mech.input.link, ("input", "link"))] + [
                (name, ("groups", i, "links", j)) for i, g in enumerate(mech.groups)
                for j, name in enumerate(g.links)]:
            if link == GROUND:
                self.problems.append(Problem(path, "'ground' names the fixed link",
                                             "give the link another name"))
            elif link in names:
                self.problems.append(Problem(path, f"link {link!r} is already defined at "
                                             f"{format_path(names[link])}",
                                             "give every link its own name"))
            else:
                names[link] = path
        self.link_names = names
        return out

    def resolve(self, ref: str, path: tuple) -> _Point | None:
        """The point a reference names (on the asked link); a problem and None otherwise.
        Returns the point with ``links`` narrowed to the one meant (``links[0]``)."""
        link: str | None = None
        name = ref.strip()
        if "." in name:
            link, name = (s.strip() for s in name.split(".", 1))
            if link != GROUND and link not in self.link_names:
                self.problems.append(Problem(path, f"no link named {link!r}",
                                             _choose(link, [GROUND, *self.link_names])))
                return None
        if name not in self.declared:
            self.problems.append(Problem(path, f"unknown point {name!r}", _choose(
                name, [*self.points, *(p for p in self.declared if p not in self.points)],
                "the ground points, the input's joint, joints of earlier groups and points "
                "on links")))
            return None
        if name not in self.points:
            where, at = self.declared[name]
            if where == "points":
                on = self.mech.points[name].link
                defined = self.link_names.get(on)
                fix = (f"point {name} is on link {on!r}, defined at {format_path(defined)}: "
                       "attach this group after that one" if defined is not None else
                       f"point {name} is on link {on!r}, which no group defines")
            else:
                fix = (f"{name} is defined by {where} ({format_path(at)}): a group can only "
                       "use points of the ground, the input and earlier groups — move this "
                       "group after that one")
            self.problems.append(Problem(path, f"point {name!r} is not defined yet", fix))
            return None
        point = self.points[name]
        if point.broken:
            return None
        if link is None:
            if len(point.owners) > 1:
                options = " or ".join(f"{k}.{name}" for k in point.owners)
                self.problems.append(Problem(path, f"point {name!r} joins links "
                                             f"{' and '.join(point.owners)}: which one is "
                                             "meant is not clear", f"write {options}"))
                return None
            link = point.owners[0]
        if link not in point.links:
            self.problems.append(Problem(path, f"point {name!r} is not on link {link!r}",
                                         f"{name} is on {', '.join(point.links)}"))
            return None
        return _Point(point.name, point.owners, [link], point.ground, point.path)

    # -- segments and roles --------------------------------------------------------------

    def seg(self, name: str, tail: str, head: str, r: Template, a: Template, link: str,
            held: dict[str, str] | None = None) -> int:
        """A new segment; ``held`` names the links at the two ends of a sliding one."""
        self.segs.append(_Seg(len(self.segs), name, tail, head, r, a, link, held or {}))
        return len(self.segs) - 1

    def angle_on(self, link: str, angle: float, dim: str | None = None) -> Template:
        """Template of an angle ``angle`` from the line of ``link`` (from +X: ground)."""
        owner = self.links[link]
        if owner.ref is None:
            return ("const", angle, dim)
        return ("link", owner.ref, "a", angle - owner.ref_delta, dim)

    def new_point(self, name: str, owners: tuple[str, ...], ground: str,
                  path: tuple[tuple[int, int], ...], broken: bool = False) -> None:
        """A new named point, carried by ``owners``, reached by ``path`` from ``ground``."""
        self.points[name] = _Point(name, owners, list(owners), ground, path, broken)

    def new_link(self, name: str, ref: int | None, ref_delta: float,
                 local: dict[str, complex], first: str | None, second: str | None) -> _Link:
        """A new link (body number: the next one) with the points fixed in it."""
        link = _Link(name, len(self.links), ref, ref_delta, local, first, second)
        self.links[name] = link
        for point in local:
            if point in self.points and name not in self.points[point].links:
                self.points[point].links.append(name)
        return link

    def frame(self, name: str) -> int:
        """The frame segment from the root to ground point ``name``."""
        if name not in self.frames:
            d = self.coords[name] - self.coords[self.root]
            r = abs(d)
            a = math.degrees(cmath.phase(d)) * (self.half / 180.0) if r > 0 else 0.0
            self.dims[f"ground.{name}.distance"] = r
            self.dims[f"ground.{name}.direction"] = a
            self.frames[name] = self.seg(f"frame {self.root}{name}", self.root, name,
                                         ("const", r, f"ground.{name}.distance"),
                                         ("const", a, f"ground.{name}.direction"), GROUND)
        return self.frames[name]

    # -- contours ------------------------------------------------------------------------

    def place(self, seg_id: int, direction: int, out: list[int]) -> None:
        """Put segment ``seg_id`` (traversed forward or backward) in a contour: the vector
        itself the first time, a linked copy afterwards."""
        seg = self.segs[seg_id]
        number = len(self.vectors) + 1
        if seg.vector is None:
            seg.vector, seg.reversed = number, direction < 0
            name = seg.name
            if seg.reversed:
                ends = f"{seg.tail}{seg.head}"
                name = (f"{name[:-len(ends)]}{seg.head}{seg.tail}" if name.endswith(ends)
                        else f"{name} (reversed)")
            self.vectors[number] = _Vec(name, seg.r, seg.a, seg.reversed)
        else:
            delta = 0.0 if direction > 0 else self.half
            suffix = "copy" if direction > 0 else "reversed copy"
            self.vectors[number] = _Vec(f"{seg.name} ({suffix})",
                                        ("link", seg_id, "r", 0.0, None),
                                        ("link", seg_id, "a", delta, None), False)
        out.append(number)

    def end_of(self, seg_id: int, end: str) -> TailPoint | HeadPoint:
        """The written vector's end at the segment's ``end``."""
        seg = self.segs[seg_id]
        assert seg.vector is not None
        tail = (end == "tail") != seg.reversed
        return TailPoint(tail=seg.vector) if tail else HeadPoint(head=seg.vector)

    def loop(self, side1: tuple[str, tuple], own: list[tuple[int, int]],
             side2: tuple[str, tuple], *, name: str, variant: Variant, module: str) -> None:
        """One contour: from a ground point along ``side1`` (a chain to the first
        attachment), the group's own segments, back along ``side2`` and through the
        ground.

        When only ``side2`` meets the input's vector before it is written, the loop is
        written the other way round, so that the input's vector keeps its direction (the
        argument is its angle): a Pl1, Pl2 or Pl3 loop has the same solution either way, a
        Pl4 loop swaps its variants (not done for ``auto``, which starts from variant 1).
        """
        def meets_input(chain: tuple) -> bool:
            return any(s in self.input_segs and self.segs[s].vector is None for s, _ in chain)

        if meets_input(side2[1]) and not meets_input(side1[1]) and not (
                module == "Pl4" and variant == "auto"):
            side1, side2 = side2, side1
            own = [(s, -d) for s, d in reversed(own)]
            if module == "Pl4":
                variant = 2 if variant == 1 else 1
        g1, s1 = side1
        g2, s2 = side2
        common = 0
        if g1 == g2:
            while (common < min(len(s1), len(s2)) and s1[common] == s2[common]
                   and self.segs[s1[common][0]].vector is not None):
                common += 1
        elements = list(s1[common:]) + own + [(s, -d) for s, d in reversed(s2[common:])]
        if g1 != g2:
            if g2 != self.root:
                elements.append((self.frame(g2), -1))
            if g1 != self.root:
                elements.append((self.frame(g1), +1))
        start: Any
        if common:
            seg_id, direction = s1[common - 1]
            start = self.end_of(seg_id, "head" if direction > 0 else "tail")
        else:
            start = self.start_at(g1)
        self.contour(elements, start=start, name=name, variant=variant)

    def start_at(self, ground: str) -> _At:
        """A contour start at the coordinates of ground point ``ground``."""
        return _At(ground)

    def contour(self, elements: list[tuple[int, int]], *, start: Any, name: str,
                variant: Variant = 1) -> None:
        numbers: list[int] = []
        for seg_id, direction in elements:
            self.place(seg_id, direction, numbers)
        if isinstance(start, _At):  # coordinates (kept even at 0, 0 if synthesis moves them)
            self.starts[len(self.contours) + 1] = start.ground
            z = self.coords[start.ground]
            start = "origin" if z == 0 and start.ground not in self.moved else (z.real,
                                                                                 z.imag)
        entry: dict[str, Any] = {"vectors": numbers, "name": name}
        if variant != 1:
            entry["variant"] = variant
        if start != "origin":
            entry["start"] = start
        self.contours.append(entry)

    def closing(self, seg_id: int, start: Any, name: str) -> None:
        """A Pl1 contour that holds segment ``seg_id`` alone: the segment and a vector of
        unknown length and angle back to its tail."""
        seg = self.segs[seg_id]
        closer = self.seg(f"closing {seg.head}{seg.tail}", seg.head, seg.tail, ("function",),
                          ("function",), GROUND)
        self.contour([(seg_id, +1), (closer, +1)], start=start, name=name)

    def handle(self, point: str) -> Any:
        """A contour start at ``point``: a written vector end there, or ground coords."""
        if point in self.coords:
            return self.start_at(point)
        for seg in self.segs:
            if seg.vector is not None and point in (seg.tail, seg.head):
                return self.end_of(seg.id, "tail" if seg.tail == point else "head")
        raise AssertionError(f"point {point} is not placed")  # every placed point has one

    # -- the mechanism -------------------------------------------------------------------

    def run(self) -> BuiltModel:
        mech = self.mech
        for kind in ("angle", "length"):
            try:
                factor = unit_factor(getattr(self.units, kind), kind)
            except UnitProblem as exc:
                raise ModelError([Problem(("units", kind), exc.message, exc.hint)]) from None
            if kind == "angle":
                self.half = math.pi / factor
        self.links[GROUND] = _Link(GROUND, 0, None, 0.0, {}, None, None)
        for name, (x, y) in mech.ground.items():
            z = complex(self.num(x, "length", ("ground", name, 0)),
                        self.num(y, "length", ("ground", name, 1)))
            self.coords[name] = z
            self.links[GROUND].local[name] = z
            self.new_point(name, (GROUND,), name, ())
        self.add_input()
        for i, group in enumerate(mech.groups):
            self.add_group(i, group)
        for name in list(self.pending):
            spec = self.pending.pop(name)
            if spec.link == GROUND:
                self.problems.append(Problem(("points", name, "link"), "a fixed point is a "
                                             "ground point", f"move {name} under ground: "
                                             "with its coordinates [x, y]"))
            else:
                self.problems.append(Problem(("points", name, "link"),
                                             f"no link named {spec.link!r}",
                                             _choose(spec.link, list(self.link_names))))
        for name in mech.masses:
            self.link_of(name, ("masses", name))
        if self.problems:
            raise ModelError(self.problems)
        self.close_loose_ends()
        data = self.model_data()
        if mech.synthesis is not None:
            data["synthesis"] = self.synthesis(mech.synthesis)
        if self.problems:
            raise ModelError(self.problems)
        from mechloop.model.check import check_model

        try:
            model = Model.model_validate(data)
        except ValidationError as exc:  # pragma: no cover - a builder mistake
            raise ModelError([Problem(tuple(e["loc"]), e["msg"], "report this: the "
                                      "generated model is invalid") for e in exc.errors()]
                             ) from None
        _, problems = check_model(model)
        if problems:
            raise ModelError(problems)
        return BuiltModel(model, {k: v.body for k, v in self.links.items()},
                          self.locations(), self.carriers(), mech.formula)

    def add_input(self) -> None:
        spec = self.mech.input
        path = ("input",)
        if spec.argument not in self.mech.arguments:
            self.problems.append(Problem((*path, "argument"), f"argument {spec.argument} is "
                                         "not defined",
                                         f"add it under arguments: (e.g. {spec.argument}: "
                                         "{table: {0: 0, N: 360}}) or use one that exists"))
        if isinstance(spec, CrankInput):
            pivot = self.resolve(spec.pivot, (*path, "pivot"))
            length = self.num(spec.length, "length", (*path, "length"), positive=True,
                              dim="input.length")
            angle = self.num(spec.angle, "angle", (*path, "angle"), dim="input.angle")
            if pivot is not None and pivot.links[0] != GROUND:
                self.problems.append(Problem((*path, "pivot"), f"the crank's pivot {pivot.name} "
                                             "is not a ground point",
                                             "pivot the crank on a point of ground:"))
                pivot = None
            if pivot is None:
                self.new_point(spec.joint, (spec.link,), self.root, (), broken=True)
                self.new_link(spec.link, None, 0.0, {}, None, None)
                return
            crank = self.seg(f"{spec.link} {pivot.name}{spec.joint}", pivot.name, spec.joint,
                             ("const", length, "input.length"),
                             ("arg", spec.argument, angle, "input.angle"), spec.link)
            self.input_segs.add(crank)
            self.new_link(spec.link, crank, 0.0, {pivot.name: 0j, spec.joint: complex(length)},
                          pivot.name, spec.joint)
            self.links[spec.link].segments.append(crank)
            self.new_point(spec.joint, (spec.link,), pivot.ground,
                           (*pivot.path, (crank, +1)))
            self.pins.append((pivot.name, GROUND, spec.link, crank, "tail"))
        else:
            guide = self.guide(spec.guide, (*path, "guide"), "input.guide")
            shift = self.num(spec.shift, "length", (*path, "shift"), dim="input.shift")
            if guide is not None and guide[0].links[0] != GROUND:
                self.problems.append(Problem((*path, "guide", "through"), "the input slider's "
                                             "guide must be fixed in the ground",
                                             "run it through a ground point"))
                guide = None
            if guide is None:
                self.new_point(spec.joint, (spec.link,), self.root, (), broken=True)
                self.new_link(spec.link, None, 0.0, {}, None, None)
                return
            through, angle, offset = guide
            slide = self.seg(f"{spec.link} along guide to {spec.joint}", ".foot", spec.joint,
                             ("arg", spec.argument, shift, "input.shift"),
                             self.angle_on(GROUND, angle, "input.guide.angle"), spec.link,
                             held={"tail": GROUND, "head": spec.link})
            chain = self.guide_chain(through, offset, slide, +90.0, "input.guide",
                                     f"guide offset of {spec.link}")
            self.input_segs.update(s for s, _ in chain)
            self.input_segs.add(slide)
            self.new_link(spec.link, slide, 0.0, {spec.joint: 0j}, spec.joint, None)
            self.links[spec.link].segments.append(slide)
            self.new_point(spec.joint, (spec.link,), through.ground,
                           (*chain, (slide, +1)))
            self.slides.append((f"S{spec.joint}", GROUND, spec.link, slide, slide, "head"))
        self.add_points(spec.link)

    def guide(self, spec: Guide, path: tuple, dim: str
              ) -> tuple[_Point, float, float | None] | None:
        """The point a guide runs through, its angle and offset (model units)."""
        through = self.resolve(spec.through, (*path, "through"))
        angle = self.num(spec.angle, "angle", (*path, "angle"), dim=f"{dim}.angle")
        offset = None if spec.offset is None else self.num(spec.offset, "length",
                                                           (*path, "offset"),
                                                           dim=f"{dim}.offset")
        return None if through is None else (through, angle, offset)

    def guide_chain(self, through: _Point, offset: float | None, slide: int, turn: float,
                    dim: str, name: str) -> tuple[tuple[int, int], ...]:
        """The chain to the guide's origin (the foot of the slide): the chain of
        ``through`` plus the offset segment, whose direction is the slide's turned by
        ``turn`` degrees."""
        if offset is None:
            return through.path
        link = through.links[0]
        off = self.seg(name, through.name, ".foot", ("const", offset, f"{dim}.offset"),
                       ("link", slide, "a", turn * self.half / 180.0, None), link)
        if link != GROUND:
            self.links[link].segments.append(off)
        return (*through.path, (off, +1))

    def add_points(self, link: str) -> None:
        """Register the points of ``points`` that are fixed in ``link`` (in file order)."""
        owner = self.links[link]
        for name, spec in list(self.pending.items()):
            if spec.link != link:
                continue
            del self.pending[name]
            path = ("points", name)
            distance = self.num(spec.distance, "length", (*path, "distance"), positive=True,
                                dim=f"points.{name}.distance")
            angle = self.num(spec.angle, "angle", (*path, "angle"),
                             dim=f"points.{name}.angle")
            origin_name = spec.from_ or owner.first
            if owner.ref is None:  # the link itself failed
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            later = (origin_name or "").split(".")[-1].strip()
            if later in self.pending and self.pending[later].link == link:
                self.problems.append(Problem((*path, "from"), f"point {name} is measured from "
                                             f"{later}, which is listed after it",
                                             f"list {later} before {name} under points:"))
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            if origin_name is None:
                self.problems.append(Problem((*path, "from"), f"link {link!r} has no first "
                                             "point to measure from", "give from: a point "
                                             "of the link"))
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            origin = self.resolve(f"{link}.{origin_name.split('.')[-1]}", (*path, "from"))
            if origin is None:
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            if origin.name not in owner.local:
                self.problems.append(Problem((*path, "from"), f"{origin.name} is not a fixed "
                                             f"point of link {link!r}",
                                             f"measure from one of {', '.join(owner.local)}"))
                self.new_point(name, (link,), self.root, (), broken=True)
                continue
            seg = self.seg(f"{link} point {name}", origin.name, name,
                           ("const", distance, f"points.{name}.distance"),
                           self.angle_on(link, angle, f"points.{name}.angle"), link)
            owner.local[name] = owner.local[origin.name] + distance * cmath.exp(
                1j * angle * math.pi / self.half)
            owner.segments.append(seg)
            self.new_point(name, (link,), origin.ground, (*origin.path, (seg, +1)))

    def add_group(self, i: int, g: Any) -> None:
        kind = KIND[g.kind]
        path: tuple = ("groups", i)
        dim = f"groups[{i}]"
        l1, l2 = g.links
        if g.variant == 2 and kind in ("L3", "L4", "L5"):
            why = {"L3": "its slide passes through the guide's pivot",
                   "L4": "its two slides meet in one point",
                   "L5": "its slot and guide meet in one point"}[kind]
            self.problems.append(Problem((*path, "variant"), f"an {kind} group has one "
                                         f"assembly ({why})", "remove variant (or write 1)"))
        variant: Variant = 1 if kind in ("L3", "L4", "L5") else g.variant
        new = getattr(g, "joint", None) or getattr(g, "point", None)
        before = len(self.problems)
        built = getattr(self, f"_{kind.lower()}")(g, path, dim, l1, l2, variant)
        if not built or len(self.problems) > before:
            for link in (l1, l2):
                if link not in self.links:
                    self.new_link(link, None, 0.0, {}, None, None)
            if new is not None and new not in self.points:
                self.new_point(new, (l1, l2), self.root, (), broken=True)
        for link in (l1, l2):
            self.add_points(link)

    def _attach(self, refs: list[tuple[str, tuple]]) -> list[_Point] | None:
        out = [self.resolve(ref, p) for ref, p in refs]
        if any(p is None for p in out):
            return None
        names = [p.name for p in out if p is not None]
        if len(set(names)) < len(names):
            self.problems.append(Problem(refs[-1][1], f"both attachments are {names[0]}",
                                         "attach the group's links at two different points"))
            return None
        return out  # type: ignore[return-value]

    def _l1(self, g: RRR, path: tuple, dim: str, l1: str, l2: str, variant: Variant) -> bool:
        len1 = self.num(g.lengths[0], "length", (*path, "lengths", 0), positive=True,
                        dim=f"{dim}.lengths[0]")
        len2 = self.num(g.lengths[1], "length", (*path, "lengths", 1), positive=True,
                        dim=f"{dim}.lengths[1]")
        got = self._attach([(g.at[0], (*path, "at", 0)), (g.at[1], (*path, "at", 1))])
        if got is None:
            return False
        p1, p2 = got
        b = g.joint
        u = self.seg(f"{l1} {p1.name}{b}", p1.name, b, ("const", len1, f"{dim}.lengths[0]"),
                     ("function",), l1)
        w = self.seg(f"{l2} {b}{p2.name}", b, p2.name, ("const", len2, f"{dim}.lengths[1]"),
                     ("function",), l2)
        self.loop((p1.ground, p1.path), [(u, +1), (w, +1)], (p2.ground, p2.path),
                  name=f"L1 {l1}-{l2}", variant=variant, module="Pl4")
        self.new_link(l1, u, 0.0, {p1.name: 0j, b: complex(len1)}, p1.name, b)
        self.new_link(l2, w, self.half, {p2.name: 0j, b: complex(len2)}, p2.name, b)
        self.links[l1].segments.append(u)
        self.links[l2].segments.append(w)
        via1 = (p1.ground, (*p1.path, (u, +1)))
        via2 = (p2.ground, (*p2.path, (w, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(b, (l1, l2), ground, chain)
        self.pins += [(p1.name, p1.links[0], l1, u, "tail"), (b, l1, l2, u, "head"),
                      (p2.name, p2.links[0], l2, w, "head")]
        return True

    def _l2(self, g: RRP, path: tuple, dim: str, rod: str, slider: str,
            variant: Variant) -> bool:
        length = self.num(g.length, "length", (*path, "length"), positive=True,
                          dim=f"{dim}.length")
        guide = self.guide(g.guide, (*path, "guide"), f"{dim}.guide")
        got = self._attach([(g.at, (*path, "at"))])
        if got is None or guide is None:
            return False
        (p1,), (through, angle, offset) = got, guide
        b = g.joint
        u = self.seg(f"{rod} {p1.name}{b}", p1.name, b, ("const", length, f"{dim}.length"),
                     ("function",), rod)
        s = self.seg(f"{slider} {b} along guide", b, ".foot", ("function",),
                     self.angle_on(through.links[0], angle + self.half, f"{dim}.guide.angle"),
                     slider, held={"tail": slider, "head": through.links[0]})
        side2 = self.guide_chain(through, offset, s, -90.0, f"{dim}.guide",
                                 f"guide offset of {slider}")
        self.loop((p1.ground, p1.path), [(u, +1), (s, +1)], (through.ground, side2),
                  name=f"L2 {rod}-{slider}", variant=variant, module="Pl3")
        self.new_link(rod, u, 0.0, {p1.name: 0j, b: complex(length)}, p1.name, b)
        self.new_link(slider, s, self.half, {b: 0j}, b, None)
        self.links[rod].segments.append(u)
        self.links[slider].segments.append(s)
        via1 = (p1.ground, (*p1.path, (u, +1)))
        via2 = (through.ground, (*side2, (s, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(b, (rod, slider), ground, chain)
        self.pins += [(p1.name, p1.links[0], rod, u, "tail"), (b, rod, slider, u, "head")]
        self.slides.append((f"S{b}", through.links[0], slider, s, s, "tail"))
        return True

    def _l3(self, g: RPR, path: tuple, dim: str, block: str, lever: str,
            variant: Variant) -> bool:
        got = self._attach([(g.at[0], (*path, "at", 0)), (g.at[1], (*path, "at", 1))])
        if got is None:
            return False
        p1, p2 = got
        v = self.seg(f"{block}/{lever} {p1.name}{p2.name}", p1.name, p2.name, ("function",),
                     ("function",), lever, held={"tail": block, "head": lever})
        self.loop((p1.ground, p1.path), [(v, +1)], (p2.ground, p2.path),
                  name=f"L3 {block}-{lever}", variant=variant, module="Pl1")
        self.new_link(block, v, self.half, {p1.name: 0j}, p1.name, None)
        self.new_link(lever, v, self.half, {p2.name: 0j}, p2.name, None)
        self.links[block].segments.append(v)
        self.links[lever].segments.append(v)
        self.pins += [(p1.name, p1.links[0], block, v, "tail"),
                      (p2.name, p2.links[0], lever, v, "head")]
        self.slides.append((f"S{p1.name}", block, lever, v, v, "tail"))
        return True

    def _l4(self, g: PRP, path: tuple, dim: str, l1: str, l2: str, variant: Variant) -> bool:
        guide1 = self.guide(g.guides[0], (*path, "guides", 0), f"{dim}.guides[0]")
        guide2 = self.guide(g.guides[1], (*path, "guides", 1), f"{dim}.guides[1]")
        if guide1 is None or guide2 is None:
            return False
        (t1, angle1, off1), (t2, angle2, off2) = guide1, guide2
        b = g.joint
        u = self.seg(f"{l1} along guide to {b}", ".foot1", b, ("function",),
                     self.angle_on(t1.links[0], angle1, f"{dim}.guides[0].angle"), l1,
                     held={"tail": t1.links[0], "head": l1})
        w = self.seg(f"{l2} {b} along guide", b, ".foot2", ("function",),
                     self.angle_on(t2.links[0], angle2 + self.half, f"{dim}.guides[1].angle"),
                     l2, held={"tail": l2, "head": t2.links[0]})
        side1 = self.guide_chain(t1, off1, u, +90.0, f"{dim}.guides[0]",
                                 f"guide offset of {l1}")
        side2 = self.guide_chain(t2, off2, w, -90.0, f"{dim}.guides[1]",
                                 f"guide offset of {l2}")
        self.loop((t1.ground, side1), [(u, +1), (w, +1)], (t2.ground, side2),
                  name=f"L4 {l1}-{l2}", variant=variant, module="Pl2")
        self.new_link(l1, u, 0.0, {b: 0j}, b, None)
        self.new_link(l2, w, self.half, {b: 0j}, b, None)
        self.links[l1].segments.append(u)
        self.links[l2].segments.append(w)
        via1 = (t1.ground, (*side1, (u, +1)))
        via2 = (t2.ground, (*side2, (w, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(b, (l1, l2), ground, chain)
        self.slides.append((f"S{b}", t1.links[0], l1, u, u, "head"))
        self.pins.append((b, l1, l2, u, "head"))
        self.slides.append((f"S{b}", t2.links[0], l2, w, w, "tail"))
        return True

    def _l5(self, g: RPP, path: tuple, dim: str, block: str, yoke: str,
            variant: Variant) -> bool:
        guide = self.guide(g.guide, (*path, "guide"), f"{dim}.guide")
        slot = self.num(g.slot, "angle", (*path, "slot"), dim=f"{dim}.slot")
        got = self._attach([(g.at, (*path, "at"))])
        if got is None or guide is None:
            return False
        (p1,), (through, angle, offset) = got, guide
        if abs(math.sin(slot * math.pi / self.half)) < 1e-9:
            self.problems.append(Problem((*path, "slot"), "the slot runs along the guide, so "
                                         "the yoke's position along it is not determined",
                                         "give the slot an angle to the guide (90 for a "
                                         "Scotch yoke)"))
            return False
        point = g.point
        # P1 -> W back along the slot, W -> the guide's origin back along the guide
        w = self.seg(f"{yoke} {point} along guide", point, ".foot", ("function",),
                     self.angle_on(through.links[0], angle + self.half, f"{dim}.guide.angle"),
                     yoke, held={"tail": yoke, "head": through.links[0]})
        s = self.seg(f"{yoke} slot {p1.name}{point}", p1.name, point, ("function",),
                     ("link", w, "a", slot, f"{dim}.slot"), yoke,
                     held={"tail": block, "head": yoke})
        side2 = self.guide_chain(through, offset, w, -90.0, f"{dim}.guide",
                                 f"guide offset of {yoke}")
        self.loop((p1.ground, p1.path), [(s, +1), (w, +1)], (through.ground, side2),
                  name=f"L5 {block}-{yoke}", variant=variant, module="Pl2")
        self.new_link(block, s, self.half, {p1.name: 0j}, p1.name, None)
        self.new_link(yoke, w, self.half, {point: 0j}, point, None)
        self.links[block].segments.append(s)
        self.links[yoke].segments += [w, s]
        via1 = (p1.ground, (*p1.path, (s, +1)))
        via2 = (through.ground, (*side2, (w, -1)))
        ground, chain = via1 if len(via1[1]) <= len(via2[1]) else via2
        self.new_point(point, (yoke,), ground, chain)
        self.pins.append((p1.name, p1.links[0], block, s, "tail"))
        self.slides.append((f"S{p1.name}", block, yoke, s, s, "tail"))
        self.slides.append((f"S{point}", through.links[0], yoke, w, w, "tail"))
        return True

    def close_loose_ends(self) -> None:
        """Pl1 contours for the input and the points of links that no group used."""
        joint = self.points[self.mech.input.joint]
        if any(self.segs[s].vector is None for s, _ in joint.path):
            closer = self.seg(f"closing {joint.name}{joint.ground}", joint.name, joint.ground,
                              ("function",), ("function",), GROUND)
            self.contour([*joint.path, (closer, +1)], start=self.start_at(joint.ground),
                         name=f"input {self.mech.input.link}")
        for name in self.mech.points:
            point = self.points.get(name)
            if point is None or point.broken:
                continue
            seg_id, _ = point.path[-1]
            seg = self.segs[seg_id]
            if seg.vector is None:
                self.closing(seg_id, self.handle(seg.tail), f"point {name}")

    # -- output ----------------------------------------------------------------------------

    def role(self, template: Template, letter: str, reversed_: bool) -> Any:
        turn = self.half if reversed_ and letter == "a" else 0.0
        kind = template[0]
        if kind == "const":
            return _tidy(template[1] + turn, self.half) if letter == "a" else template[1]
        if kind == "function":
            return "function"
        if kind == "arg":
            offset = _tidy(template[2] + turn, self.half) if letter == "a" else template[2]
            return {"argument": template[1], "offset": offset}
        target = self.segs[template[1]]
        back = self.half if target.reversed and letter == "a" else 0.0
        delta = template[3] + turn - back
        if letter == "a":
            delta = _tidy(delta, self.half)
        return {"link": f"{letter}{target.vector}", "delta": delta}

    def model_data(self) -> dict[str, Any]:
        mech = self.mech
        vectors = {}
        for number, vec in self.vectors.items():
            vectors[number] = {"r": self.role(vec.r, "r", vec.reversed),
                               "a": self.role(vec.a, "a", vec.reversed), "name": vec.name}
        data: dict[str, Any] = {
            "name": mech.name, "description": mech.description, "units": mech.units,
            "positions": mech.positions, "time": mech.time, "arguments": mech.arguments,
            "vectors": vectors, "contours": self.contours, "bodies": self.bodies(),
            "joints": self.joints(), "friction": mech.friction,
        }
        for key in ("gravity", "machine"):
            if getattr(mech, key) is not None:
                data[key] = getattr(mech, key)
        data["forces"] = self.forces()
        data["moments"] = [{"body": self.links[m.link].body, "value": m.value,
                            **({"name": m.name} if m.name else {})}
                           for i, m in enumerate(mech.moments)
                           if self.link_of(m.link, ("moments", i, "link"))]
        return data

    def link_of(self, name: str, path: tuple) -> _Link | None:
        if name in self.links and name != GROUND:
            return self.links[name]
        self.problems.append(Problem(path, f"no moving link named {name!r}",
                                     _choose(name, [k for k in self.links if k != GROUND])))
        return None

    def bodies(self) -> dict[int, dict[str, Any]]:
        out: dict[int, dict[str, Any]] = {}
        ground_slides: list[int] = []
        for link in self.links.values():
            if link.name == GROUND:
                continue
            order = sorted(set(link.segments), key=lambda s: (s != link.ref, s))
            numbers = [self.segs[s].vector for s in order]
            body: dict[str, Any] = {"name": link.name, "vectors": numbers}
            ends = {}
            for s in order:
                seg = self.segs[s]
                if seg.held:
                    end = next(e for e, owner in seg.held.items() if owner == link.name)
                    ends[seg.vector] = "head" if (end == "head") != seg.reversed else "tail"
                    if seg.held.get("tail" if end == "head" else "head") == GROUND \
                            and seg.r[0] == "arg":
                        ground_slides.append(s)
            if ends:
                body["ends"] = ends
            body.update(self.mass(link))
            out[link.body] = body
        if ground_slides:  # a driven slide: its other end is held by the ground
            segs = [self.segs[s] for s in ground_slides]
            out[0] = {"name": GROUND, "vectors": [s.vector for s in segs],
                      "ends": {s.vector: "tail" if (s.held["tail"] == GROUND) != s.reversed
                               else "head" for s in segs}}
        return dict(sorted(out.items()))

    def joints(self) -> dict[str, dict[str, Any]]:
        out: dict[str, dict[str, Any]] = {}

        def name_for(base: str) -> str:
            if base not in out:
                return base
            n = 2
            while f"{base}{n}" in out:
                n += 1
            return f"{base}{n}"

        pins = [(n, a, b, s, e, None) for n, a, b, s, e in self.pins]
        for n, first, second, seg, end, along in pins + [
                (n, a, b, s, e, al) for n, a, b, al, s, e in self.slides]:
            entry: dict[str, Any] = {
                "type": "revolute" if along is None else "prismatic",
                "bodies": [self.links[first].body, self.links[second].body],
                "at": self.end_of(seg, end)}
            if along is not None:
                entry["along"] = self.segs[along].vector
            out[name_for(n)] = entry
        return out

    def place_on(self, link: _Link, spec: Any, path: tuple
                 ) -> tuple[TailPoint | HeadPoint | VectorPoint, int, float] | None:
        """A place on ``link`` as a point on one of its vectors, with a vector of the body
        and that vector's angle from the link's line (for directions)."""
        if isinstance(spec, Share):
            if link.second is None:
                self.problems.append(Problem(path, f"link {link.name!r} has no second point, "
                                             "so no line to take a share of",
                                             "give a point name or {from: X, distance: d, "
                                             "angle: φ}"))
                return None
            a, b = link.local[link.first], link.local[link.second]
            local = a + spec.share * (b - a)
            for s in link.segments:
                seg = self.segs[s]
                if seg.r[0] == "const" and {seg.tail, seg.head} == {link.first, link.second}:
                    share = spec.share if seg.tail == link.first else 1.0 - spec.share
                    if seg.reversed:
                        share = 1.0 - share
                    return VectorPoint(vector=seg.vector, share=share), *self.direction(link)
        elif isinstance(spec, str):
            name = spec.split(".")[-1].strip()
            if name not in link.local:
                self.problems.append(Problem(path, f"{name!r} is not a point of link "
                                             f"{link.name!r}", f"use one of "
                                             f"{', '.join(link.local)}"))
                return None
            for s in link.segments:
                seg = self.segs[s]
                for end in ("tail", "head"):
                    point = seg.tail if end == "tail" else seg.head
                    fixed = seg.r[0] == "const" or seg.held.get(end) == link.name
                    if point == name and fixed:
                        return self.end_of(s, end), *self.direction(link)
            local = link.local[name]
        else:
            origin = (spec.from_ or link.first or "").split(".")[-1].strip()
            if origin not in link.local:
                self.problems.append(Problem((*path, "from"), f"{origin!r} is not a point of "
                                             f"link {link.name!r}", f"use one of "
                                             f"{', '.join(link.local)}"))
                return None
            d = self.num(spec.distance, "length", (*path, "distance"))
            phi = self.num(spec.angle, "angle", (*path, "angle"))
            local = link.local[origin] + d * cmath.exp(1j * phi * math.pi / self.half)
        for s in link.segments:
            seg = self.segs[s]
            tail_end = "head" if seg.reversed else "tail"  # the seg end at the vector's tail
            tail_point = seg.head if seg.reversed else seg.tail
            fixed = seg.r[0] == "const" or seg.held.get(tail_end) == link.name
            if not fixed or tail_point not in link.local:
                continue
            delta = self.line_delta(link, s) * math.pi / self.half
            w = (local - link.local[tail_point]) * cmath.exp(-1j * delta)
            return (VectorPoint(vector=seg.vector, along=w.real, across=w.imag),
                    *self.direction(link))
        self.problems.append(Problem(path, f"link {link.name!r} has no vector with a fixed "
                                     "tail to place this point from",
                                     f"define a point there (points: {{S: {{link: "
                                     f"{link.name}, from: ..., distance: ..., angle: ...}}}}) "
                                     "and name it"))
        return None

    def direction(self, link: _Link) -> tuple[int, float]:
        assert link.ref is not None
        return self.segs[link.ref].vector, self.line_delta(link, link.ref)

    def line_delta(self, link: _Link, s: int) -> float:
        """Angle of segment ``s``'s written vector from the line of ``link`` (model
        units)."""
        seg = self.segs[s]
        return self.seg_delta(link, s) + (self.half if seg.reversed else 0.0)

    def seg_delta(self, link: _Link, s: int) -> float:
        """Angle of segment ``s`` (as defined, tail to head) from the line of ``link``."""
        if s == link.ref:
            return link.ref_delta
        template = self.segs[s].a
        assert template[0] == "link", "a vector of a moving link follows the link's angle"
        return template[3] + self.seg_delta(link, template[1])

    def mass(self, link: _Link) -> dict[str, Any]:
        spec = self.mech.masses.get(link.name)
        if spec is None:
            return {}
        path = ("masses", link.name)
        out: dict[str, Any] = {"mass": spec.mass}
        if spec.center is None:
            self.problems.append(Problem(path, f"link {link.name!r} has a mass but no centre "
                                         "of mass", "add center: a point name, {share: "
                                         "0.5} or {from: A, distance: d, angle: φ}"))
            return out
        placed = self.place_on(link, spec.center, (*path, "center"))
        if placed is None:
            return out
        out["center"] = placed[0]
        if spec.inertia == "rod":
            if link.second is None:
                self.problems.append(Problem((*path, "inertia"), f"'rod' needs the length of "
                                             f"the link, and {link.name!r} has no second "
                                             "point", "give the moment of inertia as a "
                                             "number"))
                return out
            if isinstance(placed[0], VectorPoint) and self._on_line(link, placed[0].vector):
                out["inertia"] = "rod"  # from the line vector's length: follows synthesis
                return out
            length = abs(link.local[link.second] - link.local[link.first])
            units = self.units
            try:
                m = to_si(spec.mass, "mass", units.mass)
                inertia = m * (length * unit_factor(units.length, "length")) ** 2 / 12.0
                out["inertia"] = inertia / unit_factor(units.inertia, "inertia")
            except UnitProblem as exc:
                self.problems.append(Problem((*path, "mass"), exc.message, exc.hint))
        else:
            out["inertia"] = spec.inertia
        return out

    def _on_line(self, link: _Link, vector: int) -> bool:
        """Whether ``vector`` is the link's line from its first to its second point, of
        constant length."""
        return any(self.segs[s].vector == vector and self.segs[s].r[0] == "const"
                   and {self.segs[s].tail, self.segs[s].head} == {link.first, link.second}
                   for s in link.segments)

    def forces(self) -> list[dict[str, Any]]:
        out = []
        for i, f in enumerate(self.mech.forces):
            path = ("forces", i)
            link = self.link_of(f.link, (*path, "link"))
            if link is None:
                continue
            placed = self.place_on(link, f.at, (*path, "at"))
            if placed is None:
                continue
            at, vector, delta = placed
            entry: dict[str, Any] = {"body": link.body, "at": at, "value": f.value,
                                     "angle": f.angle}
            if f.follow:
                entry["along"] = vector
                entry["angle"] = self.num(f.angle, "angle", (*path, "angle")) - delta
            if f.name:
                entry["name"] = f.name
            out.append(entry)
        return out

    def locations(self) -> dict[str, PointLocation]:
        out = {}
        for name, point in self.points.items():
            if name not in self.declared or point.broken:
                continue
            signed = []
            for seg_id, direction in point.path:
                seg = self.segs[seg_id]
                assert seg.vector is not None
                signed.append(seg.vector if (direction > 0) != seg.reversed else -seg.vector)
            end = None
            for seg in sorted(self.segs, key=lambda s: s.vector or 1 << 30):
                if seg.vector is not None and name in (seg.tail, seg.head):
                    end = self.end_of(seg.id, "tail" if seg.tail == name else "head")
                    break
            z = self.coords[point.ground]
            out[name] = PointLocation(name, (z.real, z.imag), tuple(signed), end,
                                      tuple(point.links))
        return out

    def dimension_names(self) -> list[str]:
        """What synthesis may vary: every carried dimension (a ground point by its x and y
        rather than its polar form from the root)."""
        carried = [k for k in self.carriers() if not k.startswith(f"{GROUND}.")]
        return carried + [f"{GROUND}.{g}.{axis}" for g in self.mech.ground for axis in "xy"]

    def ties(self, name: str, varied: set[str], carried: dict[str, tuple[Carrier, ...]]
             ) -> tuple[float, list[Tie]]:
        """The value of dimension ``name`` (model units) and the constants it sets, when
        the dimensions ``varied`` are varied together.

        A ground point's coordinate sets the starts of the contours that start there and
        a component of every frame vector it ends (from the root: the point minus the
        root, negated when the written vector is reversed); the other point's part of that
        component is the shift unless it is varied too.
        """
        match = _GROUND_XY.match(name)
        if match is None:
            return self.dims[name], [Tie(set=c.parameter, shift=c.shift)
                                     for c in carried[name]]
        ground, axis = match.groups()
        pick = (lambda z: z.real) if axis == "x" else (lambda z: z.imag)
        ties = [Tie(set=f"start{k}.{axis}") for k, g in self.starts.items() if g == ground]
        for other, seg_id in self.frames.items():
            seg = self.segs[seg_id]
            sign = -1.0 if seg.reversed else 1.0
            if ground == other:
                factor, partner = sign, self.root
            elif ground == self.root:
                factor, partner = -sign, other
            else:
                continue
            shift = 0.0 if f"{GROUND}.{partner}.{axis}" in varied else \
                -factor * pick(self.coords[partner]) + 0.0
            ties.append(Tie(set=f"v{seg.vector}.{axis}", factor=factor, shift=shift))
        return pick(self.coords[ground]), ties

    def synthesis(self, task: GroupSynthesisTask) -> dict[str, Any]:
        """The vector model's synthesis task: each varied dimension with the constants it
        sets (``dimensions``), named points as vector ends."""
        base = ("synthesis",)
        if task.dimensions:
            self.problems.append(Problem((*base, "dimensions"), "a group file names its "
                                         "dimensions in vary:; mechloop writes "
                                         "dimensions: into the vector model",
                                         "remove dimensions:"))
        carried = self.carriers()
        names = self.dimension_names()
        dims: dict[str, Any] = {}
        for name in task.vary:
            if name not in names:
                self.problems.append(Problem((*base, "vary", name), f"no dimension named "
                                             f"{name!r}", _choose(name, names, "dimensions "
                                             "as the file spells them")))
                continue
            value, ties = self.ties(name, set(task.vary), carried)
            if not ties:
                self.problems.append(Problem((*base, "vary", name), f"{name} moves nothing: "
                                             "no contour passes that ground point",
                                             "vary a point that a group uses"))
                continue
            dims[name] = {"value": value, "sets": [t.model_dump() for t in ties]}
        data = task.model_dump(mode="json", by_alias=True, exclude_defaults=True,
                               exclude={"dimensions"})
        data["dimensions"] = dims
        locations = self.locations()

        def end(ref: str, path: tuple) -> Any:
            link, _, name = ref.strip().rpartition(".")
            where = locations.get(name.strip())
            if where is None:
                self.problems.append(Problem(path, f"no point named {name.strip()!r}",
                                             _choose(name.strip(), list(locations),
                                                     "named points")))
            elif link and link.strip() not in where.links:
                self.problems.append(Problem(path, f"point {where.name!r} is not on link "
                                             f"{link.strip()!r}", f"{where.name} is on "
                                             f"{', '.join(where.links)}"))
            elif where.end is None:
                self.problems.append(Problem(path, f"{where.name} is a ground point that no "
                                             "vector reaches", "trace a point of a link"))
            else:
                return where.end.model_dump()
            return {"head": 1}

        if task.path is not None:
            data["path"]["point"] = end(task.path.point, (*base, "path", "point"))
        if task.motion is not None:
            data["motion"]["point"] = end(task.motion.point, (*base, "motion", "point"))
        if task.workspace is not None:
            data["workspace"]["points"] = [
                end(ref, (*base, "workspace", "points", i))
                for i, ref in enumerate(task.workspace.points)]
        return data

    def carriers(self) -> dict[str, tuple[Carrier, ...]]:
        found: dict[str, list[Carrier]] = {}
        for seg in self.segs:
            if seg.vector is None:
                continue
            for letter in "ra":
                template = seg.r if letter == "r" else seg.a
                dim = template[-1] if template[0] in ("const", "arg", "link") else None
                if dim is None or dim not in self.dims:
                    continue
                role = self.role(template, letter, seg.reversed)
                part: Literal["value", "delta", "offset"]
                if isinstance(role, dict):
                    part = "offset" if "argument" in role else "delta"
                    value = role["offset" if "argument" in role else "delta"]
                else:
                    part, value = "value", role
                shift = round(value - self.dims[dim], 9) + 0.0
                found.setdefault(dim, []).append(Carrier(f"{letter}{seg.vector}", part, shift))
        return {k: tuple(v) for k, v in found.items()}


def _plain(value: Scalar) -> float | None:
    """A number in model units as a float (exactly as written); None for a quantity."""
    if not isinstance(value, str):
        return float(value)
    try:
        return float(value.strip())
    except ValueError:
        return None


def _tidy(angle: float, half: float) -> float:
    """An angle folded into (−half, half] (half a turn in model units) by whole turns
    (exactly, in one step: :func:`math.remainder`)."""
    folded = math.remainder(angle, 2 * half)
    return half if folded == -half else folded


def _choose(name: str, options: list[str], what: str | None = None) -> str:
    close = get_close_matches(name, options, n=1)
    listed = ", ".join(options) if options else "none yet"
    hint = f"use one of: {listed}" + (f" ({what})" if what else "")
    return f"did you mean {close[0]!r}? " + hint if close else hint
