"""The distance from a target to the traced curve itself, not to its samples.

Without timing, a target's deviation is its distance to the nearest point of the curve
the tracing point describes.  The search measures it to the polyline through the
sampled positions (:func:`~mechloop.synthesis.deviations.nearest_on_curve`), which can
be shorter or longer than the distance to the curve by the chord's sag.  Here the
nearest point is refined on the continuous curve: around the nearest place on the
polyline (parameter ``s``), the input (argument 1) ``x`` in
``[x(s - 1), x(s + 1)]`` that minimizes ``f(x) = |P(x) - target|²`` is found by a
safeguarded Newton iteration on ``f'`` (bisection where Newton leaves the bracket), with
``P(x)`` solved exactly at every trial input — all designs and targets in one call of
:func:`~mechloop.solve.designs.solve_designs_at` per iteration, the derivatives of
``P`` by central differences.  An argument that turns fully (an angle spanning 360°)
lets the bracket cross its ends (the motion repeats there).

The refined distance is never above the distance to the nearest sampled position
(a sample is a point of the curve too): the least of both is returned.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from mechloop.solve.designs import solve_designs_at
from mechloop.synthesis import deviations as dv

if TYPE_CHECKING:
    from mechloop.synthesis.problem import SynthesisProblem

Array = NDArray[np.float64]

#: Newton iterations (each one solve of ``3 K`` extra columns per design).
ITERATIONS = 30
#: Central-difference step, as a share of the first bracket (two positions).
_STEP = 1e-4


def curve_distance(problem: SynthesisProblem, designs: Array, z: NDArray[np.complex128],
                   targets: NDArray[np.complex128]) -> Array:
    """Distance (m) from each target ``(K,)`` (or ``(D, K)``, a row per design) to the
    continuous curve traced by the
    tracing point of each design ``(D, V)``, ``(D, K)``; ``z`` ``(D, P)`` is the point at
    the positions.  Without an argument 1 that runs one way over the positions, the
    distance to the polyline is returned (nothing to refine over)."""
    targets = np.broadcast_to(targets, (z.shape[0], targets.shape[-1]))
    polyline, s, _ = dv.nearest_on_curve(z, targets)
    args = problem.model.arguments
    if 1 not in args:
        return polyline
    from mechloop.solve.inputs import model_arguments, model_time

    values = model_arguments(problem.model, model_time(problem.model), strict=False)[1].value
    steps = np.diff(values)
    if not ((steps > 0).all() or (steps < 0).all()):
        return polyline
    n = values.size - 1
    from mechloop.model.check import argument_kind

    turns = argument_kind(problem.model, 1) == "angle" and \
        abs(values[-1] - values[0]) >= 2 * np.pi * (1 - 1e-9)
    index = np.arange(n + 1, dtype=float)

    def input_at(par: Array) -> Array:
        if turns:  # extrapolate linearly past the ends: the motion repeats there
            step = (values[-1] - values[0]) / n
            inside = np.interp(np.clip(par, 0, n), index, values)
            return inside + np.where(par < 0, par, 0) * step + \
                np.where(par > n, par - n, 0) * step
        return np.interp(np.clip(par, 0, n), index, values)

    lo = input_at(s - 1.0)
    hi = input_at(s + 1.0)
    lo, hi = np.minimum(lo, hi), np.maximum(lo, hi)
    overrides = problem.variables.overrides(designs)
    # the nearest sample: a point of the curve, the bound of the result
    vertex = np.abs(z[:, None, :] - targets[:, :, None])
    sampled = np.nan_to_num(vertex, nan=np.inf).min(axis=-1)
    x = np.clip(input_at(s), lo, hi)
    point = problem.point
    k = targets.shape[-1]
    h = _STEP * np.maximum(hi - lo, 1e-300)  # fixed: the bracket shrinks to nothing
    for _ in range(ITERATIONS):
        trial = np.concatenate([x - h, x, x + h], axis=1)            # (D, 3K)
        _, at = solve_designs_at(problem.model, overrides, trial, derivatives=False)
        p = problem.place(at, designs, point)
        before, here, after = p[:, :k], p[:, k:2 * k], p[:, 2 * k:]
        d1 = (after - before) / (2 * h)
        d2 = (after - 2 * here + before) / (h * h)
        gap = here - targets
        g = 2 * np.real(np.conj(gap) * d1)                     # f'(x)
        curv = 2 * (np.abs(d1) ** 2 + np.real(np.conj(gap) * d2))  # f''(x)
        ok = np.isfinite(g) & np.isfinite(curv)
        lo = np.where(ok & (g < 0), x, lo)  # f falls at x: the minimum lies above
        hi = np.where(ok & (g > 0), x, hi)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            newton = x - g / curv
        inside = ok & (curv > 0) & (newton > lo) & (newton < hi)
        moved = np.where(inside, newton, 0.5 * (lo + hi))
        done = np.all(np.abs(moved - x) <= 1e-14 * np.maximum(np.abs(x), 1.0))
        x = moved
        if done:
            break
    _, at = solve_designs_at(problem.model, overrides, x, derivatives=False)
    refined = np.abs(problem.place(at, designs, point) - targets)
    refined = np.where(np.isfinite(refined), refined, np.inf)
    return np.minimum(refined, sampled)
