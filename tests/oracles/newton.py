"""Newton oracle for the kinematic core: every contour solved position by position.

The fast solver (:mod:`mechloop.solve.kinematics`) runs closed-form modules over all
positions at once.  This oracle knows nothing of the modules: for every contour it takes
the raw loop equations

    F(u) = Σ_i r_i (cos α_i, sin α_i) = 0

in the contour's two unknowns ``u`` (whatever they are: two lengths, two angles, one of
each) and runs a plain 2×2 Newton iteration in a Python loop over positions, with the
Jacobian written from the equations (``∂F/∂r_j = e_j``, ``∂F/∂α_j = r_j n_j``) and the sums
taken with :func:`math.fsum`.  It does its own bookkeeping of roles: constants, arguments
(values from :mod:`mechloop.solve.inputs`, plus offsets), link chains with their deltas,
and the order in which contours become solvable.  From mechloop it uses only the model
data classes, :func:`mechloop.model.units.to_si` and the argument values.

Newton needs a start.  ``start`` gives one value per unknown and position (normally the
fast solution, which the oracle perturbs by a relative ``perturbation``, scaled down by the
contour's conditioning near a toggle, so that it has to iterate back to the root); with
``continuation=True`` only position 0 uses ``start`` and every later position starts from
the oracle's own solution at the previous position, so the branch is followed by the
oracle itself.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.units import to_si
from mechloop.solve.inputs import model_arguments, model_time

KIND = {"r": "length", "a": "angle"}


def _role(model: Model, name: str) -> object:
    vector = model.vectors[int(name[1:])]
    return vector.r if name[0] == "r" else vector.a


def _is_function(role: object) -> bool:
    return isinstance(role, str) and role.strip() == "function"


def _si(model: Model, name: str, value: float | str) -> float:
    kind = KIND[name[0]]
    return to_si(value, kind, getattr(model.units, kind))


@dataclass(frozen=True)
class Loop:
    """One contour as the oracle sees it: listing number, vectors, its two unknowns."""

    number: int
    vectors: tuple[int, ...]
    unknowns: tuple[str, str]


@dataclass(frozen=True)
class OracleResult:
    """Every parameter (SI: m, rad) over positions and the quality of each solve.

    ``residual[k]`` is the largest over contours of ``|Σ r_i e_i| / Σ |r_i|`` at position
    ``k``; ``conditioning[k]`` the smallest over contours of ``|det J| / (|J_1| |J_2|)``
    (the sine of the angle between the Jacobian's columns: 0 at a dead point);
    ``converged[k]`` is false where Newton failed in some contour (values NaN there).
    """

    values: dict[str, np.ndarray]
    residual: np.ndarray
    conditioning: np.ndarray
    converged: np.ndarray
    order: tuple[int, ...]


class _Known:
    """Values of the parameters known at one position, following link chains."""

    def __init__(self, model: Model, base: dict[str, np.ndarray | float]):
        self.model = model
        self.base = base  # constants, arguments (+ offsets), and solved unknowns

    def get(self, name: str, k: int) -> float | None:
        delta = 0.0
        seen = set()
        while True:
            if name in self.base:
                value = self.base[name]
                value = float(value if np.ndim(value) == 0 else value[k])
                return value + delta
            role = _role(self.model, name)
            if not isinstance(role, LinkRole) or name in seen:
                return None
            seen.add(name)
            delta += _si(self.model, name, role.delta)
            name = role.link


def loops(model: Model) -> list[Loop]:
    """The contours with their unknowns (every parameter whose role is ``function``)."""
    out = []
    for i, contour in enumerate(model.contours):
        unknowns = [f"{letter}{n}" for n in contour.vectors for letter in "ra"
                    if _is_function(_role(model, f"{letter}{n}"))]
        assert len(unknowns) == 2, f"contour {i + 1} has unknowns {unknowns}"
        out.append(Loop(i + 1, tuple(contour.vectors), (unknowns[0], unknowns[1])))
    return out


def known_inputs(model: Model) -> dict[str, np.ndarray | float]:
    """Constants and argument-driven parameters, SI, before any contour is solved."""
    args = model_arguments(model, model_time(model))
    base: dict[str, np.ndarray | float] = {}
    for number, vector in model.vectors.items():
        for letter in "ra":
            name = f"{letter}{number}"
            role = vector.r if letter == "r" else vector.a
            if isinstance(role, ArgumentRole):
                base[name] = np.asarray(args[role.argument].value, dtype=float) + _si(
                    model, name, role.offset)
            elif not isinstance(role, LinkRole) and not _is_function(role):
                base[name] = _si(model, name, role)
    return base


def _ready(loop: Loop, known: _Known) -> bool:
    return all(known.get(f"{letter}{n}", 0) is not None
               for n in loop.vectors for letter in "ra"
               if f"{letter}{n}" not in loop.unknowns)


def _closure(loop: Loop, value) -> tuple[float, float, float]:
    """Σ r cos α, Σ r sin α (exactly rounded sums) and Σ |r| of the contour."""
    xs, ys, rs = [], [], []
    for n in loop.vectors:
        r, a = value(f"r{n}"), value(f"a{n}")
        xs.append(r * math.cos(a))
        ys.append(r * math.sin(a))
        rs.append(abs(r))
    return math.fsum(xs), math.fsum(ys), math.fsum(rs)


def _columns(loop: Loop, value) -> list[tuple[float, float]]:
    cols = []
    for name in loop.unknowns:
        n = int(name[1:])
        a = value(f"a{n}")
        if name[0] == "r":
            cols.append((math.cos(a), math.sin(a)))
        else:
            r = value(f"r{n}")
            cols.append((-r * math.sin(a), r * math.cos(a)))
    return cols


def _conditioning(cols: list[tuple[float, float]]) -> float:
    (ax, ay), (bx, by) = cols
    norm = math.hypot(ax, ay) * math.hypot(bx, by)
    return abs(ax * by - ay * bx) / norm if norm > 0 else 0.0


def _newton(loop: Loop, fixed: dict[str, float], guess: tuple[float, float],
            max_iter: int) -> tuple[tuple[float, float], bool]:
    u = list(guess)

    def value(name: str) -> float:
        if name == loop.unknowns[0]:
            return u[0]
        if name == loop.unknowns[1]:
            return u[1]
        return fixed[name]

    converged = False
    polish = 0
    for _ in range(max_iter):
        fx, fy, scale = _closure(loop, value)
        (ax, ay), (bx, by) = _columns(loop, value)
        det = ax * by - ay * bx
        if not math.isfinite(det) or det == 0.0:
            return (math.nan, math.nan), False
        d0 = (-fx * by + fy * bx) / det  # J d = -F by Cramer's rule
        d1 = (-ax * fy + ay * fx) / det
        u[0] += d0
        u[1] += d1
        # converged once the loop closes to round-off (the step size is no criterion:
        # near a toggle the Jacobian is nearly singular and round-off moves u by eps/cond)
        if math.hypot(fx, fy) <= 1e-14 * scale:
            converged = True
            polish += 1
            if polish >= 3:  # two more steps after convergence: settle on the root
                break
    return (u[0], u[1]), converged


def _noise(unknowns: tuple[str, str], n_pos: int, length_scale: float,
           start: Mapping[str, np.ndarray], rng: np.random.Generator) -> dict[str, np.ndarray]:
    """Random directions of the start perturbation: rad for angles, m for lengths."""
    out = {}
    for name in unknowns:
        noise = rng.standard_normal(n_pos)
        if name[0] == "r":
            base = np.broadcast_to(np.asarray(start[name], dtype=float), (n_pos,))
            noise = noise * np.maximum(np.abs(base), length_scale)
        out[name] = noise
    return out


def _start_at(start, loop: Loop, fixed: dict[str, float], noise, k: int,
              perturbation: float) -> tuple[float, float]:
    """The start guess at position ``k`` moved by ``perturbation`` times the conditioning
    of the contour there: close to a toggle the other root is near, and a start kept
    within the basin of the root being checked must be nearer still."""
    u = [float(np.broadcast_to(start[name], noise[name].shape)[k]) for name in loop.unknowns]
    values = {**fixed, loop.unknowns[0]: u[0], loop.unknowns[1]: u[1]}
    if not all(math.isfinite(v) for v in values.values()):
        return (math.nan, math.nan)
    size = perturbation * min(1.0, _conditioning(_columns(loop, values.__getitem__)))
    return (u[0] + size * noise[loop.unknowns[0]][k], u[1] + size * noise[loop.unknowns[1]][k])


def newton_solve(
    model: Model,
    start: Mapping[str, np.ndarray],
    *,
    perturbation: float = 1e-2,
    continuation: bool = False,
    seed: int = 0,
    max_iter: int = 60,
) -> OracleResult:
    """Solve every contour of ``model`` at every position by Newton's method.

    Parameters
    ----------
    model : the model (only its data are read).
    start : initial guesses for the unknowns, ``{name: array (P,)}`` in SI (e.g. the fast
        solver's ``Results.values``); NaN means "no guess": that position is not solved.
    perturbation : relative size of the random change made to ``start`` (angles: rad).
    continuation : start each position after the first from the previous solution.
    """
    n_pos = model.positions + 1
    base = known_inputs(model)
    known = _Known(model, base)
    rng = np.random.default_rng(seed)
    lengths = [abs(v) for n, v in base.items() if n[0] == "r" and np.ndim(v) == 0]
    length_scale = float(np.mean(lengths)) if lengths else 1.0

    residual = np.zeros(n_pos)
    conditioning = np.full(n_pos, np.inf)
    converged = np.ones(n_pos, dtype=bool)
    pending = loops(model)
    order = []
    while pending:
        ready = [loop for loop in pending if _ready(loop, known)]
        assert ready, f"no contour can be solved next among {[lp.number for lp in pending]}"
        loop = ready[0]
        pending.remove(loop)
        order.append(loop.number)
        noise = _noise(loop.unknowns, n_pos, length_scale, start, rng)
        out = {name: np.full(n_pos, np.nan) for name in loop.unknowns}
        previous: tuple[float, float] | None = None
        for k in range(n_pos):
            fixed = {}
            for n in loop.vectors:
                for letter in "ra":
                    name = f"{letter}{n}"
                    if name not in loop.unknowns:
                        fixed[name] = known.get(name, k)
            if any(not math.isfinite(v) for v in fixed.values()):
                converged[k] = False
                previous = None
                continue
            if continuation and previous is not None:
                g = previous
            else:
                g = _start_at(start, loop, fixed, noise, k, perturbation)
            if not (math.isfinite(g[0]) and math.isfinite(g[1])):
                converged[k] = False
                previous = None
                continue
            (u0, u1), ok = _newton(loop, fixed, g, max_iter)
            if not ok:
                converged[k] = False
                previous = None
                continue
            previous = (u0, u1)
            out[loop.unknowns[0]][k], out[loop.unknowns[1]][k] = u0, u1
            values = {**fixed, loop.unknowns[0]: u0, loop.unknowns[1]: u1}
            fx, fy, scale = _closure(loop, values.__getitem__)
            residual[k] = max(residual[k], math.hypot(fx, fy) / scale)
            cond = _conditioning(_columns(loop, values.__getitem__))
            conditioning[k] = min(conditioning[k], cond)
        base.update(out)

    values = {}
    for number in model.vectors:
        for letter in "ra":
            name = f"{letter}{number}"
            values[name] = np.array([known.get(name, k) for k in range(n_pos)], dtype=float)
    values = {name: np.where(converged, v, np.nan) for name, v in values.items()}
    return OracleResult(values=values, residual=residual, conditioning=conditioning,
                        converged=converged, order=tuple(order))


def closure_residual(model: Model, values: Mapping[str, np.ndarray]) -> np.ndarray:
    """``|Σ r_i e_i| / Σ |r_i|`` of every contour at every position, shape (C, P).

    ``values`` holds every parameter over positions in SI (e.g. ``Results.values``); the
    sums are exactly rounded, so this measures the values, not the summation.
    """
    n_pos = model.positions + 1
    out = np.zeros((len(model.contours), n_pos))
    for i, loop in enumerate(loops(model)):
        for k in range(n_pos):
            def value(name: str, k: int = k) -> float:
                v = values[name]
                return float(v if np.ndim(v) == 0 else v[k])

            fx, fy, scale = _closure(loop, value)
            out[i, k] = math.hypot(fx, fy) / scale
    return out


def conditioning(model: Model, values: Mapping[str, np.ndarray]) -> np.ndarray:
    """Sine of the angle between each contour's Jacobian columns, min over contours, (P,)."""
    n_pos = model.positions + 1
    out = np.full(n_pos, np.inf)
    for loop in loops(model):
        for k in range(n_pos):
            def value(name: str, k: int = k) -> float:
                v = values[name]
                return float(v if np.ndim(v) == 0 else v[k])

            out[k] = min(out[k], _conditioning(_columns(loop, value)))
    return out


def wrap(angle: np.ndarray | float) -> np.ndarray:
    """An angle or an angle difference folded into [-π, π)."""
    return (np.asarray(angle, dtype=float) + np.pi) % (2 * np.pi) - np.pi
