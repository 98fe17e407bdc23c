"""The data of the page's views (``/api/view`` with ``format: data``) are the library's
numbers in the model's display units: the reduced moment of inertia and load are
``solve_dynamics(model).reduced``'s, the hodograph's points the reaction's components at
every position, the reactions' magnitudes, the balancing moment by both methods, the
machine motion's speeds over the input angle, the increment the parameter's differences
from the reference position (and its derivatives the solver's), the angle between two
vectors the difference of their angles, a combination the ratio of two lengths, the
summary's tables the library's rows; the labels are in the page's language; the position
number of every point; refusals with their fix."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from starlette.testclient import TestClient

from mechloop.dynamics.analysis import solve_dynamics
from mechloop.model.load import load_model
from mechloop.views.dynamics import summary_rows
from mechloop.views.russian import russian
from mechloop.web.app import create_app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
ENGINE = "single_cylinder_engine"
#: Display units other than SI, so the conversion is checked too.
DISPLAY = "\ndisplay: {force: kN, moment: kN*m, inertia: kg*cm^2, length: mm}\n"
KG_CM2, KN, MM = 1e4, 1e-3, 1e3  # display unit per SI unit


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    folder = tmp_path_factory.mktemp("served")
    (folder / f"{ENGINE}.yaml").write_text(
        (EXAMPLES / f"{ENGINE}.yaml").read_text(encoding="utf-8") + DISPLAY, encoding="utf-8")
    return TestClient(create_app(folder)), folder


@pytest.fixture(scope="module")
def dyn(client):
    _, folder = client
    return solve_dynamics(load_model(folder / f"{ENGINE}.yaml"))


def _view(client, kind: str, lang: str = "en", **extra) -> dict:
    app, folder = client
    text = (folder / f"{ENGINE}.yaml").read_text(encoding="utf-8")
    answer = app.post("/api/view", json={"text": text, "path": f"{ENGINE}.yaml",
                                         "kind": kind, "format": "data", "lang": lang,
                                         **extra})
    assert answer.status_code == 200, answer.text
    assert answer.headers["content-type"] == "application/json"
    return answer.json()


def _values(values: list) -> np.ndarray:
    return np.array([np.nan if v is None else v for v in values], dtype=float)


def _series(data: dict, name: str) -> dict:
    found = [s for p in data["panels"] for a in p["yaxes"] for s in a["series"]
             if s["name"] == name]
    assert len(found) == 1, (name, [s["name"] for p in data["panels"]
                                    for a in p["yaxes"] for s in a["series"]])
    return found[0]


def _over_positions(series: dict, count: int) -> np.ndarray:
    """The y of a curve over the positions, checked to be drawn at x = position."""
    x, positions = _values(series["x"]), _values(series["positions"])
    assert np.array_equal(x, np.arange(count)) and np.array_equal(positions, x)
    return _values(series["y"])


def test_reduced_inertia_and_load_are_the_librarys(client, dyn):
    data = _view(client, "reduced")
    count = dyn.kinematics.positions.size
    assert data["count"] == count and [p["title"] for p in data["panels"]] == [
        "reduced inertia and its derivative", "reduced load"]
    top = data["panels"][0]
    assert [a["unit"] for a in top["yaxes"]] == ["kg*cm^2", "kg*cm^2/rad"]
    inertia = _over_positions(_series(data, "J_red"), count)
    np.testing.assert_allclose(inertia, dyn.reduced.inertia * KG_CM2, rtol=1e-12)
    np.testing.assert_allclose(_over_positions(_series(data, "dJ_red"), count),
                               dyn.reduced.d_inertia * KG_CM2, rtol=1e-12, atol=1e-15)
    load = _series(data, "M_red")
    assert load["unit"] == "kN*m"
    np.testing.assert_allclose(_over_positions(load, count), dyn.reduced.load * KN,
                               rtol=1e-12, atol=1e-15)
    assert data["panels"][1]["xlabel"] == "position"


def test_the_hodograph_is_the_reaction_at_every_position(client, dyn):
    data = _view(client, "hodograph", joint="J1_2")
    (panel,) = data["panels"]
    assert panel["over"] == "xy" and panel["equal"] and panel["xunit"] == "kN"
    curve = _series(data, "RJ1_2")
    force = dyn.forces.reactions["J1_2"].force
    count = force.size
    assert _values(curve["positions"]).tolist() == list(range(count))
    np.testing.assert_allclose(_values(curve["x"]), force.real * KN, rtol=1e-12)
    np.testing.assert_allclose(_values(curve["y"]), force.imag * KN, rtol=1e-12)
    origin = _series(data, "origin")
    assert origin["kind"] == "points" and origin["x"] == [0.0] and origin["y"] == [0.0]
    russian_data = _view(client, "hodograph", lang="ru", joint="J1_2")
    assert russian_data["panels"][0]["title"] == russian("hodograph of the reaction in J1_2",
                                                         {"J1_2"})
    assert _series(russian_data, "RJ1_2")["x"] == curve["x"]
    assert _series(russian_data, "начало")["unit"] == "кН"


def test_reactions_and_balancing_are_the_librarys(client, dyn):
    count = dyn.kinematics.positions.size
    reactions = _view(client, "reactions")
    for joint, result in dyn.forces.reactions.items():
        np.testing.assert_allclose(_over_positions(_series(reactions, f"|R{joint}|"), count),
                                   np.abs(result.force) * KN, rtol=1e-12)
    balancing = _view(client, "balancing")
    solid, dashed = _series(balancing, "M_bal"), _series(balancing, "M_bal_vp")
    assert (solid["dash"], bool(dashed["dash"])) == ("", True)
    np.testing.assert_allclose(_over_positions(solid, count),
                               dyn.forces.balancing[1] * KN, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(_over_positions(dashed, count), _values(solid["y"]),
                               rtol=1e-6, atol=1e-9)


def test_machine_motion_is_the_cycles_speed_over_the_input(client, dyn):
    data = _view(client, "motion")
    (panel,) = data["panels"]
    assert panel["over"] == "cycle" and panel["xunit"] == "deg"
    (axis,) = panel["yaxes"]
    lines = [s for s in axis["series"] if s["kind"] == "line"]
    assert len(lines) == 2
    cycle = dyn.cycle
    for line, motion in zip(lines, (cycle.motion, cycle.with_flywheel), strict=True):
        np.testing.assert_allclose(_values(line["x"]), np.degrees(cycle.q), rtol=1e-12)
        np.testing.assert_allclose(_values(line["y"]), motion.omega, rtol=1e-12)
        assert _values(line["positions"]).tolist() == list(range(cycle.q.size))
    (mean,) = [s for s in axis["series"] if s["kind"] == "hline"]
    assert mean["y"] == pytest.approx([float(cycle.omega_mean)], rel=1e-12)


def test_increment_angle_and_combination_are_the_parameters_differences(client, dyn):
    kin = dyn.kinematics
    count = kin.positions.size
    data = _view(client, "increment", names=["r3"], position=12)
    assert data["reference"] == 12 and len(data["panels"]) == 3
    r3 = kin.value("r3")
    np.testing.assert_allclose(_over_positions(_series(data, "Δr3"), count),
                               (r3 - r3[12]) * MM, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(_over_positions(_series(data, "dr3"), count),
                               kin.rate("r3") * MM, rtol=1e-12, atol=1e-9)
    reference = _series(data, "reference: position 12")
    assert (reference["x"], reference["y"], reference["positions"]) == ([12.0], [0.0], [12.0])
    angle = _view(client, "angle", names=["1", "2"])
    difference = _over_positions(_series(angle, "a2 − a1"), count)
    turns = (difference - np.degrees(kin.value("a2") - kin.value("a1"))) / 360.0
    np.testing.assert_allclose(turns, np.round(turns), atol=1e-9)
    ratio = _view(client, "combination", names=["r3", "r2"], op="ratio")
    np.testing.assert_allclose(_over_positions(_series(ratio, "r3 / r2"), count),
                               r3 / kin.value("r2"), rtol=1e-12)
    assert _series(ratio, "r3 / r2")["unit"] == ""
    total = _view(client, "combination", names=["r3", "r2"], op="sum")
    assert _series(total, "r3 + r2")["unit"] == "mm"


def test_the_summary_is_the_librarys_table(client, dyn):
    from mechloop.output.display import plot_display, resolve

    data = _view(client, "summary")
    assert data["panels"] == []
    header, rows, totals = summary_rows(dyn, plot_display(resolve(dyn.kinematics.model
                                                                  .display)))
    loads, figures = data["tables"]
    assert loads == {"rows": [header, *rows], "header": True}
    assert figures == {"rows": totals, "header": False}


def test_a_view_data_is_refused_with_the_fix(client):
    app, folder = client
    text = (folder / f"{ENGINE}.yaml").read_text(encoding="utf-8")
    base = {"text": text, "path": f"{ENGINE}.yaml"}
    bad = app.post("/api/view", json={**base, "kind": "reduced", "format": "gif"})
    assert bad.status_code == 400 and bad.json()["hint"] == "use one of svg, png, data"
    nameless = app.post("/api/view", json={**base, "kind": "parameters", "format": "data"},
                        headers={"X-Mechloop-Lang": "ru"})
    assert nameless.status_code == 422
    assert nameless.json()["error"] == "для графика параметров нужно имя"
    png = app.post("/api/view", json={**base, "kind": "reduced", "format": "png"})
    assert png.status_code == 200 and png.content.startswith(b"\x89PNG")
