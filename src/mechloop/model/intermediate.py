"""Intermediate arguments in a model file: which parameters and contours they reach, the
envelopes the file asks for, and the checks of both.

An intermediate argument (:class:`~mechloop.model.signals.IntermediateArgument`) is swept
inside every calculation position; the parameters it drives, the contours that read them
and everything solved from those (transitively, through links too) get its extra axis.
An *envelope* names a point — the end of a chain of vectors laid end to end from the
origin — whose curves over the sweep form a family, one curve per position; the envelope
of that family (e.g. a cam profile, the envelope of the roller circles) is solved by
:mod:`mechloop.solve.intermediate`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

from mechloop.errors import Problem
from mechloop.model.signals import IntermediateArgument

if TYPE_CHECKING:
    from mechloop.model.schema import Model
    from mechloop.model.structure import Structure
    from mechloop.model.units import Kind


def intermediate_numbers(model: Model) -> list[int]:
    """Numbers of the model's intermediate arguments, increasing."""
    return sorted(k for k, a in model.arguments.items()
                  if isinstance(a, IntermediateArgument))


def dependents(model: Model, structure: Structure, number: int
               ) -> tuple[frozenset[str], frozenset[int]]:
    """The parameters (``'a3'``, ``'r4'``) and the contours that depend on argument
    ``number``: driven by it, linked to such a parameter, or solved by a contour that
    reads one (transitively, in solving order)."""
    from mechloop.model.schema import ArgumentRole
    from mechloop.model.structure import param_role

    reached: set[str] = set()
    for n in model.vectors:
        for letter in "ra":
            role = param_role(model, f"{letter}{n}")
            if isinstance(role, ArgumentRole) and role.argument == number:
                reached.add(f"{letter}{n}")

    def add_links() -> None:
        reached.update(name for name, chain in structure.links.items()
                       if chain.root in reached)

    add_links()
    contours: set[int] = set()
    for info in structure.ordered():
        known = {f"{letter}{n}" for n in info.vectors for letter in "ra"} - set(
            info.functions)
        if known & reached or set(info.needs) & contours:
            contours.add(info.number)
            reached.update(info.functions)
            add_links()
    return frozenset(reached), frozenset(contours)


def check_intermediate(model: Model, structure: Structure, kinds: Mapping[int, Kind]
                       ) -> list[Problem]:
    """Problems of the intermediate arguments and the envelopes: at most one intermediate
    argument, not the first argument (the motion the derivatives follow), a sweep of
    distinct ends, and envelopes of points that depend on it.  ``kinds`` gives each
    argument's kind ('length' or 'angle', from the parameters it drives)."""
    from mechloop.model.units import UnitProblem, to_si

    problems: list[Problem] = []
    numbers = intermediate_numbers(model)
    for k in numbers[1:]:
        problems.append(Problem(("arguments", k, "intermediate"), "a model has at most one "
                                f"intermediate argument (argument {numbers[0]} is one)",
                                "sweep one argument inside the positions; give the "
                                "others as tables or laws"))
    if numbers and numbers[0] == min(model.arguments):
        k = numbers[0]
        problems.append(Problem(("arguments", k, "intermediate"), f"argument {k} is the "
                                "first argument, which the positions follow (derivatives "
                                "are taken along it): it cannot be intermediate",
                                "give the motion over the positions as a lower-numbered "
                                "argument (e.g. 1) and sweep a higher-numbered one"))
    for k in numbers:
        arg = model.arguments[k]
        kind = kinds[k]
        unit = arg.unit or getattr(model.units, kind)
        ends = []
        for key, value in (("from", arg.intermediate.start), ("to", arg.intermediate.to)):
            try:
                ends.append(to_si(value, kind, unit))
            except UnitProblem as exc:
                problems.append(Problem(("arguments", k, "intermediate", key),
                                        exc.message, exc.hint))
        if len(ends) < 2:
            continue
        if ends[0] == ends[1]:
            problems.append(Problem(("arguments", k, "intermediate", "to"), "the sweep "
                                    "starts and ends at the same value",
                                    "give 'to' different from 'from'"))
    names: set[str] = set()
    for i, env in enumerate(model.envelopes):
        path = ("envelopes", i)
        if env.name in names:
            problems.append(Problem((*path, "name"), f"envelope {env.name!r} is named twice",
                                    "give every envelope its own name"))
        names.add(env.name)
        missing = [n for n in env.vectors if n not in model.vectors]
        if missing:
            problems.append(Problem((*path, "vectors"), f"no vector {missing[0]} in the "
                                    "model", f"use vectors of {sorted(model.vectors)}"))
            continue
        if env.argument is None:
            if len(numbers) != 1:
                problems.append(Problem(path, "the model has no intermediate argument"
                                        if not numbers else "say which intermediate argument "
                                        "the envelope sweeps", "declare one: arguments: "
                                        "{K: {intermediate: {from: .., to: .., count: ..}}}"))
                continue
            k = numbers[0]
        elif env.argument not in numbers:
            problems.append(Problem((*path, "argument"), f"argument {env.argument} is not "
                                    "an intermediate argument",
                                    f"use one of {numbers}" if numbers else "declare it "
                                    "with {intermediate: {from: .., to: .., count: ..}}"))
            continue
        else:
            k = env.argument
        reached, _ = dependents(model, structure, k)
        if not {f"{letter}{n}" for n in env.vectors for letter in "ra"} & reached:
            problems.append(Problem((*path, "vectors"), f"the end of vectors {env.vectors} "
                                    f"does not depend on argument {k}: its curve is a "
                                    "single point in every position",
                                    "list the vectors up to one the intermediate argument "
                                    "turns or stretches (e.g. the roller's radius)"))
    return problems
