"""The API behind the web application's model editor: the working copy (autosave) of a
model, new models from the bundled templates, and the library's error messages in the
page's language — with their refusals (paths out of the folder, unknown templates, size)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
import yaml
from starlette.testclient import TestClient

from mechloop.bundled.catalog import examples, find_example
from mechloop.messages import render_error
from mechloop.model.limits import MAX_DOCUMENT_BYTES
from mechloop.web.app import create_app
from mechloop.web.autosave import AUTOSAVE_DIR
from mechloop.web.safety import WebError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SLIDER = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    root = tmp_path / "work"
    (root / "sub").mkdir(parents=True)
    (root / "crank_slider.yaml").write_text(SLIDER, encoding="utf-8")
    (tmp_path / "secret.yaml").write_text("name: secret outside\n")
    return root


@pytest.fixture
def client(folder: Path) -> TestClient:
    return TestClient(create_app(folder))


def test_a_working_copy_is_kept_offered_and_cleared_by_save(client, folder):
    edited = SLIDER.replace("2: {r: 0.2,", "2: {r: 0.26,")
    assert client.get("/api/autosave", params={"path": "crank_slider.yaml"}).json() == \
        {"text": None, "time": None, "differs": False}
    assert client.post("/api/autosave", json={"path": "crank_slider.yaml",
                                               "text": edited}).json() == {"kept": True}
    copy = folder / AUTOSAVE_DIR / "files" / "crank_slider.yaml"
    assert copy.read_text(encoding="utf-8") == edited
    assert (folder / "crank_slider.yaml").read_text(encoding="utf-8") == SLIDER
    answer = client.get("/api/autosave", params={"path": "crank_slider.yaml"}).json()
    assert answer["text"] == edited and answer["differs"]
    assert answer["time"] == pytest.approx(copy.stat().st_mtime)
    # the working copy is not a model of the folder
    assert client.get("/api/models").json()["files"] == ["crank_slider.yaml"]
    # back to the file's text: nothing to keep
    assert client.post("/api/autosave", json={"path": "crank_slider.yaml",
                                               "text": SLIDER}).json() == {"kept": False}
    assert not copy.exists()
    client.post("/api/autosave", json={"path": "crank_slider.yaml", "text": edited})
    saved = client.post("/api/save", json={"path": "crank_slider.yaml", "text": edited})
    assert saved.json() == {"saved": "crank_slider.yaml"}
    assert not copy.exists()
    assert (folder / "crank_slider.yaml").read_text(encoding="utf-8") == edited


def test_a_working_copy_of_a_new_file_and_of_an_example(client, folder):
    client.post("/api/autosave", json={"path": "sub/new.yaml", "text": "name: new\n"})
    answer = client.get("/api/autosave", params={"path": "sub/new.yaml"}).json()
    assert answer["text"] == "name: new\n" and answer["differs"]  # no file yet: differs
    assert (folder / AUTOSAVE_DIR / "files" / "sub" / "new.yaml").is_file()
    example = find_example("four_bar").path.read_text(encoding="utf-8")
    client.post("/api/autosave", json={"example": "four_bar", "text": example + "# mine\n"})
    assert (folder / AUTOSAVE_DIR / "examples" / "four_bar.yaml").read_text() == \
        example + "# mine\n"
    assert client.post("/api/autosave/clear", json={"example": "four_bar"}).json() == \
        {"cleared": True}
    assert client.post("/api/autosave/clear", json={"example": "four_bar"}).json() == \
        {"cleared": False}
    assert client.get("/api/autosave", params={"example": "four_bar"}).json()["text"] is None


@pytest.mark.parametrize("path", ["../secret.yaml", "/etc/passwd.yaml", "sub/../../x.yaml",
                                  "link_out.yaml", "notes.txt", ""])
def test_no_working_copy_leads_out_of_the_folder(client, folder, path):
    os.symlink(folder.parent / "secret.yaml", folder / "link_out.yaml")
    put = client.post("/api/autosave", json={"path": path, "text": "name: x\n"})
    got = client.get("/api/autosave", params={"path": path})
    cleared = client.post("/api/autosave/clear", json={"path": path})
    for answer in (put, got, cleared):
        assert answer.status_code in (400, 403) and answer.json()["hint"]
    assert (folder.parent / "secret.yaml").read_text() == "name: secret outside\n"
    assert not (folder / ".mechloop").exists() and not (folder.parent / "x.yaml").exists()


def test_a_working_copy_through_a_link_out_is_refused(client, folder, tmp_path):
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    os.symlink(outside, folder / ".mechloop")
    answer = client.post("/api/autosave", json={"path": "crank_slider.yaml", "text": "x: 1"})
    assert answer.status_code == 403
    assert not list(outside.rglob("*"))


def test_a_working_copy_past_the_size_limit_is_refused(client, folder):
    text = "#" * (MAX_DOCUMENT_BYTES + 1)
    answer = client.post("/api/autosave", json={"path": "crank_slider.yaml", "text": text})
    assert answer.status_code == 413
    assert not (folder / AUTOSAVE_DIR).exists()
    too_large = client.post("/api/autosave", json={"path": "crank_slider.yaml",
                                                    "text": "#" * (MAX_DOCUMENT_BYTES * 2)})
    assert too_large.status_code == 413  # the request itself (safety.Guard)


def test_unknown_examples_have_no_working_copy(client):
    for name in ("no_such_model", "../../etc/passwd", "python_api"):
        answer = client.post("/api/autosave", json={"example": name, "text": "x: 1"})
        assert answer.status_code == 404 and answer.json()["hint"]


def test_the_templates_are_every_bundled_model_course_tasks_first(client):
    listed = client.get("/api/templates").json()["templates"]
    models = [e for e in examples() if e.path.suffix == ".yaml"]
    assert [t["id"] for t in listed] == [e.stem for e in models]
    course = [t for t in listed if t["group"] == "course"]
    assert [t["number"] for t in course] == list(range(1, 21))
    assert listed.index(course[-1]) == len(course) - 1
    first = course[0]
    assert first == {"id": "01_an10_landing_gear", "group": "course", "number": 1,
                     "title": "An-10 aircraft landing gear",
                     "title_ru": "Шасси самолета Ан-10", "file": "01_an10_landing_gear.yaml"}
    answer = client.get("/api/template", params={"name": "01_an10_landing_gear"}).json()
    assert answer["file"] == "01_an10_landing_gear.yaml"
    assert answer["text"] == find_example("1").path.read_text(encoding="utf-8")


@pytest.mark.parametrize("name", ["", "no_such_model", "../crank_slider", "python_api",
                                  "/etc/passwd"])
def test_an_unknown_template_is_refused(client, folder, name):
    answer = client.get("/api/template", params={"name": name})
    assert answer.status_code == 404 and answer.json()["hint"]
    if name:  # nothing saved from it either
        saved = client.post("/api/save", json={"path": "x.yaml", "text": "x: 1\n",
                                               "template": name})
        assert saved.status_code == 404 and not (folder / "x.yaml").exists()


def test_a_new_model_saved_from_a_course_template_brings_its_documents(client, folder):
    text = client.get("/api/template", params={"name": "01_an10_landing_gear"}).json()["text"]
    assert yaml.safe_load(text)["project"] == {"cam": "project/01_cam.yaml",
                                               "gears": "project/01_gears.yaml"}
    # unsaved, it is checked beside its template
    assert client.post("/api/validate", json={"example": "01_an10_landing_gear",
                                              "text": text}).json()["ok"]
    refused = client.post("/api/save", json={"path": "../gear.yaml", "text": text,
                                             "template": "01_an10_landing_gear"})
    assert refused.status_code == 403 and not (folder.parent / "gear.yaml").exists()
    assert not (folder.parent / "project").exists()
    saved = client.post("/api/save", json={"path": "sub/gear.yaml", "text": text,
                                           "template": "01_an10_landing_gear"}).json()
    assert saved == {"saved": "sub/gear.yaml",
                     "copied": ["sub/project/01_cam.yaml", "sub/project/01_gears.yaml"]}
    bundled = find_example("1").path.parent / "project"
    for name in ("01_cam.yaml", "01_gears.yaml"):
        assert (folder / "sub" / "project" / name).read_bytes() == \
            (bundled / name).read_bytes()
    assert client.post("/api/validate", json={"path": "sub/gear.yaml",
                                              "text": text}).json()["ok"]
    # a file the folder already has is kept, not overwritten
    (folder / "sub" / "project" / "01_cam.yaml").write_text("cam: mine\n")
    again = client.post("/api/save", json={"path": "sub/gear.yaml", "text": text,
                                           "template": "01_an10_landing_gear"}).json()
    assert again["copied"] == []
    assert (folder / "sub" / "project" / "01_cam.yaml").read_text() == "cam: mine\n"


def test_a_template_names_no_file_outside_the_folder(client, folder):
    text = SLIDER.replace("arguments:\n  1: {table: {0: 0, 72: 360}}",
                          "arguments:\n  1: {csv: ../../../../secret.csv}")
    saved = client.post("/api/save", json={"path": "x.yaml", "text": text,
                                           "template": "crank_slider"}).json()
    assert saved["copied"] == []
    assert sorted(p.name for p in folder.parent.iterdir()) == ["secret.yaml", "work"]


def test_errors_are_said_in_the_pages_language(client):
    bad = SLIDER.replace("positions: 72", "positions: many")
    english = client.post("/api/validate", json={"path": "crank_slider.yaml", "text": bad})
    russian = client.post("/api/validate", json={"path": "crank_slider.yaml", "text": bad},
                          headers={"X-Mechloop-Lang": "ru"})
    [en], [ru] = english.json()["problems"], russian.json()["problems"]
    line = next(n for n, text in enumerate(bad.splitlines(), 1) if text.startswith("positions"))
    assert (ru["line"], ru["path"]) == (en["line"], en["path"]) == (line, "positions")
    assert ru["message"] == render_error(WebError(en["message"]), "ru") != en["message"]
    assert ru["hint"] == render_error(WebError(en["hint"]), "ru") != en["hint"]
    # a refusal too, by the header or the query, and an unknown language is English
    refused = client.post("/api/save?lang=ru", json={"path": "../x.yaml", "text": ""}).json()
    plain = client.post("/api/save", json={"path": "../x.yaml", "text": ""},
                        headers={"X-Mechloop-Lang": "xx"}).json()
    assert refused["problems"][0]["message"] == render_error(WebError(plain["error"]), "ru")
    assert plain["error"] == "'../x.yaml' leads out of the folder"
    solved = client.post("/api/solve", json={"path": "crank_slider.yaml", "text": bad},
                         headers={"X-Mechloop-Lang": "ru"})
    assert solved.status_code == 422
    assert solved.json()["error"] == ru["message"]
