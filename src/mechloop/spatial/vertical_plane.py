"""Pr2–Pr4 — length and elevation ``r_i, α_i`` of vector ``i`` unknown (its rotation
``β_i`` known), plus one parameter of vector ``j``.

Vector ``i`` lies in the vertical plane of rotation ``β_i`` whatever ``r_i, α_i`` are, so
the closure projected on that plane's normal ``n_i = (−sin β_i, 0, cos β_i)`` holds only
vector ``j``::

    n_i · (S + r_j u_j) = 0,   n_i · u_j = cos α_j sin(β_j − β_i)

— linear in ``r_j`` (Pr2, 1 solution) or ``a cos θ + b sin θ = c`` in ``α_j`` (Pr3) or
``β_j`` (Pr4), 2 solutions.  Then ``r_i u_i = W = −S − r_j u_j`` is Pl1 in the plane:
``r_i = hypot ≥ 0``, ``α_i`` a full turn.  ``S = (sx, sy, sz)`` is the sum of the known
vectors.  Outputs have the branch axis first, shape ``(B, ..., P)``; NaN with ``ok``
false at a chain break.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import DEGENERATE, masked, r_alpha_in_plane
from mechloop.spatial.roots import trig_linear
from mechloop.spatial.vector import unit

Array = NDArray[np.float64]
Result = tuple[Array, Array, Array, NDArray[np.bool_]]


def _f(*v: ArrayLike) -> list[Array]:
    return [np.asarray(x, dtype=float) for x in v]


def _normal_dot_s(sx: Array, sz: Array, beta_i: Array) -> Array:
    return -sx * np.sin(beta_i) + sz * np.cos(beta_i)


def _finish(sx, sy, sz, r_j, alpha_j, beta_j, beta_i, ok):
    ux, uy, uz = unit(alpha_j, beta_j)
    w = (-sx - r_j * ux, -sy - r_j * uy, -sz - r_j * uz)
    r_i, alpha_i, ok_i = r_alpha_in_plane(w, beta_i)
    return r_i, alpha_i, ok & ok_i


def solve_pr2(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, beta_i: ArrayLike,
              alpha_j: ArrayLike, beta_j: ArrayLike) -> Result:
    """Pr2 — unknown ``r_i, α_i, r_j`` (1 solution).  ``ok`` false where vector ``j`` is
    parallel to the plane of vector ``i`` (``cos α_j sin(β_j − β_i) = 0``) or ``r_i = 0``.
    Returns ``r_i, alpha_i, r_j, ok`` of shape ``(1, ..., P)``."""
    sx, sy, sz, beta_i, alpha_j, beta_j = _f(sx, sy, sz, beta_i, alpha_j, beta_j)
    den = np.cos(alpha_j) * np.sin(beta_j - beta_i)
    ok = np.abs(den) > DEGENERATE
    r_j = -_normal_dot_s(sx, sz, beta_i) / np.where(ok, den, 1.0)
    r_i, alpha_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, beta_i, ok)
    return tuple(v[None] for v in (*masked(ok, r_i, alpha_i, r_j), ok))  # type: ignore[return-value]


def solve_pr3(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, beta_i: ArrayLike,
              r_j: ArrayLike, beta_j: ArrayLike) -> Result:
    """Pr3 — unknown ``r_i, α_i, α_j`` (2 solutions: ``α_j = ±acos(c)``, branch 1 the
    ``+`` root).  Returns ``r_i, alpha_i, alpha_j, ok`` of shape ``(2, ..., P)``."""
    sx, sy, sz, beta_i, r_j, beta_j = _f(sx, sy, sz, beta_i, r_j, beta_j)
    a = r_j * np.sin(beta_j - beta_i)
    alpha_j, ok = trig_linear(a, np.zeros_like(a), -_normal_dot_s(sx, sz, beta_i))
    r_i, alpha_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, beta_i, ok)
    return (*masked(ok, r_i, alpha_i, alpha_j), ok)


def solve_pr4(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, beta_i: ArrayLike,
              r_j: ArrayLike, alpha_j: ArrayLike) -> Result:
    """Pr4 — unknown ``r_i, α_i, β_j`` (2 solutions of ``sin(β_j − β_i) = c``).
    Returns ``r_i, alpha_i, beta_j, ok`` of shape ``(2, ..., P)``."""
    sx, sy, sz, beta_i, r_j, alpha_j = _f(sx, sy, sz, beta_i, r_j, alpha_j)
    rho = r_j * np.cos(alpha_j)
    beta_j, ok = trig_linear(-rho * np.sin(beta_i), rho * np.cos(beta_i),
                             -_normal_dot_s(sx, sz, beta_i))
    r_i, alpha_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, beta_i, ok)
    return (*masked(ok, r_i, alpha_i, beta_j), ok)
