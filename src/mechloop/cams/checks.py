"""What a cam must satisfy, decided over the continuous cam angle.

Every quantity here is a smooth function of the cam angle inside each segment of the
motion program (the laws are), possibly jumping at a join.  So each extreme is found
segment by segment over the closed segment, with that segment's law on both ends
(:meth:`~mechloop.cams.profile.Cam.on_segment`), by
:func:`~mechloop.cams.laws.continuous_max`: a sample, then a zoom on the best
local maxima.  The results say where the extreme is (cam angle, rad).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.cams.laws import continuous_max
from mechloop.cams.profile import Cam, Geometry
from mechloop.cams.program import Motion, MotionProgram

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Extreme:
    """A value and the cam angle (rad) where it is reached."""

    value: float
    phi: float


def segment_max(program: MotionProgram, func: Callable[[int, Array], Array],
                segments: list[int] | None = None) -> Extreme:
    """Max over the turn of ``func(k, phi)`` (segment ``k``'s values at ``phi``), each
    segment over its closed range."""
    edges = program.edges
    best = Extreme(-math.inf, 0.0)
    for k in range(len(program.segments)) if segments is None else segments:
        value, where = continuous_max(lambda x, k=k: func(k, x), edges[k], edges[k + 1])
        if value > best.value:
            best = Extreme(value, where)
    return best


def motion_max(program: MotionProgram, pick: Callable[[Motion], Array]) -> Extreme:
    """Max over the turn of ``pick(motion)`` (e.g. ``lambda m: m.ds``)."""
    return segment_max(program, lambda k, x: pick(program.on_segment(k, x)))


def cam_max(cam: Cam, pick: Callable[[Geometry], Array]) -> Extreme:
    """Max over the turn of ``pick(geometry)``."""
    return segment_max(cam.program, lambda k, x: pick(cam.on_segment(k, x)))


def max_pressure_angle(cam: Cam, kinds: tuple[str, ...] = ("rise", "dwell", "return")
                       ) -> Extreme:
    """Largest ``|α|`` (rad) over the segments of ``kinds``."""
    picked = [k for k, seg in enumerate(cam.program.segments) if seg.kind in kinds]
    if not picked:
        return Extreme(0.0, 0.0)
    return segment_max(cam.program, lambda k, x: np.abs(cam.on_segment(k, x).pressure),
                       picked)


def min_curvature_radius(cam: Cam) -> Extreme:
    """Smallest radius of curvature of the working profile where it is convex (m), found
    as the largest convex curvature ``1/ρ`` (a profile that is concave everywhere has no
    convex part: +∞); for a flat face the smallest ``R₀ + s + s''`` (negative: a cusp)."""
    if cam.follower.flat:
        low = cam_max(cam, lambda g: -g.rho)
        return Extreme(-low.value, low.phi)
    curvature = cam_max(cam, convex_curvature)
    if curvature.value <= 0:
        return Extreme(math.inf, curvature.phi)
    return Extreme(1.0 / curvature.value - cam.follower.roller_radius, curvature.phi)


def convex_curvature(g: Geometry) -> Array:
    """Curvature of the pitch curve, ``−P' × P'' / |P'|³`` (1/m), positive where the cam
    is convex (the pitch curve runs clockwise)."""
    p1, p2 = g.pitch_d1, g.pitch_d2
    return -(p1[..., 0] * p2[..., 1] - p1[..., 1] * p2[..., 0]) / np.hypot(
        p1[..., 0], p1[..., 1])**3


@dataclass(frozen=True)
class FaceWidth:
    """The contact point's travel along a flat face (m, from the axis, or from the foot of
    the pivot's perpendicular on a rocker's face): ``low`` and ``high``, the width
    ``high − low`` (a translating face: the extremes of ``s'`` per rad)."""

    low: Extreme
    high: Extreme

    @property
    def width(self) -> float:
        return self.high.value - self.low.value


def face_width(cam: Cam) -> FaceWidth:
    """Where a flat face touches over the turn."""
    high = cam_max(cam, lambda g: g.contact_along)
    low = cam_max(cam, lambda g: -g.contact_along)
    return FaceWidth(Extreme(-low.value, low.phi), high)
