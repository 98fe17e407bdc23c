"""Compiled kernels (numba) of the planar modules, for large blocks of designs × positions.

:func:`pl4_contour` is :func:`mechloop.modules.planar.pl4_unit` followed by the position
solve's dead-point test and assembly branch (``kinematics._solve_contour``), fused in one
pass over the elements: the same arithmetic in the same order, so its results equal the
NumPy path's bit for bit (tests/test_kernels.py; the angles are taken by NumPy's
``arctan2`` after it, as on the NumPy path).  NumPy's cost there is not the arithmetic but
some thirty temporaries per contour; a population of designs at a few target positions
is exactly that case.

Importing this module imports numba; :mod:`mechloop.solve.kinematics` imports it only
when a block is large enough to pay for it, so the command line and a single solve never
load numba.  ``cache=True`` keeps the compiled code between runs.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from numpy.typing import NDArray

Array = NDArray[np.float64]


@njit(cache=True, nogil=True)
def _pl4_contour(x, y, r1, r2, k, rtol, singular_sin,
                 c1, s1, c2, s2, ok, dead, branch):  # pragma: no cover - compiled
    n, m = x.shape
    for i in range(n):
        for j in range(m):
            xx = x[i, j]
            yy = y[i, j]
            a = r1[i, j]
            b = r2[i, j]
            psq = xx * xx + yy * yy
            p = math.sqrt(psq)
            good = False
            if p > 0 and a != 0 and b != 0:
                ux = -xx / p
                uy = -yy / p
                along = (a * a - b * b + psq) / (2.0 * p)
                h2 = (a - along) * (a + along)
                good = h2 >= -rtol * max(a * a, b * b)
            ok[i, j] = good
            dead[i, j] = False
            branch[i, j] = 0
            if not good:
                c1[i, j] = math.nan
                s1[i, j] = math.nan
                c2[i, j] = math.nan
                s2[i, j] = math.nan
                continue
            h = k * math.sqrt(max(h2, 0.0))
            rest = p - along
            u = (along * ux - h * uy) / a
            v = (along * uy + h * ux) / a
            w = (rest * ux + h * uy) / b
            z = (rest * uy - h * ux) / b
            c1[i, j] = u
            s1[i, j] = v
            c2[i, j] = w
            s2[i, j] = z
            # Jacobian columns of the two unknown angles: r n = (-r sin, r cos)
            c1x = -a * v
            c1y = a * u
            c2x = -b * z
            c2y = b * w
            det = c1x * c2y - c1y * c2x
            norm = math.sqrt((c1x * c1x + c1y * c1y) * (c2x * c2x + c2y * c2y))
            if not abs(det) > singular_sin * norm:
                dead[i, j] = True
            elif det > 0:
                branch[i, j] = 1
            elif det < 0:
                branch[i, j] = -1


def pl4_contour(x: Array, y: Array, r1: Array, r2: Array, *, variant: int,
                rtol: float, singular_sin: float
                ) -> tuple[Array, Array, Array, Array, NDArray[np.bool_], NDArray[np.bool_],
                           NDArray[np.int8]]:
    """A Pl4 contour at every element of a block, arrays of one shape ``(..., P)``.

    ``x``, ``y`` (m): the sum of the known vectors; ``r1``, ``r2`` (m): the lengths of the
    two vectors of unknown direction (broadcast views are fine); ``variant`` 1 or 2.
    Returns the directions ``cos α1, sin α1, cos α2, sin α2`` (NaN where no solution;
    bit for bit those of :func:`~mechloop.modules.planar.pl4_unit`),
    ``ok`` (a solution exists), ``dead`` (it exists but the Jacobian's
    ``|sin|`` is not above ``singular_sin``) and the branch (the sign of the Jacobian's
    determinant where the solution is regular, else 0)."""
    shape = x.shape
    two = (math.prod(shape[:-1]), shape[-1]) if len(shape) else (1, 1)
    args = [np.broadcast_to(v, shape).reshape(two) for v in (x, y, r1, r2)]
    out = [np.empty(two) for _ in range(4)]
    ok, dead = np.empty(two, dtype=np.bool_), np.empty(two, dtype=np.bool_)
    branch = np.empty(two, dtype=np.int8)
    _pl4_contour(*args, 1.0 if variant == 1 else -1.0, rtol, singular_sin, *out, ok, dead,
                 branch)
    return (*(a.reshape(shape) for a in out), ok.reshape(shape), dead.reshape(shape),
            branch.reshape(shape))


__all__ = ["pl4_contour"]
