"""Joints of a model with spatial contours and the drives of its arguments (issue 17).

A joint (``joints:``, by name) connects two bodies (``bodies: [first, second]``, 0 is the
ground) and transmits the reaction of the first on the second: a force through its point
``at`` and a moment, with these unknown components (in the model's axes)::

    type         force                  moment                 axis
    spherical    x, y, z                none                   none
    revolute     x, y, z                two across the axis    needed
    cylindrical  two across the axis    two across the axis    needed
    prismatic    two across the axis    x, y, z                needed

``axis`` is a vector number (the axis along that vector, turning with it) or a direction
``[x, y, z]`` fixed in the model's axes.  ``at`` is the ball's centre or a point of the
pin's axis; for a cylindrical or prismatic joint it is the point about which the moment is
given (default the tail of the axis vector).

A **drive** is the balancing load of a model argument, acting on the body the argument
moves (:class:`Drive3`):

* an elevation α of vector ``v``: a moment about ``n = u × ∂u/∂α = (−sin β, 0, cos β)``
  (the plane's normal for a vector of a planar contour) on the body that holds ``v``,
  against the ground: for any motion of that body ``n·ω = α̇`` (ω = α̇ n − β̇ Y + s u);
* a rotation β: a moment about −Y (β turns a vector about −Y);
* a length r: a force along ``v`` at its head, pushing the body that holds the head away
  from the body that holds the tail (those listing ``v`` with ``ends`` head and tail;
  the ground holds the tail of a vector of no body; the other body of a prismatic or
  cylindrical joint along ``v`` holds the end no body lists).

This module checks what the model file says (bodies, types, axes, points) and places the
joints and drives over the positions; whether the joints fit the motion and the force
analysis is determinate is decided by :mod:`mechloop.spatial.reactions`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import Problem
from mechloop.model.dynamic import HeadPoint, TailPoint, VectorPoint, point_vector
from mechloop.model.schema import ArgumentRole, Model
from mechloop.spatial.directions import unit_of
from mechloop.spatial.points import Placement3

Array = NDArray[np.float64]
PointOn = TailPoint | HeadPoint | VectorPoint

#: The reaction components of each joint type: the force's and the moment's, each
#: ``"xyz"`` (three, in the model's axes), ``"across"`` (two across the axis) or "".
COMPONENTS = {"spherical": ("xyz", ""), "revolute": ("xyz", "across"),
              "cylindrical": ("across", "across"), "prismatic": ("across", "xyz")}


@dataclass(frozen=True)
class Joint3:
    """A joint of a spatial model: ``kind`` (a key of :data:`COMPONENTS`), ``bodies``
    (first, second: the reaction is the first's on the second), its point ``at`` and
    ``axis`` (a vector number, a unit direction ``(3,)`` fixed in the model's axes, or None
    for a spherical joint)."""

    name: str
    kind: str
    bodies: tuple[int, int]
    at: PointOn
    axis: int | Array | None

    def direction(self, place: Placement3) -> Array:
        """The unit axis over positions, ``(3, P)``."""
        n = place.results.broken.size
        if isinstance(self.axis, int):
            return place.direction(self.axis).p
        return np.zeros((3, n)) + np.asarray(self.axis, float)[:, None]


@dataclass(frozen=True)
class Drive3:
    """The balancing load of ``argument``: ``letter`` ``a``/``b`` (a moment) or ``r`` (a
    force) of ``vector``; ``bodies`` = (against, driven): (0, the body holding the vector)
    for an angle, (the body at the tail, the body at the head) for a length."""

    argument: int
    letter: str
    vector: int
    bodies: tuple[int, int]

    @property
    def kind(self) -> str:
        return "length" if self.letter == "r" else "angle"

    def wrench(self, place: Placement3) -> tuple[Array, Array, Array]:
        """Force (N per unit load), point and moment (N·m per unit load) on the driven
        body, each ``(3, P)``."""
        res = place.results
        n = res.broken.size
        zero = np.zeros((3, n))
        head = place.head(self.vector).p
        if self.letter == "r":
            return place.direction(self.vector).p, head, zero
        if self.letter == "b":
            return zero, head, zero + np.array([[0.0], [-1.0], [0.0]])
        if self.vector in res.axes:  # a vector of a planar contour: its plane's normal
            e1, e2 = res.axes[self.vector]
            return zero, head, zero + np.cross(e1, e2)[:, None]
        beta = res.value(f"b{self.vector}")
        return zero, head, np.stack([-np.sin(beta), 0.0 * beta, np.cos(beta)])


def build_joints3(model: Model, moving: set[int], problems: list[Problem]) -> list[Joint3]:
    """The joints of ``model`` (a model with spatial contours; ``moving``: its moving
    bodies), every misuse a located problem with its fix."""
    out: list[Joint3] = []
    vectors = model.vectors
    if model.friction.coefficient > 0:
        problems.append(Problem(("friction", "coefficient"), "friction in the joints of a "
                                "model with spatial contours is not computed yet",
                                "remove it (the joints are ideal)"))
    for name, joint in (model.joints or {}).items():
        path = ("joints", name)
        kind = joint.type
        bad = len(problems)
        for i, b in enumerate(joint.bodies):
            if b != 0 and b not in moving:
                problems.append(Problem((*path, "bodies", i), f"body {b} is not a moving "
                                        "body of the model",
                                        f"use 0 (the ground) or one of {sorted(moving)}"))
        if joint.bodies[0] == joint.bodies[1]:
            problems.append(Problem((*path, "bodies"), "a joint needs two different bodies",
                                    "name the two bodies it connects"))
        for key in ("friction", "radius", "length"):
            if getattr(joint, key) is not None:
                problems.append(Problem((*path, key), "friction in the joints of a model "
                                        "with spatial contours is not computed yet",
                                        "remove it (the joints are ideal)"))
        if joint.along is not None:
            problems.append(Problem((*path, "along"), "in a model with spatial contours a "
                                    "joint's axis is given by 'axis'",
                                    f"write axis: {joint.along} in place of along: "
                                    f"{joint.along}"))
        axis: int | Array | None = None
        if kind == "spherical":
            if joint.axis is not None:
                problems.append(Problem((*path, "axis"), "a spherical joint has no axis (it "
                                        "turns about every axis)", "remove 'axis', or make "
                                        "it a revolute joint (type: revolute)"))
        elif joint.axis is None:
            if joint.along is None:
                problems.append(Problem(path, f"a {kind} joint of a model with spatial "
                                        "contours needs its axis", "give axis: K (along "
                                        "vector K) or axis: [x, y, z]"))
        elif isinstance(joint.axis, int):
            if joint.axis not in vectors:
                problems.append(Problem((*path, "axis"), f"vector {joint.axis} does not "
                                        "exist", f"use one of {sorted(vectors)}"))
            axis = joint.axis
        else:
            axis = unit_of(joint.axis, (*path, "axis"), problems)
        at = joint.at
        if at is None and isinstance(axis, int) and kind in ("cylindrical", "prismatic"):
            at = TailPoint(tail=axis)
        elif at is None:
            problems.append(Problem(path, f"a {kind} joint needs 'at': " + (
                "its centre" if kind == "spherical" else "a point of its axis"),
                "give the point, e.g. at: {head: 1}"))
        elif point_vector(at) not in vectors:
            problems.append(Problem((*path, "at"), f"vector {point_vector(at)} does not "
                                    "exist", f"use one of {sorted(vectors)}"))
        elif isinstance(at, VectorPoint) and at.across != 0:
            problems.append(Problem((*path, "at", "across"), "'across' has no side in a "
                                    "model with spatial contours",
                                    "place the point on the vector (share or along)"))
        if len(problems) == bad and at is not None:
            out.append(Joint3(name, kind, (joint.bodies[0], joint.bodies[1]), at, axis))
    if model.joints is not None:
        named = {b for j in model.joints.values() for b in j.bodies}
        for b in sorted(moving - named):
            problems.append(Problem(("joints",), f"body {b} is in no joint, so the force "
                                    "analysis has nothing to hold it",
                                    f"name the joints of body {b} with the bodies it "
                                    "touches"))
    return out


def build_drives3(model: Model, bodies: dict[int, list[int]], joints: list[Joint3],
                  problems: list[Problem]) -> list[Drive3]:
    """The drive of every argument of ``model`` (``bodies``: every moving body's
    vectors)."""
    drives: list[Drive3] = []
    member = {v: [b for b, vs in bodies.items() if v in vs] for v in model.vectors}
    for k in sorted(model.arguments):
        path = ("arguments", k)
        driven = [(letter, v) for v, vec in model.vectors.items() for letter in "rab"
                  if isinstance(getattr(vec, letter), ArgumentRole)
                  and getattr(vec, letter).argument == k]
        if not driven:
            continue
        letter, v = driven[0]
        owners = sorted({b for _, u in driven for b in member[u]})
        if len({x for x, _ in driven}) > 1 or (letter != "r" and len(owners) > 1) or (
                letter == "r" and len(driven) > 1):
            problems.append(Problem(path, f"argument {k} drives "
                                    f"{', '.join(f'{x}{u}' for x, u in driven)} of "
                                    f"bodies {', '.join(map(str, owners)) or 'none'}; its "
                                    "balancing load needs one parameter of one body",
                                    "drive one body per argument"))
            continue
        if letter != "r":
            if not owners:
                problems.append(Problem(path, f"argument {k} turns vector {v} of no body",
                                        "add the driven vector to the body it turns"))
                continue
            drives.append(Drive3(k, letter, v, (0, owners[0])))
            continue
        ends = {b: model.bodies[b].ends.get(v, "tail") for b in member[v]}
        tail = {b for b, e in ends.items() if e == "tail"} or ({0} if not ends else set())
        head = {b for b, e in ends.items() if e == "head"}
        for j in joints:
            if j.kind in ("prismatic", "cylindrical") and isinstance(j.axis, int) \
                    and j.axis == v:
                for have, other in ((tail, head), (head, tail)):
                    if not other and have & set(j.bodies):
                        other.update(set(j.bodies) - have)
        if len(tail) != 1 or len(head) != 1 or tail == head:
            problems.append(Problem(path, f"argument {k} drives the length of vector {v}, "
                                    "but the bodies at its ends are not clear (tail: "
                                    f"{sorted(tail) or 'none'}, head: "
                                    f"{sorted(head) or 'none'})",
                                    f"list vector {v} in the body at its head with ends: "
                                    f"{{{v}: head}}, or name the joint along it "
                                    "(prismatic, cylindrical)"))
            continue
        drives.append(Drive3(k, "r", v, (next(iter(tail)), next(iter(head)))))
    return drives


def body_reference(model: Model, results, body: int, vectors: list[int]) -> PointOn:
    """A point fixed in ``body``: the end of its first vector that it holds (the tail,
    unless that vector changes length and ``ends`` says head)."""
    first = vectors[0]
    if f"r{first}" not in results.constant and \
            model.bodies[body].ends.get(first, "tail") == "head":
        return HeadPoint(head=first)
    return TailPoint(tail=first)
