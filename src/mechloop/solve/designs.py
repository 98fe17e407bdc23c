"""Many candidate designs of one model solved in one vectorized call: arrays ``(D, P)``.

A *design* replaces some constants of the model — constant lengths and angles, link
deltas, argument offsets — by its own values.  Everything else (the contours, the
arguments, the time) is shared, so the whole population goes through the elementary
modules at once, with designs on the leading axis and positions on the last
(STYLE §2).  This is what synthesis evaluates; :func:`mechloop.solve` is the same
computation for one design.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.errors import SolveError
from mechloop.model.check import require_valid
from mechloop.model.schema import Model
from mechloop.solve.inputs import Signal, model_arguments, model_time
from mechloop.solve.kinematics import _finish_angles, _setup, _solve_block
from mechloop.solve.memory import require_memory

Array = NDArray[np.float64]

#: Designs × positions solved together: keeps a chunk's temporaries a few MB.
CHUNK_ELEMENTS = 1 << 16


class NotSolved(Mapping[str, Array]):
    """The rates or the accelerations of a position-only solve
    (``solve_designs(..., derivatives=False)``): any look-up raises :class:`SolveError`
    instead of giving numbers that were never computed."""

    def __init__(self, what: str):
        self.what = what

    def _refuse(self) -> SolveError:
        return SolveError(f"the {self.what} were not solved: these results come from "
                          "solve_designs(..., derivatives=False), which solves positions "
                          "only", "call solve_designs(..., derivatives=True)")

    def __getitem__(self, name: str) -> Array:
        raise self._refuse()

    def __iter__(self) -> Iterator[str]:
        raise self._refuse()

    def __len__(self) -> int:
        raise self._refuse()

    def __repr__(self) -> str:
        return f"NotSolved({self.what!r})"


@dataclass(frozen=True)
class DesignResults:
    """Every parameter of every design at every position.

    ``values``, ``rates`` and ``accels`` map a parameter name to an array shaped
    ``(D, P)`` in SI (m, rad; per second, or per unit of argument 1 without model time).
    Broken positions are NaN and marked in ``broken``; ``no_solution`` and ``dead`` say
    per contour where it has no real solution or a singular Jacobian (a position where
    floating point overflowed is broken too, in neither); ``branch_changes``
    per contour and design whether the assembly branch (the sign of the loop's Jacobian)
    changes between positions where it is regular.  Parameters that stay constant
    (constants and links of constants) are read-only broadcast views: their values, and
    their rates and accelerations (zeros).

    After a position-only solve (``derivatives=False``) ``rates`` and ``accels`` are
    :class:`NotSolved`: looking anything up in them raises :class:`SolveError`; see
    :attr:`derivatives`.

    ``positions`` is None when every position 0..N was solved; after
    ``solve_designs(..., positions=...)`` it holds the position numbers of the columns,
    shape ``(P,)``, and every mask and ``branch_changes`` speak of those columns only.
    """

    def columns(self, positions: NDArray[np.int64]) -> NDArray[np.int64]:
        """The columns of the tables that hold the model's ``positions`` (each must have
        been solved)."""
        if self.positions is None:
            return positions
        found = np.searchsorted(self.positions, positions)
        found = np.minimum(found, self.positions.size - 1)
        if not np.array_equal(self.positions[found], positions):
            raise SolveError(f"positions {sorted(set(positions) - set(self.positions))} "
                             "were not solved", "solve them: solve_designs(..., "
                             "positions=...)")
        return found

    model: Model
    arguments: dict[int, Array]
    time: Array | None
    values: dict[str, Array]
    rates: Mapping[str, Array]
    accels: Mapping[str, Array]
    broken: NDArray[np.bool_]
    no_solution: dict[int, NDArray[np.bool_]]
    dead: dict[int, NDArray[np.bool_]]
    branch_changes: dict[int, NDArray[np.bool_]]
    positions: NDArray[np.int64] | None = None

    @property
    def designs(self) -> int:
        return self.broken.shape[0]

    @property
    def derivatives(self) -> bool:
        """Whether ``rates`` and ``accels`` were solved (False after a position-only
        solve)."""
        return not isinstance(self.rates, NotSolved)

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
            values={k: _rows(v, rows) for k, v in self.values.items()},
            rates=({k: _rows(v, rows) for k, v in self.rates.items()}
                   if self.derivatives else self.rates),
            accels=({k: _rows(v, rows) for k, v in self.accels.items()}
                    if self.derivatives else self.accels),
            broken=self.broken[rows],
            no_solution={k: v[rows] for k, v in self.no_solution.items()},
            dead={k: v[rows] for k, v in self.dead.items()},
            branch_changes={k: v[rows] for k, v in self.branch_changes.items()},
            positions=self.positions)


def solve_designs(model: Model, overrides: Mapping[str, ArrayLike], *,
                  derivatives: bool = True, positions: ArrayLike | None = None,
                  chunk_elements: int = CHUNK_ELEMENTS,
                  analogs_of: int | None = None) -> DesignResults:
    """Solve ``D`` designs of ``model`` at every position in one vectorized pass.

    ``overrides`` maps parameter names (``'r3'``, ``'a5'``) to SI values shaped ``(D,)``:
    for a constant parameter its value (m or rad), for a link its own delta, for a
    driven parameter its offset.  Every override has the same length ``D``.

    With ``derivatives=False`` only positions are solved: ``values``, ``broken``,
    ``no_solution``, ``dead`` and ``branch_changes`` are exactly those of
    ``derivatives=True`` (the same arithmetic, the velocity and acceleration solves
    left out), and ``rates`` and ``accels`` are :class:`NotSolved`, which raise
    :class:`SolveError` on any look-up.  Synthesis solves so when no criterion reads a
    rate or an acceleration.

    With ``positions`` (increasing position numbers, shape ``(P,)``) only those positions
    are solved — each by the same closed-form arithmetic as in a solve of all of them —
    and the tables have one column per position given (``DesignResults.positions``):
    synthesis evaluates so when its objective reads the target positions only.  The
    positions need not be neighbours, so the angles found are not unwrapped: each lies
    in (−π, π] (plus its link's delta), the same direction as in a solve of all.  A
    contour whose variant is tracked (``auto``) follows its neighbours, and so does a
    coupled block (Newton's continuation), so such a model cannot be solved at some
    positions only (:class:`SolveError`).

    With ``analogs_of=k`` the derivatives are the analogs with respect to argument ``k``
    alone, as ``solve(model, analogs_of=k)`` gives them: its rate 1 and acceleration 0,
    every other argument held, no time.

    Returns :class:`DesignResults` with arrays shaped ``(D, P)``, ``P = N + 1``.
    """
    from mechloop.model.spatial import is_spatial, refuse_spatial

    if is_spatial(model) and positions is None:  # issue 17: mechloop.spatial.solve
        from mechloop.spatial.solve import solve_spatial_designs

        return solve_spatial_designs(model, require_valid(model), dict(overrides),
                                     analogs_of=analogs_of)
    refuse_spatial(model, "solving chosen positions of many designs")
    regular, _ = _solve(model, overrides, None, derivatives=derivatives,
                        chunk_elements=chunk_elements, positions=_chosen(model, positions),
                        analogs_of=analogs_of)
    return regular


def _chosen(model: Model, positions: ArrayLike | None) -> NDArray[np.int64] | None:
    """``positions`` checked: increasing position numbers of the model, and no tracked
    variant (:class:`SolveError` otherwise)."""
    if positions is None:
        return None
    chosen = np.asarray(positions, dtype=np.int64).reshape(-1)
    if chosen.size == 0 or (np.diff(chosen) <= 0).any() or chosen[0] < 0 \
            or chosen[-1] > model.positions:
        raise SolveError(f"positions must increase within 0..{model.positions}",
                         "pass sorted, distinct position numbers")
    if any(c.variant == "auto" for c in model.contours):
        raise SolveError("a contour with variant auto follows its neighbours: it is "
                         "solved at every position", "give its variant as 1 or 2")
    if require_valid(model).coupled:
        raise SolveError("a coupled block is continued from position to position: it is "
                         "solved at every position", "solve every position (positions=None)")
    from mechloop.solve.turns import carried_angles

    structure = require_valid(model)
    carried = carried_angles(structure, {n: c.scale for n, c in structure.links.items()})
    if carried:
        raise SolveError(f"{', '.join(sorted(carried))} is scaled by a link ratio, so its "
                         "whole turns are followed from position to position: it is "
                         "solved at every position", "solve every position (positions=None)")
    return chosen


def solve_designs_at(model: Model, overrides: Mapping[str, ArrayLike], inputs: ArrayLike,
                     *, derivatives: bool = True, positions: ArrayLike | None = None,
                     chunk_elements: int = CHUNK_ELEMENTS
                     ) -> tuple[DesignResults, DesignResults]:
    """:func:`solve_designs`, and each design also at its own ``K`` values of argument 1.

    ``inputs`` : shape ``(D, K)``, SI (rad or m) — per design, the values of argument 1
    (its offsets not included) at which to solve besides the model's positions: free
    timing in path synthesis.  They are solved in the same vectorized call, as ``K``
    extra columns of the position axis, by the same closed-form modules; any other
    argument takes there its value interpolated over argument 1 along the positions
    (which then must run monotonically).

    Returns ``(regular, at)``: ``regular`` is exactly what :func:`solve_designs` returns
    (arrays ``(D, P)``); ``at`` holds the positions only (``rates`` and ``accels`` are
    :class:`NotSolved`), arrays ``(D, K)``, with ``arguments[1]`` the inputs, its masks
    at those inputs, and as ``branch_changes`` per contour whether the assembly branch at
    any input differs from the branch of the regular positions.  With a tracked variant
    (``auto``) the extra columns would follow the last position rather than their own
    place in the motion: give such contours a fixed variant.  ``positions`` restricts the
    regular positions as in :func:`solve_designs`.
    """
    from mechloop.model.spatial import refuse_spatial

    refuse_spatial(model, "solving many designs at once")
    values = np.asarray(inputs, dtype=float)
    if values.ndim != 2:
        raise SolveError(f"inputs need the shape (D, K), got {values.shape}",
                         "pass one row of argument values per design")
    return _solve(model, overrides, values, derivatives=derivatives,
                  chunk_elements=chunk_elements, positions=_chosen(model, positions))


def _solve(model: Model, overrides: Mapping[str, ArrayLike], inputs: Array | None, *,
           derivatives: bool, chunk_elements: int,
           positions: NDArray[np.int64] | None = None, analogs_of: int | None = None
           ) -> tuple[DesignResults, DesignResults | None]:
    """The regular positions (or ``positions`` only), and with ``inputs`` ``(D, K)`` the
    extra columns too; the analogs of argument ``analogs_of`` as derivatives if given."""
    structure, time, args = _prepared(model)
    if analogs_of is not None:  # as solve(model, analogs_of=k)
        n_pos = model.positions + 1
        args = {k: Signal(s.value, np.full(n_pos, float(k == analogs_of)), np.zeros(n_pos))
                for k, s in model_arguments(model, time, strict=False).items()}
        time = None
    over = {name: np.atleast_1d(np.asarray(v, dtype=float)) for name, v in overrides.items()}
    sizes = {v.shape for v in over.values()}
    if len(sizes) > 1 or any(len(s) != 1 for s in sizes):
        raise SolveError("every varied parameter needs one value per design",
                         f"pass 1-D arrays of one length (got shapes {sorted(sizes)})")
    n_designs = next(iter(sizes))[0] if sizes else 1
    require_memory(model, designs=max(n_designs, 1 if inputs is None else inputs.shape[0]))
    n_pos = model.positions + 1
    every = args  # the extra inputs interpolate over every position
    if positions is not None:
        args = {k: Signal(s.value[positions], s.rate[positions], s.accel[positions])
                for k, s in args.items()}
        time = None if time is None else Signal(time.value[positions],
                                                time.rate[positions], time.accel[positions])
        n_pos = positions.size
    full = (n_designs, n_pos)
    n_extra = 0
    if inputs is not None:
        if not sizes:
            n_designs = inputs.shape[0]
            full = (n_designs, n_pos)
        if inputs.shape[0] != n_designs or 1 not in args:
            raise SolveError(f"inputs need one row per design ({n_designs}) and a model "
                             "with argument 1", f"got inputs of shape {inputs.shape}")
        n_extra = inputs.shape[1]
        extra_at = _extra_arguments(every, inputs)
    n_cols = n_pos + n_extra
    chunk = max(1, int(chunk_elements) // n_cols)

    setup = _setup(model, structure, args, over)
    names = [f"{letter}{n}" for n in sorted(model.vectors) for letter in "ra"]
    # Parameters that no design changes over positions are broadcast, not copied: a
    # constant, or a link of one, is its root's value plus the link's delta.
    values: dict[str, Array] = {}
    extra: dict[str, Array] = {}
    for name in names:
        if name in setup.constant:
            root = structure.links[name].root if name in structure.links else name
            value = (setup.constants[name] if name == root
                     else setup.link_value(name, setup.constants[root]))
            values[name] = np.broadcast_to(value, full)
            extra[name] = np.broadcast_to(value, (n_designs, n_extra))
    still = np.broadcast_to(0.0, full)
    rates = {name: still for name in values}
    accels = dict(rates)
    for name in setup.varying:
        values[name] = np.empty(full)
        extra[name] = np.empty((n_designs, n_extra))
        if derivatives:
            rates[name], accels[name] = np.empty(full), np.empty(full)
    values = {name: values[name] for name in names}
    extra = {name: extra[name] for name in names}
    numbers = [c.number for c in setup.ordered]
    no_solution = {c: np.zeros(full, dtype=bool) for c in numbers}
    dead = {c: np.zeros(full, dtype=bool) for c in numbers}
    changes = {c: np.zeros(n_designs, dtype=bool) for c in numbers}
    extra_none = {c: np.zeros((n_designs, n_extra), dtype=bool) for c in numbers}
    extra_dead = {c: np.zeros((n_designs, n_extra), dtype=bool) for c in numbers}
    extra_changes = {c: np.zeros(n_designs, dtype=bool) for c in numbers}

    for lo in range(0, n_designs, chunk):
        hi = min(lo + chunk, n_designs)
        shape = (hi - lo, n_cols)
        part = (setup if hi - lo == n_designs else  # one chunk: the setup of all
                _setup(model, structure, args, {k: v[lo:hi] for k, v in over.items()}))
        if n_extra:
            part = _with_extra_columns(part, args, extra_at, lo, hi)
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # see below
            block = _solve_block(part, 0, n_cols, shape, {}, derivatives=derivatives)
        for c in numbers:
            no_solution[c][lo:hi] = block.no_solution[c][:, :n_pos]
            dead[c][lo:hi] = block.dead[c][:, :n_pos]
            branch = block.branch[c][:, :n_pos]
            changes[c][lo:hi] = (branch.max(axis=-1) > 0) & (branch.min(axis=-1) < 0)
            if n_extra:
                extra_none[c][lo:hi] = block.no_solution[c][:, n_pos:]
                extra_dead[c][lo:hi] = block.dead[c][:, n_pos:]
                at = block.branch[c][:, n_pos:]
                extra_changes[c][lo:hi] = ((at.max(axis=-1) > 0) & (branch.min(axis=-1) < 0)
                                           | (at.min(axis=-1) < 0)
                                           & (branch.max(axis=-1) > 0))
        for name in setup.varying:
            p = block.params[name]
            values[name][lo:hi] = p.value[..., :n_pos]
            if n_extra:
                extra[name][lo:hi] = p.value[..., n_pos:]
            if derivatives:
                rates[name][lo:hi] = p.rate[..., :n_pos]
                accels[name][lo:hi] = p.accel[..., :n_pos]

    broken = np.zeros(full, dtype=bool)
    for c in numbers:
        broken |= no_solution[c]
        broken |= dead[c]
    clock = [] if time is None else [time.value]
    inputs_of = [*clock, *(f for s in args.values() for f in (s.value, s.rate, s.accel))]
    _mark_overflow(broken, [*inputs_of, *(table[name] for name in setup.varying for table in (
        (values, rates, accels) if derivatives else (values,)))])
    if positions is None:  # chosen positions need not be neighbours: angles stay wrapped
        _finish_angles(setup, {name: values[name] for name in setup.varying})
    if broken.any():
        for name in setup.varying:
            for table in (values, rates, accels) if derivatives else (values,):
                np.copyto(table[name], np.nan, where=broken)
    regular = DesignResults(
        model=model,
        arguments={k: s.value for k, s in args.items()},
        time=None if time is None else time.value,
        values=values,
        rates=rates if derivatives else NotSolved("rates"),
        accels=accels if derivatives else NotSolved("accelerations"),
        broken=broken,
        no_solution=no_solution,
        dead=dead,
        branch_changes=changes,
        positions=positions,
    )
    if inputs is None:
        return regular, None
    extra_broken = np.zeros((n_designs, n_extra), dtype=bool)
    for c in numbers:
        extra_broken |= extra_none[c] | extra_dead[c]
    _mark_overflow(extra_broken, [extra[name] for name in setup.varying])
    _finish_angles(setup, {name: extra[name] for name in setup.varying})
    for name in setup.varying:
        np.copyto(extra[name], np.nan, where=extra_broken)
    at_inputs = DesignResults(
        model=model, arguments=extra_at, time=None, values=extra,
        rates=NotSolved("rates"), accels=NotSolved("accelerations"), broken=extra_broken,
        no_solution=extra_none, dead=extra_dead, branch_changes=extra_changes)
    return regular, at_inputs


#: Recently solved models (by identity; a model is frozen) -> (the model, its structure,
#: time and arguments): a population solved generation after generation checks and
#: tabulates its model once.
_PREPARED: dict[int, tuple[Model, object, Signal | None, dict[int, Signal]]] = {}


def _prepared(model: Model):
    """``(structure, time, arguments)`` of ``model``, computed once per model object."""
    found = _PREPARED.get(id(model))
    if found is None or found[0] is not model:
        structure = require_valid(model)
        time = model_time(model)
        found = (model, structure, time, model_arguments(model, time))
        if len(_PREPARED) >= 16:
            _PREPARED.pop(next(iter(_PREPARED)))
        _PREPARED[id(model)] = found
    return found[1:]


def _mark_overflow(broken: NDArray[np.bool_], arrays: list[Array]) -> None:
    """Mark broken, as :func:`mechloop.solve.solve` does, the positions where one of
    ``arrays`` (broadcast to ``broken``'s shape) is not finite: floating point overflowed
    (a dimension, an input or a speed too large), so no row not marked broken holds a
    non-number.  One pass per array when everything is finite."""
    for arr in arrays:
        finite = np.isfinite(arr)
        if not finite.all():
            broken |= ~np.broadcast_to(finite, broken.shape)


def _extra_arguments(args: Mapping[int, Signal], inputs: Array) -> dict[int, Array]:
    """Every argument at the extra inputs, SI, ``(D, K)``: argument 1 is ``inputs``, any
    other is interpolated over argument 1 along the positions."""
    out = {1: inputs}
    first = args[1].value
    order = np.argsort(first, kind="stable")
    for number, signal in args.items():
        if number != 1:
            out[number] = np.interp(inputs, first[order], signal.value[order])
    return out


def _with_extra_columns(part, args: Mapping[int, Signal], extra_at: Mapping[int, Array],
                        lo: int, hi: int):
    """``part`` with every driven parameter extended by the extra columns: the argument's
    signal gets zeros there (and no rates), and the per-design argument values enter
    through the offset, ``(rows, P + K)``."""
    driven = {}
    for name, (signal, offset) in part.driven.items():
        number = next(k for k, s in args.items() if s is signal)
        n_pos = signal.value.shape[-1]
        at = extra_at[number][lo:hi]
        pad = np.zeros(at.shape[-1])
        longer = Signal(np.concatenate([signal.value, pad]),
                        np.concatenate([signal.rate, pad]),
                        np.concatenate([signal.accel, pad]))
        shift = np.concatenate([np.zeros((at.shape[0], n_pos)), at], axis=-1)
        driven[name] = (longer, offset + shift)
    return replace(part, driven=driven, n_regular=args[1].value.shape[-1],
                   extra_start=_nearest(args[1].value, extra_at[1][lo:hi]))


def _nearest(x: Array, inputs: Array) -> NDArray[np.int64]:
    """The position nearest to each input by argument 1's value ``x`` ``(P,)``: where a
    coupled block starts Newton's method for an extra column, ``(D, K)``."""
    if x.size == 0:
        return np.zeros(inputs.shape, dtype=np.int64)
    order = np.argsort(x, kind="stable")
    at = np.clip(np.searchsorted(x[order], inputs), 1, max(x.size - 1, 1))
    below = order[at - 1]
    above = order[np.minimum(at, x.size - 1)]
    closer = np.abs(x[below] - inputs) <= np.abs(x[above] - inputs)
    return np.where(closer, below, above).astype(np.int64)


def _rows(table: Array, rows: NDArray[np.int64]) -> Array:
    """Rows ``rows`` of a ``(D, P)`` table; a broadcast table stays a broadcast view."""
    if table.strides[0] == 0 or table.strides[-1] == 0:
        return np.broadcast_to(table[rows[:1] if table.strides[0] == 0 else rows, :1],
                               (len(rows), table.shape[-1]))
    return table[rows]
