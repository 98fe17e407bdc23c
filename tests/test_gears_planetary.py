"""Planetary trains of mechloop.gears: Willis' ratio against mechloop's vector models
(the bundled example and the models the package writes), the rolling conditions, the
assembly condition against the carrier-turn argument in exact fractions, and the choice
of tooth numbers against a plain loop."""

from __future__ import annotations

import math
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.gears.planetary import SCHEMES, assembles, planetary_train
from mechloop.gears.tooth_search import choose_teeth
from mechloop.gears.vector_model import vector_model
from mechloop.gears.velocity_plan import velocity_plan
from mechloop.model.load import model_from_data
from mechloop.solve.kinematics import solve

ROOT = Path(__file__).resolve().parents[1]


def test_willis_ratio_equals_the_solved_ratio_of_the_bundled_example():
    # examples/planetary_reducer.yaml: sun 20, planet 30, ring 80 fixed, written by hand
    frame = solve(mechloop.load_model(ROOT / "examples" / "planetary_reducer.yaml")).to_frame()
    train = planetary_train("simple", {"a": 20, "g": 30, "b": 80}, 4)
    turn = frame["a1 [deg]"].to_numpy()
    moving = turn > 1.0
    carrier = frame["a2 [deg]"].to_numpy()[moving] / turn[moving]
    planet = frame["a3 [deg]"].to_numpy()[moving] / turn[moving]
    assert np.allclose(carrier, 1 / train.ratio, rtol=1e-12, atol=0)
    assert np.allclose(planet, train.speeds(1.0)["g"], rtol=1e-12, atol=0)
    assert train.ratio == 5.0


TRAINS = [("simple", {"a": 20, "g": 30, "b": 80}, 4),
          ("double_planet", {"a": 18, "g": 54, "f": 27, "b": 99}, 3),
          ("two_rings", {"a": 80, "g": 40, "f": 38, "b": 78}, 2),
          ("two_suns", {"a": 40, "g": 20, "f": 21, "b": 39}, 3)]


@pytest.mark.parametrize("scheme, teeth, k", TRAINS, ids=[t[0] for t in TRAINS])
def test_the_written_vector_model_rolls_without_slip(scheme, teeth, k):
    train = planetary_train(scheme, teeth, k, m_n=2.0)
    assert train.coaxial
    model = model_from_data(vector_model(train, positions=40))
    results = solve(model)
    assert not results.broken.any()
    frame = results.to_frame()
    w_a = frame["da1 [rad/s]"].to_numpy()
    w_h = frame["da2 [rad/s]"].to_numpy()
    w_g = frame["da3 [rad/s]"].to_numpy()
    radii = train.pitch_radii()
    s = train.scheme
    # the planet's points at its two meshes (inside for an external mesh, outside for a
    # ring) move with the central gear's pitch point there: ω_a r_a and 0 (b fixed)
    y_a = train.a_w - s.sigma_a * radii["g"]
    y_b = train.a_w - s.sigma_b * radii["f"]
    assert np.isclose(abs(y_a), radii["a"]) and np.isclose(abs(y_b), radii["b"])
    v_a = w_h * train.a_w + w_g * (y_a - train.a_w)
    v_b = w_h * train.a_w + w_g * (y_b - train.a_w)
    scale = np.abs(w_a).max() * radii["a"]
    assert np.max(np.abs(v_a - w_a * y_a)) < 1e-10 * scale
    assert np.max(np.abs(v_b)) < 1e-10 * scale
    # and the solved carrier turns 1/i_ah of the input, i_ah by Willis
    moving = np.abs(w_a) > 1e-9 * np.abs(w_a).max()
    assert np.allclose(w_h[moving] / w_a[moving], 1 / train.ratio, rtol=1e-10)


@pytest.mark.parametrize("scheme, teeth, k", TRAINS, ids=[t[0] for t in TRAINS])
def test_the_velocity_plan_meets_every_pitch_point(scheme, teeth, k):
    train = planetary_train(scheme, teeth, k, m_n=2.0)
    plan = velocity_plan(train, 1500.0)
    w = plan.omega
    assert w["a"] == pytest.approx(1500 * np.pi / 30)
    s = train.scheme
    y_a = plan.a_w - s.sigma_a * train.pitch_radii()["g"]
    y_b = plan.a_w - s.sigma_b * train.pitch_radii()["f"]
    assert float(plan.planet_speed(y_a)) == pytest.approx(w["a"] * plan.r_a, rel=1e-12)
    assert abs(float(plan.planet_speed(y_b))) < 1e-9 * w["a"] * plan.r_a
    assert float(plan.planet_speed(plan.a_w)) == pytest.approx(w["h"] * plan.a_w)


def _assembles_by_turning_the_carrier(scheme, z_a, z_g, z_f, z_b, k) -> bool:
    """The classical argument, in exact fractions: turn the carrier by 2π/k with b fixed;
    a turns i_ah·2π/k, shifting its teeth at the first planet's place by
    z_a·i_ah/k pitches while b's stay; a new planet fits there iff it can be turned so
    that row f stays matched to b (a turn of j/z_f of a revolution) and row g takes up
    a's shift: z_a·i_ah/k ≡ j·z_g/z_f (mod 1) for some whole j."""
    s = SCHEMES[scheme]
    ratio = 1 - Fraction(s.sigma_a * s.sigma_b * z_g * z_b, z_a * z_f)
    shift = Fraction(z_a) * ratio / k
    return any((shift - Fraction(j * z_g, z_f)).denominator == 1 for j in range(z_f))


@settings(max_examples=300, deadline=None)
@given(scheme=st.sampled_from(sorted(SCHEMES)), z_a=st.integers(12, 90),
       z_g=st.integers(12, 60), z_f=st.integers(12, 60), k=st.integers(2, 6))
def test_assembly_condition_against_the_carrier_turn(scheme, z_a, z_g, z_f, k):
    s = SCHEMES[scheme]
    if not s.double:
        z_f = z_g
    z_b = z_a + s.sigma_a * z_g - s.sigma_b * z_f  # coaxial
    if z_b < 8 or (s.sigma_a == -1 and z_a - z_g < 1):
        return
    expected = _assembles_by_turning_the_carrier(scheme, z_a, z_g, z_f, z_b, k)
    assert bool(assembles(s, z_a, z_g, z_f, z_b, k)) == expected
    if not s.double:
        assert expected == ((z_a + z_b) % k == 0)


def test_the_choice_of_teeth_is_what_a_plain_loop_finds():
    target, k, tol = 5.6, 3, 0.02
    choice = choose_teeth(SCHEMES["simple"], target, k, teeth_min=17, teeth_max=90,
                          tolerance=tol)
    found = set()
    for z_a in range(17, 91):
        for z_g in range(17, 91):
            z_b = z_a + 2 * z_g
            if z_b > 90 or z_b - z_g < 8:
                continue
            ratio = 1 + z_b / z_a
            if abs(ratio - target) / target > tol or (z_a + z_b) % k:
                continue
            if (z_g + 2) >= (z_a + z_g) * math.sin(math.pi / k):
                continue
            found.add((z_a, z_g, z_b))
    assert found and {(int(a), int(g), int(b)) for a, g, b in
                      zip(choice.z_a, choice.z_g, choice.z_b, strict=True)} == found
    assert np.all(np.diff(np.round(choice.error, 12)) >= 0)  # best ratio first
    best = choice.train(0)
    assert best.coaxial and best.assembles and best.neighbour_margin > 0


def test_a_two_row_choice_meets_every_condition():
    choice = choose_teeth(SCHEMES["double_planet"], 12.0, 3, teeth_min=17, teeth_max=100)
    assert len(choice) > 0
    for i in range(min(len(choice), 20)):
        train = choice.train(i)
        assert train.coaxial and train.assembles and train.neighbour_margin > 0
        assert abs(train.ratio - 12) <= 0.01 * 12 + 1e-12
        assert train.z_b - train.z_f >= 8
    assert (choice.z_a[0], choice.z_g[0], choice.z_f[0], choice.z_b[0]) == (18, 54, 27, 99)


def test_a_train_whose_carrier_cannot_turn_is_refused():
    from mechloop.errors import HintedError

    with pytest.raises(HintedError, match="i_ab"):
        planetary_train("two_rings", {"a": 80, "g": 30, "f": 30, "b": 80}, 2)
