"""Exact velocities and accelerations of a spatial contour's three unknowns (DESIGN §3
in 3-D).  Differentiating the closure ``Σ r u(α, β) = 0`` in time::

    Σ ṙ u + r (α̇ u_α + β̇ u_β) = 0
    Σ r̈ u + 2 ṙ (α̇ u_α + β̇ u_β) + r (α̈ u_α + β̈ u_β)
        + r (α̇² u_αα + 2 α̇ β̇ u_αβ + β̇² u_ββ) = 0

Both are linear in the three unknown rates with one 3×3 matrix (the module's Jacobian:
columns ``u``, ``r u_α`` or ``r u_β`` of the unknown parameters), solved per position by
a batched ``numpy.linalg.solve``.  "Analogs" (derivatives with respect to the argument)
are the same computation with unit argument rate.

Parameters are arrays of shape ``(m, ..., P)`` over the contour's ``m`` vectors; the
entries of the unknowns in the rate arrays are ignored.  ``unknowns`` names the three
unknowns as ``(vector index, "r" | "a" | "b")``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.parts import DEGENERATE

Array = NDArray[np.float64]
Unknowns = list[tuple[int, str]]


def _basis(alpha: Array, beta: Array) -> dict[str, Array]:
    ca, sa, cb, sb = np.cos(alpha), np.sin(alpha), np.cos(beta), np.sin(beta)
    z = np.zeros_like(ca * cb)
    return {
        "u": np.stack([ca * cb, sa + z, ca * sb]),
        "a": np.stack([-sa * cb, ca + z, -sa * sb]),
        "b": np.stack([-ca * sb, z, ca * cb]),
        "ab": np.stack([sa * sb, z, -sa * cb]),
        "bb": np.stack([-ca * cb, z, -ca * sb]),
    }


def _zeroed(x: Array, unknowns: Unknowns, name: str) -> Array:
    x = np.array(x, dtype=float, copy=True)
    for v, p in unknowns:
        if p == name:
            x[v] = 0.0
    return x


def _solve(r: Array, alpha: Array, beta: Array, rhs: Array, unknowns: Unknowns
           ) -> tuple[Array, Array, Array, NDArray[np.bool_]]:
    cols = []
    for v, p in unknowns:
        e = _basis(alpha[v], beta[v])
        cols.append(e["u"] if p == "r" else r[v] * e[p])
    mat = np.moveaxis(np.stack(np.broadcast_arrays(*cols)), (0, 1), (-1, -2))  # (..., 3, 3)
    det = np.linalg.det(np.where(np.isfinite(mat), mat, 0.0))
    ok = np.isfinite(det) & (np.abs(det) > DEGENERATE) & np.isfinite(rhs).all(axis=0)
    mat = np.where(ok[..., None, None], mat, np.eye(3))
    b = np.where(ok[..., None], np.moveaxis(rhs, 0, -1), 0.0)
    x = np.linalg.solve(mat, b[..., None])[..., 0]
    x = np.where(ok[..., None], x, np.nan)
    return x[..., 0], x[..., 1], x[..., 2], ok


def rates(r: ArrayLike, alpha: ArrayLike, beta: ArrayLike, dr: ArrayLike, dalpha: ArrayLike,
          dbeta: ArrayLike, unknowns: Unknowns) -> tuple[Array, Array, Array,
                                                         NDArray[np.bool_]]:
    """First time derivatives of the three unknowns, each shape ``(..., P)`` (units of the
    parameter per second), and ``ok`` (false where the Jacobian is singular: a dead
    point or a break)."""
    r, alpha, beta = (np.asarray(x, dtype=float) for x in (r, alpha, beta))
    dr, da, db = (_zeroed(x, unknowns, n) for x, n in ((dr, "r"), (dalpha, "a"),
                                                      (dbeta, "b")))
    total = 0.0
    for v in range(r.shape[0]):
        e = _basis(alpha[v], beta[v])
        total = total + dr[v] * e["u"] + r[v] * (da[v] * e["a"] + db[v] * e["b"])
    return _solve(r, alpha, beta, -total, unknowns)


def accelerations(r: ArrayLike, alpha: ArrayLike, beta: ArrayLike, dr: ArrayLike,
                  dalpha: ArrayLike, dbeta: ArrayLike, ddr: ArrayLike, ddalpha: ArrayLike,
                  ddbeta: ArrayLike, unknowns: Unknowns) -> tuple[Array, Array, Array,
                                                                  NDArray[np.bool_]]:
    """Second time derivatives of the three unknowns.  The first derivatives ``dr,
    dalpha, dbeta`` must be complete (the unknowns' rates from :func:`rates` filled in)."""
    r, alpha, beta, dr, da, db = (np.asarray(x, dtype=float)
                                  for x in (r, alpha, beta, dr, dalpha, dbeta))
    ddr, dda, ddb = (_zeroed(x, unknowns, n) for x, n in ((ddr, "r"), (ddalpha, "a"),
                                                          (ddbeta, "b")))
    total = 0.0
    for v in range(r.shape[0]):
        e = _basis(alpha[v], beta[v])
        turn = da[v] * e["a"] + db[v] * e["b"]
        total = total + ddr[v] * e["u"] + 2.0 * dr[v] * turn \
            + r[v] * (dda[v] * e["a"] + ddb[v] * e["b"]) \
            + r[v] * (-da[v] ** 2 * e["u"] + 2.0 * da[v] * db[v] * e["ab"]
                      + db[v] ** 2 * e["bb"])
    return _solve(r, alpha, beta, -total, unknowns)
