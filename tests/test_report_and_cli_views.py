"""The course-project report (PDF, English and Russian) and the view commands of the CLI."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pypdf
import pypdfium2
import pytest
from PIL import Image
from typer.testing import CliRunner

import mechloop
from mechloop.cli import PLOTS, app
from mechloop.report.appendix import COLUMNS
from mechloop.report.content import build_document
from mechloop.report.document import Paragraph
from mechloop.report.words import TEXT
from mechloop.views.report import write_report

ROOT = Path(__file__).resolve().parents[1]
DYNAMIC = ROOT / "examples/crank_slider_dynamics.yaml"
KINEMATIC = ROOT / "examples/crank_slider.yaml"

SECTIONS = ("s_parameters", "s_formula", "s_increment", "s_angles", "s_dependence",
            "s_conclusion", "s_appendix")
DYNAMIC_SECTIONS = ("s_masses", "s_reduced", "s_reactions", "s_centres")


def pdf_text(path: Path) -> list[str]:
    return [" ".join(page.extract_text().split()) for page in pypdf.PdfReader(path).pages]


def heading(lang: str, key: str) -> str:
    return TEXT[lang][key].split("{")[0].strip()


@pytest.fixture(scope="module", params=["en", "ru"])
def dynamic_report(request, tmp_path_factory) -> tuple[str, Path]:
    """The whole report typeset (end to end: content, Typst)."""
    path = tmp_path_factory.mktemp("report") / f"report_{request.param}.pdf"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        write_report(mechloop.load_model(DYNAMIC), path, lang=request.param)
    return request.param, path


def test_report_has_every_section_of_the_course_project(dynamic_report):
    lang, path = dynamic_report
    text = "\n".join(pdf_text(path))
    for key in SECTIONS + DYNAMIC_SECTIONS:
        assert heading(lang, key) in text, f"section {key!r} missing from the {lang} report"
    other = "ru" if lang == "en" else "en"
    assert heading(other, "s_conclusion") not in text


def test_report_appendix_holds_every_position_and_column():
    document = build_document(mechloop.load_model(DYNAMIC), lang="en")
    frame = mechloop.solve_dynamics(mechloop.load_model(DYNAMIC)).to_frame()
    tables = document.appendices[0].blocks
    # every column but the position (in each table) and the empty chain-break column
    assert len(tables) == math.ceil((len(frame.columns) - 2) / (COLUMNS - 1))
    assert sum(len(t.header) - 1 for t in tables) == len(frame.columns) - 2
    assert all(len(t.rows) == len(frame) for t in tables)
    # the value of r3 at the last position is printed in the appendix
    r3 = next(t for t in tables if "r3, m" in t.header)
    cell = r3.rows[-1][r3.header.index("r3, m")]
    assert float(cell) == pytest.approx(frame["r3 [m]"].iloc[-1], abs=5e-6)


def test_report_conclusion_states_the_stroke_and_the_peak_balancing_moment(dynamic_report):
    lang, path = dynamic_report
    dyn = mechloop.solve_dynamics(mechloop.load_model(DYNAMIC))
    r3 = dyn.kinematics.value("r3")
    text = " ".join(pdf_text(path))
    metre, newton_metre = ("m", "N·m") if lang == "en" else ("м", "Н·м")
    stroke = f"{r3.max() - r3.min():.5g}"
    peak = f"{np.abs(dyn.forces.balancing[1]).max():.5g}"
    if lang == "ru":  # the decimal comma
        stroke, peak = stroke.replace(".", ","), peak.replace(".", ",")
    assert f"{stroke} {metre}" in text
    assert f"{peak} {newton_metre}" in text


def test_report_pages_render_to_images(dynamic_report):
    _, path = dynamic_report
    document = pypdfium2.PdfDocument(str(path))
    for index in (0, 2, len(document) - 1):
        image = document[index].render(scale=0.5).to_pil().convert("L")
        pixels = np.asarray(image)
        assert pixels.min() < 128 < pixels.max(), f"page {index + 1} is blank"


def test_the_docx_report_holds_the_same_sections(tmp_path):
    import docx

    path = write_report(mechloop.load_model(KINEMATIC), tmp_path / "k.docx", lang="ru")
    text = "\n".join(p.text for p in docx.Document(str(path)).paragraphs)
    for key in SECTIONS:
        assert heading("ru", key) in text, key


def test_kinematic_report_has_no_dynamic_sections():
    document = build_document(mechloop.load_model(KINEMATIC), lang="ru")
    titles = [s.title for s in document.sections]
    assert titles[2].startswith(heading("ru", "s_increment"))
    for key in DYNAMIC_SECTIONS:
        assert not any(t.startswith(heading("ru", key)) for t in titles)
    assert isinstance(document.sections[-1].blocks[0], Paragraph)


def test_report_errors(tmp_path):
    model = mechloop.load_model(KINEMATIC)
    with pytest.raises(mechloop.MechloopError, match="use 'en' or 'ru'"):
        write_report(model, tmp_path / "x.pdf", lang="de")
    with pytest.raises(mechloop.MechloopError, match=r"ending in \.pdf or \.docx"):
        write_report(model, tmp_path / "x.png")
    with pytest.raises(mechloop.MechloopError, match="not a varying parameter"):
        write_report(model, tmp_path / "x.pdf", output="r1")
    assert not list(tmp_path.iterdir())


KIND_OPTIONS = {
    "plan": ["-p", "10"], "trajectories": ["--points", "head:2,S2"],
    "parameters": ["-n", "r3,dr3"], "combination": ["-n", "r3,r1"], "angle": ["-n", "2,3"],
    "increment": ["-n", "r3"], "hodograph": ["--joint", "A"],
}


#: Views that need a model of their own kind (the rest draw the dynamic example).
KIND_MODEL = {"envelope": DYNAMIC.parent / "cam_roller_follower.yaml"}


@pytest.mark.parametrize("kind", [k for k in PLOTS if k != "motion"])
def test_every_view_is_drawn_from_the_command_line(kind, tmp_path):
    out = tmp_path / f"{kind}.png"
    model = KIND_MODEL.get(kind, DYNAMIC)
    result = CliRunner().invoke(app, ["plot", str(model), kind, "-o", str(out),
                                      *KIND_OPTIONS.get(kind, [])])
    assert result.exit_code == 0, result.output
    with Image.open(out) as image:
        assert image.size[0] > 100


def test_machine_motion_view_from_the_command_line(tmp_path):
    out = tmp_path / "motion.svg"
    result = CliRunner().invoke(app, ["plot", str(ROOT / "examples/single_cylinder_engine.yaml"),
                                      "motion", "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "<svg" in out.read_text()


@pytest.mark.parametrize("args, message", [
    (["plot", str(DYNAMIC), "nope"], "unknown view 'nope'"),
    (["plot", str(DYNAMIC), "hodograph"], "needs a joint"),
    (["plot", str(KINEMATIC), "reduced"], "needs a model with bodies"),
    (["plot", str(DYNAMIC), "plan", "--units", "length=parsec2"], "parsec2"),
    (["report", str(DYNAMIC), "--lang", "de"], "use 'en' or 'ru'"),
    (["animate", str(KINEMATIC)], None),
])
def test_view_command_mistakes_exit_2_without_a_traceback(args, message, tmp_path):
    if args[0] != "animate":
        args = [*args, "-o", str(tmp_path / ("x.pdf" if args[0] == "report" else "x.png"))]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    if message:
        assert message in result.output


def test_animation_from_the_command_line_has_a_frame_per_position(tmp_path):
    """The example turns its crank a full turn: position N repeats position 0 and is
    left out of the loop, and the message counts the frames written."""
    out = tmp_path / "cycle.gif"
    result = CliRunner().invoke(app, ["animate", str(KINEMATIC), "-o", str(out)])
    assert result.exit_code == 0, result.output
    frames = mechloop.load_model(KINEMATIC).positions
    with Image.open(out) as image:
        assert image.n_frames == frames
    assert f"({frames} frames)" in result.output


@pytest.mark.parametrize("command", ["plot", "animate", "report"])
def test_view_commands_show_an_example_in_their_help(command):
    result = CliRunner().invoke(app, [command, "--help"])
    assert result.exit_code == 0
    assert f"mechloop {command} examples/" in result.output


def test_russian_report_figures_speak_russian(dynamic_report):
    lang, path = dynamic_report
    text = "\n".join(pdf_text(path))
    if lang == "ru":
        assert "приращение r3 от положения 0" in text
        assert "increment of" not in text and "reactions in the joints" not in text
    else:
        assert "increment of r3 from position 0" in text
