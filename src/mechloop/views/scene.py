"""What the planar and the 3-D scenes of a solved model share: their positions and the
colour of each vector (the same in every view of it).

:class:`VectorScene` is a mixin of :class:`mechloop.views.plan.PlanScene` and
:class:`mechloop.views.spatial_plan.SpatialScene`: each holds ``results`` (its
``broken`` mask over the positions ``(P,)``) and ``tails`` (vector number → its tail over
the positions).
"""

from __future__ import annotations

from typing import Any

import matplotlib


class VectorScene:
    """Positions and vector colours of a scene with ``results`` and ``tails``."""

    results: Any
    tails: dict[int, Any]

    @property
    def count(self) -> int:
        """Number of positions ``P = N + 1``."""
        return int(self.results.broken.size)

    def vectors(self) -> list[int]:
        """The vector numbers, in increasing order."""
        return sorted(self.tails)

    def color(self, number: int) -> tuple[float, float, float, float]:
        """The colour of vector ``number`` (the same in every view): the ``tab10``
        colour of its place among :meth:`vectors`, RGBA in [0, 1]."""
        return matplotlib.colormaps["tab10"](self.vectors().index(number) % 10)
