"""Pr8–Pr10 — both angles ``α_i, β_i`` of vector ``i`` unknown (its length ``r_i``
known), plus one parameter of vector ``j``.

Whatever the angles are, ``W = r_i u_i = −S − r_j u_j`` lies on the sphere
``|W|² = r_i²``::

    |S|² + r_j² + 2 r_j (S · u_j) = r_i²

— a quadratic in ``r_j`` (Pr8, smaller root first) or ``a cos θ + b sin θ = c`` in ``α_j``
(Pr9) or ``β_j`` (Pr10); 2 solutions each.  Then ``α_i, β_i`` are the direction of
``W / r_i`` in the chosen parameter ``convention`` (:mod:`mechloop.spatial.vector`; the
pair ``(α, β)`` and ``(π − α, β + π)`` is the same direction, the convention picks one).
Outputs have the branch axis first, shape ``(2, ..., P)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import alpha_beta_of, masked
from mechloop.spatial.roots import quadratic, trig_linear
from mechloop.spatial.vector import unit

Array = NDArray[np.float64]
Result = tuple[Array, Array, Array, NDArray[np.bool_]]


def _f(*v: ArrayLike) -> list[Array]:
    return [np.asarray(x, dtype=float) for x in v]


def _finish(sx, sy, sz, r_j, alpha_j, beta_j, r_i, ok, convention):
    ux, uy, uz = unit(alpha_j, beta_j)
    w = (-sx - r_j * ux, -sy - r_j * uy, -sz - r_j * uz)
    alpha_i, beta_i, ok_i = alpha_beta_of(w, r_i, convention=convention)
    return alpha_i, beta_i, ok & ok_i


def solve_pr8(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
              alpha_j: ArrayLike, beta_j: ArrayLike, *, convention: int = 1) -> Result:
    """Pr8 — unknown ``α_i, β_i, r_j``.  Returns ``alpha_i, beta_i, r_j, ok``."""
    sx, sy, sz, r_i, alpha_j, beta_j = _f(sx, sy, sz, r_i, alpha_j, beta_j)
    s_u = sx * np.cos(alpha_j) * np.cos(beta_j) + sy * np.sin(alpha_j) \
        + sz * np.cos(alpha_j) * np.sin(beta_j)
    one = np.ones_like(s_u)
    r_j, ok = quadratic(one, 2.0 * s_u, sx * sx + sy * sy + sz * sz - r_i * r_i)
    alpha_i, beta_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, r_i, ok, convention)
    return (*masked(ok, alpha_i, beta_i, r_j), ok)


def solve_pr9(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
              r_j: ArrayLike, beta_j: ArrayLike, *, convention: int = 1) -> Result:
    """Pr9 — unknown ``α_i, β_i, α_j``.  Returns ``alpha_i, beta_i, alpha_j, ok``.

    With every ``β = 0`` (convention 1) this is the planar Pl4 (``α_i, α_j``, ``β_i = 0``).
    """
    sx, sy, sz, r_i, r_j, beta_j = _f(sx, sy, sz, r_i, r_j, beta_j)
    ss = sx * sx + sy * sy + sz * sz
    alpha_j, ok = trig_linear(2.0 * r_j * (sx * np.cos(beta_j) + sz * np.sin(beta_j)),
                              2.0 * r_j * sy, r_i * r_i - ss - r_j * r_j)
    alpha_i, beta_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, r_i, ok, convention)
    return (*masked(ok, alpha_i, beta_i, alpha_j), ok)


def solve_pr10(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
               r_j: ArrayLike, alpha_j: ArrayLike, *, convention: int = 1) -> Result:
    """Pr10 — unknown ``α_i, β_i, β_j``.  Returns ``alpha_i, beta_i, beta_j, ok``."""
    sx, sy, sz, r_i, r_j, alpha_j = _f(sx, sy, sz, r_i, r_j, alpha_j)
    ss = sx * sx + sy * sy + sz * sz
    rho = r_j * np.cos(alpha_j)
    beta_j, ok = trig_linear(2.0 * rho * sx, 2.0 * rho * sz,
                             r_i * r_i - ss - r_j * r_j - 2.0 * r_j * sy * np.sin(alpha_j))
    alpha_i, beta_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, r_i, ok, convention)
    return (*masked(ok, alpha_i, beta_i, beta_j), ok)
