"""Profile shifts and centre distance of an external pair, both ways (ISO 21771).

The sum of the shifts fixes the working pressure angle (no backlash):

    inv α_w = inv α + 2 (x_1 + x_2) tan α / (z_1 + z_2),

and the centre distance ``a = a_0 cos α / cos α_w`` with ``a_0 = m (z_1 + z_2)/2``.  Given
``a``, ``cos α_w = a_0 cos α / a`` and the sum of the shifts follows from the first line.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from mechloop.errors import HintedError
from mechloop.gears.involute import inv, inv_inverse


def working_pressure_angle(z_sum: ArrayLike, x_sum: ArrayLike, alpha: ArrayLike
                           ) -> np.ndarray:
    """``α_w`` (rad) of an external pair with ``z_1 + z_2`` teeth and shifts summing to
    ``x_1 + x_2``; ``alpha`` the pressure angle of the basic rack (rad).  Broadcasts."""
    z_sum, x_sum, alpha = (np.asarray(v, float) for v in (z_sum, x_sum, alpha))
    value = inv(alpha) + 2.0 * x_sum * np.tan(alpha) / z_sum
    if np.any(value <= 0):
        raise HintedError("the shifts are so negative that the working pressure angle "
                          "would be zero or less",
                          "make the sum of the shifts x1 + x2 larger")
    return inv_inverse(value)


def centre_distance_from_shifts(m_n: ArrayLike, z1: ArrayLike, z2: ArrayLike,
                                x1: ArrayLike, x2: ArrayLike, alpha: ArrayLike
                                ) -> tuple[np.ndarray, np.ndarray]:
    """``(a, α_w)``: the centre distance (unit of ``m_n``) and working pressure angle (rad)
    of an external pair with shifts ``x1, x2``, without backlash.  Broadcasts."""
    z_sum = np.asarray(z1, float) + np.asarray(z2, float)
    alpha_w = working_pressure_angle(z_sum, np.asarray(x1, float) + np.asarray(x2, float),
                                     alpha)
    a0 = np.asarray(m_n, float) * z_sum / 2.0
    return a0 * np.cos(alpha) / np.cos(alpha_w), alpha_w


def shift_sum_from_centre_distance(m_n: ArrayLike, z1: ArrayLike, z2: ArrayLike,
                                   a: ArrayLike, alpha: ArrayLike
                                   ) -> tuple[np.ndarray, np.ndarray]:
    """``(x_1 + x_2, α_w)``: the sum of the shifts and the working pressure angle (rad) that
    make an external pair mesh without backlash at the centre distance ``a``."""
    z_sum = np.asarray(z1, float) + np.asarray(z2, float)
    a0 = np.asarray(m_n, float) * z_sum / 2.0
    cos_w = a0 * np.cos(alpha) / np.asarray(a, float)
    if np.any(cos_w >= 1.0) or np.any(cos_w <= 0.0):
        raise HintedError("the centre distance is too small for these gears: no working "
                          "pressure angle fits it",
                          f"take a centre distance above a0·cos α = "
                          f"{float(np.min(a0 * np.cos(alpha))):.6g}")
    alpha_w = np.arccos(cos_w)
    x_sum = z_sum * (inv(alpha_w) - inv(alpha)) / (2.0 * np.tan(alpha))
    return x_sum, alpha_w
