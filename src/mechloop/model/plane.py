"""The plane of a planar contour in a model with spatial contours (issue 17).

A planar contour lies in the XY plane unless its ``plane`` gives another one, by its
normal: ``{normal: [nx, ny, nz]}`` (any length but zero), or by the normal's two angles
``{a: α, b: β}`` (the direction ``(cos α cos β, sin α, cos α sin β)`` of a spatial vector,
in the model's angle unit).  The contour is solved in the plane's own axes ``e1, e2``
exactly as in the XY plane (its angles measured from ``e1`` towards ``e2``); the plane
places its vectors in space: ``v = r (cos α e1 + sin α e2)``.  The axes: ``e1`` is the
horizontal line of the plane, ``Y × n`` normalised (``X`` for a horizontal plane), and
``e2 = n × e1``; the XY plane (``n = Z``) has ``e1 = X``, ``e2 = Y``.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray
from pydantic import Field, model_validator

from mechloop.model.numbers import Number, Scalar
from mechloop.model.signals import _Frozen

Array = NDArray[np.float64]


class Plane(_Frozen):
    """The plane of a planar contour: its ``normal``, or the normal's angles ``a``, ``b``."""

    normal: tuple[Number, Number, Number] | None = Field(
        None, description="the plane's normal [nx, ny, nz] (not zero)")
    a: Scalar | None = Field(None, description="the normal's elevation α (model angle "
                             "units), with b instead of normal")
    b: Scalar | None = Field(None, description="the normal's rotation β about Y (model "
                             "angle units), with a instead of normal")

    @model_validator(mode="after")
    def _one_way(self) -> Plane:
        angles = self.a is not None or self.b is not None
        if (self.normal is not None) == angles or (angles and (self.a is None
                                                               or self.b is None)):
            raise ValueError("give the plane's normal [nx, ny, nz], or its two angles a "
                             "and b")
        if self.normal is not None and not any(self.normal):
            raise ValueError("the plane's normal is zero")
        return self


def plane_axes(normal: tuple[float, float, float]) -> tuple[Array, Array]:
    """The in-plane axes ``e1, e2`` (unit, ``e1 × e2`` along ``normal``)."""
    n = np.asarray(normal, dtype=float)
    n = n / np.linalg.norm(n)
    e1 = np.array([n[2], 0.0, -n[0]])  # Y × n
    size = np.linalg.norm(e1)
    e1 = e1 / size if size > 1e-12 else np.array([1.0, 0.0, 0.0])
    return e1, np.cross(n, e1)


def normal_of(alpha: float, beta: float) -> tuple[float, float, float]:
    """The normal of the angles ``α, β`` (rad)."""
    return (math.cos(alpha) * math.cos(beta), math.sin(alpha),
            math.cos(alpha) * math.sin(beta))
