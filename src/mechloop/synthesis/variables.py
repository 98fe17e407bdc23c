"""Design variables: which constants of a model a synthesis varies, their bounds, and the
way back from a vector of values to a model file.

A variable is a vector parameter (``r3``, ``a5``: a constant, a link's delta or an
argument's offset), a coordinate of a contour's fixed start (``start1.x``), or a named
*dimension* of ``synthesis.dimensions`` that sets several such constants at once, each
``factor · value + shift`` (:class:`~mechloop.model.synthesis.Tie`) — a model built from
Assur groups varies its link lengths and point coordinates this way.  A target ``vK.x`` /
``vK.y`` is a component of the constant vector K: its length and angle follow from both
components.  Every target is a linear function of the design, so a whole population maps
to its parameters in a few array operations (:meth:`Variables.targets`) and is solved in
one call of :func:`~mechloop.solve.designs.solve_designs`.

Path synthesis with free timing (``timing: free``) adds one *internal* variable per
target, ``input@target1`` ...: the value of argument 1 at which the target is reached.
They are columns of the design matrix like any other (bounded by the argument's range
over the positions) and are reported with the result, but they set no constant of the
model: :func:`apply_design` leaves them out, the written model is the mechanism.

Inside the search every value is SI (m, rad); bounds and saved models are in the model's
units.  A *periodic* angle (``vary: {a4: periodic}``, or bounds spanning a full turn) has
no bound at its cut: :meth:`Variables.scale` wraps its unit coordinate (any real number)
onto the turn, :meth:`Variables.clip` wraps an SI value, and
:meth:`Variables.unit_bounds` leaves it unbounded for a search that honours bounds.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.units import to_si, unit_factor

Array = NDArray[np.float64]


def kind_of(name: str) -> str:
    """``'length'`` or ``'angle'``: the kind of quantity a constant (``r3``, ``a5``,
    ``start1.x``, ``v4.x``) is."""
    return "angle" if name[0] == "a" else "length"


@dataclass(frozen=True)
class Variables:
    """The design variables of a task, in the order of the columns of a design matrix.

    ``low`` and ``high`` are SI bounds, shape ``(V,)``; ``units`` the model unit of each.
    ``ties`` say what each column sets: ``(target, column, factor, shift)`` with ``shift``
    in SI — the target is the sum of ``factor · design[column] + shift`` over its ties.
    ``components`` hold, for every vector set by its components (``vK.x``), the SI
    components ``(x, y)`` it has in the model (used where a component is not tied).
    ``internal`` maps the name of each internal variable (free timing:
    ``input@target1`` ...) to its kind; they come last and tie nothing.
    """

    names: tuple[str, ...]
    low: Array
    high: Array
    units: tuple[str, ...]
    ties: tuple[tuple[str, int, float, float], ...] = ()
    components: Mapping[int, tuple[float, float]] | None = None
    internal: Mapping[str, str] | None = None
    periodic: NDArray[np.bool_] | None = None

    def __post_init__(self) -> None:
        if self.periodic is None:
            object.__setattr__(self, "periodic", np.zeros(len(self.names), dtype=bool))
        if not self.ties:  # plain variables: each sets the constant it names
            object.__setattr__(self, "ties", tuple(
                (name, i, 1.0, 0.0) for i, name in enumerate(self.names)
                if name not in (self.internal or {})))

    @property
    def input_columns(self) -> NDArray[np.int64]:
        """The columns of the internal free-timing inputs, in target order, ``(K,)``."""
        return np.array([i for i, name in enumerate(self.names)
                         if name in (self.internal or {})], dtype=np.int64)

    def __len__(self) -> int:
        return len(self.names)

    def targets(self, designs: Array) -> dict[str, Array]:
        """Every constant the designs ``(D, V)`` (SI) set, as given by the ties: name ->
        SI values ``(D,)`` (``r3``, ``a5``, ``start2.x``, ``v4.x``)."""
        out: dict[str, Array] = {}
        for target, column, factor, shift in self.ties:
            term = factor * designs[:, column] + shift
            out[target] = out[target] + term if target in out else term
        return out

    def overrides(self, designs: Array) -> dict[str, Array]:
        """Vector-parameter overrides for :func:`~mechloop.solve.designs.solve_designs`
        from a design matrix ``(D, V)`` (SI): a vector set by components gets its length
        and angle."""
        found = self.targets(designs)
        out = {target: values for target, values in found.items() if target[0] in "ra"}
        for number, (x0, y0) in (self.components or {}).items():
            x = found.get(f"v{number}.x", np.full(designs.shape[0], x0))
            y = found.get(f"v{number}.y", np.full(designs.shape[0], y0))
            out[f"r{number}"] = np.hypot(x, y)
            out[f"a{number}"] = np.arctan2(y, x)
        return out

    def starts(self, designs: Array) -> dict[int, tuple[Array | None, Array | None]]:
        """Contour number -> (x, y) of its start per design, shape ``(D,)`` (None where
        that coordinate is not varied)."""
        out: dict[int, list[Array | None]] = {}
        for name, values in self.targets(designs).items():
            if name.startswith("start"):
                number, axis = name[5:].split(".")
                out.setdefault(int(number), [None, None])["xy".index(axis)] = values
        return {k: (v[0], v[1]) for k, v in out.items()}

    def to_model_units(self, design: Array) -> dict[str, float]:
        """One design ``(V,)`` in SI -> {name: value in the model's units}."""
        return {name: float(value) / unit_factor(unit, self.kind(i))
                for i, (name, value, unit) in enumerate(zip(self.names, design, self.units,
                                                            strict=True))}

    def kind(self, column: int) -> str:
        """``'length'`` or ``'angle'``: the kind of variable ``column``."""
        if self.names[column] in (self.internal or {}):
            return self.internal[self.names[column]]
        target = next(t for t, c, _, _ in self.ties if c == column)
        return kind_of(target)

    def scale(self, unit: Array) -> Array:
        """Map ``[0, 1]^V`` to the bounds; a periodic column takes any unit value,
        wrapped onto its turn (``unit mod 1``), so a search may cross 0/360 freely."""
        unit = np.where(self.periodic, _wrap(unit), unit)
        return self.low + unit * (self.high - self.low)

    def unscale(self, designs: Array) -> Array:
        """Map the bounds to ``[0, 1]^V`` (a periodic column wrapped onto ``[0, 1)``)."""
        unit = (designs - self.low) / (self.high - self.low)
        return np.where(self.periodic, _wrap(unit), unit)

    def clip(self, designs: Array) -> Array:
        """SI designs ``(..., V)`` within the bounds: a periodic column wrapped onto
        ``[low, low + turn)``, any other clipped."""
        span = self.high - self.low
        wrapped = self.low + _wrap((designs - self.low) / span) * span
        return np.where(self.periodic, wrapped, np.clip(designs, self.low, self.high))

    def clip_unit(self, unit: Array) -> Array:
        """Unit coordinates ``(..., V)`` clipped to ``[0, 1]``, a periodic column left
        as it is (:meth:`scale` wraps it)."""
        return np.where(self.periodic, unit, np.clip(unit, 0.0, 1.0))

    def unit_bounds(self) -> tuple[Array, Array]:
        """Bounds of a search in unit coordinates, ``(V,)`` each: ``[0, 1]``, and
        ``(-inf, inf)`` for a periodic column (:meth:`scale` wraps it)."""
        return (np.where(self.periodic, -np.inf, 0.0), np.where(self.periodic, np.inf, 1.0))


def _wrap(unit: Array) -> Array:
    """``unit mod 1`` in ``[0, 1)`` (a tiny negative value rounds to 1.0 in ``np.mod``:
    it is the cut, 0)."""
    wrapped = np.mod(unit, 1.0)
    return np.where(wrapped >= 1.0, 0.0, wrapped)


def compile_variables(model: Model) -> Variables:
    """The variables of ``model.synthesis`` with SI bounds and what each sets."""
    task = model.synthesis
    if task is None:
        raise ValueError("the model has no synthesis task")
    names = tuple(task.vary)
    kinds, units, ties = [], [], []
    for column, name in enumerate(names):
        dim = task.dimensions.get(name)
        sets = [(name, 1.0, 0.0)] if dim is None else [(t.set, t.factor, t.shift)
                                                        for t in dim.sets]
        kind = kind_of(sets[0][0])
        unit = getattr(model.units, kind)
        kinds.append(kind)
        units.append(unit)
        for target, factor, shift in sets:
            ties.append((target, column, float(factor),
                         to_si(shift, kind_of(target), getattr(model.units,
                                                                 kind_of(target)))))
    low, high, periodic = _bounds(task.vary, names, kinds, units)
    components: dict[int, tuple[float, float]] = {}
    for target, *_ in ties:
        if target[0] == "v":
            number = int(target[1:].split(".")[0])
            r, a = _vector_si(model, number)
            components[number] = (r * math.cos(a), r * math.sin(a))
    internal: dict[str, str] = {}
    if task.path is not None and task.path.timing == "free":
        kind, unit, lowest, highest = input_range(model)
        count = _target_count(task.path.targets)
        inputs = tuple(input_name(k) for k in range(count))
        names += inputs
        units += [unit] * count
        low = np.concatenate([low, np.full(count, lowest)])
        high = np.concatenate([high, np.full(count, highest)])
        internal = dict.fromkeys(inputs, kind)
        # an input that turns fully is periodic too (the order is kept modulo the turn)
        turns = kind == "angle" and highest - lowest >= TURN * (1 - _SLACK)
        if turns:
            high[-count:] = low[-count:] + TURN
        periodic = np.concatenate([periodic, np.full(count, turns)])
    return Variables(names, low, high, tuple(units), tuple(ties), components,
                     internal or None, periodic)


#: A turn, rad, and the relative slack for bounds that span one.
TURN = 2 * math.pi
_SLACK = 1e-9


def _bounds(vary, names, kinds, units) -> tuple[Array, Array, NDArray[np.bool_]]:
    """SI bounds and the periodic mask of the variables: ``'periodic'`` is an angle on
    ``[0, 360 deg)``; an angle with bounds spanning a full turn (or more) is periodic
    on ``[low, low + 360 deg)``."""
    low, high, periodic = [], [], []
    for name, kind, unit in zip(names, kinds, units, strict=True):
        bounds = vary[name]
        if bounds == "periodic":
            lo, hi = 0.0, TURN
        else:
            lo, hi = (to_si(v, kind, unit) for v in bounds)
        turn = kind == "angle" and hi - lo >= TURN * (1 - _SLACK)
        low.append(lo)
        high.append(lo + TURN if turn else hi)
        periodic.append(turn)
    return np.array(low), np.array(high), np.array(periodic, dtype=bool)


def input_name(k: int) -> str:
    """The internal variable of free timing for target ``k`` (from 0): ``input@target1``."""
    return f"input@target{k + 1}"


def is_input(name: str) -> bool:
    """Whether ``name`` is an internal free-timing input (not a constant of the model)."""
    return name.startswith("input@target")


def input_range(model: Model) -> tuple[str, str, float, float]:
    """Argument 1: its kind, its unit in the model, and its least and greatest value over
    positions 0..N (SI)."""
    from mechloop.model.check import argument_kind
    from mechloop.solve.inputs import model_arguments, model_time

    kind = argument_kind(model, 1)
    unit = model.arguments[1].unit or getattr(model.units, kind)
    values = model_arguments(model, model_time(model), strict=False)[1].value
    return kind, unit, float(values.min()), float(values.max())


def _target_count(targets) -> int:
    return targets.count if hasattr(targets, "count") and not isinstance(
        targets, list | dict) else len(targets)


def _vector_si(model: Model, number: int) -> tuple[float, float]:
    """Length (m) and angle (rad) of the constant vector ``number``."""
    vector = model.vectors[number]
    return (to_si(vector.r, "length", model.units.length),
            to_si(vector.a, "angle", model.units.angle))


def _constant(model: Model, name: str) -> float:
    """The model's own value of a constant (``r3``, ``a5``, ``start2.x``, ``v4.x``), in
    model units."""
    if name.startswith("start"):
        number, axis = name[5:].split(".")
        raw = model.contours[int(number) - 1].start["xy".index(axis)]
        return to_si(raw, "length", model.units.length) / unit_factor(model.units.length,
                                                                         "length")
    if name[0] == "v":
        number, axis = name[1:].split(".")
        r, a = _vector_si(model, int(number))
        value = r * (math.cos(a) if axis == "x" else math.sin(a))
        return value / unit_factor(model.units.length, "length")
    vector = model.vectors[int(name[1:])]
    role = vector.r if name[0] == "r" else vector.a
    raw = (role.offset if isinstance(role, ArgumentRole)
           else role.delta if isinstance(role, LinkRole) else role)
    unit = getattr(model.units, kind_of(name))
    return to_si(raw, kind_of(name), unit) / unit_factor(unit, kind_of(name))


def current_values(model: Model, variables: Variables) -> Array:
    """The model's own values of the variables, SI, shape ``(V,)`` (clipped to the
    bounds): the design the model file describes."""
    task = model.synthesis
    dims = task.dimensions if task is not None else {}
    values = []
    inputs = variables.input_columns
    for i, name in enumerate(variables.names):
        if is_input(name):  # free timing: spread over the argument's range in order
            k = int(np.flatnonzero(inputs == i)[0])
            share = (k + 0.5) / inputs.size
            values.append(variables.low[i] + share * (variables.high[i] - variables.low[i]))
            continue
        raw = dims[name].value if name in dims else _constant(model, name)
        unit = variables.units[i]
        values.append(raw * unit_factor(unit, variables.kind(i)))
    return variables.clip(np.array(values))


def apply_design(model: Model, values: Mapping[str, float]) -> Model:
    """A copy of ``model`` with the variables set to ``values`` (model units): a named
    dimension sets every constant it ties and takes the new value itself.  The synthesis
    task is kept, so the result can be refined by another run.  Internal variables (free
    timing's ``input@targetK``) set nothing: they are not part of the mechanism."""
    task = model.synthesis
    dims = dict(task.dimensions) if task is not None else {}
    data = model.model_dump(mode="json", exclude_defaults=True)
    settings: dict[str, float] = {}
    for name, value in values.items():
        if name not in dims and not is_input(name):
            settings[name] = float(value)
    # constants tied to dimensions: the sum of the terms of every dimension that sets them
    sums: dict[str, float] = {}
    for name, dim in dims.items():
        value = float(values.get(name, dim.value))
        for tie in dim.sets:
            sums[tie.set] = sums.get(tie.set, 0.0) + tie.factor * value + tie.shift
        if name in values:
            data["synthesis"]["dimensions"][name]["value"] = value
    settings.update({k: v for k, v in sums.items() if k[0] != "v"})
    angle = unit_factor(model.units.angle, "angle")
    for number in sorted({int(k[1:].split(".")[0]) for k in sums if k[0] == "v"}):
        x = sums.get(f"v{number}.x", _constant(model, f"v{number}.x"))
        y = sums.get(f"v{number}.y", _constant(model, f"v{number}.y"))
        settings[f"r{number}"] = math.hypot(x, y)
        settings[f"a{number}"] = math.atan2(y, x) / angle
    for name, value in settings.items():
        if name.startswith("start"):
            number, axis = name[5:].split(".")
            start = list(data["contours"][int(number) - 1]["start"])
            start["xy".index(axis)] = value
            data["contours"][int(number) - 1]["start"] = start
            continue
        vector = data["vectors"][str(int(name[1:]))]
        role = vector[name[0]]
        if isinstance(role, dict) and "argument" in role:
            role["offset"] = value
        elif isinstance(role, dict) and "link" in role:
            role["delta"] = value
        else:
            vector[name[0]] = value
    return Model.model_validate(data)
