"""Position plans: the vector model drawn in the plane (KDAM's plan, "photo" and trajectories).

* :func:`plot_plan` — every vector at one position as an arrow from its tail to its head,
  its number at the middle, the ground hatched at the fixed points, function parameters
  marked with circles and argument parameters with triangles; with a
  :class:`~mechloop.dynamics.analysis.DynamicResults` also the centres of mass (the usual
  quartered-circle symbol) and the joints by name.
* :func:`plot_overlay` — "photo" mode: many positions drawn over each other, faded.
* :func:`plot_trajectories` — paths of chosen points (vector ends, points on vectors,
  centres of mass, joints) over the plan at one position.

Coordinates come from :class:`~mechloop.dynamics.points.Placement` (each contour placed by
its ``start:``) and are drawn in the model's length unit unless ``length_unit`` says
otherwise.  The scale is the same on both axes; by default the limits cover every position
(so the frames of an animation share one scale).  A position where the chain breaks draws
only what is known there and says "chain break at position k" — never a NaN.  A new
figure is shaped for the limits: the legend goes below the drawing in columns (the drawing
spanning the figure's width) unless the mechanism is much taller than wide, when it goes
beside it (:func:`legend_side`).

The lower-level pieces (:func:`plan_scene`, :func:`setup_axes`, :func:`draw_position`) are
what :mod:`mechloop.views.animation` uses to draw its frames.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import matplotlib
import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.markers import MarkerStyle
from matplotlib.patches import Polygon
from matplotlib.path import Path
from numpy.typing import NDArray
from pydantic import TypeAdapter, ValidationError

from mechloop.dynamics.analysis import DynamicResults
from mechloop.dynamics.points import Placement
from mechloop.model.dynamic import HeadPoint, PointOn, TailPoint, VectorPoint
from mechloop.model.schema import ArgumentRole
from mechloop.model.units import UnitProblem, unit_factor
from mechloop.solve.results import Results, compress_positions
from mechloop.views.figure import ViewError, new_figure
from mechloop.views.labels import arrange_labels, settle
from mechloop.views.russian import keep_names, model_names
from mechloop.views.scene import VectorScene, check_position, check_positions

Complex = NDArray[np.complex128]
Limits = tuple[float, float, float, float]

#: Where on a vector (fraction of its length from the tail) the mark of each parameter goes.
MARK_AT = {"a": 0.25, "r": 0.75}
#: Margin around the drawn points, as a fraction of the larger span.
MARGIN = 0.08
#: Size of a ground symbol, as a fraction of the larger span of the limits.
GROUND_SIZE = 0.035
#: Points closer than this (relative to the size of the drawing) are the same point.
SAME_POINT_RTOL = 1e-9

_POINT_ADAPTER: TypeAdapter[Any] = TypeAdapter(PointOn)


# ------------------------------------------------------------------------------- the scene


@dataclass(frozen=True)
class PlanScene(VectorScene):
    """Everything a plan draws, in display units (``unit``), over positions ``0..N``.

    ``tails`` and ``heads``: complex ``x + iy`` of every vector's ends, shape ``(P,)``;
    ``ground``: the fixed points, shape ``(G,)``; ``scale``: display units per metre.
    """

    results: Results
    placement: Placement
    dynamic: DynamicResults | None
    unit: str
    scale: float
    tails: dict[int, Complex]
    heads: dict[int, Complex]
    ground: Complex

    def to_display(self, z: Complex) -> Complex:
        """SI points (m) → display units."""
        return z * self.scale


def plan_scene(results: Results | DynamicResults, *, length_unit: str | None = None
               ) -> PlanScene:
    """Place every vector of ``results`` in the plane, in ``length_unit`` (default: the
    model's length unit).  Raises :class:`ViewError` for an unknown unit."""
    if isinstance(results, DynamicResults):
        kin, placement, dynamic = results.kinematics, results.placement, results
    elif isinstance(results, Results):
        if any(c.spatial for c in results.model.contours):  # issue 17: drawn in 3-D
            raise ViewError("a model with spatial contours is drawn in 3-D, not in the plane",
                            "use plot_spatial_plan, plot_spatial_overlay or "
                            "plot_spatial_trajectories of mechloop.views.spatial_plan, or "
                            "animate_spatial of mechloop.views.spatial_animation")
        kin, placement, dynamic = results, Placement(results), None
    else:
        raise ViewError(f"cannot draw a plan of {type(results).__name__}",
                        "pass the results of mechloop.solve or mechloop.solve_dynamics")
    unit = length_unit or kin.model.units.length
    try:
        scale = 1.0 / unit_factor(unit, "length")
    except UnitProblem as exc:
        raise ViewError(exc.message, exc.hint) from exc
    tails = {n: placement.tail(n).z * scale for n in kin.model.vectors}
    heads = {n: placement.head(n).z * scale for n in kin.model.vectors}
    ground = _ground_points(kin, tails, heads)
    return PlanScene(kin, placement, dynamic, unit, scale, tails, heads, ground)


def _ground_points(results: Results, tails: dict[int, Complex],
                   heads: dict[int, Complex]) -> Complex:
    """Fixed points: ends of constant vectors and the starts of contours, where they do not
    move over the positions (a constant vector of a contour started on a moving point
    moves)."""
    candidates = [tails[c.vectors[0]] for c in results.model.contours]
    for n in results.model.vectors:
        if f"r{n}" in results.constant and f"a{n}" in results.constant:
            candidates += [tails[n], heads[n]]
    size = _size([*tails.values(), *heads.values()])
    fixed: list[complex] = []
    for z in candidates:
        known = z[np.isfinite(z)]
        if not known.size or np.abs(known - known[0]).max() > SAME_POINT_RTOL * size:
            continue
        if all(abs(known[0] - f) > SAME_POINT_RTOL * size for f in fixed):
            fixed.append(complex(known[0]))
    return np.array(fixed, dtype=complex)


def _size(points: Iterable[Complex]) -> float:
    """The largest finite coordinate magnitude (at least 1), a scale for tolerances."""
    biggest = 1.0
    for z in points:
        known = np.abs(z[np.isfinite(z)])
        if known.size:
            biggest = max(biggest, float(known.max()))
    return biggest


def scene_limits(points: Iterable[Complex]) -> Limits:
    """``(xmin, xmax, ymin, ymax)`` around every finite point, with equal margins; a
    square of side 2 around the origin when nothing is known."""
    known = np.concatenate([np.ravel(z)[np.isfinite(np.ravel(z))] for z in points]
                           or [np.zeros(0, complex)])
    if not known.size:
        return (-1.0, 1.0, -1.0, 1.0)
    x0, x1 = float(known.real.min()), float(known.real.max())
    y0, y1 = float(known.imag.min()), float(known.imag.max())
    span = max(x1 - x0, y1 - y0)
    pad = MARGIN * span if span > 0 else max(abs(x0), abs(y0), 1.0) * 0.5
    return (x0 - pad, x1 + pad, y0 - pad, y1 + pad)


def _all_points(scene: PlanScene, positions: Sequence[int] | None = None) -> list[Complex]:
    """Every drawn point of the scene at ``positions`` (default: all)."""
    pick = slice(None) if positions is None else list(positions)
    points = [z[pick] for z in (*scene.tails.values(), *scene.heads.values())]
    points.append(scene.ground)
    if scene.dynamic is not None:
        points += [scene.to_display(c.z)[pick] for c in scene.dynamic.centers.values()]
    return points


def resolve_limits(scene: PlanScene, limits: str | Sequence[float] | None,
                   position: int | None = None, extra: Sequence[Complex] = ()) -> Limits:
    """The axes limits of a plan: ``None`` — over every position (and ``extra`` points);
    ``"auto"`` — around what is drawn at ``position``; or four numbers
    ``(xmin, xmax, ymin, ymax)`` in the display unit."""
    if limits is None:
        return scene_limits([*_all_points(scene), *extra])
    if isinstance(limits, str):
        if limits != "auto":
            raise ViewError(f"unknown limits {limits!r}",
                            "use None (every position), 'auto' or (xmin, xmax, ymin, ymax)")
        at = [position] if position is not None else None
        return scene_limits([*_all_points(scene, at), *extra])
    try:
        x0, x1, y0, y1 = (float(v) for v in limits)
    except (TypeError, ValueError) as exc:
        raise ViewError(f"limits {limits!r} are not four numbers",
                        "give (xmin, xmax, ymin, ymax) in the plan's length unit") from exc
    if not (np.isfinite([x0, x1, y0, y1]).all() and x0 < x1 and y0 < y1):
        raise ViewError(f"limits {limits!r} do not enclose an area",
                        "give finite (xmin, xmax, ymin, ymax) with xmin < xmax, ymin < ymax")
    return (x0, x1, y0, y1)


# ------------------------------------------------------------------------------- drawing


def parameter_roles(scene: PlanScene) -> dict[str, str]:
    """``{'a2': 'function', 'a1': 'argument', ...}`` for the parameters that KDAM marks."""
    roles = {}
    for number, vector in scene.results.model.vectors.items():
        for letter in "ra":
            value = getattr(vector, letter)
            if isinstance(value, ArgumentRole):
                roles[f"{letter}{number}"] = "argument"
            elif isinstance(value, str) and value.strip() == "function":
                roles[f"{letter}{number}"] = "function"
    return roles


def _cm_marker() -> MarkerStyle:
    """The two filled opposite quarters of the centre-of-mass symbol."""
    return MarkerStyle(Path.make_compound_path(Path.wedge(0, 90), Path.wedge(180, 270)))


def _legend_handles(scene: PlanScene, *, marks: bool = True) -> list[Artist]:
    handles: list[Artist] = []
    for n in scene.vectors():
        name = scene.results.model.vectors[n].name
        handles.append(Line2D([], [], color=scene.color(n), lw=2,
                              label=f"{n}" + (f" {name}" if name else "")))
    roles = set(parameter_roles(scene).values()) if marks else set()
    if "function" in roles:
        handles.append(Line2D([], [], ls="", marker="o", mfc="white", mec="k", ms=6,
                              label="function (α near tail, r near head)"))
    if "argument" in roles:
        handles.append(Line2D([], [], ls="", marker=argument_marker(0.0), mfc="0.5", mec="k",
                              ms=7, label="argument (α near tail, r near head)"))
    if len(scene.ground):
        handles.append(Line2D([], [], ls="", marker="^", mfc="white", mec="k", ms=7,
                              label="ground"))
    if scene.dynamic is not None and marks:
        handles.append(Line2D([], [], ls="", marker="o", mfc="0.75", mec="k", ms=5,
                              label="joint"))
        if scene.dynamic.centers:
            handles.append(Line2D([], [], ls="", marker=_cm_marker(), color="k", mew=0,
                                  ms=8, label="centre of mass"))
    return handles


def setup_axes(ax: Axes, scene: PlanScene, limits: Limits, *, grid: bool = False,
               axes: bool = True, legend: Sequence[Artist] = (),
               legend_side: str = "right") -> None:
    """What does not change from position to position: limits (equal scale), axis labels,
    grid, the origin lines, the ground symbols and the legend (``legend_side``:
    ``"right"`` beside the axes, ``"below"`` under the x-axis in columns)."""
    x0, x1, y0, y1 = limits
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal", adjustable="box")
    if axes:
        ax.set_xlabel(f"x [{scene.unit}]")
        ax.set_ylabel(f"y [{scene.unit}]")
        ax.axhline(0.0, color="0.6", lw=0.6, ls="-.", zorder=0)
        ax.axvline(0.0, color="0.6", lw=0.6, ls="-.", zorder=0)
    else:
        ax.tick_params(left=False, bottom=False, labelleft=False, labelbottom=False)
        for spine in ax.spines.values():
            spine.set_visible(False)
    if grid:
        ax.grid(True, color="0.85", lw=0.6)
        ax.set_axisbelow(True)
    draw_ground(ax, scene.ground, GROUND_SIZE * max(x1 - x0, y1 - y0))
    if legend and legend_side == "below":
        from mechloop.views.curves import legend_below

        legend_below(ax, legend)
        ax.get_legend().set_frame_on(False)
    elif legend:
        ax.legend(handles=list(legend), loc="upper left", bbox_to_anchor=(1.02, 1.0),
                  fontsize=7, frameon=False, borderaxespad=0.0)


def draw_ground(ax: Axes, points: Complex, size: float) -> None:
    """KDAM's ground at each fixed point: a support triangle on a hatched base, ``size`` in
    data units."""
    lines = []
    drawn: list[complex] = []
    for z in points:
        if any(abs(z - d) < 1.5 * size for d in drawn):
            continue  # one symbol for fixed points closer than the symbol itself
        drawn.append(z)
        x, y = z.real, z.imag
        base = y - size
        ax.add_patch(Polygon([(x, y), (x - 0.7 * size, base), (x + 0.7 * size, base)],
                             closed=True, facecolor="white", edgecolor="k", lw=0.8,
                             zorder=1, gid="ground"))
        lines.append([(x - size, base), (x + size, base)])
        for i in range(5):
            hx = x - size + i * 0.5 * size
            lines.append([(hx, base), (hx - 0.4 * size, base - 0.4 * size)])
    if lines:
        ax.add_collection(LineCollection(lines, colors="k", linewidths=0.8, zorder=1,
                                         gid="ground hatch"), autolim=False)


def _finite(*values: complex) -> bool:
    return all(np.isfinite(v) for v in values)


def draw_position(ax: Axes, scene: PlanScene, position: int, *, numbers: bool = True,
                  marks: bool = True, alpha: float = 1.0, arrange: bool = True
                  ) -> list[Artist]:
    """Draw the vectors (and, for dynamic results, the joints and centres of mass) at
    ``position``; returns the artists, so an animation can remove them for the next frame.

    ``arrange``: place the labels without overlaps on the axes as laid out now
    (:func:`~mechloop.views.labels.arrange_labels`); a view that lays its figure out
    afterwards passes False and arranges them then.

    Only what is known is drawn: at a chain break, the vectors with unknown ends are left
    out and the axes say "chain break at position k" with the reason.
    """
    drawn: list[Artist] = []
    roles = parameter_roles(scene) if marks else {}
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    near = 0.02 * max(x1 - x0, y1 - y0)
    middles: list[complex] = []
    for n in scene.vectors():
        tail, head = scene.tails[n][position], scene.heads[n][position]
        if not _finite(tail, head):
            continue
        drawn += _draw_vector(ax, scene, n, tail, head, roles, alpha=alpha)
        if numbers:
            middle = (tail + head) / 2
            shift = sum(abs(middle - m) < near for m in middles)
            middles.append(middle)
            drawn.append(_number_label(ax, scene, n, middle, shift, alpha))
    if scene.dynamic is not None and marks:
        drawn += _draw_joints(ax, scene, position, alpha)
        drawn += _draw_centers(ax, scene, position, alpha)
    if scene.results.broken[position]:
        drawn.append(_break_note(ax, scene, position))
    if arrange:
        arrange_labels(ax, drawn)
    return drawn


def _draw_arranged(figure: Figure, ax: Axes, scene: PlanScene, position: int,
                   **options: Any) -> list[Artist]:
    """:func:`draw_position` with its labels arranged on the figure as it will be saved."""
    drawn = draw_position(ax, scene, position, arrange=False, **options)
    settle(figure, ax)
    arrange_labels(ax, drawn)
    return drawn


def _draw_vector(ax: Axes, scene: PlanScene, n: int, tail: complex, head: complex,
                 roles: dict[str, str], *, alpha: float) -> list[Artist]:
    """The arrow of vector ``n`` and the marks of its function and argument parameters."""
    color = scene.color(n)
    arrow = ax.annotate("", xy=(head.real, head.imag), xytext=(tail.real, tail.imag),
                        xycoords="data", textcoords="data", annotation_clip=False,
                        arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.8,
                                    "shrinkA": 0, "shrinkB": 0, "mutation_scale": 12,
                                    "alpha": alpha},
                        zorder=3)
    arrow.set_gid(f"vector {n}")
    drawn: list[Artist] = [arrow]
    direction = float(np.degrees(np.angle(head - tail))) if head != tail else 0.0
    for letter, fraction in MARK_AT.items():
        role = roles.get(f"{letter}{n}")
        if role is None:
            continue
        at = tail + fraction * (head - tail)
        if role == "function":
            style: dict[str, Any] = {"marker": "o", "mfc": "white", "ms": 6}
        else:  # argument: a triangle pointing along the vector
            style = {"marker": argument_marker(direction), "mfc": color, "ms": 7}
        (mark,) = ax.plot([at.real], [at.imag], ls="", mec="k", mew=0.8, alpha=alpha,
                          zorder=4, gid=f"{role} {letter}{n}", **style)
        drawn.append(mark)
    return drawn


def argument_marker(direction: float) -> tuple[int, int, float]:
    """The marker of an argument parameter: a triangle with a vertex pointing at
    ``direction`` (deg, counter-clockwise from +x) — matplotlib's ``(3, 0, angle)``
    points up at angle 0."""
    return (3, 0, direction - 90.0)


def _number_label(ax: Axes, scene: PlanScene, n: int, middle: complex, shift: int,
                  alpha: float) -> Artist:
    """The number of vector ``n``, anchored at its middle; moved aside by ``shift`` label
    widths when earlier labels sit at the same place (coinciding vectors)."""
    label = ax.annotate(str(n), (middle.real, middle.imag), xytext=(11 * shift, 0),
                        textcoords="offset points", ha="center", va="center", fontsize=8,
                        zorder=5, alpha=alpha, annotation_clip=False,
                        bbox={"boxstyle": "round,pad=0.15", "fc": "white",
                              "ec": scene.color(n), "lw": 0.6, "alpha": alpha})
    label.set_gid(f"number {n}")
    label.set_in_layout(False)
    return label


def _draw_joints(ax: Axes, scene: PlanScene, position: int, alpha: float) -> list[Artist]:
    assert scene.dynamic is not None
    drawn: list[Artist] = []
    for pair in scene.dynamic.mechanism.pairs:
        z = scene.to_display(scene.placement.point(pair.at).z[position])
        if pair.kind == "prismatic" and pair.along is not None:
            z = (scene.tails[pair.along][position] + scene.heads[pair.along][position]) / 2
        if not _finite(z):
            continue
        if pair.kind == "revolute":
            (pin,) = ax.plot([z.real], [z.imag], ls="", marker="o", ms=5, mfc="0.75",
                             mec="k", mew=0.8, zorder=6, alpha=alpha,
                             gid=f"joint {pair.name}")
            drawn.append(pin)
            offset = (5, 5)
        else:
            offset = (0, -14)
        label = ax.annotate(pair.name, (z.real, z.imag), xytext=offset,
                            textcoords="offset points", fontsize=8, fontweight="bold",
                            zorder=7, alpha=alpha, annotation_clip=False)
        label.set_gid(f"joint label {pair.name}")
        label.set_in_layout(False)
        drawn.append(label)
    return drawn


def _draw_centers(ax: Axes, scene: PlanScene, position: int, alpha: float) -> list[Artist]:
    assert scene.dynamic is not None
    drawn: list[Artist] = []
    for body, motion in sorted(scene.dynamic.centers.items()):
        z = scene.to_display(motion.z[position])
        if not _finite(z):
            continue
        (ring,) = ax.plot([z.real], [z.imag], ls="", marker="o", ms=8, mfc="white", mec="k",
                          mew=0.8, zorder=6, alpha=alpha, gid=f"center S{body}")
        (quarters,) = ax.plot([z.real], [z.imag], ls="", marker=_cm_marker(), ms=8,
                              color="k", mew=0, zorder=6, alpha=alpha)
        label = ax.annotate(f"S{body}", (z.real, z.imag), xytext=(5, -10),
                            textcoords="offset points", fontsize=7, zorder=7, alpha=alpha,
                            annotation_clip=False, gid=f"center label S{body}")
        label.set_in_layout(False)
        drawn += [ring, quarters, label]
    return drawn


def _break_note(ax: Axes, scene: PlanScene, position: int) -> Artist:
    reasons = [f"contour {b.contour} ({b.module}):\n{b.reason}"  # a long reason: own line
               for b in scene.results.breaks if position in b.positions]
    text = "\n".join([f"chain break at position {position}", *reasons])
    return ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center",
                   fontsize=9, color="tab:red", zorder=10, wrap=True, gid="chain break",
                   bbox={"boxstyle": "round", "fc": "white", "ec": "tab:red"})


def position_title(scene: PlanScene, position: int) -> str:
    """``'Offset slider-crank\nposition 9 of 0..72, t = 0.0025 s'``."""
    name = scene.results.model.name or "mechanism"
    title = f"{name}\nposition {position} of 0..{scene.count - 1}"
    if scene.results.time is not None:
        title += f", t = {scene.results.time[position]:.4g} s"
    return title


def figure_size(limits: Limits, width: float = 8.0) -> tuple[float, float]:
    """A figure size (inches) that suits the shape of ``limits`` beside a legend."""
    x0, x1, y0, y1 = limits
    height = float(np.clip(0.62 * width * (y1 - y0) / (x1 - x0) + 1.3, 3.5, 8.0))
    return width, height


#: Legend columns when the legend goes below the drawing (as in views.curves).
LEGEND_COLUMNS = 3


#: The tallest drawing (height over width of the limits) whose legend goes below it.
TALLEST_BELOW = 1.5


def legend_side(limits: Limits) -> str:
    """Where the legend leaves the drawing the most room: ``"below"`` unless the
    mechanism is more than :data:`TALLEST_BELOW` times as tall as wide (the drawing takes
    the figure's width), ``"right"`` for a taller one (the legend fills the width the
    drawing leaves)."""
    x0, x1, y0, y1 = limits
    return "below" if y1 - y0 <= TALLEST_BELOW * (x1 - x0) else "right"


def figure_size_below(limits: Limits, entries: int, width: float = 8.0
                      ) -> tuple[float, float]:
    """A figure size (inches) whose drawing of ``limits`` spans the width, with the
    two-line title above and the axis labels and a legend of ``entries`` in
    :data:`LEGEND_COLUMNS` columns below it (sizes of matplotlib's default fonts)."""
    x0, x1, y0, y1 = limits
    rows = -(-entries // LEGEND_COLUMNS)
    drawing = (width - 0.75) * (y1 - y0) / (x1 - x0)
    return width, float(np.clip(drawing + 1.05 + 0.2 * rows, 3.0, 11.0))


def _target(ax: Axes | None, limits: Limits, entries: int = 0
            ) -> tuple[Figure, Axes, str]:
    """The figure and axes to draw in and the legend's side: a new figure shaped for
    ``limits`` and a legend of ``entries`` (:func:`legend_side`), or the given axes with
    the legend beside them."""
    if ax is None:
        side = legend_side(limits) if entries else "right"
        size = figure_size_below(limits, entries) if side == "below" else \
            figure_size(limits)
        figure = new_figure(*size)
        # "compressed": constrained layout that also fits equal-aspect axes and the legend
        figure.set_layout_engine("compressed")
        return figure, figure.add_subplot(), side
    figure = ax.get_figure()
    if not isinstance(figure, Figure):
        raise ViewError("the axes belong to no figure", "pass axes made by Figure.add_subplot")
    return figure, ax, "right"


# ------------------------------------------------------------------------------- the views


def plot_plan(results: Results | DynamicResults, position: int, *, ax: Axes | None = None,
              numbers: bool = True, grid: bool = False, axes: bool = True,
              limits: str | Sequence[float] | None = None,
              length_unit: str | None = None) -> Figure:
    """The vector model at ``position`` (0..N): KDAM's position plan.

    Every vector is an arrow from its tail to its head, coloured by vector, with its
    number at the middle (``numbers``); the ground is hatched at the fixed points; a
    function parameter is marked by a circle and an argument parameter by a triangle (on
    the vector at 1/4 of its length from the tail for the angle α, at 3/4 for the length
    r; an argument's triangle points along the vector).  With
    :class:`~mechloop.dynamics.analysis.DynamicResults` the centres of mass (``S1``, ...)
    and the joints are drawn and named.

    ``limits``: ``None`` (default) fits every position, so plans of different positions
    share a scale; ``"auto"`` fits this position; or ``(xmin, xmax, ymin, ymax)`` in
    ``length_unit`` (default: the model's length unit).  The scale is equal on x and y.
    ``grid`` adds a grid; ``axes=False`` hides the axes, their ticks and the origin lines.

    Returns the figure (``ax.figure`` when ``ax`` is given).  Raises :class:`ViewError`
    for a position outside ``0..N``, bad limits or an unknown unit.
    """
    scene = plan_scene(results, length_unit=length_unit)
    position = check_position(scene, position)
    box = resolve_limits(scene, limits, position)
    handles = _legend_handles(scene)
    figure, ax, side = _target(ax, box, len(handles))
    keep_names(figure, model_names(scene.results.model))
    setup_axes(ax, scene, box, grid=grid, axes=axes, legend=handles, legend_side=side)
    ax.set_title(position_title(scene, position), fontsize=10)
    _draw_arranged(figure, ax, scene, position, numbers=numbers)
    return figure


def plot_overlay(results: Results | DynamicResults, positions: Iterable[int] | None = None,
                 *, ax: Axes | None = None, highlight: int | None = None,
                 grid: bool = False, axes: bool = True,
                 limits: str | Sequence[float] | None = None,
                 length_unit: str | None = None) -> Figure:
    """"Photo" mode: the vectors at every chosen position (default: all) drawn over each
    other as faded lines, coloured by vector, with the ground hatched.

    ``highlight``: a position also drawn in full as a plan (arrows, numbers, marks) on
    top.  Positions where the chain breaks draw only their known vectors, and the title
    lists them.  ``limits`` and ``length_unit`` as in :func:`plot_plan` (``"auto"`` fits
    the chosen positions).
    """
    scene = plan_scene(results, length_unit=length_unit)
    chosen = check_positions(scene, positions)
    if isinstance(limits, str) and limits == "auto":
        box = scene_limits(_all_points(scene, chosen))
    else:
        box = resolve_limits(scene, limits)
    handles = _legend_handles(scene, marks=highlight is not None)
    figure, ax, side = _target(ax, box, len(handles))
    keep_names(figure, model_names(scene.results.model))
    setup_axes(ax, scene, box, grid=grid, axes=axes, legend=handles, legend_side=side)
    alpha = float(np.clip(4.0 / len(chosen), 0.12, 0.6))
    for n in scene.vectors():
        tails, heads = scene.tails[n][chosen], scene.heads[n][chosen]
        known = np.isfinite(tails) & np.isfinite(heads)
        segments = np.stack([np.column_stack([tails.real, tails.imag]),
                             np.column_stack([heads.real, heads.imag])], axis=1)[known]
        ax.add_collection(LineCollection(segments, colors=[scene.color(n)], alpha=alpha,
                                         linewidths=1.4, zorder=2, gid=f"overlay {n}"),
                          autolim=False)
    broken = [p for p in chosen if scene.results.broken[p]]
    title = f"{scene.results.model.name or 'mechanism'}: positions {compress_positions(chosen)}"
    if broken:
        title += f"\nchain break at positions {compress_positions(broken)}"
    ax.set_title(title, fontsize=10)
    if highlight is not None:
        _draw_arranged(figure, ax, scene, check_position(scene, highlight))
    return figure


def trajectory_point(scene: PlanScene, point: Any) -> tuple[str, Complex]:
    """A label and the path (display units, shape (P,)) of ``point``: ``{tail: K}``,
    ``{head: K}``, ``{vector: K, share: s}`` / ``{vector: K, along: d, across: e}`` (model
    units), the same as :mod:`mechloop.model.dynamic` objects, or for dynamic results
    ``"S2"`` (centre of mass of body 2), ``"S"`` (the common centre, unless a joint is
    named S) or a joint's name."""
    if isinstance(point, str):
        return point, _named_point(scene, point)
    if not isinstance(point, TailPoint | HeadPoint | VectorPoint):
        try:
            point = _POINT_ADAPTER.validate_python(point)
        except ValidationError as exc:
            raise ViewError(f"{point!r} is not a point",
                            "use {tail: K}, {head: K}, {vector: K, share: s}, "
                            "{vector: K, along: d, across: e} or 'S2'") from exc
    if isinstance(point, TailPoint):
        number = point.tail
    elif isinstance(point, HeadPoint):
        number = point.head
    else:
        number = point.vector
    if number not in scene.tails:
        raise ViewError(f"vector {number} does not exist",
                        f"use one of {scene.vectors()}")
    return _point_label(point), scene.to_display(scene.placement.point(point).z)


def _point_label(point: TailPoint | HeadPoint | VectorPoint) -> str:
    if isinstance(point, TailPoint):
        return f"tail of {point.tail}"
    if isinstance(point, HeadPoint):
        return f"head of {point.head}"
    place = f"{point.share:g} of" if point.share is not None else f"{_number(point.along)} along"
    across = f", {_number(point.across)} across" if point.across else ""
    return f"{place} {point.vector}{across}"


def _number(value: float | str | None) -> str:
    """A model-file value as written: ``70`` for 70.0, ``'5 mm'`` as is."""
    return f"{value:g}" if isinstance(value, int | float) else str(value)


def _named_point(scene: PlanScene, name: str) -> Complex:
    dynamic = scene.dynamic
    if dynamic is None:
        raise ViewError(f"point {name!r} (a joint or centre of mass) needs dynamic "
                        "results, of a model with bodies",
                        "add bodies and joints to the model file (see "
                        "examples/crank_slider_dynamics.yaml), or give the point on a vector: "
                        "head:K, tail:K or vector:K:s (in Python: {head: K}, ..., with the "
                        "results of solve_dynamics)")
    pairs = {p.name: p for p in dynamic.mechanism.pairs}
    if name in pairs:
        return scene.to_display(scene.placement.point(pairs[name].at).z)
    if name == "S":
        return scene.to_display(dynamic.center.z)
    if name.startswith("S") and name[1:].isdigit() and int(name[1:]) in dynamic.centers:
        return scene.to_display(dynamic.centers[int(name[1:])].z)
    known = [f"S{b}" for b in sorted(dynamic.centers)] + ["S", *pairs]
    raise ViewError(f"no point named {name!r}", f"use one of {', '.join(known)}")


def plot_trajectories(results: Results | DynamicResults, points: Sequence[Any], *,
                      position: int = 0, ax: Axes | None = None, numbers: bool = True,
                      grid: bool = False, axes: bool = True,
                      limits: str | Sequence[float] | None = None,
                      length_unit: str | None = None) -> Figure:
    """Trajectories of ``points`` over every position, on top of the plan at ``position``.

    ``points``: any of the forms of :func:`trajectory_point`.  Each path is a line (gaps
    at chain breaks) with a dot where the point is at ``position``; the limits cover the
    mechanism at every position and every path.
    """
    scene = plan_scene(results, length_unit=length_unit)
    position = check_position(scene, position)
    if isinstance(points, str | dict) or not isinstance(points, Sequence):
        points = [points]
    paths = [trajectory_point(scene, p) for p in points]
    if not paths:
        raise ViewError("no points to trace", "give at least one point, e.g. [{'head': 2}]")
    box = resolve_limits(scene, limits, position, [z for _, z in paths])
    handles = _legend_handles(scene)
    colors = matplotlib.colormaps["Dark2"]
    for i, (label, _) in enumerate(paths):
        handles.append(Line2D([], [], color=colors(i % 8), lw=1.6, label=label))
    figure, ax, side = _target(ax, box, len(handles))
    keep_names(figure, model_names(scene.results.model))
    setup_axes(ax, scene, box, grid=grid, axes=axes, legend=handles, legend_side=side)
    ax.set_title(position_title(scene, position) + ", trajectories", fontsize=10)
    _draw_arranged(figure, ax, scene, position, numbers=numbers, alpha=0.7)
    for i, (label, z) in enumerate(paths):
        ax.plot(z.real, z.imag, color=colors(i % 8), lw=1.6, zorder=8,
                gid=f"trajectory {label}")
        if np.isfinite(z[position]):
            ax.plot([z[position].real], [z[position].imag], ls="", marker="o", ms=4,
                    color=colors(i % 8), zorder=9)
    return figure
