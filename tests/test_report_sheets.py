"""The course project's gears and cam sheets in the report (sheets 3 and 4): their numbers
against the gear and cam packages and closed forms, their English and Russian texts, their
pages, the ``project:`` references of a model with their located errors, and one report
through the command line."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from matplotlib.text import Text
from typer.testing import CliRunner

import mechloop
from mechloop.cams import load_cam
from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.gears.tables import pair_table
from mechloop.model.project import project_documents
from mechloop.report.document import Document, FigureItem, Table, TitlePage, caption, numbered
from mechloop.report.sheets import sheet_section
from mechloop.views.cam_sheet import cam_sheet
from mechloop.views.decimal_mark import localized
from mechloop.views.gear_sheet import gear_sheet, load_gears

ROOT = Path(__file__).resolve().parents[1]
CAMS = ROOT / "examples/cams"
GEARS = ROOT / "examples/gears"
MODEL = ROOT / "examples/course_project_sheets.yaml"


def rows_by_symbol(sheet) -> dict[str, tuple[str, ...]]:
    return {row[1]: row for row in sheet.tables[0].rows if row[1]}


def number(row: tuple[str, ...]) -> float:
    return float(row[2])


@pytest.fixture(scope="module")
def roller():
    return load_cam(CAMS / "roller.yaml")


def test_cam_table_holds_the_cam_packages_figures_in_the_files_units(roller):
    s = roller.summary()
    rows = rows_by_symbol(cam_sheet(roller, "en"))
    w = roller.omega
    assert w == pytest.approx(120 * math.pi / 30)
    expected = {"r": 10.0, "e": 12.0, "R₀": 37.0, "R₀ − r": 27.0, "h": 20.0, "[α]": 30.0,
                "[α]′": 45.0, "n": 120.0,
                "R₀_min": s.minimum * 1e3, "α_max": math.degrees(s.pressure.value),
                "α/[α]": s.pressure_ratio, "ρ_min": s.rho.value * 1e3,
                "v_max": s.peak("v") * w * 1e3, "a_max": s.peak("a") * w**2 * 1e3,
                "j_max": s.peak("j") * w**3 * 1e3}
    for symbol, value in expected.items():
        assert number(rows[symbol]) == pytest.approx(value, rel=1e-4), symbol
    for symbol in ("R₀", "ρ_min", "v_max", "a_max", "j_max"):
        assert rows[symbol][3].startswith("mm")
    # cycloidal rise of h = 20 mm over β = 120°: v_max = 2hω/β, a_max = 2πhω²/β² (closed form)
    beta = math.radians(120)
    assert number(rows["v_max"]) == pytest.approx(2 * 20 * w / beta, rel=1e-4)
    assert number(rows["a_max"]) == pytest.approx(2 * math.pi * 20 * w**2 / beta**2, rel=1e-4)
    # the peak pressure angle is where the summary says, and within the allowed on both phases
    assert f"φ = {math.degrees(s.pressure.phi):.1f}" in rows["α_max"][0]


def test_segment_table_gives_the_laws_peak_coefficients(roller):
    table = cam_sheet(roller, "en").tables[1]
    rise = table.rows[0]
    assert rise[:4] == ("rise", "120", "20", "cycloidal")
    # cycloidal law: C_v = 2, C_a = 2π, C_j = 4π² (closed form)
    assert [float(c) for c in rise[4:]] == pytest.approx([2, 2 * math.pi, 4 * math.pi**2],
                                                         rel=1e-4)
    assert table.rows[1][2:] == ("—",) * 5


def test_flat_face_sheet_gives_the_face_width_and_no_pressure_figure():
    design = load_cam(CAMS / "flat.yaml")
    sheet = cam_sheet(design, "en")
    rows = rows_by_symbol(sheet)
    face = design.summary().face
    assert number(rows["b_min"]) == pytest.approx(face.width * 1e3, rel=1e-4)
    assert number(rows["u_max"]) - number(rows["u_min"]) == pytest.approx(
        number(rows["b_min"]), abs=2e-3)
    assert "α_max" not in rows
    assert [f.caption for f in sheet.figures] == [
        "Follower motion program: displacement, velocity, acceleration, jerk",
        "Cam profile: working profile, base circle, follower's face",
        "Radius of curvature of the profile over the turn"]
    assert any("convex" in p for p in sheet.paragraphs)


#: Latin words a Russian sheet may hold: unit names (symbols are not words: d_Nf, N1N2).
UNIT_WORDS = {"mm", "deg", "rad"}


def latin_words(text: str) -> set[str]:
    return {w for w in re.findall(r"(?<![\w^])[A-Za-z]{2,}(?![\w^])", text)
            if w not in UNIT_WORDS}


def sheet_texts(sheet, *, skip: str = "") -> list[str]:
    """Every text of a sheet: title, paragraphs, tables, captions and the figures' texts."""
    texts = [sheet.title, *sheet.paragraphs]
    for table in sheet.tables:
        texts += [table.caption, *table.header]
        texts += [cell for row in table.rows if skip not in row for cell in row]
    for item in sheet.figures:
        texts.append(item.caption)
        texts += [t.get_text() for t in item.draw().findobj(Text)]
    return texts


@pytest.mark.parametrize("name", ["roller", "flat_rocker"])
def test_russian_sheet_has_no_english_words(name):
    design = load_cam(CAMS / f"{name}.yaml")
    sheet = cam_sheet(design, "ru")
    assert sheet.title == "Лист 4. Кулачковый механизм"
    found = set().union(*(latin_words(t) for t in sheet_texts(sheet, skip=design.name)))
    assert not found, f"English in the Russian sheet: {sorted(found)}"
    english = cam_sheet(design, "en")  # the same symbols and numbers in both languages
    assert [(r[1], localized(r[2], "ru")) for r in english.tables[0].rows if r[1]] == \
        [r[1:3] for r in sheet.tables[0].rows if r[1]]
    decimals = [c for r in sheet.tables[0].rows for c in r if re.fullmatch(r"\d+[.,]\d+", c)]
    assert decimals and all("," in c for c in decimals)  # the decimal comma (GOST 2.105)
    assert [r[0] for r in english.tables[0].rows] != [r[0] for r in sheet.tables[0].rows]


def test_a_sheet_is_a_report_section_with_numbered_captions(roller):
    sheet = cam_sheet(roller, "ru")
    section = sheet_section(sheet)
    assert section.title == "Лист 4. Кулачковый механизм"
    tables = [b for b in section.blocks if isinstance(b, Table)]
    figures = [b for b in section.blocks if isinstance(b, FigureItem)]
    assert len(tables) == len(sheet.tables) == 2 and len(figures) == len(sheet.figures) == 4
    title = TitlePage([], "", "", "", "", [], "")
    document = Document("ru", "", title, [section, section, section, section])
    captions = [caption(document, n) for n in numbered(document)
                if n.number.startswith("4.") and isinstance(n.block, Table | FigureItem)]
    assert "Таблица 4.1 — Параметры кулачкового механизма" in captions
    assert "Таблица 4.2 — Фазы закона движения" in captions
    assert any(c.startswith("Рисунок 4.2 — Профиль кулачка") for c in captions)
    cells = [cell for table in tables for row in table.rows for cell in row]
    assert "37" in cells and "26,073" in cells and "синусоидальный (циклоидальный)" in cells
    assert [p.text for p in section.blocks if hasattr(p, "text")] == sheet.paragraphs


def test_model_project_section_reads_the_cam_relative_to_the_model():
    model = mechloop.load_model(MODEL)
    assert model.project.cam == "cams/roller.yaml"
    docs = project_documents(model, MODEL)
    assert docs.cam == load_cam(CAMS / "roller.yaml")
    assert docs.gears == load_gears(GEARS / "planetary_reducer.yaml")
    assert project_documents(mechloop.load_model(ROOT / "examples/crank_slider.yaml"),
                             ROOT / "examples/crank_slider.yaml").cam is None


def test_bad_cam_references_are_located_in_the_model_file(tmp_path):
    text = MODEL.read_text().replace("cam: cams/roller.yaml", "cam: cams/missing.yaml")
    with_gears = text
    text = text.replace("gears: gears/planetary_reducer.yaml",
                        f"gears: {GEARS / 'planetary_reducer.yaml'}")
    missing = tmp_path / "model.yaml"
    missing.write_text(with_gears)  # both references missing: both told at once
    with pytest.raises(ModelError) as caught:
        project_documents(mechloop.load_model(missing), missing)
    assert [p.path for p in caught.value.problems] == [("project", "cam"),
                                                       ("project", "gears")]
    missing.write_text(text)
    with pytest.raises(ModelError) as caught:
        project_documents(mechloop.load_model(missing), missing)
    error = caught.value
    assert error.file == str(missing)
    [problem] = error.problems
    assert problem.path == ("project", "cam")
    assert problem.line == text.splitlines().index("  cam: cams/missing.yaml") + 1
    assert "cams/missing.yaml" in problem.message and "file not found" in problem.message
    (tmp_path / "cams").mkdir()
    bad = (CAMS / "roller.yaml").read_text().replace("law: cycloidal", "law: cubic", 1)
    (tmp_path / "cams/missing.yaml").write_text(bad)
    with pytest.raises(ModelError) as caught:
        project_documents(mechloop.load_model(missing), missing)
    [problem] = caught.value.problems
    assert problem.path == ("project", "cam")
    line = bad.splitlines().index("    - {rise: 20, angle: 120, law: cubic}") + 1
    assert f"cams/missing.yaml:{line}, cam.segments[0].law: Input should be 'constant_speed'" \
        in problem.message
    result = CliRunner().invoke(app, ["report", str(missing), "-o", str(tmp_path / "r.pdf")])
    assert result.exit_code == 2 and "project.cam" in result.output
    assert "Traceback" not in result.output


def test_report_with_cam_and_gears_options_has_both_sheets(tmp_path, monkeypatch):
    """One report through the command line (a kinematic model, so it is quick); the
    document is caught before it is typeset."""
    import mechloop.report.write as write

    made = []

    def capture(document, path, *, progress=None):
        made.append(document)
        return Path(path)

    monkeypatch.setattr(write, "write_document", capture)
    out = tmp_path / "report.pdf"
    result = CliRunner().invoke(app, ["report", str(ROOT / "examples/crank_slider.yaml"),
                                      "--cam", str(CAMS / "roller.yaml"), "--gears",
                                      str(GEARS / "gear_pair.yaml"), "-o", str(out),
                                      "--lang", "ru"])
    assert result.exit_code == 0, result.output
    [document] = made
    titles = [s.title for s in document.sections]
    gears = titles.index("Лист 3. Зубчатая передача")
    assert titles[gears + 1] == "Лист 4. Кулачковый механизм"
    assert titles[gears + 2] == "Вывод о работе механизма"
    gear_cells = " ".join(c for b in document.sections[gears].blocks
                          if isinstance(b, Table) for row in b.rows for c in row)
    assert "коэффициент торцового перекрытия" in gear_cells
    cam = document.sections[gears + 1]
    cam_text = " ".join([*(c for b in cam.blocks if isinstance(b, Table)
                           for row in b.rows for c in row),
                         *(b.text for b in cam.blocks if hasattr(b, "text"))])
    assert "26,073" in cam_text and "Подрезания нет" in cam_text


def test_gear_pair_sheet_holds_the_gear_packages_geometry_and_checks():
    task = load_gears(GEARS / "gear_pair.yaml")
    pair = task.pair
    sheet = gear_sheet(task, "en")
    assert sheet.title == "Sheet 3. Gear pair" and task.train is None
    geometry, checks = sheet.tables
    frame = pair_table(pair)
    assert [r[1] for r in geometry.rows] == frame["symbol"].tolist()
    for row, (_, symbol, pinion, wheel, unit) in zip(geometry.rows, frame.itertuples(
            index=False), strict=True):
        assert float(row[2]) == pytest.approx(pinion, rel=1e-4, abs=1e-9), symbol
        if not math.isnan(wheel):
            assert float(row[3]) == pytest.approx(wheel, rel=1e-4, abs=1e-9), symbol
        assert row[4] == ("°" if unit == "deg" else unit)
    rows = {r[1]: r for r in geometry.rows}
    # the KHK worked example: z 12/24, m 3, x 0.6/0.36 (examples/gears/gear_pair.yaml):
    # reference diameters m z, centre distance and contact ratio of the pair
    assert (rows["d"][2], rows["d"][3]) == ("36", "72")
    assert float(rows["a"][2]) == pytest.approx(pair.a, rel=1e-5)
    assert float(rows["ε_α"][2]) == pytest.approx(pair.eps_alpha, rel=1e-4)
    assert [r[4] for r in checks.rows] == ["met" if c.ok else "NOT MET"
                                           for c in pair.checks()]
    assert len(checks.rows) == 9 and sheet.paragraphs[0].startswith("All checks")
    assert [f.caption.split(":")[0] for f in sheet.figures] == [
        "Meshing of the gear pair", "Specific sliding of the pinion and the wheel along the "
        "line of action"]


def test_planetary_sheet_gives_willis_ratio_conditions_and_speeds():
    task = load_gears(GEARS / "planetary_reducer.yaml")
    sheet = gear_sheet(task, "en")
    assert sheet.title == "Sheet 3. Planetary train"
    teeth, train = sheet.tables
    assert teeth.rows == [("central gear a", "a", "20", "input"), ("planet g", "g", "30", "—"),
                          ("central gear b", "b", "80", "fixed"),
                          ("carrier h", "h", "—", "output")]
    rows = {r[1]: r for r in train.rows if r[1]}
    # simple train 20/30/80, m = 2, sun at 1500 rpm, ring fixed (closed forms):
    # i_ab^h = −z_b/z_a, i_ah = 1 + z_b/z_a, a_w = m(z_a + z_g)/2, n_h = n_a/i_ah,
    # the planet's absolute speed n_g = n_h − (z_a/z_g)(n_a − n_h)
    assert float(rows["i_ab^h"][2]) == pytest.approx(-4.0)
    assert float(rows["i_ah"][2]) == pytest.approx(5.0)
    assert float(rows["a_w"][2]) == pytest.approx(50.0)
    assert float(rows["n_h"][2]) == pytest.approx(300.0)
    assert float(rows["n_g"][2]) == pytest.approx(300 - 20 / 30 * 1200, rel=1e-4)
    assert sheet.paragraphs == ["Coaxiality: met.", "Assembly: met.",
                                "Neighbourhood (the planets clear each other): met."]
    chosen = gear_sheet(load_gears(GEARS / "planetary_choice.yaml"), "ru")
    ratio = {r[1]: r for r in chosen.tables[1].rows if r[1]}
    assert float(ratio["i_ah*"][2]) == 12
    assert abs(float(ratio["i_ah"][2]) - 12) <= 0.01 * 12  # within the search's tolerance


@pytest.mark.parametrize("name", ["gear_pair", "planetary_choice"])
def test_russian_gear_sheet_has_no_english_words(name):
    sheet = gear_sheet(load_gears(GEARS / f"{name}.yaml"), "ru")
    assert sheet.title.startswith("Лист 3. ")
    found = set().union(*(latin_words(t) for t in sheet_texts(sheet)))
    assert not found, f"English in the Russian sheet: {sorted(found)}"


def test_bad_gear_references_are_located_in_the_model_file(tmp_path):
    (tmp_path / "gears").mkdir()
    (tmp_path / "gears/train.yaml").write_text(
        "planetary:\n  scheme: simple\n  teeth: {a: 20, g: 30}\n")
    model = tmp_path / "model.yaml"
    text = MODEL.read_text().replace("gears: gears/planetary_reducer.yaml",
                                     "gears: gears/train.yaml").replace(
        "cam: cams/roller.yaml", f"cam: {CAMS / 'roller.yaml'}")
    model.write_text(text)
    with pytest.raises(ModelError) as caught:
        project_documents(mechloop.load_model(model), model)
    [problem] = caught.value.problems
    assert problem.path == ("project", "gears")
    assert problem.line == text.splitlines().index("  gears: gears/train.yaml") + 1
    assert "gears/train.yaml:3, planetary.teeth" in problem.message
