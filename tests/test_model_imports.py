"""The imports inside ``mechloop.model`` flow one way: no module imports a module that
imports it back, directly or through others, counting the imports inside functions too
(only ``if TYPE_CHECKING:`` blocks are left out: they never run).  Read from the source
with :mod:`ast`, so a deferred import cannot hide a circle."""

from __future__ import annotations

import ast
from graphlib import CycleError, TopologicalSorter
from pathlib import Path

import pytest

MODEL = Path(__file__).resolve().parents[1] / "src" / "mechloop" / "model"


def _module_name(path: Path, root: Path, package: str) -> str:
    parts = list(path.relative_to(root).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join([package, *parts])


def _runs(node: ast.AST) -> bool:
    """Whether ``node`` is not an ``if TYPE_CHECKING:`` block."""
    if isinstance(node, ast.If):
        test = node.test
        name = test.id if isinstance(test, ast.Name) else getattr(test, "attr", None)
        return name != "TYPE_CHECKING"
    return True


def _imports(tree: ast.AST) -> list[tuple[str, list[str]]]:
    """(module, names) of every import that runs, at any depth."""
    out: list[tuple[str, list[str]]] = []
    stack = [tree]
    while stack:
        node = stack.pop()
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.append((node.module, [a.name for a in node.names]))
        elif isinstance(node, ast.Import):
            out += [(a.name, []) for a in node.names]
        if isinstance(node, ast.If) and not _runs(node):
            stack.extend(node.orelse)
            continue
        stack.extend(ast.iter_child_nodes(node))
    return out


def import_graph(root: Path, package: str) -> dict[str, set[str]]:
    """Module -> the modules of ``package`` it imports (a package counts as its
    ``__init__``; ``from package import sub`` as the submodule ``sub``)."""
    modules = {_module_name(p, root, package): p for p in root.rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        deps: set[str] = set()
        for module, names in _imports(ast.parse(path.read_text(encoding="utf-8"))):
            if module not in modules:
                continue
            subs = [f"{module}.{n}" for n in names if f"{module}.{n}" in modules]
            deps.update(subs or [module])
        deps.discard(name)
        graph[name] = deps
    return graph


def _cycle(graph: dict[str, set[str]]) -> list[str] | None:
    try:
        tuple(TopologicalSorter(graph).static_order())
    except CycleError as exc:
        return list(exc.args[1])
    return None


def test_the_model_package_imports_flow_one_way():
    graph = import_graph(MODEL, "mechloop.model")
    assert "mechloop.model.groups.core" in graph and "mechloop.model.load" in graph
    assert _cycle(graph) is None, f"import circle: {' -> '.join(_cycle(graph) or [])}"


def test_the_loader_is_on_top_and_the_schema_below_it():
    """The layers the package docstring states: the loader imports the group builder,
    the builder the schema; nothing below imports upwards."""
    graph = import_graph(MODEL, "mechloop.model")

    def reaches(a: str, b: str) -> bool:
        seen, todo = set(), [a]
        while todo:
            node = todo.pop()
            if node == b:
                return True
            if node not in seen:
                seen.add(node)
                todo.extend(graph.get(node, ()))
        return False

    assert reaches("mechloop.model.load", "mechloop.model.groups.builder")
    assert reaches("mechloop.model.groups.builder", "mechloop.model.schema")
    for low in ("schema", "synthesis", "structure", "check", "document", "salvage"):
        assert not reaches(f"mechloop.model.{low}", "mechloop.model.load"), low
        assert not reaches(f"mechloop.model.{low}", "mechloop.model.groups"), low


@pytest.mark.parametrize("deferred", [False, True])
def test_a_circle_is_found_also_through_an_import_inside_a_function(tmp_path, deferred):
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from pkg.b import f\n")
    body = "def g():\n    from pkg.a import f\n" if deferred else "from pkg import a\n"
    (pkg / "b.py").write_text(body + "def f():\n    pass\n")
    (pkg / "c.py").write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
                              "    from pkg.a import f\n")
    graph = import_graph(pkg, "pkg")
    assert set(_cycle(graph) or []) == {"pkg.a", "pkg.b"}
    assert graph["pkg.c"] == set()  # a type-checking import does not run


def test_model_from_dict_reads_through_the_loader_in_a_fresh_interpreter():
    """The schema does not import the loader; importing any module of the package sets
    the reader Model.from_dict uses (a group file's data too)."""
    import subprocess
    import sys

    code = ("from mechloop.model.schema import Model\n"
            "m = Model.from_dict({'positions': 4, 'arguments': {1: {'table': {0: 0, 4: 90}}},"
            " 'ground': {'O': [0, 0], 'C': [0.3, 0]}, 'input': {'kind': 'crank', 'pivot': "
            "'O', 'joint': 'A', 'length': 0.1}, 'groups': [{'kind': 'L1', 'links': ['c', "
            "'r'], 'at': ['A', 'C'], 'joint': 'B', 'lengths': [0.35, 0.25]}]})\n"
            "print(len(m.contours), len(m.vectors))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.split() == ["1", "4"]
