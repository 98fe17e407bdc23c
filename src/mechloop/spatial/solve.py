"""Positions, velocities and accelerations of a model with spatial contours (issue 17).

The blocks are solved one after another in the order of
:func:`mechloop.model.spatial.analyze_spatial`; each is one call over the whole array of
positions:

* a spatial contour by its module Pr1–Pr19 (:mod:`mechloop.spatial.contour`): every branch
  at once, then the variant's branch (fixed, or followed by continuity from position 0
  with ``auto``), then the exact rates by the 3×3 Jacobian (:mod:`mechloop.spatial.rates`);
* a planar contour (its vectors without β; in the XY plane or in its ``plane``,
  :mod:`mechloop.model.plane`, solved in that plane's axes) by its module Pl1–Pl4, its
  rates by the same 3×3 systems with a unit Z vector of unknown length 0 as the third
  unknown (its column is ``(0, 0, 1)``: the Z row gives 0 and the XY rows are exactly
  the planar 2×2 system);
* a coupled block (contours that need each other's functions, or a contour linking to
  one of its own) by Newton's method with continuation on its raw closure equations,
  its rates by the block Jacobian (:mod:`mechloop.spatial.block`), its breaks by the
  planar coupled solver's statuses (no assembly near the previous one, a dead point, a
  jump to another assembly).

A negative vector number in a spatial contour subtracts that vector: the closure is
multiplied by the sign of the module's vector ``i`` (so its length keeps the module's
sign convention) and every other subtracted vector enters with its length negated.
No real solution on the chosen branch is a chain break, a singular Jacobian a dead point
(the sine of the angle between the unit Jacobian columns below
:data:`~mechloop.solve.kinematics.SINGULAR_SIN`); both are reported per contour and make
the row NaN, as in the planar core.  Solved angles are made continuous along the
positions: an α from position 0's value in [0, 2π) as the planar core does, a β from
its value at position 0.  The arrays are ``(P,)``: a model is one design.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from mechloop.errors import SolveError
from mechloop.model.check import KIND_OF, argument_kind
from mechloop.model.plane import plane_axes
from mechloop.model.roles import is_function
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.spatial import contour_signs, plane_normal
from mechloop.model.structure import COUPLED, ContourInfo, Structure, param_role
from mechloop.model.units import to_si
from mechloop.modules.coupled import DEAD, JUMP, NO_CONVERGENCE, OK, REASONS
from mechloop.modules.planar import solve_pl1, solve_pl2, solve_pl3, solve_pl4
from mechloop.solve.inputs import Signal, model_arguments, model_time
from mechloop.solve.kinematics import BREAK_REASONS, DEAD_POINT, SINGULAR_SIN, unwrap_angles
from mechloop.solve.results import ChainBreak, Results
from mechloop.spatial.block import solve_coupled
from mechloop.spatial.contour import classify, follow_branch, run_module
from mechloop.spatial.rates import accelerations, rates
from mechloop.spatial.vector import unit

Array = NDArray[np.float64]
Triple = tuple[Array, Array, Array]  # value, rate, acceleration, each (P,)


@dataclass(frozen=True)
class SpatialResults(Results):
    """:class:`~mechloop.solve.results.Results` of a model with spatial contours: the
    parameters include ``b<n>`` (β, rad) of the spatial vectors, and the table adds the
    components of every vector of a spatial contour that is not constant, with their
    derivatives (``x3 [m]``, ``dx3 [m/s]``, ``ddx3 [m/s^2]``, then y, z)."""

    spatial_vectors: tuple[int, ...] = ()
    #: the in-plane axes ``(e1, e2)`` of every vector of a planar contour
    axes: dict[int, tuple[Array, Array]] = field(default_factory=dict)

    def components(self, number: int) -> tuple[Triple, Triple, Triple]:
        """``(x, y, z)`` of vector ``number`` (m), each as (value, first, second
        derivative): ``d(r u) = ṙ u + r (α̇ u_α + β̇ u_β)`` and its derivative; a vector
        of a planar contour is ``r (cos α e1 + sin α e2)`` in its plane's axes."""
        if number in self.axes:
            r, a = (self.values[f"{k}{number}"] for k in "ra")
            dr, da = (self.rates[f"{k}{number}"] for k in "ra")
            ddr, dda = (self.accels[f"{k}{number}"] for k in "ra")
            e1, e2 = (x[:, None] for x in self.axes[number])
            u = np.cos(a) * e1 + np.sin(a) * e2
            n = -np.sin(a) * e1 + np.cos(a) * e2
            value = r * u
            rate = dr * u + r * da * n
            accel = (ddr - r * da**2) * u + (2.0 * dr * da + r * dda) * n
        else:
            r, a, b = (self.values[f"{k}{number}"] for k in "rab")
            dr, da, db = (self.rates[f"{k}{number}"] for k in "rab")
            ddr, dda, ddb = (self.accels[f"{k}{number}"] for k in "rab")
            e = _basis(a, b)
            turn = da * e["a"] + db * e["b"]
            value = r * e["u"]
            rate = dr * e["u"] + r * turn
            accel = (ddr * e["u"] + 2.0 * dr * turn + r * (dda * e["a"] + ddb * e["b"])
                     + r * (-da**2 * e["u"] + 2.0 * da * db * e["ab"] + db**2 * e["bb"]))
        return tuple((value[i], rate[i], accel[i]) for i in range(3))  # type: ignore[return-value]

    def to_frame(self) -> pd.DataFrame:
        frame = super().to_frame()
        d1, d2 = self.derivative_units()
        flag = frame.pop("chain_break")
        for number in sorted({*self.spatial_vectors, *self.axes}):
            if all(f"{k}{number}" in self.constant for k in "rab"):
                continue  # a constant vector (as constant parameters, not tabulated)
            for axis, (v, dv, ddv) in zip("xyz", self.components(number), strict=True):
                name = f"{axis}{number}"
                frame[f"{name} [m]"] = v
                frame[f"d{name} [m/{d1}]"] = dv
                frame[f"dd{name} [m/{d2}]"] = ddv
        frame["chain_break"] = flag
        return frame


def _basis(alpha: Array, beta: Array) -> dict[str, Array]:
    """``u`` and its derivatives by α and β (stacked x, y, z on the first axis)."""
    ca, sa, cb, sb = np.cos(alpha), np.sin(alpha), np.cos(beta), np.sin(beta)
    zero = np.zeros_like(ca * cb)
    return {"u": np.stack([ca * cb, sa + zero, ca * sb]),
            "a": np.stack([-sa * cb, ca + zero, -sa * sb]),
            "b": np.stack([-ca * sb, zero, ca * cb]),
            "ab": np.stack([sa * sb, zero, -sa * cb]),
            "bb": np.stack([-ca * cb, zero, -ca * sb])}


def _inputs(model: Model, analogs_of: int | None) -> tuple[Signal | None, dict[int, Signal]]:
    """Model time and arguments as in :func:`mechloop.solve.kinematics.solve`."""
    n_pos = model.positions + 1
    time = model_time(model)
    if analogs_of is None:
        return time, model_arguments(model, time)
    if analogs_of not in model.arguments:
        raise SolveError(f"the model has no argument {analogs_of}",
                         f"use one of {sorted(model.arguments)}")
    return None, {k: Signal(s.value, np.full(n_pos, float(k == analogs_of)), np.zeros(n_pos))
                  for k, s in model_arguments(model, time, strict=False).items()}


class _Params:
    """Every parameter over the positions, SI, resolved on demand from its role; arrays
    shaped ``shape``: ``(P,)``, or ``(D, P)`` when ``over`` gives some constants, link
    deltas or argument offsets one value per design (arrays ``(D,)``, SI)."""

    def __init__(self, model: Model, structure: Structure, args: dict[int, Signal],
                 over: dict[str, Array] | None = None):
        self.model, self.structure, self.args = model, structure, args
        self.over = {k: np.asarray(v, dtype=float)[:, None] for k, v in (over or {}).items()}
        n_designs = {v.shape[0] for v in self.over.values()}
        self.shape: tuple[int, ...] = (*n_designs, model.positions + 1)
        self.known: dict[str, Triple] = {}
        self.constant: set[str] = set()

    def si(self, name: str, value: float | str) -> Array | float:
        """The number ``value`` of parameter ``name`` in SI, or its designs' values."""
        if name in self.over:
            return self.over[name]
        kind = KIND_OF[name[0]]
        return to_si(value, kind, getattr(self.model.units, kind))

    def __call__(self, name: str) -> Triple:
        if name in self.known:
            return self.known[name]
        zero = np.zeros(self.shape)
        role = param_role(self.model, name)
        if isinstance(role, ArgumentRole):
            sig = self.args[role.argument]
            out = (sig.value + self.si(name, role.offset), sig.rate, sig.accel)
        elif isinstance(role, LinkRole):
            chain = self.structure.links[name]
            root = self(chain.root)
            # p = k·q + Δ step by step: the composed factor and delta (each step's own Δ)
            delta: Array | float = 0.0
            factor = 1.0
            current = name
            while isinstance(step := param_role(self.model, current), LinkRole):
                delta = delta + factor * self.si(current, step.delta)
                factor *= float(step.ratio)
                current = step.link
            out = (factor * root[0] + delta, factor * root[1], factor * root[2])
            if chain.root in self.constant:
                self.constant.add(name)
        else:
            out = (self.si(name, role) + zero, zero, zero)
            self.constant.add(name)
        out = tuple(np.broadcast_to(x, self.shape) for x in out)
        self.known[name] = out  # type: ignore[assignment]
        return out  # type: ignore[return-value]


@dataclass
class _Solved:
    """Every contour solved: the parameters, and per contour where it has no solution,
    its dead points and the sign of its Jacobian (the assembly branch; 0 where not
    regular), each shaped like the parameters."""

    params: _Params
    no_solution: dict[int, NDArray[np.bool_]]
    dead: dict[int, NDArray[np.bool_]]
    sign: dict[int, NDArray[np.int8]]
    broken: NDArray[np.bool_]
    #: per coupled block (by its first contour): the status of every position
    #: (:data:`mechloop.modules.coupled.OK`, ...)
    status: dict[int, NDArray[np.int8]] = field(default_factory=dict)


def _solve_all(model: Model, structure: Structure, args: dict[int, Signal],
               over: dict[str, Array] | None = None) -> _Solved:
    params = _Params(model, structure, args, over)
    broken = np.zeros(params.shape, dtype=bool)
    out = _Solved(params, {}, {}, {}, broken)
    with np.errstate(all="ignore"):
        by_number = {info.number: info for info in structure.contours}
        for block in structure.blocks:
            if block.coupled:  # solved together (mechloop.spatial.block)
                status, sign = solve_coupled(model, structure, block, params, SINGULAR_SIN)
                out.status[block.contours[0]] = status
                for n in block.contours:
                    out.no_solution[n] = (status == NO_CONVERGENCE) | (status == JUMP)
                    out.dead[n], out.sign[n] = status == DEAD, sign
                broken |= status != OK
                continue
            info = by_number[block.contours[0]]
            no_solution, dead, sign = _solve_contour(model, info, params)
            out.no_solution[info.number], out.dead[info.number] = no_solution, dead
            out.sign[info.number] = sign
            broken |= no_solution | dead
    return out


def _axes(model: Model, structure: Structure) -> dict[int, tuple[Array, Array]]:
    """The in-plane axes of every vector of a planar contour."""
    axes = {}
    for info in structure.contours:
        contour = model.contours[info.number - 1]
        if not contour.spatial:
            e1e2 = plane_axes(plane_normal(model, contour.plane))
            axes.update({n: e1e2 for n in info.vectors})
    return axes


def _names(model: Model, structure: Structure) -> tuple[list[str], tuple[int, ...]]:
    spatial = tuple(sorted(n for info in structure.contours
                           if model.contours[info.number - 1].spatial for n in info.vectors))
    return [f"{letter}{number}" for number in sorted(model.vectors)
            for letter in ("rab" if number in spatial else "ra")], spatial


def solve_spatial(model: Model, structure: Structure, *, analogs_of: int | None = None
                  ) -> SpatialResults:
    """Solve a valid model with spatial contours (``structure`` from
    :func:`~mechloop.model.spatial.analyze_spatial`) at every position.

    Derivatives are with respect to time, or the analogs with respect to argument
    ``analogs_of`` (or argument 1 without model time), as in the planar solve.
    """
    time, args = _inputs(model, analogs_of)
    solved = _solve_all(model, structure, args)
    params, broken = solved.params, solved.broken
    breaks: list[ChainBreak] = []
    seen = np.zeros_like(broken)
    for info in structure.ordered():
        if info.number in solved.status:  # a coupled block: its breaks by status
            status = solved.status[info.number]
            block = next(b for b in structure.blocks if b.contours[0] == info.number)
            for code in (NO_CONVERGENCE, DEAD, JUMP):
                mask = (status == code) & ~seen
                if mask.any():
                    breaks.append(ChainBreak(info.number, COUPLED, np.flatnonzero(mask),
                                             REASONS[code], contours=block.contours))
            seen |= status != OK
            continue
        if info.module == COUPLED:
            continue
        no_solution, dead = solved.no_solution[info.number], solved.dead[info.number]
        for reason, mask in ((_break_reason(info), no_solution & ~seen),
                             (DEAD_POINT, dead & ~no_solution & ~seen)):
            if mask.any():
                breaks.append(ChainBreak(info.number, info.module, np.flatnonzero(mask),
                                         reason))
        seen |= no_solution | dead
    names, spatial = _names(model, structure)
    values, rate, accel = {}, {}, {}
    for name in names:
        values[name], rate[name], accel[name] = (np.where(broken, np.nan, x)
                                                 for x in params(name))
    axes = _axes(model, structure)
    constant = frozenset(params.constant | {f"b{n}" for n in axes})
    for name in constant:
        values[name] = np.array(params(name)[0])  # a constant stays defined on broken rows
    return SpatialResults(
        model=model, structure=structure, time=None if time is None else time.value,
        arguments={k: s.value for k, s in args.items()},
        argument_kinds={k: argument_kind(model, k) for k in model.arguments},
        values=values, rates=rate, accels=accel, constant=constant, broken=broken,
        breaks=tuple(sorted(breaks, key=lambda b: b.contour)), analogs_of=analogs_of,
        spatial_vectors=spatial, axes=axes)


def solve_spatial_designs(model: Model, structure: Structure, overrides: dict[str, Array],
                          *, analogs_of: int | None = None):
    """``D`` designs of a model with spatial contours at every position in one vectorized
    pass (``overrides``: constants, link deltas or argument offsets, one value per
    design, SI): :class:`~mechloop.solve.designs.DesignResults` with arrays ``(D, P)``,
    derivatives included."""
    from mechloop.solve.designs import DesignResults

    time, args = _inputs(model, analogs_of)
    names, _ = _names(model, structure)
    unknown = sorted(set(overrides) - {n for n in names
                                       if not is_function(param_role(model, n))})
    if unknown:
        raise SolveError(f"cannot vary {', '.join(unknown)}: only constants, link deltas "
                         "and argument offsets can differ between designs",
                         "vary a parameter whose role is a number, a link or an argument")
    over = {k: np.atleast_1d(np.asarray(v, dtype=float)) for k, v in overrides.items()}
    if len({v.shape for v in over.values()}) > 1 or any(v.ndim != 1 for v in over.values()):
        raise SolveError("every varied parameter needs one value per design",
                         "pass 1-D arrays of one length")
    solved = _solve_all(model, structure, args, over)
    params, broken = solved.params, solved.broken
    values, rate, accel = {}, {}, {}
    for name in names:
        v, d, dd = params(name)
        if name in params.constant:
            values[name], rate[name], accel[name] = v, d, dd
        else:
            values[name], rate[name], accel[name] = (np.where(broken, np.nan, x)
                                                     for x in (v, d, dd))
    changes = {}
    for number, sign in solved.sign.items():
        flat = sign.reshape(-1, sign.shape[-1])
        # the sign at the previous regular position, carried over the irregular ones
        index = np.where(flat != 0, np.arange(flat.shape[-1]), 0)
        np.maximum.accumulate(index, axis=-1, out=index)
        last = np.take_along_axis(flat, index, axis=-1)
        flips = (flat[:, 1:] != 0) & (last[:, :-1] != 0) & (flat[:, 1:] != last[:, :-1])
        changes[number] = flips.any(axis=-1).reshape(sign.shape[:-1])
    return DesignResults(
        model=model, arguments={k: s.value for k, s in args.items()},
        time=None if time is None else time.value, values=values, rates=rate,
        accels=accel, broken=broken, no_solution=solved.no_solution, dead=solved.dead,
        branch_changes=changes)


def _break_reason(info: ContourInfo) -> str:
    if info.module in BREAK_REASONS:
        return BREAK_REASONS[info.module]
    return (f"module {info.module} has no real solution on the chosen variant (the "
            "vectors cannot close the loop in space)")


def _solve_contour(model: Model, info: ContourInfo, params: _Params
                   ) -> tuple[NDArray[np.bool_], NDArray[np.bool_], NDArray[np.int8]]:
    """Solve one contour, adding its functions to ``params``; returns the positions with
    no real solution, the dead points and the sign of the Jacobian (0 where neither
    regular)."""
    contour = model.contours[info.number - 1]
    signs = contour_signs(model, info.number - 1)
    letters = "rab" if contour.spatial else "ra"
    unknown = set(info.functions)
    found = [(n, k) for n, _ in signs for k in letters if f"{k}{n}" in unknown]
    sign_of = dict(signs)
    shape = params.shape
    zero = np.zeros(shape)

    def get(n: int, k: str) -> Triple:
        if k == "b" and not contour.spatial:
            return zero, zero, zero
        return params(f"{k}{n}")

    carriers = {n for n, _ in found}
    s = [np.zeros(shape) for _ in range(3)]
    for n, sign in signs:
        if n in carriers:
            continue
        comp = unit(get(n, "a")[0], get(n, "b")[0])
        r = get(n, "r")[0]
        for axis in range(3):
            s[axis] = s[axis] + sign * r * comp[axis]

    if contour.spatial:
        choice = classify(found)
        assert choice is not None
        flip = sign_of[choice.roles[0]]
        eff = {n: flip * sign_of[n] for n in choice.roles}
        known = {(n, k): (eff[n] if k == "r" else 1.0) * get(n, k)[0]
                 for n in choice.roles for k in "rab" if (n, k) not in choice.unknowns}
        vals, ok = run_module(choice, (flip * s[0], flip * s[1], flip * s[2]), known,
                              convention=contour.convention)
        vals = tuple(eff[n] * v if k == "r" else v
                     for (n, k), v in zip(choice.unknowns, vals, strict=True))
        order = choice.unknowns
    else:
        order = tuple((int(f[1:]), f[0]) for f in info.functions)
        vals, ok = _planar_branches(info.module, order, s, get)

    # the branch at every position: the variant's, or followed from variant 1 (auto)
    n_branch = ok.shape[0]
    if info.variant == "auto" and n_branch > 1:
        points = _branch_points(order, vals, get, n_branch)
        index = follow_branch(points, ok, 0)
    else:
        index = np.full(shape, (1 if info.variant == "auto" else info.variant) - 1)
    chosen = [np.take_along_axis(v, index[None], axis=0)[0] for v in vals]
    good = np.take_along_axis(ok, index[None], axis=0)[0] & np.isfinite(s).all(axis=0)
    for (n, k), v in zip(order, chosen, strict=True):
        params.known[f"{k}{n}"] = (np.where(good, v, np.nan), zero, zero)

    # exact rates by the 3×3 Jacobian of the whole contour (signed lengths)
    numbers = [n for n, _ in signs]
    triples = {k: [get(n, k) for n in numbers] for k in "rab"}
    sgn = np.array([sign_of[n] for n in numbers]).reshape((-1,) + (1,) * len(shape))
    stacked = {k: [np.stack([t[i] for t in triples[k]]) for i in range(3)] for k in "rab"}
    r, dr, ddr = (sgn * x for x in stacked["r"])
    a, da, dda = stacked["a"]
    b, db, ddb = stacked["b"]
    slots = [(numbers.index(n), k) for n, k in order]
    if not contour.spatial:  # the planar contour's third unknown: a unit Z vector
        pad = np.zeros((1, *shape))
        r, dr, ddr, a, da, dda, db, ddb = (np.concatenate([x, pad]) for x in
                                          (r, dr, ddr, a, da, dda, db, ddb))
        b = np.concatenate([b, np.full((1, *shape), np.pi / 2)])
        slots.append((len(numbers), "r"))
    det, degenerate = _jacobian_sine(r, a, b, slots)
    dead = good & ((np.abs(det) < SINGULAR_SIN) | degenerate)
    good &= ~dead
    sign = np.where(good, np.sign(det), 0).astype(np.int8)
    d1 = rates(r, a, b, dr, da, db, slots)[:3]
    dr, da, db = (_filled(x, slots, name, d1) for x, name in ((dr, "r"), (da, "a"), (db, "b")))
    d2 = accelerations(r, a, b, dr, da, db, ddr, dda, ddb, slots)[:3]
    for slot, (n, k), v1, v2 in zip(slots, order, d1, d2, strict=False):
        scale = sgn[slot[0], 0] if k == "r" else 1.0
        value = params.known[f"{k}{n}"][0]
        if k == "a" or (k == "b" and contour.spatial):
            # α from [0, 2π) as the planar core; β, and α in convention 2, from their own
            value = _continuous(value, good, base_turn=k == "a" and contour.convention == 1)
        params.known[f"{k}{n}"] = (value, np.where(good, scale * v1, np.nan),
                                   np.where(good, scale * v2, np.nan))
    return ~good & ~dead, dead, sign


def _filled(x: Array, slots: list[tuple[int, str]], letter: str, solved: tuple) -> Array:
    """``x`` (m, P) with the unknowns' rates of kind ``letter`` put in."""
    x = x.copy()
    for (v, k), value in zip(slots, solved, strict=True):
        if k == letter:
            x[v] = value
    return x


def _continuous(angle: Array, good: NDArray[np.bool_], *, base_turn: bool) -> Array:
    """A solved angle made continuous along the positions (NaN where not ``good``): from
    its value at the first good position in [0, 2π) (``base_turn``), else as it is."""
    if not good.any():
        return angle
    out = unwrap_angles(angle, good)
    if not base_turn:
        first = np.argmax(good, axis=-1)[..., None]  # the first good position of a row
        out = out + (np.take_along_axis(angle, first, axis=-1)
                     - np.take_along_axis(out, first, axis=-1))
    return out


def _jacobian_sine(r: Array, a: Array, b: Array, slots: list[tuple[int, str]]
                   ) -> tuple[Array, NDArray[np.bool_]]:
    """The contour's Jacobian in the unit frame of its unknowns' vectors: the determinant
    of the columns ``u`` (a length), ``u_α`` (an elevation), ``u_β / cos α`` (a rotation)
    — ±1 for orthogonal columns, 0 at a dead point, its sign the assembly branch (no
    parametrization's sign in it) — and where a column itself vanishes (``r = 0`` under
    an angle, ``cos α = 0`` under a rotation: also a dead point), relative to the
    contour's longest vector."""
    size = np.abs(r).max(axis=0)
    cols, degenerate = [], np.zeros(np.shape(size), dtype=bool)
    for v, k in slots:
        e = _basis(a[v], b[v])
        if k == "r":
            cols.append(e["u"])
            continue
        scale = r[v] * (1.0 if k == "a" else np.cos(a[v]))
        degenerate |= ~(np.abs(scale) > SINGULAR_SIN * size)
        cols.append(e["a"] if k == "a" else np.stack(
            [-np.sin(b[v]), np.zeros_like(b[v]), np.cos(b[v])]))
    mat = np.moveaxis(np.stack(np.broadcast_arrays(*cols)), (0, 1), (-1, -2))
    return np.linalg.det(np.where(np.isfinite(mat), mat, 0.0)), degenerate


def _planar_branches(module: str, order, s: list[Array], get) -> tuple[tuple[Array, ...],
                                                                       NDArray[np.bool_]]:
    """Both variants of a planar contour's module (one for Pl1, Pl2): the unknowns in
    ``order``, each ``(B, P)``, and ``ok``."""
    (n1, _), (n2, _) = order
    x, y = s[0], s[1]
    if module == "Pl1":
        out = [solve_pl1(x, y)]
    elif module == "Pl2":
        out = [solve_pl2(x, y, get(n1, "a")[0], get(n2, "a")[0])]
    elif module == "Pl3":
        out = [solve_pl3(x, y, get(n1, "a")[0], get(n2, "r")[0], variant=v) for v in (1, 2)]
    else:
        out = [solve_pl4(x, y, get(n1, "r")[0], get(n2, "r")[0], variant=v) for v in (1, 2)]
    first = np.stack([o[0] for o in out])
    second = np.stack([o[1] for o in out])
    ok = np.stack([o[2] for o in out])
    return (first, second), ok


def _branch_points(order, vals: tuple[Array, ...], get, n_branch: int) -> Array:
    """Per branch, the Cartesian components of the vectors that carry the unknowns
    ``(B, 3·m, P)`` (for continuity tracking)."""
    carriers = sorted({n for n, _ in order})
    coords = []
    for n in carriers:
        par = {}
        for k in "rab":
            if (n, k) in order:
                par[k] = vals[order.index((n, k))]
            else:
                par[k] = np.broadcast_to(get(n, k)[0], vals[0].shape)
        ux, uy, uz = unit(par["a"], par["b"])
        coords += [par["r"] * ux, par["r"] * uy, par["r"] * uz]
    return np.stack(coords, axis=1)
