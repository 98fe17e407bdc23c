"""Models with spatial contours end to end (issue 17): the model file, the solver, the CLI.

Checked against independent references: the planar solver (a planar model written as
spatial), the RSSR and spherical four-bar input–output equations in closed form over the
whole cycle, finite differences of the solver's own positions for the exact rates, the
3-D closure of every contour, and located errors for bad input.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.model.load import model_from_data
from mechloop.spatial.contour import classify, follow_branch
from mechloop.spatial.dynamics import solve_spatial_dynamics

ROOT = Path(__file__).resolve().parents[1]
SPATIAL = ROOT / "examples" / "spatial"
EXAMPLES = sorted(SPATIAL.glob("*.yaml"))


def _data(path: Path) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8"))


def _solve(data: dict, **kwargs):
    return mechloop.solve(model_from_data(copy.deepcopy(data)), **kwargs)


# ------------------------------------------------------------ planar models as spatial
def _as_spatial(data: dict, extra: dict[int, int]) -> dict:
    """``data`` with the contours ``extra`` (index: vector) spatial, that vector's β the
    contour's third unknown."""
    out = copy.deepcopy(data)
    for ci, vector in extra.items():
        out["contours"][ci]["spatial"] = True
        out["vectors"][vector]["b"] = "function"
    return out


#: A planar model written as spatial gives the planar results to this (relative to each
#: column's largest value; docs/spatial.md quotes it).
PLANAR_RTOL = 1e-12


def _assert_same(spatial, planar, rtol: float = PLANAR_RTOL) -> None:
    for name in planar.varying():
        for what in ("values", "rates", "accels"):
            got, want = getattr(spatial, what)[name], getattr(planar, what)[name]
            scale = np.abs(want).max()
            assert np.abs(got - want).max() <= rtol * scale, (name, what)


@pytest.mark.parametrize("variant", [1, 2])
def test_planar_four_bar_written_as_spatial_gives_the_planar_results(variant):
    data = _data(ROOT / "examples" / "four_bar.yaml")
    data["contours"][0]["variant"] = variant
    planar = _solve(data)
    both = _solve(_as_spatial(data, {0: 2, 1: 7}))  # Pr9 (a2, b2, a3) and Pr1 (r7 a7 b7)
    assert [c.module for c in both.structure.contours] == ["Pr9", "Pr1"]
    _assert_same(both, planar, PLANAR_RTOL)
    assert np.abs(both.values["b2"]).max() == 0 and np.abs(both.rates["b2"]).max() == 0
    # mixed: contour 1 spatial, contour 2 planar (Pl1) reading the spatial a2 by a link
    mixed = _solve(_as_spatial(data, {0: 2}))
    assert [c.module for c in mixed.structure.contours] == ["Pr9", "Pl1"]
    _assert_same(mixed, planar)


def test_planar_slider_crank_written_as_spatial_gives_the_planar_results():
    data = _data(ROOT / "examples" / "crank_slider.yaml")
    planar = _solve(data)
    unknowns = [(n, k) for n, v in data["vectors"].items() for k in "ra"
                if v[k] == "function"]
    rod = next(n for n, k in unknowns if k == "a")
    matched = []
    for variant in (1, 2):  # Pr8's branches are numbered by the module, not as Pl3's
        data["contours"][0]["variant"] = variant
        spatial = _solve(_as_spatial(data, {0: rod}))
        assert spatial.structure.contours[0].module == "Pr8"  # α β of the rod, r slider
        try:
            _assert_same(spatial, planar)
            matched.append(variant)
        except AssertionError:
            pass
    assert len(matched) == 1


# --------------------------------------------------------------------- RSSR four-bar
def _rssr_data(a, L, c, r4, al4, be4, positions=72, variant=1) -> dict:
    return {"units": {"length": "m", "angle": "deg"}, "positions": positions,
            "arguments": {1: {"table": {0: 0, positions: 360}}},
            "vectors": {1: {"r": a, "a": {"argument": 1}, "b": 0},
                        2: {"r": L, "a": "function", "b": "function"},
                        3: {"r": c, "a": 0, "b": "function"},
                        4: {"r": r4, "a": al4, "b": be4}},
            "contours": [{"vectors": [1, 2, -3, -4], "spatial": True, "variant": variant}]}


def _rssr_coefficients(a, L, c, d, theta):
    """The RSSR's input–output equation in the published form
    ``A(θ) cos ψ + B(θ) sin ψ = C(θ)`` — J. M. McCarthy and G. S. Soh, *Geometric Design
    of Linkages*, 2nd ed., Springer (Interdisciplinary Applied Mathematics 11), 2011,
    Appendix A "Solving Constraint Equations", eq. (A.1), p. 411: "The analysis of planar
    and spherical 4R linkages, the spatial RSSR, and Bennett's linkage all yield a
    constraint equation between the output angle ψ and the input angle θ that takes the
    form (A.1)" (https://doi.org/10.1007/978-1-4419-7892-9; the appendix's text is at
    https://docslib.org/doc/4904453/solving-constraint-equations).

    The coefficients A, B, C of this RSSR (the book's own RSSR coefficients are in its
    spatial-linkage chapter, which the search tool did not find; nor a published numeric
    worked example) are derived here from the closure, independently of the solver:

    * the input crank turns about Z through O: its ball joint is at
      ``P = a (cos θ, sin θ, 0)``;
    * the output crank turns about the line through ``D`` parallel to Y: its ball joint
      is at ``Q = D + c (cos ψ, 0, sin ψ)`` (ψ is the crank's rotation β3 about Y);
    * the S–S coupler keeps its length: ``|Q − P|² = L²``, i.e.
      ``|D − P|² + 2c (D − P)·(cos ψ, 0, sin ψ) + c² = L²``;
    * so ``A(θ) = 2c (x_D − a cos θ)``, ``B(θ) = 2c z_D`` (the Y component of ``D − P``
      is normal to the crank's circle), ``C(θ) = L² − c² − |D − P|²``.
    """
    dx, dy, dz = d[0] - a * np.cos(theta), d[1] - a * np.sin(theta), d[2]
    return 2 * c * dx, 2 * c * dz * np.ones_like(theta), L**2 - c**2 - (dx**2 + dy**2
                                                                        + dz**2)


def _rssr_roots(a, L, c, d, theta):
    """Both roots ψ of (A.1) by the book's trigonometric solution, eq. (A.5),
    ``ψ = arctan(B/A) ± arccos(C / √(A² + B²))`` (``arctan2`` for the quadrant), and
    where they exist: ``A² + B² − C² ≥ 0`` (p. 412)."""
    p, q, rhs = _rssr_coefficients(a, L, c, d, theta)
    h = np.hypot(p, q)
    with np.errstate(divide="ignore", invalid="ignore"):
        mid, half = np.arctan2(q, p), np.arccos(np.clip(rhs / h, -1, 1))
    return np.stack([mid + half, mid - half]), np.abs(rhs) <= h


def _rssr_half_angle_roots(a, L, c, d, theta):
    """Both roots ψ of (A.1) by the book's second route, the tan-half-angle technique:
    with ``y = tan(ψ/2)``, eq. (A.7) ``(A + C) y² − 2B y − (A − C) = 0``, each position's
    quadratic solved by :func:`numpy.roots` (an eigenvalue solve, no arccos), then
    ``ψ = 2 arctan y``.  Shape ``(2, P)``; assumes every position assembles."""
    p, q, rhs = _rssr_coefficients(a, L, c, d, theta)
    roots = np.stack([np.roots([p[i] + rhs[i], -2 * q[i], -(p[i] - rhs[i])])
                      for i in range(theta.size)], axis=1)
    assert np.abs(roots.imag).max() == 0
    return 2 * np.arctan(roots.real)


def _frame(r4, al4, be4):
    al4, be4 = math.radians(al4), math.radians(be4)
    return r4 * np.array([math.cos(al4) * math.cos(be4), math.sin(al4),
                          math.cos(al4) * math.sin(be4)])


def _wrapped_distance(x, y):
    return np.abs(np.angle(np.exp(1j * (x - y))))


def test_rssr_example_follows_its_input_output_equation_over_the_cycle():
    model = mechloop.load_model(SPATIAL / "rssr.yaml")
    data = _data(SPATIAL / "rssr.yaml")
    v = data["vectors"]
    a, L, c = (v[n]["r"] / 1000 for n in (1, 2, 3))
    d = _frame(v[4]["r"] / 1000, v[4]["a"], v[4]["b"])
    for variant in (1, 2):
        data["contours"][0]["variant"] = variant
        res = _solve(data)
        assert not res.broken.any() and res.breaks == ()
        theta = res.arguments[1]
        roots, exists = _rssr_roots(a, L, c, d, theta)
        assert exists.all()
        miss = _wrapped_distance(res.values["b3"][None], roots).min(axis=0)
        assert miss.max() < 1e-12
        # the same by the tan-half-angle route (A.7): the roots of a quadratic per position
        halves = _rssr_half_angle_roots(a, L, c, d, theta)
        assert _wrapped_distance(res.values["b3"][None], halves).min(axis=0).max() < 1e-12
        # the coupler keeps its length: |D + c(cos φ, 0, sin φ) − A| = L, as closed
        phi = res.values["b3"]
        b = d[:, None] + c * np.stack([np.cos(phi), 0 * phi, np.sin(phi)])
        assert np.abs(np.linalg.norm(b - a * np.stack(
            [np.cos(theta), np.sin(theta), 0 * theta]), axis=0) - L).max() < 1e-14
    assert model.contours[0].spatial


def test_rssr_variants_are_the_two_assemblies_throughout():
    data = _data(SPATIAL / "rssr.yaml")
    one = _solve(data).values["b3"]
    data["contours"][0]["variant"] = 2
    two = _solve(data).values["b3"]
    assert _wrapped_distance(one, two).min() > 0.1  # never meet over the cycle
    data["contours"][0]["variant"] = "auto"  # variant 1 followed by continuity
    auto = _solve(data).values["b3"]
    assert np.abs(auto - one).max() < 1e-12


def _finite_differences(data: dict, names: list[str], h_deg: float = 1e-3):
    """Analog rates and accelerations by central differences in argument 1's offset."""
    runs = []
    for step in (-h_deg, 0.0, h_deg):
        moved = copy.deepcopy(data)
        for vec in moved["vectors"].values():
            for k in "rab":
                if isinstance(vec.get(k), dict) and vec[k].get("argument") == 1:
                    vec[k]["offset"] = step
        runs.append(_solve(moved))
    h = math.radians(h_deg)
    out = {}
    for name in names:
        lo, mid, hi = (r.values[name] for r in runs)
        out[name] = ((hi - lo) / (2 * h), (hi - 2 * mid + lo) / h**2)
    return out


@pytest.mark.parametrize("example", ["rssr.yaml", "spherical_four_bar.yaml"])
def test_rates_and_accelerations_match_finite_differences(example):
    data = _data(SPATIAL / example)
    data.pop("time", None)  # analogs with respect to argument 1 (per rad)
    res = _solve(data)
    names = res.varying()
    fd = _finite_differences(data, names)
    for name in names:
        d1, d2 = fd[name]
        scale1, scale2 = np.abs(res.rates[name]).max(), np.abs(res.accels[name]).max()
        assert np.abs(res.rates[name] - d1).max() <= 1e-6 * max(scale1, 1e-3), name
        assert np.abs(res.accels[name] - d2).max() <= 1e-4 * max(scale2, 1e-3), name
    # with model time (constant speed) the derivatives are the analogs times ω, ω²
    timed = mechloop.load_model(SPATIAL / example)
    t = mechloop.solve(timed)
    omega = 2 * math.pi * timed.time.rpm / 60
    for name in names:
        np.testing.assert_allclose(t.rates[name], res.rates[name] * omega, rtol=1e-12,
                                   atol=1e-12 * np.abs(t.rates[name]).max())
        np.testing.assert_allclose(t.accels[name], res.accels[name] * omega**2,
                                   rtol=1e-12, atol=1e-12 * np.abs(t.accels[name]).max())


def test_a_reversed_loop_gives_the_same_mechanism():
    """The signs: the same RSSR loop written the other way round (every vector
    subtracted: the module's vector i then enters with a minus sign)."""
    data = _data(SPATIAL / "rssr.yaml")
    want = _solve(data)
    data["contours"][0]["vectors"] = [-1, -2, 3, 4]
    got = _solve(data)
    for name in want.varying():
        for what in ("values", "rates", "accels"):
            np.testing.assert_allclose(getattr(got, what)[name], getattr(want, what)[name],
                                       rtol=1e-12, atol=1e-12)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(a=st.floats(0.02, 0.08), L=st.floats(0.08, 0.2), c=st.floats(0.04, 0.12),
       r4=st.floats(0.05, 0.15), al4=st.floats(-60, 60), be4=st.floats(-80, 80),
       variant=st.sampled_from([1, 2]))
def test_random_rssr_geometry_against_the_closed_form(a, L, c, r4, al4, be4, variant):
    data = _rssr_data(a, L, c, r4, al4, be4, positions=36, variant=variant)
    res = _solve(data)
    theta = res.arguments[1]
    d = _frame(r4, al4, be4)
    roots, exists = _rssr_roots(a, L, c, d, theta)
    ok = ~res.broken
    # every position the closed form says does not assemble is a chain break
    assert not (ok & ~exists).any()
    # away from a tangency (the two assemblies meet: a dead point, rightly a break)
    margin = np.abs(np.sin((roots[0] - roots[1]) / 2)) > 1e-6
    assert not (~ok & exists & margin).any()
    miss = _wrapped_distance(res.values["b3"][None], roots).min(axis=0)
    assert (miss[ok] < 1e-9).all()
    assert np.isfinite(res.to_frame().drop(columns="chain_break").to_numpy(float)[ok]).all()


# ------------------------------------------------------------------ spherical four-bar
def test_spherical_four_bar_follows_the_spherical_cosine_law_over_the_cycle():
    data = _data(SPATIAL / "spherical_four_bar.yaml")
    v = data["vectors"]
    g1 = math.radians(90 - v[1]["a"])  # crank arc from the Y axis
    g2 = 2 * math.asin(v[2]["r"] / (2 * v[1]["r"]))  # coupler arc from its chord
    g3 = math.atan2(v[3]["r"], v[4]["r"])  # output arc from the X axis
    assert math.isclose(math.hypot(v[3]["r"], v[4]["r"]), v[1]["r"], rel_tol=1e-15)
    for variant in (1, 2):
        data["contours"][0]["variant"] = variant
        res = _solve(data)
        assert not res.broken.any()
        t, psi = res.arguments[1], res.values["a3"]
        lhs = (math.sin(g1) * math.sin(g3) * np.sin(t) * np.cos(psi)
               + math.cos(g1) * math.sin(g3) * np.sin(psi))
        rhs = math.cos(g2) - math.sin(g1) * math.cos(g3) * np.cos(t)
        assert np.abs(lhs - rhs).max() < 1e-14
        # A and B on the sphere, the coupler arc constant
        ax, ay, az = res.components(1)[0][0], res.components(1)[1][0], res.components(1)[2][0]
        assert np.abs(np.sqrt(ax**2 + ay**2 + az**2) - 0.1).max() < 1e-15


# ---------------------------------------------------------------- closure and the CLI
@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_contours_close_in_space(path):
    model = mechloop.load_model(path)
    res = mechloop.solve(model)
    for contour in model.contours:
        total = np.zeros((3, 3, model.positions + 1))
        scale = np.zeros(3)
        for entry in contour.vectors:
            sign = -1.0 if entry < 0 else 1.0
            comps = res.components(abs(entry))
            for axis in range(3):
                for order in range(3):
                    total[order, axis] += sign * comps[axis][order]
                    scale[order] = max(scale[order], np.abs(comps[axis][order]).max())
        for order in range(3):
            assert np.abs(total[order]).max() <= 1e-12 * scale[order]


#: Examples whose force analysis is refused on purpose: file name -> the refusal (the
#: four revolutes of a spherical four-bar: 3 redundant constraints, see
#: tests/test_structure_spatial_joints.py).
REFUSED = {"spherical_four_bar_joints.yaml": "statically indeterminate: 3 reaction"}


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_example_through_the_cli(path, tmp_path):
    runner = CliRunner()
    out = tmp_path / "x.csv"
    if path.name in REFUSED:
        for command in (["check", str(path)], ["solve", str(path), "-o", str(out)]):
            result = runner.invoke(app, command)
            assert result.exit_code == 2 and REFUSED[path.name] in result.output
        return
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 0 and "OK" in result.output, result.output
    result = runner.invoke(app, ["solve", str(path), "-o", str(out)])
    assert result.exit_code == 0, result.output
    written = pd.read_csv(out)
    model = mechloop.load_model(path)
    frame = (solve_spatial_dynamics(model) if model.bodies else mechloop.solve(model)
             ).to_frame()
    assert list(written.columns) == list(frame.columns)
    for column in ("b3 [deg]", "x2 [m]", "dz2 [m/s]", "ddy2 [m/s^2]"):
        assert column in written.columns or any(  # the swashplate's turning vector is 1
            column.replace("b3", other) in written.columns for other in ("a3", "b1"))
    np.testing.assert_allclose(written.drop(columns="chain_break").to_numpy(float),
                               frame.drop(columns="chain_break").to_numpy(float),
                               rtol=1e-15, atol=0)
    result = runner.invoke(app, ["solve", str(path), "-o", str(tmp_path / "x.json")])
    assert result.exit_code == 0, result.output


# -------------------------------------------------------------------------- bad input
BAD = """\
units: {length: mm, angle: deg}
positions: 12
arguments:
  1: {table: {0: 0, 12: 360}}
vectors:
  1: {r: 40, a: {argument: 1}}
  2: {r: 120, a: function, b: %s}
  3: {r: 80, a: 0, b: function}
  4: {r: 100, a: 30, b: %s}
contours:
  - vectors: [1, 2, -3, -4]
    spatial: true
    variant: %s
"""


@pytest.mark.parametrize("b2, b4, variant, where, words, fix", [
    ("10", "45", "1", "contours[0]", "has 2 function parameter(s) (a2, b3)",
     "mark 3 of its parameters 'function'"),
    ("function", "function", "1", "contours[0]", "has 4 function parameter(s)",
     "make all but 3 of them"),
    ("function", "{link: b9}", "1", "vectors[4].b", "vector 9 is not defined",
     "link to a vector that exists"),
    ("function", "{link: a2}", "1", "vectors[4].b", "b4 (angle) links to a2 (angle)", ""),
    ("function", "45", "3", "contours[0].variant", "module Pr10, which has 2 solution(s)",
     "set 'variant' to 1..2 or 'auto'"),
    ("function", "{argument: 2}", "1", "vectors[4].b", "uses argument 2, which is not "
     "defined", "add argument 2"),
])
def test_bad_spatial_contours_are_located_with_a_fix(tmp_path, b2, b4, variant, where, words,
                                                     fix):
    path = tmp_path / "bad.yaml"
    path.write_text(BAD % (b2, b4, variant), encoding="utf-8")
    if "links to a2" in words:  # a link joins parameters of the same kind: α to β is
        path.write_text(BAD % ("function", "{link: r2}", variant), encoding="utf-8")
        words, fix = "b4 (angle) links to r2 (length)", "link to b2 instead"
    with pytest.raises(ModelError) as info:
        mechloop.load_model(path)
    found = [p for p in info.value.problems if words in p.message]
    assert found, str(info.value)
    assert found[0].where() == where and fix in found[0].hint
    assert found[0].line is not None
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2 and words.split()[0] in result.output


def test_three_unknown_rotations_are_refused_as_pr20_with_the_fix():
    data = _rssr_data(0.04, 0.12, 0.08, 0.1, 30, 45)
    data["vectors"][2] = {"r": 0.12, "a": 10, "b": "function"}
    data["vectors"][1]["b"] = "function"
    data["vectors"][1]["a"] = 0
    data["vectors"][4]["b"] = {"argument": 1}
    with pytest.raises(ModelError) as info:
        model_from_data(data)
    text = str(info.value)
    assert "Pr20" in text and "infinitely many" in text and "give one of these" in text


def test_rotation_on_a_planar_contour_and_unsupported_sections_are_refused():
    data = _data(ROOT / "examples" / "four_bar.yaml")
    data["vectors"][1]["b"] = 0
    with pytest.raises(ModelError) as info:
        model_from_data(copy.deepcopy(data))
    assert "add 'spatial: true'" in str(info.value)
    spatial = _data(SPATIAL / "rssr.yaml")
    spatial["springs"] = [{"bodies": [0, 1], "ends": [{"tail": 1}, {"head": 1}],
                           "stiffness": 1000, "free_length": 30}]  # none in space yet
    with pytest.raises(ModelError) as info:
        model_from_data(spatial)
    assert "'springs' is not solved for a model with spatial contours" in str(info.value)


def test_old_models_keep_their_schema_meaning():
    """A planar model reads as before: no β anywhere, variant 3 still refused."""
    data = _data(ROOT / "examples" / "four_bar.yaml")
    model = model_from_data(copy.deepcopy(data))
    assert all(v.b is None for v in model.vectors.values())
    assert not any(c.spatial for c in model.contours)
    data["contours"][0]["variant"] = 3
    with pytest.raises(ModelError, match="at most two solutions"):
        model_from_data(data)


# ------------------------------------------------------------------ module and branches
def test_every_unknown_pattern_names_its_module():
    assert classify([(1, "r"), (1, "a"), (1, "b")]).module == "Pr1"
    assert classify([(2, "a"), (2, "b"), (3, "b")]).module == "Pr10"
    assert classify([(3, "b"), (2, "b"), (2, "a")]).roles == (2, 3)
    assert classify([(1, "b"), (2, "r"), (3, "b")]).module == "Pr18"
    assert classify([(1, "b"), (2, "r"), (3, "b")]).roles == (1, 3, 2)
    assert classify([(1, "a"), (2, "b"), (3, "b")]).module == "Pr19"
    seen = {classify(u).module for u in (
        [(1, x), (2, y), (3, z)] for x in "rab" for y in "rab" for z in "rab")}
    seen |= {classify([(1, x), (1, y), (2, z)]).module
             for x, y in (("r", "a"), ("r", "b"), ("a", "b")) for z in "rab"}
    assert seen == {f"Pr{k}" for k in range(2, 21)}
    assert classify([(1, "r"), (2, "r")]) is None


def test_follow_branch_undoes_swapped_labels():
    """Two assemblies whose first coordinate crosses (a root sort swaps their labels
    there) while the second keeps them apart: followed, each stays itself."""
    t = np.linspace(0, 2 * np.pi, 200)
    first = np.stack([np.sin(t), -np.sin(t)])
    second = np.stack([np.ones_like(t), -np.ones_like(t)])
    order = np.argsort(first, axis=0)  # labels by increasing first coordinate
    points = np.stack([np.take_along_axis(first, order, axis=0),
                       np.take_along_axis(second, order, axis=0)], axis=1)
    ok = np.ones((2, t.size), dtype=bool)
    for start in (0, 1):
        index = follow_branch(points, ok, start)
        path = np.take_along_axis(points, index[None, None], axis=0)[0]
        assert np.all(path[1] == path[1, 0])  # never jumps to the other assembly
        assert np.abs(np.diff(path[0])).max() < 2 * (t[1] - t[0])
    # a break (one branch missing) keeps the labels through it
    ok[0, 50:60] = False
    index = follow_branch(points, ok, 1)
    assert index.shape == t.shape


# --------------------------------------------------------------- landing-gear retraction
GEAR = SPATIAL / "landing_gear_skewed_axis.yaml"


def test_landing_gear_swing_angle_and_wheel_path_in_closed_form():
    data = _data(GEAR)
    res = _solve(data)
    assert not res.broken.any()
    v = data["vectors"]
    a_vec = _frame(v[1]["r"], v[1]["a"], v[1]["b"])
    d, length, b0 = v[3]["r"], v[4]["r"], math.radians(v[3]["b"])
    s, alpha = res.values["r2"], res.values["a3"]
    # the cylinder's length: d (xA cos b0 + zA sin b0) cos a3 + d yA sin a3 = (d² + |A|² − s²)/2
    lhs = d * (a_vec[0] * math.cos(b0) + a_vec[2] * math.sin(b0)) * np.cos(alpha) \
        + d * a_vec[1] * np.sin(alpha)
    rhs = (d**2 + a_vec @ a_vec - s**2) / 2
    assert np.abs(lhs - rhs).max() < 1e-15
    assert np.all(np.cos(alpha) > 0) and np.all(np.sin(alpha) < 0)  # below the hinge, ahead
    # the wheel axle W = −(vector 5): on the sphere of radius L, in the hinge's plane
    w = -np.stack([c[0] for c in res.components(5)])
    assert np.abs(np.linalg.norm(w, axis=0) - length).max() < 1e-14
    assert np.abs(-math.sin(b0) * w[0] + math.cos(b0) * w[2]).max() < 1e-14
    assert w[1, 0] < -0.99 * length and w[1, -1] > -0.2 * length  # down, then up


def test_landing_gear_rates_by_finite_differences_and_the_chain_rule():
    """dq/ds and d²q/ds² by central differences in the cylinder length's offset; the
    time derivatives are then q̇ = q' ṡ and q̈ = q'' ṡ² + q' s̈ (ṡ, s̈ of the law, as the
    cylinder's own r2 rates)."""
    data = _data(GEAR)
    res = _solve(data)
    h = 1e-4  # m: truncation and round-off of the second difference both near 1e-8
    runs = []
    for step in (-h, 0.0, h):
        moved = copy.deepcopy(data)
        moved["vectors"][2]["r"] = {"argument": 1, "offset": step}
        runs.append(_solve(moved))
    s_dot, s_ddot = res.rates["r2"], res.accels["r2"]
    # the axle's distance from O is fixed, and so is the plane it moves in
    assert np.abs(res.rates["r5"]).max() < 1e-12 and np.abs(res.rates["b5"]).max() < 1e-12
    for name in ("a2", "b2", "a3", "a5"):
        lo, mid, hi = (r.values[name] for r in runs)
        d1, d2 = (hi - lo) / (2 * h), (hi - 2 * mid + lo) / h**2
        rate, accel = d1 * s_dot, d2 * s_dot**2 + d1 * s_ddot
        assert np.abs(res.rates[name] - rate).max() <= 1e-6 * np.abs(rate).max() + 1e-12, name
        assert np.abs(res.accels[name] - accel).max() <= 1e-6 * np.abs(accel).max(), name


def test_what_is_not_built_for_spatial_models_is_refused_with_the_fix(tmp_path):
    from mechloop.errors import HintedError, SolveError
    from mechloop.solve.designs import solve_designs
    from mechloop.solve.existence import assembles_throughout

    model = mechloop.load_model(SPATIAL / "rssr.yaml")
    for call in (lambda: solve_designs(model, {"r2": [0.11, 0.12]}, positions=[0, 1]),
                 lambda: assembles_throughout(model),
                 lambda: mechloop.solve_intermediate(model)):
        with pytest.raises(SolveError, match="not built for a model with spatial contours"):
            call()
    runner = CliRunner()
    # (the plan of a spatial model is drawn in 3-D: tests/test_views_spatial.py; its
    # report is written: tests/test_report_spatial.py)
    result = runner.invoke(app, ["plot", str(SPATIAL / "rssr.yaml"), "parameters", "-n",
                                 "b3,db3", "-o", str(tmp_path / "b3.png")])
    assert result.exit_code == 0, result.output
    assert issubclass(SolveError, HintedError)  # the CLI prints it with its fix


# ------------------------------------------------------- a planar contour in another plane
@pytest.mark.parametrize("plane", [{"normal": [1, 1, 1]}, {"a": 30, "b": 60},
                                   {"normal": [0, 2, 0]}])
def test_a_planar_contour_in_a_plane_beside_a_spatial_one(plane):
    """The four-bar's loop spatial, its coupler-point loop planar in another plane: the
    parameters are the planar model's, and the plane places the second loop's vectors."""
    data = _data(ROOT / "examples" / "four_bar.yaml")
    planar = _solve(data)
    mixed = _as_spatial(data, {0: 2})
    mixed["contours"][1]["plane"] = plane
    res = _solve(mixed)
    _assert_same(res, planar)
    if "normal" in plane:
        n = np.asarray(plane["normal"], float)
    else:
        a, b = math.radians(plane["a"]), math.radians(plane["b"])
        n = np.array([math.cos(a) * math.cos(b), math.sin(a), math.cos(a) * math.sin(b)])
    n /= np.linalg.norm(n)
    total = np.zeros((3, 3, res.broken.size))
    for number in (5, 6, 7):
        comps = res.components(number)
        v = np.stack([c[0] for c in comps])
        assert np.abs(n @ v).max() < 1e-15  # in the plane
        np.testing.assert_allclose(np.linalg.norm(v, axis=0), res.values[f"r{number}"],
                                   rtol=1e-14)
        for order in range(3):
            total[order] += np.stack([c[order] for c in comps])
            assert np.abs(n @ np.stack([c[order] for c in comps])).max() < 1e-12
    assert np.abs(total).max() < 1e-12  # the loop closes in space, with its rates
    frame = res.to_frame()
    assert {"x7 [m]", "dz6 [m/s]", "ddy5 [m/s^2]"} <= set(frame.columns)


def test_a_plane_is_refused_where_it_does_not_apply():
    data = _data(ROOT / "examples" / "four_bar.yaml")
    data["contours"][1]["plane"] = {"normal": [1, 0, 0]}
    with pytest.raises(ModelError, match="no contour of the model is spatial"):
        model_from_data(copy.deepcopy(data))
    spatial = _data(SPATIAL / "rssr.yaml")
    spatial["contours"][0]["plane"] = {"normal": [1, 0, 0]}
    with pytest.raises(ModelError, match="a plane applies to a planar contour"):
        model_from_data(copy.deepcopy(spatial))
    spatial["contours"][0]["plane"] = {"normal": [0, 0, 0]}
    with pytest.raises(ModelError, match="normal is zero"):
        model_from_data(spatial)


def test_chain_breaks_and_dead_points_are_reported_as_in_the_planar_core(tmp_path):
    # a coupler too short to reach at some crank angles: a break, positions named
    data = _rssr_data(0.04, 0.07, 0.08, 0.1, 30, 45, positions=36)
    res = _solve(data)
    _, exists = _rssr_roots(0.04, 0.07, 0.08, _frame(0.1, 30, 45), res.arguments[1])
    assert (~exists).any() and exists.any()
    (brk,) = res.breaks
    assert brk.contour == 1 and brk.module == "Pr10"
    np.testing.assert_array_equal(brk.positions, np.flatnonzero(~exists))
    assert "no real solution" in brk.describe()
    frame = res.to_frame()
    assert frame.loc[~exists, "b3 [deg]"].isna().all()
    assert np.isfinite(frame.loc[exists].drop(columns="chain_break").to_numpy(float)).all()
    path = tmp_path / "short.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    result = CliRunner().invoke(app, ["solve", str(path)])
    assert result.exit_code == 0 and "chain break" in result.output
    # the crank in line with the frame: the two assemblies meet (φ = 0), a dead point
    res = _solve(_rssr_data(0.0625, 0.125, 0.0625, 0.125, 0, 0, positions=36))
    (dead,) = res.breaks
    assert "dead point" in dead.reason and list(dead.positions) == [0, 18, 36]
    assert res.broken.sum() == 3


def test_many_designs_in_one_pass_are_the_designs_solved_one_by_one():
    """``solve_designs`` on a spatial model: arrays ``(D, P)``, each row the solve of that
    design's model (a constant, an argument offset and a link delta varied)."""
    from mechloop.solve.designs import solve_designs

    data = _data(GEAR)
    model = model_from_data(copy.deepcopy(data))
    over = {"r3": np.array([0.38, 0.40, 0.42]),     # a constant (m)
            "r2": np.array([0.0, 0.002, -0.003]),   # the cylinder's argument offset (m)
            "a4": np.radians([0.0, 5.0, -5.0])}     # the link delta of the wheel's strut
    many = solve_designs(model, over)
    assert many.broken.shape == (3, model.positions + 1) and not many.broken.any()
    for row in range(3):
        one = copy.deepcopy(data)
        one["vectors"][3]["r"] = float(over["r3"][row])
        one["vectors"][2]["r"] = {"argument": 1, "offset": float(over["r2"][row])}
        one["vectors"][4]["a"] = {"link": "a3", "delta": float(np.degrees(over["a4"][row]))}
        want = _solve(one)
        for name in want.varying():
            for what in ("values", "rates", "accels"):
                np.testing.assert_allclose(getattr(many, what)[name][row],
                                           getattr(want, what)[name], rtol=1e-12,
                                           atol=1e-12, err_msg=f"{name} {what} {row}")
    assert not any(c.any() for c in many.branch_changes.values())
    with pytest.raises(Exception, match="cannot vary a3"):
        solve_designs(model, {"a3": [0.1, 0.2]})


def _pr14(variant) -> dict:
    """A loop with unknowns r2, a3, a4 (module Pr14: four roots of a trigonometric
    quartic, sorted by value, two of them real only over part of the cycle)."""
    return {"units": {"length": "m", "angle": "deg"}, "positions": 180,
            "arguments": {1: {"table": {0: 0, 180: 360}}},
            "vectors": {1: {"r": 0.3, "a": {"argument": 1}, "b": 0},
                        2: {"r": "function", "a": 20, "b": 70},
                        3: {"r": 1.0, "a": "function", "b": 30},
                        4: {"r": 0.9, "a": "function", "b": -60},
                        5: {"r": 0.8, "a": 10, "b": 40}},
            "contours": [{"vectors": [1, 2, 3, 4, -5], "spatial": True,
                          "variant": variant}]}


def test_auto_follows_an_assembly_where_sorted_roots_change_labels():
    def steps(res):
        pts = np.stack([c[0] for n in (2, 3, 4) for c in res.components(n)])
        return np.abs(np.diff(pts, axis=1)).sum(axis=0)

    fixed, auto = _solve(_pr14(1)), _solve(_pr14("auto"))
    assert fixed.structure.contours[0].module == "Pr14"
    assert not fixed.broken.any() and not auto.broken.any()
    np.testing.assert_array_equal(auto.values["a3"][:5], fixed.values["a3"][:5])  # from 1
    jump = steps(fixed)
    assert jump.max() > 20 * np.median(jump)  # branch 1 of the sorted roots jumps
    smooth = steps(auto)
    assert smooth.max() < 2 * np.median(smooth)  # followed, the assembly moves smoothly
    # and it is a solution: the loop closes, its velocities and accelerations too
    for order in range(3):
        total = sum(sign * np.stack([c[order] for c in auto.components(n)])
                    for n, sign in ((1, 1), (2, 1), (3, 1), (4, 1), (5, -1)))
        assert np.abs(total).max() < 1e-12


def test_the_second_convention_gives_the_same_vectors_in_its_own_ranges():
    """Seed 000 sec. 1.1: convention 2 (β a full turn, α a half turn) describes the same
    coupler of the RSSR; its angles stay in their ranges (continuous from position 0)."""
    data = _data(SPATIAL / "rssr.yaml")
    one = _solve(data)
    data["contours"][0]["convention"] = 2
    two = _solve(data)
    for k in range(3):
        for order in range(3):
            np.testing.assert_allclose(two.components(2)[k][order],
                                       one.components(2)[k][order], atol=1e-13)
    assert np.abs(two.values["a2"]).max() <= np.pi / 2
    assert np.abs(one.values["b2"]).max() <= np.pi / 2
    np.testing.assert_allclose(two.values["b3"], one.values["b3"], atol=1e-13)
    planar = _data(ROOT / "examples" / "four_bar.yaml")
    planar["contours"][0]["convention"] = 2
    with pytest.raises(ModelError, match="applies to a spatial contour"):
        model_from_data(planar)


def test_a_rotation_linked_with_a_ratio_follows_its_source_exactly():
    """b1 = 0.5·b5 + 10° (b5 driven by argument 1, a vector of another contour) drives
    the spherical four-bar over half a turn from 10° in the same time: the same motion as
    its argument so given, values and time derivatives."""
    data = _data(SPATIAL / "spherical_four_bar.yaml")
    linked = copy.deepcopy(data)
    linked["vectors"][1]["b"] = {"link": "b5", "ratio": 0.5, "delta": 10}
    linked["vectors"][5] = {"r": 100, "a": 0, "b": {"argument": 1}}
    linked["vectors"][6] = {"r": "function", "a": "function", "b": "function"}
    linked["contours"].append({"vectors": [5, 6], "spatial": True})
    direct = copy.deepcopy(data)
    direct["arguments"][1] = {"table": {0: 10, 72: 190}}
    got, want = _solve(linked), _solve(direct)
    assert not got.broken.any() and got.structure.contours[1].module == "Pr1"
    for name in ("b1", "a2", "b2", "a3"):
        for what in ("values", "rates", "accels"):
            np.testing.assert_allclose(getattr(got, what)[name], getattr(want, what)[name],
                                       rtol=1e-12, atol=1e-12, err_msg=f"{name} {what}")
    np.testing.assert_allclose(got.rates["b1"], 0.5 * got.rates["b5"], rtol=1e-15)
