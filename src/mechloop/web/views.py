"""The other plot kinds of the page: the views of ``mechloop plot`` (parameters,
combination, increment, angle between vectors, reduced characteristics, balancing load,
reactions, hodograph, energy summary, machine motion) with the same functions and options,
in the page's language — drawn by the server as an SVG or PNG file (where the x axis is
the position number, the current position marked by a vertical line, gid ``'position'``),
or as the data of the page's own interactive plot (:func:`view_data`), read back from the
same figure (:mod:`mechloop.web.figure_data`) so it is what the file shows.
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import Any

from mechloop.errors import ModelError
from mechloop.web.documents import read_model
from mechloop.web.safety import WebError

#: The kinds the page offers, and whether they need a model with bodies.
VIEW_KINDS = {"parameters": False, "combination": False, "increment": False, "angle": False,
              "reduced": True, "balancing": True, "reactions": True,
              "hodograph": True, "summary": True, "motion": True}
#: The kinds drawn against the position number (the current position is marked there).
MARKED = ("parameters", "combination", "increment", "angle", "reduced", "balancing",
          "reactions")
#: What the x axis of a kind is, for :func:`~mechloop.web.figure_data.figure_data`.
OVER = {**dict.fromkeys(MARKED, "position"), "hodograph": "xy", "summary": "table",
        "motion": "cycle"}
#: The files a view is drawn to.
VIEW_TYPES = {"svg": "image/svg+xml", "png": "image/png"}


def view_figure(model: Any, kind: str, *, names: list[str], joint: str | None,
                position: int, op: str = "ratio", mark: bool = True) -> tuple[Any, int]:
    """The matplotlib figure of view ``kind`` of a loaded model, as ``mechloop plot``
    draws it (display units of the model), with the current ``position`` marked (``mark``;
    also the reference of an increment), and the number of positions."""
    from mechloop.dynamics.analysis import solve_dynamics
    from mechloop.output.display import plot_display, resolve
    from mechloop.solve.kinematics import solve
    from mechloop.views import curves, dynamics
    from mechloop.views.display import DEFAULT_DISPLAY

    if kind not in VIEW_KINDS:
        raise WebError(f"no view {kind!r}", f"use one of {', '.join(VIEW_KINDS)}")
    if VIEW_KINDS[kind] and not model.bodies:
        raise WebError(f"'{kind}' needs a model with bodies",
                       "add bodies (see examples/crank_slider_dynamics.yaml)")
    display = plot_display(resolve(model.display)) or DEFAULT_DISPLAY
    spatial = any(c.spatial for c in model.contours)
    if spatial and VIEW_KINDS[kind]:  # issue 17: the dynamics of a spatial model
        figure, count = _spatial_view(model, kind, names, joint, position, display)
        if kind in MARKED and mark:
            for ax in figure.axes:
                ax.axvline(min(max(int(position), 0), count - 1), color="#d62728",
                           linewidth=1.0, linestyle=":", gid="position")
        return figure, count
    results = solve_dynamics(model) if model.bodies and not spatial else solve(model)
    count = (results.kinematics if model.bodies and not spatial else results
             ).positions.size
    position = min(max(int(position), 0), count - 1)
    if kind == "parameters":
        if not names:
            raise WebError("the parameters plot needs a name", "give names, e.g. r3,dr3")
        figure = curves.plot_parameters(results, names, display=display)
    elif kind == "combination":
        if len(names) != 2:
            raise WebError("a combination needs two names", "give two names, e.g. r3,r1")
        b: str | float = names[1]
        with contextlib.suppress(ValueError):
            b = float(names[1])
        figure = curves.plot_combination(results, names[0], b, op, display=display)
    elif kind == "increment":
        if len(names) != 1:
            raise WebError("the increment needs one parameter", "give one name, e.g. r3")
        figure = curves.plot_increment(results, names[0], position, display=display)
    elif kind == "angle":
        if len(names) != 2:
            raise WebError("the angle between two vectors needs two vector numbers",
                           "give two numbers, e.g. 2,3")
        figure = curves.plot_angle_between(results, *names, display=display)
    elif kind == "reduced":
        figure = dynamics.plot_reduced(results, display=display)
    elif kind == "balancing":
        figure = dynamics.plot_balancing(results, display=display)
    elif kind == "reactions":
        figure = dynamics.plot_reactions(results, names or None, display=display)
    elif kind == "hodograph":
        if not joint:
            raise WebError("a hodograph needs a joint",
                           f"give one of {', '.join(results.forces.reactions)}")
        figure = dynamics.plot_hodograph(results, joint, display=display)
    elif kind == "summary":
        figure = dynamics.plot_summary(results, display=display)
    else:
        figure = dynamics.plot_machine_motion(results, display=display)
    if kind in MARKED and mark:
        for ax in figure.axes:
            ax.axvline(position, color="#d62728", linewidth=1.0, linestyle=":",
                       gid="position")
    return figure, count


def _spatial_view(model: Any, kind: str, names: list[str], joint: str | None,
                  position: int, display: Any) -> tuple[Any, int]:
    """View ``kind`` of a model with spatial contours and bodies, as ``mechloop plot``
    draws it (:func:`mechloop.views.spatial_dynamics.plot_spatial_dynamics`), and the
    number of positions; a view it does not draw is a :class:`WebError`."""
    from mechloop.spatial.dynamics import solve_spatial_dynamics
    from mechloop.views.figure import ViewError
    from mechloop.views.spatial_dynamics import plot_spatial_dynamics

    dyn = solve_spatial_dynamics(model)
    count = dyn.kinematics.positions.size
    position = min(max(int(position), 0), count - 1)
    try:
        figure = plot_spatial_dynamics(dyn, kind, display=display, names=names,
                                       joint=joint, position=position)
    except ViewError as exc:
        raise WebError(exc.message, exc.hint) from None
    return figure, count


def view_svg(text: str, path: Path, root: Path, kind: str, names: list[str],
             joint: str | None, position: int, lang: str, op: str = "ratio",
             fmt: str = "svg") -> bytes:
    """The file (``fmt``: svg or png) of :func:`view_figure` for the model in ``text``
    (run in a child)."""
    import tempfile

    from mechloop.views.figure import save_figure
    from mechloop.views.russian import translate

    document = read_model(text, path, root)
    try:
        figure, _ = view_figure(document.model, kind, names=names, joint=joint,
                                position=position, op=op)
    except ModelError as exc:
        raise document.locate(exc) from None
    with tempfile.TemporaryDirectory(prefix="mechloop-web-") as folder:
        target = Path(folder) / f"view.{fmt}"
        save_figure(translate(figure, lang), target)
        return target.read_bytes()


def view_data(text: str, path: Path, root: Path, kind: str, names: list[str],
              joint: str | None, position: int, lang: str, op: str = "ratio") -> bytes:
    """The data of :func:`view_figure` for the page's interactive plot, as JSON bytes
    (run in a child): ``{kind, count, reference, panels, tables}`` — the panels and
    tables of :func:`~mechloop.web.figure_data.figure_data`, read back from the figure
    the SVG shows (without its position mark), the number of positions and ``reference``,
    the position an increment is taken from (``position``; null for other kinds)."""
    import orjson

    from mechloop.views.russian import translate
    from mechloop.web.figure_data import figure_data

    document = read_model(text, path, root)
    try:
        figure, count = view_figure(document.model, kind, names=names, joint=joint,
                                    position=position, op=op, mark=False)
    except ModelError as exc:
        raise document.locate(exc) from None
    data = figure_data(translate(figure, lang), count=count, over=OVER[kind], lang=lang)
    data.update(kind=kind, count=count, reference=position if kind == "increment" else None)
    return orjson.dumps(data, option=orjson.OPT_SERIALIZE_NUMPY)
