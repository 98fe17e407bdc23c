"""What the planar and the 3-D scenes of a solved model share: their positions and the
colour of each vector (the same in every view of it), and the check of the positions a
view is asked for.

:class:`VectorScene` is a mixin of :class:`mechloop.views.plan.PlanScene` and
:class:`mechloop.views.spatial_plan.SpatialScene`: each holds ``results`` (its
``broken`` mask over the positions ``(P,)``) and ``tails`` (vector number → its tail over
the positions).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import matplotlib
import numpy as np

from mechloop.views.figure import ViewError


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


def check_position(scene: VectorScene, position: int) -> int:
    """``position`` as an int in ``0..N``, or a :class:`ViewError`."""
    if isinstance(position, bool) or not isinstance(position, int | np.integer):
        raise ViewError(f"position {position!r} is not a position number",
                        f"use an integer 0..{scene.count - 1}")
    if not 0 <= int(position) < scene.count:
        raise ViewError(f"position {position} is outside the model's positions",
                        f"use 0..{scene.count - 1}")
    return int(position)


def check_positions(scene: VectorScene, positions: Iterable[int] | None) -> list[int]:
    """The chosen positions (default every one), each checked."""
    if positions is None:
        return list(range(scene.count))
    chosen = [check_position(scene, p) for p in positions]
    if not chosen:
        raise ViewError("no positions chosen", "give at least one position, or None for all")
    return chosen
