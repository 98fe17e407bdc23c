"""The report of a model with spatial contours (issue 17), built as a document without
typesetting (every page typeset: tests/test_report_pages.py): the planar report's
sections in its order with the spatial ones, none for what is not computed (the machine
motion; the reactions of a model without joints, which the report says need them: the
reactions' section is in tests/test_report_spatial_reactions.py); the tables hold the
solver's values in the display units — β, the vector ends placed independently
(:class:`mechloop.spatial.points.Placement3`), the appendix's columns — and the works of
the loads equal their closed forms; both languages."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import yaml
from helpers.latin import latin_words, model_names

import mechloop
from mechloop.report.content import build_document
from mechloop.report.document import FigureItem, Paragraph, Section, Table, texts, walk
from mechloop.report.spatial_words import spatial_words
from mechloop.spatial.dynamics import solve_spatial_dynamics
from mechloop.spatial.points import Placement3

ROOT = Path(__file__).resolve().parents[1]
SPATIAL = ROOT / "examples" / "spatial"
DYNAMIC = SPATIAL / "rssr_dynamics.yaml"
#: Significant digits of the report's numbers (no display: section).
RTOL = 1e-4
NUMBER = re.compile(r"-?\d+(?:[.,]\d+)?(?:e-?\d+|·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?")
_DIGITS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def numbers(text: str) -> list[float]:
    """The numbers of a cell ('1,5·10⁻⁵' and '1.5e-5' alike)."""
    out = []
    for found in NUMBER.findall(text.replace("−", "-")):
        plain = found.replace(",", ".").replace("·10", "e").translate(_DIGITS)
        out.append(float(plain))
    return out


@pytest.fixture(scope="module")
def solved():
    model = mechloop.load_model(DYNAMIC)
    return model, solve_spatial_dynamics(model)


@pytest.fixture(scope="module")
def documents(solved):
    model, _ = solved
    return {lang: build_document(model, lang=lang) for lang in ("en", "ru")}


def _tables(document) -> dict[str, Table]:
    return {b.caption: b for s in [*document.sections, *document.appendices]
            for b in walk(s.blocks) if isinstance(b, Table)}


def _section(document, key: str, lang: str) -> Section:
    title = spatial_words(lang)[key]
    return next(s for s in document.sections if s.title == title)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_sections_in_the_planar_order_with_the_spatial_ones(documents, lang):
    w = spatial_words(lang)
    document = documents[lang]
    assert [s.title for s in document.sections] == [
        w["s_parameters"], w["s_formula"], w["s_increment"].format(name="β3"),
        w["s_angles3"], w["s_dependence"], w["s_trajectories"], w["s_masses"],
        w["s_reduced"], w["s_centres"], w["s_conclusion"]]
    subsections = [b.title for s in document.sections for b in walk(s.blocks)
                   if isinstance(b, Section)]
    assert subsections == [w["s_reduced_sub"], w["s_balancing"], w["s_energy"]]
    titles = {*(s.title for s in document.sections), *subsections}
    assert not titles & {w["s_reactions"], w["s_motion"]}  # not computed: no heading
    said = " ".join(b.text for b in walk(_section(document, "s_reduced", lang).blocks)
                    if isinstance(b, Paragraph))
    assert w["p_virtual_power"] in said and w["p_no_joints"] in said
    figures = [b for s in document.sections for b in walk(s.blocks)
               if isinstance(b, FigureItem)]
    assert w["f_plan3"].format(position=24) in [f.caption for f in figures]
    assert [s.title for s in document.appendices] == [w["s_appendix"]]


def test_the_vectors_table_holds_r_alpha_and_beta(documents, solved):
    _, dyn = solved
    kin = dyn.kinematics
    for lang, document in documents.items():
        table = _tables(document)[spatial_words(lang)["t_vectors3"]]
        assert table.header[-2:] == (f"β: {spatial_words(lang)['h_role']}", "β, °")
        for row in table.rows:
            n = int(row[0])
            for cell, name in ((row[3], f"r{n}"), (row[5], f"a{n}"), (row[7], f"b{n}")):
                values = np.asarray(kin.value(name), dtype=float)
                values = values if name[0] == "r" else np.degrees(values)
                expected = [values.min(), values.max()]
                shown = numbers(cell)
                expected = expected[:len(shown)] if np.ptp(values) > 1e-12 else [values[0]]
                assert shown == pytest.approx(expected, rel=RTOL, abs=1e-9), (lang, name)


def test_vector_ends_are_the_independently_placed_points(documents, solved):
    _, dyn = solved
    kin = dyn.kinematics
    place = Placement3(kin)
    for lang, document in documents.items():
        table = _tables(document)[spatial_words(lang)["t_joints"].format(position=24)]
        assert [int(r[0]) for r in table.rows] == sorted(kin.model.vectors)
        scale = max(abs(v) for r in table.rows for c in r[1:] for v in numbers(c))
        for row in table.rows:
            n = int(row[0])
            expected = [*place.tail(n).p[:, 24], *place.head(n).p[:, 24]]
            shown = [numbers(c)[0] for c in row[1:]]
            assert shown == pytest.approx(expected, abs=RTOL * scale), (lang, n)


def test_the_works_of_the_loads_equal_their_closed_forms(documents, solved):
    """Over the cycle a constant moment M about the output axis (Y) does the positive
    work |M|·(β3max − β3min), gravity on a body m·g·(yS max − yS min); every load's
    total and the sum are zero over the closed cycle (the kinetic energy returns)."""
    _, dyn = solved
    kin = dyn.kinematics
    beta = np.asarray(kin.value("b3"))
    closed = {"M_out": 2.0 * np.ptp(beta),
              "G1": 0.4 * 9.81 * np.ptp(dyn.centers[1].p[1]),
              "G2": 0.3 * 9.81 * np.ptp(dyn.centers[2].p[1])}
    for lang, document in documents.items():
        table = _tables(document)[spatial_words(lang)["t_works"]]
        rows = {r[0]: [numbers(c)[0] for c in r[1:]] for r in table.rows}
        for name, work in closed.items():
            plus, minus, total = rows[name]
            assert plus == pytest.approx(work, rel=2e-3), (lang, name)
            assert minus == pytest.approx(-work, rel=2e-3), (lang, name)
            assert total == 0, (lang, name)
        balancing = spatial_words(lang)["bal_load"].format(name="M_bal")
        assert balancing in rows
        energy = _tables(document)[spatial_words(lang)["t_energy"]]
        low, high = numbers(energy.rows[0][1])
        assert [low, high] == pytest.approx([dyn.kinetic_energy.min(),
                                             dyn.kinetic_energy.max()], rel=RTOL)
        assert [numbers(r[1])[0] for r in energy.rows[1:]] == [0, 0]


def test_the_appendix_holds_every_column_of_the_solver(documents, solved):
    _, dyn = solved
    frame = dyn.to_frame()
    for lang, document in documents.items():
        parts = [t for t in _tables(document).values() if t.rows and len(t.rows) == 73
                 and t.caption.startswith(spatial_words(lang)["t_appendix"][:8])]
        columns = {h: [row[k] for row in t.rows] for t in parts
                   for k, h in enumerate(t.header)}
        for column, shown in (("b3 [deg]", "β3, °"), ("x2 [m]", "x2, " + (
                "м" if lang == "ru" else "m")), ("J_red [kg*m^2]", None),
                ("T [J]", None)):
            header = shown or next(h for h in columns if h.startswith(column.split()[0] + ","))
            values = frame[column].to_numpy(dtype=float)
            cells = [numbers(c)[0] for c in columns[header]]
            assert cells == pytest.approx(values, abs=RTOL * np.abs(values).max()), column


def test_the_conclusion_and_formula_in_the_spatial_terms(documents, solved):
    _, dyn = solved
    beta = np.degrees(np.asarray(dyn.kinematics.value("b3")))
    for lang, document in documents.items():
        conclusion = [b.text for b in _section(document, "s_conclusion", lang).blocks]
        assert numbers(conclusion[0])[1:] == pytest.approx([np.ptp(beta), beta.min(),
                                                            beta.max()], rel=RTOL)
        assert numbers(conclusion[-1]) == pytest.approx(
            [dyn.kinetic_energy.min(), dyn.kinetic_energy.max()], rel=RTOL)
        formula = next(b.text for b in _section(document, "s_formula", lang).blocks
                       if isinstance(b, Paragraph))
        assert formula.count("n=3") == 2
        assert ("Pr10" if lang == "en" else "Пр10") in formula
        assert ("(2 solution(s))" if lang == "en" else "(решений: 2)") in formula
        figure = next(b for b in _section(document, "s_formula", lang).blocks
                      if isinstance(b, FigureItem)).draw()
        boxes = [t.get_text() for ax in figure.axes for t in ax.texts if "m=" in t.get_text()]
        assert len(boxes) == 2 and all("\nn=3, m=" in box for box in boxes), boxes


def test_each_language_holds_only_its_words(documents, solved):
    model, _ = solved
    names = [n for n in model_names(model) if n]
    for lang, document in documents.items():
        text = " ".join(texts(document))
        spoken = [re.sub("|".join(map(re.escape, names)), "", t) for t in texts(document)]
        if lang == "ru":
            assert latin_words(text, names) == []
            assert not [t for t in spoken if re.search(r"(?<![\w.])\d+\.\d+(?![\w.])", t)]
        else:
            assert not re.findall(r"[А-Яа-яЁё]+", " ".join(spoken))


@pytest.mark.parametrize("name", ["rssr", "spherical_four_bar", "landing_gear_skewed_axis",
                                  "swashplate"])
def test_a_kinematic_spatial_model_gets_the_kinematic_report(name):
    model = mechloop.load_model(SPATIAL / f"{name}.yaml")
    document = build_document(model, lang="ru")
    w = spatial_words("ru")
    titles = [s.title for s in document.sections]
    assert titles[:2] == [w["s_parameters"], w["s_formula"]]
    assert titles[3:] == [w["s_angles3"], w["s_dependence"], w["s_trajectories"],
                          w["s_conclusion"]]
    assert latin_words(" ".join(texts(document)), [n for n in model_names(model) if n]) == []
    dependence = next(b for b in document.sections[4].blocks if isinstance(b, FigureItem))
    kind = mechloop.solve(model).argument_kinds[1]
    assert dependence.caption.endswith("s1" if kind == "length" else "φ1"), kind


def _rssr(**changes) -> mechloop.Model:
    data = yaml.safe_load(DYNAMIC.read_text())
    data.update(changes)
    return mechloop.Model.from_dict(data)


def test_the_tables_take_the_display_units(solved):
    """With ``display: {length: mm, energy: mJ, digits: 4}`` the coordinates are in mm
    and the works in mJ, to 4 digits."""
    _, dyn = solved
    model = _rssr(display={"length": "mm", "energy": "mJ", "digits": 4})
    document = build_document(model, lang="en")
    tables = _tables(document)
    joints = tables[spatial_words("en")["t_joints"].format(position=24)]
    assert joints.header[1] == "tail x, mm"
    head = Placement3(dyn.kinematics).head(2).p[:, 24] * 1000
    # 4 digits of the column's largest value (116.7 mm): to 0.1 mm
    assert [numbers(c)[0] for c in joints.rows[1][4:]] == pytest.approx(head, abs=0.05)
    works = tables[spatial_words("en")["t_works"]]
    assert works.header[1] == "A+, mJ"
    assert numbers(dict((r[0], r[1]) for r in works.rows)["M_out"])[0] == pytest.approx(
        2000 * np.ptp(dyn.kinematics.value("b3")), rel=2e-3)


def test_a_chain_break_is_said_and_the_cycle_works_left_out():
    """The crank made longer than the RSSR can take (r1 = 75 mm): the chain breaks at
    positions 48-58; the report says where and why in each language, gives no works
    over the cycle, and leaves those rows of the appendix empty."""
    data = yaml.safe_load(DYNAMIC.read_text())
    data["vectors"][1]["r"] = 75
    model = mechloop.Model.from_dict(data)
    broken = np.flatnonzero(mechloop.solve(model).broken)
    assert broken.tolist() == list(range(48, 59))
    for lang in ("en", "ru"):
        w = spatial_words(lang)
        warned: list[str] = []
        document = build_document(model, lang=lang, warn=warned.append)
        warnings = [b.text for s in document.sections for b in walk(s.blocks)
                    if isinstance(b, Paragraph) and b.kind == "warning"]
        assert len(warnings) == 2 and "48-58" in warnings[0] and "48-58" in warnings[1]
        assert warned and warned[0] == warnings[0]
        assert ("Пр10" in warnings[0]) == (lang == "ru")
        assert "контур не собирается" not in warnings[0]  # the reason itself, translated
        tables = _tables(document)
        assert w["t_works"] not in tables and w["t_energy"] not in tables
        appendix = next(t for c, t in tables.items() if c.startswith(w["t_appendix"][:8]))
        assert all(appendix.rows[p][3] == "—" for p in broken)
        if lang == "ru":
            assert latin_words(" ".join(texts(document)), model_names(model)) == []


def test_a_planar_model_written_as_spatial_concludes_as_the_planar_report():
    """The four-bar's loop written as a spatial contour (β2 its third unknown, all β 0),
    its coupler-point loop planar beside it: the conclusion's numbers are the planar
    report's, and the vectors of the planar contour have no β in the vectors' table."""
    data = yaml.safe_load((ROOT / "examples" / "four_bar.yaml").read_text())
    planar = mechloop.Model.from_dict(data)
    data["contours"][0]["spatial"] = True
    data["vectors"][2]["b"] = "function"
    mixed = mechloop.Model.from_dict(data)
    for lang in ("en", "ru"):
        expected = build_document(planar, lang=lang, output="a3")
        document = build_document(mixed, lang=lang, output="a3")
        got = [numbers(b.text) for b in _section(document, "s_conclusion", lang).blocks]
        want = [numbers(b.text) for b in _section(expected, "s_conclusion", lang).blocks]
        assert got == want and len(got) == 4, lang
        table = _tables(document)[spatial_words(lang)["t_vectors3"]]
        no_beta = [r[0] for r in table.rows if r[6:] == ("—", "—")]
        assert no_beta == ["5", "6", "7"], lang
