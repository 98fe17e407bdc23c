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


def split_work(power: Array, clock: Array) -> tuple[float, float]:
    """Positive and negative work (J) of ``power`` (W) over ``clock`` (s).

    Where the power changes sign inside a step, the step is split at the linear zero
    crossing, so ``A(+) + A(−)`` equals the trapezoidal work of ``power`` exactly.
    """
    p0, p1 = power[:-1], power[1:]
    dt = np.diff(clock)
    ok = np.isfinite(p0) & np.isfinite(p1) & np.isfinite(dt)
    p0, p1, dt = p0[ok], p1[ok], dt[ok]
    same = p0 * p1 >= 0
    whole = 0.5 * (p0 + p1) * dt
    pos = np.where(same & (whole > 0), whole, 0.0).sum()
    neg = np.where(same & (whole < 0), whole, 0.0).sum()
    cross = ~same
    if cross.any():
        a, b, h = p0[cross], p1[cross], dt[cross]
        t0 = h * np.abs(a) / (np.abs(a) + np.abs(b))  # time to the zero crossing
        first = 0.5 * a * t0
        second = 0.5 * b * (h - t0)
        pos += np.where(first > 0, first, 0).sum() + np.where(second > 0, second, 0).sum()
        neg += np.where(first < 0, first, 0).sum() + np.where(second < 0, second, 0).sum()
    return float(pos), float(neg)


#: Net work below this share of the largest work over the cycle counts as none.
NO_WORK_RTOL = 1e-9


def _extreme(values: Array, how) -> float:
    finite = values[np.isfinite(values)]
    return float(how(finite)) if finite.size else float("nan")


def _clean(value: float, tiny: float) -> float:
    """Rounding noise (below ``tiny``) shown as zero, and no negative zero."""
    return 0.0 if abs(value) <= tiny else value


@dataclass(frozen=True)
class PowerRow:
    """One line of the summary table (SI: J, W, W/kg)."""

    name: str
    positive_work: float
    negative_work: float
    max_power: float
    min_power: float
    mean_power: float
    specific_power: float


@dataclass(frozen=True)
class Summary:
    """The summary characteristics of a cycle."""

    rows: tuple[PowerRow, ...]
    driving_work: float
    friction_work: float
    loss_coefficient: float
    efficiency: float
    kinetic_energy_change: float

    def to_frame(self) -> pd.DataFrame:
        return pd.DataFrame([{
            "load": r.name, "A+ [J]": r.positive_work, "A- [J]": r.negative_work,
            "max N [W]": r.max_power, "min N [W]": r.min_power, "mean N [W]": r.mean_power,
            "N per kg [W/kg]": r.specific_power} for r in self.rows])


def summarize(powers: dict[str, Array], friction_loss: Array, clock: Array,
              total_mass: float, kinetic_energy: Array) -> Summary:
    """Build the summary table from the power of every load (W, shape (P,)), the power
    lost to friction (W, ≥ 0), the clock (s) and the kinetic energy (J)."""
    span = float(clock[-1] - clock[0]) if clock.size > 1 else 0.0
    rows = []
    driving = scale = 0.0
    for name, power in powers.items():
        pos, neg = split_work(power, clock)
        mean = (pos + neg) / span if span else float("nan")
        rows.append(PowerRow(name, pos, neg, _extreme(power, np.max),
                             _extreme(power, np.min), mean,
                             mean / total_mass if total_mass > 0 else float("nan")))
        if pos + neg > 0:
            driving += pos + neg
        scale = max(scale, pos - neg)
    fpos, fneg = split_work(-friction_loss, clock)
    friction_work = -(fpos + fneg)
    mean = (fpos + fneg) / span if span else float("nan")
    rows.append(PowerRow("friction", fpos, fneg, _extreme(-friction_loss, np.max),
                         _extreme(-friction_loss, np.min), mean,
                         mean / total_mass if total_mass > 0 else float("nan")))
    # a machine whose loads only exchange energy over the cycle has no driving work
    tiny = NO_WORK_RTOL * scale
    rows = [PowerRow(r.name, *(_clean(v, tiny) for v in (
        r.positive_work, r.negative_work, r.max_power, r.min_power, r.mean_power)),
        _clean(r.specific_power, tiny / total_mass if total_mass > 0 else 0.0))
        for r in rows]
    driving, friction_work = _clean(driving, tiny), _clean(friction_work, tiny)
    psi = friction_work / driving if driving > 0 else float("nan")
    ke = kinetic_energy[np.isfinite(kinetic_energy)]
    change = _clean(float(ke[-1] - ke[0]), tiny) if ke.size else 0.0
    efficiency = _clean(1.0 - psi, NO_WORK_RTOL)
    return Summary(tuple(rows), driving, friction_work, psi, efficiency, change)
