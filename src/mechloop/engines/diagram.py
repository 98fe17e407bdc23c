"""The ideal indicator diagram: the gas pressure as a function of the cylinder volume on
each stroke, and its closed-form work.

A cycle is a sequence of strokes between dead centres, counted from top dead centre: a
four-stroke engine's ``expansion, exhaust, intake, compression`` (stroke 0 starts at the
firing dead centre), a two-stroke's ``expansion, compression``, a compressor's
``suction`` (re-expansion of the clearance gas, then suction) and ``delivery``
(compression, then discharge).  On even strokes the piston moves away from the head, on
odd ones towards it.  Jumps of the pressure (combustion at constant volume, the exhaust
blow-down, a valve opening at a dead centre) happen at a volume, so the pressure on a
stroke is a function of the volume alone.

Units SI: volumes m³, pressures Pa, work J.  ``swept`` is the swept volume ``V_h``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.engines.cycle import CompressorCycle, EngineCycle

Array = NDArray[np.float64]
Cycle = EngineCycle | CompressorCycle


def stroke_names(cycle: Cycle) -> tuple[str, ...]:
    """The strokes of ``cycle`` from top dead centre on."""
    if isinstance(cycle, CompressorCycle):
        return ("suction", "delivery")
    if cycle.strokes == 2:
        return ("expansion", "compression")
    return ("expansion", "exhaust", "intake", "compression")


def clearance_volume(cycle: Cycle, swept: float) -> float:
    """``V_c`` (m³): ``V_h/(ε − 1)`` of an engine, ``c·V_h`` of a compressor."""
    if isinstance(cycle, CompressorCycle):
        return cycle.clearance * swept
    return swept / (cycle.compression_ratio - 1.0)


def points(cycle: Cycle, swept: float) -> dict[str, tuple[float, float]]:
    """The diagram's corners ``name: (V m³, p Pa)``.

    Engine: ``a`` (start of compression), ``c`` (its end), ``z'`` (after combustion at
    constant volume), ``z`` (after combustion at constant pressure), ``b`` (end of
    expansion), and a four-stroke's ``r`` (exhaust at top dead centre).  Compressor: ``1``
    (bottom dead centre, suction), ``2`` (discharge valve opens), ``3`` (top dead
    centre), ``4`` (suction valve opens)."""
    vc = clearance_volume(cycle, swept)
    va = vc + swept
    if isinstance(cycle, CompressorCycle):
        ps, pd = cycle.suction, cycle.discharge
        v2 = va * (ps / pd) ** (1.0 / cycle.compression_exponent)
        v4 = vc * (pd / ps) ** (1.0 / cycle.expansion_exponent)
        return {"1": (va, ps), "2": (v2, pd), "3": (vc, pd), "4": (v4, ps)}
    ve = cycle.port_ratio * vc
    pc = cycle.intake * (ve / vc) ** cycle.compression_exponent
    pz = cycle.pressure_ratio * pc
    vz = cycle.pre_expansion * vc
    pb = pz * (vz / ve) ** cycle.expansion_exponent
    out = {"a": (ve, cycle.intake), "c": (vc, pc), "z'": (vc, pz), "z": (vz, pz),
           "b": (ve, pb)}
    if cycle.strokes == 4:
        out["r"] = (vc, float(cycle.exhaust))
    return out


def pressure(cycle: Cycle, volume: ArrayLike, stroke: ArrayLike, swept: float) -> Array:
    """The gas pressure (Pa) at ``volume`` (m³, ``V_c ≤ V ≤ V_c + V_h``) on ``stroke``
    (an index into :func:`stroke_names`), arrays of one shape (they broadcast)."""
    v = np.asarray(volume, dtype=float)
    s = np.asarray(stroke)
    vc = clearance_volume(cycle, swept)
    va = vc + swept
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        if isinstance(cycle, CompressorCycle):
            ps, pd = cycle.suction, cycle.discharge
            out = np.where(s == 0, np.maximum(pd * (vc / v) ** cycle.expansion_exponent, ps),
                           np.minimum(ps * (va / v) ** cycle.compression_exponent, pd))
            return np.asarray(out, dtype=float)
        p = points(cycle, swept)
        (ve, pa), (_, pz), (vz, _) = p["a"], p["z'"], p["z"]
        expansion = np.where(v <= vz, pz, pz * (vz / v) ** cycle.expansion_exponent)
        compression = pa * (ve / v) ** cycle.compression_exponent
        if cycle.strokes == 2:
            port = v >= ve
            out = np.where(s == 0, np.where(port, pa, expansion),
                           np.where(port, pa, compression))
        else:
            out = np.select([s == 0, s == 1, s == 2], [expansion, cycle.exhaust, pa],
                            compression)
    return np.asarray(out, dtype=float)


def loop_work(cycle: Cycle, swept: float) -> float:
    """``∮ p dV`` over the cycle (J), closed form: the sum of the works of its polytropes,
    isobars and isochores.  Positive for an engine (the indicated work), negative for a
    compressor (minus the work it takes).

    The ideal Otto cycle (one exponent, no pumping loop) against its textbook form
    ``p_a·V_a/(n − 1)·(λ − 1)·(ε^(n−1) − 1)``:

    >>> from mechloop.engines import EngineCycle
    >>> otto = EngineCycle(4, 9.0, 3.0, 1.0, 1.3, 1.3, 1e5, 1e5)
    >>> swept = 4e-4
    >>> textbook = 1e5 * swept * 9 / 8 / 0.3 * 2 * (9**0.3 - 1)
    >>> abs(loop_work(otto, swept) / textbook - 1) < 1e-12
    True
    """
    p = points(cycle, swept)
    if isinstance(cycle, CompressorCycle):
        (v1, ps), (v2, pd), (v3, _), (v4, _) = p["1"], p["2"], p["3"], p["4"]
        nc, ne = cycle.compression_exponent, cycle.expansion_exponent
        return ((pd * v3 - ps * v4) / (ne - 1.0) + ps * (v1 - v4)
                - (pd * v2 - ps * v1) / (nc - 1.0) - pd * (v2 - v3))
    (ve, pa), (vc, pc), (_, pz), (vz, _), (_, pb) = (p[k] for k in ("a", "c", "z'", "z",
                                                                      "b"))
    n1, n2 = cycle.compression_exponent, cycle.expansion_exponent
    work = pz * (vz - vc) + (pz * vz - pb * ve) / (n2 - 1.0) - (pc * vc - pa * ve) / (n1 - 1.0)
    if cycle.strokes == 4:  # the pumping loop: exhaust at p_r, intake at p_a
        work += (pa - float(cycle.exhaust)) * swept
    return float(work)


def mean_pressure(cycle: Cycle) -> float:
    """The mean indicated pressure ``∮p dV / V_h`` (Pa); negative for a compressor."""
    return loop_work(cycle, 1.0)


def volumetric_efficiency(cycle: CompressorCycle) -> float:
    """``λ_V = 1 − c·(π^(1/n_e) − 1)``: the share of the stroke that draws in gas.

    >>> from mechloop.engines import CompressorCycle
    >>> round(volumetric_efficiency(CompressorCycle(1e5, 6e5, 0.05, 1.3, 1.25)), 4)
    0.8404
    """
    return 1.0 - cycle.clearance * (cycle.pressure_ratio ** (1.0 / cycle.expansion_exponent)
                                    - 1.0)


def curve(cycle: Cycle, swept: float, *, samples: int = 200) -> tuple[Array, Array, Array]:
    """The closed diagram for a plot: ``(V m³, p Pa, stroke)``, each shape (S·samples,),
    stroke by stroke from top dead centre, the breaks of the pressure (``V_z``, the port)
    among the volumes."""
    vc = clearance_volume(cycle, swept)
    va = vc + swept
    base = np.linspace(vc, va, samples)
    extra = [v for name, (v, _) in points(cycle, swept).items() if name in ("z", "b", "2",
                                                                           "4")]
    grid = np.unique(np.concatenate([base, extra]))
    vs, ps, ss = [], [], []
    for k in range(len(stroke_names(cycle))):
        v = grid if k % 2 == 0 else grid[::-1]
        vs.append(v)
        ps.append(pressure(cycle, v, np.full(v.size, k), swept))
        ss.append(np.full(v.size, k))
    return np.concatenate(vs), np.concatenate(ps), np.concatenate(ss)
