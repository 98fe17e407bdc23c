"""Deviations of traced curves and functions from their targets, for a whole population.

Every function takes arrays with designs on the leading axis and positions on the last,
``(D, P)``, and returns one deviation per design and target, ``(D, K)``, in the units of
its inputs.  No loop over designs or positions.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


#: Designs per block of the distance computation: its (rows, K, P) temporaries stay in
#: the CPU cache.
_ROWS = 16
#: Smallest normal double: a squared segment length below it is a point.
_TINY = np.finfo(np.float64).tiny


def distance_to_curve(z: NDArray[np.complex128], targets: NDArray[np.complex128]) -> Array:
    """Distance from each target to the nearest point of the traced polyline.

    ``z`` : complex, shape ``(D, P)`` — the traced point at every position (x + iy);
    ``targets`` : complex, shape ``(K,)``.  The curve is the polyline through the
    positions in order (segments between neighbours), so the result does not depend on
    where between two positions the nearest point falls.  Returns ``(D, K)``.
    """
    if z.shape[0] > _ROWS:
        return np.concatenate([distance_to_curve(z[i:i + _ROWS], targets)
                               for i in range(0, z.shape[0], _ROWS)])
    x, y = z.real, z.imag
    ax, ay = x[:, None, :-1], y[:, None, :-1]                  # (D, 1, S)
    sx, sy = np.diff(x, axis=-1)[:, None, :], np.diff(y, axis=-1)[:, None, :]
    length2 = sx * sx + sy * sy
    # a segment shorter than ~1e-154 is a point (1 / its subnormal length² overflows)
    inv = np.divide(1.0, length2, out=np.zeros_like(length2), where=length2 > _TINY)
    rx = targets.real[None, :, None] - ax                     # (D, K, S)
    ry = targets.imag[None, :, None] - ay
    t = (rx * sx + ry * sy) * inv
    np.clip(t, 0.0, 1.0, out=t)
    rx -= t * sx
    ry -= t * sy
    rx *= rx
    ry *= ry
    rx += ry
    return np.sqrt(rx.min(axis=-1))


def nearest_on_curve(z: NDArray[np.complex128], targets: NDArray[np.complex128]
                     ) -> tuple[Array, Array, NDArray[np.complex128]]:
    """Where the traced polyline comes nearest each target: the distance, the position
    parameter ``s`` (position ``floor(s)`` plus the share of the segment to the next),
    and the nearest point, each ``(D, K)``.  ``z`` : complex ``(D, P)``, ``targets`` :
    complex ``(K,)`` or one row per design ``(D, K)``; the distance is that of
    :func:`distance_to_curve`."""
    targets = np.broadcast_to(targets, (z.shape[0], targets.shape[-1]))
    if z.shape[0] > _ROWS:
        parts = [nearest_on_curve(z[i:i + _ROWS], targets[i:i + _ROWS])
                 for i in range(0, z.shape[0], _ROWS)]
        return tuple(np.concatenate(p) for p in zip(*parts, strict=True))
    a = z[:, None, :-1]                                        # (D, 1, S)
    seg = np.diff(z, axis=-1)[:, None, :]
    length2 = seg.real ** 2 + seg.imag ** 2
    inv = np.divide(1.0, length2, out=np.zeros_like(length2), where=length2 > _TINY)
    rel = targets[:, :, None] - a                               # (D, K, S)
    t = np.clip((rel.real * seg.real + rel.imag * seg.imag) * inv, 0.0, 1.0)
    gap = rel - t * seg
    d2 = gap.real ** 2 + gap.imag ** 2
    best = np.nan_to_num(d2, nan=np.inf).argmin(axis=-1)[..., None]     # (D, K, 1)
    share = np.take_along_axis(t, best, axis=-1)[..., 0]
    start = np.take_along_axis(np.broadcast_to(a, d2.shape), best, axis=-1)[..., 0]
    step = np.take_along_axis(np.broadcast_to(seg, d2.shape), best, axis=-1)[..., 0]
    distance = np.sqrt(np.take_along_axis(d2, best, axis=-1)[..., 0])
    return distance, best[..., 0] + share, start + share * step


def distance_at_positions(z: NDArray[np.complex128], targets: NDArray[np.complex128],
                          positions: NDArray[np.int64]) -> Array:
    """Distance from target ``k`` to the traced point at position ``positions[k]``
    (path generation with timing).  Returns ``(D, K)``."""
    return np.abs(z[:, positions] - targets[None, :])


def pose_error(z: NDArray[np.complex128], angle: Array, targets: NDArray[np.complex128],
               target_angles: Array, length: float,
               positions: NDArray[np.int64] | None) -> Array:
    """Motion generation: ``sqrt(distance² + (length · angle error)²)`` per pose.

    ``angle`` (rad) is the guided body's direction, ``(D, P)``; angle errors are wrapped to
    ``(−π, π]``.  With ``positions`` each pose is compared with its position, otherwise
    with the position where the combined error is least.  Returns ``(D, K)``.
    """
    if positions is not None:
        dz = z[:, positions] - targets[None, :]
        da = angle[:, positions] - target_angles[None, :]
        da = np.angle(np.exp(1j * da))
        return np.sqrt(np.abs(dz) ** 2 + (length * da) ** 2)
    dz = z[:, None, :] - targets[None, :, None]
    da = np.angle(np.exp(1j * (angle[:, None, :] - target_angles[None, :, None])))
    return np.sqrt(np.abs(dz) ** 2 + (length * da) ** 2).min(axis=-1)


def function_error(output: Array, target: Array, *, relative: bool) -> Array:
    """Function generation: output minus target at every position, ``(D, P)``; with
    ``relative`` the increments from position 0 are compared."""
    if relative:
        return (output - output[:, :1]) - (target - target[0])[None, :]
    return output - target[None, :]


def reduce_deviation(dev: Array, kind: str, weights: Array | None = None) -> Array:
    """The main criterion Q per design from deviations ``(D, K)``: ``'max'`` the largest
    weighted |deviation|, ``'rms'`` the root mean square, ``'ssq'`` the sum of squares."""
    if weights is not None:
        dev = dev * weights[None, :]
    if kind == "max":
        return np.abs(dev).max(axis=-1)
    if kind == "rms":
        return np.sqrt(np.mean(dev * dev, axis=-1))
    return np.sum(dev * dev, axis=-1)


def polygon_outside(z: NDArray[np.complex128], polygon: NDArray[np.complex128]) -> Array:
    """How far each point lies outside a closed polygon (0 inside), same shape as ``z``.

    Inside is decided by the even–odd crossing rule, the distance is to the nearest edge.
    """
    a = polygon
    b = np.roll(polygon, -1)
    pts = z[..., None]
    # crossing rule: edges that straddle the point's y and cross to its right
    ay, by_ = a.imag, b.imag
    straddle = (ay > pts.imag) != (by_ > pts.imag)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        # the share along the edge first: in [0, 1] where the edge straddles, even when
        # the edge's height is subnormal (only edges that straddle are used)
        x_cross = a.real + (pts.imag - ay) / (by_ - ay) * (b.real - a.real)
    inside = (np.count_nonzero(straddle & (pts.real < x_cross), axis=-1) % 2) == 1
    seg = b - a
    rel = pts - a
    length2 = seg.real ** 2 + seg.imag ** 2
    point = length2 <= _TINY  # a degenerate edge: its start point
    t = np.clip((rel.real * seg.real + rel.imag * seg.imag) / np.where(point, 1, length2),
                0, 1)
    t = np.where(point, 0.0, t)
    dist = np.abs(rel - t * seg).min(axis=-1)
    return np.where(inside, 0.0, dist)


def box_outside(z: NDArray[np.complex128], low: complex, high: complex) -> Array:
    """How far each point lies outside the box ``[low, high]`` (0 inside)."""
    dx = np.maximum(np.maximum(low.real - z.real, z.real - high.real), 0.0)
    dy = np.maximum(np.maximum(low.imag - z.imag, z.imag - high.imag), 0.0)
    return np.hypot(dx, dy)
