"""Figures: creation without pyplot's global state, and atomic saving by file type."""

from __future__ import annotations

import os
from pathlib import Path

from matplotlib.figure import Figure

from mechloop.errors import HintedError

#: File types a figure can be saved as.
FIGURE_SUFFIXES = (".png", ".svg", ".pdf")


class ViewError(HintedError):
    """A view cannot be drawn as asked (an unknown parameter, an unsupported file type)."""


def new_figure(width: float = 8.0, height: float = 6.0) -> Figure:
    """A figure that belongs to no pyplot window (safe headless and in threads)."""
    return Figure(figsize=(width, height), layout="constrained")


def save_figure(figure: Figure, path: str | os.PathLike[str], *, dpi: int = 150) -> Path:
    """Write ``figure`` as PNG, SVG or PDF (by the suffix of ``path``), atomically."""
    from mechloop.output.atomic import atomic_file
    from mechloop.views.save_once import save_once

    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in FIGURE_SUFFIXES:
        raise ViewError(f"{target}: cannot save a figure as '{suffix or 'no suffix'}'",
                        "use a file name ending in .png, .svg or .pdf")
    with atomic_file(target) as handle:
        save_once(figure, handle, format=suffix[1:], dpi=dpi)
    return target
