"""Numbers as a language writes them: Russian documents use the decimal comma and write a
power of ten as ``·10⁻⁵`` (GOST 2.105 and 8.417: ``1,5·10⁻⁵``); English keeps ``1.5`` and
``1.5e-05``.

The texts are numbers already formatted by the views and the report (``f"{x:.5g}"``), so
the conversion works on text: a point between digits is a decimal point unless it is part
of a run of dotted numbers (``24.11.2026``, a section number ``3.1.2``), and an exponent is
rewritten only after a number's digits.
"""

from __future__ import annotations

import re

from matplotlib.axis import Axis
from matplotlib.figure import Figure
from matplotlib.ticker import Formatter

#: A number with one decimal point and an optional exponent, not inside a dotted run or a
#: word (``r3.5`` is a name, ``3.1.2`` a section number).
_NUMBER = re.compile(r"(?<![\w.,])(\d+)\.(\d+)(?:e([-+−]?)(\d+))?(?![\w.]|,\d)"
                     r"|(?<![\w.,])(\d+)e([-+−]?)(\d+)(?![\w.])")
_SUPERSCRIPTS = str.maketrans("0123456789-−+", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁻⁺")


def _power(sign: str, digits: str) -> str:
    exponent = (sign if sign in "-−" else "") + digits.lstrip("0") or "0"
    return "·10" + exponent.translate(_SUPERSCRIPTS)


def _russian(match: re.Match[str]) -> str:
    whole, fraction, sign, exponent, mantissa, sign2, exponent2 = match.groups()
    if whole is not None:
        text = f"{whole},{fraction}"
        return text + (_power(sign, exponent) if exponent is not None else "")
    return mantissa + _power(sign2, exponent2)


def localized(text: str, lang: str) -> str:
    """``text`` with its numbers written as ``lang`` writes them: ``'ru'``: ``1,5``,
    ``1,5·10⁻⁵``; any other language: unchanged.

    >>> localized("ε = 1.62, t = 2.5e-05 s, 24.11.2026", "ru")
    'ε = 1,62, t = 2,5·10⁻⁵ s, 24.11.2026'
    """
    if lang != "ru" or not text:
        return text
    return _NUMBER.sub(_russian, text)


class LocalizedFormatter(Formatter):
    """Tick labels of another formatter, with their numbers written in a language."""

    def __init__(self, inner: Formatter, lang: str):
        self.inner = inner
        self.lang = lang

    def set_axis(self, axis: Axis | None) -> None:
        super().set_axis(axis)
        self.inner.set_axis(axis)

    def set_locs(self, locs) -> None:
        self.inner.set_locs(locs)

    def __call__(self, x: float, pos: int | None = None) -> str:
        return localized(self.inner(x, pos), self.lang)

    def format_ticks(self, values) -> list[str]:
        return [localized(t, self.lang) for t in self.inner.format_ticks(values)]

    def format_data_short(self, value: float) -> str:
        return localized(self.inner.format_data_short(value), self.lang)

    def get_offset(self) -> str:
        return localized(self.inner.get_offset(), self.lang)


def localize_ticks(figure: Figure, lang: str) -> Figure:
    """Write the tick labels of every axis of ``figure`` in ``lang`` (``'ru'``: decimal
    comma); other languages leave the figure as it is."""
    if lang != "ru":
        return figure
    for ax in figure.get_axes():
        axes = [ax.xaxis, ax.yaxis, *([ax.zaxis] if hasattr(ax, "zaxis") else [])]
        for axis in axes:
            for which in ("major", "minor"):
                getter = getattr(axis, f"get_{which}_formatter")
                inner = getter()
                if not isinstance(inner, LocalizedFormatter):
                    getattr(axis, f"set_{which}_formatter")(LocalizedFormatter(inner, lang))
    return figure
