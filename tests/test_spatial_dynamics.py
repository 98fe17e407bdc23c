"""Dynamics of models with spatial contours (issue 17): bodies with inertia tensors, 3-D
loads, the balancing load and the reduced characteristics by virtual power.

Checked against independent references: the planar dynamics (a planar model written as
spatial, β = 0), the energy balance ``dT/dt = Σ power`` with ``dT/dt`` the spectral
derivative of the kinetic energy over the periodic cycle, ``dJ_red/dφ`` the same way, each
body's angular velocity solved from the rates of its vectors' components
(``u̇ = ω × u``), the loads' powers in closed form, and located errors for bad input.
"""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest
import yaml

from mechloop.dynamics.analysis import solve_dynamics
from mechloop.errors import ModelError
from mechloop.model.load import model_from_data
from mechloop.spatial.dynamics import solve_spatial_dynamics

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "spatial" / "rssr_dynamics.yaml"

#: A four-bar with a coupler triangle (body 2: vectors 2 and 5, two lumped masses), a
#: force from a table, a force along a vector, a moment and gravity.
PLANAR = {
    "name": "four-bar with a coupler triangle",
    "units": {"length": "mm", "angle": "deg", "mass": "kg", "force": "N"},
    "positions": 72, "time": {"rpm": 120},
    "arguments": {1: {"table": {0: 0, 72: 360}}},
    "vectors": {1: {"r": 40, "a": {"argument": 1}}, 2: {"r": 120, "a": "function"},
                3: {"r": 90, "a": "function"}, 4: {"r": 110, "a": 10},
                5: {"r": 70, "a": {"link": "a2", "delta": 35}},
                6: {"r": "function", "a": "function"},
                7: {"r": {"link": "r1"}, "a": {"link": "a1"}}},
    "contours": [{"vectors": [1, 2, 3, 4], "variant": 1}, {"vectors": [7, 5, 6]}],
    "bodies": {
        1: {"vectors": [1, 7], "mass": 0.8, "inertia": 0.0004,
            "center": {"vector": 1, "share": 0.4}},
        2: {"vectors": [2, 5], "mass": 1.5, "inertia": 0.003,
            "center": {"vector": 5, "share": 0.5},
            "parts": [{"mass": 0.3, "inertia": 0.0001, "center": {"vector": 2, "along": 20}}]},
        3: {"vectors": [3], "mass": 1.1, "inertia": 0.002,
            "center": {"vector": 3, "share": 0.5}}},
    "forces": [{"body": 2, "at": {"head": 5}, "value": {"table": {0: 50, 72: 120}},
                "angle": 200},
               {"body": 3, "at": {"tail": 3}, "value": 30, "along": 3}],
    "moments": [{"body": 3, "value": -4}],
    "gravity": {"g": 9.81},
}


def _as_spatial(data: dict) -> dict:
    """``data`` with contour 1 spatial (β = 0; a2, b2, a3 unknown) and every planar moment
    of inertia ``J`` a tensor whose ``Jz`` is ``J`` (``[0, J, J]`` for a one-axis body)."""
    out = copy.deepcopy(data)
    for n in (1, 2, 3, 4):
        out["vectors"][n]["b"] = "function" if n == 2 else 0
    out["contours"][0]["spatial"] = True
    for body in out["bodies"].values():
        for item in (body, *body.get("parts", [])):
            j = item["inertia"]  # bodies 1 (vectors 1, 7: one line) and 3 are one-axis
            item["inertia"] = [0.6 * j, 0.5 * j, j] if body["vectors"] == [2, 5] else [0, j, j]
    return out


def _spectral_derivative(values: np.ndarray, period: float) -> np.ndarray:
    """The derivative of samples of a smooth periodic function over one period (the last
    sample, the first one again, left out)."""
    f = values[:-1]
    n = f.size
    k = 2 * np.pi * np.fft.fftfreq(n, d=period / n)
    if n % 2 == 0:
        k[n // 2] = 0.0
    out = np.fft.ifft(1j * k * np.fft.fft(f)).real
    return np.append(out, out[0])


def _dense_example(positions: int = 360) -> dict:
    data = yaml.safe_load(EXAMPLE.read_text(encoding="utf-8"))
    data["positions"] = positions
    data["arguments"][1] = {"table": {0: 0, positions: 360}}
    return data


# ------------------------------------------------------------ the planar dynamics
def test_a_planar_model_written_as_spatial_gives_the_planar_dynamics():
    planar = solve_dynamics(model_from_data(copy.deepcopy(PLANAR)))
    spatial = solve_spatial_dynamics(model_from_data(_as_spatial(PLANAR)))
    assert np.abs(spatial.kinematics.value("b2")).max() < 1e-12
    pairs = {"M_bal_vp [N*m]": planar.balancing_vp[1], "J_red [kg*m^2]":
             planar.reduced.inertia, "dJ_red [kg*m^2/rad]": planar.reduced.d_inertia,
             "M_red [N*m]": planar.reduced.load, "T [J]": planar.kinetic_energy,
             "xS [m]": planar.center.z.real, "yS [m]": planar.center.z.imag}
    for body, motion in planar.centers.items():
        pairs[f"xS{body} [m]"], pairs[f"yS{body} [m]"] = motion.z.real, motion.z.imag
        pairs[f"wz{body} [rad/s]"] = planar.kinematics.rate(
            f"a{planar.mechanism.bodies[body].angle_vector}")
        pairs[f"wx{body} [rad/s]"] = pairs[f"zS{body} [m]"] = 0.0 * motion.z.real
    frame = spatial.to_frame()
    for column, want in pairs.items():
        got = frame[column].to_numpy(float)
        scale = max(np.abs(want).max(), 1e-300)
        assert np.abs(got - want).max() <= 1e-10 * scale + 1e-15, column
    # the planar balancing moment by kinetostatics (reactions) agrees too
    assert np.allclose(spatial.balancing[1], planar.forces.balancing[1], rtol=0,
                       atol=1e-10 * np.abs(planar.forces.balancing[1]).max())


# --------------------------------------------------------------- the energy balance
def test_energy_balance_over_the_cycle_of_the_rssr():
    data = _dense_example()
    data["time"] = {"rpm": 600}  # fast: the inertia powers as large as the loads'
    res = solve_spatial_dynamics(model_from_data(data))
    assert not res.kinematics.broken.any()
    period = 0.1  # one turn of the input
    d_kinetic = _spectral_derivative(res.kinetic_energy, period)
    power = sum(res.powers.values())
    scale = np.abs(d_kinetic).max()
    assert np.abs(d_kinetic - power).max() <= 1e-9 * scale
    assert scale > 0.3 * max(np.abs(p).max() for p in res.powers.values())


def test_reduced_inertia_derivative_by_the_spectral_derivative():
    res = solve_spatial_dynamics(model_from_data(_dense_example()))
    j_red, dj_red, _ = res.reduced
    assert j_red.min() > 0
    dj = _spectral_derivative(j_red, 2 * np.pi)
    assert np.abs(dj - dj_red).max() <= 1e-9 * np.abs(dj_red).max()
    # one input: Q = J_red φ̈ + ½ dJ_red φ̇² − M_red (φ̈ = 0 at constant speed)
    rate = 2 * np.pi
    assert np.allclose(res.balancing[1], 0.5 * dj_red * rate**2 - res.reduced[2],
                       rtol=0, atol=1e-12 * np.abs(res.balancing[1]).max())


def _components(kin, n: int):
    return tuple(np.stack(x) for x in zip(*kin.components(n), strict=True))


def test_angular_velocities_from_the_rates_of_the_vectors():
    """Solve ``Σ (I − u uᵀ) ω = Σ u × u̇`` over the body's vectors (``u̇ = ω × u``) from
    the vectors' Cartesian components, and ε by the spectral derivative of ω."""
    res = solve_spatial_dynamics(model_from_data(_dense_example()))
    kin = res.kinematics
    for body, (vectors, _) in res.mechanism.bodies.items():
        lhs, rhs = np.zeros((3, 3, kin.broken.size)), np.zeros((3, kin.broken.size))
        for n in vectors:
            p, v, _ = _components(kin, n)
            size = np.linalg.norm(p, axis=0)
            u = p / size
            du = (v - u * np.einsum("ip,ip->p", u, v)) / size
            lhs += np.eye(3)[:, :, None] - u[:, None] * u[None]
            rhs += np.cross(u, du, axis=0)
        omega = res.frames[body].omega
        if len(vectors) > 1:
            want = np.linalg.solve(np.moveaxis(lhs, -1, 0), rhs.T[..., None])[..., 0].T
        else:  # one axis: no spin about it
            want = rhs
        assert np.abs(omega - want).max() <= 1e-12 * np.abs(want).max(), body
        eps = np.stack([_spectral_derivative(w, 1.0) for w in omega])
        scale = max(np.abs(eps).max(), np.abs(omega).max() * 2 * np.pi)  # ε ~ ω²
        assert np.abs(res.frames[body].epsilon - eps).max() <= 1e-8 * scale
    # the output crank turns about Y: ω3 = −β̇3 Y
    assert np.allclose(res.frames[3].omega[1], -kin.rate("b3"), rtol=0, atol=1e-12)


def test_powers_of_the_loads_in_closed_form():
    res = solve_spatial_dynamics(model_from_data(_dense_example(72)))
    kin = res.kinematics
    v = {n: _components(kin, n)[1] for n in (1, 2, 3, 5)}
    e_speed = v[1] + v[2] - v[3] + v[5]  # E = O + r1 + r2 − r3 + r5
    push = 15 * np.array([1.0, -1.0, 2.0]) / np.sqrt(6.0)
    assert np.allclose(res.powers["P"], push @ e_speed, rtol=0, atol=1e-12)
    assert np.allclose(res.powers["M_out"], 2.0 * kin.rate("b3"), rtol=0, atol=1e-12)
    crank_center = 0.5 * v[1]
    assert np.allclose(res.powers["G1"], -0.4 * 9.81 * crank_center[1], rtol=0, atol=1e-12)
    # the crank turns about Z: T of body 1 is ½ (m v² + J φ̇²)
    t1 = 0.5 * (0.4 * (0.02 * 2 * np.pi) ** 2 + 6.0e-5 * (2 * np.pi) ** 2)
    part = res.frames[1].omega
    assert np.allclose(part[2], 2 * np.pi) and np.abs(part[:2]).max() < 1e-12
    assert t1 < res.kinetic_energy.min()


def test_a_static_model_has_no_inertia_terms():
    data = _dense_example(72)
    del data["time"]
    res = solve_spatial_dynamics(model_from_data(data))
    assert res.static and not res.kinetic_energy.any()
    assert np.allclose(res.balancing[1], -res.reduced[2], rtol=0, atol=1e-15)


# ------------------------------------------------------------------ located errors
@pytest.mark.parametrize(("change", "where", "words"), [
    (lambda d: d["bodies"][3].update(inertia=[[1e-4, 2e-5, 0], [0, 1e-4, 0], [0, 0, 1e-4]]),
     ("bodies", 3, "inertia"), "symmetric"),
    (lambda d: d["bodies"][3].update(inertia=[1e-4, 1e-4, 5e-4]),
     ("bodies", 3, "inertia"), "belong to no body"),
    (lambda d: d["bodies"][3].update(inertia=1e-4), ("bodies", 3, "inertia"),
     "needs its inertia tensor"),
    (lambda d: d["bodies"][3].update(inertia=[1e-4, 2e-4]), ("bodies", 3, "inertia"),
     "3 rows of 3"),
    (lambda d: d["bodies"][1].update(inertia=[1e-4, 1.5e-4, 2e-4]), ("bodies", 1, "inertia"),
     "symmetric about them"),
    (lambda d: d["bodies"][3].update(inertia="rod"), ("bodies", 3, "inertia"),
     "first vector"),
    (lambda d: d["bodies"][2].update(vectors=[2, 3]), ("bodies", 2, "vectors"),
     "turn relative to each other"),
    (lambda d: d["bodies"][2].update(vectors=[2, 99]), ("bodies", 2, "vectors"),
     "lists vector 99, which is not defined"),
    (lambda d: d["bodies"][2].update(center={"vector": 2, "share": 0.5, "across": 3}),
     ("bodies", 2, "center", "across"), "no side"),
    (lambda d: d["forces"][0].update(direction=[0, 0, 0]), ("forces", 0, "direction"),
     "non-zero"),
    (lambda d: d["forces"][0].update(direction=None, along=5, angle=10),
     ("forces", 0, "angle"), "no angle"),
    (lambda d: d["forces"][0].update(when={"rate_of": "a1", "sign": "positive"}),
     ("forces", 0, "when"), "'when'"),
    (lambda d: d["moments"][0].update(value={"expression": "2*t"}),
     ("moments", 0, "value"), "expressions"),
    (lambda d: d["moments"][0].update(body=7), ("moments", 0, "body"), "not a moving body"),
])
def test_bad_bodies_and_loads_are_located_with_a_fix(change, where, words):
    data = _dense_example(12)
    change(data)
    with pytest.raises(ModelError) as info:
        solve_spatial_dynamics(model_from_data(data))
    problem = next(p for p in info.value.problems if p.path == where)
    assert words in problem.message and problem.hint


@pytest.mark.parametrize(("change", "where"), [
    (lambda d: d["bodies"][3].update(inertia=[0.001, 0.002, 0.003]), ("bodies", 3, "inertia")),
    (lambda d: d["forces"][1].update(direction=[1, 0, 0]), ("forces", 1, "direction")),
    (lambda d: d["moments"][0].update(axis=[0, 0, 1]), ("moments", 0, "axis")),
])
def test_planar_models_refuse_what_applies_in_space(change, where):
    data = copy.deepcopy(PLANAR)
    change(data)
    with pytest.raises(ModelError) as info:
        solve_dynamics(model_from_data(data))
    problem = next(p for p in info.value.problems if p.path == where)
    assert "spatial contours" in problem.message and problem.hint


def test_the_planar_force_analysis_refuses_a_spatial_model_with_the_fix(tmp_path):
    from typer.testing import CliRunner

    from mechloop.cli import app
    from mechloop.errors import SolveError

    with pytest.raises(SolveError, match="not built for a model with spatial contours") as info:
        solve_dynamics(model_from_data(_dense_example(12)))
    assert "mechloop solve" in info.value.hint
    # (reduced, balancing, summary, reactions and hodographs are drawn:
    # tests/test_views_spatial_dynamics.py)
    result = CliRunner().invoke(app, ["plot", str(EXAMPLE), "motion", "-o",
                                      str(tmp_path / "j.png")])
    assert result.exit_code == 2 and "spatial contours" in result.output, result.output


def test_chain_breaks_leave_their_rows_empty_and_the_others_whole():
    data = _dense_example(72)
    data["vectors"][2]["r"] = 75  # too short a coupler for part of the turn
    res = solve_spatial_dynamics(model_from_data(data))
    frame = res.to_frame()
    broken = frame["chain_break"].to_numpy()
    assert 0 < broken.sum() < broken.size
    values = frame.drop(columns="chain_break").to_numpy(float)
    assert np.isfinite(values[~broken]).all()
    assert np.isnan(frame["M_bal_vp [N*m]"].to_numpy()[broken]).all()


def test_energy_balance_with_two_inputs():
    """A telescopic coupler (its length argument 2, a harmonic stroke over the cycle):
    ``dT/dt = Σ F·v + Σ M·ω + M_bal1 φ̇ + F_bal2 ṙ2``, ``dT/dt`` by 6th-order central
    differences over a fine grid (the stroke makes the cycle non-periodic)."""
    n = 1440
    data = _dense_example(n)
    data["time"] = {"rpm": 600}
    data["arguments"][2] = {"law": "harmonic", "start": [0, 105], "end": [n, 125]}
    data["vectors"][2]["r"] = {"argument": 2}
    data["bodies"][2] = {"vectors": [2], "mass": 0.3, "inertia": [0, 3e-4, 3e-4],
                         "center": {"vector": 2, "along": 30}}
    data["forces"].append({"name": "Q", "body": 2, "at": {"vector": 2, "along": 30},
                           "value": 20, "direction": [0, 0, 1]})
    res = solve_spatial_dynamics(model_from_data(data))
    assert res.reduced is None and {"M_bal1", "F_bal2"} <= set(res.powers)
    step = 0.1 / n
    weights = np.array([-1 / 60, 3 / 20, -3 / 4, 0, 3 / 4, -3 / 20, 1 / 60])
    d_kinetic = np.convolve(res.kinetic_energy, weights[::-1], mode="valid") / step
    power = sum(res.powers.values())[3:-3]
    scale = np.abs(d_kinetic).max()
    assert np.abs(d_kinetic - power).max() <= 1e-9 * scale
    assert scale > 0.3 * max(np.abs(p).max() for p in res.powers.values())
    assert "F_bal2_vp [N]" in res.to_frame().columns
