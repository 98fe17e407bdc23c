"""The Units tab of the web page in a real headless Chromium (the fixtures of
``test_web_browser.py``: one server and one browser for this module): millimetres for
lengths and three significant digits, chosen in the tab, write ``display: {length: mm,
digits: 3}`` into the YAML text; the results table then shows the slider's length in mm
with three significant digits, the API's number converted and rounded; decimals in
place of digits; undo takes the section away again and the table is back in metres."""

from __future__ import annotations

import re

import pytest
from selenium.common.exceptions import StaleElementReferenceException
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from test_web_browser import (  # noqa: F401  (the fixtures: one server/browser here)
    EXAMPLES,
    SHOTS,
    _open,
    _post,
    _wait,
    browser,
    downloads,
    server,
)

SLIDER = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")


def _text(driver) -> str:
    return driver.find_element(By.ID, "editor").get_property("value")


def _choose(driver, keys: str, value: str) -> None:
    """Choose ``value`` at ``keys`` in the tab (again if the tab was drawn anew from the
    edited text under the pointer: the choice on the new one)."""
    def chosen(d) -> bool:
        try:
            boxes = d.find_elements(By.CSS_SELECTOR, f"#forms select[data-keys='{keys}']")
            if boxes:
                Select(boxes[0]).select_by_value(value)
            return bool(boxes)
        except StaleElementReferenceException:
            return False
    _wait(driver, chosen, f"no choice {keys}")


def _changed_to(driver, text: str) -> None:
    _wait(driver, lambda d: _text(d) == text, f"the text did not become {text[-60:]!r}")


def _settled(driver) -> None:
    _wait(driver, lambda d: d.execute_script(
        "return document.body.dataset.solved === String(state.version)"
        " && document.getElementById('status').className === 'ok'"), "not solved")


def _row(driver, name: str) -> tuple[str, str]:
    """The value and unit shown for ``name`` in the results table (read at once)."""
    return tuple(driver.execute_script(
        "return [...document.querySelectorAll(`#results tr[data-name='${arguments[0]}'] td`)]"
        ".slice(1).map((c) => c.textContent)", name))


def test_millimetres_and_three_digits_chosen_in_the_units_tab(browser, server):  # noqa: F811
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    Select(browser.find_element(By.ID, "plot-select")).select_by_value("r3")
    browser.find_element(By.ID, "slider").send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * 9)
    api = _post(base, "/api/solve", {"path": "crank_slider.yaml", "text": SLIDER})
    r3 = next(c for c in api["columns"] if c["name"] == "r3")["values"][9]  # m
    assert api["precision"] == {}
    value, unit = _row(browser, "r3")
    assert unit == "m" and float(value) == float(f"{r3:.6g}")
    browser.find_element(By.CSS_SELECTOR, "#form-tabs button[data-tab='units']").click()
    _choose(browser, '["display","length"]', "mm")
    _changed_to(browser, SLIDER + "display: {length: mm}\n")
    _choose(browser, '["display","precision"]', "digits")
    _changed_to(browser, SLIDER + "display: {length: mm, digits: 6}\n")
    _choose(browser, '["display","digits"]', "3")
    done = SLIDER + "display: {length: mm, digits: 3}\n"
    _changed_to(browser, done)
    _settled(browser)
    value, unit = _row(browser, "r3")
    assert unit == "mm"
    assert float(value) == float(f"{r3 * 1000:.3g}")  # the API's metres, converted
    assert len(re.sub(r"^[-0.]+", "", value.replace(".", ""))) == 3, value  # 3 digits
    assert r3 * 1000 != float(value)  # rounded, not the double itself
    marker = browser.find_element(By.ID, "plot-marker")  # the curve: mm, every digit
    assert float(marker.get_attribute("data-value")) == pytest.approx(r3 * 1000, rel=1e-12)
    # the choices drawn again from the new text say what it holds
    for keys, chosen in (('["display","length"]', "mm"), ('["display","precision"]', "digits"),
                         ('["display","digits"]', "3")):
        box = browser.find_element(By.CSS_SELECTOR, f"#forms select[data-keys='{keys}']")
        assert Select(box).first_selected_option.get_attribute("value") == chosen
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-units.png"))
    _choose(browser, '["display","precision"]', "decimals")  # digits out, decimals in
    _changed_to(browser, SLIDER + "display: {length: mm, decimals: 3}\n")
    _settled(browser)
    value, unit = _row(browser, "r3")
    assert unit == "mm" and re.fullmatch(r"\d+\.\d{3}", value), value
    assert float(value) == round(r3 * 1000, 3)
    for text in (SLIDER + "display: {length: mm}\n", done,
                 SLIDER + "display: {length: mm, digits: 6}\n",
                 SLIDER + "display: {length: mm}\n", SLIDER):
        browser.find_element(By.ID, "undo").click()
        _changed_to(browser, text)
    _settled(browser)
    value, unit = _row(browser, "r3")
    assert unit == "m" and float(value) == float(f"{r3:.6g}")
    box = browser.find_element(By.CSS_SELECTOR,
                               "#forms select[data-keys='[\"display\",\"length\"]']")
    assert Select(box).first_selected_option.get_attribute("value") == ""  # default again


def test_two_quick_choices_make_one_section(browser, server):  # noqa: F811
    """The second choice, made before the first edit is back, is decided from the text the
    first one left: both units in one new section (not the second replacing it)."""
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    browser.find_element(By.CSS_SELECTOR, "#form-tabs button[data-tab='units']").click()
    _wait(browser, lambda d: d.find_elements(
        By.CSS_SELECTOR, "#forms select[data-keys='[\"display\",\"moment\"]']"), "no tab")
    browser.execute_script("""
        for (const [kind, unit] of [["force", "kN"], ["moment", "kN*m"]]) {
          const box = document.querySelector(`#forms select[data-keys='["display","${kind}"]']`);
          box.value = unit; box.dispatchEvent(new Event("change"));
        }""")
    _changed_to(browser, SLIDER + "display: {force: kN, moment: kN*m}\n")
    for text in (SLIDER + "display: {force: kN}\n", SLIDER):
        browser.find_element(By.ID, "undo").click()
        _changed_to(browser, text)
