"""External loads over all positions, SI: forces at points, moments, and gravity.

A load's value is given like a model argument (a constant, a sparse table filled by KDAM's
rules, or a law); its direction is a fixed angle or follows a vector.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.mechanism import Mechanism
from mechloop.dynamics.points import Motion, Placement
from mechloop.errors import ModelError, Problem
from mechloop.model.schema import Model
from mechloop.model.units import Kind, UnitProblem, to_si
from mechloop.solve.inputs import Signal, evaluate_signal

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]


@dataclass(frozen=True)
class PointForce:
    """A force ``force`` (N, complex ``Fx + i·Fy``, shape (P,)) on ``body`` at ``point``."""

    name: str
    body: int
    point: Motion
    force: Complex


@dataclass(frozen=True)
class Couple:
    """A moment ``moment`` (N·m, counter-clockwise, shape (P,)) on ``body``."""

    name: str
    body: int
    moment: Array


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


def build_loads(model: Model, mechanism: Mechanism, placement: Placement,
                time: Signal | None, *, designs: int = 1) -> Loads:
    """Compile the model's forces, moments and gravity over all positions (SI).

    With ``designs`` > 1 the placement's positions are the designs × positions of a
    population (``(D·P,)``, :mod:`mechloop.dynamics.population`): a load's values over
    the model's positions are the same for every design (repeated), its direction and
    point are each design's own."""
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
        value = np.tile(_values(model, load.value, "force", units.force, time, n_pos,
                                (*path, "value"), problems), designs)
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
        forces.append(PointForce(load.name or f"F{i + 1}", load.body, point,
                                 value * np.exp(1j * angle)))
    for i, load in enumerate(model.moments):
        path = ("moments", i)
        if load.body not in mechanism.bodies:
            problems.append(Problem((*path, "body"), f"body {load.body} is not a moving body",
                                    f"use one of {sorted(mechanism.bodies)}"))
            continue
        value = np.tile(_values(model, load.value, "moment", units.moment, time, n_pos,
                                (*path, "value"), problems), designs)
        moments.append(Couple(load.name or f"M{i + 1}", load.body, value))
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
    if problems:
        raise ModelError(problems)
    return Loads(tuple(forces), tuple(moments))
