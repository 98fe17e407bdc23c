"""What the issue-16 audit of the web application fixed, at the API and the library:
the structure comes with the solution (in both languages, from the same kinematics, so an
edit solves the model once), and the HTML animation plays without the internet."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import orjson
import pytest
from matplotlib._animation_data import DISPLAY_TEMPLATE, JS_INCLUDE
from starlette.testclient import TestClient

from mechloop.web.app import _solve_text, create_app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
URL = re.compile(rb"(?:https?:)?//[\w.-]+\.[a-z]{2,}/")


@pytest.fixture(scope="module")
def client() -> TestClient:
    return TestClient(create_app(EXAMPLES))


@pytest.mark.parametrize("name", ["crank_slider_dynamics", "crank_slider"])
def test_the_solution_carries_the_structure_the_structure_route_gives(client, name):
    """The same answer as api/structure in each language (a model with bodies: formula
    and Assur groups; without: the vector model's description only)."""
    text = (EXAMPLES / f"{name}.yaml").read_text(encoding="utf-8")
    source = {"example": name, "text": text}
    solved = client.post("/api/solve", json=source).json()
    for lang in ("en", "ru"):
        alone = client.post("/api/structure", json=source,
                            headers={"X-Mechloop-Lang": lang}).json()
        assert solved["structure"][lang] == alone
    if name == "crank_slider_dynamics":
        assert solved["structure"]["en"]["mechanism"]["formula"] == "L0(1) → L2(2,3)"
        assert solved["structure"]["ru"]["mechanism"]["explanation"] != \
            solved["structure"]["en"]["mechanism"]["explanation"]
        assert "плоская" in solved["structure"]["ru"]["description"]
    else:
        assert solved["structure"]["en"]["mechanism"] is None


def test_the_structure_is_made_from_the_solved_kinematics(monkeypatch):
    """No second solve for the structure: the analysis's own solve is never called."""
    import mechloop.structure.analysis as analysis

    def second_solve(*args, **kwargs):
        raise AssertionError("the structure solved the model again")

    monkeypatch.setattr(analysis, "solve", second_solve)
    path = EXAMPLES / "crank_slider_dynamics.yaml"
    payload = _solve_text(path.read_text(encoding="utf-8"), path, EXAMPLES)
    assert b'"formula":"L0(1) \xe2\x86\x92 L2(2,3)"' in payload


def test_a_structure_problem_leaves_the_solution_and_is_said_in_both_languages(monkeypatch):
    import mechloop.structure.analysis as analysis
    from mechloop.errors import HintedError

    def refused(*args, **kwargs):
        raise HintedError("the pairs cannot be told", "name the joints")

    monkeypatch.setattr(analysis, "decompose", refused)
    path = EXAMPLES / "crank_slider_dynamics.yaml"
    payload = orjson.loads(_solve_text(path.read_text(encoding="utf-8"), path, EXAMPLES))
    assert payload["count"] == 73 and payload["columns"]
    assert payload["structure"]["en"] == {"error": "the pairs cannot be told",
                                          "hint": "name the joints"}
    assert set(payload["structure"]["ru"]) == {"error", "hint"}


def test_the_html_player_needs_no_other_site(tmp_path):
    """The page of an HTML animation links nothing outside itself, and every button of
    matplotlib's player shows a character instead of a Font Awesome icon."""
    from mechloop.views.animation import write_frames
    from mechloop.views.offline_html import ICONS, offline

    template = (JS_INCLUDE + DISPLAY_TEMPLATE).encode()
    assert URL.search(template)  # matplotlib's page does link a CDN
    names = set(re.findall(r'<i class="fa ([^"]+)"></i>', DISPLAY_TEMPLATE))
    assert names and names <= set(ICONS)  # every icon of the player has its character
    assert b"<i class=" not in offline(template) and not URL.search(offline(template))

    frames = (np.full((16, 16, 4), 255 * i, dtype=np.uint8) for i in range(2))
    target = tmp_path / "motion.html"
    write_frames(frames, (16, 16), target, 100.0)
    page = target.read_bytes()
    assert b"anim-buttons" in page and b"&#x25B6;" in page  # the player, with its buttons
    assert not URL.search(page), URL.search(page)
    assert b"font-awesome" not in page


def test_the_printed_address_opens_a_file_whose_name_has_a_space_or_an_ampersand(tmp_path):
    from urllib.parse import parse_qs, urlsplit

    from mechloop.web.serve import plan

    model = tmp_path / "my crank & rod #2.yaml"
    model.write_text((EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8"))
    for host in ("127.0.0.1", "0.0.0.0"):
        url = plan(model, host=host, port=8765).url
        query = parse_qs(urlsplit(url).query)
        assert query["path"] == ["my crank & rod #2.yaml"], url
        assert ("token" in query) == (host != "127.0.0.1")
