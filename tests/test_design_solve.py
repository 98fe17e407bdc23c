"""A population of designs solved at once equals each design solved alone."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.errors import SolveError
from mechloop.solve.designs import solve_designs
from mechloop.synthesis.problem import SynthesisProblem

FOUR_BAR = "examples/four_bar.yaml"


def _one_design(model: mechloop.Model, r2_mm: float, r3_mm: float, delta6_deg: float,
                offset1_deg: float) -> mechloop.Model:
    data = model.model_dump(mode="json", exclude_none=True)
    data["vectors"]["2"]["r"] = r2_mm
    data["vectors"]["3"]["r"] = r3_mm
    data["vectors"]["6"]["a"]["delta"] = delta6_deg
    data["vectors"]["1"]["a"]["offset"] = offset1_deg
    return mechloop.Model.from_dict(data)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.floats(150, 500), st.floats(80, 400), st.floats(-90, 90),
                          st.floats(-180, 180)), min_size=1, max_size=6))
def test_population_equals_designs_solved_one_by_one(designs):
    model = mechloop.load_model(FOUR_BAR)
    r2, r3, d6, off = (np.array(col) for col in zip(*designs, strict=True))
    batch = solve_designs(model, {"r2": r2 / 1000, "r3": r3 / 1000,
                                  "a6": np.radians(d6), "a1": np.radians(off)},
                          chunk_elements=150)  # several chunks of designs
    for d in range(len(designs)):
        alone = mechloop.solve(_one_design(model, r2[d], r3[d], d6[d], off[d]))
        np.testing.assert_array_equal(batch.broken[d], alone.broken)
        assert batch.assembles[d] == (not alone.breaks)
        for name in ("a1", "a2", "a3", "r7", "a7", "a6"):
            for got, want in ((batch.values, alone.values), (batch.rates, alone.rates),
                              (batch.accels, alone.accels)):
                np.testing.assert_allclose(got[name][d], want[name], rtol=1e-9,
                                           atol=1e-12, equal_nan=True)


def test_branch_change_is_reported_for_a_tracked_variant():
    # A change-point four-bar (s + l = p + q) with variant 'auto': at the folded position
    # the branches meet and continuity may carry the coupler onto the other branch.
    model = mechloop.load_model(FOUR_BAR)
    data = model.model_dump(mode="json", exclude_none=True)
    data["contours"][0]["variant"] = "auto"
    model = mechloop.Model.from_dict(data)
    batch = solve_designs(model, {"r2": np.array([0.35, 0.35])})
    assert batch.keeps_variant.all()  # a crank-rocker stays on its branch
    # a parallelogram (crank = rocker, coupler = frame) folds twice per turn
    par = solve_designs(model, {"r2": np.array([0.3]), "r3": np.array([0.1])})
    assert not par.assembles[0] or not par.keeps_variant[0]


def test_breaks_are_per_design():
    model = mechloop.load_model(FOUR_BAR)
    batch = solve_designs(model, {"r3": np.array([0.25, 0.05])})  # second cannot close
    assert batch.assembles.tolist() == [True, False]
    assert np.isnan(batch.values["a2"][1][batch.broken[1]]).all()
    assert np.isfinite(batch.values["a2"][0]).all()


def test_only_constants_links_and_offsets_can_vary():
    model = mechloop.load_model(FOUR_BAR)
    with pytest.raises(SolveError, match="cannot vary a2"):
        solve_designs(model, {"a2": np.array([0.1])})
    with pytest.raises(SolveError, match="one value per design"):
        solve_designs(model, {"r2": np.array([0.3, 0.4]), "r3": np.array([0.2])})


def _four_bars(model: mechloop.Model, designs, *, tracked: bool) -> tuple[
        mechloop.Model, dict[str, np.ndarray]]:
    if tracked:
        data = model.model_dump(mode="json", exclude_none=True)
        data["contours"][0]["variant"] = "auto"
        model = mechloop.Model.from_dict(data)
    r2, r3, d6, off = (np.array(col) for col in zip(*designs, strict=True))
    return model, {"r2": r2 / 1000, "r3": r3 / 1000, "a6": np.radians(d6),
                   "a1": np.radians(off)}


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.floats(50, 500), st.floats(50, 400), st.floats(-90, 90),
                          st.floats(-180, 180)), min_size=1, max_size=8),
       st.booleans())
def test_position_only_solve_gives_the_same_positions_breaks_and_branches(designs, tracked):
    model, overrides = _four_bars(mechloop.load_model(FOUR_BAR), designs, tracked=tracked)
    full = solve_designs(model, overrides, chunk_elements=150)
    positions = solve_designs(model, overrides, derivatives=False, chunk_elements=150)
    assert full.derivatives and not positions.derivatives
    assert positions.values.keys() == full.values.keys()
    for name, value in full.values.items():
        np.testing.assert_array_equal(positions.values[name], value)  # bit for bit
    np.testing.assert_array_equal(positions.broken, full.broken)
    for masks in ("no_solution", "dead", "branch_changes"):
        got, want = getattr(positions, masks), getattr(full, masks)
        assert got.keys() == want.keys()
        for contour in want:
            np.testing.assert_array_equal(got[contour], want[contour])
    np.testing.assert_array_equal(positions.keeps_variant, full.keeps_variant)
    np.testing.assert_array_equal(positions.assembles, full.assembles)


def test_rates_of_a_position_only_solve_raise_a_clear_error():
    model = mechloop.load_model(FOUR_BAR)
    res = solve_designs(model, {"r3": np.array([0.25, 0.05])}, derivatives=False)
    for table in (res.rates, res.accels, res.subset(np.array([0])).rates):
        with pytest.raises(SolveError, match=r"derivatives=False") as info:
            table["a3"]
        assert "derivatives=True" in str(info.value)  # the fix
        with pytest.raises(SolveError):
            dict(table)
    assert not res.subset(np.array([1])).derivatives
    with pytest.raises(SolveError, match="not solved"):
        pickle.loads(pickle.dumps(res)).accels["a2"]  # also in a worker's results
    assert np.isfinite(res.values["a3"][0]).all()  # the positions are all there


@pytest.mark.parametrize(("path", "variant", "ranges"), [
    ("examples/crank_slider.yaml", "auto", {"r2": (0.03, 0.3), "r4": (-0.1, 0.1)}),
    ("examples/six_bar.yaml", 1, {"r2": (0.2, 0.4), "r7": (0.1, 0.3), "a5": (-0.7, 0.7)}),
])
def test_position_only_solve_of_sliders_and_six_bars_gives_the_same_positions(
        path, variant, ranges):
    data = mechloop.load_model(path).model_dump(mode="json", exclude_none=True)
    data["contours"][0]["variant"] = variant
    model = mechloop.Model.from_dict(data)
    rng = np.random.default_rng(3)
    overrides = {name: rng.uniform(*bounds, 60) for name, bounds in ranges.items()}
    full = solve_designs(model, overrides)
    positions = solve_designs(model, overrides, derivatives=False)
    assert not full.assembles.all() and full.assembles.any()
    for name, value in full.values.items():
        np.testing.assert_array_equal(positions.values[name], value)
    np.testing.assert_array_equal(positions.broken, full.broken)
    np.testing.assert_array_equal(positions.keeps_variant, full.keeps_variant)


PATH_SYNTHESIS = "examples/four_bar_path_synthesis.yaml"


def _with_criteria(criteria: list[dict]) -> mechloop.Model:
    data = mechloop.load_model(PATH_SYNTHESIS).model_dump(mode="json",
                                                          exclude_defaults=True)
    data["synthesis"]["criteria"] = criteria
    return mechloop.Model.from_dict(data)


@pytest.mark.parametrize("criteria", [
    [],
    [{"column": "a3", "reduce": "range", "max": 40},
     {"point": {"head": 6}, "coordinate": "y", "reduce": "max", "max": "300 mm"}],
])
def test_synthesis_on_positions_solves_no_derivatives_and_scores_the_same(criteria):
    problem = SynthesisProblem(_with_criteria(criteria))
    assert not problem.needs_derivatives
    rng = np.random.default_rng(7)
    designs = problem.variables.scale(rng.uniform(size=(40, len(problem.variables))))
    assert not problem.solve(designs).derivatives
    fast = problem.evaluate(designs)
    problem.needs_derivatives = True  # the same evaluation with rates and accelerations
    assert problem.solve(designs).derivatives
    full = problem.evaluate(designs)
    assert fast.feasible.any() and not fast.feasible.all()
    np.testing.assert_array_equal(fast.total, full.total)
    np.testing.assert_array_equal(fast.q, full.q)
    assert fast.terms.keys() == full.terms.keys()
    for key in full.terms:
        np.testing.assert_array_equal(fast.terms[key], full.terms[key])
        np.testing.assert_array_equal(fast.measures[key], full.measures[key])


@pytest.mark.parametrize("column", ["da3", "ddr7"])
def test_a_criterion_on_a_rate_or_an_acceleration_solves_derivatives(column):
    problem = SynthesisProblem(_with_criteria([{"column": column, "reduce": "absmax",
                                                "max": 1e6}]))
    assert problem.needs_derivatives
    middle = np.full((1, len(problem.variables)), 0.5)
    evaluation = problem.evaluate(problem.variables.scale(middle))
    assert evaluation.feasible[0]
    assert np.isfinite(evaluation.measures[f"absmax {column}"][0])
