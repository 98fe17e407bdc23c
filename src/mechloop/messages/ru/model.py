"""Russian of the messages and fixes of the model's files and checks (src/mechloop/model/)."""

from __future__ import annotations

from mechloop.messages.ru.base import Entry

ENTRIES: list[Entry] = [
]
