"""``mechloop energy`` says when its cycle figures are not the cycle's, and prints how well
the works balance (issue 13, point 3; the command line only)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import yaml
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _energy(path: Path):
    return CliRunner().invoke(app, ["energy", str(path)])


def test_a_chain_that_breaks_is_told_and_its_positions_named(tmp_path: Path):
    # the crank (0.25 m) longer than the rod (0.2 m): the rod cannot reach the guide
    # where |0.01 + 0.25 sin(theta)| > 0.2, around 90 and 270 deg
    data = yaml.safe_load((EXAMPLES / "crank_slider_dynamics.yaml").read_text())
    data["vectors"][1]["r"] = 0.25
    path = tmp_path / "long_crank.yaml"
    path.write_text(yaml.safe_dump(data))
    broken = mechloop.solve(mechloop.load_model(path)).broken
    assert 0 < broken.sum() < broken.size
    result = _energy(path)
    assert result.exit_code == 0, result.output
    assert "warning: the chain breaks" in result.output
    assert f"at {int(broken.sum())} of {broken.size} positions" in result.output
    assert "are not the cycle's" in result.output
    assert "positions with a break are left out" in result.output
    drawn = CliRunner().invoke(app, ["plot", str(path), "summary", "-o",
                                     str(tmp_path / "summary.png")])
    assert drawn.exit_code == 0, drawn.output
    assert "warning: the chain breaks" in drawn.output and "works drawn" in drawn.output


def test_a_whole_cycle_prints_no_warning_and_a_balance_at_rounding():
    # the compressor with friction: driving = resisting + friction + change of kinetic
    # energy, work by work as the table prints them
    result = _energy(EXAMPLES / "crank_slider_friction.yaml")
    assert result.exit_code == 0, result.output
    assert "warning" not in result.output
    found = re.search(r"leave (\S+) J \((\S+) of the largest work", result.output)
    assert found, result.output
    dyn = mechloop.solve_dynamics(mechloop.load_model(EXAMPLES / "crank_slider_friction.yaml"))
    s = dyn.summary
    residual = sum(r.positive_work + r.negative_work for r in s.rows) - s.kinetic_energy_change
    assert float(found.group(1)) == float(f"{residual:.3g}")
    largest = max(r.positive_work - r.negative_work for r in s.rows)
    assert abs(residual) < 1e-12 * largest
    # the rows hold the drive, the gas force, gravity and friction: the balance is not
    # empty (friction takes a real share)
    assert s.friction_work > 0.1 * s.driving_work and np.isfinite(s.efficiency)
