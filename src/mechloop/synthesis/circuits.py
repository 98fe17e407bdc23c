"""Both assembly circuits in one synthesis run (``synthesis.circuits``).

A contour solved by a module with two solutions (Pl3, Pl4) has two assembly circuits,
its ``variant`` 1 or 2.  With ``circuits: both`` (every such contour with a fixed
variant) or ``circuits: [3, 5]`` (those contours), the circuit is a design choice: every
design is evaluated on each combination of circuits, ``2^C`` for ``C`` chosen contours,
and keeps the better one (the least total).

Why evaluate every circuit rather than add a rounded column to the design matrix: the
objective the search sees is then the pointwise minimum over the circuits, a function of
the continuous variables alone, so DE, CMA-ES (which has no integer variables) and the
local polish run unchanged; a rounded column would make a discrete jump that a
population must sample and a local search cannot cross.  The price is ``2^C`` solves
per design (one for each circuit, each a whole vectorized population).

Each combination is a :class:`~mechloop.synthesis.problem.SynthesisProblem` of its own
(the model with those variants, its task with ``circuits: given``); the choice per
design is reported as a measure ``variantK`` (1 or 2) and written into the model.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import ModelError, Problem
from mechloop.model.schema import Model

if TYPE_CHECKING:
    from mechloop.synthesis.problem import Evaluation, SynthesisProblem

Array = NDArray[np.float64]

#: Modules whose contour has two assembly circuits.
TWO_CIRCUITS = ("Pl3", "Pl4")


def chosen_contours(model: Model) -> list[int]:
    """The contours (numbers from 1) whose circuit the synthesis chooses: every contour
    of a two-circuit module with a fixed variant (``both``), or the listed ones, which
    must be of such a module (else :class:`~mechloop.errors.ModelError`, located)."""
    from mechloop.model.check import require_valid

    circuits = model.synthesis.circuits
    if circuits == "given":
        return []
    modules = {info.number: info.module for info in require_valid(model).ordered()}
    if circuits == "both":
        return [n for n in sorted(modules) if modules[n] in TWO_CIRCUITS
                and model.contours[n - 1].variant != "auto"]
    problems = [Problem(("synthesis", "circuits", i), f"contour {n} is solved by "
                        f"{modules.get(n, 'no module')}, which has one circuit",
                        "list contours of Pl3 or Pl4 modules")
                for i, n in enumerate(circuits) if modules.get(n) not in TWO_CIRCUITS]
    if problems:
        raise ModelError(problems)
    return sorted(set(circuits))


def circuit_problems(problem: SynthesisProblem) -> list[tuple[dict[int, int],
                                                               SynthesisProblem]]:
    """One sub-problem per combination of circuits of the chosen contours: ``(variants,
    problem)`` with ``variants`` contour -> 1 or 2; empty when no circuit is chosen."""
    from mechloop.synthesis.problem import SynthesisProblem

    model = problem.model
    contours = chosen_contours(model)
    if not contours:
        return []
    task = model.synthesis.model_copy(update={"circuits": "given"})
    out = []
    for combo in itertools.product((1, 2), repeat=len(contours)):
        variants = dict(zip(contours, combo, strict=True))
        changed = [c.model_copy(update={"variant": variants[i + 1]})
                   if i + 1 in variants else c for i, c in enumerate(model.contours)]
        sub = model.model_copy(update={"contours": changed, "synthesis": task})
        out.append((variants, SynthesisProblem(sub, task)))
    return out


def evaluate_best(subs: list[tuple[dict[int, int], SynthesisProblem]], designs: Array,
                  *, continuous: bool = False) -> tuple[Evaluation, NDArray[np.int64]]:
    """Every design on every circuit, the better kept: the combined evaluation (each
    field from the circuit of least total, ``measures['variantK']`` its variant) and the
    index of that circuit per design, ``(D,)``."""
    from mechloop.synthesis.problem import Evaluation

    evs = [sub.evaluate(designs, continuous=continuous) for _, sub in subs]
    choice = np.argmin(np.stack([ev.total for ev in evs]), axis=0)

    rows = np.arange(designs.shape[0])

    def pick(values: list[NDArray]) -> NDArray:
        return np.stack(values)[choice, rows]

    measures = {key: pick([ev.measures[key] for ev in evs]) for key in evs[0].measures}
    for contour in subs[0][0]:
        measures[f"variant{contour}"] = pick([np.full(designs.shape[0], float(v[contour]))
                                              for v, _ in subs])
    combined = Evaluation(
        total=pick([ev.total for ev in evs]), q=pick([ev.q for ev in evs]),
        feasible=pick([ev.feasible for ev in evs]),
        broken_share=pick([ev.broken_share for ev in evs]),
        keeps_variant=pick([ev.keeps_variant for ev in evs]),
        terms={key: pick([ev.terms[key] for ev in evs]) for key in evs[0].terms},
        measures=measures)
    return combined, choice


def residuals_best(subs: list[tuple[dict[int, int], SynthesisProblem]], designs: Array,
                   *, continuous: bool = False) -> Array:
    """The residuals of each design on the circuit where their sum of squares (what a
    least-squares polish minimizes) is least, ``(D, R)``."""
    res = np.stack([sub.residuals(designs, continuous=continuous)
                    for _, sub in subs])  # (C, D, R)
    choice = np.argmin(np.sum(res * res, axis=-1), axis=0)
    return np.take_along_axis(res, choice[None, :, None], axis=0)[0]
