"""Gear meshes in the force analysis (``gears:``, :mod:`mechloop.dynamics.meshes`): the
gear pair of examples/gear_pair_dynamics.yaml — pinion z1 = 20 (R1 = 20 mm) driven,
wheel z2 = 50 (R2 = 50 mm) under a load moment — against

* the moment balance of each gear about its centre, with ε from finite differences in
  time of the solved angles (not the solver's accelerations): ``M1 = J1·ε1 + F_t·R1`` and
  ``F_t·R2 = M_load − J2·ε2``; at rest (the cycloidal law starts and ends at rest) and
  with the inertia taken out the torque ratio is the gear ratio, ``M1/M_load = z1/z2``;
* the line of action: radial ``|F_t|·tan 20°``, pushing the gears apart whichever the
  sign of the load; the bearing reactions balance the mesh force (the centres are fixed);
* the virtual-power balance ``M1·ω1 + M_load·ω2 = d/dt(½J1ω1² + ½J2ω2²)`` (the ideal mesh
  does no work).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from oracles.dynamics import angle_second_derivative, first_derivative, time_step

import mechloop
from mechloop import ModelError, load_model
from mechloop.dynamics.analysis import solve_dynamics

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "gear_pair_dynamics.yaml"
R1, R2, J1, J2 = 0.020, 0.050, 1e-4, 4e-3
TAN = math.tan(math.radians(20))


def _solved(tmp_path, load: float = 20.0):
    text = EXAMPLE.read_text().replace("value: 20,", f"value: {load},")
    file = tmp_path / "pair.yaml"
    file.write_text(text)
    return solve_dynamics(load_model(file))


@pytest.mark.parametrize("load", [20.0, -20.0])
def test_gear_pair_moment_balance_and_line_of_action(tmp_path, load) -> None:
    d = _solved(tmp_path, load)
    kin, forces = d.kinematics, d.forces
    h = time_step(d)
    eps1 = angle_second_derivative(kin.value("a1"), h, periodic=False)
    eps2 = angle_second_derivative(kin.value("a3"), h, periodic=False)
    inner = slice(3, -3)  # the seven-point stencil's rows
    mesh = forces.meshes["mesh"]
    m1 = forces.balancing[1]
    scale = abs(load)
    # each gear about its centre (finite-difference ε)
    np.testing.assert_allclose((m1 - J1 * eps1)[inner], (mesh.tangential * R1)[inner],
                               rtol=0, atol=1e-7 * scale)
    np.testing.assert_allclose((mesh.tangential * R2)[inner], (load - J2 * eps2)[inner],
                               rtol=0, atol=1e-7 * scale)
    # at rest the torque ratio is the gear ratio z1/z2
    assert m1[0] == pytest.approx(load * 20 / 50, rel=1e-12)
    assert m1[-1] == pytest.approx(load * 20 / 50, rel=1e-12)
    np.testing.assert_allclose((m1 - J1 * kin.accel("a1")) / (load - J2 * kin.accel("a3")),
                               20 / 50, rtol=1e-12)
    # the line of action: radial part |Ft|·tan α, separating (wheel pushed along +X)
    np.testing.assert_allclose(mesh.radial, np.abs(mesh.tangential) * TAN, rtol=1e-13)
    np.testing.assert_allclose(mesh.force.real, np.abs(mesh.tangential) * TAN, rtol=1e-13)
    np.testing.assert_allclose(mesh.force.imag, mesh.tangential, rtol=1e-13)
    np.testing.assert_allclose(mesh.normal, np.abs(mesh.force), rtol=1e-13)
    np.testing.assert_allclose(mesh.point, 0.02 + 0j, atol=1e-15)
    # bearings: the centres stay, so each bearing carries the mesh force
    wheel, pinion = forces.reactions["J0_2"], forces.reactions["J0_1"]
    np.testing.assert_allclose(wheel.force, -mesh.force, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(pinion.force, mesh.force, rtol=0, atol=1e-9 * scale)


def test_gear_pair_virtual_power(tmp_path) -> None:
    """The input moment by virtual power (a second method, which knows no mesh force)
    equals the kinetostatic one; the power balance; the table's mesh columns."""
    d = _solved(tmp_path)
    np.testing.assert_allclose(d.balancing_vp[1], d.forces.balancing[1], rtol=1e-12)
    table = d.to_frame()
    np.testing.assert_array_equal(table["Gmesh_t [N]"], d.forces.meshes["mesh"].tangential)
    np.testing.assert_array_equal(table["Gmesh_n [N]"], d.forces.meshes["mesh"].normal)
    kin = d.kinematics
    h = time_step(d)
    w1, w2 = kin.rate("a1"), kin.rate("a3")
    energy = 0.5 * J1 * w1**2 + 0.5 * J2 * w2**2
    power = d.forces.balancing[1] * w1 + 20.0 * w2
    inner = slice(3, -3)
    exact = J1 * w1 * kin.accel("a1") + J2 * w2 * kin.accel("a3")
    np.testing.assert_allclose(power, exact, rtol=0, atol=1e-12 * np.abs(power).max())
    # and against finite differences in time of the kinetic energy (36 positions: O(h⁶))
    np.testing.assert_allclose(power[inner], first_derivative(energy, h, periodic=False)[inner],
                               rtol=0, atol=1e-4 * np.abs(power).max())
    # the mesh force does no work: its contact points move alike along the normal
    mesh = d.forces.meshes["mesh"]
    v1 = 1j * w1 * mesh.point  # pinion point at P about O1 = 0
    v2 = 1j * w2 * (mesh.point - 0.07)  # wheel point at P about O2 = 70 mm
    np.testing.assert_allclose(((np.conj(mesh.force) * (v2 - v1)).real), 0.0,
                               atol=1e-12 * np.abs(power).max())


def test_mesh_errors_are_located(tmp_path) -> None:
    text = EXAMPLE.read_text()
    file = tmp_path / "bad.yaml"
    file.write_text(text.replace("bodies: [1, 2], at", "bodies: [1, 5], at"))
    with pytest.raises(ModelError) as info:
        solve_dynamics(load_model(file))
    assert any(p.path[:3] == ("gears", "mesh", "bodies") for p in info.value.problems)
    file.write_text(text.replace("pressure_angle: 20", "pressure_angle: 95"))
    with pytest.raises(ModelError) as info:
        solve_dynamics(load_model(file))
    assert any(p.path[-1] == "pressure_angle" for p in info.value.problems)
    # without the mesh the force analysis is not determinate
    file.write_text(text.replace("gears:\n  mesh: {bodies: [1, 2], at: {vector: 2, along: "
                                 "50}, pressure_angle: 20}\n", ""))
    with pytest.raises(ModelError, match="not determinate") as info:
        solve_dynamics(load_model(file))
    assert "gears:" in info.value.problems[0].hint


def test_old_models_have_no_meshes() -> None:
    d = solve_dynamics(load_model(EXAMPLE.parent / "crank_slider_dynamics.yaml"))
    assert d.forces.meshes == {} and d.mechanism.meshes == ()
    assert isinstance(mechloop.Model, type)


def _geared_rocker_data(load: float) -> dict:
    """The crank-rocker of tests/test_ratio_solved_angles.py (crank 0.1, coupler 0.3,
    rocker 0.25, frame 0.3 m) driven at constant speed, its rocker carrying a pinion
    (R1 = 50 mm) that meshes with a wheel (R2 = 125 mm, k = −0.4) on the frame, masses on
    every link and a moment ``load`` on the wheel; SI units and degrees."""
    from test_ratio_solved_angles import geared_four_bar

    data = geared_four_bar(0.1, 0.3, 0.25, 0.3, k=-0.4, n=360, sweep=360.0).model_dump(
        mode="python", exclude_none=True)
    data["time"] = {"table": {0: 0.0, 360: 0.5}}
    data["bodies"] = {
        1: {"vectors": [1], "mass": 0.8, "inertia": 0.002, "center": {"vector": 1,
                                                                      "share": 0.5}},
        2: {"vectors": [2], "mass": 1.2, "inertia": 0.01, "center": {"vector": 2,
                                                                     "share": 0.5}},
        3: {"vectors": [3, 5], "mass": 1.5, "inertia": 0.02, "center": {"vector": 3,
                                                                        "share": 0.7}},
        4: {"vectors": [7], "mass": 4.0, "inertia": 0.03, "center": {"head": 7}}}
    data["gears"] = {"mesh": {"bodies": [3, 4], "at": {"vector": 8, "along": 0.125}}}
    data["moments"] = [{"body": 4, "value": load}]
    return data


@pytest.mark.parametrize("load", [15.0, -15.0])
def test_geared_rocker_newton_euler_and_virtual_power(load) -> None:
    """A gear on a linkage: the mesh force enters the rocker's equations, coupled to the
    four-bar's.  Newton–Euler residuals of every body (the oracle's, with the mesh force
    added: accelerations from finite differences in time of the positions) and the
    virtual-power balance of the drive (Σ power of the loads = d/dt kinetic energy)."""
    from oracles.dynamics import cross, lumped_masses, newton_euler, point_z, rows

    data = _geared_rocker_data(load)
    d = solve_dynamics(mechloop.Model.from_dict(data))
    assert set(d.forces.meshes) == {"mesh"} and not d.forces.singular.any()
    mesh = d.forces.meshes["mesh"]
    take = rows(d, periodic=False)
    origins = {}
    for m in lumped_masses(data, d):
        origins.setdefault(m.body, point_z(d, m.center)[take])
    worst_f = worst_m = 0.0
    for r in newton_euler(d, data):
        f, mo = r.force.copy(), r.moment.copy()
        for body, sign in ((mesh.mesh.bodies[1], 1.0), (mesh.mesh.bodies[0], -1.0)):
            if body == r.body:
                f += sign * mesh.force[take]
                mo += cross(mesh.point[take] - origins[body], sign * mesh.force[take])
        inner = slice(3, -3)
        worst_f = max(worst_f, np.abs(f[inner]).max() / r.force_scale)
        worst_m = max(worst_m, np.abs(mo[inner]).max() / r.moment_scale)
    assert worst_f < 1e-7 and worst_m < 1e-7
    # without the mesh force the wheel would not balance: the check can fail
    wheel = next(r for r in newton_euler(d, data) if r.body == 4)
    assert np.abs(wheel.moment[3:-3]).max() / wheel.moment_scale > 1e-3
    # the radial part separates the gears whatever the sign of Ft
    np.testing.assert_allclose(mesh.radial, np.abs(mesh.tangential) * TAN, rtol=1e-12)
    # virtual power: the drive and the load against the kinetic energy's rate (solver
    # velocities; the mesh and the pins do no work)
    kin = d.kinematics
    energy_rate = np.zeros(kin.broken.size)
    for m in lumped_masses(data, d):
        body = data["bodies"][m.body]
        angle = f"a{body['vectors'][0]}"
        s = d.placement.point(d.mechanism.masses[[x.body for x in d.mechanism.masses].index(
            m.body)].center)
        energy_rate += m.mass * (np.conj(s.v) * s.a).real + m.inertia * kin.rate(
            angle) * kin.accel(angle)
    power = d.forces.balancing[1] * kin.rate("a1") + load * kin.rate("a7")
    np.testing.assert_allclose(power, energy_rate, rtol=0, atol=1e-9 * np.abs(power).max())


def test_internal_mesh_pushes_the_ring_outward() -> None:
    """A pinion (R1 = 20 mm) inside a ring (R2 = 50 mm, internal teeth: ratio +z1/z2),
    centres 30 mm apart, the pitch point on the pinion's far side from the ring's centre.
    At rest (the law starts and ends at rest) M1 = −(z1/z2)·M_load; at every position each
    gear's moment balance holds with the solver's ε; the radial force pushes the ring
    outward at the pitch point and the pinion towards the ring's centre."""
    r1, r2, e, load = 0.02, 0.05, 0.03, 12.0
    model = mechloop.Model.from_dict({
        "units": {"length": "m", "angle": "deg"}, "positions": 36,
        "time": {"table": {0: 0.0, 36: 0.5}},
        "arguments": {1: {"law": "cycloidal", "start": [0, 0], "end": [36, 360]}},
        "vectors": {1: {"r": r1, "a": {"argument": 1}},
                    4: {"r": "function", "a": "function"},
                    3: {"r": r2, "a": {"link": "a1", "ratio": "20/50", "delta": 90}},
                    2: {"r": e, "a": 180}},
        "contours": [{"vectors": [1, 4, 3, 2]}],
        "bodies": {1: {"vectors": [1], "mass": 0.5, "inertia": 1e-4, "center": {"tail": 1}},
                   2: {"vectors": [3], "mass": 3.0, "inertia": 4e-3, "center": {"head": 3}}},
        "gears": {"inner": {"bodies": [1, 2], "at": {"vector": 2, "along": e + r1},
                            "ring": 2}},
        "moments": [{"body": 2, "value": load}]})
    d = solve_dynamics(model)
    kin, forces = d.kinematics, d.forces
    mesh = forces.meshes["inner"]
    np.testing.assert_allclose(mesh.point, -r1 + 0j, atol=1e-15)
    m1 = forces.balancing[1]
    assert m1[0] == pytest.approx(-load * 20 / 50, rel=1e-12)
    np.testing.assert_allclose(J2 * kin.accel("a3"), load + r2 * mesh.tangential, rtol=0,
                               atol=1e-9 * load)
    np.testing.assert_allclose(J1 * kin.accel("a1"), m1 - r1 * mesh.tangential, rtol=0,
                               atol=1e-9 * load)
    np.testing.assert_allclose(mesh.force.real, -np.abs(mesh.tangential) * TAN, rtol=1e-13)
    assert (mesh.radial >= 0).all()
    np.testing.assert_allclose(d.balancing_vp[1], m1, rtol=1e-12)
