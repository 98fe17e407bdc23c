"""Benchmark: a coupled block over 1e5 positions beside an elementary chain of the same size.

Three solves of positions, velocities and accelerations over N = 10**5 positions (one crank
turn), in one run:

* the crank-rocker four-bar of ``examples/four_bar.yaml`` (two contours: Pl4, then the
  coupler point's Pl1) in closed form — the elementary chain;
* the same model forced through the coupled solver (Newton's continuation,
  :mod:`mechloop.modules.coupled`, every contour a block of its own) — the same work
  done by Newton's method; its numbers are checked against the closed form (≤ 1e-12);
* a class-III triad (RRR–RRR–RRR: ternary link B1 B2 B3 pinned to the frame at A1, A2 by
  two dyads and to a crank O→A3 by the third; two contours that need each other, one
  coupled block of 4 unknowns), assembled over the whole turn.

Each time is the best of ``--repeats`` runs (time.perf_counter), model set-up included,
after one warm-up solve (numba's compiled kernel is loaded from its cache then).  The last
line printed is ``coupled vs closed form: X`` — the forced four-bar's time over the closed
form's, the cost of Newton's method against the closed forms for the same mechanism.

Usage: ``python benchmarks/bench_coupled.py [--n N] [--repeats R]``
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

import numpy as np

import mechloop
from mechloop.solve import blocks

ROOT = Path(__file__).resolve().parents[1]

# the triad (m, deg): ternary link B1 B2 B3, frame pins A1, A2, crank O→A3 of C
B1, B2, B3 = (-0.039, 1.285), (0.422, 1.478), (-0.288, 1.598)
A1, A2, C = (-0.765, 0.0), (0.896, 0.0), 0.1


def _ang(p) -> float:
    return math.degrees(math.atan2(p[1], p[0]))


def _len(p) -> float:
    return math.hypot(p[0], p[1])


def _sub(p, q):
    return (p[0] - q[0], p[1] - q[1])


def triad(n: int) -> mechloop.Model:
    """The triad as two coupled contours (see tests/test_coupled_blocks.py ``triad``)."""
    A3 = (C, 0.0)
    vectors = {
        1: {"r": _len(_sub(B1, A1)), "a": "function"},
        2: {"r": _len(_sub(B2, B1)),
            "a": {"link": "a7", "delta": _ang(_sub(B2, B1)) - _ang(_sub(B1, B3))}},
        3: {"r": _len(_sub(A2, B2)), "a": "function"},
        4: {"r": _len(_sub(A1, A2)), "a": _ang(_sub(A1, A2))},
        5: {"r": C, "a": {"argument": 1}},
        6: {"r": _len(_sub(B3, A3)), "a": "function"},
        7: {"r": _len(_sub(B1, B3)), "a": "function"},
        8: {"r": {"link": "r1"}, "a": {"link": "a1", "delta": 180}},
        9: {"r": _len(A1), "a": _ang((-A1[0], -A1[1]))},
    }
    contours = [
        {"vectors": [1, 2, 3, 4],
         "guess": {"a1": _ang(_sub(B1, A1)), "a3": _ang(_sub(A2, B2))}},
        {"vectors": [5, 6, 7, 8, 9],
         "guess": {"a6": _ang(_sub(B3, A3)), "a7": _ang(_sub(B1, B3))}},
    ]
    return mechloop.Model.from_dict({
        "positions": n, "time": {"rpm": 60}, "arguments": {1: {"table": {0: 0, n: 360}}},
        "vectors": vectors, "contours": contours})


def four_bar(n: int) -> mechloop.Model:
    data = mechloop.load_model(ROOT / "examples" / "four_bar.yaml").model_dump()
    data["positions"] = n
    data["arguments"] = {1: {"table": {0: 0, n: 360}}}
    return mechloop.Model.model_validate(data)


def best(fn, repeats: int) -> tuple[float, object]:
    out = fn()  # warm-up
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def forced(model: mechloop.Model):
    blocks.FORCE_COUPLED = True
    try:
        return mechloop.solve(model)
    finally:
        blocks.FORCE_COUPLED = False


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, default=10**5, help="positions (default 1e5)")
    parser.add_argument("--repeats", type=int, default=3, help="runs, best kept (default 3)")
    args = parser.parse_args()
    fb, tr = four_bar(args.n), triad(args.n)

    t_closed, closed = best(lambda: mechloop.solve(fb), args.repeats)
    t_newton, newton = best(lambda: forced(fb), args.repeats)
    t_triad, solved = best(lambda: mechloop.solve(tr), args.repeats)
    worst = 0.0
    for table in ("values", "rates", "accels"):
        for name, value in getattr(closed, table).items():
            scale = max(1.0, float(np.nanmax(np.abs(value))))
            worst = max(worst, float(np.nanmax(np.abs(value - getattr(newton, table)[name])))
                        / scale)
    if worst > 1e-12 or closed.broken.any() or newton.broken.any():
        raise SystemExit(f"forced four-bar differs from the closed form: {worst:.3g}")
    if solved.broken.any():
        raise SystemExit("the triad breaks: " + "; ".join(b.describe() for b in solved.breaks))
    n = args.n + 1
    print(f"positions: {n}")
    print(f"four-bar, closed form:        {t_closed * 1e3:8.1f} ms")
    print(f"four-bar, coupled (Newton):   {t_newton * 1e3:8.1f} ms  (largest difference "
          f"{worst:.1e} of the size)")
    print(f"triad (4 unknowns), coupled:  {t_triad * 1e3:8.1f} ms  "
          f"({t_triad / n * 1e9:.0f} ns per position)")
    print(f"triad vs four-bar closed form: {t_triad / t_closed:.1f}")
    print(f"coupled vs closed form: {t_newton / t_closed:.1f}")


if __name__ == "__main__":
    main()
