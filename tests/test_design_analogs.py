"""``solve_designs(..., analogs_of=k)`` gives each design's analogs as ``solve(design,
analogs_of=k)`` does (the drives' analogs of a population in the dynamics)."""

from __future__ import annotations

import numpy as np

import mechloop
from mechloop.solve.designs import solve_designs
from mechloop.solve.kinematics import solve


def test_analogs_of_a_population_equal_each_design_solved_alone():
    model = mechloop.load_model("examples/crank_slider_dynamics.yaml")
    data = model.model_dump(mode="json", exclude_defaults=True)
    crank, rod = [0.04, 0.06, 0.09], [0.16, 0.2, 0.1]  # the last breaks (rod < crank + e)
    population = solve_designs(model, {"r1": np.array(crank), "r2": np.array(rod)},
                               analogs_of=1)
    assert population.time is None and population.broken[2].any()
    for d, (r1, r2) in enumerate(zip(crank, rod, strict=True)):
        data["vectors"]["1"]["r"], data["vectors"]["2"]["r"] = r1, r2
        alone = solve(mechloop.Model.from_dict(data), analogs_of=1)
        np.testing.assert_array_equal(population.broken[d], alone.broken)
        for name in alone.varying():
            for got, want in ((population.values, alone.values),
                              (population.rates, alone.rates),
                              (population.accels, alone.accels)):
                np.testing.assert_allclose(got[name][d], want[name], rtol=1e-12,
                                           atol=1e-12, err_msg=f"design {d}, {name}")
