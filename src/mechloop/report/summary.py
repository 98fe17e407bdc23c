"""The summary characteristics of the report (KDAM's summary panel) as two tables: per
load its positive and negative work and its extreme, mean and specific power; then the
totals (driving work, friction, ψ, η, the machine motion's figures) — the rows of
:func:`mechloop.views.dynamics.summary_rows`, in the display's units, put in the report's
language."""

from __future__ import annotations

import re

from mechloop.dynamics.analysis import DynamicResults
from mechloop.report.document import Table
from mechloop.report.numbers import unit_text
from mechloop.views.decimal_mark import localized
from mechloop.views.display import Display
from mechloop.views.dynamics import summary_rows
from mechloop.views.russian import model_names, russian

_BRACKETED = re.compile(r"\s*\[([^\]]+)\]")
_TRAILING_UNIT = re.compile(r"^(\S+) ([^\s\d−-][^\s]*)$")


def summary_tables(dyn: DynamicResults, display: Display, lang: str,
                   w: dict[str, str]) -> list[Table]:
    """The loads' table and the totals' table; ``w``: the report's words
    (:func:`mechloop.report.words.words`)."""
    header, rows, totals = summary_rows(dyn, display)
    names = model_names(dyn.kinematics.model)

    def words(text: str) -> str:
        text = russian(text, names) if lang == "ru" else text
        return _BRACKETED.sub(lambda m: ", " + unit_text(m.group(1), lang), text)

    def value(text: str) -> str:
        match = _TRAILING_UNIT.match(text)
        if match:
            return f"{localized(match.group(1), lang)} {unit_text(match.group(2), lang)}"
        return words(text)

    loads = Table(w["t_summary_loads"], tuple(words(h) for h in header),
                  [(words(r[0]), *(localized(c, lang) for c in r[1:])) for r in rows])
    figures = Table(w["t_summary_totals"], (w["h_quantity"], w["h_value"]),
                    [(words(name), value(text)) for name, text in totals])
    return [loads, figures]
