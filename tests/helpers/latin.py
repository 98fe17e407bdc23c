"""Latin words in a Russian text that are neither symbols, unit names nor the user's own
names (issue 15: the Russian report, messages and plots hold no English words but these)."""

from __future__ import annotations

import re
from collections.abc import Iterable

#: Unit names and their parts as printed (SI and the display units of mechloop).
UNITS = {"m", "mm", "cm", "km", "kg", "g", "t", "N", "kN", "MN", "Pa", "kPa", "MPa", "bar",
         "s", "ms", "min", "h", "rad", "deg", "rev", "rpm", "Hz", "W", "kW", "J", "kJ",
         "mJ", "L", "l", "dm", "in", "ft", "lbf", "psi", "K", "C", "V", "A"}

#: Short English words that are never symbols.
ENGLISH_SHORT = {"of", "the", "and", "at", "to", "in", "no", "on", "by", "for", "is", "it",
                 "or", "as", "an", "be", "per", "not", "all", "off", "yes", "see", "use",
                 "set", "via", "one", "two", "new", "old", "top", "end", "row", "col", "add",
                 "bad", "low", "high", "from", "with", "mean", "peak", "left", "right"}

WORD = re.compile(r"[A-Za-z][A-Za-z0-9_']*")
#: A word of Cyrillic and Latin letters together ("положениеs").
MIXED = re.compile(r"\w*(?:[А-Яа-яЁё][A-Za-z]|[A-Za-z][А-Яа-яЁё])\w*")


def latin_words(text: str, names: Iterable[str] = ()) -> list[str]:
    """The Latin words of ``text`` that are not allowed in a Russian document: a word is
    allowed when it is a unit name, one of ``names`` (the user's names from the model:
    vectors, bodies, joints, loads, the model's name) or a word of them, or a symbol: at
    most three letters (with digits or subscripts: r3, ddr3, F_bal, S2, Jred), unless it
    is a short English word. 'units' 'kN·m', 'rad/s' split into their parts."""
    allowed = set(UNITS)
    for name in names:
        allowed.update(WORD.findall(name))
    found = MIXED.findall(text)
    for word in WORD.findall(text):
        if word in allowed or word.replace("'", "") in allowed:
            continue
        letters = re.sub(r"[0-9_']", "", word)
        head = word.split("_")[0]
        if (len(letters) <= 3 or len(re.sub(r"[0-9']", "", head)) <= 3) \
                and letters.lower() not in ENGLISH_SHORT:
            continue
        found.append(word)
    return found


def model_names(model) -> list[str]:
    """The user's own names of a model (allowed in a Russian report)."""
    out = [model.name, model.description]
    out += [v.name or "" for v in model.vectors.values()]
    out += [b.name or "" for b in model.bodies.values()]
    out += [*(model.joints or {}), *model.gears]
    out += [c.name or "" for c in model.contours]
    for load in [*model.forces, *model.moments]:
        out.append(load.name or "")
        out.append(getattr(load.value, "expression", ""))
    out += [x.name or "" for x in [*model.springs, *model.dampers]]
    if model.report is not None:
        out += [str(v) for v in model.report.model_dump(exclude_none=True).values()]
    return out
