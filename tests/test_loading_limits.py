"""A model file is bounded before it is expanded: size, nesting, aliases and value length
are refused at once with the line and the fix; unreadable bytes and keys that are not names
name their line too (issue 10, part 1)."""

from __future__ import annotations

import time
from pathlib import Path

import pytest
import yaml
from typer.testing import CliRunner

from mechloop import ModelError, load_model
from mechloop.cli import app
from mechloop.errors import ModelFileError
from mechloop.model import limits

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CRANK = (EXAMPLES / "crank_slider.yaml").read_text()

# the classic "billion laughs": 9**9 items from under 500 bytes
BOMB = "a: &a [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"{b}: &{b} [{', '.join(['*' + a] * 9)}]\n" for a, b in zip("abcdefgh", "bcdefghi",
                                                                 strict=True))


def _refused(tmp_path: Path, text: str | bytes, name: str = "m.yaml") -> ModelFileError:
    path = tmp_path / name
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text)
    start = time.perf_counter()
    with pytest.raises(ModelFileError) as info:
        load_model(path)
    assert time.perf_counter() - start < 3.0
    (problem,) = info.value.problems
    assert problem.hint and info.value.file == str(path)
    return info.value


def test_alias_bomb_is_refused_before_expansion(tmp_path):
    assert len(BOMB) < 500
    error = _refused(tmp_path, BOMB)
    problem = error.problems[0]
    assert "expands to more than 1,000,000 items" in problem.message
    assert problem.line is not None and 2 <= problem.line <= 9


def test_aliases_a_model_may_use_still_load(tmp_path):
    text = CRANK.replace("  1: {r: 0.05, a: {argument: 1}, name: crank}",
                         "  1: {r: &crank 0.05, a: {argument: 1}, name: crank}"
                         ).replace("  4: {r: 0.01, a: 90", "  4: {r: *crank, a: 90")
    path = tmp_path / "m.yaml"
    path.write_text(text)
    assert load_model(path).vectors[4].r == 0.05


def test_deep_nesting_is_refused_with_its_line(tmp_path):
    text = CRANK + "deep:\n  x: " + "[" * 1000 + "]" * 1000 + "\n"
    error = _refused(tmp_path, text)
    assert "nests more than 64 levels" in error.problems[0].message
    assert error.problems[0].line == CRANK.count("\n") + 2


def test_long_value_is_refused_before_any_unit_parsing(tmp_path):
    text = CRANK.replace("{0: 0, 72: 360}", "{0: 0, 72: '" + "x" * 100_000 + "'}")
    error = _refused(tmp_path, text)
    assert "100,000 characters" in error.problems[0].message
    assert error.problems[0].line == 15


def test_document_size_is_capped(tmp_path, monkeypatch):
    monkeypatch.setattr(limits, "MAX_DOCUMENT_BYTES", 1000)
    error = _refused(tmp_path, CRANK + "#" * 1000 + "\n")
    assert "larger than" in error.problems[0].message
    assert "csv" in error.problems[0].hint


def test_real_size_limit_admits_100000_inline_positions():
    table = ", ".join(f"{0.0036 * i:.4f}" for i in range(100_001))
    assert len(table) * 1.5 < limits.MAX_DOCUMENT_BYTES


def test_non_utf8_byte_names_its_line_and_column(tmp_path):
    payload = CRANK.encode().replace(b"connecting rod", b"connecting \xff rod")
    line = CRANK[:CRANK.index("connecting rod")].count("\n") + 1
    error = _refused(tmp_path, payload)
    problem = error.problems[0]
    assert problem.line == line
    assert "0xff" in problem.message and "column" in problem.message


def test_list_as_key_is_a_located_error(tmp_path):
    text = CRANK.replace("positions: 72", "positions: 72\n? [1, 2]\n: 3")
    error = _refused(tmp_path, text)
    problem = error.problems[0]
    assert "list or mapping as a key" in problem.message
    assert problem.line == CRANK[:CRANK.index("positions")].count("\n") + 2
    assert "name or a number" in problem.hint


@pytest.mark.parametrize("text", [BOMB, "a: " + "[" * 1000 + "]" * 1000 + "\n"])
def test_cli_refuses_quickly_with_exit_2(tmp_path, text):
    path = tmp_path / "m.yaml"
    path.write_text(text)
    start = time.perf_counter()
    result = CliRunner().invoke(app, ["check", str(path)])
    assert time.perf_counter() - start < 3.0
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert f"{path}:" in result.output and "fix:" in result.output


class _Refusing(yaml.SafeLoader):
    """A parser that stops at once, as libyaml does on what PyYAML accepts."""

    def check_event(self, *choices):
        raise yaml.parser.ParserError("refused")


def test_scan_falls_back_to_pyyaml_when_the_fast_parser_stops(tmp_path, monkeypatch):
    monkeypatch.setattr(limits, "_Parser", _Refusing)
    error = _refused(tmp_path, BOMB)
    assert "expands to more than" in error.problems[0].message


def test_many_bad_table_entries_give_a_bounded_report(tmp_path):
    wide = "{" + ", ".join(f"{k}: {k}" for k in range(0, 5000)) + "}"
    text = CRANK.replace("{0: 0, 72: 360}", wide)
    path = tmp_path / "m.yaml"
    path.write_text(text)
    with pytest.raises(ModelError) as info:
        load_model(path)
    (problem,) = info.value.problems
    assert problem.path == ("arguments", 1, "table", 73)
    assert "(and 4,926 more)" in problem.message

    junk = "[" + ", ".join(["[1, 2]"] * 5000) + "]"
    path.write_text(CRANK.replace("{0: 0, 72: 360}", junk))
    start = time.process_time()  # the work done, whatever the machine's load
    with pytest.raises(ModelError) as info:
        load_model(path)
    assert time.process_time() - start < 5.0
    problems = info.value.problems
    assert len(problems) == 51 and "more problems not listed" in problems[-1].message


@pytest.mark.parametrize("target", ["/dev/zero", "."])
def test_csv_that_is_not_a_file_is_never_read(tmp_path, target):
    path = tmp_path / "m.yaml"
    path.write_text(CRANK.replace("{table: {0: 0, 72: 360}}", "{csv: '" + target + "'}"))
    with pytest.raises(ModelError) as info:
        load_model(path)
    (problem,) = info.value.problems
    assert "is not a CSV file" in problem.message and problem.path == ("arguments", 1)


def test_csv_size_is_capped(tmp_path, monkeypatch):
    from mechloop.model import signals

    monkeypatch.setattr(signals, "MAX_CSV_BYTES", 100)
    (tmp_path / "t.csv").write_text("k,v\n" + "".join(f"{k},{k}\n" for k in range(73)))
    path = tmp_path / "m.yaml"
    path.write_text(CRANK.replace("{table: {0: 0, 72: 360}}", "{csv: t.csv}"))
    with pytest.raises(ModelError, match="larger than"):
        load_model(path)


def test_a_csv_table_is_read_once_also_when_the_file_has_problems(tmp_path, monkeypatch):
    """On the error path the tables were read a second time for the structural check (a
    large CSV twice); each is read once, and the problems of both kinds are reported."""
    from mechloop.model import document

    reads = []
    real = document.read_csv_table
    monkeypatch.setattr(document, "read_csv_table", lambda *a: reads.append(a) or real(*a))
    (tmp_path / "t.csv").write_text("k,v\n0,0\n72,360\n")
    path = tmp_path / "m.yaml"
    path.write_text(CRANK.replace("{table: {0: 0, 72: 360}}", "{csv: t.csv}")
                    .replace("rpm: 3000", "rpm: fast").replace("vectors: [1, 2, 3, 4]",
                                                                "vectors: [1, 2, 3, 9]"))
    with pytest.raises(ModelError) as info:
        load_model(path)
    assert {p.path[0] for p in info.value.problems} == {"time", "contours", "vectors"}
    assert len(reads) == 1


def test_readme_states_the_loading_limits():
    """The Limits paragraph of the model file's page (docs/models.md) says what the code
    enforces."""
    from mechloop.model import limits, numbers, signals

    text = " ".join((Path(__file__).resolve().parents[1] / "docs" / "models.md")
                    .read_text(encoding="utf-8").split())
    for phrase in (f"at most {limits.MAX_DOCUMENT_BYTES // 2**20} MiB",
                   f"at most {signals.MAX_CSV_BYTES // 2**20} MiB",
                   f"nests at most {limits.MAX_DEPTH} levels",
                   f"longer than {limits.MAX_SCALAR_CHARS:,} characters",
                   f"(a quantity string: {numbers.MAX_QUANTITY_CHARS})",
                   f"at most {limits.MAX_NODES:,} items",
                   f"at most {numbers.MAX_MAGNITUDE:.0e}".replace("e+", "e") + " in size",
                   f"below {numbers.MIN_MAGNITUDE:.0e} it counts as 0",
                   "is at most 10⁸"):
        assert phrase in text, phrase
    assert signals.MAX_POSITIONS == 10**8
