"""Kinematic pairs inferred from the contours and the bodies (no ``joints:`` in the file).

* The bundled slider-crank without its ``joints:`` infers the four pairs the file names
  (O, A, B revolute; S prismatic along vector 3) and gives the same reactions and
  balancing moment.
* The V-twin (examples/v_engine.yaml with bodies: crank [1, 4], rods [2] and [5], pistons
  [3] and [6]) infers a main bearing, two crank-pin bearings on the same pin, two wrist
  pins and two cylinder slides; kinetostatics and virtual power agree on it.
* The Watt six-bar (examples/six_bar.yaml with bodies, the bell crank [3, 5]) infers its
  seven pins when its second contour is placed at C (``start: {tail: 4}``); placed at the
  origin, the bell crank would meet the ground at two points and the model says to give
  ``start``.
* A model whose bodies leave the force analysis undetermined says so.
* Physics does not depend on how bodies are numbered — pinned on a crank and slotted
  lever, whose prismatic pair joins two moving bodies.
* A given prismatic joint without ``at`` takes the point the schema documents (the tail
  of ``along``), and naming its bodies the other way round reverses its reaction.
"""

from __future__ import annotations

import numpy as np
import pytest
from oracles.dynamic_models import dynamics, example, four_bar, quick_return

from mechloop import ModelError

RTOL = 1e-9
FRICTION = {"coefficient": 0.1, "radius": 0.01, "length": 0.04}


def relative(a, b) -> float:
    return float(np.abs(np.asarray(a) - np.asarray(b)).max() / np.abs(b).max())


def pairs_of(d) -> dict[str, tuple[str, tuple[int, int]]]:
    return {p.name: (p.kind, p.bodies) for p in d.mechanism.pairs}


def test_example_without_joints_infers_the_same_pairs():
    given = dynamics(example("crank_slider_dynamics.yaml"))
    inferred = dynamics(example("crank_slider_dynamics.yaml", joints=None))
    assert pairs_of(inferred) == {"J0_1": ("revolute", (0, 1)), "J1_2": ("revolute", (1, 2)),
                                  "J2_3": ("revolute", (2, 3)),
                                  "J0_3": ("prismatic", (0, 3))}
    assert all(p.inferred for p in inferred.mechanism.pairs)
    assert not any(p.inferred for p in given.mechanism.pairs)
    assert relative(inferred.forces.balancing[1], given.forces.balancing[1]) <= RTOL
    same = {"J0_1": "O", "J1_2": "A", "J2_3": "B", "J0_3": "S"}
    for mine, theirs in same.items():
        a, b = inferred.forces.reactions[mine], given.forces.reactions[theirs]
        np.testing.assert_allclose(a.point.z, b.point.z, rtol=0, atol=1e-15, err_msg=mine)
        assert relative(a.force, b.force) <= RTOL, mine
    s, s_given = inferred.forces.reactions["J0_3"], given.forces.reactions["S"]
    assert inferred.mechanism.pairs[-1].along == 3
    assert relative(s.normal, s_given.normal) <= RTOL
    np.testing.assert_allclose(s.moment, s_given.moment, rtol=0,
                               atol=RTOL * np.abs(s_given.normal).max())


V_TWIN_BODIES = {
    1: {"name": "crank", "vectors": [1, 4], "mass": 2.0, "inertia": 0.004,
        "center": {"vector": 1, "share": 0.2}},
    2: {"name": "rod 1", "vectors": [2], "mass": 0.5, "inertia": "rod",
        "center": {"vector": 2, "share": 0.3}},
    3: {"name": "piston 1", "vectors": [3], "mass": 0.4, "center": {"tail": 3}},
    4: {"name": "rod 2", "vectors": [5], "mass": 0.5, "inertia": "rod",
        "center": {"vector": 5, "share": 0.3}},
    5: {"name": "piston 2", "vectors": [6], "mass": 0.4, "center": {"tail": 6}},
}


def test_v_twin_infers_its_pairs():
    data = example("v_engine.yaml", bodies=V_TWIN_BODIES,
                   forces=[{"body": 3, "at": {"tail": 3}, "value": 2000.0, "along": 3},
                           {"body": 5, "at": {"tail": 6}, "value": 500.0, "along": 6}],
                   gravity={"g": 9.81})
    d = dynamics(data)
    assert pairs_of(d) == {
        "J0_1": ("revolute", (0, 1)),  # main bearing O (met in both loops: one pair)
        "J1_2": ("revolute", (1, 2)), "J1_4": ("revolute", (1, 4)),  # both on the crank pin
        "J2_3": ("revolute", (2, 3)), "J4_5": ("revolute", (4, 5)),  # wrist pins
        "J0_3": ("prismatic", (0, 3)), "J0_5": ("prismatic", (0, 5)),  # cylinders
    }
    slides = {p.name: p.along for p in d.mechanism.pairs if p.kind == "prismatic"}
    assert slides == {"J0_3": 3, "J0_5": 6}
    r = d.forces.reactions
    np.testing.assert_allclose(r["J0_1"].point.z, 0.0, atol=1e-15)
    np.testing.assert_allclose(r["J1_2"].point.z, r["J1_4"].point.z, rtol=0, atol=1e-15)
    np.testing.assert_allclose(r["J1_2"].point.z,
                               0.04 * np.exp(1j * d.kinematics.value("a1")), rtol=0,
                               atol=1e-15)
    assert relative(d.forces.balancing[1], d.balancing_vp[1]) <= RTOL


SIX_BAR_BODIES = {
    1: {"name": "crank", "vectors": [1], "mass": 1.0, "center": {"vector": 1, "share": 0.5}},
    2: {"name": "coupler", "vectors": [2], "mass": 2.0, "inertia": "rod",
        "center": {"vector": 2, "share": 0.5}},
    3: {"name": "bell crank", "vectors": [3, 5], "mass": 2.0, "inertia": 0.01,
        "center": {"tail": 5}},
    4: {"name": "link", "vectors": [6], "mass": 1.0, "inertia": "rod",
        "center": {"vector": 6, "share": 0.5}},
    5: {"name": "output rocker", "vectors": [7], "mass": 1.0, "inertia": "rod",
        "center": {"vector": 7, "share": 0.5}},
}


def six_bar(start) -> dict:
    data = example("six_bar.yaml", bodies=SIX_BAR_BODIES, moments=[{"body": 5, "value": 3.0}])
    if start is None:
        data["contours"][1].pop("start", None)
    else:
        data["contours"][1]["start"] = start
    return data


def test_six_bar_placed_at_c_infers_seven_pins():
    d = dynamics(six_bar({"tail": 4}))
    assert pairs_of(d) == {
        "J0_1": ("revolute", (0, 1)), "J1_2": ("revolute", (1, 2)),
        "J2_3": ("revolute", (2, 3)), "J0_3": ("revolute", (0, 3)),
        "J3_4": ("revolute", (3, 4)), "J4_5": ("revolute", (4, 5)),
        "J0_5": ("revolute", (0, 5)),
    }
    # the bell crank's ground pivot is C = (0.3 m, 0), fixed
    np.testing.assert_allclose(d.forces.reactions["J0_3"].point.z, 0.3, rtol=0, atol=1e-15)
    assert relative(d.forces.balancing[1], d.balancing_vp[1]) <= RTOL


def test_six_bar_placed_at_the_origin_asks_for_start():
    with pytest.raises(ModelError) as info:
        dynamics(six_bar(None))
    assert "start" in str(info.value)
    assert "bodies 0 and 3 meet at 2 different points" in str(info.value)


def test_six_bar_placed_at_the_origin_gives_no_misleading_hint():
    """Vector 5 has a constant length: naming one of its ends in ``ends`` cannot help;
    every hint points to the contour's start."""
    with pytest.raises(ModelError) as info:
        dynamics(six_bar(None))
    for problem in info.value.problems:
        assert "ends" not in problem.hint and "start" in problem.hint, problem.render()


def test_undetermined_force_analysis_is_reported():
    """The rocker is not a body: 2 moving bodies, 2 pins, 1 drive — 6 equations, 5
    unknowns."""
    data = four_bar(0.1, 0.35, 0.25, 0.3, bodies={1: {"vectors": [1]}, 2: {"vectors": [2]}})
    with pytest.raises(ModelError) as info:
        dynamics(data)
    text = str(info.value)
    assert "not determinate" in text and "joints" in text


def test_renumbering_bodies_changes_nothing_without_friction():
    a = dynamics(quick_return(block=2, lever=3))
    b = dynamics(quick_return(block=3, lever=2))
    assert relative(b.forces.balancing[1], a.forces.balancing[1]) <= RTOL
    pin_a, pin_b = a.forces.reactions["J0_3"].force, b.forces.reactions["J0_2"].force
    assert relative(pin_b, pin_a) <= RTOL  # the lever's pivot C


def test_renumbering_bodies_changes_nothing_with_friction():
    """The friction force f·max(|N|, 2|M|/b) of the slide takes the reaction moment about
    the pair's point, which must be the block (the tail of vector 2) whichever of the
    block and the lever has the larger number."""
    a = dynamics(quick_return(block=2, lever=3, friction=FRICTION))
    b = dynamics(quick_return(block=3, lever=2, friction=FRICTION))
    for d in (a, b):
        np.testing.assert_array_equal(d.forces.reactions["J2_3"].point.z,
                                      d.placement.tail(2).z)
    assert relative(b.forces.balancing[1], a.forces.balancing[1]) <= RTOL
    fa = a.forces.reactions["J2_3"].friction
    fb = b.forces.reactions["J2_3"].friction
    assert relative(np.abs(fb), np.abs(fa)) <= RTOL


def test_given_prismatic_joint_defaults_to_the_tail_of_along():
    """model/dynamic.py, Joint: the normal force and moment are about ``at``, by default the
    tail of ``along`` (where a slider's vector starts) — whichever body is named first."""
    for bodies in ([0, 3], [3, 0]):
        data = example("crank_slider_dynamics.yaml")
        data["joints"]["S"] = {"type": "prismatic", "bodies": bodies, "along": 3}
        d = dynamics(data)
        np.testing.assert_allclose(d.forces.reactions["S"].point.z, d.placement.tail(3).z,
                                   rtol=0, atol=0, err_msg=str(bodies))


def test_given_prismatic_joint_reversed_bodies_reverse_the_reaction():
    """Whatever its reference point, naming the bodies the other way round reverses the
    pair's force and leaves the balancing moment alone."""
    data = example("crank_slider_dynamics.yaml")
    data["joints"]["S"] = {"type": "prismatic", "bodies": [3, 0], "along": 3,
                           "at": {"tail": 3}}
    reversed_ = dynamics(data)
    given = dynamics(example("crank_slider_dynamics.yaml"))
    assert relative(reversed_.forces.reactions["S"].force,
                    -given.forces.reactions["S"].force) <= RTOL
    assert relative(reversed_.forces.balancing[1], given.forces.balancing[1]) <= RTOL
