"""The web application's API for a spatial model (issue 17): the solve answer is the 3-D
view's data — every vector's tail and head in x, y, z equal to the placed scene of the
solver's results, null where the chain breaks, marked ``spatial`` — and the results table;
an animation job in HTML is the interactive 3-D view (``mechloop.views.spatial_html``), a
GIF the 3-D plan's frames."""

from __future__ import annotations

import io
import time
from pathlib import Path

import numpy as np
import orjson
import pytest
import yaml
from PIL import Image
from starlette.testclient import TestClient

import mechloop
from mechloop.views.spatial_plan import spatial_scene
from mechloop.web.app import create_app
from mechloop.web.payload import solution

SPATIAL = Path(__file__).resolve().parents[1] / "examples" / "spatial"


def rssr_text(coupler: float, positions: int) -> str:
    data = yaml.safe_load((SPATIAL / "rssr.yaml").read_text(encoding="utf-8"))
    data["positions"] = positions
    data["arguments"][1] = {"table": {0: 0, positions: 360}}
    data["vectors"][2]["r"] = coupler
    return yaml.safe_dump(data)


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    with TestClient(create_app(tmp_path_factory.mktemp("served"))) as client:
        yield client


def test_the_solve_answer_of_a_spatial_model_is_the_3d_views_data(tmp_path):
    # the answer of /api/solve (its route is driven in test_web_view3d_browser.py), made
    # here in this process: the short coupler breaks the chain over part of the turn
    (tmp_path / "m.yaml").write_text(rssr_text(80.0, 24), encoding="utf-8")
    model = mechloop.load_model(tmp_path / "m.yaml")
    solved = orjson.loads(orjson.dumps(solution(model), option=orjson.OPT_SERIALIZE_NUMPY))
    results = mechloop.solve(model)
    scene = spatial_scene(results)
    diagram = solved["diagram"]
    assert diagram["spatial"] is True and diagram["unit"] == "mm"
    assert (diagram["elev"], diagram["azim"]) == (20.0, 30.0)  # the static plan's view
    assert solved["count"] == 25 and solved["broken"] == results.broken.tolist()
    assert any(solved["broken"])
    for vector in diagram["vectors"]:
        n = vector["number"]
        for end, expected in (("tail", scene.tails[n]), ("head", scene.heads[n])):
            got = np.array([[np.nan if v is None else v for v in vector[end][a]]
                            for a in "xyz"])
            np.testing.assert_array_equal(got, expected)  # every digit, NaN as null
    marks = {v["number"]: v["marks"] for v in diagram["vectors"]}
    assert marks[1] == {"a": "argument"} and marks[2] == {"a": "function", "b": "function"}
    names = {c["name"] for c in solved["columns"]}
    assert {"x2", "y2", "z2", "b3"} <= names
    z2 = next(c for c in solved["columns"] if c["name"] == "z2")
    table = results.to_frame()
    column = next(h for h in table.columns if str(h).startswith("z2 "))
    np.testing.assert_allclose(np.array(z2["values"], dtype=float),
                               table[column].to_numpy(dtype=float), rtol=1e-12)


@pytest.mark.parametrize("fmt", ["html", "gif"])
def test_an_animation_job_of_a_spatial_model(client, fmt):
    answer = client.post("/api/jobs", json={"text": rssr_text(120.0, 4), "path": "rssr.yaml",
                                            "kind": "animation", "format": fmt})
    assert answer.status_code == 200, answer.text
    job = answer.json()["id"]
    end = time.monotonic() + 120
    while (status := client.get(f"/api/jobs/{job}").json())["state"] not in ("done",
                                                                             "failed"):
        assert time.monotonic() < end, status
        time.sleep(0.05)
    assert status["state"] == "done", status["problems"]
    assert status["result"]["frames"] == 4  # position 4 closes the turn
    content = client.get(f"/api/jobs/{job}/file").content
    if fmt == "html":
        assert b"class View3d" in content and b'"frames":[0,1,2,3]' in content
        assert b"data:image/png" not in content
    else:
        assert Image.open(io.BytesIO(content)).n_frames == 4
