"""Russian of the messages and fixes of the web application (src/mechloop/web/)."""

from __future__ import annotations

from mechloop.messages.ru.base import Entry

ENTRIES: list[Entry] = [
]
