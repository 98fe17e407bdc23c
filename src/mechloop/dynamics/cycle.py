"""The steady cycle of a one-input machine, from its solved reduced characteristics.

The positions ``0..N`` of the model are one cycle of the input ``q`` (argument of the
drive).  The machine's loads reduced to the input (``M_red``, and friction reduced at the
nominal speed when asked) plus a constant moment ``M_c`` that makes the net work over the
cycle zero drive its motion; :mod:`mechloop.dynamics.machine` gives the speed over the
cycle, the coefficient of speed fluctuation and the flywheel for a wanted one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics import machine
from mechloop.dynamics.reduced import Reduced
from mechloop.errors import SolveError
from mechloop.model.dynamic import Machine

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Cycle:
    """Machine motion over one cycle (SI; arrays shaped (P,)).

    ``constant_load``: the constant moment (force) on the input that balances the cycle's
    work; ``motion``: the motion without a flywheel; ``flywheel``/``flywheel_approx``: the
    flywheel moment of inertia for ``delta`` (exact root of δ(J_f) = δ, and the textbook
    approximation), None without ``delta``; ``with_flywheel``: the motion with it.
    """

    q: Array
    omega_mean: float
    reduced_load: Array
    constant_load: float
    motion: machine.MachineMotion
    delta: float | None
    flywheel: float | None
    flywheel_approx: float | None
    with_flywheel: machine.MachineMotion | None


def steady_cycle(q: Array, time: Array, red: Reduced, friction_loss: Array, rate: Array,
                 spec: Machine) -> Cycle:
    """Machine motion of a solved one-input model.

    ``q`` (rad or m) and ``time`` (s) over positions, ``red`` the reduced characteristics,
    ``friction_loss`` (W) and ``rate`` (the input's speed) from the force analysis at the
    nominal speed.
    """
    if not (np.all(np.isfinite(q)) and np.all(np.isfinite(red.inertia))):
        raise SolveError("machine motion needs the whole cycle, but the chain breaks or the "
                         "force analysis is singular at some positions",
                         "remove the chain break (see the solve report) before sizing "
                         "the flywheel")
    if np.any(np.diff(q) <= 0):
        raise SolveError("machine motion needs the input to advance at every position of "
                         "the cycle", "make argument 1 increase from position 0 to N")
    omega_mean = float((q[-1] - q[0]) / (time[-1] - time[0]))
    load = red.load.copy()
    if spec.friction:
        with np.errstate(divide="ignore", invalid="ignore"):
            load -= np.where(rate != 0, friction_loss / rate, 0.0)
    constant = float(machine.steady_driving_moment(q, load))
    total = load + constant
    motion = machine.machine_motion(q, red.inertia, total, omega_mean=omega_mean,
                                    dj_red=red.d_inertia)
    flywheel = approx = with_flywheel = None
    if spec.delta is not None:
        flywheel = float(machine.flywheel_inertia(q, red.inertia, total, omega_mean=omega_mean,
                                                  delta=spec.delta, dj_red=red.d_inertia))
        approx = float(machine.flywheel_inertia_approx(q, red.inertia, total,
                                                       omega_mean=omega_mean,
                                                       delta=spec.delta,
                                                       dj_red=red.d_inertia))
        with_flywheel = machine.machine_motion(q, red.inertia + flywheel, total,
                                               omega_mean=omega_mean, dj_red=red.d_inertia)
    return Cycle(q, omega_mean, load, constant, motion, spec.delta, flywheel, approx,
                 with_flywheel)
