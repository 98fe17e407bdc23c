"""Every mistake a user can make in a model file gives one clear message — file, line, the
offending item and the fix — exit code 2, and no traceback (issue 2, point 2)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest
from typer.testing import CliRunner

from mechloop import ModelError, load_model
from mechloop.cli import app

GOOD = """\
positions: 36
time: {rpm: 100}
arguments:
  1: {table: {0: 0, 36: 360}}
vectors:
  1: {r: 0.05, a: {argument: 1}}
  2: {r: 0.2, a: function}
  3: {r: function, a: 180}
  4: {r: 0.01, a: 90}
contours:
  - vectors: [1, 2, 3, 4]
"""

# name, file text, the line the message must name, fragments the message must contain
CASES = [
    ("too_many_functions", GOOD.replace("3: {r: function, a: 180}",
                                        "3: {r: function, a: function}"),
     11, ["contour 1 has 3 function parameters", "a2, r3, a3", "fix:"]),
    ("too_few_functions", GOOD.replace("2: {r: 0.2, a: function}", "2: {r: 0.2, a: 10}"),
     11, ["contour 1 has 1 function parameter (r3)", "mark two of its parameters"]),
    ("link_to_missing_vector", GOOD.replace("4: {r: 0.01, a: 90}",
                                            "4: {r: 0.01, a: {link: a9}}"),
     9, ["a4 links to a9", "vector 9 is not defined", "fix:"]),
    ("link_to_other_kind", GOOD.replace("4: {r: 0.01, a: 90}",
                                        "4: {r: 0.01, a: {link: r1}}"),
     9, ["a4 (angle) links to r1 (length)", "link to a1 instead"]),
    ("block_with_wrong_count", GOOD.replace("3: {r: function, a: 180}",
                                            "3: {r: function, a: {link: a6}}").replace(
        "4: {r: 0.01, a: 90}",
        "4: {r: 0.01, a: 90}\n  5: {r: 0.1, a: {link: a2}}\n  6: {r: function, a: function}"
        "\n  7: {r: 0.1, a: function}",
    ) + "  - vectors: [5, 6, 7]\n",
     15, ["contour 2 has 3 function parameters (r6, a6, a7)", "coupled block", "fix:"]),
    ("cycle_of_links", GOOD.replace("4: {r: 0.01, a: 90}",
                                    "4: {r: 0.01, a: {link: a5}}\n  5: {r: 1, a: {link: a4}}"
                                    ).replace("[1, 2, 3, 4]", "[1, 2, 3, 4, 5]"),
     9, ["links form a cycle: a4 -> a5 -> a4", "fix:"]),
    ("unknown_length_unit", "units: {length: furlongz}\n" + GOOD,
     1, ["units.length", "unknown unit 'furlongz'", "m, cm, mm"]),
    ("wrong_kind_of_unit", "units: {angle: mm}\n" + GOOD,
     1, ["'mm' is not an angle unit", "deg, rad, grad"]),
    ("quantity_with_wrong_unit", GOOD.replace("r: 0.2,", "r: 20 kg,"),
     7, ["vectors[2].r", "'20 kg' is not a length"]),
    ("misspelt_function", GOOD.replace("a: function", "a: functon"),
     7, ["'functon' is not a role", "did you mean 'function'?"]),
    ("table_position_not_a_number", GOOD.replace("{0: 0, 36: 360}", "{0: 0, x: 360}"),
     4, ["arguments[1].table.x", "a table position must be a whole number"]),
    ("table_position_out_of_range", GOOD.replace("{0: 0, 36: 360}", "{0: 0, 40: 360}"),
     4, ["position 40 is outside the calculation positions 0..36"]),
    ("table_list_wrong_length", GOOD.replace("{0: 0, 36: 360}", "[0, 10, 20]"),
     4, ["lists 3 values, but the model has 37 positions", "fix:"]),
    ("table_not_a_table", GOOD.replace("{0: 0, 36: 360}", "360"),
     4, ["a table is a mapping of position: value", "fix:"]),
    ("table_value_not_a_number", GOOD.replace("{0: 0, 36: 360}", "{0: 0, 36: lots}"),
     4, ["cannot read 'lots' as an angle"]),
    ("argument_not_defined", GOOD.replace("{argument: 1}", "{argument: 2}"),
     6, ["a1 uses argument 2, which is not defined", "fix:"]),
    ("argument_unused", GOOD.replace("  1: {table: {0: 0, 36: 360}}",
                                     "  1: {table: {0: 0, 36: 360}}\n  2: {table: {0: 1}}"),
     5, ["argument 2 drives no vector parameter", "fix:"]),
    ("vector_not_defined", GOOD.replace("[1, 2, 3, 4]", "[1, 2, 3, 4, 7]"),
     11, ["contour 1 lists vector 7, which is not defined"]),
    ("vector_in_no_contour", GOOD.replace("4: {r: 0.01, a: 90}",
                                          "4: {r: 0.01, a: 90}\n  5: {r: 1, a: 0}"),
     10, ["vector 5 is in no contour"]),
    ("vector_in_two_contours", GOOD + "  - vectors: [4, 1]\n",
     12, ["vector 4 is in contours 1 and 2", "link"]),
    ("variant_on_single_solution_module", GOOD.replace(
        "3: {r: function, a: 180}", "3: {r: function, a: 180}").replace(
        "2: {r: 0.2, a: function}", "2: {r: function, a: 30}") + "    variant: 2\n",
     12, ["module Pl2, which has one solution", "variant 2 does not apply"]),
    ("variant_not_allowed", GOOD + "    variant: 3\n", 12, ["contours[0].variant", "1, 2"]),
    ("unknown_key", GOOD.replace("1: {r: 0.05,", "1: {colour: red, r: 0.05,"),
     6, ["vectors[1].colour", "unknown key 'colour'"]),
    ("missing_positions", GOOD.replace("positions: 36\n", ""),
     None, ["'positions' is required"]),
    ("time_not_increasing", GOOD.replace("time: {rpm: 100}", "time: {table: {5: 0, 36: 1}}"),
     2, ["model time must increase"]),
    ("law_backwards", GOOD.replace("{table: {0: 0, 36: 360}}",
                                   "{law: cycloidal, start: [30, 0], end: [10, 90]}"),
     4, ["the law ends at position 10, not after its start 30"]),
    ("unknown_law", GOOD.replace("{table: {0: 0, 36: 360}}",
                                 "{law: sinusoid, start: [0, 0], end: [10, 90]}"),
     4, ["arguments[1].law", "constant_speed"]),
    ("yaml_syntax", GOOD.replace("1: {r: 0.05, a: {argument: 1}}",
                                 "1: {r: 0.05, a: {argument: 1}"),
     7, ["YAML syntax error", "flow mapping that starts at line 6", "fix:"]),
    ("duplicate_key", GOOD.replace("  4: {r: 0.01, a: 90}", "  4: {r: 0.01, a: 90}\n"
                                   "  4: {r: 0.02, a: 90}"),
     10, ["found the key 4 twice"]),
    ("not_a_mapping", "- just\n- a list\n", 1, ["does not hold a model mapping"]),
]


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "model.yaml"
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


@pytest.mark.parametrize(("text", "line", "fragments"),
                         [pytest.param(t, ln, f, id=name) for name, t, ln, f in CASES])
def test_check_reports_mistake_with_place_and_fix(tmp_path, text, line, fragments):
    path = _write(tmp_path, text)
    result = CliRunner().invoke(app, ["check", str(path)])
    message = result.output
    assert result.exit_code == 2, message
    assert "Traceback" not in message
    assert str(path) in message
    if line is not None:
        assert f"{path}:{line}" in message, message
    for fragment in fragments:
        assert fragment in message, message


def test_every_problem_is_reported_at_once(tmp_path):
    text = GOOD.replace("{argument: 1}", "{argument: 2}").replace(
        "4: {r: 0.01, a: 90}", "4: {r: 0.01, a: {link: a9}}")
    with pytest.raises(ModelError) as info:
        load_model(_write(tmp_path, text))
    # a1 uses a missing argument, so argument 1 drives nothing, and a4 links to nothing
    assert len(info.value.problems) == 3
    assert {p.line for p in info.value.problems} == {4, 6, 9}


def test_missing_file_is_reported(tmp_path):
    result = CliRunner().invoke(app, ["check", str(tmp_path / "nope.yaml")])
    assert result.exit_code == 2
    assert "file not found" in result.output
    assert "Traceback" not in result.output


@pytest.mark.parametrize("command", ["check", "info", "solve"])
def test_every_command_reports_errors_the_same_way(tmp_path, command):
    path = _write(tmp_path, GOOD.replace("a: function", "a: functon"))
    result = CliRunner().invoke(app, [command, str(path)])
    assert result.exit_code == 2
    assert f"{path}:7" in result.output
    assert "Traceback" not in result.output


def test_unknown_output_format(tmp_path):
    path = _write(tmp_path, GOOD)
    result = CliRunner().invoke(app, ["solve", str(path), "-o", str(tmp_path / "r.txt")])
    assert result.exit_code == 2
    assert "use a file name ending in .csv, .json, .parquet or .xlsx" in result.output


def test_model_error_pickles():
    import pickle

    err = ModelError([], "x.yaml")
    again = pickle.loads(pickle.dumps(err))
    assert again.file == "x.yaml"


def test_a_bad_force_unit_is_one_problem_at_the_unit_not_one_per_force(tmp_path):
    """``units.force`` (and the other load units) wrong: said once, at the unit; the
    forces are still checked for their own mistakes."""
    text = (Path(__file__).resolve().parents[1] / "examples" / "crank_slider_dynamics.yaml"
            ).read_text()
    force = "  - {name: P, body: 3, at: {tail: 3}, value: 1000, angle: 180}"
    assert force in text and "mass: kg, force: N}" in text
    path = tmp_path / "m.yaml"
    path.write_text(text.replace("mass: kg, force: N}", "mass: lbx, force: kgx}").replace(
        force, force + "\n" + force.replace("P,", "Q,").replace("1000", "'3 kgy'")
        + "\n" + force.replace("P,", "R,")))
    with pytest.raises(ModelError) as info:
        load_model(path)
    found = sorted((p.path, p.message) for p in info.value.problems)
    assert found == [(("forces", 1, "value"), "cannot read '3 kgy' as a force"),
                     (("units", "force"), "unknown unit 'kgx'"),
                     (("units", "mass"), "unknown unit 'lbx'")]
