"""The language of the API's error messages: the page's language, sent by the page in the
``X-Mechloop-Lang`` header (or ``?lang=``); English when none is given.

The library raises its errors in English; each message and fix is said in the page's
language by :func:`mechloop.messages.render_error` (a message without a Russian entry in
the catalogue stays English rather than being lost).
"""

from __future__ import annotations

from typing import Any

from mechloop.errors import HintedError
from mechloop.messages import render_error

LANG_HEADER = "x-mechloop-lang"
LANGUAGES = ("en", "ru")


def request_language(headers: Any, query: Any) -> str:
    """``ru`` or ``en``: the header :data:`LANG_HEADER`, else the query's ``lang``; an
    unknown language is English."""
    value = (headers.get(LANG_HEADER) or query.get("lang") or "en").strip().lower()
    return value if value in LANGUAGES else "en"


def said(text: str, lang: str) -> str:
    """One message or fix of the library in ``lang``."""
    if not text or lang == "en":
        return text
    return render_error(HintedError(text, ""), lang)


def problems_in(items: list[dict[str, Any]], lang: str) -> list[dict[str, Any]]:
    """The located problems (``message``, ``hint``, ``line``, ``path``) in ``lang``."""
    return [dict(item, message=said(item.get("message") or "", lang),
                 hint=said(item.get("hint") or "", lang)) for item in items]
