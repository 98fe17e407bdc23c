"""Benchmark: one crank-rocker four-bar solved by pylinkage and by mechloop.

Both tools compute positions, velocities and accelerations of the linkage for
N = 10**6 crank angles θ = 0..2π (endpoints included) at a constant crank speed
of ω = 2π rad/s (60 rpm), so that t = θ/ω.

Mechanism (SI units), a Grashof crank-rocker, assembled with B above the x axis:

    O = (0, 0)  crank OA = 0.1   coupler AB = 0.35   rocker CB = 0.25
    C = (0.3, 0)                 ground  OC = 0.3 along +x

* pylinkage: ``Linkage.step_fast_with_kinematics`` (numba kernel
  ``simulate_with_kinematics``) steps the crank by a fixed angle h = 2π/(N-1)
  per iteration and records *after* each step, so the crank starts at -h to put
  sample k at θ = k·h. The JIT is warmed up before timing.
* mechloop: ``Model.from_dict`` + ``solve`` of the vector loop
  r1 e(a1) + r2 e(a2) + r3 e(a3) + r4 e(a4) = 0, variant 1 (B above the axis).

Each timing is the best of several runs (time.perf_counter), set-up included.
Both results are checked against each other through joint B (position,
velocity, acceleration); a disagreement makes the script exit with status 1.
The last line printed is ``speedup vs pylinkage: X`` (pylinkage time / mechloop
time).

Usage: ``python benchmarks/bench_fourbar.py [--n N] [--repeats R]``
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from importlib import metadata
from typing import Any, TypeVar

import numpy as np
from numpy.typing import NDArray

# Link lengths (m) and crank speed.
R_CRANK = 0.1  # OA
R_COUPLER = 0.35  # AB
R_ROCKER = 0.25  # CB
R_GROUND = 0.3  # OC, along +x
RPM = 60.0
OMEGA = 2.0 * math.pi * RPM / 60.0  # rad/s

POS_TOL = 1e-6  # m, absolute
RATE_TOL = 1e-6  # relative to the largest magnitude over the cycle

EXIT_MISMATCH = 1
EXIT_UNAVAILABLE = 2

T = TypeVar("T")
Array = NDArray[np.float64]


@dataclass(frozen=True)
class JointKinematics:
    """Position, velocity and acceleration of one joint, each of shape (N, 2)."""

    pos: Array
    vel: Array
    acc: Array


def best_of(fn: Callable[[], T], repeats: int) -> tuple[float, T]:
    """Run ``fn`` ``repeats`` times; return the best wall time and the last result."""
    best = math.inf
    result: T | None = None
    for _ in range(repeats):
        result = None  # release the previous run's arrays before the next one
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    assert result is not None
    return best, result


def version_of(dist: str) -> str:
    """Installed version of a distribution, or '?' if unknown."""
    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return "?"


# --------------------------------------------------------------------------- pylinkage


def pylinkage_solve(n: int) -> Any:
    """Build the four-bar in pylinkage and run ``step_fast_with_kinematics`` for n steps.

    Returns the ``(positions, velocities, accelerations)`` arrays, each of shape
    (n, 4, 2) with joints ordered O, C, A, B. A fresh linkage is built on each
    call because stepping mutates the linkage (it ends at the last pose).
    """
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage

    step = 2.0 * math.pi / (n - 1)  # rad per iteration: n samples cover 0..2π
    o = Ground(0.0, 0.0, name="O")
    c = Ground(R_GROUND, 0.0, name="C")
    # The kernel rotates the crank before recording, so start one step early.
    crank = Crank(anchor=o, radius=R_CRANK, angular_velocity=step, initial_angle=-step, name="A")
    # Initial guess is above O-C, so the solver picks (and keeps) B above the x axis.
    b = RRRDyad(crank.output, c, distance1=R_COUPLER, distance2=R_ROCKER, name="B")
    linkage = Linkage([o, c, crank, b], name="crank-rocker")
    linkage.set_input_velocity(crank, omega=OMEGA, alpha=0.0)  # physical rad/s, rad/s^2
    return linkage.step_fast_with_kinematics(iterations=n, dt=1.0)


def run_pylinkage(n: int, repeats: int) -> tuple[float, JointKinematics, float]:
    """Time pylinkage; return (seconds, kinematics of B, max crank-angle deviation)."""
    if importlib.util.find_spec("numba") is None:
        print("warning: numba not importable, pylinkage runs in pure Python", file=sys.stderr)
    pylinkage_solve(16)  # JIT warm-up (or numba cache load), not timed
    seconds, (pos, vel, acc) = best_of(lambda: pylinkage_solve(n), repeats)
    if pos.shape != (n, 4, 2):
        raise RuntimeError(f"unexpected pylinkage trajectory shape {pos.shape}")
    # Alignment check: sample k must sit at θ = k·2π/(n-1); the crank angle is
    # re-derived by atan2 at every step, so it drifts by rounding only.
    crank_angle = np.unwrap(np.arctan2(pos[:, 2, 1], pos[:, 2, 0]))
    drift = float(np.max(np.abs(crank_angle - np.linspace(0.0, 2.0 * math.pi, n))))
    b_idx = 3
    kin = JointKinematics(pos[:, b_idx].copy(), vel[:, b_idx].copy(), acc[:, b_idx].copy())
    return seconds, kin, drift


# --------------------------------------------------------------------------- mechloop


def mechloop_solve(n: int) -> Any:
    """Build the four-bar as a mechloop model and solve it over n positions."""
    import mechloop

    model = mechloop.Model.from_dict(
        {
            "units": {"length": "m", "angle": "rad"},
            "positions": n - 1,  # positions 0..n-1 => n rows
            "time": {"rpm": RPM},  # one full turn over the positions
            "arguments": {
                1: {"law": "constant_speed", "start": [0, 0.0], "end": [n - 1, 2.0 * math.pi]}
            },
            "vectors": {
                1: {"r": R_CRANK, "a": {"argument": 1}},  # crank O->A
                2: {"r": R_COUPLER, "a": "function"},  # coupler A->B
                3: {"r": R_ROCKER, "a": "function"},  # rocker B->C
                4: {"r": R_GROUND, "a": math.pi},  # ground C->O
            },
            "contours": [{"vectors": [1, 2, 3, 4], "variant": 1}],
        }
    )
    return mechloop.solve(model)


def mechloop_joint_b(res: Any, n: int) -> JointKinematics:
    """Kinematics of B = r1 e(a1) + r2 e(a2) and its time derivatives.

    The crank input is the one the model prescribes: a1 = θ, ω constant, α = 0.
    """
    a1 = np.linspace(0.0, 2.0 * math.pi, n)
    a2 = np.asarray(res.value("a2"), dtype=np.float64)
    w2 = np.asarray(res.rate("a2"), dtype=np.float64)
    alpha2 = np.asarray(res.accel("a2"), dtype=np.float64)
    for name, arr in (("value", a2), ("rate", w2), ("accel", alpha2)):
        if arr.shape != (n,):
            raise RuntimeError(f"mechloop {name}('a2') has shape {arr.shape}, expected ({n},)")
    e1 = np.column_stack((np.cos(a1), np.sin(a1)))
    n1 = np.column_stack((-e1[:, 1], e1[:, 0]))
    e2 = np.column_stack((np.cos(a2), np.sin(a2)))
    n2 = np.column_stack((-e2[:, 1], e2[:, 0]))
    pos = R_CRANK * e1 + R_COUPLER * e2
    vel = R_CRANK * OMEGA * n1 + R_COUPLER * w2[:, None] * n2
    acc = (
        -R_CRANK * OMEGA**2 * e1
        + R_COUPLER * alpha2[:, None] * n2
        - R_COUPLER * (w2**2)[:, None] * e2
    )
    return JointKinematics(pos, vel, acc)


def run_mechloop(n: int, repeats: int) -> tuple[float, JointKinematics]:
    """Time mechloop (model construction + solve); return (seconds, kinematics of B)."""
    mechloop_solve(16)  # warm-up (imports, caches), not timed
    seconds, res = best_of(lambda: mechloop_solve(n), repeats)
    return seconds, mechloop_joint_b(res, n)


def mechloop_missing() -> str | None:
    """Why mechloop cannot be benchmarked, or None if its API is there."""
    try:
        import mechloop
    except ImportError as exc:
        return f"mechloop is not importable ({exc}); install it with pip install -e ."
    missing = [name for name in ("Model", "solve") if not hasattr(mechloop, name)]
    if missing:
        return f"mechloop does not export {', '.join(missing)} yet"
    return None


# --------------------------------------------------------------------------- main


def compare(ref: JointKinematics, other: JointKinematics) -> tuple[float, float, float]:
    """Max position error (m) and max velocity/acceleration errors relative to the peak."""
    dpos = float(np.max(np.hypot(*(ref.pos - other.pos).T)))
    dvel = float(np.max(np.hypot(*(ref.vel - other.vel).T)) / np.max(np.hypot(*ref.vel.T)))
    dacc = float(np.max(np.hypot(*(ref.acc - other.acc).T)) / np.max(np.hypot(*ref.acc.T)))
    return dpos, dvel, dacc


def print_table(rows: list[tuple[str, float]], n: int) -> None:
    """Print tool, seconds and positions per second."""
    print(f"{'tool':<10} {'seconds':>10} {'positions/s':>14}")
    for tool, seconds in rows:
        print(f"{tool:<10} {seconds:>10.4f} {n / seconds:>14.4g}")


def main(argv: list[str] | None = None) -> int:
    """Run the benchmark; return the process exit status."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10**6, help="number of crank positions")
    parser.add_argument("--repeats", type=int, default=3, help="timed runs per tool (best kept)")
    args = parser.parse_args(argv)
    n: int = args.n
    if n < 3 or args.repeats < 1:
        parser.error("need --n >= 3 and --repeats >= 1")

    print(f"crank-rocker four-bar, {n} positions over 0..2π at {RPM:g} rpm, best of {args.repeats}")
    print(
        f"pylinkage {version_of('pylinkage')}, numba {version_of('numba')}, "
        f"mechloop {version_of('mechloop')}"
    )
    try:
        t_pyl, kin_pyl, drift = run_pylinkage(n, args.repeats)
    except ImportError as exc:
        print(f"pylinkage is not available ({exc}); pip install -e '.[bench]'", file=sys.stderr)
        return EXIT_UNAVAILABLE
    print(f"pylinkage crank angle vs nominal θ_k: max |Δθ| = {drift:.2e} rad")

    why = mechloop_missing()
    if why is not None:
        print_table([("pylinkage", t_pyl)], n)
        print(f"cannot compare: {why}", file=sys.stderr)
        return EXIT_UNAVAILABLE
    t_ml, kin_ml = run_mechloop(n, args.repeats)

    dpos, dvel, dacc = compare(kin_pyl, kin_ml)
    print(
        f"joint B, pylinkage vs mechloop: max |Δp| = {dpos:.2e} m, "
        f"max |Δv|/max|v| = {dvel:.2e}, max |Δa|/max|a| = {dacc:.2e}"
    )
    print_table([("pylinkage", t_pyl), ("mechloop", t_ml)], n)
    if not (dpos <= POS_TOL and dvel <= RATE_TOL and dacc <= RATE_TOL):
        print(
            f"FAIL: the tools disagree beyond {POS_TOL:g} m / relative {RATE_TOL:g}",
            file=sys.stderr,
        )
        return EXIT_MISMATCH
    print(f"speedup vs pylinkage: {t_pyl / t_ml:.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
