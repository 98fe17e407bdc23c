"""The model editor and the plot in a real headless Chromium (the fixtures of
``test_web_browser.py``): type, undo and redo and see the text and the diagram follow;
reload after an unsaved edit and get it back; make a new model from a course task and
save it; hover the plot and read the API's value; zoom in and out.  The screenshot
``docs/screenshots/web-editor.png`` is made here."""

from __future__ import annotations

import json
import shutil
import urllib.request

import pytest
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from test_web_browser import (
    SHOTS,
    _line_of,
    _open,
    _post,
    _replace,
    _solved,
    _vector,
    _wait,
    browser,
    downloads,
    server,
)

from mechloop.web.autosave import AUTOSAVE_DIR

__all__ = ["browser", "downloads", "server"]  # the fixtures, shared


def _text(driver) -> str:
    return driver.find_element(By.ID, "editor").get_property("value")


def _apis_rod(base: str, text: str, k: int) -> tuple[float, ...]:
    """Vector 2 (the rod) at position ``k`` as the API draws it for ``text``."""
    rod = next(v for v in _post(base, "/api/solve", {"path": "crank_slider.yaml",
                                                     "text": text})["diagram"]["vectors"]
               if v["number"] == 2)
    return (rod["tail"]["x"][k], rod["tail"]["y"][k], rod["head"]["x"][k], rod["head"]["y"][k])


def _after(driver, action, what: str) -> None:
    """Do ``action`` and wait for the page to have solved the text it leaves."""
    solved = _solved(driver)
    action()
    _wait(driver, lambda d: _solved(d) != solved, f"{what} was not solved")


def _keys(driver, *keys) -> None:
    """Press a key chord in the editor."""
    chord = ActionChains(driver)
    modifiers = keys[:-1]
    for key in modifiers:
        chord.key_down(key)
    chord.send_keys(keys[-1])
    for key in reversed(modifiers):
        chord.key_up(key)
    chord.perform()


def test_typing_undo_and_redo_move_the_text_and_the_diagram(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    original = _text(browser)
    assert _vector(browser, 2) == pytest.approx(_apis_rod(base, original, 0), rel=1e-12)
    # the highlighted layer shows the same text, its parts told apart
    layer = browser.find_element(By.ID, "highlight-code")
    assert layer.get_property("textContent") == original + "\n "
    kinds = browser.execute_script("""
        const out = {};
        for (const s of document.querySelectorAll('#highlight-code span[class^=y-]'))
          (out[s.className] = out[s.className] || []).push(s.textContent);
        return out;""")
    assert {"positions", "units", "length", "vectors", "contours"} <= set(kinds["y-key"])
    assert "72" in kinds["y-number"] and "0.05" in kinds["y-number"]
    assert {"m", "deg"} <= set(kinds["y-unit"]) and "function" in kinds["y-word"]
    assert any(c.startswith("# calculation positions") for c in kinds["y-comment"])
    assert browser.find_element(By.ID, "undo").get_property("disabled")

    line = _line_of(original, "  2: {r: 0.2,")
    _after(browser, lambda: _replace(browser, line, "0.2", "0.26"), "the typed length")
    edited = _text(browser)
    assert edited == original.replace("2: {r: 0.2,", "2: {r: 0.26,")
    assert _vector(browser, 2) == pytest.approx(_apis_rod(base, edited, 0), rel=1e-12)
    assert layer.get_property("textContent") == edited + "\n "

    _after(browser, lambda: _keys(browser, Keys.CONTROL, "z"), "the undone text")
    assert _text(browser) == original  # the whole typed number is one step
    assert _vector(browser, 2) == pytest.approx(_apis_rod(base, original, 0), rel=1e-12)
    assert browser.find_element(By.ID, "undo").get_property("disabled")
    _after(browser, lambda: _keys(browser, Keys.CONTROL, Keys.SHIFT, "z"), "the redone text")
    assert _text(browser) == edited
    assert _vector(browser, 2) == pytest.approx(_apis_rod(base, edited, 0), rel=1e-12)
    _after(browser, browser.find_element(By.ID, "undo").click, "the undo button's text")
    assert _text(browser) == original
    _after(browser, lambda: _keys(browser, Keys.CONTROL, "y"), "Ctrl+Y's text")
    assert _text(browser) == edited

    # a change made by another part of the page is one undo step and is solved the same
    moved = edited.replace("4: {r: 0.01,", "4: {r: 0.03,")
    _after(browser, lambda: browser.execute_script(
        "mechloopEditor.setText(arguments[0])", moved), "the set text")
    assert _vector(browser, 2) == pytest.approx(_apis_rod(base, moved, 0), rel=1e-12)
    assert browser.execute_script("return mechloopEditor.getText()") == moved
    _after(browser, lambda: browser.execute_script("mechloopEditor.undo()"), "the undo")
    assert _text(browser) == edited
    _after(browser, browser.find_element(By.ID, "redo").click, "the redo button's text")
    assert _text(browser) == moved
    assert browser.find_element(By.ID, "redo").get_property("disabled")


def test_an_unsaved_edit_comes_back_after_a_reload_and_save_clears_it(browser, server):
    base, folder = server
    on_disk = (folder / "crank_slider.yaml").read_text(encoding="utf-8")
    _open(browser, base + "/?path=crank_slider.yaml")
    browser.execute_script("localStorage.clear()")  # the other tests' edits
    shutil.rmtree(folder / ".mechloop", ignore_errors=True)
    _open(browser, base + "/?path=crank_slider.yaml")
    assert not browser.find_element(By.ID, "restore-bar").is_displayed()
    line = _line_of(on_disk, "  2: {r: 0.2,")
    _after(browser, lambda: _replace(browser, line, "0.2", "0.25"), "the edit")
    edited = _text(browser)
    copy = folder / AUTOSAVE_DIR / "files" / "crank_slider.yaml"
    _wait(browser, lambda d: copy.exists() and copy.read_text(encoding="utf-8") == edited,
          "the working copy was not kept on the server")
    assert (folder / "crank_slider.yaml").read_text(encoding="utf-8") == on_disk

    for where in ("browser", "server"):  # the browser's copy, then the server's alone
        if where == "server":
            browser.execute_script("localStorage.clear()")
        _open(browser, base + "/?path=crank_slider.yaml")
        assert _text(browser) == on_disk  # the file, with the working copy offered
        bar = _wait(browser, lambda d: d.find_element(By.ID, "restore-bar").is_displayed()
                    and d.find_element(By.ID, "restore-bar"), f"the {where}'s copy not offered")
        assert "differs from the file" in bar.text
        _after(browser, browser.find_element(By.ID, "restore").click, "the restored text")
        assert _text(browser) == edited and not bar.is_displayed()
        assert _vector(browser, 2) == pytest.approx(_apis_rod(base, edited, 0), rel=1e-12)
    _after(browser, lambda: _keys(browser, Keys.CONTROL, "z"), "the undone restore")
    assert _text(browser) == on_disk  # the restore is one undo step
    _after(browser, lambda: _keys(browser, Keys.CONTROL, "y"), "the redone restore")

    browser.find_element(By.ID, "save").click()
    _wait(browser, lambda d: d.find_element(By.ID, "status").text == "saved crank_slider.yaml",
          "not saved")
    assert (folder / "crank_slider.yaml").read_text(encoding="utf-8") == edited
    assert not copy.exists()
    assert browser.execute_script("return Object.keys(localStorage).filter("
                                  "(k) => k.startsWith('mechloop-autosave'))") == []
    _open(browser, base + "/?path=crank_slider.yaml")
    assert not browser.find_element(By.ID, "restore-bar").is_displayed()
    (folder / "crank_slider.yaml").write_text(on_disk, encoding="utf-8")  # for the others


def test_a_new_model_from_a_course_task_is_saved_under_a_name_asked(browser, server):
    base, folder = server
    _open(browser, base + "/?path=crank_slider.yaml&lang=en")
    Select(browser.find_element(By.ID, "new-model")).select_by_value("01_an10_landing_gear")
    _wait(browser, lambda d: "not saved yet" in d.find_element(By.ID, "status").text
          or "solved" in d.find_element(By.ID, "status").text, "the new model did not open")
    template = browser.execute_script("return newModel.templates[0]")
    assert template["title"] == "An-10 aircraft landing gear"
    _wait(browser, lambda d: d.find_element(By.ID, "status").text == "solved",
          "the new model was not solved")
    with urllib.request.urlopen(base + "/api/template?name=01_an10_landing_gear") as answer:
        text = json.loads(answer.read())["text"]
    assert _text(browser) == text
    assert browser.find_element(By.ID, "save-path").get_property("value") == ""
    browser.find_element(By.ID, "save").click()
    name = browser.find_element(By.ID, "save-as-name")
    assert name.is_displayed() and name.get_property("value") == "01_an10_landing_gear.yaml"
    name.clear()
    name.send_keys("../gear.yaml", Keys.ENTER)
    _wait(browser, lambda d: d.find_element(By.ID, "status").get_attribute("class") == "error",
          "saving out of the folder was not refused")
    assert "leads out of the folder" in browser.find_element(By.ID, "status").text
    assert not (folder.parent / "gear.yaml").exists()
    browser.find_element(By.ID, "save").click()  # still new: asked again
    name.clear()
    name.send_keys("gear.yaml")
    browser.find_element(By.ID, "save-as-ok").click()
    _wait(browser, lambda d: d.find_element(By.ID, "status").text == "saved gear.yaml",
          "the new model was not saved")
    assert (folder / "gear.yaml").read_text(encoding="utf-8") == text
    assert (folder / "project" / "01_cam.yaml").is_file()
    assert Select(browser.find_element(By.ID, "model-select")).first_selected_option \
        .get_attribute("value") == "path:gear.yaml"
    browser.find_element(By.ID, "lang-ru").click()
    group = browser.find_element(By.CSS_SELECTOR, "#new-model optgroup")
    assert group.get_attribute("label") == "Задания курсового проекта"
    option = browser.find_element(By.CSS_SELECTOR,
                                  "#new-model option[value='01_an10_landing_gear']")
    assert option.text == "1. Шасси самолета Ан-10"
    browser.find_element(By.ID, "lang-en").click()


def _hover(driver, position: int, name: str) -> dict:
    """Move the pointer onto the curve ``name`` at ``position``; the tooltip's data."""
    plot = driver.find_element(By.ID, "plot")
    x, y, width, height = driver.execute_script("""
        const [k, name] = arguments; const svg = document.getElementById('plot');
        const f = svg.plotFrame; const c = f.columns.find((c) => c.name === name);
        const box = svg.getBoundingClientRect(); const s = box.width / f.width;
        return [f.x(k) * s, f.scales[c.unit](c.values[k]) * s, box.width, box.height];""",
                                                position, name)
    ActionChains(driver).move_to_element_with_offset(
        plot, round(x - width / 2), round(y - height / 2)).perform()
    tip = _wait(driver, lambda d: d.find_element(By.ID, "plot-tip").is_displayed()
                and d.find_element(By.ID, "plot-tip"), "no tooltip")
    return {"text": tip.text, **{k: tip.get_attribute(f"data-{k}")
                                 for k in ("name", "position", "value", "unit")}}


def _shown(driver) -> tuple[float, float]:
    plot = driver.find_element(By.ID, "plot")
    return float(plot.get_attribute("data-from")), float(plot.get_attribute("data-to"))


def test_the_plot_shows_the_apis_values_on_hover_and_zooms(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml&lang=en")
    columns = {c["name"]: c for c in _post(base, "/api/solve", {
        "path": "crank_slider.yaml", "text": _text(browser)})["columns"]}
    Select(browser.find_element(By.ID, "plot-select")).select_by_value("r3")
    Select(browser.find_element(By.ID, "plot-add")).select_by_value("a2")
    tip = _hover(browser, 20, "r3")
    r3 = columns["r3"]["values"][20]
    assert (tip["name"], tip["position"], tip["unit"]) == ("r3", "20", "m")
    assert float(tip["value"]) == r3  # the API's number, to the last bit
    shown = browser.execute_script("return format(arguments[0])", r3)  # 6 digits
    assert tip["text"].splitlines() == [f"r3 = {shown} m", "position 20 of 0..72, t = 0.00555556 s"]
    tip = _hover(browser, 47, "a2")
    assert (tip["name"], tip["unit"]) == ("a2", "deg")
    assert float(tip["value"]) == columns["a2"]["values"][47]
    assert _shown(browser) == (0, 72)

    plot = browser.find_element(By.ID, "plot")
    ActionChains(browser).scroll_from_origin(ScrollOrigin.from_element(plot), 0, -300).perform()
    _wait(browser, lambda d: _shown(d)[1] - _shown(d)[0] < 72, "the wheel did not zoom in")
    low, high = _shown(browser)
    assert 0 <= low < 36 < high <= 72  # about the pointer, at the middle
    tip = _hover(browser, 30, "r3")  # the values hold when zoomed
    assert float(tip["value"]) == columns["r3"]["values"][30]
    browser.find_element(By.ID, "lang-ru").click()
    assert _hover(browser, 30, "r3")["text"].splitlines()[1].startswith("положение 30 из 0..72")
    browser.find_element(By.ID, "lang-en").click()
    ActionChains(browser).double_click(plot).perform()
    _wait(browser, lambda d: _shown(d) == (0, 72), "the double click did not show all")

    # a box dragged from position 10 to 30 shows those positions
    ends = browser.execute_script("""
        const svg = document.getElementById('plot'); const f = svg.plotFrame;
        const box = svg.getBoundingClientRect(); const s = box.width / f.width;
        return [f.x(10) * s - box.width / 2, f.x(30) * s - box.width / 2,
                (f.top + 30) * s - box.height / 2];""")
    (ActionChains(browser).move_to_element_with_offset(plot, round(ends[0]), round(ends[2]))
     .click_and_hold().move_by_offset(round(ends[1] - ends[0]), 0).release().perform())
    low, high = _shown(browser)  # to a few pixels (a pixel is 0.15 positions)
    assert low == pytest.approx(10, abs=0.5) and high == pytest.approx(30, abs=0.5)
    # the slider carries the zoomed range with it
    slider = browser.find_element(By.ID, "slider")
    slider.send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * 50)
    low, high = _shown(browser)
    assert high == 50 and high - low == pytest.approx(20, abs=1)
    marker = browser.find_element(By.ID, "plot-marker")
    assert marker.get_attribute("data-position") == "50"
    assert float(marker.get_attribute("data-value")) == columns["r3"]["values"][50]
    _hover(browser, 45, "r3")
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-editor.png"))
    ActionChains(browser).double_click(plot).perform()
    _wait(browser, lambda d: _shown(d) == (0, 72), "the double click did not zoom out")
