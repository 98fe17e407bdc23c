"""Normalized follower motion laws of cam design, with exact derivatives to the jerk.

A law is ``f(τ)`` over ``τ ∈ [0, 1]`` with ``f(0) = 0`` and ``f(1) = 1``; a segment of
the motion program scales it (``s = s₀ ± h·f((φ − φ₀)/β)``).  Each law gives ``f, f', f'',
f'''`` (derivatives with respect to τ) exactly, and says how smooth it joins a dwell
(:attr:`Law.continuity`: 0 — the velocity jumps at the ends, 1 — the acceleration jumps,
2 — the jerk jumps, 3 — the jerk is continuous too).

=====================  =========================================================  =====
law                    f(τ)                                                       joins
=====================  =========================================================  =====
``constant_speed``     τ                                                          C⁰
``harmonic``           (1 − cos πτ)/2                                             C¹
``cycloidal``          τ − sin(2πτ)/(2π)                                          C²
``poly345``            10τ³ − 15τ⁴ + 6τ⁵                                          C²
``poly4567``           35τ⁴ − 84τ⁵ + 70τ⁶ − 20τ⁷                                  C³
``modified_trapezoidal``  acceleration: sine quarter-waves over τ ∈ [0, ⅛], [⅜, ⅝],  C²
                       [⅞, 1], constant between (Norton, *Cam Design and
                       Manufacturing Handbook*, 2nd ed., sec. 3.8)
``modified_sine``      acceleration: sine quarter-waves of period ½ over [0, ⅛]    C²
                       and [⅞, 1], of period 3/2 over [⅛, ⅞] (Norton, sec. 3.9)
=====================  =========================================================  =====

The peak coefficients ``C_v = max|f'|``, ``C_a = max|f''|``, ``C_j = max|f'''|`` are
computed from the laws (:func:`peak_coefficients`), over the continuous τ, never written
down: the tests compare them with the textbook values.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import make_interp_spline

Array = NDArray[np.float64]
Shape = Callable[[Array], tuple[Array, Array, Array, Array]]

#: Names of the standard laws, in the order of the table above.
LAW_NAMES = ("constant_speed", "harmonic", "cycloidal", "poly345", "poly4567",
             "modified_trapezoidal", "modified_sine")


@dataclass(frozen=True)
class Law:
    """A normalized motion law: ``shape(τ) -> (f, f', f'', f''')`` for ``τ`` in [0, 1]
    (any shape), with ``continuity`` the order of the derivatives that are continuous
    where it joins a dwell (see the module notes)."""

    name: str
    shape: Shape = field(repr=False, compare=False)
    continuity: int

    def __call__(self, tau: ArrayLike) -> tuple[Array, Array, Array, Array]:
        t = np.clip(np.asarray(tau, dtype=float), 0.0, 1.0)
        return self.shape(t)


def _constant_speed(t: Array):
    return t, np.ones_like(t), np.zeros_like(t), np.zeros_like(t)


def _harmonic(t: Array):
    p = math.pi
    return ((1 - np.cos(p * t)) / 2, p / 2 * np.sin(p * t), p**2 / 2 * np.cos(p * t),
            -(p**3) / 2 * np.sin(p * t))


def _cycloidal(t: Array):
    w = 2 * math.pi
    return (t - np.sin(w * t) / w, 1 - np.cos(w * t), w * np.sin(w * t),
            w**2 * np.cos(w * t))


def _polynomial(coefficients: dict[int, float]) -> Shape:
    """``f = Σ c_k τ^k`` and its derivatives."""
    poly = np.polynomial.Polynomial([coefficients.get(k, 0.0)
                                     for k in range(max(coefficients) + 1)])
    ders = [poly, poly.deriv(1), poly.deriv(2), poly.deriv(3)]

    def shape(t: Array):
        return tuple(d(t) for d in ders)  # type: ignore[return-value]

    return shape


@dataclass(frozen=True)
class _Piece:
    """One piece of a piecewise acceleration ``c + A sin(ω(τ − τ₀) + φ)`` on
    ``[τ₀, τ₁]``."""

    start: float
    c: float
    amplitude: float = 0.0
    omega: float = 1.0
    phase: float = 0.0


def _piecewise_sine(pieces: tuple[_Piece, ...]) -> Shape:
    """The law whose acceleration is ``pieces`` times a constant chosen so that
    ``f(1) = 1``: velocity and displacement integrated exactly piece by piece from
    ``f(0) = f'(0) = 0``."""
    starts = np.array([p.start for p in pieces] + [1.0])

    def integrate(scale: float, t: Array, index: Array):
        f = np.zeros_like(t)
        v = np.zeros_like(t)
        a = np.zeros_like(t)
        j = np.zeros_like(t)
        f0 = v0 = 0.0
        for k, p in enumerate(pieces):
            c, amp = scale * p.c, scale * p.amplitude
            w, ph = p.omega, p.phase

            def at(u, c=c, amp=amp, w=w, ph=ph, f0=f0, v0=v0):
                arg = w * u + ph
                acc = c + amp * np.sin(arg)
                jerk = amp * w * np.cos(arg)
                vel = v0 + c * u - amp / w * (np.cos(arg) - math.cos(ph))
                disp = (f0 + v0 * u + c * u * u / 2 - amp / w**2 * (np.sin(arg) - math.sin(ph))
                        + amp / w * math.cos(ph) * u)
                return disp, vel, acc, jerk

            here = index == k
            u = t[here] - p.start
            f[here], v[here], a[here], j[here] = at(u)
            end = np.array([starts[k + 1] - p.start])
            fe, ve, _, _ = at(end)
            f0, v0 = float(fe[0]), float(ve[0])
        return f, v, a, j, f0

    _, _, _, _, total = integrate(1.0, np.zeros(0), np.zeros(0, dtype=int))
    scale = 1.0 / total

    def shape(t: Array):
        index = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(pieces) - 1)
        flat = t.reshape(-1)
        out = integrate(scale, flat, index.reshape(-1))[:4]
        return tuple(o.reshape(t.shape) for o in out)  # type: ignore[return-value]

    return shape


_Q = 4 * math.pi  # a quarter sine wave over τ-length 1/8
_MOD_TRAP = (_Piece(0.0, 0.0, 1.0, _Q), _Piece(1 / 8, 1.0), _Piece(3 / 8, 0.0, 1.0, _Q,
             math.pi / 2), _Piece(5 / 8, -1.0), _Piece(7 / 8, 0.0, -1.0, _Q, math.pi / 2))
_MOD_SINE = (_Piece(0.0, 0.0, 1.0, _Q), _Piece(1 / 8, 0.0, 1.0, 4 * math.pi / 3,
             math.pi / 2), _Piece(7 / 8, 0.0, -1.0, _Q, math.pi / 2))

STANDARD: dict[str, Law] = {
    "constant_speed": Law("constant_speed", _constant_speed, 0),
    "harmonic": Law("harmonic", _harmonic, 1),
    "cycloidal": Law("cycloidal", _cycloidal, 2),
    "poly345": Law("poly345", _polynomial({3: 10, 4: -15, 5: 6}), 2),
    "poly4567": Law("poly4567", _polynomial({4: 35, 5: -84, 6: 70, 7: -20}), 3),
    "modified_trapezoidal": Law("modified_trapezoidal", _piecewise_sine(_MOD_TRAP), 2),
    "modified_sine": Law("modified_sine", _piecewise_sine(_MOD_SINE), 2),
}


def law(name: str) -> Law:
    """The standard law ``name`` (one of :data:`LAW_NAMES`)."""
    try:
        return STANDARD[name]
    except KeyError:
        raise ValueError(f"unknown law {name!r}; use one of {', '.join(LAW_NAMES)}") from None


def table_law(tau: ArrayLike, value: ArrayLike, name: str = "table") -> Law:
    """A law through the points ``(τ_k, f_k)`` (τ from 0 to 1 increasing, ``f`` from 0 to
    1): the interpolating quintic spline with zero velocity and acceleration at both ends
    (:func:`scipy.interpolate.make_interp_spline`, ``k = 5``), so it joins dwells with a
    continuous acceleration (C²)."""
    t = np.asarray(tau, dtype=float)
    f = np.asarray(value, dtype=float)
    ends = [(1, 0.0), (2, 0.0)]
    spline = make_interp_spline(t, f, k=5, bc_type=(ends, ends))
    ders = [spline, spline.derivative(1), spline.derivative(2), spline.derivative(3)]

    def shape(x: Array):
        return tuple(np.asarray(d(x), dtype=float) for d in ders)  # type: ignore[return-value]

    return Law(name, shape, 2)


@dataclass(frozen=True)
class PeakCoefficients:
    """``C_v = max|f'|``, ``C_a = max|f''|``, ``C_j = max|f'''|`` over ``τ ∈ [0, 1]``
    (dimensionless: the peak velocity of a segment is ``C_v·h/β``, acceleration
    ``C_a·h/β²``, jerk ``C_j·h/β³``, per radian of cam angle)."""

    velocity: float
    acceleration: float
    jerk: float


def continuous_max(func: Callable[[Array], Array], lo: float, hi: float, *,
                   samples: int = 513, refine: int = 4, zoom: int = 33) -> tuple[float, float]:
    """``(max, argmax)`` of a smooth ``func`` (vectorized) over the continuous ``[lo, hi]``:
    sampled at ``samples`` points, then each of the ``refine`` best sampled local maxima
    refined by zooming: its bracket between the neighbouring samples is sampled at
    ``zoom`` points and narrowed to the best one's neighbours, all brackets in one call,
    until the brackets are ``1e-13·(hi − lo)`` wide (a maximum of a smooth function is
    located to that, its value to rounding).  The ends count."""
    x = np.linspace(lo, hi, samples)
    y = func(x)
    # local maxima of the samples, the ends included: a peak between an end and its
    # neighbour leaves the end the larger of the two
    peak = np.r_[y[0] >= y[1], (y[1:-1] >= y[:-2]) & (y[1:-1] >= y[2:]), y[-1] >= y[-2]]
    found = np.flatnonzero(peak)
    found = found[np.argsort(-y[found], kind="stable")][:refine]
    best = int(np.argmax(y))
    value, where = float(y[best]), float(x[best])
    left = x[np.maximum(found - 1, 0)]
    right = x[np.minimum(found + 1, samples - 1)]
    steps = np.linspace(0.0, 1.0, zoom)
    while True:
        points = left[:, None] + (right - left)[:, None] * steps
        values = func(points.reshape(-1)).reshape(points.shape)
        k = np.argmax(values, axis=1)
        rows = np.arange(points.shape[0])
        top = values[rows, k]
        if top.max() > value:
            value, where = float(top.max()), float(points[rows, k][np.argmax(top)])
        if (right - left).max() <= 1e-13 * (hi - lo):
            return value, where
        left = points[rows, np.maximum(k - 1, 0)]
        right = points[rows, np.minimum(k + 1, zoom - 1)]


def peak_coefficients(law_: Law) -> PeakCoefficients:
    """The peak coefficients of a law over the continuous ``τ ∈ [0, 1]``."""
    peaks = [continuous_max(lambda t, k=k: np.abs(law_(t)[k]), 0.0, 1.0)[0]
             for k in (1, 2, 3)]
    return PeakCoefficients(*peaks)
