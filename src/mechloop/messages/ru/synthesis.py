"""Russian of the messages and fixes of synthesis, engines, the solver, the bundled
examples, structure and spatial (src/mechloop/synthesis/, engines/, solve/, bundled/,
structure/, spatial/, modules/)."""

from __future__ import annotations

from mechloop.messages.ru.base import Entry

ENTRIES: list[Entry] = [
]
