"""A timed objective evaluated at its target positions only, with the crank's full turn
decided in closed form, gives what solving every position gives.

The general path (``objective_positions = None``, ``inputs_only = False``) solves all
positions and decides feasibility at them; the fast path solves the targets' positions and asks
:func:`mechloop.synthesis.crank_turn.compile_turn_check`.  Their Q agree to 1e-12 where
both find a design feasible; the exact check refuses every design the samples refuse,
and a design only the samples accept breaks between two samples (a dense check of the
triangle inequality and of the dead-point margin finds the break).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.errors import SolveError
from mechloop.solve.designs import solve_designs
from mechloop.solve.kinematics import SINGULAR_SIN
from mechloop.synthesis.crank_turn import compile_turn_check
from mechloop.synthesis.problem import SynthesisProblem

FIVE = "examples/five_points_timing_synthesis.yaml"
EIGHTEEN = "examples/eighteen_points_timing_synthesis.yaml"
SIX = "examples/six_points_line_synthesis.yaml"
FREE = "examples/six_points_free_timing_synthesis.yaml"
# A share of a bound: 0, or not below 1e-9 (a link some 1e-185 of the others' length is
# degenerate: Pl4 then gives a direction that is not a unit vector and a later contour
# overflows, in every path alike — the degenerate-link check is another part's).
share = st.one_of(st.just(0.0), st.floats(1e-9, 1))


def _problems(path: str) -> tuple[SynthesisProblem, SynthesisProblem]:
    model = mechloop.load_model(path)
    fast, general = SynthesisProblem(model), SynthesisProblem(model)
    general.objective_positions = None  # every position, decided at them
    return fast, general


def dense_turns(crank, coupler, rocker, frame, steps: int = 100_000) -> np.ndarray:
    """Whether a four-bar's crank turns fully, by the triangle inequality and the
    dead-point margin (|sin| of the coupler-rocker angle above SINGULAR_SIN) at
    ``steps`` crank angles; arrays ``(D,)``."""
    theta = np.linspace(0, 2 * np.pi, steps, endpoint=False)
    turns = np.empty(len(crank), dtype=bool)
    for d in range(len(crank)):
        k2 = frame[d] ** 2 + crank[d] ** 2 - 2 * frame[d] * crank[d] * np.cos(theta)
        with np.errstate(divide="ignore", invalid="ignore"):
            cos = (coupler[d] ** 2 + rocker[d] ** 2 - k2) / (2 * coupler[d] * rocker[d])
        turns[d] = bool((np.abs(cos) < np.sqrt(1 - SINGULAR_SIN**2)).all())
    return turns


@settings(max_examples=30, deadline=None)
@given(st.lists(st.lists(share, min_size=6, max_size=6), min_size=4, max_size=40))
def test_five_points_fast_path_equals_every_position(rows):
    fast, general = _problems(FIVE)
    designs = fast.variables.scale(np.array(rows))
    _same_evaluation(fast, general, designs)


@settings(max_examples=30, deadline=None)
@given(st.lists(st.lists(share, min_size=10, max_size=10), min_size=4, max_size=40))
def test_eighteen_points_fast_path_equals_every_position(rows):
    fast, general = _problems(EIGHTEEN)
    designs = fast.variables.scale(np.array(rows))
    _same_evaluation(fast, general, designs)


def test_many_random_designs_take_the_fast_path_with_the_same_q():
    fast, general = _problems(EIGHTEEN)
    assert fast.objective_positions is not None
    np.testing.assert_array_equal(fast.objective_positions, np.arange(0, 360, 20))
    rng = np.random.default_rng(5)
    designs = fast.variables.scale(rng.uniform(size=(3000, len(fast.variables))))
    ev = _same_evaluation(fast, general, designs)
    assert ev.feasible.sum() > 500


def _same_evaluation(fast: SynthesisProblem, general: SynthesisProblem, designs):
    a, b = fast.evaluate(designs), general.evaluate(designs)
    both = a.feasible & b.feasible
    np.testing.assert_allclose(a.q[both], b.q[both], rtol=1e-12, atol=0)
    np.testing.assert_allclose(a.total[both], b.total[both], rtol=1e-12, atol=0)
    assert not (a.feasible & ~b.feasible).any()  # exact never accepts what samples refuse
    only = np.flatnonzero(b.feasible & ~a.feasible)
    if only.size:  # a break between two samples: a dense check finds it
        v = {n: designs[only, i] for i, n in enumerate(fast.variables.names)}
        assert not dense_turns(v["r1"], v["r2"], v["r3"], v["r4"]).any()
    assert (a.total[~a.feasible] >= 1e12).all()
    assert (a.broken_share[~a.feasible] > 0).all()
    assert (a.broken_share[a.feasible] == 0).all()
    return a


def test_untimed_problems_solve_every_position():
    problem = SynthesisProblem(mechloop.load_model(SIX))
    assert problem.objective_positions is None and not problem.inputs_only


@settings(max_examples=8, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_free_timing_at_the_inputs_only_equals_every_position(seed):
    """Free timing whose objective reads the target inputs only: position 0 and the
    inputs are solved, the full turn decided exactly; the same Q as solving every
    position, and the same feasibility but for breaks between two samples."""
    model = mechloop.load_model(FREE)
    fast, general = SynthesisProblem(model), SynthesisProblem(model)
    assert fast.objective_positions is None and fast.inputs_only
    general.inputs_only = False
    rng = np.random.default_rng(seed)
    designs = fast.variables.scale(rng.uniform(size=(300, len(fast.variables))))
    ev = _same_evaluation(fast, general, designs)
    assert ev.feasible.any()
    rows = ev.feasible  # (a design only the samples accept breaks between two of them)
    np.testing.assert_allclose(fast.residuals(designs)[rows],
                               general.residuals(designs)[rows], rtol=1e-12, atol=0)


@pytest.mark.parametrize("margin", [1e-3, 1e-6, 1e-9, -1e-9, -1e-6, -1e-3])
def test_crank_turn_agrees_with_grashof_and_a_dense_check_near_the_limit(margin):
    """Random four-bars with s + l = p + q + margin·l (crank or frame the shortest link):
    the closed form, Grashof's inequality and a dense check at 1e5 crank angles agree
    (margins beyond the dead-point tolerance, SINGULAR_SIN)."""
    model = mechloop.load_model(FIVE)
    check = compile_turn_check(model)
    rng = np.random.default_rng(abs(hash(margin)) % 2**32)
    n = 60
    shortest = rng.uniform(1, 5, n)
    p, q = rng.uniform(6, 30, n), rng.uniform(6, 30, n)
    # s + l = p + q + margin·l  ->  l = (p + q - s) / (1 - margin)
    longest = (p + q - shortest) / (1 - margin)
    crank_short = rng.uniform(size=n) < 0.5
    crank = np.where(crank_short, shortest, p)       # crank-rocker, or a drag link
    frame = np.where(crank_short, p, shortest)
    coupler, rocker = longest, q
    swap = rng.uniform(size=n) < 0.5                  # the longest link anywhere
    coupler, rocker = np.where(swap, q, coupler), np.where(swap, coupler, rocker)
    turns, share = check({"r1": crank, "r2": coupler, "r3": rocker, "r4": frame}, n)
    s = np.minimum.reduce([crank, coupler, rocker, frame])
    l_ = np.maximum.reduce([crank, coupler, rocker, frame])
    grashof = 2 * (s + l_) < crank + coupler + rocker + frame
    np.testing.assert_array_equal(turns, grashof & ((crank == s) | (frame == s)))
    np.testing.assert_array_equal(turns, dense_turns(crank, coupler, rocker, frame))
    assert ((share > 0) == ~turns).all()


def test_share_of_the_turn_where_a_four_bar_breaks_is_exact():
    """A triple-rocker's broken share against a dense count of crank angles."""
    check = compile_turn_check(mechloop.load_model(FIVE))
    crank, coupler, rocker, frame = (np.array([v]) for v in (20.0, 12.0, 15.0, 18.0))
    turns, share = check({"r1": crank, "r2": coupler, "r3": rocker, "r4": frame}, 1)
    theta = np.linspace(0, 2 * np.pi, 1_000_000, endpoint=False)
    k = np.sqrt(frame**2 + crank**2 - 2 * frame * crank * np.cos(theta))
    broken = (k > coupler + rocker) | (k < abs(coupler - rocker))
    assert not turns[0]
    assert share[0] == pytest.approx(broken.mean(), abs=1e-5)


@settings(max_examples=20, deadline=None)
@given(st.lists(st.integers(0, 360), min_size=1, max_size=12, unique=True),
       st.lists(st.floats(0.2, 1.0), min_size=3, max_size=3))
def test_designs_solved_at_some_positions_equal_those_columns_of_all(chosen, lengths):
    model = mechloop.load_model(FIVE)
    positions = np.array(sorted(chosen))
    over = {"r2": np.array(lengths) * 50e-3, "r3": np.array(lengths[::-1]) * 40e-3}
    some = solve_designs(model, over, derivatives=False, positions=positions)
    every = solve_designs(model, over, derivatives=False)
    np.testing.assert_array_equal(some.broken, every.broken[:, positions])
    np.testing.assert_array_equal(some.positions, positions)
    for name in ("a1", "a2", "a3", "r8"):
        got, want = some.values[name], every.values[name][:, positions]
        np.testing.assert_array_equal(np.isnan(got), np.isnan(want))
        ok = ~np.isnan(want)
        if name[0] == "a":  # the same direction; turns counted along different positions
            got, want = np.exp(1j * got[ok]), np.exp(1j * want[ok])
        else:
            got, want = got[ok], want[ok]
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)


def test_some_positions_need_a_fixed_variant_and_increasing_numbers():
    model = mechloop.load_model("examples/four_bar.yaml")
    data = model.model_dump(mode="json", exclude_none=True)
    data["contours"][0]["variant"] = "auto"
    tracked = mechloop.Model.from_dict(data)
    with pytest.raises(SolveError, match="variant auto"):
        solve_designs(tracked, {"r2": np.array([0.35])}, positions=[0, 10])
    with pytest.raises(SolveError, match="must increase"):
        solve_designs(model, {"r2": np.array([0.35])}, positions=[10, 0])


def test_a_timed_curve_at_its_inputs_only_equals_every_position():
    """A timed parametric curve (its targets at inputs of their own): position 0 and the
    inputs solved, the verdict exact; the same evaluation as solving every position."""
    from test_synthesis_formulations import coupler_expressions, path_data

    data = path_data()
    data["synthesis"]["path"].update(targets={**coupler_expressions(), "t": [10, 300],
                                              "count": 7}, timing=True)
    model = mechloop.Model.from_dict(data)
    fast, general = SynthesisProblem(model), SynthesisProblem(model)
    assert fast.inputs_only and fast.exact_feasibility(
        fast.variables.scale(np.full((1, len(fast.variables)), 0.5))) is not None
    general.inputs_only = False
    rng = np.random.default_rng(2)
    designs = fast.variables.scale(rng.uniform(size=(400, len(fast.variables))))
    a, b = fast.evaluate(designs), general.evaluate(designs)
    assert a.feasible.any()
    np.testing.assert_array_equal(a.feasible, b.feasible)
    np.testing.assert_allclose(a.q[a.feasible], b.q[b.feasible], rtol=1e-12, atol=0)
    np.testing.assert_allclose(fast.residuals(designs)[a.feasible],
                               general.residuals(designs)[b.feasible], rtol=1e-12, atol=0)
