"""Pr11–Pr13 — the lengths of two vectors ``i, j`` unknown (their directions known), plus
the length (Pr11), elevation (Pr12) or rotation (Pr13) of vector ``k``.

Pr11 is the linear 3×3 system ``r_i u_i + r_j u_j + r_k u_k = −S`` (Cramer's rule with
triple products; 1 solution, a break where the three directions are coplanar).  In Pr12
and Pr13 ``r_i u_i + r_j u_j`` stays in the plane of ``u_i, u_j``, so the closure on its
normal ``n = u_i × u_j`` holds only vector ``k``::

    n · (S + r_k u_k) = 0

— ``a cos θ + b sin θ = c`` in ``α_k`` or ``β_k``, 2 solutions; then ``r_i, r_j``
(signed) from the 2-D system in that plane.  Outputs have the branch axis first,
shape ``(B, ..., P)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import DEGENERATE, cross, dot, masked, two_lengths
from mechloop.spatial.roots import trig_linear
from mechloop.spatial.vector import unit

Array = NDArray[np.float64]
Result = tuple[Array, Array, Array, NDArray[np.bool_]]


def _f(*v: ArrayLike) -> list[Array]:
    return [np.asarray(x, dtype=float) for x in v]


def solve_pr11(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike,
               alpha_i: ArrayLike, beta_i: ArrayLike, alpha_j: ArrayLike, beta_j: ArrayLike,
               alpha_k: ArrayLike, beta_k: ArrayLike) -> Result:
    """Pr11 — unknown ``r_i, r_j, r_k`` (signed).  Returns ``r_i, r_j, r_k, ok`` of shape
    ``(1, ..., P)``; ``ok`` false where ``|u_i · (u_j × u_k)| ≤ 1e-12``."""
    s = tuple(_f(sx, sy, sz))
    ui, uj, uk = unit(alpha_i, beta_i), unit(alpha_j, beta_j), unit(alpha_k, beta_k)
    jk, ki, ij = cross(uj, uk), cross(uk, ui), cross(ui, uj)
    det = dot(ui, jk)
    ok = np.abs(det) > DEGENERATE
    den = np.where(ok, det, 1.0)
    r_i, r_j, r_k = (-dot(s, c) / den for c in (jk, ki, ij))
    ok = np.broadcast_to(ok, r_i.shape)
    return tuple(v[None] for v in (*masked(ok, r_i, r_j, r_k), ok))  # type: ignore[return-value]


def _finish(s, ui, uj, r_k, alpha_k, beta_k, ok):
    uk = unit(alpha_k, beta_k)
    w = tuple(-s[m] - r_k * uk[m] for m in range(3))
    r_i, r_j, ok_ij = two_lengths(w, ui, uj)
    return r_i, r_j, ok & ok_ij


def solve_pr12(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike,
               alpha_i: ArrayLike, beta_i: ArrayLike, alpha_j: ArrayLike, beta_j: ArrayLike,
               r_k: ArrayLike, beta_k: ArrayLike) -> Result:
    """Pr12 — unknown ``r_i, r_j, α_k`` (2 solutions).
    Returns ``r_i, r_j, alpha_k, ok`` of shape ``(2, ..., P)``."""
    s = tuple(_f(sx, sy, sz))
    r_k, beta_k = _f(r_k, beta_k)
    ui, uj = unit(alpha_i, beta_i), unit(alpha_j, beta_j)
    n = cross(ui, uj)
    alpha_k, ok = trig_linear(r_k * (n[0] * np.cos(beta_k) + n[2] * np.sin(beta_k)),
                              r_k * n[1], -dot(n, s))
    r_i, r_j, ok = _finish(s, ui, uj, r_k, alpha_k, beta_k, ok)
    return (*masked(ok, r_i, r_j, alpha_k), ok)


def solve_pr13(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike,
               alpha_i: ArrayLike, beta_i: ArrayLike, alpha_j: ArrayLike, beta_j: ArrayLike,
               r_k: ArrayLike, alpha_k: ArrayLike) -> Result:
    """Pr13 — unknown ``r_i, r_j, β_k`` (2 solutions).
    Returns ``r_i, r_j, beta_k, ok`` of shape ``(2, ..., P)``.

    With every ``β = 0`` this is the planar Pl2 (``r_i, r_j``) on the branch ``β_k = 0``
    (the other branch, ``β_k = π``, mirrors vector ``k`` in the YZ plane).
    """
    s = tuple(_f(sx, sy, sz))
    r_k, alpha_k = _f(r_k, alpha_k)
    ui, uj = unit(alpha_i, beta_i), unit(alpha_j, beta_j)
    n = cross(ui, uj)
    rho = r_k * np.cos(alpha_k)
    beta_k, ok = trig_linear(rho * n[0], rho * n[2],
                             -dot(n, s) - r_k * np.sin(alpha_k) * n[1])
    r_i, r_j, ok = _finish(s, ui, uj, r_k, alpha_k, beta_k, ok)
    return (*masked(ok, r_i, r_j, beta_k), ok)
