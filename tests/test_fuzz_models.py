"""Fuzzing the command line: no input makes ``mechloop check`` or ``mechloop solve`` end
in a traceback, run over a few seconds, exit with a code other than 0 or 2, let a warning
reach the user, or write a non-finite number in a row not marked ``chain_break``
(issue 10, part 3).

Inputs: the cases the issue reports (each class must stay fixed), mutations of every
bundled example (vector files and group files), documents drawn from the model schema,
YAML documents of any shape, and raw text and bytes.  Each input runs in a child of a
warmed-up fork server, with a wall-clock limit per command and a memory cap
(``tests/fuzz/harness.py``).

CI runs a fixed, derandomized budget (profile ``fuzz-ci``); ``MECHLOOP_FUZZ=long`` selects
the profile ``fuzz-long`` (random, many examples, shrinking on) for a longer local run —
see docs/testing.md, section "Fuzzing".
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from fuzz.harness import assert_clean, check_rows, run_input
from fuzz.mutations import BILLION_LAUGHS, EXAMPLES, mutated
from fuzz.strategies import raw_files, schema_files, yaml_files
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

pytestmark = pytest.mark.skipif(not hasattr(os, "fork") or sys.platform != "linux",
                                reason="the fuzz harness forks a child per input (Linux)")

_COMMON = dict(deadline=None,  # the harness enforces its own wall-clock limit per command
               suppress_health_check=list(HealthCheck), print_blob=True)
settings.register_profile("fuzz-ci", max_examples=5, derandomize=True, database=None,
                          phases=(Phase.explicit, Phase.generate), **_COMMON)
settings.register_profile("fuzz-long", max_examples=int(os.environ.get(
    "MECHLOOP_FUZZ_EXAMPLES", "500")), **_COMMON)
FUZZ = settings.get_profile("fuzz-long" if os.environ.get("MECHLOOP_FUZZ") == "long"
                            else "fuzz-ci")


def _scaled(n: int):
    """The profile, with ``n`` times its examples (a strategy that finds more per example
    gets fewer)."""
    return settings(FUZZ, max_examples=max(1, FUZZ.max_examples * n))


@pytest.fixture(scope="module", autouse=True)
def fork_server():
    """Start the harness's fork server (it imports mechloop and runs every example once)
    before the first timed input; an example must come out clean."""
    assert_clean(run_input({"model.yaml": EXAMPLES[0].read_bytes()}))


def test_the_judge_of_written_rows(tmp_path):
    """A non-finite or non-numeric cell is a failure only in a row not marked broken."""
    table = tmp_path / "out.csv"
    table.write_text("position,x [m],chain_break\n0,1.5,False\n1,,True\n2,inf,True\n"
                     "3,nan,False\n4,,False\n5,abc,False\n", encoding="utf-8")
    assert check_rows(table) == ["row 3, x [m]: 'nan'", "row 4, x [m]: ''",
                                 "row 5, x [m]: 'abc'"]
    records = tmp_path / "out.json"
    records.write_text('[{"position": 0, "x [m]": null, "chain_break": true},'
                       ' {"position": 1, "x [m]": null, "chain_break": false},'
                       ' {"position": 2, "x [m]": Infinity, "chain_break": false},'
                       ' {"position": 3, "x [m]": 2.0, "chain_break": false}]',
                       encoding="utf-8")
    assert check_rows(records) == ["row 1, x [m]: None", "row 2, x [m]: inf"]


def _example(name: str) -> str:
    return (Path(__file__).resolve().parents[1] / "examples" / name).read_text("utf-8")


SLIDER = _example("crank_slider.yaml")
DYNAMICS = _example("crank_slider_dynamics.yaml")
FOUR_BAR_GROUPS = _example("four_bar_groups.yaml")
SIX_BAR_GROUPS = _example("six_bar_groups.yaml")
TRIAD = _example("class3_six_bar_groups.yaml")
FORCE = "value: 1000, angle: 180"


def _replace(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


KNOWN = {
    # hangs
    "group_angle_1e20": _replace(FOUR_BAR_GROUPS, "distance: 250, angle: 30",
                                 "distance: 250, angle: 1e20"),
    "group_angle_huge_int": _replace(FOUR_BAR_GROUPS, "distance: 250, angle: 30",
                                     f"distance: 250, angle: {10**30}"),
    "group_guide_angle_1e20": _replace(SIX_BAR_GROUPS, "through: G, angle: 0",
                                       "through: G, angle: -1e20"),
    "alias_bomb": BILLION_LAUGHS + SLIDER,
    # a triad's numbers (its middle link, its assembly guess)
    "triad_angle_1e20": _replace(TRIAD, "angle: 47 ", "angle: 1e20 "),
    "triad_guess_nan": _replace(TRIAD, "B: [170, 270]", "B: [.nan, 270]"),
    "triad_side_inf": _replace(TRIAD, "sides: [310, 350]", "sides: [.inf, 350]"),
    "triad_guess_1e300": _replace(TRIAD, "guess: {A: [60, 0]", "guess: {A: [1e300, 0]"),
    "table_value_100k_string": _replace(SLIDER, "72: 360}", "72: " + "x" * 100_000 + "}"),
    "table_value_100k_digits": _replace(SLIDER, "72: 360}", "72: " + "9" * 100_000 + "}"),
    # tracebacks
    "nesting_1000_deep": SLIDER + "nested: " + "[" * 1000 + "1" + "]" * 1000 + "\n",
    "nesting_1000_deep_mapping": SLIDER + "nested: " + "{a: " * 1000 + "1" + "}" * 1000,
    "complex_key": SLIDER + "? [1, 2]\n: 3\n",
    "complex_key_in_vectors": _replace(SLIDER, "vectors:\n", "vectors:\n  ? [1, 2]\n  : 3\n"),
    "force_list_one_short": _replace(DYNAMICS, FORCE, f"value: {[1000] * 72}, angle: 180"),
    "force_table_list_one_short": _replace(DYNAMICS, FORCE,
                                           f"value: {{table: {[1000] * 72}}}, angle: 180"),
    "center_along_with_units": _replace(DYNAMICS, "center: {vector: 2, share: 0.3}",
                                        'center: {vector: 2, along: "5 kg"}'),
    "positions_1e9": _replace(SLIDER, "positions: 72", "positions: 1000000000"),
    "positions_1e9_float": _replace(SLIDER, "positions: 72", "positions: 1.0e+9"),
    "positions_huge_int": _replace(SLIDER, "positions: 72", f"positions: {2**64}"),
    # non-numbers accepted
    "rpm_inf": _replace(SLIDER, "time: {rpm: 3000}", "time: {rpm: .inf}"),
    "rpm_nan": _replace(SLIDER, "time: {rpm: 3000}", "time: {rpm: .nan}"),
    "gravity_nan": _replace(DYNAMICS, "gravity: {g: 9.81}", "gravity: {g: .nan}"),
    "mass_inf": _replace(DYNAMICS, "mass: 2,", "mass: .inf,"),
    "inertia_nan": _replace(DYNAMICS, "inertia: 0.01,", "inertia: .nan,"),
    "table_ending_in_nan": _replace(SLIDER, "{0: 0, 72: 360}", "{0: 0, 72: .nan}"),
    "table_list_with_inf": _replace(SLIDER, "{0: 0, 72: 360}",
                                    str([5.0 * i for i in range(72)] + [".inf"]).replace(
                                        "'", "")),
    "length_1e200": _replace(SLIDER, "r: 0.05,", "r: 1e200,"),
    "length_inf": _replace(SLIDER, "r: 0.2,", "r: .inf,"),
    "angle_nan": _replace(SLIDER, "a: 90,", "a: .nan,"),
    "force_table_inf": _replace(DYNAMICS, FORCE, "value: {table: {0: 1000, 72: .inf}}, "
                                "angle: 180"),
    "force_value_nan": _replace(DYNAMICS, FORCE, "value: .nan, angle: 180"),
    "force_angle_1e20": _replace(DYNAMICS, FORCE, "value: 1000, angle: 1e20"),
    "force_angle_nan": _replace(DYNAMICS, FORCE, "value: 1000, angle: .nan"),
    "rpm_1e308": _replace(SLIDER, "time: {rpm: 3000}", "time: {rpm: 1.0e+308}"),
    "table_1e308": _replace(SLIDER, "{0: 0, 72: 360}", "{0: 1.0e+308, 72: 360}"),
    "friction_radius_1e9": _replace(_example("crank_slider_friction.yaml"), "radius: 0.015",
                                    "radius: 1.0e+9"),
    "unit_expression_1200_tokens": _replace(SLIDER, "units: {length: m,",
                                            "units: {length: '" + "1 " * 1200 + "m',"),
    "csv_path_is_a_directory": _replace(SLIDER, "1: {table: {0: 0, 72: 360}}",
                                        '1: {csv: ""}'),
    "alias_bomb_inside_a_value": _replace(SLIDER, "name: Offset slider-crank",
                                          "name: Offset slider-crank\nextra:\n  " +
                                          BILLION_LAUGHS.replace("\n", "\n  ").rstrip()),
    "nesting_5000_deep": SLIDER + "nested: " + "[" * 5000 + "1" + "]" * 5000 + "\n",
    # errors without a place
    "non_utf8": _replace(SLIDER, "name: Offset", "name: Offset \udcff"),
    "nul_byte": _replace(SLIDER, "name: Offset", "name: Offset \x00"),
}

CSV_KNOWN = {
    "csv_table_inf": "position,value\n0,0\n36,inf\n72,360\n",
    "csv_table_nan": "position,value\n0,0\n36,nan\n72,360\n",
    "csv_table_1e400": "position,value\n0,0\n72,1e400\n",
    "csv_table_huge_position": f"position,value\n0,0\n{2**64},360\n",
    "csv_table_empty": "",
    "csv_table_binary": "position,value\n0,\xff\xfe\n",
    "csv_table_inf_position": "position,value\ninf,inf\n72,360\n",
}


ACCEPTABLE = {"group_angle_1e20", "group_angle_huge_int", "group_guide_angle_1e20",
              "force_angle_1e20"}
"""Cases whose fix may accept the input (an angle is taken modulo a turn); every other case
feeds a malformed, non-finite or absurd value that must be refused where it enters."""


def _assert_refused(report) -> None:
    """Clean, and every command exits 2 with a message (the input is refused)."""
    assert_clean(report)
    accepted = [o for o in report.outcomes if o.exit_code != 2 or "error" not in o.output]
    assert not accepted, ("the input must be refused (exit 2 with an error), but:\n"
                          + "\n".join(f"$ mechloop {' '.join(o.command)} => exit "
                                      f"{o.exit_code}: {o.output[-300:]}" for o in accepted)
                          + "\n" + report.reproducer())


@pytest.mark.parametrize("name", sorted(KNOWN))
def test_inputs_the_issue_reports(name):
    report = run_input({"model.yaml": KNOWN[name]})
    if name in ACCEPTABLE:
        assert_clean(report)
    else:
        _assert_refused(report)


@pytest.mark.parametrize("name", sorted(CSV_KNOWN))
def test_csv_tables_the_issue_reports(name):
    model = _replace(SLIDER, "1: {table: {0: 0, 72: 360}}", "1: {csv: table.csv}")
    _assert_refused(run_input({"model.yaml": model, "table.csv": CSV_KNOWN[name].encode(
        "utf-8", "surrogateescape")}))


@pytest.mark.parametrize("example", EXAMPLES, ids=[e.stem for e in EXAMPLES])
@FUZZ
@given(data=st.data())
def test_mutated_examples(example, data):
    assert_clean(run_input(data.draw(mutated(example), label="files")))


@_scaled(4)
@given(files=schema_files())
def test_documents_from_the_schema(files):
    assert_clean(run_input(files))


@_scaled(3)
@given(files=yaml_files())
def test_yaml_documents_of_any_shape(files):
    assert_clean(run_input(files))


@_scaled(4)
@given(files=raw_files())
def test_raw_text_and_bytes(files):
    assert_clean(run_input(files))


def test_the_standalone_fuzzer_prints_its_summary(capsys):
    """``tests/fuzz/run_fuzz.py`` (the longer run of docs/testing.md) counts every command."""
    from fuzz import run_fuzz

    code = run_fuzz.main(["-n", "2", "--sources", "raw", "--seed", "1"])
    printed = capsys.readouterr().out
    assert "2 inputs, 6 commands" in printed
    assert "exit codes: 2: 6" in printed
    assert code == 0 and "0 failing inputs in 0 groups" in printed
