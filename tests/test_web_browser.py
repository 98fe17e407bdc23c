"""The web application in a real headless Chromium (Debian's ``chromium`` and
``chromium-driver``, installed by the README's test command; never skipped): load a
model, type a new length and see the diagram and the plotted value become the numbers the
API gives, type a YAML error and see it at its line, move the slider, play the cycle, see
a chain break, switch to Russian, download the report.  The screenshots of docs/web.md
(and of the README's tour) are made here (``docs/screenshots/``)."""

from __future__ import annotations

import itertools
import json
import re
import shutil
import threading
import time
import urllib.request
from pathlib import Path

import numpy as np
import pytest
import uvicorn
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select, WebDriverWait

from mechloop.web.app import create_app
from mechloop.web.serve import free_port
from mechloop.web.worker import warm_up

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
SHOTS = ROOT / "docs" / "screenshots"
CHROMIUM = Path("/usr/bin/chromium")
DRIVER = Path("/usr/bin/chromedriver")
WAIT = 30  # s, the longest a step may take (a solve under load)
REPORT_WAIT = 120  # s, the longest the report may take (under load)


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    folder = tmp_path_factory.mktemp("served")
    shutil.copy(EXAMPLES / "crank_slider.yaml", folder / "crank_slider.yaml")
    warm_up().join()  # the solves' fork server, ready before the first page
    port = free_port()
    config = uvicorn.Config(create_app(folder, hosts=["127.0.0.1"]), host="127.0.0.1",
                            port=port, log_level="warning")
    running = uvicorn.Server(config)
    thread = threading.Thread(target=running.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + WAIT
    while not running.started:
        assert thread.is_alive() and time.monotonic() < deadline, "the server did not start"
        time.sleep(0.02)
    yield f"http://127.0.0.1:{port}", folder
    running.should_exit = True
    thread.join(10)


@pytest.fixture(scope="module")
def downloads(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("downloads")


@pytest.fixture(scope="module")
def browser(downloads):
    assert CHROMIUM.exists() and DRIVER.exists(), (
        "the browser tests need Debian's chromium and chromium-driver: "
        "apt-get update && apt-get install -y chromium chromium-driver")
    options = webdriver.ChromeOptions()
    options.binary_location = str(CHROMIUM)
    for argument in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage",
                     "--window-size=1320,1040", "--lang=en-US", "--disable-gpu"):
        options.add_argument(argument)
    options.add_experimental_option("prefs", {"download.default_directory": str(downloads),
                                              "download.prompt_for_download": False})
    driver = webdriver.Chrome(service=Service(str(DRIVER)), options=options)
    driver.execute_cdp_cmd("Browser.setDownloadBehavior",
                           {"behavior": "allow", "downloadPath": str(downloads)})
    yield driver
    driver.quit()


def _post(base: str, path: str, data: dict) -> dict:
    request = urllib.request.Request(base + path, data=json.dumps(data).encode(),
                                     headers={"content-type": "application/json"})
    with urllib.request.urlopen(request, timeout=WAIT) as answer:
        return json.loads(answer.read())


def _wait(driver, condition, message: str):
    return WebDriverWait(driver, WAIT).until(lambda d: condition(d), message)


def _solved(driver) -> str:
    return driver.execute_script("return document.body.dataset.solved || ''")


def _fresh(driver, base: str, path: str) -> None:
    """Discard the working copies of ``path`` (the server's and the page's) that earlier
    edits left, so the page opens the file itself."""
    _post(base, "/api/autosave/clear", {"path": path})
    driver.get(base + "/")
    driver.execute_script("window.localStorage.clear()")


def _open(driver, url: str) -> None:
    driver.get(url)
    _wait(driver, _solved, "the model was not solved")


def _replace(driver, line: int, old: str, new: str) -> None:
    """Select ``old`` on ``line`` of the editor and type ``new`` over it (real key
    presses), then wait for the page to have checked the new text."""
    editor = driver.find_element(By.ID, "editor")
    editor.click()
    found = driver.execute_script("""
        const [line, old] = arguments; const e = document.getElementById('editor');
        const lines = e.value.split('\\n');
        const at = lines[line - 1].indexOf(old); if (at < 0) return false;
        const start = lines.slice(0, line - 1).reduce((s, l) => s + l.length + 1, 0) + at;
        e.setSelectionRange(start, start + old.length); return true;""", line, old)
    assert found, f"{old!r} is not on line {line}"
    editor.send_keys(new)


def _line_of(text: str, start: str) -> int:
    return next(i for i, line in enumerate(text.splitlines(), 1) if line.startswith(start))


def _vector(driver, number: int) -> tuple[float, ...]:
    """The drawn vector's tail and head, read in one script (the page may redraw the
    diagram between two reads of an element: a drag's checks run one after another)."""
    values = driver.execute_script(
        "const line = document.getElementById(arguments[0]);"
        "return line && ['x1', 'y1', 'x2', 'y2'].map((k) => line.dataset[k]);",
        f"vector-{number}")
    if values is None:
        raise AssertionError(f"vector {number} is not drawn")
    return tuple(float(v) for v in values)


def _position(driver) -> int:
    return int(driver.find_element(By.ID, "slider").get_attribute("value"))


def test_a_new_length_moves_the_diagram_and_the_plot_to_the_apis_numbers(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    Select(browser.find_element(By.ID, "plot-select")).select_by_value("r3")
    slider = browser.find_element(By.ID, "slider")
    slider.click()  # the middle of the range
    slider.send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * 9)
    assert _position(browser) == 9
    before = _vector(browser, 2)
    marker = float(browser.find_element(By.ID, "plot-marker").get_attribute("data-value"))
    text = browser.find_element(By.ID, "editor").get_property("value")
    solved = _solved(browser)
    _replace(browser, _line_of(text, "  2: {r: 0.2,"), "0.2", "0.26")
    _wait(browser, lambda d: _solved(d) != solved, "the new length was not solved")
    edited = browser.find_element(By.ID, "editor").get_property("value")
    assert "2: {r: 0.26," in edited
    api = _post(base, "/api/solve", {"path": "crank_slider.yaml", "text": edited})
    rod = next(v for v in api["diagram"]["vectors"] if v["number"] == 2)
    expected = (rod["tail"]["x"][9], rod["tail"]["y"][9], rod["head"]["x"][9],
                rod["head"]["y"][9])
    after = _vector(browser, 2)
    assert after == pytest.approx(expected, rel=1e-12, abs=1e-15)
    assert after != pytest.approx(before)
    r3 = next(c for c in api["columns"] if c["name"] == "r3")["values"][9]
    shown = float(browser.find_element(By.ID, "plot-marker").get_attribute("data-value"))
    assert shown == pytest.approx(r3, rel=1e-12) and shown != pytest.approx(marker)
    row = browser.find_element(By.CSS_SELECTOR, "#results tr[data-name='r3'] td.number")
    assert float(row.text) == pytest.approx(r3, rel=1e-5)
    assert "position 9 of 0..72" in browser.find_element(By.ID, "position-label").text


def test_a_yaml_error_is_shown_at_its_line_with_the_fix(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    text = browser.find_element(By.ID, "editor").get_property("value")
    line = _line_of(text, "positions: 72")
    _replace(browser, line, "72", "many")
    item = _wait(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#problems li.problem"),
                 "no problem was listed")[0]
    assert item.get_attribute("data-line") == str(line)
    assert f"line {line}" in item.text and "positions" in item.text
    assert "fix:" in item.find_element(By.CLASS_NAME, "hint").text
    gutter = browser.find_element(By.CSS_SELECTOR, f"#gutter span[data-line='{line}']")
    assert "bad" in gutter.get_attribute("class")
    _replace(browser, line, "many", "72")
    _wait(browser, lambda d: d.find_elements(By.CSS_SELECTOR, "#problems li.ok"),
          "the fixed model still shows problems")


def test_play_runs_the_cycle_in_a_loop_and_pauses(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    browser.find_element(By.ID, "play").click()
    seen: list[int] = []

    def wrapped(driver) -> bool:
        seen.append(_position(driver))
        return max(seen) >= 60 and seen[-1] < max(seen)  # came round to the start

    _wait(browser, wrapped, "the animation did not loop")
    browser.find_element(By.ID, "play").click()
    stopped = _position(browser)
    first = _vector(browser, 1)
    assert browser.execute_script("return state.timer") is None
    assert _position(browser) == stopped and _vector(browser, 1) == first


def test_a_chain_break_is_shown_where_it_occurs(browser, server):
    base, _ = server
    _open(browser, base + "/?example=four_bar_break_ahead")
    api = _post(base, "/api/solve", {"example": "four_bar_break_ahead", "text": browser.
                                     find_element(By.ID, "editor").get_property("value")})
    broken = api["broken"].index(True)
    note = browser.find_element(By.ID, "break-note")
    assert not note.is_displayed()
    browser.find_element(By.ID, "slider").send_keys(Keys.HOME,
                                                    *[Keys.ARROW_RIGHT] * broken)
    _wait(browser, lambda d: note.is_displayed(), "no break shown")
    assert f"chain break at position {broken}" in note.text
    assert api["breaks"][0]["reason"] in note.text


def test_russian_and_english_screens_and_the_report(browser, server, downloads):
    base, _ = server
    _fresh(browser, base, "crank_slider.yaml")  # no working copy left by the tests above
    _open(browser, base + "/?path=crank_slider.yaml&lang=en")
    browser.find_element(By.ID, "slider").send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * 12)
    assert not browser.find_element(By.ID, "restore-bar").is_displayed()
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-en.png"))
    browser.find_element(By.ID, "lang-ru").click()
    headings = [h.text for h in browser.find_elements(By.CSS_SELECTOR, "[data-i18n]")]
    assert "Механизм" in headings and "Сохранить" in headings and "Пуск" in headings
    assert not [h for h in headings if any("a" <= c.lower() <= "z" for c in h)
                and h not in ("Отчёт (PDF)", "Модель (YAML)")], headings
    assert "положение 12 из 0..72" in browser.find_element(By.ID, "position-label").text
    assert "r3, м" in browser.find_element(By.ID, "plot-select").text
    assert browser.find_element(By.ID, "status").text == "рассчитано"
    row = browser.find_element(By.CSS_SELECTOR, "#results tr[data-name='time']")
    assert row.text.split() == ["время", "0,00333333", "с"]  # 12 of 72 at 3000 rpm, GOST
    browser.save_screenshot(str(SHOTS / "web-ru.png"))
    browser.find_element(By.ID, "lang-en").click()
    assert browser.find_element(By.ID, "play").text == "Play"
    browser.find_element(By.ID, "report").click()
    target = downloads / "crank_slider-en.pdf"
    WebDriverWait(browser, REPORT_WAIT).until(
        lambda d: target.exists() and target.stat().st_size > 0, "no report downloaded")
    assert target.read_bytes().startswith(b"%PDF")


def test_save_writes_the_editors_text_inside_the_folder_only(browser, server):
    base, folder = server
    _open(browser, base + "/?path=crank_slider.yaml")
    name = browser.find_element(By.ID, "save-path")
    for target, saved in (("../outside.yaml", False), ("copy.yaml", True)):
        name.clear()
        name.send_keys(target)
        browser.find_element(By.ID, "save").click()
        kind = "ok" if saved else "error"
        _wait(browser, lambda d, kind=kind: d.find_element(By.ID, "status")
              .get_attribute("class") == kind, f"saving {target} did not end in {kind}")
    assert not (folder.parent / "outside.yaml").exists()
    text = browser.find_element(By.ID, "editor").get_property("value")
    assert (folder / "copy.yaml").read_text(encoding="utf-8") == text
    assert browser.find_element(By.ID, "status").text == "saved copy.yaml"
    assert Select(browser.find_element(By.ID, "model-select")).first_selected_option \
        .get_attribute("value") == "path:copy.yaml"


def _downloaded(driver, path: Path, wait: float = WAIT) -> Path:
    """``path`` once the browser has finished writing it."""
    WebDriverWait(driver, wait).until(
        lambda d: path.exists() and path.stat().st_size > 0
        and not path.with_name(path.name + ".crdownload").exists(), f"no {path.name}")
    return path


def test_the_structure_panel_and_every_download(browser, server, downloads):
    import pandas as pd
    from docx import Document as DocxDocument

    base, _ = server
    _open(browser, base + "/?example=crank_slider_dynamics&lang=en")
    text = browser.find_element(By.ID, "editor").get_property("value")
    source = {"example": "crank_slider_dynamics", "text": text}
    api = _post(base, "/api/structure", source)["mechanism"]
    formula = _wait(browser, lambda d: d.find_elements(By.ID, "structure-formula"),
                    "no structure shown")[0]
    assert formula.text == f"structure formula: {api['formula']}" \
        == "structure formula: L0(1) → L2(2,3)"
    rows = browser.find_elements(By.CSS_SELECTOR, "#structure-groups tbody tr")
    assert [r.get_attribute("data-label") for r in rows] == \
        [g["label"] for g in api["groups"]]
    assert "W = 3·3 − 2·4 − 0 = 1" in browser.find_element(By.ID, "structure").text
    browser.find_element(By.ID, "lang-ru").click()
    assert browser.find_element(By.ID, "structure-formula").text == \
        "формула строения: L0(1) → L2(2,3)"
    assert "Звенья" in browser.find_element(By.ID, "structure-groups").text
    browser.find_element(By.ID, "lang-en").click()

    solved = _post(base, "/api/solve", source)
    r3 = next(c for c in solved["columns"] if c["name"] == "r3")
    Select(browser.find_element(By.ID, "table-format")).select_by_value("xlsx")
    browser.find_element(By.ID, "table-download").click()
    table = pd.read_excel(_downloaded(browser, downloads / "crank_slider_dynamics.xlsx"))
    assert table[f"r3 [{r3['unit']}]"].to_numpy() == pytest.approx(r3["values"], rel=1e-12)

    Select(browser.find_element(By.ID, "plot-select")).select_by_value("r3")
    Select(browser.find_element(By.ID, "figure-format")).select_by_value("svg")
    browser.find_element(By.ID, "figure-download").click()
    svg = _downloaded(browser, downloads / "crank_slider_dynamics-r3.svg").read_text()
    assert "<!-- r3 [m] -->" in svg and "<!-- position -->" in svg

    browser.find_element(By.ID, "model-download").click()
    model = _downloaded(browser, downloads / "crank_slider_dynamics.yaml")
    assert model.read_text(encoding="utf-8") == text

    Select(browser.find_element(By.ID, "report-format")).select_by_value("docx")
    browser.find_element(By.ID, "report").click()
    docx = _downloaded(browser, downloads / "crank_slider_dynamics-en.docx", REPORT_WAIT)
    assert any(p.style.name.startswith("Heading") for p in DocxDocument(docx).paragraphs)
    assert browser.find_element(By.ID, "status").text == "report downloaded"
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-structure.png"))


def test_up_to_six_curves_one_axis_per_unit_follow_the_slider(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml&lang=en")
    text = browser.find_element(By.ID, "editor").get_property("value")
    api = {c["name"]: c for c in _post(base, "/api/solve", {"path": "crank_slider.yaml",
                                                            "text": text})["columns"]}
    Select(browser.find_element(By.ID, "plot-select")).select_by_value("r3")
    for name in ("dr3", "a2", "ddr3"):
        Select(browser.find_element(By.ID, "plot-add")).select_by_value(name)
    axes = browser.find_elements(By.CSS_SELECTOR, "#plot g.y-axis")
    assert [a.get_attribute("data-unit") for a in axes] == \
        [api[n]["unit"] for n in ("r3", "dr3", "a2", "ddr3")] == ["m", "m/s", "deg", "m/s^2"]
    for k in (0, 7, 30):
        browser.find_element(By.ID, "slider").send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * k)
        markers = browser.find_elements(By.CSS_SELECTOR, "#plot circle.marker")
        shown = {m.get_attribute("data-name"): float(m.get_attribute("data-value"))
                 for m in markers}
        assert shown == pytest.approx({n: api[n]["values"][k]
                                       for n in ("r3", "dr3", "a2", "ddr3")}, rel=1e-12)
        assert all(m.get_attribute("data-position") == str(k) for m in markers)
    assert browser.find_element(By.ID, "plot-marker").get_attribute("data-name") == "r3"
    for name in ("da2", "dda2"):
        Select(browser.find_element(By.ID, "plot-add")).select_by_value(name)
    assert len(browser.find_elements(By.CSS_SELECTOR, "#plot path.curve")) == 6
    assert not browser.find_element(By.ID, "plot-add").is_enabled()  # six at most
    assert len(browser.find_elements(By.CSS_SELECTOR, "#plot g.y-axis")) == 6
    browser.find_element(By.CSS_SELECTOR, ".curve-chip[data-name='a2']").click()
    assert [c.get_attribute("data-name") for c in browser.find_elements(
        By.CSS_SELECTOR, "#plot path.curve")] == ["r3", "dr3", "ddr3", "da2", "dda2"]
    assert browser.find_element(By.ID, "plot-add").is_enabled()
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-curves.png"))


def _path_points(driver, element_id: str) -> list[tuple[float, float]]:
    d = driver.find_element(By.ID, element_id).get_attribute("d")
    return [tuple(map(float, pair.split(","))) for pair in re.findall(r"[ML]([^ ]+)", d)]


def test_trajectories_and_all_positions_on_the_mechanism(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml&lang=en")
    assert not browser.find_elements(By.CSS_SELECTOR, "#diagram path.overlay")
    browser.find_element(By.ID, "overlay").click()
    faint = browser.find_elements(By.CSS_SELECTOR, "#diagram path.overlay")
    assert [p.get_attribute("data-vector") for p in faint] == ["1", "2", "3", "4"]
    rod = faint[1].get_attribute("d")
    assert rod.count("M") == 73  # the rod at every position of 0..72
    for key in ("head:1", "head:2"):
        Select(browser.find_element(By.ID, "trace-add")).select_by_value(key)
    crank = _path_points(browser, "trajectory-head-1")
    assert len(crank) == 73
    for k in (0, 11, 40):
        browser.find_element(By.ID, "slider").send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * k)
        line = browser.find_element(By.ID, "vector-1")
        head = (float(line.get_attribute("x2")), float(line.get_attribute("y2")))
        assert crank[k] == pytest.approx(head, abs=1e-9)  # the drawn head is on it
    # the crank's head runs on a circle of r1 = 0.05 m round O (the tail of vector 1)
    line = browser.find_element(By.ID, "vector-1")
    centre = np.array([float(line.get_attribute("x1")), float(line.get_attribute("y1"))])
    scale = np.hypot(*(np.array([float(line.get_attribute("x2")),
                                 float(line.get_attribute("y2"))]) - centre)) / 0.05
    radii = np.hypot(*(np.array(crank) - centre).T) / scale
    assert radii == pytest.approx(np.full(73, 0.05), rel=1e-9)
    # the rod's head, the slider pin B, moves on the guide: y = -r4 = -0.01 m
    pin = np.array(_path_points(browser, "trajectory-head-2"))
    assert (pin[:, 1] - centre[1]) / scale == pytest.approx(np.full(73, 0.01), rel=1e-9)
    browser.find_element(By.ID, "lang-ru").click()
    chips = [c.text for c in browser.find_elements(By.CSS_SELECTOR, "#traces button")]
    assert chips == ["конец вектора 1 ✕", "конец вектора 2 ✕"]
    browser.find_element(By.CSS_SELECTOR, "#traces button[data-key='head:1']").click()
    assert not browser.find_elements(By.ID, "trajectory-head-1")
    assert browser.find_elements(By.ID, "trajectory-head-2")
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-trajectories.png"))
    browser.find_element(By.ID, "lang-en").click()


def test_play_modes_step_by_step_backward_and_faster(browser, server):
    base, _ = server
    _open(browser, base + "/?path=crank_slider.yaml")
    count = browser.execute_script("return state.solution.count")
    browser.find_element(By.ID, "step-forward").click()
    browser.find_element(By.ID, "step-forward").click()
    assert _position(browser) == 2
    for _ in range(3):
        browser.find_element(By.ID, "step-back").click()
    assert _position(browser) == count - 1  # frame by frame, round the cycle
    Select(browser.find_element(By.ID, "play-direction")).select_by_value("-1")
    Select(browser.find_element(By.ID, "play-speed")).select_by_value("4")
    browser.find_element(By.ID, "play").click()
    assert browser.execute_script("return state.timer") is not None
    # the positions the page shows, read at every animation frame until eight differ
    seen = browser.execute_async_script("""
        const done = arguments[arguments.length - 1]; const seen = [];
        function look() {
          const k = state.position;
          if (!seen.length || seen[seen.length - 1] !== k) seen.push(k);
          if (seen.length >= 8) done(seen); else requestAnimationFrame(look);
        }
        requestAnimationFrame(look);""")
    browser.find_element(By.ID, "step-forward").click()  # a step pauses the play
    assert browser.execute_script("return state.timer") is None
    steps = [(a - b) % count for a, b in itertools.pairwise(seen)]
    assert all(0 < s < count // 2 for s in steps), (seen, count)  # backward, round
    assert browser.find_element(By.ID, "step-back").get_attribute("title") == \
        "one position back"


def test_a_synthesis_shows_progress_and_its_best_is_kept_on_cancel(browser, server):
    base, _ = server
    _open(browser, base + "/?example=four_bar_path_synthesis")
    browser.find_element(By.ID, "job-start").click()
    _wait(browser, lambda d: float(d.find_element(By.ID, "job-bar").get_attribute("value"))
          > 0 and d.find_elements(By.ID, "best-vector-1"), "no progress shown")
    assert browser.find_element(By.ID, "job-diagram").is_displayed()
    assert "generation" in browser.find_element(By.ID, "job-info").text
    browser.find_element(By.ID, "job-cancel").click()
    _wait(browser, lambda d: d.execute_script("return document.body.dataset.job || ''"),
          "the job did not finish after the cancel")
    job = browser.execute_script("return job.id")
    with urllib.request.urlopen(f"{base}/api/jobs/{job}", timeout=WAIT) as answer:
        status = json.loads(answer.read())
    result = status["result"]
    assert status["state"] == "done" and result["stopped"] == "interrupted"
    info = browser.find_element(By.ID, "job-info").text
    assert info.startswith("done (cancelled)")
    if result["feasible"]:
        shown = float(browser.find_element(By.ID, "job-bar").get_attribute("data-best"))
        assert shown == result["best"]
    else:
        assert "no feasible design" in info
    browser.execute_script("document.getElementById('view-kind').scrollIntoView()")
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-synthesis.png"))
    browser.find_element(By.ID, "job-open").click()
    _wait(browser, lambda d: d.find_element(By.ID, "editor").get_attribute("value")
          == result["text"], "the result did not open in the editor")
    assert browser.find_element(By.ID, "save-path").get_attribute("value") == \
        "four_bar_path_synthesis_synthesized.yaml"
    _wait(browser, lambda d: "solved" in d.find_element(By.ID, "status").text,
          "the synthesized model was not solved")
    browser.find_element(By.ID, "lang-ru").click()
    assert browser.find_element(By.ID, "job-info").text.startswith("готово (прервано)")
    browser.find_element(By.ID, "lang-en").click()
