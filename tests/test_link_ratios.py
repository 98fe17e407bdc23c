"""Links with a ratio, ``α_i = k·α_j + Δ`` (``r_i = k·r_j + Δ``): gear pairs, gear trains
and a planetary reducer against the textbook ratio formulas computed here from the tooth
counts; random ratio chains against the composed formula and against finite differences
of the solved values; the design sensitivities through a ratio; the located errors.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import mechloop
from mechloop import ModelError, load_model
from mechloop.model.check import require_valid
from mechloop.solve.designs import solve_designs
from mechloop.solve.inputs import model_arguments, model_time
from mechloop.solve.kinematics import _setup, solve
from mechloop.solve.sensitivity import position_tangents

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
DEG = math.pi / 180


def _solved(name: str):
    return solve(load_model(EXAMPLES / name))


def test_gear_pair_turns_at_the_tooth_ratio() -> None:
    """z1 = 20 drives z2 = 50 (external): the wheel's angle, speed and acceleration are
    −z1/z2 times the pinion's at every position, and the pitch circles (R = m·z/2) roll
    without slipping: R1·ω1 = −R2·ω2."""
    res = _solved("gear_pair.yaml")
    z1, z2, m = 20, 50, 2e-3
    k = -z1 / z2
    a1, a3 = res.value("a1"), res.value("a3")
    np.testing.assert_allclose(a3, k * a1 + 90 * DEG, rtol=0, atol=1e-12)
    np.testing.assert_allclose(res.rate("a3"), k * res.rate("a1"), rtol=1e-13, atol=0)
    np.testing.assert_allclose(res.accel("a3"), k * res.accel("a1"), rtol=1e-13, atol=0)
    assert np.abs(res.accel("a1")).max() > 100  # a real acceleration, not a constant speed
    r1, r2 = m * z1 / 2, m * z2 / 2
    np.testing.assert_allclose(r1 * res.rate("a1"), -r2 * res.rate("a3"), rtol=1e-13, atol=0)
    # the mark-to-mark vector closes the loop O1 -> M1 -> M2 -> O2 -> O1 (centres 70 mm)
    x1, y1 = r1 * np.cos(a1), r1 * np.sin(a1)
    x2, y2 = (r1 + r2) - r2 * np.cos(a3), -r2 * np.sin(a3)
    np.testing.assert_allclose(res.value("r4"), np.hypot(x2 - x1, y2 - y1), atol=1e-15)
    assert not res.broken.any()


def test_compound_train_ratio_is_the_product_of_its_pairs() -> None:
    """20/50 then 25/50 on a common shaft: ω4/ω1 = (−z1/z2)(−z3/z4) = 1/5, the same sense;
    the two gears of shaft II turn together (a link with ratio 1)."""
    res = _solved("gear_train.yaml")
    z1, z2, z3, z4 = 20, 50, 25, 50
    i = (-z1 / z2) * (-z3 / z4)
    np.testing.assert_allclose(res.value("a3"), res.value("a2"), atol=0)
    np.testing.assert_allclose(res.value("a4"), i * res.value("a1") + 180 * DEG, atol=1e-12)
    for get in (res.rate, res.accel):
        np.testing.assert_allclose(get("a4"), i * get("a1"), rtol=1e-13, atol=0)
    # five input turns give one output turn, in the same sense
    turned = res.value("a4")[-1] - res.value("a4")[0]
    assert turned == pytest.approx(2 * math.pi, rel=1e-12)


def test_planetary_reducer_obeys_willis_formula() -> None:
    """Sun z1 = 20 in, ring z3 = 80 fixed, carrier out, planets z2 = 30.  Willis'
    formula (ω1 − ωH)/(ω3 − ωH) = −z3/z1 with ω3 = 0 holds for speeds and accelerations;
    the sun–planet mesh, which the model does not state (it links the planet through
    the ring's mesh), obeys its own formula (ω2 − ωH)/(ω1 − ωH) = −z1/z2; and the planet
    rolls on both pitch circles: the planet's points at the contacts move with the sun's
    pitch point and stand still at the ring."""
    res = _solved("planetary_reducer.yaml")
    z1, z2, z3, m = 20, 30, 80, 2e-3
    assert z3 == z1 + 2 * z2  # the centres line up
    r1, r2 = m * z1 / 2, m * z2 / 2
    for get in (res.rate, res.accel):
        w1, wh, w2 = get("a1"), get("a2"), get("a3")
        assert np.abs(wh).max() > 1
        np.testing.assert_allclose(w1 - wh, (-z3 / z1) * (0.0 - wh), rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(w2 - wh, (-z1 / z2) * (w1 - wh), rtol=1e-12, atol=1e-12)
        # rolling: planet point at the sun contact (C − R2·e_H) and at the ring (C + R2·e_H)
        np.testing.assert_allclose(wh * (r1 + r2) - w2 * r2, w1 * r1, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(wh * (r1 + r2) + w2 * r2, 0.0, atol=1e-12)
    # two sun turns: the carrier turns 2/5 of a turn, the planet 2/3 of a turn backwards
    a1, ah, a2 = (res.value(n) for n in ("a1", "a2", "a3"))
    assert ah[-1] - ah[0] == pytest.approx((a1[-1] - a1[0]) * z1 / (z1 + z3), rel=1e-12)
    assert a2[-1] - a2[0] == pytest.approx(-(2 / 3) * 2 * math.pi, rel=1e-12)
    assert not res.broken.any()


def test_setup_scales_hold_the_composed_ratio() -> None:
    """``_Setup.scales``: one entry per link name, the product of the ratios along its
    chain (rigid links 1.0), and ``deltas`` the composed constant."""
    model = load_model(EXAMPLES / "gear_train.yaml")
    structure = require_valid(model)
    setup = _setup(model, structure, model_arguments(model, model_time(model)))
    assert set(setup.scales) == set(structure.links)
    assert setup.scales["a3"] == pytest.approx(-0.4)
    assert setup.scales["a4"] == pytest.approx(0.2)
    assert setup.deltas["a4"] == pytest.approx(225 * DEG - 0.5 * 90 * DEG)
    assert structure.links["a4"].ratios == (-0.5, 1.0, -0.4)
    assert structure.links["a4"].root == "a1"


ratio = st.one_of(st.floats(-3.0, -0.2), st.floats(0.2, 3.0))


@settings(max_examples=25, deadline=None)
@given(ks=st.lists(ratio, min_size=1, max_size=4),
       ds=st.lists(st.floats(-180.0, 180.0), min_size=4, max_size=4),
       kr=st.lists(ratio, min_size=1, max_size=3),
       dr=st.lists(st.floats(-0.05, 0.05), min_size=3, max_size=3),
       stroke=st.floats(30.0, 400.0))
def test_random_ratio_chains_match_composition_and_differences(ks, ds, kr, dr, stroke):
    """A chain of angle links with random ratios and deltas from a driven angle, a chain
    of length links from a driven length, both in one loop closed by an unknown vector
    (Pl1): the values equal the composed formula, and every rate and acceleration —
    the links' and the closing vector's — equals finite differences of the solved values
    over a dense grid of a poly345 law (which has a real acceleration)."""
    assume(abs(math.prod(ks)) * stroke <= 360)  # at most a turn: differences resolve it
    n = 2000
    vectors: dict = {1: {"r": 0.3, "a": {"argument": 1}}}
    for i, k in enumerate(ks):
        vectors[2 + i] = {"r": 0.1, "a": {"link": f"a{1 + i}", "ratio": k, "delta": ds[i]}}
    last = 1 + len(ks)
    first_r = last + 1
    vectors[first_r] = {"r": {"argument": 2}, "a": 30.0}
    for i, k in enumerate(kr):
        vectors[first_r + 1 + i] = {"r": {"link": f"r{first_r + i}", "ratio": k,
                                          "delta": dr[i]}, "a": 10.0 * (i + 1)}
    close = max(vectors) + 1
    vectors[close] = {"r": "function", "a": "function"}
    model = mechloop.Model.from_dict({
        "units": {"length": "m", "angle": "deg"}, "positions": n,
        "time": {"table": {0: 0, n: 1.0}},
        "arguments": {1: {"law": "poly345", "start": [0, 0], "end": [n, stroke]},
                      2: {"law": "poly345", "start": [0, 0.2], "end": [n, 0.5]}},
        "vectors": vectors, "contours": [{"vectors": sorted(vectors)}]})
    res = solve(model)
    assert not res.broken.any()
    # the composed formula, link by link
    angle, scale = res.value("a1"), 1.0
    for i, k in enumerate(ks):
        angle = k * angle + ds[i] * DEG
        scale *= k
        np.testing.assert_allclose(res.value(f"a{2 + i}"), angle, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(res.rate(f"a{last}"), scale * res.rate("a1"), rtol=1e-12,
                               atol=1e-12)
    length = res.value(f"r{first_r}")
    for i, k in enumerate(kr):
        length = k * length + dr[i]
        np.testing.assert_allclose(res.value(f"r{first_r + 1 + i}"), length, rtol=1e-12,
                                   atol=1e-14)
    h = res.time[1] - res.time[0]  # uniform: the time table is linear
    names = [f"a{2 + i}" for i in range(len(ks))] + [f"r{first_r + 1 + i}"
                                                     for i in range(len(kr))]
    names += [f"r{close}", f"a{close}"]
    assume(res.value(f"r{close}").min() > 0.05)  # the closing vector's angle stays smooth
    for name in names:
        for value, derivative in ((res.value(name), res.rate(name)),
                                  (res.rate(name), res.accel(name))):
            # 5-point central differences (error O(h⁴))
            fd = (value[:-4] - 8 * value[1:-3] + 8 * value[3:-1] - value[4:]) / (12 * h)
            size = np.abs(derivative).max() + 1e-9
            assert np.abs(fd - derivative[2:-2]).max() < 2e-5 * size, name


def test_ratio_chain_design_sensitivity_matches_differences() -> None:
    """A slider-crank whose crank is the wheel of a gear pair, α1 = −0.5·α5 + 20°: the
    slider's derivative with respect to the link's own delta and to the pinion's angle
    offset (which reaches the crank times −0.5) against central differences."""
    model = mechloop.Model.from_dict({
        "units": {"length": "m", "angle": "deg"}, "positions": 36,
        "arguments": {1: {"table": {0: 0, 36: 720}}},
        "vectors": {5: {"r": 0.04, "a": {"argument": 1}}, 6: {"r": "function", "a": "function"},
                    1: {"r": 0.05, "a": {"link": "a5", "ratio": -0.5, "delta": 20}},
                    2: {"r": 0.2, "a": "function"}, 3: {"r": "function", "a": 180},
                    4: {"r": 0.01, "a": 90}},
        "contours": [{"vectors": [5, 6]}, {"vectors": [1, 2, 3, 4]}]})
    names = ["a1", "a5"]
    base = np.array([20 * DEG, 0.0])
    h = 1e-6
    rows = np.concatenate([base[None], base + h * np.eye(2), base - h * np.eye(2)])
    res = solve_designs(model, dict(zip(names, rows.T, strict=True)), derivatives=False)
    values = {k: np.asarray(t)[:1] for k, t in res.values.items()}
    seeds = {name: np.eye(2)[:, i][:, None, None] for i, name in enumerate(names)}
    tangents = position_tangents(model, values, seeds, 2)
    table = np.asarray(res.values["r3"])
    fd = (table[1:3] - table[3:5]) / (2 * h)
    np.testing.assert_allclose(tangents["r3"][:, 0], fd, rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(tangents["r3"][1, 0], -0.5 * tangents["r3"][0, 0], rtol=1e-12)
    assert np.abs(fd).max() > 0.01


def _model_problems(tmp_path: Path, text: str):
    file = tmp_path / "m.yaml"
    file.write_text(text)
    with pytest.raises(ModelError) as info:
        load_model(file)
    return info.value.problems, text


PAIR = (EXAMPLES / "gear_pair.yaml").read_text()


@pytest.mark.parametrize(("ratio", "words", "hint"), [
    ("0", "not 0", "-z1/z2"),
    (".inf", "outside the range", "finite number"),
    ("1/0", "divides by 0", "teeth over teeth"),
    ("fast", "valid number", "fraction of tooth counts"),
])
def test_bad_ratios_are_located_with_a_fix(tmp_path, ratio, words, hint) -> None:
    problems, text = _model_problems(tmp_path, PAIR.replace("ratio: -20/50", f"ratio: {ratio}"))
    (problem,) = problems
    assert problem.path[:3] == ("vectors", 3, "a") and problem.path[-1] == "ratio"
    assert words in problem.message and hint in problem.hint
    assert problem.line == text[:text.index(f"ratio: {ratio}")].count("\n") + 1


def test_a_ratio_between_kinds_and_onto_a_solved_angle_are_refused(tmp_path) -> None:
    """A length linked to an angle (with a ratio or not) is refused where it is written;
    an angle linked with a ratio to an angle its own coupled block solves (Newton's
    unknown is not kept continuous inside the iteration).  A ratio onto an angle an
    earlier contour solves is built (tests/test_ratio_solved_angles.py)."""
    problems, _ = _model_problems(tmp_path, PAIR.replace("3: {r: 50,",
                                                         "3: {r: {link: a1, ratio: 2},"))
    assert any(p.path == ("vectors", 3, "r") and "same kind" in p.message
               and "link to r1" in p.hint for p in problems)
    text = PAIR.replace("2: {r: 70, a: 180, name: frame}",
                        "2: {r: 70, a: 180, name: frame}\n"
                        "  5: {r: 10, a: {link: a4, ratio: 2}}").replace(
        "vectors: [1, 4, 3, 2] ", "vectors: [1, 4, 3, 2, 5]")
    problems, _ = _model_problems(tmp_path, text)
    (problem,) = problems
    assert problem.path == ("vectors", 5, "a", "ratio")
    assert "same block as contour 1" in problem.message and "earlier contour" in problem.hint


def test_a_ratio_is_refused_as_a_design_variable(tmp_path) -> None:
    """``vary: {a1.ratio: ...}`` names the ratio, which no synthesis varies: refused where
    it is written, with the link's delta as the fix."""
    text = (EXAMPLES / "log10_function_generator.yaml").read_text().replace(
        "    r1: [10, 200]\n", "    r1: [10, 200]\n    a1.ratio: [0.5, 2]\n")
    problems, _ = _model_problems(tmp_path, text)
    (problem,) = problems
    assert problem.path == ("synthesis", "vary", "a1.ratio")
    assert "not a design variable" in problem.message and "vary a1" in problem.hint


def test_structure_counts_a_gear_mesh_between_bodies(tmp_path) -> None:
    """Pinion and wheel as bodies: their mesh is a higher pair, counted as p4 (W = 3·2 −
    2·2 − 1 = 1, the one input), and replaced by its equivalent link with two revolute
    pairs for the decomposition: L0(1) → L1(2,3), the equivalent four-bar O1 N1 N2 O2.
    Never answered with the wheel as a link of its own mobility."""
    from mechloop.structure.analysis import analyze

    text = PAIR + ("bodies:\n"
                   "  1: {name: pinion, vectors: [1], mass: 1, inertia: 0.001, center: {tail: 1}}\n"
                   "  2: {name: wheel, vectors: [3], mass: 2, inertia: 0.01, center: {head: 3}}\n")
    file = tmp_path / "m.yaml"
    file.write_text(text)
    model = load_model(file)
    mob, dec = analyze(model)
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (2, 2, 1, 1, 1) and mob.ok
    assert "gear mesh (ratio link) between bodies 1 and 2, ratio -0.4" in str(mob)
    assert dec.formula == "L0(1) → L1(2,3)" and dec.mechanism_class == 2
    assert any("replaced by its equivalent, link 3" in note for note in dec.notes)


def _geared_rocker(ratio: float) -> mechloop.Model:
    """A non-Grashof four-bar (crank 0.2, coupler 0.3, rocker 0.3, frame 0.45 m: it
    assembles for |crank angle| ≤ acos(−0.653) ≈ 130.8°) whose crank is a wheel turned
    through ``ratio`` from a pinion driven over −180°…180°; the coupler is written as
    2/3 of the frame."""
    return mechloop.Model.from_dict({
        "units": {"length": "m", "angle": "deg"}, "positions": 72,
        "arguments": {1: {"table": {0: -180, 72: 180}}},
        "vectors": {5: {"r": 0.05, "a": {"argument": 1}},
                    6: {"r": "function", "a": "function"},
                    1: {"r": 0.2, "a": {"link": "a5", "ratio": ratio}},
                    2: {"r": {"link": "r4", "ratio": "2/3"}, "a": "function"},
                    3: {"r": 0.3, "a": "function"}, 4: {"r": 0.45, "a": 180}},
        "contours": [{"vectors": [5, 6]}, {"vectors": [1, 2, 3, 4]}]})


def test_existence_does_not_take_a_geared_crank_for_the_argument() -> None:
    """Through ratio 0.25 the crank sweeps ±45° and the linkage assembles throughout; the
    closed-form crank check (which assumes crank angle = argument + constant) is not
    applied to it.  Through ratio 1 the crank would need the whole turn: it does not."""
    from mechloop.solve.existence import (
        ExistenceCheck,
        _Resolver,
        assembles_throughout,
        crank_loops,
    )

    geared = _geared_rocker(0.25)
    check = ExistenceCheck(geared)
    assert crank_loops(_Resolver(check, {}, 1)) == []
    # a constant through a ratio, and through a ratio after its root is overridden
    assert _Resolver(check, {}, 1).value("r2") == pytest.approx([0.3])
    assert _Resolver(check, {"r4": np.array([0.6, 0.3])}, 2).value("r2") == pytest.approx(
        [0.4, 0.2])
    assert assembles_throughout(geared).feasible.tolist() == [True]
    assert not solve(geared).broken.any()
    rigid = _geared_rocker(1.0)
    assert [loop.info.number for loop in crank_loops(_Resolver(ExistenceCheck(rigid), {}, 1))
            ] == [2]
    assert assembles_throughout(rigid).feasible.tolist() == [False]


def test_designs_and_placement_carry_the_ratio() -> None:
    """``solve_designs`` equals ``solve`` through ratio links (a constant's link and a
    driven one, with overrides of a root); a similarity placement (turn 30°, scale 2)
    turns every angle of the gear pair by 30° — the delta of the ratio link gains
    (1 − k)·30° — and doubles every length."""
    from mechloop.synthesis.shape import place_model

    geared = _geared_rocker(0.25)
    one = solve(geared)
    many = solve_designs(geared, {"r4": np.array([0.45, 0.6]), "a1": np.array([0.0, 0.1])})
    for name in ("r2", "a1", "a2", "a3"):
        np.testing.assert_allclose(np.asarray(many.values[name])[0], one.value(name),
                                   atol=1e-12)
    assert np.asarray(many.values["r2"])[1] == pytest.approx(0.4)
    np.testing.assert_allclose(np.asarray(many.values["a1"])[1], one.value("a1") + 0.1,
                               atol=1e-12)
    pair = load_model(EXAMPLES / "gear_pair.yaml")
    base, turned = solve(pair), solve(place_model(pair, 2 * np.exp(30j * DEG), 0j))
    for n in (1, 3, 4):
        np.testing.assert_allclose(turned.value(f"r{n}"), 2 * base.value(f"r{n}"), atol=1e-12)
        np.testing.assert_allclose(np.exp(1j * turned.value(f"a{n}")),
                                   np.exp(1j * (base.value(f"a{n}") + 30 * DEG)), atol=1e-12)
