"""The views of ``mechloop plot`` drawn by the page itself (plots.js) in a real headless
Chromium (the fixtures of ``test_web_browser.py``): every kind draws the series the API
reads back from the figure (as many curves and points), the tables of the summary; the
hover value is the API's at the pointed position; the wheel zooms (the x range shrinks),
a double click shows everything again; the slider moves the cursor to the position's x
(and the hodograph's marker to the reaction at that position); a click on a curve moves
the slider; the view follows the language.  The README's screenshot of the views is made
here (``docs/screenshots/web-views.png``).  The view's file downloads as the API draws it
(the curves of ``mechloop plot`` and the current position marked)."""

from __future__ import annotations

import json
import math
import re
import urllib.request

import pytest
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from test_web_browser import (  # noqa: F401  (the fixtures: one server/browser here)
    SHOTS,
    _downloaded,
    _open,
    _post,
    _wait,
    browser,
    downloads,
    server,
)

ENGINE = "single_cylinder_engine"
#: The kinds and the choices they take (names, joint).
KINDS = [("reduced", "", ""), ("hodograph", "", "J1_2"), ("balancing", "", ""),
         ("reactions", "", ""), ("motion", "", ""), ("increment", "r3", ""),
         ("angle", "1,2", ""), ("combination", "r3,r2", ""), ("summary", "", "")]


def _api(driver, base: str, kind: str, names: str, joint: str, lang: str = "en") -> dict:
    """The data the API gives for the page's model and view."""
    text = driver.find_element(By.ID, "editor").get_property("value")
    return _post(base, "/api/view", {"text": text, "example": ENGINE, "kind": kind,
                                     "names": [n for n in names.split(",") if n],
                                     "joint": joint or None, "format": "data",
                                     "position": 0, "lang": lang})


def _show(driver, kind: str, names: str = "", joint: str = "") -> None:
    """Choose the view ``kind`` with its names and joint; wait until it is drawn."""
    before = driver.execute_script("return document.body.dataset.view || ''")
    for field, value in (("view-names", names), ("view-joint", joint)):
        driver.execute_script("document.getElementById(arguments[0]).value = arguments[1]",
                              field, value)
    Select(driver.find_element(By.ID, "view-kind")).select_by_value(kind)
    _wait(driver, lambda d: (v := d.execute_script("return document.body.dataset.view"
                                                   " || ''")) != before
          and v.startswith(kind + ":"), f"the view {kind} was not drawn")


def _set_position(driver, k: int) -> None:
    slider = driver.find_element(By.ID, "slider")
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", slider)
    slider.click()
    slider.send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * k)
    _wait(driver, lambda d: d.find_element(By.ID, "view-plot").get_attribute(
        "data-position") == str(k), "the view did not follow the slider")


def _post_text(base: str, data: dict) -> str:
    request = urllib.request.Request(base + "/api/view", data=json.dumps(data).encode(),
                                     headers={"content-type": "application/json"})
    with urllib.request.urlopen(request, timeout=30) as answer:
        return answer.read().decode()


def _paths(svg: str) -> list[str]:
    return re.findall(r'<path d="([^"]{40,})"', svg)


def _counts(data: dict) -> tuple[list[int], int]:
    """The finite points of each curve and the number of point groups, as the API says."""
    curves, points = [], 0
    for panel in data["panels"]:
        for axis in panel["yaxes"]:
            for s in axis["series"]:
                if s["kind"] == "line":
                    curves.append(sum(1 for x, y in zip(s["x"], s["y"], strict=True)
                                      if x is not None and y is not None))
                points += s["kind"] == "points"
    return curves, points


def _series(data: dict, name: str) -> dict:
    return next(s for p in data["panels"] for a in p["yaxes"] for s in a["series"]
                if s["name"] == name)


def _at(data: dict, name: str, k: int) -> tuple[float, float]:
    s = _series(data, name)
    i = s["positions"].index(k)
    return s["x"][i], s["y"][i]


def test_every_view_kind_is_drawn_from_the_apis_series(browser, server):  # noqa: F811
    base, _ = server
    _open(browser, base + f"/?example={ENGINE}")
    for kind, names, joint in KINDS:
        _show(browser, kind, names, joint)
        data = browser.execute_script("return viewPlot.data")  # the API's answer
        curves, points = _counts(data)
        drawn = [int(p.get_attribute("data-points")) for p in
                 browser.find_elements(By.CSS_SELECTOR, "#view-plot path.view-curve")]
        assert drawn == curves, kind
        assert len(browser.find_elements(By.CSS_SELECTOR, "#view-plot g.view-points")) \
            == points, kind
        tables = browser.find_elements(By.CSS_SELECTOR, "#view-tables table")
        assert len(tables) == len(data["tables"]), kind
        for table, expected in zip(tables, data["tables"], strict=True):
            cells = [[c.text for c in row.find_elements(By.CSS_SELECTOR, "th, td")]
                     for row in table.find_elements(By.TAG_NAME, "tr")]
            assert cells == expected["rows"], kind
        if kind == "summary":
            assert not curves and browser.find_element(By.ID, "view-plot").get_attribute(
                "hidden") is not None
        else:
            assert curves, kind


def test_hover_zoom_slider_and_click_on_the_views(browser, server,  # noqa: F811
                                                  downloads):  # noqa: F811
    base, _ = server
    _open(browser, base + f"/?example={ENGINE}")
    _show(browser, "reduced")
    data = _api(browser, base, "reduced", "", "")
    _set_position(browser, 10)
    svg = browser.find_element(By.ID, "view-plot")
    cursors = browser.find_elements(By.CSS_SELECTOR, "#view-plot line.view-cursor")
    assert len(cursors) == 2 and {float(c.get_attribute("data-x")) for c in cursors} == {10}
    at = browser.execute_script("return arguments[0].viewFrames.map((f) => f.x(10))", svg)
    assert [float(c.get_attribute("x1")) for c in cursors] == pytest.approx(at)
    # hover on the J_red marker: the tip says the API's value at position 10
    marker = browser.find_element(By.CSS_SELECTOR,
                                  "#view-plot circle.view-marker[data-name='J_red']")
    browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", svg)
    ActionChains(browser).move_to_element(marker).perform()
    tip = browser.find_element(By.ID, "view-tip")
    _wait(browser, lambda d: tip.is_displayed(), "no hover value")
    name = tip.get_attribute("data-name")
    assert tip.get_attribute("data-position") == "10"
    assert float(tip.get_attribute("data-value")) == _at(data, name, 10)[1]
    assert tip.get_attribute("data-unit") in tip.text
    # the wheel zooms about the pointer: the x range shrinks; a double click: all again
    panel = browser.find_element(By.CSS_SELECTOR, "#view-plot g.view-panel")

    def span() -> float:
        g = browser.find_element(By.CSS_SELECTOR, "#view-plot g.view-panel")
        return float(g.get_attribute("data-x1")) - float(g.get_attribute("data-x0"))
    full = span()
    browser.execute_script("""
        const svg = arguments[0], box = svg.getBoundingClientRect();
        svg.dispatchEvent(new WheelEvent('wheel', {clientX: box.left + box.width / 2,
          clientY: box.top + 120, deltaY: -120, bubbles: true, cancelable: true}));""", svg)
    assert span() == pytest.approx(0.8 * full)
    assert full == pytest.approx(72.0) and panel is not None
    ActionChains(browser).double_click(svg).perform()
    assert span() == pytest.approx(full)
    # a click on a curve: the slider goes to the nearest point's position
    scale = svg.size["width"] / 560
    px, py = browser.execute_script("""
        const f = arguments[0].viewFrames[0], s = f.panel.yaxes[0].series[0];
        return [f.x(30), f.ys[0](s.y[s.positions.indexOf(30)])];""", svg)
    ActionChains(browser).move_to_element_with_offset(
        svg, px * scale - svg.size["width"] / 2, py * scale - svg.size["height"] / 2
    ).click().perform()
    _wait(browser, lambda d: d.find_element(By.ID, "slider").get_attribute("value") == "30",
          "a click did not move the slider")
    # the hodograph: its marker is the reaction at the slider's position
    _show(browser, "hodograph", joint="J1_2")
    hodograph = _api(browser, base, "hodograph", "", "J1_2")
    _set_position(browser, 5)
    marker = browser.find_element(By.CSS_SELECTOR, "#view-plot circle.view-marker")
    x, y = _at(hodograph, marker.get_attribute("data-name"), 5)
    assert (float(marker.get_attribute("data-x")), float(marker.get_attribute("data-value"))) \
        == (x, y)
    vector = browser.find_element(By.CSS_SELECTOR, "#view-plot line.view-vector")
    assert math.isclose(float(vector.get_attribute("x2")), float(marker.get_attribute("cx")))
    # the file of the reduced view: the server's SVG with position 5 marked
    _show(browser, "reduced")
    Select(browser.find_element(By.ID, "view-format")).select_by_value("svg")
    browser.find_element(By.ID, "view-download").click()
    svg_file = _downloaded(browser, downloads / f"{ENGINE}-reduced.svg").read_text()
    text = browser.find_element(By.ID, "editor").get_property("value")
    expected = _post_text(base, {"text": text, "example": ENGINE, "kind": "reduced",
                                 "position": 5})
    assert _paths(svg_file) == _paths(expected) and 'id="position' in svg_file
    _show(browser, "hodograph", joint="J1_2")
    browser.execute_script("document.getElementById('view-kind').scrollIntoView()")
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-views.png"))
    # Russian: the view asked again, its texts in Russian
    browser.find_element(By.ID, "lang-ru").click()
    _wait(browser, lambda d: re.search("[А-Яа-я]", d.find_element(
        By.CSS_SELECTOR, "#view-plot .view-title").text), "the view is not in Russian")
    browser.find_element(By.ID, "lang-en").click()
