"""The one exception family of mechloop.

Every error a user can cause derives from :class:`MechloopError` and also from the builtin a
caller would naturally catch (``ValueError``).  Each carries typed fields and builds its
message in ``__str__``, so it reads well on the command line and survives pickling (worker
processes raise these too).
"""

from __future__ import annotations

from dataclasses import dataclass


class MechloopError(Exception):
    """Base class of every error mechloop raises on purpose."""


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a model: where it is, what is wrong and how to fix it.

    ``path`` is the location inside the model document as a tuple of keys and list indices,
    e.g. ``("vectors", 3, "a")``; ``line`` is the 1-based line in the file when known.
    """

    path: tuple[str | int, ...]
    message: str
    hint: str = ""
    line: int | None = None

    def where(self) -> str:
        return format_path(self.path)

    def render(self, file: str | None = None) -> str:
        place = []
        if file:
            place.append(file if self.line is None else f"{file}:{self.line}")
        elif self.line is not None:
            place.append(f"line {self.line}")
        if self.path:
            place.append(self.where())
        head = ", ".join(place)
        text = f"{head}: {self.message}" if head else self.message
        if self.hint:
            text += f"\n    fix: {self.hint}"
        return text


def format_path(path: tuple[str | int, ...]) -> str:
    """Render a document path: ``vectors[3].a``, ``contours[0].variant``."""
    out = ""
    for key in path:
        if isinstance(key, int):
            out += f"[{key}]"
        else:
            out += ("." if out else "") + str(key)
    return out


class ModelError(ValueError, MechloopError):
    """A model (from a file or built in code) is invalid; lists every problem found."""

    def __init__(self, problems: list[Problem] | tuple[Problem, ...], file: str | None = None):
        self.problems = tuple(problems)
        self.file = file
        super().__init__(self.problems, file)

    def __str__(self) -> str:
        return problem_list([p.render(self.file) for p in self.problems],
                            f"{len(self.problems)} problems in {self.file or 'the model'}:")

    def __reduce__(self):
        return (type(self), (self.problems, self.file))


def problem_list(lines: list[str], head: str) -> str:
    """Rendered problems as printed: one alone, or ``head`` and each as an indented item."""
    if len(lines) == 1:
        return lines[0]
    return "\n".join([head, *("- " + line.replace("\n", "\n  ") for line in lines)])


class ModelFileError(ModelError):
    """The model file cannot be read or parsed (missing, not YAML, not a mapping)."""


class HintedError(ValueError, MechloopError):
    """An error told as one message and the fix; the base of the errors that are not
    about a place in a model file."""

    def __init__(self, message: str, hint: str = ""):
        self.message = message
        self.hint = hint
        super().__init__(message, hint)

    def __str__(self) -> str:
        return self.message + (f"\n    fix: {self.hint}" if self.hint else "")

    def __reduce__(self):
        return (type(self), (self.message, self.hint))

    def at(self, path: tuple[str | int, ...], hint: str | None = None) -> ModelSolveError:
        """This error told at ``path`` in the model (e.g. ``("machine",)``), with ``hint``
        (a fix in terms of the model file) instead of its own when given."""
        return ModelSolveError([Problem(path, self.message,
                                        self.hint if hint is None else hint)])


class SolveError(HintedError):
    """A model is valid but its data make a requested quantity undefined."""


class ModelSolveError(ModelError, SolveError):
    """A valid model that cannot be solved, told at the place in the model that causes it
    (so the command line names the file, line and key); still a :class:`SolveError`."""

    def __init__(self, problems: list[Problem] | tuple[Problem, ...], file: str | None = None):
        ModelError.__init__(self, problems, file)
        first = self.problems[0] if self.problems else Problem((), "")
        self.message, self.hint = first.message, first.hint
