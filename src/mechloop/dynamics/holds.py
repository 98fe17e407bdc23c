"""Which bodies hold the ends of the vectors, and where two bodies meet in a contour.

Shared by the planar mechanism (:func:`mechloop.dynamics.mechanism.build_mechanism`) and
the structure of models with spatial contours (:mod:`mechloop.structure.spatial`): both
infer the kinematic pairs a model does not name in ``joints:`` from the bodies that hold
the point where one vector of a contour ends and the next starts.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Collection, Iterator

from mechloop.errors import Problem
from mechloop.model.schema import Model

#: ``(vector, "tail" | "head")`` → the bodies (0: the ground) that hold that end.
Holds = dict[tuple[int, str], set[int]]


def vector_holds(model: Model, constant: Collection[str], *, letters: str = "ra") -> Holds:
    """Which bodies hold each end of each vector.

    A body holds both ends of its vectors of constant length (``r{v}`` in ``constant``,
    the names of the parameters constant over the positions) and, of a sliding one, the
    end its ``ends`` names (the tail by default).  The ground (0) holds both ends of a
    vector in no body whose parameters ``letters`` are all constant (``"ra"`` in the
    plane, ``"rab"`` with spatial contours).
    """
    holds: Holds = defaultdict(set)
    member: set[int] = set()
    for number, body in model.bodies.items():
        for v in body.vectors:
            member.add(v)
            if f"r{v}" in constant:
                holds[(v, "tail")].add(number)
                holds[(v, "head")].add(number)
            else:
                holds[(v, body.ends.get(v, "tail"))].add(number)
    for v in model.vectors:
        if v not in member and all(f"{k}{v}" in constant for k in letters):
            holds[(v, "tail")].add(0)
            holds[(v, "head")].add(0)
    return holds


def shared_junctions(model: Model, holds: Holds, problems: list[Problem]
                     ) -> Iterator[tuple[int, tuple[int, int]]]:
    """The points of the contours where one vector ends and the next starts that exactly
    two bodies hold: ``(v, (b1, b2))`` per point, ``v`` the signed entry of the vector
    that starts there (``−K``, a subtracted vector of a spatial contour, runs from K's
    head to its tail, so the point is K's head) and ``b1 < b2`` the bodies.  A point
    held by more than two bodies is ambiguous: a problem is appended and it is skipped.
    """
    for ci, contour in enumerate(model.contours):
        vectors = contour.vectors
        for i, v in enumerate(vectors):
            before = vectors[i - 1]
            leaving = (before, "head") if before > 0 else (-before, "tail")
            entering = (v, "tail") if v > 0 else (-v, "head")
            owners = holds.get(leaving, set()) | holds.get(entering, set())
            if len(owners) < 2:
                continue
            if len(owners) > 2:
                problems.append(Problem(
                    ("contours", ci, "vectors", i),
                    f"bodies {', '.join(map(str, sorted(owners)))} all hold the point where "
                    f"vector {abs(before)} ends and vector {abs(v)} starts: which pairs they "
                    "form is ambiguous", "name the kinematic pairs in joints:"))
                continue
            b1, b2 = sorted(owners)
            yield v, (b1, b2)
