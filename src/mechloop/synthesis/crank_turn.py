"""Whether the crank of a four-bar turns fully, decided in closed form for a population.

A contour solved by Pl4 (two unknown directions of the constant lengths ``L2``, ``L3``)
whose known vectors are constants and one crank — a vector of constant length ``r`` at
the angle of argument 1 plus an offset — closes where the known side
``K(θ) = c + r·e^{iθ}`` satisfies the triangle condition.  Over a full turn of the
crank ``|K|²`` runs through ``[(|c| − r)², (|c| + r)²]`` exactly (``A + B cos φ`` with
``A = |c|² + r²``, ``B = 2|c|r``), so the chain never breaks over the *continuous* input
if and only if the angle γ between the two unknown vectors keeps
``|sin γ| > SINGULAR_SIN`` at both ends of that range — the test the position solve
applies at a sample, by the law of cosines ``cos γ = (L2² + L3² − |K|²) / (2 L2 L3)``.
The share of the turn where it breaks follows in closed form as well (``arccos``).

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

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.model.check import require_valid
from mechloop.model.schema import Model
from mechloop.solve.inputs import model_arguments, model_time
from mechloop.solve.kinematics import SINGULAR_SIN, _setup

Array = NDArray[np.float64]

#: |cos γ| above this is a dead point (|sin γ| <= SINGULAR_SIN).
_COS_LIMIT = math.sqrt(1.0 - SINGULAR_SIN * SINGULAR_SIN)


@dataclass(frozen=True)
class _Loop:
    """One Pl4 contour driven by the crank: the names of its crank's length and angle,
    of its constant vectors (length, angle) and of the two unknown vectors' lengths."""

    crank: tuple[str, str]
    constants: tuple[tuple[str, str], ...]
    lengths: tuple[str, str]


@dataclass(frozen=True)
class TurnCheck:
    """The closed-form check of every Pl4 contour of a model, compiled once."""

    model: Model = field(repr=False)
    loops: tuple[_Loop, ...]
    structure: object = field(repr=False)
    args: dict = field(repr=False)

    def __call__(self, overrides: Mapping[str, ArrayLike], designs: int
                 ) -> tuple[NDArray[np.bool_], Array]:
        """Whether each of ``designs`` designs (``overrides`` as for
        :func:`~mechloop.solve.designs.solve_designs`) turns fully with no break in any
        checked contour, ``(D,)``, and the share of the turn where it breaks, ``(D,)``
        (the largest over the contours; 0 where it turns)."""
        structure = self.structure
        setup = _setup(self.model, structure, self.args, overrides)
        turns = np.ones(designs, dtype=bool)
        share = np.zeros(designs)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            for loop in self.loops:
                c = sum((_value(setup, structure, r) * np.exp(1j * _value(setup, structure, a))
                         for r, a in loop.constants), np.zeros(1, dtype=complex))
                r = np.abs(_value(setup, structure, loop.crank[0]))
                l2 = np.abs(_value(setup, structure, loop.lengths[0]))
                l3 = np.abs(_value(setup, structure, loop.lengths[1]))
                m = np.abs(c)
                a, b = m * m + r * r, 2 * m * r
                mid, half = l2 * l2 + l3 * l3, 2 * l2 * l3 * _COS_LIMIT
                upper, lower = mid + half, mid - half
                ok = (upper > a + b) & (lower < a - b) & (l2 > 0) & (l3 > 0)
                # share of φ where A + B cos φ > upper, and where it is < lower
                above = np.arccos(np.clip((upper - a) / b, -1.0, 1.0)) / np.pi
                below = 1.0 - np.arccos(np.clip((lower - a) / b, -1.0, 1.0)) / np.pi
                part = np.where(ok, 0.0, np.nan_to_num(np.clip(above + below, 0, 1), nan=1.0))
                part = np.where(~ok & (part == 0), 1.0 / 360, part)  # a touch still breaks
                turns &= np.broadcast_to(ok, turns.shape)
                share = np.maximum(share, np.broadcast_to(part, share.shape))
        return turns, share


def _value(setup, structure, name: str) -> Array | float:
    """A constant parameter's value per design, ``(D,)`` or a float."""
    if name in setup.constants:
        value = setup.constants[name]
    else:
        value = setup.link_value(name, setup.constants[structure.links[name].root])
    return value[:, 0] if isinstance(value, np.ndarray) else value


def compile_turn_check(model: Model) -> TurnCheck | None:
    """The closed-form check for ``model`` or None when it does not apply: every contour
    must be a Pl4 driven by one crank on argument 1 (which runs through a full turn
    over the positions, one way) with constants otherwise, or a Pl1 contour."""
    structure = require_valid(model)
    if 1 not in model.arguments:
        return None
    args = model_arguments(model, model_time(model), strict=False)
    values = args[1].value
    steps = np.diff(values)
    if not ((steps >= 0).all() or (steps <= 0).all()) \
            or np.ptp(values) < 2 * np.pi * (1 - 1e-12):
        return None
    setup = _setup(model, structure, args)
    loops = []
    for info in structure.ordered():
        if info.module == "Pl1":
            continue
        if info.module != "Pl4" or info.variant == "auto":
            return None
        crank, constants = None, []
        for number in info.vectors:
            r, a = f"r{number}", f"a{number}"
            if a in info.functions:
                if _root(structure, r) not in setup.constants:
                    return None
                continue
            if _root(structure, r) not in setup.constants:
                return None
            root = _root(structure, a)
            if root in setup.constants:
                constants.append((r, a))
            elif root in setup.driven and crank is None and a == root \
                    and args[1] is setup.driven[root][0]:
                crank = (r, a)
            else:
                return None
        if crank is None:
            return None
        lengths = tuple(f"r{f[1:]}" for f in info.functions)
        loops.append(_Loop(crank, tuple(constants), lengths))
    return TurnCheck(model, tuple(loops), structure, args) if loops else None


def _root(structure, name: str) -> str:
    return structure.links[name].root if name in structure.links else name


__all__ = ["TurnCheck", "compile_turn_check"]
