"""Structure of a vector model: roles resolved, modules named, contours put in order.

:func:`analyze` reads a :class:`~mechloop.model.schema.Model` and returns a
:class:`Structure` — for every contour its functions, module type (Pl1–Pl4, or
``coupled``) and the contours it needs, and the blocks solved one after another
(:func:`find_blocks`: a contour alone in closed form, or a coupled block) — together with
every structural problem it found (a contour or block with the wrong number of functions,
a link to nothing, a cycle of links, ...), each with its place in the document and the
fix.  Nothing here touches numbers beyond reading roles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from graphlib import CycleError, TopologicalSorter

from mechloop.errors import Problem
from mechloop.model.block_guess import read_guess
from mechloop.model.roles import is_function
from mechloop.model.schema import ArgumentRole, LinkRole, Model

MODULE_SOLUTIONS = {"Pl1": 1, "Pl2": 1, "Pl3": 2, "Pl4": 2}


def param_role(model: Model, name: str) -> object:
    """The role object of parameter ``name`` ('r3', 'a2') — raises KeyError if absent."""
    vector = model.vectors[int(name[1:])]
    if name[0] == "b":  # β of a spatial vector (mechloop.model.spatial): 0 when absent
        return 0.0 if vector.b is None else vector.b
    return vector.r if name[0] == "r" else vector.a


@dataclass(frozen=True)
class LinkChain:
    """Where a linked parameter finally comes from, one step per link from the parameter
    towards ``root``: step ``i`` is ``p_i = ratios[i]·p_(i+1) + deltas[i]`` (model units).

    The parameter is ``scale·root + Σ_i (Π_(j<i) ratios[j])·deltas[i]``; ``ratios`` is
    empty for a chain built without them (every ratio 1).
    """

    root: str
    deltas: tuple[float | str, ...]
    ratios: tuple[float, ...] = ()

    @property
    def scale(self) -> float:
        """The composed ratio: the product of the steps' ratios (1 for rigid links)."""
        return math.prod(self.ratios)

    @property
    def rigid(self) -> bool:
        """Every step has ratio 1: the parameter is the root plus a constant."""
        return all(k == 1 for k in self.ratios)


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
    #: number of the block (1, 2, ... in solving order) that solves this contour
    block: int = 0


#: The module name of a contour solved in a coupled block (not by a closed form).
COUPLED = "coupled"


@dataclass(frozen=True)
class BlockInfo:
    """Contours solved together, in solving order.

    An *elementary* block is one contour solved by its closed-form module (Pl1–Pl4).  A
    *coupled* block (``coupled`` true) is a set of ``k`` contours whose ``2k`` closure
    equations must be solved at once for its ``2k`` ``unknowns`` (Newton's method,
    :mod:`mechloop.modules.coupled`): contours that need each other's functions (a strongly
    connected component of the "needs" graph), or a contour linking to one of its own
    functions (a non-elementary module).  ``unknowns`` are in the order of the contours and
    of their vectors (the columns of the block Jacobian); ``needs`` the earlier blocks
    whose functions it reads; ``variant`` the assembly at position 0 when no ``guess``
    (approximate unknowns at position 0, SI, from the contours' ``guess``) is given.
    """

    number: int
    contours: tuple[int, ...]
    unknowns: tuple[str, ...]
    needs: tuple[int, ...]
    coupled: bool
    variant: int | str = 1
    guess: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class Structure:
    """The analysed model: contours in solving order and resolved links.

    ``order`` lists the contours in solving order, block after block (``blocks``); the
    contours of one coupled block are adjacent in it.
    """

    contours: tuple[ContourInfo, ...]
    order: tuple[int, ...]
    links: dict[str, LinkChain] = field(default_factory=dict)
    owner: dict[str, int] = field(default_factory=dict)
    blocks: tuple[BlockInfo, ...] = ()

    def ordered(self) -> list[ContourInfo]:
        by_number = {c.number: c for c in self.contours}
        return [by_number[n] for n in self.order]

    @property
    def coupled(self) -> bool:
        """Whether some block is coupled (solved by Newton's method)."""
        return any(b.coupled for b in self.blocks)


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
    for ci, contour in enumerate(model.contours):
        if contour.convention != 1:
            problems.append(Problem(("contours", ci, "convention"), f"contour {ci + 1} is "
                                    "planar; a convention of parameter ranges applies to a "
                                    "spatial contour", "remove 'convention'"))
        if contour.plane is not None:
            problems.append(Problem(("contours", ci, "plane"), f"contour {ci + 1} has a "
                                    "plane, but no contour of the model is spatial: a plane "
                                    "places a planar contour beside spatial ones",
                                    "remove 'plane' (a planar model lies in the XY plane)"))
    for number, vector in model.vectors.items():
        if vector.b is not None:
            problems.append(Problem(("vectors", number, "b"), f"vector {number} has a "
                                    "rotation β (b), but no contour of the model is spatial",
                                    "add 'spatial: true' to its contour, or remove 'b'"))
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
    links.update(vector_links(model, "ra", problems))

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
            module, ordered = "?", tuple(functions)
        else:
            module, ordered = _module_of(functions)
            if contour.variant in (3, 4, 5, 6, 7, 8):
                problems.append(Problem((*path, "variant"),
                                        f"contour {ci + 1} is module {module}, which has at "
                                        f"most two solutions; variant {contour.variant!r} "
                                        "does not apply", "set 'variant' to 1, 2 or 'auto'"))
            elif MODULE_SOLUTIONS[module] == 1 and contour.variant != 1:
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
                    needs.add(owner[root])  # its own contour too: a coupled block
                elif is_function(param_role(model, root)):
                    problems.append(Problem(("vectors", n, letter),
                                            f"{name} links to {root}, a function that no "
                                            "contour solves",
                                            f"add vector {root[1:]} to a contour"))
        final.append(ContourInfo(number=info.number, vectors=info.vectors,
                                 functions=info.functions, module=info.module,
                                 variant=info.variant, needs=tuple(sorted(needs)),
                                 arguments=tuple(arguments), links=tuple(link_names)))

    final, blocks = find_blocks(model, final, problems)
    _ratio_inside_block(final, links, owner, problems)
    order = tuple(n for b in blocks for n in b.contours)
    return Structure(contours=tuple(final), order=order, links=links, owner=owner,
                     blocks=blocks), problems


def _ratio_inside_block(infos: list[ContourInfo], links: dict[str, LinkChain],
                        owner: dict[str, int], problems: list[Problem]) -> None:
    """Refuse an angle linked with a ratio ≠ 1 to an angle solved in the same coupled
    block (Newton's unknown would have to be continuous inside the iteration, which is
    not built); a ratio onto an angle an earlier block solves is made continuous before
    it is scaled (:mod:`mechloop.solve.turns`)."""
    block_of = {info.number: info.block for info in infos}
    for info in infos:
        for name in info.links:
            chain = links[name]
            root = chain.root
            if name[0] != "a" or chain.scale == 1 or root not in owner:
                continue
            if owner[root] == info.number or block_of.get(owner[root]) == info.block:
                problems.append(Problem(
                    ("vectors", int(name[1:]), "a", "ratio"),
                    f"{name} links to {root} with ratio {chain.scale:g}, and {root} is "
                    f"solved in the same block as contour {info.number}: a ratio onto an "
                    "angle of its own coupled block is not supported",
                    f"link {name} to an angle that an earlier contour solves, to an "
                    "argument or a constant, or use ratio 1"))


def vector_links(model: Model, letters: str, problems: list[Problem]
                 ) -> dict[str, LinkChain]:
    """The link chains of the vectors' parameters ``letters`` (``"ra"``; ``"rab"`` in a
    spatial model), by name (``a3``); an argument that is not defined or a broken link is
    added to ``problems``."""
    links: dict[str, LinkChain] = {}
    for number, vector in model.vectors.items():
        for letter in letters:
            role = getattr(vector, letter)
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
    return links


def _follow_link(model: Model, name: str, path: tuple, problems: list[Problem]
                 ) -> LinkChain | None:
    """Follow ``name``'s link chain to a parameter that is not itself a link."""
    deltas: list[float | str] = []
    ratios: list[float] = []
    seen = [name]
    current = name
    while True:
        role = param_role(model, current)
        if not isinstance(role, LinkRole):
            return LinkChain(root=current, deltas=tuple(deltas), ratios=tuple(ratios))
        if current == name and (role.ratio == 0 or not math.isfinite(role.ratio)):
            problems.append(Problem((*path, "ratio"), f"{name} links to {role.link} with "
                                    f"ratio {role.ratio}; a ratio is a finite number, not 0",
                                    "give the transmission ratio (e.g. -z1/z2 for an "
                                    "external gear pair), or remove 'ratio' for a rigid link"))
            return None
        target = role.link
        if target[0] != current[0]:
            kind = {"r": "length", "a": "angle", "b": "angle"}
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
        ratios.append(role.ratio)
        if target in seen:
            problems.append(Problem(path, "links form a cycle: " + " -> ".join(
                [*seen, target]), "one parameter in the chain must be a constant, an "
                "argument or a function"))
            return None
        seen.append(target)
        current = target


def find_blocks(model: Model, infos: list[ContourInfo], problems: list[Problem]
                ) -> tuple[list[ContourInfo], tuple[BlockInfo, ...]]:
    """Group the contours into blocks solved one after another (see :class:`BlockInfo`).

    Each contour contributes two closure equations; each function is an unknown used by
    its own contour and by every contour that links to it.  The unknowns are matched to
    the contours (two per contour: a contour with two functions keeps its own); a contour
    *needs* the contours matched to the unknowns it uses, and the strongly connected
    components of that graph, in topological order, are the blocks (the Dulmage–Mendelsohn
    decomposition of the model's equations, contour by contour).  A component of one
    contour that solves its own two functions and links to none of them is elementary.
    Problems (a contour or a block with the wrong number of functions, a bad ``guess``)
    are appended to ``problems``; the infos come back with ``needs``, ``module`` and
    ``block`` set.
    """
    own = {c.number: list(c.functions) for c in infos}
    uses: dict[int, set[str]] = {c.number: set(c.functions) for c in infos}
    owner = {f: n for n, fs in own.items() for f in fs}
    self_link: set[int] = set()
    for info in infos:
        for name in info.links:
            root = _root(model, name)
            if root in owner:
                uses[info.number].add(root)
                if owner[root] == info.number:
                    self_link.add(info.number)
    numbers = [c.number for c in infos]
    if all(len(fs) == 2 for fs in own.values()):
        matched = {n: tuple(own[n]) for n in numbers}
    else:
        matched = _match(numbers, uses, sorted(owner))
        if matched is None:
            for ci, info in enumerate(infos):
                found = list(info.functions)
                if len(found) == 2:
                    continue
                text = ", ".join(found) if found else "none"
                fix = ("mark two of its parameters 'function' (the unknowns of this loop)"
                       if len(found) < 2 else
                       "make all but two of them constants, arguments or links to earlier "
                       "contours")
                noun = "parameter" if len(found) == 1 else "parameters"
                problems.append(Problem(
                    ("contours", ci), f"contour {info.number} has {len(found)} function "
                    f"{noun} ({text}); a planar contour needs exactly 2 (contours solved "
                    "together as a coupled block: 2 per contour in all, each contour "
                    "linking to the others' functions)", fix))
            return infos, ()
    solver = {u: n for n, us in matched.items() for u in us}
    needs = {n: {solver[u] for u in uses[n]} - {n} for n in numbers}
    groups = _components(numbers, needs)
    block_of = {n: i + 1 for i, group in enumerate(groups) for n in group}
    by_number = {c.number: c for c in infos}
    out: list[ContourInfo] = []
    blocks: list[BlockInfo] = []
    for i, group in enumerate(groups):
        first = by_number[group[0]]
        coupled = (len(group) > 1 or first.number in self_link
                   or set(matched[first.number]) != set(own[first.number]))
        unknowns: list[str] = []
        for n in group:
            mine = matched[n]
            if set(mine) == set(own[n]) and len(mine) == 2:
                mine = _module_of(list(own[n]))[1]
            unknowns.extend(mine)
        guess: dict[str, float] = {}
        for n in group:
            if coupled:
                read_guess(model, n, group, unknowns, guess, problems)
                continue
            for name in model.contours[n - 1].guess or {}:
                problems.append(Problem(("contours", n - 1, "guess", name),
                                        f"contour {n} is solved in closed form "
                                        f"(module {first.module}); a guess applies "
                                        "only to a coupled block",
                                        "remove 'guess' and choose the assembly with "
                                        "'variant'"))
        variant = next((by_number[n].variant for n in group
                        if by_number[n].variant != 1), 1)
        blocks.append(BlockInfo(number=i + 1, contours=tuple(group),
                                unknowns=tuple(unknowns),
                                needs=tuple(sorted({block_of[m] for n in group
                                                    for m in needs[n]} - {i + 1})),
                                coupled=coupled, variant=variant, guess=guess))
        for n in group:
            info = by_number[n]
            module = COUPLED if coupled else info.module
            functions = info.functions if not coupled else tuple(
                u for u in unknowns if u in own[n]) or info.functions
            out.append(ContourInfo(number=n, vectors=info.vectors, functions=functions,
                                   module=module, variant=info.variant,
                                   needs=tuple(sorted(needs[n])), arguments=info.arguments,
                                   links=info.links, block=i + 1))
    out.sort(key=lambda c: c.number)
    return out, tuple(blocks)


def _root(model: Model, name: str) -> str:
    """The parameter a link chain ends at (``name`` itself if not a link)."""
    seen = {name}
    while isinstance(role := param_role(model, name), LinkRole):
        name = role.link
        if name in seen or int(name[1:]) not in model.vectors:
            return name
        seen.add(name)
    return name


def _match(numbers: list[int], uses: dict[int, set[str]], unknowns: list[str]
           ) -> dict[int, tuple[str, ...]] | None:
    """Two unknowns per contour, each used by it (maximum bipartite matching of the
    contours' equations to the unknowns), or None when no perfect matching exists."""
    if len(unknowns) != 2 * len(numbers):
        return None
    from scipy.sparse import csr_array
    from scipy.sparse.csgraph import maximum_bipartite_matching

    column = {u: j for j, u in enumerate(unknowns)}
    rows, cols = [], []
    for i, n in enumerate(numbers):
        for u in uses[n]:
            for slot in (2 * i, 2 * i + 1):
                rows.append(slot)
                cols.append(column[u])
    graph = csr_array(([1] * len(rows), (rows, cols)),
                      shape=(2 * len(numbers), len(unknowns)))
    found = maximum_bipartite_matching(graph, perm_type="column")
    if (found < 0).any():
        return None
    return {n: tuple(sorted((unknowns[found[2 * i]], unknowns[found[2 * i + 1]]),
                            key=lambda u: (int(u[1:]), u[0])))
            for i, n in enumerate(numbers)}


def _components(numbers: list[int], needs: dict[int, set[int]]) -> list[tuple[int, ...]]:
    """Strongly connected components of the "needs" graph, each sorted, in an order where
    every component comes after those it needs (the contour order when there is no
    cycle)."""
    try:
        return [(n,) for n in TopologicalSorter(needs).static_order()]
    except CycleError:
        pass
    from scipy.sparse import csr_array
    from scipy.sparse.csgraph import connected_components

    index = {n: i for i, n in enumerate(numbers)}
    rows = [index[n] for n in numbers for m in needs[n]]
    cols = [index[m] for n in numbers for m in needs[n]]
    graph = csr_array(([1] * len(rows), (rows, cols)), shape=(len(numbers),) * 2)
    _, label = connected_components(graph, directed=True, connection="strong")
    members: dict[int, list[int]] = {}
    for n in numbers:
        members.setdefault(int(label[index[n]]), []).append(n)
    condensed = {lab: {int(label[index[m]]) for n in group for m in needs[n]} - {lab}
                 for lab, group in members.items()}
    return [tuple(members[lab]) for lab in TopologicalSorter(condensed).static_order()]
