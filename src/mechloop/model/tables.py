"""Sparse tables over calculation positions, filled by KDAM's rules (seed 000, App. A 1.4).

Before the first given position the first value holds, between two given positions the
values are interpolated linearly, after the last given position the last value holds.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
from numpy.typing import NDArray


def fill_table(
    table: Mapping[int, float] | Sequence[float], n_positions: int
) -> NDArray[np.float64]:
    """Values at every position ``0..N`` from a sparse ``{position: value}`` table.

    Parameters
    ----------
    table : mapping position -> value, or a sequence with one value per position.
    n_positions : N, the last position number; the result has N + 1 values.

    Returns
    -------
    array, shape (N + 1,)

    Examples
    --------
    KDAM's worked example (12 positions, values given at 3, 6 and 10):

    >>> fill_table({3: 0.12, 6: 0.26, 10: 0.18}, 12).round(4).tolist()
    [0.12, 0.12, 0.12, 0.12, 0.1667, 0.2133, 0.26, 0.24, 0.22, 0.2, 0.18, 0.18, 0.18]
    """
    k = np.arange(n_positions + 1, dtype=float)
    if isinstance(table, Mapping):
        items = sorted((int(p), float(v)) for p, v in table.items())
        xs = np.array([p for p, _ in items], dtype=float)
        ys = np.array([v for _, v in items], dtype=float)
        return np.interp(k, xs, ys)  # np.interp holds the end values outside: KDAM's rules
    values = np.asarray(table, dtype=float)
    if values.shape != k.shape:
        raise ValueError(f"table has {values.size} values, expected {k.size}")
    return values
