"""Plots of the dynamic analysis (KDAM's dynamics panels): reduced inertia and loads, the
balancing load, joint reactions and their hodographs, the summary characteristics table
and the machine motion with and without the flywheel.

Every function takes a :class:`~mechloop.dynamics.analysis.DynamicResults` (from
:func:`mechloop.solve_dynamics`) and returns a new figure; numbers are shown in the units
and precision of a :class:`~mechloop.views.display.Display`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from mechloop.dynamics.analysis import DynamicResults
from mechloop.views.curves import Series, draw_curves, series
from mechloop.views.display import DEFAULT_DISPLAY, Display
from mechloop.views.figure import ViewError, new_figure
from mechloop.views.russian import keep_names, model_names


def _check(dyn: object) -> DynamicResults:
    if not isinstance(dyn, DynamicResults):
        raise ViewError(f"a dynamics plot needs DynamicResults, not {type(dyn).__name__}",
                        "solve the model with mechloop.solve_dynamics(model)")
    return dyn


def _linear_input(dyn: DynamicResults) -> bool:
    """Whether the (first) drive is a length argument (a sliding input)."""
    k = dyn.mechanism.drives[0].argument
    return dyn.kinematics.argument_kinds[k] == "length"


# ----------------------------------------------------------------------- reduced, balancing


def plot_reduced(dyn: DynamicResults, *, against: str = "position",
                 display: Display = DEFAULT_DISPLAY) -> Figure:
    """The reduced moment of inertia ``J_red`` and its derivative ``dJ_red/dq`` (twin
    axes, top) and the reduced moment of the loads ``M_red`` (bottom) over the cycle;
    ``m_red``, ``dm_red`` and ``F_red`` for a sliding input.  One-input machines only."""
    dyn = _check(dyn)
    if dyn.reduced is None:
        raise ViewError(f"reduced characteristics need a one-input machine; this model has "
                        f"{len(dyn.mechanism.drives)} drives", "plot the balancing loads "
                        "(plot_balancing) instead")
    stems = ("m_red", "dm_red", "F_red") if _linear_input(dyn) else ("J_red", "dJ_red", "M_red")
    x = series(dyn, against)
    figure = keep_names(new_figure(8.0, 7.0), model_names(dyn.kinematics.model))
    top, bottom = figure.subplots(2, 1, sharex=True)
    draw_curves(top, x, [series(dyn, stems[0]), series(dyn, stems[1])], display,
                xlabel=False)
    top.set_title("reduced inertia and its derivative")
    draw_curves(bottom, x, [series(dyn, stems[2])], display)
    bottom.set_title("reduced load")
    return figure


def plot_balancing(dyn: DynamicResults, *, against: str = "position",
                   display: Display = DEFAULT_DISPLAY) -> Figure:
    """The balancing load of every drive by kinetostatics (solid) and by virtual power
    (dashed) on one plot — the two agree to rounding."""
    dyn = _check(dyn)
    curves: list[Series] = []
    styles: list[str] = []
    for k in sorted(dyn.forces.balancing):
        stem, _ = dyn.balancing_name(k)
        curves += [series(dyn, stem), series(dyn, f"{stem}_vp")]
        styles += ["-", "--"]
    if not curves:
        raise ViewError("this model has no drive, so there is no balancing load",
                        "drive a body by a model argument")
    figure = keep_names(new_figure(8.0, 5.0), model_names(dyn.kinematics.model))
    ax = figure.add_subplot()
    draw_curves(ax, series(dyn, against), curves, display, styles=styles)
    # two lines: one would not fit the figure in Russian
    ax.set_title("balancing load\nkinetostatics (solid), virtual power (dashed)")
    return figure


# -------------------------------------------------------------------------------- reactions


def _joints(dyn: DynamicResults, joints: Sequence[str] | str | None) -> list[str]:
    return chosen_joints(list(dyn.forces.reactions), joints)


def chosen_joints(known: list[str], joints: Sequence[str] | str | None) -> list[str]:
    """``joints`` (a name, names, or None: every one of ``known``) checked against the
    model's ``known`` joints; a :class:`~mechloop.views.figure.ViewError` names a joint
    it does not have."""
    if joints is None:
        return known
    chosen = [joints] if isinstance(joints, str) else list(joints)
    missing = [j for j in chosen if j not in known]
    if missing:
        raise ViewError(f"no joint {', '.join(map(repr, missing))} in this model",
                        f"use one of {', '.join(known)}")
    return chosen


def plot_reactions(dyn: DynamicResults, joints: Sequence[str] | str | None = None, *,
                   against: str = "position", display: Display = DEFAULT_DISPLAY) -> Figure:
    """The magnitude of the reaction in every joint (or in ``joints``) over the cycle."""
    dyn = _check(dyn)
    names = _joints(dyn, joints)
    x = series(dyn, against)
    figure = keep_names(new_figure(8.0, 5.0), model_names(dyn.kinematics.model))
    ax = figure.add_subplot()
    xs = x.shown(display)
    for i, name in enumerate(names):
        magnitude = np.abs(dyn.forces.reactions[name].force)
        ax.plot(xs, display.convert(magnitude, "force"), color=f"C{i % 10}", label=f"|R{name}|")
    ax.set_xlabel(x.label(display))
    ax.set_ylabel(f"reaction [{display.label('force')}]")
    ax.set_title("reactions in the joints")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small", ncols=2 if len(names) > 6 else 1)
    return figure


def plot_hodograph(dyn: DynamicResults, joint: str, *, polar: bool = False,
                   display: Display = DEFAULT_DISPLAY) -> Figure:
    """The hodograph of the reaction in ``joint``: the tip of the reaction vector over the
    cycle, with the vector drawn from the origin at the first position (where it is known).

    x-y form: the line labelled ``R<joint>`` has the points ``(R_x, R_y)`` in the display
    force unit, the origin is marked.  Polar form (``polar=True``): the points are
    ``(θ, |R|)`` with ``θ`` the reaction's direction (rad, unwrapped so the curve does
    not jump) — ``|R|·e^{iθ}`` is the reaction.
    """
    dyn = _check(dyn)
    (name,) = _joints(dyn, [joint])
    force = display.convert(dyn.forces.reactions[name].force.real, "force") \
        + 1j * display.convert(dyn.forces.reactions[name].force.imag, "force")
    unit = display.label("force")
    figure = keep_names(new_figure(6.5, 6.5), model_names(dyn.kinematics.model))
    label = f"R{name}"
    if polar:
        ax = figure.add_subplot(projection="polar")
        theta = _unwrap(np.angle(force))
        ax.plot(theta, np.abs(force), color="C0", label=label)
        first = _first_finite(force)
        if first is not None:
            ax.plot(theta[first:first + 1], np.abs(force[first:first + 1]), "o", color="C3",
                    label=f"position {first}")
        ax.set_title(f"hodograph of the reaction in {name} [{unit}] (polar)")
    else:
        ax = figure.add_subplot()
        ax.plot(force.real, force.imag, color="C0", label=label)
        first = _first_finite(force)
        if first is not None:
            ax.annotate("", xy=(force.real[first], force.imag[first]), xytext=(0.0, 0.0),
                        arrowprops={"arrowstyle": "->", "color": "C3"})
            ax.plot(force.real[first:first + 1], force.imag[first:first + 1], "o",
                    color="C3", label=f"position {first}")
        ax.plot([0.0], [0.0], "k+", markersize=12, label="origin")
        ax.axhline(0.0, color="k", linewidth=0.5)
        ax.axvline(0.0, color="k", linewidth=0.5)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel(f"{label}_x [{unit}]")
        ax.set_ylabel(f"{label}_y [{unit}]")
        ax.set_title(f"hodograph of the reaction in {name}")
        _number_positions(ax, force)
        ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    return figure


def _first_finite(values) -> int | None:
    """The first position where ``values`` is known (the chain may break at 0)."""
    finite = np.flatnonzero(np.isfinite(values))
    return int(finite[0]) if finite.size else None


def _unwrap(theta):
    """``np.unwrap`` over the finite stretch (a NaN would poison the rest)."""
    out = np.array(theta, dtype=float)
    ok = np.isfinite(out)
    out[ok] = np.unwrap(out[ok])
    return out


def _number_positions(ax: Axes, points, count: int = 8) -> None:
    """Write position numbers beside about ``count`` points of the curve."""
    step = max(1, points.size // count)
    closed = points.size > 1 and bool(np.isclose(points[0], points[-1]))
    for k in range(0, points.size - 1 if closed else points.size, step):
        if np.isfinite(points[k]):
            ax.annotate(str(k), (points[k].real, points[k].imag), fontsize="x-small",
                        textcoords="offset points", xytext=(3, 3), color="0.35")


# ------------------------------------------------------------------------------ summary


def summary_rows(dyn: DynamicResults, display: Display = DEFAULT_DISPLAY
                 ) -> tuple[list[str], list[list[str]], list[list[str]]]:
    """The summary characteristics as text: the header and one row per load, and the
    totals (name, value) — in the display units and digits."""
    dyn = _check(dyn)
    energy, power = display.label("energy"), display.label("power")
    specific = display.label("specific_power")
    header = ["load", f"A+ [{energy}]", f"A− [{energy}]", f"N max [{power}]",
              f"N min [{power}]", f"N mean [{power}]", f"N per kg [{specific}]"]

    def shown(value: float, kind: str) -> str:
        return display.format(float(display.convert(value, kind)))

    rows = [[r.name, shown(r.positive_work, "energy"), shown(r.negative_work, "energy"),
             shown(r.max_power, "power"), shown(r.min_power, "power"),
             shown(r.mean_power, "power"), shown(r.specific_power, "specific_power")]
            for r in dyn.summary.rows]
    s = dyn.summary
    from mechloop.dynamics.cycle_validity import cycle_breaks

    broken = cycle_breaks(dyn)
    refused = f"not given: the chain breaks ({broken.where()})" if broken else None
    totals = [["driving work", f"{shown(s.driving_work, 'energy')} {energy}"],
              ["work lost to friction", f"{shown(s.friction_work, 'energy')} {energy}"],
              ["loss coefficient ψ", refused or display.format(s.loss_coefficient)],
              ["efficiency η", refused or display.format(s.efficiency)],
              ["kinetic energy change", f"{shown(s.kinetic_energy_change, 'energy')} {energy}"]]
    if dyn.cycle is not None:
        totals += _cycle_rows(dyn, display)
    return header, rows, totals


def _cycle_rows(dyn: DynamicResults, display: Display) -> list[list[str]]:
    c = dyn.cycle
    assert c is not None
    linear = _linear_input(dyn)
    load_kind, inertia_kind = ("force", "mass") if linear else ("moment", "inertia")
    rows = [["constant load on the input",
             f"{display.format(float(display.convert(c.constant_load, load_kind)))} "
             f"{display.label(load_kind)}"],
            ["δ without flywheel", display.format(float(c.motion.delta))]]
    if c.flywheel is not None:
        unit = display.label(inertia_kind)
        rows += [["δ wanted", display.format(float(c.delta))],
                 ["flywheel (exact)",
                  f"{display.format(float(display.convert(c.flywheel, inertia_kind)))} {unit}"],
                 ["flywheel (approximate)",
                  f"{display.format(float(display.convert(c.flywheel_approx, inertia_kind)))}"
                  f" {unit}"]]
    return rows


def plot_summary(dyn: DynamicResults, *, display: Display = DEFAULT_DISPLAY) -> Figure:
    """KDAM's summary characteristics drawn as tables: work, extreme and mean power of
    every load and of friction; then driving work, friction work, ψ, η (and the machine
    motion figures when the model has ``machine:``)."""
    header, rows, totals = summary_rows(dyn, display)
    lines = len(rows) + 1 + len(totals) + 1  # the rows of both tables and a gap
    figure = keep_names(new_figure(10.0, 0.9 + 0.3 * lines), model_names(dyn.kinematics.model))
    ax = figure.add_subplot()
    ax.axis("off")
    row = 1.0 / lines
    loads = ax.table(cellText=rows, colLabels=header, cellLoc="right",
                     bbox=[0.0, 1.0 - row * (len(rows) + 1), 1.0, row * (len(rows) + 1)])
    figures = ax.table(cellText=totals, cellLoc="left",
                       bbox=[0.15, 0.0, 0.7, row * len(totals)])
    for table in (loads, figures):
        table.auto_set_font_size(False)
        table.set_fontsize(9)
    ax.set_title(f"summary characteristics — {dyn.kinematics.model.name or 'model'}")
    return figure


# ----------------------------------------------------------------------- machine motion


def plot_machine_motion(dyn: DynamicResults, *, display: Display = DEFAULT_DISPLAY) -> Figure:
    """The speed of the input over the cycle without and with the flywheel (lines with
    gid ``'omega'`` and ``'omega_fw'``), the mean speed, and δ and the flywheel's moment
    of inertia in the legend.  ViewError if the model has no ``machine:`` section."""
    dyn = _check(dyn)
    cycle = dyn.cycle
    if cycle is None:
        raise ViewError("this model has no machine motion", "add machine: {delta: 0.0125} "
                        "to a one-input model with a time, then solve it again")
    linear = _linear_input(dyn)
    q_kind, w_kind = ("length", "velocity") if linear else ("angle", "angular_velocity")
    inertia_kind = "mass" if linear else "inertia"
    k = dyn.mechanism.drives[0].argument
    q = display.convert(cycle.q, q_kind)
    unit = display.label(w_kind)
    figure = keep_names(new_figure(8.0, 5.0), model_names(dyn.kinematics.model))
    ax = figure.add_subplot()
    ax.plot(q, display.convert(cycle.motion.omega, w_kind), color="C0", gid="omega",
            label=f"without flywheel, δ = {display.format(float(cycle.motion.delta))}")
    if cycle.with_flywheel is not None and cycle.flywheel is not None:
        flywheel = display.format(float(display.convert(cycle.flywheel, inertia_kind)))
        ax.plot(q, display.convert(cycle.with_flywheel.omega, w_kind), color="C1",
                gid="omega_fw",
                label=f"with flywheel J = {flywheel} {display.label(inertia_kind)}, "
                      f"δ = {display.format(float(cycle.with_flywheel.delta))}")
    ax.axhline(float(display.convert(cycle.omega_mean, w_kind)), color="k", linestyle=":",
               label=f"mean {display.format(float(display.convert(cycle.omega_mean, w_kind)))}"
                     f" {unit}")
    ax.set_xlabel(f"arg{k} [{display.label(q_kind)}]")
    ax.set_ylabel(f"ω [{unit}]" if not linear else f"v [{unit}]")
    ax.set_title("machine motion over the cycle")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize="small")
    return figure
