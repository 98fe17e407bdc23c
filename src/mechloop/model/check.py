"""Whole-model validation: structure, units, argument tables and laws, model time.

:func:`check_model` returns every problem at once (STYLE: validate up front, report all);
:func:`require_valid` raises them as one :class:`~mechloop.errors.ModelError`.
"""

from __future__ import annotations

from difflib import get_close_matches

import numpy as np

from mechloop.errors import ModelError, Problem
from mechloop.model.display import check_display
from mechloop.model.dynamic import VectorPoint
from mechloop.model.indicator import IndicatorValue, indicator_problems
from mechloop.model.intermediate import check_intermediate
from mechloop.model.schema import ArgumentRole, LawArgument, LinkRole, Model, TableArgument, Units
from mechloop.model.signals import MIN_TIME_STEP
from mechloop.model.spatial import analyze_spatial
from mechloop.model.structure import Structure, analyze
from mechloop.model.synthesis import check_synthesis
from mechloop.model.units import Kind, UnitProblem, to_si, unit_factor

KIND_OF = {"r": "length", "a": "angle", "b": "angle"}
#: Values of one table reported one by one; the rest are counted.
MAX_TABLE_PROBLEMS = 5


def argument_kinds(model: Model) -> dict[int, set[str]]:
    """For each argument, the kinds ('length', 'angle') of the parameters it drives."""
    kinds: dict[int, set[str]] = {k: set() for k in model.arguments}
    for vector in model.vectors.values():
        for letter in "rab":  # b: β of a spatial vector (None when absent)
            role = getattr(vector, letter)
            if isinstance(role, ArgumentRole) and role.argument in kinds:
                kinds[role.argument].add(KIND_OF[letter])
    return kinds


def argument_kind(model: Model, number: int) -> Kind:
    """The kind of argument ``number`` (defaults to 'angle' for an unused argument)."""
    kinds = argument_kinds(model).get(number, set())
    return "length" if kinds == {"length"} else "angle"


def check_model(model: Model) -> tuple[Structure, list[Problem]]:
    """Every problem of ``model``, in document order as far as practical."""
    if any(c.spatial for c in model.contours):  # spatial contours (issue 17)
        structure, problems = analyze_spatial(model)
    else:
        structure, problems = analyze(model)
    problems = _check_units(model) + problems
    problems += _check_arguments(model)
    problems += check_intermediate(model, structure,
                                   {k: argument_kind(model, k) for k in model.arguments})
    problems += _check_time(model)
    problems += _check_loads(model)
    problems += check_synthesis(model)
    problems += check_display(model.display)
    return structure, problems


def require_valid(model: Model, *, file: str | None = None) -> Structure:
    """The model's structure, or a :class:`ModelError` listing every problem."""
    structure, problems = check_model(model)
    if problems:
        raise ModelError(problems, file)
    return structure


def _unit_problem(path: tuple, exc: UnitProblem) -> Problem:
    return Problem(path, exc.message, exc.hint)


def _check_units(model: Model) -> list[Problem]:
    problems: list[Problem] = []
    for kind in ("length", "angle"):
        try:
            unit_factor(getattr(model.units, kind), kind)
        except UnitProblem as exc:
            problems.append(_unit_problem(("units", kind), exc))
    if problems:
        return problems  # every number below would repeat the same complaint
    for number, vector in model.vectors.items():
        for letter in "rab":  # b: β of a spatial vector (None when absent)
            role = getattr(vector, letter)
            if role is None:
                continue
            kind = KIND_OF[letter]
            default = getattr(model.units, kind)
            path = ("vectors", number, letter)
            values: list[tuple[tuple, float | str]] = []
            if isinstance(role, ArgumentRole):
                values.append(((*path, "offset"), role.offset))
            elif isinstance(role, LinkRole):
                values.append(((*path, "delta"), role.delta))
            elif isinstance(role, float | int) or (isinstance(role, str)
                                                  and role.strip() != "function"):
                values.append((path, role))
            for where, value in values:
                try:
                    to_si(value, kind, default)
                except UnitProblem as exc:
                    if isinstance(value, str) and get_close_matches(value.strip(),
                                                                    ["function"]):
                        problems.append(Problem(where, f"{value!r} is not a role",
                                                "did you mean 'function'?"))
                    else:
                        problems.append(_unit_problem(where, exc))
    return problems


def _check_arguments(model: Model) -> list[Problem]:
    problems: list[Problem] = []
    n = model.positions
    kinds = argument_kinds(model)
    for number, arg in model.arguments.items():
        path = ("arguments", number)
        used = kinds[number]
        if not used:
            problems.append(Problem(path, f"argument {number} drives no vector parameter",
                                    f"use it in a vector (e.g. a: {{argument: {number}}}) "
                                    "or remove it"))
        elif len(used) > 1:
            problems.append(Problem(path, f"argument {number} drives both lengths and angles",
                                    "give lengths and angles separate arguments"))
        kind: Kind = "length" if used == {"length"} else "angle"
        unit = arg.unit or getattr(model.units, kind)
        try:
            unit_factor(unit, kind)
        except UnitProblem as exc:
            problems.append(_unit_problem((*path, "unit"), exc))
            continue
        problems += _check_signal(arg, n, path, kind, unit)
    return problems


def _check_signal(arg, n: int, path: tuple, kind: Kind, unit: str) -> list[Problem]:
    """The problems of a table or a law (of an argument or a load) over positions 0..n."""
    problems: list[Problem] = []
    if isinstance(arg, TableArgument):
        problems += _check_table(arg.table, n, (*path, "table"), kind, unit)
    elif isinstance(arg, LawArgument):
        (k0, v0), (k1, v1) = arg.start, arg.end
        for key, k in (("start", k0), ("end", k1)):
            if not 0 <= k <= n:
                problems.append(Problem((*path, key, 0), f"{key} position {k} is outside "
                                        f"the calculation positions 0..{n}",
                                        f"use a position between 0 and {n}"))
        if k1 <= k0:
            problems.append(Problem((*path, "end", 0), f"the law ends at position {k1}, "
                                    f"not after its start {k0}",
                                    "make the end position larger than the start"))
        for key, v in (("start", v0), ("end", v1)):
            try:
                to_si(v, kind, unit)
            except UnitProblem as exc:
                problems.append(_unit_problem((*path, key, 1), exc))
    return problems


def _check_loads(model: Model) -> list[Problem]:
    """Units, tables and laws of the forces, moments and gravity; masses, moments of
    inertia, pin radii and slider lengths; every point given on a vector (in bodies,
    joints and forces) and every fixed contour start with a readable length."""
    problems: list[Problem] = []
    units = model.units
    for kind in ("force", "moment", "mass", "inertia", "acceleration"):
        try:
            unit_factor(getattr(units, kind), kind)
        except UnitProblem as exc:  # said once, here; the values are checked without it
            problems.append(_unit_problem(("units", kind), exc))
            units = units.model_copy(update={kind: Units.model_fields[kind].default})
    for key, kind in (("forces", "force"), ("moments", "moment")):
        for i, load in enumerate(getattr(model, key)):
            path = (key, i, "value")
            value = load.value
            try:
                if isinstance(value, TableArgument | LawArgument):
                    unit = value.unit or getattr(units, kind)
                    unit_factor(unit, kind)
                    problems += _check_signal(value, model.positions, path, kind, unit)
                elif isinstance(value, int | float | str):
                    to_si(value, kind, getattr(units, kind))
                elif isinstance(value, IndicatorValue):
                    problems += indicator_problems(value, units, path)
            except UnitProblem as exc:
                problems.append(_unit_problem(path, exc))
            if kind == "force":
                problems += _check_values([((key, i, "angle"), load.angle, "angle")], units)
    for i, contour in enumerate(model.contours):
        if isinstance(contour.start, tuple):
            problems += _check_values([(("contours", i, "start", j), c, "length")
                                       for j, c in enumerate(contour.start)], units)
    if model.gravity is not None:
        problems += _check_values([(("gravity", "g"), model.gravity.g, "acceleration"),
                                   (("gravity", "angle"), model.gravity.angle, "angle")],
                                  units)
    problems += _check_values(_quantities(model), units)
    for path, point in _points(model):
        if isinstance(point, VectorPoint):
            values = [((*path, "across"), point.across, "length")]
            if point.along is not None:
                values.append(((*path, "along"), point.along, "length"))
            problems += _check_values(values, units)
    return problems


def _check_values(values: list[tuple[tuple, float | str, Kind]], units) -> list[Problem]:
    problems = []
    for path, value, kind in values:
        try:
            to_si(value, kind, getattr(units, kind))
        except UnitProblem as exc:
            problems.append(_unit_problem(path, exc))
    return problems


def _quantities(model: Model) -> list[tuple[tuple, float | str, Kind]]:
    """Every mass, moment of inertia, pin radius and slider length with its path."""
    out: list[tuple[tuple, float | str, Kind]] = []
    masses = [(("bodies", n), body) for n, body in model.bodies.items()]
    masses += [(("bodies", n, "parts", i), part) for n, body in model.bodies.items()
               for i, part in enumerate(body.parts)]
    for path, item in masses:
        out.append(((*path, "mass"), item.mass, "mass"))
        if isinstance(item.inertia, list):  # a tensor (spatial models): each entry
            out += [((*path, "inertia", i, *([j] if isinstance(row, list) else [])), x,
                     "inertia") for i, row in enumerate(item.inertia)
                    for j, x in enumerate(row if isinstance(row, list) else [row])]
        elif item.inertia != "rod":
            out.append(((*path, "inertia"), item.inertia, "inertia"))
    holders = [(("joints", name), joint) for name, joint in (model.joints or {}).items()]
    holders.append((("friction",), model.friction))
    for path, item in holders:
        out += [((*path, key), getattr(item, key), "length") for key in ("radius", "length")
                if getattr(item, key) is not None]
    return out


def _points(model: Model) -> list[tuple[tuple, object]]:
    """Every point of the dynamic part with its path: centres, pins, points of forces."""
    out: list[tuple[tuple, object]] = []
    for number, body in model.bodies.items():
        if body.center is not None:
            out.append((("bodies", number, "center"), body.center))
        out += [(("bodies", number, "parts", i, "center"), part.center)
                for i, part in enumerate(body.parts)]
    for name, joint in (model.joints or {}).items():
        if joint.at is not None:
            out.append((("joints", name, "at"), joint.at))
    out += [(("forces", i, "at"), force.at) for i, force in enumerate(model.forces)]
    return out


def _check_table(table, n: int, path: tuple, kind: Kind | None, unit: str | None
                 ) -> list[Problem]:
    problems: list[Problem] = []
    if isinstance(table, dict):
        if not table:
            problems.append(Problem(path, "the table is empty",
                                    "give at least one 'position: value' pair"))
        items = list(table.items())
    else:
        if len(table) != n + 1:
            problems.append(Problem(path, f"the table lists {len(table)} values, but the "
                                    f"model has {n + 1} positions (0..{n})",
                                    f"give {n + 1} values, or a sparse mapping "
                                    "{position: value}"))
        items = list(enumerate(table))
    outside = [k for k, _ in items if not 0 <= k <= n] if isinstance(table, dict) else []
    if outside:  # one problem for the table, however many positions it lists
        more = f" (and {len(outside) - 1:,} more)" if len(outside) > 1 else ""
        problems.append(Problem((*path, outside[0]), f"position {outside[0]} is outside the "
                                f"calculation positions 0..{n}{more}",
                                f"use positions between 0 and {n}, or raise 'positions'"))
    unreadable = 0
    for k, value in items if kind is not None and unit is not None else ():
        try:
            to_si(value, kind, unit)
        except UnitProblem as exc:
            unreadable += 1
            if unreadable <= MAX_TABLE_PROBLEMS:
                problems.append(_unit_problem((*path, k), exc))
    if unreadable > MAX_TABLE_PROBLEMS:
        problems.append(Problem(path, f"{unreadable - MAX_TABLE_PROBLEMS:,} more values of "
                                "this table cannot be read", "fix the values above the "
                                "same way"))
    return problems


def _check_time(model: Model) -> list[Problem]:
    time = model.time
    if time is None or not hasattr(time, "table"):
        return []
    path = ("time", "table")
    problems = _check_table(time.table, model.positions, path, None, None)
    if problems:
        return problems
    from mechloop.model.tables import fill_table

    t = fill_table(time.table, model.positions)
    step = np.diff(t)
    if len(time.table) < 2 or not (step > 0).all():
        problems.append(Problem(path, "model time must increase from position to position",
                                "give at least the first and the last position with "
                                "increasing times, e.g. {0: 0, N: 0.03}"))
    elif not (step >= MIN_TIME_STEP).all():
        k = int(np.flatnonzero(step < MIN_TIME_STEP)[0])
        problems.append(Problem(path, f"model time advances by {step[k]:.3g} s from position "
                                f"{k} to {k + 1}; the shortest step is {MIN_TIME_STEP:g} s",
                                "give times in seconds, spread over the positions"))
    return problems
