"""Motor characteristics: the driving moment on a machine's input as a function of its
speed, for :mod:`mechloop.dynamics.simulate`.

A characteristic is a function ``torque(omega) -> moment`` on the input (rad/s → N·m, any
shape) with the motor reached through a gear of ``ratio`` motor turns per input turn: the
motor turns at ``ratio·ω`` and the input gets ``ratio·M``.  :func:`motor_curve` builds one
from a model file's ``simulate.motor`` section.

>>> torque = kloss(10.0, 1440 * RPM, 1500 * RPM, 2.5)
>>> round(float(torque(1440 * RPM)), 9)   # the rated point
10.0
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.errors import ModelError, Problem
from mechloop.model.simulate import Motor
from mechloop.model.units import UnitProblem, to_si

Array = NDArray[np.float64]

#: rad/s per rpm.
RPM = 2.0 * math.pi / 60.0


@dataclass(frozen=True)
class MotorCurve:
    """A driving moment on the input as a function of its speed, switched off at
    ``off_at`` (s; ``inf``: never).

    ``torque(omega)`` takes the input's speed (rad/s, any shape) and returns the moment on
    the input (N·m); ``inertia`` is the rotor's inertia reduced to the input
    (``ratio²·J_rotor``), kg·m²; ``name`` describes the characteristic.
    """

    torque: Callable[[Array], Array]
    name: str
    inertia: float = 0.0
    off_at: float = math.inf
    name_ru: str = ""

    def title(self, lang: str = "en") -> str:
        """``name`` in ``lang`` ('en' or 'ru': units in Russian, the decimal comma)."""
        if lang != "ru" or not self.name_ru:
            return self.name
        from mechloop.views.decimal_mark import localized

        return localized(self.name_ru, lang)

    def at(self, omega: ArrayLike, t: ArrayLike) -> Array:
        """The moment at speed ``omega`` (rad/s) and time ``t`` (s), N·m."""
        omega, t = np.asarray(omega, dtype=float), np.asarray(t, dtype=float)
        return np.where(t < self.off_at, self.torque(omega), 0.0)


def kloss(rated_torque: float, rated_speed: float, synchronous_speed: float,
          breakdown: float = 2.5, *, ratio: float = 1.0) -> Callable[[Array], Array]:
    """An induction motor's torque by Kloss's formula, reduced to the input.

    ``M(s) = 2·M_k·s·s_k / (s² + s_k²)``, ``s = 1 − ω_m/ω_s`` (``ω_m = ratio·ω`` the motor's
    speed), ``M_k = breakdown·rated_torque`` and ``s_k = s_n·(λ + √(λ² − 1))`` with the
    rated slip ``s_n = 1 − rated_speed/synchronous_speed`` and λ = ``breakdown``, so that
    the curve passes through the rated point and peaks at ``M_k`` (at ``s = s_k``).  Speeds
    rad/s of the motor shaft, torques N·m.
    """
    s_n = 1.0 - rated_speed / synchronous_speed
    s_k = s_n * (breakdown + math.sqrt(breakdown**2 - 1.0))
    m_k = breakdown * rated_torque

    def torque(omega: Array) -> Array:
        s = 1.0 - ratio * np.asarray(omega, dtype=float) / synchronous_speed
        return ratio * 2.0 * m_k * s * s_k / (s * s + s_k * s_k)

    return torque


def linear(stall_torque: float, idle_speed: float, *, ratio: float = 1.0
           ) -> Callable[[Array], Array]:
    """``M = stall_torque·(1 − ω_m/idle_speed)`` on the motor shaft (rad/s, N·m)."""

    def torque(omega: Array) -> Array:
        return ratio * stall_torque * (1.0 - ratio * np.asarray(omega, dtype=float)
                                       / idle_speed)

    return torque


def tabulated(speeds: ArrayLike, torques: ArrayLike, *, ratio: float = 1.0
              ) -> Callable[[Array], Array]:
    """Linear interpolation of ``torques`` (N·m) over increasing motor ``speeds`` (rad/s),
    the end values held beyond."""
    x, y = np.asarray(speeds, dtype=float), np.asarray(torques, dtype=float)

    def torque(omega: Array) -> Array:
        return ratio * np.interp(ratio * np.asarray(omega, dtype=float), x, y)

    return torque


def constant(value: float, *, ratio: float = 1.0) -> Callable[[Array], Array]:
    """A constant moment ``value`` (N·m) on the motor shaft."""

    def torque(omega: Array) -> Array:
        return np.full(np.shape(omega), ratio * value)

    return torque


def motor_curve(motor: Motor, units, path: tuple[str | int, ...] = ("simulate", "motor")
                ) -> MotorCurve:
    """The :class:`MotorCurve` of a model file's motor section (``units``: the model's
    :class:`~mechloop.model.schema.Units`).  Raises :class:`ModelError` for unreadable
    quantities, at ``path``."""
    problems: list[Problem] = []

    def si(value, kind, where) -> float:
        try:
            return to_si(value, kind, getattr(units, kind))
        except UnitProblem as exc:
            problems.append(Problem((*path, *where), exc.message, exc.hint))
            return 0.0

    i = motor.ratio
    gear = f" through a gear of {i:g}" if i != 1 else ""
    gear_ru = f" через передачу {i:g}" if i != 1 else ""
    if motor.kloss is not None:
        k = motor.kloss
        rated = si(k.rated_torque, "moment", ("kloss", "rated_torque"))
        torque = kloss(rated, k.rated_rpm * RPM, k.synchronous_rpm * RPM, k.breakdown,
                       ratio=i)
        name = (f"induction motor (Kloss): {rated:.6g} N*m at {k.rated_rpm:g} rpm, "
                f"synchronous {k.synchronous_rpm:g} rpm, breakdown {k.breakdown:g}×")
        name_ru = (f"асинхронный двигатель (формула Клосса): {rated:.6g} Н·м при "
                   f"{k.rated_rpm:g} об/мин, синхронная скорость {k.synchronous_rpm:g} "
                   f"об/мин, перегрузочная способность {k.breakdown:g}")
    elif motor.linear is not None:
        stall = si(motor.linear.stall_torque, "moment", ("linear", "stall_torque"))
        torque = linear(stall, motor.linear.idle_rpm * RPM, ratio=i)
        name = f"linear motor: {stall:.6g} N*m at rest, 0 at {motor.linear.idle_rpm:g} rpm"
        name_ru = (f"двигатель с линейной характеристикой: {stall:.6g} Н·м при пуске, 0 "
                   f"при {motor.linear.idle_rpm:g} об/мин")
    elif motor.table is not None:
        speeds = [row[0] * RPM for row in motor.table]
        torques = [si(row[1], "moment", ("table", n, 1)) for n, row in
                   enumerate(motor.table)]
        torque = tabulated(speeds, torques, ratio=i)
        name = f"motor table of {len(speeds)} points"
        name_ru = f"характеристика двигателя таблицей из {len(speeds)} точек"
    else:
        value = si(motor.constant, "moment", ("constant",))
        torque = constant(value, ratio=i)
        name = f"constant moment {value:.6g} N*m"
        name_ru = f"постоянный момент {value:.6g} Н·м"
    rotor = si(motor.inertia, "inertia", ("inertia",))
    if problems:
        raise ModelError(problems)
    return MotorCurve(torque, name + gear, i * i * rotor,
                      math.inf if motor.off_at is None else float(motor.off_at),
                      name_ru + gear_ru)
