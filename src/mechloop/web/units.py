"""The choices of the page's Units tab (KDAM's units and tolerances panels): for each kind
of quantity of the model's ``display:`` section (:class:`mechloop.model.display.DisplaySection`)
the units offered — the ones the section's schema names (:data:`mechloop.model.display.UNIT_FIELDS`)
and then the further examples of :mod:`mechloop.views.display`, each one checked by
:func:`mechloop.output.display.unit_problem` — and the unit the tables use when the kind
is not named; and the range of the precision (``digits``, ``decimals``).
"""

from __future__ import annotations

import functools
from typing import Any

from mechloop.model.display import UNIT_FIELDS, DisplaySection
from mechloop.output.display import unit_problem
from mechloop.views.display import BASE_KINDS, DERIVED_EXAMPLES, DERIVED_KINDS, SI_DERIVED


def _listed(text: str) -> list[str]:
    return [unit.strip() for unit in text.split(",") if unit.strip()]


def default_unit(kind: str) -> str:
    """The unit a table column of ``kind`` is written in when the kind is not named:
    degrees for angles, SI for everything else (``'m'``, ``'rad/s'``, ``'kg*m^2'``)."""
    if kind == "angle":
        return "deg"
    if kind in BASE_KINDS:
        return BASE_KINDS[kind][0]
    return SI_DERIVED[DERIVED_KINDS[kind]]


def kind_units(kind: str) -> list[str]:
    """The units offered for ``kind``: the schema's list, then the views' further examples,
    without repeats, every one a unit of ``kind`` the section accepts."""
    more = BASE_KINDS[kind][1] if kind in BASE_KINDS else DERIVED_EXAMPLES.get(kind, "")
    units = list(dict.fromkeys([*_listed(UNIT_FIELDS[kind]), *_listed(more)]))
    return [unit for unit in units if unit_problem(kind, unit) is None]


@functools.cache
def unit_choices() -> dict[str, Any]:
    """``{"kinds": [{"kind", "default", "units"}, ...], "digits": [low, high],
    "decimals": [low, high]}``: the kinds in the order of the section's fields."""
    fields = DisplaySection.model_fields
    bounds = {}
    for name in ("digits", "decimals"):
        limits = {type(m).__name__: m for m in fields[name].metadata}
        bounds[name] = [limits["Ge"].ge, limits["Le"].le]
    return {"kinds": [{"kind": kind, "default": default_unit(kind), "units": kind_units(kind)}
                      for kind in UNIT_FIELDS], **bounds}
