"""The dynamic columns of a population solved in one pass (designs × positions) equal each
design solved alone by ``solve_dynamics(problem.design_model(d))``: the oracle."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

import mechloop
from mechloop.dynamics.analysis import solve_dynamics
from mechloop.errors import MechloopError
from mechloop.solve.designs import solve_designs
from mechloop.synthesis.dynamic_batch import dynamic_columns
from mechloop.synthesis.problem import SynthesisProblem

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
RTOL = 1e-9
#: A column that is zero up to rounding (the inertia moment of a point mass about itself)
#: is compared to this absolute floor (SI: N, N·m, m, J, ...).
ATOL = 1e-9


def _example(name: str, synthesis: dict | None = None) -> mechloop.Model:
    data = yaml.safe_load((EXAMPLES / name).read_text())
    if synthesis is not None:
        data["synthesis"] = synthesis
    return mechloop.Model.from_dict(data)


def _roof_support(*, move_base: bool = False) -> mechloop.Model:
    model = mechloop.load_model(EXAMPLES / "roof_support_synthesis.yaml")
    if not move_base:
        return model
    data = model.model_dump(mode="json", exclude_defaults=True)
    data["synthesis"]["vary"].update({"start1.x": [-0.5, 0.5], "start1.y": [0.0, 0.4]})
    return mechloop.Model.from_dict(data)


def _slider_crank() -> mechloop.Model:
    """The time-driven slider-crank at 3000 rpm with its crank, rod, offset, guide angle
    and crank phase varied; a short rod (r2 < r1 + |r4|) breaks the chain."""
    return _example("crank_slider_dynamics.yaml", {
        "vary": {"r1": [0.03, 0.12], "r2": [0.05, 0.2], "r4": [-0.05, 0.05],
                 "a3": [170, 190], "a1": [0, 30]},
        "criteria": [{"column": "M_bal", "reduce": "absmax", "max": 100},
                     {"column": "RA", "reduce": "max", "minimize": 1.0}]})


def _designs(problem: SynthesisProblem, count: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return problem.variables.scale(rng.random((count, len(problem.variables))))


def _all_columns(problem: SynthesisProblem) -> list[str]:
    """Every dynamic column of the model's table (after the kinematic ones)."""
    frame = solve_dynamics(problem.model).to_frame()
    names = [c.split(" [")[0] for c in frame.columns]
    first = next(i for i, n in enumerate(names) if n.startswith(("F_bal", "M_bal")))
    return names[first:-1]  # up to chain_break


def _assert_matches_oracle(problem: SynthesisProblem, designs: np.ndarray,
                           columns: list[str]) -> int:
    """Compare every column with the per-design solve; returns how many designs broke
    somewhere (so a test can require that breaks were exercised)."""
    batch = dynamic_columns(problem, designs, columns)
    broken = 0
    for d, design in enumerate(designs):
        try:
            frame = solve_dynamics(problem.design_model(design)).to_frame()
        except MechloopError:  # a design broken everywhere has no mechanism of its own
            for name in columns:
                assert np.isnan(batch[name][d]).all(), (d, name)
            broken += 1
            continue
        by_name = {c.split(" [")[0]: c for c in frame.columns}
        broken += bool(frame["chain_break"].any())
        for name in columns:
            expected = frame[by_name[name]].to_numpy(dtype=float)
            got = batch[name][d]
            assert got.shape == expected.shape
            np.testing.assert_array_equal(np.isnan(got), np.isnan(expected),
                                          err_msg=f"design {d}, {name}: NaN mask")
            scale = np.nanmax(np.abs(expected), initial=0.0)
            np.testing.assert_allclose(got, expected, rtol=0, atol=RTOL * scale + ATOL,
                                       err_msg=f"design {d}, {name}")
    return broken


def test_roof_support_leg_force_and_every_column_match_each_design_alone():
    problem = SynthesisProblem(_roof_support())
    designs = _designs(problem, 20, seed=1)
    _assert_matches_oracle(problem, designs, _all_columns(problem))


def test_varied_contour_start_moves_the_points_of_each_design():
    problem = SynthesisProblem(_roof_support(move_base=True))
    designs = _designs(problem, 12, seed=2)
    _assert_matches_oracle(problem, designs, ["F_bal", "RJ0_2", "xS1", "yS", "xS2"])


def test_time_driven_slider_crank_matches_each_design_alone_breaks_included():
    problem = SynthesisProblem(_slider_crank())
    designs = _designs(problem, 24, seed=3)
    broken = _assert_matches_oracle(problem, designs, _all_columns(problem))
    assert broken > 0  # the sample reaches designs whose chain breaks


def test_columns_come_out_designs_by_positions():
    problem = SynthesisProblem(_slider_crank())
    designs = _designs(problem, 3, seed=4)
    out = dynamic_columns(problem, designs, ["M_bal", "RA"])
    assert set(out) == {"M_bal", "RA"}
    assert out["M_bal"].shape == (3, problem.model.positions + 1)
    one = dynamic_columns(problem, designs[1], ["M_bal"])["M_bal"]  # (V,) is one design
    np.testing.assert_allclose(one, out["M_bal"][1:2], rtol=1e-12)  # not bit for bit:
    # a stack of 3 force systems is inverted and multiplied in other kernels than 1
    solved = solve_designs(problem.model, problem.variables.overrides(designs))
    given = dynamic_columns(problem, designs, ["M_bal", "RA"], kinematics=solved)
    for name in ("M_bal", "RA"):
        np.testing.assert_array_equal(given[name], out[name])


def test_unknown_column_names_the_columns_there_are():
    problem = SynthesisProblem(_slider_crank())
    with pytest.raises(KeyError, match="M_bal"):
        dynamic_columns(problem, _designs(problem, 2, seed=5), ["F_bal"])


@pytest.mark.parametrize("example, reason", [
    ("crank_slider_friction.yaml", "friction"),
    ("single_cylinder_engine.yaml", "machine"),
])
def test_what_the_batch_does_not_do_is_refused_with_the_reason(example, reason):
    data = yaml.safe_load((EXAMPLES / example).read_text())
    number, value = next((k, float(v["r"])) for k, v in data["vectors"].items()
                         if isinstance(v["r"], int | float))
    data["synthesis"] = {"vary": {f"r{number}": [0.9 * value, 1.1 * value]},
                         "criteria": [{"column": "M_bal", "reduce": "absmax",
                                       "minimize": 1.0}]}
    problem = SynthesisProblem(mechloop.Model.from_dict(data))
    with pytest.raises(NotImplementedError, match=reason):
        dynamic_columns(problem, _designs(problem, 2, seed=6), ["M_bal"])


def test_an_empty_population_gives_empty_columns():
    problem = SynthesisProblem(_slider_crank())
    out = dynamic_columns(problem, np.empty((0, len(problem.variables))), ["M_bal"])
    assert out["M_bal"].shape == (0, problem.model.positions + 1)


def test_synthesis_uses_the_batch_and_agrees_with_the_loop(monkeypatch):
    """The roof support's F_bal criterion: the problem's batched measure equals the
    per-design force analysis, and the per-design loop is not taken."""

    problem = SynthesisProblem(mechloop.load_model(EXAMPLES / "roof_support_synthesis.yaml"))
    rng = np.random.default_rng(5)
    designs = problem.variables.scale(rng.uniform(size=(12, len(problem.variables))))
    ev = problem.evaluate(designs)
    loop = np.array([problem._dynamic_value(d, problem.task.criteria[2]) if f else np.nan
                     for d, f in zip(designs, ev.feasible, strict=True)])
    np.testing.assert_allclose(ev.measures["max F_bal"], loop, rtol=1e-9)

    def forbidden(*args, **kwargs):
        raise AssertionError("the per-design loop was taken")

    monkeypatch.setattr(SynthesisProblem, "_dynamic_value", forbidden)
    again = problem.evaluate(designs)
    np.testing.assert_array_equal(again.measures["max F_bal"], ev.measures["max F_bal"])


def test_efficiency_and_friction_models_fall_back_to_the_force_analysis_per_design():
    """Efficiency and the loss coefficient are numbers of the cycle, and friction is not
    batched: both are taken from solve_dynamics of each design."""
    data = yaml.safe_load((EXAMPLES / "crank_slider_friction.yaml").read_text())
    data["synthesis"] = {"vary": {"r2": [0.15, 0.3]}, "criteria": [
        {"column": "efficiency", "min": 0.5},
        {"column": "loss_coefficient", "max": 0.5},
        {"column": "M_bal", "reduce": "absmax", "minimize": 1.0}]}
    problem = SynthesisProblem(mechloop.Model.from_dict(data))
    designs = problem.variables.scale(np.array([[0.0], [0.4], [1.0]]))
    ev = problem.evaluate(designs)
    assert ev.feasible.all()
    for d, design in enumerate(designs):
        result = solve_dynamics(problem.design_model(design))
        assert ev.measures["efficiency"][d] == pytest.approx(
            result.summary.efficiency, nan_ok=True)
        assert ev.measures["loss_coefficient"][d] == pytest.approx(
            result.summary.loss_coefficient, nan_ok=True)
        m_bal = result.to_frame()["M_bal [N*m]"].to_numpy()
        assert ev.measures["absmax M_bal"][d] == pytest.approx(np.abs(m_bal).max(),
                                                               rel=1e-12)
    with pytest.raises(MechloopError):
        data["synthesis"]["criteria"] = [{"column": "efficency", "min": 0.5}]
        SynthesisProblem(mechloop.Model.from_dict(data))
