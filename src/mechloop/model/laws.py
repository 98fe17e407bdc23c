"""Motion laws for model arguments, with exact first and second derivatives.

A law moves a value from ``q0`` to ``q1`` while a clock ``c`` (time, or the position number
when the model has no time) goes from ``c0`` to ``c1``.  With ``τ = (c − c0)/(c1 − c0)``
and ``h = q1 − q0`` the value is ``q0 + h·f(τ)``; outside ``[c0, c1]`` the end values hold
and the derivatives are zero.

=================  ==========================================
law                f(τ)
=================  ==========================================
constant_speed     τ
harmonic           (1 − cos πτ)/2
cycloidal          τ − sin(2πτ)/(2π)
poly345            10τ³ − 15τ⁴ + 6τ⁵
=================  ==========================================
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

Array = NDArray[np.float64]


def _shape(law: str, tau: Array) -> tuple[Array, Array, Array]:
    """``f, f', f''`` of a normalized law at ``tau`` in [0, 1]."""
    if law == "constant_speed":
        return tau, np.ones_like(tau), np.zeros_like(tau)
    # sines are taken of the distance to the nearer end so that they vanish exactly there
    # (sin(π) in floating point is 1.2e-16, which would make a dwell look like motion)
    near = np.minimum(tau, 1.0 - tau)
    if law == "harmonic":
        return ((1 - np.cos(np.pi * tau)) / 2, np.pi / 2 * np.sin(np.pi * near),
                np.pi**2 / 2 * np.cos(np.pi * tau))
    if law == "cycloidal":
        w = 2 * np.pi
        sin_w = np.where(tau <= 0.5, 1.0, -1.0) * np.sin(w * near)
        return (tau - sin_w / w, 1 - np.cos(w * tau), w * sin_w)
    if law == "poly345":
        t2, t3 = tau * tau, tau**3
        return (10 * t3 - 15 * t3 * tau + 6 * t3 * t2, 30 * t2 - 60 * t3 + 30 * t2 * t2,
                60 * tau - 180 * t2 + 120 * t3)
    raise ValueError(f"unknown law {law!r}")


def evaluate_law(
    law: str, clock: ArrayLike, c0: float, c1: float, q0: float, q1: float
) -> tuple[Array, Array, Array]:
    """Value and exact derivatives of a law with respect to the clock.

    Parameters
    ----------
    law : one of ``constant_speed``, ``harmonic``, ``cycloidal``, ``poly345``.
    clock : array, shape (P,) — time in s (or position numbers).
    c0, c1 : clock at the start and the end of the law, ``c1 > c0``.
    q0, q1 : value at the start and at the end (SI).

    Returns
    -------
    q, dq/dc, d²q/dc² : arrays, shape (P,).
    """
    c = np.asarray(clock, dtype=float)
    span = c1 - c0
    tau = (c - c0) / span
    inside = (tau >= 0) & (tau <= 1)
    f, df, ddf = _shape(law, np.clip(tau, 0.0, 1.0))
    h = q1 - q0
    q = q0 + h * f
    dq = np.where(inside, h * df / span, 0.0)
    ddq = np.where(inside, h * ddf / span**2, 0.0)
    return q, dq, ddq
