"""The structural analysis as text, in English or Russian: what ``mechloop structure``
prints and the web's structure panel shows (Chebyshev's count with its explanation, the
structure formula, the class, the groups, the notes, the identification table).

English is the analysis' own text; Russian is said by :mod:`.words_ru` with the decimal
comma.
"""

from __future__ import annotations

from mechloop.structure.assur import ROMAN, Decomposition, Group
from mechloop.structure.mobility import Mobility
from mechloop.structure.words_ru import WORDS, russian

LANGUAGES = ("en", "ru")


def _numbers(text: str, lang: str) -> str:
    if lang == "en":
        return text
    from mechloop.views.decimal_mark import localized  # the decimal comma

    return localized(text, lang)


def note_text(note: str, lang: str = "en") -> str:
    """One note of the analysis (a passive link, a local mobility, a gear mesh) in
    ``lang``."""
    return note if lang == "en" else _numbers(russian(note), lang)


def explanation(mobility: Mobility, lang: str = "en") -> str:
    """:attr:`Mobility.explanation` in ``lang``: the verdict on W against the inputs and
    the notes that point at the links."""
    text = mobility.explanation
    if lang == "en":
        return text
    body = text[:-1] if text.endswith(".") else text
    for key in ("but", "found"):
        joint = WORDS["en"][key]
        if joint in body:
            head, notes = body.split(joint, 1)
            said = "; ".join(russian(n) for n in notes.split("; "))
            return _numbers(f"{russian(head)}{WORDS[lang][key]}{said}.", lang)
    return _numbers(russian(body) + ".", lang)


def mobility_text(mobility: Mobility, lang: str = "en") -> str:
    """Chebyshev's count as one line, ``n = 3, p5 = 4, p4 = 0 (…): W = 3·3 − 2·4 − 0 = 1;
    inputs: 1. …`` (``str(mobility)`` in English)."""
    if lang == "en":
        return str(mobility)
    words = WORDS[lang]
    m = mobility
    higher = (words["no meshes"] if not m.meshes
              else "; ".join(russian(str(mesh)) for mesh in m.meshes))
    return _numbers(f"n = {m.n}, p5 = {m.p5}, p4 = {m.p4} ({higher}): W = 3·{m.n} − "
                    f"2·{m.p5} − {m.p4} = {m.W}; {words['inputs']}: {m.inputs}. ",
                    lang) + explanation(m, lang)


def class_text(decomposition: Decomposition, lang: str = "en") -> str:
    """The class of the mechanism in Roman numerals, or why it is not determined."""
    cls = decomposition.mechanism_class
    if cls is None:
        return WORDS[lang]["undetermined"]
    return ROMAN[cls] if cls < len(ROMAN) else str(cls)


def group_line(group: Group, lang: str = "en") -> str:
    """``L1(2,3): external A R 2→1, C R 3→0; internal B R 2–3; variant 1``."""
    words = WORDS[lang]
    ext = ", ".join(f"{p.name} {p.kind} {p.link}→{p.to}" for p in group.external)
    inner = ", ".join(f"{p.name} {p.kind} {p.link}–{p.to}" for p in group.internal)
    variant = "" if group.variant is None else f"{words['variant']}{group.variant}"
    return (f"{group.label}: {words['external']} {ext or '—'}; {words['internal']} "
            f"{inner or '—'}{variant}")


def structure_lines(mobility: Mobility, decomposition: Decomposition,
                    lang: str = "en") -> list[tuple[str, str]]:
    """The lines ``mechloop structure`` prints before the identification table, as
    (kind, text): kind 'note' for a note (printed after its label ``note:``), else ''."""
    words = WORDS[lang]
    lines = [("", mobility_text(mobility, lang)),
             ("", f"{words['formula']}{decomposition.formula}"),
             ("", f"{words['class']}{class_text(decomposition, lang)}")]
    lines += [("", f"  {group_line(group, lang)}") for group in decomposition.groups]
    lines += [("note", note_text(note, lang)) for note in decomposition.notes]
    return lines


#: The identification table's columns and index in Russian.
RUSSIAN_COLUMNS = {"pairs": "пары", "variant": "вариант"}


def table_text(decomposition: Decomposition, lang: str = "en") -> str:
    """The identification table (:func:`mechloop.structure.table.identification_table`)
    as printed."""
    from mechloop.structure.table import identification_table

    frame = identification_table(decomposition)
    if lang != "en":
        frame = frame.rename(columns=RUSSIAN_COLUMNS)
        frame.index.name = "группа"
    return frame.to_string()
