"""A planetary train written as a vector model of mechloop (link ratios), so the
kinematics and the force analysis of the rest of mechloop apply to it.

The model follows ``examples/planetary_reducer.yaml``: the carrier ``O→C`` (length
``a_w``) turns with the ratio ``1/i_ah`` of the input ``a`` (argument 1); a mark on the
planet ``C→M`` (the pitch radius of the row meshing with ``b``) turns with the ratio
``ω_g/ω_h``; contour 1 (carrier, planet mark, unknown ``M→O``) follows the mark, contour 2
(the mark of ``a`` at its pitch radius ``O→S``, unknown ``S→M``, back along the planet mark
and the carrier) ties it to ``a``.  All ratios are exact fractions of tooth numbers.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from mechloop.errors import HintedError
from mechloop.gears.planetary import PlanetaryTrain


def _fraction(value: Fraction) -> str:
    return f"{value.numerator}/{value.denominator}" if value.denominator != 1 \
        else str(value.numerator)


def train_ratios(train: PlanetaryTrain) -> tuple[Fraction, Fraction]:
    """Exact ``(ω_h/ω_a, ω_g/ω_h)`` with ``b`` fixed."""
    s = train.scheme
    willis = Fraction(s.sigma_a * s.sigma_b * train.z_g * train.z_b, train.z_a * train.z_f)
    carrier = 1 / (1 - willis)
    planet = 1 - s.sigma_a * Fraction(train.z_a, train.z_g) * (1 / carrier - 1)
    return carrier, planet


def vector_model(train: PlanetaryTrain, *, turns: float = 1.0, positions: int = 120,
                 name: str | None = None) -> dict[str, Any]:
    """The plain data of a vector model of ``train`` (mm, degrees): ``a`` turns ``turns``
    times under a cycloidal law over ``positions`` positions in 1 s."""
    if (train.fixed, train.driver) != ("b", "a"):
        raise HintedError(f"the vector model is written with a driving and b fixed; this "
                          f"train holds {train.fixed} and drives {train.driver}",
                          "drop --model, or write the train with fixed: b, input: a")
    carrier, planet = train_ratios(train)
    radii = train.pitch_radii()
    teeth = "/".join(f"{k}{v}" for k, v in train.teeth.items())
    return {
        "name": name or f"Planetary train {train.scheme.name} {teeth} "
                        f"(i_ah = {float(1 / carrier):.6g})",
        "units": {"length": "mm", "angle": "deg"},
        "positions": positions,
        "time": {"table": {0: 0, positions: 1}},
        "arguments": {1: {"law": "cycloidal", "start": [0, 0],
                          "end": [positions, round(360.0 * turns, 9)]}},
        "vectors": {
            2: {"r": train.a_w, "a": {"link": "a1", "ratio": _fraction(carrier)},
                "name": "carrier"},
            3: {"r": radii["f"], "a": {"link": "a2", "ratio": _fraction(planet)},
                "name": "planet mark"},
            4: {"r": "function", "a": "function", "name": "planet mark to centre"},
            1: {"r": radii["a"], "a": {"argument": 1}, "name": "mark of a"},
            5: {"r": "function", "a": "function", "name": "mark of a to planet mark"},
            6: {"r": {"link": "r3"}, "a": {"link": "a3", "delta": 180},
                "name": "planet mark back"},
            7: {"r": {"link": "r2"}, "a": {"link": "a2", "delta": 180}, "name": "carrier back"},
        },
        "contours": [{"vectors": [2, 3, 4], "name": "planet mark"},
                     {"vectors": [1, 5, 6, 7], "name": "mesh of a"}],
    }
