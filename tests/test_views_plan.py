"""Position plans, "photo" overlays, trajectories and "cinema" animations draw the mechanism
where the solver puts it.

The checks read what was drawn (the arrows' end points, the labels' anchors, the line data
of a trajectory, the frames of a GIF / MP4 / HTML page) and compare it with closed forms of
the slider-crank (crank pin ``r1 (cos φ, sin φ)``, slider pin ``(x_B, -e)`` with
``x_B = r1 cos φ + sqrt(r2² - (r1 sin φ + e)²)``), with the geometry of the model files
(fixed points), or with ``Results.point`` / ``Placement`` (coupler points, centres of
mass).  Every bundled example renders every view to PNG, SVG and PDF with warnings turned
into errors.
"""

from __future__ import annotations

import base64
import io
import math
import re
import warnings
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.markers import MarkerStyle
from matplotlib.patches import Polygon
from matplotlib.text import Annotation
from PIL import Image
from pydantic import TypeAdapter

import mechloop
from mechloop.dynamics.points import Placement
from mechloop.model.dynamic import HeadPoint, PointOn, VectorPoint
from mechloop.views.animation import _Stage, animate, frame_interval, loop_frames, same_pose
from mechloop.views.figure import ViewError, save_figure
from mechloop.views.labels import label_box
from mechloop.views.plan import (
    draw_position,
    plan_scene,
    plot_overlay,
    plot_plan,
    plot_trajectories,
)

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.yaml"))

# the slider-crank of examples/crank_slider.yaml (m, deg): crank, rod, offset e
R1, R2, E = 0.05, 0.2, 0.01
TOL = 1e-12  # m: the plan draws the solver's numbers, only rounding may differ

#: A slider-crank whose rod (55 mm) cannot reach the guide (offset 30 mm) when the crank
#: points up: the chain breaks around 90 deg (positions 1-5 of 0..12).
SHORT_ROD = {
    "name": "slider-crank with a short rod",
    "positions": 12,
    "time": {"rpm": 3000},
    "arguments": {1: {"table": {0: 0, 12: 360}}},
    "vectors": {1: {"r": 0.05, "a": {"argument": 1}}, 2: {"r": 0.055, "a": "function"},
                3: {"r": "function", "a": 180}, 4: {"r": 0.03, "a": 90}},
    "contours": [{"vectors": [1, 2, 3, 4]}],
}


def load(name: str) -> mechloop.Model:
    return mechloop.load_model(ROOT / "examples" / name)


def solved(path: Path):
    """Dynamic results for a model with bodies, kinematic results otherwise."""
    model = mechloop.load_model(path)
    return mechloop.solve_dynamics(model) if model.bodies else mechloop.solve(model)


def drawn(figure, gid: str):
    """The one artist of the figure's first axes with this gid."""
    found = [a for a in figure.axes[0].get_children() if a.get_gid() == gid]
    assert len(found) == 1, f"{len(found)} artists with gid {gid!r}"
    return found[0]


def gids(figure) -> set[str]:
    return {a.get_gid() for a in figure.axes[0].get_children() if a.get_gid()}


def arrow_ends(figure, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(tail, head) of the arrow of vector n, as drawn."""
    arrow = drawn(figure, f"vector {n}")
    assert isinstance(arrow, Annotation)
    return np.asarray(arrow.xyann, float), np.asarray(arrow.xy, float)


def slider_crank_pins(phi: float) -> tuple[np.ndarray, np.ndarray]:
    """Crank pin A and slider pin B (m) of the offset slider-crank at crank angle phi."""
    x_b = R1 * math.cos(phi) + math.sqrt(R2**2 - (R1 * math.sin(phi) + E) ** 2)
    return np.array([R1 * math.cos(phi), R1 * math.sin(phi)]), np.array([x_b, -E])


# ------------------------------------------------------------------------------ the plan


@pytest.mark.parametrize("position", [0, 9, 30, 50])
def test_plan_draws_crank_and_slider_pins_where_the_closed_form_puts_them(position):
    results = mechloop.solve(load("crank_slider.yaml"))
    figure = plot_plan(results, position)
    pin_a, pin_b = slider_crank_pins(math.radians(5.0 * position))  # 360 deg over 72
    tail1, head1 = arrow_ends(figure, 1)
    tail2, head2 = arrow_ends(figure, 2)
    tail3, head3 = arrow_ends(figure, 3)
    np.testing.assert_allclose(tail1, [0, 0], atol=TOL)
    np.testing.assert_allclose(head1, pin_a, atol=TOL)
    np.testing.assert_allclose(tail2, pin_a, atol=TOL)
    np.testing.assert_allclose(head2, pin_b, atol=TOL)
    np.testing.assert_allclose(tail3, pin_b, atol=TOL)
    np.testing.assert_allclose(head3, [0, -E], atol=TOL)  # the guide ends below O


def test_plan_is_drawn_in_the_asked_length_unit():
    results = mechloop.solve(load("crank_slider.yaml"))
    figure = plot_plan(results, 9, length_unit="mm")
    pin_a, pin_b = slider_crank_pins(math.radians(45.0))
    np.testing.assert_allclose(arrow_ends(figure, 2)[0], 1000 * pin_a, atol=1e-9)
    np.testing.assert_allclose(arrow_ends(figure, 2)[1], 1000 * pin_b, atol=1e-9)
    assert figure.axes[0].get_xlabel() == "x [mm]"


@pytest.mark.parametrize("name", ["crank_slider.yaml", "four_bar.yaml", "six_bar.yaml"])
def test_number_labels_sit_at_the_vector_midpoints(name):
    results = mechloop.solve(load(name))
    placement = Placement(results)
    figure = plot_plan(results, 20)
    to_unit = 1000.0 if results.model.units.length == "mm" else 1.0
    for n in results.model.vectors:
        label = drawn(figure, f"number {n}")
        assert label.get_text() == str(n)
        middle = (placement.tail(n).z[20] + placement.head(n).z[20]) / 2 * to_unit
        np.testing.assert_allclose(label.xy, [middle.real, middle.imag], atol=1e-9)
        tail, head = arrow_ends(figure, n)
        np.testing.assert_allclose(label.xy, (tail + head) / 2, atol=1e-9)


def test_functions_are_marked_with_circles_and_arguments_with_triangles():
    results = mechloop.solve(load("crank_slider.yaml"))
    figure = plot_plan(results, 9)
    marks = {g for g in gids(figure) if g.startswith(("function", "argument"))}
    assert marks == {"argument a1", "function a2", "function r3"}
    assert drawn(figure, "function a2").get_marker() == "o"
    assert drawn(figure, "argument a1").get_marker() != "o"
    # angle marks at 1/4 of the vector from its tail, length marks at 3/4
    tail2, head2 = arrow_ends(figure, 2)
    np.testing.assert_allclose(np.ravel(drawn(figure, "function a2").get_xydata()),
                               tail2 + 0.25 * (head2 - tail2), atol=1e-12)
    tail3, head3 = arrow_ends(figure, 3)
    np.testing.assert_allclose(np.ravel(drawn(figure, "function r3").get_xydata()),
                               tail3 + 0.75 * (head3 - tail3), atol=1e-12)
    legend = [t.get_text() for t in figure.axes[0].get_legend().get_texts()]
    assert any(t.startswith("function") for t in legend)
    assert any(t.startswith("argument") for t in legend)


def marker_vertex_angles(line) -> np.ndarray:
    """Directions (deg) from a marker's centre to its polygon's vertices, as drawn."""
    style = MarkerStyle(line.get_marker())
    vertices = style.get_transform().transform(style.get_path().vertices)
    return np.degrees(np.arctan2(vertices[:, 1], vertices[:, 0]))


@pytest.mark.parametrize("position", [0, 7, 20, 45])
def test_the_argument_triangle_points_along_its_vector(position):
    """The crank's angle a1 is the argument: its triangle has a vertex pointing in the
    crank's direction (5° per position), not across it."""
    figure = plot_plan(mechloop.solve(load("crank_slider.yaml")), position)
    angles = marker_vertex_angles(drawn(figure, "argument a1"))
    miss = np.abs((angles - 5.0 * position + 180.0) % 360.0 - 180.0)
    assert miss.min() < 1e-9, angles
    # and in the legend: pointing right, like a vector along +x
    (legend,) = [h for h in figure.axes[0].get_legend().legend_handles
                 if h.get_label().startswith("argument")]
    assert np.abs((marker_vertex_angles(legend) + 180.0) % 360.0 - 180.0).min() < 1e-9


@pytest.mark.parametrize("position", [0, 9, 36])
def test_labels_around_the_ground_pivot_overlap_neither_each_other_nor_other_links(
        position):
    """The engine's plan: at the crank's pivot O sit the ground, the joint O, the offset
    vector 4 and the crank 1 with S1; every label is clear of every other label, of the
    markers, and of every link but its own vector (measured on the rendered figure)."""
    figure = plot_plan(mechloop.solve_dynamics(load("crank_slider_dynamics.yaml")),
                       position)
    boxes = rendered_label_boxes(figure)
    assert {"joint label O", "number 1", "number 4", "center label S1"} <= set(boxes)
    assert not overlapping(boxes)
    ax = figure.axes[0]
    to_px = ax.transData.transform
    for n in range(1, 5):
        tail, head = arrow_ends(figure, n)
        points = to_px(tail + np.linspace(0.0, 1.0, 400)[:, None] * (head - tail))
        for gid, box in boxes.items():
            if gid == f"number {n}":
                continue
            inside = ((points[:, 0] > box[0] + 1) & (points[:, 0] < box[2] - 1)
                      & (points[:, 1] > box[1] + 1) & (points[:, 1] < box[3] - 1))
            assert not inside.any(), f"{gid} covers vector {n}"
    renderer = figure.canvas.get_renderer()
    for gid in ("joint O", "joint A", "center S1", "function a2", "argument a1"):
        mark = drawn(figure, gid).get_window_extent(renderer)
        for label, box in boxes.items():
            assert (min(box[2], mark.x1) - max(box[0], mark.x0) <= 1
                    or min(box[3], mark.y1) - max(box[1], mark.y0) <= 1), (label, gid)


def ground_apexes(figure) -> list[tuple[float, float]]:
    return sorted(tuple(np.round(p.get_xy()[0], 6)) for p in figure.axes[0].patches
                  if isinstance(p, Polygon) and p.get_gid() == "ground")


def test_the_ground_is_hatched_at_the_fixed_points():
    four_bar = plot_plan(mechloop.solve(load("four_bar.yaml")), 5)
    assert ground_apexes(four_bar) == [(0.0, 0.0), (300.0, 0.0)]  # O and C (mm)
    six_bar = plot_plan(mechloop.solve(load("six_bar.yaml")), 5)
    # F = C - r8 (cos 150°, sin 150°): the tail of the frame vector 8 (mm)
    f = (300.0 + 400.0 * math.cos(math.radians(30.0)), -400.0 * math.sin(math.radians(30.0)))
    assert ground_apexes(six_bar) == sorted([(0.0, 0.0), (300.0, 0.0),
                                             (round(f[0], 6), round(f[1], 6))])
    assert "ground hatch" in gids(six_bar)


def test_dynamic_plan_marks_centres_of_mass_and_names_the_joints():
    results = mechloop.solve_dynamics(load("crank_slider_dynamics.yaml"))
    figure = plot_plan(results, 9)
    pin_a, pin_b = slider_crank_pins(math.radians(45.0))
    # body 2's centre is 0.3 of the rod from A; body 1's at the middle of the crank
    np.testing.assert_allclose(np.ravel(drawn(figure, "center S2").get_xydata()),
                               pin_a + 0.3 * (pin_b - pin_a), atol=TOL)
    np.testing.assert_allclose(np.ravel(drawn(figure, "center S1").get_xydata()),
                               0.5 * pin_a, atol=TOL)
    np.testing.assert_allclose(np.ravel(drawn(figure, "joint A").get_xydata()), pin_a,
                               atol=TOL)
    np.testing.assert_allclose(np.ravel(drawn(figure, "joint B").get_xydata()), pin_b,
                               atol=TOL)
    labels = {drawn(figure, f"joint label {j}").get_text() for j in "OABS"}
    assert labels == {"O", "A", "B", "S"}


def test_default_limits_are_shared_by_every_position_and_the_scale_is_equal():
    results = mechloop.solve(load("crank_slider.yaml"))
    first, later = plot_plan(results, 0).axes[0], plot_plan(results, 30).axes[0]
    assert first.get_xlim() == later.get_xlim() and first.get_ylim() == later.get_ylim()
    assert first.get_aspect() == 1.0
    tight = plot_plan(results, 36, limits="auto").axes[0]  # crank pin at the far left
    assert tight.get_xlim()[1] < first.get_xlim()[1]
    fixed = plot_plan(results, 0, limits=(-0.1, 0.3, -0.1, 0.1)).axes[0]
    assert fixed.get_xlim() == (-0.1, 0.3) and fixed.get_ylim() == (-0.1, 0.1)


def test_a_wide_mechanism_spans_the_figure_with_its_legend_below_and_a_tall_one_beside():
    """The slider-crank (wider than tall): the drawing takes the figure's width, the legend
    in columns under the x-axis label clear of the axes and their labels, and the figure's
    height fits the drawing (little empty space); a box twice as tall as wide keeps the
    legend at the right."""
    results = mechloop.solve(load("crank_slider.yaml"))
    figure = plot_plan(results, 9)
    FigureCanvasAgg(figure).draw()
    renderer = figure.canvas.get_renderer()
    ax = figure.axes[0]
    box, legend = ax.get_window_extent(renderer), ax.get_legend().get_window_extent(renderer)
    labels = ax.xaxis.get_tightbbox(renderer)
    assert box.width >= 0.85 * figure.bbox.width
    assert legend.y1 <= labels.y0 and labels.y1 <= box.y1 and legend.y0 >= figure.bbox.y0
    assert figure.bbox.x0 <= legend.x0 and legend.x1 <= figure.bbox.x1
    assert ax.get_legend()._ncols == 3
    assert figure.get_tightbbox(renderer).height >= 0.9 * figure.get_size_inches()[1]
    tall = plot_plan(results, 9, limits=(-0.1, 0.1, -0.2, 0.2))
    FigureCanvasAgg(tall).draw()
    renderer = tall.canvas.get_renderer()
    ax = tall.axes[0]
    assert ax.get_legend().get_window_extent(renderer).x0 >= \
        ax.get_window_extent(renderer).x1


def test_grid_and_axes_switch_on_and_off():
    results = mechloop.solve(load("crank_slider.yaml"))
    plain = plot_plan(results, 3, grid=False, axes=False).axes[0]
    assert not any(line.get_visible() for line in plain.get_xgridlines())
    assert plain.get_xlabel() == "" and not plain.spines["left"].get_visible()
    gridded = plot_plan(results, 3, grid=True).axes[0]
    assert all(line.get_visible() for line in gridded.get_xgridlines())


@pytest.mark.parametrize("call, match", [
    (lambda r: plot_plan(r, 73), "outside"),
    (lambda r: plot_plan(r, -1), "outside"),
    (lambda r: plot_plan(r, 1.5), "not a position"),
    (lambda r: plot_plan(r, 0, length_unit="kg"), "not a length"),
    (lambda r: plot_plan(r, 0, limits=(1, 0, 0, 1)), "do not enclose"),
    (lambda r: plot_trajectories(r, [{"head": 9}]), "does not exist"),
    (lambda r: plot_trajectories(r, ["S2"]), "needs dynamic results"),
    (lambda r: plot_trajectories(r, [{"bogus": 1}]), "is not a point"),
])
def test_impossible_requests_raise_view_errors(call, match):
    results = mechloop.solve(load("crank_slider.yaml"))
    with pytest.raises(ViewError, match=match):
        call(results)


# ------------------------------------------------------------------------- chain breaks


def test_a_chain_break_position_says_so_and_draws_nothing_broken(tmp_path):
    results = mechloop.solve(mechloop.Model.from_dict(SHORT_ROD))
    assert results.broken[3] and not results.broken[8]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        figure = plot_plan(results, 3)
        for suffix in (".png", ".svg", ".pdf"):
            save_figure(figure, tmp_path / f"break{suffix}")
        overlay = plot_overlay(results)
        save_figure(overlay, tmp_path / "overlay.png")
        save_figure(plot_trajectories(results, [{"head": 2}], position=3),
                    tmp_path / "paths.png")
        animate(results, tmp_path / "break.gif", dpi=40)
    note = drawn(figure, "chain break").get_text()
    assert note.startswith("chain break at position 3")
    assert "contour 1 (Pl3)" in note
    assert not {g for g in gids(figure) if g.startswith("vector")}  # nothing unknown
    assert "chain break at positions 1-5" in overlay.axes[0].get_title()
    whole = plot_plan(results, 8)
    assert "chain break" not in gids(whole)
    assert {f"vector {n}" for n in range(1, 5)} <= gids(whole)


# ----------------------------------------------------------------- every example, every view


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_renders_every_view_without_warnings(path, tmp_path):
    results = solved(path)
    model = mechloop.load_model(path)
    points = [{"head": n} for n in model.vectors]
    if model.bodies:
        points += [f"S{b}" for b in results.centers]
    middle = model.positions // 2
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        views = {"plan": plot_plan(results, middle, grid=True),
                 "overlay": plot_overlay(results, highlight=0),
                 "paths": plot_trajectories(results, points, position=middle)}
        for name, figure in views.items():
            for suffix, magic in ((".png", b"\x89PNG"), (".svg", b"<?xml"),
                                  (".pdf", b"%PDF")):
                written = save_figure(figure, tmp_path / f"{name}{suffix}", dpi=60)
                assert written.read_bytes().startswith(magic)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(
        f"{n}{s}" for n in views for s in (".png", ".svg", ".pdf"))  # no temp files left
    for name in ("plan", "paths"):  # the labels of the drawn figures overlap nowhere
        boxes = rendered_label_boxes(views[name])
        assert boxes, f"{name}: no labels"
        assert not overlapping(boxes), f"{path.stem} {name}: {overlapping(boxes)}"


def rendered_label_boxes(figure) -> dict[str, np.ndarray]:
    """Every label's drawn box (text and frame, pixels) on the figure rendered by Agg."""
    FigureCanvasAgg(figure).draw()
    renderer = figure.canvas.get_renderer()
    return {a.get_gid(): label_box(a, renderer) for a in figure.axes[0].get_children()
            if isinstance(a, Annotation) and str(a.get_gid()).startswith(
                ("number ", "joint label ", "center label "))}


def overlapping(boxes: dict[str, np.ndarray]) -> list[tuple[str, str]]:
    """The pairs of labels whose boxes share an area (touching edges do not count)."""
    names = sorted(boxes)
    return [(a, b) for i, a in enumerate(names) for b in names[i + 1:]
            if min(boxes[a][2], boxes[b][2]) - max(boxes[a][0], boxes[b][0]) > 0.5
            and min(boxes[a][3], boxes[b][3]) - max(boxes[a][1], boxes[b][1]) > 0.5]


def test_overlay_draws_every_vector_at_every_position():
    results = mechloop.solve(load("four_bar.yaml"))
    placement = Placement(results)
    figure = plot_overlay(results)
    for n in results.model.vectors:
        lines = drawn(figure, f"overlay {n}")
        assert isinstance(lines, LineCollection)
        segments = np.asarray(lines.get_segments())
        assert segments.shape == (73, 2, 2)
        tails = placement.tail(n).z * 1000  # mm
        np.testing.assert_allclose(segments[:, 0, 0] + 1j * segments[:, 0, 1], tails,
                                   atol=1e-9)
    chosen = plot_overlay(results, [0, 18, 36])
    assert np.asarray(drawn(chosen, "overlay 2").get_segments()).shape == (3, 2, 2)


# --------------------------------------------------------------------------- trajectories


def test_coupler_point_trajectory_equals_results_point():
    results = mechloop.solve(load("four_bar.yaml"))
    x, y = results.point([5, 6])  # m; the model draws in mm
    for point in ({"head": 6}, HeadPoint(head=6),
                  TypeAdapter(PointOn).validate_python({"vector": 6, "share": 1.0})):
        figure = plot_trajectories(results, [point], position=10)
        label = "head of 6" if not isinstance(point, VectorPoint) else "1 of 6"
        line = drawn(figure, f"trajectory {label}")
        np.testing.assert_allclose(line.get_xdata(), 1000 * x, rtol=0, atol=1e-9)
        np.testing.assert_allclose(line.get_ydata(), 1000 * y, rtol=0, atol=1e-9)


def test_centre_of_mass_trajectory_follows_the_rod():
    results = mechloop.solve_dynamics(load("crank_slider_dynamics.yaml"))
    figure = plot_trajectories(results, ["S2", {"head": 1}], position=0)
    line = drawn(figure, "trajectory S2")
    phi = np.radians(np.arange(73) * 5.0)
    pins = [slider_crank_pins(p) for p in phi]
    expected = np.array([a + 0.3 * (b - a) for a, b in pins])
    np.testing.assert_allclose(np.column_stack([line.get_xdata(), line.get_ydata()]),
                               expected, atol=1e-12)


# ------------------------------------------------------------------------------ animation


def slow_crank_slider() -> mechloop.Model:
    """crank_slider.yaml turning once in 3.6 s: 50 ms per position (72 positions)."""
    data = load("crank_slider.yaml").model_dump(exclude_none=True)
    data["time"] = {"table": {0: 0.0, 72: 3.6}}
    return mechloop.Model.from_dict(data)


def test_frame_time_is_the_model_time_step():
    assert frame_interval(mechloop.solve(slow_crank_slider()), list(range(73))) == \
        pytest.approx(50.0)
    fast = mechloop.solve(load("crank_slider.yaml"))
    # 3000 rpm over 72 positions: 60/3000/72 s = 0.28 ms, slowed to 50 frames per second
    assert 60 / 3000 / 72 * 1000 < 20.0
    assert frame_interval(fast, list(range(73))) == 20.0
    assert frame_interval(fast, list(range(73)), fps=10) == 100.0


def test_gif_has_one_frame_per_position_with_the_model_frame_time(tmp_path):
    calls = []
    path = animate(mechloop.solve(slow_crank_slider()), tmp_path / "slow.gif", dpi=40,
                   progress=lambda done, total: calls.append((done, total)))
    with Image.open(path) as gif:  # position 72 is position 0 again: left out of the loop
        assert gif.n_frames == 72
        assert gif.info["duration"] == 50  # ms: 3.6 s / 72 positions
    assert calls == [(k, 72) for k in range(1, 73)]
    fast = animate(mechloop.solve(load("crank_slider.yaml")), tmp_path / "fast.gif", dpi=40)
    with Image.open(fast) as gif:
        assert gif.n_frames == 72
        assert gif.info["duration"] == 20  # the shortest delay browsers play as written
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fast.gif", "slow.gif"]


def test_gif_frames_show_the_crank_turning(tmp_path):
    """A pixel probe: the crank pin's pixel is drawn in the crank's colour only in the
    frames where the crank is there (positions 0 and 36 differ)."""
    path = animate(mechloop.solve(load("crank_slider.yaml")), tmp_path / "c.gif", dpi=60,
                   positions=[0, 36])
    with Image.open(path) as gif:
        first = np.asarray(gif.convert("RGB"), int)
        gif.seek(1)
        second = np.asarray(gif.convert("RGB"), int)
    assert first.shape == second.shape
    assert np.abs(first - second).sum(axis=2).max() > 100  # the frames differ


def test_mp4_has_one_frame_per_position_at_the_model_frame_rate(tmp_path):
    path = animate(mechloop.solve(slow_crank_slider()), tmp_path / "slow.mp4", dpi=40)
    frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(path))
    assert frames == 72  # a closed cycle: position 72 repeats position 0
    assert seconds == pytest.approx(72 * 0.050, abs=0.06)  # ffmpeg reports 1/100 s


def test_html_page_embeds_every_frame_and_plays_at_the_frame_time(tmp_path):
    path = animate(mechloop.solve(slow_crank_slider()), tmp_path / "slow.html", dpi=40)
    page = path.read_text()
    frames = re.findall(r'"data:image/png;base64,([^"]*)"', page.replace("\\\n", ""))
    assert len(frames) == 72  # a closed cycle: position 72 repeats position 0
    with Image.open(io.BytesIO(base64.b64decode(frames[0]))) as first:
        assert first.size[0] > 100
    # the player: new Animation(frames, img_id, slider_id, <interval in ms>, ...)
    interval = re.search(r"new Animation\(frames, img_id, slider_id, ([0-9.]+),", page)
    assert interval is not None and float(interval.group(1)) == 50.0


def test_a_closed_cycle_drops_its_repeated_last_frame_and_an_open_range_keeps_it():
    """A full turn of the crank (0..360°) ends on the first pose: the loop leaves position
    72 out; a half turn (0..180°), or positions that do not return, keep every one."""
    closed = plan_scene(mechloop.solve(load("crank_slider.yaml")))
    assert same_pose(closed, 0, 72) and not same_pose(closed, 0, 71)
    assert loop_frames(closed, list(range(73))) == list(range(72))
    assert loop_frames(closed, [0, 36, 72]) == [0, 36]
    assert loop_frames(closed, list(range(37))) == list(range(37))  # half a turn: open
    data = load("crank_slider.yaml").model_dump(exclude_none=True)
    data["arguments"][1] = {"table": {0: 0.0, 72: 180.0}}
    half = mechloop.solve(mechloop.Model.from_dict(data))
    assert loop_frames(plan_scene(half), list(range(73))) == list(range(73))
    broken = plan_scene(mechloop.solve(mechloop.Model.from_dict(SHORT_ROD)))
    assert broken.results.broken[3]
    assert not same_pose(broken, 0, 3)  # a pose with unknown ends is not the first pose
    assert loop_frames(broken, list(range(13))) == list(range(12))


def test_animation_frames_place_their_labels_without_overlaps():
    """Each frame arranges its labels on the frozen layout of the animation."""
    scene = plan_scene(mechloop.solve_dynamics(load("crank_slider_dynamics.yaml")))
    stage = _Stage(scene, 0, dpi=60, width=6.4, grid=False, axes=True, numbers=True)
    renderer = stage.canvas.get_renderer()
    for position in (0, 9, 36):
        drawn = draw_position(stage.ax, scene, position)
        boxes = {a.get_gid(): label_box(a, renderer) for a in drawn
                 if str(a.get_gid()).startswith(("number ", "joint label ", "center label "))}
        assert len(boxes) == 4 + 4 + 3  # vectors 1-4, joints O A B S, centres S1-S3
        assert not overlapping(boxes), (position, overlapping(boxes))
        for artist in drawn:
            artist.remove()


def test_animation_rejects_unknown_file_types(tmp_path):
    results = mechloop.solve(load("crank_slider.yaml"))
    with pytest.raises(ViewError, match=r"\.avi"):
        animate(results, tmp_path / "film.avi")
    with pytest.raises(ViewError, match="fps"):
        animate(results, tmp_path / "film.gif", fps=0)
    assert list(tmp_path.iterdir()) == []
