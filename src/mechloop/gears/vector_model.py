"""A planetary train written as a vector model of mechloop (link ratios), so the
kinematics and the force analysis of the rest of mechloop apply to it.

The model follows ``examples/planetary_reducer.yaml``: the carrier ``O→C`` (length
``a_w``) turns with the ratio ``1/i_ah`` of the input ``a`` (argument 1); a mark on the
planet ``C→M`` (the pitch radius of the row meshing with ``b``) turns with the ratio
``ω_g/ω_h``; contour 1 (carrier, planet mark, unknown ``M→O``) follows the mark, contour 2
(the mark of ``a`` at its pitch radius ``O→S``, unknown ``S→M``, back along the planet mark
and the carrier) ties it to ``a``.  All ratios are exact fractions of tooth numbers.  With
another member held or driving, argument 1 is the driver's angle (a third contour through a
mark of ``b`` when ``b`` drives), every other member a link to it and the held one a
constant angle.
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

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


def exact_speeds(train: PlanetaryTrain) -> dict[str, Fraction]:
    """Exact angular speeds of ``a, h, g, b`` for the driver turning at 1, whichever member
    is held (Willis' formula in fractions of tooth numbers)."""
    s = train.scheme
    w = Fraction(s.sigma_a * s.sigma_b * train.z_g * train.z_b, train.z_a * train.z_f)
    forward = {"b": 1 - w, "a": 1 - 1 / w, "h": w}[train.fixed]
    first = {"b": "a", "a": "b", "h": "a"}[train.fixed]
    ratio = forward if train.driver == first else 1 / forward
    omega = {train.fixed: Fraction(0), train.driver: Fraction(1), train.output: 1 / ratio}
    omega["g"] = omega["h"] - s.sigma_a * Fraction(train.z_a, train.z_g) * (omega["a"]
                                                                           - omega["h"])
    return omega


def _held_model(train: PlanetaryTrain, turns: float, positions: int, name: str | None
                ) -> dict[str, Any]:
    """The vector model of a train with another member held or driving: argument 1 is the
    driver's angle (the mark of ``a``, the carrier, or a mark of ``b`` at its pitch radius
    closed by a third contour through the planet mark); every other member is linked to
    the driver with its exact speed ratio, the held one at a constant angle."""
    omega = exact_speeds(train)
    radii = train.pitch_radii()
    driver = {"a": 1, "h": 2, "b": 8}[train.driver]

    def angle(member: str) -> dict[str, Any] | float:
        if member == train.driver:
            return {"argument": 1}
        if omega[member] == 0:       # the held member: a constant angle
            return 0.0
        return {"link": f"a{driver}", "ratio": _fraction(omega[member])}

    teeth = "/".join(f"{k}{v}" for k, v in train.teeth.items())
    i, o = train.driver, train.output
    vectors: dict[int, Any] = {
        2: {"r": train.a_w, "a": angle("h"), "name": "carrier"},
        3: {"r": radii["f"], "a": angle("g"), "name": "planet mark"},
        4: {"r": "function", "a": "function", "name": "planet mark to centre"},
        1: {"r": radii["a"], "a": angle("a"), "name": "mark of a"},
        5: {"r": "function", "a": "function", "name": "mark of a to planet mark"},
        6: {"r": {"link": "r3"}, "a": {"link": "a3", "delta": 180},
            "name": "planet mark back"},
        7: {"r": {"link": "r2"}, "a": {"link": "a2", "delta": 180}, "name": "carrier back"},
    }
    contours = [{"vectors": [2, 3, 4], "name": "planet mark"},
                {"vectors": [1, 5, 6, 7], "name": "mesh of a"}]
    if train.driver == "b":
        vectors |= {
            8: {"r": radii["b"], "a": {"argument": 1}, "name": "mark of b"},
            9: {"r": "function", "a": "function", "name": "mark of b to planet mark"},
            10: {"r": {"link": "r3"}, "a": {"link": "a3", "delta": 180},
                 "name": "planet mark back (b)"},
            11: {"r": {"link": "r2"}, "a": {"link": "a2", "delta": 180},
                 "name": "carrier back (b)"}}
        contours.append({"vectors": [8, 9, 10, 11], "name": "mesh of b"})
    return {
        "name": name or f"Planetary train {train.scheme.name} {teeth}, {train.fixed} held "
                        f"(i_{i}{o} = {train.ratio:.6g})",
        "units": {"length": "mm", "angle": "deg"},
        "positions": positions,
        "time": {"table": {0: 0, positions: 1}},
        "arguments": {1: {"law": "cycloidal", "start": [0, 0],
                          "end": [positions, round(360.0 * turns, 9)]}},
        "vectors": vectors,
        "contours": contours,
    }


def vector_model(train: PlanetaryTrain, *, turns: float = 1.0, positions: int = 120,
                 name: str | None = None) -> dict[str, Any]:
    """The plain data of a vector model of ``train`` (mm, degrees): ``a`` turns ``turns``
    times under a cycloidal law over ``positions`` positions in 1 s."""
    if (train.fixed, train.driver) != ("b", "a"):
        return _held_model(train, turns, positions, name)
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
