"""The James train with any member held and the Wolfrom train, each ratio checked without
Willis' formula: the rolling of the planet at every pitch point written as linear equations
in the members' angular speeds and solved (numpy), and the velocity plans meeting every
pitch point; the Wolfrom assembly condition against the tooth phases at every planet."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechloop.errors import HintedError
from mechloop.gears.planetary import SCHEMES, member_ratio, planetary_train
from mechloop.gears.tooth_search import choose_teeth
from mechloop.gears.velocity_plan import velocity_plan, wolfrom_plan
from mechloop.gears.wolfrom import wolfrom_ratio, wolfrom_train

FIXINGS = [("b", "a"), ("b", "h"), ("a", "b"), ("a", "h"), ("h", "a"), ("h", "b")]
TRAINS = [("simple", {"a": 20, "g": 30, "b": 80}, 4),
          ("double_planet", {"a": 18, "g": 54, "f": 27, "b": 99}, 3),
          ("two_rings", {"a": 80, "g": 40, "f": 38, "b": 78}, 2),
          ("two_suns", {"a": 40, "g": 20, "f": 21, "b": 39}, 3)]


def _rolling_speeds_2kh(train, fixed: str, driver: str) -> dict[str, float]:
    """Speeds (a, h, p, b) from the pitch points alone: the planet (axis at a_w on the
    carrier, spin ω_p) moves at v(y) = ω_h a_w + ω_p (y − a_w) along the radius through
    its axis; at each mesh that speed is the central gear's ω r there."""
    r = train.pitch_radii()
    s = train.scheme
    y_a = train.a_w - s.sigma_a * r["g"]   # the planet's point at the mesh with a
    y_b = train.a_w - s.sigma_b * r["f"]   # … with b
    index = {"a": 0, "h": 1, "p": 2, "b": 3}
    rows = [[-y_a, train.a_w, y_a - train.a_w, 0.0],
            [0.0, train.a_w, y_b - train.a_w, -y_b]]
    rhs = [0.0, 0.0]
    for member, value in ((fixed, 0.0), (driver, 1.0)):
        row = [0.0] * 4
        row[index[member]] = 1.0
        rows.append(row)
        rhs.append(value)
    w = np.linalg.solve(np.array(rows), np.array(rhs))
    return dict(zip("ahpb", w, strict=True))


@pytest.mark.parametrize("fixed, driver", FIXINGS)
@pytest.mark.parametrize("scheme, teeth, k", TRAINS, ids=[t[0] for t in TRAINS])
def test_every_member_held_gives_the_ratio_of_the_rolling_planet(scheme, teeth, k, fixed,
                                                                  driver):
    train = planetary_train(scheme, teeth, k, m_n=2.0, fixed=fixed, driver=driver)
    w = _rolling_speeds_2kh(train, fixed, driver)
    output = train.output
    assert output not in (fixed, driver) and output in "abh"
    assert train.ratio == pytest.approx(1.0 / w[output], rel=1e-12)
    speeds = train.speeds(1.0)
    for member in "ahb":
        assert speeds[member] == pytest.approx(w[member], rel=1e-12, abs=1e-14)
    assert speeds["g"] == pytest.approx(w["p"], rel=1e-12, abs=1e-14)
    # the velocity plan meets both pitch points with the central gears' lines
    plan = velocity_plan(train, 1000.0)
    s, r = train.scheme, train.pitch_radii()
    y_a, y_b = plan.a_w - s.sigma_a * r["g"], plan.a_w - s.sigma_b * r["f"]
    scale = abs(plan.omega[driver]) * max(r.values())
    assert abs(float(plan.planet_speed(y_a)) - plan.omega["a"] * y_a) < 1e-12 * scale
    assert abs(float(plan.planet_speed(y_b)) - plan.omega["b"] * y_b) < 1e-12 * scale


def test_the_james_train_textbook_ratios():
    # sun 20, planet 30, ring 80 (i_ab^h = −4): ring held 1 + 80/20 = 5, sun held
    # 1 + 20/80 = 1.25, carrier held −80/20 = −4, and their inverses
    w = -4.0
    expected = {("b", "a"): 5.0, ("b", "h"): 0.2, ("a", "b"): 1.25, ("a", "h"): 0.8,
                ("h", "a"): -4.0, ("h", "b"): -0.25}
    for (fixed, driver), ratio in expected.items():
        assert float(member_ratio(w, fixed, driver)) == pytest.approx(ratio, rel=1e-15)
    with pytest.raises(HintedError, match="two different members"):
        member_ratio(w, "a", "a")


def test_the_choice_for_a_held_sun_is_what_a_plain_loop_finds():
    target, k, tol = 1.3, 3, 0.01
    choice = choose_teeth(SCHEMES["simple"], target, k, teeth_min=17, teeth_max=100,
                          tolerance=tol, fixed="a", driver="b")
    found = set()
    for z_a in range(17, 101):
        for z_g in range(17, 101):
            z_b = z_a + 2 * z_g
            if z_b > 100 or z_b - z_g < 8 or (z_a + z_b) % k:
                continue
            if abs(1 + z_a / z_b - target) / target > tol:
                continue
            if (z_g + 2) >= (z_a + z_g) * math.sin(math.pi / k):
                continue
            found.add((z_a, z_g, z_b))
    assert found and {(int(a), int(g), int(b)) for a, g, b in
                      zip(choice.z_a, choice.z_g, choice.z_b, strict=True)} == found
    best = choice.train(0)
    assert (best.fixed, best.driver, best.output) == ("a", "b", "h")
    assert abs(best.ratio - target) <= tol * target


# ------------------------------------------------------------------------------ Wolfrom
WOLFROM = {"a": 15, "g": 24, "f": 21, "b": 63, "e": 60}


def _rolling_speeds_wolfrom(train) -> dict[str, float]:
    """(a, h, p, b, e) from the three pitch points of the stepped planet, a = 1, b = 0."""
    r = train.pitch_radii()
    a_w = train.a_w
    y_a, y_b, y_e = a_w - r["g"], a_w + r["g"], a_w + r["f"]
    rows = [[-y_a, a_w, y_a - a_w, 0.0, 0.0],
            [0.0, a_w, y_b - a_w, -y_b, 0.0],
            [0.0, a_w, y_e - a_w, 0.0, -y_e],
            [1.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 1.0, 0.0]]
    w = np.linalg.solve(np.array(rows), np.array([0.0, 0.0, 0.0, 1.0, 0.0]))
    assert np.isclose(y_a, r["a"]) and np.isclose(y_b, r["b"]) and np.isclose(y_e, r["e"])
    return dict(zip("ahpbe", w, strict=True))


def test_the_wolfrom_example_train():
    train = wolfrom_train(WOLFROM, 3, m_n=1.5)
    # (1 + 63/15)/(1 − 63·21/(24·60)) = 5.2/(117/1440) = 64 exactly
    assert Fraction(1) + Fraction(63, 15) == Fraction(26, 5)
    assert 1 - Fraction(63 * 21, 24 * 60) == Fraction(117, 1440)
    assert (Fraction(26, 5) / Fraction(117, 1440)) == 64
    assert train.carrier_ratio == pytest.approx(5.2, rel=1e-15)
    assert train.ratio == 64.0                        # exact: one division of integers
    assert train.coaxial and train.assembles and train.assembly == (26.0, 13.0)
    assert train.a_w == pytest.approx(1.5 * 39 / 2)
    assert train.neighbour_margin == pytest.approx(1.5 * (39 * math.sin(math.pi / 3) - 26))
    w = _rolling_speeds_wolfrom(train)
    assert 1.0 / w["e"] == pytest.approx(train.ratio, rel=1e-12)
    speeds = train.speeds(1.0)
    for member, key in (("a", "a"), ("h", "h"), ("g", "p"), ("b", "b"), ("e", "e")):
        assert speeds[member] == pytest.approx(w[key], rel=1e-12, abs=1e-15)


@settings(max_examples=200, deadline=None)
@given(z_a=st.integers(10, 60), z_g=st.integers(10, 50), z_f=st.integers(10, 50))
def test_the_wolfrom_ratio_is_that_of_the_rolling_planet(z_a, z_g, z_f):
    z_b = z_a + 2 * z_g
    z_e = z_a + z_g + z_f
    if z_b * z_f == z_g * z_e:
        return
    train = wolfrom_train({"a": z_a, "g": z_g, "f": z_f, "b": z_b, "e": z_e}, 3, m_n=2.0)
    assert train.coaxial
    w = _rolling_speeds_wolfrom(train)
    assert train.ratio == pytest.approx(1.0 / w["e"], rel=1e-9)
    assert float(wolfrom_ratio(z_a, z_g, z_f, z_b, z_e)) == train.ratio
    plan = wolfrom_plan(train, 100.0)
    r = train.pitch_radii()
    scale = abs(plan.omega["a"]) * r["e"]
    for y, member in ((r["a"], "a"), (r["b"], "b"), (r["e"], "e")):
        assert abs(float(plan.planet_speed(y)) - plan.omega[member] * y) < 1e-9 * scale


def _assembles_by_tooth_phases(z_a, z_g, z_f, z_b, z_e, k) -> bool:
    """Place planet i at θ_i = i/k of a turn.  Tooth phases in turns, mod 1: the sun's
    tooth phase at θ is z_a θ (sun at 0); a planet at angle ψ has the phase z_g (θ' − ψ)
    of row g at its own direction θ' and z_f (θ' − ψ) + c of row f (c the same for every
    planet: identical stepped planets).  An external mesh puts a space against a tooth
    (phases add to 1/2), an internal one likewise (ring phase minus planet phase 1/2).
    Ring b fixes ψ_i mod 1/z_g; the sun (its own angle free) must agree with it at every
    planet; so must ring e (its own angle free) with one of the z_g choices ψ_i + n/z_g."""
    def frac(x: Fraction) -> Fraction:
        return x - math.floor(x)

    psi, sun = [], []
    for i in range(k):
        theta = Fraction(i, k)
        # ring b (at angle 0): z_b θ − z_g (θ − ψ) ≡ 1/2  →  z_g ψ ≡ 1/2 − (z_b − z_g) θ
        base = (Fraction(1, 2) - (z_b - z_g) * theta) / z_g
        # the sun at an angle ψ_a of its own: z_a (θ − ψ_a) + z_g (θ + 1/2 − ψ) ≡ 1/2 for
        # ψ = base + n/z_g: z_a ψ_a must be this residue at every planet
        sun.append(frac(z_a * theta + z_g * (theta + Fraction(1, 2) - base) - Fraction(1, 2)))
        psi.append(base)
    if any(value != sun[0] for value in sun):
        return False
    # ring e: z_e (θ − ψ_e) − z_f (θ − ψ_i) − c ≡ 1/2 with one ψ_e and c for all planets:
    # the phase z_e θ_i − z_f (θ_i − ψ_i − n_i/z_g) must be the same mod 1 at every planet
    ref = frac(z_f * psi[0])
    for i in range(1, k):
        theta = Fraction(i, k)
        if not any(frac(z_e * theta - z_f * (theta - psi[i] - Fraction(n, z_g)) - ref) == 0
                   for n in range(z_g)):
            return False
    return True


@settings(max_examples=150, deadline=None)
@given(z_a=st.integers(10, 40), z_g=st.integers(10, 30), z_f=st.integers(10, 30),
       k=st.integers(2, 5))
def test_the_wolfrom_assembly_condition_against_the_tooth_phases(z_a, z_g, z_f, k):
    z_b = z_a + 2 * z_g
    z_e = z_a + z_g + z_f
    if z_b * z_f == z_g * z_e:
        return
    train = wolfrom_train({"a": z_a, "g": z_g, "f": z_f, "b": z_b, "e": z_e}, k)
    assert train.assembles == _assembles_by_tooth_phases(z_a, z_g, z_f, z_b, z_e, k)


def test_the_wolfrom_assembly_cases_both_ways():
    # the example: (15 + 63)/3 = 26 and (60·24 − 63·21)/(3·3) = 13, both whole
    assert _assembles_by_tooth_phases(15, 24, 21, 63, 60, 3)
    # four planets: (15 + 45)/4 = 15 whole, but (46·15 − 45·16)/(4·1) = −7.5 is not
    train = wolfrom_train({"a": 15, "g": 15, "f": 16, "b": 45, "e": 46}, 4)
    assert train.assembly == (15.0, -7.5) and not train.assembles
    assert not _assembles_by_tooth_phases(15, 15, 16, 45, 46, 4)
    # coaxial: z_e z_g − z_b z_f = (z_a + z_g)(z_g − z_f) and z_a + z_b = 2 (z_a + z_g), so
    # for an odd number of planets the second condition follows from the first
    assert 46 * 15 - 45 * 16 == (15 + 15) * (15 - 16)


def test_a_wolfrom_train_whose_output_cannot_turn_is_refused():
    with pytest.raises(HintedError, match="stand still"):
        wolfrom_train({"a": 20, "g": 20, "f": 20, "b": 60, "e": 60}, 3)
    with pytest.raises(HintedError, match="missing e"):
        wolfrom_train({"a": 20, "g": 20, "f": 20, "b": 60}, 3)


@pytest.mark.parametrize("fixed, driver", FIXINGS)
def test_the_written_vector_model_of_any_held_member_rolls_without_slip(fixed, driver):
    from mechloop.gears.vector_model import vector_model
    from mechloop.model.load import model_from_data
    from mechloop.solve.kinematics import solve

    train = planetary_train("double_planet", {"a": 18, "g": 54, "f": 27, "b": 99}, 3,
                            m_n=2.0, fixed=fixed, driver=driver)
    results = solve(model_from_data(vector_model(train, positions=40)))
    assert not results.broken.any()
    frame = results.to_frame()

    def rate(vector: int) -> np.ndarray:   # a held member's angle is a constant
        column = f"da{vector} [rad/s]"
        return frame[column].to_numpy() if column in frame else np.zeros(len(frame))

    w_a, w_h, w_g = rate(1), rate(2), rate(3)
    w_in = {"a": w_a, "h": w_h, "b": rate(8)}[driver]
    w_b = w_in if driver == "b" else w_in * train.speeds(1.0)["b"]
    r = train.pitch_radii()
    y_a, y_b = train.a_w - r["g"], train.a_w + r["f"]     # sun a, ring b
    scale = np.abs(w_in).max() * r["b"]
    assert scale > 0
    # the planet's points at both meshes move with the central gears' pitch points
    assert np.max(np.abs(w_h * train.a_w + w_g * (y_a - train.a_w) - w_a * y_a)) \
        < 1e-10 * scale
    assert np.max(np.abs(w_h * train.a_w + w_g * (y_b - train.a_w) - w_b * y_b)) \
        < 1e-10 * scale
    # the held member stands, the output turns 1/ratio of the driver
    held = {"a": w_a, "h": w_h, "b": w_b}[fixed]
    assert np.max(np.abs(held)) < 1e-12 * scale
    out = {"a": w_a, "h": w_h, "b": w_b}[train.output]
    moving = np.abs(w_in) > 1e-9 * np.abs(w_in).max()
    assert np.allclose(out[moving] / w_in[moving], 1 / train.ratio, rtol=1e-10)


def test_the_wolfrom_choice_is_what_a_plain_loop_finds():
    from mechloop.gears.tooth_search import choose_wolfrom_teeth

    target, k, tol, low, high = 64.0, 3, 0.01, 12, 70
    choice = choose_wolfrom_teeth(target, k, teeth_min=low, teeth_max=high, tolerance=tol)
    found = set()
    for z_a in range(low, high + 1):
        for z_g in range(low, high + 1):
            z_b = z_a + 2 * z_g
            if z_b > high or (z_a + z_b) % k:
                continue
            if (z_g + 2) >= (z_a + z_g) * math.sin(math.pi / k):
                continue
            for z_f in range(low, high + 1):
                z_e = z_a + z_g + z_f
                if z_e > high or z_b * z_f == z_g * z_e or (z_f + 2) >= (z_a + z_g) * \
                        math.sin(math.pi / k):
                    continue
                ratio = Fraction(z_a + z_b, z_a) / (1 - Fraction(z_b * z_f, z_g * z_e))
                if abs(ratio - Fraction(target)) > Fraction(tol) * Fraction(target):
                    continue
                if not _assembles_by_tooth_phases(z_a, z_g, z_f, z_b, z_e, k):
                    continue
                found.add((z_a, z_g, z_f, z_b, z_e))
    got = {tuple(int(v) for v in row) for row in
           zip(choice.z_a, choice.z_g, choice.z_f, choice.z_b, choice.z_e, strict=True)}
    assert found and got == found
    # the example's train is the best: the exact ratio and the smallest rings
    assert (choice.z_a[0], choice.z_g[0], choice.z_f[0], choice.z_b[0], choice.z_e[0]) == \
        (15, 24, 21, 63, 60)
    assert np.all(np.diff(np.round(choice.error, 12)) >= 0)
    best = choice.train(0, m_n=1.5)
    assert best.ratio == 64.0 and best.coaxial and best.assembles
