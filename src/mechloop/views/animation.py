"""KDAM's "cinema" mode: the position plan played over the cycle, saved as GIF, MP4 or HTML.

One frame per position (``0..N`` by default, none skipped; a chain-break position is a
frame that says so), all on one fixed scale that covers every position.  A closed cycle
loops seamlessly: when the last chosen position draws the same pose as the first (a crank
turned a full turn), the last frame is dropped, since the loop shows the first again
right after it; an open motion (a stroke, a range of the argument) keeps every frame.

The frame time is the model time: the mean time step between the chosen positions (100 ms
without a model time; ``fps`` overrides).  What each format can hold:

* a frame is shown for at least :data:`MIN_INTERVAL_MS` (20 ms, 50 frames per second):
  a machine faster than that plays in slow motion (a 3000 rpm crank over 72 positions
  moves 0.28 ms per position; real time would be a 3600 fps, 20 ms long video).  An
  explicit ``fps`` is taken as given;
* **MP4** (H.264 by the ffmpeg of ``imageio-ffmpeg``, matplotlib's ``FFMpegWriter``) and
  **HTML** (a self-contained page with the frames embedded and play controls,
  matplotlib's ``HTMLWriter`` as behind ``to_jshtml``) hold any frame time;
* **GIF** stores frame delays in hundredths of a second, and browsers slow any delay
  under 20 ms down to 100 ms: the delay is rounded to 10 ms and at least 20 ms.

Frames are drawn fast: the fixed parts (axes, ticks, ground) are rendered once, and each
frame restores that background and draws only the moving vectors and the title.  The file
is written atomically: to a temporary file in the same folder, then renamed.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path

import matplotlib
import numpy as np
from matplotlib.artist import Artist
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.image import FigureImage
from numpy.typing import NDArray
from PIL import Image

from mechloop.dynamics.analysis import DynamicResults
from mechloop.output.atomic import atomic_file, atomic_path
from mechloop.solve.results import Results
from mechloop.views.figure import ViewError
from mechloop.views.offline_html import make_offline
from mechloop.views.plan import (
    PlanScene,
    check_positions,
    draw_position,
    figure_size,
    plan_scene,
    position_title,
    resolve_limits,
    setup_axes,
)

#: File types an animation can be saved as.
ANIMATION_SUFFIXES = (".gif", ".mp4", ".html", ".htm")
#: Frame time (ms) of a model without time.
DEFAULT_INTERVAL_MS = 100.0
#: Shortest frame time (ms) taken from the model time: 50 frames per second.
MIN_INTERVAL_MS = 20.0
#: Shortest GIF frame delay (ms) that browsers play as written.
GIF_MIN_DELAY_MS = 20
#: Largest HTML page (MB) before matplotlib would start dropping frames.
HTML_LIMIT_MB = 512.0
#: Two poses are the same when no drawn point differs by more than this fraction of the
#: size of the drawing.
SAME_POSE_RTOL = 1e-7

Progress = Callable[[int, int], object]


def frame_interval(results: Results, positions: list[int], fps: float | None = None
                   ) -> float:
    """Frame time (ms): ``1000 / fps`` when given; else the mean model time step between
    ``positions`` (s → ms), at least :data:`MIN_INTERVAL_MS`; else (no model time, or one
    position) :data:`DEFAULT_INTERVAL_MS`."""
    if fps is not None:
        if not (isinstance(fps, int | float) and np.isfinite(fps) and fps > 0):
            raise ViewError(f"fps {fps!r} is not a positive number",
                            "give frames per second, e.g. fps=25, or leave it out to use "
                            "the model time")
        return 1000.0 / float(fps)
    if results.time is None or len(positions) < 2:
        return DEFAULT_INTERVAL_MS
    step = abs(float(np.mean(np.diff(results.time[positions])))) * 1000.0
    if not (np.isfinite(step) and step > 0):
        return DEFAULT_INTERVAL_MS
    return max(step, MIN_INTERVAL_MS)


def same_pose(scene: PlanScene, first: int, last: int) -> bool:
    """Whether positions ``first`` and ``last`` draw the same picture: every vector end
    (and, for dynamic results, every centre of mass) at the same place to
    :data:`SAME_POSE_RTOL` of the drawing's size, and the same ends known."""
    points = [*scene.tails.values(), *scene.heads.values()]
    if scene.dynamic is not None:
        points += [scene.to_display(c.z) for c in scene.dynamic.centers.values()]
    ends = np.array([[z[first], z[last]] for z in points], dtype=complex)
    known = np.isfinite(ends)
    if not known.any() or not np.array_equal(known[:, 0], known[:, 1]):
        return False
    both = known[:, 0]
    size = max(float(np.abs(ends[both]).max()), 1e-300)
    return bool(np.abs(ends[both, 0] - ends[both, 1]).max() <= SAME_POSE_RTOL * size)


def loop_frames(scene: PlanScene, positions: list[int]) -> list[int]:
    """The positions drawn as frames of a repeating loop: ``positions`` without its last
    one when that closes the cycle (the same pose as the first, e.g. 360° of a crank), so
    the loop does not show one pose twice in a row; unchanged for an open motion or two
    positions or fewer."""
    if len(positions) > 2 and same_pose(scene, positions[0], positions[-1]):
        return positions[:-1]
    return positions


def gif_delay(interval_ms: float) -> int:
    """The GIF frame delay (ms) for a frame time: rounded to the format's 10 ms, at least
    :data:`GIF_MIN_DELAY_MS`."""
    return max(GIF_MIN_DELAY_MS, 10 * round(interval_ms / 10.0))


def animate(results: Results | DynamicResults, path: str | os.PathLike[str], *,
            fps: float | None = None, positions: Iterable[int] | None = None,
            progress: Progress | None = None, dpi: int = 100, width: float = 6.4,
            numbers: bool = True, grid: bool = False, axes: bool = True,
            length_unit: str | None = None) -> Path:
    """Save the position plan at every position as an animation; returns the path.

    ``path``: ``.gif``, ``.mp4`` or ``.html``.  ``positions``: the frames (default every
    position ``0..N``; the last is left out when it closes the cycle, see
    :func:`loop_frames`).  ``fps``: frames per second instead of the model time (see the
    module notes for the frame time).  ``progress(done, total)`` is called after each
    frame (for a progress bar).  ``dpi`` and ``width`` (inches) set the frame size;
    ``numbers``, ``grid``, ``axes`` and ``length_unit`` are as in
    :func:`~mechloop.views.plan.plot_plan`.

    Raises :class:`ViewError` for an unsupported file type, a bad position or fps.
    """
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in ANIMATION_SUFFIXES:
        raise ViewError(f"{target}: cannot save an animation as '{suffix or 'no suffix'}'",
                        "use a file name ending in .gif, .mp4 or .html")
    scene = plan_scene(results, length_unit=length_unit)
    chosen = loop_frames(scene, check_positions(scene, positions))
    interval = frame_interval(scene.results, chosen, fps)
    stage = _Stage(scene, chosen[0], dpi=dpi, width=width, grid=grid, axes=axes,
                   numbers=numbers)
    frames = _counted((stage.render(p) for p in chosen), len(chosen), progress)
    if suffix == ".gif":
        _save_gif(frames, target, gif_delay(interval))
    elif suffix == ".mp4":
        _save_mp4(frames, stage.size, target, interval)
    else:
        _save_html(frames, stage.size, target, interval)
    return target


class _Stage:
    """The figure that draws the frames: a fixed scale over every position, a layout
    computed once and frozen (so frames do not shift), and a pixel size that is even (as
    H.264 needs).  The fixed parts are rendered once; :meth:`render` restores them and
    draws only one position's vectors and title."""

    def __init__(self, scene: PlanScene, first: int, *, dpi: int, width: float,
                 grid: bool, axes: bool, numbers: bool):
        self.scene, self.numbers = scene, numbers
        limits = resolve_limits(scene, None)
        w, h = figure_size(limits, width)
        self.size = (_even(w, dpi), _even(h, dpi))
        self.figure = Figure(figsize=(self.size[0] / dpi, self.size[1] / dpi), dpi=dpi,
                             layout="compressed")
        self.canvas = FigureCanvasAgg(self.figure)
        self.ax = self.figure.add_subplot()
        setup_axes(self.ax, scene, limits, grid=grid, axes=axes)
        drawn = draw_position(self.ax, scene, first, numbers=numbers)
        self.ax.set_title(position_title(scene, first), fontsize=9)
        self.canvas.draw()  # lays the figure out around a full frame
        self.figure.set_layout_engine("none")
        for artist in drawn:
            artist.remove()
        self.ax.title.set_animated(True)
        self.canvas.draw()
        self.background = self.canvas.copy_from_bbox(self.figure.bbox)

    def render(self, position: int) -> NDArray[np.uint8]:
        """The frame of ``position``: RGBA pixels, shape (height, width, 4)."""
        self.canvas.restore_region(self.background)
        drawn = draw_position(self.ax, self.scene, position, numbers=self.numbers)
        self.ax.set_title(position_title(self.scene, position), fontsize=9)
        for artist in sorted([*drawn, self.ax.title], key=Artist.get_zorder):
            self.ax.draw_artist(artist)
        pixels = np.array(self.canvas.buffer_rgba(), dtype=np.uint8)
        for artist in drawn:
            artist.remove()
        return pixels


def _even(inches: float, dpi: int) -> int:
    return max(2, 2 * round(inches * dpi / 2))


def _counted(frames: Iterator[NDArray[np.uint8]], total: int, progress: Progress | None
             ) -> Iterator[NDArray[np.uint8]]:
    """Pass the frames through, reporting ``progress(done, total)`` after each."""
    for done, frame in enumerate(frames, start=1):
        yield frame
        if progress is not None:
            progress(done, total)


def _save_gif(frames: Iterator[NDArray[np.uint8]], target: Path, delay_ms: int) -> None:
    """Frames written by Pillow with an exact delay (matplotlib's PillowWriter truncates
    ``1000 / fps`` and cannot hold a delay of whole 10 ms); each frame gets its own
    palette."""
    images = [Image.fromarray(frame[..., :3]).quantize(256, method=Image.Quantize.FASTOCTREE)
              for frame in frames]
    with atomic_file(target) as handle:
        images[0].save(handle, format="GIF", save_all=True, append_images=images[1:],
                       duration=delay_ms, loop=0)


def _player(size: tuple[int, int]) -> tuple[Figure, FigureImage]:
    """A figure that is nothing but one image of ``size`` pixels, for matplotlib's movie
    writers: each grabbed frame is the pixels put into it, unchanged."""
    figure = Figure(figsize=(size[0] / 100, size[1] / 100), dpi=100)
    FigureCanvasAgg(figure)
    image = figure.figimage(np.zeros((size[1], size[0], 4), np.uint8), origin="upper",
                            resize=False)
    return figure, image


def _save_mp4(frames: Iterator[NDArray[np.uint8]], size: tuple[int, int], target: Path,
              interval_ms: float) -> None:
    """H.264 by the ffmpeg that ``imageio-ffmpeg`` ships, at ``1000 / interval_ms`` fps."""
    import imageio_ffmpeg
    from matplotlib.animation import FFMpegWriter

    figure, image = _player(size)
    with matplotlib.rc_context({"animation.ffmpeg_path": imageio_ffmpeg.get_ffmpeg_exe()}):
        writer = FFMpegWriter(fps=1000.0 / interval_ms, codec="h264",
                              extra_args=["-f", "mp4"])  # the staged path has no suffix
        with atomic_path(target) as staged, writer.saving(figure, staged, figure.dpi):
            for frame in frames:
                image.set_data(frame)
                writer.grab_frame()


def _save_html(frames: Iterator[NDArray[np.uint8]], size: tuple[int, int], target: Path,
               interval_ms: float) -> None:
    """A self-contained page that plays the frames (PNG embedded), as ``to_jshtml``."""
    from matplotlib.animation import HTMLWriter

    figure, image = _player(size)
    writer = HTMLWriter(fps=1000.0 / interval_ms, embed_frames=True, default_mode="loop",
                        embed_limit=HTML_LIMIT_MB)
    with atomic_path(target) as staged:
        with writer.saving(figure, target, figure.dpi):
            writer.outfile = Path(staged)  # the page is written there at the end (frames embedded)
            for frame in frames:
                image.set_data(frame)
                writer.grab_frame()
        make_offline(Path(staged))  # its buttons without Font Awesome's CDN


def write_frames(frames: Iterator[NDArray[np.uint8]], size: tuple[int, int], target: Path,
                 interval_ms: float) -> None:
    """Write RGBA frames of ``size`` pixels (even, for H.264) to ``target`` by its suffix
    (``.gif``, ``.mp4``, ``.html``), one every ``interval_ms``, as :func:`animate` does
    (used by the 3-D plans of :mod:`mechloop.views.spatial_animation`)."""
    suffix = target.suffix.lower()
    if suffix == ".gif":
        _save_gif(frames, target, gif_delay(interval_ms))
    elif suffix == ".mp4":
        _save_mp4(frames, size, target, interval_ms)
    else:
        _save_html(frames, size, target, interval_ms)
