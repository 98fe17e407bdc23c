"""Cam designs as files: the cam: document (located errors, units, schema), the
`mechloop cam` command, and the profile written as CSV, DXF and SVG read back."""

from __future__ import annotations

import json
import math
import xml.etree.ElementTree as ET
from pathlib import Path

import jsonschema
import numpy as np
import pandas as pd
import pytest
import yaml
from typer.testing import CliRunner

from mechloop.cams.document import cam_from_data, cam_json_schema, load_cam
from mechloop.cli import app
from mechloop.errors import ModelError

CAMS = sorted((Path(__file__).resolve().parents[1] / "examples" / "cams").glob("*.yaml"))
ROLLER = CAMS[[p.stem for p in CAMS].index("roller")]


def _data(path: Path) -> dict:
    return yaml.safe_load(path.read_text(encoding="utf-8"))


@pytest.mark.parametrize("path", CAMS, ids=lambda p: p.stem)
def test_example_runs_through_the_cli_and_validates(path, tmp_path):
    assert path.read_text(encoding="utf-8").startswith("#")
    jsonschema.validate(json.loads(json.dumps(_data(path))), cam_json_schema())
    design = load_cam(path)
    s = design.summary()
    if s.pressure_ratio is not None:
        assert s.pressure_ratio <= 1 + 1e-9
    assert not s.undercut
    result = CliRunner().invoke(app, ["cam", str(path), "--table", str(tmp_path / "c.csv"),
                                      "--svg", str(tmp_path / "c.svg")])
    assert result.exit_code == 0, result.output
    assert "smallest radius of curvature" in result.output


def test_outputs_read_back(tmp_path):
    """The CSV holds the table of the design; the DXF's profile polyline and the SVG's
    polygon hold the profile in mm (the SVG mirrored in y, as SVG's y runs down)."""
    import ezdxf

    design = load_cam(ROLLER)
    files = {k: tmp_path / f"cam.{k}" for k in ("csv", "dxf", "svg")}
    figures = {k: tmp_path / f"{k}.png" for k in ("program", "profile", "pressure",
                                                  "curvature", "plan")}
    args = ["cam", str(ROLLER), "--table", str(files["csv"]), "--dxf", str(files["dxf"]),
            "--svg", str(files["svg"]), "--at", "75", "--animate", str(tmp_path / "a.gif"),
            "--frames", "4"]
    for view, path in figures.items():
        args += [f"--{view}", str(path)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    for path in [*figures.values(), tmp_path / "a.gif"]:
        assert path.stat().st_size > 1000
    g = design.cycle()
    table = pd.read_csv(files["csv"])
    assert np.array_equal(table[["x_profile [m]", "y_profile [m]"]].to_numpy(), g.profile)
    assert table["pressure angle [deg]"].to_numpy() == pytest.approx(np.degrees(g.pressure),
                                                                     rel=1e-15)
    doc = ezdxf.readfile(files["dxf"])
    polylines = {e.dxf.layer: e for e in doc.modelspace().query("LWPOLYLINE")}
    profile = np.array([p[:2] for p in polylines["PROFILE"].get_points()])
    assert polylines["PROFILE"].closed
    assert np.abs(profile - g.profile[:-1] * 1000).max() < 1e-9
    circle = doc.modelspace().query("CIRCLE")[0]
    assert circle.dxf.radius == pytest.approx(27.0)  # R0 − r of the example
    root = ET.parse(files["svg"]).getroot()
    polygon = next(e for e in root.iter() if e.get("id") == "profile")
    pts = np.array([[float(v) for v in p.split(",")] for p in polygon.get("points").split()])
    assert np.abs(pts * [1, -1] - g.profile[:-1] * 1000).max() < 1e-5


def test_units_of_the_file_do_not_change_the_design():
    data = _data(ROLLER)
    cam = data["cam"]
    metric = {**cam, "units": {"length": "m", "angle": "rad"},
              "follower": {**cam["follower"], "roller_radius": 0.01, "offset": "12 mm"},
              "base_radius": 0.037, "pressure_angle": math.radians(30),
              "return_pressure_angle": "45 deg",
              "segments": [{"rise": 0.02, "angle": math.radians(120), "law": "cycloidal"},
                           {"dwell": math.pi / 3},
                           {"return": "20 mm", "angle": "120 deg", "law": "cycloidal"},
                           {"dwell": "60 deg"}]}
    a = load_cam(ROLLER).cycle().profile
    b = cam_from_data({"cam": metric}).cycle().profile
    assert np.abs(a - b).max() < 1e-15


BAD = """\
cam:
  units: {length: mm, angle: deg}
  follower: {type: oscillating_roller, roller_radius: -3, pivot_distance: 100}
  pressure_angle: 40
  segments:
    - {rise: 20, angle: 100, law: poly345}
    - {dwell: 80}
    - {return: 20, angle: 100, law: cycloidal}
"""


def test_every_problem_is_reported_with_its_line(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(BAD, encoding="utf-8")
    with pytest.raises(ModelError) as info:
        load_cam(path)
    text = str(info.value)
    assert f"{path}:3" in text and "a rocker needs arm" in text
    assert "the segments span 280 deg, not one turn" in text
    result = CliRunner().invoke(app, ["cam", str(path)])
    assert result.exit_code == 2 and "Traceback" not in result.output


@pytest.mark.parametrize("change, message, line", [
    ({"law": "parabolic"}, "Input should be", 6),
    ({"angle": None}, "needs its angle and law", 6),
    ({"rise": 25}, "does not end where it starts", 5),
])
def test_segment_problems_are_located(tmp_path, change, message, line):
    data = _data(ROLLER)
    seg = {k: v for k, v in {**data["cam"]["segments"][0], **change}.items() if v is not None}
    data["cam"]["segments"][0] = seg
    path = tmp_path / "cam.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    with pytest.raises(ModelError) as info:
        load_cam(path)
    problem = info.value.problems[0]
    assert message in problem.message
    text = path.read_text().splitlines()
    assert problem.line is not None and "segments" in "".join(text[:problem.line])


def test_a_cam_file_given_to_the_vector_model_commands_says_what_it_is():
    result = CliRunner().invoke(app, ["check", str(ROLLER)])
    assert result.exit_code == 2
    assert "cam design" in result.output and "mechloop cam" in result.output


def test_impossible_designs_are_errors_at_their_key():
    data = _data(ROLLER)
    data["cam"]["base_radius"] = 5  # inside the offset of 12 mm
    with pytest.raises(ModelError, match="base radius must lie between"):
        cam_from_data(data)
    rocker = _data(ROLLER)["cam"]
    rocker.pop("base_radius")
    rocker.pop("return_pressure_angle")
    rocker.update(follower={"type": "oscillating_roller", "roller_radius": 5,
                            "pivot_distance": 40, "arm": 20}, pressure_angle=5)
    with pytest.raises(ModelError) as info:
        cam_from_data({"cam": rocker})
    assert info.value.problems[0].path == ("cam", "pressure_angle")


def test_the_schema_command_prints_the_cam_schema():
    result = CliRunner().invoke(app, ["schema", "--cam"])
    assert result.exit_code == 0
    assert json.loads(result.output) == cam_json_schema()


def test_the_shipped_schema_is_the_generated_one_and_the_docstrings_run():
    import doctest

    import mechloop.cams

    shipped = Path(mechloop.cams.__file__).parents[1] / "schema" / "cam.schema.json"
    assert json.loads(shipped.read_text(encoding="utf-8")) == cam_json_schema()
    assert doctest.testmod(mechloop.cams, raise_on_error=True).attempted > 0


def test_a_follower_pushed_past_its_geometry_is_an_error_at_the_base_radius():
    """A program that starts with a return takes a translating roller below its start:
    with too small a base radius its centre would pass the cam centre."""
    data = _data(ROLLER)
    cam = data["cam"]
    cam["segments"] = [{"return": 30, "angle": 120, "law": "cycloidal"}, {"dwell": 60},
                       {"rise": 30, "angle": 120, "law": "cycloidal"}, {"dwell": 60}]
    cam["base_radius"] = 30
    with pytest.raises(ModelError) as info:
        cam_from_data(data)
    assert info.value.problems[0].path == ("cam", "base_radius")
    assert "leaves its geometry" in info.value.problems[0].message


def test_a_rocker_face_returning_as_fast_as_the_cam_is_an_error():
    data = _data(ROLLER.parent / "flat_rocker.yaml")
    data["cam"]["segments"] = [{"rise": 40, "angle": 120, "law": "cycloidal"},
                               {"dwell": 200}, {"return": 40, "angle": 40, "law": "cycloidal"}]
    with pytest.raises(ModelError, match="turns back as fast as the cam"):
        cam_from_data(data)
