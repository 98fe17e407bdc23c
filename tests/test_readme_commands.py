"""Every command the README and the pages of docs/ show runs: each `mechloop ...` line of their
```bash blocks and each inline `mechloop ...` (or `plot M ...` of the views table) with its
arguments, in a scratch folder holding a copy of the examples, exits 0.

Placeholders: `M` and `MODEL` stand for a model with bodies (the README says so); the
machine-motion view needs a `machine:` section. The synthesis commands run with
`--iterations 3 --no-polish` (the README says the suite does so; their figures are checked
by the tests listed in tests/test_readme_figures.py). The energy example's numbers are
checked against the energy balance, and the synthesis summary's terms against its total.
"""

from __future__ import annotations

import re
import shlex
import shutil
from pathlib import Path

import numpy as np
import pytest
from helpers.docs import all_text
from typer.main import get_command
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app

ROOT = Path(__file__).resolve().parents[1]
README = all_text()  # README.md and every page of docs/
PLACEHOLDER = {"M": "examples/crank_slider_dynamics.yaml",
               "MODEL": "examples/crank_slider_dynamics.yaml"}
MACHINE = "examples/single_cylinder_engine.yaml"  # `plot M motion` needs a machine: section
SHORT_RUN = ["--iterations", "3", "--no-polish"]
#: lines of ```bash blocks that are not mechloop commands, and why the suite does not run them
#: here (a prefix of the line -> the reason)
NOT_MECHLOOP = {
    "python3 -m venv .venv": "set-up: tests/test_docs_and_cli.py checks these two blocks "
                             "and .ci/run runs the test command verbatim",
    ". .venv/bin/activate": "activates the environment the suite runs in",
    "apt-get update": "set-up: the headless Chromium of the web application's browser tests "
                      "(the test command, run verbatim by .ci/run)",
    "python examples/": "run by tests/test_docs_and_cli.py::test_example_scripts_run",
    "python benchmarks/": "a benchmark the README names for its figures",
    ".venv/bin/pip install -e \".[bench]\"": "needs the optional bench extra (pylinkage)",
    "MECHLOOP_FUZZ=long": "the long fuzz run (many minutes); the suite runs the same tests "
                          "with the CI budget",
    ".venv/bin/python tests/fuzz/run_fuzz.py": "run with a small -n by tests/"
                                               "test_fuzz_models.py (the standalone fuzzer)",
}


def _bash_lines() -> list[str]:
    lines = []
    for block in re.findall(r"```bash\n(.*?)```", README, flags=re.S):
        for line in block.replace("\\\n", " ").splitlines():
            line = re.sub(r"\s+#.*$", "", line).strip()
            if line:
                lines.append(line)
    return lines


def _commands() -> list[str]:
    found: list[str] = []
    for line in _bash_lines():
        parts = [p.strip() for p in line.split("&&")]
        mech = [p.removeprefix(".venv/bin/") for p in parts
                if p.removeprefix(".venv/bin/").startswith("mechloop ")]
        if mech:
            found += mech
        else:
            assert any(line.startswith(k) for k in NOT_MECHLOOP), f"unclassified: {line}"
    for span in re.findall(r"`((?:mechloop|plot M) [^`]+)`", README):
        if not span.startswith("mechloop "):
            span = "mechloop " + span
        words = span.split()
        if len(words) >= 3 or words[1:] == ["schema"]:  # a command with its arguments
            found.append(span)
    return list(dict.fromkeys(found))




def test_every_command_name_the_readme_mentions_exists():
    names = set(re.findall(r"`mechloop (\w+)", README))
    assert names <= set(get_command(app).commands), names - set(get_command(app).commands)
    assert len(COMMANDS) >= 30  # the README shows every command and every view


def test_the_readme_says_how_the_suite_runs_its_commands():
    assert ". .venv/bin/activate" in README
    assert "`--iterations 3 --no-polish`" in README


@pytest.fixture(scope="module")
def scratch(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("readme")
    shutil.copytree(ROOT / "examples", folder / "examples")
    return folder


def _args(command: str) -> list[str]:
    args = shlex.split(command)[1:]
    args = [PLACEHOLDER.get(a, a) for a in args]
    if args[:1] == ["plot"] and "motion" in args:
        args[1] = MACHINE
    if args[:1] == ["plot"] and "-o" not in args:
        args += ["-o", f"{args[2]}.png"]  # the views table leaves out the file
    if args[:1] == ["synthesize"]:
        args += SHORT_RUN
    return args


#: each command once: `mechloop report MODEL ...` is the README's explicit report command
COMMANDS = list({tuple(_args(c)): c for c in reversed(_commands())}.values())[::-1]


@pytest.mark.parametrize("command", COMMANDS)
def test_readme_command_runs(command, scratch, monkeypatch):
    monkeypatch.chdir(scratch)
    result = CliRunner().invoke(app, _args(command))
    assert result.exit_code == 0, result.output
    if command.startswith("mechloop synthesize"):
        _check_synthesis_summary(result.output)


def _rows(output: str, title: str) -> dict[str, str]:
    """Rows of a Rich table printed under ``title``: first cell -> second cell."""
    block = output.split(title, 1)[1].split("└", 1)[0]
    rows = {}
    for line in block.splitlines():
        cells = [c.strip() for c in line.split("│")[1:-1]]
        if len(cells) >= 2 and cells[0]:
            rows[cells[0]] = cells[1]
    return rows


def _check_synthesis_summary(output: str) -> None:
    """The printed terms add up to the printed minimized total, Q among them."""
    rows = _rows(output, "Minimized total and its terms")
    total = float(rows.pop("total (minimized)"))
    terms = [float(v) for v in rows.values()]
    assert sum(terms) == pytest.approx(total, rel=1e-5, abs=1e-9)
    line = next(ln for ln in output.splitlines() if ln.startswith("minimized total"))
    assert f"minimized total {total:.6g}" in line
    q = [v for k, v in rows.items() if k.startswith("Q: main condition")]
    if q:
        assert f"Q = {float(q[0]):.6g}" in line


def test_synthesis_summary_shows_a_penalty_as_a_term_of_the_total(monkeypatch, scratch):
    """Free timing with ordered inputs: Q and the order penalty are both terms; the line
    under the table names the total, not Q alone (it printed Q = 4.3e-13 while the total
    minimized was 5.64). The same run from Python, its best design evaluated again, gives
    the printed numbers."""
    from mechloop.synthesis.search import synthesize

    monkeypatch.chdir(scratch)
    path = "examples/six_points_free_timing_synthesis.yaml"
    result = CliRunner().invoke(app, ["synthesize", path, "--iterations", "2", "--no-polish"])
    assert result.exit_code == 0, result.output
    _check_synthesis_summary(result.output)
    rows = _rows(result.output, "Minimized total and its terms")
    assert "penalty order" in rows
    run = synthesize(mechloop.load_model(path), iterations=2, polish=False)
    again = run.problem.evaluate(run.best[None, :])
    assert float(rows["total (minimized)"]) == pytest.approx(again.total[0], rel=1e-5)
    q = next(v for k, v in rows.items() if k.startswith("Q: main condition"))
    assert float(q) == pytest.approx(again.q[0], rel=1e-5)
    assert float(rows["penalty order"]) == pytest.approx(again.terms["order"][0], rel=1e-5,
                                                         abs=1e-12)


def test_energy_example_prints_a_meaningful_efficiency(scratch, monkeypatch):
    """`mechloop energy examples/crank_slider_friction.yaml` (the compressor): the printed
    works and efficiency agree with the energy balance computed here from the results table —
    the piston force's work from the slider's speed, the friction work from the lost power."""
    monkeypatch.chdir(scratch)
    path = "examples/crank_slider_friction.yaml"
    assert f"mechloop energy {path}" in README
    result = CliRunner().invoke(app, ["energy", path])
    assert result.exit_code == 0, result.output
    text = " ".join(result.output.split())
    driving = float(re.search(r"driving ([\d.e+-]+) J", text).group(1))
    friction = float(re.search(r"friction ([\d.e+-]+) J", text).group(1))
    loss = float(re.search(r"loss coefficient ([\d.e+-]+) %", text).group(1)) / 100
    efficiency = float(re.search(r"efficiency ([\d.e+-]+) %", text).group(1)) / 100

    model = mechloop.load_model(path)
    frame = mechloop.solve_dynamics(model).to_frame()
    t = frame["time [s]"].to_numpy()
    # P acts on the slider along -x; the slider's x is r3 (the loop closes at the crank
    # centre), so P's power is -P(t)·dr3; P follows its table {0: 0, 36: 0, 38: 1000, 70:
    # 1000, 72: 0}, filled linearly between the given positions
    table = model.forces[0].value.table
    p = np.interp(frame["position"], list(table), list(table.values()))
    useful = -np.trapezoid(-p * frame["dr3 [m/s]"].to_numpy(), t)
    lost = np.trapezoid(frame["friction_loss [W]"].to_numpy(), t)
    assert useful > 50 and lost > 50  # the compressor does work and friction costs some
    assert friction == pytest.approx(lost, rel=1e-5)
    assert driving == pytest.approx(useful + lost, rel=1e-4)  # gravity's net work is zero
    assert loss == pytest.approx(lost / (useful + lost), rel=1e-3)
    assert efficiency == pytest.approx(useful / (useful + lost), rel=1e-3)
    assert 0.05 < efficiency < 0.95
    assert round(100 * efficiency) == 28  # the README's comment beside the command


def test_shown_output_is_what_the_command_prints(scratch, monkeypatch):
    """The README's ```text block is the output of the command named just above it."""
    shown = re.findall(r"`(mechloop [^`]+)` prints:\s*```text\n(.*?)```", README, flags=re.S)
    assert shown
    monkeypatch.chdir(scratch)
    for command, text in shown:
        result = CliRunner().invoke(app, _args(command))
        assert result.exit_code == 0, result.output
        assert result.output.strip() == text.strip()
