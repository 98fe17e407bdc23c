"""Does every contour assemble over the *whole* continuous input interval?

A solve looks at the positions only; a chain may break between two of them (a four-bar
just past Grashof's limit loses its toggle for a fraction of a degree).  This module
decides existence over the continuous motion, for ``D`` designs at once
(:func:`assembles_throughout`):

* **Closed forms** (:mod:`.loop_forms`): a four-bar or slider-crank loop driven by a crank
  is decided exactly from its dimensions over the argument's whole range.
* **Any other contour** (:mod:`.between`): its existence margin (``sin²`` of the angle
  between the columns of its Jacobian) is located between the positions wherever its
  sampled minimum comes near zero, by a vectorized zoom with the same closed-form
  modules; a point with no solution, a dead point, or a sign change of a Pl2 margin is
  a break.
* A **degenerate link** — a rotating vector of constant length below :data:`DEGENERATE`
  times the largest constant length of the design — makes a design infeasible.

The continuous motion between positions ``i`` and ``i + 1`` is argument 1 running linearly
from its value at ``i`` to its value at ``i + 1``, any other argument interpolated over
argument 1 (exact for tables; a law is followed through its sampled values, and a crank
loop is decided over the range of the argument's values at the positions).  A contour
with ``variant: auto`` is checked itself (its margin does not depend on the variant); a
contour that needs one (directly or through others) is checked at the positions only,
since which variant holds between two positions is not known: give such contours a fixed
variant for the check between positions.

A **coupled block** (contours solved together by Newton's continuation,
:mod:`mechloop.modules.coupled`) is checked between positions as one: its margin is
``±ρ²``, ``ρ = |det J| / Π ‖column‖`` of the block Jacobian (scale-free, the sine between
the columns for a 2×2 block), signed positive on the branch followed
(:class:`~mechloop.solve.blocks.BlockMargin`); its minima are located like the others',
and the zoom solves the block at each intermediate input by Newton's method started
from the line through the two solved points around it (the continuation's predictor),
on the branch's determinant sign.  Where Newton does not converge, meets a singular
Jacobian, lands on the other sign or jumps farther than the continuation allows, the
block breaks.  Contours that need a block are checked between positions too (the zoom
solves the block first).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.model.check import require_valid
from mechloop.model.schema import Model
from mechloop.model.structure import ContourInfo, Structure, param_role
from mechloop.solve.between import (
    THRESHOLD,
    BreakInterval,
    Sampled,
    between_positions,
)
from mechloop.solve.blocks import BlockMargin
from mechloop.solve.inputs import Signal, model_arguments, model_time
from mechloop.solve.kinematics import _constant_si, _Setup, _setup
from mechloop.solve.loop_forms import CrankLoop, least_margin, lost_intervals

Array = NDArray[np.float64]

#: A rotating link shorter than this times the design's largest constant length is
#: degenerate (a crank of 3e-15 mm does not turn anything).
DEGENERATE = 1e-6

__all__ = ["DEGENERATE", "THRESHOLD", "BreakInterval", "Existence", "ExistenceCheck",
           "Sampled", "assembles_throughout", "crank_loops", "four_bar_type_holds"]


@dataclass(frozen=True)
class Existence:
    """The verdict for ``D`` designs.

    ``feasible`` ``(D,)``: every contour assembles at every input of the continuous
    interval and no link is degenerate; ``margin`` ``(D,)``: the smallest existence margin
    found (≤ :data:`THRESHOLD` where the design breaks; −1 for a break located by a point
    with no solution); ``degenerate`` ``(D,)``; ``breaks``: the intervals (only when asked
    for, ``intervals=True``).
    """

    feasible: NDArray[np.bool_]
    margin: Array
    degenerate: NDArray[np.bool_]
    breaks: tuple[BreakInterval, ...] = field(default_factory=tuple)


def assembles_throughout(model: Model, overrides: Mapping[str, ArrayLike] | None = None,
                         *, samples: Sampled | None = None,
                         intervals: bool = False) -> Existence:
    """Decide for every design whether the model assembles over the whole input interval.

    ``overrides`` are as in :func:`~mechloop.solve.designs.solve_designs` (SI, ``(D,)``).
    ``samples`` are the designs already solved at the model's positions (values only are
    read); they are needed only for contours without a closed form and are solved here
    (positions only) when not given.  With ``intervals=True`` the break intervals are
    listed too (a loop over the broken designs; the verdict itself is vectorized).
    Compiling the model is most of the cost for a few designs: to check many
    populations of one model, build an :class:`ExistenceCheck` once and call it.
    """
    from mechloop.model.spatial import refuse_spatial

    refuse_spatial(model, "the existence check over the input interval")
    return ExistenceCheck(model)(overrides, samples=samples, intervals=intervals)


class ExistenceCheck:
    """:func:`assembles_throughout` compiled for one model: call it with ``overrides``
    (and ``samples``, ``intervals``) for each population.  ``structure`` and ``args`` (the
    model's arguments as :func:`~mechloop.solve.inputs.model_arguments` gives them) and
    ``setup`` (compiled from them without overrides) may be passed by a caller that has
    them."""

    def __init__(self, model: Model, *, structure: Structure | None = None,
                 args: Mapping[int, Signal] | None = None, setup: _Setup | None = None):
        self.model = model
        self.structure = structure if structure is not None else require_valid(model)
        self.args = dict(args) if args is not None else model_arguments(
            model, model_time(model), strict=False)
        self.base = setup if setup is not None else _setup(model, self.structure, self.args)
        self.chains: dict[str, list[tuple[str, float]]] = {}
        self.own_delta: dict[str, float] = {}
        for name, chain in self.structure.links.items():
            current, path, factor = name, [], 1.0
            while current != chain.root:  # each link with the ratio its delta is scaled by
                role = param_role(model, current)
                path.append((current, factor))
                self.own_delta[current] = _constant_si(model, current, role.delta)
                factor *= role.ratio
                current = role.link
            self.chains[name] = path
        # the coupled blocks, each checked as one (its margin from its Jacobian)
        self.block_margins = [BlockMargin(b, self.base) for b in self.structure.blocks
                              if b.coupled]
        in_block = {n: b.block.contours for b in self.block_margins
                    for n in b.block.contours}
        by_number = {c.number: c for c in self.structure.contours}
        # contours that need an elementary contour with a tracked variant, directly or not
        # (a block's contours together: a block follows its assembly by continuity)
        self.after_auto: set[int] = set()
        for info in self.base.ordered:  # in solving order: needs come first
            needs = {n for c in in_block.get(info.number, (info.number,))
                     for n in by_number[c].needs} - set(in_block.get(info.number, ()))
            if any((by_number[n].variant == "auto" and n not in in_block)
                   or n in self.after_auto for n in needs):
                self.after_auto.add(info.number)
        self.in_block = set(in_block)
        self.argument_of = {root: next(k for k, sig in self.args.items() if sig is signal)
                            for root, (signal, _) in self.base.driven.items()}

    def __call__(self, overrides: Mapping[str, ArrayLike] | None = None, *,
                 samples: Sampled | None = None, intervals: bool = False) -> Existence:
        """The verdict for the population ``overrides`` (see :func:`assembles_throughout`);
        a design whose numbers overflow is infeasible, with no warning."""
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            return self._decide(overrides, samples, intervals)

    def _decide(self, overrides: Mapping[str, ArrayLike] | None, samples: Sampled | None,
                intervals: bool) -> Existence:
        model, structure, args = self.model, self.structure, self.args
        over = {k: np.atleast_1d(np.asarray(v, dtype=float))
                for k, v in (overrides or {}).items()}
        n_designs = next(iter(over.values())).shape[0] if over else (
            samples.broken.shape[0] if samples is not None else 1)
        values = _Resolver(self, over, n_designs)
        degenerate = _degenerate(values)
        margin = np.full(n_designs, np.inf)
        breaks: list[BreakInterval] = []

        loops = {loop.info.number: loop for loop in crank_loops(values)}
        for loop in loops.values():
            x = args[loop.argument].value
            lo, hi = float(x.min()), float(x.max())
            least = least_margin(loop, np.full(n_designs, lo), np.full(n_designs, hi))
            margin = np.minimum(margin, least)
            if intervals:
                for d in np.flatnonzero(least <= THRESHOLD):
                    for start, stop in lost_intervals(loop, int(d), lo, hi, THRESHOLD):
                        breaks.append(BreakInterval(int(d), loop.info.number, start, stop,
                                                    _after(x, start), True))

        generic: list = [info for info in self.base.ordered if info.number not in loops
                         and info.number not in self.in_block
                         and _checked(info, structure) and info.number not in self.after_auto]
        generic += [b for b in self.block_margins if b.number not in self.after_auto]
        if generic and 1 in args:
            if samples is None:
                from mechloop.solve.designs import solve_designs

                samples = solve_designs(model, over, derivatives=False)
            # a design broken at a position is infeasible already: its positions between
            # are looked at only when the intervals are asked for
            active = margin > THRESHOLD
            if not intervals:
                active &= ~samples.broken.any(axis=-1)
            least, found = between_positions(values, over, samples, generic, active,
                                              extent=intervals)
            margin = np.minimum(margin, least)
            if intervals:
                breaks.extend(found)
        if samples is not None:
            margin = np.where(samples.broken.any(axis=-1), np.minimum(margin, -1.0), margin)
        margin = np.where(degenerate | np.isnan(margin), np.minimum(margin, -1.0), margin)
        margin = np.where(np.isnan(margin), -1.0, margin)
        feasible = margin > THRESHOLD
        return Existence(feasible, margin, degenerate,
                         tuple(sorted(breaks, key=lambda b: (b.design, b.start, b.contour))))


    def loops(self, overrides: Mapping[str, ArrayLike] | None = None) -> list[CrankLoop]:
        """The crank loops of the model (:func:`crank_loops`) for the population
        ``overrides`` (one design without)."""
        over = {k: np.atleast_1d(np.asarray(v, dtype=float))
                for k, v in (overrides or {}).items()}
        n_designs = next(iter(over.values())).shape[0] if over else 1
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            return crank_loops(_Resolver(self, over, n_designs))


class _Resolver:
    """The values per design ``(D,)`` of the parameters that are constant over positions
    (constants, links of constants) and the offsets of driven angles, for one
    population ``over``."""

    def __init__(self, check: ExistenceCheck, over: Mapping[str, Array], n_designs: int):
        self.check, self.over, self.n_designs = check, over, n_designs
        self.ordered = check.base.ordered
        self._known: dict[str, Array | None] = {}

    def _delta(self, name: str) -> Array | float:
        return sum((factor * self.over.get(link, self.check.own_delta[link])
                    for link, factor in self.check.chains.get(name, ())), 0.0)

    def _scale(self, name: str) -> float:
        return float(self.check.base.scales.get(name, 1.0))

    def _root(self, name: str) -> str:
        links = self.check.structure.links
        return links[name].root if name in links else name

    def _rows(self, value: Array | float) -> Array:
        return np.broadcast_to(np.asarray(value, dtype=float), (self.n_designs,))

    def value(self, name: str) -> Array | None:
        """A parameter constant over positions, per design; None for any other."""
        if name not in self._known:
            found = None
            if name in self.check.base.constant:
                root = self._root(name)
                found = self._rows(self._scale(name)
                                   * self.over.get(root, self.check.base.constants[root])
                                   + self._delta(name))
            self._known[name] = found
        return self._known[name]

    def driven(self, name: str) -> tuple[int, Array] | None:
        """(argument, offset per design) when angle ``name`` is an argument plus a
        constant; None otherwise (an angle linked with a ratio ≠ 1 turns at another speed:
        it is no rigid part of a crank)."""
        root = self._root(name)
        if root not in self.check.base.driven or self._scale(name) != 1:
            return None
        offset = self.over.get(root, self.check.base.driven[root][1])
        return self.check.argument_of[root], self._rows(offset + self._delta(name))

    def lengths(self) -> dict[int, Array]:
        """|length| per design of every vector whose length is constant."""
        numbers = sorted(self.check.model.vectors)
        found = {n: self.value(f"r{n}") for n in numbers}
        return {n: np.abs(v) for n, v in found.items() if v is not None}


def _after(values: Array, where: float) -> int:
    """The position ``i`` whose segment ``[values[i], values[i+1]]`` first holds
    ``where`` (the last position if none does)."""
    lo = np.minimum(values[:-1], values[1:])
    hi = np.maximum(values[:-1], values[1:])
    inside = np.flatnonzero((lo <= where) & (where <= hi))
    return int(inside[0]) if inside.size else int(values.size - 1)


def crank_loops(values: _Resolver) -> list[CrankLoop]:
    """The contours that :mod:`.loop_forms` decides in closed form (four-bars and
    slider-cranks driven by a crank), per design: every known vector is constant but
    those of constant length whose angle is one argument plus a constant — together
    one crank, ``c·e^{i(θ + offset)}`` with ``c e^{i·offset} = Σ r e^{i·offset_j}``."""
    n_designs = values.n_designs
    loops = []
    for info in values.ordered:
        if info.module not in ("Pl3", "Pl4"):
            continue
        v1, v2 = (int(u[1:]) for u in info.functions)
        rest: Array | complex = 0.0 + 0.0j
        turning: Array | complex = 0.0 + 0.0j
        cranks: list[int] = []
        argument = None
        for n in (n for n in info.vectors if n not in (v1, v2)):
            r, a = values.value(f"r{n}"), values.value(f"a{n}")
            if r is not None and a is not None:
                rest = rest + r * np.exp(1j * a)
                continue
            driven = values.driven(f"a{n}")
            if r is None or driven is None or argument not in (None, driven[0]):
                break
            argument = driven[0]
            turning = turning + r * np.exp(1j * driven[1])
            cranks.append(n)
        else:
            if not cranks:
                continue
            if info.module == "Pl4":
                r1, r2 = values.value(f"r{v1}"), values.value(f"r{v2}")
                guide = np.zeros(n_designs)
            else:
                r1 = np.zeros(n_designs)
                r2, guide = values.value(f"r{v2}"), values.value(f"a{v1}")
            if r1 is None or r2 is None or guide is None:
                continue
            order = list(info.vectors)
            at = order.index(cranks[0])
            neighbours = {order[at - 1], order[(at + 1) % len(order)]}
            coupler = v1 if v1 in neighbours or v2 not in neighbours else v2
            turning = np.broadcast_to(turning, (n_designs,))
            rest = np.broadcast_to(rest, (n_designs,))
            loops.append(CrankLoop(
                info=info, kind="four-bar" if info.module == "Pl4" else "slider-crank",
                crank=cranks[0], argument=argument, offset=np.angle(turning),
                c=np.abs(turning), k=np.abs(rest), kappa=np.angle(rest), r1=r1, r2=r2,
                guide=guide, coupler=coupler, rocker=v2 if coupler == v1 else v1))
    return loops


def _degenerate(values: _Resolver) -> NDArray[np.bool_]:
    """Designs with a rotating link of constant length below :data:`DEGENERATE` times the
    design's largest constant length (a link: a vector of a Pl3/Pl4 loop whose angle
    changes, or a vector whose angle an argument drives)."""
    lengths = values.lengths()
    bad = np.zeros(values.n_designs, dtype=bool)
    if not lengths:
        return bad
    size = np.max(np.stack(list(lengths.values())), axis=0)
    base = values.check.base
    loops = {n for info in base.ordered if info.module in ("Pl3", "Pl4")
             for n in info.vectors}
    driven = {int(name[1:]) for name in base.driven if name[0] == "a"}
    for number, length in lengths.items():
        rotates = f"a{number}" not in base.constant
        if number in driven or (rotates and number in loops):
            bad |= length <= DEGENERATE * size
    return bad


def _checked(info: ContourInfo, structure: Structure) -> bool:
    """Whether a contour without a closed form is checked between positions: every
    Pl2–Pl4, and a Pl1 whose direction another contour reads (through a link)."""
    if info.module != "Pl1":
        return True
    return any(chain.root == info.functions[1] for chain in structure.links.values())


def four_bar_type_holds(model: Model | ExistenceCheck,
                        overrides: Mapping[str, ArrayLike] | None = None, *,
                        grashof: str = "any", crank_shortest: bool = False
                        ) -> NDArray[np.bool_]:
    """Whether each design's crank-driven four-bar loops are of the type asked for
    (closed form, from the four lengths: crank, frame — the distance between the fixed
    pivots —, coupler and rocker), ``(D,)``.

    ``grashof``: ``"any"``; ``"grashof"`` (``s + l ≤ p + q``); ``"crank-rocker"`` (Grashof,
    the crank shortest); ``"double-crank"`` (Grashof, the frame shortest);
    ``"double-rocker"`` (Grashof, the coupler shortest); ``"non-grashof"``
    (``s + l > p + q``).  ``crank_shortest``: the crank is the shortest of the four.
    Raises :class:`~mechloop.errors.ModelError` when the model has no four-bar loop
    driven by a crank of constant length.
    """
    from mechloop.errors import ModelError, Problem
    from mechloop.solve.loop_forms import grashof_class

    check = model if isinstance(model, ExistenceCheck) else ExistenceCheck(model)
    over = {k: np.atleast_1d(np.asarray(v, dtype=float)) for k, v in (overrides or {}).items()}
    n_designs = next(iter(over.values())).shape[0] if over else 1
    loops = [loop for loop in crank_loops(_Resolver(check, over, n_designs))
             if loop.kind == "four-bar"]
    if not loops:
        key = "grashof" if grashof != "any" else "crank_shortest"
        raise ModelError([Problem(("synthesis", key), "the model has no four-bar loop "
                                  "driven by a crank (a Pl4 contour whose only moving "
                                  "known vector is a constant length turned by an "
                                  "argument), so its four-bar type is undefined",
                                  f"remove '{key}', or model the four-bar as one contour "
                                  "crank, coupler, rocker, frame")])
    ok = np.ones(n_designs, dtype=bool)
    for loop in loops:
        is_grashof, shortest = grashof_class(loop)
        wanted = {"any": np.ones(n_designs, dtype=bool), "grashof": is_grashof,
                  "non-grashof": ~is_grashof,
                  "crank-rocker": is_grashof & (shortest == "crank"),
                  "double-crank": is_grashof & (shortest == "frame"),
                  "double-rocker": is_grashof & (shortest == "coupler")}[grashof]
        ok &= wanted
        if crank_shortest:
            ok &= shortest == "crank"
    return ok
