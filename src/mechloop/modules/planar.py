"""Planar elementary modules Pl1–Pl4: closed-form positions of a closed vector contour.

A planar contour closes when ``Σ r_i (cos α_i, sin α_i) = 0``.  ``X, Y`` are the sums of
the known vectors; the two unknowns sit on "vector 1" and "vector 2" of the module
(DESIGN.md §2, seed 000 sec. 1.5):

========  ==============  =========  ==================================================
module    unknowns        solutions  variant convention
========  ==============  =========  ==================================================
Pl1       ``r1, α1``      1          —
Pl2       ``r1, r2``      1          —
Pl3       ``r1, α2``      2          1: ``cos(α2 − α1) < 0``; 2: ``cos(α2 − α1) ≥ 0``
Pl4       ``α1, α2``      2          1: ``α1 = α_p + B, α2 = α_p − A``; 2: signs swapped
========  ==============  =========  ==================================================

Each module has a core ``plN_unit`` that returns directions as cosines and sines (no
trigonometric calls: they dominate the cost of a solve) and a wrapper ``solve_plN`` that
returns angles.  Every function is pure and works on arrays of any shape ``(..., P)``
(positions last, candidate designs leading) by broadcasting.  Lengths are in any consistent
unit, angles in radians.  Each returns the unknowns and a boolean ``ok`` mask: where ``ok``
is false the contour has no (unique) real solution — a chain break — and the unknowns are
NaN.

``variant`` is 1, 2, or an integer array of 1/2 broadcastable to the result (used when the
variant is tracked by continuity, see :func:`track_variant`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

Array = NDArray[np.float64]

#: Relative slack allowed on the existence conditions so that an exact toggle position
#: (triangle collapsed to a line) computed with round-off is not reported as a break.
EXISTENCE_RTOL = 1e-12


def _sign_of_variant(variant: ArrayLike) -> NDArray[np.float64]:
    v = np.asarray(variant)
    if not np.all((v == 1) | (v == 2)):
        raise ValueError(f"variant must be 1 or 2, got {variant!r}")
    return np.where(v == 1, 1.0, -1.0)


def _ok_or_nan(ok: NDArray[np.bool_], *arrays: Array) -> tuple[Array, ...]:
    """NaN where ``ok`` is false (skipped entirely when every position is fine)."""
    if ok.all():
        return arrays
    return tuple(np.where(ok, a, np.nan) for a in arrays)


def pl1_unit(x: ArrayLike, y: ArrayLike) -> tuple[Array, Array, Array, NDArray[np.bool_]]:
    """Pl1 core: ``r1`` and the direction ``(cos α1, sin α1)`` without any trigonometry."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    r1 = np.sqrt(x * x + y * y)
    ok = r1 > 0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        c1, s1 = -x / r1, -y / r1
    return (*_ok_or_nan(ok, r1, c1, s1), ok)


def solve_pl1(x: ArrayLike, y: ArrayLike) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Pl1 — unknown length and angle of one vector.

    Parameters
    ----------
    x, y : array, shape (..., P)
        Sum of the known vectors (length units).

    Returns
    -------
    r1 : array, shape (..., P), length units — ``hypot(x, y)``.
    a1 : array, shape (..., P), rad — ``atan2(-y, -x)``.
    ok : bool array — false where ``r1 == 0`` (direction undefined).
    """
    r1, c1, s1, ok = pl1_unit(x, y)
    return r1, np.arctan2(s1, c1), ok


def pl2_unit(
    x: ArrayLike, y: ArrayLike, c1: ArrayLike, s1: ArrayLike, c2: ArrayLike, s2: ArrayLike
) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Pl2 core: lengths ``r1, r2`` for known directions given as cosines and sines."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    xp = x * c2 + y * s2  # known sum in the frame of vector 2
    yp = -x * s2 + y * c2
    sin_d = np.asarray(s1 * c2 - c1 * s2)  # sin(α1 − α2)
    cos_d = c1 * c2 + s1 * s2
    ok = np.abs(sin_d) > 1e-12
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        r1 = -yp / sin_d
    r2 = -xp - r1 * cos_d
    return (*_ok_or_nan(ok, r1, r2), ok)


def solve_pl2(
    x: ArrayLike, y: ArrayLike, a1: ArrayLike, a2: ArrayLike
) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Pl2 — unknown lengths of two vectors with known directions ``a1, a2`` (rad).

    Lengths come out signed: a negative length places the end point behind the vector's
    origin along its (fixed) direction.  ``ok`` is false where the directions are parallel.
    """
    a1, a2 = np.asarray(a1, dtype=float), np.asarray(a2, dtype=float)
    return pl2_unit(x, y, np.cos(a1), np.sin(a1), np.cos(a2), np.sin(a2))


def pl3_unit(
    x: ArrayLike, y: ArrayLike, c1: ArrayLike, s1: ArrayLike, r2: ArrayLike, *,
    variant: ArrayLike = 1
) -> tuple[Array, Array, Array, NDArray[np.bool_]]:
    """Pl3 core: ``r1`` and the direction ``(cos α2, sin α2)``; vector 1's direction is
    given as ``(c1, s1)``."""
    x, y, r2 = (np.asarray(v, dtype=float) for v in (x, y, r2))
    k = _sign_of_variant(variant)
    xp = x * c1 + y * s1  # known sum in the frame of vector 1
    yp = -x * s1 + y * c1
    r2sq = r2 * r2
    disc = r2sq - yp * yp
    ok = (disc >= -EXISTENCE_RTOL * r2sq) & (r2 != 0)
    dp = np.sqrt(np.maximum(disc, 0.0))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        cphi = -k * dp / r2  # φ = α2 − α1 in the frame of vector 1
        sphi = -yp / r2
    r1 = -xp + k * dp
    c2 = cphi * c1 - sphi * s1
    s2 = sphi * c1 + cphi * s1
    return (*_ok_or_nan(ok, r1, c2, s2), ok)


def solve_pl3(
    x: ArrayLike, y: ArrayLike, a1: ArrayLike, r2: ArrayLike, *, variant: ArrayLike = 1
) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Pl3 — unknown length ``r1`` of a vector with known direction ``a1`` (rad) and
    unknown direction ``a2`` of a vector with known length ``r2``.

    In the frame of vector 1, ``sin φ = −Y'/r2`` with ``φ = α2 − α1``; variant 1 takes
    ``cos φ < 0`` and variant 2 ``cos φ ≥ 0``.  ``ok`` is false where ``|Y'| > |r2|``.
    """
    a1 = np.asarray(a1, dtype=float)
    r1, c2, s2, ok = pl3_unit(x, y, np.cos(a1), np.sin(a1), r2, variant=variant)
    return r1, np.arctan2(s2, c2), ok


def pl4_unit(
    x: ArrayLike, y: ArrayLike, r1: ArrayLike, r2: ArrayLike, *, variant: ArrayLike = 1
) -> tuple[Array, Array, Array, Array, NDArray[np.bool_]]:
    """Pl4 core: directions ``(cos α1, sin α1), (cos α2, sin α2)`` without trigonometry.

    With ``u`` the unit vector of ``p = r1 + r2 = −(x, y)`` and ``v`` the unit normal to
    its left, vector 1 is ``along·u + h·v`` and vector 2 is ``(p − along)·u − h·v``, where
    ``along`` is the projection of vector 1 on ``p`` and ``h = ±sqrt(r1² − along²)``.
    """
    x, y, r1, r2 = (np.asarray(v, dtype=float) for v in (x, y, r1, r2))
    k = _sign_of_variant(variant)
    psq = x * x + y * y
    p = np.sqrt(psq)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        ux, uy = -x / p, -y / p
        along = (r1 * r1 - r2 * r2 + psq) / (2.0 * p)
        h2 = (r1 - along) * (r1 + along)
        scale = np.maximum(r1 * r1, r2 * r2)
        ok = (p > 0) & (h2 >= -EXISTENCE_RTOL * scale) & (r1 != 0) & (r2 != 0)
        h = k * np.sqrt(np.maximum(h2, 0.0))
        rest = p - along
        c1 = (along * ux - h * uy) / r1
        s1 = (along * uy + h * ux) / r1
        c2 = (rest * ux + h * uy) / r2
        s2 = (rest * uy - h * ux) / r2
    return (*_ok_or_nan(ok, c1, s1, c2, s2), ok)


def solve_pl4(
    x: ArrayLike, y: ArrayLike, r1: ArrayLike, r2: ArrayLike, *, variant: ArrayLike = 1
) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Pl4 — unknown directions ``a1, a2`` (rad) of two vectors with known lengths.

    ``r1 + r2`` must equal ``p = −(x, y)``.  With ``A`` the triangle angle opposite
    ``r1`` and ``B`` the one opposite ``r2``, variant 1 is ``α1 = α_p + B,
    α2 = α_p − A`` (vector 1 turned counter-clockwise from ``p``) and variant 2 the mirror
    image.  ``ok`` is false where the triangle inequality fails or ``p = 0``.
    """
    c1, s1, c2, s2, ok = pl4_unit(x, y, r1, r2, variant=variant)
    return np.arctan2(s1, c1), np.arctan2(s2, c2), ok


def track_variant(
    branch1: tuple[Array, ...],
    branch2: tuple[Array, ...],
    ok: NDArray[np.bool_],
    *,
    start: int = 1,
) -> NDArray[np.int8]:
    """Follow a solution branch by continuity from one position to the next.

    ``branch1`` and ``branch2`` hold the same unknowns, as Cartesian coordinates of points
    that the unknowns move (so distances are comparable), for variant 1 and variant 2 at
    every position, each shaped ``(..., P)``.  At each position the labels swap when the
    crossed assignment is closer to the previous position than the straight one; the
    label persists across chain breaks.  Fully vectorized: the swaps are found for all
    positions at once and accumulated with ``cumsum``.

    Returns the variant (1 or 2) to use at every position, shape ``(..., P)``.
    """

    def dist(u: tuple[Array, ...], v: tuple[Array, ...]) -> Array:
        return sum(np.abs(a[..., 1:] - b[..., :-1]) for a, b in zip(u, v, strict=True))

    same = dist(branch1, branch1) + dist(branch2, branch2)
    cross = dist(branch1, branch2) + dist(branch2, branch1)
    both_ok = ok[..., 1:] & ok[..., :-1]
    swap = both_ok & (cross < same)
    flips = np.concatenate([np.zeros((*swap.shape[:-1], 1), dtype=np.int64),
                            np.cumsum(swap, axis=-1)], axis=-1)
    first = start - 1
    return ((first + flips) % 2 + 1).astype(np.int8)
