"""Root helpers shared by the spatial modules: every module except the quartic and
octic ones reduces to one of two scalar equations, solved here with both roots.

Branch axis first: a helper returns arrays of shape ``(2, ...)`` (branch, then the
broadcast input shape ``(..., P)``), NaN with ``ok`` false where a root is not real.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

Array = NDArray[np.float64]

#: Relative slack on existence conditions so that an exact tangency (a toggle position)
#: computed with round-off is not reported as a break (as in the planar modules).
EXISTENCE_RTOL = 1e-12


def wrap(angle: ArrayLike) -> Array:
    """Angle moved into ``(−π, π]`` (rad)."""
    a = np.asarray(angle, dtype=float)
    w = np.arctan2(np.sin(a), np.cos(a))
    return np.where(w == -np.pi, np.pi, w)


def trig_linear(a: ArrayLike, b: ArrayLike, c: ArrayLike) -> tuple[Array, NDArray[np.bool_]]:
    """Both roots of ``a cos θ + b sin θ = c``.

    Returns ``theta`` shape ``(2, ...)``: branch 1 ``atan2(b, a) + acos(c/h)``, branch 2
    ``atan2(b, a) − acos(c/h)`` with ``h = hypot(a, b)`` (rad, wrapped to ``(−π, π]``),
    and ``ok`` shape ``(2, ...)``, false where ``|c| > h`` or ``h = 0``.
    """
    a, b, c = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (a, b, c)))
    h = np.hypot(a, b)
    ok = (h > 0) & (np.abs(c) <= h * (1.0 + EXISTENCE_RTOL))
    with np.errstate(divide="ignore", invalid="ignore"):
        half = np.arccos(np.clip(c / np.where(h > 0, h, 1.0), -1.0, 1.0))
    mid = np.arctan2(b, a)
    theta = wrap(np.stack([mid + half, mid - half]))
    ok2 = np.stack([ok, ok])
    return np.where(ok2, theta, np.nan), ok2


def quadratic(a2: ArrayLike, a1: ArrayLike, a0: ArrayLike) -> tuple[Array, NDArray[np.bool_]]:
    """Both real roots of ``a2 t² + a1 t + a0 = 0``, smaller first (shape ``(2, ...)``).

    Computed without cancellation (``q = −(a1 + sign(a1)√D)/2``, roots ``q/a2, a0/q``).
    Where ``a2 = 0`` the equation is linear and only branch 1 carries its root.
    """
    a2, a1, a0 = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (a2, a1, a0)))
    disc = a1 * a1 - 4.0 * a2 * a0
    scale = np.maximum(a1 * a1, np.abs(4.0 * a2 * a0))
    real = disc >= -EXISTENCE_RTOL * scale
    sq = np.sqrt(np.maximum(disc, 0.0))
    q = -0.5 * (a1 + np.where(a1 >= 0, sq, -sq))
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = q / a2
        t2 = np.where(q != 0, a0 / np.where(q != 0, q, 1.0), t1)
        lin = -a0 / a1
    quad = a2 != 0
    lo = np.where(quad, np.minimum(t1, t2), lin)
    hi = np.where(quad, np.maximum(t1, t2), np.nan)
    t = np.stack([lo, hi])
    ok = np.stack([real & (quad | (a1 != 0)), real & quad]) & np.isfinite(t)
    return np.where(ok, t, np.nan), ok
