"""Springs and dampers of a model file: loads that follow the state of the mechanism.

A **spring** joins a point of one body to a point of another (``bodies``, ``ends``: points
given as for forces, ``{head: 3}``...).  Its tension (positive: it pulls the ends together)
at length ``l`` is ``stiffness·(l − free_length) + preload``, or read from ``table`` of
``[length, tension]`` pairs (linear between them, the end slopes held beyond).

A **damper** between two points resists their relative speed along the line that joins
them: tension ``coefficient·l̇`` (or the ``table`` of ``[speed, tension]`` pairs, speeds
≥ 0, mirrored for negative speeds); without ``ends`` it is a damper in the joint of its two
``bodies``: a moment ``coefficient·(ω₂ − ω₁)`` against their relative rotation.

Numbers are in the model's units: a stiffness in force units per length unit, a linear
coefficient in force units·s per length unit (in a joint: moment units·s per rad), speeds
in length units per second.
"""

from __future__ import annotations

from itertools import pairwise

from pydantic import Field, model_validator

from mechloop.model.dynamic import PointOn
from mechloop.model.numbers import Number
from mechloop.model.signals import _Frozen


def _increasing(table: list[tuple[float, float]] | None, what: str) -> None:
    if table is not None and not all(a[0] < b[0] for a, b in pairwise(table)):
        raise ValueError(f"the {what} of the table must increase")


class Spring(_Frozen):
    """A spring between a point of ``bodies[0]`` (``ends[0]``) and one of ``bodies[1]``
    (``ends[1]``): linear (``stiffness``, ``free_length``, ``preload``) or a ``table``."""

    bodies: tuple[int, int] = Field(description="the bodies of the two ends (0: ground)")
    ends: tuple[PointOn, PointOn] = Field(description="the two attachment points")
    stiffness: Number | None = Field(None, ge=0, description="force units per length unit")
    free_length: Number | None = Field(None, ge=0, description="length at which the "
                                       "linear spring's tension is the preload (length "
                                       "units)")
    preload: Number = Field(0.0, description="tension at the free length (force units)")
    table: list[tuple[Number, Number]] | None = Field(
        None, min_length=2, description="[length, tension] pairs, lengths increasing "
        "(length and force units): instead of stiffness and free_length")
    name: str | None = None

    @model_validator(mode="after")
    def _one_law(self) -> Spring:
        linear = self.stiffness is not None or self.free_length is not None
        if linear == (self.table is not None) or (
                linear and (self.stiffness is None or self.free_length is None)):
            raise ValueError("give either stiffness and free_length (a linear spring) or "
                             "a table of [length, tension]")
        _increasing(self.table, "lengths")
        return self


class Damper(_Frozen):
    """A damper between two points (``ends``) or, without ``ends``, in the joint of its two
    ``bodies``: a linear ``coefficient`` or a ``table`` of tension (moment) against the
    relative speed."""

    bodies: tuple[int, int] = Field(description="the bodies of the two ends, or the two "
                                    "bodies of the joint (0: ground)")
    ends: tuple[PointOn, PointOn] | None = Field(None, description="the two attachment "
                                                 "points (default: a rotary damper in "
                                                 "the joint of the bodies)")
    coefficient: Number | None = Field(None, ge=0, description="force units·s per length "
                                       "unit (in a joint: moment units·s per rad)")
    table: list[tuple[Number, Number]] | None = Field(
        None, min_length=2, description="[relative speed ≥ 0, tension] pairs, speeds "
        "increasing (length units/s or rad/s; force or moment units), mirrored for "
        "negative speeds")
    name: str | None = None

    @model_validator(mode="after")
    def _one_law(self) -> Damper:
        if (self.coefficient is None) == (self.table is None):
            raise ValueError("give either a coefficient or a table of [speed, tension]")
        _increasing(self.table, "speeds")
        if self.table is not None and self.table[0][0] < 0:
            raise ValueError("the speeds of a damper's table start at 0 or above (the "
                             "table is mirrored for negative speeds)")
        return self
