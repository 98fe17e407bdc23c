"""Derivatives of positions with respect to design constants, by implicit differentiation.

Each contour closes, ``F(u, p) = Σ r_i e(α_i) = 0``, for its two unknowns ``u`` given the
known parameters ``p``.  Differentiating along a direction of the design constants,

    J du = −(∂F/∂p) dp,

with ``J`` the contour's Jacobian — the same two columns (``e_j`` for an unknown length,
``r_j n_j`` for an unknown angle) and the same 2×2 solve as the velocities
(:func:`mechloop.solve.kinematics._solve_derivatives`): a tangent is a velocity whose
"time" is the design constant.  So the velocity solve itself is run, with every known
parameter's *rate* set to its derivative with respect to one design constant; the
contours are taken in their solving order, so that a solved contour's tangents feed the
next ones.  All directions and designs go at once: arrays ``(V, D, P)`` (directions,
designs, positions).  No finite differences.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
from numpy.typing import NDArray

from mechloop.model.check import require_valid
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.structure import is_function, param_role
from mechloop.solve.kinematics import (
    SINGULAR_SIN,
    _Param,
    _solve_derivatives,
    jacobian_columns,
    resolve_known,
)

Array = NDArray[np.float64]


def position_tangents(model: Model, values: Mapping[str, Array],
                      seeds: Mapping[str, Array], directions: int) -> dict[str, Array]:
    """The derivative of every vector parameter along ``directions`` directions of the
    design constants.

    ``values`` : every parameter's solved value (SI), arrays ``(D, P)`` (the positions
        of interest; a constant may be a broadcast view).
    ``seeds`` : for each overridden name (as :func:`~mechloop.solve.designs.solve_designs`
        takes them: a constant's value, a link's own delta, a driven parameter's offset —
        or a driven parameter's argument value), its derivative along each direction,
        arrays broadcastable to ``(V, D, P)``, ``V = directions``.

    Returns name -> tangent ``(V, D, P)`` (SI per unit of the direction); NaN where the
    contour is broken or at a dead point (singular Jacobian), as the velocities are.
    """
    from mechloop.model.spatial import refuse_spatial

    refuse_spatial(model, "the sensitivity to the dimensions")
    structure = require_valid(model)
    shape = np.broadcast_shapes(*(np.shape(v) for v in values.values()))
    full = (directions, *shape)
    zero = np.zeros(full)
    params: dict[str, _Param] = {}

    def seed(name: str) -> Array:
        return np.broadcast_to(seeds[name], full) if name in seeds else zero

    for number, vector in model.vectors.items():
        for letter in "ra":
            name = f"{letter}{number}"
            role = vector.r if letter == "r" else vector.a
            if isinstance(role, LinkRole) or is_function(role):
                continue
            # a constant or an argument-driven parameter: its own seed
            params[name] = _Param(np.asarray(values[name])[None], seed(name), 0.0)

    def resolve(name: str) -> _Param | None:
        if name in params:
            return params[name]
        chain = structure.links.get(name)
        if chain is None or chain.root not in params or params[chain.root].rate is None:
            return None
        # p = k_1(k_2(... root ...) + d_2) + d_1: each delta's seed scaled by the ratios
        # before it, the root's tangent by all of them (a ratio is not a variable)
        tangent: Array | float = 0.0
        factor = 1.0
        current = name
        while isinstance(role := param_role(model, current), LinkRole):
            tangent = tangent + factor * seed(current)
            factor *= role.ratio
            current = role.link
        tangent = tangent + factor * params[chain.root].rate
        params[name] = _Param(np.asarray(values[name])[None], tangent, 0.0)
        return params[name]

    def chain_seed(name: str) -> tuple[Array, float]:
        """The tangent of a link's own deltas along its chain (each scaled by the ratios
        before it, as in ``resolve``) and the chain's ratio to its root."""
        total: Array = zero
        factor = 1.0
        current = name
        while isinstance(role := param_role(model, current), LinkRole):
            total = total + factor * seed(current)
            factor *= role.ratio
            current = role.link
        return total, factor

    by_number = {c.number: c for c in structure.contours}
    for block in structure.blocks:  # in solving order
        if block.coupled:
            _block_tangents(block, structure, params, resolve, values, chain_seed, full)
            continue
        info = by_number[block.contours[0]]
        u1, u2 = info.functions
        resolve_known(info, resolve)
        for name in (u1, u2):
            params[name] = _Param(np.asarray(values[name])[None], None, None)

        found, det, norm = jacobian_columns(params, u1, u2)
        with np.errstate(invalid="ignore"):
            good = np.abs(det) > SINGULAR_SIN * norm  # False where NaN (broken)
        good = np.broadcast_to(good, full)
        columns = tuple(np.broadcast_to(c, full) for c in found)
        with np.errstate(invalid="ignore", over="ignore"):
            _solve_derivatives(info, params, columns, np.broadcast_to(det, full), good)
    for name in structure.links:
        resolve(name)
    return {name: np.broadcast_to(p.rate, full) for name, p in params.items()}


def _block_tangents(block, structure, params: dict, resolve, values: Mapping[str, Array],
                    chain_seed, full: tuple[int, ...]) -> None:
    """The tangents of a coupled block's unknowns (:mod:`mechloop.modules.coupled`): the
    block Jacobian's linear system with the known tangents on the right — those of the
    known parameters, and of the deltas of the links to the block's unknowns."""
    from mechloop.modules.coupled import Plan, block_hadamard, block_rates

    by_number = {c.number: c for c in structure.contours}
    index = {u: i for i, u in enumerate(block.unknowns)}
    for name in block.unknowns:
        params[name] = _Param(np.asarray(values[name])[None], None, None)
    eq, sources, r, a, r_rate, a_rate, r_scale, a_scale = ([] for _ in range(8))
    for j, n in enumerate(block.contours):
        for number in by_number[n].vectors:
            eq.append(j)
            for name, vals, rates, scales in ((f"r{number}", r, r_rate, r_scale),
                                              (f"a{number}", a, a_rate, a_scale)):
                chain = structure.links.get(name)
                vals.append(np.asarray(values[name]))
                if name in index:
                    sources.append(index[name])
                    rates.append(0.0)
                    scales.append(1.0)
                elif chain is not None and chain.root in index:
                    sources.append(index[chain.root])
                    delta_tangent, ratio = chain_seed(name)
                    rates.append(delta_tangent)
                    scales.append(ratio)
                else:
                    scales.append(1.0)
                    sources.append(-1)
                    param = resolve(name)
                    if param is None:
                        raise AssertionError(f"{name} not known before block {block.number}")
                    rates.append(param.rate)
    plan = Plan(unknowns=block.unknowns, eq=np.array(eq, dtype=np.int64),
                r_unknown=np.array(sources[0::2], dtype=np.int64),
                r_scale=np.zeros(len(eq), dtype=np.int64),
                r_col=np.zeros(len(eq), dtype=np.int64),
                a_unknown=np.array(sources[1::2], dtype=np.int64),
                a_scale=np.zeros(len(eq), dtype=np.int64),
                a_col=np.zeros(len(eq), dtype=np.int64),
                angle=np.array([u[0] == "a" for u in block.unknowns]))
    with np.errstate(invalid="ignore", over="ignore"):
        ratio = block_hadamard(plan, r, a, r_scale, a_scale, full[1:])
        good = np.broadcast_to(ratio > SINGULAR_SIN, full)  # False where NaN (broken)
        tangent, _ = block_rates(plan, r, a, r_rate, a_rate, None, None, r_scale, a_scale,
                                 good)
    for i, name in enumerate(block.unknowns):
        params[name].rate = tangent[..., i]
        params[name].accel = 0.0


def override_seeds(model: Model, variables, designs: Array, *,
                   inputs: Array | None = None, positions: int | None = None
                   ) -> tuple[dict[str, Array], dict[int, tuple[Array, Array]]]:
    """The derivative of each override and of each varied contour start with respect to
    each design variable: ``(seeds, starts)``.

    ``variables`` : the task's :class:`~mechloop.synthesis.variables.Variables`;
    ``designs`` ``(D, V)`` SI.  ``seeds`` maps an override name to ``(V, D, 1)`` (with
    ``inputs``, free timing: argument 1's value at the ``K`` target inputs, and every
    parameter driven by argument 1 gets its derivative with respect to the input
    variables, ``(V, D, K)``; ``positions`` must then be ``K``).  ``starts`` maps a
    contour number to the tangents ``(V, D)`` of its start's x and y.
    """
    n_var = len(variables)
    n_designs = designs.shape[0]
    eye = np.eye(n_var)
    targets: dict[str, Array] = {}
    for target, col, factor, _ in variables.ties:
        d = factor * eye[:, col][:, None] * np.ones((1, n_designs))  # (V, D)
        targets[target] = targets[target] + d if target in targets else d
    seeds: dict[str, Array] = {n: t[..., None] for n, t in targets.items() if n[0] in "ra"}
    found = variables.targets(designs)
    for number, (x0, y0) in (variables.components or {}).items():
        x = found.get(f"v{number}.x", np.full(n_designs, x0))
        y = found.get(f"v{number}.y", np.full(n_designs, y0))
        dx = targets.get(f"v{number}.x", np.zeros((n_var, n_designs)))
        dy = targets.get(f"v{number}.y", np.zeros((n_var, n_designs)))
        r2 = x * x + y * y
        seeds[f"r{number}"] = ((x * dx + y * dy) / np.sqrt(r2))[..., None]
        seeds[f"a{number}"] = ((x * dy - y * dx) / r2)[..., None]
    starts: dict[int, tuple[Array, Array]] = {}
    for name, d in targets.items():
        if name.startswith("start"):
            number, axis = name[5:].split(".")
            pair = list(starts.get(int(number), (np.zeros((n_var, n_designs)),) * 2))
            pair["xy".index(axis)] = d
            starts[int(number)] = (pair[0], pair[1])
    if inputs is not None:
        columns = variables.input_columns
        k = columns.size
        if positions != k:
            raise ValueError("with inputs, positions must be the number of target inputs")
        dinput = np.zeros((n_var, n_designs, k))
        dinput[columns, :, np.arange(k)] = 1.0
        for number, vector in model.vectors.items():
            for letter in "ra":
                role = vector.r if letter == "r" else vector.a
                if isinstance(role, ArgumentRole) and role.argument == 1:
                    name = f"{letter}{number}"
                    seeds[name] = seeds.get(name, 0.0) + dinput
    return seeds, starts


__all__ = ["override_seeds", "position_tangents"]
