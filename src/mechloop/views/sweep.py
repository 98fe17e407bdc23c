"""Plots of a parametric analysis (:func:`mechloop.synthesis.sweep.sweep`).

One parameter: every quantity against the parameter, quantities of one unit on one plot
(KDAM seed 000, Fig. 2.5: the balancing moment against the engine speed).  Two
parameters: for every quantity one line per value of the second parameter, or — for more
than :data:`~mechloop.views.curves.MAX_CURVES` values — a filled contour map over the
grid.  Quantities are shown in the units of a :class:`~mechloop.views.display.Display`
(the parameters as the table holds them, in the model's units).  Designs whose chain
breaks have no values: lines have a gap there and maps a blank.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from numpy.typing import NDArray

from mechloop.synthesis.sweep import grid, sweep_columns
from mechloop.views.curves import COLUMN_KINDS, MAX_CURVES
from mechloop.views.display import DEFAULT_DISPLAY, Display
from mechloop.views.figure import ViewError, new_figure

Array = NDArray[np.float64]


def _split_header(header: str) -> tuple[str, str]:
    """``'M_bal:max [N*m]'`` -> ``('M_bal:max', 'N*m')``."""
    if header.endswith("]") and " [" in header:
        name, _, unit = header[:-1].rpartition(" [")
        return name, unit
    return header, ""


def _shown(frame: pd.DataFrame, header: str, display: Display) -> tuple[Array, str]:
    """The values of a quantity column in display units, and the unit shown."""
    _, unit = _split_header(header)
    values = frame[header].to_numpy(dtype=float)
    kind = COLUMN_KINDS.get(unit)
    if kind is None:
        return values, unit
    if unit == "deg":
        values = np.radians(values)
    return display.convert(values, kind), display.label(kind)


def _label(header: str, unit: str) -> str:
    name, _ = _split_header(header)
    return f"{name} [{unit}]" if unit else name


def _choose(frame: pd.DataFrame, quantities: Sequence[str] | str | None) -> list[str]:
    known = sweep_columns(frame)[1]
    if quantities is None:
        if not known:
            raise ViewError("the table has no quantities to plot",
                            "pass the table that mechloop.synthesis.sweep.sweep returns")
        return known
    chosen = [quantities] if isinstance(quantities, str) else list(quantities)
    out = []
    for q in chosen:
        match = [k for k in known if q in (k, _split_header(k)[0])]
        if not match:
            raise ViewError(f"no quantity {q!r} in this sweep", f"use one of {', '.join(known)}")
        out.append(match[0])
    return out


def plot_sweep(frame: pd.DataFrame, quantities: Sequence[str] | str | None = None, *,
               contour: bool | None = None, display: Display = DEFAULT_DISPLAY) -> Figure:
    """Draw a sweep table.

    Parameters
    ----------
    frame : the table of :func:`~mechloop.synthesis.sweep.sweep` (or the same read back
        from CSV: parameter columns first, quantity columns named ``COLUMN:REDUCTION``).
    quantities : which quantity columns to draw (``'M_bal:max'`` or the full header;
        default all).
    contour : two parameters only — a filled contour map per quantity (True), one line per
        value of the second parameter (False), or None: a map when the second parameter
        has more than :data:`~mechloop.views.curves.MAX_CURVES` values.
    display : units of the quantities.
    """
    params, _ = sweep_columns(frame)
    names = _choose(frame, quantities)
    if len(params) == 1:
        return _lines_one(frame, params[0], names, display)
    if len(params) != 2:
        raise ViewError(f"cannot draw a sweep of {len(params)} parameters",
                        "sweep one parameter (lines) or two (a family of lines or a map)")
    n_second = len(pd.unique(frame[params[1]]))
    if contour is None:
        contour = n_second > MAX_CURVES
    return (_maps if contour else _lines_two)(frame, params, names, display)


def _broken(frame: pd.DataFrame) -> int:
    if "broken" not in frame or "note" not in frame:
        return 0
    notes = frame["note"].map(lambda v: v if isinstance(v, str) else "")
    return int(((frame["broken"] > 0) | (notes != "")).sum())


def _title(figure: Figure, frame: pd.DataFrame, text: str) -> None:
    failed = _broken(frame)
    if failed:
        text += f" — {failed} design(s) without values (chain break; see 'note')"
    figure.suptitle(text, fontsize="medium")


def _axes(figure: Figure, count: int) -> list[Axes]:
    axes = figure.subplots(count, 1, sharex=True, squeeze=False)[:, 0]
    return list(axes)


def _lines_one(frame: pd.DataFrame, param: str, names: list[str], display: Display
               ) -> Figure:
    """One parameter: quantities grouped by their display unit, one plot per unit."""
    x = frame[param].to_numpy(dtype=float)
    groups: dict[str, list[tuple[str, Array]]] = {}
    for name in names:
        values, unit = _shown(frame, name, display)
        groups.setdefault(unit, []).append((name, values))
    figure = new_figure(8.0, 1.5 + 3.0 * len(groups))
    for ax, (unit, curves) in zip(_axes(figure, len(groups)), groups.items(), strict=True):
        for i, (name, values) in enumerate(curves):
            ax.plot(x, values, "o-", color=f"C{i % 10}", markersize=3,
                    label=_split_header(name)[0])
        ax.set_ylabel(", ".join(_split_header(n)[0] for n, _ in curves)
                      + (f" [{unit}]" if unit else ""))
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small")
    ax.set_xlabel(param)
    _title(figure, frame, f"parametric analysis: against {_split_header(param)[0]}")
    return figure


def _lines_two(frame: pd.DataFrame, params: list[str], names: list[str], display: Display
               ) -> Figure:
    """Two parameters: one plot per quantity, one line per value of the second."""
    figure = new_figure(8.0, 1.5 + 3.0 * len(names))
    second = pd.unique(frame[params[1]])
    if len(second) > 2 * MAX_CURVES:
        raise ViewError(f"{len(second)} values of {params[1]} are too many lines for one "
                        "plot", "draw a contour map (contour=True, --contour)")
    axes = _axes(figure, len(names))
    name2, unit2 = _split_header(params[1])
    for ax, name in zip(axes, names, strict=True):
        values, unit = _shown(frame, name, display)
        for i, value in enumerate(second):
            rows = (frame[params[1]] == value).to_numpy()
            ax.plot(frame[params[0]].to_numpy(dtype=float)[rows], values[rows], "o-",
                    color=f"C{i % 10}", markersize=3,
                    label=f"{name2} = {_value(value, display)}" + (f" {unit2}" if unit2 else ""))
        ax.set_ylabel(_label(name, unit))
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small", ncols=2 if len(second) > 6 else 1)
    axes[-1].set_xlabel(params[0])
    _title(figure, frame, f"parametric analysis: against {_split_header(params[0])[0]}")
    return figure


def _value(value: object, display: Display) -> str:
    return display.format(float(value)) if isinstance(value, int | float | np.number) \
        else str(value)


def _maps(frame: pd.DataFrame, params: list[str], names: list[str], display: Display
          ) -> Figure:
    """Two parameters: a filled contour map of every quantity over the grid."""
    figure = new_figure(8.0, 1.0 + 4.0 * len(names))
    for ax, name in zip(_axes(figure, len(names)), names, strict=True):
        x, y, _ = grid(frame, name)
        values, unit = _shown(frame, name, display)
        z = np.ma.masked_invalid(values.reshape(len(x), len(y)))
        if z.count() < 1 or len(x) < 2 or len(y) < 2:
            raise ViewError(f"{name}: too few values for a contour map",
                            "sweep at least two values of each parameter, or draw lines")
        filled = ax.contourf(x, y, z.T, levels=12, cmap="viridis")
        ax.contour(x, y, z.T, levels=filled.levels, colors="k", linewidths=0.4)
        figure.colorbar(filled, ax=ax, label=_label(name, unit))
        ax.set_ylabel(params[1])
        ax.set_title(_split_header(name)[0], fontsize="medium")
    ax.set_xlabel(params[0])
    _title(figure, frame, "parametric analysis")
    return figure
