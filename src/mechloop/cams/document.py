"""The ``cam:`` document: a cam design as a file (YAML or JSON), read with located errors.

::

    cam:
      name: Disc cam, offset roller follower
      units: {length: mm, angle: deg}
      follower: {type: translating_roller, roller_radius: 10, offset: 12}
      pressure_angle: 30          # allowed; without base_radius: R0 = the smallest
      speed: {rpm: 120}
      segments:
        - {rise: 20, angle: 120, law: cycloidal}
        - {dwell: 60}
        - {return: 20, angle: 120, law: poly345}
        - {dwell: 60}

Lengths are in ``units.length``, angles (segment angles, pressure angles, a rocker's
swing) in ``units.angle``; any value may carry its own unit ("37 mm").  A segment is a
rise, a return (``{rise|return: lift, angle: β, law: name}``, or ``table:`` points
``[angle, displacement]`` from the segment's start instead of a law) or a dwell
(``{dwell: β}``).  Every problem is reported at once, with its line and the fix
(:func:`load_cam`).
"""

from __future__ import annotations

import itertools
import math
import os
from typing import Any, Literal

from pydantic import Field, model_validator

from mechloop.cams.base_radius import CamDesignError
from mechloop.cams.design import CamDesign
from mechloop.cams.followers import (
    Follower,
    OscillatingFlat,
    OscillatingRoller,
    TranslatingFlat,
    TranslatingRoller,
    base_limits,
)
from mechloop.cams.laws import LAW_NAMES, law, table_law
from mechloop.cams.program import TURN_TOLERANCE, MotionProgram, Segment
from mechloop.errors import ModelError, Problem
from mechloop.model.document import located_error, read_document, validate_data
from mechloop.model.numbers import Number, Scalar
from mechloop.model.signals import _Frozen
from mechloop.model.units import UnitProblem, to_si

LawName = Literal["constant_speed", "harmonic", "cycloidal", "poly345", "poly4567",
                  "modified_trapezoidal", "modified_sine"]
assert set(LawName.__args__) == set(LAW_NAMES)  # type: ignore[attr-defined]


class CamUnits(_Frozen):
    """Units of the numbers in the cam document."""

    length: str = Field("mm", max_length=100, description="length unit: mm, m, ...")
    angle: str = Field("deg", max_length=100, description="angle unit: deg, rad")


class FollowerSpec(_Frozen):
    """The follower: its type and dimensions (length units)."""

    type: Literal["translating_roller", "oscillating_roller", "translating_flat",
                  "oscillating_flat"] = Field(
        description="translating_roller, oscillating_roller (a rocker), translating_flat "
        "(a flat face perpendicular to its axis through the cam centre) or "
        "oscillating_flat (a flat face on a rocker)")
    roller_radius: Scalar | None = Field(None, description="roller radius (roller "
                                         "followers)")
    offset: Scalar = Field(0.0, description="translating roller: offset e of the axis "
                           "from the cam centre, along +x (the cam turns "
                           "counter-clockwise)")
    pivot_distance: Scalar | None = Field(None, description="rocker: distance from the "
                                          "cam centre to the rocker's pivot")
    arm: Scalar | None = Field(None, description="rocker: pivot to roller centre")
    face_offset: Scalar = Field(0.0, description="oscillating_flat: distance of the face "
                                "from the pivot (positive: away from the cam)")


class SpeedSpec(_Frozen):
    """The cam's speed."""

    rpm: Number = Field(gt=0, le=1e6, description="cam speed, revolutions per minute")


class SegmentSpec(_Frozen):
    """One segment: ``{rise: h, angle: β, law: L}``, ``{return: h, angle: β, law: L}``,
    ``{dwell: β}`` or ``{table: [[angle, displacement], ...]}`` (from the segment's start;
    displacements going up for a rise, down for a return)."""

    model_config = _Frozen.model_config | {"populate_by_name": True}

    rise: Scalar | None = Field(None, description="lift of a rise (length; a rocker: angle)")
    return_: Scalar | None = Field(None, alias="return", description="lift of a return "
                                   "(length; a rocker: angle)")
    dwell: Scalar | None = Field(None, description="cam angle of a dwell")
    angle: Scalar | None = Field(None, description="cam angle of a rise or return")
    law: LawName | None = Field(None, description="the motion law: " + ", ".join(LAW_NAMES))
    table: list[tuple[Scalar, Scalar]] | None = Field(
        None, min_length=2, description="[cam angle, displacement] from the segment's "
        "start, angles increasing, first [0, 0]: a quintic spline with zero velocity and "
        "acceleration at both ends")

    @model_validator(mode="after")
    def _one_kind(self) -> SegmentSpec:
        kinds = [k for k, v in (("rise", self.rise), ("return", self.return_),
                                ("dwell", self.dwell), ("table", self.table))
                 if v is not None]
        if len(kinds) != 1:
            raise ValueError("a segment is exactly one of rise, return, dwell or table "
                             f"(got {', '.join(kinds) or 'none'})")
        if kinds[0] in ("rise", "return") and (self.angle is None or self.law is None):
            raise ValueError(f"a {kinds[0]} needs its angle and law")
        if kinds[0] in ("dwell", "table") and (self.angle is not None or self.law is not None):
            raise ValueError(f"a {kinds[0]} takes no angle or law")
        return self


class CamSpec(_Frozen):
    """A disc cam: follower, motion program, base radius or allowed pressure angle."""

    name: str = ""
    units: CamUnits = CamUnits()
    follower: FollowerSpec
    segments: list[SegmentSpec] = Field(min_length=1, description="rise, dwell, return, "
                                        "dwell, ... filling one turn")
    base_radius: Scalar | None = Field(None, description="base radius: of the pitch curve "
                                       "(roller followers), of the profile (flat face); "
                                       "default: the smallest allowed")
    pressure_angle: Scalar | None = Field(None, description="allowed pressure angle on "
                                          "rises and dwells (roller followers)")
    return_pressure_angle: Scalar | None = Field(None, description="allowed pressure angle "
                                                 "on returns (default: pressure_angle)")
    min_curvature_radius: Scalar = Field(0.0, description="flat face: smallest radius of "
                                         "curvature of the profile (length)")
    speed: SpeedSpec | None = Field(None, description="cam speed (default: analogs per "
                                    "radian only)")
    positions: int = Field(360, ge=8, le=100_000, description="points over the turn in "
                           "tables, drawings and the profile files")


class CamDocument(_Frozen):
    """A file holding one cam design under ``cam:``."""

    cam: CamSpec


def cam_json_schema() -> dict[str, Any]:
    """The JSON Schema of cam documents."""
    schema = CamDocument.model_json_schema(by_alias=True)
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "mechloop cam design"
    return schema


class _Reader:
    """Converts values to SI, collecting every problem with its path."""

    def __init__(self, units: CamUnits):
        self.units = units
        self.problems: list[Problem] = []

    def si(self, value, kind: str, path: tuple) -> float | None:
        try:
            return to_si(value, kind, getattr(self.units, kind))  # type: ignore[arg-type]
        except UnitProblem as exc:
            self.problems.append(Problem(path, exc.message, exc.hint))
            return None

    def positive(self, value, kind: str, path: tuple, what: str) -> float | None:
        got = self.si(value, kind, path)
        if got is not None and not got > 0:
            self.problems.append(Problem(path, f"{what} must be positive", "write a "
                                         "positive value"))
            return None
        return got

    def problem(self, path: tuple, message: str, hint: str) -> None:
        self.problems.append(Problem(path, message, hint))


def _follower(spec: FollowerSpec, read: _Reader) -> Follower | None:
    base = ("cam", "follower")
    if spec.type == "translating_flat":
        return TranslatingFlat()
    if spec.type == "oscillating_flat":
        if spec.pivot_distance is None:
            read.problem(base, "a rocker needs pivot_distance", "add pivot_distance: (a "
                         "length)")
            return None
        pivot = read.positive(spec.pivot_distance, "length", (*base, "pivot_distance"),
                              "the pivot distance")
        offset = read.si(spec.face_offset, "length", (*base, "face_offset"))
        return None if pivot is None or offset is None else OscillatingFlat(pivot, offset)
    if spec.roller_radius is None:
        read.problem(base, "a roller follower needs roller_radius", "add roller_radius: 10")
        return None
    roller = read.positive(spec.roller_radius, "length", (*base, "roller_radius"),
                           "the roller radius")
    if spec.type == "translating_roller":
        offset = read.si(spec.offset, "length", (*base, "offset"))
        return None if roller is None or offset is None else TranslatingRoller(roller, offset)
    missing = [k for k in ("pivot_distance", "arm") if getattr(spec, k) is None]
    for key in missing:
        read.problem(base, f"a rocker needs {key}", f"add {key}: (a length)")
    if missing:
        return None
    pivot = read.positive(spec.pivot_distance, "length", (*base, "pivot_distance"),
                          "the pivot distance")
    arm = read.positive(spec.arm, "length", (*base, "arm"), "the arm")
    if roller is None or pivot is None or arm is None:
        return None
    return OscillatingRoller(roller, pivot, arm)


def _segments(spec: CamSpec, read: _Reader, rocker: bool) -> MotionProgram | None:
    lift_kind = "angle" if rocker else "length"
    known = len(read.problems)
    segments: list[Segment] = []
    for i, seg in enumerate(spec.segments):
        path = ("cam", "segments", i)
        if seg.dwell is not None:
            angle = read.positive(seg.dwell, "angle", (*path, "dwell"), "a dwell's angle")
            if angle is not None:
                segments.append(Segment("dwell", angle))
            continue
        if seg.table is not None:
            built = _table_segment(seg.table, read, (*path, "table"), lift_kind)
            if built is not None:
                segments.append(built)
            continue
        kind = "rise" if seg.rise is not None else "return"
        lift = read.positive(seg.rise if seg.rise is not None else seg.return_, lift_kind,
                             (*path, kind), f"the lift of a {kind}")
        angle = read.positive(seg.angle, "angle", (*path, "angle"), f"a {kind}'s angle")
        if lift is not None and angle is not None:
            segments.append(Segment(kind, angle, lift, law(seg.law)))  # type: ignore[arg-type]
    if len(read.problems) > known:
        return None
    total = sum(s.angle for s in segments)
    if abs(total - 2 * math.pi) > TURN_TOLERANCE * 2 * math.pi:
        read.problem(("cam", "segments"), f"the segments span {math.degrees(total):.9g} "
                     "deg, not one turn (360 deg)", "make the segment angles add up to 360")
        return None
    net = sum(s.sign * s.lift for s in segments)
    if abs(net) > 1e-9 * max(s.lift for s in segments):
        read.problem(("cam", "segments"), "the follower does not end where it starts "
                     f"(net {'rise' if net > 0 else 'return'} of {abs(net):.6g} SI units)",
                     "make the returns undo the rises")
        return None
    return MotionProgram(tuple(segments))


def _table_segment(table, read: _Reader, path: tuple, lift_kind: str) -> Segment | None:
    angles = [read.si(a, "angle", (*path, i, 0)) for i, (a, _) in enumerate(table)]
    values = [read.si(v, lift_kind, (*path, i, 1)) for i, (_, v) in enumerate(table)]
    if any(v is None for v in (*angles, *values)):
        return None
    if angles[0] != 0 or values[0] != 0:
        read.problem((*path, 0), "a table starts at [0, 0] (the segment's start)",
                     "write the first point as [0, 0]")
        return None
    if any(b <= a for a, b in itertools.pairwise(angles)):
        read.problem(path, "the table's angles must increase", "sort the points by angle")
        return None
    span, lift = angles[-1], values[-1]
    if lift == 0:
        read.problem((*path, len(table) - 1), "a table ends where it starts",
                     "end a rise above 0, a return below 0 (or use a dwell)")
        return None
    kind = "rise" if lift > 0 else "return"
    shape = table_law([a / span for a in angles], [v / lift for v in values])
    return Segment(kind, span, abs(lift), shape)


def cam_from_data(data: Any, *, file: str | None = None, lines=None) -> CamDesign:
    """A :class:`CamDesign` from plain data (as read from a file); every problem at once,
    each with its line when ``lines`` is given."""
    lines = lines or {}
    if not isinstance(data, dict) or "cam" not in data:
        raise ModelError([Problem((), "a cam document holds a cam: mapping",
                                  "see examples/cams/roller.yaml", 1)], file)
    document, problems = validate_data(CamDocument, data, file)
    if document is None:
        raise located_error(problems, file, lines)
    spec = document.cam
    read = _Reader(spec.units)
    for key in ("length", "angle"):
        read.si(1, key, ("cam", "units", key))
    if read.problems:
        raise located_error(read.problems, file, lines)
    follower = _follower(spec.follower, read)
    program = _segments(spec, read, spec.follower.type.startswith("oscillating"))
    allowed = allowed_return = base = None
    if spec.pressure_angle is not None:
        allowed = read.positive(spec.pressure_angle, "angle", ("cam", "pressure_angle"),
                                "the allowed pressure angle")
    if spec.return_pressure_angle is not None:
        allowed_return = read.positive(spec.return_pressure_angle, "angle",
                                       ("cam", "return_pressure_angle"),
                                       "the allowed pressure angle")
    for value, path in ((allowed, "pressure_angle"), (allowed_return,
                                                      "return_pressure_angle")):
        if value is not None and not value < math.pi / 2:
            read.problem(("cam", path), "a pressure angle is below 90 deg",
                         "e.g. 30 deg for a translating follower, 45 deg for a rocker")
    if spec.base_radius is not None:
        base = read.positive(spec.base_radius, "length", ("cam", "base_radius"),
                             "the base radius")
    min_rho = read.si(spec.min_curvature_radius, "length", ("cam", "min_curvature_radius"))
    flat = spec.follower.type.endswith("flat")
    if not flat and base is None and spec.pressure_angle is None:
        read.problem(("cam",), "give the base radius or the allowed pressure angle",
                     "add base_radius: 40, or pressure_angle: 30 for the smallest base "
                     "radius")
    if flat and spec.pressure_angle is not None:
        read.problem(("cam", "pressure_angle"), "a flat face's base radius follows from "
                     "its convexity, not from a pressure angle", "remove pressure_angle "
                     "(the base radius follows from min_curvature_radius)")
    if follower is not None and base is not None:
        lo, hi = base_limits(follower)
        if not lo < base < hi:
            read.problem(("cam", "base_radius"), f"the base radius must lie between "
                         f"{lo:.6g} and {hi:.6g} m for this follower",
                         "a roller's base radius exceeds the offset; a rocker's lies "
                         "between |pivot_distance − arm| and pivot_distance + arm, a "
                         "rocker face's between face_offset and face_offset + "
                         "pivot_distance")
    if read.problems or follower is None or program is None:
        raise located_error(read.problems, file, lines)
    omega = None if spec.speed is None else spec.speed.rpm * math.pi / 30
    try:
        return CamDesign.build(follower, program, base_radius=base, allowed=allowed,
                               allowed_return=allowed_return, min_curvature=min_rho or 0.0,
                               omega=omega, name=spec.name, positions=spec.positions,
                               units=(spec.units.length, spec.units.angle))
    except CamDesignError as exc:
        where = "base_radius" if base is not None else (
            "min_curvature_radius" if flat else "pressure_angle")
        raise located_error([Problem(("cam", where), exc.message, exc.hint)], file,
                            lines) from None


def load_cam(path: str | os.PathLike[str]) -> CamDesign:
    """Read a cam document (``.yaml``, ``.yml`` or ``.json``) into a :class:`CamDesign`;
    every problem is raised at once as one :class:`~mechloop.errors.ModelError` naming
    the file, line, key and fix."""
    data, lines = read_document(path)
    return cam_from_data(data, file=str(path), lines=lines)
