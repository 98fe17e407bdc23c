"""The rest of a spatial module's unknowns once its one scalar root is known.

Every helper takes the vector ``W`` that the unknown-carrying vector(s) must equal, as
three arrays ``(wx, wy, wz)`` of any common shape, and returns the unknown parameters and
an ``ok`` mask (false where the parameters are undefined: NaN there).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from mechloop.spatial.vector import parameters

Array = NDArray[np.float64]
Vec = tuple[Array, Array, Array]

#: Below this a denominator (a sine, a determinant of unit vectors) counts as zero.
DEGENERATE = 1e-12


def masked(ok: NDArray[np.bool_], *arrays: Array) -> tuple[Array, ...]:
    """NaN where ``ok`` is false."""
    if ok.all():
        return arrays
    return tuple(np.where(ok, a, np.nan) for a in arrays)


def dot(a: Vec, b: Vec) -> Array:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a: Vec, b: Vec) -> Vec:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def r_alpha_in_plane(w: Vec, beta: Array) -> tuple[Array, Array, NDArray[np.bool_]]:
    """``r ≥ 0`` and ``α`` (full turn) of the vector ``W`` that lies in the vertical plane
    of rotation ``β`` (Pl1 in that plane)."""
    a = w[0] * np.cos(beta) + w[2] * np.sin(beta)
    r = np.hypot(a, w[1])
    ok = r > 0
    return (*masked(ok, r, np.arctan2(w[1], a)), ok)


def r_beta_on_cone(w: Vec, alpha: Array) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Signed ``r`` and ``β`` (full turn) of ``W = r u(α, β)`` for a known elevation ``α``
    (``W`` lies on the double cone of half-angle ``π/2 − α`` about Y).  Undefined for a
    vertical (``cos α = 0``) or horizontal (``sin α = 0``: the sign of ``r`` and ``β + π``
    give the same vector) direction."""
    sa, ca = np.sin(alpha), np.cos(alpha)
    norm = np.sqrt(dot(w, w))
    r = np.where(w[1] * sa >= 0, norm, -norm)
    sgn = np.where(r * ca >= 0, 1.0, -1.0)
    beta = np.arctan2(sgn * w[2], sgn * w[0])
    ok = (np.abs(ca) > DEGENERATE) & (np.abs(sa) > DEGENERATE) & (norm > 0)
    return (*masked(ok, r, beta), ok)


def alpha_beta_of(w: Vec, r: Array, *, convention: int) -> tuple[Array, Array, NDArray[np.bool_]]:
    """``α, β`` (in ``convention``) of ``W = r u(α, β)`` for a known, nonzero ``r``."""
    sgn = np.where(r >= 0, 1.0, -1.0)
    _, alpha, beta, ok = parameters(sgn * w[0], sgn * w[1], sgn * w[2], convention=convention)
    ok = ok & (r != 0)
    return (*masked(ok, alpha, beta), ok)


def two_lengths(w: Vec, ui: Vec, uj: Vec) -> tuple[Array, Array, NDArray[np.bool_]]:
    """Signed ``r_i, r_j`` with ``r_i u_i + r_j u_j = W`` (``W`` in the plane of the unit
    vectors ``u_i, u_j``); undefined where they are parallel."""
    n = cross(ui, uj)
    nn = dot(n, n)
    ok = nn > DEGENERATE**2
    den = np.where(ok, nn, 1.0)
    ri = dot(cross(w, uj), n) / den
    rj = -dot(cross(w, ui), n) / den
    return (*masked(ok, ri, rj), ok)
