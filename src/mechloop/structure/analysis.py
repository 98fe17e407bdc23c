"""Structural analysis of a model: solve it, build its mechanism, analyse the structure."""

from __future__ import annotations

from mechloop.dynamics.mechanism import build_mechanism
from mechloop.dynamics.points import Placement
from mechloop.model.schema import Model
from mechloop.solve.kinematics import solve
from mechloop.structure.assur import Decomposition, decompose
from mechloop.structure.mobility import Mobility, mobility


def analyze(model: Model) -> tuple[Mobility, Decomposition]:
    """Mobility and decomposition of ``model`` (which needs ``bodies``), with the assembly
    variants of its groups taken from its contours.

    Raises :class:`~mechloop.errors.ModelError` when the model has no bodies or its pairs
    cannot be told (see :func:`~mechloop.dynamics.mechanism.build_mechanism`).
    """
    results = solve(model)
    mechanism = build_mechanism(model, Placement(results), determinate=False)
    return mobility(mechanism), decompose(mechanism, structure=results.structure)
