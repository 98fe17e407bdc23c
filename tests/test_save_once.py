"""Saving a figure with one draw (views/save_once.py): the same bytes as matplotlib's
savefig with its two draws, in PDF, PNG and SVG, for constrained and compressed layouts;
one draw instead of two; the figure left as it was."""

from __future__ import annotations

import io

import numpy as np
import pytest
from matplotlib import rc_context

from mechloop.views.figure import new_figure
from mechloop.views.save_once import save_once

KWARGS = {
    "pdf": {"metadata": {"Creator": None, "Producer": None, "CreationDate": None}},
    "png": {"dpi": 213.7, "facecolor": "white"},
    "svg": {"dpi": 150, "metadata": {"Date": None}},
}


def _figure(layout: str):
    """Two axes with legends, long tick labels and titles: the layout moves them."""
    figure = new_figure(7, 5)
    figure.set_layout_engine(layout)
    t = np.linspace(0, 2 * np.pi, 400)
    top, bottom = figure.subplots(2, 1)
    top.plot(t, 1e4 * np.sin(t), label="ξ₁, мм")
    top.set_ylabel("a long label of the vertical axis, N·m")
    top.set_title("Заголовок")
    top.legend(loc="best")
    bottom.plot(np.cos(t), np.sin(2 * t), label="path")
    bottom.set_aspect("equal")
    bottom.set_xlabel("x, m")
    bottom.legend(loc="upper right")
    return figure


@pytest.mark.parametrize("layout", ["constrained", "compressed"])
@pytest.mark.parametrize("fmt", ["pdf", "png", "svg"])
def test_the_same_bytes_as_savefig(fmt, layout):
    with rc_context({"svg.hashsalt": "fixed"}):  # SVG ids are random otherwise
        expected, got = io.BytesIO(), io.BytesIO()
        _figure(layout).savefig(expected, format=fmt, **KWARGS[fmt])
        save_once(_figure(layout), got, format=fmt, **KWARGS[fmt])
    assert got.getvalue() == expected.getvalue()


def test_one_draw_and_the_figure_left_as_it_was(monkeypatch):
    figure = _figure("constrained")
    engine, canvas, dpi = figure.get_layout_engine(), figure.canvas, figure.dpi
    draws = []
    draw = type(figure).draw
    monkeypatch.setattr(type(figure), "draw", lambda self, r: (draws.append(r), draw(self, r)))
    save_once(figure, io.BytesIO(), format="pdf")
    assert len(draws) == 1
    figure.savefig(io.BytesIO(), format="pdf")
    assert len(draws) == 3  # savefig's own: a layout draw and the printing draw
    assert figure.get_layout_engine() is engine
    assert figure.canvas is canvas and figure.dpi == dpi


def test_a_figure_without_layout_or_saved_tight_is_saved_by_savefig():
    for layout, extra in [("none", {}), ("constrained", {"bbox_inches": "tight"})]:
        expected, got = io.BytesIO(), io.BytesIO()
        kwargs = {**KWARGS["png"], **extra}
        _figure(layout).savefig(expected, format="png", **kwargs)
        save_once(_figure(layout), got, format="png", **kwargs)
        assert got.getvalue() == expected.getvalue()
