"""The bundled synthesis examples, each run as ``mechloop synthesize`` runs it.

Each example is loaded and synthesized with its own search settings (method, seed,
population, generations, budget), as the command line does; the table gives the best Q
(the example's objective and unit), whether the best design meets every mandatory
condition (the exact existence check included), the designs evaluated and the time.
With CMA-ES and DE the last digits depend on the machine (floating-point rounding
differs between CPUs and libraries, and the search amplifies it).

    python benchmarks/bench_synthesis_examples.py            # every example below
    python benchmarks/bench_synthesis_examples.py six_points_line_synthesis.yaml
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = [
    "four_bar_path_synthesis.yaml",
    "six_points_line_synthesis.yaml",
    "six_points_free_timing_synthesis.yaml",
    "five_points_timing_synthesis.yaml",
    "eighteen_points_timing_synthesis.yaml",
    "six_points_timing_synthesis.yaml",
    "log10_function_generator.yaml",
    "slider_crank_stroke_synthesis.yaml",
]


def main() -> None:
    import mechloop
    from mechloop.synthesis.search import synthesize

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("examples", nargs="*", default=EXAMPLES,
                        help="example file names (default: all of the list)")
    names = parser.parse_args().examples
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at "
          "the start")
    print("| example | method | Q | unit | feasible | designs | time s |\n"
          "| --- | --- | --- | --- | --- | --- | --- |")
    for name in names:
        model = mechloop.load_model(ROOT / "examples" / name)
        result = synthesize(model)
        print(f"| {name} | {result.method} | {result.q:.6g} | {result.problem.q_shown_unit} "
              f"| {'yes' if result.feasible else 'no'} | {result.evaluations} "
              f"| {result.elapsed:.1f} |", flush=True)
    print(f"load average at the end {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
