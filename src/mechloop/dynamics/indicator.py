"""The gas force of a force whose value is an indicator diagram
(:class:`~mechloop.model.indicator.IndicatorValue`), over a solved model's positions.

The model file's numbers become SI, the crank's angle is the value of its argument, the
piston's parameter and its analog ``dx/dφ`` (its rate over the rate of the crank's angle)
come from the state placement, and :func:`mechloop.engines.gas_force` does the rest,
design by design when the positions are a population's ``(D·P,)``.  The force is a
function of the positions alone: the reduced loads, ``machine:`` and ``simulate`` take it
as they take a table.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.mechanism import Mechanism
from mechloop.dynamics.points import Placement
from mechloop.engines.cycle import CompressorCycle, EngineCycle
from mechloop.engines.diagram import loop_work
from mechloop.engines.gas_force import GasForce, gas_force, port_share
from mechloop.errors import HintedError, ModelError, Problem
from mechloop.model.indicator import IndicatorValue, compile_cycle, si
from mechloop.model.schema import Model

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]


def _located(path: tuple, message: str, hint: str) -> ModelError:
    return ModelError([Problem(path, message, hint)])


def _crank(model: Model, mechanism: Mechanism, value: IndicatorValue, path: tuple
           ) -> tuple[int, int]:
    """The crank's argument and the vector whose angle it drives."""
    if value.argument is None:
        if not mechanism.drives:
            raise _located((*path, "argument"), "the model has no drive to take the crank's "
                           "angle from", "give argument: K (the crank's argument)")
        k = mechanism.drives[0].argument
    else:
        k = value.argument
    for number, vector in sorted(model.vectors.items()):
        if getattr(vector.a, "argument", None) == k:
            return k, number
    raise _located((*path, "argument"), f"no vector's angle is driven by argument {k}",
                   "give the argument that turns the crank")


def indicator_gas(model: Model, value: IndicatorValue, mechanism: Mechanism,
                  state: Placement, *, designs: int = 1, path: tuple = ()
                  ) -> tuple[list[EngineCycle | CompressorCycle], GasForce]:
    """The cycle of each design (one for all, or a two-stroke's with its port from its
    own kinematics) and the gas force (:class:`~mechloop.engines.gas_force.GasForce`,
    arrays ``(D, P)``) at the state's positions.  Raises
    :class:`~mechloop.errors.ModelError` located at ``path`` and below."""
    res = state.results
    cycle = compile_cycle(value, path)
    bore = si(value.bore, "length", model.units.length, (*path, "bore"))
    crankcase = si(value.crankcase, "pressure", value.unit, (*path, "crankcase"))
    if value.piston not in res.values:
        raise _located((*path, "piston"), f"the model has no parameter {value.piston}",
                       "name the length rK of an existing vector K that places the piston")
    k, crank = _crank(model, mechanism, value, path)
    if res.argument_kinds.get(k) != "angle":
        raise _located((*path, "argument"), f"argument {k} is not an angle",
                       "give the argument that turns the crank")
    firing = 0.0
    if isinstance(cycle, EngineCycle) and cycle.strokes == 4:
        firing = si(value.engine.firing, "angle", model.units.angle,
                     (*path, "engine", "firing"))
    shape = (designs, -1)
    phi = np.asarray(res.arguments[k], dtype=float).reshape(shape)
    x = res.value(value.piston).reshape(shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        dx = (res.rate(value.piston) / res.rate(f"a{crank}")).reshape(shape)
    broken = res.broken.reshape(shape)
    x, dx = np.where(broken, np.nan, x), np.where(broken, np.nan, dx)
    head = 1 if value.head == "max" else -1
    try:
        if isinstance(cycle, EngineCycle) and value.engine.exhaust_opens is not None:
            return _ported(model, value, phi, x, dx, bore, crankcase, head, path)
        return [cycle], gas_force(cycle, phi, x, dx, bore=bore, crankcase=crankcase,
                                  head=head, firing=firing)
    except HintedError as exc:
        raise _located(path, exc.message, exc.hint) from None


def _ported(model: Model, value: IndicatorValue, phi, x, dx, bore: float,
            crankcase: float, head: int, path: tuple
            ) -> tuple[list[EngineCycle | CompressorCycle], GasForce]:
    """The gas force of a two-stroke whose port is given by its timing: the port's share
    of the stroke from each design's kinematics, the cycle per share (one for a single
    design: designs whose shares differ are computed one by one)."""
    opens = si(value.engine.exhaust_opens, "angle", model.units.angle,
               (*path, "engine", "exhaust_opens"))
    shares = port_share(phi, x, dx, opens, head=head)
    parts, cycles = [], []
    for row in range(phi.shape[0]):
        cycle = compile_cycle(value, path, port=float(shares[row]))
        cycles.append(cycle)
        parts.append(gas_force(cycle, phi[row:row + 1], x[row:row + 1], dx[row:row + 1],
                               bore=bore, crankcase=crankcase, head=head))
    return cycles, GasForce(*(np.concatenate([getattr(p, f) for p in parts]) for f in (
        "volume", "pressure", "force", "stroke", "swept", "clearance", "top", "bottom")),
        parts[0].area)


def indicator_force(model: Model, value: IndicatorValue, mechanism: Mechanism,
                    state: Placement, designs: int, path: tuple, problems: list[Problem]
                    ) -> Array | None:
    """The force's magnitude (N) at every position ``(D·P,)``, positive away from the
    head; None (with a problem) when it cannot be computed."""
    try:
        _, gas = indicator_gas(model, value, mechanism, state, designs=designs, path=path)
    except ModelError as exc:
        problems.extend(exc.problems)
        return None
    force = gas.force.reshape(-1)
    return np.where(state.results.broken | ~np.isfinite(force), 0.0, force)


def check_direction(value: IndicatorValue, direction: Complex, point, placement: Placement,
                    path: tuple, problems: list[Problem]) -> None:
    """A problem when the force's direction pushes the piston towards the cylinder head
    (where the piston moves fast: its power against the rate of its parameter)."""
    res = placement.results
    if value.piston not in res.values:
        return  # said by indicator_force
    head = 1.0 if value.head == "max" else -1.0
    with np.errstate(invalid="ignore"):
        away = -head * res.rate(value.piston)
        power = (np.conj(direction) * point.v).real
        fast = np.abs(away) > 0.1 * np.fmax.reduce(np.abs(away), initial=0.0)
    fast &= ~res.broken & np.isfinite(power)
    if fast.any() and np.mean(np.sign(power[fast]) == np.sign(away[fast])) < 0.5:
        problems.append(Problem(path, "the gas force points towards the cylinder head (a "
                                "positive value must push the piston away from it)",
                                "turn the force by 180 deg (angle:), or set head: to the "
                                "other end (max/min of the piston's parameter)"))


@dataclass(frozen=True)
class Indicator:
    """One indicator load of a solved model, over its positions.

    Attributes
    ----------
    name : the force's name; index : its place in ``forces``.
    cycle : the engine's or compressor's cycle (SI).
    angle : array (P,), rad — the crank's angle at the positions.
    gas : :class:`~mechloop.engines.gas_force.GasForce` with arrays (P,) and floats.
    loop_work : float, J — ``∮p dV`` of the diagram, closed form.
    sampled_work : float, J — ``∮p dV`` over the positions by the trapezoidal rule in V
        (the positions' reading of the same area).
    """

    name: str
    index: int
    cycle: EngineCycle | CompressorCycle
    angle: Array
    gas: GasForce
    loop_work: float
    sampled_work: float


def model_indicators(model: Model) -> list[Indicator]:
    """Every force of ``model`` whose value is an indicator diagram, evaluated over the
    model's positions (SI).  Raises :class:`~mechloop.errors.ModelError` (located) when
    the model has none or one cannot be evaluated."""
    from mechloop.dynamics.analysis import compile_mechanism

    found = [(i, f) for i, f in enumerate(model.forces) if isinstance(f.value, IndicatorValue)]
    if not found:
        raise ModelError([Problem(("forces",), "the model has no indicator load",
                                  "give a force a value {piston: rK, bore: ..., "
                                  "crankcase: ..., engine: {...}} (examples/"
                                  "engine_indicator.yaml)")])
    _, placement, mechanism = compile_mechanism(model)
    out = []
    for i, force in found:
        path = ("forces", i, "value")
        (cycle,), gas = indicator_gas(model, force.value, mechanism, placement, path=path)
        flat = GasForce(*(np.asarray(v)[0] if np.ndim(v) else v for v in (
            gas.volume, gas.pressure, gas.force, gas.stroke, gas.swept, gas.clearance,
            gas.top, gas.bottom)), gas.area)
        k, _ = _crank(model, mechanism, force.value, path)
        p, v = flat.pressure, flat.volume
        ok = np.isfinite(p) & np.isfinite(v)
        sampled = float(np.sum(0.5 * (p[ok][1:] + p[ok][:-1]) * np.diff(v[ok])))
        out.append(Indicator(force.name or f"F{i + 1}", i, cycle,
                             np.asarray(placement.results.arguments[k], dtype=float), flat,
                             loop_work(cycle, float(flat.swept)), sampled))
    return out
