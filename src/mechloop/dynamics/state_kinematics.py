"""The exact kinematics of a model with several inputs at given states ``(q, q̇)``.

The motion in time of a machine with ``n`` inputs needs, at the current state, the
velocity of every point per unit rate of each input (the first-order analogs) and the
velocity-dependent part of the accelerations.  Both come from the model's own solver
(:func:`~mechloop.solve.kinematics._solve_block`, the same closed-form modules and linear
velocity and acceleration solves as :func:`mechloop.solve`) over ``n + 1`` columns of one
state:

* column 0: the inputs at ``q`` with rates ``q̇`` and accelerations 0 — the true
  velocities, and the accelerations the motion would have with ``q̈ = 0`` (the Coriolis
  and centripetal terms, exact: no finite differences);
* column ``1 + i``: the same ``q`` with rate 1 for input ``i``, 0 for the others — the
  analogs of input ``i``.

Any number ``S`` of states is solved in one vectorized call (``S·(n + 1)`` columns).  The
result is a :class:`~mechloop.solve.results.Results` over those columns, so that
:class:`~mechloop.dynamics.points.Placement` and the loads read it like any solve.

A state's chain is whole when every contour assembles there with a regular Jacobian;
:attr:`States.margin` is the least existence margin of its contours
(:func:`mechloop.solve.between.contour_margins`: ``sin²`` of the angle between a
contour's Jacobian columns, ...), positive while the chain is whole and at or below
:data:`~mechloop.solve.between.THRESHOLD` at a dead point or a break — what the
integrator watches to stop before the chain breaks.

Limits (:class:`~mechloop.errors.SolveError` from :class:`StateKinematics`): a coupled
block (solved by continuation from position to position, it has no closed form for a
free-standing state) and an angle scaled by a link ratio (its whole turns are followed
from position to position).  A contour with ``variant: auto`` keeps the variant it has at
the model's position 0 (variant 1: a branch changes only through a dead point, where the
run ends).  Units SI (m, rad, s).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import SolveError
from mechloop.model.check import argument_kind, require_valid
from mechloop.model.schema import Model
from mechloop.solve.between import contour_margins
from mechloop.solve.inputs import Signal, model_arguments
from mechloop.solve.kinematics import _setup, _solve_block
from mechloop.solve.results import Results

Array = NDArray[np.float64]


@dataclass(frozen=True)
class States:
    """``S`` states solved: ``results`` over ``S·(n + 1)`` columns (state after state,
    column 0 of each the true motion, then the analogs of each input), ``broken`` ``(S,)``
    (the chain does not assemble, or a dead point), ``margin`` ``(S,)`` the least existence
    margin (−1 where broken) and ``contour`` ``(S,)`` the contour that has it."""

    results: Results
    broken: NDArray[np.bool_]
    margin: Array
    contour: NDArray[np.int64]


class StateKinematics:
    """Solve a model at states of its inputs ``inputs`` (argument numbers, in order);
    any other argument is held at its value at position 0.  ``signs``: per contour
    solved by Pl2 the sign that makes its margin positive (from a first call:
    :meth:`orient`)."""

    def __init__(self, model: Model, inputs: tuple[int, ...]):
        structure = require_valid(model)
        if structure.coupled:
            raise SolveError("a coupled block (contours solved together by Newton's "
                             "continuation) has no closed form at a free-standing state",
                             "the motion of several inputs needs contours that each "
                             "close by an elementary module")
        self.model, self.structure, self.inputs = model, structure, tuple(inputs)
        self.n = len(self.inputs)
        held = model_arguments(model, None, strict=False)
        self._held = {k: float(s.value[0]) for k, s in held.items()}
        self._kinds = {k: argument_kind(model, k) for k in model.arguments}
        self._setups: dict[int, tuple[object, dict[int, Signal]]] = {}
        self._size = 1.0
        self.signs: dict[int, float] = {}
        probe = self._setup(1)[0]
        from mechloop.solve.turns import carried_angles

        if carried_angles(structure, probe.scales):
            raise SolveError("an angle scaled by a link ratio follows its whole turns from "
                             "position to position", "the motion of several inputs "
                             "needs links of ratio 1")

    def _setup(self, columns: int):
        found = self._setups.get(columns)
        if found is None:
            signals = {k: Signal(np.zeros(columns), np.zeros(columns), np.zeros(columns))
                       for k in self.model.arguments}
            found = (_setup(self.model, self.structure, signals), signals)
            if len(self._setups) > 4:
                self._setups.pop(next(iter(self._setups)))
            self._setups[columns] = found
        return found

    def at(self, q: Array, qdot: Array) -> States:
        """The states ``q``, ``qdot``: shape ``(n,)`` or ``(S, n)`` (rad or m, per s)."""
        q = np.atleast_2d(np.asarray(q, dtype=float))
        qdot = np.atleast_2d(np.asarray(qdot, dtype=float))
        n_states, width = q.shape[0], self.n + 1
        columns = n_states * width
        setup, signals = self._setup(columns)
        eye = np.concatenate([np.zeros((1, self.n)), np.eye(self.n)])  # (n + 1, n)
        for k, signal in signals.items():
            signal.accel[:] = 0.0
            if k in self.inputs:
                i = self.inputs.index(k)
                signal.value[:] = np.repeat(q[:, i], width)
                rates = np.broadcast_to(eye[:, i], (n_states, width)).copy()
                rates[:, 0] = qdot[:, i]
                signal.rate[:] = rates.reshape(-1)
            else:
                signal.value[:] = self._held[k]
                signal.rate[:] = 0.0
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            block = _solve_block(setup, 0, columns, (columns,), {})
        shape = (columns,)
        values, rates, accels = {}, {}, {}
        for name, p in block.params.items():
            values[name] = _column(p.value, shape)
            rates[name] = _column(p.rate, shape)
            accels[name] = _column(p.accel, shape)
        broken = np.zeros(shape, dtype=bool)
        for mask in block.broken.values():
            broken |= mask
        results = Results(model=self.model, structure=self.structure, time=None,
                          arguments={k: s.value for k, s in signals.items()},
                          argument_kinds=self._kinds, values=values, rates=rates,
                          accels=accels, constant=frozenset(setup.constant), broken=broken)
        state_broken = broken.reshape(n_states, width).any(axis=1)
        margin, contour = self._margins(setup, values, n_states, width, state_broken)
        return States(results, state_broken, margin, contour)

    def orient(self, states: States) -> None:
        """Fix the signs of the Pl2 margins and the size that scales Pl1's from the
        first state of ``states`` (the start: assembled)."""
        values = states.results.values
        lengths = [abs(float(values[f"r{v}"][0])) for v in self.model.vectors]
        self._size = max(max(lengths, default=1.0), 1e-300)
        for info in self.structure.ordered():
            if info.module == "Pl2":
                m = float(contour_margins(info, {k: v[:1] for k, v in values.items()},
                                          np.ones(1))[0])
                self.signs[info.number] = 1.0 if m >= 0 else -1.0

    def _margins(self, setup, values, n_states: int, width: int, broken
                 ) -> tuple[Array, NDArray[np.int64]]:
        """The least existence margin of every state and the contour that has it."""
        firsts = {k: v[::width] for k, v in values.items()}
        rows, numbers = [], []
        for info in setup.ordered:
            with np.errstate(invalid="ignore"):
                m = contour_margins(info, firsts, np.full(n_states, self._size))
            rows.append(m * self.signs.get(info.number, 1.0) if info.module == "Pl2"
                        else m)
            numbers.append(info.number)
        if not rows:
            return np.ones(n_states), np.zeros(n_states, dtype=np.int64)
        table = np.where(np.isfinite(np.stack(rows)), np.stack(rows), -1.0)
        which = np.argmin(table, axis=0)
        margin = np.where(broken, -1.0, table[which, np.arange(n_states)])
        return margin, np.asarray(numbers, dtype=np.int64)[which]


def _column(x, shape: tuple[int]) -> Array:
    """``x`` (a solved array, or a constant's scalar) as an array of ``shape``."""
    if isinstance(x, np.ndarray) and x.shape == shape:
        return x
    return np.full(shape, x, dtype=float)
