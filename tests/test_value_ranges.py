"""Non-finite and absurd numbers are refused where they enter the model, with the file,
line, key and the range a value must lie in (issue 10, part 1)."""

from __future__ import annotations

import math
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

from mechloop import ModelError, load_model
from mechloop.model.groups import _tidy
from mechloop.model.numbers import MAX_MAGNITUDE
from mechloop.model.units import UnitProblem, to_si

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CRANK = (EXAMPLES / "crank_slider.yaml").read_text()
DYN = (EXAMPLES / "crank_slider_dynamics.yaml").read_text()
GROUPS = (EXAMPLES / "four_bar_groups.yaml").read_text()


def _line(text: str, fragment: str) -> int:
    return text[:text.index(fragment)].count("\n") + 1


# name, base text, what to replace, by what, path of the problem, words in the message
CASES = [
    ("rpm_inf", CRANK, "rpm: 3000", "rpm: .inf", ("time", "rpm"), "inf is not a finite number"),
    ("rpm_huge", CRANK, "rpm: 3000", "rpm: 1.0e9", ("time", "rpm"), "1000000"),
    ("rpm_tiny", DYN, "rpm: 3000", "rpm: 1.0e-200", ("time", "rpm"), "greater than or equal"),
    ("time_step_tiny", DYN, "time: {rpm: 3000}", "time: {table: {0: 0, 72: 1.0e-20}}",
     ("time", "table"), "the shortest step is 1e-15 s"),
    ("gravity_nan", DYN, "g: 9.81", "g: .nan", ("gravity", "g"), "finite number"),
    ("mass_inf", DYN, "mass: 2,", "mass: .inf,", ("bodies", 1, "mass"), "finite number"),
    ("table_nan", CRANK, "72: 360}", "72: .nan}", ("arguments", 1, "table", 72),
     "finite number"),
    ("force_table_inf", DYN, "value: 1000,", "value: {table: {0: 1, 72: .inf}},",
     ("forces", 0, "value", "table", 72), "finite number"),
    ("length_1e200", CRANK, "r: 0.05,", "r: 1e200,", ("vectors", 1, "r"), "range of a length"),
    ("length_float_1e200", CRANK, "r: 0.05,", "r: 1.0e+200,", ("vectors", 1, "r"),
     "finite number"),
    ("quantity_overflow", CRANK, "r: 0.05,", "r: 5e400 mm,", ("vectors", 1, "r"),
     "range of a length"),
    ("quantity_too_long", CRANK, "r: 0.05,", f"r: '{'1' * 200} mm',", ("vectors", 1, "r"),
     "203 characters"),
    ("pin_radius_kg", DYN, "O: {type: revolute,", "O: {radius: 2 kg, type: revolute,",
     ("joints", "O", "radius"), "not a length"),
    ("group_angle_huge", GROUPS, "angle: 30}", "angle: 1e20}", ("points", "P", "angle"),
     "range of an angle"),
    ("group_angle_big_int", GROUPS, "angle: 30}", "angle: 100000000000000000000}",
     ("points", "P", "angle"), "finite number"),
]


@pytest.mark.parametrize(("base", "old", "new", "path", "words"),
                         [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_value_refused_where_it_enters(tmp_path, base, old, new, path, words):
    file = tmp_path / "m.yaml"
    file.write_text(base.replace(old, new, 1))
    start = time.perf_counter()
    with pytest.raises(ModelError) as info:
        load_model(file)
    assert time.perf_counter() - start < 3.0
    problem = next(p for p in info.value.problems if p.path == path)
    assert words in problem.message
    assert problem.line == _line(base, old) and problem.hint


def test_csv_inf_is_refused_with_the_csv_line(tmp_path):
    (tmp_path / "arg.csv").write_text("position,angle\n0,0\n36,inf\n72,360\n")
    file = tmp_path / "m.yaml"
    file.write_text(CRANK.replace("{table: {0: 0, 72: 360}}", "{csv: arg.csv}"))
    with pytest.raises(ModelError) as info:
        load_model(file)
    (problem,) = info.value.problems
    assert problem.path == ("arguments", 1) and problem.line == _line(CRANK, "1: {table")
    assert "arg.csv, line 3: 36, inf" in problem.message and "finite" in problem.message


def test_to_si_refuses_values_out_of_range_in_file_units_or_si():
    assert to_si("1e12", "length", "m") == MAX_MAGNITUDE
    assert to_si("5e-324", "length", "m") == 0.0 and to_si(1e-99, "length", "mm") == 0.0
    for value, unit in (("1e11 km", "m"), ("nan", "mm"), (math.inf, "m"), ("-1e13", "m")):
        with pytest.raises(UnitProblem, match="outside the range"):
            to_si(value, "length", unit)


@pytest.mark.parametrize("angle", [1e20, -1e20, 7230.0, -180.0, 180.0, 540.0, 0.0])
def test_tidy_folds_any_angle_in_one_step(angle):
    folded = _tidy(angle, 180.0)
    assert -180.0 < folded <= 180.0
    assert math.isclose(math.remainder(folded - angle, 360.0), 0.0, abs_tol=1e-9 * abs(angle)
                        + 1e-12)


def test_fixed_contour_start_is_checked_when_loading(tmp_path):
    text = (EXAMPLES / "roof_support.yaml").read_text()
    old = "start: [0.0, 0.15]"
    file = tmp_path / "m.yaml"
    file.write_text(text.replace(old, "start: [0.0, 1e400]"))
    with pytest.raises(ModelError) as info:
        load_model(file)
    (problem,) = info.value.problems
    assert problem.path[0] == "contours" and problem.path[2:] == ("start", 1)
    assert "range of a length" in problem.message and problem.line == _line(text, old)


@pytest.mark.parametrize(("old", "new"), [("mass: 2,", "mass: 5.0e-324,"),
                                          ("mass: 2,", "mass: 5e-324,"),
                                          ("g: 9.81", "g: -1.0e-300")])
def test_subnormal_values_count_as_zero_without_overflow(tmp_path, old, new):
    from mechloop.dynamics.analysis import solve_dynamics

    file = tmp_path / "m.yaml"
    file.write_text(DYN.replace(old, new))
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        result = solve_dynamics(load_model(file))
    frame = result.to_frame()
    assert np.isfinite(frame[~frame["chain_break"]].select_dtypes("number")).all().all()


@pytest.mark.parametrize("text", ["9**9**9 mm", "(9)**99 mm", "10**400 mm", "2 mm^999"])
def test_powers_of_numbers_are_refused_before_pint_computes_them(text):
    start = time.perf_counter()
    with pytest.raises(UnitProblem, match="only units take powers"):
        to_si(text, "length", "m")
    assert time.perf_counter() - start < 1.0


@pytest.mark.parametrize("text", ["5 kg*m^2", "2 g*cm**2", "9.81 m/s^2", "1 (m/s)^2 * s^2 / m"])
def test_units_with_powers_still_read(text):
    kind = "inertia" if "kg" in text or "g*cm" in text else (
        "acceleration" if "/s^2" in text else "length")
    assert to_si(text, kind, "m") > 0


def test_long_unit_expression_is_refused_in_the_schema(tmp_path):
    file = tmp_path / "m.yaml"
    file.write_text(CRANK.replace("units: {length: m,", "units: {length: '" + "1 " * 1200
                                  + "m',"))
    with pytest.raises(ModelError) as info:
        load_model(file)
    (problem,) = info.value.problems
    assert problem.path == ("units", "length") and "at most 100 characters" in problem.message


def test_csv_position_that_is_not_finite_is_refused(tmp_path):
    (tmp_path / "arg.csv").write_text("position,angle\ninf,0\n72,360\n")
    file = tmp_path / "m.yaml"
    file.write_text(CRANK.replace("{table: {0: 0, 72: 360}}", "{csv: arg.csv}"))
    with pytest.raises(ModelError, match=r"arg\.csv, line 2: inf"):
        load_model(file)


def test_a_nan_speed_is_called_not_finite_not_too_large(tmp_path):
    """pydantic compares a NaN with the bound of ``rpm`` before any finiteness check and
    called it "less than or equal to 1000000"; the message says what is wrong."""
    text = (Path(__file__).resolve().parents[1] / "examples" / "crank_slider.yaml"
            ).read_text(encoding="utf-8").replace("time: {rpm: 3000}", "time: {rpm: .nan}")
    path = tmp_path / "m.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ModelError) as caught:
        load_model(path)
    (problem,) = caught.value.problems
    assert problem.path == ("time", "rpm")
    assert problem.message == "nan is not a finite number"
    assert "rpm: .nan" in text.splitlines()[problem.line - 1]
