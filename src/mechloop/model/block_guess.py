"""A contour's ``guess`` of the unknowns of the coupled block it is solved in: the values
it may give, checked and converted to SI — read alike for planar models
(:mod:`mechloop.model.structure`) and models with spatial contours
(:mod:`mechloop.spatial.blocks`)."""

from __future__ import annotations

from collections.abc import Sequence

from mechloop.errors import Problem
from mechloop.model.schema import Model
from mechloop.model.units import UnitProblem, to_si


def read_guess(model: Model, number: int, group: Sequence[int], unknowns: Sequence[str],
               guess: dict[str, float], problems: list[Problem]) -> None:
    """Add contour ``number``'s ``guess`` (1-based; the block holds the contours
    ``group`` and solves ``unknowns``) to ``guess``: each value in SI (m for a length
    ``r…``, rad for an angle), keyed by the unknown's name.  A name that is not one of
    ``unknowns``, or a value in units that do not apply, is a located problem."""
    contour = model.contours[number - 1]
    for name, value in (contour.guess or {}).items():
        path = ("contours", number - 1, "guess", name)
        if name not in unknowns:
            problems.append(Problem(path, f"{name} is not an unknown of the coupled block of "
                                    f"contours {', '.join(map(str, group))}",
                                    f"guess some of {', '.join(unknowns)}"))
            continue
        kind = "length" if name[0] == "r" else "angle"
        try:
            guess[name] = to_si(value, kind, getattr(model.units, kind))
        except UnitProblem as exc:
            problems.append(Problem(path, exc.message, exc.hint))
