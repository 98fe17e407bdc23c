"""Bodies and joints that cannot be what they say are rejected with an error that names
them (STYLE 4: validate the whole model up front).

* A body whose vectors turn relative to each other (a four-bar's crank and coupler put in
  one body) raises :class:`mechloop.errors.ModelError` naming the body, the two vectors and
  the YAML path ``bodies[1].vectors[1]``.
* A centre of mass must be a point of its body.  On a vector of varying length only the
  end the body holds is fixed in it: a ``share`` of the length is rejected; a distance
  ``along`` from the tail is a point of the body that holds the tail, but not of a body
  that holds the head (``ends: {K: head}``, e.g. a hydraulic cylinder's barrel).
* A given joint must be a joint of its two bodies: a pin at a point fixed in both, a slide
  along the direction in which one body moves relative to the other.  Pinned on the
  bundled slider-crank with the crank-pin joint A moved to the main bearing O, and with
  the slide S turned to run along the connecting rod.
"""

from __future__ import annotations

import numpy as np
import pytest
from oracles.dynamic_models import dynamics, example, four_bar

from mechloop import ModelError


def test_body_whose_vectors_turn_is_named():
    data = four_bar(0.1, 0.35, 0.25, 0.3, bodies={1: {"vectors": [1, 2]}, 2: {"vectors": [3]}})
    with pytest.raises(ModelError) as info:
        dynamics(data)
    text = str(info.value)
    assert "body 1" in text and "vectors 1 and 2" in text and "bodies[1].vectors[1]" in text
    assert any(p.path == ("bodies", 1, "vectors", 1) for p in info.value.problems)


def test_body_with_mass_and_no_centre_is_named():
    data = four_bar(0.1, 0.35, 0.25, 0.3)
    data["bodies"][2]["mass"] = 1.0
    with pytest.raises(ModelError) as info:
        dynamics(data)
    assert "body 2 has a mass but no centre of mass" in str(info.value)


def cylinder(barrel_center: dict) -> dict:
    """examples/hydraulic_rocker.yaml with the leg, the barrel (holds the head of the
    cylinder vector 2, pivoted on the airframe) and the piston rod (holds its tail)."""
    return example(
        "hydraulic_rocker.yaml",
        bodies={1: {"vectors": [1, 4], "mass": 40.0, "inertia": 6.0,
                    "center": {"vector": 4, "share": 0.5}},
                2: {"name": "barrel", "vectors": [2], "ends": {2: "head"}, "mass": 6.0,
                    "inertia": 0.1, "center": barrel_center},
                3: {"name": "piston rod", "vectors": [2], "mass": 3.0, "inertia": 0.05,
                    "center": {"vector": 2, "along": 0.15}}},
        gravity={"g": 9.81})


def test_centre_at_a_share_of_a_sliding_vector_is_rejected():
    with pytest.raises(ModelError) as info:
        dynamics(cylinder({"vector": 2, "share": 0.5}))
    assert "changes length" in str(info.value)


def test_centre_at_the_held_end_of_a_sliding_vector_is_a_point_of_the_body():
    d = dynamics(cylinder({"head": 2}))
    g = d.placement.tail(3).z  # the barrel's pivot G = the head of vector 2
    assert np.abs(g - g[0]).max() <= 1e-15


def test_centre_along_a_sliding_vector_from_the_end_the_body_does_not_hold_is_rejected():
    """The barrel holds the head of vector 2; a point 0.1 m from its tail is fixed in the
    piston rod, and moves along the barrel as the rod extends."""
    with pytest.raises(ModelError) as info:
        dynamics(cylinder({"vector": 2, "along": 0.1}))
    assert any(p.path == ("bodies", 2, "center") for p in info.value.problems), \
        str(info.value)


def test_pin_that_is_not_a_point_of_both_bodies_is_rejected():
    data = example("crank_slider_dynamics.yaml")
    data["joints"]["A"]["at"] = {"tail": 1}  # O: on the crank, never on the rod
    with pytest.raises(ModelError) as info:
        dynamics(data)
    assert "joints.A" in str(info.value)


def test_slide_along_a_vector_the_bodies_do_not_slide_along_is_rejected():
    data = example("crank_slider_dynamics.yaml")
    data["joints"]["S"]["along"] = 2
    with pytest.raises(ModelError) as info:
        dynamics(data)
    assert "joints.S" in str(info.value)
