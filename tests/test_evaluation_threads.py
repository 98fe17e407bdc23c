"""A population evaluated in shares on several threads gives exactly what one call gives,
and the number of threads follows the population's size and the idle cores."""

from __future__ import annotations

import os

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.output import parallel
from mechloop.synthesis import cores
from mechloop.synthesis.problem import Evaluation, SynthesisProblem
from mechloop.synthesis.variables import current_values

#: Problems of different evaluation paths: timed targets at their positions with the
#: exact turn check, free timing at the target inputs, every position with conditions
#: and both circuits, a shape objective with circuits, criteria over the motion, a
#: dynamic criterion (the batched force analysis), a model of groups.
EXAMPLES = ["eighteen_points_timing_synthesis", "six_points_free_timing_synthesis",
            "four_bar_path_synthesis", "four_bar_shape_synthesis",
            "slider_crank_stroke_synthesis", "roof_support_synthesis",
            "four_bar_groups_synthesis"]
_PROBLEMS: dict[str, SynthesisProblem] = {}


def problem_of(name: str) -> SynthesisProblem:
    if name not in _PROBLEMS:
        _PROBLEMS[name] = SynthesisProblem(mechloop.load_model(f"examples/{name}.yaml"))
    return _PROBLEMS[name]


def population(problem: SynthesisProblem, count: int, seed: int) -> np.ndarray:
    """``count`` designs: uniform in the bounds, a quarter of them near the model's own
    design (feasible ones), SI ``(count, V)``."""
    v = problem.variables
    rng = np.random.default_rng(seed)
    designs = v.low + rng.uniform(size=(count, len(v))) * (v.high - v.low)
    near = rng.uniform(size=count) < 0.25
    own = np.clip(current_values(problem.model, v), v.low, v.high)
    designs[near] = np.clip(own + 0.02 * (v.high - v.low) * rng.standard_normal(
        (near.sum(), len(v))), v.low, v.high)
    return designs


#: A design's last digits may depend on its companions in one call, threads or not:
#: NumPy's SIMD loops (sin, cos, exp) may treat an element by a vector or a scalar path
#: depending on the array's length (seen: 7e-16 with free timing).
RTOL = 1e-12
#: The shape objective refines its placements until the whole population has converged
#: (to 1e-12 relative steps), its normal equations summed by einsum in an order that
#: depends on the population's shape (synthesis/shape.py): seen 1.4e-12 relative.
SHAPE_RTOL = 1e-9


def assert_same(a: Evaluation, b: Evaluation, rtol: float = 0.0) -> None:
    """Every field equal: bit for bit, or to ``rtol`` relative."""
    def same(x, y, what):
        x = np.broadcast_to(x, a.total.shape)
        if rtol:
            np.testing.assert_allclose(x, y, rtol=rtol, atol=0, err_msg=what)
        else:
            np.testing.assert_array_equal(x, y, err_msg=what)

    for name in ("total", "q", "feasible", "broken_share", "keeps_variant"):
        same(getattr(a, name), getattr(b, name), name)
    for field in ("terms", "measures"):
        one, other = getattr(a, field), getattr(b, field)
        assert one.keys() == other.keys()
        for key in one:
            same(one[key], other[key], f"{field}[{key}]")


@settings(max_examples=16, deadline=None)
@given(st.sampled_from(EXAMPLES), st.integers(3, 40), st.integers(2, 3),
       st.integers(0, 2**32 - 1))
def test_shares_on_threads_equal_one_call(name, count, threads, seed):
    problem = problem_of(name)
    designs = population(problem, count, seed)
    one = problem.evaluate(designs, threads=1)
    assert one.feasible.any() or name != "eighteen_points_timing_synthesis" or count < 20
    rtol = SHAPE_RTOL if problem.shape is not None else RTOL
    assert_same(one, problem.evaluate(designs, threads=threads), rtol)


def test_the_benchmark_population_is_the_same_on_two_threads():
    """Above the threshold, the benchmark's designs: the kernel runs in both shares."""
    problem = problem_of("eighteen_points_timing_synthesis")
    designs = population(problem, cores.PARALLEL_ELEMENTS // 18 + 1, 1)
    assert cores.evaluation_threads(designs.shape[0], cores.columns_of(problem)) \
        >= min(2, int(cores.idle_cores(own=cores.own_load()) + 0.5))
    one = problem.evaluate(designs, threads=1)
    assert one.feasible.sum() > 10  # the comparison is not only of infeasible designs
    assert_same(one, problem.evaluate(designs, threads=2), RTOL)


def test_a_failing_share_raises_in_the_caller():
    class Failing:
        circuits = ()

        def evaluate(self, designs, *, continuous=False, threads=None):
            if designs[0, 0] > 0:
                raise ValueError("share failed")
            return problem_of("eighteen_points_timing_synthesis").evaluate(
                np.zeros((designs.shape[0], 10)), threads=1)

    designs = np.zeros((10, 10))
    designs[5:, 0] = 1.0  # the second share fails, in the worker thread
    with pytest.raises(ValueError, match="share failed"):
        cores.evaluate_shares(Failing(), designs, 2)
    designs = designs[::-1].copy()  # the first share fails, in this thread
    with pytest.raises(ValueError, match="share failed"):
        cores.evaluate_shares(Failing(), designs, 2)


def test_a_share_runs_under_the_callers_errstate():
    seen = []

    class Recording:
        circuits = ()

        def evaluate(self, designs, *, continuous=False, threads=None):
            seen.append(np.geterr()["invalid"])
            return problem_of("eighteen_points_timing_synthesis").evaluate(
                np.zeros((designs.shape[0], 10)), threads=1)

    with np.errstate(invalid="raise"):
        cores.evaluate_shares(Recording(), np.zeros((6, 10)), 3)
    assert seen == ["raise"] * 3


def test_threads_follow_the_population_and_the_idle_cores(monkeypatch):
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1, 2, 3}, raising=False)
    monkeypatch.setattr(cores, "own_load", lambda: 1.0)  # this process keeps one busy
    monkeypatch.setattr(parallel, "running_threads", lambda: 99)  # the average decides
    big = 10 * cores.PARALLEL_ELEMENTS
    for load, threads in ((0.0, 4), (1.0, 4), (1.6, 3), (2.4, 3), (3.0, 2), (3.6, 1),
                          (8.0, 1)):
        monkeypatch.setattr(os, "getloadavg", lambda load=load: (load, 0.0, 0.0))
        assert cores.evaluation_threads(big) == threads, load
    monkeypatch.setattr(os, "getloadavg", lambda: (1.0, 0.0, 0.0))
    small = cores.PARALLEL_ELEMENTS // 18
    assert cores.evaluation_threads(small, 18) == 1  # too small
    assert cores.evaluation_threads(small + 1, 18) == 2  # a share of half each
    assert cores.evaluation_threads(small + 1, 1) == 1  # fewer positions: too small
    assert cores.evaluation_threads(3, 10**6) == 3  # never more threads than designs
    # a job that has just ended weighs on the average, not on what runs now
    monkeypatch.setattr(os, "getloadavg", lambda: (4.0, 0.0, 0.0))
    for running, threads in ((1, 4), (2, 3), (3, 2), (4, 1), (None, 1)):
        monkeypatch.setattr(parallel, "running_threads", lambda running=running: running)
        assert cores.evaluation_threads(big) == threads, running
    cores._local.inside = True  # inside a share: never split again
    try:
        assert cores.evaluation_threads(big) == 1
    finally:
        cores._local.inside = False


def test_columns_are_the_positions_an_evaluation_solves():
    assert cores.columns_of(problem_of("eighteen_points_timing_synthesis")) == 18
    free = problem_of("six_points_free_timing_synthesis")  # position 0 and 6 inputs
    assert free.inputs_only and cores.columns_of(free) == 1 + 6
    path = problem_of("four_bar_path_synthesis")  # every position, each circuit
    assert cores.columns_of(path) == (path.model.positions + 1) * max(len(path.circuits), 1)


def test_own_load_is_this_process_cpu_rate_averaged_over_a_minute(monkeypatch):
    clock = {"wall": 100.0, "cpu": 10.0}
    monkeypatch.setattr(cores.time, "monotonic", lambda: clock["wall"])
    monkeypatch.setattr(cores.time, "process_time", lambda: clock["cpu"])
    load = cores._OwnLoad()
    for _ in range(600):  # ten minutes at one busy core: the average reaches 1
        clock["wall"] += 1.0
        clock["cpu"] += 1.0
        load()
    assert load() == pytest.approx(1.0, abs=1e-4)
    clock["wall"] += 60.0  # a minute idle: e^-1 of it is left
    assert load() == pytest.approx(np.exp(-1.0), rel=1e-3)


def test_running_threads_counts_the_caller_on_linux():
    if not os.path.exists("/proc/loadavg"):
        pytest.skip("no /proc/loadavg")
    assert parallel.running_threads() >= 1
