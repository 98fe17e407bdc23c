"""Gear meshes of a model: higher pairs (p4) between bodies linked by a ratio.

A vector of body ``j`` whose angle is linked with a ratio ``k ≠ 1`` to a vector of body
``i`` (``α_j = k·α_i + Δ``) imposes one condition between the two bodies: the gear mesh,
a higher pair of the fourth class (one condition, two freedoms left).  Chebyshev's count
takes it as ``p4``.  A ratio link that is not a physical mesh — the carrier of a planetary
train linked to its sun by Willis' ratio, or two gears joined through idlers that are not
bodies — is one condition between the two bodies all the same, so the count holds; it is
reported the same way, "gear mesh (ratio link)", with its ratio.

For the decomposition into Assur groups each higher pair is replaced by its standard
structural equivalent (seed 002; any TMM text): a link with two revolute pairs joining the
two bodies (at the centres of curvature of the profiles in contact, for involute teeth the
points where the line of action touches the base circles).  The equivalent adds
``3 − 2·2 = −1`` to W, exactly as the higher pair does, so the mobility is unchanged; the
equivalent links are numbered after the model's bodies and named in the notes.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from mechloop.dynamics.mechanism import Mechanism, Pair
from mechloop.errors import ModelError, Problem
from mechloop.model.dynamic import TailPoint
from mechloop.model.schema import LinkRole, Model


@dataclass(frozen=True)
class Mesh:
    """A ratio link between two bodies: ``bodies = (source body, linked body)``, the
    linked angle ``a{vector} = ratio·a{source} + Δ`` (ratio composed along links through
    vectors that are in no body)."""

    bodies: tuple[int, int]
    ratio: float
    vector: int
    source: int

    def __str__(self) -> str:
        return (f"gear mesh (ratio link) between bodies {self.bodies[0]} and "
                f"{self.bodies[1]}, ratio {self.ratio:g} (a{self.vector} = "
                f"{self.ratio:g}·a{self.source} + Δ): a higher pair p4")


def gear_meshes(model: Model) -> tuple[Mesh, ...]:
    """Every ratio link between two bodies of ``model`` (see the module docstring).

    Raises :class:`~mechloop.errors.ModelError` (located at the ratio) when the link's
    source, followed through links, reaches no body: the mesh's other member is unknown.
    """
    body_of = {v: b for b, body in model.bodies.items() for v in body.vectors}
    found, problems = [], []
    for n, vector in sorted(model.vectors.items()):
        role = vector.a
        if n not in body_of or not isinstance(role, LinkRole) or role.ratio == 1:
            continue
        ratio, current = float(role.ratio), int(role.link[1:])
        while current not in body_of:
            nxt = model.vectors[current].a
            if not isinstance(nxt, LinkRole):
                break
            ratio *= float(nxt.ratio)
            current = int(nxt.link[1:])
        if current not in body_of:
            problems.append(Problem(
                ("vectors", n, "a", "ratio"),
                f"a{n} (body {body_of[n]}) is linked with a ratio to a{current}, which is in "
                "no body: the gear it meshes with is not a link of the mechanism",
                f"add vector {current} to the body of the driving gear"))
            continue
        if body_of[current] != body_of[n]:
            found.append(Mesh((body_of[current], body_of[n]), ratio, n, current))
    if problems:
        raise ModelError(problems)
    return tuple(found)


def replaced(mechanism: Mechanism, meshes: tuple[Mesh, ...]) -> tuple[Mechanism, list[str]]:
    """``mechanism`` with every mesh replaced by a link with two revolute pairs (numbered
    after the largest link), and one note per replacement.  The pairs' points are not
    geometry (the structure reads only the graph): the replacement is for counting and
    grouping, never for forces."""
    if not meshes:
        return mechanism, []
    links = set(mechanism.bodies)
    for p in mechanism.pairs:
        links.update(p.bodies)
    for d in mechanism.drives:
        links.update(d.bodies)
    nxt = max(links) + 1
    pairs = list(mechanism.pairs)
    notes = []
    for mesh in meshes:
        i, j = mesh.bodies
        pairs += [Pair(f"N{i}_{nxt}", "revolute", (i, nxt), TailPoint(tail=mesh.source),
                       None, 0.0, 0.0, 0.0, True),
                  Pair(f"N{nxt}_{j}", "revolute", (nxt, j), TailPoint(tail=mesh.vector),
                       None, 0.0, 0.0, 0.0, True)]
        notes.append(f"the gear mesh between bodies {i} and {j} is replaced by its "
                     f"equivalent, link {nxt} with revolute pairs N{i}_{nxt} and "
                     f"N{nxt}_{j} (at the centres of curvature of the teeth in contact)")
        nxt += 1
    return replace(mechanism, pairs=tuple(pairs)), notes
