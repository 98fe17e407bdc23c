"""Values that overflow floating point inside the solver are chain breaks: the rows are
marked broken, the break says why, and no NumPy warning reaches the user (found by the
fuzz suite: an argument table starting at 1e308 deg, or 1e308 rpm, wrote empty
accelerations into rows not marked broken after RuntimeWarnings; a pin radius of 1e9 m
warned before its error).  The models are built past the loader, which refuses such
values where they enter: the solver must hold for a model built in code too."""

from __future__ import annotations

import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from mechloop import ModelError, SolveError, load_model
from mechloop.dynamics.analysis import solve_dynamics
from mechloop.dynamics.energy import split_work
from mechloop.solve.kinematics import OVERFLOW, solve

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "crank_slider.yaml"


def _with_table(table: dict[int, float]):
    """The example with argument 1's table replaced, past the loader's checks (the solver
    must hold even for a model built in code)."""
    model = load_model(EXAMPLE)
    argument = model.arguments[1].model_copy(update={"table": table})
    return model.model_copy(update={"arguments": {1: argument}})


def test_a_table_value_that_would_overflow_is_refused_before_solving():
    """A table value of 1e308 overflowed the rates (a chain break with RuntimeWarnings);
    the model check now refuses it, naming the key, before anything is solved."""
    model = _with_table({0: 1e308, 72: 360.0})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ModelError, match=r"outside the range") as caught:
            solve(model)
    assert caught.value.problems[0].path[:2] == ("arguments", 1)


def test_finite_models_have_no_overflow_break():
    results = solve(load_model(EXAMPLE))
    assert not results.broken.any()
    assert not results.breaks


def test_an_overflowing_model_time_is_a_chain_break_without_warnings():
    model = load_model(EXAMPLE)
    model = model.model_copy(update={"time": model.time.model_copy(update={"rpm": 1e308})})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        results = solve(model)
        frame = results.to_frame()
    assert any(b.reason == OVERFLOW for b in results.breaks)
    kept = frame[~frame["chain_break"]].drop(columns="chain_break")
    assert np.isfinite(kept.to_numpy(dtype=float)).all()


def test_friction_that_overflows_does_not_settle_without_warnings():
    model = load_model(EXAMPLE.with_name("crank_slider_friction.yaml"))
    friction = model.friction.model_copy(update={"radius": 1e9})
    model = model.model_copy(update={"friction": friction})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(SolveError, match="did not settle"):
            solve_dynamics(model)


def test_work_leaves_out_steps_of_a_clock_that_is_not_finite_without_warnings():
    """A clock (argument 1 of a model without time) that ends in -inf, as a CSV table can
    give it, made ``split_work`` warn on inf - inf; the steps are left out as documented."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        positive, negative = split_work(np.ones(4), np.array([0.0, 1.0, -np.inf, -np.inf]))
    assert positive == 1.0  # the one finite step: 0.5 * (1 + 1) * 1
    assert negative == 0.0


def test_an_infinite_constant_length_is_refused_before_the_dynamics():
    """A 100 KB string of nines as a length read as inf (fuzz), and placing the points
    multiplied inf by a zero rate with a warning at every position; the model check now
    refuses the length, naming the vector."""
    model = load_model(EXAMPLE.with_name("crank_slider_dynamics.yaml"))
    offset = model.vectors[4].model_copy(update={"r": float("inf")})
    model = model.model_copy(update={"vectors": {**model.vectors, 4: offset}})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ModelError, match=r"outside the range") as caught:
            solve_dynamics(model)
    assert caught.value.problems[0].path == ("vectors", 4, "r")


def test_rows_with_a_singular_force_system_are_marked_broken():
    """Found by the fuzz suite (a group file with a 2**64 mm link): where the force system
    is singular the reactions and balancing loads are empty, so the row is marked
    ``chain_break`` like a row where the chain breaks."""
    dynamic = solve_dynamics(load_model(EXAMPLE.with_name("crank_slider_dynamics.yaml")))
    singular = np.zeros(dynamic.forces.singular.shape, dtype=bool)
    singular[[3, 40]] = True
    marked = replace(dynamic, forces=replace(dynamic.forces, singular=singular))
    assert (marked.to_frame()["chain_break"].to_numpy() == singular).all()
    assert not dynamic.to_frame()["chain_break"].any()


def test_solve_designs_marks_overflow_broken_like_solve():
    """``solve_designs`` (synthesis' solver) marks the positions that overflow as broken,
    where ``solve`` does, without warnings: no unbroken row holds a non-number."""
    from mechloop.solve.designs import solve_designs, solve_designs_at

    model = load_model(EXAMPLE)
    model = model.model_copy(update={"time": model.time.model_copy(update={"rpm": 1e308})})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        single = solve(model)
        r1 = float(np.asarray(single.values["r1"])[0])  # SI
        designs = solve_designs(model, {"r1": np.array([r1, 0.06])})
        _, at = solve_designs_at(model, {"r1": np.array([0.05, 0.06])},
                                 np.array([[0.1, np.inf], [0.2, 0.3]]))
    assert single.broken.any()
    assert np.array_equal(designs.broken[0], single.broken)
    assert designs.broken.any(axis=-1).all() and not designs.assembles.any()
    for table in (designs.values, designs.rates, designs.accels):
        for name, arr in table.items():
            assert np.isfinite(np.broadcast_to(arr, designs.broken.shape)[~designs.broken]
                               ).all(), name
    assert at.broken[0, 1] and not at.broken[1].any()
