"""A direction given in a model with spatial contours (``direction: [x, y, z]`` of a
force, ``axis: [x, y, z]`` of a moment or a joint) as a unit vector."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import Problem


def unit_of(values: Sequence[float], path: tuple, problems: list[Problem]
            ) -> NDArray[np.float64] | None:
    """``values`` (any length unit, shape ``(3,)``) divided by its length: a unit vector
    ``(3,)``, or None with a problem at ``path`` when every component is 0."""
    d = np.array([float(x) for x in values])
    size = float(np.linalg.norm(d))
    if not size > 0:
        problems.append(Problem(path, "a direction needs a non-zero component",
                                "give [x, y, z] with at least one component not 0"))
        return None
    return d / size
