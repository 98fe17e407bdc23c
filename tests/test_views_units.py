"""The plots' units: every plotted line equals the solver's value (as the result table
writes it) converted by pint into the unit its label prints — with no ``display:`` section
(angles in degrees, every rate and per-angle quantity per radian: rad/s, rad/s^2, m/rad,
kg*m^2/rad, as the CSV) and with one; and angles plotted continuous over the positions
(a four-bar's transmission angle against its law-of-cosines closed form)."""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pytest
import yaml

import mechloop
from mechloop.model.units import registry
from mechloop.output.display import apply_display, plot_display, resolve
from mechloop.views import curves, dynamics
from mechloop.views.display import DEFAULT_DISPLAY

ROOT = Path(__file__).resolve().parents[1]
LABEL = re.compile(r"^(.+) \[(.+)\]$")


def factor(source: str, target: str) -> float:
    return float(registry().Quantity(1.0, source).to(target).magnitude)


def table_column(frame, name: str) -> tuple[np.ndarray, str]:
    """The values and unit of the table's column ``name`` (its header 'name [unit]')."""
    for column in frame.columns:
        match = LABEL.match(str(column))
        if match and match.group(1) == name:
            return frame[column].to_numpy(dtype=float), match.group(2)
    raise KeyError(name)


def check_line(frame, name: str, unit: str, y, *, angle: bool = False) -> None:
    """The plotted ``y`` is the table's ``name`` converted from the table's unit to the
    printed ``unit`` (an angle: up to whole turns, the table's being wrapped)."""
    values, table_unit = table_column(frame, name)
    expected = values * factor(table_unit, unit)
    y = np.asarray(y, dtype=float)
    if angle:
        turn = factor("turn", unit)
        np.testing.assert_allclose((y - expected + turn / 2) % turn - turn / 2, 0.0,
                                   atol=1e-9 * turn, err_msg=name)
    else:
        np.testing.assert_allclose(y, expected, rtol=1e-12, atol=1e-12 * np.nanmax(
            np.abs(expected)), err_msg=f"{name} [{unit}]")


def labelled_lines(figure):
    """(name, unit, line) of every line labelled 'name [unit]'."""
    for ax in figure.axes:
        for line in ax.get_lines():
            match = LABEL.match(line.get_label())
            if match:
                yield match.group(1), match.group(2), line


def with_display(tmp_path, example: str, section: dict) -> mechloop.Model:
    data = yaml.safe_load((ROOT / "examples" / example).read_text())
    data["display"] = section
    path = tmp_path / "model.yaml"
    path.write_text(yaml.safe_dump(data, allow_unicode=True))
    return mechloop.load_model(path)


SECTIONS = [None, {"length": "mm", "force": "kN", "angular_velocity": "rpm"},
            {"angle": "deg", "inertia": "kg*cm^2", "moment": "kN*m"}]


@pytest.mark.parametrize("section", SECTIONS, ids=["no display", "mm-kN-rpm", "angle deg"])
def test_every_plot_kind_draws_the_table_values_in_its_printed_unit(section, tmp_path):
    example = "crank_slider_dynamics.yaml"
    model = (mechloop.load_model(ROOT / "examples" / example) if section is None
             else with_display(tmp_path, example, section))
    shown = resolve(model.display)
    display = plot_display(shown) or DEFAULT_DISPLAY
    dyn = mechloop.solve_dynamics(model)
    frame = apply_display(dyn.to_frame(), shown)
    res = dyn.kinematics
    units = {}
    figures = [curves.plot_parameters(dyn, ["a2", "da2", "dda2", "r3", "dr3", "ddr3"],
                                      display=display),
               curves.plot_parameters(dyn, ["M_bal", "RA", "RA_to_a2"], display=display),
               dynamics.plot_reduced(dyn, display=display),
               dynamics.plot_balancing(dyn, display=display)]
    for figure in figures:
        for name, unit, line in labelled_lines(figure):
            check_line(frame, name, unit, line.get_ydata(), angle=unit == "deg")
            units[name] = unit
        plt.close(figure)
    # the increment's axes: Δ from position 0, and the derivatives as the table
    figure = curves.plot_increment(dyn, "a2", 0, display=display)
    for ax, name in zip(figure.axes, ["a2", "da2", "dda2"], strict=True):
        label = LABEL.match(ax.get_ylabel())
        y = np.asarray(ax.get_lines()[0].get_ydata())
        if name == "a2":
            values, table_unit = table_column(frame, "a2")
            expected = (values - values[0]) * factor(table_unit, label.group(2))
            np.testing.assert_allclose(y, expected, atol=1e-9)
        else:
            check_line(frame, name, label.group(2), y)
    plt.close(figure)
    # reactions: the magnitude column of each joint, in the printed force unit
    figure = dynamics.plot_reactions(dyn, display=display)
    force = LABEL.match(figure.axes[0].get_ylabel()).group(2)
    for line in figure.axes[0].get_lines():
        check_line(frame, line.get_label().strip("|"), force, line.get_ydata())
    plt.close(figure)
    figure = dynamics.plot_hodograph(dyn, "A", display=display)
    x_unit = LABEL.match(figure.axes[0].get_xlabel()).group(2)
    line = next(li for li in figure.axes[0].get_lines() if li.get_label() == "RA")
    check_line(frame, "RA_x", x_unit, line.get_xdata())
    check_line(frame, "RA_y", x_unit, line.get_ydata())
    plt.close(figure)
    # the angle between two vectors and its rate: the table's a2 - a1 and da2 - da1
    figure = curves.plot_angle_between(dyn, 1, 2, display=display)
    lines = {n: (u, li) for n, u, li in labelled_lines(figure)}
    unit, line = lines["a2 − a1"]
    a1, a1_unit = table_column(frame, "a1")
    a2, _ = table_column(frame, "a2")
    turn = factor("turn", unit)
    difference = (a2 - a1) * factor(a1_unit, unit)
    np.testing.assert_allclose((line.get_ydata() - difference + turn / 2) % turn - turn / 2,
                               0.0, atol=1e-9 * turn)
    rate_unit, line = lines["d(a2 − a1)"]
    da1, da_unit = table_column(frame, "da1")
    da2, _ = table_column(frame, "da2")
    np.testing.assert_allclose(line.get_ydata(), (da2 - da1) * factor(da_unit, rate_unit),
                               rtol=1e-12)
    plt.close(figure)

    # the units printed: SI, angles in degrees, per radian, unless the section names one
    named = section or {}
    assert units["da2"] == named.get("angular_velocity", "rad/s")
    assert units["dda2"] == "rad/s^2"
    assert units["a2"] == "deg"
    per = named.get("angle", "rad")  # a per-angle unit follows a named angle, as the table
    assert units["dJ_red"] == f"{named.get('inertia', 'kg*m^2')}/{per}"
    assert units["M_bal"] == named.get("moment", "N*m")
    assert units["RA"] == named.get("force", "N")
    assert res.has_time


def test_machine_motion_speed_is_in_rad_per_second_by_default():
    dyn = mechloop.solve_dynamics(mechloop.load_model(ROOT / "examples/single_cylinder_engine"
                                                                 ".yaml"))
    figure = dynamics.plot_machine_motion(dyn)
    ax = figure.axes[0]
    assert ax.get_ylabel() == "ω [rad/s]"
    line = next(li for li in ax.get_lines() if li.get_gid() == "omega")
    np.testing.assert_array_equal(line.get_ydata(), dyn.cycle.motion.omega)
    assert ax.get_xlabel().endswith("[deg]")
    np.testing.assert_allclose(line.get_xdata(), np.degrees(dyn.cycle.q), rtol=1e-14)
    plt.close(figure)


@pytest.mark.parametrize(("example", "names", "units"), [
    ("log10_function_generator.yaml", ["da3", "dda3", "a3"], ["rad/rad", "rad/rad^2", "deg"]),
    ("roof_support.yaml", ["da3", "dr7", "ddr7"], ["rad/m", "m/m", "m/m^2"])])
def test_analogs_are_per_radian_or_metre_as_in_the_table(example, names, units):
    # no model time: derivatives are analogs with respect to argument 1 (an angle in the
    # function generator, a length in the roof support): dφ/dφ1 is a plain number per rad
    res = mechloop.solve(mechloop.load_model(ROOT / "examples" / example))
    assert not res.has_time
    frame = res.to_frame()
    figure = curves.plot_parameters(res, names)
    drawn = {name: (unit, line) for name, unit, line in labelled_lines(figure)}
    assert [drawn[n][0] for n in names] == units
    for name, (unit, line) in drawn.items():
        check_line(frame, name, unit, line.get_ydata(), angle=unit == "deg")
    plt.close(figure)


def test_four_bar_transmission_angle_is_the_law_of_cosines_at_every_position():
    # examples/four_bar.yaml: crank OA = 100, coupler AB = 350, rocker BC = 250, frame
    # OC = 300 mm.  With AC the diagonal, cos μ = (AB² + BC² − AC²) / (2·AB·BC) gives the
    # angle μ at B between BA and BC; the angle from the coupler vector (A→B) to the rocker
    # vector (B→C) is its exterior angle, ±(180° − μ), the same sign at every position.
    res = mechloop.solve(mechloop.load_model(ROOT / "examples/four_bar.yaml"))
    phi = res.arguments[1]
    ac2 = 100.0**2 + 300.0**2 - 2 * 100.0 * 300.0 * np.cos(phi)  # O at 0, C at (300, 0)
    mu = np.degrees(np.arccos((350.0**2 + 250.0**2 - ac2) / (2 * 350.0 * 250.0)))
    figure = curves.plot_angle_between(res, 2, 3)
    lines = {n: li for n, _, li in labelled_lines(figure)}
    y = np.asarray(lines["a3 − a2"].get_ydata(), dtype=float)
    sign = np.sign(y[0])
    np.testing.assert_allclose(y, sign * (180.0 - mu), atol=1e-9)
    assert np.all(np.abs(y) > 0) and np.all(np.abs(y) < 180)  # (−180°, 180°], one curve
    plt.close(figure)


def test_angle_crossing_180_degrees_plots_without_a_jump():
    # synthetic: a difference turning from 150° through 180° to 250° and back, with a break
    # (NaN) in the middle; wrapped to (−180°, 180°] it would jump by ~360°
    true = np.radians(np.concatenate([np.linspace(150, 250, 30), [np.nan],
                                      np.linspace(240, 160, 20)]))
    wrapped = curves.wrap_angle(true)
    assert np.nanmax(np.abs(np.diff(np.degrees(wrapped)))) > 300
    shown = np.degrees(curves.continuous_angle(wrapped, centred=True))
    steps = np.abs(np.diff(shown))
    true_steps = np.abs(np.diff(np.degrees(true)))
    ok = np.isfinite(steps)
    assert np.all(steps[ok] <= true_steps[ok] + 1e-9)
    assert np.isnan(shown[30])  # the break stays a gap
    # each stretch keeps the true values up to whole turns, centred in (−180°, 180°]:
    # 150…250 has its middle at 200°, so it is drawn as −210…−110
    np.testing.assert_allclose(shown[:30], np.degrees(true[:30]) - 360, atol=1e-9)
    np.testing.assert_allclose(shown[31:], np.degrees(true[31:]) - 360, atol=1e-9)
    # not centred: the branch of the first value (a solver's angle) is kept
    kept = np.degrees(curves.continuous_angle(wrapped))
    np.testing.assert_allclose(kept[:30], np.degrees(true[:30]), atol=1e-9)
