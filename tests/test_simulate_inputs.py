"""Motion in time of a machine with several inputs (``mechloop.simulate`` on a two-input
model): Lagrange's equations from the kinematic analogs.

The references are independent of mechloop's equations: the five-bar of
``tests/oracles/multibody.py`` (four free bodies, five pins, Newton–Euler's equations
with the pin forces as Lagrange multipliers, integrated separately), its energy
``T + V`` written from its own coordinates, finite differences of the mass matrix
(the Christoffel form of the velocity terms) and of that potential (the generalized
forces), and the closed-form geometry of the five-bar's break.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from oracles import multibody
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.dynamics.lagrange import LagrangeMachine
from mechloop.dynamics.motors import RPM
from mechloop.dynamics.simulate_inputs import NEAR_BREAK, InputsSimulation
from mechloop.errors import ModelError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

# the five-bar: cranks a, d, links b, c, pivots O = (0, 0) and D = (g, 0) (m); the cranks
# are short beside the links, so it assembles at every pair of crank angles
A, B, C, D, G = 0.05, 0.22, 0.25, 0.05, 0.15
MASSES = (1.0, 0.6, 0.8, 1.2)
INERTIAS = (0.02, 0.6 * B * B / 12, 0.8 * C * C / 12, 0.02)  # cranks carry flywheels
Q0 = (90.0, 60.0)  # deg, the cranks at position 0
SPRING = (300.0, 0.15)  # N/m, free length m: from (g/2, 0) to B


def five_bar(*, spring: bool = True, gravity: bool = True, simulate=None, lengths=None,
             extra=None) -> mechloop.Model:
    """The mechloop model of the oracle's five-bar (SI units)."""
    a, b, c, d, g = lengths or (A, B, C, D, G)
    data = {"positions": 12, "time": {"rpm": 60},
            "arguments": {1: {"table": {0: Q0[0], 12: Q0[0] + 360}},
                          2: {"table": {0: Q0[1], 12: Q0[1] + 360}}},
            "vectors": {1: {"r": a, "a": {"argument": 1}}, 2: {"r": b, "a": "function"},
                        3: {"r": c, "a": "function"},
                        4: {"r": d, "a": {"argument": 2, "offset": 180}},
                        5: {"r": g, "a": 180}},
            "contours": [{"vectors": [1, 2, 3, 4, 5], "variant": 1}],
            "bodies": {i + 1: {"vectors": [i + 1], "mass": MASSES[i], "inertia": INERTIAS[i],
                               "center": {"vector": i + 1, "share": 0.5}} for i in range(4)},
            **(extra or {})}
    if gravity:
        data["gravity"] = {"g": 9.81}
    if spring:
        data["springs"] = [{"bodies": [0, 2], "ends": [{"vector": 5, "share": 0.5},
                                                       {"head": 2}],
                            "stiffness": SPRING[0], "free_length": SPRING[1]}]
    if simulate is not None:
        data["simulate"] = simulate
    return mechloop.Model.from_dict(data)


def oracle(*, spring: bool = True, gravity: bool = True, lengths=None) -> multibody.FiveBar:
    a, b, c, d, g = lengths or (A, B, C, D, G)
    return multibody.FiveBar(a, b, c, d, g, tuple(multibody.Body(m, j) for m, j in
                                                  zip(MASSES, INERTIAS, strict=True)),
                             up=True, g_acc=9.81 if gravity else 0.0,
                             stiffness=SPRING[0] if spring else 0.0, free=SPRING[1])


def _machine(model: mechloop.Model) -> LagrangeMachine:
    dyn = mechloop.solve_dynamics(model)
    machine = LagrangeMachine(model, dyn.mechanism, (1, 2))
    q0 = np.radians(Q0)
    machine.kinematics.orient(machine.kinematics.at(q0, np.zeros(2)))
    return machine


def test_the_start_is_the_oracles_assembly():
    # variant 1 puts B where the oracle's up=True does
    res = mechloop.solve(five_bar())
    x, y = res.point([1, 2])
    fb = oracle()
    s = fb.start(*np.radians(Q0), 0.0, 0.0)
    assert np.allclose((x[0], y[0]), fb.point_b(s[:12]), atol=1e-13)


# ------------------------------------------------------------------ the equations' terms


def test_the_terms_against_the_christoffel_form_and_the_potential():
    # at a state with both cranks turning: M symmetric and T = q'Mq'/2 = the oracle's
    # kinetic energy; h = (dM/dt) q' - 1/2 q'(dM/dq)q' by central differences of M
    # (error ~1e-9 here); Q = -dV/dq by central differences of the oracle's potential;
    # the loads' power P = Q.q'; S states in one call equal one by one
    machine = _machine(five_bar())
    fb = oracle()
    q, w = np.radians([110.0, 35.0]), np.array([2.0, -3.0])
    terms = machine.terms(0.0, q, w)
    mass = terms.mass[0]
    assert np.allclose(mass, mass.T, rtol=0, atol=1e-15)
    assert np.all(np.linalg.eigvalsh(mass) > 0)
    state = fb.start(*q, *w)
    potential = fb.energy(np.concatenate([state[:12], np.zeros(12)]))
    kinetic = fb.energy(state) - potential
    assert terms.kinetic[0] == pytest.approx(kinetic, rel=1e-12)
    assert 0.5 * w @ mass @ w == pytest.approx(kinetic, rel=1e-12)
    h = 1e-5
    steps = np.eye(2) * h
    d_mass = [(machine.terms(0.0, q + e, w).mass[0] - machine.terms(0.0, q - e, w).mass[0])
              / (2 * h) for e in steps]
    christoffel = sum(d_mass[k] * w[k] for k in range(2)) @ w \
        - 0.5 * np.array([w @ d_mass[i] @ w for i in range(2)])
    assert np.allclose(terms.bias[0], christoffel, rtol=1e-7, atol=1e-9)

    def v(qq):
        s = fb.start(*qq, 0.0, 0.0)
        return fb.energy(s)

    grad = np.array([(v(q + e) - v(q - e)) / (2 * h) for e in steps])
    assert np.allclose(terms.force[0], -grad, rtol=1e-7, atol=1e-8)
    assert terms.power[0] == pytest.approx(terms.force[0] @ w, rel=1e-12)
    many = machine.terms(np.zeros(3), np.array([q, q + 0.3, q - 0.2]),
                         np.array([w, -w, 2 * w]))
    assert np.allclose(many.mass[0], mass, rtol=1e-14, atol=0)
    assert np.allclose(many.bias[0], terms.bias[0], rtol=1e-14, atol=0)
    one = machine.terms(0.0, q + 0.3, -w)
    assert np.allclose(many.force[1], one.force[0], rtol=1e-14, atol=0)


# ---------------------------------------------------------------- the multibody oracle


def test_simulate_agrees_with_the_multibody_oracle():
    # gravity, the spring and a linear motor on each crank, from rest: Lagrange's
    # equations of the two inputs (mechloop) against Newton-Euler's equations of the four
    # bodies with the pin forces as multipliers (24 states, Baumgarte-stabilised).  Both
    # at rtol 1e-10: they agree to 1e-7 (measured ~1e-9 rad, 1e-8 rad/s)
    stall, idle = (3.0, 2.0), (60.0, 45.0)
    model = five_bar(simulate={
        "duration": 0.4, "friction": False, "rtol": 1e-10, "atol": 1e-12,
        "motors": {k + 1: {"linear": {"stall_torque": stall[k], "idle_rpm": idle[k]}}
                   for k in range(2)}})
    sim = mechloop.simulate(model)
    assert isinstance(sim, InputsSimulation) and sim.end.kind == "duration"
    t = np.linspace(0.0, 0.4, 41)

    def moments(_t, w1, w4):
        return tuple(stall[k] * (1 - w / (idle[k] * RPM)) for k, w in enumerate((w1, w4)))

    cranks, _, drift = multibody.simulate_five_bar(
        oracle(), moments, (*np.radians(Q0), 0.0, 0.0), t, rtol=1e-10)
    assert drift < 1e-9
    q, w = sim.state(t)
    assert np.ptp(q[0]) > 2.0 and np.ptp(q[1]) > 0.5  # both cranks move well
    assert np.abs(q - cranks[:2]).max() < 1e-7
    assert np.abs(w - cranks[2:]).max() < 1e-7 * np.abs(cranks[2:]).max()
    assert np.abs(sim.balance).max() < 1e-8


# --------------------------------------------------------------------------- energy


def test_a_conservative_five_bar_keeps_its_energy_for_many_seconds():
    # gravity and the spring, no motor, no damper: T + V from the oracle's own geometry
    # (closed-form assembly, velocities from its constraints) stays constant while the
    # cranks swing and turn for 2 s (each crank through more than 4 rad); the integrator keeps
    # each step within rtol 1e-9 of the state, so about S·rtol over S steps is allowed
    # (measured: 2e-9 of the swing of T)
    model = five_bar(simulate={"duration": 2.0, "friction": False, "rtol": 1e-9,
                               "atol": 1e-11, "every": 0.05,
                               "start": {1: {"rpm": 40}, 2: {"rpm": -25}}})
    sim = mechloop.simulate(model)
    fb = oracle()
    energy = np.array([fb.energy(fb.start(*sim.q[:, k], *sim.omega[:, k]))
                       for k in range(sim.time.size)])
    swing = np.ptp(sim.kinetic_energy)
    assert swing > 0.3 * sim.kinetic_energy.max()  # energy moves between T and V
    assert np.ptp(sim.q[0]) > 4.0 and np.ptp(sim.q[1]) > 4.0  # the cranks swing wide
    assert np.abs(energy - energy[0]).max() < 10 * sim.steps * 1e-9 * swing
    assert np.abs(sim.balance).max() < 10 * sim.steps * 1e-9 * swing


# --------------------------------------------------------------------------- events


def test_the_run_ends_before_the_chain_breaks():
    # links of 0.25 m between cranks of 0.1 m on pivots 0.15 m apart: released at
    # 60/120 deg under gravity, the cranks open until A, B, E line up (|AE| = b + c) and
    # the chain would break.  The run ends there with a 'chain break ahead' event, at an
    # assembled state whose links' sine is 1e-3 (sin² = NEAR_BREAK), from the
    # closed-form geometry
    lengths = (0.1, 0.25, 0.25, 0.1, 0.15)
    model = five_bar(spring=False, lengths=lengths, extra={
        "arguments": {1: {"table": {0: 60, 12: 420}}, 2: {"table": {0: 120, 12: 480}}}},
        simulate={"duration": 1.0, "friction": False})
    sim = mechloop.simulate(model)
    end = sim.end
    assert end.kind == "chain break ahead" and end.detail == "contour 1"
    assert 0.05 < end.t < 0.2
    a, b, c, d, g = lengths
    pa = a * np.exp(1j * end.q[0])
    pe = g + d * np.exp(1j * end.q[1])
    span = abs(pe - pa)
    cos_b = (b * b + span * span - c * c) / (2 * b * span)  # the angle at A
    angle_ab = math.acos(cos_b)
    cos_c = (c * c + span * span - b * b) / (2 * c * span)  # the angle at E
    between = angle_ab + math.acos(cos_c)  # the links' directions differ by this
    assert math.sin(between) ** 2 == pytest.approx(NEAR_BREAK, rel=1e-6)
    assert np.all(np.isfinite(sim.q)) and np.all(np.isfinite(sim.epsilon))
    assert sim.time[-1] == end.t


def test_stop_at_an_angle_and_rest():
    # a crank reaching its stop_at ends the run there; a damper in each crank's pivot
    # brings the five-bar to rest: the run ends once both cranks are slower than rest_rpm
    model = five_bar(simulate={"duration": 2.0, "friction": False, "stop_at": {2: 45},
                               "start": {1: {"rpm": 30}, 2: {"rpm": -30}}})
    sim = mechloop.simulate(model)
    assert sim.end.kind == "angle" and sim.end.detail == "input 2"
    assert sim.end.q[1] == pytest.approx(math.radians(45), abs=1e-12)
    assert sim.state(sim.end.t)[0][1, 0] == pytest.approx(math.radians(45), abs=1e-9)
    dampers = [{"bodies": [0, 1], "coefficient": 2.0}, {"bodies": [0, 4], "coefficient": 2.0}]
    model = five_bar(extra={"dampers": dampers},
                     simulate={"duration": 10.0, "friction": False, "rest_rpm": 5.0,
                               "rtol": 1e-6, "atol": 1e-8})
    sim = mechloop.simulate(model)
    assert sim.end.kind == "stopped" and sim.end.t < 10.0
    assert np.abs(sim.end.omega).max() == pytest.approx(5.0 * RPM, rel=1e-6)
    assert np.all(np.abs(sim.omega[:, :-1]).max(axis=0)[sim.time[:-1] > 0.1] > 5.0 * RPM)
    # the dampers' work took the energy: T - T0 = W_loads (no motor)
    assert sim.load_work[-1] == pytest.approx(sim.kinetic_energy[-1],
                                              abs=1e-4 * np.abs(sim.load_work).max())


# ------------------------------------------------------------------ settings and errors


def test_the_per_input_forms_on_a_one_input_model_are_the_plain_ones():
    # the slider-crank of test_simulate.py (one input, argument 1): motors: {1: ...},
    # start: {1: ...} and stop_at: {1: ...} run exactly as motor:, start: and stop_at:
    from test_simulate import _slider_crank

    model = _slider_crank(constant_inertia=True)
    plain = mechloop.simulate(model, {"motor": {"constant": 2.0}, "duration": 1.0,
                                      "start": {"angle": 30, "rpm": 10}, "stop_at": 400})
    keyed = mechloop.simulate(model, {"motors": {1: {"constant": 2.0}}, "duration": 1.0,
                                      "start": {1: {"angle": 30, "rpm": 10}},
                                      "stop_at": {1: 400}})
    assert plain.end.kind == "angle"
    assert np.array_equal(plain.q, keyed.q) and np.array_equal(plain.omega, keyed.omega)
    with pytest.raises(ModelError) as info:
        mechloop.simulate(model, {"motors": {2: {"constant": 2.0}}, "duration": 1.0})
    assert info.value.problems[0].path == ("simulate", "motors", 2)
    with pytest.raises(ModelError) as info:
        mechloop.simulate(model, {"rest_rpm": 5, "duration": 1.0})
    assert info.value.problems[0].path == ("simulate", "rest_rpm")


def test_model_problems_are_located():
    base = {"duration": 1.0, "friction": False}
    cases = [({"cycles": 3}, ("simulate", "cycles")),
             ({"motor": {"constant": 1}}, ("simulate", "motor")),
             ({"motors": {3: {"constant": 1}}}, ("simulate", "motors", 3)),
             ({"start": {"rpm": 10}}, ("simulate", "start")),
             ({"stop_at": 30}, ("simulate", "stop_at")),
             ({"friction": True, "reverse": True}, ("simulate", "reverse"))]
    for extra, path in cases:
        with pytest.raises(ModelError) as info:
            mechloop.simulate(five_bar(), {**base, **extra})
        assert path in [p.path for p in info.value.problems], extra
    with pytest.raises(ModelError) as info:  # a load over the positions
        mechloop.simulate(five_bar(extra={"moments": [{"body": 1, "value": {
            "table": {0: 0, 12: 1}}}]}), base)
    assert info.value.problems[0].path == ("moments", 0, "value")
    with pytest.raises(ModelError) as info:  # a start that does not assemble
        mechloop.simulate(five_bar(lengths=(0.1, 0.1, 0.1, 0.1, 0.15)), {
            **base, "start": {1: {"angle": 180}, 2: {"angle": 0}}})
    assert "does not assemble" in str(info.value)


# ------------------------------------------------------------------- output and views


def test_the_view_and_the_table():
    from mechloop.views.motion import plot_simulation

    model = five_bar(simulate={"duration": 0.3, "friction": False, "every": 0.01,
                               "motors": {1: {"constant": 1.0}}})
    sim = mechloop.simulate(model)
    figure = plot_simulation(sim)
    lines = {line.get_gid(): line for ax in figure.axes for line in ax.get_lines()
             if line.get_gid()}
    assert {"q1", "q2", "omega1", "omega2", "epsilon1", "epsilon2", "phase1",
            "phase2"} <= lines.keys()
    assert np.allclose(lines["omega2"].get_ydata(), sim.omega[1] / RPM)
    frame = sim.to_frame()
    assert list(frame.columns[:6]) == ["time [s]", "q1 [deg]", "omega1 [rad/s]", "n1 [rpm]",
                                       "epsilon1 [rad/s^2]", "M_motor1 [N*m]"]
    assert np.allclose(frame["M_motor1 [N*m]"], 1.0) and np.allclose(frame["M_motor2 [N*m]"], 0)
    assert frame.notna().all().all() and len(frame) == 31
    # epsilon at the rows is the derivative of the speed: central differences of the
    # dense output (error ~1e-6 here)
    t = sim.time[5:-5]
    h = 1e-4
    slope = (sim.state(t + h)[1] - sim.state(t - h)[1]) / (2 * h)
    assert np.allclose(sim.epsilon[:, 5:-5], slope, rtol=1e-5, atol=1e-5)


def test_cli_runs_the_example(tmp_path: Path):
    table, figure = tmp_path / "run.csv", tmp_path / "run.png"
    result = CliRunner().invoke(app, ["simulate", str(EXAMPLES / "two_input_five_bar.yaml"),
                                      "-o", str(table), "--plot", str(figure),
                                      "--duration", "0.8"])  # past the motor's switch-off
    assert result.exit_code == 0, result.output
    assert "2 inputs" in result.output and "motor off (input 2)" in result.output
    import pandas as pd

    frame = pd.read_csv(table)
    assert {"q1 [deg]", "q2 [deg]", "n2 [rpm]", "balance [J]"} <= set(frame.columns)
    assert frame["balance [J]"].abs().max() < 1e-5
    assert figure.stat().st_size > 10_000
