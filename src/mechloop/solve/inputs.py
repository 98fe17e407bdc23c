"""Model time and model arguments over all positions, with their first and second derivatives.

Everything here is SI: seconds, metres, radians.  Derivatives are with respect to time when
the model has a time, otherwise with respect to argument 1 ("analogs", DESIGN §3).

* Laws (:mod:`mechloop.model.laws`) are exact in the model's clock: time, or the position
  number when there is no time.
* Tables are filled by KDAM's rules (:mod:`mechloop.model.tables`); their derivatives are
  those of the piecewise-linear fill (central differences over positions) or, on request
  (``derivatives: spline``), of the not-a-knot cubic spline through the filled values.
  A table linear in the position number (``{0: 0, 72: 360}``) gets its exact slope.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicSpline

from mechloop.errors import SolveError
from mechloop.model.check import argument_kind
from mechloop.model.laws import evaluate_law
from mechloop.model.schema import LawArgument, Model, RpmTime, TableArgument
from mechloop.model.signals import CsvTable, IntermediateArgument, read_csv_table
from mechloop.model.tables import fill_table
from mechloop.model.units import Kind, to_si

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Signal:
    """A quantity over positions with its first and second derivatives, shape (P,)."""

    value: Array
    rate: Array
    accel: Array


def _position_derivatives(values: Array, method: str = "linear") -> tuple[Array, Array]:
    """First and second derivative with respect to the position number.

    ``linear``: the derivatives of the piecewise-linear fill — central differences, which
    give a segment's slope inside it, zero while a value holds, the mean of the two slopes
    at a kink (and the jump of slope as the second derivative there).  ``spline``: the
    not-a-knot cubic spline through the values (smooth tabulated motion).
    """
    if values.size < 2:
        return np.zeros_like(values), np.zeros_like(values)
    second = np.diff(values, 2)
    if not second.size or np.abs(second).max() <= 1e-13 * max(np.abs(values).max(), 1e-300):
        # linear in the position number (e.g. {0: 0, 72: 360}): exact slope, no noise
        slope = (values[-1] - values[0]) / (values.size - 1)
        return np.full(values.shape, slope), np.zeros_like(values)
    if method == "linear" or values.size < 4:
        first = np.gradient(values)
        curvature = np.zeros_like(values)
        curvature[1:-1] = second
        return first, curvature
    k = np.arange(values.size, dtype=float)
    spline = CubicSpline(k, values, bc_type="not-a-knot")
    return spline(k, 1), spline(k, 2)


@np.errstate(over="ignore", invalid="ignore", divide="ignore")  # overflow: a chain break
def model_time(model: Model) -> Signal | None:
    """Time at every position and its derivatives with respect to the position number."""
    n = model.positions
    k = np.arange(n + 1, dtype=float)
    if model.time is None:
        return None
    if isinstance(model.time, RpmTime):
        step = 60.0 * model.time.turns / model.time.rpm / n
        return Signal(k * step, np.full(k.shape, step), np.zeros(k.shape))
    t = fill_table(model.time.table, n)
    dt, ddt = _position_derivatives(t, model.time.derivatives)
    return Signal(t, dt, ddt)


@np.errstate(over="ignore", invalid="ignore", divide="ignore")  # overflow: a chain break
def evaluate_signal(spec: TableArgument | LawArgument | CsvTable | IntermediateArgument,
                    model: Model, kind: Kind, unit: str, time: Signal | None) -> Signal:
    """A table or law of the model (an argument, a load) in SI over all positions, with its
    derivatives with respect to the model clock: time when the model has one, else the
    position number."""
    n = model.positions
    if isinstance(spec, CsvTable):  # built in code: load_model reads these when loading
        spec = TableArgument(**read_csv_table(spec.model_dump(), Path.cwd()))
    if isinstance(spec, IntermediateArgument):  # held at its first value, never moving
        q0 = to_si(spec.intermediate.start, kind, unit)
        return Signal(np.full(n + 1, q0), np.zeros(n + 1), np.zeros(n + 1))
    if isinstance(spec, LawArgument):
        (k0, v0), (k1, v1) = spec.start, spec.end
        q0, q1 = to_si(v0, kind, unit), to_si(v1, kind, unit)
        clock = time.value if time is not None else np.arange(n + 1, dtype=float)
        q, dq, ddq = evaluate_law(spec.law, clock, clock[k0], clock[k1], q0, q1)
        return Signal(q, dq, ddq)
    table = spec.table
    if isinstance(table, dict):
        si = {k: to_si(v, kind, unit) for k, v in table.items()}
    else:
        si = [to_si(v, kind, unit) for v in table]
    q = fill_table(si, n)
    dq, ddq = _position_derivatives(q, spec.derivatives)
    if time is None:
        return Signal(q, dq, ddq)
    # q' = q̇ t',  q'' = q̈ t'² + q̇ t''
    rate = dq / time.rate
    accel = (ddq - rate * time.accel) / time.rate**2
    return Signal(q, rate, accel)


def _argument_in_position(model: Model, number: int, time: Signal | None) -> Signal:
    """Argument ``number`` (SI) and its derivatives with respect to the model clock."""
    arg = model.arguments[number]
    kind = argument_kind(model, number)
    return evaluate_signal(arg, model, kind, arg.unit or getattr(model.units, kind), time)


@np.errstate(over="ignore", invalid="ignore", divide="ignore")  # overflow: a chain break
def model_arguments(model: Model, time: Signal | None, *, strict: bool = True
                    ) -> dict[int, Signal]:
    """Every argument over all positions, SI, derivatives with respect to time — or, when
    the model has no time, with respect to argument 1 (analogs).

    Raises :class:`SolveError` when the model has no time and argument 1 stands still at
    some position, where derivatives with respect to it do not exist (``strict=False``
    returns the values with derivatives per position number instead, for callers that
    replace the derivatives).
    """
    raw = {number: _argument_in_position(model, number, time) for number in model.arguments}
    if time is not None or not raw or not strict:
        return raw
    first = min(raw)
    base = raw[first]
    still = np.flatnonzero(base.rate == 0)
    if still.size:
        shown = ", ".join(map(str, still[:10])) + (" ..." if still.size > 10 else "")
        raise SolveError(
            f"the model has no time and argument {first} does not change at positions "
            f"{shown}: derivatives with respect to it are undefined there",
            "give the model a time (time: {rpm: ...} or time: {table: ...})"
        ).at(("arguments", first))
    d1, dd1 = base.rate, base.accel
    out = {}
    for number, sig in raw.items():
        # d q/d q1 = q'/q1',  d² q/d q1² = (q'' q1' − q' q1'')/q1'³
        out[number] = Signal(sig.value, sig.rate / d1,
                             (sig.accel * d1 - sig.rate * dd1) / d1**3)
    return out
