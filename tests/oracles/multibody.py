"""Oracles for the motion in time: a slider-crank (one input) and a five-bar (two inputs)
as free bodies held by constraints.

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


# ---------------------------------------------------------------- a two-input five-bar


@dataclass(frozen=True)
class FiveBar:
    """A five-bar with two cranks as four free bodies held by five pins (nothing of
    mechloop is used): crank 1 ``O–A`` (length ``a``, pivot ``O`` at the origin), link 2
    ``A–B`` (``b``), link 3 ``B–E`` (``c``), crank 4 ``D–E`` (``d``, pivot ``D`` at
    ``(g, 0)``); every body's centre at the middle of its two pins; ``up``: B on the left
    of the line from A to E (else on the right).  Loads: gravity ``g_acc`` along −y, a
    linear spring ``stiffness`` (N/m) of free length ``free`` (m) from the ground point
    ``(g/2, 0)`` to ``B``, and a moment on each crank ``moments(t, ω1, ω4)``."""

    a: float
    b: float
    c: float
    d: float
    g: float
    bodies: tuple[Body, Body, Body, Body]
    up: bool = True
    g_acc: float = 0.0
    stiffness: float = 0.0
    free: float = 0.0

    def pins(self) -> list[tuple[int, float, int, float]]:
        """(body, local x, body, local x) per pin, body −1 the ground at global ``(x,
        0)``; each body's local x axis runs along it (O→A, A→B, B→E, D→E), its centre
        at 0."""
        a, b, c, d = self.a / 2, self.b / 2, self.c / 2, self.d / 2
        return [(0, -a, -1, 0.0), (0, a, 1, -b), (1, b, 2, -c), (2, c, 3, d),
                (3, -d, -1, self.g)]

    def start(self, q1: float, q4: float, w1: float, w4: float) -> np.ndarray:
        """The 24 states at crank angles ``q1``, ``q4`` (rad; crank 4's angle is that of
        ``D → E``) turning at ``w1``, ``w4`` (rad/s)."""
        pa = self.a * np.exp(1j * q1)
        pe = self.g + self.d * np.exp(1j * q4)
        span = pe - pa
        ell = abs(span)
        cos_t = (self.b**2 + ell**2 - self.c**2) / (2 * self.b * ell)
        turn = math.acos(cos_t) * (1 if self.up else -1)
        pb = pa + self.b * span / ell * np.exp(1j * turn)
        centres = [pa / 2, (pa + pb) / 2, (pb + pe) / 2, (self.g + pe) / 2]
        angles = [q1, np.angle(pb - pa), np.angle(pe - pb), q4]
        x = np.array([v for z, p in zip(centres, angles, strict=True)
                      for v in (z.real, z.imag, p)])
        # velocities: the pins' constraints with the two crank rates prescribed
        _, jac = self.constraints(x)
        rows = np.zeros((2, 12))
        rows[0, 2] = rows[1, 11] = 1.0
        v = np.linalg.solve(np.vstack([jac, rows]), np.concatenate([np.zeros(10), [w1, w4]]))
        return np.concatenate([x, v])

    def constraints(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``Φ`` (10,) and ``Φ_x`` (10, 12): every pin's two bodies' points coincide."""
        phi, jac = np.zeros(10), np.zeros((10, 12))
        for k, (i, pi, j, pj) in enumerate(self.pins()):
            rows = slice(2 * k, 2 * k + 2)
            for body, p, sign in ((i, pi, 1.0), (j, pj, -1.0)):
                if body < 0:
                    phi[rows] += sign * np.array([p, 0.0])
                    continue
                px, py = x[3 * body], x[3 * body + 1]
                rx, ry = _rot(x[3 * body + 2], p)
                dx, dy = _drot(x[3 * body + 2], p)
                phi[rows] += sign * np.array([px + rx, py + ry])
                jac[rows, 3 * body:3 * body + 3] += sign * np.array([[1, 0, dx], [0, 1, dy]])
        return phi, jac

    def gamma(self, x: np.ndarray, v: np.ndarray) -> np.ndarray:
        """The velocity terms ``γ`` of ``Φ_x ẍ = γ``."""
        out = np.zeros(10)
        for k, (i, pi, j, pj) in enumerate(self.pins()):
            for body, p, sign in ((i, pi, 1.0), (j, pj, -1.0)):
                if body >= 0:
                    out[2 * k:2 * k + 2] += sign * np.array(_rot(x[3 * body + 2], p)) \
                        * v[3 * body + 2] ** 2
        return out

    def point_b(self, x: np.ndarray) -> tuple[float, float]:
        """The pin B (from link 2)."""
        rx, ry = _rot(x[5], self.b / 2)
        return x[3] + rx, x[4] + ry

    def energy(self, s: np.ndarray) -> float:
        """Kinetic plus potential energy (gravity and the spring), J."""
        x, v = s[:12], s[12:]
        kinetic = sum(0.5 * (body.mass * (v[3 * n]**2 + v[3 * n + 1]**2)
                             + body.inertia * v[3 * n + 2]**2)
                      for n, body in enumerate(self.bodies))
        height = sum(body.mass * self.g_acc * x[3 * n + 1] for n, body in enumerate(self.bodies))
        bx, by = self.point_b(x)
        stretch = math.hypot(bx - self.g / 2, by) - self.free
        return kinetic + height + 0.5 * self.stiffness * stretch**2


def simulate_five_bar(m: FiveBar, moments: Callable[[float, float, float], tuple[float, float]],
                      start: tuple[float, float, float, float], t_eval: np.ndarray, *,
                      rtol: float = 1e-11, atol: float = 1e-12, baumgarte: float = 20.0
                      ) -> tuple[np.ndarray, np.ndarray, float]:
    """The cranks' angles and speeds ``(4, len(t_eval))`` (q1, q4, ω1, ω4: rad, rad/s),
    the 24 states ``(24, len(t_eval))``, and the largest constraint residual met."""
    masses = np.repeat([b.mass for b in m.bodies], 3)
    masses[2::3] = [b.inertia for b in m.bodies]
    mass = np.diag(masses)

    def rhs(t: float, s: np.ndarray) -> np.ndarray:
        x, v = s[:12], s[12:]
        phi, jac = m.constraints(x)
        q = np.zeros(12)
        q[1::3] = -np.array([b.mass for b in m.bodies]) * m.g_acc
        if m.stiffness:  # the spring pulls B (on link 2, local x = b/2) to (g/2, 0)
            bx, by = m.point_b(x)
            length = math.hypot(bx - m.g / 2, by)
            tension = m.stiffness * (length - m.free)
            fx, fy = -tension * (bx - m.g / 2) / length, -tension * by / length
            rx, ry = _rot(x[5], m.b / 2)
            q[3:6] += [fx, fy, rx * fy - ry * fx]
        m1, m4 = moments(t, v[2], v[11])
        q[2] += m1
        q[11] += m4
        gamma = m.gamma(x, v) - 2 * baumgarte * (jac @ v) - baumgarte**2 * phi
        system = np.block([[mass, jac.T], [jac, np.zeros((10, 10))]])
        acc = np.linalg.solve(system, np.concatenate([q, gamma]))[:12]
        return np.concatenate([v, acc])

    sol = solve_ivp(rhs, (0.0, float(t_eval[-1])), m.start(*start), method="DOP853",
                    rtol=rtol, atol=atol, t_eval=t_eval)
    assert sol.success, sol.message
    drift = max(float(np.abs(m.constraints(sol.y[:12, k])[0]).max())
                for k in range(sol.t.size))
    cranks = np.array([sol.y[2], sol.y[11], sol.y[14], sol.y[23]])
    return cranks, sol.y, drift
