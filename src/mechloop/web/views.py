"""The other plot kinds of the page, drawn by the server as SVG: the views of
``mechloop plot`` (increment, angle between vectors, reduced characteristics, balancing
load, reactions, hodograph, energy summary, machine motion) with the same functions and
options, in the page's language, and — where the x axis is the position number — the
current position marked by a vertical line (gid ``'position'``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from mechloop.errors import ModelError
from mechloop.web.documents import read_model
from mechloop.web.safety import WebError

#: The kinds the page offers, and whether they need a model with bodies.
VIEW_KINDS = {"increment": False, "angle": False, "reduced": True, "balancing": True,
              "reactions": True, "hodograph": True, "summary": True, "motion": True}
#: The kinds drawn against the position number (the current position is marked there).
MARKED = ("increment", "angle", "reduced", "balancing", "reactions")


def view_figure(model: Any, kind: str, *, names: list[str], joint: str | None,
                position: int) -> Any:
    """The matplotlib figure of view ``kind`` of a loaded model, as ``mechloop plot``
    draws it (display units of the model), with the current ``position`` marked."""
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
    results = solve_dynamics(model) if model.bodies else solve(model)
    count = len(results.kinematics.time if model.bodies else results.time)
    position = min(max(int(position), 0), count - 1)
    if kind == "increment":
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
    if kind in MARKED:
        for ax in figure.axes:
            ax.axvline(position, color="#d62728", linewidth=1.0, linestyle=":",
                       gid="position")
    return figure


def view_svg(text: str, path: Path, root: Path, kind: str, names: list[str],
             joint: str | None, position: int, lang: str) -> bytes:
    """The SVG of :func:`view_figure` for the model in ``text`` (run in a child)."""
    import tempfile

    from mechloop.views.figure import save_figure
    from mechloop.views.russian import translate

    document = read_model(text, path, root)
    try:
        figure = view_figure(document.model, kind, names=names, joint=joint,
                             position=position)
    except ModelError as exc:
        raise document.locate(exc) from None
    with tempfile.TemporaryDirectory(prefix="mechloop-web-") as folder:
        target = Path(folder) / "view.svg"
        save_figure(translate(figure, lang), target)
        return target.read_bytes()
