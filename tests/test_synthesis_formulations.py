"""The formulations of the literature's path problems: both assembly circuits in one run,
the crank turning either way, periodic angle variables, a timed parametric curve, the
distance to the continuous curve, and the shape-only objective (free placement).

The reference mechanism is the four-bar of examples/four_bar_path_synthesis.yaml
(crank 100, coupler 350, rocker 250, frame 300 mm, P 250 mm from A at 30 deg to AB);
its coupler point is computed here independently, by intersecting two circles.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import mechloop
from mechloop.errors import ModelError
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import synthesize
from mechloop.synthesis.variables import compile_variables

PATH = "examples/four_bar_path_synthesis.yaml"
FREE = "examples/six_points_free_timing_synthesis.yaml"
KNOWN = {"r1": 100, "r2": 350, "r3": 250, "r4": 300, "a4": 180, "r6": 250, "a6": 30}


def coupler_point(theta):
    """P (mm, x + iy) at the crank angle ``theta`` (rad) by circle intersection: A on
    the crank circle about O = 0, B at 350 from A and 250 from C = (300, 0), on the
    side of the example's variant 1; P 250 from A at 30 deg to AB."""
    a = 100 * np.exp(1j * np.asarray(theta))
    c = 300 + 0j
    d = np.abs(c - a)
    along = (350**2 - 250**2 + d**2) / (2 * d)
    b = a + (c - a) / d * (along + 1j * np.sqrt(350**2 - along**2))
    return a + 250 * np.exp(1j * (np.angle(b - a) + np.radians(30)))


def path_data(**synthesis) -> dict:
    data = mechloop.load_model(PATH).model_dump(mode="json", exclude_defaults=True)
    data["synthesis"].pop("pressure_angle")
    data["synthesis"].update(synthesis)
    return data


def known_row(problem: SynthesisProblem, values=KNOWN) -> np.ndarray:
    v = problem.variables
    return np.array([values.get(n, 0.0) * (np.pi / 180 if v.kind(i) == "angle" else 1e-3)
                     for i, n in enumerate(v.names)])


def with_targets(data: dict, points) -> dict:
    data["synthesis"]["path"]["targets"] = [[float(p.real), float(p.imag)] for p in points]
    return data


# ------------------------------------------------------------------ crank direction
def free_problem(direction: str) -> SynthesisProblem:
    data = mechloop.load_model(FREE).model_dump(mode="json", exclude_defaults=True)
    data["synthesis"]["path"]["direction"] = direction
    return SynthesisProblem(mechloop.Model.from_dict(data))


def test_a_design_reaching_the_targets_backwards_is_in_order_when_decreasing():
    """Column 7 of the published designs (tests/test_free_timing.py) reaches the six
    points while the crank angle decreases, column 8 while it increases."""
    from test_free_timing import PUBLISHED, si_row

    for direction, backwards_ok, forwards_ok in [("increasing", False, True),
                                                  ("decreasing", True, False),
                                                  ("either", True, True)]:
        problem = free_problem(direction)
        for name, ok in (("column 7", backwards_ok), ("column 8", forwards_ok)):
            ev = problem.evaluate(si_row(problem, PUBLISHED[name])[None, :])
            assert ev.q[0] < 2e-11
            assert (ev.measures["order"][0] == 0) == ok, (direction, name)
            assert (ev.total[0] == ev.q[0]) == ok


@settings(max_examples=30, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.floats(0, 2 * np.pi), min_size=6, max_size=6))
def test_either_direction_is_the_lesser_overlap(inputs):
    problems = {d: free_problem(d) for d in ("increasing", "decreasing", "either")}
    design = problems["either"].variables.scale(np.full(15, 0.5))
    design[9:] = inputs
    found = {d: p.order_violation(design[None, :])[0] for d, p in problems.items()}
    assert found["either"] == min(found["increasing"], found["decreasing"])
    reverse = design.copy()
    reverse[9:] = inputs[::-1]
    assert problems["decreasing"].order_violation(reverse[None, :])[0] == \
        pytest.approx(found["increasing"], abs=1e-12)


def test_direction_needs_free_timing():
    data = path_data()
    data["synthesis"]["path"]["direction"] = "either"
    with pytest.raises(ModelError, match=r"synthesis\.path\.direction"):
        mechloop.Model.from_dict(data)


# ------------------------------------------------------------------ periodic angles
def test_periodic_angles_have_a_turn_and_wrap():
    data = path_data()
    data["synthesis"]["vary"].update({"a4": "periodic", "a6": [-180, 180]})
    variables = compile_variables(mechloop.Model.from_dict(data))
    names = variables.names
    periodic = dict(zip(names, variables.periodic, strict=True))
    assert periodic["a4"] and periodic["a6"] and not periodic["r1"]
    i4, i6 = names.index("a4"), names.index("a6")
    assert variables.low[i4] == 0 and variables.high[i4] == pytest.approx(2 * np.pi)
    assert variables.low[i6] == pytest.approx(-np.pi)
    lower, upper = variables.unit_bounds()
    assert np.isinf(lower[i4]) and lower[0] == 0 and upper[0] == 1


@functools.cache
def full_turn_variables():
    data = path_data()
    data["synthesis"]["vary"]["a4"] = [0, 360]
    return compile_variables(mechloop.Model.from_dict(data))


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.lists(st.floats(-3, 4), min_size=9, max_size=9))
def test_scale_wraps_a_periodic_column_and_clips_none(unit):
    variables = full_turn_variables()
    unit = np.array(unit)
    inside = variables.clip_unit(unit)
    design = variables.scale(inside)
    i4 = variables.names.index("a4")
    assert np.all((design >= variables.low) & (design <= variables.high))
    turns = unit[i4] % 1.0 if unit[i4] % 1.0 < 1.0 else 0.0  # -1e-300 % 1 is 1.0
    assert design[i4] == pytest.approx(2 * np.pi * turns, abs=1e-12)
    assert design[i4] < variables.high[i4]
    again = variables.clip(design + 2 * np.pi * variables.periodic)
    assert again[i4] == pytest.approx(design[i4], abs=1e-12) or \
        abs(again[i4] - design[i4]) == pytest.approx(2 * np.pi, abs=1e-12)  # at the cut
    np.testing.assert_allclose(np.delete(again, i4), np.delete(design, i4))
    assert variables.unscale(design)[i4] == pytest.approx(turns, abs=1e-12)


def test_a_length_is_not_periodic():
    data = path_data()
    data["synthesis"]["vary"]["r1"] = "periodic"
    with pytest.raises(ModelError, match=r"synthesis\.vary\.r1"):
        mechloop.Model.from_dict(data)


def test_an_optimum_on_the_cut_is_reached_across_it():
    """The coupler point's angle a6 varies over [30, 390] deg, a full turn cut exactly at
    the answer (30 deg): the search crosses the cut and ends on the answer, within
    the turn."""
    data = path_data(vary={"a6": [30, 390], "r6": [150, 350]})
    for key in ("1", "2", "3", "4"):
        data["vectors"][key]["r"] = KNOWN[f"r{key}"]
    data["vectors"]["6"]["a"]["delta"] = 200
    data["synthesis"]["search"] = {"method": "cmaes", "seed": 2, "population": 12,
                                   "iterations": 40}
    result = synthesize(mechloop.Model.from_dict(data))
    a6 = result.values()["a6"]
    assert 30 <= a6 < 390
    assert min(abs(a6 - 30), abs(a6 - 390)) < 1e-3
    assert result.q < 1e-4


# ------------------------------------------------------------------ timed curve
def coupler_expressions() -> dict[str, str]:
    """x(t), y(t) of :func:`coupler_point` at the crank angle t (deg), written in the
    target expression language."""
    ax, ay = "(100*cos(radians(t)))", "(100*sin(radians(t)))"
    dx, dy = f"(300 - {ax})", f"(-{ay})"
    d2 = f"({dx}**2 + {dy}**2)"
    along = f"((350**2 - 250**2 + {d2}) / (2*sqrt({d2})))"
    h = f"sqrt(350**2 - {along}**2)"
    phi = f"(arctan2({dy}*{along} + {dx}*{h}, {dx}*{along} - {dy}*{h}) + radians(30))"
    return {"x": f"{ax} + 250*cos({phi})", "y": f"{ay} + 250*sin({phi})"}


def test_a_timed_curve_is_reached_at_its_inputs():
    """The curve x(t), y(t) is P at the crank angle t: with timing, the known design
    reaches every target at t (error ~0), and a crank turned 5 deg further does not."""
    theta = np.radians(np.linspace(10, 300, 7))
    p = coupler_point(theta)
    curve = {**coupler_expressions(), "t": [10, 300], "count": 7}
    data = path_data()
    data["synthesis"]["path"].update(targets=curve, timing=True)
    problem = SynthesisProblem(mechloop.Model.from_dict(data))
    np.testing.assert_allclose(problem.timed_inputs, theta, rtol=1e-12)
    np.testing.assert_allclose(problem.targets * 1e3, p, rtol=1e-12)
    ev = problem.evaluate(known_row(problem)[None, :])
    assert ev.feasible[0] and ev.q[0] < 1e-9
    data["vectors"]["1"]["a"]["offset"] = 5
    late = SynthesisProblem(mechloop.Model.from_dict(data))
    ev = late.evaluate(known_row(late)[None, :])
    expected = np.abs(coupler_point(theta + np.radians(5)) - p).max()
    assert ev.q[0] == pytest.approx(expected, rel=1e-7)
    res = problem.residuals(known_row(problem)[None, :])
    assert res.shape == (1, 14) and np.abs(res).max() < 1e-7


def test_a_timed_curve_needs_argument_one_and_fixed_variants():
    data = path_data()
    data["synthesis"]["path"].update(targets={"x": "t", "y": "t"}, timing=True)
    data["contours"][0]["variant"] = "auto"
    with pytest.raises(ModelError, match=r"contours\.0\.variant|contours\[0\]"):
        mechloop.Model.from_dict(data)


# ------------------------------------------------------------------ both circuits
def test_a_design_on_the_other_circuit_is_scored_and_written():
    data = path_data()
    data["contours"][0]["variant"] = 2
    given_only = SynthesisProblem(mechloop.Model.from_dict(data))
    x = known_row(given_only)
    assert given_only.evaluate(x[None, :]).q[0] > 100
    data["synthesis"]["circuits"] = "both"
    both = SynthesisProblem(mechloop.Model.from_dict(data))
    assert len(both.circuits) == 2
    ev = both.evaluate(np.stack([x, x]))
    assert (ev.q < 1e-4).all()
    assert (ev.measures["variant1"] == 1).all()
    model = both.design_model(x)
    assert model.contours[0].variant == 1 and model.synthesis.circuits == "both"
    assert both.residuals(x[None, :]).shape == (1, 9)
    assert np.abs(both.residuals(x[None, :])).max() < 1e-4
    data["synthesis"]["circuits"] = [1]
    listed = SynthesisProblem(mechloop.Model.from_dict(data))
    assert listed.evaluate(x[None, :]).q[0] == ev.q[0]


def test_a_circuit_of_a_one_solution_contour_is_refused():
    data = path_data(circuits=[2])
    with pytest.raises(ModelError, match=r"synthesis\.circuits"):
        SynthesisProblem(mechloop.Model.from_dict(data))
    data = path_data(circuits=[3])
    with pytest.raises(ModelError, match="no contour 3"):
        mechloop.Model.from_dict(data)


# ------------------------------------------------------------------ continuous curve
def test_continuous_distance_is_the_distance_to_the_curve():
    """Each target's continuous distance equals the distance to the curve of the
    circle-intersection point (independent), minimized by parabolas through the squared
    distance on shrinking steps from a 0.5 deg grid, and the polyline's differs."""
    problem = SynthesisProblem(mechloop.Model.from_dict(path_data()))
    x = known_row(problem)[None, :]
    res = problem.solve(x)
    found = problem.deviations(res, x, continuous=True)[0]
    polyline = problem.deviations(res, x)[0]
    grid = np.radians(np.arange(0, 360, 0.5))
    for k, target in enumerate(problem.targets * 1e3):
        t = grid[np.argmin(np.abs(coupler_point(grid) - target))]
        for h in (1e-3, 1e-5, 1e-7):
            f0, f1, f2 = np.abs(coupler_point(t + np.array([-h, 0, h])) - target) ** 2
            t += h * (f0 - f2) / (2 * (f0 - 2 * f1 + f2))
        assert found[k] == pytest.approx(abs(coupler_point(t) - target), rel=1e-7)
    assert np.abs(found - polyline).max() > 1e-8


def test_the_reported_result_is_measured_on_the_curve():
    model = mechloop.Model.from_dict(path_data())
    result = synthesize(model, method="de", iterations=2, population=20, polish=False,
                        start={k: v for k, v in KNOWN.items()})
    problem = result.problem
    assert result.q == pytest.approx(problem.evaluate(result.best[None, :],
                                                      continuous=True).q[0], rel=1e-12)


# ------------------------------------------------------------------ shape only
def shape_problem(points, frame="free") -> SynthesisProblem:
    data = with_targets(path_data(), points)
    data["synthesis"]["path"]["frame"] = frame
    return SynthesisProblem(mechloop.Model.from_dict(data))


TARGETS = coupler_point(np.radians(np.arange(0, 360, 40.0)))  # on the samples


@settings(max_examples=12, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(0.05, 20), st.floats(-np.pi, np.pi), st.floats(-1e3, 1e3),
       st.floats(-1e3, 1e3))
def test_shape_objective_is_invariant_to_moving_the_targets(size, turn, dx, dy):
    """Translating and rotating the targets leaves Q as it is, scaling multiplies it by
    the scale (Q is in the user's units); the designs here do not pass through them."""
    noisy = TARGETS + 3 * np.exp(1j * np.arange(TARGETS.size))  # 3 mm off the curve
    base = shape_problem(noisy)
    x = known_row(base)
    others = np.array([x, x * np.where(np.arange(x.size) < 4, 1.1, 1.0)])
    q0 = base.evaluate(others).q
    move = size * np.exp(1j * turn)
    moved = shape_problem(move * noisy + complex(dx, dy))
    q1 = moved.evaluate(others).q
    np.testing.assert_allclose(q1, size * q0, rtol=1e-6)


def test_a_moved_rotated_scaled_coupler_curve_is_recovered():
    move, shift = 0.4 * np.exp(1j * np.radians(130)), complex(500, -200)
    problem = shape_problem(move * TARGETS + shift)
    x = known_row(problem)
    ev = problem.evaluate(x[None, :])
    assert ev.q[0] < 1e-8
    a, b = problem.placement(x[None, :])
    assert a[0] == pytest.approx(move, abs=1e-10)
    assert b[0] == pytest.approx(shift * 1e-3, abs=1e-10)
    # the written model traces the moved curve itself
    written = problem.design_model(x)
    plain = written.model_dump(mode="json", exclude_defaults=True)
    plain["synthesis"]["path"].pop("frame")
    plain["synthesis"]["vary"] = {n: [-1e4, 1e4] for n in plain["synthesis"]["vary"]}
    again = SynthesisProblem(mechloop.Model.from_dict(plain))
    from mechloop.synthesis.variables import current_values

    assert again.evaluate(current_values(again.model, again.variables)[None, :]).q[0] < 1e-8
    # a bigger mechanism of the same shape elsewhere scores the same
    bigger = {**KNOWN, **{k: 2 * KNOWN[k] for k in ("r1", "r2", "r3", "r4", "r6")}}
    assert problem.evaluate(known_row(problem, bigger)[None, :]).q[0] < 1e-8


@pytest.mark.parametrize(("frame", "ok"), [
    ({"scale": False}, True), ({"rotate": False}, False), ({"translate": False}, False)])
def test_a_partly_free_frame_keeps_what_is_fixed(frame, ok):
    """The targets turned by 130 deg and moved (same size): found with scale fixed,
    not with rotation or translation fixed."""
    move = np.exp(1j * np.radians(130))
    problem = shape_problem(move * TARGETS + complex(50, 20), frame=frame)
    x = known_row(problem)
    a, _ = problem.placement(x[None, :])
    if not frame.get("scale", True):
        assert abs(a[0]) == pytest.approx(1, abs=1e-12)
    if not frame.get("rotate", True):
        assert a[0].imag == 0
    assert (problem.evaluate(x[None, :]).q[0] < 1e-8) == ok


def test_a_shape_task_with_timing_or_a_workspace_is_refused():
    data = path_data()
    data["synthesis"]["path"].update(frame="free", timing=True,
                                     targets=[[0, 0]] * 181)
    with pytest.raises(ModelError, match=r"synthesis\.path\.frame"):
        mechloop.Model.from_dict(data)
    data = path_data(workspace={"points": [{"head": 6}], "box": [[0, 0], [1, 1]]})
    data["synthesis"]["path"]["frame"] = "free"
    with pytest.raises(ModelError, match=r"synthesis\.workspace"):
        mechloop.Model.from_dict(data)


def test_the_shape_example_places_the_known_design_on_its_circuit():
    """examples/four_bar_shape_synthesis.yaml: its targets are the known curve turned by
    130 deg, scaled by 0.4 and moved by (500, -200) mm; the file's variant is 2, the
    known design's circuit 1 (circuits: both)."""
    problem = SynthesisProblem(mechloop.load_model("examples/four_bar_shape_synthesis.yaml"))
    x = known_row(problem)[None, :]
    a, b = problem.placement(x)
    assert a[0] == pytest.approx(0.4 * np.exp(1j * np.radians(130)), abs=1e-6)
    assert b[0] == pytest.approx(complex(0.5, -0.2), abs=1e-6)
    ev = problem.evaluate(x, continuous=True)
    assert ev.q[0] < 1e-4 and ev.measures["variant1"][0] == 1  # targets rounded to 1e-4
    placed = problem.design_model(x[0])
    assert placed.vectors[1].r == pytest.approx(40, rel=1e-6)
    assert placed.contours[0].variant == 1


def test_continuous_residuals_are_the_continuous_deviations():
    problem = SynthesisProblem(mechloop.Model.from_dict(path_data(circuits="both")))
    x = known_row(problem)[None, :]
    res = problem.residuals(x, continuous=True)[0]
    assert np.max(res) == pytest.approx(problem.evaluate(x, continuous=True).q[0],
                                        rel=1e-12)
    assert np.max(problem.residuals(x)[0]) == pytest.approx(problem.evaluate(x).q[0],
                                                            rel=1e-12)


@settings(max_examples=40, deadline=None, derandomize=True)
@given(st.integers(0, 2**32 - 1))
def test_nearest_on_curve_agrees_with_the_polyline_distance(seed):
    """The nearest place of nearest_on_curve is on the polyline (at its parameter s)
    and as far from the target as distance_to_curve says."""
    from mechloop.synthesis import deviations as dv

    rng = np.random.default_rng(seed)
    z = rng.normal(size=(3, 7)) + 1j * rng.normal(size=(3, 7))
    targets = rng.normal(size=4) + 1j * rng.normal(size=4)
    distance, s, point = dv.nearest_on_curve(z, targets)
    np.testing.assert_allclose(distance, dv.distance_to_curve(z, targets), rtol=1e-12)
    np.testing.assert_allclose(np.abs(point - targets[None, :]), distance, rtol=1e-12)
    i = np.minimum(np.floor(s).astype(int), 5)
    along = np.take_along_axis(z, i, 1) + (s - i) * np.diff(z, axis=1)[
        np.arange(3)[:, None], i]
    np.testing.assert_allclose(along, point, atol=1e-12)


def test_each_design_keeps_its_better_circuit():
    data = path_data(circuits="both")
    both = SynthesisProblem(mechloop.Model.from_dict(data))
    rng = np.random.default_rng(5)
    designs = both.variables.scale(rng.uniform(size=(60, len(both.variables))))
    ev = both.evaluate(designs)
    totals = np.stack([sub.evaluate(designs).total for _, sub in both.circuits])
    np.testing.assert_array_equal(ev.total, totals.min(axis=0))
    chosen = ev.measures["variant1"]
    assert set(np.unique(chosen[ev.feasible])) == {1.0, 2.0}  # both circuits win some
    variants = np.array([v[1] for v, _ in both.circuits])
    np.testing.assert_array_equal(chosen, variants[totals.argmin(axis=0)])
