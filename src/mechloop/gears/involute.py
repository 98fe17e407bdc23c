"""The involute function, its inverse, and the tooth thickness on any circle.

``inv α = tan α − α``.  The thickness of an involute tooth on the circle of diameter
``d_y`` follows from its thickness ``s`` on the reference circle ``d`` (ISO 21771, the
transverse tooth thickness on a circle):

    s_y = d_y · (s/d + inv α − inv α_y),   cos α_y = d_b/d_y.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from mechloop.errors import HintedError


def inv(alpha: ArrayLike) -> np.ndarray:
    """The involute function ``tan α − α``; ``alpha`` in rad, any shape."""
    alpha = np.asarray(alpha, dtype=float)
    return np.tan(alpha) - alpha


def inv_inverse(value: ArrayLike) -> np.ndarray:
    """The angle ``α`` in [0, π/2) with ``inv α = value`` (rad, same shape as ``value``).

    Newton's method from the cube-root start ``(3v)^(1/3)`` (inv α ≈ α³/3), safeguarded so
    every step stays in (0, π/2); converges to machine precision in a few steps.

    >>> round(float(np.degrees(inv_inverse(0.014904383867336446))), 9)
    20.0
    """
    v = np.asarray(value, dtype=float)
    if np.any(~np.isfinite(v)) or np.any(v < 0):
        raise HintedError("the involute function is defined for angles 0 to 90°: a negative "
                          "or non-finite value has no angle",
                          "check the shifts and the centre distance")
    a = np.minimum(np.cbrt(3.0 * v), 1.5)
    for _ in range(60):
        t = np.tan(a)
        f = t - a - v
        step = f / np.maximum(t * t, 1e-300)
        new = np.where(step > a, 0.5 * a, a - step)          # stay above 0
        new = np.where(new >= np.pi / 2, 0.5 * (a + np.pi / 2), new)  # and below π/2
        if np.all(np.abs(new - a) <= 1e-15 * np.maximum(1.0, np.abs(a))):
            a = new
            break
        a = new
    return np.where(v == 0, 0.0, a)


def pressure_angle_on_circle(d_b: ArrayLike, d_y: ArrayLike) -> np.ndarray:
    """The pressure angle ``α_y = arccos(d_b/d_y)`` on a circle of diameter ``d_y ≥ d_b``
    (rad)."""
    d_b, d_y = np.asarray(d_b, float), np.asarray(d_y, float)
    if np.any(d_y < d_b * (1 - 1e-12)):
        raise HintedError("a circle inside the base circle has no involute",
                          "take a diameter at least the base diameter d_b")
    return np.arccos(np.clip(d_b / d_y, -1.0, 1.0))


def thickness_on_circle(s: ArrayLike, d: ArrayLike, alpha: ArrayLike, d_y: ArrayLike
                        ) -> np.ndarray:
    """Transverse tooth thickness (arc) on the circle ``d_y``: ``d_y (s/d + inv α − inv α_y)``.

    ``s`` : thickness on the reference circle ``d``; ``alpha`` : the pressure angle on the
    reference circle (rad).  Lengths in any one unit; broadcasts.  A negative result means
    the flanks have crossed below ``d_y`` (the tooth is pointed there).
    """
    s, d, alpha, d_y = (np.asarray(v, float) for v in (s, d, alpha, d_y))
    d_b = d * np.cos(alpha)
    alpha_y = pressure_angle_on_circle(d_b, d_y)
    return d_y * (s / d + inv(alpha) - inv(alpha_y))


def chordal_thickness(s_y: ArrayLike, d_y: ArrayLike, d_a: ArrayLike
                      ) -> tuple[np.ndarray, np.ndarray]:
    """The chord of the tooth on the circle ``d_y`` and its height over that chord from the
    tip circle ``d_a`` (what a gear tooth caliper measures): ``(s̄_y, h̄_y)`` with
    ``s̄_y = d_y sin(s_y/d_y)`` and ``h̄_y = (d_a − d_y cos(s_y/d_y))/2``."""
    s_y, d_y, d_a = (np.asarray(v, float) for v in (s_y, d_y, d_a))
    half = s_y / d_y
    return d_y * np.sin(half), 0.5 * (d_a - d_y * np.cos(half))
