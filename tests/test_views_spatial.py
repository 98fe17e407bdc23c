"""3-D position plans of models with spatial contours (issue 17): the vector scheme, the
three projections, trajectories, overlay, animation and the CLI.

What is drawn is read back from the artists and compared with what it must be: each
arrow's ends against the solver's x/y/z columns of its vector and against the RSSR's
joints in closed form, each projection against the 3-D ends with one coordinate dropped,
a planar contour of a mixed model against the planar solver's own placement, and the
paths against the columns, with gaps exactly at the chain breaks.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.text import Annotation
from mpl_toolkits.mplot3d import proj3d
from PIL import Image
from test_spatial_models import _as_spatial
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.dynamics.points import Placement
from mechloop.model.load import model_from_data
from mechloop.model.schema import LinkRole
from mechloop.views.figure import ViewError
from mechloop.views.plan import plot_plan
from mechloop.views.spatial_animation import animate_spatial
from mechloop.views.spatial_plan import (
    Arrow3D,
    plot_spatial_overlay,
    plot_spatial_plan,
    plot_spatial_trajectories,
    spatial_scene,
)

ROOT = Path(__file__).resolve().parents[1]
SPATIAL = ROOT / "examples" / "spatial"
EXAMPLES = sorted(SPATIAL.glob("*.yaml"))
#: the projections: which coordinates each shows (horizontal, vertical)
SHOWN = {"xy": (0, 1), "zy": (2, 1), "xz": (0, 2)}


def _data(path: Path) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8"))


def _solve(data: dict):
    return mechloop.solve(model_from_data(copy.deepcopy(data)))


def _panels(figure) -> dict:
    """The plan's axes by name: the 3-D one and the projections by their titles."""
    out = {}
    for ax in figure.axes:
        title = ax.get_title()
        out["3d" if title.startswith("3-D") else title.split()[-1].lower()] = ax
    return out


def _arrows3d(ax) -> dict[int, Arrow3D]:
    return {int(a.get_gid().split()[1]): a for a in ax.patches
            if isinstance(a, Arrow3D) and (a.get_gid() or "").startswith("vector ")}


def _arrows2d(ax) -> dict[int, Annotation]:
    return {int(t.get_gid().split()[1]): t for t in ax.texts
            if isinstance(t, Annotation) and (t.get_gid() or "").startswith("vector ")}


def _columns(results, number: int, position: int) -> np.ndarray:
    """Vector ``number`` at ``position`` in the model's length unit: from the solver's
    table (its x/y/z columns, m), or for a constant vector (not tabulated) from its r, a,
    b as written in the file (mm or m, deg)."""
    scale = 1000.0 if results.model.units.length == "mm" else 1.0
    frame = results.to_frame()
    if f"x{number} [m]" in frame:
        return scale * np.array([frame[f"{k}{number} [m]"].iloc[position] for k in "xyz"])
    vector = results.model.vectors[number]

    def value(v, letter: str) -> float:  # a number, or a link to a constant (r3 = r1)
        own = getattr(v, letter) or 0.0
        if isinstance(own, LinkRole):
            source = results.model.vectors[int(own.link[1:])]
            return own.ratio * value(source, own.link[0]) + own.delta
        return float(own)

    r, a, b = value(vector, "r"), math.radians(value(vector, "a")), \
        math.radians(value(vector, "b"))
    return r * np.array([math.cos(a) * math.cos(b), math.sin(a), math.cos(a) * math.sin(b)])


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_the_drawn_arrows_are_the_solved_vectors_in_3d_and_in_each_projection(path):
    results = mechloop.solve(mechloop.load_model(path))
    position = 9
    figure = plot_spatial_plan(results, position, elev=35, azim=-20)
    panels = _panels(figure)
    assert set(panels) == {"3d", *SHOWN}
    arrows = _arrows3d(panels["3d"])
    assert sorted(arrows) == sorted(results.model.vectors)
    for n, arrow in arrows.items():
        np.testing.assert_allclose(arrow.head3d - arrow.tail3d,
                                   _columns(results, n, position), rtol=0, atol=1e-9)
        for name, (h, v) in SHOWN.items():  # the projection drops the third coordinate
            flat = _arrows2d(panels[name])[n]
            np.testing.assert_allclose(flat.xy, arrow.head3d[[h, v]], rtol=0, atol=1e-12)
            np.testing.assert_allclose(flat.xyann, arrow.tail3d[[h, v]], rtol=0, atol=1e-12)
    # drawn where it is: after drawing, each arrow's screen ends are the projected points
    FigureCanvasAgg(figure).draw()
    ax = panels["3d"]
    assert (ax.elev, ax.azim) == (35, -20)
    # the same scale on the three axes: each side of the box as long as its data span
    # (matplotlib keeps the box in its view order: with Y up, the sides of z, x, y)
    spans = np.roll(np.ptp([ax.get_xlim(), ax.get_ylim(), ax.get_zlim()], axis=1), 1)
    box = np.asarray(ax.get_box_aspect())
    np.testing.assert_allclose(box / spans, box[0] / spans[0], rtol=1e-9)
    for arrow in arrows.values():
        xs, ys, _ = proj3d.proj_transform(*np.stack([arrow.tail3d, arrow.head3d], 1), ax.M)
        (ta, tb), (ha, hb) = arrow._posA_posB  # matplotlib has no public getter
        np.testing.assert_allclose([ta, tb, ha, hb], [xs[0], ys[0], xs[1], ys[1]])


def test_the_rssr_joints_are_where_its_closed_form_puts_them():
    """O at the origin, A = a (cos t, sin t, 0), D = 100 u(30°, 45°), |B − D| = c,
    |B − A| = L: from the file's numbers, not from the solver."""
    results = mechloop.solve(mechloop.load_model(SPATIAL / "rssr.yaml"))
    scene = spatial_scene(results)
    t = np.deg2rad(5.0 * np.arange(73))
    a30, b45 = math.radians(30), math.radians(45)
    d = 100 * np.array([math.cos(a30) * math.cos(b45), math.sin(a30),
                        math.cos(a30) * math.sin(b45)])
    np.testing.assert_allclose(scene.tails[1], 0.0, atol=1e-12)
    np.testing.assert_allclose(scene.heads[1], [40 * np.cos(t), 40 * np.sin(t), 0 * t],
                               atol=1e-9)
    np.testing.assert_allclose(scene.tails[2], scene.heads[1], atol=1e-9)
    np.testing.assert_allclose(scene.tails[3], d[:, None] + 0 * t, atol=1e-9)
    np.testing.assert_allclose(scene.heads[4], d[:, None] + 0 * t, atol=1e-9)
    np.testing.assert_allclose(scene.heads[2], scene.heads[3], atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(scene.heads[3] - d[:, None], axis=0), 80,
                               atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(scene.heads[2] - scene.heads[1], axis=0),
                               120, atol=1e-9)
    # the ground: O and D, nothing else
    ground = sorted(map(tuple, np.round(scene.ground, 9)))
    assert ground == sorted([(0.0, 0.0, 0.0), tuple(np.round(d, 9))])


def test_a_planar_model_written_as_spatial_is_placed_as_the_planar_plan():
    """The four-bar with contour 1 spatial and its coupler-point contour planar: every end
    as the planar placement puts it, in the plane z = 0."""
    data = _data(ROOT / "examples" / "four_bar.yaml")
    planar = Placement(_solve(data))
    scene = spatial_scene(_solve(_as_spatial(data, {0: 2})))
    scale = scene.scale
    for n in scene.vectors():
        for mine, theirs in ((scene.tails[n], planar.tail(n).z),
                             (scene.heads[n], planar.head(n).z)):
            np.testing.assert_allclose(mine[0], theirs.real * scale, atol=1e-9 * scale)
            np.testing.assert_allclose(mine[1], theirs.imag * scale, atol=1e-9 * scale)
            np.testing.assert_allclose(mine[2], 0.0, atol=1e-9 * scale)


def _broken_rssr():
    data = _data(SPATIAL / "rssr.yaml")
    data["vectors"][2]["r"] = 80  # a short coupler: no assembly at positions 44..62
    results = _solve(data)
    assert 0 < results.broken.sum() < results.broken.size
    return results


def test_trajectories_are_the_solved_columns_with_gaps_at_the_chain_breaks():
    results = _broken_rssr()
    figure = plot_spatial_trajectories(results, [{"head": 2}, {"vector": 2, "share": 0.5}],
                                       position=3)
    frame = results.to_frame()
    b = 1000.0 * np.array([frame[f"{k}1 [m]"] + frame[f"{k}2 [m]"] for k in "xyz"])
    a = 1000.0 * np.array([frame[f"{k}1 [m]"] for k in "xyz"])
    broken = results.broken
    panels = _panels(figure)
    for label, want in (("head of 2", b), ("0.5 of 2", (a + b) / 2)):
        (line,) = [ln for ln in panels["3d"].lines if ln.get_gid() == f"trajectory {label}"]
        got = np.array(line.get_data_3d())
        np.testing.assert_allclose(got[:, ~broken], want[:, ~broken], atol=1e-9)
        assert np.isnan(got[:, broken]).all()  # a gap exactly at the breaks
        for name, (h, v) in SHOWN.items():
            (flat,) = [ln for ln in panels[name].lines
                       if ln.get_gid() == f"trajectory {label}"]
            np.testing.assert_array_equal(flat.get_xdata(), got[h])
            np.testing.assert_array_equal(flat.get_ydata(), got[v])
    # the plan at a broken position draws no arrow and says why
    position = int(np.flatnonzero(broken)[0])
    broken_plan = plot_spatial_plan(results, position, views="3d")
    ax = broken_plan.axes[0]
    assert not _arrows3d(ax)
    assert any(f"chain break at position {position}" in t.get_text()
               for t in broken_plan.texts)


def test_default_trajectories_trace_every_moving_head_once():
    results = mechloop.solve(mechloop.load_model(SPATIAL / "rssr.yaml"))
    figure = plot_spatial_trajectories(results, views="3d")
    gids = sorted(ln.get_gid() for ln in figure.axes[0].lines
                  if (ln.get_gid() or "").startswith("trajectory"))
    # A (head of 1) and B (head of 2 = head of 3); D and O (heads of 3's tail, 4) are fixed
    assert gids == ["trajectory head of 1", "trajectory head of 2"]


def test_the_overlay_draws_every_known_position_and_names_the_breaks():
    results = _broken_rssr()
    figure = plot_spatial_overlay(results)
    ax = _panels(figure)["3d"]
    (line,) = [ln for ln in ax.lines if ln.get_gid() == "overlay 2"]
    got = np.array(line.get_data_3d()).reshape(3, -1, 3)  # tail, head, gap per position
    scene = spatial_scene(results)
    known = ~results.broken
    np.testing.assert_allclose(got[:, known, 0], scene.tails[2][:, known])
    np.testing.assert_allclose(got[:, known, 1], scene.heads[2][:, known])
    assert np.isnan(got[:, ~known, :2]).all() and np.isnan(got[:, :, 2]).all()
    assert "chain break at positions 44-62" in figure.texts[0].get_text()


def test_bad_requests_are_refused_with_a_fix():
    results = mechloop.solve(mechloop.load_model(SPATIAL / "rssr.yaml"))
    for call, message in ((lambda: plot_spatial_plan(results, 73), "outside"),
                          (lambda: plot_spatial_plan(results, 0, views="2d"), "unknown views"),
                          (lambda: plot_spatial_plan(results, 0, elev=float("nan")),
                           "elevation"),
                          (lambda: plot_spatial_trajectories(results, ["S2"]), "not a point"),
                          (lambda: plot_spatial_trajectories(results, [{"head": 9}]),
                           "vector 9 does not exist"),
                          (lambda: plot_plan(results, 0), "drawn in 3-D")):
        with pytest.raises(ViewError, match=message) as caught:
            call()
        assert caught.value.hint
    planar = mechloop.solve(mechloop.load_model(ROOT / "examples" / "four_bar.yaml"))
    with pytest.raises(ViewError, match="spatial contours"):
        spatial_scene(planar)


def test_the_animation_has_a_frame_per_position_and_drops_the_closing_one(tmp_path):
    results = mechloop.solve(mechloop.load_model(SPATIAL / "rssr.yaml"))
    out = animate_spatial(results, tmp_path / "a.gif", positions=[0, 36, 72], views="3d",
                          dpi=40)
    with Image.open(out) as image:
        assert image.n_frames == 2  # position 72 is position 0 again
        first = np.array(image.convert("RGB"))
        image.seek(1)
        second = np.array(image.convert("RGB"))
    assert first.shape == second.shape and (first != second).any()
    html = animate_spatial(results, tmp_path / "a.html", positions=[0, 9], views="3d", dpi=30)
    text = html.read_text(encoding="utf-8")  # the interactive 3-D view, not frames
    assert "data:image/png" not in text and '"frames":[0,9]' in text  # test_spatial_html.py


def test_the_cli_draws_spatial_plans_and_animations(tmp_path):
    data = _data(SPATIAL / "rssr.yaml")
    data["positions"] = 4  # a short cycle keeps the animation cheap
    data["arguments"][1] = {"table": {0: 0, 4: 360}}
    model = tmp_path / "rssr.yaml"
    model.write_text(yaml.safe_dump(data), encoding="utf-8")
    runner = CliRunner()
    for kind, extra in (("plan", ["-p", "1", "--elev", "10", "--azim", "40"]),
                        ("overlay", ["--views", "3d"]),
                        ("trajectories", ["--points", "head:2,vector:2:0.5"])):
        out = tmp_path / f"{kind}.png"
        result = runner.invoke(app, ["plot", str(model), kind, *extra, "-o", str(out)])
        assert result.exit_code == 0, result.output
        with Image.open(out) as image:
            assert image.format == "PNG" and image.size[0] > 500
    result = runner.invoke(app, ["plot", str(model), "plan", "--views", "2d", "-o",
                                 str(tmp_path / "x.png")])
    assert result.exit_code == 2 and "unknown views" in result.output
    out = tmp_path / "cycle.gif"
    result = runner.invoke(app, ["animate", str(model), "--views", "3d", "-o", str(out)])
    assert result.exit_code == 0, result.output
    with Image.open(out) as image:
        assert image.n_frames == 4  # positions 0..3; 4 closes the turn
    assert "(4 frames)" in result.output


def test_spatial_plans_in_russian_have_no_english_words():
    from test_views_russian import english, user_names

    results = _broken_rssr()
    names = user_names(results.model)
    broken = int(np.flatnonzero(results.broken)[0])
    for figure in (plot_spatial_plan(results, broken),
                   plot_spatial_trajectories(results, [{"tail": 2}, {"vector": 2,
                                                                     "share": 0.5}]),
                   plot_spatial_overlay(results, views="3d")):
        assert not english(figure, names)
