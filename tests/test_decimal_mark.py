"""Numbers in Russian documents with the decimal comma and ``·10ⁿ`` powers (GOST 2.105):
every number the views and the report format comes back as the same value; dotted runs
(dates, section numbers), names and English texts are left alone; Russian figures' tick
labels use the comma too."""

from __future__ import annotations

import re

import matplotlib
import pytest
from hypothesis import given
from hypothesis import strategies as st
from matplotlib.figure import Figure

from mechloop.views.decimal_mark import localize_ticks, localized

matplotlib.use("Agg")

_DIGITS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def _back(text: str) -> float:
    """A Russian number read back as an independent reader would."""
    mantissa, _, power = text.partition("·10")
    return float(mantissa.replace(",", ".") + (f"e{power.translate(_DIGITS)}" if power else ""))


@given(st.floats(allow_nan=False, allow_infinity=False),
       st.sampled_from(["{:.5g}", "{:g}", "{:.3f}", "{:.6e}", "{}"]))
def test_a_formatted_number_keeps_its_value_and_has_no_point(value, form):
    english = form.format(value)
    russian = localized(english, "ru")
    assert "." not in russian and "e" not in russian.replace("inf", "")
    assert _back(russian) == float(english)
    assert localized(english, "en") == english


def test_words_dates_and_section_numbers_keep_their_points():
    assert localized("r3.5 at 24.11.2026, section 3.1.2, v1.2.3", "ru") == \
        "r3.5 at 24.11.2026, section 3.1.2, v1.2.3"
    assert localized("ε_α = 1.62 ≥ 1.2; t = 2.5e-05 s; 1e+06 N", "ru") == \
        "ε_α = 1,62 ≥ 1,2; t = 2,5·10⁻⁵ s; 1·10⁶ N"


def test_russian_tick_labels_have_the_decimal_comma():
    figure = Figure()
    ax = figure.add_subplot()
    ax.plot([0.0, 0.5, 1.0], [0.0, 2.5e-5, 1e-5])
    localize_ticks(figure, "ru")
    figure.canvas.draw()
    ticks = ax.get_xticks()
    x = ax.xaxis.get_major_formatter().format_ticks(ticks)
    assert any("," in t for t in x) and not any(re.search(r"\d\.\d", t) for t in x)
    assert [_back(t.replace("−", "-")) for t in x] == pytest.approx(list(ticks), abs=1e-12)
    drawn = [t.get_text() for t in ax.get_yticklabels() if t.get_text()]
    assert drawn and not any(re.search(r"\d\.\d", t) for t in drawn)
    assert localize_ticks(figure, "ru") is figure  # twice: wrapped once
    assert type(ax.xaxis.get_major_formatter().inner).__name__ != "LocalizedFormatter"
