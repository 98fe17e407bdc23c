"""The links of a spatial model without bodies, taken from its vectors (issue 17).

A model with spatial contours and no ``bodies:`` still describes a chain of links when
every vector keeps its length: a vector whose r, α and β are all constant belongs to the
ground 0; every other vector is a link of its own, joined into one link with the vectors
whose angles it is linked to (``a: {link: a3}``: the chain of links of its parameters),
which must then turn together (a constant angle between them at every position).  With
these links as bodies the pairs are found and classified as for a model with bodies
(:func:`mechloop.structure.spatial.spatial_pairs`): where two links of one vector each
meet, the pair is spherical (a rod has no spin the contours decide) — the RSSR read from
its four vectors is the RSSR of its bodies.

A vector that changes length (a slider, a piston, a coordinate along a guide) does not
tell which links hold its two ends, and a link chain whose vectors turn relative to each
other is no rigid link: the structure is then not defined by the contours alone and the
model is refused with the fix (name the bodies).
"""

from __future__ import annotations

import numpy as np

from mechloop.errors import ModelError, Problem
from mechloop.model.dynamic import Body
from mechloop.model.schema import LinkRole, Model
from mechloop.spatial.bodies import RIGID_TOL
from mechloop.structure.spatial import SpatialPair, spatial_pairs

#: The fix of every refusal here.
FIX = ("add bodies: naming the vectors of each link (with ends: {K: head} for the link "
       "that holds the head of a vector K of varying length), and joints: for its pairs")


def _groups(model: Model, moving: list[int]) -> dict[int, int]:
    """Each moving vector's group: the smallest vector joined to it through angle links."""
    parent = {v: v for v in moving}

    def root(v: int) -> int:
        while parent[v] != v:
            v = parent[v]
        return v

    for v in moving:
        vector = model.vectors[v]
        for letter in ("a", "b"):
            role = getattr(vector, letter, None)
            if isinstance(role, LinkRole):
                w = int(role.link[1:])
                if w in parent:
                    low, high = sorted((root(v), root(w)))
                    parent[high] = low
    return {v: root(v) for v in moving}


def _rigid(model: Model, results, members: dict[int, list[int]],
           problems: list[Problem]) -> None:
    """A problem for each vector of a link that turns relative to the link's first."""
    from mechloop.spatial.points import unit_direction

    ok = ~np.asarray(results.broken, dtype=bool)
    for vectors in members.values():
        first = unit_direction(results, vectors[0]).p[:, ok]
        for v in vectors[1:]:
            cos = np.einsum("ip,ip->p", first, unit_direction(results, v).p[:, ok])
            if cos.size and np.ptp(cos) > RIGID_TOL:
                letter = next(x for x in "ab" if isinstance(getattr(model.vectors[v], x,
                                                                   None), LinkRole))
                problems.append(Problem(
                    ("vectors", v, letter), f"the model has no bodies, and vector {v}, "
                    f"linked to vector {vectors[0]}, turns relative to it: the two are no "
                    "rigid link, so the contours alone do not give the structure", FIX))


def vector_pairs(model: Model, results) -> tuple[tuple[int, ...], list[SpatialPair],
                                                 dict[int, bool],
                                                 dict[int, tuple[int, ...]]]:
    """The moving links (numbered 1, 2, ... by their first vector), the pairs, which links
    are rods and each link's vectors, for ``model`` without bodies (see the module).

    Raises :class:`~mechloop.errors.ModelError` when the contours alone do not define
    the structure."""
    constant = results.constant
    problems = [Problem(("vectors", v, "r"), f"the model has no bodies, and vector {v} "
                        "changes length: the contours alone do not tell which links hold "
                        "its ends (a slider on its guide, a piston in its cylinder)", FIX)
                for v in model.vectors if f"r{v}" not in constant]
    if problems:
        raise ModelError(problems)
    moving = [v for v in sorted(model.vectors)
              if not all(f"{k}{v}" in constant for k in "rab")]
    group = _groups(model, moving)
    firsts = sorted(set(group.values()))
    members = {i + 1: [v for v in moving if group[v] == g] for i, g in enumerate(firsts)}
    _rigid(model, results, members, problems)
    if problems:
        raise ModelError(problems)
    bodies = {n: Body(vectors=vectors) for n, vectors in members.items()}
    try:
        links, pairs, rods = spatial_pairs(model.model_copy(update={"bodies": bodies}),
                                           results)
    except ModelError as exc:
        raise ModelError([_unbodied(p, members) for p in exc.problems]) from None
    return links, pairs, rods, {n: tuple(v) for n, v in members.items()}


def _unbodied(problem: Problem, members: dict[int, list[int]]) -> Problem:
    """A problem of the pairs found from links taken from the vectors, said so."""
    if problem.path[:1] == ("bodies",):  # a link joined to nothing
        link = problem.path[1]
        return Problem(("contours",), f"the model has no bodies, and the link of vectors "
                       f"{', '.join(map(str, members[link]))} is joined to the ground by no "
                       "pair the contours give", FIX)
    return Problem(problem.path, "the model has no bodies, and three or more links taken "
                   "from its vectors meet at one point of a contour: which pairs they form "
                   "is ambiguous", FIX)
