"""What a solve returns: every parameter over all positions, chain breaks, and tables.

All arrays are SI (m, rad, s) with shape ``(P,)``, ``P = N + 1``.  Rows where any contour
has no real solution are NaN in every solved column and marked in :attr:`Results.broken`;
:attr:`Results.breaks` says which contour breaks where and why.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
from numpy.typing import NDArray

if TYPE_CHECKING:
    from mechloop.model.schema import Model
    from mechloop.model.structure import Structure

Array = NDArray[np.float64]


@dataclass(frozen=True)
class ChainBreak:
    """A contour with no real solution at some positions (KDAM: "check the kinematic chain
    for a break").  ``positions`` are position numbers ``0..N``."""

    contour: int
    module: str
    positions: NDArray[np.int64]
    reason: str
    #: every contour of the coupled block that breaks (``contour`` is its first); empty
    #: for an elementary contour
    contours: tuple[int, ...] = ()

    def describe(self) -> str:
        where = (f"the coupled block of contours {', '.join(map(str, self.contours))}"
                 if len(self.contours) > 1 else f"contour {self.contour} ({self.module})")
        return (f"{where} breaks at positions "
                f"{compress_positions(self.positions)}: {self.reason}")


@dataclass(frozen=True)
class BreakBetween:
    """A contour that cannot be assembled somewhere between positions ``after`` and
    ``after + 1`` although neither position is broken: the sampled values would draw a
    smooth curve through a break.  ``start``/``stop`` are the values of argument 1 (SI:
    rad or m) where assembly is lost (in closed form for a four-bar or slider-crank
    driven by a crank, by bisection otherwise), ``at`` the argument's values at the two
    positions."""

    contour: int
    module: str
    after: int
    start: float
    stop: float
    at: tuple[float, float]
    kind: str = "angle"

    def describe(self) -> str:
        def shown(value: float) -> str:
            return f"{np.degrees(value):.6g} deg" if self.kind == "angle" else f"{value:.6g} m"

        where = (f"argument 1 = {shown(self.start)}" if self.start == self.stop else
                 f"argument 1 from {shown(self.start)} to {shown(self.stop)}")
        return (f"contour {self.contour} ({self.module}) cannot be assembled between "
                f"positions {self.after} and {self.after + 1} (argument 1 "
                f"{shown(self.at[0])} and {shown(self.at[1])}): no solution at {where}")


def compress_positions(positions: NDArray[np.int64] | list[int]) -> str:
    """``[3, 4, 5, 9]`` -> ``'3-5, 9'``."""
    pos = [int(p) for p in positions]
    if not pos:
        return ""
    runs: list[str] = []
    start = prev = pos[0]
    for p in [*pos[1:], None]:
        if p is not None and p == prev + 1:
            prev = p
            continue
        runs.append(str(start) if start == prev else f"{start}-{prev}")
        if p is not None:
            start = prev = p
    return ", ".join(runs)


@dataclass(frozen=True)
class Results:
    """Solved model: values, first and second derivatives of every vector parameter.

    Derivatives are with respect to time (s) when the model has a time; otherwise they
    are analogs with respect to argument 1 (per rad or per m of that argument).
    """

    model: Model
    structure: Structure
    time: Array | None
    arguments: dict[int, Array]
    argument_kinds: dict[int, str]
    values: dict[str, Array]
    rates: dict[str, Array]
    accels: dict[str, Array]
    constant: frozenset[str]
    broken: NDArray[np.bool_]
    breaks: tuple[ChainBreak, ...] = field(default_factory=tuple)
    analogs_of: int | None = None
    #: breaks that fall between two positions that both assemble (exact existence check)
    breaks_between: tuple[BreakBetween, ...] = field(default_factory=tuple)

    @property
    def positions(self) -> NDArray[np.int64]:
        """Position numbers ``0..N``."""
        return np.arange(self.broken.size)

    def value(self, name: str) -> Array:
        """Value of parameter ``name`` ('r3' in m, 'a2' in rad) at every position."""
        return self.values[_check_name(self, name)]

    def rate(self, name: str) -> Array:
        """First derivative of ``name`` (m/s, rad/s; or analogs without model time)."""
        return self.rates[_check_name(self, name)]

    def accel(self, name: str) -> Array:
        """Second derivative of ``name`` (m/s², rad/s²; or analogs without model time)."""
        return self.accels[_check_name(self, name)]

    def point(self, vectors: list[int] | tuple[int, ...]) -> tuple[Array, Array]:
        """x, y (m) of the end of the chain of ``vectors`` laid end to end from the origin."""
        x = sum(self.values[f"r{n}"] * np.cos(self.values[f"a{n}"]) for n in vectors)
        y = sum(self.values[f"r{n}"] * np.sin(self.values[f"a{n}"]) for n in vectors)
        return np.asarray(x), np.asarray(y)

    @property
    def has_time(self) -> bool:
        return self.time is not None

    def varying(self) -> list[str]:
        """Names of the parameters that are not constant, in vector order (r before a)."""
        names = []
        for number in sorted(self.model.vectors):
            for letter in "rab":  # b (β) only in spatial models
                name = f"{letter}{number}"
                if name not in self.constant and (letter != "b" or name in self.values):
                    names.append(name)
        return names

    def derivative_units(self) -> tuple[str, str]:
        """Units of first/second derivatives as a divisor: ('s', 's^2') or analogs."""
        if self.has_time:
            return "s", "s^2"
        first = self.analogs_of or (min(self.arguments) if self.arguments else None)
        base = "m" if first is not None and self.argument_kinds[first] == "length" else "rad"
        return base, f"{base}^2"

    def to_frame(self) -> pd.DataFrame:
        """One row per position: position, time, arguments, then every non-constant
        parameter with its first and second derivatives, and ``chain_break``.

        Column names carry units: ``a2 [deg]``, ``da2 [rad/s]``, ``dda2 [rad/s^2]``,
        ``r3 [m]``, ``dr3 [m/s]``, ``ddr3 [m/s^2]``; without model time the derivative
        units are per unit of argument 1 (``da2 [rad/rad]``).
        """
        d1, d2 = self.derivative_units()
        cols: dict[str, NDArray] = {"position": self.positions}
        if self.time is not None:
            cols["time [s]"] = self.time
        for number, values in sorted(self.arguments.items()):
            if self.argument_kinds[number] == "angle":
                cols[f"arg{number} [deg]"] = np.degrees(values)
            else:
                cols[f"arg{number} [m]"] = values
        for name in self.varying():
            base = "m" if name[0] == "r" else "rad"
            shown = np.degrees(self.values[name]) if name[0] != "r" else self.values[name]
            cols[f"{name} [{'m' if name[0] == 'r' else 'deg'}]"] = shown
            cols[f"d{name} [{base}/{d1}]"] = self.rates[name]
            cols[f"dd{name} [{base}/{d2}]"] = self.accels[name]
        cols["chain_break"] = self.broken
        return pd.DataFrame(cols)


def _check_name(results: Results, name: str) -> str:
    if name not in results.values:
        known = ", ".join(results.varying()[:12])
        raise KeyError(f"no parameter {name!r} in this model (parameters that vary: {known})")
    return name
