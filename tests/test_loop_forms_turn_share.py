"""The closed-form share of a crank turn where a loop breaks
(:func:`mechloop.solve.loop_forms.turn_share`) against a dense solve of the slider-crank
(7,200 positions over the turn: the share of broken positions)."""

from __future__ import annotations

import numpy as np

import mechloop
from mechloop.solve.designs import solve_designs
from mechloop.solve.existence import THRESHOLD, ExistenceCheck
from mechloop.solve.loop_forms import turn_share

N = 7200


def test_slider_crank_share_of_the_turn_matches_a_dense_solve():
    model = mechloop.load_model("examples/crank_slider.yaml")
    data = model.model_dump(mode="json", exclude_defaults=True)
    data.update(positions=N, arguments={1: {"table": {0: 0, N: 360}}})
    model = mechloop.Model.from_dict(data)
    rng = np.random.default_rng(4)
    over = {"r1": rng.uniform(0.02, 0.12, 40), "r2": rng.uniform(0.03, 0.2, 40),
            "r4": rng.uniform(-0.06, 0.06, 40)}
    for name, last in (("r1", 0.02), ("r2", 0.03), ("r4", -0.06)):  # broken everywhere
        over[name] = np.append(over[name], last)
    (loop,) = ExistenceCheck(model).loops(over)
    assert loop.kind == "slider-crank"
    turns, share = turn_share(loop, THRESHOLD)
    broken = solve_designs(model, over, derivatives=False).broken[:, :-1]  # one turn
    dense = broken.mean(axis=1)
    assert turns.any() and (~turns).any() and (dense == 1).any()  # every case met
    np.testing.assert_array_equal(turns, ~broken.any(axis=1))
    np.testing.assert_allclose(share, dense, atol=2.0 / N)
