"""The model's ``display:`` section: the units and precision its results are shown in.

KDAM's "units" and "current tolerances" panels: for each kind of quantity a unit (any pint
unit of that kind) and, for every number, a count of significant digits or of decimals.
The section applies to the ``solve`` tables, every export, ``energy``, ``simulate`` and the
plots (:mod:`mechloop.output.display`); a kind not named keeps the unit the tables have
always used (lengths m, angles deg, angular velocities rad/s, forces N, ...).

.. code-block:: yaml

    display:
      force: kN
      moment: kN*m
      angular_velocity: rpm
      digits: 6
"""

from __future__ import annotations

from pydantic import Field

from mechloop.errors import Problem
from mechloop.model.signals import _Frozen

#: The unit fields of the section: each one a kind of quantity of
#: :class:`mechloop.views.display.Display`, with units that work.
UNIT_FIELDS: dict[str, str] = {
    "length": "m, mm, cm", "angle": "deg, rad, grad", "time": "s, ms, min",
    "velocity": "m/s, mm/s", "acceleration": "m/s^2, mm/s^2",
    "angular_velocity": "rad/s, rpm, deg/s", "angular_acceleration": "rad/s^2, deg/s^2",
    "mass": "kg, g, t", "inertia": "kg*m^2, kg*cm^2", "force": "N, kN, kgf",
    "moment": "N*m, kN*m, kgf*m", "energy": "J, kJ, kgf*m", "power": "W, kW, hp"}

#: Other names a kind is known by on the command line and in the file.
ALIASES: dict[str, str] = {"omega": "angular_velocity", "epsilon": "angular_acceleration",
                           "work": "energy", "speed": "velocity"}


def _unit(kind: str) -> object:
    return Field(None, description=f"unit of {kind.replace('_', ' ')}: "
                 f"{UNIT_FIELDS[kind]} (default: as the tables have always shown it)")


class DisplaySection(_Frozen):
    """Units and precision of the results (KDAM's units and tolerances panels)."""

    length: str | None = _unit("length")
    angle: str | None = _unit("angle")
    time: str | None = _unit("time")
    velocity: str | None = _unit("velocity")
    acceleration: str | None = _unit("acceleration")
    angular_velocity: str | None = _unit("angular_velocity")
    angular_acceleration: str | None = _unit("angular_acceleration")
    mass: str | None = _unit("mass")
    inertia: str | None = _unit("inertia")
    force: str | None = _unit("force")
    moment: str | None = _unit("moment")
    energy: str | None = _unit("energy")
    power: str | None = _unit("power")
    digits: int | None = Field(None, ge=1, le=15, description="significant digits of every "
                               "number written (default: every digit of the double)")
    decimals: int | None = Field(None, ge=0, le=15, description="digits after the point of "
                                 "every number written (instead of digits)")

    def units(self) -> dict[str, str]:
        """The kinds named, kind -> unit."""
        return {kind: getattr(self, kind) for kind in UNIT_FIELDS
                if getattr(self, kind) is not None}


def check_display(section: DisplaySection | None) -> list[Problem]:
    """Every unit of ``section`` that is unknown or of the wrong kind, and digits given
    together with decimals, located at ``display.KIND``."""
    if section is None:
        return []
    from mechloop.output.display import unit_problem

    problems = []
    for kind, unit in section.units().items():
        found = unit_problem(kind, unit)
        if found is not None:
            problems.append(Problem(("display", kind), *found))
    if section.digits is not None and section.decimals is not None:
        problems.append(Problem(("display", "decimals"), "digits and decimals both given",
                                "give either significant digits or decimals"))
    return problems
