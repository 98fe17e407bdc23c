"""Whether the crank of a four-bar turns fully, decided in closed form for a population.

The contours are recognized by :func:`mechloop.solve.existence.crank_loops` — the one
recognizer of crank-driven loops, which :mod:`mechloop.solve.existence` uses for its
closed-form verdict — and their margin over a whole turn comes from
:func:`mechloop.solve.loop_forms.turn_share`: a four-bar loop (a Pl4 contour whose known
side is ``K(θ) = c·e^{iθ} + k·e^{iκ}``) closes while ``|K|²``, which runs through
``[(k − c)², (k + c)²]`` over a turn, keeps the angle γ between the two unknown vectors
at ``sin² γ > THRESHOLD`` (the test the position solve applies at a sample); the share of
the turn where it breaks follows in closed form as well (``arccos``).

With a fixed assembly variant and no break the Jacobian's sign cannot change, so such
a design keeps its variant over the whole turn.

Synthesis takes its feasibility verdict from :mod:`mechloop.solve.existence` (which
has the same closed form, the degenerate links and the four-bar type conditions); this
module tells it that a model needs no solved positions for that verdict — a model it
does not recognise (another module with an unknown, a crank that does not turn fully, an
input other than argument 1) gets ``None`` from :func:`compile_turn_check`, and synthesis
then solves every position — and gives the share of the turn where an infeasible design
breaks, which ranks infeasible designs in the search.  A Pl1 contour (the closing vector
to a traced point) has a solution wherever that vector has a length.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.model.schema import Model
from mechloop.solve.existence import THRESHOLD, ExistenceCheck
from mechloop.solve.loop_forms import turn_share

Array = NDArray[np.float64]


@dataclass(frozen=True)
class TurnCheck:
    """The closed-form check of the crank-driven four-bar contours of a model (their
    numbers ``contours``), compiled once."""

    check: ExistenceCheck = field(repr=False)
    contours: frozenset[int]

    def __call__(self, overrides: Mapping[str, ArrayLike], designs: int
                 ) -> tuple[NDArray[np.bool_], Array]:
        """Whether each of ``designs`` designs (``overrides`` as for
        :func:`~mechloop.solve.designs.solve_designs`) turns fully with no break in any
        checked contour, ``(D,)``, and the share of the turn where it breaks, ``(D,)``
        (the largest over the contours; 0 where it turns)."""
        turns = np.ones(designs, dtype=bool)
        share = np.zeros(designs)
        for loop in self.check.loops(overrides):
            if loop.info.number in self.contours:
                ok, part = turn_share(loop, THRESHOLD)
                turns &= np.broadcast_to(ok, turns.shape)
                share = np.maximum(share, np.broadcast_to(part, share.shape))
        return turns, share


def compile_turn_check(model: Model) -> TurnCheck | None:
    """The closed-form check for ``model`` or None when it does not apply: every contour
    must be a four-bar loop driven by one crank on argument 1 (which runs through a full
    turn over the positions, one way) with a fixed variant, or a Pl1 contour."""
    check = ExistenceCheck(model)
    if 1 not in check.args:
        return None
    values = check.args[1].value
    steps = np.diff(values)
    if not ((steps >= 0).all() or (steps <= 0).all()) \
            or np.ptp(values) < 2 * np.pi * (1 - 1e-12):
        return None
    found = {loop.info.number for loop in check.loops()
             if loop.kind == "four-bar" and loop.argument == 1}
    for info in check.base.ordered:
        if info.module != "Pl1" and (info.number not in found or info.variant == "auto"):
            return None
    return TurnCheck(check, frozenset(found)) if found else None


__all__ = ["TurnCheck", "compile_turn_check"]
