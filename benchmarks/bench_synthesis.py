"""Benchmark: synthesis quality and speed on path-synthesis problems, and evaluations per
second beside pylinkage's particle swarm on the same problem.

For each problem (bundled examples) mechloop's synthesis runs with the example's own
search settings and a fixed seed; the table gives the best error reached (Q in the
example's objective: the largest distance, or the sum of squared distances), designs
evaluated, evaluations per second and time, beside the error of the best published design
recomputed from its design vector (benchmarks/README.md, "Published benchmark problems":
the papers themselves could not be read, so their printed errors are not quoted).

Then the six-points-on-a-line problem (Cabrera et al. 2002, no timing) is evaluated by
both tools with the same design vector and the same 360 crank positions per design:
pylinkage 1.x with its numba solver (``Linkage.step_fast``) inside
``particle_swarm_optimization``, mechloop with its population evaluation.  The last line
is ``synthesis evals/s vs pylinkage: X`` (mechloop's rate / pylinkage's).

    pip install -e ".[bench]"
    python benchmarks/bench_synthesis.py [--quick]
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = [  # title, example, the best published design's error (or what is known)
    ("known four-bar, 9 points, no timing (max distance, mm)",
     "examples/four_bar_path_synthesis.yaml", "0 (the targets lie on a known curve)"),
    ("six points on a vertical line, no timing (sum of squares, mm^2)",
     "examples/six_points_line_synthesis.yaml",
     "3.1e-11: a source design (label uncertain), recomputed here"),
    ("six points on a vertical line, free timing (sum of squares, mm^2)",
     "examples/six_points_free_timing_synthesis.yaml",
     "below 2e-11: source designs, recomputed here"),
    ("five points with prescribed timing (sum of squares, mm^2)",
     "examples/five_points_timing_synthesis.yaml", "MUMSA 1.284e-06 recomputed"),
    ("log10 function generator (max error, deg)", "examples/log10_function_generator.yaml",
     "none known"),
]
TARGETS = np.array([[20.0, 20.0], [20.0, 25.0], [20.0, 30.0], [20.0, 35.0], [20.0, 40.0],
                    [20.0, 45.0]])
STEPS = 360


def run_problems(quick: bool) -> None:
    import mechloop
    from mechloop.synthesis.search import synthesize

    print(f"{'problem':<66} {'Q':>11} {'designs':>8} {'evals/s':>9} {'s':>6}  published")
    for title, path, published in PROBLEMS:
        model = mechloop.load_model(ROOT / path)
        result = synthesize(model, iterations=40 if quick else None)
        print(f"{title:<66} {result.q:>11.4g} {result.evaluations:>8d} "
              f"{result.evaluations_per_second:>9.0f} {result.elapsed:>6.1f}  {published}")


def mechloop_rate(designs: int, repeats: int = 3) -> float:
    """Evaluations per second of mechloop on the six-point problem (random designs in the
    bounds, one population call)."""
    import mechloop
    from mechloop.synthesis.problem import SynthesisProblem

    model = mechloop.load_model(ROOT / "examples/six_points_line_synthesis.yaml")
    problem = SynthesisProblem(model)
    rng = np.random.default_rng(0)
    x = problem.variables.scale(rng.uniform(size=(designs, len(problem.variables))))
    problem.evaluate(x[:8])
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        problem.evaluate(x)
        best = min(best, time.perf_counter() - start)
    return designs / best


def pylinkage_rate(particles: int, iterations: int) -> float | None:
    """Fitness evaluations per second of pylinkage's PSO on the six-point problem."""
    try:
        import pylinkage as pl
        from pylinkage.actuators import Crank
        from pylinkage.components import Ground
        from pylinkage.dyads import FixedDyad, RRRDyad
        from pylinkage.exceptions import UnbuildableError
        from pylinkage.simulation import Linkage
    except ImportError:
        return None
    o1, o2 = Ground(0.0, 0.0, name="O1"), Ground(30.0, 0.0, name="O2")
    crank = Crank(anchor=o1, radius=10.0, angular_velocity=2 * math.pi / STEPS, name="B")
    rocker = RRRDyad(crank.output, o2, distance1=30.0, distance2=20.0, name="C")
    point = FixedDyad(crank.output, rocker, distance=10.0, angle=0.5, name="P")
    linkage = Linkage([o1, o2, crank, rocker, point], name="fourbar")
    count = [0]

    def fitness(linkage, params, init_pos=None) -> float:
        count[0] += 1
        r1, r2, r3, r4, rcx, rcy, x0, y0, th0 = params
        c, s = math.cos(th0), math.sin(th0)
        far = (x0 + r1 * c, y0 + r1 * s)
        b = (x0 + r2 * c, y0 + r2 * s)
        hint = ((b[0] + far[0]) / 2 - s * r3, (b[1] + far[1]) / 2 + c * r3)
        linkage.set_constraints([r2, r3, r4, math.hypot(rcx, rcy), math.atan2(rcy, rcx)])
        linkage.set_coords([(x0, y0), far, b, hint, hint])
        try:
            path = linkage.step_fast(iterations=STEPS)
        except UnbuildableError:
            return 1e10
        if np.isnan(path).any():
            return 1e10
        d2 = ((path[:, 4, None, :] - TARGETS[None, :, :]) ** 2).sum(axis=2)
        return float(d2.min(axis=0).sum())

    fitness(linkage, [30, 10, 30, 20, 10, 5, 0, 0, 0.0])  # numba warm-up
    count[0] = 0
    start = time.perf_counter()
    pl.particle_swarm_optimization(
        eval_func=fitness, linkage=linkage, dimensions=9, n_particles=particles,
        iterations=iterations, order_relation=min, verbose=False,
        bounds=([5, 5, 5, 5, -60, -60, -60, -60, 0.0],
                [60, 60, 60, 60, 60, 60, 60, 60, 2 * math.pi]))
    return count[0] / (time.perf_counter() - start)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="short runs (for CI smoke)")
    args = parser.parse_args(argv)
    run_problems(args.quick)
    ours = mechloop_rate(500 if args.quick else 4000)
    theirs = pylinkage_rate(60, 20 if args.quick else 100)
    print(f"six points, {STEPS} positions per design: mechloop {ours:.0f} evals/s")
    if theirs is None:
        print("pylinkage is not installed: pip install -e '.[bench]'", file=sys.stderr)
        return 2
    print(f"six points, {STEPS} positions per design: pylinkage PSO {theirs:.0f} evals/s")
    print(f"synthesis evals/s vs pylinkage: {ours / theirs:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
