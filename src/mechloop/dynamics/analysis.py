"""The basic dynamic model solved: kinematics, loads, reactions, reduced characteristics,
balancing loads (kinetostatics and virtual power), power and work.

:func:`solve_dynamics` is the entry point; :class:`DynamicResults` holds everything and
writes the table (``to_frame``) that ``mechloop solve`` prints for a model with bodies.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from mechloop.dynamics.cycle import Cycle, steady_cycles
from mechloop.dynamics.energy import Summary, summarize
from mechloop.dynamics.kinetostatics import (
    ForceAnalysis,
    FrictionError,
    body_motions,
    kinetostatics,
)
from mechloop.dynamics.loads import Loads, build_loads
from mechloop.dynamics.machine import MachineError
from mechloop.dynamics.mechanism import Mechanism, build_mechanism
from mechloop.dynamics.points import Motion, Placement
from mechloop.dynamics.reduced import Reduced, balancing_by_virtual_power, reduced
from mechloop.errors import ModelError, ModelSolveError, Problem, SolveError
from mechloop.model.schema import Model
from mechloop.solve.inputs import model_time
from mechloop.solve.kinematics import solve
from mechloop.solve.memory import require_memory
from mechloop.solve.results import Results

Array = NDArray[np.float64]


@dataclass(frozen=True)
class DynamicResults:
    """A solved dynamic model (SI, arrays shaped (P,)).

    ``forces``: reactions and balancing loads by kinetostatics; ``balancing_vp``: the
    balancing load of each drive by virtual power (friction power included for a
    one-input machine); ``reduced``: reduced characteristics to the input (one-input
    machines only, else None); ``centers``: every centre of mass, and ``center`` the
    common one; ``inertia``: for every body its inertia force ``−Σ m·a_S`` (N, complex)
    and inertia moment about its centre of mass ``−Σ (J·ε + (S_i − S)×m_i·a_Si)`` (N·m);
    ``summary``: power and work over the cycle; ``cycle``: the machine
    motion and flywheel when the model asks for them (``machine:``).  Without model time
    the analysis is static (no inertia loads).  Where the chain breaks in the cycle
    (:attr:`cycle_breaks` is not None) the summary's works, ψ and η are not the cycle's
    (the positions next to the breaks are left out): read them only when it is None.

    For a population of ``D`` designs (``analyze(..., designs=D)``,
    :mod:`mechloop.dynamics.population`) the arrays run over designs × positions
    ``(D·P,)``, design after design; ``summary`` and ``cycle`` hold one cycle per design
    (numbers ``(D,)``, arrays ``(D, P)``), and ``summary`` (with ``powers``) is left out
    (None, and no powers) when not asked for (``analyze(..., summary=False)``).
    """

    kinematics: Results
    placement: Placement
    mechanism: Mechanism
    loads: Loads
    forces: ForceAnalysis
    balancing_vp: dict[int, Array]
    reduced: Reduced | None
    centers: dict[int, Motion]
    center: Motion
    kinetic_energy: Array
    powers: dict[str, Array]
    summary: Summary | None
    static: bool
    inertia: dict[int, tuple[Array, Array]]
    cycle: Cycle | None = None

    @property
    def cycle_breaks(self):
        """Where the chain breaks in the cycle (at positions, or between two by the exact
        existence check): a :class:`~mechloop.dynamics.cycle_validity.CycleBreaks`, or
        None when the cycle figures are the cycle's."""
        from mechloop.dynamics.cycle_validity import cycle_breaks

        return cycle_breaks(self)

    def balancing_name(self, argument: int) -> tuple[str, str]:
        """Column stem and unit of the balancing load of ``argument``."""
        kind = self.kinematics.argument_kinds[argument]
        stem = "M_bal" if kind == "angle" else "F_bal"
        if len(self.mechanism.drives) > 1:
            stem += str(argument)
        return stem, "N*m" if kind == "angle" else "N"

    def to_frame(self) -> pd.DataFrame:
        """The kinematic table followed by the dynamic columns: balancing loads (and by
        virtual power, ``_vp``), reduced characteristics, centres of mass, and for every
        joint the reaction components and magnitude, and the angle of the reaction to
        each vector that ends at the joint; ``chain_break`` is also true where the force
        system is singular (its reactions are empty there)."""
        frame = self.kinematics.to_frame()
        cols: dict[str, Array] = {}
        for k, value in self.forces.balancing.items():
            stem, unit = self.balancing_name(k)
            cols[f"{stem} [{unit}]"] = value
            cols[f"{stem}_vp [{unit}]"] = self.balancing_vp[k]
        if self.reduced is not None:
            k = self.mechanism.drives[0].argument
            linear = self.kinematics.argument_kinds[k] == "length"
            cols["m_red [kg]" if linear else "J_red [kg*m^2]"] = self.reduced.inertia
            cols["dm_red [kg/m]" if linear else "dJ_red [kg*m^2/rad]"] = \
                self.reduced.d_inertia
            cols["F_red [N]" if linear else "M_red [N*m]"] = self.reduced.load
        for body, motion in sorted(self.centers.items()):
            cols[f"xS{body} [m]"] = motion.z.real
            cols[f"yS{body} [m]"] = motion.z.imag
        cols["xS [m]"] = self.center.z.real
        cols["yS [m]"] = self.center.z.imag
        for body, (force, moment) in sorted(self.inertia.items()):
            cols[f"Fi{body}_x [N]"] = force.real
            cols[f"Fi{body}_y [N]"] = force.imag
            cols[f"Mi{body} [N*m]"] = moment
        for name, reaction in self.forces.reactions.items():
            cols[f"R{name}_x [N]"] = reaction.force.real
            cols[f"R{name}_y [N]"] = reaction.force.imag
            cols[f"R{name} [N]"] = np.abs(reaction.force)
            if reaction.normal is not None:
                cols[f"R{name}_n [N]"] = reaction.normal
                cols[f"R{name}_m [N*m]"] = reaction.moment
            for v in _vectors_at(self, reaction.pair):
                angle = np.angle(reaction.force) - self.kinematics.value(f"a{v}")
                cols[f"R{name}_to_a{v} [deg]"] = np.degrees(np.angle(np.exp(1j * angle)))
        for name, mesh in self.forces.meshes.items():  # gear meshes (dynamics/meshes.py)
            cols[f"G{name}_x [N]"] = mesh.force.real
            cols[f"G{name}_y [N]"] = mesh.force.imag
            cols[f"G{name}_t [N]"] = mesh.tangential
            cols[f"G{name}_r [N]"] = mesh.radial
            cols[f"G{name}_n [N]"] = mesh.normal
        cols["friction_loss [W]"] = self.forces.friction_loss
        cols["T [J]"] = self.kinetic_energy
        if self.cycle is not None:
            linear = self.reduced is not None and self.kinematics.argument_kinds[
                self.mechanism.drives[0].argument] == "length"
            speed, accel = ("m/s", "m/s^2") if linear else ("rad/s", "rad/s^2")
            cols[f"omega [{speed}]"] = np.ravel(self.cycle.motion.omega)
            cols[f"epsilon [{accel}]"] = np.ravel(self.cycle.motion.epsilon)
            if self.cycle.with_flywheel is not None:
                cols[f"omega_fw [{speed}]"] = np.ravel(self.cycle.with_flywheel.omega)
                cols[f"epsilon_fw [{accel}]"] = np.ravel(self.cycle.with_flywheel.epsilon)
        extra = pd.DataFrame(cols)
        # a singular force system leaves the reactions empty: such a row is broken too
        broken = frame[["chain_break"]] | self.forces.singular[:, None]
        return pd.concat([frame.drop(columns="chain_break"), extra, broken], axis=1)


def _vectors_at(results: DynamicResults, pair) -> list[int]:
    """The body vectors (for the ground: the constant vectors of no body) that have an end
    at the pair's point (for reaction angles)."""
    kin, placement = results.kinematics, results.placement
    in_bodies = {u for f in results.mechanism.bodies.values() for u in f.vectors}
    ground = [v for v in kin.model.vectors if v not in in_bodies
              and f"r{v}" in kin.constant and f"a{v}" in kin.constant]
    z = results.forces.reactions[pair.name].point.z
    scale = max(float(np.nanmax(np.abs(z), initial=0.0)), 1.0)
    out: list[int] = []
    for b in pair.bodies:
        frame = results.mechanism.bodies.get(b)
        for v in frame.vectors if frame is not None else ground:
            if v not in out and (_same_point(placement.tail(v).z, z, scale)
                                 or _same_point(placement.head(v).z, z, scale)):
                out.append(v)
    return out


def _same_point(a, b, scale: float) -> bool:
    """Whether two points coincide at every position where both are known."""
    gap = np.abs(a - b)
    gap = gap[np.isfinite(gap)]
    return bool(gap.size) and float(gap.max()) <= 1e-9 * scale


def solve_dynamics(model: Model, *, friction: bool = True) -> DynamicResults:
    """Solve ``model`` with its bodies, joints and loads at every position (SI).

    Raises :class:`~mechloop.errors.ModelError` for an invalid model (naming every
    problem) and :class:`~mechloop.errors.SolveError` when the force analysis cannot be
    done (friction that does not settle).
    """
    require_memory(model, dynamics=True)  # the kinematics' needs included
    kin, placement, mechanism = compile_mechanism(model, memory_checked=True)
    return analyze(model, kin, mechanism,
                   lambda k: solve(model, analogs_of=k, memory_checked=True),
                   placement=placement, friction=friction)


def compile_mechanism(model: Model, *, memory_checked: bool = False
                      ) -> tuple[Results, Placement, Mechanism]:
    """The kinematics of ``model``, where its vectors lie, and its mechanism (bodies,
    masses, pairs, drives: :func:`~mechloop.dynamics.mechanism.build_mechanism`);
    ``memory_checked`` as for :func:`~mechloop.solve.kinematics.solve`."""
    if any(c.spatial for c in model.contours):  # issue 17: virtual power only
        raise SolveError("the force analysis with reactions, the machine motion and the "
                         "planar plots of the dynamics are not built for a model with "
                         "spatial contours yet",
                         "write its dynamics by virtual power with mechloop solve")
    kin = solve(model, memory_checked=memory_checked)
    placement = Placement(kin)
    return kin, placement, build_mechanism(model, placement)


def analyze(model: Model, kin: Results, mechanism: Mechanism,
            analogs: Callable[[int], Results], *, placement: Placement | None = None,
            starts: Mapping[int, NDArray[np.complex128]] | None = None,
            designs: int | None = None, friction: bool = True, flywheel: bool = True,
            summary: bool = True) -> DynamicResults:
    """The force analysis of solved kinematics: what :func:`solve_dynamics` returns.

    ``kin`` are the kinematics, ``analogs(k)`` the analogs with respect to argument ``k``
    (``solve(model, analogs_of=k)``), and ``placement`` (optional) ``Placement(kin)``.
    With ``designs=D`` the positions of ``kin`` and of the analogs are the designs ×
    positions ``(D·P,)`` of a population of ``model`` that share ``mechanism``
    (:mod:`mechloop.dynamics.population`): each contour in ``starts`` begins at each
    design's own point, friction iterates per design, and the summary and the machine's
    cycle are per design (arrays ``(D, ...)``); a design whose friction does not settle
    is marked in ``forces.unsettled`` and one whose cycle cannot be computed in
    ``cycle.computed`` instead of raising.  ``flywheel=False`` leaves out the flywheel of
    a machine (``delta``), which changes no other number; ``summary=False`` the powers
    and the summary (work over the cycle), which no column of the table needs.
    """
    time = model_time(model)
    static = time is None
    if placement is None:
        placement = Placement(kin, starts)
    n = kin.broken.size
    lead = () if designs is None else (designs,)

    def per_design(values: Array) -> Array:
        return np.reshape(values, (*lead, n // (designs or 1)))

    loads = build_loads(model, mechanism, placement, time, designs=designs or 1)
    segments = None if designs is None else np.repeat(np.arange(designs), n // designs)
    try:
        forces = kinetostatics(mechanism, placement, loads, friction=friction, static=static,
                               segments=segments)
    except FrictionError as exc:
        raise exc.at(_friction_path(model), "lower the coefficient of friction there "
                     "(friction.coefficient, or a joint's friction) or check the pin radii "
                     "and slider lengths") from None

    balancing_vp: dict[int, Array] = {}
    red: Reduced | None = None
    analog_cache: dict[int, tuple[Placement, Loads]] = {}
    for drive in mechanism.drives:
        at = Placement(analogs(drive.argument), starts)
        loads_at = build_loads(model, mechanism, at, time, designs=designs or 1,
                               state=placement)
        analog_cache[drive.argument] = (at, loads_at)
        balancing_vp[drive.argument] = balancing_by_virtual_power(
            mechanism, placement, at, loads_at, static=static)
    if len(mechanism.drives) == 1:
        k = mechanism.drives[0].argument
        at, loads_at = analog_cache[k]
        red = reduced(mechanism, at, loads_at)
        if friction:
            rate = _argument_rate(kin, k)
            with np.errstate(divide="ignore", invalid="ignore"):
                balancing_vp[k] = balancing_vp[k] + np.where(
                    rate != 0, forces.friction_loss / rate, 0.0)

    centers, center, inertia, kinetic = mass_terms(mechanism, placement, static)
    powers, work = {}, None
    if summary:
        powers = load_powers(kin, placement, mechanism, loads, forces)
        work = summarize({name: per_design(p) for name, p in powers.items()},
                         per_design(forces.friction_loss), per_design(cycle_clock(kin)),
                         mechanism.total_mass, per_design(kinetic))
    cycle = None
    if model.machine is not None:
        check_machine(mechanism, red, time)
        k = mechanism.drives[0].argument
        spec = model.machine if flywheel else model.machine.model_copy(update={"delta": None})
        state = None
        if designs is None and any(load.depends is not None for load in
                                   (*loads.forces, *loads.moments)):
            # loads that depend on the speed: machine: takes them at the cycle's speed
            from mechloop.dynamics.state_terms import StateTerms

            at, loads_at = analog_cache[k]
            state = StateTerms(np.asarray(kin.arguments[k], dtype=float), loads_at,
                               mechanism, at, periodic=True)
        try:
            if designs is None and kin.breaks_between:
                # every position assembles, but the machine cannot pass between two
                raise MachineError("machine motion needs the whole cycle, but the chain "
                                   f"breaks between positions: "
                                   f"{kin.breaks_between[0].describe()}",
                                   cause="cycle")
            cycle = steady_cycles(per_design(kin.arguments[k]), per_design(kin.time),
                                  Reduced(*(per_design(x) for x in (red.inertia,
                                                                    red.d_inertia,
                                                                    red.load))),
                                  per_design(forces.friction_loss),
                                  per_design(_argument_rate(kin, k)), spec,
                                  failures="raise" if designs is None else "nan",
                                  state=state or None)
        except SolveError as exc:
            raise _machine_error(exc, k) from None
    return DynamicResults(kin, placement, mechanism, loads, forces, balancing_vp, red,
                          centers, center, kinetic, powers, work, static, inertia, cycle)


def _friction_path(model: Model) -> tuple[str | int, ...]:
    """Where the friction of ``model`` is set: its first joint with a coefficient of its
    own, else the defaults."""
    for name, joint in (model.joints or {}).items():
        if joint.friction:
            return ("joints", name, "friction")
    return ("friction", "coefficient")


#: What to change in the model file when the machine motion cannot be found, by the
#: cause of :class:`~mechloop.dynamics.machine.MachineError`: (key, fix).
_MACHINE_FIXES = {
    "cycle": (
        "machine", "remove the chain break first (mechloop solve lists the positions): "
        "check the dimensions, the variant and the argument range"),
    "advance": (
        "arguments", "make the argument's table or law increase from position 0 to N"),
    "stops": (
        "time", "raise the speed (time: {rpm: ...}), lower the loads, or give the moving "
        "bodies more inertia (a flywheel mass on the input link)"),
    "inertia": (
        "bodies", "the machine has no moving mass at some positions (its reduced moment of "
        "inertia is zero there): give the moving bodies masses and moments of inertia "
        "(bodies: mass:, inertia:)"),
    "unsteady": (
        "machine", "check the loads over the cycle: positions 0..N must be one whole cycle "
        "of the input"),
    "settle": (
        "machine", "the dampers or one-way loads change too much with the speed over the "
        "cycle: raise the speed (time: {rpm: ...}), give a smaller delta (a larger "
        "flywheel), or simulate the machine in time (simulate:)"),
}


def _machine_error(exc: SolveError, argument: int) -> ModelSolveError:
    """``exc`` from the machine motion told at the key of the model to change."""
    if isinstance(exc, MachineError) and exc.cause in _MACHINE_FIXES:
        key, hint = _MACHINE_FIXES[exc.cause]
        path: tuple[str | int, ...] = ("arguments", argument) if key == "arguments" \
            else (key,)
        return exc.at(path, hint)
    return exc.at(("machine",), "check the loads, masses and speed of the machine "
                  "(forces, moments, bodies, time)")


def check_machine(mechanism: Mechanism, red: Reduced | None, time) -> None:
    """Raise :class:`~mechloop.errors.ModelError` unless a ``machine:`` model has what its
    cycle needs: one input (reduced characteristics ``red``) and a model time."""
    if red is None or time is None:
        raise ModelError([Problem(("machine",), "machine motion needs one input and a "
                                  f"model time (the model has {len(mechanism.drives)} "
                                  f"drive(s) and {'no' if time is None else 'a'} time)",
                                  "remove machine:, or drive the machine by one "
                                  "argument and give time: {rpm: ...}")])


def load_powers(kin: Results, placement: Placement, mechanism: Mechanism, loads: Loads,
                forces: ForceAnalysis) -> dict[str, Array]:
    """The power (W) of every external load and of each drive's balancing load, by name
    (forces of one name summed), arrays over positions: what :func:`summarize` takes."""
    motions = body_motions(mechanism, placement)
    powers: dict[str, Array] = {}
    for load in loads.forces:
        powers[load.name] = (np.conj(load.force) * load.point.v).real + powers.get(load.name, 0)
    for couple in loads.moments:
        powers[couple.name] = couple.moment * motions[couple.body].omega
    for drive in mechanism.drives:
        stem = "M_bal" if drive.kind == "angle" else "F_bal"
        if len(mechanism.drives) > 1:
            stem += str(drive.argument)
        powers[stem] = forces.balancing[drive.argument] * _argument_rate(kin, drive.argument)
    return powers


def cycle_clock(kin: Results) -> Array:
    """What work is integrated over: the model time (s), or argument 1 without time."""
    return kin.time if kin.time is not None else kin.arguments[min(kin.arguments)]


def mass_terms(mechanism: Mechanism, placement: Placement, static: bool
               ) -> tuple[dict[int, Motion], Motion, dict[int, tuple[Array, Array]], Array]:
    """Centres of mass of the bodies, the common centre, the inertia loads (force, moment
    per body; none when ``static``) and the kinetic energy (J), arrays over positions.
    Masses and inertias may be arrays over positions too (designs flattened into one
    axis, :mod:`mechloop.dynamics.population`)."""
    centers = {}
    total = mechanism.total_mass
    for body in sorted(mechanism.bodies):
        parts = [m for m in mechanism.masses if m.body == body and m.mass > 0]
        if not parts:
            continue
        mass = sum(m.mass for m in parts)
        points = [placement.point(m.center) for m in parts]
        centers[body] = Motion(*(sum(m.mass * getattr(p, f) for m, p in zip(parts, points,
                                                                              strict=True))
                                 / mass for f in ("z", "v", "a")))
    n = placement.results.broken.size
    motions = body_motions(mechanism, placement)
    inertia: dict[int, tuple[Array, Array]] = {}
    if not static:
        for body in sorted(mechanism.bodies):
            parts = [m for m in mechanism.masses if m.body == body]
            if not parts or (body not in centers
                             and all(np.all(np.asarray(m.inertia) == 0) for m in parts)):
                continue
            force = np.zeros(n, dtype=complex)
            moment = np.zeros(n)
            middle = centers[body].z if body in centers else None
            for m in parts:
                s = placement.point(m.center)
                force -= m.mass * s.a
                moment -= m.inertia * motions[body].epsilon
                if middle is not None:
                    moment -= m.mass * ((np.conj(s.z - middle) * s.a).imag)
            inertia[body] = (force, moment)
    zero = np.zeros(n, dtype=complex)
    if total > 0:
        center = Motion(*(sum(sum(m.mass for m in mechanism.masses if m.body == b)
                              * getattr(c, f) for b, c in centers.items()) / total
                          for f in ("z", "v", "a")))
    else:
        center = Motion(zero, zero, zero)
    kinetic = np.zeros(n)
    if not static:
        for m in mechanism.masses:
            s = placement.point(m.center)
            kinetic += 0.5 * (m.mass * np.abs(s.v) ** 2 + m.inertia * motions[m.body].omega ** 2)
    return centers, center, inertia, kinetic


def _argument_rate(results: Results, k: int) -> Array:
    """Rate of argument ``k`` (rad/s or m/s; per argument 1 without time)."""
    for number, vector in results.model.vectors.items():
        for letter in "ra":
            role = getattr(vector, letter)
            if getattr(role, "argument", None) == k:
                return results.rate(f"{letter}{number}")
    raise KeyError(k)
