"""Motion in time of a one-input machine: start-up, run-down, the approach to the steady
cycle.

The machine is reduced to its input ``q`` (rad) as in :mod:`mechloop.dynamics.machine`:
reduced moment of inertia ``J(q)`` (kg·m²), the reduced moment ``M_q(q)`` (N·m) of the
model's loads (gravity, forces and moments over the positions, and the joints' friction
reduced at the nominal speed), and a motor ``M_d(ω, t)`` on the input.  The equation of
motion (Lagrange's, one degree of freedom)

    J(q)·q̈ + ½·J'(q)·q̇² = M_q(q) + M_d(q̇, t)

is integrated by :func:`scipy.integrate.solve_ivp` for the state ``(q, ω, W_d, W_s)``,
``W_d`` the motor's work and ``W_s`` the work of the loads that depend on the speed, with
dense output, cycle by cycle.  Those loads (dampers, loads that act only while a
parameter moves one way: :mod:`mechloop.dynamics.state_terms`) add ``M_s(q, ω)`` to the
right-hand side; springs, like gravity, are in ``M_q(q)``.

**Functions of q** (:class:`~mechloop.dynamics.reduced_machine.ReducedMachine`). ``J`` and
``M_q`` are known exactly at the model's positions (one cycle of the input) and read
between them as the cubic spline that :mod:`.machine` uses.  ``J'`` is the derivative of
that same spline — not a second interpolation of the analogs' ``dJ/dq`` — so ``½·J(q)·ω²``
changes exactly by the work done and energy is conserved to the integrator's tolerance.
How well the spline reads the true ``J`` between positions is estimated
(``Interpolation.inertia_error``: a spline through every other position misses the rest
by ``e``; through all of them the error is about ``e/16``, fourth order) and checked
(``Interpolation.slope_error``: the spline's slope against the analogs' ``dJ/dq`` at the
positions); refine ``positions`` for a smaller one.  A machine whose ``J`` is periodic runs
through any number of cycles; one whose ``J`` is not (a rocker's range) stops where it
leaves the modelled range (event ``"range"``).  A chain that breaks somewhere in the range
(at positions, or between two by the exact existence check) is simulated over the
stretch of positions around the start that it passes through
(:mod:`mechloop.dynamics.chain_span`): the run stops at the stretch's last position with
the event ``"chain break ahead"``, which names the exact input value of the break.

**Cycles and the steady state.** A cycle is one period ``L`` of ``q`` (the model's range of
the input), from the angle of position 0 on, turn by turn (a start inside a cycle makes the
first one partial: it is not counted).  Its mean speed is ``L / T_k`` (``T_k`` its
duration).
The motion is steady at the end of the first cycle whose mean speed differs from the
previous cycle's by less than ``steady`` of itself; the **time to steady state** is the
time at the end of that cycle.

Units: SI (rad, rad/s, rad/s², s, N·m, kg·m², J).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp

from mechloop.dynamics.motors import RPM, MotorCurve, motor_curve
from mechloop.dynamics.reduced_machine import ReducedMachine
from mechloop.dynamics.state_terms import StateTerms
from mechloop.errors import ModelError, Problem, SolveError
from mechloop.model.units import UnitProblem, to_si

if TYPE_CHECKING:
    from mechloop.dynamics.analysis import DynamicResults
    from mechloop.dynamics.simulate_inputs import InputsSimulation
    from mechloop.model.schema import Model
    from mechloop.model.simulate import Simulate

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Event:
    """Something that happened: ``kind`` is one of ``"start"``, ``"motor off"``,
    ``"stopped"`` (the speed fell to zero), ``"range"`` (the input reached an end of the
    modelled range of a machine that is not periodic: the model knows nothing beyond),
    ``"chain break ahead"`` (the input reached the last position before a chain break:
    ``at`` is the input value where the chain breaks, rad, from the exact existence check,
    :mod:`mechloop.dynamics.chain_span`), ``"angle"`` (``stop_at`` reached), ``"steady"``,
    ``"cycles"``, ``"duration"``; at time ``t`` (s), angle ``q`` (rad), speed ``omega``
    (rad/s)."""

    kind: str
    t: float
    q: float
    omega: float
    at: float | None = None

    def describe(self, lang: str = "en") -> str:
        """The event in words, angles in degrees, speeds in rpm, in ``lang`` ('en', or
        'ru': :mod:`mechloop.dynamics.simulate_words`, the decimal comma)."""
        from mechloop.dynamics.simulate_words import RUSSIAN_KINDS, WORDS

        words = WORDS[lang]
        kind = RUSSIAN_KINDS.get(self.kind, self.kind) if lang == "ru" else self.kind
        text = words["event"].format(kind=kind, t=f"{self.t:.6g}",
                                     q=f"{math.degrees(self.q):.6g}",
                                     omega=f"{self.omega / RPM:.6g}")
        if self.kind == "chain break ahead" and self.at is not None:
            text += words["break"].format(at=f"{math.degrees(self.at):.8g}",
                                          further=f"{abs(math.degrees(self.at - self.q)):.4g}")
        elif self.kind == "range":
            text += words["range"]
        if lang == "en":
            return text
        from mechloop.views.decimal_mark import localized  # the decimal comma

        return localized(text, lang)


@dataclass(frozen=True)
class Settings:
    """How to integrate (SI): ``duration`` (s) and/or ``cycles`` end the run;
    ``until_steady`` stops at the first steady cycle (relative change of the mean speed
    below ``steady``); ``reverse``: turn back where the speed passes through zero instead
    of ending the run; ``stop_at``: an angle (rad) that ends the run; ``rtol``, ``atol``,
    ``method``: of :func:`scipy.integrate.solve_ivp` (``atol`` in rad and rad/s; the
    motor's work, J, gets ``atol`` times the largest ``J``); ``every``: output step (s),
    ``"cycle"``, or None (1/1000 of the simulated time)."""

    duration: float | None = None
    cycles: int | None = None
    until_steady: bool = False
    steady: float = 1e-4
    reverse: bool = False
    stop_at: float | None = None
    rtol: float = 1e-8
    atol: float = 1e-9
    method: str = "DOP853"
    every: float | str | None = None


@dataclass(frozen=True)
class Segment:
    """One piece of the run, ``t0 ≤ t ≤ t1`` (s), and its dense output: calling it at
    times ``t`` gives the state ``(4, n)`` (``q``, ``ω``, the motor's work, the work of
    the speed-dependent loads).  The integrator
    works on ``q`` from the cycle's start, so that its relative tolerance does not loosen
    as ``q`` grows cycle by cycle."""

    t0: float
    t1: float
    sol: Callable[[Array], Array]
    offset: float = 0.0  # the integrator's q is q − offset (rad): its cycle's start

    def __call__(self, t: Array) -> Array:
        y = self.sol(t)
        y[0] += self.offset
        return y


@dataclass(frozen=True)
class Simulation:
    """The motion in time.

    Attributes
    ----------
    time, q, omega, epsilon : array, shape (R,) — output rows: s, rad, rad/s, rad/s².
    motor_moment, load_moment : array, shape (R,), N·m — the motor's moment on the input,
        and the reduced moment of the model's loads ``M_q(q) + M_s(q, ω)``.
    inertia : array, shape (R,), kg·m² — ``J(q)`` (with flywheel and rotor).
    kinetic_energy, motor_work, load_work : array, shape (R,), J — ``½·J·ω²``, the motor's
        work and the loads' work since time 0 (``state_work`` included).
    balance : array, shape (R,), J — ``T − T(0) − W_motor − W_loads``: zero but for the
        integrator's error.
    events : list of :class:`Event` — in time order, the first ``"start"``, the last what
        ended the run.
    cycle_start, cycle_time, cycle_speed : array, shape (C,) — for each completed cycle:
        its start (s), duration (s) and mean speed ``L/T`` (rad/s).
    steady_time : float or None — time to steady state (s): the end of the first cycle
        whose mean speed changed by less than ``settings.steady`` (None: not reached).
    machine : :class:`ReducedMachine` — the machine integrated (flywheel and rotor
        included); ``motor``: the motor (None: none); ``settings``; ``segments``: the
        pieces of the run with their dense output.
    """

    time: Array
    q: Array
    omega: Array
    epsilon: Array
    motor_moment: Array
    load_moment: Array
    inertia: Array
    kinetic_energy: Array
    motor_work: Array
    load_work: Array
    balance: Array
    events: list[Event]
    cycle_start: Array
    cycle_time: Array
    cycle_speed: Array
    steady_time: float | None
    machine: ReducedMachine
    motor: MotorCurve | None
    settings: Settings
    segments: list[Segment] = field(repr=False, default_factory=list)
    steps: int = 0
    state_work: Array | None = None  # (R,), J: work of the speed-dependent loads (None: none)

    @property
    def end(self) -> Event:
        """What ended the run."""
        return self.events[-1]

    def state(self, t: ArrayLike) -> tuple[Array, Array]:
        """``(q, ω)`` at times ``t`` (s, within the run), shape (n,), from the dense
        output."""
        y = _dense(self.segments, np.atleast_1d(np.asarray(t, dtype=float)))
        return y[0], y[1]

    def motor_work_at(self, t: ArrayLike) -> Array:
        """The motor's work since time 0 at times ``t`` (s), J, shape (n,)."""
        return _dense(self.segments, np.atleast_1d(np.asarray(t, dtype=float)))[2]

    def cycle_profile(self, cycle: int = -1) -> tuple[Array, Array, Array]:
        """``(q, t, ω)`` at the model's positions during completed cycle ``cycle`` (an
        index into ``cycle_start``; default the last), each shape (P,): ``q`` (rad) from
        the cycle's start angle on, the times (s) found by Newton's method on the dense
        output, the speeds (rad/s)."""
        if self.cycle_start.size == 0:
            raise SolveError("no cycle was completed", "simulate longer")
        t0 = float(self.cycle_start[cycle])
        t1 = t0 + float(self.cycle_time[cycle])
        q0 = float(self.state(t0)[0][0])
        targets = q0 + (self.machine.q - self.machine.q[0])
        grid = np.linspace(t0, t1, 64 * targets.size)
        t = np.interp(targets, self.state(grid)[0], grid)
        q = self.state(t)[0]
        for _ in range(4):  # Newton's steps, each kept only where it gets closer
            w = self.state(t)[1]
            with np.errstate(divide="ignore", invalid="ignore"):
                trial = np.clip(t - (q - targets) / w, t0, t1)
            trial = np.where(np.isfinite(trial), trial, t)
            q_trial = self.state(trial)[0]
            better = np.abs(q_trial - targets) < np.abs(q - targets)
            t, q = np.where(better, trial, t), np.where(better, q_trial, q)
        return targets, t, self.state(t)[1]

    def to_frame(self) -> pd.DataFrame:
        """The output rows as a table (SI; the angle in degrees, the speed also in rpm)."""
        return pd.DataFrame({
            "time [s]": self.time, "q [deg]": np.degrees(self.q),
            "omega [rad/s]": self.omega, "n [rpm]": self.omega / RPM,
            "epsilon [rad/s^2]": self.epsilon, "J [kg*m^2]": self.inertia,
            "M_motor [N*m]": self.motor_moment, "M_loads [N*m]": self.load_moment,
            "T [J]": self.kinetic_energy, "W_motor [J]": self.motor_work,
            "W_loads [J]": self.load_work, "balance [J]": self.balance})


def integrate(machine: ReducedMachine, motor: MotorCurve | None, q0: float, omega0: float,
              settings: Settings, *, progress: Callable[[float, float], None] | None = None
              ) -> Simulation:
    """Integrate the reduced equation of motion from ``(q0, omega0)`` (rad, rad/s ≥ 0).

    The run is split into pieces — one cycle each, ended by the cycle's end, the motor's
    switch-off and the end time — so that the integrator never steps over a jump of the
    right-hand side.  ``progress(done, total)`` is called after every piece (seconds, or
    cycles when only ``cycles`` bounds the run).  Raises :class:`SolveError` when the
    integrator fails or a cycle without a time bound does not end.
    """
    if settings.duration is None and settings.cycles is None:
        raise SolveError("the run needs an end", "give a duration (s) or a number of cycles")
    if not omega0 >= 0:
        raise SolveError(f"the start speed must be zero or positive, got {omega0!r} rad/s",
                         "start from rest or turning forwards")
    if motor is not None and motor.inertia:
        machine = machine.with_inertia(motor.inertia)
    if not machine.periodic and not machine.q[0] <= q0 <= machine.q[-1]:
        raise SolveError(f"the start angle {math.degrees(q0):.6g} deg is outside the "
                         f"modelled range {math.degrees(machine.q[0]):.6g} … "
                         f"{math.degrees(machine.q[-1]):.6g} deg of a machine that is not "
                         "periodic", "start inside the range of the input's argument")
    if settings.stop_at is not None and not settings.stop_at > q0:
        raise SolveError(f"stop_at ({math.degrees(settings.stop_at):.6g} deg) must lie "
                         f"ahead of the start ({math.degrees(q0):.6g} deg)",
                         "give an angle beyond the start angle (it grows turn by turn)")
    t_end = math.inf if settings.duration is None else float(settings.duration)
    off = math.inf if motor is None else motor.off_at
    work_atol = settings.atol * max(1.0, float(machine.inertia.max()))
    atol = np.array([settings.atol, settings.atol, work_atol, work_atol])
    events = [Event("start", 0.0, q0, omega0)]
    segments: list[Segment] = []
    starts: list[float] = []
    times: list[float] = []
    t, y = 0.0, np.array([q0, omega0, 0.0, 0.0])
    shift = np.zeros(4)
    # laps are the model's cycles: from the angle of position 0, turn by turn; a start
    # inside one makes the first lap partial (not counted as a cycle)
    lap_t, lap_q, partial = 0.0, machine.start, False
    if machine.periodic:
        turn = math.floor((q0 - machine.start) / machine.period + 1e-12)
        lap_q = machine.start + turn * machine.period
        partial = q0 - lap_q > 1e-12 * machine.period
    steady_time: float | None = None
    steps = 0
    while True:
        driven = motor is not None and t < off

        def rhs(time: float, s: Array, driven=driven, lap_q=lap_q) -> Array:
            q, w = float(s[0]) + lap_q, float(s[1])
            drive = float(motor.torque(np.asarray(w))) if driven else 0.0
            j, dj, m = machine.terms(q, lap_q)
            ms = float(machine.state_moment(q, w, time)) if machine.state is not None \
                else 0.0
            return np.array([w, (m + ms + drive - 0.5 * dj * w * w) / j, drive * w, ms * w])

        checks = {} if settings.reverse else {"stopped": _event(1, 0.0, -1.0)}
        if machine.periodic:
            checks["lap"] = _event(0, machine.period, +1.0)
            if settings.reverse:
                checks["back"] = _event(0, 0.0, -1.0)
        else:
            checks["range"] = _event(0, float(machine.q[-1]) - lap_q, +1.0)
            checks["range "] = _event(0, float(machine.q[0]) - lap_q, -1.0)
        if settings.stop_at is not None and y[0] < settings.stop_at:
            checks["angle"] = _event(0, settings.stop_at - lap_q, +1.0)
        stop_t = min(t_end, off) if driven else t_end
        if math.isinf(stop_t):
            stop_t = t + max(1000.0, 1000.0 * machine.period / max(float(y[1]), 1e-9))
        shift[0] = lap_q
        sol = solve_ivp(rhs, (t, stop_t), y - shift, method=settings.method,
                        rtol=settings.rtol, atol=atol, dense_output=True,
                        events=list(checks.values()))
        if sol.status == -1:
            raise SolveError(f"the integrator failed at t = {sol.t[-1]:.6g} s: "
                             f"{sol.message}", "loosen rtol/atol or try method: Radau")
        segments.append(Segment(t, float(sol.t[-1]), sol.sol, lap_q))
        steps += sol.t.size - 1
        t, y = float(sol.t[-1]), sol.y[:, -1] + shift
        hits = sorted((float(te[0]), order, kind) for order, (kind, te) in
                      enumerate(zip(checks, sol.t_events, strict=True)) if te.size)
        if progress is not None:
            progress(*((min(t, t_end), t_end) if settings.duration is not None
                       else (float(len(times)), float(settings.cycles or 0))))
        if not hits:
            if t >= t_end:
                events.append(Event("duration", t, y[0], y[1]))
                break
            if driven and t >= off:
                events.append(Event("motor off", t, y[0], y[1]))
                continue
            raise SolveError(f"the cycle that starts at t = {lap_t:.6g} s does not end",
                             "give a duration (s)")
        kind = hits[0][2]
        end = None
        if kind.startswith("range"):
            end = machine.breaks[0 if kind == "range " else 1]
            kind = "range" if end is None else "chain break ahead"
        kind = kind.strip()
        if kind == "back":  # turned back into the previous cycle: it is not a whole one
            y[0] = lap_q
            lap_t, lap_q, partial = t, lap_q - machine.period, True
            continue
        if kind != "lap":
            if kind == "stopped":
                y[1] = 0.0
            events.append(Event(kind, t, y[0], y[1], None if end is None else end.q))
            break
        y[0] = lap_q + machine.period  # exactly on the cycle's end
        if not partial:
            starts.append(lap_t)
            times.append(t - lap_t)
        lap_t, lap_q, partial = t, float(y[0]), False
        if steady_time is None and len(times) >= 2 and \
                abs(times[-1] - times[-2]) <= settings.steady * times[-1]:
            steady_time = t
            if settings.until_steady:
                events.append(Event("steady", t, y[0], y[1]))
                break
        if settings.cycles is not None and len(times) >= settings.cycles:
            events.append(Event("cycles", t, y[0], y[1]))
            break
        if t >= t_end:
            events.append(Event("duration", t, y[0], y[1]))
            break
    return _assemble(machine, motor, settings, events, segments, starts, times,
                     steady_time, steps)


def _event(index: int, value: float, direction: float) -> Callable[[float, Array], float]:
    """A terminal event: state component ``index`` crosses ``value`` in ``direction``."""

    def event(t: float, y: Array) -> float:
        return y[index] - value

    event.terminal, event.direction = True, direction  # type: ignore[attr-defined]
    return event


def _dense(segments: list[Segment], t: Array) -> Array:
    """The state ``(4, n)`` at times ``t`` from the segments' dense output."""
    out = np.empty((4, t.size))
    ends = np.array([s.t1 for s in segments])
    which = np.minimum(np.searchsorted(ends, t, side="left"), len(segments) - 1)
    for i in np.unique(which):
        sel = which == i
        out[:, sel] = segments[i](t[sel])
    return out


def _assemble(machine: ReducedMachine, motor: MotorCurve | None, settings: Settings,
              events: list[Event], segments: list[Segment], starts: list[float],
              times: list[float], steady_time: float | None, steps: int) -> Simulation:
    """The output rows of a finished run."""
    t_final = events[-1].t
    if settings.every == "cycle":
        t = np.unique([0.0, *(a + d for a, d in zip(starts, times, strict=True)), t_final])
    else:
        step = t_final / 1000.0 if settings.every is None else float(settings.every)
        t = np.append(np.arange(0.0, t_final, step), t_final) if step > 0 else np.zeros(1)
    q, w, w_motor, w_state = _dense(segments, t)
    if events[-1].kind == "stopped":
        w[-1] = 0.0
    drive = np.zeros_like(t) if motor is None else motor.at(w, t)
    j, m = machine.j(q), machine.m(q) + machine.state_moment(q, w, t)
    eps = (m + drive - 0.5 * machine.dj(q) * w * w) / j
    kinetic = 0.5 * j * w * w
    start = events[0]
    load_work = machine.work(q) - machine.work(start.q) + w_state
    balance = kinetic - 0.5 * float(machine.j(start.q)) * start.omega**2 - w_motor - load_work
    cycle_time = np.array(times)
    return Simulation(t, q, w, eps, drive, m, j, kinetic, w_motor, load_work, balance,
                      events, np.array(starts), cycle_time,
                      machine.period / cycle_time if times else np.empty(0), steady_time,
                      machine, motor, settings, segments, steps,
                      None if machine.state is None else w_state)


def simulate(model: Model, settings: Simulate | dict[str, Any] | None = None, *,
             dynamics: DynamicResults | None = None,
             progress: Callable[[float, float], None] | None = None
             ) -> Simulation | InputsSimulation:
    """The motion in time of a one-input ``model`` (its ``simulate:`` section, or
    ``settings``: a :class:`~mechloop.model.simulate.Simulate` or the same as a mapping).

    The reduced inertia and loads come from :func:`mechloop.solve_dynamics` (pass its
    result as ``dynamics`` to reuse it) over the model's positions, which must be one cycle
    of the input (an angle argument over whole turns) or, for a machine that is not
    periodic (its range is not whole turns, or ``J`` does not return), its range: the run
    then ends where the input leaves it.
    ``progress(done, total)`` is called as the run goes (see :func:`integrate`).

    Raises :class:`~mechloop.errors.ModelError` (located at the key to change) when the
    model cannot be simulated: no settings, not one turning input, a start at a chain
    break or fewer than 4 positions between breaks around it, an input that does not
    advance, no moving mass, ``flywheel: machine`` without a flywheel from ``machine:``.

    A model with several inputs (drives) moves by Lagrange's equations instead:
    :func:`mechloop.dynamics.simulate_inputs.simulate_inputs` (an
    :class:`~mechloop.dynamics.simulate_inputs.InputsSimulation`).
    """
    from mechloop.model.simulate import Simulate

    if settings is None:
        settings = model.simulate
        if settings is None:
            raise ModelError([Problem(("simulate",), "the model has no simulate: section",
                                      "add simulate: {motor: ..., duration: 5} or pass "
                                      "settings")])
    elif not isinstance(settings, Simulate):
        from pydantic import ValidationError

        try:
            settings = Simulate.model_validate(settings)
        except ValidationError as exc:
            raise ModelError([Problem(("simulate", *e["loc"]), e["msg"],
                                      "see the simulate: section of the model schema")
                              for e in exc.errors()]) from None
    if dynamics is None:
        from mechloop.dynamics.analysis import solve_dynamics

        dynamics = solve_dynamics(model)
    if len(dynamics.mechanism.drives) > 1:  # Lagrange's equations of several inputs
        from mechloop.dynamics.simulate_inputs import simulate_inputs

        return simulate_inputs(model, settings, dynamics, progress=progress)
    if dynamics.mechanism.drives:
        from mechloop.dynamics.simulate_inputs import one_input

        settings = one_input(settings, dynamics.mechanism.drives[0].argument)
    k = dynamics.mechanism.drives[0].argument
    start = settings.start
    q0 = float(dynamics.kinematics.arguments[k][0]) if start.angle is None else _si(
        start.angle, "angle", model.units.angle, ("simulate", "start", "angle"))
    machine, extra = model_machine(model, settings, dynamics, start=q0)
    motor = None if settings.motor is None else motor_curve(settings.motor, model.units)
    stop_at = None if settings.stop_at is None else _si(
        settings.stop_at, "angle", model.units.angle, ("simulate", "stop_at"))
    run = Settings(duration=settings.duration, cycles=settings.cycles,
                   until_steady=settings.until_steady, steady=settings.steady,
                   reverse=settings.reverse, stop_at=stop_at, rtol=settings.rtol,
                   atol=settings.atol, method=settings.method, every=settings.every)
    try:
        return integrate(machine.with_inertia(extra) if extra else machine, motor, q0,
                         start.rpm * RPM, run, progress=progress)
    except SolveError as exc:
        raise exc.at(("simulate",)) from None


def model_machine(model: Model, settings: Simulate, dynamics: DynamicResults, *,
                  start: float | None = None) -> tuple[ReducedMachine, float]:
    """The reduced machine of a solved model (loads, and friction at the nominal speed when
    ``settings.friction``), and the flywheel's inertia (kg·m²) to add.

    Where the chain breaks (at positions, or between them by the exact existence check)
    the machine is the stretch of positions around ``start`` (rad; default position 0)
    that the chain passes through, with the breaks beyond its ends
    (:func:`~mechloop.dynamics.chain_span.unbroken_span`)."""
    mech, red, kin = dynamics.mechanism, dynamics.reduced, dynamics.kinematics
    if red is None or kin.argument_kinds[mech.drives[0].argument] != "angle":
        raise ModelError([Problem(("simulate",), "motion in time needs one input that "
                                  f"turns (the model has {len(mech.drives)} drive(s)"
                                  + ("" if red is None else ", driven by a length") + ")",
                                  "drive the machine by one angle argument")])
    k = mech.drives[0].argument
    q = np.asarray(kin.arguments[k], dtype=float)
    turns = (q[-1] - q[0]) / (2 * np.pi)
    whole = round(turns) >= 1 and abs(turns - round(turns)) <= 1e-9 * turns
    keep, breaks = slice(None), (None, None)
    if (kin.broken | dynamics.forces.singular).any() or kin.breaks_between:
        from mechloop.dynamics.chain_span import unbroken_span

        span = unbroken_span(model, kin, k, dynamics.forces.singular,
                             float(q[0]) if start is None else start, whole=whole)
        keep, breaks = span.index, (span.lower, span.upper)
        q = span.q
    load = np.array(red.load, dtype=float)[keep]
    state = _state_terms(model, dynamics, k, q, whole and breaks == (None, None),
                         keep=keep)
    if state is not None:
        load -= state.static
    if settings.friction and dynamics.forces.friction_loss.any():
        rate = _argument_rate(kin, k)[keep]
        with np.errstate(divide="ignore", invalid="ignore"):
            load -= np.where(rate != 0, dynamics.forces.friction_loss[keep] / rate, 0.0)
    try:
        machine = ReducedMachine(q, np.asarray(red.inertia)[keep], load,
                                 np.asarray(red.d_inertia)[keep],
                                 periodic=None if whole and breaks == (None, None) else False,
                                 state=state, breaks=breaks)
    except SolveError as exc:
        key = ("arguments", k) if "advance" in exc.message else ("bodies",)
        raise exc.at(key) from None
    extra = 0.0
    if settings.flywheel == "machine":
        cycle = dynamics.cycle
        if cycle is None or cycle.flywheel is None:
            raise ModelError([Problem(("simulate", "flywheel"), "flywheel: machine takes "
                                      "the flywheel machine: sizes, and the model has no "
                                      "machine: {delta: ...}", "add machine: {delta: "
                                      "0.0125} or give the flywheel's moment of inertia")])
        extra = float(cycle.flywheel)
    elif settings.flywheel is not None:
        extra = _si(settings.flywheel, "inertia", model.units.inertia,
                    ("simulate", "flywheel"))
    return machine, extra


def _state_terms(model: Model, dynamics: DynamicResults, k: int, q: Array, whole: bool,
                 *, keep: slice | NDArray[np.int64] = slice(None)) -> StateTerms | None:
    """The reduced moment of the loads that depend on the speed (None: the model has
    none), from the analogs of input ``k``, at the positions ``keep`` (input ``q``)."""
    if not any(load.depends is not None
               for load in (*dynamics.loads.forces, *dynamics.loads.moments)):
        return None
    from mechloop.dynamics.loads import build_loads
    from mechloop.dynamics.points import Placement
    from mechloop.solve.inputs import model_time
    from mechloop.solve.kinematics import solve

    at = Placement(solve(model, analogs_of=k))
    loads_at = build_loads(model, dynamics.mechanism, at, model_time(model),
                           state=dynamics.placement)
    return StateTerms(q, loads_at, dynamics.mechanism, at, periodic=whole, keep=keep)


def _si(value, kind, unit: str, path: tuple[str | int, ...]) -> float:
    try:
        return to_si(value, kind, unit)
    except UnitProblem as exc:
        raise ModelError([Problem(path, exc.message, exc.hint)]) from None


def _argument_rate(results, k: int) -> Array:
    """Rate of angle argument ``k`` at the model's positions (rad/s)."""
    for number, vector in results.model.vectors.items():
        role = vector.a
        if getattr(role, "argument", None) == k:
            return results.rate(f"a{number}")
    raise KeyError(k)  # pragma: no cover - a drive is an argument of some vector
