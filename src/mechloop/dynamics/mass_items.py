"""The mass items of a body (the body and each of its ``parts``) and where their centres
of mass lie: read alike by the planar mechanism (:mod:`mechloop.dynamics.mechanism`) and
by models with spatial contours (:mod:`mechloop.spatial.dynamics`), which then check the
centre and the inertia each in its own way.
"""

from __future__ import annotations

from typing import Any

from mechloop.errors import Problem
from mechloop.model.dynamic import PointOn, point_vector

#: ``(path, mass, inertia, center)``: the YAML path of an item and its values as written
#: (model units; ``center`` None where not given).
MassItem = tuple[tuple[Any, ...], Any, Any, PointOn | None]


def mass_items(number: int, body: Any) -> list[MassItem]:
    """Body ``number``'s mass items: the body itself, then each of its ``parts``."""
    path = ("bodies", number)
    items: list[MassItem] = [(path, body.mass, body.inertia, body.center)]
    items += [((*path, "parts", i), p.mass, p.inertia, p.center)
              for i, p in enumerate(body.parts)]
    return items


def center_vector(number: int, body: Any, item: MassItem, mass: float,
                  problems: list[Problem]) -> int | None:
    """The vector of body ``number`` that carries the centre of mass of ``item`` (its
    mass ``mass`` in kg), or None: where the item has no centre (a problem if it has a
    mass or an inertia) or its centre lies on a vector the body does not list (a
    problem)."""
    where, _, inertia, center = item
    if center is None:
        if mass > 0 or inertia != 0:
            problems.append(Problem(where, f"body {number} has a mass but no centre "
                                    "of mass", "add center: {vector: K, share: 0.5}"))
        return None
    v = point_vector(center)
    if v not in body.vectors:
        problems.append(Problem((*where, "center"), f"the centre of mass is on vector "
                                f"{v}, which is not in body {number}",
                                f"place it on one of {body.vectors}"))
        return None
    return v
