"""A report figure drawn as a vector image for the typeset PDF.

The figure is saved as PDF (matplotlib's own fonts as Type 3 fonts with their Unicode
map): Typst embeds a PDF image as vector graphics and keeps its texts as text, so the
report's text layer holds the figures' words too (an SVG image's texts become outlines).
Saving PDF takes about as long as SVG and less than a PNG at print resolution.

Saved with one draw (:func:`mechloop.views.save_once.save_once`).
"""

from __future__ import annotations

import io

from mechloop.report.document import FigureItem
from mechloop.views.save_once import save_once

#: Metadata left out of each figure's PDF (the report has its own).
_NO_METADATA = {"Creator": None, "Producer": None, "CreationDate": None}


def figure_pdf(item: FigureItem) -> tuple[bytes, float, float]:
    """The figure of ``item`` as PDF bytes, with its width and height, inches."""
    figure = item.draw()
    try:
        width, height = figure.get_size_inches()
        buffer = io.BytesIO()
        save_once(figure, buffer, format="pdf", metadata=_NO_METADATA)
    finally:
        if figure.canvas.manager is not None:  # drawn through pyplot: release it
            import matplotlib.pyplot as plt

            plt.close(figure)
    return buffer.getvalue(), float(width), float(height)
