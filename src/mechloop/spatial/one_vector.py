"""Pr1 — all three parameters ``r_i, α_i, β_i`` of one vector unknown (1 solution):
the inverse of the spatial vector, ``r_i u(α_i, β_i) = −S`` (seed 000 table 2.1)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.vector import parameters

Array = NDArray[np.float64]


def solve_pr1(
    sx: ArrayLike, sy: ArrayLike, sz: ArrayLike, *, convention: int = 1
) -> tuple[Array, Array, Array, NDArray[np.bool_]]:
    """Pr1 — ``r_i ≥ 0, α_i, β_i`` closing the known sum ``S = (sx, sy, sz)``.

    Returns ``r_i, alpha_i, beta_i, ok``, each shape ``(1, ...)`` (one branch, then the
    broadcast input shape ``(..., P)``); angles in ``convention`` (see
    :mod:`mechloop.spatial.vector`).  ``ok`` is false where ``S = 0``.
    """
    r, a, b, ok = parameters(-np.asarray(sx, float), -np.asarray(sy, float),
                             -np.asarray(sz, float), convention=convention)
    return r[None], a[None], b[None], ok[None]
