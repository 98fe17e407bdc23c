"""The choices of the web page's Units tab (``GET /api/units``) are the library's: every
kind of the model's ``display:`` section, the units its schema lists (then the views'
further examples), each a unit of its kind, the default unit the tables use, and the
precision ranges of the schema; the solve answer carries the model's precision and the
table in the chosen unit, every digit for the curves and rounded to it for the table."""

from __future__ import annotations

import csv
import io
import re
from pathlib import Path

import pydantic
import pytest
from starlette.testclient import TestClient

from mechloop.model.display import UNIT_FIELDS, DisplaySection
from mechloop.model.units import registry
from mechloop.views.display import BASE_KINDS, DERIVED_EXAMPLES
from mechloop.web.app import STATIC, create_app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SLIDER = (EXAMPLES / "crank_slider.yaml").read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def client(tmp_path_factory) -> TestClient:
    folder = tmp_path_factory.mktemp("served")
    (folder / "crank_slider.yaml").write_text(SLIDER, encoding="utf-8")
    return TestClient(create_app(folder))


def _listed(text: str) -> list[str]:
    return [u.strip() for u in text.split(",")]


def test_the_units_are_the_librarys_lists(client):
    answer = client.get("/api/units").json()
    kinds = [k["kind"] for k in answer["kinds"]]
    assert kinds == list(UNIT_FIELDS) == [
        f for f in DisplaySection.model_fields if f not in ("digits", "decimals")]
    for item in answer["kinds"]:
        kind, units = item["kind"], item["units"]
        schema = _listed(UNIT_FIELDS[kind])
        more = _listed(BASE_KINDS[kind][1] if kind in BASE_KINDS else DERIVED_EXAMPLES[kind])
        assert units[:len(schema)] == schema  # the schema's list first, in its order
        assert units == list(dict.fromkeys(schema + more))  # then the views' examples
        assert item["default"] in units
        si = registry().parse_units(item["default"])
        for unit in units:  # each one a unit of the kind the section takes
            assert registry().parse_units(unit).dimensionality == si.dimensionality, unit
            assert DisplaySection(**{kind: unit}).units() == {kind: unit}
    assert {"in", "turn", "km/h"} <= {u for k in answer["kinds"] for u in k["units"]}
    assert answer["digits"] == [1, 15] and answer["decimals"] == [0, 15]
    for name, (low, high) in (("digits", answer["digits"]),
                              ("decimals", answer["decimals"])):
        DisplaySection(**{name: low})
        DisplaySection(**{name: high})
        for wrong in (low - 1, high + 1):
            with pytest.raises(pydantic.ValidationError):
                DisplaySection(**{name: wrong})


def test_the_defaults_are_the_units_of_a_table_without_a_display(client):
    answer = client.get("/api/units").json()
    default = {k["kind"]: k["default"] for k in answer["kinds"]}
    columns = client.post("/api/solve", json={"path": "crank_slider.yaml",
                                              "text": SLIDER}).json()["columns"]
    units = {c["name"]: c["unit"] for c in columns}
    assert units["r3"] == default["length"] == "m"
    assert units["a2"] == default["angle"] == "deg"
    assert units["dr3"] == default["velocity"] == "m/s"  # per second: the model has time
    assert units["da2"] == default["angular_velocity"] == "rad/s"
    assert units["ddr3"] == default["acceleration"] == "m/s^2"


def test_the_solve_carries_the_precision_and_the_rounded_table(client):
    plain = client.post("/api/solve", json={"path": "crank_slider.yaml", "text": SLIDER})
    assert plain.json()["precision"] == {}
    assert not any("shown" in c for c in plain.json()["columns"])  # every digit shown
    r3 = next(c for c in plain.json()["columns"] if c["name"] == "r3")["values"]
    for unit, precision, shown in (
            ("mm", {"digits": 3}, lambda v: float(f"{v * 1e3:.3g}")),
            ("cm", {"decimals": 2}, lambda v: round(v * 100, 2))):
        (name, count), = precision.items()
        text = SLIDER + f"display: {{length: {unit}, {name}: {count}}}\n"
        answer = client.post("/api/solve", json={"path": "crank_slider.yaml",
                                                 "text": text}).json()
        assert answer["precision"] == precision
        column = next(c for c in answer["columns"] if c["name"] == "r3")
        assert column["unit"] == unit
        factor = {"mm": 1e3, "cm": 1e2}[unit]  # the curves: converted, every digit
        assert column["values"] == pytest.approx([v * factor for v in r3], rel=1e-15)
        assert column["shown"] == pytest.approx([shown(v) for v in r3], rel=1e-15)
        assert column["shown"] != pytest.approx(column["values"], rel=1e-9)


def test_every_unit_offered_has_its_russian_name(client):
    """The Units tab names each unit in the page's language (i18n.js's UNITS_RU); ``g0``,
    the standard gravity, is a symbol in both."""
    script = (STATIC / "i18n.js").read_text(encoding="utf-8")
    start = script.index("const UNITS_RU")
    block = script[start:script.index("};", start)]
    named = set(re.findall(r'"([^"]+)":', block)) | set(re.findall(r"[\s,{](\w+):", block))
    answer = client.get("/api/units").json()
    offered = {u for k in answer["kinds"] for u in [*k["units"], k["default"]]}
    assert offered - named == {"g0"}


def test_the_table_download_follows_the_section(client):
    """What the tab writes reaches the downloads: the CSV in mm with three digits."""
    plain = client.post("/api/solve", json={"path": "crank_slider.yaml", "text": SLIDER})
    r3 = next(c for c in plain.json()["columns"] if c["name"] == "r3")["values"]
    text = SLIDER + "display: {length: mm, digits: 3}\n"
    answer = client.post("/api/table", json={"path": "crank_slider.yaml", "text": text,
                                             "format": "csv"})
    assert answer.status_code == 200
    rows = list(csv.DictReader(io.StringIO(answer.text)))
    assert [float(row["r3 [mm]"]) for row in rows] == [float(f"{v * 1e3:.3g}") for v in r3]
