"""Parametric analysis (``mechloop sweep``) and the Dask scale-out behind it.

The reference for every swept value is independent of the sweep machinery: the model
document is edited by hand (plain YAML data), built with ``Model.from_dict``, solved, and
the column reduced with NumPy.  The physics check: with a constant crank speed ω and only
inertia loads, every acceleration is ω² times its analog, so every inertia load — and the
balancing moment that holds them — scales exactly as ω².
"""

from __future__ import annotations

import math
import operator
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from matplotlib.figure import Figure
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.synthesis import parallel
from mechloop.synthesis.parallel import SchedulerError, choose_scheduler, map_tasks
from mechloop.synthesis.sweep import (
    REDUCTIONS,
    SweepError,
    grid,
    parse_values,
    parse_vary,
    reduce_column,
    sweep,
)
from mechloop.views.figure import ViewError
from mechloop.views.sweep import plot_sweep

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def document(name: str) -> dict:
    """The raw data of an example model file (integer keys, as YAML reads them)."""
    return yaml.safe_load((EXAMPLES / name).read_text(encoding="utf-8"))


def built(data: dict) -> mechloop.Model:
    return mechloop.Model.from_dict(data)


def slider_crank(**changes) -> dict:
    """examples/crank_slider_dynamics.yaml as data with top-level keys replaced
    (a value None removes the key)."""
    data = document("crank_slider_dynamics.yaml")
    for key, value in changes.items():
        if value is None:
            data.pop(key, None)
        else:
            data[key] = value
    return data


def inertia_only() -> dict:
    """The dynamic slider-crank without its slider force and gravity: only inertia loads
    (no friction in that model)."""
    return slider_crank(forces=None, gravity=None)


# ---------------------------------------------------------------- values against direct


def test_sweep_equals_each_modified_model_solved_directly():
    base = slider_crank()
    rods = [0.15, 0.2, 0.25]
    table = sweep(built(base), {"vectors.2.r": rods},
                  ["r3:range", "da2:absmax", "M_bal:max", "RA:rms", "J_red:mean"])
    assert list(table.columns) == ["vectors.2.r [m]", "r3:range [m]", "da2:absmax [rad/s]",
                                   "M_bal:max [N*m]", "RA:rms [N]", "J_red:mean [kg*m^2]",
                                   "broken", "note"]
    np.testing.assert_array_equal(table["vectors.2.r [m]"], rods)
    for row, rod in zip(table.itertuples(index=False), rods, strict=True):
        data = slider_crank()
        data["vectors"][2]["r"] = rod
        dyn = mechloop.solve_dynamics(built(data))
        kin = dyn.kinematics
        r3 = kin.value("r3")
        expected = [r3.max() - r3.min(),
                    np.abs(kin.rate("a2")).max(),
                    dyn.forces.balancing[1].max(),
                    np.sqrt(np.mean(np.abs(dyn.forces.reactions["A"].force) ** 2)),
                    dyn.reduced.inertia.mean()]
        np.testing.assert_allclose(row[1:6], expected, rtol=1e-12)
        assert row.broken == 0 and row.note == ""


def test_peak_balancing_moment_scales_as_speed_squared():
    speeds = np.array([500.0, 1000.0, 3000.0])
    table = sweep(built(inertia_only()), {"time.rpm": speeds},
                  ["M_bal:absmax", "M_bal:max", "M_bal:min", "M_bal:at=7", "RB:absmax"])
    ratio = (speeds / speeds[0]) ** 2
    for column in ("M_bal:absmax [N*m]", "M_bal:max [N*m]", "M_bal:min [N*m]",
                   "M_bal:at=7 [N*m]", "RB:absmax [N]"):
        values = table[column].to_numpy()
        assert np.all(np.abs(values) > 0), column
        np.testing.assert_allclose(values / values[0], ratio, rtol=1e-9, err_msg=column)


def test_reductions_agree_with_numpy():
    model = mechloop.load_model(EXAMPLES / "crank_slider.yaml")
    specs = [f"r3:{r}" for r in REDUCTIONS] + ["r3:at=10", "ddr3:rms", "a2:range",
                                                "dda2:at=0"]
    table = sweep(model, {"time.rpm": [3000]}, specs)
    res = mechloop.solve(model)
    r3, ddr3 = res.value("r3"), res.accel("r3")
    a2 = np.degrees(res.value("a2"))  # the table writes angles in degrees
    expected = {"max": r3.max(), "min": r3.min(), "mean": r3.mean(),
                "rms": np.sqrt(np.mean(r3**2)), "range": np.ptp(r3), "absmax": np.abs(r3).max()}
    for reduction, value in expected.items():
        assert table.at[0, f"r3:{reduction} [m]"] == pytest.approx(value, rel=1e-13)
    assert table.at[0, "r3:at=10 [m]"] == r3[10]
    assert table.at[0, "ddr3:rms [m/s^2]"] == pytest.approx(np.sqrt(np.mean(ddr3**2)),
                                                            rel=1e-13)
    assert table.at[0, "a2:range [deg]"] == pytest.approx(np.ptp(a2), rel=1e-13)
    assert table.at[0, "dda2:at=0 [rad/s^2]"] == res.accel("a2")[0]


def test_reduce_column_by_hand():
    x = np.array([1.0, -4.0, 2.0, 3.0])
    assert reduce_column(x, "max") == 3.0
    assert reduce_column(x, "min") == -4.0
    assert reduce_column(x, "mean") == 0.5
    assert reduce_column(x, "rms") == pytest.approx(math.sqrt((1 + 16 + 4 + 9) / 4))
    assert reduce_column(x, "range") == 7.0
    assert reduce_column(x, "absmax") == 4.0
    assert reduce_column(x, "at=1") == -4.0
    assert reduce_column(x, "at = 3") == 3.0


def test_two_parameter_grid_has_the_right_shape_and_order():
    rods, speeds = [0.15, 0.2], [1000.0, 2000.0, 3000.0]
    model = mechloop.load_model(EXAMPLES / "crank_slider.yaml")
    table = sweep(model, {"vectors.2.r": rods, "time.rpm": "1000:3000:3"},
                  ["dr3:absmax", "r3:max"])
    assert table.shape == (6, 6)
    # the first parameter varies slowest
    np.testing.assert_array_equal(table["vectors.2.r [m]"], [0.15] * 3 + [0.2] * 3)
    np.testing.assert_array_equal(table["time.rpm [rpm]"], speeds * 2)
    for row in table.itertuples(index=False):
        data = document("crank_slider.yaml")
        data["vectors"][2]["r"] = row[0]
        data["time"] = {"rpm": row[1]}
        res = mechloop.solve(built(data))
        assert row[2] == pytest.approx(np.abs(res.rate("r3")).max(), rel=1e-13)
        assert row[3] == pytest.approx(res.value("r3").max(), rel=1e-13)
    x, y, z = grid(table, "dr3:absmax [m/s]")
    np.testing.assert_array_equal(x, rods)
    np.testing.assert_array_equal(y, speeds)
    assert z.shape == (2, 3)
    np.testing.assert_array_equal(z.ravel(), table["dr3:absmax [m/s]"])
    # the stroke does not depend on the speed; the piston speed is proportional to it
    np.testing.assert_allclose(z[:, 2] / z[:, 0], 3.0, rtol=1e-12)


def test_values_with_units_and_ranges_are_read_in_the_model_units():
    engine = mechloop.load_model(EXAMPLES / "single_cylinder_engine.yaml")  # lengths in mm
    table = sweep(engine, {"vectors.2.r": "0.12 m:160 mm:3"}, ["r3:max"])
    np.testing.assert_allclose(table["vectors.2.r [mm]"], [120.0, 140.0, 160.0])
    # crank 40 mm: at top dead centre the piston is r1 + r2 from the crank axis
    np.testing.assert_allclose(table["r3:max [m]"], [0.16, 0.18, 0.2], rtol=1e-12)
    assert parse_values("1000:4000:4") == [1000.0, 2000.0, 3000.0, 4000.0]
    assert parse_values("0.1, 50 mm") == [0.1, "50 mm"]
    assert parse_vary("bodies.2.mass=1,2") == ("bodies.2.mass", [1.0, 2.0])
    masses = sweep(engine, {"bodies[2].mass": ["1200 g", 2.0]}, ["M_bal:rms"])
    np.testing.assert_array_equal(masses["bodies[2].mass [kg]"], [1.2, 2.0])


def test_unitless_settings_sweep_as_whole_numbers_and_fractions():
    four_bar = mechloop.load_model(EXAMPLES / "four_bar.yaml")
    variants = sweep(four_bar, {"contours.0.variant": "1,2"}, ["a3:at=5"])
    assert variants["contours.0.variant"].tolist() == [1, 2]
    for variant, value in zip([1, 2], variants["a3:at=5 [deg]"], strict=True):
        data = document("four_bar.yaml")
        data["contours"][0]["variant"] = variant
        expected = np.degrees(mechloop.solve(built(data)).value("a3")[5])
        assert value == pytest.approx(expected, rel=1e-13)
    assert variants.at[0, "a3:at=5 [deg]"] != pytest.approx(variants.at[1, "a3:at=5 [deg]"])
    # the flywheel holds the speed swing to δ times the nominal speed (3000 rpm)
    engine = mechloop.load_model(EXAMPLES / "single_cylinder_engine.yaml")
    flywheels = sweep(engine, {"machine.delta": [0.01, 0.02]}, ["omega_fw:range"])
    np.testing.assert_allclose(flywheels["omega_fw:range [rad/s]"],
                               np.array([0.01, 0.02]) * 3000 * 2 * np.pi / 60, rtol=1e-6)


# ----------------------------------------------------------------------- chain breaks


def test_a_design_that_breaks_is_reported_not_raised():
    model = mechloop.load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    table = sweep(model, {"vectors.2.r": [0.2, 0.03]}, ["r3:max", "M_bal:absmax"])
    data = slider_crank()
    data["vectors"][2]["r"] = 0.03
    short = mechloop.solve(built(data))
    assert short.broken.any()
    assert table.at[1, "broken"] == int(short.broken.sum())
    assert "contour 1 (Pl3) breaks at positions" in table.at[1, "note"]
    assert np.isnan(table.loc[1, ["r3:max [m]", "M_bal:absmax [N*m]"]].to_numpy(float)).all()
    assert table.at[0, "broken"] == 0 and table.at[0, "note"] == ""
    assert np.isfinite(table.loc[0, ["r3:max [m]", "M_bal:absmax [N*m]"]].to_numpy(float)).all()


# ---------------------------------------------------------------------- user mistakes


@pytest.mark.parametrize(("path", "words"), [
    ("tim.rpm", ["has no key 'tim'", "time", "vectors", "bodies"]),
    ("vectors.9.r", ["vectors has no key '9'", "1, 2, 3, 4"]),
    ("vectors.1.radius", ["vectors.1 has no key 'radius'", "r, a, b, name"]),
    ("forces.3.value", ["forces is a list of 1 item(s)", "0..0"]),
    ("machine.delta", ["machine is not set in this model", "add 'machine:'"]),
    ("vectors.1", ["group of settings", "vectors.1.r"]),
    ("vectors.1.r.offset", ["single value", "sweep vectors.1.r itself"]),
    ("vectors..r", ["cannot read the parameter path", "separated by dots"]),
])
def test_a_bad_path_names_the_place_and_the_valid_keys(path, words):
    model = mechloop.load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    with pytest.raises(SweepError) as info:
        sweep(model, {path: [1.0]}, ["r3:max"])
    text = str(info.value)
    assert isinstance(info.value, ValueError | mechloop.MechloopError)
    for word in words:
        assert word in text, text


@pytest.mark.parametrize(("model_file", "quantity", "words"), [
    ("crank_slider_dynamics.yaml", "M_bla:max", ["no column 'M_bla'", "did you mean M_bal"]),
    ("crank_slider.yaml", "M_bal:max", ["no column 'M_bal'", "need a model with bodies"]),
    ("crank_slider.yaml", "r3:maximum", ["unknown reduction 'maximum'", "absmax",
                                         "at=K"]),
    ("crank_slider.yaml", "r3:at=500", ["no position 500", "0 to 72"]),
    ("crank_slider.yaml", "r3", ["cannot read the quantity", "COLUMN:REDUCTION"]),
])
def test_a_bad_quantity_names_the_fix(model_file, quantity, words):
    model = mechloop.load_model(EXAMPLES / model_file)
    with pytest.raises(SweepError) as info:
        sweep(model, {"time.rpm": [1000.0]}, [quantity])
    for word in words:
        assert word in str(info.value), str(info.value)


def test_other_mistakes_name_the_fix():
    model = mechloop.load_model(EXAMPLES / "crank_slider.yaml")
    cases = [
        ({"vectors.2.r": ["20 kg"]}, ["r3:max"], "cannot read '20 kg' as a value in m"),
        ({"vectors.2.r": "0.1:0.2"}, ["r3:max"], "start:stop:count"),
        ({"vectors.2.r": [0.2], "time.rpm": [1.0], "vectors.1.r": [0.05]}, ["r3:max"],
         "one or two parameters"),
        ({"time.rpm": [1.0], "time[rpm]": [2.0]}, ["r3:max"], "varied twice"),
        ({"time.rpm": [1.0]}, [], "no quantity"),
    ]
    for parameters, quantities, words in cases:
        with pytest.raises(SweepError, match=None) as info:
            sweep(model, parameters, quantities)
        assert words in str(info.value), str(info.value)
    with pytest.raises(SchedulerError, match="'serial', 'processes'"):
        sweep(model, {"time.rpm": [1.0]}, ["r3:max"], scheduler="threads")


def test_an_invalid_design_raises_a_model_error_naming_it():
    model = mechloop.load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    with pytest.raises(mechloop.ModelError) as info:
        sweep(model, {"bodies.2.mass": [1.5, -1.0]}, ["M_bal:max"])
    text = str(info.value)
    assert "the design bodies.2.mass=-1" in text
    assert "bodies[2].mass: a mass cannot be negative" in text


# ------------------------------------------------------------------------------ views


def test_plots_of_one_and_two_parameters():
    model = mechloop.load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    line = sweep(model, {"time.rpm": "1000:3000:3"}, ["M_bal:max", "M_bal:rms", "RA:absmax"])
    figure = plot_sweep(line)
    assert isinstance(figure, Figure)
    assert len(figure.axes) == 2  # N*m and N: one plot per unit
    assert [len(ax.lines) for ax in figure.axes] == [2, 1]
    np.testing.assert_allclose(figure.axes[1].lines[0].get_ydata(), line["RA:absmax [N]"])

    family = sweep(model, {"time.rpm": [1000, 2000], "vectors.2.r": [0.15, 0.2, 0.25]},
                   ["M_bal:absmax"])
    lines = plot_sweep(family)
    assert len(lines.axes) == 1 and len(lines.axes[0].lines) == 3
    assert lines.axes[0].get_legend().get_texts()[0].get_text() == "vectors.2.r = 0.15 m"
    mapped = plot_sweep(family, contour=True)
    assert len(mapped.axes) == 2  # the map and its colour bar

    back = pd.read_csv(pd.io.common.StringIO(family.to_csv(index=False)))
    assert len(plot_sweep(back, "M_bal:absmax", contour=False).axes[0].lines) == 3
    with pytest.raises(ViewError, match="use one of M_bal:absmax"):
        plot_sweep(family, "RA:max")


# -------------------------------------------------------------------------------- CLI


def test_cli_sweep_writes_the_table(tmp_path):
    path = EXAMPLES / "crank_slider_dynamics.yaml"
    out, figure = tmp_path / "sweep.csv", tmp_path / "sweep.png"
    result = CliRunner().invoke(app, ["sweep", str(path), "--vary", "time.rpm=1000:3000:3",
                                      "--collect", "M_bal:absmax", "--collect", "r3:range",
                                      "-o", str(out), "--plot", str(figure)])
    assert result.exit_code == 0, result.output
    frame = pd.read_csv(out, keep_default_na=False)
    assert list(frame.columns) == ["time.rpm [rpm]", "M_bal:absmax [N*m]", "r3:range [m]",
                                   "broken", "note"]
    expected = sweep(mechloop.load_model(path), {"time.rpm": [1000, 2000, 3000]},
                     ["M_bal:absmax", "r3:range"])
    np.testing.assert_allclose(frame["M_bal:absmax [N*m]"], expected["M_bal:absmax [N*m]"],
                               rtol=1e-14)
    assert figure.stat().st_size > 0
    assert "M_bal:absmax [N*m]" in result.output and "Parametric analysis" in result.output


def test_cli_sweep_reports_breaks_and_errors(tmp_path):
    path = str(EXAMPLES / "crank_slider.yaml")
    runner = CliRunner()
    result = runner.invoke(app, ["sweep", path, "--vary", "vectors.2.r=0.2,0.03",
                                 "--collect", "r3:max"])
    assert result.exit_code == 0, result.output
    assert "no values for vectors.2.r [m] = 0.03" in result.output
    assert "breaks at positions" in result.output
    for args, words in [
        (["--vary", "vectors.7.r=1,2", "--collect", "r3:max"], "vectors has no key '7'"),
        (["--vary", "time.rpm=1,2", "--collect", "r4:max"], "no column 'r4'"),
        (["--vary", "time.rpm", "--collect", "r3:max"], "PATH=VALUES"),
        (["--vary", "time.rpm=1,2", "--collect", "r3:max", "--scheduler", "threads"],
         "unknown scheduler"),
        (["--vary", "time.rpm=1,2", "--collect", "r3:max", "-o", "x.txt"],
         "unknown output format"),
    ]:
        result = runner.invoke(app, ["sweep", path, *args])
        assert result.exit_code == 2, result.output
        assert words in result.output and "fix:" in result.output
        assert "Traceback" not in result.output


def test_cli_sweep_help_has_a_worked_example():
    result = CliRunner().invoke(app, ["sweep", "--help"])
    assert result.exit_code == 0
    assert "time.rpm=1000:4000:7" in result.output and "M_bal:max" in result.output


# --------------------------------------------------------------------- map_tasks, Dask


def test_map_tasks_serial_keeps_order_and_reports_progress():
    seen = []
    out = map_tasks(operator.neg, [3, 1, 2], scheduler="serial",
                    progress=lambda done, total: seen.append((done, total)))
    assert out == [-3, -1, -2]
    assert seen == [(0, 3), (1, 3), (2, 3), (3, 3)]
    assert map_tasks(operator.neg, [], scheduler="serial") == []


def test_the_automatic_scheduler_rule():
    assert choose_scheduler(8, cpus=4) == "serial"
    assert choose_scheduler(9, cpus=4) == "processes"
    assert choose_scheduler(100, cpus=1) == "serial"
    assert choose_scheduler(100, seconds_per_item=0.05, cpus=4) == "serial"  # 5 s
    assert choose_scheduler(100, seconds_per_item=0.2, cpus=4) == "processes"  # 20 s


@pytest.fixture(scope="module")
def cluster():
    """A LocalCluster of two worker processes shared by the tests that need an address."""
    from distributed import LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as local:
        yield local


def _engine_sweep(scheduler, progress=None) -> pd.DataFrame:
    model = mechloop.load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    return sweep(model, {"time.rpm": "1000:3000:3", "vectors.2.r": [0.15, 0.2]},
                 ["M_bal:max", "RA:rms", "r3:range"], scheduler=scheduler,
                 progress=progress)


def test_a_local_dask_cluster_gives_the_serial_results():
    serial = _engine_sweep("serial")
    seen = []
    start = time.perf_counter()
    local = _engine_sweep("processes", progress=lambda done, total: seen.append(done))
    assert time.perf_counter() - start < 60
    pd.testing.assert_frame_equal(local, serial, check_exact=True)
    assert seen[0] == 0 and seen[-1] == len(serial) and seen == sorted(seen)


def test_a_cluster_address_gives_the_serial_results(cluster):
    serial = _engine_sweep("serial")
    pd.testing.assert_frame_equal(_engine_sweep(cluster.scheduler_address), serial,
                                  check_exact=True)
    assert map_tasks(operator.neg, [3, 1, 2], scheduler=cluster.scheduler_address) \
        == [-3, -1, -2]


def test_an_error_in_a_worker_comes_back_as_raised(cluster):
    model = mechloop.load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    with pytest.raises(mechloop.ModelError) as info:
        sweep(model, {"bodies.2.mass": [1.0, 2.0, -1.0, 3.0]}, ["M_bal:max"],
              scheduler=cluster.scheduler_address)
    assert "the design bodies.2.mass=-1" in str(info.value)
    assert "a mass cannot be negative" in str(info.value)
    with pytest.raises(mechloop.ModelError) as info:
        map_tasks(mechloop.Model.from_dict, [{"positions": 0}],
                  scheduler=cluster.scheduler_address)
    assert "positions: Input should be greater than or equal to 1" in str(info.value)
    assert "'vectors' is required" in str(info.value)


def test_an_interrupt_cancels_the_queued_work(cluster):
    def stop(done, total):
        if done == 1:
            raise KeyboardInterrupt

    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        map_tasks(time.sleep, [0.5] * 8, scheduler=cluster.scheduler_address, progress=stop)
    assert time.perf_counter() - start < 1.5  # not the 2 s that 8 × 0.5 s on 2 workers take
    from distributed import Client

    with Client(cluster.scheduler_address, set_as_default=False) as client:
        deadline = time.time() + 5
        while client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)) \
                and time.time() < deadline:
            time.sleep(0.05)
        assert client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)) == 0


def test_an_unreachable_scheduler_names_the_fix(monkeypatch):
    monkeypatch.setattr(parallel, "CONNECT_TIMEOUT", 1.0)
    with pytest.raises(SchedulerError) as info:
        map_tasks(operator.neg, [1], scheduler="tcp://127.0.0.1:9")
    assert "cannot reach the dask scheduler at tcp://127.0.0.1:9" in str(info.value)
    assert "dask scheduler" in str(info.value) and "dask worker" in str(info.value)
