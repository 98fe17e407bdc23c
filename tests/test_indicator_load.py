"""The indicator load in a model file: a force whose value is an engine's or compressor's
indicator diagram, computed from the piston's solved position.

The gas force's work over a cycle, through the mechanism's kinematics (the force's power
``Re(F̄·v)`` from the dynamics, ``v`` the analog velocity of its point), equals the
diagram's closed-form area: exactly (to 1e-9) when the positions are Gauss–Legendre nodes
between the integrand's breaks, and to the trapezoidal rule's accuracy on an even grid
(the energy table's work; its error falls as the step squared).
"""

from __future__ import annotations

from itertools import pairwise
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

import mechloop
from mechloop.engines import EngineCycle, clearance_volume, loop_work
from mechloop.engines.diagram import points
from mechloop.errors import ModelError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
R, ROD, BORE = 0.04, 0.14, 0.08
MIXED = {"strokes": 4, "firing": 360, "compression_ratio": 16, "pressure_ratio": 1.7,
         "pre_expansion": 1.4, "compression_exponent": 1.36, "expansion_exponent": 1.26,
         "intake": 0.09, "exhaust": 0.115}
CYCLE = EngineCycle(4, 16, 1.7, 1.4, 1.36, 1.26, 0.09e6, 0.115e6)


def _engine(angles, *, value=None, angle=180, time=None) -> mechloop.Model:
    """A central crank-slider (crank 40 mm, rod 140 mm) with the crank at ``angles`` (deg,
    one per position) and the indicator load on its piston."""
    data = {"units": {"length": "m", "angle": "deg"}, "positions": len(angles) - 1,
            "arguments": {1: {"table": {k: float(a) for k, a in enumerate(angles)}}},
            "vectors": {1: {"r": R, "a": {"argument": 1}}, 2: {"r": ROD, "a": "function"},
                        3: {"r": "function", "a": 180}},
            "contours": [{"vectors": [1, 2, 3]}],
            "bodies": {1: {"vectors": [1]}, 2: {"vectors": [2]},
                       3: {"vectors": [3], "mass": 0.5, "center": {"tail": 3}}},
            "forces": [{"name": "gas", "body": 3, "at": {"tail": 3}, "angle": angle,
                        "value": value or {"piston": "r3", "bore": BORE,
                                           "crankcase": 0.1, "engine": MIXED}}]}
    if time is not None:
        data["time"] = time
    return mechloop.Model.from_dict(data)


def _gas_power(dyn) -> np.ndarray:
    gas = next(f for f in dyn.loads.forces if f.name == "gas")
    return (np.conj(gas.force) * gas.point.v).real


def test_gas_force_work_through_the_model_is_the_diagram_area_exactly_by_quadrature():
    # positions at 32 Gauss-Legendre nodes between the dead centres and the angles where
    # the volume passes V_z = rho V_c (the end of combustion), plus those breaks (weight 0)
    area = np.pi * BORE**2 / 4
    swept = area * 2 * R
    vc = clearance_volume(CYCLE, swept)
    vz = points(CYCLE, swept)["z"][0]
    x = lambda p: R * np.cos(p) + np.sqrt(ROD**2 - (R * np.sin(p))**2)  # noqa: E731
    z = 2 * np.pi + brentq(lambda p: vc + area * (R + ROD - x(p)) - vz, 1e-9, np.pi)
    breaks = np.array([0, np.pi, 2 * np.pi, z, 3 * np.pi, 4 * np.pi])
    t, w = np.polynomial.legendre.leggauss(32)
    phi = [breaks] + [(a + b) / 2 + (b - a) / 2 * t for a, b in pairwise(breaks)]
    weight = [np.zeros(breaks.size)] + [(b - a) / 2 * w for a, b in pairwise(breaks)]
    phi, weight = np.concatenate(phi), np.concatenate(weight)
    order = np.argsort(phi)
    model = _engine(np.degrees(phi[order]))
    dyn = mechloop.solve_dynamics(model)
    work = float(np.sum(weight[order] * _gas_power(dyn)))  # analogs: power per rad
    assert work == pytest.approx(loop_work(CYCLE, swept), rel=1e-9)


def test_the_energy_table_work_converges_to_the_diagram_area():
    # the energy table integrates the power over the positions by the trapezoidal rule:
    # its error falls as the step squared (the integrand's kinks: the dead centres, V_z)
    swept = np.pi * BORE**2 / 4 * 2 * R
    exact = loop_work(CYCLE, swept)
    errors = []
    for n in (144, 576):
        model = _engine(np.linspace(0, 720, n + 1), time={"rpm": 3000, "turns": 2})
        dyn = mechloop.solve_dynamics(model)
        summary = dyn.summary.to_frame().set_index("load")
        errors.append(abs(summary.loc["gas", "A+ [J]"] + summary.loc["gas", "A- [J]"]
                          - exact) / exact)
    assert errors[0] < 5e-3
    assert errors[1] < errors[0] / 10


def test_the_engine_indicator_example_does_the_diagram_work():
    model = mechloop.load_model(EXAMPLES / "engine_indicator.yaml")
    dyn = mechloop.solve_dynamics(model)
    cycle = EngineCycle(4, 9, 3.2, 1, 1.35, 1.25, 0.09e6, 0.11e6)
    exact = loop_work(cycle, np.pi * 0.08**2 / 4 * 0.08)
    # machine:'s constant moment takes the gas work (gravity does none over the cycle)
    assert -dyn.cycle.constant_load * 4 * np.pi == pytest.approx(exact, rel=5e-3)


def test_a_v_twin_gets_each_cylinder_its_own_dead_centres():
    # two cylinders 90 deg apart on one crank pin, each with its own indicator load; the
    # strokes are found from each piston's position: each cylinder does the diagram's work
    engine = dict(MIXED)
    angles = np.linspace(0, 720, 1441)
    data = {"units": {"length": "m", "angle": "deg"}, "positions": 1440,
            "time": {"rpm": 3000, "turns": 2},
            "arguments": {1: {"table": {0: 0, 1440: 720}}},
            "vectors": {1: {"r": R, "a": {"argument": 1}}, 2: {"r": ROD, "a": "function"},
                        3: {"r": "function", "a": 225},
                        4: {"r": {"link": "r1"}, "a": {"link": "a1"}},
                        5: {"r": ROD, "a": "function"}, 6: {"r": "function", "a": 315}},
            "contours": [{"vectors": [1, 2, 3]}, {"vectors": [4, 5, 6]}],
            "bodies": {1: {"vectors": [1, 4]}, 2: {"vectors": [2]}, 3: {"vectors": [3]},
                       4: {"vectors": [5]}, 5: {"vectors": [6]}},
            "forces": [{"name": f"gas {k}", "body": body, "at": {"tail": vec}, "along": vec,
                        "value": {"piston": f"r{vec}", "bore": BORE, "crankcase": 0.1,
                                  "engine": dict(engine, firing=firing)}}
                       for k, body, vec, firing in ((1, 3, 3, 45 + 360), (2, 5, 6, 135))]}
    dyn = mechloop.solve_dynamics(mechloop.Model.from_dict(data))
    swept = np.pi * BORE**2 / 4 * 2 * R
    summary = dyn.summary.to_frame().set_index("load")
    for name in ("gas 1", "gas 2"):
        work = summary.loc[name, "A+ [J]"] + summary.loc[name, "A- [J]"]
        assert work == pytest.approx(loop_work(CYCLE, swept), rel=1e-4)
    gas = {f.name: np.abs(f.force) for f in dyn.loads.forces}
    # the peaks at each cylinder's firing dead centre: 405 deg and 135 deg
    assert angles[np.argmax(gas["gas 1"])] == pytest.approx(405)
    assert angles[np.argmax(gas["gas 2"])] == pytest.approx(135)


def test_problems_are_located():
    grid = np.linspace(0, 720, 73)
    with pytest.raises(ModelError) as info:  # pushes towards the head
        mechloop.solve_dynamics(_engine(grid, angle=0))
    assert "towards the cylinder head" in str(info.value)
    assert info.value.problems[0].path == ("forces", 0)
    with pytest.raises(ModelError) as info:
        mechloop.solve_dynamics(_engine(grid, value={"piston": "r9", "bore": BORE,
                                                     "crankcase": 0.1, "engine": MIXED}))
    assert info.value.problems[0].path == ("forces", 0, "value", "piston")
    with pytest.raises(ModelError) as info:  # half a turn: the stroke is not known
        mechloop.solve_dynamics(_engine(np.linspace(0, 180, 19), value={
            "piston": "r3", "bore": BORE, "crankcase": 0.1, "engine": dict(
                MIXED, strokes=2, firing=None, intake=None, exhaust=None, scavenge=0.1,
                exhaust_port=0.2)}))
    assert "whole stroke" in str(info.value)
    with pytest.raises(ModelError) as info:  # a four-stroke over one turn only
        mechloop.solve_dynamics(_engine(np.linspace(0, 360, 37)))
    assert "two turns" in str(info.value)
    with pytest.raises(ModelError) as info:  # checked on loading: a pressure's unit
        _engine(grid, value={"piston": "r3", "bore": BORE, "crankcase": "1 kg",
                             "engine": MIXED})
    assert info.value.problems[0].path == ("forces", 0, "value", "crankcase")
    with pytest.raises(ModelError) as info:  # a two-stroke takes no firing angle
        _engine(grid, value={"piston": "r3", "bore": BORE, "crankcase": 0.1,
                             "engine": dict(MIXED, strokes=2)})
    assert "missing exhaust_port, scavenge; not exhaust, firing, intake" in str(info.value)
    with pytest.raises(ModelError) as info:  # rho beyond the expansion: the cycle's check
        _engine(grid, value={"piston": "r3", "bore": BORE, "crankcase": 0.1,
                             "engine": dict(MIXED, pre_expansion=20)})
    assert info.value.problems[0].path == ("forces", 0, "value", "engine")


def test_the_indicator_examples_figures():
    # the figures docs/dynamics.md "Engine and compressor indicator diagrams" quotes
    from mechloop.dynamics.indicator import model_indicators

    (engine,) = model_indicators(mechloop.load_model(EXAMPLES / "engine_indicator.yaml"))
    assert round(engine.loop_work, 1) == 332.5
    assert round(engine.sampled_work, 1) == 331.3
    (compressor,) = model_indicators(
        mechloop.load_model(EXAMPLES / "compressor_indicator.yaml"))
    assert round(-compressor.loop_work, 1) == 147.5
    from mechloop.engines import volumetric_efficiency

    assert round(volumetric_efficiency(compressor.cycle), 3) == 0.840
    # the closed form is the quadrature of the diagram (tests/test_engines.py) and the
    # positions' reading is within the grid's accuracy of it
    assert abs(engine.sampled_work / engine.loop_work - 1) < 5e-3
    assert abs(compressor.sampled_work / compressor.loop_work - 1) < 5e-3


def test_designs_of_a_population_each_get_their_own_stroke():
    # a population of crank radii on one axis: each design's gas force is the one it has
    # alone (its own stroke, swept and clearance volume)
    from mechloop.dynamics.population import solve_population

    model = _engine(np.linspace(0, 720, 145), time={"rpm": 3000, "turns": 2})
    radii = np.array([0.035, 0.04, 0.045])
    ref = mechloop.solve_dynamics(model)
    batch = solve_population(model, {"r1": radii}, ref.kinematics, ref.mechanism)
    n = model.positions + 1
    gas = next(f for f in batch.loads.forces if f.name == "gas").force
    for d, value in enumerate(radii):
        data = model.model_dump(mode="json", exclude_defaults=True)
        data["vectors"]["1"]["r"] = float(value)
        alone = mechloop.solve_dynamics(mechloop.Model.from_dict(data))
        single = next(f for f in alone.loads.forces if f.name == "gas").force
        np.testing.assert_allclose(gas[d * n:(d + 1) * n], single, rtol=1e-12, atol=1e-9)
    # and the peak grows with the stroke at a fixed compression ratio only through p0·A:
    # p_z is the same, so the peaks of the designs agree
    peaks = gas.real.reshape(3, n).min(axis=1)  # the force points along -X
    assert np.ptp(peaks) < 1e-9 * np.abs(peaks).max()


@pytest.mark.parametrize("n", [720, 1440])
def test_a_two_stroke_through_the_model(n):
    # the port opens and closes at one piston position: the pressure jumps there while
    # the piston moves, so the trapezoidal rule's error is of the order of the step, and
    # depends on where the positions fall around the port (measured: 5e-4 at 1 deg,
    # 2e-4 at 0.5 and 0.25 deg, 1e-6 at 0.125 deg); bound: 1e-3 x the step in degrees
    engine = {"strokes": 2, "compression_ratio": 8, "pressure_ratio": 3,
              "pre_expansion": 1, "compression_exponent": 1.33, "expansion_exponent": 1.25,
              "scavenge": 0.12, "exhaust_port": 0.22}
    model = _engine(np.linspace(0, 360, n + 1), time={"rpm": 3000},
                    value={"piston": "r3", "bore": BORE, "crankcase": 0.1, "engine": engine})
    dyn = mechloop.solve_dynamics(model)
    summary = dyn.summary.to_frame().set_index("load")
    work = summary.loc["gas", "A+ [J]"] + summary.loc["gas", "A- [J]"]
    cycle = EngineCycle(2, 8, 3, 1, 1.33, 1.25, 0.12e6, exhaust_port=0.22)
    exact = loop_work(cycle, np.pi * BORE**2 / 4 * 2 * R)
    assert work == pytest.approx(exact, rel=1e-3 * 360 / n)


def test_the_command_prints_writes_and_draws(tmp_path: Path):
    from typer.testing import CliRunner

    from mechloop.cli import app

    table, figure = tmp_path / "diagram.csv", tmp_path / "diagram.png"
    result = CliRunner().invoke(app, ["indicator", str(EXAMPLES / "compressor_indicator.yaml"),
                                      "-o", str(table), "--plot", str(figure)])
    assert result.exit_code == 0, result.output
    assert "-147.512" in result.output and "0.840352" in result.output
    for name in ("stroke [mm]", "swept volume V_h [cm³]", "clearance volume V_c [cm³]",
                 "∮p dV, closed form [J]", "peak pressure [MPa]"):
        assert name in result.output  # every figure with its unit
    import pandas as pd

    frame = pd.read_csv(table)
    assert len(frame) == 73
    assert set(frame["gas: stroke"]) == {"suction", "delivery"}
    assert frame["gas: p [Pa]"].max() == pytest.approx(0.6e6)
    assert frame["gas: p [Pa]"].min() == pytest.approx(0.1e6)
    assert figure.stat().st_size > 10_000
    bad = CliRunner().invoke(app, ["indicator", str(EXAMPLES / "four_bar.yaml")])
    assert bad.exit_code == 2 and "no indicator load" in bad.output


def test_a_design_whose_chain_breaks_does_not_stop_the_population():
    # a crank of 0.3 m against the 0.14 m rod breaks at most positions: its gas force is
    # zero where it breaks, the other designs' are their own, and nothing warns
    from mechloop.dynamics.population import solve_population

    model = _engine(np.linspace(0, 720, 145), time={"rpm": 3000, "turns": 2})
    ref = mechloop.solve_dynamics(model)
    batch = solve_population(model, {"r1": np.array([0.04, 0.3])}, ref.kinematics,
                             ref.mechanism)
    gas = next(f for f in batch.loads.forces if f.name == "gas").force.reshape(2, -1)
    broken = batch.kinematics.broken.reshape(2, -1)
    assert broken[1].any() and not broken[0].any()
    assert np.all(gas[1][broken[1]] == 0) and np.all(np.isfinite(gas))
    single = next(f for f in ref.loads.forces if f.name == "gas").force
    np.testing.assert_allclose(gas[0], single, rtol=1e-12, atol=1e-9)


@pytest.mark.parametrize("offset", [0.0, 0.012])
def test_a_two_stroke_port_given_by_its_timing(offset):
    # exhaust_opens: 110 deg after top dead centre; the port is where the piston is then
    # (closed-form slider, offset or not: its own top dead centre), and it closes there
    # again on the way up; the model's cycle is the one with that port share
    from scipy.optimize import brentq

    from mechloop.dynamics.indicator import model_indicators

    def x(p):
        lateral = offset - R * np.sin(p)
        return R * np.cos(p) + np.sqrt(ROD**2 - lateral**2)

    def dx(p):
        lateral = offset - R * np.sin(p)
        return -R * np.sin(p) + lateral * R * np.cos(p) / np.sqrt(ROD**2 - lateral**2)

    tdc, bdc = brentq(dx, -1, 1), brentq(dx, 2, 4)
    share = (x(tdc + np.radians(110)) - x(bdc)) / (x(tdc) - x(bdc))
    engine = {"strokes": 2, "compression_ratio": 8, "pressure_ratio": 3,
              "pre_expansion": 1, "compression_exponent": 1.33, "expansion_exponent": 1.25,
              "scavenge": 0.12, "exhaust_opens": 110}
    model = _engine(np.linspace(0, 360, 721), time={"rpm": 3000},
                    value={"piston": "r3", "bore": BORE, "crankcase": 0.1, "engine": engine})
    if offset:
        data = model.model_dump(mode="json", exclude_defaults=True)
        data["vectors"]["4"] = {"r": offset, "a": 270}  # the cylinder's axis at y = offset
        data["contours"][0]["vectors"] = [1, 2, 3, 4]
        model = mechloop.Model.from_dict(data)
    (item,) = model_indicators(model)
    # (read between the 0.5-deg positions by the cubic Hermite interpolant: error ~h^4)
    assert item.cycle.exhaust_port == pytest.approx(share, rel=1e-7)
    # the pressure drops to the scavenging pressure where the piston passes the port
    v_port = item.gas.clearance + item.gas.swept * (1 - share)
    port = item.gas.volume >= v_port
    assert np.all(item.gas.pressure[port] == pytest.approx(0.12e6))
    assert np.all(item.gas.pressure[~port] > 0.12e6)

