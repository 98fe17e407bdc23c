"""Structure of a vector model: roles resolved, modules named, contours put in order.

:func:`analyze` reads a :class:`~mechloop.model.schema.Model` and returns a
:class:`Structure` — for every contour its functions, module type (Pl1–Pl4) and the
contours it needs first — together with every structural problem it found (a contour with
the wrong number of functions, a link to nothing, a cycle, ...), each with its place in the
document and the fix.  Nothing here touches numbers beyond reading roles.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from graphlib import CycleError, TopologicalSorter

from mechloop.errors import Problem
from mechloop.model.roles import is_function
from mechloop.model.schema import ArgumentRole, LinkRole, Model

MODULE_SOLUTIONS = {"Pl1": 1, "Pl2": 1, "Pl3": 2, "Pl4": 2}


def param_role(model: Model, name: str) -> object:
    """The role object of parameter ``name`` ('r3', 'a2') — raises KeyError if absent."""
    vector = model.vectors[int(name[1:])]
    return vector.r if name[0] == "r" else vector.a


@dataclass(frozen=True)
class LinkChain:
    """Where a linked parameter finally comes from: ``root`` plus the sum of ``deltas``."""

    root: str
    deltas: tuple[float | str, ...]


@dataclass(frozen=True)
class ContourInfo:
    """The parametric characteristic of one contour.

    ``functions`` are the two unknowns in module order ("vector 1" first), ``module`` the
    elementary module that solves them, ``needs`` the numbers of earlier contours whose
    functions this one reads through links.
    """

    number: int
    vectors: tuple[int, ...]
    functions: tuple[str, ...]
    module: str
    variant: int | str
    needs: tuple[int, ...]
    arguments: tuple[str, ...]
    links: tuple[str, ...]


@dataclass(frozen=True)
class Structure:
    """The analysed model: contours in solving order and resolved links."""

    contours: tuple[ContourInfo, ...]
    order: tuple[int, ...]
    links: dict[str, LinkChain] = field(default_factory=dict)
    owner: dict[str, int] = field(default_factory=dict)

    def ordered(self) -> list[ContourInfo]:
        by_number = {c.number: c for c in self.contours}
        return [by_number[n] for n in self.order]


def _module_of(functions: list[str]) -> tuple[str, tuple[str, ...]]:
    """Module name and unknowns in module order for a contour's two functions."""
    (p, q) = functions
    if p[1:] == q[1:]:
        return "Pl1", (f"r{p[1:]}", f"a{p[1:]}")
    kinds = p[0] + q[0]
    if kinds == "rr":
        return "Pl2", (p, q)
    if kinds == "aa":
        return "Pl4", (p, q)
    length, angle = (p, q) if kinds == "ra" else (q, p)
    return "Pl3", (length, angle)


def analyze(model: Model) -> tuple[Structure, list[Problem]]:
    """Resolve roles, classify contours and order them; collect every problem found."""
    problems: list[Problem] = []
    vectors = model.vectors

    for number in vectors:
        if number < 1:
            problems.append(Problem(("vectors", number), f"vector number {number} is not "
                                    "positive", "number vectors 1, 2, 3, ..."))

    # Which contour holds each vector.
    holder: dict[int, int] = {}
    for ci, contour in enumerate(model.contours):
        seen: set[int] = set()
        for vi, number in enumerate(contour.vectors):
            path = ("contours", ci, "vectors", vi)
            if number not in vectors:
                problems.append(Problem(path, f"contour {ci + 1} lists vector {number}, "
                                        "which is not defined",
                                        f"add vector {number} under 'vectors:' or remove it "
                                        "from the contour"))
            elif number in seen:
                problems.append(Problem(path, f"contour {ci + 1} lists vector {number} twice",
                                        "list each vector once"))
            elif number in holder:
                problems.append(Problem(path, f"vector {number} is in contours "
                                        f"{holder[number]} and {ci + 1}; a vector belongs to "
                                        "one contour",
                                        f"in contour {ci + 1} use a new vector linked to it: "
                                        f"r: {{link: r{number}}}, a: {{link: a{number}}}"))
            else:
                holder[number] = ci + 1
            seen.add(number)
    for number in vectors:
        if number not in holder:
            problems.append(Problem(("vectors", number), f"vector {number} is in no contour",
                                    "add it to the 'vectors' list of a contour, or remove it"))

    # Roles of every parameter: arguments exist, links point at something real.
    links: dict[str, LinkChain] = {}
    for number, vector in vectors.items():
        for letter in "ra":
            role = vector.r if letter == "r" else vector.a
            name = f"{letter}{number}"
            path = ("vectors", number, letter)
            if isinstance(role, ArgumentRole) and role.argument not in model.arguments:
                problems.append(Problem(path, f"{name} uses argument {role.argument}, which "
                                        "is not defined",
                                        f"add argument {role.argument} under 'arguments:' or "
                                        "use one that exists"))
            if isinstance(role, LinkRole):
                chain = _follow_link(model, name, path, problems)
                if chain is not None:
                    links[name] = chain

    # Functions per contour, module type, dependencies.
    owner: dict[str, int] = {}
    infos: list[ContourInfo] = []
    for ci, contour in enumerate(model.contours):
        functions = [f"{letter}{n}" for n in contour.vectors if n in vectors
                     for letter in "ra" if is_function(param_role(model, f"{letter}{n}"))]
        for f in functions:
            owner[f] = ci + 1
        path = ("contours", ci)
        if len(functions) != 2:
            found = ", ".join(functions) if functions else "none"
            fix = ("mark two of its parameters 'function' (the unknowns of this loop)"
                   if len(functions) < 2 else
                   "make all but two of them constants, arguments or links to earlier "
                   "contours")
            noun = "parameter" if len(functions) == 1 else "parameters"
            problems.append(Problem(path, f"contour {ci + 1} has {len(functions)} function "
                                    f"{noun} ({found}); a planar contour needs exactly 2",
                                    fix))
            module, ordered = "?", tuple(functions)
        else:
            module, ordered = _module_of(functions)
            if MODULE_SOLUTIONS[module] == 1 and contour.variant != 1:
                problems.append(Problem((*path, "variant"),
                                        f"contour {ci + 1} is module {module}, which has one "
                                        f"solution; variant {contour.variant!r} does not apply",
                                        "remove 'variant' or set it to 1"))
        infos.append(ContourInfo(number=ci + 1, vectors=tuple(contour.vectors),
                                 functions=ordered, module=module, variant=contour.variant,
                                 needs=(), arguments=(), links=()))

    # Links into functions: which contour needs which; links into the same contour.
    final: list[ContourInfo] = []
    for info, contour in zip(infos, model.contours, strict=True):
        needs: set[int] = set()
        arguments: list[str] = []
        link_names: list[str] = []
        for n in contour.vectors:
            if n not in vectors:
                continue
            for letter in "ra":
                name = f"{letter}{n}"
                role = param_role(model, name)
                if isinstance(role, ArgumentRole):
                    arguments.append(name)
                if not isinstance(role, LinkRole) or name not in links:
                    continue
                link_names.append(name)
                root = links[name].root
                if root in owner:
                    if owner[root] == info.number:
                        problems.append(Problem(
                            ("vectors", n, letter),
                            f"{name} links to {root}, a function of its own contour "
                            f"{info.number}; a link must point at a known parameter",
                            f"move vector {n} to a later contour, or model the rigid pair "
                            f"{n} and {root[1:]} as one vector"))
                    else:
                        needs.add(owner[root])
                elif is_function(param_role(model, root)):
                    problems.append(Problem(("vectors", n, letter),
                                            f"{name} links to {root}, a function that no "
                                            "contour solves",
                                            f"add vector {root[1:]} to a contour"))
        final.append(ContourInfo(number=info.number, vectors=info.vectors,
                                 functions=info.functions, module=info.module,
                                 variant=info.variant, needs=tuple(sorted(needs)),
                                 arguments=tuple(arguments), links=tuple(link_names)))

    order: tuple[int, ...] = tuple(c.number for c in final)
    sorter = TopologicalSorter({c.number: c.needs for c in final})
    try:
        order = tuple(sorter.static_order())
    except CycleError as exc:
        cycle = exc.args[1]
        loop = " -> ".join(f"contour {n}" for n in cycle)
        problems.append(Problem(("contours",), f"the contours depend on each other in a "
                                f"cycle: {loop} (each needs a function of the next)",
                                "break the cycle: a contour may only link to functions of "
                                "contours that do not need it"))
    return Structure(contours=tuple(final), order=order, links=links, owner=owner), problems


def _follow_link(model: Model, name: str, path: tuple, problems: list[Problem]
                 ) -> LinkChain | None:
    """Follow ``name``'s link chain to a parameter that is not itself a link."""
    deltas: list[float | str] = []
    seen = [name]
    current = name
    while True:
        role = param_role(model, current)
        if not isinstance(role, LinkRole):
            return LinkChain(root=current, deltas=tuple(deltas))
        target = role.link
        if target[0] != current[0]:
            kind = {"r": "length", "a": "angle"}
            problems.append(Problem(path, f"{current} ({kind[current[0]]}) links to "
                                    f"{target} ({kind[target[0]]}); a link joins parameters "
                                    "of the same kind",
                                    f"link to {current[0]}{target[1:]} instead"))
            return None
        if int(target[1:]) not in model.vectors:
            problems.append(Problem(path, f"{current} links to {target}, but vector "
                                    f"{target[1:]} is not defined",
                                    "link to a vector that exists, or add the vector"))
            return None
        deltas.append(role.delta)
        if target in seen:
            problems.append(Problem(path, "links form a cycle: " + " -> ".join(
                [*seen, target]), "one parameter in the chain must be a constant, an "
                "argument or a function"))
            return None
        seen.append(target)
        current = target
