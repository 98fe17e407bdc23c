"""The atlas of four-bar coupler curves: invariant descriptors, crank-rockers only, and
a mechanism recovered exactly from targets on its own (moved, turned, scaled) curve."""

from __future__ import annotations

import numpy as np
import pytest

from mechloop.model.load import load_model
from mechloop.synthesis import atlas as atlas_module
from mechloop.synthesis.atlas import (
    ATLAS_SIZE,
    build_atlas,
    coefficients,
    coupler_curves,
    descriptors,
    recognize,
)
from mechloop.synthesis.problem import SynthesisProblem

SIX = "examples/six_points_free_timing_synthesis.yaml"


@pytest.fixture(scope="module")
def small():
    return build_atlas(count=2000, seed=7)


def test_atlas_size_and_crank_rockers(small) -> None:
    """The shipped size is at least 1e5; every mechanism is a crank-rocker whose crank
    (1) is the shortest link and which meets Grashof's inequality, and its curve
    assembles at every sample."""
    assert ATLAS_SIZE >= 100_000
    g, c, k = small.params[:, 0], small.params[:, 1], small.params[:, 2]
    lengths = np.stack([np.ones_like(g), g, c, k], axis=1)
    assert np.all(lengths.min(axis=1) == 1.0)
    assert np.all(lengths.max(axis=1) + 1.0 < lengths.sum(axis=1) - lengths.max(axis=1) - 1)
    assert small.params.shape[0] > 1900 and np.isfinite(small.curves()).all()


def test_descriptors_are_invariant(small) -> None:
    """A curve moved, turned, scaled and started elsewhere has the same descriptors
    (under one of the two start normalizations), and another curve does not."""
    rng = np.random.default_rng(1)
    curves = small.curves(slice(0, 50))
    base = descriptors(coefficients(curves))
    a = 3.7 * np.exp(1.1j)
    moved = np.roll(a * curves + (5 - 2j), rng.integers(1, 60), axis=1)
    coef = coefficients(moved)
    both = np.stack([descriptors(coef, False), descriptors(coef, True)])
    err = np.min(np.max(np.abs(both - base[None]), axis=2), axis=0)
    assert np.all(err < 5e-2), np.sort(err)[-5:]
    other = np.max(np.abs(base[1:] - base[:-1]), axis=1)
    assert np.median(other) > 10 * np.max(err)


def test_recognizes_the_four_bar_of_the_six_point_problem() -> None:
    problem = SynthesisProblem(load_model(SIX))
    found, reason = recognize(problem.model, problem)
    assert reason == "" and (found.crank, found.coupler, found.rocker, found.frame) == (
        1, 2, 3, 4) and found.point == (6,)
    five = SynthesisProblem(load_model("examples/five_points_timing_synthesis.yaml"))
    assert recognize(five.model, five)[0] is None


def test_a_mechanism_is_recovered_from_points_of_its_curve(small, monkeypatch) -> None:
    """Six targets on the curve of an atlas mechanism mapped by a similarity into the
    six-point problem's box: the atlas start reaches them with (almost) zero error."""
    monkeypatch.setattr(atlas_module, "load_atlas", lambda: small)
    model = load_model(SIX)
    row = 11
    angles = np.linspace(0.3, 1.8, 6)
    points, ok = coupler_curves(small.params[row:row + 1], angles)
    assert ok.all()
    a = 6.0 * np.exp(0.7j)
    targets = a * points[0] + (20 + 30j)
    task = model.synthesis
    path = task.path.model_copy(update={"targets": [[float(z.real), float(z.imag)]
                                                    for z in targets]})
    bounds = dict(task.vary)
    bounds.update(r1=[1, 60], r2=[1, 60], r3=[1, 60], r4=[1, 60], r6=[0, 200])
    model = model.model_copy(update={"synthesis": task.model_copy(
        update={"path": path, "vary": bounds})})
    problem = SynthesisProblem(model)
    designs, reason = atlas_module.atlas_starts(problem, count=5)
    assert reason == ""
    ev = problem.evaluate(designs)
    assert ev.feasible[0] and ev.q[0] < 1e-3 * 6.0**2
