"""examples/roof_support.yaml, the lemniscate powered roof support, checked against
independent plain-NumPy geometry and statics.

The reference never runs mechloop.  It restates the drawing in the example's header (pivot
coordinates, link lengths, masses) and places the linkage by circle intersection for a
given leg length: the shield pin B is on the circle of radius ℓ about the leg's base pivot D
and on the circle of the front link about O2; the shield pin A is on the circle of radius L
about B and on the circle of the rear link about O1; the canopy tip E is on the line A->B,
1.72 m past B.  Derivatives with respect to the leg length are central finite differences
of these reference positions (step 1e-5 m; truncation and rounding both below 1e-9 of the
value).  The statics references are virtual work: a massless leg that holds the mechanism
still does the work the loads do not, ``F_leg·dℓ = −Σ F·dz``.
"""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app

PATH = Path(__file__).resolve().parents[1] / "examples" / "roof_support.yaml"

# The drawing (m): pivots on the base, link lengths, the leg's stroke over positions 0..40.
D = np.array([0.0, 0.15])       # leg base pivot
O1 = np.array([0.30, 0.20])     # rear lemniscate link on the base
O2 = np.array([1.605, 0.725])   # front lemniscate link on the base
FRONT, REAR = 1.07, 0.78        # O2-B and O1-A
SHIELD, CANOPY = 0.85, 1.72     # |AB| (the seed's L) and |BE| along the shield line
LEG0, LEG1, N = 1.00, 1.60, 40  # leg length at positions 0 and N (linear table)
ROOF = 2000e3                   # N, straight down on the canopy tip E
G = 9.81
MASS = {1: 6000.0, 2: 650.0, 3: 500.0}  # shield + canopy, front link, rear link (kg)
SHIELD_CENTRE = 0.5             # m from B towards E

POS_TOL = 1e-9                  # m
FORCE_RTOL = 1e-6
H = 1e-5                        # finite-difference step in the leg length (m)


# ------------------------------------------------------------------ the reference


def circle_intersection(p, rp, q, rq, *, left: bool) -> np.ndarray:
    """The intersection of circle (p, rp) with circle (q, rq) on the left (or right) of the
    line p -> q; shapes (2, n)."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    dist = np.hypot(dx, dy)
    along = (rp**2 - rq**2 + dist**2) / (2 * dist)
    height = np.sqrt(rp**2 - along**2) * (1.0 if left else -1.0)
    return np.array([p[0] + (along * dx - height * dy) / dist,
                     p[1] + (along * dy + height * dx) / dist])


def reference(leg) -> dict[str, np.ndarray]:
    """Pins A, B and the tip E, shape (2, n), for leg lengths ``leg`` (m)."""
    leg = np.atleast_1d(np.asarray(leg, float))
    ones = np.ones_like(leg)
    b = circle_intersection(D[:, None] * ones, leg, O2[:, None] * ones, FRONT, left=True)
    a = circle_intersection(b, SHIELD, O1[:, None] * ones, REAR, left=False)
    e = b + CANOPY * (b - a) / SHIELD
    return {"A": a, "B": b, "E": e}


def legs() -> np.ndarray:
    """The leg length at every position: the linear table 1.00 m -> 1.60 m."""
    return LEG0 + (LEG1 - LEG0) * np.arange(N + 1) / N


def d_dleg(point: str, coordinate: int, leg: np.ndarray) -> np.ndarray:
    """Central difference of a reference coordinate with respect to the leg length."""
    up, down = reference(leg + H)[point], reference(leg - H)[point]
    return (up[coordinate] - down[coordinate]) / (2 * H)


def xy(z: np.ndarray) -> np.ndarray:
    return np.array([z.real, z.imag])


# ------------------------------------------------------------------ fixtures


@pytest.fixture(scope="module")
def data() -> dict:
    return yaml.safe_load(PATH.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def dynamic() -> mechloop.DynamicResults:
    return mechloop.solve_dynamics(mechloop.load_model(PATH))


def variant(data: dict, *, gravity: bool = True, masses: bool = True) -> mechloop.Model:
    """The example built from its own YAML data, without gravity and/or without masses."""
    doc = copy.deepcopy(data)
    if not gravity:
        doc.pop("gravity")
    if not masses:
        for body in doc["bodies"].values():
            for key in ("mass", "inertia", "center"):
                body.pop(key, None)
    return mechloop.Model.from_dict(doc)


# ------------------------------------------------------------------ the tests


def test_solves_over_the_whole_stroke_without_a_chain_break(tmp_path):
    model = mechloop.load_model(PATH)
    res = mechloop.solve(model)
    assert not res.broken.any(), "; ".join(b.describe() for b in res.breaks)
    assert res.breaks == ()
    np.testing.assert_allclose(res.arguments[1], legs(), rtol=0, atol=1e-15)

    runner = CliRunner()
    check = runner.invoke(app, ["check", str(PATH)])
    assert check.exit_code == 0, check.output
    assert "3 moving bodies, 4 pairs" in check.output
    out = tmp_path / "r.csv"
    result = runner.invoke(app, ["solve", str(PATH), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "chain break" not in result.output
    frame = pd.read_csv(out)
    assert len(frame) == N + 1
    assert not frame["chain_break"].any()
    assert np.isfinite(frame["F_bal [N]"]).all()


def test_tip_trajectory_equals_circle_intersection(dynamic):
    ref = reference(dynamic.kinematics.value("r7"))
    np.testing.assert_allclose(dynamic.kinematics.value("r7"), legs(), rtol=0, atol=1e-15)
    placement = dynamic.placement
    # E as the library places it: contour 3 starts at O2 (start: {tail: 3})
    tip = xy(placement.tail(12).z)
    assert np.abs(tip - ref["E"]).max() <= POS_TOL
    # E from the Pl1 closing vector alone: E = O2 - r12
    res = dynamic.kinematics
    closing = res.value("r12") * np.array([np.cos(res.value("a12")), np.sin(res.value("a12"))])
    assert np.abs(O2[:, None] - closing - ref["E"]).max() <= POS_TOL
    # the shield pins, placed through contours 1 and 2 (start: [0, 0.15] and {tail: 1})
    assert np.abs(xy(placement.head(3).z) - ref["B"]).max() <= POS_TOL
    assert np.abs(xy(placement.head(7).z) - ref["B"]).max() <= POS_TOL
    assert np.abs(xy(placement.head(8).z) - ref["A"]).max() <= POS_TOL
    assert np.abs(xy(placement.tail(5).z) - O1[:, None]).max() <= POS_TOL


def test_tip_moves_nearly_vertically(dynamic, record_property):
    """The lemniscate property.  With the example's dimensions the reference gives a
    horizontal wander max|x - x0| = 8.0 mm while the tip rises 1.123 m; changing any one
    dimension by its 5 mm rounding step keeps it under 9.5 mm.  So: under 10 mm, and under
    1 % of the vertical stroke."""
    x, y = xy(dynamic.placement.tail(12).z)
    assert np.all(np.diff(y) > 0), "the tip rises as the leg extends"
    deviation = float(np.abs(x - x[0]).max())
    stroke = float(y[-1] - y[0])
    record_property("tip_wander_m", deviation)
    record_property("tip_stroke_m", stroke)
    print(f"canopy tip: rises {y[0]:.3f} -> {y[-1]:.3f} m ({stroke:.3f} m), "
          f"horizontal wander max|x - x0| = {deviation * 1e3:.2f} mm "
          f"({deviation / stroke:.2%} of the stroke)")
    assert stroke > 1.1
    assert deviation < 0.010
    assert deviation < 0.01 * stroke


def test_leg_force_is_virtual_work_of_the_roof_load(data):
    dyn = mechloop.solve_dynamics(variant(data, gravity=False))
    assert dyn.static, "no model time: a static force analysis"
    frame = dyn.to_frame()
    leg = legs()
    expected = ROOF * d_dleg("E", 1, leg)  # F·δℓ + (−ROOF)·δy_E = 0
    np.testing.assert_allclose(frame["F_bal [N]"].to_numpy(), expected, rtol=FORCE_RTOL,
                               atol=0)
    assert np.all(expected > 0), "the leg pushes against the roof"


def test_leg_force_with_the_weights_is_virtual_work(dynamic):
    leg = legs()
    ref, up, down = reference(leg), reference(leg + H), reference(leg - H)

    def centres(r):
        unit = (r["E"] - r["B"]) / CANOPY
        return {1: r["B"] + SHIELD_CENTRE * unit, 2: (O2[:, None] + r["B"]) / 2,
                3: (O1[:, None] + r["A"]) / 2}

    c_up, c_down = centres(up), centres(down)
    expected = ROOF * (up["E"][1] - down["E"][1]) / (2 * H)
    for body, mass in MASS.items():
        expected = expected + mass * G * (c_up[body][1] - c_down[body][1]) / (2 * H)
    np.testing.assert_allclose(dynamic.to_frame()["F_bal [N]"].to_numpy(), expected,
                               rtol=FORCE_RTOL, atol=0)
    # the library's centres of mass are where the reference puts them
    for body, centre in centres(ref).items():
        np.testing.assert_allclose(dynamic.to_frame()[f"xS{body} [m]"], centre[0], rtol=0,
                                   atol=POS_TOL)
        np.testing.assert_allclose(dynamic.to_frame()[f"yS{body} [m]"], centre[1], rtol=0,
                                   atol=POS_TOL)


def _off_link(dyn: mechloop.DynamicResults) -> dict[tuple[int, int], float]:
    """For each pin of a lemniscate link: the largest angle (rad) between the reaction and
    the link's line, after checking the pin is where the reference puts it."""
    ref = reference(legs())
    pins = {(0, 2): O2[:, None], (1, 2): ref["B"], (0, 3): O1[:, None], (1, 3): ref["A"]}
    link_angle = {2: dyn.kinematics.value("a3"), 3: dyn.kinematics.value("a9")}
    out = {}
    for reaction in dyn.forces.reactions.values():
        bodies = reaction.pair.bodies
        assert bodies in pins, f"unexpected pair {reaction.pair.name} {bodies}"
        assert np.abs(xy(reaction.point.z) - pins[bodies]).max() <= POS_TOL
        assert np.abs(reaction.force).min() > 1e5, "a link carries the roof load"
        phi = np.angle(reaction.force) - link_angle[bodies[1]]
        off = np.abs((phi + np.pi / 2) % np.pi - np.pi / 2)  # distance to 0 or 180 deg
        out[bodies] = float(off.max())
    assert set(out) == set(pins)
    return out


def test_massless_lemniscate_links_are_two_force_members(data):
    massless = mechloop.solve_dynamics(variant(data, masses=False))
    assert massless.mechanism.total_mass == 0
    for pair, off in _off_link(massless).items():
        assert off <= 1e-9, f"reaction {pair} is {np.degrees(off):.3g} deg off the link"
    # with their own weight the links are not two-force members: the check can tell
    heavy = mechloop.solve_dynamics(variant(data))
    assert max(_off_link(heavy).values()) > 1e-4
