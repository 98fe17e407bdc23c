"""The fonts of the typeset report and what they can print.

The PDF is set in matplotlib's own font files (always installed with it): STIXGeneral, a
Times-like face with Latin, Cyrillic, Greek and the mathematical signs, for the text;
DejaVu Sans Mono for formulas; DejaVu Sans after each of them for any sign the first one
lacks. Typst gets only these folders (no system fonts, no fallback to other fonts), so the
same characters print the same everywhere, and :func:`missing_glyphs` can tell before
typesetting which characters no font of a role has (Typst itself prints them as empty
boxes without a word).
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import matplotlib

#: The folder of matplotlib's TrueType fonts, given to Typst as its only font path.
FONT_DIR = Path(matplotlib.get_data_path()) / "fonts" / "ttf"

#: Font families of each role, in Typst's order of fallback, and their files.
FAMILIES = {
    "text": ("STIXGeneral", "DejaVu Sans"),
    "mono": ("DejaVu Sans Mono", "DejaVu Sans"),
}
_FILES = {
    ("text", False): ("STIXGeneral.ttf", "DejaVuSans.ttf"),
    ("text", True): ("STIXGeneralBol.ttf", "DejaVuSans-Bold.ttf"),
    ("mono", False): ("DejaVuSansMono.ttf", "DejaVuSans.ttf"),
    ("mono", True): ("DejaVuSansMono-Bold.ttf", "DejaVuSans-Bold.ttf"),
}


@cache
def _font(name: str):
    """(character map, advance widths in em) of the font file ``name``."""
    from fontTools.ttLib import TTFont

    with TTFont(FONT_DIR / name, lazy=True) as font:  # closed: read what is kept first
        cmap = dict(font.getBestCmap())
        em = font["head"].unitsPerEm
        metrics = font["hmtx"].metrics
        return cmap, {code: metrics[glyph][0] / em for code, glyph in cmap.items()}


def _fonts(role: str, bold: bool):
    return [_font(name) for name in _FILES[role, bold]]


def missing_glyphs(text: str, *, role: str = "text", bold: bool = False) -> set[str]:
    """The characters of ``text`` that no font of ``role`` ('text' or 'mono') in the
    weight has (white space and zero-width spaces aside)."""
    fonts = _fonts(role, bold)
    return {c for c in set(text) if not c.isspace() and c != "\u200b"
            and not any(ord(c) in cmap for cmap, _ in fonts)}


def text_width(text: str, *, bold: bool = False) -> float:
    """The width of ``text`` on one line in the text font, em (a missing sign counts as
    1 em)."""
    fonts = _fonts("text", bold)
    total = 0.0
    for c in text:
        code = ord(c)
        total += next((widths[code] for cmap, widths in fonts if code in cmap), 1.0)
    return total
