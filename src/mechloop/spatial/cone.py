"""Pr5–Pr7 — length and rotation ``r_i, β_i`` of vector ``i`` unknown (its elevation
``α_i`` known), plus ``r_j`` (Pr5), ``α_j`` (Pr6) or ``β_j`` (Pr7) of vector ``j``.

Whatever ``r_i`` (signed) and ``β_i`` are, ``W = r_i u_i = −S − r_j u_j`` lies on the
double cone about Y of elevation ``α_i``::

    W_y² cos² α_i = (W_x² + W_z²) sin² α_i

— a quadratic in ``r_j`` (Pr5, 2 solutions, smaller ``r_j`` first) or, with ``β_j``
moving ``W`` on a horizontal circle at the fixed height ``W_y``, the circle
``W_x² + W_z² = (W_y cot α_i)²``: ``a cos β_j + b sin β_j = c`` (Pr7, 2 solutions);
with ``α_j`` moving ``W`` on a vertical circle, a trigonometric quartic (Pr6, 4
solutions).
Then ``r_i = ±|W|`` with the sign of ``W_y sin α_i`` and ``β_i`` a full turn.
The module is undefined (break) for a horizontal or vertical vector ``i``.
Outputs have the branch axis first, shape ``(B, ..., P)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import DEGENERATE, masked, r_beta_on_cone
from mechloop.spatial.quartic import trig_quartic
from mechloop.spatial.roots import quadratic, trig_linear
from mechloop.spatial.vector import unit

Array = NDArray[np.float64]
Result = tuple[Array, Array, Array, NDArray[np.bool_]]


def _f(*v: ArrayLike) -> list[Array]:
    return [np.asarray(x, dtype=float) for x in v]


def _finish(sx, sy, sz, r_j, alpha_j, beta_j, alpha_i, ok):
    ux, uy, uz = unit(alpha_j, beta_j)
    w = (-sx - r_j * ux, -sy - r_j * uy, -sz - r_j * uz)
    r_i, beta_i, ok_i = r_beta_on_cone(w, alpha_i)
    return r_i, beta_i, ok & ok_i


def solve_pr5(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, alpha_i: ArrayLike,
              alpha_j: ArrayLike, beta_j: ArrayLike) -> Result:
    """Pr5 — unknown ``r_i, β_i, r_j`` (2 solutions, branch 1 the smaller ``r_j``).
    Returns ``r_i, beta_i, r_j, ok`` of shape ``(2, ..., P)``."""
    sx, sy, sz, alpha_i, alpha_j, beta_j = _f(sx, sy, sz, alpha_i, alpha_j, beta_j)
    c2, s2 = np.cos(alpha_i) ** 2, np.sin(alpha_i) ** 2
    bx, by, bz = (-v for v in unit(alpha_j, beta_j))  # W = −S + r_j B
    ax, ay, az = -sx, -sy, -sz
    a2 = by * by * c2 - (bx * bx + bz * bz) * s2
    a1 = 2.0 * (ay * by * c2 - (ax * bx + az * bz) * s2)
    a0 = ay * ay * c2 - (ax * ax + az * az) * s2
    r_j, ok = quadratic(a2, a1, a0)
    r_i, beta_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, alpha_i, ok)
    return (*masked(ok, r_i, beta_i, r_j), ok)


def solve_pr7(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, alpha_i: ArrayLike,
              r_j: ArrayLike, alpha_j: ArrayLike) -> Result:
    """Pr7 — unknown ``r_i, β_i, β_j`` (2 solutions).
    Returns ``r_i, beta_i, beta_j, ok`` of shape ``(2, ..., P)``."""
    sx, sy, sz, alpha_i, r_j, alpha_j = _f(sx, sy, sz, alpha_i, r_j, alpha_j)
    sa = np.sin(alpha_i)
    good = np.abs(sa) > DEGENERATE
    wy = -sy - r_j * np.sin(alpha_j)
    big_r2 = (wy * np.cos(alpha_i) / np.where(good, sa, 1.0)) ** 2
    rho = r_j * np.cos(alpha_j)  # W_h = −S_h − ρ (cos β_j, sin β_j)
    beta_j, ok = trig_linear(2.0 * rho * sx, 2.0 * rho * sz,
                             big_r2 - sx * sx - sz * sz - rho * rho)
    r_i, beta_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, alpha_i, ok & good)
    return (*masked(ok, r_i, beta_i, beta_j), ok)


def _polish_pr6(alpha_j, sx, sy, sz, c2, s2, r_j, beta_j, steps: int = 2):
    """Newton steps on the cone condition evaluated from ``W`` itself (no expanded
    coefficients, so no cancellation in the constant term)."""
    cb, sb = np.cos(beta_j), np.sin(beta_j)
    for _ in range(steps):
        ca, sa = np.cos(alpha_j), np.sin(alpha_j)
        wx, wy, wz = -sx - r_j * ca * cb, -sy - r_j * sa, -sz - r_j * ca * sb
        dx, dy, dz = r_j * sa * cb, -r_j * ca, r_j * sa * sb
        f = c2 * wy * wy - s2 * (wx * wx + wz * wz)
        df = 2.0 * (c2 * wy * dy - s2 * (wx * dx + wz * dz))
        good = np.isfinite(alpha_j) & (df != 0)
        alpha_j = np.where(good, alpha_j - f / np.where(good, df, 1.0), alpha_j)
    return alpha_j


def solve_pr6(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, alpha_i: ArrayLike,
              r_j: ArrayLike, beta_j: ArrayLike) -> Result:
    """Pr6 — unknown ``r_i, β_i, α_j`` (4 solutions): ``W(α_j)`` runs on a circle in the
    vertical plane of ``β_j`` and meets the cone in up to four points, the roots of a
    trigonometric polynomial of degree 2 in ``α_j`` (:func:`trig_quartic`; real roots in
    increasing ``α_j``).  Returns ``r_i, beta_i, alpha_j, ok`` of shape ``(4, ..., P)``.

    With every ``β = 0`` this is the planar Pl3 (``r_i, α_j``) on the branches with
    ``β_i = 0``.
    """
    sx, sy, sz, alpha_i, r_j, beta_j = _f(sx, sy, sz, alpha_i, r_j, beta_j)
    c2, s2 = np.cos(alpha_i) ** 2, np.sin(alpha_i) ** 2
    ay = -sy
    a_d = -(sx * np.cos(beta_j) + sz * np.sin(beta_j))  # A_h · d_j with A = −S
    a_h2 = sx * sx + sz * sz
    rr = r_j * r_j
    alpha_j, ok = trig_quartic(c2 * (ay * ay + rr / 2) - s2 * (a_h2 + rr / 2),
                               2.0 * s2 * r_j * a_d, -2.0 * c2 * ay * r_j,
                               -rr / 2 * (c2 + s2), np.zeros_like(rr))
    alpha_j = _polish_pr6(alpha_j, sx, sy, sz, c2, s2, r_j, beta_j)
    r_i, beta_i, ok = _finish(sx, sy, sz, r_j, alpha_j, beta_j, alpha_i, ok)
    return (*masked(ok, r_i, beta_i, alpha_j), ok)
