"""The web application's API (``mechloop serve``), endpoint by endpoint, with Starlette's
TestClient: the numbers it sends are the library's (and the crank's closed form), its
refusals (path traversal, request size, token, host, time limit) and a bad model that is
reported by line and never takes the server down."""

from __future__ import annotations

import math
import os
import shutil
import time
from io import BytesIO
from pathlib import Path

import numpy as np
import pytest
import yaml
from pypdf import PdfReader
from starlette.testclient import TestClient
from typer.testing import CliRunner

from mechloop.cli import app as cli
from mechloop.dynamics.analysis import solve_dynamics
from mechloop.model.load import load_model
from mechloop.solve.kinematics import solve
from mechloop.web import serve
from mechloop.web.app import create_app
from mechloop.web.safety import MAX_BODY_BYTES
from mechloop.web.worker import WorkFailed, run_limited

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SLIDER = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    root = tmp_path / "work"
    (root / "sub").mkdir(parents=True)
    (root / "crank_slider.yaml").write_text(SLIDER, encoding="utf-8")
    (root / "sub" / "four_bar.yaml").write_text((EXAMPLES / "four_bar.yaml").read_text())
    (tmp_path / "secret.yaml").write_text("name: secret outside\n")
    (tmp_path / "table.csv").write_text("position,value\n0,0\n72,360\n")
    (root / "notes.txt").write_text("not a model")
    os.symlink(tmp_path / "secret.yaml", root / "link_out.yaml")
    return root


@pytest.fixture
def client(folder: Path) -> TestClient:
    return TestClient(create_app(folder))


def _columns(answer: dict) -> dict[str, dict]:
    return {c["name"]: c for c in answer["columns"]}


def test_models_lists_the_folder_and_the_bundled_examples(client):
    answer = client.get("/api/models").json()
    assert answer["files"] == ["crank_slider.yaml", "sub/four_bar.yaml"]  # no link out
    ids = [e["id"] for e in answer["examples"]]
    assert "crank_slider" in ids and "01_an10_landing_gear" in ids
    course = next(e for e in answer["examples"] if e["id"] == "01_an10_landing_gear")
    assert course["number"] == 1 and course["title_ru"] != course["title"]


def test_model_reads_a_file_of_the_folder_or_an_example(client):
    assert client.get("/api/model", params={"path": "crank_slider.yaml"}).json() == \
        {"text": SLIDER}
    answer = client.get("/api/model", params={"example": "four_bar"}).json()
    assert answer["text"] == (EXAMPLES / "four_bar.yaml").read_text(encoding="utf-8")
    missing = client.get("/api/model", params={"path": "nothing.yaml"})
    assert missing.status_code == 404 and missing.json()["hint"]


@pytest.mark.parametrize("path", ["../secret.yaml", "sub/../../secret.yaml",
                                  "/etc/passwd", "link_out.yaml", "notes.txt",
                                  "..\\secret.yaml", "C:/secret.yaml", ""])
def test_no_file_outside_the_folder_is_read_or_written(client, folder, path):
    read = client.get("/api/model", params={"path": path})
    assert read.status_code in (400, 403, 404)
    assert "secret outside" not in read.text and "root:" not in read.text
    assert read.json()["error"] and read.json()["hint"]
    before = (folder.parent / "secret.yaml").read_text()
    write = client.post("/api/save", json={"path": path, "text": "name: overwritten\n"})
    assert write.status_code in (400, 403, 404)
    assert (folder.parent / "secret.yaml").read_text() == before
    assert client.post("/api/solve", json={"path": path, "text": SLIDER}).status_code \
        in (400, 403, 404)


def test_validate_reports_every_problem_at_its_line_with_the_fix(client):
    good = client.post("/api/validate", json={"path": "crank_slider.yaml", "text": SLIDER})
    assert good.json() == {"ok": True, "problems": []}
    lines = SLIDER.splitlines()
    row = next(i for i, line in enumerate(lines) if line.startswith("  2: {r: 0.2"))
    lines[row] = "  2: {r: 0.2, a: function, nam: connecting rod}"
    bad = client.post("/api/validate", json={"path": "crank_slider.yaml",
                                             "text": "\n".join(lines)}).json()
    assert bad["ok"] is False
    (problem,) = bad["problems"]
    assert problem["line"] == row + 1 and "nam" in problem["message"] and problem["hint"]
    assert problem["path"] == "vectors[2].nam"
    lines[row] = "  2: {r: 0.2, a: function"  # an unclosed flow mapping
    syntax = client.post("/api/validate", json={"path": "crank_slider.yaml",
                                                "text": "\n".join(lines)}).json()
    assert not syntax["ok"] and "YAML syntax" in syntax["problems"][0]["message"]
    assert syntax["problems"][0]["line"] in (row + 1, row + 2)


def test_a_csv_table_outside_the_folder_is_refused(client, folder):
    data = yaml.safe_load(SLIDER)
    data["arguments"] = {1: {"csv": "../table.csv"}}
    answer = client.post("/api/validate", json={"path": "crank_slider.yaml",
                                                "text": yaml.safe_dump(data)}).json()
    assert not answer["ok"]
    assert "outside the folder" in answer["problems"][0]["message"]
    shutil.copy(folder.parent / "table.csv", folder / "table.csv")
    data["arguments"] = {1: {"csv": "table.csv"}}
    inside = client.post("/api/validate", json={"path": "crank_slider.yaml",
                                                "text": yaml.safe_dump(data)}).json()
    assert inside == {"ok": True, "problems": []}


def test_a_project_document_outside_the_folder_is_refused(client):
    text = SLIDER + "project: {cam: ../secret.yaml}\n"
    answer = client.post("/api/validate", json={"path": "crank_slider.yaml",
                                                "text": text}).json()
    (problem,) = answer["problems"]
    assert problem["path"] == "project.cam" and "outside the folder" in problem["message"]
    assert problem["line"] == len(text.splitlines())
    report = client.post("/api/report", json={"path": "crank_slider.yaml", "text": text})
    assert report.status_code == 422 and "outside the folder" in report.json()["error"]


def test_solve_sends_the_diagram_and_table_of_the_library(client):
    answer = client.post("/api/solve", json={"path": "crank_slider.yaml",
                                             "text": SLIDER}).json()
    model = load_model(EXAMPLES / "crank_slider.yaml")
    results = solve(model)
    assert answer["count"] == 73 and answer["dynamics"] is False
    crank = next(v for v in answer["diagram"]["vectors"] if v["number"] == 1)
    assert crank["marks"] == {"a": "argument"}
    k = np.arange(73)
    # the crank turns 5 deg a position from the origin (the model's table 0..360 deg)
    assert crank["tail"]["x"] == pytest.approx(np.zeros(73), abs=1e-15)
    assert crank["head"]["x"] == pytest.approx(0.05 * np.cos(np.radians(5 * k)), abs=1e-12)
    assert crank["head"]["y"] == pytest.approx(0.05 * np.sin(np.radians(5 * k)), abs=1e-12)
    rod = next(v for v in answer["diagram"]["vectors"] if v["number"] == 2)
    assert rod["marks"] == {"a": "function"}
    length = np.hypot(np.subtract(rod["head"]["x"], rod["tail"]["x"]),
                      np.subtract(rod["head"]["y"], rod["tail"]["y"]))
    assert length == pytest.approx(np.full(73, 0.2), rel=1e-12)
    columns = _columns(answer)
    assert columns["r3"]["unit"] == "m"
    assert columns["r3"]["values"] == pytest.approx(results.values["r3"], rel=1e-12)
    assert columns["da2"]["unit"] == "rad/s"
    assert columns["da2"]["values"] == pytest.approx(results.rates["a2"], rel=1e-12)
    assert answer["broken"] == [False] * 73 and answer["breaks"] == []
    # fixed: the ends of the constant offset, vector 4, which closes the loop at O
    offset = next(v for v in answer["diagram"]["vectors"] if v["number"] == 4)
    ground = np.array(sorted(zip(answer["diagram"]["ground"]["x"],
                                 answer["diagram"]["ground"]["y"], strict=True),
                             key=lambda p: p[1]))
    ends = np.array(sorted([(offset["tail"]["x"][0], offset["tail"]["y"][0]),
                            (offset["head"]["x"][0], offset["head"]["y"][0])],
                           key=lambda p: p[1]))
    assert ground == pytest.approx(ends, abs=1e-15)
    assert ground[1] == pytest.approx([0.0, 0.0], abs=1e-15)


def test_solve_uses_the_models_display_units(client):
    text = SLIDER + "display:\n  length: mm\n"
    answer = client.post("/api/solve", json={"path": "crank_slider.yaml",
                                             "text": text}).json()
    plain = _columns(client.post("/api/solve", json={"path": "crank_slider.yaml",
                                                     "text": SLIDER}).json())
    shown = _columns(answer)
    assert shown["r3"]["unit"] == "mm" and shown["dr3"]["unit"] == "mm/s"
    assert shown["r3"]["values"] == pytest.approx(np.multiply(plain["r3"]["values"], 1000))
    assert answer["diagram"]["unit"] == "m"  # the plan keeps the model's length unit


def test_solve_of_a_model_with_bodies_gives_the_dynamics(client):
    text = (EXAMPLES / "crank_slider_dynamics.yaml").read_text(encoding="utf-8")
    answer = client.post("/api/solve", json={"example": "crank_slider_dynamics",
                                             "text": text}).json()
    assert answer["dynamics"] is True
    frame = solve_dynamics(load_model(EXAMPLES / "crank_slider_dynamics.yaml")).to_frame()
    columns = _columns(answer)
    moment = next(h for h in frame.columns if h.startswith("M_bal"))
    name = moment.split(" [")[0]
    assert columns[name]["values"] == pytest.approx(frame[moment].to_numpy(), rel=1e-10)
    assert [c["name"] for c in answer["diagram"]["centers"]]
    assert {j["name"] for j in answer["diagram"]["joints"]}


def test_solve_sends_the_chain_breaks_of_the_library(client):
    path = EXAMPLES / "four_bar_break_ahead.yaml"
    answer = client.post("/api/solve", json={"example": "four_bar_break_ahead",
                                             "text": path.read_text()}).json()
    results = solve(load_model(path))
    assert answer["broken"] == results.broken.tolist() and any(answer["broken"])
    assert [b["positions"] for b in answer["breaks"]] == \
        [b.positions.tolist() for b in results.breaks]
    broken = answer["broken"].index(True)
    follower = [v for v in answer["diagram"]["vectors"] if v["head"]["x"][broken] is None]
    assert follower  # unknown ends are null there, never a made-up number
    assert all(c["values"][broken] is None for c in answer["columns"]
               if c["name"] in results.varying())


def test_a_bad_model_is_a_located_error_and_the_server_goes_on(client):
    bad = SLIDER.replace("positions: 72", "positions: many")
    answer = client.post("/api/solve", json={"path": "crank_slider.yaml", "text": bad})
    assert answer.status_code == 422
    line = next(i for i, text in enumerate(bad.splitlines(), 1) if "many" in text)
    assert answer.json()["problems"][0]["line"] == line
    for junk in ("", "[1, 2", "- just\n- a list\n", "a: *nothing\n"):
        reply = client.post("/api/solve", json={"path": "crank_slider.yaml", "text": junk})
        assert reply.status_code == 422 and reply.json()["error"]
    assert client.post("/api/solve", content=b"not json",
                       headers={"content-type": "application/json"}).status_code == 400
    assert client.post("/api/solve", json=[1, 2]).status_code == 400
    assert client.post("/api/solve", json={"path": "crank_slider.yaml",
                                           "text": SLIDER}).status_code == 200


def test_a_solve_past_the_time_limit_is_stopped(folder):
    client = TestClient(create_app(folder, solve_seconds=0.001))
    answer = client.post("/api/solve", json={"path": "crank_slider.yaml", "text": SLIDER})
    assert answer.status_code == 504 and "longer than" in answer.json()["error"]


def test_the_worker_stops_long_work_and_reports_crashes():
    start = time.monotonic()
    with pytest.raises(WorkFailed) as slow:
        run_limited(time.sleep, 30, seconds=0.3)
    assert slow.value.status == 504 and time.monotonic() - start < 10
    with pytest.raises(WorkFailed) as crash:
        run_limited(math.sqrt, -1.0, seconds=10)
    assert crash.value.status == 500 and "ValueError" in crash.value.message
    assert run_limited(math.sqrt, 4.0, seconds=10) == 2.0


def test_save_writes_inside_the_folder_only(client, folder):
    text = SLIDER.replace("r: 0.2,", "r: 0.25,")
    answer = client.post("/api/save", json={"path": "sub/new.yaml", "text": text})
    assert answer.json() == {"saved": "sub/new.yaml"}
    assert (folder / "sub" / "new.yaml").read_text(encoding="utf-8") == text
    assert "sub/new.yaml" in client.get("/api/models").json()["files"]
    assert client.post("/api/save", json={"example": "four_bar", "text": text}
                       ).status_code == 403
    assert client.post("/api/save", json={"path": "nofolder/x.yaml", "text": text}
                       ).status_code == 404
    assert not list(folder.rglob("*.tmp*"))


def test_a_request_past_the_size_limit_is_refused(client):
    big = {"path": "crank_slider.yaml", "text": "#" * (MAX_BODY_BYTES + 10)}
    answer = client.post("/api/validate", json=big)
    assert answer.status_code == 413 and "larger than" in answer.json()["error"]

    def chunks():  # no content-length: the limit holds on the bytes received
        for _ in range(MAX_BODY_BYTES // 65536 + 2):
            yield b" " * 65536

    assert client.post("/api/validate", content=chunks()).status_code == 413


def test_a_token_guards_the_api_and_hosts_are_checked(folder):
    guarded = TestClient(create_app(folder, token="s3cret"))
    assert guarded.get("/api/models").status_code == 403
    assert guarded.get("/api/models", headers={"X-Mechloop-Token": "wrong"}
                       ).status_code == 403
    assert guarded.get("/api/models", headers={"X-Mechloop-Token": "s3cret"}
                       ).status_code == 200
    assert guarded.get("/api/models?token=s3cret").status_code == 200
    assert guarded.get("/").status_code == 200  # the page itself is the package's
    local = TestClient(create_app(folder, hosts=["127.0.0.1"]), base_url="http://127.0.0.1")
    assert local.get("/api/models").status_code == 200
    rebound = TestClient(create_app(folder, hosts=["127.0.0.1"]),
                         base_url="http://evil.example:8000")
    assert rebound.get("/api/models").status_code == 403


def test_a_page_of_another_origin_cannot_save(client, folder):
    """A page elsewhere can send a simple cross-site request (form-like content types,
    its own Origin) to the loopback port; nothing it asks is done."""
    for headers in ({"content-type": "text/plain"},
                    {"content-type": "application/x-www-form-urlencoded"},
                    {"content-type": "application/json", "origin": "http://evil.example"}):
        answer = client.post("/api/save", headers=headers,
                             content=b'{"path": "evil.yaml", "text": "name: evil"}')
        assert answer.status_code in (403, 415), headers
    assert not (folder / "evil.yaml").exists()
    same = client.post("/api/save", headers={"origin": "http://testserver"},
                       json={"path": "ok.yaml", "text": "name: ok\n"})
    assert same.status_code == 200 and (folder / "ok.yaml").exists()


def test_the_page_and_its_scripts_ship_in_the_package(client):
    page = client.get("/")
    assert page.status_code == 200 and "static/app.js" in page.text
    for name in ("app.js", "draw.js", "i18n.js", "app.css"):
        assert client.get(f"/static/{name}").status_code == 200
    assert "http" not in page.text.replace('href="data:,"', "")  # no CDN


def test_report_is_a_pdf_with_the_course_projects_sheets(client):
    """A course model's report holds the cam and gear sheets its project: section names
    (read from the examples' folder, where the model is)."""
    text = (EXAMPLES / "course" / "01_an10_landing_gear.yaml").read_text(encoding="utf-8")
    assert "project: {cam:" in text
    answer = client.post("/api/report", json={"example": "01_an10_landing_gear",
                                              "text": text, "lang": "ru"})
    assert answer.status_code == 200, answer.text
    assert answer.content.startswith(b"%PDF")
    assert answer.headers["content-type"] == "application/pdf"
    words = " ".join(page.extract_text() for page in PdfReader(BytesIO(answer.content)).pages)
    assert "кулачков" in words.lower() and "сателлит" in words.lower()  # sheets 4 and 3
    assert client.post("/api/report", json={"path": "crank_slider.yaml", "text": SLIDER,
                                            "lang": "de"}).status_code == 400


def test_serve_binds_loopback_and_asks_a_token_elsewhere(folder, monkeypatch):
    assert serve.is_loopback("127.0.0.1") and serve.is_loopback("::1")
    assert not serve.is_loopback("0.0.0.0") and not serve.is_loopback("192.168.1.5")
    local = serve.plan(folder / "crank_slider.yaml")
    assert local.token is None and local.start == "crank_slider.yaml"
    assert local.url == f"http://127.0.0.1:{local.port}/?path=crank_slider.yaml"
    assert "127.0.0.1" in local.hosts
    started = {}
    monkeypatch.setattr("uvicorn.run", lambda app, **kw: started.update(kw))
    monkeypatch.setattr("webbrowser.open", lambda url: started.update(opened=url))
    result = CliRunner().invoke(cli, ["serve", str(folder), "--host", "0.0.0.0",
                                      "--port", "8765", "--no-browser"])
    assert result.exit_code == 0, result.output
    assert "warning" in result.output and "?token=" in result.output
    assert started == {"host": "0.0.0.0", "port": 8765, "log_level": "warning"}
    result = CliRunner().invoke(cli, ["serve", str(folder)])
    assert result.exit_code == 0 and started["opened"].startswith("http://127.0.0.1:")
    assert started["opened"] in result.output
    missing = CliRunner().invoke(cli, ["serve", str(folder / "nothing.yaml")])
    assert missing.exit_code == 2 and "not found" in missing.output
