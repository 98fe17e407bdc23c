"""The words of the structure description (:func:`mechloop.model.formula.describe_structure`,
``mechloop info``) in each language: English, and Russian with the terms of the course
(контур, вектор, аргумент, формула строения, искомый параметр, модуль, решений).

Each entry is a :meth:`str.format` template; the English ones print the description as it
always was, byte for byte.
"""

from __future__ import annotations

WORDS: dict[str, dict[str, str]] = {
    "en": {
        "model": "vector model",
        "planar": "planar",
        "spatial": "spatial",
        "head": "{title}: {kind}, {contours} contour(s), {vectors} vectors, "
                "positions 0..{positions}",
        "no time": "time: none — derivatives are analogs with respect to argument 1",
        "turns": ", {turns} turns",
        "rpm": "time: {rpm} rpm{turns} over positions 0..{positions}",
        "time table": "time: table over positions 0..{positions}",
        "angle": "angle",
        "length": "length",
        "law": "law {law} from position {start} to {end}",
        "intermediate": "intermediate, {count} values from {start} to {to} in every position",
        "table": "table of {count} value(s)",
        "argument": "argument {number} ({kind}): {form}; drives {driven}",
        "order": "solving order: ",
        "contour": "contour {number}",
        "contour vectors": "{contour}{name}: vectors {vectors}",
        "structure formula": "  structure formula:  {formula}",
        "links": "; links: ",
        "solutions": "{count} solution(s)",
        "block": "coupled block {number}: contours {contours} solved together for "
                 "{unknowns} by Newton's method",
        "parametric formula": "  parametric formula: {formula} ({solutions})",
        "constants": "  constants:          {known}",
        "needs": "  needs contours:     {needs}",
        "function": "function",
        "arg": "arg {number}{offset}",
        "constants only": "constants only",
    },
    "ru": {
        "model": "векторная модель",
        "planar": "плоская",
        "spatial": "пространственная",
        "head": "{title}: {kind}, контуров: {contours}, векторов: {vectors}, "
                "положения 0..{positions}",
        "no time": "время: не задано — производные являются аналогами по аргументу 1",
        "turns": ", оборотов: {turns}",
        "rpm": "время: {rpm} об/мин{turns} на положениях 0..{positions}",
        "time table": "время: таблица на положениях 0..{positions}",
        "angle": "угол",
        "length": "длина",
        "law": "закон «{law}» от положения {start} до {end}",
        "intermediate": "промежуточный, значений: {count}, от {start} до {to} в каждом "
                        "положении",
        "table": "таблица, значений: {count}",
        "argument": "аргумент {number} ({kind}): {form}; задаёт {driven}",
        "order": "порядок решения: ",
        "contour": "контур {number}",
        "contour vectors": "{contour}{name}: векторы {vectors}",
        "structure formula": "  формула строения:        {formula}",
        "links": "; связи: ",
        "solutions": "решений: {count}",
        "block": "связанный блок {number}: контуры {contours} решаются совместно "
                 "относительно {unknowns} методом Ньютона",
        "parametric formula": "  параметрическая формула: {formula} ({solutions})",
        "constants": "  постоянные:              {known}",
        "needs": "  нужны контуры:           {needs}",
        "function": "искомый",
        "arg": "арг. {number}{offset}",
        "constants only": "только постоянные",
        "module coupled": "блок",
    },
}

#: The laws of motion of an argument (:mod:`mechloop.model.laws`) in Russian.
RUSSIAN_LAWS: dict[str, str] = {
    "constant_speed": "равномерный", "harmonic": "косинусоидальный",
    "cycloidal": "синусоидальный (циклоидальный)", "poly345": "полином 3-4-5",
    "poly4567": "полином 4-5-6-7", "modified_trapezoidal": "модифицированный трапецеидальный",
    "modified_sine": "модифицированный синусоидальный",
}


def law_name(law: str, lang: str) -> str:
    """The name of a law of motion in ``lang`` (its key in English)."""
    return RUSSIAN_LAWS.get(law, law) if lang == "ru" else law
