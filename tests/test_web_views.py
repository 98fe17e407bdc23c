"""The other plot kinds of the page (``/api/view``): the SVG the server draws holds the
curves ``mechloop plot`` draws for the same view (every path of the CLI's SVG is in the
page's, the page's adds the position mark), in the page's language; refusals."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from starlette.testclient import TestClient
from typer.testing import CliRunner

from mechloop.cli import app as cli
from mechloop.web.app import create_app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
DYNAMICS = "crank_slider_dynamics"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    return TestClient(create_app(tmp_path_factory.mktemp("served")))


def _paths(svg: str) -> set[str]:
    """The drawn path data of an SVG (the curves, axes and marks), without the rounded
    legend frames (a legend placed 'best' may move aside for the position mark)."""
    return {d for d in re.findall(r'<path d="([^"]{40,})"', svg) if "Q" not in d}


def _cli_svg(tmp_path: Path, *args: str) -> str:
    target = tmp_path / "cli.svg"
    result = CliRunner().invoke(cli, ["plot", str(EXAMPLES / f"{DYNAMICS}.yaml"), *args,
                                      "-o", str(target)])
    assert result.exit_code == 0, result.output
    return target.read_text(encoding="utf-8")


@pytest.mark.parametrize(("kind", "cli_args", "request_args"), [
    ("reduced", [], {}),
    ("increment", ["-n", "r3", "-p", "7"], {"names": ["r3"], "position": 7}),
    ("hodograph", ["--joint", "A"], {"joint": "A"}),
])
def test_a_view_holds_the_clis_curves_and_marks_the_position(client, tmp_path, kind,
                                                              cli_args, request_args):
    text = (EXAMPLES / f"{DYNAMICS}.yaml").read_text(encoding="utf-8")
    answer = client.post("/api/view", json={"text": text, "example": DYNAMICS,
                                            "kind": kind, "position": 7, **request_args})
    assert answer.status_code == 200, answer.text
    assert answer.headers["content-type"].startswith("image/svg+xml")
    page, drawn = answer.text, _cli_svg(tmp_path, kind, *cli_args)
    cli_paths = _paths(drawn)
    assert len(cli_paths) > 3 and cli_paths <= _paths(page)
    assert ('id="position' in page) == (kind != "hodograph")
    russian = client.post("/api/view", json={"text": text, "example": DYNAMICS,
                                             "kind": kind, "lang": "ru", **request_args})
    ru_drawn = _cli_svg(tmp_path, kind, *cli_args, "--lang", "ru")
    assert _paths(ru_drawn) <= _paths(russian.text)
    assert re.search("[А-Яа-я]", ru_drawn) is None or \
        re.search("[А-Яа-я]", russian.text) is not None


def test_a_view_is_refused_with_the_fix(client):
    slider = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")
    no_bodies = client.post("/api/view", json={"text": slider, "example": "crank_slider",
                                               "kind": "reduced"})
    assert no_bodies.status_code == 422 and "bodies" in no_bodies.json()["error"]
    unknown = client.post("/api/view", json={"text": slider, "example": "crank_slider",
                                             "kind": "nothing"})
    assert unknown.status_code == 422 and unknown.json()["hint"].startswith("use one of")
    nameless = client.post("/api/view", json={"text": slider, "example": "crank_slider",
                                              "kind": "increment"})
    assert nameless.status_code == 422 and nameless.json()["hint"]
    bad = client.post("/api/view", json={"text": slider, "example": "crank_slider",
                                         "kind": "angle", "position": "x"})
    assert bad.status_code == 400
