"""The page's background work in a real headless Chromium (the fixtures of
``test_web_browser.py``: one server and one browser for this module): the animation of
the motion downloaded as a GIF of one frame per position of the cycle, a short
parametric sweep whose table and plot appear when it is done, its values those the
library computes, and a simulation whose curves appear, then a long one cancelled."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import yaml
from PIL import Image
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import Select
from test_web_browser import (  # noqa: F401  (the fixtures: one server/browser here)
    EXAMPLES,
    SHOTS,
    WAIT,
    _downloaded,
    _open,
    _wait,
    browser,
    downloads,
    server,
)

from mechloop.model.load import model_from_data
from mechloop.solve.kinematics import solve

POSITIONS = 12


def _four_bar(folder: Path) -> str:
    """The four-bar example over 12 steps of one crank turn, saved in the served folder."""
    text = (EXAMPLES / "four_bar.yaml").read_text(encoding="utf-8") \
        .replace("positions: 72", f"positions: {POSITIONS}") \
        .replace("{0: 0, 72: 360}", f"{{0: 0, {POSITIONS}: 360}}")
    (folder / "four_bar_12.yaml").write_text(text, encoding="utf-8")
    return "four_bar_12.yaml"


def test_the_animation_downloads_as_a_gif_of_every_position(browser, server,  # noqa: F811
                                                            downloads):  # noqa: F811
    base, folder = server
    _open(browser, base + "/?path=" + _four_bar(folder))
    Select(browser.find_element(By.ID, "anim-format")).select_by_value("gif")
    browser.find_element(By.ID, "anim-download").click()
    gif = _downloaded(browser, downloads / "four_bar_12.gif", wait=2 * WAIT)
    image = Image.open(gif)
    # 13 positions 0..12 over one crank turn; the last repeats the first and is left out
    assert image.format == "GIF" and image.n_frames == POSITIONS
    _wait(browser, lambda d: "four_bar_12.gif" in d.find_element(By.ID, "status").text,
          "the status does not say the animation was downloaded")
    assert f"({POSITIONS} frames)" in browser.find_element(By.ID, "status").text
    assert not browser.find_element(By.ID, "anim-bar").is_displayed()


def test_a_sweep_shows_its_table_and_plot_when_done(browser, server):  # noqa: F811
    base, folder = server
    _open(browser, base + "/?path=" + _four_bar(folder))
    browser.find_element(By.ID, "sweep-vary").send_keys("vectors.1.r=80:120:3")
    browser.find_element(By.ID, "sweep-collect").send_keys("r7:max")
    browser.find_element(By.ID, "sweep-start").click()
    _wait(browser, lambda d: d.find_element(By.ID, "sweep-result").is_displayed(),
          "the sweep's result is not shown")
    head = [c.text for c in browser.find_elements(By.CSS_SELECTOR, "#sweep-table th")]
    assert head == ["vectors.1.r [mm]", "r7:max [m]", "broken positions"]
    rows = [[c.text for c in row.find_elements(By.TAG_NAME, "td")]
            for row in browser.find_elements(By.CSS_SELECTOR, "#sweep-table tbody tr")]
    assert [r[0] for r in rows] == ["80", "100", "120"]
    data = yaml.safe_load((folder / "four_bar_12.yaml").read_text(encoding="utf-8"))
    for row, length in zip(rows, (80, 100, 120), strict=True):
        data["vectors"][1]["r"] = length
        model = model_from_data(data, file=str(folder / "four_bar_12.yaml"))
        # the largest r7 over the 13 positions, as the library solves this design
        expected = solve(model).to_frame()["r7 [m]"].max()
        assert np.isclose(float(row[1]), expected, rtol=1e-5), (row, expected)
        assert row[2] == "0"
    assert browser.find_element(By.ID, "sweep-info").text == "3 designs, 0 with a chain break"
    assert browser.find_element(By.ID, "sweep-bar").get_property("value") == 1
    plot = browser.find_element(By.ID, "sweep-plot")
    assert plot.get_attribute("src").startswith("data:image/svg+xml")
    assert browser.execute_script("return arguments[0].naturalWidth", plot) > 100
    browser.execute_script("arguments[0].scrollIntoView()",
                           browser.find_element(By.ID, "sweep-result"))
    browser.save_screenshot(str(SHOTS / "web-sweep.png"))


def test_a_simulation_shows_its_curves_and_is_cancelled(browser, server):  # noqa: F811
    base, folder = server
    shutil.copy(EXAMPLES / "compressor_startup.yaml", folder / "compressor_startup.yaml")
    _open(browser, base + "/?path=compressor_startup.yaml")
    browser.find_element(By.ID, "sim-duration").send_keys("0.3")
    browser.find_element(By.ID, "sim-start").click()
    _wait(browser, lambda d: d.find_element(By.ID, "sim-result").is_displayed(),
          "the simulation's result is not shown")
    info = browser.find_element(By.ID, "sim-info").text
    assert info.startswith("0.3 s simulated"), info
    summary = browser.find_element(By.ID, "sim-summary").text
    assert "duration: t = 0.3 s" in summary  # the library's account of how the run ended
    plot = browser.find_element(By.ID, "sim-plot")
    assert browser.execute_script("return arguments[0].naturalWidth", plot) > 100
    # a long run, cancelled while it runs (not stopped at the steady cycle, which the
    # example reaches after 2.7 s simulated: the run could end before the click)
    browser.execute_script("const e = document.getElementById('editor');"
                           "e.value = e.value.replace('until_steady: true',"
                           " 'until_steady: false'); e.dispatchEvent(new Event('input'));")
    field = browser.find_element(By.ID, "sim-duration")
    field.clear()
    field.send_keys("300")
    browser.find_element(By.ID, "sim-start").click()
    _wait(browser, lambda d: " s of 300 s simulated" in d.find_element(By.ID, "sim-info").text,
          "no progress of the simulation is shown")
    assert 0 < browser.find_element(By.ID, "sim-bar").get_property("value") < 1
    browser.find_element(By.ID, "sim-cancel").click()
    _wait(browser, lambda d: d.find_element(By.ID, "sim-info").text == "cancelled",
          "the simulation was not cancelled")
    assert browser.find_element(By.ID, "sim-start").is_enabled()
