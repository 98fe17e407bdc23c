"""Figures of the joint reactions of a model with spatial contours (issue 17), from
:func:`mechloop.spatial.dynamics.solve_spatial_dynamics` with ``joints:``:

* :func:`plot_spatial_reactions` — the magnitude ``|R|`` of every joint's force over the
  positions and, below it, the magnitude ``|R_m|`` of the moment of every joint that has
  one (revolute, cylindrical, prismatic);
* :func:`plot_spatial_hodograph` — the hodograph of a joint's force (or moment): the tip
  of the reaction vector drawn from the origin over the positions, as a 3-D curve with
  its projections on the XY, ZY and XZ planes (the axes conventions of
  :mod:`mechloop.views.spatial_plan`: Y up, the same scale on the three axes, XY drops z,
  ZY drops x, XZ drops y), the vector at one position drawn as an arrow from the origin.

Reactions are the first body's on the second (the joint's ``bodies:`` order), in the
model's axes, in the display's force and moment units.  A position where the chain
breaks or the force system is singular has no reaction: the curves have a gap there.
The texts are English; :func:`mechloop.views.russian.translate` puts them in Russian.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from numpy.typing import NDArray

from mechloop.spatial.joints import COMPONENTS
from mechloop.views import spatial_plan as sp
from mechloop.views.display import DEFAULT_DISPLAY, Display
from mechloop.views.figure import ViewError, new_figure
from mechloop.views.russian import keep_names, model_names

Array = NDArray[np.float64]

#: The parts of a reaction a hodograph can trace, with their display kind.
PARTS = {"force": "force", "moment": "moment"}
#: Position numbers written along a hodograph's projections at most.
NUMBERED = 8


def _reactions(dyn: Any):
    reactions = getattr(dyn, "reactions", None)
    if reactions is None:
        raise ViewError("this model has no joint reactions",
                        "name its kinematic pairs under joints: (type, bodies, at, axis; "
                        "see examples/spatial/rssr_reactions.yaml)")
    return reactions


def reaction_joints(dyn: Any, joints: Sequence[str] | str | None = None) -> list[str]:
    """The names of ``joints`` (default: every joint) of the solved spatial dynamics
    ``dyn``; a :class:`~mechloop.views.figure.ViewError` for a model without
    reactions or a joint it does not have."""
    from mechloop.views.dynamics import chosen_joints

    return chosen_joints(list(_reactions(dyn).joints), joints)


def has_moment(reaction: Any) -> bool:
    """Whether a joint's reaction has a moment (every type but spherical)."""
    return bool(COMPONENTS[reaction.joint.kind][1])


def magnitudes(dyn: Any, joint: str) -> tuple[Array, Array | None]:
    """``|R|`` (N) and ``|R_m|`` (N·m; None for a spherical joint) of ``joint`` over the
    positions, ``(P,)`` each, NaN where it is not known."""
    reaction = _reactions(dyn).joints[joint]
    force = np.linalg.norm(reaction.force, axis=0)
    return force, (np.linalg.norm(reaction.moment, axis=0) if has_moment(reaction)
                   else None)


def plot_spatial_reactions(dyn: Any, joints: Sequence[str] | str | None = None, *,
                           display: Display = DEFAULT_DISPLAY) -> Figure:
    """The magnitude of the force of every joint (or of ``joints``) over the positions,
    each a line ``|R<name>|`` in the display force unit; below it, when one of them has
    a moment, the magnitude of the moments ``|R<name>_m|`` in the display moment unit."""
    names = reaction_joints(dyn, joints)
    kin = dyn.kinematics
    x = kin.positions.astype(float)
    moments = [n for n in names if has_moment(_reactions(dyn).joints[n])]
    figure = keep_names(new_figure(8.0, 7.0 if moments else 4.8), model_names(kin.model))
    axes = np.atleast_1d(figure.subplots(2 if moments else 1, 1, sharex=True))
    for i, name in enumerate(names):
        force, moment = magnitudes(dyn, name)
        axes[0].plot(x, display.convert(force, "force"), color=f"C{i % 10}",
                     label=f"|R{name}|", gid=f"|R{name}|")
        if moment is not None:
            axes[1].plot(x, display.convert(moment, "moment"), color=f"C{i % 10}",
                         label=f"|R{name}_m|", gid=f"|R{name}_m|")
    panels = [(axes[0], "reactions in the joints", "reaction", "force")]
    if moments:
        panels.append((axes[1], "reaction moments in the joints", "reaction moment",
                       "moment"))
    for ax, title, quantity, kind in panels:
        ax.set_title(title)
        ax.set_ylabel(f"{quantity} [{display.label(kind)}]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="best", fontsize="small", ncols=2 if len(names) > 6 else 1)
    axes[-1].set_xlabel("position")
    return figure


def _first_finite(points: Array) -> int | None:
    finite = np.flatnonzero(np.isfinite(points).all(axis=0))
    return int(finite[0]) if finite.size else None


def plot_spatial_hodograph(dyn: Any, joint: str, *, part: str = "force",
                           position: int | None = None, views: str = "all",
                           elev: float = sp.ELEV, azim: float = sp.AZIM,
                           display: Display = DEFAULT_DISPLAY) -> Figure:
    """The hodograph of the reaction in ``joint``: its ``part`` ('force', or 'moment' of a
    joint that has one) as a vector from the origin, its tip traced over the positions.

    ``views="all"``: the projections on XY, ZY and XZ and the 3-D view (``elev``,
    ``azim`` in degrees, Y up) in a 2×2 figure; ``"3d"``: the 3-D view alone.  The curve
    (gid ``R<joint>`` or ``R<joint>_m``) has the points ``(R_x, R_y, R_z)`` in the
    display force (moment) unit, with gaps where the reaction is not known; the origin is
    marked and the vector at ``position`` (default: the first known one) drawn as an
    arrow; the projections number about :data:`NUMBERED` positions along the curve.
    """
    (name,) = reaction_joints(dyn, [joint])
    if part not in PARTS:
        raise ViewError(f"unknown part {part!r} of a reaction",
                        "use 'force' or 'moment'")
    reaction = _reactions(dyn).joints[name]
    if part == "moment" and not has_moment(reaction):
        raise ViewError(f"joint {name} is spherical: its reaction has no moment",
                        "trace its force (part='force')")
    kin = dyn.kinematics
    kind = PARTS[part]
    values = reaction.force if part == "force" else reaction.moment
    points = display.convert(values, kind)
    unit = display.label(kind)
    label = f"R{name}" if part == "force" else f"R{name}_m"
    # a scene with no vectors: the plan's axes, limits and views in the reaction's unit
    scene = sp.SpatialScene(kin, unit, 1.0, {}, {}, np.zeros((0, 3)))
    position = _first_finite(points) if position is None else \
        sp.check_position(scene, position)
    box = sp.scene_box([points, np.zeros((3, 1))])
    handles = [Line2D([], [], color="C0", lw=1.6, label=label),
               Line2D([], [], color="k", ls="", marker="+", ms=10, label="origin")]
    tip = None if position is None else points[:, int(position)]
    if tip is not None and np.isfinite(tip).all():
        handles.append(Line2D([], [], color="C3", lw=1.4, marker="o", ms=4,
                              label=f"position {int(position)}"))
    else:
        tip = None
    st = sp.stage(scene, box, views=views, elev=elev, azim=azim, grid=True,
                  legend=handles)
    keep_names(st.figure, model_names(kin.model))
    title = ("hodograph of the reaction in" if part == "force" else
             "hodograph of the reaction moment in")
    st.figure.suptitle(f"{title} {name} [{unit}]", fontsize=10)
    origin = np.zeros(3)
    for which, ax in st.panels.items():
        if which == "3d":
            for axis, letter in zip((ax.xaxis, ax.yaxis, ax.zaxis), "xyz", strict=True):
                axis.set_label_text(f"{label}_{letter} [{unit}]")
            ax.plot(*points, color="C0", lw=1.6, gid=label)
            ax.plot(*origin[:, None], ls="", marker="+", ms=10, color="k")
            if tip is not None:
                ax.add_artist(sp.Arrow3D(origin, tip, arrowstyle="-|>", mutation_scale=12,
                                         color="C3", lw=1.4, shrinkA=0, shrinkB=0,
                                         zorder=6))
            continue
        _, h, v = sp.PROJECTIONS[which]
        ax.set_xlabel(f"{label}_{'xyz'[h]} [{unit}]", fontsize=8)
        ax.set_ylabel(f"{label}_{'xyz'[v]} [{unit}]", fontsize=8)
        ax.plot(points[h], points[v], color="C0", lw=1.6, gid=label)
        ax.plot([0.0], [0.0], ls="", marker="+", ms=10, color="k")
        if tip is not None:
            ax.annotate("", xy=(tip[h], tip[v]), xytext=(0.0, 0.0), annotation_clip=False,
                        arrowprops={"arrowstyle": "-|>", "color": "C3", "lw": 1.4,
                                    "shrinkA": 0, "shrinkB": 0})
            ax.plot([tip[h]], [tip[v]], ls="", marker="o", ms=4, color="C3")
        _number_positions(ax, points[h], points[v])
    return st.figure


def _number_positions(ax: Any, xs: Array, ys: Array) -> None:
    """Position numbers beside about :data:`NUMBERED` known points of a curve (the
    closing position of a cycle that returns to its start is left out)."""
    step = max(1, xs.size // NUMBERED)
    closed = xs.size > 1 and bool(np.isclose(xs[0], xs[-1]) and np.isclose(ys[0], ys[-1]))
    for k in range(0, xs.size - 1 if closed else xs.size, step):
        if np.isfinite(xs[k]) and np.isfinite(ys[k]):
            ax.annotate(str(k), (xs[k], ys[k]), fontsize=6, textcoords="offset points",
                        xytext=(3, 3), color="0.35")
