"""Structural analysis of a model: solve it, build its mechanism, analyse the structure."""

from __future__ import annotations

from mechloop.dynamics.mechanism import build_mechanism
from mechloop.dynamics.points import Placement
from mechloop.errors import ModelError, Problem
from mechloop.model.schema import LinkRole, Model
from mechloop.solve.kinematics import solve
from mechloop.structure.assur import Decomposition, decompose
from mechloop.structure.mobility import Mobility, mobility


def analyze(model: Model) -> tuple[Mobility, Decomposition]:
    """Mobility and decomposition of ``model`` (which needs ``bodies``), with the assembly
    variants of its groups taken from its contours.

    Raises :class:`~mechloop.errors.ModelError` when the model has no bodies or its pairs
    cannot be told (see :func:`~mechloop.dynamics.mechanism.build_mechanism`).
    """
    _refuse_gear_meshes(model)
    results = solve(model)
    mechanism = build_mechanism(model, Placement(results), determinate=False)
    return mobility(mechanism), decompose(mechanism, structure=results.structure)


def _refuse_gear_meshes(model: Model) -> None:
    """A body's angle linked with a ratio ≠ 1 is a gear mesh, a higher pair (p4), which
    the count and the decomposition into groups (lower pairs only) would take for a link
    with a mobility of its own: refused, located at the ratio, rather than answered
    wrongly."""
    in_body = {v for body in model.bodies.values() for v in body.vectors}
    problems = [Problem(("vectors", n, "a", "ratio"),
                        f"a{n} is linked to {vector.a.link} with ratio {vector.a.ratio:g}: a "
                        "gear mesh, a higher pair, which the structural analysis does not "
                        "count yet (it would report a wrong mobility)",
                        "solve the model (mechloop solve) for its kinematics; analyse the "
                        "structure of the linkage without the geared bodies")
                for n, vector in sorted(model.vectors.items())
                if n in in_body and isinstance(vector.a, LinkRole) and vector.a.ratio != 1]
    if problems:
        raise ModelError(problems)
