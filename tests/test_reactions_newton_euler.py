"""Joint reactions and balancing loads satisfy Newton–Euler for every body, at every
position, with accelerations the solver did not compute.

For each moving body (``tests/oracles/dynamics.py``):

    Σ F = Σ m·a_S,     Σ M_S = Σ (z_S − z_O) × m·a_S + J·ε

summing the returned pair reactions (``+`` on the second body of a pair, ``−`` on the
first; a prismatic pair's normal force at its point plus its moment; a revolute pair's
friction moment), the balancing load of the drive, the external forces and moments and
gravity, read from the model data.  ``a_S`` and ``ε`` are seven-point central finite
differences in time of the centre positions and body angles over a fine model (360
positions a turn, error O(h⁶) ≈ 1e-11 relative).  Residuals must stay below 1e-9 of the
largest force on the mechanism (moments: of that force times the mechanism's size).

Models: the bundled offset slider-crank (gravity, a piston force), the same with friction
in every pair, a crank and slotted lever (a prismatic pair between two moving bodies on a
turning guide, with and without friction), random crank-rocker four-bars (transmission
angle kept within 35°..145°, so that the finite differences converge) and offset
slider-cranks (hypothesis), and a landing-gear leg raised by a hydraulic cylinder (a
length drive between two bodies of the cylinder, a prismatic pair between them, a leg
with two lumped masses, non-periodic poly345 motion).  The whole mechanism is checked
too: the ground reactions plus the external loads accelerate the common centre of mass,
Σ F_ext = M·a_C.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from oracles.dynamic_models import (
    crank_turn,
    dynamics,
    example,
    four_bars,
    landing_gear,
    quick_return,
    slider_cranks,
)
from oracles.dynamics import (
    external_forces,
    lumped_masses,
    newton_euler,
    point_z,
    rows,
    second_derivative,
    time_step,
)

RTOL = 1e-9
#: Random geometry reaches 35° transmission angles, where the 7-point finite-difference
#: accelerations of the oracle are only good to ~1e-9; the residual bound allows for that.
RANDOM_RTOL = 1e-8
N = 360  # positions per turn for the finite differences


def assert_balanced(d, data, *, periodic: bool = True, rtol: float = RTOL) -> None:
    for r in newton_euler(d, data, periodic=periodic):
        ok = np.isfinite(r.force)
        assert ok.sum() > 0
        f_err = np.abs(r.force[ok]).max() / r.force_scale
        m_err = np.abs(r.moment[ok]).max() / r.moment_scale
        assert f_err <= rtol, f"body {r.body}: Σ F − m a off by {f_err:.2e} of the largest force"
        assert m_err <= rtol, f"body {r.body}: Σ M − J ε off by {m_err:.2e} (relative)"


def fine_example(**changes) -> dict:
    return example("crank_slider_dynamics.yaml", positions=N, arguments=crank_turn(N),
                   **changes)


def test_example_slider_crank_every_body_balances():
    data = fine_example()
    d = dynamics(data)
    assert not d.forces.singular.any()
    assert_balanced(d, data)


def test_example_with_friction_in_every_pair_balances():
    """Friction enters each pair's force (prismatic) or as a moment (revolute): the
    returned reactions still balance every body."""
    data = fine_example(friction={"coefficient": 0.1, "radius": 0.01, "length": 0.05})
    d = dynamics(data)
    assert d.forces.iterations > 1
    assert all(np.abs(r.friction).max() > 0 for r in d.forces.reactions.values())
    assert_balanced(d, data)


def test_example_explicit_joint_points_are_the_pins():
    """The reactions are reported at the pins the file names: O, A = crank pin, B."""
    data = fine_example()
    d = dynamics(data)
    r = d.forces.reactions
    np.testing.assert_allclose(r["O"].point.z, 0.0, atol=1e-15)
    np.testing.assert_allclose(r["A"].point.z, 0.05 * np.exp(1j * d.kinematics.value("a1")),
                               rtol=0, atol=1e-15)
    np.testing.assert_allclose(r["B"].point.z, d.kinematics.value("r3") - 0.01j,
                               rtol=0, atol=1e-15)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=four_bars(n=N, min_transmission=35.0))
def test_random_four_bar_every_body_balances(data):
    d = dynamics(data)
    assert not d.kinematics.broken.any() and not d.forces.singular.any()
    assert_balanced(d, data, rtol=RANDOM_RTOL)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=slider_cranks(n=N))
def test_random_slider_crank_every_body_balances(data):
    d = dynamics(data)
    assert not d.kinematics.broken.any() and not d.forces.singular.any()
    assert_balanced(d, data, rtol=RANDOM_RTOL)


@pytest.mark.parametrize("friction", [None, {"coefficient": 0.1, "radius": 0.01,
                                              "length": 0.04}], ids=["ideal", "friction"])
def test_slotted_lever_every_body_balances(friction):
    """A prismatic pair between two moving bodies on a turning guide (Coriolis in the
    block's motion relative to the lever), with and without friction."""
    data = quick_return(N, friction=friction)
    d = dynamics(data)
    assert [p.kind for p in d.mechanism.pairs].count("prismatic") == 1
    assert_balanced(d, data)


def test_hydraulic_leg_with_length_drive_balances():
    data = landing_gear()
    d = dynamics(data)
    kinds = sorted(p.kind for p in d.mechanism.pairs)
    assert kinds == ["prismatic", "revolute", "revolute", "revolute"]
    assert [dr.kind for dr in d.mechanism.drives] == ["length"]
    assert_balanced(d, data, periodic=False)


def test_whole_mechanism_momentum():
    """Σ (ground reactions on the bodies) + Σ external forces + gravity = M·a_C, with a_C
    the finite difference of the common centre of mass, which itself is the mass-weighted
    mean of the centres taken from the data."""
    data = fine_example()
    d = dynamics(data)
    masses = lumped_masses(data, d)
    total = sum(m.mass for m in masses)
    center = sum(m.mass * point_z(d, m.center) for m in masses) / total
    np.testing.assert_allclose(d.center.z, center, rtol=0, atol=1e-15)
    assert abs(d.mechanism.total_mass - total) <= 1e-15 * total

    take = rows(d, periodic=True)
    a_c = second_derivative(center, time_step(d), periodic=True)
    on_mechanism = sum(f.force for f in external_forces(data, d))
    for r in d.forces.reactions.values():
        first, second = r.pair.bodies
        if first == 0:
            on_mechanism = on_mechanism + r.force
        elif second == 0:
            on_mechanism = on_mechanism - r.force
    scale = max(np.abs(r.force).max() for r in d.forces.reactions.values())
    err = np.abs(on_mechanism[take] - total * a_c).max()
    assert err <= RTOL * scale, f"Σ F_ext − M a_C = {err:.3e} N (scale {scale:.3e} N)"
