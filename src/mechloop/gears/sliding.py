"""Specific sliding of an external pair over its line of action, and the split of a sum
of shifts that balances it.

A contact point at ``g`` from N_1 along the line of action (``0 < g < N_1N_2``) has the
radii of curvature ``ρ_1 = g`` and ``ρ_2 = N_1N_2 − g`` on the two involutes; the contact
point runs along profile ``i`` at ``ω_i ρ_i``, so the specific sliding is

    ϑ_1 = 1 − ρ_2/(u ρ_1),   ϑ_2 = 1 − u ρ_1/ρ_2,   u = z_2/z_1.

Both are most negative at the ends of the active line on the own root side: ϑ_1 at A
(where the wheel's tip meets the pinion), ϑ_2 at E (the pinion's tip).  Balanced shifts
make them equal: for a given sum ``x_1 + x_2`` the pinion's shift ``x_1`` is found by
Brent's method on ``ϑ_1(A) − ϑ_2(E)``.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike
from scipy.optimize import brentq

from mechloop.errors import HintedError
from mechloop.gears.pair import GearPair


def specific_sliding(pair: GearPair, g: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """``(ϑ_1, ϑ_2)`` at the points ``g`` of the line of action measured from N_1 (unit of
    the module; strictly between N_1 and N_2)."""
    g = np.asarray(g, float)
    rho1, rho2 = g, pair.line_of_action - g
    if np.any(rho1 <= 0) or np.any(rho2 <= 0):
        raise HintedError("specific sliding is infinite at N_1 and N_2",
                          "take points strictly between the base circles' tangent points")
    return 1.0 - rho2 / (pair.u * rho1), 1.0 - pair.u * rho1 / rho2


def extreme_sliding(pair: GearPair) -> tuple[float, float]:
    """``(ϑ_1(A), ϑ_2(E))``: the specific sliding of each gear at its lowest contact point
    (−inf when that point falls on or beyond its base circle's tangent point)."""
    g_a, g_e = pair.active_line
    length = pair.line_of_action
    t1 = 1.0 - (length - g_a) / (pair.u * g_a) if g_a > 0 else -np.inf
    t2 = 1.0 - pair.u * g_e / (length - g_e) if g_e < length else -np.inf
    return float(t1), float(t2)


def balanced_shift(pair: GearPair, x_sum: float, *,
                   bounds: tuple[float, float] | None = None) -> float:
    """The pinion's shift ``x_1`` for which ``ϑ_1(A) = ϑ_2(E)`` when the shifts of the
    pair (module, teeth, rack of ``pair``) sum to ``x_sum`` (the wheel has
    ``x_sum − x_1``).  ``bounds`` of ``x_1`` default to ``(−1, x_sum + 1)``.

    The difference ``ϑ_1(A) − ϑ_2(E)`` rises with ``x_1`` (a larger pinion shift moves A
    away from N_1 and E towards N_2); a scan of the bounds brackets its root for Brent."""
    lo, hi = bounds if bounds is not None else (-1.0, x_sum + 1.0)

    def f(x1: float) -> float:
        t1, t2 = extreme_sliding(replace(pair, x=(float(x1), float(x_sum - x1))))
        return float(np.clip(t1 - t2, -1e12, 1e12))

    grid = np.linspace(lo, hi, 81)
    diff = np.array([f(x1) for x1 in grid])  # 81 closed-form evaluations, once per design
    change = np.flatnonzero(np.sign(diff[:-1]) * np.sign(diff[1:]) <= 0)
    if change.size == 0:
        raise HintedError(f"no pinion shift between {lo:.4g} and {hi:.4g} balances the "
                          "specific sliding for this centre distance",
                          "change the centre distance or give the shifts")
    i = int(change[0])
    return float(brentq(f, grid[i], grid[i + 1], xtol=1e-12, rtol=1e-14))
