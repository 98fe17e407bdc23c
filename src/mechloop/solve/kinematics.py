"""Positions, velocities and accelerations of every vector parameter over all positions.

The contours are solved in dependency order; each is one call of its elementary module over
the whole array of positions, then two 2×2 linear solves with the module's Jacobian
(DESIGN §3):

* velocity: ``Σ (ṙ_i e_i + r_i α̇_i n_i) = 0``,
* acceleration: ``Σ (r̈_i e_i + 2 ṙ_i α̇_i n_i + r_i α̈_i n_i − r_i α̇_i² e_i) = 0``,

with ``e = (cos α, sin α)``, ``n = (−sin α, cos α)``: the unknown rates multiply the
Jacobian columns (``e_j`` for an unknown length, ``r_j n_j`` for an unknown angle) and all
other terms are known.  No Python loop runs over positions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import SolveError
from mechloop.model.check import KIND_OF, argument_kind, require_valid
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.structure import ContourInfo, is_function
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
from mechloop.solve.results import ChainBreak, Results

Array = NDArray[np.float64]

#: A contour position whose Jacobian has |sin(angle between its columns)| below this is a
#: dead point: the position exists but velocities are unbounded.  Modules accept a
#: position whose discriminant is as low as ``-EXISTENCE_RTOL·r²`` (rounding), so near a
#: limit position the computed sine is only known to about ``sqrt(EXISTENCE_RTOL)``;
#: below that the rates would be noise amplified by up to 1e8.
SINGULAR_SIN = math.sqrt(EXISTENCE_RTOL)

BREAK_REASONS = {
    "Pl1": "the closing vector has zero length, its direction is undefined",
    "Pl2": "the two vectors of unknown length are parallel",
    "Pl3": "the vector of known length cannot reach the line of the other vector",
    "Pl4": "the two vectors cannot close the loop (triangle inequality fails)",
}
DEAD_POINT = "dead point: the loop's Jacobian is singular, velocities are unbounded"


@dataclass
class _Param:
    """A parameter over positions: value, rate, acceleration (arrays or scalars), and for
    angles the cached cosine and sine of the value."""

    value: Array | float
    rate: Array | float
    accel: Array | float
    cos: Array | float | None = None
    sin: Array | float | None = None

    def trig(self) -> tuple[Array | float, Array | float]:
        if self.cos is None:
            self.cos, self.sin = np.cos(self.value), np.sin(self.value)
        return self.cos, self.sin


def _is_zero(term: Array | float) -> bool:
    return np.isscalar(term) and term == 0


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
        steps = (steps + np.pi) % two_pi - np.pi
        return np.concatenate([base, base + np.cumsum(steps, axis=-1)], axis=-1)
    idx = np.where(ok, np.arange(angle.shape[-1]), 0)
    idx = np.maximum.accumulate(idx, axis=-1)
    filled = np.take_along_axis(np.where(ok, angle, 0.0), idx, axis=-1)
    first = np.argmax(ok, axis=-1)[..., None]
    start = np.take_along_axis(filled, first, axis=-1)
    filled = np.where(np.arange(angle.shape[-1]) < first, start, filled)
    steps = np.diff(filled, axis=-1)
    steps = (steps + np.pi) % two_pi - np.pi
    base = np.mod(start, two_pi)
    cont = np.concatenate([base, base + np.cumsum(steps, axis=-1)], axis=-1)
    return np.where(ok, cont, np.nan)


def _constant_si(model: Model, name: str, value: float | str) -> float:
    kind = KIND_OF[name[0]]
    return to_si(value, kind, getattr(model.units, kind))


#: Positions solved together in one block: small enough that a block's temporaries stay
#: in the CPU cache, large enough that NumPy's per-call overhead is negligible.
BLOCK = 8192


def solve(model: Model, *, block: int = BLOCK, analogs_of: int | None = None) -> Results:
    """Solve a model for positions, velocities and accelerations at every position.

    With ``analogs_of=k`` the derivatives are the analogs with respect to argument ``k``
    alone (its rate 1 and acceleration 0, every other argument held): first- and
    second-order transfer functions, per rad or per m of that argument.

    The positions are processed in blocks of ``block`` (all contours of a block at once,
    every operation vectorized over the block); results do not depend on ``block``.

    Returns :class:`~mechloop.solve.results.Results`; raises
    :class:`~mechloop.errors.ModelError` if the model is invalid and
    :class:`~mechloop.errors.SolveError` if its derivatives are undefined.
    """
    structure = require_valid(model)
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

    constants: dict[str, float] = {}
    driven: dict[str, tuple[Signal, float]] = {}
    for number, vector in model.vectors.items():
        for letter in "ra":
            name = f"{letter}{number}"
            role = vector.r if letter == "r" else vector.a
            if isinstance(role, ArgumentRole):
                driven[name] = (args[role.argument],
                                _constant_si(model, name, role.offset))
            elif not isinstance(role, LinkRole) and not is_function(role):
                constants[name] = _constant_si(model, name, role)
    deltas = {name: sum(_constant_si(model, name, d) for d in chain.deltas)
              for name, chain in structure.links.items()}
    constant = set(constants) | {n for n, c in structure.links.items()
                                 if c.root in constants}
    varying = [f"{letter}{n}" for n in sorted(model.vectors) for letter in "ra"
               if f"{letter}{n}" not in constant]
    out = {name: (np.empty(n_pos), np.empty(n_pos), np.empty(n_pos)) for name in varying}
    ordered = structure.ordered()
    no_solution = {c.number: np.zeros(n_pos, dtype=bool) for c in ordered}
    singular = {c.number: np.zeros(n_pos, dtype=bool) for c in ordered}
    broken_by = {c.number: np.zeros(n_pos, dtype=bool) for c in ordered}
    last_variant: dict[int, int] = {}

    for first in range(0, n_pos, max(int(block), 2)):
        lo = max(first - 1, 0)  # one position of overlap carries variant tracking across
        hi = min(first + max(int(block), 2), n_pos)
        size, skip = hi - lo, first - lo
        params = {name: _Param(value, 0.0, 0.0) for name, value in constants.items()}
        for name, (sig, offset) in driven.items():
            params[name] = _Param(sig.value[lo:hi] + offset, sig.rate[lo:hi],
                                  sig.accel[lo:hi])

        def resolve(name: str, params: dict[str, _Param] = params) -> _Param | None:
            """The parameter, following links once their root is known."""
            if name in params:
                return params[name]
            chain = structure.links.get(name)
            if chain is None or chain.root not in params:
                return None
            root = params[chain.root]
            delta = deltas[name]
            param = _Param(root.value + delta, root.rate, root.accel)
            if name[0] == "a":
                rc, rs = root.trig()
                cd, sd = np.cos(delta), np.sin(delta)
                param.cos, param.sin = rc * cd - rs * sd, rs * cd + rc * sd
            params[name] = param
            return param

        for info in ordered:
            inherited = np.zeros(size, dtype=bool)
            for need in info.needs:
                inherited |= broken_by[need][lo:hi]
            none, dead, variant = _solve_contour(info, params, resolve, size,
                                                 start=last_variant.get(info.number, 1))
            last_variant[info.number] = variant
            none &= ~inherited
            dead &= ~inherited
            no_solution[info.number][first:hi] = none[skip:]
            singular[info.number][first:hi] = dead[skip:]
            broken_by[info.number][lo:hi] = (none | dead | inherited)
        for name in structure.links:
            resolve(name)
        for name, arrays in out.items():
            p = params[name]
            for target, field in zip(arrays, (p.value, p.rate, p.accel), strict=True):
                target[first:hi] = np.broadcast_to(field, (size,))[skip:]

    broken = np.zeros(n_pos, dtype=bool)
    for mask in broken_by.values():
        broken |= mask
    for info in ordered:
        for name in info.functions:
            if name[0] == "a":
                value = out[name][0]
                value[:] = unwrap_angles(value, np.isfinite(value))
    for name, chain in structure.links.items():
        if name in out and chain.root in out:
            out[name][0][:] = out[chain.root][0] + deltas[name]
    if broken.any():
        for arrays in out.values():
            for arr in arrays:
                arr[broken] = np.nan

    breaks = []
    for info in ordered:
        for reason, mask in ((BREAK_REASONS[info.module], no_solution[info.number]),
                             (DEAD_POINT, singular[info.number])):
            if mask.any():
                breaks.append(ChainBreak(info.number, info.module, np.flatnonzero(mask),
                                         reason))
    values, rates, accels = {}, {}, {}
    for name, (value, rate, accel) in out.items():
        values[name], rates[name], accels[name] = value, rate, accel
    zero = np.broadcast_to(0.0, (n_pos,))
    for name in constant:
        root = structure.links[name].root if name in structure.links else name
        value = constants[root] + deltas.get(name, 0.0)
        values[name], rates[name], accels[name] = np.broadcast_to(value, (n_pos,)), zero, zero
    arg_kinds = {k: argument_kind(model, k) for k in model.arguments}
    return Results(
        model=model,
        structure=structure,
        time=None if time is None else time.value,
        arguments={k: s.value for k, s in args.items()},
        argument_kinds=arg_kinds,
        values=values,
        rates=rates,
        accels=accels,
        constant=frozenset(constant),
        broken=broken,
        breaks=tuple(sorted(breaks, key=lambda b: b.contour)),
        analogs_of=analogs_of,
    )


def _solve_contour(info: ContourInfo, params: dict[str, _Param], resolve, n_pos: int, *,
                   start: int = 1) -> tuple[NDArray[np.bool_], NDArray[np.bool_], int]:
    """Solve one contour, adding its functions to ``params``.

    ``start`` is the variant at the first position when the variant is tracked (``auto``).
    Returns two masks over positions — no real solution, and dead point (singular
    Jacobian; positions where an input is already NaN come out in the first mask) — and
    the variant in use at the last position.
    """
    u1, u2 = info.functions
    for number in info.vectors:
        for letter in "ra":
            name = f"{letter}{number}"
            if name not in (u1, u2) and resolve(name) is None:
                raise AssertionError(f"{name} not known before contour {info.number}")

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
    x = np.broadcast_to(np.asarray(x, dtype=float), (n_pos,))
    y = np.broadcast_to(np.asarray(y, dtype=float), (n_pos,))

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
        last = int(variant[-1])
    else:
        last = info.variant if info.variant != "auto" else 1
        unknowns, ok = run(last)

    for name, (val, c, s) in zip((u1, u2), unknowns, strict=True):
        if name[0] == "a":
            params[name] = _Param(np.arctan2(s, c), 0.0, 0.0, c, s)  # unwrapped at the end
        else:
            params[name] = _Param(val, 0.0, 0.0)

    # Jacobian columns of the unknowns: e_j for a length, r_j n_j for an angle.
    def column(name: str) -> tuple[Array, Array]:
        number = int(name[1:])
        c, s = params[f"a{number}"].trig()
        if name[0] == "r":
            return c, s
        r = params[f"r{number}"].value
        return -r * s, r * c

    c1x, c1y = column(u1)
    c2x, c2y = column(u2)
    det = c1x * c2y - c1y * c2x
    norm = np.sqrt((c1x * c1x + c1y * c1y) * (c2x * c2x + c2y * c2y))
    with np.errstate(invalid="ignore"):
        singular = ok & ~(np.abs(det) > SINGULAR_SIN * norm)
    good = ok & ~singular
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
    return ~ok, singular, last


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
