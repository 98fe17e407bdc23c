"""The synthesis task of a model file (``synthesis:``): what to vary, what to reach, what
to respect, and how to search (seed 002, part 2; KDAM's "parametric synthesis" panel).

Numbers are in the model's units (``units``) unless written with their own unit.  Checks
that need the model (does ``r9`` exist, is it a constant) live in :func:`check_synthesis`
and run with the rest of the model's checks, so a bad task is reported with its place in
the file before any search starts.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Annotated, Literal

from pydantic import Field, model_validator

from mechloop.errors import Problem
from mechloop.model.dynamic import HeadPoint, TailPoint
from mechloop.model.signals import Number, Scalar, _Frozen
from mechloop.model.units import UnitProblem, to_si

if TYPE_CHECKING:
    from mechloop.model.schema import Model

VARIABLE = re.compile(r"^(?:[ra][1-9][0-9]*|start[1-9][0-9]*\.[xy])$")
ParamName = Annotated[str, Field(pattern=r"^[ra][1-9][0-9]*$")]
Point = TailPoint | HeadPoint
TARGET = re.compile(r"^(?:[ra][1-9][0-9]*|(?:start|v)[1-9][0-9]*\.[xy])$")


class Tie(_Frozen):
    """A constant that a named dimension sets: ``factor · value + shift`` (the target's
    model units).  A constant that several dimensions set is the sum of their terms."""

    set: str = Field(pattern=TARGET.pattern, description="'r3' / 'a5' (a constant, a "
                     "link's delta, an argument's offset), 'start2.x' (a contour's fixed "
                     "start) or 'v4.x' / 'v4.y' (a component of the constant vector 4: "
                     "its r and a follow)")
    factor: Number = Field(1.0, description="how much the target moves per unit of the "
                          "dimension")
    shift: Number = Field(0.0, description="added to the target (the target's model units)")


class Dimension(_Frozen):
    """A named design variable that moves several constants of the model together (a model
    built from Assur groups writes one per varied dimension, e.g. a link length that two
    vectors carry, or a ground point's x that moves a frame vector and a contour start)."""

    value: Number = Field(description="the dimension's value in the model (model units)")
    sets: list[Tie] = Field(min_length=1, description="the constants it sets")


CYCLE_VALUES = {
    "efficiency": "summary.efficiency",
    "loss_coefficient": "summary.loss_coefficient",
    "delta": "cycle.motion.delta",
    "flywheel": "cycle.flywheel",
    "constant_load": "cycle.constant_load",
}
"""Criteria on one number of the cycle (as mechloop energy and solve print), not on a
column: the name in a criterion and its field of
:class:`~mechloop.dynamics.analysis.DynamicResults` — of the energy ``summary``, or of the
machine's ``cycle`` (``machine:``): the coefficient of speed fluctuation without a
flywheel, the flywheel inertia for the wanted ``delta``, the constant load on the input
that balances the cycle (NaN without them)."""


def point_label(point: Point) -> str:
    """``'head 11'`` or ``'tail 3'``."""
    return f"head {point.head}" if isinstance(point, HeadPoint) else f"tail {point.tail}"


class Curve(_Frozen):
    """Target points given by parametric equations ``x(t)``, ``y(t)`` (length units)."""

    x: str = Field(description="expression in t, e.g. '20'")
    y: str = Field(description="expression in t, e.g. '20 + 25*t'")
    t: tuple[Number, Number] = Field((0.0, 1.0), description="range of the parameter t")
    count: int = Field(10, ge=2, description="number of target points")


class Frame(_Frozen):
    """Which parts of the targets' placement a shape-only path task leaves free: the
    mechanism is compared with the targets after the best similarity transform of this
    kind (:mod:`mechloop.synthesis.shape`), and the written model is placed on them."""

    translate: bool = Field(True, description="the targets' position is free")
    rotate: bool = Field(True, description="the targets' orientation is free")
    scale: bool = Field(True, description="the targets' size is free")


class PathTask(_Frozen):
    """Path generation: a point of the mechanism passes through target points.

    Without ``timing`` (class 3) the deviation of a target is its distance to the nearest
    point of the traced curve; with ``timing`` (class 4) the target ``k`` is reached at the
    position given for it, and the deviation is the distance to the point there, times
    its weight E_k.  With ``timing: free`` the input (argument 1, model units) at which
    each target is reached is a design variable of its own (``input@target1`` ...,
    bounded by the argument's range over the positions), and the deviation is the
    distance to the point solved at that input; with ``ordered`` (the default) the
    inputs must follow the targets' order (increasing, modulo a turn for an input that
    turns fully), and a design out of order is penalized by the overlap; ``direction``
    lets them decrease instead (``decreasing``) or either way (``either``).

    A parametric ``Curve`` with ``timing: true`` places target k at ``t_k`` (``count``
    values evenly over ``t``), reached where argument 1 equals ``t_k`` (model units of
    the argument): solved exactly there, not at the nearest position.

    ``frame`` (no timing): shape only; the deviation is measured after the best
    placement of the traced curve on the targets (see :class:`Frame`).
    """

    point: Point = Field(description="the tracing point: {head: K} or {tail: K}")
    targets: list[tuple[Scalar, Scalar]] | dict[int, tuple[Scalar, Scalar]] | Curve = Field(
        description="target points [[x, y], ...]; with timing a mapping position -> [x, y] "
        "(or a list, one per position); or a parametric curve")
    timing: bool | Literal["free"] = Field(
        False, description="targets are reached at given positions (true), anywhere on "
        "the curve (false), or at inputs that the synthesis chooses (free)")
    ordered: bool = Field(True, description="with timing: free, the inputs of the "
                          "targets follow the targets' order (within one turn)")
    direction: Literal["increasing", "decreasing", "either"] = Field(
        "increasing", description="with timing: free and ordered, the inputs of the "
        "targets increase in the targets' order, decrease, or either (the better of the "
        "two: the crank may turn either way)")
    frame: Frame | Literal["free"] | None = Field(
        None, description="shape only: the targets' position (translate), orientation "
        "(rotate) and size (scale) are free; 'free' frees all three. Without timing")
    weights: list[Number] | None = Field(None, description="E_k: a weight per target")


class FunctionTask(_Frozen):
    """Function generation: an output parameter follows a function of the input.

    A rotating output (class 1) is an angle ``aK``, a sliding output (class 2) a length
    ``rK``.  The target is given per position (``table``) or as an expression of ``t``
    (0 at position 0, 1 at position N), of ``x`` (argument 1 in model units) and ``pos``,
    in the output's model units.  With ``relative`` (the default) increments from
    position 0 are compared, so the output's starting value is free.
    """

    output: ParamName = Field(description="the output parameter, e.g. 'a3' or 'r4'")
    target: str | dict[int, Scalar] = Field(
        description="expression, e.g. '60*log10(1 + 9*t)', or a table position -> value")
    relative: bool = Field(True, description="compare increments from position 0")


class MotionTask(_Frozen):
    """Motion generation: a body passes through poses (x, y of a point, angle of a vector).

    Poses are a mapping position -> [x, y, angle] (with timing) or a list (each pose
    compared with the nearest position).  The angle error is weighted by ``length``
    (length units per radian; default: the size of the targets) to add to the distance.
    """

    point: Point
    angle: ParamName = Field(description="a vector fixed in the guided body, e.g. 'a2'")
    poses: list[tuple[Scalar, Scalar, Scalar]] | dict[int, tuple[Scalar, Scalar, Scalar]]
    length: Scalar | None = None


class PressureAngle(_Frozen):
    """Pressure angle in the L1/L2 groups (Pl4 and Pl3 contours) at most ``max``."""

    max: Scalar = Field(description="allowed pressure angle (angle units), e.g. 40")
    contours: list[int] | None = Field(None, description="contours to check (all Pl3/Pl4)")
    weight: Number = 1000.0


class Rotation(_Frozen):
    """Relative rotation of two bodies (rubber-bushed joint): range of ``aI − aJ`` over the
    cycle at most ``max``."""

    between: tuple[ParamName, ParamName]
    max: Scalar
    weight: Number = 1000.0


class Workspace(_Frozen):
    """Points stay inside a box ``[[x0, y0], [x1, y1]]`` or a polygon at every position."""

    points: list[Point]
    box: tuple[tuple[Scalar, Scalar], tuple[Scalar, Scalar]] | None = None
    polygon: list[tuple[Scalar, Scalar]] | None = None
    weight: Number = 1000.0

    @model_validator(mode="after")
    def _one_shape(self) -> Workspace:
        if (self.box is None) == (self.polygon is None):
            raise ValueError("give either box or polygon")
        return self


Reduction = Literal["max", "min", "absmax", "mean", "rms", "range"]


class Criterion(_Frozen):
    """A user criterion on any computed column, kinematic or dynamic (e.g. M_bal), or on a
    coordinate of a point of the mechanism (``point`` with ``coordinate``).

    ``reduce`` turns the column into one number per design; with ``max`` / ``min`` it is a
    limit (penalized beyond it), with ``minimize`` a term added to Q with that weight.
    Values are in the column's SI unit (a coordinate in m) unless written with a unit
    ('200 N*m', '5 mm').
    """

    column: str | None = Field(None, description="a column of mechloop solve's table, "
                               "e.g. 'a3', 'dr4', 'M_bal', 'RJ0_1', or a number of the "
                               "cycle: 'efficiency', 'loss_coefficient', and with machine: "
                               "'delta', 'flywheel', 'constant_load'")
    point: Point | None = Field(None, description="or a point: {head: K} or {tail: K}")
    coordinate: Literal["x", "y"] | None = Field(None, description="x or y of the point")
    reduce: Reduction = "absmax"
    max: Scalar | None = None
    min: Scalar | None = None
    minimize: Number | None = Field(None, description="weight of the reduced value in Q")
    weight: Number = 1000.0

    @model_validator(mode="after")
    def _column_or_point(self) -> Criterion:
        if (self.column is None) == (self.point is None):
            raise ValueError("give either column or point (with coordinate)")
        if self.point is not None and self.coordinate is None:
            raise ValueError("a point criterion needs coordinate: x or y")
        return self

    @property
    def label(self) -> str:
        """The criterion's name in reports: ``'range x(head 11)'``, ``'max F_bal'``."""
        if self.column in CYCLE_VALUES:
            return self.column  # one number per design: nothing to reduce
        if self.point is None:
            return f"{self.reduce} {self.column}"
        return f"{self.reduce} {self.coordinate}({point_label(self.point)})"


class Search(_Frozen):
    """Search strategy and stopping rules."""

    method: Literal["auto", "de", "cmaes", "multistart"] = Field(
        "auto", description="auto (chosen by the problem, measured on the bundled "
        "four-bar path problems: multistart where the coupler-curve atlas applies, CMA-ES "
        "on another timed path, DE otherwise), de, cmaes or multistart")
    seed: int | None = 1
    population: int = Field(40, ge=4, description="designs per generation")
    iterations: int = Field(300, ge=1, description="generations at most")
    good_enough: Scalar | None = Field(None, description="stop when Q is at most this")
    patience: int | None = Field(60, ge=1, description="stop after this many generations "
                                 "without improvement")
    time: Number | None = Field(None, gt=0, description="time budget, s")
    polish: bool = Field(True, description="polish the best design by a local search")
    starts: int = Field(8, ge=1, description="multistart: local searches")
    atlas: bool = Field(True, description="add starting designs from the atlas of four-bar "
                        "coupler curves where the task is a four-bar path problem it applies "
                        "to and no start is given (see mechloop.synthesis.atlas)")
    start: dict[str, Scalar] | list[dict[str, Scalar]] | None = Field(
        None, description="starting design(s), e.g. a classical solution: {r1: 52.3, a1: "
        "40} or a list of them; names of vary, values in the model's units within the "
        "bounds; a variable left out takes the model's own value. Each is evaluated "
        "first; DE puts them into its first population, CMA-ES starts from the best, "
        "multistart runs its first local searches from them. Default: the model's own "
        "design")


class SynthesisTask(_Frozen):
    """What a synthesis varies, reaches and respects, and how it searches."""

    vary: dict[str, tuple[Scalar, Scalar] | Literal["periodic"]] = Field(
        description="design variables with their bounds [low, high]: constants of the model "
        "('r3' / 'a5': a constant, a link's delta, an argument's offset; 'start2.x' / "
        "'start2.y': the fixed start of contour 2) or names of 'dimensions'; an angle "
        "may be 'periodic' (any value, no bound at 0/360 deg), as is an angle whose "
        "bounds span a full turn")
    circuits: Literal["given", "both"] | list[int] = Field(
        "given", description="assembly circuits: the contours' own variants (given), "
        "or the synthesis chooses the better variant per design for every contour with "
        "two (both) or for the listed contours")
    dimensions: dict[str, Dimension] = Field(
        default_factory=dict, description="named dimensions that set several constants "
        "together (written by the builder of a model made of Assur groups)")
    path: PathTask | None = None
    function: FunctionTask | None = None
    motion: MotionTask | None = None
    objective: Literal["max", "rms", "ssq"] = Field(
        "max", description="Q: max |deviation|, RMS, or the sum of squares")
    pressure_angle: PressureAngle | None = None
    rotation: list[Rotation] = Field(default_factory=list)
    workspace: Workspace | None = None
    criteria: list[Criterion] = Field(default_factory=list)
    grashof: Literal["any", "grashof", "crank-rocker", "double-crank", "double-rocker",
                     "non-grashof"] = Field(
        "any", description="mandatory type of the crank-driven four-bar (checked exactly): "
        "'grashof' s + l <= p + q; 'crank-rocker' Grashof with the crank shortest; "
        "'double-crank' Grashof with the frame shortest; 'double-rocker' Grashof with the "
        "coupler shortest; 'non-grashof' s + l > p + q")
    crank_shortest: bool = Field(False, description="mandatory: the driven crank is the "
                                 "shortest link of its four-bar")
    search: Search = Search()

    @model_validator(mode="after")
    def _one_task(self) -> SynthesisTask:
        tasks = [t for t in (self.path, self.function, self.motion) if t is not None]
        if len(tasks) > 1:
            raise ValueError("give one task: path, function or motion")
        if not tasks and not any(c.minimize for c in self.criteria):
            raise ValueError("give a task (path, function or motion) or a criterion to "
                             "minimize")
        return self


def check_synthesis(model: Model) -> list[Problem]:
    """Problems of the model's synthesis task that need the model to be seen."""
    from mechloop.model.structure import is_function

    task = model.synthesis
    if task is None:
        return []
    problems: list[Problem] = []
    base = ("synthesis",)
    starts = {i + 1: c.start for i, c in enumerate(model.contours)}

    def vector_of(name: str) -> int | None:
        number = int(name[1:])
        return number if number in model.vectors else None

    def check_constant(name: str, path: tuple) -> None:
        """``name`` ('r3', 'a5', 'start2.x', 'v4.x') is a constant a design can set."""
        if name.startswith("start"):
            number = int(name[5:].split(".")[0])
            if number not in starts:
                problems.append(Problem(path, f"there is no contour {number}",
                                        f"contours are 1..{len(starts)}"))
            elif not isinstance(starts[number], tuple):
                problems.append(Problem(path, f"contour {number} does not start at fixed "
                                        "coordinates", "give it start: [x, y] to vary them"))
        elif name[0] == "v":
            number = int(name[1:].split(".")[0])
            vector = model.vectors.get(number)
            if vector is None:
                problems.append(Problem(path, f"there is no vector {number}",
                                        f"vectors are {sorted(model.vectors)}"))
            elif not all(isinstance(p, int | float | str) and not is_function(p)
                         for p in (vector.r, vector.a)):
                problems.append(Problem(path, f"{name} needs vector {number} with a constant "
                                        "length and angle",
                                        f"set r{number} and a{number} themselves instead"))
        else:
            number = vector_of(name)
            if number is None:
                problems.append(Problem(path, f"there is no vector {name[1:]}",
                                        f"vectors are {sorted(model.vectors)}"))
                return
            role = model.vectors[number].r if name[0] == "r" else model.vectors[number].a
            if is_function(role):
                problems.append(Problem(path, f"{name} is a function of its contour, "
                                        "not a dimension", "vary a constant, a link's delta "
                                        "or an argument's offset"))

    set_by: dict[str, str] = {}
    for name, dim in task.dimensions.items():
        kinds = {_target_kind(tie.set) for tie in dim.sets}
        if len(kinds) > 1:
            problems.append(Problem((*base, "dimensions", name, "sets"), f"dimension {name!r} "
                                    "sets both lengths and angles", "give it targets of "
                                    "one kind"))
        for i, tie in enumerate(dim.sets):
            check_constant(tie.set, (*base, "dimensions", name, "sets", i, "set"))
            set_by.setdefault(tie.set, name)
    for name, bounds in task.vary.items():
        path = (*base, "vary", name)
        low, high = (0.0, 1.0) if bounds == "periodic" else bounds
        if bounds == "periodic" and _target_kind(
                task.dimensions[name].sets[0].set if name in task.dimensions else name
        ) != "angle":
            problems.append(Problem(path, f"{name} is a length: only an angle is periodic",
                                    "give it bounds [low, high]"))
        if name in task.dimensions:
            pass
        elif name.endswith(".ratio") and VARIABLE.match(name[:-6]):
            problems.append(Problem(path, f"{name}: a link's ratio is not a design variable "
                                    "(a transmission ratio is fixed by the tooth counts)",
                                    f"vary {name[:-6]} (the link's delta), or try each ratio "
                                    "in a model of its own"))
        elif not VARIABLE.match(name):
            problems.append(Problem(path, f"{name!r} is neither a constant of the model nor "
                                    "a named dimension", "vary 'r3' / 'a5' (a constant, a "
                                    "link's delta, an argument's offset), 'start2.x' / "
                                    "'start2.y', or a name under dimensions:"))
        else:
            check_constant(name, path)
            if name in set_by:
                problems.append(Problem(path, f"{name} is also set by dimension "
                                        f"{set_by[name]!r}", f"vary {set_by[name]!r} or "
                                        f"{name}, not both"))
        if isinstance(low, int | float) and isinstance(high, int | float) and low >= high:
            problems.append(Problem(path, f"the bounds [{low}, {high}] are empty",
                                    "write [low, high] with low < high"))

    def check_point(point: Point, path: tuple) -> None:
        number = point.head if isinstance(point, HeadPoint) else point.tail
        if number not in model.vectors:
            problems.append(Problem(path, f"there is no vector {number}",
                                    f"vectors are {sorted(model.vectors)}"))

    def check_param(name: str, path: tuple) -> None:
        if vector_of(name) is None:
            problems.append(Problem(path, f"there is no vector {name[1:]}",
                                    f"vectors are {sorted(model.vectors)}"))

    n = model.positions
    if task.path is not None:
        check_point(task.path.point, (*base, "path", "point"))
        targets = task.path.targets
        if isinstance(targets, dict):
            bad = [k for k in targets if not 0 <= k <= n]
            if bad:
                problems.append(Problem((*base, "path", "targets"), f"positions {bad} are "
                                        f"outside 0..{n}", "give positions of the model"))
        if task.path.timing is True and isinstance(targets, list) and \
                len(targets) != n + 1:
            problems.append(Problem((*base, "path", "targets"), f"with timing, a list of "
                                    f"targets has one point per position ({n + 1})",
                                    "or map positions to points: {0: [x, y], 5: [x, y]}"))
        if task.path.timing == "free":
            if isinstance(targets, dict):
                problems.append(Problem((*base, "path", "targets"), "with timing: free the "
                                        "targets are a list: the synthesis chooses where "
                                        "each is reached", "write targets: [[x, y], ...], "
                                        "or timing: true to keep the positions"))
            if 1 not in model.arguments:
                problems.append(Problem((*base, "path", "timing"), "timing: free varies "
                                        "the value of argument 1, and the model has none",
                                        "add arguments: {1: {table: ...}}"))
            for i, contour in enumerate(model.contours):
                if contour.variant == "auto":
                    problems.append(Problem(
                        ("contours", i, "variant"), f"contour {i + 1} tracks its variant "
                        "(auto); timing: free solves the targets' inputs apart from the "
                        "positions, where a tracked variant is not defined",
                        "give the contour variant: 1 or 2"))
        else:
            for key in ("ordered", "direction"):
                if key in task.path.model_fields_set:
                    problems.append(Problem((*base, "path", key), f"{key} applies to "
                                            "timing: free only", f"remove {key}, or set "
                                            "timing: free"))
        if task.path.timing is True and isinstance(targets, Curve):
            problems.extend(_timed_curve_problems(model, base))
        if task.path.frame is not None:
            problems.extend(_frame_problems(task, base))
        count = (targets.count if isinstance(targets, Curve) else len(targets))
        if task.path.weights is not None and len(task.path.weights) != count:
            problems.append(Problem((*base, "path", "weights"), f"{len(task.path.weights)} "
                                    f"weights for {count} targets", "give one per target"))
    if task.function is not None:
        check_param(task.function.output, (*base, "function", "output"))
        if isinstance(task.function.target, dict):
            bad = [k for k in task.function.target if not 0 <= k <= n]
            if bad:
                problems.append(Problem((*base, "function", "target"), f"positions {bad} "
                                        f"are outside 0..{n}", "give positions of the model"))
    if task.motion is not None:
        check_point(task.motion.point, (*base, "motion", "point"))
        check_param(task.motion.angle, (*base, "motion", "angle"))
    for i, rot in enumerate(task.rotation):
        for name in rot.between:
            check_param(name, (*base, "rotation", i, "between"))
    if task.workspace is not None:
        for i, point in enumerate(task.workspace.points):
            check_point(point, (*base, "workspace", "points", i))
    for i, crit in enumerate(task.criteria):
        if crit.point is not None:
            check_point(crit.point, (*base, "criteria", i, "point"))
        where = CYCLE_VALUES.get(crit.column or "", "")
        if where.startswith("cycle.") and model.machine is None:
            problems.append(Problem((*base, "criteria", i, "column"), f"{crit.column} is a "
                                    "number of the machine's steady cycle, and the model "
                                    "has no machine: section", "add machine: {delta: ...} "
                                    "(see examples/single_cylinder_engine.yaml)"))
        elif crit.column == "flywheel" and model.machine is not None and \
                model.machine.delta is None:
            problems.append(Problem((*base, "criteria", i, "column"), "the flywheel is "
                                    "sized only for a wanted speed fluctuation",
                                    "give machine: {delta: ...}"))
        if crit.max is None and crit.min is None and crit.minimize is None:
            problems.append(Problem((*base, "criteria", i), f"criterion {crit.label} "
                                    "has no max, min or minimize", "give one of them"))
    problems.extend(_circuit_problems(model, base))
    given = task.search.start
    for i, design in enumerate([given] if isinstance(given, dict) else given or []):
        where = (*base, "search", "start", *(() if isinstance(given, dict) else (i,)))
        for name, value in design.items():
            path = (*where, name)
            if name not in task.vary:
                problems.append(Problem(path, f"{name} is not a variable of the task",
                                        f"the variables are {', '.join(task.vary)}: add "
                                        f"{name} to vary, or leave it out of the start"))
                continue
            if task.vary[name] == "periodic":
                continue  # any angle
            low, high = task.vary[name]
            dim = task.dimensions.get(name)
            kind = _target_kind(name if dim is None else dim.sets[0].set)
            try:
                x, lo, hi = (to_si(v, kind, getattr(model.units, kind))
                             for v in (value, low, high))
            except UnitProblem as exc:
                problems.append(Problem(path, exc.message, exc.hint))
                continue
            if not lo - 1e-12 * abs(lo) <= x <= hi + 1e-12 * abs(hi):
                shown = [f"{v:g}" if isinstance(v, float) else v for v in (value, low, high)]
                problems.append(Problem(path, f"{name} = {shown[0]} is outside its bounds "
                                        f"[{shown[1]}, {shown[2]}]", "give a value within "
                                        f"the bounds, or widen vary.{name} on purpose"))
    return problems


def _target_kind(name: str) -> str:
    """``'angle'`` for 'aK', ``'length'`` for 'rK', 'startK.x' and 'vK.x'."""
    return "angle" if name[0] == "a" else "length"


def _timed_curve_problems(model: Model, base: tuple) -> list[Problem]:
    """A parametric curve with timing: true is solved at argument 1 = t_k: the model needs
    argument 1, and a contour may not track its variant (auto)."""
    problems = []
    if 1 not in model.arguments:
        problems.append(Problem((*base, "path", "timing"), "a curve with timing: true "
                                "reaches target k where argument 1 equals t_k, and the "
                                "model has no argument 1", "add arguments: {1: {table: "
                                "...}}, or timing: false"))
    for i, contour in enumerate(model.contours):
        if contour.variant == "auto":
            problems.append(Problem(("contours", i, "variant"), f"contour {i + 1} tracks "
                                    "its variant (auto); a timed curve is solved at the "
                                    "targets' inputs apart from the positions, where a "
                                    "tracked variant is not defined",
                                    "give the contour variant: 1 or 2"))
    return problems


def _frame_problems(task: SynthesisTask, base: tuple) -> list[Problem]:
    """A shape-only path (frame) compares shapes: no timing, and no condition on a
    point's place in the plane (the mechanism is placed on the targets afterwards)."""
    problems = []
    where = (*base, "path", "frame")
    if task.path.timing is not False:
        problems.append(Problem(where, "frame (shape only) applies to a path without "
                                "timing", "remove frame, or set timing: false"))
    if task.workspace is not None:
        problems.append(Problem((*base, "workspace"), "a workspace fixes where the "
                                "mechanism lies, and frame leaves its placement free",
                                "remove the workspace or the frame"))
    for i, crit in enumerate(task.criteria):
        if crit.point is not None:
            problems.append(Problem((*base, "criteria", i, "point"), "a point's "
                                    "coordinate depends on the placement, which frame "
                                    "leaves free", "remove the criterion or the frame"))
    return problems


def _circuit_problems(model: Model, base: tuple) -> list[Problem]:
    """``circuits``: the listed contours exist and have a fixed variant."""
    circuits = model.synthesis.circuits
    if circuits == "given":
        return []
    problems = []
    where = (*base, "circuits")
    count = len(model.contours)
    numbers = range(1, count + 1) if circuits == "both" else circuits
    for j, number in enumerate(numbers):
        if not 1 <= number <= count:
            problems.append(Problem((*where, j), f"there is no contour {number}",
                                    f"contours are 1..{count}"))
        elif model.contours[number - 1].variant == "auto" and circuits != "both":
            problems.append(Problem(("contours", number - 1, "variant"), f"contour "
                                    f"{number} tracks its variant (auto): its circuit is "
                                    "not a choice", "give it variant: 1 or 2, or leave it "
                                    "out of circuits"))
    return problems
