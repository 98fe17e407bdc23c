"""The lockstep Nelder–Mead (mechloop.synthesis.simplex) against SciPy's own, start by
start: the same points, values and evaluation counts, with the budget ending anywhere
inside an iteration, ties, infinite values, bounds and the adaptive coefficients; the
outside stop; and one call of the objective per stage for all the starts."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import minimize

from mechloop.synthesis.simplex import BUDGET, CONVERGED, STOPPED, nelder_mead


def _rosenbrock(points: np.ndarray) -> np.ndarray:
    """Rows independent: a shifted Rosenbrock valley."""
    p = 3.0 * points - 1.0
    return np.sum(100.0 * (p[:, 1:] - p[:, :-1] ** 2) ** 2 + (1.0 - p[:, :-1]) ** 2, axis=1)


def _terraced(points: np.ndarray) -> np.ndarray:
    """Plateaus (ties between vertices, shrinks) and an infinite region."""
    values = np.round(8.0 * np.sum((points - 0.3) ** 2, axis=1)) / 8.0
    return np.where(points[:, 0] > 0.9, np.inf, values)


def _scipy(func, x0, lower, upper, maxfev, adaptive, xatol=1e-10, fatol=1e-14):
    with np.errstate(invalid="ignore"):  # SciPy subtracts inf from inf
        found = minimize(lambda x: float(func(x[None, :])[0]), x0, method="Nelder-Mead",
                         bounds=list(zip(lower, upper, strict=True)),
                         options={"maxfev": maxfev, "xatol": xatol, "fatol": fatol,
                                  "adaptive": adaptive})
    return found.x, found.fun, found.nfev, found.status


@pytest.mark.parametrize("func", [_rosenbrock, _terraced])
@pytest.mark.parametrize(("n", "adaptive"), [(2, False), (5, True), (9, True), (3, False)])
@pytest.mark.parametrize("maxfev", [1, 4, 11, 12, 37, 400])
def test_every_start_follows_scipy(func, n, adaptive, maxfev):
    rng = np.random.default_rng(n * 1000 + maxfev)
    x0 = rng.random((6, n))
    x0[0, 0] = 0.0  # SciPy's zero step
    x0[1, -1] = 1.0  # a simplex reflected off the upper bound
    lower, upper = np.zeros(n), np.ones(n)
    lower[-1], upper[-1] = -np.inf, np.inf  # a column without bounds
    calls = []

    def batch(points):
        calls.append(len(points))
        return func(points)

    got = nelder_mead(batch, x0, lower=lower, upper=upper, maxfev=maxfev, xatol=1e-10,
                      fatol=1e-14, adaptive=adaptive)
    for s in range(len(x0)):
        x, fun, nfev, status = _scipy(func, x0[s], lower, upper, maxfev, adaptive)
        np.testing.assert_array_equal(got.x[s], x)
        assert got.fun[s] == fun
        assert got.nfev[s] == nfev
        assert got.status[s] == (CONVERGED if status == 0 else BUDGET)
    assert sum(calls) == got.nfev.sum()
    # one call per stage for all the starts: at most three per iteration of the longest
    assert len(calls) <= 1 + 3 * max(got.nfev.max() - n - 1, 0)


def test_converged_starts_stop_early_and_agree_with_scipy():
    x0 = np.array([[0.5, 0.5], [0.1, 0.9], [0.7, 0.2]])
    got = nelder_mead(_rosenbrock, x0, lower=np.zeros(2), upper=np.ones(2), maxfev=5000,
                      xatol=1e-8, fatol=1e-12)
    assert np.all(got.status == CONVERGED) and np.all(got.nfev < 5000)
    np.testing.assert_allclose(got.x, 2.0 / 3.0, atol=1e-7)  # the valley's minimum
    for s in range(3):
        x, fun, nfev, _ = _scipy(_rosenbrock, x0[s], np.zeros(2), np.ones(2), 5000, False,
                                 1e-8, 1e-12)
        np.testing.assert_array_equal(got.x[s], x)
        assert (got.fun[s], got.nfev[s]) == (fun, nfev)


@pytest.mark.parametrize("after", [0, 1, 2, 5, 17])
def test_an_outside_stop_returns_the_best_point_evaluated(after):
    rng = np.random.default_rng(after)
    x0 = rng.random((4, 3))
    seen: list[tuple[np.ndarray, np.ndarray]] = []

    def batch(points):
        seen.append((points.copy(), _rosenbrock(points)))
        return seen[-1][1]

    calls = iter(range(10**6))
    got = nelder_mead(batch, x0, lower=np.zeros(3), upper=np.ones(3), maxfev=10**6,
                      stop=lambda: next(calls) >= after)
    assert np.all(got.status == STOPPED)
    points = np.concatenate([p for p, _ in seen])
    values = np.concatenate([v for _, v in seen])
    if after == 0:  # stopped before anything: the starts alone are evaluated
        assert len(seen) == 1 and np.all(got.nfev == 1)
        np.testing.assert_array_equal(got.x, x0)
    for s in range(4):
        assert got.fun[s] == pytest.approx(_rosenbrock(got.x[s][None, :])[0], abs=0)
        mine = [v for p, v in zip(points, values, strict=True)
                if np.any(np.all(np.isclose(p, got.x[s], atol=0), axis=-1))]
        assert mine  # the point returned was evaluated
    assert got.fun.min() == values.min()
