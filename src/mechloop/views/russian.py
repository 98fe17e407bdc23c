"""The words of the figures' texts in Russian (the course's terms) and the translation of
a drawn figure into the report's language.

The views draw their texts in English; :func:`translate` puts every text of a drawn figure
(titles, axis labels, tick labels, legends, tables, annotations) into Russian by the
phrases of :data:`RUSSIAN_WORDS`, whole words only (``position`` is not replaced inside
``positions``), the longest phrase first, in one pass (a replaced text is not replaced
again).  Symbols (``r3``, ``φ1``, ``F_bal``, ``S2``), unit names (``rad/s``, ``N*m``) and
numbers stay as they are.  The user's own names (the model's, its vectors', contours',
joints', loads' names) stay as the user wrote them: a view marks them on its figure
(:func:`keep_names`) and :func:`translate` leaves them alone.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Iterable
from typing import Any

from matplotlib.figure import Figure
from matplotlib.table import Table as MplTable
from matplotlib.text import Text

from mechloop.modules.coupled import DEAD, JUMP, NO_CONVERGENCE, REASONS
from mechloop.solve.kinematics import BREAK_REASONS, DEAD_POINT, OVERFLOW
from mechloop.views.decimal_mark import localize_ticks, localized
from mechloop.views.unit_words import RUSSIAN_UNITS, unit_text

#: Why the chain breaks (the solver's sentences) in Russian.
BREAK_WORDS: dict[str, str] = {
    BREAK_REASONS["Pl1"]: "замыкающий вектор имеет нулевую длину, его направление не "
                          "определено",
    BREAK_REASONS["Pl2"]: "два вектора неизвестной длины параллельны",
    BREAK_REASONS["Pl3"]: "вектор известной длины не достаёт до линии другого вектора",
    BREAK_REASONS["Pl4"]: "два вектора не замыкают контур (не выполняется неравенство "
                          "треугольника)",
    DEAD_POINT: "мёртвая точка: матрица Якоби контура вырождена, скорости неограниченны",
    OVERFLOW: "значения переполняют числа с плавающей точкой (слишком велик размер, "
              "аргумент или скорость)",
    REASONS[NO_CONVERGENCE]: "метод Ньютона не находит сборки связанного блока рядом с "
                             "предыдущей (пройдено крайнее положение, или блок не "
                             "замыкается)",
    REASONS[DEAD]: "мёртвая точка: матрица Якоби связанного блока вырождена, скорости "
                   "неограниченны",
    REASONS[JUMP]: "связанный блок перескочил на другую ветвь сборки: положения здесь "
                   "слишком редки, или движение проходит особое положение",
}

#: Words of the figures' titles, labels and legends in Russian (the course's terms).
RUSSIAN_WORDS: dict[str, str] = {
    **BREAK_WORDS,
    # dynamics (views/dynamics.py)
    "balancing load: kinetostatics (solid) and virtual power (dashed)":
        "уравновешивающая нагрузка: кинетостатика (сплошная) и метод мощностей (штрих)",
    "balancing load": "уравновешивающая нагрузка",
    "kinetostatics (solid), virtual power (dashed)":
        "кинетостатика (сплошная), метод мощностей (штрих)",
    "reduced inertia and its derivative": "приведённый момент инерции и его производная",
    "machine motion over the cycle": "движение машины за цикл",
    "hodograph of the reaction in": "годограф реакции в шарнире",
    "(polar)": "(полярная форма)",
    "summary characteristics": "сводные характеристики",
    "reactions in the joints": "реакции в шарнирах",
    "reduced load": "приведённая нагрузка",
    "without flywheel": "без маховика",
    "with flywheel": "с маховиком",
    "driving work": "работа движущих сил",
    "work lost to friction": "работа сил трения",
    "loss coefficient": "коэффициент потерь",
    "efficiency": "КПД",
    "kinetic energy change": "изменение кинетической энергии",
    "kinetic energy": "кинетическая энергия",
    "not given: the chain breaks": "не приводится: цепь разрывается",
    "constant load on the input": "постоянная нагрузка на входном звене",
    "δ wanted": "δ заданный",
    "flywheel (exact)": "маховик (точно)",
    "flywheel (approximate)": "маховик (приближённо)",
    "N mean": "N ср",
    "N per kg": "N уд",
    "load": "нагрузка",
    "friction": "трение",
    "model": "модель",
    "reaction": "реакция",
    "origin": "начало",
    "mean": "среднее",
    # curves (views/curves.py)
    "angle from vector": "угол от вектора",
    "to vector": "к вектору",
    "increment of": "приращение",
    "from position": "от положения",
    "reference:": "базовое:",
    "sum of": "сумма",
    "difference of": "разность",
    "product of": "произведение",
    "ratio of": "отношение",
    "power of": "степень",
    "and": "и",
    # plans (views/plan.py)
    "argument (α near tail, r near head)": "аргумент (α у начала, r у конца)",
    "function (α near tail, r near head)": "функция (α у начала, r у конца)",
    "centre of mass": "центр масс",
    "chain break at positions": "разрыв цепи в положениях",
    "chain break at position": "разрыв цепи в положении",
    "trajectories": "траектории",
    "mechanism": "механизм",
    "ground": "стойка",
    "joint": "шарнир",
    "of 0..": "из 0..",
    # 3-D plans of spatial models (views/spatial_plan.py)
    "front view": "вид спереди",
    "side view": "вид сбоку",
    "top view": "вид сверху",
    "3-D view": "объёмный вид",
    "elev": "возвышение",
    "azim": "азимут",
    "joint (vector end)": "шарнир (конец вектора)",
    "head of": "конец вектора",
    "tail of": "начало вектора",
    "module": "модуль",
    "has no real solution on the chosen variant (the vectors cannot close the loop in "
    "space)": "не имеет действительного решения на выбранном варианте (векторы не "
              "замыкают контур в пространстве)",
    # reactions of spatial models (views/spatial_reactions.py)
    "hodograph of the reaction moment in": "годограф момента реакции в шарнире",
    "reaction moments in the joints": "моменты реакций в шарнирах",
    "reaction moment": "момент реакции",
    "Newton–Euler equations (solid), virtual power (dashed)":
        "уравнения Ньютона — Эйлера (сплошная), метод мощностей (штрих)",
    # structure (views/formula.py, mechloop.model.formula.describe_structure)
    "vector model": "векторная модель",
    "planar": "плоская",
    "contour(s)": "контур(ов)",
    "vectors, positions": "векторов, положения",
    "time: none — derivatives are analogs with respect to argument":
        "время: нет — производные являются аналогами по аргументу",
    "turns over positions": "оборота(ов) на положениях",
    "over positions": "на положениях",
    "time: table": "время: таблица",
    "intermediate": "промежуточный",
    "values from": "значений от",
    "in every position": "в каждом положении",
    "table of": "таблица из",
    "value(s)": "значений",
    "law": "закон",
    "constant_speed": "равномерный",
    "harmonic": "гармонический",
    "cycloidal": "циклоидальный",
    "poly345": "полином 3-4-5",
    "drives": "приводит",
    "solving order": "порядок решения",
    "no contours": "нет контуров",
    "contour": "контур",
    "vectors": "векторы",
    "links": "связи",
    "function": "функция",
    "argument": "аргумент",
    "(angle)": "(угол)",
    "(length)": "(длина)",
    # machine motion in time (views/motion.py)
    "motion in time": "движение во времени",
    "inputs": "входа(ов)",
    "ended:": "окончено:",
    "motor off": "двигатель отключён",
    "steady at": "установившийся режим с",
    "input angle within the cycle": "угол входного звена в цикле",
    "input angle": "угол входного звена",
    "speed n": "частота вращения n",
    "acceleration ε": "ускорение ε",
    "phase portraits": "фазовые портреты",
    "phase portrait (later cycles darker)": "фазовый портрет (поздние циклы темнее)",
    "turns": "обороты",
    "input": "вход",
    "duration": "длительность",
    "steady": "установившийся режим",
    "cycles": "циклы",
    "start": "начало",
    "at": "при",
    # envelopes (views/envelope.py)
    "curves over the sweep": "кривые семейства",
    "envelope": "огибающая",
    "branch": "ветвь",
    "over argument": "по аргументу",
    # the x-axes
    "position": "положение",
    "positions": "положения",
    "between positions": "между положениями",
    "between": "между",
    "of": "из",
    "to": "до",
    "time": "время",
}


@functools.cache
def _pattern() -> re.Pattern[str]:
    """One pattern of every phrase, longest first, each whole (no letter next to it)."""
    phrases = sorted(RUSSIAN_WORDS, key=len, reverse=True)
    def whole(phrase: str) -> str:  # no letter, digit or _ joined on (r3_to_a2 stays)
        before = r"(?<!\w)" if re.match(r"\w", phrase) else ""
        after = r"(?!\w)" if re.search(r"\w$", phrase) else ""
        return before + re.escape(phrase) + after

    return re.compile("|".join(whole(p) for p in phrases))


#: The attribute of a figure that holds the user's names drawn on it.
NAMES_ATTRIBUTE = "_mechloop_user_names"


def model_names(model: Any) -> set[str]:
    """The names the user gave in ``model`` (a :class:`~mechloop.model.schema.Model`): its
    name, its vectors', contours', bodies', joints', gear meshes' and loads' names."""
    names = {model.name}
    names |= {v.name or "" for v in model.vectors.values()}
    names |= {c.name or "" for c in model.contours}
    names |= {getattr(b, "name", None) or "" for b in model.bodies.values()}
    names |= {*(model.joints or {}), *model.gears}
    names |= {e.name for e in getattr(model, "envelopes", [])}
    for load in [*model.forces, *model.moments, *model.springs, *model.dampers]:
        names.add(getattr(load, "name", None) or "")
    return {str(n) for n in names if n}


def keep_names(figure: Figure, names: Iterable[str]) -> Figure:
    """Mark ``names`` (the user's own, drawn on ``figure``) to be kept as written when the
    figure is translated."""
    kept = getattr(figure, NAMES_ATTRIBUTE, set())
    setattr(figure, NAMES_ATTRIBUTE, kept | {str(n) for n in names if n})
    return figure


#: A unit in brackets after a quantity's name ('M_bal [N*m]', 'ω [rad/s]').
_UNIT_BRACKETS = re.compile(r"\[([A-Za-z][A-Za-z0-9*/^()·\-]*)\]")


def _russian_unit(match: re.Match[str]) -> str:
    """A bracketed unit in its Russian designation (GOST 8.417) when every name in it is
    a unit mechloop prints; anything else as it is."""
    unit = match.group(1)
    names = re.findall(r"[A-Za-z_]+", unit)
    if not all(n in RUSSIAN_UNITS or n in ("deg", "degree") for n in names):
        return match.group(0)
    return f"[{unit_text(unit, 'ru')}]"


def russian(text: str, names: Iterable[str] = ()) -> str:
    """``text`` with every phrase of :data:`RUSSIAN_WORDS` put in Russian, the user's
    ``names`` (of two characters or more) in it left as they are, and its numbers
    written with the decimal comma.

    >>> russian("increment of r3 from position 0")
    'приращение r3 от положения 0'
    >>> russian("positions 0..72, position 5")
    'положения 0..72, положение 5'
    >>> russian("Run up to the break, position 5", ["Run up to the break"])
    'Run up to the break, положение 5'
    >>> russian("t = 0.25 s, position 3")
    't = 0,25 s, положение 3'
    >>> russian("M_bal [N*m], ω [rad/s], x [px]")
    'M_bal [Н·м], ω [рад/с], x [px]'
    """
    kept: list[str] = []

    def hide(match: re.Match[str]) -> str:
        kept.append(match.group(0))
        return f"\x00{len(kept) - 1}\x00"

    # a name may be wrapped over lines: any white space between its words
    protected = sorted((n for n in names if len(n) >= 2), key=len, reverse=True)
    spelled = [r"\s+".join(map(re.escape, n.split())) for n in protected]
    spelled = [rf"(?<!\w){n}(?!\w)" for n in spelled if n]
    if spelled:
        text = re.sub("|".join(spelled), hide, text)
    text = _pattern().sub(lambda match: RUSSIAN_WORDS[match.group(0)], text)
    text = localized(_UNIT_BRACKETS.sub(_russian_unit, text), "ru")
    return re.sub("\x00(\\d+)\x00", lambda match: kept[int(match.group(1))], text)


def figure_texts(figure: Figure) -> list[Text]:
    """Every text of ``figure``: titles, labels, tick labels, legends, annotations and the
    cells of its tables (which ``findobj`` does not reach)."""
    texts = list(figure.findobj(Text))
    for table in figure.findobj(MplTable):
        texts += [cell.get_text() for cell in table.get_celld().values()]
    return texts


def translate(figure: Figure, lang: str) -> Figure:
    """Put the words of a figure's texts (:func:`figure_texts`) in ``lang`` ('en': as
    drawn; 'ru': :func:`russian`, and the tick labels with the decimal comma)."""
    if lang != "ru":
        return figure
    names = getattr(figure, NAMES_ATTRIBUTE, set())
    for text in figure_texts(figure):
        content = text.get_text()
        if content:
            translated = russian(content, names)
            if translated != content:
                text.set_text(translated)
    return localize_ticks(figure, lang)
