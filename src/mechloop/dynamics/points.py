"""Points of a solved vector model in the plane, with exact velocities and accelerations.

A contour is a closed loop: it fixes where its points are relative to each other, not
where they are in the plane.  Each contour is placed by its ``start`` (the origin by
default, or an end of a vector of another contour, or fixed coordinates), and then the tail
of each of its vectors is the sum of the vectors before it.

Points are complex numbers ``z = x + i·y`` (m) over positions, shape ``(P,)``; a vector is
``r·e^{iα}``, so its derivatives are ``(ṙ + i r α̇)·e^{iα}`` and
``(r̈ − r α̇² + i(2 ṙ α̇ + r α̈))·e^{iα}``.  Derivatives follow the results: time
derivatives, or analogs when the results are.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.placing import ContourPlacement
from mechloop.model.dynamic import HeadPoint, TailPoint, VectorPoint
from mechloop.model.units import to_si
from mechloop.solve.results import Results

Complex = NDArray[np.complex128]
Array = NDArray[np.float64]


@dataclass(frozen=True)
class Motion:
    """A point (or vector) over positions: position ``z`` (m), velocity ``v`` (m/s) and
    acceleration ``a`` (m/s²) as complex arrays, shape ``(P,)``."""

    z: Complex
    v: Complex
    a: Complex

    def __add__(self, other: Motion) -> Motion:
        return Motion(self.z + other.z, self.v + other.v, self.a + other.a)

    def __sub__(self, other: Motion) -> Motion:
        return Motion(self.z - other.z, self.v - other.v, self.a - other.a)


@np.errstate(invalid="ignore", over="ignore")  # inf·0 at broken rows: NaN, marked broken
def vector_motion(results: Results, number: int) -> Motion:
    """Vector ``number`` as ``r·e^{iα}`` with its first and second derivatives."""
    r, a = results.value(f"r{number}"), results.value(f"a{number}")
    dr, da = results.rate(f"r{number}"), results.rate(f"a{number}")
    ddr, dda = results.accel(f"r{number}"), results.accel(f"a{number}")
    e = np.exp(1j * a)
    return Motion(r * e, (dr + 1j * r * da) * e,
                  (ddr - r * da * da + 1j * (2 * dr * da + r * dda)) * e)


@np.errstate(invalid="ignore", over="ignore")  # inf·0 at broken rows: NaN, marked broken
def offset_motion(results: Results, number: int, share: float, along: float,
                  across: float) -> Motion:
    """The offset from vector ``number``'s tail to a point placed on it: ``share`` of its
    length plus ``along`` (m) along it, ``across`` (m) to its left."""
    r, a = results.value(f"r{number}"), results.value(f"a{number}")
    dr, da = results.rate(f"r{number}"), results.rate(f"a{number}")
    ddr, dda = results.accel(f"r{number}"), results.accel(f"a{number}")
    w = share * r + along + 1j * across
    dw, ddw = share * dr, share * ddr
    e = np.exp(1j * a)
    return Motion(w * e, (dw + 1j * da * w) * e,
                  (ddw + 2j * da * dw + 1j * dda * w - da * da * w) * e)


class Placement(ContourPlacement[Motion]):
    """Where every vector of a solved model lies: tails and heads over positions (the
    walk of :class:`~mechloop.dynamics.placing.ContourPlacement`).

    ``starts`` (optional) maps a contour's index to where it starts at every position,
    complex ``(P,)`` (m): the fixed start of each design when the positions are the
    designs × positions of a population (:mod:`mechloop.dynamics.population`); a contour
    not in it starts as its model says."""

    def __init__(self, results: Results, starts: Mapping[int, Complex] | None = None):
        if any(c.spatial for c in results.model.contours):  # issue 17: no 3-D views yet
            from mechloop.errors import HintedError

            raise HintedError("position plans, trajectories and animations of a model with "
                              "spatial contours are not built yet (its points are in 3-D)",
                              "plot its parameters against the position (plot ... "
                              "parameters -n b3) or write the table with mechloop solve")
        super().__init__(results, {n: vector_motion(results, n) for n in results.model.vectors},
                         starts)

    def _at_rest(self, position: Complex | None) -> Motion:
        zero = np.zeros(self.results.broken.size, dtype=complex)
        return Motion(zero if position is None else position, zero, zero)

    def _fixed(self, x: float, y: float) -> Complex:
        return np.full(self.results.broken.size, complex(x, y))

    def point(self, where: TailPoint | HeadPoint | VectorPoint) -> Motion:
        """A point given as in a model file (model units converted to SI)."""
        if isinstance(where, TailPoint):
            return self.tail(where.tail)
        if isinstance(where, HeadPoint):
            return self.head(where.head)
        units = self.results.model.units.length
        along = 0.0 if where.along is None else to_si(where.along, "length", units)
        share = 0.0 if where.share is None else float(where.share)
        across = to_si(where.across, "length", units)
        return self.tail(where.vector) + offset_motion(self.results, where.vector, share,
                                                       along, across)
