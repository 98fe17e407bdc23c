"""Positions, velocities and accelerations of every vector parameter over all positions.

The contours are solved in dependency order; each is one call of its elementary module over
the whole array of positions, then two 2×2 linear solves with the module's Jacobian
(DESIGN §3):

* velocity: ``Σ (ṙ_i e_i + r_i α̇_i n_i) = 0``,
* acceleration: ``Σ (r̈_i e_i + 2 ṙ_i α̇_i n_i + r_i α̈_i n_i − r_i α̇_i² e_i) = 0``,

with ``e = (cos α, sin α)``, ``n = (−sin α, cos α)``: the unknown rates multiply the
Jacobian columns (``e_j`` for an unknown length, ``r_j n_j`` for an unknown angle) and all
other terms are known.  No Python loop runs over positions.

The contours come in *blocks* (:attr:`~mechloop.model.structure.Structure.blocks`): an
elementary block is one contour solved as above; a coupled block (contours that need each
other's functions, or link to their own) is solved by Newton's continuation along the
positions (:mod:`mechloop.solve.blocks`, :mod:`mechloop.modules.coupled`), its rates by
the same two linear systems with the block's ``2k × 2k`` Jacobian.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from dataclasses import field as _field

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import SolveError
from mechloop.model.check import KIND_OF, argument_kind, require_valid
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.structure import BlockInfo, ContourInfo, Structure, is_function
from mechloop.model.units import to_si
from mechloop.modules.planar import (
    EXISTENCE_RTOL,
    pl1_unit,
    pl2_unit,
    pl3_unit,
    pl4_unit,
    track_variant,
)
from mechloop.solve.inputs import Signal, model_arguments, model_time
from mechloop.solve.memory import require_memory
from mechloop.solve.results import BreakBetween, ChainBreak, Results

Array = NDArray[np.float64]

#: A contour position whose Jacobian has |sin(angle between its columns)| below this is a
#: dead point: the position exists but velocities are unbounded.  Modules accept a
#: position whose discriminant is as low as ``-EXISTENCE_RTOL·r²`` (rounding), so near a
#: limit position the computed sine is only known to about ``sqrt(EXISTENCE_RTOL)``;
#: below that the rates would be noise amplified by up to 1e8.
SINGULAR_SIN = math.sqrt(EXISTENCE_RTOL)

#: Elements (designs × positions) of a block from which a position-only solve runs the
#: compiled Pl4 kernel (:mod:`mechloop.modules.kernels`) instead of NumPy: below it,
#: loading numba would cost more than it saves (a single solve never loads it).
KERNEL_ELEMENTS = 4096

BREAK_REASONS = {
    "Pl1": "the closing vector has zero length, its direction is undefined",
    "Pl2": "the two vectors of unknown length are parallel",
    "Pl3": "the vector of known length cannot reach the line of the other vector",
    "Pl4": "the two vectors cannot close the loop (triangle inequality fails)",
}
DEAD_POINT = "dead point: the loop's Jacobian is singular, velocities are unbounded"
OVERFLOW = ("the values overflow floating point (a dimension, an input or a speed is too "
            "large)")


@dataclass
class _Param:
    """A parameter over positions: value, rate, acceleration (arrays or scalars; rate and
    acceleration are None in a position-only solve), and for angles the cached cosine and
    sine of the value."""

    value: Array | float
    rate: Array | float | None
    accel: Array | float | None
    cos: Array | float | None = None
    sin: Array | float | None = None

    def trig(self) -> tuple[Array | float, Array | float]:
        if self.cos is None:
            self.cos, self.sin = np.cos(self.value), np.sin(self.value)
        return self.cos, self.sin


def _is_zero(term: Array | float) -> bool:
    return np.isscalar(term) and term == 0


def _is_one(term: Array | float) -> bool:
    """A scale that is exactly the scalar 1 (a rigid link)."""
    return np.isscalar(term) and term == 1


def unwrap_angles(angle: Array, ok: NDArray[np.bool_]) -> Array:
    """Make an angle continuous along positions (last axis), starting in [0, 2π).

    Rows where ``ok`` is false stay NaN and do not break the continuity of the others.
    """
    two_pi = 2 * np.pi
    if ok.all():
        steps = np.diff(angle, axis=-1)
        base = np.mod(angle[..., :1], two_pi)
        if np.all(np.abs(steps) < np.pi):
            return angle + (base - angle[..., :1])
        return np.concatenate([base, base + np.cumsum(_wrap(steps), axis=-1)], axis=-1)
    # Each step goes from the previous position where ``ok`` holds (zero at the others and
    # before the first): the regular angles, taken in row order, differenced pairwise.
    rows = ok.reshape(-1, ok.shape[-1])
    kept = angle.reshape(rows.shape)[rows]
    jumps = np.zeros(kept.shape)
    np.subtract(kept[1:], kept[:-1], out=jumps[1:])
    counts = np.count_nonzero(rows, axis=-1)
    firsts = (np.cumsum(counts) - counts)[counts > 0]
    _wrap(jumps)
    jumps[firsts] = 0.0  # the first regular position of a row starts it
    steps = np.zeros(rows.shape)
    steps[rows] = jumps
    first = np.argmax(rows, axis=-1)[:, None]
    base = np.mod(np.take_along_axis(angle.reshape(rows.shape), first, axis=-1), two_pi)
    cont = np.empty(rows.shape)
    cont[:, :1] = base
    np.cumsum(steps[:, 1:], axis=-1, out=cont[:, 1:])
    cont[:, 1:] += base
    cont[~rows] = np.nan
    return cont.reshape(angle.shape)


def _wrap(steps: Array) -> Array:
    """``(steps + π) mod 2π − π`` in place (angle steps wrapped to [−π, π)), bit for bit
    as :func:`numpy.mod` gives it; the modulo (a slow call) runs only where
    ``steps + π`` lies outside [0, 2π), where it is not the identity."""
    steps += np.pi
    with np.errstate(invalid="ignore"):
        wide = (steps < 0) | (steps >= 2 * np.pi)
    if wide.any():
        steps[wide] = np.mod(steps[wide], 2 * np.pi)
    steps -= np.pi
    return steps


def _constant_si(model: Model, name: str, value: float | str) -> float:
    kind = KIND_OF[name[0]]
    return to_si(value, kind, getattr(model.units, kind))


#: Positions solved together in one block: small enough that a block's temporaries stay
#: in the CPU cache, large enough that NumPy's per-call overhead is negligible.
BLOCK = 8192

Value = Array | float


@dataclass
class _Setup:
    """What every block of a solve shares: the compiled roles of all parameters.

    Constant values and link deltas are floats, or arrays shaped ``(D, 1)`` when they
    differ between candidate designs.  A linked parameter is
    ``scales[name] · root + deltas[name]`` (SI): ``scales`` holds the composed ratio of
    every link name (a float, 1.0 for a rigid link; a ``(D, 1)`` array if it ever differs
    between designs), ``deltas`` the composed constant.
    """

    structure: Structure
    ordered: list[ContourInfo]
    constants: dict[str, Value]
    driven: dict[str, tuple[Signal, Value]]
    deltas: dict[str, Value]
    constant: set[str]
    varying: list[str]
    scales: dict[str, Value] = _field(default_factory=dict)
    #: columns from this one on are arbitrary inputs (solve_designs_at), not positions in
    #: sequence; a coupled block solves each from the regular column ``extra_start``
    #: ``(D, K)`` (the nearest position by argument 1)
    n_regular: int | None = None
    extra_start: NDArray[np.int64] | None = None
    #: solved angles that a link scales by a ratio ≠ 1: made continuous as soon as they
    #: are solved (:func:`mechloop.solve.turns.continue_turns`), since ``k·α`` depends on
    #: α's whole turns
    carried: frozenset[str] = frozenset()
    #: per carried angle, its continuous value near each extra column ``(D, K)`` (SI),
    #: where the solve has no regular positions to take the turns from; see ``turns``
    turn_ref: Mapping[str, Array] | None = None
    #: the existence check's zoom: per coupled block (number), a start ``(R, K, m)``
    #: and the branch's determinant sign ``(R, K)`` for each extra column
    block_starts: dict[int, tuple[Array, Array]] | None = None

    def link_value(self, name: str, root: Value) -> Value:
        """The value of linked parameter ``name`` given its root's value (SI)."""
        scale = self.scales.get(name, 1.0)
        return (root if _is_one(scale) else scale * root) + self.deltas[name]


def _setup(model: Model, structure: Structure, args: dict[int, Signal],
           overrides: Mapping[str, Array] | None = None) -> _Setup:
    """Compile the roles; ``overrides`` replace constants, link deltas and argument offsets
    (SI, shape ``(D,)``) by one value per design."""
    over = {name: np.asarray(v, dtype=float)[:, None] for name, v in (overrides or {}).items()}

    def own(name: str, value: float | str) -> Value:
        return over[name] if name in over else _constant_si(model, name, value)

    constants: dict[str, Value] = {}
    driven: dict[str, tuple[Signal, Value]] = {}
    roles = {}
    for number, vector in model.vectors.items():
        for letter in "ra":
            name = f"{letter}{number}"
            role = vector.r if letter == "r" else vector.a
            roles[name] = role
            if isinstance(role, ArgumentRole):
                driven[name] = (args[role.argument], own(name, role.offset))
            elif not isinstance(role, LinkRole) and not is_function(role):
                constants[name] = own(name, role)
    unknown = sorted(set(over) - set(constants) - set(driven) - set(structure.links))
    if unknown:
        raise SolveError(f"cannot vary {', '.join(unknown)}: only constants, link deltas "
                         "and argument offsets can differ between designs",
                         "vary a parameter whose role is a number, a link or an argument")
    deltas: dict[str, Value] = {}
    scales: dict[str, Value] = {}
    for name in structure.links:
        # p_name = scale·p_current + total; each step p_current = k·p_next + d
        total: Value = 0.0
        scale: Value = 1.0
        current = name
        while isinstance(roles[current], LinkRole):
            step = own(current, roles[current].delta)
            total = total + (step if _is_one(scale) else scale * step)
            scale = scale * float(roles[current].ratio)
            current = roles[current].link
        deltas[name] = total
        scales[name] = scale
    constant = set(constants) | {n for n, c in structure.links.items()
                                 if c.root in constants}
    varying = [f"{letter}{n}" for n in sorted(model.vectors) for letter in "ra"
               if f"{letter}{n}" not in constant]
    from mechloop.solve.turns import carried_angles

    return _Setup(structure, structure.ordered(), constants, driven, deltas, constant,
                  varying, scales, carried=carried_angles(structure, scales))


@dataclass
class _Block:
    """One block solved: every parameter, and per contour the positions with no solution,
    the dead points, everything broken (own or inherited), the variant at the last
    position and the sign of the Jacobian (which assembly branch the contour is on)."""

    params: dict[str, _Param]
    no_solution: dict[int, NDArray[np.bool_]]
    dead: dict[int, NDArray[np.bool_]]
    broken: dict[int, NDArray[np.bool_]]
    last_variant: dict[int, int]
    branch: dict[int, NDArray[np.int8]]
    #: per contour of a coupled block: where its block jumped to another assembly branch
    jump: dict[int, NDArray[np.bool_]] = _field(default_factory=dict)
    #: per coupled block (number): the continuation state at the last position
    carry: dict[int, object] = _field(default_factory=dict)


def _solve_block(setup: _Setup, lo: int, hi: int, shape: tuple[int, ...],
                 starts: Mapping[int, int], *, derivatives: bool = True,
                 carry: Mapping[int, object] | None = None) -> _Block:
    """Solve positions ``lo:hi`` of every contour; arrays come out shaped ``shape``.

    The structure's blocks are solved in order: an elementary one by its closed-form
    module, a coupled one by Newton's continuation (:mod:`mechloop.solve.blocks`), which
    ``carry`` (per block, from the previous call: ``_Block.carry``) continues when
    position ``lo`` is the last position of that call.

    With ``derivatives=False`` only the values are solved (every rate and acceleration is
    None); the masks, variants and branches are the same either way.
    """
    structure, deltas = setup.structure, setup.deltas
    still = 0.0 if derivatives else None
    params = {name: _Param(value, still, still) for name, value in setup.constants.items()}
    for name, (sig, offset) in setup.driven.items():
        params[name] = (_Param(sig.value[lo:hi] + offset, sig.rate[lo:hi], sig.accel[lo:hi])
                        if derivatives else _Param(sig.value[lo:hi] + offset, None, None))

    def resolve(name: str) -> _Param | None:
        """The parameter, following links once their root is known: ``k·root + Δ``
        (``setup.scales``, ``setup.deltas``), its rate and acceleration ``k`` times the
        root's; with ``k = 1`` the cosine and sine come from the root's by rotation."""
        if name in params:
            return params[name]
        chain = structure.links.get(name)
        if chain is None or chain.root not in params:
            return None
        root = params[chain.root]
        delta, scale = deltas[name], setup.scales.get(name, 1.0)
        if _is_one(scale):
            param = _Param(root.value + delta, root.rate, root.accel)
            if name[0] == "a":
                rc, rs = root.trig()
                cd, sd = np.cos(delta), np.sin(delta)
                param.cos, param.sin = rc * cd - rs * sd, rs * cd + rc * sd
        else:  # a transmission: value, rate and acceleration scale by the ratio
            param = _Param(scale * root.value + delta,
                           None if root.rate is None else scale * root.rate,
                           None if root.accel is None else scale * root.accel)
        params[name] = param
        return param

    block = _Block(params, {}, {}, {}, {}, {})
    from mechloop.solve import blocks as coupled
    from mechloop.solve.turns import continue_turns

    by_number = {c.number: c for c in setup.ordered}
    parts = structure.blocks or tuple(  # a Structure built without blocks: one each
        BlockInfo(i + 1, (c.number,), c.functions, (), False)
        for i, c in enumerate(setup.ordered))
    for part in parts:
        if not (part.coupled or coupled.FORCE_COUPLED):
            info = by_number[part.contours[0]]
            inherited = np.zeros(shape, dtype=bool)
            for need in info.needs:
                inherited |= block.broken[need]
            none, dead, variant, branch = _solve_contour(info, params, resolve, shape,
                                                         start=starts.get(info.number, 1),
                                                         derivatives=derivatives)
            block.last_variant[info.number] = variant
            block.no_solution[info.number] = none & ~inherited
            block.dead[info.number] = dead & ~inherited
            block.broken[info.number] = none | dead | inherited
            block.branch[info.number] = branch
            continue_turns(setup, info.functions, params, shape, carry, block.carry)
            continue
        inherited = np.zeros(shape, dtype=bool)
        for n in part.contours:
            for need in by_number[n].needs:
                if need not in part.contours:
                    inherited |= block.broken[need]
        got = coupled.solve_coupled(part, setup, params, resolve, shape,
                                    (carry or {}).get(part.number), derivatives=derivatives)
        block.carry[part.number] = got.carry
        for n in part.contours:
            block.last_variant[n] = 1
            block.no_solution[n] = got.no_solution & ~inherited
            block.dead[n] = got.dead & ~inherited
            block.jump[n] = got.jump & ~inherited
            block.broken[n] = got.no_solution | got.dead | got.jump | inherited
            block.branch[n] = got.branch
        continue_turns(setup, coupled.unknowns_of(part, [by_number[n] for n in part.contours]),
                       params, shape, carry, block.carry)
    for name in structure.links:
        resolve(name)
    return block


def solve(model: Model, *, block: int = BLOCK, analogs_of: int | None = None,
          memory_checked: bool = False) -> Results:
    """Solve a model for positions, velocities and accelerations at every position.

    With ``analogs_of=k`` the derivatives are the analogs with respect to argument ``k``
    alone (its rate 1 and acceleration 0, every other argument held): first- and
    second-order transfer functions, per rad or per m of that argument.

    The positions are processed in blocks of ``block`` (all contours of a block at once,
    every operation vectorized over the block); results do not depend on ``block``.
    ``memory_checked=True``: the caller has checked that the solve fits in memory (the
    dynamics, for all it needs).

    Returns :class:`~mechloop.solve.results.Results`; raises
    :class:`~mechloop.errors.ModelError` if the model is invalid and
    :class:`~mechloop.errors.SolveError` if its derivatives are undefined.
    """
    structure = require_valid(model)
    if not memory_checked:
        require_memory(model)
    if any(c.spatial for c in model.contours):  # spatial contours (issue 17)
        from mechloop.spatial.solve import solve_spatial

        return solve_spatial(model, structure, analogs_of=analogs_of)
    n_pos = model.positions + 1
    time = model_time(model)
    if analogs_of is not None:
        if analogs_of not in model.arguments:
            raise SolveError(f"the model has no argument {analogs_of}",
                             f"use one of {sorted(model.arguments)}")
        args = {k: Signal(s.value, np.full(n_pos, float(k == analogs_of)), np.zeros(n_pos))
                for k, s in model_arguments(model, time, strict=False).items()}
        time = None
    else:
        args = model_arguments(model, time)

    setup = _setup(model, structure, args)
    out = {name: (np.empty(n_pos), np.empty(n_pos), np.empty(n_pos))
           for name in setup.varying}
    no_solution = {c.number: np.zeros(n_pos, dtype=bool) for c in setup.ordered}
    singular = {c.number: np.zeros(n_pos, dtype=bool) for c in setup.ordered}
    jumps = {c.number: np.zeros(n_pos, dtype=bool) for c in setup.ordered}
    last_variant: dict[int, int] = {}
    carry: dict[int, object] = {}  # coupled blocks continue across blocks of positions

    for first in range(0, n_pos, max(int(block), 2)):
        lo = max(first - 1, 0)  # one position of overlap carries variant tracking across
        hi = min(first + max(int(block), 2), n_pos)
        size, skip = hi - lo, first - lo
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            solved = _solve_block(setup, lo, hi, (size,), last_variant, carry=carry)
        last_variant, carry = solved.last_variant, solved.carry
        for info in setup.ordered:
            no_solution[info.number][first:hi] = solved.no_solution[info.number][skip:]
            singular[info.number][first:hi] = solved.dead[info.number][skip:]
            if info.number in solved.jump:
                jumps[info.number][first:hi] = solved.jump[info.number][skip:]
        for name, arrays in out.items():
            p = solved.params[name]
            for target, field in zip(arrays, (p.value, p.rate, p.accel), strict=True):
                target[first:hi] = np.broadcast_to(field, (size,))[skip:]

    broken = np.zeros(n_pos, dtype=bool)
    for info in setup.ordered:
        broken |= no_solution[info.number] | singular[info.number] | jumps[info.number]
    clock = [] if time is None else [time.value]
    overflow = _overflow(setup, out, broken,
                         [*clock, *(field for s in args.values() for field in (
                             s.value, s.rate, s.accel))])
    for mask in overflow.values():
        broken |= mask
    with np.errstate(over="ignore", invalid="ignore"):
        _finish_angles(setup, {name: arrays[0] for name, arrays in out.items()})
    for arrays in out.values():
        for arr in arrays:
            arr[broken] = np.nan

    breaks = _coupled_breaks(setup, no_solution, singular, jumps, overflow)
    for info in setup.ordered:
        if info.number in solved.jump:
            continue  # its block's breaks are reported once, for the block
        for reason, mask in ((BREAK_REASONS[info.module], no_solution[info.number]),
                             (DEAD_POINT, singular[info.number]),
                             (OVERFLOW, overflow.get(info.number, np.zeros(n_pos, dtype=bool)))):
            if mask.any():
                breaks.append(ChainBreak(info.number, info.module, np.flatnonzero(mask),
                                         reason))
    values, rates, accels = {}, {}, {}
    for name, (value, rate, accel) in out.items():
        values[name], rates[name], accels[name] = value, rate, accel
    zero = np.broadcast_to(0.0, (n_pos,))
    for name in setup.constant:
        root = structure.links[name].root if name in structure.links else name
        value = (setup.link_value(name, setup.constants[root]) if name in structure.links
                 else setup.constants[root])
        values[name], rates[name], accels[name] = np.broadcast_to(value, (n_pos,)), zero, zero
    arg_kinds = {k: argument_kind(model, k) for k in model.arguments}
    between = _breaks_between(model, setup, values, broken, args, arg_kinds)
    return Results(
        model=model,
        structure=structure,
        time=None if time is None else time.value,
        arguments={k: s.value for k, s in args.items()},
        argument_kinds=arg_kinds,
        values=values,
        rates=rates,
        accels=accels,
        constant=frozenset(setup.constant),
        broken=broken,
        breaks=tuple(sorted(breaks, key=lambda b: b.contour)),
        analogs_of=analogs_of,
        breaks_between=between,
    )


def _coupled_breaks(setup: _Setup, no_solution: dict[int, NDArray[np.bool_]],
                    singular: dict[int, NDArray[np.bool_]],
                    jumps: dict[int, NDArray[np.bool_]],
                    overflow: dict[int, NDArray[np.bool_]]) -> list[ChainBreak]:
    """The breaks of every coupled block (or every block while forced through Newton),
    one record per block and kind of break, naming the block's contours."""
    from mechloop.modules.coupled import DEAD, JUMP, NO_CONVERGENCE, REASONS
    from mechloop.solve import blocks as coupled

    out = []
    for part in setup.structure.blocks:
        if not (part.coupled or coupled.FORCE_COUPLED):
            continue
        first = part.contours[0]
        over = np.zeros_like(no_solution[first])
        for n in part.contours:
            over |= overflow.get(n, over)
        for reason, mask in ((REASONS[NO_CONVERGENCE], no_solution[first]),
                             (REASONS[DEAD], singular[first]), (REASONS[JUMP], jumps[first]),
                             (OVERFLOW, over)):
            if mask.any():
                out.append(ChainBreak(first, "coupled", np.flatnonzero(mask), reason,
                                      contours=part.contours))
    return out


def _breaks_between(model: Model, setup: _Setup, values: dict[str, Array],
                    broken: NDArray[np.bool_], args: dict[int, Signal],
                    kinds: dict[int, str]) -> tuple[BreakBetween, ...]:
    """The breaks of the exact existence check
    (:func:`~mechloop.solve.existence.assembles_throughout`) that no broken position
    shows: between two positions that assemble."""
    from types import SimpleNamespace

    from mechloop.solve.existence import ExistenceCheck

    if 1 not in args or broken.size < 2:
        return ()
    samples = SimpleNamespace(values={k: np.asarray(v)[None, :] for k, v in values.items()},
                              broken=broken[None, :])
    check = ExistenceCheck(model, structure=setup.structure, args=args, setup=setup)
    found = check(samples=samples, intervals=True).breaks
    x = args[1].value
    modules = {c.number: c.module for c in setup.ordered}
    out = []
    for brk in found:
        inside = (x >= brk.start) & (x <= brk.stop)
        if broken[inside].any() or brk.after >= x.size - 1:
            continue  # a position shows it
        i = brk.after
        out.append(BreakBetween(brk.contour, modules[brk.contour], i, brk.start, brk.stop,
                                (float(x[i]), float(x[i + 1])), kinds.get(1, "angle")))
    return tuple(out)


def _overflow(setup: _Setup, out: dict[str, tuple[Array, Array, Array]],
              broken: NDArray[np.bool_], inputs: list[Array]
              ) -> dict[int, NDArray[np.bool_]]:
    """Per contour, the positions not already broken where a parameter of its vectors has a
    non-finite value, rate or acceleration (floating point overflowed): a chain break too,
    so no row that is not marked broken holds a non-number.  Positions where one of
    ``inputs`` (the time, the arguments and their derivatives) is not finite count for the
    first contour solved."""
    found: dict[int, NDArray[np.bool_]] = {}
    seen = broken.copy()
    for i, info in enumerate(setup.ordered):
        bad = np.zeros_like(broken)
        for arr in inputs if i == 0 else ():
            bad |= ~np.isfinite(arr)
        for number in info.vectors:
            for name in (f"r{number}", f"a{number}"):
                for arr in out.get(name, ()):
                    bad |= ~np.isfinite(arr)
        bad &= ~seen
        if bad.any():
            found[info.number] = bad
            seen |= bad
    return found


def _finish_angles(setup: _Setup, values: dict[str, Array]) -> None:
    """Unwrap the solved angles along positions, then re-derive the linked ones (an angle
    that a ratio scales is continuous already: ``setup.carried``)."""
    for info in setup.ordered:
        for name in info.functions:
            if name[0] == "a" and name not in setup.carried:
                value = values[name]
                value[...] = unwrap_angles(value, np.isfinite(value))
    for name, chain in setup.structure.links.items():
        if name in values and chain.root in values:
            values[name][...] = setup.link_value(name, values[chain.root])


def _solve_contour(info: ContourInfo, params: dict[str, _Param], resolve,
                   shape: tuple[int, ...], *, start: int = 1, derivatives: bool = True
                   ) -> tuple[NDArray[np.bool_], NDArray[np.bool_], int, NDArray[np.int8]]:
    """Solve one contour, adding its functions to ``params``; arrays shaped ``shape``.

    ``start`` is the variant at the first position when the variant is tracked (``auto``).
    With ``derivatives=False`` the rates and accelerations of the functions are left None
    (and none are read).
    Returns two masks over positions — no real solution, and dead point (singular
    Jacobian; positions where an input is already NaN come out in the first mask) —, the
    variant in use at the last position, and the sign of the Jacobian determinant (+1,
    −1, 0 where there is no regular solution): the assembly branch the contour is on.
    """
    u1, u2 = info.functions
    resolve_known(info, resolve)

    x: Array | float = 0.0
    y: Array | float = 0.0
    for number in info.vectors:
        rn, an = f"r{number}", f"a{number}"
        if rn in (u1, u2) or an in (u1, u2):
            continue  # a vector that carries an unknown is handled by the module itself
        r = params[rn].value
        c, s = params[an].trig()
        x = x + r * c
        y = y + r * s
    module = info.module
    v1, v2 = int(u1[1:]), int(u2[1:])
    x = np.broadcast_to(np.asarray(x, dtype=float), shape)
    y = np.broadcast_to(np.asarray(y, dtype=float), shape)
    if module == "Pl4" and info.variant != "auto" and not derivatives \
            and x.size >= KERNEL_ELEMENTS:
        # a large position-only block (a population of designs): the compiled module
        from mechloop.modules.kernels import pl4_contour

        c1, s1, c2, s2, ok, dead, branch = pl4_contour(
            x, y, params[f"r{v1}"].value, params[f"r{v2}"].value, variant=info.variant,
            rtol=EXISTENCE_RTOL, singular_sin=SINGULAR_SIN)
        params[u1] = _Param(np.arctan2(s1, c1), None, None, c1, s1)
        params[u2] = _Param(np.arctan2(s2, c2), None, None, c2, s2)
        return ~ok, dead, info.variant, branch

    def run(variant):
        """Unknowns as (value or None, cos, sin) per function, and ok."""
        if module == "Pl1":
            r1, c1, s1, ok = pl1_unit(x, y)
            return ((r1, None, None), (None, c1, s1)), ok
        if module == "Pl2":
            r1, r2, ok = pl2_unit(x, y, *params[f"a{v1}"].trig(), *params[f"a{v2}"].trig())
            return ((r1, None, None), (r2, None, None)), ok
        if module == "Pl3":
            r1, c2, s2, ok = pl3_unit(x, y, *params[f"a{v1}"].trig(),
                                      params[f"r{v2}"].value, variant=variant)
            return ((r1, None, None), (None, c2, s2)), ok
        c1, s1, c2, s2, ok = pl4_unit(x, y, params[f"r{v1}"].value, params[f"r{v2}"].value,
                                      variant=variant)
        return ((None, c1, s1), (None, c2, s2)), ok

    if info.variant == "auto" and module in ("Pl3", "Pl4"):
        first, ok1 = run(1)
        second, ok2 = run(2)
        variant = track_variant(_points(module, first, params, v1, v2),
                                _points(module, second, params, v1, v2), ok1 & ok2,
                                start=start)
        unknowns, ok = run(variant)
        last = int(variant.reshape(-1, variant.shape[-1])[0, -1])
    else:
        last = info.variant if info.variant != "auto" else 1
        unknowns, ok = run(last)

    for name, (val, c, s) in zip((u1, u2), unknowns, strict=True):
        if name[0] == "a":
            params[name] = _Param(np.arctan2(s, c), None, None, c, s)  # unwrapped at the end
        else:
            params[name] = _Param(val, None, None)

    (c1x, c1y, c2x, c2y), det, norm = jacobian_columns(params, u1, u2)
    with np.errstate(invalid="ignore"):
        singular = ok & ~(np.abs(det) > SINGULAR_SIN * norm)
        good = ok & ~singular
        # the sign of det where the solution is regular (det is not 0 there), else 0
        branch = ((good & (det > 0)).astype(np.int8)
                  - (good & (det < 0)).astype(np.int8))
    if derivatives:
        _solve_derivatives(info, params, (c1x, c1y, c2x, c2y), det, good)
    return ~ok, singular, last, branch


def resolve_known(info: ContourInfo, resolve) -> None:
    """Resolve every parameter of the contour's vectors but its two functions (the
    contour order guarantees they are known; ``resolve(name)`` returns None otherwise)."""
    for number in info.vectors:
        for letter in "ra":
            name = f"{letter}{number}"
            if name not in info.functions and resolve(name) is None:
                raise AssertionError(f"{name} not known before contour {info.number}")


def jacobian_columns(params: dict[str, _Param], u1: str, u2: str
                     ) -> tuple[tuple[Array, Array, Array, Array], Array, Array]:
    """The contour's Jacobian by its two unknowns ``u1``, ``u2``: the columns (x, y of
    the first's, then the second's; ``e_j`` for a length, ``r_j n_j`` for an angle), their
    determinant and the product of their lengths (``|det| / norm`` is the sine between
    them), arrays broadcast over the positions (NaN where broken)."""
    def column(name: str) -> tuple[Array, Array]:
        number = int(name[1:])
        c, s = params[f"a{number}"].trig()
        if name[0] == "r":
            return c, s
        r = params[f"r{number}"].value
        return -r * s, r * c

    c1x, c1y = column(u1)
    c2x, c2y = column(u2)
    with np.errstate(invalid="ignore", over="ignore"):
        det = c1x * c2y - c1y * c2x
        norm = np.sqrt((c1x * c1x + c1y * c1y) * (c2x * c2x + c2y * c2y))
    return (c1x, c1y, c2x, c2y), det, norm


def _solve_derivatives(info: ContourInfo, params: dict[str, _Param],
                       columns: tuple[Array, Array, Array, Array], det: Array,
                       good: NDArray[np.bool_]) -> None:
    """Rates and accelerations of the contour's two functions (NaN where not ``good``),
    from the Jacobian ``columns`` (x, y of the first unknown's, then the second's) and
    their determinant ``det``: two 2×2 linear solves."""
    u1, u2 = info.functions
    for name in (u1, u2):
        params[name].rate = params[name].accel = 0.0  # unknown until solved below
    c1x, c1y, c2x, c2y = columns
    all_good = bool(good.all())
    inv_det = 1.0 / (det if all_good else np.where(good, det, 1.0))

    def solve2(bx: Array, by: Array) -> tuple[Array, Array]:
        d1 = (by * c2x - bx * c2y) * inv_det
        d2 = (bx * c1y - by * c1x) * inv_det
        if all_good:
            return d1, d2
        return np.where(good, d1, np.nan), np.where(good, d2, np.nan)

    # velocity: Σ (ṙ e + r α̇ n) = 0 with the unknown rates still zero
    bx: Array | float = 0.0
    by: Array | float = 0.0
    for number in info.vectors:
        rp, ap = params[f"r{number}"], params[f"a{number}"]
        c, s = ap.trig()
        if not _is_zero(rp.rate):
            bx = bx + rp.rate * c
            by = by + rp.rate * s
        if not _is_zero(ap.rate):
            w = rp.value * ap.rate
            bx = bx - w * s
            by = by + w * c
    params[u1].rate, params[u2].rate = solve2(bx, by)

    # acceleration: Σ (r̈ e + 2ṙα̇ n + r α̈ n − r α̇² e) = 0 with the unknown accelerations zero
    bx, by = 0.0, 0.0
    for number in info.vectors:
        rp, ap = params[f"r{number}"], params[f"a{number}"]
        c, s = ap.trig()
        radial: Array | float = rp.accel
        tangential: Array | float = 0.0
        if not _is_zero(ap.rate):
            r_da = rp.value * ap.rate
            radial = radial - r_da * ap.rate
            if not _is_zero(rp.rate):
                tangential = 2.0 * rp.rate * ap.rate
        if not _is_zero(ap.accel):
            tangential = tangential + rp.value * ap.accel
        if not _is_zero(radial):
            bx = bx + radial * c
            by = by + radial * s
        if not _is_zero(tangential):
            bx = bx - tangential * s
            by = by + tangential * c
    params[u1].accel, params[u2].accel = solve2(bx, by)


def _points(module: str, unknowns, params: dict[str, _Param], v1: int, v2: int
            ) -> tuple[Array, ...]:
    """Cartesian coordinates that a solution branch places (for continuity tracking)."""
    (w1, c1, s1), (_, c2, s2) = unknowns
    if module == "Pl3":
        a1c, a1s = params[f"a{v1}"].trig()
        r2 = params[f"r{v2}"].value
        return (w1 * a1c, w1 * a1s, r2 * c2, r2 * s2)
    r1, r2 = params[f"r{v1}"].value, params[f"r{v2}"].value
    return (r1 * c1, r1 * s1, r2 * c2, r2 * s2)
