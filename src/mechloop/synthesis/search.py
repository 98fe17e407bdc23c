"""Search strategies for synthesis: differential evolution (SciPy), CMA-ES (``cma``) and
multi-start local search, with the stopping rules of seed 002 (good enough, no progress
over K generations, a time budget), a progress callback and Ctrl-C returning the best
design found so far.

Every strategy hands whole generations to :meth:`SynthesisProblem.evaluate` (one
vectorized call per generation, designs × positions).  The Nelder–Mead polish of the best
design evaluates one design at a time; the local searches of the multi-start run side by
side, each stage of all of them one vectorized call (:mod:`mechloop.synthesis.simplex`),
and can be spread over Dask workers.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import differential_evolution, least_squares, minimize
from scipy.stats import qmc

from mechloop.errors import ModelError, Problem
from mechloop.model.schema import Model
from mechloop.model.synthesis import Search, check_synthesis
from mechloop.model.units import to_si, unit_factor
from mechloop.synthesis.problem import Evaluation, SynthesisProblem
from mechloop.synthesis.variables import current_values

Array = NDArray[np.float64]

#: Starting designs as :func:`synthesize` takes them: one mapping name -> value, a list of
#: them, or an array ``(S, V)`` / ``(V,)`` (columns in the order of ``vary``), model units.
StartDesigns = Mapping[str, float | str] | Sequence[Mapping[str, float | str]] | ArrayLike


@dataclass(frozen=True)
class Progress:
    """What a progress callback receives after every generation."""

    iteration: int
    evaluations: int
    best_total: float
    best_q: float
    elapsed: float
    feasible: bool
    #: The model with the best design so far (built when called), or None before any.
    best_model: Callable[[], Model] | None = None


#: Share of a time budget kept for the final polish (DE and CMA-ES with polish), and the
#: margin kept otherwise (the final evaluation and the result's assembly): the whole run,
#: polish included, stays within the budget (the polish stops at the budget's end).
POLISH_SHARE = 0.1
MARGIN_SHARE = 0.02


class _Stop(Exception):
    """Raised inside the search to end it; carries the reason."""


class _Tracker:
    """Counts evaluations, keeps the best designs, applies the stopping rules."""

    def __init__(self, problem: SynthesisProblem, search: Search, keep: int,
                 progress: Callable[[Progress], None] | None, budget: float | None,
                 started: float | None = None, reserve: float = 0.0):
        self.problem = problem
        self.search = search
        self.keep = keep
        self.progress = progress
        self.started = time.perf_counter() if started is None else started
        # the hard wall-clock limit of the whole run (perf_counter, s), and the part of
        # the budget the global phase may use (the rest is kept for the polish)
        self.deadline = math.inf if budget is None else self.started + budget
        self.budget = None if budget is None else budget * (1.0 - reserve)
        self.polish_evaluations = 0
        self.polish_note = ""
        self.notes: list[str] = []
        self.evaluations = 0
        self.iteration = 0
        self.best_x: Array | None = None
        self.best_total = math.inf
        self.best_q = math.nan
        self.since_better = 0
        self.history: list[dict[str, float]] = []
        self.archive_x = np.empty((0, len(problem.variables)))
        self.archive_f = np.empty(0)
        self.good_enough = None
        if search.good_enough is not None:
            self.good_enough = _in_q_units(problem, search.good_enough)

    def evaluate(self, designs: Array) -> Evaluation:
        """Evaluate a generation (SI designs ``(D, V)``) and remember the best."""
        if time.perf_counter() >= self.deadline:
            raise _Stop("time budget spent")
        designs = self.problem.variables.clip(np.atleast_2d(designs))
        ev = self.problem.evaluate(designs)
        self.evaluations += designs.shape[0]
        order = np.argsort(ev.total)
        best = order[0]
        if ev.total[best] < self.best_total:
            self.best_total = float(ev.total[best])
            self.best_x = designs[best].copy()
            self.best_q = float(ev.q[best])
        ok = ev.feasible[order[: self.keep]]
        chosen = order[: self.keep][ok]
        if chosen.size:
            self.archive_x = np.vstack([self.archive_x, designs[chosen]])
            self.archive_f = np.concatenate([self.archive_f, ev.total[chosen]])
            if self.archive_f.size > 4 * self.keep:
                top = np.argsort(self.archive_f)[: 2 * self.keep]
                self.archive_x, self.archive_f = self.archive_x[top], self.archive_f[top]
        return ev

    def generation_done(self, improved_before: float) -> None:
        """Record a generation, report it, and stop the search if a rule says so."""
        self.iteration += 1
        elapsed = time.perf_counter() - self.started
        if self.best_total < improved_before * (1 - 1e-12) - 1e-300:
            self.since_better = 0
        else:
            self.since_better += 1
        self.history.append({"iteration": self.iteration, "evaluations": self.evaluations,
                             "best": self.best_total, "q": self.best_q, "time": elapsed})
        if self.progress is not None:
            best_x = self.best_x
            self.progress(Progress(self.iteration, self.evaluations, self.best_total,
                                   self.best_q, elapsed, math.isfinite(self.best_q),
                                   None if best_x is None else
                                   (lambda: self.problem.design_model(best_x))))
        if self.good_enough is not None and self.best_q <= self.good_enough:
            raise _Stop("good enough")
        if self.search.patience is not None and self.since_better >= self.search.patience:
            raise _Stop(f"no progress over {self.search.patience} generations")
        if self.budget is not None and elapsed >= self.budget:
            raise _Stop("time budget spent")
        if self.iteration >= self.search.iterations:
            raise _Stop("iteration limit")


def _in_q_units(problem: SynthesisProblem, value) -> float:
    """A value of Q (a number in Q's unit, or a quantity string) in Q's unit."""
    if not isinstance(value, str):
        return float(value)
    angle = problem.target_kind == "function" and problem.output[0] == "a"
    kind = "angle" if angle else "length"
    return to_si(value, kind, problem.q_unit) / unit_factor(problem.q_unit, kind)


@dataclass(frozen=True)
class SynthesisResult:
    """The outcome of a synthesis run.

    ``best`` is the best design (SI, ``(V,)``), ``evaluation`` its terms (arrays of one),
    ``model`` the model with the best design written in, ``history`` one row per
    generation (evaluations, best total, best Q, time), ``designs`` the best distinct
    feasible designs found (model units), ``stopped`` why the search ended.
    """

    problem: SynthesisProblem
    best: Array
    evaluation: Evaluation
    model: Model
    history: pd.DataFrame
    designs: pd.DataFrame
    stopped: str
    evaluations: int
    elapsed: float
    method: str
    polish: str = ""
    polish_evaluations: int = 0
    notes: tuple[str, ...] = ()

    @property
    def feasible(self) -> bool:
        """The feasibility verdict of the best design (the problem's own decision: every
        mandatory condition holds)."""
        return bool(self.evaluation.feasible[0])

    def summary(self) -> list[str]:
        """The run in a few lines: method, evaluations, time, why it stopped, the polish,
        every term of the best design and the feasibility verdict (the lines the CLI
        prints and a written model's header repeats)."""
        lines = [f"method: {self.method}; {self.evaluations} evaluations "
                 f"({self.polish_evaluations} in the local search/polish) in "
                 f"{self.elapsed:.2f} s; stopped: {self.stopped}"]
        if self.polish:
            lines.append(f"local search: {self.polish}")
        lines += [f"note: {note}" for note in self.notes]
        lines.append("terms: " + ", ".join(f"{k} = {v:.6g}" for k, v in self.terms().items()))
        lines.append("feasible: " + ("yes, every mandatory condition holds" if self.feasible
                                     else "no"))
        return lines

    @property
    def q(self) -> float:
        """The main criterion of the best design (model units of the target)."""
        return float(self.evaluation.q[0])

    def values(self) -> dict[str, float]:
        """The best design in the model's units."""
        return self.problem.variables.to_model_units(self.best)

    def terms(self) -> dict[str, float]:
        """Every term of the objective for the best design: Q, each penalty and each
        measured quantity, and the mandatory conditions."""
        ev = self.evaluation
        out: dict[str, float] = {"Q": self.q, "total": float(ev.total[0]),
                                 "broken share": float(ev.broken_share[0]),
                                 "variant kept": float(ev.keeps_variant[0])}
        for key, value in ev.measures.items():
            out[key] = float(value[0])
        for key, value in ev.terms.items():
            out[f"penalty {key}"] = float(value[0])
        return out

    @property
    def evaluations_per_second(self) -> float:
        return self.evaluations / self.elapsed if self.elapsed > 0 else math.inf


def synthesize(model: Model, *, method: str | None = None, seed: int | None = None,
               iterations: int | None = None, population: int | None = None,
               time_budget: float | None = None, polish: bool | None = None,
               progress: Callable[[Progress], None] | None = None,
               scheduler: str | None = None, keep: int = 10,
               start: StartDesigns | None = None, atlas: bool | None = None
               ) -> SynthesisResult:
    """Run the synthesis task of ``model`` (its ``synthesis:`` section).

    Keyword arguments override the task's ``search`` settings.  ``scheduler`` spreads the
    multi-start's local searches (see :mod:`mechloop.synthesis.parallel`).  Ctrl-C ends the
    search and returns the best design found so far (``stopped == 'interrupted'``).

    ``start`` (default: the task's ``search.start``, else the model's own design) gives
    starting designs, e.g. classical closed-form solutions (:mod:`mechloop.synthesis.
    classical`): a mapping variable name -> value, a list of such mappings, or an array
    ``(S, V)`` (or ``(V,)``) whose columns follow ``vary``; values in the model's units
    (a string may carry its own unit), within the bounds.  A variable a mapping leaves out
    takes the model's own value.  A name that is not varied or a value outside the bounds
    raises :class:`~mechloop.errors.ModelError`.  Every starting design is evaluated first
    (one call); DE puts them into its first population (the rest stays a Sobol or Latin
    hypercube sample drawn from the seed), CMA-ES centres its first run on the best of
    them with a step of 0.1 of the box instead of 0.3 (restarts stay random), and the
    multi-start runs its first local searches from them (then from the best samples,
    ``search.starts`` runs at least).

    ``atlas`` (default: the task's ``search.atlas``) adds starting designs from the
    atlas of four-bar coupler curves (:mod:`mechloop.synthesis.atlas`) where the problem
    is a four-bar path problem it applies to and no starting design is given; the
    result's ``notes`` say how many, or why it was skipped.
    """
    started = time.perf_counter()  # the budget counts from here, compiling included
    problem = SynthesisProblem(model)
    search = problem.task.search
    update = {k: v for k, v in {"method": method, "seed": seed, "iterations": iterations,
                                "population": population, "time": time_budget,
                                "polish": polish, "atlas": atlas}.items() if v is not None}
    if update:  # validated like the file's own settings (method, bounds of counts)
        search = type(search).model_validate({**search.model_dump(), **update})
    method, why = choose_method(problem, search.method)
    if why:
        search = type(search).model_validate({**search.model_dump(), "method": method})
    polishing = search.polish and search.method != "multistart"
    tracker = _Tracker(problem, search, keep, progress, search.time, started,
                       POLISH_SHARE if polishing else MARGIN_SHARE)
    if why:
        tracker.notes.append(f"method auto: {method} ({why})")
    rng = np.random.default_rng(search.seed)
    given = start_designs(problem, start)
    starts = current_values(model, problem.variables)[None, :] if given is None else given
    has_starts = given is not None
    if search.atlas and given is not None:
        tracker.notes.append("atlas not used: starting designs are given")
    elif search.atlas:
        from mechloop.synthesis.atlas import atlas_starts

        found, why = atlas_starts(problem)
        if found is None:
            tracker.notes.append(f"atlas skipped: {why}")
        else:
            starts = np.vstack([starts, found])  # the model's own design first
            has_starts = True
            tracker.notes.append(f"atlas: {len(found)} starting designs from the coupler-"
                                 "curve atlas")
    stopped = "iteration limit"
    try:
        if search.method == "de":
            _run_de(problem, search, tracker, starts, rng, has_starts)
        elif search.method == "cmaes":
            _run_cmaes(problem, search, tracker, starts, rng, has_starts)
        else:
            _run_multistart(problem, search, tracker, starts, rng, scheduler, has_starts)
    except _Stop as stop:
        stopped = str(stop)
    except KeyboardInterrupt:
        stopped = "interrupted"
    if polishing and stopped not in ("interrupted",) and tracker.best_x is not None:
        try:
            _polish(problem, tracker, tracker.best_x, search)
        except KeyboardInterrupt:
            stopped = "interrupted"
        except _Stop:
            tracker.polish_note += " (stopped by the time budget)"
    return _result(problem, tracker, stopped, search.method)


def choose_method(problem: SynthesisProblem, method: str) -> tuple[str, str]:
    """The method ``auto`` stands for on ``problem``, and why (``(method, '')`` for any
    other).  Measured on the bundled four-bar path problems
    (``benchmarks/bench_synthesis_problems.py --compare``): the multistart by exact least
    squares from the atlas's starting designs where the atlas applies; CMA-ES on a timed
    path it does not apply to; DE, the earlier default, elsewhere (not measured)."""
    if method != "auto":
        return method, ""
    from mechloop.synthesis.atlas import recognize
    from mechloop.synthesis.gradient import exact_jacobian_available

    if exact_jacobian_available(problem):
        if recognize(problem.model, problem)[0] is not None:
            return "multistart", "a four-bar path the atlas applies to"
        return "cmaes", "a timed path the atlas does not apply to"
    return "de", "no timed path"


def start_designs(problem: SynthesisProblem, start: StartDesigns | None = None
                  ) -> Array | None:
    """The starting designs, SI, shape ``(S, V)``: ``start`` (see :func:`synthesize`) or,
    without it, the task's ``search.start``; None when neither is given.

    Raises :class:`~mechloop.errors.ModelError` for a name that is not varied or a value
    outside the bounds (checked as :func:`~mechloop.model.synthesis.check_synthesis` checks
    ``search.start``) or an array with the wrong number of columns.
    """
    variables = problem.variables
    task = problem.task
    if start is None:
        given = task.search.start
        if given is None:
            return None
    else:
        if not isinstance(start, Mapping) and not (
                isinstance(start, Sequence) and all(isinstance(d, Mapping) for d in start)):
            array = np.atleast_2d(np.asarray(start, dtype=float))
            if array.ndim != 2 or array.shape[1] != len(variables):
                raise ModelError([Problem(("start",), f"an array of starting designs has "
                                          f"shape {np.shape(start)}, not (S, V) or (V,) "
                                          f"with V = {len(variables)}", "give one column "
                                          f"per variable: {', '.join(variables.names)}")])
            start = [dict(zip(variables.names, map(float, row), strict=True))
                     for row in array]
        search = Search.model_validate({**task.search.model_dump(), "start": start})
        given = search.start
        model = problem.model.model_copy(update={
            "synthesis": task.model_copy(update={"search": search})})
        where = ("synthesis", "search", "start")
        problems = [p for p in check_synthesis(model) if p.path[:3] == where]
        if problems:
            raise ModelError([Problem(("start", *p.path[3:]), p.message, p.hint)
                              for p in problems])
    designs = [given] if isinstance(given, Mapping) else list(given)
    if not designs:  # an empty list: no starting design
        return None
    base = current_values(problem.model, variables)
    out = np.repeat(base[None, :], len(designs), axis=0)
    for row, design in zip(out, designs, strict=True):
        for name, value in design.items():
            i = variables.names.index(name)
            row[i] = to_si(value, variables.kind(i), variables.units[i])
    return out


def _result(problem: SynthesisProblem, tracker: _Tracker, stopped: str, method: str
            ) -> SynthesisResult:
    best = tracker.best_x
    if best is None:
        best = problem.variables.scale(np.full(len(problem.variables), 0.5))
    evaluation = problem.evaluate(best[None, :], continuous=True)  # as it really moves
    elapsed = time.perf_counter() - tracker.started
    order = np.argsort(tracker.archive_f)
    rows, seen = [], []
    span = problem.variables.high - problem.variables.low
    for i in order:
        x = tracker.archive_x[i]
        if any(np.max(np.abs(x - s) / span) < 1e-6 for s in seen):
            continue
        seen.append(x)
        row = {"total": float(tracker.archive_f[i])}
        row.update(problem.variables.to_model_units(x))
        rows.append(row)
        if len(rows) >= tracker.keep:
            break
    designs = pd.DataFrame(rows)
    if len(designs):
        designs.insert(0, "rank", np.arange(1, len(designs) + 1))
    return SynthesisResult(problem=problem, best=best, evaluation=evaluation,
                           model=problem.design_model(best),
                           history=pd.DataFrame(tracker.history), designs=designs,
                           stopped=stopped, evaluations=tracker.evaluations,
                           elapsed=elapsed, method=method, polish=tracker.polish_note,
                           polish_evaluations=tracker.polish_evaluations,
                           notes=tuple(tracker.notes))


def _run_de(problem: SynthesisProblem, search: Search, tracker: _Tracker, starts: Array,
            rng: np.random.Generator, given: bool) -> None:
    """Differential evolution; ``starts`` (``(S, V)``, SI) are evaluated first.  The
    model's own design (``given`` false) replaces one member of SciPy's own first
    population (``x0``); given starting designs replace the first members of a Sobol or
    Latin hypercube sample of the same size drawn here from ``rng``."""
    variables = problem.variables
    n_vars = len(variables)
    popsize = max(1, math.ceil(search.population / n_vars))
    before = [math.inf]
    unit_starts = np.clip(variables.unscale(starts), 0.0, 1.0)
    if given:
        count = max(popsize * n_vars, 5, len(starts))
        sampler = (qmc.Sobol(n_vars, seed=rng) if _pow2(count)
                   else qmc.LatinHypercube(n_vars, seed=rng))
        init = sampler.random(count)
        init[: len(starts)] = unit_starts
        first: dict = {"init": init}
    else:
        first = {"x0": unit_starts[0],
                 "init": "sobol" if _pow2(popsize * n_vars) else "latinhypercube"}

    def func(unit: Array) -> Array:  # scipy passes (V, S) when vectorized
        return tracker.evaluate(variables.scale(unit.T)).total

    def callback(intermediate_result) -> None:
        tracker.generation_done(before[0])
        before[0] = tracker.best_total

    tracker.evaluate(starts)
    before[0] = tracker.best_total
    differential_evolution(func, [(0.0, 1.0)] * n_vars, maxiter=search.iterations,
                           popsize=popsize, tol=0.0, atol=0.0, rng=rng, polish=False,
                           callback=callback, vectorized=True, updating="deferred",
                           **first)


def _pow2(n: int) -> bool:
    return n > 0 and n & (n - 1) == 0


def _run_cmaes(problem: SynthesisProblem, search: Search, tracker: _Tracker, starts: Array,
               rng: np.random.Generator, given: bool) -> None:
    """CMA-ES with restarts.  The first run is centred on the best of ``starts``, with an
    initial step of 0.3 of the box from the model's own design and 0.1 from ``given``
    starting designs (a refinement of a known good design, e.g. a classical solution on a
    thin feasible set); restarts begin at random points with 0.3."""
    import cma

    variables = problem.variables
    seed = int(rng.integers(1, 2**31 - 1))
    lower, upper = variables.unit_bounds()
    options = {"bounds": [[None if np.isinf(v) else 0.0 for v in lower],
                          [None if np.isinf(v) else 1.0 for v in upper]],
               "popsize": search.population, "seed": seed, "verbose": -9,
               "maxiter": search.iterations + 1, "tolfun": 0, "tolx": 1e-14,
               "tolfunhist": 0, "tolstagnation": 10**9}
    ev = tracker.evaluate(starts)
    best = variables.clip(starts[int(np.argmin(ev.total))])
    x0 = np.clip(variables.unscale(best), 0.05, 0.95)
    restarts = 0
    sigma = 0.1 if given else 0.3
    while True:
        es = cma.CMAEvolutionStrategy(x0, sigma, options)
        while not es.stop():
            before = tracker.best_total
            unit = variables.clip_unit(np.array(es.ask()))
            ev = tracker.evaluate(variables.scale(unit))
            es.tell(list(unit), list(ev.total))
            tracker.generation_done(before)
        restarts += 1  # converged early: restart from a random point, as IPOP would
        x0 = rng.uniform(0.05, 0.95, len(variables))
        sigma = 0.3
        options["popsize"] = int(options["popsize"] * 2) if restarts < 4 else \
            options["popsize"]


def _local(problem: SynthesisProblem, x0_unit: Array, max_evals: int,
           evaluate: Callable[[Array], float]) -> tuple[Array, float]:
    variables = problem.variables

    def func(unit: Array) -> float:
        return evaluate(variables.scale(variables.clip_unit(unit)))

    lower, upper = variables.unit_bounds()
    found = minimize(func, x0_unit, method="Nelder-Mead",
                     bounds=list(zip(lower, upper, strict=True)),
                     options={"maxfev": max_evals, "xatol": 1e-10, "fatol": 1e-14,
                              "adaptive": len(variables) > 4})
    return variables.scale(variables.clip_unit(found.x)), float(found.fun)


def _polish(problem: SynthesisProblem, tracker: _Tracker, best: Array, search: Search
            ) -> None:
    """Least squares on the residuals from the best design, then Nelder–Mead on the
    objective itself; every result goes through the tracker, so the best design only
    ever improves, and every evaluation checks the run's hard deadline (raising
    :class:`_Stop` past it).

    The least squares' Jacobian is exact where the target allows it (a timed path:
    implicit differentiation, :mod:`mechloop.synthesis.gradient`), else forward
    differences (all V + 1 designs in one vectorized call)."""
    x_best, ok = _least_squares(problem, tracker, best, 50 * len(problem.variables),
                                _polish_deadline(tracker))
    if ok:
        tracker.evaluate(x_best[None, :])

    tracker.polish_note += ", then Nelder-Mead"

    def evaluate(x: Array) -> float:
        return float(tracker.evaluate(x[None, :]).total[0])

    before = tracker.evaluations
    _local(problem, problem.variables.unscale(tracker.best_x), 100 * len(problem.variables),
           evaluate)
    tracker.polish_evaluations += tracker.evaluations - before


def _polish_deadline(tracker: _Tracker) -> float:
    """When the polish's least squares must hand back its best design: the hard
    deadline less the margin kept for the final evaluations."""
    if not math.isfinite(tracker.deadline):
        return math.inf
    budget = tracker.deadline - tracker.started
    return tracker.deadline - MARGIN_SHARE * budget


def _least_squares(problem: SynthesisProblem, tracker: _Tracker, start: Array,
                   max_nfev: int, deadline: float, guarded: bool = False
                   ) -> tuple[Array, bool]:
    """One least-squares run (SciPy's trust region reflective, in the unit box) from
    ``start`` (SI); returns the design it ends at (SI) — at ``deadline``
    (``perf_counter``) the best one it has seen — and whether it ran.  ``guarded``: add
    the crank guard's rows where it applies (the multistart's runs from afar; the polish
    of a design already found goes without, so that it may reach a design close to the
    Grashof limit)."""
    from mechloop.synthesis.gradient import (
        CrankGuard,
        exact_jacobian_available,
        residual_jacobian,
    )

    variables = problem.variables
    n_vars = len(variables)
    span = variables.high - variables.low
    step = 1e-7
    exact = exact_jacobian_available(problem)
    tracker.polish_note = ("least squares with the exact Jacobian (implicit "
                           "differentiation)" if exact else
                           "least squares with a forward-difference Jacobian")
    seen: list = [start, math.inf]  # the best design seen and its sum of squares

    def check_time() -> None:
        if time.perf_counter() >= deadline:
            raise _OutOfTime

    guard = CrankGuard.of(problem) if exact and guarded else None
    if guard is not None:
        tracker.polish_note += ("; the least squares keeps the four-bar's crank off the "
                                "Grashof limit (guard rows, zero inside)")

    def fun(unit: Array) -> Array:
        check_time()
        tracker.evaluations += 1
        tracker.polish_evaluations += 1
        x = variables.scale(unit)
        res = problem.residuals(x[None, :])[0]
        if guard is not None:
            res = np.concatenate([res, guard.rows(x)[0]])
        size = float(res @ res)
        if size < seen[1]:
            seen[:] = [x, size]
        return res

    def jac(unit: Array) -> Array:
        check_time()
        if exact:
            tracker.evaluations += 1
            tracker.polish_evaluations += 1
            x = variables.scale(unit)
            _, jacobian = residual_jacobian(problem, x)
            if guard is not None:
                jacobian = np.vstack([jacobian, guard.rows(x)[1]])
            return jacobian * span[None, :]
        probes = np.repeat(unit[None, :], n_vars + 1, axis=0)
        steps = np.where(unit + step <= 1.0, step, -step)
        probes[np.arange(1, n_vars + 1), np.arange(n_vars)] += steps
        res = problem.residuals(variables.scale(probes))
        tracker.evaluations += n_vars + 1
        tracker.polish_evaluations += n_vars + 1
        return ((res[1:] - res[0]) / steps[:, None]).T

    x0 = np.clip(variables.unscale(start), 0.0, 1.0)
    try:
        if not np.all(np.abs(fun(x0)) < 1e6):
            return start, False
        turn = periodic_columns(problem)
        low, high = np.where(turn, -np.inf, 0.0), np.where(turn, np.inf, 1.0)
        found = least_squares(lambda u: fun(_wrap_unit(u, turn)),
                              x0, jac=lambda u: jac(_wrap_unit(u, turn)),
                              bounds=(low, high), x_scale=1.0 if exact else "jac",
                              xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=max_nfev)
    except _OutOfTime:
        return seen[0], math.isfinite(seen[1])
    return variables.scale(_wrap_unit(found.x, turn)), True


def periodic_columns(problem: SynthesisProblem) -> NDArray[np.bool_]:
    """The periodic variables, ``(V,)`` (:attr:`Variables.periodic`: ``periodic`` or
    bounds spanning a full turn): the local search moves them freely and takes them
    modulo the turn (a design at 359° is next to one at 1°), instead of stopping at the
    cut."""
    return np.asarray(problem.variables.periodic, dtype=bool)


def _wrap_unit(unit: Array, turn: NDArray[np.bool_]) -> Array:
    """Unit coordinates with the periodic columns taken modulo 1 (the turn)."""
    return np.where(turn, np.mod(unit, 1.0), unit)


class _OutOfTime(Exception):
    """A local search reached the run's deadline."""


def _local_runs(problem: SynthesisProblem, x0_unit: Array, max_evals: int,
                deadline: float | None = None) -> list[tuple[Array, float, int]]:
    """The local searches of the multi-start from the unit starts ``x0_unit`` ``(S, V)``
    (on one worker): SciPy's Nelder–Mead from each start, run side by side
    (:func:`mechloop.synthesis.simplex.nelder_mead`, every stage of all the starts one
    vectorized evaluation); each stops with the best design it has evaluated at
    ``deadline`` (``time.time()``, s), the search's time budget.  One ``(design SI,
    total, evaluations)`` per start."""
    from mechloop.synthesis.simplex import nelder_mead

    variables = problem.variables

    def func(unit: Array) -> Array:
        return problem.evaluate(variables.scale(variables.clip_unit(unit))).total

    def stop() -> bool:
        return deadline is not None and time.time() > deadline

    lower, upper = variables.unit_bounds()
    found = nelder_mead(func, x0_unit, lower=lower, upper=upper, maxfev=max_evals,
                        xatol=1e-10, fatol=1e-14, adaptive=len(variables) > 4, stop=stop)
    designs = variables.scale(variables.clip_unit(found.x))
    return [(x, float(f), int(count))
            for x, f, count in zip(designs, found.fun, found.nfev, strict=True)]


def _run_multistart(problem: SynthesisProblem, search: Search, tracker: _Tracker,
                    starts: Array, rng: np.random.Generator, scheduler: str | None,
                    given: bool) -> None:
    """Sample a Sobol population (one vectorized call per generation), then run local
    searches from the best distinct samples, on Dask workers when asked; ``given``
    starting designs are the first local starts (then the best samples, ``search.starts``
    runs at least)."""
    from mechloop.synthesis.gradient import exact_jacobian_available
    from mechloop.synthesis.parallel import choose_scheduler, map_tasks

    variables = problem.variables
    if exact_jacobian_available(problem) and scheduler in (None, "serial"):
        _run_multistart_lsq(problem, search, tracker, starts, rng, given)
        return
    sampler = qmc.Sobol(len(variables), seed=rng)
    samples = sampler.random_base2(math.ceil(math.log2(max(search.population * 4, 16))))
    before = tracker.best_total
    tracker.evaluate(starts)
    ev = tracker.evaluate(variables.scale(samples))
    tracker.generation_done(before)
    order = np.argsort(ev.total)
    first = list(np.clip(variables.unscale(starts), 0.0, 1.0)) if given else []
    local = first + [samples[i] for i in order[: max(search.starts - len(first), 0)]]
    # each run is one generation: the runs past the iteration limit would never be read
    local = np.array(local[: max(search.iterations - tracker.iteration, 0)])
    if not len(local):
        return
    budget = max(200, search.iterations * 10) * len(variables)
    deadline = None if tracker.budget is None else \
        time.time() + tracker.budget - (time.perf_counter() - tracker.started)
    clock = time.perf_counter()
    problem.evaluate(variables.scale(local))
    # side by side, the runs cost about one run's evaluations of all their starts at once
    per_run = (time.perf_counter() - clock) * budget / len(local)
    if scheduler is None:
        scheduler = choose_scheduler(len(local), seconds_per_item=per_run)
    jobs = [(problem, group, budget, deadline) for group in _groups(local, scheduler)]
    runs = [run for group in map_tasks(_run_job, jobs, scheduler=scheduler)
            for run in group]
    for x, _, count in runs:
        before = tracker.best_total
        tracker.evaluate(x[None, :])
        tracker.evaluations += count - 1
        tracker.generation_done(before)


def _run_multistart_lsq(problem: SynthesisProblem, search: Search, tracker: _Tracker,
                        starts: Array, rng: np.random.Generator, given: bool) -> None:
    """Multi-start by least squares with the exact Jacobian (a timed path): Sobol
    samples (one vectorized call), then local least-squares runs from the best feasible
    samples in order — ``search.starts`` at least, and with a time budget as many more as
    it allows (one generation per run)."""
    variables = problem.variables
    sampler = qmc.Sobol(len(variables), seed=rng)
    samples = sampler.random_base2(math.ceil(math.log2(max(search.population * 16, 1024))))
    before = tracker.best_total
    tracker.evaluate(starts)
    ev = tracker.evaluate(variables.scale(samples))
    tracker.generation_done(before)
    order = [i for i in np.argsort(ev.total) if ev.feasible[i]]
    local = (list(variables.scale(np.clip(variables.unscale(starts), 0.0, 1.0)))
             if given else []) + [variables.scale(samples[i]) for i in order]
    limit = len(local) if tracker.budget is not None else min(len(local), search.starts)
    for x0 in local[:limit]:
        before = tracker.best_total
        soft = (math.inf if tracker.budget is None
                else tracker.started + tracker.budget)
        found, ok = _least_squares(problem, tracker, x0, max(150, 10 * len(variables)),
                                   soft, guarded=True)
        if ok:
            tracker.evaluate(found[None, :])
        tracker.generation_done(before)


def _groups(local: Array, scheduler) -> list[Array]:
    """The unit starts ``(S, V)`` split into the jobs of ``scheduler``: all in one
    (serial), one group per core (a local cluster), one start each (a remote one)."""
    from mechloop.synthesis.parallel import PROCESSES, SERIAL

    if scheduler == SERIAL:
        count = 1
    elif scheduler == PROCESSES:
        count = min(len(local), os.cpu_count() or 1)
    else:
        count = len(local)
    return [group for group in np.array_split(local, max(count, 1)) if len(group)]


def _run_job(job: tuple[SynthesisProblem, Array, int, float | None]
             ) -> list[tuple[Array, float, int]]:
    problem, x0, budget, deadline = job
    return _local_runs(problem, x0, budget, deadline)
