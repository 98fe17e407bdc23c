"""Sheet 3 of the course project, the gear pair and/or the planetary train (a ``mechloop
gear`` document), as content: the meshing drawing, the geometry table with the ISO 21771
names and units, the checks (undercut, pointed tooth, interference, contact ratio) and the
specific sliding; for a planetary train (a James 2K-H train with any member held and any
input, or the Wolfrom train) its members with their tooth numbers and roles, the ratio by
Willis' formula read for the member held, the conditions (coaxiality, assembly, neighbours),
the speeds and the velocity plan (:mod:`mechloop.views.train_sheet`) — in English or
Russian.

Every number comes from :mod:`mechloop.gears` (:func:`mechloop.gears.tables.pair_table`,
:meth:`mechloop.gears.GearPair.checks`, :class:`mechloop.gears.PlanetaryTrain`,
:class:`mechloop.gears.wolfrom.WolfromTrain`); lengths
in mm, angles in degrees, as the gear documents are.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

from matplotlib.figure import Figure

from mechloop.errors import Problem
from mechloop.gears.document import (
    choice_of,
    no_design,
    pair_of,
    read_gear_document,
    train_of,
)
from mechloop.gears.drawing import draw_mesh, plot_sliding
from mechloop.gears.pair import GearPair
from mechloop.gears.planetary import PlanetaryTrain
from mechloop.gears.tables import pair_table
from mechloop.gears.wolfrom import WolfromTrain
from mechloop.model.document import located_error
from mechloop.views.sheet import (
    FigureItem,
    Sheet,
    Table,
    localized_sheet,
    number_text,
    translate_figure,
)
from mechloop.views.train_sheet import (
    PLAN_WORDS_RU,
    TRAIN_TEXT,
    train_paragraphs,
    train_plan,
    train_tables,
)


@dataclass(frozen=True)
class GearTask:
    """What a gear document gives the report: the ``pair`` and/or the ``train`` (a train
    chosen for a target ratio is the best design of the choice), the input ``speed`` of
    the train (rpm), its ``target`` ratio (or None) and the sections' names."""

    pair: GearPair | None
    pair_name: str
    train: PlanetaryTrain | WolfromTrain | None
    train_name: str
    speed: float
    target: float | None


def load_gears(path: str | os.PathLike[str]) -> GearTask:
    """Read a gear document (``gear_pair:`` and/or ``planetary:``); every problem is a
    located :class:`~mechloop.errors.ModelError` of that file."""
    file = str(path)
    doc, lines = read_gear_document(path)
    if doc.gear_pair is None and doc.planetary is None:
        raise located_error([Problem((), "the file has neither a 'gear_pair:' nor a "
                                     "'planetary:' section", "see examples/gears/", 1)],
                            file, lines)
    pair = pair_of(doc.gear_pair, file=file, lines=lines) if doc.gear_pair else None
    train = None
    spec = doc.planetary
    if spec is not None:
        train = train_of(spec, file=file, lines=lines)
        if train is None:  # the best design of the choice for the target ratio
            choice = choice_of(spec, file=file, lines=lines)
            if not len(choice):
                raise located_error([no_design(spec)], file, lines)
            train = choice.train(0, spec.module, spec.addendum)
    return GearTask(pair, (doc.gear_pair.name or "") if doc.gear_pair else "", train,
                    (spec.name or "") if spec else "", float(spec.input_speed) if spec
                    else 0.0, None if spec is None else spec.target_ratio)


PAIR_TEXT: dict[str, dict[str, str]] = {
    "en": {
        "pair": "Sheet 3. Gear pair", "train": "Sheet 3. Planetary train",
        "both": "Sheet 3. Gear pair and planetary train",
        "geometry": "Geometry of the external involute spur gear pair (ISO 21771)",
        "checks": "Checks of the gear pair",
        "quantity": "quantity", "symbol": "symbol", "pinion": "pinion", "wheel": "wheel",
        "unit": "unit", "check": "check", "gear": "gear", "value": "value",
        "limit": "limit", "result": "result", "ok": "met", "fails": "NOT MET",
        "all_met": "All checks of the pair are met: the teeth have involute flanks, no "
                   "undercut, no pointed tooth, no "
                   "interference, and the contact ratio is at least 1.",
        "involute flank": "involute flank", "undercut": "undercut",
        "pointed tooth": "pointed tooth",
        "interference": "interference", "contact ratio": "contact ratio", "pair_gear": "pair",
        "fig_mesh": "Meshing of the gear pair: circles, line of action N1N2, active line A–E",
        "fig_sliding": "Specific sliding of the pinion and the wheel along the line of "
                       "action",
    },
    "ru": {
        "pair": "Лист 3. Зубчатая передача", "train": "Лист 3. Планетарный механизм",
        "both": "Лист 3. Зубчатая передача и планетарный механизм",
        "geometry": "Геометрия внешнего эвольвентного прямозубого зацепления",
        "checks": "Проверки зубчатой передачи",
        "quantity": "величина", "symbol": "обозн.", "pinion": "шестерня", "wheel": "колесо",
        "unit": "ед. изм.", "check": "проверка", "gear": "колесо", "value": "значение",
        "limit": "предел", "result": "результат", "ok": "выполнена",
        "fails": "НЕ ВЫПОЛНЕНА",
        "all_met": "Все проверки передачи выполнены: зубья имеют эвольвентный профиль, "
                   "подрезания, заострения зуба и "
                   "интерференции нет, коэффициент перекрытия не меньше 1.",
        "failed": "Проверка «{check}» ({gear}) не выполнена: {value}, предел {limit}.",
        "beyond": " Линия зацепления выходит за точки касания N1, N2 основных окружностей: "
                  "вершина зуба сопряжённого колеса заходит в подрезанную ножку.",
        "involute flank": "эвольвентный профиль", "undercut": "подрезание",
        "pointed tooth": "заострение зуба",
        "interference": "интерференция", "contact ratio": "коэффициент перекрытия",
        "pair_gear": "передача",
        "fig_mesh": "Картина зацепления: окружности, линия зацепления N1N2, активная "
                    "линия A–E",
        "fig_sliding": "Удельное скольжение шестерни и колеса вдоль линии зацепления",
    },
}

#: Every text of the sheet, the pair's and the train's, by language.
TEXT: dict[str, dict[str, str]] = {lang: PAIR_TEXT[lang] | TRAIN_TEXT[lang]
                                   for lang in PAIR_TEXT}

#: The gear pair's quantities (mechloop.gears.tables.pair_table) in Russian.
QUANTITIES_RU: dict[str, str] = {
    "number of teeth": "число зубьев",
    "profile shift coefficient": "коэффициент смещения",
    "least shift without undercut": "наименьшее смещение без подрезания",
    "reference diameter": "делительный диаметр",
    "base diameter": "основной диаметр",
    "working pitch diameter": "начальный диаметр",
    "tip diameter": "диаметр вершин",
    "root diameter": "диаметр впадин",
    "form diameter (involute starts)": "граничный диаметр (начало эвольвенты)",
    "lowest contact diameter": "диаметр нижней точки активного профиля",
    "addendum": "высота головки зуба",
    "dedendum": "высота ножки зуба",
    "tooth depth": "высота зуба",
    "tooth thickness, reference circle": "толщина зуба по делительной окружности",
    "space width, reference circle": "ширина впадины по делительной окружности",
    "tooth thickness, working pitch circle": "толщина зуба по начальной окружности",
    "tooth thickness, base circle": "толщина зуба по основной окружности",
    "tooth thickness, tip circle": "толщина зуба по окружности вершин",
    "chordal thickness, reference circle": "толщина зуба по хорде делительной окружности",
    "chordal height, reference circle": "высота до хорды делительной окружности",
    "teeth in the span": "число охватываемых зубьев",
    "base tangent length (span)": "длина общей нормали",
    "tip clearance": "радиальный зазор",
    "module": "модуль",
    "pressure angle": "угол профиля исходного контура",
    "gear ratio": "передаточное число",
    "reference centre distance": "делительное межосевое расстояние",
    "centre distance": "межосевое расстояние",
    "working pressure angle": "угол зацепления",
    "centre distance modification coefficient": "коэффициент воспринимаемого смещения",
    "tip shortening coefficient": "коэффициент уравнительного смещения",
    "pitch": "шаг по делительной окружности",
    "base pitch": "основной шаг",
    "line of action N1N2": "теоретическая линия зацепления N1N2",
    "start of contact from N1": "начало зацепления от N1",
    "end of contact from N1": "конец зацепления от N1",
    "length of path of contact": "длина активной линии зацепления",
    "transverse contact ratio": "коэффициент торцового перекрытия",
}

#: The words of the gear figures (mechloop.gears.drawing, .velocity_plan) in Russian.
FIGURE_WORDS_RU: dict[str, str] = {
    "active line": "активная линия",
    "the mesh zone": "зона зацепления",
    "distance from N1 along the line of action": "расстояние от N1 вдоль линии "
                                                 "зацепления, mm",
    "specific sliding": "удельное скольжение",
    "pinion": "шестерня",
    "wheel": "колесо",
    **PLAN_WORDS_RU,
}

#: The two numbers each check compares (value, limit).
CHECK_SYMBOLS = {"involute flank": ("d_a", "d_Ff"), "undercut": ("x", "x_min"),
                 "pointed tooth": ("s_a", "[s_a]"), "interference": ("d_Nf", "d_Ff"),
                 "contact ratio": ("ε_α", "1")}


def gear_sheet(task: GearTask, lang: str = "en") -> Sheet:
    """The gear sheet of ``task`` in ``lang`` ('en' or 'ru')."""
    text = TEXT[lang]
    tables: list[Table] = []
    figures: list[FigureItem] = []
    paragraphs: list[str] = []
    if task.pair is not None:
        tables += [_geometry(task.pair, text, lang), _checks(task.pair, text)]
        paragraphs += _check_words(task.pair, text, lang)
        figures += [_figure(lambda: draw_mesh(task.pair), text["fig_mesh"], lang),
                    _figure(lambda: plot_sliding(task.pair), text["fig_sliding"], lang)]
    if task.train is not None:
        tables += train_tables(task.train, task.speed, task.target, text)
        paragraphs += train_paragraphs(task.train, text)
        figures.append(_figure(lambda: train_plan(task.train, task.speed, text),
                               text["fig_plan"], lang))
    title = text["both" if task.pair is not None and task.train is not None else
                 "pair" if task.pair is not None else "train"]
    return localized_sheet(Sheet(3, title, lang, figures, tables, paragraphs))


def _figure(draw, caption: str, lang: str) -> FigureItem:
    def make() -> Figure:
        figure = draw()
        return translate_figure(figure, FIGURE_WORDS_RU) if lang == "ru" else figure
    return FigureItem(caption, make)


def _unit(unit: str) -> str:
    return "°" if unit == "deg" else unit


def _geometry(pair: GearPair, text: dict[str, str], lang: str) -> Table:
    frame = pair_table(pair)
    rows = []
    for quantity, symbol, pinion, wheel, unit in frame.itertuples(index=False):
        name = QUANTITIES_RU.get(quantity, quantity) if lang == "ru" else quantity
        rows.append((name, symbol, number_text(pinion),
                     "" if math.isnan(wheel) else number_text(wheel), _unit(unit)))
    header = (text["quantity"], text["symbol"], f"{text['pinion']} (1)",
              f"{text['wheel']} (2)", text["unit"])
    return Table(text["geometry"], header, rows)


def _check_words(pair: GearPair, text: dict[str, str], lang: str) -> list[str]:
    """The checks in words: that all are met, or each one that fails (in English the
    gear package's own sentence with its reason)."""
    failing = [c for c in pair.checks() if not c.ok]
    if not failing:
        return [text["all_met"]]
    if lang == "en":
        return [f"{c.name} NOT MET: {c.text}" for c in failing]
    words = []
    for c in failing:
        value, limit = CHECK_SYMBOLS.get(c.name, ("", ""))
        gear = text["pair_gear"] if c.gear is None else text[("pinion", "wheel")[c.gear - 1]]
        words.append(text["failed"].format(check=text.get(c.name, c.name), gear=gear,
                                           value=f"{value} = {number_text(c.value)}",
                                           limit=limit if limit == "1" else
                                           f"{limit} = {number_text(c.limit)}")
                     + (text["beyond"] if c.value >= c.limit else ""))
    return words


def _checks(pair: GearPair, text: dict[str, str]) -> Table:
    rows = []
    for check in pair.checks():
        value, limit = CHECK_SYMBOLS.get(check.name, ("", ""))
        gear = text["pair_gear"] if check.gear is None else \
            text[("pinion", "wheel")[check.gear - 1]]
        rows.append((text.get(check.name, check.name), gear,
                     f"{value} = {number_text(check.value)}",
                     f"{limit} = {number_text(check.limit)}" if limit != "1" else "1",
                     text["ok" if check.ok else "fails"]))
    return Table(text["checks"], (text["check"], text["gear"], text["value"], text["limit"],
                                  text["result"]), rows)
