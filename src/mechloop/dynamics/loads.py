"""External loads over all positions, SI: forces at points, moments, gravity, springs and
dampers.

A load's value is given like a model argument (a constant, a sparse table filled by KDAM's
rules, or a law) or as a table over a parameter's value; its direction is a fixed angle or
follows a vector.  A load with ``when`` acts only where a parameter's rate has the given
sign.  Springs and dampers: :mod:`mechloop.dynamics.elements`.

**Two placements.**  ``placement`` gives the points where the loads act (the motion, or
the analogs of an input for reduced loads and virtual power); ``state`` (default the same)
gives the state the loads depend on: the values and true rates of the motion.  A load
that depends on a rate records how (:class:`Dependence`), so that the motion in time can
re-evaluate it at another speed (:mod:`mechloop.dynamics.simulate`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.elements import RateLaw, element_loads
from mechloop.dynamics.indicator import check_direction, indicator_force
from mechloop.dynamics.mechanism import Mechanism
from mechloop.dynamics.points import Motion, Placement
from mechloop.errors import ModelError, Problem
from mechloop.model.dynamic import ExpressionValue, ParameterValue
from mechloop.model.expression import Expression
from mechloop.model.indicator import IndicatorValue
from mechloop.model.schema import Model
from mechloop.model.units import Kind, UnitProblem, to_si
from mechloop.solve.inputs import Signal, evaluate_signal

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]


@dataclass(frozen=True)
class Dependence:
    """How a load depends on the rates, for re-evaluating it at another speed.

    ``law`` set (a damper): the load is ``law(v)·unit`` with ``v`` the relative speed,
    whose value on the placement the load was built on is ``speed`` (per unit rate of
    the input when that placement holds analogs).  ``sign`` set (a load with ``when``):
    the load is ``ungated`` where ``sign·rate > 0`` and zero elsewhere, ``rate`` the
    deciding parameter's rate on that placement.  Arrays shaped (P,)."""

    law: RateLaw | None = None
    speed: Array | None = None
    unit: Complex | Array | None = None
    sign: float | None = None
    rate: Array | None = None
    ungated: Complex | Array | None = None
    expression: Expression | None = None
    scale: float = 1.0


@dataclass(frozen=True)
class PointForce:
    """A force ``force`` (N, complex ``Fx + i·Fy``, shape (P,)) on ``body`` at ``point``;
    ``depends`` when it follows the rates (None: the positions only)."""

    name: str
    body: int
    point: Motion
    force: Complex
    depends: Dependence | None = field(default=None, repr=False)


@dataclass(frozen=True)
class Couple:
    """A moment ``moment`` (N·m, counter-clockwise, shape (P,)) on ``body``; ``depends``
    as for :class:`PointForce`."""

    name: str
    body: int
    moment: Array
    depends: Dependence | None = field(default=None, repr=False)


@dataclass(frozen=True)
class Loads:
    """Every external load of a model: forces (gravity included, one per mass) and
    moments."""

    forces: tuple[PointForce, ...]
    moments: tuple[Couple, ...]


def _values(model: Model, value, kind: Kind, unit: str, time: Signal | None, n: int,
            path: tuple, problems: list[Problem]) -> Array:
    try:
        if isinstance(value, int | float | str):
            return np.full(n, to_si(value, kind, unit))
        return evaluate_signal(value, model, kind, value.unit or unit, time).value
    except UnitProblem as exc:
        problems.append(Problem(path, exc.message, exc.hint))
        return np.zeros(n)


def _parameter(results, name: str, path: tuple, problems: list[Problem]) -> str | None:
    """``name`` if the model has that parameter, else a problem and None."""
    if name in results.values:
        return name
    problems.append(Problem(path, f"the model has no parameter {name}",
                            "name rK or aK of an existing vector K"))
    return None


def _parameter_values(model: Model, value, state: Placement, kind: Kind, unit: str,
                      path: tuple, problems: list[Problem]) -> Array | None:
    """A load given as a table over a parameter's value, at the state's values."""
    name = _parameter(state.results, value.of, (*path, "of"), problems)
    if name is None:
        return None
    x_kind: Kind = "length" if name[0] == "r" else "angle"
    x_unit = model.units.length if name[0] == "r" else model.units.angle
    try:
        xs = np.array([to_si(x, x_kind, x_unit) for x, _ in value.table])
        ys = np.array([to_si(y, kind, value.unit or unit) for _, y in value.table])
    except UnitProblem as exc:
        problems.append(Problem((*path, "table"), exc.message, exc.hint))
        return None
    if not np.all(np.diff(xs) > 0):
        problems.append(Problem((*path, "table"), f"the values of {name} must increase "
                                "down the table", "sort the [value, load] pairs"))
        return None
    return np.interp(state.results.value(name), xs, ys)


def expression_names(expression: Expression, state: Placement, time: Signal | None,
                     designs: int) -> dict[str, Array]:
    """The state an expression reads, SI over the state's positions: ``t`` (s), ``rK``,
    ``aK`` (m, rad), ``drK``, ``daK`` (their rates).  Raises KeyError naming what the
    model does not have."""
    res = state.results
    out: dict[str, Array] = {}
    for name in expression.names:
        if name == "t":
            if time is None:
                raise KeyError("t (the model has no time)")
            out[name] = np.tile(time.value, designs)
        elif name.startswith("d"):
            if name[1:] not in res.values:
                raise KeyError(name)
            out[name] = res.rate(name[1:])
        else:
            if name not in res.values:
                raise KeyError(name)
            out[name] = res.value(name)
    return out


def _expression_values(value: ExpressionValue, state: Placement, kind: Kind, unit: str,
                       time: Signal | None, designs: int, path: tuple,
                       problems: list[Problem]) -> Array | None:
    """A load given as an expression of the state, SI at the state's positions."""
    expression = Expression(value.expression)
    try:
        scale = to_si(1.0, kind, value.unit or unit)
        names = expression_names(expression, state, time, designs)
        out = scale * expression(names)
    except UnitProblem as exc:
        problems.append(Problem((*path, "unit"), exc.message, exc.hint))
        return None
    except KeyError as exc:
        problems.append(Problem((*path, "expression"), f"the model has no {exc.args[0]}",
                                "use t (with model time), rK, aK, drK, daK of existing "
                                "vectors K"))
        return None
    except (TypeError, ValueError, ZeroDivisionError) as exc:
        problems.append(Problem((*path, "expression"), f"cannot evaluate "
                                f"{value.expression!r}: {exc}", "call functions as "
                                "sin(x); use numbers and the state's names"))
        return None
    out = np.broadcast_to(out, state.results.broken.shape).astype(float)
    bad = ~np.isfinite(out) & ~state.results.broken
    if bad.any():
        problems.append(Problem((*path, "expression"), f"{value.expression!r} is not "
                                f"finite at position {int(np.flatnonzero(bad)[0])}",
                                "keep divisions and logarithms away from zero"))
        return None
    return out


def follows_motion(value) -> bool:
    """Whether a load's value follows the rates or the time (an expression that reads
    ``t`` or a rate)."""
    return isinstance(value, ExpressionValue) and any(
        n == "t" or n.startswith("d") for n in Expression(value.expression).names)


def _expression_dependence(model: Model, value: ExpressionValue, kind: Kind, unit: str,
                           direction) -> Dependence:
    return Dependence(expression=Expression(value.expression), unit=direction,
                      scale=to_si(1.0, kind, value.unit or unit))


def _gate(load, placement: Placement, state: Placement, path: tuple,
          problems: list[Problem]) -> tuple[Array, Dependence] | None:
    """Where a load with ``when`` acts (True/False over positions) and its dependence
    (the ungated load is filled in by the caller)."""
    name = _parameter(state.results, load.when.rate_of, (*path, "when", "rate_of"),
                      problems)
    if name is None:
        return None
    sign = 1.0 if load.when.sign == "positive" else -1.0
    return sign * state.results.rate(name) > 0, Dependence(
        sign=sign, rate=placement.results.rate(name))


def _dependent(model: Model, load, value, kind: str, unit: str, direction, gate,
               path: tuple, problems: list[Problem]):
    """A load's values over positions and how they depend on the state: ``(value,
    depends)``, or None (with a problem) for an expression of the state that also has
    ``when:``.  ``direction`` turns an expression's scalar into the load (the force's
    unit direction, ones for a moment); ``gate`` is the load's ``when:`` (positions where it
    acts, its dependence) or None."""
    depends = None
    if follows_motion(load.value):
        if gate is not None:
            problems.append(Problem((*path, "when"), "an expression of the rates or time "
                                    "cannot also have when:", "write the condition into "
                                    "the expression: (drK > 0)*..."))
            return None
        depends = _expression_dependence(model, load.value, kind, unit, direction)
    if gate is not None:
        acts, depends = gate
        depends = Dependence(sign=depends.sign, rate=depends.rate, ungated=value)
        value = np.where(acts, value, 0.0)
    return value, depends


def build_loads(model: Model, mechanism: Mechanism, placement: Placement,
                time: Signal | None, *, designs: int = 1,
                state: Placement | None = None) -> Loads:
    """Compile the model's forces, moments, gravity, springs and dampers over all
    positions (SI).

    ``state`` (default ``placement``) is the motion whose values and rates the loads
    depend on (a table over a parameter, ``when``, dampers); ``placement`` gives the
    points.  With ``designs`` > 1 the placement's positions are the designs × positions
    of a population (``(D·P,)``, :mod:`mechloop.dynamics.population`): a load's values
    over the model's positions are the same for every design (repeated), its direction,
    point and state are each design's own."""
    state = placement if state is None else state
    problems: list[Problem] = []
    n = placement.results.broken.size
    n_pos = n // designs
    units = model.units
    forces: list[PointForce] = []
    moments: list[Couple] = []
    for i, load in enumerate(model.forces):
        path = ("forces", i)
        if load.body not in mechanism.bodies:
            problems.append(Problem((*path, "body"), f"body {load.body} is not a moving body",
                                    f"use one of {sorted(mechanism.bodies)}"))
            continue
        if load.direction is not None:  # a 3-D direction: spatial models (issue 17)
            problems.append(Problem((*path, "direction"), "a 3-D direction applies to a "
                                    "force in a model with spatial contours",
                                    "give the direction in the plane with 'angle'"))
            continue
        if isinstance(load.value, IndicatorValue):  # the gas force of an indicator diagram
            value = indicator_force(model, load.value, mechanism, state, designs,
                                    (*path, "value"), problems)
        else:
            value = _load_values(model, load.value, "force", units.force, time, n_pos,
                                 designs, state, (*path, "value"), problems)
        gate = None if load.when is None else _gate(load, placement, state, path,
                                                     problems)
        if value is None or (load.when is not None and gate is None):
            continue
        try:
            angle = to_si(load.angle, "angle", units.angle)
        except UnitProblem as exc:
            problems.append(Problem((*path, "angle"), exc.message, exc.hint))
            continue
        if load.along is not None:
            if load.along not in model.vectors:
                problems.append(Problem((*path, "along"), f"vector {load.along} does not "
                                        "exist", f"use one of {sorted(model.vectors)}"))
                continue
            angle = angle + placement.results.value(f"a{load.along}")
        try:
            point = placement.point(load.at)
        except KeyError as exc:
            problems.append(Problem((*path, "at"), f"vector {exc.args[0]} does not exist",
                                    f"use one of {sorted(model.vectors)}"))
            continue
        if isinstance(load.value, IndicatorValue):
            check_direction(load.value, np.exp(1j * angle), point, placement, path, problems)
        made = _dependent(model, load, value * np.exp(1j * angle), "force", units.force,
                          np.exp(1j * angle), gate, path, problems)
        if made is not None:
            forces.append(PointForce(load.name or f"F{i + 1}", load.body, point, *made))
    for i, load in enumerate(model.moments):
        path = ("moments", i)
        if load.body not in mechanism.bodies:
            problems.append(Problem((*path, "body"), f"body {load.body} is not a moving body",
                                    f"use one of {sorted(mechanism.bodies)}"))
            continue
        if load.axis is not None:  # a 3-D axis: spatial models (issue 17)
            problems.append(Problem((*path, "axis"), "an axis applies to a moment in a "
                                    "model with spatial contours", "remove 'axis' (a "
                                    "planar moment turns about Z, counter-clockwise)"))
            continue
        value = _load_values(model, load.value, "moment", units.moment, time, n_pos,
                             designs, state, (*path, "value"), problems)
        gate = None if load.when is None else _gate(load, placement, state, path,
                                                     problems)
        if value is None or (load.when is not None and gate is None):
            continue
        made = _dependent(model, load, value, "moment", units.moment, np.ones(value.size),
                          gate, path, problems)
        if made is not None:
            moments.append(Couple(load.name or f"M{i + 1}", load.body, *made))
    if model.gravity is not None:
        try:
            g = to_si(model.gravity.g, "acceleration", units.acceleration)
            direction = np.exp(1j * to_si(model.gravity.angle, "angle", units.angle))
        except UnitProblem as exc:
            problems.append(Problem(("gravity",), exc.message, exc.hint))
        else:
            for mass in mechanism.masses:
                if mass.mass > 0:
                    forces.append(PointForce(f"G{mass.body}", mass.body,
                                             placement.point(mass.center),
                                             np.full(n, mass.mass * g * direction)))
    for element in element_loads(model, mechanism, placement, state, static=time is None,
                                 problems=problems, check_ends=designs == 1):
        depends = None if element.law is None else Dependence(
            law=element.law, speed=element.speed, unit=element.unit)
        if element.point is None:
            moments.append(Couple(element.name, element.body, element.force, depends))
        else:
            forces.append(PointForce(element.name, element.body, element.point,
                                     element.force, depends))
    if problems:
        raise ModelError(problems)
    return Loads(tuple(forces), tuple(moments))


def _load_values(model: Model, value, kind: Kind, unit: str, time: Signal | None,
                 n_pos: int, designs: int, state: Placement, path: tuple,
                 problems: list[Problem]) -> Array | None:
    """A load's value at every position (SI): over the model's positions (the same for
    every design), or over a parameter's value (each design's own)."""
    if isinstance(value, ParameterValue):
        return _parameter_values(model, value, state, kind, unit, path, problems)
    if isinstance(value, ExpressionValue):
        return _expression_values(value, state, kind, unit, time, designs, path, problems)
    return np.tile(_values(model, value, kind, unit, time, n_pos, path, problems), designs)
