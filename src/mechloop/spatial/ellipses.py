"""Pr14, Pr15 — the length ``r_i`` of vector ``i`` (direction known) and one angle of each
of vectors ``j`` and ``k``: ``α_j, α_k`` (Pr14) or ``α_j, β_k`` (Pr15); 4 solutions.

Projected on the plane normal to ``u_i`` (basis ``t1 = (−sin β_i, 0, cos β_i)``,
``t2 = ∂u_i/∂α_i``) the closure loses ``r_i``, and each of ``j, k`` runs on an ellipse
(the projection of its circle)::

    c + f1 cos θ_j + f2 sin θ_j + e1 cos θ_k + e2 sin θ_k = 0      (2-D)

Solving for ``(cos θ_k, sin θ_k) = M⁻¹(…)`` with ``M = [e1 e2]`` and asking it to be a
unit vector leaves a trigonometric quartic in ``θ_j`` (:func:`trig_quartic`); the ellipse
whose matrix is better conditioned is the one inverted (roles swapped otherwise).  Two
Newton steps on the 2-D system polish each root; then ``r_i = −u_i · (S + v_j + v_k)``.
Both ellipses flat (each rotation plane containing ``u_i``) is a break.
Outputs have the branch axis first, shape ``(4, ..., P)``, real roots first.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import DEGENERATE, masked
from mechloop.spatial.quartic import trig_quartic
from mechloop.spatial.roots import wrap
from mechloop.spatial.vector import unit

Array = NDArray[np.float64]
Result = tuple[Array, Array, Array, NDArray[np.bool_]]
V2 = tuple[Array, Array]


def _f(*v: ArrayLike) -> list[Array]:
    return [np.asarray(x, dtype=float) for x in v]


def _cross2(a: V2, b: V2) -> Array:
    return a[0] * b[1] - a[1] * b[0]


def ellipse_pair(c: V2, f1: V2, f2: V2, e1: V2, e2: V2
                 ) -> tuple[Array, Array, NDArray[np.bool_]]:
    """All solutions ``(θ_j, θ_k)``, each shape ``(4, ...)``, of
    ``c + f1 cos θ_j + f2 sin θ_j + e1 cos θ_k + e2 sin θ_k = 0`` (2-D vectors given as
    pairs of arrays)."""
    det_e, det_f = _cross2(e1, e2), _cross2(f1, f2)
    norm_e = np.hypot(*e1) * np.hypot(*e2)
    norm_f = np.hypot(*f1) * np.hypot(*f2)
    rel_e = np.abs(det_e) / np.where(norm_e > 0, norm_e, 1.0)
    rel_f = np.abs(det_f) / np.where(norm_f > 0, norm_f, 1.0)
    swap = rel_f > rel_e  # invert the better-conditioned ellipse
    g1 = tuple(np.where(swap, e, f) for e, f in zip(e1, f1, strict=True))  # variable
    g2 = tuple(np.where(swap, e, f) for e, f in zip(e2, f2, strict=True))
    h1 = tuple(np.where(swap, f, e) for e, f in zip(e1, f1, strict=True))  # inverted
    h2 = tuple(np.where(swap, f, e) for e, f in zip(e2, f2, strict=True))
    det = _cross2(h1, h2)
    good = np.maximum(rel_e, rel_f) > DEGENERATE
    det = np.where(good, det, 1.0)

    def solve_h(v: V2) -> V2:  # M⁻¹ v with M = [h1 h2]
        return (_cross2(v, h2) / det, _cross2(h1, v) / det)

    a0 = solve_h((-c[0], -c[1]))
    a1 = solve_h((-g1[0], -g1[1]))
    a2 = solve_h((-g2[0], -g2[1]))
    d00 = a0[0] ** 2 + a0[1] ** 2
    d11 = a1[0] ** 2 + a1[1] ** 2
    d22 = a2[0] ** 2 + a2[1] ** 2
    tv, ok = trig_quartic(d00 + (d11 + d22) / 2 - 1.0,
                          2 * (a0[0] * a1[0] + a0[1] * a1[1]),
                          2 * (a0[0] * a2[0] + a0[1] * a2[1]),
                          (d11 - d22) / 2, a1[0] * a2[0] + a1[1] * a2[1])
    cv, sv = np.cos(tv), np.sin(tv)
    tw = np.arctan2(a0[1] + a1[1] * cv + a2[1] * sv, a0[0] + a1[0] * cv + a2[0] * sv)
    theta_j = np.where(swap, tw, tv)
    theta_k = np.where(swap, tv, tw)
    for _ in range(2):  # Newton on the 2-D system in (θ_j, θ_k)
        cj, sj, ck, sk = np.cos(theta_j), np.sin(theta_j), np.cos(theta_k), np.sin(theta_k)
        rx = c[0] + f1[0] * cj + f2[0] * sj + e1[0] * ck + e2[0] * sk
        ry = c[1] + f1[1] * cj + f2[1] * sj + e1[1] * ck + e2[1] * sk
        jx = (-f1[0] * sj + f2[0] * cj, -e1[0] * sk + e2[0] * ck)
        jy = (-f1[1] * sj + f2[1] * cj, -e1[1] * sk + e2[1] * ck)
        jd = jx[0] * jy[1] - jx[1] * jy[0]
        fine = ok & (np.abs(jd) > DEGENERATE)
        jd = np.where(fine, jd, 1.0)
        theta_j = np.where(fine, theta_j - (rx * jy[1] - ry * jx[1]) / jd, theta_j)
        theta_k = np.where(fine, theta_k - (jx[0] * ry - jy[0] * rx) / jd, theta_k)
    ok = ok & good
    return (*masked(ok, wrap(theta_j), wrap(theta_k)), ok)


def _frame(alpha_i: Array, beta_i: Array):
    ca, sa, cb, sb = np.cos(alpha_i), np.sin(alpha_i), np.cos(beta_i), np.sin(beta_i)
    t1 = (-sb, np.zeros_like(sb), cb)
    t2 = (-sa * cb, ca, -sa * sb)

    def proj(v):
        return (t1[0] * v[0] + t1[1] * v[1] + t1[2] * v[2],
                t2[0] * v[0] + t2[1] * v[1] + t2[2] * v[2])
    return proj


def _r_i(s, alpha_i, beta_i, r_j, alpha_j, beta_j, r_k, alpha_k, beta_k, ok):
    ui, uj, uk = unit(alpha_i, beta_i), unit(alpha_j, beta_j), unit(alpha_k, beta_k)
    r_i = -sum(ui[m] * (s[m] + r_j * uj[m] + r_k * uk[m]) for m in range(3))
    return masked(ok, r_i)[0]


def solve_pr14(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, alpha_i: ArrayLike,
               beta_i: ArrayLike, r_j: ArrayLike, beta_j: ArrayLike, r_k: ArrayLike,
               beta_k: ArrayLike) -> Result:
    """Pr14 — unknown ``r_i, α_j, α_k`` (4 solutions).
    Returns ``r_i, alpha_j, alpha_k, ok`` of shape ``(4, ..., P)``."""
    sx, sy, sz, alpha_i, beta_i, r_j, beta_j, r_k, beta_k = _f(
        sx, sy, sz, alpha_i, beta_i, r_j, beta_j, r_k, beta_k)
    proj = _frame(alpha_i, beta_i)
    zero = np.zeros_like(r_j)
    ey = (zero, np.ones_like(zero), zero)
    c = proj((sx, sy, sz))
    pj, pk = proj((np.cos(beta_j), zero, np.sin(beta_j))), proj(
        (np.cos(beta_k), zero, np.sin(beta_k)))
    py = proj(ey)
    alpha_j, alpha_k, ok = ellipse_pair(
        c, (r_j * pj[0], r_j * pj[1]), (r_j * py[0], r_j * py[1]),
        (r_k * pk[0], r_k * pk[1]), (r_k * py[0], r_k * py[1]))
    r_i = _r_i((sx, sy, sz), alpha_i, beta_i, r_j, alpha_j, beta_j, r_k, alpha_k, beta_k, ok)
    return r_i, alpha_j, alpha_k, ok


def solve_pr15(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, alpha_i: ArrayLike,
               beta_i: ArrayLike, r_j: ArrayLike, beta_j: ArrayLike, r_k: ArrayLike,
               alpha_k: ArrayLike) -> Result:
    """Pr15 — unknown ``r_i, α_j, β_k`` (4 solutions).
    Returns ``r_i, alpha_j, beta_k, ok`` of shape ``(4, ..., P)``."""
    sx, sy, sz, alpha_i, beta_i, r_j, beta_j, r_k, alpha_k = _f(
        sx, sy, sz, alpha_i, beta_i, r_j, beta_j, r_k, alpha_k)
    proj = _frame(alpha_i, beta_i)
    zero = np.zeros_like(r_j)
    one = np.ones_like(zero)
    pj = proj((np.cos(beta_j), zero, np.sin(beta_j)))
    py, px, pz = proj((zero, one, zero)), proj((one, zero, zero)), proj((zero, zero, one))
    s0 = proj((sx, sy, sz))
    hk, vk = r_k * np.cos(alpha_k), r_k * np.sin(alpha_k)
    c = (s0[0] + vk * py[0], s0[1] + vk * py[1])
    alpha_j, beta_k, ok = ellipse_pair(
        c, (r_j * pj[0], r_j * pj[1]), (r_j * py[0], r_j * py[1]),
        (hk * px[0], hk * px[1]), (hk * pz[0], hk * pz[1]))
    r_i = _r_i((sx, sy, sz), alpha_i, beta_i, r_j, alpha_j, beta_j, r_k, alpha_k, beta_k, ok)
    return r_i, alpha_j, beta_k, ok
