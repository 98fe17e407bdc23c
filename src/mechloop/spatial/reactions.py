"""Joint reactions of a model with spatial contours by the Newton–Euler equations (issue 17).

Every moving body ``b`` gives six equations, its forces and its moments about a point
``O_b`` fixed in it (:func:`~mechloop.spatial.joints.body_reference`)::

    Σ F = Σ m a_S
    Σ (P − O_b) × F + Σ M = Σ [(S − O_b) × m a_S + J_w ε + ω × J_w ω]

with the loads and gravity of :mod:`mechloop.spatial.loads`, the masses of
:mod:`mechloop.spatial.bodies`, and as unknowns the components of every joint's reaction
(:data:`~mechloop.spatial.joints.COMPONENTS`: ``−(F, M)`` on the first body, ``(F, M)``
on the second, ``F`` through the joint's point) and the balancing load of every argument
(:class:`~mechloop.spatial.joints.Drive3`).  Without model time the inertia terms are left
out (a static analysis).  The systems of all positions form one batch ``(P, 6B, K)``,
scaled so that its entries are O(1) (moment rows divided by the mechanism's size ``L``,
moment unknowns multiplied by it), and are solved by the batched SVD.

What is decided before the reactions are trusted:

* **the joints fit the motion**: a reaction does no work on any motion of the mechanism,
  so every unknown's power with the velocity analogs of every argument (each body's
  ``v'_O``, ``ω'``) is zero — and a drive's is 1 for its own argument, 0 for the others.
  A joint that breaks this (a pin whose bodies turn about another axis, a ball centre that
  is not a point of both bodies) is a located problem;
* **determinacy**: the rank ``r`` of the system (singular values above
  :data:`~mechloop.spatial.determinacy.RANK_RTOL` of the largest; the largest rank over
  the positions) equals the number of unknowns ``K``; otherwise some reactions balance
  each other whatever the loads (statically indeterminate) and the problem names the
  joints involved and a change of joint types that makes the analysis determinate
  (:mod:`mechloop.spatial.determinacy`);
* **idle motions**: ``6B − r`` combinations of the equations have no unknown (a coupler
  between two ball joints spinning about their line): each is dropped when the loads and
  inertia balance in it (residual ≤ :data:`~mechloop.spatial.determinacy.RESIDUAL_RTOL`
  of the system's scale at every position), and is otherwise a problem that names the
  body, the axis and the imbalance — never a least-squares answer.

A position where the system loses rank (``s_min/s_max`` below :data:`SINGULAR_RTOL`) is
singular: its reactions are unbounded, left NaN and marked.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import ModelError, Problem
from mechloop.spatial.bodies import Frame
from mechloop.spatial.determinacy import RANK_RTOL, idle_motions, indeterminate
from mechloop.spatial.joints import COMPONENTS, Drive3, Joint3, PointOn
from mechloop.spatial.loads import Force3, Moment3
from mechloop.spatial.points import Placement3

Array = NDArray[np.float64]

#: A position whose smallest used singular value is below this share of the largest is
#: singular (a dead point of the force analysis), as the planar ``SINGULAR_COND`` = 1e12.
SINGULAR_RTOL = 1e-12
#: A reaction's power on the mechanism's motion must vanish to this share of its terms.
POWER_RTOL = 1e-7
#: Positions per batched SVD (memory: 8·6B·K bytes and the same for U, V per position).
CHUNK = 8192


@dataclass(frozen=True)
class JointReaction:
    """The reaction of a joint's first body on its second over positions: ``force`` (N)
    through ``point`` (m) and ``moment`` (N·m, about ``point``), each ``(3, P)`` in the
    model's axes."""

    joint: Joint3
    point: Array
    force: Array
    moment: Array


@dataclass(frozen=True)
class SpatialReactions:
    """The force analysis of a spatial model: the reaction of every joint by name, the
    balancing load of every argument from the Newton–Euler equations (N·m or N),
    ``singular`` positions (reactions NaN there), the idle motions whose equations were
    dropped (each described), the rank and the number of unknowns, and each position's
    residual ``|A x − b|`` relative to the system's scale."""

    joints: dict[str, JointReaction]
    balancing: dict[int, Array]
    singular: NDArray[np.bool_]
    idle: tuple[str, ...]
    rank: int
    unknowns: int
    residual: Array


@dataclass(frozen=True)
class Column:
    """One unknown: a unit wrench (force through ``point``, moment) on ``bodies[1]``,
    its opposite on ``bodies[0]``; ``owner`` is a joint's name or a drive's argument,
    ``part`` force or moment, ``role`` axial, across or xyz."""

    owner: str | int
    part: str
    role: str
    bodies: tuple[int, int]
    force: Array
    point: Array
    moment: Array


def _across(axis: Array) -> tuple[Array, Array]:
    """Two unit directions across ``axis`` (``(3, P)``), with it a right-handed frame."""
    pick = np.argmin(np.abs(np.nan_to_num(axis)), axis=0)
    first = np.cross(axis, np.eye(3)[:, pick], axis=0)
    first /= np.linalg.norm(first, axis=0)
    return first, np.cross(axis, first, axis=0)


def _joint_columns(joint: Joint3, place: Placement3) -> list[Column]:
    at = place.point(joint.at).p
    zero = np.zeros_like(at)
    forces, moments = COMPONENTS[joint.kind]
    if joint.axis is None:
        dirs = {"xyz": [("xyz", zero + e[:, None]) for e in np.eye(3)]}
    else:
        axis = joint.direction(place)
        p1, p2 = _across(axis)
        dirs = {"xyz": [("axial", axis), ("across", p1), ("across", p2)],
                "across": [("across", p1), ("across", p2)]}
    out = [Column(joint.name, "force", role, joint.bodies, d, at, zero)
           for role, d in dirs[forces]]
    if moments:
        out += [Column(joint.name, "moment", role, joint.bodies, zero, at, d)
                for role, d in dirs[moments]]
    return out


def _drive_column(drive: Drive3, place: Placement3) -> Column:
    force, point, moment = drive.wrench(place)
    return Column(drive.argument, "force" if drive.kind == "length" else "moment",
                   "drive", drive.bodies, force, point, moment)


def _matrix(columns: list[Column], rows: dict[int, int], refs: dict[int, Array]
            ) -> Array:
    """The unknowns' wrenches on every body, ``(P, 6B, K)`` (forces, moments about the
    body's reference point)."""
    n = refs[next(iter(refs))].shape[1]
    a = np.zeros((n, 6 * len(rows), len(columns)))
    for c, col in enumerate(columns):
        for sign, b in ((-1.0, col.bodies[0]), (1.0, col.bodies[1])):
            if b == 0:
                continue
            i = 6 * rows[b]
            a[:, i:i + 3, c] += sign * col.force.T
            a[:, i + 3:i + 6, c] += sign * (np.cross(col.point - refs[b], col.force, axis=0)
                                             + col.moment).T
    return a


def _mv(j: Array, w: Array) -> Array:
    return np.einsum("ijp,jp->ip", j, w)


def newton_euler_rhs(terms, forces: list[Force3], moments: list[Moment3],
                     place: Placement3, rows: dict[int, int], refs: dict[int, Array], *,
                     static: bool) -> Array:
    """``b`` of ``A x = b``: per body the inertia terms less the known loads, ``(P, 6B)``
    (``terms``: per mass its centre's motion, frame and tensor in the model's axes)."""
    n = place.results.broken.size
    out = np.zeros((6 * len(rows), n))
    if not static:
        for mass, s, frame, jw in terms:
            i = 6 * rows[mass.body]
            ma = mass.mass * s.a
            out[i:i + 3] += ma
            out[i + 3:i + 6] += (np.cross(s.p - refs[mass.body], ma, axis=0)
                                 + _mv(jw, frame.epsilon)
                                 + np.cross(frame.omega, _mv(jw, frame.omega), axis=0))
    for f in forces:
        i = 6 * rows[f.body]
        out[i:i + 3] -= f.force
        out[i + 3:i + 6] -= np.cross(place.point(f.at).p - refs[f.body], f.force, axis=0)
    for m in moments:
        i = 6 * rows[m.body]
        out[i + 3:i + 6] -= m.moment
    return out.T


def _twist(place: Placement3, frames: dict[int, Frame], rows: dict[int, int],
           ref_points: dict[int, PointOn]) -> Array:
    """Every body's ``(v_O, ω)`` over positions, ``(P, 6B)``."""
    n = place.results.broken.size
    out = np.zeros((6 * len(rows), n))
    for b, i in rows.items():
        out[6 * i:6 * i + 3] = place.point(ref_points[b]).v
        out[6 * i + 3:6 * i + 6] = frames[b].omega
    return out.T


def _check_power(sa: Array, columns: list[Column], col_scale: Array, size: float,
                 analogs, rows, ref_points, good: NDArray[np.bool_],
                 problems: list[Problem]) -> None:
    """Every unknown's power with the analogs of every argument: 0 for a reaction, 1 for a
    drive with its own argument (see the module); problems name the joints that break it.
    ``sa``: the scaled system (its unknowns' powers are ``col_scale`` times theirs with
    the twists ``(v_O, ω·size)``), compared to its columns' and the twists' sizes."""
    worst: dict[tuple, int] = {}
    if not good.any():  # every position broken: no motion to check against
        return
    width = np.linalg.norm(sa[good], axis=1).max(axis=0, initial=0.0)  # (K,)
    for k, (place, frames) in analogs.items():
        t = _twist(place, frames, rows, ref_points)[good]
        t.reshape(len(t), -1, 6)[:, :, 3:] *= size
        power = np.einsum("prk,pr->pk", sa[good], t) / col_scale
        want = np.array([1.0 if c.owner == k and c.role == "drive" else 0.0
                         for c in columns])
        scale = width * np.linalg.norm(t, axis=1).max(initial=0.0) / col_scale
        bad = np.abs(power - want).max(axis=0, initial=0.0) > POWER_RTOL * np.maximum(
            np.maximum(scale, want), 1e-300)
        for c in np.flatnonzero(bad):
            col = columns[c]
            key = (col.owner, col.part if col.role != "drive" else "drive")
            worst[key] = k
    for (owner, part), k in worst.items():
        problems.append(_misfit(owner, part, k, columns))


def _misfit(owner, part: str, k: int, columns: list[Column]) -> Problem:
    """The problem of a joint (or drive) whose reaction would do work on the motion."""
    if part == "drive":
        col = next(c for c in columns if c.owner == owner and c.role == "drive")
        return Problem(("arguments", owner), (
            f"the balancing force of argument {owner}" if col.part == "force" else
            f"the balancing moment of argument {owner}") + " does not move with the "
            "argument (its power is not that of the argument's rate)",
            "drive a body that turns about the argument's axis (an elevation a: about "
            "(-sin b, 0, cos b); a rotation b: about Y), or the bodies at the two ends of a "
            "driven length")
    kind = next(c for c in columns if c.owner == owner).bodies
    first, second = kind
    path = ("joints", owner)
    if part == "force":
        return Problem((*path, "at"), f"the bodies {first} and {second} of joint {owner} "
                       f"move apart at its point (with argument {k}): its force would do "
                       "work", "place 'at' on the joint (the ball's centre, a point of the "
                       "axis) and check its type and axis")
    return Problem((*path, "type"), f"the bodies {first} and {second} of joint {owner} turn "
                   f"relative to each other about an axis its moment holds (with argument "
                   f"{k})", "give the axis they turn about (axis: K along vector K, or "
                   "[x, y, z]), or a type that lets them turn (spherical, cylindrical)")


def _scaled(a: Array, rhs: Array, columns: list[Column], size: float
            ) -> tuple[Array, Array, Array]:
    """The system with moment rows divided by ``size`` and moment unknowns multiplied by
    it; also the unknowns' scales."""
    rows = np.ones(a.shape[1])
    rows.reshape(-1, 6)[:, 3:] = 1.0 / size
    cols = np.array([size if c.part == "moment" else 1.0 for c in columns])
    return a * rows[:, None] * cols, rhs * rows, cols


def _singular_values(a: Array) -> Array:
    return np.concatenate([np.linalg.svd(a[i:i + CHUNK], compute_uv=False)
                           for i in range(0, a.shape[0], CHUNK)]
                          or [np.zeros((0, min(a.shape[1:])))])


def _unknowns(joints: list[Joint3], drives: list[Drive3], place: Placement3,
              frames: dict[int, Frame], ref_points: dict[int, PointOn]):
    """The bodies' rows, their reference points ``(3, P)``, the unknowns and their wrenches
    on the bodies ``(P, 6B, K)``."""
    rows = {b: i for i, b in enumerate(sorted(frames))}
    refs = {b: place.point(ref_points[b]).p for b in rows}
    columns = [c for j in joints for c in _joint_columns(j, place)]
    columns += [_drive_column(d, place) for d in drives]
    with np.errstate(invalid="ignore", divide="ignore"):
        a = _matrix(columns, rows, refs)
    return rows, refs, columns, a


def _checked(a: Array, rhs: Array, good: NDArray[np.bool_], columns: list[Column],
             place: Placement3, analogs: dict, rows: dict[int, int],
             ref_points: dict[int, PointOn]) -> tuple[Array, Array, Array, float]:
    """The scaled system (:func:`_scaled`, the mechanism's size ``L`` from the vectors'
    lengths at the ``good`` positions), after the check that every joint and drive fits the
    motion (:func:`_check_power`: a :class:`~mechloop.errors.ModelError` naming them)."""
    kin = place.results
    lengths = [np.abs(kin.value(f"r{v}"))[good] for v in kin.model.vectors]
    size = max((float(x.max()) for x in lengths if x.size), default=1.0) or 1.0
    sa, sb, col_scale = _scaled(np.where(good[:, None, None], a, 0.0),
                                np.where(good[:, None], rhs, 0.0), columns, size)
    problems: list[Problem] = []
    _check_power(sa, columns, col_scale, size, analogs, rows, ref_points, good, problems)
    if problems:
        raise ModelError(problems)
    return sa, sb, col_scale, size


def check_joints_fit(joints: list[Joint3], drives: list[Drive3], place: Placement3,
                     frames: dict[int, Frame], analogs: dict,
                     ref_points: dict[int, PointOn]) -> None:
    """Raise :class:`~mechloop.errors.ModelError` when a joint (or drive) does not fit the
    motion: its reaction would do work on a motion of some argument (see the module) —
    the check :func:`solve_reactions` makes first, without the loads (the structure of a
    spatial model, :mod:`mechloop.structure.spatial_joints`)."""
    _, _, columns, a = _unknowns(joints, drives, place, frames, ref_points)
    good = ~place.results.broken & np.isfinite(a).all(axis=(1, 2))
    rows = {b: i for i, b in enumerate(sorted(frames))}
    _checked(a, np.zeros(a.shape[:2]), good, columns, place, analogs, rows, ref_points)


def solve_reactions(joints: list[Joint3], drives: list[Drive3], place: Placement3,
                    frames: dict[int, Frame], terms, forces: list[Force3],
                    moments: list[Moment3], analogs: dict, ref_points: dict[int, PointOn],
                    *, static: bool) -> SpatialReactions:
    """The reactions of every joint and the balancing loads at every position (SI); see
    the module.  ``analogs``: per argument its analog placement and frames; ``terms``:
    the inertia terms of :mod:`mechloop.spatial.dynamics`.  Raises
    :class:`~mechloop.errors.ModelError` for joints that do not fit the motion, a
    statically indeterminate system and idle motions driven by the loads."""
    kin = place.results
    n = kin.broken.size
    rows, refs, columns, a = _unknowns(joints, drives, place, frames, ref_points)
    with np.errstate(invalid="ignore", divide="ignore"):
        rhs = newton_euler_rhs(terms, forces, moments, place, rows, refs, static=static)
    good = ~kin.broken & np.isfinite(a).all(axis=(1, 2)) & np.isfinite(rhs).all(axis=1)
    sa, sb, col_scale, size = _checked(a, rhs, good, columns, place, analogs, rows,
                                       ref_points)
    by_name = {j.name: j for j in joints}
    k_count, r_count = len(columns), sa.shape[1]
    s = _singular_values(sa[good])
    if not s.size:  # every position broken
        rank, generic = 0, 0
    else:
        ranks = (s > RANK_RTOL * s[:, :1]).sum(axis=1)
        rank = int(ranks.max())
        ratio = s[:, rank - 1] / np.maximum(s[:, 0], 1e-300) if rank else np.zeros(len(s))
        generic = int(np.flatnonzero(good)[np.argmax(ratio)])
    if s.size and rank < k_count:
        raise ModelError([indeterminate(sa[generic], columns, by_name, rank)])
    x = np.full((n, k_count), np.nan)
    residual = np.zeros(n)
    singular = np.zeros(n, bool)
    idle: tuple[str, ...] = ()
    if s.size:
        idx = np.flatnonzero(good)
        for lo in range(0, idx.size, CHUNK):
            part = idx[lo:lo + CHUNK]
            u, sv, vt = np.linalg.svd(sa[part], full_matrices=True)
            singular[part] = ~(sv[:, k_count - 1] >= SINGULAR_RTOL * sv[:, 0])
            inverse = np.where(singular[part, None], 0.0, 1.0 / np.where(
                sv[:, :k_count] > 0, sv[:, :k_count], 1.0))
            c = np.einsum("pri,pr->pi", u[:, :, :k_count], sb[part]) * inverse
            x[part] = np.einsum("pik,pi->pk", vt[:, :k_count], c)
            residual[part] = np.linalg.norm(
                np.einsum("prk,pk->pr", sa[part], x[part]) - sb[part], axis=1)
        solved = good & ~singular
        scale = (np.abs(sb[solved]).max(initial=0.0) + float(
            (s[solved[good], 0] * np.linalg.norm(x[solved], axis=1)).max(initial=0.0)))
        residual = residual / scale if scale > 0 else residual
        if rank < r_count:
            loads = -newton_euler_rhs((), forces, moments, place, rows, refs, static=True)
            loads.reshape(n, -1, 6)[:, :, 3:] /= size  # scaled as the system
            points = {j.name: place.point(j.at).p for j in joints}
            idle = idle_motions(sa, sb, loads, residual, solved, rank, rows, refs, joints,
                                points, generic, size)
        x[singular] = np.nan
    x = x * col_scale
    return _collect(joints, drives, columns, x, place, singular, idle, rank, k_count,
                    residual)


def _collect(joints, drives, columns, x, place, singular, idle, rank, k_count, residual
             ) -> SpatialReactions:
    n = x.shape[0]
    out = {}
    for j in joints:
        force, moment = np.zeros((3, n)), np.zeros((3, n))
        for c, col in enumerate(columns):
            if col.owner == j.name:
                if col.part == "force":
                    force += x[:, c] * col.force
                else:
                    moment += x[:, c] * col.moment
        out[j.name] = JointReaction(j, place.point(j.at).p, force, moment)
    balancing = {d.argument: x[:, len(columns) - len(drives) + i]
                 for i, d in enumerate(drives)}
    return SpatialReactions(out, balancing, singular, idle, rank, k_count, residual)

