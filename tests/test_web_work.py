"""The page's animation, sweep and simulation as background jobs (``/api/jobs`` with
``kind`` animation, sweep or simulation; ``GET /api/jobs/{id}/file``): each runs in a
child, reports its progress and gives what the library computes for the same model —
checked here against the library called directly (the sweep's values by solving each
design on its own, the GIF's frames by reading the file back) — and is cancelled; bad
requests are refused before any child starts with the library's message, what only the
model can tell fails the job with its problem."""

from __future__ import annotations

import io
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from PIL import Image
from starlette.testclient import TestClient

from mechloop.dynamics.analysis import solve_dynamics
from mechloop.model.load import model_from_data
from mechloop.synthesis.sweep import SweepError, parse_vary, plan_sweep
from mechloop.web.app import create_app
from mechloop.web.work import MAX_SWEEP_DESIGNS

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
ENGINE = "single_cylinder_engine"


def _text(name: str) -> str:
    return (EXAMPLES / f"{name}.yaml").read_text(encoding="utf-8")


def four_bar(positions: int) -> str:
    """The four-bar example over ``positions`` steps of one crank turn."""
    return _text("four_bar").replace("positions: 72", f"positions: {positions}") \
        .replace("{0: 0, 72: 360}", f"{{0: 0, {positions}: 360}}")


def _wait(client: TestClient, job: str, until, seconds: float = 120.0) -> dict:
    """Poll the job until ``until(status)`` (a bounded wait, not a sleep in a test)."""
    end = time.monotonic() + seconds
    status: dict = {}
    while time.monotonic() < end:
        status = client.get(f"/api/jobs/{job}").json()
        if until(status):
            return status
        time.sleep(0.05)
    raise AssertionError(f"the job did not reach the state in {seconds} s: {status}")


def _finished(status: dict) -> bool:
    return status["state"] in ("done", "failed")


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    with TestClient(create_app(tmp_path_factory.mktemp("served"))) as client:
        yield client


def _start(client: TestClient, kind: str, text: str, **options) -> str:
    answer = client.post("/api/jobs", json={"text": text, "example": "four_bar",
                                            "kind": kind, **options})
    assert answer.status_code == 200, answer.text
    return answer.json()["id"]


def test_an_animation_job_makes_a_gif_of_every_position_of_the_cycle(client):
    job = _start(client, "animation", four_bar(12), format="gif", fps=10)
    done = _wait(client, job, _finished)
    assert done["state"] == "done", done["problems"]
    # 13 positions 0..12 over one crank turn: the last repeats the first and is left out
    assert done["result"]["frames"] == 12
    assert done["progress"] == {"done": 12.0, "total": 12.0}
    answer = client.get(f"/api/jobs/{job}/file")
    assert answer.status_code == 200 and answer.headers["content-type"] == "image/gif"
    assert 'filename="model.gif"' in answer.headers["content-disposition"]
    assert len(answer.content) == done["result"]["size"]
    image = Image.open(io.BytesIO(answer.content))
    assert image.format == "GIF" and image.n_frames == 12
    assert image.info["duration"] == 100  # fps 10: 100 ms a frame
    assert "file" not in done["result"]  # the bytes are downloaded, not polled


def test_a_sweep_job_gives_the_values_of_each_design_solved_on_its_own(client):
    text = _text(ENGINE)
    job = _start(client, "sweep", text, vary=["time.rpm=1000:3000:3"],
                 collect=["M_bal:max", "M_bal:rms"])
    done = _wait(client, job, _finished)
    assert done["state"] == "done", done["problems"]
    result = done["result"]
    assert result["parameters"] == ["time.rpm [rpm]"]
    assert result["quantities"] == ["M_bal:max [N*m]", "M_bal:rms [N*m]"]
    assert done["progress"] == {"done": 3.0, "total": 3.0}
    frame = pd.DataFrame(result["rows"], columns=result["columns"])
    assert list(frame["time.rpm [rpm]"]) == [1000.0, 2000.0, 3000.0]
    for rpm, row in zip((1000, 2000, 3000), frame.itertuples(index=False), strict=True):
        data = yaml.safe_load(text)
        data["time"]["rpm"] = rpm
        model = model_from_data(data, file=str(EXAMPLES / f"{ENGINE}.yaml"))
        moment = solve_dynamics(model).to_frame()["M_bal [N*m]"].to_numpy()
        assert np.isclose(row[1], moment.max(), rtol=1e-9)
        assert np.isclose(row[2], np.sqrt(np.mean(moment ** 2)), rtol=1e-9)
    assert result["svg"].lstrip().startswith("<?xml") and "<svg" in result["svg"]
    table = client.get(f"/api/jobs/{job}/file")
    assert table.status_code == 200 and table.headers["content-type"].startswith("text/csv")
    read = pd.read_csv(io.BytesIO(table.content))
    assert np.allclose(read["M_bal:max [N*m]"], frame["M_bal:max [N*m]"], rtol=1e-9)


def test_a_simulation_job_runs_the_simulate_section_for_the_duration_asked(client):
    text = _text("compressor_startup")
    answer = client.post("/api/jobs", json={"text": text, "example": "compressor_startup",
                                            "kind": "simulation", "duration": 0.4})
    assert answer.status_code == 200, answer.text
    job = answer.json()["id"]
    done = _wait(client, job, _finished)
    assert done["state"] == "done", done["problems"]
    summary = done["result"]["summary"]
    assert summary["end"] == pytest.approx(0.4)  # not the model's 10 s
    assert summary["events"] and "duration" in summary["events"][-1]
    assert done["progress"]["done"] == pytest.approx(0.4)
    series = pd.read_csv(io.BytesIO(client.get(f"/api/jobs/{job}/file").content))
    assert len(series) == summary["rows"]
    assert series["time [s]"].iloc[0] == 0 and series["time [s]"].iloc[-1] == \
        pytest.approx(0.4)
    # from rest: the crank speeds up from 0 rpm under the motor
    assert series["n [rpm]"].iloc[0] == 0 and series["n [rpm]"].iloc[-1] > 10
    svg = done["result"]["svg"]
    for curve in ("q", "omega", "epsilon", "phase"):
        assert f'id="{curve}' in svg


def test_a_sweep_is_cancelled_and_says_so(client):
    job = _start(client, "sweep", _text(ENGINE), vary=["time.rpm=1000:4000:20",
                                                      "machine.delta=0.01:0.05:20"],
                 collect=["M_bal:max"])
    _wait(client, job, lambda s: s["progress"].get("done", 0) >= 1 or _finished(s))
    busy = client.get(f"/api/jobs/{job}/file")
    cancelled = client.post(f"/api/jobs/{job}/cancel").json()
    assert cancelled["cancelled"]
    done = _wait(client, job, _finished)
    assert done["state"] == "failed" and done["progress"]["done"] < 400
    assert done["problems"][0]["message"] == "the job was cancelled"
    assert busy.status_code == 409 and busy.json()["hint"]
    assert client.get(f"/api/jobs/{job}/file").status_code == 404


@pytest.mark.parametrize(("options", "status", "message"), [
    ({"kind": "animation", "format": "avi"}, 400, "no animation format 'avi'"),
    ({"kind": "animation", "fps": -1}, 400, "'fps' is not a positive number"),
    ({"kind": "animation", "fps": 1000}, 400, "'fps' is 1000, more than 100"),
    ({"kind": "sweep", "vary": ["time.rpm"], "collect": ["M_bal:max"]}, 400,
     "cannot read 'time.rpm' as PATH=VALUES"),
    ({"kind": "sweep", "vary": "time.rpm=1:2:3", "collect": []}, 400,
     "'collect' is not a list of texts"),
    ({"kind": "sweep", "vary": ["a=1:2:3", "b=1:2:3", "c=1:2:3"], "collect": ["x:max"]},
     400, "3 parameters to vary; a sweep varies one or 2"),
    ({"kind": "sweep", "vary": ["a=1:2:21", "b=1:2:20"], "collect": ["x:max"]}, 400,
     f"the sweep has 420 designs; the page runs at most {MAX_SWEEP_DESIGNS}"),
    ({"kind": "simulation", "cycles": 1.5}, 400, "'cycles' is not a whole number"),
    ({"kind": "simulation", "lang": "de"}, 400, "no language 'de'"),
    ({"kind": "film"}, 400, "no job kind 'film'"),
    ({"kind": "animation", "example": None, "path": "../outside.yaml"}, 403,
     "'../outside.yaml' leads out of the folder"),
    ({"kind": "animation", "example": None, "path": "/etc/passwd.yaml"}, 403,
     "'/etc/passwd.yaml' is an absolute path"),
])
def test_a_bad_request_is_refused_before_a_job_starts(client, options, status, message):
    body = {"text": _text(ENGINE), "example": ENGINE, **options}
    answer = client.post("/api/jobs", json={k: v for k, v in body.items() if v is not None})
    assert answer.status_code == status, answer.text
    assert answer.json()["error"] == message and answer.json()["hint"]


def test_what_only_the_model_tells_fails_the_job_with_the_librarys_problem(client):
    text = _text(ENGINE)
    job = _start(client, "sweep", text, vary=["time.rpm=1000:2000:2"], collect=["M_bla:max"])
    done = _wait(client, job, _finished)
    model = model_from_data(yaml.safe_load(text), file=str(EXAMPLES / f"{ENGINE}.yaml"))
    with pytest.raises(SweepError) as raised:
        plan_sweep(model, [parse_vary("time.rpm=1000:2000:2")], ["M_bla:max"])
    assert done["state"] == "failed" and not done["cancelled"]
    assert done["problems"][0]["message"] == raised.value.message
    # a model without a simulate: section: said at the key to add
    job = _start(client, "simulation", four_bar(12))
    done = _wait(client, job, _finished)
    assert done["state"] == "failed"
    assert done["problems"][0]["message"] == "the model has no simulate: section"
    assert done["problems"][0]["path"] == "simulate"
    # a model with an error: located by line, as the editor shows it
    job = _start(client, "animation", four_bar(12).replace("r: 350", "r: -x"))
    done = _wait(client, job, _finished)
    assert done["state"] == "failed" and done["problems"][0]["line"] == 29


def test_the_file_of_an_unknown_job_is_not_found(client):
    answer = client.get("/api/jobs/nothere/file")
    assert answer.status_code == 404 and answer.json()["error"] == "no job 'nothere'"


@pytest.mark.parametrize(("fmt", "kind", "mark"), [
    ("mp4", "video/mp4", b"ftyp"), ("html", "text/html; charset=utf-8", b"<script")])
def test_an_animation_as_mp4_or_html(client, fmt, kind, mark):
    job = _start(client, "animation", four_bar(4), format=fmt)
    done = _wait(client, job, _finished)
    assert done["state"] == "done", done["problems"]
    assert done["result"]["frames"] == 4 and done["result"]["format"] == fmt
    answer = client.get(f"/api/jobs/{job}/file")
    assert answer.headers["content-type"] == kind
    assert f'filename="model.{fmt}"' in answer.headers["content-disposition"]
    assert mark in answer.content[:4096]
    if fmt == "html":  # every frame embedded in the page
        assert answer.content.count(b"data:image/png;base64") == 4


def test_an_animation_of_a_model_with_bodies_draws_its_centres_of_mass(client):
    text = _text("crank_slider_dynamics").replace("positions: 72", "positions: 6") \
        .replace("{0: 0, 72: 360}", "{0: 0, 6: 360}")
    answer = client.post("/api/jobs", json={"text": text, "example": "crank_slider_dynamics",
                                            "kind": "animation", "format": "gif"})
    done = _wait(client, answer.json()["id"], _finished)
    assert done["state"] == "done", done["problems"]
    image = Image.open(io.BytesIO(client.get(f"/api/jobs/{answer.json()['id']}/file")
                                  .content))
    assert image.n_frames == done["result"]["frames"] == 6


def test_a_job_past_its_time_limit_is_stopped_and_says_so(tmp_path):
    # a limit shorter than any simulation takes on any machine (a fast idle one finishes
    # this 300 s run of the compressor in under a second)
    with TestClient(create_app(tmp_path, job_seconds=0.05)) as client:
        answer = client.post("/api/jobs", json={
            "text": _text("compressor_startup"), "example": "compressor_startup",
            "kind": "simulation", "duration": 300})
        done = _wait(client, answer.json()["id"], _finished)
    assert done["state"] == "failed" and not done["cancelled"]
    assert done["problems"][0]["message"] == "the job took longer than 0.05 s and was stopped"
    assert done["elapsed"] < 30


def test_the_refusals_and_problems_come_in_the_pages_language(client):
    ru = {"X-Mechloop-Lang": "ru"}
    answer = client.post("/api/jobs", headers=ru, json={
        "text": _text(ENGINE), "example": ENGINE, "kind": "sweep",
        "vary": ["a=1:2:21", "b=1:2:20"], "collect": ["x:max"]})
    assert answer.status_code == 400
    assert answer.json()["error"] == ("в параметрическом анализе 420 вариантов; страница "
                                      f"выполняет не больше {MAX_SWEEP_DESIGNS}")
    job = _start(client, "simulation", four_bar(12))
    _wait(client, job, _finished)
    done = client.get(f"/api/jobs/{job}", headers=ru).json()
    assert done["problems"][0]["message"] == "в модели нет раздела 'simulate:'"
