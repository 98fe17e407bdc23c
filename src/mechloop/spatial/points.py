"""Points of a solved model with spatial contours, in 3-D, with exact derivatives.

A contour is placed (:mod:`mechloop.dynamics.placing`) by its ``start`` (the origin, an
end of a vector of another contour, or fixed coordinates ``[x, y]`` in the XY plane) and
walked along its ``vectors`` list: a vector listed with a plus sign has its tail at the
current point, one listed with a minus sign (subtracted, spatial contours only) has its
head there.  Vectors come from
:meth:`~mechloop.spatial.solve.SpatialResults.components` (planar contours in their
plane's axes), so derivatives are time derivatives, or analogs when the results are.

A point is a :class:`Motion3`: position, velocity and acceleration, each ``(3, P)``
(x, y, z on the first axis; m, m/s, m/s², or per unit of the argument for analogs).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.placing import ContourPlacement
from mechloop.model.dynamic import HeadPoint, TailPoint, VectorPoint
from mechloop.model.units import to_si

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Motion3:
    """A point or vector over positions: ``p``, ``v``, ``a`` each ``(3, P)``."""

    p: Array
    v: Array
    a: Array

    def __add__(self, other: Motion3) -> Motion3:
        return Motion3(self.p + other.p, self.v + other.v, self.a + other.a)

    def __sub__(self, other: Motion3) -> Motion3:
        return Motion3(self.p - other.p, self.v - other.v, self.a - other.a)

    def scaled(self, k: float) -> Motion3:
        return Motion3(k * self.p, k * self.v, k * self.a)


class Placement3(ContourPlacement[Motion3]):
    """Tails and heads of every vector of a solved spatial model (``SpatialResults``):
    the walk of :class:`~mechloop.dynamics.placing.ContourPlacement` over points
    ``(3, P)``."""

    def __init__(self, results):
        super().__init__(results, {
            n: Motion3(*(np.stack(x) for x in zip(*results.components(n), strict=True)))
            for n in results.model.vectors})

    def _at_rest(self, position: Array | None) -> Motion3:
        zero = np.zeros((3, self.results.broken.size))
        return Motion3(zero if position is None else position, zero, zero)

    def _fixed(self, x: float, y: float) -> Array:
        return np.zeros((3, self.results.broken.size)) + np.array([[x], [y], [0.0]])

    def point(self, where: TailPoint | HeadPoint | VectorPoint) -> Motion3:
        """A point given as in a model file: an end, or ``share`` of the vector's length
        plus ``along`` (m) from its tail (``across`` has no side in 3-D: the caller
        refuses it)."""
        if isinstance(where, TailPoint):
            return self.tail(where.tail)
        if isinstance(where, HeadPoint):
            return self.head(where.head)
        units = self.results.model.units.length
        along = 0.0 if where.along is None else to_si(where.along, "length", units)
        share = 0.0 if where.share is None else float(where.share)
        vec = self._vectors[where.vector]
        out = self.tail(where.vector) + vec.scaled(share)
        if along:
            out = out + self.direction(where.vector).scaled(along)
        return out

    def direction(self, number: int) -> Motion3:
        """The unit direction of vector ``number`` by its angles (α, β; fixed in the body
        that holds the vector whatever the sign and the changes of its length)."""
        return unit_direction(self.results, number)


@np.errstate(invalid="ignore", over="ignore")  # NaN angles at broken rows stay NaN
def unit_direction(results, number: int) -> Motion3:
    """``u(α, β)`` of vector ``number`` and its exact derivatives: ``u̇ = α̇ u_α + β̇ u_β``,
    ``ü = α̈ u_α + β̈ u_β − α̇² u + 2 α̇ β̇ u_αβ + β̇² u_ββ``; for a vector of a planar
    contour ``u = cos α e1 + sin α e2`` in its plane's axes."""
    a, da, dda = (x[f"a{number}"] for x in (results.values, results.rates, results.accels))
    if number in results.axes:
        e1, e2 = (x[:, None] for x in results.axes[number])
        u = np.cos(a) * e1 + np.sin(a) * e2
        t = -np.sin(a) * e1 + np.cos(a) * e2
        return Motion3(u, da * t, dda * t - da**2 * u)
    from mechloop.spatial.solve import _basis

    b, db, ddb = (x[f"b{number}"] for x in (results.values, results.rates, results.accels))
    e = _basis(a, b)
    return Motion3(e["u"], da * e["a"] + db * e["b"],
                   dda * e["a"] + ddb * e["b"] - da**2 * e["u"] + 2.0 * da * db * e["ab"]
                   + db**2 * e["bb"])
