"""Motion in time (``mechloop.simulate``): closed forms, energy, the machine's steady cycle.

Every check compares the integrated motion with something it does not compute itself: a
start-up and a run-down against their closed forms, the kinetic energy of a machine with
no loads against its start value, the steady cycle against :mod:`mechloop.dynamics.machine`
(the energy equation by quadrature and bisection, not an ODE).  Tolerances are tied to the
integrator's: solve_ivp keeps each step's error within about ``rtol`` (relative), so over
a run of ``S`` steps the relative error is at most about ``S·rtol``; :func:`_bound` allows
``10·S·rtol`` (energy is quadratic in the speed, and the step's error is an estimate;
measured: 1 to 4 ``S·rtol`` with DOP853).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.dynamics import machine as machine_motion
from mechloop.dynamics.motors import RPM, kloss
from mechloop.dynamics.simulate import simulate
from mechloop.errors import ModelError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TIGHT = {"rtol": 1e-10, "atol": 1e-12}


def _bound(sim) -> float:
    """The relative error a run may have: 10 × steps × rtol."""
    return 10 * sim.steps * sim.settings.rtol


def _slider_crank(*, constant_inertia: bool = False, moments=(), forces=(), gravity=False,
                  extra=None, turn: float = 360, crank: float = 0.05) -> mechloop.Model:
    """The offset slider-crank of examples/crank_slider_dynamics.yaml (crank 0.05 m, rod
    0.2 m) at 600 rpm nominal; with ``constant_inertia`` only the crank has inertia (0.05
    kg·m² about its pivot), so J_red is constant."""
    if constant_inertia:
        bodies = {1: {"vectors": [1], "mass": 0, "inertia": 0.05, "center": {"tail": 1}},
                  2: {"vectors": [2]}, 3: {"vectors": [3]}}
    else:
        bodies = {1: {"vectors": [1], "mass": 2, "inertia": 0.01,
                      "center": {"vector": 1, "share": 0.5}},
                  2: {"vectors": [2], "mass": 1.5, "inertia": 0.006,
                      "center": {"vector": 2, "share": 0.3}},
                  3: {"vectors": [3], "mass": 1.2, "center": {"tail": 3}}}
    data = {"positions": 72, "time": {"rpm": 600},
            "arguments": {1: {"table": {0: 0, 72: turn}}},
            "vectors": {1: {"r": crank, "a": {"argument": 1}}, 2: {"r": 0.2, "a": "function"},
                        3: {"r": "function", "a": 180}, 4: {"r": 0.01, "a": 90}},
            "contours": [{"vectors": [1, 2, 3, 4]}], "bodies": bodies,
            "moments": list(moments), "forces": list(forces), **(extra or {})}
    if gravity:
        data["gravity"] = {"g": 9.81}
    return mechloop.Model.from_dict(data)


# ----------------------------------------------------------------------- closed forms


def test_start_up_under_a_constant_moment_is_uniformly_accelerated():
    # J = 0.05 kg*m^2 constant, M = 2 N*m: omega = M t / J, q = M t^2 / (2 J)
    model = _slider_crank(constant_inertia=True, moments=[{"body": 1, "value": 2.0}])
    sim = simulate(model, {"duration": 2.0, **TIGHT})
    assert np.ptp(sim.inertia) < 1e-12
    assert sim.end.kind == "duration" and sim.end.t == pytest.approx(2.0, abs=1e-12)
    assert np.allclose(sim.omega, 2.0 * sim.time / 0.05, rtol=1e-9, atol=1e-9)
    assert np.allclose(sim.q, 2.0 * sim.time**2 / (2 * 0.05), rtol=1e-9, atol=1e-9)
    assert np.allclose(sim.epsilon, 2.0 / 0.05, rtol=1e-9)


def test_start_up_under_a_linear_motor_through_a_gear_is_exponential():
    # motor M = M0 (1 - n_m/n0) through ratio i with rotor J_r: on the input
    # J = 0.05 + i^2 J_r, omega -> omega_0 / i with time constant J omega_0 / (i^2 M0)
    m0, n0, i, j_r = 8.0, 1500.0, 3.0, 0.002
    model = _slider_crank(constant_inertia=True)
    sim = simulate(model, {"motor": {"linear": {"stall_torque": m0, "idle_rpm": n0},
                                     "ratio": i, "inertia": j_r},
                           "duration": 3.0, **TIGHT})
    j = 0.05 + i * i * j_r
    w_end, tau = n0 * RPM / i, j * n0 * RPM / (i * i * m0)
    assert np.allclose(sim.inertia, j, rtol=1e-12)
    assert np.allclose(sim.omega, w_end * (1 - np.exp(-sim.time / tau)), rtol=1e-8,
                       atol=1e-8)
    # the motor's work equals the kinetic energy gained (no loads)
    assert sim.motor_work[-1] == pytest.approx(0.5 * j * sim.omega[-1] ** 2, rel=1e-8)


def test_kloss_curve_passes_through_the_rated_point_and_peaks_at_the_breakdown_torque():
    torque = kloss(20.0, 1430 * RPM, 1500 * RPM, 2.3)
    assert float(torque(1430 * RPM)) == pytest.approx(20.0, rel=1e-12)
    assert float(torque(1500 * RPM)) == 0.0
    speeds = np.linspace(0.0, 1500 * RPM, 200_001)
    assert torque(speeds).max() == pytest.approx(2.3 * 20.0, rel=1e-8)
    s_k = (1 - 1430 / 1500) * (2.3 + math.sqrt(2.3**2 - 1))
    assert speeds[np.argmax(torque(speeds))] == pytest.approx((1 - s_k) * 1500 * RPM,
                                                              abs=2 * speeds[1])


def test_run_down_stops_where_the_resistance_has_taken_the_kinetic_energy():
    # constant resisting moment M_r, no motor: (1/2) J(q0) w0^2 = M_r (q_stop - q0),
    # whatever J does in between
    m_r, n0 = 3.0, 300.0
    model = _slider_crank(moments=[{"body": 1, "value": -m_r}])
    dyn = mechloop.solve_dynamics(model)
    sim = simulate(model, {"start": {"rpm": n0}, "duration": 60, **TIGHT}, dynamics=dyn)
    assert np.ptp(dyn.reduced.inertia) > 0.1 * dyn.reduced.inertia.mean()  # J varies
    assert sim.end.kind == "stopped" and sim.end.omega == 0.0
    expected = 0.5 * dyn.reduced.inertia[0] * (n0 * RPM) ** 2 / m_r
    assert sim.end.q == pytest.approx(expected, rel=_bound(sim))
    assert sim.omega[-1] == 0.0 and np.all(sim.omega[:-1] > 0)


def test_run_down_after_the_motor_is_switched_off():
    # a constant motor moment M_m until t_off, then coasting against M_r: the machine
    # stops where M_r (q_stop - q0) = M_m (q_off - q0), the motor's work
    m_m, m_r = 5.0, 2.0
    model = _slider_crank(moments=[{"body": 1, "value": -m_r}])
    sim = simulate(model, {"motor": {"constant": m_m, "off_at": 0.5}, "duration": 60,
                           **TIGHT})
    kinds = [e.kind for e in sim.events]
    assert kinds == ["start", "motor off", "stopped"]
    off = sim.events[1]
    assert off.t == pytest.approx(0.5, abs=1e-12)
    assert sim.end.q > off.q + 2 * math.pi  # it coasts for more than a turn
    assert sim.end.q == pytest.approx(m_m * off.q / m_r, rel=_bound(sim))
    assert sim.motor_work[-1] == pytest.approx(m_m * off.q, rel=_bound(sim))


# ----------------------------------------------------------------------------- energy


def test_energy_is_conserved_without_loads_over_many_cycles():
    # no motor, no loads, no gravity: (1/2) J(q) w^2 stays constant while J varies by a
    # third over every turn, for 20 cycles
    model = _slider_crank()
    sim = simulate(model, {"start": {"rpm": 600}, "cycles": 20, **TIGHT})
    assert sim.end.kind == "cycles" and sim.cycle_time.size == 20
    assert np.ptp(sim.inertia) > 0.3 * sim.inertia.min()
    assert np.ptp(sim.omega) > 0.1 * sim.omega.mean()  # the speed swings with J
    energy = sim.kinetic_energy
    assert np.abs(energy / energy[0] - 1).max() < _bound(sim) < 1e-4
    # every cycle takes the same time
    assert np.ptp(sim.cycle_time) < _bound(sim) * sim.cycle_time[0]
    assert np.abs(sim.balance).max() < _bound(sim) * energy[0]


def test_gravity_alone_conserves_the_total_energy():
    # gravity is a load over positions: the kinetic energy plus its potential (minus the
    # load's work) is constant — the balance column
    model = _slider_crank(gravity=True)
    sim = simulate(model, {"start": {"rpm": 120}, "cycles": 10, **TIGHT})
    assert np.ptp(sim.load_work) > 0.1 * sim.kinetic_energy[0]  # gravity matters
    # a step's error in q (up to rtol of a cycle's angle L) is one in energy of M·δq: the
    # scale of the energy's error is T + L·max|M|
    scale = sim.kinetic_energy.max() + sim.machine.period * np.abs(sim.load_moment).max()
    assert np.abs(sim.balance).max() < _bound(sim) * scale


# ------------------------------------------------------------------------ steady cycle


def test_the_steady_cycle_of_machine_is_a_periodic_motion_of_the_simulation():
    # the engine with machine:'s flywheel and a consumer of machine:'s constant moment,
    # started at machine:'s speed at position 0, runs machine:'s cycle cycle after cycle:
    # omega(q) at the positions and the period agree with the energy equation's
    model = mechloop.load_model(EXAMPLES / "single_cylinder_engine.yaml")
    dyn = mechloop.solve_dynamics(model)
    cycle = dyn.cycle
    steady = cycle.with_flywheel
    sim = simulate(model, {"motor": {"constant": cycle.constant_load},
                           "flywheel": "machine", "friction": True,
                           "start": {"rpm": steady.omega[0] / RPM}, "cycles": 4, **TIGHT},
                   dynamics=dyn)
    for k in range(4):
        _, t, omega = sim.cycle_profile(k)
        assert np.allclose(omega, steady.omega, rtol=_bound(sim), atol=0)
        assert np.allclose(t - t[0], steady.time, rtol=_bound(sim), atol=1e-12)
    assert np.allclose(sim.cycle_time, steady.time[-1], rtol=_bound(sim), atol=0)
    assert _bound(sim) < 1e-5


def test_start_up_reaches_the_cycle_the_energy_equation_gives_for_the_motor():
    # the compressor from rest under its induction motor: once steady (mean speed
    # changing by < 1e-7 a cycle, well above the integrator's noise of about 1e-8 a cycle
    # at rtol 1e-10), omega(q) over the last cycle is the steady motion that
    # machine.machine_motion finds for the loads plus the motor's moment at that speed,
    # and the motor's mean moment over the cycle is machine:'s constant moment
    model = mechloop.load_model(EXAMPLES / "compressor_startup.yaml")
    dyn = mechloop.solve_dynamics(model)
    settings = model.simulate.model_copy(update={"steady": 1e-7, **TIGHT})
    sim = simulate(model, settings, dynamics=dyn)
    assert sim.end.kind == "steady" and sim.steady_time == sim.end.t
    changes = np.abs(np.diff(sim.cycle_speed)) / sim.cycle_speed[1:]
    assert changes[-1] < 1e-7 and np.all(changes[:-1] >= 1e-7)
    assert np.all(changes[:-2] > changes[1:-1])  # the approach is monotonic,
    assert np.all(np.diff(sim.cycle_speed) > 0)  # from below (no overshoot)
    _, t, omega = sim.cycle_profile()
    drive = sim.motor.torque(omega)
    # the cycle returns to its start (to the steady tolerance): read it as periodic
    assert abs(drive[-1] - drive[0]) < 1e-5 * abs(drive[0])
    drive[-1] = drive[0]
    red = sim.machine
    total = red.load + drive
    residual = machine_motion.steady_driving_moment(red.q, total)
    assert abs(residual) < 1e-5 * abs(drive).mean()
    reference = machine_motion.machine_motion(
        red.q, red.inertia, total + residual,
        omega_mean=(omega.max() + omega.min()) / 2)
    assert np.allclose(omega, reference.omega, rtol=1e-6, atol=0)
    assert np.ptp(omega) > 0.01 * omega.mean()  # a real fluctuation is compared
    mean_drive = float(np.diff(sim.motor_work_at([t[0], t[-1]]))[0]) / red.period
    assert mean_drive == pytest.approx(dyn.cycle.constant_load, rel=1e-6)


# ------------------------------------------------------------------- events and output


def test_stop_at_an_angle_and_rows_every_cycle():
    model = _slider_crank(constant_inertia=True, moments=[{"body": 1, "value": 2.0}])
    sim = simulate(model, {"stop_at": "1000 deg", "duration": 10, "every": "cycle",
                           **TIGHT})
    assert sim.end.kind == "angle"
    assert sim.end.q == pytest.approx(math.radians(1000), rel=1e-10)
    # q = M t^2 / (2 J) reaches the angle at t = sqrt(2 J q / M)
    assert sim.end.t == pytest.approx(math.sqrt(2 * 0.05 * math.radians(1000) / 2.0),
                                      rel=1e-9)
    # rows at 0, at the end of each of the two whole cycles, and at the end
    assert np.allclose(sim.q[1:3], [2 * math.pi, 4 * math.pi], rtol=1e-10)
    assert sim.time.size == 4


def test_a_range_that_is_not_a_whole_turn_ends_the_run_where_it_ends():
    # crank over 0..180 deg only: J is constant (it returns), yet the model is a range,
    # not a cycle; q = M t^2 / (2 J) reaches pi at t = sqrt(2 J pi / M)
    model = _slider_crank(constant_inertia=True, moments=[{"body": 1, "value": 2.0}],
                          turn=180)
    sim = simulate(model, {"duration": 10, **TIGHT})
    assert not sim.machine.periodic
    assert sim.end.kind == "range" and sim.end.q == pytest.approx(math.pi, rel=1e-10)
    assert sim.end.t == pytest.approx(math.sqrt(2 * 0.05 * math.pi / 2.0), rel=1e-9)
    assert sim.cycle_time.size == 0


def test_a_start_inside_the_cycle_under_a_load_table_that_jumps_at_its_end():
    # a moment on the crank rising from 0 to 3 N*m over the turn and back to 0 at its end
    # (the table does not return: a jump at every 360 deg); J = 0.05 constant; from rest
    # at 90 deg the kinetic energy is the work A(q) - A(90 deg), with
    # A(q) = 3·pi·k + 3 x^2 / (4 pi) for q = 2 pi k + x
    model = _slider_crank(constant_inertia=True,
                          moments=[{"body": 1, "value": {"table": {0: 0, 72: 3}}}])
    sim = simulate(model, {"start": {"angle": 90}, "duration": 3, **TIGHT})

    def work(q):
        k, x = np.divmod(q, 2 * np.pi)
        return 3 * np.pi * k + 3 * x**2 / (4 * np.pi)

    assert sim.q[-1] > 4 * 2 * np.pi  # through several jumps
    expected = work(sim.q) - work(np.pi / 2)
    assert np.allclose(0.5 * 0.05 * sim.omega**2, expected, rtol=_bound(sim),
                       atol=_bound(sim) * expected.max())
    # the first, partial turn (90..360 deg) is not a cycle: the cycles start at 360 deg
    assert sim.state(sim.cycle_start[0])[0][0] == pytest.approx(2 * np.pi, rel=1e-12)


def test_a_motor_too_weak_to_start_stops_at_once():
    model = _slider_crank(constant_inertia=True, moments=[{"body": 1, "value": -2.0}])
    sim = simulate(model, {"motor": {"constant": 1.0}, "duration": 1})
    assert sim.end.kind == "stopped" and sim.end.t < 1e-9


def test_model_problems_are_located():
    model = _slider_crank()
    with pytest.raises(ModelError) as info:
        simulate(model)
    assert info.value.problems[0].path == ("simulate",)
    with pytest.raises(ModelError) as info:
        simulate(model, {"flywheel": "machine", "duration": 1})
    assert info.value.problems[0].path == ("simulate", "flywheel")
    with pytest.raises(ModelError) as info:
        _slider_crank(extra={"simulate": {"motor": {"constant": 1, "linear": {
            "stall_torque": 1, "idle_rpm": 10}}, "duration": 1}})
    assert "exactly one characteristic" in str(info.value)
    assert info.value.problems[0].path[:2] == ("simulate", "motor")
    with pytest.raises(ModelError) as info:
        simulate(model, {"start": {"angle": 90}, "stop_at": 45, "duration": 1})
    assert info.value.problems[0].path == ("simulate",)
    assert "must lie ahead of the start" in str(info.value)
    # a crank longer than the rod: the chain breaks where 0.01 + 0.25 sin(q) = 0.2 (the
    # rod cannot reach the guide); the run stops before it (tests/test_simulate_breaks.py)
    broken = simulate(_slider_crank(crank=0.25), {"duration": 1, "start": {"rpm": 60}})
    assert broken.end.kind == "chain break ahead"
    assert broken.end.at == pytest.approx(math.asin(0.19 / 0.25), abs=1e-9)
    with pytest.raises(ModelError) as info:  # settings given in code are checked alike
        simulate(model, {"duration": -1})
    assert info.value.problems[0].path == ("simulate", "duration")


def test_cli_writes_the_time_series_and_the_figure(tmp_path: Path):
    table, figure = tmp_path / "run.csv", tmp_path / "run.png"
    result = CliRunner().invoke(app, ["simulate", str(EXAMPLES / "compressor_startup.yaml"),
                                      "-o", str(table), "--plot", str(figure)])
    assert result.exit_code == 0, result.output
    assert "time to steady state" in result.output
    import pandas as pd

    frame = pd.read_csv(table)
    assert list(frame.columns[:4]) == ["time [s]", "q [deg]", "omega [rad/s]", "n [rpm]"]
    assert frame["time [s]"].is_monotonic_increasing
    assert np.allclose(frame["n [rpm]"], frame["omega [rad/s]"] / RPM)
    assert figure.stat().st_size > 10_000
    bad = CliRunner().invoke(app, ["simulate", str(EXAMPLES / "crank_slider_dynamics.yaml")])
    assert bad.exit_code == 2 and "simulate" in bad.output


def test_compressor_start_up_figures():
    # the figures docs/motion.md "Motion in time" quotes for examples/compressor_startup.yaml
    model = mechloop.load_model(EXAMPLES / "compressor_startup.yaml")
    sim = simulate(model)
    assert sim.end.kind == "steady"
    assert round(sim.steady_time, 2) == 2.72
    assert sim.cycle_time.size == 14
    _, _, omega = sim.cycle_profile()
    mean = sim.cycle_speed[-1]
    assert round(mean / RPM, 1) == 488.1
    assert round(float((omega.max() - omega.min()) / mean), 4) == 0.0192
    assert round(float(sim.kinetic_energy[-1])) == 2799
    assert np.abs(sim.balance).max() < 0.02
    # the first cycle starts from rest: its profile is found there too
    q, t, omega = sim.cycle_profile(0)
    assert np.abs(sim.state(t)[0] - q).max() < 1e-9 and omega[0] == 0.0
    assert np.all(np.diff(t) > 0)


def test_simulate_agrees_with_the_multibody_oracle():
    # the slider-crank with masses, gravity and a slider force, started from rest by a
    # linear motor: the reduced equation (mechloop) against Newton-Euler's equations of the
    # three bodies with the constraint forces as Lagrange multipliers (tests/oracles/
    # multibody.py, 18 states).  The reduced machine reads J and M between the 72
    # positions by splines (J to about 1e-6 of itself here): the states agree to 5e-6
    # (measured: 8e-7 rad in the angle, 4e-7 of the speed).
    from oracles import multibody

    stall, idle = 30.0, 1500 * RPM
    model = _slider_crank(gravity=True, forces=[{"body": 3, "at": {"tail": 3},
                                                 "value": 200, "angle": 180}])
    sim = simulate(model, {"motor": {"linear": {"stall_torque": stall, "idle_rpm": 1500}},
                           "duration": 0.4, **TIGHT})
    assert sim.machine.interpolation.inertia_error < 1e-6 * sim.machine.inertia.min()
    oracle = multibody.SliderCrank(
        a=0.05, b=0.2, e=0.01, g=9.81, push=200.0,
        crank=multibody.Body(2.0, 0.01, 0.5), rod=multibody.Body(1.5, 0.006, 0.3),
        slider=multibody.Body(1.2, 0.0))
    t = np.linspace(0.0, 0.4, 201)
    theta, omega, drift = multibody.simulate(
        oracle, lambda _t, w: stall * (1 - w / idle), 0.0, 0.0, t, rtol=1e-10)
    assert drift < 1e-9
    q, w = sim.state(t)
    assert q[-1] > 4 * 2 * math.pi  # several turns, through the whole speed range
    assert np.allclose(q, theta, rtol=5e-6, atol=5e-6)
    assert np.allclose(w, omega, rtol=5e-6, atol=5e-6 * omega.max())


def test_the_view_draws_the_run():
    from mechloop.views.motion import plot_simulation

    model = _slider_crank(constant_inertia=True, moments=[{"body": 1, "value": 2.0}])
    sim = simulate(model, {"duration": 1.0})
    figure = plot_simulation(sim)
    lines = {line.get_gid(): line for ax in figure.axes for line in ax.get_lines()
             if line.get_gid()}
    assert {"q", "omega", "epsilon", "phase"} <= lines.keys()
    assert np.allclose(lines["omega"].get_ydata(), sim.omega / RPM)
    assert np.allclose(lines["q"].get_ydata(), sim.q / (2 * np.pi))
    # the phase portrait: the speed over the angle within the cycle, one line a cycle
    phase = [line for ax in figure.axes for line in ax.get_lines() if line.get_gid() == "phase"]
    assert len(phase) == int(sim.q[-1] // (2 * np.pi)) + 1
    for turn, line in enumerate(phase):
        x = line.get_xdata()
        assert 0 <= x.min() and x.max() < 360
        q = np.radians(x) + 2 * np.pi * turn  # omega = sqrt(2 M q / J) from rest
        assert np.allclose(line.get_ydata() * RPM, np.sqrt(2 * 2.0 * q / 0.05), rtol=1e-6)


def test_the_motors_doctest():
    import doctest

    from mechloop.dynamics import motors

    assert doctest.testmod(motors, raise_on_error=True).attempted > 0


def test_friction_enters_as_machine_takes_it():
    # the compressor of crank_slider_friction.yaml (friction 0.1 in every pair) with a
    # machine: section: its loads include the friction reduced at the nominal 3000 rpm,
    # -friction_loss / (dq/dt), as machine: takes it; started on machine:'s cycle with
    # machine:'s constant moment, the simulation runs that cycle
    import yaml

    data = yaml.safe_load((EXAMPLES / "crank_slider_friction.yaml").read_text())
    data["machine"] = {}
    model = mechloop.Model.from_dict(data)
    dyn = mechloop.solve_dynamics(model)
    steady = dyn.cycle.motion
    sim = simulate(model, {"motor": {"constant": dyn.cycle.constant_load},
                           "start": {"rpm": steady.omega[0] / RPM}, "cycles": 2, **TIGHT},
                   dynamics=dyn)
    nominal = 3000 * RPM
    assert dyn.forces.friction_loss.max() > 10.0  # friction matters here
    assert np.allclose(sim.machine.load, dyn.reduced.load - dyn.forces.friction_loss / nominal,
                       rtol=1e-12, atol=1e-12)
    _, _, omega = sim.cycle_profile(1)
    assert np.allclose(omega, steady.omega, rtol=_bound(sim), atol=0)
    without = simulate(model, {"friction": False, "cycles": 1, "start": {"rpm": 3000}},
                       dynamics=dyn)
    assert np.array_equal(without.machine.load, dyn.reduced.load)


def test_a_pendulum_released_from_rest_swings_with_its_closed_form_period():
    # only the crank has mass: 2 kg at r = 0.025 m from the pivot (its middle) and 0.001
    # kg*m^2 about its centre; gravity. Released from rest horizontal (q = 0) it swings
    # down and back (reverse: true) as a physical pendulum of amplitude 90 deg:
    # T = 4 sqrt(I / (m g r)) K(sin^2 45 deg), I = J + m r^2, turning at q = -180 deg
    from scipy.special import ellipk

    m, r, j, g = 2.0, 0.025, 0.001, 9.81
    bodies = {1: {"vectors": [1], "mass": m, "inertia": j,
                  "center": {"vector": 1, "share": 0.5}},
              2: {"vectors": [2]}, 3: {"vectors": [3]}}
    model = _slider_crank(gravity=True, extra={"bodies": bodies})
    inertia = j + m * r * r
    period = 4 * math.sqrt(inertia / (m * g * r)) * float(ellipk(0.5))
    sim = simulate(model, {"reverse": True, "duration": 2.2 * period, **TIGHT})
    assert sim.end.kind == "duration" and sim.cycle_time.size == 0
    q, w = sim.state([period / 2, period, 1.5 * period, 2 * period])
    assert np.allclose(q, [-math.pi, 0.0, -math.pi, 0.0], atol=1e-6)
    assert np.allclose(w, 0.0, atol=1e-5 * math.sqrt(2 * m * g * r / inertia))
    assert sim.q.min() >= -math.pi - 1e-6 and sim.q.max() <= 1e-6  # never beyond
    assert np.abs(sim.balance).max() < _bound(sim) * m * g * r * 2 * math.pi
    without = simulate(model, {"duration": period, **TIGHT})
    assert without.end.kind == "stopped" and without.end.t < 1e-9  # it would turn back
