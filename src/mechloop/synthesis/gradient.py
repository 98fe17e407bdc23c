"""The Jacobian of a synthesis problem's residuals with respect to the design variables.

The rows that measure the target — the x and y errors of the tracing point at the
targets of a timed path (given or free timing) — are differentiated exactly:
:func:`mechloop.solve.sensitivity.position_tangents` gives every parameter's derivative
from the contours' own Jacobians (implicit differentiation), and the tracing point, a sum
of vectors from a start, has as derivative the same sum of the vectors' derivatives
``(dr + i r dα) e^{iα}``, laid by the same placement code.  The penalty rows (square
roots of the penalties) are differentiated by forward differences, in one vectorized
call, and only where a penalty is not zero at the design (a zero penalty contributes a
zero row: it is flat on the feasible side).

Other targets (a curve without timing, a function, poses) have no exact Jacobian here:
:func:`exact_jacobian_available` says which.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.solve.sensitivity import override_seeds, position_tangents
from mechloop.synthesis.problem import SynthesisProblem, _place

Array = NDArray[np.float64]


def exact_jacobian_available(problem: SynthesisProblem) -> bool:
    """Whether the problem's target rows have an exact Jacobian: a path with timing
    (given positions or free timing) on a model whose only argument is argument 1 when
    the timing is free (another argument would be interpolated over it)."""
    if problem.target_kind != "path":
        return False
    if problem.free_timing:
        return set(problem.model.arguments) == {1}
    return problem.target_positions is not None


@dataclass(frozen=True)
class _Tangents:
    """What :func:`_place` reads: ``values`` and the shape of ``broken``."""

    values: dict[str, Array]
    broken: NDArray[np.bool_]


def point_tangents(problem: SynthesisProblem, designs: Array) -> tuple[
        NDArray[np.complex128], NDArray[np.complex128]]:
    """The tracing point at the targets and its derivative with respect to each design
    variable: ``(z, dz)``, shapes ``(D, K)`` and ``(V, D, K)``, SI (m, m per SI unit of
    the variable; x + iy).  NaN where a design breaks at a target."""
    variables = problem.variables
    n_var = len(variables)
    if problem.free_timing:
        _, at = problem.solve_at_inputs(designs)
        values = at.values
        inputs = designs[:, variables.input_columns]
        k = inputs.shape[1]
        seeds, starts = override_seeds(problem.model, variables, designs, inputs=inputs,
                                       positions=k)
        z = problem.place(at, designs, problem.point)
    else:
        res = problem.solve(designs)
        cols = problem.target_positions
        values = {name: np.asarray(v)[:, cols] for name, v in res.values.items()}
        seeds, starts = override_seeds(problem.model, variables, designs)
        z = problem.place(res, designs, problem.point)[:, cols]
    tangents = position_tangents(problem.model, values, seeds, n_var)
    n_designs, k = z.shape
    flat = (n_var * n_designs, k)
    fake: dict[str, Array] = {}
    for number in problem.model.vectors:
        r = np.broadcast_to(values[f"r{number}"], (n_designs, k))[None]
        a = np.broadcast_to(values[f"a{number}"], (n_designs, k))[None]
        dv = (tangents[f"r{number}"] + 1j * r * tangents[f"a{number}"]) * np.exp(1j * a)
        fake[f"r{number}"] = np.abs(dv).reshape(flat)
        fake[f"a{number}"] = np.angle(dv).reshape(flat)
    start_tangents: dict[int, tuple[Array, Array]] = {}
    for index, contour in enumerate(problem.model.contours):
        if isinstance(contour.start, tuple | list):
            dx, dy = starts.get(index + 1, (np.zeros((n_var, n_designs)),) * 2)
            start_tangents[index + 1] = (dx.reshape(-1), dy.reshape(-1))
    dz = _place(problem.model, _Tangents(fake, np.zeros(flat, dtype=bool)),
                start_tangents, problem.point)
    return z, dz.reshape(n_var, n_designs, k)


def residual_jacobian(problem: SynthesisProblem, design: Array, step: float = 1e-7
                      ) -> tuple[Array, Array]:
    """The residuals of one design ``(V,)`` (SI; :meth:`SynthesisProblem.residuals`)
    and their Jacobian ``(R, V)`` per SI unit of each variable: the target rows exact,
    the penalty rows by forward differences of ``step`` (relative to each variable's
    span) where the penalty is not zero.  Raises ValueError where
    :func:`exact_jacobian_available` is false."""
    if not exact_jacobian_available(problem):
        raise ValueError("no exact Jacobian for this target (a path with timing only)")
    design = np.asarray(design, dtype=float)
    res = problem.residuals(design[None, :])[0]
    _, dz = point_tangents(problem, design[None, :])
    error = dz[:, 0, :] / problem.length_unit  # (V, K)
    if problem.weights is not None:
        error = error * problem.weights[None, :]
    k = error.shape[1]
    jac = np.zeros((res.size, design.size))
    jac[:k] = error.real.T
    jac[k:2 * k] = error.imag.T
    penalty = slice(2 * k, res.size)
    if res.size > 2 * k and np.any(res[penalty] != 0):
        variables = problem.variables
        steps = step * (variables.high - variables.low)
        steps = np.where(design + steps <= variables.high, steps, -steps)
        probes = design[None, :] + np.diag(steps)
        moved = problem.residuals(probes)[:, penalty]
        jac[penalty] = ((moved - res[penalty][None, :]) / steps[:, None]).T
    return res, jac





#: The crank guard keeps the Grashof margin and the crank's lead over the other links
#: above this share of the four links' total length.
GUARD_SHARE = 1e-3
#: Weight of a guard row (a length in the model's unit times this).
GUARD_WEIGHT = 10.0


class CrankGuard:
    """Rows that keep a local search off the edge of a four-bar's full crank rotation.

    For a model with a four-bar contour (:func:`mechloop.synthesis.atlas.
    fourbar_contour`) whose crank turns a full turn over the positions and whose links
    are design variables, two residual rows: ``w · max(0, τ − m)`` for the Grashof margin
    ``m = p + q − s − l`` and for the crank's lead ``min(other links) − crank``, with
    ``τ`` = :data:`GUARD_SHARE` of the links' total and ``w`` = :data:`GUARD_WEIGHT`, in
    the model's length unit, with their exact Jacobian.  They are zero wherever the
    crank turns fully with some margin, so a design with zero error there keeps zero
    residual; they only stop the least squares from sliding to the Grashof limit, where
    the chain breaks (the designs it ends at are scored by the problem itself, without
    these rows).
    """

    def __init__(self, problem: SynthesisProblem, vectors: tuple[int, int, int, int]):
        from mechloop.model.units import to_si

        self.problem = problem
        self.names = [f"r{n}" for n in vectors]  # crank, coupler, rocker, frame
        model = problem.model
        self.fixed = np.array([to_si(model.vectors[n].r, "length", model.units.length)
                               for n in vectors])

    @classmethod
    def of(cls, problem: SynthesisProblem) -> CrankGuard | None:
        from mechloop.synthesis.atlas import fourbar_contour
        from mechloop.synthesis.variables import input_range

        found = fourbar_contour(problem.model)
        if found is None or 1 not in problem.model.arguments:
            return None
        _, _, lowest, highest = input_range(problem.model)
        if highest - lowest < 2 * np.pi * (1 - 1e-9):  # the crank need not turn fully
            return None
        guard = cls(problem, found[1:])
        return guard if any(n in problem.variables.overrides(
            problem.variables.low[None, :]) for n in guard.names) else None

    def rows(self, design: Array) -> tuple[Array, Array]:
        """The two rows ``(2,)`` and their Jacobian ``(2, V)`` (per SI unit)."""
        variables = self.problem.variables
        over = variables.overrides(design[None, :])
        seeds, _ = override_seeds(self.problem.model, variables, design[None, :])
        unit = self.problem.length_unit
        lengths = np.array([over[n][0] if n in over else f
                            for n, f in zip(self.names, self.fixed, strict=True)]) / unit
        grads = np.array([seeds[n][:, 0, 0] if n in seeds else np.zeros(len(variables))
                          for n in self.names]) / unit  # (4, V)
        total = lengths.sum()
        tau = GUARD_SHARE * total
        i_max, i_min = int(np.argmax(lengths)), int(np.argmin(lengths))
        g1 = np.ones(4)
        g1[i_max] -= 2.0
        g1[i_min] -= 2.0
        m1 = float(g1 @ lengths)
        j = 1 + int(np.argmin(lengths[1:]))
        g2 = np.zeros(4)
        g2[j], g2[0] = 1.0, -1.0
        m2 = float(g2 @ lengths)
        rows = np.zeros(2)
        jac = np.zeros((2, len(variables)))
        for k, (m, g) in enumerate(((m1, g1), (m2, g2))):
            if tau - m > 0:
                rows[k] = GUARD_WEIGHT * (tau - m)
                jac[k] = GUARD_WEIGHT * ((GUARD_SHARE * np.ones(4) - g) @ grads)
        return rows, jac
__all__ = ["CrankGuard", "exact_jacobian_available", "point_tangents", "residual_jacobian"]
