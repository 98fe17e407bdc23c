"""Every error message and fix of the library has Russian (issue 15: "CLI messages … contain
no English words except symbols, unit names and the user's own names"): each text read from
the source (:mod:`helpers.message_texts`: every ``Problem``, ``…Error`` and located-error
call's message and fix, with sample values in its ``{…}``) goes through the catalogue and
comes out with no English word but the sample values — checked area by area of the library.
"""

from __future__ import annotations

from functools import cache

import pytest
from helpers.message_texts import MessageText, message_texts
from test_messages_ru import english_left

from mechloop.messages.catalogue_ru import translate

#: The areas of the library, by the first part of a module's path under src/mechloop, as the
#: modules of mechloop.messages.ru hold their entries.
AREAS = {
    "model": {"model"},
    "dynamics": {"dynamics"},
    "synthesis": {"synthesis", "engines", "solve", "bundled", "structure", "spatial",
                  "modules", "__init__"},
    "gears": {"gears", "cams"},
    "views": {"views", "output", "report", "cli"},
    "web": {"web"},
}
#: Texts whose one hole takes a few words the reader cannot see (a validator's own
#: names): the words it takes.
CLOSED = {
    "a {…} needs its angle and law": ("rise", "return"),
    "a {…} takes no angle or law": ("dwell", "table"),
}


@cache
def _texts() -> tuple[MessageText, ...]:
    return tuple(message_texts())


def english_of(text: MessageText) -> str | None:
    """None when some sample of ``text`` comes out of the catalogue with no English word
    but its sample values; else the Russian of its first sample with what is left."""
    if text.template() in CLOSED:  # every word it takes
        for word in CLOSED[text.template()]:
            russian = translate(text.template().replace("{…}", word))
            if left := english_left(russian):
                return f"{russian!r} (English: {', '.join(left)})"
        return None
    first = None
    for sample, values in text.samples():
        russian = translate(sample)
        words = {w for v in values for w in v.split()}
        left = [w for w in english_left(russian) if w not in words]
        if not left:
            return None
        first = first or f"{russian!r} (English: {', '.join(left)})"
    return first


def test_every_module_of_the_library_is_in_an_area():
    known = set().union(*AREAS.values())
    assert {text.area for text in _texts()} <= known
    assert len(_texts()) > 900  # the reader still finds the library's messages


@pytest.mark.parametrize("area", AREAS)
def test_every_message_of_an_area_has_russian(area):
    left = []
    for text in _texts():
        if text.area in AREAS[area] and (english := english_of(text)) is not None:
            left.append(f"{text.file}:{text.line}: {text.template()!r} -> {english}")
    assert not left, f"{len(left)} texts without Russian:\n" + "\n".join(left)
