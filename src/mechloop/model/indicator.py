"""The gas force of an indicator diagram as a force's value in a model file.

A force on the piston whose ``value`` names the piston's parameter and the cycle::

    forces:
      - name: gas
        body: 3                  # the piston
        at: {tail: 3}
        along: 3                 # positive: pushes the piston away from the cylinder head
        value:
          piston: r3             # the length that places the piston (largest at TDC)
          bore: 80               # length units
          crankcase: 0.1 MPa     # pressure under the piston
          engine: {strokes: 4, firing: 360, compression_ratio: 9, pressure_ratio: 3.2,
                   pre_expansion: 1, compression_exponent: 1.35,
                   expansion_exponent: 1.25, intake: 0.09 MPa, exhaust: 0.11 MPa}

or ``compressor: {suction: ..., discharge: ..., clearance: 0.05, compression_exponent:
1.3, expansion_exponent: 1.25}``.  The stroke, the dead centres and the cylinder volume
come from the mechanism's solved positions (:mod:`mechloop.engines.gas_force`); the
pressures are in ``unit`` (default MPa) unless they carry their own unit.  Cycle
parameters: :mod:`mechloop.engines.cycle`.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from mechloop.engines.cycle import CompressorCycle, EngineCycle
from mechloop.errors import HintedError, ModelError, Problem
from mechloop.model.numbers import Number, Scalar, UnitName
from mechloop.model.signals import _Frozen
from mechloop.model.units import Kind, UnitProblem, to_si

PistonName = Annotated[str, Field(pattern=r"^r[1-9][0-9]{0,5}$")]


class EngineParameters(_Frozen):
    """An engine's cycle: a four-stroke's ``intake``/``exhaust`` lines and ``firing``
    angle, or a two-stroke's ``scavenge`` pressure and ``exhaust_port``."""

    strokes: Literal[2, 4] = Field(description="2 or 4")
    firing: Scalar | None = Field(None, description="four-stroke: the crank's angle at the "
                                  "firing top dead centre (angle units; within a quarter "
                                  "turn of it), e.g. 360 when the cycle starts with intake")
    compression_ratio: Number = Field(gt=1, description="ε = (V_c + V_h)/V_c")
    pressure_ratio: Number = Field(ge=1, description="λ = p_z/p_c: the pressure rise of "
                                   "combustion at constant volume (1: none)")
    pre_expansion: Number = Field(ge=1, description="ρ = V_z/V_c: the expansion during "
                                  "combustion at constant pressure (1: none)")
    compression_exponent: Number = Field(gt=1, description="n₁ of the compression "
                                         "polytrope")
    expansion_exponent: Number = Field(gt=1, description="n₂ of the expansion polytrope")
    intake: Scalar | None = Field(None, description="four-stroke: the intake pressure p_a "
                                  "(the start of compression)")
    exhaust: Scalar | None = Field(None, description="four-stroke: the exhaust pressure p_r")
    scavenge: Scalar | None = Field(None, description="two-stroke: the scavenging pressure "
                                    "(the start of compression)")
    exhaust_port: Number | None = Field(None, ge=0, lt=1, description="two-stroke: the "
                                        "share of the stroke above bottom dead centre "
                                        "that the exhaust port takes")
    exhaust_opens: Scalar | None = Field(None, description="two-stroke, instead of "
                                         "exhaust_port: the crank's angle after top dead "
                                         "centre at which the piston uncovers the exhaust "
                                         "port (angle units; it covers it again at the "
                                         "same piston position)")

    @model_validator(mode="after")
    def _stroke_keys(self) -> EngineParameters:
        port = "exhaust_opens" if self.exhaust_opens is not None else "exhaust_port"
        own = ({"firing", "intake", "exhaust"} if self.strokes == 4
               else {"scavenge", port})
        other = {"firing", "intake", "exhaust", "scavenge", "exhaust_port",
                 "exhaust_opens"} - own
        missing = sorted(k for k in own if getattr(self, k) is None)
        extra = sorted(k for k in other if getattr(self, k) is not None)
        if missing or extra:
            raise ValueError(f"a {self.strokes}-stroke engine takes {', '.join(sorted(own))}"
                             + (f"; missing {', '.join(missing)}" if missing else "")
                             + (f"; not {', '.join(extra)}" if extra else ""))
        return self


class CompressorParameters(_Frozen):
    """A single-acting piston compressor's cycle with its clearance."""

    suction: Scalar = Field(description="suction pressure p_s")
    discharge: Scalar = Field(description="discharge pressure p_d")
    clearance: Number = Field(gt=0, lt=1, description="c = V_c/V_h")
    compression_exponent: Number = Field(gt=1, description="n_c of the compression "
                                         "polytrope")
    expansion_exponent: Number = Field(gt=1, description="n_e of the re-expansion of the "
                                       "clearance gas")


class IndicatorValue(_Frozen):
    """A force's value from an indicator diagram: ``(p − crankcase)·A`` on the piston,
    ``p`` the gas pressure of the ``engine``'s or ``compressor``'s ideal cycle at the
    cylinder volume that the piston's solved position gives."""

    piston: PistonName = Field(description="the length that places the piston, e.g. r3")
    head: Literal["max", "min"] = Field("max", description="where the cylinder head is: "
                                        "the piston's parameter is largest (max) or "
                                        "smallest (min) at top dead centre")
    bore: Scalar = Field(description="the cylinder's diameter (length units)")
    crankcase: Scalar = Field(description="the pressure under the piston")
    unit: UnitName = Field("MPa", description="unit of the pressures given as plain numbers")
    argument: int | None = Field(None, ge=1, description="the crank's argument (default: "
                                 "the model's first drive)")
    engine: EngineParameters | None = None
    compressor: CompressorParameters | None = None

    @model_validator(mode="after")
    def _one_cycle(self) -> IndicatorValue:
        if (self.engine is None) == (self.compressor is None):
            raise ValueError("give either engine: {...} or compressor: {...}")
        return self


def si(value: float | str, kind: Kind, unit: str, path: tuple) -> float:
    """``value`` in SI; a :class:`~mechloop.errors.ModelError` at ``path`` when its unit
    is wrong."""
    try:
        return to_si(value, kind, unit)
    except UnitProblem as exc:
        raise ModelError([Problem(path, exc.message, exc.hint)]) from None


def compile_cycle(value: IndicatorValue, path: tuple = (), *, port: float | None = None
                  ) -> EngineCycle | CompressorCycle:
    """The cycle of ``value`` in SI (:mod:`mechloop.engines.cycle`); raises
    :class:`~mechloop.errors.ModelError` located below ``path`` (the value's place in the
    model).  ``port``: a two-stroke's exhaust port share found from ``exhaust_opens``
    and the kinematics (without it such a cycle is checked with the port at bottom dead
    centre)."""
    unit = value.unit
    if value.compressor is not None:
        c = value.compressor
        where = (*path, "compressor")
        args = (si(c.suction, "pressure", unit, (*where, "suction")),
                si(c.discharge, "pressure", unit, (*where, "discharge")),
                c.clearance, c.compression_exponent, c.expansion_exponent)
        make = CompressorCycle
    else:
        e = value.engine
        where = (*path, "engine")
        four = e.strokes == 4
        intake = si(e.intake if four else e.scavenge, "pressure", unit,
                    (*where, "intake" if four else "scavenge"))
        exhaust = si(e.exhaust, "pressure", unit, (*where, "exhaust")) if four else None
        args = (e.strokes, e.compression_ratio, e.pressure_ratio, e.pre_expansion,
                e.compression_exponent, e.expansion_exponent, intake, exhaust,
                0.0 if four else float(e.exhaust_port if e.exhaust_port is not None
                                       else port or 0.0))
        make = EngineCycle
    try:
        return make(*args)
    except HintedError as exc:
        raise ModelError([Problem(where, exc.message, exc.hint)]) from None


def indicator_problems(value: IndicatorValue, units, path: tuple) -> list[Problem]:
    """Every problem of ``value``'s numbers (units, the cycle's consistency) that shows
    before solving; ``units`` the model's units."""
    problems: list[Problem] = []
    checks = [lambda: compile_cycle(value, path),
              lambda: si(value.bore, "length", units.length, (*path, "bore")),
              lambda: si(value.crankcase, "pressure", value.unit, (*path, "crankcase"))]
    for key in ("firing", "exhaust_opens"):
        if value.engine is not None and getattr(value.engine, key) is not None:
            checks.append(lambda key=key: si(getattr(value.engine, key), "angle",
                                             units.angle, (*path, "engine", key)))
    for check in checks:
        try:
            check()
        except ModelError as exc:
            problems += exc.problems
    return problems
