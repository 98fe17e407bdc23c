"""All real roots of a trigonometric polynomial of degree 2 (the quartic modules)::

    f(θ) = A0 + A1 cos θ + B1 sin θ + A2 cos 2θ + B2 sin 2θ = 0

With ``z = e^{iθ}``, ``z² f`` is a complex polynomial of degree 4 whose roots on the unit
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


def _f(theta, a0, a1, b1, a2, b2):
    return a0 + a1 * np.cos(theta) + b1 * np.sin(theta) + a2 * np.cos(2 * theta) \
        + b2 * np.sin(2 * theta)


def _df(theta, a1, b1, a2, b2):
    return -a1 * np.sin(theta) + b1 * np.cos(theta) - 2 * a2 * np.sin(2 * theta) \
        + 2 * b2 * np.cos(2 * theta)


def trig_quartic(a0: ArrayLike, a1: ArrayLike, b1: ArrayLike, a2: ArrayLike,
                 b2: ArrayLike) -> tuple[Array, NDArray[np.bool_]]:
    """The (up to 4) real roots of ``f``, shape ``(4, ...)`` (rad, ``(−π, π]``), real
    roots first in increasing angle, NaN with ``ok`` false for the missing ones.  A root
    of multiplicity two (a tangency) appears twice."""
    a0, a1, b1, a2, b2 = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (a0, a1, b1, a2, b2)))
    shape = a0.shape
    scale = np.abs(a0) + np.abs(a1) + np.abs(b1) + np.abs(a2) + np.abs(b2)
    unit = np.where(scale > 0, scale, 1.0)
    # z² f(θ) = c4 z⁴ + c3 z³ + c2 z² + c1 z + c0
    c4 = (a2 - 1j * b2) / 2 / unit
    c3 = (a1 - 1j * b1) / 2 / unit
    c2 = (a0 + 0j) / unit
    c1 = (a1 + 1j * b1) / 2 / unit
    c0 = (a2 + 1j * b2) / 2 / unit
    tiny = 1e-14
    c4 = np.where(np.abs(c4) < tiny, tiny, c4)  # degree drop: push the lost roots to ∞
    comp = np.zeros((*shape, 4, 4), dtype=complex)
    comp[..., 1, 0] = comp[..., 2, 1] = comp[..., 3, 2] = 1.0
    comp[..., 0, 3] = -c0 / c4
    comp[..., 1, 3] = -c1 / c4
    comp[..., 2, 3] = -c2 / c4
    comp[..., 3, 3] = -c3 / c4
    z = np.moveaxis(np.linalg.eigvals(comp), -1, 0)  # (4, ...)
    near = np.abs(np.abs(z) - 1.0) < UNIT_CIRCLE_SLACK
    theta = np.angle(z)
    for _ in range(3):
        d = _df(theta, a1, b1, a2, b2)
        step = _f(theta, a0, a1, b1, a2, b2) / np.where(d != 0, d, 1.0)
        theta = theta - np.where(d != 0, step, 0.0)
    theta = wrap(theta)
    ok = near & (np.abs(_f(theta, a0, a1, b1, a2, b2)) <= RESIDUAL_RTOL * unit) & (scale > 0)
    key = np.where(ok, theta, np.inf)
    order = np.argsort(key, axis=0)
    theta = np.take_along_axis(theta, order, axis=0)
    ok = np.take_along_axis(ok, order, axis=0)
    return np.where(ok, theta, np.nan), ok
