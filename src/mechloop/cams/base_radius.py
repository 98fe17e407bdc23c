"""The smallest base radius: for a roller follower, the smallest ``R₀`` whose pressure
angle stays within the allowed one over the whole turn; for a flat face, the smallest
whose profile is convex (radius of curvature at least a given one).

Decided over the continuous cam angle (:mod:`mechloop.cams.checks`):

* translating roller: ``tan α = (s' − e)/(s₀ + s)``, so ``|α| ≤ α_allow`` everywhere is
  ``s₀ ≥ max_φ (|s' − e| / tan α_allow − s)`` — a maximum over the continuous angle — and
  ``R₀ = √(s₀² + e²)``;
* oscillating roller: the largest ``|α|`` over the turn is a function of ``R₀``; the
  smallest ``R₀`` where it is within the limit is bracketed on a grid of ``R₀`` over the
  interval where the rocker can be placed and found by Brent's method
  (:func:`scipy.optimize.brentq`), each value of the function a continuous maximum;
* flat face: ``ρ = R₀ + s + s'' ≥ ρ_min`` everywhere is
  ``R₀ ≥ ρ_min + max_φ (−s − s'')``; the face must also stay above the cam centre,
  ``R₀ + s > 0``;
* a rocker's flat face: the smallest ``ρ`` over the turn against ``R₀``, bracketed and
  solved like the oscillating roller's pressure angle.

The rise and the dwells are held to ``allowed``, the returns to ``allowed_return`` (the
return of a force-closed cam is driven by the spring: a larger angle is usual).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy.optimize import brentq

from mechloop.cams.checks import (
    max_pressure_angle,
    min_curvature_radius,
    motion_max,
    segment_max,
)
from mechloop.cams.followers import (
    Follower,
    OscillatingFlat,
    OscillatingRoller,
    TranslatingRoller,
    base_limits,
)
from mechloop.cams.profile import Cam
from mechloop.cams.program import MotionProgram
from mechloop.errors import HintedError

#: Grid of base radii scanned for the oscillating follower before Brent's method.
ROCKER_GRID = 64


class CamDesignError(HintedError):
    """A cam cannot be designed as asked (no base radius meets the conditions)."""


def _allowed(program: MotionProgram, allowed: float, allowed_return: float | None
             ) -> list[float]:
    back = allowed if allowed_return is None else allowed_return
    return [back if seg.kind == "return" else allowed for seg in program.segments]


def max_pressure_ratio(cam: Cam, allowed: float, allowed_return: float | None = None
                       ) -> float:
    """Largest ``|α| / α_allow`` over the turn (each segment against its own limit):
    at most 1 when the pressure angle stays within the limits."""
    limits = _allowed(cam.program, allowed, allowed_return)
    worst = 0.0
    for k, limit in enumerate(limits):
        worst = max(worst, max_pressure_angle_of(cam, k) / limit)
    return worst


def max_pressure_angle_of(cam: Cam, k: int) -> float:
    """Largest ``|α|`` (rad) over segment ``k``."""
    return segment_max(cam.program, lambda j, x: np.abs(cam.on_segment(j, x).pressure),
                       [k]).value


def minimum_base_radius(follower: Follower, program: MotionProgram, allowed: float, *,
                        allowed_return: float | None = None) -> float:
    """The smallest base radius (m) of a roller follower's pitch curve for which the
    pressure angle stays within ``allowed`` (rad; ``allowed_return`` on the returns) over
    the whole turn."""
    if not 0 < allowed < math.pi / 2 or (allowed_return is not None
                                         and not 0 < allowed_return < math.pi / 2):
        raise CamDesignError("an allowed pressure angle must be between 0 and 90 deg",
                             "e.g. 30 deg for a translating follower, 45 for a rocker")
    limits = _allowed(program, allowed, allowed_return)
    if isinstance(follower, TranslatingRoller):
        e = follower.offset
        need = segment_max(program, lambda k, x: _s0_needed(program, k, x, e, limits[k]))
        lo, _ = base_limits(follower)
        radius = math.hypot(max(need.value, 0.0), e)
        if radius <= lo:  # the condition holds down to the offset: not a design limit
            raise CamDesignError(
                f"the pressure angle stays within the limit for any base radius above the "
                f"offset {lo:.6g} m", "give the base radius itself (base_radius:)")
        return radius
    if isinstance(follower, OscillatingRoller):
        return _rocker_minimum(follower, program, allowed, allowed_return)
    raise CamDesignError("a flat face perpendicular to its axis has a pressure angle of 0",
                         "use minimum_flat_base_radius (a convex profile) instead")


def _s0_needed(program: MotionProgram, k: int, x, e: float, limit: float):
    m = program.on_segment(k, x)
    return np.abs(m.ds - e) / math.tan(limit) - m.s


def _rocker_minimum(follower: OscillatingRoller, program: MotionProgram, allowed: float,
                    allowed_return: float | None) -> float:
    high, low = _swing(program)
    limits = np.array(_allowed(program, allowed, allowed_return))
    phi = np.linspace(0.0, 2 * math.pi, 4 * 360 + 1)
    segment = program.evaluate(phi).segment

    def fits(radius: float) -> bool:  # the arm's angle β = ψ₀ + ψ stays in (0, π)
        start = follower.start_angle(radius)
        return 0 < start + low and start + high < math.pi

    def sampled(radius: float) -> float:
        ratio = np.abs(Cam(follower, program, radius).at(phi).pressure) / limits[segment]
        return float(ratio.max()) - 1.0

    def excess(radius: float) -> float:
        return max_pressure_ratio(Cam(follower, program, radius), allowed,
                                  allowed_return) - 1.0

    return _smallest_radius(follower, fits, sampled, excess, CamDesignError(
        "no base radius keeps the pressure angle within the limit for this rocker",
        "lengthen the arm, move the pivot, lower the swing or allow a larger angle"))


def _swing(program: MotionProgram) -> tuple[float, float]:
    """Largest and smallest displacement over the turn."""
    return (motion_max(program, lambda m: m.s).value,
            -motion_max(program, lambda m: -m.s).value)


def _smallest_radius(follower: Follower, fits: Callable[[float], bool],
                     sampled: Callable[[float], float], excess: Callable[[float], float],
                     failure: CamDesignError) -> float:
    """The smallest base radius where ``excess`` (over the continuous turn) is at most 0,
    among those that ``fits``: a scan of :data:`ROCKER_GRID` radii over the interval where
    the follower can be placed by ``sampled`` (the excess on a dense sample: a lower
    bound, cheap), then Brent's method on the continuous ``excess`` in the first bracket
    (the excess falls with the radius there)."""
    lo, hi = base_limits(follower)
    span = hi - lo

    def fitting(f: Callable[[float], float]) -> Callable[[float], float]:
        return lambda r: f(r) if fits(r) else math.inf

    sampled, excess = fitting(sampled), fitting(excess)
    grid = lo + span * np.linspace(0.0, 1.0, ROCKER_GRID + 2)[1:-1]
    scan = [sampled(float(r)) for r in grid]
    first = next((i for i, v in enumerate(scan) if v <= 0), None)
    while first is not None and excess(float(grid[first])) > 0:
        first = first + 1 if first + 1 < len(grid) else None
    if first is None:
        raise failure
    right = float(grid[first])
    left = float(grid[first - 1]) if first else lo + span * 1e-9
    if not math.isfinite(excess(left)):  # the geometry ends inside the bracket: bisect it
        inner = right
        for _ in range(60):
            mid = 0.5 * (left + inner)
            if fits(mid):
                inner = mid
            else:
                left = mid
        left = inner
    if excess(left) <= 0:  # feasible down to where the follower can be placed at all
        return left
    tol = 1e-12 * span
    root = float(brentq(excess, left, right, xtol=tol, rtol=4 * np.finfo(float).eps))
    for nudge in (0.0, 2 * tol, 8 * tol):  # the feasible side, within Brent's tolerance
        if excess(root + nudge) <= 0:
            return root + nudge
    return right


def minimum_flat_base_radius(program: MotionProgram, min_radius: float = 0.0, *,
                             follower: Follower | None = None) -> float:
    """The smallest base radius (m) of a flat-faced follower's cam whose profile has a
    radius of curvature of at least ``min_radius`` (m) everywhere.  A translating face
    (the default): ``R₀ = ρ_min + max_φ(−s − s'')``, and above ``−min s`` (the face above
    the centre); a rocker's face (:class:`OscillatingFlat`): the smallest radius by
    :func:`_smallest_radius`, its face kept at ``0 < β < 90°``."""
    if isinstance(follower, OscillatingFlat):
        return _oscillating_flat_minimum(follower, program, min_radius)
    need = motion_max(program, lambda m: -m.s - m.dds).value + min_radius
    above = motion_max(program, lambda m: -m.s).value
    if need <= above:
        raise CamDesignError(
            f"the profile is convex for any base radius above {max(above, 0):.6g} m",
            "give the base radius itself (base_radius:), or a larger min_curvature_radius")
    return need


def _oscillating_flat_minimum(follower: OscillatingFlat, program: MotionProgram,
                              min_radius: float) -> float:
    high, low = _swing(program)
    phi = np.linspace(0.0, 2 * math.pi, 4 * 360 + 1)
    scale = follower.pivot_distance

    def fits(radius: float) -> bool:
        start = follower.start_angle(radius)
        return 0 < start + low and start + high < math.pi / 2

    def sampled(radius: float) -> float:
        return (min_radius - float(Cam(follower, program, radius).at(phi).rho.min())) / scale

    def excess(radius: float) -> float:
        return (min_radius - min_curvature_radius(Cam(follower, program, radius)).value) / scale

    return _smallest_radius(follower, fits, sampled, excess, CamDesignError(
        "no base radius gives this rocker's face a convex profile",
        "move the pivot farther, lower the swing or use slower laws"))


__all__ = ["CamDesignError", "max_pressure_angle", "max_pressure_ratio",
           "minimum_base_radius", "minimum_flat_base_radius"]
