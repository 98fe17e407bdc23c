"""Friction in the kinematic pairs of the bundled slider-crank, against the laws the model
states and against the energy balance of a steady cycle.

The model: examples/crank_slider_dynamics.yaml with ``friction: {coefficient: 0.1, radius:
0.01, length: 0.05}`` for every pair, and a piston force that acts only on the return
stroke (a compressor: φ = 180°..360°, the slider moving away from the crank), so that the
force does useful (negative) work.

* The returned friction loads are the settled ones: a revolute pair's friction moment is
  f·ρ·|R| of its returned reaction and a prismatic pair's friction force is
  f·max(|N|, 2|M|/b) of its returned normal force and moment (≤ 1e-9); each opposes the
  relative motion, computed here from the crank angle and the slider's closed-form
  velocity; each pair's lost power is |friction|·|relative speed| ≥ 0.
* Energy over one steady cycle (trapezoidal work of every load, the summary table):
  A(M_bal) + A(P) + A(gravity) − A_friction = ΔT = 0 to 1e-6 of the driving work, and
  driving work = useful work + friction work; η = 1 − A_f/A_d.
* At every position the power of the loads (``d.powers``: M_bal, P, a moment on the rod,
  gravity) minus the friction loss is dT/dt, the seven-point finite difference in time of
  the returned kinetic energy over a fine model (360 positions a turn).
* Friction raises the peak of |M_bal|; the balancing moment by kinetostatics equals the one
  by virtual power plus the friction power over ω.
* A joint's own ``friction`` overrides the model's default.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from oracles.dynamic_models import crank_turn, dynamics, example
from oracles.dynamics import first_derivative, time_step

from mechloop import Model, solve_dynamics

F, RHO, B = 0.1, 0.01, 0.05
FRICTION = {"coefficient": F, "radius": RHO, "length": B}
R, L, E = 0.05, 0.2, 0.01
OMEGA = 2 * math.pi * 3000 / 60
RTOL = 1e-9
ENERGY_RTOL = 1e-6


def compressor(**changes) -> dict:
    """The example, the piston force on the return stroke only (positions 36..72 of 72)."""
    force = {"name": "P", "body": 3, "at": {"tail": 3}, "angle": 180.0,
             "value": {"table": {0: 0.0, 36: 0.0, 38: 1000.0, 70: 1000.0, 72: 0.0}}}
    return example("crank_slider_dynamics.yaml", forces=[force], **changes)


@pytest.fixture(scope="module")
def with_friction():
    return dynamics(compressor(friction=FRICTION))


@pytest.fixture(scope="module")
def without_friction():
    return dynamics(compressor())


def relative_speeds(d) -> dict[str, np.ndarray]:
    """Relative angular speed (second body minus first) of each revolute pair, and the
    sliding speed of the slider along the guide vector (at 180°), from the crank angle and
    the closed-form rod angle β and piston velocity."""
    phi = d.kinematics.value("a1")
    s = R * np.sin(phi) + E
    w = np.sqrt(L * L - s * s)
    rod_rate = -R * np.cos(phi) / w * OMEGA  # d/dt of the rod angle −asin(s/l)
    piston = (-R * np.sin(phi) - s * R * np.cos(phi) / w) * OMEGA  # ẋ_B
    return {"O": np.full(phi.shape, OMEGA), "A": rod_rate - OMEGA, "B": -rod_rate,
            "S": -piston}  # the slide along vector 3 (pointing −X) is −ẋ_B


def test_friction_loads_are_settled(with_friction):
    r = with_friction.forces.reactions
    for name in ("O", "A", "B"):
        want = F * RHO * np.abs(r[name].force)
        scale = want.max()
        err = np.abs(np.abs(r[name].friction) - want).max()
        assert err <= RTOL * scale, f"{name}: |M_f| − f ρ |R| = {err:.3e}"
    load = np.maximum(np.abs(r["S"].normal), 2 * np.abs(r["S"].moment) / B)
    err = np.abs(np.abs(r["S"].friction) - F * load).max()
    assert err <= RTOL * F * load.max(), f"S: |F_f| − f max(|N|, 2|M|/b) = {err:.3e}"
    # a prismatic pair's force is its normal force plus its friction along the guide
    e = np.exp(1j * np.pi)
    np.testing.assert_allclose(r["S"].force, r["S"].normal * 1j * e + r["S"].friction * e,
                               rtol=0, atol=1e-12 * np.abs(r["S"].force).max())


def test_friction_opposes_relative_motion(with_friction):
    r = with_friction.forces.reactions
    for name, speed in relative_speeds(with_friction).items():
        moving = np.abs(speed) > 1e-6 * np.abs(speed).max()
        assert (r[name].friction[moving] * speed[moving] < 0).all(), name
        np.testing.assert_allclose(r[name].loss, np.abs(r[name].friction * speed),
                                   rtol=1e-9, atol=1e-9 * r[name].loss.max(), err_msg=name)
        assert (r[name].loss >= 0).all()
    assert with_friction.summary.friction_work > 0


def net_work(d, name: str) -> float:
    row = next(r for r in d.summary.rows if r.name == name)
    return row.positive_work + row.negative_work


def test_energy_balance_over_a_cycle(with_friction):
    d = with_friction
    s = d.summary
    assert abs(s.kinetic_energy_change) <= 1e-12 * d.kinetic_energy.max()  # a steady cycle
    works = {r.name: r.positive_work + r.negative_work for r in s.rows}
    assert set(works) == {"M_bal", "P", "G1", "G2", "G3", "friction"}
    # friction's row is its (negative) power
    assert works["friction"] == pytest.approx(-s.friction_work, rel=1e-12)
    driving = works["M_bal"]
    assert driving > 0 and works["P"] < 0
    balance = sum(works.values()) - s.kinetic_energy_change
    assert abs(balance) <= ENERGY_RTOL * driving, balance
    useful = -sum(w for name, w in works.items() if name != "friction" and w < 0)
    assert s.driving_work == pytest.approx(useful + s.friction_work, rel=ENERGY_RTOL)
    assert s.driving_work == pytest.approx(driving, rel=1e-12)
    assert s.efficiency == pytest.approx(1 - s.friction_work / s.driving_work, rel=1e-12)
    assert 0 < s.efficiency < 1


def test_energy_balance_without_friction(without_friction):
    s = without_friction.summary
    works = {r.name: r.positive_work + r.negative_work for r in s.rows}
    assert works["friction"] == 0 and s.friction_work == 0
    assert abs(sum(works.values())) <= ENERGY_RTOL * works["M_bal"]
    assert s.efficiency == pytest.approx(1.0, abs=ENERGY_RTOL)


def test_friction_raises_the_peak_balancing_moment(with_friction, without_friction):
    peak = np.abs(with_friction.forces.balancing[1]).max()
    ideal = np.abs(without_friction.forces.balancing[1]).max()
    assert peak > ideal
    # solve_dynamics(friction=False) is the ideal machine, whatever the model says
    ideal_again = solve_dynamics(Model.from_dict(compressor(friction=FRICTION)),
                                 friction=False)
    np.testing.assert_allclose(ideal_again.forces.balancing[1],
                               without_friction.forces.balancing[1], rtol=0,
                               atol=1e-12 * ideal)
    assert ideal_again.forces.friction_loss.max() == 0


def test_kinetostatics_equals_virtual_power_plus_friction_power(with_friction):
    d = with_friction
    ks, vp = d.forces.balancing[1], d.balancing_vp[1]
    assert np.abs(ks - vp).max() <= RTOL * np.abs(ks).max()
    ideal_vp = vp - d.forces.friction_loss / OMEGA
    assert np.abs(ks - ideal_vp).max() > 1e-3 * np.abs(ks).max()  # friction matters


def test_joint_friction_overrides_the_default():
    data = compressor(friction=FRICTION)
    data["joints"]["S"] = {**data["joints"]["S"], "friction": 0.0}
    data["joints"]["A"] = {**data["joints"]["A"], "friction": 0.2, "radius": 0.02}
    d = dynamics(data)
    r = d.forces.reactions
    assert np.abs(r["S"].friction).max() == 0 and r["S"].loss.max() == 0
    np.testing.assert_allclose(np.abs(r["A"].friction), 0.2 * 0.02 * np.abs(r["A"].force),
                               rtol=1e-9)
    np.testing.assert_allclose(np.abs(r["O"].friction), F * RHO * np.abs(r["O"].force),
                               rtol=1e-9)


def test_power_balance_at_every_position():
    n = 360
    d = dynamics(example("crank_slider_dynamics.yaml", positions=n, arguments=crank_turn(n),
                         friction=FRICTION, moments=[{"body": 2, "value": 5.0}]))
    assert set(d.powers) == {"M_bal", "P", "M1", "G1", "G2", "G3"}
    net = sum(d.powers.values()) - d.forces.friction_loss
    dT = first_derivative(d.kinetic_energy, time_step(d), periodic=True)
    scale = np.abs(d.powers["M_bal"]).max()
    err = np.abs(net[:-1] - dT).max()
    assert err <= 1e-8 * scale, f"Σ N − N_f − dT/dt = {err:.3e} W (scale {scale:.3e} W)"
