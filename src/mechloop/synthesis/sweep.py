"""Parametric analysis (KDAM's "parametric analysis" panel): vary one or two numbers of a
model over a list, a range or a grid, solve every design, and tabulate chosen reductions
of chosen columns — e.g. the peak balancing moment of an engine against its speed.

A **parameter** is addressed by its path in the model's data, as in the model file:
``vectors.3.r``, ``vectors.6.a.delta``, ``time.rpm``, ``bodies.2.mass``,
``forces.0.value``, ``machine.delta``, ``arguments.1.end.1`` (list items by their index
from 0; ``vectors[3].r`` is read the same way).  Its values are numbers in the model's
units or quantity strings (``"50 mm"``), given as a list or as a range
``"start:stop:count"`` (``count`` evenly spaced values, both ends included).  Two
parameters give the full grid, the first varying slowest.

A **quantity** is ``COLUMN:REDUCTION``: ``COLUMN`` is a column of the kinematic table
(:meth:`Results.to_frame <mechloop.solve.results.Results.to_frame>`) or, for a model with
bodies, of the dynamic table (:meth:`DynamicResults.to_frame
<mechloop.dynamics.analysis.DynamicResults.to_frame>`), written with or without its unit
(``M_bal`` or ``M_bal [N*m]``); ``REDUCTION`` is one of :data:`REDUCTIONS` or ``at=K``
(the value at position K).  The dynamics are solved only when a quantity needs them.

Every design is rebuilt from data with :meth:`Model.from_dict
<mechloop.model.schema.Model.from_dict>`, so it is validated like a model file; an invalid
design raises :class:`~mechloop.errors.ModelError` naming the design.  A design whose
chain breaks is not an error: its row holds NaN quantities, the number of broken positions
(``broken``) and the description of the break (``note``).  The designs are solved by
:func:`mechloop.synthesis.parallel.map_tasks` (serially, on local processes, or on a
dask.distributed cluster).
"""

from __future__ import annotations

import copy
import difflib
import itertools
import math
import re
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import pandas as pd
import pint
from numpy.typing import ArrayLike, NDArray

from mechloop.dynamics.analysis import solve_dynamics
from mechloop.errors import HintedError, ModelError, SolveError
from mechloop.model.schema import Model
from mechloop.model.units import registry
from mechloop.solve.kinematics import solve
from mechloop.solve.results import compress_positions
from mechloop.synthesis.parallel import Progress, check_scheduler, choose_scheduler, map_tasks

if TYPE_CHECKING:
    from distributed import Client

#: Reductions of a column over the positions 0..N (each position counts once); ``at=K``
#: is the value at position K.
REDUCTIONS = ("max", "min", "mean", "rms", "range", "absmax")
#: Columns of the result tables that are not quantities.
_NOT_QUANTITIES = ("chain_break",)
#: A sweep varies at most this many parameters (a line or a grid).
MAX_PARAMETERS = 2

_COLUMN = re.compile(r"^(.+?) \[(.+)\]$")
_AT = re.compile(r"^at\s*=\s*(-?\d+)$")

#: Values of one parameter: a list (or array) of numbers / quantity strings, one value,
#: or a string: "start:stop:count" or "v1,v2,...".
Values = str | float | ArrayLike | Sequence[float | str]


class SweepError(HintedError):
    """A sweep asked for something the model does not have: a path, a column, a
    reduction, a value that cannot be read."""


# ------------------------------------------------------------------------------ values


def parse_values(text: str) -> list[float | str]:
    """The values of a parameter written as text.

    ``"start:stop:count"`` gives ``count`` evenly spaced values from start to stop (both
    included; start and stop may carry a unit: ``"30 mm:60 mm:4"``); ``"v1,v2,..."`` a
    list (numbers, or quantity strings kept as they are).

    >>> parse_values("1000:4000:4")
    [1000.0, 2000.0, 3000.0, 4000.0]
    >>> parse_values("0.1, 0.2, 50 mm")
    [0.1, 0.2, '50 mm']
    >>> parse_values("30 mm:60 mm:3")
    ['30 mm', '45 mm', '60 mm']
    """
    text = str(text).strip()
    if ":" in text:
        parts = [p.strip() for p in text.split(":")]
        if len(parts) != 3 or not all(parts):
            raise SweepError(f"cannot read the range {text!r}",
                             "write start:stop:count, e.g. 1000:4000:7")
        try:
            count = int(parts[2])
        except ValueError:
            raise SweepError(f"the count {parts[2]!r} of the range {text!r} is not a whole "
                             "number", "write start:stop:count, e.g. 1000:4000:7") from None
        if count < 1:
            raise SweepError(f"the range {text!r} has no values", "give a count of 1 or more")
        return _linspace(parts[0], parts[1], count, text)
    values = [p.strip() for p in text.split(",")]
    if not all(values):
        raise SweepError(f"an empty value in {text!r}",
                         "separate values by commas: 1000,2000,3000, or give a range "
                         "1000:4000:7")
    return [_number_or_text(v) for v in values]


def _number_or_text(text: str) -> float | str:
    try:
        return float(text)
    except ValueError:
        return text


def _linspace(start: str, stop: str, count: int, text: str) -> list[float | str]:
    a, b = _number_or_text(start), _number_or_text(stop)
    if isinstance(a, float) and isinstance(b, float):
        return [float(v) for v in np.linspace(a, b, count)]
    try:
        qa = registry().Quantity(start)
        qb = registry().Quantity(stop).to(qa.units)
    except (pint.errors.PintError, ValueError, TypeError, AttributeError,
            AssertionError) as exc:
        raise SweepError(f"cannot read the range {text!r} ({exc})",
                         "give start and stop as numbers or in one kind of unit, e.g. "
                         "30 mm:60 mm:4") from None
    unit = f"{qa.units:~}"
    return [f"{v:.12g} {unit}" for v in np.linspace(qa.magnitude, qb.magnitude, count)]


def parse_vary(text: str) -> tuple[str, list[float | str]]:
    """``"PATH=VALUES"`` (the ``--vary`` option) -> ``(path, values)``.

    >>> parse_vary("time.rpm=1000:3000:3")
    ('time.rpm', [1000.0, 2000.0, 3000.0])
    """
    path, sep, values = str(text).partition("=")
    if not sep or not path.strip() or not values.strip():
        raise SweepError(f"cannot read {text!r} as PATH=VALUES",
                         "write e.g. time.rpm=1000:4000:7 or vectors.2.r=0.15,0.2,0.25")
    return path.strip(), parse_values(values)


def _values(path: str, values: Values) -> list[Any]:
    if isinstance(values, str):
        out: list[Any] = parse_values(values)
    elif isinstance(values, int | float | np.number):
        out = [values]
    else:
        out = list(np.asarray(values, dtype=object).ravel()) \
            if isinstance(values, np.ndarray) else list(values)  # type: ignore[arg-type]
    out = [v.item() if isinstance(v, np.generic) else v for v in out]
    if not out:
        raise SweepError(f"{path}: no values to sweep", "give a list of values or a range "
                         "start:stop:count")
    return out


# ------------------------------------------------------------------------------- paths


def split_path(path: str) -> tuple[str, ...]:
    """``"vectors.3.r"`` or ``"vectors[3].r"`` -> ``("vectors", "3", "r")``."""
    text = re.sub(r"\[\s*([^\]]*?)\s*\]", r".\1", str(path).strip())
    keys = tuple(text.split("."))
    if not text or not all(keys):
        raise SweepError(f"cannot read the parameter path {path!r}",
                         "write keys separated by dots, as in the model file: "
                         "vectors.3.r, time.rpm, bodies.2.mass")
    return keys


def resolve_path(data: Mapping[str, Any], path: str) -> tuple[str | int, ...]:
    """The keys of ``path`` in the model data ``data`` (dict keys as strings, list items
    as ints).

    Raises :class:`SweepError` naming the place where the path leaves the data and the
    keys (or indices) that are valid there.
    """
    node: Any = data
    keys: list[str | int] = []
    parts = split_path(path)
    for i, part in enumerate(parts):
        where = ".".join(parts[:i])
        place = where or "the model"
        if isinstance(node, Mapping):
            if part not in node:
                valid = ", ".join(map(str, node)) or "none"
                raise SweepError(f"{path}: {place} has no key {part!r}",
                                 f"use one of the keys of {place}: {valid}")
            keys.append(part)
            node = node[part]
        elif isinstance(node, list):
            index = int(part) if re.fullmatch(r"\d+", part) else -1
            if not 0 <= index < len(node):
                raise SweepError(
                    f"{path}: {place} is a list of {len(node)} item(s), {part!r} is not "
                    "one of its indices",
                    f"use an index 0..{len(node) - 1}" if node
                    else f"the model has no {place}; add one to the model first")
            keys.append(index)
            node = node[index]
        elif node is None:
            raise SweepError(f"{path}: {place} is not set in this model",
                             f"add '{parts[i - 1]}:' to the model first, then sweep {path}")
        else:
            raise SweepError(f"{path}: {place} is a single value ({node!r}), it has no "
                             f"key {part!r}", f"sweep {place} itself")
    if isinstance(node, Mapping) and node:
        raise SweepError(f"{path} is a group of settings, not a number",
                         f"name one of its keys: {', '.join(f'{path}.{k}' for k in node)}")
    if isinstance(node, list):
        raise SweepError(f"{path} is a list, not a number",
                         f"name one of its items: {path}.0 .. {path}.{len(node) - 1}"
                         if node else "sweep a number")
    return tuple(keys)


def set_path(data: Mapping[str, Any], keys: Sequence[str | int], value: Any
             ) -> dict[str, Any]:
    """A deep copy of ``data`` with the item at ``keys`` (from :func:`resolve_path`)
    set to ``value``."""
    out = copy.deepcopy(dict(data))
    node: Any = out
    for key in keys[:-1]:
        node = node[key]
    node[keys[-1]] = value
    return out


def _argument_kind(model: Model, k: int) -> str:
    """'length' when argument ``k`` drives a length, else 'angle'."""
    for vector in model.vectors.values():
        if getattr(vector.r, "argument", None) == k:
            return "length"
    return "angle"


def parameter_unit(model: Model, keys: Sequence[str | int]) -> str:
    """The unit (pint text) in which the model reads the number at ``keys`` (from
    :func:`resolve_path`); ``''`` for a plain number (a count, a fraction, a coefficient,
    a position number, a vector number)."""
    units = model.units
    head, last, n = keys[0], keys[-1], len(keys)
    in_point = n >= 2 and keys[-2] in ("center", "at") and last in ("along", "across")
    if head == "vectors":
        if n >= 3 and keys[2] in ("r", "a") and (n == 3 or keys[3] in ("offset", "delta")):
            return units.length if keys[2] == "r" else units.angle
        return ""
    if head == "arguments" and n >= 3:
        k = int(keys[1])
        unit = getattr(model.arguments.get(k), "unit", None) or (
            units.length if _argument_kind(model, k) == "length" else units.angle)
        if keys[2] == "table" or (keys[2] in ("start", "end") and n == 4 and keys[3] == 1):
            return unit
        return ""
    if head == "time" and n >= 2:
        return {"rpm": "rpm", "table": "s"}.get(str(keys[1]), "")
    if head in ("forces", "moments") and n >= 3 and keys[2] == "value":
        base = units.force if head == "forces" else units.moment
        own = getattr(getattr(model, head)[int(keys[1])].value, "unit", None) or base
        if n == 3:
            return base
        if keys[3] == "table" or (keys[3] in ("start", "end") and n == 5 and keys[4] == 1):
            return own
        return ""
    if head == "gravity":
        return {"g": units.acceleration, "angle": units.angle}.get(str(last), "")
    if head == "contours":
        return units.length if n == 4 and keys[2] == "start" else ""
    if in_point or (head in ("joints", "friction") and last in ("radius", "length")):
        return units.length
    if head == "forces" and last == "angle":
        return units.angle
    if head == "bodies" and last in ("mass", "inertia"):
        return units.mass if last == "mass" else units.inertia
    return ""


def _in_unit(value: Any, unit: str, path: str) -> Any:
    """``value`` as a number in ``unit`` (a quantity string is converted); for a parameter
    without a unit, a whole number as an int (a count, a variant) and anything else as it
    is."""
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        return value
    if not unit:  # a count, a variant, a fraction: whole numbers stay whole
        number = _number_or_text(value) if isinstance(value, str) else value
        return int(number) if isinstance(number, float) and number.is_integer() else number
    if not isinstance(value, str):
        return float(value)
    try:
        return float(value)
    except ValueError:
        pass
    try:
        quantity = registry().Quantity(value.strip())
        return float(quantity.to(unit).magnitude)
    except (pint.errors.PintError, ValueError, TypeError, AttributeError,
            AssertionError) as exc:
        raise SweepError(f"{path}: cannot read {value!r} as a value in {unit} ({exc})",
                         f"write a number (in {unit}, the model's unit) or a number with "
                         f"a unit of the same kind, e.g. '1 {unit}'") from None


@dataclass(frozen=True)
class Parameter:
    """One swept parameter: its path, the keys in the model data, the unit of its numbers
    (``''`` for a plain number) and its values (numbers in ``unit``)."""

    path: str
    keys: tuple[str | int, ...]
    unit: str
    values: tuple[Any, ...]

    @property
    def header(self) -> str:
        """The column of the sweep table: ``'time.rpm [rpm]'``, ``'machine.delta'``."""
        return f"{self.path} [{self.unit}]" if self.unit else self.path


def _parameters(model: Model, data: Mapping[str, Any],
                parameters: Mapping[str, Values] | Sequence[tuple[str, Values]]
                ) -> list[Parameter]:
    pairs = list(parameters.items()) if isinstance(parameters, Mapping) else list(parameters)
    if not 1 <= len(pairs) <= MAX_PARAMETERS:
        raise SweepError(f"a sweep varies one or two parameters, not {len(pairs)}",
                         "give one parameter (a line) or two (a grid), e.g. "
                         "{'time.rpm': '1000:4000:7'}")
    out: list[Parameter] = []
    for path, values in pairs:
        keys = resolve_path(data, str(path))
        if any(p.keys == keys for p in out):
            raise SweepError(f"{path} is varied twice", "vary each parameter once")
        unit = parameter_unit(model, keys)
        shown = tuple(_in_unit(v, unit, str(path)) for v in _values(str(path), values))
        out.append(Parameter(str(path), keys, unit, shown))
    return out


# --------------------------------------------------------------------------- quantities


def reduce_column(values: ArrayLike, reduction: str) -> float:
    """One number from a column over the positions, shape (P,) -> scalar.

    ``max``, ``min``, ``mean``, ``rms`` (√mean(x²)), ``range`` (max − min), ``absmax``
    (max |x|), or ``at=K`` (the value at position K, 0..N).  NaN in, NaN out.

    >>> reduce_column([1.0, -3.0, 2.0], "absmax"), reduce_column([1.0, -3.0, 2.0], "at=2")
    (3.0, 2.0)
    """
    x = np.asarray(values, dtype=float)
    text = reduction.strip()
    at = _AT.match(text)
    if at is not None:
        k = int(at.group(1))
        if not 0 <= k < x.size:
            raise SweepError(f"at={k}: no position {k}; the positions are 0..{x.size - 1}",
                             f"use at=K with K from 0 to {x.size - 1}")
        return float(x[k])
    if text == "max":
        return float(np.max(x))
    if text == "min":
        return float(np.min(x))
    if text == "mean":
        return float(np.mean(x))
    if text == "rms":
        return float(np.sqrt(np.mean(x * x)))
    if text == "range":
        return float(np.max(x) - np.min(x))
    if text == "absmax":
        return float(np.max(np.abs(x)))
    raise _unknown_reduction(reduction)


def _unknown_reduction(reduction: str) -> SweepError:
    close = difflib.get_close_matches(reduction.strip(), [*REDUCTIONS, "at="], n=2)
    guess = f"did you mean {' or '.join(close)}? " if close else ""
    return SweepError(f"unknown reduction {reduction!r}",
                      f"{guess}use one of {', '.join(REDUCTIONS)}, or at=K (the value at "
                      "position K)")


@dataclass(frozen=True)
class Quantity:
    """A collected quantity: ``reduction`` of the table column ``column`` (its header,
    with the unit: ``'M_bal [N*m]'``); ``dynamic`` when the column needs the dynamics."""

    column: str
    reduction: str
    dynamic: bool = False

    @property
    def stem(self) -> str:
        """The column's name without its unit: ``'M_bal'``."""
        match = _COLUMN.match(self.column)
        return match.group(1) if match else self.column

    @property
    def unit(self) -> str:
        """The column's unit as the table writes it (``'N*m'``; ``''`` for none)."""
        match = _COLUMN.match(self.column)
        return match.group(2) if match else ""

    @property
    def header(self) -> str:
        """The column of the sweep table: ``'M_bal:max [N*m]'``."""
        name = f"{self.stem}:{self.reduction}"
        return f"{name} [{self.unit}]" if self.unit else name

    def reduce(self, values: ArrayLike) -> float:
        """This quantity from the column's values, shape (P,), in the table's unit."""
        return reduce_column(values, self.reduction)


def _stem(header: str) -> str:
    match = _COLUMN.match(header)
    return match.group(1) if match else header


def parse_quantity(text: str, kinematic: Sequence[str], dynamic: Sequence[str] = (), *,
                   has_bodies: bool = True) -> Quantity:
    """Read ``"COLUMN:REDUCTION"`` against the headers of the kinematic and dynamic
    tables.  Raises :class:`SweepError` with close matches for an unknown column, or the
    list of reductions for an unknown one."""
    column, sep, reduction = str(text).strip().rpartition(":")
    column, reduction = column.strip(), reduction.strip()
    if not sep or not column or not reduction:
        raise SweepError(f"cannot read the quantity {text!r}",
                         "write COLUMN:REDUCTION, e.g. M_bal:max, r3:range or a2:at=18")
    if _AT.match(reduction) is None and reduction not in REDUCTIONS:
        raise _unknown_reduction(reduction)
    for headers, is_dynamic in ((kinematic, False), (dynamic, True)):
        for header in headers:
            if header in _NOT_QUANTITIES:
                continue
            if column in (header, _stem(header)):
                return Quantity(header, reduction.replace(" ", ""), is_dynamic)
    stems = [_stem(h) for h in [*kinematic, *dynamic] if h not in _NOT_QUANTITIES]
    close = difflib.get_close_matches(column, stems, n=4, cutoff=0.5)
    guess = f"did you mean {', '.join(close)}? " if close else ""
    extra = ("" if has_bodies else "; dynamic columns (M_bal, J_red, R<joint>, ...) need a "
             "model with bodies")
    raise SweepError(f"no column {column!r} in the results of this model",
                     f"{guess}columns: {', '.join(stems)}{extra}")


# ------------------------------------------------------------------------------ designs


@dataclass(frozen=True)
class Design:
    """One design of a sweep, as sent to a worker: the model data, a label for messages
    (``'time.rpm=2000'``), the quantities and whether the dynamics are needed."""

    data: dict[str, Any]
    label: str
    quantities: tuple[Quantity, ...]
    dynamics: bool


@dataclass(frozen=True)
class Outcome:
    """What a design gives: the quantities (NaN when they cannot be had), the number of
    positions where the chain breaks, and a note ('' when all went well)."""

    values: tuple[float, ...]
    broken: int = 0
    note: str = ""


def evaluate_design(design: Design) -> Outcome:
    """Build, solve and reduce one design (runs in a worker).

    Raises :class:`~mechloop.errors.ModelError` (with the design's label in place of
    the file) when the design is not a valid model; a chain break, or a quantity the
    design's data leave undefined (:class:`~mechloop.errors.SolveError`), gives NaN
    values and a note instead.
    """
    blank = (math.nan,) * len(design.quantities)
    try:
        model = Model.from_dict(design.data)
        kin = solve(model)
        if kin.broken.any():
            note = "; ".join(b.describe() for b in kin.breaks)
            return Outcome(blank, int(kin.broken.sum()), note)
        notes: list[str] = []
        if design.dynamics:
            dyn = solve_dynamics(model)
            frame = dyn.to_frame()
            singular = dyn.forces.singular
            if singular.any():
                notes.append("force analysis singular at positions "
                             f"{compress_positions(np.flatnonzero(singular))}")
        else:
            frame = kin.to_frame()
        values = []
        for q in design.quantities:
            if q.column not in frame.columns:
                notes.append(f"no column {q.column!r} for this design")
                values.append(math.nan)
            else:
                values.append(q.reduce(frame[q.column].to_numpy(dtype=float)))
        return Outcome(tuple(values), 0, "; ".join(notes))
    except ModelError as exc:
        raise type(exc)(exc.problems, exc.file or f"the design {design.label}") from None
    except (SolveError, SweepError) as exc:
        return Outcome(blank, 0, str(exc).replace("\n    fix:", "; fix:"))


def _format(value: Any) -> str:
    return f"{value:.6g}" if isinstance(value, float) else str(value)


def plan_sweep(model: Model, parameters: Mapping[str, Values] | Sequence[tuple[str, Values]],
               quantities: str | Sequence[str]) -> tuple[list[Parameter], list[Quantity],
                                                         list[Design]]:
    """Check a sweep and list its designs, without solving them (the base model is
    solved once to know its columns).  Returns the parameters, the quantities and the
    designs (the grid in row order: the first parameter varies slowest)."""
    data = model.model_dump(mode="json")
    params = _parameters(model, data, parameters)
    specs = [quantities] if isinstance(quantities, str) else list(quantities)
    if not specs:
        raise SweepError("no quantity to collect",
                         "name at least one, e.g. M_bal:max or r3:range")
    kinematic = list(solve(model).to_frame().columns)
    dynamic: list[str] = []

    def known(spec: str) -> bool:
        column = str(spec).rpartition(":")[0].strip()
        return any(column in (h, _stem(h)) for h in kinematic)

    if model.bodies and not all(known(s) for s in specs):
        dynamic = [c for c in solve_dynamics(model).to_frame().columns if c not in kinematic]
    wanted = [parse_quantity(s, kinematic, dynamic, has_bodies=bool(model.bodies))
              for s in specs]
    headers = [q.header for q in wanted]
    if len(set(headers)) != len(headers):
        raise SweepError("a quantity is collected twice", "collect each quantity once")
    if all(p.keys != ("positions",) for p in params):
        for q in wanted:
            at = _AT.match(q.reduction)
            if at is not None and not 0 <= int(at.group(1)) <= model.positions:
                raise SweepError(f"{q.stem}:{q.reduction}: no position {at.group(1)}; the "
                                 f"positions of this model are 0..{model.positions}",
                                 f"use at=K with K from 0 to {model.positions}")
    needs_dynamics = any(q.dynamic for q in wanted)
    designs = []
    for combo in itertools.product(*(p.values for p in params)):
        design = data
        for p, value in zip(params, combo, strict=True):
            design = set_path(design, p.keys, value)
        label = ", ".join(f"{p.path}={_format(v)}" for p, v in zip(params, combo, strict=True))
        designs.append(Design(design, label, tuple(wanted), needs_dynamics))
    return params, wanted, designs


def sweep(model: Model, parameters: Mapping[str, Values] | Sequence[tuple[str, Values]],
          quantities: str | Sequence[str], *, scheduler: str | Client | None = None,
          progress: Progress | None = None) -> pd.DataFrame:
    """Solve ``model`` for every value (or grid point) of one or two parameters and
    collect reductions of result columns.

    Parameters
    ----------
    model : the base model; the parameters are set in a copy of its data.
    parameters : ``{path: values}`` (or a list of ``(path, values)`` pairs), one or two
        entries; values are a list of numbers (model units) or quantity strings, or a
        string ``"start:stop:count"`` / ``"v1,v2,..."``.
    quantities : ``"COLUMN:REDUCTION"`` strings, e.g. ``["M_bal:max", "RB:absmax"]``.
    scheduler : ``"serial"``, ``"processes"``, ``"tcp://host:8786"``, a
        ``distributed.Client``, or None: serial unless the sweep would take more than
        10 s (timed on its first design) — see
        :func:`~mechloop.synthesis.parallel.choose_scheduler`.
    progress : ``progress(done, total)`` after every solved design.

    Returns
    -------
    pandas.DataFrame : one row per design (D rows; a grid in row order, the first
        parameter varying slowest): the parameters (``'time.rpm [rpm]'``, numbers in the
        model's units), the quantities (``'M_bal:max [N*m]'``, in the units of the result
        tables: SI, angles in degrees), ``broken`` (positions where the chain breaks) and
        ``note`` (what went wrong, '' when nothing).  ``frame.attrs`` holds the lists
        ``"parameters"`` and ``"quantities"`` of the column names.

    Raises
    ------
    SweepError
        A bad path (naming the valid keys where it fails), an unknown column (with close
        matches) or reduction, a value that cannot be read.
    ModelError
        A design that is not a valid model (the message names the design).
    """
    check_scheduler(scheduler)
    params, wanted, designs = plan_sweep(model, parameters, quantities)
    outcomes = _run(designs, scheduler, progress)
    table: dict[str, Any] = {}
    for i, p in enumerate(params):
        column = [combo[i] for combo in itertools.product(*(q.values for q in params))]
        table[p.header] = column
    for j, q in enumerate(wanted):
        table[q.header] = np.array([o.values[j] for o in outcomes], dtype=float)
    table["broken"] = np.array([o.broken for o in outcomes], dtype=np.int64)
    table["note"] = [o.note for o in outcomes]
    frame = pd.DataFrame(table)
    frame.attrs["parameters"] = [p.header for p in params]
    frame.attrs["quantities"] = [q.header for q in wanted]
    return frame


def _run(designs: list[Design], scheduler: str | Client | None,
         progress: Progress | None) -> list[Outcome]:
    """Evaluate the designs; with ``scheduler=None`` the first one is timed here and the
    rest go where :func:`choose_scheduler` sends them."""
    if scheduler is not None or len(designs) < 2:
        return map_tasks(evaluate_design, designs, scheduler=scheduler or "serial",
                         progress=progress)
    total = len(designs)
    if progress is not None:
        progress(0, total)
    start = time.perf_counter()
    first = evaluate_design(designs[0])
    seconds = time.perf_counter() - start
    if progress is not None:
        progress(1, total)
    chosen = choose_scheduler(total - 1, seconds_per_item=seconds)
    shifted = None if progress is None else _shift(progress, 1, total)
    return [first, *map_tasks(evaluate_design, designs[1:], scheduler=chosen,
                              progress=shifted)]


def _shift(progress: Progress, offset: int, total: int) -> Callable[[int, int], Any]:
    def report(done: int, _: int) -> Any:
        return progress(done + offset, total)

    return report


def grid(frame: pd.DataFrame, quantity: str) -> tuple[NDArray[np.float64],
                                                      NDArray[np.float64],
                                                      NDArray[np.float64]]:
    """A two-parameter sweep's ``quantity`` column as a grid: ``(x, y, z)`` with ``x``
    the values of the first parameter, shape (n1,), ``y`` of the second, shape (n2,),
    and ``z`` shape (n1, n2) (``z[i, j]`` at ``x[i], y[j]``)."""
    names = sweep_columns(frame)[0]
    if len(names) != 2:
        raise SweepError(f"a grid needs a two-parameter sweep; this one has {len(names)}",
                         "sweep two parameters")
    x = pd.unique(frame[names[0]])
    y = pd.unique(frame[names[1]])
    z = frame[quantity].to_numpy(dtype=float).reshape(len(x), len(y))
    return np.asarray(x, dtype=float), np.asarray(y, dtype=float), z


def sweep_columns(frame: pd.DataFrame) -> tuple[list[str], list[str]]:
    """The parameter and quantity columns of a sweep table (from ``frame.attrs``, or for
    a table read back from a file, by their names: quantities hold a ':')."""
    params = frame.attrs.get("parameters")
    quants = frame.attrs.get("quantities")
    if params is not None and quants is not None:
        return list(params), list(quants)
    rest = [str(c) for c in frame.columns if c not in ("broken", "note")]
    return [c for c in rest if ":" not in c], [c for c in rest if ":" in c]
