"""Closed-form existence of a crank-driven loop over a whole input interval.

A contour is a *crank loop* when everything it knows is constant but one vector of
constant length ``c`` whose angle is the input ``θ`` (an argument plus an offset): its known
sum is ``c·e^{iθ} + K`` with ``K = k·e^{iκ}`` constant.  Two such loops have closed forms:

* **four-bar** (Pl4, unknown angles of vectors of lengths ``r1, r2``): the loop closes
  where ``q = |c e^{iθ} + K|² = c² + k² + 2ck·cos(θ − κ)`` lies in
  ``[(r1 − r2)², (r1 + r2)²]``.  Its margin ``M = ((r1 + r2)² − q)(q − (r1 − r2)²) /
  (4 r1² r2²)`` is ``sin²`` of the angle between the two unknown vectors (the Jacobian's
  sine) where the loop closes and negative where it does not; concave in ``q``, so its
  minimum over an interval of ``θ`` is at the extreme ``q``.  Over a full turn this is
  Grashof's condition with the crank the shortest link, ``s + l ≤ p + q``.
* **slider-crank** (Pl3, the unknown length on a fixed guide of direction ``α``, the
  unknown angle on a rod of length ``l``): the offset ``y = c·sin(θ − α) + k·sin(κ − α)``
  must satisfy ``|y| ≤ l``; the margin ``M = 1 − y²/l²`` is ``cos²`` of the rod's angle to
  the guide (the Jacobian's sine).  Over a full turn: ``c + |e| ≤ l``.

Everything is an array over designs ``(D,)``; the interval of the input may be anything
(a full turn, or the range a rocking crank is driven over).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.model.structure import ContourInfo

Array = NDArray[np.float64]
TWO_PI = 2.0 * np.pi


@dataclass(frozen=True)
class CrankLoop:
    """A contour solvable in closed form over the input interval, arrays ``(D,)`` (SI).

    ``crank`` is the driven vector's number, ``argument`` the argument driving it,
    ``offset`` the angle added to the argument (its offset plus any link delta), ``c``
    its length, ``k`` and ``kappa`` the modulus and angle of the constant rest of the known
    sum.  For a four-bar ``r1, r2`` are the lengths of the two vectors of unknown angle
    (``coupler`` is the number of the one next to the crank in the contour, ``rocker`` the
    other); for a slider-crank ``r2`` is the rod and ``guide`` the guide's direction.
    """

    info: ContourInfo
    kind: str  # "four-bar" or "slider-crank"
    crank: int
    argument: int
    offset: Array
    c: Array
    k: Array
    kappa: Array
    r1: Array
    r2: Array
    guide: Array
    coupler: int
    rocker: int


def cos_range(lo: Array, hi: Array, phase: Array) -> tuple[Array, Array]:
    """Smallest and largest ``cos(θ − phase)`` for ``θ`` in ``[lo, hi]`` (rad), ``(D,)``."""
    ends = np.stack([np.cos(lo - phase), np.cos(hi - phase)])
    least, most = ends.min(axis=0), ends.max(axis=0)
    top = np.floor((hi - phase) / TWO_PI) >= np.ceil((lo - phase) / TWO_PI)
    bottom = (np.floor((hi - phase - np.pi) / TWO_PI)
              >= np.ceil((lo - phase - np.pi) / TWO_PI))
    return np.where(bottom, -1.0, least), np.where(top, 1.0, most)


def four_bar_margin(q: Array, r1: Array, r2: Array) -> Array:
    """``((r1 + r2)² − q)(q − (r1 − r2)²) / (4 r1² r2²)`` for ``q = p²``."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return ((r1 + r2) ** 2 - q) * (q - (r1 - r2) ** 2) / (4.0 * r1 * r1 * r2 * r2)


def least_margin(loop: CrankLoop, lo: Array, hi: Array) -> Array:
    """The smallest existence margin of ``loop`` for the argument in ``[lo, hi]``, ``(D,)``:
    ``sin²`` (four-bar) or ``cos²`` (slider-crank) of the Jacobian's angle where the loop
    closes, negative where it cannot (NaN-free; a degenerate length gives −1)."""
    theta_lo, theta_hi = lo + loop.offset, hi + loop.offset
    with np.errstate(divide="ignore", invalid="ignore"):
        if loop.kind == "four-bar":
            cmin, cmax = cos_range(theta_lo, theta_hi, loop.kappa)
            base = loop.c ** 2 + loop.k ** 2
            twice = 2.0 * loop.c * loop.k
            margin = np.minimum(four_bar_margin(base + twice * cmin, loop.r1, loop.r2),
                                four_bar_margin(base + twice * cmax, loop.r1, loop.r2))
        else:
            smin, smax = cos_range(theta_lo, theta_hi, loop.guide + np.pi / 2)
            rest = loop.k * np.sin(loop.kappa - loop.guide)
            worst = np.maximum(np.abs(loop.c * smin + rest), np.abs(loop.c * smax + rest))
            margin = 1.0 - (worst / loop.r2) ** 2
    return np.where(np.isfinite(margin), margin, -1.0)


def turn_share(loop: CrankLoop, threshold: float) -> tuple[NDArray[np.bool_], Array]:
    """Over a whole turn of the crank: whether the margin of ``loop`` stays above
    ``threshold`` everywhere, and the share of the turn where it does not, ``(D,)`` each
    (closed form: ``arccos``; a loop that touches the threshold without a measurable share
    counts 1/360).

    Both loops run through ``base + amp·cos ψ`` over the turn and must stay strictly
    inside ``(low, high)``: ``q`` between the roots of ``M(q) = threshold`` (four-bar), the
    offset ``y`` within ``±|l|·√(1 − threshold)`` (slider-crank)."""
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        if loop.kind == "four-bar":
            r1, r2 = np.abs(loop.r1), np.abs(loop.r2)
            base, amp = loop.k * loop.k + loop.c * loop.c, 2 * loop.k * loop.c
            mid, half = r1 * r1 + r2 * r2, 2 * r1 * r2 * np.sqrt(1.0 - threshold)
            low, high, valid = mid - half, mid + half, (r1 > 0) & (r2 > 0)
        else:
            base, amp = loop.k * np.sin(loop.kappa - loop.guide), loop.c
            high = np.abs(loop.r2) * np.sqrt(1.0 - threshold)
            low, valid = -high, high > 0
        turns = (high > base + amp) & (low < base - amp) & valid
        above = np.arccos(np.clip((high - base) / amp, -1.0, 1.0)) / np.pi
        below = 1.0 - np.arccos(np.clip((low - base) / amp, -1.0, 1.0)) / np.pi
    share = np.where(turns, 0.0, np.nan_to_num(np.clip(above + below, 0, 1), nan=1.0))
    return turns, np.where(~turns & (share == 0), 1.0 / 360, share)


def lost_intervals(loop: CrankLoop, design: int, lo: float, hi: float, threshold: float
                   ) -> list[tuple[float, float]]:
    """The intervals of the argument in ``[lo, hi]`` where the margin of ``loop`` is at most
    ``threshold`` for one design (closed form: the roots of ``cos(θ − φ) = value``)."""
    c, k, kappa = loop.c[design], loop.k[design], loop.kappa[design]
    offset = loop.offset[design]
    # each condition is "cos(θ − phase) ≥ value" or "≤ value"
    conditions: list[tuple[float, float, bool]] = []
    if loop.kind == "four-bar":
        r1, r2 = loop.r1[design], loop.r2[design]
        a, b = (r1 - r2) ** 2, (r1 + r2) ** 2
        # M(q) = threshold: −q² + (a + b) q − ab − 4 r1² r2² t = 0
        disc = max((b - a) ** 2 / 4.0 - 4.0 * r1 * r1 * r2 * r2 * threshold, 0.0)
        q_low, q_high = (a + b) / 2.0 - np.sqrt(disc), (a + b) / 2.0 + np.sqrt(disc)
        twice = 2.0 * c * k
        base = c * c + k * k
        if twice > 0:
            conditions.append((kappa, (q_low - base) / twice, False))
            conditions.append((kappa, (q_high - base) / twice, True))
        elif not q_low < base < q_high:
            return [(lo, hi)]
    else:
        limit = abs(loop.r2[design]) * np.sqrt(max(1.0 - threshold, 0.0))
        rest = k * np.sin(kappa - loop.guide[design])
        phase = loop.guide[design] + np.pi / 2
        if c > 0:
            conditions.append((phase, (limit - rest) / c, True))
            conditions.append((phase, (-limit - rest) / c, False))
        elif abs(rest) >= limit:
            return [(lo, hi)]
    found: list[tuple[float, float]] = []
    for phase, value, above in conditions:
        if value > 1 or value < -1:
            if (value < -1) == above:  # the condition holds everywhere
                return [(lo, hi)]
            continue
        half = float(np.arccos(value))
        # above: θ − phase ∈ [−half, half] (mod 2π); below: [half, 2π − half]
        start, width = (-half, 2 * half) if above else (half, TWO_PI - 2 * half)
        first = phase + start - offset
        turn = np.floor((lo - first - width) / TWO_PI)
        begin = first + turn * TWO_PI
        while begin <= hi:
            a_, b_ = max(begin, lo), min(begin + width, hi)
            if a_ <= b_:
                found.append((float(a_), float(b_)))
            begin += TWO_PI
    return sorted(found)


def grashof_class(loop: CrankLoop) -> tuple[NDArray[np.bool_], NDArray[np.str_]]:
    """Whether each design of a four-bar loop satisfies Grashof's condition
    ``s + l ≤ p + q`` (within a relative 1e-12), and which link is the shortest:
    ``"crank"``, ``"frame"``, ``"coupler"`` or ``"rocker"``, arrays ``(D,)``."""
    lengths = np.stack([np.abs(loop.c), np.abs(loop.k), np.abs(loop.r1), np.abs(loop.r2)])
    names = np.array(["crank", "frame", "coupler", "rocker"])
    if loop.coupler != int(loop.info.functions[0][1:]):
        names = np.array(["crank", "frame", "rocker", "coupler"])
    ordered = np.sort(lengths, axis=0)
    grashof = ordered[0] + ordered[3] <= (ordered[1] + ordered[2]) * (1 + 1e-12)
    return grashof, names[np.argmin(lengths, axis=0)]
