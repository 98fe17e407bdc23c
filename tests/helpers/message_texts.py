"""The library's error messages and fixes, read from its source (issue 15: "CLI messages …
in Russian"): every text passed to an error or a problem — ``Problem(path, message, hint)``,
``HintedError(message, hint)`` and every other ``…Error(…)``, the located-error helpers
(``fail``, ``problem``, ``.at``) — as the English the user would read, with each
``{value}`` of an f-string replaced by a sample value.

A text held in a variable is followed to the assignments of that name in the same function
(``message = f"…"`` then ``raise SolveError(message, hint)``); a conditional or a ``+`` of
texts gives each of its texts.  What cannot be followed (a text from a table or a parameter)
is not listed: the coverage this measures is a lower bound of the real one.
"""

from __future__ import annotations

import ast
import builtins
import itertools
import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2] / "src" / "mechloop"

#: Calls whose text arguments are messages: names ending so, and the helpers named here.
SUFFIXES = ("Error", "Problem")
HELPERS = {"fail", "_fail", "problem", "_problem", "at", "refuse", "_refuse", "_located",
           "located", "BadParameter"}
#: Python's own errors: a program's mistake, not the user's (the command line never prints
#: them as messages) — but a ``ValueError`` in a module of pydantic models is a validator's
#: message, which the user reads as a schema problem.
BUILTIN = {name for name in dir(builtins) if name.endswith("Error")}
#: Keyword arguments that hold a message or a fix.
KEYWORDS = {"message", "hint", "fix", "why", "reason"}
#: Modules that only print or translate messages (their texts are not the library's).
SKIP = {"messages", "errors.py"}

#: Sample values tried for a ``{value}``: a name, a number, a key path, a sentence.
SAMPLES = ("x", "1", "r1", "1.5", "a.b", "x y", "length", "mm", "m", "a.b or c.b")
#: At most this many combinations of samples are tried for one text.
MAX_TRIES = 64


#: A hole of a ``{value!r}``: the value in quotes, as ``repr`` writes a name.
REPR = "\x00!r"


@dataclass(frozen=True)
class MessageText:
    """One message or fix: where it is written and its parts (literal text, or None for a
    formatted value)."""

    file: str
    line: int
    parts: tuple[str | None, ...]

    @property
    def area(self) -> str:
        """The library's package the text is in (``model``, ``dynamics``, …; ``cli``)."""
        first = self.file.split("/")[0]
        return first.removesuffix(".py")

    @property
    def holes(self) -> int:
        return sum(_is_hole(part) for part in self.parts)

    def template(self) -> str:
        return "".join("{…!r}" if part == REPR else "{…}" if part is None else part
                       for part in self.parts)

    def samples(self) -> Iterator[tuple[str, tuple[str, ...]]]:
        """The text with sample values in its holes, and the values used: first the same
        sample in every hole, then mixes (at most :data:`MAX_TRIES` in all)."""
        holes = self.holes
        tries = [(s,) * holes for s in SAMPLES]
        if holes > 1:
            mixed = itertools.islice(itertools.product(SAMPLES, repeat=holes), MAX_TRIES)
            tries += [t for t in mixed if len(set(t)) > 1]
        seen = set()
        for values in tries[:MAX_TRIES] if holes else [()]:
            if values in seen:
                continue
            seen.add(values)
            it = iter(values)
            yield "".join(_repr(next(it)) if part == REPR else next(it) if part is None
                          else part for part in self.parts), values


def _repr(sample: str) -> str:
    """A sample as ``{value!r}`` prints it: a number bare, a name in quotes."""
    try:
        return repr(float(sample)) if "." in sample else repr(int(sample))
    except ValueError:
        return repr(sample)


def _is_hole(part: str | None) -> bool:
    return part is None or part == REPR


def _name(func: ast.expr) -> str:
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return func.attr
    return ""


def _is_message_call(node: ast.Call, validators: bool) -> bool:
    name = _name(node.func)
    builtin = name in BUILTIN and not (validators and name == "ValueError")
    return (name.endswith(SUFFIXES) or name in HELPERS) and not builtin


def _texts(node: ast.expr, scope: ast.AST | None, depth: int = 0
           ) -> list[tuple[str | None, ...]]:
    """Every text ``node`` can be, as parts (None for a formatted value)."""
    if depth > 4:
        return []
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [(node.value,)]
    if isinstance(node, ast.JoinedStr):
        parts: list[tuple[str | None, ...]] = [()]
        for value in node.values:
            if isinstance(value, ast.Constant):
                parts = [(*p, value.value) for p in parts]
            else:
                inner = value.value
                nested = _texts(inner, scope, depth + 1) if isinstance(
                    inner, ast.IfExp | ast.Constant | ast.JoinedStr) else []
                if nested and len(nested) * len(parts) <= 16:
                    parts = [p + n for p in parts for n in nested]
                else:
                    hole = REPR if value.conversion == ord("r") else None
                    parts = [(*p, hole) for p in parts]
        return parts
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = _texts(node.left, scope, depth + 1), _texts(node.right, scope, depth + 1)
        if left and right:
            return [a + b for a in left for b in right][:16]
        return left or right
    if isinstance(node, ast.IfExp):
        return _texts(node.body, scope, depth + 1) + _texts(node.orelse, scope, depth + 1)
    if isinstance(node, ast.Name) and scope is not None:
        found = []
        for sub in ast.walk(scope):
            if isinstance(sub, ast.Assign) and any(
                    isinstance(t, ast.Name) and t.id == node.id for t in sub.targets):
                found += _texts(sub.value, None, depth + 1)
            elif isinstance(sub, ast.AugAssign) and isinstance(sub.target, ast.Name) \
                    and sub.target.id == node.id:
                found += _texts(sub.value, None, depth + 1)
        return found
    return []


def _merged(parts: tuple[str | None, ...]) -> tuple[str | None, ...]:
    out: list[str | None] = []
    for part in parts:
        if not _is_hole(part) and out and not _is_hole(out[-1]):
            out[-1] += part
        elif _is_hole(part) or part != "":
            out.append(part)
    return tuple(out)


def _is_message(parts: tuple[str | None, ...]) -> bool:
    """A sentence a user reads: some words of letters, not a bare name or format."""
    text = "".join(p for p in parts if not _is_hole(p))
    if len(parts) == 1 and re.fullmatch(r"\w+", text):  # a key or an error's type name
        return False
    return any(len(w) >= 3 for w in re.findall(r"[A-Za-z]+", text))


def _calls(node: ast.AST, scope: ast.AST | None, validators: bool
           ) -> Iterator[tuple[ast.Call, ast.AST | None]]:
    """The message calls under ``node`` with the innermost function around each
    (``validators``: the module defines pydantic models)."""
    for child in ast.iter_child_nodes(node):
        inner = child if isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef) else scope
        if isinstance(child, ast.Call) and _is_message_call(child, validators):
            yield child, scope
        yield from _calls(child, inner, validators)


def message_texts(root: Path = SOURCE) -> list[MessageText]:
    """Every message and fix text of the library under ``root``, in file and line order."""
    out: dict[tuple[str, tuple], MessageText] = {}
    for path in sorted(root.rglob("*.py")):
        relative = path.relative_to(root).as_posix()
        if relative.split("/")[0] in SKIP:
            continue
        source = path.read_text(encoding="utf-8")
        tree = ast.parse(source)
        for node, scope in _calls(tree, None, "pydantic" in source):
            args = [*node.args, *(k.value for k in node.keywords if k.arg in KEYWORDS)]
            for arg in args:
                for parts in _texts(arg, scope):
                    parts = _merged(parts)
                    if _is_message(parts):
                        out.setdefault((relative, parts),
                                       MessageText(relative, arg.lineno, parts))
    return sorted(out.values(), key=lambda m: (m.file, m.line))
