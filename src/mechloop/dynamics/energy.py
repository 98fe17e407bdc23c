"""Power and work over the cycle: KDAM's "summary characteristics" table.

For every load (each external force and moment, gravity, each drive's balancing load) and
for friction: its power over positions, the positive and negative work over the cycle, the
extreme powers, the mean power and the mean power per kilogram of the mechanism.  The loads
whose net work over the cycle is positive drive the machine; with ``A_d`` their work and
``A_f`` the work lost to friction, the mechanical loss coefficient is ``ψ = A_f/A_d`` and
the efficiency ``η = 1 − ψ``.

Work is integrated over the model time with the trapezoidal rule (over argument 1, and
then "power" is per unit of argument 1, when the model has no time).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import NDArray

Array = NDArray[np.float64]


def split_work(power: Array, clock: Array) -> tuple[Array, Array]:
    """Positive and negative work (J) of ``power`` (W, shape (..., P)) over ``clock`` (s,
    shape (P,) or (..., P)): arrays shaped (...), NumPy scalars for one cycle.

    Where the power changes sign inside a step, the step is split at the linear zero
    crossing, so ``A(+) + A(−)`` equals the trapezoidal work of ``power`` exactly.  Steps
    with an end that is not finite (a broken position) are left out.
    """
    power, clock = np.broadcast_arrays(np.asarray(power, dtype=float),
                                       np.asarray(clock, dtype=float))
    p0, p1 = power[..., :-1], power[..., 1:]
    with np.errstate(invalid="ignore", over="ignore"):  # inf - inf: a step left out
        dt = np.diff(clock, axis=-1)
    ok = np.isfinite(p0) & np.isfinite(p1) & np.isfinite(dt)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        same = p0 * p1 >= 0
        whole = 0.5 * (p0 + p1) * dt
        cross = ok & ~same
        t0 = dt * np.abs(p0) / (np.abs(p0) + np.abs(p1))  # time to the zero crossing
        first = 0.5 * p0 * t0
        second = 0.5 * p1 * (dt - t0)
    pos = _sum(whole, ok & same & (whole > 0))
    neg = _sum(whole, ok & same & (whole < 0))
    pos = pos + _sum(first, cross & (first > 0)) + _sum(second, cross & (second > 0))
    neg = neg + _sum(first, cross & (first < 0)) + _sum(second, cross & (second < 0))
    return pos[()], neg[()]


def _sum(values: Array, where: NDArray[np.bool_]) -> Array:
    return np.where(where, values, 0.0).sum(axis=-1)


#: Net work below this share of the largest work over the cycle counts as none.
NO_WORK_RTOL = 1e-9


def _extreme(values: Array, how) -> Array:
    """``how`` (np.max or np.min) of the finite values over the last axis; NaN where there
    is none."""
    finite = np.isfinite(values)
    fill = -np.inf if how is np.max else np.inf
    out = how(np.where(finite, values, fill), axis=-1, initial=fill)
    return np.where(finite.any(axis=-1), out, np.nan)


def _clean(value: Array, tiny: Array | float) -> Array:
    """Rounding noise (below ``tiny``) shown as zero, and no negative zero."""
    return np.where(np.abs(value) <= tiny, 0.0, value)


@dataclass(frozen=True)
class PowerRow:
    """One line of the summary table (SI: J, W, W/kg): floats for one cycle, arrays shaped
    (...) for a stack of cycles (designs)."""

    name: str
    positive_work: float | Array
    negative_work: float | Array
    max_power: float | Array
    min_power: float | Array
    mean_power: float | Array
    specific_power: float | Array


@dataclass(frozen=True)
class Summary:
    """The summary characteristics of a cycle: floats, or arrays shaped (...) when
    :func:`summarize` is given a stack of cycles (then :meth:`to_frame` does not apply)."""

    rows: tuple[PowerRow, ...]
    driving_work: float | Array
    friction_work: float | Array
    loss_coefficient: float | Array
    efficiency: float | Array
    kinetic_energy_change: float | Array

    def to_frame(self) -> pd.DataFrame:
        return pd.DataFrame([{
            "load": r.name, "A+ [J]": r.positive_work, "A- [J]": r.negative_work,
            "max N [W]": r.max_power, "min N [W]": r.min_power, "mean N [W]": r.mean_power,
            "N per kg [W/kg]": r.specific_power} for r in self.rows])


def summarize(powers: dict[str, Array], friction_loss: Array, clock: Array,
              total_mass: float, kinetic_energy: Array) -> Summary:
    """Build the summary table from the power of every load (W), the power lost to
    friction (W, ≥ 0), the clock (s) and the kinetic energy (J).

    Every array is shaped (P,) for one cycle — the summary then holds floats — or
    (..., P) for a stack of cycles, e.g. the designs of a population (``clock`` may stay
    (P,)): the summary then holds arrays shaped (...), each cycle's numbers as it alone
    would give them.
    """
    friction_loss = np.asarray(friction_loss, dtype=float)
    clock = np.asarray(clock, dtype=float)
    kinetic_energy = np.asarray(kinetic_energy, dtype=float)
    lead = np.broadcast_shapes(friction_loss.shape[:-1], kinetic_energy.shape[:-1],
                               clock.shape[:-1], *(np.shape(p)[:-1] for p in powers.values()))
    if clock.shape[-1] > 1:
        span = clock[..., -1] - clock[..., 0]
    else:
        span = np.zeros(clock.shape[:-1])
    span = np.broadcast_to(span, lead)

    def row(name: str, power: Array) -> tuple[PowerRow, Array, Array]:
        pos, neg = split_work(power, clock)
        with np.errstate(invalid="ignore", divide="ignore"):
            mean = np.where(span != 0, (pos + neg) / np.where(span != 0, span, 1.0), np.nan)
        specific = mean / total_mass if total_mass > 0 else np.full(np.shape(mean), np.nan)
        return PowerRow(name, pos, neg, _extreme(power, np.max), _extreme(power, np.min),
                        mean, specific), pos, neg

    rows = []
    driving = scale = np.zeros(lead)
    for name, power in powers.items():
        line, pos, neg = row(name, np.asarray(power, dtype=float))
        rows.append(line)
        net = pos + neg
        driving = driving + np.where(net > 0, net, 0.0)
        scale = np.maximum(scale, pos - neg)
    line, fpos, fneg = row("friction", -friction_loss)
    rows.append(line)
    friction_work = -(fpos + fneg)
    # a machine whose loads only exchange energy over the cycle has no driving work
    tiny = NO_WORK_RTOL * scale
    tiny_specific = tiny / total_mass if total_mass > 0 else 0.0
    rows = [PowerRow(r.name, *(_clean(v, tiny) for v in (
        r.positive_work, r.negative_work, r.max_power, r.min_power, r.mean_power)),
        _clean(r.specific_power, tiny_specific)) for r in rows]
    driving, friction_work = _clean(driving, tiny), _clean(friction_work, tiny)
    with np.errstate(invalid="ignore", divide="ignore"):
        psi = np.where(driving > 0, friction_work / np.where(driving > 0, driving, 1.0),
                       np.nan)
    change = _clean(_finite_change(kinetic_energy), tiny)
    efficiency = _clean(1.0 - psi, NO_WORK_RTOL)
    summary = Summary(tuple(rows), driving, friction_work, psi, efficiency, change)
    if lead:
        return summary
    return Summary(tuple(PowerRow(r.name, *(_float(getattr(r, f)) for f in _ROW_FIELDS))
                         for r in summary.rows),
                   *(_float(v) for v in (driving, friction_work, psi, efficiency, change)))


_ROW_FIELDS = ("positive_work", "negative_work", "max_power", "min_power", "mean_power",
               "specific_power")


def _float(value: Array) -> float:
    return float(np.asarray(value).reshape(()))


def _finite_change(values: Array) -> Array:
    """Last minus first finite value over the last axis (0 where none is finite)."""
    finite = np.isfinite(values)
    if values.shape[-1] == 0:
        return np.zeros(values.shape[:-1])
    first = np.argmax(finite, axis=-1)
    last = values.shape[-1] - 1 - np.argmax(finite[..., ::-1], axis=-1)
    take = np.take_along_axis
    change = (take(values, last[..., None], axis=-1)[..., 0]
              - take(values, first[..., None], axis=-1)[..., 0])
    return np.where(finite.any(axis=-1), change, 0.0)
