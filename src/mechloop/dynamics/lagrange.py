"""Lagrange's equations of a machine with several inputs, from the kinematic analogs.

With ``q`` the inputs (``n`` arguments: rad, or m for a length), ``v'_S,i`` the velocity
of centre ``S`` and ``ω'_i`` the angular velocity of its body per unit rate of input
``i`` (the first-order analogs), every centre moves at ``v_S = Σ_i v'_S,i q̇_i`` and
accelerates at ``a_S = Σ_i v'_S,i q̈_i + c_S(q, q̇)``, ``c_S`` the acceleration it would
have with ``q̈ = 0`` (likewise ``ε = Σ ω'_i q̈_i + ε_c``).  The virtual power of the
inertia forces against the analogs of input ``i`` equals that of the loads:

    Σ_j M_ij(q) q̈_j + h_i(q, q̇) = Q_i(q, q̇, t)

* ``M_ij = Σ_bodies (m v'_S,i·v'_S,j + J_S ω'_i ω'_j)`` — the mass matrix (symmetric,
  positive definite while the chain is whole and every input moves some mass);
* ``h_i = Σ (m v'_S,i·c_S + J_S ω'_i ε_c)`` — the velocity terms (the Christoffel terms
  ``Σ_jk Γ_ijk q̇_j q̇_k`` of the textbook form, here from the acceleration analysis at
  ``q̈ = 0``, exact);
* ``Q_i = Σ F·v'_P,i + Σ M ω'_i`` — the generalized forces of the model's loads (gravity,
  forces and moments, springs, dampers, loads with ``when``, expressions of the state
  and time) by virtual power, at the state's true rates; the motors add their moments.

The kinetic energy is ``T = ½ q̇ᵀ M q̇`` and the loads' power ``P = Σ F·v_P + Σ M ω =
Q·q̇``; ``dT/dt = (Q + Q_motor)·q̇`` holds exactly for these equations, so a conservative
machine keeps ``T + V`` to the integrator's tolerance.  Everything is evaluated at the
current state by :class:`~mechloop.dynamics.state_kinematics.StateKinematics` (any
number of states in one call).  Units SI.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.loads import build_loads, follows_motion
from mechloop.dynamics.mechanism import Mechanism
from mechloop.dynamics.points import Placement
from mechloop.dynamics.state_kinematics import StateKinematics
from mechloop.model.schema import Model
from mechloop.solve.inputs import Signal
from mechloop.solve.results import Results

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Terms:
    """The equations at ``S`` states: ``mass`` ``(S, n, n)`` (kg·m², kg), ``bias``
    ``(S, n)`` (the velocity terms ``h``), ``force`` ``(S, n)`` (``Q`` of the loads, N·m
    or N), ``power`` ``(S,)`` (the loads' power, W), ``kinetic`` ``(S,)`` (J),
    ``broken`` ``(S,)``, ``margin`` ``(S,)`` and ``contour`` ``(S,)`` (the least existence
    margin and its contour, :class:`~mechloop.dynamics.state_kinematics.States`)."""

    mass: Array
    bias: Array
    force: Array
    power: Array
    kinetic: Array
    broken: NDArray[np.bool_]
    margin: Array
    contour: NDArray[np.int64]


class LagrangeMachine:
    """Lagrange's equations of ``model`` with inputs ``inputs`` (argument numbers) and the
    bodies, masses and drives of ``mechanism`` (:func:`mechloop.solve_dynamics`'s)."""

    def __init__(self, model: Model, mechanism: Mechanism, inputs: tuple[int, ...]):
        self.model, self.mechanism = _plain_gravity(model), mechanism
        self.inputs = tuple(inputs)
        self.n = len(self.inputs)
        self.kinematics = StateKinematics(model, self.inputs)
        #: whether a load reads the rates or the time (dampers, when:, expressions of
        #: rates or t): only then are the loads built on a second placement of the true
        #: state repeated over the analog columns
        self.reads_rates = bool(model.dampers) or any(
            load.when is not None or follows_motion(load.value)
            for load in (*model.forces, *model.moments))

    def terms(self, t: Array | float, q: Array, qdot: Array) -> Terms:
        """The terms at times ``t`` (s, ``(S,)`` or a float) and states ``q``, ``qdot``
        (``(n,)`` or ``(S, n)``)."""
        q = np.atleast_2d(np.asarray(q, dtype=float))
        n_states, n, width = q.shape[0], self.n, self.n + 1
        states = self.kinematics.at(q, qdot)
        res = states.results
        motion = Placement(res)
        first = np.arange(n_states) * width
        state = Placement(_columns(res, np.repeat(first, width))) if self.reads_rates \
            else motion
        with np.errstate(invalid="ignore", over="ignore"):
            mass = np.zeros((n_states, n, n))
            bias = np.zeros((n_states, n))
            kinetic = np.zeros(n_states)
            for part in self.mechanism.masses:
                v = motion.point(part.center)
                velocity = v.v.reshape(n_states, width)
                analog, c = velocity[:, 1:], v.a.reshape(n_states, width)[:, 0]
                angle = f"a{self.mechanism.bodies[part.body].angle_vector}"
                rate = res.rate(angle).reshape(n_states, width)
                omega, eps = rate[:, 1:], res.accel(angle).reshape(n_states, width)[:, 0]
                inertia = np.broadcast_to(part.inertia, (n_states * width,))[first]
                mass += part.mass * (np.conj(analog)[:, :, None] * analog[:, None, :]).real
                mass += inertia[:, None, None] * omega[:, :, None] * omega[:, None, :]
                bias += part.mass * (np.conj(analog) * c[:, None]).real
                bias += inertia[:, None] * omega * eps[:, None]
                kinetic += 0.5 * (part.mass * np.abs(velocity[:, 0]) ** 2
                                  + inertia * rate[:, 0] ** 2)
            clock = np.repeat(np.broadcast_to(np.asarray(t, dtype=float), (n_states,)),
                              width)
            time = Signal(clock, np.ones(clock.size), np.zeros(clock.size))
            loads = build_loads(self.model, self.mechanism, motion, time, state=state)
            virtual = np.zeros(n_states * width)
            for force in loads.forces:
                virtual += (np.conj(force.force) * force.point.v).real
            for couple in loads.moments:
                body = self.mechanism.bodies[couple.body]
                virtual += couple.moment * res.rate(f"a{body.angle_vector}")
        virtual = virtual.reshape(n_states, width)
        return Terms(mass, bias, virtual[:, 1:], virtual[:, 0], kinetic, states.broken,
                     states.margin, states.contour)


def _plain_gravity(model: Model) -> Model:
    """``model`` with its gravity's quantities as plain numbers in the model's units (the
    default direction is the text ``"-90 deg"``, which pint would parse at every
    evaluation of the equations)."""
    gravity = model.gravity
    if gravity is None or not any(isinstance(v, str) for v in (gravity.g, gravity.angle)):
        return model
    from mechloop.model.units import to_si, unit_factor

    units = model.units
    plain = {"g": to_si(gravity.g, "acceleration", units.acceleration)
             / unit_factor(units.acceleration, "acceleration"),
             "angle": to_si(gravity.angle, "angle", units.angle)
             / unit_factor(units.angle, "angle")}
    return model.model_copy(update={"gravity": gravity.model_copy(update=plain)})


def _columns(results: Results, index: NDArray[np.int64]) -> Results:
    """``results`` with its columns taken at ``index`` (the true state repeated over its
    analog columns: the state the loads read their rates from)."""
    from dataclasses import replace

    def take(table):
        return {k: np.asarray(v)[index] for k, v in table.items()}

    return replace(results, values=take(results.values), rates=take(results.rates),
                   accels=take(results.accels), broken=results.broken[index],
                   arguments={k: np.asarray(v)[index] for k, v in results.arguments.items()})
