"""Intermediate arguments: an argument swept inside every calculation position, and the
envelope of the curves a point draws over it (KDAM's "промежуточные аргументы").

A thin layer over the vectorized solve (:func:`mechloop.solve.kinematics._solve_block`):
the sweep's ``M`` values become a leading axis, so one call solves every contour over
``(M, P)`` elements at once (in chunks of rows when large) — no Python loop runs over
positions or over the sweep.  The parameters driven by the intermediate argument, and
every parameter of the contours depending on them, come out shaped ``(P, M)``; the others
keep ``(P,)`` (those of the ordinary solve, which holds the argument at its first value).

The intermediate argument does not move in time: its rate is zero in the velocities and
accelerations.  Its own direction is solved like an analog — the same linear systems with
its rate 1 and every other argument's 0 — giving ``∂q/∂θ`` and ``∂²q/∂θ²``.

**Envelope.**  For a point ``C(θ, s)`` (the end of a chain of vectors; ``s`` runs along the
positions), the envelope of the curves ``θ ↦ C(θ, s)`` touches the curve of position
``s`` where ``∂C/∂θ × ∂C/∂s = 0``.  The cross product is sampled over the sweep; every
sign change is refined by Chandrupatla's bracketing method
(:func:`scipy.optimize.elementwise.find_root`, all brackets of all positions together),
each evaluation an exact solve at the bracket's own position and ``θ`` with the exact
derivatives of the solver.  ``∂C/∂s`` is the rate of the ordinary solve (time derivative,
or the analog with respect to argument 1 without model time): the condition does not
depend on its scale.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from mechloop.errors import ModelSolveError, Problem, SolveError
from mechloop.model.check import argument_kind, require_valid
from mechloop.model.intermediate import dependents, intermediate_numbers
from mechloop.model.schema import ArgumentRole, Envelope, Model
from mechloop.model.structure import Structure, param_role
from mechloop.model.units import to_si
from mechloop.solve.inputs import Signal, model_arguments, model_time
from mechloop.solve.kinematics import _Setup, _setup, _solve_block, solve, unwrap_angles
from mechloop.solve.memory import USABLE_SHARE, available_memory
from mechloop.solve.results import Results

Array = NDArray[np.float64]

#: Elements (sweep values × positions) solved in one call: keeps the temporaries small.
CHUNK_ELEMENTS = 1 << 18
#: Two roots of one position closer than this (rad, relative to 1 + |θ|) over a full
#: turn are one root found from both sides of the sweep's seam (the bracketing method
#: converges to a few ulps).
SAME_ROOT = 1e-10


@dataclass(frozen=True)
class EnvelopePoints:
    """The envelope ``name`` of the point at the end of ``vectors``: every tangency found,
    one row per root (``K`` rows, by position then by ``theta``).

    ``position`` (K,) position numbers; ``theta`` (K,) the intermediate argument there (SI:
    rad or m); ``x``, ``y`` (K,) the envelope point (m); ``branch`` (K,) ``+1`` or ``−1``:
    the sign of ``d(∂C/∂θ × ∂C/∂s)/dθ`` at the root, ``s`` along increasing positions,
    which tells the two sides of a family apart (for circles swept counter-clockwise in
    θ and moving along a path with the positions: −1 is the side to the right of the
    motion, +1 the left); ``tangency`` (K,) the sine of the angle between ``∂C/∂θ`` and
    ``∂C/∂s`` at the root (the residual, zero at an exact tangency).
    """

    name: str
    vectors: tuple[int, ...]
    positions: int
    position: NDArray[np.int64]
    theta: Array
    x: Array
    y: Array
    branch: NDArray[np.int8]
    tangency: Array

    def curve(self, branch: int) -> tuple[Array, Array]:
        """x, y (m) of the ``branch`` (+1 or −1) at every position, shape ``(P,)``: NaN
        where that branch has no root or more than one."""
        pick = self.branch == branch
        counts = np.bincount(self.position[pick], minlength=self.positions)
        x, y = np.full(self.positions, np.nan), np.full(self.positions, np.nan)
        single = pick & (counts[self.position] == 1)
        x[self.position[single]] = self.x[single]
        y[self.position[single]] = self.y[single]
        return x, y

    def to_frame(self, kind: str = "angle", argument: int = 0) -> pd.DataFrame:
        """One row per envelope point: envelope, position, branch, the argument (deg or
        m), x and y (m), tangency (the residual sine)."""
        theta = np.degrees(self.theta) if kind == "angle" else self.theta
        unit = "deg" if kind == "angle" else "m"
        return pd.DataFrame({"envelope": np.full(self.position.size, self.name, dtype=object),
                             "position": self.position, "branch": self.branch,
                             f"arg{argument} [{unit}]": theta, "x [m]": self.x,
                             "y [m]": self.y, "tangency": self.tangency})


@dataclass(frozen=True)
class IntermediateResults:
    """A model solved over its intermediate argument ``argument`` in every position.

    ``theta`` (M,) the sweep (SI: rad or m; ``kind`` 'angle' or 'length').
    ``values``, ``rates``, ``accels``: every parameter that depends on the argument,
    shaped ``(P, M)``, SI; the rates and accelerations are those of the ordinary solve's
    kind (time, or analogs with respect to argument 1), the intermediate argument held.
    ``by_theta``, ``by_theta2``: the first and second derivatives of the same parameters
    with respect to the intermediate argument (per rad or per m).  ``broken`` (P, M):
    elements where a contour has no regular solution (NaN in every array).
    ``base``: the ordinary results, shape ``(P,)``, for every other parameter.
    ``envelopes``: the model's envelopes by name.
    """

    model: Model
    base: Results
    argument: int
    kind: str
    theta: Array
    values: dict[str, Array]
    rates: dict[str, Array]
    accels: dict[str, Array]
    by_theta: dict[str, Array]
    by_theta2: dict[str, Array]
    broken: NDArray[np.bool_]
    contours: frozenset[int]
    envelopes: dict[str, EnvelopePoints]

    def value(self, name: str) -> Array:
        """Parameter ``name``: ``(P, M)`` if it depends on the argument, else ``(P,)``."""
        return self.values[name] if name in self.values else self.base.value(name)

    def point(self, vectors: list[int] | tuple[int, ...]) -> tuple[Array, Array]:
        """x, y (m) of the end of ``vectors`` laid end to end from the origin, ``(P, M)``."""
        x, y, *_ = _chain(self, vectors)
        return x, y

    def to_frame(self) -> pd.DataFrame:
        """The long table: one row per position and sweep value (position-major):
        position, (time,) the intermediate argument, every dependent parameter with its
        derivatives and its derivatives by the argument (``a4~arg3 [rad/rad]``,
        ``a4~~arg3 [rad/rad^2]``), and ``chain_break``."""
        p, m = self.broken.shape
        k = self.argument
        unit = "deg" if self.kind == "angle" else "m"
        d1, d2 = self.base.derivative_units()
        cols: dict[str, NDArray] = {"position": np.repeat(np.arange(p), m)}
        if self.base.time is not None:
            cols["time [s]"] = np.repeat(self.base.time, m)
        theta = np.degrees(self.theta) if self.kind == "angle" else self.theta
        cols[f"arg{k} [{unit}]"] = np.tile(theta, p)
        base_t = "rad" if self.kind == "angle" else "m"
        for name in self.base.varying():
            if name not in self.values:
                continue
            si = "m" if name[0] == "r" else "rad"
            shown = np.degrees(self.values[name]) if name[0] == "a" else self.values[name]
            cols[f"{name} [{'m' if name[0] == 'r' else 'deg'}]"] = shown.ravel()
            cols[f"d{name} [{si}/{d1}]"] = self.rates[name].ravel()
            cols[f"dd{name} [{si}/{d2}]"] = self.accels[name].ravel()
            cols[f"{name}~arg{k} [{si}/{base_t}]"] = self.by_theta[name].ravel()
            cols[f"{name}~~arg{k} [{si}/{base_t}^2]"] = self.by_theta2[name].ravel()
        cols["chain_break"] = self.broken.ravel()
        return pd.DataFrame(cols)

    def envelope_frame(self) -> pd.DataFrame:
        """Every envelope's points in one table (see :meth:`EnvelopePoints.to_frame`)."""
        frames = [e.to_frame(self.kind, self.argument) for e in self.envelopes.values()]
        if not frames:
            return EnvelopePoints("", (), 0, *(np.empty(0),) * 6).to_frame(
                self.kind, self.argument)
        return pd.concat(frames, ignore_index=True)


def solve_intermediate(model: Model, *, results: Results | None = None,
                       chunk_elements: int = CHUNK_ELEMENTS) -> IntermediateResults:
    """Solve ``model`` over its intermediate argument in every position, and its
    envelopes.

    ``results``: the ordinary solve of the model when the caller already has it.
    Raises :class:`SolveError` when the model has no intermediate argument, or has
    envelopes and a contour whose variant is tracked (``auto``): an envelope point is
    solved at its own position alone, so the variant must be given (1 or 2).
    """
    from mechloop.model.spatial import refuse_spatial

    refuse_spatial(model, "the solve over an intermediate argument")
    structure = require_valid(model)
    numbers = intermediate_numbers(model)
    if not numbers:
        raise SolveError("the model has no intermediate argument", "declare one: "
                         "arguments: {K: {intermediate: {from: .., to: .., count: ..}}}")
    k = numbers[0]
    base = results if results is not None else solve(model)
    kind = argument_kind(model, k)
    spec = model.arguments[k]
    unit = spec.unit or getattr(model.units, kind)
    theta = np.linspace(to_si(spec.intermediate.start, kind, unit),
                        to_si(spec.intermediate.to, kind, unit), spec.intermediate.count)
    reached, contours = dependents(model, structure, k)
    names = [n for n in base.varying() if n in reached]
    _require_memory(model, k, len(names))
    args = model_arguments(model, model_time(model))
    n_pos = model.positions + 1
    m = theta.size
    values = {n: np.empty((m, n_pos)) for n in names}
    rates = {n: np.empty((m, n_pos)) for n in names}
    accels = {n: np.empty((m, n_pos)) for n in names}
    by_theta = {n: np.empty((m, n_pos)) for n in names}
    by_theta2 = {n: np.empty((m, n_pos)) for n in names}
    broken = np.empty((m, n_pos), dtype=bool)
    rows = max(1, int(chunk_elements) // n_pos)
    for lo in range(0, m, rows):  # chunks of the sweep, each vectorized over rows × positions
        hi = min(lo + rows, m)
        offsets = theta[lo:hi, None]
        moving = _solve_at(model, structure, args, k, offsets, (hi - lo, n_pos), False)
        turning = _solve_at(model, structure, args, k, offsets, (hi - lo, n_pos), True)
        bad = moving.broken | turning.broken
        broken[lo:hi] = bad
        for n in names:
            for target, field in ((values[n], moving.params[n].value),
                                  (rates[n], moving.params[n].rate),
                                  (accels[n], moving.params[n].accel),
                                  (by_theta[n], turning.params[n].rate),
                                  (by_theta2[n], turning.params[n].accel)):
                target[lo:hi] = np.broadcast_to(field, (hi - lo, n_pos))
    with np.errstate(invalid="ignore", over="ignore"):
        for table in (values, rates, accels, by_theta, by_theta2):
            for arr in table.values():
                broken |= ~np.isfinite(arr)
        _unwrap(_setup(model, structure, args), values)
    out = {}
    for key, table in (("values", values), ("rates", rates), ("accels", accels),
                       ("by_theta", by_theta), ("by_theta2", by_theta2)):
        out[key] = {}
        for n, arr in table.items():
            arr[broken] = np.nan
            out[key][n] = np.ascontiguousarray(arr.T)
    result = IntermediateResults(model=model, base=base, argument=k, kind=kind, theta=theta,
                                 broken=np.ascontiguousarray(broken.T),
                                 contours=contours, envelopes={}, **out)
    if model.envelopes:
        found = {e.name: _envelope(result, structure, args, e) for e in model.envelopes}
        result = replace(result, envelopes=found)
    return result


#: Bytes held per (position, swept value) per dependent parameter: its value, rate,
#: acceleration and two derivatives by the argument (float64), the long table's copy of
#: them, and room for the solve's temporaries.
BYTES_PER_ELEMENT = 5 * 8 * 3


def _require_memory(model: Model, k: int, parameters: int) -> None:
    """Refuse a sweep whose arrays would not fit in the memory available (at the
    argument's ``count``, with the most that fits)."""
    available = available_memory()
    if available is None:
        return
    cells = (model.positions + 1) * model.arguments[k].intermediate.count
    per_cell = BYTES_PER_ELEMENT * max(parameters, 1) + 8
    budget = USABLE_SHARE * available
    if cells * per_cell <= budget:
        return
    most = max(int(budget // (per_cell * (model.positions + 1))), 2)
    raise ModelSolveError([Problem(
        ("arguments", k, "intermediate", "count"), f"sweeping argument {k} over "
        f"{model.arguments[k].intermediate.count:,} values in {model.positions + 1:,} "
        f"positions needs about {cells * per_cell / 2**30:.3g} GiB of memory; this "
        f"machine has {available / 2**30:.3g} GiB available",
        f"sweep fewer values (at most about {most:,} here) or use fewer positions")])


def _unwrap(setup: _Setup, values: dict[str, Array]) -> None:
    """Make the solved angles among ``values`` (shape ``(M, P)``) continuous along the
    positions, then re-derive the linked ones (as the ordinary solve does)."""
    for info in setup.ordered:
        for name in info.functions:
            if name[0] == "a" and name in values and name not in setup.carried:
                value = values[name]
                value[...] = unwrap_angles(value, np.isfinite(value))
    for name, chain in setup.structure.links.items():
        if name in values and chain.root in values:
            values[name][...] = setup.link_value(name, values[chain.root])


@dataclass
class _Solved:
    params: dict
    broken: NDArray[np.bool_]


def _solve_at(model: Model, structure: Structure, args: dict[int, Signal], k: int,
              theta: Array, shape: tuple[int, ...], by_theta: bool,
              positions: NDArray[np.int64] | None = None) -> _Solved:
    """Every contour solved with argument ``k`` at ``theta`` (broadcast to ``shape``).

    ``positions``: solve each element at its own position (shape ``shape``), else at every
    position along the last axis.  ``by_theta``: the rates and accelerations are the
    derivatives by argument ``k`` (its rate 1, every other argument's 0), else those of
    the ordinary solve with argument ``k`` held.
    """
    n = shape[-1]
    zero = np.zeros(n)
    if positions is not None:
        args = {j: Signal(s.value[positions], s.rate[positions], s.accel[positions])
                for j, s in args.items()}
        zero = np.zeros(shape)
    if by_theta:
        args = {j: Signal(s.value, np.zeros_like(s.rate), np.zeros_like(s.accel))
                for j, s in args.items()}
    args = {**args, k: Signal(zero, zero + float(by_theta), zero)}
    setup: _Setup = _setup(model, structure, args)
    if positions is not None and setup.carried:
        raise SolveError(f"{', '.join(sorted(setup.carried))} is scaled by a link ratio: its "
                         "whole turns are followed along the positions, which the envelope's "
                         "points (each at its own position) do not have (not built)",
                         "link the ratio to an argument or a constant, or leave out the "
                         "envelope of this chain")
    driven = dict(setup.driven)
    for name, (sig, offset) in setup.driven.items():
        role = param_role(model, name)
        if isinstance(role, ArgumentRole) and role.argument == k:
            driven[name] = (sig, offset + theta)
    setup = replace(setup, driven=driven)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        block = _solve_block(setup, 0, n, shape, {}, derivatives=True)
    broken = np.zeros(shape, dtype=bool)
    for mask in block.broken.values():
        broken |= mask
    return _Solved(block.params, broken)


def _chain(res: IntermediateResults, vectors) -> tuple[Array, ...]:
    """x, y of the end of ``vectors`` and of its derivatives along the positions and by
    the argument, each ``(P, M)``."""
    p, m = res.broken.shape
    x = y = sx = sy = tx = ty = np.zeros((p, m))
    for n in vectors:
        parts = []
        for name in (f"r{n}", f"a{n}"):
            if name in res.values:
                parts.append((res.values[name], res.rates[name], res.by_theta[name]))
            else:
                parts.append((res.base.values[name][:, None], res.base.rates[name][:, None],
                              0.0))
        (r, dr, tr), (a, da, ta) = parts
        c, s = np.cos(a), np.sin(a)
        x, y = x + r * c, y + r * s
        sx, sy = sx + dr * c - r * da * s, sy + dr * s + r * da * c
        tx, ty = tx + tr * c - r * ta * s, ty + tr * s + r * ta * c
    return x, y, sx, sy, tx, ty


def _envelope(res: IntermediateResults, structure: Structure, args: dict[int, Signal],
              env: Envelope) -> EnvelopePoints:
    """The tangencies of ``env`` at every position: sign changes of the cross product
    along the sweep, refined by a bracketing root finder on exact solves."""
    from scipy.optimize.elementwise import find_root

    model, k = res.model, res.argument
    auto = [c.number for c in structure.ordered() if c.variant == "auto"]
    if auto:
        raise SolveError(f"contour {auto[0]} follows its variant from position to "
                         "position (auto); an envelope point is solved at its own "
                         "position alone", "give the contour's variant as 1 or 2")
    along = _along(model)
    _, _, sx, sy, tx, ty = _chain(res, env.vectors)
    with np.errstate(invalid="ignore", over="ignore"):
        cross = (tx * sy - ty * sx) * along[:, None]
    ok = np.isfinite(cross)
    theta, p = res.theta, res.broken.shape[0]
    periodic = res.kind == "angle" and math.isclose(abs(theta[-1] - theta[0]), 2 * math.pi,
                                                    rel_tol=1e-12)
    # exact zeros at a sample
    zp, zi = np.nonzero(ok & (cross == 0))
    # sign changes between neighbouring samples, both solved; over a full turn the last
    # sample is the first one again (its value, rounded differently, may hide a root
    # at the seam), so the last pair closes the circle on the first sample
    ahead = cross[:, 1:].copy()
    if periodic:
        ahead[:, -1] = cross[:, 0]
    pair = ok[:, :-1] & ok[:, 1:] & (np.sign(cross[:, :-1]) * np.sign(ahead) < 0)
    bp, bi = np.nonzero(pair)

    def f(t: Array, pos: Array) -> Array:
        return _cross_at(model, structure, args, k, env.vectors, t, pos.astype(np.int64),
                         along)

    if bp.size:
        lo_t, hi_t = theta[bi], theta[bi + 1]
        lo, hi = np.minimum(lo_t, hi_t), np.maximum(lo_t, hi_t)
        with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
            found = find_root(f, (lo, hi), args=(bp.astype(float),))
        roots = np.where(found.success, found.x, np.nan)
        if periodic:  # no sign change inside the closing pair: the root is the seam
            roots[~found.success & (bi == theta.size - 2)] = theta[-1]
        slope = np.sign(ahead[bp, bi] - cross[bp, bi]) * np.sign(theta[1] - theta[0])
    else:
        roots, slope = np.empty(0), np.empty(0)
    before = np.clip(zi - 1, 0, theta.size - 1)
    after = np.clip(zi + 1, 0, theta.size - 1)
    zslope = np.sign(cross[zp, after] - cross[zp, before]) * np.sign(theta[1] - theta[0])
    position = np.concatenate([bp, zp]).astype(np.int64)
    at = np.concatenate([roots, theta[zi]])
    branch = np.concatenate([slope, zslope]).astype(np.int8)
    keep = np.isfinite(at) & (branch != 0)
    position, at, branch = position[keep], at[keep], branch[keep]
    if periodic:  # a full turn: θ and θ + 2π are one point, found once
        turn = math.copysign(2 * math.pi, theta[-1] - theta[0])
        at = theta[0] + np.mod(at - theta[0], turn)
    order = np.lexsort((at, position))
    position, at, branch = position[order], at[order], branch[order]
    if periodic and at.size:
        same = np.zeros(at.size, dtype=bool)
        near = SAME_ROOT * (1 + abs(theta[0]))
        same[1:] = (position[1:] == position[:-1]) & (np.abs(np.diff(at)) <= near)
        first = np.r_[True, position[1:] != position[:-1]]
        last = np.r_[position[1:] != position[:-1], True]
        starts, ends = np.flatnonzero(first), np.flatnonzero(last)
        seam = (ends > starts) & (np.abs(at[ends] - at[starts] - turn) <= near)
        same[ends[seam]] = True  # the last root of a position is its first one, turned
        position, at, branch = position[~same], at[~same], branch[~same]
    x, y, sine = _point_at(model, structure, args, k, env.vectors, at, position, along)
    good = np.isfinite(x) & np.isfinite(y) & np.isfinite(sine)
    return EnvelopePoints(env.name, tuple(env.vectors), p, position[good], at[good],
                          x[good], y[good], branch[good], sine[good])


def _along(model: Model) -> Array:
    """Per position, the sign that turns the solve's rates into derivatives along
    increasing positions: 1 with model time, else the sign of argument 1's step."""
    if model.time is None and model.arguments:
        raw = model_arguments(model, None, strict=False)[min(model.arguments)]
        return np.sign(raw.rate)
    return np.ones(model.positions + 1)


def _cross_at(model: Model, structure: Structure, args: dict[int, Signal], k: int,
              vectors, theta: Array, positions: NDArray[np.int64], along: Array) -> Array:
    """``∂C/∂θ × ∂C/∂s`` at each (position, θ) element, solved exactly there."""
    _, _, sx, sy, tx, ty = _local(model, structure, args, k, vectors, theta, positions)
    return (tx * sy - ty * sx) * along[positions]


def _point_at(model: Model, structure: Structure, args: dict[int, Signal], k: int,
              vectors, theta: Array, positions: NDArray[np.int64], along: Array
              ) -> tuple[Array, Array, Array]:
    """x, y of the point and the sine between ``∂C/∂θ`` and ``∂C/∂s`` (along increasing
    positions) at each element."""
    x, y, sx, sy, tx, ty = _local(model, structure, args, k, vectors, theta, positions)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        sine = ((tx * sy - ty * sx) * along[positions]
                / (np.hypot(tx, ty) * np.hypot(sx, sy)))
    return x, y, sine


def _local(model: Model, structure: Structure, args: dict[int, Signal], k: int, vectors,
           theta: Array, positions: NDArray[np.int64]) -> tuple[Array, ...]:
    """The chain's end and its derivatives (along the positions, by θ) at each element
    (``theta``, ``positions`` shaped alike, flat)."""
    shape = theta.shape
    theta, positions = theta.ravel(), positions.ravel()
    if theta.size == 0:
        return (np.empty(shape),) * 6
    moving = _solve_at(model, structure, args, k, theta, theta.shape, False, positions)
    turning = _solve_at(model, structure, args, k, theta, theta.shape, True, positions)
    x = y = sx = sy = tx = ty = np.zeros(theta.shape)
    with np.errstate(invalid="ignore", over="ignore"):
        for n in vectors:
            r, a = moving.params[f"r{n}"], moving.params[f"a{n}"]
            tr, ta = turning.params[f"r{n}"].rate, turning.params[f"a{n}"].rate
            c, s = np.cos(a.value), np.sin(a.value)
            x, y = x + r.value * c, y + r.value * s
            sx = sx + r.rate * c - r.value * a.rate * s
            sy = sy + r.rate * s + r.value * a.rate * c
            tx, ty = tx + tr * c - r.value * ta * s, ty + tr * s + r.value * ta * c
    bad = moving.broken | turning.broken
    return tuple(np.where(bad, np.nan, np.broadcast_to(v, theta.shape)).reshape(shape)
                 for v in (x, y, sx, sy, tx, ty))
