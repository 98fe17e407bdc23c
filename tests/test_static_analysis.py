"""Static force analysis (a model without time): balancing loads by the principle of virtual
work, no inertia.

A powered roof support sketched as a four-bar: a rear link O–A (with a lug O–P), a canopy
A–B, a front link B–D on the base; a hydraulic leg G–P between the base and the lug is the
input (model argument 1: its length, 0.75 m → 0.95 m).  The roof presses on the canopy with
20 kN at a point off its line; the links have masses (gravity on).  A second variant
drives the rear link by its angle instead (a balancing moment).

Without model time the derivatives are analogs with respect to argument 1 and the
analysis is static.  Checked against:

* virtual work, ``Q = −Σ F·dz_P/dq − Σ M·dθ/dq`` over the external forces, moments and
  gravity, with ``dz/dq`` by seven-point central differences of positions over the
  argument (≤ 1e-8 of the largest load times the stroke's lever);
* the equilibrium of every body (Newton–Euler with a = 0, ε = 0: ``tests/oracles``);
* no inertia: with gravity off, masses and moments of inertia change nothing;
* the leg pushes (Q > 0: the balancing force of a length argument pushes the ends of the
  driven vector apart) against a roof that presses down;
* with friction in the pins (directed by the analogs: the leg extending), the leg must push
  harder at every position, and kinetostatics still equals virtual work plus the
  friction's work per unit of stroke.
"""

from __future__ import annotations

import copy

import numpy as np
import pytest
from oracles.dynamic_models import dynamics
from oracles.dynamics import (
    angle_first_derivative,
    external_forces,
    external_moments,
    first_derivative,
    newton_euler,
)

N = 400
STROKE = (0.75, 0.95)  # leg length (m)
SWING = (63.0, 84.0)  # rear-link angle (deg) for the angle-driven variant
FD_RTOL = 1e-8
RTOL = 1e-9

BODIES = {
    1: {"name": "rear link", "vectors": [1, 4], "mass": 120.0, "inertia": "rod",
        "center": {"vector": 4, "share": 0.5}},
    2: {"name": "canopy", "vectors": [5], "mass": 300.0, "inertia": 25.0,
        "center": {"vector": 5, "share": 0.5, "across": 0.1}},
    3: {"name": "front link", "vectors": [6], "mass": 100.0, "inertia": "rod",
        "center": {"vector": 6, "along": 0.7}},
}
ROOF = [{"name": "roof", "body": 2, "at": {"vector": 5, "share": 0.3, "across": 0.15},
         "value": 20000.0, "angle": -90.0}]


def roof_support(*, by_angle: bool = False, bodies=None, gravity=True, time=None) -> dict:
    if by_angle:  # the rear link turned by argument 1; the leg is left out
        rear = {"r": 1.2, "a": {"argument": 1}}
        arguments = {1: {"table": {0: SWING[0], N: SWING[1]}}}
        contours = [{"vectors": [4, 5, 6, 7], "variant": 1}]
        vectors = {4: rear, 5: {"r": 0.9, "a": "function"}, 6: {"r": 1.4, "a": "function"},
                   7: {"r": 0.5, "a": 180.0}}
        bodies = copy.deepcopy(bodies if bodies is not None else BODIES)
        bodies[1]["vectors"] = [4]
    else:
        arguments = {1: {"table": {0: STROKE[0], N: STROKE[1]}}}
        vectors = {1: {"r": 0.8, "a": "function"},  # O->P, the lug along the rear link
                   2: {"r": {"argument": 1}, "a": "function"},  # P->G, the leg
                   3: {"r": 0.6, "a": 180.0},  # G->O, base
                   4: {"r": 1.2, "a": {"link": "a1"}},  # O->A, rear link
                   5: {"r": 0.9, "a": "function"},  # A->B, canopy
                   6: {"r": 1.4, "a": "function"},  # B->D, front link
                   7: {"r": 0.5, "a": 180.0}}  # D->O, base
        contours = [{"vectors": [1, 2, 3], "variant": 1},
                    {"vectors": [4, 5, 6, 7], "variant": 1}]
        bodies = copy.deepcopy(bodies if bodies is not None else BODIES)
    data = {"positions": N, "arguments": arguments, "vectors": vectors,
            "contours": contours, "bodies": bodies, "forces": copy.deepcopy(ROOF),
            "moments": [{"body": 3, "value": -500.0}]}
    if gravity:
        data["gravity"] = {"g": 9.81}
    if time is not None:
        data["time"] = time
    return data


def virtual_work(d, data) -> np.ndarray:
    """−Σ F·dz/dq − Σ M dθ/dq, finite differences over the argument (NaN at the ends)."""
    q = d.kinematics.arguments[1]
    h = float(q[1] - q[0])
    out = np.zeros(q.size)
    for f in external_forces(data, d):
        out -= (np.conj(f.force) * first_derivative(f.at, h, periodic=False)).real
    for body, moment in external_moments(data, q.size):
        angle = d.kinematics.value(f"a{data['bodies'][body]['vectors'][0]}")
        out -= moment * angle_first_derivative(angle, h, periodic=False)
    return out


@pytest.fixture(params=["leg", "rear link"])
def case(request):
    data = roof_support(by_angle=request.param == "rear link")
    d = dynamics(data)
    assert d.static and not d.kinematics.broken.any() and not d.forces.singular.any()
    return data, d


def test_balancing_load_is_virtual_work(case):
    data, d = case
    want = virtual_work(d, data)
    got = d.forces.balancing[1]
    inner = np.isfinite(want)
    scale = np.abs(got).max()
    err = np.abs(got[inner] - want[inner]).max()
    assert err <= FD_RTOL * scale, f"Q − virtual work = {err:.3e} (scale {scale:.3e})"
    # the virtual-power path of the solver gives the same
    assert np.abs(d.balancing_vp[1] - got).max() <= RTOL * scale


def test_every_body_in_equilibrium(case):
    data, d = case
    for r in newton_euler(d, data, static=True):
        assert np.abs(r.force).max() <= RTOL * r.force_scale, r.body
        assert np.abs(r.moment).max() <= RTOL * r.moment_scale, r.body


def test_no_inertia_without_time():
    """Gravity off: the masses and inertias matter only through inertia, which a static
    analysis leaves out; with model time they do matter."""
    massless = {k: {key: v for key, v in b.items() if key in ("name", "vectors")}
                for k, b in BODIES.items()}
    heavy = dynamics(roof_support(gravity=False))
    light = dynamics(roof_support(gravity=False, bodies=massless))
    scale = np.abs(light.forces.balancing[1]).max()
    np.testing.assert_allclose(heavy.forces.balancing[1], light.forces.balancing[1], rtol=0,
                               atol=RTOL * scale)
    for name, r in heavy.forces.reactions.items():
        np.testing.assert_allclose(r.force, light.forces.reactions[name].force, rtol=0,
                                   atol=RTOL * scale, err_msg=name)
    assert heavy.kinetic_energy.max() == 0
    timed = dynamics(roof_support(gravity=False, time={"table": {0: 0.0, N: 0.2}}))
    assert not timed.static
    assert np.abs(timed.forces.balancing[1] - light.forces.balancing[1]).max() > 1e-3 * scale


def test_the_leg_pushes_against_the_roof():
    d = dynamics(roof_support())
    assert (d.forces.balancing[1] > 0).all()
    assert d.mechanism.drives[0].kind == "length"
    assert d.mechanism.drives[0].bodies == (1, 0)  # the lug's body at its tail, the base


def test_friction_in_a_static_analysis():
    data = roof_support()
    data["friction"] = {"coefficient": 0.1, "radius": 0.03}
    d, ideal = dynamics(data), dynamics(roof_support())
    assert d.forces.iterations > 1
    assert (d.forces.balancing[1] > ideal.forces.balancing[1]).all()
    scale = np.abs(d.forces.balancing[1]).max()
    loss = d.forces.friction_loss  # per unit of argument 1 without time
    assert (loss > 0).all()
    np.testing.assert_allclose(d.forces.balancing[1], ideal.forces.balancing[1] + loss,
                               rtol=0, atol=RTOL * scale)
    np.testing.assert_allclose(d.balancing_vp[1], d.forces.balancing[1], rtol=0,
                               atol=RTOL * scale)
