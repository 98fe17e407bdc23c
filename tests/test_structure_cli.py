"""``mechloop structure``: mobility, formula, class and table on the command line."""

from __future__ import annotations

from pathlib import Path

from typer.testing import CliRunner

from mechloop.cli import app

ROOT = Path(__file__).resolve().parents[1]


def test_structure_of_the_slider_crank_by_hand():
    """n = 3 moving links, p5 = 4 lower pairs: W = 3·3 − 2·4 = 1 = one input; the crank is
    the input group and rod + slider an RRP dyad (L2): a class II mechanism."""
    path = ROOT / "examples/crank_slider_dynamics.yaml"
    result = CliRunner().invoke(app, ["structure", str(path)])
    assert result.exit_code == 0, result.output
    assert "W = 3·3 − 2·4 − 0 = 1" in result.output
    assert "structure formula: L0(1) → L2(2,3)" in result.output
    assert "class of the mechanism: II" in result.output
    assert "RRP" in result.output


def test_structure_needs_bodies():
    result = CliRunner().invoke(app, ["structure", str(ROOT / "examples/crank_slider.yaml")])
    assert result.exit_code == 2
    assert "no bodies" in result.output and "Traceback" not in result.output
