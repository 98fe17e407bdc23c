"""A synthetic report document with every kind of block, in English or Russian, for the
typesetters' tests (independent of the mechanism content)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from mechloop.report.document import Document, FigureItem, Paragraph, Section, Table, TitlePage

TEXT = {
    "en": dict(kind="Course project", course="Theory of machines and mechanisms",
               title="Kinematic and dynamic analysis of the mechanism",
               student="Student", group="Group", supervisor="Supervisor",
               s1="Model parameters", s2="Reactions in the kinematic pairs",
               sub="Hodograph of the reaction in joint B", app="Values at every position",
               para="The kinematic chain does not break at any position.",
               warn="WARNING: the chain breaks in the cycle.",
               fig="Increment of the output parameter r3", tab="Vectors of the model",
               head=("vector", "r, mm", "α, deg", "role")),
    "ru": dict(kind="Курсовой проект", course="Теория механизмов и машин",
               title="Кинематический и динамический анализ механизма",
               student="Студент", group="Группа", supervisor="Руководитель",
               s1="Параметры модели", s2="Реакции в кинематических парах",
               sub="Годограф реакции в шарнире B", app="Значения во всех положениях",
               para="Проверка кинематической цепи на разрыв: разрывов нет.",
               warn="ВНИМАНИЕ: кинематическая цепь разрывается в цикле.",
               fig="Приращение параметра выходного звена r3", tab="Векторы модели",
               head=("вектор", "r, мм", "α, град", "роль")),
}


def _plot(wide: bool) -> Figure:
    figure = Figure(figsize=(9, 5) if wide else (6, 7), layout="constrained")
    ax = figure.add_subplot()
    x = np.linspace(0, 360, 73)
    ax.plot(x, np.sin(np.radians(x)), label="r3")
    ax.set_xlabel("φ1, deg")
    ax.legend()
    return figure


def sample_document(lang: str = "en", rows: int = 150, columns: int = 9) -> Document:
    """A document with a title page, two sections (tables, paragraphs, a warning, a
    formula, figures, a subsection) and an appendix holding a ``rows`` × ``columns``
    table that spans pages."""
    t = TEXT[lang]
    vectors = Table(t["tab"], t["head"], [("1", "100", "30", "argument"),
                                          ("2", "420.5", "−12.25", "function")],
                    [100.0, 420.5])
    big = Table(t["app"], tuple(["№", *(f"c{j}" for j in range(1, columns))]),
                [tuple([str(i), *(f"{i * j / 7:.4f}" for j in range(1, columns))])
                 for i in range(rows)])
    return Document(
        lang=lang, name="sample",
        title=TitlePage(organisation=["Samara University", "Department of mechanics"],
                        kind=t["kind"], course=t["course"], title=t["title"],
                        subject="crank_slider_dynamics",
                        people=[(t["student"], "I. I. Ivanov"), (t["group"], "1234-150301"),
                                (t["supervisor"], "B. B. Kosenok")],
                        place_year="Samara 2026"),
        sections=[
            Section(t["s1"], [vectors, Paragraph(t["para"]), Paragraph(t["warn"], "warning"),
                              Paragraph("W = 3·n − 2·p5 − p4\n  = 3·3 − 2·4 − 0 = 1",
                                        "formula"),
                              FigureItem(t["fig"], lambda: _plot(True))]),
            Section(t["s2"], [Paragraph(t["para"]),
                              Section(t["sub"], [FigureItem(t["sub"], lambda: _plot(False))])]),
        ],
        appendices=[Section(t["app"], [big])],
    )
