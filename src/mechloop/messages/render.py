"""A :class:`~mechloop.errors.MechloopError` as printed in a language.

English is the error's own ``str`` (unchanged); Russian lays out the same parts — file,
line, key path, message, fix — with Russian words, and each message and fix translated by
:func:`mechloop.messages.catalogue_ru.translate` (a message without a Russian entry stays
English rather than being lost).
"""

from __future__ import annotations

from mechloop.errors import HintedError, MechloopError, ModelError, Problem, problem_list

#: The printer's label before an error, per language.
LABELS = {"en": "error:", "ru": "ошибка:"}
#: The label of the fix, per language (English: the errors' own ``fix:``).
FIX = {"en": "fix:", "ru": "как исправить:"}


def error_label(lang: str) -> str:
    """``error:`` / ``ошибка:``."""
    return LABELS.get(lang, LABELS["en"])


def render_error(exc: MechloopError, lang: str) -> str:
    """The text of ``exc`` in ``lang`` (``en``: ``str(exc)``, byte for byte)."""
    if lang != "ru":
        return str(exc)
    if isinstance(exc, ModelError):
        return _model_error(exc)
    if isinstance(exc, HintedError):
        return _ru(exc.message) + _fix(exc.hint)
    return _ru(str(exc))


def _ru(text: str) -> str:
    from mechloop.messages.catalogue_ru import translate

    return translate(text)


def _fix(hint: str) -> str:
    return f"\n    {FIX['ru']} {_ru(hint)}" if hint else ""


def _problem(problem: Problem, file: str | None) -> str:
    place = []
    if file:
        place.append(file if problem.line is None else f"{file}:{problem.line}")
    elif problem.line is not None:
        place.append(f"строка {problem.line}")
    if problem.path:
        place.append(problem.where())
    head = ", ".join(place)
    text = f"{head}: {_ru(problem.message)}" if head else _ru(problem.message)
    return text + _fix(problem.hint)


def _model_error(exc: ModelError) -> str:
    lines = [_problem(p, exc.file) for p in exc.problems]
    return problem_list(lines, f"проблем в файле {exc.file}: {len(lines)}" if exc.file
                        else f"проблем в модели: {len(lines)}")
