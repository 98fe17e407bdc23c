"""The words of the figures' texts in Russian (the course's terms) and the translation of
a drawn figure into the report's language."""

from __future__ import annotations

from matplotlib.figure import Figure

#: Words of the figures' titles, labels and legends in Russian (the course's terms), longest
#: first so that a phrase is replaced before the words in it.
RUSSIAN_WORDS: dict[str, str] = {
    "balancing load: kinetostatics (solid) and virtual power (dashed)":
        "уравновешивающая нагрузка: кинетостатика (сплошная) и метод мощностей (штрих)",
    "argument (α near tail, r near head)": "аргумент (α у начала, r у конца)",
    "function (α near tail, r near head)": "функция (α у начала, r у конца)",
    "reduced inertia and its derivative": "приведённый момент инерции и его производная",
    "machine motion over the cycle": "движение машины за цикл",
    "hodograph of the reaction in": "годограф реакции в шарнире",
    "summary characteristics": "сводные характеристики",
    "reactions in the joints": "реакции в шарнирах",
    "angle from vector": "угол от вектора",
    "without flywheel": "без маховика",
    "with flywheel": "с маховиком",
    "reduced load": "приведённая нагрузка",
    "centre of mass": "центр масс",
    "chain break at position": "разрыв цепи в положении",
    "increment of": "приращение",
    "reference:": "базовое:",
    "from position": "от положения",
    "of 0..": "из 0..",
    "to vector": "к вектору",
    "reaction": "реакция",
    "position": "положение",
    "ground": "стойка",
    "origin": "начало",
    "joint": "шарнир",
    "mean": "среднее",
    "time": "время",
}


def translate(figure: Figure, lang: str) -> Figure:
    """Put the words of a figure's texts (titles, labels, legends, tables) in ``lang``."""
    if lang != "ru":
        return figure
    from matplotlib.text import Text

    for text in figure.findobj(Text):
        content = text.get_text()
        if not content:
            continue
        for english, russian in RUSSIAN_WORDS.items():
            content = content.replace(english, russian)
        text.set_text(content)
    return figure
