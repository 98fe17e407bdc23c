"""The joint reactions in the report of a model with spatial contours (issue 17), built as a
document without typesetting (every page typeset: tests/test_report_pages.py): the
section 'Reactions in the kinematic pairs' in the planar report's place, its tables equal
to :class:`~mechloop.spatial.reactions.SpatialReactions` in the display units, the
figure's lines equal to the magnitudes and the hodograph's curves to the components, the
balancing load by the Newton–Euler equations beside the one by virtual power and their
difference, the conclusion's peak reaction equal to the largest one, idle motions and
singular positions said in words, the words of every joint type in both languages."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import yaml
from helpers.latin import latin_words, model_names
from test_report_spatial import RTOL, numbers
from test_spatial_reactions import _crank_slider

import mechloop
from mechloop.model.load import model_from_data
from mechloop.report.content import build_document
from mechloop.report.document import FigureItem, Paragraph, Section, Table, texts, walk
from mechloop.report.numbers import Shown
from mechloop.report.spatial_reactions import (
    idle_text,
    pairs_table3,
    reaction_table,
    table_positions,
)
from mechloop.report.spatial_words import spatial_words
from mechloop.solve.results import compress_positions
from mechloop.spatial import reactions as reactions_module
from mechloop.spatial.dynamics import solve_spatial_dynamics
from mechloop.views.display import Display
from mechloop.views.figure import ViewError
from mechloop.views.russian import figure_texts
from mechloop.views.spatial_reactions import plot_spatial_hodograph, plot_spatial_reactions

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = ROOT / "examples" / "spatial" / "rssr_reactions.yaml"
#: The scheme's position of the RSSR's report (a third of its 72 steps).
POSITION = 24
LANGS = ("en", "ru")


@pytest.fixture(scope="module")
def solved():
    model = mechloop.load_model(EXAMPLE)
    return model, solve_spatial_dynamics(model)


@pytest.fixture(scope="module")
def documents(solved):
    model, _ = solved
    return {lang: build_document(model, lang=lang) for lang in LANGS}


def _section(document, key: str, lang: str) -> Section:
    return next(s for s in document.sections if s.title == spatial_words(lang)[key])


def _blocks(section: Section, kind) -> list:
    return [b for b in walk(section.blocks) if isinstance(b, kind)]


def _data(data: dict | None = None, **changes) -> mechloop.Model:
    data = data or yaml.safe_load(EXAMPLE.read_text(encoding="utf-8"))
    data.update(changes)
    return model_from_data(data)


@pytest.mark.parametrize("lang", LANGS)
def test_the_section_stands_where_the_planar_report_has_it(documents, solved, lang):
    _, dyn = solved
    w = spatial_words(lang)
    titles = [s.title for s in documents[lang].sections]
    at = titles.index(w["s_reactions"])
    assert titles[at - 1:at + 2] == [w["s_reduced"], w["s_reactions"], w["s_centres"]]
    section = documents[lang].sections[at]
    assert [s.title for s in _blocks(section, Section)] == [
        w["s_joint3"].format(name=n) for n in dyn.reactions.joints]
    said = " ".join(p.text for p in _blocks(_section(documents[lang], "s_reduced", lang),
                                            Paragraph))
    assert w["p_joints"] in said and w["p_no_joints"] not in said
    first = _blocks(section, Paragraph)[0].text
    assert numbers(first) == [3, 18, 17, 17]  # bodies, equations, unknowns, rank
    assert (dyn.reactions.unknowns, dyn.reactions.rank) == (17, 17)


def test_the_pairs_table_names_every_joint_in_both_languages(documents, solved):
    model, _ = solved
    for lang, document in documents.items():
        w = spatial_words(lang)
        table = next(t for t in _blocks(_section(document, "s_reactions", lang), Table)
                     if t.caption == w["t_pairs3"])
        axis = {"O": w["d_vector"].format(x=0, y=0, z=1),
                "D": w["d_vector"].format(x=0, y=1, z=0), "A": "—", "B": "—"}
        for row in table.rows:
            joint = model.joints[row[0]]
            assert row[1] == w[joint.type]
            assert row[2] == f"{joint.bodies[0]}–{joint.bodies[1]}"
            assert row[4] == axis[row[0]]
            assert row[5] == ("3; 2" if joint.type == "revolute" else "3; 0")
        assert [r[3] for r in table.rows] == [w["p_tail"].format(v=1), w["p_head"].format(
            v=1), w["p_head"].format(v=2), w["p_tail"].format(v=3)]


def _joint_tables(document, lang: str) -> dict[str, Table]:
    w = spatial_words(lang)
    out = {}
    for sub in _blocks(_section(document, "s_reactions", lang), Section):
        name = re.fullmatch(w["s_joint3"].format(name="(.+)"), sub.title).group(1)
        out[name] = next(b for b in sub.blocks if isinstance(b, Table))
    return out


def test_the_tables_hold_the_reactions_at_the_reports_positions(documents, solved):
    """Every joint's table: its force's x, y, z and size and, for a revolute joint, its
    moment's, at positions 0, 6, …, 72 (the scheme's position 24 among them), each to
    the precision of the table's largest force (moment)."""
    _, dyn = solved
    rows = list(range(0, 73, 6))
    assert table_positions(73, POSITION) == rows
    for lang, document in documents.items():
        tables = _joint_tables(document, lang)
        assert list(tables) == list(dyn.reactions.joints)
        for name, table in tables.items():
            reaction = dyn.reactions.joints[name]
            assert [int(r[0]) for r in table.rows] == rows
            shown = np.array([[numbers(c)[0] for c in r[1:]] for r in table.rows]).T
            parts = [reaction.force]
            if reaction.joint.kind == "revolute":
                parts.append(reaction.moment)
            assert shown.shape[0] == 4 * len(parts), (lang, name)
            for k, values in enumerate(parts):
                want = np.vstack([values, np.linalg.norm(values, axis=0)])[:, rows]
                got = shown[4 * k:4 * k + 4]
                assert got == pytest.approx(want, abs=RTOL * np.abs(want).max()), name


def test_the_tables_conclusion_and_figures_take_the_display_units(solved):
    """With ``display: {force: kN, moment: N*mm, digits: 4}`` the tables, the conclusion
    and the figures are in kN and N·mm."""
    _, dyn = solved
    model = _data(display={"force": "kN", "moment": "N*mm", "digits": 4})
    document = build_document(model, lang="en")
    table = _joint_tables(document, "en")["D"]
    assert table.header[1:] == ("R_x, kN", "R_y, kN", "R_z, kN", "|R|, kN", "R_mx, N·mm",
                                "R_my, N·mm", "R_mz, N·mm", "|R_m|, N·mm")
    reaction = dyn.reactions.joints["D"]
    got = np.array([[numbers(c)[0] for c in r[1:]] for r in table.rows]).T
    force = np.vstack([reaction.force, np.linalg.norm(reaction.force, axis=0)])[:, ::6]
    moment = np.vstack([reaction.moment, np.linalg.norm(reaction.moment, axis=0)])[:, ::6]
    # 4 digits of the largest value (49.6 N = 0.0496 kN; 2052 N·mm)
    assert got[:4] == pytest.approx(force / 1000, abs=5e-6)
    assert got[4:] == pytest.approx(moment * 1000, abs=0.5)
    conclusion = [p.text for p in _section(document, "s_conclusion", "en").blocks]
    assert next(t for t in conclusion if t.startswith("Peak reaction:")).endswith(
        "0.04975 kN (at position 7).")
    figure = next(f for f in _blocks(_section(document, "s_reactions", "en"), FigureItem)
                  ).draw()
    lines = {ln.get_gid(): ln.get_ydata() for ax in figure.axes for ln in ax.get_lines()}
    assert lines["|RD|"] == pytest.approx(np.linalg.norm(reaction.force, axis=0) / 1000)
    assert lines["|RD_m|"] == pytest.approx(np.linalg.norm(reaction.moment, axis=0) * 1000)
    assert figure.axes[0].get_ylabel() == "reaction [kN]"


def test_the_figure_draws_the_magnitudes_of_every_joint(documents, solved):
    _, dyn = solved
    item = _blocks(_section(documents["en"], "s_reactions", "en"), FigureItem)[0]
    assert item.caption == spatial_words("en")["f_reactions3m"]
    figure = item.draw()
    top, bottom = figure.axes
    forces = {ln.get_gid(): ln for ln in top.get_lines()}
    moments = {ln.get_gid(): ln for ln in bottom.get_lines()}
    assert list(forces) == [f"|R{n}|" for n in "OABD"]
    assert list(moments) == ["|RO_m|", "|RD_m|"]  # the balls have no moment
    for name, reaction in dyn.reactions.joints.items():
        line = forces[f"|R{name}|"]
        assert np.array_equal(line.get_xdata(), np.arange(73))
        assert np.array_equal(line.get_ydata(), np.linalg.norm(reaction.force, axis=0))
        if f"|R{name}_m|" in moments:
            assert np.array_equal(moments[f"|R{name}_m|"].get_ydata(),
                                  np.linalg.norm(reaction.moment, axis=0))


def test_the_hodograph_is_the_force_in_3d_and_its_projections(documents, solved):
    """Joint D's hodograph: the 3-D curve is its force (x, y, z), each projection drops
    one coordinate (XY: z, ZY: x, XZ: y), the arrow ends at the force at position 24."""
    _, dyn = solved
    force = dyn.reactions.joints["D"].force
    sub = next(s for s in _blocks(_section(documents["en"], "s_reactions", "en"), Section)
               if s.title.endswith(" D"))
    item = next(b for b in sub.blocks if isinstance(b, FigureItem))
    assert item.caption == spatial_words("en")["f_hodograph3"].format(name="D",
                                                                       position=POSITION)
    figure = item.draw()
    curves = [ln for ax in figure.axes for ln in ax.get_lines() if ln.get_gid() == "RD"]
    assert len(curves) == 4
    spatial = [ln for ln in curves if hasattr(ln, "get_data_3d")]
    assert len(spatial) == 1 and np.array_equal(np.array(spatial[0].get_data_3d()), force)
    flat = {ax.get_title(): ax for ax in figure.axes if ax.name != "3d"}
    for title, (h, v) in (("front view XY", (0, 1)), ("side view ZY", (2, 1)),
                          ("top view XZ", (0, 2))):
        (line,) = [ln for ln in flat[title].get_lines() if ln.get_gid() == "RD"]
        assert np.array_equal(line.get_xdata(), force[h])
        assert np.array_equal(line.get_ydata(), force[v])
        arrow = flat[title].texts[0]  # the annotation from the origin
        assert arrow.xy == pytest.approx((force[h, POSITION], force[v, POSITION]))
        assert arrow.xyann == (0.0, 0.0)


def test_the_hodograph_of_a_moment_and_what_it_refuses(solved):
    _, dyn = solved
    figure = plot_spatial_hodograph(dyn, "O", part="moment", views="3d",
                                    display=Display(moment="N*mm"))
    (curve,) = [ln for ln in figure.axes[0].get_lines() if ln.get_gid() == "RO_m"]
    assert np.allclose(np.array(curve.get_data_3d()), dyn.reactions.joints["O"].moment * 1e3)
    for call, words in ((lambda: plot_spatial_hodograph(dyn, "A", part="moment"),
                         "no moment"),
                        (lambda: plot_spatial_hodograph(dyn, "Q"), "no joint 'Q'"),
                        (lambda: plot_spatial_hodograph(dyn, "O", part="torque"),
                         "unknown part"),
                        (lambda: plot_spatial_hodograph(dyn, "O", position=73), "outside"),
                        (lambda: plot_spatial_reactions(solve_spatial_dynamics(_data(
                            joints=None))), "no joint reactions")):
        with pytest.raises(ViewError, match=words):
            call()


def test_the_balancing_load_by_both_methods_and_their_difference(documents, solved):
    _, dyn = solved
    ne, vp = dyn.reactions.balancing[1], dyn.balancing[1]
    for lang, document in documents.items():
        w = spatial_words(lang)
        sub = next(s for s in _blocks(_section(document, "s_reduced", lang), Section)
                   if s.title == w["s_balancing"])
        figure, paragraph = sub.blocks
        assert figure.caption == w["f_balancing3_ne"]
        diff, share, largest = numbers(paragraph.text)
        assert diff == pytest.approx(np.abs(ne - vp).max(), rel=0.05)
        assert share == pytest.approx(np.abs(ne - vp).max() / np.abs(vp).max(), rel=0.05)
        assert largest == pytest.approx(np.abs(vp).max(), rel=RTOL)
        assert diff <= 1e-12 * largest
    lines = {ln.get_label(): ln for ax in figure.draw().axes for ln in ax.get_lines()}
    solid, dashed = lines["M_bal [N*m]"], lines["M_bal_vp [N*m]"]
    assert np.array_equal(solid.get_ydata(), ne) and solid.get_linestyle() == "-"
    assert np.array_equal(dashed.get_ydata(), vp) and dashed.get_linestyle() == "--"


def test_the_conclusion_gives_the_peak_reaction_force_and_moment(documents, solved):
    _, dyn = solved
    joints = dyn.reactions.joints
    force = {n: np.linalg.norm(r.force, axis=0) for n, r in joints.items()}
    moment = {n: np.linalg.norm(joints[n].moment, axis=0) for n in ("O", "D")}
    for lang, document in documents.items():
        w = spatial_words(lang)
        said = [p.text for p in _section(document, "s_conclusion", lang).blocks]
        for key, sizes in (("peak_reaction", force), ("peak_reaction_moment", moment)):
            joint = max(sizes, key=lambda n: sizes[n].max())
            position = int(np.argmax(sizes[joint]))
            head = w[key].split("{name}")[0]
            (line,) = [t for t in said if t.startswith(head)]
            assert line.startswith(head + joint + ",")
            value, at = numbers(line[len(head) + len(joint):])
            assert value == pytest.approx(sizes[joint].max(), rel=RTOL)
            assert at == position
        assert (joint, position) == ("D", 57)  # the moment's, from the figure's red curve


def test_the_idle_motion_is_said_in_each_language(documents, solved):
    _, dyn = solved
    (idle,) = dyn.reactions.idle
    assert idle.startswith("body 2: turn about (")
    for lang, document in documents.items():
        w = spatial_words(lang)
        axis = [float(c) for c in re.search(r"\(([^)]*)\)", idle).group(1).split(",")]
        said = _blocks(_section(document, "s_reactions", lang), Paragraph)[1].text
        assert said.startswith(w["p_idle"].split("{count}")[0])
        text = idle_text(idle, Shown(None, lang), w)
        assert text in said
        assert numbers(text) == [2, *axis, 31]
        assert text.endswith(w["idle_line"].format(joints="A, B"))
    assert idle_text("something else", Shown(None, "en"), w) == "something else"


def test_singular_positions_are_said_and_left_empty(monkeypatch):
    """With the singular threshold raised to the RSSR's median conditioning (as in
    tests/test_spatial_reactions.py) about half of the positions are singular: the
    report names them, its tables give '—' there, the conclusion's peak is among the
    others."""
    monkeypatch.setattr(reactions_module, "SINGULAR_RTOL", 0.0856)
    model = _data()
    dyn = solve_spatial_dynamics(model)
    singular = dyn.reactions.singular
    assert 10 < singular.sum() < 62
    for lang in LANGS:
        w = spatial_words(lang)
        document = build_document(model, lang=lang)
        warnings = [p.text for p in _blocks(_section(document, "s_reactions", lang),
                                            Paragraph) if p.kind == "warning"]
        assert warnings == [w["p_singular"].format(
            list=compress_positions(np.flatnonzero(singular)))]
        for table in _joint_tables(document, lang).values():
            for row in table.rows:
                assert (set(row[1:]) == {"—"}) == bool(singular[int(row[0])])
        force = {n: np.linalg.norm(r.force, axis=0) for n, r in dyn.reactions.joints.items()}
        peak = max(np.nanmax(f) for f in force.values())
        line = next(p.text for p in _section(document, "s_conclusion", lang).blocks
                    if p.text.startswith(w["peak_reaction"].split("{name}")[0]))
        assert numbers(line.split(", ", 1)[1])[0] == pytest.approx(peak, rel=RTOL)


def test_every_joint_type_has_its_words_in_both_languages():
    """The slider-crank written as spatial (tests/test_spatial_reactions.py) has a
    revolute, a spherical, a cylindrical and a prismatic joint."""
    _, data = _crank_slider(driven_slider=False)
    model = model_from_data(data)
    dyn = solve_spatial_dynamics(model)
    expected = {"en": ["revolute", "spherical (ball joint)", "cylindrical", "prismatic"],
                "ru": ["вращательная", "сферическая (шаровой шарнир)", "цилиндрическая",
                       "поступательная"]}
    names = [n for n in model_names(model) if n]
    for lang in LANGS:
        w = spatial_words(lang)
        shown = Shown(None, lang)
        table = pairs_table3(dyn.reactions, model, shown, w)
        assert [r[1] for r in table.rows] == expected[lang]
        assert [r[5] for r in table.rows] == ["3; 2", "3; 0", "2; 2", "2; 3"]
        assert [r[4] for r in table.rows][2:] == [w["d_vector"].format(x=0, y=0, z=1),
                                                  w["d_along3"].format(v=3)]
        slider = reaction_table("S", dyn.reactions.joints["S"], [0, 36], shown, w)
        assert len(slider.header) == 9  # a prismatic joint holds a moment
        cells = " ".join([table.caption, *table.header, *(c for r in table.rows for c in r),
                          slider.caption, *slider.header])
        if lang == "ru":
            assert latin_words(cells, names) == []
        else:
            assert not re.findall(r"[А-Яа-яЁё]", cells)


def test_each_language_holds_only_its_words_in_the_section_and_its_figures(documents,
                                                                           solved):
    model, _ = solved
    names = [n for n in model_names(model) if n]
    ru = documents["ru"]
    text = " ".join(texts(ru))
    assert latin_words(text, names) == []
    spoken = [re.sub("|".join(map(re.escape, names)), "", t) for t in texts(ru)]
    assert not [t for t in spoken if re.search(r"(?<![\w.])\d+\.\d+(?![\w.])", t)]
    assert not re.findall(r"[А-Яа-яЁё]+", " ".join(texts(documents["en"])))
    figures = _blocks(_section(ru, "s_reactions", "ru"), FigureItem)[:2]
    figures.append(_blocks(_section(ru, "s_reduced", "ru"), FigureItem)[1])
    for item in figures:
        drawn = " ".join(t.get_text() for t in figure_texts(item.draw()))
        assert latin_words(drawn, names) == [], item.caption
        assert not re.search(r"(?<![\w.])\d+\.\d+(?![\w.])", drawn), item.caption


def test_a_model_without_joints_says_the_reactions_need_them():
    model = _data(joints=None)
    for lang in LANGS:
        w = spatial_words(lang)
        document = build_document(model, lang=lang)
        assert w["s_reactions"] not in [s.title for s in document.sections]
        said = " ".join(p.text for p in _blocks(_section(document, "s_reduced", lang),
                                                Paragraph))
        assert w["p_no_joints"] in said
        conclusion = " ".join(p.text for p in _section(document, "s_conclusion",
                                                       lang).blocks)
        assert w["peak_reaction"].split("{name}")[0] not in conclusion
