"""Decomposition of a mechanism into input groups L0 and Assur groups (seed 002, part 1).

The mechanism is read as a graph: links are the ground 0 and the moving bodies, edges are
the constraints between them —

* a lower pair removes two degrees of freedom (a revolute R or a prismatic P pair; a P pair
  also fixes the relative rotation);
* a drive removes one once its argument is given: an ``angle`` drive fixes the angle of
  its link relative to the ground; a ``length`` drive (a hydraulic cylinder) fixes the
  distance between its two attachment points.  The cylinder and rod are *not* links of the
  graph: they are a driving pair between the two bodies at their ends (with their three
  pairs they would add ``3·2 − 2·3 = 0`` to W).  Where the driven length runs along a
  prismatic pair of the same two bodies (cylinder and rod modelled as bodies), pair and
  drive together weld the two.

Groups are attached to the *placed* links (the ground first), smallest first: a set ``S``
of unplaced links is a group when its constraints to ``S`` and the placed links number
exactly ``3·|S|``, no proper part of it is already determined or over-constrained, and no
part has more rotation-fixing constraints (P pairs, angle drives) than links — the
counting (Laman–Tay) test of a rigid, minimal group; a chain of three P pairs fails it.
A group with a drive is an input group **L0** (the crank and the ground; the rocker and
its cylinder).  A group of two links without one is a class-II Assur group (a dyad);
larger groups are of class III or higher: the class is the number of pairs of the most
complex closed contour inside the group (a triad, whose links form no contour, is class
III).  Groups of the same size are taken in order of their link numbers, so the formula
reads as the seed's: ``L0(1) → L1(2,3) → L4(4,5) → …``.

**Kinds of dyads** are read from the pair letters *external pair of j, internal pair,
external pair of i* (seed, figs 1.20–1.23):

======  =====  ===========================================================================
kind    pairs  which link is ``i``
======  =====  ===========================================================================
L1      RRR    ``j`` is the link paired with the ground when exactly one is; else ``i`` is
               the lower-numbered link
L2      RRP    ``i`` has the external P pair (its guide is ``i−1``), ``j`` the external R
               (``PRR`` is the same group read from the other end)
L3      RPR    ``i`` is the guide (kulisa): the one link of the two that lists the slide's
               ``along`` vector; else the lower-numbered link
L4      PRP    as L1: ``j`` is the link guided by the ground when exactly one is
L5      RPP    ``i`` has the external P pair, ``j`` the external R (``PPR`` mirrored)
======  =====  ===========================================================================

The **assembly variant** of a group is taken from the vector model when one Pl3 or Pl4
contour solves exactly that group (its two functions are parameters of the group's links
or of its cylinder, and every link of the group has one); otherwise it is ``None``.

When no group can be attached, a link held by more constraints than it has freedoms by
the placed links alone is a *passive* link (a redundant constraint) and a link held only
by placed links with fewer is *free* (a local mobility); both are placed, noted, and the
search goes on.  Anything else left is the *rest*, reported and never forced into dyads.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from itertools import combinations

from mechloop.dynamics.mechanism import Mechanism
from mechloop.model.structure import Structure

#: The largest group searched, in links.  Assur groups of real mechanisms have 2 or 4.
MAX_GROUP = 8

DYAD_KINDS = {"RRR": "L1", "RRP": "L2", "RPR": "L3", "PRP": "L4", "RPP": "L5"}
ROMAN = ("", "I", "II", "III", "IV", "V", "VI", "VII", "VIII", "IX", "X")


@dataclass(frozen=True)
class Constraint:
    """An edge of the link graph: a lower pair (R, P; 2 conditions) or a drive (1).

    ``turns`` is the number of relative rotations it fixes (a P pair, an angle drive).
    """

    name: str
    kind: str  # 'R' | 'P' | 'angle' | 'length'
    links: tuple[int, int]
    weight: int
    turns: int
    argument: int | None = None
    along: int | None = None
    vector: int | None = None


@dataclass(frozen=True)
class GroupPair:
    """A lower pair of a group: ``link`` is the group's link, ``to`` the link it joins (a
    link placed earlier for an external pair, the other group link for an internal one)."""

    name: str
    kind: str  # 'R' | 'P'
    link: int
    to: int


@dataclass(frozen=True)
class Group:
    """An input group or an Assur group.

    ``kind`` is ``'L0'`` (an input group), ``'L1'`` … ``'L5'`` (class-II dyads), or the
    class in Roman numerals (``'III'``) for a group of a higher class; ``links`` are
    ``(i, j)`` for a dyad and in increasing order otherwise; ``pairs`` the letters of a
    dyad read *external of j, internal, external of i* (``'RRP'``), for other groups the
    letters of their external pairs; ``drives`` the arguments an input group takes;
    ``cylinders`` the links at the two ends of each of its length drives; ``variant`` the
    assembly variant from the vector model (``None`` when there is none or it cannot be
    told) and ``contour`` the contour it comes from.
    """

    kind: str
    assur_class: int
    links: tuple[int, ...]
    external: tuple[GroupPair, ...]
    internal: tuple[GroupPair, ...]
    pairs: str
    drives: tuple[int, ...] = ()
    cylinders: tuple[tuple[int, int], ...] = ()
    variant: int | str | None = None
    contour: int | None = None

    @property
    def label(self) -> str:
        """``L1(2,3)``: the kind and the links in increasing order."""
        return f"{self.kind}({','.join(map(str, sorted(self.links)))})"

    def partner(self, link: int) -> int | None:
        """The placed link that ``link`` is joined to by an external pair (the first one)."""
        return next((p.to for p in self.external if p.link == link), None)


@dataclass(frozen=True)
class Decomposition:
    """Groups in the order they attach, and what could not be decomposed.

    ``passive`` links over-constrained by the links placed before them, ``free`` links
    held by too few constraints, ``rest`` the links left when no group attaches, ``notes``
    one sentence per finding.
    """

    groups: tuple[Group, ...]
    rest: tuple[int, ...] = ()
    passive: tuple[int, ...] = ()
    free: tuple[int, ...] = ()
    notes: tuple[str, ...] = ()

    @property
    def formula(self) -> str:
        """The structure formula, ``L0(1) → L1(2,3) → L2(4,5)``; links left over as
        ``?(6,7)``."""
        parts = [g.label for g in self.groups]
        if self.rest:
            parts.append(f"?({','.join(map(str, self.rest))})")
        return " → ".join(parts)

    @property
    def mechanism_class(self) -> int | None:
        """The highest class of the groups (II for an all-dyad mechanism); ``None`` when
        links are left over or there are no groups."""
        if self.rest or not self.groups:
            return None
        return max(g.assur_class for g in self.groups)


def constraints(mechanism: Mechanism) -> list[Constraint]:
    """The edges of the link graph of ``mechanism`` (pairs, then drives)."""
    out = [Constraint(p.name, "R" if p.kind == "revolute" else "P", tuple(p.bodies), 2,
                      0 if p.kind == "revolute" else 1, along=p.along)
           for p in mechanism.pairs]
    for d in mechanism.drives:
        if d.kind == "angle":
            out.append(Constraint(f"argument {d.argument}", "angle", (0, d.bodies[1]), 1, 1,
                                  argument=d.argument, vector=d.vector))
        else:
            out.append(Constraint(f"argument {d.argument}", "length", tuple(d.bodies), 1, 0,
                                  argument=d.argument, vector=d.vector))
    return out


def moving_links(mechanism: Mechanism) -> list[int]:
    """Moving links: the bodies and any other link a pair or drive names, ground excluded."""
    named = set(mechanism.bodies)
    for p in mechanism.pairs:
        named.update(p.bodies)
    for d in mechanism.drives:
        named.update(d.bodies)
    return sorted(named - {0})


def decompose(mechanism: Mechanism, *, structure: Structure | None = None) -> Decomposition:
    """Decompose ``mechanism`` into input groups L0 and Assur groups, in attaching order.

    ``structure`` (``results.structure`` of the solved model) gives the groups their
    assembly variants; without it they are ``None``.

    >>> from mechloop.dynamics.mechanism import Drive, Mechanism, Pair
    >>> from mechloop.model.dynamic import TailPoint
    >>> pin = lambda a, b: Pair(f"J{a}_{b}", "revolute", (a, b), TailPoint(tail=1), None,
    ...                         0.0, 0.0, 0.0, False)
    >>> four_bar = Mechanism({}, (), (pin(0, 1), pin(1, 2), pin(2, 3), pin(0, 3)),
    ...                      (Drive(1, "angle", 1, (0, 1)),), 0.0)
    >>> decompose(four_bar).formula
    'L0(1) → L1(2,3)'
    """
    cons = constraints(mechanism)
    placed = {0}
    groups: list[Group] = []
    passive: list[int] = []
    free: list[int] = []
    notes: list[str] = []
    used: set[str] = set()
    while unplaced := [k for k in moving_links(mechanism) if k not in placed]:
        found = _next_group(cons, unplaced, placed)
        if found is not None:
            groups.append(_group(found, cons, placed, mechanism, structure))
            used.update(c.name for c in _touching(cons, set(found), placed))
            placed.update(found)
            continue
        stray = _stray_link(cons, unplaced, placed)
        if stray is None:
            break
        link, weight, turns, held = stray
        what = ", ".join(held)
        if weight > 3 or turns > 1:
            passive.append(link)
            notes.append(f"link {link} is held by {what} to links already placed: "
                         f"{weight} conditions on its 3 freedoms — a passive link, its extra "
                         f"constraint redundant")
        else:
            free.append(link)
            held_by = f"is held only by {what}" if held else "is joined to nothing"
            notes.append(f"link {link} {held_by}: it keeps {3 - weight} degree(s) of "
                         "freedom of its own — a local mobility")
        used.update(c.name for c in _touching(cons, {link}, placed))
        placed.add(link)
    rest = tuple(k for k in moving_links(mechanism) if k not in placed)
    if rest:
        weight, _ = _count(cons, set(rest), placed)
        spare = 3 * len(rest) - weight
        if spare > 0:
            notes.append(f"links {_listed(rest)} keep {spare} degree(s) of freedom: an input "
                         "is missing (or they have a local mobility)")
        elif spare < 0:
            notes.append(f"links {_listed(rest)} have {-spare} constraint(s) more than their "
                         "freedoms: a redundant constraint (an over-constrained chain)")
        else:
            notes.append(f"links {_listed(rest)} have as many constraints as freedoms but form "
                         "no rigid group: one part is over-constrained while another moves "
                         "(or a chain of prismatic pairs slides freely)")
    for c in cons:
        if c.argument is not None and c.name not in used and not set(c.links) & set(rest):
            notes.append(f"the drive of argument {c.argument} acts between links "
                         f"{c.links[0]} and {c.links[1]}, which are placed without it: a "
                         "redundant input")
    return Decomposition(tuple(groups), rest, tuple(passive), tuple(free), tuple(notes))


def _listed(links: Iterable[int]) -> str:
    return ", ".join(map(str, links))


def _touching(cons: list[Constraint], group: set[int], placed: set[int]) -> list[Constraint]:
    """Constraints with an end in ``group`` and both ends in ``group`` or ``placed``."""
    return [c for c in cons
            if (c.links[0] in group or c.links[1] in group)
            and all(k in group or k in placed for k in c.links)]


def _count(cons: list[Constraint], group: set[int], placed: set[int]) -> tuple[int, int]:
    """Conditions and rotation-fixing conditions on ``group`` from itself and ``placed``."""
    touching = _touching(cons, group, placed)
    return sum(c.weight for c in touching), sum(c.turns for c in touching)


def _is_group(cons: list[Constraint], links: tuple[int, ...], placed: set[int]) -> bool:
    size = len(links)
    weight, turns = _count(cons, set(links), placed)
    if weight != 3 * size or turns > size:
        return False
    for k in range(1, size):
        for part in combinations(links, k):
            weight, turns = _count(cons, set(part), placed)
            if weight >= 3 * k or turns > k:
                return False
    for k in range(2, size + 1):
        for part in combinations(links, k):
            weight, turns = _count(cons, set(part), set())
            if weight > 3 * (k - 1) or turns > k - 1:
                return False
    return True


def _components(cons: list[Constraint], links: list[int]) -> list[list[int]]:
    """The unplaced links in groups connected through constraints among themselves."""
    root = {k: k for k in links}

    def find(k: int) -> int:
        while root[k] != k:
            root[k] = root[root[k]]
            k = root[k]
        return k

    for c in cons:
        a, b = c.links
        if a in root and b in root:
            root[find(a)] = find(b)
    parts: dict[int, list[int]] = {}
    for k in links:
        parts.setdefault(find(k), []).append(k)
    return list(parts.values())


def _next_group(cons: list[Constraint], unplaced: list[int], placed: set[int]
                ) -> tuple[int, ...] | None:
    """The smallest group that attaches to ``placed`` (input groups, then lowest links)."""
    parts = _components(cons, unplaced)
    for size in range(1, MAX_GROUP + 1):
        found = [links for part in parts if len(part) >= size
                 for links in combinations(part, size) if _is_group(cons, links, placed)]
        if found:
            return min(found, key=lambda links: (
                not any(c.argument is not None for c in _touching(cons, set(links), placed)),
                links))
    return None


def _stray_link(cons: list[Constraint], unplaced: list[int], placed: set[int]
                ) -> tuple[int, int, int, list[str]] | None:
    """A link over-constrained by the placed links alone, else one held by placed links
    only (with too few conditions): (link, conditions, rotations fixed, constraint names)."""
    for k in unplaced:
        weight, turns = _count(cons, {k}, placed)
        if weight > 3 or turns > 1:
            return k, weight, turns, [c.name for c in _touching(cons, {k}, placed)]
    for k in unplaced:
        mine = [c for c in cons if k in c.links]
        if all(c.links[0] in placed or c.links[1] in placed for c in mine):
            weight, turns = _count(cons, {k}, placed)
            return k, weight, turns, [c.name for c in mine]
    return None


def _group(links: tuple[int, ...], cons: list[Constraint], placed: set[int],
           mechanism: Mechanism, structure: Structure | None) -> Group:
    group = set(links)
    touching = _touching(cons, group, placed)
    pairs = [c for c in touching if c.kind in "RP"]
    external = tuple(GroupPair(c.name, c.kind, *(c.links if c.links[0] in group
                                                  else c.links[::-1]))
                     for c in pairs if not set(c.links) <= group)
    internal = tuple(GroupPair(c.name, c.kind, *c.links) for c in pairs
                     if set(c.links) <= group)
    drives = [c for c in touching if c.argument is not None]
    variant, contour = _variant(group, drives, mechanism, structure)
    if drives:
        return Group("L0", _input_class(group, touching), tuple(sorted(links)), external,
                     internal, "".join(p.kind for p in external),
                     tuple(sorted(c.argument for c in drives)),
                     tuple(c.links for c in drives if c.kind == "length"), variant, contour)
    if len(links) == 2:
        i, j = _orient(links, external, internal[0], touching, mechanism)
        letters = (next(p.kind for p in external if p.link == j) + internal[0].kind
                   + next(p.kind for p in external if p.link == i))
        return Group(DYAD_KINDS[letters], 2, (i, j), external, internal, letters,
                     variant=variant, contour=contour)
    klass = max(3, _longest_cycle(c.links for c in pairs if set(c.links) <= group))
    return Group(ROMAN[klass] if klass < len(ROMAN) else str(klass), klass,
                 tuple(sorted(links)), external, internal,
                 "".join(p.kind for p in external), variant=variant, contour=contour)


def _orient(links: tuple[int, ...], external: tuple[GroupPair, ...], middle: GroupPair,
            touching: list[Constraint], mechanism: Mechanism) -> tuple[int, int]:
    """``(i, j)`` of a dyad by the conventions of the module docstring."""
    u, v = sorted(links)
    kind = {p.link: p.kind for p in external}
    if kind[u] != kind[v]:  # RRP, RPP and their mirror images: i has the external P
        return (u, v) if kind[u] == "P" else (v, u)
    if middle.kind == "P" and kind[u] == "R":  # RPR: i is the guide (kulisa)
        along = next(c.along for c in touching if c.name == middle.name)
        carriers = [k for k in (u, v) if k in mechanism.bodies
                    and along in mechanism.bodies[k].vectors]
        return (carriers[0], v if carriers[0] == u else u) if len(carriers) == 1 else (u, v)
    grounded = [k for k in (u, v) if any(p.link == k and p.to == 0 for p in external)]
    if len(grounded) == 1:  # RRR, PRP: j is the link paired with the ground
        return (v, u) if grounded[0] == u else (u, v)
    return u, v


def _input_class(group: set[int], touching: list[Constraint]) -> int:
    """Class of an input group: the crank (one link) is class I; otherwise the cylinder of
    each length drive counts as a link (a driven slide along a pair welds its two links)
    and the group is classed like an Assur group of those links."""
    placed = 0  # every placed link is one unit, the ground's
    unit = {k: k for k in group}

    def find(k: int) -> int:
        k = k if k in group or k < 0 else placed
        while unit.get(k, k) != k:
            k = unit[k]
        return k

    prismatic = {frozenset(c.links) for c in touching if c.kind == "P"}
    edges: list[tuple[int, int]] = []
    for n, c in enumerate(c for c in touching if c.kind == "length"):
        if frozenset(c.links) in prismatic:  # cylinder and rod are bodies: a weld
            a, b = find(c.links[0]), find(c.links[1])
            if a != b:
                unit[a if a != placed else b] = b if a != placed else a
        else:  # the cylinder is a link between the two bodies
            cylinder = -1 - n
            unit[cylinder] = cylinder
            edges += [(cylinder, k) for k in c.links]
    edges += [tuple(c.links) for c in touching if c.kind in "RP"]
    units = {find(k) for k in unit} - {placed}
    if len(units) <= 2:
        return max(len(units), 1)
    return max(3, _longest_cycle([(find(a), find(b)) for a, b in edges
                                  if placed not in (find(a), find(b))]))


def _longest_cycle(edges: Iterable[tuple[int, int]]) -> int:
    """Number of edges of the longest simple cycle of the graph (0 if none)."""
    adjacent: dict[int, set[int]] = {}
    for a, b in edges:
        if a != b:
            adjacent.setdefault(a, set()).add(b)
            adjacent.setdefault(b, set()).add(a)
    best = 0

    def walk(start: int, node: int, path: list[int]) -> None:
        nonlocal best
        for nxt in adjacent.get(node, ()):
            if nxt == start and len(path) >= 3:
                best = max(best, len(path))
            elif nxt not in path and nxt > start:
                walk(start, nxt, [*path, nxt])

    for start in adjacent:
        walk(start, start, [start])
    return best


def _variant(group: set[int], drives: list[Constraint], mechanism: Mechanism,
             structure: Structure | None) -> tuple[int | str | None, int | None]:
    """The assembly variant of the one Pl3/Pl4 contour that solves exactly this group."""
    if structure is None:
        return None, None
    owned: dict[int, set[int]] = {}
    for k in group:
        frame = mechanism.bodies.get(k)
        for v in frame.vectors if frame is not None else ():
            owned.setdefault(v, set()).add(k)
    cylinders = {c.vector for c in drives if c.kind == "length" and c.vector is not None}
    matches = []
    for contour in structure.contours:
        vectors = {int(f[1:]) for f in contour.functions}
        if not vectors <= set(owned) | cylinders:
            continue
        solved = set().union(*(owned.get(v, set()) for v in vectors))
        if solved == group:
            matches.append(contour)
    if len(matches) != 1 or matches[0].module not in ("Pl3", "Pl4"):
        return None, None
    return matches[0].variant, matches[0].number
