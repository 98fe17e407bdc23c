"""The follower's motion program over one cam turn: segments of rise, dwell and return.

A segment spans the cam angle ``β`` (rad) from where the previous one ends; a rise moves
the follower by ``+h``, a return by ``−h``, each by a normalized law
(:mod:`mechloop.cams.laws`), a dwell holds it.  The segments fill the whole turn and the
follower ends where it started.  ``s`` is a length (m) for a translating follower and an
angle (rad) of the rocker for an oscillating one; the analogs ``s' = ds/dφ``,
``s'' = d²s/dφ²``, ``s''' = d³s/dφ³`` are per radian of cam angle, and at the cam speed
``ω`` the velocity, acceleration and jerk are ``s'ω``, ``s''ω²``, ``s'''ω³``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.cams.laws import Law, PeakCoefficients, peak_coefficients

Array = NDArray[np.float64]
Kind = Literal["rise", "dwell", "return"]

#: Segment angles must fill the turn to this relative tolerance.
TURN_TOLERANCE = 1e-9


@dataclass(frozen=True)
class Segment:
    """One segment: ``kind``, its cam angle ``angle`` (rad, > 0), its ``lift`` ``h`` (m or
    rad, > 0; 0 for a dwell) and ``law`` (None for a dwell)."""

    kind: Kind
    angle: float
    lift: float = 0.0
    law: Law | None = None

    @property
    def sign(self) -> float:
        return {"rise": 1.0, "return": -1.0, "dwell": 0.0}[self.kind]


@dataclass(frozen=True)
class Motion:
    """The program evaluated at cam angles ``phi`` (rad, shape ``(...)``): displacement
    ``s`` and its analogs ``ds``, ``dds``, ``ddds`` (per rad, per rad², per rad³), all of
    the shape of ``phi``; ``segment`` the index of the segment of each angle."""

    phi: Array
    s: Array
    ds: Array
    dds: Array
    ddds: Array
    segment: NDArray[np.int64]


@dataclass(frozen=True)
class MotionProgram:
    """The segments of one cam turn, in order from cam angle 0."""

    segments: tuple[Segment, ...]

    def __post_init__(self) -> None:
        total = sum(seg.angle for seg in self.segments)
        if not self.segments or abs(total - 2 * math.pi) > TURN_TOLERANCE * 2 * math.pi:
            raise ValueError(f"the segments span {math.degrees(total):.9g} deg, not 360")
        if abs(sum(seg.sign * seg.lift for seg in self.segments)) > 1e-9 * max(
                1e-300, max(seg.lift for seg in self.segments)):
            raise ValueError("the follower does not end where it starts (the returns must "
                             "undo the rises)")

    @property
    def edges(self) -> Array:
        """Cam angles where the segments start, and 2π: shape ``(n + 1,)``, rad."""
        return np.concatenate([[0.0], np.cumsum([seg.angle for seg in self.segments])])

    @property
    def levels(self) -> Array:
        """Displacement at the start of each segment, shape ``(n,)``."""
        steps = [seg.sign * seg.lift for seg in self.segments]
        return np.concatenate([[0.0], np.cumsum(steps)[:-1]])

    @property
    def stroke(self) -> float:
        """Largest minus smallest displacement over the turn (m or rad)."""
        ends = np.concatenate([self.levels, [0.0]])
        return float(ends.max() - ends.min())

    def evaluate(self, phi: ArrayLike) -> Motion:
        """The program at cam angles ``phi`` (rad; taken modulo 2π)."""
        p = np.asarray(phi, dtype=float)
        local = np.mod(p, 2 * math.pi)
        edges = self.edges
        index = np.clip(np.searchsorted(edges, local, side="right") - 1, 0,
                        len(self.segments) - 1)
        out = [np.zeros_like(local) for _ in range(4)]
        levels = self.levels
        for k, seg in enumerate(self.segments):
            here = index == k
            out[0][here] = levels[k]
            if seg.law is None:
                continue
            tau = (local[here] - edges[k]) / seg.angle
            f = seg.law(tau)
            scale = seg.sign * seg.lift
            for order in range(4):
                out[order][here] += scale * f[order] / seg.angle**order
        return Motion(p, *out, index)

    def on_segment(self, k: int, phi: ArrayLike) -> Motion:
        """Segment ``k``'s law at cam angles ``phi`` (rad), including its closed ends:
        the one-sided values at a join (``evaluate`` gives the next segment's there)."""
        seg = self.segments[k]
        p = np.asarray(phi, dtype=float)
        out = [np.full_like(p, self.levels[k]), *(np.zeros_like(p) for _ in range(3))]
        if seg.law is not None:
            f = seg.law((p - self.edges[k]) / seg.angle)
            for order in range(4):
                out[order] = out[order] + seg.sign * seg.lift * f[order] / seg.angle**order
        return Motion(p, *out, np.full(p.shape, k, dtype=np.int64))

    def peaks(self) -> list[PeakCoefficients | None]:
        """Peak coefficients of each segment's law (None for a dwell)."""
        return [None if seg.law is None else peak_coefficients(seg.law)
                for seg in self.segments]
