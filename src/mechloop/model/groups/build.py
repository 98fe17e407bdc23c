"""Building a group mechanism: its vector model, the locations of its points and the
parameters that carry its dimensions.
"""

from __future__ import annotations

from mechloop.errors import ModelError, Problem
from mechloop.model.groups.builder import Builder
from mechloop.model.groups.core import _choose
from mechloop.model.groups.located import BuiltModel, Carrier, PointLocation
from mechloop.model.groups.spec import GroupMechanism
from mechloop.model.schema import Model


def build_model(mech: GroupMechanism) -> Model:
    """The vector model of ``mech``.

    Raises :class:`~mechloop.errors.ModelError` listing every problem, each with its path
    in the mechanism's document and the fix.

    >>> mech = GroupMechanism.model_validate({
    ...     "positions": 36, "arguments": {1: {"table": {0: 0, 36: 360}}},
    ...     "ground": {"O": [0, 0], "C": [0.3, 0]},
    ...     "input": {"kind": "crank", "pivot": "O", "joint": "A", "length": 0.1},
    ...     "groups": [{"kind": "L1", "links": ["coupler", "rocker"], "at": ["A", "C"],
    ...                 "joint": "B", "lengths": [0.35, 0.25]}]})
    >>> model = build_model(mech)
    >>> [c.vectors for c in model.contours]
    [[1, 2, 3, 4]]
    >>> [model.vectors[k].name for k in (1, 2, 3, 4)]
    ['crank OA', 'coupler AB', 'rocker BC', 'frame CO']
    """
    return build(mech).model


def build(mech: GroupMechanism) -> BuiltModel:
    """The vector model of ``mech`` with its point locations and dimension carriers."""
    return Builder(mech).run()


def point_vectors(mech: GroupMechanism, model: Model, name: str) -> PointLocation:
    """Where point ``name`` of ``mech`` is in ``model`` — the model built from ``mech``,
    possibly with other constants (as synthesis varies them).

    ``Placement(results).point(location.end)`` (``mechloop.dynamics.points``) or
    ``location.xy(results)`` give its position over the positions.
    """
    built = build(mech)
    if [c.vectors for c in built.model.contours] != [c.vectors for c in model.contours] \
            or set(built.model.vectors) != set(model.vectors):
        raise ModelError([Problem((), "the model was not built from this mechanism: its "
                                  "vectors or contours differ",
                                  "pass the model that build_model(mech) returned (its "
                                  "constants may be changed, not its vectors)")])
    if name not in built.points:
        raise ModelError([Problem(("points",), f"no point named {name!r}",
                                  _choose(name, list(built.points)))])
    return built.points[name]


def dimension_parameters(mech: GroupMechanism) -> dict[str, tuple[Carrier, ...]]:
    """Which vector parameter carries each dimension of ``mech`` (see :class:`Carrier`),
    e.g. ``{"input.length": (Carrier("r1", "value"),), "points.P.angle":
    (Carrier("a5", "delta"),), ...}``.  The root ground point is carried by no parameter
    (it places the contours: their ``start``)."""
    return build(mech).dimensions


def dimension_names(mech: GroupMechanism) -> list[str]:
    """The dimensions of ``mech`` a synthesis may vary, as ``vary:`` names them."""
    builder = Builder(mech.model_copy(update={"synthesis": None}))
    builder.run()
    return builder.dimension_names()
