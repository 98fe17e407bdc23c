"""The seed's brute-force tabulation of a lemniscate roof support (seed 001, sec. 1.2.2),
in NumPy, for the four-bar of ``examples/roof_support.yaml`` and its synthesis.

The seed's spreadsheet macro does not solve the four-bar: it tabulates both lever angles
in 1° steps (90 × 90 = 8100 combinations), computes the squared distance between the two
lever tips for each, and keeps the combinations whose value falls within a window around
the shield's squared length L² (0.72 ≤ L² ≤ 0.73 m² for L = 0.85 m).  The kept pairs are
the tabulated positions; the canopy tip E follows from the line through the two shield
pins (eq. 1.1).  Used by ``benchmarks/bench_roof_support.py`` and by the tests as an
independent, geometry-only description of the same mechanism.

Geometry (m, the model's frame): D the leg's base pivot (the start of contour 1), the
front lever O2 → B (length ``front``), the rear lever O1 → A (``rear``), the shield
B → A (``shield``), E on the line A → B extended ``canopy`` past B; the leg D → B.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


@dataclass(frozen=True)
class RoofSupport:
    """Dimensions of the lemniscate four-bar (m), as in ``examples/roof_support.yaml``:
    ``o2 = D + (r1, r2)``, ``o1 = D + (r5, r6)``, ``front = r3``, ``rear = r9``,
    ``shield = r8``, ``canopy = r11``."""

    d: complex
    o2: complex
    o1: complex
    front: float
    rear: float
    shield: float
    canopy: float

    @classmethod
    def from_values(cls, values: dict[str, float], d: complex = 0.15j) -> RoofSupport:
        """From the model's constants ``r1, r2, r3, r5, r6, r8, r9, r11`` (m)."""
        v = values
        return cls(d=d, o2=d + complex(v["r1"], v["r2"]), o1=d + complex(v["r5"], v["r6"]),
                   front=v["r3"], rear=v["r9"], shield=v["r8"], canopy=v["r11"])

    def tip(self, b: Array, a: Array) -> Array:
        """Canopy tip E for shield pins B, A (complex arrays): eq. 1.1 of the seed."""
        with np.errstate(invalid="ignore"):  # NaN where the four-bar does not assemble
            return b + self.canopy * (b - a) / np.abs(b - a)

    def exact(self, leg: Array) -> tuple[Array, Array, Array]:
        """B, A, E for leg lengths ``leg`` by two circle intersections (the assembly of
        the example: B above the base line D → O2, A behind the shield B → O1)."""
        b = _circles(self.d, leg, self.o2, self.front, left=True)
        a = _circles(b, self.shield, self.o1, self.rear, left=False)
        return b, a, self.tip(b, a)

    def tabulate(self, front_angles: Array, rear_angles: Array, window: tuple[float, float]
                 ) -> tuple[Array, Array]:
        """The seed's macro: every pair of lever angles (rad), kept where the squared
        shield length lies in ``window`` (m²).  Returns B and A of the kept pairs."""
        b = self.o2 + self.front * np.exp(1j * front_angles)[:, None]
        a = self.o1 + self.rear * np.exp(1j * rear_angles)[None, :]
        b, a = np.broadcast_arrays(b, a)
        square = np.abs(b - a) ** 2
        keep = (square >= window[0]) & (square <= window[1])
        return b[keep], a[keep]


def _circles(c1: Array | complex, r1: Array | float, c2: complex, r2: float, *,
             left: bool) -> Array:
    """The intersection of circles (c1, r1) and (c2, r2) on the left (or right) of the
    line c1 → c2 (complex numbers); NaN where they do not meet."""
    c1 = np.asarray(c1, dtype=complex)
    r1 = np.asarray(r1, dtype=float)
    base = c2 - c1
    d = np.abs(base)
    x = (d**2 + r1**2 - r2**2) / (2 * d)
    with np.errstate(invalid="ignore"):
        h = np.sqrt(r1**2 - x**2)
        return c1 + base / d * (x + (1j if left else -1j) * h)


def _lower_end(ends: Array) -> float:
    """The smaller angle (deg) of two directions, without a jump at ±180°."""
    first = np.degrees(np.angle(ends[0]))
    turn = np.degrees(np.angle(ends[1] / ends[0]))
    return float(min(first, first + turn))


def tabulated_positions(support: RoofSupport, legs: tuple[float, float],
                        window: tuple[float, float], step_deg: float = 1.0,
                        count: int = 90) -> tuple[Array, Array, Array]:
    """The seed's 90 × 90 tabulation around the working range of ``support``.

    Each lever's angle runs over ``count`` steps of ``step_deg`` starting a whole degree
    below its angle at the lowest leg length (the seed chose its ranges by hand, 10°…85°
    for its own design); kept pairs whose leg length lies in ``legs``.  Returns the
    kept leg lengths, the tabulated E and the exact E at the same front-lever angle."""
    b0, a0, _ = support.exact(np.array([legs[0], legs[1]]))
    front0 = np.floor(_lower_end(b0 - support.o2)) - step_deg
    rear0 = np.floor(_lower_end(a0 - support.o1)) - step_deg
    front = np.radians(front0 + step_deg * np.arange(count))
    rear = np.radians(rear0 + step_deg * np.arange(count))
    b, a = support.tabulate(front, rear, window)
    leg = np.abs(b - support.d)
    inside = (leg >= legs[0]) & (leg <= legs[1])
    b, a, leg = b[inside], a[inside], leg[inside]
    exact_a = _circles(b, support.shield, support.o1, support.rear, left=False)
    return leg, support.tip(b, a), support.tip(b, exact_a)
