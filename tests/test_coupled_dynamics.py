"""Dynamics of a class-III mechanism (a triad, one coupled block) balance like any other.

The triad of ``benchmarks/bench_coupled.py`` (ternary link B1 B2 B3 pinned to the frame at
A1 and A2 by two dyads and to a crank O→A3 by the third) with masses, inertias, an
off-axis centre, a force on the ternary link, a moment on a dyad and gravity, 360
positions a turn at 60 rpm.  The pairs are inferred from the vector model (seven
revolute pairs); then, as for the elementary mechanisms
(``tests/test_reactions_newton_euler.py``, ``tests/test_dynamics_balance.py``):

* every body satisfies Newton–Euler with the returned reactions and balancing moment,
  accelerations by seven-point finite differences in time (``oracles.dynamics``),
  residuals ≤ 1e-9 of the largest force (moments: times the mechanism's size);
* the balancing moment of the kinetostatics equals the virtual-power one (≤ 1e-9).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
from oracles.dynamic_models import dynamics
from oracles.dynamics import moment_scale, newton_euler

from mechloop.model.load import model_to_data

N = 360
_spec = importlib.util.spec_from_file_location(
    "bench_coupled", Path(__file__).resolve().parents[1] / "benchmarks" / "bench_coupled.py")
bench = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bench)
A1, triad = bench.A1, bench.triad


def triad_with_masses() -> dict:
    data = model_to_data(triad(N))
    data["vectors"] = {int(k): v for k, v in data["vectors"].items()}
    data["arguments"] = {1: {"table": {0: 0, N: 360}}}
    data["contours"][0]["start"] = list(A1)  # contour 1 starts at the frame pin A1
    data["bodies"] = {
        1: {"name": "crank", "vectors": [5], "mass": 2.0, "inertia": 0.01,
            "center": {"vector": 5, "share": 0.5}},
        2: {"name": "dyad 1", "vectors": [1, 8], "mass": 3.0, "inertia": 0.2,
            "center": {"vector": 1, "share": 0.5}},
        3: {"name": "ternary link", "vectors": [2, 7], "mass": 8.0, "inertia": 0.5,
            "center": {"vector": 7, "share": 0.3, "across": 0.1}},
        4: {"name": "dyad 2", "vectors": [3], "mass": 3.0, "inertia": 0.2,
            "center": {"vector": 3, "share": 0.5}},
        5: {"name": "dyad 3", "vectors": [6], "mass": 4.0, "inertia": 0.4,
            "center": {"vector": 6, "share": 0.5}},
    }
    data["forces"] = [{"body": 3, "at": {"head": 2}, "value": 500.0, "angle": -90.0}]
    data["moments"] = [{"body": 4, "value": -30.0}]
    data["gravity"] = {"g": 9.81}
    return data


def test_triad_dynamics_balance_every_body():
    data = triad_with_masses()
    d = dynamics(data)
    assert not d.kinematics.broken.any()
    assert not d.forces.singular.any()
    pairs = sorted(tuple(sorted(p.bodies)) for p in d.mechanism.pairs)
    # O (frame–crank), A3 (crank–dyad 3), B3 (dyad 3–ternary), B1 (dyad 1–ternary),
    # A1 (frame–dyad 1), B2 (ternary–dyad 2), A2 (frame–dyad 2)
    assert pairs == [(0, 1), (0, 2), (0, 4), (1, 5), (2, 3), (3, 4), (3, 5)]
    assert all(p.kind == "revolute" for p in d.mechanism.pairs)
    residuals = newton_euler(d, data, periodic=True)
    assert len(residuals) == 5
    for r in residuals:
        ok = np.isfinite(r.force)
        assert ok.all()
        assert np.abs(r.force).max() <= 1e-9 * r.force_scale, f"body {r.body}"
        assert np.abs(r.moment).max() <= 1e-9 * r.moment_scale, f"body {r.body}"
    err = np.abs(d.forces.balancing[1] - d.balancing_vp[1]).max()
    assert err <= 1e-9 * moment_scale(d, data)
