"""The structure and parametric formula of a vector model, drawn (KDAM's "structure of the
vector model" panel as a picture).

One box per contour, in a solving order that keeps chains of contours together, laid out
as a snake (left to right, then right to left on the next row) so that a chain is a
chain of short arrows.  Each box holds the contour's vectors, structure formula and
parametric formula ``arguments → functions · module, variant``; an arrow runs from
contour A to contour B for every link by which B reads a function of A — labelled with the
linked parameters when the boxes are neighbours (the box's ``links:`` line always names
them).  The text is that of
:func:`mechloop.model.formula.describe_structure`.
"""

from __future__ import annotations

import math
import textwrap

from matplotlib.figure import Figure

from mechloop.model.check import require_valid
from mechloop.model.formula import describe_structure, parametric_formula, role_text, symbol
from mechloop.model.schema import Model
from mechloop.model.structure import ContourInfo, Structure
from mechloop.views.figure import new_figure
from mechloop.views.russian import keep_names, model_names

#: Boxes per row of the drawing (more contours wrap to further rows).
BOXES_PER_ROW = 4
#: Characters per line inside a box before the text wraps.
BOX_WIDTH_CHARS = 34


def box_text(model: Model, info: ContourInfo) -> str:
    """The text of a contour's box: title, vectors, structure and parametric formulas."""
    name = model.contours[info.number - 1].name
    lines = [f"contour {info.number}" + (f" — {name}" if name else ""),
             f"vectors {', '.join(map(str, info.vectors))}",
             f"n=2, m={len(info.vectors)}"]
    links = [f"{symbol(p)} = {role_text(model, p)}" for p in info.links]
    if links:
        lines.append("links: " + ", ".join(links))
    # no line break inside "· Pl3, V=1" (textwrap breaks at ASCII spaces only)
    lines.append(parametric_formula(model, info).replace(" · ", "\u00a0·\u00a0")
                 .replace(", V=", ",\u00a0V="))
    wrapped = [textwrap.fill(line, BOX_WIDTH_CHARS, subsequent_indent="  ") for line in lines]
    return "\n".join(wrapped)


def _link_labels(structure: Structure, info: ContourInfo) -> dict[int, list[str]]:
    """Earlier contour -> the parameters of ``info`` linked to its functions."""
    labels: dict[int, list[str]] = {}
    for name in info.links:
        chain = structure.links.get(name)
        if chain is not None and chain.root in structure.owner:
            source = structure.owner[chain.root]
            if source != info.number:
                labels.setdefault(source, []).append(f"{symbol(chain.root)} → {symbol(name)}")
    return labels


def chain_order(structure: Structure) -> list[ContourInfo]:
    """The contours in a solving order (each after the contours it needs) that puts a
    contour right after the most recently placed contour it needs, so chains stay
    together; ties follow :attr:`Structure.order`."""
    remaining = structure.ordered()
    placed: list[ContourInfo] = []
    done: set[int] = set()
    block_of = {c.number: c.block for c in remaining}
    while remaining:  # a contour waits for the contours it needs outside its own block
        ready = [c for c in remaining
                 if {n for n in c.needs if block_of[n] != c.block} <= done]
        pick = ready[0]
        for previous in reversed(placed):
            dependents = [c for c in ready if previous.number in c.needs]
            if dependents:
                pick = dependents[0]
                break
        placed.append(pick)
        done.add(pick.number)
        remaining.remove(pick)
    return placed


def plot_structure(model: Model) -> Figure:
    """The structure and parametric formula of every contour of ``model`` as a figure.

    Raises :class:`~mechloop.errors.ModelError` for an invalid model (as
    :func:`~mechloop.model.formula.describe_structure` does).
    """
    structure = require_valid(model)
    ordered = chain_order(structure)
    count = len(ordered)
    columns = max(1, min(BOXES_PER_ROW, count))
    rows = max(1, math.ceil(count / columns))
    width = 3.6 * columns + 0.6
    header = "\n".join(textwrap.fill(line, int(width * 11), subsequent_indent="    ")
                       for line in describe_structure(model).split("\n\n")[0].splitlines())
    header_lines = header.count("\n") + 1
    figure = keep_names(new_figure(width, 1.8 * rows + 0.2 * header_lines + 0.4),
                        model_names(model))
    ax = figure.add_subplot()
    ax.set_xlim(-0.5, columns - 0.5)
    ax.set_ylim(rows - 0.5, -0.5)
    ax.axis("off")
    figure.suptitle(header, fontsize=9, ha="left", x=0.02, fontfamily="monospace")

    boxes = {}
    place = {}
    for i, info in enumerate(ordered):
        row = i // columns
        col = i % columns if row % 2 == 0 else columns - 1 - i % columns
        place[info.number] = (col, row)
        boxes[info.number] = ax.text(
            col, row, box_text(model, info), ha="center", va="center", fontsize=8,
            bbox={"boxstyle": "round,pad=0.5", "facecolor": "#eef3fb", "edgecolor": "#3b5b92"})
    if count == 0:
        ax.text(0, 0, "no contours", ha="center", va="center")
    for info in ordered:
        for source, labels in _link_labels(structure, info).items():
            _arrow(ax, boxes[source], boxes[info.number], place[source], place[info.number],
                   ", ".join(labels))
    return figure


def _arrow(ax, start, end, a: tuple[int, int], b: tuple[int, int], label: str) -> None:
    """An arrow from box ``start`` to box ``end`` (grid places ``a``, ``b``), labelled."""
    adjacent = abs(a[0] - b[0]) + abs(a[1] - b[1]) == 1
    ax.annotate("", xy=(0.5, 0.5), xycoords=end, xytext=(0.5, 0.5), textcoords=start,
                arrowprops={"arrowstyle": "-|>", "color": "#b03a2e", "shrinkA": 2,
                            "shrinkB": 2, "patchA": start.get_bbox_patch(),
                            "patchB": end.get_bbox_patch(),
                            "connectionstyle": f"arc3,rad={0.0 if adjacent else 0.3}"})
    if not adjacent:
        return
    mid_x, mid_y = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    if a[1] == b[1]:  # along a row: the label above the arrow
        place, align = (mid_x, mid_y - 0.08), "center"
    else:  # down a column: the label beside the arrow
        place, align = (mid_x + 0.04, mid_y), "left"
    ax.text(*place, label, fontsize=7, color="#b03a2e", ha=align, va="bottom",
            bbox={"boxstyle": "round,pad=0.2", "facecolor": "white", "edgecolor": "none",
                  "alpha": 0.8})
