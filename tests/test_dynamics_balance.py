"""The balancing load three ways, and the reduced characteristics against finite differences.

1. Kinetostatics (the batched linear solve of every body's equilibrium) and virtual power
   (``Q = Σ (m a_S·v'_S + J ε ω') − Σ F·v'_P − Σ M ω'``, no reactions) give the same
   balancing moment (≤ 1e-9 of the mechanism's typical moment) on random crank-rocker
   four-bars and random offset slider-cranks: random dimensions, masses, inertias
   (numbers or ``rod``), centres ``{vector, share, across}`` / ``{vector, along, across}``, a
   force at a random point (fixed or following a vector), a moment, gravity on or off.
2. For one input (``DESIGN §5``): ``M_bal = J_red·q̈ + ½·dJ_red/dq·q̇² − M_red`` — at constant
   speed (``q̈ = 0``), under a harmonic start-stop law, and for a sliding input (a hydraulic
   cylinder extended by a 3-4-5 polynomial law: ``F_bal = m_red q̈ + ½ dm_red/dq q̇² −
   F_red``), with ``q̇``, ``q̈`` of the laws written out here.
3. ``J_red``, ``dJ_red/dq`` and ``M_red`` against finite differences over the input angle:
   ``J_red = Σ m |dz_S/dq|² + J (dθ/dq)²``, ``M_red = Σ F·dz_P/dq + Σ M dθ/dq`` with the
   derivatives by seven-point central differences of positions (720 positions a turn), and
   ``dJ_red/dq`` by the same stencil applied to ``J_red``.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from oracles.dynamic_models import dynamics, four_bar, four_bars, landing_gear, slider_cranks
from oracles.dynamics import (
    angle_first_derivative,
    external_forces,
    external_moments,
    first_derivative,
    lumped_masses,
    moment_scale,
    point_z,
)

SETTINGS = settings(max_examples=60, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow])
RTOL = 1e-9
FD_RTOL = 1e-8  # seven-point finite differences over 720 positions a turn, O(h⁶)
N = 720


def assert_same(got, want, scale: float, what: str, rtol: float = RTOL) -> None:
    err = np.abs(np.asarray(got) - np.asarray(want)).max()
    assert np.isfinite(err), f"{what}: NaN"
    assert err <= rtol * scale, f"{what}: off by {err:.3e} (scale {scale:.3e})"


# --------------------------------------------------- kinetostatics = virtual power


@SETTINGS
@given(data=four_bars())
def test_four_bar_kinetostatics_equals_virtual_power(data):
    d = dynamics(data)
    assert not d.forces.singular.any()
    assert_same(d.forces.balancing[1], d.balancing_vp[1], moment_scale(d, data), "M_bal")


@SETTINGS
@given(data=slider_cranks())
def test_slider_crank_kinetostatics_equals_virtual_power(data):
    d = dynamics(data)
    assert not d.forces.singular.any()
    assert_same(d.forces.balancing[1], d.balancing_vp[1], moment_scale(d, data), "M_bal")


# ------------------------------------------------------ reduced characteristics


def fd_reduced(d, data) -> tuple[np.ndarray, np.ndarray]:
    """J_red and M_red from finite differences of positions over the crank angle q
    (the model turns the crank once over its positions at constant speed)."""
    q = d.kinematics.value("a1")
    h = float(q[1] - q[0])
    n = q.size - 1
    inertia, load = np.zeros(n), np.zeros(n)
    for m in lumped_masses(data, d):
        v = first_derivative(point_z(d, m.center), h, periodic=True)
        angle = d.kinematics.value(f"a{data['bodies'][m.body]['vectors'][0]}")
        w = angle_first_derivative(angle, h, periodic=True)
        inertia += m.mass * np.abs(v) ** 2 + m.inertia * w**2
    for f in external_forces(data, d):
        load += (np.conj(f.force[:-1]) * first_derivative(f.at, h, periodic=True)).real
    for body, moment in external_moments(data, q.size):
        angle = d.kinematics.value(f"a{data['bodies'][body]['vectors'][0]}")
        load += moment[:-1] * angle_first_derivative(angle, h, periodic=True)
    return inertia, load


def check_reduced(data) -> None:
    d = dynamics(data)
    red = d.reduced
    omega = 2 * math.pi * data["time"]["rpm"] / 60.0
    np.testing.assert_allclose(d.kinematics.rate("a1"), omega, rtol=1e-14)
    # M_bal = J_red q̈ + ½ dJ_red/dq q̇² − M_red, with q̈ = 0
    assert_same(d.forces.balancing[1], 0.5 * red.d_inertia * omega**2 - red.load,
                moment_scale(d, data), "M_bal vs ½ dJ ω² − M_red")
    # against finite differences over the crank angle
    inertia, load = fd_reduced(d, data)
    assert_same(red.inertia[:-1], inertia, red.inertia.max(), "J_red", FD_RTOL)
    # the size of the loads' moments about the origin (floored: a model may have no load)
    load_scale = max(
        sum(np.abs(f.force).max() * 2 * np.abs(f.at).max() for f in external_forces(data, d))
        + sum(np.abs(m).max() for _, m in external_moments(data, 1)),
        1e-9 * moment_scale(d, data))
    assert_same(red.load[:-1], load, load_scale, "M_red", FD_RTOL)
    h = float(d.kinematics.value("a1")[1] - d.kinematics.value("a1")[0])
    dj = first_derivative(red.inertia, h, periodic=True)
    assert_same(red.d_inertia[:-1], dj, np.abs(red.d_inertia).max() + red.inertia.max(),
                "dJ_red/dq", FD_RTOL)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=four_bars(n=N, min_transmission=35.0))
def test_four_bar_reduced_characteristics(data):
    check_reduced(data)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=slider_cranks(n=N))
def test_slider_crank_reduced_characteristics(data):
    check_reduced(data)


def test_balancing_moment_under_a_start_stop_law():
    """The crank turns once in T = 1 s by the harmonic law q = π (1 − cos(π t/T)), so
    q̇ = (π²/T) sin(π t/T) and q̈ = (π³/T²) cos(π t/T): both terms of
    M_bal = J_red q̈ + ½ dJ_red/dq q̇² − M_red matter."""
    n, period = 144, 1.0
    data = four_bar(
        0.1, 0.35, 0.25, 0.3, n=n, rpm=60.0 / period,
        arguments={1: {"law": "harmonic", "start": [0, 0.0], "end": [n, 360.0]}},
        bodies={1: {"vectors": [1], "mass": 2.0, "inertia": 0.004,
                    "center": {"vector": 1, "share": 0.4, "across": 0.01}},
                2: {"vectors": [2], "mass": 3.0, "inertia": "rod",
                    "center": {"vector": 2, "share": 0.5, "across": 0.05}},
                3: {"vectors": [3], "mass": 1.5, "inertia": 0.01,
                    "center": {"vector": 3, "along": 0.1, "across": -0.02}}},
        forces=[{"body": 2, "at": {"vector": 2, "share": 0.7, "across": 0.1}, "value": 200.0,
                 "angle": -60.0}],
        moments=[{"body": 3, "value": 15.0}],
        gravity={"g": 9.81})
    d = dynamics(data)
    t = d.kinematics.time
    np.testing.assert_allclose(t, np.arange(n + 1) / n * period, rtol=1e-14)
    q = math.pi * (1 - np.cos(math.pi * t / period))
    dq = math.pi**2 / period * np.sin(math.pi * t / period)
    ddq = math.pi**3 / period**2 * np.cos(math.pi * t / period)
    np.testing.assert_allclose(d.kinematics.value("a1"), q, rtol=0, atol=1e-13)
    red = d.reduced
    want = red.inertia * ddq + 0.5 * red.d_inertia * dq**2 - red.load
    scale = moment_scale(d, data)
    assert_same(d.forces.balancing[1], want, scale, "M_bal vs J q̈ + ½ dJ q̇² − M_red")
    assert_same(d.balancing_vp[1], want, scale, "M_bal (virtual power)")
    # the q̈ term is not negligible here
    assert np.abs(red.inertia * ddq).max() > 0.1 * np.abs(want).max()


def test_balancing_force_of_a_sliding_input():
    """A landing-gear leg raised by a cylinder whose length follows q = q0 + h f(τ),
    f = 10τ³ − 15τ⁴ + 6τ⁵, τ = t/T: q̇ = h f'(τ)/T, q̈ = h f''(τ)/T²."""
    n, period, q0, stroke = 200, 4.0, 0.60, 0.25
    d = dynamics(landing_gear(n))
    tau = d.kinematics.time / period
    dq = stroke * (30 * tau**2 - 60 * tau**3 + 30 * tau**4) / period
    ddq = stroke * (60 * tau - 180 * tau**2 + 120 * tau**3) / period**2
    np.testing.assert_allclose(d.kinematics.value("r2"),
                               q0 + stroke * (10 * tau**3 - 15 * tau**4 + 6 * tau**5),
                               rtol=0, atol=1e-14)
    red = d.reduced
    want = red.inertia * ddq + 0.5 * red.d_inertia * dq**2 - red.load
    scale = np.abs(d.forces.balancing[1]).max()
    assert_same(d.forces.balancing[1], want, scale, "F_bal vs m q̈ + ½ dm q̇² − F_red")
    assert_same(d.balancing_vp[1], want, scale, "F_bal (virtual power)")
    frame = d.to_frame()
    assert {"F_bal [N]", "F_bal_vp [N]", "m_red [kg]", "dm_red [kg/m]",
            "F_red [N]"} <= set(frame.columns)
    np.testing.assert_array_equal(frame["m_red [kg]"], red.inertia)
