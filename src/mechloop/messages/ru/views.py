"""Russian of the messages and fixes of views, output, report and the command line
(src/mechloop/views/, output/, report/, cli.py)."""

from __future__ import annotations

from mechloop.messages.ru.base import Entry

ENTRIES: list[Entry] = [
]
