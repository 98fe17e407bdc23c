"""The bundled example models: each loads, solves and tabulates cleanly, and the numbers of
each one agree with an independent computation in plain NumPy.

The independent references never run mechloop: positions come from textbook geometry
(circle-circle intersection, the slider-crank formula, the law of cosines) written out
here; velocities and accelerations are five-point central finite differences of those
reference positions as continuous functions of the crank angle or of time (so no denser
model is needed).  Tolerances, relative to the largest magnitude over the cycle: 1e-9 for
positions and angles (rad), 1e-9 for velocities and 1e-7 for accelerations — about 100
times the finite-difference error, far below any real mistake.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE_DIR = ROOT / "examples"
EXAMPLES = sorted([*EXAMPLE_DIR.glob("*.yaml"), *EXAMPLE_DIR.glob("*.yml")])

#: Examples that break on purpose: file name -> the broken positions (none today).
INTENDED_BREAKS: dict[str, list[int]] = {
    # a crank that cannot turn fully: simulate runs it up to the break
    "four_bar_break_ahead.yaml": list(range(31, 42)),
}

POS_RTOL = 1e-9
RATE_RTOL = 1e-9
ACCEL_RTOL = 1e-7


# ----------------------------------------------------------------------------- helpers


def load(name: str) -> mechloop.Model:
    return mechloop.load_model(EXAMPLE_DIR / name)


def wrap(angle):
    """Angle difference folded into [-π, π)."""
    return (np.asarray(angle) + np.pi) % (2 * np.pi) - np.pi


def assert_angles(actual, expected, what: str, tol: float = POS_RTOL) -> None:
    err = np.abs(wrap(np.asarray(actual) - np.asarray(expected)))
    assert np.all(np.isfinite(err)), f"{what}: NaN"
    assert err.max() <= tol, f"{what}: off by {err.max():.3e} rad (max at {err.argmax()})"


def assert_close(actual, expected, what: str, rtol: float) -> None:
    """|actual - expected| <= rtol * max|expected| everywhere (a scale-aware tolerance)."""
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = max(np.abs(expected).max(), 1e-300)
    err = np.abs(actual - expected)
    assert np.all(np.isfinite(err)), f"{what}: NaN"
    assert err.max() <= rtol * scale, (
        f"{what}: off by {err.max():.3e} (scale {scale:.3e}, max at {err.argmax()})")


def _steps(f: Callable[[np.ndarray], np.ndarray], x: np.ndarray, h: float, angle: bool):
    """f(x + k h) - f(x) for k = -2..2 (angle differences folded into [-π, π))."""
    f0 = f(x)
    return {k: (wrap(f(x + k * h) - f0) if angle else f(x + k * h) - f0)
            for k in (-2, -1, 1, 2)}


def d1(f: Callable[[np.ndarray], np.ndarray], x: np.ndarray, h: float = 1e-3, angle=False):
    """Five-point central first difference of ``f`` at ``x`` (error ~ h⁴ f⁽⁵⁾/30)."""
    s = _steps(f, x, h, angle)
    return (8 * (s[1] - s[-1]) - (s[2] - s[-2])) / (12 * h)


def d2(f: Callable[[np.ndarray], np.ndarray], x: np.ndarray, h: float = 4e-3, angle=False):
    """Five-point central second difference of ``f`` at ``x`` (error ~ h⁴ f⁽⁶⁾/90)."""
    s = _steps(f, x, h, angle)
    return (16 * (s[1] + s[-1]) - (s[2] + s[-2])) / (12 * h**2)


def e(angle) -> np.ndarray:
    """Unit vectors, shape (2, P)."""
    angle = np.asarray(angle, float)
    return np.array([np.cos(angle), np.sin(angle)])


def circle_intersection(p, rp, q, rq) -> np.ndarray:
    """The intersection of circle (p, rp) and circle (q, rq) on the left of p -> q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    dist = np.hypot(dx, dy)
    along = (rp**2 - rq**2 + dist**2) / (2 * dist)
    height = np.sqrt(rp**2 - along**2)
    return np.array([p[0] + (along * dx - height * dy) / dist,
                     p[1] + (along * dy + height * dx) / dist])


def chain_point_rate(res: mechloop.Results, vectors: list[int]) -> np.ndarray:
    """Velocity of the end of a chain of vectors, from the solved parameters and rates."""
    total = np.zeros((2, res.broken.size))
    for n in vectors:
        r, a = res.value(f"r{n}"), res.value(f"a{n}")
        dr, da = res.rate(f"r{n}"), res.rate(f"a{n}")
        total += dr * e(a) + r * da * e(a + np.pi / 2)
    return total


def vector_roles(data: dict) -> dict[str, object]:
    """Raw role of every parameter of a model document, keyed 'r3', 'a2', ..."""
    return {f"{letter}{number}": spec[letter]
            for number, spec in data["vectors"].items() for letter in "ra"}


def is_constant(name: str, roles: dict[str, object]) -> bool:
    """A number or quantity string, or a link chain that ends on one."""
    seen = set()
    while isinstance(roles[name], dict) and "link" in roles[name] and name not in seen:
        seen.add(name)
        name = roles[name]["link"]
    role = roles[name]
    if isinstance(role, dict):
        return False
    return not (isinstance(role, str) and role.strip() == "function")


def argument_unit(number: int, roles: dict[str, object]) -> str:
    """'m' for an argument that drives lengths, 'rad' for one that drives angles."""
    letters = {name[0] for name, role in roles.items()
               if isinstance(role, dict) and role.get("argument") == number}
    return "m" if letters == {"r"} else "rad"


def documented_columns(data: dict) -> list[str]:
    """The columns Results.to_frame documents, derived from the raw document: position,
    time, arguments, then value, rate and acceleration of every parameter that varies,
    and chain_break; derivatives per second, or analogs per unit of argument 1."""
    roles = vector_roles(data)
    arguments = sorted(data.get("arguments", {}))
    cols = ["position"]
    if data.get("time") is not None:
        cols.append("time [s]")
        per1, per2 = "s", "s^2"
    else:
        per1 = argument_unit(arguments[0], roles) if arguments else "rad"
        per2 = f"{per1}^2"
    for number in arguments:
        cols.append(f"arg{number} [{'m' if argument_unit(number, roles) == 'm' else 'deg'}]")
    for number in sorted(data["vectors"]):
        for letter in "ra":
            name = f"{letter}{number}"
            if is_constant(name, roles):
                continue
            base = "m" if letter == "r" else "rad"
            cols.append(f"{name} [{'m' if letter == 'r' else 'deg'}]")
            cols.append(f"d{name} [{base}/{per1}]")
            cols.append(f"dd{name} [{base}/{per2}]")
    cols.append("chain_break")
    return cols


# ------------------------------------------------------------- every bundled example


def test_examples_are_found():
    names = {p.name for p in EXAMPLES}
    assert {"crank_slider.yaml", "four_bar.yaml", "six_bar.yaml", "v_engine.yaml",
            "sparse_argument.yaml", "hydraulic_rocker.yaml", "four_bar_groups.yaml",
            "crank_slider_groups.yaml", "six_bar_groups.yaml"} <= names


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_loads_solves_and_tabulates(path: Path):
    text = path.read_text(encoding="utf-8")
    assert text.startswith("#"), "an example starts with a comment header explaining it"
    data = yaml.safe_load(text)
    model = mechloop.load_model(path)
    if "groups" in data:  # built from Assur groups: the columns are the generated model's
        data = model.model_dump()
    res = mechloop.solve(model)

    broken = np.flatnonzero(res.broken).tolist()
    assert broken == INTENDED_BREAKS.get(path.name, []), \
        "; ".join(b.describe() for b in res.breaks)
    if not broken:
        assert res.breaks == ()

    frame = res.to_frame()
    assert len(frame) == model.positions + 1
    assert list(frame.columns) == documented_columns(data)
    assert frame["position"].tolist() == list(range(model.positions + 1))
    solved = frame.drop(columns="chain_break").to_numpy(float)
    assert np.isfinite(solved[~res.broken]).all()


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_contours_close(path: Path):
    """Every contour's vectors, and their velocities and accelerations, sum to zero."""
    model = mechloop.load_model(path)
    res = mechloop.solve(model)
    ok = ~res.broken
    for number, contour in enumerate(model.contours, start=1):
        pos = np.zeros((2, ok.sum()))
        vel = np.zeros_like(pos)
        acc = np.zeros_like(pos)
        scale = [0.0, 0.0, 0.0]
        for n in contour.vectors:
            r, a = res.value(f"r{n}")[ok], res.value(f"a{n}")[ok]
            dr, da = res.rate(f"r{n}")[ok], res.rate(f"a{n}")[ok]
            ddr, dda = res.accel(f"r{n}")[ok], res.accel(f"a{n}")[ok]
            u, w = e(a), e(a + np.pi / 2)
            terms = (r * u, dr * u + r * da * w,
                     (ddr - r * da**2) * u + (2 * dr * da + r * dda) * w)
            for i, (total, term) in enumerate(zip((pos, vel, acc), terms, strict=True)):
                total += term
                scale[i] = max(scale[i], np.abs(term).max())
        for what, total, s in zip(("positions", "velocities", "accelerations"),
                                  (pos, vel, acc), scale, strict=True):
            assert np.abs(total).max() <= 1e-12 * max(s, 1e-300), \
                f"contour {number}: {what} do not close"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_runs_through_the_cli(path: Path, tmp_path: Path):
    runner = CliRunner()
    for command in (["check", str(path)], ["info", str(path)]):
        result = runner.invoke(app, command)
        assert result.exit_code == 0, result.output
    out = tmp_path / "x.csv"
    result = runner.invoke(app, ["solve", str(path), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert ("chain break" in result.output) == bool(INTENDED_BREAKS.get(path.name))
    written = pd.read_csv(out)
    model = mechloop.load_model(path)
    solved = mechloop.solve_dynamics(model) if model.bodies else mechloop.solve(model)
    frame = solved.to_frame()
    assert list(written.columns) == list(frame.columns)
    np.testing.assert_allclose(written.drop(columns="chain_break").to_numpy(float),
                               frame.drop(columns="chain_break").to_numpy(float),
                               rtol=1e-15, atol=0)
    assert (written["chain_break"] == frame["chain_break"]).all()


# ------------------------------------------------------------------------ four_bar.yaml

FB_CRANK, FB_COUPLER, FB_ROCKER, FB_FRAME = 0.100, 0.350, 0.250, 0.300
FB_POINT, FB_POINT_ANGLE = 0.250, math.radians(30)
FB_OMEGA = 120 * 2 * math.pi / 60


def four_bar_reference(theta):
    """Crank pin A, rocker pin B and coupler point P for crank angles ``theta``."""
    a = FB_CRANK * e(theta)
    c = np.array([FB_FRAME, 0.0])[:, None] * np.ones_like(np.asarray(theta, float))
    b = circle_intersection(a, FB_COUPLER, c, FB_ROCKER)  # B above the frame line
    coupler = np.arctan2(b[1] - a[1], b[0] - a[0])
    p = a + FB_POINT * e(coupler + FB_POINT_ANGLE)
    return a, b, c, p


def test_four_bar_positions_by_circle_intersection():
    res = mechloop.solve(load("four_bar.yaml"))
    theta = np.radians(np.arange(73) * 5.0)
    a, b, c, p = four_bar_reference(theta)
    assert_close(res.time, np.arange(73) * 0.5 / 72, "time (120 rpm)", 1e-15)
    assert_angles(res.value("a1"), theta, "crank angle")
    assert_angles(res.value("a2"), np.arctan2(b[1] - a[1], b[0] - a[0]), "coupler angle")
    # the rocker angle C->B is a3 + 180 deg
    assert_angles(res.value("a3") + np.pi, np.arctan2(b[1] - c[1], b[0] - c[0]),
                  "rocker angle")
    assert_close(np.array(res.point([1, 2])), b, "rocker pin B", POS_RTOL)
    assert_close(np.array(res.point([5, 6])), p, "coupler point P", POS_RTOL)
    assert_close(-res.value("r7") * e(res.value("a7")), p, "coupler point = -r7", POS_RTOL)
    assert_close(res.value("r7"), np.hypot(*p), "|OP|", POS_RTOL)
    # a crank-rocker: the rocker swings between two limits, never turns round
    swing = np.degrees(np.ptp(np.unwrap(res.value("a3"))))
    assert 30 < swing < 90


def test_four_bar_velocities_and_accelerations_by_finite_differences():
    res = mechloop.solve(load("four_bar.yaml"))
    theta = np.radians(np.arange(73) * 5.0)
    w = FB_OMEGA

    def rocker(t):
        _, b, c, _ = four_bar_reference(t)
        return np.arctan2(b[1] - c[1], b[0] - c[0])

    def coupler(t):
        a, b, _, _ = four_bar_reference(t)
        return np.arctan2(b[1] - a[1], b[0] - a[0])

    def point(t):
        return four_bar_reference(t)[3]

    assert_close(res.rate("a1"), np.full(73, w), "crank speed", 1e-15)
    assert_close(res.rate("a3"), w * d1(rocker, theta, angle=True), "rocker speed",
                 RATE_RTOL)
    assert_close(res.rate("a2"), w * d1(coupler, theta, angle=True), "coupler speed",
                 RATE_RTOL)
    assert_close(res.accel("a3"), w**2 * d2(rocker, theta, angle=True),
                 "rocker acceleration", ACCEL_RTOL)
    assert_close(res.accel("a2"), w**2 * d2(coupler, theta, angle=True),
                 "coupler acceleration", ACCEL_RTOL)
    assert_close(chain_point_rate(res, [5, 6]), w * d1(point, theta),
                 "coupler point velocity", RATE_RTOL)
    assert_close(-chain_point_rate(res, [7]), w * d1(point, theta),
                 "coupler point velocity from r7, a7", RATE_RTOL)
    assert_close(res.rate("r7"), w * d1(lambda t: np.hypot(*point(t)), theta),
                 "rate of |OP|", RATE_RTOL)
    assert_close(res.accel("r7"), w**2 * d2(lambda t: np.hypot(*point(t)), theta),
                 "acceleration of |OP|", ACCEL_RTOL)


# ------------------------------------------------------------------------- six_bar.yaml

SB_CRANK, SB_COUPLER, SB_ROCKER, SB_FRAME = 0.080, 0.320, 0.220, 0.300
SB_CD, SB_DE, SB_OUT = 0.200, 0.300, 0.150
SB_BELL = math.radians(170)  # C->D is C->B turned by 170 deg (a5 = a3 - 10 deg)
SB_F = np.array([SB_FRAME + 0.4 * math.cos(math.radians(-30)), 0.4 * math.sin(math.radians(-30))])
SB_OMEGA = 60 * 2 * math.pi / 60


def six_bar_reference(theta):
    """Joints B, C, D, E, F of the Watt II six-bar for crank angles ``theta``."""
    ones = np.ones_like(np.asarray(theta, float))
    a = SB_CRANK * e(theta)
    c = np.array([SB_FRAME, 0.0])[:, None] * ones
    b = circle_intersection(a, SB_COUPLER, c, SB_ROCKER)
    psi = np.arctan2(b[1] - c[1], b[0] - c[0])
    d = c + SB_CD * e(psi + SB_BELL)
    f = SB_F[:, None] * ones
    e_joint = circle_intersection(d, SB_DE, f, SB_OUT)  # E on the left of D->F
    return b, c, d, e_joint, f


def six_bar_output(theta):
    _, _, _, ej, f = six_bar_reference(theta)
    return np.arctan2(ej[1] - f[1], ej[0] - f[0])


def test_six_bar_positions_by_circle_intersection():
    res = mechloop.solve(load("six_bar.yaml"))
    theta = np.radians(np.arange(73) * 5.0)
    b, c, d, ej, f = six_bar_reference(theta)
    assert_angles(res.value("a3") + np.pi, np.arctan2(b[1] - c[1], b[0] - c[0]),
                  "bell crank angle C->B")
    # output rocker F->E is a7 + 180 deg; link D->E is a6
    assert_angles(res.value("a7") + np.pi, six_bar_output(theta), "output rocker angle")
    assert_angles(res.value("a6"), np.arctan2(ej[1] - d[1], ej[0] - d[0]), "link D-E angle")
    assert_close(np.array(res.point([1, 2, 3])), c, "C", POS_RTOL)
    assert_close(np.array(res.point([1, 2, 3, 5])), d, "D", POS_RTOL)
    assert_close(np.array(res.point([1, 2, 3, 5, 6])), ej, "E", POS_RTOL)
    assert_close(np.array(res.point([1, 2, 3, 5, 6, 7])), f, "F", POS_RTOL)
    swing = np.degrees(np.ptp(res.value("a7")))
    assert 55 < swing < 70, "the comment header promises a swing of about 62 deg"


def test_six_bar_output_rates_by_finite_differences():
    res = mechloop.solve(load("six_bar.yaml"))
    theta = np.radians(np.arange(73) * 5.0)
    w = SB_OMEGA
    assert_close(res.rate("a7"), w * d1(six_bar_output, theta, angle=True),
                 "output rocker speed", RATE_RTOL)
    assert_close(res.accel("a7"), w**2 * d2(six_bar_output, theta, angle=True),
                 "output rocker acceleration", ACCEL_RTOL)
    assert_close(res.rate("a5"), res.rate("a3"), "bell crank is rigid", 1e-15)


# ------------------------------------------------------------------------ v_engine.yaml

VE_CRANK, VE_ROD = 0.040, 0.140
VE_AXES = (math.radians(45), math.radians(135))
VE_OMEGA = 3000 * 2 * math.pi / 60


def piston(theta, axis):
    """Textbook slider-crank: distance of the piston pin from the crank axis along a
    cylinder axis at angle ``axis``, x = r cos β + sqrt(l² - r² sin² β), β = θ - axis."""
    beta = np.asarray(theta) - axis
    return VE_CRANK * np.cos(beta) + np.sqrt(VE_ROD**2 - (VE_CRANK * np.sin(beta)) ** 2)


def test_v_engine_piston_positions_by_slider_crank_formula():
    res = mechloop.solve(load("v_engine.yaml"))
    theta = np.radians(np.arange(73) * 5.0)
    for (length, rod, chain), axis in zip((("r3", "a2", [1, 2]), ("r6", "a5", [4, 5])),
                                          VE_AXES, strict=True):
        s = piston(theta, axis)
        assert_close(res.value(length), s, f"piston distance {length}", POS_RTOL)
        pin = s * e(np.full_like(theta, axis))
        assert_close(np.array(res.point(chain)), pin, f"piston pin {chain}", POS_RTOL)
        crank_pin = VE_CRANK * e(theta)
        assert_angles(res.value(rod), np.arctan2(pin[1] - crank_pin[1], pin[0] - crank_pin[0]),
                      f"rod angle {rod}")
    # top and bottom dead centres: cylinder 1 at 45/225 deg (positions 9/45),
    # cylinder 2 at 135/315 deg (positions 27/63)
    for name, tdc, bdc in (("r3", 9, 45), ("r6", 27, 63)):
        assert res.value(name)[tdc] == pytest.approx(VE_CRANK + VE_ROD, rel=1e-12)
        assert res.value(name)[bdc] == pytest.approx(VE_ROD - VE_CRANK, rel=1e-12)
        assert res.rate(name)[tdc] == pytest.approx(0, abs=1e-12)
    # the two cylinders run the same motion 90 deg (18 positions) apart
    assert_close(res.value("r6")[18:], res.value("r3")[:-18], "90 deg phase", POS_RTOL)


def test_v_engine_piston_velocities_by_finite_differences():
    res = mechloop.solve(load("v_engine.yaml"))
    theta = np.radians(np.arange(73) * 5.0)
    w = VE_OMEGA
    for name, axis in zip(("r3", "r6"), VE_AXES, strict=True):
        def s(t, axis=axis):
            return piston(t, axis)
        assert_close(res.rate(name), w * d1(s, theta), f"piston speed {name}",
                     RATE_RTOL)
        assert_close(res.accel(name), w**2 * d2(s, theta),
                     f"piston acceleration {name}", ACCEL_RTOL)
    # textbook: at TDC the piston acceleration is -r ω² (1 + r/l)
    assert res.accel("r3")[9] == pytest.approx(-VE_CRANK * w**2 * (1 + VE_CRANK / VE_ROD),
                                               rel=1e-9)


# ------------------------------------------------------------------ hydraulic_rocker.yaml

HR_LUG, HR_FRAME, HR_LEG = 0.2, 0.7, 1.2
HR_LEG_OFFSET = math.radians(40)
HR_L0, HR_L1, HR_T = 0.60, 0.85, 4.0


def cylinder_length(t):
    """3-4-5 polynomial from 0.60 m at t = 0 to 0.85 m at t = 4 s.

    Not clipped outside [0, 4] s: every position of the model lies inside, and the smooth
    polynomial lets central differences at t = 0 and 4 s see the law's one-sided
    derivatives (zero) instead of the kink of the held end values.
    """
    tau = np.asarray(t, float) / HR_T
    return HR_L0 + (HR_L1 - HR_L0) * (10 * tau**3 - 15 * tau**4 + 6 * tau**5)


def lug_angle_of_length(length):
    """Law of cosines in triangle O (trunnion), G = (-0.7, 0), P: a1 = 180 deg + γ."""
    cos_g = (HR_LUG**2 + HR_FRAME**2 - length**2) / (2 * HR_LUG * HR_FRAME)
    return np.pi + np.arccos(cos_g)


def lug_angle(t):
    return lug_angle_of_length(cylinder_length(t))


def test_hydraulic_rocker_positions_by_law_of_cosines():
    res = mechloop.solve(load("hydraulic_rocker.yaml"))
    t = np.arange(41) * 0.1
    assert_close(res.time, t, "time table", 1e-15)
    length = cylinder_length(t)
    assert_close(res.arguments[1], length, "cylinder length (poly345)", 1e-12)
    assert_close(res.value("r2"), length, "r2 = argument 1", 1e-12)
    a1 = lug_angle(t)
    assert_angles(res.value("a1"), a1, "lug angle")
    lug = HR_LUG * e(a1)
    ground = np.array([-HR_FRAME, 0.0])[:, None]
    assert_angles(res.value("a2"), np.arctan2(ground[1] - lug[1], ground[0] - lug[0]),
                  "cylinder angle")
    wheel = HR_LEG * e(a1 + HR_LEG_OFFSET)
    assert_close(np.array(res.point([4])), wheel, "wheel axle", POS_RTOL)
    assert_close(-res.value("r5") * e(res.value("a5")), wheel, "wheel axle = -r5", POS_RTOL)
    # as the comment header says: the leg hangs nearly straight down and swings ~81 deg
    leg = np.degrees(res.value("a4")) - 360
    assert -90 < leg[0] < -85 and -10 < leg[-1] < 0
    assert 80 < leg[-1] - leg[0] < 82


def test_hydraulic_rocker_rates_by_finite_differences():
    res = mechloop.solve(load("hydraulic_rocker.yaml"))
    t = np.arange(41) * 0.1
    assert_close(res.rate("r2"), d1(cylinder_length, t), "cylinder speed", RATE_RTOL)
    assert_close(res.accel("r2"), d2(cylinder_length, t), "cylinder acceleration",
                 ACCEL_RTOL)
    assert_close(res.rate("a1"), d1(lug_angle, t), "leg angular speed", RATE_RTOL)
    assert_close(res.accel("a1"), d2(lug_angle, t), "leg angular acceleration",
                 ACCEL_RTOL)

    def wheel(time):
        return HR_LEG * e(lug_angle(time) + HR_LEG_OFFSET)

    assert_close(chain_point_rate(res, [4]), d1(wheel, t), "wheel axle velocity",
                 RATE_RTOL)
    # the law starts and ends at rest
    for name in ("r2", "a1", "a4"):
        assert res.rate(name)[[0, -1]] == pytest.approx([0, 0], abs=1e-15)


def test_hydraulic_rocker_dense_copy_agrees():
    """A 10x denser copy (same law and time span) gives the same leg motion."""
    model = load("hydraulic_rocker.yaml")
    dense = mechloop.Model.from_dict({
        **model.model_dump(mode="json", exclude_defaults=True),
        "positions": 400,
        "time": {"table": {0: 0, 400: 4.0}},
        "arguments": {1: {"law": "poly345", "start": [0, 0.60], "end": [400, 0.85]}},
    })
    res = mechloop.solve(dense)
    t = np.arange(401) * 0.01
    assert not res.broken.any()
    assert_angles(res.value("a1"), lug_angle(t), "dense lug angle")
    assert_close(res.rate("a1"), d1(lug_angle, t), "dense leg speed", RATE_RTOL)


# ------------------------------------------------------------------- sparse_argument.yaml

SP_LEVER, SP_FRAME, SP_BODY = 0.25, 0.55, 0.45
#: KDAM seed 000, table 3.2: the sparse table {3: 0.12, 6: 0.26, 10: 0.18} over 12 positions
KDAM_TABLE_3_2 = [0.12, 0.12, 0.12, 0.12, 0.12 + 0.14 / 3, 0.12 + 0.28 / 3, 0.26,
                  0.24, 0.22, 0.20, 0.18, 0.18, 0.18]


def lever_angle_of_length(length):
    """Law of cosines in triangle O, G = (0.55, 0), P: a1 = γ."""
    return np.arccos((SP_LEVER**2 + SP_FRAME**2 - length**2) / (2 * SP_LEVER * SP_FRAME))


def test_sparse_argument_is_kdam_table_3_2():
    res = mechloop.solve(load("sparse_argument.yaml"))
    assert len(KDAM_TABLE_3_2) == 13
    assert_close(res.arguments[1], KDAM_TABLE_3_2, "argument 1", 1e-12)
    frame = res.to_frame()
    assert_close(frame["arg1 [m]"], KDAM_TABLE_3_2, "arg1 column", 1e-12)
    assert_close(frame["time [s]"], np.arange(13) * 0.1, "time column", 1e-15)
    assert_close(frame["r2 [m]"], np.add(KDAM_TABLE_3_2, SP_BODY), "r2 = stroke + body",
                 1e-12)


def test_sparse_argument_positions_by_law_of_cosines():
    res = mechloop.solve(load("sparse_argument.yaml"))
    length = np.add(KDAM_TABLE_3_2, SP_BODY)
    a1 = lever_angle_of_length(length)
    assert_angles(res.value("a1"), a1, "lever angle")
    pin = SP_LEVER * e(a1)
    assert_close(np.array(res.point([1])), pin, "actuator pin P", POS_RTOL)
    assert_angles(res.value("a2"), np.arctan2(-pin[1], SP_FRAME - pin[0]), "actuator angle")
    # as the comment header says: 81.6 deg at the shortest stroke, 120.4 deg at the longest
    assert np.degrees(a1[0]) == pytest.approx(81.6, abs=0.05)
    assert np.degrees(a1[6]) == pytest.approx(120.4, abs=0.05)


def test_sparse_argument_rates_follow_the_chain_rule():
    """Whatever derivative the table gets, the lever's rate is dγ/dL times the actuator's
    rate and its acceleration γ''(L) L̇² + γ'(L) L̈ (γ(L) by the law of cosines)."""
    res = mechloop.solve(load("sparse_argument.yaml"))
    length = np.add(KDAM_TABLE_3_2, SP_BODY)
    dl, ddl = res.rate("r2"), res.accel("r2")
    slope = d1(lever_angle_of_length, length, 1e-4)
    curve = d2(lever_angle_of_length, length, 1e-3)
    assert_close(res.rate("a1"), slope * dl, "lever speed", RATE_RTOL)
    assert_close(res.accel("a1"), curve * dl**2 + slope * ddl, "lever acceleration",
                 ACCEL_RTOL)


def test_sparse_argument_rate_is_the_slope_of_the_linear_fill():
    """Where the filled table is a straight line through positions k-1, k, k+1, the
    argument's rate is that line's slope: 0 where it holds (KDAM: "the first value holds",
    "the last value holds"), 0.4667 m/s from position 3 to 6, -0.2 m/s from 6 to 10."""
    res = mechloop.solve(load("sparse_argument.yaml"))
    step = 0.1  # s per position
    expected = {1: 0.0, 2: 0.0, 4: 0.14 / 0.3, 5: 0.14 / 0.3, 7: -0.2, 8: -0.2, 9: -0.2,
                11: 0.0}
    got = {k: float(res.rate("r2")[k]) for k in expected}
    table = np.array(KDAM_TABLE_3_2)
    for k in expected:  # the reference itself: the fill is straight through k-1, k, k+1
        assert table[k + 1] - table[k] == pytest.approx(table[k] - table[k - 1], abs=1e-15)
        assert expected[k] == pytest.approx((table[k + 1] - table[k - 1]) / (2 * step))
    assert got == pytest.approx(expected, abs=1e-9)
