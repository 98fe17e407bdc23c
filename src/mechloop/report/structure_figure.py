"""The structure figure of section 2 (:func:`mechloop.views.formula.plot_structure`) in the
report's language: the contour boxes' words in Russian, and without the figure's header
text, which the section's formula paragraph gives in full in the report's language."""

from __future__ import annotations

import re

from matplotlib.figure import Figure

from mechloop.model.schema import Model
from mechloop.views.russian import translate

#: The words of the contour boxes in Russian (pattern -> replacement), in order.
RUSSIAN_BOX: list[tuple[str, str]] = [
    (r"\bcontour (\d+)", r"контур \1"), (r"\bvectors\b", "векторы"),
    (r"\blinks:", "связи:"), (r"\(arg (\d+)", r"(аргумент \1"),
    (r"\bconstants only\b", "только константы"), (r"\bcoupled\b", "связанный"),
    (r"\bfunction\b", "функция"), (r"\bPl(\d)", r"Пл\1"), (r"\bdeg\b", "°"),
    (r"\bno contours\b", "контуров нет"), (r"\bPr(\d)", r"Пр\1"),
]

#: The first line of a contour's box: its number.
_CONTOUR = re.compile(r"contour (\d+)\b")


def structure_figure(model: Model, lang: str) -> Figure:
    """The structure of the vector model drawn, in ``lang``."""
    from mechloop.views import formula

    figure = formula.plot_structure(model)
    if figure._suptitle is not None:
        figure._suptitle.set_text("")
    for ax in figure.axes:  # a spatial contour's structure formula: n = 3 (issue 17)
        for text in ax.texts:
            found = _CONTOUR.match(text.get_text())
            if found and model.contours[int(found.group(1)) - 1].spatial:
                text.set_text(text.get_text().replace("\nn=2, ", "\nn=3, ", 1))
    if lang == "ru":
        for ax in figure.axes:
            for text in ax.texts:
                content = text.get_text()
                for pattern, replacement in RUSSIAN_BOX:
                    content = re.sub(pattern, replacement, content)
                text.set_text(content.replace(" °", "°"))
    return translate(figure, lang)
