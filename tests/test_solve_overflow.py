"""Values that overflow floating point inside the solver are chain breaks: the rows are
marked broken, the break says why, and no NumPy warning reaches the user (found by the
fuzz suite: an argument table starting at 1e308 deg wrote empty accelerations into rows
not marked broken, after RuntimeWarnings)."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

from mechloop import load_model
from mechloop.solve.kinematics import OVERFLOW, solve

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "crank_slider.yaml"


def _with_table(table: dict[int, float]):
    """The example with argument 1's table replaced, past the loader's checks (the solver
    must hold even for a model built in code)."""
    model = load_model(EXAMPLE)
    argument = model.arguments[1].model_copy(update={"table": table})
    return model.model_copy(update={"arguments": {1: argument}})


def test_overflowing_rates_are_a_chain_break_without_warnings():
    model = _with_table({0: 1e308, 72: 360.0})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        results = solve(model)
        frame = results.to_frame()
    overflow = [b for b in results.breaks if b.reason == OVERFLOW]
    assert overflow and overflow[0].contour == 1
    assert results.broken[overflow[0].positions].all()
    kept = frame[~frame["chain_break"]].drop(columns="chain_break")
    assert np.isfinite(kept.to_numpy(dtype=float)).all()
    assert frame["chain_break"].any()


def test_finite_models_have_no_overflow_break():
    results = solve(load_model(EXAMPLE))
    assert not results.broken.any()
    assert not results.breaks
