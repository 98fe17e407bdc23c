"""Machine motion of a solved model (``machine:``) against hand-derived answers.

A flywheel-like crank alone (J constant, centre of mass on the axis) driven through a
cycle while an external moment ``M0·sin φ`` acts on it: J_red = J, M_red = M0 sin φ, and
the energy equation ``½Jω² = E0 + M0(1 − cos φ)`` gives ``δ = 2·M0/(J·ω_m²)`` exactly
(ω_m = (ω_max + ω_min)/2), and the flywheel for δ: ``J_f = 2·M0/(δ·ω_m²) − J``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app

ROOT = Path(__file__).resolve().parents[1]


def crank_with_sine_moment(j: float, m0: float, rpm: float, n: int = 360,
                           delta: float | None = None) -> mechloop.Model:
    k = np.arange(n + 1)
    return mechloop.Model.from_dict({
        "units": {"length": "m", "angle": "deg"},
        "positions": n,
        "time": {"rpm": rpm},
        "arguments": {1: {"table": {0: 0, n: 360}}},
        "vectors": {1: {"r": 0.1, "a": {"argument": 1}},
                    2: {"r": "function", "a": "function"}},
        "contours": [{"vectors": [1, 2]}],
        "bodies": {1: {"vectors": [1], "mass": 0.0, "inertia": j, "center": {"tail": 1}}},
        "joints": {"O": {"bodies": [0, 1], "at": {"tail": 1}}},
        "moments": [{"body": 1, "value": {"table": (m0 * np.sin(2 * np.pi * k / n)).tolist()}}],
        "machine": {"delta": delta} if delta else {},
    })


@pytest.mark.parametrize("j, m0, rpm, wanted", [(0.5, 20.0, 600.0, 0.01),
                                                (2.0, 150.0, 1500.0, 0.002)])
def test_sine_moment_on_a_constant_inertia(j, m0, rpm, wanted):
    omega = 2 * math.pi * rpm / 60
    cycle = mechloop.solve_dynamics(crank_with_sine_moment(j, m0, rpm, delta=wanted)).cycle
    assert cycle.omega_mean == pytest.approx(omega, rel=1e-12)
    assert cycle.constant_load == pytest.approx(0.0, abs=1e-9 * m0)  # sin has no mean
    assert cycle.motion.delta == pytest.approx(2 * m0 / (j * omega**2), rel=1e-6)
    assert 2 * m0 / (j * omega**2) > wanted  # a flywheel is needed
    assert cycle.flywheel == pytest.approx(2 * m0 / (wanted * omega**2) - j, rel=1e-6)
    assert cycle.with_flywheel.delta == pytest.approx(wanted, rel=1e-9)
    # slowest where the moment has done the most negative work (φ = 0), fastest at φ = π
    omega_phi = cycle.motion.omega
    assert np.argmin(omega_phi) in (0, omega_phi.size - 1)
    assert np.argmax(omega_phi) == omega_phi.size // 2


def test_engine_constant_resisting_moment_is_the_mean_indicated_torque():
    """The constant load that balances the engine's cycle equals minus the gas work over
    the cycle (trapezoid of F·dx_B over the table, an independent quadrature) over 4π."""
    model = mechloop.load_model(ROOT / "examples/single_cylinder_engine.yaml")
    dyn = mechloop.solve_dynamics(model)
    gas = dyn.loads.forces[0]
    x_b = dyn.kinematics.value("r3")  # the piston pin is at x = r3 (guide along -X)
    force_x = gas.force.real
    work = float(np.sum(0.5 * (force_x[1:] + force_x[:-1]) * np.diff(x_b)))
    assert dyn.cycle.constant_load == pytest.approx(-work / (4 * math.pi), rel=2e-2)
    assert dyn.cycle.with_flywheel.delta == pytest.approx(0.0125, rel=1e-9)
    assert 0 < dyn.cycle.flywheel_approx
    assert dyn.cycle.flywheel == pytest.approx(dyn.cycle.flywheel_approx, rel=0.05)


def test_machine_motion_is_printed_and_written():
    path = ROOT / "examples/single_cylinder_engine.yaml"
    result = CliRunner().invoke(app, ["energy", str(path)])
    assert result.exit_code == 0, result.output
    assert "flywheel for δ = 0.0125" in result.output
    frame = mechloop.solve_dynamics(mechloop.load_model(path)).to_frame()
    assert {"omega [rad/s]", "omega_fw [rad/s]", "epsilon_fw [rad/s^2]"} <= set(frame.columns)


def test_machine_motion_needs_one_input_and_time():
    data = crank_with_sine_moment(0.5, 20.0, 600.0).model_dump(exclude_none=True)
    data.pop("time")
    data["machine"] = {"delta": 0.01}
    with pytest.raises(mechloop.ModelError, match="machine motion needs one input and a "
                       "model time"):
        mechloop.solve_dynamics(mechloop.Model.from_dict(data))


def test_no_flywheel_when_the_fluctuation_is_already_small():
    j, m0, rpm = 2.0, 150.0, 1500.0
    omega = 2 * math.pi * rpm / 60
    assert 2 * m0 / (j * omega**2) < 0.01
    cycle = mechloop.solve_dynamics(crank_with_sine_moment(j, m0, rpm, delta=0.01)).cycle
    assert cycle.flywheel == 0.0
