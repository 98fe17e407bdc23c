"""The spatial vector: length ``r``, elevation ``α`` above the XZ plane, rotation ``β``
about the Y axis (seed 000 sec. 1.1, fig. 1.2 b; DESIGN.md §1)::

    r (cos α cos β, sin α, cos α sin β)

The inverse (components → ``r, α, β``) is unique only once a parameter-range convention
is chosen; seed 000 sec. 1.1 gives two, both with ``r ≥ 0``:

* **convention 1** — ``α`` a full turn ``(−π, π]``, ``β`` a half turn ``(−π/2, π/2]``.
  The vector lies in the vertical plane through the horizontal direction
  ``(cos β, 0, sin β)`` and ``α`` is its planar angle in that plane; ``β = 0`` is the
  planar XY contour with ``α`` its planar angle (how a planar model is written as
  spatial).
* **convention 2** — ``β`` a full turn ``(−π, π]``, ``α`` a half turn ``[−π/2, π/2]``:
  ordinary azimuth/elevation.

(The seed also allows the shifted ranges ``[0, 2π)`` / ``[0, π]``; they are the same
conventions with the angles moved by a turn and are not offered separately.)
A vertical vector (``cos α = 0``) has no defined ``β``: it is returned as ``β = 0``.
All functions broadcast over arrays of any shape ``(..., P)``; angles in radians.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

Array = NDArray[np.float64]

CONVENTIONS = (1, 2)


def unit(alpha: ArrayLike, beta: ArrayLike) -> tuple[Array, Array, Array]:
    """Components ``(cos α cos β, sin α, cos α sin β)`` of the unit vector, each shape
    of the broadcast of ``alpha`` and ``beta``."""
    alpha = np.asarray(alpha, dtype=float)
    beta = np.asarray(beta, dtype=float)
    ca = np.cos(alpha)
    return ca * np.cos(beta), np.sin(alpha) * np.ones_like(beta), ca * np.sin(beta)


def components(r: ArrayLike, alpha: ArrayLike, beta: ArrayLike) -> tuple[Array, Array, Array]:
    """Components ``(x, y, z)`` of the vector ``r (cos α cos β, sin α, cos α sin β)``."""
    r = np.asarray(r, dtype=float)
    ux, uy, uz = unit(alpha, beta)
    return r * ux, r * uy, r * uz


def parameters(
    x: ArrayLike, y: ArrayLike, z: ArrayLike, *, convention: int = 1
) -> tuple[Array, Array, Array, NDArray[np.bool_]]:
    """Inverse of :func:`components`: ``r ≥ 0, α, β`` in the chosen ``convention``.

    Returns
    -------
    r, alpha, beta : arrays, shape of the broadcast inputs (length units, rad, rad).
    ok : bool array — false where the vector is zero (its direction is undefined); there
        all three are NaN.
    """
    if convention not in CONVENTIONS:
        raise ValueError(f"convention must be 1 or 2, got {convention!r}")
    x, y, z = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (x, y, z)))
    h = np.hypot(x, z)
    r = np.hypot(h, y)
    beta = np.arctan2(z, x)  # (−π, π]; 0 for a vertical vector
    if convention == 2:
        alpha = np.arctan2(y, h)
    else:
        back = (beta > np.pi / 2) | (beta <= -np.pi / 2)
        beta = np.where(back, np.where(beta > 0, beta - np.pi, beta + np.pi), beta)
        horizontal = x * np.cos(beta) + z * np.sin(beta)  # signed, = r cos α
        alpha = np.arctan2(y, horizontal)
    ok = r > 0
    if not ok.all():
        r, alpha, beta = (np.where(ok, v, np.nan) for v in (r, alpha, beta))
    return r, alpha, beta, ok


def in_convention(alpha: ArrayLike, beta: ArrayLike, *, convention: int = 1) -> tuple[
    Array, Array
]:
    """The same direction's angles moved into the ranges of ``convention`` (rad)."""
    x, y, z = unit(alpha, beta)
    _, a, b, _ = parameters(x, y, z, convention=convention)
    return a, b
