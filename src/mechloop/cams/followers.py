"""The three followers and where their point is for a displacement ``s`` (fixed frame).

Conventions (the cam rotates counter-clockwise about the origin ``O``; the fixed frame has
``y`` up):

* :class:`TranslatingRoller` — the follower moves along ``y`` on the line ``x = e``
  (``offset``); the roller centre is at ``(e, s₀ + s)`` with ``s₀ = √(R₀² − e²)``, ``R₀``
  the base radius of the pitch curve (the roller centre's path on the cam);
* :class:`OscillatingRoller` — the rocker turns about ``A = (a, 0)`` (``pivot_distance``
  ``a``); its arm of length ``l`` makes the angle ``β = ψ₀ + ψ`` with the line ``AO`` and
  the roller centre is at ``A + l(−cos β, sin β)``; ``ψ₀`` puts the roller centre at
  distance ``R₀`` from ``O`` when ``ψ = 0``;
* :class:`TranslatingFlat` — the face is perpendicular to the ``y`` axis at
  ``y = R₀ + s`` (``R₀`` the base radius of the profile itself);
* :class:`OscillatingFlat` — a flat face on a rocker pivoted at ``A = (a, 0)``: the face
  is the line ``A + u·t + f·n`` with ``t = (−cos β, sin β)``, ``n = (sin β, cos β)``,
  ``β = ψ₀ + ψ`` its angle from ``AO``, ``f`` the face's offset from the pivot
  (``face_offset``); its distance from ``O`` is ``a sin β + f``, which is ``R₀`` at
  ``ψ = 0``, so ``ψ₀ = asin((R₀ − f)/a)`` (the face stays on the near side of the
  perpendicular to ``AO``: ``β < 90°``).

:func:`follower_point` gives the follower's reference point ``B`` (the roller centre; the
face's foot on the axis) and its first two analogs, and the unit direction ``d`` in which
that point of the follower moves: the pressure angle is the angle between ``d`` and the
contact normal.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


@dataclass(frozen=True)
class TranslatingRoller:
    """A translating roller follower: roller radius (m) and offset ``e`` of its axis
    from the cam centre (m, along +x; the sign chooses the side)."""

    roller_radius: float
    offset: float = 0.0
    kind: str = "translating_roller"
    flat = False
    oscillating = False


@dataclass(frozen=True)
class OscillatingRoller:
    """An oscillating (rocker) roller follower: roller radius, the distance ``a`` from
    the cam centre to the rocker's pivot and the arm ``l`` from the pivot to the roller
    centre (m); its motion program is in radians of the rocker."""

    roller_radius: float
    pivot_distance: float
    arm: float
    kind: str = "oscillating_roller"
    flat = False
    oscillating = True

    def start_angle(self, base_radius: float) -> float:
        """``ψ₀`` (rad): the arm's angle from ``AO`` that puts the roller centre at the
        distance ``base_radius`` from the cam centre."""
        a, arm = self.pivot_distance, self.arm
        return math.acos((a * a + arm * arm - base_radius**2) / (2 * a * arm))


@dataclass(frozen=True)
class TranslatingFlat:
    """A translating flat-faced follower, the face perpendicular to its axis through the
    cam centre."""

    kind: str = "translating_flat"
    flat = True
    oscillating = False


@dataclass(frozen=True)
class OscillatingFlat:
    """An oscillating flat-faced follower: the distance ``a`` from the cam centre to the
    pivot and the face's offset ``f`` from the pivot (m: the face is the line at the distance
    ``f`` from the pivot, on the far side from the cam when ``f > 0``); its
    motion program is in radians of the rocker."""

    pivot_distance: float
    face_offset: float = 0.0
    kind: str = "oscillating_flat"
    flat = True
    oscillating = True

    def start_angle(self, base_radius: float) -> float:
        """``ψ₀`` (rad): the face's angle from ``AO`` that puts it at the distance
        ``base_radius`` from the cam centre."""
        return math.asin((base_radius - self.face_offset) / self.pivot_distance)


Follower = TranslatingRoller | OscillatingRoller | TranslatingFlat | OscillatingFlat


def base_limits(follower: Follower) -> tuple[float, float]:
    """Open interval of base radii (m) for which the follower can be placed at all."""
    if isinstance(follower, TranslatingRoller):
        return abs(follower.offset), math.inf
    if isinstance(follower, OscillatingRoller):
        a, arm = follower.pivot_distance, follower.arm
        return abs(a - arm), a + arm
    if isinstance(follower, OscillatingFlat):
        return max(follower.face_offset, 0.0), follower.face_offset + follower.pivot_distance
    return 0.0, math.inf


def follower_point(follower: Follower, base_radius: float, s: Array, ds: Array, dds: Array
                   ) -> tuple[Array, Array, Array, Array]:
    """``B, B', B''`` (analogs per rad of cam angle) and ``d`` in the fixed frame, each
    shape ``(..., 2)`` for ``s`` of shape ``(...)`` (m, or rad of the rocker)."""
    zero = np.zeros_like(s)
    if isinstance(follower, TranslatingRoller):
        e = follower.offset
        s0 = math.sqrt(base_radius**2 - e * e)
        b = np.stack([zero + e, s0 + s], axis=-1)
        db = np.stack([zero, ds], axis=-1)
        ddb = np.stack([zero, dds], axis=-1)
        d = np.stack([zero, zero + 1.0], axis=-1)
        return b, db, ddb, d
    if isinstance(follower, OscillatingRoller):
        a, arm = follower.pivot_distance, follower.arm
        beta = follower.start_angle(base_radius) + s
        c, n = np.cos(beta), np.sin(beta)
        b = np.stack([a - arm * c, arm * n], axis=-1)
        d = np.stack([n, c], axis=-1)
        db = arm * d * ds[..., None]
        ddb = arm * (np.stack([c, -n], axis=-1) * (ds * ds)[..., None]
                     + d * dds[..., None])
        return b, db, ddb, d
    if isinstance(follower, OscillatingFlat):  # the face's foot from the pivot, A + f·n
        a, f = follower.pivot_distance, follower.face_offset
        beta = follower.start_angle(base_radius) + s
        c, n = np.cos(beta), np.sin(beta)
        normal = np.stack([n, c], axis=-1)
        along = np.stack([-c, n], axis=-1)
        b = np.stack([zero + a, zero], axis=-1) + f * normal
        db = -f * along * ds[..., None]
        ddb = -f * (normal * (ds * ds)[..., None] + along * dds[..., None])
        return b, db, ddb, normal
    b = np.stack([zero, base_radius + s], axis=-1)
    return (b, np.stack([zero, ds], axis=-1), np.stack([zero, dds], axis=-1),
            np.stack([zero, zero + 1.0], axis=-1))
