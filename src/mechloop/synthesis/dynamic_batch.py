"""Dynamic columns of a whole population of designs in one vectorized pass: ``(D, P)``.

The columns are those of ``solve_dynamics(problem.design_model(d)).to_frame()`` of every
design ``d``, computed by the same force analysis
(:func:`~mechloop.dynamics.analysis.analyze`) for all designs at once: the population is
laid out on one long axis of designs × positions by
:func:`~mechloop.dynamics.population.solve_population` (each design's friction iterated
on its own, each design's cycle), and the table is cut back into ``(D, P)`` rows.  The
mechanism every design shares (bodies, pairs, drives) is compiled once from a reference
design: the model's own, or the first one of the population that assembles.  The cycle's
numbers (``efficiency``, ``loss_coefficient``, and of a machine model ``delta``,
``flywheel``, ``constant_load``) come out one per design.

:func:`dynamic_columns` is the fast path; ``solve_dynamics(problem.design_model(d))`` per
design is its oracle (tests/test_dynamic_batch.py).  A caller keeps a fallback to that
loop for what a batch may refuse with :class:`NotImplementedError` (today nothing does).
"""

from __future__ import annotations

from collections.abc import Iterable
from weakref import WeakKeyDictionary

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.analysis import DynamicResults, compile_mechanism
from mechloop.dynamics.mechanism import Mechanism
from mechloop.dynamics.population import solve_population
from mechloop.model.schema import Model
from mechloop.model.synthesis import CYCLE_VALUES
from mechloop.solve.designs import DesignResults, solve_designs
from mechloop.solve.results import Results

Array = NDArray[np.float64]

#: The mechanism of each problem's own design (the model is frozen): compiled once.
_OWN: WeakKeyDictionary = WeakKeyDictionary()

#: What needs the flywheel of a machine model: a root per design (``brentq``), solved only
#: when asked for.  A machine that runs without it runs with it, so leaving it out changes
#: no other column and fails no design.
FLYWHEEL_VALUES = frozenset({"omega_fw", "epsilon_fw", "flywheel"})
#: What needs the work over the cycle (the summary), computed only when asked for.
SUMMARY_VALUES = frozenset(name for name, path in CYCLE_VALUES.items()
                           if path.startswith("summary."))


def dynamic_columns(problem, designs: Array, columns: Iterable[str], *,
                    kinematics: DesignResults | None = None) -> dict[str, Array]:
    """The dynamic columns ``columns`` of every design, one pass over designs × positions.

    ``problem`` is a :class:`~mechloop.synthesis.problem.SynthesisProblem`; ``designs``
    are SI values shaped ``(D, V)`` in the order of ``problem.variables.names``;
    ``columns`` are names of ``solve_dynamics(model).to_frame()`` without the unit suffix
    (``'F_bal'``, ``'M_bal'``, ``'M_bal_vp'``, ``'RJ0_2'``, ``'RA_to_a2'``, ``'xS1'``,
    ``'T'``, and of a machine model ``'omega'``, ``'epsilon_fw'``, ...) or the cycle's
    numbers ``'efficiency'``, ``'loss_coefficient'``, and of a machine model ``'delta'``,
    ``'flywheel'``, ``'constant_load'`` (:data:`~mechloop.model.synthesis.CYCLE_VALUES`).
    Units are those of the table (SI; reaction angles in degrees).

    Returns ``{column: array (D, P)}``, equal to
    ``solve_dynamics(problem.design_model(d)).to_frame()[column]`` row by row: NaN at the
    positions where a design's chain breaks (so a row of NaN for a design that breaks
    everywhere) or its force system is singular; a cycle's number is an array ``(D,)``
    equal to :func:`cycle_value` of ``solve_dynamics(...)`` (NaN without driving work,
    and a machine's number NaN without ``machine:`` or, for ``flywheel``, its ``delta``).
    A design whose own solve raises :class:`~mechloop.errors.SolveError` — its friction
    does not settle, or the cycle of a machine model cannot be computed (the chain breaks
    somewhere, the input does not advance, the machine stops) — is NaN in every column.

    Raises :class:`KeyError` for a column the model's table does not have and
    :class:`~mechloop.errors.ModelError` for a machine model without one input or a
    model time (as ``solve_dynamics``).
    """
    model: Model = problem.model
    designs = np.atleast_2d(np.asarray(designs, dtype=float))
    wanted = list(dict.fromkeys(columns))
    n_designs, n_pos = designs.shape[0], model.positions + 1
    if n_designs == 0:
        return {name: np.empty((0,) if name in CYCLE_VALUES else (0, n_pos))
                for name in wanted}
    overrides = problem.variables.overrides(designs)
    kin_designs = kinematics
    if kin_designs is None or not kin_designs.derivatives:
        kin_designs = solve_designs(model, overrides, derivatives=True)
    elif kin_designs.broken.shape != (n_designs, n_pos):
        raise ValueError(f"kinematics are shaped {kin_designs.broken.shape}, the designs "
                         f"{(n_designs, n_pos)}: pass the solve of these designs")
    reference, mechanism = _reference(problem, designs, kin_designs.assembles)
    flat = solve_population(model, overrides, reference, mechanism,
                            starts=problem.variables.starts(designs),
                            kinematics=kin_designs,
                            flywheel=bool(FLYWHEEL_VALUES.intersection(wanted)),
                            summary=bool(SUMMARY_VALUES.intersection(wanted)))
    table = _frame(flat, [c for c in wanted if c not in CYCLE_VALUES])
    out = {name: np.array(table[name].reshape(n_designs, n_pos)) for name in table}
    for name in (c for c in wanted if c in CYCLE_VALUES):
        out[name] = np.array(np.broadcast_to(cycle_value(flat, name), (n_designs,)),
                             dtype=float)
    failed = flat.forces.unsettled.reshape(n_designs, n_pos).any(axis=1)
    if flat.cycle is not None:
        failed |= ~flat.cycle.computed
    for values in out.values():  # its own solve raises: no number of this design
        values[failed] = np.nan
    return {name: out[name] for name in wanted}


def cycle_value(result, name: str) -> float | Array:
    """The number ``name`` of :data:`~mechloop.model.synthesis.CYCLE_VALUES` of a solved
    model (:class:`DynamicResults`; or of a stack of designs, an array ``(D,)``): the
    field its dotted path names, NaN where a step is missing (a model without
    ``machine:``, a machine without ``delta`` has no ``flywheel``)."""
    value = result
    for step in CYCLE_VALUES[name].split("."):
        value = getattr(value, step, None) if value is not None else None
    return np.nan if value is None else value


def _reference(problem, designs: Array, assembles: NDArray[np.bool_]
               ) -> tuple[Results, Mechanism]:
    """The kinematics and mechanism of one design that assembles at every position (the
    model's own if it does, else the first such design of the population): the
    mechanism every design shares and the vectors that end at each pair."""
    own = _OWN.get(problem)
    if own is None:
        kin, _, mechanism = compile_mechanism(problem.model)
        own = _OWN[problem] = (kin, mechanism)
    if not own[0].broken.any() or not assembles.any():
        return own
    kin, _, mechanism = compile_mechanism(problem.design_model(
        designs[int(np.argmax(assembles))]))
    return kin, mechanism


def _frame(flat: DynamicResults, wanted: list[str]) -> dict[str, Array]:
    """The requested columns of :meth:`DynamicResults.to_frame` of the long axis, by bare
    name (``(D·P,)`` each).  A reaction-angle column names the vectors that end at the
    pair in every design (where each is known)."""
    frame = flat.to_frame()
    by_name = {c.split(" [")[0]: c for c in frame.columns}
    missing = [c for c in wanted if c not in by_name]
    if missing:
        raise KeyError(f"no column {', '.join(map(repr, missing))} in the dynamic table "
                       f"of this model (columns: {', '.join(sorted(by_name))})")
    return {name: frame[by_name[name]].to_numpy(dtype=float) for name in wanted}


__all__ = ["cycle_value", "dynamic_columns"]
