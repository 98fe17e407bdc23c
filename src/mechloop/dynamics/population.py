"""The dynamics of a population of designs of one model in one pass: ``(D, P)``.

The force analysis of :func:`~mechloop.dynamics.analysis.analyze` works position by
position on arrays over positions, so ``D`` designs × ``P`` positions of one model are
solved as the ``D·P`` positions of one long axis by that same function — the one
:func:`~mechloop.dynamics.analysis.solve_dynamics` runs for one design.  This module only
lays a population out on that axis: the kinematics of the designs
(:func:`~mechloop.solve.designs.solve_designs`, and with ``analogs_of`` the analogs of each
drive) flattened into :class:`~mechloop.solve.results.Results` whose every parameter —
constants included, since they differ between designs — is a ``(D·P,)`` array, each
design's fixed start of a contour (``startK.x/y``), and each design's ``inertia: rod``
(:func:`~mechloop.dynamics.mechanism.design_masses`).  ``analyze(..., designs=D)`` then
iterates friction per design, and gives the summary and the machine's cycle per design.

What is the same for every design is compiled once from a reference design (``mechanism``,
from :func:`~mechloop.dynamics.analysis.compile_mechanism` of a design that assembles):
the bodies, the kinematic pairs (inferred or named) and the drives.  These follow from the
roles of the vectors, not from their values, except at degenerate designs (two pins made
to coincide).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.dynamics.analysis import DynamicResults, analyze
from mechloop.dynamics.mechanism import Mechanism, design_masses
from mechloop.model.schema import Model
from mechloop.model.units import to_si
from mechloop.solve.designs import DesignResults, solve_designs
from mechloop.solve.results import Results

Complex = NDArray[np.complex128]


def solve_population(model: Model, overrides: Mapping[str, ArrayLike],
                     reference: Results, mechanism: Mechanism, *,
                     starts: Mapping[int, tuple] | None = None,
                     kinematics: DesignResults | None = None,
                     flywheel: bool = True, summary: bool = True) -> DynamicResults:
    """The dynamics of ``D`` designs of ``model`` on one axis of designs × positions.

    ``overrides`` are as for :func:`~mechloop.solve.designs.solve_designs` (SI, ``(D,)``);
    ``starts`` maps a contour's number to the ``(x, y)`` of its fixed start per design
    (m, arrays ``(D,)``, None for a coordinate the designs keep); ``kinematics`` the
    solve of these designs with derivatives (solved here when not given); ``reference``
    the kinematics of a design of the model and ``mechanism`` its mechanism
    (:func:`~mechloop.dynamics.analysis.compile_mechanism`).

    Returns what ``analyze(..., designs=D)`` returns: every array over the ``D·P``
    positions of the long axis, design after design (reshape to ``(D, P)``), the summary
    and the cycle per design (friction always on; a design whose friction does not
    settle or whose cycle cannot be computed is marked, not raised).  ``flywheel=False``
    leaves out the flywheel of a machine model, ``summary=False`` the work over the
    cycle.
    """
    if kinematics is None:
        kinematics = solve_designs(model, overrides, derivatives=True)
    n_designs, n_pos = kinematics.broken.shape
    if kinematics.positions is not None or n_pos != model.positions + 1 \
            or not kinematics.derivatives:
        raise ValueError("the dynamics need the kinematics of every position with their "
                         "derivatives: solve_designs(model, overrides, derivatives=True)")
    kin = flat_results(reference, kinematics)
    return analyze(model, kin, design_masses(model, mechanism, kin, n_designs),
                   lambda k: flat_results(reference, solve_designs(model, overrides,
                                                                   analogs_of=k), k),
                   starts=_starts(model, starts or {}, n_pos), designs=n_designs,
                   flywheel=flywheel, summary=summary)


def flat_results(reference: Results, designs: DesignResults,
                 analogs_of: int | None = None) -> Results:
    """A :class:`Results` whose positions are the designs × positions ``(D·P,)`` of
    ``designs`` (tables ``(D, P)``, with derivatives); what is the same for every design
    (the structure, which parameters are constant) from ``reference``."""
    n_designs = designs.broken.shape[0]
    return Results(
        model=designs.model, structure=reference.structure,
        time=None if designs.time is None else np.tile(designs.time, n_designs),
        arguments={k: np.tile(v, n_designs) for k, v in designs.arguments.items()},
        argument_kinds=reference.argument_kinds,
        values={k: _flatten(v) for k, v in designs.values.items()},
        rates={k: _flatten(v) for k, v in designs.rates.items()},
        accels={k: _flatten(v) for k, v in designs.accels.items()},
        constant=reference.constant, broken=_flatten(designs.broken),
        analogs_of=analogs_of)


def _flatten(table: NDArray) -> NDArray:
    return np.ascontiguousarray(table).reshape(-1)


def _starts(model: Model, varied: Mapping[int, tuple], n_pos: int) -> dict[int, Complex]:
    """Contour index -> its start per design and position ``(D·P,)`` (m), for contours
    whose fixed start a design varies."""
    out = {}
    for number, (x, y) in varied.items():
        fixed = model.contours[number - 1].start
        x0, y0 = (to_si(c, "length", model.units.length) for c in fixed)
        xs = np.full(len(x if x is not None else y), x0) if x is None else x
        ys = np.full(len(xs), y0) if y is None else y
        out[number - 1] = np.repeat(xs + 1j * ys, n_pos)
    return out


__all__ = ["flat_results", "solve_population"]
