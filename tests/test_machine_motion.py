"""Machine motion (steady run of a one-degree-of-freedom machine) and flywheel sizing.

Reference answers are written as the formulas that give them:

* constant ``J`` and ``M = M0 sin q`` over 2π: ``A = M0 (1 − cos q)``, so
  ``ω² = ω(0)² + 2 M0 (1 − cos q) / J``; the slowest speed is at ``q = 0``, the fastest at
  ``q = π``, and with ``ω_mean = (ω_max + ω_min)/2`` the hand solution is
  ``ω(0) = ω_mean − M0/(J ω_mean)``, ``ω(π) = ω_mean + M0/(J ω_mean)``,
  ``δ = 2 M0 / (J ω_mean²)``, hence the flywheel ``J_f = 2 M0 / (δ ω_mean²) − J``;
* variable ``J``: a slider-crank-like reduced inertia
  ``J = J0 + m r² (sin q + λ/2 · sin 2q)²`` (the slider's velocity ratio to first order in
  λ) and a balanced two-harmonic load; checked against a slow oracle that integrates the
  equation of motion ``dω/dq = (M − ½ ω² J') / (J ω)``, ``dt/dq = 1/ω`` with ``solve_ivp``
  and analytic ``J, J', M``;
* a four-stroke engine over 4π whose driving moment is a trigonometric series of mean
  ``a0``: the constant resisting moment that balances it is ``−a0``.
"""

from __future__ import annotations

import doctest
import math
import pickle

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad, solve_ivp
from scipy.interpolate import CubicSpline

from mechloop.dynamics import machine
from mechloop.dynamics.machine import (
    flywheel_inertia,
    flywheel_inertia_approx,
    machine_motion,
    steady_driving_moment,
    work,
)
from mechloop.errors import SolveError

SETTINGS = settings(max_examples=25, deadline=None)
TWO_PI = 2.0 * math.pi
Q = np.linspace(0.0, TWO_PI, 2001)  # odd: q = π is position 1000
HALF = 1000

moment = st.floats(1.0, 500.0)  # N·m
inertia = st.floats(0.05, 20.0)  # kg·m²
speed = st.floats(5.0, 300.0)  # rad/s
# load ratio M0 / (J ω_mean²): δ = 2·ratio, the machine runs while ratio < 1
ratio = st.floats(0.002, 0.4)


def sine_case(m0: float, j: float, w_mean: float):
    """Constant inertia, load ``m0 sin q``; returns (j_red, m_red, ω(0), ω(π), δ)."""
    swing = m0 / (j * w_mean)
    return (np.full_like(Q, j), m0 * np.sin(Q), w_mean - swing, w_mean + swing,
            2.0 * m0 / (j * w_mean**2))


def slider_crank(q, j0, mr2, lam, m1, m2, phase):
    """Variable reduced inertia, its derivative and a balanced load (see module docstring)."""
    s = np.sin(q) + 0.5 * lam * np.sin(2 * q)
    ds = np.cos(q) + lam * np.cos(2 * q)
    return j0 + mr2 * s**2, 2.0 * mr2 * s * ds, m1 * np.sin(q + phase) + m2 * np.sin(2 * q)


def ode_oracle(q, j_of, dj_of, m_of, omega0):
    """ω(q) and t(q) by integrating the equation of motion position by position."""

    def rhs(x, y):
        omega = y[0]
        return [(m_of(x) - 0.5 * omega**2 * dj_of(x)) / (j_of(x) * omega), 1.0 / omega]

    sol = solve_ivp(rhs, (q[0], q[-1]), [omega0, 0.0], t_eval=q, rtol=1e-12, atol=1e-12,
                    method="DOP853")
    return sol.y[0], sol.y[1]


@st.composite
def variable_case(draw):
    """Parameters of :func:`slider_crank` and a mean speed at which the machine runs:
    ``ω_mean² ≥ 4 ΔA / J0`` with ``ΔA ≤ 2|m1| + |m2|`` the swing of the work."""
    case = (
        draw(st.floats(0.2, 5.0)),  # j0, kg·m²
        draw(st.floats(0.0, 3.0)),  # m r², kg·m²
        draw(st.floats(0.0, 0.4)),  # λ = r / l
        draw(st.floats(-50.0, 50.0)),  # m1, N·m
        draw(st.floats(-30.0, 30.0)),  # m2, N·m
        draw(st.floats(-math.pi, math.pi)),  # phase, rad
    )
    swing = 2.0 * abs(case[3]) + abs(case[4]) + 1.0
    return case, draw(st.floats(2.0, 30.0)) * math.sqrt(swing / case[0])


# ------------------------------------------------------------------------------ work


def test_work_is_exact_for_a_constant_and_a_sine_over_a_period():
    assert np.allclose(work(Q, np.full_like(Q, 3.5)), 3.5 * Q, rtol=0, atol=1e-10)
    assert np.allclose(work(Q, np.sin(Q)), 1.0 - np.cos(Q), rtol=0, atol=1e-10)
    assert abs(work(Q, np.cos(Q))[-1]) < 1e-12


def test_work_of_non_periodic_samples_uses_an_open_spline():
    q = np.linspace(0.0, 2.0, 9)
    stacked = np.stack([3.0 * q**2 - q, np.cos(np.pi * q)])  # a cubic's derivative; periodic
    expected = np.stack([q**3 - 0.5 * q**2, np.sin(np.pi * q) / np.pi])
    got = work(q, stacked)
    assert np.allclose(got[0], expected[0], rtol=0, atol=1e-12)  # exact: splines hold cubics
    assert np.allclose(got[1], expected[1], rtol=0, atol=5e-3)
    assert np.array_equal(got[1], work(q, stacked[1]))  # each row keeps its own spline


# ---------------------------------------------------------------- constant J, sine load


@SETTINGS
@given(inertia, speed, ratio)
def test_constant_inertia_sine_load_matches_the_hand_solution(j, w_mean, r):
    m0 = r * j * w_mean**2
    j_red, m_red, omega_0, omega_pi, delta = sine_case(m0, j, w_mean)
    motion = machine_motion(Q, j_red, m_red, omega_mean=w_mean)
    assert motion.delta == pytest.approx(delta, rel=1e-8)
    assert motion.omega[0] == pytest.approx(omega_0, rel=1e-10)
    assert motion.omega[HALF] == pytest.approx(omega_pi, rel=1e-10)
    assert (motion.omega_min, motion.omega_max) == pytest.approx((omega_0, omega_pi), rel=1e-10)
    hand = omega_0**2 + 2.0 * m0 * (1.0 - np.cos(Q)) / j
    assert np.allclose(motion.omega**2, hand, rtol=1e-10, atol=0)
    assert np.allclose(motion.epsilon, m_red / j, rtol=0, atol=1e-9 * m0 / j)


@SETTINGS
@given(inertia, speed, ratio, st.floats(0.05, 0.95))
def test_flywheel_for_a_sine_load_matches_the_closed_form(j, w_mean, r, fraction):
    m0 = r * j * w_mean**2
    j_red, m_red, *_, delta = sine_case(m0, j, w_mean)
    target = fraction * delta
    expected = 2.0 * m0 / (target * w_mean**2) - j
    for size in (flywheel_inertia, flywheel_inertia_approx):
        got = size(Q, j_red, m_red, omega_mean=w_mean, delta=target)
        assert got == pytest.approx(expected, rel=1e-8)
    assert flywheel_inertia(Q, j_red, m_red, omega_mean=w_mean, delta=1.01 * delta) == 0.0
    assert flywheel_inertia_approx(Q, j_red, m_red, omega_mean=w_mean, delta=1.01 * delta) == 0


def test_a_machine_that_would_stop_still_gets_a_flywheel():
    j, w_mean, m0, target = 1.0, 10.0, 150.0, 0.05  # M0 > J ω_mean²: stops without one
    j_red, m_red, *_ = sine_case(m0, j, w_mean)
    j_f = flywheel_inertia(Q, j_red, m_red, omega_mean=w_mean, delta=target)
    assert j_f == pytest.approx(2.0 * m0 / (target * w_mean**2) - j, rel=1e-8)
    assert machine_motion(Q, j_red + j_f, m_red, omega_mean=w_mean).delta == pytest.approx(
        target, rel=1e-8)


# --------------------------------------------------------------------- four-stroke engine


def test_four_stroke_engine_is_balanced_by_the_steady_moment():
    a0 = 30.0  # N·m, mean of the driving moment over the 4π cycle

    def m_drive(q):
        return (a0 + 40.0 * np.sin(q / 2) + 60.0 * np.sin(q) + 25.0 * np.cos(1.5 * q)
                - 35.0 * np.sin(2 * q))

    for positions, rel in ((49, 1e-3), (1441, 1e-9)):  # 15° and 0.5° tables over 720°
        q = np.linspace(0.0, 4 * np.pi, positions)
        table = m_drive(q)
        m_resist = steady_driving_moment(q, table)
        assert m_resist == pytest.approx(-a0, rel=rel)
        assert m_resist == pytest.approx(-np.trapezoid(table, q) / (4 * np.pi), rel=1e-2)
        net = work(q, table + m_resist)[-1]
        assert abs(net) < 1e-12 * np.abs(work(q, table)).max()
        with pytest.raises(SolveError, match="not steady"):
            machine_motion(q, np.full_like(q, 0.5), table, omega_mean=150.0)
        motion = machine_motion(q, np.full_like(q, 0.5), table + m_resist, omega_mean=150.0)
        assert 0.0 < motion.delta < 0.1


# --------------------------------------------------------------------------- variable J


@SETTINGS
@given(variable_case())
def test_variable_inertia_keeps_the_energy_equation_and_the_equation_of_motion(running):
    case, w_mean = running
    j_red, dj_red, m_red = slider_crank(Q, *case)
    motion = machine_motion(Q, j_red, m_red, omega_mean=w_mean)
    a = work(Q, m_red)
    e0 = motion.kinetic_energy[0]
    scale = motion.kinetic_energy.max()
    assert np.allclose(0.5 * j_red * motion.omega**2 - a, e0, rtol=0, atol=1e-9 * scale)
    assert np.allclose(motion.kinetic_energy, 0.5 * j_red * motion.omega**2, rtol=1e-12)
    assert 0.5 * (motion.omega_max + motion.omega_min) == pytest.approx(w_mean, rel=1e-12)
    # ε = dω/dt = ω dω/dq, with dω/dq by the five-point central difference (error ~ h⁴)
    w, h = motion.omega, Q[1] - Q[0]
    slope = (w[:-4] - 8.0 * w[1:-3] + 8.0 * w[3:-1] - w[4:]) / (12.0 * h)
    eps_scale = np.abs(motion.epsilon).max() + 1e-3 * w_mean**2
    assert np.allclose(motion.epsilon[2:-2], w[2:-2] * slope, rtol=0, atol=1e-6 * eps_scale)
    given_dj = machine_motion(Q, j_red, m_red, omega_mean=w_mean, dj_red=dj_red)
    assert np.allclose(given_dj.epsilon, motion.epsilon, rtol=0, atol=1e-8 * eps_scale)


@SETTINGS
@given(variable_case())
def test_variable_inertia_matches_an_integrated_equation_of_motion(running):
    case, w_mean = running
    j_red, _, m_red = slider_crank(Q, *case)
    motion = machine_motion(Q, j_red, m_red, omega_mean=w_mean)

    def pick(k):
        return lambda x: float(slider_crank(np.asarray(x), *case)[k])

    omega, time = ode_oracle(Q, pick(0), pick(1), pick(2), motion.omega[0])
    assert np.allclose(motion.omega, omega, rtol=1e-9, atol=0)
    assert np.allclose(motion.time, time, rtol=1e-9, atol=0)
    assert omega[-1] == pytest.approx(omega[0], rel=1e-9)  # steady: the cycle repeats


# ---------------------------------------------------------------------------------- time


@SETTINGS
@given(inertia, speed, ratio)
def test_period_equals_the_integral_of_dq_over_omega(j, w_mean, r):
    m0 = r * j * w_mean**2
    j_red, m_red, omega_0, *_ = sine_case(m0, j, w_mean)
    motion = machine_motion(Q, j_red, m_red, omega_mean=w_mean)

    def slowness(q):
        return 1.0 / math.sqrt(omega_0**2 + 2.0 * m0 * (1.0 - math.cos(q)) / j)

    half, _ = quad(slowness, 0.0, math.pi, epsabs=0, epsrel=1e-13)
    assert motion.time[HALF] == pytest.approx(half, rel=1e-9)
    assert motion.time[-1] == pytest.approx(2.0 * half, rel=1e-9)  # symmetric about π


@SETTINGS
@given(variable_case())
def test_period_of_a_variable_inertia_machine_by_quadrature(running):
    case, w_mean = running
    j_red, _, m_red = slider_crank(Q, *case)
    motion = machine_motion(Q, j_red, m_red, omega_mean=w_mean)
    omega = CubicSpline(Q, motion.omega)
    period, _ = quad(lambda q: 1.0 / omega(q), Q[0], Q[-1], limit=200, epsrel=1e-12)
    assert motion.time[-1] == pytest.approx(period, rel=1e-9)


def test_no_load_turns_at_the_mean_speed():
    motion = machine_motion(Q, np.full_like(Q, 3.0), np.zeros_like(Q), omega_mean=12.0)
    assert np.allclose(motion.omega, 12.0, rtol=1e-14)
    assert motion.delta == 0.0
    assert motion.time[-1] == pytest.approx(TWO_PI / 12.0, rel=1e-13)


# -------------------------------------------------------------------------- broadcasting


def test_stacked_cases_equal_separate_calls():
    cases = [(1.0, 0.0, 0.0, 20.0, 5.0, 0.3), (2.0, 1.0, 0.25, -10.0, 8.0, 1.0),
             (0.5, 0.3, 0.1, 4.0, -2.0, -2.0)]
    j_red, _, m_red = (np.stack(x) for x in zip(*(slider_crank(Q, *c) for c in cases),
                                                 strict=True))
    w_mean = np.array([20.0, 40.0, 30.0])
    delta = np.array([0.02, 0.05, 0.1])
    stacked = machine_motion(Q, j_red, m_red, omega_mean=w_mean)
    sizes = {f: f(Q, j_red, m_red, omega_mean=w_mean, delta=delta)
             for f in (flywheel_inertia, flywheel_inertia_approx)}
    assert stacked.omega.shape == stacked.time.shape == (3, Q.size)
    assert stacked.delta.shape == (3,)
    for k in range(3):
        alone = machine_motion(Q, j_red[k], m_red[k], omega_mean=w_mean[k])
        for name in ("omega", "epsilon", "kinetic_energy", "time", "omega_max", "omega_min",
                     "delta"):
            assert np.array_equal(getattr(stacked, name)[k], getattr(alone, name)), name
        for f, size in sizes.items():
            assert size[k] == f(Q, j_red[k], m_red[k], omega_mean=w_mean[k], delta=delta[k])
        assert steady_driving_moment(Q, m_red)[k] == steady_driving_moment(Q, m_red[k])


def test_shared_inertia_broadcasts_against_stacked_loads():
    j_red = np.full_like(Q, 2.0)
    m_red = np.stack([10.0 * np.sin(Q), 20.0 * np.sin(Q)])
    motion = machine_motion(Q, j_red, m_red, omega_mean=10.0)
    assert motion.delta == pytest.approx([0.1, 0.2], rel=1e-8)
    single = machine_motion(Q, j_red[None], m_red[:1], omega_mean=10.0)
    assert single.omega.shape == (1, Q.size)
    assert np.array_equal(single.omega[0], motion.omega[0])


# -------------------------------------------------------------------------------- errors


def test_non_steady_load_is_refused_with_the_balancing_moment():
    m_red = 100.0 * np.sin(Q) - 5.0  # net work −5·2π J
    with pytest.raises(SolveError) as info:
        machine_motion(Q, np.full_like(Q, 1.0), m_red, omega_mean=20.0)
    text = str(info.value)
    assert "not steady" in text
    assert f"{-5.0 * TWO_PI:.6g} J" in text
    assert "steady_driving_moment" in text and "= 5 N·m" in text
    assert isinstance(info.value, ValueError)
    assert str(pickle.loads(pickle.dumps(info.value))) == text
    with pytest.raises(SolveError, match="not steady"):
        flywheel_inertia(Q, 1.0 + 0 * Q, m_red, omega_mean=20.0, delta=0.05)
    balanced = m_red + steady_driving_moment(Q, m_red)
    machine_motion(Q, np.full_like(Q, 1.0), balanced, omega_mean=20.0)  # runs


def test_steady_means_net_work_below_a_millionth_of_the_work_swing():
    j_red = np.full_like(Q, 1.0)
    # max|A| ≈ 2·100 J; a constant c adds net work 2π·c
    with pytest.raises(SolveError, match="not steady"):
        machine_motion(Q, j_red, 100.0 * np.sin(Q) + 3e-4, omega_mean=20.0)
    machine_motion(Q, j_red, 100.0 * np.sin(Q) + 3e-6, omega_mean=20.0)


def test_too_low_a_speed_stops_the_machine():
    j, m0 = 2.0, 50.0  # runs only while ω_mean > √(M0/J) = 5 rad/s
    j_red, m_red, *_ = sine_case(m0, j, 4.0)
    with pytest.raises(SolveError, match=r"machine stops.*omega_mean > 5 rad/s"):
        machine_motion(Q, j_red, m_red, omega_mean=4.0)
    stacked = np.stack([m_red, 0.1 * m_red])
    with pytest.raises(SolveError, match=r"stops.*\(case 0; 1 of 2 cases\)"):
        machine_motion(Q, j_red, stacked, omega_mean=4.0)
    assert machine_motion(Q, j_red, m_red, omega_mean=5.5).omega_min > 0


@pytest.mark.parametrize(("arguments", "message"), [
    ({"q": Q[::-1]}, "strictly increasing"),
    ({"j_red": -np.ones_like(Q)}, "j_red must be positive"),
    ({"m_red": np.zeros(7)}, r"m_red must have shape \(\.\.\., 2001\)"),
    ({"omega_mean": 0.0}, "omega_mean must be positive"),
])
def test_bad_arguments_are_refused(arguments, message):
    kwargs = {"q": Q, "j_red": np.ones_like(Q), "m_red": np.sin(Q), "omega_mean": 10.0,
              **arguments}
    with pytest.raises(SolveError, match=message):
        machine_motion(kwargs.pop("q"), kwargs.pop("j_red"), kwargs.pop("m_red"), **kwargs)


def test_flywheel_target_must_be_a_possible_fluctuation():
    with pytest.raises(SolveError, match=r"delta must lie in \(0, 2\)"):
        flywheel_inertia(Q, np.ones_like(Q), np.sin(Q), omega_mean=10.0, delta=0.0)


# ------------------------------------------------------------------ flywheel, variable J


@SETTINGS
@given(variable_case(), st.floats(0.005, 0.05))
def test_flywheel_gives_exactly_the_requested_fluctuation(running, target):
    case, w_mean = running
    j_red, _, m_red = slider_crank(Q, *case)
    j_f = flywheel_inertia(Q, j_red, m_red, omega_mean=w_mean, delta=target)
    approx = flywheel_inertia_approx(Q, j_red, m_red, omega_mean=w_mean, delta=target)
    if j_f == 0.0:
        assert machine_motion(Q, j_red, m_red, omega_mean=w_mean).delta <= target
        return
    assert machine_motion(Q, j_red + j_f, m_red, omega_mean=w_mean).delta == pytest.approx(
        target, rel=1e-9)
    # the Merzalov approximation takes the variable part at the mean speed: it errs by
    # about half the swing of j_red (plus δ of the whole inertia)
    bound = np.ptp(j_red) + 2.0 * target * (j_f + j_red.min())
    assert approx == pytest.approx(j_f, abs=bound)


def test_approximate_flywheel_is_the_merzalov_formula():
    case, w_mean, target = (1.5, 2.0, 0.3, 40.0, -15.0, 0.7), 30.0, 0.02
    j1, _, m_red = slider_crank(Q, *case)
    m1, m2, phase = case[3:]
    a = m1 * (math.cos(phase) - np.cos(Q + phase)) + 0.5 * m2 * (1.0 - np.cos(2 * Q))
    group_one = a - 0.5 * j1 * w_mean**2
    expected = np.ptp(group_one) / (target * w_mean**2) - j1.min()
    got = flywheel_inertia_approx(Q, j1, m_red, omega_mean=w_mean, delta=target)
    assert got == pytest.approx(expected, rel=1e-9)
    assert got != pytest.approx(flywheel_inertia(Q, j1, m_red, omega_mean=w_mean,
                                                 delta=target), rel=1e-3)


def test_module_examples_run():
    assert doctest.testmod(machine, raise_on_error=True).attempted > 0
