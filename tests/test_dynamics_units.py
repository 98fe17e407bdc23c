"""Units only at the edges: the bundled slider-crank written in millimetres, grams,
kilonewtons, kN·m and mm/s² (lengths, centres, friction radius and slider length, masses,
the piston force, a moment, gravity) gives the same SI reactions, balancing moment and
friction work as the same model in metres, kilograms and newtons.
"""

from __future__ import annotations

import copy

import numpy as np
import pytest
from oracles.dynamic_models import dynamics, example

RTOL = 1e-12


def in_si() -> dict:
    data = example("crank_slider_dynamics.yaml",
                   friction={"coefficient": 0.1, "radius": 0.01, "length": 0.05},
                   moments=[{"body": 2, "value": 5.0}])
    data["bodies"][2]["center"] = {"vector": 2, "along": 0.06, "across": 0.005}
    return data


def in_other_units() -> dict:
    data = copy.deepcopy(in_si())
    data["units"] = {"length": "mm", "angle": "deg", "mass": "g", "force": "kN",
                     "moment": "kN*m", "inertia": "kg*m^2", "acceleration": "mm/s^2"}
    for vector in data["vectors"].values():
        if isinstance(vector["r"], int | float):
            vector["r"] *= 1000.0
    for body in data["bodies"].values():
        body["mass"] *= 1000.0
    data["bodies"][2]["center"] = {"vector": 2, "along": 60.0, "across": 5.0}
    data["forces"][0]["value"] = 1.0  # kN
    data["moments"] = [{"body": 2, "value": 0.005}]  # kN·m
    data["gravity"] = {"g": 9810.0}  # mm/s²
    data["friction"] = {"coefficient": 0.1, "radius": 10.0, "length": 50.0}
    return data


def test_model_units_do_not_change_the_si_results():
    a, b = dynamics(in_si()), dynamics(in_other_units())
    scale = np.abs(a.forces.balancing[1]).max()
    np.testing.assert_allclose(b.forces.balancing[1], a.forces.balancing[1], rtol=0,
                               atol=RTOL * scale)
    for name, r in a.forces.reactions.items():
        np.testing.assert_allclose(b.forces.reactions[name].force, r.force, rtol=0,
                                   atol=RTOL * np.abs(r.force).max(), err_msg=name)
        np.testing.assert_allclose(b.forces.reactions[name].friction, r.friction, rtol=0,
                                   atol=RTOL * np.abs(r.friction).max(), err_msg=name)
    assert abs(b.summary.friction_work - a.summary.friction_work) <= RTOL * \
        a.summary.friction_work
    assert b.mechanism.total_mass == pytest.approx(a.mechanism.total_mass, rel=1e-15)
    assert a.mechanism.total_mass == pytest.approx(2.0 + 1.5 + 1.2, rel=1e-15)
