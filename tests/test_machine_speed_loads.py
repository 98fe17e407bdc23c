"""``machine:`` takes the loads that depend on the speed (dampers) at the steady cycle's own
speed ω(q), by a fixed point over ω(q), so that the steady cycle the motion in time reaches
is ``machine:``'s (issue 13).  The reference is the integrated motion (solve_ivp over
several cycles), which ``machine:`` (the energy equation by quadrature and bisection)
does not compute; the tolerance is 1e-6 relative on ω at every position, ten times the
integrator's drift measured over two cycles at rtol 1e-10 (about 1e-7)."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

import mechloop
from mechloop.dynamics import machine
from mechloop.dynamics.motors import RPM
from mechloop.dynamics.simulate import simulate

TIGHT = {"rtol": 1e-10, "atol": 1e-12}


def _damped(delta: float | None = None, coefficient: float = 20.0) -> mechloop.Model:
    """The offset slider-crank of tests/test_state_loads.py (crank 0.05 m, rod 0.2 m,
    600 rpm nominal) with a damper from the crank's pivot O to the slider."""
    bodies = {1: {"vectors": [1], "mass": 2, "inertia": 0.01,
                  "center": {"vector": 1, "share": 0.5}},
              2: {"vectors": [2], "mass": 1.5, "inertia": 0.006,
                  "center": {"vector": 2, "share": 0.3}},
              3: {"vectors": [3], "mass": 1.2, "center": {"tail": 3}}}
    return mechloop.Model.from_dict({
        "positions": 72, "arguments": {1: {"table": {0: 0, 72: 360}}},
        "time": {"rpm": 600},
        "vectors": {1: {"r": 0.05, "a": {"argument": 1}}, 2: {"r": 0.2, "a": "function"},
                    3: {"r": "function", "a": 180}, 4: {"r": 0.01, "a": 90}},
        "contours": [{"vectors": [1, 2, 3, 4]}], "bodies": bodies,
        "dampers": [{"name": "D", "bodies": [0, 3], "ends": [{"tail": 1}, {"tail": 3}],
                     "coefficient": coefficient}],
        "machine": {} if delta is None else {"delta": delta}})


class TestTheSteadyCycleIsTheSimulatedOne:
    @pytest.mark.parametrize("delta", [None, 0.05])
    def test_simulate_runs_machines_cycle(self, delta):
        # started on machine:'s cycle with machine:'s constant moment (and flywheel), the
        # simulation runs that cycle, cycle after cycle
        model = _damped(delta)
        dyn = mechloop.solve_dynamics(model)
        cycle = dyn.cycle
        steady = cycle.motion if delta is None else cycle.with_flywheel
        assert 1 < cycle.iterations < 50
        sim = simulate(model, {"motor": {"constant": cycle.constant_load},
                               "flywheel": None if delta is None else "machine",
                               "start": {"rpm": steady.omega[0] / RPM}, "cycles": 2,
                               **TIGHT}, dynamics=dyn)
        for k in range(2):
            _, t, omega = sim.cycle_profile(k)
            np.testing.assert_allclose(omega, steady.omega, rtol=1e-6, atol=0)
            np.testing.assert_allclose(t - t[0], steady.time, rtol=1e-6, atol=1e-12)
        # the damper is taken at the speed of the cycle, not at the nominal 600 rpm: the
        # loads as the force analysis at 600 rpm gives them would need another moment,
        # and the speed over the cycle they give misses the simulated one by far more
        nominal = machine.steady_driving_moment(sim.machine.q, dyn.reduced.load)
        assert abs(nominal - cycle.constant_load) > 1e-2 * abs(cycle.constant_load)
        inertia = dyn.reduced.inertia + (0.0 if delta is None else cycle.flywheel)
        old = machine.machine_motion(sim.machine.q, inertia, dyn.reduced.load + nominal,
                                     omega_mean=cycle.omega_mean)
        assert np.max(np.abs(old.omega / steady.omega - 1)) > 1e-4
        # the cycle's own loads: the damper's -c (dl/dq)^2 omega at the cycle's speed (taken
        # at the last iterate's speed, within SETTLE_RTOL = 1e-11 of the final one)
        state = sim.machine.state
        np.testing.assert_allclose(
            cycle.reduced_load,
            sim.machine.load + state.moment(sim.machine.q, steady.omega), rtol=1e-9,
            atol=1e-9 * np.abs(cycle.reduced_load).max())


def test_with_a_flywheel_the_bare_machine_is_its_own_steady_cycle():
    dyn = mechloop.solve_dynamics(_damped(0.05))
    bare = mechloop.solve_dynamics(_damped(None)).cycle
    cycle = dyn.cycle
    assert cycle.bare_constant_load == pytest.approx(bare.constant_load, rel=1e-9)
    np.testing.assert_allclose(cycle.motion.omega, bare.motion.omega, rtol=1e-9)
    assert cycle.constant_load != pytest.approx(bare.constant_load, rel=1e-3)
    # the flywheel still gives the wanted delta on the machine with it
    assert cycle.with_flywheel.delta == pytest.approx(0.05, rel=1e-6)


def test_a_fixed_point_that_does_not_settle_is_a_located_error(monkeypatch, tmp_path):
    import yaml

    from mechloop.cli import app

    monkeypatch.setattr(machine, "SETTLE_ITERATIONS", 2)
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.solve_dynamics(_damped(0.05))
    assert info.value.problems[0].path == ("machine",)
    assert "did not settle" in str(info.value)
    path = tmp_path / "damped.yaml"
    path.write_text(yaml.safe_dump(_damped(0.05).model_dump(mode="json", exclude_none=True)))
    result = CliRunner().invoke(app, ["energy", str(path)])
    assert result.exit_code == 2 and "did not settle" in result.output
    assert "Traceback" not in result.output


def test_without_speed_dependent_loads_nothing_changes():
    model = mechloop.load_model(
        __import__("pathlib").Path(__file__).resolve().parents[1]
        / "examples" / "single_cylinder_engine.yaml")
    cycle = mechloop.solve_dynamics(model).cycle
    assert cycle.iterations == 0 and cycle.bare_constant_load is None
