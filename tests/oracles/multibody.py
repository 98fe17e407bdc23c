"""Oracle for the motion in time: a slider-crank as three free bodies held by constraints.

Nothing of mechloop is used.  Every body has its own coordinates ``(x, y, φ)`` of its centre
of mass and its angle (nine in all); the pins and the slide are eight constraint equations
``Φ(x) = 0``; Newton–Euler's equations of every body with the constraint forces as Lagrange
multipliers, in the index-1 form

    | M   Φ_xᵀ | | ẍ |   | Q |
    | Φ_x  0   | | λ | = | γ − 2α·Φ̇ − β²·Φ |

(``γ`` the velocity terms of ``Φ̈ = 0``; Baumgarte's terms keep the drift from the
constraints down), are integrated by ``solve_ivp`` for the 18 states.  The mechanism is the
offset slider-crank of the tests: crank ``a`` pinned at the origin ``O``, rod ``b`` from the
crank pin ``A`` to the slider's pin ``B``, the slider on the line ``y = −e``; loads: gravity
(−y), a force ``P`` along −x on the slider and a moment ``moment(ω)`` on the crank.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp


@dataclass(frozen=True)
class Body:
    """Mass (kg), moment of inertia about the centre (kg·m²) and the centre's place on the
    link as a share of its length from its first point (O for the crank, A for the rod)."""

    mass: float
    inertia: float
    share: float = 0.0


@dataclass(frozen=True)
class SliderCrank:
    """Crank ``a``, rod ``b``, guide offset ``e`` (m: the slider runs on ``y = −e``)."""

    a: float
    b: float
    e: float
    crank: Body
    rod: Body
    slider: Body
    g: float = 0.0
    push: float = 0.0  # N along −x on the slider

    def points(self) -> tuple[tuple[float, float], ...]:
        """Local x of O and A on the crank, of A and B on the rod, from the centres."""
        c, r = self.crank.share, self.rod.share
        return ((-c * self.a, (1 - c) * self.a), (-r * self.b, (1 - r) * self.b))

    def start(self, theta: float, omega: float) -> np.ndarray:
        """The 18 states at crank angle ``theta`` (rad) turning at ``omega`` (rad/s), the
        rod with cos φ2 > 0 (the slider on the +x side)."""
        a, b, e = self.a, self.b, self.e
        phi2 = math.asin((-e - a * math.sin(theta)) / b)
        dphi2 = -a * math.cos(theta) * omega / (b * math.cos(phi2))
        (o1, _), (a2, _) = self.points()
        x1 = -o1 * np.exp(1j * theta)
        v1 = 1j * omega * x1
        pin = a * np.exp(1j * theta)
        vpin = 1j * omega * pin
        x2 = pin - a2 * np.exp(1j * phi2)
        v2 = vpin - 1j * dphi2 * a2 * np.exp(1j * phi2)
        bpin = pin + b * np.exp(1j * phi2)
        vb = vpin + 1j * dphi2 * b * np.exp(1j * phi2)
        x = [x1.real, x1.imag, theta, x2.real, x2.imag, phi2, bpin.real, bpin.imag, 0.0]
        v = [v1.real, v1.imag, omega, v2.real, v2.imag, dphi2, vb.real, vb.imag, 0.0]
        return np.array(x + v)


def _rot(phi: float, p: float) -> tuple[float, float]:
    return p * math.cos(phi), p * math.sin(phi)


def _drot(phi: float, p: float) -> tuple[float, float]:
    return -p * math.sin(phi), p * math.cos(phi)


def constraints(m: SliderCrank, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``Φ`` (8,) and ``Φ_x`` (8, 9) at coordinates ``x`` (9,)."""
    (o1, a1), (a2, b2) = m.points()
    x1, y1, p1, x2, y2, p2, x3, y3, p3 = x
    phi = np.zeros(8)
    jac = np.zeros((8, 9))
    ox, oy = _rot(p1, o1)
    phi[0:2] = x1 + ox, y1 + oy
    jac[0:2, 0:3] = [[1, 0, _drot(p1, o1)[0]], [0, 1, _drot(p1, o1)[1]]]
    ax1, ay1 = _rot(p1, a1)
    ax2, ay2 = _rot(p2, a2)
    phi[2:4] = x1 + ax1 - x2 - ax2, y1 + ay1 - y2 - ay2
    jac[2:4, 0:3] = [[1, 0, _drot(p1, a1)[0]], [0, 1, _drot(p1, a1)[1]]]
    jac[2:4, 3:6] = [[-1, 0, -_drot(p2, a2)[0]], [0, -1, -_drot(p2, a2)[1]]]
    bx, by = _rot(p2, b2)
    phi[4:6] = x2 + bx - x3, y2 + by - y3
    jac[4:6, 3:6] = [[1, 0, _drot(p2, b2)[0]], [0, 1, _drot(p2, b2)[1]]]
    jac[4:6, 6:8] = [[-1, 0], [0, -1]]
    phi[6], phi[7] = y3 + m.e, p3
    jac[6, 7] = jac[7, 8] = 1.0
    return phi, jac


def _gamma(m: SliderCrank, x: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The velocity terms: ``Φ_x ẍ = γ`` from ``Φ̈ = 0`` (a point ``R(φ)p`` accelerates by
    ``−R(φ)p·φ̇²`` besides ``R'(φ)p·φ̈``)."""
    (o1, a1), (a2, b2) = m.points()
    p1, p2 = x[2], x[5]
    w1, w2 = v[2], v[5]
    g = np.zeros(8)
    g[0:2] = np.array(_rot(p1, o1)) * w1**2
    g[2:4] = np.array(_rot(p1, a1)) * w1**2 - np.array(_rot(p2, a2)) * w2**2
    g[4:6] = np.array(_rot(p2, b2)) * w2**2
    return g


def simulate(m: SliderCrank, moment: Callable[[float, float], float], theta0: float,
             omega0: float, t_eval: np.ndarray, *, rtol: float = 1e-11, atol: float = 1e-12,
             baumgarte: float = 20.0) -> tuple[np.ndarray, np.ndarray, float]:
    """Crank angle (rad) and speed (rad/s) at ``t_eval`` (s), and the largest constraint
    residual ``|Φ|`` (m or rad) met at those times.  ``moment(t, ω)`` is the moment on the
    crank (N·m)."""
    mass = np.diag([m.crank.mass, m.crank.mass, m.crank.inertia, m.rod.mass, m.rod.mass,
                    m.rod.inertia, m.slider.mass, m.slider.mass, m.slider.inertia])
    weights = np.array([m.crank.mass, m.rod.mass, m.slider.mass])

    def rhs(t: float, s: np.ndarray) -> np.ndarray:
        x, v = s[:9], s[9:]
        phi, jac = constraints(m, x)
        q = np.zeros(9)
        q[[1, 4, 7]] = -weights * m.g
        q[6] -= m.push
        q[2] += moment(t, v[2])
        rate = jac @ v
        gamma = _gamma(m, x, v) - 2 * baumgarte * rate - baumgarte**2 * phi
        system = np.block([[mass, jac.T], [jac, np.zeros((8, 8))]])
        acc = np.linalg.solve(system, np.concatenate([q, gamma]))[:9]
        return np.concatenate([v, acc])

    sol = solve_ivp(rhs, (0.0, float(t_eval[-1])), m.start(theta0, omega0), method="DOP853",
                    rtol=rtol, atol=atol, t_eval=t_eval)
    assert sol.success, sol.message
    drift = max(float(np.abs(constraints(m, sol.y[:9, k])[0]).max())
                for k in range(sol.t.size))
    return sol.y[2], sol.y[11], drift
