"""Coupled blocks: contours solved together by Newton's continuation.

* the structure finds the blocks (a triad written as two contours that need each other, a
  contour linking to its own function, a contour with three functions beside one with
  one) and locates a block with the wrong number of functions;
* a model that elementary modules solve gives the same numbers (≤ 1e-12) when forced
  through the coupled solver;
* random class-III triads (RRR–RRR–RRR: a ternary link pinned to three dyads, one driven
  by a crank) against the assembly oracle (:mod:`oracles.assemblies`: SciPy's
  least-squares on the raw loop equations of the whole model from many starts):
  positions, every assembly at position 0, velocities and accelerations by finite
  differences, and the first break where the oracle, following the branch in fine
  steps, loses it;
* designs ``(D, P)`` equal one solve each, extra inputs start from the nearest position,
  results do not depend on the blocks of positions, and the design tangents through the
  block Jacobian equal finite differences.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from oracles.assemblies import Equations

import mechloop
from mechloop.errors import ModelError
from mechloop.model.check import require_valid
from mechloop.solve import blocks
from mechloop.solve.designs import solve_designs, solve_designs_at

EXAMPLES = ["four_bar", "crank_slider", "six_bar", "v_engine", "hydraulic_rocker",
            "roof_support", "single_cylinder_engine", "log10_function_generator",
            "gear_train", "planetary_reducer"]


def _ang(p) -> float:
    return math.degrees(math.atan2(p[1], p[0]))


def _len(p) -> float:
    return float(np.hypot(*p))


def triad(B1, B2, B3, A1, A2, c, sweep, n, *, guess=True, variant=None) -> mechloop.Model:
    """A class-III mechanism: crank ``O→A3`` (length ``c``, argument 1 from 0 to
    ``sweep`` deg over ``n`` positions), ternary link ``B1 B2 B3``, dyads ``A1–B1``,
    ``A2–B2`` (frame pins) and ``A3–B3``; assembled at position 0 as drawn (the
    ``guess``).  Contour 1: A1→B1→B2→A2→A1, unknowns α1, α3, the side B1→B2 linked to
    the ternary link's angle α7; contour 2: O→A3→B3→B1→A1→O, unknowns α6, α7, B1→A1
    linked to α1.  Each needs the other: one coupled block."""
    B1, B2, B3, A1, A2 = (np.asarray(p, dtype=float) for p in (B1, B2, B3, A1, A2))
    A3 = np.array([c, 0.0])
    vectors = {
        1: {"r": _len(B1 - A1), "a": "function"},
        2: {"r": _len(B2 - B1), "a": {"link": "a7", "delta": _ang(B2 - B1) - _ang(B1 - B3)}},
        3: {"r": _len(A2 - B2), "a": "function"},
        4: {"r": _len(A1 - A2), "a": _ang(A1 - A2)},
        5: {"r": c, "a": {"argument": 1}},
        6: {"r": _len(B3 - A3), "a": "function"},
        7: {"r": _len(B1 - B3), "a": "function"},
        8: {"r": {"link": "r1"}, "a": {"link": "a1", "delta": 180}},
        9: {"r": _len(A1), "a": _ang(-A1)},
    }
    c1: dict = {"vectors": [1, 2, 3, 4]}
    c2: dict = {"vectors": [5, 6, 7, 8, 9]}
    if guess:
        c1["guess"] = {"a1": _ang(B1 - A1), "a3": _ang(A2 - B2)}
        c2["guess"] = {"a6": _ang(B3 - A3), "a7": _ang(B1 - B3)}
    if variant is not None:
        c1["variant"] = variant
    return mechloop.Model.from_dict({
        "positions": n, "arguments": {1: {"table": {0: 0, n: sweep}}},
        "vectors": vectors, "contours": [c1, c2]})


BASE = dict(B1=(0.2, 0.8), B2=(0.7, 0.9), B3=(0.4, 1.2), A1=(-0.3, 0.0), A2=(1.0, 0.1),
            c=0.15)


def _unknowns(res, eq: Equations, k: int) -> np.ndarray:
    return np.array([res.values[n][k] for n in eq.names])


# ----------------------------------------------------------------------------- structure

def test_triad_is_one_coupled_block():
    structure = require_valid(triad(**BASE, sweep=60, n=12))
    (block,) = structure.blocks
    assert block.coupled and block.contours == (1, 2)
    assert sorted(block.unknowns) == ["a1", "a3", "a6", "a7"]
    assert structure.order == (1, 2)
    assert [c.module for c in structure.ordered()] == ["coupled", "coupled"]


def test_elementary_chain_stays_elementary():
    structure = require_valid(mechloop.load_model("examples/six_bar.yaml"))
    assert not structure.coupled
    assert [b.contours for b in structure.blocks] == [(n,) for n in structure.order]


GOOD = {
    "positions": 36, "arguments": {1: {"table": {0: 0, 36: 360}}},
    "vectors": {1: {"r": 0.05, "a": {"argument": 1}}, 2: {"r": 0.2, "a": "function"},
                3: {"r": "function", "a": 180}, 4: {"r": 0.01, "a": 90}},
    "contours": [{"vectors": [1, 2, 3, 4]}],
}


def _with(vectors=None, contours=None) -> dict:
    data = {**GOOD, "vectors": {**GOOD["vectors"], **(vectors or {})}}
    if contours is not None:
        data["contours"] = contours
    return data


def test_link_to_own_function_is_a_coupled_block_of_one():
    # the slider's offset vector turns with the connecting rod: not a closed form
    model = mechloop.Model.from_dict(_with({4: {"r": 0.01, "a": {"link": "a2",
                                                                  "delta": 90}}}))
    (block,) = require_valid(model).blocks
    assert block.coupled and block.contours == (1,)
    res = mechloop.solve(model)
    eq = Equations(model)
    for k in (0, 13, 29):
        roots = eq.assemblies(k, starts=20)
        assert min(eq.distance(_unknowns(res, eq, k), x) for x in roots) < 1e-10


def test_three_functions_beside_one_form_a_block():
    # the triad with the ternary link's angle a function of contour 1 (three functions)
    # and contour 2 holding only α6: matched two and two, they need each other
    model = triad(**BASE, sweep=60, n=12, guess=False)
    B1, B2, B3, A1, A2 = (np.asarray(BASE[k]) for k in ("B1", "B2", "B3", "A1", "A2"))
    vectors = {k: dict(v) for k, v in _triad_dict(model)["vectors"].items()}
    vectors[2]["a"] = "function"
    vectors[7]["a"] = {"link": "a2", "delta": _ang(B1 - B3) - _ang(B2 - B1)}
    contours = [{"vectors": [1, 2, 3, 4], "guess": {"a1": _ang(B1 - A1), "a2": _ang(B2 - B1),
                                                     "a3": _ang(A2 - B2)}},
                {"vectors": [5, 6, 7, 8, 9], "guess": {"a6": _ang(B3 - (BASE["c"], 0))}}]
    other = mechloop.Model.from_dict({**_triad_dict(model), "vectors": vectors,
                                      "contours": contours})
    (block,) = require_valid(other).blocks
    assert block.coupled and block.contours == (1, 2)
    assert sorted(block.unknowns) == ["a1", "a2", "a3", "a6"]
    a, b = mechloop.solve(triad(**BASE, sweep=60, n=12)), mechloop.solve(other)
    np.testing.assert_array_equal(a.broken, b.broken)
    for name in ("a1", "a3", "a6"):
        np.testing.assert_allclose(b.values[name], a.values[name], atol=1e-12)
        np.testing.assert_allclose(b.rates[name], a.rates[name], atol=1e-10)


def _triad_dict(model: mechloop.Model) -> dict:
    from mechloop.model.load import model_to_data

    data = model_to_data(model)
    data["vectors"] = {int(k): v for k, v in data["vectors"].items()}
    return data


def test_block_with_wrong_function_count_is_located():
    data = _with({4: {"r": 0.01, "a": {"link": "a6"}}, 5: {"r": 0.1, "a": {"link": "a2"}},
                  6: {"r": "function", "a": "function"}, 7: {"r": 0.1, "a": "function"}},
                 [{"vectors": [1, 2, 3, 4]}, {"vectors": [5, 6, 7]}])
    with pytest.raises(ModelError) as err:
        require_valid(mechloop.Model.from_dict(data))
    text = str(err.value)
    assert "contour 2 has 3 function parameters (r6, a6, a7)" in text
    assert "coupled block" in text and "fix:" in text


def test_guess_only_for_coupled_blocks():
    data = _with(contours=[{"vectors": [1, 2, 3, 4], "guess": {"a2": 10}}])
    with pytest.raises(ModelError, match="a guess applies only to a coupled block"):
        require_valid(mechloop.Model.from_dict(data))
    model = triad(**BASE, sweep=60, n=12)
    data = _triad_dict(model)
    data["contours"][0]["guess"] = {"a4": 10}
    with pytest.raises(ModelError, match="a4 is not an unknown of the coupled block"):
        require_valid(mechloop.Model.from_dict(data))


# -------------------------------------------------------------- forced through Newton

def _forced(fn, *args, **kwargs):
    blocks.FORCE_COUPLED = True
    try:
        return fn(*args, **kwargs)
    finally:
        blocks.FORCE_COUPLED = False


def _same(a: np.ndarray, b: np.ndarray) -> None:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    np.testing.assert_array_equal(np.isnan(a), np.isnan(b))
    # ≤ 1e-12 relative to the quantity's size over the cycle (m, rad; their rates)
    scale = max(1.0, float(np.nanmax(np.abs(a), initial=0.0)))
    assert np.nanmax(np.abs(a - b), initial=0.0) <= 1e-12 * scale


@pytest.mark.parametrize("name", EXAMPLES)
def test_forced_through_newton_gives_the_closed_form_numbers(name):
    model = mechloop.load_model(f"examples/{name}.yaml")
    for analogs in (None, 1):
        closed = mechloop.solve(model, analogs_of=analogs)
        newton = _forced(mechloop.solve, model, analogs_of=analogs)
        np.testing.assert_array_equal(closed.broken, newton.broken)
        for table in ("values", "rates", "accels"):
            for key, value in getattr(closed, table).items():
                _same(value, getattr(newton, table)[key])


def test_forced_designs_give_the_closed_form_numbers():
    model = mechloop.load_model("examples/four_bar.yaml")
    rng = np.random.default_rng(3)
    over = {"r2": rng.uniform(0.30, 0.40, 40), "r3": rng.uniform(0.22, 0.30, 40)}
    closed = solve_designs(model, over)
    newton = _forced(solve_designs, model, over)
    np.testing.assert_array_equal(closed.broken, newton.broken)
    for table in ("values", "rates", "accels"):
        for key, value in getattr(closed, table).items():
            _same(value, getattr(newton, table)[key])


# -------------------------------------------------------------- triads against the oracle

def test_every_assembly_at_position_0_is_reached_from_its_guess():
    model = triad(**BASE, sweep=30, n=6)
    eq = Equations(model)
    roots = eq.assemblies(0, starts=80)
    assert len(roots) >= 2
    data = _triad_dict(model)
    for root in roots:
        guess = {n: math.degrees(v) for n, v in zip(eq.names, root, strict=True)}
        data["contours"][0]["guess"] = {n: guess[n] for n in ("a1", "a3")}
        data["contours"][1]["guess"] = {n: guess[n] for n in ("a6", "a7")}
        res = mechloop.solve(mechloop.Model.from_dict(data))
        assert not res.broken[0]
        assert eq.distance(_unknowns(res, eq, 0), root) < 1e-10


@pytest.mark.parametrize("variant, sign", [(1, -1.0), (2, 1.0)])
def test_without_a_guess_the_variant_picks_the_determinant_sign(variant, sign):
    model = triad(**BASE, sweep=30, n=6, guess=False, variant=variant)
    res = mechloop.solve(model)
    eq = Equations(model)
    u = _unknowns(res, eq, 0)
    assert np.abs(eq.residual(u, 0)).max() < 1e-12
    # the oracle's Jacobian is in the model's unknown order (a1, a3, a6, a7): the block's
    # order here too, so the signs compare directly
    assert require_valid(model).blocks[0].unknowns == tuple(eq.names)
    assert eq.jacobian_sign(u, 0) == sign


points = st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0))


@st.composite
def triads(draw):
    B1 = np.array(draw(points)) + np.array([0.0, 1.0])
    B2 = B1 + draw(st.floats(0.3, 0.8)) * np.array(
        [math.cos(t := draw(st.floats(-1.0, 1.0))), math.sin(t)])
    B3 = B1 + draw(st.floats(0.3, 0.8)) * np.array(
        [math.cos(s := t + draw(st.floats(0.5, 2.5))), math.sin(s)])
    A1 = np.array(draw(points)) * (1.5, 0.3)
    A2 = np.array(draw(points)) * (1.5, 0.3)
    c = draw(st.floats(0.1, 0.3))
    lengths = [_len(B1 - A1), _len(B2 - A2), _len(B3 - (c, 0)), _len(A1 - A2), _len(A1)]
    assume(min(lengths) > 0.15)
    return dict(B1=B1, B2=B2, B3=B3, A1=A1, A2=A2, c=c)


def _followed(eq: Equations, u: np.ndarray, k: int, x: np.ndarray) -> np.ndarray | None:
    """The oracle's own continuation of root ``u`` from position ``k`` to ``k + 1``:
    steps of 1/8 of the way, halved (down to 2⁻¹⁶ of it) wherever a step moves the
    root by more than 0.05 rad; None where the branch is lost (no root within the
    smallest step, or the Jacobian's determinant changes sign)."""
    sign = eq.jacobian_sign(u, k)
    dx = x[k + 1] - x[k]
    at, step = 0.0, 1.0 / 8
    while at < 1.0:
        step = min(step, 1.0 - at)
        nxt = eq.solve_from(u, k, dx * (at + step))
        if nxt is None or eq.distance(nxt, u) > 0.05:
            if step < 2.0 ** -16:
                return None
            step /= 2
            continue
        u, at = nxt, at + step
        step *= 2
    root = eq.solve_from(u, k + 1)
    if root is None or eq.jacobian_sign(root, k + 1) != sign:
        return None
    return root


@settings(max_examples=8, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(triads())
def test_random_triads_follow_the_oracle(geometry):
    n = 12
    model = triad(**geometry, sweep=120, n=n)
    res = mechloop.solve(model, analogs_of=1)
    eq = Equations(model)
    x = res.arguments[1]
    assert not res.broken[0]
    u = _unknowns(res, eq, 0)
    k = 0
    while k < n:
        nxt = _followed(eq, u, k, x)
        if nxt is None:
            break
        k += 1
        u = nxt
        # the solver is on the oracle's branch, to round-off
        assert not res.broken[k], f"broken at {k}, where the oracle follows the branch"
        assert eq.distance(_unknowns(res, eq, k), u) < 1e-9
    reached = k
    if reached < n:
        # the oracle lost the branch between `reached` and `reached + 1`: so does the
        # solver — at `reached + 1`, or as a break between the two positions named by the
        # exact check (where the continuation's step passed over the loss)
        assert res.broken[reached + 1] or any(b.after == reached
                                              for b in res.breaks_between)
    for k in range(0, reached + 1, 3):
        if eq.jacobian_sign(_unknowns(res, eq, k), k) == 0:
            continue
        found = eq.rates(_unknowns(res, eq, k), k)
        if found is None:
            continue  # a limit position within the difference step
        d1, d2, e1, e2 = found
        # within 1e-7 (rates) and 1e-5 (accelerations) of the size, or the oracle's own
        # error estimate where a limit position is near
        rates = np.array([res.rates[n][k] for n in eq.names])
        accels = np.array([res.accels[n][k] for n in eq.names])
        assert (np.abs(rates - d1) <= 1e-7 * max(1.0, np.abs(d1).max()) + 10 * e1).all()
        assert (np.abs(accels - d2) <= 1e-4 * max(1.0, np.abs(d2).max()) + 10 * e2).all()


def test_results_do_not_depend_on_the_blocks_of_positions():
    model = triad(**BASE, sweep=360, n=72)
    whole = mechloop.solve(model)
    parts = mechloop.solve(model, block=5)
    np.testing.assert_array_equal(whole.broken, parts.broken)
    for name, value in whole.values.items():
        np.testing.assert_array_equal(value, parts.values[name])
        np.testing.assert_array_equal(whole.rates[name], parts.rates[name])
    assert [b.describe() for b in whole.breaks] == [b.describe() for b in parts.breaks]


def test_designs_of_a_triad_match_one_solve_each():
    model = triad(**BASE, sweep=360, n=36)
    r6 = np.array([1.20, 1.2257650672131262, 1.25])
    many = solve_designs(model, {"r6": r6})
    data = _triad_dict(model)
    for d, value in enumerate(r6):
        data["vectors"][6]["r"] = float(value)
        one = mechloop.solve(mechloop.Model.from_dict(data))
        np.testing.assert_array_equal(many.broken[d], one.broken)
        for name in ("a1", "a3", "a6", "a7"):
            np.testing.assert_allclose(many.values[name][d], one.values[name], atol=1e-12)
            np.testing.assert_allclose(many.rates[name][d], one.rates[name], atol=1e-10)
    # extra inputs solved from the nearest regular position land on the same branch
    x = many.arguments[1]
    inputs = np.tile(x[20:30] + 0.01, (3, 1))
    regular, at = solve_designs_at(model, {"r6": r6}, inputs)
    near = regular.values["a6"][:, 20:30]
    assert (np.abs(np.where(at.broken, 0.0, np.nan_to_num(at.values["a6"]) - near))
            < 0.05).all()
    np.testing.assert_array_equal(at.broken, regular.broken[:, 20:30])


def test_some_positions_only_are_refused_for_a_coupled_block():
    from mechloop.errors import SolveError

    with pytest.raises(SolveError, match="coupled block is continued"):
        solve_designs(triad(**BASE, sweep=60, n=12), {"r6": [1.2]}, positions=[0, 5])


def test_sensitivities_of_a_triad_match_finite_differences():
    """Design tangents through the block Jacobian (a dyad length, the ternary link's
    side angle — a link's own delta —, a frame length and the crank's angle offset)
    against central differences of solve_designs at every position."""
    from mechloop.solve.sensitivity import position_tangents

    model = triad(**BASE, sweep=360, n=36)
    names = ["r6", "a2", "r4", "a5"]
    base = np.array([1.2257650672131262, math.radians(127.8749836510982), 1.3038404810405297,
                     0.0])
    h = 1e-6 * np.array([0.1, 1.0, 0.1, 1.0])
    rows = np.concatenate([base[None], base + np.diag(h), base - np.diag(h)])
    res = solve_designs(model, dict(zip(names, rows.T, strict=True)), derivatives=False)
    values = {k: np.asarray(t)[:1] for k, t in res.values.items()}
    seeds = {name: np.eye(4)[:, i][:, None, None] for i, name in enumerate(names)}
    tangents = position_tangents(model, values, seeds, 4)
    ok = ~res.broken.any(axis=0)
    assert ok.sum() > 10
    for name in ("a1", "a3", "a6", "a7", "a2", "a8"):
        table = np.asarray(res.values[name])
        fd = np.angle(np.exp(1j * (table[1:5] - table[5:9]))) / (2 * h[:, None])
        np.testing.assert_allclose(tangents[name][:, 0, ok], fd[:, ok], rtol=1e-5,
                                   atol=1e-6)
