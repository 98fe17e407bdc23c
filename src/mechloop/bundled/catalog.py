"""The catalogue of bundled examples: every ``examples/*.yaml`` and ``*.py`` with its title,
and the course-project models of ``examples/course/`` with their task number (seed 000
sec. 3) and their English and Russian titles.

A course model is named ``NN_stem.yaml`` (NN its task number); its ``name:`` is the English
title and its ``description:`` the Russian one (the seed's title).  Other examples take
their title from ``name:`` (a model) or the first line of the docstring (a Python script).
The files ship inside the package (``mechloop/examples_data``, a link to ``examples/`` in
the source tree, resolved into the wheel by setuptools).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from importlib.resources import files
from pathlib import Path

from mechloop.errors import HintedError

_COURSE = "course"
_NUMBERED = re.compile(r"^(\d+)_")
_KEY = re.compile(r"^(name|description):\s*(.*?)\s*$")


@dataclass(frozen=True)
class Example:
    """One bundled example: its file, its course task number (None outside the course
    project) and its titles."""

    path: Path
    title: str
    number: int | None = None
    title_ru: str = ""

    @property
    def stem(self) -> str:
        """The file name without its suffix, e.g. ``01_an10_landing_gear``."""
        return self.path.stem

    @property
    def course(self) -> bool:
        """Whether the example is a course-project model."""
        return self.number is not None


def examples_dir() -> Path:
    """The folder of the bundled examples (inside the installed package, else the source
    tree's ``examples/``)."""
    packaged = Path(str(files("mechloop") / "examples_data"))
    if packaged.is_dir():
        return packaged
    source = Path(__file__).resolve().parents[3] / "examples"
    if source.is_dir():
        return source
    raise HintedError("the bundled examples are not installed",
                      "reinstall mechloop (pip install --force-reinstall mechloop)")


def _unquote(text: str) -> str:
    text = text.split(" #", 1)[0].strip()
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "\"'":
        return text[1:-1]
    return text


def _titles(path: Path) -> tuple[str, str]:
    """(name, description) of a model file, read from its top-level keys (no YAML parse:
    the catalogue is listed without loading any model)."""
    found: dict[str, str] = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        match = _KEY.match(line)
        if match and match.group(1) not in found:
            found[match.group(1)] = _unquote(match.group(2))
    return found.get("name", ""), found.get("description", "")


def _docstring_title(path: Path) -> str:
    match = re.match(r'\s*(?:#.*\n)*\s*[rRuU]?"""(.*?)(?:\n\s*\n|""")',
                     path.read_text(encoding="utf-8"), flags=re.S)
    return " ".join(match.group(1).split()).rstrip(".") if match else ""


@cache
def _catalogue(root: Path) -> tuple[Example, ...]:
    out: list[Example] = []
    for path in sorted((root / _COURSE).glob("*.yaml")) if (root / _COURSE).is_dir() else []:
        number = _NUMBERED.match(path.name)
        name, ru = _titles(path)
        out.append(Example(path, name, int(number.group(1)) if number else None, ru))
    out.sort(key=lambda e: (e.number is None, e.number or 0, e.stem))
    for path in sorted([*root.glob("*.yaml"), *root.glob("*.py")]):
        title = _titles(path)[0] if path.suffix == ".yaml" else _docstring_title(path)
        out.append(Example(path, title))
    return tuple(out)


def examples(course_only: bool = False) -> list[Example]:
    """The bundled examples: the course models first (by task number), then the others by
    file name."""
    found = _catalogue(examples_dir())
    return [e for e in found if e.course or not course_only]


def find_example(name: str) -> Example:
    """The example called ``name``: a course task number (``1``, ``01``), a file name with
    or without its suffix, or a unique prefix of one.

    Raises:
        HintedError: no example or several match (the hint names them).
    """
    key = name.strip()
    catalogue = examples()
    if key.isdigit():
        hits = [e for e in catalogue if e.number == int(key)]
        if hits:
            return hits[0]
    for exact in (lambda e: e.path.name == key, lambda e: e.stem == key):
        hits = [e for e in catalogue if exact(e)]
        if len(hits) == 1:
            return hits[0]
    hits = [e for e in catalogue if e.stem.startswith(key) or e.path.name.startswith(key)]
    if len(hits) == 1:
        return hits[0]
    if not hits:
        numbers = sorted(e.number for e in catalogue if e.number is not None)
        known = f"course tasks {numbers[0]}..{numbers[-1]} or " if numbers else ""
        raise HintedError(f"no bundled example is called {name!r}",
                          f"give {known}a file name that `mechloop examples` lists")
    shown = ", ".join(e.stem for e in hits[:8]) + (", ..." if len(hits) > 8 else "")
    raise HintedError(f"{name!r} matches {len(hits)} examples: {shown}",
                      "give more of the name, or the course task number")
