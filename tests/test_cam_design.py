"""Cam design by inverted motion (mechloop.cams) against closed forms, finite differences
of the produced profile, the textbook peak coefficients, and the vector model of the same
cam built with intermediate arguments (seed 000 sec. 2.3–2.6)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechloop.cams.base_radius import (
    max_pressure_ratio,
    minimum_base_radius,
    minimum_flat_base_radius,
)
from mechloop.cams.checks import face_width, max_pressure_angle, min_curvature_radius
from mechloop.cams.followers import (
    OscillatingFlat,
    OscillatingRoller,
    TranslatingFlat,
    TranslatingRoller,
)
from mechloop.cams.laws import LAW_NAMES, Law, law, peak_coefficients, table_law
from mechloop.cams.profile import Cam
from mechloop.cams.program import MotionProgram, Segment

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
deg = math.radians


def program(rise: str = "cycloidal", back: str = "cycloidal", lift: float = 0.02,
            angles=(120, 60, 120, 60)) -> MotionProgram:
    a = [deg(x) for x in angles]
    return MotionProgram((Segment("rise", a[0], lift, law(rise)), Segment("dwell", a[1]),
                          Segment("return", a[2], lift, law(back)), Segment("dwell", a[3])))


# ------------------------------------------------------------------ laws and coefficients
#: Peak coefficients C_v, C_a, C_j of the normalized laws as printed in R. L. Norton, Cam
#: Design and Manufacturing Handbook, 2nd ed. (Industrial Press, 2009), ch. 3 (to four or
#: five figures) ...
TEXTBOOK = {
    "constant_speed": (1.0, 0.0, 0.0),
    "harmonic": (1.5708, 4.9348, 15.503),
    "cycloidal": (2.0, 6.2832, 39.478),
    "poly345": (1.875, 5.7735, 60.0),
    "poly4567": (2.1875, 7.5132, 52.5),
    "modified_trapezoidal": (2.0, 4.8881, 61.426),
    "modified_sine": (1.7596, 5.5280, 69.466),
}
#: ... and their closed forms where they have one: π/2, π²/2, π³/2; 2, 2π, 4π²;
#: 15/8, 10/√3, 60; 35/16, —, 52.5.
CLOSED = {
    "harmonic": (math.pi / 2, math.pi**2 / 2, math.pi**3 / 2),
    "cycloidal": (2.0, 2 * math.pi, 4 * math.pi**2),
    "poly345": (15 / 8, 10 / math.sqrt(3), 60.0),
    "poly4567": (35 / 16, None, 52.5),
}


@pytest.mark.parametrize("name", LAW_NAMES)
def test_peak_coefficients_match_the_textbook(name):
    got = peak_coefficients(law(name))
    values = (got.velocity, got.acceleration, got.jerk)
    for value, expected in zip(values, TEXTBOOK[name], strict=True):
        assert value == pytest.approx(expected, rel=1e-4, abs=1e-12)
    for value, exact in zip(values, CLOSED.get(name, (None,) * 3), strict=True):
        if exact is not None:
            assert value == pytest.approx(exact, rel=1e-12)


@pytest.mark.parametrize("top", [0.0004, 0.37, 0.9995])
def test_continuous_max_finds_a_peak_between_samples(top):
    """The maximum of a smooth function between two samples — inside, or between an end
    and its neighbour — is found to rounding (its place to √ε), not the best sample
    (0.05 away at most, a value 2.5e-3 low)."""
    from mechloop.cams.laws import continuous_max

    value, where = continuous_max(lambda x: 1 - (x - top)**2, 0.0, 1.0, samples=11)
    assert where == pytest.approx(top, abs=1e-7)
    assert value == pytest.approx(1.0, abs=1e-15)


@pytest.mark.parametrize("name", LAW_NAMES)
def test_law_ends_and_derivatives_by_finite_differences(name):
    f = law(name)
    ends = f(np.array([0.0, 1.0]))
    assert ends[0].tolist() == pytest.approx([0.0, 1.0], abs=1e-14)
    assert ends[1].tolist() == pytest.approx([0.0 if name != "constant_speed" else 1.0] * 2,
                                             abs=1e-12)
    tau = np.linspace(0.02, 0.98, 97)
    h = 1e-5
    for k in range(3):
        fd = (f(tau + h)[k] - f(tau - h)[k]) / (2 * h)
        assert np.abs(fd - f(tau)[k + 1]).max() <= 1e-5 * max(1.0, np.abs(f(tau)[k + 1]).max())


def test_table_law_is_a_quintic_spline_with_dwell_ends():
    f = table_law([0, 0.25, 0.5, 1.0], [0, 0.1, 0.5, 1.0])
    v = f(np.array([0.0, 0.25, 0.5, 1.0]))
    assert v[0].tolist() == pytest.approx([0, 0.1, 0.5, 1.0], abs=1e-12)
    for k in (1, 2):  # zero velocity and acceleration at both ends: C² against a dwell
        assert v[k][[0, -1]].tolist() == pytest.approx([0, 0], abs=1e-10)
    # through a straight line the spline with these ends is the 3-4-5 polynomial
    line = table_law([0, 0.5, 1.0], [0, 0.5, 1.0])
    tau = np.linspace(0, 1, 41)
    for k in range(4):
        assert np.abs(line(tau)[k] - law("poly345")(tau)[k]).max() < 1e-9


# ------------------------------------------------------------------ program continuity
LAWS = st.sampled_from(LAW_NAMES)


@st.composite
def programs(draw) -> MotionProgram:
    """A random turn: rises and returns by random laws, dwells between some of them, and
    a final motion back to where it started."""
    n = draw(st.integers(1, 4))
    kinds = []
    for _ in range(n):
        kinds.append(draw(st.sampled_from(["rise", "return"])))
        if draw(st.booleans()):
            kinds.append("dwell")
    weights = [draw(st.floats(0.3, 3.0)) for _ in range(len(kinds) + 1)]
    total = sum(weights)
    segs, level = [], 0.0
    for kind, w in zip(kinds, weights, strict=False):
        angle = 2 * math.pi * w / total
        if kind == "dwell":
            segs.append(Segment("dwell", angle))
            continue
        lift = draw(st.floats(0.001, 0.05))
        segs.append(Segment(kind, angle, lift, law(draw(LAWS))))
        level += lift if kind == "rise" else -lift
    last = 2 * math.pi * weights[-1] / total
    if abs(level) < 1e-4:  # back where it started but for a sliver: the last motion takes it
        k = max(i for i, seg in enumerate(segs) if seg.kind != "dwell")
        seg = segs[k]
        lift = seg.lift - level if seg.kind == "rise" else seg.lift + level
        segs[k] = Segment(seg.kind, seg.angle, lift, seg.law)
        segs.append(Segment("dwell", last))
    else:
        kind = "return" if level > 0 else "rise"
        segs.append(Segment(kind, last, abs(level), law(draw(LAWS))))
    return MotionProgram(tuple(segs))


def _order(seg: Segment) -> int:
    return 99 if seg.law is None else seg.law.continuity


@settings(max_examples=60, deadline=None)
@given(prog=programs())
def test_joins_are_as_smooth_as_the_laws_claim(prog):
    """At every join (and at 360° = 0°) s is continuous, and s', s'', s''' are continuous
    when both laws claim it; a law that claims less does jump against a dwell."""
    n = len(prog.segments)
    edges = prog.edges
    scale = [max(1e-300, abs(x)) for x in (prog.stroke, prog.stroke * 10, prog.stroke * 100,
                                           prog.stroke * 1e4)]
    for k in range(n):
        j = (k + 1) % n
        left = prog.on_segment(k, np.array([edges[k + 1]]))
        right = prog.on_segment(j, np.array([edges[j]]))
        order = min(_order(prog.segments[k]), _order(prog.segments[j]))
        for d, name in enumerate(("s", "ds", "dds", "ddds")):
            jump = abs(float(getattr(left, name)[0] - getattr(right, name)[0]))
            if d <= order:
                assert jump <= 1e-9 * scale[d], (k, name, jump)
            elif prog.segments[j].law is None and d == order + 1 and d < 3:
                assert jump > 1e-6 * scale[d] * 1e-3, (k, name, "claimed jump missing")


@settings(max_examples=30, deadline=None)
@given(prog=programs())
def test_program_analogs_by_finite_differences(prog):
    edges = prog.edges
    h = 1e-6
    for k, seg in enumerate(prog.segments):
        phi = np.linspace(edges[k] + 0.1 * seg.angle, edges[k + 1] - 0.1 * seg.angle, 9)
        m = prog.on_segment(k, phi)
        for lo, hi in (("s", "ds"), ("ds", "dds"), ("dds", "ddds")):
            fd = (getattr(prog.on_segment(k, phi + h), lo)
                  - getattr(prog.on_segment(k, phi - h), lo)) / (2 * h)
            ref = max(1e-12, np.abs(getattr(m, hi)).max())
            assert np.abs(fd - getattr(m, hi)).max() <= 1e-5 * ref + 1e-9 * np.abs(
                getattr(m, lo)).max() / h


# ------------------------------------------------------------------ eccentric circle
class _EccentricRise:
    """The follower motion of a radial roller follower on an eccentric circle (pitch
    radius R', eccentricity ε), normalized: ``y(φ) = −ε cos φ + √(R'² − ε² sin² φ)``,
    rising from φ = 0 to π by 2ε; with its exact derivatives."""

    def __init__(self, eps: float, pitch: float, back: bool = False):
        self.eps, self.pitch, self.back = eps, pitch, back

    def y(self, phi):
        e, r = self.eps, self.pitch
        u = r * r - (e * np.sin(phi))**2
        du = -e * e * np.sin(2 * phi)
        ddu = -2 * e * e * np.cos(2 * phi)
        dddu = 4 * e * e * np.sin(2 * phi)
        g = np.sqrt(u)
        dg = du / (2 * g)
        ddg = ddu / (2 * g) - du**2 / (4 * g**3)
        dddg = (dddu / (2 * g) - ddu * dg / (2 * g * g) - du * ddu / (2 * g**3)
                + 3 * du**2 * dg / (4 * g**4))
        c, s = np.cos(phi), np.sin(phi)
        return (-e * c + g, e * s + dg, e * c + ddg, -e * s + dddg)

    def __call__(self, tau):
        h = 2 * self.eps
        if not self.back:
            y = self.y(math.pi * tau)
            base = self.y(np.zeros(1))[0][0]
            return ((y[0] - base) / h, *(y[k] * math.pi**k / h for k in (1, 2, 3)))
        # the return: f(τ) = 1 − f_rise(1 − τ)
        y = self.y(math.pi * (1 - tau))
        base = self.y(np.zeros(1))[0][0]
        return (1 - (y[0] - base) / h, *(-y[k] * (-math.pi)**k / h for k in (1, 2, 3)))


def test_eccentric_circle_with_a_roller_follower_is_exact():
    """A disc of radius Rc whose centre is ε from the shaft, under a radial roller
    follower of radius r: given the follower motion it makes, the synthesis gives back the
    circle (its working profile and its pitch circle R' = Rc + r), the pressure angle
    sin α = ε sin φ / R' (the normal passes through the disc's centre) and the radii of
    curvature Rc and R'."""
    eps, rc, r = 0.008, 0.03, 0.01
    pitch = rc + r
    rise = Law("eccentric rise", _EccentricRise(eps, pitch), 1)
    back = Law("eccentric return", _EccentricRise(eps, pitch, back=True), 1)
    prog = MotionProgram((Segment("rise", math.pi, 2 * eps, rise),
                          Segment("return", math.pi, 2 * eps, back)))
    cam = Cam(TranslatingRoller(r, 0.0), prog, pitch - eps)  # lowest: R' − ε
    phi = np.linspace(0, 2 * math.pi, 721)
    g = cam.at(phi)
    centre = np.array([0.0, -eps])  # the disc's centre in the cam's frame
    assert np.abs(np.hypot(*(g.profile - centre).T) - rc).max() < 1e-14
    assert np.abs(np.hypot(*(g.pitch - centre).T) - pitch).max() < 1e-14
    # the follower displacement is the closed form
    y = -eps * np.cos(phi) + np.sqrt(pitch**2 - (eps * np.sin(phi))**2)
    assert np.abs(g.motion.s - (y - (pitch - eps))).max() < 1e-15
    assert np.abs(g.pressure - np.arcsin(eps * np.sin(phi) / pitch)).max() < 1e-13
    assert np.abs(g.pitch_rho - pitch).max() < 1e-12
    assert np.abs(g.rho - rc).max() < 1e-12
    assert min_curvature_radius(cam).value == pytest.approx(rc, rel=1e-10)


def test_eccentric_circle_is_the_harmonic_cam_of_a_flat_follower():
    """The harmonic law rising 2ε over 180° and returning over 180° under a flat face:
    the profile is the circle of radius R0 + ε about (0, −ε) in the cam's frame, with
    ρ = R0 + s + s'' = R0 + ε everywhere (the scotch yoke)."""
    eps, r0 = 0.006, 0.025
    prog = MotionProgram((Segment("rise", math.pi, 2 * eps, law("harmonic")),
                          Segment("return", math.pi, 2 * eps, law("harmonic"))))
    cam = Cam(TranslatingFlat(), prog, r0)
    phi = np.linspace(0, 2 * math.pi, 721)
    g = cam.at(phi)
    assert np.abs(g.motion.s - eps * (1 - np.cos(phi))).max() < 1e-15
    assert np.abs(np.hypot(g.profile[:, 0], g.profile[:, 1] + eps) - (r0 + eps)).max() < 1e-15
    assert np.abs(g.rho - (r0 + eps)).max() < 1e-15
    width = face_width(cam)
    assert (width.low.value, width.high.value) == pytest.approx((-eps, eps), rel=1e-12)


# ------------------------------------------------------ finite-difference geometry check
FOLLOWERS = {
    "translating": (TranslatingRoller(0.01, 0.012), 0.04, program()),
    "rocker": (OscillatingRoller(0.008, 0.1, 0.08), 0.036,
               program("poly345", "modified_sine", deg(20), (100, 80, 120, 60))),
    "flat": (TranslatingFlat(), 0.07, program("modified_trapezoidal", "poly4567", 0.015)),
    "flat rocker": (OscillatingFlat(0.09, 0.004), 0.03,
                    program("cycloidal", "poly345", deg(12), (120, 60, 120, 60))),
}


@pytest.mark.parametrize("name", sorted(FOLLOWERS))
def test_pressure_angle_and_curvature_by_finite_differences_of_the_profile(name):
    """Inside each segment: the profile's tangent by central differences, its normal
    against the follower's direction of motion (pressure angle), and its radius of
    curvature |W'|³ / (W' × W'') by differences; the contact point is where the roller
    circle touches the profile (W − P normal to the profile)."""
    follower, radius, prog = FOLLOWERS[name]
    cam = Cam(follower, prog, radius)
    h = 1e-5
    for k, seg in enumerate(prog.segments):
        if seg.law is None:
            continue
        phi = np.linspace(prog.edges[k] + 0.05 * seg.angle, prog.edges[k + 1] - 0.05 * seg.angle,
                          41)
        g = cam.on_segment(k, phi)
        ahead, behind = cam.on_segment(k, phi + h).profile, cam.on_segment(k, phi - h).profile
        d1 = (ahead - behind) / (2 * h)
        d2 = (ahead - 2 * g.profile + behind) / h**2
        rho = -np.hypot(*d1.T)**3 / (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0])
        assert np.abs(rho - g.rho).max() <= 2e-4 * np.abs(g.rho).max()
        # the follower's direction of motion in the cam's frame, from the follower's own
        # point moved by a small step of s (not from the synthesis' formulas)
        step = 1e-7
        moved = _point_with_s(cam, phi, g.motion.s + step)
        direction = (moved - _point_with_s(cam, phi, g.motion.s - step)) / (2 * step)
        direction /= np.hypot(*direction.T)[:, None]
        # α between the profile's normal and the direction of motion: atan2(T·d, T×d)
        # with T the profile's tangent (along the pitch curve's where the cam is convex)
        pressure = np.arctan2(np.sum(d1 * direction, axis=1),
                              d1[:, 0] * direction[:, 1] - d1[:, 1] * direction[:, 0])
        assert np.abs(pressure - g.pressure).max() < 1e-6
        if not follower.flat:
            radial = g.pitch - g.profile
            assert np.abs(np.hypot(*radial.T) - follower.roller_radius).max() < 1e-15
            assert np.abs(np.sum(radial * d1, axis=1)).max() < 1e-6 * np.hypot(*d1.T).max() * \
                follower.roller_radius


def _point_with_s(cam: Cam, phi, s):
    """The follower's reference point (roller centre; face foot) in the cam's frame for a
    displacement ``s``, by plain trigonometry of each follower."""
    f = cam.follower
    if isinstance(f, TranslatingRoller):
        fixed = np.stack([np.full_like(s, f.offset),
                          math.sqrt(cam.base_radius**2 - f.offset**2) + s], axis=1)
    elif isinstance(f, OscillatingRoller):
        a, arm = f.pivot_distance, f.arm
        beta = math.acos((a * a + arm * arm - cam.base_radius**2) / (2 * a * arm)) + s
        fixed = np.stack([a - arm * np.cos(beta), arm * np.sin(beta)], axis=1)
    elif isinstance(f, OscillatingFlat):  # the contact point as a point of the rocker
        a, off = f.pivot_distance, f.face_offset
        beta = math.asin((cam.base_radius - off) / a) + s
        u = cam.on_segment(cam.program.evaluate(phi).segment[len(phi) // 2], phi)\
            .contact_along
        fixed = np.stack([a - u * np.cos(beta) + off * np.sin(beta),
                          u * np.sin(beta) + off * np.cos(beta)], axis=1)
    else:
        fixed = np.stack([np.zeros_like(s), cam.base_radius + s], axis=1)
    c, n = np.cos(phi), np.sin(phi)
    return np.stack([c * fixed[:, 0] + n * fixed[:, 1], -n * fixed[:, 0] + c * fixed[:, 1]],
                    axis=1)


def test_translating_pressure_angle_is_the_textbook_formula():
    """tan α = (s' − e)/(s₀ + s), s₀ = √(R0² − e²) (Norton, eq. 8.5 with the offset)."""
    follower, radius, prog = FOLLOWERS["translating"]
    g = Cam(follower, prog, radius).cycle(720)
    s0 = math.sqrt(radius**2 - follower.offset**2)
    expected = np.arctan((g.motion.ds - follower.offset) / (s0 + g.motion.s))
    assert np.abs(g.pressure - expected).max() < 1e-14


# ------------------------------------------------------------------ minimum base radius
def _dense_max_pressure(cam: Cam, n: int = 20001) -> float:
    return float(np.abs(cam.at(np.linspace(0, 2 * math.pi, n)).pressure).max())


@pytest.mark.parametrize("follower, prog, allowed", [
    (TranslatingRoller(0.01, 0.0), program("poly345", "cycloidal"), deg(30)),
    (TranslatingRoller(0.01, 0.008), program("modified_trapezoidal", "harmonic"), deg(28)),
    (OscillatingRoller(0.008, 0.1, 0.08),
     program("poly345", "modified_sine", deg(20), (100, 80, 120, 60)), deg(40)),
], ids=["radial", "offset", "rocker"])
def test_minimum_base_radius_is_the_smallest_within_the_limit(follower, prog, allowed):
    """At R_min the largest pressure angle over the continuous turn equals the limit; a
    small step below it exceeds the limit even at the samples of a dense grid, a small
    step above stays within at every sample."""
    radius = minimum_base_radius(follower, prog, allowed)
    at = Cam(follower, prog, radius)
    assert max_pressure_angle(at).value == pytest.approx(allowed, rel=1e-9)
    assert max_pressure_ratio(at, allowed) <= 1 + 1e-12
    step = 1e-4 * radius
    assert _dense_max_pressure(Cam(follower, prog, radius - step)) > allowed
    assert _dense_max_pressure(Cam(follower, prog, radius + step)) < allowed


def test_minimum_base_radius_with_a_larger_return_limit():
    follower, prog = TranslatingRoller(0.01, 0.01), program()
    both = minimum_base_radius(follower, prog, deg(30))
    relaxed = minimum_base_radius(follower, prog, deg(30), allowed_return=deg(45))
    assert relaxed < both
    cam = Cam(follower, prog, relaxed)
    assert max_pressure_ratio(cam, deg(30), deg(45)) == pytest.approx(1.0, rel=1e-9)


@pytest.mark.parametrize("follower, prog", [
    (TranslatingFlat(), program("modified_trapezoidal", "poly4567", 0.015)),
    (OscillatingFlat(0.09, 0.004), program("cycloidal", "poly345", deg(12),
                                           (120, 60, 120, 60))),
], ids=["translating", "rocker"])
def test_minimum_flat_base_radius_is_the_smallest_convex(follower, prog):
    for rho_min in (0.0, 0.005):
        radius = minimum_flat_base_radius(prog, rho_min, follower=follower)
        assert min_curvature_radius(Cam(follower, prog, radius)).value == \
            pytest.approx(rho_min, abs=1e-11)
        phi = np.linspace(0, 2 * math.pi, 20001)
        step = 1e-4 * radius
        below = Cam(follower, prog, radius - step).at(phi).rho
        above = Cam(follower, prog, radius + step).at(phi).rho
        assert below.min() < rho_min < above.min()


@pytest.mark.parametrize("name", ["flat", "flat rocker"])
def test_a_flat_face_never_cuts_its_convex_cam(name):
    """The face in every position is a supporting line of the produced profile: every
    profile point lies on the cam's side of it (a check of the envelope that does not use
    the synthesis' contact formula), and touches it at the contact point."""
    follower, radius, prog = FOLLOWERS[name]
    g = Cam(follower, prog, radius).cycle(720)
    gap = np.einsum("ijk,ik->ij", g.profile[None, :, :] - g.profile[:, None, :], g.normal)
    assert gap.max() <= 1e-12 * radius
    assert np.abs(np.diagonal(gap)).max() == 0


def test_undercut_is_found_where_the_roller_is_larger_than_the_pitch_curvature():
    follower, radius, prog = FOLLOWERS["translating"]
    cam = Cam(follower, prog, radius)
    rho = min_curvature_radius(cam)
    pitch = rho.value + follower.roller_radius  # smallest convex pitch radius
    big = Cam(TranslatingRoller(pitch * 1.01, follower.offset), prog, radius)
    assert min_curvature_radius(big).value < 0
    g = big.at(np.linspace(rho.phi - 0.05, rho.phi + 0.05, 201))
    assert (g.rho < 0).any()  # the profile there is a loop (undercut)


# ----------------------------------------------------------- the vector model of the cam
def test_profile_matches_the_vector_model_with_intermediate_arguments():
    """examples/cam_roller_follower.yaml and cam_flat_follower.yaml (the seed's route: the
    guide turned by −φ, the roller or face swept by an intermediate argument, the profile
    their envelope) against the synthesis of the same cams, position by position."""
    import mechloop
    from mechloop.cams.document import load_cam
    from mechloop.solve.intermediate import solve_intermediate

    design = load_cam(EXAMPLES / "cams" / "roller.yaml")
    res = solve_intermediate(mechloop.load_model(EXAMPLES / "cam_roller_follower.yaml"))
    x, y = res.envelopes["profile"].curve(-1)
    g = design.cam.cycle(360)
    assert np.isfinite(x).all()
    assert np.abs(np.stack([x, y], axis=1) - g.profile).max() < 1e-12
    flat = Cam(TranslatingFlat(), program(), 0.04)
    res = solve_intermediate(mechloop.load_model(EXAMPLES / "cam_flat_follower.yaml"))
    x, y = res.envelopes["profile"].curve(-1)
    assert np.abs(np.stack([x, y], axis=1) - flat.cycle(360).profile).max() < 1e-12


@pytest.mark.parametrize("follower, radius", [(TranslatingRoller(0.009, -0.008), 0.045),
                                              (TranslatingFlat(), 0.05)],
                         ids=["roller", "flat"])
def test_the_vector_model_written_from_a_design_gives_its_profile(follower, radius, tmp_path):
    """`mechloop cam --model`: the design written as the seed's vector model (other laws,
    the offset on the other side) and solved by the intermediate-argument solver gives
    the same profile at every degree, the acceleration jumps of the harmonic law
    included."""
    import mechloop
    from mechloop.cams.design import CamDesign
    from mechloop.cams.vector_model import write_vector_model
    from mechloop.solve.intermediate import solve_intermediate

    prog = MotionProgram((Segment("rise", deg(90), 0.018, law("harmonic")),
                          Segment("dwell", deg(30)),
                          Segment("return", deg(150), 0.018, law("poly345")),
                          Segment("dwell", deg(90))))
    design = CamDesign.build(follower, prog, base_radius=radius)
    path = write_vector_model(design, tmp_path / "cam.yaml")
    x, y = solve_intermediate(mechloop.load_model(path)).envelopes["profile"].curve(-1)
    assert np.isfinite(x).all()
    assert np.abs(np.stack([x, y], axis=1) - design.cam.cycle(360).profile).max() < 1e-12


@pytest.mark.parametrize("rise_law, return_law", [
    ("harmonic", "cycloidal"), ("poly345", "poly4567"),
    ("modified_trapezoidal", "modified_sine"), ("cycloidal", "modified_trapezoidal")])
def test_a_flat_cam_at_its_smallest_convex_radius_is_not_called_undercut(
        tmp_path, rise_law, return_law):
    """At the smallest base radius for a convex profile ρ_min equals the allowed radius up
    to rounding: the design is sound; a hair smaller is not."""
    from mechloop.cams import load_cam

    for rise, rho in ((8, 3), (10, 6), (15, 6)):
        path = tmp_path / "flat.yaml"
        path.write_text(f"""cam:
  units: {{length: mm, angle: deg}}
  follower: {{type: translating_flat}}
  min_curvature_radius: {rho}
  segments:
    - {{rise: {rise}, angle: 110, law: {rise_law}}}
    - {{dwell: 70}}
    - {{return: {rise}, angle: 120, law: {return_law}}}
    - {{dwell: 60}}
""", encoding="utf-8")
        design = load_cam(path)
        summary = design.summary()
        assert summary.base_radius == summary.minimum
        assert summary.rho.value == pytest.approx(rho * 1e-3, rel=1e-9)
        assert not summary.undercut
        smaller = path.read_text().replace("segments:", f"base_radius: "
                                           f"{summary.minimum * 1e3 * (1 - 1e-6)!r}\n  segments:")
        path.write_text(smaller, encoding="utf-8")
        assert load_cam(path).summary().undercut
