"""Indicator diagrams of piston engines and compressors, and the gas force they put on the
piston (KDAM extensions 1 and 3).

Owns: the cycle parameters (:mod:`.cycle`), the ideal indicator diagram and its closed-form
work (:mod:`.diagram`), and the gas force over a mechanism's positions from the piston's
solved position (:mod:`.gas_force`).  Pure functions over NumPy arrays, SI throughout
(Pa, m³, m, rad, N, J).  May import :mod:`mechloop.errors` only; the model file's
``indicator`` load (:mod:`mechloop.model.indicator`) and the dynamics
(:mod:`mechloop.dynamics.indicator`) call into this package, never the other way.
"""

from mechloop.engines.cycle import CompressorCycle, EngineCycle
from mechloop.engines.diagram import (
    clearance_volume,
    curve,
    loop_work,
    mean_pressure,
    points,
    pressure,
    stroke_names,
    volumetric_efficiency,
)
from mechloop.engines.gas_force import (
    GasForce,
    gas_force,
    piston_extremes,
    port_share,
    stroke_of,
)

__all__ = ["CompressorCycle", "EngineCycle", "GasForce", "clearance_volume", "curve",
           "gas_force", "loop_work", "mean_pressure", "piston_extremes", "points",
           "port_share", "pressure", "stroke_names", "stroke_of", "volumetric_efficiency"]
