"""Existence between the positions for a contour without a closed form.

The existence margin of a contour — ``sin²`` of the angle between the two columns of its
Jacobian (Pl4: the two unknown vectors; Pl3: ``cos²`` of the rod to the guide; Pl2: the
signed sine between the two directions; Pl1: the closing length) — is taken at the solved
positions.  Wherever the sampled margin has a local minimum whose parabola through three
positions comes within :data:`SUSPICION` curvatures of zero, the minimum is located
between the positions by a zoom: :data:`ZOOM_POINTS` inputs per bracket, all candidates
of all designs solved together by the same closed-form modules
(:func:`~mechloop.solve.kinematics._solve_block`), the bracket narrowed around the least.
A point with no solution or a margin at or below :data:`THRESHOLD` is a break; its ends
are found by bisection when asked for.  Used by :mod:`.existence`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from mechloop.model.structure import ContourInfo
from mechloop.solve.designs import _extra_arguments, _with_extra_columns
from mechloop.solve.inputs import Signal
from mechloop.solve.kinematics import SINGULAR_SIN, _setup, _solve_block

if TYPE_CHECKING:
    from mechloop.solve.existence import ExistenceCheck, _Resolver

Array = NDArray[np.float64]

#: A margin at or below this is a break: ``sin² ≤ SINGULAR_SIN²`` is the sampled solve's
#: dead point (its Jacobian's sine below ``SINGULAR_SIN``).
THRESHOLD = SINGULAR_SIN ** 2
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


def between_positions(values: _Resolver, over: Mapping[str, Array],
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
    # a solved angle that a link ratio scales: its whole turns from the sampled positions
    turns = {k: v[cand] for k, v in values.items() if k in check.base.carried}
    best, hit = _zoom(check, over, rows[cand], which, contours,
                      lo, hi, size[cand], {n: s[cand] for n, s in signs.items()}, turns)
    np.minimum.at(least, rows[cand], best)
    lost = np.flatnonzero(best <= THRESHOLD)
    ends = np.stack([hit[lost], hit[lost]], axis=1)
    if extent and lost.size:
        ends = _edges(check, {k: v[rows[cand[lost]]] for k, v in over.items()}, hit[lost],
                      best[lost] < 0, {k: v[lost] for k, v in turns.items()})
    for j, (t0, t1) in zip(lost, ends, strict=True):
        start, stop = np.interp([t0, t1], np.arange(n_pos), x)
        found.append(BreakInterval(int(rows[cand[j]]), contours[which[j]].number,
                                   float(min(start, stop)), float(max(start, stop)),
                                   int(min(np.floor(t0), n_pos - 2)), False))
    return least, found


def _edges(check: ExistenceCheck, over: Mapping[str, Array], hit: Array,
           unsolved: NDArray[np.bool_], turns: Mapping[str, Array] | None = None) -> Array:
    """The ends (position numbers) of the breaks around the points ``hit`` ``(B,)``
    where the solve found no solution (``unsolved``), by bisection against the
    positions on either side (which assemble): ``(B, 2)``.  A break known only by its
    margin keeps its point."""
    left, right = np.floor(hit), np.ceil(hit)
    inner_left, inner_right = hit.copy(), hit.copy()
    for _ in range(48):  # a position / 2**48
        mid = np.stack([(left + inner_left) / 2, (inner_right + right) / 2], axis=1)
        _, broken = _solve_at(check, over, np.interp(mid, np.arange(check.args[1].value.size),
                                                     check.args[1].value),
                              _turns_at(turns, mid))
        inner_left = np.where(broken[:, 0], mid[:, 0], inner_left)
        left = np.where(broken[:, 0], left, mid[:, 0])
        inner_right = np.where(broken[:, 1], mid[:, 1], inner_right)
        right = np.where(broken[:, 1], right, mid[:, 1])
    return np.where(unsolved[:, None], np.stack([inner_left, inner_right], axis=1),
                    hit[:, None])


def _zoom(check: ExistenceCheck, over: Mapping[str, Array], designs: NDArray[np.int64],
          which: NDArray[np.int64], contours: list[ContourInfo], lo: Array, hi: Array, size: Array,
          signs: Mapping[int, Array], turns: Mapping[str, Array] | None = None
          ) -> tuple[Array, Array]:
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
                                   inputs, _turns_at({k: v[live] for k, v in
                                                      (turns or {}).items()}, t))
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


def _turns_at(turns: Mapping[str, Array] | None, t: Array) -> dict[str, Array] | None:
    """The sampled continuous values ``(R, P)`` of the solved angles a ratio scales,
    interpolated at the fractional positions ``t`` ``(R, K)``: where their whole turns are
    taken from (:mod:`mechloop.solve.turns`)."""
    if not turns:
        return None
    out = {}
    for name, v in turns.items():
        i = np.clip(np.floor(t).astype(np.int64), 0, v.shape[-1] - 2)
        w = t - i
        out[name] = (np.take_along_axis(v, i, axis=-1) * (1 - w)
                     + np.take_along_axis(v, i + 1, axis=-1) * w)
    return out


def _solve_at(check: ExistenceCheck, over: Mapping[str, Array], inputs: Array,
              turn_ref: Mapping[str, Array] | None = None
              ) -> tuple[dict[str, Array], NDArray[np.bool_]]:
    """Every parameter of designs ``over`` (rows ``(R,)``) at their own inputs of argument
    1, ``(R, K)``, positions only — the extra columns of
    :func:`~mechloop.solve.designs.solve_designs_at` without the regular positions."""
    extra_at = _extra_arguments(check.args, inputs)
    empty = np.empty(0)
    bare = {k: Signal(empty, empty, empty) for k in check.args}
    part = _setup(check.model, check.structure, bare, over)
    part = _with_extra_columns(part, bare, extra_at, 0, inputs.shape[0])
    if turn_ref:
        part = replace(part, turn_ref=turn_ref)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        block = _solve_block(part, 0, inputs.shape[1], inputs.shape, {}, derivatives=False)
    broken = np.zeros(inputs.shape, dtype=bool)
    for info in part.ordered:
        if info.number in block.jump:
            continue  # a coupled block is checked at the positions only (no start here)
        broken |= block.no_solution[info.number] | block.dead[info.number]
    values = {name: np.broadcast_to(p.value, inputs.shape) for name, p in
              block.params.items()}
    return values, broken
