"""Display units and precision of the views (KDAM's "units" and "current tolerances" panels).

The core is SI (m, rad, s, kg, N); a :class:`Display` says in which units a view shows each
kind of quantity and with how many significant digits it prints numbers.  Conversion is by
pint (:func:`mechloop.model.units.registry`), so any pint unit of the right kind works:
``Display(length="mm", angle="deg", force="kgf", power="hp", angular_velocity="rpm")``.

A *kind* is one of :data:`BASE_KINDS` (``"length"``, ``"angle"``, ``"force"``, ...), one of
the named derived kinds in :data:`DERIVED_KINDS` (``"velocity"`` is ``"length/time"``,
``"angular_velocity"`` is ``"angle/time"``, ...), or a quotient of products of base kinds
written the same way (``"inertia/angle"``, ``"length/angle^2"``).  A derived unit follows
the base units, except that an angle inside a derived kind is in ``derived_angle``
(default ``"rad"``, as the result tables write it): angles are shown in degrees, but an
angular velocity in rad/s, an analog ``dφ/dφ1`` in rad/rad (a plain number), ``dr/dφ1``
in m/rad and ``dJ_red`` in kg*m^2/rad — unless ``angular_velocity`` names its own unit
(``"rpm"``) or ``derived_angle=None`` makes the derived kinds follow ``angle``.

>>> d = Display(force="kgf")
>>> round(float(d.convert(9.80665, "force")), 9), d.label("force")
(1.0, 'kgf')
>>> d.label("angle"), d.label("angular_velocity"), d.label("angular_acceleration")
('deg', 'rad/s', 'rad/s^2')
>>> d.label("length/angle"), d.label("inertia/angle"), d.label("angle/angle")
('m/rad', 'kg*m^2/rad', 'rad/rad')
>>> Display(derived_angle=None).label("angular_velocity")
'deg/s'
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass, fields

import numpy as np
import pint
from numpy.typing import ArrayLike, NDArray

from mechloop.model.units import registry
from mechloop.views.figure import ViewError

#: Base kinds: the Display field that holds the unit, the SI unit and units that work.
BASE_KINDS: dict[str, tuple[str, str]] = {
    "length": ("m", "m, cm, mm, in"),
    "angle": ("rad", "deg, rad, grad, turn"),
    "time": ("s", "s, ms, min"),
    "mass": ("kg", "kg, g, t"),
    "inertia": ("kg*m^2", "kg*m^2, kg*cm^2, g*cm^2"),
    "force": ("N", "N, kN, kgf"),
    "moment": ("N*m", "N*m, kN*m, kgf*m"),
    "power": ("W", "W, kW, hp"),
    "energy": ("J", "J, kJ, kgf*m"),
}

#: Named derived kinds and the quotient of base kinds each one stands for.
DERIVED_KINDS: dict[str, str] = {
    "velocity": "length/time",
    "acceleration": "length/time^2",
    "angular_velocity": "angle/time",
    "angular_acceleration": "angle/time^2",
    "specific_power": "power/mass",
}

#: Derived kinds whose unit can be named on its own (instead of following the base units):
#: the quotient and the Display field that names it.
OVERRIDES: dict[str, str] = {
    "angle/time": "angular_velocity",
    "angle/time^2": "angular_acceleration",
    "length/time": "velocity",
    "length/time^2": "acceleration",
}
#: The SI unit of each derived kind that can be named on its own.
SI_DERIVED: dict[str, str] = {"angle/time": "rad/s", "angle/time^2": "rad/s^2",
                              "length/time": "m/s", "length/time^2": "m/s^2"}
#: Units that work for the derived kinds that can be named on their own.
DERIVED_EXAMPLES: dict[str, str] = {"angular_velocity": "rad/s, rpm, deg/s",
                                    "angular_acceleration": "rad/s^2, deg/s^2",
                                    "velocity": "m/s, mm/s, km/h",
                                    "acceleration": "m/s^2, mm/s^2, g0"}

_FACTOR = re.compile(r"^([a-z_]+)(?:\^(\d+))?$")


@functools.cache
def _parse_kind(kind: str) -> tuple[tuple[tuple[str, int], ...], tuple[tuple[str, int], ...]]:
    """``"inertia/angle^2"`` -> ``((("inertia", 1),), (("angle", 2),))``; ViewError if the
    text is not a quotient of products of base kinds."""
    text = DERIVED_KINDS.get(kind, kind).replace(" ", "")
    parts = text.split("/")
    if not 1 <= len(parts) <= 2 or not parts[0]:
        raise _unknown_kind(kind)
    out = []
    for part in parts:
        factors = []
        for factor in part.split("*") if part != "1" else []:
            match = _FACTOR.match(factor)
            if match is None or match.group(1) not in BASE_KINDS:
                raise _unknown_kind(kind)
            factors.append((match.group(1), int(match.group(2) or 1)))
        out.append(tuple(factors))
    return out[0], (out[1] if len(out) == 2 else ())


def _unknown_kind(kind: str) -> ViewError:
    return ViewError(f"unknown kind of quantity {kind!r}",
                     f"use one of {', '.join([*BASE_KINDS, *DERIVED_KINDS])}, or a quotient "
                     "of them such as 'inertia/angle' or 'length/time^2'")


def _unit(text: str) -> pint.Unit:
    return registry().parse_units(text)


def _power(unit: str, exponent: int) -> str:
    if exponent == 1:
        return unit
    return f"({unit})^{exponent}" if re.search(r"[*/^]", unit) else f"{unit}^{exponent}"


def _is_derived(top: tuple, bottom: tuple) -> bool:
    """Whether a parsed kind is derived (not one base kind to the first power)."""
    return bool(bottom) or len(top) != 1 or top[0][1] != 1


def _check_unit(name: str, unit: str, kind: str) -> None:
    """ViewError unless ``unit`` is a pint unit of ``kind``."""
    si = BASE_KINDS[kind][0] if kind in BASE_KINDS else SI_DERIVED[DERIVED_KINDS[kind]]
    works = BASE_KINDS[kind][1] if kind in BASE_KINDS else DERIVED_EXAMPLES[kind]
    try:
        parsed = _unit(str(unit).strip())
    except (pint.errors.PintError, AttributeError, TypeError, ValueError,
            AssertionError) as exc:
        raise ViewError(f"unknown display unit {name}={unit!r}",
                        f"{name} takes a {kind} unit: {works}") from exc
    try:
        registry().Quantity(1.0, parsed).to(si)
    except pint.errors.DimensionalityError as exc:
        raise ViewError(f"display unit {name}={unit!r} is not a unit of {kind}",
                        f"{name} takes a {kind} unit: {works}") from exc
    plain = parsed.dimensionless and str(parsed) in ("dimensionless", "")
    if kind in ("angle", "angular_velocity", "angular_acceleration") and plain:
        raise ViewError(f"display unit {name}={unit!r} is not a unit of {kind}",
                        f"{name} takes a {kind} unit: {works}")


@dataclass(frozen=True)
class Display:
    """Units and precision of the numbers a view shows.

    Each field is a pint unit for one kind of quantity; ``angular_velocity`` overrides
    the derived ``angle/time`` (None: derived, e.g. deg/s) — ``"rpm"`` for machine speed.
    ``derived_angle`` is the unit of an angle inside a derived kind (a rate, an analog,
    a quantity per angle; None: the same as ``angle``) — by default rad, so that only
    angles themselves are in degrees, as in the result tables.
    ``digits`` is the number of significant digits in tables and legends.  An unknown
    unit, or one of the wrong kind, raises :class:`~mechloop.views.figure.ViewError`.
    """

    length: str = "m"
    angle: str = "deg"
    force: str = "N"
    moment: str = "N*m"
    power: str = "W"
    mass: str = "kg"
    inertia: str = "kg*m^2"
    time: str = "s"
    digits: int = 4
    energy: str = "J"
    angular_velocity: str | None = None
    angular_acceleration: str | None = None
    velocity: str | None = None
    acceleration: str | None = None
    derived_angle: str | None = "rad"

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name in BASE_KINDS:
                _check_unit(f.name, value, f.name)
            elif f.name in OVERRIDES.values() and value is not None:
                _check_unit(f.name, value, f.name)
            elif f.name == "derived_angle" and value is not None:
                _check_unit(f.name, value, "angle")
        if not isinstance(self.digits, int) or not 1 <= self.digits <= 15:
            raise ViewError(f"digits={self.digits!r} is not a number of significant digits",
                            "use an integer from 1 to 15")

    def _override(self, kind: str) -> str | None:
        """The unit named for a derived kind (``angular_velocity="rpm"``), or None."""
        name = OVERRIDES.get(DERIVED_KINDS.get(kind, kind).replace(" ", ""))
        return None if name is None else getattr(self, name)

    def _base(self, kind: str, *, derived: bool) -> str:
        """The unit of base ``kind``, alone or (``derived``) inside a derived kind."""
        if kind == "angle" and derived and self.derived_angle is not None:
            return self.derived_angle
        return getattr(self, kind)

    def _units(self, kind: str) -> tuple[str, str]:
        """(SI unit, display unit) of ``kind`` as pint-readable text."""
        named = self._override(kind)
        if named is not None:
            return SI_DERIVED[DERIVED_KINDS.get(kind, kind).replace(" ", "")], named
        top, bottom = _parse_kind(kind)

        def text(factors, unit_of) -> str:
            return "*".join(f"({unit_of(k)})**{n}" for k, n in factors) or "1"

        def si(k):
            return BASE_KINDS[k][0]

        derived = _is_derived(top, bottom)

        def shown(k):
            return self._base(k, derived=derived)

        return (f"{text(top, si)}/({text(bottom, si)})",
                f"{text(top, shown)}/({text(bottom, shown)})")

    def factor(self, kind: str) -> float:
        """The number that turns an SI value of ``kind`` into display units."""
        si, shown = self._units(kind)
        return _factor(si, shown)

    def convert(self, values_si: ArrayLike, kind: str) -> NDArray[np.float64]:
        """``values_si`` (SI, any shape) in the display unit of ``kind``, same shape.

        The values are returned unchanged (not even copied through a multiplication by
        1.0) when the display unit is the SI one, so drawn data can equal the results.
        """
        values = np.asarray(values_si, dtype=float)
        k = self.factor(kind)
        return values if k == 1.0 else values * k

    def label(self, kind: str) -> str:
        """The display unit of ``kind`` as it is printed: ``'deg/s^2'``, ``'kgf'``."""
        named = self._override(kind)
        if named is not None:
            return named
        top, bottom = _parse_kind(kind)
        derived = _is_derived(top, bottom)
        num = "*".join(_power(self._base(k, derived=derived), n) for k, n in top) or "1"
        if not bottom:
            return num
        den = "*".join(_power(self._base(k, derived=True), n) for k, n in bottom)
        if len(bottom) > 1 or (re.search(r"[*/]", den) and not den.startswith("(")):
            den = f"({den})"
        return f"{num}/{den}"

    def format(self, value: float) -> str:
        """``value`` with :attr:`digits` significant digits (``'—'`` for NaN)."""
        if not np.isfinite(value):
            return "—"
        return f"{value:.{self.digits}g}"


@functools.cache
def _factor(si: str, shown: str) -> float:
    if si == shown:
        return 1.0
    return float(registry().Quantity(1.0, si).to(shown).magnitude)


#: The display a view uses when given none: SI units, angles in degrees, every derived
#: angle in rad (rad/s, rad/s^2, m/rad, kg*m^2/rad, as the tables), 4 digits.
DEFAULT_DISPLAY = Display()
