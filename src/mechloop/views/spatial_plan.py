"""Position plans of a model with spatial contours (issue 17): KDAM's 3-D vector scheme.

* :func:`plot_spatial_plan` — every vector at one position as an arrow from its tail to
  its head in 3-D, with KDAM's marks: the ground at the fixed points, the joints (every
  vector end) and the numbers of the vectors; seen from a chosen elevation and azimuth
  (``elev``, ``azim``, deg; the model's Y axis up), with the same scale on the three
  axes; and beside it the projections on the three planes (``views="all"``, a 2×2
  figure: the front view XY, the side view ZY, the top view XZ and the 3-D view).
* :func:`plot_spatial_overlay` — "photo" mode: every position drawn faded.
* :func:`plot_spatial_trajectories` — paths of vector ends (or points on vectors) over
  every position, with gaps where the chain breaks, over the plan at one position.

Coordinates: each contour is placed by its ``start:`` (the origin, a fixed ``[x, y]`` in
the plane z = 0, or an end of a vector of another contour), and walked vector by vector:
a vector ``n`` of the contour runs from the point reached to that point plus its
components ``(x_n, y_n, z_n)`` (:meth:`~mechloop.spatial.solve.SpatialResults.components`);
a subtracted one (``-n``) ends at the point reached and starts its length back.  Points
are ``(3, P)`` arrays in the display length unit; a position where the chain breaks is
NaN there (the drawing leaves it out and says so).

The projections drop one coordinate: XY drops z, ZY (horizontal z, vertical y) drops x,
XZ drops y.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import matplotlib
import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.markers import MarkerStyle
from matplotlib.patches import FancyArrowPatch
from matplotlib.path import Path
from mpl_toolkits.mplot3d import Axes3D, proj3d
from numpy.typing import NDArray

from mechloop.model.units import UnitProblem, unit_factor
from mechloop.solve.results import Results, compress_positions
from mechloop.views.figure import ViewError, new_figure
from mechloop.views.russian import keep_names, model_names
from mechloop.views.scene import VectorScene, check_position, check_positions

Array = NDArray[np.float64]

#: Default viewing angles (deg): elevation above the XZ plane, azimuth about the Y axis.
ELEV, AZIM = 20.0, 30.0
#: The views a spatial plan can hold: the 2×2 figure, or the 3-D view alone.
VIEWS = ("all", "3d")
#: The projections: title, the axes drawn horizontally and vertically (0 x, 1 y, 2 z).
PROJECTIONS = {"xy": ("front view XY", 0, 1), "zy": ("side view ZY", 2, 1),
               "xz": ("top view XZ", 0, 2)}
#: Margin around the drawn points, as a fraction of the largest span.
MARGIN = 0.08
#: A span shorter than this fraction of the largest is widened to it (a flat model).
MIN_SPAN = 0.25
#: Points closer than this (relative to the size of the drawing) are the same point.
SAME_POINT_RTOL = 1e-9


# ------------------------------------------------------------------------------- the scene


@dataclass(frozen=True)
class SpatialScene(VectorScene):
    """Every vector's ends of a spatial model in display units (``unit``), over the
    positions ``0..N``: ``tails`` and ``heads`` ``{n: (3, P)}``, ``ground`` ``(G, 3)``
    (the fixed points), ``scale`` display units per metre."""

    results: Results
    unit: str
    scale: float
    tails: dict[int, Array]
    heads: dict[int, Array]
    ground: Array


def spatial_scene(results: Results, *, length_unit: str | None = None) -> SpatialScene:
    """Place every vector of the solved spatial model ``results`` in 3-D, in
    ``length_unit`` (default: the model's).  Raises :class:`ViewError` for results that
    are not spatial or an unknown unit, :class:`~mechloop.errors.ModelError` for contour
    starts that cannot be placed (that refer to each other in a cycle, or to a vector of
    the contour itself or to none)."""
    if not callable(getattr(results, "components", None)):
        raise ViewError("a 3-D plan needs the results of a model with spatial contours",
                        "solve a model with 'spatial: true' contours by mechloop.solve, or "
                        "draw a planar model by plot_plan")
    unit = length_unit or results.model.units.length
    try:
        scale = 1.0 / unit_factor(unit, "length")
    except UnitProblem as exc:
        raise ViewError(exc.message, exc.hint) from exc
    tails, heads = _place(results)
    tails = {n: v * scale for n, v in tails.items()}
    heads = {n: v * scale for n, v in heads.items()}
    return SpatialScene(results, unit, scale, tails, heads, _ground(results, tails, heads))


def _place(results: Any) -> tuple[dict[int, Array], dict[int, Array]]:
    """Tails and heads (m, ``(3, P)``) of every vector, each contour from its start (the
    walk of :class:`~mechloop.spatial.points.Placement3`, which raises a located
    :class:`~mechloop.errors.ModelError` for a start that cannot be placed)."""
    from mechloop.spatial.points import Placement3

    with np.errstate(invalid="ignore"):
        place = Placement3(results)
        numbers = results.model.vectors
        return ({n: place.tail(n).p for n in numbers}, {n: place.head(n).p for n in numbers})


def _ground(results: Results, tails: dict[int, Array], heads: dict[int, Array]) -> Array:
    """Fixed points: the starts of contours and the ends of constant vectors, where they
    do not move over the positions."""
    candidates = [tails[abs(c.vectors[0])] for c in results.model.contours]
    candidates += [end for n in results.model.vectors
                   if all(f"{k}{n}" in results.constant for k in "rab")
                   for end in (tails[n], heads[n])]
    size = _size([*tails.values(), *heads.values()])
    fixed: list[Array] = []
    for p in candidates:
        known = p[:, np.isfinite(p).all(axis=0)]
        if not known.shape[1] or np.abs(known - known[:, :1]).max() > SAME_POINT_RTOL * size:
            continue
        if all(np.abs(known[:, 0] - f).max() > SAME_POINT_RTOL * size for f in fixed):
            fixed.append(known[:, 0])
    return np.array(fixed).reshape(-1, 3)


def _size(points: Iterable[Array]) -> float:
    """The largest finite coordinate magnitude (at least 1), a scale for tolerances."""
    biggest = 1.0
    for p in points:
        known = np.abs(p[np.isfinite(p)])
        if known.size:
            biggest = max(biggest, float(known.max()))
    return biggest


def joints(scene: SpatialScene, position: int) -> Array:
    """The distinct vector ends at ``position`` (``(J, 3)``, display units): KDAM's
    joints, where vectors meet or end."""
    size = _size([*scene.tails.values(), *scene.heads.values()])
    found: list[Array] = []
    for n in scene.vectors():
        for p in (scene.tails[n][:, position], scene.heads[n][:, position]):
            if np.isfinite(p).all() and all(np.abs(p - f).max() > SAME_POINT_RTOL * size
                                            for f in found):
                found.append(p)
    return np.array(found).reshape(-1, 3)


def scene_box(points: Iterable[Array]) -> Array:
    """``[[x0, x1], [y0, y1], [z0, z1]]`` around every finite point of ``points`` (each
    ``(3, ...)``), with margins; a span under :data:`MIN_SPAN` of the largest is widened
    about its middle, so a flat model is still seen in 3-D."""
    known = np.concatenate([np.reshape(p, (3, -1)) for p in points], axis=1)
    known = known[:, np.isfinite(known).all(axis=0)]
    if not known.shape[1]:
        return np.array([[-1.0, 1.0]] * 3)
    low, high = known.min(axis=1), known.max(axis=1)
    span = max(float((high - low).max()), 1e-12 * max(1.0, float(np.abs(known).max())))
    half = np.maximum(high - low, MIN_SPAN * span) / 2 + MARGIN * span
    middle = (low + high) / 2
    return np.stack([middle - half, middle + half], axis=1)


def _all_points(scene: SpatialScene, positions: Sequence[int] | None = None) -> list[Array]:
    pick = slice(None) if positions is None else list(positions)
    return [*(p[:, pick] for p in (*scene.tails.values(), *scene.heads.values())),
            scene.ground.T]


def check_view(views: str, elev: float, azim: float) -> None:
    """A :class:`ViewError` for an unknown ``views`` or angles that are not numbers."""
    if views not in VIEWS:
        raise ViewError(f"unknown views {views!r} of a 3-D plan",
                        "use 'all' (the 3-D view and the three projections) or '3d'")
    if not (isinstance(elev, int | float) and np.isfinite(elev)):
        raise ViewError(f"the viewing elevation {elev!r} is not a number",
                        "give the angles in degrees as finite numbers, e.g. 20 and 30")
    if not (isinstance(azim, int | float) and np.isfinite(azim)):
        raise ViewError(f"the viewing azimuth {azim!r} is not a number",
                        "give the angles in degrees as finite numbers, e.g. 20 and 30")


# ------------------------------------------------------------------------------- drawing


class Arrow3D(FancyArrowPatch):
    """An arrow from ``tail`` to ``head`` (3-D data points), projected when drawn."""

    def __init__(self, tail: Array, head: Array, **style: Any):
        super().__init__((0.0, 0.0), (0.0, 0.0), **style)
        self.tail3d = np.asarray(tail, dtype=float)
        self.head3d = np.asarray(head, dtype=float)

    def do_3d_projection(self, renderer: Any = None) -> float:
        xs, ys, zs = proj3d.proj_transform(*np.stack([self.tail3d, self.head3d], axis=1),
                                           self.axes.M)  # type: ignore[union-attr]
        self.set_positions((xs[0], ys[0]), (xs[1], ys[1]))
        return float(np.min(zs))


def ground_marker() -> MarkerStyle:
    """KDAM's ground as a marker: a support triangle on a hatched base."""
    verts = [(0.0, 0.0), (-0.7, -1.0), (0.7, -1.0), (0.0, 0.0)]
    codes = [Path.MOVETO, Path.LINETO, Path.LINETO, Path.CLOSEPOLY]
    verts += [(-1.0, -1.0), (1.0, -1.0)]
    codes += [Path.MOVETO, Path.LINETO]
    for i in range(5):
        x = -1.0 + 0.5 * i
        verts += [(x, -1.0), (x - 0.4, -1.4)]
        codes += [Path.MOVETO, Path.LINETO]
    return MarkerStyle(Path(verts, codes))


def _setup_3d(ax: Axes3D, scene: SpatialScene, box: Array, elev: float, azim: float,
              grid: bool) -> None:
    ax.set_xlim(*box[0])
    ax.set_ylim(*box[1])
    ax.set_zlim(*box[2])
    ax.view_init(elev=elev, azim=azim, vertical_axis="y")
    # the same scale on the three axes: each side of the box as long as its span
    ax.set_box_aspect(tuple(np.ptp(box, axis=1)))
    for axis, letter in zip((ax.xaxis, ax.yaxis, ax.zaxis), "xyz", strict=True):
        axis.set_label_text(f"{letter} [{scene.unit}]")
        axis.label.set_fontsize(8)
    ax.tick_params(labelsize=7)
    ax.locator_params(nbins=5)
    ax.grid(grid)
    ax.set_title(f"3-D view, elev {elev:g}°, azim {azim:g}°", fontsize=9)


def _setup_2d(ax: Axes, scene: SpatialScene, box: Array, which: str, grid: bool) -> None:
    title, h, v = PROJECTIONS[which]
    ax.set_xlim(*box[h])
    ax.set_ylim(*box[v])
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(f"{'xyz'[h]} [{scene.unit}]", fontsize=8)
    ax.set_ylabel(f"{'xyz'[v]} [{scene.unit}]", fontsize=8)
    ax.tick_params(labelsize=7)
    ax.axhline(0.0, color="0.6", lw=0.6, ls="-.", zorder=0)
    ax.axvline(0.0, color="0.6", lw=0.6, ls="-.", zorder=0)
    if grid:
        ax.grid(True, color="0.85", lw=0.6)
    ax.set_title(title, fontsize=9)


def _pick(points: Array, which: str) -> tuple[Array, Array]:
    """The two coordinates a projection shows (its horizontal, its vertical)."""
    _, h, v = PROJECTIONS[which]
    return points[h], points[v]


def draw_position(ax: Axes, scene: SpatialScene, position: int, which: str = "3d", *,
                  numbers: bool = True, alpha: float = 1.0) -> list[Artist]:
    """Draw the vectors at ``position`` on ``ax`` — 3-D axes (``which="3d"``) or a
    projection (``"xy"``, ``"zy"``, ``"xz"``): arrows tail to head (gid ``vector n``),
    the joints (the vector ends) as dots, the numbers at the middles; the ground is drawn
    by the setup.  Returns the artists (an animation removes them for the next frame)."""
    drawn: list[Artist] = []
    flat = which != "3d"
    for n in scene.vectors():
        tail, head = scene.tails[n][:, position], scene.heads[n][:, position]
        if not (np.isfinite(tail).all() and np.isfinite(head).all()):
            continue
        style = {"arrowstyle": "-|>", "mutation_scale": 12, "color": scene.color(n),
                 "lw": 1.8, "alpha": alpha, "shrinkA": 0, "shrinkB": 0}
        if flat:
            arrow: Artist = ax.annotate("", xy=_pick(head, which), xytext=_pick(tail, which),
                                        arrowprops=style, annotation_clip=False, zorder=3)
        else:
            arrow = Arrow3D(tail, head, zorder=3, **style)
            ax.add_artist(arrow)
        arrow.set_gid(f"vector {n}")
        drawn.append(arrow)
    if numbers:
        drawn += _numbers(ax, scene, position, which, alpha)
    points = joints(scene, position)
    if len(points):
        coords = _pick(points.T, which) if flat else tuple(points.T)
        (dots,) = ax.plot(*coords, ls="", marker="o", ms=4, mfc="0.75", mec="k", mew=0.7,
                          alpha=alpha, zorder=4, gid="joints")
        drawn.append(dots)
    return drawn


def _numbers(ax: Axes, scene: SpatialScene, position: int, which: str, alpha: float
             ) -> list[Artist]:
    """The numbers of the vectors at their middles; vectors with the same middle in this
    view (coinciding, or one behind the other in a projection) share one label "4, 5"."""
    size = _size([*scene.tails.values(), *scene.heads.values()])
    groups: list[tuple[Array, list[int]]] = []
    for n in scene.vectors():
        middle = (scene.tails[n][:, position] + scene.heads[n][:, position]) / 2
        if not np.isfinite(middle).all():
            continue
        seen = np.array(_pick(middle, which)) if which != "3d" else middle
        for at, members in groups:
            if np.abs(at - seen).max() <= 1e-6 * size:
                members.append(n)
                break
        else:
            groups.append((seen, [n]))
    drawn: list[Artist] = []
    for at, members in groups:
        box = {"boxstyle": "round,pad=0.15", "fc": "white", "ec": scene.color(members[0]),
               "lw": 0.6, "alpha": alpha}
        label = ax.text(*at, ", ".join(map(str, members)), ha="center", va="center",
                        fontsize=7, zorder=5, alpha=alpha, bbox=box,
                        gid="number " + ",".join(map(str, members)))
        drawn.append(label)
    return drawn


def draw_ground(ax: Axes, scene: SpatialScene, which: str = "3d") -> None:
    """The ground symbol at every fixed point."""
    if not len(scene.ground):
        return
    coords = _pick(scene.ground.T, which) if which != "3d" else tuple(scene.ground.T)
    ax.plot(*coords, ls="", marker=ground_marker(), ms=14, mfc="white", mec="k", mew=0.8,
            zorder=2, gid="ground")


def _break_note(figure: Figure, scene: SpatialScene, position: int) -> Artist:
    """One note across the figure: the chain breaks here, and why."""
    reasons = [f"contour {b.contour} ({b.module}):\n{b.reason}"
               for b in scene.results.breaks if position in b.positions]
    text = "\n".join([f"chain break at position {position}", *reasons])
    note = figure.text(0.5, 0.5, text, ha="center", va="center", fontsize=9,
                       color="tab:red", zorder=10, wrap=True, gid="chain break",
                       bbox={"boxstyle": "round", "fc": "white", "ec": "tab:red"})
    note.set_in_layout(False)
    return note


def _legend_handles(scene: SpatialScene) -> list[Artist]:
    handles: list[Artist] = []
    for n in scene.vectors():
        name = scene.results.model.vectors[n].name
        handles.append(Line2D([], [], color=scene.color(n), lw=2,
                              label=f"{n}" + (f" {name}" if name else "")))
    handles.append(Line2D([], [], ls="", marker="o", mfc="0.75", mec="k", ms=5,
                          label="joint (vector end)"))
    if len(scene.ground):
        handles.append(Line2D([], [], ls="", marker=ground_marker(), mfc="white", mec="k",
                              ms=12, label="ground"))
    return handles


def position_title(scene: SpatialScene, position: int) -> str:
    """``'RSSR spatial four-bar, position 9 of 0..72, t = 0.125 s'``."""
    name = scene.results.model.name or "mechanism"
    title = f"{name}, position {position} of 0..{scene.count - 1}"
    if scene.results.time is not None:
        title += f", t = {scene.results.time[position]:.4g} s"
    return title


@dataclass
class Stage:
    """The axes of a spatial plan: ``panels`` ``{"3d": Axes3D, "xy": ..., ...}``."""

    figure: Figure
    panels: dict[str, Axes]


def stage(scene: SpatialScene, box: Array, *, views: str, elev: float, azim: float,
          grid: bool, legend: Sequence[Artist] = (), width: float | None = None,
          figure: Figure | None = None) -> Stage:
    """A figure with the axes of ``views``, their limits, labels and the ground drawn."""
    check_view(views, elev, azim)
    if figure is None:
        size = (11.0, 9.0) if views == "all" else (8.0, 6.5)
        if width is not None:
            size = (width, width * size[1] / size[0])
        figure = new_figure(*size)
    if views == "all":
        panels: dict[str, Axes] = {"xy": figure.add_subplot(2, 2, 1),
                                   "zy": figure.add_subplot(2, 2, 2),
                                   "xz": figure.add_subplot(2, 2, 3),
                                   "3d": figure.add_subplot(2, 2, 4, projection="3d")}
    else:
        panels = {"3d": figure.add_subplot(projection="3d")}
    for which, ax in panels.items():
        if which == "3d":
            _setup_3d(ax, scene, box, float(elev), float(azim), grid)  # type: ignore[arg-type]
        else:
            _setup_2d(ax, scene, box, which, grid)
        draw_ground(ax, scene, which)
    if legend:
        figure.legend(handles=list(legend), loc="outside right upper", fontsize=7,
                      frameon=False)
    return Stage(figure, panels)


def _draw_all(st: Stage, scene: SpatialScene, position: int, **style: Any) -> list[Artist]:
    """The position in every panel, and the note of a chain break there."""
    drawn = [a for which, ax in st.panels.items()
             for a in draw_position(ax, scene, position, which, **style)]
    if scene.results.broken[position]:
        drawn.append(_break_note(st.figure, scene, position))
    return drawn


# ------------------------------------------------------------------------------- the views


def plot_spatial_plan(results: Results, position: int = 0, *, views: str = "all",
                      elev: float = ELEV, azim: float = AZIM, numbers: bool = True,
                      grid: bool = True, limits: str | None = None,
                      length_unit: str | None = None) -> Figure:
    """KDAM's vector scheme of a spatial model at ``position`` (0..N).

    Every vector is an arrow from its tail to its head, coloured by vector, numbered at
    its middle (``numbers``); the joints (vector ends) are dots and the ground is marked
    at the fixed points.  ``views="all"``: the 3-D view with the front (XY), side (ZY) and
    top (XZ) projections in a 2×2 figure; ``"3d"``: the 3-D view alone.  ``elev`` and
    ``azim`` (deg) set the viewing angles (Y up).  ``limits``: ``None`` fits every
    position (plans of different positions share a scale), ``"auto"`` this one.  The
    scale is the same on the three axes.
    """
    scene = spatial_scene(results, length_unit=length_unit)
    position = check_position(scene, position)
    box = _box(scene, limits, [position])
    st = stage(scene, box, views=views, elev=elev, azim=azim, grid=grid,
               legend=_legend_handles(scene))
    keep_names(st.figure, model_names(scene.results.model))
    st.figure.suptitle(position_title(scene, position), fontsize=10)
    _draw_all(st, scene, position, numbers=numbers)
    return st.figure


def _box(scene: SpatialScene, limits: str | None, at: list[int],
         extra: Sequence[Array] = ()) -> Array:
    if limits is None:
        return scene_box([*_all_points(scene), *extra])
    if limits != "auto":
        raise ViewError(f"limits {limits!r} of a 3-D plan are neither None nor 'auto'",
                        "use None (every position) or 'auto' (the positions drawn)")
    return scene_box([*_all_points(scene, at), *(p[:, at] for p in extra)])


def plot_spatial_overlay(results: Results, positions: Iterable[int] | None = None, *,
                         views: str = "all", elev: float = ELEV, azim: float = AZIM,
                         grid: bool = True, length_unit: str | None = None) -> Figure:
    """"Photo" mode in 3-D: the vectors at every chosen position (default: all) drawn over
    each other as faded lines, coloured by vector; broken positions are left out and
    named in the title."""
    scene = spatial_scene(results, length_unit=length_unit)
    chosen = check_positions(scene, positions)
    st = stage(scene, _box(scene, None, chosen), views=views, elev=elev, azim=azim,
               grid=grid, legend=_legend_handles(scene)[:len(scene.vectors())])
    keep_names(st.figure, model_names(scene.results.model))
    alpha = float(np.clip(4.0 / len(chosen), 0.12, 0.6))
    for n in scene.vectors():
        tails, heads = scene.tails[n][:, chosen], scene.heads[n][:, chosen]
        # one polyline tail-head-gap per position: NaN separates the segments
        gap = np.full_like(tails, np.nan)
        path = np.stack([tails, heads, gap], axis=2).reshape(3, -1)
        for which, ax in st.panels.items():
            coords = tuple(path) if which == "3d" else _pick(path, which)
            ax.plot(*coords, color=scene.color(n), alpha=alpha, lw=1.2, zorder=2,
                    gid=f"overlay {n}")
    broken = [p for p in chosen if scene.results.broken[p]]
    title = f"{scene.results.model.name or 'mechanism'}: positions {compress_positions(chosen)}"
    if broken:
        title += f"\nchain break at positions {compress_positions(broken)}"
    st.figure.suptitle(title, fontsize=10)
    return st.figure


def spatial_point(scene: SpatialScene, point: Any) -> tuple[str, Array]:
    """A label and the path (display units, ``(3, P)``) of ``point``: ``{head: K}``,
    ``{tail: K}``, ``{vector: K, share: s}`` (``s`` of vector K from its tail), or a
    vector number K (its head)."""
    if isinstance(point, int | np.integer) and not isinstance(point, bool):
        point = {"head": int(point)}
    forms = ({"head"}, {"tail"}, {"vector", "share"})
    if (not isinstance(point, dict) or set(point) not in forms
            or not isinstance(point.get("share", 0.0), int | float)):
        raise ViewError(f"{point!r} is not a point of a 3-D plan",
                        "use {head: K}, {tail: K} or {vector: K, share: s} "
                        "(head:K, tail:K or vector:K:s on the command line)")
    key = "vector" if "vector" in point else next(iter(point))
    number = point[key]
    if number not in scene.tails:
        raise ViewError(f"vector {number} does not exist", f"use one of {scene.vectors()}")
    tail, head = scene.tails[number], scene.heads[number]
    if key == "head":
        return f"head of {number}", head
    if key == "tail":
        return f"tail of {number}", tail
    share = float(point["share"])
    return f"{share:g} of {number}", tail + share * (head - tail)


def moving_heads(scene: SpatialScene) -> list[int]:
    """The vectors whose heads move, one per distinct path (the default points traced)."""
    size = _size([*scene.heads.values()])
    chosen: list[int] = []
    paths: list[Array] = []
    for n in scene.vectors():
        p = scene.heads[n]
        known = p[:, np.isfinite(p).all(axis=0)]
        if not known.shape[1] or np.abs(known - known[:, :1]).max() <= SAME_POINT_RTOL * size:
            continue  # a fixed point
        if any(np.array_equal(np.isfinite(p), np.isfinite(q)) and
               np.nanmax(np.abs(p - q), initial=0.0) <= SAME_POINT_RTOL * size
               for q in paths):
            continue
        chosen.append(n)
        paths.append(p)
    return chosen


def plot_spatial_trajectories(results: Results, points: Sequence[Any] | None = None, *,
                              position: int = 0, views: str = "all", elev: float = ELEV,
                              azim: float = AZIM, numbers: bool = True, grid: bool = True,
                              length_unit: str | None = None) -> Figure:
    """Trajectories of ``points`` (default: the head of every vector whose head moves)
    over every position, in 3-D and in the projections, on top of the plan at
    ``position``.  Each path is a line with gaps where the chain breaks and a dot where the
    point is at ``position``; the limits cover every position and every path."""
    scene = spatial_scene(results, length_unit=length_unit)
    position = check_position(scene, position)
    if points is None or (isinstance(points, Sequence) and not points):
        points = moving_heads(scene)
    elif isinstance(points, dict | int):
        points = [points]
    paths = [spatial_point(scene, p) for p in points]
    if not paths:
        raise ViewError("no points to trace", "give at least one point, e.g. [{'head': 2}]")
    colors = matplotlib.colormaps["Dark2"]
    handles = _legend_handles(scene)
    handles += [Line2D([], [], color=colors(i % 8), lw=1.6, label=label)
                for i, (label, _) in enumerate(paths)]
    st = stage(scene, _box(scene, None, [position], [p for _, p in paths]), views=views,
               elev=elev, azim=azim, grid=grid, legend=handles)
    keep_names(st.figure, model_names(scene.results.model))
    st.figure.suptitle(position_title(scene, position) + ", trajectories", fontsize=10)
    _draw_all(st, scene, position, numbers=numbers, alpha=0.7)
    for i, (label, path) in enumerate(paths):
        for which, ax in st.panels.items():
            coords = tuple(path) if which == "3d" else _pick(path, which)
            ax.plot(*coords, color=colors(i % 8), lw=1.6, zorder=8,
                    gid=f"trajectory {label}")
            at = path[:, position]
            if np.isfinite(at).all():
                here = tuple(at[:, None]) if which == "3d" else _pick(at[:, None], which)
                ax.plot(*here, ls="", marker="o", ms=4, color=colors(i % 8), zorder=9)
    return st.figure
