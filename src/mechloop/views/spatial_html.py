"""The interactive 3-D view of a spatial model as one self-contained HTML file (issue 17):
``mechloop animate SPATIAL_MODEL -o cycle.html``.

The page holds the viewer of the web application (``web/static/view3d.js``, with the
strings of ``web/static/i18n.js`` and the numbers of ``numbers.js``) and the solved
positions as JSON, every script and style inlined: it works offline, from a file, without
the server.  The view turns with the mouse (or a finger), zooms with the wheel, goes back
to the viewing angles it was written with (``elev``, ``azim``: those of
:mod:`mechloop.views.spatial_plan`, so the first view is the static figure's 3-D view in an
orthographic projection) and shows the three projections; a position slider, play/pause
(the model time, as the other animations) and frame steps; the chain breaks are said where
they occur.

:func:`view_data` is the JSON both the file and the web page (``mechloop serve``) give the
viewer: every vector's tail and head ``{x, y, z}`` over the positions in display length
units, ``None`` where the chain breaks.
"""

from __future__ import annotations

import html
import json
import math
import os
from collections.abc import Iterable
from importlib.resources import files
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from mechloop.messages import message_language
from mechloop.output.atomic import atomic_write_text
from mechloop.report.words import reason
from mechloop.solve.results import Results
from mechloop.views.animation import Progress, frame_interval
from mechloop.views.figure import ViewError
from mechloop.views.spatial_animation import same_pose
from mechloop.views.spatial_plan import (
    AZIM,
    ELEV,
    SpatialScene,
    check_positions,
    check_view,
    moving_heads,
    spatial_scene,
)

#: Coordinates are written rounded to this fraction of the drawing's size (a step of a
#: power of ten): far below a pixel at any zoom, and short numbers in the file.
ROUND_RTOL = 1e-8


def _hex(color: tuple[float, float, float, float]) -> str:
    return "#" + "".join(f"{round(255 * c):02x}" for c in color[:3])


def coordinate_decimals(scene: SpatialScene) -> int:
    """The decimals the coordinates are rounded to: a step of a power of ten no larger
    than :data:`ROUND_RTOL` times the largest coordinate (display units)."""
    size = max((float(np.nanmax(np.abs(p), initial=0.0))
                for p in (*scene.tails.values(), *scene.heads.values())), default=0.0)
    size = max(size, float(np.abs(scene.ground).max(initial=0.0)), 1e-300)
    return -math.floor(math.log10(size * ROUND_RTOL))


def _column(values: NDArray[np.float64], decimals: int | None) -> list[float | None]:
    """``values`` as a JSON list: rounded to ``decimals`` (every digit when ``None``),
    ``None`` where unknown."""
    shown = np.round(values, decimals) if decimals is not None else values
    return [float(v) if math.isfinite(v) else None for v in shown.tolist()]


def _end(points: NDArray[np.float64], decimals: int | None) -> dict[str, list[float | None]]:
    return {axis: _column(points[i], decimals) for i, axis in enumerate("xyz")}


def view_data(scene: SpatialScene, *, elev: float = ELEV, azim: float = AZIM,
              decimals: int | None = None) -> dict[str, Any]:
    """What the 3-D viewer draws: ``unit``, ``elev``, ``azim`` (deg), ``vectors`` (each
    ``number``, ``color``, ``name``, ``tail`` and ``head`` ``{x, y, z}`` lists over the
    positions, ``None`` where the chain breaks), ``ground`` ``{x, y, z}`` (the fixed
    points), ``broken`` and ``breaks`` (contour, module, reason and its Russian
    ``reason_ru``, positions), ``time`` (s,
    or ``None``).  ``decimals``: coordinates rounded so (every digit when ``None``)."""
    check_view("3d", elev, azim)
    results = scene.results
    vectors = []
    for n in scene.vectors():
        name = results.model.vectors[n].name
        vectors.append({"number": n, "color": _hex(scene.color(n)), "name": name or "",
                        "tail": _end(scene.tails[n], decimals),
                        "head": _end(scene.heads[n], decimals)})
    breaks = [{"contour": b.contour, "module": b.module, "reason": b.reason,
               "reason_ru": reason(b.reason, "ru"),  # the page's words in Russian
               "positions": [int(p) for p in b.positions]} for b in results.breaks]
    time = None if results.time is None else _column(np.asarray(results.time, float), None)
    return {"unit": scene.unit, "elev": float(elev), "azim": float(azim),
            "vectors": vectors, "ground": _end(scene.ground.T, decimals),
            "broken": [bool(b) for b in np.asarray(results.broken)], "breaks": breaks,
            "time": time}


def _static(name: str) -> str:
    return (files("mechloop.web") / "static" / name).read_text(encoding="utf-8")


def _script(code: str) -> str:
    """JavaScript safe inside ``<script>``: no ``</`` closes the element early."""
    return code.replace("</", "<\\/")


_STYLE = """
body { font: 14px system-ui, sans-serif; margin: 12px 18px; color: #222; }
h1 { font-size: 17px; margin: 0 0 8px; }
.view3d-bar { display: flex; gap: 4px; align-items: center; margin-bottom: 4px; }
.view3d-bar button, .controls button { font: inherit; padding: 2px 9px; }
.view3d-angles { margin-left: 10px; color: #555; font-size: 12px; }
.view3d-svg { border: 1px solid #ccc; background: #fff; cursor: grab; display: block; }
.view3d-help { color: #666; font-size: 12px; margin: 3px 0; }
.controls { display: flex; gap: 6px; align-items: center; flex-wrap: wrap; margin: 6px 0; }
#slider { width: 320px; }
.break { color: #d62728; }
.languages { margin-left: auto; }
"""


def page(data: dict[str, Any], *, title: str, lang: str = "en") -> str:
    """The self-contained HTML page of the viewer over ``data`` (:func:`view_data` with
    ``frames``, ``interval``, ``traced``)."""
    payload = _script(json.dumps(data, ensure_ascii=False, allow_nan=False,
                                 separators=(",", ":")))
    return f"""<!DOCTYPE html>
<html lang="{lang}">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{html.escape(title)}</title>
<style>{_STYLE}</style>
</head>
<body>
<div class="controls"><h1>{html.escape(title)}</h1>
  <span class="languages"><button id="lang-en" class="lang" data-lang="en">EN</button>
  <button id="lang-ru" class="lang" data-lang="ru">RU</button></span></div>
<div id="view"></div>
<div class="controls">
  <button id="step-back" data-i18n-title="stepBack">|&#x25C0;</button>
  <button id="play" data-i18n="play">Play</button>
  <button id="step-forward" data-i18n-title="stepForward">&#x25B6;|</button>
  <input id="slider" type="range" min="0" max="0" value="0">
  <span id="position-label"></span>
</div>
<div class="controls">
  <label><input id="overlay" type="checkbox"> <span data-i18n="overlay">all positions</span></label>
  <label><input id="traces" type="checkbox">
    <span id="traces-label">trajectories</span></label>
</div>
<p id="break-note" class="break" hidden></p>
<script>{_script(_static("i18n.js"))}</script>
<script>{_script(_static("numbers.js"))}</script>
<script>{_script(_static("view3d.js"))}</script>
<script>
"use strict";
const DATA = {payload};
LANG = "{lang}";
applyWords();
const VIEW = view3dPlayer(document.getElementById("view"), DATA);
for (const button of document.querySelectorAll("button.lang")) {{
  button.addEventListener("click", () => {{
    LANG = button.dataset.lang;
    applyWords();
    VIEW.words();
    window.mechloopPlayer.show(VIEW.position);
  }});
}}
</script>
</body>
</html>
"""


def write_spatial_html(results: Results, path: str | os.PathLike[str], *,
                       fps: float | None = None, positions: Iterable[int] | None = None,
                       elev: float = ELEV, azim: float = AZIM,
                       length_unit: str | None = None, lang: str | None = None,
                       progress: Progress | None = None) -> Path:
    """Write the interactive 3-D view of the solved spatial model ``results`` as one
    self-contained HTML file; returns the path.

    Every position is in the file (the slider reaches each); ``positions`` are the
    frames played in a loop (default every position, the last left out when it closes the
    cycle), one every model time step (``fps`` overrides, as
    :func:`mechloop.views.animation.animate`).  ``elev``, ``azim`` (deg): the first view
    (its "3-D" button goes back to it).  ``lang``: the page's language, ``en`` or ``ru``
    (default ``MECHLOOP_LANG``, else English; the page switches).  ``progress(done,
    total)`` is called once, with the number of frames, when the file is written.
    """
    target = Path(path)
    scene = spatial_scene(results, length_unit=length_unit)
    chosen = check_positions(scene, positions)
    if len(chosen) > 2 and same_pose(scene, chosen[0], chosen[-1]):
        chosen = chosen[:-1]
    lang = message_language() if lang is None else lang
    if lang not in ("en", "ru"):
        raise ViewError(f"no page language {lang!r}", "use en or ru")
    data = view_data(scene, elev=elev, azim=azim, decimals=coordinate_decimals(scene))
    data["frames"] = chosen
    data["interval"] = frame_interval(scene.results, chosen, fps)
    data["traced"] = [f"head:{n}" for n in moving_heads(scene)]
    atomic_write_text(target, page(data, title=results.model.name or "mechloop",
                                   lang=lang))
    if progress is not None:
        progress(len(chosen), len(chosen))
    return target
