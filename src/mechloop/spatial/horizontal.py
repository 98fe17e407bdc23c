"""Pr18–Pr20 — the rotations ``β_i, β_j`` of two vectors unknown, plus ``r_k`` (Pr18),
``α_k`` (Pr19) or ``β_k`` (Pr20).

Rotations about Y do not change the Y components, so the Y row of the closure (1.1)
holds only vector ``k``: ``r_k sin α_k = −(S_y + r_i sin α_i + r_j sin α_j)`` — linear
in ``r_k`` (Pr18) or ``sin α_k = c`` (Pr19, 2 solutions).  The X, Z rows are then the
planar Pl4 in the XZ plane for the horizontal projections ``ρ = r cos α`` of ``i, j``
(2 solutions): Pr18 has 2 solutions, Pr19 4 (branch ``2·m + n`` = ``α_k`` root ``m``,
then ``β_i`` root ``n``).  Pr20 (three ``β``) is indeterminate: its Y row does not
involve any unknown and two equations remain for three angles — an infinite family
when the Y row holds, none otherwise; fixing one of the three ``β`` (giving it as a
known) leaves Pl4 in the XZ plane, i.e. Pr18/Pr19's second step.
Outputs have the branch axis first, shape ``(B, ..., P)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import DEGENERATE, masked
from mechloop.spatial.roots import EXISTENCE_RTOL, trig_linear

Array = NDArray[np.float64]
Result = tuple[Array, Array, Array, NDArray[np.bool_]]


def _f(*v: ArrayLike) -> list[Array]:
    return [np.asarray(x, dtype=float) for x in v]


def horizontal_pair(px: Array, pz: Array, rho_i: Array, rho_j: Array
                    ) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Both solutions ``β_i, β_j`` (shape ``(2, ...)``) of
    ``ρ_i (cos β_i, sin β_i) + ρ_j (cos β_j, sin β_j) = (px, pz)`` (Pl4 in the XZ plane,
    coordinates ``(x, z)``; ``ρ`` signed)."""
    pp = px * px + pz * pz
    beta_i, ok = trig_linear(2.0 * rho_i * px, 2.0 * rho_i * pz, pp + rho_i**2 - rho_j**2)
    qx = px - rho_i * np.cos(beta_i)
    qz = pz - rho_i * np.sin(beta_i)
    sgn = np.where(rho_j >= 0, 1.0, -1.0)
    beta_j = np.arctan2(sgn * qz, sgn * qx)
    ok = ok & (np.abs(rho_j) > DEGENERATE)
    return (*masked(ok, beta_i, beta_j), ok)


def solve_pr18(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
               alpha_i: ArrayLike, r_j: ArrayLike, alpha_j: ArrayLike,
               alpha_k: ArrayLike, beta_k: ArrayLike) -> Result:
    """Pr18 — unknown ``β_i, β_j, r_k`` (2 solutions).
    Returns ``beta_i, beta_j, r_k, ok`` of shape ``(2, ..., P)``."""
    sx, sy, sz, r_i, alpha_i, r_j, alpha_j, alpha_k, beta_k = _f(
        sx, sy, sz, r_i, alpha_i, r_j, alpha_j, alpha_k, beta_k)
    sk = np.sin(alpha_k)
    good = np.abs(sk) > DEGENERATE
    r_k = -(sy + r_i * np.sin(alpha_i) + r_j * np.sin(alpha_j)) / np.where(good, sk, 1.0)
    rho_k = r_k * np.cos(alpha_k)
    px = -sx - rho_k * np.cos(beta_k)
    pz = -sz - rho_k * np.sin(beta_k)
    beta_i, beta_j, ok = horizontal_pair(px, pz, r_i * np.cos(alpha_i), r_j * np.cos(alpha_j))
    ok = ok & good
    r_k = np.broadcast_to(r_k, beta_i.shape)
    return (*masked(ok, beta_i, beta_j, r_k), ok)


def solve_pr19(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
               alpha_i: ArrayLike, r_j: ArrayLike, alpha_j: ArrayLike,
               r_k: ArrayLike, beta_k: ArrayLike) -> Result:
    """Pr19 — unknown ``β_i, β_j, α_k`` (4 solutions).
    Returns ``beta_i, beta_j, alpha_k, ok`` of shape ``(4, ..., P)``."""
    sx, sy, sz, r_i, alpha_i, r_j, alpha_j, r_k, beta_k = _f(
        sx, sy, sz, r_i, alpha_i, r_j, alpha_j, r_k, beta_k)
    c = -(sy + r_i * np.sin(alpha_i) + r_j * np.sin(alpha_j))
    alpha_k, ok_k = trig_linear(np.zeros_like(c), r_k, c)  # (2, ...)
    rho_k = r_k * np.cos(alpha_k)
    px = -sx - rho_k * np.cos(beta_k)
    pz = -sz - rho_k * np.sin(beta_k)
    beta_i, beta_j, ok = horizontal_pair(px, pz, r_i * np.cos(alpha_i), r_j * np.cos(alpha_j))
    # beta_i: (2 roots of β_i, 2 roots of α_k, ...) → branch 2·m + n
    beta_i, beta_j, ok = (np.swapaxes(v, 0, 1).reshape((4, *v.shape[2:]))
                          for v in (beta_i, beta_j, ok & ok_k[None]))
    alpha_k = np.repeat(alpha_k, 2, axis=0)
    return (*masked(ok, beta_i, beta_j, alpha_k), ok)


def pr20_family(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
                alpha_i: ArrayLike, r_j: ArrayLike, alpha_j: ArrayLike, r_k: ArrayLike,
                alpha_k: ArrayLike) -> NDArray[np.bool_]:
    """Pr20 — unknown ``β_i, β_j, β_k``: infinitely many solutions or none.

    Returns a bool array, shape ``(..., P)``: true where a (one-parameter) family of
    solutions exists — the Y row of the closure holds (relative slack 1e-9) and the
    horizontal lengths ``|S_h|, |ρ_i|, |ρ_j|, |ρ_k|`` close a polygon (the largest is at
    most the sum of the others).  The family is made determinate by giving one ``β``:
    the other two are then Pl4 in the XZ plane (:func:`horizontal_pair`).  False is a
    chain break (no solution at all).
    """
    sx, sy, sz, r_i, alpha_i, r_j, alpha_j, r_k, alpha_k = _f(
        sx, sy, sz, r_i, alpha_i, r_j, alpha_j, r_k, alpha_k)
    terms = (sy, r_i * np.sin(alpha_i), r_j * np.sin(alpha_j), r_k * np.sin(alpha_k))
    scale = sum(np.abs(t) for t in terms)
    y_row = np.abs(sum(terms)) <= 1e-9 * np.maximum(scale, 1e-300)
    sides = np.stack(np.broadcast_arrays(
        np.hypot(sx, sz), np.abs(r_i * np.cos(alpha_i)), np.abs(r_j * np.cos(alpha_j)),
        np.abs(r_k * np.cos(alpha_k))))
    total = sides.sum(axis=0)
    closes = 2.0 * sides.max(axis=0) <= total * (1.0 + EXISTENCE_RTOL)
    return y_row & closes
