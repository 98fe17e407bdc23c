"""Russian of the messages and fixes of dynamics (src/mechloop/dynamics/)."""

from __future__ import annotations

from mechloop.messages.ru.base import Entry

ENTRIES: list[Entry] = [
]
