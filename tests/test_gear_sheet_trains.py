"""The gear sheet (sheet 3) of every planetary train ``mechloop gear planetary`` analyses:
a James 2K-H train of each scheme with each member held and each input, and the Wolfrom
train.  The members' roles follow the document; the ratio's formula, read as arithmetic on
the sheet's own Willis ratio, gives the sheet's ratio; the ratio and every member's speed
equal the gears package's and the planet's rolling at its pitch points solved without
Willis' formula (the functions of tests/test_gears_james_wolfrom.py); the Russian sheet
has no English word; one report with the Wolfrom train is typeset in both languages."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from test_gears_james_wolfrom import (
    FIXINGS,
    TRAINS,
    WOLFROM,
    _rolling_speeds_2kh,
    _rolling_speeds_wolfrom,
)
from test_report_sheets import latin_words, sheet_texts

from mechloop.gears.planetary import planetary_train
from mechloop.views.gear_sheet import GearTask, gear_sheet, load_gears
from mechloop.views.train_sheet import FORMULAS, WOLFROM_FORMULA

ROOT = Path(__file__).resolve().parents[1]
GEARS = ROOT / "examples/gears"
SPEED = 1200.0  # rpm of the input


def _task(train, target=None) -> GearTask:
    return GearTask(None, "", train, "a train", SPEED, target)


def _rows(sheet) -> dict[str, tuple[str, ...]]:
    return {r[1]: r for r in sheet.tables[1].rows if r[1]}


def _value(row: tuple[str, ...]) -> float:
    return float(row[2])


def _evaluate(formula: str, values: dict[str, float]) -> float:
    """The right-hand side of ``formula`` ('i_bh = 1 − i_ba^h') with the symbols' values:
    the written formula as arithmetic (symbols longest first)."""
    right = formula.split(" = ", 1)[1].replace("−", "-")
    for symbol in sorted(values, key=len, reverse=True):
        right = right.replace(symbol, repr(values[symbol]))
    assert set(right) <= set("0123456789.-+*/() e"), right
    return eval(right)  # only numbers and arithmetic are left (asserted above)


@pytest.mark.parametrize("fixed, driver", FIXINGS)
@pytest.mark.parametrize("scheme, teeth, k", TRAINS, ids=[t[0] for t in TRAINS])
def test_the_sheet_of_a_james_train_with_any_member_held(scheme, teeth, k, fixed, driver):
    train = planetary_train(scheme, teeth, k, m_n=2.0, fixed=fixed, driver=driver)
    sheet = gear_sheet(_task(train), "en")
    members = sheet.tables[0]
    output = ({"a", "b", "h"} - {fixed, driver}).pop()
    roles = {row[1]: row[3] for row in members.rows}
    assert roles == {**{key: "—" for key in train.teeth}, fixed: "fixed", driver: "input",
                     output: "output"}
    assert [row[2] for row in members.rows] == [*map(str, train.teeth.values()), "—"]
    rows = _rows(sheet)
    symbol = f"i_{driver}{output}"
    ratio_row = rows[symbol]
    formula = FORMULAS[fixed, driver]
    assert ratio_row[0].endswith(f"fixed: {formula}") and formula.startswith(symbol + " = ")
    # the written formula on Willis' ratio (the sheet shows it to 5 digits) gives the
    # sheet's ratio …
    willis = train.willis
    assert _value(rows["i_ab^h"]) == pytest.approx(willis, rel=1e-4)
    values = {"i_ab^h": willis, "i_ba^h": 1.0 / willis}
    assert ("i_ba^h" in rows) == ("i_ba^h" in formula)
    if "i_ba^h" in rows:
        assert _value(rows["i_ba^h"]) == pytest.approx(1.0 / willis, rel=1e-4)
    assert _value(ratio_row) == pytest.approx(_evaluate(formula, values), rel=1e-4)
    # … which is the package's and that of the planet rolling at both pitch points
    rolling = _rolling_speeds_2kh(train, fixed, driver)
    assert _value(ratio_row) == pytest.approx(train.ratio, rel=1e-4)
    assert _value(ratio_row) == pytest.approx(1.0 / rolling[output], rel=1e-4)
    speeds = train.speeds(SPEED * math.pi / 30)
    scale = SPEED * 1e-4
    for member, key in (("a", "a"), ("h", "h"), ("g", "p"), ("b", "b")):
        shown = _value(rows[f"n_{member}"])
        assert shown == pytest.approx(speeds[member] * 30 / math.pi, rel=1e-4, abs=scale)
        assert shown == pytest.approx(rolling[key] * SPEED, rel=1e-4, abs=scale)
    assert _value(rows[f"n_{fixed}"]) == 0 and _value(rows[f"n_{driver}"]) == SPEED
    assert ("turns against" in " ".join(sheet.paragraphs)) == (train.ratio < 0)


def test_the_sheet_of_the_wolfrom_train():
    task = load_gears(GEARS / "wolfrom.yaml")
    train = task.train
    assert train.teeth == WOLFROM and task.speed == 1500
    sheet = gear_sheet(task, "en")
    members, table = sheet.tables
    assert [(r[1], r[2], r[3]) for r in members.rows] == [
        ("a", "15", "input"), ("g", "24", "—"), ("f", "21", "—"), ("b", "63", "fixed"),
        ("e", "60", "output"), ("h", "—", "free (holds the planets)")]
    rows = _rows(sheet)
    # 1 + 63/15 = 5.2; 63·21/(24·60) = 0.91875; 5.2/(1 − 0.91875) = 64 (the example's header)
    assert _value(rows["i_ah"]) == pytest.approx(1 + 63 / 15, rel=1e-12)
    assert _value(rows["i_eb^h"]) == pytest.approx(63 * 21 / (24 * 60), rel=1e-12)
    assert rows["i_ae"][0].endswith(WOLFROM_FORMULA) and _value(rows["i_ae"]) == 64
    assert _evaluate(WOLFROM_FORMULA, {"i_ah": _value(rows["i_ah"]),
                                       "i_eb^h": _value(rows["i_eb^h"])}) == \
        pytest.approx(64, rel=1e-12)
    rolling = _rolling_speeds_wolfrom(train)
    assert _value(rows["i_ae"]) == pytest.approx(1 / rolling["e"], rel=1e-9)
    for member, key in (("a", "a"), ("h", "h"), ("g", "p"), ("b", "b"), ("e", "e")):
        assert _value(rows[f"n_{member}"]) == pytest.approx(rolling[key] * 1500, rel=1e-4,
                                                            abs=1e-9)
    assert _value(rows["a_w"]) == pytest.approx(1.5 * (15 + 24) / 2)
    assembly = [_value(r) for r in table.rows if r[0].startswith("assembly number")]
    assert assembly == [26, 13]            # (15 + 63)/3 and (60·24 − 63·21)/(3·3)
    assert sheet.paragraphs == ["Coaxiality: met.", "Assembly: met.",
                                "Neighbourhood (the planets clear each other): met."]
    [plan] = sheet.figures
    axes = plan.draw().axes[0]
    assert "i_ae = 64" in axes.get_title()
    assert [t.get_text().split(":")[0] for t in axes.get_legend().get_texts()] == [
        "sun a", "carrier h", "ring b (fixed)", "ring e (output)", "stepped planet g/f"]


def test_a_wolfrom_train_chosen_for_a_target_is_the_best_design(tmp_path):
    path = tmp_path / "w.yaml"
    path.write_text("planetary:\n  scheme: wolfrom\n  planets: 3\n  target_ratio: -40\n"
                    "  search: {teeth_min: 12, teeth_max: 80}\n", encoding="utf-8")
    task = load_gears(path)
    rows = _rows(gear_sheet(task, "en"))
    assert _value(rows["i_ae*"]) == -40
    assert abs(_value(rows["i_ae"]) + 40) <= 0.01 * 40
    assert _value(rows["i_ae"]) == pytest.approx(task.train.ratio, rel=1e-4)
    assert _value(rows["Δi"]) == pytest.approx(100 * abs(task.train.ratio + 40) / 40,
                                               rel=1e-4, abs=1e-9)
    sheet = gear_sheet(task, "ru")
    assert sheet.paragraphs[-1].startswith("Выходное звено e вращается в сторону")


def test_the_held_sun_sheet_and_its_plan_name_every_role():
    sheet = gear_sheet(load_gears(GEARS / "james_sun_fixed.yaml"), "en")
    rows = _rows(sheet)
    # sun 20, ring 80 held sun: i_bh = 1 − i_ba^h = 1 + 20/80 = 1.25; the carrier at 960 rpm
    assert rows["i_bh"][0] == "ratio, central gear a fixed: i_bh = 1 − i_ba^h"
    assert _value(rows["i_bh"]) == 1.25 and _value(rows["n_h"]) == 1200 / 1.25
    axes = sheet.figures[0].draw().axes[0]
    assert [t.get_text().split(":")[0] for t in axes.get_legend().get_texts()] == [
        "a (fixed)", "carrier h (output)", "b (input)", "planet g"]
    assert "i_bh = 1.25, n_b = 1200 rpm" in axes.get_title()


@pytest.mark.parametrize("name", ["wolfrom", "james_sun_fixed"])
def test_russian_train_sheet_has_no_english_words(name):
    sheet = gear_sheet(load_gears(GEARS / f"{name}.yaml"), "ru")
    found = set().union(*(latin_words(t) for t in sheet_texts(sheet)))
    assert not found, f"English in the Russian sheet: {sorted(found)}"
    text = " ".join(c for t in sheet.tables for r in t.rows for c in r)
    assert "неподвижно" in text and "водило h" in text and "центральное колесо" in text


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_report_with_the_wolfrom_train_is_typeset(lang, tmp_path):
    """The one typeset case: the slider-crank's report with the Wolfrom train as its gear
    sheet, through every page check of tests/test_report_pages.py."""
    from test_report_pages import test_every_page_of_the_report

    model = tmp_path / "model.yaml"
    model.write_text((ROOT / "examples/crank_slider.yaml").read_text(encoding="utf-8")
                     + f"\nproject: {{gears: {GEARS / 'wolfrom.yaml'}}}\n", encoding="utf-8")
    test_every_page_of_the_report(model, lang, tmp_path)
