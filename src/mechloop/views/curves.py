"""KDAM's plots of parameters over the cycle: dependencies, combinations of two parameters,
the angle between two vectors, and the increment of a parameter with its derivatives.

A *name* is spelled like a column of the results table without its unit: ``'r3'``,
``'a2'`` (value), ``'dr3'``, ``'da2'`` (first derivative), ``'ddr3'``, ``'dda2'`` (second
derivative), ``'arg1'``, ``'time'``, ``'position'``, and — for
:class:`~mechloop.dynamics.analysis.DynamicResults` — any dynamic column stem (``'M_bal'``,
``'J_red'``, ``'RA'``, ``'RA_x'``, ``'xS2'``, ``'omega_fw'``, ...).  Values are kept in SI
(:class:`Series`) and shown in the units of a
:class:`~mechloop.views.display.Display`.  Every plot function returns the figure it drew
on; with ``ax=`` it draws on that axes (and its figure).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pint
from matplotlib import rcParams
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.transforms import offset_copy
from numpy.typing import NDArray

from mechloop.dynamics.analysis import DynamicResults
from mechloop.model.units import registry
from mechloop.solve.results import Results
from mechloop.views.display import DEFAULT_DISPLAY, Display
from mechloop.views.figure import ViewError, new_figure

Array = NDArray[np.float64]
AnyResults = Results | DynamicResults

#: Most curves on one plot (KDAM's limit).
MAX_CURVES = 6
#: Most units drawn on y-axes side by side; more go on stacked panels.
MAX_AXES = 3
#: How far each further right y-axis is pushed out (fraction of the axes width).
AXIS_OFFSET = 0.16
#: Line style of the curves of the first, second, ... y-axis.
AXIS_STYLES = ("-", "--", "-.", ":")
#: Gap (points) between the x-axis label and a legend below it.
LEGEND_GAP = 4.0
#: How :func:`plot_parameters` lays out several units.
LAYOUTS = ("auto", "axes", "panels")
#: The operations of :func:`combine`.
COMBINATIONS = ("sum", "difference", "product", "ratio", "power")
_SYMBOL = {"sum": "+", "difference": "−", "product": "·", "ratio": "/", "power": "^"}

#: The kind of quantity of each unit the dynamic table writes.
COLUMN_KINDS = {"m": "length", "deg": "angle", "s": "time", "kg": "mass", "N": "force",
                "N*m": "moment", "kg*m^2": "inertia", "kg*m^2/rad": "inertia/angle",
                "kg/m": "mass/length", "W": "power", "J": "energy",
                "rad/s": "angular_velocity", "rad/s^2": "angular_acceleration",
                "m/s": "velocity", "m/s^2": "acceleration"}

_KINEMATIC = re.compile(r"^(d{0,2})([rab])(\d+)$")  # b: β of a spatial vector
_COLUMN = re.compile(r"^(.+) \[(.+)\]$")
_TABLE_HEAD = re.compile(r"^(time|arg\d+)$")


@dataclass(frozen=True)
class Series:
    """One quantity over the positions.

    ``values``: shape (P,), SI (m, rad, s, N, ...); ``kind``: its kind of quantity for a
    :class:`~mechloop.views.display.Display` (None: a number shown as it is, in
    ``unit``); ``period``: for a wrapped angle, its period (rad) — the plot breaks the
    line where the value jumps by more than half of it.
    """

    name: str
    values: Array
    kind: str | None
    unit: str = ""
    period: float | None = None

    def shown(self, display: Display) -> Array:
        """The values in the display units, shape (P,)."""
        return self.values if self.kind is None else display.convert(self.values, self.kind)

    def unit_text(self, display: Display) -> str:
        return self.unit if self.kind is None else display.label(self.kind)

    def label(self, display: Display) -> str:
        """``'a2 [deg]'`` (or just the name for a plain number)."""
        unit = self.unit_text(display)
        return f"{self.name} [{unit}]" if unit else self.name


class _Source:
    """Resolves names against one set of results (the dynamic table built once)."""

    def __init__(self, results: AnyResults):
        if isinstance(results, DynamicResults):
            self.dynamic: DynamicResults | None = results
            self.kin = results.kinematics
        elif isinstance(results, Results):
            self.dynamic, self.kin = None, results
        else:
            raise ViewError(f"cannot plot a {type(results).__name__}",
                            "pass the Results of mechloop.solve or the DynamicResults of "
                            "mechloop.solve_dynamics")
        self._columns: dict[str, tuple[Array, str]] | None = None

    def columns(self) -> dict[str, tuple[Array, str]]:
        """Dynamic column stem -> (values as written, unit as written)."""
        if self._columns is None:
            self._columns = {}
            if self.dynamic is not None:
                frame = self.dynamic.to_frame()
                for column in frame.columns:
                    match = _COLUMN.match(str(column))
                    if match and not _KINEMATIC.match(match.group(1)) \
                            and not _TABLE_HEAD.match(match.group(1)):
                        self._columns[match.group(1)] = (
                            frame[column].to_numpy(dtype=float), match.group(2))
        return self._columns

    def names(self) -> list[str]:
        """Every name this source knows, for messages."""
        kin = [f"{d}{p}" for p in self.kin.varying() for d in ("", "d", "dd")]
        args = [f"arg{k}" for k in sorted(self.kin.arguments)]
        clock = ["time"] if self.kin.has_time else []
        return ["position", *clock, *args, *kin, *self.columns()]

    def get(self, name: str) -> Series:
        name = str(name).strip()
        match = _KINEMATIC.match(name)
        if match and f"{match.group(2)}{match.group(3)}" in self.kin.values:
            return self._kinematic(name, *match.groups())
        if name == "position":
            return Series(name, self.kin.positions.astype(float), None)
        if name == "time" and self.kin.time is not None:
            return Series(name, self.kin.time, "time")
        if name.startswith("arg") and name[3:].isdigit() and int(name[3:]) in self.kin.arguments:
            k = int(name[3:])
            return Series(name, self.kin.arguments[k], self.kin.argument_kinds[k])
        if name in self.columns():
            values, unit = self.columns()[name]
            kind = COLUMN_KINDS.get(unit)
            if unit == "deg":  # a reaction's direction: continuous, not wrapped
                values = continuous_angle(np.radians(values), centred=True)
            return Series(name, values, kind, "" if kind else unit)
        raise self._unknown(name)

    def _kinematic(self, name: str, order: str, letter: str, number: str) -> Series:
        parameter = f"{letter}{number}"
        base = "length" if letter == "r" else "angle"
        divisor = {"s": "time", "rad": "angle", "m": "length"}[self.kin.derivative_units()[0]]
        if order == "":
            value = self.kin.value(parameter)
            return Series(name, continuous_angle(value) if letter != "r" else value, base)
        if order == "d":
            return Series(name, self.kin.rate(parameter), f"{base}/{divisor}")
        return Series(name, self.kin.accel(parameter), f"{base}/{divisor}^2")

    def _unknown(self, name: str) -> ViewError:
        known = self.names()
        shown = ", ".join(known[:40]) + (", ..." if len(known) > 40 else "")
        extra = ("" if self.dynamic is not None else
                 "; dynamic columns (M_bal, RA, J_red, ...) need mechloop.solve_dynamics")
        if name == "time":
            return ViewError("this model has no time, so nothing can be plotted against "
                             "time", "plot against 'position' or an argument ('arg1'), or "
                             "give the model a time: {rpm: ...}")
        return ViewError(f"no quantity {name!r} in these results",
                         f"use one of: {shown}{extra}")


def series(results: AnyResults, name: str) -> Series:
    """The quantity ``name`` of ``results`` over the positions (SI), with its kind."""
    return _Source(results).get(name)


# ----------------------------------------------------------------------------- drawing


def axes_for(ax: Axes | None, width: float = 8.0, height: float = 5.0
             ) -> tuple[Figure, Axes]:
    """The figure and axes to draw on: ``ax`` and its figure, or a new single plot."""
    if ax is None:
        figure = new_figure(width, height)
        return figure, figure.add_subplot()
    figure = ax.figure
    while not isinstance(figure, Figure):  # a SubFigure: its parent (matplotlib >= 3.8)
        figure = figure.figure
    return figure, ax


def broken_at_jumps(x: Array, y: Array, period: float | None) -> tuple[Array, Array]:
    """``x, y`` with a NaN point inserted where ``y`` jumps by more than ``period/2`` (a
    wrapped angle), so the line is not drawn across the plot; unchanged without period."""
    if period is None or y.size < 2:
        return x, y
    jumps = np.flatnonzero(np.abs(np.diff(y)) > period / 2) + 1
    return (np.insert(x.astype(float), jumps, np.nan), np.insert(y.astype(float), jumps, np.nan))


def unit_groups(curves: Sequence[Series], display: Display) -> dict[str, list[int]]:
    """The display unit of each y-axis (in the order the curves first use it) and the
    indices of its curves: ``{'m': [0], 'm/s': [1], 'm/s^2': [2]}``."""
    groups: dict[str, list[int]] = {}
    for i, curve in enumerate(curves):
        groups.setdefault(curve.unit_text(display), []).append(i)
    return groups


def check_curves(curves: Sequence[Series], display: Display) -> None:
    """ViewError for no curve or more than :data:`MAX_CURVES`, naming the asked curves
    with their units."""
    if not curves:
        raise ViewError("nothing to plot", "name at least one quantity, e.g. ['a2']")
    if len(curves) > MAX_CURVES:
        asked = ", ".join(c.label(display) for c in curves)
        raise ViewError(f"{len(curves)} curves asked for one plot ({asked}); at most "
                        f"{MAX_CURVES} fit", "split them over several plots")


def draw_curves(ax: Axes, x: Series, curves: Sequence[Series], display: Display,
                *, styles: Sequence[str] | None = None, xlabel: bool = True) -> list[Axes]:
    """Draw up to :data:`MAX_CURVES` ``curves`` against ``x`` on ``ax``, one y-axis per
    display unit: the first unit on the left, the second on the right, each further one
    on the right again, its spine pushed out by :data:`AXIS_OFFSET` of the axes width.

    Each y-axis is labelled with its curves' names and its unit; an axis of one curve is
    coloured like it.  The legend goes below the x-axis label (``xlabel=False``: no
    label, e.g. over another plot sharing x), outside the curves.
    Returns the y-axes, one per unit, in the order of :func:`unit_groups`.
    """
    check_curves(curves, display)
    groups = unit_groups(curves, display)
    axes = [ax]
    for k in range(1, len(groups)):
        twin = ax.twinx()
        for side in ("left", "top", "bottom"):  # the host draws these
            twin.spines[side].set_visible(False)
        if k > 1:
            twin.spines["right"].set_position(("axes", 1.0 + AXIS_OFFSET * (k - 1)))
        axes.append(twin)
    xs = x.shown(display)
    for axis, (unit, members) in zip(axes, groups.items(), strict=True):
        _draw_group(axis, xs, curves, members, unit, display, styles,
                    AXIS_STYLES[axes.index(axis) % len(AXIS_STYLES)])
    ax.set_xlabel(x.label(display) if xlabel else "")
    ax.grid(True, alpha=0.3)
    legend_below(ax, [line for axis in axes for line in axis.get_lines()])
    return axes


def draw_panels(figure: Figure, x: Series, curves: Sequence[Series], display: Display,
                *, styles: Sequence[str] | None = None) -> list[Axes]:
    """Draw ``curves`` against ``x`` on stacked panels of ``figure`` sharing the x-axis,
    one panel (y-axis) per display unit, labelled as in :func:`draw_curves`; the legend
    goes below the bottom panel's x-axis label.  Returns the panels, top first."""
    check_curves(curves, display)
    groups = unit_groups(curves, display)
    panels = list(np.atleast_1d(figure.subplots(len(groups), 1, sharex=True)))
    xs = x.shown(display)
    for panel, (unit, members) in zip(panels, groups.items(), strict=True):
        _draw_group(panel, xs, curves, members, unit, display, styles, "-")
        panel.grid(True, alpha=0.3)
    panels[-1].set_xlabel(x.label(display))
    legend_below(panels[-1], [line for panel in panels for line in panel.get_lines()])
    return panels


def _draw_group(axis: Axes, xs: Array, curves: Sequence[Series], members: list[int],
                unit: str, display: Display, styles: Sequence[str] | None,
                style: str) -> None:
    """The curves ``members`` (of one ``unit``) on ``axis``; its y-axis label names them
    with the unit and takes the colour of a lone curve."""
    for i in members:
        curve = curves[i]
        xx, yy = broken_at_jumps(xs, curve.shown(display), _shown_period(curve, display))
        axis.plot(xx, yy, styles[i] if styles else style, color=f"C{i}",
                  label=curve.label(display))
    names = ", ".join(curves[i].name for i in members)
    axis.set_ylabel(names + (f" [{unit}]" if unit else ""))
    if len(members) == 1:
        color = f"C{members[0]}"
        axis.yaxis.label.set_color(color)
        axis.tick_params(axis="y", colors=color)
        axis.spines[axis.yaxis.get_ticks_position()].set_edgecolor(color)


def legend_below(ax: Axes, handles: Sequence[Artist]) -> None:
    """The legend of ``handles`` centred under the x-axis tick labels and label of ``ax``
    (as far as they are shown), in up to three columns, so it never covers a curve
    (constrained layout makes room for it)."""
    below = rcParams["xtick.major.size"] + LEGEND_GAP
    if ax.xaxis.get_tick_params().get("labelbottom", True):
        below += rcParams["xtick.major.pad"] + 1.3 * FontProperties(
            size=rcParams["xtick.labelsize"]).get_size_in_points()
    if ax.get_xlabel():
        below += rcParams["axes.labelpad"] + 1.3 * FontProperties(
            size=rcParams["axes.labelsize"]).get_size_in_points()
    figure, _ = axes_for(ax)
    anchor = offset_copy(ax.transAxes, figure, y=-below, units="points")
    ax.legend(handles=list(handles), loc="upper center", bbox_to_anchor=(0.5, 0.0),
              bbox_transform=anchor, ncols=min(3, len(handles)), fontsize="small",
              borderaxespad=0.0)


def _shown_period(curve: Series, display: Display) -> float | None:
    if curve.period is None or curve.kind is None:
        return curve.period
    return float(display.convert(curve.period, curve.kind))


# ------------------------------------------------------------------ parameter dependencies


def plot_parameters(results: AnyResults, names: str | Sequence[str], *,
                    against: str = "position", display: Display = DEFAULT_DISPLAY,
                    ax: Axes | None = None, layout: str = "auto") -> Figure:
    """Dependencies of up to six quantities of any units on ``against``
    (``'position'``, ``'time'``, ``'arg1'``, or any other name), in the display units.

    Curves of one unit share a y-axis.  ``layout``: ``'axes'`` — one plot with a y-axis
    per unit, side by side (:func:`draw_curves`); ``'panels'`` — stacked panels sharing
    the x-axis, one per unit (:func:`draw_panels`); ``'auto'`` (default) — y-axes for up
    to :data:`MAX_AXES` units, panels for more.  With ``ax`` the curves go on that axes
    (``'auto'`` then means y-axes; ``'panels'`` needs a figure of its own).  More than
    six curves raise a ViewError naming them with their units.  Positions where the
    chain breaks are gaps.
    """
    if layout not in LAYOUTS:
        raise ViewError(f"unknown layout {layout!r}", f"use one of {', '.join(LAYOUTS)}")
    source = _Source(results)
    names = [names] if isinstance(names, str) else list(names)
    if len(names) > MAX_CURVES:
        asked = ", ".join(_asked(source, n, display) for n in names)
        raise ViewError(f"{len(names)} curves asked for one plot ({asked}); at most "
                        f"{MAX_CURVES} fit", "split them over several plots")
    curves = [source.get(n) for n in names]
    x = source.get(against)
    panels = layout == "panels" or (
        layout == "auto" and ax is None and len(unit_groups(curves, display)) > MAX_AXES)
    if panels:
        if ax is not None:
            raise ViewError("stacked panels cannot be drawn on given axes",
                            "leave out ax=, or use layout='axes'")
        figure = new_figure(8.0, 1.2 + 1.9 * len(unit_groups(curves, display)))
        draw_panels(figure, x, curves, display)
        return figure
    figure, ax = axes_for(ax)
    draw_curves(ax, x, curves, display)
    return figure


def _asked(source: _Source, name: str, display: Display) -> str:
    """``'dr3 [m/s]'`` for a known name, the name as given otherwise."""
    try:
        return source.get(name).label(display)
    except ViewError:
        return name


# ------------------------------------------------------------------------- combinations


def combine(results: AnyResults, a: str, b: str | float, op: str, *,
            display: Display = DEFAULT_DISPLAY) -> tuple[Array, str]:
    """The combination ``a op b`` of two quantities (``b`` may be a number), computed on
    their values in the display units.

    ``op``: ``'sum'``, ``'difference'``, ``'product'``, ``'ratio'`` or ``'power'``.
    Returns the values, shape (P,), and a label with the unit of the result
    (``'r3 + r4 [m]'``; pint works it out: a sum needs two quantities of one kind, a
    ratio of equal kinds is a plain number).  Division by zero gives ±inf.
    """
    if op not in COMBINATIONS:
        raise ViewError(f"unknown combination {op!r}", f"use one of {', '.join(COMBINATIONS)}")
    source = _Source(results)
    qa = _quantity(source.get(a), display)
    qb = (registry().Quantity(float(b)) if isinstance(b, int | float)
          else _quantity(source.get(b), display))
    b_name = f"{b:g}" if isinstance(b, int | float) else str(b)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        try:
            result = _apply(qa, qb, op, a, b_name)
        except pint.errors.DimensionalityError as exc:
            raise ViewError(f"cannot take the {op} of {a} [{qa.units:~C}] and {b_name} "
                            f"[{qb.units:~C}]: their units do not match",
                            "combine quantities of the same kind (a length with a length)"
                            ) from exc
    unit = _unit_text(result.units)
    text = f"{a} {_SYMBOL[op]} {b_name}"
    return np.asarray(result.magnitude, dtype=float), (f"{text} [{unit}]" if unit else text)


def _quantity(s: Series, display: Display) -> pint.Quantity:
    unit = s.unit_text(display)
    ureg = registry()
    return ureg.Quantity(s.shown(display), ureg.parse_units(unit) if unit else "")


def _apply(qa: pint.Quantity, qb: pint.Quantity, op: str, a: str, b: str) -> pint.Quantity:
    if op == "sum":
        return qa + qb
    if op == "difference":
        return qa - qb
    if op == "product":
        return qa * qb
    if op == "ratio":
        out = qa / qb
        return out.to("dimensionless") if out.dimensionless else out
    exponent = np.asarray(qb.to("dimensionless").magnitude)
    if exponent.ndim == 0:
        return qa ** float(exponent)
    if not qa.dimensionless:
        raise ViewError(f"cannot raise {a} [{qa.units:~C}] to the varying power {b}: the "
                        "unit of the result would change from position to position",
                        "raise a plain number (e.g. a ratio) to it, or use a constant "
                        "exponent")
    return registry().Quantity(qa.to("dimensionless").magnitude ** exponent)


def _unit_text(unit: pint.Unit) -> str:
    text = f"{unit:~C}".replace("**", "^")
    return "" if text in ("", "dimensionless") else text


def plot_combination(results: AnyResults, a: str, b: str | float, op: str, *,
                     against: str = "position", display: Display = DEFAULT_DISPLAY,
                     ax: Axes | None = None) -> Figure:
    """Plot :func:`combine` of ``a`` and ``b`` against ``against``."""
    values, label = combine(results, a, b, op, display=display)
    source = _Source(results)
    x = source.get(against)
    figure, ax = axes_for(ax)
    finite = np.where(np.isfinite(values), values, np.nan)  # a ratio's ±inf is a gap
    ax.plot(x.shown(display), finite, color="C0", label=label)
    ax.set_xlabel(x.label(display))
    ax.set_ylabel(label)
    ax.set_title(f"{op} of {a} and {b}")
    ax.grid(True, alpha=0.3)
    return figure


# ----------------------------------------------------------------- angle between vectors


def wrap_angle(angle: Array) -> Array:
    """``angle`` (rad, any shape) folded into (−π, π]."""
    angle = np.asarray(angle, dtype=float)
    return np.pi - np.mod(np.pi - angle, 2 * np.pi)


def continuous_angle(angle: Array, *, centred: bool = False) -> Array:
    """``angle`` (rad, shape (P,)) made continuous over the positions: within each unbroken
    stretch (a run of finite values; a NaN, where the chain breaks, ends it) every step is
    taken as the smallest turn, ``np.unwrap``, so no ±180° wrap shows as a jump.

    The branch of each stretch: as given at its first position (``centred=False``: a
    solver's angle keeps its values); or (``centred=True``: an angle difference, a
    reaction's direction) the whole stretch shifted by whole turns so that the middle of
    its range, ``(min + max) / 2``, lies in (−π, π] — a transmission angle reads
    40°…140° (or −140°…−40°), a difference turning a full revolution 0°…360°.
    NaN stay NaN; shape (P,), rad.
    """
    out = np.array(angle, dtype=float)
    finite = np.isfinite(out)
    edges = np.flatnonzero(np.diff(np.concatenate(([0], finite.astype(np.int8), [0]))))
    for start, stop in edges.reshape(-1, 2):  # one pass per unbroken stretch (few)
        piece = np.unwrap(out[start:stop])
        if centred:
            middle = 0.5 * (piece.min() + piece.max())
            turns = np.round((wrap_angle(middle) - middle) / (2 * np.pi))
            piece = piece + 2 * np.pi * turns
        out[start:stop] = piece
    return out


def _vector_angle(v: int | str) -> str:
    text = str(v).strip()
    number = text[1:] if text[:1] == "a" else text
    if not number.isdigit():
        raise ViewError(f"{v!r} does not name a vector", "give a vector number (3) or its "
                        "angle ('a3')")
    return f"a{number}"


def angle_between(results: AnyResults, v1: int | str, v2: int | str) -> tuple[Array, Array]:
    """The angle from vector ``v1`` to vector ``v2``: ``α_v2 − α_v1`` continuous over the
    positions, each unbroken stretch with the middle of its range in (−π, π]
    (:func:`continuous_angle`; rad, shape (P,)), and its rate (rad/s; an analog without
    model time).

    Vectors are given by number (3) or angle name ('a3').  The transmission angle of a
    four-bar is the angle between its coupler and its rocker; a pressure angle is the
    angle between a reaction and the velocity of its point.
    """
    source = _Source(results)
    first, second = _vector_angle(v1), _vector_angle(v2)
    vectors = ", ".join(map(str, sorted(source.kin.model.vectors)))
    for name in (first, second):
        if name not in source.kin.values:
            raise ViewError(f"no vector {name[1:]} in this model",
                            f"use one of vectors {vectors}")
    kin = source.kin
    return (continuous_angle(kin.value(second) - kin.value(first), centred=True),
            kin.rate(second) - kin.rate(first))


def plot_angle_between(results: AnyResults, v1: int | str, v2: int | str, *,
                       against: str = "position", display: Display = DEFAULT_DISPLAY,
                       ax: Axes | None = None) -> Figure:
    """Plot :func:`angle_between` (solid, left axis) and its rate (dashed, right axis)."""
    source = _Source(results)
    angle, rate = angle_between(results, v1, v2)
    first, second = _vector_angle(v1), _vector_angle(v2)
    d1 = source.get(f"d{second}").kind
    name = f"{second} − {first}"
    curves = [Series(name, angle, "angle"), Series(f"d({name})", rate, d1)]
    figure, ax = axes_for(ax)
    draw_curves(ax, source.get(against), curves, display)
    ax.set_title(f"angle from vector {first[1:]} to vector {second[1:]}")
    return figure


# --------------------------------------------------------------------------- increments


def increment(results: AnyResults, name: str, position: int) -> tuple[Array, Array, Array]:
    """The increment of parameter ``name`` ('r3', 'a2') from its value at ``position``,
    and its first and second derivatives: ``(value − value[position], rate, accel)``,
    each shape (P,), SI (m or rad; per s and s², or analogs without model time)."""
    source = _Source(results)
    match = _KINEMATIC.match(str(name))
    if match is None or match.group(1) or str(name) not in source.kin.values:
        raise ViewError(f"{name!r} is not a vector parameter of this model",
                        f"use one of {', '.join(source.kin.varying())}")
    kin = source.kin
    n = kin.positions.size
    if not isinstance(position, int | np.integer) or not 0 <= position < n:
        raise ViewError(f"position {position!r} is not a calculation position",
                        f"use a position from 0 to {n - 1}")
    value = kin.value(name)
    if not np.isfinite(value[position]):
        raise ViewError(f"{name} has no value at position {position} (the chain breaks "
                        "there)", "choose a position where the mechanism assembles")
    return value - value[position], kin.rate(name), kin.accel(name)


def plot_increment(results: AnyResults, name: str, position: int = 0, *,
                   against: str = "position", display: Display = DEFAULT_DISPLAY) -> Figure:
    """KDAM's standard plot of the output link: the increment of ``name`` from its value
    at ``position`` and its first and second derivatives, on three stacked axes."""
    source = _Source(results)
    delta, rate, accel = increment(results, name, position)
    kinds = [source.get(f"{d}{name}").kind for d in ("", "d", "dd")]
    curves = [Series(f"Δ{name}", delta, kinds[0]), Series(f"d{name}", rate, kinds[1]),
              Series(f"dd{name}", accel, kinds[2])]
    x = source.get(against)
    figure = new_figure(8.0, 8.0)
    axes = figure.subplots(3, 1, sharex=True)
    xs = x.shown(display)
    for i, (axis, curve) in enumerate(zip(axes, curves, strict=True)):
        axis.plot(xs, curve.shown(display), color=f"C{i}")
        axis.set_ylabel(curve.label(display))
        axis.grid(True, alpha=0.3)
    axes[0].plot([xs[position]], [0.0], "o", color="k",
                 label=f"reference: position {position}")
    axes[0].legend(loc="best", fontsize="small")
    axes[0].set_title(f"increment of {name} from position {position}")
    axes[-1].set_xlabel(x.label(display))
    return figure
