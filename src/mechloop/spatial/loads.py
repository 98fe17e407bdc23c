"""Loads of a model with spatial contours: forces and moments as 3-D vectors, gravity.

* a force (``forces:``) acts at a point of a body; its magnitude ``value`` is a constant,
  a table or law over the positions, or a table over a parameter's value (as in a planar
  model), and its direction is ``direction: [x, y, z]`` (normalized), else that of vector
  ``along`` (``angle`` must then be 0), else ``angle`` from +X in the XY plane;
* a moment (``moments:``) is ``value`` about ``axis: [x, y, z]`` (normalized; default Z);
* gravity (``gravity:``) pulls every mass by ``m·g`` at ``angle`` from +X in the XY plane
  (default −90°: along −Y).

Expressions, indicator diagrams and ``when`` are not read for a spatial model yet (a
located problem says so).  Arrays ``(3, P)``, SI.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.loads import _parameter_values, _values
from mechloop.errors import Problem
from mechloop.model.dynamic import (
    ExpressionValue,
    HeadPoint,
    ParameterValue,
    TailPoint,
    VectorPoint,
)
from mechloop.model.indicator import IndicatorValue
from mechloop.model.units import UnitProblem, to_si
from mechloop.spatial.directions import unit_of
from mechloop.spatial.points import unit_direction

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Force3:
    """A force ``force`` (N, ``(3, P)``) on ``body`` at ``at``."""

    name: str
    body: int
    force: Array
    at: TailPoint | HeadPoint | VectorPoint


@dataclass(frozen=True)
class Moment3:
    """A moment ``moment`` (N·m, ``(3, P)``) on ``body``."""

    name: str
    body: int
    moment: Array


class _State:
    """What :func:`~mechloop.dynamics.loads._parameter_values` reads: ``.results``."""

    def __init__(self, results):
        self.results = results


def _unit(values, path: tuple, problems: list[Problem]) -> Array | None:
    """A given direction as a unit column ``(3, 1)`` (:func:`~mechloop.spatial.directions.
    unit_of`)."""
    d = unit_of(values, path, problems)
    return None if d is None else d[:, None]


def _magnitude(model, value, kind, unit, time, n, results, path, problems):
    if isinstance(value, ExpressionValue | IndicatorValue):
        problems.append(Problem(path, "expressions and indicator diagrams are not read for "
                                "a model with spatial contours yet",
                                "give a number, a table or law over the positions, or a "
                                "table over a parameter {of: a1, table: [[value, load], "
                                "...]}"))
        return None
    if isinstance(value, ParameterValue):
        return _parameter_values(model, value, _State(results), kind, unit, path, problems)
    return _values(model, value, kind, unit, time, n, path, problems)


def _readable(load, path: tuple, bodies: set[int], problems: list[Problem]) -> bool:
    """Whether a force or moment ``load`` (at YAML ``path``) acts on a moving body and
    has no ``when`` (not read for spatial models yet); else a problem is appended."""
    if load.body not in bodies:
        problems.append(Problem((*path, "body"), f"body {load.body} is not a moving body",
                                f"use one of {sorted(bodies)}"))
        return False
    if load.when is not None:
        problems.append(Problem((*path, "when"), "'when' is not read for a model with "
                                "spatial contours yet", "remove 'when'"))
        return False
    return True


def build_loads(model, results, masses, bodies: set[int], time, problems: list[Problem]
                ) -> tuple[list[Force3], list[Moment3]]:
    """The forces (gravity included) and moments of ``model`` over its positions, from
    its solved kinematics ``results``; problems are appended."""
    n = results.broken.size
    units = model.units
    forces: list[Force3] = []
    moments: list[Moment3] = []
    for i, load in enumerate(model.forces):
        path = ("forces", i)
        if not _readable(load, path, bodies, problems):
            continue
        value = _magnitude(model, load.value, "force", units.force, time, n, results,
                           (*path, "value"), problems)
        try:
            angle = to_si(load.angle, "angle", units.angle)
        except UnitProblem as exc:
            problems.append(Problem((*path, "angle"), exc.message, exc.hint))
            continue
        if load.direction is not None:
            direction = _unit(load.direction, (*path, "direction"), problems)
        elif load.along is not None:
            direction = None
            if load.along not in model.vectors:
                problems.append(Problem((*path, "along"), f"vector {load.along} does not "
                                        "exist", f"use one of {sorted(model.vectors)}"))
            elif angle != 0:
                problems.append(Problem((*path, "angle"), "in a model with spatial "
                                        "contours a force along a vector has no angle to it",
                                        "remove 'angle', or give 'direction: [x, y, z]'"))
            else:
                direction = unit_direction(results, load.along).p
        else:
            direction = np.array([[np.cos(angle)], [np.sin(angle)], [0.0]])
        if value is None or direction is None:
            continue
        forces.append(Force3(load.name or f"F{i + 1}", load.body, value * direction, load.at))
    for i, load in enumerate(model.moments):
        path = ("moments", i)
        if not _readable(load, path, bodies, problems):
            continue
        value = _magnitude(model, load.value, "moment", units.moment, time, n, results,
                           (*path, "value"), problems)
        axis = (np.array([[0.0], [0.0], [1.0]]) if load.axis is None
                else _unit(load.axis, (*path, "axis"), problems))
        if value is not None and axis is not None:
            moments.append(Moment3(load.name or f"M{i + 1}", load.body, value * axis))
    if model.gravity is not None:
        try:
            g = to_si(model.gravity.g, "acceleration", units.acceleration)
            angle = to_si(model.gravity.angle, "angle", units.angle)
        except UnitProblem as exc:
            problems.append(Problem(("gravity",), exc.message, exc.hint))
        else:
            down = np.array([[np.cos(angle)], [np.sin(angle)], [0.0]])
            for mass in masses:
                if mass.mass > 0:
                    forces.append(Force3(f"G{mass.body}", mass.body,
                                         np.zeros((3, n)) + mass.mass * g * down,
                                         mass.center))
    return forces, moments
