"""Nelder–Mead local searches from many starts at once, in lockstep.

:func:`nelder_mead` runs SciPy's Nelder–Mead (``scipy.optimize.minimize(method=
"Nelder-Mead")`` with ``bounds``, ``maxfev``, ``xatol``, ``fatol``, ``adaptive``: the same
initial simplex, coefficients, clipping, order of tests, stopping rules and the same
behaviour when the evaluation budget ends inside an iteration) from ``S`` starts side by
side.  Each iteration has at most three stages — the reflection, then the expansion or
one of the contractions, then the shrink — and every stage evaluates the points that all
the starts still running need in **one** call of the objective, a population
``(K, N)``: the synthesis evaluates a population of designs × positions in about the time
of one design (:meth:`~mechloop.synthesis.problem.SynthesisProblem.evaluate`), so ``S``
searches cost about as much as one.  Each start follows exactly the path SciPy's run
from it would follow on the same objective values (``tests/test_simplex.py`` checks the
points, values and evaluation counts against SciPy).

The multi-start of the synthesis (:mod:`mechloop.synthesis.search`) runs its local
searches through it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]

#: SciPy's initial simplex: each coordinate in turn moved by 5 % of its value, or set to
#: this where it is zero.
NONZERO_STEP, ZERO_STEP = 0.05, 0.00025

#: ``status`` of a start: converged (``xatol`` and ``fatol`` both met), evaluation budget
#: spent (``maxfev``), stopped from outside (``stop()`` said so).
CONVERGED, BUDGET, STOPPED = 0, 1, 2


@dataclass(frozen=True)
class SimplexResult:
    """The end of every start's search.

    ``x`` ``(S, N)`` and ``fun`` ``(S,)``: SciPy's ``x`` (the first vertex of the last
    sorted simplex) and ``fun`` (the smallest value of the simplex) — for a start stopped
    from outside, the best point it has evaluated; ``nfev`` ``(S,)``: evaluations of each
    start; ``status`` ``(S,)``: :data:`CONVERGED`, :data:`BUDGET` or :data:`STOPPED`.
    """

    x: Array
    fun: Array
    nfev: NDArray[np.int64]
    status: NDArray[np.int64]


def nelder_mead(func: Callable[[Array], Array], x0: Array, *, lower: Array, upper: Array,
                maxfev: int, xatol: float = 1e-4, fatol: float = 1e-4,
                adaptive: bool = False, stop: Callable[[], bool] | None = None
                ) -> SimplexResult:
    """Minimize ``func`` by Nelder–Mead from every row of ``x0`` at once.

    Parameters
    ----------
    func : the objective of a population: points ``(K, N)`` -> values ``(K,)``; each row
        is one point, its value must not depend on the other rows.
    x0 : starts, shape ``(S, N)`` (or ``(N,)``, one start).
    lower, upper : bounds, shape ``(N,)`` (``-inf``/``inf`` for none); the simplex is
        clipped to them, as SciPy does.
    maxfev : evaluations allowed to each start.
    xatol, fatol : a start has converged when every vertex lies within ``xatol`` of the
        best one in every coordinate and every value within ``fatol`` of the best one.
    adaptive : the dimension-dependent coefficients of Gao and Han (2012), as SciPy's
        ``adaptive``.
    stop : checked before every call of ``func`` after the first; when it returns True
        every start still running ends with the best point it has evaluated
        (status :data:`STOPPED`).  When it is already True before the first call, only
        the starts themselves are evaluated.

    Returns
    -------
    SimplexResult
    """
    x0 = np.atleast_2d(np.asarray(x0, dtype=float))
    lower = np.asarray(lower, dtype=float)
    upper = np.asarray(upper, dtype=float)
    n_starts, n = x0.shape
    if adaptive:
        rho, chi, psi, sigma = 1.0, 1.0 + 2.0 / n, 0.75 - 1.0 / (2.0 * n), 1.0 - 1.0 / n
    else:
        rho, chi, psi, sigma = 1.0, 2.0, 0.5, 0.5
    x0 = np.clip(x0, lower, upper)
    run = _Runs(func, x0, maxfev, stop)
    if run.stopped_before_start():
        return run.result()
    sim = np.repeat(x0[:, None, :], n + 1, axis=1)
    diagonal = sim[:, np.arange(1, n + 1), np.arange(n)]
    sim[:, np.arange(1, n + 1), np.arange(n)] = np.where(
        diagonal != 0, (1 + NONZERO_STEP) * diagonal, ZERO_STEP)
    sim = np.clip(np.where(sim > upper, 2 * upper - sim, sim), lower, upper)
    fsim = np.full((n_starts, n + 1), np.inf)
    # the initial simplex: as many vertices of each start as its budget allows
    allowed = np.minimum(n + 1, maxfev)
    counted = np.arange(n + 1)[None, :] < np.full((n_starts, 1), allowed)
    fsim[counted] = run.evaluate(sim[counted], np.nonzero(counted)[0])
    sim, fsim = _sorted(sim, fsim, np.ones(n_starts, dtype=bool))
    active = run.nfev < maxfev
    run.status[~active] = BUDGET
    while active.any():
        with np.errstate(invalid="ignore"):  # inf - inf: not converged, as in SciPy
            spread = np.max(np.abs(fsim[:, :1] - fsim[:, 1:]), axis=1)
        converged = active & (np.max(np.abs(sim[:, 1:] - sim[:, :1]), axis=(1, 2)) <= xatol) \
            & (spread <= fatol)
        run.status[converged] = CONVERGED
        active &= ~converged
        if not active.any():
            break
        if run.should_stop():
            return run.result(sim, fsim, active)
        going = np.nonzero(active)[0]
        worst = sim[going, -1]
        xbar = np.add.reduce(sim[going, :-1], 1) / n
        xr = np.clip((1 + rho) * xbar - rho * worst, lower, upper)
        fxr = run.evaluate(xr, going)
        f0, f_second, f_worst = fsim[going, 0], fsim[going, -2], fsim[going, -1]
        expand = fxr < f0
        accept = ~expand & (fxr < f_second)
        outside = ~expand & ~accept & (fxr < f_worst)
        inside = ~expand & ~accept & ~outside
        # the second point: expansion, outside or inside contraction
        second = np.where(expand[:, None], (1 + rho * chi) * xbar - rho * chi * worst,
                          np.where(outside[:, None],
                                   (1 + psi * rho) * xbar - psi * rho * worst,
                                   (1 - psi) * xbar + psi * worst))
        second = np.clip(second, lower, upper)
        wants = ~accept & (run.nfev[going] < maxfev)  # else SciPy's run ends here
        if wants.any() and run.should_stop():
            return run.result(sim, fsim, active)
        fsecond = np.full(going.size, np.nan)
        fsecond[wants] = run.evaluate(second[wants], going[wants])
        take_second = wants & ((expand & (fsecond < fxr)) | (outside & (fsecond <= fxr))
                               | (inside & (fsecond < f_worst)))
        take_reflection = accept | (wants & expand & ~(fsecond < fxr))
        shrink = wants & ~expand & ~take_second
        sim[going[take_second], -1] = second[take_second]
        fsim[going[take_second], -1] = fsecond[take_second]
        sim[going[take_reflection], -1] = xr[take_reflection]
        fsim[going[take_reflection], -1] = fxr[take_reflection]
        if shrink.any():
            if run.should_stop():
                return run.result(sim, fsim, active)
            _shrink(run, sim, fsim, going[shrink], sigma, lower, upper, maxfev)
        sim, fsim = _sorted(sim, fsim, active)
        ended = active & (run.nfev >= maxfev)
        run.status[ended] = BUDGET
        active &= ~ended
    return run.result(sim, fsim)


def _shrink(run: _Runs, sim: Array, fsim: Array, rows: NDArray[np.intp], sigma: float,
            lower: Array, upper: Array, maxfev: int) -> None:
    """Shrink the simplices ``rows`` towards their best vertex, in place: SciPy moves
    and evaluates vertex 1, 2, … in turn; where the budget ends after ``m`` of them,
    vertex ``m + 1`` is moved but not evaluated (its old value stays) and the rest stay."""
    n = sim.shape[2]
    best = sim[rows, :1]
    moved = np.clip(best + sigma * (sim[rows, 1:] - best), lower, upper)
    left = maxfev - run.nfev[rows]
    vertex = np.arange(n)[None, :]
    evaluated = vertex < left[:, None]
    placed = vertex <= left[:, None]
    block = sim[rows, 1:]
    block[placed] = moved[placed]
    sim[rows, 1:] = block
    values = fsim[rows, 1:]
    values[evaluated] = run.evaluate(moved[evaluated], np.repeat(rows, evaluated.sum(1)))
    fsim[rows, 1:] = values


def _sorted(sim: Array, fsim: Array, rows: NDArray[np.bool_]) -> tuple[Array, Array]:
    """Each simplex of ``rows`` sorted by value (``np.argsort`` per start, as SciPy)."""
    order = np.argsort(fsim[rows], axis=1)
    sim = sim.copy()
    fsim = fsim.copy()
    sim[rows] = np.take_along_axis(sim[rows], order[:, :, None], axis=1)
    fsim[rows] = np.take_along_axis(fsim[rows], order, axis=1)
    return sim, fsim


class _Runs:
    """The starts' bookkeeping: evaluations per start, the best point each has
    evaluated, its status, and the outside stop."""

    def __init__(self, func: Callable[[Array], Array], x0: Array, maxfev: int,
                 stop: Callable[[], bool] | None) -> None:
        self.func = func
        self.x0 = x0
        self.stop = stop
        n_starts = x0.shape[0]
        self.nfev = np.zeros(n_starts, dtype=np.int64)
        self.status = np.full(n_starts, BUDGET, dtype=np.int64)
        self.best_x = x0.copy()
        self.best_f = np.full(n_starts, np.inf)
        self.calls = 0
        self.maxfev = maxfev

    def evaluate(self, points: Array, starts: NDArray[np.intp]) -> Array:
        """Values of ``points`` ``(K, N)``, the row ``k`` on behalf of start
        ``starts[k]``: one call of the objective."""
        if points.shape[0] == 0:
            return np.empty(0)
        values = np.asarray(self.func(np.array(points, dtype=float)), dtype=float)
        self.calls += 1
        np.add.at(self.nfev, starts, 1)
        # each start's smallest value of this call (the first of equal ones), kept where
        # it is below the start's best so far
        order = np.lexsort((values, starts))
        first = np.ones(order.size, dtype=bool)
        first[1:] = starts[order[1:]] != starts[order[:-1]]
        rows = order[first]
        better = rows[values[rows] < self.best_f[starts[rows]]]
        self.best_f[starts[better]] = values[better]
        self.best_x[starts[better]] = points[better]
        return values

    def should_stop(self) -> bool:
        return self.stop is not None and self.calls > 0 and bool(self.stop())

    def stopped_before_start(self) -> bool:
        """The stop holds before anything was evaluated: evaluate the starts alone."""
        if self.stop is None or not self.stop() or self.maxfev < 1:
            return False
        self.evaluate(self.x0, np.arange(self.x0.shape[0]))
        self.status[:] = STOPPED
        return True

    def result(self, sim: Array | None = None, fsim: Array | None = None,
               stopped: NDArray[np.bool_] | None = None) -> SimplexResult:
        """Each start's end: SciPy's ``x``/``fun`` from its simplex, or for the starts
        ``stopped`` (and when there is no simplex) the best point it has evaluated."""
        x, fun = self.best_x.copy(), self.best_f.copy()
        if sim is not None and fsim is not None:
            done = np.ones(x.shape[0], dtype=bool) if stopped is None else ~stopped
            x[done], fun[done] = sim[done, 0], np.min(fsim[done], axis=1)
            if stopped is not None:
                self.status[stopped] = STOPPED
        return SimplexResult(x=x, fun=fun, nfev=self.nfev.copy(), status=self.status.copy())


__all__ = ["BUDGET", "CONVERGED", "STOPPED", "SimplexResult", "nelder_mead"]
