"""The involute spur gear pair of mechloop.gears against a published worked example, and
its formulas against the geometry of the teeth the basic rack generates.

Reference: KHK Gear Technical Reference (Kohara Gear Industry), sec. 4.3 "Profile shifted
spur gear", the worked calculation of a profile-shifted pair: m = 3 mm, α = 20°,
z = 12/24, x = +0.6/+0.36 (its table of results is reproduced, with a = 56.5 mm, at
http://bolsover.com/utilitiesforalibre/profile-shifted-external-spur-gears.html).  Every
printed value is recomputed here to the digits printed.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from mechloop.gears.centre_distance import (
    centre_distance_from_shifts,
    shift_sum_from_centre_distance,
)
from mechloop.gears.drawing import mesh_phases, mesh_points, pair_profiles
from mechloop.gears.generation import generate_tooth
from mechloop.gears.involute import inv, inv_inverse, thickness_on_circle
from mechloop.gears.pair import GearPair, gear_pair
from mechloop.gears.sliding import balanced_shift, extreme_sliding, specific_sliding

ALPHA = np.radians(20.0)


@pytest.fixture(scope="module")
def khk():
    return gear_pair(3.0, (12, 24), ALPHA, x=(0.6, 0.36))


def test_the_khk_worked_example_of_a_profile_shifted_pair(khk):
    # printed: inv α = 0.014904, inv α_w = 0.034316, α_w = 26.0886°, y = 0.83329,
    # a = 56.4999 mm
    assert round(float(inv(ALPHA)), 6) == 0.014904
    assert round(float(inv(khk.alpha_w)), 6) == 0.034316
    assert round(float(np.degrees(khk.alpha_w)), 4) == 26.0886
    assert round(khk.y, 5) == 0.83329
    assert round(khk.a, 4) == 56.4999
    # d = 36/72, d_b = 33.8289/67.6579, d_w = 37.667/75.333
    assert np.allclose(khk.d, [36.0, 72.0], atol=0)
    assert np.array_equal(np.round(khk.d_b, 4), [33.8289, 67.6579])
    assert np.array_equal(np.round(khk.d_w, 3), [37.667, 75.333])
    # h_a = 4.420/3.700, h_f = 1.950/2.670, h = 6.370, d_a = 44.840/79.400,
    # d_f = 32.100/66.660
    assert np.array_equal(np.round(khk.h_a, 3), [4.420, 3.700])
    assert np.array_equal(np.round(khk.h_f, 3), [1.950, 2.670])
    assert np.array_equal(np.round(khk.h, 3), [6.370, 6.370])
    assert np.array_equal(np.round(khk.d_a, 3), [44.840, 79.400])
    assert np.array_equal(np.round(khk.d_f, 3), [32.100, 66.660])
    # contact ratio 1.202
    assert round(khk.eps_alpha, 3) == 1.202
    # KHK's tip: h_a1 = (1 + y − x2) m keeps the tip clearance c* m = 0.75 mm
    assert np.allclose(khk.tip_clearances, 0.25 * 3.0, rtol=0, atol=1e-12)


def test_the_khk_example_backwards_from_the_centre_distance():
    # the reverse calculation: a = 56.4999 mm gives α_w = 26.0886°, x1 + x2 = 0.9600; the
    # bolsover table gives a = 56.500 mm: inv α_w = 0.034317, α_w = 26.0888°, y = 0.83333
    x_sum, alpha_w = shift_sum_from_centre_distance(3.0, 12, 24, 56.4999, ALPHA)
    assert round(float(x_sum), 4) == 0.9600
    assert round(float(np.degrees(alpha_w)), 4) == 26.0886
    x_sum, alpha_w = shift_sum_from_centre_distance(3.0, 12, 24, 56.5, ALPHA)
    assert round(float(inv(alpha_w)), 6) == 0.034317
    assert round(float(np.degrees(alpha_w)), 4) == 26.0888
    pair = gear_pair(3.0, (12, 24), ALPHA, a=56.5, x1=0.6)
    assert round(pair.y, 5) == 0.83333 and abs(pair.a - 56.5) < 1e-12


def test_unshifted_pair_is_the_textbook_standard_pair():
    pair = gear_pair(3.0, (12, 24), ALPHA, x=(0.0, 0.0))
    assert pair.a == pytest.approx(54.0, abs=1e-12)
    assert pair.alpha_w == pytest.approx(ALPHA, abs=1e-14)
    assert np.allclose(pair.d_a, [42.0, 78.0]) and np.allclose(pair.d_f, [28.5, 64.5])
    assert np.allclose(pair.s, np.pi * 3 / 2) and pair.dy == pytest.approx(0, abs=1e-12)


@settings(max_examples=300, deadline=None)
@given(z1=st.integers(8, 150), z2=st.integers(8, 300), x1=st.floats(-0.5, 1.2),
       x2=st.floats(-0.5, 1.2), m=st.floats(0.5, 20))
def test_centre_distance_from_shifts_and_back(z1, z2, x1, x2, m):
    # within limits: a working pressure angle of at least 5° (a real pair)
    assume(inv(ALPHA) + 2 * (x1 + x2) * np.tan(ALPHA) / (z1 + z2) > inv(np.radians(5.0)))
    a, alpha_w = centre_distance_from_shifts(m, z1, z2, x1, x2, ALPHA)
    x_sum, back = shift_sum_from_centre_distance(m, z1, z2, a, ALPHA)
    assert abs(float(x_sum) - (x1 + x2)) < 1e-9
    assert abs(float(back - alpha_w)) < 1e-12
    # the definition: the working circles roll without backlash, s_w1 + s_w2 = p_w
    pair = GearPair(m, (z1, z2), ALPHA, (x1, x2))
    p_w = np.pi * pair.d_w[0] / z1
    assert abs(pair.s_w.sum() - p_w) < 1e-9 * m


@settings(max_examples=200, deadline=None)
@given(alpha=st.floats(1e-4, 1.5))
def test_the_inverse_involute_inverts_the_involute(alpha):
    assert abs(float(inv_inverse(inv(alpha))) - alpha) < 1e-12 * max(1.0, alpha)


def test_undercut_limit_is_the_textbook_rule():
    # x_min = h_a*(z_min − z)/z_min with z_min = 2 h_a*/sin²α when the rack's straight flank
    # reaches h_a* below its datum (ρ* = 0: h_FfP0* = h_a* + c*; take c* = 0)
    z = np.arange(5, 30)
    pair_x = gear_pair(1.0, (12, 24), ALPHA, x=(0, 0), c=0.0, rho=0.0).x_min
    z_min = 2 / np.sin(ALPHA) ** 2
    assert np.allclose(pair_x, 1.0 * (z_min - np.array([12, 24])) / z_min)
    from mechloop.gears.checks import minimum_shift
    assert np.allclose(minimum_shift(z, 1.0, 0.0, 0.0, ALPHA), (z_min - z) / z_min)
    # ISO 53 profile A (c* = 0.25, ρ* = 0.38): the straight flank still ends 1.0 m deep
    assert np.allclose(minimum_shift(z, 1.0, 0.25, 0.38, ALPHA), (z_min - z) / z_min,
                       atol=1e-4)


@pytest.mark.parametrize("z, x", [(12, 0.6), (24, 0.36), (10, 0.0), (17, -0.2), (17, 0.1),
                                  (40, 0.5)])
def test_tooth_thickness_matches_the_generated_tooth(z, x):
    m = 2.0
    pair = gear_pair(m, (z, 40), ALPHA, x=(x, 0.0))
    tooth = generate_tooth(m, z, ALPHA, x, d_a=float(pair.d_a[0]), radii=2000)
    # above the fillet (of an undercut tooth, above the part it cuts away)
    low = max(pair.d_Ff[0] / 2, pair.d_b[0] / 2, tooth.cut_top) + 0.02 * m
    radii = np.linspace(low, pair.d_a[0] / 2, 9)
    measured = tooth.thickness(radii)
    formula = thickness_on_circle(pair.s[0], pair.d[0], ALPHA, 2 * radii)
    assert np.max(np.abs(measured - formula)) < 2e-5 * m
    # the generated involute starts at the form circle (undercut: at the base circle, to
    # the spacing of the rack's positions, and the fillet cuts it further up)
    start = np.hypot(*tooth.flank[0])
    assert abs(start - pair.d_Ff[0] / 2) < (1e-4 if pair.undercut[0] else 1e-9) * m
    # undercut (x < x_min) exactly when the generated fillet reaches above the involute's
    # start
    cut_in = tooth.cut_top > start + 1e-3 * m
    assert pair.undercut[0] == (x < pair.x_min[0]) == cut_in


def test_undercut_tooth_is_thinner_than_its_involute_near_the_base_circle():
    m = 1.0
    for z, undercut in ((10, True), (20, False)):
        pair = gear_pair(m, (z, 40), ALPHA, x=(0.0, 0.0))
        tooth = generate_tooth(m, z, ALPHA, 0.0, radii=2000)
        rho = pair.d_b[0] / 2 * 1.002
        involute = thickness_on_circle(pair.s[0], pair.d[0], ALPHA, 2 * rho)
        thinner = involute - tooth.thickness(rho)
        assert (thinner > 0.005 * m) == undercut, (z, thinner)
        assert thinner > -1e-4 * m  # never thicker than the involute


def _flank(profile, rho, phase, centre, side):
    """Points of a drawn flank (side +1: the side at +ψ from the tooth's axis)."""
    ang = phase + side * np.interp(rho, profile.rho, profile.psi)
    return centre + np.stack([rho * np.cos(ang), rho * np.sin(ang)], axis=-1)


@pytest.mark.parametrize("z, x", [((12, 24), (0.6, 0.36)), ((20, 50), (0.0, 0.0)),
                                   ((18, 31), (0.3, -0.1))])
def test_contact_ratio_is_the_rotation_between_the_tips_crossing_the_line_of_action(z, x):
    pair = gear_pair(2.0, z, ALPHA, x=x)
    prof = pair_profiles(pair, radii=3000)
    pts = mesh_points(pair)
    u = (pts["N2"] - pts["N1"]) / np.linalg.norm(pts["N2"] - pts["N1"])
    n = np.array([-u[1], u[0]])
    r_a1, r_a2 = pair.d_a / 2

    def pinion_tip(phi):  # the driving flank's tip corner of pinion tooth 0
        return _flank(prof[0], np.array(r_a1), mesh_phases(pair, phi)[0], pts["O1"], +1)

    def wheel_tip(phi):   # the tip corner of the wheel tooth mating with it
        phase = mesh_phases(pair, phi)[1] - 2 * np.pi / pair.z[1]
        return _flank(prof[1], np.array(r_a2), phase, pts["O2"], +1)

    step = 2 * np.pi / pair.z[0]
    length = pair.line_of_action

    def crossing(corner):
        """The pinion's turn at which ``corner`` crosses the segment N1 N2."""
        grid = np.linspace(-3 * step, 3 * step, 601)
        side = np.array([(corner(f) - pts["N1"]) @ n for f in grid])
        for k in np.flatnonzero(np.sign(side[:-1]) != np.sign(side[1:])):
            root = brentq(lambda f: (corner(f) - pts["N1"]) @ n, grid[k], grid[k + 1],
                          xtol=1e-14)
            if 0 < (corner(root) - pts["N1"]) @ u < length:
                return root
        raise AssertionError("the corner does not cross the line of action")

    phi_e, phi_a = crossing(pinion_tip), crossing(wheel_tip)
    measured_eps = (phi_e - phi_a) / step
    measured_g = np.linalg.norm(pinion_tip(phi_e) - wheel_tip(phi_a))
    assert abs(measured_eps - pair.eps_alpha) < 2e-4
    assert abs(measured_g - pair.g_alpha) < 1e-4 * pair.m_n
    # between those, the driving flank meets the line of action on the wheel's flank
    for phi in np.linspace(phi_a, phi_e, 7)[1:-1]:
        rho = np.linspace(pair.d_b[0] / 2 * 1.0001, r_a1, 4000)
        f1 = _flank(prof[0], rho, mesh_phases(pair, phi)[0], pts["O1"], +1)
        side = (f1 - pts["N1"]) @ n
        k = np.flatnonzero(np.sign(side[:-1]) != np.sign(side[1:]))[0]
        t = side[k] / (side[k] - side[k + 1])
        contact = f1[k] + t * (f1[k + 1] - f1[k])
        # the contact point runs along the line at the base circle's speed: g = g_0 + r_b1 φ
        g = (contact - pts["N1"]) @ u
        assert abs(g - (pair.d_b[0] / 2 * (phi - phi_e) + pair.active_line[1])) < 1e-4
        rho2 = np.linspace(pair.d_b[1] / 2 * 1.0001, r_a2, 4000)
        f2 = _flank(prof[1], rho2, mesh_phases(pair, phi)[1] - 2 * np.pi / pair.z[1],
                    pts["O2"], +1)
        assert np.min(np.linalg.norm(f2 - contact, axis=1)) < 2e-3 * pair.m_n


def test_balanced_shifts_equalize_the_extreme_specific_sliding(khk):
    x1 = balanced_shift(khk, 0.96)
    pair = gear_pair(3.0, (12, 24), ALPHA, x=(x1, 0.96 - x1))
    t1, t2 = extreme_sliding(pair)
    assert abs(t1 - t2) < 1e-9 and pair.a == pytest.approx(khk.a, abs=1e-9)
    # more pinion shift than that relieves the pinion's root at the wheel's expense
    t1_more, t2_more = extreme_sliding(gear_pair(3.0, (12, 24), ALPHA, x=(x1 + 0.1,
                                                                         0.86 - x1)))
    assert t1_more > t1 and t2_more < t2


def test_specific_sliding_is_the_ratio_of_arc_lengths_on_the_generated_flanks(khk):
    prof = pair_profiles(khk)
    arcs = []
    for i in range(2):
        flank = prof[i].flank
        radius = np.hypot(flank[:, 0], flank[:, 1])
        s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(flank, axis=0).T))])
        arcs.append((radius, s))
    g_a, g_e = khk.active_line
    length = khk.line_of_action
    for g in np.linspace(g_a, g_e, 5):
        dg = 1e-3
        swept = []
        for i, along in ((0, np.array([g - dg, g + dg])),
                         (1, length - np.array([g - dg, g + dg]))):
            rho = np.hypot(khk.d_b[i] / 2, along)  # where the contact is on flank i
            radius, s = arcs[i]
            swept.append(abs(np.diff(np.interp(rho, radius, s))[0]))
        t1, t2 = specific_sliding(khk, g)
        assert abs((1 - swept[1] / swept[0]) - t1) < 2e-3
        assert abs((1 - swept[0] / swept[1]) - t2) < 2e-3


def test_the_checks_flag_undercut_pointed_teeth_and_interference():
    bad = gear_pair(2.0, (10, 40), ALPHA, x=(0.0, 0.0))
    failed = {(c.name, c.gear) for c in bad.checks() if not c.ok}
    assert ("undercut", 1) in failed and ("interference", 1) in failed
    pointed = gear_pair(2.0, (10, 40), ALPHA, x=(1.2, 0.0))
    assert pointed.s_a[0] < 0.25 * 2.0
    assert ("pointed tooth", 1) in {(c.name, c.gear) for c in pointed.checks() if not c.ok}
    assert all(c.ok for c in gear_pair(3.0, (12, 24), ALPHA, x=(0.6, 0.36)).checks())


def test_the_docstring_examples_of_the_gear_modules_run():
    import doctest

    from mechloop.gears import involute, pair, planetary

    attempted = sum(doctest.testmod(module, raise_on_error=True).attempted
                    for module in (involute, pair, planetary))
    assert attempted >= 4


def _sector(profile, centre, phase, teeth=2):
    """Teeth −teeth…teeth of a drawn gear about the direction ``phase``, closed through
    its centre (a simple polygon)."""
    one = profile.outline(phase=0.0)[:-1]
    first = one[:len(one) // profile.z]
    turns = phase + 2 * np.pi / profile.z * np.arange(-teeth, teeth + 1)
    pts = np.vstack([first @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]])
                     for a in turns]) + centre
    return np.vstack([centre, pts, centre])


def _overlap(pair, turns=17):
    """The deepest a drawn wheel tooth enters the drawn pinion over a pitch of rotation,
    in modules."""
    from matplotlib.path import Path as Polygon
    from scipy.spatial import cKDTree

    prof = pair_profiles(pair, radii=300)
    pts = mesh_points(pair)
    worst = 0.0
    for phi in np.linspace(-np.pi / pair.z[0], np.pi / pair.z[0], turns):
        p1, p2 = mesh_phases(pair, phi)
        pinion = _sector(prof[0], pts["O1"], p1)
        wheel = _sector(prof[1], pts["O2"], p2)[1:-1]
        inside = Polygon(pinion).contains_points(wheel)
        if inside.any():
            worst = max(worst, cKDTree(pinion[1:-1]).query(wheel[inside])[0].max())
    return worst / pair.m_n


@pytest.mark.parametrize("z, x, overlap", [((12, 24), (0.6, 0.36), False),
                                           ((20, 30), (0.0, 0.0), False),
                                           ((20, 30), (3.0, 3.0), True),
                                           ((15, 15), (1.5, 1.5), True),
                                           ((10, 40), (0.0, 0.0), False)])
def test_interference_is_where_the_drawn_teeth_overlap(z, x, overlap):
    """A tip reaching below the form circle of a tooth that is not undercut overlaps the
    drawn fillet; an undercut pinion (z = 10) is flagged too, yet lets the tip pass (the
    contact there is not on the involute)."""
    from mechloop.gears.pair import GearPair

    pair = GearPair(2.0, z, ALPHA, x)
    flagged = not all(c.ok for c in pair.checks() if c.name == "interference")
    depth = _overlap(pair)
    if pair.undercut.any():
        assert flagged and depth == 0.0
    else:
        assert flagged == overlap == (depth > 0.02), depth


def test_a_tooth_all_fillet_fails_the_involute_flank_check():
    """With x = 3 on 10 and 20 teeth the tool's straight flank meets the blank only beyond
    its tip circle: the form diameter (where the involute would start) lies above the tip
    diameter, the tooth has no involute flank, and the check says so for both gears."""
    degenerate = gear_pair(2.0, (10, 20), ALPHA, x=(3.0, 3.0))
    assert (degenerate.d_a < degenerate.d_Ff).all()
    flank = {c.gear: c for c in degenerate.checks() if c.name == "involute flank"}
    assert set(flank) == {1, 2} and not any(c.ok for c in flank.values())
    assert flank[1].value == degenerate.d_a[0] and flank[1].limit == degenerate.d_Ff[0]
    standard = gear_pair(3.0, (12, 24), ALPHA, x=(0.6, 0.36))
    assert all(c.ok for c in standard.checks() if c.name == "involute flank")
    assert (standard.d_a > standard.d_Ff).all()
