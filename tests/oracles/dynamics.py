"""Oracles for the dynamics: Newton–Euler equations of every body and finite differences.

The kinetostatic solver (:mod:`mechloop.dynamics.kinetostatics`) writes d'Alembert's
equations as one batched linear system.  This oracle knows nothing of that system.  It
reads the model as the plain data the test wrote (SI numbers, angles in degrees: the
default units), takes from mechloop only

* the positions of the points (``DynamicResults.placement`` tails and the solved
  ``r``/``a`` values; positions are checked against a Newton solve elsewhere),
* the unknowns the solver returned: pair reactions (force, prismatic normal and moment,
  friction) and the balancing loads,

and checks, for every moving body at every position,

    Σ F = Σ m·a_S          Σ M_O = Σ (z_S − z_O) × m·a_S + J·ε

where the accelerations ``a_S`` of the centres of mass and ``ε`` of the bodies are seven-point
central finite differences *in time* of the positions (error O(h⁶)), not the solver's own
accelerations.  Everything is complex ``x + i·y``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from mechloop.dynamics.analysis import DynamicResults

#: Seven-point central stencil of the second derivative, O(h⁶); weights over k = -3..3.
STENCIL2 = np.array([2.0, -27.0, 270.0, -490.0, 270.0, -27.0, 2.0]) / 180.0
#: Seven-point central stencil of the first derivative, O(h⁶).
STENCIL1 = np.array([-1.0, 9.0, -45.0, 0.0, 45.0, -9.0, 1.0]) / 60.0


def cross(z, w):
    """z × w for plane vectors written as complex numbers."""
    return (np.conj(z) * w).imag


def _apply(values: np.ndarray, weights: np.ndarray, h: float, power: int, *,
           periodic: bool) -> np.ndarray:
    """Stencil ``weights`` over ``values`` with step ``h``.

    ``periodic``: ``values`` has P = N + 1 rows whose last repeats the first (a full
    cycle); the result has N rows (positions 0..N−1).  Otherwise the result has P rows and
    the three rows at each end are NaN.
    """
    if periodic:
        base = values[:-1]
        out = sum(w * np.roll(base, -k) for k, w in zip(range(-3, 4), weights, strict=True))
        return out / h**power
    out = np.full(values.shape, np.nan, dtype=values.dtype)
    n = values.size
    out[3:-3] = sum(w * values[3 + k:n - 3 + k] for k, w in zip(range(-3, 4), weights,
                                                                 strict=True))
    return out / h**power


def second_derivative(values, h: float, *, periodic: bool) -> np.ndarray:
    """d²/dt² of samples ``values`` at step ``h`` (seven-point central stencil)."""
    return _apply(np.asarray(values), STENCIL2, h, 2, periodic=periodic)


def first_derivative(values, h: float, *, periodic: bool) -> np.ndarray:
    """d/dt of samples ``values`` at step ``h`` (seven-point central stencil)."""
    return _apply(np.asarray(values), STENCIL1, h, 1, periodic=periodic)


def angle_second_derivative(angle, h: float, *, periodic: bool) -> np.ndarray:
    """d²/dt² of an angle (rad) that may wrap and, over a cycle, gain whole turns."""
    theta = np.unwrap(np.asarray(angle, dtype=float))
    if periodic:  # remove the steady drift of a fully turning link (its 2nd derivative is 0)
        n = theta.size - 1
        theta = theta - (theta[-1] - theta[0]) * np.arange(n + 1) / n
    return second_derivative(theta, h, periodic=periodic)


def rows(d: DynamicResults, *, periodic: bool) -> slice:
    """The rows of the solver's arrays that the finite differences cover."""
    return slice(0, d.kinematics.broken.size - 1) if periodic else slice(None)


def time_step(d: DynamicResults) -> float:
    """The uniform time step of a model (asserted uniform)."""
    t = d.kinematics.time
    dt = np.diff(t)
    assert np.allclose(dt, dt[0], rtol=1e-12, atol=0), "finite differences need a uniform clock"
    return float(dt[0])


# ---------------------------------------------------------------- the model as data


def point_z(d: DynamicResults, spec: Mapping) -> np.ndarray:
    """Position (m, complex, shape (P,)) of a point written as in a model file, in SI."""
    res = d.kinematics
    if "tail" in spec:
        return d.placement.tail(spec["tail"]).z
    if "head" in spec:
        v = spec["head"]
        return d.placement.tail(v).z + res.value(f"r{v}") * np.exp(1j * res.value(f"a{v}"))
    v = spec["vector"]
    r, a = res.value(f"r{v}"), res.value(f"a{v}")
    along = spec.get("share", 0.0) * r + spec.get("along", 0.0)
    return d.placement.tail(v).z + (along + 1j * spec.get("across", 0.0)) * np.exp(1j * a)


def _center_vector(spec: Mapping) -> int:
    return spec.get("tail") or spec.get("head") or spec["vector"]


@dataclass(frozen=True)
class LumpedMass:
    body: int
    mass: float
    inertia: float
    center: Mapping


def lumped_masses(data: Mapping, d: DynamicResults) -> list[LumpedMass]:
    """Every lumped mass of the model data (``mass``/``inertia``/``center`` and ``parts``)."""
    out = []
    for number, body in data.get("bodies", {}).items():
        items = [body, *body.get("parts", [])]
        for item in items:
            mass, center = float(item.get("mass", 0.0)), item.get("center")
            if center is None:
                continue
            inertia = item.get("inertia", 0.0)
            if inertia == "rod":
                length = d.kinematics.value(f"r{_center_vector(center)}")[0]
                inertia = mass * length**2 / 12.0
            out.append(LumpedMass(int(number), mass, float(inertia), center))
    return out


@dataclass(frozen=True)
class AppliedForce:
    body: int
    force: np.ndarray  # N, complex, (P,)
    at: np.ndarray  # m, complex, (P,)


def external_forces(data: Mapping, d: DynamicResults) -> list[AppliedForce]:
    """The model's constant forces and gravity, from the data (degrees, SI)."""
    res = d.kinematics
    n = res.broken.size
    out = []
    for f in data.get("forces", []):
        angle = math.radians(f.get("angle", 0.0)) + (
            res.value(f"a{f['along']}") if f.get("along") is not None else 0.0)
        out.append(AppliedForce(f["body"], float(f["value"]) * np.exp(1j * angle)
                                * np.ones(n), point_z(d, f["at"])))
    gravity = data.get("gravity")
    if gravity is not None:
        g = gravity.get("g", 9.81) * np.exp(1j * math.radians(gravity.get("angle", -90.0)))
        for m in lumped_masses(data, d):
            if m.mass > 0:
                out.append(AppliedForce(m.body, m.mass * g * np.ones(n),
                                        point_z(d, m.center)))
    return out


def external_moments(data: Mapping, n: int) -> list[tuple[int, np.ndarray]]:
    return [(c["body"], float(c["value"]) * np.ones(n)) for c in data.get("moments", [])]


def state_loads(data: Mapping, d: DynamicResults, *, periodic: bool
                ) -> tuple[list[AppliedForce], list[tuple[int, np.ndarray]]]:
    """Linear springs and dampers (SI data), from the points' positions alone: the length
    ``l = |B − A|`` and, for a damper, its rate by finite differences in time (a damper in
    a joint: the bodies' angular speeds from ``d/dt e^{iα}``); ``+T·u`` on the first end,
    ``−T·u`` on the second (``T`` the tension, ``u`` from the first end to the second)."""
    forces: list[AppliedForce] = []
    moments: list[tuple[int, np.ndarray]] = []
    res = d.kinematics
    h = time_step(d) if data.get("dampers") else 1.0

    def rate(values: np.ndarray) -> np.ndarray:
        out = first_derivative(values, h, periodic=periodic)
        return np.append(out, out[:1]) if periodic else out  # the last row repeats

    def omega(body: int) -> np.ndarray:
        if body == 0:
            return np.zeros(res.broken.size)
        e = np.exp(1j * res.value(f"a{data['bodies'][body]['vectors'][0]}"))
        return (np.conj(e) * rate(e)).imag

    for kind in ("springs", "dampers"):
        for item in data.get(kind, []):
            first, second = item["bodies"]
            if item.get("ends") is None:  # a damper in the joint of its bodies
                m = item["coefficient"] * (omega(second) - omega(first))
                moments += [(first, m), (second, -m)]
                continue
            za, zb = (point_z(d, end) for end in item["ends"])
            length = np.abs(zb - za)
            u = (zb - za) / length
            if kind == "springs":
                tension = item["stiffness"] * (length - item["free_length"]) \
                    + item.get("preload", 0.0)
            else:
                tension = item["coefficient"] * rate(length)
            forces += [AppliedForce(first, tension * u, za),
                       AppliedForce(second, -tension * u, zb)]
    return forces, moments


# -------------------------------------------------------------------- Newton–Euler


@dataclass(frozen=True)
class Residual:
    """Newton–Euler residuals of one body over the covered rows, and their scales."""

    body: int
    force: np.ndarray  # N, complex
    moment: np.ndarray  # N·m, about ``origin``
    force_scale: float  # the largest force acting on the mechanism (N)
    moment_scale: float  # force_scale times the size of the mechanism (N·m)


def newton_euler(d: DynamicResults, data: Mapping, *, periodic: bool = False,
                 static: bool = False) -> list[Residual]:
    """Σ F − Σ m a_S and Σ M_O − Σ (z_S − z_O) × m a_S − Σ J ε for every moving body.

    ``a_S`` and ``ε`` are finite differences in time of positions over a uniform clock;
    ``periodic`` models run over a full cycle (the last position repeats the first).
    ``static``: a model without time, in equilibrium (``a_S = 0``, ``ε = 0``).
    The reaction of a pair is the force of its first body on the second: it enters the
    second body with ``+`` and the first with ``−`` (so do a prismatic pair's moment and
    a revolute pair's friction moment).  Drives: an angle argument's balancing moment acts
    on the driven body; a length argument's balancing force acts along the driven vector
    on the body at its head and, reversed, on the body at its tail.
    """
    h = 1.0 if static else time_step(d)
    take = rows(d, periodic=periodic)
    res = d.kinematics
    n = res.broken.size
    bodies = {int(b): body for b, body in data["bodies"].items() if int(b) != 0}

    forces: dict[int, list[tuple[np.ndarray, np.ndarray]]] = {b: [] for b in bodies}
    couples: dict[int, list[np.ndarray]] = {b: [] for b in bodies}

    def apply(body: int, force, at, sign: float = 1.0) -> None:
        if body in forces:
            forces[body].append((sign * np.asarray(force, dtype=complex), at))

    def turn(body: int, moment, sign: float = 1.0) -> None:
        if body in couples:
            couples[body].append(sign * np.asarray(moment, dtype=float))

    for r in d.forces.reactions.values():
        first, second = r.pair.bodies
        apply(second, r.force, r.point.z)
        apply(first, r.force, r.point.z, -1.0)
        if r.pair.kind == "prismatic":
            turn(second, r.moment)
            turn(first, r.moment, -1.0)
        else:
            turn(second, r.friction)
            turn(first, r.friction, -1.0)
    for drive in d.mechanism.drives:
        q = d.forces.balancing[drive.argument]
        if drive.kind == "angle":
            turn(drive.bodies[1], q)
        else:
            v = drive.vector
            e = np.exp(1j * res.value(f"a{v}"))
            apply(drive.bodies[1], q * e, point_z(d, {"head": v}))
            apply(drive.bodies[0], q * e, point_z(d, {"tail": v}), -1.0)
    for f in external_forces(data, d):
        apply(f.body, f.force, f.at)
    for body, moment in external_moments(data, n):
        turn(body, moment)
    extra_forces, extra_moments = state_loads(data, d, periodic=periodic)
    for f in extra_forces:
        apply(f.body, f.force, f.at)
    for body, moment in extra_moments:
        turn(body, moment)

    masses = lumped_masses(data, d)
    largest = max((float(np.nanmax(np.abs(f[take]))) for fs in forces.values()
                   for f, _ in fs), default=0.0)
    inertial = {}
    for m in masses:
        z = point_z(d, m.center)
        a = np.zeros_like(z[take]) if static else second_derivative(z, h, periodic=periodic)
        inertial.setdefault(m.body, []).append((m, z[take], a))
        largest = max(largest, float(np.nanmax(np.abs(m.mass * a))))
    size = max(float(np.nanmax(np.abs(point_z(d, {"head": v})))) for v in data["vectors"])
    size = max(size, max(float(np.nanmax(np.abs(point_z(d, {"tail": v}))))
                         for v in data["vectors"]))

    out = []
    for b, body in bodies.items():
        angle = res.value(f"a{body['vectors'][0]}")
        eps = 0.0 if static else angle_second_derivative(angle, h, periodic=periodic)
        parts = inertial.get(b, [])
        origin = parts[0][1] if parts else forces[b][0][1][take]
        f_sum = sum((f[take] for f, _ in forces[b]), np.zeros_like(origin))
        m_sum = sum((cross(z[take] - origin, f[take]) for f, z in forces[b]),
                    np.zeros(origin.shape))
        m_sum = m_sum + sum((c[take] for c in couples[b]), np.zeros(origin.shape))
        for m, z, a in parts:
            f_sum = f_sum - m.mass * a
            m_sum = m_sum - cross(z - origin, m.mass * a) - m.inertia * eps
        out.append(Residual(b, f_sum, m_sum, largest, largest * 2 * size))
    return out


def angle_first_derivative(angle, h: float, *, periodic: bool) -> np.ndarray:
    """d/dt of an angle (rad) that may wrap and, over a cycle, gain whole turns."""
    theta = np.unwrap(np.asarray(angle, dtype=float))
    if not periodic:
        return first_derivative(theta, h, periodic=False)
    n = theta.size - 1
    drift = (theta[-1] - theta[0]) / n
    periodic_part = theta - drift * np.arange(n + 1)
    return first_derivative(periodic_part, h, periodic=True) + drift / h


def moment_scale(d: DynamicResults, data: Mapping) -> float:
    """A moment typical of the mechanism: its largest reaction (or balancing load) times
    its longest constant vector."""
    force = max(float(np.nanmax(np.abs(r.force))) for r in d.forces.reactions.values())
    lengths = [v["r"] for v in data["vectors"].values() if isinstance(v["r"], int | float)]
    moment = max(float(np.nanmax(np.abs(q))) for q in d.forces.balancing.values())
    return max(force * max(lengths), moment)
