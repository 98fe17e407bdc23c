"""Kinetostatics: joint reactions and balancing loads at every position, with friction.

d'Alembert: for every moving body, external loads + joint reactions + drive loads +
inertia loads (``−m·a_S`` at each centre of mass, ``−J·ε``) balance.  Three equations
per body (forces in x, y; moments about a point of the body) in the unknowns

* two per revolute pair: the reaction ``R = Rx + i·Ry`` of the first body on the second;
* two per prismatic pair: the normal force ``N`` (along the left normal of the sliding
  vector) and the reaction moment ``M`` about the pair's point, on the second body;
* one per drive: the balancing moment (an angle argument; on the driven body, against the
  ground) or force (a length argument; along the driven vector, pushing its ends apart).

The systems of all positions are one batched linear solve, shape ``(P, K, K)``.  Friction
(a moment ``f·ρ·|R|`` in a revolute pair, a force ``f·max(|N|, 2|M|/b)`` in a prismatic
one, each against the relative motion) depends on the reactions: it is added as a known load
and the solve repeated until the reactions stop changing (a fixed point; f·ρ/l is small).
"""

from __future__ import annotations

from dataclasses import dataclass
from dataclasses import field as _field

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.loads import Loads
from mechloop.dynamics.mechanism import Mechanism, Pair
from mechloop.dynamics.points import Motion, Placement
from mechloop.errors import SolveError

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]

#: Friction iterations stop when no reaction changes by more than this (relative).
FRICTION_RTOL = 1e-12
FRICTION_MAX_ITER = 200
#: A force system whose matrix has a condition number above this is singular (a dead
#: point of the force analysis: the reactions are unbounded).
SINGULAR_COND = 1e12


class FrictionError(SolveError):
    """Friction in the pairs that does not settle: the reactions keep changing from one
    iteration to the next (a self-locking mechanism, or friction too large)."""


def cross(z: Complex, w: Complex) -> Array:
    """z × w for plane vectors written as complex numbers (``x_z·y_w − y_z·x_w``)."""
    return (np.conj(z) * w).imag


@dataclass(frozen=True)
class BodyMotion:
    """A body's reference point and angle over positions: ``ref`` (m) and
    ``angle``/``omega``/``epsilon`` (rad, rad/s, rad/s²), shape (P,)."""

    ref: Motion
    angle: Array
    omega: Array
    epsilon: Array

    def velocity_at(self, z: Complex) -> Complex:
        """Velocity (m/s) of the body's point that is at ``z``."""
        return self.ref.v + 1j * self.omega * (z - self.ref.z)


def body_motions(mechanism: Mechanism, placement: Placement) -> dict[int, BodyMotion]:
    """Every moving body's frame (the ground is at rest)."""
    res = placement.results
    out = {}
    for number, frame in mechanism.bodies.items():
        v, end = frame.held[0] if frame.held else (frame.vectors[0], "tail")
        ref = placement.tail(v) if end == "tail" else placement.head(v)
        name = f"a{frame.angle_vector}"
        out[number] = BodyMotion(ref, res.value(name), res.rate(name), res.accel(name))
    return out


@dataclass(frozen=True)
class PairReaction:
    """The reaction of a pair over positions (force of the first body on the second).

    ``force`` (N, complex) includes friction; for a prismatic pair ``normal`` (N) and
    ``moment`` (N·m) are the normal force and the reaction moment about ``point``, and
    ``friction`` the friction force along the slide; for a revolute pair ``friction`` is the
    friction moment on the second body (N·m).  ``loss`` (W, ≥ 0) is the power friction
    takes from the machine; ``point`` is where the pair is.
    """

    pair: Pair
    point: Motion
    force: Complex
    normal: Array | None
    moment: Array | None
    friction: Array
    loss: Array


@dataclass(frozen=True)
class ForceAnalysis:
    """Reactions of every pair and the balancing load of every drive, shape (P,).

    ``singular`` marks the positions whose force system is singular; ``iterations`` is the
    number of friction iterations done (0 without friction).  For a batch solved in
    segments (``kinetostatics(..., segments=...)``), ``unsettled`` marks the positions of
    the segments whose friction did not settle (their rows are NaN) and
    ``segment_iterations`` (shape (S,)) the iteration at which each segment settled
    (:data:`FRICTION_MAX_ITER` for one that did not); without segments ``unsettled`` is
    all False (friction that does not settle raises) and ``segment_iterations`` None.
    """

    reactions: dict[str, PairReaction]
    balancing: dict[int, Array]
    singular: NDArray[np.bool_]
    iterations: int
    unsettled: NDArray[np.bool_]
    segment_iterations: NDArray[np.int64] | None = None
    #: the force of every gear mesh (:mod:`mechloop.dynamics.meshes`), by name
    meshes: dict = _field(default_factory=dict)

    @property
    def friction_loss(self) -> Array:
        """Power taken by friction in all pairs (W, ≥ 0)."""
        n = self.singular.size
        return sum((r.loss for r in self.reactions.values()), np.zeros(n))


def kinetostatics(mechanism: Mechanism, placement: Placement, loads: Loads, *,
                  friction: bool = True, static: bool = False,
                  segments: NDArray[np.int64] | None = None) -> ForceAnalysis:
    """Reactions and balancing loads at every position (SI).

    The placement's results hold time derivatives; with ``static=True`` (a model without
    time) inertia is left out and the derivatives only give friction its direction.  With
    ``friction=False`` the pairs are ideal whatever the model says.  Rows where the chain
    breaks are NaN; rows where the force system is singular are NaN and marked in
    ``singular``.

    Friction is iterated until no reaction changes by more than :data:`FRICTION_RTOL` of
    the largest known load, and :class:`~mechloop.errors.SolveError` is raised when it does
    not settle in :data:`FRICTION_MAX_ITER` iterations.  ``segments`` (shape (P,), the
    integers ``0..S−1``; default None: one segment) splits the positions into independent
    problems, e.g. the designs of a population laid out on one axis: the tolerance and the
    stop are then per segment, a settled segment keeps the reactions and friction loads of
    the iteration at which it settled (so each equals its own separate run), and a segment
    that does not settle is reported in ``unsettled`` (NaN rows) instead of raising.
    """
    res = placement.results
    n = res.broken.size
    bodies = body_motions(mechanism, placement)
    index = {b: i for i, b in enumerate(sorted(mechanism.bodies))}
    size = 3 * len(index)
    ok = ~res.broken

    def rows(body: int) -> int | None:
        return None if body == 0 else 3 * index[body]

    def origin(body: int) -> Complex:
        return bodies[body].ref.z

    # right-hand side: inertia loads minus known loads, per body
    rhs = np.zeros((n, size))

    def add_known(body: int, force: Complex | float, at: Complex | None, moment=0.0,
                  target=rhs) -> None:
        row = rows(body)
        if row is None:
            return
        force = np.asarray(force, dtype=complex)
        target[:, row] -= force.real
        target[:, row + 1] -= force.imag
        m = moment if at is None else moment + cross(at - origin(body), force)
        target[:, row + 2] -= m

    for mass in () if static else mechanism.masses:
        s = placement.point(mass.center)
        row = rows(mass.body)
        inertia = mass.mass * s.a
        rhs[:, row] += inertia.real
        rhs[:, row + 1] += inertia.imag
        rhs[:, row + 2] += (cross(s.z - origin(mass.body), inertia)
                            + mass.inertia * bodies[mass.body].epsilon)
    for load in loads.forces:
        add_known(load.body, load.force, load.point.z)
    for couple in loads.moments:
        add_known(couple.body, 0.0, None, couple.moment)

    # matrix of the unknowns
    columns: list[tuple[str, object]] = []
    matrix = np.zeros((n, size, size))
    points: dict[str, Motion] = {}
    directions: dict[str, Complex] = {}

    def put(col: int, body: int, force: Complex | float, at: Complex | None,
            moment: Array | float = 0.0, sign: float = 1.0) -> None:
        row = rows(body)
        if row is None:
            return
        force = np.asarray(force, dtype=complex)
        matrix[:, row, col] += sign * force.real
        matrix[:, row + 1, col] += sign * force.imag
        m = moment if at is None else moment + cross(at - origin(body), force)
        matrix[:, row + 2, col] += sign * m

    col = 0
    for pair in mechanism.pairs:
        first, second = pair.bodies
        point = placement.point(pair.at)
        points[pair.name] = point
        z = point.z
        if pair.kind == "revolute":
            for unit in (1.0 + 0j, 1j):
                put(col, second, np.full(n, unit), z)
                put(col, first, np.full(n, unit), z, sign=-1.0)
                col += 1
        else:
            e = np.exp(1j * res.value(f"a{pair.along}"))
            directions[pair.name] = e
            normal = 1j * e
            put(col, second, normal, z)
            put(col, first, normal, z, sign=-1.0)
            put(col + 1, second, 0.0, None, 1.0)
            put(col + 1, first, 0.0, None, 1.0, sign=-1.0)
            col += 2
        columns.append((pair.name, pair))
    from mechloop.dynamics import meshes as gearing

    mesh_cols = []  # one unknown per gear mesh: its tangential force
    for mesh in mechanism.meshes:
        p, u, t = gearing.directions(mesh, placement)
        mesh_cols.append((mesh, col, p, u, t))
        col += 1
    drive_cols = {}
    for drive in mechanism.drives:
        tail_body, head_body = drive.bodies
        if drive.kind == "angle":
            put(col, head_body, 0.0, None, 1.0)
        else:
            e = np.exp(1j * res.value(f"a{drive.vector}"))
            put(col, head_body, e, placement.head(drive.vector).z)
            put(col, tail_body, -e, placement.tail(drive.vector).z)
        drive_cols[drive.argument] = col
        col += 1
    if col != size:  # build_mechanism guarantees a square system
        raise SolveError(f"force analysis has {col} unknowns for {size} equations")

    safe = ok.copy()
    rhs[~safe] = 0.0
    minus = {mesh.name: np.zeros(n, dtype=bool) for mesh, *_ in mesh_cols}
    for _ in range(3):  # the line of action of each mesh follows the sign of its force
        for mesh, c, p, u, t in mesh_cols:
            side = np.where(minus[mesh.name], -1.0, 1.0)
            d = t + side * np.tan(mesh.pressure) * u
            matrix[:, :, c] = 0.0
            put(c, mesh.bodies[1], d, p)
            put(c, mesh.bodies[0], d, p, sign=-1.0)
        matrix[~safe] = np.eye(size)
        inverse, singular = _invert(matrix, safe)
        x = np.einsum("pij,pj->pi", inverse, rhs)
        flips = {mesh.name: gearing.choose_sides(x[:, c]) & safe & ~singular
                 for mesh, c, *_ in mesh_cols}
        if all(np.array_equal(flips[k], minus[k]) for k in minus):
            break
        minus = flips

    def solve(b: Array) -> Array:
        return np.einsum("pij,pj->pi", inverse, b)
    with_friction = friction and any(p.friction > 0 for p in mechanism.pairs)
    iterations = 0
    losses = {p.name: np.zeros(n) for p in mechanism.pairs}
    fric = {p.name: np.zeros(n) for p in mechanism.pairs}
    # each segment (a design of a batch; the whole axis without one) iterates on its own
    seg = np.zeros(n, dtype=np.int64) if segments is None else np.asarray(segments)
    if seg.shape != (n,) or (n and seg.min() < 0):
        raise ValueError(f"segments must be integers ≥ 0 shaped ({n},), one per position "
                         f"(got shape {seg.shape})")
    n_seg = 1 if segments is None else int(seg.max(initial=-1)) + 1
    seg_iterations = np.zeros(n_seg, dtype=np.int64)
    settling = np.zeros(n_seg, dtype=bool)  # segments still iterating
    if with_friction:
        good = safe & ~singular
        scale = _segment_max(np.abs(rhs[good]).max(axis=1, initial=0.0), seg[good], n_seg)
        scale = np.maximum(scale, 1e-300)
        settling[:] = True
        # a segment that diverges (self-locking) may overflow before it is stopped: its rows
        # end NaN and marked unsettled, or the whole solve raises below
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            for iterations in range(1, FRICTION_MAX_ITER + 1):
                moving = settling[seg]
                extra = np.zeros((n, size))
                c = 0
                for pair in mechanism.pairs:
                    first, second = pair.bodies
                    z = points[pair.name].z
                    if pair.kind == "revolute":
                        r = np.hypot(x[:, c], x[:, c + 1])
                        rel = _omega(bodies, second) - _omega(bodies, first)
                        m_f = -pair.friction * pair.radius * r * np.sign(rel)
                        add_known(second, 0.0, None, m_f, extra)
                        add_known(first, 0.0, None, -m_f, extra)
                        fric[pair.name] = np.where(moving, m_f, fric[pair.name])
                        losses[pair.name] = np.where(moving, -m_f * rel, losses[pair.name])
                        c += 2
                    else:
                        e = directions[pair.name]
                        normal, moment = x[:, c], x[:, c + 1]
                        load = np.maximum(np.abs(normal), 2.0 * np.abs(moment) / pair.length) \
                            if pair.length > 0 else np.abs(normal)
                        rel = (_velocity(bodies, second, z) - _velocity(bodies, first, z))
                        slide = (np.conj(e) * rel).real
                        f_f = -pair.friction * load * np.sign(slide)
                        add_known(second, f_f * e, z, 0.0, extra)
                        add_known(first, -f_f * e, z, 0.0, extra)
                        fric[pair.name] = np.where(moving, f_f, fric[pair.name])
                        losses[pair.name] = np.where(moving, -f_f * slide, losses[pair.name])
                        c += 2
                new = solve(rhs + extra)
                step = np.abs(new - x)[good].max(axis=1, initial=0.0)
                change = _segment_max(step, seg[good], n_seg)
                x = np.where(moving[:, None], new, x)
                done = settling & (change <= FRICTION_RTOL * scale)
                seg_iterations[done] = iterations
                settling &= ~done
                if not settling.any():
                    break
        seg_iterations[settling] = FRICTION_MAX_ITER
        if segments is None and settling.any():
            raise FrictionError(
                f"friction: the reactions did not settle in {FRICTION_MAX_ITER} iterations "
                "(the mechanism may be self-locking at some positions)",
                "lower the coefficients of friction or check the pin radii and slider "
                "lengths")
    unsettled = settling[seg]

    bad = ~safe | singular | unsettled
    x[bad] = np.nan
    reactions: dict[str, PairReaction] = {}
    c = 0
    for pair in mechanism.pairs:
        point = points[pair.name]
        if pair.kind == "revolute":
            force = x[:, c] + 1j * x[:, c + 1]
            reactions[pair.name] = PairReaction(pair, point, force, None, None,
                                                _nan(fric[pair.name], bad),
                                                _nan(losses[pair.name], bad))
        else:
            e = directions[pair.name]
            normal, moment = x[:, c], x[:, c + 1]
            force = normal * 1j * e + fric[pair.name] * e
            reactions[pair.name] = PairReaction(pair, point, force, normal, moment,
                                                _nan(fric[pair.name], bad),
                                                _nan(losses[pair.name], bad))
        c += 2
    balancing = {k: x[:, c] for k, c in drive_cols.items()}
    mesh_forces = {}
    for mesh, c, p, u, t in mesh_cols:
        side = np.where(minus[mesh.name], -1.0, 1.0)
        tangential = x[:, c]
        radial = side * np.tan(mesh.pressure) * tangential
        mesh_forces[mesh.name] = gearing.MeshForce(
            mesh, p, tangential * t + radial * u, tangential, radial,
            np.abs(tangential) / np.cos(mesh.pressure))
    return ForceAnalysis(reactions, balancing, singular, iterations, unsettled,
                         None if segments is None else seg_iterations, mesh_forces)


def _invert(matrix: Array, safe: NDArray[np.bool_]) -> tuple[Array, NDArray[np.bool_]]:
    """Inverses of a stack of matrices ``(P, K, K)`` and the mask of the singular ones
    (condition number in the ∞-norm above :data:`SINGULAR_COND`), replaced by identities
    before inverting.  The exact SVD condition number is used only when some matrix is
    exactly singular."""
    try:
        with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
            inverse = np.linalg.inv(matrix)
            cond = (np.abs(matrix).sum(axis=2).max(axis=1)
                    * np.abs(inverse).sum(axis=2).max(axis=1))
    except np.linalg.LinAlgError:
        with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
            cond = np.linalg.cond(matrix)
        inverse = None
    singular = safe & ~(cond < SINGULAR_COND)
    if singular.any() or inverse is None:
        matrix = matrix.copy()
        matrix[singular] = np.eye(matrix.shape[-1])
        inverse = np.linalg.inv(matrix)
    return inverse, singular


def _segment_max(values: Array, segments: NDArray[np.int64], count: int) -> Array:
    """The largest of ``values`` (≥ 0) in each of ``count`` segments (0 for an empty one;
    NaN propagates)."""
    out = np.zeros(count)
    np.maximum.at(out, segments, values)
    return out


def _nan(values: Array, bad: NDArray[np.bool_]) -> Array:
    out = np.array(values, dtype=float)
    out[bad] = np.nan
    return out


def _omega(bodies: dict[int, BodyMotion], body: int) -> Array | float:
    return 0.0 if body == 0 else bodies[body].omega


def _velocity(bodies: dict[int, BodyMotion], body: int, z: Complex) -> Complex:
    return np.zeros_like(z) if body == 0 else bodies[body].velocity_at(z)
