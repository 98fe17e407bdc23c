"""A standalone mutation fuzzer for the ``mechloop`` command line.

Runs N inputs (mutations of every bundled example, documents from the model schema, YAML
of any shape, raw text and bytes) through ``mechloop check``, ``solve -o out.csv`` and
``solve -o out.json``, and prints a summary: exit codes, times, and the failures grouped by
where they happen (the innermost mechloop frame), with one reproducer per group written to
``--out``.  Nothing stops at the first failure.

    .venv/bin/python tests/fuzz/run_fuzz.py -n 2000 --seed 1 --out /tmp/fuzz
    .venv/bin/python tests/fuzz/run_fuzz.py -n 200 --subprocess   # real processes

By default each input runs in a child of the harness's warmed-up fork server (fast, ~0.2 s
an input);
``--subprocess`` runs the installed command as the issue's reporter did (~2 s a command).
"""

from __future__ import annotations

import argparse
import collections
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from hypothesis import HealthCheck, Phase, given, seed, settings
from hypothesis import strategies as st

from fuzz import harness
from fuzz.mutations import EXAMPLES, mutated
from fuzz.strategies import raw_files, schema_files, yaml_files

SUBPROCESS_LIMIT = harness.TIME_LIMIT + 15
"""Seconds one command may take as a process of its own (it imports mechloop first)."""

SOURCES = {"mutations": st.sampled_from(EXAMPLES).flatmap(mutated),
           "schema": schema_files(), "yaml": yaml_files(), "raw": raw_files()}


def _signature(outcome: harness.Outcome) -> str:
    """Where a failure happens: each kind of failure and the innermost frame in mechloop's
    sources (for a warning: where it was raised; for bad rows: the columns)."""
    frames = re.findall(r'File "[^"]*?(mechloop/[^"]+)", line \d+, in (\w+)', outcome.detail)
    parts = []
    for kind in (outcome.failure or "").split("; "):
        if kind.startswith("non-finite"):
            columns = sorted({re.sub(r"^row \d+, ", "", line).split(":")[0]
                              for line in outcome.detail.splitlines() if line.startswith("row")})
            parts.append(f"{kind} ({', '.join(columns[:4])})")
        elif kind.startswith("warning"):
            where = re.findall(r"(mechloop/[^:]+:\d+): ", outcome.detail)
            parts.append(kind + (f" at {where[0]}" if where else ""))
        else:
            parts.append(kind + (f" at {frames[-1][0]}:{frames[-1][1]}" if frames else ""))
    return " + ".join(parts)


def _run_subprocess(files: dict[str, bytes]) -> harness.Report:
    """The input through the installed command, one process per command."""
    report = harness.Report(files)
    model = next(name for name in files if name.startswith("model."))
    with tempfile.TemporaryDirectory(prefix="mechloop-fuzz-") as tmp:
        directory = Path(tmp)
        for name, data in files.items():
            (directory / name).write_bytes(data)
        for command in harness.COMMANDS:
            args = [command[0], model, *command[1:]]
            start = time.perf_counter()
            try:
                done = subprocess.run([sys.executable, "-m", "mechloop.cli", *args],
                                      cwd=directory, capture_output=True, text=True,
                                      errors="replace", timeout=SUBPROCESS_LIMIT,
                                      check=False)
            except subprocess.TimeoutExpired:
                report.outcomes.append(harness.Outcome(
                    tuple(args), None, time.perf_counter() - start,
                    failure=f"timeout (over {SUBPROCESS_LIMIT:g} s)"))
                break
            outcome = harness.Outcome(tuple(args), done.returncode,
                                      time.perf_counter() - start, done.stderr[-2000:])
            if "Traceback" in done.stderr:
                outcome.failure, outcome.detail = "traceback", done.stderr[-4000:]
            elif done.returncode not in (0, 2):
                outcome.failure, outcome.detail = (f"exit code {done.returncode}",
                                                   done.stderr[-2000:])
            elif "Warning" in done.stderr:
                outcome.failure, outcome.detail = "warning reached the user", done.stderr
            elif done.returncode == 0 and len(command) > 1:
                bad = harness.check_rows(directory / command[-1])
                if bad:
                    outcome.failure = "non-finite value in a row not marked chain_break"
                    outcome.detail = "\n".join(bad[:10])
            report.outcomes.append(outcome)
    return report


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("-n", type=int, default=300, help="inputs per source (default 300)")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument("--sources", default=",".join(SOURCES),
                        help=f"comma-separated, of {', '.join(SOURCES)} (default all)")
    parser.add_argument("--subprocess", action="store_true",
                        help="run the installed command in a process per command")
    parser.add_argument("--out", type=Path, default=None,
                        help="write one reproducer per failure group into this directory")
    args = parser.parse_args(argv)

    run = _run_subprocess if args.subprocess else harness.run_input
    codes: collections.Counter = collections.Counter()
    times: list[float] = []
    groups: dict[str, list[harness.Report]] = collections.defaultdict(list)
    inputs = 0
    start = time.perf_counter()

    for name in args.sources.split(","):
        @seed(args.seed)
        @settings(max_examples=args.n, deadline=None, database=None,
                  phases=(Phase.generate,), suppress_health_check=list(HealthCheck))
        @given(files=SOURCES[name])
        def drive(files):
            nonlocal inputs
            inputs += 1
            report = run(files)
            for outcome in report.outcomes:
                codes[outcome.exit_code] += 1
                times.append(outcome.seconds)
            for outcome in report.failures:
                groups[_signature(outcome)].append(report)
            if inputs % 100 == 0:
                print(f"{inputs} inputs, {sum(map(len, groups.values()))} failing, "
                      f"{time.perf_counter() - start:.0f} s", file=sys.stderr)

        drive()
        print(f"{name}: done ({inputs} inputs so far, {time.perf_counter() - start:.0f} s)",
              file=sys.stderr)

    times.sort()
    print(f"{inputs} inputs, {len(times)} commands in {time.perf_counter() - start:.0f} s")
    print("exit codes: " + ", ".join(f"{k}: {v}" for k, v in sorted(
        codes.items(), key=lambda kv: (kv[0] is None, kv[0] or 0))))
    if times:
        print(f"command time: median {times[len(times) // 2]:.3f} s, "
              f"max {times[-1]:.2f} s, over 2 s: {sum(t > 2 for t in times)}")
    print(f"{sum(len(v) for v in groups.values())} failing inputs in {len(groups)} groups:")
    for i, (signature, reports) in enumerate(sorted(groups.items(),
                                                    key=lambda kv: -len(kv[1]))):
        print(f"  {len(reports):5d}  {signature}")
        if args.out is not None:
            args.out.mkdir(parents=True, exist_ok=True)
            smallest = min(reports, key=lambda r: sum(len(d) for d in r.files.values()))
            (args.out / f"group{i:03d}.txt").write_text(
                f"{signature}\n\n{smallest.reproducer()}\n", encoding="utf-8",
                errors="backslashreplace")
    return 1 if groups else 0


if __name__ == "__main__":
    sys.exit(main())
