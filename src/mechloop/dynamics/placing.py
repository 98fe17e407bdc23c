"""Placing the contours of a solved model: each from its start, walked along its vectors.

A contour is a closed loop: it fixes where its points are relative to each other, not
where they are.  Each contour is placed by its ``start`` — the origin by default, an end
of a vector of another contour (placed first), or fixed coordinates ``[x, y]`` (in the
XY plane) — and walked along its ``vectors`` list: a vector listed with a plus sign has
its tail at the current point, one listed with a minus sign (subtracted, spatial contours
only) has its head there.

:class:`ContourPlacement` is that walk for any kind of motion: the planar
:class:`~mechloop.dynamics.points.Placement` (complex points) and the spatial
:class:`~mechloop.spatial.points.Placement3` (``(3, P)`` points) only say what a point
at rest is.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Generic, Protocol, Self, TypeVar

from mechloop.errors import ModelError, Problem
from mechloop.model.dynamic import TailPoint
from mechloop.model.units import to_si


class _Motion(Protocol):
    def __add__(self, other: Self) -> Self: ...

    def __sub__(self, other: Self) -> Self: ...


M = TypeVar("M", bound=_Motion)


class ContourPlacement(Generic[M]):
    """Tails and heads of every vector of solved ``results`` (``results.model`` its
    model, ``results.broken`` its positions ``(P,)``), as motions ``M`` over the
    positions.

    ``vectors`` maps every vector's number to its motion (from tail to head); ``starts``
    (optional) maps a contour's index to the position it starts at (a position array of
    the kind :meth:`_at_rest` takes), overriding its model's ``start``.  Raises
    :class:`~mechloop.errors.ModelError` for starts that refer to each other in a cycle,
    to a vector that does not exist or to a vector of the contour itself.
    """

    def __init__(self, results: Any, vectors: dict[int, M],
                 starts: Mapping[int, Any] | None = None):
        self.results = results
        self._starts = dict(starts or {})
        self._vectors = vectors
        self._tails: dict[int, M] = {}
        model = results.model
        self._contour_of = {abs(v): i for i, c in enumerate(model.contours)
                            for v in c.vectors}
        for index in range(len(model.contours)):
            self._place(index, ())

    # what a kind of motion says ---------------------------------------------------------

    def _at_rest(self, position: Any | None) -> M:
        """A point that does not move: at ``position`` (a position array over the
        positions, m), or at the origin for ``None``."""
        raise NotImplementedError

    def _fixed(self, x: float, y: float) -> Any:
        """The position array of the fixed point ``(x, y)`` (m) of the XY plane."""
        raise NotImplementedError

    # the walk ---------------------------------------------------------------------------

    def _place(self, index: int, visiting: tuple[int, ...]) -> None:
        contour = self.results.model.contours[index]
        if abs(contour.vectors[0]) in self._tails:
            return
        if index in visiting:
            raise ModelError([Problem(("contours", index, "start"),
                                      "the starts of contours refer to each other in a cycle",
                                      "start one of them at the origin or at fixed "
                                      "coordinates [x, y]")])
        current = self._start(index, contour.start, (*visiting, index))
        for entry in contour.vectors:
            number = abs(entry)
            if entry > 0 or not contour.spatial:
                self._tails[number] = current
                current = current + self._vectors[number]
            else:  # subtracted: the walk runs from its head to its tail
                current = current - self._vectors[number]
                self._tails[number] = current

    def _start(self, index: int, start, visiting: tuple[int, ...]) -> M:
        if index in self._starts:
            return self._at_rest(self._starts[index])
        if isinstance(start, str):
            return self._at_rest(None)
        if isinstance(start, tuple | list):
            units = self.results.model.units.length
            x, y = (to_si(c, "length", units) for c in start)
            return self._at_rest(self._fixed(x, y))
        number = start.tail if isinstance(start, TailPoint) else start.head
        if number not in self._contour_of:
            raise ModelError([Problem(("contours", index, "start"),
                                      f"vector {number} does not exist",
                                      f"use one of {sorted(self._contour_of)}")])
        other = self._contour_of[number]
        if other == index:
            raise ModelError([Problem(("contours", index, "start"),
                                      f"vector {number} is in this contour",
                                      "start a contour at a point of another contour")])
        self._place(other, visiting)
        return self.tail(number) if isinstance(start, TailPoint) else self.head(number)

    # the placed vectors -----------------------------------------------------------------

    def vector(self, number: int) -> M:
        """Vector ``number`` from its tail to its head."""
        return self._vectors[number]

    def tail(self, number: int) -> M:
        """The tail of vector ``number``."""
        return self._tails[number]

    def head(self, number: int) -> M:
        """The head of vector ``number``."""
        return self._tails[number] + self._vectors[number]
