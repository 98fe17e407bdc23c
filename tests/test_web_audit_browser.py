"""What the issue-16 audit fixed, in a real headless Chromium (the fixtures of
``test_web_browser.py``): the page's numbers in Russian with the decimal comma (checked
against the library's own conversion, :func:`mechloop.views.decimal_mark.localized`) and
read back from a typed ``0,06``; KDAM's play modes (one cycle stops, back and forth
turns); the mechanism following a drag while the pointer still moves; the structure in the
page's language after a switch.  The screenshot ``docs/screenshots/web-russian.png`` is
made here."""

from __future__ import annotations

import pytest
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select
from test_web_browser import SHOTS, _open, _post, _solved, _wait, browser, downloads, server

from mechloop.views.decimal_mark import localized

__all__ = ["browser", "downloads", "server"]  # the fixtures, shared

#: Numbers of every form the page writes: plain, rounded, exponent small and large.
SAMPLES = [0.05, -78.63821, 314.159265, 2.5e-5, -1.23456e-7, 1234567.0, 3e12, 0.001]


def _cells(driver) -> dict[str, str]:
    return driver.execute_script("""return Object.fromEntries([...document.querySelectorAll(
        '#results tbody tr')].map((r) => [r.dataset.name, r.cells[1].textContent]))""")


def test_russian_numbers_have_the_decimal_comma_and_typed_commas_are_read(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml&lang=en")
    browser.execute_script("setPosition(7)")
    english = _cells(browser)
    english_label = browser.find_element(By.ID, "position-label").text
    english_numbers = browser.execute_script(
        "return arguments[0].map((x) => mechloopNumber(x))", SAMPLES)
    browser.find_element(By.ID, "lang-ru").click()
    russian = _cells(browser)
    # the page writes each number as the library's Russian outputs do
    assert russian == {name: localized(text, "ru") for name, text in english.items()}
    assert russian["da1"] == "314,159" and english["da1"] == "314.159"
    api = _post(base, "/api/solve", {"path": "crank_slider.yaml",
                                     "text": browser.find_element(By.ID, "editor")
                                     .get_property("value")})
    a2 = next(c for c in api["columns"] if c["name"] == "a2")["values"][7]
    assert float(russian["a2"].replace(",", ".")) == pytest.approx(a2, rel=1e-5)
    assert browser.find_element(By.ID, "position-label").text.endswith(
        localized(english_label.split("t = ")[1], "ru").replace("s", "с"))
    legend = browser.find_element(By.CSS_SELECTOR, "#plot .legend").text
    assert "," in legend and "." not in legend.split("=")[1]
    russian_numbers = browser.execute_script(
        "return arguments[0].map((x) => mechloopNumber(x))", SAMPLES)
    assert russian_numbers == [localized(text, "ru") for text in english_numbers]
    assert russian_numbers[3] == "2,5·10⁻⁵" and english_numbers[3] == "2.5e-5"
    # what a user types: the point always, the comma and ·10⁻ⁿ in Russian
    typed = ["0,06", "-1,5e-3", "2,5·10⁻⁵", "0.5", "1 200,5", "1,2,3", "abc", ""]
    read = browser.execute_script(
        "return arguments[0].map((s) => { const x = mechloopParseNumber(s);"
        " return Number.isNaN(x) ? null : x; })", typed)
    assert read == [0.06, -1.5e-3, 2.5e-5, 0.5, 1200.5, None, None, None]

    browser.find_element(By.CSS_SELECTOR, "#form-tabs button[data-tab='vectors']").click()
    field = _wait(browser, lambda d: d.find_elements(
        By.CSS_SELECTOR, "#forms input[data-keys='[\"vectors\",1,\"r\"]']"), "no form")[0]
    assert field.get_property("value") == "0,05"
    contour = browser.find_element(By.CSS_SELECTOR,
                                   "#forms input[data-keys='[\"contours\",0,\"vectors\"]']")
    assert contour.get_property("value") == "1; 2; 3; 4"
    solved = _solved(browser)
    field.click()
    field.send_keys(Keys.CONTROL, "a")
    field.send_keys("0,06", Keys.TAB)
    _wait(browser, lambda d: "  1: {r: 0.06, a: {argument: 1}, name: crank}"
          in d.find_element(By.ID, "editor").get_property("value"), "0,06 was not written")
    _wait(browser, lambda d: _solved(d) != solved, "the new length was not solved")
    browser.find_element(By.CSS_SELECTOR, "#form-tabs button[data-tab='yaml']").click()
    browser.execute_script("document.getElementById('results').scrollIntoView(false)")
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-russian.png"))
    browser.find_element(By.ID, "lang-en").click()


def test_one_cycle_stops_at_its_end_and_back_and_forth_turns(browser, server):
    base, _ = server
    _open(browser, base + "/?example=crank_slider&lang=en")
    last = browser.execute_script("return state.solution.count - 1")
    Select(browser.find_element(By.ID, "play-speed")).select_by_value("4")
    Select(browser.find_element(By.ID, "play-mode")).select_by_value("once")
    browser.execute_script(f"setPosition({last - 5})")
    browser.find_element(By.ID, "play").click()
    _wait(browser, lambda d: d.execute_script("return state.timer === null"),
          "one cycle did not stop")
    assert browser.execute_script("return state.position") == last
    assert browser.find_element(By.ID, "play").text == "Play"
    browser.find_element(By.ID, "play").click()  # again from the end: the cycle anew
    assert browser.execute_script("return state.position") < last // 2
    browser.find_element(By.ID, "play").click()

    Select(browser.find_element(By.ID, "play-mode")).select_by_value("reflect")
    browser.execute_script(f"setPosition({last - 3})")
    browser.find_element(By.ID, "play").click()
    _wait(browser, lambda d: d.execute_script(
        "return document.getElementById('play-direction').value === '-1'"
        f" && state.position < {last - 4}"), "back and forth did not turn at the end")
    assert browser.execute_script("return state.timer") is not None  # it goes on
    browser.find_element(By.ID, "play").click()
    Select(browser.find_element(By.ID, "play-mode")).select_by_value("loop")
    Select(browser.find_element(By.ID, "play-direction")).select_by_value("1")
    Select(browser.find_element(By.ID, "play-speed")).select_by_value("1")


def test_the_mechanism_follows_a_drag_that_goes_on(browser, server):
    """A drag changes the text every moment (drag.js); the page solves and draws those
    texts while it goes on, not only once it stops."""
    base, _ = server
    _open(browser, base + "/?example=crank_slider&lang=en")
    browser.set_script_timeout(60)
    drawn, moves = browser.execute_async_script("""
        const done = arguments[arguments.length - 1];
        const base = mechloopEditor.getText();
        document.body.dataset.dragging = "1";
        let n = 0, drawn = 0, last = state.solution;
        const timer = setInterval(() => {
          n += 1;  // a new crank length every 100 ms: at least 2 s, until two are drawn
          mechloopEditor.setText(base.replace("{r: 0.05,", `{r: ${0.05 + n / 20000},`),
            { record: n === 1 });
          if (state.solution !== last) { drawn += 1; last = state.solution; }
          if ((n >= 20 && drawn >= 2) || n === 400) {  // (40 s: a loaded machine)
            clearInterval(timer);
            delete document.body.dataset.dragging;
            done([drawn, n]);
          }
        }, 100);""")
    assert drawn >= 2  # solved and drawn while the text kept changing
    tail = browser.execute_script("return state.solution.diagram.vectors[0].head.x[0]")
    assert 0.05 < tail <= 0.05 + moves / 20000 + 1e-12


def test_the_structure_follows_the_language(browser, server):
    base, _ = server
    _open(browser, base + "/?example=crank_slider_dynamics&lang=en")
    panel = _wait(browser, lambda d: d.find_elements(By.ID, "structure-formula"),
                  "no structure")[0].find_element(By.XPATH, "..")
    assert "planar" in panel.text
    browser.find_element(By.ID, "lang-ru").click()
    text = browser.find_element(By.ID, "structure").text
    assert "плоская" in text and "planar" not in text
    browser.find_element(By.ID, "lang-en").click()


def test_at_a_chain_break_the_nearest_closed_position_is_drawn_faded(browser, server):
    """Not a blank diagram: the mechanism where it last closes, faded, said in the note,
    with its handles (a drag can bring the chain back)."""
    base, _ = server
    _open(browser, base + "/?example=four_bar_break_ahead&lang=en")
    api = _post(base, "/api/solve", {"example": "four_bar_break_ahead", "text": browser.
                                     find_element(By.ID, "editor").get_property("value")})
    first = api["broken"].index(True)  # broken from here (the crank cannot turn on)
    browser.execute_script(f"setPosition({first + 1})")
    diagram = browser.find_element(By.ID, "diagram")
    assert "faded" in diagram.get_attribute("class")
    assert diagram.get_attribute("data-shown") == str(first - 1)
    crank = next(v for v in api["diagram"]["vectors"] if v["number"] == 1)
    line = browser.find_element(By.ID, "vector-1")
    assert float(line.get_attribute("data-x2")) == crank["head"]["x"][first - 1]
    assert browser.find_elements(By.CSS_SELECTOR, "#diagram .drag-handle")
    assert f"faded at position {first - 1}" in browser.find_element(By.ID, "break-note").text
    browser.find_element(By.ID, "lang-ru").click()  # the reason in the page's language
    assert api["breaks"][0]["reason_ru"] in browser.find_element(By.ID, "break-note").text
    assert "неравенство треугольника" in api["breaks"][0]["reason_ru"]
    browser.find_element(By.ID, "lang-en").click()
    browser.execute_script(f"setPosition({first - 1})")
    assert "faded" not in diagram.get_attribute("class")
