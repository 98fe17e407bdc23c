"""KDAM's "cinema" mode for a model with spatial contours: the 3-D plan (and its
projections) played over the cycle, saved as GIF or MP4 by the writers of
:mod:`mechloop.views.animation` (the same frame time, loop and file rules); an HTML file
is the interactive 3-D view of :mod:`mechloop.views.spatial_html`.

Each frame is the whole figure drawn again (a 3-D view re-sorts its artists by depth, so
the planar animation's fixed background is not reused): one scale over every position,
the layout computed once on the first frame and then frozen, so the frames do not shift.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from numpy.typing import NDArray

from mechloop.solve.results import Results
from mechloop.views.animation import (
    ANIMATION_SUFFIXES,
    SAME_POSE_RTOL,
    Progress,
    _counted,
    frame_interval,
    write_frames,
)
from mechloop.views.figure import ViewError
from mechloop.views.spatial_plan import (
    AZIM,
    ELEV,
    SpatialScene,
    _all_points,
    _draw_all,
    check_positions,
    position_title,
    scene_box,
    spatial_scene,
    stage,
)


def same_pose(scene: SpatialScene, first: int, last: int) -> bool:
    """Whether positions ``first`` and ``last`` draw the same picture: every vector end
    at the same place to :data:`~mechloop.views.animation.SAME_POSE_RTOL` of the drawing's
    size, and the same ends known."""
    ends = np.stack([p[:, [first, last]] for p in (*scene.tails.values(),
                                                    *scene.heads.values())])
    known = np.isfinite(ends).all(axis=1)  # (ends, 2)
    if not known.any() or not np.array_equal(known[:, 0], known[:, 1]):
        return False
    both = ends[known[:, 0]]
    size = max(float(np.abs(both).max()), 1e-300)
    return bool(np.abs(both[:, :, 0] - both[:, :, 1]).max() <= SAME_POSE_RTOL * size)


def animate_spatial(results: Results, path: str | os.PathLike[str], *,
                    fps: float | None = None, positions: Iterable[int] | None = None,
                    progress: Progress | None = None, views: str = "all",
                    elev: float = ELEV, azim: float = AZIM, dpi: int = 80,
                    width: float | None = None, numbers: bool = True, grid: bool = True,
                    length_unit: str | None = None, lang: str | None = None) -> Path:
    """Save the 3-D plan of a spatial model at every position as an animation; returns
    the path.

    ``path``: ``.gif``, ``.mp4`` or ``.html`` (the interactive 3-D view of
    :func:`mechloop.views.spatial_html.write_spatial_html`: every position, ``views``,
    ``dpi``, ``width``, ``numbers`` and ``grid`` do not apply).  ``positions``: the
    frames (default every position; the last is left out when it closes the cycle).
    ``fps``, ``progress`` as in :func:`mechloop.views.animation.animate`; ``views``,
    ``elev``, ``azim``, ``numbers``, ``grid`` and ``length_unit`` as in
    :func:`~mechloop.views.spatial_plan.plot_spatial_plan`; ``dpi`` and ``width``
    (inches) set the frame size; ``lang`` (``en`` or ``ru``, default ``MECHLOOP_LANG``):
    the language of the ``.html`` page (the frames of pixels have no words).
    """
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in ANIMATION_SUFFIXES:
        raise ViewError(f"{target}: cannot save an animation as '{suffix or 'no suffix'}'",
                        "use a file name ending in .gif, .mp4 or .html")
    if suffix in (".html", ".htm"):  # the interactive 3-D view, not frames of pixels
        from mechloop.views.spatial_html import write_spatial_html

        return write_spatial_html(results, target, fps=fps, positions=positions, elev=elev,
                                  azim=azim, length_unit=length_unit, lang=lang,
                                  progress=progress)
    scene = spatial_scene(results, length_unit=length_unit)
    chosen = check_positions(scene, positions)
    if len(chosen) > 2 and same_pose(scene, chosen[0], chosen[-1]):
        chosen = chosen[:-1]
    interval = frame_interval(scene.results, chosen, fps)
    st = stage(scene, scene_box(_all_points(scene)), views=views, elev=elev, azim=azim,
               grid=grid, width=width, figure=None)
    figure = st.figure
    w, h = figure.get_size_inches()
    size = (_even(w, dpi), _even(h, dpi))
    figure.set_size_inches(size[0] / dpi, size[1] / dpi)
    figure.set_dpi(dpi)
    canvas = FigureCanvasAgg(figure)
    frozen = [False]

    def render(position: int) -> NDArray[np.uint8]:
        drawn = _draw_all(st, scene, position, numbers=numbers)
        title = figure.suptitle(position_title(scene, position), fontsize=10)
        if not frozen[0]:  # the layout of the first frame, kept for the others
            canvas.draw()
            figure.set_layout_engine("none")
            frozen[0] = True
        canvas.draw()
        pixels = np.array(canvas.buffer_rgba(), dtype=np.uint8)
        for artist in drawn:
            artist.remove()
        title.set_text("")
        return pixels

    frames = _counted((render(p) for p in chosen), len(chosen), progress)
    write_frames(frames, size, target, interval)
    return target


def _even(inches: float, dpi: int) -> int:
    return max(2, 2 * round(inches * dpi / 2))


