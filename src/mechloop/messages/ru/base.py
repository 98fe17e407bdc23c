"""What every area's Russian entries share: the entry type, the kinds of quantity and the
small word helpers of the templates."""

from __future__ import annotations

import re
from collections.abc import Callable

#: (pattern, Russian template): the pattern matches one English message or fix whole, with
#: named groups for the user's values; the template is ``str.format`` over the groups, or a
#: function of the match.  Group-name suffixes: ``_tr`` a nested English text (translated
#: too), ``_or`` a list of the user's values joined by "or"/"and", ``_kind`` a kind of
#: quantity (a key of :data:`KINDS`).
Entry = tuple[str, str | Callable[[re.Match[str]], str]]

#: Kinds of quantity: English word -> (nominative, genitive) in Russian.
KINDS = {
    "length": ("длина", "длины"), "angle": ("угол", "угла"), "time": ("время", "времени"),
    "mass": ("масса", "массы"), "force": ("сила", "силы"), "moment": ("момент", "момента"),
    "inertia": ("момент инерции", "момента инерции"),
    "moment of inertia": ("момент инерции", "момента инерции"),
    "acceleration": ("ускорение", "ускорения"), "velocity": ("скорость", "скорости"),
    "speed": ("скорость", "скорости"), "energy": ("энергия", "энергии"),
    "power": ("мощность", "мощности"), "pressure": ("давление", "давления"),
    "stiffness": ("жёсткость", "жёсткости"), "damping": ("демпфирование", "демпфирования"),
    "angular velocity": ("угловая скорость", "угловой скорости"),
    "angular acceleration": ("угловое ускорение", "углового ускорения"),
    "frequency": ("частота", "частоты"), "area": ("площадь", "площади"),
    "volume": ("объём", "объёма"),
}
#: A pattern matching any kind of quantity of :data:`KINDS` (longest first).
KIND = "|".join(sorted(map(re.escape, KINDS), key=len, reverse=True))


def accusative(nominative: str) -> str:
    """The accusative after «как» (feminine -а → -у; the others read as nominative)."""
    words = nominative.split(" ")
    return " ".join(w[:-1] + "у" if w.endswith("а") else
                    w[:-2] + "ую" if w.endswith("ая") else w for w in words)


def quoted(items: str) -> str:
    """A list of the words a user types (views, quantities), each in quotes."""
    return ", ".join(f"'{item.strip()}'" for item in items.split(",") if item.strip())


def or_words(text: str) -> str:
    """"a or b and c" with the joining words in Russian."""
    return re.sub(r"(?<=\S) (or|and) (?=\S)", lambda m: " или " if m[1] == "or" else " и ",
                  text)
