"""Labels of a plan placed without overlaps: a greedy choice among candidate offsets.

Each label (a vector's number, a joint's name, a centre of mass ``S2``) is an annotation
anchored at its point and shifted by an offset in points.  :func:`arrange_labels` tries, for
one label after the other, a set of candidate offsets and keeps the one with the lowest
score, measured in display coordinates (pixels) on the figure's renderer:

* the area shared with the labels already placed (weighted most),
* the area shared with the markers (joints, centres of mass, parameter marks) and the
  ground symbols,
* the length of the drawn links (vector arrows, ground hatching) inside the label — a
  vector's number may lie on its own vector, it is written on it,
* the area outside the axes,
* and, to break ties, the distance from the anchor.

A vector's number slides along its vector first and then off it; a point's name goes around
the point, clear of its marker.  The transform of the axes must be final (the figure laid
out) for the measure to hold in the saved figure: the plan views lay the figure out first,
and the animation places the labels of each frame on its frozen layout.  The labels are
left out of the layout (``set_in_layout(False)``), so placing them does not move the axes.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.backend_bases import RendererBase
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch
from matplotlib.text import Annotation
from matplotlib.transforms import Bbox
from numpy.typing import NDArray

Array = NDArray[np.float64]

#: Score per square pixel shared with a label already placed.
LABEL_WEIGHT = 100.0
#: Score per square pixel shared with a marker or a ground symbol.
MARKER_WEIGHT = 20.0
#: Score per pixel of a link drawn inside the label.
LINK_WEIGHT = 30.0
#: Score per square pixel outside the axes.
OUTSIDE_WEIGHT = 20.0
#: Score per pixel of offset (along a vector; across it counts twice).
DISTANCE_WEIGHT = 1.0
#: Clearance (points) between a point's name and the point's marker, first and further rings.
RINGS_PT = (2.0, 8.0, 16.0)
#: Shifts of a vector's number along its vector (fractions of its length) and across it
#: (points).
ALONG = (0.0, -0.12, 0.12, -0.25, 0.25, -0.38, 0.38)
ACROSS_PT = (0.0, -10.0, 10.0, -18.0, 18.0, -28.0, 28.0)


@dataclass
class _Label:
    artist: Annotation
    anchor: Array  # display px, shape (2,)
    size: Array  # width, height (px) of what is drawn, box included
    candidates: Array  # offsets (px), shape (C, 2)
    cost: Array  # distance penalty of each candidate, shape (C,)
    own: int | None  # the vector a number is written on


def renderer_of(figure: Figure) -> RendererBase:
    """The renderer that measures text in ``figure`` (an Agg one for a canvas-less
    figure)."""
    canvas = figure.canvas
    get = getattr(canvas, "get_renderer", None)
    return get() if get is not None else figure._get_renderer()  # type: ignore[attr-defined]


def settle(figure: Figure, ax: Axes) -> None:
    """Lay ``figure`` out as saving it would (its layout engine, the equal aspect of
    ``ax``), so the display transform of ``ax`` is the final one."""
    engine = figure.get_layout_engine()
    if engine is not None:
        engine.execute(figure)
    ax.apply_aspect()


def arrange_labels(ax: Axes, drawn: Sequence[Artist]) -> None:
    """Place the labels among ``drawn`` (gids ``number K``, ``joint label X``,
    ``center label SK``) without overlaps, in that order, avoiding each other, the
    markers and the links of ``drawn`` and the ground of ``ax``."""
    figure = ax.get_figure()
    if not isinstance(figure, Figure) and figure is not None:
        figure = figure.get_figure(root=True)  # a SubFigure: its root figure
    if not isinstance(figure, Figure):
        return
    renderer = renderer_of(figure)
    px = figure.dpi / 72.0
    to_px = ax.transData.transform
    links, owners = _links(ax, drawn, to_px)
    markers = _markers(ax, drawn, to_px, px, renderer)
    labels = [_label(a, links, owners, to_px, px, renderer) for a in _ordered(drawn)]
    frame = ax.get_window_extent(renderer)
    placed: list[Array] = []
    for label in labels:
        boxes = _boxes(label)
        score = label.cost * DISTANCE_WEIGHT
        if placed:
            score = score + LABEL_WEIGHT * _overlap(boxes, np.array(placed)).sum(axis=1)
        if markers.size:
            score = score + MARKER_WEIGHT * _overlap(boxes, markers).sum(axis=1)
        if links.size:
            inside = _inside_length(boxes, links)
            if label.own is not None:
                inside[:, owners == label.own] = 0.0
            score = score + LINK_WEIGHT * inside.sum(axis=1)
        area = (boxes[:, 2] - boxes[:, 0]) * (boxes[:, 3] - boxes[:, 1])
        within = _overlap(boxes, np.array([[frame.x0, frame.y0, frame.x1, frame.y1]]))[:, 0]
        score = score + OUTSIDE_WEIGHT * (area - within)
        best = int(np.argmin(score))
        placed.append(boxes[best])
        offset = label.candidates[best] / px
        label.artist.set_position((float(offset[0]), float(offset[1])))
        label.artist.set_horizontalalignment("center")
        label.artist.set_verticalalignment("center")


def label_box(label: Annotation, renderer: RendererBase) -> Array:
    """``(x0, y0, x1, y1)`` (px) of what ``label`` draws: its text and its box, if any."""
    box = label.get_window_extent(renderer)
    patch = label.get_bbox_patch()
    if patch is not None:
        label.update_bbox_position_size(renderer)
        outer = patch.get_window_extent(renderer)
        box = Bbox.union([box, outer])
    return np.array([box.x0, box.y0, box.x1, box.y1])


def _ordered(drawn: Sequence[Artist]) -> list[Annotation]:
    """The labels to place: vectors' numbers first (they can only slide along their
    vector), then the names of joints and centres of mass."""
    kinds = ("number ", "joint label ", "center label ")
    labels = [a for a in drawn if isinstance(a, Annotation)
              and str(a.get_gid() or "").startswith(kinds)]
    return sorted(labels, key=lambda a: [str(a.get_gid()).startswith(k)
                                         for k in kinds].index(True))


def _links(ax: Axes, drawn: Sequence[Artist], to_px) -> tuple[Array, NDArray[np.int64]]:
    """The drawn links as segments ``(x0, y0, x1, y1)`` (px), shape (S, 4), and the vector
    each belongs to (−1: the ground hatching)."""
    segments, owners = [], []
    for artist in drawn:
        gid = str(artist.get_gid() or "")
        if isinstance(artist, Annotation) and gid.startswith("vector "):
            tail, head = to_px(np.array([artist.xyann, artist.xy], dtype=float))
            segments.append([*tail, *head])
            owners.append(int(gid.split()[1]))
    for collection in ax.collections:
        if isinstance(collection, LineCollection) and collection.get_gid() == "ground hatch":
            for segment in collection.get_segments():
                ends = to_px(np.asarray(segment, dtype=float))
                segments.append([*ends[0], *ends[-1]])
                owners.append(-1)
    return np.array(segments, dtype=float).reshape(-1, 4), np.array(owners, dtype=np.int64)


def _markers(ax: Axes, drawn: Sequence[Artist], to_px, px: float,
             renderer: RendererBase) -> Array:
    """Boxes (px) of the point markers of ``drawn`` and of the ground symbols, (M, 4)."""
    boxes = []
    for artist in drawn:
        if isinstance(artist, Line2D) and artist.get_marker() not in ("", "None", None):
            half = artist.get_markersize() * px / 2
            for x, y in to_px(np.asarray(artist.get_xydata(), dtype=float)):
                boxes.append([x - half, y - half, x + half, y + half])
    for patch in ax.patches:
        if isinstance(patch, Patch) and patch.get_gid() == "ground":
            box = patch.get_window_extent(renderer)
            boxes.append([box.x0, box.y0, box.x1, box.y1])
    return np.array(boxes, dtype=float).reshape(-1, 4)


def _label(artist: Annotation, links: Array, owners: NDArray[np.int64], to_px, px: float,
           renderer: RendererBase) -> _Label:
    box = label_box(artist, renderer)
    size = np.array([box[2] - box[0], box[3] - box[1]]) + 2.0  # a pixel of air around
    anchor = to_px(np.asarray(artist.xy, dtype=float))
    gid = str(artist.get_gid())
    if gid.startswith("number "):
        own = int(gid.split()[1])
        segment = links[owners == own]
        return _number_label(artist, anchor, size, segment[0] if segment.size else None,
                             own, px)
    rings = []
    angles = np.radians(np.arange(0.0, 360.0, 45.0) + 45.0)  # up-right first
    for clearance in RINGS_PT:
        reach = np.array([size[0] / 2, size[1] / 2]) + (4.0 + clearance) * px
        rings.append(np.column_stack([np.cos(angles) * reach[0], np.sin(angles) * reach[1]]))
    candidates = np.concatenate(rings)
    return _Label(artist, anchor, size, candidates, np.hypot(*candidates.T), None)


def _number_label(artist: Annotation, anchor: Array, size: Array, segment: Array | None,
                  own: int, px: float) -> _Label:
    """Candidates of a vector's number: along the vector, then across it."""
    if segment is None or np.hypot(*(segment[2:] - segment[:2])) < 1e-9:
        along, across, length = np.array([1.0, 0.0]), np.array([0.0, 1.0]), 0.0
    else:
        d = segment[2:] - segment[:2]
        length = float(np.hypot(*d))
        along = d / length
        across = np.array([-along[1], along[0]])
    s, t = np.meshgrid(np.array(ALONG) * length, np.array(ACROSS_PT) * px, indexing="ij")
    s, t = s.ravel(), t.ravel()
    candidates = np.outer(s, along) + np.outer(t, across)
    return _Label(artist, anchor, size, candidates, np.abs(s) + 2.0 * np.abs(t), own)


def _boxes(label: _Label) -> Array:
    """The label's box (px) at each candidate offset, shape (C, 4)."""
    centre = label.anchor + label.candidates
    half = label.size / 2
    return np.column_stack([centre - half, centre + half])


def _overlap(a: Array, b: Array) -> Array:
    """Shared area (px²) of boxes ``a`` (A, 4) and ``b`` (B, 4), shape (A, B)."""
    w = np.minimum(a[:, None, 2], b[None, :, 2]) - np.maximum(a[:, None, 0], b[None, :, 0])
    h = np.minimum(a[:, None, 3], b[None, :, 3]) - np.maximum(a[:, None, 1], b[None, :, 1])
    return np.clip(w, 0.0, None) * np.clip(h, 0.0, None)


def _inside_length(boxes: Array, segments: Array) -> Array:
    """Length (px) of each segment (S, 4) inside each box (C, 4) — Liang-Barsky clipping,
    shape (C, S)."""
    p0, d = segments[None, :, :2], segments[None, :, 2:] - segments[None, :, :2]
    low, high = boxes[:, None, :2], boxes[:, None, 2:]
    moving = np.abs(d) > 1e-12
    safe = np.where(moving, d, 1.0)
    t1 = np.where(moving, (low - p0) / safe, -np.inf)
    t2 = np.where(moving, (high - p0) / safe, np.inf)
    # a segment parallel to a side is inside the slab or not at all
    still_in = (p0 >= low) & (p0 <= high)
    enter = np.where(moving, np.minimum(t1, t2), np.where(still_in, -np.inf, np.inf))
    leave = np.where(moving, np.maximum(t1, t2), np.where(still_in, np.inf, -np.inf))
    t_in = np.maximum(enter.max(axis=2), 0.0)
    t_out = np.minimum(leave.min(axis=2), 1.0)
    return np.clip(t_out - t_in, 0.0, None) * np.hypot(d[..., 0], d[..., 1])
