"""Profile synthesis by inverted motion: the cam stands still, the follower turns about
the cam centre by ``−φ``, and its positions draw the pitch curve and envelop the profile.

In the cam's frame a point ``X`` of the fixed frame is ``R(−φ)X``.  With ``J`` the
quarter turn and ``B`` the follower point (:func:`mechloop.cams.followers.follower_point`),
the pitch curve and its exact analogs are

    P = R(−φ) B,   P' = R(−φ)(B' − J B),   P'' = R(−φ)(B'' − 2 J B' − B).

The cam turns counter-clockwise, so ``P`` runs clockwise round the cam.  A roller's
working profile is the pitch curve offset by the roller radius ``r`` along the exact
normal towards the cam, ``W = P − r J P'/|P'|`` (the inner envelope of the roller
circles); the radius of curvature of the pitch curve is ``ρ = −|P'|³ / (P' × P'')``
(positive where the cam is convex) and the profile's is ``ρ − r``.  A flat face touches
the cam at the distance ``s'`` from the axis along the face: ``W = R(−φ)(s', R₀ + s)``,
with the radius of curvature ``ρ = R₀ + s + s''``.  A rocker's flat face (the line
``A + u·t + f·n``, :mod:`mechloop.cams.followers`) touches where
``u = a cos β / (1 + ψ')`` (the envelope condition of the lines in the cam's frame), and
the profile's radius of curvature is ``ρ = (a sin β + f(1 + ψ') − u')/(1 + ψ')`` (the
rate of the arc along the face over the rate of the face's turn in the cam's frame).

The pressure angle is the angle between the contact normal (the normal of the pitch curve)
and the direction ``d`` in which the follower's point moves,
``α = atan2(T·d, T×d)`` with ``T`` the tangent of the profile as the cam angle grows
(``B' − J B`` for a roller, in the fixed frame's terms): its sign says to which side of
the follower's direction the normal leans; ``tan α = (s' − e)/(s₀ + s)`` for a
translating roller (so a positive offset lowers the pressure angle on the rise); a flat
face perpendicular to the axis has 0, a rocker's face ``α = atan2(f, u)`` (0 when the
face passes through the pivot).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.cams.followers import (
    Follower,
    OscillatingFlat,
    TranslatingFlat,
    base_limits,
    follower_point,
)
from mechloop.cams.program import Motion, MotionProgram

Array = NDArray[np.float64]


def _rotate(v: Array, phi: Array) -> Array:
    """``R(−φ) v`` for ``v`` shape ``(..., 2)``, ``phi`` shape ``(...)``."""
    c, s = np.cos(phi), np.sin(phi)
    return np.stack([c * v[..., 0] + s * v[..., 1], -s * v[..., 0] + c * v[..., 1]], axis=-1)


def _quarter(v: Array) -> Array:
    """``J v``: ``v`` turned by +90°."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def _cross(u: Array, v: Array) -> Array:
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _dot(u: Array, v: Array) -> Array:
    return u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]


@dataclass(frozen=True)
class Geometry:
    """The cam at cam angles ``phi`` (rad, shape ``(...)``); points shape ``(..., 2)``, m,
    in the cam's frame.

    ``pitch``: the follower point's path (the roller centre; for a flat face its foot on
    the axis); ``pitch_d1``, ``pitch_d2``: its analogs per rad; ``profile``: the working
    profile (the contact point); ``normal``: unit contact normal pointing out of the cam;
    ``pressure``: pressure angle (rad); ``pitch_rho``: radius of curvature of the pitch
    curve (m; +∞ where straight; None for a flat face); ``rho``: radius of curvature of
    the working profile (m, positive where convex); ``contact_along``: a flat face's
    contact point along the face (m, from the axis; from the pivot's foot for a rocker),
    None for a roller.
    """

    motion: Motion
    pitch: Array
    pitch_d1: Array
    pitch_d2: Array
    profile: Array
    normal: Array
    pressure: Array
    pitch_rho: Array | None
    rho: Array
    contact_along: Array | None = None


def geometry(follower: Follower, base_radius: float, motion: Motion) -> Geometry:
    """The cam of ``follower`` with ``base_radius`` (m) for the program values ``motion``
    (:meth:`MotionProgram.evaluate` or :meth:`MotionProgram.on_segment`)."""
    phi = motion.phi
    b, db, ddb, d = follower_point(follower, base_radius, motion.s, motion.ds, motion.dds)
    t_fixed = db - _quarter(b)
    p = _rotate(b, phi)
    p1 = _rotate(t_fixed, phi)
    p2 = _rotate(ddb - 2 * _quarter(db) - b, phi)
    if isinstance(follower, TranslatingFlat):
        rho = base_radius + motion.s + motion.dds
        contact = _rotate(np.stack([motion.ds, base_radius + motion.s], axis=-1), phi)
        normal = _rotate(np.stack([np.zeros_like(phi), np.ones_like(phi)], axis=-1), phi)
        return Geometry(motion, p, p1, p2, contact, normal, np.zeros_like(phi), None, rho,
                        motion.ds)
    if isinstance(follower, OscillatingFlat):
        a, f = follower.pivot_distance, follower.face_offset
        beta = follower.start_angle(base_radius) + motion.s
        c, n = np.cos(beta), np.sin(beta)
        turn = 1.0 + motion.ds
        u = a * c / turn
        du = (-a * n * motion.ds * turn - a * c * motion.dds) / turn**2
        rho = (a * n + f * turn - du) / turn
        normal_fixed = np.stack([n, c], axis=-1)
        contact = np.stack([a - u * c, u * n], axis=-1) + f * normal_fixed
        return Geometry(motion, p, p1, p2, _rotate(contact, phi), _rotate(normal_fixed, phi),
                        np.arctan2(f, u), None, rho, u)
    speed = np.hypot(p1[..., 0], p1[..., 1])
    outward = _quarter(p1) / speed[..., None]  # clockwise path: J·tangent points out
    cross = _cross(p1, p2)
    with np.errstate(divide="ignore"):
        pitch_rho = np.where(cross == 0, np.inf, -(speed**3) / np.where(cross == 0, 1, cross))
    r = follower.roller_radius
    pressure = np.arctan2(_dot(t_fixed, d), _cross(t_fixed, d))
    return Geometry(motion, p, p1, p2, p - r * outward, outward, pressure, pitch_rho,
                    pitch_rho - r)


@dataclass(frozen=True)
class Cam:
    """A cam design: the follower, its motion program and the base radius ``R₀`` (m): of
    the pitch curve for a roller follower, of the profile for a flat face."""

    follower: Follower
    program: MotionProgram
    base_radius: float

    def __post_init__(self) -> None:
        lo, hi = base_limits(self.follower)
        if not lo < self.base_radius < hi:
            raise ValueError(f"base radius {self.base_radius:.6g} m is outside ({lo:.6g}, "
                             f"{hi:.6g}) m, where the follower can be placed")

    def at(self, phi: ArrayLike) -> Geometry:
        """The cam at cam angles ``phi`` (rad)."""
        return geometry(self.follower, self.base_radius, self.program.evaluate(phi))

    def on_segment(self, k: int, phi: ArrayLike) -> Geometry:
        """The cam by segment ``k``'s law at ``phi`` (rad), its closed ends included."""
        return geometry(self.follower, self.base_radius, self.program.on_segment(k, phi))

    def cycle(self, positions: int = 360) -> Geometry:
        """The cam at ``positions + 1`` cam angles from 0 to 2π (both ends)."""
        return self.at(np.linspace(0.0, 2 * math.pi, positions + 1))
