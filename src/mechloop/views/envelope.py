"""The family of curves a point draws over an intermediate argument, and its envelope
(e.g. the roller circles of a cam and the cam profile they touch)."""

from __future__ import annotations

import textwrap

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from mechloop.solve.intermediate import IntermediateResults
from mechloop.views.display import DEFAULT_DISPLAY, Display
from mechloop.views.figure import ViewError, new_figure
from mechloop.views.russian import keep_names, model_names

#: Family curves drawn at most (every k-th position past this many).
MAX_FAMILY = 36
#: Colours of the envelope's branches −1 and +1.
BRANCH_COLOURS = {-1: "tab:red", 1: "tab:blue"}


def plot_envelope(results: IntermediateResults, name: str | None = None, *,
                  every: int | None = None, ax: Axes | None = None,
                  display: Display = DEFAULT_DISPLAY) -> Figure:
    """Draw the curves of envelope ``name``'s point over the intermediate argument (thin,
    grey; one per ``every``-th position, by default at most :data:`MAX_FAMILY` of them)
    and the envelope's branches through every position (−1 red, +1 blue; a branch with
    no single root at a position breaks its line there).

    ``name``: the envelope (default: the model's only one).  Returns the figure.
    """
    if not results.envelopes:
        raise ViewError("the model has no envelopes", "add one: envelopes: [{name: "
                        "profile, vectors: [...]}]")
    if name is None:
        if len(results.envelopes) > 1:
            raise ViewError("the model has several envelopes",
                            f"name one of {', '.join(results.envelopes)}")
        name = next(iter(results.envelopes))
    if name not in results.envelopes:
        raise ViewError(f"no envelope {name!r}", f"use one of {', '.join(results.envelopes)}")
    env = results.envelopes[name]
    p = results.broken.shape[0]
    step = max(1, int(every) if every else -(-p // MAX_FAMILY))
    if ax is None:
        figure = new_figure(7.0, 7.0)
        ax = figure.add_subplot()
    else:
        figure = ax.figure
    x, y = results.point(env.vectors)
    unit = display.label("length")
    for k in range(0, p, step):
        ax.plot(display.convert(x[k], "length"), display.convert(y[k], "length"),
                color="0.6", linewidth=0.6,
                label="curves over the sweep" if k == 0 else None)
    for branch in (-1, 1):
        bx, by = env.curve(branch)
        if np.isfinite(bx).any():
            ax.plot(display.convert(bx, "length"), display.convert(by, "length"),
                    color=BRANCH_COLOURS[branch], linewidth=1.8,
                    label=f"envelope {name}, branch {branch:+d}")
    ax.plot([0], [0], marker="+", color="black", markersize=10, linestyle="none",
            label="origin")
    ax.set_aspect("equal")
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    ax.set_title(textwrap.fill(f"{results.model.name or 'model'}: envelope {name} over "
                               f"argument {results.argument}", 60))
    ax.grid(True, linewidth=0.3)
    ax.legend(loc="best", fontsize="small")
    return keep_names(figure, model_names(results.model))
