"""The interactive 3-D view of a spatial model as one HTML file (issue 17,
``mechloop animate SPATIAL -o x.html``, :mod:`mechloop.views.spatial_html`): the file holds
the solved positions as JSON — every vector's tail and head equal to the placed scene and
its components (head − tail) equal to the solver's x/y/z, to the rounding written —, null
where the chain breaks, at exactly the broken positions; every script and style is inlined
(nothing fetched: it works offline); the command line writes it, the GIF stays a GIF."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
import yaml
from PIL import Image
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.views.figure import ViewError
from mechloop.views.spatial_html import coordinate_decimals, write_spatial_html
from mechloop.views.spatial_plan import spatial_scene

ROOT = Path(__file__).resolve().parents[1]
SPATIAL = ROOT / "examples" / "spatial"
#: The only address the page may name: the SVG namespace (a name, not a fetch).
SVG_NS = "http://www.w3.org/2000/svg"


def rssr(tmp_path: Path, coupler: float = 120.0, positions: int = 24) -> Path:
    """The RSSR example with ``positions`` positions and the coupler's length (80 mm:
    the chain breaks over part of the turn)."""
    data = yaml.safe_load((SPATIAL / "rssr.yaml").read_text(encoding="utf-8"))
    data["positions"] = positions
    data["arguments"][1] = {"table": {0: 0, positions: 360}}
    data["vectors"][2]["r"] = coupler
    path = tmp_path / f"rssr_{coupler:g}.yaml"
    path.write_text(yaml.safe_dump(data), encoding="utf-8")
    return path


def page_data(path: Path) -> dict:
    """The JSON the page gives its viewer."""
    text = path.read_text(encoding="utf-8")
    match = re.search(r"^const DATA = (\{.*\});$", text, re.MULTILINE)
    assert match, "the page holds no data"
    return json.loads(match.group(1).replace("<\\/", "</"))


def as_array(end: dict) -> np.ndarray:
    """``{x, y, z}`` lists (null unknown) as a (3, P) array with NaN."""
    return np.array([[np.nan if v is None else v for v in end[a]] for a in "xyz"])


@pytest.mark.parametrize("coupler", [120.0, 80.0])
def test_the_file_holds_the_solvers_coordinates_and_the_breaks(tmp_path, coupler):
    results = mechloop.solve(mechloop.load_model(rssr(tmp_path, coupler)))
    out = write_spatial_html(results, tmp_path / "view.html", elev=12.0, azim=-40.0,
                             lang="en")
    data = page_data(out)
    scene = spatial_scene(results)
    step = 10.0 ** -coordinate_decimals(scene)
    size = max(float(np.nanmax(np.abs(p))) for p in scene.heads.values())
    assert step <= 1e-7 * size  # rounded far below what can be seen
    broken = np.asarray(results.broken)
    assert data["broken"] == broken.tolist()
    assert (coupler == 80.0) == bool(broken.any())  # the short coupler breaks the chain
    assert data["elev"] == 12.0 and data["azim"] == -40.0 and data["unit"] == "mm"
    assert [v["number"] for v in data["vectors"]] == scene.vectors()
    for vector in data["vectors"]:
        n = vector["number"]
        tail, head = as_array(vector["tail"]), as_array(vector["head"])
        # unknown exactly where the scene is (the broken positions of the moving vectors)
        assert np.array_equal(np.isnan(head), np.isnan(scene.heads[n]))
        assert np.array_equal(np.isnan(tail), np.isnan(scene.tails[n]))
        np.testing.assert_allclose(head, scene.heads[n], rtol=0, atol=step / 2 * 1.0001)
        np.testing.assert_allclose(tail, scene.tails[n], rtol=0, atol=step / 2 * 1.0001)
        # the solver's x/y/z of the vector (m → mm), every known position
        solver = np.stack([np.broadcast_to(c[0], broken.shape) for c in
                           results.components(n)]) * 1000.0
        known = np.isfinite(head - tail).all(axis=0)
        assert known[~broken].all()  # every position that does not break is drawn
        np.testing.assert_allclose((head - tail)[:, known], solver[:, known], rtol=0,
                                   atol=step * 1.0001)
    coupler_head = as_array(data["vectors"][1]["head"])
    assert np.isnan(coupler_head[:, broken]).all() and np.isfinite(coupler_head[:, ~broken]).all()
    for item, b in zip(data["breaks"], results.breaks, strict=True):
        assert item["positions"] == [int(p) for p in b.positions]
        assert item["reason"] == b.reason
    # the ground: the fixed points O and D (the frame's ends)
    ground = as_array(data["ground"]).T
    np.testing.assert_allclose(ground, scene.ground, atol=step)
    assert len(ground) == 2


def test_the_page_is_self_contained(tmp_path):
    results = mechloop.solve(mechloop.load_model(rssr(tmp_path)))
    text = write_spatial_html(results, tmp_path / "view.html").read_text(encoding="utf-8")
    assert "<script src" not in text and "<link" not in text and "@import" not in text
    addresses = re.findall(r"https?://[^\s\"'`)]+", text)
    assert set(addresses) == {SVG_NS}  # no script, style, font or image fetched
    assert text.count("<script>") == 4  # the strings, the numbers, the viewer, the start
    assert "class View3d" in text and "view3dReset" in text  # the viewer and its words
    data = page_data(tmp_path / "view.html")
    assert data["frames"] == list(range(24))  # position 24 closes the turn: left out
    assert data["interval"] == pytest.approx(1000.0 / 24)  # 60 rpm, 24 positions a turn
    assert data["traced"] == ["head:1", "head:2"]  # the heads that move (B = head of 2)


def test_the_command_line_writes_the_view_and_keeps_the_gif(tmp_path):
    model = rssr(tmp_path, positions=4)
    runner = CliRunner()
    html = tmp_path / "cycle.html"
    result = runner.invoke(app, ["animate", str(model), "-o", str(html), "--elev", "5",
                                 "--azim", "60"])
    assert result.exit_code == 0, result.output
    assert "4 frames" in result.output
    data = page_data(html)
    assert (data["elev"], data["azim"]) == (5.0, 60.0) and len(data["broken"]) == 5
    gif = tmp_path / "cycle.gif"
    result = runner.invoke(app, ["animate", str(model), "-o", str(gif), "--views", "3d"])
    assert result.exit_code == 0, result.output
    with Image.open(gif) as image:
        assert image.format == "GIF" and image.n_frames == 4


def test_a_bad_language_or_no_position_is_refused(tmp_path):
    results = mechloop.solve(mechloop.load_model(rssr(tmp_path)))
    with pytest.raises(ViewError, match="no page language") as caught:
        write_spatial_html(results, tmp_path / "x.html", lang="de")
    assert caught.value.hint
    with pytest.raises(ViewError, match="no positions"):
        write_spatial_html(results, tmp_path / "x.html", positions=[])
    with pytest.raises(ViewError, match="outside"):
        write_spatial_html(results, tmp_path / "x.html", positions=[99])
    assert not (tmp_path / "x.html").exists()
