"""mechloop structure of a model with spatial contours (issue 17): links and pairs inferred
from the contours and bodies, the class of each pair from the relative motion of its links,
the Somov–Malyshev count W = 6n − 5p5 − 4p4 − 3p3 − 2p2 − p1, the idle spin of an RSSR
coupler, and the spherical four-bar as an overconstrained chain (3 redundant constraints)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mechloop.errors import ModelError
from mechloop.model.load import load_model
from mechloop.solve.kinematics import solve
from mechloop.spatial.points import Placement3
from mechloop.structure.spatial import SpatialPair, count, spatial_structure
from mechloop.structure.spatial_text import spatial_structure_lines

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "spatial"


@pytest.fixture(scope="module")
def rssr():
    model = load_model(EXAMPLES / "rssr_dynamics.yaml")
    return model, spatial_structure(model)


def test_rssr_pairs_are_two_revolutes_about_the_model_axes_and_two_balls(rssr):
    _, s = rssr
    pairs = {p.name: p for p in s.pairs}
    assert sorted(pairs) == ["R0_1", "R0_3", "S1_2", "S2_3"]
    # the crank turns in the XY plane (β1 = 0): axis Z through O; the output crank keeps
    # α3 = 0 and turns by β3: axis Y through D = r4 (cos α4 cos β4, sin α4, cos α4 sin β4)
    np.testing.assert_allclose(np.abs(pairs["R0_1"].axis), [0, 0, 1], atol=1e-12)
    np.testing.assert_allclose(pairs["R0_1"].point, 0.0, atol=1e-15)
    np.testing.assert_allclose(np.abs(pairs["R0_3"].axis), [0, 1, 0], atol=1e-12)
    a4, b4 = np.radians(30), np.radians(45)
    d = 0.1 * np.array([np.cos(a4) * np.cos(b4), np.sin(a4), np.cos(a4) * np.sin(b4)])
    np.testing.assert_allclose(pairs["R0_3"].point, d, atol=1e-15)
    np.testing.assert_allclose(pairs["S1_2"].point, [0.04, 0, 0], atol=1e-15)
    # B is where the coupler (length 120 mm) meets the output crank (80 mm from D)
    b = pairs["S2_3"].point
    assert np.linalg.norm(b - [0.04, 0, 0]) == pytest.approx(0.12, rel=1e-12)
    assert np.linalg.norm(b - d) == pytest.approx(0.08, rel=1e-12)


def test_rssr_mobility_is_two_with_the_coupler_spin_idle(rssr):
    _, s = rssr
    assert (s.n, s.p[5], s.p[3]) == (3, 2, 2)
    assert s.W == 6 * 3 - 5 * 2 - 3 * 2 == 2
    assert s.idle == (2,) and s.W - len(s.idle) == s.inputs == 1 and s.q == 0
    assert s.family is None


def test_spherical_four_bar_is_overconstrained_by_three(tmp_path):
    """The spherical four-bar of the example, its pairs as the textbook draws them: four
    revolutes whose axes all pass through the sphere's centre O (OA, OB, the input's Y
    axis and the output's axis along vector 4), taken from the solved geometry."""
    model = load_model(EXAMPLES / "spherical_four_bar.yaml")
    place = Placement3(solve(model))
    o = np.zeros(3)
    a, b = place.head(1).p[:, 5], place.head(2).p[:, 5]
    d = place.tail(3).p[:, 5]

    def pin(links, at, axis):
        axis = np.asarray(axis, dtype=float)
        return SpatialPair("R", "R", links, at, axis / np.linalg.norm(axis))

    pairs = [pin((0, 1), o, [0, 1, 0]), pin((1, 2), a, a - o), pin((2, 3), b, b - o),
             pin((0, 3), d, d - o)]
    s = count((1, 2, 3), pairs, {1: False, 2: False, 3: False}, 1)
    assert s.W == 6 * 3 - 5 * 4 == -2
    assert s.family == "spherical" and s.W_family == 3 * 3 - 2 * 4 == 1
    assert s.q == 3
    lines = spatial_structure_lines(s, model)
    assert any("3 redundant constraint(s)" in line for line in lines)
    assert any("Dobrovolsky" in line and "= 1" in line for line in lines)
    # moved off O, the output's axis no longer meets the others: no spherical family
    pairs[3] = pin((0, 3), d + np.array([0, 0, 0.01]), d - o)
    assert count((1, 2, 3), pairs, {1: False, 2: False, 3: False}, 1).family is None


def test_structure_text_in_russian_says_the_count_and_the_idle_spin(rssr):
    model, s = rssr
    text = "\n".join(spatial_structure_lines(s, model, "ru"))
    assert "формула Сомова–Малышева" in text and "= 2; число входов: 1" in text
    assert "местные (пассивные) подвижности: 1" in text
    assert "группы Ассура" in text and "Pr10" in text
    assert "61,2372" in text


def test_cli_structure_of_spatial_models(tmp_path):
    from typer.testing import CliRunner

    from mechloop.cli import app

    run = CliRunner().invoke(app, ["structure", str(EXAMPLES / "rssr_dynamics.yaml")])
    assert run.exit_code == 0, run.output
    assert "idle (passive) degrees of freedom: 1" in run.output
    assert "position plans" not in run.output
    run = CliRunner().invoke(app, ["structure", str(EXAMPLES / "swashplate.yaml")])
    assert run.exit_code == 2 and "the model has no bodies" in run.output
    assert "position plans" not in run.output


def test_a_model_without_bodies_is_refused():
    with pytest.raises(ModelError, match="no bodies"):
        spatial_structure(load_model(EXAMPLES / "swashplate.yaml"))


def test_web_structure_panel_shows_the_spatial_structure():
    from mechloop.web.exports import structure

    path = EXAMPLES / "rssr_dynamics.yaml"
    shown = structure(path.read_text(encoding="utf-8"), path, path.parent, "en")
    assert shown["mechanism"] is None
    assert "W = 6n − 5p5" in shown["description"] and "= 2; inputs: 1" in shown["description"]


LANDING_GEAR_BODIES = """
bodies:
  1: {name: strut, vectors: [3, 4]}
  2: {name: barrel, vectors: [2], ends: {2: tail}}
  3: {name: piston rod, vectors: [2], ends: {2: head}}
"""


def test_landing_gear_cylinder_between_ball_joints_has_two_idle_spins(tmp_path):
    """The skewed-axis landing gear with its strut, the cylinder's barrel and its rod as
    bodies: the strut turns about the normal of its plane β = 20° (the hinge axis
    (−sin 20°, 0, cos 20°)), the barrel and the rod slide and turn on one line (C) between
    two ball joints (S): W = 6·3 − 5 − 4 − 3·2 = 3, of which the spins of the barrel and
    of the rod about the cylinder's line are idle, 1 working = the cylinder's drive."""
    text = (EXAMPLES / "landing_gear_skewed_axis.yaml").read_text(encoding="utf-8")
    path = tmp_path / "gear.yaml"
    path.write_text(text + LANDING_GEAR_BODIES, encoding="utf-8")
    s = spatial_structure(load_model(path))
    kinds = sorted(p.name for p in s.pairs)
    assert kinds == ["C2_3", "R0_1", "S0_2", "S1_3"]
    hinge = next(p for p in s.pairs if p.kind == "R")
    b = np.radians(20)
    np.testing.assert_allclose(hinge.axis * np.sign(hinge.axis[2]),
                               [-np.sin(b), 0, np.cos(b)], atol=1e-9)
    assert s.W == 6 * 3 - 5 - 4 - 3 * 2 == 3
    assert s.idle == (2, 3) and s.W - len(s.idle) == s.inputs == 1 and s.q == 0


def test_a_body_the_contours_reach_only_through_vectors_of_no_body_is_named(tmp_path):
    """The inclined-axis gear's strut meets the hinge and the cylinder's lug only through
    the auxiliary vectors of its plane: no pair can be found, and the body is named."""
    text = (EXAMPLES / "landing_gear_inclined_axis.yaml").read_text(encoding="utf-8")
    path = tmp_path / "gear.yaml"
    path.write_text(text + LANDING_GEAR_BODIES.replace("[3, 4]", "[5, 8]")
                    .replace("[2]", "[3]").replace("{2:", "{3:"), encoding="utf-8")
    with pytest.raises(ModelError, match="body 1 is joined to the ground by no pair"):
        spatial_structure(load_model(path))


def test_the_planar_analysis_refuses_a_spatial_model_with_the_fix():
    from mechloop.errors import HintedError
    from mechloop.structure import analyze

    with pytest.raises(HintedError, match="does not apply to a model with spatial") as info:
        analyze(load_model(EXAMPLES / "rssr_dynamics.yaml"))
    assert "spatial_structure" in info.value.hint
