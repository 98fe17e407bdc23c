"""The mechanism behind a vector model: bodies with their masses, kinematic pairs, drives.

:func:`build_mechanism` compiles the dynamic part of a model (SI numbers) and, when the
file names no ``joints``, infers them from the contours:

* an end of a vector is *held* by a body when the vector belongs to the body and that end
  is fixed in it (both ends of a vector of constant length; the end named in ``ends``,
  else the tail, of a vector whose length varies); vectors that are constant and in no
  body belong to the ground (body 0).  The free end of a sliding vector is held by the
  body that carries its direction (the ground for a constant angle, the linked vector's
  body for a linked one) when the point is fixed in that body;
* where two vectors meet in a contour and exactly two bodies hold that point, the two
  bodies form a **revolute** pair there (the same pair met again at the same place, in
  another contour, is the same joint);
* a vector of varying length whose two ends are held by two different bodies is a
  **prismatic** pair between them along it.

Every number of moving bodies ``n`` must then satisfy ``3n = 2·p + d`` (``p`` lower pairs,
``d`` drives) for the force analysis to be determinate; otherwise the model says so and
asks for ``joints``.  Inferred joints are named ``J<first>_<second>`` (``J0_1``).
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, replace

import numpy as np

from mechloop.dynamics.holds import shared_junctions, vector_holds
from mechloop.dynamics.mass_items import center_vector, mass_items
from mechloop.dynamics.points import Motion, Placement
from mechloop.errors import ModelError, Problem
from mechloop.model.dynamic import HeadPoint, Joint, TailPoint, VectorPoint
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.units import UnitProblem, to_si

PointOn = TailPoint | HeadPoint | VectorPoint

#: Points closer than this (relative to the size of the mechanism) are the same point.
SAME_POINT_RTOL = 1e-9


@dataclass(frozen=True)
class Mass:
    """A lumped mass of a body: ``mass`` (kg), ``inertia`` (kg·m²) about ``center`` (an
    array ``(D·P,)`` for a rod in a population of designs, :func:`design_masses`)."""

    body: int
    mass: float
    inertia: float | np.ndarray
    center: PointOn


@dataclass(frozen=True)
class BodyFrame:
    """A moving body: its vectors, the points fixed in it, and its angle (that of
    ``angle_vector``)."""

    number: int
    name: str
    vectors: tuple[int, ...]
    angle_vector: int
    held: tuple[tuple[int, str], ...]  # (vector, 'tail'|'head') ends fixed in the body


@dataclass(frozen=True)
class Pair:
    """A kinematic pair: ``bodies`` = (first, second); the reaction is the force of the
    first on the second.  ``at`` is the pin (revolute) or the reference point of the normal
    force and moment (prismatic, sliding along vector ``along``)."""

    name: str
    kind: str  # 'revolute' | 'prismatic'
    bodies: tuple[int, int]
    at: PointOn
    along: int | None
    friction: float
    radius: float
    length: float
    inferred: bool


@dataclass(frozen=True)
class Drive:
    """A model argument that moves bodies: a moment on ``bodies[1]`` against the ground
    (an angle), or a force along vector ``vector`` pushing the body at its head
    (``bodies[1]``) away from the body at its tail (``bodies[0]``) (a length)."""

    argument: int
    kind: str  # 'angle' | 'length'
    vector: int
    bodies: tuple[int, int]


@dataclass(frozen=True)
class Mechanism:
    """Bodies, masses, pairs and drives of a model, all SI."""

    bodies: dict[int, BodyFrame]
    masses: tuple[Mass, ...]
    pairs: tuple[Pair, ...]
    drives: tuple[Drive, ...]
    total_mass: float
    #: gear meshes (higher pairs) of the model's ``gears:`` (:mod:`.meshes`)
    meshes: tuple = ()


def _si(value, kind, unit, path, problems) -> float:
    try:
        return to_si(value, kind, unit)
    except UnitProblem as exc:
        problems.append(Problem(path, exc.message, exc.hint))
        return 0.0


def build_mechanism(model: Model, placement: Placement, *, determinate: bool = True
                    ) -> Mechanism:
    """Compile the dynamic part of ``model`` (bodies, masses, joints, drives) in SI.

    Raises :class:`~mechloop.errors.ModelError` listing every problem: a body vector that
    does not exist, a body whose vectors do not move together, a mass without a centre,
    joints that cannot be inferred, a force analysis that is not determinate (unless
    ``determinate=False``: structural analysis reports that itself).
    """
    problems: list[Problem] = []
    results = placement.results
    if not model.bodies:
        raise ModelError([Problem(("bodies",), "the model has no bodies",
                                  "add bodies: {1: {vectors: [1], mass: ..., center: ...}}")])
    constant = results.constant
    member: dict[int, list[int]] = defaultdict(list)
    for number, body in model.bodies.items():
        for i, v in enumerate(body.vectors):
            if v not in model.vectors:
                problems.append(Problem(("bodies", number, "vectors", i),
                                        f"vector {v} does not exist",
                                        f"use one of {sorted(model.vectors)}"))
            else:
                member[v].append(number)
        for v in body.ends:
            if v not in body.vectors:
                problems.append(Problem(("bodies", number, "ends", v),
                                        f"vector {v} is not a vector of body {number}",
                                        "list it in vectors, or remove it from ends"))
    if problems:
        raise ModelError(problems)

    def fixed_length(v: int) -> bool:
        return f"r{v}" in constant

    # ends held through a body's own vectors
    holds = vector_holds(model, constant)
    scale = _size(model, placement)
    frames = _frames(model, placement, holds, scale, problems)

    def end_motion(v: int, end: str) -> Motion:
        return placement.tail(v) if end == "tail" else placement.head(v)

    # free ends of sliding vectors: held by the body that carries the vector's direction
    for v in member:
        if fixed_length(v):
            continue
        for end in ("tail", "head"):
            if holds.get((v, end)):
                continue
            guide = _guide_body(model, v, member)
            if guide is not None and _fixed_in(end_motion(v, end), guide, frames,
                                               placement, scale):
                holds[(v, end)].add(guide)

    if model.joints is not None:
        pairs = _given_pairs(model, problems)
        if not problems:
            _check_given_pairs(pairs, frames, placement, scale, problems)
    else:
        pairs = _inferred_pairs(model, placement, holds, member, scale, problems)
    drives = _drives(model, holds, member, problems)
    masses = _masses(model, placement.results, problems)
    moving = [b for b in model.bodies if b != 0]
    from mechloop.dynamics.meshes import mesh_pairs

    meshes = mesh_pairs(model, pairs, problems)
    if determinate and not problems:
        unknowns = 2 * len(pairs) + len(drives) + len(meshes)
        if unknowns != 3 * len(moving):
            listed = "; ".join(f"{p.name} ({p.kind}, bodies {p.bodies[0]}-{p.bodies[1]})"
                               for p in pairs) or "none"
            origin = "named in the file" if model.joints is not None else "inferred"
            problems.append(Problem(
                ("joints",) if model.joints is not None else ("bodies",),
                f"the force analysis is not determinate: {len(moving)} moving bodies give "
                f"{3 * len(moving)} equations, but {len(pairs)} lower pairs"
                + (f", {len(meshes)} gear meshes" if meshes else "") + " and "
                f"{len(drives)} drives give {unknowns} unknowns (joints {origin}: {listed})",
                "name the kinematic pairs in joints: (revolute at a point, prismatic along "
                "a vector), or check that every moving link is a body and every driven "
                "vector belongs to one"
                + ("; name each gear mesh between bodies linked by a ratio in gears: "
                   "(bodies, pitch point at, pressure_angle)" if _geared(model) else "")))
    if problems:
        raise ModelError(problems)
    total = sum(m.mass for m in masses)
    return Mechanism(bodies=frames, masses=tuple(masses), pairs=tuple(pairs),
                     drives=tuple(drives), total_mass=total, meshes=meshes)


def _geared(model: Model) -> bool:
    """Some body's angle is linked with a ratio ≠ 1 (a gear mesh the model may not name)."""
    in_body = {v for body in model.bodies.values() for v in body.vectors}
    return any(isinstance(model.vectors[v].a, LinkRole) and model.vectors[v].a.ratio != 1
               for v in in_body if v in model.vectors)


def _size(model: Model, placement: Placement) -> float:
    ok = ~placement.results.broken
    sizes = [np.abs(placement.vector(v).z[ok]).max(initial=0.0) for v in model.vectors]
    return max(max(sizes, default=1.0), 1e-300)


def _frames(model, placement, holds, scale, problems) -> dict[int, BodyFrame]:
    results = placement.results
    ok = ~results.broken
    frames: dict[int, BodyFrame] = {}
    for number, body in model.bodies.items():
        path = ("bodies", number)
        if number == 0:
            if body.mass or body.parts:
                problems.append(Problem(path, "the ground (body 0) cannot have a mass",
                                        "remove mass and parts from body 0"))
            continue
        first = body.vectors[0]
        for i, v in enumerate(body.vectors[1:], start=1):
            diff = results.value(f"a{v}")[ok] - results.value(f"a{first}")[ok]
            diff = np.angle(np.exp(1j * (diff - diff[:1]))) if diff.size else diff
            if diff.size and np.ptp(diff) > 1e-9:
                problems.append(Problem(
                    (*path, "vectors", i),
                    f"vectors {first} and {v} of body {number} turn relative to each other "
                    f"(by up to {np.degrees(np.ptp(diff)):.3g} deg)",
                    "a body's vectors must move together: link their angles "
                    f"(a{v}: {{link: a{first}, delta: ...}}) or put them in different bodies"))
        held = tuple(sorted(end for end, owners in holds.items() if number in owners))
        frames[number] = BodyFrame(number, body.name or f"body {number}", tuple(body.vectors),
                                   first, held)
    if problems:
        return frames
    for number, frame in frames.items():
        ref = None
        for v, end in frame.held:
            point = placement.tail(v) if end == "tail" else placement.head(v)
            if ref is None:
                ref = point
                continue
            if not _rigid(point, ref, results.value(f"a{frame.angle_vector}"), ok, scale):
                problems.append(Problem(
                    ("bodies", number),
                    f"the {end} of vector {v} is not fixed in body {number}: it moves "
                    "relative to the body's other points",
                    "a vector of varying length has only one end in a body: name it in "
                    f"ends (ends: {{{v}: tail}} or head)" if f"r{v}" not in results.constant
                    else "the body's vectors lie in different contours that are not placed "
                    "where they are: give the later contour start: {tail: K} (a vector end "
                    "it shares with an earlier contour) or fixed coordinates [x, y]"))
    return frames


def _rigid(point: Motion, ref: Motion, angle, ok, scale) -> bool:
    local = (point.z - ref.z)[ok] * np.exp(-1j * angle[ok])
    return bool(local.size == 0 or np.abs(local - local[0]).max() <= SAME_POINT_RTOL * 1e3
                * scale)


def _guide_body(model: Model, v: int, member) -> int | None:
    role = model.vectors[v].a
    if isinstance(role, LinkRole) and role.ratio != 1:
        return None  # a transmission (gears): the direction turns with neither body
    if isinstance(role, LinkRole):
        root = int(role.link[1:])
        owners = member.get(root, [])
        return owners[0] if len(owners) == 1 else None
    if isinstance(role, int | float) or (isinstance(role, str)
                                        and role.strip() != "function"):
        return 0
    return None


def _fixed_in(point: Motion, body: int, frames, placement, scale) -> bool:
    ok = ~placement.results.broken
    if body == 0:
        return bool(np.abs(point.z[ok] - point.z[ok][:1]).max(initial=0.0)
                    <= SAME_POINT_RTOL * 1e3 * scale)
    frame = frames.get(body)
    if frame is None or not frame.held:
        return False
    v, end = frame.held[0]
    ref = placement.tail(v) if end == "tail" else placement.head(v)
    return _rigid(point, ref, placement.results.value(f"a{frame.angle_vector}"), ok, scale)


def _check_given_pairs(pairs: list[Pair], frames, placement: Placement, scale: float,
                       problems: list[Problem]) -> None:
    """A named pin must be a point of both its bodies; a named slide must let its bodies
    only translate relative to each other along its vector."""
    res = placement.results
    ok = ~res.broken
    for pair in pairs:
        path = ("joints", pair.name)
        point = placement.point(pair.at)
        if pair.kind == "revolute":
            for b in pair.bodies:
                if not _fixed_in(point, b, frames, placement, scale):
                    problems.append(Problem(
                        (*path, "at"), f"the pin of joint {pair.name} is not a point of "
                        f"body {b}: it moves relative to the body",
                        "place the pin at a vector end that both bodies hold (the tail or "
                        "head of one of their vectors)"))
            continue
        direction = res.value(f"a{pair.along}")[ok]
        for b in pair.bodies:
            body_angle = 0.0 if b == 0 else res.value(f"a{frames[b].angle_vector}")[ok]
            turn = np.angle(np.exp(1j * (direction - body_angle)))
            if turn.size and np.ptp(np.unwrap(turn)) > 1e-9:
                problems.append(Problem(
                    (*path, "along"), f"vector {pair.along} turns relative to body {b}, so "
                    f"joint {pair.name} cannot slide along it",
                    "slide along a vector whose direction is fixed in both bodies (the guide)"))
                break
        else:
            first, second = pair.bodies
            gap = (_velocity_at(point, second, frames, placement)
                   - _velocity_at(point, first, frames, placement))[ok]
            e = np.exp(1j * direction)
            across = (np.conj(e) * gap).imag
            speed = max(float(np.abs(gap).max(initial=0.0)), 1e-300)
            if np.abs(across).max(initial=0.0) > 1e-6 * speed:
                problems.append(Problem(
                    (*path, "along"), f"the bodies of joint {pair.name} do not slide along "
                    f"vector {pair.along}: their relative motion has a component across it",
                    "slide along the vector that runs along the guide"))


def _velocity_at(point: Motion, body: int, frames, placement: Placement):
    """Velocity of the point of ``body`` that is at ``point`` (zero for the ground)."""
    if body == 0:
        return np.zeros_like(point.z)
    frame = frames[body]
    v, end = frame.held[0]
    ref = placement.tail(v) if end == "tail" else placement.head(v)
    omega = placement.results.rate(f"a{frame.angle_vector}")
    return ref.v + 1j * omega * (point.z - ref.z)


def _friction(model: Model, joint: Joint | None, kind: str, path, problems
              ) -> tuple[float, float, float]:
    units = model.units.length
    f = model.friction.coefficient if joint is None or joint.friction is None \
        else joint.friction
    radius = (joint.radius if joint is not None and joint.radius is not None
              else model.friction.radius)
    length = (joint.length if joint is not None and joint.length is not None
              else model.friction.length)
    r = 0.0 if radius is None else _si(radius, "length", units, (*path, "radius"), problems)
    b = 0.0 if length is None else _si(length, "length", units, (*path, "length"), problems)
    if f > 0 and kind == "revolute" and r <= 0:
        problems.append(Problem(path, "friction needs the pin radius",
                                "give radius: (here or in friction:)"))
    if f > 0 and kind == "prismatic" and b <= 0:
        problems.append(Problem(path, "friction needs the slider length",
                                "give length: (here or in friction:)"))
    return f, r, b


def _given_pairs(model: Model, problems: list[Problem]) -> list[Pair]:
    pairs = []
    for name, joint in (model.joints or {}).items():
        path = ("joints", name)
        if joint.type in ("spherical", "cylindrical"):  # issue 17: spatial joints
            problems.append(Problem((*path, "type"), f"a {joint.type} joint applies to a "
                                    "model with spatial contours",
                                    "a planar model's joints are revolute or prismatic"))
            continue
        if joint.axis is not None:
            problems.append(Problem((*path, "axis"), "a joint's axis applies to a model "
                                    "with spatial contours", "remove 'axis' (a planar pin "
                                    "turns about Z; a prismatic joint slides 'along' a "
                                    "vector)"))
            continue
        for i, b in enumerate(joint.bodies):
            if b != 0 and b not in model.bodies:
                problems.append(Problem((*path, "bodies", i), f"body {b} does not exist",
                                        f"use 0 (ground) or one of {sorted(model.bodies)}"))
        if joint.bodies[0] == joint.bodies[1]:
            problems.append(Problem((*path, "bodies"), "a joint needs two different bodies",
                                    "name the two bodies it connects"))
        for_point = [joint.at] if joint.at is not None else []
        if joint.type == "prismatic":
            if joint.along is None:
                problems.append(Problem(path, "a prismatic joint needs 'along'",
                                        "give the vector along which the bodies slide"))
                continue
            if joint.along not in model.vectors:
                problems.append(Problem((*path, "along"), f"vector {joint.along} does not "
                                        "exist", f"use one of {sorted(model.vectors)}"))
                continue
            at = joint.at if joint.at is not None else TailPoint(tail=joint.along)
        else:
            if joint.at is None:
                problems.append(Problem(path, "a revolute joint needs 'at'",
                                        "give the pin, e.g. at: {head: 1}"))
                continue
            at = joint.at
        for p in for_point:
            v = p.tail if isinstance(p, TailPoint) else (
                p.head if isinstance(p, HeadPoint) else p.vector)
            if v not in model.vectors:
                problems.append(Problem((*path, "at"), f"vector {v} does not exist",
                                        f"use one of {sorted(model.vectors)}"))
        f, r, b = _friction(model, joint, joint.type, path, problems)
        pairs.append(Pair(name, joint.type, tuple(joint.bodies), at, joint.along, f, r, b,
                          inferred=False))
    return pairs


def _inferred_pairs(model, placement, holds, member, scale, problems) -> list[Pair]:
    found: dict[tuple[int, int], list[tuple[PointOn, Motion]]] = defaultdict(list)
    pairs: list[Pair] = []
    for v, key in shared_junctions(model, holds, problems):
        point = TailPoint(tail=v)
        motion = placement.tail(v)
        if any(np.nanmax(np.abs(motion.z - m.z), initial=0.0) <= SAME_POINT_RTOL * scale
               for _, m in found[key]):
            continue
        found[key].append((point, motion))
    for (b1, b2), points in found.items():
        if len(points) > 1:
            problems.append(Problem(
                ("bodies",),
                f"bodies {b1} and {b2} meet at {len(points)} different points (at the tail "
                f"of vectors {', '.join(str(p.tail) for p, _ in points)})",
                "if these are one pin, a contour is not placed where it lies: give it "
                "start: {tail: K} (or [x, y]); otherwise name the pairs in joints:"))
        for k, (point, _) in enumerate(points):
            suffix = "" if k == 0 else chr(ord("a") + k)
            path = ("friction",)
            f, r, b = _friction(model, None, "revolute", path, problems)
            pairs.append(Pair(f"J{b1}_{b2}{suffix}", "revolute", (b1, b2), point, None,
                              f, r, b, inferred=True))
    for v in sorted(member):
        if f"r{v}" in placement.results.constant:
            continue
        tail, head = holds.get((v, "tail"), set()), holds.get((v, "head"), set())
        if len(tail) == 1 and len(head) == 1 and tail != head:
            (bt,), (bh,) = tail, head
            first, second = sorted((bt, bh))
            at = TailPoint(tail=v)
            f, r, b = _friction(model, None, "prismatic", ("friction",), problems)
            pairs.append(Pair(f"J{first}_{second}", "prismatic", (first, second), at, v,
                              f, r, b, inferred=True))
        elif not tail or not head:
            end = "tail" if not tail else "head"
            problems.append(Problem(
                ("bodies", member[v][0], "vectors"),
                f"vector {v} changes length, but no body holds its {end}: the body it slides "
                "in is unknown",
                f"list vector {v} in the body at its {end} too, with ends: {{{v}: {end}}}, "
                "or name the pairs in joints:"))
    return pairs


def _drives(model: Model, holds, member, problems) -> list[Drive]:
    drives: list[Drive] = []
    for k in sorted(model.arguments):
        driven = [(letter, v) for v, vec in model.vectors.items() for letter in "ra"
                  if isinstance(getattr(vec, letter), ArgumentRole)
                  and getattr(vec, letter).argument == k]
        bodies_of = {v: member.get(v, []) for _, v in driven}
        if all(not b for b in bodies_of.values()) and all(letter == "a" for letter, _ in
                                                           driven):
            problems.append(Problem(("arguments", k),
                                    f"argument {k} turns vector(s) "
                                    f"{', '.join(str(v) for _, v in driven)} of no body",
                                    "add the driven vector to the body it turns"))
            continue
        letter, v = driven[0]
        if letter == "a":
            owners = sorted({b for vs in bodies_of.values() for b in vs})
            if len(owners) != 1:
                problems.append(Problem(("arguments", k), f"argument {k} turns vectors of "
                                        f"several bodies ({', '.join(map(str, owners))})",
                                        "drive one body per argument"))
                continue
            drives.append(Drive(k, "angle", v, (0, owners[0])))
            continue
        tail = holds.get((v, "tail"), set()) or _node_holders(model, holds, v, "tail")
        head = holds.get((v, "head"), set()) or _node_holders(model, holds, v, "head")
        if len(tail) != 1 or len(head) != 1 or tail == head:
            problems.append(Problem(
                ("arguments", k),
                f"argument {k} drives the length of vector {v}, but the bodies at its ends "
                f"are not clear (tail: {sorted(tail) or 'none'}, head: {sorted(head) or 'none'})",
                "make each end of the driven vector a point of exactly one body"))
            continue
        drives.append(Drive(k, "length", v, (next(iter(tail)), next(iter(head)))))
    return drives


def _node_holders(model: Model, holds, v: int, end: str) -> set[int]:
    for contour in model.contours:
        vs = contour.vectors
        if v in vs:
            i = vs.index(v)
            if end == "tail":
                return set(holds.get((vs[i - 1], "head"), set()))
            return set(holds.get((vs[(i + 1) % len(vs)], "tail"), set()))
    return set()


def design_masses(model: Model, mechanism: Mechanism, results, designs: int) -> Mechanism:
    """``mechanism`` with the masses of each design of a population whose designs ×
    positions are the positions of ``results`` (``(D·P,)``): an ``inertia: rod`` is
    ``m·r²/12`` of each design's own length (an array ``(D·P,)``); every other mass
    property is the same for all designs."""
    problems: list[Problem] = []
    masses = _masses(model, results, problems, designs)
    if problems:  # the mechanism was compiled from the same model: cannot happen
        raise ModelError(problems)
    return replace(mechanism, masses=tuple(masses))


def _first(values, designs: int):
    """The value at the first position (a float), or at each design's first position
    repeated over its positions (``(D·P,)``) for a population of ``designs`` > 1."""
    if designs == 1:
        return float(values[0])
    rows = np.asarray(values).reshape(designs, -1)
    return np.repeat(rows[:, 0], rows.shape[1])


def _masses(model: Model, results, problems, designs: int = 1) -> list[Mass]:
    out: list[Mass] = []
    units = model.units
    for number, body in model.bodies.items():
        if number == 0:
            continue
        for item in mass_items(number, body):
            where, mass, inertia, center = item
            m = _si(mass, "mass", units.mass, (*where, "mass"), problems)
            if m < 0:
                problems.append(Problem((*where, "mass"), "a mass cannot be negative",
                                        "give a mass ≥ 0"))
            v = center_vector(number, body, item, m, problems)
            if v is None:
                continue
            sliding = f"r{v}" not in results.constant
            held = body.ends.get(v, "tail")
            if sliding and isinstance(center, VectorPoint) and center.share:
                problems.append(Problem((*where, "center"), f"vector {v} changes length, so "
                                        "a share of it is not a fixed point of the body",
                                        "place the centre with along/across from the tail"))
                continue
            if sliding and held == "head" and not isinstance(center, HeadPoint):
                problems.append(Problem((*where, "center"), f"body {number} holds the head of "
                                        f"vector {v}, which changes length, so a point "
                                        "placed from its tail moves in the body",
                                        f"put the centre at {{head: {v}}}, or on a vector of "
                                        "constant length"))
                continue
            if sliding and held == "tail" and isinstance(center, HeadPoint):
                problems.append(Problem((*where, "center"), f"body {number} holds the tail of "
                                        f"vector {v}, which changes length, so its head moves "
                                        "in the body", f"put the centre at {{tail: {v}}} or "
                                        "along/across from it"))
                continue
            if isinstance(inertia, list):  # a 3×3 tensor: spatial models (issue 17)
                problems.append(Problem((*where, "inertia"), "an inertia tensor applies to "
                                        "a body of a model with spatial contours",
                                        "give one moment of inertia (about the axis normal "
                                        "to the plane)"))
                continue
            if inertia == "rod":
                if sliding:
                    problems.append(Problem((*where, "inertia"), "'rod' needs a vector of "
                                            f"constant length, and vector {v} changes length",
                                            "give the moment of inertia as a number"))
                    continue
                j = m * _first(results.value(f"r{v}"), designs) ** 2 / 12.0
            else:
                j = _si(inertia, "inertia", units.inertia, (*where, "inertia"), problems)
            if np.any(j < 0):
                problems.append(Problem((*where, "inertia"), "a moment of inertia cannot "
                                        "be negative", "give a value ≥ 0"))
            out.append(Mass(number, m, j, center))
    return out
