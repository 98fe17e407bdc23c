"""Inertia forces and moments of the bodies (the ``Fi``/``Mi`` columns)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import mechloop

ROOT = Path(__file__).resolve().parents[1]


def test_whole_mechanism_is_in_dynamic_equilibrium_with_the_ground():
    """d'Alembert for the mechanism as a whole: external forces + inertia forces + the
    forces the ground exerts through its pairs = 0 (internal reactions cancel)."""
    model = mechloop.load_model(ROOT / "examples/crank_slider_dynamics.yaml")
    dyn = mechloop.solve_dynamics(model)
    total = sum(force for force, _ in dyn.inertia.values())
    total = total + sum(load.force for load in dyn.loads.forces)
    for reaction in dyn.forces.reactions.values():
        first, second = reaction.pair.bodies
        if first == 0:
            total = total + reaction.force
        elif second == 0:
            total = total - reaction.force
    scale = max(np.abs(r.force).max() for r in dyn.forces.reactions.values())
    assert np.abs(total).max() <= 1e-9 * scale


def test_inertia_loads_of_the_slider_crank_bodies():
    """Slider: −m3·ẍ_B along the guide; rod: −J2·ε2 about its own centre; crank with its
    centre on the rotation axis at a steady speed: no inertia moment about its centre."""
    model = mechloop.load_model(ROOT / "examples/crank_slider_dynamics.yaml")
    dyn = mechloop.solve_dynamics(model)
    kin = dyn.kinematics
    force3, moment3 = dyn.inertia[3]
    np.testing.assert_allclose(moment3, 0.0, atol=1e-12)  # a slider does not turn
    np.testing.assert_allclose(force3.real, -1.2 * kin.accel("r3"), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(force3.imag, 0.0, atol=1e-9)
    np.testing.assert_allclose(dyn.inertia[2][1], -0.006 * kin.accel("a2"), rtol=1e-12,
                               atol=1e-12)
    np.testing.assert_allclose(dyn.inertia[1][1], 0.0, atol=1e-12)
    frame = dyn.to_frame()
    np.testing.assert_array_equal(frame["Fi3_x [N]"], force3.real)
    np.testing.assert_array_equal(frame["Mi2 [N*m]"], dyn.inertia[2][1])
