"""A large population evaluated on every idle core: threads, each a share of the designs.

On a large population :meth:`~mechloop.synthesis.problem.SynthesisProblem.evaluate`
spends most of its time in NumPy's ufuncs and the compiled kernels
(:mod:`mechloop.modules.kernels`), which release Python's global lock: threads, each
evaluating a contiguous share of the designs, run that arithmetic on several cores at
once.  The Python code between those calls still runs one thread at a time — about 2 ms
per call whatever the population —, so a population is split only when it solves at
least :data:`PARALLEL_ELEMENTS` designs × positions (measured on a quiet 2-core machine:
two threads gained 1.2x from 4,000 designs at 18 target positions, 1.1x from 500 designs
at 181 positions, 1.5–1.7x at 20,000 designs; below 65,536 elements they lost up to
40 %; benchmarks/bench_synthesis.py ``--sizes``).

A design's numbers do not depend on the other designs of its population (elementwise
arithmetic, reductions along each design's own positions), so the evaluations of the
shares put end to end are those of one call — to the last digits that already depend on
the population in one call (the shape objective iterates until every design has
converged; NumPy's SIMD loops may round an element differently by its place in the
array): 1e-12 relative, tests/test_evaluation_threads.py.
Each share is evaluated by a private shallow copy of the problem (and of its circuits'
sub-problems), kept between calls, so the state an evaluation stores on its problem is
never shared between two threads.

How many threads: one per core this process may use that other work leaves idle
(:func:`mechloop.output.parallel.idle_cores`: the cores less the 1-minute load average;
the table writers, whose write lasts seconds, take every core instead), where this
process's own recent work, its CPU time per second averaged over the same minute, is not
counted as other work, and where other work counts at most as the threads running
elsewhere at that moment (a job that has just ended weighs on the average for a minute).
On a busy machine that leaves one core, and the population is evaluated in one call.
"""

from __future__ import annotations

import contextvars
import copy
import math
import threading
import time
import weakref
from concurrent.futures import Future, ThreadPoolExecutor
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from mechloop.output.parallel import idle_cores, usable_cores

if TYPE_CHECKING:
    from mechloop.synthesis.problem import Evaluation, SynthesisProblem

Array = NDArray[np.float64]

#: Fewest elements (designs × positions solved, every circuit counted) worth splitting
#: a population for; each share holds at least half of it.
PARALLEL_ELEMENTS = 1 << 16

#: At most this many threads.
MAX_THREADS = 8

#: Time constant of the 1-minute load average (s), for this process's own share of it.
LOAD_SECONDS = 60.0

_local = threading.local()
_pool: ThreadPoolExecutor | None = None
_pool_lock = threading.Lock()
_twins: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


class _OwnLoad:
    """This process's CPU time per second of wall time, averaged as the kernel averages
    the load (exponentially, over :data:`LOAD_SECONDS`), from its first reading on."""

    def __init__(self) -> None:
        self.wall = time.monotonic()
        self.cpu = time.process_time()
        self.load = 0.0

    def __call__(self) -> float:
        wall, cpu = time.monotonic(), time.process_time()
        elapsed = wall - self.wall
        if elapsed > 0.05:  # a shorter interval is noise
            keep = math.exp(-elapsed / LOAD_SECONDS)
            self.load = keep * self.load + (1.0 - keep) * (cpu - self.cpu) / elapsed
            self.wall, self.cpu = wall, cpu
        return self.load


own_load = _OwnLoad()


def evaluation_threads(designs: int, columns: int = 1) -> int:
    """Threads to evaluate a population of ``designs`` designs with, each solved at
    ``columns`` positions (:func:`columns_of`): 1 below :data:`PARALLEL_ELEMENTS`
    elements, inside a share already being evaluated, or when fewer than two cores are
    idle; else one per idle core (at most :data:`MAX_THREADS`, and each share at least
    half of :data:`PARALLEL_ELEMENTS`)."""
    elements = designs * max(columns, 1)
    if elements < PARALLEL_ELEMENTS or getattr(_local, "inside", False):
        return 1
    idle = int(idle_cores(own=own_load(), now=True) + 0.5)
    return max(1, min(usable_cores(), MAX_THREADS, idle, designs,
                      elements // (PARALLEL_ELEMENTS // 2)))


def columns_of(problem: SynthesisProblem) -> int:
    """Positions (and target inputs) an evaluation of ``problem`` solves per design,
    times its circuits: the targets' positions where the objective reads only them,
    position 0 and the target inputs with free timing, else every position."""
    every = problem.model.positions + 1
    if problem.at_inputs:
        columns = (1 if problem.inputs_only else every) + problem._target_count()
    elif problem.objective_positions is not None:
        columns = problem.objective_positions.size
    else:
        columns = every
    return columns * max(len(problem.circuits), 1)


def evaluate_shares(problem: SynthesisProblem, designs: Array, threads: int, *,
                    continuous: bool = False) -> Evaluation:
    """``problem.evaluate(designs, continuous=continuous)`` (SI, ``(D, V)``) as
    ``threads`` contiguous shares of the designs, each in its own thread (this one
    evaluates the first), joined in order: the same
    :class:`~mechloop.synthesis.problem.Evaluation`."""
    bounds = np.linspace(0, designs.shape[0], threads + 1).round().astype(int)
    twins = _twins_of(problem, threads)
    pool = _executor(threads - 1)
    futures: list[Future] = []
    try:
        for k in range(1, threads):
            # in a copy of this thread's context: NumPy's errstate as the caller set it
            futures.append(pool.submit(contextvars.copy_context().run, _evaluate_share,
                                       twins[k], designs[bounds[k]:bounds[k + 1]],
                                       continuous))
        first = _evaluate_share(twins[0], designs[bounds[0]:bounds[1]], continuous)
        parts = [first, *(future.result() for future in futures)]
    finally:
        for future in futures:  # nothing still runs when this returns or raises
            future.cancel() or future.exception()
    return _joined(parts)


def _evaluate_share(problem: SynthesisProblem, designs: Array, continuous: bool
                    ) -> Evaluation:
    """One share, with splitting off inside it (a circuit's sub-problem, say)."""
    _local.inside = True
    try:
        return problem.evaluate(designs, continuous=continuous, threads=1)
    finally:
        _local.inside = False


def _twins_of(problem: SynthesisProblem, threads: int) -> list[SynthesisProblem]:
    """``threads`` private shallow copies of ``problem``, its circuits' sub-problems
    copied too, made once and kept while the problem lives."""
    twins = _twins.setdefault(problem, [])
    while len(twins) < threads:
        twin = copy.copy(problem)
        twin.circuits = [(variants, copy.copy(sub)) for variants, sub in problem.circuits]
        twins.append(twin)
    return twins


def _executor(workers: int) -> ThreadPoolExecutor:
    """The process's pool of evaluation threads, grown to at least ``workers``."""
    global _pool
    with _pool_lock:
        if _pool is None or _pool._max_workers < workers:
            old, _pool = _pool, ThreadPoolExecutor(max(workers, 1),
                                                   thread_name_prefix="mechloop-evaluate")
            if old is not None:
                old.shutdown(wait=False)
        return _pool


def _joined(parts: list[Evaluation]) -> Evaluation:
    """The evaluations of consecutive shares as one (every field put end to end)."""
    from mechloop.synthesis.problem import Evaluation

    sizes = [p.total.shape[0] for p in parts]

    def cat(values: list) -> NDArray:  # a share's scalar stands for each of its designs
        return np.concatenate([np.broadcast_to(v, (n, *np.shape(v)[1:]))
                               for v, n in zip(values, sizes, strict=True)])

    return Evaluation(
        total=cat([p.total for p in parts]), q=cat([p.q for p in parts]),
        feasible=cat([p.feasible for p in parts]),
        broken_share=cat([p.broken_share for p in parts]),
        keeps_variant=cat([p.keeps_variant for p in parts]),
        terms={key: cat([p.terms[key] for p in parts]) for key in parts[0].terms},
        measures={key: cat([p.measures[key] for p in parts]) for key in parts[0].measures})


__all__ = ["MAX_THREADS", "PARALLEL_ELEMENTS", "columns_of", "evaluate_shares",
           "evaluation_threads", "own_load"]
