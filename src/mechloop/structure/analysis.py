"""Structural analysis of a model: solve it, build its mechanism, analyse the structure."""

from __future__ import annotations

from dataclasses import replace

from mechloop.dynamics.mechanism import build_mechanism
from mechloop.dynamics.points import Placement
from mechloop.model.schema import Model
from mechloop.solve.kinematics import solve
from mechloop.solve.results import Results
from mechloop.structure.assur import Decomposition, decompose
from mechloop.structure.meshes import gear_meshes, replaced
from mechloop.structure.mobility import Mobility, mobility


def analyze(model: Model, results: Results | None = None) -> tuple[Mobility, Decomposition]:
    """Mobility and decomposition of ``model`` (which needs ``bodies``), with the assembly
    variants of its groups taken from its contours; ``results``: its kinematics when
    already solved (else solved here).

    A ratio link between two bodies is a gear mesh, a higher pair (:mod:`.meshes`):
    counted as ``p4``, and replaced by its equivalent link with two revolute pairs for the
    decomposition (named in the decomposition's notes).

    A model with spatial contours has :func:`mechloop.structure.spatial.spatial_structure`
    instead (HintedError here).  Raises :class:`~mechloop.errors.ModelError` when the model
    has no bodies or its pairs cannot be told (see
    :func:`~mechloop.dynamics.mechanism.build_mechanism`).
    """
    if any(c.spatial for c in model.contours):  # issue 17: Somov–Malyshev instead
        from mechloop.errors import HintedError

        raise HintedError("the planar structural analysis (Chebyshev's count, Assur groups) "
                          "does not apply to a model with spatial contours",
                          "use mechloop.structure.spatial.spatial_structure(model)")
    meshes = gear_meshes(model)
    results = solve(model) if results is None else results
    mechanism = build_mechanism(model, Placement(results), determinate=False)
    equivalent, notes = replaced(mechanism, meshes)
    dec = decompose(equivalent, structure=results.structure)
    if notes:
        dec = replace(dec, notes=(*notes, *dec.notes))
    return mobility(mechanism, meshes), dec
