"""The report's content as a Document (mechloop.report.content): sections in the order of
seed 000 sec. 2.1 item 9, every number of the parameter tables, the conclusion and the
appendix equal to the solver's value in the chosen display unit (parsed back from the
printed text, within its printed precision), no empty columns and no NaN text, Russian
without English words, a report of a model whose position 0 breaks, the scheme's
position, and the title page from the model's report: section and the command line."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
import yaml
from helpers.latin import latin_words, model_names
from typer.testing import CliRunner

import mechloop
from mechloop.cli import app
from mechloop.errors import HintedError
from mechloop.model.project import project_documents
from mechloop.report.content import build_document
from mechloop.report.document import FigureItem, Paragraph, Section, Table, walk
from mechloop.report.document import texts as document_texts
from mechloop.report.numbers import Shown
from mechloop.report.words import TEXT

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
DYNAMIC = EXAMPLES / "crank_slider_dynamics.yaml"
KINEMATIC = EXAMPLES / "crank_slider.yaml"
SHEETS = EXAMPLES / "course_project_sheets.yaml"

KINEMATIC_KEYS = ["s_parameters", "s_formula", "s_increment", "s_angles", "s_dependence"]
DYNAMIC_KEYS = ["s_masses", "s_reduced", "s_reactions", "s_centres"]
#: A printed number: English ``-1.5e-05``, Russian ``-1,5·10⁻⁵`` (the decimal comma).
NUMBER = re.compile(r"-?\d+(?:[.,]\d+)?(?:e-?\d+|·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
_DIGITS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def plain(text: str) -> str:
    """A printed number as Python writes it (``1,5·10⁻⁵`` -> ``1.5e-5``)."""
    mantissa, _, power = text.partition("·10")
    return mantissa.replace(",", ".") + (f"e{power.translate(_DIGITS)}" if power else "")


def _title(lang: str, key: str) -> str:
    return TEXT[lang][key].split("{")[0].strip()


def texts(document) -> list[str]:
    """Every text of ``document`` (:func:`mechloop.report.document.texts`)."""
    return document_texts(document)


@pytest.fixture(scope="module")
def dynamic():
    model = mechloop.load_model(DYNAMIC)
    return model, mechloop.solve_dynamics(model)


@pytest.fixture(scope="module")
def documents(dynamic):
    return {lang: build_document(dynamic[0], lang=lang) for lang in ("en", "ru")}


def section_titles(document) -> list[str]:
    return [s.title for s in document.sections] + [s.title for s in document.appendices]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_sections_follow_the_seeds_order(lang, documents):
    w = TEXT[lang]
    kinematic = build_document(mechloop.load_model(KINEMATIC), lang=lang)
    expected = [_title(lang, k) for k in [*KINEMATIC_KEYS, "s_conclusion"]]
    assert [t.split(" r3")[0] for t in section_titles(kinematic)[:-1]] == \
        [e.split(" {")[0] for e in expected]
    assert section_titles(kinematic)[-1] == w["s_appendix"]
    dynamic = section_titles(documents[lang])
    expected = [_title(lang, k) for k in [*KINEMATIC_KEYS, *DYNAMIC_KEYS, "s_conclusion",
                                          "s_appendix"]]
    assert [t.startswith(e) for t, e in zip(dynamic, expected, strict=True)] == \
        [True] * len(expected)
    reduced = documents[lang].sections[6]
    assert [s.title for s in reduced.blocks if isinstance(s, Section)][:3] == \
        [w["s_reduced_sub"], w["s_balancing"], w["s_summary"]]
    reactions = documents[lang].sections[7]
    assert [s.title for s in reactions.blocks if isinstance(s, Section)] == \
        [w["s_hodograph"].format(name=j) for j in "OABS"]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_project_sheets_come_before_the_conclusion(lang):
    model = mechloop.load_model(SHEETS)
    document = build_document(model, lang=lang, project=project_documents(model, SHEETS))
    titles = section_titles(document)
    sheet3 = "Sheet 3" if lang == "en" else "Лист 3"
    sheet4 = "Sheet 4" if lang == "en" else "Лист 4"
    k3 = next(i for i, t in enumerate(titles) if t.startswith(sheet3))
    k4 = next(i for i, t in enumerate(titles) if t.startswith(sheet4))
    assert k4 == k3 + 1 and titles[k4 + 1] == TEXT[lang]["s_conclusion"]
    cam = document.sections[k4]
    assert any(isinstance(b, Table) for b in cam.blocks)
    assert any(isinstance(b, FigureItem) for b in cam.blocks)


# ------------------------------------------------------------------ numbers parsed back
def _close(text: str, expected: float, digits: int | None = None) -> None:
    """``text`` (a printed number) equals ``expected`` within half a unit of its last
    printed digit (plus a relative 1e-12); with ``digits``, of its last significant
    digit too (-10270 to 4 digits)."""
    text = plain(text)
    value = float(text)
    mantissa = text.split("e")[0]
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    exponent = int(text.split("e")[1]) if "e" in text else 0
    tolerance = 0.5 * 10.0 ** (exponent - decimals) + 1e-12 * abs(expected)
    if digits is not None and expected != 0:
        tolerance = max(tolerance, 0.5 * 10.0 ** (math.floor(math.log10(abs(expected)))
                                                  - digits + 1) * (1 + 1e-9))
    assert abs(value - expected) <= tolerance, (text, expected)


DISPLAYED = {"length": "mm", "force": "kN", "angular_velocity": "rpm"}
#: (length, force, angular velocity, acceleration) factors from SI of each display
FACTORS = {None: dict(m=1.0, N=1.0, w=1.0, unit_m="m", unit_w="rad/s", unit_N="N"),
           "display": dict(m=1e3, N=1e-3, w=30 / math.pi, unit_m="mm", unit_w="rpm",
                           unit_N="kN")}


def _model(display: str | None) -> mechloop.Model:
    data = yaml.safe_load(DYNAMIC.read_text())
    if display:
        data["display"] = {**DISPLAYED, "digits": 4}
    return mechloop.Model.from_dict(data)


@pytest.mark.parametrize("display", [None, "display"])
def test_parameter_tables_and_conclusion_hold_the_solvers_values(display):
    model = _model(display)
    dyn = mechloop.solve_dynamics(model)
    kin = dyn.kinematics
    f = FACTORS[display]
    document = build_document(model, lang="en")
    vectors = document.sections[0].blocks[1]
    assert vectors.header[3] == f"r, {f['unit_m']}" and vectors.header[5] == "α, °"
    for row in vectors.rows:
        n = int(row[0])
        for cell, name, factor in ((row[3], f"r{n}", f["m"]), (row[5], f"a{n}", None)):
            values = kin.value(name) * factor if factor else np.degrees(kin.value(name))
            numbers = NUMBER.findall(cell)
            expected = [values.min(), values.max()] if len(numbers) == 2 else [values[0]]
            for text, value in zip(numbers, expected, strict=True):
                _close(text, value)
    general = dict(document.sections[0].blocks[0].rows)
    speed = general["model time"]
    _close(NUMBER.findall(speed)[0], 3000.0)
    assert f["unit_w"].replace("rad/s", "rpm") in speed
    conclusion = {p.text.split(":")[0]: p.text for p in document.sections[-1].blocks}
    r3 = kin.value("r3") * f["m"]
    stroke = conclusion["Range of the output parameter r3"]
    value, low, high = NUMBER.findall(stroke.split(":")[1])
    _close(value, r3.max() - r3.min())
    _close(low, r3.min())
    _close(high, r3.max())
    assert f" {f['unit_m']} (" in stroke
    rate = conclusion["Extremes of the 1st derivative of r3"]
    low, high = NUMBER.findall(rate.split(":")[1])
    _close(low, kin.rate("r3").min() * f["m"])
    _close(high, kin.rate("r3").max() * f["m"])
    assert f"{f['unit_m']}/s …" in rate
    bal = next(v for k, v in conclusion.items() if k.startswith("Peak balancing load"))
    _close(NUMBER.findall(bal.split(":")[1])[0], np.abs(dyn.forces.balancing[1]).max())
    assert "N·m" in bal  # the moment's unit is not named in the display
    reaction = next(v for k, v in conclusion.items() if k.startswith("Peak reaction"))
    peaks = {n: np.abs(r.force).max() for n, r in dyn.forces.reactions.items()}
    joint = max(peaks, key=peaks.get)
    assert f"joint {joint}, " in reaction and f" {f['unit_N']} (" in reaction
    _close(NUMBER.findall(reaction.split(",")[1])[0], peaks[joint] * f["N"])
    reduced = next(v for k, v in conclusion.items() if k.startswith("Reduced inertia"))
    numbers = NUMBER.findall(reduced.split("J_red:", 1)[1])
    _close(numbers[0], dyn.reduced.inertia.min())
    _close(numbers[-1], dyn.reduced.d_inertia.max())  # per radian, as in the CSV
    assert "kg·m²/rad" in reduced
    forces = document.sections[5].blocks[2]
    assert forces.rows[0][2] == ("1 kN" if display else "1000 N")


@pytest.mark.parametrize("display", [None, "display"])
def test_appendix_holds_the_results_table_in_the_display_units(display):
    model = _model(display)
    dyn = mechloop.solve_dynamics(model)
    frame = dyn.to_frame()
    f = FACTORS[display]
    document = build_document(model, lang="en")
    tables = document.appendices[0].blocks
    columns: dict[str, list[str]] = {}
    for table in tables:
        assert len(table.header) <= 8 and table.header[0] == "position"
        assert [row[0] for row in table.rows] == [str(k) for k in range(len(frame))]
        for k, head in enumerate(table.header[1:], start=1):
            columns[head] = [row[k] for row in table.rows]
    checks = {f"r3, {f['unit_m']}": frame["r3 [m]"] * f["m"],
              f"dr3, {f['unit_m']}/s": frame["dr3 [m/s]"] * f["m"],
              f"dα1, {f['unit_w']}": frame["da1 [rad/s]"] * f["w"],
              f"RA, {f['unit_N']}": frame["RA [N]"] * f["N"],
              "M_bal, N·m": frame["M_bal [N*m]"], "α2, °": frame["a2 [deg]"],
              "J_red, kg·m²": frame["J_red [kg*m^2]"],
              "dJ_red, kg·m²/rad": frame["dJ_red [kg*m^2/rad]"]}
    for head, values in checks.items():
        for text, value in zip(columns[head], values, strict=True):
            _close(text, value, 4 if display else None)
    # every column of the frame but the empty ones is there, and no cell is empty text
    assert len(columns) == len(frame.columns) - 2  # the position, and no chain break
    cells = [c for column in columns.values() for c in column]
    assert all(cells) and not any(c.lower() in ("nan", "inf", "-inf") for c in cells)
    # zero to the printed precision is 0: ddα1 is zero at constant speed
    assert set(columns["ddα1, rad/s²"]) == {"0"}
    assert not any("e-" in c for head, col in columns.items() for c in col
                   if head.startswith(("r3", "α2", "RA")))


def test_numbers_zero_to_their_column_precision_print_as_0():
    shown = Shown(None, "en")
    assert shown.column([0.1, 5.04e-15, -0.05, np.nan]) == ["0.1", "0", "-0.05", "—"]
    assert shown.number(-1e-20, 300.0) == "0"
    assert Shown(None, "ru").text(1000.0, "N*m") == "1000 Н·м"
    assert Shown(None, "ru").text(30.0, "deg") == "30°"


def test_no_nan_or_empty_column_anywhere(documents):
    for document in documents.values():
        for text in texts(document):
            assert not re.search(r"\b(nan|inf)\b", text, flags=re.I), text
        for table in (b for s in [*document.sections, *document.appendices]
                      for b in walk(s.blocks) if isinstance(b, Table)):
            for k in range(len(table.header)):
                assert any(row[k] for row in table.rows), (table.caption, table.header[k])


# ------------------------------------------------------------------ Russian
RUSSIAN_MODELS = [DYNAMIC, KINEMATIC, EXAMPLES / "engine_indicator.yaml",
                  EXAMPLES / "spring_release.yaml", EXAMPLES / "gear_pair_dynamics.yaml",
                  EXAMPLES / "course/01_an10_landing_gear.yaml",
                  EXAMPLES / "course/05_compressor.yaml",
                  EXAMPLES / "course/17_oil_pump.yaml", SHEETS]


@pytest.mark.parametrize("path", RUSSIAN_MODELS, ids=lambda p: p.stem)
def test_the_russian_document_has_no_english_words(path):
    model = mechloop.load_model(path)
    project = project_documents(model, path) if model.project else None
    document = build_document(model, lang="ru", project=project)
    names = model_names(model)
    if project is not None:  # the names of the cam and the gears in their documents
        names += [getattr(project.cam, "name", None) or "",
                  getattr(project.gears, "pair_name", None) or "",
                  getattr(project.gears, "train_name", None) or ""]
    found = {word for text in texts(document) for word in latin_words(text, names)}
    assert not found, f"English in the Russian report of {path.name}: {sorted(found)}"


# ------------------------------------------------------------------ breaks and positions
@pytest.fixture(scope="module")
def broken_at_0() -> mechloop.Model:
    """The four-bar of four_bar_break_ahead.yaml turned from 180°: its crank cannot pass
    positions 0-5 and 67-72."""
    data = yaml.safe_load((EXAMPLES / "four_bar_break_ahead.yaml").read_text())
    data["arguments"] = {1: {"table": {0: 180, 72: 540}}}
    data.pop("simulate")
    return mechloop.Model.from_dict(data)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_model_broken_at_position_0_gets_its_report(broken_at_0, lang):
    results = mechloop.solve(broken_at_0)
    assert results.broken[0]
    told: list[str] = []
    document = build_document(broken_at_0, lang=lang, warn=told.append)
    first = [b for b in document.sections[0].blocks if isinstance(b, Paragraph)]
    assert first[0].kind == "warning"
    text = first[0].text
    assert "0-5, 67-72" in text
    assert ("ontour 1 (Pl4)" if lang == "en" else "онтур 1 (Пл4)") in text
    assert ("triangle inequality" if lang == "en" else "неравенство треугольника") in text
    conclusion = [p.text for p in document.sections[-1].blocks]
    assert any("0-5, 67-72" in p for p in conclusion)
    assert told and ("WARNING" if lang == "en" else "ВНИМАНИЕ") in told[0]
    # the cycle figures are not given: no efficiency, no machine motion
    assert not any(p.startswith(("Mechanical efficiency", "Механический КПД"))
                   for p in conclusion)
    appendix = document.appendices[0].blocks
    assert appendix[-1].header[-1] == TEXT[lang]["chain_break"]
    assert appendix[-1].rows[0][-1] == TEXT[lang]["chain_break"]
    assert appendix[-1].rows[30][-1] == ""
    assert "—" in appendix[0].rows[0]
    increment = document.sections[2].blocks[0]
    assert "position 6" in increment.caption or "положения 6" in increment.caption


def test_every_figure_of_a_broken_model_is_drawn(broken_at_0):
    import matplotlib.pyplot as plt

    document = build_document(broken_at_0, lang="ru")
    for section in document.sections:
        for block in walk(section.blocks):
            if isinstance(block, FigureItem):
                plt.close(block.draw())


def test_position_chooses_the_scheme_and_a_broken_one_is_refused(broken_at_0):
    document = build_document(broken_at_0, lang="en", position=40)
    plan = next(b for b in document.sections[0].blocks if isinstance(b, FigureItem))
    assert plan.caption.endswith("position 40")
    default = build_document(broken_at_0, lang="en")
    assert next(b for b in default.sections[0].blocks
            if isinstance(b, FigureItem)).caption.endswith("position 24")
    with pytest.raises(HintedError) as caught:
        build_document(broken_at_0, lang="en", position=3)
    assert "breaks at that position" in caught.value.message
    assert "6-66" in caught.value.hint
    with pytest.raises(HintedError, match="0 to 72"):
        build_document(broken_at_0, lang="en", position=73)


def test_cli_position_and_title_options(tmp_path, monkeypatch):
    import mechloop.report.write as write

    made = {}

    def capture(document, path, *, progress=None):
        made[Path(path).suffix] = document
        Path(path).write_bytes(b"")
        return Path(path)

    monkeypatch.setattr(write, "write_document", capture)
    result = CliRunner().invoke(app, [
        "report", str(DYNAMIC), "-o", str(tmp_path / "r.pdf"), "-o",
        str(tmp_path / "r.docx"), "--lang", "ru", "--position", "10", "--student",
        "П. Сидоров", "--group", "2305", "--year", "2025"])
    assert result.exit_code == 0, result.output
    assert set(made) == {".pdf", ".docx"}
    assert f"записан {tmp_path / 'r.pdf'}" in " ".join(result.output.split())
    title = made[".pdf"].title
    # the options over the model's report: section, which fills the rest
    assert title.people == [("Студент", "П. Сидоров"), ("Группа", "2305"),
                            ("Руководитель", "A. Petrov")]
    assert title.organisation == ["Samara University", "Department of machine design"]
    assert title.place_year == "Samara 2025"
    assert title.kind == "Курсовой проект" and title.course == "Теория механизмов и машин"
    plan = next(b for b in made[".pdf"].sections[0].blocks if isinstance(b, FigureItem))
    assert plan.caption.endswith("положении 10")
    bad = CliRunner().invoke(app, ["report", str(DYNAMIC), "-o", str(tmp_path / "x.pdf"),
                                   "--position", "100"])
    assert bad.exit_code == 2 and "0 to 72" in bad.output and "Traceback" not in bad.output


def test_title_page_defaults_without_a_report_section():
    import datetime

    model = mechloop.load_model(KINEMATIC)
    assert model.report is None
    title = build_document(model, lang="en").title
    assert (title.kind, title.course, title.title) == (
        "Course project", "Theory of machines and mechanisms",
        "Kinematic and dynamic analysis of the mechanism")
    assert title.subject.startswith(model.name)
    assert title.organisation == [] and title.people == []
    assert title.place_year == str(datetime.date.today().year)


def test_report_section_is_checked_where_it_is_written(tmp_path):
    data = yaml.safe_load(DYNAMIC.read_text())
    data["report"]["grade"] = "A"
    with pytest.raises(mechloop.ModelError) as caught:
        mechloop.Model.from_dict(data)
    assert caught.value.problems[0].path[:2] == ("report", "grade")


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_machine_gets_its_motion_flywheel_and_efficiency(lang):
    model = mechloop.load_model(EXAMPLES / "single_cylinder_engine.yaml")
    dyn = mechloop.solve_dynamics(model)
    document = build_document(model, lang=lang)
    w = TEXT[lang]
    assert [s.title for s in document.sections[6].blocks] == [
        w["s_reduced_sub"], w["s_balancing"], w["s_summary"], w["s_motion"]]
    conclusion = [p.text for p in document.sections[-1].blocks]
    flywheel = next(p for p in conclusion if p.startswith(w["flywheel"][:12]))
    delta, value = NUMBER.findall(flywheel.split("δ = ")[1])
    _close(delta, dyn.cycle.delta)
    _close(value, float(dyn.cycle.flywheel))
    assert flywheel.endswith(("kg·m².", "кг·м²."))
    efficiency = next(p for p in conclusion if "η = " in p)
    _close(NUMBER.findall(efficiency.split("η = ")[1])[0], 100 * float(dyn.summary.efficiency))
    assert efficiency.endswith(" %.")


def test_the_plots_take_the_units_of_the_tables():
    """Angular velocities in rad/s (as the tables and the conclusion) unless the display
    names another unit."""
    import matplotlib.pyplot as plt
    from matplotlib.text import Text

    for display, unit in ((None, "rad/s"), ({"angular_velocity": "rpm"}, "rpm")):
        data = yaml.safe_load((EXAMPLES / "four_bar.yaml").read_text())
        if display:
            data["display"] = display
        document = build_document(mechloop.Model.from_dict(data), lang="en")
        figure = document.sections[2].blocks[0].draw()
        labels = [t.get_text() for t in figure.findobj(Text) if t.get_text().startswith("da3")]
        plt.close(figure)
        assert labels and all(unit in label and "deg/s" not in label for label in labels)


@pytest.mark.parametrize("path", RUSSIAN_MODELS, ids=lambda p: p.stem)
def test_the_english_document_has_no_russian_words(path):
    model = mechloop.load_model(path)
    project = project_documents(model, path) if model.project else None
    document = build_document(model, lang="en", project=project)
    found = [text for text in texts(document) if re.search("[А-Яа-яЁё]", text)
             and not (model.description and model.description in text)]
    assert not found, found[:3]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_break_between_two_positions_is_explained_with_its_angles(lang):
    from oracles.dynamic_models import four_bar_data

    data = {"name": "four-bar, break between positions", **four_bar_data(0.149999, 73),
            "moments": [{"name": "resistance", "body": 3, "value": -2.0}]}
    model = mechloop.Model.from_dict(data)
    [found] = mechloop.solve(model).breaks_between
    document = build_document(model, lang=lang)
    [text] = [p.text for p in document.sections[-1].blocks
              if p.text.startswith(("Contour 1 (Pl4)", "Контур 1 (Пл4)"))]
    assert f"{found.after} {'and' if lang == 'en' else 'и'} {found.after + 1}" in text
    numbers = re.findall(r"(-?\d+(?:[.,]\d+)?)°", text)
    expected = np.degrees([*found.at, found.start, found.stop])
    assert len(numbers) == 4
    for printed, value in zip(numbers, expected, strict=True):
        _close(printed, value)


def test_rounding_noise_prints_as_zero_and_nothing_else_does():
    """A slider's inertia moment (1e-12 N·m of rounding beside 50 N·m) is 0 in the
    appendix; a value at 1e-6 of its unit's largest is kept."""
    import pandas as pd

    from mechloop.report.appendix import _rounding_noise_as_zero

    frame = pd.DataFrame({"M_bal [N*m]": [50.0, -20.0, np.nan],
                          "Mi3 [N*m]": [1.1e-12, -8e-13, np.nan],
                          "Mi2 [N*m]": [5e-5, 0.0, np.nan],
                          "r3 [m]": [1e-13, 2e-13, np.nan]})
    out = _rounding_noise_as_zero(frame)
    assert out["Mi3 [N*m]"].tolist()[:2] == [0.0, 0.0]
    assert out["M_bal [N*m]"].tolist()[:2] == [50.0, -20.0]
    assert out["Mi2 [N*m]"].tolist()[:2] == [5e-5, 0.0]
    assert out["r3 [m]"].tolist()[:2] == [1e-13, 2e-13]  # its own unit's scale
    assert np.isnan(out.iloc[2]).all()
    model = mechloop.load_model(ROOT / "examples" / "crank_slider_dynamics.yaml")
    document = build_document(model, lang="en")
    cells = [c for block in walk(document.appendices) if isinstance(block, Table)
             for row in block.rows for c in row]
    assert not [c for c in cells if re.search(r"e-\d", c)]
