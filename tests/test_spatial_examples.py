"""The landing gear retracted about an inclined hinge axis (issue 17's example), checked
against references independent of the solver.

``examples/spatial/landing_gear_inclined_axis.yaml``: the strut swings in the plane
normal to a hinge axis tilted from the horizontal (a planar contour in that plane), the
cylinder anchored off that plane closes a spatial contour, and the two are one coupled
block.  The references: the swing angle from the cylinder's length in closed form (the
lug P on the circle about the axis, ``|P − A| = s``, both roots), the plane's axes from
the axis direction by :func:`numpy.cross` (not :mod:`mechloop.model.plane`), the wheel
axle's distance to the axis and to the plane, and central differences for the rates.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import yaml

import mechloop
from mechloop.model.load import model_from_data

GEAR = Path(__file__).resolve().parents[1] / "examples" / "spatial" / \
    "landing_gear_inclined_axis.yaml"


def _data() -> dict:
    return yaml.safe_load(GEAR.read_text(encoding="utf-8"))


def _solve(data: dict, **kwargs):
    return mechloop.solve(model_from_data(copy.deepcopy(data)), **kwargs)


def _direction(a_deg: float, b_deg: float) -> np.ndarray:
    """The unit vector of elevation ``a`` and rotation ``b`` about Y (docs/spatial.md's
    ``(cos α cos β, sin α, cos α sin β)``)."""
    a, b = math.radians(a_deg), math.radians(b_deg)
    return np.array([math.cos(a) * math.cos(b), math.sin(a), math.cos(a) * math.sin(b)])


def _axes(data: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The hinge axis n and the swing plane's axes e1 (horizontal, Y × n) and e2 = n × e1,
    by cross products of the angles the file states."""
    plane = data["contours"][1]["plane"]
    n = _direction(plane["a"], plane["b"])
    e1 = np.cross([0.0, 1.0, 0.0], n)
    e1 /= np.linalg.norm(e1)
    return n, e1, np.cross(n, e1)


def _wrapped(x, y):
    return np.abs(np.angle(np.exp(1j * (x - y))))


def _points(res, number: int) -> np.ndarray:
    """Vector ``number``'s components (3, P)."""
    return np.stack([c[0] for c in res.components(number)])


def test_the_swing_angle_solves_the_cylinder_length_in_closed_form():
    data = _data()
    res = _solve(data)
    assert not res.broken.any() and res.breaks == ()
    (block,) = [b for b in res.structure.blocks if b.coupled]
    assert block.contours == (1, 2)
    n, e1, e2 = _axes(data)
    assert abs(n[1]) > 0.2 and abs(n[1]) < 0.99  # the axis is inclined, not level
    v = data["vectors"]
    # the spatial contour's fixed directions are the plane's axes
    np.testing.assert_allclose(_direction(v[2]["a"], v[2]["b"]), e1, rtol=0, atol=1e-15)
    np.testing.assert_allclose(_direction(v[4]["a"], v[4]["b"]), e2, rtol=0, atol=1e-15)
    anchor = v[1]["r"] * _direction(v[1]["a"], v[1]["b"])
    assert abs(anchor @ n) > 0.1  # the anchor is off the strut's plane
    d, s, theta = v[5]["r"], res.values["r3"], res.values["a5"]
    # |P − A|² = s² with P = d (cos θ e1 + sin θ e2):  p cos θ + q sin θ = c
    p, q = anchor @ e1, anchor @ e2
    c = (d**2 + anchor @ anchor - s**2) / (2 * d)
    h = math.hypot(p, q)
    assert np.all(np.abs(c) < h)  # two roots at every position
    mid, half = math.atan2(q, p), np.arccos(c / h)
    roots = np.stack([mid + half, mid - half])
    miss = _wrapped(theta[None], roots)
    assert miss.min(axis=0).max() < 1e-12
    taken = miss.argmin(axis=0)
    assert np.all(taken == taken[0])  # one root throughout: no jump to the other assembly
    other = roots[1 - taken[0]]
    assert _wrapped(theta, other).min() > 0.5
    # the lug as the spatial contour places it (−(v2 + v4)) is the strut's P in the plane
    lug = -(_points(res, 2) + _points(res, 4))
    np.testing.assert_allclose(lug, _points(res, 5), rtol=0, atol=1e-14)
    np.testing.assert_allclose(
        lug, d * (np.cos(theta) * e1[:, None] + np.sin(theta) * e2[:, None]), rtol=0,
        atol=1e-14)
    # and the cylinder, A → P, has the law's length
    np.testing.assert_allclose(np.linalg.norm(lug - anchor[:, None], axis=0), s,
                               rtol=0, atol=1e-14)


def test_the_wheel_axle_moves_on_the_circle_about_the_inclined_axis():
    data = _data()
    res = _solve(data)
    n, e1, e2 = _axes(data)
    radius = data["vectors"][8]["r"]
    wheel = -_points(res, 9)  # W = −(W → O)
    along = n @ wheel
    across = np.linalg.norm(wheel - np.outer(n, along), axis=0)
    assert np.abs(along).max() < 1e-12  # in the plane through O normal to the axis
    assert np.abs(across - radius).max() < 1e-12  # at the strut's length from the axis
    phi = res.values["a8"]  # its angle in the plane, from e1 towards e2
    np.testing.assert_allclose(wheel, radius * (np.cos(phi) * e1[:, None]
                                                + np.sin(phi) * e2[:, None]), rtol=0, atol=1e-14)
    # its rates are tangent to the circle: along the axis 0, radially 0
    rate = np.stack([c[1] for c in res.components(9)])
    assert np.abs(n @ rate).max() < 1e-12
    assert np.abs(np.einsum("ip,ip->p", wheel, rate)).max() < 1e-12
    # down at the start, nearly level and inboard (−Z) at the end; never in one vertical
    # plane (the axis is inclined, so the path leaves every plane containing Y)
    assert wheel[1, 0] < -0.97 * radius and abs(wheel[1, -1]) < 0.1 * radius
    assert wheel[2, -1] < -0.9 * radius
    swing = math.degrees(_wrapped(res.values["a8"][-1], res.values["a8"][0]))
    assert 80 < swing < 95


def test_the_swing_angle_rates_in_closed_form():
    """Differentiating p cos θ + q sin θ = (d² + |A|² − s²) / (2d) by s:
    θ' = −s / (d (q cos θ − p sin θ)), θ'' = (−1/d + (p cos θ + q sin θ) θ'²) /
    (q cos θ − p sin θ); in time θ̇ = θ' ṡ, θ̈ = θ'' ṡ² + θ' s̈ (ṡ, s̈ the law's)."""
    data = _data()
    res = _solve(data)
    _, e1, e2 = _axes(data)
    v = data["vectors"]
    anchor = v[1]["r"] * _direction(v[1]["a"], v[1]["b"])
    p, q, d = anchor @ e1, anchor @ e2, v[5]["r"]
    theta, s = res.values["a5"], res.values["r3"]
    s_dot, s_ddot = res.rates["r3"], res.accels["r3"]
    lever = q * np.cos(theta) - p * np.sin(theta)
    d1 = -s / (d * lever)
    d2 = (-1 / d + (p * np.cos(theta) + q * np.sin(theta)) * d1**2) / lever
    rate, accel = d1 * s_dot, d2 * s_dot**2 + d1 * s_ddot
    assert np.abs(res.rates["a5"] - rate).max() <= 1e-12 * np.abs(rate).max()
    assert np.abs(res.accels["a5"] - accel).max() <= 1e-12 * np.abs(accel).max()
    np.testing.assert_array_equal(res.rates["a8"], res.rates["a5"])  # the link, exactly


def test_the_rates_match_finite_differences_and_the_chain_rule():
    """dq/ds and d²q/ds² by central differences in the cylinder length's offset; the time
    derivatives are then q̇ = q' ṡ and q̈ = q'' ṡ² + q' s̈ (ṡ, s̈ of the law, the
    cylinder's own r3 rates).  The coupled block's rates come from its Jacobian, its
    positions from Newton's method: two independent routes.  The cylinder and the wheel
    axle by their components (the cylinder's a3, b3 may be written as the other pair of
    angles of the same direction in a shifted run)."""
    data = _data()
    res = _solve(data)
    h = 3e-5  # m: truncation (~h²) and round-off (~1e-16/h²) of the differences balanced
    runs = []
    for step in (-h, h):
        moved = copy.deepcopy(data)
        moved["vectors"][3]["r"] = {"argument": 1, "offset": step}
        runs.append(_solve(moved))
    s_dot, s_ddot = res.rates["r3"], res.accels["r3"]
    series = {name: (runs[0].values[name], res.values[name], runs[1].values[name],
                     res.rates[name], res.accels[name]) for name in ("r2", "r4", "a5", "r7")}
    for number in (3, 9):
        for axis, (value, rate, accel) in zip("xyz", res.components(number), strict=True):
            lo, hi = (r.components(number)["xyz".index(axis)][0] for r in runs)
            series[f"{axis}{number}"] = (lo, value, hi, rate, accel)
    for name, (lo, mid, hi, got_rate, got_accel) in series.items():
        d1, d2 = (hi - lo) / (2 * h), (hi - 2 * mid + lo) / h**2
        rate, accel = d1 * s_dot, d2 * s_dot**2 + d1 * s_ddot
        assert np.abs(got_rate - rate).max() <= 1e-6 * np.abs(rate).max(), name
        assert np.abs(got_accel - accel).max() <= 2e-6 * np.abs(accel).max(), name
    assert np.abs(res.rates["r9"]).max() < 1e-12  # the axle's distance from O is fixed


def test_a_coupled_blocks_directions_follow_their_contours_convention():
    """The cylinder's direction (α3 and β3 both unknowns of the coupled block) comes out
    in the spatial contour's parameter-range convention — convention 1: β in (−90°, 90°],
    convention 2: α in [−90°, 90°] — continuous along the positions, and the same
    direction either way (Newton alone may end on either angle pair of a direction)."""
    units = []
    for convention in (1, 2):
        data = _data()
        data["contours"][0]["convention"] = convention
        res = _solve(data)
        assert not res.broken.any()
        a, b = res.values["a3"], res.values["b3"]
        if convention == 1:
            assert np.all(np.abs(b) <= math.pi / 2 + 1e-12)
            assert 0 <= a[0] < 2 * math.pi
        else:
            assert np.all(np.abs(a) <= math.pi / 2 + 1e-12)
        assert np.abs(np.diff(a)).max() < 0.1 and np.abs(np.diff(b)).max() < 0.1
        units.append(np.stack([np.cos(a) * np.cos(b), np.sin(a), np.cos(a) * np.sin(b)]))
    np.testing.assert_allclose(units[0], units[1], rtol=0, atol=1e-12)
