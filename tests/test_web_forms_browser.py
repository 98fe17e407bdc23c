"""The form views and the drag editing of the web page in a real headless Chromium (the
fixtures of ``test_web_browser.py``: one server and one browser for this module): a length
changed in the vectors form changes the YAML text in place (its comments kept), the
diagram and a plotted value to the numbers the API gives; an argument table row and a
CSV import; a YAML edit shows in the forms; a drag of a handle on the diagram writes a
rounded length (a ground point: length and angle) into the text and the diagram
follows; one undo step takes it back."""

from __future__ import annotations

import math

import pytest
from selenium.common.exceptions import StaleElementReferenceException
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from test_web_browser import (  # noqa: F401  (the fixtures: one server/browser here)
    EXAMPLES,
    SHOTS,
    _open,
    _post,
    _solved,
    _vector,
    _wait,
    browser,
    downloads,
    server,
)

SLIDER = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")


def _text(driver) -> str:
    return driver.find_element(By.ID, "editor").get_property("value")


def _tab(driver, tab: str) -> None:
    driver.find_element(By.CSS_SELECTOR, f"#form-tabs button[data-tab='{tab}']").click()
    _wait(driver, lambda d: d.find_element(By.ID, "forms").is_displayed()
          and d.find_elements(By.CSS_SELECTOR, "#forms fieldset"), f"no {tab} form")


def _again(driver, action, message: str):
    """``action(driver)`` retried while the forms redraw under it (a re-solve replaces
    their elements: a stale element is tried again, found anew)."""
    def attempt(d):
        try:
            return action(d)
        except StaleElementReferenceException:
            return False
    return _wait(driver, attempt, message)


def _field(driver, keys: str):
    return driver.find_element(By.CSS_SELECTOR,
                               f"#forms input[data-keys='{keys}']:not(.form-position)")


def _value(driver, keys: str) -> str | None:
    """A form field's value read in one script (the forms are redrawn when a solve
    arrives: an element found first and read after may be gone)."""
    return driver.execute_script(
        "const e = document.querySelector(arguments[0]); return e ? e.value : null;",
        f"#forms input[data-keys='{keys}']:not(.form-position)")


def _type(driver, keys: str, value: str) -> None:
    box = _field(driver, keys)
    box.click()
    box.send_keys(Keys.CONTROL, "a")
    box.send_keys(value, Keys.TAB)


def _settled(driver) -> None:
    """Wait for the page to have solved its current text (before a screenshot)."""
    _wait(driver, lambda d: d.execute_script(
        "return document.body.dataset.solved === String(state.version)"
        " && document.getElementById('status').className === 'ok'"), "not solved")


def _changed(driver, old: str) -> str:
    _wait(driver, lambda d: _text(d) != old, "the form did not change the text")
    return _text(driver)


def test_a_length_in_the_form_moves_the_diagram_and_the_plot(browser, server):  # noqa: F811
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    Select(browser.find_element(By.ID, "plot-select")).select_by_value("r3")
    browser.find_element(By.ID, "slider").send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * 9)
    marker = float(browser.find_element(By.ID, "plot-marker").get_attribute("data-value"))
    _tab(browser, "vectors")
    assert _value(browser, '["vectors",2,"r"]') == "0.2"
    solved = _solved(browser)
    _type(browser, '["vectors",2,"r"]', "0.26")
    edited = _changed(browser, SLIDER)
    assert edited == SLIDER.replace("  2: {r: 0.2, a: function,", "  2: {r: 0.26, a: function,")
    _wait(browser, lambda d: _solved(d) != solved, "the new length was not solved")
    api = _post(base, "/api/solve", {"path": "crank_slider.yaml", "text": edited})
    rod = next(v for v in api["diagram"]["vectors"] if v["number"] == 2)
    expected = (rod["tail"]["x"][9], rod["tail"]["y"][9], rod["head"]["x"][9],
                rod["head"]["y"][9])
    assert _vector(browser, 2) == pytest.approx(expected, rel=1e-12, abs=1e-15)
    r3 = next(c for c in api["columns"] if c["name"] == "r3")["values"][9]
    shown = float(browser.find_element(By.ID, "plot-marker").get_attribute("data-value"))
    assert shown == pytest.approx(r3, rel=1e-12) and shown != pytest.approx(marker)
    # the role of a parameter, and a YAML edit shows in the form
    Select(browser.find_element(By.CSS_SELECTOR, "#forms select[data-keys='"
                                "[\"vectors\",4,\"a\",\"role\"]']")).select_by_value("function")
    assert "  4: {r: 0.01, a: function, name: offset}\n" in _changed(browser, edited)
    browser.find_element(By.CSS_SELECTOR, "#form-tabs button[data-tab='yaml']").click()
    undo = "window.mechloopEditor ? mechloopEditor.undo() : null"
    browser.execute_script(undo)
    if browser.execute_script("return !!window.mechloopEditor"):
        _wait(browser, lambda d: _text(d) == edited, "one undo did not take the role back")
    else:  # without the editor's undo: the form's change is put back by hand
        browser.execute_script("const e = document.getElementById('editor');"
                               "e.value = arguments[0]; e.dispatchEvent(new Event('input'));",
                               edited)
    browser.execute_script("const e = document.getElementById('editor');"
                           "e.value = e.value.replace('name: crank', 'name: handle');"
                           "e.dispatchEvent(new Event('input'));")
    _tab(browser, "vectors")
    _wait(browser, lambda d: _value(d, '["vectors",1,"name"]') == "handle",
          "the form did not follow the YAML")
    _settled(browser)
    browser.save_screenshot(str(SHOTS / "web-forms-vectors.png"))


def test_an_argument_row_and_a_csv_import(browser, server, tmp_path):  # noqa: F811
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    _tab(browser, "arguments")
    _type(browser, '["arguments",1,"table",72]', "180")
    text = _changed(browser, SLIDER)
    assert "  1: {table: {0: 0, 72: 180}}       # argument 1:" in text
    table = tmp_path / "turn.csv"
    table.write_text("position;angle\n0;0\n36;90,5\n72;360\n", encoding="utf-8")
    _again(browser, lambda d: d.find_element(By.CSS_SELECTOR, "#forms input.form-csv")
           .send_keys(str(table)) or True, "no CSV import")
    imported = _changed(browser, text)
    assert "  1: {table: {0: 0, 36: 90.5, 72: 360}}" in imported
    assert imported.count("\n") == SLIDER.count("\n")  # in place: no other line changed
    _wait(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#forms tr[data-position='36']"),
          "the imported row is not in the form")
    _again(browser, lambda d: d.find_element(
        By.CSS_SELECTOR, "#forms tr[data-position='36'] .form-delete").click() or True,
           "no delete")
    assert "  1: {table: {0: 0, 72: 360}}" in _changed(browser, imported)
    _tab(browser, "time")
    _again(browser, lambda d: _field(d, '["time","rpm"]').get_property("value") == "3000",
           "the time form does not show 3000 rpm")
    browser.find_element(By.ID, "lang-ru").click()
    _wait(browser, lambda d: "Время модели" in d.find_element(By.ID, "forms").text,
          "the form is not in Russian")
    _settled(browser)
    browser.save_screenshot(str(SHOTS / "web-forms-ru.png"))
    browser.find_element(By.ID, "lang-en").click()


def test_dragging_a_handle_changes_a_length(browser, server):  # noqa: F811
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    _tab(browser, "vectors")  # the forms' data is there: the handles are drawn
    handle = _wait(browser, lambda d: d.find_elements(
        By.CSS_SELECTOR, "#diagram circle.drag-handle[data-vector='1']"), "no handle")[0]
    x1, y1, x2, y2 = _vector(browser, 1)  # the crank at position 0: along +x, 0.05 m
    assert (x2 - x1, y2 - y1) == pytest.approx((0.05, 0.0), abs=1e-12)
    scale = browser.execute_script(
        "const s = state.solution.diagram; const svg = document.getElementById('diagram');"
        "return planeMap(s.limits, Number(svg.getAttribute('width')),"
        " Number(svg.getAttribute('height')), 16).scale;")
    box = browser.execute_script("return document.getElementById('diagram')"
                                 ".getBoundingClientRect().width / 560")
    pixels = 0.03 * scale * box  # 3 cm further along the crank
    solved = _solved(browser)
    chain = ActionChains(browser, duration=50).click_and_hold(handle)
    for _ in range(5):
        chain.move_by_offset(pixels / 5, 0)
    chain.pause(0.5).release().perform()
    _wait(browser, lambda d: d.execute_script("return document.body.dataset.dragged || ''")
          .startswith("1:"), "the drag wrote nothing")
    r1 = float(browser.execute_script("return document.body.dataset.dragged").split(":")[1])
    assert r1 == pytest.approx(0.08, abs=0.002)
    assert r1 == float(f"{r1:.3g}")  # rounded to three significant digits
    text = _text(browser)
    assert text == SLIDER.replace("  1: {r: 0.05,", f"  1: {{r: {r1:g},")
    _wait(browser, lambda d: _solved(d) != solved and math.isclose(
        _vector(d, 1)[2] - _vector(d, 1)[0], r1, rel_tol=1e-12), "the diagram did not follow")
    _settled(browser)
    browser.save_screenshot(str(SHOTS / "web-drag.png"))
    if browser.execute_script("return !!window.mechloopEditor"):  # one undo: the whole drag
        browser.execute_script("mechloopEditor.undo()")
        _wait(browser, lambda d: _text(d) == SLIDER, "one undo did not take the drag back")


def test_dragging_a_ground_point_sets_its_length_and_angle(browser, server):  # noqa: F811
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    _tab(browser, "vectors")
    handle = _wait(browser, lambda d: d.find_elements(
        By.CSS_SELECTOR, "#diagram circle.drag-handle.ground[data-vector='4']"),
        "no ground handle")[0]
    tail_x, tail_y, head_x, head_y = _vector(browser, 4)  # the offset B -> O, 0.01 m up
    scale = browser.execute_script(
        "const s = state.solution.diagram; const svg = document.getElementById('diagram');"
        "return planeMap(s.limits, Number(svg.getAttribute('width')),"
        " Number(svg.getAttribute('height')), 16).scale"
        " * svg.getBoundingClientRect().width / 560;")
    solved = _solved(browser)
    ActionChains(browser, duration=50).click_and_hold(handle).move_by_offset(
        0, -round(0.01 * scale)).pause(0.5).release().perform()  # 1 cm higher
    _wait(browser, lambda d: d.execute_script("return document.body.dataset.dragged || ''")
          .startswith("4:"), "the drag wrote nothing")
    data = _post(base, "/api/data", {"text": _text(browser)})["data"]["vectors"]["4"]
    dx, dy = head_x - tail_x, head_y + 0.01 - tail_y  # the pointer's place, m
    assert data["r"] == pytest.approx(math.hypot(dx, dy), abs=0.002)
    assert data["a"] == pytest.approx(math.degrees(math.atan2(dy, dx)), abs=5)
    assert data["r"] == float(f"{data['r']:.3g}") and data["a"] == round(data["a"], 1)
    assert _text(browser).count("\n") == SLIDER.count("\n")  # in place
    _wait(browser, lambda d: _solved(d) != solved, "the diagram did not follow")
