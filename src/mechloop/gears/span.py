"""The base tangent length (span measurement, «длина общей нормали») of an external spur
gear: the distance ``W_k`` between two parallel planes touching opposite flanks of ``k``
teeth, which lies along the base circle's tangent (ISO 21771, GOST 16532-70):

    W_k = m cos α [π (k − 0.5) + z inv α] + 2 x m sin α,

and the number of teeth ``k`` spanned so that the planes touch the flanks near the middle
of the tooth depth, at the circle of diameter ``d + 2 x m``:

    k = round(z/π · (tan α_x − 2 x tan α/z − inv α) + 0.5),   cos α_x = d_b/(d + 2 x m)

(for ``x = 0`` the textbook ``k = z α/π + 0.5``).  Broadcasts over arrays of gears.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from mechloop.gears.involute import inv


def span_teeth(z: ArrayLike, x: ArrayLike, alpha: ArrayLike) -> np.ndarray:
    """Teeth ``k`` in the span of gears with ``z`` teeth and shift ``x`` (``alpha`` the
    pressure angle, rad); at least 1.  Integer array."""
    z, x = np.asarray(z, float), np.asarray(x, float)
    cos_x = z * np.cos(alpha) / (z + 2.0 * x)       # d_b/(d + 2 x m), the module cancels
    alpha_x = np.arccos(np.clip(cos_x, -1.0, 1.0))
    k = z / np.pi * (np.tan(alpha_x) - 2.0 * x * np.tan(alpha) / z - inv(alpha)) + 0.5
    return np.maximum(np.rint(k), 1).astype(int)


def base_tangent_length(m_n: ArrayLike, z: ArrayLike, x: ArrayLike, alpha: ArrayLike,
                        k: ArrayLike) -> np.ndarray:
    """``W_k`` (unit of ``m_n``) over ``k`` teeth of gears with ``z`` teeth and shift
    ``x``.

    >>> round(float(base_tangent_length(1.0, 20, 0.0, np.radians(20), 3)), 4)
    7.6604
    """
    m_n, z, x, k = (np.asarray(v, float) for v in (m_n, z, x, k))
    return m_n * np.cos(alpha) * (np.pi * (k - 0.5) + z * inv(alpha)) \
        + 2.0 * x * m_n * np.sin(alpha)
