"""The loads of the course-project engines and compressors (examples/course/, tasks 5, 12,
13, 16, 18) and the machine cycle of every course model with a ``machine:`` section.

Every gas force is the indicator diagram its header states, recomputed here from the
model's own piston positions: the compressors' (5, 16, 18) are mechloop's indicator loads
(docs/dynamics.md, "Engine and compressor indicator diagrams"), the engines' (12, 13) tables, inputs
of the models.  The diagrams below are written out independently of mechloop (polytropes
between the piston's dead centres), so a table edited by hand, an indicator load given
other numbers or a piston that no longer moves as the diagram assumed fails
``test_indicator_loads_are_the_stated_indicator_diagrams`` or
``test_gas_tables_are_the_stated_indicator_diagrams``.  With ``machine: {delta: ...}`` the
speed with the flywheel found varies by that δ over the cycle.

What every course model must do (no break, finite and balanced dynamics, the mobility) is
tested in tests/test_course_models.py, its structure in tests/test_structure_examples.py.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
import yaml

import mechloop

COURSE = Path(__file__).resolve().parents[1] / "examples" / "course"

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
MACHINES = sorted(p.name for p in COURSE.glob("*.yaml")
                  if "\nmachine:" in p.read_text(encoding="utf-8"))


class _Course:
    """The course models of this module, each loaded, solved and analysed at most once."""

    def __init__(self) -> None:
        self._models: dict[str, mechloop.Model] = {}
        self._solved: dict[str, mechloop.Results] = {}
        self._dynamics: dict[str, mechloop.DynamicResults] = {}

    def model(self, name: str) -> mechloop.Model:
        if name not in self._models:
            self._models[name] = mechloop.load_model(COURSE / name)
        return self._models[name]

    def solved(self, name: str) -> mechloop.Results:
        if name not in self._solved:
            self._solved[name] = mechloop.solve(self.model(name))
        return self._solved[name]

    def dynamics(self, name: str) -> mechloop.DynamicResults:
        if name not in self._dynamics:
            self._dynamics[name] = mechloop.solve_dynamics(self.model(name))
        return self._dynamics[name]


@pytest.fixture(scope="module")
def course() -> _Course:
    return _Course()


#: file: {force of GAS: ((the model's indicator load, its sign towards the crank), ...)}
INDICATOR: dict[str, dict[str, tuple[tuple[str, float], ...]]] = {
    # double-acting: the head end's load pushes towards the crank, the crank end's away
    "05_compressor.yaml": {"gas": (("gas head end", 1.0), ("gas crank end", -1.0))},
    "16_two_cylinder_compressor.yaml": {"gas 1": (("gas 1", 1.0),),
                                        "gas 2": (("gas 2", 1.0),)},
    "18_two_stage_compressor.yaml": {"LP gas": (("LP gas", 1.0),),
                                     "HP gas": (("HP gas", 1.0),)},
}


@pytest.mark.parametrize("name", sorted(INDICATOR))
def test_indicator_loads_are_the_stated_indicator_diagrams(course: _Course, name: str):
    """mechloop's indicator load (the dead centres from the interpolated kinematics, the
    volume from the piston's position) gives the force recomputed here; the cylinders are
    central and the crank steps 5 deg, so both find the dead centres at the same
    positions and agree to rounding."""
    from mechloop.dynamics.indicator import model_indicators

    res = course.solved(name)
    loads = {i.name: i.gas.force / 1e3 for i in model_indicators(course.model(name))}  # kN
    assert loads.keys() == {load for parts in INDICATOR[name].values() for load, _ in parts}
    for force, parts in INDICATOR[name].items():
        expected = gas_force(res, GAS[name][force])
        got = sum(sign * loads[load] for load, sign in parts)
        assert np.abs(got - expected).max() <= 1e-9 * np.abs(expected).max(), force


@pytest.mark.parametrize("name", sorted(set(GAS) - set(INDICATOR)))
def test_gas_tables_are_the_stated_indicator_diagrams(course: _Course, name: str):
    """The engines' diagrams (a linear pressure rise around the firing dead centre) are
    not the indicator load's mixed cycle: their gas forces stay tables."""
    res = course.solved(name)
    data = yaml.safe_load((COURSE / name).read_text(encoding="utf-8"))
    tables = {f["name"]: np.asarray(f["value"]["table"], float) for f in data["forces"]
              if f["name"] in GAS[name]}
    assert tables.keys() == GAS[name].keys()
    for force, spec in GAS[name].items():
        expected = gas_force(res, spec)
        assert np.abs(tables[force] - expected).max() <= 0.0005 + 1e-9, force


def test_every_engine_and_compressor_has_its_diagram_here():
    assert set(GAS) <= set(MACHINES) and set(INDICATOR) <= set(GAS)
    assert set(GAS) == {p.name for p in COURSE.glob("*.yaml")
                        if re.search(r"compressor|engine", p.name)}


@pytest.mark.parametrize("name", MACHINES)
def test_machine_cycle_keeps_the_stated_delta(course: _Course, name: str):
    model, dyn = course.model(name), course.dynamics(name)
    cycle = dyn.cycle
    assert cycle is not None and np.isfinite(cycle.constant_load)
    assert cycle.flywheel is not None and np.isfinite(cycle.flywheel) and cycle.flywheel >= 0
    omega = dyn.to_frame()["omega_fw [rad/s]"].to_numpy()
    mean = 2 * np.pi * model.time.rpm / 60
    delta = (omega.max() - omega.min()) / mean
    assert delta == pytest.approx(model.machine.delta, rel=1e-3)
