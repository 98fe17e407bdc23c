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

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.model.check import KIND_OF, argument_kind, require_valid
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.structure import ContourInfo, is_function
from mechloop.model.units import to_si
from mechloop.modules.planar import solve_pl1, solve_pl2, solve_pl3, solve_pl4, track_variant
from mechloop.solve.inputs import model_arguments, model_time
from mechloop.solve.results import ChainBreak, Results

Array = NDArray[np.float64]

#: A contour position whose Jacobian has |sin(angle between its columns)| below this is a
#: dead point: the position exists but velocities are unbounded.
SINGULAR_SIN = 1e-10

BREAK_REASONS = {
    "Pl1": "the closing vector has zero length, its direction is undefined",
    "Pl2": "the two vectors of unknown length are parallel",
    "Pl3": "the vector of known length cannot reach the line of the other vector",
    "Pl4": "the two vectors cannot close the loop (triangle inequality fails)",
}
DEAD_POINT = "dead point: the loop's Jacobian is singular, velocities are unbounded"


@dataclass
class _Param:
    value: Array | float
    rate: Array | float
    accel: Array | float


def unwrap_angles(angle: Array, ok: NDArray[np.bool_]) -> Array:
    """Make an angle continuous along positions (last axis), starting in [0, 2π).

    Rows where ``ok`` is false stay NaN and do not break the continuity of the others.
    """
    idx = np.where(ok, np.arange(angle.shape[-1]), 0)
    idx = np.maximum.accumulate(idx, axis=-1)
    filled = np.take_along_axis(np.where(ok, angle, 0.0), idx, axis=-1)
    first = np.argmax(ok, axis=-1)[..., None]
    start = np.take_along_axis(filled, first, axis=-1)
    filled = np.where(np.arange(angle.shape[-1]) < first, start, filled)
    steps = np.diff(filled, axis=-1)
    steps = (steps + np.pi) % (2 * np.pi) - np.pi
    base = np.mod(start, 2 * np.pi)
    cont = np.concatenate([base, base + np.cumsum(steps, axis=-1)], axis=-1)
    return np.where(ok, cont, np.nan)


def _constant_si(model: Model, name: str, value: float | str) -> float:
    kind = KIND_OF[name[0]]
    return to_si(value, kind, getattr(model.units, kind))


def solve(model: Model) -> Results:
    """Solve a model for positions, velocities and accelerations at every position.

    Returns :class:`~mechloop.solve.results.Results`; raises
    :class:`~mechloop.errors.ModelError` if the model is invalid and
    :class:`~mechloop.errors.SolveError` if its derivatives are undefined.
    """
    structure = require_valid(model)
    n_pos = model.positions + 1
    time = model_time(model)
    args = model_arguments(model, time)

    params: dict[str, _Param] = {}
    constant: set[str] = set()
    for number, vector in model.vectors.items():
        for letter in "ra":
            name = f"{letter}{number}"
            role = vector.r if letter == "r" else vector.a
            if isinstance(role, ArgumentRole):
                sig = args[role.argument]
                params[name] = _Param(sig.value + _constant_si(model, name, role.offset),
                                      sig.rate, sig.accel)
            elif not isinstance(role, LinkRole) and not is_function(role):
                params[name] = _Param(_constant_si(model, name, role), 0.0, 0.0)
                constant.add(name)

    def resolve(name: str) -> _Param | None:
        """The parameter, following links once their root is known."""
        if name in params:
            return params[name]
        chain = structure.links.get(name)
        if chain is None or chain.root not in params:
            return None
        root = params[chain.root]
        delta = sum(_constant_si(model, name, d) for d in chain.deltas)
        params[name] = _Param(root.value + delta, root.rate, root.accel)
        if chain.root in constant:
            constant.add(name)
        return params[name]

    broken_by: dict[int, NDArray[np.bool_]] = {}
    breaks: list[ChainBreak] = []
    for info in structure.ordered():
        inherited = np.zeros(n_pos, dtype=bool)
        for need in info.needs:
            inherited |= broken_by[need]
        no_solution, singular = _solve_contour(info, params, resolve, n_pos)
        no_solution &= ~inherited
        singular &= ~inherited
        broken_by[info.number] = no_solution | singular | inherited
        for reason, mask in ((BREAK_REASONS[info.module], no_solution),
                             (DEAD_POINT, singular)):
            if mask.any():
                breaks.append(ChainBreak(info.number, info.module, np.flatnonzero(mask),
                                         reason))

    for name in list(structure.links):
        resolve(name)

    broken = np.zeros(n_pos, dtype=bool)
    for mask in broken_by.values():
        broken |= mask
    values, rates, accels = {}, {}, {}
    for name, p in params.items():
        values[name] = np.broadcast_to(np.asarray(p.value, dtype=float), (n_pos,)).copy()
        rates[name] = np.broadcast_to(np.asarray(p.rate, dtype=float), (n_pos,)).copy()
        accels[name] = np.broadcast_to(np.asarray(p.accel, dtype=float), (n_pos,)).copy()
        if name not in constant:
            for arr in (values[name], rates[name], accels[name]):
                arr[broken] = np.nan
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
    )


def _solve_contour(info: ContourInfo, params: dict[str, _Param], resolve, n_pos: int
                   ) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """Solve one contour, adding its functions to ``params``.

    Returns two masks over positions: no real solution, and dead point (singular
    Jacobian).  Positions where an input is already NaN come out in the first mask.
    """
    u1, u2 = info.functions
    for number in info.vectors:
        for letter in "ra":
            name = f"{letter}{number}"
            if name not in (u1, u2) and resolve(name) is None:
                raise AssertionError(f"{name} not known before contour {info.number}")

    def value(name: str) -> Array | float:
        return params[name].value

    x: Array | float = 0.0
    y: Array | float = 0.0
    for number in info.vectors:
        rn, an = f"r{number}", f"a{number}"
        if rn in (u1, u2) or an in (u1, u2):
            continue
        r, a = value(rn), value(an)
        x = x + r * np.cos(a)
        y = y + r * np.sin(a)
    # vectors that carry an unknown still contribute nothing to X, Y: their known part is
    # handled by the module itself.
    module = info.module
    v1, v2 = int(u1[1:]), int(u2[1:])
    x = np.broadcast_to(np.asarray(x, dtype=float), (n_pos,))
    y = np.broadcast_to(np.asarray(y, dtype=float), (n_pos,))

    def run(variant):
        if module == "Pl1":
            return solve_pl1(x, y)
        if module == "Pl2":
            return solve_pl2(x, y, value(f"a{v1}"), value(f"a{v2}"))
        if module == "Pl3":
            return solve_pl3(x, y, value(f"a{v1}"), value(f"r{v2}"), variant=variant)
        return solve_pl4(x, y, value(f"r{v1}"), value(f"r{v2}"), variant=variant)

    if info.variant == "auto" and module in ("Pl3", "Pl4"):
        s1, s2 = run(1), run(2)
        ok_any = s1[2] & s2[2]
        variant = track_variant(_points(module, s1, value, v1, v2),
                                _points(module, s2, value, v1, v2), ok_any, start=1)
        w1, w2, ok = run(variant)
    else:
        w1, w2, ok = run(info.variant if info.variant != "auto" else 1)

    if u2[0] == "a":
        w2 = unwrap_angles(w2, ok)
    if u1[0] == "a":
        w1 = unwrap_angles(w1, ok)
    params[u1] = _Param(w1, 0.0, 0.0)
    params[u2] = _Param(w2, 0.0, 0.0)

    # Jacobian columns of the unknowns.
    def column(name: str) -> tuple[Array, Array]:
        number = int(name[1:])
        a = np.asarray(value(f"a{number}"), dtype=float)
        if name[0] == "r":
            return np.cos(a), np.sin(a)
        r = value(f"r{number}")
        return -r * np.sin(a), r * np.cos(a)

    c1x, c1y = column(u1)
    c2x, c2y = column(u2)
    det = c1x * c2y - c1y * c2x
    norm = np.hypot(c1x, c1y) * np.hypot(c2x, c2y)
    with np.errstate(invalid="ignore"):
        singular = ok & ~(np.abs(det) > SINGULAR_SIN * norm)
    good = ok & ~singular
    safe_det = np.where(good, det, 1.0)

    def solve2(bx: Array, by: Array) -> tuple[Array, Array]:
        d1 = (-bx * c2y + by * c2x) / safe_det
        d2 = (-c1x * by + c1y * bx) / safe_det
        return np.where(good, d1, np.nan), np.where(good, d2, np.nan)

    trig = {}
    for number in info.vectors:
        a = np.asarray(value(f"a{number}"), dtype=float)
        trig[number] = (np.cos(a), np.sin(a))

    bx: Array | float = 0.0
    by: Array | float = 0.0
    for number in info.vectors:
        c, s = trig[number]
        rp, ap = params[f"r{number}"], params[f"a{number}"]
        r = rp.value
        bx = bx + rp.rate * c - r * ap.rate * s
        by = by + rp.rate * s + r * ap.rate * c
    d1, d2 = solve2(bx, by)
    params[u1].rate, params[u2].rate = d1, d2

    bx, by = 0.0, 0.0
    for number in info.vectors:
        c, s = trig[number]
        rp, ap = params[f"r{number}"], params[f"a{number}"]
        r, dr, ddr, da, dda = rp.value, rp.rate, rp.accel, ap.rate, ap.accel
        tangential = 2 * dr * da + r * dda
        radial = ddr - r * da * da
        bx = bx + radial * c - tangential * s
        by = by + radial * s + tangential * c
    dd1, dd2 = solve2(bx, by)
    params[u1].accel, params[u2].accel = dd1, dd2

    return ~ok, singular


def _points(module: str, sol, value, v1: int, v2: int) -> tuple[Array, ...]:
    """Cartesian coordinates that a solution branch places (for continuity tracking)."""
    w1, w2, _ = sol
    if module == "Pl3":
        a1, r2 = value(f"a{v1}"), value(f"r{v2}")
        return (w1 * np.cos(a1), w1 * np.sin(a1), r2 * np.cos(w2), r2 * np.sin(w2))
    r1, r2 = value(f"r{v1}"), value(f"r{v2}")
    return (r1 * np.cos(w1), r1 * np.sin(w1), r2 * np.cos(w2), r2 * np.sin(w2))
