"""The schema of a group file: the input group, the dyads L1–L5, the triads, points on
links, masses, loads and the synthesis task, as pydantic classes (see
:mod:`mechloop.model.groups` for what the names and dimensions mean).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import ConfigDict, Discriminator, Field, Tag, model_validator
from pydantic.json_schema import SkipJsonSchema

from mechloop.model.dynamic import (
    Friction,
    Gravity,
    Inertia,
    LoadValue,
    Machine,
)
from mechloop.model.project import Project
from mechloop.model.schema import Units
from mechloop.model.signals import MAX_POSITIONS, Argument, Number, Scalar, Time, _Frozen
from mechloop.model.synthesis import (
    Dimension,
    MotionTask,
    PathTask,
    SynthesisTask,
    Workspace,
)

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


class LegDrive(_Frozen):
    """The length of a driven leg: model argument ``argument`` plus ``shift``."""

    argument: int = Field(ge=1, description="the model argument that sets the length")
    shift: Scalar = Field(0.0, description="added to the argument (length units)")


class TriadLeg(_Frozen):
    """An outer link (leg) of a triad: pinned to the middle link at ``joint``, and either
    pinned to the placed point ``at`` (``length`` from ``at`` to ``joint``: an RR leg) or
    sliding along a ground ``guide`` (a block at ``joint``: a PR leg).  A leg whose length
    is an argument (``length: {argument: 1}``) is a hydraulic leg: the mechanism's drive
    between ``at`` and ``joint`` (massless, not a link: it has no ``link``), and the triad
    with it is the input group."""

    link: Name | None = Field(None, description="name of the leg (none for a driven leg)")
    joint: Name = Field(description="name of the pin between the leg and the middle link "
                        "(a new point)")
    at: PointRef | None = Field(None, description="the placed point the leg is pinned to "
                                "(an RR leg; with length)")
    length: Scalar | LegDrive | None = Field(
        None, description="|at joint| (length units; an RR leg), or {argument: k, shift: "
        "c}: a driven leg")
    guide: Guide | None = Field(None, description="the ground guide the leg's block slides "
                                "along (a PR leg, instead of at and length)")

    @property
    def driven(self) -> bool:
        """Whether the leg's length is an argument (a hydraulic leg)."""
        return isinstance(self.length, LegDrive)

    @model_validator(mode="after")
    def _one_kind(self) -> TriadLeg:
        if self.guide is None and (self.at is None or self.length is None):
            raise ValueError("a leg is pinned ({at: A, length: l}) or slides ({guide: "
                             "{through: O, angle: φ}}): give at and length, or guide")
        if self.guide is not None and (self.at is not None or self.length is not None):
            raise ValueError("a leg is pinned (at, length) or slides (guide), not both")
        if self.driven and self.link is not None:
            raise ValueError("a driven leg is a drive between its two points, not a link: "
                             "remove its link")
        if not self.driven and self.link is None:
            raise ValueError("a leg needs link: its name")
        return self


class Triad(_Frozen):
    """A class-III group (triad): a ternary middle link ``link`` pinned at the three legs'
    joints J1, J2, J3 (its line runs from J1 to J2; J2 is ``sides[0]`` from J1, J3 is
    ``sides[1]`` from J1 at ``angle`` from the line), and three legs (:class:`TriadLeg`)
    joining it to placed points or ground guides — RRR-RRR-RRR, or with sliding legs.

    A triad has no elementary module: its two contours need each other's unknowns and are
    solved together (a coupled block).  Its assembly is chosen by ``guess``: approximate
    positions at position 0 of the three joints and of any leg attachment that moves."""

    kind: Literal["III", "triad"]
    link: Name = Field(description="name of the middle (ternary) link")
    legs: tuple[TriadLeg, TriadLeg, TriadLeg] = Field(description="the three legs; the "
                                                      "middle link's line runs from the "
                                                      "first joint to the second")
    sides: tuple[Scalar, Scalar] = Field(description="[|J1 J2|, |J1 J3|] on the middle "
                                         "link (length units)")
    angle: Scalar = Field(description="angle from J1→J2 to J1→J3, counter-clockwise "
                          "(angle units; 0 or 180 for three pins on a straight link)")
    guess: dict[Name, tuple[Scalar, Scalar]] = Field(
        description="approximate positions [x, y] at position 0 (length units) of the three "
        "joints and of every moving point a leg is pinned to: the assembly the triad "
        "starts in")

    @property
    def links(self) -> tuple[str, ...]:
        """The legs (but a driven one) and the middle link, in the order their bodies are
        numbered."""
        return (*(leg.link for leg in self.legs if leg.link is not None), self.link)

    @property
    def driven(self) -> bool:
        """Whether a leg of the triad is driven (the triad is then the input group)."""
        return any(leg.driven for leg in self.legs)


KIND = {"L1": "L1", "RRR": "L1", "L2": "L2", "RRP": "L2", "L3": "L3", "RPR": "L3",
        "L4": "L4", "PRP": "L4", "L5": "L5", "RPP": "L5", "III": "III", "triad": "III"}

Group = Annotated[
    Annotated[RRR, Tag("L1")] | Annotated[RRP, Tag("L2")] | Annotated[RPR, Tag("L3")]
    | Annotated[PRP, Tag("L4")] | Annotated[RPP, Tag("L5")] | Annotated[Triad, Tag("III")],
    Discriminator(lambda v: KIND.get(_kind_tag(v) or ""), custom_error_type="group_kind",
                  custom_error_message="a group's kind is L1 (RRR), L2 (RRP), L3 (RPR), "
                  "L4 (PRP), L5 (RPP) or III (a triad)"),
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
        "groups[i].legs[j].length, groups[i].legs[j].guide.angle, groups[i].sides[k], "
        "groups[i].angle, "
        "points.NAME.distance, points.NAME.angle, ground.NAME.x, ground.NAME.y")
    path: GroupPathTask | None = None  # type: ignore[assignment]
    motion: GroupMotionTask | None = None  # type: ignore[assignment]
    workspace: GroupWorkspace | None = None  # type: ignore[assignment]
    dimensions: SkipJsonSchema[dict[str, Dimension]] = Field(  # type: ignore[assignment]
        default_factory=dict, description="written by the builder, not in a group file")


class GroupMechanism(_Frozen):
    """A planar mechanism as an input group plus class-II Assur groups (see the module
    docstring for points, lines and variants).  ``units``, ``positions``, ``time``,
    ``arguments``, ``gravity``, ``friction``, ``machine`` and ``project`` are those of
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
    input: Input | None = Field(None, description="the input group L0: a crank or a driven "
                                "slider (none when a triad has a driven leg)")
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
    project: Project | None = Field(
        None, description="the course project's cam (sheet 4) and gear pair or planetary "
        "train (sheet 3) documents, paths relative to this file (as in a vector model)")
    synthesis: GroupSynthesisTask | None = Field(
        None, description="a synthesis task that varies the dimensions by their names "
        "(mechloop synthesize)")

    @model_validator(mode="after")
    def _one_drive(self) -> GroupMechanism:
        driven = sum(leg.driven for g in self.groups if isinstance(g, Triad) for leg in g.legs)
        if self.input is None and driven != 1:
            raise ValueError("the mechanism needs one input: give input: (a crank or a "
                             "slider), or drive one leg of a triad (length: {argument: 1})")
        if self.input is not None and driven:
            raise ValueError("a triad's leg is driven and there is an input: drive the "
                             "mechanism once (remove input:, or give the leg a length)")
        return self

    @property
    def formula(self) -> str:
        """The structure formula the generated model has: ``L0(1) → L1(2,3) → …``; a
        triad with a driven leg is the input group (``L0(1,2,3)``)."""
        parts, body = (["L0(1)"], 2) if self.input is not None else ([], 1)
        for g in self.groups:
            count = len(g.links)
            kind = "L0" if isinstance(g, Triad) and g.driven else KIND[g.kind]
            parts.append(f"{kind}({','.join(map(str, range(body, body + count)))})")
            body += count
        return " → ".join(parts)


def group_json_schema() -> dict[str, Any]:
    """The JSON Schema of a model file built from Assur groups."""
    schema = GroupMechanism.model_json_schema(by_alias=True)
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "mechloop mechanism built from Assur groups"
    return schema
