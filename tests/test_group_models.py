"""Models built from Assur groups (mechloop.model.groups): the generated vector models
solve to the same motion as hand-written ones, satisfy the geometry their groups state,
decompose back into the same structure formula, and bad input is reported at its place.

Every check of geometry reads the *placed points* (``Placement``, or the point chains the
builder reports) and compares them with the dimensions given to the group — distances
between joints, a slider pin's distance from its guide line, a block on its lever's line —
never with the vector parameters the builder wrote.  The closed forms (circle
intersection, the slider-crank formula) are written out here.
"""

from __future__ import annotations

import copy
import doctest
import math
from pathlib import Path
from typing import Any

import jsonschema
import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from oracles.dynamic_models import grashof_crank_rocker

import mechloop
from mechloop.dynamics.points import Placement
from mechloop.model import groups as groups_module
from mechloop.model.groups import (
    BuiltModel,
    GroupMechanism,
    build,
    build_model,
    dimension_parameters,
    group_json_schema,
    point_vectors,
)
from mechloop.structure import analyze

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
GROUP_EXAMPLES = sorted(EXAMPLES.glob("*groups*.yaml"))
TOL = 1e-9


# ----------------------------------------------------------------------------- helpers


def mechanism(**data: Any) -> GroupMechanism:
    return GroupMechanism.model_validate(data)


def crank_base(n: int = 36, length: float = 0.1, **extra: Any) -> dict[str, Any]:
    """A crank O-A of ``length`` m turned once over positions 0..n at 60 rpm; ground points
    O (0, 0), C (0, 0.25) and D (0.3, 0)."""
    return {"positions": n, "time": {"rpm": 60.0},
            "arguments": {1: {"table": {0: 0, n: 360}}},
            "ground": {"O": [0, 0], "C": [0, 0.25], "D": [0.3, 0]},
            "input": {"kind": "crank", "pivot": "O", "joint": "A", "length": length},
            **extra}


def solved_points(mech: GroupMechanism) -> tuple[BuiltModel, mechloop.Results,
                                                  dict[str, np.ndarray]]:
    """The built model, its results and every named point as complex positions (m)."""
    built = build(mech)
    results = mechloop.solve(built.model)
    placement = Placement(results)
    points = {}
    for name, where in built.points.items():
        x, y = where.xy(results)
        points[name] = x + 1j * y
        if where.end is not None:  # the vector end the builder names is the same point
            np.testing.assert_allclose(placement.point(where.end).z, points[name],
                                       rtol=0, atol=1e-12)
    return built, results, points


def close(actual, expected, what: str, tol: float = TOL) -> None:
    err = np.max(np.abs(np.asarray(actual) - np.asarray(expected)))
    assert np.isfinite(err) and err <= tol, f"{what}: off by {err:.3e}"


def wrap(angle):
    return (np.asarray(angle) + np.pi) % (2 * np.pi) - np.pi


def unit(angle_deg: float) -> complex:
    return complex(math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg)))


def signed_distance(z, through: complex, direction: complex) -> np.ndarray:
    """Distance of ``z`` to the left of the line through ``through`` along ``direction``."""
    return (np.conj(direction) * (z - through)).imag / abs(direction)


def circle_intersection(p, rp, q, rq):
    """The intersection of circles (p, rp) and (q, rq) on the left of p -> q (complex)."""
    d = q - p
    dist = np.abs(d)
    along = (rp**2 - rq**2 + dist**2) / (2 * dist)
    height = np.sqrt(rp**2 - along**2)
    return p + (along + 1j * height) * d / dist


# ------------------------------------------------------- the same mechanism, two routes


def test_four_bar_from_groups_equals_four_bar_yaml():
    """examples/four_bar_groups.yaml is examples/four_bar.yaml: rocker angle a3 and the
    coupler point's path agree to 1e-9 (positions, velocities, accelerations)."""
    direct = mechloop.solve(mechloop.load_model(EXAMPLES / "four_bar.yaml"))
    mech = GroupMechanism.model_validate(yaml.safe_load(
        (EXAMPLES / "four_bar_groups.yaml").read_text()))
    built = build(mech)
    assert built.model == mechloop.load_model(EXAMPLES / "four_bar_groups.yaml")
    res = mechloop.solve(built.model)
    names = {v.name: k for k, v in built.model.vectors.items()}
    rocker, coupler = names["rocker BC"], names["coupler AB"]
    for kind in ("value", "rate", "accel"):
        close(getattr(res, kind)(f"a{rocker}"), getattr(direct, kind)("a3"), f"a3 {kind}")
        close(getattr(res, kind)(f"a{coupler}"), getattr(direct, kind)("a2"), f"a2 {kind}")
    path = Placement(res).point(built.points["P"].end)
    reference = Placement(direct).head(6)  # four_bar.yaml: P is the head of vector 6
    close(path.z, reference.z, "coupler point P")
    close(path.v, reference.v, "velocity of P", 1e-9 * np.abs(reference.v).max())
    close(path.a, reference.a, "acceleration of P", 1e-9 * np.abs(reference.a).max())


def test_crank_slider_from_groups_has_the_dynamics_of_crank_slider_dynamics_yaml():
    direct = mechloop.solve_dynamics(mechloop.load_model(EXAMPLES /
                                                         "crank_slider_dynamics.yaml"))
    grouped = mechloop.solve_dynamics(mechloop.load_model(EXAMPLES /
                                                          "crank_slider_groups.yaml"))
    a, b = direct.to_frame(), grouped.to_frame()
    scale = np.abs(a["M_bal [N*m]"]).max()
    for column in ("M_bal [N*m]", "M_bal_vp [N*m]", "J_red [kg*m^2]", "RO [N]", "RA [N]",
                   "RB [N]"):
        close(b[column], a[column], column, 1e-9 * max(scale, np.abs(a[column]).max()))
    close(b["RSB_n [N]"], a["RS_n [N]"], "slide reaction", 1e-9 * np.abs(a["RS_n [N]"]).max())


def watt_six_bar_groups() -> GroupMechanism:
    """examples/six_bar.yaml as groups: the bell crank B-C-D carries D at 170 deg to its
    line C->B (six_bar.yaml: a5 = a3 - 10 deg with a3 the direction B->C)."""
    f = 300 + 400 * unit(-30)
    return mechanism(
        units={"length": "mm", "angle": "deg"}, positions=72, time={"rpm": 60},
        arguments={1: {"table": {0: 0, 72: 360}}},
        ground={"O": [0, 0], "C": [300, 0], "F": [f.real, f.imag]},
        input={"kind": "crank", "pivot": "O", "joint": "A", "length": 80},
        groups=[{"kind": "L1", "links": ["coupler", "bell crank"], "at": ["A", "C"],
                 "joint": "B", "lengths": [320, 220]},
                {"kind": "RRR", "links": ["link", "rocker"], "at": ["D", "F"],
                 "joint": "E", "lengths": [300, 150]}],
        points={"D": {"link": "bell crank", "from": "C", "distance": 200, "angle": 170}})


def test_watt_six_bar_from_groups_equals_six_bar_yaml():
    direct = mechloop.solve(mechloop.load_model(EXAMPLES / "six_bar.yaml"))
    built, res, points = solved_points(watt_six_bar_groups())
    placement = Placement(direct)
    close(points["E"], placement.head(6).z, "joint E")
    close(points["D"], placement.head(5).z, "point D")
    names = {v.name: k for k, v in built.model.vectors.items()}
    close(res.value(f"a{names['rocker EF']}"), direct.value("a7"), "output rocker")
    close(res.rate(f"a{names['rocker EF']}"), direct.rate("a7"), "output rocker speed")
    assert analyze(built.model)[1].formula == "L0(1) → L1(2,3) → L1(4,5)"


# ------------------------------------------------------------- every kind of group


def kinds() -> dict[str, GroupMechanism]:
    """One mechanism per kind, with a point on the second link of each group."""
    q = {"Q": {"link": "w", "distance": 0.2, "angle": 20}}
    return {
        "L1": mechanism(**crank_base(points=q, groups=[
            {"kind": "L1", "links": ["u", "w"], "at": ["A", "D"], "joint": "B",
             "lengths": [0.25, 0.35]}])),
        "L2": mechanism(**crank_base(points=q, groups=[
            {"kind": "L2", "links": ["u", "w"], "at": "A", "joint": "B", "length": 0.4,
             "guide": {"through": "C", "angle": -30, "offset": 0.02}}])),
        "L2 on a moving guide": mechanism(**crank_base(points={
            **q, "G": {"link": "r", "from": "D", "distance": 0.1, "angle": 40}}, groups=[
            {"kind": "L1", "links": ["c", "r"], "at": ["A", "D"], "joint": "B",
             "lengths": [0.3, 0.2]},
            {"kind": "L2", "links": ["u", "w"], "at": "crank.A", "joint": "E", "length": 0.35,
             "guide": {"through": "G", "angle": 70, "offset": -0.03}, "variant": 2}])),
        "L3": mechanism(**crank_base(points={"Q": {"link": "w", "distance": 0.5,
                                                   "angle": 15}}, groups=[
            {"kind": "L3", "links": ["u", "w"], "at": ["A", "C"]}])),
        "L4": mechanism(**crank_base(points=q, arguments={1: {"table": {0: 20, 36: 60}}},
                                     groups=[
            {"kind": "L4", "links": ["u", "w"], "joint": "B",
             "guides": [{"through": "C", "angle": 0, "offset": 0.1},
                        {"through": "A", "angle": 60}]}])),
        "L5": mechanism(**crank_base(points=q, groups=[
            {"kind": "L5", "links": ["u", "w"], "at": "A", "slot": 80, "point": "W",
             "guide": {"through": "C", "angle": 10, "offset": 0.05}}])),
    }


KINDS = kinds()


@pytest.mark.parametrize("name", sorted(KINDS))
def test_every_kind_builds_solves_and_decomposes(name):
    mech = KINDS[name]
    built, res, _ = solved_points(mech)
    assert res.breaks == (), [b.describe() for b in res.breaks]
    mob, dec = analyze(built.model)
    assert mob.ok and dec.formula == mech.formula
    assert [g.kind for g in dec.groups] == ["L0", *(groups_module.KIND[g.kind]
                                                    for g in mech.groups)]
    # the input keeps its direction: its vector is turned by the argument itself
    assert built.model.vectors[1].a.argument == 1 and built.model.vectors[1].a.offset == 0


def test_rrr_joint_distances_and_coupler_point():
    _, _, p = solved_points(KINDS["L1"])
    close(np.abs(p["A"] - p["O"]), 0.1, "|OA|")
    close(np.abs(p["B"] - p["A"]), 0.25, "|AB|")
    close(np.abs(p["B"] - p["D"]), 0.35, "|BD|")
    close(np.abs(p["Q"] - p["D"]), 0.2, "|DQ|")
    # Q at 20 deg from the line of the second link, D -> B (pivot to pin)
    close(wrap(np.angle(p["Q"] - p["D"]) - np.angle(p["B"] - p["D"]) - math.radians(20)),
          0, "angle of Q")


def test_rrp_rod_length_and_slider_on_its_guide():
    _, _, p = solved_points(KINDS["L2"])
    close(np.abs(p["B"] - p["A"]), 0.4, "|AB|")
    close(signed_distance(p["B"], p["C"], unit(-30)), 0.02, "B 0.02 m left of the guide")
    close(np.abs(p["Q"] - p["B"]), 0.2, "|BQ|")
    # the slider does not turn: Q keeps its bearing from B, 20 deg from the guide direction
    close(wrap(np.angle(p["Q"] - p["B"]) - math.radians(-30 + 20)), 0, "slider angle")


def test_rrp_on_a_guide_fixed_in_a_moving_link():
    _, _, p = solved_points(KINDS["L2 on a moving guide"])
    close(np.abs(p["E"] - p["A"]), 0.35, "|AE|")
    close(np.abs(p["G"] - p["D"]), 0.1, "|DG|")
    rocker_line = p["B"] - p["D"]  # the rocker's line: pivot D to pin B
    close(wrap(np.angle(p["G"] - p["D"]) - np.angle(rocker_line) - math.radians(40)), 0,
          "G on the rocker")
    direction = rocker_line / np.abs(rocker_line) * unit(70)
    close(signed_distance(p["E"], p["G"], direction), -0.03, "E on the turning guide")
    # variant 2: E behind A along the guide direction
    assert ((np.conj(direction) * (p["E"] - p["A"])).real < 0).all()


def test_rpr_block_stays_on_the_line_through_the_pivot():
    _, _, p = solved_points(KINDS["L3"])
    close(np.abs(p["Q"] - p["C"]), 0.5, "|CQ|")
    lever = p["Q"] - p["C"]
    block = p["A"] - p["C"]
    # the lever's line runs from its pivot C towards the block's pin A; Q is 15 deg off it
    close(wrap(np.angle(lever) - np.angle(block) - math.radians(15)), 0, "lever turns "
          "with the line C->A")


def test_prp_joint_lies_on_both_guides():
    _, res, p = solved_points(KINDS["L4"])
    theta = res.arguments[1]
    close(signed_distance(p["B"], p["C"], unit(0)), 0.1, "B on the ground guide")
    crank = np.exp(1j * theta)
    close(signed_distance(p["B"], p["A"], crank * unit(60)), 0, "B on the crank's guide")
    # the second slider turns with the crank: Q keeps 20 deg from its guide direction
    close(wrap(np.angle(p["Q"] - p["B"]) - theta - math.radians(60 + 20)), 0, "slider 2")


def test_rpp_block_in_the_slot_and_yoke_on_its_guide():
    _, _, p = solved_points(KINDS["L5"])
    close(signed_distance(p["W"], p["C"], unit(10)), 0.05, "W on the guide")
    close(signed_distance(p["A"], p["W"], unit(10 + 80)), 0, "A in the slot through W")
    close(np.abs(p["Q"] - p["W"]), 0.2, "|WQ|")
    close(wrap(np.angle(p["Q"] - p["W"]) - math.radians(30)), 0, "the yoke only slides")


def test_slider_input_is_driven_along_its_guide():
    mech = mechanism(
        positions=20, arguments={1: {"table": {0: 0.1, 20: 0.3}}},
        ground={"O": [0, 0], "C": [0.2, 0.3]},
        input={"kind": "slider", "guide": {"through": "O", "angle": 20, "offset": 0.01},
               "joint": "B", "shift": 0.05},
        groups=[{"kind": "L1", "links": ["l1", "l2"], "at": ["B", "C"], "joint": "D",
                 "lengths": [0.3, 0.2]}])
    built, res, p = solved_points(mech)
    along = (np.conj(unit(20)) * p["B"]).real
    close(along, res.arguments[1] + 0.05, "slider position = argument + shift")
    close(signed_distance(p["B"], 0, unit(20)), 0.01, "slider offset")
    close(np.abs(p["D"] - p["B"]), 0.3, "|BD|")
    assert analyze(built.model)[1].formula == "L0(1) → L1(2,3)"


# ------------------------------------------------------------------ assembly variants


@pytest.mark.parametrize("order", [("A", "D"), ("D", "A")])
def test_rrr_variants_are_mirror_images(order):
    """Variant 1 puts the joint on the left of at[0] -> at[1], variant 2 is its mirror
    image in that line — also when the dyad is listed from its ground end."""
    p1, p2 = order
    out = {}
    for variant in (1, 2):
        mech = mechanism(**crank_base(groups=[
            {"kind": "L1", "links": ["u", "w"], "at": [p1, p2], "joint": "B",
             "lengths": [0.3, 0.25], "variant": variant}]))
        built, _, out[variant] = solved_points(mech)
        assert built.model.vectors[1].name == "crank OA"
    a, b = out[1][p1], out[1][p2]
    left = signed_distance(out[1]["B"], a, b - a)
    assert (left > 0).all()
    d = (b - a) / np.abs(b - a)
    mirror = a + d * np.conj((out[1]["B"] - a) / d)
    close(out[2]["B"], mirror, "variant 2 mirrors variant 1")


def test_rrp_variants_are_mirror_images_across_the_normal_to_the_guide():
    out = {}
    for variant in (1, 2):
        mech = mechanism(**crank_base(groups=[
            {"kind": "L2", "links": ["u", "w"], "at": "A", "joint": "B", "length": 0.3,
             "guide": {"through": "O", "angle": 20, "offset": -0.02}, "variant": variant}]))
        _, _, out[variant] = solved_points(mech)
    u = unit(20)
    foot = (np.conj(u) * out[1]["A"]).real * u + (-0.02) * 1j * u  # A's foot on B's line
    close(out[1]["B"] + out[2]["B"], 2 * foot, "variants symmetric about A's foot")
    assert ((np.conj(u) * (out[1]["B"] - out[1]["A"])).real > 0).all()  # 1: ahead of A


# ------------------------------------------------------------------------ the examples


@pytest.mark.parametrize("path", GROUP_EXAMPLES, ids=lambda p: p.name)
def test_example_formula_and_schema(path: Path):
    data = yaml.safe_load(path.read_text())
    jsonschema.validate(json_ready(data), group_json_schema())
    mech = GroupMechanism.model_validate(data)
    mob, dec = analyze(mechloop.load_model(path))
    assert mob.ok and dec.formula == mech.formula
    assert dec.formula == {"four_bar_groups.yaml": "L0(1) → L1(2,3)",
                           "four_bar_groups_synthesis.yaml": "L0(1) → L1(2,3)",
                           "crank_slider_groups.yaml": "L0(1) → L2(2,3)",
                           "six_bar_groups.yaml": "L0(1) → L1(2,3) → L2(4,5)",
                           "class3_six_bar_groups.yaml": "L0(1) → III(2,3,4,5)",
                           "roof_support_groups.yaml": "L0(1,2,3)"}[path.name]
    assert all(g.variant in (1, None) for g in dec.groups)


def json_ready(data: Any) -> Any:
    """The JSON form of a YAML document (mapping keys are strings)."""
    if isinstance(data, dict):
        return {str(k): json_ready(v) for k, v in data.items()}
    if isinstance(data, list):
        return [json_ready(v) for v in data]
    return data


def test_six_bar_example_matches_its_comment():
    _, _, p = solved_points(GroupMechanism.model_validate(yaml.safe_load(
        (EXAMPLES / "six_bar_groups.yaml").read_text())))
    swing = np.degrees(np.ptp(np.unwrap(np.angle(p["B"] - p["C"]))))
    assert 46 < swing < 48, "the header promises a 47 deg swing of the bell crank"
    assert 154 < 1000 * np.ptp(p["E"].real) < 156, "... and a 155 mm stroke"
    close(p["E"].imag, -0.22, "the ram runs along y = -220 mm")


# ------------------------------------------------------- points and dimension carriers


def test_point_vectors_name_the_chain_and_the_vector_end():
    mech = KINDS["L2 on a moving guide"]
    model = build_model(mech)
    res = mechloop.solve(model)
    placement = Placement(res)
    for name in ("A", "B", "E", "G", "Q"):
        where = point_vectors(mech, model, name)
        total = complex(*where.start) + sum(
            math.copysign(1, k) * placement.vector(abs(k)).z for k in where.vectors)
        close(total, placement.point(where.end).z, f"chain of {name}")
    assert point_vectors(mech, model, "O").vectors == ()
    with pytest.raises(mechloop.ModelError, match="no point named 'Z'"):
        point_vectors(mech, model, "Z")
    with pytest.raises(mechloop.ModelError, match="not built from this mechanism"):
        point_vectors(mech, build_model(KINDS["L1"]), "A")


def changed(model: mechloop.Model, target: str, value: float) -> mechloop.Model:
    """``model`` with the part ``target`` ('r2', 'a5.delta', 'a1.offset') set to value."""
    data = model.model_dump(mode="python")
    name, _, part = target.partition(".")
    role = data["vectors"][int(name[1:])][name[0]]
    if part:
        role[part] = value
    else:
        data["vectors"][int(name[1:])][name[0]] = value
    return mechloop.Model.model_validate(data)


CHANGES = [  # (mechanism, dimension, how to change it in the document, new value)
    ("L2 on a moving guide", "groups[0].lengths[1]", ("groups", 0, "lengths", 1), 0.21),
    ("L2 on a moving guide", "groups[1].guide.angle", ("groups", 1, "guide", "angle"), 75.0),
    ("L2 on a moving guide", "groups[1].guide.offset", ("groups", 1, "guide", "offset"),
     -0.01),
    ("L2 on a moving guide", "points.G.angle", ("points", "G", "angle"), 50.0),
    ("L2 on a moving guide", "points.Q.distance", ("points", "Q", "distance"), 0.15),
    ("L5", "groups[0].slot", ("groups", 0, "slot"), 70.0),
    ("L4", "groups[0].guides[1].angle", ("groups", 0, "guides", 1, "angle"), 55.0),
    ("L1", "input.length", ("input", "length"), 0.09),
    ("L1", "input.angle", ("input", "angle"), 15.0),
]


@pytest.mark.parametrize(("kind", "dimension", "where", "value"), CHANGES,
                         ids=[c[1] for c in CHANGES])
def test_changing_the_carrier_is_changing_the_dimension(kind, dimension, where, value):
    """Setting a dimension's carrier parameters (value = dimension + shift) moves the
    mechanism exactly as rebuilding it with the new dimension does."""
    mech = KINDS[kind]
    built = build(mech)
    carriers = built.dimensions[dimension]
    model = built.model
    for c in carriers:
        model = changed(model, c.target, value + c.shift)
    data = mech.model_dump(mode="json", by_alias=True, exclude_defaults=True)
    data.setdefault("input", {}).setdefault("kind", "crank")
    node = data
    for key in where[:-1]:
        node = node[key]
    node[where[-1]] = value
    rebuilt = build(GroupMechanism.model_validate(copy.deepcopy(data)))
    assert [c.vectors for c in rebuilt.model.contours] == [c.vectors for c in model.contours]
    moved, reference = mechloop.solve(model), mechloop.solve(rebuilt.model)
    for name, where_ in rebuilt.points.items():
        x, y = where_.xy(reference)
        x2, y2 = built.points[name].xy(moved)
        close(x2 + 1j * y2, x + 1j * y, f"point {name}")


def test_ground_points_are_carried_in_polar_form_from_the_root():
    dims = dimension_parameters(KINDS["L1"])
    (distance,), (direction,) = dims["ground.D.distance"], dims["ground.D.direction"]
    model = build_model(KINDS["L1"])
    frame = model.vectors[int(distance.parameter[1:])]
    assert (frame.r, frame.a) == (0.3 + distance.shift, 0.0 + direction.shift)
    assert "ground.O.distance" not in dims  # the root places the contours only


# ----------------------------------------------------------------------- bad input


def problems_of(data: dict[str, Any]) -> list[mechloop.Problem]:
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.Model.from_dict(data)
    return list(info.value.problems)


def four_bar_data(**group: Any) -> dict[str, Any]:
    g = {"kind": "L1", "links": ["coupler", "rocker"], "at": ["A", "D"], "joint": "B",
         "lengths": [0.25, 0.35], **group}
    return crank_base(groups=[{k: v for k, v in g.items() if v is not None}])


def test_unknown_point_is_named_with_the_points_to_choose_from():
    (p,) = problems_of(four_bar_data(at=["A", "X"]))
    assert p.path == ("groups", 0, "at", 1)
    assert "unknown point 'X'" in p.message and "O, C, D, A" in p.hint


def test_point_of_a_later_group_is_not_yet_defined():
    data = crank_base(groups=[
        {"kind": "L1", "links": ["a", "b"], "at": ["A", "E"], "joint": "B",
         "lengths": [0.3, 0.3]},
        {"kind": "L1", "links": ["c", "d"], "at": ["A", "D"], "joint": "E",
         "lengths": [0.3, 0.3]}])
    problems = problems_of(data)
    assert problems[0].path == ("groups", 0, "at", 1)
    assert "not defined yet" in problems[0].message
    assert "groups[1]" in problems[0].hint and "move this group after" in problems[0].hint


def test_missing_dimension_names_the_group_and_what_to_add():
    (p,) = problems_of(four_bar_data(lengths=None))
    assert p.path == ("groups", 0, "lengths")
    assert "'lengths' is required" in p.message and "lengths: [" in p.hint


def test_an_internal_joint_needs_its_link():
    data = four_bar_data()
    data["groups"].append({"kind": "L2", "links": ["rod", "slider"], "at": "B", "joint": "E",
                           "length": 0.2, "guide": {"through": "O"}})
    (p,) = problems_of(data)
    assert p.path == ("groups", 1, "at")
    assert "coupler.B or rocker.B" in p.hint
    data["groups"][1]["at"] = "rocker.B"
    mechloop.solve(mechloop.Model.from_dict(data))


def test_every_problem_is_reported_at_once_with_its_fix():
    data = four_bar_data(at=["A", "Z"], lengths=[0.25, "-3 mm"])
    data["groups"].append({"kind": "L4", "links": ["s", "t"], "joint": "E", "variant": 2,
                           "guides": [{"through": "O"}, {"through": "C", "angle": 90}]})
    data["points"] = {"P": {"link": "crank", "from": "Q", "distance": 0.1}}
    data["masses"] = {"couplr": {"mass": 1, "center": {"share": 0.5}}}
    found = {(p.path, p.message.split(":")[0]) for p in problems_of(data)}
    assert {path for path, _ in found} == {
        ("groups", 0, "at", 1), ("groups", 0, "lengths", 1), ("groups", 1, "variant"),
        ("points", "P", "from"), ("masses", "couplr")}
    assert all(p.hint for p in problems_of(data))


def test_broken_core_values_are_reported_with_the_structural_problems():
    """Schema problems inside the core sections (a dimension that is a list, a pair one
    value short, a variant out of range, a ground point without y) are reported together
    with the builder's problems of the rest — and nothing about the stand-ins: the point
    O stays defined, the replaced values are not called wrong twice."""
    data = four_bar_data(at=["A", "X"], lengths=[0.25], variant=7)
    data["input"]["length"] = [0.1]
    data["input"]["angle"] = [3]
    data["ground"]["O"] = [0]
    data["groups"].append({"kind": "L1", "links": ["p", "q"], "at": ["B", "Z"],
                           "joint": "E", "lengths": ["x", 0.2]})
    data["points"] = {"P": {"link": "couplr", "from": "A", "distance": 0.1},
                      "R": {"link": "coupler", "from": "A", "distance": [1]}}
    found = {p.path for p in problems_of(data)}
    assert found == {
        ("input", "length"), ("input", "angle"), ("ground", "O", 1),  # schema
        ("groups", 0, "lengths", 1), ("groups", 0, "variant"),
        ("groups", 1, "lengths", 0), ("points", "R", "distance"),
        ("groups", 0, "at", 1), ("groups", 1, "at", 1), ("points", "P", "link")}  # built
    assert all(p.hint for p in problems_of(data) if p.path[0] == "groups")


def test_a_broken_name_or_kind_still_reports_the_schema_problems_only():
    """No stand-in for a name (it would make up a point): the schema problem alone."""
    data = four_bar_data(at=["A", "X"], joint=["B"])
    assert {p.path for p in problems_of(data)} == {("groups", 0, "joint")}


def test_file_errors_name_the_file_line_and_fix(tmp_path):
    text = (EXAMPLES / "four_bar_groups.yaml").read_text()
    bad = tmp_path / "bad.yaml"
    bad.write_text(text.replace("at: [A, C]", "at: [A, K]").replace("lengths: [350, 250]",
                                                                     "lengths: [350]"))
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.load_model(bad)
    message = str(info.value)
    lines = text.splitlines()
    at_line = next(i for i, s in enumerate(lines, 1) if "at: [A, C]" in s)
    length_line = next(i for i, s in enumerate(lines, 1) if "lengths: [350, 250]" in s)
    assert f"bad.yaml:{length_line}, groups[0].lengths" in message
    # the shape error and the unknown point at once (the lengths get a stand-in)
    assert f"bad.yaml:{at_line}, groups[0].at[1]: unknown point 'K'" in message
    bad.write_text(text.replace("at: [A, C]", "at: [A, K]"))
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.load_model(bad)
    assert f"bad.yaml:{at_line}, groups[0].at[1]: unknown point 'K'" in str(info.value)
    assert "fix:" in str(info.value)


def test_a_file_with_vectors_and_groups_is_refused(tmp_path):
    data = yaml.safe_load((EXAMPLES / "four_bar_groups.yaml").read_text())
    data["vectors"] = {1: {"r": 1, "a": 0}}
    path = tmp_path / "mixed.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(mechloop.ModelError, match="belongs to a vector model"):
        mechloop.load_model(path)


def test_unknown_group_kind_lists_the_kinds():
    (p,) = problems_of(four_bar_data(kind="L6"))
    assert p.path == ("groups", 0) and "L5 (RPP)" in p.hint


# ------------------------------------------------------------- property: closed forms


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(dims=grashof_crank_rocker(), ground=st.floats(-180, 180), theta0=st.floats(-180, 180),
       variant=st.sampled_from([1, 2]), flip=st.booleans())
def test_random_four_bars_match_circle_intersection(dims, ground, theta0, variant, flip):
    a, b, c, g = dims
    pivot = g * unit(ground)
    at = ["C", "A"] if flip else ["A", "C"]
    lengths = [c, b] if flip else [b, c]
    mech = mechanism(positions=24, arguments={1: {"table": {0: theta0, 24: theta0 + 360}}},
                     ground={"O": [0, 0], "C": [pivot.real, pivot.imag]},
                     input={"kind": "crank", "pivot": "O", "joint": "A", "length": a},
                     groups=[{"kind": "L1", "links": ["u", "w"], "at": at, "joint": "B",
                              "lengths": lengths, "variant": variant}])
    _, _, p = solved_points(mech)
    theta = np.radians(theta0 + 15.0 * np.arange(25))
    crank = a * np.exp(1j * theta)
    first, second = (pivot, crank) if flip else (crank, pivot)
    r1, r2 = lengths
    left = circle_intersection(first, r1, second, r2)
    expected = left if variant == 1 else circle_intersection(second, r2, first, r1)
    close(p["B"], expected, "joint B", 1e-9 * max(a, b, c, g))
    close(p["A"], crank, "crank pin", 1e-12 * a)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(a=st.floats(0.02, 0.5), e_share=st.floats(-0.5, 0.5), ratio=st.floats(1.3, 5.0),
       guide=st.floats(-180, 180), theta0=st.floats(-180, 180), variant=st.sampled_from([1, 2]))
def test_random_slider_cranks_match_the_slider_crank_formula(a, e_share, ratio, guide, theta0,
                                                             variant):
    e = e_share * a
    b = (a + abs(e)) * ratio
    mech = mechanism(positions=24, arguments={1: {"table": {0: theta0, 24: theta0 + 360}}},
                     ground={"O": [0, 0]},
                     input={"kind": "crank", "pivot": "O", "joint": "A", "length": a},
                     groups=[{"kind": "L2", "links": ["rod", "slider"], "at": "A",
                              "joint": "B", "length": b, "variant": variant,
                              "guide": {"through": "O", "angle": guide, "offset": e}}])
    _, _, p = solved_points(mech)
    beta = np.radians(theta0 + 15.0 * np.arange(25) - guide)
    # textbook: x = a cos β ± sqrt(b² − (e − a sin β)²) along the guide, e to its left
    x = a * np.cos(beta) + (1 if variant == 1 else -1) * np.sqrt(
        b**2 - (e - a * np.sin(beta)) ** 2)
    expected = (x + 1j * e) * unit(guide)
    close(p["B"], expected, "slider pin B", 1e-9 * b)


# ------------------------------------------------------------------------------ docs


def test_docstring_examples_run():
    """The docstring examples of every module of the groups package run."""
    import importlib
    import pkgutil

    attempted = 0
    for info in pkgutil.iter_modules(groups_module.__path__):
        module = importlib.import_module(f"{groups_module.__name__}.{info.name}")
        attempted += doctest.testmod(module, raise_on_error=True).attempted
    assert attempted > 0


def test_group_model_saves_as_a_vector_model(tmp_path):
    model = mechloop.load_model(EXAMPLES / "six_bar_groups.yaml")
    mechloop.save_model(model, tmp_path / "six.yaml")
    again = mechloop.load_model(tmp_path / "six.yaml")
    assert again == model


def test_many_broken_values_report_the_schema_problems_without_stand_ins(monkeypatch):
    """Past MAX_STAND_INS broken values (each stand-in costs validations) only the schema
    problems are reported, still every one of them."""
    from mechloop.model import salvage

    monkeypatch.setattr(salvage, "MAX_STAND_INS", 1)
    data = four_bar_data(at=["A", "X"], lengths=[0.25], variant=7)
    assert {p.path for p in problems_of(data)} == {("groups", 0, "lengths", 1),
                                                   ("groups", 0, "variant")}
