"""Structure of a model with spatial contours (issue 17): its links, its kinematic pairs
with their classes, and the mobility by the Somov–Malyshev formula
``W = 6n − 5p5 − 4p4 − 3p3 − 2p2 − p1``, with the passive (idle) degrees of freedom and
the redundant constraints.

Links are the model's bodies and the ground 0 (a vector of no body whose r, α and β are
all constant), as in the planar analysis (:mod:`mechloop.dynamics.mechanism`): a body's
vectors of constant length hold both their ends, a sliding one the end ``ends`` names.
Where a contour passes from a vector held by one link to a vector held by another, the two
links form a pair at that point (one pair per distinct point); a vector that changes
length between two links is a sliding pair between them.

The class of a pair is told from the relative motion of its links over the positions:
the relative angular velocity ``ω_B − ω_A`` in the frame of link A spans 1, 2 or 3
directions — a revolute pair R (class 5, its axis that direction through the point), a
universal joint U (class 4) or a spherical pair S (class 3); a sliding pair with no
relative rotation is prismatic P (class 5), with rotation about one axis cylindrical C
(class 4).  A body whose vectors all lie on one line (a rod) has no spin about it in the
model: at a pair whose relative rotation spans two directions or more it is a spherical
pair, and a rod whose every pair is spherical, or cylindrical along its line, spins
about its line freely — one idle (passive) degree of freedom (the RSSR coupler between
its two ball joints; each of a hydraulic cylinder's barrel and rod between two ball
joints).  Two rods that slide along one vector form a cylindrical pair C.

When every pair is revolute and all the axes meet at one point the mechanism is spherical
(three common constraints: Dobrovolsky's formula ``W = 3n − 2p5``); all axes parallel:
planar (``W = 3n − 2p5`` again).  Redundant constraints are ``q = W_real − W`` where the
real mobility is the number of inputs plus the idle degrees of freedom.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.holds import shared_junctions, vector_holds
from mechloop.errors import ModelError, Problem
from mechloop.model.schema import ArgumentRole, Model

Array = NDArray[np.float64]

#: Relative angular velocities smaller than this share of the largest are zero (rank).
RANK_RTOL = 1e-7
#: Two pair points are one when they differ by at most this share of the model's size.
SAME_POINT_RTOL = 1e-9
#: Axes meet at one point / are parallel within this share of the model's size (sine).
AXES_RTOL = 1e-7

#: class of each kind of pair (the number of constraints it imposes)
CLASSES = {"R": 5, "P": 5, "C": 4, "U": 4, "S": 3}


@dataclass(frozen=True)
class SpatialPair:
    """A kinematic pair: ``kind`` (R, P, C, U, S), its ``links`` ``(A, B)`` (0: ground),
    where it is (``point``, m, at the first position that closes) and, for R and C, its
    ``axis`` (unit vector, model axes); ``points`` and ``axes`` ``(3, P')`` are the same
    over every position that closes (None: only the one known)."""

    name: str
    kind: str
    links: tuple[int, int]
    point: Array
    axis: Array | None
    points: Array | None = None
    axes: Array | None = None

    @property
    def klass(self) -> int:
        """The class of the pair: how many relative motions it takes away."""
        return CLASSES[self.kind]


@dataclass(frozen=True)
class SpatialStructure:
    """The structure of a spatial model: ``links`` (moving), ``pairs``, the counts ``p``
    by class, ``W`` by Somov–Malyshev, ``idle`` (the rods that spin freely), ``inputs``
    (arguments), ``family`` (``"spherical"``, ``"planar"`` or None: common constraints
    of all pairs) with its ``W_family`` (``3n − 2p5``), and the redundant constraints
    ``q`` (≥ 0; 0: none)."""

    links: tuple[int, ...]
    pairs: tuple[SpatialPair, ...]
    p: dict[int, int]
    W: int
    idle: tuple[int, ...]
    inputs: int
    family: str | None
    W_family: int | None
    q: int
    #: where the pairs come from: ``"contours"`` (found from the contours and bodies),
    #: ``"joints"`` (the model's joints:) or ``"vectors"`` (no bodies: links from the
    #: vectors, :mod:`.spatial_vectors`)
    source: str = "contours"
    #: with ``source == "vectors"``: each moving link's vectors
    vector_links: dict[int, tuple[int, ...]] | None = None

    @property
    def n(self) -> int:
        return len(self.links)


def _frames(model: Model, results, problems: list[Problem]):
    """Each link's axes ``(3, 3, P)``, angular velocity ``(3, P)`` and whether it is a
    rod; the ground's are the model axes and zero."""
    from mechloop.spatial.bodies import body_frame, frame_vector, vectors_defined

    count = results.positions.size
    frames = {0: (np.repeat(np.eye(3)[:, :, None], count, axis=2), np.zeros((3, count)),
                  False)}
    for number, body in model.bodies.items():
        if not vectors_defined(model, number, body, problems):
            continue
        second = frame_vector(results, number, body.vectors, problems)
        frame = body_frame(results, body.vectors, second=second)
        frames[number] = (frame.axes, frame.omega, frame.rod)
    return frames


def _rank(m: Array) -> tuple[int, Array]:
    """The rank of ``m`` ``(3, P)`` (relative to its largest singular value) and its left
    singular vectors (columns, largest first)."""
    u, sv, _ = np.linalg.svd(m, full_matrices=False)
    if sv[0] == 0.0:
        return 0, u
    return int(np.sum(sv > RANK_RTOL * sv[0])), u


def _relative(frames, a: int, b: int, ok) -> tuple[str, Array | None, Array | None]:
    """``"R"`` with its axis (model axes, at the position of the largest relative
    rotation) and the axis over the positions ``ok`` ``(3, P')``, ``"U"``, ``"S"`` or
    ``"0"`` (no relative rotation) for the rotation of link ``b`` relative to link ``a``.

    Full frames: the rank of ``ω_b − ω_a`` in ``a``'s frame.  A rod (its spin unknown):
    revolute when some direction ``k`` fixed in the other link is coplanar with the rod's
    line ``u`` and its swing ``ω`` at every position, ``(ω × u) · k = 0`` (``ω + s u ∥ k``
    for some spin ``s``), else spherical; two rods: spherical."""
    axes_a, wa, rod_a = frames[a]
    axes_b, wb, rod_b = frames[b]
    if rod_a and rod_b:
        return "S", None, None
    if rod_a:  # the rod second
        a, b = b, a
        axes_a, wa, axes_b, wb = axes_b, wb, axes_a, wa
    rel = (wb - wa)[:, ok]
    frame = axes_a[:, :, ok]
    local = np.einsum("iap,ip->ap", frame, rel)
    if not (rod_a or rod_b):
        rank, u = _rank(local)
        if rank == 0:
            return "0", None, None
        if rank > 1:
            return ("U" if rank == 2 else "S"), None, None
        axis = np.einsum("iap,a->ip", frame, u[:, 0])
        k = int(np.argmax(np.linalg.norm(rel, axis=0)))
        return "R", axis[:, k], axis
    line = np.einsum("iap,ip->ap", frame, axes_b[:, 0, ok])
    normals = np.cross(local, line, axis=0)
    rank, u = _rank(normals)
    if rank == 0:  # no swing: spin only, about the rod's own line
        return "R", axes_b[:, 0, ok][:, 0], axes_b[:, 0, ok]
    if rank == 3:
        return "S", None, None
    axis = np.einsum("iap,a->ip", frame, u[:, -1])
    return "R", axis[:, 0], axis


def _kind(relative: str, sliding: bool) -> str:
    if sliding:
        return {"0": "P", "R": "C"}.get(relative, "S")
    return "R" if relative == "0" else relative


def spatial_pairs(model: Model, results) -> tuple[tuple[int, ...], list[SpatialPair],
                                                  dict[int, bool]]:
    """The moving links, the pairs inferred from the contours, and which links are rods.

    Raises :class:`~mechloop.errors.ModelError` without bodies, or when a point is held
    by more than two links."""
    from mechloop.spatial.points import Placement3, unit_direction

    if not model.bodies:
        raise ModelError([Problem(("bodies",), "the model has no bodies",
                                  "add bodies: {1: {vectors: [1], mass: ..., center: ...}}")])
    problems: list[Problem] = []
    frames = _frames(model, results, problems)
    if problems:
        raise ModelError(problems)
    holds = vector_holds(model, results.constant, letters="rab")
    place = Placement3(results)
    ok = ~np.asarray(results.broken, dtype=bool)
    first = int(np.argmax(ok))
    size = max(float(np.nanmax(np.abs(place.vector(v).p[:, ok]), initial=0.0))
               for v in model.vectors) or 1.0
    found: dict[tuple[int, int], list[tuple[Array, bool]]] = defaultdict(list)
    sliding_along: dict[tuple[int, int], int] = {}
    for v, key in shared_junctions(model, holds, problems):
        path = (place.tail(v) if v > 0 else place.head(-v)).p[:, ok]
        if any(np.max(np.abs(path - p)) <= SAME_POINT_RTOL * size for p, _ in found[key]):
            continue
        found[key].append((path, False))
    for v in model.vectors:
        if f"r{v}" in results.constant:
            continue
        tail, head = holds.get((v, "tail"), set()), holds.get((v, "head"), set())
        if len(tail) == 1 and len(head) == 1 and tail != head:
            key = tuple(sorted(tail | head))
            found[key].append((place.tail(v).p[:, ok], True))
            sliding_along[key] = v
    if problems:
        raise ModelError(problems)
    pairs = []
    for (a, b), points in sorted(found.items()):
        relative, direction, track = _relative(frames, a, b, ok)
        for k, (path, sliding) in enumerate(points):
            kind = _kind(relative, sliding)
            axis, axes = (direction, track) if kind in ("R", "C") else (None, None)
            if sliding and frames[a][2] and frames[b][2]:  # two rods on one line: a
                # cylinder and its rod — they slide and turn about it (C)
                axes = unit_direction(results, sliding_along[(a, b)]).p[:, ok]
                kind, axis = "C", axes[:, 0]
            name = f"{kind}{a}_{b}" + ("" if k == 0 else chr(ord("a") + k))
            pairs.append(SpatialPair(name, kind, (a, b), path[:, 0] if path.size else
                                     place.tail(1).p[:, first], axis,
                                     path if path.size else None, axes))
    links = tuple(sorted(b for b in model.bodies if b != 0))
    reached, grew = {0}, True
    while grew:  # the links joined to the ground through the pairs found
        grew = False
        for pair in pairs:
            if len(reached & set(pair.links)) == 1:
                reached |= set(pair.links)
                grew = True
    loose = [b for b in links if b not in reached]
    if loose:
        raise ModelError([Problem(("bodies", b), f"body {b} is joined to the ground by no "
                                  "pair found from the contours (they pass between its "
                                  "vectors and the others' through vectors of no body)",
                                  "list the vectors that meet it in the bodies they belong "
                                  "to, so that a contour passes from one body to another "
                                  "at each pair") for b in loose])
    rods = {b: frames[b][2] for b in links}
    return links, pairs, rods


def _tracks(pairs: list[SpatialPair]) -> tuple[Array, Array]:
    """Every pair's point and axis over the positions ``(K, 3, P')``: their tracks when
    all pairs have them over the same positions, else the one position known."""
    counts = {None if p.points is None or p.axes is None else p.points.shape[1]
              for p in pairs}
    if len(counts) == 1 and None not in counts:
        return (np.stack([p.points for p in pairs]),  # type: ignore[misc]
                np.stack([p.axes for p in pairs]))  # type: ignore[misc]
    return (np.stack([p.point for p in pairs])[:, :, None],
            np.stack([p.axis for p in pairs])[:, :, None])


def _family(pairs: list[SpatialPair]) -> str | None:
    """``"spherical"`` when every pair is revolute and all axes meet at one point,
    ``"planar"`` when they are all parallel, else None — at every position the pairs are
    known at (:attr:`SpatialPair.points`, :attr:`~SpatialPair.axes`), not at one."""
    if not pairs or any(p.kind != "R" or p.axis is None for p in pairs):
        return None
    points, axes = _tracks(pairs)  # (K, 3, P)
    axes = axes / np.linalg.norm(axes, axis=1, keepdims=True)
    size = max(float(np.max(np.abs(points))), 1e-12)
    if np.all(np.linalg.norm(np.cross(axes, axes[:1], axis=1), axis=1) <= AXES_RTOL):
        return "planar"
    # at each position the point nearest to every axis (least squares: Σ P_k c = Σ P_k x_k
    # with P_k = I − a_k a_kᵀ, regular when two axes are not parallel) and its distances
    proj = np.eye(3)[None, :, :, None] - axes[:, :, None] * axes[:, None, :]  # (K,3,3,P)
    lhs = np.moveaxis(proj.sum(axis=0), -1, 0)  # (P, 3, 3)
    rhs = np.einsum("kijp,kjp->pi", proj, points)
    sv = np.linalg.svd(lhs, compute_uv=False)
    if np.any(sv[:, -1] <= AXES_RTOL * sv[:, 0]):  # all axes parallel there only
        return None
    centre = np.linalg.solve(lhs, rhs[:, :, None])[:, :, 0].T  # (3, P)
    gaps = np.einsum("kijp,kjp->kip", proj, points - centre[None])
    return "spherical" if np.max(np.linalg.norm(gaps, axis=1)) <= AXES_RTOL * size else None


def _inputs(model: Model) -> int:
    """The arguments that drive a vector parameter."""
    used = {getattr(vec, letter).argument for vec in model.vectors.values()
            for letter in ("r", "a", "b")
            if isinstance(getattr(vec, letter, None), ArgumentRole)}
    return len(used)


def spatial_structure(model: Model, results=None) -> SpatialStructure:
    """The structure of ``model`` (with spatial contours), from its kinematics ``results``
    (solved when None): the pairs of its ``joints:`` when it names them
    (:mod:`.spatial_joints`: each checked against the motion), else the pairs found from
    the contours and bodies, or without bodies from the links its vectors make
    (:mod:`.spatial_vectors`)."""
    from dataclasses import replace

    if results is None:
        from mechloop.solve.kinematics import solve

        results = solve(model)
    if model.joints is not None and model.bodies:
        from mechloop.structure.spatial_joints import declared_pairs

        links, pairs, rods = declared_pairs(model, results)
        return replace(count(links, pairs, rods, _inputs(model)), source="joints")
    if not model.bodies:
        from mechloop.structure.spatial_vectors import vector_pairs

        links, pairs, rods, members = vector_pairs(model, results)
        return replace(count(links, pairs, rods, _inputs(model)), source="vectors",
                       vector_links=members)
    links, pairs, rods = spatial_pairs(model, results)
    return count(links, pairs, rods, _inputs(model))


def count(links: tuple[int, ...], pairs: list[SpatialPair], rods: dict[int, bool],
          inputs: int) -> SpatialStructure:
    """The Somov–Malyshev count of moving ``links`` joined by ``pairs`` (``rods``: which
    links are rods, for the idle spins) against ``inputs``.

    >>> import numpy as np
    >>> z, o = np.array([0, 0, 1.0]), np.zeros(3)
    >>> pin = lambda a, b: SpatialPair("R", "R", (a, b), o, z)
    >>> ball = lambda a, b: SpatialPair("S", "S", (a, b), o, None)
    >>> s = count((1, 2, 3), [pin(0, 1), ball(1, 2), ball(2, 3), pin(0, 3)],
    ...           {1: False, 2: True, 3: False}, 1)
    >>> s.W, s.idle, s.q
    (2, (2,), 0)
    """
    p = {c: sum(1 for pair in pairs if pair.klass == c) for c in (5, 4, 3, 2, 1)}
    n = len(links)
    w = 6 * n - sum(c * p[c] for c in p)
    idle = tuple(b for b in links if rods.get(b) and
                 all(pair.kind in ("S", "C") for pair in pairs if b in pair.links)
                 and any(pair.kind == "S" for pair in pairs if b in pair.links))
    family = _family(pairs)
    w_family = 3 * n - 2 * p[5] if family else None
    q = max(inputs + len(idle) - w, 0)
    return SpatialStructure(tuple(links), tuple(pairs), p, w, idle, inputs, family,
                            w_family, q)
