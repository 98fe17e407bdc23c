"""A coupled block inside a solve: its parameters gathered, Newton's continuation run
(:mod:`mechloop.modules.coupled`), its unknowns and their rates handed back.

:func:`solve_coupled` is what :func:`mechloop.solve.kinematics._solve_block` calls for a
block of contours that no closed form solves (or for every block while
:data:`FORCE_COUPLED` is set: the test switch that sends elementary contours through
Newton's method too, to check both give the same numbers).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.model.structure import MODULE_SOLUTIONS, BlockInfo, ContourInfo

Array = NDArray[np.float64]

#: Test switch: solve every block, elementary ones too, by Newton's method.
FORCE_COUPLED = False


@dataclass
class Outcome:
    """One coupled block solved over a block of positions: the masks of the three kinds
    of break and the assembly branch (sign of the block Jacobian's determinant, 0 where
    not regular), arrays shaped like the positions; the carry for the next positions."""

    no_solution: NDArray[np.bool_]
    dead: NDArray[np.bool_]
    jump: NDArray[np.bool_]
    branch: NDArray[np.int8]
    carry: object


def unknowns_of(block: BlockInfo, infos: list[ContourInfo]) -> tuple[str, ...]:
    """The block's unknowns; for an elementary contour forced through Newton, its two
    functions in module order (so the determinant's sign is the module's variant)."""
    if block.coupled:
        return block.unknowns
    return infos[0].functions


def wanted_sign(block: BlockInfo, infos: list[ContourInfo]) -> int:
    """The determinant sign of the first assembly: −1 for variant 1 (and ``auto``: the
    assembly of variant 1 at the first position, then followed by continuity through a
    change of the determinant's sign — what ``auto`` means for an elementary contour —,
    :func:`~mechloop.modules.coupled.continue_block`'s ``track``), +1 for variant 2 —
    the convention of Pl3/Pl4 —; for a forced Pl1 +1 (its length positive: the
    determinant is that length), for a forced Pl2 0 (any: one solution)."""
    if not block.coupled and MODULE_SOLUTIONS.get(infos[0].module, 2) == 1:
        return 1 if infos[0].module == "Pl1" else 0
    return 1 if block.variant == 2 else -1


def solve_coupled(block: BlockInfo, setup, params: dict, resolve: Callable,
                  shape: tuple[int, ...], carry, *, derivatives: bool) -> Outcome:
    """Solve ``block`` at every element of ``shape`` (designs × positions), adding its
    unknowns to ``params`` (values with cosines and sines, and with ``derivatives`` their
    rates and accelerations from the block Jacobian).

    ``carry`` continues the previous positions (None at position 0).  Where the block's
    inputs are NaN (an earlier block broken) Newton does not converge: the caller masks
    those positions as inherited.
    """
    from mechloop.modules.coupled import Plan, block_rates, continue_block
    from mechloop.solve.kinematics import SINGULAR_SIN, _Param

    structure = setup.structure
    by_number = {c.number: c for c in structure.contours}
    infos = [by_number[n] for n in block.contours]
    unknowns = unknowns_of(block, infos)
    index = {u: i for i, u in enumerate(unknowns)}
    scales = getattr(setup, "scales", {})  # link ratios: α_i = k·α_j + d (1 by default)

    columns: list = [0.0, 1.0]  # 0: zero, 1: one

    def add(value) -> int:
        columns.append(value)
        return len(columns) - 1

    terms = []  # per vector: (eq, (unknown, scale col, col) for r, the same for a, names)
    for j, info in enumerate(infos):
        for number in info.vectors:
            sources = []
            for name in (f"r{number}", f"a{number}"):
                chain = structure.links.get(name)
                if name in index:
                    sources.append((index[name], 1, 0))
                elif chain is not None and chain.root in index:
                    sources.append((index[chain.root], add(scales.get(name, 1.0)),
                                    add(setup.deltas[name])))
                else:
                    param = resolve(name)
                    if param is None:
                        raise AssertionError(f"{name} not known before block {block.number}")
                    sources.append((-1, 1, add(param.value)))
            terms.append((j, *sources, number))
    n_rows = int(np.prod(shape[:-1], dtype=np.int64))
    known = np.empty((len(columns), n_rows, shape[-1]))
    for k, value in enumerate(columns):
        known[k] = np.broadcast_to(value, shape).reshape(n_rows, shape[-1])
    ints = {key: np.array([t[pos][k] for t in terms], dtype=np.int64)
            for key, pos, k in (("r_unknown", 1, 0), ("r_scale", 1, 1), ("r_col", 1, 2),
                                ("a_unknown", 2, 0), ("a_scale", 2, 1), ("a_col", 2, 2))}
    plan = Plan(unknowns=unknowns, eq=np.array([t[0] for t in terms], dtype=np.int64),
                angle=np.array([u[0] == "a" for u in unknowns]), **ints)
    guess = {index[n]: v for n, v in block.guess.items() if n in index}
    n_regular = getattr(setup, "n_regular", None)
    extra_start = getattr(setup, "extra_start", None)
    extra_from = (getattr(setup, "block_starts", None) or {}).get(block.number)
    U, status, det, new_carry = continue_block(
        plan, known, want=wanted_sign(block, infos), guess=guess,
        singular_sin=SINGULAR_SIN, carry=carry, n_regular=n_regular,
        extra_start=None if extra_start is None else extra_start.reshape(n_rows, -1),
        extra_from=extra_from)

    good = (status == 0).reshape(shape)
    for i, name in enumerate(unknowns):
        value = U[..., i].reshape(shape)
        if name[0] == "a":
            c, s = np.cos(value), np.sin(value)
            params[name] = _Param(np.arctan2(s, c), None, None, c, s)
        else:
            params[name] = _Param(value, None, None)
    if derivatives:
        _rates(plan, terms, params, known, columns, shape, good, block_rates)
    branch = (np.sign(det).astype(np.int8) * (status == 0)).reshape(shape)
    return Outcome(no_solution=(status == 1).reshape(shape), dead=(status == 2).reshape(shape),
                   jump=(status == 3).reshape(shape), branch=branch, carry=new_carry)


def _rates(plan, terms, params: dict, known: Array, columns: list, shape, good, block_rates
           ) -> None:
    """Rates and accelerations of the unknowns (block Jacobian), into ``params``."""
    def col(k: int) -> Array:
        return known[k].reshape(shape)

    r, a, r_rate, a_rate, r_accel, a_accel, r_scale, a_scale = ([] for _ in range(8))
    for t in terms:
        number = t[3]
        for (unknown, scale, offset), name, values, rates, accels, scl in (
                (t[1], f"r{number}", r, r_rate, r_accel, r_scale),
                (t[2], f"a{number}", a, a_rate, a_accel, a_scale)):
            if unknown >= 0:
                u = params[plan.unknowns[unknown]].value
                values.append(col(scale) * u + col(offset))
                rates.append(0.0)
                accels.append(0.0)
                scl.append(col(scale))
            else:
                p = params[name]
                values.append(col(offset))
                rates.append(p.rate)
                accels.append(p.accel)
                scl.append(1.0)
    with np.errstate(invalid="ignore", over="ignore"):
        rate, accel = block_rates(plan, r, a, r_rate, a_rate, r_accel, a_accel, r_scale,
                                  a_scale, good)
    for i, name in enumerate(plan.unknowns):
        params[name].rate = rate[..., i]
        params[name].accel = accel[..., i]


class BlockMargin:
    """The existence margin of a coupled block, for the check between positions
    (:mod:`mechloop.solve.between`): ``s·ρ²`` with ``ρ = |det J| / Π ‖column‖`` of the
    block Jacobian (scale-free: 1 for orthogonal columns, 0 at a dead point; for a 2×2
    block the sine between the columns, so ``ρ²`` is the elementary modules' ``sin²``)
    and ``s = sign(det J)`` times the branch's sign (given per design), so the margin is
    positive on the branch followed and changes sign where the block passes a singular
    position onto another assembly — except for a block of ``variant: auto``, which
    follows its assembly through such a change: its margin is ``ρ²`` and its sign
    (:meth:`branch`) 0, either.  ``number`` is the block's first contour (where its
    breaks are reported), ``module`` :data:`~mechloop.model.structure.COUPLED`."""

    def __init__(self, block: BlockInfo, setup):
        from mechloop.model.structure import COUPLED
        from mechloop.modules.coupled import Plan

        self.block, self.number, self.module = block, block.contours[0], COUPLED
        self.tracked = block.variant == "auto"
        self.unknowns = block.unknowns
        self.angle = np.array([u[0] == "a" for u in block.unknowns])
        structure = setup.structure
        by_number = {c.number: c for c in structure.contours}
        index = {u: i for i, u in enumerate(block.unknowns)}
        eq, ru, au, self.terms = [], [], [], []
        for j, n in enumerate(block.contours):
            for number in by_number[n].vectors:
                found = []
                for name in (f"r{number}", f"a{number}"):
                    chain = structure.links.get(name)
                    if name in index:
                        found.append((index[name], 1.0))
                    elif chain is not None and chain.root in index:
                        found.append((index[chain.root], setup.scales.get(name, 1.0)))
                    else:
                        found.append((-1, 1.0))
                eq.append(j)
                ru.append(found[0][0])
                au.append(found[1][0])
                self.terms.append((number, found[0][1], found[1][1]))
        none = np.full(len(eq), -1, dtype=np.int64)  # columns: unused by block_jacobian
        self.plan = Plan(unknowns=block.unknowns, eq=np.array(eq, dtype=np.int64),
                         r_unknown=np.array(ru, dtype=np.int64), r_scale=none, r_col=none,
                         a_unknown=np.array(au, dtype=np.int64), a_scale=none, a_col=none,
                         angle=self.angle)

    def raw(self, values) -> Array:
        """``sign(det J)·ρ²`` (``ρ²`` for ``variant: auto``) at the solved ``values``
        (name -> array, one shape), NaN where a value is."""
        from mechloop.modules.coupled import block_signed_ratio

        shape = np.shape(values[self.unknowns[0]])
        r = [values[f"r{n}"] for n, _, _ in self.terms]
        a = [values[f"a{n}"] for n, _, _ in self.terms]
        ratio = block_signed_ratio(self.plan, r, a, [s for _, s, _ in self.terms],
                                   [s for _, _, s in self.terms], shape)
        return np.abs(ratio) * (np.abs(ratio) if self.tracked else ratio)

    def branch(self, raw: Array) -> Array:
        """The branch's sign per design ``(D, 1)``: the sign of the first finite margin
        along positions (+1 if none); 0 (either) for ``variant: auto``."""
        if self.tracked:
            return np.zeros((raw.shape[0], 1))
        finite = np.isfinite(raw)
        first = np.argmax(finite, axis=-1)
        value = np.take_along_axis(raw, first[:, None], axis=-1)
        return np.where(np.isfinite(value) & (value < 0), -1.0, 1.0)
