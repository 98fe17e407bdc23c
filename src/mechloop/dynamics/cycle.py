"""The steady cycle of a one-input machine, from its solved reduced characteristics.

The positions ``0..N`` of the model are one cycle of the input ``q`` (argument of the
drive).  The machine's loads reduced to the input (``M_red``, and friction reduced at the
nominal speed when asked) plus a constant moment ``M_c`` that makes the net work over the
cycle zero drive its motion; :mod:`mechloop.dynamics.machine` gives the speed over the
cycle, the coefficient of speed fluctuation and the flywheel for a wanted one.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics import machine
from mechloop.dynamics.reduced import Reduced
from mechloop.model.dynamic import Machine

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Cycle:
    """Machine motion over one cycle, or over a stack of independent cycles (SI; arrays
    shaped (..., P), numbers a float or an array shaped (...)).

    ``constant_load``: the constant moment (force) on the input that balances the cycle's
    work (of the machine with its flywheel when ``delta`` is given; see
    ``bare_constant_load``); ``motion``: the motion without a flywheel;
    ``flywheel``/``flywheel_approx``: the flywheel moment of inertia for ``delta`` (exact
    root of δ(J_f) = δ, and the textbook approximation), None without ``delta``;
    ``with_flywheel``: the motion with it.
    ``computed``: where the cycle could be computed (:func:`steady_cycles`); every number
    and array of a cycle where it is False is NaN (its own :func:`steady_cycle` raises).

    With loads that depend on the speed (dampers, one-way loads: ``state``) the loads are
    taken at the cycle's own speed ω(q), not the nominal one (:func:`_settled`):
    ``reduced_load`` holds them at the speed of the machine with its flywheel (without,
    when no ``delta``); the motion without a flywheel is its own steady cycle, balanced
    by ``bare_constant_load`` (None when it equals ``constant_load``);
    ``iterations`` the fixed point's iterations (0 without such loads).
    """

    q: Array
    omega_mean: Array | float
    reduced_load: Array
    constant_load: Array | float
    motion: machine.MachineMotion
    delta: float | None
    flywheel: Array | float | None
    flywheel_approx: Array | float | None
    with_flywheel: machine.MachineMotion | None
    computed: NDArray[np.bool_] | bool = True
    bare_constant_load: float | None = None
    iterations: int = 0


def steady_cycle(q: Array, time: Array, red: Reduced, friction_loss: Array, rate: Array,
                 spec: Machine, *, state=None) -> Cycle:
    """Machine motion of a solved one-input model.

    ``q`` (rad or m) and ``time`` (s) over positions, ``red`` the reduced characteristics,
    ``friction_loss`` (W) and ``rate`` (the input's speed) from the force analysis at the
    nominal speed; arrays shaped (P,).  ``state``
    (:class:`~mechloop.dynamics.state_terms.StateTerms`, optional): the loads that depend
    on the speed, taken at the cycle's own speed.  Raises :class:`SolveError` when the
    cycle cannot be computed (the chain breaks, the input does not advance, the machine
    stops, the loads that depend on the speed do not settle).
    """
    return steady_cycles(q, time, red, friction_loss, rate, spec, failures="raise",
                         state=state)


def steady_cycles(q: Array, time: Array, red: Reduced, friction_loss: Array, rate: Array,
                  spec: Machine, *, failures: str = "nan", state=None) -> Cycle:
    """Machine motion of a stack of solved one-input models (e.g. candidate designs).

    ``red`` (its arrays), ``friction_loss`` and ``rate`` shaped (..., P); ``q`` and
    ``time`` shaped (P,) or (..., P).  Returns a :class:`Cycle` whose arrays are (..., P)
    and numbers (...).  ``failures`` (default ``"nan"``): a cycle that cannot be computed —
    what :func:`steady_cycle` raises as :class:`SolveError` — is NaN with False in
    ``computed``, or (``"raise"``) raises that error.  Cases that share one ``q`` are
    solved together; each case's numbers are those of its own :func:`steady_cycle` (to
    rounding: the stack's linear solves and bisection stops).  ``state`` (one case only,
    with ``failures="raise"``): see :func:`steady_cycle`; a stack takes the loads that
    depend on the speed at the nominal speed, as its reduced loads hold them.
    """
    if failures not in ("raise", "nan"):
        raise ValueError(f"failures must be 'raise' or 'nan', got {failures!r}")
    raising = failures == "raise"
    inertia, d_inertia = np.asarray(red.inertia, dtype=float), np.asarray(red.d_inertia,
                                                                              dtype=float)
    lead = inertia.shape[:-1]
    q = np.asarray(q, dtype=float)
    time = np.asarray(time, dtype=float)
    whole = np.all(np.isfinite(q), axis=-1) & np.all(np.isfinite(inertia), axis=-1)
    if raising and not np.all(whole):
        raise machine.MachineError("machine motion needs the whole cycle, but the chain breaks "
                                   "or the force analysis is singular at some positions",
                                   "remove the chain break (see the solve report) before "
                                   "sizing the flywheel", cause="cycle")
    with np.errstate(invalid="ignore"):
        advances = np.all(np.diff(q, axis=-1) > 0, axis=-1)
    if raising and not np.all(advances):
        raise machine.MachineError("machine motion needs the input to advance at every "
                                   "position of the cycle",
                                   "make argument 1 increase from position 0 to N",
                                   cause="advance")
    omega_mean = (q[..., -1] - q[..., 0]) / (time[..., -1] - time[..., 0])
    load = np.array(red.load, dtype=float)
    if spec.friction:
        with np.errstate(divide="ignore", invalid="ignore"):
            load -= np.where(rate != 0, friction_loss / rate, 0.0)
    if raising and state is not None and lead == ():
        return _settled(q, inertia, d_inertia, load - state.static, float(omega_mean),
                        spec, state)
    if raising:  # machine.py raises for the rest
        return _on_one_q(q, inertia, d_inertia, load, omega_mean, spec, "raise")
    # what machine.py would raise for: every case that fails becomes a placeholder
    # (J = 1, no load, the q of a good case) that solves, and NaN at the end
    ok = np.broadcast_to(whole & advances, lead) & np.all(
        np.isfinite(load) & np.isfinite(d_inertia) & (inertia > 0), axis=-1)
    with np.errstate(invalid="ignore"):
        ok &= np.broadcast_to(np.isfinite(omega_mean) & (omega_mean > 0), lead)
    n_pos = inertia.shape[-1]
    flat = int(np.prod(lead, dtype=int))
    rows_q = np.array(np.broadcast_to(q, (*lead, n_pos)).reshape(flat, n_pos))
    good = ok.reshape(flat)
    if not good.any():
        rows_q[:] = np.arange(n_pos)
    else:
        rows_q[~good] = rows_q[np.argmax(good)]
    j = np.where(good[:, None], inertia.reshape(flat, n_pos), 1.0)
    dj = np.where(good[:, None], d_inertia.reshape(flat, n_pos), 0.0)
    m = np.where(good[:, None], np.broadcast_to(load, (*lead, n_pos)).reshape(flat, n_pos),
                 0.0)
    w_mean = np.where(good, np.broadcast_to(omega_mean, lead).reshape(flat), 1.0)
    groups, which = np.unique(rows_q, axis=0, return_inverse=True)
    which = np.asarray(which).reshape(flat)
    parts = [(np.flatnonzero(which == g),
              _on_one_q(groups[g], j[which == g], dj[which == g], m[which == g],
                        w_mean[which == g], spec, "nan"))
             for g in range(len(groups))]
    cycle = parts[0][1] if len(parts) == 1 else _gather(parts, flat)
    computed = good & cycle.computed
    return Cycle(
        q=_shaped(rows_q, computed, lead), omega_mean=_shaped(w_mean, computed, lead),
        reduced_load=_shaped(m, computed, lead),
        constant_load=_shaped(cycle.constant_load, computed, lead),
        motion=_motion_shaped(cycle.motion, computed, lead), delta=spec.delta,
        flywheel=_shaped(cycle.flywheel, computed, lead),
        flywheel_approx=_shaped(cycle.flywheel_approx, computed, lead),
        with_flywheel=_motion_shaped(cycle.with_flywheel, computed, lead),
        computed=computed.reshape(lead) if lead else bool(computed[0]))


def _on_one_q(q: Array, inertia: Array, d_inertia: Array, load: Array,
              omega_mean: Array | float, spec: Machine, stops: str) -> Cycle:
    """The cycles of cases that share one ``q`` (P,); ``inertia``, ``d_inertia``, ``load``
    (..., P), ``omega_mean`` (...).  With ``stops="nan"`` a case that is not steady or
    stops (with or without the flywheel) is NaN and False in ``computed``."""
    single = np.ndim(omega_mean) == 0
    omega_mean = float(omega_mean) if single else omega_mean
    constant = _number(machine.steady_driving_moment(q, load))
    total = load + (constant if single else np.asarray(constant)[..., None])
    motion = machine.machine_motion(q, inertia, total, omega_mean=omega_mean,
                                    dj_red=d_inertia, stops=stops)
    runs = np.asarray(motion.runs)
    flywheel = approx = with_flywheel = None
    if spec.delta is not None:
        # a case that stops has no cycle: size a harmless stand-in (no load) instead
        j = inertia if runs.all() else np.where(runs[..., None], inertia, 1.0)
        m = total if runs.all() else np.where(runs[..., None], total, 0.0)
        flywheel = _number(machine.flywheel_inertia(q, j, m, omega_mean=omega_mean,
                                                    delta=spec.delta, dj_red=d_inertia))
        approx = _number(machine.flywheel_inertia_approx(q, j, m, omega_mean=omega_mean,
                                                         delta=spec.delta,
                                                         dj_red=d_inertia))
        with_flywheel = machine.machine_motion(
            q, inertia + (flywheel if single else np.asarray(flywheel)[..., None]), total,
            omega_mean=omega_mean, dj_red=d_inertia, stops=stops)
        runs = runs & np.asarray(with_flywheel.runs)
    return Cycle(q, omega_mean, load, constant, motion, spec.delta, flywheel, approx,
                 with_flywheel, bool(runs) if single else runs)


def _settled(q: Array, inertia: Array, d_inertia: Array, load: Array, omega_mean: float,
             spec: Machine, state) -> Cycle:
    """The cycle of one case whose loads depend on the speed: ``load`` (P,) without them,
    ``state`` their reduced moment ``M_s(q, ω, t)``, taken at the speed of the cycle that
    runs (with the flywheel when ``spec.delta``), by :func:`machine.settle_speed`."""

    def cycle_at(omega: Array, time: Array):
        cycle = _on_one_q(q, inertia, d_inertia, load + state.moment(q, omega, time),
                          omega_mean, spec, "raise")
        return cycle, cycle.with_flywheel if cycle.with_flywheel is not None \
            else cycle.motion

    cycle, _, count = machine.settle_speed(cycle_at, omega_mean, q)
    if spec.delta is None:
        return replace(cycle, iterations=count)
    bare = _settled(q, inertia, d_inertia, load, omega_mean,
                    spec.model_copy(update={"delta": None}), state)
    return replace(cycle, motion=bare.motion, bare_constant_load=bare.constant_load,
                   iterations=count)


def _number(x: Array | float) -> Array | float:
    return float(x) if np.ndim(x) == 0 else np.asarray(x)


def _gather(parts: list[tuple[NDArray[np.intp], Cycle]], n: int) -> Cycle:
    """One cycle of ``n`` cases from the cycles of groups of them (their indices)."""

    def put(get):
        first = get(parts[0][1])
        if first is None:
            return None
        first = np.asarray(first)
        out = np.empty((n, *first.shape[1:]), dtype=first.dtype)
        for index, cycle in parts:
            out[index] = get(cycle)
        return out

    def motion(name):
        if getattr(parts[0][1], name) is None:
            return None
        return machine.MachineMotion(**{f.name: put(lambda c, f=f: getattr(getattr(c, name),
                                                                          f.name))
                                        for f in fields(machine.MachineMotion)})

    return Cycle(put(lambda c: np.broadcast_to(c.q, c.reduced_load.shape)),
                 put(lambda c: c.omega_mean),
                 put(lambda c: c.reduced_load), put(lambda c: c.constant_load),
                 motion("motion"), parts[0][1].delta, put(lambda c: c.flywheel),
                 put(lambda c: c.flywheel_approx), motion("with_flywheel"),
                 put(lambda c: c.computed))


def _shaped(x: Array | None, computed: NDArray[np.bool_], lead: tuple[int, ...]
            ) -> Array | float | None:
    """Cases ``(n, ...)`` back to the stack's shape, NaN where not ``computed``."""
    if x is None:
        return None
    x = np.asarray(x, dtype=float)
    mask = computed.reshape(computed.shape + (1,) * (x.ndim - 1))
    x = np.where(mask, x, np.nan).reshape(*lead, *x.shape[1:])
    return float(x) if x.ndim == 0 else x


def _motion_shaped(motion: machine.MachineMotion | None, computed: NDArray[np.bool_],
                   lead: tuple[int, ...]) -> machine.MachineMotion | None:
    if motion is None:
        return None
    values = {f.name: _shaped(getattr(motion, f.name), computed, lead)
              for f in fields(machine.MachineMotion) if f.name != "runs"}
    return machine.MachineMotion(**values, runs=computed.reshape(lead) if lead
                                 else bool(computed[0]))
