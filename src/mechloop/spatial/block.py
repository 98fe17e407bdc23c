"""A coupled block of spatial and planar contours solved together (issue 17).

The 3-D counterpart of :mod:`mechloop.modules.coupled`: contours that need each other's
functions (or a contour linking to one of its own: a non-elementary module) have their
raw closure equations solved together — 3 per spatial contour,
``Σ ±r_i (cos α_i cos β_i, sin α_i, cos α_i sin β_i) = 0``, and 2 per planar contour in
its plane's axes, ``Σ r_i (cos α_i, sin α_i) = 0`` — for the block's unknowns (3 per
spatial contour, 2 per planar one) by Newton's method with continuation over the
positions, compiled (numba) over every design × position with no Python loop, by the
planar coupled solver itself (:func:`mechloop.modules.coupled.continue_block` over the
block's :class:`~mechloop.modules.coupled.Terms`): the same Newton step (Gaussian
elimination with the determinant and the Hadamard ratio ``|det J| / Π ‖column‖``), the
same fixed starts (:func:`~mechloop.modules.coupled.start_points`), the same tolerances
and the same break statuses (:data:`~mechloop.modules.coupled.REASONS`).

**Position 0** starts from the contours' ``guess`` (the converged solution nearest to it),
or without one from the fixed starts, keeping the first regular solution whose Jacobian
determinant (columns in the order of the block's unknowns) is negative for variant 1 and
positive for variant 2 (``auto``: variant 1, then the sign may change on a continuous
path).  **Continuation**: each next position starts from the line through the last two
solutions (the first-order predictor ``u − J⁻¹F`` after the first or after a break); a
step that does not converge is a break (:data:`~mechloop.modules.coupled.NO_CONVERGENCE`),
a Jacobian whose Hadamard ratio is below ``SINGULAR_SIN`` a dead point, a determinant sign
change (fixed variant) or a solution farther from the predictor than twice the last step
and :data:`~mechloop.modules.coupled.JUMP_ANGLE` (a fraction
:data:`~mechloop.modules.coupled.JUMP_LENGTH` of the block's size for a length) a jump to
another assembly.

**Rates** are exact from the block Jacobian ``J`` (:func:`block_rates`): ``J u̇ = −b₁``
with ``b₁`` the closure's time derivative at the known rates, and ``J ü = −b₂`` with
``b₂`` its second derivative at the full rates and the known accelerations.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.modules.coupled import OK, Terms, continue_block

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Plan(Terms):
    """The block's terms (:class:`~mechloop.modules.coupled.Terms`: per term its first
    equation, its number of equations — 3 spatial, 2 planar —, its sign and where its r,
    α, β come from), the names of its unknowns and ``angle[i]``, which marks the angle
    unknowns."""

    unknowns: tuple[str, ...]
    angle: NDArray[np.bool_]

    @property
    def terms(self) -> Terms:
        """The terms as the compiled solver of :mod:`mechloop.modules.coupled` reads
        them: the plan itself."""
        return self


def solve_block(plan: Plan, known: Array, *, want: int, guess: dict[int, float],
                singular_sin: float, track: bool = False
                ) -> tuple[Array, NDArray[np.int8], Array]:
    """Solve the block at every row (design) and column (position) of the known stack
    ``known`` ``(n_known, R, C)``: the unknowns ``(R, C, m)`` (NaN where not OK), the
    status ``(R, C)`` and the Jacobian determinant ``(R, C)`` (0 where not OK).  ``want``
    the determinant sign of the first assembly (−1 variant 1, +1 variant 2); ``guess``
    approximate unknowns (SI) by index; ``track`` follows the assembly through a sign
    change of the determinant (``variant: auto``)."""
    U, status, det, _ = continue_block(plan, known, want=want, guess=guess,
                                       singular_sin=singular_sin, track=track)
    return U, status, det


def _directions(dim: int, a: Array, b: Array) -> dict[str, Array]:
    """The unit vector of a term and its derivatives by α and β, ``(3, ...)``: a planar
    term's in its plane's axes (third component 0)."""
    ca, sa = np.cos(a), np.sin(a)
    zero = np.zeros_like(ca)
    if dim == 2:
        u = np.stack([ca, sa, zero])
        ua = np.stack([-sa, ca, zero])
        return {"u": u, "a": ua, "b": np.zeros_like(u), "ab": np.zeros_like(u),
                "bb": np.zeros_like(u), "aa": -u}
    cb, sb = np.cos(b), np.sin(b)
    u = np.stack([ca * cb, sa, ca * sb])
    return {"u": u, "a": np.stack([-sa * cb, ca, -sa * sb]),
            "b": np.stack([-ca * sb, zero, ca * cb]),
            "ab": np.stack([sa * sb, zero, -sa * cb]),
            "bb": np.stack([-ca * cb, zero, -ca * sb]), "aa": -u}


def block_rates(plan: Plan, values: list[Array], rates: list[Array], accels: list[Array],
                scales: list[Array], good: NDArray[np.bool_]) -> tuple[Array, Array, Array]:
    """Rates and accelerations of the block's unknowns, ``(..., m)`` each (NaN where not
    ``good``), and the block Jacobian ``(..., m, m)``.

    Per term ``t``: ``values[t]`` ``(3, ...)`` its r, α, β (β 0 for a planar term);
    ``rates[t]``, ``accels[t]`` the *known* parts (zero for a parameter linked to an
    unknown); ``scales[t]`` ``(3, ...)`` the link scales to an unknown (unused where
    known).
    """
    m = len(plan.unknowns)
    shape = good.shape
    J = np.zeros((*shape, m, m))
    b1 = np.zeros((*shape, m))
    frames = []
    for t in range(len(values)):
        dim, e, sg = int(plan.dim[t]), int(plan.row[t]), float(plan.sign[t])
        r, a, b = values[t]
        d = _directions(dim, a, b)
        frames.append(d)
        dr, da, db = rates[t]
        vel = dr * d["u"] + r * (da * d["a"] + db * d["b"])
        cols = {0: d["u"], 1: r * d["a"], 2: r * d["b"]}
        for q in range(dim):
            b1[..., e + q] += sg * vel[q]
            for k in range(3):
                i = int(plan.unknown[k, t])
                if i >= 0:
                    J[..., e + q, i] += sg * scales[t][k] * cols[k][q]
    J[~good] = np.eye(m)
    b1[~good] = 0.0
    inverse = np.linalg.inv(J)
    rate = -(inverse @ b1[..., None])[..., 0]
    b2 = np.zeros((*shape, m))
    for t, d in enumerate(frames):
        dim, e, sg = int(plan.dim[t]), int(plan.row[t]), float(plan.sign[t])
        r, _, _ = values[t]
        full = [rates[t][k] + (scales[t][k] * rate[..., int(plan.unknown[k, t])]
                               if plan.unknown[k, t] >= 0 else 0.0) for k in range(3)]
        dr, da, db = full
        ddr, dda, ddb = accels[t]
        acc = (ddr * d["u"] + 2.0 * dr * (da * d["a"] + db * d["b"])
               + r * (dda * d["a"] + ddb * d["b"])
               + r * (da**2 * d["aa"] + 2.0 * da * db * d["ab"] + db**2 * d["bb"]))
        for q in range(dim):
            b2[..., e + q] += sg * acc[q]
    b2[~good] = 0.0
    accel = -(inverse @ b2[..., None])[..., 0]
    rate[~good] = np.nan
    accel[~good] = np.nan
    J[~good] = np.nan
    return rate, accel, J


def _directions_in_convention(model, block, index: dict[str, int], U: Array,
                              good: NDArray[np.bool_], roots: set[str]) -> set[int]:
    """Move the vectors of ``block`` whose α and β are both its unknowns into their
    contour's parameter-range convention (Newton may end on either of the two angle
    pairs of one direction, ``(α, β)`` and ``(π − α, β + π)``), then make them continuous
    along the positions as a single contour's are (:func:`mechloop.spatial.solve.
    _continuous`: α of convention 1 from [0, 2π)).  A vector whose α or β another
    parameter links to (``roots``) keeps Newton's pair: the other pair would move the linked
    one, a different assembly, not the same direction.  ``U`` (…, m) is changed in place;
    returns the columns moved."""
    from mechloop.spatial.solve import _continuous
    from mechloop.spatial.vector import in_convention

    moved: set[int] = set()
    if not good.any():
        return moved
    for number in block.contours:
        contour = model.contours[number - 1]
        if not contour.spatial:
            continue
        for n in contour.vectors:
            i, j = index.get(f"a{abs(n)}"), index.get(f"b{abs(n)}")
            if i is None or j is None or i in moved or \
                    {f"a{abs(n)}", f"b{abs(n)}"} & roots:
                continue
            with np.errstate(invalid="ignore"):
                a, b = in_convention(U[..., i], U[..., j], convention=contour.convention)
            U[..., i] = _continuous(np.where(good, a, np.nan), good,
                                    base_turn=contour.convention == 1)
            U[..., j] = _continuous(np.where(good, b, np.nan), good, base_turn=False)
            moved |= {i, j}
    return moved


def solve_coupled(model, structure, block, params, singular_sin: float
                  ) -> tuple[NDArray[np.int8], Array]:
    """Solve the coupled ``block`` (:class:`~mechloop.model.structure.BlockInfo`) of a
    model with spatial contours over ``params`` (:class:`mechloop.spatial.solve._Params`,
    arrays ``(P,)`` or ``(D, P)``), adding its unknowns (value, rate, acceleration; NaN
    where not solved) to ``params.known``.  Returns the status (:data:`~mechloop.modules.
    coupled.OK`, ...) and the sign of the Jacobian determinant (0 where not OK), both
    shaped like the parameters."""
    from mechloop.model.schema import LinkRole
    from mechloop.model.spatial import contour_signs
    from mechloop.model.structure import param_role
    from mechloop.solve.kinematics import unwrap_angles

    shape = params.shape
    index = {name: i for i, name in enumerate(block.unknowns)}
    columns: list[Array] = [np.zeros(shape), np.ones(shape)]
    terms: list[tuple[int, int, float, list[tuple[int, int, int]]]] = []
    known: list[tuple[list, list, list]] = []  # per term: values, rates, accels (known)
    row = 0
    for number in block.contours:
        contour = model.contours[number - 1]
        dim = 3 if contour.spatial else 2
        for n, sg in contour_signs(model, number - 1):
            sources, vals, rates, accels = [], [], [], []
            for k in "rab":
                name = f"{k}{n}"
                if k == "b" and dim == 2:
                    sources.append((-1, 1, 0))
                    vals.append(0.0), rates.append(0.0), accels.append(0.0)
                    continue
                link = structure.links.get(name)
                if name in index or (link is not None and link.root in index):
                    factor, delta, current = 1.0, 0.0, name
                    while isinstance(step := param_role(model, current), LinkRole):
                        delta = delta + factor * params.si(current, step.delta)
                        factor *= float(step.ratio)
                        current = step.link
                    columns += [np.broadcast_to(factor, shape), np.broadcast_to(delta, shape)]
                    sources.append((index[current], len(columns) - 2, len(columns) - 1))
                    vals.append(None), rates.append(0.0), accels.append(0.0)
                else:
                    v, d, dd = params(name)
                    columns.append(v)
                    sources.append((-1, 1, len(columns) - 1))
                    vals.append(v), rates.append(d), accels.append(dd)
            terms.append((row, dim, sg, sources))
            known.append((vals, rates, accels))
        row += dim
    m = len(block.unknowns)
    plan = Plan(unknowns=tuple(block.unknowns),
                row=np.array([t[0] for t in terms], dtype=np.int64),
                dim=np.array([t[1] for t in terms], dtype=np.int64),
                sign=np.array([t[2] for t in terms], dtype=float),
                unknown=np.array([[t[3][k][0] for t in terms] for k in range(3)],
                                 dtype=np.int64),
                scale=np.array([[t[3][k][1] for t in terms] for k in range(3)],
                               dtype=np.int64),
                col=np.array([[t[3][k][2] for t in terms] for k in range(3)],
                             dtype=np.int64),
                angle=np.array([name[0] != "r" for name in block.unknowns]))
    K = np.stack([np.broadcast_to(c, shape) for c in columns]).reshape(len(columns), -1,
                                                                         shape[-1])
    K = np.where(np.isfinite(K), K, np.nan)
    want = 1 if block.variant == 2 else -1
    guess = {index[name]: value for name, value in block.guess.items()}
    U, status, det = solve_block(plan, K, want=want, guess=guess, singular_sin=singular_sin,
                                 track=block.variant == "auto")
    U = U.reshape(*shape, m)
    status = status.reshape(shape)
    good = status == OK
    roots = {link.root for name, link in structure.links.items() if name != link.root}
    paired = _directions_in_convention(model, block, index, U, good, roots)
    for i, name in enumerate(block.unknowns):
        if name[0] == "a" and good.any() and i not in paired:
            U[..., i] = unwrap_angles(U[..., i], good)
    # the terms' values, rates and accelerations (the known parts) and link scales
    values, rates, accels, scales = [], [], [], []
    for (_, _, _, sources), (vals, d1, d2) in zip(terms, known, strict=True):
        full, scale = [], []
        for k, (i, s, c) in enumerate(sources):
            if i >= 0:
                full.append(K[s].reshape(shape) * U[..., i] + K[c].reshape(shape))
                scale.append(K[s].reshape(shape))
            else:
                full.append(np.broadcast_to(vals[k], shape))
                scale.append(np.ones(shape))
        values.append(full)
        rates.append([np.broadcast_to(x, shape) for x in d1])
        accels.append([np.broadcast_to(x, shape) for x in d2])
        scales.append(scale)
    rate, accel, _ = block_rates(plan, values, rates, accels, scales, good)
    for i, name in enumerate(block.unknowns):
        params.known[name] = (np.where(good, U[..., i], np.nan), rate[..., i], accel[..., i])
    return status, np.where(good, np.sign(det).reshape(shape), 0).astype(np.int8)
