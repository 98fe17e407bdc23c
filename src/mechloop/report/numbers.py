"""Numbers and units of the report as text, in the user's display units and precision.

A :class:`Shown` turns a value in the unit a result table's header names (``'m'``,
``'deg'``, ``'N*m'``, ``'kg*m^2/rad'``) into the unit of the model's ``display:``
section (:meth:`mechloop.output.display.TableDisplay.target`) and prints it with its
precision: ``digits`` significant digits (default :data:`DEFAULT_DIGITS`) or ``decimals``
after the point.  A column of numbers is printed to the precision of its largest value,
so that a value that is zero to that precision is printed as 0 (not ``5.04e-15``).

Units are printed as the typesetters show them: ``N·m``, ``m/s²``, ``°``; in Russian in
the Russian designations (GOST 8.417: ``Н·м``, ``м/с²``, ``об/мин``).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from mechloop.output.display import TableDisplay, unit_factor
from mechloop.views.decimal_mark import localized
from mechloop.views.unit_words import unit_text

#: Significant digits of a number when the model's display: section gives none.
DEFAULT_DIGITS = 5

def _decimals(scale: float, digits: int) -> int | None:
    """Decimals that print a number of size ``scale`` with ``digits`` significant digits;
    None when it is printed with an exponent (below 10⁻³ or from 10⁹)."""
    if scale == 0 or not math.isfinite(scale):
        return max(digits - 1, 0)
    if not 1e-3 <= scale < 1e9:
        return None
    return max(0, digits - 1 - math.floor(math.log10(scale)))


def _strip(text: str) -> str:
    if "." in text and "e" not in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


@dataclass(frozen=True)
class Shown:
    """The units and precision of the report's numbers: ``td`` the model's display (None:
    the tables' own units and :data:`DEFAULT_DIGITS` digits) and ``lang``."""

    td: TableDisplay | None
    lang: str

    @property
    def digits(self) -> int:
        return self.td.digits if self.td is not None and self.td.digits else DEFAULT_DIGITS

    @property
    def decimals(self) -> int | None:
        return self.td.decimals if self.td is not None else None

    def unit(self, unit: str) -> str:
        """The display unit (pint's notation) of values a table header gives in
        ``unit``."""
        target = self.td.target(unit) if self.td is not None else None
        return target or unit

    def factor(self, unit: str) -> float:
        """The factor from ``unit`` to :meth:`unit`."""
        return unit_factor(unit, self.unit(unit))

    def unit_text(self, unit: str) -> str:
        """The printed display unit of values given in ``unit``."""
        return unit_text(self.unit(unit), self.lang)

    def number(self, value: float, scale: float | None = None) -> str:
        """``value`` (already in its display unit) to the display's precision, written as
        the language writes numbers (Russian: ``1,5``, ``1,5·10⁻⁵``); a value that is zero
        to the precision of a number of size ``scale`` (default its own) is '0'.  Not
        finite: '—'."""
        return localized(self._number(value, scale), self.lang)

    def _number(self, value: float, scale: float | None = None) -> str:
        if value is None or not np.isfinite(value):
            return "—"
        value = float(value)
        if self.decimals is not None:
            return _strip(f"{value:.{self.decimals}f}")
        size = abs(value) if scale is None else scale
        decimals = _decimals(size, self.digits)
        if decimals is None:
            if scale is not None and abs(value) < 0.5 * 10.0 ** (
                    math.floor(math.log10(scale)) - self.digits + 1):
                return "0"
            mantissa, exponent = f"{value:.{self.digits - 1}e}".split("e")
            return f"{_strip(mantissa)}e{int(exponent)}"
        return _strip(f"{value:.{decimals}f}")

    def column(self, values: Iterable[float]) -> list[str]:
        """Numbers of one column, each to the precision of the column's largest one."""
        array = np.asarray(list(values), dtype=float)
        finite = array[np.isfinite(array)]
        scale = float(np.max(np.abs(finite))) if finite.size else 0.0
        return [self.number(v, scale) for v in array]

    def value(self, value: float, unit: str) -> float:
        """``value`` in ``unit`` converted into its display unit."""
        return value * self.factor(unit)

    def text(self, value: float, unit: str, scale: float | None = None) -> str:
        """'1.5 kN', '30°': ``value`` given in ``unit`` in its display unit."""
        shown = self.number(self.value(value, unit),
                            None if scale is None else scale * self.factor(unit))
        return joined(shown, self.unit_text(unit))

    def span(self, low: float, high: float, unit: str) -> str:
        """'from … to … unit' as 'low … high unit' to the precision of the larger."""
        f = self.factor(unit)
        scale = max(abs(low * f), abs(high * f))
        return joined(f"{self.number(low * f, scale)} … {self.number(high * f, scale)}",
                      self.unit_text(unit))

    def angle(self, radians: float) -> str:
        """An angle given in radians, in the display's angle unit."""
        return self.text(math.degrees(radians), "deg")


def joined(number: str, unit: str) -> str:
    """A number and its unit: '30°' (no space before the degree sign), '1.5 kN'."""
    if not unit:
        return number
    return f"{number}{unit}" if unit == "°" else f"{number} {unit}"
