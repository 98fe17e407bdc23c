"""Tables imported from CSV files (arguments, time, load values): read when the model is
loaded, relative to the model file, and equal to the same table written inline."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app

ROOT = Path(__file__).resolve().parents[1]
ENGINE = ROOT / "examples/single_cylinder_engine.yaml"


def engine_with_csv(tmp_path: Path, rows: str, value: dict) -> Path:
    data = yaml.safe_load(ENGINE.read_text())
    (tmp_path / "data").mkdir()
    (tmp_path / "data/gas.csv").write_text(rows)
    data["forces"][0]["value"] = value
    path = tmp_path / "engine.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def test_load_table_from_csv_equals_the_inline_table(tmp_path):
    inline = yaml.safe_load(ENGINE.read_text())["forces"][0]["value"]["table"]
    rows = "position,other,gas_kN\n" + "".join(f"{k},0,{v}\n" for k, v in enumerate(inline))
    path = engine_with_csv(tmp_path, rows, {"csv": "data/gas.csv", "column": "gas_kN",
                                            "unit": "kN"})
    from_csv = mechloop.solve_dynamics(mechloop.load_model(path))
    expected = mechloop.solve_dynamics(mechloop.load_model(ENGINE))
    np.testing.assert_array_equal(from_csv.loads.forces[0].force,
                                  expected.loads.forces[0].force)
    np.testing.assert_array_equal(from_csv.forces.balancing[1], expected.forces.balancing[1])


def test_sparse_csv_argument_is_filled_by_kdam_rules(tmp_path):
    """KDAM's table 3.1 example (values at positions 3, 6, 10) from a CSV file, by column
    index, gives the same argument as the inline sparse table of sparse_argument.yaml."""
    data = yaml.safe_load((ROOT / "examples/sparse_argument.yaml").read_text())
    table = data["arguments"][1]["table"]
    (tmp_path / "stroke.csv").write_text(
        "k,s\n" + "".join(f"{k},{v}\n" for k, v in table.items()))
    data["arguments"][1] = {"csv": "stroke.csv", "column": 1,
                            **{k: v for k, v in data["arguments"][1].items() if k != "table"}}
    path = tmp_path / "sparse.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    got = mechloop.solve(mechloop.load_model(path))
    want = mechloop.solve(mechloop.load_model(ROOT / "examples/sparse_argument.yaml"))
    np.testing.assert_array_equal(got.arguments[1], want.arguments[1])


@pytest.mark.parametrize("rows, value, message", [
    ("position,gas\n0,1\n", {"csv": "data/missing.csv"}, "not found"),
    ("position,gas\n0,1\n", {"csv": "data/gas.csv", "column": "pressure"},
     "has no column 'pressure'"),
    ("position,gas\n0,1\n1.5,2\n", {"csv": "data/gas.csv"}, "line 3: not a position"),
    ("position,gas\n0,1\n", {"csv": "data/gas.csv", "column": 4}, "has no value column 4"),
])
def test_csv_mistakes_name_the_file_and_the_fix(tmp_path, rows, value, message):
    path = engine_with_csv(tmp_path, rows, value)
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code == 2
    assert message in result.output
    assert f"{path.name}:" in result.output and "forces[0].value" in result.output
    assert "fix:" in result.output
    assert "Traceback" not in result.output
