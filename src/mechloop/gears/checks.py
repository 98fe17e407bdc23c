"""Checks of a generated external gear: undercut, pointed tooth, interference in mesh.

The gear is cut by the basic rack (ISO 53 profile A by default): addendum of the tool
``h_a0 = (h_a* + c*) m`` with a tip radius ``ρ_a0 = ρ* m``.  The tool's straight flank
ends ``h_FfP0 = (h_a* + c* − ρ*(1 − sin α)) m`` below its datum line; that end generates
the start of the involute (the form circle).  All functions broadcast over arrays.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike


def straight_flank_height(ha: ArrayLike, c: ArrayLike, rho: ArrayLike, alpha: ArrayLike
                          ) -> np.ndarray:
    """``h_FfP0*``: depth (in modules) of the end of the tool's straight flank below its
    datum line, ``h_a* + c* − ρ*(1 − sin α)`` (1.0 for ISO 53 profile A at 20°)."""
    return (np.asarray(ha, float) + np.asarray(c, float)
            - np.asarray(rho, float) * (1.0 - np.sin(alpha)))


def minimum_shift(z: ArrayLike, ha: ArrayLike, c: ArrayLike, rho: ArrayLike,
                  alpha: ArrayLike) -> np.ndarray:
    """The smallest shift coefficient without undercut, exactly:
    ``x_min = h_FfP0* − z sin²α / 2`` (the end of the tool's straight flank reaches the
    interference point N of the generating mesh).  With ``h_FfP0* = h_a*`` this is the
    textbook ``x_min = h_a* (z_min − z)/z_min``, ``z_min = 2 h_a*/sin²α``."""
    return straight_flank_height(ha, c, rho, alpha) - np.asarray(z, float) \
        * np.sin(alpha) ** 2 / 2.0


def form_diameter(m_n: ArrayLike, z: ArrayLike, x: ArrayLike, ha: ArrayLike, c: ArrayLike,
                  rho: ArrayLike, alpha: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """``(d_Ff, undercut)``: the diameter where the generated involute starts (the tool's
    straight flank end meets it on the generating line of action) and whether the gear is
    undercut (that point would lie beyond N, inside the involute's reach)."""
    m_n, z, x = (np.asarray(v, float) for v in (m_n, z, x))
    r = m_n * z / 2.0
    r_b = r * np.cos(alpha)
    along = r * np.sin(alpha) - (straight_flank_height(ha, c, rho, alpha) - x) * m_n \
        / np.sin(alpha)
    undercut = along < 0
    return 2.0 * np.hypot(r_b, np.where(undercut, 0.0, along)), undercut


def lowest_contact_diameters(a: float, alpha_w: float, d_b: np.ndarray, d_a: np.ndarray
                             ) -> tuple[np.ndarray, np.ndarray]:
    """``(d_Nf, beyond)`` for both gears of an external pair: the diameter of the lowest
    point of contact on each gear's flank (where the mate's tip circle crosses the line of
    action), and whether that point falls beyond the interference point N (the mate's tip
    would reach inside the base circle: interference whatever the fillet)."""
    r_b, r_a = d_b / 2.0, d_a / 2.0
    length = a * np.sin(alpha_w)                       # N1 N2
    reach = np.sqrt(np.maximum(r_a ** 2 - r_b ** 2, 0.0))  # from N_i to the tip crossing
    from_own = length - reach[::-1]                    # own N to the mate's tip crossing
    beyond = from_own < 0
    return 2.0 * np.hypot(r_b, np.maximum(from_own, 0.0)), beyond


@dataclass(frozen=True)
class Check:
    """One check of a gear pair: its name, the gear (1, 2 or None for the pair), the
    value, the limit, whether it passes and a sentence saying so."""

    name: str
    gear: int | None
    value: float
    limit: float
    ok: bool
    text: str
