"""The multi-start's Nelder–Mead local searches, one at a time (SciPy's ``minimize``, one
design per evaluation, as the multi-start ran them before) and side by side
(:func:`mechloop.synthesis.simplex.nelder_mead`: every stage of all the starts one
vectorized evaluation, as the multi-start runs them now).

The task is ``examples/four_bar_path_synthesis.yaml`` (nine targets, no timing, nine
variables, the objective the multi-start minimizes there); the starts are the first
``--starts`` starting designs from the coupler-curve atlas, each search with the budget
``--evaluations`` and the tolerances of the multi-start.  Both ways must end every search
at the same design and value (relative 1e-9; they follow the same steps, so in practice
bit for bit) with the same number of evaluations, else status 1.  Each way is timed with
``time.perf_counter``, best of ``--repeats``, after a warm-up evaluation.  The last line
is ``multistart local searches side by side: X`` (one-at-a-time time over side-by-side
time).  Timings depend on the machine and its load.

    python benchmarks/bench_multistart.py        # options: --starts 20 --evaluations 450
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
from scipy.optimize import minimize

import mechloop
from mechloop.synthesis.atlas import atlas_starts
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.search import _local_runs

MODEL = Path(__file__).resolve().parents[1] / "examples/four_bar_path_synthesis.yaml"


def one_at_a_time(problem: SynthesisProblem, starts: np.ndarray, evaluations: int
                  ) -> list[tuple[np.ndarray, float, int]]:
    """SciPy's Nelder–Mead from each start in turn, one design per evaluation."""
    variables = problem.variables
    lower, upper = variables.unit_bounds()
    out = []
    for start in starts:
        found = minimize(
            lambda u: float(problem.evaluate(
                variables.scale(variables.clip_unit(u))[None, :]).total[0]),
            start, method="Nelder-Mead", bounds=list(zip(lower, upper, strict=True)),
            options={"maxfev": evaluations, "xatol": 1e-10, "fatol": 1e-14,
                     "adaptive": len(variables) > 4})
        out.append((variables.scale(variables.clip_unit(found.x)), float(found.fun),
                    int(found.nfev)))
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--starts", type=int, default=20)
    parser.add_argument("--evaluations", type=int, default=450)
    parser.add_argument("--repeats", type=int, default=2)
    args = parser.parse_args()
    problem = SynthesisProblem(mechloop.load_model(MODEL))
    found, why = atlas_starts(problem)
    if found is None:
        print(f"no atlas starts: {why}")
        return 1
    starts = np.clip(problem.variables.unscale(found[: args.starts]), 0.0, 1.0)
    problem.evaluate(problem.variables.scale(starts))  # warm-up
    times = {"one at a time": [], "side by side": []}
    for _ in range(args.repeats):
        clock = time.perf_counter()
        single = one_at_a_time(problem, starts, args.evaluations)
        times["one at a time"].append(time.perf_counter() - clock)
        clock = time.perf_counter()
        batch = _local_runs(problem, starts, args.evaluations)
        times["side by side"].append(time.perf_counter() - clock)
    span = problem.variables.high - problem.variables.low
    bad = 0
    for (x1, f1, n1), (x2, f2, n2) in zip(single, batch, strict=True):
        same = (np.max(np.abs(x1 - x2) / span) <= 1e-9 and n1 == n2
                and abs(f1 - f2) <= 1e-9 * max(abs(f1), 1e-300))
        bad += not same
    total = sum(n for _, _, n in batch)
    for name, values in times.items():
        print(f"{name}: best of {args.repeats} {min(values):.2f} s "
              f"({total / min(values):.0f} evaluations/s)")
    print(f"{len(starts)} searches, {total} evaluations, {bad} ending differently")
    if bad:
        return 1
    ratio = min(times["one at a time"]) / min(times["side by side"])
    print(f"multistart local searches side by side: {ratio:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
