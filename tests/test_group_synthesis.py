"""Synthesis of mechanisms built from Assur groups: ``vary`` names the group file's
dimensions (``groups[0].lengths[1]``, ``points.P.angle``, ``ground.C.x``), the builder ties
each to the vector parameters and contour starts that carry it, and the result is written
back as a group file.

The oracle everywhere is the slow route: set the dimension in the mechanism's document,
rebuild the vector model from the groups, solve it with :func:`mechloop.solve` and read
the named points (their chains, ``PointLocation.xy``) — never the ties themselves.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.dynamics.analysis import solve_dynamics
from mechloop.model.dynamic import HeadPoint
from mechloop.model.groups import (
    GroupMechanism,
    GroupSynthesisTask,
    build,
    build_model,
    dimension_names,
    mechanism_of,
    with_dimensions,
)
from mechloop.synthesis.output import write_model
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import synthesize
from mechloop.synthesis.variables import current_values

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "four_bar_groups_synthesis.yaml"
SIX_BAR = ROOT / "examples" / "six_bar_groups.yaml"


def example_mechanism() -> GroupMechanism:
    mech = mechanism_of(EXAMPLE)
    assert mech is not None
    return mech


def six_bar_with_task() -> GroupMechanism:
    """The six-bar press drive, whose second contour starts at the coordinates of ground
    point C, with a task that varies a dimension of every kind."""
    data = yaml.safe_load(SIX_BAR.read_text())
    data["synthesis"] = {
        "vary": {"input.angle": [-20, 20], "groups[0].lengths[0]": [300, 340],
                 "points.D.angle": [120, 150], "groups[1].length": [280, 320],
                 "groups[1].guide.angle": [-10, 10], "ground.O.x": [-20, 20],
                 "ground.C.x": [280, 320], "ground.C.y": [-20, 20],
                 "ground.G.y": [-240, -200]},
        "path": {"point": "E", "targets": [[400, -220], [450, -220]]}}
    return GroupMechanism.model_validate(data)


def points_alone(mech: GroupMechanism) -> dict[str, np.ndarray]:
    """Every named point that moves, solved from the rebuilt groups alone (m, complex)."""
    built = build(mech)
    results = mechloop.solve(built.model)
    out = {}
    for name, where in built.points.items():
        if where.end is not None:
            x, y = where.xy(results)
            out[name] = x + 1j * y
    return out


def points_batched(mech: GroupMechanism, designs: np.ndarray
                   ) -> tuple[SynthesisProblem, np.ndarray, dict[str, np.ndarray]]:
    """The named points of a population ``(D, V)`` (SI) in one call (m, complex
    ``(D, P)``), and the broken mask."""
    built = build(mech)
    problem = SynthesisProblem(built.model)
    results = problem.solve(designs)
    out = {name: problem.place(results, designs, where.end)
           for name, where in built.points.items() if where.end is not None}
    return problem, results.broken, out


# ------------------------------------------------------------------ the names and ties


@pytest.mark.parametrize("make", [example_mechanism, six_bar_with_task],
                         ids=["four-bar", "six-bar"])
def test_changing_a_dimension_variable_is_rebuilding_the_groups(make):
    """(a) Moving one dimension by δ through the synthesis variables moves every point as
    writing the new value in the group file and rebuilding it does — ground coordinates
    included, which set a frame vector's components and contour starts together."""
    mech = make()
    model = build_model(mech)
    problem = SynthesisProblem(model)
    variables = problem.variables
    base = current_values(model, variables)
    span = variables.high - variables.low
    for i, name in enumerate(variables.names):
        design = base.copy()
        design[i] += 0.05 * span[i]
        _, broken, batched = points_batched(mech, design[None, :])
        assert not broken.any(), name
        values = variables.to_model_units(design)
        alone = points_alone(with_dimensions(mech, {name: values[name]}))
        for point, z in alone.items():
            np.testing.assert_allclose(batched[point][0], z, rtol=0, atol=1e-9,
                                       err_msg=f"{name}: point {point}")


def test_the_task_names_dimensions_and_the_model_gets_their_ties():
    model = mechloop.load_model(EXAMPLE)
    task = model.synthesis
    assert list(task.vary) == list(example_mechanism().synthesis.vary)
    sets = {name: [t.set for t in dim.sets] for name, dim in task.dimensions.items()}
    assert sets["groups[0].lengths[1]"] == ["r3"]
    assert sets["points.P.angle"] == ["a5"]                   # the delta of a link role
    assert sets["ground.O.x"] == ["start1.x", "v4.x"]         # a start and the frame C->O
    assert task.path.point == HeadPoint(head=5)
    assert "ground.C.y" in dimension_names(example_mechanism())
    assert "ground.C.distance" not in dimension_names(example_mechanism())


# --------------------------------------------------------------------- the search


@pytest.fixture(scope="module")
def recovered():
    return synthesize(mechloop.load_model(EXAMPLE))


def targets_of(mech: GroupMechanism) -> np.ndarray:
    return np.array([complex(x, y) for x, y in mech.synthesis.path.targets])


def curve_distance(curve: np.ndarray, targets: np.ndarray, steps: int = 400) -> float:
    """Largest distance from a target to the densely resampled closed polyline."""
    t = np.linspace(0, 1, steps, endpoint=False)
    dense = (curve[:-1, None] + (curve[1:] - curve[:-1])[:, None] * t).ravel()
    return float(np.abs(targets[:, None] - dense[None, :]).min(axis=1).max())


def test_synthesis_recovers_the_known_four_bar(recovered):
    """(b) From the bounds, a fixed seed finds a four-bar through the nine targets of the
    coupler curve of examples/four_bar.yaml (crank 100, coupler 350, rocker 250, frame
    300, P 250 mm at 30 deg)."""
    targets = targets_of(example_mechanism())
    size = abs(complex(np.ptp(targets.real), np.ptp(targets.imag)))
    assert recovered.feasible
    assert recovered.q <= 1e-4 * size
    values = recovered.values()
    assert set(values) == set(example_mechanism().synthesis.vary)
    low, high = recovered.problem.variables.low, recovered.problem.variables.high
    assert np.all(recovered.best >= low) and np.all(recovered.best <= high)


def test_the_written_group_file_reloads_and_passes_through_the_targets(recovered, tmp_path):
    """(c) The result is written back as a group file with the dimensions found; loaded
    and solved on its own, its point P passes through the targets."""
    out = write_model(recovered, tmp_path / "best.yaml", mechanism=example_mechanism())
    again = mechanism_of(out)
    assert again is not None and again.synthesis == example_mechanism().synthesis
    values = recovered.values()
    assert again.input.length == pytest.approx(values["input.length"])
    assert again.ground["C"][0] == pytest.approx(values["ground.C.x"])
    assert again.points["P"].angle == pytest.approx(values["points.P.angle"])
    curve = points_alone(again)["P"] * 1000  # mm
    brute = curve_distance(curve, targets_of(again))
    assert brute <= recovered.q + 0.05  # the resampling's error bound is well below this
    # the vector model it generates is the one the search evaluated
    assert mechloop.load_model(out).vectors == recovered.model.vectors


def test_python_route_equals_the_file_route():
    """(3) A GroupMechanism plus a task keyed by dimension names gives the file's result."""
    data = yaml.safe_load(EXAMPLE.read_text())
    task = GroupSynthesisTask.model_validate(data.pop("synthesis"))
    mech = GroupMechanism.model_validate(data).model_copy(update={"synthesis": task})
    short = {"iterations": 8, "polish": False}
    by_code = synthesize(build_model(mech), **short)
    by_file = synthesize(mechloop.load_model(EXAMPLE), **short)
    np.testing.assert_array_equal(by_code.best, by_file.best)
    assert by_code.values() == by_file.values()


def test_cli_writes_the_group_file_back(tmp_path):
    best = tmp_path / "best.yaml"
    result = CliRunner().invoke(app, ["synthesize", str(EXAMPLE), "--iterations", "3",
                                      "-o", str(best)])
    assert result.exit_code == 0, result.output
    assert "group file with the best dimensions" in result.output
    written = yaml.safe_load(best.read_text())
    assert "groups" in written and "vectors" not in written
    assert "ground.C.x" in written["synthesis"]["vary"]
    mechloop.solve(mechloop.load_model(best))


# ----------------------------------------------------------------------- bad names


def test_a_bad_dimension_name_is_located_with_the_names_to_choose_from(tmp_path):
    """(d) An unknown dimension or point: file, line, place, the valid names, a fix."""
    text = EXAMPLE.read_text().replace("groups[0].lengths[0]: [200, 450]",
                                       "groups[0].length[0]: [200, 450]")
    text = text.replace("point: P ", "point: Q ")
    bad = tmp_path / "bad.yaml"
    bad.write_text(text)
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.load_model(bad)
    problems = {p.path: p for p in info.value.problems}
    vary = problems[("synthesis", "vary", "groups[0].length[0]")]
    assert "no dimension named 'groups[0].length[0]'" in vary.message
    assert "did you mean 'groups[0].lengths[0]'" in vary.hint
    assert "ground.C.x" in vary.hint and "points.P.angle" in vary.hint
    line = text.splitlines().index("    groups[0].length[0]: [200, 450]") + 1
    assert vary.line == line
    point = problems[("synthesis", "path", "point")]
    assert "no point named 'Q'" in point.message and "P" in point.hint
    assert str(bad) in str(info.value)


# ------------------------------------------------------------ property: batch == alone


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.lists(st.floats(0, 1), min_size=9, max_size=9), min_size=1,
                max_size=4))
def test_batched_designs_equal_each_group_model_built_and_solved_alone(units):
    """(e) For random dimensions within the bounds, the population evaluated in one call
    gives every named point where the group model rebuilt with those dimensions puts it,
    and breaks exactly where it breaks."""
    mech = example_mechanism()
    problem = SynthesisProblem(build_model(mech))
    designs = problem.variables.scale(np.array(units))
    _, broken, batched = points_batched(mech, designs)
    for d in range(designs.shape[0]):
        values = problem.variables.to_model_units(designs[d])
        alone_model = build_model(with_dimensions(mech, values))
        solved = mechloop.solve(alone_model)
        assert broken[d].any() == bool(solved.breaks)
        if broken[d].any():
            continue
        for name, z in points_alone(with_dimensions(mech, values)).items():
            np.testing.assert_allclose(batched[name][d], z, rtol=0, atol=1e-9,
                                       err_msg=f"design {d}: point {name}")


def test_dimensions_of_a_vector_model_are_checked_at_their_place():
    """A hand-written vector model may name dimensions too; bad ties and names are
    located like any other problem of the task."""
    model = mechloop.load_model(ROOT / "examples" / "four_bar_path_synthesis.yaml")
    data = model.model_dump(mode="json", exclude_defaults=True)
    data["synthesis"]["dimensions"] = {"frame": {"value": 300, "sets": [
        {"set": "r4"}, {"set": "v9.x"}, {"set": "a2"}]}}
    data["synthesis"]["vary"]["frame"] = [200, 400]
    data["synthesis"]["vary"]["frame2"] = [200, 400]
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.Model.from_dict(data)
    text = str(info.value)
    assert "synthesis.dimensions.frame.sets" in text and "both lengths and angles" in text
    assert "no vector 9" in text and "function of its contour" in text
    assert "synthesis.vary.frame2" in text and "neither a constant" in text
    assert "synthesis.vary.r4" in text and "also set by dimension 'frame'" in text


def test_a_rod_inertia_follows_the_length_synthesis_varies():
    """inertia: rod of a link whose centre is on its line is written as 'rod', so a
    design with another length gets m·l²/12 of that length, as rebuilding the groups
    with it does."""
    data = yaml.safe_load((ROOT / "examples" / "crank_slider_groups.yaml").read_text())
    data["masses"]["connecting rod"]["inertia"] = "rod"
    data["synthesis"] = {"vary": {"groups[0].length": [0.15, 0.3]},
                         "criteria": [{"column": "M_bal", "reduce": "absmax",
                                       "minimize": 1.0}]}
    mech = GroupMechanism.model_validate(data)
    model = build_model(mech)
    assert "rod" in {b.inertia for b in model.bodies.values()}
    problem = SynthesisProblem(model)
    design = problem.variables.scale(np.array([0.8]))
    batched = solve_dynamics(problem.design_model(design)).to_frame()["M_bal [N*m]"]
    rebuilt = build_model(with_dimensions(mech, problem.variables.to_model_units(design)))
    alone = solve_dynamics(rebuilt).to_frame()["M_bal [N*m]"]
    np.testing.assert_allclose(batched.to_numpy(), alone.to_numpy(), rtol=1e-12)
    ev = problem.evaluate(design[None, :])
    assert ev.measures["absmax M_bal"][0] == pytest.approx(np.abs(alone).max(), rel=1e-9)
