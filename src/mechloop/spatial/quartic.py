"""All real roots of a trigonometric polynomial of degree ``n`` (2 for the quartic
modules, 4 for the octic ones), e.g. for ``n = 2``::

    f(θ) = A0 + A1 cos θ + B1 sin θ + A2 cos 2θ + B2 sin 2θ = 0

With ``z = e^{iθ}``, ``zⁿ f`` is a complex polynomial of degree ``2n`` whose roots on the unit
circle are the real roots (no tangent half-angle: nothing special happens at ``θ = π``).
Its companion matrices, one per position, go through one batched
``numpy.linalg.eigvals``; candidates with ``| |z| − 1 | < 1e-5`` are polished by three
Newton steps on the real ``f`` and kept where ``|f| ≤ 1e-10 · Σ|coefficients|``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.spatial.roots import wrap

Array = NDArray[np.float64]

UNIT_CIRCLE_SLACK = 1e-5
RESIDUAL_RTOL = 1e-10


def _eval(theta: Array, a: list[Array], b: list[Array]) -> tuple[Array, Array]:
    """``f(θ)`` and ``f'(θ)`` for cosine coefficients ``a[m]`` and sine coefficients
    ``b[m]`` (``b[0]`` unused)."""
    f = a[0] + 0.0 * theta
    df = 0.0 * theta
    for m in range(1, len(a)):
        c, s = np.cos(m * theta), np.sin(m * theta)
        f = f + a[m] * c + b[m] * s
        df = df + m * (-a[m] * s + b[m] * c)
    return f, df


def trig_roots(a: list[ArrayLike], b: list[ArrayLike]) -> tuple[Array, NDArray[np.bool_]]:
    """The (up to ``2n``) real roots of ``Σ_{m=0..n} a[m] cos mθ + b[m] sin mθ = 0``,
    shape ``(2n, ...)`` (rad, ``(−π, π]``), real roots first in increasing angle, NaN
    with ``ok`` false for the missing ones.  A double root (tangency) appears twice."""
    arrs = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (*a, *b)))
    n = len(a) - 1
    finite = np.logical_and.reduce([np.isfinite(v) for v in arrs])
    arrs = [np.where(finite, v, 0.0) for v in arrs]  # a broken input is a break, silently
    a, b = list(arrs[: n + 1]), list(arrs[n + 1:])
    shape = a[0].shape
    scale = sum(np.abs(v) for v in a) + sum(np.abs(v) for v in b[1:])
    unit = np.where(scale > 0, scale, 1.0)
    # z^n f(θ): coefficient of z^(n+m) is (a_m − i b_m)/2, of z^(n−m) is (a_m + i b_m)/2
    coef = np.zeros((2 * n + 1, *shape), dtype=complex)  # coef[k] multiplies z^k
    coef[n] = a[0] / unit
    for m in range(1, n + 1):
        coef[n + m] = (a[m] - 1j * b[m]) / 2 / unit
        coef[n - m] = (a[m] + 1j * b[m]) / 2 / unit
    lead = coef[2 * n]
    lead = np.where(np.abs(lead) < 1e-14, 1e-14, lead)  # degree drop: lost roots go to ∞
    deg = 2 * n
    comp = np.zeros((*shape, deg, deg), dtype=complex)
    for k in range(1, deg):
        comp[..., k, k - 1] = 1.0
    for k in range(deg):
        comp[..., k, deg - 1] = -coef[k] / lead
    z = np.moveaxis(np.linalg.eigvals(comp), -1, 0)  # (2n, ...)
    near = np.abs(np.abs(z) - 1.0) < UNIT_CIRCLE_SLACK
    theta = np.angle(z)
    for _ in range(3):
        f, df = _eval(theta, a, b)
        theta = theta - np.where(df != 0, f / np.where(df != 0, df, 1.0), 0.0)
    theta = wrap(theta)
    ok = near & (np.abs(_eval(theta, a, b)[0]) <= RESIDUAL_RTOL * unit) & (scale > 0) & finite
    order = np.argsort(np.where(ok, theta, np.inf), axis=0)
    theta = np.take_along_axis(theta, order, axis=0)
    ok = np.take_along_axis(ok, order, axis=0)
    return np.where(ok, theta, np.nan), ok


def trig_quartic(a0: ArrayLike, a1: ArrayLike, b1: ArrayLike, a2: ArrayLike,
                 b2: ArrayLike) -> tuple[Array, NDArray[np.bool_]]:
    """The (up to 4) real roots of ``f`` (degree 2), shape ``(4, ...)``: see
    :func:`trig_roots`."""
    zero = np.zeros_like(np.asarray(a0, dtype=float))
    return trig_roots([a0, a1, a2], [zero, b1, b2])
