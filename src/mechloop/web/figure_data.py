"""The data of a drawn view, read back from its matplotlib figure, for the page's own
interactive plot: what the page draws is what ``mechloop plot`` draws, by construction.

A view function (:mod:`mechloop.views.curves`, :mod:`mechloop.views.dynamics`) builds a
figure; :func:`figure_data` walks its axes and gives, per subplot (twin y-axes made by
``twinx`` share their host's subplot), its title, x label and y-axes, and per y-axis its
label and its series: each line's label, colour, dash, kind (``line``, ``points``, or
``hline``/``vline`` for a line across the axes at one value), its x and y arrays as drawn
(display units, NaN where the chain breaks or a wrapped angle jumps) and the position
number of each point (``positions``: the x itself on a plot over the positions, the point's
index on a curve of one point per position — a hodograph, the machine motion — else None).
Labels are translated as the figure's texts are (:func:`mechloop.views.russian.russian`):
the axis labels and titles by :func:`~mechloop.views.russian.translate` itself, the lines'
labels (which only its legend shows) by the same function.  The tables of a figure (the
summary) come as rows of text.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.colors import to_hex
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.table import Table

from mechloop.views.russian import NAMES_ATTRIBUTE, russian

#: The unit in brackets at the end of a label: ``'J_red [kg*m^2]'`` -> ``'kg*m^2'``.
_UNIT = re.compile(r"^(.*?)\s*\[([^\[\]]*)\]\s*$", re.S)
#: SVG dashes of matplotlib's line styles (px at a line width of 1.8).
DASHES = {"-": "", "--": "6 3", "-.": "6 3 1.5 3", ":": "1.5 3"}


def split_unit(label: str) -> tuple[str, str]:
    """``'J_red [kg*m^2]'`` -> ``('J_red', 'kg*m^2')``; a label without a unit as it is,
    with ``''``."""
    match = _UNIT.match(label or "")
    return (match.group(1), match.group(2)) if match else (label or "", "")


def figure_data(figure: Figure, *, count: int, over: str, lang: str = "en"
                ) -> dict[str, Any]:
    """The panels and tables of ``figure`` (already translated into ``lang``).

    ``count``: the number of positions of the solution; ``over``: ``'position'`` (the x
    axis is the position number), ``'cycle'`` (one point per position along another x:
    the machine motion) or ``'xy'`` (a curve of one point per position in the plane: a
    hodograph).  Returns ``{"panels": [...], "tables": [...]}``.
    """
    names = getattr(figure, NAMES_ATTRIBUTE, set())
    groups: list[list[Axes]] = []
    for ax in figure.axes:
        if ax.name == "3d":  # a 3-D view (a spatial hodograph's): its projections are panels
            continue
        spec = ax.get_subplotspec()
        host = next((g for g in groups if spec is not None
                     and g[0].get_subplotspec() == spec), None)
        if host is None:
            groups.append([ax])
        else:
            host.append(ax)
    panels, tables = [], []
    for group in groups:
        host = group[0]
        tables += [_table(t) for ax in group for t in ax.tables if isinstance(t, Table)]
        yaxes = [_yaxis(ax, count, over, lang, names) for ax in group]
        yaxes = [y for y in yaxes if y["series"]]
        if not yaxes:
            continue
        xlabel = next((ax.get_xlabel() for ax in group if ax.get_xlabel()), "")
        panels.append({"title": host.get_title(), "xlabel": xlabel,
                       "xunit": split_unit(xlabel)[1],
                       "equal": host.get_aspect() == 1.0, "over": over, "yaxes": yaxes})
    return {"panels": panels, "tables": tables}


def _yaxis(ax: Axes, count: int, over: str, lang: str, names: set[str]) -> dict[str, Any]:
    label = ax.get_ylabel()
    name, unit = split_unit(label)
    series = [_series(ax, line, count, over, lang, names, unit) for line in ax.get_lines()]
    for s in series:  # a lone unlabelled curve (an increment's panel): the axis's name
        if not s["name"] and s["kind"] == "line":
            s["name"] = name
    return {"label": label, "unit": unit, "series": series}


def _series(ax: Axes, line: Line2D, count: int, over: str, lang: str, names: set[str],
            unit: str) -> dict[str, Any]:
    x = np.asarray(line.get_xdata(), dtype=float)
    y = np.asarray(line.get_ydata(), dtype=float)
    label = str(line.get_label())
    label = "" if label.startswith("_") else (russian(label, names) if lang == "ru" else label)
    name, own = split_unit(label)
    transform = line.get_transform()
    if transform == ax.get_yaxis_transform(which="grid"):  # axhline: one y across
        kind, x, y = "hline", np.array([]), y[:1]
    elif transform == ax.get_xaxis_transform(which="grid"):  # axvline: one x across
        kind, x, y = "vline", x[:1], np.array([])
    elif line.get_linestyle() in ("None", "", " ") and line.get_marker() not in (None, "None"):
        kind = "points"
    else:
        kind = "line"
    marker = line.get_marker()
    return {"label": label, "name": name, "unit": own or unit, "kind": kind,
            "color": to_hex(line.get_color()), "dash": DASHES.get(line.get_linestyle(), ""),
            "marker": "" if marker in (None, "None", "") else str(marker),
            "x": x, "y": y, "positions": _positions(x, count, over, kind)}


def _positions(x: np.ndarray, count: int, over: str, kind: str) -> np.ndarray | None:
    """The position number of each point of a series (NaN at an inserted break), or None
    where the points are not the positions."""
    if kind not in ("line", "points"):
        return None
    if over == "position":
        finite = np.isfinite(x)
        if not np.array_equal(x[finite], np.round(x[finite])):
            return None
        return np.where(finite & (x >= 0) & (x < count), x, np.nan)
    if x.size == count:
        return np.arange(count, dtype=float)
    return None


def _table(table: Table) -> dict[str, Any]:
    """The rows of text of a matplotlib table; ``header``: its first row holds the
    column heads (drawn centred over cells aligned otherwise)."""
    cells = table.get_celld()
    rows = max(r for r, _ in cells) + 1
    cols = max(c for _, c in cells) + 1
    text = [[cells[(r, c)].get_text().get_text() if (r, c) in cells else ""
             for c in range(cols)] for r in range(rows)]

    def aligned(r: int) -> set[str]:
        return {cells[(r, c)].get_text().get_horizontalalignment()
                for c in range(cols) if (r, c) in cells}
    header = rows > 1 and aligned(0) == {"center"} and aligned(1) != {"center"}
    return {"rows": text, "header": header}
