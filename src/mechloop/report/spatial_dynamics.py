"""The dynamic parts of the report of a model with spatial contours (issue 17), from
:func:`mechloop.spatial.dynamics.solve_spatial_dynamics` (virtual power): the bodies with
their inertia tensors, the forces and moments with their 3-D directions, the balancing
load and the reduced characteristics plotted, the works of the loads over the cycle and
the kinetic energy (tabulated, with the balance ``Σ A = T(N) − T(0)``), the trajectories
of the centres of mass, and the conclusion's lines.

Works are the trapezoid integrals of the loads' powers over the model's time (without
time: over argument 1, the powers then being per unit rate of it); a positive work
``A+`` sums the parts where the power is positive, ``A−`` the others.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import trapezoid

from mechloop.model.schema import Model
from mechloop.report.conclusion import kinematic_lines
from mechloop.report.document import FigureItem, Paragraph, Section, Table
from mechloop.report.dynamic_parameters import _value_text, _when, other_table
from mechloop.report.numbers import Shown
from mechloop.report.spatial_reactions import agreement_lines, reaction_lines
from mechloop.report.values import angle_text, finite_span, peak, point_text
from mechloop.solve.results import compress_positions
from mechloop.spatial.dynamics import SpatialDynamics
from mechloop.views.display import Display
from mechloop.views.russian import translate

Array = NDArray[np.float64]

#: Centres of mass traced at most (as the planar report).
MAX_CENTRES = 6


def body_table3(dyn: SpatialDynamics, model: Model, shown: Shown, w: dict[str, str]
                ) -> Table:
    """Each lumped mass: body, name, m, the tensor's axial moments and its products of
    inertia in the body's axes, the centre of mass."""
    rows = []
    for mass in dyn.mechanism.masses:
        tensor = shown.value(np.asarray(mass.tensor, dtype=float), "kg*m^2")
        scale = float(np.max(np.abs(tensor))) or None
        axial = "; ".join(shown.number(tensor[i, i], scale) for i in range(3))
        products = "; ".join(shown.number(tensor[i, j], scale)
                             for i, j in ((0, 1), (1, 2), (0, 2)))
        rows.append((str(mass.body), model.bodies[mass.body].name or "",
                     shown.number(shown.value(float(mass.mass), "kg")), axial, products,
                     point_text(mass.center, model, shown, w)))
    unit = shown.unit_text("kg*m^2")
    header = (w["h_number"], w["h_name"], f"m, {shown.unit_text('kg')}",
              f"{w['h_axial']}, {unit}", f"{w['h_products']}, {unit}", w["h_centre"])
    return Table(w["t_bodies3"], header, rows)


def _direction_text(values, shown: Shown, w: dict[str, str]) -> str:
    """A direction ``[x, y, z]`` (any length) as its unit vector '(x; y; z)'."""
    v = np.asarray(values, dtype=float)
    v = v / np.linalg.norm(v)
    x, y, z = (shown.number(c, 1.0) for c in v)
    return w["d_vector"].format(x=x, y=y, z=z)


def _loads(dyn: SpatialDynamics, model: Model):
    """The forces and moments over the positions (SI, ``(3, P)``) by name."""
    from mechloop.solve.inputs import model_time
    from mechloop.spatial.loads import build_loads

    forces, moments = build_loads(model, dyn.kinematics, dyn.mechanism.masses,
                                  set(dyn.mechanism.bodies), model_time(model), [])
    return {f.name: f for f in forces}, {m.name: m for m in moments}


def force_table3(dyn: SpatialDynamics, model: Model, shown: Shown, w: dict[str, str]
                 ) -> Table:
    """Each force: name, body, magnitude (or its range), point, direction in space."""
    forces, _ = _loads(dyn, model)
    rows = []
    for i, force in enumerate(model.forces):
        name = force.name or f"F{i + 1}"
        found = forces.get(name)
        magnitude = None if found is None else np.linalg.norm(found.force, axis=0)
        text = _value_text(force.value, magnitude, "N", model.units.force, shown, w,
                           "force") + _when(force, w)
        if force.direction is not None:
            direction = _direction_text(force.direction, shown, w)
        elif force.along is not None:
            direction = w["d_along3"].format(v=force.along)
        else:
            direction = w["d_plane"].format(angle=angle_text(force.angle, model, shown))
        rows.append((name, str(force.body), text, point_text(force.at, model, shown, w),
                     direction))
    header = (w["h_name"], w["h_body"], w["h_magnitude"], w["h_point"], w["h_direction"])
    return Table(w["t_forces"], header, rows)


def moment_table3(dyn: SpatialDynamics, model: Model, shown: Shown, w: dict[str, str]
                  ) -> Table:
    """Each moment: name, body, value (or its range) and its axis in space."""
    _, moments = _loads(dyn, model)
    rows = []
    for i, moment in enumerate(model.moments):
        name = moment.name or f"M{i + 1}"
        found = moments.get(name)
        axis = moment.axis or (0, 0, 1)
        values = None
        if found is not None:  # the signed value about the axis
            unit = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
            values = np.einsum("i,ip->p", unit, found.moment)
        rows.append((name, str(moment.body),
                     _value_text(moment.value, values, "N*m", model.units.moment, shown, w,
                                 "moment") + _when(moment, w),
                     _direction_text(axis, shown, w)))
    return Table(w["t_moments"], (w["h_name"], w["h_body"], w["h_value"], w["h_axis"]),
                 rows)


def masses_section3(dyn: SpatialDynamics, model: Model, shown: Shown, w: dict[str, str]
                    ) -> Section:
    """The planar report's section 6 for a spatial model: bodies, forces, moments,
    gravity (the kinematic pairs are tabulated in the reactions' section)."""
    blocks: list = [body_table3(dyn, model, shown, w)]
    if model.forces:
        blocks.append(force_table3(dyn, model, shown, w))
    if model.moments:
        blocks.append(moment_table3(dyn, model, shown, w))
    other = other_table(model, shown, {**w, "o_gravity_v": w["o_gravity_v3"]})
    if other is not None:
        blocks.append(other)
    return Section(w["s_masses"], [b for b in blocks if not isinstance(b, Table) or b.rows])


# ------------------------------------------------------------------------------ figures


def _position(dyn: SpatialDynamics):
    from mechloop.views.spatial_dynamics import x_series

    return x_series(dyn, "position")


def plot_reduced3(dyn: SpatialDynamics, display: Display):
    """``J_red`` and ``dJ_red`` (top) and ``M_red`` (bottom) over the positions;
    ``m_red``, ``dm_red``, ``F_red`` for a length argument: the figure of
    :func:`mechloop.views.spatial_dynamics.plot_reduced3`."""
    from mechloop.views import spatial_dynamics

    assert dyn.reduced is not None
    return spatial_dynamics.plot_reduced3(dyn, display=display)


def plot_balancing3(dyn: SpatialDynamics, display: Display):
    """The balancing load of every argument by virtual power over the positions; with
    joints the one by the Newton–Euler equations (solid, ``M_bal``) beside it (dashed,
    ``M_bal_vp``), as the planar report's kinetostatics and virtual power."""
    from mechloop.views.curves import Series, draw_curves
    from mechloop.views.figure import new_figure
    from mechloop.views.russian import keep_names, model_names

    reactions = dyn.reactions
    figure = keep_names(new_figure(8.0, 4.5 if reactions is None else 5.0),
                        model_names(dyn.kinematics.model))
    curves, styles = [], []
    for k, values in dyn.balancing.items():
        stem, unit = dyn.balancing_name(k)
        kind = "moment" if unit == "N*m" else "force"
        if reactions is not None:
            curves.append(Series(stem, reactions.balancing[k], kind))
            styles.append("-")
        curves.append(Series(stem if reactions is None else f"{stem}_vp", values, kind))
        styles.append("--" if reactions is not None else "-")
    ax = figure.add_subplot()
    draw_curves(ax, _position(dyn), curves, display, styles=styles)
    if reactions is not None:  # two lines: one would not fit the figure in Russian
        ax.set_title("balancing load\nNewton–Euler equations (solid), virtual power "
                     "(dashed)")
    return figure


def plot_energy(dyn: SpatialDynamics, display: Display):
    """The kinetic energy ``T`` over the positions."""
    from mechloop.views.curves import Series, draw_curves
    from mechloop.views.figure import new_figure
    from mechloop.views.russian import keep_names, model_names

    figure = keep_names(new_figure(8.0, 4.5), model_names(dyn.kinematics.model))
    draw_curves(figure.add_subplot(), _position(dyn),
                [Series("T", dyn.kinetic_energy, "energy")], display)
    return figure


# ------------------------------------------------------------------------------ works


def integration_variable(dyn: SpatialDynamics) -> Array:
    """What the powers are integrated over: the model's time (s), or without time
    argument 1 (rad or m; the powers are then per unit rate of it)."""
    kin = dyn.kinematics
    if kin.time is not None:
        return np.asarray(kin.time, dtype=float)
    return np.asarray(kin.arguments[min(kin.arguments)], dtype=float)


def works(dyn: SpatialDynamics) -> dict[str, tuple[float, float, float]]:
    """Per load (and balancing load) by name: ``(A+, A−, A)`` over the positions (J)."""
    x = integration_variable(dyn)
    out = {}
    for name, power in dyn.powers.items():
        p = np.broadcast_to(np.asarray(power, dtype=float), x.shape)
        plus = float(trapezoid(np.maximum(p, 0.0), x))
        minus = float(trapezoid(np.minimum(p, 0.0), x))
        out[name] = (plus, minus, plus + minus)
    return out


def _load_name(name: str, dyn: SpatialDynamics, w: dict[str, str]) -> str:
    stems = {dyn.balancing_name(k)[0] for k in dyn.balancing}
    return w["bal_load"].format(name=name) if name in stems else name


def energy_section(dyn: SpatialDynamics, display: Display, shown: Shown, lang: str,
                   w: dict[str, str]) -> Section:
    """The works of the loads over the cycle, the kinetic energy plotted and the
    balance of the works and the change of ``T`` — or, when the chain breaks, the
    warning that these figures are not valid."""
    kin = dyn.kinematics
    blocks: list = []
    if kin.broken.any():
        where = compress_positions(np.flatnonzero(kin.broken))
        blocks.append(Paragraph(w["cycle_breaks"].format(
            where=w["at_positions"].format(list=where)), "warning"))
    else:
        found = works(dyn)
        # one precision for the three columns: a cycle's total work that is zero to the
        # precision of the loads' works prints as 0
        table = shown.value(np.array(list(found.values()), dtype=float), "J")
        scale = float(np.max(np.abs(table))) if table.size else 0.0
        columns = [[shown.number(v, scale) for v in table[:, i]] for i in range(3)]
        rows = [(_load_name(name, dyn, w), *(c[k] for c in columns))
                for k, name in enumerate(found)]
        unit = shown.unit_text("J")
        blocks.append(Table(w["t_works"], (w["h_load"], *(
            f"{w[h]}, {unit}" for h in ("h_work_plus", "h_work_minus", "h_work"))), rows))
        if not dyn.static:
            t = dyn.kinetic_energy
            total = sum(v[2] for v in found.values())
            change = float(t[-1] - t[0])
            scale = max(abs(total), abs(change), float(np.max(np.abs(t))))
            blocks.append(Table(w["t_energy"], (w["h_quantity"], w["h_value"]), [
                (w["e_t_span"], shown.span(float(t.min()), float(t.max()), "J")),
                (w["e_t_change"], shown.text(change, "J", scale)),
                (w["e_works_sum"], shown.text(total, "J", scale))]))
    if not dyn.static:
        blocks.append(FigureItem(w["f_energy"], lambda: translate(plot_energy(dyn, display),
                                                                 lang)))
    return Section(w["s_energy"], blocks)


def reduced_section3(dyn: SpatialDynamics, display: Display, shown: Shown, lang: str,
                     w: dict[str, str]) -> Section:
    """The planar report's section 7 for a spatial model: what is computed, the reduced
    characteristics (one argument), the balancing load, the works and the energy."""
    joints = dyn.reactions is not None
    blocks: list = [Paragraph(" ".join((w["p_virtual_power"],
                                        w["p_joints" if joints else "p_no_joints"])))]
    if dyn.static:
        blocks.append(Paragraph(w["p_static"]))
    if dyn.reduced is not None:
        blocks.append(Section(w["s_reduced_sub"], [FigureItem(w["f_reduced"], lambda:
                              translate(plot_reduced3(dyn, display), lang))]))
    blocks.append(Section(w["s_balancing"], [FigureItem(
        w["f_balancing3_ne" if joints else "f_balancing3"],
        lambda: translate(plot_balancing3(dyn, display), lang)),
        *agreement_lines(dyn, shown, w)]))
    blocks.append(energy_section(dyn, display, shown, lang, w))
    return Section(w["s_reduced"], blocks)


def centre_paths(dyn: SpatialDynamics) -> dict[str, Array]:
    """``S<body>`` -> the path ``(3, P)`` (m) of each body's centre of mass, the first
    :data:`MAX_CENTRES`."""
    return {f"S{b}": np.asarray(m.p, dtype=float)
            for b, m in list(sorted(dyn.centers.items()))[:MAX_CENTRES]}


def plot_centres3(dyn: SpatialDynamics, position: int, length_unit: str | None):
    """The paths of the centres of mass over the cycle in 3-D and the projections, over
    the vector scheme at ``position`` (faded)."""
    import matplotlib
    from matplotlib.lines import Line2D

    from mechloop.views import spatial_plan as sp
    from mechloop.views.russian import keep_names, model_names

    scene = sp.spatial_scene(dyn.kinematics, length_unit=length_unit)
    paths = {name: p * scene.scale for name, p in centre_paths(dyn).items()}
    box = sp.scene_box([*(scene.tails[n] for n in scene.vectors()),
                        *(scene.heads[n] for n in scene.vectors()), *paths.values()])
    colors = matplotlib.colormaps["Dark2"]
    handles = [Line2D([], [], color=scene.color(n), lw=2, label=str(n))
               for n in scene.vectors()]
    handles += [Line2D([], [], color=colors(i % 8), lw=1.6, marker="o", ms=4, label=name)
                for i, name in enumerate(paths)]
    st = sp.stage(scene, box, views="all", elev=sp.ELEV, azim=sp.AZIM, grid=True,
                  legend=handles)
    keep_names(st.figure, model_names(dyn.kinematics.model))
    for which, ax in st.panels.items():
        sp.draw_position(ax, scene, position, which, alpha=0.5)
        for i, path in enumerate(paths.values()):
            at = path[:, position:position + 1]
            if which == "3d":
                ax.plot(*path, color=colors(i % 8), lw=1.6, zorder=8)
                ax.plot(*at, ls="", marker="o", ms=4, color=colors(i % 8), zorder=9)
            else:
                h, v = sp.PROJECTIONS[which][1:]
                ax.plot(path[h], path[v], color=colors(i % 8), lw=1.6, zorder=8)
                ax.plot(at[h], at[v], ls="", marker="o", ms=4, color=colors(i % 8),
                        zorder=9)
    return st.figure


def centres_section3(dyn: SpatialDynamics, position: int, length_unit: str | None,
                     lang: str, w: dict[str, str]) -> Section | None:
    """The trajectories of the centres of mass (None without a mass)."""
    if not dyn.centers:
        return None
    return Section(w["s_centres"], [FigureItem(w["f_centres"], lambda: translate(
        plot_centres3(dyn, position, length_unit), lang))])


def conclusion3(dyn: SpatialDynamics | None, results, name: str, shown: Shown,
                w: dict[str, str]) -> list[Paragraph]:
    """The conclusion: the output parameter and the breaks (as the planar report), then
    the peak balancing loads, the peak reaction force and moment (with joints), the
    reduced inertia and the kinetic energy."""
    from mechloop.views.spatial_dynamics import length_argument

    out = kinematic_lines(results, name, shown, w)
    if dyn is None:
        return out
    for k, values in dyn.balancing.items():
        stem, unit = dyn.balancing_name(k)
        found = peak(values)
        if found is not None:
            out.append(Paragraph(w["peak_bal"].format(name=stem, value=shown.text(
                abs(found[1]), unit), position=found[0])))
    out += reaction_lines(dyn, shown, w)
    if dyn.reduced is not None:
        from mechloop.report.conclusion import reduced_range

        out += reduced_range(length_argument(dyn), dyn.reduced[0], dyn.reduced[1], shown, w)
    energy = finite_span(dyn.kinetic_energy)
    if not dyn.static and energy is not None:
        scale = max(map(abs, energy))
        out.append(Paragraph(w["energy_range"].format(
            low=shown.text(energy[0], "J", scale), high=shown.text(energy[1], "J", scale))))
    return out
