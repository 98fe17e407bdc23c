"""Plots of the dynamics of a model with spatial contours (issue 17) for ``mechloop plot``:
the reduced characteristics, the balancing loads and the summary (the works of the loads
over the cycle and the kinetic energy), drawn from a
:class:`~mechloop.spatial.dynamics.SpatialDynamics` (virtual power) with the look, units
and texts of the planar views (:mod:`mechloop.views.dynamics`) — the curves are drawn by
:func:`mechloop.views.curves.draw_curves` as there, the works by the report's
:func:`mechloop.report.spatial_dynamics.works`.

With ``joints:`` the reactions and their hodographs are drawn by
:mod:`mechloop.views.spatial_reactions`; the machine motion (``motion``) is refused with a
:class:`~mechloop.views.figure.ViewError`.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from mechloop.spatial.dynamics import SpatialDynamics
from mechloop.views.curves import Series, draw_curves
from mechloop.views.display import DEFAULT_DISPLAY, Display
from mechloop.views.figure import ViewError, new_figure
from mechloop.views.russian import keep_names, model_names

#: Kinds of ``mechloop plot`` drawn here for a spatial model with bodies.
SPATIAL_DYNAMIC_KINDS = ("reduced", "balancing", "summary", "reactions", "hodograph")


def length_argument(dyn: SpatialDynamics) -> bool:
    """Whether the (first) argument is a length (m_red, F_red, a balancing force)."""
    return dyn.kinematics.argument_kinds[next(iter(dyn.balancing))] == "length"


def x_series(dyn: SpatialDynamics, against: str) -> Series:
    """The x axis: ``position``, ``time`` or ``arg<k>`` over the positions (SI)."""
    kin = dyn.kinematics
    if against == "position":
        return Series("position", kin.positions.astype(float), None)
    if against == "time" and kin.time is not None:
        return Series("time", np.asarray(kin.time, dtype=float), "time")
    if against.startswith("arg") and against[3:].isdigit() \
            and int(against[3:]) in kin.arguments:
        k = int(against[3:])
        return Series(against, np.asarray(kin.arguments[k], dtype=float),
                      kin.argument_kinds[k])
    known = ["position", *(["time"] if kin.time is not None else []),
             *(f"arg{k}" for k in sorted(kin.arguments))]
    raise ViewError(f"cannot plot against {against!r} for this model",
                    f"use one of: {', '.join(known)}")


def reduced_series(dyn: SpatialDynamics) -> list[Series]:
    """``J_red``, ``dJ_red``, ``M_red`` (``m_red``, ``dm_red``, ``F_red`` for a length
    argument), SI, shape (P,) each; ViewError for a model with several arguments."""
    if dyn.reduced is None:
        raise ViewError(f"reduced characteristics need a one-input machine; this model has "
                        f"{len(dyn.balancing)} arguments", "plot the balancing loads "
                        "(plot ... balancing) instead")
    inertia, slope, load = dyn.reduced
    if length_argument(dyn):
        return [Series("m_red", inertia, "mass"), Series("dm_red", slope, "mass/length"),
                Series("F_red", load, "force")]
    return [Series("J_red", inertia, "inertia"), Series("dJ_red", slope, "inertia/angle"),
            Series("M_red", load, "moment")]


def balancing_series(dyn: SpatialDynamics) -> list[Series]:
    """The balancing load of every argument by virtual power (N·m or N), shape (P,)."""
    out = []
    for k, values in dyn.balancing.items():
        stem, unit = dyn.balancing_name(k)
        out.append(Series(stem, values, "moment" if unit == "N*m" else "force"))
    return out


def plot_reduced3(dyn: SpatialDynamics, *, against: str = "position",
                  display: Display = DEFAULT_DISPLAY) -> Figure:
    """As :func:`mechloop.views.dynamics.plot_reduced`: the reduced inertia and its
    derivative (top) and the reduced load (bottom) over the cycle."""
    curves = reduced_series(dyn)
    x = x_series(dyn, against)
    figure = keep_names(new_figure(8.0, 7.0), model_names(dyn.kinematics.model))
    top, bottom = figure.subplots(2, 1, sharex=True)
    draw_curves(top, x, curves[:2], display, xlabel=False)
    top.set_title("reduced inertia and its derivative")
    draw_curves(bottom, x, curves[2:], display)
    bottom.set_title("reduced load")
    return figure


def plot_balancing3(dyn: SpatialDynamics, *, against: str = "position",
                    display: Display = DEFAULT_DISPLAY) -> Figure:
    """As :func:`mechloop.views.dynamics.plot_balancing`: the balancing loads."""
    figure = keep_names(new_figure(8.0, 4.5), model_names(dyn.kinematics.model))
    draw_curves(figure.add_subplot(), x_series(dyn, against), balancing_series(dyn),
                display)
    figure.axes[0].set_title("balancing load")
    return figure


def summary_rows3(dyn: SpatialDynamics, display: Display = DEFAULT_DISPLAY
                  ) -> tuple[list[str], list[list[str]]]:
    """The works over the cycle of every load and balancing load as text: the header and
    one row per load ``(name, A+, A−, A)`` in the display unit of energy.  Without a
    model time the powers are per unit rate of argument 1 and so are the 'works'."""
    from mechloop.report.spatial_dynamics import works

    energy = display.label("energy")
    header = ["load", f"A+ [{energy}]", f"A− [{energy}]", f"A [{energy}]"]
    found = works(dyn)
    # a total that is zero to the precision of the works (1e-12 of the largest) prints 0
    scale = max((abs(v) for values in found.values() for v in values), default=0.0)
    rows = [[name, *(display.format(float(display.convert(
        0.0 if abs(v) <= 1e-12 * scale else v, "energy"))) for v in values)]
        for name, values in found.items()]
    return header, rows


def plot_summary3(dyn: SpatialDynamics, *, against: str = "position",
                  display: Display = DEFAULT_DISPLAY) -> Figure:
    """The works of the loads over the cycle (a table, top) and the kinetic energy ``T``
    over the cycle (bottom); ViewError when the chain breaks (the works are not valid)."""
    kin = dyn.kinematics
    if kin.broken.any():
        from mechloop.solve.results import compress_positions

        raise ViewError("the summary is not given: the chain breaks at positions "
                        f"{compress_positions(np.flatnonzero(kin.broken))}",
                        "choose the arguments' range so that the chain closes at every "
                        "position")
    header, rows = summary_rows3(dyn, display)
    figure = keep_names(new_figure(8.0, 4.5 + 0.3 * (len(rows) + 1)),
                        model_names(kin.model))
    share = (len(rows) + 1) / (len(rows) + 1 + 12)
    table_ax, curve_ax = figure.subplots(2, 1, height_ratios=[share, 1 - share])
    table_ax.axis("off")
    table = table_ax.table(cellText=rows, colLabels=header, cellLoc="right",
                           bbox=[0.0, 0.0, 1.0, 1.0])
    table.auto_set_font_size(False)
    table.set_fontsize(9)
    table_ax.set_title(f"summary characteristics — {kin.model.name or 'model'}")
    draw_curves(curve_ax, x_series(dyn, against), [Series("T", dyn.kinetic_energy,
                                                          "energy")], display)
    curve_ax.set_title("kinetic energy")
    return figure


def plot_spatial_dynamics(dyn: SpatialDynamics, kind: str, *, against: str = "position",
                          display: Display = DEFAULT_DISPLAY, names: list[str] | None = None,
                          joint: str | None = None, position: int | None = None,
                          elev: float | None = None, azim: float | None = None,
                          views: str = "all") -> Figure:
    """The view ``kind`` of :data:`SPATIAL_DYNAMIC_KINDS`: with the joint reactions
    (``joints:``) also ``reactions`` (of ``names``, default every joint) and ``hodograph``
    (of ``joint``, its force; ``position`` marked; ``elev``/``azim``/``views`` as the 3-D
    plan's) by :mod:`mechloop.views.spatial_reactions`; ViewError for the others."""
    if kind == "reduced":
        return plot_reduced3(dyn, against=against, display=display)
    if kind == "balancing":
        return plot_balancing3(dyn, against=against, display=display)
    if kind == "summary":
        return plot_summary3(dyn, against=against, display=display)
    if kind == "reactions":
        from mechloop.views.spatial_reactions import plot_spatial_reactions

        return plot_spatial_reactions(dyn, names or None, display=display)
    if kind == "hodograph":
        from mechloop.views import spatial_plan as sp
        from mechloop.views.spatial_reactions import plot_spatial_hodograph, reaction_joints

        if joint is None:
            raise ViewError("a hodograph needs a joint",
                            f"give --joint, one of {', '.join(reaction_joints(dyn))}")
        return plot_spatial_hodograph(dyn, joint, position=position, views=views,
                                      elev=sp.ELEV if elev is None else elev,
                                      azim=sp.AZIM if azim is None else azim,
                                      display=display)
    raise ViewError(f"'{kind}' is not drawn for a model with spatial contours yet (it "
                    "needs the machine motion, which the spatial dynamics does not give)",
                    f"plot one of {', '.join(SPATIAL_DYNAMIC_KINDS)}, or write the "
                    "dynamics table with mechloop solve")
