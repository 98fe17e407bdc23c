"""The web application's downloads and structure panel (issue 16, second slice), through
the API: the table (CSV, XLSX, JSON) holds the numbers ``/api/solve`` shows, in the same
display units; the figure (PNG, SVG) is the parameters plot of those names; the report
comes as DOCX too; the structure is the library's (``mechloop structure``)."""

from __future__ import annotations

import json
import re
from io import BytesIO
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pandas as pd
import pytest
from docx import Document as DocxDocument
from PIL import Image
from starlette.testclient import TestClient

from mechloop.model.formula import describe_structure
from mechloop.model.load import load_model
from mechloop.structure import analyze
from mechloop.views.unit_words import unit_text
from mechloop.web.app import create_app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
DYNAMICS = (EXAMPLES / "crank_slider_dynamics.yaml").read_text(encoding="utf-8")
#: The dynamics example shown in millimetres and kilonewtons (the display: section).
SHOWN = DYNAMICS + "display:\n  length: mm\n  force: kN\n"


@pytest.fixture(scope="module")
def client(tmp_path_factory) -> TestClient:
    folder = tmp_path_factory.mktemp("work")
    (folder / "slider.yaml").write_text(SHOWN, encoding="utf-8")
    return TestClient(create_app(folder))


def _post(client: TestClient, route: str, **data):
    return client.post(route, json={"path": "slider.yaml", "text": SHOWN, **data})


@pytest.fixture(scope="module")
def shown(client) -> dict[str, tuple[str, np.ndarray]]:
    """The API's table: name -> (unit, values)."""
    answer = _post(client, "/api/solve").json()
    return {c["name"]: (c["unit"], np.array(c["values"], dtype=float))
            for c in answer["columns"]}


def _check_frame(frame: pd.DataFrame, shown: dict[str, tuple[str, np.ndarray]]) -> None:
    headers = {str(h).split(" [")[0]: str(h) for h in frame.columns}
    assert "r3 [mm]" in frame.columns and any(h.endswith("[kN]") for h in frame.columns)
    for name, (unit, values) in shown.items():
        header = headers[name]
        assert header == (f"{name} [{unit}]" if unit else name)
        assert frame[header].to_numpy(dtype=float) == pytest.approx(values, rel=1e-12,
                                                                    nan_ok=True), name
    assert len(frame) == 73 and list(frame["position"]) == list(range(73))


@pytest.mark.parametrize("fmt", ["csv", "xlsx", "json"])
def test_the_table_download_holds_the_numbers_the_page_shows(client, shown, fmt):
    answer = _post(client, "/api/table", format=fmt)
    assert answer.status_code == 200
    kind = answer.headers["content-type"]
    assert kind.startswith({"csv": "text/csv", "json": "application/json",
                            "xlsx": "application/vnd.openxmlformats"}[fmt])
    assert answer.headers["content-disposition"] == f'attachment; filename="slider.{fmt}"'
    if fmt == "csv":
        frame = pd.read_csv(BytesIO(answer.content))
    elif fmt == "xlsx":
        frame = pd.read_excel(BytesIO(answer.content), sheet_name="results")
    else:
        frame = pd.DataFrame(json.loads(answer.content))
    _check_frame(frame, shown)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_figure_download_is_the_parameters_plot(client, shown, lang):
    names = ["r3", "dr3", "M_bal"]
    svg = _post(client, "/api/figure", names=names, format="svg", lang=lang)
    assert svg.status_code == 200 and svg.headers["content-type"].startswith("image/svg")
    assert ElementTree.fromstring(svg.content).tag.endswith("svg")
    texts = re.findall(r"<!-- (.*?) -->", svg.content.decode())  # matplotlib's text
    for name in names:  # an axis per unit, labelled in the API's display unit
        unit = shown[name][0] if lang == "en" else unit_text(shown[name][0], "ru")  # [кН·м]
        assert f"{name} [{unit}]" in texts, (name, unit)
    assert ("положение" if lang == "ru" else "position") in texts
    r3 = "r3 [mm]" if lang == "en" else "r3 [мм]"
    ticks = [float(t.replace("−", "-").replace(",", ".")) for t in
             texts[texts.index(r3) - 5:texts.index(r3)]]
    low, high = np.nanmin(shown["r3"][1]), np.nanmax(shown["r3"][1])
    assert ticks[0] <= low + 20 and ticks[-1] >= high - 20  # the r3 axis spans r3 in mm
    png = _post(client, "/api/figure", names=names[:1], format="png", lang=lang)
    assert png.headers["content-type"] == "image/png"
    image = Image.open(BytesIO(png.content))
    assert image.format == "PNG" and image.size[0] > 300 and image.size[1] > 200


def test_the_figure_refuses_more_than_six_curves_and_unknown_names(client):
    seven = _post(client, "/api/figure", names=["r3"] * 7, format="png")
    assert seven.status_code == 400 and "at most 6" in seven.json()["error"]
    unknown = _post(client, "/api/figure", names=["r9"], format="png")
    assert unknown.status_code == 422 and "r9" in unknown.json()["error"]
    assert unknown.json()["hint"]
    assert _post(client, "/api/figure", names="r3").status_code == 400
    assert _post(client, "/api/figure", names=["r3"], format="gif").status_code == 400
    assert _post(client, "/api/table", format="parquet").status_code == 400
    assert _post(client, "/api/report", format="odt").status_code == 400
    assert _post(client, "/api/report", lang="de").status_code == 400


def test_the_report_downloads_as_docx(client):
    answer = _post(client, "/api/report", format="docx", lang="ru")
    assert answer.status_code == 200
    assert answer.headers["content-type"].endswith("wordprocessingml.document")
    assert answer.headers["content-disposition"] == 'attachment; filename="slider.docx"'
    document = DocxDocument(BytesIO(answer.content))
    headings = [p.text for p in document.paragraphs if p.style.name.startswith("Heading")]
    assert headings and any("Кинематический" in h or "кинемат" in h.lower()
                            for h in headings), headings


def test_structure_is_the_librarys(client):
    answer = _post(client, "/api/structure").json()
    model = load_model(EXAMPLES / "crank_slider_dynamics.yaml")
    mob, dec = analyze(model)
    mechanism = answer["mechanism"]
    assert mechanism["formula"] == dec.formula == "L0(1) → L2(2,3)"
    assert (mechanism["n"], mechanism["p5"], mechanism["p4"], mechanism["W"]) == \
        (mob.n, mob.p5, mob.p4, mob.W) == (3, 4, 0, 1)
    assert mechanism["W"] == 3 * mechanism["n"] - 2 * mechanism["p5"] - mechanism["p4"]
    assert mechanism["class"] == "II" and mechanism["ok"] is True
    assert [g["label"] for g in mechanism["groups"]] == [g.label for g in dec.groups]
    dyad = mechanism["groups"][1]
    assert dyad["pairs"] == "RRP" and dyad["variant"] == 1
    assert {p["name"] for p in dyad["external"]} == {"A", "S"}
    assert answer["description"] == describe_structure(model)
    plain = client.post("/api/structure", json={
        "example": "crank_slider",
        "text": (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")}).json()
    assert plain["mechanism"] is None and "contour 1" in plain["description"]
    bad = _post(client, "/api/structure", text=SHOWN.replace("positions: 72",
                                                             "positions: x"))
    assert bad.status_code == 422 and bad.json()["problems"][0]["line"]
