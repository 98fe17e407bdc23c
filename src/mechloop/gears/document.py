"""The YAML (or JSON) form of a gear task: ``gear_pair:`` (an external spur pair) and
``planetary:`` (a planetary train to analyse, or tooth numbers to choose for a target
ratio).  Read with every problem at once, each located by line, as model files are.

Lengths are in mm, angles in degrees (the file's units are fixed: gear data are tabulated
in mm and degrees).  See ``examples/gears/`` for both forms.
"""

from __future__ import annotations

import os
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field

from mechloop.errors import HintedError, Problem
from mechloop.gears.centre_distance import shift_sum_from_centre_distance
from mechloop.gears.checks import minimum_shift
from mechloop.gears.pair import GearPair, gear_pair
from mechloop.gears.planetary import SCHEMES, PlanetaryTrain, planetary_train
from mechloop.gears.sliding import balanced_shift
from mechloop.gears.wolfrom import WolfromTrain, wolfrom_train
from mechloop.model.document import LineMap, located_error, read_document, validate_data
from mechloop.model.numbers import Number
from mechloop.model.signals import _Frozen

Positive = Annotated[float, Field(gt=0, lt=1e6)]
Coefficient = Annotated[float, Field(ge=0, le=5)]
Teeth = Annotated[int, Field(ge=1, le=10_000)]


class PairSpec(_Frozen):
    """An external involute spur gear pair (ISO 21771 names in the comments)."""

    name: str | None = Field(None, description="a title")
    module: Positive = Field(description="module m_n, mm")
    teeth: tuple[Teeth, Teeth] = Field(description="numbers of teeth [z1, z2], pinion "
                                       "first")
    pressure_angle: Annotated[float, Field(gt=0, lt=45)] = Field(
        20.0, description="normal pressure angle α_n of the basic rack, degrees")
    addendum: Coefficient = Field(1.0, description="addendum coefficient h_a* of the rack")
    clearance: Coefficient = Field(0.25, description="tip clearance coefficient c*")
    tool_tip_radius: Coefficient = Field(0.38, description="tip radius coefficient ρ* of "
                                         "the cutting rack (ISO 53 profile A: 0.38)")
    shifts: tuple[Number, Number] | Literal["balanced", "no_undercut"] | None = Field(
        None, description="profile shift coefficients [x1, x2]; or 'balanced' (the sum "
        "from centre_distance, split for equal specific sliding); or 'no_undercut' (each "
        "gear the least shift without undercut, none if not needed); default [0, 0]")
    pinion_shift: Number | None = Field(None, description="with centre_distance: the "
                                        "pinion's shift x1 (the wheel takes the rest)")
    centre_distance: Positive | None = Field(None, description="centre distance a, mm "
                                             "(the sum of the shifts follows from it)")
    tip_thickness_min: Coefficient = Field(0.25, description="least tooth thickness on the "
                                           "tip circle, in modules (pointed-tooth check; "
                                           "0.25 to 0.4)")


class SearchSpec(_Frozen):
    """Limits of the choice of tooth numbers."""

    teeth_min: Teeth = Field(17, description="fewest teeth of a gear (17: no undercut of "
                             "an unshifted 20° gear)")
    teeth_max: Teeth = Field(120, description="most teeth of a gear (a ring included)")
    ring_difference_min: Annotated[int, Field(ge=1, le=100)] = Field(
        8, description="least difference of teeth between a ring and its planet (internal "
        "mesh without interference; 8 is the usual rule for h_a* = 1, α = 20°)")
    tolerance: Annotated[float, Field(ge=0, le=1)] = Field(
        0.01, description="largest relative error of the ratio")
    show: Annotated[int, Field(ge=1, le=1000)] = Field(10, description="designs listed")


class PlanetarySpec(_Frozen):
    """A planetary train: its scheme, planets and module; tooth numbers to analyse, or a
    target ratio to choose them for."""

    name: str | None = Field(None, description="a title")
    scheme: Literal[(*SCHEMES, "wolfrom")] = Field(  # type: ignore[valid-type]
        "simple", description="simple (James), double_planet, two_rings, two_suns or "
        "wolfrom (sun a, stepped planet g/f, fixed ring b, output ring e)")
    planets: Annotated[int, Field(ge=1, le=30)] = Field(3, description="number of planets k")
    module: Positive = Field(1.0, description="module m_n, mm (one module, unshifted)")
    addendum: Coefficient = Field(1.0, description="addendum coefficient h_a*")
    teeth: dict[Literal["a", "g", "f", "b", "e"], Teeth] | None = Field(
        None, description="tooth numbers {a, g, b} (simple), {a, g, f, b} (two-row) or "
        "{a, g, f, b, e} (wolfrom)")
    fixed: Literal["a", "b", "h"] = Field("b", description="the member held: central gear "
                                          "a or b, or the carrier h (2K-H schemes)")
    input: Literal["a", "b", "h"] = Field("a", description="the driving member; the "
                                          "output is the third of a, b and h")
    target_ratio: Annotated[float, Field(gt=-1e6, lt=1e6)] | None = Field(
        None, description="the ratio ω_input/ω_output (i_ah by default) to choose the "
        "tooth numbers for")
    input_speed: Number = Field(1000.0, description="speed of the input member, rpm "
                                "(velocity plan)")
    search: SearchSpec = Field(default_factory=SearchSpec, description="limits of the choice")


class GearDocument(_Frozen):
    """A gear task file: ``gear_pair:`` and/or ``planetary:``."""

    gear_pair: PairSpec | None = None
    planetary: PlanetarySpec | None = None


def read_gear_document(path: str | os.PathLike[str]) -> tuple[GearDocument, LineMap]:
    """The validated document of a gear task file; every problem at once, located."""
    file = str(path)
    data, lines = read_document(path)
    doc, problems = validate_data(GearDocument, data, file)
    if problems or doc is None:
        raise located_error(problems, file, lines)
    return doc, lines


def pair_of(spec: PairSpec, *, file: str | None = None, lines: LineMap | None = None
            ) -> GearPair:
    """The :class:`GearPair` a ``gear_pair:`` section describes; an inconsistent section
    (shifts and a centre distance that disagree, 'balanced' without a centre distance…)
    is told at its key and line."""
    lines = lines or {}
    where = ("gear_pair",)
    alpha = np.radians(spec.pressure_angle)
    base = dict(ha=spec.addendum, c=spec.clearance, rho=spec.tool_tip_radius,
                s_a_min=spec.tip_thickness_min)
    z = spec.teeth
    problems: list[Problem] = []

    def fail(key: str, message: str, hint: str) -> None:
        problems.append(Problem((*where, key), message, hint))

    try:
        if spec.pinion_shift is not None and spec.centre_distance is None:
            fail("pinion_shift", "a pinion shift alone leaves the wheel's open",
                 "give centre_distance too, or write shifts: [x1, x2]")
        elif spec.pinion_shift is not None and spec.shifts is not None:
            fail("pinion_shift", "both pinion_shift and shifts are given",
                 "keep one of them")
        elif spec.centre_distance is not None:
            a = spec.centre_distance
            x_sum = float(shift_sum_from_centre_distance(spec.module, *z, a, alpha)[0])
            if spec.shifts == "no_undercut":
                fail("shifts", "'no_undercut' chooses the shifts, so the centre distance "
                     "follows from them", "remove centre_distance, or write shifts: balanced")
            elif spec.shifts is None or spec.shifts == "balanced":
                if spec.pinion_shift is not None:
                    x1 = spec.pinion_shift
                else:
                    probe = gear_pair(spec.module, z, alpha, x=(0.0, 0.0), **base)
                    x1 = balanced_shift(probe, x_sum)
                return gear_pair(spec.module, z, alpha, x=(x1, x_sum - x1), **base)
            else:
                given = gear_pair(spec.module, z, alpha, x=spec.shifts, **base)
                if abs(given.a - a) > 1e-6 * a:
                    fail("centre_distance", f"the shifts {list(spec.shifts)} give the "
                         f"centre distance {given.a:.6f}, not {a:g}",
                         f"remove centre_distance, or make the shifts sum to {x_sum:.6f} "
                         "(or write shifts: balanced)")
                else:
                    return given
        elif spec.shifts == "balanced":
            fail("shifts", "balanced shifts need their sum, which the centre distance fixes",
                 "add centre_distance (mm)")
        elif spec.shifts == "no_undercut":
            x = np.maximum(0.0, minimum_shift(np.asarray(z, float), spec.addendum,
                                              spec.clearance, spec.tool_tip_radius, alpha))
            return gear_pair(spec.module, z, alpha, x=(float(x[0]), float(x[1])), **base)
        else:
            return gear_pair(spec.module, z, alpha, x=spec.shifts or (0.0, 0.0), **base)
    except HintedError as exc:
        key = "centre_distance" if spec.centre_distance is not None else "shifts"
        problems.append(Problem((*where, key), exc.message, exc.hint))
    raise located_error(problems, file, lines)


def train_of(spec: PlanetarySpec, *, file: str | None = None,
             lines: LineMap | None = None) -> PlanetaryTrain | WolfromTrain | None:
    """The :class:`PlanetaryTrain` (or :class:`WolfromTrain`) of a ``planetary:`` section
    with tooth numbers (None when it only asks for a choice); problems told at their key
    and line."""
    if spec.scheme == "wolfrom":
        return _wolfrom_of(spec, file, lines or {})
    if spec.fixed == spec.input:
        raise located_error([Problem(("planetary", "input"), f"the input {spec.input} is "
                                     "the member held fixed",
                                     "take another input of a, b and h")], file, lines or {})
    if spec.teeth is None:
        if spec.target_ratio is None:
            raise located_error([Problem(("planetary",), "neither tooth numbers nor a "
                                         "target ratio", "add teeth: {a: 20, g: 30, b: 80} "
                                         "or target_ratio: 5")], file, lines or {})
        return None
    try:
        if "e" in spec.teeth:
            raise HintedError("a ring e belongs to the wolfrom scheme only",
                              "remove e, or write scheme: wolfrom")
        return planetary_train(spec.scheme, dict(spec.teeth), spec.planets, spec.module,
                               spec.addendum, fixed=spec.fixed, driver=spec.input)
    except HintedError as exc:
        raise located_error([Problem(("planetary", "teeth"), exc.message, exc.hint)], file,
                            lines or {}) from None


def _wolfrom_of(spec: PlanetarySpec, file: str | None, lines: LineMap
                ) -> WolfromTrain | None:
    problems = []
    if spec.teeth is None and spec.target_ratio is None:
        problems.append(Problem(("planetary",), "neither tooth numbers nor a target ratio",
                                "add teeth: {a: 15, g: 24, f: 21, b: 63, e: 60} or "
                                "target_ratio: 64"))
    if (spec.fixed, spec.input) != ("b", "a"):
        key = "fixed" if spec.fixed != "b" else "input"
        problems.append(Problem(("planetary", key), "the wolfrom train holds ring b and "
                                "is driven by the sun a (its output is ring e)",
                                "remove fixed: and input:"))
    if not problems and spec.teeth is None:
        return None
    if not problems:
        try:
            return wolfrom_train(dict(spec.teeth), spec.planets, spec.module, spec.addendum)
        except HintedError as exc:
            problems.append(Problem(("planetary", "teeth"), exc.message, exc.hint))
    raise located_error(problems, file, lines)


def choice_of(spec: PlanetarySpec, *, file: str | None = None,
              lines: LineMap | None = None):
    """The tooth numbers a ``planetary:`` section's ``target_ratio`` and ``search:`` ask
    for (a :class:`~mechloop.gears.tooth_search.Choice` or ``WolfromChoice``, best first,
    possibly empty);
    a bad search is told at its key and line."""
    from mechloop.gears.planetary import scheme_of
    from mechloop.gears.tooth_search import choose_teeth

    s = spec.search
    try:
        if spec.scheme == "wolfrom":
            from mechloop.gears.tooth_search import choose_wolfrom_teeth

            return choose_wolfrom_teeth(float(spec.target_ratio), spec.planets,
                                        teeth_min=s.teeth_min, teeth_max=s.teeth_max,
                                        tolerance=s.tolerance, ha=spec.addendum)
        return choose_teeth(scheme_of(spec.scheme), float(spec.target_ratio), spec.planets,
                            teeth_min=s.teeth_min, teeth_max=s.teeth_max,
                            ring_difference_min=s.ring_difference_min,
                            tolerance=s.tolerance, ha=spec.addendum, fixed=spec.fixed,
                            driver=spec.input)
    except HintedError as exc:
        raise located_error([Problem(("planetary", "search"), exc.message, exc.hint)],
                            file, lines or {}) from None


def no_design(spec: PlanetarySpec) -> Problem:
    """The problem of a choice that found no tooth numbers."""
    return Problem(("planetary", "target_ratio"),
                   f"no design of the {spec.scheme} scheme meets the ratio "
                   f"{spec.target_ratio:g} within {100 * spec.search.tolerance:g} %",
                   "widen search.tolerance or teeth_max, change the number of planets, or "
                   "try another scheme")


def section(doc: GearDocument, key: str, file: str, lines: LineMap) -> Any:
    """The ``gear_pair`` or ``planetary`` section of a document, or a located error."""
    value = getattr(doc, key)
    if value is None:
        example = "examples/gears/gear_pair.yaml" if key == "gear_pair" else \
            "examples/gears/planetary_reducer.yaml"
        raise located_error([Problem((), f"the file has no '{key}:' section",
                                     f"add one (see {example})", 1)], file, lines)
    return value
