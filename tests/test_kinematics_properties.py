"""Whole-model kinematics (DESIGN §1–3) on random mechanisms, against independent answers.

Families, each built with ``mechloop.Model.from_dict`` from random dimensions:

* four-bar (Pl4) — Grashof crank-rockers and arbitrary, non-Grashof ones;
* offset slider-crank (Pl3) with the guide at any angle;
* slotted-link drive, an inverted slider-crank: the guide turns with argument 1 and carries
  the unknown length (Pl3 with the length on a moving vector, a link with a delta);
* two-slider / Scotch-yoke type (Pl2), with a fixed or a turning slot;
* a three-contour chain: four-bar, a coupler point closed by a Pl1 vector, and a slider
  driven from the rocker — links and deltas on lengths and angles;
* a two-input five-bar (arguments 1 and 2, the second with an offset).

What is checked:

(a) positions equal a slow Newton solve of the raw loop equations (``tests/oracles``) to
    1e-10 (relaxed by 1e-13/κ at rows whose Jacobian conditioning κ is tiny: toggles);
(b) velocities and accelerations equal finite differences of positions in time — 5-point
    central stencils over models whose argument table is shifted by ±h, ±2h (exact time
    steps, no interpolation), and over a dense grid for a ``poly345`` law whose own
    acceleration is not zero;
(c) chain breaks of a non-Grashof four-bar sit exactly where the triangle inequality fails;
(d) the order in which contours are listed does not matter;
(e) ``variant: auto`` equals a fixed variant when nothing toggles and follows the smooth
    branch when the dyad's triangle flips.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from oracles.newton import closure_residual, conditioning, newton_solve, wrap

import mechloop
from mechloop.solve.kinematics import BREAK_REASONS

SETTINGS = settings(max_examples=80, deadline=None)

RPM = 120.0
OMEGA = 2 * math.pi * RPM / 60  # rad/s of a crank table {0: θ0, N: θ0 + 360°}

length = st.floats(0.05, 2.0)
degrees = st.floats(-180.0, 180.0)
variant = st.sampled_from([1, 2])


def crank_table(n: int, theta0: float, shift: float = 0.0) -> dict:
    """Argument 1: one turn at constant speed, starting at ``theta0 + shift`` degrees."""
    return {"table": {0: theta0 + shift, n: theta0 + 360.0 + shift}}


def model(vectors: dict, contours: list, n: int, arg: dict, time: dict | None = None,
          more: dict | None = None) -> mechloop.Model:
    """A model of ``positions: n`` with argument 1 = ``arg`` and ``more`` arguments."""
    data = {"positions": n, "arguments": {1: arg, **(more or {})}, "vectors": vectors,
            "contours": contours}
    if time is not None:
        data["time"] = time
    return mechloop.Model.from_dict(data)


# -------------------------------------------------------------------------- families
#
# Each family returns (vectors, contours) of a model dict; angles in degrees, lengths in m.


def four_bar(a, b, c, g, ground, v=1):
    """O crank A (a, argument 1), A coupler B (b), B to rocker pivot D (c), D back to O."""
    return ({1: {"r": a, "a": {"argument": 1}},
             2: {"r": b, "a": "function"},
             3: {"r": c, "a": "function"},
             4: {"r": g, "a": ground + 180.0}},
            [{"vectors": [1, 2, 3, 4], "variant": v}])


def slider_crank(a, b, e, guide, v=1):
    """Crank, rod, slider B on a line at angle ``guide`` offset by ``e`` from O."""
    return ({1: {"r": a, "a": {"argument": 1}},
             2: {"r": b, "a": "function"},
             3: {"r": "function", "a": guide + 180.0},
             4: {"r": e, "a": guide + 90.0}},
            [{"vectors": [1, 2, 3, 4], "variant": v}])


def slotted_link(g, c, e, ground, v=1):
    """Slotted link through O turned by argument 1 (unknown slider distance r1 along it,
    the slot offset ``e`` to its left as a link ``a2 = a1 + 90°``); rocker D–B of length
    ``c`` pivoted at D = g·(cos ground, sin ground)."""
    return ({1: {"r": "function", "a": {"argument": 1}},
             2: {"r": e, "a": {"link": "a1", "delta": 90.0}},
             3: {"r": c, "a": "function"},
             4: {"r": g, "a": ground + 180.0}},
            [{"vectors": [1, 2, 3, 4], "variant": v}])


def two_slider(a, slot, guide, q, qa, turning):
    """Scotch-yoke type: crank pin A slides in a slot (fixed at ``slot`` degrees to the
    guide, or turning with the crank at ``slot`` degrees to it) whose other end slides
    along a fixed guide at ``guide`` degrees."""
    slot_angle = {"link": "a1", "delta": slot} if turning else guide + slot
    return ({1: {"r": a, "a": {"argument": 1}},
             2: {"r": "function", "a": slot_angle},
             3: {"r": "function", "a": guide},
             4: {"r": q, "a": qa}},
            [{"vectors": [1, 2, 3, 4]}])


def five_bar(a, b, c, d, g, ground, v=1):
    """Two-input five-bar: crank O–A (a, argument 1), links A–B (b) and B–E (c), second
    crank D–E (d, argument 2) pivoted at D = g·e(ground); vector 4 runs E→D, so its angle
    is argument 2 plus an offset of 180°."""
    return ({1: {"r": a, "a": {"argument": 1}},
             2: {"r": b, "a": "function"},
             3: {"r": c, "a": "function"},
             4: {"r": d, "a": {"argument": 2, "offset": 180.0}},
             5: {"r": g, "a": ground + 180.0}},
            [{"vectors": [1, 2, 3, 4, 5], "variant": v}])


def second_crank(phi0: float, ratio: float):
    """Argument 2: ``ratio`` turns per turn of argument 1, from ``phi0`` degrees; shifted
    in step with argument 1 (a shift of h degrees of argument 1 is ratio·h of it)."""
    def more(n: int, shift: float) -> dict:
        return {2: {"table": {0: phi0 + ratio * shift, n: phi0 + 360 * ratio + ratio * shift}}}
    return more


def chain3(fb, point, out, variants=(1, 2)):
    """Four-bar (contour 1), coupler point P closed to a fixed point Q by a Pl1 vector
    (contour 2), and a slider driven by an arm on the rocker (contour 3).

    ``fb = (a, b, c, g, ground)``, ``point = (m, gamma, q, qa)``: P = A + m·e(a2 + gamma),
    Q = −q·e(qa); ``out = (d, delta, b2, guide, h)``: arm of length c + d at ``delta`` to
    the rocker, rod b2, slider guide at ``guide`` offset by ``h`` from D.
    """
    a, b, c, g, ground = fb
    m, gamma, q, qa = point
    d, delta, b2, guide, h = out
    vectors, contours = four_bar(a, b, c, g, ground, variants[0])
    vectors.update({
        5: {"r": {"link": "r1"}, "a": {"link": "a1"}},
        6: {"r": m, "a": {"link": "a2", "delta": gamma}},
        7: {"r": "function", "a": "function"},
        8: {"r": q, "a": qa},
        9: {"r": {"link": "r3", "delta": d}, "a": {"link": "a3", "delta": 180.0 + delta}},
        10: {"r": b2, "a": "function"},
        11: {"r": "function", "a": guide + 180.0},
        12: {"r": h, "a": guide + 90.0},
    })
    contours += [{"vectors": [5, 6, 7, 8]},
                 {"vectors": [9, 10, 11, 12], "variant": variants[1]}]
    return vectors, contours


# ------------------------------------------------------------- random dimensions


@st.composite
def grashof_crank_rocker(draw):
    """(a, b, c, g): the crank a is the shortest link and a + l < p + q by a margin."""
    b, c, g = draw(st.floats(0.2, 2.0)), draw(st.floats(0.2, 2.0)), draw(st.floats(0.2, 2.0))
    longest = max(b, c, g)
    room = min(b + c + g - 2 * longest, min(b, c, g)) - 0.02 * longest
    assume(room > 0.06)
    a = draw(st.floats(0.05, room))
    return a, b, c, g


@st.composite
def any_four_bar(draw):
    return tuple(draw(length) for _ in range(4))


@st.composite
def families(draw):
    """A random single-contour mechanism (vectors, contours), possibly with breaks."""
    kind = draw(st.sampled_from(["grashof", "four_bar", "slider_crank", "slotted_link",
                                 "two_slider"]))
    if kind == "grashof":
        return four_bar(*draw(grashof_crank_rocker()), draw(degrees), draw(variant))
    if kind == "four_bar":
        return four_bar(*draw(any_four_bar()), draw(degrees), draw(variant))
    if kind == "slider_crank":
        return slider_crank(draw(length), draw(length), draw(st.floats(-0.5, 0.5)),
                            draw(degrees), draw(variant))
    if kind == "slotted_link":
        return slotted_link(draw(length), draw(length), draw(st.floats(-0.5, 0.5)),
                            draw(degrees), draw(variant))
    return two_slider(draw(length), draw(st.floats(20.0, 160.0)), draw(degrees),
                      draw(length), draw(degrees), draw(st.booleans()))


@st.composite
def chains(draw):
    fb = (*draw(grashof_crank_rocker()), draw(degrees))
    point = (draw(length), draw(degrees), draw(length), draw(degrees))
    c = fb[2]
    d = draw(st.floats(-0.5 * c, 1.0))
    h = draw(st.floats(-0.5, 0.5))
    # the rod reaches the guide from anywhere the arm can be: no break in contour 3
    b2 = c + d + abs(h) + draw(st.floats(0.05, 1.0))
    out = (d, draw(degrees), b2, draw(degrees), h)
    return chain3(fb, point, out, (draw(variant), draw(variant)))


# ------------------------------------------------------------------------- helpers


def solved_names(m: mechloop.Model, res: mechloop.Results) -> list[str]:
    """Every parameter that changes over positions (functions, arguments, their links)."""
    return [name for name in res.values if name not in res.constant]


def assert_positions_match(m, res, oracle, atol=1e-10):
    """Fast and Newton positions agree to ``atol`` (rad; m relative to the largest length
    over 1 m) — plus 1e-13/κ at a row whose Jacobian conditioning κ (sine of the angle
    between its columns) is small: near a toggle any solver's round-off grows as 1/κ."""
    ok = ~res.broken
    assert oracle.converged[ok].all(), "Newton failed where the fast solver succeeded"
    slack = 1e-13 / np.maximum(conditioning(m, res.values)[ok], 1e-300)
    for name in solved_names(m, res):
        fast, slow = res.value(name)[ok], oracle.values[name][ok]
        diff = wrap(fast - slow) if name[0] == "a" else fast - slow
        scale = 1.0 if name[0] == "a" else max(1.0, np.abs(slow).max(initial=0))
        bad = np.abs(diff) > (atol + slack) * scale
        assert not bad.any(), (name, np.flatnonzero(ok)[bad], diff[bad])


def size_of(m: mechloop.Model, name: str) -> float:
    """1 rad for an angle; for a length the largest constant length of the model."""
    if name[0] == "a":
        return 1.0
    return max(abs(v.r) for v in m.vectors.values() if isinstance(v.r, float))


# ---------------------------------------------------------------- (a) positions


@SETTINGS
@given(mech=families(), n=st.integers(8, 90), theta0=degrees)
def test_positions_match_newton_oracle(mech, n, theta0):
    m = model(*mech, n, crank_table(n, theta0), {"rpm": RPM})
    res = mechloop.solve(m)
    assume((~res.broken).sum() >= 2)
    oracle = newton_solve(m, res.values)
    assert_positions_match(m, res, oracle)
    ok = ~res.broken
    assert oracle.residual[ok].max() <= 1e-14
    assert closure_residual(m, res.values)[:, ok].max() <= 1e-12
    # no NaN outside the broken rows, in any column
    for table in (res.values, res.rates, res.accels):
        for name in solved_names(m, res):
            assert np.isfinite(table[name][ok]).all(), name


@SETTINGS
@given(mech=chains(), n=st.integers(8, 90), theta0=degrees)
def test_chained_contours_match_newton_oracle(mech, n, theta0):
    m = model(*mech, n, crank_table(n, theta0), {"rpm": RPM})
    res = mechloop.solve(m)
    assert not res.broken.any()
    oracle = newton_solve(m, res.values)
    assert_positions_match(m, res, oracle)
    assert closure_residual(m, res.values).max() <= 1e-12
    # links: values of linked parameters are their roots plus the deltas
    np.testing.assert_allclose(res.value("a6"), res.value("a2") + math.radians(
        m.vectors[6].a.delta), rtol=0, atol=1e-14)
    np.testing.assert_allclose(res.rate("a9"), res.rate("a3"), rtol=0, atol=0)


@settings(max_examples=50, deadline=None)
@given(mech=families(), n=st.integers(72, 144), theta0=degrees)
def test_oracle_by_continuation_follows_the_fixed_variant(mech, n, theta0):
    """Newton started once at position 0 and then from its own previous solution stays on
    the branch the fast solver picks by its variant convention (no toggle in between)."""
    m = model(*mech, n, crank_table(n, theta0), {"rpm": RPM})
    res = mechloop.solve(m)
    assume(not res.broken.any())
    assume(conditioning(m, res.values).min() > 0.2)
    assert_positions_match(m, res, newton_solve(m, res.values, continuation=True))


# -------------------------------------------------------- (b) derivatives by FD
#
# Scheme: 5-point central stencils, error O(h⁴), at step h and at step 2h.  Where the two
# agree to FD_RTOL/10 the stencil at h has converged (its error is about 1/15 of their
# difference), and there the exact derivative must agree with it to FD_RTOL.  Rows close
# to a break, where higher derivatives explode, drop out by themselves; a wrong sign or a
# missing term is a relative error of order one at every row and cannot hide.  Tolerances
# are relative to the largest magnitude over the cycle, with a floor of size·ω (size·ω²),
# size = 1 rad or the mechanism's largest constant length.

H_DEG = 0.01  # step of the crank in degrees for the shifted-table stencils
SHIFTS = (-4, -2, -1, 0, 1, 2, 4)
FD_RTOL_RATE = 1e-6
FD_RTOL_ACCEL = 1e-5
MIN_CONDITIONING = 0.05


def stencils(f: dict[int, np.ndarray], step: int, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """5-point central first and second derivatives from samples ``f[s]`` taken at
    ``s·dt``, with stride ``step``."""
    a, b = step, 2 * step
    h = step * dt
    d1 = (-f[b] + 8 * f[a] - 8 * f[-a] + f[-b]) / (12 * h)
    d2 = (-f[b] + 16 * f[a] - 30 * f[0] + 16 * f[-a] - f[-b]) / (12 * h * h)
    return d1, d2


def check_derivatives(name, samples, exact_rate, exact_accel, rows, dt, size) -> int:
    """Compare exact rates with converged stencils; returns how many rows were compared."""
    if name[0] == "a":  # differences from the centre: immune to 2π jumps between samples
        samples = {s: wrap(v - samples[0]) for s, v in samples.items()}
    fine1, fine2 = stencils(samples, 1, dt)
    coarse1, coarse2 = stencils(samples, 2, dt)
    scale_v = max(np.abs(exact_rate[rows]).max(initial=0), size * OMEGA)
    scale_a = max(np.abs(exact_accel[rows]).max(initial=0), size * OMEGA**2)
    with np.errstate(invalid="ignore"):
        conv_v = rows & (np.abs(fine1 - coarse1) <= 0.1 * FD_RTOL_RATE * scale_v)
        conv_a = rows & (np.abs(fine2 - coarse2) <= 0.1 * FD_RTOL_ACCEL * scale_a)
    err_v = np.abs(exact_rate - fine1)[conv_v]
    err_a = np.abs(exact_accel - fine2)[conv_a]
    assert err_v.max(initial=0) <= FD_RTOL_RATE * scale_v, f"velocity of {name}"
    assert err_a.max(initial=0) <= FD_RTOL_ACCEL * scale_a, f"acceleration of {name}"
    return int(min(conv_v.sum(), conv_a.sum()))


def check_by_shifted_tables(vectors, contours, n, theta0, more=None):
    """Exact rates against stencils over models whose crank table is shifted by whole
    steps of H_DEG (each model's position k sits exactly s·dt later in time).  ``more(n,
    shift)`` gives further arguments, shifted by the same time step."""
    solved = {}
    for s in SHIFTS:
        extra = more(n, s * H_DEG) if more is not None else None
        m = model(vectors, contours, n, crank_table(n, theta0, s * H_DEG), {"rpm": RPM},
                  extra)
        solved[s] = mechloop.solve(m)
    base = solved[0]
    m0 = base.model
    rows = ~np.logical_or.reduce([r.broken for r in solved.values()])
    rows &= conditioning(m0, base.values) > MIN_CONDITIONING
    assume(rows.sum() >= 2)
    dt = math.radians(H_DEG) / OMEGA
    compared = 0
    for name in solved_names(m0, base):
        samples = {s: r.value(name) for s, r in solved.items()}
        compared += check_derivatives(name, samples, base.rate(name), base.accel(name),
                                      rows, dt, size_of(m0, name))
    assert compared > 0


@SETTINGS
@given(mech=families(), n=st.integers(8, 72), theta0=degrees)
def test_rates_match_finite_differences(mech, n, theta0):
    check_by_shifted_tables(*mech, n, theta0)


@SETTINGS
@given(mech=chains(), n=st.integers(8, 72), theta0=degrees)
def test_chained_rates_match_finite_differences(mech, n, theta0):
    check_by_shifted_tables(*mech, n, theta0)


@st.composite
def five_bars(draw):
    g = draw(st.floats(0.5, 2.0))
    a, d = draw(st.floats(0.05, 0.25 * g)), draw(st.floats(0.05, 0.25 * g))
    b, c = draw(st.floats(0.3, 2.0)), draw(st.floats(0.3, 2.0))
    spec = five_bar(a, b, c, d, g, draw(degrees), draw(variant))
    return spec, second_crank(draw(degrees), draw(st.floats(-2.0, 2.0)))


@SETTINGS
@given(five=five_bars(), n=st.integers(8, 72), theta0=degrees)
def test_two_input_five_bar_matches_oracle_and_finite_differences(five, n, theta0):
    (vectors, contours), more = five
    m = model(vectors, contours, n, crank_table(n, theta0), {"rpm": RPM}, more(n, 0.0))
    res = mechloop.solve(m)
    assume((~res.broken).sum() >= 2)
    assert_positions_match(m, res, newton_solve(m, res.values))
    check_by_shifted_tables(vectors, contours, n, theta0, more)


@settings(max_examples=15, deadline=None)
@given(five=five_bars(), theta0=degrees)
def test_analogs_of_a_two_input_five_bar(five, theta0):
    """Without time, derivatives are taken with respect to argument 1; both arguments run
    at constant speed, so analog = time derivative / ω1, second analog = ... / ω1²."""
    (vectors, contours), more = five
    n = 36
    timed = mechloop.solve(model(vectors, contours, n, crank_table(n, theta0), {"rpm": RPM},
                                 more(n, 0.0)))
    analog = mechloop.solve(model(vectors, contours, n, crank_table(n, theta0), None,
                                  more(n, 0.0)))
    for name in ("a2", "a3", "a4"):
        np.testing.assert_allclose(analog.rate(name), timed.rate(name) / OMEGA, rtol=1e-9,
                                   atol=1e-12)
        np.testing.assert_allclose(analog.accel(name), timed.accel(name) / OMEGA**2,
                                   rtol=1e-9, atol=1e-12)


DENSE = 3000


@settings(max_examples=50, deadline=None)
@given(mech=st.one_of(families(), chains()), theta0=degrees,
       sweep=st.floats(90.0, 400.0), law=st.sampled_from(["poly345", "cycloidal"]))
def test_rates_match_finite_differences_under_an_accelerating_law(mech, theta0, sweep, law):
    """Argument 1 follows a law with non-zero acceleration (the terms r α̈ and 2 ṙ α̇ of
    the known vectors matter); stencils over a dense uniform time grid."""
    arg = {"law": law, "start": [0, theta0], "end": [DENSE, theta0 + sweep]}
    m = model(*mech, DENSE, arg, {"rpm": RPM})
    res = mechloop.solve(m)
    dt = 60.0 / RPM / DENSE
    rows = np.zeros(DENSE + 1, dtype=bool)
    rows[4:-4] = True
    for s in SHIFTS:
        rows &= ~np.roll(res.broken, s)
    rows &= conditioning(m, res.values) > MIN_CONDITIONING
    assume(rows.sum() >= 2)
    compared = 0
    for name in solved_names(m, res):
        v = res.value(name)
        samples = {s: np.roll(v, -s) for s in SHIFTS}
        compared += check_derivatives(name, samples, res.rate(name), res.accel(name), rows,
                                      dt, size_of(m, name))
    assert compared > 0


# ------------------------------------------------------------- (c) chain breaks


@st.composite
def non_grashof(draw):
    a, b, c, g = (draw(length) for _ in range(4))
    s, p, q, longest = sorted([a, b, c, g])
    assume(s + longest > p + q + 0.01)
    return a, b, c, g


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(dims=non_grashof(), ground=degrees, theta0=degrees, n=st.integers(12, 144),
       v=variant)
def test_non_grashof_four_bar_breaks_where_the_triangle_fails(dims, ground, theta0, n, v):
    a, b, c, g = dims
    m = model(*four_bar(a, b, c, g, ground, v), n, crank_table(n, theta0), {"rpm": RPM})
    # independent: distance from the crank pin A to the rocker pivot D
    theta = np.radians(theta0 + 360.0 * np.arange(n + 1) / n)
    ax, ay = a * np.cos(theta), a * np.sin(theta)
    dx, dy = g * math.cos(math.radians(ground)), g * math.sin(math.radians(ground))
    p = np.hypot(dx - ax, dy - ay)
    lo, hi = abs(b - c), b + c
    assume(np.minimum(np.abs(p - lo), np.abs(p - hi)).min() > 1e-6 * hi)
    expected = ~((lo < p) & (p < hi))
    assume(expected.any() and not expected.all())

    res = mechloop.solve(m)
    np.testing.assert_array_equal(res.broken, expected)
    assert len(res.breaks) == 1
    brk = res.breaks[0]
    assert (brk.contour, brk.module) == (1, "Pl4")
    assert brk.reason == BREAK_REASONS["Pl4"]
    np.testing.assert_array_equal(brk.positions, np.flatnonzero(expected))
    for name in ("a1", "a2", "a3"):
        for table in (res.values, res.rates, res.accels):
            assert np.isnan(table[name][expected]).all(), name
            assert np.isfinite(table[name][~expected]).all(), name
    for name in ("r1", "r2", "r3", "r4", "a4"):  # constants stay numbers everywhere
        assert np.isfinite(res.value(name)).all()


@settings(max_examples=80, deadline=None)
@given(a=length, b=length, e=st.floats(-0.5, 0.5), guide=degrees, theta0=degrees,
       n=st.integers(12, 144), v=variant)
def test_slider_crank_breaks_where_the_rod_cannot_reach_the_guide(a, b, e, guide, theta0,
                                                                  n, v):
    m = model(*slider_crank(a, b, e, guide, v), n, crank_table(n, theta0), {"rpm": RPM})
    # independent: distance from the crank pin A to the slider line {B : B·n = −e}
    theta = np.radians(theta0 + 360.0 * np.arange(n + 1) / n)
    normal = math.radians(guide + 90.0)
    dist = np.abs(a * np.cos(theta - normal) + e)
    assume(np.abs(dist - b).min() > 1e-6 * b)
    expected = dist > b
    res = mechloop.solve(m)
    np.testing.assert_array_equal(res.broken, expected)
    if expected.any():
        assert [(b.contour, b.module, b.reason) for b in res.breaks] == [
            (1, "Pl3", BREAK_REASONS["Pl3"])]
        np.testing.assert_array_equal(res.breaks[0].positions, np.flatnonzero(expected))
    else:
        assert res.breaks == ()
    for name in ("r3", "a2"):
        assert np.isnan(res.value(name)[expected]).all()
        assert np.isfinite(res.accel(name)[~expected]).all()


@pytest.mark.parametrize("a, g, b_share", [(0.5, 0.8, 0.3), (0.5, 0.4, 0.3),
                                           (0.7, 0.8, 0.3), (0.7, 0.4, 0.3),
                                           (0.3, 1.1, 0.45)])
def test_limit_position_on_a_calculation_position_is_a_dead_point(a, g, b_share):
    """A non-Grashof four-bar whose limit positions fall on positions 12 and 60 of 72
    (crank at ±60°): there |AD| = sqrt(a² + g² − ag) = b + c, coupler and rocker are in
    line, the loop's Jacobian is singular and the velocities are unbounded.  Those rows
    must be reported (a dead point or a break), never returned as numbers."""
    p60 = math.sqrt(a * a + g * g - 2 * a * g * math.cos(math.radians(60.0)))
    b = b_share * p60
    c = p60 - b
    m = model(*four_bar(a, b, c, g, 0.0), 72, crank_table(72, 0.0), {"rpm": 60})
    res = mechloop.solve(m)
    theta = np.radians(5.0 * np.arange(73))
    p = np.hypot(g - a * np.cos(theta), a * np.sin(theta))
    at_limit = np.abs(p - (b + c)) <= 1e-12 * (b + c)
    assert np.flatnonzero(at_limit).tolist() == [12, 60]
    assert res.broken[at_limit].all(), (
        "limit positions not reported; rate of a3 there: "
        f"{res.rate('a3')[at_limit]}, acceleration {res.accel('a3')[at_limit]}")
    # and nothing unbounded is returned as a number anywhere
    omega = 2 * math.pi
    assert np.nanmax(np.abs(res.rate("a3"))) < 1e4 * omega


@pytest.mark.parametrize("a, e, guide", [(0.3, 0.0, 0.0), (0.45, 0.05, 30.0),
                                         (0.7, -0.1, 0.0)])
def test_rod_square_to_the_guide_on_a_calculation_position_is_a_dead_point(a, e, guide):
    """An offset slider-crank whose rod just reaches the guide (rod length = distance of
    the crank pin from the guide line at crank 60°, position 12 of 72): the rod is square
    to the guide, the loop's Jacobian is singular, the slider velocity unbounded."""
    normal = math.radians(guide + 90.0)
    b = abs(a * math.cos(math.radians(60.0) - normal) + e)
    res = mechloop.solve(model(*slider_crank(a, b, e, guide), 72, crank_table(72, 0.0),
                               {"rpm": 60}))
    theta = np.radians(5.0 * np.arange(73))
    at_limit = np.abs(np.abs(a * np.cos(theta - normal) + e) - b) <= 1e-12 * b
    assert 12 in np.flatnonzero(at_limit)
    assert res.broken[at_limit].all(), (
        f"limit positions {np.flatnonzero(at_limit)} not reported; slider velocity there "
        f"{res.rate('r3')[at_limit]}, acceleration {res.accel('r3')[at_limit]}")


def test_turning_slot_breaks_where_it_is_parallel_to_the_guide():
    """Slot at 90° to the crank, guide at 0°: parallel when the crank is at 90° and 270°,
    positions 18 and 54 of 72 (5° steps)."""
    m = model(*two_slider(0.1, 90.0, 0.0, 0.3, 250.0, True), 72, crank_table(72, 0.0),
              {"rpm": RPM})
    res = mechloop.solve(m)
    assert np.flatnonzero(res.broken).tolist() == [18, 54]
    assert [(b.contour, b.module, b.positions.tolist(), b.reason) for b in res.breaks] == [
        (1, "Pl2", [18, 54], BREAK_REASONS["Pl2"])]
    assert np.isnan(res.value("r2")[[18, 54]]).all()
    assert np.isfinite(res.value("r2")[~res.broken]).all()


@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(dims=non_grashof(), ground=degrees, theta0=degrees, gamma=degrees, delta=degrees,
       guide=degrees)
def test_break_in_a_contour_propagates_to_the_contours_that_need_it(dims, ground, theta0,
                                                                    gamma, delta, guide):
    a, b, c, g = dims
    n = 72
    fb = model(*four_bar(a, b, c, g, ground), n, crank_table(n, theta0), {"rpm": RPM})
    alone = mechloop.solve(fb)
    assume(alone.broken.any() and not alone.broken.all())
    # contour 3's rod reaches its guide from anywhere: it can only break with contour 1
    chain = chain3((a, b, c, g, ground), (0.2, gamma, 0.3, 100.0),
                   (0.1, delta, c + 0.1 + 0.05 + 0.2, guide, 0.05))
    res = mechloop.solve(model(*chain, n, crank_table(n, theta0), {"rpm": RPM}))
    np.testing.assert_array_equal(res.broken, alone.broken)
    # contours 2 and 3 need contour 1: they inherit its break and do not report it again
    # (a toggle that falls on a position is a second, "dead point" record of contour 1)
    assert {brk.contour for brk in res.breaks} == {1}
    assert [(b.reason, b.positions.tolist()) for b in res.breaks] == [
        (b.reason, b.positions.tolist()) for b in alone.breaks]
    for name in ("a2", "r7", "a7", "r11", "a10"):
        assert np.isnan(res.value(name)[alone.broken]).all(), name
        assert np.isfinite(res.value(name)[~alone.broken]).all(), name


# --------------------------------------------------------- (d) contour order


@settings(max_examples=50, deadline=None)
@given(mech=chains(), theta0=degrees, perm=st.permutations([0, 1, 2]))
def test_contour_order_does_not_matter(mech, theta0, perm):
    vectors, contours = mech
    n = 36
    ref = mechloop.solve(model(vectors, contours, n, crank_table(n, theta0), {"rpm": RPM}))
    shuffled = [contours[i] for i in perm]
    res = mechloop.solve(model(vectors, shuffled, n, crank_table(n, theta0), {"rpm": RPM}))
    for table in ("values", "rates", "accels"):
        for name, want in getattr(ref, table).items():
            np.testing.assert_allclose(getattr(res, table)[name], want, rtol=1e-14,
                                       atol=1e-300, err_msg=f"{table} {name}")
    np.testing.assert_array_equal(res.broken, ref.broken)


def test_every_listing_order_of_a_chain_gives_the_same_numbers():
    vectors, contours = chain3((0.1, 0.35, 0.3, 0.4, 10.0), (0.2, 30.0, 0.3, 200.0),
                               (0.05, 20.0, 0.6, -15.0, 0.02))
    n = 24
    ref = mechloop.solve(model(vectors, contours, n, crank_table(n, 0.0), {"rpm": RPM}))
    for perm in itertools.permutations(range(3)):
        res = mechloop.solve(model(vectors, [contours[i] for i in perm], n,
                                   crank_table(n, 0.0), {"rpm": RPM}))
        for name in ref.values:
            np.testing.assert_array_equal(res.value(name), ref.value(name))
            np.testing.assert_array_equal(res.rate(name), ref.rate(name))
            np.testing.assert_array_equal(res.accel(name), ref.accel(name))


# ------------------------------------------------------------ (e) variant: auto


@SETTINGS
@given(dims=grashof_crank_rocker(), ground=degrees, theta0=degrees, n=st.integers(36, 90))
def test_auto_variant_equals_variant_1_without_a_toggle(dims, ground, theta0, n):
    fixed = model(*four_bar(*dims, ground, 1), n, crank_table(n, theta0), {"rpm": RPM})
    auto = model(*four_bar(*dims, ground, "auto"), n, crank_table(n, theta0), {"rpm": RPM})
    ref, res = mechloop.solve(fixed), mechloop.solve(auto)
    for name in ref.values:
        np.testing.assert_array_equal(res.value(name), ref.value(name))
        np.testing.assert_array_equal(res.rate(name), ref.rate(name))
        np.testing.assert_array_equal(res.accel(name), ref.accel(name))


@settings(max_examples=50, deadline=None)
@given(g=length, extra=st.floats(0.05, 1.0), e=st.floats(-0.3, 0.3), ground=degrees,
       theta0=degrees)
def test_auto_variant_equals_variant_1_for_a_slotted_link(g, extra, e, ground, theta0):
    c = g + abs(e) + extra  # the rocker always reaches the slot: no break, no toggle
    n = 72
    ref = mechloop.solve(model(*slotted_link(g, c, e, ground, 1), n,
                               crank_table(n, theta0), {"rpm": RPM}))
    res = mechloop.solve(model(*slotted_link(g, c, e, ground, "auto"), n,
                               crank_table(n, theta0), {"rpm": RPM}))
    for name in ref.values:
        np.testing.assert_array_equal(res.value(name), ref.value(name))


def folded_dyad(c: float, s_max: float, n: int, v) -> mechloop.Model:
    """Two equal links (c) from the end of a vector of signed length s (argument 1,
    constant speed from +s_max to −0.9 s_max) back to its start: the dyad's base shrinks
    through zero and the triangle flips through a straight line (n positions, s ≠ 0)."""
    return mechloop.Model.from_dict({
        "positions": n,
        "arguments": {1: {"law": "constant_speed", "start": [0, s_max],
                          "end": [n, -0.9 * s_max]}},
        "vectors": {1: {"r": {"argument": 1}, "a": 30.0},
                    2: {"r": c, "a": "function"},
                    3: {"r": c, "a": "function"}},
        "contours": [{"vectors": [1, 2, 3], "variant": v}],
    })


@pytest.mark.parametrize("n", [41, 60, 97])
def test_auto_variant_follows_the_smooth_branch_through_a_flip(n):
    c, s_max, phi = 0.5, 0.3, math.radians(30.0)
    res = mechloop.solve(folded_dyad(c, s_max, n, "auto"))
    s = res.arguments[1]
    assert not res.broken.any() and (s > 0).any() and (s < 0).any()
    # Independent: r2 + r3 = −s e(φ) with |r2| = |r3| = c.  On the smooth branch r3 is r2
    # mirrored about the line φ: α2 = φ + β, α3 = φ − β, 2c cos β = −s.  Variant 1 at the
    # start (s > 0) has cross(p, r2) = −s c sin β > 0: sin β < 0, kept throughout.
    beta = -np.arccos(-s / (2 * c))
    assert np.abs(wrap(res.value("a2") - (phi + beta))).max() < 1e-12
    assert np.abs(wrap(res.value("a3") - (phi - beta))).max() < 1e-12
    # analogs with respect to s (no model time): dβ/ds = −1 / (2c sin(−β))
    dbeta = 1 / (2 * c * np.sin(beta))
    np.testing.assert_allclose(res.rate("a2"), dbeta, rtol=1e-9)
    np.testing.assert_allclose(res.rate("a3"), -dbeta, rtol=1e-9)
    # d²β/ds² = −cos β · β' / (2c sin² β)
    ddbeta = -np.cos(beta) * dbeta / (2 * c * np.sin(beta) ** 2)
    np.testing.assert_allclose(res.accel("a2"), ddbeta, rtol=1e-8)
    # a fixed variant jumps to the mirror branch where the triangle flips
    fixed = mechloop.solve(folded_dyad(c, s_max, n, 1))
    jump = np.abs(wrap(np.diff(fixed.value("a2")))).max()
    assert jump > 1.0
    # and Newton continued from position 0 agrees with the tracked branch
    oracle = newton_solve(res.model, res.values, continuation=True, perturbation=1e-3)
    assert np.abs(wrap(oracle.values["a2"] - res.value("a2"))).max() < 1e-10


# ------------------------------------------------- blocks of positions (solve(block=))


def assert_same_results(res, ref):
    np.testing.assert_array_equal(res.broken, ref.broken)
    assert [(b.contour, b.reason, b.positions.tolist()) for b in res.breaks] == [
        (b.contour, b.reason, b.positions.tolist()) for b in ref.breaks]
    for table in ("values", "rates", "accels"):
        for name, want in getattr(ref, table).items():
            np.testing.assert_array_equal(getattr(res, table)[name], want,
                                          err_msg=f"{table} {name}")


@settings(max_examples=50, deadline=None)
@given(mech=st.one_of(families(), chains()), n=st.integers(8, 90), theta0=degrees,
       block=st.integers(1, 40), auto=st.booleans())
def test_results_do_not_depend_on_the_block_size(mech, n, theta0, block, auto):
    vectors, contours = mech
    if auto:
        contours = [c | {"variant": "auto"} if "variant" in c else c for c in contours]
    m = model(vectors, contours, n, crank_table(n, theta0), {"rpm": RPM})
    assert_same_results(mechloop.solve(m, block=block), mechloop.solve(m))


@pytest.mark.parametrize("block", [1, 2, 3, 20, 21, 22, 23])
def test_auto_variant_is_tracked_across_blocks(block):
    """The folded dyad flips between positions 21 and 22 of 41 (s = 0 there)."""
    m = folded_dyad(0.5, 0.3, 41, "auto")
    ref = mechloop.solve(m)
    assert np.flatnonzero(np.diff(np.sign(ref.arguments[1]))).tolist() == [21]
    assert_same_results(mechloop.solve(m, block=block), ref)
