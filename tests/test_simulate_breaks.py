"""Motion in time of a machine whose chain breaks: the run stops at the last position
before the break with the event ``"chain break ahead"``, naming the exact input value where
the chain breaks (checked against Grashof's closed-form limit of a four-bar), and no row
holds a NaN; a range that simply ends is the event ``"range"`` (issue 13)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from oracles.dynamic_models import four_bar_data
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.dynamics.simulate import simulate
from mechloop.errors import ModelError

TIGHT = {"rtol": 1e-10, "atol": 1e-12}
CRANK, FRAME, ROCKER = 0.1, 0.3, 0.25


def _four_bar(coupler: float, positions: int = 72, **simulate_section) -> mechloop.Model:
    """A four-bar driven at the crank (0.1 m; frame 0.3 m, rocker 0.25 m): with
    ``coupler + rocker < crank + frame`` the crank cannot pass the angle where the crank
    pin is ``coupler + rocker`` from the rocker's pivot."""
    data = {**four_bar_data(coupler, positions, crank=CRANK, frame=FRAME, rocker=ROCKER),
            "simulate": {"motor": {"constant": 0.5}, "duration": 5, **TIGHT,
                         **simulate_section}}
    return mechloop.Model.from_dict(data)


def _limit(coupler: float) -> float:
    """The crank angle (rad, in 0..pi) where the crank pin is ``coupler + rocker`` from
    the rocker's pivot: law of cosines in the triangle crank, frame, coupler + rocker."""
    reach = coupler + ROCKER
    return math.acos((CRANK**2 + FRAME**2 - reach**2) / (2 * CRANK * FRAME))


def test_a_crank_that_cannot_turn_stops_before_the_exact_break():
    model = _four_bar(0.14)
    assert mechloop.solve(model).broken.any()
    sim = simulate(model)
    end = sim.end
    assert end.kind == "chain break ahead"
    # the break from the exact existence check, not the grid's 150 deg (the check takes
    # the loss where its margin falls to THRESHOLD, 1.2e-12 rad from the geometric limit
    # here; 1e-9 rad is a thousandth of the 150 deg grid point's miss of 4.6e-3 rad)
    assert end.at == pytest.approx(_limit(0.14), abs=1e-9)
    assert math.degrees(end.at) != pytest.approx(150.0, abs=0.1)
    # the run stops at the last position before it, with the state there
    assert end.q == pytest.approx(math.radians(150.0), abs=1e-9)
    assert end.q < end.at and end.omega > 0
    assert sim.q[-1] == pytest.approx(end.q, abs=1e-9)
    assert np.all(sim.q <= end.q + 1e-9)
    frame = sim.to_frame()
    assert not frame.isna().any().any()
    assert np.all(np.isfinite(frame.to_numpy(dtype=float)))
    # the energy still balances over the stretch the machine ran
    assert np.abs(sim.balance).max() < 1e-6 * sim.kinetic_energy.max()
    # no cycle over a stretch between two breaks
    assert not sim.machine.periodic and sim.cycle_time.size == 0


def test_backwards_the_stretch_wraps_around_the_turn_and_stops_at_the_other_limit():
    # started at 300 deg turning backwards: the stretch runs 210 -> 360 -> 510 deg (the
    # positions 42..72 and 0..30 a turn on); the break below is at 360 deg - limit
    model = _four_bar(0.14, motor={"constant": -0.5}, reverse=True,
                      start={"angle": 300})
    sim = simulate(model)
    end = sim.end
    assert end.kind == "chain break ahead" and end.omega < 0
    assert end.at == pytest.approx(2 * math.pi - _limit(0.14), abs=1e-9)
    assert end.q == pytest.approx(math.radians(210.0), abs=1e-9)
    assert sim.machine.q[0] == pytest.approx(math.radians(210), abs=1e-12)
    assert sim.machine.q[-1] == pytest.approx(math.radians(510), abs=1e-12)


def test_a_break_between_two_positions_that_assemble_stops_the_run_too():
    # coupler + rocker 1 um short of crank + frame: the crank loses its turn for about
    # 0.6 deg around 180 deg, between positions 36 (177.5 deg) and 37 (182.5 deg) of 73
    model = _four_bar(0.149999, positions=73)
    kin = mechloop.solve(model)
    assert not kin.broken.any() and kin.breaks_between
    sim = simulate(model)
    assert sim.end.kind == "chain break ahead"
    assert sim.end.at == pytest.approx(_limit(0.149999), abs=1e-9)
    assert sim.end.q == pytest.approx(math.radians(36 * 360 / 73), abs=1e-9)
    assert sim.end.q < sim.end.at


def test_a_start_at_a_break_is_located():
    with pytest.raises(ModelError) as info:
        simulate(_four_bar(0.14, start={"angle": 180}))
    assert info.value.problems[0].path == ("simulate", "start")
    assert "chain break" in str(info.value)


def test_the_command_line_names_the_break_and_warns(tmp_path):
    import yaml

    model = _four_bar(0.14)
    path = tmp_path / "four_bar_break.yaml"
    path.write_text(yaml.safe_dump(model.model_dump(mode="json", exclude_none=True)))
    result = CliRunner().invoke(app, ["simulate", str(path)])
    assert result.exit_code == 0, result.output
    assert "chain break ahead" in result.output
    assert f"breaks at angle {math.degrees(_limit(0.14)):.8g} deg" in result.output
    assert "warning:" in result.output and "not a cycle" in result.output


def test_a_rocker_range_that_ends_is_a_plain_event():
    # the crank over 0..180 deg only (the model's range, not a break): the event says so
    model = _four_bar(0.2, positions=36)
    data = model.model_dump(mode="json", exclude_none=True)
    data["arguments"] = {1: {"table": {0: 0, 36: 180}}}
    model = mechloop.Model.from_dict(data)
    sim = simulate(model)
    assert sim.end.kind == "range" and sim.end.at is None
    assert sim.end.q == pytest.approx(math.pi, abs=1e-9)
    assert "end of the model's range" in sim.end.describe()


def test_the_example_runs_up_to_the_break():
    # examples/four_bar_break_ahead.yaml: crank 100, coupler 140, rocker 250, frame 300
    # mm; its header's figures: the break at 150.266 deg, positions 31 to 41 broken
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "examples" / "four_bar_break_ahead.yaml"
    model = mechloop.load_model(path)
    broken = np.flatnonzero(mechloop.solve(model).broken)
    assert broken.tolist() == list(range(31, 41 + 1))
    sim = simulate(model)
    assert sim.end.kind == "chain break ahead"
    assert math.degrees(sim.end.at) == pytest.approx(150.266, abs=5e-4)
    assert sim.end.at == pytest.approx(_limit(0.14), abs=1e-9)  # the same four-bar in m
    assert sim.end.q == pytest.approx(math.radians(150), abs=1e-9)


def test_a_start_between_positions_and_across_the_turn():
    # started at -42.5 deg (a turn below 317.5, between positions 63 and 64): the stretch
    # runs from 210 - 360 deg to 150 deg, positions 42..72 and 0..30
    sim = simulate(_four_bar(0.14, start={"angle": -42.5, "rpm": 10}))
    q = sim.machine.q
    assert q[0] == pytest.approx(math.radians(-150), abs=1e-12)
    assert q[-1] == pytest.approx(math.radians(150), abs=1e-12)
    assert sim.q[0] == pytest.approx(math.radians(-42.5), abs=1e-12)
    assert sim.end.kind == "chain break ahead"
    assert sim.end.at == pytest.approx(_limit(0.14), abs=1e-9)
