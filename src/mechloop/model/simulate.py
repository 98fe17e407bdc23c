"""The ``simulate:`` section of a model file: the machine's motion in time.

A one-input machine (one drive, turning: an angle argument) moves under a motor on its
input and the loads the model already has, from a start state, for a time or a number of
cycles (``mechloop simulate``, :func:`mechloop.dynamics.simulate.simulate`).  Speeds are in
rpm, times in seconds, moments in the model's moment unit, angles in its angle unit,
moments of inertia in its inertia unit (any value may carry its own unit, e.g.
``"50 N*m"``).
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from mechloop.model.numbers import Number, Scalar
from mechloop.model.signals import _Frozen


class Kloss(_Frozen):
    """An induction motor by Kloss's formula ``M = 2·M_k / (s/s_k + s_k/s)`` with the slip
    ``s = 1 − n/n_sync``; the breakdown torque ``M_k = breakdown·M_rated`` and the
    breakdown slip ``s_k = s_rated·(λ + √(λ² − 1))``, λ = ``breakdown``, so that the curve
    passes through the rated point."""

    rated_torque: Scalar = Field(description="rated torque on the motor shaft (moment "
                                 "units)")
    rated_rpm: Number = Field(gt=0, description="rated speed of the motor shaft, rpm")
    synchronous_rpm: Number = Field(gt=0, description="synchronous speed, rpm (e.g. 1500 "
                                    "for a four-pole motor on 50 Hz)")
    breakdown: Number = Field(2.5, gt=1, le=10, description="breakdown torque over rated "
                              "torque λ = M_k/M_rated (catalogues: 1.7 to 3)")

    @model_validator(mode="after")
    def _slips(self) -> Kloss:
        if not self.rated_rpm < self.synchronous_rpm:
            raise ValueError("rated_rpm must be below synchronous_rpm (a motor has a "
                             "positive slip at its rated load)")
        return self


class LinearMotor(_Frozen):
    """A motor whose torque falls linearly with speed (a DC shunt motor, or any motor
    near its operating point): ``M = stall_torque·(1 − n/idle_rpm)``."""

    stall_torque: Scalar = Field(description="torque at rest (moment units)")
    idle_rpm: Number = Field(gt=0, description="speed at which the torque is zero, rpm")


class Motor(_Frozen):
    """The driving moment on the input: a characteristic M(n) of the motor shaft — exactly
    one of ``kloss``, ``linear``, ``table``, ``constant`` — through a gear of ``ratio``
    motor turns per input turn (the input gets ``ratio·M``, the motor turns at ``ratio·n``);
    the rotor's inertia adds ``ratio²·inertia`` to the machine's.  ``off_at``: the motor is
    switched off at that time (a run-down follows)."""

    kloss: Kloss | None = Field(None, description="induction motor (Kloss's formula)")
    linear: LinearMotor | None = Field(None, description="torque falling linearly with "
                                       "speed")
    table: list[tuple[Number, Scalar]] | None = Field(
        None, min_length=2, description="[rpm, torque] pairs of the motor shaft, speeds "
        "increasing; linear between them, the end torques held beyond")
    constant: Scalar | None = Field(None, description="a constant torque (moment units)")
    ratio: Number = Field(1.0, gt=0, description="gear ratio: motor turns per input turn")
    inertia: Scalar = Field(0.0, description="rotor's moment of inertia (inertia units)")
    off_at: Number | None = Field(None, ge=0, description="time at which the motor is "
                                  "switched off, s (default: never)")

    @model_validator(mode="after")
    def _one_characteristic(self) -> Motor:
        given = [k for k in ("kloss", "linear", "table", "constant")
                 if getattr(self, k) is not None]
        if len(given) != 1:
            raise ValueError("give exactly one characteristic: kloss, linear, table or "
                             f"constant (got {', '.join(given) or 'none'})")
        if self.table is not None and not all(
                a[0] < b[0] for a, b in zip(self.table, self.table[1:], strict=False)):
            raise ValueError("the speeds of the motor table must increase")
        return self


class Start(_Frozen):
    """The state at time 0: the input's angle and speed."""

    angle: Scalar | None = Field(None, description="angle of the input (angle units; "
                                 "default: its value at position 0)")
    rpm: Number = Field(0.0, ge=-1e6, le=1e6, description="speed of the input, rpm "
                        "(default 0: start from rest)")


class Simulate(_Frozen):
    """Motion in time of a one-input machine: ``J(q)·q̈ + ½·J'(q)·q̇² = M(q, q̇, t)``
    integrated from ``start`` with the reduced inertia and loads of the model (over its
    positions, one cycle of the input), the motor and a flywheel.  The run ends at
    ``duration``, after ``cycles`` cycles, when the machine stops (speed 0), when the input
    reaches ``stop_at``, or, with ``until_steady``, once the motion is steady; with
    ``reverse`` it turns back instead of stopping.

    A machine with several inputs (drives) moves by Lagrange's equations
    ``M(q)·q̈ + h(q, q̇) = Q(q, q̇, t)`` (:mod:`mechloop.dynamics.lagrange`): ``motors``,
    ``start`` and ``stop_at`` are then keyed by the input's argument number, the run
    ends at ``duration``, when an input reaches its ``stop_at``, when every input is
    slower than ``rest_rpm``, or just before the chain breaks."""

    motor: Motor | None = Field(None, description="the driving motor (default: none — the "
                                "machine coasts)")
    motors: dict[int, Motor] | None = Field(
        None, description="several inputs: a motor per input, keyed by its argument "
        "number (default: none — the inputs move under the loads alone)")
    start: Start | dict[int, Start] = Field(
        Start(), description="state at time 0 (default: position 0, at rest); several "
        "inputs: one per input, keyed by its argument number")
    duration: Number | None = Field(None, gt=0, description="simulated time, s")
    cycles: int | None = Field(None, ge=1, le=1_000_000, description="stop after this many "
                               "cycles of the input")
    until_steady: bool = Field(False, description="stop at the end of the first steady "
                               "cycle (see steady)")
    steady: Number = Field(1e-4, gt=0, lt=1, description="a cycle is steady when its mean "
                           "speed differs from the previous cycle's by less than this "
                           "fraction")
    reverse: bool = Field(False, description="keep going when the speed passes through "
                          "zero (the machine turns back: loads over positions that store "
                          "energy, such as gravity) instead of ending the run there")
    stop_at: Scalar | dict[int, Scalar] | None = Field(
        None, description="stop when the input's angle reaches this value (angle units; "
        "it grows by a cycle each cycle); several inputs: per input, keyed by its "
        "argument number")
    rest_rpm: Number | None = Field(None, gt=0, description="several inputs: end the run "
                                    "once every input turns slower than this, rpm "
                                    "(default: never)")
    flywheel: Literal["machine"] | Scalar | None = Field(
        None, description="a flywheel on the input: its moment of inertia (inertia units), "
        "or 'machine' for the one machine: sizes for its delta")
    friction: bool = Field(True, description="include the joints' friction, reduced to the "
                           "input as found at the model's nominal speed (machine:'s rule)")
    every: Literal["cycle"] | Number | None = Field(
        None, description="output rows: every this many seconds, or 'cycle' (one row at "
        "the start of each cycle); default 1/1000 of the simulated time")
    rtol: Number = Field(1e-8, gt=0, lt=1, description="relative tolerance of the "
                         "integrator (scipy solve_ivp)")
    atol: Number = Field(1e-9, gt=0, description="absolute tolerance, rad and rad/s")
    method: Literal["DOP853", "RK45", "Radau", "BDF", "LSODA"] = Field(
        "DOP853", description="scipy solve_ivp method")

    @model_validator(mode="after")
    def _an_end(self) -> Simulate:
        if self.duration is None and self.cycles is None:
            raise ValueError("give duration (s) or cycles: the run needs an end")
        if self.motor is not None and self.motors is not None:
            raise ValueError("give motor (one input) or motors (one per input), not both")
        return self
