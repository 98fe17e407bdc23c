"""Existence over the whole continuous input: the exact check against a dense solve (1e5
steps of the crank), Grashof's inequality and its slider analogue; synthesis refuses a
design that breaks between two positions or has a degenerate crank; ``solve`` names a
break that falls between two positions."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.solve.designs import solve_designs
from mechloop.solve.existence import (
    THRESHOLD,
    assembles_throughout,
    four_bar_type_holds,
)
from mechloop.synthesis.problem import INFEASIBLE, SynthesisProblem

FOUR_BAR = mechloop.load_model("examples/four_bar.yaml")
SLIDER = mechloop.load_model("examples/crank_slider.yaml")
SIX_BAR = mechloop.load_model("examples/six_bar.yaml")
SIX_POINTS = mechloop.load_model("examples/six_points_line_synthesis.yaml")
DENSE = 100_000


# The best design of examples/six_points_line_synthesis.yaml's own search (CMA-ES, seed
# 1) when feasibility was checked at the positions only (mm, deg).
SIX_POINTS_BEST = {
    "r1": 15.351568400173582, "r2": 37.56285233608938, "r3": 37.7802893459021,
    "r4": 59.991572001427215, "a4": 0.019259434463321127, "r6": 81.19103375171447,
    "a6": 124.90017769053489, "start1.x": -45.779853942382815,
    "start1.y": 53.177360303220915}


def si_row(problem: SynthesisProblem, values: dict[str, float]) -> np.ndarray:
    """A design in the problem's variable order, SI (values in mm and deg)."""
    return np.array([values[n] * (np.pi / 180 if n[0] == "a" else 1e-3)
                     for n in problem.variables.names])


def with_vectors(model, **changes):
    """``model`` with vector fields changed: ``r2=149.9`` or ``a4=182.5``."""
    vectors = dict(model.vectors)
    for key, value in changes.items():
        number = int(key[1:])
        vectors[number] = vectors[number].model_copy(update={key[0]: value})
    return model.model_copy(update={"vectors": vectors})


def densely(model, steps: int = DENSE):
    """The model with argument 1 over the same range in ``steps`` positions, no time."""
    table = model.arguments[1].table
    first, last = min(table), max(table)
    dense = model.arguments[1].model_copy(update={"table": {0: table[first],
                                                           steps: table[last]}})
    return model.model_copy(update={"positions": steps, "arguments": {1: dense},
                                    "time": None})


def four_bar_lengths(draw_sum: float, base: tuple[float, float, float, float],
                     which: int) -> tuple[float, ...]:
    """The four lengths with length ``which`` moved so that s + l − (p + q) is
    ``draw_sum`` (a link that stays the shortest or longest keeps its role)."""
    lengths = list(base)
    ordered = sorted(range(4), key=lambda i: lengths[i])
    s, p, q, l_ = (lengths[i] for i in ordered)
    excess = s + l_ - p - q
    sign = 1.0 if which in (ordered[0], ordered[3]) else -1.0
    lengths[which] += sign * (draw_sum - excess)
    return tuple(lengths)


@settings(max_examples=20, deadline=None)
@given(crank=st.floats(0.05, 0.2), coupler=st.floats(0.2, 0.5), rocker=st.floats(0.2, 0.5),
       frame=st.floats(0.2, 0.5), angle=st.floats(0, 360),
       gap=st.sampled_from([-1e-2, -1e-3, -1e-4, -1e-5, 1e-5, 1e-4, 1e-3, 1e-2]),
       which=st.integers(0, 3))
def test_four_bar_exact_check_agrees_with_dense_solve_and_grashof(
        crank, coupler, rocker, frame, angle, gap, which):
    """A four-bar within 1e-5..1e-2 of Grashof's limit s + l = p + q: the exact verdict on
    72 positions equals the verdict of a solve on 1e5 positions, and the inequality with
    the crank or the frame the shortest link (a full turn of the crank)."""
    c, a, b, d = four_bar_lengths(gap * 0.3, (crank, coupler, rocker, frame), which)
    # crank = frame lets the diagonal pass through zero, where a break is as narrow as
    # the gap itself (1e-5 rad): finer than the dense solve's step
    assume(min(c, a, b, d) > 0.01 and abs(c - d) > 0.01)
    over = {"r1": [c], "r2": [a], "r3": [b], "r4": [d], "a4": [np.radians(angle)]}
    exact = assembles_throughout(FOUR_BAR, over)
    dense = solve_designs(densely(FOUR_BAR), over, derivatives=False).assembles
    s = sorted((c, a, b, d))
    grashof = s[0] + s[3] < s[1] + s[2] and min(c, d) == s[0]
    assert exact.feasible[0] == dense[0] == grashof


@settings(max_examples=12, deadline=None)
@given(crank=st.floats(0.05, 0.4), coupler=st.floats(0.05, 0.5), rocker=st.floats(0.05, 0.5),
       frame=st.floats(0.1, 0.5), start=st.floats(-180, 180), span=st.floats(5, 300))
def test_four_bar_over_part_of_a_turn_agrees_with_a_dense_solve(
        crank, coupler, rocker, frame, start, span):
    """A crank driven over part of a turn (36 positions): the closed form over the
    argument's range decides as a solve on 1e5 positions of the same range; where the
    verdicts would need a finer solve (a break narrower than its step), the example is
    left out."""
    model = FOUR_BAR.model_copy(update={"arguments": {1: FOUR_BAR.arguments[1].model_copy(
        update={"table": {0: start, 36: start + span}})}, "positions": 36, "time": None})
    over = {"r1": [crank], "r2": [coupler], "r3": [rocker], "r4": [frame]}
    exact = assembles_throughout(model, over)
    dense = solve_designs(densely(model), over, derivatives=False)
    assume(abs(exact.margin[0]) > 1e-6)
    assert exact.feasible[0] == dense.assembles[0]


@settings(max_examples=12, deadline=None)
@given(rod=st.floats(0.05, 0.3), offset=st.floats(-0.1, 0.1), guide=st.floats(170, 190),
       gap=st.sampled_from([-1e-3, -1e-4, -1e-5, 1e-5, 1e-4, 1e-3]))
def test_slider_crank_exact_check_agrees_with_dense_solve_and_reach(rod, offset, guide, gap):
    """The offset slider-crank: a full turn iff crank + |offset| < rod (1e-5..1e-3 m from
    the limit), exactly as a solve on 1e5 positions sees it."""
    crank = rod - abs(offset) + gap
    assume(crank > 0.005)
    # the offset vector 4 stands at 90° to the guide: a fixed 90° in the example, so turn
    # both with the guide
    model = with_vectors(SLIDER, a3=guide, a4=guide - 90)
    over = {"r1": [crank], "r2": [rod], "r4": [abs(offset)]}
    exact = assembles_throughout(model, over)
    dense = solve_designs(densely(model), over, derivatives=False).assembles
    assert exact.feasible[0] == dense[0] == (crank + abs(offset) < rod)


def test_a_break_between_two_positions_is_found_where_the_sampled_solve_sees_none():
    """The four-bar of examples/four_bar.yaml with the frame turned 2.5° and a coupler 1 µm
    short: the farthest reach of B lies between positions 36 and 37 (180° and 185°).
    Interval from the closed form p(θ)² = c² + f² + 2cf·cos(θ − 182.5°) = (r2 + r3)²;
    a solve on 1e5 positions breaks exactly there."""
    model = with_vectors(FOUR_BAR, r2=149.999, a4=182.5)
    results = mechloop.solve(model)
    assert not results.broken.any()
    (gap,) = results.breaks_between
    reach = (149.999 + 250) ** 2
    half = np.degrees(np.arccos((reach - 100**2 - 300**2) / (2 * 100 * 300)))
    assert (gap.contour, gap.after, gap.at) == (1, 36, (np.pi, np.radians(185)))
    np.testing.assert_allclose(np.degrees([gap.start, gap.stop]),
                               [182.5 - half, 182.5 + half], rtol=1e-6)
    dense = mechloop.solve(densely(model))
    where = np.degrees(dense.arguments[1][dense.broken])
    assert where.min() >= 182.5 - half and where.max() <= 182.5 + half
    assert where.max() - where.min() == pytest.approx(2 * half, abs=2 * 360 / DENSE)
    text = gap.describe()
    assert "between positions 36 and 37" in text and "182.204" in text


def test_cli_solve_warns_of_a_break_between_positions(tmp_path):
    text = (mechloop.__path__[0] + "/../../examples/four_bar.yaml")
    source = open(text).read().replace("2: {r: 350,", "2: {r: 149.999,").replace(
        "4: {r: 300, a: 180,", "4: {r: 300, a: 182.5,")
    path = tmp_path / "short.yaml"
    path.write_text(source)
    result = CliRunner().invoke(app, ["solve", str(path), "-o", str(tmp_path / "r.csv")])
    assert result.exit_code == 0, result.output
    assert "chain break between positions" in result.output
    assert "between positions 36 and 37" in result.output


def test_synthesis_refuses_a_break_between_samples_and_a_degenerate_crank():
    """The six-point line problem's four-bar with s + l exceeding p + q by 1e-4 mm and the
    frame turned 0.5° (its toggle half-way between two positions): every sampled position
    (1°) assembles, yet the crank cannot turn fully — infeasible, like a
    crank of 3.2e-15 mm.  The design the example's search (CMA-ES, seed 1, sampled check
    only) returned here is Grashof by 1.3e-6 mm and stays feasible, as a 1e5-step solve
    confirms."""
    problem = SynthesisProblem(SIX_POINTS)
    row = si_row(problem, SIX_POINTS_BEST)
    broken = row.copy()
    names = problem.variables.names
    broken[names.index("a4")] += np.radians(0.5)  # the toggle half-way between positions
    broken[names.index("r2")] -= 1e-4 * 1e-3 + (
        row[names.index("r2")] + row[names.index("r3")]
        - row[names.index("r1")] - row[names.index("r4")])
    tiny = row.copy()
    tiny[names.index("r1")] = 3.2e-15 * 1e-3
    designs = np.stack([row, broken, tiny])
    sampled = problem.solve(designs)
    assert sampled.assembles.all()
    ev = problem.evaluate(designs)
    np.testing.assert_array_equal(ev.feasible, [True, False, False])
    assert (ev.total[1:] >= INFEASIBLE).all() and np.isnan(ev.q[1:]).all()
    dense = solve_designs(densely(SIX_POINTS), problem.variables.overrides(designs[:2]),
                          derivatives=False)
    np.testing.assert_array_equal(dense.assembles, [True, False])


def six_bar_limits() -> tuple[float, float]:
    """The output loop of examples/six_bar.yaml closes while |r6 − r7| ≤ p ≤ r6 + r7,
    p = |D − F| = |v5 + v8| over the motion of the driving four-bar (which r6 does not
    change): the smallest and largest r6 that keep it closed, from a solve on 1e5
    positions of that distance."""
    res = mechloop.solve(densely(SIX_BAR))
    p = np.abs(sum(res.values[f"r{n}"] * np.exp(1j * res.values[f"a{n}"]) for n in (5, 8)))
    return p.max() - 0.15, p.min() + 0.15


def test_generic_check_of_a_six_bar_agrees_with_a_dense_solve():
    """Contour 2 of the Watt six-bar has no closed form (its input is the rocker of
    contour 1).  With r6 1e-4..1e-2 (relative) inside or outside either limit, the verdict
    from 72 positions equals a solve on 2e4 positions, a break between positions is
    caught where the sampled solve misses it, and the least margin found equals the
    dense minimum of sin² between the unknown vectors of either loop (located between the
    positions where it comes near zero, the parabola through three positions elsewhere)."""
    low, high = six_bar_limits()
    rel = np.array([-1e-2, -1e-3, -1e-4, 1e-4, 1e-3, 1e-2])
    r6 = np.concatenate([low * (1 + rel), high * (1 - rel)])
    over = {"r6": r6}
    sampled = solve_designs(SIX_BAR, over, derivatives=False)
    exact = assembles_throughout(SIX_BAR, over, samples=sampled)
    dense = solve_designs(densely(SIX_BAR, 20_000), over, derivatives=False)
    np.testing.assert_array_equal(exact.feasible, dense.assembles)
    np.testing.assert_array_equal(exact.feasible, np.tile(rel > 0, 2))
    assert (sampled.assembles & ~exact.feasible).any()
    v = dense.values
    margin = np.minimum(np.sin(v["a2"] - v["a3"]) ** 2, np.sin(v["a6"] - v["a7"]) ** 2)
    ok = exact.feasible
    np.testing.assert_allclose(exact.margin[ok], margin[ok].min(axis=-1), rtol=2e-3)
    assert (exact.margin[~ok] <= THRESHOLD).all()


def test_grashof_types_follow_the_shortest_link():
    """Classes of Grashof four-bars by the shortest link (crank 0.1, others 0.3..0.45;
    frame 0.1; coupler 0.1) and a non-Grashof one (s + l > p + q)."""
    designs = {"crank-rocker": (0.1, 0.35, 0.25, 0.3), "double-crank": (0.3, 0.35, 0.25, 0.1),
               "double-rocker": (0.3, 0.1, 0.25, 0.3), "non-grashof": (0.1, 0.45, 0.1, 0.3)}
    lengths = np.array(list(designs.values())).T
    over = {f"r{i + 1}": lengths[i] for i in range(4)}
    for kind in designs:
        held = four_bar_type_holds(FOUR_BAR, over, grashof=kind)
        np.testing.assert_array_equal(held, [k == kind for k in designs])
    np.testing.assert_array_equal(four_bar_type_holds(FOUR_BAR, over, grashof="grashof"),
                                  [True, True, True, False])
    np.testing.assert_array_equal(four_bar_type_holds(FOUR_BAR, over, crank_shortest=True),
                                  [True, False, False, True])
    with pytest.raises(ModelError, match="no four-bar loop"):
        four_bar_type_holds(SLIDER, {"r1": [0.05]}, grashof="crank-rocker")


def test_grashof_condition_of_a_synthesis_task_is_mandatory():
    """``grashof: double-crank`` refuses the six-point problem's crank-rocker (its crank
    is the shortest link), ``crank-rocker`` and ``crank_shortest`` keep it."""
    data = SIX_POINTS.model_dump(mode="json", exclude_defaults=True)
    row = None
    verdicts = {}
    for extra in ({"grashof": "double-crank"}, {"grashof": "crank-rocker"},
                  {"crank_shortest": True}):
        data["synthesis"] = {**SIX_POINTS.synthesis.model_dump(mode="json",
                                                                exclude_defaults=True),
                             **extra}
        problem = SynthesisProblem(mechloop.Model.from_dict(data))
        if row is None:
            row = si_row(problem, SIX_POINTS_BEST)
        verdicts[str(extra)] = bool(problem.evaluate(row[None, :]).feasible[0])
    assert list(verdicts.values()) == [False, True, True]


def test_solve_names_a_break_of_a_loop_without_closed_form_between_positions():
    """The six-bar's output loop with r6 1e-4 (relative) short of its lower limit: no
    position of the 72 breaks, ``solve`` reports one break between two positions, and a
    solve on 2e4 positions breaks there, from where it says to where it says (within
    that solve's step)."""
    low, _ = six_bar_limits()
    model = with_vectors(SIX_BAR, r6=low * (1 - 1e-4) * 1000)  # mm
    results = mechloop.solve(model)
    assert not results.broken.any()
    (gap,) = results.breaks_between
    assert gap.contour == 2 and gap.at[0] <= gap.start <= gap.at[1]
    dense = mechloop.solve(densely(model, 20_000))
    where = dense.arguments[1][dense.broken]
    assert where.size and gap.at[0] <= where.min() and where.max() <= gap.at[1]
    step = np.radians(360 / 20_000)
    assert gap.start < gap.stop
    np.testing.assert_allclose([gap.start, gap.stop], [where.min(), where.max()],
                               atol=step)


def test_generic_check_of_a_group_file_model_agrees_with_a_dense_solve():
    """examples/six_bar_groups.yaml (built from Assur groups): its ram loop (Pl3, the rod
    DE on a fixed guide, driven by the bell crank) closes while the rod reaches the guide,
    r6 ≥ max |r6·sin(a6 − a7)| (D's distance from the guide, from a solve on 2e4
    positions).  With r6 1e-4..1e-2 (relative) on either side, the verdict from 72
    positions equals the dense solve's."""
    model = mechloop.load_model("examples/six_bar_groups.yaml")
    dense_model = densely(model, 20_000)
    res = mechloop.solve(dense_model)
    reach = np.max(np.abs(res.values["r6"] * np.sin(res.values["a6"] - res.values["a7"])))
    rel = np.array([-1e-2, -1e-3, -1e-4, 1e-4, 1e-3, 1e-2])
    over = {"r6": reach * (1 + rel)}
    sampled = solve_designs(model, over, derivatives=False)
    exact = assembles_throughout(model, over, samples=sampled)
    dense = solve_designs(dense_model, over, derivatives=False)
    np.testing.assert_array_equal(exact.feasible, dense.assembles)
    np.testing.assert_array_equal(exact.feasible, rel > 0)
    assert (sampled.assembles & ~exact.feasible).any()


def test_solve_names_a_slider_crank_break_between_positions():
    """examples/crank_slider.yaml (crank 0.05 m, offset 0.01 m) with the guide and offset
    turned 2.5° and a rod 1 µm short of crank + offset: the crank pin cannot be reached
    around 92.5°, between positions 18 and 19 (90° and 95°); the interval named is where
    a solve on 1e5 positions breaks (within its step)."""
    model = with_vectors(SLIDER, a3=182.5, a4=92.5, r2=0.06 - 1e-6)
    results = mechloop.solve(model)
    assert not results.broken.any()
    (gap,) = results.breaks_between
    assert (gap.contour, gap.module, gap.after) == (1, "Pl3", 18)
    dense = mechloop.solve(densely(model))
    where = dense.arguments[1][dense.broken]
    np.testing.assert_allclose([gap.start, gap.stop], [where.min(), where.max()],
                               atol=np.radians(360 / DENSE))
    half = np.degrees(np.arccos((0.06 - 1e-6 - 0.01) / 0.05))  # |0.05 cos(θ − 92.5°)|
    np.testing.assert_allclose(np.degrees([gap.start, gap.stop]),
                               [92.5 - half, 92.5 + half], rtol=1e-9)


def test_a_crank_made_of_two_vectors_is_one_crank_in_the_closed_form():
    """The four-bar's crank split in two (vector 8 rigidly on the crank, 20 mm at 30°):
    the loop is still decided in closed form, with the crank pin at
    c = |100 + 20·e^{i30°}| mm from its pivot; with the coupler reaching 10 µm short of
    or beyond c + 300 − 250, the verdict equals a solve on 1e5 positions."""
    data = FOUR_BAR.model_dump(mode="json", exclude_defaults=True)
    data["vectors"][8] = {"r": 20, "a": {"link": "a1", "delta": 30}}
    data["contours"][0]["vectors"] = [1, 8, 2, 3, 4]
    model = mechloop.Model.from_dict(data)
    c = abs(100 + 20 * np.exp(1j * np.radians(30)))
    over = {"r2": (c + 300 - 250 + np.array([-1e-2, 1e-2])) * 1e-3}
    exact = assembles_throughout(model, over)
    dense = solve_designs(densely(model), over, derivatives=False)
    np.testing.assert_array_equal(exact.feasible, [False, True])
    np.testing.assert_array_equal(dense.assembles, [False, True])
    # the margin is the closed form's, sin² between coupler and rocker at the extreme
    # diagonals (c ± 300), not an estimate from the positions
    a, b = over["r2"][1] * 1e3, 250.0
    margin = [((a + b) ** 2 - q) * (q - (a - b) ** 2) / (4 * a * a * b * b)
              for q in ((c - 300) ** 2, (c + 300) ** 2)]
    assert exact.margin[1] == pytest.approx(min(margin), rel=1e-9)
