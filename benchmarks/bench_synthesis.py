"""Benchmark: design evaluations per second of mechloop's synthesis beside pylinkage's
fitness evaluation, on one published timed closed-path problem, same designs, same
objective, one run.

The problem is the eighteen points of a closed path with prescribed timing (Kunjur &
Krishnamurty 1997, reused by Cabrera et al. 2002 and Acharyya & Mandal 2009): the
coupler point of a four-bar must pass 18 targets at crank angles theta2_1 + 20° (i - 1);
ten variables (four link lengths, the coupler point rcx, rcy, the crank pivot x0, y0,
the frame angle theta0 and the start angle theta2_1); Q is the sum of the squared
distances.  Targets, bounds and objective are those of the MATLAB code of Nguyen-Van et
al., Symmetry 14 (2022) 381 (github.com/sy-nguyen-van/DE_Jaya_Synthesis_Four_Bar_
Mechanisms, Case3/Objf3.m and Additional-functions/Mechanisms.m, case 'Case3'); the
model file is examples/eighteen_points_timing_synthesis.yaml.

The same random designs (uniform in the published bounds, fixed seed) are evaluated

* by pylinkage (1.3, ``pylinkage[numba]``) as its path synthesis evaluates a candidate
  (``pylinkage.synthesis.path_generation._coupler_trajectory``): set the design's
  constraints and starting coordinates, ``Linkage.step_fast`` over a full turn at 1° with
  its numba solver, a NaN anywhere makes the design invalid; the objective is read at
  the 18 target rows.  pylinkage's batch simulator (``population.simulate_batch``, the
  same numba kernel called per design over one topology) is timed too, and the faster of
  the two is pylinkage's rate;
* by mechloop's ``SynthesisProblem.evaluate`` on the whole population in one call: in
  one thread (``threads=1``), in one thread per usable core (the population in shares,
  :mod:`mechloop.synthesis.cores`), and as a user calls it (``threads`` left to the
  default, which chooses by the population's size and the idle cores).  The default's
  rate is mechloop's.

Both must give the same objective (relative 1e-9) on the designs both find valid, and
every difference must be explained: pylinkage follows the nearest intersection from
step to step, so near a toggle it may jump to the other assembly branch (such designs
are counted and left out of the comparison), and it samples the turn at 1°, so a design
that breaks between two samples is valid for it only (mechloop decides the full turn
exactly: the share of the turn where it breaks is printed).  Each tool is timed with
``time.perf_counter``, best of ``--repeats`` rounds that interleave the tools, after a
warm-up call (numba's JIT, caches).
The last line is ``synthesis speedup vs pylinkage: X`` (mechloop's designs/s over
pylinkage's).  Timings depend on the machine and its load.

    pip install -e ".[bench]"
    python benchmarks/bench_synthesis.py [--designs 2000] [--repeats 10]
    python benchmarks/bench_synthesis.py --sizes 1000,2000,4000,8000,20000

``--sizes`` times mechloop alone, one thread beside one per usable core, on populations
of those sizes (where splitting a population over threads starts to pay:
``mechloop.synthesis.cores.PARALLEL_DESIGNS``).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
PROBLEM = ROOT / "examples/eighteen_points_timing_synthesis.yaml"
#: Case3/Objf3.m: CD, the 18 targets (mm), reached at theta2_1 + (i - 1) pi / 9.
TARGETS = np.array([[0.5, 1.1], [0.4, 1.1], [0.3, 1.1], [0.2, 1.0], [0.1, 0.9],
                    [0.05, 0.75], [0.02, 0.6], [0.0, 0.5], [0.0, 0.4], [0.03, 0.3],
                    [0.1, 0.25], [0.15, 0.2], [0.2, 0.3], [0.3, 0.4], [0.4, 0.5],
                    [0.5, 0.7], [0.6, 0.9], [0.6, 1.0]])
#: Mechanisms.m, case 'Case3': [r1..r4] in [0, 50], [rcx, rcy, x0, y0] in [-50, 50],
#: [theta0, theta2_1] in [0, 2 pi].
LOW = np.array([0, 0, 0, 0, -50, -50, -50, -50, 0, 0], dtype=float)
HIGH = np.array([50, 50, 50, 50, 50, 50, 50, 50, 2 * np.pi, 2 * np.pi])
STEPS = 360  # a full turn at 1°
EVERY = 20   # a target every 20 steps (pi / 9)
ROWS = np.arange(len(TARGETS)) * EVERY


def published_designs(count: int, seed: int) -> np.ndarray:
    """``count`` random design vectors of the source, ``(count, 10)``:
    [r1 frame, r2 crank, r3 coupler, r4 rocker, rcx, rcy, x0, y0, theta0, theta2_1]."""
    rng = np.random.default_rng(seed)
    return LOW + rng.uniform(size=(count, LOW.size)) * (HIGH - LOW)


def mechloop_designs(problem, designs: np.ndarray) -> np.ndarray:
    """The source's design vectors as rows of mechloop's design matrix (SI): the crank is
    r1, coupler r2, rocker r3, frame r4, the coupler point r6, r7, the pivot start1; the
    frame C -> O points at theta0 + pi and argument 1's offset is theta0 + theta2_1."""
    r1, r2, r3, r4, rcx, rcy, x0, y0, th0, th2 = designs.T
    values = {"r1": r2 * 1e-3, "r2": r3 * 1e-3, "r3": r4 * 1e-3, "r4": r1 * 1e-3,
              "r6": rcx * 1e-3, "r7": rcy * 1e-3, "start1.x": x0 * 1e-3,
              "start1.y": y0 * 1e-3, "a4": np.mod(th0 + np.pi, 2 * np.pi),
              "a1": np.mod(th0 + th2, 2 * np.pi)}
    return np.column_stack([values[name] for name in problem.variables.names])


def mechloop_evaluate(problem, designs: np.ndarray, threads: int | None = None
                      ) -> tuple[np.ndarray, np.ndarray]:
    """Q (mm²) and feasibility of every design, one population call (``threads``: None
    for mechloop's default, else that many threads)."""
    evaluation = problem.evaluate(designs, threads=threads)
    return evaluation.q, evaluation.feasible


def all_cores() -> int:
    """The cores this process may run on."""
    from mechloop.output.parallel import usable_cores

    return usable_cores()


def time_sizes(problem, sizes: list[int], seed: int, repeats: int) -> None:
    """mechloop's designs/s on one thread and on one thread per usable core, per
    population size (the designs of each size checked equal to 1e-12 both ways)."""
    cores = all_cores()
    print(f"mechloop SynthesisProblem.evaluate, 1 thread / {cores} threads "
          f"(best of {repeats}):")
    for size in sizes:
        designs = mechloop_designs(problem, published_designs(size, seed))
        one, many = (problem.evaluate(designs, threads=t) for t in (1, cores))
        if not np.allclose(one.total, many.total, rtol=1e-12, atol=0):
            print(f"{size} designs: the threads' evaluation differs", file=sys.stderr)
            sys.exit(1)
        best = best_times({t: (lambda d, t=t: mechloop_evaluate(problem, d, t), designs)
                           for t in (1, cores)}, repeats)
        print(f"{size:>8,} designs: {size / best[1]:>9,.0f} and {size / best[cores]:>9,.0f}"
              f" designs/s ({best[1] / best[cores]:.2f}x)")


class Pylinkage:
    """The four-bar of the problem in pylinkage: grounds O (crank pivot) and C (frame
    pivot), the crank A, the RRR dyad B (coupler AB, rocker CB) and the fixed dyad P
    (coupler point at rcx along AB, rcy normal to it)."""

    def __init__(self) -> None:
        from pylinkage.actuators import Crank
        from pylinkage.components import Ground
        from pylinkage.dyads import FixedDyad, RRRDyad
        from pylinkage.simulation import Linkage

        o, c = Ground(0.0, 0.0, name="O"), Ground(3.0, 0.0, name="C")
        crank = Crank(anchor=o, radius=1.0, angular_velocity=2 * math.pi / STEPS, name="A")
        rocker = RRRDyad(crank.output, c, distance1=3.0, distance2=2.0, name="B")
        point = FixedDyad(crank.output, rocker, distance=1.0, angle=0.5, name="P")
        self.linkage = Linkage([o, c, crank, rocker, point], name="eighteen points")
        self.linkage.compile()

    @staticmethod
    def start(designs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Per design the constraints (crank radius, coupler, rocker, |CP| and its angle
        from AB) and the starting coordinates of O, C, A, B, P, ``(D, 5, 2)``: the crank
        one step before theta0 + theta2_1 (pylinkage turns the crank before it records a
        row, so row i is at theta2_1 + i°), B on the assembly of the source's half-angle
        formula (its minus sign) where it exists, else anywhere (the design breaks)."""
        r1, r2, r3, r4, rcx, rcy, x0, y0, th0, th2 = designs.T
        o = x0 + 1j * y0
        c = o + r1 * np.exp(1j * th0)
        a = o + r2 * np.exp(1j * (th0 + th2 - 2 * np.pi / STEPS))
        # B: at r3 from A and r4 from C; with the frame along x the minus branch of
        # Freudenstein's half-angle formula puts B to the left of A -> C (seen from A)
        ac = c - a
        d = np.abs(ac)
        with np.errstate(invalid="ignore", divide="ignore"):
            along = (d * d + r3 * r3 - r4 * r4) / (2 * d)
            across = np.sqrt(np.maximum(r3 * r3 - along * along, 0.0))
            b = a + ac / d * (along + 1j * across)
        b = np.where(np.isfinite(b), b, a + r3)
        p = a + (rcx + 1j * rcy) * (b - a) / np.where(np.abs(b - a) > 0, np.abs(b - a), 1)
        coords = np.stack([o, c, a, b, p], axis=1)
        constraints = np.column_stack([r2, r3, r4, np.hypot(rcx, rcy),
                                       np.arctan2(rcy, rcx)])
        return constraints, np.stack([coords.real, coords.imag], axis=-1)

    def evaluate(self, designs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Q and validity per design, each design set up and run by ``step_fast`` as
        pylinkage's path synthesis does (``_coupler_trajectory``)."""
        constraints, coords = self.start(designs)
        linkage = self.linkage
        q = np.full(designs.shape[0], np.nan)
        for i in range(designs.shape[0]):
            linkage.set_constraints(list(constraints[i]))
            linkage.set_coords([tuple(xy) for xy in coords[i]])
            try:
                path = linkage.step_fast(iterations=STEPS)
            except Exception:  # pylinkage's own rule: any error is a failed candidate
                continue
            if not np.isfinite(path).all():
                continue
            traced = path[ROWS, -1, :]
            q[i] = float(((traced - TARGETS) ** 2).sum())
        return q, np.isfinite(q)

    def changes_branch(self, design: np.ndarray) -> bool:
        """Whether pylinkage's trajectory of one design moves B to the other side of the
        line A -> C (the other assembly branch) somewhere in the turn."""
        constraints, coords = self.start(design[None, :])
        self.linkage.set_constraints(list(constraints[0]))
        self.linkage.set_coords([tuple(xy) for xy in coords[0]])
        path = self.linkage.step_fast(iterations=STEPS)
        a, c, b = (path[:, k, 0] + 1j * path[:, k, 1] for k in (2, 1, 3))
        side = np.sign(np.imag((b - a) * np.conj(c - a)))
        side = side[np.isfinite(side) & (side != 0)]
        return bool((side != side[0]).any()) if side.size else False

    def evaluate_batch(self, designs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The same by ``pylinkage.population.simulate_batch`` (one call, the numba kernel
        per design over the shared topology)."""
        from pylinkage.population._batch_sim import simulate_batch

        constraints, coords = self.start(designs)
        paths = simulate_batch(self.linkage._solver_data, constraints, coords, STEPS)
        finite = np.isfinite(paths).all(axis=(1, 2, 3))
        traced = paths[:, ROWS, -1, :]
        q = ((traced - TARGETS[None]) ** 2).sum(axis=(1, 2))
        return np.where(finite, q, np.nan), finite


def best_times(functions: dict, repeats: int) -> dict[str, float]:
    """Best wall time of each function (name -> (function, its designs)) over ``repeats``
    rounds, after a warm-up call each (numba's JIT, caches).  The rounds interleave the
    tools, so a change in the machine's load falls on all of them alike."""
    for function, designs in functions.values():
        function(designs[:4])
    best = dict.fromkeys(functions, math.inf)
    for _ in range(repeats):
        for name, (function, designs) in functions.items():
            start = time.perf_counter()
            function(designs)
            best[name] = min(best[name], time.perf_counter() - start)
    return best


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--designs", type=int, default=2000, help="designs (default 2000)")
    parser.add_argument("--repeats", type=int, default=10, help="timings, best kept "
                        "(default 10)")
    parser.add_argument("--seed", type=int, default=0, help="random designs' seed "
                        "(default 0)")
    parser.add_argument("--sizes", help="comma-separated population sizes: time "
                        "mechloop alone, one thread beside every core")
    args = parser.parse_args(argv)
    if args.sizes:
        import mechloop
        from mechloop.synthesis.problem import SynthesisProblem

        time_sizes(SynthesisProblem(mechloop.load_model(PROBLEM)),
                   [int(s) for s in args.sizes.split(",")], args.seed, args.repeats)
        return 0
    try:
        tool = Pylinkage()
    except ImportError:
        print("pylinkage is not installed: pip install -e '.[bench]'", file=sys.stderr)
        return 2
    import mechloop
    from mechloop.synthesis.problem import SynthesisProblem

    problem = SynthesisProblem(mechloop.load_model(PROBLEM))
    source = published_designs(args.designs, args.seed)
    ours = mechloop_designs(problem, source)

    q_ours, ok_ours = mechloop_evaluate(problem, ours)
    cores = all_cores()
    for threads in (1, cores):
        q_t, ok_t = mechloop_evaluate(problem, ours, threads)
        if not (np.array_equal(ok_t, ok_ours) and np.allclose(
                q_t[ok_t], q_ours[ok_t], rtol=1e-12, atol=0)):
            print(f"mechloop on {threads} threads differs from its default",
                  file=sys.stderr)
            return 1
    q_step, ok_step = tool.evaluate(source)
    q_batch, ok_batch = tool.evaluate_batch(source)
    if not (np.array_equal(ok_step, ok_batch)
            and np.allclose(q_step[ok_step], q_batch[ok_step], rtol=1e-12, atol=0)):
        print("pylinkage's step_fast and simulate_batch disagree", file=sys.stderr)
        return 1
    both = ok_ours & ok_step
    error = np.zeros(args.designs)
    error[both] = np.abs(q_ours[both] - q_step[both]) / np.maximum(np.abs(q_step[both]),
                                                                    1e-300)
    # pylinkage follows the nearest intersection from step to step: near a toggle it may
    # jump to the other assembly branch, which mechloop (a fixed variant) never does
    jumped = np.zeros(args.designs, dtype=bool)
    for i in np.flatnonzero((error > 1e-9) | (ok_ours & ~ok_step)):
        jumped[i] = tool.changes_branch(source[i])
    # a design only pylinkage finds valid breaks between two of its samples (mechloop
    # decides the whole turn exactly): the share of the turn where it breaks
    pyl_only = np.flatnonzero(ok_step & ~ok_ours)
    exact = problem.exact_feasibility(ours[pyl_only]) if pyl_only.size else None
    agree = both & ~jumped
    worst = float(error[agree].max()) if agree.any() else math.nan
    print(f"{args.designs} designs of {PROBLEM.name} (seed {args.seed}): valid for both "
          f"{both.sum()}, for mechloop only {(ok_ours & ~ok_step).sum()}, for pylinkage "
          f"only {pyl_only.size}")
    print(f"pylinkage changes assembly branch within the turn: {(both & jumped).sum()} of "
          "the designs valid for both (excluded from the comparison), "
          f"{(ok_ours & ~ok_step & jumped).sum()} of those valid for mechloop only")
    if exact is not None:
        print(f"valid for pylinkage only: a break between two 1° samples in "
              f"{(~exact[0]).sum()} of {pyl_only.size} (share of the turn "
              f"{exact[1].min():.1e}..{exact[1].max():.1e})")
    print(f"objective on the designs valid for both: largest relative difference "
          f"{worst:.1e}")
    unexplained = (ok_ours & ~ok_step & ~jumped).sum() + (
        0 if exact is None else exact[0].sum())
    if not agree.any() or worst > 1e-9 or unexplained:
        print("the two tools disagree", file=sys.stderr)
        return 1

    best = best_times({"mechloop": (lambda d: mechloop_evaluate(problem, d), ours),
                       "one": (lambda d: mechloop_evaluate(problem, d, 1), ours),
                       "all": (lambda d: mechloop_evaluate(problem, d, cores), ours),
                       "step_fast": (tool.evaluate, source),
                       "simulate_batch": (tool.evaluate_batch, source)}, args.repeats)
    t_ours, t_step, t_batch = best["mechloop"], best["step_fast"], best["simulate_batch"]
    rate_ours = args.designs / t_ours
    rate_theirs = args.designs / min(t_step, t_batch)
    print(f"pylinkage step_fast, {STEPS} positions per design: "
          f"{args.designs / t_step:,.0f} designs/s")
    print(f"pylinkage simulate_batch, {STEPS} positions per design: "
          f"{args.designs / t_batch:,.0f} designs/s")
    print(f"mechloop SynthesisProblem.evaluate, 1 thread: "
          f"{args.designs / best['one']:,.0f} designs/s")
    print(f"mechloop SynthesisProblem.evaluate, {cores} threads (one per usable core): "
          f"{args.designs / best['all']:,.0f} designs/s")
    from mechloop.synthesis.cores import columns_of, evaluation_threads

    threads = evaluation_threads(args.designs, columns_of(problem))
    print(f"mechloop SynthesisProblem.evaluate, default (threads chosen per call: {threads}"
          f" now): {rate_ours:,.0f} designs/s")
    print(f"synthesis speedup vs pylinkage: {rate_ours / rate_theirs:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
