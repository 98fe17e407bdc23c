"""The bundled offset slider-crank (examples/crank_slider.yaml) against its closed form.

Geometry of the model: crank pin A = r (cos θ, sin θ) with θ = argument 1; the loop
r1 + r2 + r3 + r4 = 0 with vector 3 at 180° and vector 4 = e at 90° puts the slider pin at
B = (r3, −e), so the slider line is e = 0.01 m *below* the crank axis.  With |AB| = l and B
to the right of A (variant 1: cos(α2 − α1) < 0 with α1 = 180°, i.e. cos α2 > 0):

    s(θ) = r sin θ + e,   w(θ) = sqrt(l² − s²)
    x(θ) = r cos θ + w                                  (piston position, = r3)
    φ(θ) = atan2(−s, w) = −asin(s / l)                  (connecting-rod angle, = a2)

and, with s' = r cos θ, s'' = −r sin θ, w' = −s s'/w:

    x'  = −r sin θ − s s' / w
    x'' = −r cos θ − (s'² + s s'') / w − s² s'² / w³
    φ'  = −s' / w
    φ'' = −s'' / w − s s'² / w³

The crank turns at n = 3000 rpm, θ = ω t with ω = 2π n / 60, so ẋ = ω x', ẍ = ω² x'',
φ̇ = ω φ', φ̈ = ω² φ''.  (cf. R. L. Norton, *Design of Machinery*, sec. 13.3 "Slider-crank
kinematics", there with zero offset: put e = 0 above to recover his exact expressions.)
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import mechloop

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "crank_slider.yaml"

R, L, E = 0.05, 0.2, 0.01  # crank, connecting rod, offset (m)
RPM = 3000.0
OMEGA = 2 * math.pi * RPM / 60  # rad/s
RTOL = 1e-9


def closed_form(theta):
    """x, x', x'', φ, φ', φ'' of the offset slider-crank at crank angles ``theta`` (rad)."""
    s = R * np.sin(theta) + E
    ds = R * np.cos(theta)
    dds = -R * np.sin(theta)
    w = np.sqrt(L * L - s * s)
    x = R * np.cos(theta) + w
    dx = -R * np.sin(theta) - s * ds / w
    ddx = -R * np.cos(theta) - (ds * ds + s * dds) / w - s * s * ds * ds / w**3
    phi = np.arctan2(-s, w)
    dphi = -ds / w
    ddphi = -dds / w - s * ds * ds / w**3
    return x, dx, ddx, phi, dphi, ddphi


@pytest.fixture(scope="module")
def solved():
    model = mechloop.load_model(EXAMPLE)
    return model, mechloop.solve(model)


def assert_close(got, want, name):
    scale = np.abs(want).max()
    err = np.abs(got - want).max()
    assert err <= RTOL * scale, f"{name}: max error {err:.3e}, scale {scale:.3e}"


def test_example_holds_the_textbook_dimensions(solved):
    model, res = solved
    assert model.vectors[1].r == R and model.vectors[2].r == L and model.vectors[4].r == E
    assert model.vectors[3].a == 180 and model.vectors[4].a == 90
    assert model.time.rpm == RPM
    assert not res.broken.any()
    np.testing.assert_allclose(res.time, 60 / RPM * np.arange(73) / 72, rtol=1e-15)
    np.testing.assert_allclose(res.value("a1"), np.radians(5.0 * np.arange(73)),
                               rtol=1e-15, atol=1e-15)


def test_piston_position_velocity_acceleration(solved):
    _, res = solved
    x, dx, ddx, *_ = closed_form(res.value("a1"))
    assert_close(res.value("r3"), x, "x")
    assert_close(res.rate("r3"), OMEGA * dx, "piston velocity")
    assert_close(res.accel("r3"), OMEGA**2 * ddx, "piston acceleration")


def test_connecting_rod_angle_and_its_rates(solved):
    _, res = solved
    *_, phi, dphi, ddphi = closed_form(res.value("a1"))
    err = np.abs((res.value("a2") - phi + np.pi) % (2 * np.pi) - np.pi).max()
    assert err <= RTOL
    assert_close(res.rate("a2"), OMEGA * dphi, "rod angular velocity")
    assert_close(res.accel("a2"), OMEGA**2 * ddphi, "rod angular acceleration")


def test_slider_pin_runs_on_its_line(solved):
    _, res = solved
    x, *_ = closed_form(res.value("a1"))
    bx, by = res.point([1, 2])
    assert_close(bx, x, "B x")
    np.testing.assert_allclose(by, -E, rtol=0, atol=1e-15)


def test_textbook_landmarks(solved):
    """Top and bottom dead centres of the offset slider-crank, where the piston stops:
    crank and rod in line, x = sqrt((l ± r)² − e²), at θ = −asin(e/(l + r)) and
    θ = π − asin(e/(l − r))."""
    theta = np.array([-math.asin(E / (L + R)), math.pi - math.asin(E / (L - R))])
    x, dx, *_ = closed_form(theta)
    np.testing.assert_allclose(x, [math.sqrt((L + R) ** 2 - E**2),
                                   math.sqrt((L - R) ** 2 - E**2)], rtol=1e-12)
    np.testing.assert_allclose(dx, 0.0, atol=1e-12)
    # the solver's stroke over 5° steps lies within the exact stroke, and near it
    _, res = solved
    stroke = res.value("r3").max() - res.value("r3").min()
    exact = x[0] - x[1]
    assert exact * (1 - 2e-3) < stroke <= exact
