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

A coupled block (:class:`~mechloop.solve.blocks.BlockMargin`: its margin ``±ρ²`` from the
block Jacobian) has no closed form to solve a free-standing input with: the zoom solves it
by Newton's method from the line through the two solved points around each input (the
samples, then the zoom's own points), on the branch's determinant sign, and the bisection
from the last point found assembled on either side (:func:`_predict`, :func:`_solve_at`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

from mechloop.model.structure import ContourInfo
from mechloop.modules.coupled import JUMP_ANGLE, JUMP_LENGTH
from mechloop.solve.blocks import BlockMargin
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


def contour_margins(info: ContourInfo | BlockMargin, values: Mapping[str, Array],
                    size: Array, sign: Array | None = None) -> Array:
    """The existence margin of a contour from its solved values, shape of the values:
    Pl4 ``sin²(α1 − α2)``, Pl3 ``cos²(α2 − α_guide)``, Pl2 ``sign·sin(α1 − α2)`` (``sign``
    makes it positive at the first position), Pl1 the closing length over ``size``; a
    coupled block (:class:`~mechloop.solve.blocks.BlockMargin`) ``sign·sign(det J)·ρ²``
    (``sign`` the branch's)."""
    if isinstance(info, BlockMargin):
        raw = info.raw(values)
        return raw if sign is None or info.tracked else raw * sign
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
    branches, raws = {}, {}  # every coupled block: its branch's sign per row (the zoom's
    for block in check.block_margins:  # starts) and its unsigned margin at the samples
        raws[block.number] = block.raw(values)
        branches[block.block.number] = block.branch(raws[block.number])
    for ci, info in enumerate(contours):
        sign = None
        if info.module == "Pl2":
            first = contour_margins(info, {k: v[:, :1] for k, v in values.items()}, size)
            sign = np.where(first < 0, -1.0, 1.0)
            signs[info.number] = sign
        elif isinstance(info, BlockMargin):
            sign = branches[info.block.number]
            signs[info.number] = sign
        if isinstance(info, BlockMargin):  # already at hand
            m = raws[info.number] if info.tracked else raws[info.number] * sign
        else:
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
    # the coupled blocks' solutions at the bracket's ends and middle: the zoom's anchors
    mid = np.clip(np.round((lo + hi) / 2), 0, n_pos - 1).astype(np.int64)
    at = np.stack([lo, mid, hi], axis=1)
    anchors = {b.block.number: (at.astype(float), _unknowns_at(b, values, cand, at.astype(
        np.int64)), branches[b.block.number][cand, 0]) for b in check.block_margins}
    best, hit = _zoom(check, over, rows[cand], which, contours, lo, hi, size[cand],
                      {n: s[cand] for n, s in signs.items()}, anchors, turns)
    np.minimum.at(least, rows[cand], best)
    lost = np.flatnonzero(best <= THRESHOLD)
    ends = np.stack([hit[lost], hit[lost]], axis=1)
    if extent and lost.size:
        sides = {}  # per block: the samples either side of the point found, and the sign
        for b in check.block_margins:
            t = np.stack([np.floor(hit[lost]), np.ceil(hit[lost])], axis=1).astype(np.int64)
            u = _unknowns_at(b, values, cand[lost], t)
            sides[b.block.number] = (u, branches[b.block.number][cand[lost], 0],
                                     _limit(b, u[:, 0], u[:, 1], size[cand[lost]]))
        ends = _edges(check, {k: v[rows[cand[lost]]] for k, v in over.items()}, hit[lost],
                      best[lost] < 0, sides, {k: v[lost] for k, v in turns.items()})
    for j, (t0, t1) in zip(lost, ends, strict=True):
        start, stop = np.interp([t0, t1], np.arange(n_pos), x)
        found.append(BreakInterval(int(rows[cand[j]]), contours[which[j]].number,
                                   float(min(start, stop)), float(max(start, stop)),
                                   int(min(np.floor(t0), n_pos - 2)), False))
    return least, found


def _unknowns_at(block: BlockMargin, values: Mapping[str, Array], rows: NDArray[np.int64],
                 at: NDArray[np.int64]) -> Array:
    """A coupled block's unknowns in the samples ``values`` (rows ``(R, P)``) at rows
    ``rows`` ``(n,)`` and positions ``at`` ``(n, A)``: ``(n, A, m)``."""
    return np.stack([np.asarray(values[u])[rows[:, None], at] for u in block.unknowns],
                    axis=-1)


def _wrapped(block: BlockMargin, d: Array) -> Array:
    """Differences of the block's unknowns ``(..., m)`` with the angles' in [−π, π)."""
    return np.where(block.angle, (d + np.pi) % (2 * np.pi) - np.pi, d)


def _limit(block: BlockMargin, u0: Array, u1: Array, size: Array) -> Array:
    """How far a solution may lie from its predictor and stay on the branch, ``(n, m)``
    from two solved neighbours ``(n, m)``: twice their distance, at least
    :data:`~mechloop.modules.coupled.JUMP_ANGLE` (an angle) or
    :data:`~mechloop.modules.coupled.JUMP_LENGTH` of ``size`` ``(n, 1)`` (a length) —
    the continuation's own jump test."""
    floor = np.where(block.angle, JUMP_ANGLE, JUMP_LENGTH * size)
    return np.maximum(2 * np.abs(_wrapped(block, u1 - u0)), floor)


def _predict(block: BlockMargin, t_at: Array, u_at: Array, t: Array, size: Array
             ) -> tuple[Array, Array]:
    """The block's predictor at the points ``t`` ``(n, K)`` (position numbers) from its
    solutions ``u_at`` ``(n, A, m)`` at the sorted anchors ``t_at`` ``(n, A)``: the line
    through the two anchors around each point (the continuation's secant predictor), and
    the jump limit (:func:`_limit`) of that pair, each ``(n, K, m)``."""
    a = t_at.shape[1]
    k = np.clip((t_at[:, None, :] <= t[:, :, None]).sum(axis=-1) - 1, 0, a - 2)
    rows = np.arange(t.shape[0])[:, None]
    t0, t1 = t_at[rows, k], t_at[rows, k + 1]
    u0, u1 = u_at[rows, k], u_at[rows, k + 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(t1 > t0, (t - t0) / (t1 - t0), 0.0)
    pred = u0 + w[..., None] * _wrapped(block, u1 - u0)
    limit = _limit(block, u0.reshape(-1, u0.shape[-1]), u1.reshape(-1, u1.shape[-1]),
                   np.repeat(size, t.shape[1], axis=0)).reshape(pred.shape)
    return pred, limit


def _edges(check: ExistenceCheck, over: Mapping[str, Array], hit: Array,
           unsolved: NDArray[np.bool_],
           sides: Mapping[int, tuple[Array, Array, Array]] | None = None,
           turns: Mapping[str, Array] | None = None) -> Array:
    """The ends (position numbers) of the breaks around the points ``hit`` ``(B,)``
    where the solve found no solution (``unsolved``), by bisection against the
    positions on either side (which assemble): ``(B, 2)``.  A break known only by its
    margin keeps its point.  ``sides`` (per coupled block: its unknowns at the positions
    either side ``(B, 2, m)``, its branch's sign ``(B,)`` and the jump limit ``(B, m)``)
    start each bisection point of a block from the last point found assembled on its
    side: the continuation from that position towards the break."""
    sides = dict(sides or {})
    left, right = np.floor(hit), np.ceil(hit)
    inner_left, inner_right = hit.copy(), hit.copy()
    x = check.args[1].value
    for _ in range(48):  # a position / 2**48
        mid = np.stack([(left + inner_left) / 2, (inner_right + right) / 2], axis=1)
        starts = {n: (u, np.stack([sign, sign], axis=1), np.stack([lim, lim], axis=1))
                  for n, (u, sign, lim) in sides.items()}
        values, broken = _solve_at(check, over, np.interp(mid, np.arange(x.size), x),
                                   starts, _turns_at(turns, mid))
        inner_left = np.where(broken[:, 0], mid[:, 0], inner_left)
        left = np.where(broken[:, 0], left, mid[:, 0])
        inner_right = np.where(broken[:, 1], mid[:, 1], inner_right)
        right = np.where(broken[:, 1], right, mid[:, 1])
        for n, (u, sign, lim) in sides.items():
            names = next(b for b in check.block_margins if b.block.number == n).unknowns
            got = np.stack([values[name] for name in names], axis=-1)
            keep = ~broken[..., None] & np.isfinite(got)
            sides[n] = (np.where(keep, got, u), sign, lim)
    return np.where(unsolved[:, None], np.stack([inner_left, inner_right], axis=1),
                    hit[:, None])


def _zoom(check: ExistenceCheck, over: Mapping[str, Array], designs: NDArray[np.int64],
          which: NDArray[np.int64], contours: list[ContourInfo | BlockMargin], lo: Array,
          hi: Array, size: Array, signs: Mapping[int, Array],
          anchors: Mapping[int, tuple[Array, Array, Array]] | None = None,
          turns: Mapping[str, Array] | None = None
          ) -> tuple[Array, Array]:
    """Locate the least margin of each candidate (design, contour, bracket of position
    numbers ``[lo, hi]``) by zooming: ``ZOOM_POINTS`` inputs per bracket solved per step
    for all candidates at once, the bracket narrowed around the least.  Returns the least
    margin per candidate (−1 where a point had no solution) and the position number
    (fractional) where it was found.

    ``anchors`` (per coupled block: position numbers ``(n, 3)`` holding ``lo``, a middle
    point and ``hi``, the block's solutions there ``(n, 3, m)``, and its branch's sign
    ``(n,)``) let the zoom solve the blocks: each point starts Newton's method from the
    line through the two solved points around it (:func:`_predict`), on the branch's
    determinant sign; a point where it does not converge, lands on the other sign or
    farther than the jump limit from its predictor is a break.  Each step's new
    anchors are its least point and the two around it, all solved."""
    n = lo.size
    x = check.args[1].value
    positions = np.arange(x.size, dtype=float)
    best = np.full(n, np.inf)
    where = (lo + hi) / 2
    active = np.ones(n, dtype=bool)
    frac = np.arange(1, ZOOM_POINTS + 1) / (ZOOM_POINTS + 1)
    anchors = {k: (t.copy(), u.copy(), sign) for k, (t, u, sign) in (anchors or {}).items()}
    by_number = {b.block.number: b for b in check.block_margins}
    for _ in range(ZOOM_STEPS):
        live = np.flatnonzero(active)
        if live.size == 0:
            break
        t = lo[live, None] + (hi[live] - lo[live])[:, None] * frac[None, :]
        inputs = np.interp(t, positions, x)
        starts = {}
        for k, (t_at, u_at, sign) in anchors.items():
            pred, limit = _predict(by_number[k], t_at[live], u_at[live], t, size[live])
            starts[k] = (pred, np.broadcast_to(sign[live, None], t.shape), limit)
        values, broken = _solve_at(check, {k: v[designs[live]] for k, v in over.items()},
                                   inputs, starts, _turns_at({k: v[live] for k, v in
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
        every_t = np.concatenate([lo[live, None], t, hi[live, None]], axis=1)
        pick = j[:, None] + np.arange(3)[None, :]  # the least point and its neighbours
        for k, (t_at, u_at, _) in anchors.items():
            got = np.stack([values[u] for u in by_number[k].unknowns], axis=-1)
            every_u = np.concatenate([u_at[live, :1], got, u_at[live, -1:]], axis=1)
            t_at[live] = np.take_along_axis(every_t, pick, axis=1)
            u_at[live] = every_u[np.arange(live.size)[:, None], pick]
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
              starts: Mapping[int, tuple[Array, Array, Array]] | None = None,
              turn_ref: Mapping[str, Array] | None = None
              ) -> tuple[dict[str, Array], NDArray[np.bool_]]:
    """Every parameter of designs ``over`` (rows ``(R,)``) at their own inputs of argument
    1, ``(R, K)``, positions only — the extra columns of
    :func:`~mechloop.solve.designs.solve_designs_at` without the regular positions.

    A coupled block is solved only with ``starts`` for it (its number -> the start
    ``(R, K, m)``, the branch's determinant sign ``(R, K)`` and the jump limit
    ``(R, K, m)``); where its start is not finite (no solution known around) it is not
    counted, nor is a block without starts; elsewhere a point where Newton's method does
    not converge, meets a singular Jacobian, lands on the other sign or farther than the
    limit from the start is broken."""
    starts = starts or {}
    extra_at = _extra_arguments(check.args, inputs)
    empty = np.empty(0)
    bare = {k: Signal(empty, empty, empty) for k in check.args}
    part = _setup(check.model, check.structure, bare, over)
    part = _with_extra_columns(part, bare, extra_at, 0, inputs.shape[0])
    part = replace(part, block_starts={k: (u, sign) for k, (u, sign, _) in starts.items()})
    if turn_ref:
        part = replace(part, turn_ref=turn_ref)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        block = _solve_block(part, 0, inputs.shape[1], inputs.shape, {}, derivatives=False)
    broken = np.zeros(inputs.shape, dtype=bool)
    margins = {b.block.number: b for b in check.block_margins}
    for info in part.ordered:
        if info.number in block.jump:
            continue  # a coupled block: once per block, below
        broken |= block.no_solution[info.number] | block.dead[info.number]
    values = {name: np.broadcast_to(p.value, inputs.shape) for name, p in
              block.params.items()}
    for number, (u, _, limit) in starts.items():
        first = margins[number].number
        given = np.isfinite(u).all(axis=-1)
        got = np.stack([values[name] for name in margins[number].unknowns], axis=-1)
        with np.errstate(invalid="ignore"):
            far = (np.abs(_wrapped(margins[number], got - u)) > limit).any(axis=-1)
        lost = (block.no_solution[first] | block.dead[first] | block.jump[first] | far)
        broken |= lost & given
    return values, broken
