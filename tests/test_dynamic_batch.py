"""The dynamic columns of a population solved in one pass (designs × positions) equal each
design solved alone by ``solve_dynamics(problem.design_model(d))``: the oracle."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml

import mechloop
from mechloop.dynamics.analysis import solve_dynamics
from mechloop.errors import MechloopError, SolveError
from mechloop.model.synthesis import CYCLE_VALUES
from mechloop.solve.designs import solve_designs
from mechloop.synthesis.dynamic_batch import cycle_value, dynamic_columns
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
            result = solve_dynamics(problem.design_model(design))
        except MechloopError:  # a design broken everywhere has no mechanism of its own,
            for name in columns:  # one whose friction does not settle no result
                assert np.isnan(batch[name][d]).all(), (d, name)
            broken += 1
            continue
        frame = result.to_frame()
        by_name = {c.split(" [")[0]: c for c in frame.columns}
        broken += bool(frame["chain_break"].any())
        for name in columns:
            if name in CYCLE_VALUES:  # one number of the cycle per design
                expected = cycle_value(result, name)
                assert batch[name].shape == (len(designs),)
                assert batch[name][d] == pytest.approx(expected, rel=RTOL, abs=ATOL,
                                                       nan_ok=True), (d, name)
                continue
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


# ---- machine models: the steady cycle of every design ----------------------------------
MACHINE_NUMBERS = ["delta", "flywheel", "constant_load", "efficiency"]


def _forbid_the_loop(monkeypatch) -> None:
    """Make the per-design fallback of the problem fail, so a passing evaluation proves
    the batch was used."""
    def forbidden(*args, **kwargs):
        raise AssertionError("the per-design loop was taken")

    monkeypatch.setattr(SynthesisProblem, "_dynamic_value", forbidden)


def _engine() -> SynthesisProblem:
    """examples/single_cylinder_engine.yaml at 1000 rpm instead of 3000 (a third of the
    speed, a ninth of the kinetic energy), its crank r1 and rod r2 varied: a long crank
    makes the cycle's work swing more than the kinetic energy it has, so the machine stops
    without a flywheel, and a rod shorter than the crank breaks the chain."""
    data = yaml.safe_load((EXAMPLES / "single_cylinder_engine.yaml").read_text())
    data["time"]["rpm"] = 1000
    data["synthesis"] = {"vary": {"r1": [20, 60], "r2": [30, 200]},
                         "criteria": [{"column": "M_bal", "reduce": "absmax",
                                       "minimize": 1.0},
                                      {"column": "omega", "reduce": "range", "max": 50},
                                      {"column": "delta", "max": 1.5},
                                      {"column": "flywheel", "minimize": 10.0},
                                      {"column": "constant_load", "minimize": 0.01}]}
    return SynthesisProblem(mechloop.Model.from_dict(data))


def _failures(problem: SynthesisProblem, designs: np.ndarray) -> list[str]:
    """How each design solves alone: 'ok', 'stops' or 'breaks'."""
    out = []
    for design in designs:
        try:
            solve_dynamics(problem.design_model(design))
            out.append("ok")
        except SolveError as error:
            out.append("stops" if "stops" in str(error) else "breaks")
    return out


def test_machine_columns_and_numbers_of_every_engine_design_match_each_alone():
    problem = _engine()
    designs = _designs(problem, 12, seed=1)
    assert {"ok", "stops", "breaks"} <= set(_failures(problem, designs))
    columns = _all_columns(problem)
    assert {"omega", "epsilon", "omega_fw", "epsilon_fw", "RJ1_2", "M_bal"} <= set(columns)
    broken = _assert_matches_oracle(problem, designs, columns + MACHINE_NUMBERS)
    assert broken == 4  # 3 stop and 1 breaks: NaN in every column, as the loop gives
    # without a flywheel column the flywheel is not sized: the rest is the same
    some = ["M_bal", "omega", "delta", "constant_load"]
    every = dynamic_columns(problem, designs, [*some, "flywheel"])
    for name, values in dynamic_columns(problem, designs, some).items():
        np.testing.assert_array_equal(values, every[name], err_msg=name)


def test_engine_criteria_use_the_batch_and_agree_with_the_loop(monkeypatch):
    problem = _engine()
    designs = _designs(problem, 12, seed=1)
    ev = problem.evaluate(designs)
    assert ev.feasible.sum() == 8  # NaN measures (3 stop) and a break are infeasible
    for i, crit in enumerate(problem.task.criteria):  # the loop gives NaN for all 4
        loop = np.array([problem._dynamic_value(d, crit) for d in designs])
        assert np.isnan(loop).sum() == 4, crit.column
        np.testing.assert_allclose(ev.measures[problem.criterion_keys[i]], loop,
                                   rtol=RTOL, atol=ATOL, err_msg=crit.column)

    _forbid_the_loop(monkeypatch)
    again = problem.evaluate(designs)
    for key in problem.criterion_keys:
        np.testing.assert_array_equal(again.measures[key], ev.measures[key])


def test_machine_numbers_are_nan_for_a_model_without_them():
    problem = SynthesisProblem(_slider_crank())
    designs = _designs(problem, 3, seed=8)
    out = dynamic_columns(problem, designs, ["delta", "flywheel", "constant_load"])
    for name, values in out.items():
        assert values.shape == (3,) and np.isnan(values).all(), name
    result = solve_dynamics(problem.design_model(designs[0]))
    assert np.isnan(cycle_value(result, "delta"))


def test_a_stack_of_cycles_equals_each_cycle_alone_failures_as_nan():
    """steady_cycles on cycles with their own q (two grids) and one machine that stops:
    each cycle is steady_cycle's, the one that stops NaN with computed False."""
    from mechloop.dynamics.cycle import steady_cycle, steady_cycles
    from mechloop.dynamics.reduced import Reduced
    from mechloop.model.dynamic import Machine

    n = 73
    phi = np.linspace(0.0, 2 * np.pi, n)
    grids = [phi, phi + 0.5, phi, phi]
    j = np.array([np.full(n, 0.5), 0.5 + 0.1 * np.cos(phi), np.full(n, 0.5),
                  np.full(n, 0.001)])  # the last stops: the mean speed at zero energy at
    # the slowest point, √(2·2·M0/J)/2 ≈ 141 rad/s, already exceeds ω_mean = 62.8 rad/s
    load = 20.0 * np.sin(phi) + np.array([[0.0], [5.0], [-3.0], [0.0]])
    omega = 2 * np.pi * 600 / 60
    times = [(q - q[0]) / omega for q in grids]
    spec = Machine(delta=0.01, friction=False)
    zero = np.zeros((4, n))
    stack = steady_cycles(np.array(grids), np.array(times),
                          Reduced(j, np.gradient(j, phi, axis=-1), load), zero, zero, spec)
    np.testing.assert_array_equal(stack.computed, [True, True, True, False])
    for d in range(3):
        alone = steady_cycle(grids[d], times[d], Reduced(j[d], np.gradient(j[d], phi),
                                                         load[d]), zero[d], zero[d], spec)
        for name in ("constant_load", "flywheel", "flywheel_approx", "omega_mean"):
            assert getattr(stack, name)[d] == pytest.approx(getattr(alone, name),
                                                            rel=1e-12), name
        for motion in ("motion", "with_flywheel"):
            for name in ("omega", "epsilon", "time", "kinetic_energy"):
                np.testing.assert_allclose(getattr(getattr(stack, motion), name)[d],
                                           getattr(getattr(alone, motion), name),
                                           rtol=1e-12, err_msg=f"{motion}.{name}")
    with pytest.raises(SolveError, match="stops"):
        steady_cycle(grids[3], times[3], Reduced(j[3], np.gradient(j[3], phi), load[3]),
                     zero[3], zero[3], spec)
    assert np.isnan(stack.motion.omega[3]).all() and np.isnan(stack.flywheel[3])
    assert not stack.motion.runs[3]


def test_an_empty_population_gives_empty_columns():
    problem = SynthesisProblem(_slider_crank())
    out = dynamic_columns(problem, np.empty((0, len(problem.variables))),
                          ["M_bal", "efficiency"])
    assert out["M_bal"].shape == (0, problem.model.positions + 1)
    assert out["efficiency"].shape == (0,)


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

    _forbid_the_loop(monkeypatch)
    again = problem.evaluate(designs)
    np.testing.assert_array_equal(again.measures["max F_bal"], ev.measures["max F_bal"])


# ---- friction and the cycle's numbers ---------------------------------------------------
#: The piston force of examples/crank_slider_friction.yaml on the return stroke only (a
#: compressor, as tests/test_dynamics_friction.py), so that the cycle has useful work and
#: the efficiency lies strictly between 0 and 1.
COMPRESSOR = {"name": "P", "body": 3, "at": {"tail": 3}, "angle": 180.0,
              "value": {"table": {0: 0.0, 36: 0.0, 38: 1000.0, 70: 1000.0, 72: 0.0}}}

#: Designs (r2, r4) of the friction slider-crank (r1 = 0.05 m) and how each solves alone:
#: settles in 11 friction iterations (the example's own design); settles in 30;
#: settles in 71 with the chain broken at 11 positions (r2 < r1 + r4); does not settle
#: (a dead point at r2 = r1 + r4, where the slider jams).  Iteration counts from
#: ``solve_dynamics(...).forces.iterations`` of each design, checked in the tests.
SETTLES_11, SETTLES_30, SETTLES_71, NEVER = (0.2, 0.01), (0.075, 0.02), (0.075, 0.03), \
    (0.08, 0.03)
FRICTION_COLUMNS = ["M_bal", "M_bal_vp", "RA", "RS_n", "friction_loss", "efficiency",
                    "loss_coefficient"]


def _friction_problem(criteria: list | None = None) -> SynthesisProblem:
    """The friction slider-crank as a compressor, its rod r2 and offset r4 varied."""
    return SynthesisProblem(_example_with("crank_slider_friction.yaml", {
        "vary": {"r2": [0.06, 0.25], "r4": [-0.03, 0.03]},
        "criteria": criteria or [{"column": "efficiency", "min": 0.25},
                                 {"column": "loss_coefficient", "max": 0.8},
                                 {"column": "M_bal", "reduce": "absmax", "minimize": 1.0},
                                 {"column": "friction_loss", "reduce": "mean",
                                  "minimize": 1e-3}]},
        forces=[COMPRESSOR]))


def _example_with(name: str, synthesis: dict, **changes) -> mechloop.Model:
    data = yaml.safe_load((EXAMPLES / name).read_text())
    data.update(changes, synthesis=synthesis)
    return mechloop.Model.from_dict(data)


def _spy_forces(monkeypatch) -> list:
    """Record every force analysis dynamic_columns does (in the dynamics' own
    :func:`~mechloop.dynamics.analysis.analyze`, the one path of solve_dynamics too)."""
    from mechloop.dynamics import analysis

    seen = []

    def spy(*args, **kwargs):
        seen.append(kinetostatics(*args, **kwargs))
        return seen[-1]

    kinetostatics = analysis.kinetostatics
    monkeypatch.setattr(analysis, "kinetostatics", spy)
    return seen


def test_friction_columns_and_cycle_numbers_match_each_design_alone():
    problem = _friction_problem()
    designs = _designs(problem, 20, seed=7)  # 2 of them do not settle (r2 ≈ r1 + |r4|)
    unsettled = _assert_matches_oracle(problem, designs, FRICTION_COLUMNS)
    assert unsettled > 0
    out = dynamic_columns(problem, designs, ["efficiency"])["efficiency"]
    assert np.nanmin(out) > 0 and np.nanmax(out) < 1  # a compressor loses some work


def test_each_design_iterates_friction_as_if_alone(monkeypatch):
    """Designs that settle after 11, 30 and 71 iterations in one batch: each stops at its
    own count (and keeps that iteration's reactions), as when it is solved alone."""
    problem = _friction_problem()
    designs = np.array([SETTLES_71, SETTLES_11, SETTLES_30])
    alone = [solve_dynamics(problem.design_model(d)) for d in designs]
    assert [a.forces.iterations for a in alone] == [71, 11, 30]
    seen = _spy_forces(monkeypatch)
    population = solve_designs(problem.model, problem.variables.overrides(designs),
                               derivatives=True)
    batch = dynamic_columns(problem, designs, FRICTION_COLUMNS, kinematics=population)
    np.testing.assert_array_equal(seen[-1].segment_iterations, [71, 11, 30])
    assert seen[-1].iterations == 71 and not seen[-1].unsettled.any()
    for d in range(len(designs)):  # the same kinematics, the design on its own
        one = dynamic_columns(problem, designs[d], FRICTION_COLUMNS,
                              kinematics=population.subset(np.array([d])))
        np.testing.assert_array_equal(seen[-1].segment_iterations, [alone[d].forces.iterations])
        for name in FRICTION_COLUMNS:  # other kernels for a stack of 1: 1e-12
            np.testing.assert_allclose(batch[name][d], one[name][0], rtol=1e-12,
                                       atol=1e-12, err_msg=name)
        frame = alone[d].to_frame()
        np.testing.assert_allclose(batch["friction_loss"][d],
                                   frame["friction_loss [W]"].to_numpy(), rtol=1e-9)


def test_a_design_whose_friction_does_not_settle_is_nan_and_the_others_are_right(
        monkeypatch):
    problem = _friction_problem()
    designs = np.array([SETTLES_11, NEVER, SETTLES_30])
    with pytest.raises(SolveError, match="did not settle"):
        solve_dynamics(problem.design_model(designs[1]))
    seen = _spy_forces(monkeypatch)
    out = dynamic_columns(problem, designs, FRICTION_COLUMNS)
    forces = seen[-1]
    n_pos = problem.model.positions + 1
    np.testing.assert_array_equal(forces.unsettled.reshape(3, n_pos).all(axis=1),
                                  [False, True, False])
    np.testing.assert_array_equal(forces.segment_iterations, [11, 200, 30])
    for name in FRICTION_COLUMNS:
        assert np.isnan(out[name][1]).all(), name
    _assert_matches_oracle(problem, designs, FRICTION_COLUMNS)
    # the problem's criteria give NaN for it, as its own solve does in the fallback
    assert np.isnan(problem._dynamic_value(designs[1], problem.task.criteria[0]))


def test_friction_and_efficiency_criteria_use_the_batch_and_agree_with_each_design(
        monkeypatch):
    """Efficiency and the loss coefficient (numbers of the cycle) and the columns of a
    model with friction come from the batch, not from solve_dynamics design by design,
    and equal what solve_dynamics of each design gives."""
    data = yaml.safe_load((EXAMPLES / "crank_slider_friction.yaml").read_text())
    data["synthesis"] = {"vary": {"r2": [0.15, 0.3]}, "criteria": [
        {"column": "efficiency", "min": 0.5},
        {"column": "loss_coefficient", "max": 0.5},
        {"column": "M_bal", "reduce": "absmax", "minimize": 1.0}]}
    problem = SynthesisProblem(mechloop.Model.from_dict(data))
    designs = problem.variables.scale(np.array([[0.0], [0.4], [1.0]]))

    _forbid_the_loop(monkeypatch)
    ev = problem.evaluate(designs)
    assert ev.feasible.all()
    for d, design in enumerate(designs):
        result = solve_dynamics(problem.design_model(design))
        assert ev.measures["efficiency"][d] == pytest.approx(
            result.summary.efficiency, rel=RTOL, abs=ATOL, nan_ok=True)
        assert ev.measures["loss_coefficient"][d] == pytest.approx(
            result.summary.loss_coefficient, rel=RTOL, nan_ok=True)
        m_bal = result.to_frame()["M_bal [N*m]"].to_numpy()
        assert ev.measures["absmax M_bal"][d] == pytest.approx(np.abs(m_bal).max(),
                                                               rel=1e-12)
    with pytest.raises(MechloopError):
        data["synthesis"]["criteria"] = [{"column": "efficency", "min": 0.5}]
        SynthesisProblem(mechloop.Model.from_dict(data))


def test_the_compressor_population_is_evaluated_by_the_batch(monkeypatch):
    """A population with designs that do not settle: the measures of every criterion
    equal the per-design loop's (NaN for those designs) and the loop is not taken."""
    problem = _friction_problem()
    designs = _designs(problem, 12, seed=7)
    ev = problem.evaluate(designs)
    for i, crit in enumerate(problem.task.criteria):
        loop = np.array([problem._dynamic_value(d, crit) if f else np.nan
                         for d, f in zip(designs, ev.feasible, strict=True)])
        np.testing.assert_allclose(ev.measures[problem.criterion_keys[i]], loop,
                                   rtol=RTOL, atol=ATOL)

    _forbid_the_loop(monkeypatch)
    again = problem.evaluate(designs)
    for key in problem.criterion_keys:
        np.testing.assert_array_equal(again.measures[key], ev.measures[key])


def test_machine_numbers_need_a_machine_section():
    data = yaml.safe_load((EXAMPLES / "crank_slider_friction.yaml").read_text())
    data["synthesis"] = {"vary": {"r2": [0.15, 0.3]},
                         "criteria": [{"column": "delta", "max": 0.05},
                                      {"column": "M_bal", "minimize": 1.0}]}
    with pytest.raises(MechloopError) as info:
        mechloop.Model.from_dict(data)
    assert "synthesis.criteria[0].column" in str(info.value)
    assert "no machine: section" in str(info.value)
