"""Result tables in the user's units and precision (KDAM's units and tolerances panels).

Every table mechloop writes names its unit in each column header (``F_bal [N]``,
``da2 [rad/s]``, ``dr3 [m/rad]``).  :func:`apply_display` reads that unit, finds the kind
of quantity (force, angular velocity, length per angle, ...) and converts the column by
pint into the unit a :class:`TableDisplay` asks for, renaming the header
(``F_bal [kN]``).  Only the kinds the user named are converted — a kind built from named
ones follows them (``length: mm`` turns ``m/s`` into ``mm/s``) unless it is named itself —
so a table without a ``display:`` section or ``--units`` stays exactly as it always was
(angles in deg, angular velocities in rad/s, everything else SI).

Precision is applied when the table is written: ``digits`` significant digits (or
``decimals`` after the point) for CSV, JSON, XLSX and the console; Parquet keeps every
digit of the double unless ``--digits``/``--decimals`` is given on the command line.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import pint
from numpy.typing import NDArray

from mechloop.model.display import ALIASES, UNIT_FIELDS
from mechloop.model.units import registry
from mechloop.output.paths import OutputError

if TYPE_CHECKING:
    import pandas as pd

    from mechloop.model.display import DisplaySection
    from mechloop.views.display import Display

#: The SI (or table) units a header may carry for each base kind of quantity.
HEADER_BASES: dict[str, str] = {"m": "length", "rad": "angle", "deg": "angle", "s": "time",
                                "kg": "mass", "kg*m^2": "inertia", "N": "force",
                                "N*m": "moment", "J": "energy", "W": "power"}
_HEADER = re.compile(r"^(.*) \[([^\[\]]+)\]$")
_POWERED = re.compile(r"^(.+?)(?:\^(\d+))?$")

#: Derived kinds that keep their own unit unless named (angular velocity stays rad/s
#: when the angles are shown in degrees), each with the Display field that names it.
OWN_UNIT: dict[str, str] = {"angle/time": "angular_velocity",
                            "angle/time^2": "angular_acceleration",
                            "length/time": "velocity", "length/time^2": "acceleration"}


@functools.cache
def header_parts(unit: str) -> tuple[tuple[str, str], tuple[str, str, int] | None] | None:
    """A header unit split into its numerator (unit, base kind) and denominator (unit,
    base kind, power): ``'m/rad^2'`` -> ``(('m', 'length'), ('rad', 'angle', 2))``; None
    for a unit that is not one mechloop writes in SI (``'rpm'``, no unit)."""
    top, _, bottom = unit.partition("/")
    if top not in HEADER_BASES:
        return None
    if not bottom:
        return (top, HEADER_BASES[top]), None
    match = _POWERED.match(bottom)
    if match is None or match.group(1) not in HEADER_BASES:
        return None
    return ((top, HEADER_BASES[top]),
            (match.group(1), HEADER_BASES[match.group(1)], int(match.group(2) or 1)))


def header_kind(unit: str) -> str | None:
    """The kind of quantity of a header unit, a quotient of base kinds
    (``'rad/s^2'`` -> ``'angle/time^2'``, ``'kg*m^2/rad'`` -> ``'inertia/angle'``,
    ``'N'`` -> ``'force'``); None for a unit mechloop does not write in SI."""
    parts = header_parts(unit)
    if parts is None:
        return None
    (_, top), bottom = parts
    if bottom is None:
        return top
    return f"{top}/{bottom[1]}" + (f"^{bottom[2]}" if bottom[2] != 1 else "")


@dataclass(frozen=True)
class TableDisplay:
    """The units and precision a table is written in.

    ``units``: the kinds the user named and their units (every other kind keeps the
    table's own unit); ``digits``/``decimals``: the precision of every float (None:
    every digit); ``binary``: whether Parquet is rounded too (asked for on the command
    line).
    """

    units: dict[str, str]
    digits: int | None = None
    decimals: int | None = None
    binary: bool = False

    def target(self, unit: str) -> str | None:
        """The unit a column whose header says ``unit`` is written in; None when it
        stays as it is.  A named derived kind (``angular_velocity``) wins; angular
        velocity and acceleration never follow the angle unit (rad/s unless named);
        another quotient takes each named base unit in place of the header's."""
        kind = header_kind(unit)
        if kind is None:
            return None
        own = OWN_UNIT.get(kind)
        if own is not None and own in self.units:
            return self.units[own]
        if kind.startswith("angle/time"):
            return None
        (top_unit, top), bottom = header_parts(unit)  # type: ignore[misc]
        shown = self.units.get(top, top_unit)
        if bottom is None:
            return None if top not in self.units else shown
        under, base, power = bottom
        if top not in self.units and base not in self.units:
            return None
        under = self.units.get(base, under)
        if power != 1:
            under = f"({under})^{power}" if re.search(r"[*/^]", under) else \
                f"{under}^{power}"
        if re.search(r"[*/]", under) and not under.startswith("("):
            under = f"({under})"
        return f"{shown}/{under}"

    def rounds(self, suffix: str) -> bool:
        """Whether floats written to a file of ``suffix`` are rounded."""
        wanted = self.digits is not None or self.decimals is not None
        return wanted and (suffix.lower() != ".parquet" or self.binary)


def parse_units(text: str | None, *, option: str = "--units") -> dict[str, str]:
    """``'omega=rpm, force=kN'`` -> ``{'angular_velocity': 'rpm', 'force': 'kN'}``; an
    :class:`~mechloop.output.paths.OutputError` naming the pair for an unknown kind, a
    pair without ``=`` or a unit of the wrong kind."""
    found: dict[str, str] = {}
    for item in (part.strip() for part in (text or "").split(",")):
        if not item:
            continue
        kind, sep, unit = (s.strip() for s in item.partition("="))
        kind = ALIASES.get(kind, kind)
        if not sep or not unit:
            raise OutputError(f"{option}: {item!r} is not KIND=UNIT",
                              "write pairs like 'omega=rpm,force=kN'")
        if kind not in UNIT_FIELDS:
            raise OutputError(f"{option}: unknown kind of quantity {kind!r} in {item!r}",
                              f"use one of {', '.join(UNIT_FIELDS)} (or omega, epsilon, "
                              "work)")
        problem = unit_problem(kind, unit)
        if problem is not None:
            raise OutputError(f"{option}: {problem[0]}", problem[1])
        found[kind] = unit
    return found


def unit_problem(kind: str, unit: str) -> tuple[str, str] | None:
    """(message, hint) when ``unit`` is not a unit of ``kind``, else None."""
    from mechloop.model.numbers import MAX_QUANTITY_CHARS
    from mechloop.model.units import _plain_powers
    from mechloop.views.display import Display
    from mechloop.views.figure import ViewError

    if not isinstance(unit, str) or len(unit) > MAX_QUANTITY_CHARS \
            or not _plain_powers(unit):  # pint computes powers of numbers exactly
        return (f"{str(unit)[:40]!r} is not a unit of at most {MAX_QUANTITY_CHARS} "
                "characters with small powers", f"{kind} takes a unit like "
                f"{UNIT_FIELDS[kind]}")
    try:
        Display(**{kind: unit})
    except ViewError as exc:
        return exc.message, exc.hint
    return None


def resolve(section: DisplaySection | None, units: str | None = None,
            digits: int | None = None, decimals: int | None = None) -> TableDisplay | None:
    """The table display of a model's ``display:`` section and the command line's
    ``--units``, ``--digits``, ``--decimals`` (the command line wins, kind by kind, and
    its precision replaces the file's); None when none of them asks for anything (the
    tables are then written exactly as always)."""
    named = dict(section.units()) if section is not None else {}
    named |= parse_units(units)
    for option, value, low in (("--digits", digits, 1), ("--decimals", decimals, 0)):
        if value is not None and not low <= value <= 15:
            raise OutputError(f"{option} {value} is out of range", f"use {low} to 15")
    if digits is not None and decimals is not None:
        raise OutputError("--digits and --decimals both given",
                          "give either significant digits or decimals")
    asked = digits is not None or decimals is not None
    if not asked and section is not None:
        digits, decimals = section.digits, section.decimals
    if not named and digits is None and decimals is None:
        return None
    return TableDisplay(named, digits, decimals, binary=asked)


def plot_display(td: TableDisplay | None) -> Display | None:
    """The plot display that agrees with the tables of ``td`` (None: the plot's own
    default, which agrees with the tables written without a display): the named units,
    angular velocity and acceleration in rad/s and rad/s^2 unless named, an angle inside
    another derived kind (m/rad, kg*m^2/rad, rad/rad) in the named angle unit or else in
    rad, the digits of the tables when given."""
    if td is None:
        return None
    from mechloop.views.display import Display

    table = {"angular_velocity": "rad/s", "angular_acceleration": "rad/s^2",
             "derived_angle": td.units.get("angle", "rad")}
    return Display(**(table | td.units), **({"digits": td.digits} if td.digits else {}))


def convert_frame(frame: pd.DataFrame, td: TableDisplay) -> pd.DataFrame:
    """``frame`` with every column of a named kind converted into the display unit and
    its header renamed (``F_bal [N]`` -> ``F_bal [kN]``); other columns as they were."""
    import pandas as pd

    columns = {}
    for name in frame.columns:
        values = frame[name]
        match = _HEADER.match(str(name))
        unit = td.target(match.group(2)) if match else None
        if unit is not None and values.dtype.kind == "f":
            factor = unit_factor(match.group(2), unit)
            values = values * factor if factor != 1.0 else values
            name = f"{match.group(1)} [{unit}]"
        columns[name] = values
    return pd.DataFrame(columns, index=frame.index)


@functools.cache
def unit_factor(source: str, target: str) -> float:
    """The factor that turns a number in ``source`` into ``target`` (pint)."""
    if source == target:
        return 1.0
    try:
        return float(registry().Quantity(1.0, source).to(target).magnitude)
    except pint.errors.PintError as exc:  # a header unit of another kind than expected
        raise OutputError(f"cannot write a column in {source} as {target}",
                          "name a unit of the column's kind") from exc


def round_significant(values: NDArray[np.float64], digits: int) -> NDArray[np.float64]:
    """``values`` rounded to ``digits`` significant digits: each the double nearest to a
    decimal of at most ``digits`` digits within half a unit of its last digit (a tie
    either way).  NaN, ±inf and 0 stay, and so does a value whose rounding would pass
    the largest double."""
    values = np.asarray(values, dtype=float)
    out = values.copy()
    finite = np.isfinite(values) & (values != 0)
    if not finite.any():
        return out
    x = values[finite]
    exponent = np.floor(np.log10(np.abs(x))).astype(np.int64)
    shift = digits - 1 - exponent
    exact = np.abs(shift) <= 22  # powers of ten held exactly by a double
    scaled = np.where(exact, x, 0.0)
    up = np.where(shift >= 0, 10.0 ** np.clip(shift, 0, 22), 1.0)
    down = np.where(shift < 0, 10.0 ** np.clip(-shift, 0, 22), 1.0)
    q = scaled * up / down
    rounded = np.rint(q) * down / up
    # q carries the error of a product and a quotient (a few units of its last place): near
    # a half it may round the wrong way, so those few values are rounded by their decimal
    # text, which Python rounds exactly
    tie = np.abs(np.abs(q - np.trunc(q)) - 0.5) <= 8 * np.spacing(np.abs(q))
    slow = ~exact | tie
    if slow.any():
        rounded[slow] = [float(f"{v:.{digits}g}") for v in x[slow]]
    out[finite] = np.where(np.isfinite(rounded), rounded, x)  # 1.5e308 to 1 digit: kept
    return out


def round_frame(frame: pd.DataFrame, td: TableDisplay) -> pd.DataFrame:
    """``frame`` with every float column rounded to the display's precision."""
    columns = {}
    for name in frame.columns:
        values = frame[name]
        if values.dtype.kind == "f":
            array = values.to_numpy(dtype=float)
            array = (round_significant(array, td.digits) if td.digits is not None
                     else np.round(array, td.decimals))
            values = array
        columns[name] = values
    import pandas as pd

    return pd.DataFrame(columns, index=frame.index)


def apply_display(frame: pd.DataFrame, td: TableDisplay | None, suffix: str = ".csv"
                  ) -> pd.DataFrame:
    """``frame`` converted into ``td``'s units and rounded as a file of ``suffix`` is
    (``frame`` itself when ``td`` is None)."""
    if td is None:
        return frame
    shown = convert_frame(frame, td) if td.units else frame
    return round_frame(shown, td) if td.rounds(suffix) else shown


def quantity(value: float, unit: str, td: TableDisplay | None, spec: str = ".6g") -> str:
    """``'value unit'`` for the console: ``value`` (in ``unit``, as a table header says
    it) converted into ``td``'s unit and printed with its precision; with no display, or
    no precision asked, printed with the format ``spec`` as before."""
    target = td.target(unit) if td is not None else None
    if target is not None:
        value, unit = value * unit_factor(unit, target), target
    return f"{number(value, td, spec)} {unit}"


def number(value: float, td: TableDisplay | None, spec: str = ".6g") -> str:
    """``value`` with ``td``'s digits or decimals, or the format ``spec``."""
    if td is not None and td.digits is not None:
        return f"{value:.{td.digits}g}"
    if td is not None and td.decimals is not None:
        return f"{value:.{td.decimals}f}"
    return f"{value:{spec}}"
