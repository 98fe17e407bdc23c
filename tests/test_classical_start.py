"""Starting designs of the synthesis search (``search.start`` / ``synthesize(start=)``):
they are evaluated first and enter each strategy, bad ones are located, the seed still
reproduces; a classical closed form as the start (examples/classical_start.py) and the
slider-crank for a stroke and a time ratio (examples/slider_crank_stroke_synthesis.yaml)
checked against independent computations."""

from __future__ import annotations

import runpy
from pathlib import Path

import numpy as np
import pytest

import mechloop
from mechloop.errors import ModelError
from mechloop.synthesis import search as search_module
from mechloop.synthesis.classical import excess_angle, slider_crank_from_stroke
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import start_designs, synthesize

ROOT = Path(__file__).resolve().parents[1]
PATH = ROOT / "examples/four_bar_path_synthesis.yaml"
SLIDER = ROOT / "examples/slider_crank_stroke_synthesis.yaml"
#: The four-bar the targets of four_bar_path_synthesis.yaml were taken from (its header:
#: examples/four_bar.yaml placed at the origin) — an exact answer of that task.
EXACT = {"r1": 100, "r2": 350, "r3": 250, "r4": 300, "a4": 180, "r6": 250, "a6": 30,
         "start1.x": 0, "start1.y": 0}


def _with_search(model: mechloop.Model, **changes) -> mechloop.Model:
    data = model.model_dump(mode="json", exclude_defaults=True)
    data["synthesis"].setdefault("search", {}).update(changes)
    return mechloop.Model.from_dict(data)


class _Spy:
    """Records every population handed to SynthesisProblem.evaluate (SI, (D, V))."""

    def __init__(self, monkeypatch):
        self.calls: list[np.ndarray] = []
        original = SynthesisProblem.evaluate

        def evaluate(problem, designs, **options):
            self.calls.append(np.atleast_2d(np.array(designs, dtype=float)))
            return original(problem, designs, **options)

        monkeypatch.setattr(SynthesisProblem, "evaluate", evaluate)


# ------------------------------------------------------------- evaluated and included


@pytest.mark.parametrize("method", ["de", "cmaes"])
def test_an_exact_start_is_evaluated_first_and_kept(method, monkeypatch):
    model = mechloop.load_model(PATH)
    problem = SynthesisProblem(model)
    start = start_designs(problem, EXACT)
    own = problem.evaluate(start)  # as the search measures it
    exact = problem.evaluate(start, continuous=True)  # as the result is measured
    spy = _Spy(monkeypatch)
    result = synthesize(model, method=method, seed=2, iterations=1, polish=False,
                        start=EXACT)
    np.testing.assert_array_equal(spy.calls[0], start)  # the start goes first, alone
    assert result.q <= exact.q[0]
    # the best after one generation is the start (or its copy in the population, equal
    # but for the round trip through the unit box)
    assert result.history["best"].iloc[0] == pytest.approx(own.total[0], rel=1e-6)
    np.testing.assert_allclose(result.best, start[0], rtol=1e-12)
    unit = problem.variables.unscale(start[0])
    population = problem.variables.unscale(spy.calls[1])
    if method == "de":  # a member of DE's first population
        assert np.any(np.all(np.abs(population - unit) < 1e-12, axis=1))
    else:  # CMA-ES's first generation is centred on the start (step 0.1 of the box)
        assert np.all(np.abs(population.mean(axis=0) - unit) < 0.1)


def test_de_keeps_the_rest_of_its_population_a_sample(monkeypatch):
    model = mechloop.load_model(PATH)
    problem = SynthesisProblem(model)
    worse = dict(EXACT, r1=120)
    spy = _Spy(monkeypatch)
    synthesize(model, method="de", seed=2, iterations=1, polish=False,
               start=[EXACT, worse])
    unit = problem.variables.unscale(spy.calls[1])
    starts = problem.variables.unscale(start_designs(problem, [EXACT, worse]))
    np.testing.assert_allclose(unit[:2], starts, atol=1e-12)
    rest = unit[2:]
    assert len(rest) >= 40 - 2 and np.all((rest >= 0) & (rest <= 1))
    assert len(np.unique(rest.round(9), axis=0)) == len(rest)


def test_multistart_runs_its_first_local_search_from_the_start(monkeypatch):
    model = _with_search(mechloop.load_model(PATH), starts=1)
    problem = SynthesisProblem(model)
    start = start_designs(problem, EXACT)
    spy = _Spy(monkeypatch)
    result = synthesize(model, method="multistart", seed=2, iterations=1,
                        scheduler="serial", start=EXACT)
    np.testing.assert_array_equal(spy.calls[0], start)
    np.testing.assert_allclose(spy.calls[2], start, rtol=1e-12)  # the first local start
    assert result.q <= problem.evaluate(start, continuous=True).q[0]


def test_start_in_the_file_array_and_partial_designs():
    model = mechloop.load_model(PATH)
    problem = SynthesisProblem(model)
    names = problem.variables.names
    row = np.array([EXACT[n] for n in names], dtype=float)
    from_mapping = start_designs(problem, EXACT)
    np.testing.assert_array_equal(start_designs(problem, row), from_mapping)
    np.testing.assert_array_equal(start_designs(problem, np.stack([row, row])),
                                  np.repeat(from_mapping, 2, axis=0))
    filed = SynthesisProblem(_with_search(model, start=EXACT))
    np.testing.assert_array_equal(start_designs(filed), from_mapping)
    assert start_designs(problem) is None
    # a variable left out takes the model's own value (here r1 = 120 mm in the file)
    partial = start_designs(problem, {"r2": 350})
    assert partial[0, names.index("r1")] == pytest.approx(0.120)
    assert partial[0, names.index("r2")] == pytest.approx(0.350)
    # a value with its own unit
    assert start_designs(problem, {"r1": "0.1 m"})[0, 0] == pytest.approx(0.1)
    with pytest.raises(ModelError, match="one column per variable: r1, r2"):
        start_designs(problem, row[:3])
    assert start_designs(problem, []) is None


# ------------------------------------------------------------------- located errors


def test_bad_starts_in_the_file_are_located(tmp_path):
    text = PATH.read_text(encoding="utf-8")
    assert text.count("good_enough: 0.001}") == 1
    text = text.replace("good_enough: 0.001}", "good_enough: 0.001,\n           start: "
                        "[{r1: 100, r9: 5}, {r2: 1000, a6: '3 rad'}]}")
    path = tmp_path / "bad.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ModelError) as info:
        mechloop.load_model(path)
    message = str(info.value)
    line = text.splitlines().index(
        next(x for x in text.splitlines() if x.strip().startswith("start:"))) + 1
    assert f"bad.yaml:{line}" in message
    assert "synthesis.search.start[0].r9: r9 is not a variable of the task" in message
    assert "synthesis.search.start[1].r2: r2 = 1000 is outside its bounds [200, 450]" \
        in message
    assert "synthesis.search.start[1].a6" in message  # 3 rad = 171.9 deg > 90
    assert "start[0].r1" not in message
    assert "widen vary.r2" in message


def test_bad_starts_by_keyword_are_located():
    model = mechloop.load_model(PATH)
    with pytest.raises(ModelError, match=r"start\.r1: r1 = 10(\.0)? is outside its bounds"):
        synthesize(model, iterations=1, start={"r1": 10})
    with pytest.raises(ModelError, match=r"start\[1\]\.a9: a9 is not a variable"):
        synthesize(model, iterations=1, start=[EXACT, {"a9": 1}])
    model_data = model.model_dump(mode="json", exclude_defaults=True)
    model_data["synthesis"]["search"] = {"start": {"start1.x": 80}}
    with pytest.raises(ModelError, match=r"synthesis\.search\.start\.start1\.x"):
        mechloop.Model.from_dict(model_data)


# -------------------------------------------------------------------- reproducibility


@pytest.mark.parametrize("method", ["de", "cmaes"])
def test_same_seed_same_result_with_a_start(method):
    model = mechloop.load_model(PATH)
    start = [dict(EXACT, r1=110, a6=20), dict(EXACT, r3=230)]
    runs = [synthesize(model, method=method, seed=7, iterations=8, polish=False,
                       start=start) for _ in range(2)]
    np.testing.assert_array_equal(runs[0].best, runs[1].best)
    assert runs[0].history["best"].tolist() == runs[1].history["best"].tolist()
    other = synthesize(model, method=method, seed=8, iterations=8, polish=False,
                       start=start)
    assert other.history["best"].tolist() != runs[0].history["best"].tolist()


def test_without_a_start_the_models_own_design_goes_first(monkeypatch):
    model = mechloop.load_model(PATH)
    problem = SynthesisProblem(model)
    spy = _Spy(monkeypatch)
    synthesize(model, method="de", seed=2, iterations=1, polish=False, atlas=False)
    own = search_module.current_values(model, problem.variables)
    np.testing.assert_array_equal(spy.calls[0], own[None, :])
    spy.calls.clear()  # with the atlas, the own design is the first starting design
    synthesize(model, method="de", seed=2, iterations=1, polish=False)
    np.testing.assert_array_equal(spy.calls[1][:1], own[None, :])
    assert len(spy.calls[1]) > 1


# ------------------------------------------------- the slider-crank: stroke and K


H, K = 200.0, 1.4


def _fine_extreme(data: dict, angle: float, sign: float) -> tuple[float, float]:
    """(crank argument, slider position) at the extreme of r3 near ``angle`` (deg): a
    solve of the model alone over ±1.5° in 3000 steps, then the vertex of the parabola
    through the three best points."""
    data = {k: v for k, v in data.items() if k != "synthesis"}
    data["positions"] = 3000
    data["arguments"] = {1: {"table": {0: angle - 1.5, 3000: angle + 1.5}}}
    res = mechloop.solve(mechloop.Model.from_dict(data))
    assert not res.breaks
    x = np.linspace(angle - 1.5, angle + 1.5, 3001)
    y = sign * res.values["r3"] * 1000  # mm
    i = int(np.argmax(y))
    assert 0 < i < 3000, "the extreme is not inside the fine window"
    step = x[1] - x[0]
    y0, y1, y2 = y[i - 1], y[i], y[i + 1]
    offset = 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2)
    return x[i] + offset * step, sign * (y1 - 0.25 * (y0 - y2) * offset)


def test_slider_crank_example_starts_from_the_closed_form():
    """search.start of the file is slider_crank_from_stroke(200, 1.4, offset=100)."""
    from mechloop.synthesis.classical import slider_crank_from_stroke

    sc = slider_crank_from_stroke(200.0, 1.4, offset=100.0)
    start = mechloop.load_model(SLIDER).synthesis.search.start
    assert float(start["r1"]) == pytest.approx(float(sc.crank), abs=1e-4)
    assert float(start["r2"]) == pytest.approx(float(sc.rod), abs=1e-4)
    assert float(start["r4"]) == 100.0
    # the guide turned so that the far dead point falls at the crank's 20 degrees
    far = np.degrees(float(sc.crank_angle_far))
    assert float(start["a3"]) == pytest.approx(180.0 + 20.0 - abs(far), abs=1e-4)


def test_slider_crank_example_has_its_stroke_and_time_ratio():
    model = mechloop.load_model(SLIDER)
    result = synthesize(model)
    assert result.feasible and result.q < 1e-4  # degrees, rod-angle error at dead points
    design = result.model
    solved = mechloop.solve(design)
    assert not solved.breaks
    r3 = solved.values["r3"] * 1000
    data = design.model_dump(mode="json", exclude_defaults=True)
    far_arg, far = _fine_extreme(data, float(np.argmax(r3)), +1.0)
    near_arg, near = _fine_extreme(data, float(np.argmin(r3)), -1.0)
    stroke = far - near
    slow = np.mod(near_arg - far_arg, 360.0)  # crank turns far -> near (counter-clockwise)
    ratio = slow / (360.0 - slow)
    assert abs(stroke - H) <= 1e-3  # mm: the range criterion is an exact penalty
    assert abs(ratio - K) <= 1e-5   # the rod is in line with the crank to Q at both
    # the design is the member of the classical family with its offset
    values = result.values()
    crank, rod, offset = values["r1"], values["r2"], values["r4"]
    sc = slider_crank_from_stroke(H, K, offset=offset)
    assert abs(float(sc.crank) - crank) <= 1e-3
    assert abs(float(sc.rod) - rod) <= 1e-3
    # pressure angle of the solved design (rod to guide) vs the classical family's best
    guide = solved.values["a3"] - np.pi
    rel = np.mod(solved.values["a2"] - guide + np.pi, 2 * np.pi) - np.pi
    pressure = np.degrees(np.abs(rel).max())
    e = np.linspace(1e-3, H / np.tan(excess_angle(K)), 200001)
    family = slider_crank_from_stroke(H, K, offset=e)
    p_family = np.degrees(np.arcsin((family.crank + e) / family.rod))
    best = int(np.argmin(p_family))
    assert abs(pressure - p_family[best]) <= 0.01
    assert abs(offset - e[best]) <= 3.0  # a flat optimum: 3 mm cost < 0.02 deg
    assert p_family[best] == pytest.approx(57.368, abs=1e-3)  # the header's number


# ------------------------------------------------------ examples/classical_start.py


def test_classical_start_script_scores_freudensteins_design_independently():
    namespace = runpy.run_path(str(ROOT / "examples/classical_start.py"))
    out = namespace["main"](iterations=2)
    fg = out["fg"]
    k1, k2, k3 = (float(v) for v in fg.k)
    # Freudenstein's equation K1 cos ψ − K2 cos φ + K3 = cos(φ − ψ), solved for ψ:
    # (K1 − cos φ) cos ψ − sin φ sin ψ = K2 cos φ − K3
    phi = out["phi0"] + np.radians(60.0) * np.arange(31) / 30
    a, b, c = k1 - np.cos(phi), -np.sin(phi), k2 * np.cos(phi) - k3
    base, half = np.arctan2(b, a), np.arccos(np.clip(c / np.hypot(a, b), -1, 1))
    roots = [base + half, base - half]
    # the branch through the precision points
    phi_p = np.asarray(fg.phi)
    ap, bp, cp = k1 - np.cos(phi_p), -np.sin(phi_p), k2 * np.cos(phi_p) - k3
    bp_base, bp_half = np.arctan2(bp, ap), np.arccos(np.clip(cp / np.hypot(ap, bp), -1, 1))

    def gap(x, y):
        return np.abs(np.mod(x - y + np.pi, 2 * np.pi) - np.pi).max()

    sign = 0 if gap(bp_base + bp_half, fg.psi) < 1e-9 else 1
    assert gap((bp_base + bp_half, bp_base - bp_half)[sign], fg.psi) < 1e-9
    psi = np.unwrap(roots[sign])
    t = np.arange(31) / 30
    error = np.degrees(psi - psi[0]) - 60.0 * np.log10(1 + 9 * t)
    assert out["q_classical"] == pytest.approx(np.abs(error).max(), abs=1e-9)
    assert out["q_classical"] == pytest.approx(0.7540, abs=1e-4)  # as docs/synthesis.md says
    assert out["q_with"] <= out["q_classical"] + 1e-12  # the start is kept
    assert out["values"]["r1"] == pytest.approx(float(fg.a))
    assert abs(error[[0, -1]]).max() > 0 and np.abs(error).max() < 1.0  # degrees
