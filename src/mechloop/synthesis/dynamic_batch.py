"""Dynamic columns of a whole population of designs in one vectorized pass: ``(D, P)``.

The force analysis of :func:`~mechloop.dynamics.analysis.solve_dynamics` is independent
from position to position and works on arrays over positions.  ``D`` designs × ``P``
positions of one model are therefore solved as ``D·P`` "positions" of one long axis: the
kinematics (and the analogs of every drive) of the population come from
:func:`~mechloop.solve.designs.solve_designs`-style solves shaped ``(D, P)`` and are
flattened into one :class:`~mechloop.solve.results.Results` in which every parameter —
constants included, since they differ between designs — is a ``(D·P,)`` array; loads,
time and masses are tiled.  :class:`~mechloop.dynamics.points.Placement` then places the
contours (a varied fixed start ``startK.x/y`` is one value per design),
:func:`~mechloop.dynamics.kinetostatics.kinetostatics` does one batched linear solve
``(D·P, K, K)``, and the table is cut back into ``(D, P)`` rows.  Friction in the pairs
is iterated with each design as its own segment of the long axis (its own tolerance and
stop, frozen once settled), so each design's reactions are those of its own iterations; a
design whose friction does not settle gets NaN, as its own solve would raise.  The cycle's
numbers (``efficiency``, ``loss_coefficient``) come from
:func:`~mechloop.dynamics.energy.summarize` of the ``(D, P)`` powers, one per design.  A
machine model (``machine:``) adds the steady cycle of every design from its ``(D, P)``
reduced characteristics in one call of :func:`~mechloop.dynamics.cycle.steady_cycles`: the
speed columns (``omega``, ``epsilon``, ``omega_fw``, ``epsilon_fw``) and the numbers
``delta``, ``flywheel`` and ``constant_load``; a design whose cycle cannot be computed (its
chain breaks somewhere, the machine stops) is NaN in every column, as its own solve raises.

What is the same for every design is compiled once from a reference design (the model's
own, or the first one of the population that assembles): the bodies, the kinematic pairs
(inferred or named) and the drives.  These follow from the roles of the vectors, not from
their values, except at degenerate designs (two pins made to coincide); a moment of
inertia ``rod`` is the one mass property that depends on a design (its length) and is
computed per design.

:func:`dynamic_columns` is the fast path; ``solve_dynamics(problem.design_model(d))`` per
design is its oracle (tests/test_dynamic_batch.py).  A caller keeps a fallback to that
loop for what a batch may refuse with :class:`NotImplementedError` (today nothing does).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from weakref import WeakKeyDictionary

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.analysis import (
    DynamicResults,
    _argument_rate,
    check_machine,
    cycle_clock,
    load_powers,
    mass_terms,
    solve_dynamics,
)
from mechloop.dynamics.cycle import Cycle, steady_cycles
from mechloop.dynamics.energy import summarize
from mechloop.dynamics.kinetostatics import kinetostatics
from mechloop.dynamics.loads import Couple, Loads, PointForce, _values
from mechloop.dynamics.mechanism import Mass, Mechanism, _point_vector
from mechloop.dynamics.points import Motion, Placement
from mechloop.dynamics.reduced import Reduced, balancing_by_virtual_power, reduced
from mechloop.errors import ModelError
from mechloop.model.check import argument_kind, require_valid
from mechloop.model.schema import Model
from mechloop.model.synthesis import CYCLE_VALUES
from mechloop.model.units import to_si
from mechloop.solve.designs import DesignResults, solve_designs
from mechloop.solve.inputs import Signal, model_arguments, model_time
from mechloop.solve.kinematics import _finish_angles, _setup, _solve_block
from mechloop.solve.results import Results

Array = NDArray[np.float64]

#: The dynamics of each problem's own design (the model is frozen): solved once.
_OWN: WeakKeyDictionary = WeakKeyDictionary()

#: What needs the flywheel of a machine model: a root per design (``brentq``), solved only
#: when asked for.  A machine that runs without it runs with it, so leaving it out changes
#: no other column and fails no design.
FLYWHEEL_VALUES = frozenset({"omega_fw", "epsilon_fw", "flywheel"})



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
    mechanism = _reference(problem, designs, kin_designs.assembles).mechanism

    time = model_time(model)
    static = time is None
    structure = require_valid(model)
    starts = _starts(model, problem.variables.starts(designs), n_pos)
    kin = _flat_results(model, structure, kin_designs.values, kin_designs.rates,
                        kin_designs.accels, kin_designs.broken,
                        model_arguments(model, time), time, None)
    placement = _FlatPlacement(kin, starts)
    mechanism = _with_design_masses(model, mechanism, kin, n_designs, n_pos)
    loads = _flat_loads(model, mechanism, placement, time, n_designs, n_pos)
    forces = kinetostatics(mechanism, placement, loads, friction=True, static=static,
                           segments=np.repeat(np.arange(n_designs), n_pos))

    balancing_vp: dict[int, Array] = {}
    red: Reduced | None = None
    analog_cache: dict[int, tuple[Placement, Loads]] = {}
    for drive in mechanism.drives:
        analogs = _FlatPlacement(_analog_results(model, structure, overrides, drive.argument,
                                                 n_designs, n_pos), starts)
        loads_at = _flat_loads(model, mechanism, analogs, time, n_designs, n_pos)
        analog_cache[drive.argument] = (analogs, loads_at)
        balancing_vp[drive.argument] = balancing_by_virtual_power(
            mechanism, placement, analogs, loads_at, static=static)
    if len(mechanism.drives) == 1:  # as solve_dynamics(friction=True)
        k = mechanism.drives[0].argument
        analogs, loads_at = analog_cache[k]
        red = reduced(mechanism, analogs, loads_at)
        rate = _argument_rate(kin, k)
        with np.errstate(divide="ignore", invalid="ignore"):
            balancing_vp[k] = balancing_vp[k] + np.where(
                rate != 0, forces.friction_loss / rate, 0.0)

    def by_design(values: Array) -> Array:
        return np.asarray(values, dtype=float).reshape(n_designs, n_pos)

    cycle = None
    if model.machine is not None:  # as solve_dynamics: the cycle of every design at once
        check_machine(mechanism, red, time)
        k = mechanism.drives[0].argument
        spec = model.machine
        if not FLYWHEEL_VALUES.intersection(wanted):  # sizing it is most of the cycle's
            spec = spec.model_copy(update={"delta": None})  # time; the rest runs anyway
        cycle = steady_cycles(by_design(kin.arguments[k]), by_design(kin.time),
                              Reduced(*(by_design(x) for x in (red.inertia, red.d_inertia,
                                                                red.load))),
                              by_design(forces.friction_loss),
                              by_design(_argument_rate(kin, k)), spec)
    centers, center, inertia, kinetic = mass_terms(mechanism, placement, static)
    flat = DynamicResults(kin, placement, mechanism, loads, forces, balancing_vp, red,
                          centers, center, kinetic, {}, None, static, inertia,
                          None if cycle is None else _flat_cycle(cycle))
    table = _frame(flat, [c for c in wanted if c not in CYCLE_VALUES])
    out = {name: np.array(table[name].reshape(n_designs, n_pos)) for name in table}
    numbers = [c for c in wanted if c in CYCLE_VALUES]
    if numbers:
        powers = load_powers(kin, placement, mechanism, loads, forces)
        summary = summarize({k: by_design(v) for k, v in powers.items()},
                            by_design(forces.friction_loss), by_design(cycle_clock(kin)),
                            mechanism.total_mass, by_design(kinetic))
        stack = _Stack(summary, cycle)
        for name in numbers:
            out[name] = np.array(np.broadcast_to(cycle_value(stack, name), (n_designs,)),
                                 dtype=float)
    failed = forces.unsettled.reshape(n_designs, n_pos).any(axis=1)
    if cycle is not None:
        failed |= ~cycle.computed
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


class _Stack:
    """What :func:`cycle_value` reads of a population: its summary and cycle ``(D,)``."""

    def __init__(self, summary, cycle: Cycle | None):
        self.summary, self.cycle = summary, cycle


def _flat_cycle(cycle: Cycle) -> Cycle:
    """The speed arrays of a stack of cycles ``(D, P)`` on the long axis ``(D·P,)``, as
    :meth:`DynamicResults.to_frame` reads them."""
    def flat(motion):
        return None if motion is None else replace(motion, omega=_flatten(motion.omega),
                                                   epsilon=_flatten(motion.epsilon))

    return replace(cycle, motion=flat(cycle.motion), with_flywheel=flat(cycle.with_flywheel))


def _reference(problem, designs: Array, assembles: NDArray[np.bool_]) -> DynamicResults:
    """The dynamics of one design that assembles at every position (the model's own if
    it does, else the first such design of the population): the mechanism every design
    shares and the vectors that end at each pair."""
    own = _OWN.get(problem)
    if own is None:  # the mechanism only: no friction iterations (which may not settle)
        own = _OWN[problem] = solve_dynamics(_without_machine(problem.model),
                                             friction=False)
    if not own.kinematics.broken.any() or not assembles.any():
        return own
    return solve_dynamics(_without_machine(problem.design_model(
        designs[int(np.argmax(assembles))])), friction=False)


def _without_machine(model: Model) -> Model:
    """The model without its cycle (``machine:``), which the mechanism does not need and
    which may not be computable for the reference design (the machine stops); without its
    synthesis task too, whose criteria may name the cycle's numbers."""
    if model.machine is None:
        return model
    return model.model_copy(update={"machine": None, "synthesis": None})


# ---- kinematics of the population as one long axis -------------------------------------
def _flatten(table: Array) -> Array:
    return np.ascontiguousarray(table).reshape(-1)


def _flat_results(model: Model, structure, values, rates, accels, broken, args, time,
                  analogs_of: int | None) -> Results:
    """A :class:`Results` whose positions are the designs × positions ``(D·P,)`` of
    tables shaped ``(D, P)``."""
    n_designs = broken.shape[0]
    constant = _setup(model, structure, args).constant
    return Results(
        model=model, structure=structure,
        time=None if time is None else np.tile(time.value, n_designs),
        arguments={k: np.tile(s.value, n_designs) for k, s in args.items()},
        argument_kinds={k: argument_kind(model, k) for k in model.arguments},
        values={k: _flatten(v) for k, v in values.items()},
        rates={k: _flatten(v) for k, v in rates.items()},
        accels={k: _flatten(v) for k, v in accels.items()},
        constant=frozenset(constant), broken=_flatten(broken), analogs_of=analogs_of)


def _analog_results(model: Model, structure, overrides, k: int, n_designs: int,
                    n_pos: int) -> Results:
    """``solve(design_model, analogs_of=k)`` of every design, flattened: the rate of
    argument ``k`` is 1, every other argument held (mirrors
    :func:`~mechloop.solve.designs.solve_designs` with these arguments)."""
    time = model_time(model)
    args = {j: Signal(s.value, np.full(n_pos, float(j == k)), np.zeros(n_pos))
            for j, s in model_arguments(model, time, strict=False).items()}
    shape = (n_designs, n_pos)
    setup = _setup(model, structure, args, overrides)
    block = _solve_block(setup, 0, n_pos, shape, {}, derivatives=True)
    broken = np.zeros(shape, dtype=bool)
    for c in setup.ordered:
        broken |= block.no_solution[c.number] | block.dead[c.number]
    values, rates, accels = {}, {}, {}
    for name, p in block.params.items():
        if name in setup.varying:
            values[name] = np.array(np.broadcast_to(p.value, shape))
            rates[name] = np.array(np.broadcast_to(p.rate, shape))
            accels[name] = np.array(np.broadcast_to(p.accel, shape))
    _finish_angles(setup, {name: values[name] for name in setup.varying})
    for table in (values, rates, accels):
        for name in setup.varying:
            table[name][broken] = np.nan
    still = np.broadcast_to(0.0, shape)
    for name in setup.constant:
        root = structure.links[name].root if name in structure.links else name
        value = (setup.constants[name] if name == root
                 else setup.link_value(name, setup.constants[root]))
        values[name] = np.broadcast_to(value, shape)
        rates[name] = accels[name] = still
    return _flat_results(model, structure, values, rates, accels, broken, args, None, k)


class _FlatPlacement(Placement):
    """A placement over designs × positions whose contours with a varied fixed start
    begin at each design's own point."""

    def __init__(self, results: Results, starts: dict[int, NDArray[np.complex128]]):
        self._starts = starts
        super().__init__(results)

    def _start(self, index: int, start, visiting: tuple[int, ...]) -> Motion:
        if index in self._starts:
            zero = np.zeros(self.results.broken.size, dtype=complex)
            return Motion(self._starts[index], zero, zero)
        return super()._start(index, start, visiting)


def _starts(model: Model, varied: dict[int, tuple], n_pos: int
            ) -> dict[int, NDArray[np.complex128]]:
    """Contour index -> its start per design and position ``(D·P,)`` (m), for contours
    whose fixed start a design varies."""
    out = {}
    for number, (x, y) in varied.items():
        fixed = model.contours[number - 1].start
        x0, y0 = (to_si(c, "length", model.units.length) for c in fixed)
        xs = np.full(len(x if x is not None else y), x0) if x is None else x
        ys = np.full(len(xs), y0) if y is None else y
        out[number - 1] = np.repeat(xs + 1j * ys, n_pos)
    return out


# ---- masses and loads tiled over designs ----------------------------------------------
def _with_design_masses(model: Model, mechanism: Mechanism, kin: Results, n_designs: int,
                        n_pos: int) -> Mechanism:
    """The mechanism with each ``inertia: rod`` computed from the design's own length
    (``m·r²/12``, ``(D·P,)``); every other mass is the same for all designs."""
    rods: list[bool] = []
    for number, body in model.bodies.items():
        if number == 0:
            continue
        for inertia, center in [(body.inertia, body.center),
                                *((p.inertia, p.center) for p in body.parts)]:
            if center is not None:
                rods.append(isinstance(inertia, str) and inertia == "rod")
    if len(rods) != len(mechanism.masses):  # build_mechanism lists masses in this order
        raise AssertionError("masses of the mechanism do not match the model's bodies")
    masses = []
    for mass, rod in zip(mechanism.masses, rods, strict=True):
        if rod:
            first = kin.value(f"r{_point_vector(mass.center)}").reshape(n_designs, n_pos)[:, :1]
            j = mass.mass * first ** 2 / 12.0
            mass = Mass(mass.body, mass.mass, _flatten(np.broadcast_to(j, (n_designs, n_pos))),
                        mass.center)
        masses.append(mass)
    return Mechanism(mechanism.bodies, tuple(masses), mechanism.pairs, mechanism.drives,
                     mechanism.total_mass)


def _flat_loads(model: Model, mechanism: Mechanism, placement: Placement, time,
                n_designs: int, n_pos: int) -> Loads:
    """:func:`~mechloop.dynamics.loads.build_loads` over designs × positions: values
    over positions tiled, directions and points per design (the reference design has
    validated the loads)."""
    units = model.units
    n = placement.results.broken.size
    problems: list = []
    forces: list[PointForce] = []
    for i, load in enumerate(model.forces):
        value = np.tile(_values(model, load.value, "force", units.force, time, n_pos,
                                ("forces", i, "value"), problems), n_designs)
        angle = to_si(load.angle, "angle", units.angle)
        if load.along is not None:
            angle = angle + placement.results.value(f"a{load.along}")
        forces.append(PointForce(load.name or f"F{i + 1}", load.body,
                                 placement.point(load.at), value * np.exp(1j * angle)))
    moments = [Couple(load.name or f"M{i + 1}", load.body,
                      np.tile(_values(model, load.value, "moment", units.moment, time, n_pos,
                                      ("moments", i, "value"), problems), n_designs))
               for i, load in enumerate(model.moments)]
    if model.gravity is not None:
        g = to_si(model.gravity.g, "acceleration", units.acceleration)
        direction = np.exp(1j * to_si(model.gravity.angle, "angle", units.angle))
        for mass in mechanism.masses:
            if mass.mass > 0:
                forces.append(PointForce(f"G{mass.body}", mass.body,
                                         placement.point(mass.center),
                                         np.full(n, mass.mass * g * direction)))
    if problems:  # the reference design has been built with the same loads
        raise ModelError(problems)
    return Loads(tuple(forces), tuple(moments))


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
