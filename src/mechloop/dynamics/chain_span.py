"""The stretch of a one-input machine's positions that the chain passes through without a
break, around the start of a motion in time, and where exactly it ends.

A chain that breaks somewhere in the input's range (a four-bar whose crank cannot turn
fully) can move only between two breaks.  The motion in time
(:mod:`mechloop.dynamics.simulate`) integrates over the positions of that stretch and stops
at its last position with the event ``"chain break ahead"``, naming the input value where
the chain breaks.  That value comes from the exact existence check over the continuous
range (:func:`~mechloop.solve.existence.assembles_throughout`: in closed form for a crank
loop, by bisection between positions otherwise), not from the grid of positions.  A
position where only the force analysis is singular (a dead point) ends a stretch at that
position itself (``exact`` False: no finer boundary is computed).

A model whose positions are whole turns of the input wraps around: the stretch may run
from the last positions of the cycle (shifted by one turn down) into its first ones.
Units SI: rad (or m for a sliding input).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import ModelError, Problem

Array = NDArray[np.float64]


@dataclass(frozen=True)
class ChainEnd:
    """Where the chain breaks beyond an end of the stretch: ``q`` the input value (rad)
    where assembly is lost, ``last`` the input at the stretch's last position before it
    (rad), ``exact`` whether ``q`` is in closed form (a crank loop's limit; else located by
    bisection between the positions to 1e-14 of a step, or for a singular force analysis
    the singular position itself),
    ``contour`` the contour that breaks (0: the force analysis is singular)."""

    q: float
    last: float
    exact: bool
    contour: int

    def describe(self, angle: bool = True, lang: str = "en") -> str:
        """In words, with the input in degrees (or m), in ``lang`` ('en' or 'ru': the
        decimal comma)."""
        if lang == "ru":
            from mechloop.views.decimal_mark import localized

            shown = (lambda x: f"{math.degrees(x):.8g}°") if angle else (
                lambda x: f"{x:.8g} м")
            how = (f"контур {self.contour} не собирается" if self.contour else
                   "силовой расчёт вырожден")
            return localized(f"цепь разрывается при входе {shown(self.q)} ({how}"
                             f"{'; в замкнутом виде' if self.exact else ''}); движение "
                             f"известно до последнего положения перед разрывом, "
                             f"{shown(self.last)}", lang)
        shown = (lambda x: f"{math.degrees(x):.8g} deg") if angle else (
            lambda x: f"{x:.8g} m")
        how = (f"contour {self.contour} cannot be assembled" if self.contour else
               "the force analysis is singular")
        return (f"the chain breaks at input {shown(self.q)} ({how}"
                f"{'; closed form' if self.exact else ''}); the motion is known up "
                f"to the last position before it, {shown(self.last)}")


@dataclass(frozen=True)
class Span:
    """The unbroken stretch: ``index`` the model's positions in order (shape (S,)),
    ``q`` the input there (rad, increasing: a wrapped stretch shifted by whole turns),
    ``lower``/``upper`` the breaks beyond its ends (None: the range ends there)."""

    index: NDArray[np.int64]
    q: Array
    lower: ChainEnd | None
    upper: ChainEnd | None


def unbroken_span(model, kin, k: int, singular: NDArray[np.bool_], q0: float, *,
                  whole: bool) -> Span:
    """The stretch of positions around the start ``q0`` (rad) that the chain passes
    through without a break.

    ``kin`` the model's kinematics, ``k`` the input's argument, ``singular`` (P+1,) the
    positions where the force analysis is singular, ``whole`` whether the positions are
    whole turns (the stretch may wrap).  Raises :class:`ModelError` at ``simulate.start``
    when the start is at a break or the stretch has fewer than 4 positions.
    """
    from mechloop.solve.existence import assembles_throughout

    q = np.asarray(kin.arguments[k], dtype=float)
    a1 = np.asarray(kin.arguments[min(kin.arguments)], dtype=float)
    broken = np.asarray(kin.broken, dtype=bool) | np.asarray(singular, dtype=bool)
    n = q.size - 1  # segments 0..n-1
    period = float(q[-1] - q[0])
    breaks = assembles_throughout(model, intervals=True).breaks

    def to_q(value: float, i: int) -> float:
        """Argument 1's ``value`` inside segment ``i`` as the input (linear between the
        positions, the existence check's own convention)."""
        if min(kin.arguments) == k:
            return float(value)
        f = (value - a1[i]) / (a1[i + 1] - a1[i])
        return float(q[i] + f * (q[i + 1] - q[i]))

    # the breaks met in each segment (i, i+1): the first lost value going up, the last
    # going down, and the contour
    up: dict[int, tuple[float, int, bool]] = {}
    down: dict[int, tuple[float, int, bool]] = {}
    lo_a, hi_a = np.minimum(a1[:-1], a1[1:]), np.maximum(a1[:-1], a1[1:])
    for brk in breaks:
        hit = np.flatnonzero((hi_a >= brk.start) & (lo_a <= brk.stop))
        for i in hit.tolist():
            start, stop = to_q(max(brk.start, lo_a[i]), i), to_q(min(brk.stop, hi_a[i]), i)
            start, stop = min(start, stop), max(start, stop)
            if i not in up or start < up[i][0]:
                up[i] = (start, brk.contour, brk.exact)
            if i not in down or stop > down[i][0]:
                down[i] = (stop, brk.contour, brk.exact)
    cut = np.array([broken[i] or broken[i + 1] or i in up for i in range(n)])

    def wrap(index: int) -> tuple[int, float]:
        """Position and shift (rad) of an unrolled index."""
        if not whole:
            return index, 0.0
        turns, pos = divmod(index, n)
        return pos, turns * period

    start = q0
    if whole:
        start = q[0] + (q0 - q[0]) % period
    seg = int(np.clip(np.searchsorted(q, start, side="right") - 1, 0, n - 1))
    at_position = bool(np.isclose(start, q[seg], rtol=0, atol=1e-12 * max(period, 1.0)))
    if broken[seg] if at_position else cut[seg]:
        raise ModelError([Problem(("simulate", "start"), f"the motion starts at a chain "
                                  f"break (input {_deg(q0)}, position {seg}"
                                  f"{'' if at_position else f' to {seg + 1}'})",
                                  "start where the chain assembles (mechloop solve lists "
                                  "the broken positions)")])
    shift0 = q0 - start  # whole turns between the model's cycle and the start
    # the stretch holds the positions lo..hi (unrolled over turns when whole)
    lo, hi = seg, seg if at_position else seg + 1
    limit = 2 * n
    while hi - lo < limit:  # upwards
        pos, _ = wrap(hi)
        if (not whole and hi >= n) or cut[pos]:
            break
        hi += 1
    while hi - lo < limit:  # downwards
        pos, _ = wrap(lo - 1)
        if (not whole and lo <= 0) or cut[pos]:
            break
        lo -= 1
    unrolled = np.arange(lo, hi + 1)
    pos = np.array([wrap(int(i))[0] for i in unrolled])
    values = np.array([q[p] + wrap(int(i))[1] for p, i in zip(pos, unrolled, strict=True)])
    if whole:  # position n is position 0 a turn on
        pos = np.where(pos == n, 0, pos)
    values = values + shift0

    def end(segment_index: int, going_up: bool, last: float) -> ChainEnd | None:
        if not whole and not 0 <= segment_index < n:
            return None
        s, moved = wrap(segment_index)
        shift = moved + shift0
        table = up if going_up else down
        if s in table:
            value, contour, closed = table[s]
            return ChainEnd(float(value + shift), last, closed, contour)
        singular_at = s + 1 if going_up else s
        if not broken[singular_at]:
            singular_at = s if going_up else s + 1
        return ChainEnd(float(q[singular_at]) + shift, last, False,
                        _contour_at(kin, singular_at))

    upper = end(hi, True, float(values[-1]))
    lower = end(lo - 1, False, float(values[0]))
    if values.size < 4:
        raise ModelError([Problem(("simulate", "start"), f"the chain assembles at only "
                                  f"{values.size} position(s) around the start (input "
                                  f"{_deg(q0)}) before it breaks: too few to read the "
                                  "machine between them", "give more positions (a finer "
                                  "step) or start elsewhere")])
    return Span(pos.astype(np.int64), values, lower, upper)


def _contour_at(kin, position: int) -> int:
    """The contour that breaks at ``position`` (0: none, the force analysis is singular)."""
    for brk in kin.breaks:
        if position in np.asarray(brk.positions).tolist():
            return int(brk.contour)
    return 0


def _deg(q: float) -> str:
    return f"{math.degrees(q):.6g} deg"
