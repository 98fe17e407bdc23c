"""Units at the edges: pint converts model-file numbers to SI floats and radians.

The core never sees a unit: lengths are metres and angles radians once a model is compiled.
"""

from __future__ import annotations

import functools
import math
import re
from typing import Literal

import pint

from mechloop.model.numbers import MAX_QUANTITY_CHARS, RANGE, flush, usable

Kind = Literal["length", "angle", "mass", "inertia", "force", "moment", "acceleration",
               "pressure"]

#: What each kind of quantity is called in messages and which unit is SI for it.
SI_UNIT: dict[Kind, str] = {"length": "m", "angle": "rad", "mass": "kg",
                            "inertia": "kg*m^2", "force": "N", "moment": "N*m",
                            "acceleration": "m/s^2", "pressure": "Pa"}
EXAMPLES: dict[Kind, str] = {"length": "m, cm, mm", "angle": "deg, rad, grad",
                             "mass": "kg, g, t", "inertia": "kg*m^2, g*cm^2",
                             "force": "N, kN, kgf", "moment": "N*m, kN*m, kgf*m",
                             "acceleration": "m/s^2, g0", "pressure": "Pa, kPa, MPa, bar"}
SAMPLE: dict[Kind, str] = {"length": "50 mm", "angle": "90 deg", "mass": "2 kg",
                           "inertia": "0.01 kg*m^2", "force": "1000 N",
                           "moment": "50 N*m", "acceleration": "9.81 m/s^2",
                           "pressure": "0.1 MPa"}


class UnitProblem(ValueError):
    """A unit or quantity string that cannot be used; ``hint`` says what would work."""

    def __init__(self, message: str, hint: str):
        super().__init__(message)
        self.message = message
        self.hint = hint


@functools.cache
def registry() -> pint.UnitRegistry:
    """The one pint registry of mechloop (built on first use: it takes ~0.2 s)."""
    return pint.UnitRegistry()


def _a(kind: str) -> str:
    return ("an " if kind[0] in "aeiou" else "a ") + kind


def _is_kind(unit: pint.Unit, kind: Kind) -> bool:
    if kind == "angle":
        return unit.dimensionless and str(unit) != "dimensionless"
    return unit.dimensionality == registry().parse_units(SI_UNIT[kind]).dimensionality


@functools.cache
def unit_factor(name: str, kind: Kind) -> float:
    """Factor that converts a number in unit ``name`` to SI (m or rad)."""
    if len(str(name)) > MAX_QUANTITY_CHARS or not _plain_powers(str(name)):
        raise UnitProblem(f"{str(name)[:40]!r} is not a unit of a length of at most "
                          f"{MAX_QUANTITY_CHARS} characters with small powers",
                          f"use a {kind} unit: {EXAMPLES[kind]}")
    try:
        unit = registry().parse_units(str(name).strip())
    except (pint.errors.UndefinedUnitError, pint.errors.DefinitionSyntaxError,
            AttributeError, TypeError, ValueError, AssertionError, RecursionError) as exc:
        raise UnitProblem(f"unknown unit {name!r}", f"use a {kind} unit: {EXAMPLES[kind]}"
                          ) from exc
    if not _is_kind(unit, kind):
        raise UnitProblem(f"{name!r} is not {_a(kind)} unit",
                          f"use a {kind} unit: {EXAMPLES[kind]}")
    return float(registry().Quantity(1.0, unit).to(SI_UNIT[kind]).magnitude)


def to_si(value: float | str, kind: Kind, default_unit: str) -> float:
    """Convert a model-file value to SI.

    ``value`` is a number in ``default_unit`` or a string with its own unit ("50 mm").
    Raises :class:`UnitProblem` for an unreadable string, a unit of the wrong kind, or a
    value that is not finite or larger than :data:`~mechloop.model.numbers.MAX_MAGNITUDE`
    (in the file's units or in SI).
    """
    if not isinstance(value, str):
        return _usable(float(value), value, kind, unit_factor(default_unit, kind))
    text = value.strip()
    if len(text) > MAX_QUANTITY_CHARS:
        raise UnitProblem(f"a quantity of {len(text)} characters",
                          f"write a number and a unit like '{SAMPLE[kind]}'")
    try:
        number = float(text)
    except ValueError:
        pass
    else:
        return _usable(number, value, kind, unit_factor(default_unit, kind))
    if not _plain_powers(text):
        raise UnitProblem(f"cannot read {value!r} as {_a(kind)}: only units take powers, "
                          "by a small number", f"write a number and a unit like "
                          f"'{SAMPLE[kind]}' or '2 kg*m^2'")
    try:
        qty = registry().Quantity(text)
    except Exception as exc:  # pint raises many types for unreadable text
        raise UnitProblem(f"cannot read {value!r} as {_a(kind)}",
                          f"write a number, or a number and a unit like "
                          f"'{SAMPLE[kind]}'") from exc
    if not isinstance(qty, pint.Quantity) or (
        kind != "angle" and qty.dimensionless
    ) or (kind == "angle" and qty.unitless):
        raise UnitProblem(f"{value!r} has no {kind} unit",
                          f"write a plain number (model units) or a number with a {kind} "
                          f"unit ({EXAMPLES[kind]})")
    if not _is_kind(qty.units, kind):
        raise UnitProblem(f"{value!r} is not {_a(kind)}",
                          f"use a {kind} unit: {EXAMPLES[kind]}")
    try:
        number = float(qty.magnitude)
    except OverflowError:  # an integer beyond float, e.g. 10**400
        number = math.inf
    return _usable(number, value, kind, float(qty.to(SI_UNIT[kind]).magnitude) / number
                   if usable(number) and number != 0 else 1.0)


_POWER = re.compile(r"\*\*|\^")
_EXPONENT = re.compile(r"\(?\s*[-+]?\d{1,2}(\.\d+)?\s*\)?(?![\d.]|\s*(\*\*|\^))")


def _plain_powers(text: str) -> bool:
    """Whether every power in ``text`` raises a unit name (or a group without numbers) to
    a number of at most two digits: pint computes powers of numbers exactly, so
    ``9**9**9`` would never finish."""
    for match in _POWER.finditer(text):
        before = text[:match.start()].rstrip()
        if not _EXPONENT.match(text[match.end():].lstrip()):
            return False
        if before.endswith(")"):
            if any(c.isdigit() for c in before[before.rfind("("):]):
                return False
        elif not before or not (before[-1].isalpha() or before[-1] in "_°µΩ"):
            return False
    return True


def _usable(number: float, value: float | str, kind: Kind, factor: float) -> float:
    """``number · factor`` (SI; 0 when it is below
    :data:`~mechloop.model.numbers.MIN_MAGNITUDE` in size), or a :class:`UnitProblem` when
    ``number`` or the result is not finite or larger than
    :data:`~mechloop.model.numbers.MAX_MAGNITUDE`."""
    si = flush(number * factor) if usable(number) else math.inf
    if not usable(si):
        raise UnitProblem(f"{value!r} is outside the range of {_a(kind)} ({RANGE}, in the "
                          f"file's units and in {SI_UNIT[kind]})",
                          f"write {_a(kind)} like '{SAMPLE[kind]}'")
    return si
