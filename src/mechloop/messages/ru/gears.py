"""Russian of the messages and fixes of gears and cams (src/mechloop/gears/, cams/)."""

from __future__ import annotations

from mechloop.messages.ru.base import Entry

ENTRIES: list[Entry] = [
]
