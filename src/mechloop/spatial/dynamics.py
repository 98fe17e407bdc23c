"""Dynamics of a model with spatial contours by virtual power (issue 17).

With the bodies' masses and inertia tensors (:mod:`mechloop.spatial.bodies`), the loads
(:mod:`mechloop.spatial.loads`), the true motion (centre ``v_S``, ``a_S``; body ``ω``,
``ε``; tensor ``J_w`` in the model's axes) and the analogs of argument ``k`` (``v'_S``,
``v'_P``, ``ω'``: velocities per unit rate of the argument; ``v''_S``, ``ω''`` their
derivatives by it):

* the balancing load of argument ``k`` (N·m for an angle, N for a length)
  ``Q_k = Σ (m a_S·v'_S + (J_w ε + ω × J_w ω)·ω') − Σ F·v'_P − Σ M·ω'``;
* for one argument the reduced characteristics ``J_red = Σ (m |v'_S|² + ω'ᵀ J_w ω')``,
  ``dJ_red/dq = 2 Σ (m v'_S·v''_S + ω'ᵀ J_w ω'')`` (the tensor turns with the body:
  ``ω'ᵀ (dJ_w/dq) ω' = 0``) and the reduced moment ``M_red = Σ F·v'_P + Σ M·ω'``;
* the kinetic energy ``T = ½ Σ (m |v_S|² + ωᵀ J_w ω)``.

so that ``dT/dt = Σ F·v_P + Σ M·ω + Σ Q_k q̇_k``.  Without model time the analysis is
static (no inertia terms, ``T = 0``), as in the planar dynamics.

With ``joints:`` (:mod:`mechloop.spatial.joints`: spherical, revolute, cylindrical and
prismatic joints) the force analysis also solves the Newton–Euler equations of every
moving body for the joints' reactions and the balancing loads
(:mod:`mechloop.spatial.reactions`): it refuses joints that do not fit the motion and a
statically indeterminate system (naming the joints to change), drops the equations of an
idle motion that the loads and inertia leave balanced, and its balancing loads equal the
ones by virtual power.  Without ``joints:`` no reactions are computed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from mechloop.dynamics.mass_items import center_vector, mass_items
from mechloop.errors import ModelError, Problem
from mechloop.model.dynamic import HeadPoint, TailPoint, VectorPoint
from mechloop.model.schema import ArgumentRole, Model
from mechloop.model.units import UnitProblem, to_si
from mechloop.solve.inputs import model_time
from mechloop.spatial.bodies import (
    Frame,
    SpatialMass,
    body_frame,
    frame_vector,
    inertia_tensor,
    rod_symmetric,
    vectors_defined,
)
from mechloop.spatial.joints import COMPONENTS, body_reference, build_drives3, build_joints3
from mechloop.spatial.loads import Force3, Moment3, build_loads
from mechloop.spatial.points import Motion3, Placement3
from mechloop.spatial.reactions import SpatialReactions, solve_reactions

Array = NDArray[np.float64]


def _dot(a: Array, b: Array) -> Array:
    return np.einsum("ip,ip->p", a, b)


def _mv(j: Array, w: Array) -> Array:
    return np.einsum("ijp,jp->ip", j, w)


@dataclass(frozen=True)
class Mechanism3:
    """The bodies of a spatial model: per moving body its vectors and the vector that sets
    its frame's e3 (None: a one-axis body), and the lumped masses."""

    bodies: dict[int, tuple[list[int], int | None]]
    masses: tuple[SpatialMass, ...]

    def frames(self, results) -> dict[int, Frame]:
        """Every body's frame from ``results`` (time derivatives or analogs)."""
        return {b: body_frame(results, vectors, second=second)
                for b, (vectors, second) in self.bodies.items()}


def balancing_name(kin, argument: int, several: bool) -> tuple[str, str]:
    """Column stem and unit of the balancing load of ``argument`` (numbered when the
    model has ``several`` arguments), as in the planar table."""
    kind = kin.argument_kinds[argument]
    stem = "M_bal" if kind == "angle" else "F_bal"
    if several:
        stem += str(argument)
    return stem, "N*m" if kind == "angle" else "N"


@dataclass(frozen=True)
class SpatialDynamics:
    """A solved spatial dynamic model (SI, arrays ``(P,)`` or ``(3, P)``).

    ``kinematics``: the :class:`~mechloop.spatial.solve.SpatialResults`; ``frames``: every
    moving body's frame, ω and ε; ``centers``: each body's centre of mass; ``balancing``:
    the balancing load of every argument by virtual power (N·m or N); ``reduced``:
    ``(J_red, dJ_red/dq, M_red)`` for a one-argument model, else None;
    ``kinetic_energy`` (J); ``powers``: the power (W) of every load and balancing load by
    name (they sum to dT/dt); ``static``: no model time (no inertia terms)."""

    kinematics: object  # SpatialResults
    mechanism: Mechanism3
    frames: dict[int, Frame]
    centers: dict[int, Motion3]
    balancing: dict[int, Array]
    reduced: tuple[Array, Array, Array] | None
    kinetic_energy: Array
    powers: dict[str, Array]
    static: bool
    #: the common centre of mass (None without masses)
    center: Motion3 | None = None
    #: the joints' reactions and the balancing loads by the Newton–Euler equations (None
    #: without ``joints:``)
    reactions: SpatialReactions | None = None

    def balancing_name(self, argument: int) -> tuple[str, str]:
        """Column stem and unit of the balancing load of ``argument``."""
        return balancing_name(self.kinematics, argument, len(self.balancing) > 1)

    def to_frame(self) -> pd.DataFrame:
        """The kinematic table, then the balancing loads (by the reactions' equations
        when the model has joints, and by virtual power, ``_vp``), the reduced
        characteristics (one argument), each body's centre of mass, the common one, each
        body's angular velocity, the joints' reactions (force ``R<name>_x``, ``_y``,
        ``_z`` and its size ``R<name>``; the moment ``R<name>_mx``, ``_my``, ``_mz`` of a
        joint that has one: of the first body on the second, about the joint's point) and
        the kinetic energy; ``chain_break`` is also true where the force system is
        singular (its reactions are empty there)."""
        frame = self.kinematics.to_frame()
        flag = frame.pop("chain_break")
        cols: dict[str, Array] = {}
        for k, value in self.balancing.items():
            stem, unit = self.balancing_name(k)
            if self.reactions is not None:
                cols[f"{stem} [{unit}]"] = self.reactions.balancing[k]
            cols[f"{stem}_vp [{unit}]"] = value
        if self.reduced is not None:
            k = next(iter(self.balancing))
            linear = self.kinematics.argument_kinds[k] == "length"
            names = (("m_red [kg]", "dm_red [kg/m]", "F_red [N]") if linear else
                     ("J_red [kg*m^2]", "dJ_red [kg*m^2/rad]", "M_red [N*m]"))
            cols.update(zip(names, self.reduced, strict=True))
        d1 = self.kinematics.derivative_units()[0]
        for body, motion in sorted(self.centers.items()):
            for i, axis in enumerate("xyz"):
                cols[f"{axis}S{body} [m]"] = motion.p[i]
        if self.center is not None:
            for i, axis in enumerate("xyz"):
                cols[f"{axis}S [m]"] = self.center.p[i]
        for body, fr in sorted(self.frames.items()):
            for i, axis in enumerate("xyz"):
                cols[f"w{axis}{body} [rad/{d1}]"] = fr.omega[i]
        if self.reactions is not None:
            for name, reaction in self.reactions.joints.items():
                for i, axis in enumerate("xyz"):
                    cols[f"R{name}_{axis} [N]"] = reaction.force[i]
                cols[f"R{name} [N]"] = np.linalg.norm(reaction.force, axis=0)
                if COMPONENTS[reaction.joint.kind][1]:
                    for i, axis in enumerate("xyz"):
                        cols[f"R{name}_m{axis} [N*m]"] = reaction.moment[i]
            flag = flag | self.reactions.singular
        cols["T [J]"] = self.kinetic_energy
        return pd.concat([frame, pd.DataFrame(cols, index=frame.index), flag], axis=1)


def build_mechanism3(model: Model, results, problems: list[Problem]) -> Mechanism3:
    """Bodies and masses of ``model`` (SI) checked against its kinematics ``results``."""
    units = model.units
    bodies: dict[int, tuple[list[int], int | None]] = {}
    masses: list[SpatialMass] = []
    for number, body in model.bodies.items():
        if number == 0:
            continue
        if not vectors_defined(model, number, body, problems):
            continue
        second = frame_vector(results, number, body.vectors, problems)
        bodies[number] = (body.vectors, second)
        for item in mass_items(number, body):
            where, mass, inertia, center = item
            try:
                m = to_si(mass, "mass", units.mass)
            except UnitProblem as exc:
                problems.append(Problem((*where, "mass"), exc.message, exc.hint))
                continue
            if m < 0:
                problems.append(Problem((*where, "mass"), "a mass cannot be negative",
                                        "give a mass ≥ 0"))
                continue
            v = center_vector(number, body, item, m, problems)
            if v is None:
                continue
            if isinstance(center, VectorPoint) and center.across != 0:
                problems.append(Problem((*where, "center", "across"), "'across' has no side "
                                        "in a model with spatial contours",
                                        "place the centre on the vector (share or along)"))
                continue
            sliding = f"r{v}" not in results.constant
            held = body.ends.get(v, "tail")
            if sliding and not (isinstance(center, HeadPoint) if held == "head" else
                                isinstance(center, TailPoint) or (
                                    isinstance(center, VectorPoint) and not center.share)):
                problems.append(Problem((*where, "center"), f"vector {v} changes length, so "
                                        "this point is not fixed in the body",
                                        f"put the centre at the {held} of vector {v}, or "
                                        "on a vector of constant length"))
                continue
            length = None if sliding else abs(float(results.value(f"r{v}")[0]))
            tensor = inertia_tensor(inertia, m, units, length, v == body.vectors[0],
                                    (*where, "inertia"), problems)
            if tensor is None:
                continue
            if second is None and not rod_symmetric(tensor):
                problems.append(Problem((*where, "inertia"), f"the vectors of body {number} "
                                        "are parallel, so its spin about them is not known: "
                                        "its tensor must be symmetric about them",
                                        "give inertia: [J_axis, J, J] (J_axis about the "
                                        "vectors' line)"))
                continue
            masses.append(SpatialMass(number, m, tensor, center))
    return Mechanism3(bodies, tuple(masses))


def argument_rate(results, k: int) -> Array:
    """The rate of argument ``k`` (rad/s or m/s, or 1 per argument 1 without time)."""
    for number, vector in results.model.vectors.items():
        for letter in "rab":
            role = getattr(vector, letter)
            if isinstance(role, ArgumentRole) and role.argument == k:
                return results.rate(f"{letter}{number}")
    raise KeyError(k)


def _inertia_terms(mech: Mechanism3, place: Placement3, frames: dict[int, Frame]):
    """Per mass: its centre's motion, body frame and tensor in the model's axes."""
    for mass in mech.masses:
        frame = frames[mass.body]
        yield mass, place.point(mass.center), frame, mass.world(frame)


def solve_spatial_dynamics(model: Model) -> SpatialDynamics:
    """Solve a model with spatial contours and ``bodies:`` at every position (SI);
    :class:`~mechloop.errors.ModelError` names every problem of its bodies and loads."""
    from mechloop.solve.kinematics import solve

    time = model_time(model)
    static = time is None
    kin = solve(model)
    problems: list[Problem] = []
    mech = build_mechanism3(model, kin, problems)
    forces, moments = build_loads(model, kin, mech.masses, set(mech.bodies), time, problems)
    if model.joints is not None:
        joints = build_joints3(model, set(mech.bodies), problems)
        drives = build_drives3(model, {b: v for b, (v, _) in mech.bodies.items()}, joints,
                               problems)
    if not mech.bodies and not problems:
        problems.append(Problem(("bodies",), "the model has no moving body",
                                "list the moving bodies with their vectors"))
    if problems:
        raise ModelError(problems)
    place = Placement3(kin)
    frames = mech.frames(kin)
    terms = list(_inertia_terms(mech, place, frames))
    n = kin.broken.size

    balancing: dict[int, Array] = {}
    reduced = None
    analogs: dict[int, tuple[Placement3, dict[int, Frame]]] = {}
    with np.errstate(invalid="ignore"):
        for k in sorted(model.arguments):
            ana = solve(model, analogs_of=k)
            at = Placement3(ana)
            frames_a = mech.frames(ana)
            analogs[k] = (at, frames_a)
            total = np.zeros(n)
            inertia, d_inertia = np.zeros(n), np.zeros(n)
            for (mass, s, frame, jw), (_, s_a, frame_a, _) in zip(
                    terms, _inertia_terms(mech, at, frames_a), strict=True):
                w_a = frame_a.omega
                if not static:
                    total += mass.mass * _dot(s.a, s_a.v) + _dot(
                        _mv(jw, frame.epsilon) + np.cross(frame.omega, _mv(jw, frame.omega),
                                                          axis=0), w_a)
                inertia += mass.mass * _dot(s_a.v, s_a.v) + _dot(w_a, _mv(jw, w_a))
                d_inertia += 2.0 * (mass.mass * _dot(s_a.v, s_a.a)
                                    + _dot(w_a, _mv(jw, frame_a.epsilon)))
            load = _load_power(forces, moments, at, frames_a, n)
            balancing[k] = total - load
            if len(model.arguments) == 1:
                reduced = (inertia, d_inertia, load)
        kinetic = np.zeros(n)
        if not static:
            for mass, s, frame, jw in terms:
                kinetic += 0.5 * (mass.mass * _dot(s.v, s.v)
                                  + _dot(frame.omega, _mv(jw, frame.omega)))
        powers = {}
        for f in forces:
            powers[f.name] = powers.get(f.name, 0.0) + _dot(f.force, place.point(f.at).v)
        for m in moments:
            powers[m.name] = powers.get(m.name, 0.0) + _dot(m.moment, frames[m.body].omega)
        for k, q in balancing.items():
            stem = balancing_name(kin, k, len(balancing) > 1)[0]
            powers[stem] = q * argument_rate(kin, k)
    centers = _centers(mech, place)
    moving = [m for m in mech.masses if m.mass > 0]
    center = _center_of(moving, place) if moving else None
    reactions = None
    if model.joints is not None:
        refs = {b: body_reference(model, kin, b, vectors)
                for b, (vectors, _) in mech.bodies.items()}
        reactions = solve_reactions(joints, drives, place, frames, terms, forces, moments,
                                    analogs, refs, static=static)
    return SpatialDynamics(kin, mech, frames, centers, balancing, reduced, kinetic, powers,
                           static, center, reactions)


def _load_power(forces: list[Force3], moments: list[Moment3], place: Placement3,
                frames: dict[int, Frame], n: int) -> Array:
    """``Σ F·v_P + Σ M·ω`` with the points and frames of ``place``/``frames``."""
    out = np.zeros(n)
    for f in forces:
        out += _dot(f.force, place.point(f.at).v)
    for m in moments:
        out += _dot(m.moment, frames[m.body].omega)
    return out


def _center_of(parts: list[SpatialMass], place: Placement3) -> Motion3:
    """The centre of mass of ``parts`` (masses > 0)."""
    total = sum(m.mass for m in parts)
    points = [place.point(m.center).scaled(m.mass / total) for m in parts]
    return sum(points[1:], points[0])


def _centers(mech: Mechanism3, place: Placement3) -> dict[int, Motion3]:
    """The centre of mass of every body with a mass."""
    out = {}
    for body in sorted(mech.bodies):
        parts = [m for m in mech.masses if m.body == body and m.mass > 0]
        if parts:
            out[body] = _center_of(parts, place)
    return out
