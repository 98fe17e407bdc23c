"""Joint reactions of spatial models (issue 17): the Newton–Euler equations of every body
with spherical, revolute, cylindrical and prismatic joints.

Checked against independent references:

* every body's Newton–Euler equations, with the reactions and balancing load the solver
  found, hold at every position with the motion rebuilt from the **positions alone**
  (each body's frame from its vectors' components, ``ω`` from ``Ṙ Rᵀ``, ``ε`` and the
  centres' accelerations by spectral derivatives over the periodic cycle) and the loads
  read from the model data here — for the RSSR example and for random masses, inertia
  tensors and loads (hypothesis);
* the balancing load from the reactions' equations equals the one by virtual power;
* a planar four-bar and a slider-crank written as spatial, with joints that keep the
  force analysis determinate (spherical + cylindrical at the coupler), give the reactions
  of mechloop's planar force analysis, and no reaction out of the plane;
* statically indeterminate joints, joints that do not fit the motion, idle motions that
  the loads drive and every misuse of ``joints:`` are refused with a located fix.
"""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation
from test_spatial_dynamics import PLANAR, _as_spatial, _spectral_derivative

from mechloop.dynamics.analysis import solve_dynamics
from mechloop.errors import ModelError
from mechloop.model.load import model_from_data
from mechloop.spatial import reactions as reactions_module
from mechloop.spatial.dynamics import solve_spatial_dynamics
from mechloop.spatial.points import Placement3

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "spatial" / "rssr_reactions.yaml"
CRANK_SLIDER = ROOT / "examples" / "crank_slider_dynamics.yaml"
Z = [0, 0, 1]

#: The Newton–Euler residuals with the spectrally differentiated motion, relative to the
#: largest load term of the body.
NE_RTOL = 1e-9
#: A planar mechanism written as spatial gives the planar reactions to this (relative to
#: each column's largest value).
PLANAR_RTOL = 1e-9


def _example(positions: int = 72) -> dict:
    data = yaml.safe_load(EXAMPLE.read_text(encoding="utf-8"))
    data["positions"] = positions
    data["arguments"][1] = {"table": {0: 0, positions: 360}}
    return data


# --------------------------------------------------- Newton–Euler from the raw positions
def _frame_of(kin, vectors: list[int]) -> tuple[np.ndarray, bool]:
    """The body's rotation ``(3, 3, P)`` from its vectors' positions (e1 along the first,
    e3 normal to it and the first vector not parallel to it); a one-axis body: e1 only."""
    def unit(n):
        p = np.stack([c[0] for c in kin.components(n)])
        return p / np.linalg.norm(p, axis=0)

    e1 = unit(vectors[0])
    for v in vectors[1:]:
        normal = np.cross(e1, unit(v), axis=0)
        if np.linalg.norm(normal, axis=0).min() > 1e-6:
            e3 = normal / np.linalg.norm(normal, axis=0)
            return np.stack([e1, np.cross(e3, e1, axis=0), e3], axis=1), False
    return e1[:, None, :], True


def _loads(data: dict, kin, place: Placement3) -> dict[int, list[tuple]]:
    """Per body its loads ``(force (3, P), point (3, P), moment (3, P))`` from the model
    data (directions ``[x, y, z]``, constant values; gravity along −Y; SI: N, m)."""
    from mechloop.model.dynamic import HeadPoint, TailPoint, VectorPoint

    n = kin.broken.size
    zero = np.zeros((3, n))
    out: dict[int, list[tuple]] = {}

    def point(spec):
        key = next(iter(k for k in ("tail", "head", "vector") if k in spec))
        cls = {"tail": TailPoint, "head": HeadPoint, "vector": VectorPoint}[key]
        return place.point(cls(**spec)).p

    for f in data.get("forces", []):
        d = np.array(f["direction"], float)
        out.setdefault(f["body"], []).append(
            (zero + (f["value"] * d / np.linalg.norm(d))[:, None], point(f["at"]), zero))
    for m in data.get("moments", []):
        d = np.array(m["axis"], float)
        out.setdefault(m["body"], []).append(
            (zero, zero, zero + (m["value"] * d / np.linalg.norm(d))[:, None]))
    g = data.get("gravity", {}).get("g", 0.0)
    for b, body in data["bodies"].items():
        if body.get("mass", 0) > 0 and g:
            out.setdefault(b, []).append(
                (zero + np.array([[0.0], [-body["mass"] * g], [0.0]]),
                 point(body["center"]), zero))
    return out


def _newton_euler_residuals(res, data: dict, period: float, *, inertia: bool = True
                            ) -> dict[int, float]:
    """Every body's largest residual of ``Σ F = m a_S`` and ``Σ M_O = d/dt (S × m v_S +
    J_w ω)`` (O the origin) over the positions, relative to the body's largest load
    term; the motion from the positions alone (over one ``period``), the loads from
    ``data``; without ``inertia`` (a model without time) the right sides are zero."""
    kin = res.kinematics
    place = Placement3(kin)

    def d(x):
        return np.apply_along_axis(_spectral_derivative, -1, x, period)

    loads = _loads(data, kin, place)
    for r in res.reactions.joints.values():  # first body on second
        first, second = r.joint.bodies
        loads.setdefault(second, []).append((r.force, r.point, r.moment))
        loads.setdefault(first, []).append((-r.force, r.point, -r.moment))
    zero = np.zeros_like(r.force)
    drive = np.stack([0 * zero[0], 0 * zero[0], res.reactions.balancing[1]])
    loads[1].append((zero, zero, drive))  # argument 1 turns vector 1 about Z (β1 = 0)
    out = {}
    for b, body in data["bodies"].items():
        axes, rod = _frame_of(kin, body["vectors"])
        if rod:  # no spin about the rod: ω = u × u̇
            u = axes[:, 0]
            omega = np.cross(u, d(u), axis=0)
        else:
            spin = np.einsum("ikp,jkp->ijp", d(axes), axes)  # Ṙ Rᵀ = [ω]×
            omega = np.stack([spin[2, 1], spin[0, 2], spin[1, 0]])
        eps = d(omega)
        center = place.point(res.mechanism.masses[b - 1].center).p
        m = body["mass"]
        tensor = res.mechanism.masses[b - 1].tensor
        if rod:
            jw = tensor[1, 1] * np.eye(3)[:, :, None] + (tensor[0, 0] - tensor[1, 1]) * (
                u[:, None] * u[None])
        else:
            jw = np.einsum("iap,ab,jbp->ijp", axes, tensor, axes)
        a_s = d(d(center)) * inertia
        jw = jw * inertia
        force = sum(f for f, _, _ in loads[b]) - m * a_s
        moment = (sum(np.cross(p, f, axis=0) + mm for f, p, mm in loads[b])
                  - np.cross(center, m * a_s, axis=0) - np.einsum("ijp,jp->ip", jw, eps)
                  - np.cross(omega, np.einsum("ijp,jp->ip", jw, omega), axis=0))
        size = max(max(np.abs(f).max() for f, _, _ in loads[b]), np.abs(m * a_s).max())
        arm = np.abs(np.stack([p for _, p, _ in loads[b]])).max()
        out[b] = max(np.abs(force).max() / size, np.abs(moment).max() / (size * arm))
    return out


def test_the_rssr_example_balances_every_body_with_its_reactions():
    data = _example(256)
    data["time"] = {"rpm": 600}  # fast: inertia as large as the loads
    res = solve_spatial_dynamics(model_from_data(copy.deepcopy(data)))
    assert not res.kinematics.broken.any() and not res.reactions.singular.any()
    residuals = _newton_euler_residuals(res, data, period=0.1)
    assert max(residuals.values()) <= NE_RTOL, residuals
    # the balancing moment of the reactions' equations is the one by virtual power
    q, q_vp = res.reactions.balancing[1], res.balancing[1]
    assert np.abs(q - q_vp).max() <= 1e-9 * np.abs(q_vp).max()
    # the coupler's spin about the line of its balls is the one dropped equation
    assert res.reactions.unknowns == res.reactions.rank == 17
    assert len(res.reactions.idle) == 1 and "joints A, B" in res.reactions.idle[0]


def test_the_residual_check_sees_a_wrong_reaction():
    """The independent check is not blind: a reaction 1e-6 off fails it."""
    data = _example(64)
    res = solve_spatial_dynamics(model_from_data(copy.deepcopy(data)))
    reaction = res.reactions.joints["A"]
    reaction.force[2] *= 1 + 1e-6
    assert max(_newton_euler_residuals(res, data, period=1.0).values()) > 1e-8


_tensor = st.tuples(st.floats(0.5, 4.0), st.floats(0.5, 4.0), st.floats(0.0, 1.0),
                    st.integers(0, 2**32 - 1))


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(masses=st.tuples(st.floats(0.05, 2.0), st.floats(0.05, 2.0), st.floats(0.05, 2.0)),
       tensor=_tensor, rod=st.floats(0.0, 1.0),
       push=st.tuples(st.floats(-50, 50), st.floats(-1, 1), st.floats(-1, 1),
                      st.floats(-1, 1)),
       turn=st.floats(-5, 5), rpm=st.sampled_from([None, 120, 900]))
def test_random_masses_and_loads_balance_every_body(masses, tensor, rod, push, turn, rpm):
    a, b, share, seed = tensor
    principal = np.array([a, b, share * (a + b) + (1 - share) * abs(a - b)]) * 1e-4
    rotation = Rotation.random(random_state=seed).as_matrix()
    data = _example(128)
    bodies = data["bodies"]
    for body, m in zip((1, 2, 3), masses, strict=True):
        bodies[body]["mass"] = m
    bodies[2]["inertia"] = [rod * 1e-5, 3e-4, 3e-4]
    bodies[3]["inertia"] = (rotation @ np.diag(principal) @ rotation.T).tolist()
    bodies[3]["inertia"] = [[(x + y) / 2 for x, y in zip(r, c, strict=True)]
                            for r, c in zip(bodies[3]["inertia"],
                                            np.transpose(bodies[3]["inertia"]), strict=True)]
    data["forces"][0].update(value=push[0], direction=list(push[1:]) if any(push[1:])
                             else [1, 0, 0])
    data["moments"][0]["value"] = turn
    if rpm is None:
        del data["time"]
    else:
        data["time"] = {"rpm": rpm}
    res = solve_spatial_dynamics(model_from_data(copy.deepcopy(data)))
    assert not res.kinematics.broken.any()
    period = 1.0 if rpm is None else 60.0 / rpm
    residuals = _newton_euler_residuals(res, data, period, inertia=rpm is not None)
    assert max(residuals.values()) <= NE_RTOL, residuals
    q, q_vp = res.reactions.balancing[1], res.balancing[1]
    assert np.abs(q - q_vp).max() <= 1e-9 * max(np.abs(q_vp).max(), 1e-9)


# ------------------------------------------------------------ planar force analysis
def _four_bar(joints: dict) -> dict:
    data = _as_spatial(PLANAR)
    data["joints"] = joints
    return data


RSCR = {"O": {"bodies": [0, 1], "at": {"tail": 1}, "axis": Z},
        "A": {"type": "spherical", "bodies": [1, 2], "at": {"head": 1}},
        "B": {"type": "cylindrical", "bodies": [2, 3], "at": {"head": 2}, "axis": Z},
        "D": {"bodies": [0, 3], "at": {"head": 3}, "axis": Z}}


def _compare_with_planar(planar: dict, spatial: dict, moments: dict[str, str], *,
                         rtol: float) -> None:
    """The planar reactions (x, y; a prismatic joint's moment ``moments[name]``) against
    the spatial ones to ``rtol``; the spatial reactions out of the plane are zero."""
    flat = solve_dynamics(model_from_data(copy.deepcopy(planar))).to_frame()
    space = solve_spatial_dynamics(model_from_data(copy.deepcopy(spatial)))
    frame = space.to_frame()
    pairs = {f"R{j}_{axis} [N]": f"R{j}_{axis} [N]" for j in spatial["joints"]
             for axis in "xy"}
    pairs.update(moments)
    pairs["M_bal [N*m]" if "M_bal [N*m]" in flat else "F_bal [N]"] = next(
        c for c in frame.columns if "_bal " in c)
    for want, got in pairs.items():
        a, b = flat[want].to_numpy(float), frame[got].to_numpy(float)
        assert np.abs(a - b).max() <= rtol * np.abs(a).max(), want
    scale = max(np.abs(frame[c].to_numpy(float)).max() for c in pairs.values())
    for c in frame.columns:
        if c.startswith("R") and c.endswith(("_z [N]", "_mx [N*m]", "_my [N*m]")):
            assert np.abs(frame[c].to_numpy(float)).max() <= 1e-12 * scale, c
    assert np.abs(space.reactions.balancing[1] - space.balancing[1]).max() <= \
        1e-9 * np.abs(space.balancing[1]).max()


def test_a_planar_four_bar_written_as_spatial_gives_the_planar_reactions():
    planar = copy.deepcopy(PLANAR)
    planar["joints"] = {k: {"bodies": v["bodies"], "at": v["at"]} for k, v in RSCR.items()}
    _compare_with_planar(planar, _four_bar(RSCR), {}, rtol=PLANAR_RTOL)


def _crank_slider(*, driven_slider: bool) -> tuple[dict, dict]:
    planar = yaml.safe_load(CRANK_SLIDER.read_text(encoding="utf-8"))
    planar.pop("report")
    planar["bodies"][3]["center"] = {"vector": 3, "along": 0.03}  # a moment in the slide
    planar["forces"][0]["at"] = {"vector": 3, "along": 0.02}
    if driven_slider:  # the slider drives the crank: a length argument
        planar["arguments"] = {1: {"law": "harmonic", "start": [0, 0.17], "end": [72, 0.24]}}
        planar["vectors"][1]["a"] = "function"
        planar["vectors"][3]["r"] = {"argument": 1}
    spatial = copy.deepcopy(planar)
    for n in (1, 2, 3, 4):
        spatial["vectors"][n]["b"] = "function" if n == 2 else 0
    spatial["contours"][0].update(spatial=True, variant=2)  # the planar assembly
    spatial["bodies"][1]["inertia"] = [0, 0.01, 0.01]
    spatial["bodies"][2]["inertia"] = [0, 0.006, 0.006]
    spatial["joints"] = {
        "O": {"bodies": [0, 1], "at": {"tail": 1}, "axis": Z},
        "A": {"type": "spherical", "bodies": [1, 2], "at": {"head": 1}},
        "B": {"type": "cylindrical", "bodies": [2, 3], "at": {"head": 2}, "axis": Z},
        "S": {"type": "prismatic", "bodies": [0, 3], "axis": 3}}
    return planar, spatial


@pytest.mark.parametrize("driven_slider", [False, True], ids=["crank", "slider"])
def test_a_slider_crank_written_as_spatial_gives_the_planar_reactions(driven_slider):
    planar, spatial = _crank_slider(driven_slider=driven_slider)
    _compare_with_planar(planar, spatial, {"RS_m [N*m]": "RS_mz [N*m]"}, rtol=PLANAR_RTOL)


# -------------------------------------------------------------- refused, with the fix
@pytest.mark.parametrize(("change", "where", "fix"), [
    ({"A": {"bodies": [1, 2], "at": {"head": 1}, "axis": Z},
      "B": {"bodies": [2, 3], "at": {"head": 2}, "axis": Z}}, ("joints", "A", "type"),
     "A revolute → spherical, B revolute → cylindrical"),
    ({"B": {"bodies": [2, 3], "at": {"head": 2}, "axis": Z}}, ("joints", "B", "type"),
     "B revolute → cylindrical"),
])
def test_statically_indeterminate_joints_are_refused_with_the_joints_to_change(
        change, where, fix):
    joints = copy.deepcopy(RSCR)
    joints.update(change)
    with pytest.raises(ModelError) as info:
        solve_spatial_dynamics(model_from_data(_four_bar(joints)))
    problem = info.value.problems[0]
    assert problem.path == where and "statically indeterminate" in problem.message
    assert fix in problem.hint
    # the fix it names makes the analysis determinate
    joints["A"] = RSCR["A"] if "A" in change else joints["A"]
    joints["B"] = RSCR["B"]
    assert solve_spatial_dynamics(model_from_data(_four_bar(joints))).reactions is not None


def test_the_coupler_between_two_balls_of_a_planar_four_bar_keeps_its_idle_spin():
    joints = copy.deepcopy(RSCR)
    joints["B"] = {"type": "spherical", "bodies": [2, 3], "at": {"head": 2}}
    res = solve_spatial_dynamics(model_from_data(_four_bar(joints)))
    assert len(res.reactions.idle) == 1 and "body 2" in res.reactions.idle[0]
    # an inertia product between the balls' line (e1) and the normal: the spin is driven
    data = _four_bar(joints)
    j = 0.003
    data["bodies"][2]["inertia"] = [[0.8 * j, 0, 0.1 * j], [0, 0.5 * j, 0], [0.1 * j, 0, j]]
    with pytest.raises(ModelError) as info:
        solve_spatial_dynamics(model_from_data(data))
    problem = info.value.problems[0]
    assert problem.path == ("bodies", 2) and "through joints A, B" in problem.message
    assert "inertia" in problem.hint


def test_a_moment_about_the_coupler_line_is_an_unbalanced_idle_motion():
    data = _example(24)
    data["moments"].append({"name": "twist", "body": 2, "value": 1, "axis": Z})
    with pytest.raises(ModelError) as info:
        solve_spatial_dynamics(model_from_data(data))
    problem = info.value.problems[0]
    assert problem.path == ("bodies", 2) and "do not balance" in problem.message


def test_a_joint_that_does_not_fit_the_motion_is_refused():
    data = _example(24)
    data["joints"]["A"].update(type="revolute", axis=1)  # the balls turn every way
    with pytest.raises(ModelError) as info:
        solve_spatial_dynamics(model_from_data(data))
    problem = info.value.problems[0]
    assert problem.path == ("joints", "A", "type") and "spherical" in problem.hint
    data = _example(24)
    data["joints"]["B"]["at"] = {"tail": 2}  # A: not a point of the output crank
    with pytest.raises(ModelError) as info:
        solve_spatial_dynamics(model_from_data(data))
    assert info.value.problems[0].path == ("joints", "B", "at")


@pytest.mark.parametrize(("change", "where", "words"), [
    (lambda j: j["A"].update(axis=[0, 0, 1]), ("joints", "A", "axis"), "has no axis"),
    (lambda j: j["O"].pop("axis"), ("joints", "O"), "needs its axis"),
    (lambda j: j["D"].update(axis=None, along=3), ("joints", "D", "along"), "axis: 3"),
    (lambda j: j["D"].update(axis=9), ("joints", "D", "axis"), "does not exist"),
    (lambda j: j["D"].update(axis=[0, 0, 0]), ("joints", "D", "axis"), "non-zero"),
    (lambda j: j["A"].update(bodies=[1, 7]), ("joints", "A", "bodies", 1), "not a moving"),
    (lambda j: j["A"].update(bodies=[2, 2]), ("joints", "A", "bodies"), "two different"),
    (lambda j: j["A"].pop("at"), ("joints", "A"), "needs 'at'"),
    (lambda j: j["A"].update(at={"head": 9}), ("joints", "A", "at"), "does not exist"),
    (lambda j: j["A"].update(at={"vector": 1, "share": 1, "across": 5}),
     ("joints", "A", "at", "across"), "no side"),
    (lambda j: j["O"].update(friction=0.1), ("joints", "O", "friction"), "friction"),
    (lambda j: [j.pop("B"), j.pop("D")], ("joints",), "body 3 is in no joint"),
])
def test_misused_joints_are_located_with_a_fix(change, where, words):
    data = _example(12)
    change(data["joints"])
    with pytest.raises(ModelError) as info:
        solve_spatial_dynamics(model_from_data(data))
    problem = next(p for p in info.value.problems if p.path == where)
    assert words in problem.message + problem.hint and problem.hint


@pytest.mark.parametrize(("joint", "where"), [
    ({"type": "spherical", "bodies": [1, 2], "at": {"head": 1}}, ("joints", "A", "type")),
    ({"type": "cylindrical", "bodies": [1, 2], "at": {"head": 1}}, ("joints", "A", "type")),
    ({"bodies": [1, 2], "at": {"head": 1}, "axis": Z}, ("joints", "A", "axis")),
])
def test_a_planar_model_refuses_spatial_joints(joint, where):
    data = copy.deepcopy(PLANAR)
    data["joints"] = {k: {"bodies": v["bodies"], "at": v["at"]} for k, v in RSCR.items()}
    data["joints"]["A"] = joint
    with pytest.raises(ModelError) as info:
        solve_dynamics(model_from_data(data))
    problem = next(p for p in info.value.problems if p.path == where)
    assert "spatial contours" in problem.message and problem.hint


# -------------------------------------------------------------------- rows and batches
def test_broken_rows_are_marked_and_the_others_whole():
    data = _example(72)
    data["vectors"][2]["r"] = 75  # too short a coupler for part of the turn
    res = solve_spatial_dynamics(model_from_data(data))
    frame = res.to_frame()
    broken = frame["chain_break"].to_numpy()
    assert 0 < broken.sum() < broken.size
    values = frame.drop(columns="chain_break").to_numpy(float)
    assert np.isfinite(values[~broken]).all()
    assert np.isnan(frame["RA_x [N]"].to_numpy()[broken]).all()


def test_the_batch_in_chunks_is_the_batch_at_once(monkeypatch):
    model = model_from_data(_example(40))
    whole = solve_spatial_dynamics(model).reactions
    monkeypatch.setattr(reactions_module, "CHUNK", 7)
    parts = solve_spatial_dynamics(model).reactions
    for name, r in whole.joints.items():
        assert np.array_equal(r.force, parts.joints[name].force)
        assert np.array_equal(r.moment, parts.joints[name].moment)


def test_singular_positions_are_marked_broken_with_empty_reactions(monkeypatch):
    """With the threshold raised to the RSSR's median conditioning (its s_min/s_max lies
    between 0.07 and 0.13), about half of the positions count as singular."""
    model = model_from_data(_example(72))
    monkeypatch.setattr(reactions_module, "SINGULAR_RTOL", 0.0856)
    res = solve_spatial_dynamics(model)
    singular = res.reactions.singular
    assert 10 < singular.sum() < 62 and not res.kinematics.broken.any()
    frame = res.to_frame()
    assert np.array_equal(frame["chain_break"].to_numpy(), singular)
    assert np.isnan(frame["RB_z [N]"].to_numpy()[singular]).all()
    assert np.isnan(frame["M_bal [N*m]"].to_numpy()[singular]).all()
    values = frame.drop(columns="chain_break").to_numpy(float)
    assert np.isfinite(values[~singular]).all()


def test_joints_without_bodies_are_refused():
    data = _example(12)
    del data["bodies"], data["forces"], data["moments"], data["gravity"]
    with pytest.raises(ModelError) as info:
        model_from_data(data)
    problem = next(p for p in info.value.problems if p.path == ("joints",))
    assert "no bodies" in problem.message and "bodies:" in problem.hint


def test_a_telescopic_coupler_driven_in_length_as_a_second_argument():
    """The coupler as a cylinder (body 2, holding the tail of vector 2) and a rod (body 4,
    holding its head) in a cylindrical joint along it, its length argument 2: the force
    pushing the rod out of the cylinder and the input moment equal the balancing loads by
    virtual power; each part may spin about the coupler line (two idle motions)."""
    n = 144
    data = _example(n)
    data["time"] = {"rpm": 600}
    data["arguments"][2] = {"law": "harmonic", "start": [0, 105], "end": [n, 125]}
    data["vectors"][2]["r"] = {"argument": 2}
    data["bodies"][2] = {"vectors": [2], "mass": 0.3, "inertia": [0, 3e-4, 3e-4],
                         "center": {"tail": 2}}
    data["bodies"][4] = {"vectors": [2], "ends": {2: "head"}, "mass": 0.2,
                         "inertia": [0, 1e-4, 1e-4], "center": {"head": 2}}
    data["joints"]["B"]["bodies"] = [4, 3]
    data["joints"]["C"] = {"type": "cylindrical", "bodies": [2, 4], "axis": 2,
                           "at": {"head": 2}}
    res = solve_spatial_dynamics(model_from_data(data))
    reactions = res.reactions
    assert reactions.rank == reactions.unknowns == 22 and len(reactions.idle) == 2
    for k in (1, 2):
        q, q_vp = reactions.balancing[k], res.balancing[k]
        assert np.abs(q - q_vp).max() <= 1e-9 * np.abs(q_vp).max()
    # the cylindrical joint carries no force along its axis
    axis = res.kinematics.components(2)
    u = np.stack([c[0] for c in axis])
    u /= np.linalg.norm(u, axis=0)
    force = reactions.joints["C"].force
    assert np.abs(np.einsum("ip,ip->p", force, u)).max() <= 1e-12 * np.abs(force).max()


def test_an_output_driven_by_its_rotation_beta():
    """Argument 1 turns the output crank (β3 from 140 to 165 deg, about −Y): its balancing
    moment from the reactions' equations is the one by virtual power."""
    data = _example(36)
    data["arguments"][1] = {"table": {0: 140, 36: 165}}
    data["vectors"][1]["a"] = "function"
    data["vectors"][3]["b"] = {"argument": 1}
    res = solve_spatial_dynamics(model_from_data(data))
    assert not res.kinematics.broken.any()
    q, q_vp = res.reactions.balancing[1], res.balancing[1]
    assert np.abs(q - q_vp).max() <= 1e-9 * np.abs(q_vp).max()


def test_a_four_bar_in_a_tilted_plane_beside_a_spatial_contour():
    """Planar contours in the plane of normal n (their input's drive turns about n) in a
    model with a spatial contour, loads out of the plane: the balancing moment from the
    reactions' equations is the one by virtual power."""
    normal = [0.3, 0.4, 0.866]
    data = _as_spatial(PLANAR)
    data["vectors"] = copy.deepcopy(PLANAR["vectors"])
    data["contours"] = [dict(c, plane={"normal": normal}) for c in PLANAR["contours"]]
    data["contours"].append({"vectors": [8, 9, 10], "spatial": True})
    data["vectors"].update({8: {"r": 10, "a": 10, "b": 10},
                            9: {"r": 10, "a": "function", "b": "function"},
                            10: {"r": "function", "a": 0, "b": 0}})
    data["joints"] = copy.deepcopy(RSCR)
    for name in ("O", "B", "D"):
        data["joints"][name]["axis"] = normal
    data["forces"][0]["direction"] = [1, 2, 3]
    data["forces"][1] = {"body": 3, "at": {"tail": 3}, "value": 30, "direction": [0, 1, 0]}
    data["moments"][0]["axis"] = normal
    res = solve_spatial_dynamics(model_from_data(data))
    assert not res.kinematics.broken.any() and res.reactions.rank == 18
    q, q_vp = res.reactions.balancing[1], res.balancing[1]
    assert np.abs(q - q_vp).max() <= 1e-9 * np.abs(q_vp).max()
