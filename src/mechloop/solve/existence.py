"""Does every contour assemble over the *whole* continuous input interval?

A solve looks at the positions only; a chain may break between two of them (a four-bar
just past Grashof's limit loses its toggle for a fraction of a degree).  This module
decides existence over the continuous motion, for ``D`` designs at once
(:func:`assembles_throughout`):

* **Closed forms** (:mod:`.loop_forms`): a four-bar or slider-crank loop driven by a crank
  is decided exactly from its dimensions over the argument's whole range.
* **Any other contour**: its existence margin — ``sin²`` of the angle between the two
  columns of its Jacobian (Pl4: the two unknown vectors; Pl3: ``cos²`` of the rod to the
  guide; Pl2: the signed sine between the two directions; Pl1: the closing length, when a
  later contour reads its direction) — is taken at the solved positions; wherever the
  sampled margin has a local minimum whose parabola through three samples comes within a
  few curvatures of zero, the minimum is located between the positions by a vectorized
  zoom (9 points per step, all candidates of all designs in one solve per step) with the
  same closed-form modules at those inputs.  A point found with no solution, a margin at
  or below :data:`THRESHOLD` (the sampled solve's dead-point test), or a sign change of a
  Pl2 margin is a break.
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
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.model.check import require_valid
from mechloop.model.schema import Model
from mechloop.model.structure import ContourInfo, Structure, param_role
from mechloop.solve.designs import _extra_arguments, _with_extra_columns
from mechloop.solve.inputs import Signal, model_arguments, model_time
from mechloop.solve.kinematics import (
    SINGULAR_SIN,
    _constant_si,
    _Setup,
    _setup,
    _solve_block,
)
from mechloop.solve.loop_forms import CrankLoop, least_margin, lost_intervals

Array = NDArray[np.float64]

#: A margin at or below this is a break: ``sin² ≤ SINGULAR_SIN²`` is the sampled solve's
#: dead point (its Jacobian's sine below ``SINGULAR_SIN``).
THRESHOLD = SINGULAR_SIN ** 2
#: A rotating link shorter than this times the design's largest constant length is
#: degenerate (a crank of 3e-15 mm does not turn anything).
DEGENERATE = 1e-6
#: Points per zoom step, and zoom steps at most (a bracket of two positions shrinks by
#: 5 per step: 14 steps reach 3.3e-10 of a position).
ZOOM_POINTS = 9
ZOOM_STEPS = 14
#: A sampled local minimum is refined when its parabola's minimum is below this many
#: second differences (the parabola's own curvature scale) above the threshold.
SUSPICION = 2.0


class Sampled(Protocol):
    """Designs solved at the model's positions: ``values`` (name -> ``(D, P)``, SI, NaN
    where broken) and ``broken`` ``(D, P)`` —
    a :class:`~mechloop.solve.designs.DesignResults`, or a single solve's arrays with a
    leading axis of one."""

    values: Mapping[str, Array]
    broken: NDArray[np.bool_]


@dataclass(frozen=True)
class BreakInterval:
    """Where a design's contour cannot be assembled: argument 1 in ``[start, stop]``
    (SI: rad or m).  ``after`` is the position ``i`` such that the break begins between
    positions ``i`` and ``i + 1`` (or at ``i``); ``exact`` tells a closed-form interval
    from one located between positions (its ends by bisection to 1e-14 of a position;
    a break known by its margin alone, or a sign change of a Pl2 contour, gives the
    point found or the two positions)."""

    design: int
    contour: int
    start: float
    stop: float
    after: int
    exact: bool


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
        self.chains: dict[str, list[str]] = {}
        self.own_delta: dict[str, float] = {}
        for name, chain in self.structure.links.items():
            current, path = name, []
            while current != chain.root:
                role = param_role(model, current)
                path.append(current)
                self.own_delta[current] = _constant_si(model, current, role.delta)
                current = role.link
            self.chains[name] = path
        # contours that need a contour with a tracked variant, directly or not
        self.after_auto: set[int] = set()
        for info in self.base.ordered:  # in solving order: needs come first
            if any(self.structure.contours[n - 1].variant == "auto" or n in self.after_auto
                   for n in info.needs):
                self.after_auto.add(info.number)
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

        generic = [info for info in self.base.ordered if info.number not in loops
                   and _checked(info, structure) and info.number not in self.after_auto]
        if generic and 1 in args:
            if samples is None:
                from mechloop.solve.designs import solve_designs

                samples = solve_designs(model, over, derivatives=False)
            # a design broken at a position is infeasible already: its positions between
            # are looked at only when the intervals are asked for
            active = margin > THRESHOLD
            if not intervals:
                active &= ~samples.broken.any(axis=-1)
            least, found = _between_positions(values, over, samples, generic, active,
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


class _Resolver:
    """The values per design ``(D,)`` of the parameters that are constant over positions
    (constants, links of constants) and the offsets of driven angles, for one
    population ``over``."""

    def __init__(self, check: ExistenceCheck, over: Mapping[str, Array], n_designs: int):
        self.check, self.over, self.n_designs = check, over, n_designs
        self.ordered = check.base.ordered
        self._known: dict[str, Array | None] = {}

    def _delta(self, name: str) -> Array | float:
        return sum((self.over.get(link, self.check.own_delta[link])
                    for link in self.check.chains.get(name, ())), 0.0)

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
                found = self._rows(self.over.get(root, self.check.base.constants[root])
                                   + self._delta(name))
            self._known[name] = found
        return self._known[name]

    def driven(self, name: str) -> tuple[int, Array] | None:
        """(argument, offset per design) when angle ``name`` is an argument plus a
        constant; None otherwise."""
        root = self._root(name)
        if root not in self.check.base.driven:
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


def contour_margins(info: ContourInfo, values: Mapping[str, Array], size: Array,
                    sign: Array | None = None) -> Array:
    """The existence margin of a contour from its solved values, shape of the values:
    Pl4 ``sin²(α1 − α2)``, Pl3 ``cos²(α2 − α_guide)``, Pl2 ``sign·sin(α1 − α2)`` (``sign``
    makes it positive at the first position), Pl1 the closing length over ``size``."""
    u1, u2 = info.functions
    if info.module == "Pl4":
        return np.sin(values[u1] - values[u2]) ** 2
    if info.module == "Pl3":
        return np.cos(values[u2] - values[f"a{u1[1:]}"]) ** 2
    if info.module == "Pl2":
        s = np.sin(values[f"a{u1[1:]}"] - values[f"a{u2[1:]}"])
        return s if sign is None else s * sign
    return values[u1] / size


def _between_positions(values: _Resolver, over: Mapping[str, Array],
                       samples: Sampled, contours: list[ContourInfo],
                       active: NDArray[np.bool_], *, extent: bool = False
                       ) -> tuple[Array, list[BreakInterval]]:
    """The generic check: the least margin per design ``(D,)`` over ``contours`` between
    the positions of ``samples``, and the breaks found there (with ``extent``, each from
    where it begins to where it ends, else the point found)."""
    check = values.check
    args = check.args
    n_designs, n_pos = samples.broken.shape
    least = np.full(n_designs, np.inf)
    found: list[BreakInterval] = []
    rows = np.flatnonzero(active)
    if rows.size == 0 or n_pos < 2:
        return least, found
    x = args[1].value
    size = np.ones((rows.size, 1))
    lengths = values.lengths()
    if lengths:
        size = np.maximum(np.max(np.stack(list(lengths.values())), axis=0)[rows],
                          1e-300)[:, None]
    values = {k: v[rows] for k, v in samples.values.items()}
    cand_row, cand_contour, cand_lo, cand_hi = [], [], [], []
    signs: dict[int, Array] = {}
    for ci, info in enumerate(contours):
        sign = None
        if info.module == "Pl2":
            first = contour_margins(info, {k: v[:, :1] for k, v in values.items()}, size)
            sign = np.where(first < 0, -1.0, 1.0)
            signs[info.number] = sign
        m = contour_margins(info, values, size, sign)  # NaN at a broken position
        least[rows] = np.minimum(least[rows], np.where(np.isnan(m), np.inf, m).min(axis=-1))
        # sign changes (Pl2) are breaks between the positions found as they are
        with np.errstate(invalid="ignore"):
            crossed = (m[:, :-1] > THRESHOLD) & (m[:, 1:] <= 0)
        for r, i in zip(*np.nonzero(crossed), strict=True):
            least[rows[r]] = min(least[rows[r]], -1.0)
            found.append(BreakInterval(int(rows[r]), info.number, float(x[i]),
                                       float(x[i + 1]), int(i), False))
        # sampled local minima whose parabola comes near zero: candidates for the zoom
        padded = np.concatenate([m[:, 1:2], m, m[:, -2:-1]], axis=1)
        left, mid, right = padded[:, :-2], padded[:, 1:-1], padded[:, 2:]
        with np.errstate(invalid="ignore"):
            minimum = (mid <= left) & (mid <= right) & (mid > THRESHOLD)
        with np.errstate(divide="ignore", invalid="ignore"):
            second = np.maximum(left - 2 * mid + right, 0.0)
            vertex = mid - np.where(second > 0, (right - left) ** 2 / (8 * second), 0.0)
            suspect = minimum & (vertex <= THRESHOLD + SUSPICION * second)
            # a minimum clearly away from zero: its parabola's vertex is the estimate
            calm = np.where(minimum & ~suspect, vertex, np.inf).min(axis=-1)
        least[rows] = np.minimum(least[rows], calm)
        r_idx, p_idx = np.nonzero(suspect)
        cand_row.append(r_idx)
        cand_contour.append(np.full(r_idx.size, ci))
        cand_lo.append(np.maximum(p_idx - 1, 0).astype(float))
        cand_hi.append(np.minimum(p_idx + 1, n_pos - 1).astype(float))
    cand = np.concatenate(cand_row)
    if cand.size == 0:
        return least, found
    which = np.concatenate(cand_contour)
    lo, hi = np.concatenate(cand_lo), np.concatenate(cand_hi)
    best, hit = _zoom(check, over, rows[cand], which, contours,
                      lo, hi, size[cand], {n: s[cand] for n, s in signs.items()})
    np.minimum.at(least, rows[cand], best)
    lost = np.flatnonzero(best <= THRESHOLD)
    ends = np.stack([hit[lost], hit[lost]], axis=1)
    if extent and lost.size:
        ends = _edges(check, {k: v[rows[cand[lost]]] for k, v in over.items()}, hit[lost],
                      best[lost] < 0)
    for j, (t0, t1) in zip(lost, ends, strict=True):
        start, stop = np.interp([t0, t1], np.arange(n_pos), x)
        found.append(BreakInterval(int(rows[cand[j]]), contours[which[j]].number,
                                   float(min(start, stop)), float(max(start, stop)),
                                   int(min(np.floor(t0), n_pos - 2)), False))
    return least, found


def _edges(check: ExistenceCheck, over: Mapping[str, Array], hit: Array,
           unsolved: NDArray[np.bool_]) -> Array:
    """The ends (position numbers) of the breaks around the points ``hit`` ``(B,)``
    where the solve found no solution (``unsolved``), by bisection against the
    positions on either side (which assemble): ``(B, 2)``.  A break known only by its
    margin keeps its point."""
    left, right = np.floor(hit), np.ceil(hit)
    inner_left, inner_right = hit.copy(), hit.copy()
    for _ in range(48):  # a position / 2**48
        mid = np.stack([(left + inner_left) / 2, (inner_right + right) / 2], axis=1)
        _, broken = _solve_at(check, over, np.interp(mid, np.arange(check.args[1].value.size),
                                                     check.args[1].value))
        inner_left = np.where(broken[:, 0], mid[:, 0], inner_left)
        left = np.where(broken[:, 0], left, mid[:, 0])
        inner_right = np.where(broken[:, 1], mid[:, 1], inner_right)
        right = np.where(broken[:, 1], right, mid[:, 1])
    return np.where(unsolved[:, None], np.stack([inner_left, inner_right], axis=1),
                    hit[:, None])


def _zoom(check: ExistenceCheck, over: Mapping[str, Array], designs: NDArray[np.int64],
          which: NDArray[np.int64], contours: list[ContourInfo], lo: Array, hi: Array, size: Array,
          signs: Mapping[int, Array]) -> tuple[Array, Array]:
    """Locate the least margin of each candidate (design, contour, bracket of position
    numbers ``[lo, hi]``) by zooming: ``ZOOM_POINTS`` inputs per bracket solved per step
    for all candidates at once, the bracket narrowed around the least.  Returns the least
    margin per candidate (−1 where a point had no solution) and the position number
    (fractional) where it was found."""
    n = lo.size
    x = check.args[1].value
    positions = np.arange(x.size, dtype=float)
    best = np.full(n, np.inf)
    where = (lo + hi) / 2
    active = np.ones(n, dtype=bool)
    frac = np.arange(1, ZOOM_POINTS + 1) / (ZOOM_POINTS + 1)
    for _ in range(ZOOM_STEPS):
        live = np.flatnonzero(active)
        if live.size == 0:
            break
        t = lo[live, None] + (hi[live] - lo[live])[:, None] * frac[None, :]
        inputs = np.interp(t, positions, x)
        values, broken = _solve_at(check, {k: v[designs[live]] for k, v in over.items()},
                                   inputs)
        margin = np.empty(t.shape)
        for ci, info in enumerate(contours):
            mine = which[live] == ci
            if mine.any():
                sign = signs.get(info.number)
                margin[mine] = contour_margins(
                    info, {k: v[mine] for k, v in values.items()}, size[live][mine],
                    None if sign is None else sign[live][mine])
        margin = np.where(broken, -1.0, margin)
        j = np.argmin(margin, axis=1)
        low = margin[np.arange(live.size), j]
        better = low < best[live]
        best[live] = np.where(better, low, best[live])
        where[live] = np.where(better, t[np.arange(live.size), j], where[live])
        step = (hi[live] - lo[live]) / (ZOOM_POINTS + 1)
        centre = t[np.arange(live.size), j]
        lo[live], hi[live] = centre - step, centre + step
        # stop: a break found, or a minimum clearly away from zero for its curvature
        left = margin[np.arange(live.size), np.maximum(j - 1, 0)]
        right = margin[np.arange(live.size), np.minimum(j + 1, ZOOM_POINTS - 1)]
        second = np.maximum(left - 2 * low + right, 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            vertex = low - np.where(second > 0, (right - left) ** 2 / (8 * second), 0.0)
        done = (low <= THRESHOLD) | (vertex > THRESHOLD + SUSPICION * second)
        calm = done & (low > THRESHOLD)  # the vertex of a fine parabola: the estimate
        best[live[calm]] = np.minimum(best[live[calm]], vertex[calm])
        active[live[done]] = False
    return best, where


def _solve_at(check: ExistenceCheck, over: Mapping[str, Array], inputs: Array
              ) -> tuple[dict[str, Array], NDArray[np.bool_]]:
    """Every parameter of designs ``over`` (rows ``(R,)``) at their own inputs of argument
    1, ``(R, K)``, positions only — the extra columns of
    :func:`~mechloop.solve.designs.solve_designs_at` without the regular positions."""
    extra_at = _extra_arguments(check.args, inputs)
    empty = np.empty(0)
    bare = {k: Signal(empty, empty, empty) for k in check.args}
    part = _setup(check.model, check.structure, bare, over)
    part = _with_extra_columns(part, bare, extra_at, 0, inputs.shape[0])
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        block = _solve_block(part, 0, inputs.shape[1], inputs.shape, {}, derivatives=False)
    broken = np.zeros(inputs.shape, dtype=bool)
    for info in part.ordered:
        broken |= block.no_solution[info.number] | block.dead[info.number]
    values = {name: np.broadcast_to(p.value, inputs.shape) for name, p in
              block.params.items()}
    return values, broken


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
