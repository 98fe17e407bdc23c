"""Intermediate arguments (issue 12 point 4): a sweep inside every position, results with
an extra axis, and envelopes — against closed forms and a dense-sample brute force."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.errors import ModelError, SolveError
from mechloop.model.schema import Model
from mechloop.solve.inputs import model_arguments
from mechloop.solve.intermediate import solve_intermediate

CAM = Path(__file__).resolve().parents[1] / "examples" / "cam_roller_follower.yaml"
# the example's inputs (mm): offset, guide length at rest, rise, roller radius
E, S0, H, RHO = 12.0, 35.0, 20.0, 10.0


def _cycloidal(tau: np.ndarray, h: float, span: float) -> tuple[np.ndarray, np.ndarray]:
    """s and ds/dk of a cycloidal law over ``span`` positions (held outside)."""
    t = np.clip(tau, 0.0, 1.0)
    return h * (t - np.sin(2 * np.pi * t) / (2 * np.pi)), h / span * (1 - np.cos(2 * np.pi * t))


def _cam_closed_form() -> dict[str, np.ndarray]:
    """The roller cam in its own frame, written out: the pitch point P(k) (roller centre),
    its derivative along the positions, and the profile offset by the roller radius along
    the normal to the right of the motion (towards the cam centre), all in mm."""
    k = np.arange(361.0)
    s1, d1 = _cycloidal(k / 120, H, 120)
    s2, d2 = _cycloidal((k - 180) / 120, -H, 120)
    s, ds = s1 + s2, d1 + d2
    psi, dpsi = np.radians(-k), -np.pi / 180
    c, sn = np.cos(psi), np.sin(psi)
    length = S0 + s
    pitch = np.array([E * c - length * sn, E * sn + length * c])
    tangent = np.array([dpsi * (-E * sn - length * c) - ds * sn,
                        dpsi * (E * c - length * sn) + ds * c])
    right = np.array([tangent[1], -tangent[0]]) / np.hypot(*tangent)
    return {"pitch": pitch, "tangent": tangent, "dpsi": dpsi,
            "profile": pitch + RHO * right, "outer": pitch - RHO * right}


@pytest.fixture(scope="module")
def cam():
    return solve_intermediate(mechloop.load_model(CAM))


def test_cam_profile_is_the_closed_form_offset_of_the_pitch_curve(cam):
    ref = _cam_closed_form()
    env = cam.envelopes["profile"]
    for branch, key in ((-1, "profile"), (1, "outer")):
        x, y = env.curve(branch)
        assert np.isfinite(x).all() and np.isfinite(y).all()
        np.testing.assert_allclose(x * 1e3, ref[key][0], rtol=0, atol=1e-9)
        np.testing.assert_allclose(y * 1e3, ref[key][1], rtol=0, atol=1e-9)
    # exactly two tangencies per position (the roller touches both sides)
    assert np.bincount(env.position).tolist() == [2] * 361
    assert np.abs(env.tangency).max() < 1e-12
    # the profile stays a roller radius inside the pitch curve, outside the cam centre
    x, y = env.curve(-1)
    assert np.hypot(x, y).min() * 1e3 == pytest.approx(37.0 - RHO, abs=1e-9)


def test_cam_grid_values_and_both_derivatives_are_the_closed_form(cam):
    ref = _cam_closed_form()
    theta = cam.theta
    assert theta.shape == (73,) and theta[0] == 0 and theta[-1] == pytest.approx(2 * np.pi)
    assert set(cam.values) == {"a3", "r4", "a4"}  # vector 3 and the loop closing it
    assert cam.values["r4"].shape == (361, 73)
    cx = ref["pitch"][0][:, None] + RHO * np.cos(theta)
    cy = ref["pitch"][1][:, None] + RHO * np.sin(theta)
    dist = np.hypot(cx, cy)
    np.testing.assert_allclose(cam.values["r4"] * 1e3, dist, rtol=1e-13)
    # the closing vector points from the roller's point back to O
    gap = np.angle(np.exp(1j * (cam.values["a4"] - np.arctan2(-cy, -cx))))
    assert np.abs(gap).max() < 1e-12
    # by θ: d|C|/dθ = C·(ρ n(θ))/|C|
    by_theta = (cx * -RHO * np.sin(theta) + cy * RHO * np.cos(theta)) / dist
    np.testing.assert_allclose(cam.by_theta["r4"] * 1e3, by_theta, rtol=1e-9, atol=1e-12)
    assert (cam.by_theta["a3"] == 1).all() and (cam.rates["a3"] == 0).all()
    # along the positions, θ held: analogs with respect to argument 1 (ψ = −φ)
    along = (cx * ref["tangent"][0][:, None] + cy * ref["tangent"][1][:, None]) / dist
    np.testing.assert_allclose(cam.rates["r4"] * 1e3, along / ref["dpsi"], rtol=1e-9,
                               atol=1e-9)
    # second derivative by θ against a central difference of the first
    h = 1e-5
    model = mechloop.load_model(CAM)
    near = solve_intermediate(_with_sweep(model, 1.0 - h, 1.0 + h))
    fd = (near.by_theta["r4"][:, 1] - near.by_theta["r4"][:, 0]) / (2 * h)
    mid = solve_intermediate(_with_sweep(model, 1.0, 1.0 + h))
    np.testing.assert_allclose(mid.by_theta2["r4"][:, 0] * 1e3, fd * 1e3, rtol=1e-5,
                               atol=1e-6)


def _with_sweep(model: Model, start: float, stop: float) -> Model:
    data = model.model_dump(by_alias=True, exclude_none=True)
    data["arguments"][3] = {"intermediate": {"from": f"{start} rad", "to": f"{stop} rad",
                                             "count": 2}}
    data["envelopes"] = []
    return Model.from_dict(data)


def test_the_ordinary_solve_holds_the_intermediate_argument_at_its_first_value(cam):
    base = mechloop.solve(mechloop.load_model(CAM))
    assert (base.value("a3") == 0).all() and (base.rate("a3") == 0).all()
    np.testing.assert_array_equal(base.value("r4"), cam.values["r4"][:, 0])
    np.testing.assert_array_equal(base.rate("a4"), cam.rates["a4"][:, 0])


def test_long_table_and_envelope_table(cam):
    frame = cam.to_frame()
    assert len(frame) == 361 * 73
    assert list(frame.columns[:2]) == ["position", "arg3 [deg]"]
    row = frame.iloc[5 * 73 + 7]
    assert row["position"] == 5 and row["arg3 [deg]"] == pytest.approx(35.0)
    assert row["r4 [m]"] == cam.values["r4"][5, 7]
    assert "r4~arg3 [m/rad]" in frame.columns and not frame["chain_break"].any()
    env = cam.envelope_frame()
    assert len(env) == 722 and set(env["branch"]) == {-1, 1}
    assert (env["envelope"] == "profile").all()


def test_flat_faced_follower_cam_is_the_closed_form():
    """The face's points as the intermediate argument (a length): the face touches the
    cam at the point ``u = ds/dφ`` of the face (the follower's speed analog), written out
    here from the cycloidal laws."""
    res = solve_intermediate(mechloop.load_model(CAM.parent / "cam_flat_follower.yaml"))
    env = res.envelopes["profile"]
    assert res.kind == "length" and res.theta[0] == pytest.approx(-0.04)
    assert np.bincount(env.position).tolist() == [1] * 361  # one contact per position
    k = np.arange(361.0)
    s1, d1 = _cycloidal(k / 120, H, 120)
    s2, d2 = _cycloidal((k - 180) / 120, -H, 120)
    s, ds_dphi = s1 + s2, (d1 + d2) * 180 / np.pi  # per position -> per rad of φ
    psi = np.radians(-k)
    axis = np.array([-np.sin(psi), np.cos(psi)])  # e(ψ + 90°)
    face = np.array([np.cos(psi), np.sin(psi)])  # e(ψ)
    contact = (40 + s) * axis + ds_dphi * face
    np.testing.assert_allclose(env.theta * 1e3, ds_dphi, rtol=0, atol=1e-9)
    np.testing.assert_allclose(env.x * 1e3, contact[0], rtol=0, atol=1e-9)
    np.testing.assert_allclose(env.y * 1e3, contact[1], rtol=0, atol=1e-9)
    assert np.abs(env.tangency).max() < 1e-12


# ---------------------------------------------------------------- model checks
def _cam_data() -> dict:
    return mechloop.load_model(CAM).model_dump(by_alias=True, exclude_none=True)


def test_an_intermediate_first_argument_is_refused_with_the_fix():
    data = _cam_data()
    data["arguments"][1], data["arguments"][3] = data["arguments"][3], data["arguments"][1]
    with pytest.raises(ModelError) as info:
        Model.from_dict(data)
    assert "cannot be intermediate" in str(info.value)


def test_two_intermediate_arguments_and_a_constant_envelope_are_refused():
    data = _cam_data()
    data["arguments"][4] = {"intermediate": {"from": 0, "to": 1, "count": 3}}
    data["envelopes"] = [{"name": "profile", "vectors": [1, 2]}]
    with pytest.raises(ModelError) as info:
        Model.from_dict(data)
    text = str(info.value)
    assert "at most one intermediate argument" in text
    assert "say which intermediate argument" in text
    data = _cam_data()
    data["envelopes"] = [{"name": "profile", "vectors": [1, 2]}]
    with pytest.raises(ModelError, match="does not depend on argument 3"):
        Model.from_dict(data)


def test_an_envelope_with_a_tracked_variant_is_refused():
    data = {"positions": 12, "units": {"length": "mm"},
            "arguments": {1: {"table": {0: 0, 12: 360}},
                          2: {"intermediate": {"from": 0, "to": 360, "count": 5}}},
            "vectors": {1: {"r": 10, "a": {"argument": 1}}, 2: {"r": 40, "a": "function"},
                        3: {"r": 30, "a": "function"}, 4: {"r": 45, "a": 180},
                        5: {"r": 5, "a": {"argument": 2}},
                        6: {"r": "function", "a": "function"},
                        7: {"r": {"link": "r1"}, "a": {"link": "a1"}},
                        8: {"r": {"link": "r2"}, "a": {"link": "a2"}}},
            "contours": [{"vectors": [1, 2, 3, 4], "variant": "auto"},
                         {"vectors": [7, 8, 5, 6]}],
            "envelopes": [{"name": "e", "vectors": [1, 2, 5]}]}
    model = Model.from_dict(data)
    with pytest.raises(SolveError, match="give the contour's variant"):
        solve_intermediate(model)
    # the sweep itself is solved: contour 1 keeps (P,), contour 2 gets (P, M)
    res = solve_intermediate(Model.from_dict({**data, "envelopes": []}))
    assert res.contours == {2} and "a2" not in res.values and res.values["r6"].shape == (13, 5)


# ------------------------------------------------ random families, dense brute force
def _family(kind: str, e: float, s0: float, h: float, law: str, span: int, o1: float,
            o2: float, size: float, beta: float, turn: float) -> dict:
    n = 40
    sweep = ({"from": 0, "to": 360, "count": 37} if kind == "circle"
             else {"from": -size, "to": size, "count": 41})
    return {"positions": n, "units": {"length": "mm"},
            "arguments": {1: {"table": {0: 0, n: turn}},
                          2: {"law": law, "start": [0, 0], "end": [span, h]},
                          3: {"intermediate": sweep}},
            "vectors": {1: {"r": e, "a": {"argument": 1, "offset": o1}},
                        2: {"r": {"argument": 2, "offset": s0},
                            "a": {"argument": 1, "offset": o2}},
                        3: ({"r": size, "a": {"argument": 3}} if kind == "circle" else
                            {"r": {"argument": 3}, "a": {"argument": 1,
                                                         "offset": o2 - 90 + beta}}),
                        4: {"r": "function", "a": "function"}},
            "contours": [{"vectors": [1, 2, 3, 4]}],
            "envelopes": [{"name": "e", "vectors": [1, 2, 3]}]}


@settings(max_examples=25, deadline=None)
@given(kind=st.sampled_from(["circle", "line"]), e=st.floats(-15, 15),
       s0=st.floats(45, 80), h=st.floats(-15, 15),
       law=st.sampled_from(["cycloidal", "harmonic", "poly345"]), span=st.integers(5, 40),
       o1=st.floats(-180, 180), o2=st.floats(-180, 180), size=st.floats(3, 12),
       beta=st.floats(-20, 20), turn=st.sampled_from([360.0, -360.0, 200.0, -90.0]))
def test_random_families_match_a_dense_brute_force(kind, e, s0, h, law, span, o1, o2,
                                                   size, beta, turn):
    # the guide stays longer than the roller's radius (the point never reaches O, where
    # the closing vector has no direction); a face reaches 5 times as far
    size = size if kind == "circle" else 5 * size
    model = Model.from_dict(_family(kind, e, s0, h, law, span, o1, o2, size, beta, turn))
    res = solve_intermediate(model)
    assert not res.broken.any()
    env = res.envelopes["e"]
    # the family written out, sampled densely in its parameter u at every position
    args = model_arguments(model, None)
    psi, s, ds = args[1].value, args[2].value * 1e3, args[2].rate * 1e3  # per rad of ψ
    sign = np.sign(turn)  # ψ's direction along the positions
    a1, a2 = psi + np.radians(o1), psi + np.radians(o2)
    px = e * np.cos(a1) + (s0 + s) * np.cos(a2)
    py = e * np.sin(a1) + (s0 + s) * np.sin(a2)
    vx = -e * np.sin(a1) - (s0 + s) * np.sin(a2) + ds * np.cos(a2)
    vy = e * np.cos(a1) + (s0 + s) * np.cos(a2) + ds * np.sin(a2)
    if kind == "circle":
        u = np.linspace(0, 2 * np.pi, 36 * 400 + 1)
        cux, cuy = -size * np.sin(u), size * np.cos(u)  # ∂C/∂u, the same at every position
        cux, cuy = cux + 0 * psi[:, None], cuy + 0 * psi[:, None]
        csx, csy = vx[:, None] + 0 * u, vy[:, None] + 0 * u
        point = (px[:, None] + size * np.cos(u), py[:, None] + size * np.sin(u))
    else:
        u = np.linspace(-size, size, 40 * 400 + 1)
        b = psi[:, None] + np.radians(o2 - 90 + beta)  # the face, across the guide
        cux, cuy = np.cos(b) + 0 * u, np.sin(b) + 0 * u
        csx, csy = vx[:, None] - u * np.sin(b), vy[:, None] + u * np.cos(b)
        point = (px[:, None] + u * np.cos(b), py[:, None] + u * np.sin(b))
    cross = (cux * csy - cuy * csx) * sign
    step = u[1] - u[0]
    for p in range(psi.size):
        f, v = cross[p], u
        if kind == "circle":  # a full turn: 2π is 0 again, the last pair closes the circle
            f, v = np.r_[f[:-1], f[0]], np.r_[u[:-1], 2 * np.pi]
        i = np.flatnonzero(np.sign(f[:-1]) * np.sign(f[1:]) < 0)
        exact = np.flatnonzero(f[:-1] == 0)
        roots = np.concatenate([v[i] - f[i] * step / (f[i + 1] - f[i]), v[exact]])
        mine = env.theta[env.position == p] * (1e3 if kind == "line" else 1)
        if kind == "line" and (np.abs(np.abs(roots) - size) < 3 * step).any():
            continue  # a tangency at the end of the face: sampling decides it
        if kind == "circle":  # a full turn: the roots as a set on the circle
            gap = np.abs(np.angle(np.exp(1j * (np.sort(mine)[:, None] - roots[None, :]))))
            assert mine.size == roots.size, (p, mine, roots)
            assert gap.min(axis=1).max() < 1e-5
        else:
            assert mine.size == roots.size, (p, mine, roots)
            np.testing.assert_allclose(np.sort(mine), np.sort(roots), atol=1e-5 * size)
        # the point found is on the curve of its position at that parameter
        for t, x, y in zip(mine, env.x[env.position == p], env.y[env.position == p],
                           strict=True):
            j = np.argmin(np.abs(u - t))
            assert np.hypot(x * 1e3 - point[0][p, j], y * 1e3 - point[1][p, j]) < 2 * step * size
    assert (np.abs(env.tangency) < 1e-9).all()
    if kind == "line":
        found.append(env.position.size)


found: list[int] = []


def test_the_random_faces_touch_their_envelope():
    """The line families above are not all out of reach (run after them)."""
    assert sum(found) > 0, found


# ------------------------------------------------------------------------ CLI and view
def test_cli_solve_writes_the_long_table_and_the_envelopes(tmp_path, cam):
    import pandas as pd
    from typer.testing import CliRunner

    from mechloop.cli import app

    out = tmp_path / "cam.csv"
    result = CliRunner().invoke(app, ["solve", str(CAM), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "361 positions × 73 values of argument 3" in result.output
    long = pd.read_csv(tmp_path / "cam.intermediate.csv")
    envelopes = pd.read_csv(tmp_path / "cam.envelopes.csv")
    assert len(long) == 361 * 73 and len(envelopes) == 722
    np.testing.assert_array_equal(long["r4 [m]"].to_numpy(), cam.values["r4"].ravel())
    profile = envelopes[envelopes["branch"] == -1].sort_values("position")
    x, y = cam.envelopes["profile"].curve(-1)
    np.testing.assert_array_equal(profile["x [m]"].to_numpy(), x)
    np.testing.assert_array_equal(profile["y [m]"].to_numpy(), y)
    # a model without intermediate arguments writes its one table as before
    plain = tmp_path / "plain.csv"
    result = CliRunner().invoke(app, ["solve", str(CAM.parent / "crank_slider.yaml"),
                                      "-o", str(plain)])
    assert result.exit_code == 0 and sorted(p.name for p in tmp_path.iterdir()) == [
        "cam.csv", "cam.envelopes.csv", "cam.intermediate.csv", "plain.csv"]


def test_envelope_view_draws_the_family_and_both_branches(cam):
    from mechloop.views.envelope import plot_envelope

    figure = plot_envelope(cam)
    lines = figure.axes[0].get_lines()
    family = [ln for ln in lines if ln.get_color() == "0.6"]
    assert len(family) == 33  # every 11th of 361 positions (at most 36 curves)
    np.testing.assert_array_equal(family[1].get_xdata(), cam.point([1, 2, 5, 3])[0][11])
    red = next(ln for ln in lines if ln.get_color() == "tab:red")
    np.testing.assert_array_equal(red.get_xdata(), cam.envelopes["profile"].curve(-1)[0])


def test_a_sweep_too_large_for_the_memory_is_refused_at_its_count(monkeypatch):
    import importlib

    intermediate = importlib.import_module("mechloop.solve.intermediate")
    monkeypatch.setattr(intermediate, "available_memory", lambda: 10 * 2**20)
    with pytest.raises(ModelError) as info:
        solve_intermediate(mechloop.load_model(CAM))
    problem = info.value.problems[0]
    assert problem.path == ("arguments", 3, "intermediate", "count")
    # 0.8 · 10 MiB over 361 positions × (3 parameters · 120 B + 8 B) per value: 63
    assert "at most about 63 here" in problem.hint


def test_a_saved_model_writes_the_sweep_as_a_file_does(tmp_path):
    model = mechloop.load_model(CAM)
    mechloop.save_model(model, tmp_path / "cam.yaml")
    text = (tmp_path / "cam.yaml").read_text()
    assert "from: 0" in text and "start: 0" not in text.split("intermediate")[1][:40]
    assert mechloop.load_model(tmp_path / "cam.yaml") == model


@pytest.mark.parametrize("sweep", [{"from": 360, "to": 0, "count": 50},
                                   {"from": -90, "to": 270, "count": 7}])
def test_the_envelope_does_not_depend_on_the_sampling_of_the_sweep(cam, sweep):
    """A decreasing sweep, and a coarse one starting elsewhere on the circle, find the
    same tangencies (the samples only bracket them)."""
    data = _cam_data()
    data["arguments"][3] = {"intermediate": sweep}
    env = solve_intermediate(Model.from_dict(data)).envelopes["profile"]
    assert np.bincount(env.position).tolist() == [2] * 361
    for branch in (-1, 1):
        np.testing.assert_allclose(env.curve(branch), cam.envelopes["profile"].curve(branch),
                                   rtol=0, atol=1e-15)
