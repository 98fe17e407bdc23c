"""A synthesis task compiled to one function: a design matrix in, every term out.

:class:`SynthesisProblem` evaluates a population ``(D, V)`` in one call of
:func:`~mechloop.solve.designs.solve_designs` (designs × positions): the main criterion Q
(seed 002: the largest |deviation| by default), the mandatory conditions (the chain never
breaks, the assembly variant is kept) and the desirable ones as penalties (pressure angle,
relative rotation, workspace, user criteria).  Bounds are the search's own box.

What the search minimizes is ``Q + Σ penalties`` for a design that meets the mandatory
conditions, and ``INFEASIBLE · (1 + share of broken positions)`` otherwise, so every
feasible design ranks before every infeasible one and an infeasible one is never reported
as a result.  Dynamic criteria (any column of the dynamic table, the cycle's
``efficiency`` and ``loss_coefficient``, and a machine's ``delta``, ``flywheel`` and
``constant_load``) solve the force analysis of all feasible designs in one batched pass
(:mod:`mechloop.synthesis.dynamic_batch`), friction and the machine's steady cycle
included.  Solving the dynamics of each feasible design on its own remains only as the
fallback for what a batch refuses (:class:`NotImplementedError`) and for a column the
batch does not find.

An objective that reads the targets only (timed targets, or free timing, and no
condition or criterion over the motion) is evaluated at the target positions (or
inputs) only, when the existence of the chain over the whole continuous input can be
decided exactly (:meth:`SynthesisProblem.exact_feasibility`: today the closed form of
:mod:`mechloop.synthesis.crank_turn` for a four-bar driven by its crank); otherwise
every position is solved and feasibility is decided at them.
"""

from __future__ import annotations

import ast
import math
import warnings
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.errors import ModelError, Problem, SolveError
from mechloop.model.dynamic import HeadPoint
from mechloop.model.schema import Model
from mechloop.model.synthesis import CYCLE_VALUES, Criterion, Curve, Point, SynthesisTask
from mechloop.model.units import registry, to_si, unit_factor
from mechloop.solve.designs import DesignResults, solve_designs, solve_designs_at
from mechloop.synthesis import cores, shape
from mechloop.synthesis import deviations as dv
from mechloop.synthesis.circuits import circuit_problems, evaluate_best, residuals_best
from mechloop.synthesis.continuous import curve_distance
from mechloop.synthesis.crank_turn import compile_turn_check
from mechloop.synthesis.variables import Variables, apply_design, compile_variables

Array = NDArray[np.float64]

#: What an infeasible design scores (plus its share of broken positions).
INFEASIBLE = 1e12

_SAFE = {name: getattr(np, name) for name in (
    "sin", "cos", "tan", "arcsin", "arccos", "arctan", "arctan2", "sqrt", "exp", "log",
    "log10", "log2", "abs", "sinh", "cosh", "tanh", "radians", "degrees", "hypot",
    "minimum", "maximum", "where")}
_SAFE.update(pi=np.pi, e=np.e, asin=np.arcsin, acos=np.arccos, atan=np.arctan,
             atan2=np.arctan2, ln=np.log)


def evaluate_expression(text: str, where: tuple, **names: Array | float) -> Array:
    """Evaluate a target expression (NumPy functions, ``pi``, and ``names``).

    Only arithmetic, names and calls of the listed functions are accepted: the text is
    checked node by node before it runs, so a model file cannot run other code.
    """
    allowed = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.operator, ast.unaryop,
               ast.Constant, ast.Name, ast.Load, ast.Call, ast.Compare, ast.cmpop,
               ast.IfExp)
    try:
        tree = ast.parse(text, mode="eval")
        bad = next((type(node).__name__ for node in ast.walk(tree)
                    if not isinstance(node, allowed)
                    or (isinstance(node, ast.Call) and not isinstance(node.func, ast.Name))),
                   None)
        if bad is not None:
            raise ValueError(f"{bad} is not allowed in a target expression")
        value = eval(compile(tree, "<target>", "eval"), {"__builtins__": {}},
                     {**_SAFE, **names})
    except Exception as exc:  # a user's expression can fail in any way
        raise ModelError([Problem(where, f"cannot evaluate {text!r}: {exc}",
                                  f"use {', '.join(sorted(names))} and functions like "
                                  "sin, log10, sqrt")]) from None
    return np.asarray(value, dtype=float)


@dataclass(frozen=True)
class Evaluation:
    """Everything about a population of ``D`` designs.

    ``total`` is what the search minimizes, ``q`` the main criterion (model units of the
    target; NaN where a design is infeasible), ``feasible`` whether the mandatory
    conditions hold, ``broken_share`` the share of positions where the chain breaks (the
    share of the input range, where it is decided exactly: :meth:`exact_feasibility`),
    ``terms`` the penalty of each desirable condition and criterion and ``measures`` the
    quantity each penalizes (pressure angle in the model's angle unit, ...), all ``(D,)``.
    """

    total: Array
    q: Array
    feasible: NDArray[np.bool_]
    broken_share: Array
    keeps_variant: NDArray[np.bool_]
    terms: dict[str, Array] = field(default_factory=dict)
    measures: dict[str, Array] = field(default_factory=dict)


class SynthesisProblem:
    """The synthesis task of ``model`` compiled for fast evaluation.

    ``evaluate(designs)`` takes SI values shaped ``(D, V)`` in the order of
    ``variables.names`` and returns an :class:`Evaluation`.
    """

    def __init__(self, model: Model, task: SynthesisTask | None = None):
        task = task or model.synthesis
        if task is None:
            raise ModelError([Problem(("synthesis",), "the model has no synthesis task",
                                      "add a synthesis: section (see "
                                      "examples/four_bar_path_synthesis.yaml)")])
        if task is not model.synthesis:
            model = model.model_copy(update={"synthesis": task})
        self.model = model
        self.task = task
        self.variables: Variables = compile_variables(model)
        self.length_unit = unit_factor(model.units.length, "length")
        self.angle_unit = unit_factor(model.units.angle, "angle")
        self._compile_target()
        self._compile_conditions()
        #: both circuits (``circuits``): a sub-problem per combination of variants
        self.circuits = circuit_problems(self)
        self.objective_positions = self._positions_read()
        #: free timing whose objective reads the target inputs only
        self.inputs_only = self.at_inputs and self._reads_targets_only()
        self._turn_check = (compile_turn_check(model) if self.objective_positions is not None
                            or self.inputs_only else None)
        self._exact_share: Array | None = None

    @property
    def q_shown_unit(self) -> str:
        """Q's unit as printed: the target's unit, squared for a sum of squares."""
        if self.target_kind and self.task.objective == "ssq":
            return f"{self.q_unit}²"
        return self.q_unit

    # ---- compiling -------------------------------------------------------------------
    def _length(self, value) -> float:
        return to_si(value, "length", self.model.units.length)

    def _angle(self, value) -> float:
        return to_si(value, "angle", self.model.units.angle)

    def _points(self, items) -> NDArray[np.complex128]:
        return np.array([complex(self._length(x), self._length(y)) for x, y in items])

    def _compile_target(self) -> None:
        task, n = self.task, self.model.positions
        self.target_kind: str | None = None
        self.free_timing = False
        #: shape only (``path.frame``): what the placement on the targets may change
        self.shape: shape.Freedom | None = None
        #: a timed curve: the SI values of argument 1 where its targets are reached, (K,)
        self.timed_inputs: Array | None = None
        self.q_unit = self.model.units.length
        self.weights: Array | None = None
        if task.path is not None:
            path = task.path
            self.target_kind = "path"
            targets = path.targets
            if isinstance(targets, Curve):
                t = np.linspace(*targets.t, targets.count)
                where = ("synthesis", "path", "targets")
                x = np.broadcast_to(evaluate_expression(targets.x, (*where, "x"), t=t), t.shape)
                y = np.broadcast_to(evaluate_expression(targets.y, (*where, "y"), t=t), t.shape)
                self.targets = (x + 1j * y) * self.length_unit
                self.target_positions = None
                if path.timing is True:  # target k where argument 1 = t_k
                    self.timed_inputs = self._argument_si(t)
            elif isinstance(targets, dict):
                self.targets = self._points(targets.values())
                self.target_positions = np.array(list(targets), dtype=np.int64)
            else:
                self.targets = self._points(targets)
                self.target_positions = (np.arange(n + 1, dtype=np.int64)
                                         if path.timing is True else None)
            if path.timing is not True:
                self.target_positions = None
            if path.timing == "free":
                self._compile_free_timing()
            if path.weights is not None:
                self.weights = np.asarray(path.weights, dtype=float)
            self.point = path.point
            if path.frame is not None:  # shape only: the placement is free
                shape.check_frame(self.model)
                self.shape = shape.Freedom.of(path.frame)
        elif task.function is not None:
            fun = task.function
            self.target_kind = "function"
            self.output = fun.output
            kind = "angle" if fun.output[0] == "a" else "length"
            self.q_unit = getattr(self.model.units, kind)
            self.output_factor = unit_factor(self.q_unit, kind)
            positions = np.arange(n + 1)
            if isinstance(fun.target, dict):
                table = {k: to_si(v, kind, self.q_unit) / self.output_factor
                         for k, v in sorted(fun.target.items())}
                self.function_positions = np.array(list(table), dtype=np.int64)
                self.function_target = np.array(list(table.values()))
            else:
                from mechloop.solve.inputs import model_arguments, model_time

                args = model_arguments(self.model, model_time(self.model), strict=False)
                names: dict[str, Array | float] = {"t": positions / n, "pos": positions}
                if 1 in args:
                    from mechloop.model.check import argument_kind

                    akind = argument_kind(self.model, 1)
                    names["x"] = args[1].value / unit_factor(
                        getattr(self.model.units, akind), akind)
                value = evaluate_expression(fun.target, ("synthesis", "function", "target"),
                                            **names)
                self.function_target = np.broadcast_to(value, positions.shape).astype(float)
                self.function_positions = positions
            if fun.relative and self.function_positions[0] != 0:
                raise ModelError([Problem(("synthesis", "function", "target"),
                                          "a relative target needs a value at position 0",
                                          "add position 0 to the table, or set "
                                          "relative: false")])
        elif task.motion is not None:
            mot = task.motion
            self.target_kind = "motion"
            self.point = mot.point
            poses = mot.poses
            items = list(poses.values()) if isinstance(poses, dict) else list(poses)
            self.targets = self._points([(x, y) for x, y, _ in items])
            self.target_angles = np.array([self._angle(a) for _, _, a in items])
            self.target_positions = (np.array(list(poses), dtype=np.int64)
                                     if isinstance(poses, dict) else None)
            if mot.length is not None:
                self.pose_length = self._length(mot.length)
            else:
                span = np.ptp(self.targets.real) + np.ptp(self.targets.imag)
                self.pose_length = float(span) or 1.0
        if self.target_kind is None:  # Q: the weighted sum of the minimized criteria, SI
            minimized = [c for c in task.criteria if c.minimize]
            self.q_unit = "m" if all(c.point is not None for c in minimized) else "SI"

    def _compile_free_timing(self) -> None:
        """Free timing: the target inputs are the last columns of a design; argument 1
        must run one way over the positions, so that its range is the motion."""
        from mechloop.solve.inputs import model_arguments, model_time

        self.free_timing = True
        values = model_arguments(self.model, model_time(self.model), strict=False)[1].value
        steps = np.diff(values)
        if not ((steps >= 0).all() or (steps <= 0).all()) or values[0] == values[-1]:
            raise ModelError([Problem(("arguments", 1), "timing: free needs argument 1 to "
                                      "run one way over the positions (its range is where "
                                      "the targets may be reached)", "give argument 1 a "
                                      "monotonic table or law")])
        span = float(values.max() - values.min())
        angle = self.variables.kind(int(self.variables.input_columns[0])) == "angle" \
            if self.variables.input_columns.size else False
        # an input that turns fully is ordered modulo the turn (the order may start
        # anywhere); any other must simply increase
        self.input_turn = 2 * np.pi if angle and span >= 2 * np.pi * (1 - 1e-9) else None
        self.input_span = span or 1.0

    @property
    def at_inputs(self) -> bool:
        """Whether the targets are solved at inputs of their own (free timing, or a
        timed curve) rather than at the positions."""
        return self.free_timing or self.timed_inputs is not None

    def _argument_si(self, values: Array) -> Array:
        """Values of argument 1 in its model unit -> SI."""
        from mechloop.model.check import argument_kind

        kind = argument_kind(self.model, 1)
        unit = self.model.arguments[1].unit or getattr(self.model.units, kind)
        return np.asarray(values, dtype=float) * unit_factor(unit, kind)

    def order_violation(self, designs: Array) -> Array:
        """How far the free-timing inputs of ``designs`` ``(D, V)`` are out of the
        targets' order, SI, ``(D,)`` (0 in order; ``path.direction`` increasing,
        decreasing, or the lesser of both for either).  Increasing inputs: the sum of the
        backward steps.  An input that turns fully: by how much the forward steps
        (modulo the turn) add up to more than one turn."""
        inputs = designs[:, self.variables.input_columns]
        steps = np.diff(inputs, axis=-1)
        direction = self.task.path.direction
        ways = {"increasing": (steps,), "decreasing": (-steps,),
                "either": (steps, -steps)}[direction]
        return np.minimum.reduce([self._backward(way) for way in ways])

    def _backward(self, steps: Array) -> Array:
        """How far steps ``(D, K - 1)`` fall short of increasing (see
        :meth:`order_violation`), ``(D,)``."""
        if self.input_turn is None:
            return np.maximum(-steps, 0).sum(axis=-1)
        forward = np.mod(steps, self.input_turn).sum(axis=-1)
        return np.maximum(forward - self.input_turn, 0)

    def _compile_conditions(self) -> None:
        task, model = self.task, self.model
        self.pressure_contours: list[tuple[int, str, str, str]] = []
        if task.pressure_angle is not None:
            from mechloop.model.check import require_valid

            structure = require_valid(model)
            chosen = task.pressure_angle.contours
            for info in structure.ordered():
                if chosen is not None and info.number not in chosen:
                    continue
                if info.module == "Pl4":
                    self.pressure_contours.append((info.number, "Pl4", *info.functions))
                elif info.module == "Pl3":
                    u1, u2 = info.functions
                    self.pressure_contours.append((info.number, "Pl3", f"a{u1[1:]}", u2))
            self.pressure_max = self._angle(task.pressure_angle.max)
        self.rotation_max = [self._angle(r.max) for r in task.rotation]
        if task.workspace is not None:
            ws = task.workspace
            if ws.box is not None:
                (x0, y0), (x1, y1) = ws.box
                self.box = (complex(self._length(min(x0, x1)), self._length(min(y0, y1))),
                            complex(self._length(max(x0, x1)), self._length(max(y0, y1))))
                size = abs(self.box[1] - self.box[0])
            else:
                self.polygon = self._points(ws.polygon)
                size = float(np.ptp(self.polygon.real) + np.ptp(self.polygon.imag))
            self.workspace_size = size or 1.0
        self.criterion_keys: list[str] = []  # names in the terms, a repeat numbered
        for crit in task.criteria:
            key, again = crit.label, 2
            while key in self.criterion_keys:
                key, again = f"{crit.label} ({again})", again + 1
            self.criterion_keys.append(key)
        self._kinematic_criteria: dict[int, tuple[str, float]] = {}
        self._dynamic_criteria: list[int] = []
        for i, crit in enumerate(task.criteria):
            if crit.point is not None:
                continue  # a point's coordinate: placed from the batched kinematics
            if _is_parameter(crit.column, model):
                self._kinematic_criteria[i] = _parameter_column(crit.column)
            else:
                self._dynamic_criteria.append(i)
        if self._dynamic_criteria:
            self._check_dynamic_columns()
        # Rates and accelerations are solved for the population only when a criterion
        # reads one (a column d…/dd…); dynamic criteria solve their own kinematics with
        # derivatives in the batched force analysis.
        self.needs_derivatives = any(column.startswith("d") for column, _ in
                                     self._kinematic_criteria.values())

    def _check_dynamic_columns(self) -> None:
        from mechloop.dynamics.analysis import solve_dynamics

        try:
            frame = solve_dynamics(self.model).to_frame()
        except SolveError:
            return  # the model's own design may break; columns are checked per design
        columns = {c.split(" [")[0] for c in frame.columns} | set(CYCLE_VALUES)
        for i in self._dynamic_criteria:
            name = self.task.criteria[i].column
            if name not in columns:
                import difflib

                close = difflib.get_close_matches(name, sorted(columns), n=4)
                raise ModelError([Problem(("synthesis", "criteria", i, "column"),
                                          f"no column {name!r} in the tables of this model",
                                          f"did you mean {', '.join(close)}?" if close else
                                          "see the columns of mechloop solve and energy")])

    def _positions_read(self) -> NDArray[np.int64] | None:
        """The positions the objective reads, sorted, when it reads no others (targets
        with their positions, and no condition or criterion over the motion); else None.
        """
        if not self._reads_targets_only() or self.at_inputs:
            return None
        if self.target_kind in ("path", "motion") and self.target_positions is not None:
            return np.unique(self.target_positions)
        return None

    def _reads_targets_only(self) -> bool:
        """No condition or criterion reads the motion beyond the targets."""
        task = self.task
        return not (task.pressure_angle is not None or task.rotation
                    or task.workspace is not None or task.criteria
                    or self.needs_derivatives or getattr(self, "shape", None) is not None)

    def exact_feasibility(self, designs: Array) -> tuple[NDArray[np.bool_], Array] | None:
        """Whether each design ``(D, V)`` assembles, on one branch, over the whole
        continuous input — decided exactly, not at samples —, ``(D,)``, and the share of
        the input range where it breaks, ``(D,)``; None where no exact decision is
        available for this model without solving every position (then it is decided at
        the positions and between them).

        The decision is :meth:`exists` (:mod:`mechloop.solve.existence`); it needs no
        solved positions where :mod:`mechloop.synthesis.crank_turn` recognizes the model
        (a four-bar driven by its crank, traced points), whose closed form also gives the
        share of the turn where an infeasible design breaks (the search's ranking of
        infeasible designs)."""
        if self._turn_check is None:
            return None
        _, share = self._turn_check(self.variables.overrides(designs), designs.shape[0])
        feasible = self.exists(designs)
        return feasible, np.where(feasible, 0.0, np.maximum(share, 1.0 / 360))

    # ---- evaluating ------------------------------------------------------------------
    def solve(self, designs: Array) -> DesignResults:
        """The kinematics of every design, arrays ``(D, P)``: positions, and rates and
        accelerations only when a criterion needs them (:attr:`needs_derivatives`)."""
        return solve_designs(self.model, self.variables.overrides(designs),
                             derivatives=self.needs_derivatives)

    def place(self, results: DesignResults, designs: Array, point: Point
              ) -> NDArray[np.complex128]:
        """Global position (m, as x + iy) of a point at every position, ``(D, P)``."""
        return _place(self.model, results, self.variables.starts(designs), point)

    def solve_at_inputs(self, designs: Array, positions: ArrayLike | None = None
                        ) -> tuple[DesignResults, DesignResults]:
        """Free timing: the kinematics at the positions, ``(D, P)``, and at each
        design's target inputs, ``(D, K)``, in one call
        (:func:`~mechloop.solve.designs.solve_designs_at`)."""
        inputs = (designs[:, self.variables.input_columns] if self.timed_inputs is None
                  else np.broadcast_to(self.timed_inputs, (designs.shape[0],
                                                           self.timed_inputs.size)))
        return solve_designs_at(self.model, self.variables.overrides(designs), inputs,
                                derivatives=self.needs_derivatives, positions=positions)

    def reached(self, at: DesignResults, designs: Array) -> NDArray[np.complex128]:
        """Free timing: the tracing point (m, x + iy) at each design's target inputs,
        ``(D, K)``: column k is where target k is reached."""
        return self.place(at, designs, self.point)

    def exists(self, designs: Array, samples: DesignResults | None = None
               ) -> NDArray[np.bool_]:
        """The exact mandatory conditions, ``(D,)``: the chain assembles over the whole
        continuous input interval, no link is degenerate
        (:func:`~mechloop.solve.existence.assembles_throughout`, reusing the solved
        ``samples``), and the four-bar type the task asks for (``grashof``,
        ``crank_shortest``)."""
        from mechloop.solve.existence import ExistenceCheck, four_bar_type_holds

        if getattr(self, "_existence", None) is None:
            self._existence = ExistenceCheck(self.model)  # compiled once
        overrides = self.variables.overrides(designs)
        ok = self._existence(overrides, samples=samples).feasible
        if self.task.grashof != "any" or self.task.crank_shortest:
            ok &= four_bar_type_holds(self._existence, overrides, grashof=self.task.grashof,
                                      crank_shortest=self.task.crank_shortest)
        return ok

    def _assess(self, designs: Array, *, continuous: bool = False
                ) -> tuple[DesignResults, NDArray[np.bool_], Array | None,
                           dict[str, Array], dict[str, Array]]:
        """Solve a population and compute what both :meth:`evaluate` and
        :meth:`residuals` need: the results, the mandatory conditions, the weighted
        deviations ``(D, K)`` (NaN rows where a design does not assemble; None without a
        target), and the penalty terms and measures.  With free timing a design must
        also assemble, on the same branch, at its target inputs, and ``self._reached``
        keeps the points there for :meth:`residuals`."""
        terms: dict[str, Array] = {}
        measures: dict[str, Array] = {}
        if self.at_inputs:
            exact = self.exact_feasibility(designs) if self.inputs_only else None
            if exact is None:
                res, at = self.solve_at_inputs(designs)
                feasible = res.assembles & res.keeps_variant & at.assembles & at.keeps_variant
                feasible = feasible & self.exists(designs, res)
            else:  # position 0 and the target inputs, and the exact check
                res, at = self.solve_at_inputs(designs, positions=[0])
                feasible = exact[0] & res.assembles & at.assembles & at.keeps_variant
        else:
            exact = (self.exact_feasibility(designs) if self.objective_positions is not None
                     else None)
            if exact is None:  # every position, decided at them and between them
                res = self.solve(designs)
                feasible = res.assembles & res.keeps_variant & self.exists(designs, res)
            else:  # the positions the objective reads, and the exact check
                res = solve_designs(self.model, self.variables.overrides(designs),
                                    derivatives=False, positions=self.objective_positions)
                feasible = exact[0] & res.assembles & res.keeps_variant
        self._exact_share = None if exact is None else exact[1]
        dev = None
        if self.target_kind:
            rows = np.flatnonzero(feasible)  # deviations of designs that assemble only
            dev = np.full((designs.shape[0], self._target_count()), np.nan)
            if self.at_inputs:
                self._reached = np.full(dev.shape, np.nan, dtype=complex)
                if rows.size:
                    self._reached[rows] = self.reached(at.subset(rows), designs[rows])
                dev = np.abs(self._reached - self.targets[None, :]) / self.length_unit
            elif rows.size:
                dev[rows] = self.deviations(res.subset(rows), designs[rows],
                                            continuous=continuous)
            if self.weights is not None:
                dev = dev * self.weights[None, :]
        if self.free_timing and self.task.path.ordered:
            overlap = self.order_violation(designs)
            factor = unit_factor(self.variables.units[self.variables.input_columns[0]],
                                 self.variables.kind(int(self.variables.input_columns[0])))
            measures["order"] = overlap / factor
            terms["order"] = 1000.0 * overlap / self.input_span
        self._desirable(res, designs, terms, measures)
        self._criteria(res, designs, feasible, terms, measures)
        return res, feasible, dev, terms, measures

    def _target_count(self) -> int:
        if self.target_kind == "function":
            return self.function_positions.size
        return self.targets.size

    def evaluate(self, designs: Array, *, continuous: bool = False,
                 threads: int | None = None) -> Evaluation:
        """Every term for the population ``designs`` (SI, shape ``(D, V)``).

        ``continuous``: a path without timing measures each target's distance to the
        continuous curve (:mod:`mechloop.synthesis.continuous`; ~30 solves more), not to
        the polyline through the positions: the error of the design as it really moves,
        for the reported result.  ``threads``: evaluate the designs in that many shares,
        each in a thread of its own (the same result); None chooses by the population's
        size and the idle cores (:mod:`mechloop.synthesis.cores`), 1 evaluates here."""
        designs = np.atleast_2d(np.asarray(designs, dtype=float))
        if threads is None:
            threads = 1 if continuous else cores.evaluation_threads(
                designs.shape[0], cores.columns_of(self))
        if threads > 1 and designs.shape[0] >= threads:
            return cores.evaluate_shares(self, designs, threads,
                                         continuous=continuous)
        if self.circuits:  # the better circuit of each design
            return evaluate_best(self.circuits, designs, continuous=continuous)[0]
        res, feasible, dev, terms, measures = self._assess(designs, continuous=continuous)
        n_designs = designs.shape[0]
        broken_share = (res.broken.mean(axis=-1) if self._exact_share is None
                        else np.maximum(self._exact_share, res.broken.mean(axis=-1)))
        keeps = res.keeps_variant
        penalty = sum(terms.values()) if terms else np.zeros(n_designs)
        if dev is None:  # no target: Q is the weighted sum of the minimized criteria
            q = sum((c.minimize * measures[key] for c, key in zip(
                self.task.criteria, self.criterion_keys, strict=True) if c.minimize),
                np.zeros(n_designs))
            total = penalty
        else:
            q = dv.reduce_deviation(dev, self.task.objective)
            with np.errstate(invalid="ignore"):
                total = q + penalty
        bad = ~feasible | ~np.isfinite(total)
        total = np.where(bad, INFEASIBLE * (1.0 + broken_share + (~keeps)), total)
        feasible = feasible & ~bad
        return Evaluation(total=total, q=np.where(feasible, q, np.nan), feasible=feasible,
                          broken_share=broken_share, keeps_variant=keeps, terms=terms,
                          measures=measures)

    def residuals(self, designs: Array, *, continuous: bool = False) -> Array:
        """Deviations (weighted) and the square roots of the penalties, ``(D, K + T)``,
        for a least-squares polish; an infeasible design gets a large constant row.

        A path with timing (given or free) gives the x and y errors of each target
        instead of its distance, ``(D, 2K + T)``: the same sum of squares, but smooth where
        a distance is zero, so the polish does not stall with fewer targets than
        variables.  ``continuous``: distances to the continuous curve, as
        :meth:`evaluate` (a path without timing; ~10-30 solves more per call)."""
        designs = np.atleast_2d(np.asarray(designs, dtype=float))
        if self.circuits:
            return residuals_best(self.circuits, designs, continuous=continuous)
        res, feasible, dev, terms, _ = self._assess(designs, continuous=continuous)
        if dev is not None and self.at_inputs:
            error = (self._reached - self.targets[None, :]) / self.length_unit
            if self.weights is not None:
                error = error * self.weights[None, :]
            dev = np.concatenate([error.real, error.imag], axis=1)
        elif dev is not None and self.target_kind == "path" and \
                self.target_positions is not None:
            z = self.place(res, designs, self.point)[:, res.columns(self.target_positions)]
            error = (z - self.targets[None, :]) / self.length_unit
            if self.weights is not None:
                error = error * self.weights[None, :]
            dev = np.concatenate([error.real, error.imag], axis=1)
        parts = [] if dev is None else [dev]
        parts += [np.sqrt(np.maximum(t, 0))[:, None] for t in terms.values()]
        out = np.concatenate(parts, axis=1) if parts else np.zeros((designs.shape[0], 1))
        bad = ~feasible | ~np.isfinite(out).all(axis=1)
        out[bad] = 1e6
        return out

    def deviations(self, results: DesignResults, designs: Array, *,
                   continuous: bool = False) -> Array:
        """Deviations from the targets, ``(D, K)``, in the model's units.

        With free timing ``results`` are those at the target inputs (the second of
        :meth:`solve_at_inputs`): the distance from target k to the point at its input."""
        kind = self.target_kind
        if kind == "path" and self.at_inputs:
            return np.abs(self.reached(results, designs) - self.targets[None, :]) / \
                self.length_unit
        if kind == "path":
            z = self.place(results, designs, self.point)
            if self.shape is not None:  # after the best placement on the targets
                a, b, dev = shape.fit_placement(
                    z, self.targets, self.shape, self.weights,
                    fine=shape.PRECISE if continuous else shape.FINE)
                if continuous:  # the targets in the mechanism's frame, and back
                    dev = curve_distance(self, designs, z, (self.targets[None, :] -
                                                            b[:, None]) / a[:, None])
                    dev = dev * np.abs(a)[:, None]
            elif self.target_positions is None and continuous:
                dev = curve_distance(self, designs, z, self.targets)
            elif self.target_positions is None:
                dev = dv.distance_to_curve(z, self.targets)
            else:
                dev = dv.distance_at_positions(z, self.targets,
                                               results.columns(self.target_positions))
            return dev / self.length_unit
        if kind == "motion":
            z = self.place(results, designs, self.point)
            angle = results.values[self.task.motion.angle]
            dev = dv.pose_error(z, angle, self.targets, self.target_angles, self.pose_length,
                                None if self.target_positions is None
                                else results.columns(self.target_positions))
            return dev / self.length_unit
        output = results.values[self.output][:, results.columns(self.function_positions)] \
            / self.output_factor
        return dv.function_error(output, self.function_target,
                                 relative=self.task.function.relative)

    def _desirable(self, res: DesignResults, designs: Array, terms: dict[str, Array],
                   measures: dict[str, Array]) -> None:
        task = self.task
        if task.pressure_angle is not None and self.pressure_contours:
            worst = np.zeros(designs.shape[0])
            for _, module, first, second in self.pressure_contours:
                theta = np.mod(res.values[first] - res.values[second], np.pi)
                between = np.minimum(theta, np.pi - theta)  # angle between the two lines
                angle = between if module == "Pl3" else np.pi / 2 - between
                worst = np.maximum(worst, np.nanmax(np.where(np.isnan(angle), 0, angle),
                                                    axis=-1))
            measures["pressure_angle"] = worst / self.angle_unit
            excess = np.maximum(worst - self.pressure_max, 0) / self.pressure_max
            terms["pressure_angle"] = task.pressure_angle.weight * excess
        for i, rot in enumerate(task.rotation):
            rel = res.values[rot.between[0]] - res.values[rot.between[1]]
            swing = np.nanmax(rel, axis=-1) - np.nanmin(rel, axis=-1)
            key = f"rotation {rot.between[0]}-{rot.between[1]}"
            measures[key] = swing / self.angle_unit
            terms[key] = rot.weight * np.maximum(swing - self.rotation_max[i], 0) / \
                self.rotation_max[i]
        if task.workspace is not None:
            ws = task.workspace
            worst = np.zeros(designs.shape[0])
            for point in ws.points:
                z = self.place(res, designs, point)
                out = (dv.box_outside(z, *self.box) if ws.box is not None
                       else dv.polygon_outside(z, self.polygon))
                worst = np.maximum(worst, np.nanmax(np.nan_to_num(out), axis=-1))
            measures["workspace"] = worst / self.length_unit
            terms["workspace"] = ws.weight * worst / self.workspace_size

    def _criteria(self, res: DesignResults, designs: Array, feasible: NDArray[np.bool_],
                  terms: dict[str, Array], measures: dict[str, Array]) -> None:
        n_designs = designs.shape[0]
        tables = self._dynamic_tables(res, designs, feasible)
        for i, crit in enumerate(self.task.criteria):
            if crit.point is not None:
                z = self.place(res, designs, crit.point)
                value = _reduce(z.real if crit.coordinate == "x" else z.imag, crit.reduce)
            elif i in self._kinematic_criteria:
                name, factor = self._kinematic_criteria[i]
                table = _parameter_table(res, name) * factor
                value = _reduce(table, crit.reduce)
            elif tables is not None:  # a cycle's number is one per design already
                value = (tables[crit.column] if crit.column in CYCLE_VALUES
                         else _reduce(tables[crit.column], crit.reduce))
            else:  # the batch refused (NotImplementedError, KeyError): design by design
                value = np.full(n_designs, np.nan)
                for d in np.flatnonzero(feasible):
                    value[d] = self._dynamic_value(designs[d], crit)
            key = self.criterion_keys[i]
            measures[key] = value
            term = np.zeros(n_designs)
            scale = _criterion_scale(crit)
            if crit.max is not None:
                limit = _in_column_units(crit.max)
                term = term + crit.weight * np.maximum(value - limit, 0) / scale
            if crit.min is not None:
                limit = _in_column_units(crit.min)
                term = term + crit.weight * np.maximum(limit - value, 0) / scale
            if crit.minimize is not None:
                term = term + crit.minimize * value
            terms[key] = term

    def _dynamic_tables(self, res: DesignResults, designs: Array,
                        feasible: NDArray[np.bool_]) -> dict[str, Array] | None:
        """The columns of the dynamic criteria for the feasible designs in one batched
        force analysis, ``{column: (D, P)}`` (``(D,)`` for a cycle's number; NaN for the
        other designs); None where the batch refuses (:class:`NotImplementedError`, which
        it raises for nothing today) or lacks a column, so the caller solves design by
        design."""
        if not self._dynamic_criteria:
            return {}
        from mechloop.synthesis.dynamic_batch import dynamic_columns

        rows = np.flatnonzero(feasible)
        columns = [self.task.criteria[i].column for i in self._dynamic_criteria]
        try:
            found = dynamic_columns(self, designs[rows], columns,
                                    kinematics=res.subset(rows) if res.derivatives
                                    else None)
        except (NotImplementedError, KeyError):
            return None
        tables = {}
        for name, table in found.items():
            tables[name] = np.full((designs.shape[0], *table.shape[1:]), np.nan)
            tables[name][rows] = table
        return tables

    def _dynamic_value(self, design: Array, crit: Criterion) -> float:
        """One design's criterion value by its own ``solve_dynamics`` (NaN when that
        raises :class:`SolveError`): the oracle and fallback of the batch."""
        from mechloop.dynamics.analysis import solve_dynamics
        from mechloop.synthesis.dynamic_batch import cycle_value

        model = self.design_model(design)
        try:
            result = solve_dynamics(model)
        except SolveError:
            return math.nan
        if crit.column in CYCLE_VALUES:
            return float(cycle_value(result, crit.column))
        frame = result.to_frame()
        columns = {c.split(" [")[0]: c for c in frame.columns}
        if crit.column not in columns:
            return math.nan
        column = frame[columns[crit.column]].to_numpy(dtype=float)
        return float(_reduce(column[None, :], crit.reduce)[0])

    def design_model(self, design: Array) -> Model:
        """The model with one design's values (SI, shape ``(V,)``) written in (and its
        better circuit, with ``circuits``)."""
        own = self.for_design(design)
        if own is not self:
            return own.design_model(design).model_copy(update={"synthesis": self.task})
        model = apply_design(self.model, self.variables.to_model_units(np.asarray(design)))
        if self.shape is not None:  # placed on the targets
            a, b = self.placement(np.atleast_2d(design))
            model = shape.place_model(model, complex(a[0]), complex(b[0]))
        return model

    def placement(self, designs: Array) -> tuple[NDArray[np.complex128],
                                                 NDArray[np.complex128]]:
        """Shape only: the similarity ``w = a·z + b`` that places each design's traced
        curve on the targets, complex ``(D,)`` each (``a = 1, b = 0`` without
        ``path.frame``)."""
        n = designs.shape[0]
        if self.shape is None:
            return np.ones(n, complex), np.zeros(n, complex)
        if self.circuits:  # each design on its better circuit
            choice = evaluate_best(self.circuits, designs)[1]
            a, b = np.ones(n, complex), np.zeros(n, complex)
            for c, (_, sub) in enumerate(self.circuits):
                rows = np.flatnonzero(choice == c)
                if rows.size:
                    a[rows], b[rows] = sub.placement(designs[rows])
            return a, b
        z = self.place(self.solve(designs), designs, self.point)
        a, b, _ = shape.fit_placement(z, self.targets, self.shape, self.weights,
                                      fine=shape.PRECISE)
        return a, b

    def for_design(self, design: Array) -> SynthesisProblem:
        """The problem on which ``design`` ``(V,)`` is scored: itself, or with
        ``circuits`` the sub-problem of the design's better circuit (to solve or plot
        the design as it is)."""
        if not self.circuits:
            return self
        choice = evaluate_best(self.circuits, np.atleast_2d(design))[1]
        return self.circuits[int(choice[0])][1]


def _is_parameter(column: str, model: Model) -> bool:
    name = column[2:] if column.startswith("dd") else column[1:] if column.startswith(
        "d") else column
    return (len(name) > 1 and name[0] in "ra" and name[1:].isdigit()
            and int(name[1:]) in model.vectors)


def _parameter_column(column: str) -> tuple[str, float]:
    """(column, factor to the table's unit): angles are shown in degrees."""
    bare = column.lstrip("d")
    return column, (180 / np.pi if column == bare and bare[0] == "a" else 1.0)


def _parameter_table(res: DesignResults, column: str) -> Array:
    if column.startswith("dd"):
        return res.accels[column[2:]]
    if column.startswith("d"):
        return res.rates[column[1:]]
    return res.values[column]


def _reduce(table: Array, how: str) -> Array:
    """One number per row of ``table`` (D, P); NaN for a row of NaN (a broken design)."""
    with np.errstate(invalid="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # all-NaN rows
        if how == "max":
            return np.nanmax(table, axis=-1)
        if how == "min":
            return np.nanmin(table, axis=-1)
        if how == "absmax":
            return np.nanmax(np.abs(table), axis=-1)
        if how == "mean":
            return np.nanmean(table, axis=-1)
        if how == "rms":
            return np.sqrt(np.nanmean(table * table, axis=-1))
        return np.nanmax(table, axis=-1) - np.nanmin(table, axis=-1)


def _in_column_units(value) -> float:
    """A limit in the column's table unit; a quantity string is converted to SI base units
    (the tables' units, except angles, which the tables show in degrees)."""
    if isinstance(value, str):
        qty = registry().Quantity(value)
        if qty.dimensionless and not qty.unitless:
            return float(qty.to("deg").magnitude)
        return float(qty.to_base_units().magnitude)
    return float(value)


def _criterion_scale(crit: Criterion) -> float:
    limits = [abs(_in_column_units(v)) for v in (crit.max, crit.min) if v is not None]
    return max(limits) if limits and max(limits) > 0 else 1.0


def _place(model: Model, res: DesignResults, starts: dict[int, tuple], point: Point
           ) -> NDArray[np.complex128]:
    """Tail or head of a vector in the plane for every design, as in
    :class:`mechloop.dynamics.points.Placement` (contours laid from their starts).

    Only the vectors on the way to ``point`` are laid (each once), in the order of the
    contours, so the sums are the same as when every contour is laid."""
    contour_of = {v: i for i, c in enumerate(model.contours) for v in c.vectors}
    shape = res.broken.shape
    units = unit_factor(model.units.length, "length")
    for index in range(len(model.contours)):  # a cycle of starts is an error anywhere
        seen: list[int] = []
        while index not in seen:
            seen.append(index)
            start = model.contours[index].start
            if isinstance(start, str | tuple | list):
                break
            index = contour_of[start.head if isinstance(start, HeadPoint) else start.tail]
        else:
            raise ModelError([Problem(("contours", index, "start"),
                                      "the starts of contours refer to each other in a cycle",
                                      "start one of them at the origin or at [x, y]")])
    vectors: dict[int, NDArray[np.complex128]] = {}
    tails: dict[int, NDArray[np.complex128]] = {}

    def vector(n: int) -> NDArray[np.complex128]:
        if n not in vectors:
            r, a = res.values[f"r{n}"], res.values[f"a{n}"]
            out = np.empty(shape, dtype=complex)
            out.real = r * np.cos(a)
            out.imag = r * np.sin(a)
            vectors[n] = out
        return vectors[n]

    def first_tail(index: int) -> NDArray[np.complex128]:
        start = model.contours[index].start
        if isinstance(start, str):
            return np.zeros(shape, dtype=complex)
        if isinstance(start, tuple | list):
            x = np.full(shape[0], float(start[0]) * units if not isinstance(start[0], str)
                        else to_si(start[0], "length", model.units.length))
            y = np.full(shape[0], float(start[1]) * units if not isinstance(start[1], str)
                        else to_si(start[1], "length", model.units.length))
            vx, vy = starts.get(index + 1, (None, None))
            x = x if vx is None else vx
            y = y if vy is None else vy
            return np.broadcast_to((x + 1j * y)[:, None], shape)
        if isinstance(start, HeadPoint):
            return tail(start.head) + vector(start.head)
        return tail(start.tail)

    def tail(n: int) -> NDArray[np.complex128]:
        if n not in tails:
            contour = model.contours[contour_of[n]].vectors
            i = contour.index(n)
            tails[n] = (tail(contour[i - 1]) + vector(contour[i - 1]) if i
                        else first_tail(contour_of[n]))
        return tails[n]

    if isinstance(point, HeadPoint):
        return tail(point.head) + vector(point.head)
    return tail(point.tail)


__all__ = ["INFEASIBLE", "Evaluation", "SynthesisProblem", "evaluate_expression"]
