"""Pr16, Pr17 — one angle of each of three vectors unknown: ``α_i, α_j, α_k`` (Pr16) or
``α_i, α_j, β_k`` (Pr17); 8 solutions.

Pr16: vector ``k`` stays in its vertical plane, so the closure on that plane's normal
``n_k`` is linear in ``cos α_i, cos α_j`` — ``cos α_j`` is an affine function of
``cos α_i``.  Pr17: the Y row is linear in ``sin α_i, sin α_j`` — ``sin α_j`` is affine
in ``sin α_i``.  The remaining condition (``|S + v_i + v_j| = r_k``, resp. the horizontal
``|…|_h = r_k cos α_k``) reads ``A + σ B = 0`` with ``σ`` the other trigonometric function
of ``α_j``; ``A² = B² (1 − (the affine one)²)`` is a trigonometric polynomial of degree 4
in ``α_i`` — 8 roots.  Its coefficients are taken exactly from 9 equally spaced samples
(a discrete Fourier transform: a degree-4 trigonometric polynomial is determined by
them), its roots by :func:`trig_roots`; then ``σ = −A/B`` gives ``α_j``, vector ``k``
follows from the closure, and Newton steps on the raw 3-D closure (3×3 Jacobian,
batched ``numpy.linalg.solve``, four steps) polish every branch.  Breaks:
``r_j sin(β_j − β_k) = 0`` (Pr16) or ``r_j = 0`` (Pr17), and ``B = 0`` at a root.
Outputs have the branch axis first, shape ``(8, ..., P)``, real roots first.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import DEGENERATE, masked
from mechloop.spatial.quartic import trig_roots
from mechloop.spatial.roots import wrap
from mechloop.spatial.vector import unit

Array = NDArray[np.float64]
Result = tuple[Array, Array, Array, NDArray[np.bool_]]
SAMPLES = 9  # 2·4 + 1: determines a trigonometric polynomial of degree 4


def _f(*v: ArrayLike) -> list[Array]:
    return [np.asarray(x, dtype=float) for x in v]


def _fourier(values: Array) -> tuple[list[Array], list[Array]]:
    """Cosine and sine coefficients (degree 4) from samples on the last axis."""
    x = np.fft.rfft(values, axis=-1) / SAMPLES
    a = [x[..., 0].real] + [2 * x[..., m].real for m in range(1, 5)]
    b = [np.zeros_like(a[0])] + [-2 * x[..., m].imag for m in range(1, 5)]
    return a, b


def _polish(s, r, a, b, which, ok, steps: int = 4):
    """Newton steps on ``S + Σ r u(α, β) = 0``; ``which[m]`` is ``"a"`` or ``"b"``: the
    unknown angle of vector ``m``.  ``a, b`` lists of arrays (3 vectors); updated copies
    are returned."""
    a, b = list(a), list(b)
    for _ in range(steps):
        res = np.stack(np.broadcast_arrays(
            *(s[q] + sum(r[m] * unit(a[m], b[m])[q] for m in range(3)) for q in range(3)),
            ok), axis=-1)[..., :3]
        cols = []
        for m in range(3):
            ca, sa, cb, sb = np.cos(a[m]), np.sin(a[m]), np.cos(b[m]), np.sin(b[m])
            if which[m] == "a":
                col = (-r[m] * sa * cb, r[m] * ca, -r[m] * sa * sb)
            else:
                col = (-r[m] * ca * sb, 0 * ca, r[m] * ca * cb)
            cols.append(np.stack(np.broadcast_arrays(*col, ok), -1)[..., :3])
        jac = np.where(ok[..., None, None], np.stack(cols, axis=-1), np.eye(3))
        det = np.linalg.det(jac)
        good = ok & (np.abs(det) > DEGENERATE)
        jac = np.where(good[..., None, None], jac, np.eye(3))
        step = np.linalg.solve(jac, np.where(good[..., None], res, 0.0)[..., None])[..., 0]
        for m in range(3):
            if which[m] == "a":
                a[m] = a[m] - step[..., m]
            else:
                b[m] = b[m] - step[..., m]
    return a, b


def solve_pr16(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
               beta_i: ArrayLike, r_j: ArrayLike, beta_j: ArrayLike, r_k: ArrayLike,
               beta_k: ArrayLike) -> Result:
    """Pr16 — unknown ``α_i, α_j, α_k`` (8 solutions).
    Returns ``alpha_i, alpha_j, alpha_k, ok`` of shape ``(8, ..., P)``."""
    sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, beta_k = _f(
        sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, beta_k)
    den = r_j * np.sin(beta_j - beta_k)
    good = np.abs(den) > DEGENERATE
    den = np.where(good, den, 1.0)
    ns = -sx * np.sin(beta_k) + sz * np.cos(beta_k)
    ski = np.sin(beta_i - beta_k)

    known = (sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, beta_k, den, ns, ski)

    def parts(ai, sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, beta_k, den, ns, ski):
        ca, sa = np.cos(ai), np.sin(ai)
        cj = -(ns + r_i * ca * ski) / den
        hx = sx + r_i * ca * np.cos(beta_i)
        hy = sy + r_i * sa
        hz = sz + r_i * ca * np.sin(beta_i)
        big_a = hx * hx + hy * hy + hz * hz + r_j * r_j - r_k * r_k \
            + 2 * r_j * cj * (hx * np.cos(beta_j) + hz * np.sin(beta_j))
        return cj, big_a, 2 * r_j * hy

    t = 2 * np.pi * np.arange(SAMPLES) / SAMPLES
    cj, big_a, big_b = parts(t, *(v[..., None] for v in known))
    alpha_i, ok = trig_roots(*_fourier(big_a**2 - big_b**2 * (1 - cj**2)))
    cj, big_a, big_b = parts(alpha_i, *known)
    ok = ok & good & (np.abs(big_b) > DEGENERATE)
    sgn = np.where(big_b >= 0, 1.0, -1.0)
    alpha_j = np.arctan2(-big_a * sgn, cj * np.abs(big_b))
    vi, vj = unit(alpha_i, beta_i), unit(alpha_j, beta_j)
    w = [-(sx, sy, sz)[q] - r_i * vi[q] - r_j * vj[q] for q in range(3)]
    sk = np.where(r_k >= 0, 1.0, -1.0)
    alpha_k = np.arctan2(sk * w[1], sk * (w[0] * np.cos(beta_k) + w[2] * np.sin(beta_k)))
    (alpha_i, alpha_j, alpha_k), _ = _polish(
        (sx, sy, sz), (r_i, r_j, r_k), (alpha_i, alpha_j, alpha_k),
        (beta_i, beta_j, beta_k), "aaa", ok)
    return (*masked(ok, wrap(alpha_i), wrap(alpha_j), wrap(alpha_k)), ok)


def solve_pr17(sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, r_i: ArrayLike,
               beta_i: ArrayLike, r_j: ArrayLike, beta_j: ArrayLike, r_k: ArrayLike,
               alpha_k: ArrayLike) -> Result:
    """Pr17 — unknown ``α_i, α_j, β_k`` (8 solutions).
    Returns ``alpha_i, alpha_j, beta_k, ok`` of shape ``(8, ..., P)``."""
    sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, alpha_k = _f(
        sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, alpha_k)
    good = np.abs(r_j) > DEGENERATE
    rj = np.where(good, r_j, 1.0)
    rho_k = r_k * np.cos(alpha_k)

    known = (sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, alpha_k, rj, rho_k)

    def parts(ai, sx, sy, sz, r_i, beta_i, r_j, beta_j, r_k, alpha_k, rj, rho_k):
        ca, sa = np.cos(ai), np.sin(ai)
        sj = -(sy + r_i * sa + r_k * np.sin(alpha_k)) / rj
        hx = sx + r_i * ca * np.cos(beta_i)
        hz = sz + r_i * ca * np.sin(beta_i)
        big_a = hx * hx + hz * hz + r_j * r_j * (1 - sj * sj) - rho_k * rho_k
        return sj, big_a, 2 * r_j * (hx * np.cos(beta_j) + hz * np.sin(beta_j))

    t = 2 * np.pi * np.arange(SAMPLES) / SAMPLES
    sj, big_a, big_b = parts(t, *(v[..., None] for v in known))
    alpha_i, ok = trig_roots(*_fourier(big_a**2 - big_b**2 * (1 - sj**2)))
    sj, big_a, big_b = parts(alpha_i, *known)
    ok = ok & good & (np.abs(big_b) > DEGENERATE)
    sgn = np.where(big_b >= 0, 1.0, -1.0)
    alpha_j = np.arctan2(sj * np.abs(big_b), -big_a * sgn)
    vi, vj = unit(alpha_i, beta_i), unit(alpha_j, beta_j)
    w = [-(sx, sy, sz)[q] - r_i * vi[q] - r_j * vj[q] for q in range(3)]
    sk = np.where(rho_k >= 0, 1.0, -1.0)
    beta_k = np.arctan2(sk * w[2], sk * w[0])
    (alpha_i, alpha_j, _), (_, _, beta_k) = _polish(
        (sx, sy, sz), (r_i, r_j, r_k), (alpha_i, alpha_j, alpha_k),
        (beta_i, beta_j, beta_k), "aab", ok)
    return (*masked(ok, wrap(alpha_i), wrap(alpha_j), wrap(beta_k)), ok)
