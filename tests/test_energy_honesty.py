"""``mechloop energy`` says when its cycle figures are not the cycle's, and prints how well
the works balance (issue 13, point 3; the command line only)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import yaml
from oracles.dynamic_models import four_bar_data
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
    assert mechloop.solve_dynamics(mechloop.load_model(
        EXAMPLES / "crank_slider_friction.yaml")).cycle_breaks is None
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


# ------------------------------------------- every cycle figure: report, machine:, views


def _long_crank(tmp_path: Path, **extra) -> Path:
    """The slider-crank of crank_slider_dynamics.yaml with a crank (0.25 m) longer than
    the rod (0.2 m): the chain breaks at positions around 90 and 270 deg."""
    data = yaml.safe_load((EXAMPLES / "crank_slider_dynamics.yaml").read_text())
    data["vectors"][1]["r"] = 0.25
    data.update(extra)
    path = tmp_path / "long_crank.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


def _four_bar_between(tmp_path: Path, **extra) -> Path:
    """A four-bar whose crank (0.1 m; coupler 0.149999, rocker 0.25, frame 0.3 m) loses
    its turn for 0.6 deg around 180 deg, between positions 36 and 37 of 73: every position
    assembles, no friction — the works alone would claim an efficiency of 100 %."""
    data = {"name": "four-bar, break between positions", **four_bar_data(0.149999, 73),
            "moments": [{"name": "resistance", "body": 3, "value": -2.0}], **extra}
    path = tmp_path / "four_bar_between.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


def _no_efficiency_claimed(text: str) -> None:
    assert "efficiency 100 %" not in text and "efficiency: 100" not in text
    assert not re.search(r"efficiency\s+\S*\s*100\b", text)


def test_a_break_between_positions_is_told_and_no_efficiency_is_claimed(tmp_path: Path):
    path = _four_bar_between(tmp_path)
    kin = mechloop.solve(mechloop.load_model(path))
    assert not kin.broken.any() and kin.breaks_between  # only the exact check sees it
    dyn = mechloop.solve_dynamics(mechloop.load_model(path))
    assert dyn.summary.efficiency == 1.0  # what the works alone would claim
    assert dyn.cycle_breaks.between == ((36, 37),)  # and what the API says of them
    assert dyn.cycle_breaks.positions.size == 0
    result = _energy(path)
    assert result.exit_code == 0, result.output
    assert "warning: the chain breaks between positions 36 and 37" in result.output
    assert "efficiency: not given" in result.output
    _no_efficiency_claimed(result.output)
    from mechloop.views.dynamics import summary_rows

    _, _, totals = summary_rows(dyn)
    figures = dict(totals)
    assert figures["efficiency η"].startswith("not given: the chain breaks")
    assert "between positions 36 and 37" in figures["loss coefficient ψ"]


def test_machine_refuses_a_cycle_the_chain_cannot_pass(tmp_path: Path):
    # positions that all assemble, a break between two of them: machine: has no cycle
    path = _four_bar_between(tmp_path, machine={"delta": 0.05})
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.solve_dynamics(mechloop.load_model(path))
    assert info.value.problems[0].path == ("machine",)
    assert "between positions 36 and 37" in str(info.value)
    # and a break at positions, as before
    with pytest.raises(mechloop.ModelError) as info:
        mechloop.solve_dynamics(mechloop.load_model(_long_crank(tmp_path,
                                                                machine={"delta": 0.05})))
    assert "needs the whole cycle" in str(info.value)


@pytest.mark.parametrize("lang, words, told", [
    ("en", ("WARNING: the chain breaks in the cycle", "are not valid",
            "efficiency η"), "warning: WARNING: the chain breaks in the cycle"),
    ("ru", ("ВНИМАНИЕ: кинематическая цепь разрывается в цикле", "недостоверны",
            "КПД η"), "предупреждение: ВНИМАНИЕ: кинематическая цепь разрывается")])
def test_the_report_says_its_cycle_figures_are_not_valid(tmp_path: Path, monkeypatch, lang,
                                                       words, told):
    import mechloop.report.write as write
    from mechloop.report.document import Paragraph

    # the document is caught before it is typeset (tests/test_report_and_cli_views.py
    # typesets whole ones)
    made = []

    def capture(document, path, *, progress=None):
        made.append(document)
        return Path(path)

    monkeypatch.setattr(write, "write_document", capture)
    path = _long_crank(tmp_path)
    pdf = tmp_path / f"report_{lang}.pdf"
    result = CliRunner().invoke(app, ["report", str(path), "-o", str(pdf), "--lang", lang])
    assert result.exit_code == 0, result.output
    output = " ".join(result.output.split())
    assert told in output
    assert words[1] in output
    [document] = made
    conclusion = document.sections[-1]
    warning = [p.text for p in conclusion.blocks
               if isinstance(p, Paragraph) and p.kind == "warning"]
    assert len(warning) == 1
    for word in words:
        assert word in warning[0], word
    broken = mechloop.solve(mechloop.load_model(path)).broken
    from mechloop.solve.results import compress_positions

    assert compress_positions(np.flatnonzero(broken)) in warning[0]
    # the conclusion gives no efficiency, in either language
    text = " ".join(p.text for p in conclusion.blocks)
    assert "Mechanical efficiency over the cycle" not in text
    assert "Механический КПД за цикл" not in text


def test_a_whole_cycle_report_keeps_its_efficiency(tmp_path: Path):
    from mechloop.report.conclusion import conclusion_blocks
    from mechloop.report.numbers import Shown
    from mechloop.report.words import TEXT

    dyn = mechloop.solve_dynamics(mechloop.load_model(EXAMPLES / "crank_slider_friction.yaml"))
    lines = [p.text for p in conclusion_blocks(dyn.kinematics, dyn, "r3", Shown(None, "en"),
                                               TEXT["en"])]
    efficiency = [line for line in lines
                  if line.startswith("Mechanical efficiency over the cycle: η = ")]
    assert len(efficiency) == 1
    value = float(efficiency[0].split("= ")[1].split(" %")[0])
    assert value == pytest.approx(100 * float(dyn.summary.efficiency), abs=5e-3)
    assert not any("WARNING" in line for line in lines)
