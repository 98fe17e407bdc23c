"""Problems found while solving a valid-looking model name the file, line and key to change,
through the API and the command line, with no traceback and no NumPy warning; and every
problem of a file is listed in one pass (issue 10, part 1)."""

from __future__ import annotations

import time
import warnings
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechloop import ModelError, SolveError, load_model
from mechloop.cli import app
from mechloop.dynamics.analysis import solve_dynamics
from mechloop.errors import ModelSolveError
from mechloop.solve import memory
from mechloop.solve.kinematics import solve

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CRANK = (EXAMPLES / "crank_slider.yaml").read_text()
DYN = (EXAMPLES / "crank_slider_dynamics.yaml").read_text()
MACHINE = DYN + "machine: {}\n"


def _line(text: str, fragment: str) -> int:
    return text[:text.index(fragment)].count("\n") + 1


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "m.yaml"
    path.write_text(text)
    return path


def _cli(path: Path, command: str = "solve") -> str:
    start = time.perf_counter()
    result = CliRunner().invoke(app, [command, str(path)])
    assert time.perf_counter() - start < 20
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output and "Warning" not in result.output
    return result.output


# name, text, path of the problem, line fragment, words of the message, words of the fix
SOLVE_CASES = [
    ("chain_break", MACHINE.replace("r: 0.2, a: function", "r: 0.045, a: function"),
     ("machine",), "machine: {}", "needs the whole cycle", "chain break"),
    ("input_backwards", MACHINE.replace("{0: 0, 72: 360}", "{0: 360, 72: 0}"),
     ("arguments", 1), "  1: {table", "input to advance", "increase"),
    ("no_moving_mass", MACHINE.replace("mass: 2, inertia: 0.01", "mass: 0").replace(
        "mass: 1.5, inertia: 0.006", "mass: 0").replace("mass: 1.2", "mass: 0"),
     ("bodies",), "bodies:", "j_red", "masses"),
    ("machine_stops", MACHINE.replace("rpm: 3000", "rpm: 1").replace("value: 1000",
                                                                      "value: 100000"),
     ("time",), "time:", "the machine stops", "time: {rpm"),
    ("friction_self_locking", DYN + "friction: {coefficient: 50, radius: 0.05, "
     "length: 0.05}\n", ("friction", "coefficient"), "friction: {", "did not settle",
     "friction.coefficient"),
]


@pytest.mark.parametrize(("text", "path", "at", "words", "fix"), [c[1:] for c in SOLVE_CASES],
                         ids=[c[0] for c in SOLVE_CASES])
def test_solve_problem_names_the_key_to_change(tmp_path, text, path, at, words, fix):
    file = _write(tmp_path, text)
    model = load_model(file)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(ModelSolveError) as info:
            solve_dynamics(model)
    assert isinstance(info.value, SolveError)  # still what API callers catch
    (problem,) = info.value.problems
    assert problem.path == path and words in problem.message and fix in problem.hint
    assert "Python" not in problem.hint and "(q, m_red)" not in problem.hint
    output = _cli(file)
    assert f"{file}:{_line(text, at)}" in output and "fix:" in output


def test_argument_without_time_is_located(tmp_path):
    text = CRANK.replace("time: {rpm: 3000}", "").replace("{0: 0, 72: 360}",
                                                          "{10: 0, 72: 360}")
    file = _write(tmp_path, text)
    with pytest.raises(ModelSolveError) as info:
        solve(load_model(file))
    assert info.value.problems[0].path == ("arguments", 1)
    assert f"{file}:{_line(text, '  1: {table')}, arguments[1]" in _cli(file)


def test_solve_refuses_more_positions_than_memory_holds(tmp_path, monkeypatch):
    file = _write(tmp_path, CRANK.replace("positions: 72", "positions: 2000000"))
    model = load_model(file)
    need = memory.estimate_bytes(model, dynamics=False)
    monkeypatch.setattr(memory, "available_memory", lambda: need)  # 80 % usable: short
    with pytest.raises(ModelSolveError) as info:
        solve(model)
    (problem,) = info.value.problems
    assert problem.path == ("positions",) and "GiB" in problem.message
    most = int(problem.hint.split("at most about ")[1].split(" ")[0].replace(",", ""))
    assert 0.7 * 2_000_001 < most < 0.85 * 2_000_001
    assert f"{file}:{_line(CRANK, 'positions:')}, positions" in _cli(file)


def test_memory_estimate_bounds_a_measured_solve():
    # measured peak (ru_maxrss) at 10**6 positions: 224 B/position for the slider-crank's
    # kinematics and table, 2977 B/position for its dynamics (see solve/memory.py)
    model = load_model(EXAMPLES / "crank_slider.yaml")
    assert 224 <= memory.bytes_per_position(model, dynamics=False) <= 2 * 224
    dyn = load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    assert 2977 <= memory.bytes_per_position(dyn, dynamics=True) <= 2 * 2977


@pytest.mark.parametrize(("old", "new", "path", "words"), [
    ("center: {vector: 1, share: 0.5}", 'center: {vector: 1, along: "5 kg"}',
     ("bodies", 1, "center", "along"), "not a length"),
    ("value: 1000,", "value: {table: [" + ", ".join(["1"] * 72) + "]},",
     ("forces", 0, "value", "table"), "72 values"),
    ("value: 1000,", "value: {law: harmonic, start: [0, 0], end: [99, 5]},",
     ("forces", 0, "value", "end", 0), "outside the calculation positions"),
    ("g: 9.81", "g: 9.81 m", ("gravity", "g"), "not an acceleration"),
])
def test_load_and_point_problems_are_found_when_loading(tmp_path, old, new, path, words):
    text = DYN.replace(old, new, 1)
    file = _write(tmp_path, text)
    with pytest.raises(ModelError) as info:
        load_model(file)
    problem = next(p for p in info.value.problems if p.path == path)
    assert words in problem.message and problem.line == _line(DYN, old)
    assert "fix:" in _cli(file, "check")


def test_schema_and_structural_problems_are_listed_together(tmp_path):
    text = """\
positions: 36
time: {rpm: 100, turn: 2}
arguments:
  1: {table: {0: 0, 36: 360}}
vectors:
  1: {r: 0.05, a: {argument: 1}, nam: crank}
  2: {r: 0.2, a: function}
  3: {r: function, a: function}
  4: {r: 0.01, a: {link: a9}}
contours:
  - vectors: [1, 2, 3, 4]
gravity: {g: .nan}
"""
    file = _write(tmp_path, text)
    with pytest.raises(ModelError) as info:
        load_model(file)
    found = [(p.path, p.line) for p in info.value.problems]
    assert found == [(("time", "turn"), 2), (("vectors", 1, "nam"), 6),  # in file order
                     (("vectors", 4, "a"), 9), (("contours", 0), 11), (("gravity", "g"), 12)]


def test_structure_is_not_checked_on_a_broken_core(tmp_path):
    # a vector that does not validate: its contour cannot be judged, so nothing is guessed
    text = CRANK.replace("a: {argument: 1}", "a: {argumnt: 1}")
    file = _write(tmp_path, text)
    with pytest.raises(ModelError) as info:
        load_model(file)
    assert [p.path for p in info.value.problems] == [("vectors", 1, "a")]


def test_design_batches_are_checked_against_memory(monkeypatch):
    from mechloop.solve.designs import solve_designs

    model = load_model(EXAMPLES / "crank_slider.yaml")
    per_design = memory.estimate_bytes(model, dynamics=False)
    monkeypatch.setattr(memory, "available_memory", lambda: 100 * per_design)
    assert solve_designs(model, {"r1": [0.05] * 10}).values["a2"].shape == (10, 73)
    with pytest.raises(ModelSolveError, match="of 1,000 designs"):
        solve_designs(model, {"r1": [0.05] * 1000})


def test_group_file_lists_schema_and_structural_problems_together(tmp_path):
    text = (EXAMPLES / "four_bar_groups.yaml").read_text()
    bad = text.replace("time: {rpm: 120}", "time: {rpm: 120, turn: 1}").replace(
        "at: [A, C]", "at: [A, Z]")
    file = _write(tmp_path, bad)
    with pytest.raises(ModelError) as info:
        load_model(file)
    found = {(p.path, p.line) for p in info.value.problems}
    assert found == {(("time", "turn"), _line(text, "time:")),
                     (("groups", 0, "at", 1), _line(text, "at: [A, C]"))}


def test_check_reports_a_solve_that_would_not_fit_in_memory(tmp_path, monkeypatch):
    file = _write(tmp_path, CRANK.replace("positions: 72", "positions: 2000000"))
    monkeypatch.setattr(memory, "available_memory", lambda: 10**8)
    assert f"{file}:{_line(CRANK, 'positions:')}, positions" in _cli(file, "check")


def test_cli_hint_for_a_named_point_says_what_to_change_in_the_file(tmp_path):
    result = CliRunner().invoke(app, ["plot", str(EXAMPLES / "crank_slider.yaml"),
                                      "trajectories", "--points", "S2", "-o",
                                      str(tmp_path / "t.png")])
    assert result.exit_code == 2
    assert "add bodies and joints to the model file" in result.output
    assert "head:K" in result.output


def test_unreadable_csv_table_does_not_hide_the_other_problems(tmp_path):
    (tmp_path / "bad.csv").write_text("k,v\n0,0\n36,x\n72,360\n")
    text = CRANK.replace("{table: {0: 0, 72: 360}}", "{csv: bad.csv}").replace(
        "r: 0.2, a: function", "r: 0.2, a: 10").replace("rpm: 3000}", "rpm: 3000, turn: 2}")
    file = _write(tmp_path, text)
    with pytest.raises(ModelError) as info:
        load_model(file)
    assert [p.path for p in info.value.problems] == [("time", "turn"), ("arguments", 1),
                                                     ("contours", 0)]
