"""A population of designs solved at once equals each design solved alone."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.errors import SolveError
from mechloop.solve.designs import solve_designs

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
