"""Benchmark: the roof-support synthesis (examples/roof_support_synthesis.yaml) beside the
seed's brute-force approach (seed 001, sec. 1.2.2).

Three ways to the same question — which lemniscate four-bar keeps the canopy tip E
closest to a vertical line over the leg's stroke, with E rising at least 1.0 m and the leg
force at most 4300 kN:

1. the seed's tabulation: for one design, 90 × 90 = 8100 pairs of lever angles in 1°
   steps, kept where the squared shield length lies within 0.72…0.73 m²; run here in
   NumPy on the example's starting design and on the synthesized one, to show how many
   positions it finds and how far its E is from the exact E;
2. mechloop's synthesis (differential evolution with the example's settings);
3. a brute-force grid over the six dimensions (4 and 5 levels each: 4096 and 15625
   designs) with mechloop's exact batched kinematics and force analysis — the seed's
   "vary r1, r2, L, t, Δ and look" done exhaustively.

    python benchmarks/bench_roof_support.py [--quick]

The last line is ``roof support: band X mm by synthesis, Y mm by a grid of N designs``.
"""

from __future__ import annotations

import argparse
import itertools
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(Path(__file__).parent))

from roof_support_tabulation import RoofSupport, tabulated_positions  # noqa: E402

EXAMPLE = ROOT / "examples/roof_support_synthesis.yaml"
NAMES = ("r1", "r2", "r3", "r5", "r6", "r8", "r9", "r11")


def constants(model) -> dict[str, float]:
    return {name: float(model.vectors[int(name[1:])].r) for name in NAMES}


def seed_tabulation(title: str, model) -> None:
    support = RoofSupport.from_values(constants(model))
    started = time.perf_counter()
    legs, tabulated, exact = tabulated_positions(support, (1.0, 1.6), (0.72, 0.73))
    took = time.perf_counter() - started
    _, _, e = support.exact(np.linspace(1.0, 1.6, 41))
    print(f"  {title}: 8100 pairs in {took * 1e3:.2f} ms, {legs.size} kept in the stroke, "
          f"E off by up to {np.abs(tabulated - exact).max() * 1e3:.1f} mm; band of E "
          f"{np.ptp(tabulated.real) * 1e3:.1f} mm tabulated, {np.ptp(e.real) * 1e3:.1f} mm "
          "exact")


def grid_search(model, levels: int) -> tuple[float, int, float]:
    """Best band (m) over a full grid, its leg force (N) and the designs tried."""
    from mechloop.synthesis.problem import SynthesisProblem

    problem = SynthesisProblem(model)
    variables = problem.variables
    axes = [np.linspace(lo, hi, levels) for lo, hi in zip(variables.low, variables.high,
                                                           strict=True)]
    designs = np.array(list(itertools.product(*axes)))
    ev = problem.evaluate(designs)  # kinematic criteria batched, F_bal per design
    band = ev.measures["range x(head 11)"]
    force = ev.measures["max F_bal"]
    stroke = ev.measures["range y(head 11)"]
    ok = ev.feasible & (stroke >= 1.0) & (force <= 4300e3)
    best = int(np.argmin(np.where(ok, band, np.inf)))
    return float(band[best]) if ok.any() else float("nan"), designs.shape[0], \
        float(force[best])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a short synthesis, 3 levels")
    args = parser.parse_args()
    import mechloop
    from mechloop.synthesis.search import synthesize

    model = mechloop.load_model(EXAMPLE)
    print("1. the seed's tabulation (one design per run)")
    seed_tabulation("starting design", model)

    print("2. mechloop synthesis")
    result = synthesize(model, iterations=30 if args.quick else None)
    terms = result.terms()
    band = terms["range x(head 11)"]
    print(f"  band {band * 1e3:.2f} mm, stroke {terms['range y(head 11)']:.3f} m, leg "
          f"force {terms['max F_bal'] / 1e3:.0f} kN; {result.evaluations} designs in "
          f"{result.elapsed:.1f} s ({result.stopped}; the time depends on the machine)")
    dims = ", ".join(f"{name} = {value:.3f}" for name, value in result.values().items())
    print(f"  Q = {result.q * 1e3:.2f} mm; dimensions (m): {dims}")
    seed_tabulation("synthesized design", result.model)

    print("3. brute-force grid over the six dimensions, exact kinematics")
    for levels in (3,) if args.quick else (4, 5):
        started = time.perf_counter()
        grid_band, count, grid_force = grid_search(model, levels)
        took = time.perf_counter() - started
        print(f"  {levels} levels: band {grid_band * 1e3:.2f} mm (leg force "
              f"{grid_force / 1e3:.0f} kN) from {count} designs in {took:.1f} s")
    print(f"roof support: band {band * 1e3:.2f} mm by synthesis, {grid_band * 1e3:.2f} mm "
          f"by a grid of {count} designs")


if __name__ == "__main__":
    main()
