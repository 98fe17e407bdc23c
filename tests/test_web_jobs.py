"""Background jobs of the web application (``/api/jobs``): a synthesis of a bundled
example runs in a child, reports its progress and the best design so far, is cancelled
and keeps its best design — the same design the library evaluates from the returned
model's text; refusals (a second job, no synthesis task, an unknown job)."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
import yaml
from starlette.testclient import TestClient

from mechloop.model.load import model_from_data
from mechloop.synthesis.problem import SynthesisProblem
from mechloop.synthesis.variables import current_values
from mechloop.web.app import create_app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
EXAMPLE = "four_bar_path_synthesis"


def _wait(client: TestClient, job: str, until, seconds: float = 120.0) -> dict:
    """Poll the job until ``until(status)`` (a bounded wait, not a sleep in a test)."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        status = client.get(f"/api/jobs/{job}").json()
        if until(status):
            return status
        time.sleep(0.1)
    raise AssertionError(f"the job did not reach the state in {seconds} s: {status}")


@pytest.fixture
def client(tmp_path: Path):
    with TestClient(create_app(tmp_path)) as client:
        yield client


def test_a_synthesis_runs_reports_progress_is_cancelled_and_keeps_its_best(client):
    text = (EXAMPLES / f"{EXAMPLE}.yaml").read_text(encoding="utf-8")
    start = client.post("/api/jobs", json={"text": text, "example": EXAMPLE,
                                            "kind": "synthesis", "iterations": 400})
    assert start.status_code == 200, start.text
    job = start.json()["id"]
    second = client.post("/api/jobs", json={"text": text, "example": EXAMPLE})
    assert second.status_code == 429 and second.json()["hint"]
    running = _wait(client, job, lambda s: s["progress"].get("iteration", 0) >= 3
                    and s["diagram"] is not None)
    assert running["state"] == "running" and running["progress"]["total"] == 400
    drawn = running["diagram"]
    assert drawn["vectors"] and len(drawn["vectors"][0]["head"]["x"]) == 181
    cancelled = client.post(f"/api/jobs/{job}/cancel").json()
    assert cancelled["cancelled"] and cancelled["state"] in ("stopping", "done")
    done = _wait(client, job, lambda s: s["state"] in ("done", "failed"))
    assert done["state"] == "done", done["problems"]
    result = done["result"]
    assert result["stopped"] == "interrupted"
    assert done["progress"]["iteration"] < 400  # stopped early, by the cancel
    # the returned text is a model holding the best design: the library evaluates it to
    # the objective value reported
    data = yaml.safe_load(result["text"])
    model = model_from_data(data, file=str(EXAMPLES / f"{EXAMPLE}.yaml"))
    problem = SynthesisProblem(model)
    design = current_values(model, problem.variables)[None, :]
    evaluation = problem.evaluate(design, continuous=True)
    assert bool(evaluation.feasible[0]) == result["feasible"]
    if result["feasible"]:
        assert np.isclose(evaluation.q[0], result["best"], rtol=1e-6)
        # the search's last reported best, sampled; the result is evaluated as the
        # mechanism really moves (continuous), a little apart
        assert np.isclose(result["best"], done["progress"]["best"], rtol=1e-2)
    for name, value in result["values"].items():
        assert np.isclose(problem.variables.to_model_units(design[0])[name], value,
                          rtol=1e-9)
    assert client.get(f"/api/jobs/{job}").json()["state"] == "done"


def test_a_job_is_refused_without_a_synthesis_task_or_for_an_unknown_id(client):
    text = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")
    start = client.post("/api/jobs", json={"text": text, "example": "crank_slider"})
    status = _wait(client, start.json()["id"], lambda s: s["state"] == "failed")
    assert status["problems"][0]["path"] == "synthesis"
    assert client.get("/api/jobs/nothing").status_code == 404
    bad = client.post("/api/jobs", json={"text": text, "example": "crank_slider",
                                         "kind": "sweep"})
    assert bad.status_code == 400
    assert client.post("/api/jobs", json={"text": text, "example": "crank_slider",
                                          "iterations": -3}).status_code == 400


def test_past_its_time_limit_a_job_stops_keeping_its_best(tmp_path):
    text = (EXAMPLES / f"{EXAMPLE}.yaml").read_text(encoding="utf-8")
    with TestClient(create_app(tmp_path, job_seconds=2.0)) as client:
        job = client.post("/api/jobs", json={"text": text, "example": EXAMPLE,
                                             "iterations": 100000}).json()["id"]
        done = _wait(client, job, lambda s: s["state"] in ("done", "failed"))
    assert not done["cancelled"]
    if done["state"] == "done":  # stopped in the search: the best is kept
        assert done["result"]["stopped"] == "interrupted"
        assert done["progress"]["iteration"] < 100000
        assert yaml.safe_load(done["result"]["text"])["synthesis"]
    else:  # the limit came before the first generation (a loaded machine)
        assert done["problems"][0]["message"] == \
            "the job was stopped before the search started"
        assert not done["progress"]


def test_the_server_stopping_kills_a_running_job(tmp_path):
    text = (EXAMPLES / f"{EXAMPLE}.yaml").read_text(encoding="utf-8")
    app = create_app(tmp_path)
    with TestClient(app) as client:
        job = client.post("/api/jobs", json={"text": text, "example": EXAMPLE,
                                             "iterations": 100000}).json()["id"]
        _wait(client, job, lambda s: s["progress"].get("iteration", 0) >= 1)
        process = app.app.state.jobs.get(job).process
        assert process.is_alive()
    assert not process.is_alive()  # the shutdown killed it
