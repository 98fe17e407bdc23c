"""Motion in time of a machine with several inputs: Lagrange's equations integrated.

The inputs ``q`` (the model's drives, angle arguments, rad) move by

    M(q)·q̈ + h(q, q̇) = Q(q, q̇, t) + Q_motor(q̇, t)

(:mod:`mechloop.dynamics.lagrange`), each motor's moment acting on its own input (a
rotor's inertia ``ratio²·J_rotor`` adds to ``M_kk``).  The kinematics is solved exactly at
every evaluation of the right-hand side (one vectorized solve of the state and the
analogs of each input, :mod:`mechloop.dynamics.state_kinematics`), so nothing is read
between positions: the model's positions only give the default start (position 0).

:func:`scipy.integrate.solve_ivp` integrates the state ``(q, q̇, W_motor, W_loads)`` with
dense output, in pieces split at each motor's switch-off.  Events end the run:

* ``"chain break ahead"`` (``detail`` names the contour) — the chain is about to break:
  the least existence margin of the contours at the state (``sin²`` of the angle
  between a contour's Jacobian columns, ...; see
  :mod:`mechloop.dynamics.state_kinematics`) falls to :data:`NEAR_BREAK` — within about
  1e-3 rad of a dead point or of where the contour stops closing.  Closer in, the
  velocity terms grow like ``1/sin³`` and no step size follows them to the break itself
  (a trial step beyond it, where the chain does not assemble, is rejected); the run ends
  at an assembled state, never at a NaN;
* ``"angle"`` — an input reaches its ``stop_at``;
* ``"stopped"`` — every input turns slower than ``rest`` (rad/s);
* ``"duration"``.

Units SI (rad, rad/s, rad/s², s, N·m, J).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp

from mechloop.dynamics.lagrange import LagrangeMachine, Terms
from mechloop.dynamics.motors import RPM, MotorCurve, motor_curve
from mechloop.errors import ModelError, Problem, SolveError
from mechloop.model.units import UnitProblem, to_si

if TYPE_CHECKING:
    from mechloop.dynamics.analysis import DynamicResults
    from mechloop.model.schema import Model
    from mechloop.model.simulate import Simulate

Array = NDArray[np.float64]

#: The existence margin (``sin²`` of a contour's Jacobian angle) at which the run ends
#: before a break or a dead point: ``sin = 1e-3``.
NEAR_BREAK = 1e-6


@dataclass(frozen=True)
class InputsEvent:
    """Something that happened: ``kind`` one of ``"start"``, ``"motor off"`` (``detail``
    names the input), ``"chain break ahead"`` (``detail`` names the contour), ``"angle"``
    (``detail`` names the input), ``"stopped"``, ``"duration"``; at time ``t`` (s), the
    inputs' angles ``q`` (rad) and speeds ``omega`` (rad/s), shape (n,)."""

    kind: str
    t: float
    q: Array
    omega: Array
    detail: str = ""


@dataclass(frozen=True)
class InputsSettings:
    """How to integrate (SI): ``duration`` (s); ``stop_at``: per input (index into the
    inputs) an angle (rad) that ends the run when reached; ``rest``: end once every
    speed is below it (rad/s; None: never); ``rtol``, ``atol`` (rad and rad/s),
    ``method`` of :func:`scipy.integrate.solve_ivp`; ``every``: output step (s; None:
    1/1000 of the simulated time); ``near_break``: the margin that ends the run before
    a break (:data:`NEAR_BREAK`)."""

    duration: float
    stop_at: dict[int, float] = field(default_factory=dict)
    rest: float | None = None
    rtol: float = 1e-8
    atol: float = 1e-9
    method: str = "DOP853"
    every: float | None = None
    near_break: float = NEAR_BREAK


@dataclass(frozen=True)
class InputsSimulation:
    """The motion in time of a machine with several inputs.

    Attributes
    ----------
    inputs : tuple of int — the inputs' argument numbers, in the order of the rows below.
    time : array, shape (R,), s.
    q, omega, epsilon : array, shape (n, R) — every input's angle (rad), speed (rad/s),
        acceleration (rad/s²).
    motor_moment : array, shape (n, R), N·m — each input's motor moment (0: none, off).
    kinetic_energy, motor_work, load_work : array, shape (R,), J — ``½ q̇ᵀ M q̇`` (rotors
        included), the motors' work and the loads' work since time 0.
    balance : array, shape (R,), J — ``T − T(0) − W_motor − W_loads``: zero but for the
        integrator's error.
    events : list of :class:`InputsEvent` — the first ``"start"``, the last what ended
        the run.
    machine : :class:`~mechloop.dynamics.lagrange.LagrangeMachine`; ``motors``: per input
        index its :class:`MotorCurve`; ``settings``; ``segments``: the pieces of the run
        ``(t0, t1, dense output)``; ``steps``: the integrator's steps; ``evaluations``:
        its right-hand side evaluations (each a kinematic solve).
    """

    inputs: tuple[int, ...]
    time: Array
    q: Array
    omega: Array
    epsilon: Array
    motor_moment: Array
    kinetic_energy: Array
    motor_work: Array
    load_work: Array
    balance: Array
    events: list[InputsEvent]
    machine: LagrangeMachine
    motors: dict[int, MotorCurve]
    settings: InputsSettings
    segments: list[tuple[float, float, Callable[[Array], Array]]] = field(repr=False,
                                                                          default_factory=list)
    steps: int = 0
    evaluations: int = 0

    @property
    def end(self) -> InputsEvent:
        """What ended the run."""
        return self.events[-1]

    def state(self, t: ArrayLike) -> tuple[Array, Array]:
        """``(q, ω)`` at times ``t`` (s, within the run), each shape (n, m), from the dense
        output."""
        y = _dense(self.segments, np.atleast_1d(np.asarray(t, dtype=float)))
        n = len(self.inputs)
        return y[:n], y[n:2 * n]

    def to_frame(self) -> pd.DataFrame:
        """The output rows as a table (SI; angles in degrees, speeds also in rpm), columns
        per input ``k`` suffixed by its argument number."""
        columns: dict[str, Array] = {"time [s]": self.time}
        for i, k in enumerate(self.inputs):
            columns |= {f"q{k} [deg]": np.degrees(self.q[i]),
                        f"omega{k} [rad/s]": self.omega[i], f"n{k} [rpm]": self.omega[i] / RPM,
                        f"epsilon{k} [rad/s^2]": self.epsilon[i],
                        f"M_motor{k} [N*m]": self.motor_moment[i]}
        columns |= {"T [J]": self.kinetic_energy, "W_motor [J]": self.motor_work,
                    "W_loads [J]": self.load_work, "balance [J]": self.balance}
        return pd.DataFrame(columns)


class _Cached:
    """The machine's terms at the last few states (the integrator's events and its next
    step ask for the state it has just evaluated)."""

    def __init__(self, machine: LagrangeMachine):
        self.machine, self.calls, self._memo = machine, 0, {}

    def __call__(self, t: float, q: Array, w: Array) -> Terms:
        key = (t, q.tobytes(), w.tobytes())
        found = self._memo.get(key)
        if found is None:
            self.calls += 1
            found = self.machine.terms(t, q, w)
            if len(self._memo) >= 8:
                self._memo.pop(next(iter(self._memo)))
            self._memo[key] = found
        return found


def _accelerations(terms: Terms, rotors: Array, drive: Array) -> Array:
    """``q̈`` ``(S, n)`` from the terms of ``S`` states and the motors' moments ``drive``
    ``(S, n)``."""
    mass = terms.mass + np.eye(rotors.size) * rotors
    return np.linalg.solve(mass, (terms.force + drive - terms.bias)[..., None])[..., 0]


def integrate_inputs(machine: LagrangeMachine, motors: dict[int, MotorCurve], q0: Array,
                     omega0: Array, settings: InputsSettings, *,
                     progress: Callable[[float, float], None] | None = None
                     ) -> InputsSimulation:
    """Integrate Lagrange's equations from ``(q0, omega0)`` (rad, rad/s, shape (n,)).

    Raises :class:`SolveError` when the start state does not assemble (or is at a dead
    point), its mass matrix is not positive definite, or the integrator fails.
    """
    n = machine.n
    q0, omega0 = np.asarray(q0, dtype=float), np.asarray(omega0, dtype=float)
    rotors = np.array([motors[i].inertia if i in motors else 0.0 for i in range(n)])
    machine.kinematics.orient(machine.kinematics.at(q0, omega0))  # the margins' signs
    start = machine.kinematics.at(q0, omega0)  # on the start's branch
    if start.broken[0] or not start.margin[0] > settings.near_break:
        raise SolveError(f"the chain does not assemble at the start (contour "
                         f"{int(start.contour[0])} breaks or is at a dead point)",
                         "start the inputs where the mechanism assembles")
    cached = _Cached(machine)
    first = cached(0.0, q0, omega0)
    mass0 = first.mass[0] + np.diag(rotors)
    if not np.all(np.linalg.eigvalsh(mass0) > 1e-12 * max(np.abs(mass0).max(), 1e-300)):
        raise SolveError("the mass matrix at the start is not positive definite: some "
                         "input moves no mass", "give the bodies each input moves a mass "
                         "or a moment of inertia")
    scale = max(float(np.abs(mass0).max()), 1.0)
    atol = np.concatenate([np.full(2 * n, settings.atol),
                           np.full(2, settings.atol * scale)])

    def drive_at(t: float, w: Array, running: dict[int, bool]) -> Array:
        return np.array([float(motors[i].torque(np.asarray(w[i])))
                         if i in motors and running[i] else 0.0 for i in range(n)])

    offs = sorted({m.off_at for m in motors.values() if 0 < m.off_at < settings.duration})
    stops = [*offs, settings.duration]
    events = [InputsEvent("start", 0.0, q0.copy(), omega0.copy())]
    segments: list[tuple[float, float, Callable[[Array], Array]]] = []
    t, y = 0.0, np.concatenate([q0, omega0, [0.0, 0.0]])
    steps = 0
    for stop in stops:
        running = {i: t < m.off_at for i, m in motors.items()}

        def rhs(time: float, s: Array, running=running) -> Array:
            q, w = s[:n], s[n:2 * n]
            terms = cached(time, q, w)
            if terms.broken[0]:  # a trial stage beyond a break: the step is rejected
                return np.full(s.size, np.nan)
            drive = drive_at(time, w, running)
            acc = _accelerations(terms, rotors, drive[None, :])[0]
            return np.concatenate([w, acc, [float(drive @ w), float(terms.power[0])]])

        def broken_ahead(time: float, s: Array) -> float:
            return float(cached(time, s[:n], s[n:2 * n]).margin[0]) - settings.near_break

        checks: dict[str, Callable[[float, Array], float]] = {
            "chain break ahead": broken_ahead}
        broken_ahead.terminal, broken_ahead.direction = True, -1.0  # type: ignore[attr-defined]
        for i, target in settings.stop_at.items():
            checks[f"angle {i}"] = _crossing(i, target, 1.0 if target > q0[i] else -1.0)
        if settings.rest is not None:
            checks["stopped"] = _slower(n, settings.rest)
        sol = solve_ivp(rhs, (t, stop), y, method=settings.method, rtol=settings.rtol,
                        atol=atol, dense_output=True, events=list(checks.values()))
        if sol.status == -1:
            raise SolveError(f"the integrator failed at t = {sol.t[-1]:.6g} s: "
                             f"{sol.message}", "loosen rtol/atol or try method: Radau")
        steps += sol.t.size - 1
        segments.append((t, float(sol.t[-1]), sol.sol))
        t, y = float(sol.t[-1]), sol.y[:, -1].copy()
        if progress is not None:
            progress(t, settings.duration)
        hits = sorted((float(te[0]), order, kind) for order, (kind, te) in
                      enumerate(zip(checks, sol.t_events, strict=True)) if te.size)
        if hits:
            kind = hits[0][2]
            if kind == "chain break ahead":
                contour = int(cached(t, y[:n], y[n:2 * n]).contour[0])
                events.append(InputsEvent(kind, t, y[:n], y[n:2 * n],
                                          f"contour {contour}"))
            elif kind.startswith("angle"):
                i = int(kind.split()[1])
                y[i] = settings.stop_at[i]
                events.append(InputsEvent("angle", t, y[:n], y[n:2 * n],
                                          f"input {machine.inputs[i]}"))
            else:
                events.append(InputsEvent(kind, t, y[:n], y[n:2 * n]))
            break
        if stop >= settings.duration:
            events.append(InputsEvent("duration", t, y[:n], y[n:2 * n]))
            break
        for i, m in motors.items():
            if m.off_at == stop:
                events.append(InputsEvent("motor off", t, y[:n], y[n:2 * n],
                                          f"input {machine.inputs[i]}"))
    return _assemble(machine, motors, settings, events, segments, rotors, steps,
                     cached.calls)


def _crossing(index: int, value: float, direction: float) -> Callable[[float, Array], float]:
    def event(t: float, y: Array) -> float:
        return y[index] - value

    event.terminal, event.direction = True, direction  # type: ignore[attr-defined]
    return event


def _slower(n: int, rest: float) -> Callable[[float, Array], float]:
    def event(t: float, y: Array) -> float:
        return float(np.abs(y[n:2 * n]).max()) - rest

    event.terminal, event.direction = True, -1.0  # type: ignore[attr-defined]
    return event


def _dense(segments, t: Array) -> Array:
    """The state ``(2n + 2, m)`` at times ``t`` from the segments' dense output."""
    ends = np.array([s[1] for s in segments])
    which = np.minimum(np.searchsorted(ends, t, side="left"), len(segments) - 1)
    out = None
    for i in np.unique(which):
        sel = which == i
        part = segments[i][2](t[sel])
        if out is None:
            out = np.empty((part.shape[0], t.size))
        out[:, sel] = part
    return out


def _assemble(machine: LagrangeMachine, motors: dict[int, MotorCurve],
              settings: InputsSettings, events: list[InputsEvent], segments, rotors: Array,
              steps: int, evaluations: int) -> InputsSimulation:
    """The output rows of a finished run: every row's terms in one vectorized solve."""
    n = machine.n
    t_final = events[-1].t
    step = t_final / 1000.0 if settings.every is None else float(settings.every)
    t = np.append(np.arange(0.0, t_final, step), t_final) if step > 0 and t_final > 0 \
        else np.zeros(1)
    y = _dense(segments, t)
    y[:, -1] = np.concatenate([events[-1].q, events[-1].omega, y[2 * n:, -1]])
    q, w = y[:n], y[n:2 * n]
    terms = machine.terms(t, q.T, w.T)
    drive = np.zeros((n, t.size))
    for i, m in motors.items():
        drive[i] = m.at(w[i], t)
    eps = _accelerations(terms, rotors, drive.T).T
    kinetic = terms.kinetic + 0.5 * (rotors[:, None] * w * w).sum(axis=0)
    balance = kinetic - kinetic[0] - y[2 * n] - y[2 * n + 1]
    return InputsSimulation(machine.inputs, t, q, w, eps, drive, kinetic, y[2 * n],
                            y[2 * n + 1], balance, events, machine, motors, settings,
                            segments, steps, evaluations)


def simulate_inputs(model: Model, settings: Simulate, dynamics: DynamicResults, *,
                    progress: Callable[[float, float], None] | None = None
                    ) -> InputsSimulation:
    """The motion in time of ``model`` with several inputs under ``settings`` (its
    ``simulate:`` section), the mechanism from ``dynamics``.

    Raises :class:`~mechloop.errors.ModelError` located at the key to change: an input
    that is not an angle, a setting of one input (``motor``, ``cycles``,
    ``until_steady``, ``reverse``, ``flywheel``, ``every: cycle``), a motor or start for
    an argument that is not an input, a load given over the positions (it has no value
    at a state that is not a position), joint friction (not modelled here), or a model
    the state solve cannot take.
    """
    mech = dynamics.mechanism
    inputs = tuple(d.argument for d in mech.drives)
    problems = _refusals(model, settings, dynamics, inputs)
    if problems:
        raise ModelError(problems)
    units = model.units
    motors = {}
    for k, motor in (settings.motors or {}).items():
        motors[inputs.index(k)] = motor_curve(motor, units, ("simulate", "motors", k))
    starts = settings.start if isinstance(settings.start, dict) else {}
    q0 = np.array([float(dynamics.kinematics.arguments[k][0]) for k in inputs])
    w0 = np.zeros(len(inputs))
    for k, start in starts.items():
        i = inputs.index(k)
        if start.angle is not None:
            q0[i] = _si(start.angle, "angle", units.angle, ("simulate", "start", k, "angle"))
        w0[i] = start.rpm * RPM
    stop_at = {}
    if isinstance(settings.stop_at, dict):
        for k, value in settings.stop_at.items():
            i = inputs.index(k)
            stop_at[i] = _si(value, "angle", units.angle, ("simulate", "stop_at", k))
            if stop_at[i] == q0[i]:
                raise ModelError([Problem(("simulate", "stop_at", k), "stop_at is the "
                                          "start angle itself", "give an angle the input "
                                          "moves to")])
    run = InputsSettings(duration=float(settings.duration), stop_at=stop_at,
                         rest=None if settings.rest_rpm is None else settings.rest_rpm * RPM,
                         rtol=settings.rtol, atol=settings.atol, method=settings.method,
                         every=settings.every)
    try:
        machine = LagrangeMachine(model, mech, inputs)
        return integrate_inputs(machine, motors, q0, w0, run, progress=progress)
    except SolveError as exc:
        raise exc.at(("simulate",)) from None


def _refusals(model: Model, settings: Simulate, dynamics: DynamicResults,
              inputs: tuple[int, ...]) -> list[Problem]:
    """Everything that keeps ``settings`` from running on ``model`` with ``inputs``."""
    from mechloop.model.dynamic import ExpressionValue, ParameterValue

    problems = []
    kinds = dynamics.kinematics.argument_kinds
    for k in inputs:
        if kinds[k] != "angle":
            problems.append(Problem(("arguments", k), f"input {k} is a length: the motion "
                                    "of several inputs takes inputs that turn",
                                    "drive every input by an angle argument"))
    one = {"motor": settings.motor is not None, "cycles": settings.cycles is not None,
           "until_steady": settings.until_steady, "reverse": settings.reverse,
           "flywheel": settings.flywheel is not None, "every": settings.every == "cycle"}
    for key, given in one.items():
        if given:
            problems.append(Problem(("simulate", key), f"{key} applies to a machine with "
                                    f"one input; this one has {len(inputs)} "
                                    f"({', '.join(map(str, inputs))})",
                                    "use motors: {k: ...}, duration and stop_at per input"
                                    if key != "motor" else "give motors: {argument: "
                                    "{...}} with one motor per input"))
    if settings.duration is None:
        problems.append(Problem(("simulate", "duration"), "the run of several inputs needs "
                                "a duration", "give duration: seconds"))
    for key, given in (("motors", settings.motors), ("stop_at", settings.stop_at),
                       ("start", settings.start)):
        if isinstance(given, dict):
            problems += [Problem(("simulate", key, k), f"argument {k} is not an input",
                                 f"use one of {list(inputs)}") for k in given
                         if k not in inputs]
        elif given is not None and key != "start":
            problems.append(Problem(("simulate", key), f"{key} of several inputs is "
                                    "given per input", f"write {key}: {{{inputs[0]}: ...}}"))
        elif key == "start" and given.model_fields_set:
            problems.append(Problem(("simulate", "start"), "the start of several inputs "
                                    "is given per input", f"write start: {{{inputs[0]}: "
                                    "{angle: ..., rpm: ...}}"))
    for kind, loads in (("forces", model.forces), ("moments", model.moments)):
        for i, load in enumerate(loads):
            if not isinstance(load.value, int | float | str | ParameterValue |
                              ExpressionValue):
                problems.append(Problem((kind, i, "value"), "a load over the positions has "
                                        "no value at the states of several inputs",
                                        "give it as a constant, a table over a parameter "
                                        "(of: ...) or an expression of the state"))
    if settings.friction and any(p.friction for p in dynamics.mechanism.pairs):
        problems.append(Problem(("simulate", "friction"), "joint friction is not part of "
                                "the motion of several inputs (it needs the reactions at "
                                "every state)", "set friction: false to run without it"))
    return problems


def one_input(settings: Simulate, argument: int) -> Simulate:
    """``settings`` of a one-input machine with the per-input forms (``motors``,
    ``start``, ``stop_at`` keyed by the input's ``argument``) read as the plain ones.
    Raises :class:`ModelError` for a key that is not the input."""
    problems, update = [], {}
    for key, single in (("motors", "motor"), ("start", "start"), ("stop_at", "stop_at")):
        given = getattr(settings, key)
        if isinstance(given, dict):
            wrong = [k for k in given if k != argument]
            problems += [Problem(("simulate", key, k), f"argument {k} is not the input",
                                 f"the input is argument {argument}") for k in wrong]
            if not wrong:
                update[single] = given.get(argument) if key != "start" else \
                    given.get(argument, type(settings).model_fields["start"].default)
            if key == "motors":
                update["motors"] = None
    if settings.rest_rpm is not None:
        problems.append(Problem(("simulate", "rest_rpm"), "rest_rpm applies to several "
                                "inputs; one input ends its run where its speed falls to "
                                "zero", "remove rest_rpm (reverse: false stops there)"))
    if problems:
        raise ModelError(problems)
    return settings.model_copy(update=update) if update else settings


def _si(value, kind, unit: str, path: tuple[str | int, ...]) -> float:
    try:
        return to_si(value, kind, unit)
    except UnitProblem as exc:
        raise ModelError([Problem(path, exc.message, exc.hint)]) from None
