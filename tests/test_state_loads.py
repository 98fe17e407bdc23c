"""Loads that depend on the state: springs, dampers, loads over a parameter's value and
loads that act only while a parameter moves one way — in the kinetostatics, the energy
table and the motion in time.

The mechanism is the offset slider-crank of examples/crank_slider_dynamics.yaml (crank
``r1`` = 0.05 m, rod ``r2`` = 0.2 m, offset ``e`` = 0.01 m), whose slider sits at
``x(q) = r1·cos q + √(r2² − (r1·sin q + e)²)``, ``y = −e`` — the closed form every check
compares with (its derivative by the chain rule, written out below).  A spring or damper
runs from the crank pivot O (the origin, ground) to the slider B, so its length is
``l(q) = √(x² + e²)``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

import mechloop
from mechloop.dynamics.analysis import solve_dynamics
from mechloop.dynamics.population import solve_population
from mechloop.dynamics.simulate import simulate
from mechloop.errors import ModelError

R1, R2, E = 0.05, 0.2, 0.01
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
TIGHT = {"rtol": 1e-10, "atol": 1e-12}
SPRING_ENDS = [{"tail": 1}, {"tail": 3}]  # O (ground) and B (slider)


def _x(q):
    """The slider's x (m) at crank angle q (rad)."""
    return R1 * np.cos(q) + np.sqrt(R2**2 - (R1 * np.sin(q) + E) ** 2)


def _dx(q):
    """dx/dq (m/rad)."""
    s = R1 * np.sin(q) + E
    return -R1 * np.sin(q) - s * R1 * np.cos(q) / np.sqrt(R2**2 - s * s)


def _length(q):
    return np.hypot(_x(q), E)


def _dlength(q):
    return _x(q) * _dx(q) / _length(q)


def _model(*, positions: int = 72, turn: float = 360, time: bool = True,
           constant_inertia: bool = False, **extra) -> mechloop.Model:
    if constant_inertia:  # only the crank: 0.05 kg*m^2 about its pivot, J_red constant
        bodies = {1: {"vectors": [1], "inertia": 0.05, "center": {"tail": 1}},
                  2: {"vectors": [2]}, 3: {"vectors": [3]}}
    else:
        bodies = {1: {"vectors": [1], "mass": 2, "inertia": 0.01,
                      "center": {"vector": 1, "share": 0.5}},
                  2: {"vectors": [2], "mass": 1.5, "inertia": 0.006,
                      "center": {"vector": 2, "share": 0.3}},
                  3: {"vectors": [3], "mass": 1.2, "center": {"tail": 3}}}
    data = {"positions": positions, "arguments": {1: {"table": {0: 0, positions: turn}}},
            "vectors": {1: {"r": R1, "a": {"argument": 1}}, 2: {"r": R2, "a": "function"},
                        3: {"r": "function", "a": 180}, 4: {"r": E, "a": 90}},
            "contours": [{"vectors": [1, 2, 3, 4]}], "bodies": bodies, **extra}
    if time:
        data["time"] = {"rpm": 600}
    return mechloop.Model.from_dict(data)


def _row(dyn, name: str):
    return next(r for r in dyn.summary.rows if r.name == name)


# ------------------------------------------------------------------------------ springs


def test_spring_force_balancing_moment_and_work_follow_the_geometry():
    # a linear spring k = 2 kN/m, free length 0.15 m, preload 10 N from O to the slider,
    # over half a turn without model time (static: the balancing moment is the spring's
    # T·dl/dq alone, T = k (l − l0) + P)
    k, l0, p = 2000.0, 0.15, 10.0
    spring = {"bodies": [0, 3], "ends": SPRING_ENDS, "stiffness": k, "free_length": l0,
              "preload": p, "name": "S"}
    works = []
    for n in (90, 360):
        dyn = solve_dynamics(_model(positions=n, turn=180, time=False, springs=[spring]))
        q = dyn.kinematics.arguments[1]
        tension = k * (_length(q) - l0) + p
        np.testing.assert_allclose(dyn.forces.balancing[1], tension * _dlength(q),
                                   rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(dyn.balancing_vp[1], dyn.forces.balancing[1],
                                   rtol=1e-9, atol=1e-9)
        # the spring's force on the slider, −T·u (u from O to B)
        force = next(f for f in dyn.loads.forces if f.name == "S").force
        u = (_x(q) - 1j * E) / _length(q)
        np.testing.assert_allclose(force, -tension * u, rtol=1e-12, atol=1e-9)
        row = _row(dyn, "S")
        l1, l2 = _length(0.0), _length(math.pi)
        exact = -(0.5 * k * ((l2 - l0) ** 2 - (l1 - l0) ** 2) + p * (l2 - l1))
        works.append(abs(row.positive_work + row.negative_work - exact) / abs(exact))
    # the energy table integrates the power by the trapezoidal rule: second order
    assert works[1] < 1e-5 and works[1] < works[0] / 12


def test_a_tabulated_spring_is_its_table():
    # the table [length, tension] of the linear spring above gives the same loads
    linear = {"bodies": [0, 3], "ends": SPRING_ENDS, "stiffness": 2000, "free_length": 0.15}
    table = {"bodies": [0, 3], "ends": SPRING_ENDS,
             "table": [[0.1, -100.0], [0.2, 100.0], [0.3, 300.0]]}
    a = solve_dynamics(_model(springs=[linear]))
    b = solve_dynamics(_model(springs=[table]))
    np.testing.assert_allclose(b.forces.balancing[1], a.forces.balancing[1], rtol=1e-12,
                               atol=1e-9)


def test_a_spring_machine_keeps_its_total_energy_over_many_cycles():
    # no motor, no friction, no gravity: the kinetic energy plus the spring's ½k(l − l0)²
    # (from the closed-form geometry, not from the simulation) is constant over 10 cycles
    k, l0 = 2000.0, 0.15
    spring = {"bodies": [0, 3], "ends": SPRING_ENDS, "stiffness": k, "free_length": l0}
    model = _model(positions=360, springs=[spring])
    sim = simulate(model, {"start": {"rpm": 600}, "cycles": 10, **TIGHT})
    assert sim.end.kind == "cycles"
    potential = 0.5 * k * (_length(sim.q) - l0) ** 2
    assert np.ptp(potential) > 0.1 * sim.kinetic_energy[0]  # the spring matters
    total = sim.kinetic_energy + potential
    # the integrator's share is 10·steps·rtol; the splines of J and M between the 360
    # positions miss by about 1e-9 of the energy (fourth order)
    assert np.abs(total / total[0] - 1).max() < 10 * sim.steps * 1e-10 + 1e-8
    assert sim.state_work is None  # a spring depends on the positions only


# ------------------------------------------------------------------------------ dampers


def test_a_damper_dissipates_the_integral_of_c_v_squared_in_the_energy_table():
    # a damper c = 50 N*s/m from O to the slider at a steady 600 rpm: its power at every
    # position is −c·l̇², l̇ = dl/dq·ω, and its work over the cycle −∫ c l̇² dt
    c, w = 50.0, 600 * math.pi / 30
    damper = {"bodies": [0, 3], "ends": SPRING_ENDS, "coefficient": c, "name": "D"}
    dyn = solve_dynamics(_model(positions=720, dampers=[damper]))
    q = dyn.kinematics.arguments[1]
    np.testing.assert_allclose(dyn.powers["D"], -c * (_dlength(q) * w) ** 2, rtol=1e-9)
    exact = -quad(lambda t: c * (_dlength(w * t) * w) ** 2, 0, 2 * math.pi / w,
                  epsabs=0, epsrel=1e-12, limit=200)[0]
    row = _row(dyn, "D")
    assert row.positive_work == 0
    assert row.negative_work == pytest.approx(exact, rel=1e-5)  # trapezoid, 720 steps
    np.testing.assert_allclose(dyn.balancing_vp[1], dyn.forces.balancing[1], rtol=1e-9,
                               atol=1e-9)


def test_a_joint_damper_slows_a_constant_inertia_exponentially():
    # only the crank turns with J = 0.05 kg*m^2; a damper c = 0.02 N*m*s/rad in its pivot:
    # J ω' = −c ω, so ω = ω0 exp(−c t / J) and the damper took T0 − T
    c, j, w0 = 0.02, 0.05, 600 * math.pi / 30
    model = _model(constant_inertia=True, dampers=[{"bodies": [0, 1], "coefficient": c}])
    sim = simulate(model, {"start": {"rpm": 600}, "duration": 3.0, **TIGHT})
    t = np.array([0.5, 1.0, 2.0, 3.0])
    _, w = sim.state(t)
    np.testing.assert_allclose(w, w0 * np.exp(-c * t / j), rtol=1e-8)
    np.testing.assert_allclose(sim.state_work, sim.kinetic_energy - sim.kinetic_energy[0],
                               rtol=1e-8, atol=1e-8 * sim.kinetic_energy[0])


def test_a_damper_in_simulate_takes_the_integral_of_c_v_squared():
    # the damper O–slider on the full slider-crank coasting from 600 rpm: its work on the
    # way is −∫ c (l'(q) ω)² dt along the simulated motion (quadrature over the dense
    # output, l' from the closed form), and the energy balance holds
    c = 20.0
    damper = {"bodies": [0, 3], "ends": SPRING_ENDS, "coefficient": c}
    sim = simulate(_model(positions=360, dampers=[damper]),
                   {"start": {"rpm": 600}, "duration": 0.5, **TIGHT})
    assert sim.kinetic_energy[-1] < 0.8 * sim.kinetic_energy[0]  # the damper matters

    def power(t):
        q, w = sim.state(t)
        return -c * (_dlength(q[0]) * w[0]) ** 2

    exact = quad(power, 0, 0.5, epsabs=0, epsrel=1e-10, limit=500)[0]
    assert sim.state_work[-1] == pytest.approx(exact, rel=1e-6)
    assert np.abs(sim.balance).max() < 1e-6 * sim.kinetic_energy[0]


# ------------------------------------------------------------- loads with a sign of rate


def test_a_force_on_one_stroke_only_does_the_hand_computed_work():
    # 500 N on the slider pushing +X, acting only while x falls (r3's rate negative):
    # against the motion over the whole stroke, work −F·(x_max − x_min) per cycle; the
    # same force acting always does no net work
    f = 500.0
    force = {"name": "P", "body": 3, "at": {"tail": 3}, "value": f, "angle": 0,
             "when": {"rate_of": "r3", "sign": "negative"}}
    stroke = math.sqrt((R1 + R2) ** 2 - E**2) - math.sqrt((R2 - R1) ** 2 - E**2)
    dyn = solve_dynamics(_model(positions=720, forces=[force]))
    q = dyn.kinematics.arguments[1]
    acts = _dx(q) < 0
    np.testing.assert_array_equal(np.abs(dyn.loads.forces[0].force) == f, acts)
    row = _row(dyn, "P")
    assert row.positive_work == 0
    assert row.negative_work == pytest.approx(-f * stroke, rel=1e-4)
    always = solve_dynamics(_model(positions=720, forces=[{**force, "when": None}]))
    assert _row(always, "P").positive_work + _row(always, "P").negative_work == \
        pytest.approx(0.0, abs=1e-9 * f * stroke)
    np.testing.assert_allclose(dyn.balancing_vp[1], dyn.forces.balancing[1], rtol=1e-9,
                               atol=1e-9)
    # in the motion in time the force takes F·stroke every cycle
    sim = simulate(_model(positions=720, forces=[force]),
                   {"start": {"rpm": 600}, "cycles": 3, "every": "cycle", "flywheel": 1,
                    **TIGHT})
    assert sim.end.kind == "cycles"
    np.testing.assert_allclose(np.diff(sim.load_work), -f * stroke, rtol=1e-6)
    assert np.abs(sim.balance).max() < 1e-6 * sim.kinetic_energy[0]


def test_a_load_over_a_parameter_value_reads_its_table_at_the_state():
    # a moment on the crank given as a table over the slider's position r3 (values with
    # their own unit, mm), acting while the slider moves away from the crank (x grows)
    table = [["150 mm", 0.0], ["200 mm", 40.0], ["260 mm", 10.0]]
    moment = {"name": "M", "body": 1, "value": {"of": "r3", "table": table},
              "when": {"rate_of": "r3", "sign": "positive"}}
    dyn = solve_dynamics(_model(moments=[moment]))
    q = dyn.kinematics.arguments[1]
    expected = np.where(_dx(q) > 0, np.interp(_x(q), [0.15, 0.2, 0.26], [0, 40, 10]), 0)
    assert 0 < np.count_nonzero(expected) < q.size
    np.testing.assert_allclose(dyn.loads.moments[0].moment, expected, rtol=1e-12,
                               atol=1e-12)
    # its power is M·ω of the crank
    np.testing.assert_allclose(dyn.powers["M"], expected * 600 * math.pi / 30, rtol=1e-12,
                               atol=1e-12)


# -------------------------------------------------------------- batches and model errors


def test_designs_with_state_loads_match_each_design_alone():
    spring = {"bodies": [0, 3], "ends": SPRING_ENDS, "stiffness": 2000, "free_length": 0.15}
    damper = {"bodies": [1, 2], "coefficient": 0.5}
    force = {"name": "P", "body": 3, "at": {"tail": 3}, "angle": 0,
             "value": {"of": "r3", "table": [[0.1, 0], [0.25, 800]]},
             "when": {"rate_of": "r3", "sign": "negative"}}
    model = _model(springs=[spring], dampers=[damper], forces=[force])
    r1 = np.array([0.04, 0.05, 0.06])
    ref = solve_dynamics(model)
    batch = solve_population(model, {"r1": r1}, ref.kinematics, ref.mechanism)
    n = model.positions + 1
    for d, value in enumerate(r1):
        data = model.model_dump(mode="json", exclude_defaults=True)
        data["vectors"]["1"]["r"] = float(value)
        alone = solve_dynamics(mechloop.Model.from_dict(data))
        got = batch.forces.balancing[1][d * n:(d + 1) * n]
        np.testing.assert_allclose(got, alone.forces.balancing[1], rtol=1e-9, atol=1e-9)
        for name, power in alone.powers.items():
            np.testing.assert_allclose(batch.powers[name][d * n:(d + 1) * n], power,
                                       rtol=1e-9, atol=1e-9)


def test_problems_of_state_loads_are_located():
    with pytest.raises(ModelError) as err:
        solve_dynamics(_model(time=False, dampers=[{"bodies": [0, 1], "coefficient": 1}],
                              forces=[{"body": 3, "at": {"tail": 3}, "value": 1,
                                       "when": {"rate_of": "r9", "sign": "positive"}}],
                              springs=[{"bodies": [0, 7], "ends": SPRING_ENDS,
                                        "stiffness": 1, "free_length": 0}]))
    paths = {p.path for p in err.value.problems}
    assert paths == {("dampers", 0), ("forces", 0, "when", "rate_of"),
                     ("springs", 0, "bodies")}
    with pytest.raises(ModelError) as err:  # the crank pin A is not a point of the slider
        solve_dynamics(_model(springs=[{"bodies": [0, 3], "ends": [{"tail": 1}, {"head": 1}],
                                        "stiffness": 1, "free_length": 0}]))
    assert [p.path for p in err.value.problems] == [("springs", 0, "ends", 1)]
    with pytest.raises(ModelError):
        _model(springs=[{"bodies": [0, 3], "ends": SPRING_ENDS, "stiffness": 1}])
    with pytest.raises(ModelError):
        _model(dampers=[{"bodies": [0, 3], "coefficient": 1, "table": [[0, 0], [1, 1]]}])


# ------------------------------------------------------------------------------ examples


def test_shaper_cuts_on_the_working_stroke_only():
    # examples/shaper_cutting_stroke.yaml: the cutting force is a table over the ram's
    # position r6 acting while r6 falls.  Its work is −∫F dr6 over the working stroke,
    # the table's area (2 kN × (0.88 − 0.61 + 0.01) m), whatever the timing; the energy
    # table's trapezoid misses it by at most ΔF'·h²/8 at each of the table's 4 corners
    # (ΔF' = 2 kN / 10 mm, h the largest step of r6)
    import yaml

    data = yaml.safe_load((EXAMPLES / "shaper_cutting_stroke.yaml").read_text())
    data.update(positions=1440, arguments={1: {"table": {0: 0, 1440: 360}}})
    dyn = solve_dynamics(mechloop.Model.from_dict(data))
    kin = dyn.kinematics
    x, rate = kin.value("r6"), kin.rate("r6")
    force = next(f for f in dyn.loads.forces if f.name == "cutting").force
    np.testing.assert_allclose(force.real, np.where(
        rate < 0, np.interp(x, [0.60, 0.61, 0.88, 0.89], [0, 2000, 2000, 0]), 0.0),
        rtol=1e-12, atol=1e-9)
    assert np.all(force.imag == 0) and np.all(force[rate > 0] == 0)
    row = _row(dyn, "cutting")
    area = 2000 * (0.88 - 0.61 + 0.01)
    h = np.abs(np.diff(x)).max()
    assert row.positive_work == 0
    assert abs(row.negative_work + area) <= 4 * (2000 / 0.01) * h * h / 8
    # quick return: the working stroke takes 180 + 2·asin(0.4) deg of the crank's turn
    working = np.count_nonzero(rate[:-1] < 0) / 1440 * 360
    assert working == pytest.approx(180 + 2 * math.degrees(math.asin(0.4)), abs=0.5)
    np.testing.assert_allclose(dyn.balancing_vp[1], dyn.forces.balancing[1], rtol=1e-8,
                               atol=1e-8 * np.abs(dyn.forces.balancing[1]).max())


def test_spring_release_comes_to_rest_where_gravity_and_the_spring_balance():
    # examples/spring_release.yaml: crank 0.1 m with 3 kg at A, rod 0.3 m (0.5 kg, rod
    # inertia), slider 1 kg on a guide 0.02 m below O, spring O–slider 500 N/m free at
    # 0.25 m, damper 0.5 N*m*s/rad in O.  At rest the moment about O of gravity and the
    # spring, from the closed-form geometry, is zero; on the way the kinetic energy
    # plus both potentials fell by exactly the damper's work
    model = mechloop.load_model(EXAMPLES / "spring_release.yaml")
    sim = simulate(model)
    r1, r2, e = 0.1, 0.3, 0.02

    def x(q):
        return r1 * np.cos(q) + np.sqrt(r2**2 - (r1 * np.sin(q) + e) ** 2)

    def potential(q):
        spring = 0.5 * 500 * (np.hypot(x(q), e) - 0.25) ** 2
        return spring + 9.81 * (3 * r1 * np.sin(q) + 0.5 * (r1 * np.sin(q) - e) / 2)

    q_rest = sim.q[-1]
    slope = (potential(q_rest + 1e-6) - potential(q_rest - 1e-6)) / 2e-6  # −M(q) at rest
    assert abs(sim.omega[-1]) < 1e-6 and abs(slope) < 1e-5 * 9.81 * 3 * r1
    assert potential(q_rest + 0.05) > potential(q_rest) < potential(q_rest - 0.05)
    energy = sim.kinetic_energy + potential(sim.q)
    lost = energy[0] - energy
    scale = abs(potential(sim.q).max() - potential(sim.q).min())
    np.testing.assert_allclose(lost, -sim.state_work, rtol=0, atol=1e-5 * scale)
    assert -sim.state_work[-1] > 0.5 * scale  # the damper took most of the drop


def test_every_body_balances_with_springs_and_dampers():
    # Newton–Euler of every body (tests/oracles/dynamics.py) with the returned reactions
    # and balancing moment, the spring's and dampers' loads recomputed by the oracle from
    # the points' positions alone (speeds by finite differences in time)
    from oracles.dynamics import newton_euler

    data = {"positions": 360, "time": {"rpm": 600},
            "arguments": {1: {"table": {0: 0, 360: 360}}},
            "vectors": {1: {"r": R1, "a": {"argument": 1}}, 2: {"r": R2, "a": "function"},
                        3: {"r": "function", "a": 180}, 4: {"r": E, "a": 90}},
            "contours": [{"vectors": [1, 2, 3, 4]}],
            "bodies": {1: {"vectors": [1], "mass": 2, "inertia": 0.01,
                           "center": {"vector": 1, "share": 0.5}},
                       2: {"vectors": [2], "mass": 1.5, "inertia": 0.006,
                           "center": {"vector": 2, "share": 0.3}},
                       3: {"vectors": [3], "mass": 1.2, "center": {"tail": 3}}},
            "springs": [{"bodies": [2, 3], "ends": [{"vector": 2, "share": 0.5},
                                                    {"tail": 3}],
                         "stiffness": 3000, "free_length": 0.05, "preload": 20}],
            "dampers": [{"bodies": [0, 2], "ends": [{"tail": 1}, {"vector": 2, "share": 0.5}],
                         "coefficient": 40},
                        {"bodies": [1, 2], "coefficient": 0.3}],
            "gravity": {"g": 9.81}}
    d = solve_dynamics(mechloop.Model.from_dict(data))
    for r in newton_euler(d, data, periodic=True):
        assert np.abs(r.force).max() <= 1e-8 * r.force_scale, r.body
        assert np.abs(r.moment).max() <= 1e-8 * r.moment_scale, r.body


# -------------------------------------------------------------------------- expressions


def test_an_expression_of_the_rates_is_a_viscous_force():
    # −30·ẋ on the slider along +X (r3 is the slider's x): power −30·ẋ² at every position,
    # ẋ = dx/dq·ω from the closed form; and a moment 2·sin(t) on the crank (model time)
    force = {"name": "V", "body": 3, "at": {"tail": 3}, "angle": 0,
             "value": {"expression": "-30*dr3"}}
    moment = {"name": "T", "body": 1, "value": {"expression": "2*sin(t)", "unit": "N*m"}}
    dyn = solve_dynamics(_model(forces=[force], moments=[moment]))
    q, w = dyn.kinematics.arguments[1], 600 * math.pi / 30
    np.testing.assert_allclose(dyn.powers["V"], -30 * (_dx(q) * w) ** 2, rtol=1e-9)
    np.testing.assert_allclose(dyn.powers["T"], 2 * np.sin(q / w) * w, rtol=1e-12,
                               atol=1e-12)
    np.testing.assert_allclose(dyn.balancing_vp[1], dyn.forces.balancing[1], rtol=1e-9,
                               atol=1e-9)


def test_expressions_of_speed_and_time_in_the_motion_in_time():
    # a constant inertia J = 0.05 kg*m^2 under M = −c·ω + b·t (an expression of da1 and t):
    # J ω' = −c ω + b t, whose solution is
    # ω(t) = ω0 e^{−kt} + (b/c)(t − (1 − e^{−kt})/k), k = c/J
    c, b, j, w0 = 0.02, 0.3, 0.05, 600 * math.pi / 30
    moment = {"body": 1, "value": {"expression": f"-{c}*da1 + {b}*t"}}
    sim = simulate(_model(constant_inertia=True, moments=[moment]),
                   {"start": {"rpm": 600}, "duration": 3.0, **TIGHT})
    t = np.array([0.5, 1.5, 3.0])
    k = c / j
    exact = w0 * np.exp(-k * t) + b / c * (t - (1 - np.exp(-k * t)) / k)
    np.testing.assert_allclose(sim.state(t)[1], exact, rtol=1e-8)
    assert np.abs(sim.balance).max() < 1e-7 * sim.kinetic_energy.max()


def test_an_expression_cannot_run_code():
    for text in ("__import__('os').system('true')", "r1.real", "r1[0]", "open('x')",
                 "(lambda: 1)()", "sin(x=1)", "q9"):
        with pytest.raises(ModelError):
            _model(moments=[{"body": 1, "value": {"expression": text}}])
    with pytest.raises(ModelError) as err:
        solve_dynamics(_model(moments=[{"body": 1, "value": {"expression": "r9 + da1"}}]))
    assert err.value.problems[0].path == ("moments", 0, "value", "expression")


def test_a_tabulated_damper_reads_its_table_both_ways():
    # [speed, tension] for speeds ≥ 0, mirrored for negative ones, the end slope beyond:
    # power −T(l̇)·l̇ with T(v) = sign(v)·table(|v|), l̇ = dl/dq·ω from the closed form
    table = [[0.0, 0.0], [0.5, 10.0], [1.0, 12.0]]
    damper = {"bodies": [0, 3], "ends": SPRING_ENDS, "table": table, "name": "D"}
    dyn = solve_dynamics(_model(dampers=[damper]))
    q, w = dyn.kinematics.arguments[1], 600 * math.pi / 30
    v = _dlength(q) * w
    assert np.abs(v).max() > 1.0 and (v < 0).any() and (v > 0).any()  # beyond and both ways
    speed = np.abs(v)
    tension = np.sign(v) * np.where(speed > 1.0, 12.0 + 4.0 * (speed - 1.0),
                                    np.interp(speed, [0, 0.5, 1.0], [0, 10, 12]))
    np.testing.assert_allclose(dyn.powers["D"], -tension * v, rtol=1e-9, atol=1e-12)
