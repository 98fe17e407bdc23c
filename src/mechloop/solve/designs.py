"""Many candidate designs of one model solved in one vectorized call: arrays ``(D, P)``.

A *design* replaces some constants of the model — constant lengths and angles, link
deltas, argument offsets — by its own values.  Everything else (the contours, the
arguments, the time) is shared, so the whole population goes through the elementary
modules at once, with designs on the leading axis and positions on the last
(STYLE §2).  This is what synthesis evaluates; :func:`mechloop.solve` is the same
computation for one design.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.errors import SolveError
from mechloop.model.check import require_valid
from mechloop.model.schema import Model
from mechloop.solve.inputs import model_arguments, model_time
from mechloop.solve.kinematics import _finish_angles, _setup, _solve_block

Array = NDArray[np.float64]

#: Designs × positions solved together: keeps a chunk's temporaries a few MB.
CHUNK_ELEMENTS = 1 << 16


@dataclass(frozen=True)
class DesignResults:
    """Every parameter of every design at every position.

    ``values``, ``rates`` and ``accels`` map a parameter name to an array shaped
    ``(D, P)`` in SI (m, rad; per second, or per unit of argument 1 without model time).
    Broken positions are NaN and marked in ``broken``; ``no_solution`` and ``dead`` say
    per contour where it has no real solution or a singular Jacobian; ``branch_changes``
    per contour and design whether the assembly branch (the sign of the loop's Jacobian)
    changes between positions where it is regular.
    """

    model: Model
    arguments: dict[int, Array]
    time: Array | None
    values: dict[str, Array]
    rates: dict[str, Array]
    accels: dict[str, Array]
    broken: NDArray[np.bool_]
    no_solution: dict[int, NDArray[np.bool_]]
    dead: dict[int, NDArray[np.bool_]]
    branch_changes: dict[int, NDArray[np.bool_]]

    @property
    def designs(self) -> int:
        return self.broken.shape[0]

    @property
    def assembles(self) -> NDArray[np.bool_]:
        """Designs with a regular solution at every position, shape ``(D,)``."""
        return ~self.broken.any(axis=-1)

    @property
    def keeps_variant(self) -> NDArray[np.bool_]:
        """Designs whose every contour stays on one assembly branch, shape ``(D,)``."""
        keeps = np.ones(self.designs, dtype=bool)
        for changes in self.branch_changes.values():
            keeps &= ~changes
        return keeps

    def subset(self, rows: NDArray[np.int64]) -> DesignResults:
        """The designs ``rows`` only (arrays ``(len(rows), P)``)."""
        return DesignResults(
            model=self.model, arguments=self.arguments, time=self.time,
            values={k: v[rows] for k, v in self.values.items()},
            rates={k: v[rows] for k, v in self.rates.items()},
            accels={k: v[rows] for k, v in self.accels.items()},
            broken=self.broken[rows],
            no_solution={k: v[rows] for k, v in self.no_solution.items()},
            dead={k: v[rows] for k, v in self.dead.items()},
            branch_changes={k: v[rows] for k, v in self.branch_changes.items()})

    def point(self, vectors: list[int] | tuple[int, ...]) -> tuple[Array, Array]:
        """x, y (m), shape ``(D, P)``, of the end of ``vectors`` laid end to end from the
        origin."""
        x = sum(self.values[f"r{n}"] * np.cos(self.values[f"a{n}"]) for n in vectors)
        y = sum(self.values[f"r{n}"] * np.sin(self.values[f"a{n}"]) for n in vectors)
        return np.asarray(x), np.asarray(y)


def solve_designs(model: Model, overrides: Mapping[str, ArrayLike], *,
                  chunk_elements: int = CHUNK_ELEMENTS) -> DesignResults:
    """Solve ``D`` designs of ``model`` at every position in one vectorized pass.

    ``overrides`` maps parameter names (``'r3'``, ``'a5'``) to SI values shaped ``(D,)``:
    for a constant parameter its value (m or rad), for a link its own delta, for a
    driven parameter its offset.  Every override has the same length ``D``.

    Returns :class:`DesignResults` with arrays shaped ``(D, P)``, ``P = N + 1``.
    """
    structure = require_valid(model)
    over = {name: np.atleast_1d(np.asarray(v, dtype=float)) for name, v in overrides.items()}
    sizes = {v.shape for v in over.values()}
    if len(sizes) > 1 or any(len(s) != 1 for s in sizes):
        raise SolveError("every varied parameter needs one value per design",
                         f"pass 1-D arrays of one length (got shapes {sorted(sizes)})")
    n_designs = next(iter(sizes))[0] if sizes else 1
    n_pos = model.positions + 1
    time = model_time(model)
    args = model_arguments(model, time)
    chunk = max(1, int(chunk_elements) // n_pos)

    setup = _setup(model, structure, args, over)
    names = [f"{letter}{n}" for n in sorted(model.vectors) for letter in "ra"]
    values = {name: np.empty((n_designs, n_pos)) for name in names}
    rates = {name: np.empty((n_designs, n_pos)) for name in names}
    accels = {name: np.empty((n_designs, n_pos)) for name in names}
    numbers = [c.number for c in setup.ordered]
    no_solution = {c: np.zeros((n_designs, n_pos), dtype=bool) for c in numbers}
    dead = {c: np.zeros((n_designs, n_pos), dtype=bool) for c in numbers}
    changes = {c: np.zeros(n_designs, dtype=bool) for c in numbers}

    for lo in range(0, n_designs, chunk):
        hi = min(lo + chunk, n_designs)
        shape = (hi - lo, n_pos)
        part = _setup(model, structure, args, {k: v[lo:hi] for k, v in over.items()})
        block = _solve_block(part, 0, n_pos, shape, {})
        for c in numbers:
            no_solution[c][lo:hi] = block.no_solution[c]
            dead[c][lo:hi] = block.dead[c]
            branch = block.branch[c]
            changes[c][lo:hi] = (branch.max(axis=-1) > 0) & (branch.min(axis=-1) < 0)
        for name in names:
            p = block.params[name]
            values[name][lo:hi] = np.broadcast_to(p.value, shape)
            rates[name][lo:hi] = np.broadcast_to(p.rate, shape)
            accels[name][lo:hi] = np.broadcast_to(p.accel, shape)

    broken = np.zeros((n_designs, n_pos), dtype=bool)
    for c in numbers:
        broken |= no_solution[c] | dead[c]
    _finish_angles(setup, {name: values[name] for name in setup.varying})
    for name in setup.varying:
        for arr in (values[name], rates[name], accels[name]):
            arr[broken] = np.nan
    return DesignResults(
        model=model,
        arguments={k: s.value for k, s in args.items()},
        time=None if time is None else time.value,
        values=values,
        rates=rates,
        accels=accels,
        broken=broken,
        no_solution=no_solution,
        dead=dead,
        branch_changes=changes,
    )
