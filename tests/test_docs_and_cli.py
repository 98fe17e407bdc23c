"""The Python blocks of the README and docs/, the example scripts, the JSON Schema and the CLI
outputs."""

from __future__ import annotations

import json
import re
import runpy
from pathlib import Path

import jsonschema
import numpy as np
import pandas as pd
import pytest
import yaml
from helpers.docs import PAGES, page_text
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.model.schema import model_json_schema

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))


def test_readme_python_block_runs(tmp_path, monkeypatch):
    blocks = [(page, block) for page in PAGES
              for block in re.findall(r"```python\n(.*?)```", page_text(page), flags=re.S)]
    assert {"README.md", "docs/python-api.md"} <= {page for page, _ in blocks}, \
        "the README and docs/python-api.md show the Python API"
    monkeypatch.chdir(ROOT)
    for page, block in blocks:
        code = block.replace('"my_model.yaml"', repr(str(tmp_path / "my_model.yaml")))
        exec(compile(code, page, "exec"), {})
    saved = mechloop.load_model(tmp_path / "my_model.yaml")
    assert saved.positions == 72


def test_readme_starts_with_the_two_commands():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    commands = re.findall(r"```bash\n(.*?)```", text, flags=re.S)
    assert "mechloop solve examples/crank_slider.yaml -o results.csv" in commands[0]
    assert "pytest" in commands[1]
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert commands[1].strip() in ci


#: what a script prints that docs/synthesis.md quotes (its section "Starting from a classical
#: solution"): seeded DE runs with a generation limit, the same on every machine
PRINTS = {"classical_start.py": ["its structural error (the model's Q): 0.7540 deg",
                                 "seed 1, 60 generations): Q = 0.5980 deg",
                                 "without the classical start (de, seed 1, 60 generations): "
                                 "Q = 0.5839 deg"]}


@pytest.mark.parametrize("script", sorted((ROOT / "examples").glob("*.py")), ids=lambda p: p.name)
def test_example_scripts_run(script, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # scripts write their files to the working folder
    runpy.run_path(str(script), run_name="__main__")
    printed = capsys.readouterr().out
    assert printed
    for line in PRINTS.get(script.name, []):
        assert line in printed


def test_committed_schema_is_generated_from_the_code():
    committed = json.loads((ROOT / "src/mechloop/schema/model.schema.json").read_text())
    regenerate = "run: mechloop schema -o src/mechloop/schema/model.schema.json"
    assert committed == model_json_schema(), regenerate


def test_schema_command_prints_both_schemas(tmp_path):
    from typer.testing import CliRunner

    from mechloop.cli import app
    from mechloop.model.groups import group_json_schema

    runner = CliRunner()
    result = runner.invoke(app, ["schema", "--groups", "-o", str(tmp_path / "g.json")])
    assert result.exit_code == 0, result.output
    assert json.loads((tmp_path / "g.json").read_text()) == group_json_schema()
    result = runner.invoke(app, ["schema"])
    assert result.exit_code == 0 and json.loads(result.output) == model_json_schema()


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_examples_validate_against_the_schema(path):
    data = yaml.safe_load(path.read_text(encoding="utf-8"))
    # JSON object keys are strings: validate the JSON form of the document
    from mechloop.model.groups import group_json_schema

    schema = group_json_schema() if "groups" in data else model_json_schema()
    jsonschema.validate(json.loads(json.dumps(data)), schema)


def test_schema_rejects_what_the_loader_rejects():
    data = {"positions": 3, "vectors": {"1": {"r": 1, "a": "function", "colour": "red"}},
            "contours": [{"vectors": [1]}]}
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(data, model_json_schema())


def test_save_and_load_round_trip(tmp_path):
    model = mechloop.load_model(ROOT / "examples/crank_slider.yaml")
    for name in ("m.yaml", "m.json"):
        mechloop.save_model(model, tmp_path / name)
        assert mechloop.load_model(tmp_path / name) == model
    assert not list(tmp_path.glob(".*tmp")), "no temporary files left behind"


@pytest.mark.parametrize("suffix", [".csv", ".json", ".xlsx"])
def test_solve_writes_every_format(tmp_path, suffix):
    out = tmp_path / f"results{suffix}"
    result = CliRunner().invoke(app, ["solve", str(ROOT / "examples/crank_slider.yaml"),
                                      "-o", str(out)])
    assert result.exit_code == 0, result.output
    if suffix == ".csv":
        frame = pd.read_csv(out)
    elif suffix == ".json":
        frame = pd.DataFrame(json.loads(out.read_text()))
    else:
        frame = pd.read_excel(out)
    assert list(frame.columns) == [
        "position", "time [s]", "arg1 [deg]", "a1 [deg]", "da1 [rad/s]", "dda1 [rad/s^2]",
        "a2 [deg]", "da2 [rad/s]", "dda2 [rad/s^2]", "r3 [m]", "dr3 [m/s]", "ddr3 [m/s^2]",
        "chain_break"]
    assert len(frame) == 73
    expected = mechloop.solve(mechloop.load_model(ROOT / "examples/crank_slider.yaml"))
    np.testing.assert_allclose(frame["r3 [m]"], expected.value("r3"), rtol=1e-12)
    np.testing.assert_allclose(frame["time [s]"].iloc[-1], 60 / 3000)
    assert not frame["chain_break"].any()


def test_solve_reports_chain_breaks(tmp_path):
    text = (ROOT / "examples/crank_slider.yaml").read_text().replace(
        "2: {r: 0.2, a: function", "2: {r: 0.03, a: function")
    path = tmp_path / "short.yaml"
    path.write_text(text)
    out = tmp_path / "r.csv"
    result = CliRunner().invoke(app, ["solve", str(path), "-o", str(out)])
    assert result.exit_code == 0
    assert "contour 1 (Pl3) breaks at positions" in result.output
    assert "check the kinematic chain for a break" in result.output
    frame = pd.read_csv(out)
    broken = frame["chain_break"].to_numpy()
    # crank pin height r1 sin θ plus the offset must stay within the rod length
    theta = np.radians(frame["arg1 [deg]"].to_numpy())
    reach = np.abs(0.05 * np.sin(theta) + 0.01) > 0.03
    np.testing.assert_array_equal(broken, reach)
    assert frame.loc[broken, "r3 [m]"].isna().all()
    assert frame.loc[~broken, "r3 [m]"].notna().all()


def test_info_prints_parametric_formula():
    result = CliRunner().invoke(app, ["info", str(ROOT / "examples/crank_slider.yaml")])
    assert result.exit_code == 0
    assert "parametric formula: α1 (arg 1) → r3, α2 · Pl3, V=1" in result.output
    assert "structure formula:  n=2, m=4" in result.output


def test_check_accepts_every_example():
    for path in EXAMPLES:
        result = CliRunner().invoke(app, ["check", str(path)])
        assert result.exit_code == 0, result.output
        assert "OK" in result.output
