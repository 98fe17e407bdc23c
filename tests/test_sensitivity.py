"""Derivatives of positions with respect to design constants (implicit
differentiation, :mod:`mechloop.solve.sensitivity`) against central finite differences,
and the time budget of a synthesis run (polish included)."""

from __future__ import annotations

import time

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from mechloop.model.load import load_model
from mechloop.solve.designs import solve_designs
from mechloop.solve.sensitivity import position_tangents
from mechloop.synthesis.gradient import point_tangents, residual_jacobian
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import synthesize

FIVE = "examples/five_points_timing_synthesis.yaml"
SIX = "examples/six_points_free_timing_synthesis.yaml"
SLIDER = "examples/crank_slider.yaml"

_PROBLEMS: dict[str, SynthesisProblem] = {}


def _problem(path: str) -> SynthesisProblem:
    if path not in _PROBLEMS:
        _PROBLEMS[path] = SynthesisProblem(load_model(path))
    return _PROBLEMS[path]


def _feasible_design(problem: SynthesisProblem, seed: int) -> np.ndarray:
    """A random design of the box that assembles everywhere (a crank that turns)."""
    rng = np.random.default_rng(seed)
    v = problem.variables
    designs = v.scale(rng.uniform(size=(200, len(v))))
    ok = np.flatnonzero(problem.evaluate(designs).feasible)
    assert ok.size, "no feasible design among 200 random ones"
    return designs[ok[0]]


@settings(max_examples=6, deadline=None)
@given(seed=st.integers(0, 10**6), path=st.sampled_from([FIVE, SIX]))
def test_point_tangents_match_finite_differences(seed: int, path: str) -> None:
    """Random four-bars (timed targets, and free timing whose inputs are variables): the
    tracing point's derivative with respect to every variable agrees with central
    differences to 1e-6 of its size."""
    problem = _problem(path)
    x = _feasible_design(problem, seed)
    _, dz = point_tangents(problem, x[None, :])
    v = problem.variables
    h = 1e-6 * (v.high - v.low)
    probes = np.concatenate([x + np.diag(h), x - np.diag(h)])
    zp, _ = point_tangents(problem, probes)
    n = len(v)
    fd = (zp[:n] - zp[n:]) / (2 * h[:, None])
    scale = np.max(np.abs(fd)) + 1e-3
    assert np.max(np.abs(dz[:, 0, :] - fd)) < 1e-6 * scale


def test_residual_jacobian_rows_are_the_point_errors() -> None:
    """The Jacobian of the residuals: the x and y rows of each target are the point's
    derivative divided by the length unit (mm here), by differences too."""
    problem = _problem(FIVE)
    x = _feasible_design(problem, 5)
    res, jac = residual_jacobian(problem, x)
    v = problem.variables
    h = 1e-6 * (v.high - v.low)
    fd = np.stack([(problem.residuals((x + e)[None])[0] - problem.residuals((x - e)[None])[0])
                   / (2 * hj) for e, hj in zip(np.diag(h), h, strict=True)], axis=1)
    assert res.shape == (10,) and jac.shape == (10, 6)
    np.testing.assert_allclose(jac, fd, rtol=1e-5, atol=1e-6 * np.abs(fd).max())


@settings(max_examples=6, deadline=None)
@given(r1=st.floats(0.02, 0.08), r2=st.floats(0.15, 0.3), r4=st.floats(-0.05, 0.05),
       offset=st.floats(-3.0, 3.0))
def test_slider_crank_tangents_match_finite_differences(r1: float, r2: float, r4: float,
                                                         offset: float) -> None:
    """A slider-crank (module Pl3): the derivatives of the slider position r3 and the
    rod angle a2 with respect to the crank, the rod, the offset and the crank's angle
    offset, against central differences at every position."""
    model = load_model(SLIDER)
    names = ["r1", "r2", "r4", "a1"]
    base = np.array([r1, r2, r4, offset])
    h = 1e-6 * np.array([0.1, 0.1, 0.1, 1.0])
    rows = np.concatenate([base[None], base + np.diag(h), base - np.diag(h)])
    res = solve_designs(model, dict(zip(names, rows.T, strict=True)), derivatives=False)
    values = {k: np.asarray(t)[:1] for k, t in res.values.items()}
    seeds = {name: np.eye(4)[:, i][:, None, None] for i, name in enumerate(names)}
    tangents = position_tangents(model, values, seeds, 4)
    for name in ("r3", "a2"):
        table = np.asarray(res.values[name])
        step = table[1:5] - table[5:9]
        if name[0] == "a":  # an angle's difference, not across the cut at ±180°
            step = np.angle(np.exp(1j * step))
        fd = step / (2 * h[:, None])
        ok = ~res.broken[0]
        assert ok.sum() > 10
        np.testing.assert_allclose(tangents[name][:, 0, ok], fd[:, ok], rtol=1e-5,
                                   atol=1e-7)


def test_time_budget_holds_with_the_polish() -> None:
    """A 2 s budget on a bundled example, DE with the polish: the whole call (compiling
    included) ends within 1.05 × 2 s + 0.3 s."""
    model = load_model(FIVE)
    start = time.perf_counter()
    result = synthesize(model, method="de", time_budget=2.0, iterations=10**6, seed=3)
    elapsed = time.perf_counter() - start
    assert elapsed <= 1.05 * 2.0 + 0.3
    assert result.stopped == "time budget spent"
    assert result.feasible and result.elapsed <= elapsed
    assert "exact Jacobian" in result.polish


def test_multistart_least_squares_reports_itself() -> None:
    """Multistart on a timed path runs least squares with the exact Jacobian: a short
    budget gives a feasible design better than every one of the first samples, and the
    result says how it was found and what it is worth."""
    model = load_model(FIVE)
    result = synthesize(model, method="multistart", time_budget=3.0, seed=2, atlas=False)
    assert result.feasible and result.method == "multistart"
    assert result.q < float(result.history["q"].iloc[0])
    assert "exact Jacobian" in result.polish and result.polish_evaluations > 0
    assert "atlas" not in " ".join(result.notes)
    lines = result.summary()
    assert lines[0].startswith("method: multistart;") and lines[-1].startswith("feasible: yes")
    assert any(f"Q = {result.q:.6g}" in line for line in lines)
