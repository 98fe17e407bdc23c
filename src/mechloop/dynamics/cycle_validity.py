"""Whether the figures of a cycle (work over the cycle, the loss coefficient ψ, the
efficiency η, the machine's δ and flywheel) are the cycle's.

They are not when the chain breaks somewhere in the cycle: at positions (the sampled
solve, or a singular force analysis there), or between two positions that both assemble
(the exact existence check over the continuous range,
:attr:`~mechloop.solve.results.Results.breaks_between`).  The works then leave out the
steps next to the breaks, the machine cannot pass them, and an efficiency computed from
them (100 % without friction) claims what the mechanism does not do.  Every place that
prints such a figure asks :func:`cycle_breaks` and refuses or warns.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray


@dataclass(frozen=True)
class CycleBreaks:
    """The breaks of a cycle: ``positions`` (indices where the chain breaks or the force
    analysis is singular), ``between`` (pairs ``(i, i + 1)`` of positions that assemble
    with a break between them), ``count`` the number of positions of the cycle."""

    positions: NDArray[np.int64]
    between: tuple[tuple[int, int], ...]
    count: int

    def where(self, lang: str = "en") -> str:
        """Where the chain breaks, in words (``lang`` 'en' or 'ru')."""
        from mechloop.solve.results import compress_positions

        ru = lang == "ru"
        parts = []
        if self.positions.size:
            parts.append(("положения " if ru else "positions ")
                         + compress_positions(self.positions)
                         + (f" из {self.count}" if ru else f" of {self.count}"))
        for i, j in self.between:
            parts.append(f"между положениями {i} и {j}" if ru else
                         f"between positions {i} and {j}")
        return "; ".join(parts)


def cycle_breaks(dyn) -> CycleBreaks | None:
    """The breaks of a solved dynamic model's cycle
    (:class:`~mechloop.dynamics.analysis.DynamicResults`), None when the chain passes the
    whole cycle."""
    kin = dyn.kinematics
    broken = np.asarray(kin.broken, dtype=bool) | np.asarray(dyn.forces.singular, dtype=bool)
    between = tuple(sorted({(b.after, b.after + 1) for b in kin.breaks_between}))
    if not broken.any() and not between:
        return None
    return CycleBreaks(np.flatnonzero(broken), between, int(broken.size))
