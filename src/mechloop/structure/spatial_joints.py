"""The kinematic pairs of a spatial model from its declared joints (``joints:``, issue 17).

A model that names its joints (:mod:`mechloop.spatial.joints`) gives its structure by
them, not by what the contours and bodies let :mod:`.spatial` infer: each joint is a pair
of its two bodies, of the class its type takes away::

    type         pair   class   (constraints)
    spherical    S      III     3
    cylindrical  C      IV      4
    revolute     R      V       5
    prismatic    P      V       5

Every joint is first checked against the motion the contours give, by the check of the
force analysis (:func:`mechloop.spatial.reactions.check_joints_fit`: a joint's reaction
does no work on any motion of the mechanism) — a ball whose centre is not a point of both
bodies, a pin whose bodies turn about another axis, is a located problem with its fix.
The pairs keep their points and axes over every position that closes, so that the
spherical (all revolute axes through one point) and planar (all parallel) families are
decided at every position (:func:`mechloop.structure.spatial._family`).

A link whose ball centres (and cylindrical pairs' axes) lie on one line spins about that
line with no pair holding it: one idle degree of freedom (the RSSR coupler between its
two balls), as :func:`mechloop.structure.spatial.count` counts it for a link marked a
"rod" here — decided from the joints' geometry, not from the body's vectors.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import ModelError, Problem
from mechloop.model.schema import Model
from mechloop.structure.spatial import SpatialPair

Array = NDArray[np.float64]

#: The pair letter of each joint type (its class: :data:`mechloop.structure.spatial.CLASSES`).
KIND = {"spherical": "S", "revolute": "R", "cylindrical": "C", "prismatic": "P"}
#: Points off a line by at most this share of the mechanism's size are on it; directions
#: with a smaller sine are parallel.
LINE_RTOL = 1e-7


def _frames(model: Model, results, problems: list[Problem]):
    """Every moving body's vectors and the vector that sets its frame's e3."""
    from mechloop.spatial.bodies import frame_vector, vectors_defined

    out: dict[int, tuple[list[int], int | None]] = {}
    for number, body in model.bodies.items():
        if number == 0:
            continue
        if not vectors_defined(model, number, body, problems):
            continue
        out[number] = (body.vectors, frame_vector(results, number, body.vectors,
                                                  problems))
    return out


def declared_pairs(model: Model, results) -> tuple[tuple[int, ...], list[SpatialPair],
                                                   dict[int, bool]]:
    """The moving links, the pairs of the model's joints (each checked against the
    motion) and the links that spin idly about a line (see the module).

    Raises :class:`~mechloop.errors.ModelError` for a joint the file or the motion
    contradicts."""
    from mechloop.solve.kinematics import solve
    from mechloop.spatial.bodies import body_frame
    from mechloop.spatial.joints import body_reference, build_joints3
    from mechloop.spatial.points import Placement3
    from mechloop.spatial.reactions import check_joints_fit

    problems: list[Problem] = []
    bodies = _frames(model, results, problems)
    joints = build_joints3(model, set(bodies), problems)
    if problems:
        raise ModelError(problems)

    def frames_of(res):
        return {b: body_frame(res, vectors, second=second)
                for b, (vectors, second) in bodies.items()}

    place = Placement3(results)
    analogs = {}
    with np.errstate(invalid="ignore"):
        for k in sorted(model.arguments):
            ana = solve(model, analogs_of=k)
            analogs[k] = (Placement3(ana), frames_of(ana))
        refs = {b: body_reference(model, results, b, vectors)
                for b, (vectors, _) in bodies.items()}
        check_joints_fit(joints, [], place, frames_of(results), analogs, refs)
    ok = ~np.asarray(results.broken, dtype=bool)
    pairs = []
    for joint in joints:
        points = place.point(joint.at).p[:, ok]
        axes = None if joint.axis is None else joint.direction(place)[:, ok]
        pairs.append(SpatialPair(joint.name, KIND[joint.kind], tuple(sorted(joint.bodies)),
                                 points[:, 0], None if axes is None else axes[:, 0],
                                 points, axes))
    links = tuple(sorted(bodies))
    return links, pairs, {b: _on_a_line(b, pairs) for b in links}


def _distance(points: Array, base: Array, direction: Array) -> Array:
    """The distances of ``points`` from the lines through ``base`` along the unit
    ``direction`` (all ``(3, P)``), ``(P,)``."""
    rel = points - base
    return np.linalg.norm(rel - direction * np.einsum("ip,ip->p", rel, direction), axis=0)


def _on_a_line(link: int, pairs: list[SpatialPair]) -> bool:
    """Whether the balls of ``link`` (at least one) and its cylindrical pairs lie on one
    line at every position (it has no other pair): the link turns about that line freely."""
    mine = [p for p in pairs if link in p.links]
    balls = [p.points for p in mine if p.kind == "S"]
    sleeves = [(p.points, p.axes) for p in mine if p.kind == "C"]
    if not balls or len(balls) + len(sleeves) != len(mine) or len(mine) < 2:
        return False
    every = np.concatenate([*balls, *(s for s, _ in sleeves)], axis=1)
    size = max(float(np.abs(every).max()), 1e-300)
    if sleeves:
        base, direction = sleeves[0]
    else:
        base, span = balls[0], balls[1] - balls[0]
        length = np.linalg.norm(span, axis=0)
        if np.any(length <= LINE_RTOL * size):
            return False  # two balls at one point: no line
        direction = span / length
    if any(_distance(b, base, direction).max() > LINE_RTOL * size for b in balls):
        return False
    return all(_distance(s, base, direction).max() <= LINE_RTOL * size
               and np.linalg.norm(np.cross(a, direction, axis=0), axis=0).max()
               <= LINE_RTOL for s, a in sleeves)
