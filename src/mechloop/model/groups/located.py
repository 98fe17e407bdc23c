"""What building a group file gives beside the vector model: where each named point is
(:class:`PointLocation`), which parameter carries each dimension (:class:`Carrier`), and
both with the model (:class:`BuiltModel`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from mechloop.model.dynamic import (
    HeadPoint,
    TailPoint,
)
from mechloop.model.schema import Model
from mechloop.model.units import to_si


@dataclass(frozen=True)
class Carrier:
    """A vector parameter that carries a dimension: ``part`` of parameter ``parameter``
    equals the dimension plus ``shift`` (model units).  ``part`` is ``value`` (the
    constant itself), ``delta`` (of a link role) or ``offset`` (of an argument role)."""

    parameter: str
    part: Literal["value", "delta", "offset"]
    shift: float = 0.0

    @property
    def target(self) -> str:
        """``r2``, ``a5.delta`` or ``a1.offset``: what to set."""
        return self.parameter if self.part == "value" else f"{self.parameter}.{self.part}"

    def __str__(self) -> str:
        return self.target if self.shift == 0 else f"{self.target} ({self.shift:+g})"


@dataclass(frozen=True)
class PointLocation:
    """Where a named point is in the generated model.

    ``start`` are the coordinates (model length units) of the ground point its chain starts
    at, ``vectors`` the chain: the point is ``start + Σ sign(k)·vector |k|``; ``end`` is a
    vector end at the point (``None`` for a ground point no vector touches); ``links`` the
    links that carry it.
    """

    name: str
    start: tuple[float, float]
    vectors: tuple[int, ...]
    end: TailPoint | HeadPoint | None
    links: tuple[str, ...]

    def xy(self, results: Any) -> tuple[Any, Any]:
        """x, y (m) of the point over the positions of solved ``results``, shape (P,)."""
        unit = results.model.units.length
        z = complex(to_si(self.start[0], "length", unit), to_si(self.start[1], "length", unit))
        total = np.full(results.broken.size, z, dtype=complex)
        for k in self.vectors:
            n = abs(k)
            total = total + math.copysign(1.0, k) * results.value(f"r{n}") * np.exp(
                1j * results.value(f"a{n}"))
        return total.real, total.imag


@dataclass(frozen=True)
class BuiltModel:
    """A generated vector model and what it means: body numbers of the links (ground 0),
    the location of every named point, and the parameters that carry each dimension
    (keys are paths in the mechanism's document, e.g. ``groups[0].lengths[1]``,
    ``points.P.angle``, ``ground.C.distance``)."""

    model: Model
    links: dict[str, int]
    points: dict[str, PointLocation]
    dimensions: dict[str, tuple[Carrier, ...]]
    formula: str
