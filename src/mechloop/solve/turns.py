"""Whole turns of a solved angle that a link ratio scales.

A contour gives its angles by ``atan2``, in (−π, π]; the ordinary solve makes them
continuous along the positions only at the end.  A link ``α_i = k·α_j + Δ`` with
``k ≠ 1`` onto such a solved angle ``α_j`` (a gear fixed to a rocker, a coupler or a crank
of a linkage) needs ``α_j`` continuous *before* it is scaled: ``k·(α_j + 2πn)`` is a
different angle for every ``n``.  So such an angle (:func:`carried_angles`) is made
continuous in the block of positions as soon as its contour has solved it, continuing
from the last value of the previous block (the ``carry`` of
:func:`~mechloop.solve.kinematics._solve_block`), and starting, like
:func:`~mechloop.solve.kinematics.unwrap_angles`, in [0, 2π) at the first position.

Columns that are not positions in sequence (the extra inputs of
:func:`~mechloop.solve.designs.solve_designs_at`) take their turns from the nearest
regular position (``setup.extra_start``) or from ``setup.turn_ref`` where the solve has
no regular positions: ``α = ref + wrap(atan2 − ref)``.  A column whose reference is
broken (NaN) gets a NaN angle: its turns are unknown, and it is marked broken by the
caller's overflow check.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, MutableMapping

import numpy as np
from numpy.typing import NDArray

from mechloop.model.structure import Structure

Array = NDArray[np.float64]

#: Key of the turns state in a block's ``carry`` (the other keys are block numbers).
CARRY_KEY = "turns"


def carried_angles(structure: Structure, scales: Mapping[str, object]) -> frozenset[str]:
    """The angles that a contour solves and that a link scales by a ratio ≠ 1."""
    out = set()
    for name, chain in structure.links.items():
        scale = scales.get(name, 1.0)
        if chain.root[0] == "a" and chain.root in structure.owner and not (
                np.isscalar(scale) and scale == 1):
            out.add(chain.root)
    return frozenset(out)


def _near(reference: Array, raw: Array) -> Array:
    """``raw`` shifted by whole turns to lie within π of ``reference`` (NaN where the
    reference is NaN)."""
    two_pi = 2 * np.pi
    return raw + two_pi * np.round((reference - raw) / two_pi)


def continue_turns(setup, names: Iterable[str], params: MutableMapping[str, object],
                   shape: tuple[int, ...], carry_in: Mapping | None,
                   carry_out: MutableMapping) -> None:
    """Make each carried angle among ``names`` (just solved into ``params``) continuous
    along the positions of this block, in place; record its last finite value per row in
    ``carry_out`` for the next block.  The cached cosine and sine stay (whole turns
    change neither)."""
    from mechloop.solve.kinematics import unwrap_angles

    todo = [name for name in names if name in setup.carried]
    if not todo:
        return
    before = (carry_in or {}).get(CARRY_KEY, {})
    state = carry_out.setdefault(CARRY_KEY, dict(before))
    n_cols = shape[-1]
    n_reg = n_cols if setup.n_regular is None else int(setup.n_regular)
    for name in todo:
        param = params[name]
        raw = np.broadcast_to(np.asarray(param.value, dtype=float), shape)
        rows = raw.reshape(-1, n_cols)
        reg = rows[:, :n_reg]
        cont = np.empty(rows.shape)
        if n_reg:
            ok = np.isfinite(reg)
            cont[:, :n_reg] = unwrap_angles(reg, ok)
            first = np.argmax(ok, axis=-1)
            idx = np.arange(rows.shape[0])
            if name in before:  # continue the previous block's last finite value
                ref = np.broadcast_to(before[name], (rows.shape[0],))
                start = cont[idx, first]
                shift = np.where(np.isfinite(ref) & ok[idx, first],
                                 _near(ref, start) - start, 0.0)
                cont[:, :n_reg] += shift[:, None]
            last = n_reg - 1 - np.argmax(ok[:, ::-1], axis=-1)
            found = cont[idx, last]
            prev = np.broadcast_to(before.get(name, np.nan), (rows.shape[0],))
            state[name] = np.where(ok.any(axis=-1), found, prev)
        if n_cols > n_reg:
            extra = rows[:, n_reg:]
            if n_reg and setup.extra_start is not None:
                at = np.asarray(setup.extra_start).reshape(rows.shape[0], -1)
                ref = np.take_along_axis(cont[:, :n_reg], at, axis=-1)
            elif setup.turn_ref is not None and name in setup.turn_ref:
                ref = np.broadcast_to(setup.turn_ref[name], extra.shape)
            else:
                ref = np.full(extra.shape, np.nan)
            cont[:, n_reg:] = _near(ref, extra)
        param.value = cont.reshape(shape)
