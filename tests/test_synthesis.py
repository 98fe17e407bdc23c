"""Synthesis: recovery of a known four-bar, feasibility, conditions, stopping rules."""

from __future__ import annotations

import itertools
import time

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.dynamics.points import Placement
from mechloop.errors import ModelError
from mechloop.model.dynamic import HeadPoint
from mechloop.synthesis import deviations as dv
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import synthesize

PATH = "examples/four_bar_path_synthesis.yaml"


def _with(model: mechloop.Model, **changes) -> mechloop.Model:
    data = model.model_dump(mode="json", exclude_defaults=True)
    for key, value in changes.items():
        data["synthesis"][key] = value
    return mechloop.Model.from_dict(data)


def _coupler_curve(model: mechloop.Model) -> np.ndarray:
    """The coupler point of a model solved on its own (mm), an independent path."""
    return Placement(mechloop.solve(model)).head(6).z * 1000


def _max_distance(curve: np.ndarray, targets: np.ndarray, steps: int = 50
                  ) -> tuple[float, float]:
    """Largest distance from a target to a densely resampled curve (brute force), and the
    resampling's own error bound (half the largest spacing)."""
    t = np.linspace(0, 1, steps, endpoint=False)
    dense = (curve[:-1, None] + (curve[1:] - curve[:-1])[:, None] * t).ravel()
    spacing = float(np.abs(np.diff(curve)).max()) / steps
    return float(np.abs(targets[:, None] - dense[None, :]).min(axis=1).max()), spacing / 2


def _dense_max_distance(model: mechloop.Model, targets: np.ndarray,
                        positions: int = 36000) -> float:
    """Largest distance (mm) from a target to the coupler curve of ``model`` solved on its
    own at ``positions`` positions over the turn (segments between them: their sag is
    below 1e-6 mm here)."""
    data = model.model_dump(mode="json", exclude_defaults=True)
    data["positions"] = positions
    data["arguments"] = {1: {"table": {0: 0, positions: 360}}}
    z = _coupler_curve(mechloop.Model.from_dict(data))
    a, seg = z[:-1], np.diff(z)
    worst = 0.0
    for target in targets:
        t = np.clip(((target - a) * seg.conj()).real / np.abs(seg) ** 2, 0, 1)
        worst = max(worst, float(np.abs(a + t * seg - target).min()))
    return worst


@pytest.mark.parametrize("method", ["de", "cmaes"])
def test_recovers_a_known_four_bar_from_the_bounds(method):
    model = mechloop.load_model(PATH)
    result = synthesize(model, method=method, seed=3)
    targets = np.array([complex(x, y) for x, y in model.synthesis.path.targets])
    size = abs(complex(np.ptp(targets.real), np.ptp(targets.imag)))
    assert result.feasible
    assert result.q <= 1e-4 * size
    # the written model, solved on its own, passes through the targets
    solved = mechloop.solve(result.model)
    assert not solved.breaks
    # Q is the distance to the curve as the mechanism moves (not to the polyline
    # through its 180 positions): the written model solved at 36000 positions
    assert _dense_max_distance(result.model, targets) == pytest.approx(result.q, abs=1e-6)
    # bounds and the pressure-angle condition hold in the result
    low, high = result.problem.variables.low, result.problem.variables.high
    assert np.all(result.best >= low) and np.all(result.best <= high)
    between = np.mod(solved.values["a2"] - solved.values["a3"], np.pi)
    pressure = np.degrees(np.pi / 2 - np.minimum(between, np.pi - between))
    assert pressure.max() <= 60 + 1e-6


def test_same_seed_same_result():
    model = _with(mechloop.load_model(PATH), search={"method": "de", "seed": 5,
                                                     "iterations": 15, "population": 30})
    a = synthesize(model, polish=False)
    b = synthesize(model, polish=False)
    np.testing.assert_array_equal(a.best, b.best)
    assert a.history["best"].tolist() == b.history["best"].tolist()


def test_population_evaluation_matches_designs_alone_and_the_solver():
    model = mechloop.load_model(PATH)
    problem = SynthesisProblem(model)
    rng = np.random.default_rng(0)
    designs = problem.variables.scale(rng.uniform(size=(12, len(problem.variables))))
    together = problem.evaluate(designs)
    targets = np.array([complex(x, y) for x, y in model.synthesis.path.targets])
    for d in range(12):
        alone = problem.evaluate(designs[d:d + 1])
        assert alone.total[0] == pytest.approx(together.total[0 + d], rel=1e-12)
        one = problem.design_model(designs[d])
        solved = mechloop.solve(one)
        assert together.feasible[d] == (not solved.breaks)
        if together.feasible[d]:
            curve = _coupler_curve(one)
            want = np.abs(targets[:, None] - curve[None, :]).min(axis=1).max()
            # the polyline is at least as close as its vertices
            assert together.q[d] <= want + 1e-9
            brute, error = _max_distance(curve, targets)
            assert together.q[d] - 1e-9 <= brute <= together.q[d] + error


def test_a_broken_design_is_never_returned_as_feasible():
    model = mechloop.load_model(PATH)
    # a crank long enough to break the chain over most of the box
    data = model.model_dump(mode="json", exclude_defaults=True)
    data["synthesis"]["vary"]["r1"] = [50, 400]
    data["synthesis"]["search"] = {"method": "de", "seed": 1, "iterations": 10,
                                   "population": 30}
    result = synthesize(mechloop.Model.from_dict(data))
    assert result.feasible
    assert not mechloop.solve(result.model).breaks
    # nothing can close: the result says so
    data["synthesis"]["vary"] = {"r1": [500, 600]}
    result = synthesize(mechloop.Model.from_dict(data))
    assert not result.feasible
    assert np.isnan(result.q)
    assert result.designs.empty


def test_stopping_rules_and_interrupt():
    model = mechloop.load_model(PATH)
    loose = _with(model, search={"method": "de", "seed": 1, "good_enough": 50,
                                 "iterations": 500})
    assert synthesize(loose, polish=False).stopped == "good enough"
    patient = _with(model, search={"method": "cmaes", "seed": 1, "patience": 1,
                                   "iterations": 500})
    assert synthesize(patient, polish=False).stopped.startswith("no progress")
    budget = _with(model, search={"method": "de", "seed": 1, "time": 0.3,
                                  "iterations": 10**6, "patience": None})
    assert synthesize(budget, polish=False).stopped == "time budget spent"

    def interrupt(progress):
        if progress.iteration == 3:
            raise KeyboardInterrupt

    result = synthesize(model, progress=interrupt)
    assert result.stopped == "interrupted"
    assert len(result.history) == 3 and np.isfinite(result.q)


def test_multistart_runs_local_searches():
    model = _with(mechloop.load_model(PATH), search={"method": "multistart", "seed": 2,
                                                     "starts": 3, "iterations": 5,
                                                     "population": 64})
    result = synthesize(model, scheduler="serial")
    assert result.feasible and result.q < 50
    assert result.evaluations > 256


def test_multistart_keeps_the_time_budget():
    """Long local searches stop at the budget with their best design so far."""
    model = _with(mechloop.load_model(PATH), search={"method": "multistart", "seed": 2,
                                                     "starts": 4, "iterations": 100000,
                                                     "population": 16, "time": 1.5})
    started = time.perf_counter()
    result = synthesize(model, scheduler="serial")
    assert time.perf_counter() - started < 15  # without the deadline: hours
    assert result.stopped == "time budget spent"
    assert result.feasible


def test_function_generation_log10():
    model = mechloop.load_model("examples/log10_function_generator.yaml")
    result = synthesize(model, seed=1)
    assert result.feasible
    solved = mechloop.solve(result.model)
    x = 1 + 9 * np.arange(model.positions + 1) / model.positions
    out = np.degrees(solved.values["a3"] - solved.values["a3"][0])
    wanted = 60 * np.log10(x)
    assert np.max(np.abs(out - wanted)) == pytest.approx(result.q, rel=1e-6, abs=1e-9)
    assert result.q < 1.0  # degrees over a 60-degree output swing


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5)), min_size=3, max_size=8),
       st.lists(st.tuples(st.floats(-10, 10), st.floats(-10, 10)), min_size=1, max_size=6))
@example(poly=[(0.0, 0.0), (0.0, 2.225073858507203e-309), (1.0, 0.0)], points=[(0.0, 1.0)])
@example(poly=[(0.0, 0.0), (0.0, 0.0), (0.0, 1.1165482597579846e-158)], points=[(0.0, 0.0)])
def test_polygon_and_curve_distances_against_brute_force(poly, points):
    """Subnormal edges (the two examples) are points, without an overflow warning."""
    from matplotlib.path import Path as MplPath

    polygon = np.array([complex(*p) for p in poly])
    z = np.array([complex(*p) for p in points])[None, :]
    outside = dv.polygon_outside(z, polygon)[0]
    inside = MplPath(np.c_[polygon.real, polygon.imag]).contains_points(
        np.c_[z.real.ravel(), z.imag.ravel()])
    t = np.linspace(0, 1, 2001)
    edges = np.concatenate([a + (b - a) * t for a, b in zip(polygon, np.roll(polygon, -1),
                                                             strict=True)])
    brute = np.abs(z[0][:, None] - edges[None, :]).min(axis=1)
    for k in range(z.shape[1]):
        if brute[k] < 1e-6:
            continue  # on an edge: inside or outside are both right
        if inside[k]:
            assert outside[k] == 0
        else:
            assert outside[k] == pytest.approx(brute[k], abs=1e-2)
    # distance to the polyline through the polygon's vertices
    curve = dv.distance_to_curve(polygon[None, :], z[0])[0]
    segs = np.concatenate([a + (b - a) * t for a, b in itertools.pairwise(polygon)])
    np.testing.assert_allclose(curve, np.abs(z[0][:, None] - segs).min(axis=1), atol=1e-2)


def test_bad_tasks_are_located():
    model = mechloop.load_model(PATH)
    data = model.model_dump(mode="json", exclude_defaults=True)
    data["synthesis"]["vary"]["a2"] = [0, 10]
    data["synthesis"]["vary"]["r9"] = [0, 10]
    data["synthesis"]["path"]["point"] = {"head": 12}
    with pytest.raises(ModelError) as info:
        mechloop.Model.from_dict(data)
    text = str(info.value)
    assert "synthesis.vary.a2" in text and "function of its contour" in text
    assert "synthesis.vary.r9" in text and "no vector 9" in text
    assert "synthesis.path.point" in text


def test_workspace_and_rotation_measures_match_the_solver():
    model = mechloop.load_model(PATH)
    data = model.model_dump(mode="json", exclude_defaults=True)
    data["synthesis"]["workspace"] = {"points": [{"head": 6}],
                                      "box": [[-100, 100], [150, 400]]}
    data["synthesis"]["rotation"] = [{"between": ["a2", "a3"], "max": 40}]
    model = mechloop.Model.from_dict(data)
    problem = SynthesisProblem(model)
    design = problem.variables.scale(np.full(len(problem.variables), 0.5))
    ev = problem.evaluate(design[None, :])
    one = mechloop.solve(problem.design_model(design))
    z = Placement(one).head(6).z * 1000
    out = np.hypot(np.maximum(np.maximum(-100 - z.real, z.real - 150), 0),
                   np.maximum(np.maximum(100 - z.imag, z.imag - 400), 0))
    assert ev.measures["workspace"][0] == pytest.approx(out.max(), rel=1e-9, abs=1e-9)
    rel = np.degrees(one.values["a2"] - one.values["a3"])
    assert ev.measures["rotation a2-a3"][0] == pytest.approx(np.ptp(rel), rel=1e-9)
    assert HeadPoint(head=6) == model.synthesis.workspace.points[0]


def test_cli_writes_the_best_model_table_and_plots(tmp_path):
    from typer.testing import CliRunner

    from mechloop.cli import app

    runner = CliRunner()
    best = tmp_path / "best.yaml"
    result = runner.invoke(app, ["synthesize", "examples/log10_function_generator.yaml",
                                 "-o", str(best), "--table", str(tmp_path / "best.csv"),
                                 "--plot", str(tmp_path / "c.png"),
                                 "--fit", str(tmp_path / "f.svg"), "--iterations", "30"])
    assert result.exit_code == 0, result.output
    assert "Q = " in result.output and "wrote" in result.output
    written = mechloop.load_model(best)
    problem = SynthesisProblem(written)
    from mechloop.synthesis.variables import current_values

    q = problem.evaluate(current_values(written, problem.variables)[None, :]).q[0]
    assert f"Q = {q:.6g}" in result.output
    import pandas as pd

    table = pd.read_csv(tmp_path / "best.csv")
    assert list(table.columns[:2]) == ["rank", "total"] and (table["total"] >= q - 1e-9).all()
    assert (tmp_path / "c.png").stat().st_size > 0 and (tmp_path / "f.svg").exists()
    bad = runner.invoke(app, ["synthesize", "examples/four_bar.yaml"])
    assert bad.exit_code == 2 and "no synthesis task" in bad.output


def test_a_bad_method_override_is_refused():
    with pytest.raises(ValueError, match="method"):
        synthesize(mechloop.load_model(PATH), method="foo", iterations=1)


def test_cli_refuses_a_bad_method_before_searching():
    from typer.testing import CliRunner

    from mechloop.cli import app

    result = CliRunner().invoke(app, ["synthesize", PATH, "--method", "foo"])
    assert result.exit_code != 0 and "de, cmaes or multistart" in result.output


KNOWN = {"r1": 100, "r2": 350, "r3": 250, "r4": 300, "a4": 180, "r6": 250, "a6": 30,
         "start1.x": 0, "start1.y": 0}  # examples/four_bar.yaml in the path example's terms


def _motion_model(timing: bool) -> tuple[mechloop.Model, np.ndarray]:
    """The path example with a motion task instead: three poses of the coupler (point P
    and the direction of A->B) taken from the known four-bar solved alone; and the known
    design (SI)."""
    base = SynthesisProblem(mechloop.load_model(PATH))
    known = np.array([KNOWN[n] * (1e-3 if n[0] in "rs" else np.pi / 180)
                      for n in base.variables.names])
    solved = mechloop.solve(base.design_model(known))
    positions = [10, 50, 110]
    z = Placement(solved).head(6).z[positions] * 1000
    angle = np.degrees(solved.values["a2"][positions])
    poses = [[float(p.real), float(p.imag), float(a)] for p, a in zip(z, angle,
                                                                       strict=True)]
    data = base.model.model_dump(mode="json", exclude_defaults=True)
    del data["synthesis"]["path"]
    data["synthesis"]["motion"] = {
        "point": {"head": 6}, "angle": "a2", "length": 100.0,
        "poses": dict(zip(positions, poses, strict=True)) if timing else poses}
    return mechloop.Model.from_dict(data), known


@pytest.mark.parametrize("timing", [True, False])
def test_motion_generation_deviations_against_poses(timing):
    """Q of the known four-bar is 0; for other designs each pose's deviation is
    sqrt(distance² + (length · angle error)²), recomputed from each design solved
    alone (at the pose's position with timing, else the best position)."""
    model, si = _motion_model(timing)
    problem = SynthesisProblem(model)
    assert problem.evaluate(si[None, :]).q[0] == pytest.approx(0.0, abs=1e-9)
    rng = np.random.default_rng(4)
    designs = si[None, :] * (1 + 0.03 * rng.standard_normal((6, si.size)))
    ev = problem.evaluate(designs)
    assert ev.feasible.sum() >= 3
    task = model.synthesis.motion
    poses = list(task.poses.values()) if timing else task.poses
    where = list(task.poses) if timing else None
    for d, design in enumerate(designs):
        if not ev.feasible[d]:
            continue
        alone = mechloop.solve(problem.design_model(design))
        z = Placement(alone).head(6).z * 1000
        a = alone.values["a2"]
        errors = []
        for k, (x, y, deg) in enumerate(poses):
            da = np.angle(np.exp(1j * (a - np.radians(deg))))
            each = np.sqrt(np.abs(z - complex(x, y)) ** 2 + (100.0 * da) ** 2)
            errors.append(each[where[k]] if timing else each.min())
        assert ev.q[d] == pytest.approx(max(errors), rel=1e-9)


def test_curve_targets_and_weights():
    """Targets from a parametric curve equal the same points listed; weights E_k scale
    each timed target's deviation."""
    six = mechloop.load_model("examples/six_points_line_synthesis.yaml")
    listed = SynthesisProblem(six)
    data = six.model_dump(mode="json", exclude_defaults=True)
    data["synthesis"]["path"]["targets"] = {"x": "20", "y": "20 + 25*t", "count": 6}
    curve = SynthesisProblem(mechloop.Model.from_dict(data))
    np.testing.assert_allclose(curve.targets, listed.targets, rtol=0, atol=1e-15)
    designs = listed.variables.scale(np.random.default_rng(2).uniform(size=(20, 9)))
    np.testing.assert_array_equal(curve.evaluate(designs).q, listed.evaluate(designs).q)

    model, known = _motion_model(True)  # poses at positions 10, 50, 110
    data = model.model_dump(mode="json", exclude_defaults=True)
    poses = data["synthesis"].pop("motion")["poses"]
    targets = {k: v[:2] for k, v in poses.items()}
    data["synthesis"]["path"] = {"point": {"head": 6}, "targets": targets, "timing": True}
    data["synthesis"]["objective"] = "ssq"
    plain = SynthesisProblem(mechloop.Model.from_dict(data))
    data["synthesis"]["path"]["weights"] = [1.0, 2.0, 3.0]
    weighted = SynthesisProblem(mechloop.Model.from_dict(data))
    design = known * 1.01
    res = plain.solve(design[None, :])
    z = plain.place(res, design[None, :], plain.point)[0] * 1000
    dist = np.abs(z[[10, 50, 110]] - np.array([complex(*t) for t in targets.values()]))
    assert plain.evaluate(design[None, :]).q[0] == pytest.approx(np.sum(dist ** 2))
    assert weighted.evaluate(design[None, :]).q[0] == pytest.approx(
        np.sum((np.array([1.0, 2.0, 3.0]) * dist) ** 2))
