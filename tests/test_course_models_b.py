"""Ten of the twenty course-project mechanisms of seed 000 sec. 3 (examples/course/, tasks
5 and 12-20): each solves without a chain break over its whole working range (decided
between the positions too), its dynamics are finite, its works balance over the cycle,
its mobility is the hand count written here, and every gas-force table is the indicator
diagram its header states, recomputed here from the model's own piston positions.

The gas tables are inputs of the models; the diagrams below are written out independently
of mechloop (polytropes between the piston's dead centres), so a table edited by hand or a
piston that no longer moves as the diagram assumed fails
``test_gas_tables_are_the_stated_indicator_diagrams``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
import yaml

import mechloop
from mechloop.structure.analysis import analyze

COURSE = Path(__file__).resolve().parents[1] / "examples" / "course"

# file: (n, p5, p4, W, structure formula, class), by hand (see each file's header)
HAND = {
    # crank 1, rod 2, crosshead with piston 3: RRP dyad
    "05_compressor.yaml": (3, 4, 0, 1, "L0(1) → L2(2,3)", 2),
    # crank 1, master rod 2 + piston 4 (RRP), articulated rod 3 + piston 5 hung on the
    # master rod's knuckle pin (RRP): n = 5, p5 = 7 (O, A, C, B1, B2, two slides)
    "12_v_engine_articulated.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    # crank 1, fork rod 2 + piston 4 (RRP), blade rod 3 + piston 5 pinned to the fork's
    # big end (RRP): n = 5, p5 = 7 (O, A crank-fork, A fork-blade, B1, B2, two slides)
    "13_v_engine_fork_and_blade.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    # crankshaft 1 with two throws, each with a rod and a piston (RRP dyads)
    "16_two_cylinder_compressor.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    "18_two_stage_compressor.yaml": (5, 7, 0, 1, "L0(1) → L2(2,4) → L2(3,5)", 2),
    # crank 1; plunger 2 pinned to the crank pin, sliding in the cylinder 3 that swings on
    # its trunnion: an RPR dyad (pins A and C, the slide between): n = 3, p5 = 4
    "17_oil_pump.yaml": (3, 4, 0, 1, "L0(1) → L3(2,3)", 2),
    # crank 1, coupler 2, rocker with arm 3 (RRR), rod 4 and ram 5 (RRP): n = 5, p5 = 7
    "19_gear_shaper.yaml": (5, 7, 0, 1, "L0(1) → L1(2,3) → L2(4,5)", 2),
    # ring 1 driven along its slide, link 2 and flap 3 (RRR): n = 3, p5 = 4 (slide, R, L, P)
    "14_nozzle_ring.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # primary flap 1 turned by the cylinder (a drive, not a link), divergent flap 2 and
    # strut 3 (RRR): n = 3, p5 = 4 (P, T, E, Q)
    "15_nozzle_flaps.yaml": (3, 4, 0, 1, "L0(1) → L1(2,3)", 2),
    # slider 1 driven along its guide; link 2 + left door 3, link 4 + right door 5 (RRR
    # each): n = 5, p5 = 7 (slide, P twice, BL, BR, HL, HR)
    "20_solar_panel_doors.yaml": (5, 7, 0, 1, "L0(1) → L1(2,3) → L1(4,5)", 2),
}


# ------------------------------------------------------------------ indicator diagrams
@dataclass(frozen=True)
class Chamber:
    """One working chamber of a piston compressor on a piston (pressures MPa, lengths mm).

    ``far``: the chamber lies beyond the piston seen from the crank (its volume shrinks as
    the piston's distance ``param`` from the crank grows; its pressure pushes the piston
    towards the crank), else between the piston and the crank.  ``area`` mm²."""

    area: float
    far: bool
    suction: float
    discharge: float
    clearance: float
    n: float


def compressor_pressure(s: np.ndarray, ch: Chamber) -> np.ndarray:
    """Pressure (MPa) of a compressor chamber over one cycle of positions from the piston's
    distance ``s`` (mm) from the crank: re-expansion from the discharge pressure after the
    dead centre of least volume, suction, compression from the dead centre of most volume,
    discharge; polytropes of exponent ``n``; clearance as a share of the swept volume."""
    stroke = s.max() - s.min()
    travel = (s.max() - s) if ch.far else (s - s.min())       # from the least volume
    volume = travel + ch.clearance * stroke                     # per unit area
    least, most = volume.min(), volume.max()
    first, last = int(np.argmin(volume)), int(np.argmax(volume))
    k = np.arange(s.size)
    # positions from the least to the most volume (cyclically) expand, the others compress
    expanding = ((k - first) % (s.size - 1)) <= ((last - first) % (s.size - 1))
    expanding[-1] = expanding[0]                                # the last is the first
    expansion = np.maximum(ch.suction, ch.discharge * (least / volume) ** ch.n)
    compression = np.minimum(ch.discharge, ch.suction * (most / volume) ** ch.n)
    return np.where(expanding, expansion, compression)


@dataclass(frozen=True)
class Engine:
    """A four-stroke cylinder's idealized indicator diagram (pressures MPa, angles deg of
    the crank, lengths mm).  ``phase``: the crank angle (argument 1) at which the cylinder's
    cycle starts (the top dead centre before intake)."""

    bore: float
    ratio: float           # compression ratio
    phase: float
    intake: float = 0.09
    n_compression: float = 1.35
    ignition: float = 350.0
    peak_at: float = 370.0
    peak: float = 5.5
    n_expansion: float = 1.25
    exhaust_from: float = 540.0
    exhaust: float = 0.11


def engine_pressure(s: np.ndarray, crank: np.ndarray, e: Engine) -> np.ndarray:
    """Pressure (MPa) over the positions: intake at ``intake`` (0..180 deg of the cycle),
    polytropic compression from the largest volume, a linear rise from ``ignition`` to
    ``peak`` at ``peak_at``, polytropic expansion from there, exhaust from ``exhaust_from``;
    the volume from the piston's distance ``s`` from the crank and the compression ratio."""
    stroke = s.max() - s.min()
    volume = (s.max() - s) + stroke / (e.ratio - 1.0)          # per unit area, mm
    cycle = (crank - e.phase) % 720.0
    most = volume.max()

    def at(angle: float) -> float:
        return float(volume[np.argmin(np.abs(((crank - e.phase) % 720.0) - angle))])

    compression = e.intake * (most / volume) ** e.n_compression
    start = e.intake * (most / at(e.ignition)) ** e.n_compression
    rise = start + (e.peak - start) * (cycle - e.ignition) / (e.peak_at - e.ignition)
    expansion = e.peak * (at(e.peak_at) / volume) ** e.n_expansion
    return np.select([cycle < 180.0, cycle < e.ignition, cycle < e.peak_at,
                      cycle < e.exhaust_from],
                     [np.full_like(s, e.intake), compression, rise, expansion], e.exhaust)


#: file: {force name: (piston distance parameter, chambers or engine, crankcase MPa)}
GAS: dict[str, dict[str, tuple]] = {
    # double-acting: head end (far, full bore 160 mm) and crank end (ring around the 40 mm
    # piston rod), 0.1 -> 0.35 MPa, clearance 0.06, n = 1.3
    "05_compressor.yaml": {"gas": ("r3", (
        Chamber(np.pi * 160**2 / 4, True, 0.1, 0.35, 0.06, 1.3),
        Chamber(np.pi * (160**2 - 40**2) / 4, False, 0.1, 0.35, 0.06, 1.3)), 0.1)},
    # bore 148 mm, ratio 7, supercharged intake; the articulated cylinder 420 deg later
    "12_v_engine_articulated.yaml": {
        "gas 1": ("r3", Engine(148, 7, 0, intake=0.12, peak=6.5, n_expansion=1.27), 0.1),
        "gas 2": ("r7", Engine(148, 7, 420, intake=0.12, peak=6.5, n_expansion=1.27), 0.1)},
    # bore 84 mm, ratio 10; cylinder 2 450 deg later
    "13_v_engine_fork_and_blade.yaml": {
        "gas 1": ("r3", Engine(84, 10, 0, peak=6.0), 0.1),
        "gas 2": ("r6", Engine(84, 10, 450, peak=6.0), 0.1)},
    # two single-acting cylinders, bore 100 mm, 0.1 -> 0.8 MPa, clearance 0.05
    "16_two_cylinder_compressor.yaml": {
        f"gas {k}": (p, (Chamber(np.pi * 100**2 / 4, True, 0.1, 0.8, 0.05, 1.3),), 0.1)
        for k, p in ((1, "r3"), (2, "r6"))},
    # LP bore 150 mm 0.1 -> 0.33 MPa, HP bore 90 mm 0.33 -> 1.1 MPa
    "18_two_stage_compressor.yaml": {
        "LP gas": ("r3", (Chamber(np.pi * 150**2 / 4, True, 0.1, 0.33, 0.05, 1.3),), 0.1),
        "HP gas": ("r6", (Chamber(np.pi * 90**2 / 4, True, 0.33, 1.1, 0.06, 1.3),), 0.1)},
}


def gas_force(results: mechloop.Results, spec: tuple) -> np.ndarray:
    """The net gas force (kN) towards the crank over the positions for one piston."""
    param, diagram, ambient = spec
    s = results.value(param) * 1e3                               # mm
    if isinstance(diagram, Engine):
        crank = np.degrees(results.arguments[1])
        area = np.pi * diagram.bore ** 2 / 4
        return (engine_pressure(s, crank, diagram) - ambient) * area / 1e3
    force = np.zeros_like(s)
    for ch in diagram:
        sign = 1.0 if ch.far else -1.0
        force += sign * (compressor_pressure(s, ch) - ambient) * ch.area / 1e3
    return force


def format_table(values: np.ndarray, indent: int) -> str:
    """The table as the model files write it: kN to 1 N, 8 values a line."""
    items = [f"{v:.3f}" for v in np.round(values, 3) + 0.0]
    lines = [", ".join(items[i:i + 8]) for i in range(0, len(items), 8)]
    return "[" + (",\n" + " " * indent).join(lines) + "]"


# ------------------------------------------------------------------------------ tests
FILES = sorted(HAND)


@functools.cache
def _load(name: str) -> mechloop.Model:
    return mechloop.load_model(COURSE / name)


@functools.cache
def _solved(name: str) -> mechloop.Results:
    """The kinematics of a model, solved once for the tests of this file (read only)."""
    return mechloop.solve(_load(name))


@pytest.mark.parametrize("name", FILES)
def test_solves_without_a_break_over_the_working_range(name: str):
    res = _solved(name)
    assert not res.broken.any() and not res.breaks and not res.breaks_between
    for key, value in res.values.items():
        assert np.all(np.isfinite(value)), key


@pytest.mark.parametrize("name", FILES)
def test_dynamics_are_finite_and_the_works_balance(name: str):
    model = _load(name)
    dyn = mechloop.solve_dynamics(model)
    frame = dyn.to_frame()
    numbers = frame.select_dtypes("number").to_numpy()
    assert np.all(np.isfinite(numbers))
    s = dyn.summary
    residual = sum(r.positive_work + r.negative_work for r in s.rows) - s.kinetic_energy_change
    largest = max(r.positive_work - r.negative_work for r in s.rows)
    assert abs(residual) < 1e-6 * largest
    # the balancing load by kinetostatics and by virtual power agree
    for arg, load in dyn.forces.balancing.items():
        assert np.allclose(load, dyn.balancing_vp[arg], rtol=0, atol=1e-6 * np.abs(load).max())
    if model.machine is not None:
        cycle = dyn.cycle
        assert np.isfinite(cycle.constant_load) and cycle.flywheel is not None
        assert np.isfinite(cycle.flywheel) and cycle.flywheel >= 0
        omega = frame["omega_fw [rad/s]"].to_numpy()
        mean = 2 * np.pi * model.time.rpm / 60
        delta = (omega.max() - omega.min()) / mean
        assert delta == pytest.approx(model.machine.delta, rel=1e-3)


@pytest.mark.parametrize("name", FILES)
def test_mobility_and_groups_are_the_hand_count(name: str):
    mob, dec = analyze(_load(name))
    n, p5, p4, w, formula, klass = HAND[name]
    assert (mob.n, mob.p5, mob.p4, mob.W, mob.inputs) == (n, p5, p4, w, 1)
    assert dec.formula == formula and dec.mechanism_class == klass


@pytest.mark.parametrize("name", sorted(GAS))
def test_gas_tables_are_the_stated_indicator_diagrams(name: str):
    res = _solved(name)
    data = yaml.safe_load((COURSE / name).read_text(encoding="utf-8"))
    tables = {f["name"]: np.asarray(f["value"]["table"], float) for f in data["forces"]
              if f["name"] in GAS[name]}
    assert tables.keys() == GAS[name].keys()
    for force, spec in GAS[name].items():
        expected = gas_force(res, spec)
        assert np.abs(tables[force] - expected).max() <= 0.0005 + 1e-9, force


def test_the_ranges_the_headers_state():
    solved = _solved

    def deg(res: mechloop.Results, name: str) -> np.ndarray:
        return np.degrees(res.value(name))

    # 12: the articulated piston's dead centres fall a little off those of a central
    # slider-crank at 60 deg (60 and 240 deg of the crank): found on a dense copy
    data = yaml.safe_load((COURSE / "12_v_engine_articulated.yaml").read_text())
    for key in ("bodies", "forces", "gravity", "machine"):
        data.pop(key)
    data["positions"], data["arguments"][1] = 7200, {"table": {0: 0, 7200: 720}}
    dense = mechloop.solve(mechloop.Model.from_dict(data))
    s, crank = dense.value("r7"), np.degrees(dense.arguments[1])
    top, bottom = crank[np.argmax(s)], crank[np.argmin(s)]
    assert 60.5 < top < 63 and 235 < bottom < 239.5
    assert np.ptp(dense.value("r3")) * 1e3 == pytest.approx(170, abs=1e-9)
    # 14: the flap turns from 25 deg inwards to about in line with the axis
    door = deg(solved("14_nozzle_ring.yaml"), "a6") - 360
    assert door[0] == pytest.approx(-25, abs=0.05) and -1 < door[-1] < 0
    # 15: the primary flap from 30 to 12 deg inwards, the divergent one out from 5 to 9 deg
    res = solved("15_nozzle_flaps.yaml")
    primary, divergent = deg(res, "a5") - 360, deg(res, "a6")
    assert primary[[0, -1]] == pytest.approx([-30, -12], abs=0.05)
    assert np.round(divergent[[0, -1]]).tolist() == [5, 9]
    # 19: the ram moves down (r7 grows) over more of the crank's turn than up: quick return
    rate = solved("19_gear_shaper.yaml").rate("r7")
    assert (rate > 0).sum() > (rate < 0).sum() + 4
    # 20: the doors open from flat to 119 deg, mirror images of each other
    res = solved("20_solar_panel_doors.yaml")
    left, right = deg(res, "a9"), 180 - (deg(res, "a11") % 360)
    assert round(left[0]) == 0 and round(left[-1]) == 119 and np.all(np.diff(left) > 0)
    assert np.allclose(left, right, atol=1e-9)
