"""Model inputs: motion laws, sparse tables, model time, and derivatives with respect to
time or to argument 1 ("analogs") — DESIGN §1 and §3, seed 000 App. A sec. 1.4.

Laws are checked against finite differences of their own values and against their closed
forms at landmarks; tables against KDAM's worked example; time and analogs against the
chain rule written out here.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop import SolveError
from mechloop.model.laws import evaluate_law
from mechloop.model.tables import fill_table
from mechloop.solve.inputs import model_arguments, model_time

LAWS = ["constant_speed", "harmonic", "cycloidal", "poly345"]
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "crank_slider.yaml"

#: f(τ) of each normalized law, written independently of mechloop.model.laws.
SHAPES = {
    "constant_speed": lambda t: t,
    "harmonic": lambda t: (1 - np.cos(np.pi * t)) / 2,
    "cycloidal": lambda t: t - np.sin(2 * np.pi * t) / (2 * np.pi),
    "poly345": lambda t: 10 * t**3 - 15 * t**4 + 6 * t**5,
}


# ---------------------------------------------------------------------------- laws


@settings(max_examples=60, deadline=None)
@given(law=st.sampled_from(LAWS), c0=st.floats(-5, 5), span=st.floats(0.1, 10),
       q0=st.floats(-10, 10), q1=st.floats(-10, 10))
def test_law_derivatives_match_finite_differences(law, c0, span, q0, q1):
    c1 = c0 + span
    h = 1e-4 * span
    c = np.linspace(c0 + 3 * h, c1 - 3 * h, 41)  # inside: the stencils stay in [c0, c1]
    q, dq, ddq = evaluate_law(law, c, c0, c1, q0, q1)
    qp, dqp, _ = evaluate_law(law, c + h, c0, c1, q0, q1)
    qm, dqm, _ = evaluate_law(law, c - h, c0, c1, q0, q1)
    qp2, _, _ = evaluate_law(law, c + 2 * h, c0, c1, q0, q1)
    qm2, _, _ = evaluate_law(law, c - 2 * h, c0, c1, q0, q1)
    # tolerance: truncation (relative 1e-6 of the law's scale) plus round-off of values
    # of size |q| divided by the step
    noise = 1e-14 * (abs(q0) + abs(q1) + 1.0) / h
    d1 = (-qp2 + 8 * qp - 8 * qm + qm2) / (12 * h)
    assert np.abs(dq - d1).max() <= 1e-6 * abs(q1 - q0) / span + noise
    d2 = (dqp - dqm) / (2 * h)  # of the exact first derivative
    assert np.abs(ddq - d2).max() <= 1e-6 * abs(q1 - q0) / span**2 + noise / span
    # and the value is the closed form
    np.testing.assert_allclose(q, q0 + (q1 - q0) * SHAPES[law]((c - c0) / span),
                               rtol=0, atol=1e-12 * (abs(q0) + abs(q1) + 1))


@pytest.mark.parametrize("law", LAWS)
def test_law_boundary_values_and_dwells(law):
    c0, c1, q0, q1 = 2.0, 6.0, 1.5, -0.5
    c = np.array([0.0, 1.0, 1.999, c0, c1, 6.001, 9.0])
    q, dq, ddq = evaluate_law(law, c, c0, c1, q0, q1)
    h, span = q1 - q0, c1 - c0
    # the start value before the law, the end value after it, nothing moves
    assert q[:3].tolist() == pytest.approx([q0, q0, q0], abs=1e-6 * abs(h))
    assert q[5:].tolist() == pytest.approx([q1, q1], abs=1e-6 * abs(h))
    assert q[3] == q0 and q[4] == pytest.approx(q1, abs=1e-15)
    np.testing.assert_array_equal(dq[[0, 1, 6]], 0.0)
    np.testing.assert_array_equal(ddq[[0, 1, 6]], 0.0)
    # one-sided derivatives at the ends, from f'(0), f'(1), f''(0), f''(1):
    #   constant speed 1, 1, 0, 0; harmonic 0, 0, π²/2, −π²/2;
    #   cycloidal and 3-4-5 polynomial 0 everywhere (their point: no jerk at the ends)
    ends = {"constant_speed": (1, 1, 0, 0), "harmonic": (0, 0, math.pi**2 / 2,
                                                          -math.pi**2 / 2),
            "cycloidal": (0, 0, 0, 0), "poly345": (0, 0, 0, 0)}[law]
    atol1, atol2 = 1e-12 * abs(h) / span, 1e-12 * abs(h) / span**2
    assert dq[3] == pytest.approx(h * ends[0] / span, abs=atol1)
    assert dq[4] == pytest.approx(h * ends[1] / span, abs=atol1)
    assert ddq[3] == pytest.approx(h * ends[2] / span**2, abs=atol2)
    assert ddq[4] == pytest.approx(h * ends[3] / span**2, abs=atol2)


@pytest.mark.parametrize("law, slope", [("constant_speed", 1.0), ("harmonic", math.pi / 2),
                                        ("cycloidal", 2.0), ("poly345", 15 / 8)])
def test_laws_at_mid_stroke(law, slope):
    """Each law is half-way at τ = ½, with the textbook peak velocity factor f'(½)."""
    q, dq, ddq = evaluate_law(law, [0.5], 0.0, 1.0, 0.0, 1.0)
    assert q[0] == pytest.approx(0.5, abs=1e-15)
    assert dq[0] == pytest.approx(slope, rel=1e-14)
    assert ddq[0] == pytest.approx(0.0, abs=1e-13)


@pytest.mark.parametrize("law", LAWS)
def test_law_argument_in_a_model_is_evaluated_on_model_time(law):
    """A law from position 3 to 15 of 20 in degrees, 600 rpm: values in rad on the time
    axis; rates are time derivatives."""
    n, rpm = 20, 600.0
    m = crank_slider_model(n, {"law": law, "start": [3, 10.0], "end": [15, 70.0]},
                           {"rpm": rpm})
    t = 60 / rpm * np.arange(n + 1) / n
    t0, t1 = t[3], t[15]
    args = model_arguments(m, model_time(m))[1]
    tau = np.clip((t - t0) / (t1 - t0), 0, 1)
    np.testing.assert_allclose(args.value, np.radians(10 + 60 * SHAPES[law](tau)),
                               rtol=1e-13, atol=1e-15)
    # rate by a central difference of the law on a fine time step
    h = 1e-6
    up = np.radians(10 + 60 * SHAPES[law](np.clip((t + h - t0) / (t1 - t0), 0, 1)))
    dn = np.radians(10 + 60 * SHAPES[law](np.clip((t - h - t0) / (t1 - t0), 0, 1)))
    inside = (t > t0) & (t < t1)
    np.testing.assert_allclose(args.rate[inside], ((up - dn) / (2 * h))[inside], rtol=1e-6)
    np.testing.assert_array_equal(args.rate[~((t >= t0) & (t <= t1))], 0.0)


# -------------------------------------------------------------------------- tables


def test_kdam_worked_example_table():
    """Seed 000, App. A sec. 1.4, Table 3.1 -> Table 3.2: N = 12, values at 3, 6, 10.
    Positions 4, 5 (not printed in Table 3.2) interpolate 0.12 -> 0.26 linearly."""
    filled = fill_table({3: 0.12, 6: 0.26, 10: 0.18}, 12)
    expected = [0.12, 0.12, 0.12, 0.12, 0.12 + 0.14 / 3, 0.12 + 0.28 / 3,
                0.26, 0.24, 0.22, 0.20, 0.18, 0.18, 0.18]
    np.testing.assert_allclose(filled, expected, rtol=0, atol=1e-15)


def test_table_forms():
    assert fill_table({5: 2.0}, 4).tolist() == [2.0] * 5  # one value holds everywhere
    assert fill_table({0: 0.0, 4: 1.0}, 4).tolist() == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert fill_table([3, 1, 4], 2).tolist() == [3.0, 1.0, 4.0]
    assert fill_table({2: 1.0, 0: 0.0}, 3).tolist() == [0.0, 0.5, 1.0, 1.0]  # any order
    with pytest.raises(ValueError):
        fill_table([1.0, 2.0], 3)


def test_table_argument_with_units_and_exact_linear_rate():
    """{0: 0, 72: 360} deg over 72 positions at 3000 rpm: θ = ω t exactly."""
    m = mechloop.load_model(EXAMPLE)
    sig = model_arguments(m, model_time(m))[1]
    omega = 2 * math.pi * 3000 / 60
    np.testing.assert_allclose(sig.value, np.radians(5.0 * np.arange(73)), rtol=1e-15)
    np.testing.assert_allclose(sig.rate, omega, rtol=1e-12)
    np.testing.assert_allclose(sig.accel, 0.0, atol=1e-9 * omega**2)


def test_table_argument_rate_is_zero_where_the_table_holds():
    """KDAM's example as a crank-angle table (rad) at 100 rpm: the argument holds still at
    positions 0–3 and 10–12 and moves at constant slope on 3–6 and 6–10, so its time
    derivative is 0 inside the holds and slope/Δt inside the ramps (positions 4, 5 and
    7, 8, 9), whatever happens at the corners 3, 6, 10."""
    n, rpm = 12, 100.0
    m = crank_slider_model(n, {"table": {3: 0.12, 6: 0.26, 10: 0.18}, "unit": "rad"},
                           {"rpm": rpm})
    dt = 60 / rpm / n
    rate = model_arguments(m, model_time(m))[1].rate
    expected = {0: 0.0, 1: 0.0, 2: 0.0, 4: 0.14 / 3 / dt, 5: 0.14 / 3 / dt,
                7: -0.02 / dt, 8: -0.02 / dt, 9: -0.02 / dt, 11: 0.0, 12: 0.0}
    got = {k: float(rate[k]) for k in expected}
    assert got == pytest.approx(expected, abs=1e-9)
    # at a corner the (documented) rate is the mean of the slopes on either side
    corners = {3: 0.14 / 6 / dt, 6: (0.14 / 3 - 0.02) / 2 / dt, 10: -0.01 / dt}
    assert {k: float(rate[k]) for k in corners} == pytest.approx(corners, abs=1e-9)


# ---------------------------------------------------------------------------- time


def crank_slider_model(n: int, arg: dict, time: dict | None) -> mechloop.Model:
    data = {
        "positions": n,
        "arguments": {1: arg},
        "vectors": {1: {"r": 0.05, "a": {"argument": 1}},
                    2: {"r": 0.2, "a": "function"},
                    3: {"r": "function", "a": 180},
                    4: {"r": 0.01, "a": 90}},
        "contours": [{"vectors": [1, 2, 3, 4]}],
    }
    if time is not None:
        data["time"] = time
    return mechloop.Model.from_dict(data)


FULL_TURN = {"table": {0: 0, 36: 360}}


def test_time_from_rpm():
    res = mechloop.solve(crank_slider_model(36, FULL_TURN, {"rpm": 1500}))
    np.testing.assert_allclose(res.time, 60 / 1500 * np.arange(37) / 36, rtol=1e-15)


def test_time_from_a_sparse_table_equals_time_from_rpm():
    by_rpm = mechloop.solve(crank_slider_model(36, FULL_TURN, {"rpm": 1500}))
    by_table = mechloop.solve(crank_slider_model(36, FULL_TURN,
                                                 {"table": {0: 0.0, 36: 0.04}}))
    np.testing.assert_allclose(by_table.time, by_rpm.time, rtol=1e-14)
    for name in ("r3", "a2"):
        np.testing.assert_allclose(by_table.rate(name), by_rpm.rate(name), rtol=1e-9)
        np.testing.assert_allclose(by_table.accel(name), by_rpm.accel(name), rtol=1e-8,
                                   atol=1e-8 * np.abs(by_rpm.accel(name)).max())


@pytest.mark.parametrize("derivatives", ["spline", "linear"])
def test_time_table_that_is_not_uniform(derivatives):
    """t_k = T (u + u²)/2 with u = k/N and θ_k = 2π u: by the chain rule
    θ̇ = θ'/t' and θ̈ = −θ̇ t''/t'² (θ'' = 0), with ' = d/dk.  A cubic spline reproduces
    this quadratic time exactly at every position; central differences (``linear``) do so
    at the inner positions."""
    n, period = 24, 0.05
    u = np.arange(n + 1) / n
    t = period * (u + u * u) / 2
    m = crank_slider_model(n, {"table": {0: 0, n: 360}},
                           {"table": t.tolist(), "derivatives": derivatives})
    res = mechloop.solve(m)
    np.testing.assert_allclose(res.time, t, rtol=1e-15)
    dt = period * (1 / n + 2 * u / n) / 2
    ddt = period / n**2
    rate = (2 * np.pi / n) / dt
    rows = slice(None) if derivatives == "spline" else slice(1, -1)
    np.testing.assert_allclose(res.rate("a1")[rows], rate[rows], rtol=1e-10)
    np.testing.assert_allclose(res.accel("a1")[rows], (-rate * ddt / dt**2)[rows],
                               rtol=1e-8)


# ------------------------------------------------------------------------- analogs


def test_analogs_are_time_derivatives_divided_by_the_rate_of_argument_1():
    """Crank angle θ_k = 2π (u + 0.2 u²), u = k/N (a table with spline derivatives, exact
    for a quadratic): solved with time, then without; analogs must satisfy
    dx/dθ = ẋ/θ̇ and d²x/dθ² = (ẍ − θ̈ dx/dθ)/θ̇²."""
    n = 48
    u = np.arange(n + 1) / n
    theta = np.degrees(2 * np.pi * (u + 0.2 * u * u))
    arg = {"table": theta.tolist(), "derivatives": "spline"}
    timed = mechloop.solve(crank_slider_model(n, arg, {"rpm": 900}))
    analog = mechloop.solve(crank_slider_model(n, arg, None))
    assert analog.time is None and analog.derivative_units() == ("rad", "rad^2")
    w, dw = timed.rate("a1"), timed.accel("a1")
    # the argument's own rates are the chain rule of its table: θ' / t', θ'' / t'²
    step = 60 / 900 / n
    np.testing.assert_allclose(w, 2 * np.pi * (1 + 0.4 * u) / n / step, rtol=1e-10)
    np.testing.assert_allclose(dw, 2 * np.pi * 0.4 / n**2 / step**2, rtol=1e-8)
    np.testing.assert_allclose(analog.rate("a1"), 1.0, rtol=1e-14)
    np.testing.assert_allclose(analog.accel("a1"), 0.0, atol=1e-12)
    for name in ("r3", "a2"):
        d1 = timed.rate(name) / w
        d2 = (timed.accel(name) - dw * d1) / w**2
        np.testing.assert_allclose(analog.rate(name), d1, rtol=1e-9,
                                   atol=1e-12 * np.abs(d1).max())
        np.testing.assert_allclose(analog.accel(name), d2, rtol=1e-8,
                                   atol=1e-9 * np.abs(d2).max())


def test_analogs_of_the_slider_crank_are_the_geometric_derivatives():
    """Without time, r3' = dx/dθ of the closed form x = r cos θ + sqrt(l² − (r sin θ + e)²)."""
    res = mechloop.solve(crank_slider_model(36, FULL_TURN, None))
    theta = res.value("a1")
    s = 0.05 * np.sin(theta) + 0.01
    dx = -0.05 * np.sin(theta) - s * 0.05 * np.cos(theta) / np.sqrt(0.04 - s * s)
    np.testing.assert_allclose(res.rate("r3"), dx, rtol=1e-9, atol=1e-12)


# ---------------------------------------------------------------------- SolveError


def test_no_time_and_a_constant_argument_1_is_an_error():
    with pytest.raises(SolveError, match=r"argument 1 does not change at positions "
                                         r"0, 1, 2, 3, 4, 5, 6, 7, 8, 9 \.\.\.") as info:
        mechloop.solve(crank_slider_model(12, {"table": {0: 30}}, None))
    assert "time" in info.value.hint
    assert isinstance(info.value, ValueError)


def test_no_time_and_a_law_that_dwells_names_the_still_positions():
    arg = {"law": "constant_speed", "start": [2, 0], "end": [10, 90]}
    with pytest.raises(SolveError, match=r"positions 0, 1, 11, 12:"):
        mechloop.solve(crank_slider_model(12, arg, None))
    # with a time, the same law is fine: derivatives are with respect to time
    res = mechloop.solve(crank_slider_model(12, arg, {"rpm": 60}))
    assert res.rate("a1")[[0, 1, 11, 12]].tolist() == [0.0] * 4


def test_no_time_and_a_harmonic_law_names_both_of_its_ends():
    """Harmonic law from position 2 to 10: f'(τ) = (π/2) sin πτ is zero at τ = 0 and at
    τ = 1, so argument 1 stands still at 0–2 (before and at the start) and 10–12."""
    arg = {"law": "harmonic", "start": [2, 0], "end": [10, 90]}
    with pytest.raises(SolveError, match=r"positions 0, 1, 2, 10, 11, 12:"):
        mechloop.solve(crank_slider_model(12, arg, None))


def test_no_time_and_a_table_that_holds_still_is_an_error():
    """KDAM's example table as argument 1 without time: it holds still over positions
    0–3 and 10–12, where derivatives with respect to it do not exist."""
    arg = {"table": {3: 0.12, 6: 0.26, 10: 0.18}, "unit": "rad"}
    with pytest.raises(SolveError, match="argument 1 does not change"):
        mechloop.solve(crank_slider_model(12, arg, None))
