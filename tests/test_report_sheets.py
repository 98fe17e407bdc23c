"""The course project's cam sheet in the report (sheet 4): its numbers against the cam
package and closed forms, its English and Russian texts, its pages, the ``project:``
references of a model with their located errors, and one report through the command line."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pypdf
import pytest
from matplotlib.text import Text
from typer.testing import CliRunner

import mechloop
from mechloop.cams import load_cam
from mechloop.cli import app
from mechloop.errors import ModelError
from mechloop.model.project import project_documents
from mechloop.views.cam_sheet import cam_sheet
from mechloop.views.report import A4, sheet_pages

ROOT = Path(__file__).resolve().parents[1]
CAMS = ROOT / "examples/cams"
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
                "R₀,min": s.minimum * 1e3, "α_max": math.degrees(s.pressure.value),
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


#: Latin words a Russian sheet may hold: unit names and the parts of symbols.
UNIT_WORDS = {"mm", "deg", "rad", "min", "max"}


def latin_words(text: str) -> set[str]:
    return {w for w in re.findall(r"[A-Za-z]{2,}", text) if w not in UNIT_WORDS}


@pytest.mark.parametrize("name", ["roller", "flat_rocker"])
def test_russian_sheet_has_no_english_words(name):
    design = load_cam(CAMS / f"{name}.yaml")
    sheet = cam_sheet(design, "ru")
    assert sheet.title == "Лист 4. Кулачковый механизм"
    texts = [sheet.title, *sheet.paragraphs]
    for table in sheet.tables:
        texts += [table.caption, *table.header]
        texts += [cell for row in table.rows if row[2] != design.name for cell in row]
    for item in sheet.figures:
        texts.append(item.caption)
        texts += [t.get_text() for t in item.draw().findobj(Text)]
    found = set().union(*(latin_words(t) for t in texts))
    assert not found, f"English in the Russian sheet: {sorted(found)}"
    english = cam_sheet(design, "en")  # the same symbols and numbers in both languages
    assert [r[1:3] for r in english.tables[0].rows if r[1]] == \
        [r[1:3] for r in sheet.tables[0].rows if r[1]]
    assert [r[0] for r in english.tables[0].rows] != [r[0] for r in sheet.tables[0].rows]


def test_sheet_pages_are_a4_with_numbered_captions(roller):
    sheet = cam_sheet(roller, "ru")
    pages = sheet_pages(sheet)
    assert len(pages) == 1 + len(sheet.figures) == 5
    first = pages[0]()
    assert tuple(first.get_size_inches()) == pytest.approx(A4)
    words = [t.get_text() for t in first.findobj(Text)]
    assert "Таблица 4.1. Параметры кулачкового механизма" in words
    assert "Таблица 4.2. Фазы закона движения" in words
    cells = [cell.get_text().get_text() for ax in first.axes for table in ax.tables
             for cell in table.get_celld().values()]
    assert "37" in cells and "26.073" in cells and "синусоидальный (циклоидальный)" in cells
    profile = pages[2]()
    assert sorted(profile.get_size_inches()) == pytest.approx(sorted(A4))
    assert any(t.get_text().startswith("Рис. 4.2 — Профиль кулачка")
               for t in profile.findobj(Text))


def test_model_project_section_reads_the_cam_relative_to_the_model():
    model = mechloop.load_model(MODEL)
    assert model.project.cam == "cams/roller.yaml"
    docs = project_documents(model, MODEL)
    assert docs.cam == load_cam(CAMS / "roller.yaml")
    assert docs.gears is None
    assert project_documents(mechloop.load_model(ROOT / "examples/crank_slider.yaml"),
                             ROOT / "examples/crank_slider.yaml").cam is None


def test_bad_cam_references_are_located_in_the_model_file(tmp_path):
    text = MODEL.read_text().replace("cam: cams/roller.yaml", "cam: cams/missing.yaml")
    missing = tmp_path / "model.yaml"
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


def test_report_with_cam_option_has_the_cam_sheet(tmp_path):
    """One report through the command line (a kinematic model, so it is quick)."""
    out = tmp_path / "report.pdf"
    result = CliRunner().invoke(app, ["report", str(ROOT / "examples/crank_slider.yaml"),
                                      "--cam", str(CAMS / "roller.yaml"), "-o", str(out),
                                      "--lang", "ru"])
    assert result.exit_code == 0, result.output
    pages = [p.extract_text() for p in pypdf.PdfReader(out).pages]
    sheet = [k for k, p in enumerate(pages) if "Лист 4. Кулачковый механизм" in p]
    conclusion = [k for k, p in enumerate(pages) if "Вывод о работе механизма" in p]
    assert len(sheet) == 5 and sheet[-1] < conclusion[0]
    assert "26.073" in pages[sheet[0]] and "Подрезания нет" in pages[sheet[0]]
