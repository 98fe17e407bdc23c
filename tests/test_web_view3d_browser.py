"""The interactive 3-D view of a spatial model (``static/view3d.js``) in a real headless
Chromium (the fixtures of ``test_web_browser.py``): in the HTML file of ``mechloop animate``
the drawn joints, at any viewing angles and position, are the solver's points projected
as matplotlib projects them (its Axes3D with ``proj_type="ortho"``, Y up: one scale and
an offset, nothing else) and as the NumPy orthographic projection on the screen axes
``u = (cos a, 0, −sin a)``, ``v = w × u``; the three projection buttons show XY, ZY, XZ; a
mouse drag turns the view; a chain break is said and its vectors left out.  On the page of
``mechloop serve`` a spatial model is drawn by the same view, which the position slider
moves to the API's coordinates.  The README's screenshot of the 3-D view is made here."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import numpy as np
import pytest
import yaml
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d import proj3d
from selenium.webdriver.common.action_chains import ActionChains
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

import mechloop
from mechloop.views.spatial_html import write_spatial_html
from mechloop.views.spatial_plan import _all_points, joints, scene_box, spatial_scene

SPATIAL = EXAMPLES / "spatial"

READ_JOINTS = """
return [...document.querySelectorAll('#view circle.joint3d, #view3d circle.joint3d')].map(
  (c) => [Number(c.getAttribute('cx')), Number(c.getAttribute('cy')),
          Number(c.dataset.x), Number(c.dataset.y), Number(c.dataset.z)]);"""


def numpy_axes(elev: float, azim: float) -> tuple[np.ndarray, np.ndarray]:
    """The screen's right and up as matplotlib's ``_view_axes`` makes them for Y up: the
    eye along ``w``, ``u = Y × w`` normalized, ``v = w × u``."""
    e, a = np.radians(elev), np.radians(azim)
    w = np.array([np.cos(e) * np.sin(a), np.sin(e), np.cos(e) * np.cos(a)])
    u = np.cross([0.0, 1.0, 0.0], w)
    u /= np.linalg.norm(u)
    return u, np.cross(w, u)


def matplotlib_projection(points: np.ndarray, box: np.ndarray, elev: float, azim: float
                          ) -> np.ndarray:
    """``points`` (J, 3) projected by matplotlib's 3-D axes set up as the static plan's
    (limits, equal scale, Y up) in its orthographic projection: (J, 2)."""
    ax = Figure().add_subplot(projection="3d", proj_type="ortho")
    ax.set_xlim(*box[0])
    ax.set_ylim(*box[1])
    ax.set_zlim(*box[2])
    ax.view_init(elev=elev, azim=azim, vertical_axis="y")
    ax.set_box_aspect(tuple(np.ptp(box, axis=1)))
    xs, ys, _ = proj3d.proj_transform(*points.T, ax.get_proj())
    return np.stack([xs, ys], axis=1)


def fit_residual(pixels: np.ndarray, plane: np.ndarray) -> float:
    """The largest distance (relative to the drawing's extent) between the drawn pixels
    and ``offset + s (x, −y)`` of the ``plane`` points, one scale ``s`` fitted."""
    flipped = plane * [1.0, -1.0]
    a = flipped - flipped.mean(axis=0)
    b = pixels - pixels.mean(axis=0)
    s = float((a * b).sum() / (a * a).sum())
    assert s > 0  # not mirrored
    return float(np.abs(s * a - b).max() / np.abs(b).max())


@pytest.fixture(scope="module")
def view_file(tmp_path_factory) -> tuple[Path, object]:
    """The HTML file of the RSSR with a short coupler (the chain breaks over part of the
    turn), 24 positions, and its solved results."""
    folder = tmp_path_factory.mktemp("view3d")
    data = yaml.safe_load((SPATIAL / "rssr.yaml").read_text(encoding="utf-8"))
    data["positions"] = 24
    data["arguments"][1] = {"table": {0: 0, 24: 360}}
    data["vectors"][2]["r"] = 80
    model = folder / "rssr_short.yaml"
    model.write_text(yaml.safe_dump(data), encoding="utf-8")
    results = mechloop.solve(mechloop.load_model(model))
    return write_spatial_html(results, folder / "view.html", lang="en"), results


def test_the_drawn_joints_are_matplotlibs_projection_and_a_drag_turns_the_view(
        browser, view_file):  # noqa: F811
    path, results = view_file
    browser.get(path.as_uri())
    view = _wait(browser, lambda d: d.execute_script(
        "return window.mechloopView3d && window.mechloopView3d.view()"), "no 3-D view")
    assert (view["elev"], view["azim"]) == (20, 30)  # the static plan's default angles
    scene = spatial_scene(results)
    box = scene_box(_all_points(scene))
    broken = np.flatnonzero(results.broken)
    fine = np.flatnonzero(~np.asarray(results.broken))
    assert broken.size and fine.size
    for elev, azim, k in ((20.0, 30.0, int(fine[0])), (-35.0, 130.0, int(fine[-1])),
                          (75.0, -60.0, int(fine[len(fine) // 2]))):
        browser.execute_script("mechloopView3d.setView(arguments[0], arguments[1]);"
                               "mechloopPlayer.show(arguments[2]);", elev, azim, k)
        drawn = np.array(browser.execute_script(READ_JOINTS))
        expected = joints(scene, k)
        assert len(drawn) == len(expected) == 4  # O, A, B, D
        # the drawn points are the solver's joints (to the file's rounding)
        order = [int(np.argmin(np.abs(drawn[:, 2:] - p).max(axis=1))) for p in expected]
        drawn = drawn[order]
        np.testing.assert_allclose(drawn[:, 2:], expected, rtol=0, atol=1e-6)
        # the hook's screen coordinates: the NumPy orthographic projection
        u, v = numpy_axes(elev, azim)
        seen = np.array([[p["right"], p["up"]] for p in (browser.execute_script(
            "return mechloopView3d.project(arguments[0])", list(q)) for q in drawn[:, 2:])])
        np.testing.assert_allclose(seen, drawn[:, 2:] @ np.stack([u, v], axis=1),
                                   rtol=1e-12, atol=1e-12 * np.abs(expected).max())
        # the drawn pixels: matplotlib's projection, up to one scale and an offset
        plane = matplotlib_projection(drawn[:, 2:], box, elev, azim)
        assert fit_residual(drawn[:, :2], plane) < 1e-6
    # the projection buttons: the static figure's panels (x→ y↑, z→ y↑, x→ z↑)
    k = int(fine[0])
    for button, (h, w) in (("xy", (0, 1)), ("zy", (2, 1)), ("xz", (0, 2))):
        browser.find_element(By.CSS_SELECTOR, f"button[data-view3d='{button}']").click()
        drawn = np.array(browser.execute_script(READ_JOINTS))
        assert fit_residual(drawn[:, :2], drawn[:, 2:][:, [h, w]]) < 1e-9, button
    # a mouse drag turns it: 72 px right (−18° of azimuth), 48 px down (+18° of elevation)
    browser.find_element(By.CSS_SELECTOR, "button[data-view3d='reset']").click()
    before = np.array(browser.execute_script(READ_JOINTS))
    svg = browser.find_element(By.CSS_SELECTOR, "#view svg")
    ActionChains(browser).move_to_element(svg).click_and_hold().move_by_offset(72, 48)\
        .release().perform()
    view = browser.execute_script("return mechloopView3d.view()")
    assert view["azim"] == pytest.approx(30 - 18) and view["elev"] == pytest.approx(20 + 18)
    after = np.array(browser.execute_script(READ_JOINTS))
    assert np.abs(after[:, :2] - before[:, :2]).max() > 5  # pixels moved
    assert svg.get_attribute("data-azim") == str(view["azim"])
    # two fingers moved apart zoom in by the ratio of their distances
    zoom = browser.execute_script("""
        const svg = document.querySelector('#view svg'), box = svg.getBoundingClientRect();
        const at = (type, id, x) => svg.dispatchEvent(new PointerEvent(type, {pointerId: id,
          clientX: box.left + x, clientY: box.top + 200, pointerType: 'touch',
          bubbles: true, isPrimary: id === 1}));
        at('pointerdown', 1, 300); at('pointerdown', 2, 400); at('pointermove', 2, 500);
        at('pointerup', 2, 500); at('pointerup', 1, 300);
        return mechloopView3d.view().zoom;""")
    assert zoom == pytest.approx(2.0)
    # a chain break: said, and the vectors of the broken loop not drawn
    browser.execute_script("mechloopPlayer.show(arguments[0])", int(broken[0]))
    note = browser.find_element(By.ID, "break-note")
    assert note.is_displayed() and f"chain break at position {broken[0]}" in note.text
    assert not browser.find_elements(By.ID, "v3-vector-2")
    browser.execute_script("mechloopPlayer.show(arguments[0])", k)
    assert browser.find_elements(By.ID, "v3-vector-2") and not note.is_displayed()


def test_the_page_draws_a_spatial_model_in_3d_and_the_slider_moves_it(
        browser, server):  # noqa: F811
    base, folder = server
    shutil.copy(SPATIAL / "rssr.yaml", folder / "rssr.yaml")
    _open(browser, base + "/?path=rssr.yaml&lang=en")
    assert browser.find_element(By.ID, "view3d").is_displayed()
    assert not browser.find_element(By.ID, "diagram").is_displayed()
    text = browser.find_element(By.ID, "editor").get_property("value")
    api = _post(base, "/api/solve", {"path": "rssr.yaml", "text": text})
    assert api["diagram"]["spatial"] is True

    def api_joints(k: int) -> np.ndarray:
        ends = [(e["x"][k], e["y"][k], e["z"][k]) for v in api["diagram"]["vectors"]
                for e in (v["tail"], v["head"])]
        return np.unique(np.round(np.array(ends), 9), axis=0)

    before = np.array(browser.execute_script(READ_JOINTS))
    browser.find_element(By.ID, "slider").send_keys(Keys.HOME, *[Keys.ARROW_RIGHT] * 9)
    _wait(browser, lambda d: d.find_element(By.CSS_SELECTOR, "#view3d svg")
          .get_attribute("data-position") == "9", "the slider did not move the 3-D view")
    after = np.array(browser.execute_script(READ_JOINTS))
    drawn = np.unique(np.round(after[:, 2:], 9), axis=0)
    np.testing.assert_allclose(drawn, api_joints(9), rtol=1e-12, atol=1e-9)
    assert np.abs(after[:, 2:] - before[:, 2:]).max() > 1  # the crank turned 45°
    svg = browser.find_element(By.CSS_SELECTOR, "#view3d svg")
    ActionChains(browser).move_to_element(svg).click_and_hold().move_by_offset(-40, -20)\
        .release().perform()
    view = browser.execute_script("return mechloopView3d.view()")
    assert view["azim"] > 30 and view["elev"] < 20
    browser.execute_script("mechloopView3d.setView(24, 38)")
    browser.find_element(By.ID, "overlay").click()
    Select(browser.find_element(By.ID, "trace-add")).select_by_value("head:1")
    trace = browser.find_element(By.CSS_SELECTOR, "path.trajectory3d[data-key='head:1']")
    assert trace.get_attribute("data-points") == "73"  # every position: none breaks
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / "web-3d.png"))
    browser.find_element(By.ID, "lang-ru").click()
    assert "возвышение 24°" in browser.find_element(By.CSS_SELECTOR, ".view3d-angles").text
    browser.find_element(By.ID, "lang-en").click()
    browser.find_element(By.ID, "overlay").click()
    browser.find_element(By.CSS_SELECTOR, "#traces button[data-key='head:1']").click()


#: Every text the 3-D page shows: what is on the screen, the buttons' titles (the tips)
#: and the words drawn in the view (axis letters, the break's mark).
PAGE_TEXT = """
const shown = [document.body.innerText];
for (const e of document.querySelectorAll('[title]')) shown.push(e.title);
for (const e of document.querySelectorAll('svg text')) shown.push(e.textContent);
return shown.join('\\n');"""


def test_the_page_of_animate_lang_ru_is_russian_and_the_english_page_english(
        browser, view_file, tmp_path):  # noqa: F811
    """``mechloop animate MODEL -o x.html --lang ru``: at a position where the chain breaks
    (its reason said too) the Russian page shows no English word but the user's names and
    symbols, and its break reason is the Russian of the solver's; the English page of the
    same model holds no Cyrillic letter."""
    from helpers.latin import latin_words
    from typer.testing import CliRunner

    from mechloop.cli import app
    from mechloop.report.words import reason

    path, results = view_file
    model = path.parent / "rssr_short.yaml"
    broken = int(np.flatnonzero(results.broken)[0])
    names = [v.name or "" for v in results.model.vectors.values()] + [results.model.name]
    texts = {}
    for lang in ("ru", "en"):
        page = tmp_path / f"view_{lang}.html"
        run = CliRunner().invoke(app, ["animate", str(model), "-o", str(page), "--lang",
                                       lang])
        assert run.exit_code == 0, run.output
        browser.get(page.as_uri())
        _wait(browser, lambda d: d.execute_script("return window.mechloopPlayer"),
              "no 3-D view")
        browser.execute_script("mechloopPlayer.show(arguments[0])", broken)
        texts[lang] = browser.execute_script(PAGE_TEXT)
        note = browser.find_element(By.ID, "break-note").text
        assert note.startswith("разрыв цепи в положении" if lang == "ru"
                               else "chain break at position")
        assert reason(results.breaks[0].reason, lang) in note
        browser.save_screenshot(str(tmp_path / f"view_{lang}.png"))
    assert "Пуск" in texts["ru"] and "траектории" in texts["ru"]
    assert latin_words(texts["ru"], names) == []
    assert re.search(r"\d\.\d", texts["ru"]) is None  # the decimal comma: t = 0,625 с
    assert re.search(r"t = \d+,\d+ с", texts["ru"])
    assert re.findall("[А-Яа-яЁё]+", texts["en"]) == []
    assert "Play" in texts["en"] and "trajectories" in texts["en"]
