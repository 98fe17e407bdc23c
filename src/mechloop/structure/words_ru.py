"""Russian of the structural analysis' texts (``mechloop structure``, the web's structure
panel): Chebyshev's count and its explanation, the notes on passive links, local
mobilities, redundant constraints and gear meshes, the structure formula and the groups,
with the terms of the course (звено, кинематическая пара, группа Ассура, класс,
степень подвижности).

The analysis writes its texts in English (:mod:`.mobility`, :mod:`.assur`, :mod:`.meshes`);
:func:`russian` says each of its sentences in Russian by the patterns of :data:`SENTENCES`
(one per sentence the analysis writes).  Numbers get the decimal comma.
"""

from __future__ import annotations

import re
from collections.abc import Callable

_NAMES = r"(?P<what>.+?)"


def _held(names: str) -> str:
    """Constraint names as the analysis lists them: pair names, 'argument 1'."""
    return re.sub(r"\bargument (\d+)", r"привод аргумента \1", names)


#: (English pattern, Russian) for every sentence of the analysis' texts, whole match.
SENTENCES: list[tuple[str, str | Callable[[re.Match[str]], str]]] = [
    (r"W = (?P<w>-?\d+) equals the number of inputs",
     "W = {w} равно числу входов"),
    (r"W = (?P<w>-?\d+) > (?P<i>\d+) input\(s\): (?P<m>\d+) input\(s\) missing — the "
     r"mechanism needs (?P<m2>\d+) more drive\(s\), or a link has a local mobility",
     "W = {w} > {i} (число входов): не хватает входов: {m} — механизму нужно ещё приводов: "
     "{m2}, или у звена есть местная подвижность"),
    (r"W = (?P<w>-?\d+) ≤ 0 and no inputs: a structure \(a truss\), not a mechanism"
     r"(?P<r>, with redundant constraints)?",
     lambda m: f"W = {m['w']} ≤ 0 и нет входов: это ферма, а не механизм"
     + (", с избыточными связями" if m["r"] else "")),
    (r"W = (?P<w>-?\d+) < (?P<i>\d+) input\(s\): redundant constraints \(an over-constrained "
     r"chain, a passive link\) or more drives than the chain can take"
     r"(?P<z>; W ≤ 0: the chain cannot move at all unless its geometry is special)?",
     lambda m: f"W = {m['w']} < {m['i']} (число входов): избыточные связи (статически "
     "неопределимая цепь, пассивное звено) или приводов больше, чем допускает цепь"
     + ("; W ≤ 0: цепь вообще не может двигаться, если её размеры не особые"
        if m["z"] else "")),
    (r"link (?P<k>\d+) is held by " + _NAMES + r" to links already placed: (?P<c>\d+) "
     r"conditions on its 3 freedoms — a passive link, its extra constraint redundant",
     lambda m: f"звено {m['k']} присоединено парами {_held(m['what'])} к уже присоединённым "
     f"звеньям: условий связи {m['c']} на 3 степени свободы — пассивное звено, его лишняя "
     "связь избыточна"),
    (r"link (?P<k>\d+) is held only by " + _NAMES + r": it keeps (?P<f>\d+) degree\(s\) of "
     r"freedom of its own — a local mobility",
     lambda m: f"звено {m['k']} держится только за счёт {_held(m['what'])}: у него "
     f"остаётся собственных степеней свободы: {m['f']} — местная подвижность"),
    (r"link (?P<k>\d+) is joined to nothing: it keeps (?P<f>\d+) degree\(s\) of freedom of "
     r"its own — a local mobility",
     "звено {k} ни с чем не соединено: у него остаётся собственных степеней свободы: {f} "
     "— местная подвижность"),
    (r"links (?P<l>[\d, ]+) keep (?P<f>\d+) degree\(s\) of freedom: an input is missing "
     r"\(or they have a local mobility\)",
     "у звеньев {l} остаётся степеней свободы: {f} — не хватает входа (или у них местная "
     "подвижность)"),
    (r"links (?P<l>[\d, ]+) have (?P<c>\d+) constraint\(s\) more than their freedoms: a "
     r"redundant constraint \(an over-constrained chain\)",
     "у звеньев {l} условий связи больше, чем степеней свободы, на {c}: избыточная связь "
     "(статически неопределимая цепь)"),
    (r"links (?P<l>[\d, ]+) have as many constraints as freedoms but form no rigid group: "
     r"one part is over-constrained while another moves \(or a chain of prismatic pairs "
     r"slides freely\)",
     "у звеньев {l} условий связи столько же, сколько степеней свободы, но они не образуют "
     "группу нулевой подвижности: одна часть статически неопределима, а другая движется "
     "(или цепь поступательных пар свободно скользит)"),
    (r"the drive of argument (?P<a>\d+) acts between links (?P<i>\d+) and (?P<j>\d+), which "
     r"are placed without it: a redundant input",
     "привод аргумента {a} действует между звеньями {i} и {j}, положение которых "
     "определено и без него: избыточный вход"),
    (r"the gear mesh between bodies (?P<i>\d+) and (?P<j>\d+) is replaced by its "
     r"equivalent, link (?P<k>\d+) with revolute pairs (?P<p>\S+) and (?P<q>\S+) \(at the "
     r"centres of curvature of the teeth in contact\)",
     "зубчатое зацепление звеньев {i} и {j} заменено эквивалентным звеном {k} с "
     "вращательными парами {p} и {q} (в центрах кривизны профилей зубьев в точке "
     "контакта)"),
    (r"gear mesh \(ratio link\) between bodies (?P<i>\d+) and (?P<j>\d+), ratio (?P<r>\S+) "
     r"\((?P<law>[^()]*)\): a higher pair p4",
     "зубчатое зацепление (связь с передаточным отношением) звеньев {i} и {j}, отношение "
     "{r} ({law}): высшая пара p4"),
]
_COMPILED = [(re.compile(pattern), russian) for pattern, russian in SENTENCES]


def russian(sentence: str) -> str:
    """One sentence of the analysis in Russian (a sentence no pattern knows stays as
    written rather than being lost)."""
    for pattern, said in _COMPILED:
        match = pattern.fullmatch(sentence)
        if match:
            return said(match) if callable(said) else said.format(**match.groupdict())
    return sentence


#: Words of the printed structure (:func:`mechloop.structure.text.structure_lines`).
WORDS: dict[str, dict[str, str]] = {
    "en": {"no meshes": "no higher pairs in the model", "inputs": "inputs",
           "but": " — but: ", "found": " — found: ",
           "formula": "structure formula: ", "class": "class of the mechanism: ",
           "undetermined": "not determined (links left over)", "external": "external",
           "internal": "internal", "variant": "; variant ", "note": "note:"},
    "ru": {"no meshes": "высших пар в модели нет", "inputs": "число входов",
           "but": " — однако: ", "found": " — обнаружено: ",
           "formula": "формула строения: ", "class": "класс механизма: ",
           "undetermined": "не определён (остались звенья)", "external": "внешние пары",
           "internal": "внутренние пары", "variant": "; вариант сборки ",
           "note": "примечание:"},
}
