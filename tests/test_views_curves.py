"""The KDAM plots of parameters and dynamics draw exactly the solved numbers, in the units of
the display setting, and render for every bundled example without warnings.

The drawn artists' data are read back and compared with the results' arrays converted by
pint (or by the plain factors written out below), so a plot that shows a wrong column, a
wrong unit or a shifted position fails.
"""

from __future__ import annotations

import doctest
import functools
import math
import re
import warnings
from pathlib import Path

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_rgba
from matplotlib.lines import Line2D
from matplotlib.table import Table
from matplotlib.text import Annotation

import mechloop
from mechloop.model.formula import describe_structure
from mechloop.model.units import registry
from mechloop.views import curves, dynamics
from mechloop.views import display as display_module
from mechloop.views.display import Display
from mechloop.views.figure import ViewError, save_figure
from mechloop.views.formula import box_text, parametric_formula, plot_structure

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))


@functools.cache
def model(name: str) -> mechloop.Model:
    return mechloop.load_model(ROOT / "examples" / name)


@functools.cache
def kinematics(name: str) -> mechloop.Results:
    return mechloop.solve(model(name))


@functools.cache
def dynamic(name: str) -> mechloop.DynamicResults:
    return mechloop.solve_dynamics(model(name))


def lines(figure) -> dict[str, Line2D]:
    """Every labelled line of the figure by its label."""
    return {line.get_label(): line for ax in figure.axes for line in ax.get_lines()
            if not line.get_label().startswith("_")}


def pint_factor(si: str, shown: str) -> float:
    return float(registry().Quantity(1.0, si).to(shown).magnitude)


# ------------------------------------------------------------------ parameter dependencies


def test_parameter_curves_are_the_results_in_display_units():
    res = kinematics("crank_slider.yaml")
    fig = curves.plot_parameters(res, ["a2", "a1"], against="arg1")
    drawn = lines(fig)
    np.testing.assert_allclose(drawn["a2 [deg]"].get_ydata(), np.degrees(res.value("a2")),
                               rtol=1e-14)
    np.testing.assert_allclose(drawn["a1 [deg]"].get_ydata(), np.degrees(res.value("a1")),
                               rtol=1e-14)
    np.testing.assert_allclose(drawn["a2 [deg]"].get_xdata(), np.degrees(res.arguments[1]),
                               rtol=1e-14)

    mm = Display(length="mm")
    fig = curves.plot_parameters(res, ["r3", "dr3"], against="time", display=mm)
    drawn = lines(fig)
    np.testing.assert_allclose(drawn["r3 [mm]"].get_ydata(), 1000 * res.value("r3"))
    np.testing.assert_allclose(drawn["dr3 [mm/s]"].get_ydata(), 1000 * res.rate("r3"))
    np.testing.assert_array_equal(drawn["r3 [mm]"].get_xdata(), res.time)

    fig = curves.plot_parameters(res, "dda2", display=Display(angle="rad"))
    (line,) = lines(fig).values()
    assert line.get_label() == "dda2 [rad/s^2]"
    np.testing.assert_array_equal(line.get_ydata(), res.accel("a2"))
    np.testing.assert_array_equal(line.get_xdata(), np.arange(73))


def test_second_axis_appears_exactly_when_units_differ():
    res = kinematics("crank_slider.yaml")
    assert len(curves.plot_parameters(res, ["a1", "a2"]).axes) == 1
    assert len(curves.plot_parameters(res, ["r3", "r1", "r4"]).axes) == 1
    fig = curves.plot_parameters(res, ["a2", "r3", "a1"])
    assert len(fig.axes) == 2
    left, right = fig.axes
    assert {line.get_label() for line in left.get_lines()} == {"a2 [deg]", "a1 [deg]"}
    assert [line.get_label() for line in right.get_lines()] == ["r3 [m]"]
    assert len(curves.plot_parameters(res, ["da2", "dda2"]).axes) == 2


def test_more_than_six_curves_are_refused_naming_their_units():
    res = kinematics("four_bar.yaml")
    assert len(curves.plot_parameters(res, ["a1", "a2", "a3", "a6", "a7", "a5"]).axes) == 1
    with pytest.raises(ViewError, match=r"at most 6") as refused:
        curves.plot_parameters(res, ["a1", "a2", "a3", "a5", "a6", "a7", "r7"])
    assert "a7 [deg], r7 [m]" in str(refused.value)
    with pytest.raises(ViewError, match="no quantity 'a99'"):
        curves.plot_parameters(res, ["a99"])
    with pytest.raises(ViewError, match="solve_dynamics"):
        curves.plot_parameters(res, ["M_bal"])
    with pytest.raises(ViewError, match="unknown layout"):
        curves.plot_parameters(res, ["a2"], layout="grid")
    with pytest.raises(ViewError, match="cannot be drawn on given axes"):
        curves.plot_parameters(res, ["a2"], layout="panels",
                               ax=curves.axes_for(None)[1])


def _overlap(a, b) -> bool:
    """Whether two display-space boxes share an area (touching edges do not count)."""
    return a.x0 < b.x1 - 0.5 and b.x0 < a.x1 - 0.5 and a.y0 < b.y1 - 0.5 and b.y0 < a.y1 - 0.5


@pytest.fixture(scope="module")
def six_units():
    """r3, dr3, ddr3, a2, M_bal, RA of the engine: six curves of six units, drawn."""
    dyn = dynamic("crank_slider_dynamics.yaml")
    names = ["r3", "dr3", "ddr3", "a2", "M_bal", "RA"]
    figures = {layout: curves.plot_parameters(dyn, names[:count], layout=layout)
               for layout, count in (("auto", 3), ("panels", 3), ("axes", 6))}
    figures["auto6"] = curves.plot_parameters(dyn, names)
    for figure in figures.values():
        FigureCanvasAgg(figure).draw()  # the layout as saved to PNG
    return dyn, names, figures


def test_three_units_get_three_y_axes_each_labelled_and_coloured_like_its_curve(six_units):
    dyn, names, figures = six_units
    figure = figures["auto"]
    assert len(figure.axes) == 3  # one y-axis per unit, on one plot
    units = ["m", "m/s", "m/s^2"]
    renderer = figure.canvas.get_renderer()
    spines = []
    for k, (ax, name, unit) in enumerate(zip(figure.axes, names[:3], units, strict=True)):
        assert ax.get_ylabel() == f"{name} [{unit}]"
        (line,) = ax.get_lines()
        assert line.get_label() == f"{name} [{unit}]"
        assert ax.yaxis.label.get_color() == line.get_color() == f"C{k}"
        side = "left" if k == 0 else "right"
        assert ax.spines[side].get_edgecolor() == to_rgba(f"C{k}")
        spines.append(ax.spines[side].get_window_extent(renderer).x0)
    assert spines[0] < spines[1] < spines[2]  # the third axis is pushed out to the right
    np.testing.assert_array_equal(lines(figure)["ddr3 [m/s^2]"].get_ydata(),
                                  dyn.kinematics.accel("r3"))


def boxes_of(figure) -> list[tuple[float, ...]]:
    """The distinct plot boxes (figure fractions) of a figure's axes, top first."""
    boxes = {tuple(np.round(ax.get_position().bounds, 9)) for ax in figure.axes}
    return sorted(boxes, key=lambda box: -box[1])


@pytest.mark.parametrize("layout, count, panels", [("panels", 3, 3), ("axes", 6, 1),
                                                   ("auto6", 6, 6)])
def test_panels_stack_one_unit_each_and_axes_can_be_forced(six_units, layout, count,
                                                           panels):
    """Six units go on six stacked panels by default; 'axes' forces six y-axes on one
    plot; 'panels' stacks even three units.  Every y-axis names its curve and unit."""
    _, names, figures = six_units
    figure = figures[layout]
    assert len(figure.axes) == count
    assert len(boxes_of(figure)) == panels
    labelled = [ax.get_ylabel() for ax in figure.axes]
    assert all(re.fullmatch(r".+ \[.+\]", text) for text in labelled), labelled
    assert [text.split(" [")[0] for text in labelled] == names[:count]
    if panels > 1:  # one above the other, sharing x; the x label under the bottom one
        assert [ax.get_position().y0 for ax in figure.axes] == \
            sorted((ax.get_position().y0 for ax in figure.axes), reverse=True)
        assert figure.axes[0].get_shared_x_axes().joined(figure.axes[0], figure.axes[-1])
        assert figure.axes[-1].get_xlabel() == "position"


@pytest.mark.parametrize("layout", ["auto", "panels", "axes", "auto6"])
def test_the_legend_covers_no_curve_and_no_axis_text(six_units, layout):
    """The legend lies outside every plot box and clear of the tick labels and the axis
    labels, all measured on the rendered figure."""
    figure = six_units[2][layout]
    renderer = figure.canvas.get_renderer()
    legends = [ax.get_legend() for ax in figure.axes if ax.get_legend() is not None]
    assert len(legends) == 1
    legend = legends[0].get_window_extent(renderer)
    assert len(legends[0].get_texts()) == (3 if layout in ("auto", "panels") else 6)
    assert figure.bbox.contains(legend.x0, legend.y0) and figure.bbox.contains(legend.x1,
                                                                                legend.y1)
    for ax in figure.axes:
        assert not _overlap(legend, ax.get_window_extent(renderer))
        texts = [ax.xaxis.label, ax.yaxis.label, *ax.get_xticklabels(),
                 *ax.get_yticklabels()]
        for text in texts:
            if text.get_visible() and text.get_text():
                assert not _overlap(legend, text.get_window_extent(renderer)), \
                    text.get_text()


def test_the_command_line_draws_six_units_and_forces_panels(tmp_path):
    from typer.testing import CliRunner

    from mechloop.cli import app

    path = str(ROOT / "examples" / "crank_slider.yaml")
    ok = CliRunner().invoke(app, ["plot", path, "parameters", "-n", "r3,dr3,ddr3,a2",
                                  "-o", str(tmp_path / "p.png")])
    assert ok.exit_code == 0, ok.output
    ok = CliRunner().invoke(app, ["plot", path, "parameters", "-n", "r3,dr3", "--panels",
                                  "-o", str(tmp_path / "q.png")])
    assert ok.exit_code == 0, ok.output
    refused = CliRunner().invoke(app, ["plot", path, "parameters", "-n",
                                       "r3,dr3,ddr3,a2,da2,dda2,r1", "-o",
                                       str(tmp_path / "r.png")])
    assert refused.exit_code == 2
    assert "ddr3 [m/s^2]" in refused.output and "r1 [m]" in refused.output


def test_dynamic_columns_are_plotted_in_display_units():
    dyn = dynamic("crank_slider_dynamics.yaml")
    frame = dyn.to_frame()
    kgf = Display(force="kgf", moment="kgf*m")
    drawn = lines(curves.plot_parameters(dyn, ["M_bal", "M_bal_vp", "RA", "RB"],
                                         display=kgf))
    np.testing.assert_allclose(drawn["RA [kgf]"].get_ydata(),
                               np.abs(dyn.forces.reactions["A"].force) / 9.80665, rtol=1e-12)
    np.testing.assert_allclose(drawn["M_bal [kgf*m]"].get_ydata(),
                               dyn.forces.balancing[1] / 9.80665, rtol=1e-12)
    drawn = lines(curves.plot_parameters(dyn, ["RA_to_a2", "a2"]))
    # the table's direction is wrapped to (−180°, 180°]; the plot's is the same angle made
    # continuous (it passes 180° here instead of jumping to −180°)
    plotted = np.asarray(drawn["RA_to_a2 [deg]"].get_ydata())
    table = frame["RA_to_a2 [deg]"].to_numpy()
    np.testing.assert_allclose((plotted - table + 180) % 360 - 180, 0.0, atol=1e-9)
    assert np.abs(np.diff(table)).max() > 300 and np.abs(np.diff(plotted)).max() < 30
    drawn = lines(dynamics.plot_reactions(dyn, ["A", "S"]))
    np.testing.assert_array_equal(drawn["|RS|"].get_ydata(),
                                  np.abs(dyn.forces.reactions["S"].force))
    with pytest.raises(ViewError, match="no joint 'Q'"):
        dynamics.plot_reactions(dyn, ["Q"])


# ------------------------------------------------------------------------- combinations


def test_combinations_match_numpy_on_the_displayed_values():
    res = kinematics("crank_slider.yaml")
    r3, r1, a1, a2 = (res.value(n) for n in ("r3", "r1", "a1", "a2"))
    values, label = curves.combine(res, "r3", "r1", "sum")
    np.testing.assert_allclose(values, r3 + r1)
    assert label == "r3 + r1 [m]"
    values, label = curves.combine(res, "a2", "a1", "difference")
    np.testing.assert_allclose(values, np.degrees(a2) - np.degrees(a1))
    assert label.endswith("[deg]")
    values, label = curves.combine(res, "r3", "a2", "product")
    np.testing.assert_allclose(values, r3 * np.degrees(a2))
    assert sorted(label.split("[")[1].rstrip("]").split("*")) == ["deg", "m"]
    values, label = curves.combine(res, "dr3", "da1", "ratio")
    np.testing.assert_allclose(values, res.rate("r3") / res.rate("a1"))
    assert label == "dr3 / da1 [m/rad]"  # rates are in rad/s by default, as in the tables
    values, label = curves.combine(res, "a2", "a1", "ratio")
    with np.errstate(divide="ignore", invalid="ignore"):
        np.testing.assert_allclose(values, a2 / a1)
    assert label == "a2 / a1"
    values, label = curves.combine(res, "r3", 2, "power", display=Display(length="mm"))
    np.testing.assert_allclose(values, (1000 * r3) ** 2)
    assert label == "r3 ^ 2 [mm^2]"
    values, _ = curves.combine(res, "r3", "r1", "sum", display=Display(length="mm"))
    np.testing.assert_allclose(values, 1000 * (r3 + r1))
    with pytest.raises(ViewError, match="units do not match"):
        curves.combine(res, "r3", "a2", "sum")
    with pytest.raises(ViewError, match="varying power"):
        curves.combine(res, "r3", "a2", "power")
    with pytest.raises(ViewError, match="unknown combination"):
        curves.combine(res, "r3", "a2", "mean")
    (line,) = curves.plot_combination(res, "r3", "r1", "difference").axes[0].get_lines()
    np.testing.assert_allclose(line.get_ydata(), r3 - r1)


# ----------------------------------------------------------------- angle between vectors


def test_wrap_angle_folds_into_the_half_open_interval():
    angles = np.array([np.pi, -np.pi, 3 * np.pi, -3 * np.pi, 0.0, 2 * np.pi, 1.5 * np.pi])
    np.testing.assert_allclose(curves.wrap_angle(angles),
                               [np.pi, np.pi, np.pi, np.pi, 0.0, 0.0, -0.5 * np.pi], atol=1e-15)


def test_angle_between_is_continuous_across_180_degrees():
    # crank_slider: a4 = 90 deg fixed, a1 = 0..360 deg over 72 positions, so a1 - a4 runs
    # from -90 to 270 deg: continuous through +180 deg (no jump to -175 deg), and the middle
    # of its range (90 deg) lies in (-180, 180], so that branch is kept
    res = kinematics("crank_slider.yaml")
    angle, rate = curves.angle_between(res, 4, 1)
    expected = np.radians(5.0 * np.arange(73) - 90.0)
    np.testing.assert_allclose(angle, expected, atol=1e-12)
    np.testing.assert_array_equal(rate, res.rate("a1") - res.rate("a4"))
    back, _ = curves.angle_between(res, "a1", "a4")  # 90 - a1: 90 down to -270 deg
    np.testing.assert_allclose(back, -expected, atol=1e-12)

    fig = curves.plot_angle_between(res, 4, 1)
    line = lines(fig)["a1 − a4 [deg]"]
    y = np.asarray(line.get_ydata(), dtype=float)
    assert np.isfinite(y).all()  # one unbroken line
    np.testing.assert_allclose(y, 5.0 * np.arange(73) - 90.0, atol=1e-10)
    with pytest.raises(ViewError, match="no vector 9"):
        curves.angle_between(res, 1, 9)


# --------------------------------------------------------------------------- increments


def test_increment_is_zero_at_its_position_and_keeps_the_derivatives():
    res = kinematics("four_bar.yaml")
    k = 20
    delta, rate, accel = curves.increment(res, "a3", k)
    assert delta[k] == 0.0
    np.testing.assert_allclose(delta, res.value("a3") - res.value("a3")[k], atol=1e-15)
    np.testing.assert_array_equal(rate, res.rate("a3"))
    np.testing.assert_array_equal(accel, res.accel("a3"))

    fig = curves.plot_increment(res, "a3", k)
    assert len(fig.axes) == 3
    top, middle, bottom = (ax.get_lines()[0].get_ydata() for ax in fig.axes)
    np.testing.assert_allclose(top, np.degrees(delta), atol=1e-12)
    np.testing.assert_array_equal(middle, rate)
    np.testing.assert_array_equal(bottom, accel)
    assert [ax.get_ylabel() for ax in fig.axes] == ["Δa3 [deg]", "da3 [rad/s]",
                                                   "dda3 [rad/s^2]"]
    with pytest.raises(ViewError, match="position 73"):
        curves.increment(res, "a3", 73)
    with pytest.raises(ViewError, match="not a vector parameter"):
        curves.increment(res, "da3", 0)


# -------------------------------------------------------------------------------- dynamics


def test_hodograph_points_are_the_reactions():
    dyn = dynamic("crank_slider_dynamics.yaml")
    for joint, reaction in dyn.forces.reactions.items():
        force = reaction.force
        line = lines(dynamics.plot_hodograph(dyn, joint))[f"R{joint}"]
        np.testing.assert_array_equal(line.get_xdata(), force.real)
        np.testing.assert_array_equal(line.get_ydata(), force.imag)
        line = lines(dynamics.plot_hodograph(dyn, joint, polar=True))[f"R{joint}"]
        theta, radius = np.asarray(line.get_xdata()), np.asarray(line.get_ydata())
        np.testing.assert_array_equal(radius, np.abs(force))
        np.testing.assert_allclose(radius * np.exp(1j * theta), force,
                                   atol=1e-12 * np.abs(force).max())
    kn = lines(dynamics.plot_hodograph(dyn, "A", display=Display(force="kN")))["RA"]
    np.testing.assert_allclose(kn.get_xdata(), dyn.forces.reactions["A"].force.real / 1000)


def test_machine_motion_with_flywheel_stays_within_half_delta_of_the_mean():
    dyn = dynamic("single_cylinder_engine.yaml")
    cycle = dyn.cycle
    fig = dynamics.plot_machine_motion(dyn, display=Display(angular_velocity="rpm"))
    by_gid = {line.get_gid(): line for line in fig.axes[0].get_lines()}
    mean = 3000.0  # rpm: the model's time: {rpm: 3000}
    with_flywheel = np.asarray(by_gid["omega_fw"].get_ydata())
    without = np.asarray(by_gid["omega"].get_ydata())
    delta = 0.0125  # machine: {delta: 0.0125}
    assert np.all(np.abs(with_flywheel - mean) <= delta / 2 * mean * (1 + 1e-9))
    assert math.isclose(with_flywheel.max() - with_flywheel.min(), delta * mean, rel_tol=1e-6)
    np.testing.assert_allclose(without, cycle.motion.omega * 60 / (2 * np.pi))
    np.testing.assert_allclose(by_gid["omega"].get_xdata(), np.degrees(cycle.q))
    legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert any(f"J = {Display().format(cycle.flywheel)} kg*m^2" in t for t in legend)
    assert any("δ = 0.0125" in t for t in legend)
    with pytest.raises(ViewError, match="no machine motion"):
        dynamics.plot_machine_motion(dynamic("crank_slider_dynamics.yaml"))


def test_summary_table_shows_the_summary_in_display_units():
    dyn = dynamic("crank_slider_friction.yaml")
    kw = Display(power="kW", digits=3)
    fig = dynamics.plot_summary(dyn, display=kw)
    tables = [child for child in fig.axes[0].get_children() if isinstance(child, Table)]
    cells = {text for table in tables for cell in table.get_celld().values()
             for text in [cell.get_text().get_text()]}
    row = next(r for r in dyn.summary.rows if r.name == "M_bal")
    assert f"{row.max_power / 1000:.3g}" in cells
    assert "N max [kW]" in cells
    assert f"{dyn.summary.efficiency:.3g}" in cells


# --------------------------------------------------------------------------------- display


def test_display_conversions_agree_with_pint():
    d = Display(force="kgf", power="hp", angular_velocity="rpm", length="mm",
                moment="kN*m", inertia="kg*cm^2")
    cases = [("force", "N", "kgf"), ("power", "W", "hp"), ("angular_velocity", "rad/s", "rpm"),
             ("length", "m", "mm"), ("velocity", "m/s", "mm/s"), ("moment", "N*m", "kN*m"),
             ("inertia", "kg*m^2", "kg*cm^2"), ("angular_acceleration", "rad/s^2", "rad/s^2"),
             ("length/angle", "m/rad", "mm/rad")]
    values = np.array([0.5, 1.0, 123.0])
    for kind, si, shown in cases:
        np.testing.assert_allclose(d.convert(values, kind), values * pint_factor(si, shown),
                                   rtol=1e-14, err_msg=kind)
    assert d.convert(9.80665, "force") == pytest.approx(1.0, rel=1e-12)
    assert d.convert(2 * np.pi, "angular_velocity") == pytest.approx(60.0, rel=1e-12)
    assert d.convert(745.6998715822702, "power") == pytest.approx(1.0, rel=1e-9)
    assert (d.label("force"), d.label("power"), d.label("angular_velocity"),
            d.label("acceleration")) == ("kgf", "hp", "rpm", "mm/s^2")
    assert Display(digits=3).format(math.pi) == "3.14"


def test_display_docstring_examples_run():
    assert doctest.testmod(display_module, raise_on_error=True).attempted > 0


def test_display_refuses_units_it_cannot_use():
    with pytest.raises(ViewError, match="unknown display unit length='parsec_x'"):
        Display(length="parsec_x")
    with pytest.raises(ViewError, match="force='m' is not a unit of force") as err:
        Display(force="m")
    assert "kgf" in str(err.value)
    with pytest.raises(ViewError, match="angle='m'"):
        Display(angle="m")
    with pytest.raises(ViewError, match="unknown kind of quantity 'speed'") as err:
        Display().convert(1.0, "speed")
    assert "angular_velocity" in str(err.value)


# ---------------------------------------------------------------------- every example


def _kinematic_figures(res: mechloop.Results):
    varying = res.varying()
    first, last = varying[0], varying[-1]
    same = [n for n in varying[1:] if n[0] == first[0]][:2]
    against = "time" if res.has_time else "arg1"
    vectors = res.model.contours[0].vectors
    yield curves.plot_parameters(res, [first, f"d{first}", f"dd{first}", *same],
                                 against=against)  # three units: three y-axes
    yield curves.plot_combination(res, first, last, "ratio")
    yield curves.plot_angle_between(res, vectors[0], vectors[1], against=against)
    whole = np.flatnonzero(~res.broken)  # the reference must assemble (a break is refused)
    yield curves.plot_increment(res, last, int(whole[whole.size // 2]),
                                display=Display(length="mm", angle="rad"))
    yield plot_structure(res.model)


def _dynamic_figures(dyn: mechloop.DynamicResults):
    joint = next(iter(dyn.forces.reactions))
    display = Display(force="kN", power="kW", angular_velocity="rpm")
    if dyn.reduced is not None:
        yield dynamics.plot_reduced(dyn)
    yield dynamics.plot_balancing(dyn)
    yield dynamics.plot_reactions(dyn, display=display)
    yield dynamics.plot_hodograph(dyn, joint)
    yield dynamics.plot_hodograph(dyn, joint, polar=True)
    yield dynamics.plot_summary(dyn, display=display)
    if dyn.cycle is not None:
        yield dynamics.plot_machine_motion(dyn, display=display)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_view_renders_for_every_example_without_warnings(path, tmp_path):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        m = mechloop.load_model(path)
        figures = list(_kinematic_figures(mechloop.solve(m)))
        if m.bodies:
            figures += list(_dynamic_figures(mechloop.solve_dynamics(m)))
        # every figure drawn once, the three formats taken in turn (each format's writer
        # still meets many kinds of figure per example, in a third of the time)
        for i, figure in enumerate(figures):
            suffix = (".png", ".svg", ".pdf")[i % 3]
            target = save_figure(figure, tmp_path / f"view{i}{suffix}", dpi=40)
            assert target.stat().st_size > 1000


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_structure_drawing_holds_every_contour_and_link(path):
    m = mechloop.load_model(path)
    fig = plot_structure(m)
    texts = [t.get_text() for t in fig.axes[0].texts]
    structure = mechloop.solve(m).structure
    for info in structure.contours:
        assert box_text(m, info) in texts
        drawn = " ".join(box_text(m, info).replace("\u00a0", " ").split())
        assert " ".join(parametric_formula(m, info).split()) in drawn
        assert f"· {info.module}, V=" in drawn
        assert parametric_formula(m, info) in describe_structure(m)  # the printed formula
    arrows = [t for t in fig.axes[0].texts if isinstance(t, Annotation)]
    assert len(arrows) == sum(len(info.needs) for info in structure.contours)
