"""mechloop structure of a spatial model from its declared joints (``joints:``) and of a
spatial model without bodies (links from its vectors), issue 17.

The counts are derived by hand in each test's docstring and checked against a second,
independent analysis: the force analysis of the same file (its Newton–Euler system's rank
``r`` over ``K`` unknowns and ``6B`` equations: a chain with ``q`` redundant constraints
is statically indeterminate by ``K − r = q``, and each idle spin is one equation with no
unknown, ``6B − r``), the pairs the contours and bodies give when no joint is named, and
the distances of the revolute axes from the sphere's centre computed here at every
position."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.model.load import load_model
from mechloop.solve.kinematics import solve
from mechloop.spatial.dynamics import solve_spatial_dynamics
from mechloop.spatial.points import Placement3
from mechloop.structure.spatial import SpatialPair, count, spatial_structure
from mechloop.structure.spatial_text import spatial_structure_lines

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "spatial"


def test_rssr_from_its_joints_two_revolutes_two_balls_and_one_idle_spin():
    """The RSSR of ``rssr_reactions.yaml``: joints O (revolute), A, B (spherical), D
    (revolute) between the ground 0, the crank 1, the coupler 2 and the output 3:
    n = 3, p5 = 2, p3 = 2, W = 6n − 5p5 − 3p3 = 18 − 10 − 6 = 2; the coupler turns
    about the line AB through its two balls with no pair holding it (one idle spin), so
    the working mobility 2 − 1 = 1 is the one input and q = 0.  The force analysis agrees:
    K = 5 + 3 + 3 + 5 + 1 (drive) = 17 unknowns, rank 17 (determinate: q = 0) of
    6·3 = 18 equations (one idle motion: the coupler's spin about AB)."""
    model = load_model(EXAMPLES / "rssr_reactions.yaml")
    s = spatial_structure(model)
    assert s.source == "joints"
    assert [(p.name, p.kind, p.klass, p.links) for p in s.pairs] == [
        ("O", "R", 5, (0, 1)), ("A", "S", 3, (1, 2)), ("B", "S", 3, (2, 3)),
        ("D", "R", 5, (0, 3))]
    assert (s.n, s.p[5], s.p[4], s.p[3]) == (3, 2, 0, 2)
    assert s.W == 6 * 3 - 5 * 2 - 3 * 2 == 2
    assert s.idle == (2,) and s.W - len(s.idle) == s.inputs == 1 and s.q == 0
    assert s.family is None
    reactions = solve_spatial_dynamics(model).reactions
    assert reactions.unknowns == 17 and reactions.rank == 17  # determinate: q = 0
    assert 6 * 3 - reactions.rank == len(reactions.idle) == len(s.idle) == 1
    assert "line of joints A, B" in reactions.idle[0]
    # the same points and axes as the pairs the contours and bodies give (no joints:)
    inferred = spatial_structure(load_model(EXAMPLES / "rssr_dynamics.yaml"))
    found = {p.links: p for p in inferred.pairs}
    for pair in s.pairs:
        twin = found[pair.links]
        assert twin.kind == pair.kind
        np.testing.assert_allclose(twin.point, pair.point, rtol=0, atol=1e-12)
        if pair.axis is not None:
            assert abs(float(twin.axis @ pair.axis)) == pytest.approx(1.0, abs=1e-12)
    text = "\n".join(spatial_structure_lines(s, model))
    assert "the pairs are the model's joints (joints:)" in text
    assert "  A: spherical pair (class 3) of links 1 and 2 at (40; 0; 0) mm" in text
    ru = "\n".join(spatial_structure_lines(s, model, "ru"))
    assert "пары взяты из модели (joints:)" in ru and "местные (пассивные) подвижности: 1" in ru


def test_spherical_four_bar_from_its_joints_is_spherical_with_three_redundant_constraints():
    """``spherical_four_bar_joints.yaml``: four revolutes O1, A, B, O3 between the ground,
    the crank 1, the coupler 2 and the output 3.  The spatial count: n = 3, p5 = 4,
    W = 6·3 − 5·4 = −2 for a chain that moves with one degree of freedom, so
    q = 1 − (−2) = 3 redundant constraints; every axis passes through the sphere's centre
    O at every position: a spherical mechanism (3 common constraints), Dobrovolsky's
    W = 3n − 2p5 = 9 − 8 = 1.  The force analysis of the same file is statically
    indeterminate by exactly q: 4·5 + 1 = 21 unknowns, rank 18 (= 6·3)."""
    path = EXAMPLES / "spherical_four_bar_joints.yaml"
    model = load_model(path)
    s = spatial_structure(model)
    assert s.source == "joints" and [p.kind for p in s.pairs] == ["R"] * 4
    assert s.W == 6 * 3 - 5 * 4 == -2
    assert s.family == "spherical" and s.W_family == 3 * 3 - 2 * 4 == 1
    assert s.q == 3 and s.idle == ()
    with pytest.raises(ModelError, match=r"statically indeterminate: 3 reaction "):
        solve_spatial_dynamics(model)
    # every axis through O, at every position, computed here from the solved geometry
    results = solve(model)
    place = Placement3(results)
    for pair in s.pairs:
        assert pair.points.shape == pair.axes.shape == (3, model.positions + 1)
        off = np.linalg.norm(np.cross(-pair.points, pair.axes, axis=0), axis=0)
        assert off.max() <= 1e-12 * 0.1
    np.testing.assert_allclose(s.pairs[1].points, place.head(1).p, rtol=0, atol=1e-15)
    lines = spatial_structure_lines(s, model)
    assert any("Dobrovolsky's formula W = 3n − 2p5 = 3·3 − 2·4 = 1" in x for x in lines)
    assert any("overconstrained: 3 redundant constraint(s)" in x for x in lines)
    # decided at every position: an axis through O at the first position only is not
    moved = list(s.pairs)
    a = moved[1]
    points = a.points.copy()
    points[:, 10:] += 0.01 * np.cross(a.axes[:, 10:], [[0.0], [0.0], [1.0]], axis=0)
    moved[1] = SpatialPair(a.name, "R", a.links, a.point, a.axis, points, a.axes)
    assert count(s.links, moved, {}, 1).family is None
    first = [SpatialPair(p.name, "R", p.links, p.point, p.axis) for p in moved]
    assert count(s.links, first, {}, 1).family == "spherical"  # one position fooled


def test_a_joint_the_motion_contradicts_is_refused_at_its_line(tmp_path):
    """The output crank of the RSSR turns about Y; a revolute D about Z holds a moment
    about Y and would do work: refused at D's line with the fix.  A ball A placed at the
    crank's pivot O (the coupler's end is at A) is refused at its ``at``."""
    text = (EXAMPLES / "rssr_reactions.yaml").read_text(encoding="utf-8")
    pin = "D: {type: revolute, bodies: [0, 3], at: {tail: 3}, axis: [0, 1, 0]}"
    assert pin in text
    path = tmp_path / "bad_axis.yaml"
    path.write_text(text.replace(pin, pin.replace("[0, 1, 0]", "[0, 0, 1]")),
                    encoding="utf-8")
    with pytest.raises(ModelError) as caught:
        spatial_structure(load_model(path))
    assert [p.path for p in caught.value.problems] == [("joints", "D", "type")]
    run = CliRunner().invoke(app, ["structure", str(path)])
    assert run.exit_code == 2 and "Traceback" not in run.output
    line = next(i for i, text in enumerate(path.read_text().splitlines(), 1)
                if text.strip().startswith("D:"))
    assert re.search(rf"bad_axis\.yaml:{line}\b.*joints\.D\.type", run.output)
    assert "turn relative to each other about an axis its moment holds" in run.output
    assert "give the axis they turn about" in run.output
    ball = "A: {type: spherical, bodies: [1, 2], at: {head: 1}}"
    assert ball in text
    path = tmp_path / "bad_ball.yaml"
    path.write_text(text.replace(ball, ball.replace("head", "tail")), encoding="utf-8")
    with pytest.raises(ModelError, match="move apart at its point") as caught:
        spatial_structure(load_model(path))
    assert [p.path for p in caught.value.problems] == [("joints", "A", "at")]
    run = CliRunner().invoke(app, ["structure", str(path), "--lang", "ru"])
    assert run.exit_code == 2 and "joints.A.at" in run.output and "пары A" in run.output


def test_a_model_without_bodies_gets_its_links_from_its_vectors():
    """``rssr.yaml`` has no bodies: its vectors 1, 2, 3 (constant lengths) are the links
    1, 2, 3 and the constant vector 4 the ground; the crank and the output crank turn about
    fixed axes (R), the one-vector coupler meets them in balls (S): n = 3, p5 = 2, p3 = 2,
    W = 18 − 10 − 6 = 2 with the coupler's idle spin — the structure of
    ``rssr_dynamics.yaml``, whose bodies are those vectors."""
    model = load_model(EXAMPLES / "rssr.yaml")
    s = spatial_structure(model)
    assert s.source == "vectors" and s.vector_links == {1: (1,), 2: (2,), 3: (3,)}
    assert s.W == 2 and s.idle == (2,) and s.q == 0
    bodies = spatial_structure(load_model(EXAMPLES / "rssr_dynamics.yaml"))
    assert [(p.name, p.links) for p in s.pairs] == [(p.name, p.links) for p in bodies.pairs]
    for mine, theirs in zip(s.pairs, bodies.pairs, strict=True):
        np.testing.assert_allclose(mine.point, theirs.point, rtol=0, atol=1e-15)
    run = CliRunner().invoke(app, ["structure", str(EXAMPLES / "rssr.yaml"), "--lang", "ru"])
    assert run.exit_code == 0, run.output
    assert "звенья взяты из её векторов (звено 1: векторы 1; звено 2: векторы 2; звено 3: " \
        "векторы 3)" in run.output
    assert "= 2; число входов: 1" in run.output


def test_a_model_without_bodies_whose_contours_do_not_define_links_is_refused():
    """The swashplate's piston stroke 2 and the plate's coordinates 4, 5 change length:
    which links hold their ends the contours do not say — each refused at its line with
    the fix (name the bodies)."""
    path = EXAMPLES / "swashplate.yaml"
    with pytest.raises(ModelError) as caught:
        spatial_structure(load_model(path))
    assert [p.path for p in caught.value.problems] == [("vectors", v, "r") for v in (2, 4, 5)]
    run = CliRunner().invoke(app, ["structure", str(path)])
    assert run.exit_code == 2
    line = next(i for i, text in enumerate(path.read_text().splitlines(), 1)
                if text.strip().startswith("2:"))
    assert f"swashplate.yaml:{line}, vectors[2].r: the model has no bodies, and vector 2 " \
        "changes length" in run.output
    assert "fix: add bodies: naming the vectors of each link" in run.output


def test_the_web_structure_panel_of_spatial_models_with_and_without_bodies():
    """The web page's structure: the printed Somov–Malyshev text for a spatial model
    (``spatial`` true, so the page does not say "no bodies"), without bodies from the
    vectors when they define the links, else the contours' description alone."""
    from mechloop.web.exports import structure

    for name, spatial in (("rssr_reactions", True), ("rssr", True), ("swashplate", False)):
        path = EXAMPLES / f"{name}.yaml"
        shown = structure(path.read_text(encoding="utf-8"), path, path.parent, "ru")
        assert shown["mechanism"] is None and shown.get("spatial", False) is spatial
        assert ("формула Сомова–Малышева" in shown["description"]) is spatial
        assert "контур 1" in shown["description"]


LANDING_GEAR_JOINTS = """
bodies:
  1: {name: strut, vectors: [3, 4]}
  2: {name: barrel, vectors: [2], ends: {2: tail}}
  3: {name: piston rod, vectors: [2], ends: {2: head}}
joints:
  H: {type: revolute, bodies: [0, 1], at: {tail: 3}, axis: [-0.3420201433256687, 0,
      0.9396926207859084]}
  G: {type: spherical, bodies: [0, 2], at: {tail: 2}}
  C: {type: cylindrical, bodies: [2, 3], axis: 2}
  P: {type: spherical, bodies: [3, 1], at: {head: 2}}
"""


def test_landing_gear_from_its_joints_cylinder_between_balls(tmp_path):
    """The skewed-axis landing gear with its joints: the strut's hinge H (revolute about
    the normal (−sin 20°, 0, cos 20°) of its swing plane), the barrel's ball G on the
    airframe, the barrel and the rod in a cylindrical pair C along the cylinder (class
    IV), the rod's ball P on the strut: W = 6·3 − 5·1 − 4·1 − 3·2 = 3, of which the
    barrel's and the rod's spins about the cylinder's line (their balls and the sleeve's
    axis on one line) are idle: 1 working = the cylinder's drive, as the pairs the
    contours and bodies give (tests/test_structure_spatial.py)."""
    text = (EXAMPLES / "landing_gear_skewed_axis.yaml").read_text(encoding="utf-8")
    path = tmp_path / "gear.yaml"
    path.write_text(text + LANDING_GEAR_JOINTS, encoding="utf-8")
    s = spatial_structure(load_model(path))
    assert [(p.name, p.kind, p.klass) for p in s.pairs] == [
        ("H", "R", 5), ("G", "S", 3), ("C", "C", 4), ("P", "S", 3)]
    assert (s.p[5], s.p[4], s.p[3]) == (1, 1, 2)
    assert s.W == 6 * 3 - 5 - 4 - 3 * 2 == 3
    assert s.idle == (2, 3) and s.W - len(s.idle) == s.inputs == 1 and s.q == 0
    inferred = load_model(path).model_copy(update={"joints": None})
    same = spatial_structure(inferred)
    assert (same.W, same.idle, same.q) == (s.W, s.idle, s.q)
