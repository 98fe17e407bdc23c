"""Run one fuzz input through ``mechloop check`` and ``mechloop solve`` and judge it.

Each input runs in a child forked from a fork server that imported mechloop and ran every
example once (imports and first calls done, so no time limit fires on them), with

- a soft limit of CPU time per command (``SIGPROF`` raises :class:`FuzzTimeout` inside
  the run, so the report shows where it hung; CPU time, so that a loaded machine does not
  fail a fast input),
- a hard wall-clock limit (the parent kills the child), for a hang inside C code that the
  signal cannot interrupt or a child that waits,
- a cap on the child's address space, so a memory bomb fails as a ``MemoryError`` instead
  of taking the machine.

The commands are ``check``, ``solve -o out.csv`` and ``solve -o out.json`` (in-process,
through ``typer.testing.CliRunner`` on :data:`mechloop.cli.app`).  An input passes when
every command exits 0 or 2 without an exception, in time, without a Python warning reaching
the user, and every written row not marked ``chain_break`` holds only finite numbers.
"""

from __future__ import annotations

import csv
import json
import math
import multiprocessing.forkserver
import os
import resource
import signal
import sys
import tempfile
import time
import traceback
import warnings
from dataclasses import dataclass, field
from pathlib import Path

TIME_LIMIT = float(os.environ.get("MECHLOOP_FUZZ_TIME", "5"))
"""CPU seconds one command may take (a profiling timer: the time the process computes, so a
loaded machine does not turn a fast command into a timeout; the child is killed when the
commands of one input together took three times their limits and 10 s more of wall-clock
time)."""

MEMORY_LIMIT = int(float(os.environ.get("MECHLOOP_FUZZ_MEMORY_GB", "2")) * 2**30)
"""Bytes of address space a child may add to what the fork server already maps."""

COMMANDS: tuple[tuple[str, ...], ...] = (("check",), ("solve", "-o", "out.csv"),
                                         ("solve", "-o", "out.json"))


HIDDEN_WARNINGS = (DeprecationWarning, PendingDeprecationWarning, ImportWarning,
                   ResourceWarning)
"""Warnings Python's default filters do not show to a command-line user."""


class FuzzTimeout(BaseException):
    """The soft time limit fired (a BaseException, so no ``except Exception`` hides it)."""


@dataclass
class Outcome:
    """What one command did with one input."""

    command: tuple[str, ...]
    exit_code: int | None
    seconds: float
    output: str = ""
    failure: str | None = None  # None when the command behaved; else what went wrong
    detail: str = ""            # the traceback, the bad rows or the warnings


@dataclass
class Report:
    """The outcomes of every command for one input, and the input itself."""

    files: dict[str, bytes]
    outcomes: list[Outcome] = field(default_factory=list)

    @property
    def failures(self) -> list[Outcome]:
        return [o for o in self.outcomes if o.failure is not None]

    def reproducer(self) -> str:
        """The input files and the failing commands, ready to paste into a bug report."""
        parts = []
        for name, data in self.files.items():
            try:
                text = data.decode("utf-8")
                shown = text if len(text) <= 3000 else (
                    text[:1500] + f"\n... ({len(text)} characters in all) ...\n" + text[-1500:])
                parts.append(f"--- {name} ---\n{shown}")
            except UnicodeDecodeError:
                shown = data if len(data) <= 3000 else data[:3000]
                parts.append(f"--- {name} (bytes, not UTF-8) ---\n{shown!r}")
        for o in self.failures:
            parts.append(f"$ mechloop {' '.join(o.command)}"
                         f"\n=> {o.failure} (exit {o.exit_code}, {o.seconds:.2f} s)\n"
                         f"{o.detail[-4000:]}")
        return "\n".join(parts)


def _short_traceback(exc_info) -> str:
    """The traceback from the first frame in mechloop's sources on (the test runner's and
    the CLI framework's frames above it say nothing about the failure)."""
    lines = traceback.format_exception(*exc_info)
    first = next((i for i, line in enumerate(lines)
                  if line.startswith('  File "') and "/mechloop/" in line
                  and "/fuzz/" not in line), 1)
    return "".join(lines[:1] + lines[first:])


def _alarm(signum, frame):
    raise FuzzTimeout(f"over {TIME_LIMIT:g} s")


def _bad_cells(row: dict, where: str) -> list[str]:
    """Cells of a row not marked broken that are not finite numbers."""
    bad = []
    for key, value in row.items():
        if key == "chain_break":
            continue
        if isinstance(value, bool):
            continue
        if isinstance(value, int | float):
            number = float(value)
        else:
            try:
                number = float(value)
            except (TypeError, ValueError):
                bad.append(f"{where}, {key}: {value!r}")
                continue
        if not math.isfinite(number):
            bad.append(f"{where}, {key}: {value!r}")
    return bad


def _is_broken(value) -> bool:
    return value is True or str(value).strip().lower() in ("true", "1")


def check_rows(path: Path) -> list[str]:
    """Every non-finite or non-numeric cell of a written CSV/JSON table in a row whose
    ``chain_break`` is false (or that has no such column)."""
    bad: list[str] = []
    if path.suffix == ".csv":
        with path.open(newline="", encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
    else:
        rows = json.loads(path.read_text(encoding="utf-8"))
        if not isinstance(rows, list):
            return [f"{path.name}: not a list of rows"]
    for i, row in enumerate(rows):
        if not isinstance(row, dict):
            bad.append(f"row {i}: not a mapping")
        elif not _is_broken(row.get("chain_break")):
            bad.extend(_bad_cells(row, f"row {i}"))
        if len(bad) > 10:
            break
    return bad


def _run_commands(directory: Path, model: str) -> list[dict]:
    """In the child: each command in turn, judged; stops after a timeout."""
    from typer.testing import CliRunner

    from mechloop.cli import app

    runner = CliRunner()
    results = []
    signal.signal(signal.SIGPROF, _alarm)
    for command in COMMANDS:
        args = [command[0], str(directory / model), *[
            str(directory / a) if a.startswith("out.") else a for a in command[1:]]]
        out = directory / command[-1] if len(command) > 1 else None
        if out is not None and out.exists():
            out.unlink()
        result = {"command": [command[0], model, *command[1:]], "failure": None,
                  "detail": "", "exit_code": None, "output": ""}
        start = time.perf_counter()
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                signal.setitimer(signal.ITIMER_PROF, TIME_LIMIT)
                try:
                    res = runner.invoke(app, args, catch_exceptions=True)
                finally:
                    signal.setitimer(signal.ITIMER_PROF, 0)
            except FuzzTimeout:
                result.update(failure=f"timeout (over {TIME_LIMIT:g} s)",
                              detail=_short_traceback(sys.exc_info()))
                result["seconds"] = time.perf_counter() - start
                results.append(result)
                break
        result["seconds"] = time.perf_counter() - start
        result["exit_code"] = res.exit_code
        result["output"] = res.output[-2000:]
        failures, details = [], []
        if res.exception is not None and not isinstance(res.exception, SystemExit):
            failures.append(f"traceback: {type(res.exception).__name__}")
            details.append(_short_traceback(res.exc_info))
        elif res.exit_code not in (0, 2):
            failures.append(f"exit code {res.exit_code}")
            details.append(res.output[-2000:])
        shown = [w for w in caught if not issubclass(w.category, HIDDEN_WARNINGS)]
        if shown:
            failures.append(f"warning reached the user: {shown[0].category.__name__}")
            details.append("\n".join(f"{w.filename}:{w.lineno}: {w.message}"
                                     for w in shown[:5]))
        if res.exit_code == 0 and out is not None:
            bad = check_rows(out) if out.exists() else ["exit 0 but no output file"]
            if bad:
                failures.append("non-finite value in a row not marked chain_break")
                details.append("\n".join(bad[:10]))
        if failures:
            result["failure"] = "; ".join(failures)
            result["detail"] = "\n".join(details)
        results.append(result)
    return results


def _child(directory: str, model: str, connection) -> None:
    """The forked child: cap the address space, run the commands, send the outcomes."""
    _, hard = resource.getrlimit(resource.RLIMIT_AS)
    try:
        with open("/proc/self/statm") as statm:
            mapped = int(statm.read().split()[0]) * resource.getpagesize()
        resource.setrlimit(resource.RLIMIT_AS, (mapped + MEMORY_LIMIT, hard))
    except (OSError, ValueError):
        pass
    try:
        payload = _run_commands(Path(directory), model)
    except BaseException:  # the harness itself broke: report it, never hang the parent
        payload = [{"command": ["harness"], "failure": "harness error", "exit_code": None,
                    "detail": traceback.format_exc(), "seconds": 0.0, "output": ""}]
    connection.send_bytes(json.dumps(payload).encode())
    connection.close()


_CONTEXT: list = []


def context():
    """The multiprocessing context every input runs in: children forked from a fork server
    (a fresh, single-threaded process, so no lock another thread of the test process held
    is inherited) that imported mechloop and ran every example once (``fuzz.warm``)."""
    if not _CONTEXT:
        ctx = multiprocessing.get_context("forkserver")
        ctx.set_forkserver_preload(["fuzz.warm"])
        # The server imports its preload before it learns the parent's sys.path: give it
        # the directory of the ``fuzz`` package (a failed preload would be silent, and
        # every child would then import mechloop on its own).
        saved = os.environ.get("PYTHONPATH")
        here = str(Path(__file__).resolve().parents[1])
        os.environ["PYTHONPATH"] = os.pathsep.join([here, *([saved] if saved else [])])
        try:
            multiprocessing.forkserver.ensure_running()
        finally:
            if saved is None:
                del os.environ["PYTHONPATH"]
            else:
                os.environ["PYTHONPATH"] = saved
        _CONTEXT.append(ctx)
    return _CONTEXT[0]


def run_input(files: dict[str, bytes | str]) -> Report:
    """Write ``files`` (name -> content; the one named ``model.*`` is the model, the others
    are its CSV tables) to a fresh directory, run every command on the model in a child of
    the fork server, and return the judged outcomes."""
    model = next(name for name in files if name.startswith("model."))
    encoded = {name: data.encode("utf-8", "surrogateescape") if isinstance(data, str)
               else data for name, data in files.items()}
    report = Report(encoded)
    ctx = context()
    with tempfile.TemporaryDirectory(prefix="mechloop-fuzz-") as tmp:
        directory = Path(tmp)
        for name, data in encoded.items():
            (directory / name).write_bytes(data)
        receive, send = ctx.Pipe(duplex=False)
        child = ctx.Process(target=_child, args=(str(directory), model, send), daemon=True)
        child.start()
        send.close()
        start = time.perf_counter()
        payload = None
        killed = False
        try:
            if receive.poll(3 * len(COMMANDS) * TIME_LIMIT + 10):
                payload = json.loads(receive.recv_bytes())
            else:
                killed = True
        except (EOFError, OSError, ValueError):  # the child died without a report
            payload = None
        finally:
            receive.close()
        if not killed:
            child.join(2)  # it has reported: let it exit
        if child.is_alive():
            child.kill()
        child.join()
        seconds = time.perf_counter() - start
    if killed:
        report.outcomes.append(Outcome(("check/solve", model), None, seconds,
                                       failure="hang: killed by the hard time limit"))
        return report
    if payload is None:
        report.outcomes.append(Outcome(("check/solve", model), None, seconds,
                                       failure=f"child died (exit code {child.exitcode})"))
        return report
    for item in payload:
        report.outcomes.append(Outcome(tuple(item["command"]), item["exit_code"],
                                       item["seconds"], item["output"], item["failure"],
                                       item["detail"]))
    return report


def warm_up(example: Path, commands: tuple[tuple[str, ...], ...] = COMMANDS) -> None:
    """Run every command once on ``example`` in this process (the fork server), so the
    children inherit loaded modules and warmed caches and no limit fires on a first
    call."""
    from typer.testing import CliRunner

    from mechloop.cli import app

    runner = CliRunner()
    with tempfile.TemporaryDirectory() as tmp:
        for command in commands:
            args = [command[0], str(example), *[
                str(Path(tmp) / a) if a.startswith("out.") else a for a in command[1:]]]
            runner.invoke(app, args)


def assert_clean(report: Report) -> None:
    """Fail with the reproducer when any command misbehaved."""
    if report.failures:
        raise AssertionError("fuzz input misbehaved:\n" + report.reproducer())
