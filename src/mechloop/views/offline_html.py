"""The HTML player of an animation without the internet: matplotlib's ``HTMLWriter`` page
links Font Awesome from a CDN for the icons of its buttons (no icons offline, and a request
to another site when the page opens); here the link is removed and each icon is a Unicode
character, so the page needs nothing but itself."""

from __future__ import annotations

import re
from pathlib import Path

#: The Font Awesome icons of matplotlib's player, as characters (HTML entities).
ICONS = {"fa-minus": "&minus;", "fa-plus": "+", "fa-fast-backward": "&#x23EE;",
         "fa-step-backward": "|&#x25C0;", "fa-play fa-flip-horizontal": "&#x25C0;",
         "fa-pause": "&#x23F8;", "fa-play": "&#x25B6;", "fa-step-forward": "&#x25B6;|",
         "fa-fast-forward": "&#x23ED;"}
_LINK = re.compile(rb'<link rel="stylesheet"\s+href="https?://[^"]*font-awesome[^"]*">\s*')
_ICON = re.compile(rb'<i class="fa ([^"]+)"></i>')


def offline(page: bytes) -> bytes:
    """``page`` (the player's HTML) with no external link and its icons as characters;
    an icon not known keeps its name in brackets (still a visible button)."""
    def icon(match: re.Match[bytes]) -> bytes:
        name = match.group(1).decode("ascii", "replace")
        return ICONS.get(name, f"[{name.removeprefix('fa-')}]").encode("ascii")

    return _ICON.sub(icon, _LINK.sub(b"", page))


def make_offline(path: Path) -> None:
    """Rewrite the player's page at ``path`` by :func:`offline` (in place)."""
    path.write_bytes(offline(path.read_bytes()))
