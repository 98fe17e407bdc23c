"""The choice of tooth numbers of a planetary train for a target ratio.

Every combination of the free tooth numbers in ``[teeth_min, teeth_max]`` is tried at once
(a NumPy broadcast over a grid: ``z_a × z_g`` for the simple scheme, ``z_a × z_g × z_f``
for the two-row ones); the last central gear follows from coaxiality.  A design is kept
when the ratio is within the tolerance, the planets assemble equally spaced and clear
their neighbours, and every internal mesh has at least ``ring_difference_min`` teeth
between ring and planet.  The designs are ranked by the ratio's error, then by size (the
outer diameter in modules: the largest ring, or the planets' outer reach), then by the
total number of teeth.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from mechloop.errors import HintedError
from mechloop.gears.planetary import (
    PlanetaryTrain,
    Scheme,
    assembles,
    member_ratio,
    neighbour_margin,
    willis_ratio,
)
from mechloop.gears.wolfrom import WolfromTrain, wolfrom_ratio

#: Most grid points tried in one choice (about 1.7 M: teeth 17 to 136 in a two-row scheme).
MAX_GRID = 2_000_000


@dataclass(frozen=True)
class Choice:
    """Designs found, best first: tooth numbers (arrays, shape (N,)), their ratio ``i_ah``,
    relative error, outer diameter (in modules) and neighbour clearance (in modules)."""

    scheme: Scheme
    k: int
    target: float
    z_a: np.ndarray
    z_g: np.ndarray
    z_f: np.ndarray
    z_b: np.ndarray
    ratio: np.ndarray
    error: np.ndarray
    size: np.ndarray
    margin: np.ndarray
    tried: int
    fixed: str = "b"
    driver: str = "a"

    def __len__(self) -> int:
        return int(self.z_a.size)

    @property
    def scheme_name(self) -> str:
        return self.scheme.name

    def train(self, i: int = 0, m_n: float = 1.0, ha: float = 1.0) -> PlanetaryTrain:
        """Design ``i`` (0: the best) as a :class:`PlanetaryTrain`."""
        return PlanetaryTrain(self.scheme, int(self.z_a[i]), int(self.z_g[i]),
                              int(self.z_f[i]), int(self.z_b[i]), self.k, m_n, ha,
                              self.fixed, self.driver)


def choose_teeth(scheme: Scheme, target: float, k: int, *, teeth_min: int = 17,
                 teeth_max: int = 120, ring_difference_min: int = 8,
                 tolerance: float = 0.01, ha: float = 1.0, fixed: str = "b",
                 driver: str = "a") -> Choice:
    """All designs of ``scheme`` with ``k`` planets whose ratio (``i_ah`` by default;
    ``ω_driver/ω_output`` with ``fixed`` held) is within ``tolerance`` (relative) of
    ``target``, best first (see the module's docstring)."""
    if teeth_max < teeth_min:
        raise HintedError(f"teeth_max {teeth_max} is below teeth_min {teeth_min}",
                          "raise teeth_max")
    span = np.arange(teeth_min, teeth_max + 1, dtype=np.int64)
    n = span.size
    if n ** (3 if scheme.double else 2) > MAX_GRID:
        raise HintedError(f"{n ** (3 if scheme.double else 2):,} combinations of teeth "
                          f"{teeth_min} to {teeth_max} are too many to try",
                          "narrow teeth_min … teeth_max (120 values at most for a two-row "
                          "scheme)")
    if scheme.double:
        z_a, z_g, z_f = np.meshgrid(span, span, span, indexing="ij")
    else:
        z_a, z_g = np.meshgrid(span, span, indexing="ij")
        z_f = z_g
    z_a, z_g, z_f = (v.ravel() for v in (z_a, z_g, z_f))
    centre = z_a + scheme.sigma_a * z_g           # 2 a_w / m, row a–g
    z_b = centre + z_f if scheme.sigma_b == -1 else centre - z_f  # coaxial: z_b + σ_b z_f
    ok = (centre > 0) & (z_b >= teeth_min) & (z_b <= teeth_max)
    if scheme.sigma_a == -1:
        ok &= z_a - z_g >= ring_difference_min
    if scheme.sigma_b == -1:
        ok &= z_b - z_f >= ring_difference_min
    ratio = np.where(ok, member_ratio(willis_ratio(scheme, z_a, z_g, z_f, np.maximum(z_b, 1)),
                                      fixed, driver), np.nan)
    error = np.abs(ratio - target) / abs(target) if target != 0 else np.abs(ratio)
    ok &= np.where(ok, error, np.inf) <= tolerance
    ok &= assembles(scheme, z_a, z_g, z_f, np.maximum(z_b, 1), k)
    margin = neighbour_margin(scheme, z_a, z_g, z_f, k, ha)
    ok &= margin > 0
    keep = np.flatnonzero(ok)
    z_a, z_g, z_f, z_b = z_a[keep], z_g[keep], z_f[keep], z_b[keep]
    reach = np.abs(z_a + scheme.sigma_a * z_g) + np.maximum(z_g, z_f) + 2 * ha
    rings = np.maximum(np.where(scheme.sigma_a == -1, z_a, 0),
                       np.where(scheme.sigma_b == -1, z_b, 0))
    size = np.maximum(reach, rings).astype(float)
    err = error[keep]
    order = np.lexsort((z_a + z_g + z_f + z_b, size, np.round(err, 12)))
    return Choice(scheme, int(k), float(target), z_a[order], z_g[order], z_f[order],
                  z_b[order], ratio[keep][order], err[order], size[order],
                  margin[keep][order], int(n ** (3 if scheme.double else 2)), fixed, driver)


@dataclass(frozen=True)
class WolfromChoice:
    """Wolfrom designs found, best first (see :func:`choose_wolfrom_teeth`): tooth numbers
    ``z_a, z_g, z_f, z_b, z_e`` (arrays, shape (N,)), their ratio ``i_ae``, relative
    error, outer diameter (the larger ring, in modules) and neighbour clearance (in
    modules)."""

    k: int
    target: float
    z_a: np.ndarray
    z_g: np.ndarray
    z_f: np.ndarray
    z_b: np.ndarray
    z_e: np.ndarray
    ratio: np.ndarray
    error: np.ndarray
    size: np.ndarray
    margin: np.ndarray
    tried: int

    def __len__(self) -> int:
        return int(self.z_a.size)

    scheme_name = "wolfrom"

    def train(self, i: int = 0, m_n: float = 1.0, ha: float = 1.0) -> WolfromTrain:
        """Design ``i`` (0: the best) as a :class:`~mechloop.gears.wolfrom.WolfromTrain`."""
        return WolfromTrain(int(self.z_a[i]), int(self.z_g[i]), int(self.z_f[i]),
                            int(self.z_b[i]), int(self.z_e[i]), self.k, m_n, ha)


def choose_wolfrom_teeth(target: float, k: int, *, teeth_min: int = 17,
                         teeth_max: int = 120, tolerance: float = 0.01, ha: float = 1.0
                         ) -> WolfromChoice:
    """All Wolfrom designs with ``k`` planets whose ratio ``i_ae`` is within
    ``tolerance`` (relative) of ``target``: every ``z_a × z_g × z_f`` in
    ``[teeth_min, teeth_max]`` at once, the rings from coaxiality (``z_b = z_a + 2 z_g``,
    ``z_e = z_a + z_g + z_f``), kept when both rings fit ``teeth_max``, both assembly
    conditions hold and the planets clear each other; ranked by the ratio's error, then
    the larger ring, then the total number of teeth.  (The ring–planet differences are
    ``z_a + z_g`` ≥ 2 ``teeth_min``: no internal-mesh interference limit binds.)"""
    if teeth_max < teeth_min:
        raise HintedError(f"teeth_max {teeth_max} is below teeth_min {teeth_min}",
                          "raise teeth_max")
    span = np.arange(teeth_min, teeth_max + 1, dtype=np.int64)
    n = span.size
    if n ** 3 > MAX_GRID:
        raise HintedError(f"{n ** 3:,} combinations of teeth {teeth_min} to {teeth_max} "
                          "are too many to try",
                          "narrow teeth_min … teeth_max (120 values at most)")
    z_a, z_g, z_f = (v.ravel() for v in np.meshgrid(span, span, span, indexing="ij"))
    z_b, z_e = z_a + 2 * z_g, z_a + z_g + z_f
    ok = (z_b <= teeth_max) & (z_e <= teeth_max) & (z_b * z_f != z_g * z_e)
    ratio = np.where(ok, wolfrom_ratio(z_a, z_g, z_f, z_b, z_e), np.nan)
    error = np.abs(ratio - target) / abs(target) if target != 0 else np.abs(ratio)
    ok &= np.where(ok, error, np.inf) <= tolerance
    ok &= (z_a + z_b) % k == 0
    ok &= (z_e * z_g - z_b * z_f) % (k * np.gcd(z_g, z_f)) == 0
    margin = (z_a + z_g) * np.sin(np.pi / k) - (np.maximum(z_g, z_f) + 2.0 * ha)
    ok &= margin > 0
    keep = np.flatnonzero(ok)
    z_a, z_g, z_f, z_b, z_e = (v[keep] for v in (z_a, z_g, z_f, z_b, z_e))
    size = (np.maximum(z_b, z_e) + 2.0 * ha).astype(float)   # tip circle of the larger ring
    err = error[keep]
    order = np.lexsort((z_a + z_g + z_f + z_b + z_e, size, np.round(err, 12)))
    return WolfromChoice(int(k), float(target), z_a[order], z_g[order], z_f[order],
                         z_b[order], z_e[order], ratio[keep][order], err[order],
                         size[order], margin[keep][order], int(n ** 3))
