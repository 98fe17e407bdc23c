"""The language of the messages: a command's own ``--lang`` when given, else the
environment variable ``MECHLOOP_LANG`` (``en`` or ``ru``), else English."""

from __future__ import annotations

import os

#: Languages of the messages.
LANGUAGES = ("en", "ru")

#: The environment variable that sets the language of every command's messages.
ENVIRONMENT = "MECHLOOP_LANG"


def message_language(explicit: str | None = None) -> str:
    """``explicit`` (a command's ``--lang`` given on the command line) when it is a known
    language, else ``MECHLOOP_LANG`` when it is one (case and spaces ignored), else ``"en"``.

    >>> message_language("ru")
    'ru'
    """
    if explicit in LANGUAGES:
        return explicit
    chosen = os.environ.get(ENVIRONMENT, "").strip().lower()
    return chosen if chosen in LANGUAGES else "en"
