"""Classical closed-form synthesis (:mod:`mechloop.synthesis.classical`) against independent
geometry written here.

Oracles (none of them uses the formulas of the module):

* a four-bar position solution by intersecting the circle of radius ``b`` about the crank
  pin with the circle of radius ``c`` about the rocker pivot, the branch followed by
  continuity along a dense path of crank angles;
* plain rigid-body geometry for the coupler pose of an assembled four-bar;
* the slider position ``x(φ) = r cos φ + √(l² − (e + r sin φ)²)`` of an offset slider-crank
  and its derivative, whose roots (bracketed on a dense grid, refined with ``brentq``) are
  the dead centres;
* the rocker's velocity ratio ``ω4/ω2 = a sin(β − φ)/(c sin(β − ψ))`` (differentiated loop
  equation), whose roots are the rocker's extremes.

What is pinned:

(a) Freudenstein three-point synthesis reproduces the precision points to 1e-9 when the
    built four-bar is driven through them; for ``y = log10 x`` on [1, 10] with Chebyshev
    spacing the structural error vanishes at the precision points and stays small between;
    from the precision points of a random four-bar it recovers ``a/d, b/d, c/d``; a crank
    turned by π comes back as ``|a|`` with ``crank_phase = π``; least squares meets its
    normal equations and beats the three-point fit on the equation error;
(b) three-position guidance: the linkage assembled with its crank at each pose puts the
    coupler exactly at that pose, for the fixed-pivot and the inverted (moving-pivot)
    construction, and one inverts the other; collinear positions raise clearly;
(c) slider-crank: the stroke and the time ratio found numerically equal ``H`` and ``K`` to
    1e-9 for any free parameter (offset, crank, rod) and ``K = 1``;
(d) crank-rocker: swing and time ratio found numerically equal ψ and ``K`` to 1e-9, the
    slow swing turns in the documented sense, Grashof's crank-rocker condition holds;
(e) batches: ``(P,)`` and ``(D, P)`` inputs agree; ``errors="mask"`` flags exactly the
    failing designs; the docstring examples run.
"""

from __future__ import annotations

import doctest
import itertools
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from mechloop.errors import MechloopError, SolveError
from mechloop.synthesis import classical
from mechloop.synthesis.classical import (
    chebyshev_points,
    crank_rocker_frame_range,
    crank_rocker_from_swing,
    freudenstein_least_squares,
    freudenstein_three_point,
    function_generator_points,
    slider_crank_from_stroke,
    three_position_fixed_pivots,
    three_position_moving_pivots,
)

SETTINGS = settings(max_examples=60, deadline=None)


def cross2(u, v):
    return float(u[0] * v[1] - u[1] * v[0])


def wrap(angle):
    """Angle difference wrapped into (−π, π]."""
    return np.angle(np.exp(1j * np.asarray(angle)))


# --------------------------------------------------------------------------------------
# oracle: four-bar position by circle intersection, branch by continuity
# --------------------------------------------------------------------------------------


def circle_intersections(p, r, q, s):
    """Both intersections of the circle (centre p, radius r) with (centre q, radius s);
    None where they do not meet.  p, q: (2,) arrays."""
    dvec = q - p
    dist = math.hypot(*dvec)
    if dist == 0 or dist > r + s or dist < abs(r - s):
        return None
    along = (dist**2 + r**2 - s**2) / (2 * dist)
    across = math.sqrt(max(r**2 - along**2, 0.0))
    u = dvec / dist
    n = np.array([-u[1], u[0]])
    base = p + along * u
    return base + across * n, base - across * n


def rocker_path(a, b, c, d, phis, psi_start):
    """Rocker angles (rad, of O4→B) of the four-bar O2=(0,0), O4=(d,0) driven through the
    crank angles ``phis`` in order, starting on the branch nearest ``psi_start`` and
    following the nearer intersection afterwards.  None if the chain breaks."""
    o4 = np.array([d, 0.0])
    out, prev = [], None
    for phi in phis:
        pin = a * np.array([math.cos(phi), math.sin(phi)])
        both = circle_intersections(pin, b, o4, c)
        if both is None:
            return None
        if prev is None:
            angles = [math.atan2(p[1], p[0] - d) for p in both]
            pick = both[int(np.argmin([abs(wrap(t - psi_start)) for t in angles]))]
        else:
            pick = min(both, key=lambda p: math.hypot(*(p - prev)))
        out.append(math.atan2(pick[1], pick[0] - d))
        prev = pick
    out = np.unwrap(np.array(out))
    return out + 2 * np.pi * np.round((psi_start - out[0]) / (2 * np.pi))  # start near it


def dense_path(points, per_gap=400):
    """Dense ordered path through ``points`` (kept exactly); returns path and indices."""
    path, idx = [points[0]], [0]
    for p, q in itertools.pairwise(points):
        path.extend(np.linspace(p, q, per_gap + 1)[1:])
        idx.append(len(path) - 1)
    return np.array(path), idx


def generated_psi(fg, phi, per_gap=400):
    """Output angles (rad, the convention of ``fg.psi``) of a Freudenstein result driven
    continuously through the crank angles ``phi`` (the convention of ``fg.phi``), starting
    on the branch through its first precision point."""
    a, b, c, d = (float(v) for v in (fg.a, fg.b, fg.c, fg.d))
    cp, rp = float(fg.crank_phase), float(fg.rocker_phase)
    start = np.concatenate([[float(fg.phi[0])], np.asarray(phi, dtype=float)]) + cp
    path, idx = dense_path(start, per_gap=per_gap)
    psi_phys = rocker_path(a, b, c, d, path, float(fg.psi[0]) + rp)
    assert psi_phys is not None, "the linkage breaks between the precision points"
    return psi_phys[idx[1:]] - rp


# --------------------------------------------------------------------------------------
# (a) Freudenstein function generation
# --------------------------------------------------------------------------------------


def test_chebyshev_points_are_the_roots_of_T_n():
    x = chebyshev_points(-1.0, 1.0, 5)
    assert np.all(np.diff(x) > 0)
    # T_5(x) = 16x^5 − 20x^3 + 5x
    np.testing.assert_allclose(16 * x**5 - 20 * x**3 + 5 * x, 0.0, atol=1e-14)
    # the map to [x0, x1] is affine and symmetric about the middle
    y = chebyshev_points(1.0, 10.0, 3)
    np.testing.assert_allclose(y, 5.5 + 4.5 * np.array([-1, 0, 1]) * math.cos(math.pi / 6))
    assert chebyshev_points([0.0, 1.0], [1.0, 3.0], 4).shape == (2, 4)


def test_function_generator_points_map_x_and_y_linearly():
    phi, psi = function_generator_points(
        np.log10, 1.0, 10.0, 0.1, 1.0, 0.2, -2.0, n=4, spacing="uniform"
    )
    x = np.linspace(1.0, 10.0, 4)
    np.testing.assert_allclose(phi, 0.1 + (x - 1.0) / 9.0)
    np.testing.assert_allclose(psi, 0.2 - 2.0 * np.log10(x))
    with pytest.raises(SolveError, match="output range is empty"):
        function_generator_points(np.cos, 0.0, 2 * np.pi, 0.0, 1.0, 0.0, 1.0)


#: φ from 30° over 60°, ψ from −60° over −90°: a Grashof linkage that covers the range
LOG10_RANGES = dict(
    phi0=math.radians(30), dphi=math.radians(60), psi0=math.radians(-60), dpsi=math.radians(-90)
)


def test_three_point_generator_passes_its_precision_points():
    phi, psi = function_generator_points(np.log10, 1.0, 10.0, **LOG10_RANGES)
    fg = freudenstein_three_point(phi, psi, frame=0.2)
    np.testing.assert_allclose(generated_psi(fg, phi), psi, atol=1e-9, rtol=0)
    np.testing.assert_allclose(fg.residual, 0.0, atol=1e-12)
    assert float(fg.d) == 0.2 and not fg.branch_defect


def test_log10_generator_structural_error():
    """y = log10 x on [1, 10], three Chebyshev points: zero error at the precision points,
    small between them (the maximum is printed: run pytest -s to see it)."""
    x0, x1 = 1.0, 10.0
    p = LOG10_RANGES
    phi, psi = function_generator_points(np.log10, x0, x1, **p)
    fg = freudenstein_three_point(phi, psi)
    x = np.unique(np.concatenate([np.linspace(x0, x1, 901), chebyshev_points(x0, x1, 3)]))
    phis = p["phi0"] + p["dphi"] * (x - x0) / (x1 - x0)
    # from the first precision point back to x0, then over the whole range
    psis = generated_psi(fg, np.concatenate([[phis[0]], phis]), per_gap=20)[1:]
    y_generated = np.log10(x0) + (psis - p["psi0"]) / p["dpsi"] * (np.log10(x1) - np.log10(x0))
    error = y_generated - np.log10(x)
    at_points = np.isin(x, chebyshev_points(x0, x1, 3))
    assert at_points.sum() == 3
    np.testing.assert_allclose(error[at_points], 0.0, atol=1e-9)
    max_error = float(np.max(np.abs(error)))
    print(f"log10 x on [1, 10], 3 Chebyshev points: max structural error {max_error:.4g}")
    assert max_error < 0.01  # the output range is 1


four_bar_length = st.floats(0.25, 3.0)


@SETTINGS
@given(
    a=four_bar_length,
    b=four_bar_length,
    c=four_bar_length,
    d=st.floats(0.5, 2.0),
    phi1=st.floats(-math.pi, math.pi),
    gap1=st.floats(0.2, 1.2),
    gap2=st.floats(0.2, 1.2),
    start=st.floats(-math.pi, math.pi),
)
def test_three_points_of_a_four_bar_recover_its_proportions(a, b, c, d, phi1, gap1, gap2, start):
    phi = np.array([phi1, phi1 + gap1, phi1 + gap1 + gap2])
    path, idx = dense_path(phi, per_gap=100)
    # keep away from toggles (transmission angle μ near 0 or π) and from A on O4
    dist = np.hypot(a * np.cos(path) - d, a * np.sin(path))
    assume(np.all(np.abs((b**2 + c**2 - dist**2) / (2 * b * c)) < 0.995) and dist.min() > 0.05)
    psi_path = rocker_path(a, b, c, d, path, start)
    assume(psi_path is not None)
    psi = psi_path[idx]
    rows = np.stack([np.cos(psi), -np.cos(phi), np.ones(3)], axis=-1)
    assume(np.linalg.cond(rows) < 1e6)
    fg = freudenstein_three_point(phi, psi)  # frame 1: the proportions come back
    np.testing.assert_allclose([fg.a, fg.b, fg.c], np.array([a, b, c]) / d, rtol=1e-6)
    assert float(fg.crank_phase) == 0.0 and float(fg.rocker_phase) == 0.0
    np.testing.assert_allclose(generated_psi(fg, phi), psi, atol=1e-9, rtol=0)


def test_negative_crank_comes_back_turned_by_pi():
    a, b, c, d = 0.6, 1.4, 1.1, 1.0
    phi = np.radians([40.0, 70.0, 100.0])
    path, idx = dense_path(phi)
    psi = rocker_path(a, b, c, d, path, 1.5)[idx]
    fg = freudenstein_three_point(phi + np.pi, psi, frame=d)  # same ψ, input shifted by π
    np.testing.assert_allclose([fg.a, fg.b, fg.c], [a, b, c], rtol=1e-9)
    assert float(fg.crank_phase) == pytest.approx(np.pi) and float(fg.rocker_phase) == 0.0
    assert float(fg.k[0]) < 0  # K1 = d/a with the signed a
    np.testing.assert_allclose(generated_psi(fg, phi + np.pi), psi, atol=1e-9, rtol=0)


def test_least_squares_meets_normal_equations_and_beats_three_points():
    phi, psi = function_generator_points(
        np.log10, 1.0, 10.0, n=11, spacing="uniform", **LOG10_RANGES
    )
    fit = freudenstein_least_squares(phi, psi)
    rows = np.stack([np.cos(psi), -np.cos(phi), np.ones_like(phi)], axis=-1)
    residual = rows @ fit.k - np.cos(phi - psi)
    np.testing.assert_allclose(fit.residual, residual, atol=1e-14)
    np.testing.assert_allclose(rows.T @ residual, 0.0, atol=1e-12)  # normal equations
    three = freudenstein_three_point(
        *function_generator_points(np.log10, 1.0, 10.0, **LOG10_RANGES)
    )
    three_residual = rows @ three.k - np.cos(phi - psi)
    assert np.sum(residual**2) < np.sum(three_residual**2)
    # exact data of a four-bar: least squares reproduces it
    a, b, c, d = 0.5, 1.6, 1.2, 1.3
    phis = np.radians(np.linspace(20.0, 140.0, 7))
    path, idx = dense_path(phis, per_gap=50)
    psis = rocker_path(a, b, c, d, path, 2.0)[idx]
    exact = freudenstein_least_squares(phis, psis, frame=d)
    np.testing.assert_allclose([exact.a, exact.b, exact.c], [a, b, c], rtol=1e-9)
    np.testing.assert_allclose(exact.residual, 0.0, atol=1e-12)
    # three points: the same as the exact solve
    same = freudenstein_least_squares(phis[:3], psis[:3])
    exact3 = freudenstein_three_point(phis[:3], psis[:3])
    np.testing.assert_allclose(same.k, exact3.k, rtol=1e-10)


def test_freudenstein_batches_and_masks():
    phi, psi = function_generator_points(np.log10, 1.0, 10.0, **LOG10_RANGES)
    one = freudenstein_three_point(phi, psi)
    bad_phi, bad_psi = phi[[0, 0, 2]], psi[[0, 0, 2]]  # a repeated precision point
    phis, psis = np.stack([phi, bad_phi]), np.stack([psi, bad_psi])
    batch = freudenstein_three_point(phis, psis, errors="mask")
    assert batch.a.shape == (2,) and batch.branch.shape == (2, 3)
    assert batch.ok.tolist() == [True, False]
    assert batch.reason[0] == "" and "singular" in batch.reason[1]
    assert np.isnan(batch.a[1]) and np.all(np.isnan(batch.k[1]))
    np.testing.assert_allclose(batch.a[0], one.a, rtol=1e-14)
    with pytest.raises(SolveError, match=r"design \(1,\) \(1 of 2 fail\).*singular"):
        freudenstein_three_point(phis, psis)
    frames = freudenstein_three_point(phi, psi, frame=[1.0, 2.0])
    np.testing.assert_allclose(frames.a, [one.a, 2 * one.a])


def test_freudenstein_argument_errors():
    with pytest.raises(ValueError, match="exactly 3"):
        freudenstein_three_point([0.1, 0.2, 0.3, 0.4], [0.1, 0.2, 0.3, 0.4])
    with pytest.raises(ValueError, match="at least 3"):
        freudenstein_least_squares([0.1, 0.2], [0.1, 0.2])
    # mirror images (φ, ψ) → (−φ, −ψ) give the same equation twice
    with pytest.raises(SolveError, match="singular") as info:
        freudenstein_three_point([0.3, -0.3, 1.0], [0.8, -0.8, 1.2])
    assert isinstance(info.value, MechloopError) and "mirror" in str(info.value)
    with pytest.raises(SolveError, match="frame length must be positive"):
        freudenstein_three_point([0.1, 0.5, 0.9], [0.2, 0.4, 0.9], frame=0.0)


# --------------------------------------------------------------------------------------
# (b) three-position rigid-body guidance
# --------------------------------------------------------------------------------------


def rotate(theta, p):
    c, s = math.cos(theta), math.sin(theta)
    return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1]])


def assembled_poses(ground_a, ground_b, a, b, c, pa, pb, crank_angle):
    """The two coupler poses (x, y, θ) of the four-bar with its crank at ``crank_angle``
    (world), pivots ``pa, pb`` in the coupler frame; with the side of each assembly."""
    pin_a = ground_a + a * np.array([math.cos(crank_angle), math.sin(crank_angle)])
    both = circle_intersections(pin_a, b, ground_b, c)
    assert both is not None, "the linkage cannot be assembled at this crank angle"
    out = []
    for pin_b in both:
        theta = math.atan2(*(pin_b - pin_a)[::-1]) - math.atan2(*(pb - pa)[::-1])
        origin = pin_a - rotate(theta, pa)
        side = np.sign(cross2(ground_b - pin_a, pin_b - pin_a))
        out.append((origin, theta, side))
    return out


def assembly_quality(fb):
    """Smallest sine of an angle of the triangles (A_i, B_i, B0): near 0 at a toggle or
    when a moving pivot sits on a fixed pivot (where the circle oracle is ill-posed)."""
    return min(triangle_quality([fb.moving_a[i], fb.moving_b[i], fb.ground_b]) for i in range(3))


def check_guidance(fb, xy, theta):
    """Each pose is reached by the assembled linkage, on the branch the result reports."""
    xy, theta = np.asarray(xy, float), np.asarray(theta, float)
    pa, pb = np.asarray(fb.coupler_a), np.asarray(fb.coupler_b)
    ga, gb = np.asarray(fb.ground_a), np.asarray(fb.ground_b)
    size = 1.0 + float(np.max(np.abs(xy)))
    for i in range(3):
        pin_a = xy[i] + rotate(theta[i], pa)
        pin_b = xy[i] + rotate(theta[i], pb)
        np.testing.assert_allclose(pin_a, fb.moving_a[i], atol=1e-9 * size)
        assert math.hypot(*(pin_a - ga)) == pytest.approx(float(fb.a), rel=1e-9)
        assert math.hypot(*(pin_b - gb)) == pytest.approx(float(fb.c), rel=1e-9)
        crank = math.atan2(*(pin_a - ga)[::-1])
        poses = assembled_poses(ga, gb, float(fb.a), float(fb.b), float(fb.c), pa, pb, crank)
        miss = [math.hypot(*(origin - xy[i])) + abs(wrap(th - theta[i])) for origin, th, _ in poses]
        hit = int(np.argmin(miss))
        assert miss[hit] < 1e-9 * size * max(1.0, float(fb.a + fb.b + fb.c) / size)
        assert fb.branch[i] == poses[hit][2]
    np.testing.assert_allclose(float(fb.d), math.hypot(*(gb - ga)), rtol=1e-12)


POSES = ([[0.0, 0.0], [1.0, 0.2], [2.0, 0.0]], [0.0, 0.3, 0.5])


def test_fixed_pivots_put_the_coupler_at_each_pose():
    fb = three_position_fixed_pivots(*POSES, moving_a=[-0.5, 0.0], moving_b=[0.5, 0.0])
    check_guidance(fb, *POSES)
    assert fb.moving_a.shape == (3, 2) and fb.ground_a.shape == (2,)


def test_inversion_puts_the_coupler_at_each_pose_and_inverts_the_construction():
    fb = three_position_moving_pivots(*POSES, ground_a=[0.0, -2.0], ground_b=[3.0, -2.0])
    check_guidance(fb, *POSES)
    back = three_position_fixed_pivots(*POSES, moving_a=fb.coupler_a, moving_b=fb.coupler_b)
    np.testing.assert_allclose(back.ground_a, [0.0, -2.0], atol=1e-9)
    np.testing.assert_allclose(back.ground_b, [3.0, -2.0], atol=1e-9)


coord = st.floats(-1.0, 1.0)
point = st.tuples(coord, coord)


def triangle_quality(p):
    """Sine of the smallest angle of the triangle p[0..2] (0 when degenerate)."""
    p = np.asarray(p)
    sines = []
    for i in range(3):
        u, v = p[(i + 1) % 3] - p[i], p[(i + 2) % 3] - p[i]
        den = math.hypot(*u) * math.hypot(*v)
        sines.append(abs(cross2(u, v)) / den if den > 0 else 0.0)
    return min(sines)


@SETTINGS
@given(
    xy=st.tuples(point, point, point),
    theta=st.tuples(*[st.floats(-math.pi, math.pi)] * 3),
    pa=point,
    pb=point,
)
def test_random_poses_fixed_pivots(xy, theta, pa, pb):
    xy, theta = np.array(xy), np.array(theta)
    for m in (pa, pb):
        positions = [xy[i] + rotate(theta[i], m) for i in range(3)]
        assume(triangle_quality(positions) > 0.05)
    assume(math.hypot(pa[0] - pb[0], pa[1] - pb[1]) > 0.05)
    fb = three_position_fixed_pivots(xy, theta, moving_a=pa, moving_b=pb, errors="mask")
    if not fb.ok:  # the only degeneracy left: both circles share their centre
        assert fb.reason == "the two fixed pivots coincide (zero frame length)"
    assume(bool(fb.ok) and float(fb.d) > 1e-3 and float(fb.a + fb.c + fb.d) < 100)
    assume(assembly_quality(fb) > 1e-3)
    check_guidance(fb, xy, theta)


@SETTINGS
@given(
    xy=st.tuples(point, point, point),
    theta=st.tuples(*[st.floats(-math.pi, math.pi)] * 3),
    ga=point,
    gb=point,
)
def test_random_poses_inversion_round_trip(xy, theta, ga, gb):
    xy, theta, ga, gb = np.array(xy), np.array(theta), np.array(ga), np.array(gb)
    for g in (ga, gb):
        seen = [rotate(-theta[i], g - xy[i]) for i in range(3)]
        assume(triangle_quality(seen) > 0.05)
    assume(math.hypot(*(ga - gb)) > 0.05)
    fb = three_position_moving_pivots(xy, theta, ground_a=ga, ground_b=gb, errors="mask")
    if not fb.ok:  # the only degeneracy left: both circles share their centre
        assert fb.reason == "the two moving pivots found coincide (zero coupler length)"
    assume(bool(fb.ok) and float(fb.b) > 1e-3 and float(fb.a + fb.b + fb.c) < 100)
    assume(assembly_quality(fb) > 1e-3)
    check_guidance(fb, xy, theta)
    # the forward construction from the moving pivots found needs them off the poles
    assume(min(triangle_quality(fb.moving_a), triangle_quality(fb.moving_b)) > 0.05)
    back = three_position_fixed_pivots(xy, theta, moving_a=fb.coupler_a, moving_b=fb.coupler_b)
    np.testing.assert_allclose(back.ground_a, ga, atol=1e-7)
    np.testing.assert_allclose(back.ground_b, gb, atol=1e-7)


def test_collinear_positions_raise_clearly():
    translation = ([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]], [0.0, 0.0, 0.0])
    with pytest.raises(SolveError, match="moving pivot A are collinear") as info:
        three_position_fixed_pivots(*translation, moving_a=[0.0, 1.0], moving_b=[1.0, 1.0])
    assert "slider" in str(info.value) and "fix:" in str(info.value)
    with pytest.raises(SolveError, match="fixed pivot A seen from the coupler are collinear"):
        three_position_moving_pivots(*translation, ground_a=[0.0, -1.0], ground_b=[1.0, -1.0])
    # a pure rotation about the origin: the moving pivot there stays put
    turning = ([[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]], [0.0, 0.4, 0.8])
    with pytest.raises(SolveError, match="coincide"):
        three_position_fixed_pivots(*turning, moving_a=[0.0, 0.0], moving_b=[1.0, 0.0])
    with pytest.raises(ValueError, match=r"\(\.\.\., 3, 2\)"):
        three_position_fixed_pivots([[0, 0], [1, 0]], [0, 0], moving_a=[0, 0], moving_b=[1, 0])


def test_guidance_batches_and_masks():
    xy = np.array([POSES[0], [[0, 0], [1, 0], [2, 0]]], dtype=float)
    theta = np.array([POSES[1], [0, 0, 0]], dtype=float)
    fb = three_position_fixed_pivots(
        xy, theta, moving_a=[-0.5, 0.0], moving_b=[0.5, 0.0], errors="mask"
    )
    assert fb.ok.tolist() == [True, False] and "collinear" in fb.reason[1]
    assert fb.moving_a.shape == (2, 3, 2) and np.all(np.isnan(fb.ground_a[1]))
    one = three_position_fixed_pivots(*POSES, moving_a=[-0.5, 0.0], moving_b=[0.5, 0.0])
    np.testing.assert_allclose(fb.ground_a[0], one.ground_a, rtol=1e-14)


# --------------------------------------------------------------------------------------
# (c) slider-crank with stroke H and time ratio K
# --------------------------------------------------------------------------------------


def slider_dead_centres(r, ell, e):
    """Crank angles of the outer and inner dead centres of the slider-crank (guide
    y = −e, slider at x > 0) as roots of dx/dφ, and the slider positions there."""

    def x(phi):
        return r * np.cos(phi) + np.sqrt(ell**2 - (e + r * np.sin(phi)) ** 2)

    def dx(phi):
        q = e + r * np.sin(phi)
        return -r * np.sin(phi) - q * r * np.cos(phi) / np.sqrt(ell**2 - q**2)

    grid = np.linspace(-np.pi, np.pi, 4097) + 0.1234  # no root sits on the grid ends
    values = dx(grid)
    roots = [
        brentq(dx, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15)
        for i in np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]
    ]
    assert len(roots) == 2
    far, near = sorted(roots, key=x, reverse=True)
    # dense sampling agrees with the refined extremes
    assert float(x(far)) >= float(np.max(x(grid))) - 1e-12
    assert float(x(near)) <= float(np.min(x(grid))) + 1e-12
    return far, near, float(x(far)), float(x(near))


def check_slider_crank(sc, stroke, time_ratio):
    r, ell, e = float(sc.crank), float(sc.rod), float(sc.offset)
    far, near, x_far, x_near = slider_dead_centres(r, ell, e)
    assert x_far - x_near == pytest.approx(stroke, rel=1e-9, abs=1e-12)
    outward = (far - near) % (2 * np.pi)  # crank turning counter-clockwise, near → far
    assert outward / (2 * np.pi - outward) == pytest.approx(time_ratio, rel=1e-9)
    assert float(sc.crank_angle_far) == pytest.approx(wrap(far), abs=1e-9)
    assert float(sc.crank_angle_near) == pytest.approx(wrap(near), abs=1e-9)
    assert float(sc.slider_far) == pytest.approx(x_far, rel=1e-9)
    assert float(sc.slider_near) == pytest.approx(x_near, rel=1e-9, abs=1e-12)


def slider_ranges(stroke, time_ratio):
    theta = math.pi * (time_ratio - 1) / (time_ratio + 1)
    t = math.tan(theta / 2)
    return theta, t


stroke_st = st.floats(1e-3, 10.0)
k_st = st.floats(1.001, 2.9)
fraction = st.floats(0.01, 0.99)


@SETTINGS
@given(stroke=stroke_st, k=k_st, u=fraction)
def test_slider_crank_offset_gives_stroke_and_time_ratio(stroke, k, u):
    theta, _ = slider_ranges(stroke, k)
    offset = u * stroke / math.tan(theta)  # inside (0, H cot θ]
    sc = slider_crank_from_stroke(stroke, k, offset=offset)
    assert float(sc.offset) == offset
    check_slider_crank(sc, stroke, k)


@SETTINGS
@given(stroke=stroke_st, k=k_st, u=fraction, free=st.sampled_from(["crank", "rod"]))
def test_slider_crank_crank_or_rod_gives_stroke_and_time_ratio(stroke, k, u, free):
    _, t = slider_ranges(stroke, k)
    lo, hi = (stroke * t / 2, stroke / 2) if free == "crank" else (stroke / 2, stroke / (2 * t))
    value = lo + (0.01 + 0.98 * u) * (hi - lo)
    sc = slider_crank_from_stroke(stroke, k, **{free: value})
    check_slider_crank(sc, stroke, k)
    via_offset = slider_crank_from_stroke(stroke, k, offset=sc.offset)
    np.testing.assert_allclose([via_offset.crank, via_offset.rod], [sc.crank, sc.rod], rtol=1e-9)


def test_central_slider_crank_for_k_equal_one():
    sc = slider_crank_from_stroke(0.08, 1.0, rod=0.25)
    assert (float(sc.crank), float(sc.rod), float(sc.offset)) == (0.04, 0.25, 0.0)
    check_slider_crank(sc, 0.08, 1.0)
    with pytest.raises(SolveError, match="K = 1") as info:
        slider_crank_from_stroke(0.08, 1.0, offset=0.0)
    assert "rod=" in str(info.value)


def test_slider_crank_errors_say_why():
    with pytest.raises(SolveError, match="K ≥ 3"):
        slider_crank_from_stroke(0.1, 3.0, offset=0.01)
    with pytest.raises(SolveError, match="at least 1"):
        slider_crank_from_stroke(0.1, 0.8, offset=0.01)
    limit = 0.1 / math.tan(math.pi * 0.4 / 2.4)  # H cot θ for K = 1.4
    with pytest.raises(SolveError, match="offset is outside") as info:
        slider_crank_from_stroke(0.1, 1.4, offset=1.01 * limit)
    assert f"{limit:.6g}" in str(info.value)
    with pytest.raises(ValueError, match="exactly one"):
        slider_crank_from_stroke(0.1, 1.4)
    with pytest.raises(ValueError, match="exactly one"):
        slider_crank_from_stroke(0.1, 1.4, offset=0.01, crank=0.04)
    masked = slider_crank_from_stroke(0.1, [1.2, 1.4, 3.5], offset=0.05, errors="mask")
    assert masked.ok.tolist() == [True, True, False] and np.isnan(masked.crank[2])
    single = slider_crank_from_stroke(0.1, 1.4, offset=0.05)
    assert float(masked.crank[1]) == pytest.approx(float(single.crank), rel=1e-15)


# --------------------------------------------------------------------------------------
# (d) crank-rocker with swing ψ and time ratio K
# --------------------------------------------------------------------------------------


def rocker_extremes(a, b, c, d, branch):
    """Crank angles at the rocker's maximum and minimum and the rocker angles there, for
    the assembly branch ``branch`` (±1: side of B with respect to the line A → O4)."""
    o4 = np.array([d, 0.0])

    def pins(phi):
        pin_a = a * np.array([math.cos(phi), math.sin(phi)])
        both = circle_intersections(pin_a, b, o4, c)
        assert both is not None, "not a crank: the chain breaks"
        pin_b = [p for p in both if np.sign(cross2(o4 - pin_a, p - pin_a)) == branch]
        return pin_a, (pin_b[0] if pin_b else both[0])

    def psi(phi):
        pin_b = pins(phi)[1]
        return math.atan2(pin_b[1], pin_b[0] - d)

    def ratio(phi):  # ω4/ω2 = a sin(β − φ)/(c sin(β − ψ)); only its sign and roots matter
        pin_a, pin_b = pins(phi)
        beta = math.atan2(*(pin_b - pin_a)[::-1])
        return a * math.sin(beta - phi) / (c * math.sin(beta - psi(phi)))

    grid = np.linspace(-np.pi, np.pi, 2049) + 0.1234  # no root sits on the grid ends
    values = np.array([ratio(p) for p in grid])
    roots = [
        brentq(ratio, grid[i], grid[i + 1], xtol=1e-15, rtol=1e-15)
        for i in np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]
    ]
    assert len(roots) == 2
    phi_max, phi_min = roots if wrap(psi(roots[0]) - psi(roots[1])) > 0 else roots[::-1]
    swing = float(wrap(psi(phi_max) - psi(phi_min)))
    rocker = np.unwrap([psi(p) for p in grid])
    assert swing >= np.ptp(rocker) - 1e-12  # dense sampling agrees
    return phi_max, phi_min, psi(phi_max), psi(phi_min), swing


def check_crank_rocker(cr, swing, time_ratio, slow_swing):
    a, b, c, d = (float(v) for v in (cr.a, cr.b, cr.c, cr.d))
    lengths = sorted([a, b, c, d])
    assert a == lengths[0] and lengths[0] + lengths[3] < lengths[1] + lengths[2]  # Grashof
    # the branch on which the reported extremes lie
    pin_a = a * np.array([math.cos(cr.crank_angle_extended), math.sin(cr.crank_angle_extended)])
    pin_b = np.array([d, 0.0]) + c * np.array(
        [math.cos(cr.rocker_angle_extended), math.sin(cr.rocker_angle_extended)]
    )
    assert math.hypot(*(pin_b - pin_a)) == pytest.approx(b, rel=1e-9)
    branch = np.sign(cross2(np.array([d, 0.0]) - pin_a, pin_b - pin_a))
    phi_max, phi_min, psi_max, psi_min, found = rocker_extremes(a, b, c, d, branch)
    assert found == pytest.approx(swing, rel=1e-9)
    # crank turning counter-clockwise: the rocker rises (turns with it) from min to max
    rising = (phi_max - phi_min) % (2 * np.pi)
    slow_is_rising = rising > np.pi
    arcs = sorted([rising, 2 * np.pi - rising])
    assert arcs[1] / arcs[0] == pytest.approx(time_ratio, rel=1e-9)
    if time_ratio > 1 + 1e-6:
        assert slow_is_rising == (slow_swing == "with_crank")
    reported = {float(wrap(cr.rocker_angle_extended)), float(wrap(cr.rocker_angle_folded))}
    for expected in (psi_max, psi_min):
        assert min(abs(wrap(expected - r)) for r in reported) < 1e-9


@SETTINGS
@given(
    swing=st.floats(math.radians(10), math.radians(150)),
    k=st.floats(1.0, 2.5),
    u=st.floats(0.02, 0.98),
    rocker=st.floats(0.1, 5.0),
    slow_swing=st.sampled_from(["against_crank", "with_crank"]),
)
def test_crank_rocker_swing_and_time_ratio(swing, k, u, rocker, slow_swing):
    lo, hi = crank_rocker_frame_range(swing, k, rocker=rocker, slow_swing=slow_swing)
    assume(float(hi) > float(lo) * 1.001)
    frame = float(lo) + u * (min(float(hi), 10 * rocker) - float(lo))
    cr = crank_rocker_from_swing(swing, k, frame=frame, rocker=rocker, slow_swing=slow_swing)
    check_crank_rocker(cr, swing, k, slow_swing)


def test_crank_rocker_slow_swing_senses_and_k_equal_one():
    for slow_swing in ("against_crank", "with_crank"):
        cr = crank_rocker_from_swing(math.radians(50), 1.3, frame=1.08, slow_swing=slow_swing)
        check_crank_rocker(cr, math.radians(50), 1.3, slow_swing)
        turn = (cr.crank_angle_folded - cr.crank_angle_extended) % (2 * np.pi)
        expected = np.pi + cr.excess_angle * (1 if slow_swing == "against_crank" else -1)
        assert float(turn) == pytest.approx(float(expected), rel=1e-12)
    central = crank_rocker_from_swing(math.radians(60), 1.0, frame=3.0)
    assert float(central.a) == pytest.approx(math.sin(math.radians(30)), rel=1e-12)
    check_crank_rocker(central, math.radians(60), 1.0, "against_crank")


def test_crank_rocker_errors_give_the_range():
    lo, hi = crank_rocker_frame_range(math.radians(50), 1.3)
    with pytest.raises(SolveError, match="frame length") as info:
        crank_rocker_from_swing(math.radians(50), 1.3, frame=float(hi) * 1.01)
    assert f"{float(lo):.6g}, {float(hi):.6g}" in str(info.value)
    # with_crank needs ψ > 2θ: 40° < 2 · 30°
    with pytest.raises(SolveError, match="frame length") as info:
        crank_rocker_from_swing(math.radians(40), 1.4, frame=1.1, slow_swing="with_crank")
    assert "no frame length works" in str(info.value) and "against_crank" in str(info.value)
    with pytest.raises(SolveError, match=r"swing must lie in \(0, π\)"):
        crank_rocker_from_swing(4.0, 1.3, frame=2.0)
    with pytest.raises(ValueError, match="slow_swing"):
        crank_rocker_from_swing(1.0, 1.3, frame=2.0, slow_swing="fast")
    masked = crank_rocker_from_swing(math.radians(50), 1.3, frame=[2.0, 10.0], errors="mask")
    assert masked.ok.tolist() == [True, False] and np.isnan(masked.a[1])


# --------------------------------------------------------------------------------------
# (e) docs
# --------------------------------------------------------------------------------------


def test_docstring_examples_run():
    assert doctest.testmod(classical, raise_on_error=True).attempted > 0
