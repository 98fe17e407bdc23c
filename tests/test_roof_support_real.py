"""The roof support with its real leg (``examples/roof_support_real.yaml``, a class-III group
solved as one coupled block) against independent references.

* Kinematics: every position solved is an assembly the SciPy oracle finds from many starts
  (``oracles.assemblies``), the one drawn (B above the base, A behind the links); the leg
  spans the argument from D to its own pin C on the canopy; derivatives (analogs per metre
  of leg) against the oracle's finite differences.
* The shield moves on the simplification's lemniscate: the canopy tip's path is the same
  curve as in ``examples/roof_support.yaml`` (the same four-bar, only driven elsewhere).
* Forces: static Newton–Euler of every body with the returned pin reactions and leg force
  (``oracles.dynamics``), and the leg force equal to virtual work.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from oracles.assemblies import Equations
from oracles.dynamic_models import dynamics, example
from oracles.dynamics import moment_scale, newton_euler

import mechloop
from mechloop.model.check import require_valid

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
D = np.array([0.0, 0.15])
O2 = D + np.array([1.605, 0.575])


@pytest.fixture(scope="module")
def real() -> mechloop.DynamicResults:
    return mechloop.solve_dynamics(mechloop.load_model(EXAMPLES / "roof_support_real.yaml"))


def _xy(angle: np.ndarray) -> np.ndarray:
    return np.stack([np.cos(angle), np.sin(angle)])


def test_contours_1_and_2_are_one_coupled_block():
    structure = require_valid(mechloop.load_model(EXAMPLES / "roof_support_real.yaml"))
    first, tip = structure.blocks
    assert first.coupled and first.contours == (1, 2)
    assert sorted(first.unknowns) == ["a3", "a4", "a8", "a9"]
    assert not tip.coupled and tip.contours == (3,)


def test_positions_are_assemblies_of_the_oracle(real):
    k = real.kinematics
    assert not k.broken.any()
    model = mechloop.load_model(EXAMPLES / "roof_support_real.yaml")
    eq = Equations(model)
    for p in (0, 20, 40):
        u = np.array([k.values[n][p] for n in eq.names])
        roots = eq.assemblies(p, starts=40)
        assert min(eq.distance(u, x) for x in roots) < 1e-10
    # the assembly drawn: B above the front pivot's base line, A behind (left of) B
    B = O2[:, None] + 1.07 * _xy(k.value("a3"))
    A = B + 0.85 * _xy(k.value("a8"))
    assert (B[1] > O2[1]).all() and (A[0] < B[0]).all()
    # the leg runs from D to its pin C, 0.40 m along the canopy from B
    C = B + 0.40 * _xy(k.value("a8") + np.pi)
    np.testing.assert_allclose(np.hypot(*(C - D[:, None])), k.arguments[1], atol=1e-12)


def test_analogs_against_the_oracle(real):
    k = real.kinematics
    model = mechloop.load_model(EXAMPLES / "roof_support_real.yaml")
    eq = Equations(model)
    for p in (5, 20, 35):
        u = np.array([k.values[n][p] for n in eq.names])
        d1, d2, e1, e2 = eq.rates(u, p)
        rates = np.array([k.rates[n][p] for n in eq.names])
        accels = np.array([k.accels[n][p] for n in eq.names])
        assert (np.abs(rates - d1) <= 1e-7 * np.abs(d1).max() + 10 * e1).all()
        assert (np.abs(accels - d2) <= 1e-4 * np.abs(d2).max() + 10 * e2).all()


def test_the_shield_moves_on_the_simplifications_lemniscate(real):
    # the simplification solved finely: its canopy tip's path x(y)
    model = mechloop.load_model(EXAMPLES / "roof_support.yaml")
    data = model.model_dump()
    data["positions"] = 2000
    data["arguments"] = {1: {"table": {0: 0.95, 2000: 1.65}}}
    fine = mechloop.solve(mechloop.Model.model_validate(data))

    def tip(res):
        x = O2[0] - res.values["r12"] * np.cos(res.values["a12"])
        y = O2[1] - res.values["r12"] * np.sin(res.values["a12"])
        return x, y

    xs, ys = tip(fine)
    xr, yr = tip(real.kinematics)
    order = np.argsort(ys)
    assert ys.min() < yr.min() and yr.max() < ys.max()
    # linear interpolation over 2000 positions: error ~ h²·x''/8, well below 1e-6 m
    np.testing.assert_allclose(xr, np.interp(yr, ys[order], xs[order]), atol=1e-6)


def test_every_body_balances_and_the_leg_force_is_virtual_work(real):
    # the oracle reads SI data: the roof load in N
    data = example("roof_support_real.yaml")
    data["units"] = {**data["units"], "force": "N"}
    data["forces"] = [{**f, "value": f["value"] * 1e3} for f in data["forces"]]
    si = dynamics(data)
    np.testing.assert_array_equal(si.forces.balancing[1], real.forces.balancing[1])
    assert real.static
    for r in newton_euler(real, data, static=True):
        assert np.abs(r.force).max() <= 1e-9 * r.force_scale, f"body {r.body}"
        assert np.abs(r.moment).max() <= 1e-9 * r.moment_scale, f"body {r.body}"
    assert (np.abs(real.forces.balancing[1] - real.balancing_vp[1])
            <= 1e-9 * moment_scale(real, data)).all()
    force = real.to_frame()["F_bal [N]"].to_numpy()
    assert (force > 0).all(), "the leg pushes against the roof"
