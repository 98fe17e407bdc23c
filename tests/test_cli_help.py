"""Start-up and help of the command line: `mechloop --help` loads no heavy library, and every
command's help reads as written at 80 columns (paragraphs re-flowed, not broken mid-sentence,
no `<bool>` beside a flag, every option's default stated)."""

from __future__ import annotations

import importlib
import inspect
import itertools
import re
import subprocess
import sys
from pathlib import Path

import pytest
from typer.main import get_command
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app

WIDTH = 80
HEAVY = ("numpy", "pandas", "scipy", "matplotlib", "dask", "pint")
COMMANDS = sorted(get_command(app).commands)
SCRIPT = Path(sys.executable).with_name("mechloop")  # the installed entry point


def test_importing_the_cli_loads_no_heavy_library():
    code = ("import sys, mechloop.cli; "
            f"print(','.join(m for m in {HEAVY!r} if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True)
    assert done.stdout.strip() == "", f"loaded at import: {done.stdout.strip()}"


def test_public_names_load_on_first_use():
    assert set(mechloop.__all__) == set(mechloop._EXPORTS)
    for name in mechloop.__all__:
        assert getattr(mechloop, name) is not None
    # the subpackage mechloop.solve, once imported, does not hide the function solve
    importlib.import_module("mechloop.solve.results")
    assert callable(mechloop.solve) and mechloop.solve.__module__ == "mechloop.solve.kinematics"
    with pytest.raises(AttributeError):
        mechloop.no_such_name  # noqa: B018


@pytest.mark.parametrize("args", [["--help"], ["solve", "--help"]], ids=" ".join)
def test_help_runs_as_a_program(args):
    done = subprocess.run([str(SCRIPT), *args], capture_output=True,
                          text=True, env={"COLUMNS": str(WIDTH), "PATH": ""}, check=False)
    assert done.returncode == 0, done.stderr
    first = inspect.cleandoc(get_command(app).commands["solve"].help or "").split("\n\n")[0]
    expected = "Usage: mechloop" if args == ["--help"] else " ".join(first.split())
    assert expected in " ".join(done.stdout.split())
    if args == ["--help"]:
        assert all(name in done.stdout for name in COMMANDS)


def _render(args: list[str]) -> list[str]:
    result = CliRunner().invoke(app, args, env={"COLUMNS": str(WIDTH)})
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    assert max(len(line) for line in lines) <= WIDTH
    return lines


def _premature(prev: str, line: str, width: int) -> bool:
    """A break is premature when the next line's first word would have fit on this one."""
    word = line.split()[0]
    return len(prev.rstrip()) + 1 + len(word) <= width


def _check_description(lines: list[str], help_text: str) -> None:
    """The text between the usage line and the first panel: prose re-flowed to the width."""
    end = next((i for i, line in enumerate(lines) if line.startswith("╭")), len(lines))
    block = [line for line in lines[:end] if not line.lstrip().startswith("Usage:")]
    paragraphs = [p for p in inspect.cleandoc(help_text).split("\n\n") if "```" not in p]
    shown = " ".join(" ".join(block).split())
    for paragraph in paragraphs:
        assert " ".join(paragraph.split()) in shown, f"paragraph not shown whole: {paragraph}"
    code = {line.strip() for p in inspect.cleandoc(help_text).split("```")[1::2]
            for line in p.splitlines() if line.strip()}
    usable = WIDTH - 2  # one column of padding on each side
    for prev, line in itertools.pairwise(block):
        if not prev.strip() or not line.strip() or prev.strip() in code or line.strip() in code:
            continue
        assert not _premature(prev.strip(), line.strip(), usable), (
            f"sentence broken early:\n{prev}\n{line}")


def _check_panels(lines: list[str]) -> None:
    """In every panel the description column is re-flowed to its width."""
    inside = False
    rows: list[str] = []
    for line in [*lines, "╭"]:
        if line.startswith(("╭", "╰")):
            if rows:
                _check_panel(rows)
            rows, inside = [], line.startswith("╭")
        elif inside:
            rows.append(line[2:-2])  # strip "│ " and " │"
    assert not rows


def _check_panel(rows: list[str]) -> None:
    # the description column starts where the first row's last field starts: find it from
    # the widest run of spaces before a description on the first row
    first = rows[0]
    starts = [m.end() for m in re.finditer(r"\S\s{2,}(?=\S)", first)]
    column = starts[-1]
    width = len(first)
    prev = ""
    for row in rows:
        head, text = row[:column], row[column:].rstrip()
        if head.strip() or not prev or text.startswith("["):
            prev = text if not text.startswith("[") else ""
            continue
        assert not _premature(prev, text.strip(), width - column), (
            f"help broken early:\n{prev}\n{text}")
        prev = text


@pytest.mark.parametrize("command", ["", *COMMANDS])
def test_help_reads_well_at_80_columns(command):
    args = [command, "--help"] if command else ["--help"]
    lines = _render(args)
    text = "\n".join(lines)
    assert "<bool>" not in text
    group = get_command(app)
    cmd = group.commands[command] if command else group
    _check_description(lines, cmd.help or "")
    _check_panels(lines)
    if command:
        for param in cmd.params:
            if param.name == "help" or getattr(param, "required", False):
                continue
            # a default of None is stated in the help; any other default typer shows
            assert param.default is not None or "default" in (param.help or ""), param.name
